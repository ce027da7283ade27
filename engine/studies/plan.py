"""Design studies: one model over many designs (grid, Monte Carlo, Latin hypercube, Sobol').

A designer does not evaluate one design: a clutch maker asks what spread of
slip torque its tolerances give, a tool designer over which region of spring
rates the striker engages, an assembly engineer which scatter dominates the
clamp force. A :class:`Study` names the model, the fixed inputs, the inputs
that vary and how, and what to collect; this module turns it into points
(:func:`plan`), evaluates the points in chunks (:func:`evaluate_chunk`, a
pure function of its arguments, so any executor can run it: in-process or
on Dask workers, see :mod:`engine.studies.execute`), and summarises them
(:func:`summarize`): quantiles, mean, standard deviation and histogram per
output, the fraction of designs passing each check, grid maps with the
feasible region, the designs behind the extremes, and the sensitivity of
each output to each input (Sobol' indices for ``method="sobol"``, Spearman
rank correlations otherwise).

Everything is seeded and computed from the whole set of points in a fixed
order, so a study repeats exactly, bit for bit, whichever executor ran its
chunks, on one kind of processor (numpy chooses its vectorised exp, log, sin … for
the processor: a lognormal law's draws, for one, may differ in the last bit on another).

Sobol' indices follow Saltelli et al. (2010) for the first-order index and
Jansen (1999) for the total index (see ``docs/sources.md``, [Saltelli2010]).
"""

from __future__ import annotations

import math
import re
import threading
import time
from collections import Counter
from collections.abc import Collection, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..core.errors import BudgetExceeded, Cancelled, EngineError, InputOutOfRange
from ..core.points import (
    at,
    auto_index,
    in_range,
    is_one_number,
    rung_estimates,
    take,
    vector,
)
from ..core.runner import (
    DEFAULT_BUDGET_S,
    DEFAULT_TOLERANCE,
    RunResult,
    check_tolerance,
    choose_rung,
    point_outputs,
    run,
    run_point,
)
from ..core.spec import ModelSpec, Param, Scratch
from ..numerics import laws
from ..numerics.lazy import LazyModule
from . import kernels

#: scipy, imported on first use (engine.numerics.lazy): it weighs on the service's start-up
special = LazyModule("scipy.special")
stats = LazyModule("scipy.stats")
qmc = LazyModule("scipy.stats.qmc")

METHODS = ("grid", "monte_carlo", "lhs", "sobol", "points")
DISTRIBUTIONS = ("uniform", "normal", "triangular", "lognormal")
#: Largest |rank correlation| a study may ask for between two inputs.
MAX_CORRELATION = 0.99
MAX_GRID_INPUTS = 3
MAX_VARIABLES = 12
MAX_STUDY_POINTS = 2_000_000
#: Inputs an explicit-point study may give per design.
MAX_POINT_COLUMNS = 64
MAX_HISTOGRAM_BINS = 200
QUANTILES = (0.001, 0.01, 0.05, 0.25, 0.5, 0.75, 0.95, 0.99, 0.999)
#: Points the rank correlations of a larger study are computed on (its first ones).
RANK_POINTS = 200_000
#: Check states in :class:`ChunkResult`: passed, failed, not evaluated for this point.
CHECK_OK, CHECK_FAILED, CHECK_UNKNOWN = 1, 0, -1


@dataclass(frozen=True)
class Variable:
    """One varied input: its grid axis, or its distribution (SI units).

    ``grid``: ``low``…``high`` in ``num`` points (``scale`` linear or log).
    ``uniform``: ``low``…``high``. ``triangular``: ``low``, ``mode``, ``high``.
    ``normal``: ``mean``, ``sd``, truncated to ``low``…``high`` when given and
    always to the input's declared range (sampled by the inverse CDF of the
    truncated law, so no point is rejected and the sample stays seeded).
    ``lognormal``: the arithmetic ``mean`` and ``sd`` of the input (converted to the
    median and geometric sd by :func:`engine.numerics.laws.lognormal_from_mean_sd`),
    truncated like the normal law; the input must be positive.
    """

    name: str
    distribution: str = "uniform"
    low: float | None = None
    high: float | None = None
    mean: float | None = None
    sd: float | None = None
    mode: float | None = None
    num: int = 11
    scale: str = "linear"


@dataclass(frozen=True)
class Study:
    """What to evaluate: ``samples`` designs (per Sobol' base sample for ``sobol``)."""

    variables: tuple[Variable, ...]
    base: Mapping[str, Any] = field(default_factory=dict)
    method: str = "monte_carlo"
    samples: int = 1000
    seed: int = 0
    fidelity: str | None = None
    tolerance: float | None = None
    outputs: tuple[str, ...] | None = None
    bins: int = 30
    #: A boolean output that defines a feasible design (e.g. ``full_engagement``);
    #: None: a design is feasible when every check it reports passes.
    feasible_when: str | None = None
    #: Rank (Spearman) correlations between pairs of varied inputs, ``(a, b, rho_S)``:
    #: the inputs are joined by a Gaussian copula (Monte Carlo and LHS only).
    correlations: tuple[tuple[str, str, float], ...] = ()
    #: ``method="points"``: the designs themselves, a column per numeric input (SI units,
    #: one value per design) instead of ``variables``; the rest of the inputs from ``base``.
    points: Mapping[str, np.ndarray] | None = None


@dataclass
class Plan:
    """The points of a study, in evaluation order, and what to collect."""

    columns: dict[str, np.ndarray]
    n_points: int
    outputs: tuple[str, ...]
    grid_shape: tuple[int, ...] | None = None
    grid_axes: dict[str, np.ndarray] | None = None
    sobol_base: int | None = None
    notes: list[str] = field(default_factory=list)


@dataclass
class ChunkResult:
    """The values of one chunk of points; NaN where a point was refused.

    ``summary``: the chunk's partial summary (:func:`summarize_chunk`), where the chunk's
    executor made it; for a merged study, the study's, combined from its chunks'.
    """

    values: Mapping[str, np.ndarray]
    checks: dict[str, np.ndarray]
    rungs: list[str | None]
    refusals: dict[str, int]
    elapsed_s: float
    summary: ChunkSummary | None = None

    def __getstate__(self) -> dict[str, Any]:
        # a column of one number (a zero-stride view: :func:`one_numbers`) travels as that
        # number and its length, where pickle would send the length's worth of copies
        state = dict(self.__dict__)
        state["values"] = {
            name: (y[:1].copy(), y.size) if is_one_number(y) else y
            for name, y in self.values.items()
        }
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        state["values"] = {
            name: np.broadcast_to(y[0], (y[1],)) if isinstance(y, tuple) else y
            for name, y in state["values"].items()
        }
        self.__dict__.update(state)


def _one_number(y: np.ndarray) -> np.ndarray | None:
    """``y`` as a read-only zero-stride view of its first value where every value has its
    bits (so -0.0 and 0.0 stay apart, and NaNs of other payloads), else None."""
    if y.ndim != 1 or y.size < 2:
        return None
    if is_one_number(y):
        return y
    first = y[:1].copy()
    same = y.view(np.int64) == first.view(np.int64)[0]
    return np.broadcast_to(first, y.shape) if bool(same.all()) else None


def _one_of(y: np.ndarray, moments: Moments | None) -> np.ndarray | None:
    """:func:`_one_number` of ``y`` told from its ``moments`` (its finite values' partial
    summary) where they can tell it, with no pass over ``y``: a finite value beside a NaN,
    or two extremes, is not one number; every value finite and the extremes equal and not
    zero is (two equal floats other than 0.0 and -0.0 have the same bits). Only equal
    zeros and chunks with no finite value (``moments`` None) are compared bit by bit.

    >>> m = Moments.of(np.full(4, 2.5))
    >>> _one_of(np.full(4, 2.5), m).strides, _one_of(np.array([2.5, np.nan]), m)
    ((0,), None)
    >>> _one_of(np.array([0.0, -0.0]), Moments.of(np.array([0.0, -0.0]))) is None
    True
    """
    if moments is not None:
        if moments.count != y.size or moments.low != moments.high:
            return None
        if moments.low != 0.0 and y.ndim == 1 and y.size > 1:
            return np.broadcast_to(y[:1].copy(), y.shape)
    return _one_number(y)


def one_numbers(part: ChunkResult) -> ChunkResult:
    """``part`` with each output whose chunk is one number (its partial summary's
    extremes equal, no refused point; or no finite value, each NaN to the bit) as a
    zero-stride view of it: a chunk sent from a Dask worker then carries a number, not a
    column of copies (most outputs of a study are not moved by its varied inputs, and an
    output a design does not have is NaN at every point: 9 of the 24 columns a preload
    study's chunk sent)."""
    summary = part.summary or summarize_chunk(part).summary
    assert summary is not None
    values = dict(part.values)
    for name, y in values.items():
        one = _one_of(y, summary.moments.get(name))
        if one is not None:
            values[name] = one
    return replace(part, values=values)


# --------------------------------------------------------------------------- planning


def _numeric_param(spec: ModelSpec, name: str) -> Param:
    try:
        param = spec.param(name)
    except KeyError:
        raise InputOutOfRange(
            f"variables: {name!r} is not an input of {spec.name}", field="variables"
        ) from None
    if not param.is_numeric:
        raise InputOutOfRange(
            f"variables: {name!r} is not a numeric input of {spec.name}", field="variables"
        )
    return param


def _need(var: Variable, *names: str) -> list[float]:
    got = []
    for n in names:
        value = getattr(var, n)
        if value is None or not math.isfinite(float(value)):
            raise InputOutOfRange(
                f"variables: {var.name} ({var.distribution}) needs a finite {n}",
                field="variables",
            )
        got.append(float(value))
    return got


def _bounds(param: Param, var: Variable) -> tuple[float, float]:
    """The interval a variable may take: its own low/high within the declared range."""
    lo = -math.inf if param.minimum is None else float(param.minimum)
    hi = math.inf if param.maximum is None else float(param.maximum)
    if var.low is not None:
        if var.low < lo or (param.exclusive_minimum and var.low <= lo):
            raise param._error(var.low)
        lo = float(var.low)
    if var.high is not None:
        if var.high > hi or (param.exclusive_maximum and var.high >= hi):
            raise param._error(var.high)
        hi = float(var.high)
    if not lo < hi:
        raise InputOutOfRange(
            f"variables: {var.name} needs low < high (got {lo:g} and {hi:g} {param.unit})",
            field="variables",
        )
    return lo, hi


def _transform(param: Param, var: Variable, u: np.ndarray) -> np.ndarray:
    """Map uniform numbers in (0, 1) to the variable's (truncated) distribution.

    Each law's quantile function is :mod:`engine.numerics.laws`', the one the clamp-force
    capability integrates over too.
    """
    lo, hi = _bounds(param, var)
    if var.distribution == "uniform":
        _need(var, "low", "high")
        x = laws.uniform_ppf(u, lo, hi)
    elif var.distribution == "triangular":
        a, c, b = _need(var, "low", "mode", "high")
        if not a <= c <= b:
            raise InputOutOfRange(
                f"variables: {var.name} needs low ≤ mode ≤ high", field="variables"
            )
        x = laws.triangular_ppf(u, a, c, b)
    elif var.distribution in ("normal", "lognormal"):
        mean, sd = _need(var, "mean", "sd")
        if not sd > 0.0:
            raise InputOutOfRange(f"variables: {var.name} needs sd > 0", field="variables")
        if var.distribution == "normal":
            loc, scale, a, b = mean, sd, (lo - mean) / sd, (hi - mean) / sd
        else:
            if not mean > 0.0 or hi <= 0.0:
                raise InputOutOfRange(
                    f"variables: {var.name}: a lognormal law needs mean > 0 and a positive range",
                    field="variables",
                )
            median, gsd = laws.lognormal_from_mean_sd(mean, sd)
            loc, scale = math.log(median), math.log(gsd)
            a = (math.log(lo) - loc) / scale if lo > 0.0 else -math.inf
            b = (math.log(hi) - loc) / scale
        if not a < b or a > 37.0 or b < -37.0:
            raise InputOutOfRange(
                f"variables: {var.name}: the {var.distribution} law of mean {mean:g} and sd "
                f"{sd:g} has no mass inside {lo:g}…{hi:g} {param.unit}",
                field="variables",
            )
        if var.distribution == "normal":
            x = laws.truncated_normal_ppf(u, mean, sd, lo, hi)
        else:
            x = laws.truncated_lognormal_ppf(u, median, gsd, max(lo, 0.0), hi)
    else:
        raise InputOutOfRange(
            f"variables: {var.name}: distribution must be one of {', '.join(DISTRIBUTIONS)}",
            field="variables",
        )
    x = np.clip(np.asarray(x, dtype=float), lo, hi)
    if param.kind == "int":
        x = np.clip(np.round(x), math.ceil(lo), math.floor(hi))
    return x


