"""Run a model: validate, choose the rung, time it, and never return NaN or inf.

:func:`run` is the one way every caller (the service, the benchmarks, a
Python user) evaluates a model, so rung selection, timing and the finiteness
guarantee live in one place. :func:`sweep` evaluates one input over a range,
the curves the papers plot.
"""

from __future__ import annotations

import contextlib
import math
import threading
import time
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .errors import BudgetExceeded, Cancelled, EngineError, InputOutOfRange, SolverFailed
from .spec import Check, ModelSpec, Param, RunContext, Value

DEFAULT_TOLERANCE = 0.01
MAX_SWEEP_POINTS = 2000
DEFAULT_BUDGET_S = 10.0
DEFAULT_MAX_STEPS = 1_000_000


@dataclass
class RunResult:
    """A model evaluation as the service returns it (SI values, units, provenance)."""

    model: str
    results: dict[str, Value]
    units: dict[str, str]
    rung: str
    error_estimate: float | None
    elapsed_s: float
    inputs: dict[str, Any]
    checks: list[Check] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    series: dict[str, list[float]] = field(default_factory=dict)


@dataclass
class SweepResult:
    """One input varied over ``values``; ``results[name][i]`` belongs to ``values[i]``."""

    model: str
    vary: str
    values: list[float]
    results: dict[str, list[Value]]
    units: dict[str, str]
    rung: str
    elapsed_s: float
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    #: The rung that ran at each point (None where the point was refused): ``auto``
    #: chooses per point, so a sweep across a regime change may mix rungs.
    rungs: list[str | None] = field(default_factory=list)
    #: Each point's error estimate (None where refused or not known).
    error_estimates: list[float | None] = field(default_factory=list)


def _rung_summary(rungs: Sequence[str | None]) -> tuple[str, list[str]]:
    """The sweep's ``rung`` field and, when points differ, a note saying how."""
    counts: dict[str, int] = {}
    for r in rungs:
        if r is not None:
            counts[r] = counts.get(r, 0) + 1
    if len(counts) <= 1:
        return next(iter(counts), ""), []
    return ", ".join(counts), [
        "auto chose the rung per point: "
        + ", ".join(f"{r} at {n} point{'s' if n > 1 else ''}" for r, n in counts.items())
        + " (see rungs)"
    ]


def _fidelity(spec: ModelSpec, fidelity: str | None, tolerance: float | None) -> str:
    """The fidelity asked for: given, else 'auto' when a tolerance is given, else the default."""
    if fidelity is not None:
        return fidelity
    return "auto" if tolerance is not None else spec.default_fidelity


def choose_rung(
    spec: ModelSpec, inputs: Mapping[str, Any], fidelity: str, tolerance: float
) -> tuple[str, list[str]]:
    """Pick the rung to run and say why.

    A named rung runs as asked. ``"auto"`` takes the cheapest rung (the spec
    lists them cheapest first) whose a-priori error estimate is within
    ``tolerance``; if none is, the most accurate applicable rung runs and the
    note says the tolerance was not met.
    """
    if fidelity != "auto":
        if fidelity not in spec.rung_names:
            raise InputOutOfRange(
                f"fidelity = {fidelity!r} is not allowed: must be 'auto' or one of "
                + ", ".join(repr(r) for r in spec.rung_names),
                field="fidelity",
            )
        return fidelity, []
    applicable: list[tuple[str, float]] = []
    for rung in spec.rungs:
        estimate = rung.estimate(inputs)
        if estimate is None or not math.isfinite(estimate):
            continue
        applicable.append((rung.name, estimate))
        if estimate <= tolerance:
            skipped = applicable[:-1]
            why = (
                f"auto: chose {rung.name!r}, estimated error {estimate:.2g} "
                f"≤ tolerance {tolerance:.2g}"
            )
            if skipped:
                why += "; cheaper rungs estimated " + ", ".join(f"{n} {e:.2g}" for n, e in skipped)
            return rung.name, [why]
    if not applicable:
        name = spec.rungs[-1].name
        return name, [f"auto: no rung gave an error estimate; ran {name!r}"]
    name, estimate = min(applicable, key=lambda item: item[1])
    return name, [
        f"auto: no rung meets tolerance {tolerance:.2g}; ran the most accurate, {name!r} "
        f"(estimated error {estimate:.2g})"
    ]


@contextlib.contextmanager
def _arithmetic_refused(spec: ModelSpec) -> Iterator[None]:
    """A safety net under the declared ranges: a combination of extreme inputs that
    overflows or divides by zero is refused (SolverFailed, 422), never a crash (500).
    numpy's overflow/invalid warnings are silenced: a non-finite result becomes null with a
    note (numpy's error state is per thread)."""
    try:
        with np.errstate(all="ignore"):
            yield
    except ArithmeticError as exc:
        raise SolverFailed(
            f"{spec.name} cannot be evaluated for these inputs: the arithmetic failed "
            f"({type(exc).__name__}); values this extreme lie outside what the model "
            "computes reliably",
            error=type(exc).__name__,
        ) from None


