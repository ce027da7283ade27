"""Every model's array path gives what its scalar path gives, point by point, checks included.

A study varies several inputs at once and evaluates each group of points through
the model's array path (:attr:`engine.core.spec.ModelSpec.vectorized`); the loop
through :func:`engine.run` is the reference. Here every float input an example
sets is moved at once, at random within ±5 % (kept in its declared range), and
the same points are evaluated twice by :func:`engine.studies.plan.evaluate_chunk`: with
the array path, and with it switched off. An input a single run refuses when
moved alone by a few per cent (a thread diameter keyed to a table) stays at its
example value, so the comparison is not of refused points with refused points.
Every scalar float output must agree to 1e-9 (NaN where the loop refuses the
point), and every check's verdict must be the same: a study's pass fractions
may not depend on which path ran.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import engine
from engine import EngineError, ModelSpec
from engine.studies.plan import evaluate_chunk

from .common import FIXED, MODELS_UNDER_TEST, ids

POINTS = 24
SPREAD = 0.05

VECTOR_MODELS = [
    spec for spec in MODELS_UNDER_TEST if spec.vectorized is not None and spec.name != "toy.disc"
]


def _movable(spec: ModelSpec, base: dict, name: str, value: float, rung: str) -> bool:
    """Whether a single run still computes with ``name`` moved alone by ±SPREAD/2."""
    for factor in (1.0 - SPREAD / 2, 1.0 + SPREAD / 2):
        try:
            engine.run(spec, {**base, name: value * factor}, fidelity=rung)
        except EngineError:
            return False
    return True


def _columns(spec: ModelSpec, base: dict, seed: int, rung: str) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    columns = {}
    for p in spec.inputs:
        value = base.get(p.name)
        if p.kind != "float" or isinstance(value, bool) or not isinstance(value, int | float):
            continue
        if value == 0 or not _movable(spec, base, p.name, float(value), rung):
            continue
        col = value * (1.0 + rng.uniform(-SPREAD, SPREAD, POINTS))
        lo = -np.inf if p.minimum is None else p.minimum
        hi = np.inf if p.maximum is None else p.maximum
        col = np.clip(col, lo, hi)
        if p.exclusive_minimum:
            col = np.where(col <= lo, value, col)
        if p.exclusive_maximum:
            col = np.where(col >= hi, value, col)
        columns[p.name] = col
    return columns


@pytest.mark.parametrize("spec", VECTOR_MODELS, ids=ids)
def test_array_path_matches_the_loop_with_several_inputs_varied(spec: ModelSpec) -> None:
    looped_spec = dataclasses.replace(spec, vectorized=None, vector_rungs=())
    outputs = [o.name for o in spec.outputs if not o.series and o.kind == "float"]
    compared = 0
    for k, example in enumerate(spec.examples):
        base = {**example, **FIXED.get(spec.name, {})}
        for rung in spec.vector_rungs:
            try:
                engine.run(spec, base, fidelity=rung)
            except EngineError:
                continue  # an example for another rung
            columns = _columns(spec, base, seed=k, rung=rung)
            if not columns:
                continue
            fast = evaluate_chunk(spec, base, columns, outputs, fidelity=rung)
            slow = evaluate_chunk(looped_spec, base, columns, outputs, fidelity=rung)
            where = f"{spec.name}/{rung}, example {k}"
            finite = 0
            for name in outputs:
                a, b = fast.values[name], slow.values[name]
                np.testing.assert_allclose(
                    a, b, rtol=1e-9, atol=1e-300, equal_nan=True, err_msg=f"{where}: {name}"
                )
                finite += int(np.isfinite(b).sum())
            assert finite, f"{where}: every point refused; nothing compared"
            compared += finite
            assert sorted(fast.checks) == sorted(slow.checks), (
                f"{where}: the array path reports checks {sorted(fast.checks)}, "
                f"the scalar path {sorted(slow.checks)}"
            )
            for name, verdicts in slow.checks.items():
                np.testing.assert_array_equal(
                    fast.checks[name], verdicts, err_msg=f"{where}: check {name}"
                )
    assert compared, f"{spec.name}: nothing compared"