#: Uniform numbers a law's quantile function takes at once while a study is drawn.
DRAW_BLOCK = 65_536


def _transform_blocks(param: Param, var: Variable, u: np.ndarray) -> np.ndarray:
    """:func:`_transform` of ``u`` :data:`DRAW_BLOCK` numbers at a time into one column:
    the same numbers (each law's quantile function works number by number), without the
    temporaries of a quantile function over the whole study at once (scipy's truncated
    normal held some 250 MB at once for 10⁶ points).

    >>> v = Variable("thread_friction", "normal", mean=0.12, sd=0.012)
    >>> param = Param("thread_friction", "", "friction", minimum=0.0, maximum=1.0)
    >>> u = np.random.default_rng(1).random(3 * DRAW_BLOCK + 5)
    >>> bool((_transform_blocks(param, v, u) == _transform(param, v, u)).all())
    True
    """
    if u.size <= DRAW_BLOCK:
        return _transform(param, var, u)
    out = np.empty(u.size)
    for a in range(0, u.size, DRAW_BLOCK):
        out[a : a + DRAW_BLOCK] = _transform(param, var, u[a : a + DRAW_BLOCK])
    return out


def _correlation_matrix(study: Study) -> np.ndarray | None:
    """The Gaussian copula's correlation matrix of the varied inputs' normal scores.

    Each pair's rank correlation ρ_S becomes ρ = 2 sin(π ρ_S / 6)
    (:func:`engine.numerics.laws.copula_from_spearman`); None without correlations.
    """
    if not study.correlations:
        return None
    if study.method not in ("monte_carlo", "lhs"):
        raise InputOutOfRange(
            f"correlations: only Monte Carlo and LHS studies take correlated inputs, not "
            f"{study.method!r} (Sobol' indices and grids assume independent inputs)",
            field="correlations",
        )
    index = {v.name: i for i, v in enumerate(study.variables)}
    r = np.eye(len(index))
    seen: set[frozenset[str]] = set()
    for pair in study.correlations:
        a, b, rank = pair
        if a not in index or b not in index or a == b:
            raise InputOutOfRange(
                f"correlations: ({str(a)[:40]!r}, {str(b)[:40]!r}) must name two different "
                "varied inputs",
                field="correlations",
            )
        if frozenset((a, b)) in seen:
            raise InputOutOfRange(
                f"correlations: the pair ({a}, {b}) is given twice", field="correlations"
            )
        seen.add(frozenset((a, b)))
        if not -MAX_CORRELATION <= float(rank) <= MAX_CORRELATION:
            raise InputOutOfRange(
                f"correlations: rank correlation {rank!r} of ({a}, {b}) is not allowed: must "
                f"be −{MAX_CORRELATION}…{MAX_CORRELATION}",
                field="correlations",
            )
        r[index[a], index[b]] = r[index[b], index[a]] = float(laws.copula_from_spearman(rank))
    if np.linalg.eigvalsh(r)[0] <= 1e-9:
        raise InputOutOfRange(
            "correlations: the correlations given contradict each other (their matrix is "
            "not positive definite)",
            field="correlations",
        )
    return r


def _grid_axis(param: Param, var: Variable) -> np.ndarray:
    lo, hi = _bounds(param, var)
    _need(var, "low", "high")
    if not 2 <= var.num <= 1000:
        raise InputOutOfRange(
            f"variables: {var.name}: a grid axis has 2…1000 points", field="variables"
        )
    if var.scale == "log":
        if lo <= 0:
            raise InputOutOfRange(
                f"variables: {var.name}: a log axis needs low > 0", field="variables"
            )
        axis = np.geomspace(lo, hi, var.num)
    elif var.scale == "linear":
        axis = np.linspace(lo, hi, var.num)
    else:
        raise InputOutOfRange(
            f"variables: {var.name}: scale must be 'linear' or 'log'", field="variables"
        )
    if param.kind == "int":
        axis = np.unique(np.round(axis))
    return axis


def scalar_outputs(spec: ModelSpec) -> tuple[str, ...]:
    """The outputs a study can collect: every numeric or boolean scalar."""
    return tuple(
        o.name for o in spec.outputs if not o.series and o.kind in ("float", "int", "bool")
    )


def study_size(spec: ModelSpec, study: Study) -> int:
    r"""The number of points ``study`` evaluates, found without drawing them.

    Everything :func:`plan` refuses before it draws is refused here too (method, variables
    and their laws, base, bins, seed, outputs, fidelity, size), so a server can check its
    quotas before it spends the time and memory of drawing. For ``sobol`` the count is
    Saltelli's design, :math:`N = 2^{\lceil \log_2 n \rceil} (k + 2)` for ``n`` samples
    and ``k`` inputs [Saltelli2010]; for a grid the product of the axes' lengths.

    >>> from engine.models import get_model
    >>> clutch = get_model("clutch.ball")
    >>> law = Variable("flank_friction", low=0.0, high=0.1)
    >>> study_size(clutch, Study(variables=(law,), method="sobol", samples=1000))
    3072
    >>> grid = Variable("flank_friction", low=0.0, high=0.1, num=7)
    >>> study_size(clutch, Study(variables=(grid,), method="grid"))
    7
    """
    return _checked(spec, study)[2]


def _checked(
    spec: ModelSpec, study: Study
) -> tuple[list[Param], tuple[str, ...], int, dict[str, np.ndarray] | None]:
    """What :func:`plan` needs before drawing: the varied params, the outputs to collect,
    the number of points and (a grid) its axes; every cheap refusal is raised here."""
    if study.tolerance is not None:  # as engine.run refuses it, before a point is drawn
        check_tolerance(float(study.tolerance))
    if study.method not in METHODS:
        raise InputOutOfRange(
            f"method = {study.method!r} is not allowed: must be one of {', '.join(METHODS)}",
            field="method",
        )
    if study.method == "points":
        params, n = _explicit(spec, study)
        return params, _collected(spec, study), n, None
    if study.points is not None:
        raise InputOutOfRange(
            f"points: explicit designs need method 'points', not {study.method!r}", field="points"
        )
    if not study.variables:
        raise InputOutOfRange("variables: vary at least one input", field="variables")
    if len(study.variables) > MAX_VARIABLES:
        raise InputOutOfRange(
            f"variables: a study varies at most {MAX_VARIABLES} inputs", field="variables"
        )
    names = [v.name for v in study.variables]
    if len(set(names)) != len(names):
        raise InputOutOfRange("variables: each input may vary once", field="variables")
    params = [_numeric_param(spec, v.name) for v in study.variables]
    if any(n in study.base for n in names):
        raise InputOutOfRange(
            "base: an input that varies may not also be fixed in base", field="base"
        )
    outputs = _collected(spec, study)
    k = len(params)
    if study.method == "grid":
        if k > MAX_GRID_INPUTS:
            raise InputOutOfRange(
                f"variables: a grid varies at most {MAX_GRID_INPUTS} inputs", field="variables"
            )
        axes = {v.name: _grid_axis(p, v) for p, v in zip(params, study.variables, strict=True)}
        n = math.prod(a.size for a in axes.values())
        _check_size(n)
        return params, outputs, n, axes
    if study.samples < 2:
        raise InputOutOfRange("samples must be ≥ 2", field="samples")
    for p, v in zip(params, study.variables, strict=True):
        _transform(p, v, np.full(1, 0.5))  # each law's refusals, on one number
    _correlation_matrix(study)
    n = study.samples
    if study.method == "sobol":
        n = 2 ** math.ceil(math.log2(study.samples)) * (k + 2)
    _check_size(n)
    return params, outputs, n, None


def _collected(spec: ModelSpec, study: Study) -> tuple[str, ...]:
    """The outputs to collect (with ``feasible_when``), after the cheap refusals of the
    bins, the seed, the outputs and the fidelity."""
    if not 1 <= study.bins <= MAX_HISTOGRAM_BINS:
        raise InputOutOfRange(f"bins must be 1…{MAX_HISTOGRAM_BINS}", field="bins")
    if not 0 <= study.seed < 2**63:
        raise InputOutOfRange("seed must be an integer ≥ 0 and < 2^63", field="seed")
    collectable = scalar_outputs(spec)
    outputs = collectable if study.outputs is None else tuple(study.outputs)
    unknown = [o for o in outputs if o not in collectable]
    if unknown or not outputs:
        raise InputOutOfRange(
            f"outputs: {', '.join(unknown) or 'none'} cannot be collected; "
            f"{spec.name} offers {', '.join(collectable)}",
            field="outputs",
        )
    if study.feasible_when is not None:
        kinds = {o.name: o.kind for o in spec.outputs}
        if kinds.get(study.feasible_when) != "bool":
            raise InputOutOfRange(
                f"feasible_when = {study.feasible_when!r} is not a true/false output of "
                f"{spec.name}",
                field="feasible_when",
            )
        if study.feasible_when not in outputs:
            outputs = (*outputs, study.feasible_when)
    rungs = (*spec.rung_names, "auto")
    if study.fidelity is not None and study.fidelity not in rungs:
        raise InputOutOfRange(
            f"fidelity = {str(study.fidelity)[:40]!r} is not a rung of {spec.name}: "
            f"one of {', '.join(repr(r) for r in rungs)}",
            field="fidelity",
        )
    return outputs


def _explicit(spec: ModelSpec, study: Study) -> tuple[list[Param], int]:
    """An explicit-point study's columns checked before any work: numeric inputs not in
    ``base``, at most ``MAX_POINT_COLUMNS`` of them, one length, and every value in its
    input's range (an integer input's integral); a refusal names the design and the input.

    >>> from engine.models import get_model
    >>> clutch = get_model("clutch.ball")
    >>> designs = {"flank_friction": np.array([0.05, 0.08, 1.5])}
    >>> try:
    ...     _explicit(clutch, Study(variables=(), method="points", points=designs))
    ... except InputOutOfRange as exc:
    ...     print(exc.field, "|", exc.message)  # doctest: +NORMALIZE_WHITESPACE
    points | points: design 3 (points[2]), flank_friction = 1.5 is not allowed: must be
    a finite number ≥ 0 and ≤ 1
    """
    columns = study.points or {}
    if study.variables or study.correlations:
        raise InputOutOfRange(
            "points: explicit designs take neither variables nor correlations", field="points"
        )
    if not columns:
        raise InputOutOfRange("points: give at least one design of one input", field="points")
    if len(columns) > MAX_POINT_COLUMNS:
        raise InputOutOfRange(
            f"points: a design gives at most {MAX_POINT_COLUMNS} inputs, not {len(columns)}",
            field="points",
        )
    lengths = {len(col) for col in columns.values()}
    n = lengths.pop()
    if lengths or n < 1:
        raise InputOutOfRange("points: every input needs one value per design", field="points")
    _check_size(n)
    params: list[Param] = []
    for name, col in columns.items():
        try:
            param: Param | None = spec.param(name)
        except KeyError:
            param = None
        if param is None or not param.is_numeric:
            what = "an input" if param is None else "a numeric input"
            raise InputOutOfRange(
                f"points: {str(name)[:80]!r} is not {what} of {spec.name}"
                + ("" if param is None else "; give it in base"),
                field="points",
            )
        if name in study.base:
            raise InputOutOfRange(
                f"points: {name} is given per design and in base: give it once", field="points"
            )
        values = np.asarray(col, dtype=float)
        bad = ~in_range(param, values)
        if param.kind == "int":
            bad |= np.isfinite(values) & (values != np.round(values))
        if bad.any():
            j = int(np.flatnonzero(bad)[0])
            unit = "" if param.unit == "1" else f" {param.unit}"
            raise InputOutOfRange(
                f"points: design {j + 1} (points[{j}]), {name} = {values[j]:g}{unit} is not "
                f"allowed: must be {param.range_text()}",
                field="points",
                row=j,
                input=name,
            )
        params.append(param)
    return params, n


