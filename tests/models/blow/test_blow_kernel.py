"""The blow's compiled kernel (engine.physics.blow) against the lean kernel kept in
bench/extra_blow_lean.py, and the single-design run's work kept to what is asked for."""

from __future__ import annotations

import math

import numpy as np
import pytest

import engine
from engine.physics.blow import (
    BlowProblem,
    _damping_ratio,
    blow_series,
    contact_restitution,
    simulate_blow,
)

BLOW = engine.get_model("blow.joint")


@pytest.mark.slow  # the lean kernel compiles (a few seconds) on a fresh clone
def test_the_kernel_and_the_lean_kernel_give_the_same_blow_bit_for_bit() -> None:
    # the same equations, the same steps, the same event and maximum searches: the
    # lean floor the kernel is timed against computes the very same numbers
    from bench.extra_blow_lean import _cases, _lean

    for p, t0 in _cases().values():
        out = simulate_blow(p, t0)
        peak, rotation, steps = _lean(p, t0)()
        assert (out.peak_torque, out.rotation, out.steps) == (peak, rotation, steps)


def test_the_two_flywheel_blow_by_hand() -> None:
    # struck side free (T0 = k_j = 0), lossless: the spring takes the relative motion's
    # energy, T_peak = √(2E·C·J_s/(J_t + J_s)) with E = ½·J_t·ω0²; the blow ends with
    # the jaws parting, all energy back in the two flywheels (0 into the joint)
    jt, js, c, w0 = 21.07, 63.21, 203.4, 150 * math.pi / 30
    e = 0.5 * jt * w0 * w0
    out = simulate_blow(BlowProblem(jt, js, c, w0, 0.0), 0.0)
    assert out.peak_torque == pytest.approx(math.sqrt(2.0 * e * c * js / (jt + js)), rel=1e-6)
    assert out.joint_work == 0.0
    # lossless: the kinetic energy of the two flywheels after the blow is E
    assert out.energy_left == pytest.approx(e, rel=1e-6)


def test_the_damping_ratio_is_the_restitution_inverted() -> None:
    # 60 bisections on [0, 0.99]: the ratio to 1e-18, the restitution back to ~1e-15
    for e in (0.2, 0.5, 0.8, 0.99):
        assert contact_restitution(_damping_ratio(e)) == pytest.approx(e, abs=1e-12)
    assert _damping_ratio(0.5) is _damping_ratio(0.5)  # worked out once per restitution


def test_per_blow_series_only_when_asked_for_and_then_the_same() -> None:
    ex = BLOW.examples[1]  # the soft nut-runner joint: 35 blows
    scalars = engine.run(BLOW, ex, fidelity="energy")
    every = engine.run(BLOW, ex, fidelity="energy", series=True)
    one = engine.run(BLOW, ex, fidelity="energy", outputs=["torque_per_blow"])
    assert scalars.series == {}
    assert scalars.results == every.results
    assert len(every.series["torque_per_blow"]) == every.results["blows_to_target"] == 35
    assert one.series == {"torque_per_blow": every.series["torque_per_blow"]}
    # the last blow's joint torque is the final torque
    assert every.series["torque_per_blow"][-1] == every.results["final_torque"]


def test_blow_series_keeps_each_blow_only_with_history() -> None:
    p = BlowProblem(0.02, 1e-3, 2.0e4, 100.0, 1000.0)
    kept = blow_series(p, 60.0, "energy", target_torque=600.0)
    bare = blow_series(p, 60.0, "energy", target_torque=600.0, history=False)
    assert bare.per_blow == {} and len(kept.per_blow["torque"]) == 2
    assert (bare.final_torque, bare.blows_to_target) == (kept.final_torque, 2)
    assert np.isfinite(bare.joint_work) and bare.joint_work == kept.joint_work
