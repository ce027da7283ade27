"""Evaluate many points of one model at once: per-point rung choice on arrays, grouped array paths.

Both :func:`engine.sweep` (one input varied) and :func:`engine.studies.plan.evaluate_chunk`
(several inputs sampled) hand a dict of inputs whose varied entries are equal-length
arrays to the helpers here. They choose ``auto``'s rung per point from the rungs'
error estimates called on the arrays, group the points by rung and run each group
through the model's array path where it has one for that rung; the caller evaluates
the rest (the ``loop`` mask) one by one through :func:`engine.run`, with its own
bookkeeping.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .errors import EngineError
from .spec import ModelSpec, Param, RunContext, Scratch
from .text import plain

_ESTIMATE_FAILS = (TypeError, ValueError, ArithmeticError)


def in_range(param: Param, column: np.ndarray) -> np.ndarray:
    """Which entries of ``column`` lie in ``param``'s declared range (finite, bounds)."""
    ok = np.isfinite(column)
    if param.minimum is not None:
        ok &= column > param.minimum if param.exclusive_minimum else column >= param.minimum
    if param.maximum is not None:
        ok &= column < param.maximum if param.exclusive_maximum else column <= param.maximum
    return ok


def rung_estimates(
    spec: ModelSpec,
    x: Mapping[str, Any],
    n: int,
    which: Sequence[int] | None = None,
    point: Callable[[int], Mapping[str, Any]] | None = None,
    refused: np.ndarray | None = None,
    scratch: Scratch | None = None,
) -> dict[int, np.ndarray | None] | None:
    """Each rung's a-priori error estimate at the ``n`` points of ``x``, as arrays.

    Keys are rung indices (``which``, all rungs when None); a value is None where
    the rung gives no estimate, else a float array with NaN where the estimate is
    None or non-finite. Each estimate is called once with the arrays; if one cannot
    take arrays (TypeError, ValueError, ArithmeticError), it is called per point
    with ``point(j)`` (the scalar inputs of point ``j``) when given, else the
    whole answer is None. With ``point``, an estimate that refuses the arrays
    (EngineError) is also called per point; a point it refuses is NaN there and
    marked True in ``refused`` (the caller runs it alone, to report why).
    ``scratch`` is the chunk's: the arrays' estimates leave their work there for
    :func:`vector` on the same ``x``.
    """
    shared = Scratch() if scratch is None else scratch
    fails = _ESTIMATE_FAILS if point is None else (*_ESTIMATE_FAILS, EngineError)
    out: dict[int, np.ndarray | None] = {}
    for i in range(len(spec.rungs)) if which is None else which:
        rung = spec.rungs[i]
        try:
            with np.errstate(all="ignore"):
                est = rung.estimate_in(x, shared)
        except fails:
            if point is None:
                return None
            values = [_estimate_at(rung.estimate, point, j, refused) for j in range(n)]
            if all(v is None for v in values):
                out[i] = None
                continue
            arr = np.array([np.nan if v is None else float(v) for v in values])
        else:
            if est is None:
                out[i] = None
                continue
            arr = np.array(np.broadcast_to(np.asarray(est, dtype=float), (n,)))
        arr[~np.isfinite(arr)] = np.nan
        out[i] = arr
    return out


def _estimate_at(
    estimate: Callable[[Mapping[str, Any]], Any],
    point: Callable[[int], Mapping[str, Any]],
    j: int,
    refused: np.ndarray | None,
) -> Any:
    try:
        return estimate(point(j))
    except EngineError:
        if refused is not None:
            refused[j] = True
        return None