def plan(spec: ModelSpec, study: Study) -> Plan:
    """Validate a study and draw its points (seeded; SI units)."""
    params, outputs, n, axes = _checked(spec, study)
    names = [v.name for v in study.variables]
    notes: list[str] = []
    k = len(params)
    if study.method == "points":
        given = study.points or {}
        columns = {name: np.asarray(col, dtype=float).copy() for name, col in given.items()}
        _validate_base(spec, study, columns)
        return Plan(columns, n, outputs, notes=notes)
    if axes is not None:
        shape = tuple(a.size for a in axes.values())
        mesh = np.meshgrid(*axes.values(), indexing="ij")
        columns = {name: m.ravel() for name, m in zip(axes, mesh, strict=True)}
        _validate_base(spec, study, columns)
        return Plan(columns, n, outputs, grid_shape=shape, grid_axes=axes, notes=notes)
    if study.method == "sobol":
        # Saltelli's design: A and B from one 2k-dimensional scrambled Sobol' sequence
        # (a power of two keeps the sequence balanced), then A with column i from B.
        m = math.ceil(math.log2(study.samples))
        base_n = 2**m
        if base_n != study.samples:
            notes.append(
                f"samples rounded up from {study.samples} to {base_n}, a power of two, which "
                "keeps the Sobol' sequence balanced"
            )
        u = qmc.Sobol(d=2 * k, scramble=True, seed=np.random.default_rng(study.seed)).random_base2(
            m
        )
        u = np.clip(u, 1e-12, 1.0 - 1e-12)
        a = np.column_stack(
            [
                _transform(p, v, u[:, i])
                for i, (p, v) in enumerate(zip(params, study.variables, strict=True))
            ]
        )
        b = np.column_stack(
            [
                _transform(p, v, u[:, k + i])
                for i, (p, v) in enumerate(zip(params, study.variables, strict=True))
            ]
        )
        blocks = [a, b]
        for i in range(k):
            ab = a.copy()
            ab[:, i] = b[:, i]
            blocks.append(ab)
        matrix = np.vstack(blocks)
        columns = {name: matrix[:, i].copy() for i, name in enumerate(names)}
        _validate_base(spec, study, columns)
        return Plan(columns, matrix.shape[0], outputs, sobol_base=base_n, notes=notes)
    rng = np.random.default_rng(study.seed)
    u = qmc.LatinHypercube(d=k, seed=rng).random(n) if study.method == "lhs" else rng.random((n, k))
    np.clip(u, 1e-12, 1.0 - 1e-12, out=u)  # in place: a study's draws are held once
    correlation = _correlation_matrix(study)
    if correlation is not None:
        # Gaussian copula: the uniforms' normal scores correlated, then back to uniforms
        u = np.clip(
            special.ndtr(laws.correlate_scores(special.ndtri(u), correlation)), 1e-12, 1.0 - 1e-12
        )
        notes.append(
            "correlated inputs drawn through a Gaussian copula of the given rank correlations"
            + (" (the copula mixes the Latin hypercube's strata)" if study.method == "lhs" else "")
        )
    columns = {
        v.name: _transform_blocks(p, v, u[:, i])
        for i, (p, v) in enumerate(zip(params, study.variables, strict=True))
    }
    _validate_base(spec, study, columns)
    return Plan(columns, n, outputs, notes=notes)


def _validate_base(spec: ModelSpec, study: Study, columns: Mapping[str, np.ndarray]) -> None:
    """The fixed inputs, with the first point's varied ones, must pass the model's checks."""
    first = {name: col[0].item() for name, col in columns.items()}
    for name, value in first.items():
        if spec.param(name).kind == "int":
            first[name] = int(value)
    spec.validate({**{k: v for k, v in study.base.items() if v is not None}, **first})


def _check_size(n: int) -> None:
    if n > MAX_STUDY_POINTS:
        raise InputOutOfRange(
            f"the study has {n} points, over the limit of {MAX_STUDY_POINTS}", field="samples"
        )


def chunks(n_points: int, size: int) -> list[tuple[int, int]]:
    """``[start, stop)`` slices of at most ``size`` points, in order."""
    size = max(1, int(size))
    return [(i, min(i + size, n_points)) for i in range(0, n_points, size)]


# --------------------------------------------------------------------------- evaluation


#: A number in a refusal's reason: a sign, digits, decimals, an exponent; not one that is part
#: of a name (M10, R_p0.2, 898-1) nor a standard's number (ISO 261, VDI 2230, DIN 912, EN 13906)
_REASON_NUMBER = re.compile(
    r"(?<![\w.\-])(?<!ISO )(?<!VDI )(?<!DIN )(?<!EN )"
    r"[-+]?\d+(?:[.,]\d+)*(?:[eE][-+]?\d+)?(?![\w.]|-\d)"
)


def refusal_key(exc: EngineError) -> str:
    """The row a refused point is counted in: the error's class and its message's reason (the
    text before its first colon), each number in it written "…", at most 120 characters of it
    (cut after the numbers are written: a reason with longer figures is the same row).

    The reason is what the design did wrong; its figures are the design's own: a step
    budget's refusal says how many steps that design would take (about 3.1e+08 RK4 steps,
    about 2.6e+08, …), and counted by its whole text a study of stiff strikers had a row per
    design where it has one.

    >>> from engine.core.errors import BudgetExceeded, InfeasibleDesign
    >>> refusal_key(BudgetExceeded("it would take about 3.1e+08 RK4 steps (budget 1e+06): x"))
    'BudgetExceeded: it would take about … RK4 steps (budget …)'
    >>> refusal_key(InfeasibleDesign("no ISO 261 pitch, d = 13.5 mm (M10, R_p0.2, 898-1, -2): y"))
    'InfeasibleDesign: no ISO 261 pitch, d = … mm (M10, R_p0.2, 898-1, …)'
    """
    reason = _REASON_NUMBER.sub("…", exc.message.split(":")[0])
    return type(exc).__name__ + ": " + reason[:120]


#: Looped points whose outputs :func:`evaluate_chunk` keeps as rows before it puts them into
#: the columns (bounds the rows' memory where a large chunk loops).
LOOP_ROWS = 256


