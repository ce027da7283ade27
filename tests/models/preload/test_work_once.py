"""A single preload request resolves its bolt once and computes each torque coefficient once.

The runner asks the closed-form rung for its error estimate (which needs the bolt and
the coefficients of the chosen and the exact torque formulas) and then runs the model
with the same inputs; the run takes the estimate's design instead of resolving again.
"""

from __future__ import annotations

from collections import Counter
from typing import Any

import pytest

import engine.models.preload as mp
from engine import run
from engine.core.spec import ModelSpec, Scratch
from engine.models.preload import CONTROL, TIGHTENING


def _counting(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    calls: Counter[str] = Counter()
    resolve, coefficients = mp.fz.resolve, mp.pl.tightening_torque_per_preload

    def counted_resolve(x: Any) -> Any:
        calls["resolve"] += 1
        return resolve(x)

    def counted_coefficients(*args: Any) -> Any:
        calls[f"coefficients {args[-1]}"] += 1
        return coefficients(*args)

    monkeypatch.setattr(mp.fz, "resolve", counted_resolve)
    monkeypatch.setattr(mp.pl, "tightening_torque_per_preload", counted_coefficients)
    return calls


@pytest.mark.parametrize(
    ("spec", "x"),
    [
        (TIGHTENING, {"thread": "M10 ISO 4762 12.9"}),
        (TIGHTENING, {"thread": "1/2-13 UNC", "grade": "SAE 5", "torque_formula": "approx"}),
        (CONTROL, {"thread": "M8 ISO 4762 12.9", "required_clamp_force": 12e3}),
    ],
    ids=["tightening", "tightening-approx", "control"],
)
def test_one_resolution_and_each_coefficient_once(
    monkeypatch: pytest.MonkeyPatch, spec: ModelSpec, x: dict[str, Any]
) -> None:
    calls = _counting(monkeypatch)
    r = run(spec, x)
    formula = x.get("torque_formula", "vdi2230")
    assert calls == Counter({"resolve": 1, f"coefficients {formula}": 1, "coefficients exact": 1})
    assert r.error_estimate is not None and r.error_estimate > 0
    # a second identical request resolves its own bolt (nothing is kept between requests)
    calls.clear()
    again = run(spec, x)
    assert calls["resolve"] == 1
    assert again.results == r.results


def test_the_exact_formula_is_its_own_reference(monkeypatch: pytest.MonkeyPatch) -> None:
    calls = _counting(monkeypatch)
    r = run(TIGHTENING, {"thread_diameter": 0.012, "torque_formula": "exact"})
    assert calls == Counter({"resolve": 1, "coefficients exact": 1})
    assert r.results["torque_formula_deviation"] == 0.0


def test_a_named_rung_resolves_in_the_run(monkeypatch: pytest.MonkeyPatch) -> None:
    """fidelity named: no estimate runs, the run resolves the bolt itself."""
    calls = _counting(monkeypatch)
    r = run(TIGHTENING, {"thread_diameter": 0.012}, fidelity="closed_form")
    assert calls == Counter({"resolve": 1, "coefficients vdi2230": 1, "coefficients exact": 1})
    auto = run(TIGHTENING, {"thread_diameter": 0.012})
    assert r.results == auto.results


def test_an_estimate_for_other_inputs_is_not_taken() -> None:
    """The design lives in the request's scratch: another request's scratch has M16's."""
    m12 = dict(TIGHTENING.validate({"thread_diameter": 0.012})[0])
    m16 = dict(TIGHTENING.validate({"thread_diameter": 0.016})[0])
    first, second = Scratch(), Scratch()
    mp._rung_estimate(m12, first)
    mp._rung_estimate(m16, second)
    assert mp._design(m12, first).bolt.diameter == 0.012
    assert mp._design(m16, second).bolt.diameter == 0.016