def auto_index(
    spec: ModelSpec, estimates: Mapping[int, np.ndarray | None], n: int, tol: float
) -> np.ndarray:
    """``auto``'s rung index per point, as :func:`engine.core.runner.choose_rung` picks it.

    The cheapest rung whose estimate is within ``tol``; else the most accurate rung
    with an estimate; else the last rung. Where the first rung with an estimate has it
    finite and within ``tol`` at every point (the common case: a model's closed form on
    its own inputs), every point takes that rung, found in two passes over its estimates.

    >>> from engine.models import get_model
    >>> spec = get_model("preload.tightening")
    >>> auto_index(spec, {0: np.array([0.0, 0.01])}, 2, 0.02).tolist()
    [0, 0]
    >>> auto_index(spec, {0: np.array([0.0, np.nan])}, 2, 0.02).tolist()
    [0, 0]
    """
    first = next((i for i in range(len(spec.rungs)) if estimates.get(i) is not None), None)
    if first is not None:
        arr = estimates[first]
        assert arr is not None
        # every estimate within tol, no NaN (a comparison with NaN is false) and no -inf
        if arr.size == n and bool((arr <= tol).all()) and (n == 0 or arr.min() > -np.inf):
            return np.full(n, first, dtype=np.int64)
    choice = np.full(n, -1, dtype=np.int64)
    best = np.full(n, np.inf)
    best_i = np.full(n, -1, dtype=np.int64)
    for i in range(len(spec.rungs)):
        arr = estimates.get(i)
        if arr is None:
            continue
        ok = np.isfinite(arr)
        better = ok & (arr < best)
        best = np.where(better, arr, best)
        best_i = np.where(better, i, best_i)
        choice = np.where((choice < 0) & ok & (arr <= tol), i, choice)
    fallback = np.where(best_i >= 0, best_i, len(spec.rungs) - 1)
    return np.where(choice >= 0, choice, fallback)


def one_number(value: Any, n: int) -> np.ndarray:
    """``value`` (a float) at ``n`` points as a read-only zero-stride view of one float:
    NaN where it is not finite (the array contract's refused or not-computed value). An
    output that is one number at every point then costs neither memory nor a pass over
    the points; :func:`vector` gives a caller that wants columns of their own a copy.

    >>> y = one_number(2.5, 4)
    >>> y.tolist(), y.strides, y.flags.writeable, one_number(np.inf, 2).tolist()
    ([2.5, 2.5, 2.5, 2.5], (0,), False, [nan, nan])
    """
    v = float(value)
    return np.broadcast_to(np.array(v if np.isfinite(v) else np.nan), (n,))


def is_one_number(y: np.ndarray) -> bool:
    """``y`` is a zero-stride view of one number (as :func:`one_number` gives it).

    >>> is_one_number(one_number(1.0, 3)), is_one_number(np.ones(3)), is_one_number(np.ones(1))
    (True, False, False)
    """
    return y.ndim == 1 and y.size > 1 and y.strides == (0,)


def take(x: Mapping[str, Any], n: int, sel: np.ndarray) -> dict[str, Any]:
    """The inputs of the points ``sel`` selects (arrays of length ``n`` sliced, the rest as is)."""
    return {
        k: (v[sel] if isinstance(v, np.ndarray) and v.shape == (n,) else v) for k, v in x.items()
    }


def at(x: Mapping[str, Any], n: int, j: int) -> dict[str, Any]:
    """The scalar inputs of point ``j``."""
    return {
        k: (v[j].item() if isinstance(v, np.ndarray) and v.shape == (n,) else v)
        for k, v in x.items()
    }


@dataclass
class Vector:
    """What one array evaluation gave: a column per asked output, and which the model computed."""

    values: dict[str, np.ndarray]
    computed: frozenset[str]
    notes: list[str]
    warnings: list[str]
    #: Per check name, int8 per point: 1 passes, 0 fails, -1 not reported there.
    checks: dict[str, np.ndarray]
    #: The columns the model found finite at every point (:attr:`Result.finite`).
    finite: frozenset[str] = frozenset()