def evaluate_chunk(
    spec: ModelSpec | str,
    base: Mapping[str, Any],
    columns: Mapping[str, np.ndarray],
    outputs: Sequence[str],
    fidelity: str | None = None,
    tolerance: float | None = None,
    deadline_s: float | None = None,
    cancel: threading.Event | None = None,
) -> ChunkResult:
    """Evaluate the points ``columns`` (equal-length arrays) of a study, in order.

    Points that share a rung run through the model's array path where it has
    one for that rung (with its checks where the array path gives them, else
    CHECK_UNKNOWN), else one by one: on a named rung through
    :func:`engine.core.runner.run_point` (:func:`engine.run`'s answer without its per-point
    validation and sentences), under ``auto`` through :func:`engine.run`. A refused point is
    NaN in every output.
    ``deadline_s`` is a budget for the whole chunk, in seconds. ``cancel`` (in-process
    only: an event does not travel to a Dask worker) stops the chunk at the next point or
    inside a point's simulation; the caller then discards it.
    """
    if isinstance(spec, str):
        from ..models import get_model

        spec = get_model(spec)
    start = time.perf_counter()
    deadline = None if deadline_s is None else start + deadline_s
    n = len(next(iter(columns.values())))
    tol = DEFAULT_TOLERANCE if tolerance is None else float(tolerance)
    # each output's column, made NaN (a refused point) only where a part of the chunk or a
    # point alone fills it: a chunk on one rung's array path takes the model's arrays
    values: dict[str, np.ndarray] = {}

    def nan_column(name: str) -> np.ndarray:
        got = values.get(name)
        if got is None:
            got = values[name] = np.full(n, np.nan)
        return got

    checks: dict[str, np.ndarray] = {}
    rungs: list[str | None] = [None] * n
    refusals: dict[str, int] = {}
    cols = {k: np.asarray(v, dtype=float) for k, v in columns.items()}
    # the fixed inputs with the first point's varied ones (each point is range-checked below)
    first = {
        k: (int(v[0]) if spec.param(k).kind == "int" else float(v[0])) for k, v in cols.items()
    }
    fixed, _ = spec.validate({**base, **first})
    valid = np.ones(n, dtype=bool)
    for name, col in cols.items():
        valid &= in_range(spec.param(name), col)
    x: dict[str, Any] = {**fixed, **cols}
    for name, col in cols.items():
        if spec.param(name).kind == "int":
            x[name] = col.astype(np.int64)
    asked = fidelity if fidelity is not None else ("auto" if tolerance is not None else None)
    asked = asked or spec.default_fidelity
    scratch = Scratch()  # the chunk's: the estimates' work on x, for the array path on x
    if asked == "auto":
        estimates = rung_estimates(spec, x, n, scratch=scratch)
        index = None if estimates is None else auto_index(spec, estimates, n, tol)
    else:
        choose_rung(spec, fixed, asked, tol)  # refuses an unknown rung name
        index = np.full(n, spec.rung_names.index(asked), dtype=np.int64)
    loop = np.zeros(n, dtype=bool) if index is not None else valid.copy()
    if index is not None:
        for i, rung in enumerate(spec.rung_names):
            sel = valid & (index == i)
            if not sel.any():
                continue
            whole = bool(sel.all())  # the estimates' inputs: their work applies to them
            vec = vector(
                spec,
                x if whole else take(x, n, sel),  # every point: the inputs as they are
                rung,
                outputs,
                tol,
                int(sel.sum()),
                scratch=scratch if whole else None,
                one_numbers=True,  # read here, never written: one number stays a view
            )
            if vec is None or not vec.computed:
                # none of the asked outputs comes from this rung's array path here: its
                # NaN columns cannot tell a refused point from a null the scalar path gives
                # too, so the points run one by one (their checks and refusals as alone)
                loop |= sel
                continue
            got = vec.values
            # a point with no finite output is one the model refuses (NaN by the array
            # contract); once every point has one, no further column is looked at
            dead = np.ones(int(sel.sum()), dtype=bool)
            some_dead = True
            for name, column in got.items():
                if whole:
                    values[name] = np.asarray(column, dtype=float)
                else:
                    nan_column(name)[sel] = column
                if some_dead:
                    dead &= np.isnan(column)
                    some_dead = bool(dead.any())
            if dead.any():
                key = "not computable on the array path (an infeasible design)"
                refusals[key] = refusals.get(key, 0) + int(dead.sum())
            for name, codes in vec.checks.items():
                arr = checks.get(name)
                if arr is None:
                    arr = checks[name] = np.full(n, CHECK_UNKNOWN, dtype=np.int8)
                arr[sel] = np.where(dead, CHECK_UNKNOWN, codes)
            if whole and not dead.any():
                rungs = [rung] * n
                continue
            for j, is_dead in zip(np.flatnonzero(sel).tolist(), dead.tolist(), strict=True):
                rungs[j] = None if is_dead else rung
    # a named rung: each point's inputs are the chunk's validated ones with its own varied
    # values (each checked as validate checks it) and run on that rung without the sentences
    # (run_point); under auto (each point's own estimates) or where a value is refused, the
    # point goes through engine.run as a request would
    named = asked != "auto"
    to_loop = np.flatnonzero(loop).tolist()
    # what run_point checks of the tolerance, the rung and the outputs is the chunk's: checked
    # once here (where it refuses, each point checks and is refused as before)
    checked: frozenset[str] | None = None
    if named and to_loop:
        try:
            checked = point_outputs(spec, fixed, asked, outputs, tol)
        except EngineError:
            checked = None
    # each varied column as Python numbers once (what .item() gives a point at a time); a
    # looped point is in ``valid`` (finite and within the declared bounds, as Param.check
    # asks), so of a float input's check only the fold of -0.0 is left: made on the column
    # (x + 0.0 is x, and 0.0 for -0.0); an int input is checked point by point (whole)
    varied: list[tuple[str, Param | None, list[Any]]] = []
    folded: dict[str, Any] = {}  # the looped points' varied inputs as they take them
    for name in cols if to_loop else ():
        param = spec.param(name)
        if param.kind == "float":
            folded[name] = x[name] + 0.0
            varied.append((name, None, folded[name].tolist()))
        else:
            folded[name] = x[name]
            varied.append((name, param, x[name].tolist()))
    # the work a looped point's model does from its inputs alone, made for them at once
    # where the model says how (ModelSpec.prepare_points: an entry a point, or None)
    prepared: Sequence[Any] | None = None
    if named and to_loop and spec.prepare_points is not None:
        points = {**x, **folded}
        prepared = spec.prepare_points(
            points if len(to_loop) == n else take(points, n, loop), asked
        )
    # the looped points' outputs, a row each in the order of ``outputs`` (None where null),
    # put into their columns in one assignment a column every LOOP_ROWS points (a value a
    # time cost µs a point: 21 outputs of the striker's study); their verdicts likewise
    looped: list[int] = []
    rows: list[list[Any]] = []
    verdicts: list[list[tuple[str, bool]]] = []

    def check_column(name: str) -> np.ndarray:
        arr = checks.get(name)
        if arr is None:
            arr = checks[name] = np.full(n, CHECK_UNKNOWN, dtype=np.int8)
        return arr

    def put_rows() -> None:
        block = np.array(rows, dtype=float)  # None: NaN, as float() of each value
        for i, name in enumerate(outputs):
            nan_column(name)[looped] = block[:, i]
        try:  # (point, check, name or verdict) where every point has the same checks
            pairs = np.array(verdicts, dtype=object)
        except ValueError:
            pairs = None
        if (
            pairs is not None
            and pairs.ndim == 3
            and pairs.shape[2] == 2
            and bool((pairs[:, :, 0] == pairs[:1, :, 0]).all())
        ):
            for c, name in enumerate(pairs[0, :, 0].tolist()):
                check_column(name)[looped] = np.where(
                    pairs[:, c, 1].astype(bool), CHECK_OK, CHECK_FAILED
                )
        else:
            for j, flags in zip(looped, verdicts, strict=True):
                for name, ok in flags:
                    check_column(name)[j] = CHECK_OK if ok else CHECK_FAILED
        looped.clear()
        rows.clear()
        verdicts.clear()

    def past_budget() -> BudgetExceeded:
        return BudgetExceeded(
            f"a chunk of the study ran past its {deadline_s:g} s budget", field="samples"
        )

    # numpy's error state as every point's evaluation sets it (all="ignore"), entered
    # once for the loop: run_point made and entered one a point (2 µs of the striker's
    # study); a point through engine.run enters its own as a request does
    with np.errstate(all="ignore"):
        for k, j in enumerate(to_loop):
            if cancel is not None and cancel.is_set():
                break
            if deadline is not None and time.perf_counter() > deadline:
                raise past_budget()
            values_j = _point_values(fixed, varied, j) if named else None
            # a point has what is left of the chunk's budget (none without one)
            left = None if deadline is None else max(deadline - time.perf_counter(), 1e-3)
            try:
                if values_j is not None:
                    res = run_point(
                        spec,
                        values_j,
                        asked,
                        outputs,
                        tolerance=tol,
                        budget_s=left,
                        cancel=cancel,
                        checked=checked,
                        silenced=True,
                        prepared=None if prepared is None else prepared[k],
                    )
                else:
                    res = _as_point(
                        run(
                            spec,
                            {k: v for k, v in at(x, n, j).items() if v is not None},
                            fidelity=asked,
                            tolerance=tol,
                            outputs=outputs,
                            budget_s=left,
                            cancel=cancel,
                        ),
                        outputs,
                    )
            except Cancelled:
                break
            except EngineError as exc:
                if isinstance(exc, BudgetExceeded) and left is not None and left < DEFAULT_BUDGET_S:
                    # with a deadline every step budget is the time it leaves: refused with less
                    # time than a request alone has (DEFAULT_BUDGET_S), the chunk's time ran out,
                    # not the point's; counted as a refusal it would depend on the machine's load,
                    # so the chunk stops as its budget says
                    raise past_budget() from exc
                key = refusal_key(exc)
                refusals[key] = refusals.get(key, 0) + 1
                continue
            rungs[j], results, flags = res
            looped.append(j)
            # run_point's dict has the outputs in their order, each once: its values are
            # the row (a repeated name has one key, and takes the names' lookups)
            row = list(results.values())
            rows.append(row if len(row) == len(outputs) else list(map(results.get, outputs)))
            verdicts.append(flags)  # the verdicts alone: no sentence is made
            if len(rows) >= LOOP_ROWS:
                put_rows()
    if rows:
        put_rows()
    values = {o: nan_column(o) for o in outputs} | values  # the asked order, every one
    bad = int((~valid).sum())
    if bad:
        for column in values.values():
            column[~valid] = np.nan
        refusals["outside an input's declared range"] = bad
    return ChunkResult(values, checks, rungs, refusals, time.perf_counter() - start)


def _point_values(
    fixed: Mapping[str, Any], varied: Sequence[tuple[str, Param | None, list[Any]]], j: int
) -> dict[str, Any] | None:
    """Point ``j``'s validated inputs: ``fixed`` (the chunk's, validated once) with its
    varied values, each checked as :meth:`ModelSpec.validate` checks it (a column whose
    param is None is checked already: taken as it is); None where one is refused (the
    point then goes through :func:`engine.run`, which says why)."""
    values = dict(fixed)
    try:
        for name, param, column in varied:
            values[name] = column[j] if param is None else param.check(column[j])
    except InputOutOfRange:
        return None
    return values


def _as_point(res: RunResult, outputs: Sequence[str]) -> tuple[str, dict[str, Any], list[Any]]:
    """A result of :func:`engine.run` as :func:`engine.core.runner.run_point` gives a point."""
    return res.rung, {name: res.results.get(name) for name in outputs}, res.check_flags


class Columns(Mapping[str, np.ndarray]):
    """A study's output columns, each made whole once, as the chunks arrive.

    An output whose chunks are all one number, each to the last bit, holds those numbers
    alone (read-only broadcast views, no memory): a study's outputs that the varied
    inputs do not move hold nothing. The first chunk of an output that moves gets its
    whole column (one array of the study's length; the chunks put before it written
    in), and every chunk is then copied to its place in it: the chunk's own arrays are let
    go, so the next chunk's evaluation reuses their memory, and the study's values are
    first touched once, in large arrays, not chunk by chunk in fresh small ones (a cost
    that was larger than the merge). The summary reads the pieces (:meth:`pieces`) and the
    first points (:meth:`head`), copying nothing; ``columns[name]`` is a new array.

    >>> c = Columns(5, ("y", "k"))
    >>> c.put("y", 3, np.array([7.0, 7.0]))
    >>> c.put("k", 0, np.full(3, 2.0)); c.put("k", 3, np.full(2, 2.0))
    >>> c.nbytes
    0
    >>> c.put("y", 0, np.array([1.0, 2.0, 3.0]))
    >>> c["y"].tolist(), c.head("y", 4).tolist(), c["k"].tolist(), c.nbytes
    ([1.0, 2.0, 3.0, 7.0, 7.0], [1.0, 2.0, 3.0, 7.0], [2.0, 2.0, 2.0, 2.0, 2.0], 40)
    """

    def __init__(self, n_points: int, names: Sequence[str]) -> None:
        self.n_points = n_points
        self._pieces: dict[str, dict[int, np.ndarray]] = {name: {} for name in names}
        self._whole: dict[str, np.ndarray] = {}

    def put(self, name: str, start: int, y: np.ndarray, moments: Moments | None = None) -> None:
        """Keep ``y``, the values of points ``start`` onward of output ``name``.

        ``moments``: the partial summary of ``y``'s finite values where the caller has it,
        which tells whether they are one number without comparing their bits where it can
        (:func:`_one_of`); None: they are compared."""
        y = np.asarray(y, dtype=float)
        whole = self._whole.get(name)
        if whole is None:
            one = _one_of(y, moments)
            if one is not None:
                self._pieces[name][start] = one  # one number, to the bit: no memory
                return
            whole = self._whole[name] = np.empty(self.n_points)
            for a, piece in self._pieces[name].items():
                whole[a : a + piece.size] = piece
            self._pieces[name] = {}
        whole[start : start + y.size] = y

    def pieces(self, name: str) -> list[np.ndarray]:
        """The column's pieces in the points' order (every chunk put): its whole array
        where it has one."""
        whole = self._whole.get(name)
        if whole is not None:
            return [whole]
        got = self._pieces[name]
        return [got[a] for a in sorted(got)]

    def head(self, name: str, m: int) -> np.ndarray:
        """The column's first ``m`` values (fewer if it is shorter): a view where the
        column is whole or those values are one number (a zero-stride view of it), else
        only those copied.

        >>> c = Columns(6, ("k", "s"))
        >>> c.put("k", 0, np.full(3, 2.0)); c.put("k", 3, np.full(3, 2.0))
        >>> c.put("s", 0, np.full(3, 1.0)); c.put("s", 3, np.full(3, 2.0))
        >>> c.head("k", 5).tolist(), c.head("k", 5).strides, c.head("s", 5).tolist()
        ([2.0, 2.0, 2.0, 2.0, 2.0], (0,), [1.0, 1.0, 1.0, 2.0, 2.0])
        """
        whole = self._whole.get(name)
        if whole is not None:
            return whole[:m]
        out, size = [], 0
        for piece in self.pieces(name):
            if size >= m:
                break
            out.append(piece[: m - size])
            size += out[-1].size
        one = out and all(is_one_number(y) for y in out)
        if one and len({y[:1].tobytes() for y in out}) == 1:  # one number, to the bit
            return np.broadcast_to(out[0][:1], (size,))
        return np.concatenate(out) if out else np.empty(0)

    def rows(self, name: str, a: int, b: int) -> np.ndarray:
        """The column's values of points ``a`` to ``b`` (excluded).

        >>> c = Columns(5, ("y",))
        >>> c.put("y", 0, np.arange(3.0)); c.put("y", 3, np.arange(3.0, 5.0))
        >>> c.rows("y", 2, 4).tolist()
        [2.0, 3.0]
        """
        whole = self._whole.get(name)
        if whole is not None:
            return whole[a:b]
        got = self._pieces[name]
        out = []
        for start in sorted(got):
            piece = got[start]
            lo, hi = max(a, start), min(b, start + piece.size)
            if lo < hi:
                out.append(piece[lo - start : hi - start])
        return np.concatenate(out) if out else np.empty(0)

    @property
    def nbytes(self) -> int:
        """The bytes the kept values take (the whole columns; one-number chunks none)."""
        return sum(y.nbytes for y in self._whole.values())

    def __getitem__(self, name: str) -> np.ndarray:
        pieces = self.pieces(name)
        return np.concatenate(pieces) if pieces else np.empty(0)  # a new array

    def __iter__(self) -> Iterator[str]:
        return iter(self._pieces)

    def __len__(self) -> int:
        return len(self._pieces)


