"""A study summarised chunk by chunk gives the numbers of its merged columns.

Each chunk's partial summary (moments, extremes, check and rung counts) and the fine
counts gathered as chunks arrive are held against the plain computation on the merged
columns: ``np.quantile`` and ``np.histogram`` to the last bit, ``np.mean`` and
``np.std`` to 1e-12 (the pairwise combination rounds differently from numpy's pairwise
sum), ``np.nanargmin``/``np.nanargmax`` for the extremes' designs, and
``scipy.stats.spearmanr`` to 1e-12. The laws reach every branch: continuous and heavy
tailed (lognormal, Cauchy), point masses and ties, refused points (NaN), a column in
order (a pilot that is no fair sample) and chunks arriving out of order.
"""

from __future__ import annotations

import math
import pickle
from collections import Counter
from collections.abc import Callable
from dataclasses import replace

import numpy as np
import pytest
from scipy import stats

import engine
from engine.studies.execute import run_study
from engine.studies.plan import (
    CHECK_FAILED,
    CHECK_OK,
    CHECK_UNKNOWN,
    GATHER_POINTS,
    QUANTILES,
    ChunkResult,
    Columns,
    Merger,
    Moments,
    Study,
    Variable,
    _quantile_ranks,
    _stats,
    one_numbers,
    rank_correlations,
    summarize_chunk,
)

N = 3 * 65_536 + 4_321  # four chunks, the last one short
CHUNK = 65_536
BINS = 30


def _laws() -> dict[str, Callable[[np.random.Generator], np.ndarray]]:
    return {
        "normal": lambda g: g.normal(1e3, 10.0, N),
        # a heavy tail: the pilot's range is cut at its 0.05 % ends
        "lognormal": lambda g: g.lognormal(0.0, 2.0, N),
        "cauchy": lambda g: g.standard_cauchy(N),
        # point masses (a bool output, a table of three values): ties at every quantile
        "bool": lambda g: (g.random(N) < 0.3).astype(float),
        "three_values": lambda g: g.choice([1.0, 2.0, 3.0], size=N, p=[0.2, 0.5, 0.3]),
        # 40 % at one value, the rest spread above it
        "constant_tail": lambda g: np.where(g.random(N) < 0.4, 5.0, 5.0 + g.random(N)),
        # integers 0 … 6000: every histogram edge (a multiple of 200) falls on values
        "integers": lambda g: g.integers(0, 6001, N).astype(float),
        # refused points
        "with_nan": lambda g: np.where(g.random(N) < 0.1, np.nan, g.gamma(2.0, size=N)),
        # in order: the first chunk sees only the lowest quarter
        "sorted": lambda g: np.sort(g.random(N)),
        "constant": lambda g: np.full(N, 0.1),
        # the first two chunks at one value (kept as that number), the rest spread
        "steps": lambda g: np.where(np.arange(N) < 2 * CHUNK, 2.0, 2.0 + g.random(N)),
    }


def _parts(y: np.ndarray) -> list[tuple[int, ChunkResult]]:
    out = []
    for a in range(0, y.size, CHUNK):
        b = min(a + CHUNK, y.size)
        rungs: list[str | None] = ["closed_form"] * (b - a)
        part = ChunkResult({"y": y[a:b].copy()}, {}, rungs, {}, 0.0)
        out.append((a, summarize_chunk(part)))
    return out


def _merged(y: np.ndarray, order: list[int] | None = None) -> ChunkResult:
    parts = _parts(y)
    merger = Merger(y.size, ("y",))
    for i in order or range(len(parts)):
        merger.add(*parts[i])
    return merger.result()


@pytest.mark.parametrize("whole", [False, True], ids=["pieces", "column"])
@pytest.mark.parametrize("law", list(_laws()))
def test_quantiles_and_histogram_are_numpys_to_the_last_bit(law: str, whole: bool) -> None:
    y = _laws()[law](np.random.default_rng(35))
    merged = _merged(y, order=[2, 0, 3, 1])  # as a cluster might deliver them
    summary = merged.summary
    assert summary is not None and isinstance(merged.values, Columns)
    column = merged.values["y"] if whole else merged.values.pieces("y")
    got = _stats(column, BINS, summary.moments["y"], summary.fine.get("y"))
    finite = y[np.isfinite(y)]
    assert list(got["quantiles"].values()) == np.quantile(finite, QUANTILES).tolist()
    counts, edges = np.histogram(finite, BINS)
    assert got["histogram"]["counts"] == counts.tolist()
    assert got["histogram"]["edges"] == edges.tolist()
    assert got["count"] == finite.size
    assert (got["min"], got["max"]) == (finite.min(), finite.max())
    scale = max(abs(float(finite.mean())), float(finite.std()), 1e-300)
    assert abs(got["mean"] - finite.mean()) <= 1e-12 * scale
    assert abs(got["std"] - finite.std(ddof=1)) <= 1e-12 * scale


