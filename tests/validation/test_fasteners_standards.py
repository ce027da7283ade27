"""engine.physics.fasteners against the numbers printed in the standards and one published example.

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
- Bearing diameters d_w,min as printed in reproductions of the standards:
  ISO 4762:2004 (geartoolkit.com/standard/iso/iso-4762, every size M1.6…M64),
  EN 1665:1997 Table 1 (boltport.com/standards/en-1665: d_w, s, k,max),
  ISO 4017 grade B M12…M36 (the d_f,min row of the BS EN 15048 set-screw table,
  spdfasteners.com) and the misams/BAT open VDI 2230/ECSS tool's ISO 4014/4017
  database (0.1 mm, grade A up to M12 and above M27). ISO 10642 d_k,min could
  not be checked against a reproduction and is not pinned here.
- SAE J429 grades 2/5/8 (proof, yield, tensile by size range) as printed in Shigley &
  Mischke, Mechanical Engineering Design, 5th ed., p. 341.
- Surface pressure: the M10 worked example and Table 9.12 (p_G) of the lecture script
  "Bauelemente der Luftfahrzeuge 1" §9.12.2 (see the test's docstring).
- Thread stripping: the worked example of the machinecalcs.com thread-engagement
  calculator (M10×1.5 bolt of 830 MPa into 6061-T6 of 310 MPa, τ = 0.6·R_m,
  FED-STD-H28 shear area, no Alexander factors): required engagement ≈ 9.4 mm.
"""

from __future__ import annotations

import pytest

import engine.physics.fasteners as f

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


# ISO 4762:2004 d_w,min [mm], M1.6…M64, as reproduced by geartoolkit.com
ISO4762_DW = dict(
    zip(
        (1.6, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 14, 16, 20, 24, 30, 36, 42, 48, 56, 64),
        (2.72, 3.48, 4.18, 5.07, 6.53, 8.03, 9.38, 12.33, 15.33, 17.23, 20.17, 23.17,
         28.87, 34.81, 43.61, 52.54, 61.34, 70.34, 82.26, 94.26),
        strict=True,
    )
)  # fmt: skip
ISO4762_KEY = dict(
    zip(
        (1.6, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 14, 16, 20, 24, 30, 36, 42, 48, 56, 64),
        (1.5, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 14, 17, 19, 22, 27, 32, 36, 41, 46),
        strict=True,
    )
)  # fmt: skip
# EN 1665:1997 Table 1 as reproduced by boltport.com: size -> (d_w,min, s, k,max)
EN1665 = {
    5: (9.8, 8, 5.8), 6: (12.2, 10, 6.6), 8: (15.8, 13, 8.1), 10: (19.6, 16, 10.4),
    12: (23.8, 18, 11.8), 14: (27.6, 21, 13.7), 16: (31.9, 24, 15.4), 20: (39.9, 30, 18.9),
}  # fmt: skip
# ISO 4017 grade B d_w,min (BS EN 15048 table, d_f,min row): M30, M36; grade A from BAT (0.1 mm)
ISO4017_DW = {3: 4.6, 4: 5.9, 5: 6.9, 6: 8.9, 8: 11.6, 10: 14.6, 12: 16.6, 30: 42.75, 36: 51.11}


@pytest.mark.parametrize("size", sorted(ISO4762_DW))
def test_iso_4762_bearing_diameter_and_key(size):
    h = f.head("ISO 4762", f.metric_thread(size))
    assert h.bearing_diameter * 1e3 == pytest.approx(ISO4762_DW[size], abs=0.005)
    assert h.drive_size * 1e3 == pytest.approx(ISO4762_KEY[size])


@pytest.mark.parametrize("size", sorted(EN1665))
def test_en_1665_flange_head(size):
    h = f.head("EN 1665", f.metric_thread(size))
    dw, s, k = EN1665[size]
    assert h.bearing_diameter * 1e3 == pytest.approx(dw, abs=0.005)
    assert h.drive_size * 1e3 == pytest.approx(s)
    assert h.head_height * 1e3 == pytest.approx(k)


