r"""The nearest passing design: a box search through a model's array path, then refinement.

A design that fails a check is changed as little as possible until it passes them all.
"As little as possible" is the weighted relative change

.. math::
    \Delta = \sqrt{\sum_i w_i \left(\frac{x_i - x_{i,0}}{x_{i,0}}\right)^2}

over the variables a designer may change, each within its declared box
:math:`x_{i,0}(1 - L) \le x_i \le x_{i,0}(1 + L)` (clipped to the input's own range).
The verdicts come from one function the caller hands in (for the striker,
``impact.rare``'s closed form through its array path): this module holds no physics,
only the search, so the design found is judged by the same lines as a single run.

The procedure, as named steps:

1. :func:`design_box`: the box of every variable.
2. :func:`shell_samples`: random designs at growing distances from the base (shells
   of relative size :math:`r_k L`, :math:`r_k` from 1/64 to 1), so that near designs
   are sampled as densely as far ones; the base itself first.
3. :func:`relative_change`: Δ of every design.
4. :func:`nearest_passing`: the passing design of least Δ, pulled back towards the base
   along the line between them, then one variable at a time, then by random steps of
   shrinking size around it; where none passes, the design that fails the fewest checks
   (the nearest of those) and the checks it fails.

Deterministic: the random designs come from a generator seeded with a fixed number.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]
#: Verdicts of many designs: name → int8 or bool array (1 passes, 0 fails, -1 refused).
Evaluate = Callable[[Mapping[str, Array]], Mapping[str, Any]]

#: Seed of the random designs (the answer does not depend on the run).
SEED = 20261126
#: Relative sizes of the sample shells, as fractions of the box's half width L.
SHELLS = tuple(2.0**-k for k in range(6, -1, -1))
#: Points on the line from the base to a passing design (the pull towards the base).
LINE_POINTS = 65
#: Points per variable when one variable at a time is pulled towards its base value.
AXIS_POINTS = 33
#: Rounds of one-variable pulls, and of random steps around the best design.
AXIS_ROUNDS = 3
LOCAL_ROUNDS = 6
LOCAL_SAMPLES = 400


def design_box(
    base: Mapping[str, float],
    names: Sequence[str],
    change_limit: float,
    limits: Mapping[str, tuple[float, float]],
) -> tuple[Array, Array, Array]:
    r"""The base values and the box each variable may move in.

    .. math::
        \max(x_{min}, x_0(1 - L)) \le x \le \min(x_{max}, x_0(1 + L))

    Parameters
    ----------
    base : mapping
        The design's inputs, SI
    names : sequence of str
        The variables a designer may change, [-]
    change_limit : float
        L, the largest relative change of any one variable, [-]
    limits : mapping
        Each variable's declared (minimum, maximum), SI

    Returns
    -------
    x0, lower, upper : ndarray
        Base values and bounds, in the order of ``names``, SI

    Examples
    --------
    >>> x0, lo, hi = design_box({"a": 2.0, "b": 0.3}, ["a", "b"], 0.5, {"a": (0.0, 2.5),
    ...     "b": (0.0, 1.0)})
    >>> lo.round(12).tolist(), hi.round(12).tolist()  # a capped at its maximum 2.5
    ([1.0, 0.15], [2.5, 0.45])
    """
    x0 = np.array([float(base[n]) for n in names])
    lo = np.maximum(x0 * (1.0 - change_limit), [limits[n][0] for n in names])
    hi = np.minimum(x0 * (1.0 + change_limit), [limits[n][1] for n in names])
    return x0, lo, hi


def relative_change(designs: Array, x0: Array, weights: Array) -> Array:
    r"""Weighted relative change of each design (one per row) from the base.

    .. math::
        \Delta = \sqrt{\sum_i w_i \left(\frac{x_i - x_{i,0}}{x_{i,0}}\right)^2}

    Parameters
    ----------
    designs : ndarray
        One design per row, SI
    x0 : ndarray
        The base, SI
    weights : ndarray
        w_i, [-]

    Returns
    -------
    delta : ndarray
        Δ per design, [-]; a variable whose base is 0 adds nothing (its box is {0})

    Examples
    --------
    >>> relative_change(np.array([[3.0, 4.0], [1.2, 0.0]]), np.array([1.0, 1.0]),
    ...     np.array([1.0, 1.0])).round(4).tolist()
    [3.6056, 1.0198]
    """
    scale = np.where(x0 != 0.0, np.abs(x0), 1.0)
    rel = (np.asarray(designs) - x0) / scale
    return np.asarray(np.sqrt((weights * rel**2).sum(axis=-1)))


def shell_samples(x0: Array, lower: Array, upper: Array, count: int) -> Array:
    r"""Random designs in shells of growing size around the base, the base first.

    .. math::
        x = \mathrm{clip}\left(x_0 + r_k \, u \, (x_{hi} - x_{lo})/2,\; x_{lo}, x_{hi}\right),
        \quad u \sim U(-1, 1)^n, \quad r_k \in \{2^{-6}, \dots, 1\}

    Parameters
    ----------
    x0, lower, upper : ndarray
        Base and box, SI
    count : int
        Designs to draw (the base is one more), [-]

    Returns
    -------
    designs : ndarray
        ``count + 1`` rows, the base first, SI

    Examples
    --------
    >>> d = shell_samples(np.array([1.0]), np.array([0.5]), np.array([1.5]), 700)
    >>> d.shape, d[0, 0], bool((d >= 0.5).all() and (d <= 1.5).all())
    ((701, 1), np.float64(1.0), True)
    >>> bool((np.abs(d[1:101] - 1.0) <= 0.5 / 64 + 1e-12).all())  # the first shell
    True
    """
    rng = np.random.default_rng(SEED)
    per = -(-count // len(SHELLS))
    radius = np.repeat(np.asarray(SHELLS), per)[:count, None]
    u = rng.uniform(-1.0, 1.0, size=(count, x0.size))
    half = np.maximum(upper - x0, x0 - lower)
    out = np.clip(x0 + radius * u * half, lower, upper)
    return np.vstack([x0[None, :], out])


@dataclass
class Search:
    """What :func:`nearest_passing` found and what it cost."""

    design: Array
    change: float
    found: bool
    failing: tuple[str, ...]
    evaluated: int
    passing: int
    passing_by_check: dict[str, int] = field(default_factory=dict)


class _Judge:
    """Counts the designs judged; verdicts as a (checks × designs) matrix."""

    def __init__(self, names: Sequence[str], evaluate: Evaluate) -> None:
        self.names = list(names)
        self.evaluate = evaluate
        self.count = 0
        self.checks: list[str] = []

    def __call__(self, designs: Array) -> Array:
        self.count += designs.shape[0]
        verdicts = self.evaluate({n: designs[:, i] for i, n in enumerate(self.names)})
        n = designs.shape[0]
        if not verdicts:  # every design refused: each fails every check met so far
            return np.full((max(len(self.checks), 1), n), -1, dtype=np.int8)
        self.checks = list(verdicts)
        rows = [np.broadcast_to(np.asarray(v), (n,)) for v in verdicts.values()]
        return np.stack([np.asarray(r, dtype=np.int8) for r in rows])


def _pull(judge: _Judge, best: Array, x0: Array, weights: Array, t: Array) -> Array:
    """Designs on the segment from ``x0`` to ``best``; the passing one nearest to ``x0``."""
    trial = x0 + t[:, None] * (best - x0)
    ok = (judge(trial) == 1).all(axis=0)
    if ok.any():
        j = int(np.argmin(np.where(ok, relative_change(trial, x0, weights), np.inf)))
        return np.asarray(trial[j])
    return best


def _refine(
    judge: _Judge, best: Array, x0: Array, lower: Array, upper: Array, weights: Array
) -> Array:
    """Pull ``best`` (a passing design) towards the base: line, random steps, axes.

    The last pulls move one variable at a time back to its base value where the design
    still passes, so that a variable the checks do not need keeps its value.
    """
    best = _pull(judge, best, x0, weights, np.linspace(0.0, 1.0, LINE_POINTS))
    rng = np.random.default_rng(SEED + 1)
    change = float(relative_change(best, x0, weights))
    scale = np.where(x0 != 0.0, np.abs(x0), 1.0)
    for k in range(LOCAL_ROUNDS):
        step = change * 0.5**k / math.sqrt(x0.size) * scale
        trial = np.clip(
            best + rng.uniform(-1.0, 1.0, size=(LOCAL_SAMPLES, x0.size)) * step, lower, upper
        )
        ok = (judge(trial) == 1).all(axis=0)
        d = np.where(ok, relative_change(trial, x0, weights), np.inf)
        j = int(np.argmin(d))
        if d[j] < change:
            best, change = np.asarray(trial[j]), float(d[j])
            best = _pull(judge, best, x0, weights, np.linspace(0.0, 1.0, LINE_POINTS))
            change = float(relative_change(best, x0, weights))
    frac = np.linspace(0.0, 1.0, AXIS_POINTS)
    for _ in range(AXIS_ROUNDS):
        for i in range(x0.size):
            if best[i] == x0[i]:
                continue
            trial = np.repeat(best[None, :], frac.size, axis=0)
            trial[:, i] = x0[i] + frac * (best[i] - x0[i])
            ok = (judge(trial) == 1).all(axis=0)
            if ok.any():
                best = np.asarray(trial[int(np.argmax(ok))])
    return best


def nearest_passing(
    names: Sequence[str],
    x0: Array,
    lower: Array,
    upper: Array,
    weights: Array,
    evaluate: Evaluate,
    samples: int,
) -> Search:
    r"""The design of least Δ in the box that passes every check, or the nearest try.

    .. math::
        x^* = \arg\min_{x \in \text{box},\; \text{all checks pass}} \Delta(x)

    Parameters
    ----------
    names : sequence of str
        The variables, [-]
    x0, lower, upper : ndarray
        Base and box, SI
    weights : ndarray
        w_i of Δ, [-]
    evaluate : callable
        Mapping of the variables (arrays of one shape) to the verdicts of every check
        (int8 or bool arrays: 1 passes, 0 fails, -1 the model refuses the design)
    samples : int
        Random designs of step 2, [-]

    Returns
    -------
    search : Search
        The design, its Δ, whether it passes, the checks it fails, how many designs
        were judged and how many of the random ones passed (in all and per check)

    Notes
    -----
    The base is judged first: a passing base is returned with Δ = 0. Otherwise the
    random designs (:func:`shell_samples`) are judged at once; the passing one of least
    Δ is pulled towards the base (:func:`_refine`), every trial judged by ``evaluate``.
    Where none passes, the design that fails the fewest checks, of those the nearest,
    names the binding checks. A local search: the design found is the nearest the
    search met, not a proven global minimum.

    Examples
    --------
    >>> ev = lambda v: {"a+b ≥ 3": v["a"] + v["b"] >= 3.0, "a ≤ 2": v["a"] <= 2.0}
    >>> s = nearest_passing(["a", "b"], np.array([1.0, 1.0]), np.array([0.0, 0.0]),
    ...     np.array([2.0, 2.0]), np.array([1.0, 1.0]), ev, 700)
    >>> s.found, [round(float(v), 1) for v in s.design], round(s.change, 2)  # √0.5
    (True, [1.5, 1.5], 0.71)
    """
    judge = _Judge(names, evaluate)
    base_ok = judge(x0[None, :])
    if (base_ok == 1).all():
        return Search(x0, 0.0, True, (), judge.count, 1, {c: 1 for c in judge.checks})
    designs = shell_samples(x0, lower, upper, samples)[1:]
    verdicts = judge(designs)
    ok = (verdicts == 1).all(axis=0)
    by_check = {c: int((verdicts[i] == 1).sum()) for i, c in enumerate(judge.checks)}
    passing = int(ok.sum())
    delta = relative_change(designs, x0, weights)
    if passing:
        start = designs[int(np.argmin(np.where(ok, delta, np.inf)))]
        best = _refine(judge, start, x0, lower, upper, weights)
        return Search(
            best,
            float(relative_change(best, x0, weights)),
            True,
            (),
            judge.count,
            passing,
            by_check,
        )
    all_designs = np.vstack([x0[None, :], designs])
    all_verdicts = np.hstack([base_ok, verdicts])
    fails = (all_verdicts != 1).sum(axis=0)
    score = fails * 1e6 + relative_change(all_designs, x0, weights)
    j = int(np.argmin(score))
    failing = tuple(c for i, c in enumerate(judge.checks) if all_verdicts[i, j] != 1)
    return Search(
        all_designs[j],
        float(relative_change(all_designs[j], x0, weights)),
        False,
        failing,
        judge.count,
        0,
        by_check,
    )


def _round_to(values: Array, x0: Array, digits: int, away: bool) -> Array:
    """Changed values at ``digits`` significant digits: nearest, or away from the base."""
    out = []
    for v, b in zip(values.tolist(), x0.tolist(), strict=True):
        if v == b or v == 0.0:
            out.append(b if v == b else v)
            continue
        q = 10.0 ** (digits - 1 - math.floor(math.log10(abs(v))))
        if not away:
            out.append(round(v * q) / q)
        else:
            out.append((math.ceil(v * q - 1e-9) if v > b else math.floor(v * q + 1e-9)) / q)
    return np.array(out)


def rounded(
    design: Array, x0: Array, judge: Callable[[Array], bool], digits: Sequence[int] = (3, 4, 5)
) -> Array:
    r"""The design with its changed values rounded to few significant digits, if it still passes.

    .. math::
        x_i \to \mathrm{round}(x_i, p - 1 - \lfloor \log_{10} |x_i| \rfloor), \quad
        p = 3, 4, 5

    Parameters
    ----------
    design, x0 : ndarray
        The found design and the base, SI
    judge : callable
        True where one design (a 1-D array) passes every check
    digits : sequence of int
        Significant digits to try, fewest first, [-]

    Returns
    -------
    design : ndarray
        The first rounding that passes (to the nearest, else away from the base: a
        little more of the change that made it pass), else ``design`` unchanged;
        unchanged variables keep their base value exactly

    Examples
    --------
    >>> d = rounded(np.array([61234.5, 2.0]), np.array([60000.0, 2.0]), lambda d: d[0] > 61200)
    >>> d.tolist()  # 61200 fails, 61300 (away from 60000) passes
    [61300.0, 2.0]
    """
    for p in digits:
        for away in (False, True):
            trial = _round_to(design, x0, p, away)
            if judge(trial):
                return trial
    return design