def vector(
    spec: ModelSpec,
    x: Mapping[str, Any],
    rung: str,
    outputs: Sequence[str],
    tol: float,
    n: int,
    dtype: Any = float,
    scratch: Scratch | None = None,
    read_checks: bool = True,
    one_numbers: bool = False,
) -> Vector | None:
    """The array path for ``n`` points, or None where the model has none for this rung.

    An output the array version does not give is a NaN column (not in ``computed``);
    if the scalar model gives it for this rung, the answer is None (the caller loops).
    An output the array version sets to None is one it knows the scalar model does not
    give for these inputs (a NaN column, not in ``computed``, and no scalar probe).
    ``dtype=None`` keeps each column's own type (integers stay integers). ``scratch``
    is what :func:`rung_estimates` left for the same ``x`` (a new one when None).
    ``read_checks=False``: the caller does not read the checks (``Vector.checks`` may be empty).
    ``one_numbers=True``: the caller only reads the columns (a study's chunk), and a column
    of one number (a NaN column, an output the array path gives as one number: a
    read-only zero-stride view, :func:`one_number`) stays that view; else each column is
    an array of its own.
    """
    if spec.vectorized is None or rung not in spec.vector_rungs:
        return None
    ctx = RunContext(
        rung=rung,
        outputs=frozenset(outputs),
        tolerance=tol,
        scratch=Scratch() if scratch is None else scratch,
        checks=read_checks,
    )
    try:
        with np.errstate(all="ignore"):
            result = spec.vectorized(x, ctx)
    except EngineError:
        return None
    except _ESTIMATE_FAILS:
        # an array path written for one varied input may not broadcast several: loop
        return None
    absent = {name for name, value in result.values.items() if value is None}
    missing = [name for name in outputs if name not in result.values]
    if missing and scalar_gives(spec, x, ctx, missing):
        return None  # an output the array version lacks but this rung gives: loop
    values: dict[str, np.ndarray] = {}
    # the varied inputs: an output that is one of them (an input given back as it is, or a
    # view of it) is copied, so that no caller writing into an output column writes into
    # the request's inputs (a study's drawn columns, a sweep's values)
    inputs = [v for v in x.values() if isinstance(v, np.ndarray) and v.ndim]
    for name in outputs:
        if name not in result.values or name in absent:
            # not computed by this rung
            values[name] = one_number(np.nan, n) if one_numbers else np.full(n, np.nan)
            continue
        got = result.values[name]
        if (
            isinstance(got, np.ndarray)
            and got.shape == (n,)
            and (dtype is None or got.dtype == np.dtype(dtype))
            and (got.flags.writeable or (one_numbers and is_one_number(got)))
            and not any(np.may_share_memory(got, v) for v in inputs)
        ):
            values[name] = got  # already a column of its own (the common case): no copy
            continue
        try:
            column = np.broadcast_to(np.asarray(got, dtype=dtype), (n,))
        except (TypeError, ValueError):
            return None
        values[name] = column.copy()
    computed = frozenset(name for name in outputs if name in result.values and name not in absent)
    checks: dict[str, np.ndarray] = {}
    for name, verdict in result.check_arrays.items():
        arr = np.asarray(verdict)
        codes = arr.astype(np.int8) if arr.dtype == bool else np.asarray(arr, dtype=np.int8)
        checks[name] = np.broadcast_to(codes, (n,)).copy()
    notes = [plain(n) for n in result.notes]
    warnings = [plain(w) for w in result.warnings]
    return Vector(values, computed, notes, warnings, checks, result.finite & computed)


def scalar_gives(
    spec: ModelSpec, x: Mapping[str, Any], ctx: RunContext, names: Sequence[str]
) -> bool:
    """Whether the scalar model gives any of ``names`` at the first point of ``x``."""
    first = {k: (v.flat[0].item() if isinstance(v, np.ndarray) else v) for k, v in x.items()}
    try:
        values = spec.compute(first, replace(ctx, scratch=Scratch())).values
    except EngineError:
        return False
    return any(values.get(name) is not None for name in names)


def keep_ends(scratch: Scratch, name: str, low: float, high: float) -> None:
    """Leave in ``scratch`` the least and the largest value of input ``name`` over every
    point of the request (a sweep reads them to check its values), for the array path."""
    scratch.once(f"ends of {name}", lambda: (low, high))


