"""The preload models with bought fasteners: designations, surface pressure, stripping, drive."""

from __future__ import annotations

import math

import pytest

import engine.physics.fasteners as f
from engine import run
from engine.core.errors import InputOutOfRange
from engine.models.preload import CONTROL, TIGHTENING

INCH = 0.0254
KSI = 6.894757293168e6
ALU = "EN AW-6082 T6"


def test_socket_head_designation_gives_a_complete_answer():
    r = run(TIGHTENING, {"thread": "M10 ISO 4762 12.9"}).results
    assert r["fastener"] == "M10 ISO 4762 12.9"
    assert r["stress_area"] * 1e6 == pytest.approx(58.0, rel=0.001)
    assert r["yield_strength"] == pytest.approx(1100e6)
    assert r["bearing_outer_diameter"] == pytest.approx(15.33e-3)  # ISO 4762 d_w,min
    assert r["hole_diameter"] == pytest.approx(11e-3)  # ISO 273 medium
    assert r["drive_torque_limit"] == pytest.approx(120.0)  # 8 mm key, ISO 2936
    for name in ("assembly_preload", "tightening_torque", "surface_pressure_head"):
        assert math.isfinite(r[name]) and r[name] > 0
    # the same bolt typed as numbers gives the same preload and torque
    typed = run(
        TIGHTENING,
        {"thread_diameter": 0.010, "yield_strength": 1100e6, "bearing_outer_diameter": 15.33e-3},
    ).results
    assert r["assembly_preload"] == pytest.approx(typed["assembly_preload"], rel=1e-12)
    assert r["tightening_torque"] == pytest.approx(typed["tightening_torque"], rel=1e-12)


def test_inch_bolt_with_sae_grade_gives_a_complete_answer():
    r = run(TIGHTENING, {"thread": "1/2-13 UNC", "grade": "SAE 5"}).results
    assert r["stress_area"] / INCH**2 == pytest.approx(0.1419, rel=0.001)
    assert r["pitch_diameter"] / INCH == pytest.approx(0.4500, abs=5e-5)
    assert r["thread_pitch"] == pytest.approx(INCH / 13)
    assert r["yield_strength"] == pytest.approx(92 * KSI)
    assert r["bearing_outer_diameter"] == pytest.approx(0.95 * 0.75 * INCH)
    assert r["hole_diameter"] == pytest.approx(0.531 * INCH)
    assert r["assembly_preload"] > 0 and r["tightening_torque"] > 0
    c = run(CONTROL, {"thread": "1/2-13 UNC Grade 5", "required_clamp_force": 15e3}).results
    assert c["target_torque"] > 0 and c["fastener"] == "1/2-13 UNC ASME B18.2.1 SAE 5"


def test_designation_m12_equals_the_numeric_default_bolt():
    by_name = run(TIGHTENING, {"thread": "M12"}).results
    by_number = run(TIGHTENING, {"thread_diameter": 0.012}).results
    for key in ("assembly_preload", "tightening_torque", "bearing_outer_diameter", "hole_diameter"):
        assert by_name[key] == pytest.approx(by_number[key], rel=1e-12)


def test_too_short_engagement_in_aluminium_fails_with_the_length_it_needs():
    x = {
        "thread": "M8 ISO 4762 12.9",
        "internal_thread_material": ALU,
        "engagement_length": 0.008,
    }
    res = run(TIGHTENING, x)
    need = res.results["min_engagement_length"]
    # hand check: F_B = 1.2 × 1220 MPa · A_s (the bolt at its upper strength); internal
    # thread A_SN/L = 0.875 π d; τ = 0.6·310 MPa; R_S < 0.4 here, so C3 = C3(0.4) = 1.055
    # (VDI 2230-1 R11, Alexander); plus 2P = 2.5 mm for the entry chamfers
    t = f.metric_thread(8)
    c3 = 0.728 + 1.769 * 0.4 - 2.896 * 0.16 + 1.296 * 0.064
    hand = 1.2 * 1220e6 * t.stress_area / (c3 * 0.6 * 310e6 * 0.875 * math.pi * 0.008)
    hand += 2 * 1.25e-3
    assert need == pytest.approx(hand, rel=1e-4)
    check = next(c for c in res.checks if c.name == "thread_stripping")
    assert not check.ok
    assert f"{need * 1e3:.3g} mm" in check.detail and "engage at least" in check.detail
    ok = run(TIGHTENING, {**x, "engagement_length": need * 1.01})
    assert next(c for c in ok.checks if c.name == "thread_stripping").ok
    # a steel tapped hole needs less
    steel = run(TIGHTENING, {**x, "internal_thread_material": "42CrMo4 (QT)"}).results
    assert steel["min_engagement_length"] < need


