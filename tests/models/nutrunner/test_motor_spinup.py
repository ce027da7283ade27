"""Spin-up on a real motor curve: quadrature against closed forms, and the motor_curve rung."""

from __future__ import annotations

import math

import numpy as np
import pytest

from engine import InfeasibleDesign, InputOutOfRange, SolverFailed, run
from engine.models.nutrunner import EXAMPLE_INDUCTION_MOTOR, EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE
from engine.physics.motor_spinup import (
    MotorCurve,
    kloss_breakdown_slip,
    kloss_slip_torque,
    kloss_spin_up_time,
    kloss_torque,
    linear_motor_torque,
    linear_spin_up_time,
    spin_up_profile,
    spin_up_time,
    torque_limited_constant_power_spin_up_time,
)

SPEC = NUTRUNNER_DRIVE
BASE = EXAMPLE_LIGHT_TRUCK
W = 1400 * math.pi / 30
W_SYNC = 1500 * math.pi / 30
J_EQ = 0.012159  # parts 1…5 at the motor shaft, see test_drive.py
T_CP = 0.5 * J_EQ * W**2 / 1100.0  # the source's constant-power time, 0.118792 s


def _linear(m_st, w0):
    return MotorCurve(
        "linear", lambda w: linear_motor_torque(w, m_st, w0), w0, (), lambda g: m_st * g / w0
    )


def _kloss(m_k, w_s, s_k):
    return MotorCurve(
        "induction",
        lambda w: kloss_torque(w, m_k, w_s, s_k),
        w_s,
        (),
        lambda g: kloss_slip_torque(g / w_s, m_k, s_k),
    )


def test_linear_rung_by_hand():
    x = {**BASE, "motor_curve": "linear", "stall_torque": 30.0, "no_load_speed": W_SYNC}
    r = run(SPEC, x, fidelity="motor_curve")
    # t = J ω0/M_st · ln(ω0/(ω0 − ω)) = 0.012159·157.0796/30 · ln(15) = 0.0636644·2.70805
    t = J_EQ * W_SYNC / 30.0 * math.log(15.0)
    assert t == pytest.approx(0.172406, rel=1e-5)
    assert r.results["acceleration_time"] == pytest.approx(t, rel=1e-12)
    assert r.results["constant_power_time"] == pytest.approx(T_CP, rel=1e-12)
    assert r.results["time_vs_constant_power"] == pytest.approx(t / T_CP - 1, rel=1e-10)
    assert r.results["drive_inertia"] == pytest.approx(J_EQ, rel=1e-12)
    assert r.error_estimate is not None and r.error_estimate < 1e-8
    # the torque model of this rung is the geared one
    g = run(SPEC, BASE, fidelity="gear_ratio").results
    assert r.results["impact_torque"] == pytest.approx(g["impact_torque"], rel=1e-14)
    (reach,) = [c for c in r.checks if c.name == "motor_reaches_speed"]
    assert reach.ok and "1400 rpm" in reach.detail
    assert any("+45.1%" in n for n in r.notes)  # 0.172406/0.118792 − 1


def test_induction_rung_by_hand():
    r = run(SPEC, EXAMPLE_INDUCTION_MOTOR, fidelity="motor_curve")
    # J = 0.0035 + 0.001855 + 0.00992/0.95 + 0.000384/(0.95·0.97) = 0.0162138 kg·m²
    j = 0.0035 + 0.001855 + 0.00992 / 0.95 + 0.000384 / (0.95 * 0.97)
    assert r.results["drive_inertia"] == pytest.approx(j, rel=1e-12)
    # s_n = 1/15, M_n = 1100/146.6077 = 7.50302, M_k = 2.2·M_n, s_k = s_n(2.2 + √3.84) = 0.277306
    s_k = (1 / 15) * (2.2 + math.sqrt(2.2**2 - 1))
    assert s_k == pytest.approx(0.277306, rel=1e-5)
    m_k = 2.2 * 1100 / W
    # t = Jω_s/(2M_k)·[(1 − s_e²)/(2s_k) − s_k ln s_e], s_e = 1/15
    #   = 0.0771474·[1.795019 + 0.750958] = 0.196415 s
    s_e = 1 / 15
    t = j * W_SYNC / (2 * m_k) * ((1 - s_e**2) / (2 * s_k) - s_k * math.log(s_e))
    assert t == pytest.approx(0.196415, rel=1e-5)
    assert r.results["acceleration_time"] == pytest.approx(t, rel=1e-11)
    assert r.results["time_vs_constant_power"] == pytest.approx(t / T_CP - 1, rel=1e-10)


