r"""Compiled passes of a study's summary: each reads a chunk or a column once, with no
temporaries.

A 10⁶-point study's summary counts each output's values in fine bins as the chunks
arrive, gathers the values of the few bins that hold a quantile or a histogram edge,
and bins the first points of each column for its rank correlations; in numpy each of
those is four to six passes over the values, each with its temporary. Here each is one
loop compiled by numba (:func:`engine.numerics.ode.jit`, cached on disk), and every one
places a value in its bin by the one rule of :func:`uniform_bin`, so the counts, the
gathered values and the edges' bins agree to the last value.

Nothing here sums floating-point numbers that could round: the means and sums of squares
stay numpy's (pairwise summation), so a summary's numbers do not depend on these loops;
:func:`rank_table` adds whole numbers only, exactly in any order (below 2⁵³). (The extremes
and the one-number test stay numpy's too: its SIMD ``argmin``/``argmax`` and comparisons
are three times faster than a compiled loop with a branch per value, measured.)

Each function takes float64 arrays (C-contiguous, as :mod:`engine.studies.plan` gives
them); :func:`warm` calls each once, so a service pays their loading (or compiling,
with a cold cache) at start-up, not in a user's first study.
"""

from __future__ import annotations

import math

import numpy as np

from ..numerics.ode import jit

__all__ = [
    "bins_counted",
    "count_bins",
    "gather_bins",
    "lookup_bins",
    "rank_table",
    "uniform_bin",
    "warm",
]


def uniform_bin(value, low, scale, top, first):  # type: ignore[no-untyped-def]
    r"""The bin of ``value`` among uniform bins from ``low``, ``scale`` bins per unit.

    .. math::
        b = \operatorname{trunc}\bigl(\min(\max((v - v_{low})\,s, -1), b_{top})\bigr) + b_0

    Parameters
    ----------
    value : float
        The value, finite, [any unit]
    low : float
        Where the lowest bin starts, [unit]
    scale : float
        Bins per unit of the value (the bins' count over their span), [1/unit]
    top : float
        The highest bin before the offset (values above fall in it), [-]
    first : int
        The offset ``b_0``: 1 where values below ``low`` take a bin of their own (bin 0),
        0 where no value is below ``low`` (the ranks' bins), [-]

    Notes
    -----
    The arithmetic of numpy's ``np.clip((y - low) * scale, -1, top).astype(np.intp) +
    first`` (truncation toward zero, no fused multiply-add): a bin never decreases as the
    value grows, so every value of a lower bin is below every value of a higher one.

    Examples
    --------
    Ten bins over 0…5 (two per unit), one below and the top one closed: 0.2 falls in bin
    0 + 1, 4.99 in 9 + 1, 5 in the top bin 10 + 1 (clipped to 10, not 10 + 1), -3 below:

    >>> [uniform_bin(v, 0.0, 2.0, 10.0, 1) for v in (0.2, 4.99, 5.0, 7.0, -3.0)]
    [1, 10, 11, 11, 0]
    """
    f = (value - low) * scale
    if f < -1.0:
        f = -1.0
    if f > top:
        f = top
    return int(f) + first


_uniform_bin_c = jit(uniform_bin, error_model="numpy", inline=True)


def _count_bins(y, low, scale, top, first, counts):  # type: ignore[no-untyped-def]
    n = 0
    for i in range(y.size):
        v = y[i]
        if math.isfinite(v):
            counts[_uniform_bin_c(v, low, scale, top, first)] += 1
            n += 1
    return n


def _bins_counted(y, low, scale, top, first, labels, counts):  # type: ignore[no-untyped-def]
    for i in range(y.size):
        b = _uniform_bin_c(y[i], low, scale, top, first)
        labels[i] = b
        counts[b] += 1


def _lookup_bins(y, low, scale, top, first, table, out):  # type: ignore[no-untyped-def]
    for i in range(y.size):
        out[i] = table[_uniform_bin_c(y[i], low, scale, top, first)]


def _gather_bins(y, low, scale, top, first, wanted, values, labels, k):  # type: ignore[no-untyped-def]
    for i in range(y.size):
        v = y[i]
        if math.isfinite(v):
            b = _uniform_bin_c(v, low, scale, top, first)
            if wanted[b]:
                if k == values.size:  # more than there is room for: say so, write nothing
                    return -1
                values[k] = v
                labels[k] = b
                k += 1
    return k


def _rank_table(counts, mid):  # type: ignore[no-untyped-def]
    total = 0
    spread = 0.0
    for b in range(counts.size):
        c = counts[b]
        total += c
        mid[b] = float(total) - 0.5 * float(c - 1)
        if c > 1:
            f = float(c)
            spread += f * f * f - f
    return spread


_count_bins_c = jit(_count_bins, error_model="numpy")
_bins_counted_c = jit(_bins_counted, error_model="numpy")
_lookup_bins_c = jit(_lookup_bins, error_model="numpy")
_gather_bins_c = jit(_gather_bins, error_model="numpy")
_rank_table_c = jit(_rank_table, error_model="numpy")


def _floats(y: np.ndarray) -> np.ndarray:
    """``y`` as a C-contiguous float64 array (a copy only where it is not one: a
    broadcast one-number piece, a strided view), so each kernel has one signature."""
    return np.ascontiguousarray(y, dtype=np.float64)


