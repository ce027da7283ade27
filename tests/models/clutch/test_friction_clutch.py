"""The nut-runner's friction clutches [000]: their torque M_tr from the clamp of their nuts.

[000] says diaphragms 11, clamped against the spindle gears 5 by nuts 12, carry a small
torque "regulated by the clamp force" and takes it off the blow, M_max = M − (z − 1) M_tr
(eq. 10); the clamp-to-torque relation is the plate clutch's, worked here by hand.
"""

import numpy as np
import pytest

import engine
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE
from engine.physics.clutch import friction_clutch_torque
from tests.pins import pin

CLAMP = {
    "friction_clutch_clamp_force": 800.0,
    "friction_clutch_friction": 0.15,
    "friction_clutch_outer_diameter": 0.07,
    "friction_clutch_inner_diameter": 0.04,
    "friction_clutch_faces": 2,
}
# uniform wear: R_f = (70 + 40)/4 = 27.5 mm; M_tr = 2 × 0.15 × 800 N × 0.0275 m = 6.6 N·m
M_TR = 2 * 0.15 * 800.0 * 0.0275


def test_friction_radius_by_hand():
    # a full disc: uniform pressure R = D/3, uniform wear R = D/4 (a third less torque)
    assert friction_clutch_torque(100.0, 0.2, 0.06, 0.0) == pytest.approx(100 * 0.2 * 0.015)
    assert friction_clutch_torque(100.0, 0.2, 0.06, 0.0, law="uniform_pressure") == (
        pytest.approx(100 * 0.2 * 0.02)
    )
    # a narrow ring: both laws tend to the mean radius
    narrow = [
        friction_clutch_torque(1.0, 1.0, 0.1, 0.0999, law=k)
        for k in ("uniform_wear", "uniform_pressure")
    ]
    assert narrow[0] == pytest.approx(0.05, rel=1e-3)  # the ring's radius, 50 mm
    assert narrow[1] == pytest.approx(narrow[0], rel=1e-6)
    np.testing.assert_allclose(
        friction_clutch_torque(np.array([400.0, 800.0]), 0.15, 0.07, 0.04, 2), [M_TR / 2, M_TR]
    )


def test_the_clamp_sets_the_torque_the_idle_spindles_take():
    base = {**EXAMPLE_LIGHT_TRUCK, "idle_spindle_friction_torque": 0.0}
    r = engine.run(NUTRUNNER_DRIVE, {**base, **CLAMP})
    pin(
        "nutrunner.drive",
        "friction_clutch_torque",
        r.results["friction_clutch_torque"],
        M_TR,
        rel=1e-12,
    )
    assert pytest.approx(6.6) == M_TR
    # eq. 10 with that M_tr: six spindles, five idle
    m = r.results["impact_torque"]
    pin(
        "nutrunner.drive",
        "max_spindle_torque",
        r.results["max_spindle_torque"],
        m - 5 * M_TR,
        rel=1e-12,
    )
    # the same as typing M_tr in directly
    typed = engine.run(NUTRUNNER_DRIVE, {**base, "idle_spindle_friction_torque": M_TR})
    assert typed.results["max_spindle_torque"] == pytest.approx(
        r.results["max_spindle_torque"], rel=1e-15
    )
    assert typed.results["friction_clutch_torque"] == M_TR  # the typed M_tr, as used


def test_the_clamp_on_the_array_path():
    base = {**EXAMPLE_LIGHT_TRUCK, "idle_spindle_friction_torque": 0.0, **CLAMP}
    forces = [200.0, 800.0, 1600.0]
    s = engine.sweep(NUTRUNNER_DRIVE, base, "friction_clutch_clamp_force", forces)
    np.testing.assert_allclose(
        s.results["friction_clutch_torque"], [M_TR * f / 800.0 for f in forces], rtol=1e-12
    )


def test_a_partial_or_a_second_m_tr_is_said():
    # the clamp without its friction: M_tr stays the typed one, a warning says why
    part = {**EXAMPLE_LIGHT_TRUCK, "friction_clutch_clamp_force": 800.0}
    r = engine.run(NUTRUNNER_DRIVE, part)
    assert r.results["friction_clutch_torque"] == 10.0
    assert any("without friction_clutch_friction" in w for w in r.warnings)
    # the whole clamp and a typed M_tr: the clamp's, and a warning
    both = engine.run(NUTRUNNER_DRIVE, {**EXAMPLE_LIGHT_TRUCK, **CLAMP})
    assert both.results["friction_clutch_torque"] == pytest.approx(M_TR, rel=1e-12)
    assert any("idle_spindle_friction_torque is not used" in w for w in both.warnings)


def test_a_ring_inside_out_is_refused():
    x = {**EXAMPLE_LIGHT_TRUCK, **CLAMP, "friction_clutch_inner_diameter": 0.08}
    with pytest.raises(engine.InputOutOfRange) as err:
        engine.run(NUTRUNNER_DRIVE, x)
    assert err.value.field == "friction_clutch_inner_diameter"
