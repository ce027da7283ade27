"""What every stability test shares: the models under test, input draws, the verdict on a run.

Generic over :data:`engine.MODELS` plus the test-only toys, reading only the
spec contract, so a model registered tomorrow is covered without a new line.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Mapping
from typing import Any

import numpy as np
from hypothesis import strategies as st

import engine
from bench.generic import extremes
from engine import (
    BudgetExceeded,
    EngineError,
    InfeasibleDesign,
    InputOutOfRange,
    ModelSpec,
    Param,
    Result,
    RunContext,
    SolverFailed,
)
from tests.toys import TOY, TOYS

#: Every registered model, then the test-only toys (they keep the suite honest
#: while the registry is empty and show each hazard on a known answer).
MODELS_UNDER_TEST: tuple[ModelSpec, ...] = (*engine.MODELS, TOY, *TOYS)

#: Inputs held fixed per model: the disc toy's ``blowup`` switch makes a
#: non-finite output on purpose (to test the runner's guard), not a hazard.
FIXED: dict[str, dict[str, Any]] = {"toy.disc": {"blowup": False}}

#: The short wall-clock budget every stability run gets, and the slack allowed
#: past it: a model checks its deadline between steps, not continuously, and a
#: busy CI machine pauses; ten times this would mean the deadline is ignored.
BUDGET_S = 1.0
BUDGET_SLACK_S = 1.0

ALLOWED = (InputOutOfRange, InfeasibleDesign, SolverFailed, BudgetExceeded)


def ids(spec: ModelSpec) -> str:
    return spec.name


def recording(spec: ModelSpec) -> tuple[ModelSpec, list[Result]]:
    """``spec`` with its compute wrapped so the raw Result (before the runner's guard) is kept."""
    seen: list[Result] = []
    compute = spec.compute

    def wrapped(inputs: Mapping[str, Any], ctx: RunContext) -> Result:
        result = compute(inputs, ctx)
        seen.append(result)
        return result

    return dataclasses.replace(spec, compute=wrapped), seen


def _log_uniform(lo: float, hi: float) -> st.SearchStrategy[float]:
    return st.floats(math.log(lo), math.log(hi)).map(lambda e: min(max(math.exp(e), lo), hi))


def param_values(param: Param, example: Any = None) -> st.SearchStrategy[Any]:
    """Values of one input within its declared range.

    Positive ranges log-uniformly (decades matter: µm and tonnes), ranges that
    include 0 or negatives uniformly, and the two extremes themselves often.
    """
    if param.kind == "bool":
        return st.booleans()
    if param.kind in ("choice", "text"):  # a text input's choices are its suggestions
        return st.sampled_from(param.choices)
    if param.kind == "samples":  # a list of values, each drawn as a number of the same range
        one = param_values(dataclasses.replace(param, kind="float"))
        return st.lists(one, min_size=param.min_length, max_size=min(param.max_length, 64))
    bounds = extremes(param, example)
    assert bounds is not None
    lo, hi = bounds
    if param.kind == "int":
        return st.integers(int(lo), int(hi))
    if lo > 0.0:
        inner = _log_uniform(lo, hi)
    elif lo == 0.0 and hi > 0.0:
        # the range starts at 0 inclusive: 0 itself, then log-uniform over 12 decades below hi
        inner = st.one_of(st.just(0.0), _log_uniform(hi * 1e-12, hi))
    else:
        inner = st.floats(lo, hi, allow_nan=False, allow_infinity=False)
    return st.one_of(st.sampled_from((lo, hi)), inner)


@st.composite
def requests(draw: st.DrawFn, spec: ModelSpec) -> dict[str, Any]:
    """A request within every declared range.

    Half the time every input is drawn; otherwise the first example with one to
    three inputs replaced, so cross-field rules (which refuse most fully random
    designs) still leave many draws that reach deep into the model.
    """
    example = dict(spec.examples[0]) if spec.examples else {}
    fixed = FIXED.get(spec.name, {})
    free = [p for p in spec.inputs if p.name not in fixed]
    if draw(st.booleans()) and example:
        chosen = draw(st.lists(st.sampled_from(free), min_size=1, max_size=3, unique=True))
        request = dict(example)
    else:
        chosen = free
        request = {p.name: example[p.name] for p in spec.inputs if p.required}
    for param in chosen:
        if not param.required and param.default is None and draw(st.booleans()):
            request.pop(param.name, None)  # optional input: "not given"
            continue
        request[param.name] = draw(param_values(param, example.get(param.name, param.default)))
    return {**request, **fixed}


def fidelities(spec: ModelSpec) -> st.SearchStrategy[str]:
    return st.sampled_from(("auto", *spec.rung_names))


def is_finite_value(value: Any) -> bool:
    """True for finite numbers and for non-numbers (bools, strings, None)."""
    if isinstance(value, np.ndarray | list | tuple):
        return bool(np.all(np.isfinite(np.asarray(value, dtype=float))))
    if isinstance(value, float | np.floating):
        return math.isfinite(float(value))
    return True


def run_checked(
    spec: ModelSpec, request: Mapping[str, Any], **kwargs: Any
) -> engine.RunResult | None:
    """Run ``spec`` with the short budget; None if it refused with an allowed EngineError.

    Fails the test on any other exception, on a non-finite value or error
    estimate in what the model itself returned (before the runner's guard
    hides it as null), or on a run far past its budget.
    """
    watched, raw = recording(spec)
    start = time.perf_counter()
    try:
        result = engine.run(watched, request, budget_s=BUDGET_S, **kwargs)
    except ALLOWED as exc:
        elapsed = time.perf_counter() - start
        assert exc.message, f"{spec.name}: {type(exc).__name__} without a message for {request}"
        if isinstance(exc, InputOutOfRange):
            names = {p.name for p in spec.inputs} | {"fidelity", "tolerance", "outputs"}
            assert exc.field in names, (
                f"{spec.name}: InputOutOfRange must name the input at fault, got field="
                f"{exc.field!r} for {request}: {exc.message}"
            )
        assert elapsed <= BUDGET_S + BUDGET_SLACK_S, (
            f"{spec.name}: took {elapsed:.2f} s (budget {BUDGET_S} s) for {request}"
        )
        return None
    except EngineError as exc:  # pragma: no cover - a failure report
        raise AssertionError(
            f"{spec.name}: bare {type(exc).__name__} for {request}; raise one of "
            f"{[c.__name__ for c in ALLOWED]}"
        ) from exc
    elapsed = time.perf_counter() - start
    where = f"{spec.name} {kwargs} at {request}"
    for res in raw:
        bad = [n for n, v in res.values.items() if not is_finite_value(v)]
        assert not bad, f"{where}: non-finite {bad}: {res.values}"
        bad = [n for n, v in res.series.items() if not is_finite_value(list(v))]
        assert not bad, f"{where}: non-finite series {bad}"
        est = res.error_estimate
        assert est is None or math.isfinite(est), f"{where}: error estimate {est}"
        assert est is None or est >= 0.0, f"{where}: negative error estimate {est}"
    assert result.elapsed_s <= BUDGET_S + BUDGET_SLACK_S, (
        f"{where}: compute took {result.elapsed_s:.2f} s, budget {BUDGET_S} s"
    )
    assert elapsed <= BUDGET_S + BUDGET_SLACK_S, f"{where}: took {elapsed:.2f} s"
    return result
