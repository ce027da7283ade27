"""Every tabulated value of engine.physics.threads against the standards, and its boundaries.

The tables are written out again here from the standards (ISO 261, ISO 898-1 Tables 3-5,
ISO 4017, ISO 273), so a wrong digit in the module's copy fails; the stress areas come from
ISO 898-1's own table, which the module does not hold, through the module's profile formulas.
"""

import math

import pytest

from engine import InputOutOfRange
from engine.physics import threads as th

# ISO 261 coarse pitch P [mm] and ISO 898-1 Table 4 stress area A_s [mm²], M3…M39
ISO_COARSE = [
    (3, 0.5, 5.03),
    (3.5, 0.6, 6.78),
    (4, 0.7, 8.78),
    (5, 0.8, 14.2),
    (6, 1.0, 20.1),
    (8, 1.25, 36.6),
    (10, 1.5, 58.0),
    (12, 1.75, 84.3),
    (14, 2.0, 115.0),
    (16, 2.0, 157.0),
    (18, 2.5, 192.0),
    (20, 2.5, 245.0),
    (22, 2.5, 303.0),
    (24, 3.0, 353.0),
    (27, 3.0, 459.0),
    (30, 3.5, 561.0),
    (33, 3.5, 694.0),
    (36, 4.0, 817.0),
    (39, 4.0, 976.0),
]

# ISO 261 fine pitches in common use [mm], the module's order (largest first)
ISO_FINE = {
    8: (1.0,),
    10: (1.25, 1.0),
    12: (1.5, 1.25),
    14: (1.5,),
    16: (1.5,),
    18: (2.0, 1.5),
    20: (2.0, 1.5),
    22: (2.0, 1.5),
    24: (2.0,),
    27: (2.0,),
    30: (2.0,),
    33: (2.0,),
    36: (3.0,),
    39: (3.0,),
}

# ISO 898-1 Table 5 stress areas of fine threads [mm²]
ISO_FINE_AREAS = {
    (8, 1.0): 39.2,
    (10, 1.25): 61.2,
    (10, 1.0): 64.5,
    (12, 1.5): 88.1,
    (12, 1.25): 92.1,
    (14, 1.5): 125.0,
    (16, 1.5): 167.0,
    (18, 1.5): 216.0,
    (20, 1.5): 272.0,
    (22, 1.5): 333.0,
    (24, 2.0): 384.0,
    (27, 2.0): 496.0,
    (30, 2.0): 621.0,
    (33, 2.0): 761.0,
    (36, 3.0): 865.0,
    (39, 3.0): 1030.0,
}

# ISO 4017 minimum bearing-face diameter d_w,min [mm] (grade A to M24, B above)
ISO_4017_DW = {
    3: 4.57,
    3.5: 5.07,
    4: 5.88,
    5: 6.88,
    6: 8.88,
    8: 11.63,
    10: 14.63,
    12: 16.63,
    14: 19.64,
    16: 22.49,
    18: 25.34,
    20: 28.19,
    22: 31.71,
    24: 33.61,
    27: 38.0,
    30: 42.75,
    33: 46.55,
    36: 51.11,
    39: 55.86,
}

# ISO 273 clearance holes [mm]: fine, medium, coarse
ISO_273 = {
    3: (3.2, 3.4, 3.6),
    3.5: (3.7, 3.9, 4.2),
    4: (4.3, 4.5, 4.8),
    5: (5.3, 5.5, 5.8),
    6: (6.4, 6.6, 7.0),
    8: (8.4, 9.0, 10.0),
    10: (10.5, 11.0, 12.0),
    12: (13.0, 13.5, 14.5),
    14: (15.0, 15.5, 16.5),
    16: (17.0, 17.5, 18.5),
    18: (19.0, 20.0, 21.0),
    20: (21.0, 22.0, 24.0),
    22: (23.0, 24.0, 26.0),
    24: (25.0, 26.0, 28.0),
    27: (28.0, 30.0, 32.0),
    30: (31.0, 33.0, 35.0),
    33: (34.0, 36.0, 38.0),
    36: (37.0, 39.0, 42.0),
    39: (40.0, 42.0, 45.0),
}

