"""The nut-runner's rung estimates take arrays, so its sweeps never loop per point."""

import numpy as np
import pytest

import engine
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE


def _inputs(**changes):
    values, _ = NUTRUNNER_DRIVE.validate({**EXAMPLE_LIGHT_TRUCK, **changes})
    return values


def test_estimates_on_arrays_equal_the_per_point_estimates_bit_for_bit():
    # spans both sides of the idle-spindle friction test (M > (z-1)·M_tr adds a third ratio)
    friction = np.array([0.0, 1.0, 50.0, 500.0, 5000.0])
    x = {**_inputs(), "idle_spindle_friction_torque": friction}
    for rung in NUTRUNNER_DRIVE.rungs[:2]:
        on_arrays = np.asarray(rung.estimate(x))
        one_by_one = [rung.estimate(_inputs(idle_spindle_friction_torque=f)) for f in friction]
        assert on_arrays.shape == friction.shape or on_arrays.ndim == 0
        assert np.broadcast_to(on_arrays, friction.shape).tolist() == one_by_one
        assert all(type(e) is float for e in one_by_one)  # scalars stay Python floats


def test_a_sweep_does_not_run_the_points_one_by_one():
    import dataclasses

    calls = []

    def counted(x, ctx):
        calls.append(x["motor_speed"])
        return NUTRUNNER_DRIVE.compute(x, ctx)

    spec = dataclasses.replace(NUTRUNNER_DRIVE, compute=counted)
    speeds = np.linspace(100.0, 160.0, 50).tolist()
    s = engine.sweep(spec, EXAMPLE_LIGHT_TRUCK, "motor_speed", speeds, tolerance=0.5)
    assert None not in s.rungs and len(s.error_estimates) == 50
    # at most one scalar call per rung group: the probe for an output the array path lacks
    assert len(calls) <= len(set(s.rungs))
    ref = engine.run(
        NUTRUNNER_DRIVE, {**EXAMPLE_LIGHT_TRUCK, "motor_speed": speeds[7]}, tolerance=0.5
    )
    assert s.rungs[7] == ref.rung and s.error_estimates[7] == ref.error_estimate
    assert s.results["impact_torque"][7] == ref.results["impact_torque"]


def test_series_only_when_asked_for_or_named():
    from engine.models.nutrunner import EXAMPLE_INDUCTION_MOTOR

    plain = engine.run(NUTRUNNER_DRIVE, EXAMPLE_INDUCTION_MOTOR, fidelity="motor_curve")
    assert plain.series == {} and "time" not in plain.units
    named = engine.run(
        NUTRUNNER_DRIVE,
        EXAMPLE_INDUCTION_MOTOR,
        fidelity="motor_curve",
        outputs=["motor_speed_curve"],
    )
    assert set(named.series) == {"motor_speed_curve"} and named.results == {}
    every = engine.run(
        NUTRUNNER_DRIVE, EXAMPLE_INDUCTION_MOTOR, fidelity="motor_curve", series=True
    )
    assert set(every.series) == {"time", "motor_speed_curve", "flywheel_speed_curve"}
    assert every.results == plain.results


def _curves():
    """Each motor curve on the light truck's drive, with the inputs it needs."""
    from engine.models.nutrunner import EXAMPLE_INDUCTION_MOTOR

    w = EXAMPLE_LIGHT_TRUCK["motor_speed"]
    return {
        "induction": dict(EXAMPLE_INDUCTION_MOTOR),
        "linear": {
            **EXAMPLE_LIGHT_TRUCK,
            "motor_curve": "linear",
            "stall_torque": 30.0,
            "no_load_speed": 1.1 * w,
            "rotor_inertia": 0.0035,
        },
        "constant_power": {
            **EXAMPLE_LIGHT_TRUCK,
            "motor_curve": "constant_power",
            "stall_torque": 12.0,
        },
    }


def test_motor_curve_estimates_on_arrays_equal_single_runs():
    # the motor speed swept past the no-load and synchronous speeds (1500 rpm): there the
    # motor never gets to speed and the estimate is 1 on both paths
    speeds = np.linspace(100.0, 170.0, 41).tolist()
    for kind, base in _curves().items():
        for rung in ("closed_form", "gear_ratio"):
            s = engine.sweep(NUTRUNNER_DRIVE, base, "motor_speed", speeds, fidelity=rung)
            assert s.rungs == [rung] * len(speeds), kind
            for j in (0, 13, 27, 40):
                one = engine.run(NUTRUNNER_DRIVE, {**base, "motor_speed": speeds[j]}, fidelity=rung)
                assert s.error_estimates[j] == pytest.approx(one.error_estimate, rel=1e-12)
            if kind != "constant_power":
                assert s.error_estimates[-1] == 1.0, kind  # past the curve's zero torque
            if rung == "gear_ratio":  # the curve's estimate alone: it varies and bites
                assert min(s.error_estimates) < 0.5, kind


def test_motor_curve_closed_forms_against_the_quadrature():
    # the estimate's closed forms (one equation per curve) against the motor_curve rung's
    # quadrature of J dω/M(ω), two independent ways to the same time
    from engine.models.nutrunner import _curve_time, _drive_inertia, _motor_curve
    from engine.physics.motor_spinup import spin_up_time

    for kind, base in _curves().items():
        for w in (120.0, 140.0, 155.0):
            x = _inputs(**{**base, "motor_speed": w})
            j = _drive_inertia(x)
            want, _ = spin_up_time(j, _motor_curve(x), w, rtol=1e-12)
            assert float(_curve_time(x, j)) == pytest.approx(want, rel=1e-12), (kind, w)


def test_a_motor_curve_sweep_does_not_integrate_per_point(monkeypatch):
    from engine.models import nutrunner

    def refused(*args, **kwargs):
        raise AssertionError("a quadrature per point")

    monkeypatch.setattr(nutrunner, "spin_up_time", refused)
    s = engine.sweep(
        NUTRUNNER_DRIVE, _curves()["induction"], "motor_power", np.linspace(900, 1300, 300).tolist()
    )
    assert None not in s.rungs