@pytest.mark.parametrize("size", sorted(ISO4017_DW))
def test_iso_4017_bearing_diameter(size):
    printed = ISO4017_DW[size]
    h = f.head("ISO 4017", f.metric_thread(size))
    tol = 0.005 if size in (30, 36) else 0.05  # BAT prints 0.1 mm
    assert h.bearing_diameter * 1e3 == pytest.approx(printed, abs=tol)


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


def test_surface_pressure_worked_example_aircraft_structures_script():
    """Lecture notes "13 Schraubenverbindungen IV", §5 (after the script "Bauelemente der
    Luftfahrzeuge 1", V5.0.16, 2025, §9.12.2): the M10 example, d_W = 16 mm,
    d_h = 10.5 mm, F_S,max = 27 376 N: "A_P = π/4 (16² − 10.5²) = 114.5 mm²,
    p = 27 376/114.5 = 239 N/mm² < 370 (AlZnMgCu)".
    """
    assert f.bearing_area(16e-3, 10.5e-3) * 1e6 == pytest.approx(114.5, abs=0.05)
    assert f.surface_pressure(27_376.0, 16e-3, 10.5e-3) / 1e6 == pytest.approx(239, abs=0.5)
    # the same through the model, as the check in service (VDI 2230-1 R10)
    from engine import run
    from engine.models.preload import TIGHTENING

    res = run(
        TIGHTENING,
        {
            "thread_diameter": 0.010,
            "property_class": "10.9",
            "bearing_outer_diameter": 16e-3,
            "hole_diameter": 10.5e-3,
            "working_bolt_force": 27_376.0,
            "limiting_surface_pressure": 370e6,
        },
    )
    assert res.results["surface_pressure_head_working"] / 1e6 == pytest.approx(239, abs=0.5)
    assert next(c for c in res.checks if c.name == "surface_pressure_working").ok


# The same script's Table 9.12 of limiting surface pressures p_G [N/mm²]
SCRIPT_PG = [("42CrMo4 (QT)", 850), ("TiAl6V4", 1000), ("EN AW-7075 T6", 370), ("X5CrNi18-10", 210)]


@pytest.mark.parametrize(("name", "p_g"), SCRIPT_PG)
def test_limiting_surface_pressures_against_a_printed_table(name, p_g):
    assert f.MATERIALS[name].limiting_surface_pressure == pytest.approx(p_g * 1e6)


# SAE J429 as printed in Shigley & Mischke, Mechanical Engineering Design, 5th ed. (1989),
# "SAE specifications for steel bolts", p. 341: (grade, size [in], proof, yield, tensile [ksi])
SAE_J429 = [
    ("SAE 2", 0.25, 55, 57, 74), ("SAE 2", 0.75, 55, 57, 74), ("SAE 2", 0.875, 33, 36, 60),
    ("SAE 2", 1.5, 33, 36, 60), ("SAE 5", 0.5, 85, 92, 120), ("SAE 5", 1.0, 85, 92, 120),
    ("SAE 5", 1.125, 74, 81, 105), ("SAE 5", 1.5, 74, 81, 105), ("SAE 8", 0.25, 120, 130, 150),
    ("SAE 8", 1.5, 120, 130, 150),
]  # fmt: skip


@pytest.mark.parametrize(("grade", "size", "proof", "yield_", "tensile"), SAE_J429)
def test_sae_j429_strengths_as_printed_by_shigley(grade, size, proof, yield_, tensile):
    g = f.grade_strengths(grade, size * INCH)
    ksi = 6.894757293168e6
    assert g.proof_stress == pytest.approx(proof * ksi)
    assert g.yield_strength == pytest.approx(yield_ * ksi)
    assert g.tensile_strength == pytest.approx(tensile * ksi)