def _fallback(
    spec: ModelSpec,
    rung: str,
    inputs: Mapping[str, Any],
    exc: BudgetExceeded,
    *,
    auto: bool = False,
) -> tuple[str, float, float] | None:
    """The rung to run instead of ``rung`` after ``exc`` (per :attr:`Rung.fallback`), or None.

    Returns the fallback's name, the declining rung's estimate and the fallback's.

    Only a rung that declined up front (``expected_steps`` in the error: it would need
    more steps than allowed) falls back, and only to a rung whose estimated error for
    these inputs is no larger than the declining rung's own: the answer still meets
    what was asked of it. A deadline overrun part-way is not rescued. Under ``auto``
    the fallback runs even when its estimate is larger (auto's promise is the best
    answer within the budget; the caller's note then says the tolerance was not met).
    """
    declining = spec.rung(rung)
    if declining.fallback is None or "expected_steps" not in exc.context:
        return None
    own = declining.estimate(inputs)
    theirs = spec.rung(declining.fallback).estimate(inputs)
    if own is None or theirs is None or not math.isfinite(theirs):
        return None
    if theirs > own and not auto:
        return None
    return declining.fallback, own, theirs


def _finite(value: Value) -> bool:
    return not isinstance(value, float) or math.isfinite(value)


def run(
    spec: ModelSpec,
    inputs: Mapping[str, Any],
    *,
    fidelity: str | None = None,
    tolerance: float | None = None,
    outputs: Iterable[str] | None = None,
    budget_s: float | None = DEFAULT_BUDGET_S,
    max_steps: int = DEFAULT_MAX_STEPS,
    cancel: threading.Event | None = None,
) -> RunResult:
    """Evaluate ``spec`` on SI ``inputs``.

    ``outputs`` limits the work to the named outputs and series (all when
    None). Non-finite values never leave: they become None with a note.
    ``budget_s`` and ``max_steps`` reach the model as ``ctx.deadline`` and
    ``ctx.max_steps``; a model past either raises BudgetExceeded. ``cancel``
    reaches it as ``ctx.cancel``: once set, the model stops at its next budget
    check with :class:`Cancelled`.
    """
    values, warnings = spec.validate(inputs)
    tol = DEFAULT_TOLERANCE if tolerance is None else float(tolerance)
    if not (math.isfinite(tol) and 0.0 < tol < 1.0):
        raise InputOutOfRange(
            f"tolerance = {tol:g} is not allowed: must be > 0 and < 1", field="tolerance"
        )
    known = {o.name for o in spec.outputs}
    wanted = frozenset(known if outputs is None else outputs)
    unknown = sorted(wanted - known)
    if unknown:
        raise InputOutOfRange(
            f"unknown output(s) {', '.join(unknown)}; {spec.name} offers "
            + ", ".join(sorted(known)),
            field="outputs",
        )
    with _arithmetic_refused(spec):
        rung, notes = choose_rung(spec, values, _fidelity(spec, fidelity, tolerance), tol)
    start = time.perf_counter()
    ctx = RunContext(
        rung=rung,
        outputs=wanted,
        tolerance=tol,
        deadline=None if budget_s is None else start + budget_s,
        max_steps=max_steps,
        cancel=cancel,
    )
    try:
        with _arithmetic_refused(spec):
            result = spec.compute(values, ctx)
    except BudgetExceeded as exc:
        auto = _fidelity(spec, fidelity, tolerance) == "auto"
        found = _fallback(spec, rung, values, exc, auto=auto)
        if found is None:
            raise
        fallback, own, theirs = found
        ctx = replace(ctx, rung=fallback)
        notes.append(
            f"{rung!r} would need about {exc.context['expected_steps']:.2g} steps (budget "
            f"{max_steps:g}); ran its declared fallback {fallback!r} instead, whose estimated "
            + (
                f"error {theirs:.2g} is within {rung!r}'s own {own:.2g}"
                if theirs <= own
                else f"error is {theirs:.2g}"
            )
            + (f": the tolerance {tol:.2g} is not met" if auto and theirs > tol else "")
        )
        with _arithmetic_refused(spec):
            result = spec.compute(values, ctx)
    elapsed = time.perf_counter() - start

    units = {o.name: o.unit for o in spec.outputs}
    scalars: dict[str, Value] = {}
    series: dict[str, list[float]] = {}
    notes = notes + list(spec.assumptions) + result.notes
    for name, value in result.values.items():
        if name not in wanted:
            continue
        if isinstance(value, np.generic):
            value = value.item()
        if not _finite(value):
            notes.append(f"{name} could not be computed for these inputs (non-finite); null")
            value = None
        scalars[name] = value
    if outputs is not None:
        series_names = {o.name for o in spec.outputs if o.series}
        for name in sorted(wanted - set(scalars) - series_names):
            scalars[name] = None
            notes.append(f"{name} is not computed by {result.rung!r} for these inputs; null")
    for name, seq in result.series.items():
        if name not in wanted:
            continue
        arr = np.asarray(seq, dtype=float)
        if not np.all(np.isfinite(arr)):
            notes.append(f"series {name} had non-finite points; omitted")
            continue
        series[name] = arr.tolist()
    error = result.error_estimate
    if error is not None and not math.isfinite(error):
        notes.append("the error estimate is unbounded for these inputs; null")
        error = None
    return RunResult(
        model=spec.name,
        results=scalars,
        units={n: units[n] for n in (*scalars, *series)},
        rung=result.rung,
        error_estimate=error,
        elapsed_s=elapsed,
        inputs=values,
        checks=result.checks,
        notes=notes,
        warnings=warnings + result.warnings,
        series=series,
    )