@pytest.mark.parametrize("law", ["normal", "lognormal", "cauchy", "with_nan", "integers"])
def test_fine_counts_serve_continuous_and_heavy_tailed_laws(law: str) -> None:
    # the test above passes through the fallback too: here the fine counts must serve
    y = _laws()[law](np.random.default_rng(36))
    merged = _merged(y)
    assert merged.summary is not None
    fine = merged.summary.fine["y"]
    finite = y[np.isfinite(y)]
    ranks = _quantile_ranks(finite.size)
    edges = np.histogram_bin_edges(finite, BINS)
    found = fine.resolve(finite, ranks, edges[:-1])
    assert found is not None
    assert found[0].tolist() == np.sort(finite)[ranks].tolist()
    below = [int(np.count_nonzero(finite < e)) for e in edges[:-1]]
    assert found[1].tolist() == below


def test_a_point_mass_or_a_sorted_column_falls_back_to_the_column() -> None:
    for law in ("bool", "sorted"):
        y = _laws()[law](np.random.default_rng(37))
        merged = _merged(y)
        assert merged.summary is not None
        fine = merged.summary.fine["y"]
        ranks = _quantile_ranks(y.size)
        assert fine.resolve(y, ranks, np.histogram_bin_edges(y, BINS)[:-1]) is None, law


def test_a_short_study_is_summarised_from_its_columns_alone() -> None:
    y = np.random.default_rng(38).random(GATHER_POINTS - 1)
    merged = _merged(y)
    assert merged.summary is not None and merged.summary.fine == {}
    got = _stats(merged.values["y"], BINS, merged.summary.moments["y"])
    assert list(got["quantiles"].values()) == np.quantile(y, QUANTILES).tolist()


def test_moments_by_hand() -> None:
    # 1, 2 | 3, 4, NaN | 10: n = 5, mean 4, deviations -3 -2 -1 0 6, M2 = 50, s² = 12.5
    chunks = [np.array([1.0, 2.0]), np.array([3.0, 4.0, np.nan]), np.array([10.0])]
    starts = [0, 2, 5]
    parts = [Moments.of(c) for c in chunks]
    whole = parts[0]
    for a, m in zip(starts[1:], parts[1:], strict=True):
        assert whole is not None and m is not None
        whole = whole.then(m.shifted(a))
    assert whole is not None
    assert (whole.count, whole.mean, whole.m2, whole.std) == (5, 4.0, 50.0, 12.5**0.5)
    assert (whole.low, whole.first_low, whole.high, whole.first_high) == (1.0, 0, 10.0, 5)
    assert Moments.of(np.array([np.nan, np.inf])) is None


def test_extremes_keep_the_first_of_tied_points_across_chunks() -> None:
    y = np.random.default_rng(39).integers(0, 5, N).astype(float)
    y[: CHUNK + 7] = 2.0  # the first lowest and highest are in a later chunk
    y[CHUNK + 9] = y[N - 1] = -1.0
    y[2 * CHUNK + 3] = y[2 * CHUNK + 5] = 9.0
    m = _merged(y, order=[3, 1, 0, 2]).summary
    assert m is not None
    got = m.moments["y"]
    assert got is not None
    assert (got.first_low, got.first_high) == (np.nanargmin(y), np.nanargmax(y))
    assert (got.first_low, got.first_high) == (CHUNK + 9, 2 * CHUNK + 3)


def test_check_and_rung_counts_are_the_merged_arrays() -> None:
    rng = np.random.default_rng(40)
    merger = Merger(N, ("y",))
    slices = [(a, min(a + CHUNK, N)) for a in range(0, N, CHUNK)]
    names = np.array(["closed_form", "simulation", None], dtype=object)
    for a, b in reversed(slices):
        n = b - a
        checks = {"R8": rng.choice([CHECK_OK, CHECK_FAILED, CHECK_UNKNOWN], n).astype(np.int8)}
        if a:  # the first chunk reports a check the others do not
            checks["R12"] = np.full(n, CHECK_OK, np.int8)
        rungs = list(names[rng.integers(0, 3, n)]) if a else ["closed_form"] * n
        part = ChunkResult({"y": rng.random(n)}, checks, rungs, {}, 0.0)
        merger.add(a, summarize_chunk(part))
    merged = merger.result()
    assert merged.summary is not None
    for name, codes in merged.checks.items():
        want = (int((codes == CHECK_OK).sum()), int((codes == CHECK_FAILED).sum()))
        assert merged.summary.checks[name] == want
    # the same counts in the same order (first seen first), whatever the arrival order
    assert list(merged.summary.rungs.items()) == list(Counter(merged.rungs).items())


