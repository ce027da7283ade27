"""POST /api/v1/nutrunner/drive and its sweep, through the real app."""

from __future__ import annotations

import itertools
import math

import pytest

from engine.models.nutrunner import EXAMPLE_INDUCTION_MOTOR, EXAMPLE_LIGHT_TRUCK

URL = "/api/v1/nutrunner/drive"

# The illustrative design as a designer types it, in practical units.
TYPED = {
    "motor_power": "1.1 kW",
    "motor_speed": "1400 rpm",
    "coupling_mass": "1.2 kg",
    "coupling_diameter": "90 mm",
    "motor_pulley_mass": 0.8,
    "motor_pulley_diameter": "80 mm",
    "flywheel_mass": 12,
    "flywheel_diameter": "250 mm",
    "drive_gear_mass": 2.5,
    "drive_gear_diameter": "100 mm",
    "spindle_gear_mass": 0.5,
    "spindle_gear_diameter": "50 mm",
    "spindle_count": 6,
    "shaft_diameter": "45 mm",
    "shaft_length": "200 mm",
    "spindle_diameter": "32 mm",
    "spindle_length": "300 mm",
    "idle_spindle_friction_torque": "10 N*m",
}


def test_listed_with_units_ranges_and_rungs(api):
    models = {m["name"]: m for m in api.get("/api/v1/models").json()["models"]}
    m = models["nutrunner.drive"]
    assert m["path"] == "/nutrunner/drive" and m["default_fidelity"] == "closed_form"
    assert [r["name"] for r in m["rungs"]] == ["closed_form", "gear_ratio", "motor_curve"]
    inputs = {p["name"]: p for p in m["inputs"]}
    for name in (
        "motor_power",
        "motor_speed",
        "coupling_mass",
        "coupling_diameter",
        "motor_pulley_mass",
        "motor_pulley_diameter",
        "flywheel_mass",
        "flywheel_diameter",
        "drive_gear_mass",
        "drive_gear_diameter",
        "spindle_gear_mass",
        "spindle_gear_diameter",
        "spindle_count",
        "shaft_diameter",
        "shaft_length",
        "spindle_diameter",
        "spindle_length",
        "shear_modulus",
        "idle_spindle_friction_torque",
    ):
        assert name in inputs
        assert "[000, eq." in inputs[name]["description"]
    assert inputs["shear_modulus"]["default"] == 8e10
    assert inputs["idle_spindle_friction_torque"]["default"] == 0.0
    assert inputs["spindle_diameter"]["display_unit"] == "mm"
    assert inputs["motor_speed"]["display_unit"] == "rpm"
    assert inputs["motor_power"]["display_unit"] == "kW"
    assert inputs["flywheel_mass"]["unit"] == "kg" and inputs["flywheel_mass"]["minimum"] == 0.0
    outputs = {o["name"]: o for o in m["outputs"]}
    assert outputs["impact_torque"]["unit"] == "N*m"
    assert outputs["motor_speed_curve"]["series"] and outputs["motor_speed_curve"]["x"] == "time"
    assert m["examples"][0]["motor_power"] == 1100.0


def test_unit_strings_give_the_si_example(api):
    typed = api.post(URL, json=TYPED)
    si = api.post(URL, json=EXAMPLE_LIGHT_TRUCK)
    assert typed.status_code == si.status_code == 200, typed.text
    a, b = typed.json(), si.json()
    assert a["rung"] == "closed_form"
    for name, value in b["results"].items():
        assert a["results"][name] == pytest.approx(value, rel=1e-12), name
    assert a["results"]["impact_torque"] == pytest.approx(2475.762, rel=1e-6)
    assert a["units"]["impact_torque"] == "N*m"
    assert {c["name"] for c in a["checks"]} >= {"max_spindle_torque_positive"}


def test_motor_curve_over_http_with_series(api):
    r = api.post(URL, json={**EXAMPLE_INDUCTION_MOTOR, "fidelity": "motor_curve", "series": True})
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["rung"] == "motor_curve" and body["error_estimate"] < 1e-8
    assert body["results"]["acceleration_time"] == pytest.approx(0.196416, rel=1e-5)
    assert len(body["series"]["time"]) == len(body["series"]["motor_speed_curve"]) == 101


def test_infeasible_motor_is_422_with_a_sentence(api):
    body = {
        **EXAMPLE_LIGHT_TRUCK,
        "motor_curve": "linear",
        "stall_torque": "30 N*m",
        "no_load_speed": "1300 rpm",
        "fidelity": "motor_curve",
    }
    r = api.post(URL, json=body)
    assert r.status_code == 422
    (item,) = r.json()["detail"]
    assert item["type"] == "infeasible_design" and "can never reach" in item["msg"]


def test_friction_absorbing_the_blow_is_200_with_failed_check(api):
    r = api.post(URL, json={**EXAMPLE_LIGHT_TRUCK, "idle_spindle_friction_torque": "600 N*m"})
    assert r.status_code == 200
    body = r.json()
    assert body["results"]["max_spindle_torque"] < 0
    failed = [c for c in body["checks"] if not c["ok"]]
    assert [c["name"] for c in failed] == ["max_spindle_torque_positive"]
    assert any("no torque reaches the nut" in w for w in body["warnings"])


def test_missing_required_input_is_422_naming_it(api):
    body = {k: v for k, v in EXAMPLE_LIGHT_TRUCK.items() if k != "spindle_diameter"}
    r = api.post(URL, json=body)
    assert r.status_code == 422
    assert any(i["field"] == "spindle_diameter" for i in r.json()["detail"])


def test_sweep_impact_torque_against_spindle_diameter(api):
    r = api.post(
        URL + "/sweep",
        json={
            "base": EXAMPLE_LIGHT_TRUCK,
            "vary": "spindle_diameter",
            "start": "10 mm",
            "stop": "100 mm",
            "num": 10,
            "outputs": ["impact_torque", "spindle_twist"],
        },
    )
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["rung"] == "closed_form" and body["unit"] == "m"
    assert body["values"][0] == pytest.approx(0.01) and body["values"][-1] == pytest.approx(0.1)
    m = body["results"]["impact_torque"]
    # stiffer spindle, larger torque; bounded by the shaft alone: √(2T·C7) = 6487 N·m
    assert all(b > a for a, b in itertools.pairwise(m))
    t_kin = 130.6716
    c7 = math.pi * 8e10 * 0.045**4 / 6.4
    assert m[-1] < math.sqrt(2 * t_kin * c7)
    # point 4 (d8 = 50 mm) by hand: C8 = π·8e10·0.05⁴/9.6 = 163 625 N·m/rad
    c8 = math.pi * 8e10 * 0.05**4 / 9.6
    assert m[4] == pytest.approx(math.sqrt(2 * t_kin * c7 * c8 / (c7 + c8)), rel=1e-5)


def test_sweep_on_motor_curve_rung_loops_and_works(api):
    r = api.post(
        URL + "/sweep",
        json={
            "base": EXAMPLE_INDUCTION_MOTOR,
            "vary": "flywheel_mass",
            "start": 5,
            "stop": 30,
            "num": 6,
            "outputs": ["acceleration_time"],
            "fidelity": "motor_curve",
        },
    )
    assert r.status_code == 200, r.text
    t = r.json()["results"]["acceleration_time"]
    assert all(b > a for a, b in itertools.pairwise(t))
