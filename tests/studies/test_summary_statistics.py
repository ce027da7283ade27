"""The study summary's fast statistics give numpy's and scipy's numbers, to the last bit.

Each fast path (bracketed order statistics, the preallocated merge, ranks without a
tie pass) is held against the plain computation it replaces: ``np.quantile``,
``np.concatenate`` and ``scipy.stats.rankdata``, on columns chosen to reach every
branch (continuous draws, heavy ties, a constant tail, a sorted column that fools the
subsample, out-of-order chunks).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from engine.studies.plan import (
    BRACKET_POINTS,
    CHECK_FAILED,
    CHECK_OK,
    CHECK_UNKNOWN,
    QUANTILES,
    RANK_BINNED_POINTS,
    RANK_TOLERANCE,
    ChunkResult,
    Merger,
    Moments,
    _binned_ranks,
    _order_statistics,
    _quantiles,
    _ranks_along,
    _stats,
    merge,
    rank_correlations,
)

RNG = np.random.default_rng(2026)
N = 3 * BRACKET_POINTS + 17  # long enough for the brackets, odd so h = (n-1) q is fractional


def _columns() -> dict[str, np.ndarray]:
    normal = RNG.standard_normal(N)
    return {
        "normal": normal,
        "lognormal": np.exp(2.0 * normal),
        # three values, as an output rounded to a table (a bracket with a == b)
        "three_values": RNG.choice([1.0, 2.0, 3.0], size=N, p=[0.2, 0.5, 0.3]),
        # most points at one value, the rest spread: the low quantiles sit on the tie
        "constant_tail": np.where(RNG.random(N) < 0.4, 5.0, 5.0 + RNG.random(N)),
        # sorted: every 64th point is a fair subsample only by luck; exact regardless
        "sorted": np.sort(RNG.random(N)),
        # a subsample that sees one value although the column has many
        "strided": np.where(np.arange(N) % 64 == 0, 7.0, RNG.random(N)),
    }


@pytest.mark.parametrize("name", list(_columns()))
def test_quantiles_are_numpys_to_the_last_bit(name: str) -> None:
    y = _columns()[name]
    assert np.array_equal(_quantiles(y), np.quantile(y, QUANTILES))


@pytest.mark.parametrize("n", [2, 3, 10, BRACKET_POINTS - 1, BRACKET_POINTS, 1_000_003])
def test_quantiles_match_at_every_size(n: int) -> None:
    y = np.random.default_rng(n).gamma(2.0, size=n)
    assert np.array_equal(_quantiles(y), np.quantile(y, QUANTILES))


def test_order_statistics_are_the_sorted_values() -> None:
    y = _columns()["lognormal"]
    ranks = np.array([0, 1, N // 3, N // 2, N - 2, N - 1])
    assert np.array_equal(_order_statistics(y, ranks), np.sort(y)[ranks])


def test_median_by_hand() -> None:
    # 1…N shuffled: the median of N = 150,017 points is the middle one, 75,009
    y = RNG.permutation(np.arange(1.0, N + 1.0))
    assert _quantiles(y)[QUANTILES.index(0.5)] == (N + 1) / 2


@pytest.mark.parametrize("name", ["normal", "three_values", "constant_tail"])
def test_ranks_along_an_order_are_scipys_average_ranks(name: str) -> None:
    y = _columns()[name]
    got = _ranks_along(y, np.argsort(y))
    assert got is not None and np.array_equal(got, stats.rankdata(y))
    down = _ranks_along(-y, np.argsort(y))  # the order sorts -y downward
    assert down is not None and np.array_equal(down, stats.rankdata(-y))


def test_ranks_along_refuses_an_order_that_does_not_sort() -> None:
    y = _columns()["normal"]
    assert _ranks_along(y, np.arange(N)) is None


def _part(start: int, stop: int, checks: dict[str, int]) -> ChunkResult:
    n = stop - start
    idx = np.arange(start, stop, dtype=float)
    return ChunkResult(
        values={"a": idx, "b": np.where(idx % 7 == 0, np.nan, -idx)},
        checks={k: np.full(n, v, dtype=np.int8) for k, v in checks.items()},
        rungs=["closed_form" if i % 5 else None for i in range(start, stop)],
        refusals={"outside": n},
        elapsed_s=0.25,
    )


def test_merge_concatenates_in_order() -> None:
    parts = [
        _part(0, 3, {"slip": CHECK_OK}),
        _part(3, 5, {"stress": CHECK_FAILED, "slip": CHECK_FAILED}),
        _part(5, 9, {}),
    ]
    m = merge(parts, ("a", "b"))
    assert np.array_equal(m.values["a"], np.arange(9.0))
    assert np.array_equal(m.values["b"], np.concatenate([p.values["b"] for p in parts]), True)
    assert list(m.checks) == ["slip", "stress"]  # first reported in the earliest chunk first
    assert m.checks["slip"].tolist() == [1, 1, 1, 0, 0, -1, -1, -1, -1]
    assert m.checks["stress"].tolist() == [CHECK_UNKNOWN] * 3 + [0, 0] + [CHECK_UNKNOWN] * 4
    assert m.rungs == [
        None,
        "closed_form",
        "closed_form",
        "closed_form",
        "closed_form",
        None,
        "closed_form",
        "closed_form",
        "closed_form",
    ]
    assert m.refusals == {"outside": 3 + 2 + 4}
    assert m.elapsed_s == 0.75


def test_merger_in_any_arrival_order_gives_the_merge() -> None:
    slices = [(0, 4), (4, 8), (8, 12), (12, 13)]
    checks = [{}, {"b_check": 1, "a_check": 0}, {"a_check": 1, "c_check": 0}, {"c_check": 1}]
    parts = [_part(a, b, c) for (a, b), c in zip(slices, checks, strict=True)]
    whole = merge(parts, ("a", "b"))
    merger = Merger(13, ("a", "b"))
    for i in (2, 0, 3, 1):  # as a cluster might deliver them
        merger.add(slices[i][0], parts[i])
    m = merger.result()
    assert merger.received == 4
    assert list(m.checks) == list(whole.checks) == ["b_check", "a_check", "c_check"]
    for name in whole.values:
        assert np.array_equal(m.values[name], whole.values[name], equal_nan=True)
    for name in whole.checks:
        assert np.array_equal(m.checks[name], whole.checks[name])
    assert m.rungs == whole.rungs and m.refusals == whole.refusals == {"outside": 4 + 4 + 4 + 1}


def _spearman(x: np.ndarray, y: np.ndarray) -> float:
    return float(stats.spearmanr(x, y).statistic)


def test_binned_rank_correlations_stay_within_their_tolerance_of_scipys() -> None:
    """200,000 points (binned ranks): a heavy-tailed output (lognormal of σ = 2, most of
    its values in the lowest bins of its range: ranked by a sort) and smooth ones (binned)
    each within RANK_TOLERANCE of scipy's exact coefficient; in practice far closer."""
    rng = np.random.default_rng(35)
    n = 200_000
    x1, x2 = rng.standard_normal(n), rng.uniform(0.0, 1.0, n)
    outputs = {
        "smooth": x1 + 3.0 * x2,
        "heavy": np.exp(2.0 * (x1 + 0.3 * rng.standard_normal(n))),
        "product": x1 * x2,
    }
    assert n >= RANK_BINNED_POINTS
    assert _binned_ranks(outputs["smooth"]) is not None
    assert _binned_ranks(outputs["heavy"]) is None  # too coarse: sorted
    got = rank_correlations({"x1": x1, "x2": x2}, outputs)
    for name, y in outputs.items():
        for var, x in (("x1", x1), ("x2", x2)):
            rho = got[name][var]
            assert rho is not None
            # the bound allows RANK_TOLERANCE; the bins' few values each give far less
            assert abs(rho - _spearman(x, y)) <= 1e-5 < RANK_TOLERANCE, (name, var)