def count_bins(
    y: np.ndarray, low: float, scale: float, top: float, first: int, counts: np.ndarray
) -> int:
    """Add each finite value of ``y`` to ``counts`` (int64) at its bin
    (:func:`uniform_bin`); the number of values counted.

    >>> counts = np.zeros(12, dtype=np.int64)
    >>> count_bins(np.array([0.2, np.nan, 4.99, 5.0, -3.0, np.inf]), 0.0, 2.0, 10.0, 1, counts)
    4
    >>> counts.tolist()
    [1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1]
    """
    return int(_count_bins_c(_floats(y), float(low), float(scale), float(top), int(first), counts))


def bins_counted(
    y: np.ndarray,
    low: float,
    scale: float,
    top: float,
    first: int,
    labels: np.ndarray,
    counts: np.ndarray,
) -> None:
    """Each value's bin (:func:`uniform_bin`) into ``labels`` (intp, as long as ``y``),
    and added to ``counts`` (int64); the values must be finite.

    >>> labels, counts = np.empty(4, dtype=np.intp), np.zeros(4, dtype=np.int64)
    >>> bins_counted(np.array([0.0, 3.0, 1.0, 4.0]), 0.0, 1.0, 3.0, 0, labels, counts)
    >>> labels.tolist(), counts.tolist()
    ([0, 3, 1, 3], [1, 1, 0, 2])
    """
    _bins_counted_c(_floats(y), float(low), float(scale), float(top), int(first), labels, counts)


def lookup_bins(
    y: np.ndarray,
    low: float,
    scale: float,
    top: float,
    first: int,
    table: np.ndarray,
    out: np.ndarray,
) -> None:
    """``out[i] = table[b_i]`` (floats), ``b_i`` the bin of the finite value ``y[i]``
    (:func:`uniform_bin`): numpy's ``table[labels]`` without the labels' array.

    >>> out, table = np.empty(4), np.array([1.0, 2.0, 0.0, 3.5])
    >>> lookup_bins(np.array([0.0, 3.0, 1.0, 4.0]), 0.0, 1.0, 3.0, 0, table, out)
    >>> out.tolist()
    [1.0, 3.5, 2.0, 3.5]
    """
    _lookup_bins_c(_floats(y), float(low), float(scale), float(top), int(first), table, out)


def gather_bins(
    y: np.ndarray,
    low: float,
    scale: float,
    top: float,
    first: int,
    wanted: np.ndarray,
    values: np.ndarray,
    labels: np.ndarray,
    k: int,
) -> int:
    """Append the finite values of ``y`` whose bin (:func:`uniform_bin`) is ``wanted``
    (bool per bin), in order, to ``values`` and their bins to ``labels``, from place
    ``k`` on; the place after the last one written, or -1 where the arrays have no room
    for them all (values that were not counted as they were: the caller then reads the
    whole column; nothing is written beyond the arrays).

    >>> wanted = np.zeros(12, dtype=bool); wanted[[1, 11]] = True
    >>> values, labels = np.empty(4), np.empty(4, dtype=np.intp)
    >>> y = np.array([0.2, 9.0, np.nan, 0.4, 3.0, 2.0])
    >>> k = gather_bins(y, 0.0, 2.0, 10.0, 1, wanted, values, labels, 0)
    >>> values[:k].tolist(), labels[:k].tolist()
    ([0.2, 9.0, 0.4], [1, 11, 1])
    >>> gather_bins(y, 0.0, 2.0, 10.0, 1, wanted, values[:2], labels[:2], 0)
    -1
    """
    return int(
        _gather_bins_c(
            _floats(y), float(low), float(scale), float(top), int(first), wanted, values, labels, k
        )
    )


def rank_table(counts: np.ndarray, mid: np.ndarray) -> float:
    r"""The average rank of each bin's values into ``mid`` (floats, as long as ``counts``,
    the values per bin, int64), and :math:`\sum_b (c_b^3 - c_b)` over the bins, in one pass.

    A bin's c values above u in the bins below take ranks u + 1 … u + c, on average
    u + (c + 1)/2 = (u + c) − (c − 1)/2. Every number here is a whole number or a half,
    exact in floats below 2⁵³: for up to 208,063 values (n³ < 2⁵³) the sum is numpy's
    ``np.add.reduce(c * c * c - c)`` of the counts above 1, to the bit, and ``mid`` is
    ``np.cumsum(counts) - 0.5 * (counts - 1)``, without their eight passes and temporaries.

    >>> mid = np.empty(3)
    >>> rank_table(np.array([2, 0, 3]), mid), mid.tolist()
    (30.0, [1.5, 2.5, 4.0])
    """
    return float(_rank_table_c(np.ascontiguousarray(counts, dtype=np.int64), mid))


def warm() -> None:
    """Call each kernel once with the types a study gives them: numba loads them from
    its disk cache (or compiles them) now, not in a study.

    >>> warm()
    """
    y = np.array([0.0, 1.0, 2.0, np.nan])
    counts = np.zeros(4, dtype=np.int64)
    labels = np.empty(4, dtype=np.intp)
    count_bins(y, 0.0, 1.0, 2.0, 1, counts)
    bins_counted(y[:3], 0.0, 1.0, 2.0, 0, labels, counts)
    gather_bins(y, 0.0, 1.0, 2.0, 1, np.ones(4, dtype=bool), np.empty(4), labels, 0)
    lookup_bins(y[:3], 0.0, 1.0, 2.0, 0, np.arange(4.0), np.empty(3))
    rank_table(counts, np.empty(4))
