"""The nut-runner's rung estimates take arrays, so its sweeps never loop per point."""

import numpy as np

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