def sweep_values(start: float, stop: float, num: int, scale: str = "linear") -> np.ndarray:
    """The points of a sweep; ``scale="log"`` spaces them geometrically."""
    if not 2 <= num <= MAX_SWEEP_POINTS:
        raise InputOutOfRange(
            f"num = {num} is not allowed: a sweep has 2…{MAX_SWEEP_POINTS} points", field="num"
        )
    if scale == "log":
        if start <= 0 or stop <= 0:
            raise InputOutOfRange("a log sweep needs start > 0 and stop > 0", field="start")
        return np.geomspace(start, stop, num)
    return np.linspace(start, stop, num)


def sweep(
    spec: ModelSpec,
    base: Mapping[str, Any],
    vary: str,
    values: Sequence[float],
    *,
    outputs: Iterable[str] | None = None,
    fidelity: str | None = None,
    tolerance: float | None = None,
    budget_s: float | None = DEFAULT_BUDGET_S,
    max_steps: int = DEFAULT_MAX_STEPS,
    cancel: threading.Event | None = None,
) -> SweepResult:
    """Evaluate ``spec`` with ``vary`` set to each of ``values``, the rest from ``base``.

    A point that the model refuses (an infeasible design, say) is None in
    every output, with one note naming the point and the reason.
    """
    try:
        param = spec.param(vary)
    except KeyError:
        raise InputOutOfRange(
            f"vary = {vary!r} is not an input of {spec.name}", field="vary"
        ) from None
    if not param.is_numeric:
        raise InputOutOfRange(f"vary = {vary!r} is not a numeric input", field="vary")
    wanted = list(outputs) if outputs is not None else None
    start = time.perf_counter()
    if spec.vectorized is not None and len(values) > 1:
        try:
            with _arithmetic_refused(spec):
                fast = _sweep_vectorized(spec, base, param, values, wanted, fidelity, tolerance)
        except SolverFailed:
            fast = None  # loop instead: the points that fail are null, with a note
        except EngineError:
            raise
        except Exception:
            # the array path is an optimisation and the scalar model the reference: where
            # the array path fails on inputs the scalar one refuses or handles (issue 20's
            # fuzzing found one), the loop answers
            fast = None
        if fast is not None:
            fast.elapsed_s = time.perf_counter() - start
            return fast
    checked = [param.check(int(v) if param.kind == "int" else v) for v in values]
    deadline = None if budget_s is None else start + budget_s
    names: list[str] = []
    results: dict[str, list[Value]] = {}
    notes: list[str] = []
    warnings: list[str] = []
    rungs: list[str | None] = []
    errors: list[float | None] = []
    first_refusal: EngineError | None = None
    for i, value in enumerate(checked):
        if cancel is not None and cancel.is_set():
            raise Cancelled(f"sweep cancelled after {i} of {len(checked)} points")
        remaining = None if deadline is None else deadline - time.perf_counter()
        if remaining is not None and remaining <= 0:
            raise BudgetExceeded(
                f"sweep stopped after {i} of {len(checked)} points at its {budget_s:g} s budget",
                field="num",
            )
        try:
            point = run(
                spec,
                {**base, vary: value},
                fidelity=fidelity,
                tolerance=tolerance,
                outputs=wanted,
                budget_s=remaining,
                max_steps=max_steps,
                cancel=cancel,
            )
        except Cancelled:
            raise  # the whole sweep was withdrawn, not this point refused
        except EngineError as exc:
            # a point the model refuses (infeasible, or a cross-field range that this
            # value breaks) is null; if every point is refused, the first refusal stands
            point = None
            first_refusal = first_refusal or exc
            notes.append(f"{vary} = {value:g}: {exc.message}")
        rungs.append(None if point is None else point.rung)
        errors.append(None if point is None else point.error_estimate)
        if point is not None:
            if not names:
                names = list(point.results)
                for n in names:
                    results[n] = [None] * i
            for n in names:
                results[n].append(point.results.get(n))
            for w in point.warnings:
                if w not in warnings:
                    warnings.append(w)
        else:
            for n in names:
                results[n].append(None)
    if not names:
        if isinstance(first_refusal, InputOutOfRange) and first_refusal.field != vary:
            raise first_refusal  # the fixed inputs themselves are out of range
        notes.append("no point of the sweep could be computed")
    rung, mixed = _rung_summary(rungs)
    units = {o.name: o.unit for o in spec.outputs}
    return SweepResult(
        model=spec.name,
        vary=vary,
        values=[float(v) for v in checked],
        results=results,
        units={n: units[n] for n in names},
        rung=rung,
        elapsed_s=time.perf_counter() - start,
        notes=mixed + notes,
        warnings=warnings,
        rungs=rungs,
        error_estimates=errors,
    )