def test_rank_correlations_are_scipys_spearman() -> None:
    rng = np.random.default_rng(41)
    x = {"a": rng.random(20_000), "b": rng.integers(0, 7, 20_000).astype(float)}
    y = {
        "sum": x["a"] + 0.3 * x["b"],
        "ties": np.round(x["a"] * 4.0) - x["b"],
        "nan": np.where(x["a"] < 0.2, np.nan, np.exp(x["a"]) * x["b"]),
    }
    got = rank_correlations(x, y)
    for name, col in y.items():
        ok = np.isfinite(col)
        for var, xs in x.items():
            want = stats.spearmanr(xs[ok], col[ok]).statistic
            assert got[name][var] == pytest.approx(want, abs=1e-12)


def test_rank_correlations_seek_each_columns_extremes_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Each input's extremes are sought once per finite mask and each output's once (not
    once per pair); an input or an output of one value has no coefficient."""
    from engine.studies import plan as study_plan

    sought: list[int] = []
    real = study_plan._extremes

    def counted(x: np.ndarray) -> tuple[float, float]:
        sought.append(x.size)
        return real(x)

    monkeypatch.setattr(study_plan, "_extremes", counted)
    rng = np.random.default_rng(42)
    n = 60_000  # binned ranks
    x = {"a": rng.random(n), "b": rng.standard_normal(n), "fixed": np.full(n, 0.5)}
    y = {
        "sum": x["a"] + x["b"],
        "product": x["a"] * x["b"],
        "flat": np.full(n, 7.0) + 0.0 * x["a"],  # one value, not a zero-stride view
        "nan": np.where(x["a"] < 0.2, np.nan, x["b"] - x["a"]),
    }
    got = rank_correlations(x, y)
    # 4 outputs (the "nan" one on its finite points), and the 3 inputs on all points and
    # again on those finite points
    m = int(np.isfinite(y["nan"]).sum())
    assert sorted(sought) == sorted([n] * 3 + [m] + [n] * 3 + [m] * 3)
    assert got["flat"] == dict.fromkeys(x)
    for name in ("sum", "product", "nan"):
        assert got[name]["fixed"] is None
        ok = np.isfinite(y[name])
        for var in ("a", "b"):
            want = stats.spearmanr(x[var][ok], y[name][ok]).statistic
            assert got[name][var] == pytest.approx(want, abs=1e-5), (name, var)


def test_a_study_summary_is_the_plain_numbers_of_its_points() -> None:
    spec = engine.get_model("preload.tightening")
    base = {k: v for k, v in spec.examples[0].items() if k != "thread_friction"}
    study = Study(
        variables=(
            Variable("thread_friction", "uniform", low=0.08, high=0.16),
            Variable("bearing_friction", "normal", mean=0.12, sd=0.012),
        ),
        base=base,
        samples=GATHER_POINTS + 30_000,
        seed=4,
    )
    run = run_study(spec, study)
    summary, values, columns = run.summary, run.merged.values, run.plan.columns
    for name, got in summary["outputs"].items():
        y = values[name]
        finite = y[np.isfinite(y)]
        if finite.size == 0:
            continue
        assert list(got["quantiles"].values()) == np.quantile(finite, QUANTILES).tolist(), name
        try:
            counts = np.histogram(finite, study.bins)[0].tolist()
        except ValueError:  # an output constant to rounding: one bin
            counts = [finite.size]
        assert got["histogram"]["counts"] == counts, name
        scale = max(abs(float(finite.mean())), 1e-300)
        assert abs(got["mean"] - finite.mean()) <= 1e-12 * scale, name
        assert abs(got["std"] - finite.std(ddof=1)) <= 1e-12 * scale, name
        lo = int(np.nanargmin(y))
        assert summary["extremes"][name]["min"]["inputs"] == {
            k: float(v[lo]) for k, v in columns.items()
        }
    assert summary["rungs"] == {
        (k if k is not None else "refused"): c for k, c in Counter(run.merged.rungs).items()
    }


def test_an_output_that_barely_moves_keeps_its_spread() -> None:
    """Four chunks of 1e8 + N(0, 1e-3): the chunks' means are rounded to about 1e-8, as
    large as the differences between them, so combining them by the rounded means alone
    gave the spread 1e-8 off; with each mean's residual it stays within numpy's own error
    of the exact spread (a rational sum of every point)."""
    from fractions import Fraction

    rng = np.random.default_rng(11)
    size = 4096
    chunks = [1e8 + rng.normal(0.0, 1e-3, size) for _ in range(4)]
    merger = Merger(4 * size, ("y",))
    for i, c in enumerate(chunks):
        merger.add(i * size, summarize_chunk(ChunkResult({"y": c}, {}, ["r"] * size, {}, 0.0)))
    summary = merger.result().summary
    assert summary is not None
    moments = summary.moments["y"]
    assert moments is not None
    got = moments.std
    y = np.concatenate(chunks)
    exact_values = [Fraction(v) for v in y.tolist()]
    mu = sum(exact_values) / len(exact_values)
    exact = math.sqrt(float(sum((v - mu) ** 2 for v in exact_values) / (len(y) - 1)))
    assert abs(got - exact) <= 1e-10 * exact


def test_a_moving_column_is_made_whole_once_and_a_one_number_output_holds_nothing() -> None:
    y = _laws()["steps"](np.random.default_rng(39))
    merged = _merged(y, order=[3, 1, 0, 2])
    values = merged.values
    assert isinstance(values, Columns)
    # the output moves in two chunks: one whole column of 8-byte values, every chunk in it
    assert values.nbytes == 8 * N
    (whole,) = values.pieces("y")
    assert np.array_equal(whole, y) and np.array_equal(values["y"], y)
    assert values["y"] is not whole  # by name: a new array
    assert np.array_equal(values.head("y", CHUNK + 5), y[: CHUNK + 5])
    assert np.array_equal(values.head("y", 10 * N), y)
    # an output of one number in every chunk holds those numbers alone
    c = Columns(N, ("k",))
    for a in range(0, N, CHUNK):
        c.put("k", a, np.full(min(CHUNK, N - a), 2.0))
    assert c.nbytes == 0 and all(p.strides == (0,) for p in c.pieces("k"))
    assert np.array_equal(c["k"], np.full(N, 2.0)) and c.rows("k", 5, 9).tolist() == [2.0] * 4


def test_columns_keep_signed_zeros_and_copy_what_they_are_given() -> None:
    c = Columns(6, ("z", "v"))
    z = np.array([0.0, -0.0, 0.0])  # equal, not the same bits: kept as they are
    c.put("z", 0, z)
    c.put("z", 3, np.full(3, -0.0))  # one number to the bit: no memory
    assert np.signbit(c["z"]).tolist() == [False, True, False, True, True, True]
    big = np.arange(12.0)
    c.put("v", 0, big[:3])  # a view of a larger array: copied, the larger one let go
    c.put("v", 3, big[3:6])
    assert c.nbytes == 8 * (6 + 6) and c["v"].tolist() == [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]
    assert all(not np.shares_memory(p, big) for p in c.pieces("v"))


def test_a_chunk_its_moments_prove_one_number_is_kept_without_comparing_its_bits(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Every value finite and the extremes equal and not zero: one number to the bit,
    known from the chunk's moments; a chunk with a refused point beside a value is known
    not to be one from them too; only equal zeros (0.0 and -0.0 are equal) are compared
    bit by bit, and each column holds the values put."""
    from engine.studies import plan as study_plan

    compared: list[int] = []
    real = study_plan._one_number

    def counted(y: np.ndarray) -> np.ndarray | None:
        compared.append(y.size)
        return real(y)

    monkeypatch.setattr(study_plan, "_one_number", counted)
    n = 2 * CHUNK
    zeros = np.zeros(n)
    zeros[CHUNK + 7] = -0.0  # the second chunk's zeros are not one number to the bit
    refused = np.full(n, 3.0)
    refused[5] = np.nan
    columns = {"one": np.full(n, 2.5), "zeros": zeros, "refused": refused}
    merger = Merger(n, tuple(columns))
    for a in (0, CHUNK):
        part = ChunkResult(
            {k: v[a : a + CHUNK].copy() for k, v in columns.items()}, {}, [None] * CHUNK, {}, 0.0
        )
        merger.add(a, part)
    # the zeros' chunks alone were compared: the refused column's first chunk is told
    # from its moments, and its second (one number) goes into the whole column the first made
    assert compared == [CHUNK, CHUNK]
    values = merger.result().values
    assert isinstance(values, Columns)
    assert all(p.strides == (0,) for p in values.pieces("one"))
    for name, y in columns.items():
        assert values[name].tobytes() == y.tobytes(), name  # every bit, signs and NaN too
    assert values.nbytes == 8 * n * 2  # "zeros" and "refused" whole, "one" nothing


