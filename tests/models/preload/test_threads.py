"""ISO bolt data: profile diameters, stress areas, heads, holes and property classes."""

import math

import pytest

from engine import InputOutOfRange
from engine.physics import threads as th

# ISO 898-1 Table 4/5 nominal stress areas [mm²] (coarse, then fine threads).
ISO_898_STRESS_AREAS = [
    (3, 0.5, 5.03),
    (4, 0.7, 8.78),
    (5, 0.8, 14.2),
    (6, 1.0, 20.1),
    (8, 1.25, 36.6),
    (10, 1.5, 58.0),
    (12, 1.75, 84.3),
    (14, 2.0, 115.0),
    (16, 2.0, 157.0),
    (20, 2.5, 245.0),
    (24, 3.0, 353.0),
    (30, 3.5, 561.0),
    (36, 4.0, 817.0),
    (39, 4.0, 976.0),
    (10, 1.25, 61.2),
    (12, 1.5, 88.1),
    (16, 1.5, 167.0),
]


@pytest.mark.parametrize(("d", "p", "area"), ISO_898_STRESS_AREAS)
def test_stress_area_matches_iso_898_table(d, p, area):
    computed = th.stress_area(d * 1e-3, p * 1e-3) * 1e6
    # the standard rounds to 3 significant figures
    assert computed == pytest.approx(area, rel=6e-3)


def test_profile_diameters_m12_by_hand():
    # ISO 724, M12x1.75: d2 = 12 - 0.649519*1.75 = 10.863, d3 = 12 - 1.226869*1.75 = 9.853,
    # d1 = 12 - 1.082532*1.75 = 10.106
    d, p = 0.012, 0.00175
    assert th.pitch_diameter(d, p) == pytest.approx(10.8633e-3, abs=1e-7)
    assert th.minor_diameter(d, p) == pytest.approx(9.8530e-3, abs=1e-7)
    assert th.nut_minor_diameter(d, p) == pytest.approx(10.1056e-3, abs=1e-7)
    # d0 = (10.8633 + 9.8530)/2 = 10.3582; A_s = pi/4 * 10.3582^2 = 84.267 mm²
    assert th.stress_area(d, p) == pytest.approx(math.pi / 4 * 10.35816e-3**2, rel=1e-5)


def test_coarse_pitches_and_fine_list():
    assert th.coarse_pitch(0.010) == pytest.approx(0.0015)
    assert th.coarse_pitch(0.024) == pytest.approx(0.003)
    assert th.coarse_pitch(0.039) == pytest.approx(0.004)
    assert [round(p * 1e3, 3) for p in th.standard_pitches(0.010)] == [1.5, 1.25, 1.0]
    assert th.standard_pitches(0.011) == ()


def test_size_lookup_tolerates_unit_round_off():
    # "12 mm" parsed by pint may come out as 0.012000000000000002 m
    assert th.coarse_pitch(0.012000000000000002) == pytest.approx(0.00175)


def test_heads_and_holes():
    assert th.hex_bearing_diameter(0.012) == pytest.approx(16.63e-3)
    assert th.hex_bearing_diameter(0.030) == pytest.approx(42.75e-3)
    assert th.clearance_hole(0.010, "fine") == pytest.approx(10.5e-3)
    assert th.clearance_hole(0.010, "medium") == pytest.approx(11.0e-3)
    assert th.clearance_hole(0.010, "coarse") == pytest.approx(12.0e-3)
    for size in th.HEX_BEARING_DIAMETER_MM:
        fine, medium, coarse = th.CLEARANCE_HOLE_MM[size]
        assert size < fine < medium < coarse < th.HEX_BEARING_DIAMETER_MM[size]


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: th.coarse_pitch(0.011), "thread_pitch"),
        (lambda: th.hex_bearing_diameter(0.007), "bearing_outer_diameter"),
        (lambda: th.clearance_hole(0.045), "hole_diameter"),
        (lambda: th.clearance_hole(0.010, "loose"), "hole_series"),
        (lambda: th.property_class_strengths("9.8", 0.020), "property_class"),
        (lambda: th.property_class_strengths("7.7", 0.010), "property_class"),
    ],
)
def test_missing_standard_values_name_the_input_to_give(call, field):
    with pytest.raises(InputOutOfRange) as err:
        call()
    assert err.value.field == field


def test_property_classes_and_size_step():
    assert th.property_class_strengths("8.8", 0.016) == (640e6, 800e6)
    assert th.property_class_strengths("8.8", 0.018) == (660e6, 830e6)
    assert th.property_class_strengths("10.9", 0.030) == (940e6, 1040e6)
    assert th.property_class_strengths("12.9", 0.012) == (1100e6, 1220e6)
    assert th.property_class_strengths("4.6", 0.012) == (240e6, 400e6)
    assert th.property_class_strengths("9.8", 0.016) == (720e6, 900e6)
    # every class: yield below tensile, and the first digit is R_m/100 (nominal)
    for name in th.PROPERTY_CLASS_NAMES:
        rp, rm = th.property_class_strengths(name, 0.010)
        assert rp < rm
        assert rm / 1e8 >= float(name.split(".")[0]) - 1e-9