def test_constant_power_curve_reproduces_t_equals_T_over_P():
    """Constant power from standstill needs infinite torque at ω = 0, so the curve is
    min(M_c, P/ω). Its time exceeds T/P by exactly (ω_c/ω)², ω_c = P/M_c."""
    for m_c, excess in ((100.0, (11.0 / W) ** 2), (1e3, (1.1 / W) ** 2), (1e5, (0.011 / W) ** 2)):
        x = {**BASE, "motor_curve": "constant_power", "stall_torque": m_c}
        v = run(SPEC, x, fidelity="motor_curve").results
        assert v["time_vs_constant_power"] == pytest.approx(excess, rel=1e-7)
        assert v["acceleration_time"] == pytest.approx(
            torque_limited_constant_power_spin_up_time(J_EQ, 1100.0, m_c, W), rel=1e-10
        )
    # at M_c = 1e5 N·m the difference from the paper's T/P is 5.6e-9
    assert excess < 1e-8


def test_quadrature_against_closed_forms_on_a_grid():
    for ratio in (0.01, 0.5, 0.9, 0.999, 1 - 1e-6, 1 - 1e-12):
        t, err = spin_up_time(0.3, _linear(50.0, 100.0), 100.0 * ratio)
        exact = linear_spin_up_time(0.3, 50.0, 100.0, 100.0 * ratio)
        assert t == pytest.approx(exact, rel=1e-12) and err <= 1e-9 * t
    for s_k in (0.05, 0.3, 1.5):
        for s_e in (0.5, 0.05, 1e-3, 1e-9):
            t, err = spin_up_time(0.2, _kloss(40.0, 157.0, s_k), 157.0 * (1 - s_e))
            exact = kloss_spin_up_time(0.2, 40.0, 157.0, s_k, 157.0 * (1 - s_e))
            assert t == pytest.approx(exact, rel=1e-9), (s_k, s_e)
            assert err <= 1e-8 * t


def test_spin_up_profile_ends_at_the_quadrature_time():
    curve = _kloss(20.0, W_SYNC, 0.28)
    t_end, _ = spin_up_time(0.016, curve, W)
    t, w = spin_up_profile(0.016, curve, W)
    assert t[0] == 0.0 and w[0] == 0.0 and w[-1] == W
    assert np.all(np.diff(t) > 0) and np.all(np.diff(w) > 0)
    assert t[-1] == pytest.approx(t_end, rel=1e-10)


def test_motor_curve_series_when_asked():
    r = run(
        SPEC,
        EXAMPLE_INDUCTION_MOTOR,
        fidelity="motor_curve",
        outputs=["time", "motor_speed_curve", "flywheel_speed_curve", "acceleration_time"],
    )
    assert len(r.series["time"]) == len(r.series["motor_speed_curve"]) == 101
    assert r.series["time"][-1] == pytest.approx(r.results["acceleration_time"], rel=1e-8)
    assert r.series["flywheel_speed_curve"][-1] == pytest.approx(0.32 * W)
    assert run(SPEC, EXAMPLE_INDUCTION_MOTOR, fidelity="motor_curve", outputs=["time"]).series


def test_losses_and_rotor_lengthen_spin_up_in_proportion_to_inertia():
    x = {**BASE, "motor_curve": "linear", "stall_torque": 30.0, "no_load_speed": W_SYNC}
    a = run(SPEC, x, fidelity="motor_curve").results
    b = run(SPEC, {**x, "rotor_inertia": 0.004, "belt_efficiency": 0.9}, fidelity="motor_curve")
    j = 0.004 + 0.001855 + 0.00992 / 0.9 + 0.000384 / 0.9
    assert b.results["acceleration_time"] / a["acceleration_time"] == pytest.approx(j / J_EQ)
    # the blow is unchanged: the rotor sits behind the slipping coupling
    assert b.results["impact_torque"] == a["impact_torque"]


