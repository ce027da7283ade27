"""The summary's compiled passes place, count and gather values as numpy's arithmetic does.

Each kernel of :mod:`engine.studies.kernels` is held against the numpy lines it replaced
(``np.clip((y - low) * scale, -1, top).astype(np.intp) + first``, ``np.bincount``, a
boolean mask), on values chosen to reach every branch: below and above the bins, on
their edges, NaN and ±inf, a heavy tail, and a chunk that is a zero-stride view.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.studies import kernels
from engine.studies.plan import FINE_BINS, FineCounts

LOW, HIGH = -2.0, 3.0
SCALE = FINE_BINS / (HIGH - LOW)


def _values() -> np.ndarray:
    g = np.random.default_rng(47)
    edges = LOW + np.arange(FINE_BINS + 1) / SCALE  # every bin's lower edge, and the top
    y = np.concatenate(
        [
            g.standard_cauchy(100_000),  # a heavy tail, far beyond the bins both ways
            g.uniform(LOW, HIGH, 100_000),
            edges,
            np.nextafter(edges, -np.inf),
            [LOW, HIGH, -0.0, 0.0, np.nan, np.inf, -np.inf, 1e308, -1e308],
        ]
    )
    return g.permutation(y)


def _numpy_bins(y: np.ndarray, first: int = 1) -> np.ndarray:
    with np.errstate(over="ignore"):  # ±1e308 overflow to ±inf, then clipped
        f = np.clip((y - LOW) * SCALE, -1.0, float(FINE_BINS))
    return f.astype(np.intp) + first


def test_bins_are_numpys_arithmetic() -> None:
    y = _values()
    finite = y[np.isfinite(y)]
    labels = np.empty(finite.size, dtype=np.intp)
    counts = np.zeros(FINE_BINS + 2, dtype=np.int64)
    kernels.bins_counted(finite, LOW, SCALE, FINE_BINS, 1, labels, counts)
    assert np.array_equal(labels, _numpy_bins(finite))
    assert np.array_equal(counts, np.bincount(_numpy_bins(finite), minlength=FINE_BINS + 2))
    # a bin never decreases as the value grows: what the exact quantiles rest on
    order = np.argsort(finite, kind="stable")
    assert (np.diff(labels[order]) >= 0).all()


def test_counts_leave_out_nan_and_inf() -> None:
    y = _values()
    counts = np.zeros(FINE_BINS + 2, dtype=np.int64)
    counted = kernels.count_bins(y, LOW, SCALE, FINE_BINS, 1, counts)
    finite = y[np.isfinite(y)]
    assert counted == finite.size == y.size - 3
    assert np.array_equal(counts, np.bincount(_numpy_bins(finite), minlength=FINE_BINS + 2))


def test_gathered_values_are_the_masked_ones_in_order() -> None:
    y = _values()
    wanted = np.zeros(FINE_BINS + 2, dtype=bool)
    wanted[[0, 1, 777, FINE_BINS // 2, FINE_BINS + 1]] = True
    finite = y[np.isfinite(y)]
    expected = finite[wanted[_numpy_bins(finite)]]
    values, labels = np.empty(expected.size), np.empty(expected.size, dtype=np.intp)
    # in two pieces, the second one a zero-stride view of one number (copied to be read)
    k = kernels.gather_bins(y, LOW, SCALE, FINE_BINS, 1, wanted, values, labels, 0)
    assert k == expected.size
    assert np.array_equal(values, expected) and np.array_equal(labels, _numpy_bins(expected))
    one = np.broadcast_to(np.array([LOW]), (5,))
    more, more_labels = np.empty(5), np.empty(5, dtype=np.intp)
    assert kernels.gather_bins(one, LOW, SCALE, FINE_BINS, 1, wanted, more, more_labels, 0) == 5
    assert more.tolist() == [LOW] * 5 and more_labels.tolist() == [1] * 5


@pytest.mark.parametrize("first", [0, 1])
def test_the_offset_only_shifts_the_bins(first: int) -> None:
    y = np.array([LOW, 0.5, HIGH])
    labels, counts = np.empty(3, dtype=np.intp), np.zeros(FINE_BINS + 2, dtype=np.int64)
    kernels.bins_counted(y, LOW, SCALE, FINE_BINS, first, labels, counts)
    # by hand: 0 at the low end, 2.5 · 16384/5 = 8192 in the middle, the top bin at 3
    assert labels.tolist() == [first, 8192 + first, FINE_BINS + first]


def test_fine_counts_place_edges_as_they_counted_values() -> None:
    y = _values()
    fine = FineCounts(np.linspace(LOW, HIGH, 20_001))
    assert fine.low == pytest.approx(LOW + 0.0005 * 5.0, abs=1e-3)
    finite = y[np.isfinite(y)]
    labels = fine.bins(finite)
    fine.add(y)
    assert np.array_equal(fine.counts, np.bincount(labels, minlength=FINE_BINS + 2))


def test_values_that_were_not_counted_are_refused_not_written_beyond_the_room() -> None:
    # counts of one column, asked of another as long: every value of it falls in the
    # median's bin, which counted a few; the gather stops at its room and says so
    y = np.random.default_rng(48).random(100_000)
    fine = FineCounts(y)
    fine.add(y)
    other = np.full(y.size, float(np.median(y)))
    assert fine.resolve(other, np.array([50_000]), np.array([0.25])) is None


def test_a_lookup_is_numpys_table_indexed_by_the_bins() -> None:
    y = _values()
    finite = y[np.isfinite(y)]
    table = np.random.default_rng(49).random(FINE_BINS + 2)
    out = np.empty(finite.size)
    kernels.lookup_bins(finite, LOW, SCALE, FINE_BINS, 1, table, out)
    assert np.array_equal(out, table[_numpy_bins(finite)])
