"""engine.fasteners against the numbers printed in the standards and one published example.

Each table below is copied from the printed standard (values as printed, the
standard's units); the engine computes the same quantities from the basic
profile and its own strength tables, and must agree within the tolerance each
test names.

- ISO 898-1:2013, Table 4/7 (nominal stress areas A_s, coarse and fine), Table 5
  (proof loads A_s·S_p) and Table 4 (minimum ultimate loads A_s·R_m,min) for
  8.8, 10.9, 12.9 coarse M8…M24: within 0.5 %.
- ISO 3506-1:2009 Table 3 strengths of A2/A4-70 and A4-80 (R_p0.2, R_m); the
  loads it defines as A_s·R (with ISO 898-1's A_s): within 0.5 %.
- ASME B1.1 basic pitch diameters (inch, 4 decimals as printed): within half a
  unit of the last digit; tensile stress areas A_t (in², as printed): within 0.5 %.
- ISO 4017 (product grade A ≤ M24, B above) and ISO 4762 minimum bearing
  diameters d_w,min, EN 1665 flange d_w,min, ISO 10642 d_k,min: as printed.
- Thread stripping: the worked example of the machinecalcs.com thread-engagement
  calculator (M10×1.5 bolt of 830 MPa into 6061-T6 of 310 MPa, τ = 0.6·R_m,
  FED-STD-H28 shear area, no Alexander factors): required engagement ≈ 9.4 mm.
"""

from __future__ import annotations

import pytest

import engine.fasteners as f

INCH = 0.0254

# ISO 898-1:2013, nominal stress area A_s [mm²] as printed
ISO898_STRESS_AREA = [
    ("M3", 5.03), ("M3.5", 6.78), ("M4", 8.78), ("M5", 14.2), ("M6", 20.1), ("M8", 36.6),
    ("M10", 58.0), ("M12", 84.3), ("M14", 115), ("M16", 157), ("M18", 192), ("M20", 245),
    ("M22", 303), ("M24", 353), ("M27", 459), ("M30", 561), ("M33", 694), ("M36", 817),
    ("M39", 976), ("M8x1", 39.2), ("M10x1.25", 61.2), ("M10x1", 64.5), ("M12x1.5", 88.1),
    ("M12x1.25", 92.1), ("M14x1.5", 125), ("M16x1.5", 167), ("M18x1.5", 216),
    ("M20x1.5", 272), ("M22x1.5", 333), ("M24x2", 384), ("M27x2", 496), ("M30x2", 621),
    ("M33x2", 761), ("M36x3", 865), ("M39x3", 1030),
]  # fmt: skip


@pytest.mark.parametrize(("designation", "printed"), ISO898_STRESS_AREA)
def test_iso_898_1_stress_areas(designation, printed):
    computed = f.parse_designation(designation).thread.stress_area * 1e6
    assert computed == pytest.approx(printed, rel=0.005)


# ISO 898-1:2013 Table 5 proof loads and Table 4 minimum ultimate loads [N], coarse
ISO898_LOADS = [
    # (size, class, proof load, minimum ultimate tensile load)
    ("M8", "8.8", 21_200, 29_200), ("M10", "8.8", 33_700, 46_400), ("M12", "8.8", 48_900, 67_400),
    ("M16", "8.8", 91_000, 125_000), ("M20", "8.8", 147_000, 203_000),
    ("M24", "8.8", 212_000, 293_000),
    ("M8", "10.9", 30_400, 38_100), ("M10", "10.9", 48_100, 60_300),
    ("M12", "10.9", 70_000, 87_700), ("M16", "10.9", 130_000, 163_000),
    ("M20", "10.9", 203_000, 255_000), ("M24", "10.9", 293_000, 367_000),
    ("M8", "12.9", 35_500, 44_600), ("M10", "12.9", 56_300, 70_800),
    ("M12", "12.9", 81_800, 103_000), ("M16", "12.9", 152_000, 192_000),
    ("M20", "12.9", 238_000, 299_000), ("M24", "12.9", 342_000, 431_000),
]  # fmt: skip


@pytest.mark.parametrize(("size", "cls", "proof", "ultimate"), ISO898_LOADS)
def test_iso_898_1_proof_and_ultimate_loads(size, cls, proof, ultimate):
    thread = f.parse_designation(size).thread
    grade = f.grade_strengths(cls, thread.diameter)
    assert grade.proof_stress is not None
    assert thread.stress_area * grade.proof_stress == pytest.approx(proof, rel=0.005)
    assert thread.stress_area * grade.tensile_strength == pytest.approx(ultimate, rel=0.005)


# ISO 3506-1:2009 Table 3: (grade, R_p0.2 MPa, R_m MPa, largest size)
ISO3506 = [("A2-70", 450, 700, 24), ("A4-70", 450, 700, 24), ("A4-80", 600, 800, 24)]