class Merger:
    """Chunk results gathered, as they arrive, into the study's :class:`Columns`.

    Each chunk is written into the study's whole columns as it arrives (a chunk of one
    number kept as that number, :class:`Columns`), so a study holds its raw values once,
    and the chunk's arrays are let go before the next is evaluated. Checks keep the order
    :func:`merge` gives them (first reported in the earliest chunk first), whatever the
    order the chunks arrive in.

    The chunks' partial summaries (:func:`summarize_chunk`; made here for a chunk that
    comes without one) are kept and combined in the chunks' order at the end, and a study
    of :data:`GATHER_POINTS` points or more counts each output's values in fine bins as
    the chunks arrive (:class:`FineCounts`, placed by the first chunk to arrive), so
    :func:`summarize` finds quantiles and histogram in one cheap pass over the few bins
    that hold them.
    """

    def __init__(self, n_points: int, outputs: Sequence[str]) -> None:
        self.n_points = n_points
        self.values = Columns(n_points, outputs)
        self.checks: dict[str, np.ndarray] = {}
        self._first: dict[str, tuple[int, int]] = {}  # (chunk start, place in its chunk)
        self.rungs: list[str | None] = [None] * n_points
        self.refusals: dict[str, int] = {}
        self.elapsed_s = 0.0
        self.received = 0
        self._summaries: dict[int, ChunkSummary] = {}
        self._gather = n_points >= GATHER_POINTS
        #: per output its fine counts, None where the first chunk could not place them
        self._fine: dict[str, FineCounts | None] = {}

    def add(self, start: int, part: ChunkResult) -> None:
        """Put ``part``, the chunk of points ``start`` onward, in its place."""
        summary = part.summary or summarize_chunk(part).summary
        assert summary is not None
        self._summaries[start] = summary
        stop = start + len(part.rungs)
        for name in self.values:
            m = summary.moments.get(name)
            y = part.values[name]
            if self._gather and m is not None:
                self._count_fine(name, y, m)  # then the copy reads y from the cache
            self.values.put(name, start, y, m)
        for place, (name, codes) in enumerate(part.checks.items()):
            dest = self.checks.get(name)
            if dest is None:
                dest = self.checks[name] = np.full(self.n_points, CHECK_UNKNOWN, dtype=np.int8)
            dest[start:stop] = codes
            self._first[name] = min(self._first.get(name, (start, place)), (start, place))
        self.rungs[start:stop] = part.rungs
        for key, count in part.refusals.items():
            self.refusals[key] = self.refusals.get(key, 0) + count
        self.elapsed_s += part.elapsed_s
        self.received += 1

    def _count_fine(self, name: str, y: np.ndarray, moments: Moments) -> None:
        """Count output ``name``'s chunk ``y`` in its fine bins, placed by the first chunk
        with values (the pilot)."""
        if name not in self._fine:
            finite = y if moments.count == y.size else y[np.isfinite(y)]
            self._fine[name] = FineCounts(finite) if finite.size >= PILOT_MIN else None
        fine = self._fine[name]
        if fine is not None:
            fine.add(y)  # its finite values

    def result(self) -> ChunkResult:
        """The merged study (every chunk added), with its combined partial summary."""
        names = sorted(self.checks, key=self._first.__getitem__)
        starts = sorted(self._summaries)
        parts = [self._summaries[a] for a in starts]
        rungs: dict[str | None, int] = {}
        for s in parts:
            for rung, count in s.rungs.items():
                rungs[rung] = rungs.get(rung, 0) + count

        def shifted(name: str) -> list[Moments | None]:
            # each chunk's moments, their places counted from the study's first point
            moments = (s.moments[name] for s in parts)
            return [
                None if m is None else m.shifted(a) for a, m in zip(starts, moments, strict=True)
            ]

        summary = ChunkSummary(
            moments={name: _combined(shifted(name)) for name in self.values},
            checks={
                name: (
                    sum(s.checks[name][0] for s in parts if name in s.checks),
                    sum(s.checks[name][1] for s in parts if name in s.checks),
                )
                for name in names
            },
            rungs=rungs,
            fine={name: f for name, f in self._fine.items() if f is not None and f.active},
        )
        return ChunkResult(
            self.values,
            {name: self.checks[name] for name in names},
            self.rungs,
            self.refusals,
            self.elapsed_s,
            summary,
        )


def merge(parts: Sequence[ChunkResult], outputs: Sequence[str]) -> ChunkResult:
    """Concatenate chunk results in order (the order of ``parts``), through :class:`Merger`."""
    merger = Merger(sum(len(p.rungs) for p in parts), outputs)
    start = 0
    for part in parts:
        merger.add(start, part)
        start += len(part.rungs)
    return merger.result()


# --------------------------------------------------------------------------- partial summaries


@dataclass(frozen=True)
class Moments:
    r"""Count, mean, sum of squared deviations from the mean and extremes of finite values.

    ``first_low`` and ``first_high`` are the places of the first lowest and the first
    highest finite value (in a chunk, or in the study once shifted), as
    :func:`numpy.nanargmin` and :func:`numpy.nanargmax` find them among the finite values
    (an infinite output is left out like a refused point, so no ±inf reaches a summary).
    Two sets of points combine exactly in count and
    extremes, and in mean and ``m2`` by the pairwise update of Chan, Golub and LeVeque
    (1979), to the rounding of a few operations (points of one value have that value
    as their mean and no spread, exactly):

    .. math::
        n = n_a + n_b, \quad \delta = \bar y_b - \bar y_a, \quad
        \bar y = \bar y_a + \delta \frac{n_b}{n}, \quad
        M_2 = M_{2,a} + M_{2,b} + \delta^2 \frac{n_a n_b}{n}

    By hand: 3, 1 (and a NaN), then 4, 1, 5: n = 2 + 3, means 2 and 10/3, δ = 4/3,
    mean 2 + 4/3 · 3/5 = 2.8, M_2 = 2 + 8.667 + 16/9 · 6/5 = 12.8; the first lowest is
    the 1 at place 1, the highest the 5 at place 5.

    >>> y = np.array([3.0, 1.0, np.nan, 4.0, 1.0, 5.0])
    >>> a, b = Moments.of(y[:3]), Moments.of(y[3:])
    >>> assert a is not None and b is not None
    >>> both = a.then(b.shifted(3))
    >>> both.count, round(both.mean, 12), round(both.m2, 12), both.first_low, both.first_high
    (5, 2.8, 12.8, 1, 5)
    """

    count: int
    mean: float
    m2: float
    low: float
    high: float
    first_low: int
    first_high: int
    #: What ``mean`` leaves out by its rounding (the mean of the points less ``mean``): δ
    #: between two chunks' means is taken with it, so an output that barely moves (spread
    #: 1e-11 of its mean) keeps its spread to numpy's precision, not to the means' rounding.
    mean_residual: float = 0.0

    @staticmethod
    def of(y: np.ndarray) -> Moments | None:
        """The moments of ``y``'s finite values; None when it has none."""
        if y.size == 0:
            return None
        if is_one_number(y):  # one number (a zero-stride view): what the passes would find
            v = float(y[0])
            if not math.isfinite(v):
                return None
            return Moments(count=y.size, mean=v, m2=0.0, low=v, high=v, first_low=0, first_high=0)
        # extremes both finite: no NaN (where the extremes' search stops) and no ±inf, so
        # every value is finite and no mask is made (the usual chunk)
        lo, hi = int(y.argmin()), int(y.argmax())
        every = math.isfinite(y[lo]) and math.isfinite(y[hi])
        finite = y
        if not every:
            ok = np.isfinite(y)
            finite = y[ok]
            if finite.size == 0:
                return None
            lo, hi = int(finite.argmin()), int(finite.argmax())
        places = [lo, hi] if every else np.flatnonzero(ok)[[lo, hi]].tolist()
        if finite[lo] == finite[hi]:  # one value: its mean, no spread (not their rounding)
            mean, m2, residual = float(finite[lo]), 0.0, 0.0
        else:
            # numpy's mean, the sum over the count, without its Python wrapper
            mean = float(np.add.reduce(finite)) / finite.size
            work = _work(finite.size) if finite.size <= 2 * BLOCK else None
            deviation = np.subtract(finite, mean, out=work)
            residual = float(np.add.reduce(deviation)) / finite.size
            np.multiply(deviation, deviation, out=deviation)  # in place: one array, not two
            m2 = float(np.add.reduce(deviation))
        return Moments(
            count=int(finite.size),
            mean=mean,
            m2=m2,
            low=float(finite[lo]),
            high=float(finite[hi]),
            first_low=int(places[0]),
            first_high=int(places[1]),
            mean_residual=residual if math.isfinite(residual) else 0.0,
        )

    def shifted(self, offset: int) -> Moments:
        """The same moments, their places ``offset`` points further on."""
        return replace(self, first_low=self.first_low + offset, first_high=self.first_high + offset)

    def then(self, later: Moments) -> Moments:
        """These points and ``later``'s, which all come after them (ties keep the first)."""
        n = self.count + later.count
        delta = (later.mean - self.mean) + (later.mean_residual - self.mean_residual)
        step = delta * (later.count / n)
        mean = self.mean + step
        # what the rounded sum left out (Fast2Sum where |step| ≤ |mean|, else none kept)
        residual = (
            ((self.mean - mean) + step) + self.mean_residual if abs(step) <= abs(self.mean) else 0.0
        )
        lower, higher = later.low < self.low, later.high > self.high
        return Moments(
            count=n,
            mean=mean,
            mean_residual=residual if math.isfinite(residual) else 0.0,
            m2=self.m2 + later.m2 + delta * delta * (self.count * later.count / n),
            low=later.low if lower else self.low,
            high=later.high if higher else self.high,
            first_low=later.first_low if lower else self.first_low,
            first_high=later.first_high if higher else self.first_high,
        )

    @property
    def std(self) -> float:
        """The sample standard deviation (ddof = 1; 0 for one point)."""
        return math.sqrt(self.m2 / (self.count - 1)) if self.count > 1 else 0.0


@dataclass
class ChunkSummary:
    """What the study's summary needs of a chunk (or of the whole study, combined).

    Per output its :class:`Moments` (None: no finite value); per check the points that
    passed and failed; the points per rung (None: refused), first seen first.
    ``fine`` (the whole study only): each output's values counted in fine bins by
    :class:`Merger` as the chunks arrived.
    """

    moments: dict[str, Moments | None]
    checks: dict[str, tuple[int, int]]
    rungs: dict[str | None, int]
    fine: dict[str, FineCounts] = field(default_factory=dict)


def summarize_chunk(part: ChunkResult) -> ChunkResult:
    """``part`` with its partial summary: run where the chunk ran (on its worker), so the
    study's summary combines a few numbers per chunk instead of reading every value again.

    >>> part = ChunkResult({"y": np.array([2.0, np.nan, 4.0])},
    ...                    {"R8": np.array([1, 0, -1], np.int8)}, ["a", None, "a"], {}, 0.0)
    >>> s = summarize_chunk(part).summary
    >>> assert s is not None
    >>> s.moments["y"].mean, s.checks, s.rungs
    (3.0, {'R8': (1, 1)}, {'a': 2, None: 1})
    """
    rungs = part.rungs
    if rungs and rungs.count(rungs[0]) == len(rungs):  # the usual chunk: one rung
        counted: dict[str | None, int] = {rungs[0]: len(rungs)}
    else:
        counted = dict(Counter(rungs))  # counted in C, first-seen order kept
    part.summary = ChunkSummary(
        moments={name: Moments.of(y) for name, y in part.values.items()},
        checks={
            name: (
                int(np.count_nonzero(codes == CHECK_OK)),
                int(np.count_nonzero(codes == CHECK_FAILED)),
            )
            for name, codes in part.checks.items()
        },
        rungs=counted,
    )
    return part


def _combined(moments: Sequence[Moments | None]) -> Moments | None:
    """The moments of consecutive chunks (already shifted), combined pairwise in order."""
    known = [m for m in moments if m is not None]
    while len(known) > 1:
        pairs = [a.then(b) for a, b in zip(known[::2], known[1::2], strict=False)]
        known = pairs + known[len(pairs) * 2 :]
    return known[0] if known else None