def test_a_chunk_of_one_number_travels_as_that_number() -> None:
    # what a Dask worker sends back: pickled (the protocol Dask falls back to for a result)
    size = 65_536
    spread = np.random.default_rng(40).random(size)
    zeros = np.zeros(size)
    zeros[7] = -0.0  # equal to the others, not the same bits: sent whole
    part = ChunkResult(
        {"one": np.full(size, 2.5), "spread": spread, "zeros": zeros},
        {},
        ["closed_form"] * size,
        {},
        0.0,
    )
    packed = one_numbers(summarize_chunk(part))
    assert [y.strides for y in packed.values.values()] == [(0,), (8,), (8,)]
    alone = len(pickle.dumps(ChunkResult({"spread": spread}, {}, [], {}, 0.0), protocol=5))
    sent = pickle.dumps(packed, protocol=5)
    # the one-number column adds a few bytes, where it added 8 bytes a point (512 kB)
    assert (
        len(
            pickle.dumps(
                replace(packed, values={**packed.values, "one": np.full(size, 2.5)}), protocol=5
            )
        )
        - len(sent)
        > 8 * size - 1_000
    )
    back = pickle.loads(sent)
    assert len(sent) - alone < 8 * size + 200_000  # zeros, and the rung names
    for name, y in part.values.items():
        assert np.array_equal(back.values[name], y) and np.array_equal(
            np.signbit(back.values[name]), np.signbit(y)
        )
    assert back.values["one"].strides == (0,) and back.summary == packed.summary


