"""The spindle torque against the torque the wheel nut needs ([000], statement of the problem).

The torque reaching the nut is worked out from [000, eq. 3–10] by hand for the light-truck
example: T = (1/16) Σ m_k D_k² ω_k², C = π G d⁴/(32 l), M = √(2 T C7 C8/(C7 + C8)),
M_max = M − (z − 1) M_tr.
"""

import math

import numpy as np
import pytest

from engine import run
from engine.models import get_model
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK as E
from tests.pins import pin

DRIVE = get_model("nutrunner.drive")


def torque_at_the_nut_by_hand() -> float:
    w1 = E["motor_speed"]  # coupling 1 and pulley 2 turn with the motor
    w3 = w1 * E["motor_pulley_diameter"] / E["flywheel_diameter"]  # flywheel 3, gear 4
    w5 = w3 * E["drive_gear_diameter"] / E["spindle_gear_diameter"]  # spindle gears 5
    t = (
        E["coupling_mass"] * E["coupling_diameter"] ** 2 * w1**2
        + E["motor_pulley_mass"] * E["motor_pulley_diameter"] ** 2 * w1**2
        + E["flywheel_mass"] * E["flywheel_diameter"] ** 2 * w3**2
        + E["drive_gear_mass"] * E["drive_gear_diameter"] ** 2 * w3**2
        + E["spindle_count"] * E["spindle_gear_mass"] * E["spindle_gear_diameter"] ** 2 * w5**2
    ) / 16
    g = 8e10
    c7 = math.pi * g * E["shaft_diameter"] ** 4 / (32 * E["shaft_length"])
    c8 = math.pi * g * E["spindle_diameter"] ** 4 / (32 * E["spindle_length"])
    m = math.sqrt(2 * t * c7 * c8 / (c7 + c8))
    return m - (E["spindle_count"] - 1) * E["idle_spindle_friction_torque"]


def test_the_example_covers_the_default_wheel_nut_by_the_hand_calculated_reserve():
    m_max = torque_at_the_nut_by_hand()
    assert m_max == pytest.approx(2425.8, rel=1e-4)
    r = run(DRIVE, E)
    pin(
        "nutrunner.drive",
        "spindle_torque_reserve",
        r.results["spindle_torque_reserve"],
        m_max / 600.0,
        rel=1e-9,
    )
    (check,) = [c for c in r.checks if c.name == "wheel_nut_torque"]
    assert check.ok and "600 N*m" in check.detail


def test_a_wheel_nut_needing_more_than_the_blow_fails_with_a_warning():
    need = 3000.0  # above the 2425.8 N*m the blow leaves for the nut
    r = run(DRIVE, {**E, "wheel_nut_torque": need})
    assert r.results["spindle_torque_reserve"] == pytest.approx(
        torque_at_the_nut_by_hand() / need, rel=1e-9
    )
    (check,) = [c for c in r.checks if c.name == "wheel_nut_torque"]
    assert not check.ok
    assert any("less than the wheel nut's 3000 N*m" in w for w in r.warnings)


def test_the_array_path_reports_the_check_per_point():
    import engine

    x, _ = DRIVE.validate(E)
    ctx = engine.RunContext("closed_form", frozenset({"spindle_torque_reserve"}), 0.01)
    need = np.array([600.0, 2000.0, 3000.0])
    got = DRIVE.vectorized({**x, "wheel_nut_torque": need}, ctx)
    assert got.check_arrays["wheel_nut_torque"].tolist() == [True, True, False]
    assert got.values["spindle_torque_reserve"] == pytest.approx(
        torque_at_the_nut_by_hand() / need, rel=1e-9
    )
