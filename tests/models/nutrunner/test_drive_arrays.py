"""nutrunner.drive's array path reports every check with the scalar verdicts, point by point.

Spreads wide enough that each check passes somewhere and fails somewhere: the idle
spindles' friction absorbing the blow, spindle gears overlapping on their circle, shaft
and spindle yielding. The reference is the scalar compute run point by point.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import engine
from engine.core.spec import RunContext
from engine.models.nutrunner import EXAMPLE_INDUCTION_MOTOR, EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable, evaluate_chunk, plan

SPEC = NUTRUNNER_DRIVE
LOOP = dataclasses.replace(SPEC, vectorized=None, vector_rungs=())
OUTPUTS = ["impact_torque", "max_spindle_torque", "shaft_shear_stress", "spindle_shear_stress"]


def _columns(n: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    return {
        "idle_spindle_friction_torque": rng.uniform(0.0, 400.0, n),
        "spindle_gear_diameter": rng.uniform(0.02, 0.2, n),
        "spindle_diameter": rng.uniform(0.015, 0.05, n),
        "shaft_diameter": rng.uniform(0.02, 0.06, n),
        "motor_speed": rng.uniform(100.0, 200.0, n),
    }


@pytest.mark.parametrize("rung", ["closed_form", "gear_ratio"])
def test_check_verdicts_equal_the_loop_and_split(rung):
    base = {**EXAMPLE_LIGHT_TRUCK, "shear_yield_strength": 4e8}
    cols = _columns(80, seed=2)
    fast = evaluate_chunk(SPEC, base, cols, OUTPUTS, fidelity=rung)
    slow = evaluate_chunk(LOOP, base, cols, OUTPUTS, fidelity=rung)
    assert (
        sorted(fast.checks)
        == sorted(slow.checks)
        == [
            "max_spindle_torque_positive",
            "shaft_elastic",
            "spindle_elastic",
            "spindle_gears_fit",
            "wheel_nut_torque",
        ]
    )
    for name, verdicts in slow.checks.items():
        np.testing.assert_array_equal(fast.checks[name], verdicts, err_msg=name)
        assert (verdicts == 1).any() and (verdicts == 0).any(), f"{name} never splits"
    for name in OUTPUTS:
        np.testing.assert_allclose(fast.values[name], slow.values[name], rtol=1e-12)


def test_one_spindle_reports_no_gear_fit():
    # a sweep over the (integer) spindle count: z = 1 has no neighbouring gear to hit
    x, _ = SPEC.validate(EXAMPLE_LIGHT_TRUCK)
    z = np.arange(1, 33)
    ctx = engine.RunContext("closed_form", frozenset(OUTPUTS), 0.01)
    got = SPEC.vectorized({**x, "spindle_count": z}, ctx).check_arrays["spindle_gears_fit"]
    for j, count in enumerate(z.tolist()):
        one = engine.run(SPEC, {**EXAMPLE_LIGHT_TRUCK, "spindle_count": count})
        verdict = {c.name: c.ok for c in one.checks}.get("spindle_gears_fit")
        assert got[j] == (-1 if verdict is None else int(verdict)), count
    # 6 gears of 50 mm on a 150 mm circle fit; 32 do not
    assert got[5] == 1 and got[-1] == 0


def test_study_pass_fractions_equal_single_runs():
    study = Study(
        variables=(
            Variable("idle_spindle_friction_torque", "uniform", low=0.0, high=300.0),
            Variable("spindle_gear_diameter", "triangular", low=0.03, high=0.16, mode=0.05),
            Variable("spindle_diameter", "normal", mean=0.03, sd=0.006),
        ),
        base={
            k: v
            for k, v in {**EXAMPLE_LIGHT_TRUCK, "shear_yield_strength": 4e8}.items()
            if k
            not in ("idle_spindle_friction_torque", "spindle_gear_diameter", "spindle_diameter")
        },
        samples=200,
        seed=4,
        outputs=("impact_torque",),
    )
    result = run_study(SPEC, study)
    points = plan(SPEC, study).columns
    counts: dict[str, list[int]] = {}
    for j in range(study.samples):
        point = {**study.base, **{k: float(v[j]) for k, v in points.items()}}
        for c in engine.run(SPEC, point, outputs=["impact_torque"]).checks:
            counts.setdefault(c.name, [0, 0])[0 if c.ok else 1] += 1
    summary = result.summary["checks"]
    assert sorted(summary) == sorted(counts)
    for name, (passed, failed) in counts.items():
        assert (summary[name]["passed"], summary[name]["failed"]) == (passed, failed), name
    assert sum(p > 0 and f > 0 for p, f in counts.values()) >= 3


def test_estimates_take_arrays_with_a_motor_curve():
    # one quadrature per point: the same numbers as the scalar estimate, no looped chunk
    x, _ = SPEC.validate(EXAMPLE_INDUCTION_MOTOR)
    power = np.array([800.0, 1100.0, 1500.0])
    for rung in SPEC.rungs:
        on_arrays = np.broadcast_to(np.asarray(rung.estimate({**x, "motor_power": power})), (3,))
        for j, p in enumerate(power.tolist()):
            one = rung.estimate({**x, "motor_power": p})
            assert on_arrays[j] == one, (rung.name, p)
    # a breakdown torque below the rated one refuses the curve: the estimate is then 1
    weak = {**x, "breakdown_torque": np.array([1.0, x["breakdown_torque"]])}
    est = np.asarray(SPEC.rung("gear_ratio").estimate(weak))
    assert est[0] == 1.0 and 0.0 < est[1] < 1.0


def test_huge_and_tiny_inputs_stay_consistent():
    # the extremes of the declared ranges: verdicts still equal the loop, nothing raises
    base = {**EXAMPLE_LIGHT_TRUCK, "shear_yield_strength": 1e6}
    cols = {
        "motor_speed": np.array([0.1, 1.0, 1e2, 1e4, 1e4]),
        "flywheel_mass": np.array([1e-300, 1e-3, 12.0, 1e3, 1e3]),
        "spindle_diameter": np.array([1e-4, 1e-2, 0.03, 2.0, 1e-4]),
    }
    fast = evaluate_chunk(SPEC, base, cols, OUTPUTS, fidelity="closed_form")
    slow = evaluate_chunk(LOOP, base, cols, OUTPUTS, fidelity="closed_form")
    for name, verdicts in slow.checks.items():
        np.testing.assert_array_equal(fast.checks[name], verdicts, err_msg=name)
    for name in OUTPUTS:
        np.testing.assert_allclose(
            fast.values[name], slow.values[name], rtol=1e-12, atol=1e-300, equal_nan=True
        )
    assert math.isfinite(fast.values["impact_torque"][2])


@pytest.mark.parametrize("rung", ["closed_form", "gear_ratio"])
@pytest.mark.parametrize(
    ("outs", "skipped"),
    [
        # the floor's outputs: no spindle torque, reserve or detail nobody asked for
        (
            ("kinetic_energy", "acceleration_time", "impact_torque"),
            ("max_spindle_torque", "spindle_torque_reserve", "flywheel_energy", "shaft_twist"),
        ),
        # the reserve reads the spindle torque, which is then computed; the energy is not
        (
            ("spindle_torque_reserve",),
            ("kinetic_energy", "acceleration_time", "impact_torque", "flywheel_speed"),
        ),
        # a detail: the part energies and speeds, as the checks-reading path gives them
        (
            ("flywheel_energy", "spindle_gear_speed", "shaft_shear_stress"),
            ("kinetic_energy", "max_spindle_torque"),
        ),
    ],
)
def test_a_caller_reading_no_checks_gets_the_asked_outputs_alone_and_the_same(rung, outs, skipped):
    base = {**EXAMPLE_LIGHT_TRUCK, "shear_yield_strength": 4e8}
    cols = _columns(60, seed=5)
    x, _ = SPEC.validate(base)
    lean = SPEC.vectorized({**x, **cols}, RunContext(rung, frozenset(outs), 0.01, checks=False))
    full = SPEC.vectorized({**x, **cols}, RunContext(rung, frozenset(outs), 0.01))
    slow = evaluate_chunk(LOOP, base, cols, list(outs), fidelity=rung)
    for name in outs:
        np.testing.assert_array_equal(lean.values[name], full.values[name], err_msg=name)
        # the same functions on floats and on arrays: the same bits
        np.testing.assert_array_equal(lean.values[name], slow.values[name], err_msg=name)
    assert lean.check_arrays == {} and full.check_arrays
    for name in skipped:  # the checks-reading path computes them, a lean caller does not
        assert name not in lean.values, name
        assert name in full.values, name


def test_a_lean_sweep_of_the_motor_speed_equals_the_hand_sum():
    """T = Σ ½ J_k ω_k² with J = m D²/8 [000, eq. 1–4], ω3 = ω D2/D3, ω5 = ω3 D4/D5."""
    w = np.array([100.0, 150.0])
    got = engine.sweep(SPEC, EXAMPLE_LIGHT_TRUCK, "motor_speed", w, outputs=("kinetic_energy",))
    e = EXAMPLE_LIGHT_TRUCK
    for i, speed in enumerate(w):
        w3 = speed * 0.08 / 0.25
        w5 = w3 * 0.10 / 0.05
        parts = (
            1.2 * 0.09**2 / 8 * speed**2,
            0.8 * 0.08**2 / 8 * speed**2,
            12.0 * 0.25**2 / 8 * w3**2,
            2.5 * 0.10**2 / 8 * w3**2,
            e["spindle_count"] * 0.5 * 0.05**2 / 8 * w5**2,
        )
        assert got.columns["kinetic_energy"][i] == pytest.approx(0.5 * sum(parts), rel=1e-14)


@pytest.mark.parametrize("rung", ["closed_form", "gear_ratio"])
def test_single_runs_and_the_array_path_agree_bit_for_bit(rung):
    # one function per equation, written with products rather than powers (Python's float
    # power and numpy's differ in the last bit): a study's or a sweep's values are the
    # single runs' exactly, every part of the drive varied at once
    rng = np.random.default_rng(11)
    n = 40
    cols = {
        **_columns(n, seed=7),
        **{
            name: EXAMPLE_LIGHT_TRUCK[name] * rng.uniform(0.5, 1.5, n)
            for name in (
                "coupling_mass",
                "coupling_diameter",
                "motor_pulley_diameter",
                "flywheel_mass",
                "flywheel_diameter",
                "drive_gear_diameter",
                "spindle_gear_mass",
                "shaft_length",
                "motor_power",
            )
        },
        "spindle_count": rng.integers(1, 13, n).astype(float),
    }
    outs = [
        o.name
        for o in SPEC.outputs
        if not o.series
        and o.name not in ("drive_inertia", "constant_power_time")
        and o.name != "time_vs_constant_power"
    ]
    fast = evaluate_chunk(SPEC, EXAMPLE_LIGHT_TRUCK, cols, outs, fidelity=rung)
    slow = evaluate_chunk(LOOP, EXAMPLE_LIGHT_TRUCK, cols, outs, fidelity=rung)
    assert "kinetic_energy" in outs and "equivalent_inertia" in outs
    for name in outs:
        np.testing.assert_array_equal(fast.values[name], slow.values[name], err_msg=name)