def swept_ends(scratch: Scratch, name: str) -> tuple[float, float] | None:
    """The least and the largest value of input ``name`` over every point where the caller
    left them in ``scratch`` (:func:`keep_ends`), else None: an array path need not read
    them again (a pass over the points each).

    >>> s = Scratch()
    >>> swept_ends(s, "load"), keep_ends(s, "speed", 1.0, 2.0), swept_ends(s, "speed")
    (None, None, (1.0, 2.0))
    """
    ends: tuple[float, float] | None = scratch.get(f"ends of {name}")
    return ends


#: Values tested at a time: the flags of a block (64 KiB) stay in the processor's cache and
#: come from the heap, where the flags of a whole column (1 MB for 10⁶ points) would be pages
#: fresh from the kernel on each call, and a pass more.
FINITE_BLOCK = 1 << 16


def all_finite(values: np.ndarray) -> bool:
    """Whether no value of the float array ``values`` is NaN or infinite.

    Exact (a sum of the values, the earlier test, also said no where finite values overflow,
    and took more CPU: its additions wait on each other), and it stops at the first block
    that holds a non-finite value. ``values`` is read as one flat run of values: a view for a
    contiguous array, a copy otherwise.

    >>> all_finite(np.array([1.0, 2.0])), all_finite(np.array([1.0, np.nan]))
    (True, False)
    >>> all_finite(np.array([1e308, 1e308])), all_finite(np.array([[0.0], [-np.inf]]))
    (True, False)
    >>> all_finite(np.arange(FINITE_BLOCK + 3.0)), all_finite(np.empty(0))
    (True, True)
    """
    flat = values.reshape(-1)
    size = flat.size
    flags = np.empty(min(size, FINITE_BLOCK), dtype=bool)
    for start in range(0, size, FINITE_BLOCK):
        block = flat[start : start + FINITE_BLOCK]
        if not np.isfinite(block, out=flags[: block.size]).all():
            return False
    return True


def copy_with_ends(values: np.ndarray) -> tuple[np.ndarray, float, float]:
    """A copy of the 1-d float array ``values``, -0.0 folded to 0.0 (as a single run's
    :meth:`~engine.core.spec.Param.check` folds it: x + 0.0 is x for every other value), with
    its least and its largest value (NaN where a value is NaN).

    Copied a block of :data:`FINITE_BLOCK` values at a time, each block's least and largest
    taken while it is in the processor's cache: one pass over memory where a copy and then
    its ``min()`` and ``max()`` are three (10⁶ values whose pages are not cached: about
    0.4 ms against 0.85 ms; cached, the same time).

    >>> copy_with_ends(np.array([2.0, -1.0, 3.0]))
    (array([ 2., -1.,  3.]), -1.0, 3.0)
    >>> copy_with_ends(np.array([-0.0, -0.0]))
    (array([0., 0.]), 0.0, 0.0)
    >>> v = np.arange(FINITE_BLOCK + 3.0)
    >>> v[FINITE_BLOCK + 1] = np.nan
    >>> got, low, high = copy_with_ends(v)
    >>> got is v, np.shares_memory(got, v), np.array_equal(got, v, equal_nan=True), low, high
    (False, False, True, nan, nan)
    """
    size = values.shape[0]
    out = np.empty(size)
    starts = range(0, size, FINITE_BLOCK)
    lows, highs = np.empty(len(starts)), np.empty(len(starts))
    # the ufuncs' reductions called as they are (``block.min()`` goes through numpy's Python
    # wrapper first); the least value carries a NaN, so the largest need not: fmax skips
    # the NaN test (a block of 2¹⁶ values in the cache: 3.4 against 4.9 µs)
    least, largest = np.minimum.reduce, np.fmax.reduce
    for i, start in enumerate(starts):
        end = start + FINITE_BLOCK
        block = out[start:end]
        np.add(values[start:end], 0.0, out=block)  # the copy, -0.0 folded on the way
        lows[i] = least(block)
        highs[i] = largest(block)
    low = float(lows.min())
    return out, low, low if math.isnan(low) else float(highs.max())