def _sweep_vectorized(
    spec: ModelSpec,
    base: Mapping[str, Any],
    param: Param,
    values: Sequence[float],
    outputs: list[str] | None,
    fidelity: str | None,
    tolerance: float | None,
) -> SweepResult | None:
    """One array evaluation instead of a loop, when the model offers it for the rung.

    Returns None (the caller loops) when the rung chosen for the first point is
    not vectorised, when ``auto`` chooses different rungs at different points,
    or when the array version lacks an asked output the scalar rung gives.
    """
    assert spec.vectorized is not None
    arr = np.asarray(values, dtype=float)
    param.check(float(arr.min()) if param.kind == "float" else int(arr.min()))
    param.check(float(arr.max()) if param.kind == "float" else int(arr.max()))
    if param.kind == "int":
        if not np.all(arr == np.round(arr)):
            raise InputOutOfRange(f"{param.name} must be an integer", field=param.name)
        arr = arr.astype(np.int64)
    elif not np.all(np.isfinite(arr)):
        raise InputOutOfRange(f"{param.name} must be finite", field=param.name)
    first, warnings = spec.validate({**base, param.name: arr[0].item()})
    tol = DEFAULT_TOLERANCE if tolerance is None else float(tolerance)
    asked = _fidelity(spec, fidelity, tolerance)
    rung, notes = choose_rung(spec, first, asked, tol)
    if rung not in spec.vector_rungs:
        return None
    estimates: list[float | None] = [None] * arr.size
    if arr.size > MAX_SWEEP_POINTS:
        if asked == "auto":
            notes.append(f"auto chose {rung!r} from the first point of this long sweep")
    else:
        # each point's estimate; auto decides per point, so one array call serves only
        # if every point chose the same rung
        for i, v in enumerate(arr.tolist()):
            point, _ = spec.validate({**base, param.name: v})
            if asked == "auto" and choose_rung(spec, point, "auto", tol)[0] != rung:
                return None
            estimates[i] = spec.rung(rung).estimate(point)
    known = [o.name for o in spec.outputs if not o.series]
    wanted = known if outputs is None else [n for n in outputs if n in known]
    ctx = RunContext(rung=rung, outputs=frozenset(wanted), tolerance=tol)
    result = spec.vectorized({**first, param.name: arr}, ctx)
    missing = [name for name in wanted if name not in result.values]
    if missing:
        # an output the array version lacks may simply not belong to this rung; loop only
        # if the scalar model gives it at the first point
        try:
            scalar = spec.compute(first, ctx).values
        except EngineError:
            scalar = {}
        if any(scalar.get(name) is not None for name in missing):
            return None
    results: dict[str, list[Value]] = {}
    bad = np.zeros(arr.shape, dtype=bool)
    for name in wanted:
        if name not in result.values:
            continue
        column = np.broadcast_to(np.asarray(result.values[name]), arr.shape)
        if column.dtype.kind == "f":
            finite = np.isfinite(column)
            bad |= ~finite
            listed: list[Value] = column.tolist()
            if not finite.all():
                listed = [v if ok else None for v, ok in zip(listed, finite.tolist(), strict=True)]
            results[name] = listed
        else:
            results[name] = column.tolist()
    if bad.any():
        notes.append(f"{int(bad.sum())} of {arr.size} points could not be computed; null there")
    units = {o.name: o.unit for o in spec.outputs}
    return SweepResult(
        model=spec.name,
        vary=param.name,
        values=arr.astype(float).tolist(),
        results=results,
        units={n: units[n] for n in results},
        rung=rung,
        elapsed_s=0.0,
        notes=notes + result.notes,
        warnings=warnings + result.warnings,
        rungs=[None if b else rung for b in bad.tolist()],
        error_estimates=[None if b else e for b, e in zip(bad.tolist(), estimates, strict=True)],
    )