def test_surface_pressure_hand_check_and_washer():
    x = {"thread": "M8 ISO 4762 12.9", "clamped_material": ALU}
    res = run(TIGHTENING, x)
    r = res.results
    area = math.pi / 4 * (12.33**2 - 9.0**2) * 1e-6
    assert r["surface_pressure_head"] == pytest.approx(r["assembly_preload"] / area, rel=1e-9)
    assert r["limiting_surface_pressure"] == pytest.approx(360e6)
    check = next(c for c in res.checks if c.name == "surface_pressure_assembly")
    assert not check.ok and "needs a bearing area" in check.detail
    washed = run(TIGHTENING, {**x, "washer": "ISO 7089"})
    area_w = math.pi / 4 * (16.0**2 - 9.0**2) * 1e-6
    assert washed.results["surface_pressure_head"] == pytest.approx(
        washed.results["assembly_preload"] / area_w, rel=1e-9
    )
    assert next(c for c in washed.checks if c.name == "surface_pressure_assembly").ok
    # the user's limit overrides the table; the working force is checked too
    own = run(TIGHTENING, {**x, "limiting_surface_pressure": 700e6, "working_bolt_force": 40e3})
    names = {c.name: c.ok for c in own.checks}
    assert names["surface_pressure_assembly"] is True
    assert names["surface_pressure_working"] is (40e3 / area <= 700e6)


def test_nut_side_pressure_uses_the_nut_bearing_face():
    r = run(TIGHTENING, {"thread": "M12", "nut": "ISO 4032", "clamped_material": "S235JR"}).results
    area = math.pi / 4 * (16.63**2 - 13.5**2) * 1e-6
    assert r["surface_pressure_nut"] == pytest.approx(r["assembly_preload"] / area, rel=1e-9)


def test_countersunk_head_friction_on_the_cone():
    csk = run(TIGHTENING, {"thread": "M8 ISO 10642 10.9"}).results
    # the same bearing face, flat, with μ_K·√2 gives the same torque
    flat = run(
        TIGHTENING,
        {
            "thread_diameter": 0.008,
            "property_class": "10.9",
            "bearing_outer_diameter": 15.24e-3,
            "bearing_friction": 0.12 * math.sqrt(2),
        },
    ).results
    assert csk["bearing_torque"] == pytest.approx(flat["bearing_torque"], rel=1e-12)
    assert csk["tightening_torque"] == pytest.approx(flat["tightening_torque"], rel=1e-12)


def test_drive_torque_check_of_a_countersunk_12_9():
    res = run(TIGHTENING, {"thread": "M8 ISO 10642 12.9"})
    check = next(c for c in res.checks if c.name == "drive_torque")
    assert res.results["drive_torque_limit"] == pytest.approx(30.0)  # 5 mm key
    assert not check.ok and res.results["tightening_torque"] > 30.0
    hexagon = run(TIGHTENING, {"thread": "M8 ISO 4017 12.9"})
    assert "drive_torque" not in {c.name for c in hexagon.checks}  # a wrench, not a key


@pytest.mark.parametrize(
    ("inputs", "field"),
    [
        ({}, "thread"),
        ({"thread": "M12", "thread_diameter": 0.012}, "thread_diameter"),
        ({"thread": "M12", "thread_pitch": 0.00125}, "thread_pitch"),
        ({"thread": "M13"}, "thread"),
        ({"thread": "1/2-13 UNC"}, "grade"),
        ({"thread": "M10 ISO 4762 12.9", "head_standard": "ISO 4017"}, "head_standard"),
        ({"thread": "M10 ISO 4762 12.9", "grade": "8.8"}, "grade"),
        ({"thread": "M30", "grade": "A2-70"}, "grade"),
        ({"thread": "M3", "head_standard": "EN 1665"}, "head_standard"),
        (
            {"thread_diameter": 0.011, "thread_pitch": 0.0015, "head_standard": "ISO 4762"},
            "head_standard",
        ),
        ({"thread": "1/2-13 UNC", "grade": "SAE 5", "washer": "ISO 7089"}, "washer"),
    ],
)
def test_bad_fastener_inputs_name_the_field(inputs, field):
    with pytest.raises(InputOutOfRange) as err:
        run(TIGHTENING, inputs)
    assert err.value.field == field


def test_the_examples_include_the_bought_parts():
    things = [e.get("thread") for e in (*TIGHTENING.examples, *CONTROL.examples)]
    assert "M10 ISO 4762 12.9" in things and "M8 ISO 4762 12.9" in things and "1/2-13 UNC" in things
    aluminium = next(e for e in CONTROL.examples if e.get("internal_thread_material") == ALU)
    res = run(CONTROL, dict(aluminium))
    assert not next(c for c in res.checks if c.name == "thread_stripping").ok