def test_a_column_of_few_values_is_ranked_exactly_among_many_points() -> None:
    """Ten and a hundred values over 60,000 points: every bin a tie of hundreds, refused
    by the bound; the exact average ranks of the sort give scipy's coefficient."""
    rng = np.random.default_rng(36)
    x = rng.integers(0, 10, 60_000).astype(float)
    y = 10.0 * x + rng.integers(0, 30, x.size)
    assert _binned_ranks(x) is None and _binned_ranks(y) is None
    got = rank_correlations({"x": x}, {"y": y})["y"]["x"]
    assert got == pytest.approx(_spearman(x, y), abs=1e-12)


def test_an_output_moved_by_rounding_alone_has_numpys_quantiles() -> None:
    """Values three floats apart (too narrow for a histogram's 30 bins), with refused
    points and in two pieces: the quantiles found by counting are np.quantile's."""
    one = 5.76e8
    floats = [one, float(np.nextafter(one, np.inf)), float(np.nextafter(one, -np.inf))]
    y = RNG.choice(floats, size=N, p=[0.6, 0.3, 0.1])
    y[::97] = np.nan
    moments = Moments.of(y)
    assert moments is not None
    got = _stats([y[: N // 2], y[N // 2 :]], 30, moments)
    finite = y[np.isfinite(y)]
    want = np.quantile(finite, QUANTILES)
    assert [got["quantiles"][f"{q:g}"] for q in QUANTILES] == want.tolist()
    assert got["histogram"]["counts"] == [finite.size]


def test_a_column_of_a_few_floats_is_ranked_exactly_without_a_sort() -> None:
    """An output moved by rounding alone (three adjacent floats) over 60,000 points:
    each float is its own bin, so its ranks are scipy's average ranks to the bit."""
    rng = np.random.default_rng(37)
    one = 0.9
    floats = np.array([float(np.nextafter(one, 0.0)), one, float(np.nextafter(one, 1.0))])
    index = rng.integers(0, 3, 60_000)
    y = floats[index]
    near_two = np.nextafter(2.0, np.array([0.0, 0.0, 4.0, 4.0]))  # two floats, each twice
    x = near_two[index + rng.integers(0, 2, index.size)]  # moves with y, also by rounding
    got = _binned_ranks(y)
    assert got is not None and np.array_equal(got, stats.rankdata(y))
    rho = rank_correlations({"x": x}, {"y": y})["y"]["x"]
    assert rho == pytest.approx(_spearman(x, y), abs=1e-12)