# ISO 898-1:2013 Table 3 minimum values [MPa]: (yield, tensile) up to the step, above it,
# the step and the largest size [mm], and the kind of yield strength
ISO_898_CLASSES = {
    "4.6": ((240, 400), (240, 400), 39, 39, "R_eL"),
    "4.8": ((340, 420), (340, 420), 39, 39, "R_pf"),
    "5.6": ((300, 500), (300, 500), 39, 39, "R_eL"),
    "5.8": ((420, 520), (420, 520), 39, 39, "R_pf"),
    "6.8": ((480, 600), (480, 600), 39, 39, "R_pf"),
    "8.8": ((640, 800), (660, 830), 16, 39, "R_p0.2"),
    "9.8": ((720, 900), (720, 900), 16, 16, "R_p0.2"),
    "10.9": ((940, 1040), (940, 1040), 39, 39, "R_p0.2"),
    "12.9": ((1100, 1220), (1100, 1220), 39, 39, "R_p0.2"),
}


def _area_by_hand(d_mm: float, p_mm: float) -> float:
    """ISO 898-1: A_s = π/4 (d − 0.938194 P)², with 0.938194 = (0.649519 + 1.226869)/2 [mm²]."""
    return math.pi / 4 * (d_mm - 0.938194 * p_mm) ** 2


@pytest.mark.parametrize(("d", "p", "area"), ISO_COARSE)
def test_every_coarse_size_gives_iso_898s_stress_area(d, p, area):
    assert th.coarse_pitch(d * 1e-3) == pytest.approx(p * 1e-3, rel=1e-12)
    a = th.stress_area(d * 1e-3, th.coarse_pitch(d * 1e-3)) * 1e6
    assert a == pytest.approx(area, rel=6e-3)  # the standard gives 3 significant figures
    assert a == pytest.approx(_area_by_hand(d, p), rel=1e-9)


def test_the_coarse_table_is_iso_261_and_nothing_else():
    assert {k: v for k, v in th.COARSE_PITCH_MM.items()} == {float(d): p for d, p, _ in ISO_COARSE}


@pytest.mark.parametrize("d", sorted(ISO_FINE))
def test_every_fine_pitch_is_iso_261s_and_gives_its_stress_area(d):
    pitches = th.standard_pitches(d * 1e-3)
    coarse = dict((k, p) for k, p, _ in ISO_COARSE)[d]
    assert [round(p * 1e3, 6) for p in pitches] == [coarse, *ISO_FINE[d]]
    for p in ISO_FINE[d]:
        a = th.stress_area(d * 1e-3, p * 1e-3) * 1e6
        assert a == pytest.approx(_area_by_hand(d, p), rel=1e-9)
        if (d, p) in ISO_FINE_AREAS:
            assert a == pytest.approx(ISO_FINE_AREAS[(d, p)], rel=6e-3)
    assert set(th.FINE_PITCHES_MM) == {float(k) for k in ISO_FINE}


def test_sizes_without_fine_pitches_list_the_coarse_one_alone():
    for d in (3, 3.5, 4, 5, 6):
        assert th.standard_pitches(d * 1e-3) == pytest.approx(
            (dict((k, p) for k, p, _ in ISO_COARSE)[d] * 1e-3,)
        )


@pytest.mark.parametrize(("d", "dw"), sorted(ISO_4017_DW.items()))
def test_every_hexagon_bearing_diameter_is_iso_4017s(d, dw):
    assert th.hex_bearing_diameter(d * 1e-3) == pytest.approx(dw * 1e-3, rel=1e-12)


@pytest.mark.parametrize(("d", "holes"), sorted(ISO_273.items()))
def test_every_clearance_hole_is_iso_273s(d, holes):
    for series, hole in zip(("fine", "medium", "coarse"), holes, strict=True):
        assert th.clearance_hole(d * 1e-3, series) == pytest.approx(hole * 1e-3, rel=1e-12)
    assert th.clearance_hole(d * 1e-3) == pytest.approx(holes[1] * 1e-3, rel=1e-12)


def test_size_lookup_tolerance_is_one_part_per_million():
    # the key matches within 1e-6 of the size (unit round-off), not beyond
    assert th.coarse_pitch(0.012 * (1 + 5e-7)) == pytest.approx(0.00175)
    assert th.coarse_pitch(0.012 * (1 - 5e-7)) == pytest.approx(0.00175)
    with pytest.raises(InputOutOfRange):
        th.coarse_pitch(0.012 * (1 + 5e-6))
    with pytest.raises(InputOutOfRange):
        th.hex_bearing_diameter(0.0125)
    assert th.standard_pitches(0.0125) == ()


