"""engine.physics.motor_spinup: the torque-limited branch by hand, the quadrature's accuracy
on one panel, and the keyword-only tolerance."""

import math

import numpy as np
import pytest

from engine.core.errors import InfeasibleDesign
from engine.physics import motor_spinup as ms


def test_constant_power_below_the_corner_speed_is_the_torque_limit_alone():
    # ω_c = P/M_c = 1000/100 = 10 rad/s; up to it t = J ω / M_c, above it J(ω² + ω_c²)/(2P)
    assert ms.torque_limited_constant_power_spin_up_time(0.01, 1000.0, 100.0, 5.0) == (
        pytest.approx(0.01 * 5.0 / 100.0, rel=1e-12)
    )
    assert ms.torque_limited_constant_power_spin_up_time(0.01, 1000.0, 100.0, 10.0) == (
        pytest.approx(0.01 * 10.0 / 100.0, rel=1e-12)
    )
    # both branches meet at ω_c: J ω_c/M_c = J (2 ω_c²)/(2P)
    above = ms.torque_limited_constant_power_spin_up_time(0.01, 1000.0, 100.0, 10.0 * (1 + 1e-12))
    assert above == pytest.approx(0.001, rel=1e-9)
    assert ms.torque_limited_constant_power_spin_up_time(0.02, 500.0, 50.0, 4.0) == (
        pytest.approx(0.02 * 4.0 / 50.0, rel=1e-12)
    )


def test_one_gauss_panel_integrates_a_kloss_spin_up_to_1e_10():
    # one 8-node Gauss–Legendre panel in x = −ln(1 − ω/ω_s) from 0 to 95 % of ω_s
    # (s_k = 0.28): within 1.1e-11 of Kloss's closed form (7 nodes: 1.2e-9)
    curve = ms.MotorCurve(
        "induction",
        lambda w: ms.kloss_torque(w, 20.0, 157.0, 0.28),
        157.0,
        (),
        lambda g: ms.kloss_slip_torque(g / 157.0, 20.0, 0.28),
    )
    w = 157.0 * 0.95
    exact = ms.kloss_spin_up_time(0.016, 20.0, 157.0, 0.28, w)
    t, speeds = ms.spin_up_profile(0.016, curve, w, points=2)
    assert t[-1] == pytest.approx(exact, rel=1e-10)
    assert speeds.tolist() == [0.0, w]


def test_the_tolerance_is_keyword_only_and_the_design_is_named_or_positional():
    curve = ms.MotorCurve("linear", lambda w: ms.linear_motor_torque(w, 10.0, 200.0), 200.0)
    exact = 0.01 * 200 / 10 * math.log(2.0)  # J ω0/M_s ln(ω0/(ω0 − ω))
    t, _ = ms.spin_up_time(equivalent_inertia=0.01, curve=curve, speed=100.0, rtol=1e-12)
    assert t == pytest.approx(exact, rel=1e-10)
    with pytest.raises(TypeError):
        ms.spin_up_time(0.01, curve, 100.0, 1e-12)  # rtol only by name


def test_profile_of_a_curve_without_a_limit_speed_by_hand():
    # M = min(M_c, P/ω), M_c = 100 N·m, P = 1 kW: corner ω_c = 10 rad/s (a kink the profile
    # keeps as a point); t(ω) = J ω/M_c below it, J (ω² + ω_c²)/(2P) above: 1/M is piecewise
    # polynomial, so each Gauss panel is exact
    j, p, m_c = 0.01, 1000.0, 100.0
    curve = ms.MotorCurve(
        "power", lambda w: np.minimum(m_c, p / np.maximum(w, 1e-300)), None, (10.0,)
    )
    t, w = ms.spin_up_profile(j, curve, 25.0, points=6)
    assert w.tolist() == pytest.approx([0.0, 5.0, 10.0, 15.0, 20.0, 25.0], abs=1e-12)
    expected = [
        ms.torque_limited_constant_power_spin_up_time(j, p, m_c, float(x)) if x else 0.0 for x in w
    ]
    assert t.tolist() == pytest.approx(expected, rel=1e-12, abs=1e-15)
    assert t[2] == pytest.approx(j * 10.0 / m_c, rel=1e-12)
    assert t[-1] == pytest.approx(j * (25.0**2 + 10.0**2) / (2 * p), rel=1e-12)
    # a kink between the grid's points is added as a point of its own
    t7, w7 = ms.spin_up_profile(j, curve, 24.0, points=4)  # grid 0, 8, 16, 24 and 10
    assert w7.tolist() == pytest.approx([0.0, 8.0, 10.0, 16.0, 24.0], abs=1e-12)
    assert t7[2] == pytest.approx(j * 10.0 / m_c, rel=1e-12)


def test_a_speed_beyond_the_limit_is_refused_in_rad_s_and_rpm():
    curve = ms.MotorCurve("linear", lambda w: ms.linear_motor_torque(w, 10.0, 200.0), 200.0)
    with pytest.raises(InfeasibleDesign) as err:
        ms.spin_up_profile(0.01, curve, 250.0)
    assert f"working speed 250 rad/s ({250 * 30 / math.pi:.0f} rpm)" in str(err.value)
    assert f"zero at 200 rad/s ({200 * 30 / math.pi:.0f} rpm)" in str(err.value)  # 1910 rpm
    assert err.value.field == "motor_speed"
