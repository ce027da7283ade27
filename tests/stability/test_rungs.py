"""Rungs agree within their error estimates, and ``auto`` picks the cheapest one that suffices.

Agreement: if each rung's estimate is honest, |a − t| ≤ e_a |t| and
|b − t| ≤ e_b |t| for the true value t, so by the triangle inequality

    |a − b| / |b| ≤ (e_a + e_b) / (1 − e_b) ≤ 2 max(e_a, e_b) / (1 − e_b).

That factor of 2 (and the 1/(1 − e_b), which matters only for loose
estimates) is the whole safety factor: anything larger would let a dishonest
estimate through. Below it sits a floor of 1e-12, the round-off of a few
thousand double operations, for rungs that both claim machine precision.
The check runs on every example and on small random perturbations of it
(each float input moved by up to ±2 %, kept in range), wherever both rungs
apply, on every scalar float output both return.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import random
from typing import Any

import numpy as np
import pytest

import engine
from bench.generic import applicable_rungs, extremes, float_outputs
from engine import EngineError, ModelSpec

from .common import FIXED, MODELS_UNDER_TEST, ids, run_checked

SAFETY = 2.0
ROUND_OFF = 1e-12
PERTURBATIONS = 6


def agreement_bound(e_a: float, e_b: float) -> float:
    """Largest |a − b| / |b| two honest estimates allow (see the module docstring)."""
    return SAFETY * max(e_a, e_b) / (1.0 - min(e_b, 0.5)) + ROUND_OFF


def cases(spec: ModelSpec) -> list[dict[str, Any]]:
    """Each example, then small perturbations of it."""
    rng = random.Random(spec.name)
    found = []
    for example in spec.examples:
        found.append({**example, **FIXED.get(spec.name, {})})
        for _ in range(PERTURBATIONS):
            moved = {**example, **FIXED.get(spec.name, {})}
            for p in spec.inputs:
                value = moved.get(p.name)
                if p.kind != "float" or not isinstance(value, float | int) or value == 0:
                    continue
                candidate = value * (1.0 + rng.uniform(-0.02, 0.02))
                with contextlib.suppress(EngineError):
                    moved[p.name] = p.check(candidate)
            found.append(moved)
    return found


def assert_rungs_agree(spec: ModelSpec, case: dict[str, Any]) -> int:
    """Run every applicable rung on ``case``; fail if two disagree beyond their estimates.

    Returns how many (pair, output) comparisons were made.
    """
    try:
        rungs = applicable_rungs(spec, case)
    except EngineError:
        return 0
    results = {}
    for rung, estimate in rungs:
        result = run_checked(spec, case, fidelity=rung.name)
        if result is not None:
            stated = result.error_estimate if result.error_estimate is not None else estimate
            results[rung.name] = (result.results, stated)
    compared = 0
    for (name_a, (a, e_a)), (name_b, (b, e_b)) in itertools.permutations(results.items(), 2):
        bound = agreement_bound(e_a, e_b)
        for output in float_outputs(spec):
            va, vb = a.get(output), b.get(output)
            if not (isinstance(va, float | int) and isinstance(vb, float | int)) or vb == 0:
                continue
            compared += 1
            error = abs(va - vb) / abs(vb)
            assert error <= bound, (
                f"{spec.name}.{output}: {name_a} = {va!r} and {name_b} = {vb!r} differ by "
                f"{error:.3g} relative, beyond what their estimates "
                f"({e_a:.2g}, {e_b:.2g}) allow ({bound:.3g}) at {case}"
            )
    return compared


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_rungs_agree_within_their_estimates(spec: ModelSpec) -> None:
    compared = sum(assert_rungs_agree(spec, case) for case in cases(spec))
    if len(spec.rungs) > 1:
        assert compared, f"{spec.name}: no two rungs both applied to any example"


def _tolerances(estimates: list[float]) -> list[float]:
    """Each estimate, just above and just below it, and the loosest and tightest tolerances."""
    found = {0.5, 1e-15}
    for e in estimates:
        found |= {e, e * 1.01, e * 0.99}
    return sorted(t for t in found if 0.0 < t < 1.0)


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_auto_picks_the_cheapest_rung_meeting_the_tolerance(spec: ModelSpec) -> None:
    for example in spec.examples:
        case = {**example, **FIXED.get(spec.name, {})}
        rungs = applicable_rungs(spec, case)
        for tolerance in _tolerances([e for _, e in rungs]):
            meeting = [r.name for r, e in rungs if e <= tolerance]
            if meeting:
                expected, verdict = meeting[0], "≤ tolerance"
            elif rungs:
                expected, verdict = min(rungs, key=lambda item: item[1])[0].name, "no rung meets"
            else:
                expected, verdict = spec.rungs[-1].name, "no rung gave an error estimate"
            try:
                result = engine.run(spec, case, fidelity="auto", tolerance=tolerance)
            except EngineError:
                continue
            assert result.rung == expected, (
                f"{spec.name}: auto at tolerance {tolerance:.3g} ran {result.rung!r}, "
                f"expected {expected!r} (estimates {[(r.name, e) for r, e in rungs]})"
            )
            why = result.notes[0]
            assert why.startswith("auto:") and repr(expected) in why and verdict in why, why


#: The foundation toy's array form nulls discs over 5 m on purpose (to test the
#: runner's handling of NaN), which its scalar form does not: not a model to hold to this.
VECTOR_MODELS = [
    spec for spec in MODELS_UNDER_TEST if spec.vectorized is not None and spec.name != "toy.disc"
]


@pytest.mark.parametrize("spec", VECTOR_MODELS, ids=ids)
def test_vectorized_sweep_matches_single_runs(spec: ModelSpec) -> None:
    """The array form agrees with :func:`engine.run` point by point, across each float range.

    A point the array form cannot compute (null) must be one the scalar form
    refuses or also leaves null: a vectorised sweep may not hide a result, nor
    invent one.
    """
    base = {**spec.examples[0], **FIXED.get(spec.name, {})}
    compared = 0
    for rung in spec.vector_rungs:
        for param in spec.inputs:
            bounds = extremes(param, base.get(param.name, param.default))
            if param.kind != "float" or bounds is None:
                continue
            lo, hi = bounds
            values = (
                np.geomspace(lo, hi, 9).tolist()
                if lo > 0 and hi / lo > 100
                else np.linspace(lo, hi, 9).tolist()
            )
            values = [min(max(v, lo), hi) for v in values]
            try:
                swept = engine.sweep(spec, base, param.name, values, fidelity=rung)
            except EngineError:
                continue
            for i, value in enumerate(values):
                try:
                    single = engine.run(spec, {**base, param.name: value}, fidelity=rung)
                except EngineError:
                    single = None
                for name, column in swept.results.items():
                    got = column[i]
                    want = None if single is None else single.results.get(name)
                    where = f"{spec.name}/{rung}: {name} at {param.name} = {value!r}"
                    if got is None:
                        assert want is None, f"{where}: sweep null, single run {want!r}"
                    elif isinstance(got, float):
                        assert isinstance(want, float | int), (
                            f"{where}: sweep {got!r}, run {want!r}"
                        )
                        assert math.isclose(got, want, rel_tol=1e-9, abs_tol=1e-300), where
                        compared += 1
                    else:
                        assert got == want, where
    assert compared, f"{spec.name}: the vectorised form computed nothing comparable"