def test_kloss_curve_passes_through_rated_and_breakdown_points():
    s_k = kloss_breakdown_slip(W, W_SYNC, 2.2)
    m_n = 1100 / W
    assert kloss_torque(W, 2.2 * m_n, W_SYNC, s_k) == pytest.approx(m_n, rel=1e-12)
    assert kloss_torque(W_SYNC * (1 - s_k), 2.2 * m_n, W_SYNC, s_k) == pytest.approx(2.2 * m_n)


def test_motor_curve_input_errors_name_fields():
    with pytest.raises(InputOutOfRange) as e:
        run(SPEC, {**BASE, "motor_curve": "linear", "stall_torque": 30.0}, fidelity="motor_curve")
    assert e.value.field == "no_load_speed"
    induction = {**BASE, "motor_curve": "induction", "synchronous_speed": W_SYNC}
    with pytest.raises(InputOutOfRange) as e:
        run(SPEC, {**induction, "breakdown_torque": 5.0}, fidelity="motor_curve")
    assert e.value.field == "breakdown_torque"  # below rated 7.5 N·m
    # the closed form ignores the curve; only the motor rung refuses
    assert run(SPEC, {**induction, "breakdown_torque": 20.0, "synchronous_speed": W}).results
    with pytest.raises(InputOutOfRange) as e:
        run(
            SPEC,
            {**induction, "breakdown_torque": 20.0, "synchronous_speed": W},
            fidelity="motor_curve",
        )
    assert e.value.field == "synchronous_speed"


def test_induction_working_speed_at_or_above_synchronous_is_infeasible():
    x = {
        **EXAMPLE_INDUCTION_MOTOR,
        "rated_speed": 0.9 * W,
        "synchronous_speed": W,
    }
    with pytest.raises(InfeasibleDesign, match="torque falls to zero"):
        run(SPEC, x, fidelity="motor_curve")


def test_quadrature_without_gap_form_still_converges_or_says_so():
    """Without torque_below_limit, 1 − ω/ω0 loses digits close to ω0; never a silent answer."""
    curve = MotorCurve("linear", lambda w: linear_motor_torque(w, 50.0, 100.0), 100.0)
    for ratio in (0.9, 1 - 1e-6, 1 - 1e-12):
        try:
            t, err = spin_up_time(0.3, curve, 100.0 * ratio)
        except SolverFailed as exc:
            assert "did not converge" in exc.message
            continue
        exact = linear_spin_up_time(0.3, 50.0, 100.0, 100.0 * ratio)
        assert abs(t - exact) <= max(err, 1e-12 * exact) * 10


def test_negative_torque_on_the_way_is_infeasible():
    curve = MotorCurve("odd", lambda w: 10.0 - 0.25 * w + 0.001 * w**2)  # < 0 near 125
    with pytest.raises(InfeasibleDesign, match="not positive"):
        spin_up_time(0.1, curve, 150.0)


def test_constant_power_rungs_say_what_the_given_curve_would_change():
    r = run(SPEC, EXAMPLE_INDUCTION_MOTOR)  # default rung: the paper's
    assert r.rung == "closed_form"
    # 0.196415/0.118792 − 1 = +65.3 %; the estimate is the larger of |T/P / t_curve − 1| =
    # 0.395 and the gear ratio's effect on the shaft torque, u·M(u)/M − 1 = 0.668
    assert any("changes the spin-up time by +65.3%" in n for n in r.notes)
    idealisation = 1 - 0.118792 / 0.196415
    shaft = 2 * (1 + r.results["gear_ratio_torque_change"]) - 1
    assert r.error_estimate == pytest.approx(max(idealisation, shaft), rel=1e-4)
    assert shaft > idealisation
    bad = run(SPEC, {**EXAMPLE_INDUCTION_MOTOR, "synchronous_speed": 100.0}, fidelity="gear_ratio")
    assert any("it fails: rated_speed" in n for n in bad.notes)