@pytest.mark.parametrize(("grade", "rp", "rm", "largest"), ISO3506)
def test_iso_3506_1_strengths_and_loads(grade, rp, rm, largest):
    for size, a_s in (("M6", 20.1), ("M12", 84.3), ("M20", 245.0)):
        thread = f.parse_designation(f"{size} {grade}").thread
        g = f.grade_strengths(grade, thread.diameter)
        assert (g.yield_strength, g.tensile_strength) == (rp * 1e6, rm * 1e6)
        # the loads at R_p0.2 and at R_m, as ISO 3506-1 defines them (A_s·R), to 0.5 %
        assert thread.stress_area * g.yield_strength == pytest.approx(a_s * rp, rel=0.005)
        assert thread.stress_area * g.tensile_strength == pytest.approx(a_s * rm, rel=0.005)
    assert f.grade_strengths(grade, largest * 1e-3).name == grade
    with pytest.raises(f.InputOutOfRange):
        f.grade_strengths(grade, (largest + 6) * 1e-3)


# ASME B1.1: (designation, basic pitch diameter [in], tensile stress area [in²]) as printed
ASME_B1_1 = [
    ("1/4-20 UNC", 0.2175, 0.0318), ("1/4-28 UNF", 0.2268, 0.0364),
    ("5/16-18 UNC", 0.2764, 0.0524), ("3/8-16 UNC", 0.3344, 0.0775),
    ("3/8-24 UNF", 0.3479, 0.0878), ("7/16-14 UNC", 0.3911, 0.1063),
    ("1/2-13 UNC", 0.4500, 0.1419), ("1/2-20 UNF", 0.4675, 0.1599),
    ("5/8-11 UNC", 0.5660, 0.226), ("3/4-10 UNC", 0.6850, 0.334),
    ("7/8-9 UNC", 0.8028, 0.462), ("1-8 UNC", 0.9188, 0.606), ("1-12 UNF", 0.9459, 0.663),
    ("1-1/4-7 UNC", 1.1572, 0.969), ("1-1/2-6 UNC", 1.3917, 1.405),
    ("1-1/2-12 UNF", 1.4459, 1.581),
]  # fmt: skip


@pytest.mark.parametrize(("designation", "pitch_diameter", "stress_area"), ASME_B1_1)
def test_asme_b1_1_pitch_diameters_and_stress_areas(designation, pitch_diameter, stress_area):
    thread = f.parse_designation(designation).thread
    assert thread.pitch_diameter / INCH == pytest.approx(pitch_diameter, abs=0.00005)
    assert thread.stress_area / INCH**2 == pytest.approx(stress_area, rel=0.005)


# d_w,min [mm] as printed: ISO 4017 (grade A ≤ M24, B above), ISO 4762, EN 1665; d_k,min ISO 10642
BEARING_DIAMETERS = [
    ("ISO 4017", "M3", 4.57), ("ISO 4017", "M5", 6.88), ("ISO 4017", "M8", 11.63),
    ("ISO 4017", "M12", 16.63), ("ISO 4017", "M16", 22.49), ("ISO 4017", "M24", 33.61),
    ("ISO 4017", "M30", 42.75), ("ISO 4017", "M36", 51.11), ("ISO 4017", "M48", 69.45),
    ("ISO 4762", "M3", 5.07), ("ISO 4762", "M5", 8.03), ("ISO 4762", "M8", 12.33),
    ("ISO 4762", "M10", 15.33), ("ISO 4762", "M12", 17.23), ("ISO 4762", "M16", 23.17),
    ("ISO 4762", "M20", 28.87), ("ISO 4762", "M24", 34.81),
    ("EN 1665", "M8", 15.8), ("EN 1665", "M10", 19.6), ("EN 1665", "M12", 23.8),
    ("ISO 10642", "M8", 15.24), ("ISO 10642", "M10", 19.22),
]  # fmt: skip


@pytest.mark.parametrize(("standard", "size", "printed"), BEARING_DIAMETERS)
def test_bearing_diameters_as_printed(standard, size, printed):
    h = f.head(standard, f.parse_designation(size).thread)
    assert h.bearing_diameter * 1e3 == pytest.approx(printed, abs=0.005)


def test_thread_stripping_machinecalcs_worked_example():
    """machinecalcs.com thread-engagement calculator, printed worked example.

    M10×1.5 ISO 8.8 bolt, R_m taken as 830 MPa; 6061-T6 tapped hole, 310 MPa;
    τ = 0.6·R_m; FED-STD-H28 shear area: "a required tapped engagement of about
    9.4 mm at SF = 1". Our basic-profile shear area with C1 = C2 = C3 = 1.
    """
    t = f.parse_designation("M10").thread
    s = f.thread_stripping(
        t.diameter, t.pitch, t.pitch_diameter, t.nut_minor_diameter, 58.0e-6,
        830e6, 0.6 * 830e6, 0.6 * 310e6, 10e-3, c1=1.0, bending=False,
    )  # fmt: skip
    assert s.min_engagement_length * 1e3 == pytest.approx(9.4, abs=0.05)
    assert s.weaker == "internal"
    # "10 mm just clears the bolt-tensile target"
    assert s.internal_strip_force > s.bolt_breaking_force