#: A study this long or longer counts each output's values in fine bins chunk by chunk
#: (:class:`FineCounts`); a shorter one is summarised from its merged columns alone.
GATHER_POINTS = 50_000
#: The fewest finite values of an output the first chunk must have to place its bins.
PILOT_MIN = 4_096
#: At most this many of the first chunk's values (spread evenly) place the bins.
PILOT_POINTS = 16_384
#: Share of the pilot left out at either end of the range the fine bins span (so a
#: heavy tail does not stretch them): its values fall in the bins below and above.
PILOT_TAIL = 0.0005
#: Uniform bins over the pilot's range.
FINE_BINS = 16_384
#: Beyond this share of an output's values in the bins the summary must look into
#: (a point mass, a pilot that was no fair sample), the merged column is read instead.
GATHER_SHARE = 0.25
#: The least length of the work array a chunk's moments are computed in (:func:`_work`).
BLOCK = 65_536


class FineCounts:
    """An output's values counted chunk by chunk in fine bins, for its quantiles and
    histogram found exactly with one cheap pass over the merged column.

    The first chunk that arrives (the pilot) places :data:`FINE_BINS` uniform bins over
    its range (less :data:`PILOT_TAIL` of it at either end), with one bin below and one
    above for the values beyond. A value's bin never decreases as the value grows, so
    every value of a lower bin is smaller than every value of a higher one: with c values
    in the bins below, the order statistic of rank r is the value of rank r - c among its
    bin's values, and the values below a histogram edge are those of the bins below plus
    those of the edge's bin that are smaller. The summary therefore looks only into the
    few bins that hold a rank or an edge (:meth:`resolve`), in one pass that keeps their
    values. That is exact whatever the pilot; where those bins hold more than
    :data:`GATHER_SHARE` of the values (a point mass, a pilot that was no fair sample of
    the study) :meth:`resolve` gives None and the caller reads the whole column.

    >>> y = np.random.default_rng(5).standard_normal(200_000)
    >>> fine = FineCounts(y[:65_536])
    >>> for a in range(0, y.size, 65_536):
    ...     fine.add(y[a : a + 65_536])
    >>> edges = np.histogram_bin_edges(y, 30)
    >>> found = fine.resolve(y, np.array([0, 100_000, 199_999]), edges[:-1])
    >>> assert found is not None
    >>> bool((found[0] == np.sort(y)[[0, 100_000, 199_999]]).all())
    True
    >>> bool((np.diff(np.r_[found[1], y.size]) == np.histogram(y, edges)[0]).all())
    True
    """

    def __init__(self, pilot: np.ndarray) -> None:
        sample = np.sort(pilot[:: max(1, -(-pilot.size // PILOT_POINTS))])
        cut = int(PILOT_TAIL * sample.size)
        low, high = float(sample[cut]), float(sample[sample.size - 1 - cut])
        if not high > low:  # most of the pilot at one value: span all of it
            low, high = float(sample[0]), float(sample[-1])
        self.low = low
        scale = FINE_BINS / (high - low) if high > low else 0.0
        # a constant pilot, or extremes too far apart for their difference: not counted
        self.active = 0.0 < scale < math.inf
        self.scale = scale if self.active else 0.0
        self.counts = np.zeros(FINE_BINS + 2, dtype=np.int64)

    def bins(self, y: np.ndarray) -> np.ndarray:
        """Each finite value's bin, 0 (below the range) … FINE_BINS + 1 (above it), by
        the rule the counts were made with (:func:`engine.studies.kernels.uniform_bin`).

        >>> FineCounts(np.linspace(0.0, 1.0, 5_000)).bins(np.array([-1.0, 0.5, 2.0])).tolist()
        [0, 8193, 16385]
        """
        labels = np.empty(y.size, dtype=np.intp)
        spare = np.zeros(self.counts.size, dtype=np.int64)
        kernels.bins_counted(y, self.low, self.scale, FINE_BINS, 1, labels, spare)
        return labels

    def add(self, y: np.ndarray) -> None:
        """Count a chunk's finite values ``y`` (the others are left out), in one
        compiled pass (:func:`engine.studies.kernels.count_bins`)."""
        if self.active:
            kernels.count_bins(y, self.low, self.scale, FINE_BINS, 1, self.counts)

    def resolve(
        self,
        y: np.ndarray | Sequence[np.ndarray],
        ranks: np.ndarray,
        edges: np.ndarray,
        count: int | None = None,
    ) -> tuple[np.ndarray, np.ndarray] | None:
        """The values of rank ``ranks`` (0-based) and the number of values below each of
        ``edges``, of the finite values of ``y`` (an array, or its pieces; NaN and ±inf
        are left out), ``count`` of them (counted here where not given), whose chunks
        were all added; None where the bins to look into hold too many of them.

        The values of the bins looked into are gathered in the points' order in one
        compiled pass (:func:`engine.studies.kernels.gather_bins`)."""
        if not self.active:
            return None
        pieces = [y] if isinstance(y, np.ndarray) else y
        if count is None:
            count = sum(int(np.count_nonzero(np.isfinite(piece))) for piece in pieces)
        total = np.cumsum(self.counts)  # values in this bin and the ones below
        if total[-1] != count:  # pragma: no cover - defensive: every chunk is added
            return None
        under = total - self.counts  # values in the bins below
        rank_bins = np.searchsorted(total, ranks, side="right")
        edge_bins = self.bins(np.asarray(edges, dtype=float))
        wanted = np.zeros(self.counts.size, dtype=bool)
        wanted[rank_bins] = wanted[edge_bins] = True
        held = int(self.counts[wanted].sum())
        if held > GATHER_SHARE * count:
            return None
        kept, labels, k = np.empty(held), np.empty(held, dtype=np.intp), 0
        for piece in pieces:
            k = kernels.gather_bins(
                piece, self.low, self.scale, FINE_BINS, 1, wanted, kept, labels, k
            )
            if k < 0:  # defensive: the values must be the ones counted
                return None
        if k != held:  # pragma: no cover - defensive, as above
            return None
        found = np.empty(ranks.size)
        for b in np.unique(rank_bins).tolist():
            here = rank_bins == b
            k = ranks[here] - under[b]
            found[here] = np.partition(kept[labels == b], k)[k]
        below = np.array(
            [
                under[b] + np.count_nonzero(kept[labels == b] < e)
                for b, e in zip(edge_bins.tolist(), np.asarray(edges).tolist(), strict=True)
            ]
        )
        return found, below


_WORK = threading.local()


def _work(size: int) -> np.ndarray:
    """This thread's work array, ``size`` long (made at least :data:`BLOCK` long, once,
    and reused): a chunk's summary then makes no fresh temporary (each would cost the
    first touch of its pages again).

    >>> a = _work(10)
    >>> a.size, _work(10).base is a.base
    (10, True)
    """
    got = getattr(_WORK, "array", None)
    if got is None or got.size < size:
        got = _WORK.array = np.empty(max(size, BLOCK))
    return got[:size]


# --------------------------------------------------------------------------- summaries


def _stats(
    column: np.ndarray | Sequence[np.ndarray],
    bins: int,
    moments: Moments | None,
    fine: FineCounts | None = None,
) -> dict[str, Any]:
    """One output's summary from its ``column`` (an array, or its pieces in order,
    :meth:`Columns.pieces`) and its combined ``moments``.

    Count, mean, standard deviation and extremes come from the moments. The histogram
    spans the extremes (its bins are known only once every chunk is in) and the
    quantiles are numpy's; both are found exactly, through the ``fine`` counts where
    they serve (:meth:`FineCounts.resolve`, piece by piece), else from the whole column.
    """
    if moments is None:
        return {"count": 0}
    lo, hi = moments.low, moments.high
    given = [column] if isinstance(column, np.ndarray) else list(column)
    count = moments.count  # the finite values

    def finite() -> list[np.ndarray]:
        """The finite values' pieces: made only where read (the fine counts' pass leaves
        NaN and ±inf out itself)."""
        if count == sum(y.size for y in given):
            return given
        return [y[np.isfinite(y)] for y in given]

    few = None
    try:
        # numpy's edges for the range numpy would find itself (min, max); a constant
        # output (common in a study: one not moved by the varied inputs) has its
        # histogram from one value times the count and every quantile at that value
        counts, edges = np.histogram(np.array([lo]), bins=bins, range=(lo, hi))
        counts *= count
    except ValueError:  # min and max too close for the bins: one bin around them
        counts, edges = np.array([count]), np.array([lo, hi])
        few = _floats_between(lo, hi)
    if lo == hi:
        quantiles = np.full(len(QUANTILES), lo)
    elif few is not None:  # an output moved by rounding alone: a few floats, counted
        ranks = _quantile_ranks(count)
        pieces = finite()
        at_most = np.array([sum(int(np.count_nonzero(y <= v)) for y in pieces) for v in few])
        quantiles = _interpolate(count, ranks, few[np.searchsorted(at_most, ranks, "right")])
    else:
        ranks = _quantile_ranks(count)
        got = None if fine is None else fine.resolve(given, ranks, edges[:-1], count)
        if got is None:
            values = np.concatenate(finite())
            counts = np.histogram(values, bins=edges)[0]
            found = _order_statistics(values, ranks)
        else:
            found, below = got
            counts = np.diff(np.r_[below, count])
        quantiles = _interpolate(count, ranks, found)
    return {
        "count": moments.count,
        "mean": moments.mean,
        "std": moments.std,
        "min": lo,
        "max": hi,
        "quantiles": {f"{q:g}": float(v) for q, v in zip(QUANTILES, quantiles, strict=True)},
        "histogram": {"edges": edges.tolist(), "counts": counts.tolist()},
    }


#: The most floats an output's range may hold for its quantiles to be found by counting
#: the values at or below each (:func:`_floats_between`).
FEW_FLOATS = 16


def _floats_between(lo: float, hi: float) -> np.ndarray | None:
    """Every float from ``lo`` to ``hi`` (finite, ``lo`` ≤ ``hi``), in order, where there
    are at most :data:`FEW_FLOATS` of them (an output the inputs move only by rounding,
    too narrow for a histogram); else None.

    >>> _floats_between(1.0, float(np.nextafter(np.nextafter(1.0, 2.0), 2.0))).size
    3
    >>> _floats_between(1.0, 1.5) is None
    True
    """
    out = [lo]
    while out[-1] < hi:
        if len(out) == FEW_FLOATS:
            return None
        out.append(float(np.nextafter(out[-1], math.inf)))
    return np.array(out)


#: A column this long or longer has its order statistics found in brackets (see
#: :func:`_order_statistics`); a shorter one is partitioned whole.
BRACKET_POINTS = 50_000
#: Every how many points the bracketing subsample takes one.
BRACKET_STEP = 64
#: Ranks in the lowest or highest this share of a column are sought in its tail alone.
TAIL_SHARE = 0.1


def _order_statistics(y: np.ndarray, ranks: np.ndarray) -> np.ndarray:
    """``np.partition(y, ranks)[ranks]``: the values of rank ``ranks`` (0-based) in ``y``.

    A study's columns are long and only a few ranks are asked for, so each is found in
    a bracket [a, b] a sorted subsample (every :data:`BRACKET_STEP`-th point) places
    around it, eight standard deviations of the subsample's rank error wide: with
    ``c`` points below a, rank r is rank r - c of the few points inside the bracket, found
    by partitioning those alone; the ranks of a tail (the lowest or highest
    :data:`TAIL_SHARE`) are sought so in the tail, cut from the column in one pass. That
    holds whatever the subsample: a bracket that misses
    its rank (a sorted or gridded column can fool the subsample) falls back to the
    partition of the whole column, so the values are always exact.

    >>> y = np.random.default_rng(3).random(200_000)
    >>> ranks = np.array([0, 199, 100_000, 199_999])
    >>> bool((_order_statistics(y, ranks) == np.sort(y)[ranks]).all())
    True
    """
    n = y.size
    if n < BRACKET_POINTS:
        return np.partition(y, ranks)[ranks]
    sample = np.sort(y[::BRACKET_STEP])
    m = sample.size

    def bracket(r: int) -> tuple[float, float]:
        share = r / (n - 1)
        j = share * (m - 1)
        half = 8.0 * math.sqrt(share * (1.0 - share) * m) + 2.0
        return sample[max(int(j - half), 0)], sample[min(int(j + half) + 1, m - 1)]

    out = np.empty(ranks.size)
    todo = np.ones(ranks.size, dtype=bool)
    # the ranks in a tail: one pass cuts the tail (the smallest or largest points, ties
    # at the cut included), and their brackets are then sought in it alone
    low, high = ranks < TAIL_SHARE * n, ranks > (1.0 - TAIL_SHARE) * n
    if low.any():
        tail = y[y <= bracket(int(ranks[low].max()))[1]]
        if tail.size <= n // 2 and int(ranks[low].max()) < tail.size:
            out[low], todo[low] = _order_statistics(tail, ranks[low]), False
    if high.any():
        top = y[y >= bracket(int(ranks[high].min()))[0]]
        offset = n - top.size
        if top.size <= n // 2 and int(ranks[high].min()) >= offset:
            out[high], todo[high] = _order_statistics(top, ranks[high] - offset), False
    rest = np.flatnonzero(todo)
    i = 0
    while i < rest.size:  # one bracket for this rank and the next ones it holds
        a, b = bracket(int(ranks[rest[i]]))
        below = int(np.count_nonzero(y < a))
        inside = y[(y >= a) & (y <= b)]
        ks = ranks[rest[i:]] - below
        held = int(np.count_nonzero((ks >= 0) & (ks < inside.size)))
        if held == 0 or ks[0] < 0:
            return np.partition(y, ranks)[ranks]
        ks = ks[:held]
        out[rest[i : i + held]] = a if a == b else np.partition(inside, ks)[ks]
        i += held
    return out


def _quantile_ranks(n: int) -> np.ndarray:
    """The ranks (0-based, ascending, once each) of the order statistics numpy's linear
    quantiles of :data:`QUANTILES` of ``n`` values are made of: floor and ceiling of
    the virtual index h = (n - 1) q.

    By hand, n = 11: h = 10 q = 0.01, 0.1, 0.5, 2.5, 5, 7.5, 9.5, 9.9, 9.99; floors
    0 0 0 2 5 7 9 9 9 and ceilings (floor + 1, at most 10) 1 1 1 3 6 8 10 10 10.

    >>> _quantile_ranks(11).tolist()
    [0, 1, 2, 3, 5, 6, 7, 8, 9, 10]
    """
    below = np.floor((n - 1) * np.asarray(QUANTILES)).astype(np.intp)
    return np.unique(np.concatenate([below, np.minimum(below + 1, n - 1)]))


def _interpolate(n: int, ranks: np.ndarray, found: np.ndarray) -> np.ndarray:
    """numpy's linear quantiles of :data:`QUANTILES` of ``n`` values from the order
    statistics ``found`` of ``ranks`` (:func:`_quantile_ranks`): virtual index
    h = (n - 1) q and numpy's two-sided linear interpolation between its floor and
    ceiling, so the values are numpy's to the last bit."""
    virtual = (n - 1) * np.asarray(QUANTILES)
    below = np.floor(virtual)
    gamma = virtual - below
    prev = below.astype(np.intp)
    nxt = np.minimum(prev + 1, n - 1)
    a, b = found[np.searchsorted(ranks, prev)], found[np.searchsorted(ranks, nxt)]
    step = b - a
    return np.where(gamma >= 0.5, b - step * (1.0 - gamma), a + step * gamma)


def _quantiles(y: np.ndarray) -> np.ndarray:
    """``np.quantile(y, QUANTILES)`` (its default linear method), to the last bit.

    The same rule as numpy's (:func:`_interpolate`); only the order statistics are
    found faster (:func:`_order_statistics`).

    >>> y = np.random.default_rng(4).standard_normal(100_001)
    >>> bool((_quantiles(y) == np.quantile(y, QUANTILES)).all())
    True
    """
    ranks = _quantile_ranks(y.size)
    return _interpolate(y.size, ranks, _order_statistics(y, ranks))


def _rank(x: np.ndarray) -> np.ndarray:
    return np.asarray(stats.rankdata(x), dtype=float)


def _ranks_along(y: np.ndarray, order: np.ndarray) -> np.ndarray | None:
    """Average ranks of ``y`` (as :func:`scipy.stats.rankdata`) from an ``order`` that sorts it.

    None when ``order`` sorts ``y`` neither up nor down: O(n) instead of a sort, for the
    many outputs of a study that move monotonically with one input or with each other.
    A few hundred points spread along ``order`` are looked at first: an order that does
    not sort them does not sort ``y`` (most of the orders tried), and is refused at once.
    """
    probe = np.diff(y[order[:: max(1, order.size // 256)]])
    if not ((probe >= 0).all() or (probe <= 0).all()):
        return None
    ys = y[order]
    steps = np.diff(ys)
    if (steps >= 0).all():
        up = True
    elif (steps <= 0).all():
        up, ys = False, ys[::-1]
    else:
        return None
    if np.count_nonzero(steps) == steps.size:  # no ties (a continuous law): ranks 1…n
        sorted_ranks = np.arange(1.0, ys.size + 1.0)
    else:
        new = np.empty(ys.size, dtype=bool)
        new[0] = True
        np.not_equal(ys[1:], ys[:-1], out=new[1:])
        dense = np.cumsum(new)
        count = np.r_[np.flatnonzero(new), ys.size]
        sorted_ranks = 0.5 * (count[dense] + count[dense - 1] + 1)
    ranks = np.empty(ys.size)
    ranks[order if up else order[::-1]] = sorted_ranks
    return ranks


#: From this many points on, ranks are binned (:func:`_binned_ranks`) where that is
#: accurate enough, not found by sorting.
RANK_BINNED_POINTS = 50_000
#: Uniform bins a column's range is cut into for its binned ranks.
RANK_BINS = 65_536
#: The most a binned rank correlation may differ from the exact one on the same points
#: (half of it per column: :func:`_binned_ranks`).
RANK_TOLERANCE = 1e-3


def _binned_ranks(
    x: np.ndarray,
    bins: int = RANK_BINS,
    tolerance: float = RANK_TOLERANCE,
    extremes: tuple[float, float] | None = None,
) -> np.ndarray | None:
    r"""Ranks of the finite values ``x`` from ``bins`` uniform bins over their range, each
    value taking the average rank of its bin's values; None where the bins hold too many
    values for ``tolerance`` (or the range has no width).

    A bin's values, c of them above u in lower bins, take exact (average) ranks u + 1 …
    u + c and binned rank u + (c + 1)/2: the ranks keep their mean, and the error e has
    a sum of squares at most (c³ - c)/12 per bin, so against the exact ranks' spread
    (n³ - n)/12

    .. math::
        \delta = \frac{\lVert e \rVert}{\lVert r - \bar r \rVert}
        \le \sqrt{\frac{\sum_b (c_b^3 - c_b)}{n^3 - n}}

    and a correlation of two columns, the cosine of the angle between their centred
    ranks, moves by at most arcsin δ_x + arcsin δ_y. A column is binned only where
    arcsin δ ≤ tolerance / 2, so each coefficient is within ``tolerance`` of the exact
    one (about 1e-5 for the smooth laws of a study, each bin holding a few values). O(n),
    against the sort's O(n log n). A column whose range holds at most :data:`FEW_FLOATS`
    floats (:func:`_floats_between`) takes each float as a bin: its ranks are exact.
    ``extremes``: the values' least and greatest, where the caller has them (not sought
    again).

    By hand, x = 0, 3, 1, 4 in 4 bins over 0…4 (width 1, the top one closed): bins 0, 3,
    1, 3; the two values of bin 3 share ranks 3 and 4: 1, 3.5, 2, 3.5, with
    δ = √(6/60) ≈ 0.316 (arcsin 0.322: refused at a tolerance of 0.5, kept at 1).

    >>> x = np.array([0.0, 3.0, 1.0, 4.0])
    >>> _binned_ranks(x, bins=4, tolerance=0.5) is None
    True
    >>> _binned_ranks(x, bins=4, tolerance=1.0).tolist()
    [1.0, 3.5, 2.0, 3.5]

    Two correlated normal columns of 100,000 points: the binned coefficient against the
    exact one (:func:`scipy.stats.rankdata`'s ranks):

    >>> rng = np.random.default_rng(2)
    >>> x = rng.standard_normal(100_000); y = x + rng.standard_normal(100_000)
    >>> def rho(a, b): return float(np.add.reduce(_standardised(a) * _standardised(b)))
    >>> bx, by = _binned_ranks(x), _binned_ranks(y)
    >>> assert bx is not None and by is not None
    >>> bool(abs(rho(bx, by) - rho(_rank(x), _rank(y))) < 1e-5)
    True
    """
    n = x.size
    lo, hi = _extremes(x) if extremes is None else extremes
    few = _floats_between(lo, hi) if lo < hi else None
    if few is not None:  # a column moved by rounding alone: each float its own bin, exact
        labels = np.searchsorted(few, x)
        counts = np.bincount(labels, minlength=few.size)
        return (np.cumsum(counts) - 0.5 * (counts - 1))[labels]
    scale = bins / (hi - lo) if hi > lo else 0.0
    if not 0.0 < scale < math.inf:
        return None
    counts = np.zeros(bins, dtype=np.int64)
    kernels.count_bins(x, lo, scale, bins - 1, 0, counts)  # one compiled pass
    mid = np.empty(bins)  # the average rank of each bin's values, and Σ(c³ - c) at once
    delta = math.sqrt(kernels.rank_table(counts, mid) / (float(n) ** 3 - n))
    if not math.asin(min(delta, 1.0)) <= tolerance / 2:
        return None
    ranks = np.empty(n)
    kernels.lookup_bins(x, lo, scale, bins - 1, 0, mid, ranks)  # each value's bin's, again
    return ranks


def _extremes(x: np.ndarray) -> tuple[float, float]:
    """The least and the greatest of the values ``x`` (at least one)."""
    return float(x.min()), float(x.max())


def rank_correlations(
    columns: Mapping[str, np.ndarray], values: Mapping[str, np.ndarray]
) -> dict[str, dict[str, float | None]]:
    """Spearman's rank correlation of each output with each varied input (finite points).

    Ranks are computed once per array and finite mask. From
    :data:`RANK_BINNED_POINTS` points on, a column's ranks are binned (:func:`_binned_ranks`,
    each coefficient then within :data:`RANK_TOLERANCE` of the exact one) where its bins
    allow; else they are found by a sort, and an output sorted by an order already known
    (an input's, an earlier output's) is ranked without a new sort. Ties take their
    average rank whatever order a sort leaves them in, so numpy's fastest sort serves.
    Over :data:`RANK_POINTS` points, the first :data:`RANK_POINTS` (a random sample of
    the study's draws) are ranked: the coefficient's standard error there is about 0.002,
    and ranking a million points costs more than the model did. Each input's extremes
    (whether it moves, where its rank bins lie) are found once per finite mask, each
    output's once, not again for each pair.
    """
    if columns and len(next(iter(columns.values()))) > RANK_POINTS:
        columns = {k: v[:RANK_POINTS] for k, v in columns.items()}
    out: dict[str, dict[str, float | None]] = {}
    # per finite mask: the orders known so far, each input's standardised ranks and each
    # input's extremes on those points
    known: dict[
        bytes,
        tuple[list[np.ndarray], dict[str, np.ndarray], dict[str, tuple[float, float]]],
    ] = {}
    for name in values:
        y = values[name][:RANK_POINTS]  # one output at a time (:func:`_heads` makes it then)
        if is_one_number(y):  # one number (a zero-stride view): no rank moves
            out[name] = dict.fromkeys(columns)
            continue
        ok = np.isfinite(y)
        every = bool(ok.all())
        key = b"" if every else np.packbits(ok).tobytes()
        orders, input_ranks, input_extremes = known.setdefault(key, ([], {}, {}))
        row: dict[str, float | None] = {}
        ys = y if every else y[ok]
        # fewer than 3 points, or one value (max - min is 0 exactly when they are equal)
        y_extremes = _extremes(ys) if ys.size >= 3 else (0.0, 0.0)
        flat = y_extremes[0] == y_extremes[1]
        binned = ys.size >= RANK_BINNED_POINTS
        zy: np.ndarray | None = None
        for var, x in columns.items():
            if flat:
                row[var] = None
                continue
            xs = x if every else x[ok]
            x_extremes = input_extremes.get(var)
            if x_extremes is None:
                x_extremes = input_extremes[var] = _extremes(xs)
            if x_extremes[0] == x_extremes[1]:
                row[var] = None
                continue
            zx = input_ranks.get(var)
            if zx is None:
                ranked = _binned_ranks(xs, extremes=x_extremes) if binned else None
                if ranked is None:
                    order = np.argsort(xs)
                    orders.append(order)
                    ranked = _ranks_along(xs, order)
                assert ranked is not None
                zx = input_ranks[var] = _standardised(ranked)
            if zy is None:
                ry = _binned_ranks(ys, extremes=y_extremes) if binned else None
                for order in orders if ry is None else ():
                    ry = _ranks_along(ys, order)
                    if ry is not None:
                        break
                if ry is None:
                    order = np.argsort(ys)
                    orders.append(order)
                    ry = _ranks_along(ys, order)
                assert ry is not None
                zy = _standardised(ry)
            row[var] = max(-1.0, min(1.0, float(np.add.reduce(zx * zy))))
        out[name] = row
    return out


def _standardised(r: np.ndarray) -> np.ndarray:
    """``r`` less its mean, over the root of its sum of squares: Pearson's correlation of
    two such arrays is the sum of their products (the ranks' here, Spearman's ρ), one
    pass per pair instead of :func:`numpy.corrcoef`'s covariance matrix.

    By hand, ranks 1 2 3 4 against 1 3 2 4: ρ = 1 - 6 Σd² / (n (n² - 1)) = 1 - 12/60 = 0.8.

    >>> a, b = _standardised(np.array([1.0, 2, 3, 4])), _standardised(np.array([1.0, 3, 2, 4]))
    >>> round(float((a * b).sum()), 12)
    0.8
    """
    z = r - r.mean()
    return z / math.sqrt(float(np.add.reduce(z * z)))


def sobol_indices(y: np.ndarray, base: int, names: Sequence[str]) -> dict[str, dict[str, float]]:
    """First-order (Saltelli 2010) and total (Jansen 1999) Sobol' indices.

    ``y`` holds f(A), f(B), f(AB_1) … f(AB_k) in blocks of ``base`` rows.
    Rows where any needed value is not finite are dropped per input.

    Examples
    --------
    An additive model y = x1 + 2 x2 with independent uniform inputs has
    S1 = ST = 1/5 and 4/5:

    >>> import numpy as np
    >>> rng = np.random.default_rng(1)
    >>> a, b = rng.random((4096, 2)), rng.random((4096, 2))
    >>> ab = [np.column_stack([b[:, 0], a[:, 1]]), np.column_stack([a[:, 0], b[:, 1]])]
    >>> f = lambda m: m[:, 0] + 2 * m[:, 1]
    >>> y = np.concatenate([f(a), f(b), f(ab[0]), f(ab[1])])
    >>> s = sobol_indices(y, 4096, ["x1", "x2"])
    >>> round(s["x1"]["first"], 1), round(s["x2"]["total"], 1)
    (0.2, 0.8)
    """
    fa, fb = y[:base], y[base : 2 * base]
    out: dict[str, dict[str, float]] = {}
    for i, name in enumerate(names):
        fab = y[(2 + i) * base : (3 + i) * base]
        ok = np.isfinite(fa) & np.isfinite(fb) & np.isfinite(fab)
        if ok.sum() < 8:
            continue
        var = np.var(np.concatenate([fa[ok], fb[ok]]))
        if not var > 0.0:
            out[name] = {"first": 0.0, "total": 0.0}
            continue
        first = float(np.mean(fb[ok] * (fab[ok] - fa[ok])) / var)
        total = float(0.5 * np.mean((fa[ok] - fab[ok]) ** 2) / var)
        out[name] = {"first": first, "total": total}
    return out


def feasible_mask(
    merged: ChunkResult, feasible_when: str | None, advice: Collection[str] = ()
) -> np.ndarray:
    """Per point: 1 feasible, 0 not, -1 unknown (refused, or no requirement reported).

    Feasible means every requirement the point reports passes; the checks named in
    ``advice`` (a model's rules of thumb, :attr:`ModelSpec.advice`) warn and do not count.
    ``feasible_when``, a true/false output, replaces the checks.

    >>> checks = {"R8": np.array([1, 1, 0], np.int8), "thumb": np.array([0, 1, 1], np.int8)}
    >>> m = ChunkResult({}, checks, ["closed_form"] * 3, {}, 0.0)
    >>> feasible_mask(m, None).tolist(), feasible_mask(m, None, {"thumb"}).tolist()
    ([0, 1, 0], [1, 1, 0])
    """
    n = len(merged.rungs)
    if feasible_when is not None:
        col = merged.values[feasible_when]
        return np.where(np.isfinite(col), (col > 0.5).astype(np.int8), CHECK_UNKNOWN)
    counted = [arr for name, arr in merged.checks.items() if name not in advice]
    if not counted:
        return np.full(n, CHECK_UNKNOWN, dtype=np.int8)
    stack = np.vstack(counted)
    failed = (stack == CHECK_FAILED).any(axis=0)
    known = (stack != CHECK_UNKNOWN).any(axis=0)
    return np.where(failed, CHECK_FAILED, np.where(known, CHECK_OK, CHECK_UNKNOWN)).astype(np.int8)


def _pieces(values: Mapping[str, np.ndarray], name: str) -> list[np.ndarray]:
    """An output's values as pieces: a :class:`Columns`' chunks, else the one array."""
    return values.pieces(name) if isinstance(values, Columns) else [values[name]]


def _none_if_nan(a: np.ndarray) -> list[Any]:
    return [None if not math.isfinite(v) else v for v in a.tolist()]


def summarize(spec: ModelSpec, study: Study, p: Plan, merged: ChunkResult) -> dict[str, Any]:
    """JSON-ready summary of a finished study (SI units)."""
    units = {o.name: o.unit for o in spec.outputs}
    n = p.n_points
    # the chunks' partial summaries, combined by the merge (made here from the merged
    # values, as of one chunk, where the merge did not combine them)
    partial = merged.summary or summarize_chunk(replace(merged)).summary
    assert partial is not None
    outputs = {
        name: _stats(
            _pieces(merged.values, name), study.bins, partial.moments[name], partial.fine.get(name)
        )
        for name in p.outputs
    }
    feasible = feasible_mask(merged, study.feasible_when, spec.advice)
    checks = {}
    for name in merged.checks:
        passed, failed = partial.checks[name]
        checks[name] = {
            "level": spec.check_level(name),
            "passed": passed,
            "failed": failed,
            "unknown": n - passed - failed,
            "pass_fraction": passed / (passed + failed) if passed + failed else None,
        }
    known = feasible != CHECK_UNKNOWN
    summary: dict[str, Any] = {
        "model": spec.name,
        "method": study.method,
        "points": n,
        "refused": int(sum(merged.refusals.values())),
        "refusals": merged.refusals,
        "units": {name: units[name] for name in p.outputs},
        "input_units": {name: spec.param(name).unit for name in p.columns},
        "outputs": outputs,
        "checks": checks,
        "feasible": {
            "criterion": study.feasible_when or "every reported requirement passes",
            "fraction": float((feasible == CHECK_OK).sum() / known.sum()) if known.any() else None,
            "known": int(known.sum()),
        },
        "rungs": _rung_counts(partial.rungs),
        "compute_s": merged.elapsed_s,
        "notes": list(p.notes),
    }
    if merged.checks and any(
        sum(partial.checks[name]) == 0 for name in merged.checks
    ):  # pragma: no cover - defensive; checks arrays are created on first report
        summary["notes"].append("some checks were never evaluated")
    if any(r is not None for r in merged.rungs) and not merged.checks:
        summary["notes"].append(
            "checks are not evaluated on the model's array path; feasibility then needs "
            "`feasible_when` (a true/false output)"
        )
    # the designs behind the extremes of each output
    extremes: dict[str, Any] = {}
    for name in p.outputs:
        moments = partial.moments[name]
        if moments is None:
            continue
        lo, hi = moments.first_low, moments.first_high
        extremes[name] = {
            "min": {
                "value": moments.low,
                "inputs": {k: float(v[lo]) for k, v in p.columns.items()},
            },
            "max": {
                "value": moments.high,
                "inputs": {k: float(v[hi]) for k, v in p.columns.items()},
            },
        }
    summary["extremes"] = extremes
    names = list(p.columns)
    if p.sobol_base is not None:
        summary["sensitivity"] = {
            "method": "sobol (Saltelli 2010 first-order, Jansen 1999 total)",
            "indices": {
                name: sobol_indices(merged.values[name], p.sobol_base, names) for name in p.outputs
            },
        }
    elif study.method != "grid":
        summary["sensitivity"] = {
            "method": "spearman rank correlation"
            + (f" (first {RANK_POINTS:,} points)" if n > RANK_POINTS else "")
            + (
                f"; ranks binned where that keeps each coefficient within {RANK_TOLERANCE:g}"
                " of the exact one"
                if n >= RANK_BINNED_POINTS
                else ""
            ),
            "indices": rank_correlations(p.columns, _Heads(merged.values, p.outputs)),
        }
    if p.grid_shape is not None and p.grid_axes is not None:
        summary["grid"] = {
            "axes": {k: v.tolist() for k, v in p.grid_axes.items()},
            "shape": list(p.grid_shape),
            "maps": {
                name: np.asarray(_none_if_nan(merged.values[name]), dtype=object)
                .reshape(p.grid_shape)
                .tolist()
                for name in p.outputs
            },
            "feasible": feasible.reshape(p.grid_shape).tolist(),
        }
    return summary


class _Heads(Mapping[str, np.ndarray]):
    """The first :data:`RANK_POINTS` values of each output (all the ranks look at), each
    made when asked, copying no more than those from :class:`Columns`: the ranks hold one
    output's at a time, not every output's at once."""

    def __init__(self, values: Mapping[str, np.ndarray], names: Sequence[str]) -> None:
        self._values, self._names = values, names

    def __getitem__(self, name: str) -> np.ndarray:
        if isinstance(self._values, Columns):
            return self._values.head(name, RANK_POINTS)
        return self._values[name][:RANK_POINTS]

    def __iter__(self) -> Iterator[str]:
        return iter(self._names)

    def __len__(self) -> int:
        return len(self._names)


def _rung_counts(rungs: Mapping[str | None, int]) -> dict[str, int]:
    """Points per rung by name, the refused (None) as ``"refused"``, first seen first."""
    counts: dict[str, int] = {}
    for r, c in rungs.items():
        key = r if r is not None else "refused"
        counts[key] = counts.get(key, 0) + c
    return counts


def points_table(p: Plan, merged: ChunkResult) -> tuple[list[str], np.ndarray]:
    """The raw points: header and a float matrix (inputs, then outputs; NaN where refused)."""
    header = [*p.columns, *p.outputs]
    matrix = np.column_stack(
        [*(p.columns[c] for c in p.columns), *(merged.values[o] for o in p.outputs)]
    )
    return header, matrix


def points_blocks(p: Plan, merged: ChunkResult, rows: int) -> Iterator[list[np.ndarray]]:
    """The columns of :func:`points_table`'s matrix, ``rows`` points at a time (the last
    block shorter): a writer holds one block, never the whole table or a merged column.

    >>> p = Plan({"x": np.arange(5.0)}, 5, ("y",))
    >>> m = ChunkResult({"y": 10 * np.arange(5.0)}, {}, [None] * 5, {}, 0.0)
    >>> [[c.tolist() for c in block] for block in points_blocks(p, m, 3)]
    [[[0.0, 1.0, 2.0], [0.0, 10.0, 20.0]], [[3.0, 4.0], [30.0, 40.0]]]
    """
    values = merged.values
    for a in range(0, p.n_points, rows):
        b = min(a + rows, p.n_points)
        outs = [
            values.rows(o, a, b) if isinstance(values, Columns) else values[o][a:b]
            for o in p.outputs
        ]
        yield [*(p.columns[c][a:b] for c in p.columns), *outs]