@pytest.mark.parametrize("name", sorted(ISO_898_CLASSES))
def test_every_property_class_is_iso_898_table_3(name):
    small, large, step, largest, kind = ISO_898_CLASSES[name]
    cls = th.PROPERTY_CLASSES[name]
    assert cls.yield_kind == kind
    assert cls.max_diameter_mm == largest
    assert th.property_class_strengths(name, 0.003) == (small[0] * 1e6, small[1] * 1e6)
    assert th.property_class_strengths(name, step * 1e-3) == (small[0] * 1e6, small[1] * 1e6)
    # just above the step (a size of its own, not round-off) the large-size row holds
    if step < largest:
        above = th.property_class_strengths(name, (step + 1) * 1e-3)
        assert above == (large[0] * 1e6, large[1] * 1e6)
    top = th.property_class_strengths(name, largest * 1e-3)
    assert top == (large[0] * 1e6, large[1] * 1e6)
    assert not th.beyond_iso898(name, largest * 1e-3)
    if largest == 39:
        # ISO 898-1's M39 values carried on to M64 (CARRIED_TO_MM), then refused
        assert th.largest_diameter(name) == pytest.approx(0.064)
        assert th.beyond_iso898(name, 0.042)
        assert th.property_class_strengths(name, 0.064) == top
        with pytest.raises(InputOutOfRange) as err:
            th.property_class_strengths(name, 0.068)
        assert "M64" in str(err.value)
    else:
        assert th.largest_diameter(name) == pytest.approx(largest * 1e-3)
        assert th.beyond_iso898(name, (largest + 2) * 1e-3)
        with pytest.raises(InputOutOfRange) as err:
            th.property_class_strengths(name, (largest + 2) * 1e-3)
        assert "M64" not in str(err.value)


def test_size_step_tolerates_unit_round_off_only():
    # 16 mm parsed as 0.016000000000000002 m is still at the step (the small-size row)
    assert th.property_class_strengths("8.8", 0.016 * (1 + 1e-12)) == (640e6, 800e6)
    assert th.property_class_strengths("8.8", 0.016 * (1 + 1e-6)) == (660e6, 830e6)
    # the tolerance is 1e-9 of the step: 2e-9 above it is a larger size
    assert th.property_class_strengths("8.8", 0.016 * (1 + 2e-9)) == (660e6, 830e6)
    assert th.property_class_strengths("9.8", 0.016 * (1 + 1e-12)) == (720e6, 900e6)
    with pytest.raises(InputOutOfRange):
        th.property_class_strengths("9.8", 0.016 * (1 + 1e-6))
    assert not th.beyond_iso898("8.8", 0.039 * (1 + 1e-12))
    assert th.beyond_iso898("8.8", 0.039 * (1 + 1e-6))
    assert not th.beyond_iso898("7.7", 0.048)  # not a class: nothing carried
    assert th.property_class_strengths("8.8", 0.064 * (1 + 1e-12)) == (660e6, 830e6)
    with pytest.raises(InputOutOfRange):
        th.property_class_strengths("8.8", 0.064 * (1 + 1e-6))
    assert th.CARRIED_TO_MM == 64.0
    assert th.HOLE_SERIES == ("fine", "medium", "coarse")


def test_refusals_state_the_size_asked_in_mm():
    # the refusal is what the caller reads: it names the size as given, in mm
    with pytest.raises(InputOutOfRange) as err:
        th.coarse_pitch(0.011)
    assert "no ISO 261 coarse pitch is tabulated for d = 11 mm" in str(err.value)
    assert "M3, M3.5, M4" in str(err.value) and str(err.value).endswith("give thread_pitch")
    with pytest.raises(InputOutOfRange) as err:
        th.hex_bearing_diameter(0.007)
    assert "no ISO 4017 hexagon head is tabulated for d = 7 mm" in str(err.value)
    with pytest.raises(InputOutOfRange) as err:
        th.clearance_hole(0.045)
    assert "no ISO 273 clearance hole is tabulated for d = 45 mm" in str(err.value)
    with pytest.raises(InputOutOfRange) as err:
        th.clearance_hole(0.010, "loose")
    assert "hole_series = 'loose' is not allowed: must be one of fine, medium, coarse" in str(
        err.value
    )
    with pytest.raises(InputOutOfRange) as err:
        th.property_class_strengths("9.8", 0.020)
    assert "defined by ISO 898-1 only up to M16; give yield_strength for d = 20 mm" in str(
        err.value
    )