def test_a_chunk_with_no_value_travels_as_one_nan() -> None:
    # an output the design does not have (a preload study's nut and stripping outputs
    # without a nut) is NaN at every point: one number to the bit, sent as one
    size = 65_536
    nan = np.full(size, np.nan)
    other = nan.copy()
    other.view(np.int64)[9] ^= 1  # a NaN of another payload: not the same bits, sent whole
    part = ChunkResult({"none": nan, "other": other}, {}, ["closed_form"] * size, {}, 0.0)
    packed = one_numbers(summarize_chunk(part))
    assert packed.summary is not None and packed.summary.moments == {"none": None, "other": None}
    assert [y.strides for y in packed.values.values()] == [(0,), (8,)]
    back = pickle.loads(pickle.dumps(packed, protocol=5))
    assert back.values["none"].shape == (size,) and back.values["none"].strides == (0,)
    for name, y in part.values.items():  # every bit as it was
        assert np.array_equal(back.values[name].view(np.int64), y.view(np.int64))


@pytest.mark.parametrize(
    ("model", "varied"),
    [
        ("tool.capability", ("mean_torque", "torque_sd", "lower_limit", "upper_limit")),
        ("nutrunner.drive", ("idle_spindle_friction_torque",)),
        ("clutch.ball", ("allowable_shear_stress",)),
    ],
)
def test_a_chunk_output_that_is_an_input_given_back_is_a_column_of_its_own(
    model: str, varied: tuple[str, ...]
) -> None:
    """An array path may give an input back as an output (tool.capability's limits, the
    clutch's permissible stress); the chunk's column is then a copy, not the study's drawn
    column: a later write into an output column cannot change the study's inputs."""
    spec = engine.get_model(model)
    example = dict(spec.examples[0])
    if model == "clutch.ball":  # its example leaves τ_zul out
        example["allowable_shear_stress"] = 700e6
    n = 40
    columns = {k: float(example[k]) * np.linspace(0.99, 1.01, n) for k in varied if example.get(k)}
    assert columns, "the example gives the varied inputs"
    base = {k: v for k, v in example.items() if k not in columns}
    from engine.studies.plan import evaluate_chunk

    outputs = [o.name for o in spec.outputs if not o.series and o.kind == "float"]
    chunk = evaluate_chunk(spec, base, columns, outputs)
    given_back = 0
    for name, y in chunk.values.items():
        for k, column in columns.items():
            assert not np.shares_memory(y, column), (name, k)
            given_back += bool(np.array_equal(y, column))
    assert given_back, "some output is one of the inputs, value for value"
