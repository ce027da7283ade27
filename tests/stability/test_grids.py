"""Explicit grids at the hazards: each input at its extremes, and pairs of extremes together.

Random draws rarely land exactly on a bound; the numerical hazards live
there (angles near 0 and 90°, c3 → c1, D_f → d_h, stiff springs with light
parts, a motor too weak). Starting from each model's worked example, every
numeric input goes to its minimum and its maximum (exclusive bounds nudged
inside by 1e-9 relative), then every pair of numeric inputs takes all four
combinations of their extremes (stiff spring AND light mass). Each case runs
on every rung and on ``auto``; the verdict is :func:`run_checked`'s. Pairs are
sampled deterministically down to :data:`MAX_PAIR_CASES` per model so the
suite stays within minutes for models with many inputs.
"""

from __future__ import annotations

import itertools
import random
from typing import Any

import pytest
from fastapi.testclient import TestClient

from bench.generic import as_kind, extremes
from engine import ModelSpec
from service import create_app

from .common import FIXED, MODELS_UNDER_TEST, ids, run_checked
from .test_property import post

MAX_PAIR_CASES = 120


def _numeric(spec: ModelSpec) -> list[tuple[str, tuple[float | int, float | int]]]:
    base = dict(spec.examples[0])
    found = []
    for p in spec.inputs:
        if p.name in FIXED.get(spec.name, {}):
            continue
        bounds = extremes(p, base.get(p.name, p.default))
        if bounds is not None:
            found.append((p.name, (as_kind(p, bounds[0]), as_kind(p, bounds[1]))))
    return found


def single_extremes(spec: ModelSpec) -> list[dict[str, Any]]:
    base = {**spec.examples[0], **FIXED.get(spec.name, {})}
    return [{**base, name: value} for name, ends in _numeric(spec) for value in ends]


def pair_extremes(spec: ModelSpec) -> list[dict[str, Any]]:
    base = {**spec.examples[0], **FIXED.get(spec.name, {})}
    cases = [
        {**base, a: va, b: vb}
        for (a, ends_a), (b, ends_b) in itertools.combinations(_numeric(spec), 2)
        for va in ends_a
        for vb in ends_b
    ]
    if len(cases) > MAX_PAIR_CASES:
        cases = random.Random(spec.name).sample(cases, MAX_PAIR_CASES)
    return cases


def _run_everywhere(spec: ModelSpec, case: dict[str, Any]) -> int:
    """Run ``case`` on every rung and on auto; how many runs gave an answer."""
    answered = 0
    for fidelity in ("auto", *spec.rung_names):
        answered += run_checked(spec, case, fidelity=fidelity) is not None
    return answered


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_examples_are_complete_valid_requests(spec: ModelSpec) -> None:
    """The grids, the benchmark and the form start from the examples: each must run as given."""
    assert spec.examples, f"{spec.name} declares no example"
    for example in spec.examples:
        assert run_checked(spec, example) is not None, f"{spec.name}: example {example} refused"


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_each_input_at_its_extremes(spec: ModelSpec) -> None:
    cases = single_extremes(spec)
    assert cases, f"{spec.name} has no numeric input to push to its extremes"
    for case in cases:
        _run_everywhere(spec, case)


@pytest.mark.slow
@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_pairs_of_extremes(spec: ModelSpec) -> None:
    for case in pair_extremes(spec):
        _run_everywhere(spec, case)


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_api_at_the_extremes(spec: ModelSpec) -> None:
    client = TestClient(create_app(models=[spec]), raise_server_exceptions=False)
    for case in single_extremes(spec):
        post(client, "/api/v1" + spec.path, case)


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_api_sweeps_over_whole_ranges(spec: ModelSpec) -> None:
    """Each numeric input swept end to end (log where the range allows) through HTTP."""
    client = TestClient(create_app(models=[spec]), raise_server_exceptions=False)
    base = {**spec.examples[0], **FIXED.get(spec.name, {})}
    for name, (lo, hi) in _numeric(spec):
        if spec.param(name).kind == "int" or lo == hi:
            continue
        scale = "log" if lo > 0 and hi / lo > 100 else "linear"
        body = {"base": base, "vary": name, "start": lo, "stop": hi, "num": 25, "scale": scale}
        sweep = post(client, "/api/v1" + spec.path + "/sweep", body)
        for column in sweep.get("results", {}).values():
            assert len(column) == 25
