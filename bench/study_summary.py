"""Benchmark: where a 10⁶-point Monte Carlo study spends its time, and a numpy floor study.

``python -m bench.study_summary [points]`` (default 10⁶) runs, in process, with every
scalar output collected (the default outputs):

* ``joint.vdi2230``: the friction study of :mod:`bench.extra_joint` (friction box, plate
  thickness and working load scattered);
* ``preload.tightening``: M12 8.8 with μ_G uniform 0.08…0.16 and μ_K normal (0.12, 0.012);

and prints the split of each, in CPU seconds of this process: points drawn
(:func:`engine.studies.plan.plan`), model evaluation (the chunks), the chunks' partial
summaries (:func:`engine.studies.plan.summarize_chunk`, made where a chunk runs: on its
worker under Dask, here in this process, so counted as summary work), merge (the values
put in place, each output counted in fine bins, the partials combined), quantiles and
histograms (``_stats`` of every output: one pass over the few fine bins that hold them,
exact), rank correlations, the rest of
:func:`engine.studies.plan.summarize` (extremes, checks, rung counts), and the share the
partial summaries, merge and summary take of the whole.

Beside ``preload.tightening`` it times a numpy floor study: the same laws drawn (inverse
CDF of the same uniform numbers), the floor's equations (the assembly preload F_M and the
tightening torque M_A of VDI 2230-1 R7 and R13, through :mod:`engine.physics.preload`),
and the same summary statistics of those two outputs (count, mean, std, min, max, the
nine quantiles, the histogram, Spearman's rank correlation with each input on the first
:data:`~engine.studies.plan.RANK_POINTS` points); the ratio study / floor prints.

``measure()`` gives the same as rows for ``make bench`` (listed in ``bench/run.py``).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from scipy import special

import engine
from bench.extra_joint import monte_carlo as joint_monte_carlo
from engine.physics import preload as pl
from engine.studies.execute import ChunkArgs, chunk_size, run_study
from engine.studies.plan import (
    QUANTILES,
    RANK_POINTS,
    Study,
    Variable,
    _stats,
    chunks,
    evaluate_chunk,
    merge,
    plan,
    rank_correlations,
    summarize,
    summarize_chunk,
)

POINTS = 1_000_000
#: The share of a study merge and summary may take (issue 35's target).
SHARE_TARGET = 0.30
#: A study's time over its numpy floor study's (issue 35's target).
FLOOR_RATIO_TARGET = 3.0

PRELOAD = engine.get_model("preload.tightening")
#: μ_G's box and μ_K's mean and standard deviation in the preload study.
MU_G = (0.08, 0.16)
MU_K = (0.12, 0.012)
#: The M12 8.8 bolt's geometry and strength, as the model resolves them (once, untimed).
_BOLT: dict[str, float] = {
    k: float(v)
    for k, v in engine.run(PRELOAD, PRELOAD.examples[0]).results.items()
    if isinstance(v, int | float)
}


def preload_study(n: int) -> Study:
    """M12 8.8 tightened to 90 % of yield with both frictions scattered; every output."""
    return Study(
        variables=(
            Variable("thread_friction", "uniform", low=MU_G[0], high=MU_G[1]),
            Variable("bearing_friction", "normal", mean=MU_K[0], sd=MU_K[1]),
        ),
        base={k: v for k, v in PRELOAD.examples[0].items() if k != "thread_friction"},
        samples=n,
        seed=1,
    )


def joint_study(n: int) -> Study:
    """The friction study of :mod:`bench.extra_joint` with every output collected."""
    study = joint_monte_carlo(n)
    return Study(study.variables, study.base, samples=n, seed=study.seed)


def _clock(call: Callable[[], Any]) -> tuple[float, Any]:
    """The CPU seconds of this process ``call`` takes (steadier than the wall clock on a
    machine other work shares: numpy's summaries here run in one thread), and its value."""
    t0 = time.process_time()
    out = call()
    return time.process_time() - t0, out


def split(spec: engine.ModelSpec, study: Study) -> dict[str, float]:
    """Seconds spent per phase of one in-process study (as :func:`run_study` runs it)."""
    t_plan, p = _clock(lambda: plan(spec, study))
    base = {k: v for k, v in study.base.items() if v is not None}
    slices = chunks(p.n_points, chunk_size(spec, study))
    calls: list[ChunkArgs] = [
        (spec, base, {k: v[a:b] for k, v in p.columns.items()}, p.outputs, None, None, None)
        for a, b in slices
    ]
    t_eval, parts = _clock(lambda: [evaluate_chunk(*args) for args in calls])
    t_partial, parts = _clock(lambda: [summarize_chunk(part) for part in parts])
    t_merge, merged = _clock(lambda: merge(parts, p.outputs))
    partial = merged.summary
    assert partial is not None
    t_quant, _ = _clock(
        lambda: [
            _stats(merged.values[o], study.bins, partial.moments[o], partial.fine.get(o))
            for o in p.outputs
        ]
    )
    t_rank, _ = _clock(
        lambda: rank_correlations(p.columns, {o: merged.values[o] for o in p.outputs})
    )
    t_summary, _ = _clock(lambda: summarize(spec, study, p, merged))
    t_whole, _ = _clock(lambda: run_study(spec, study))
    return {
        "plan": t_plan,
        "evaluate": t_eval,
        "partials": t_partial,
        "merge": t_merge,
        "quantiles": t_quant,
        "ranks": t_rank,
        "summary_rest": max(t_summary - t_quant - t_rank, 0.0),
        "summary": t_summary,
        "run_study": t_whole,
    }


def _floor_stats(y: np.ndarray, bins: int) -> dict[str, Any]:
    """The summary statistics of one output, in a few numpy lines (one sort)."""
    s = np.sort(y)
    lo, hi = s[0], s[-1]
    counts, edges = np.histogram(y, bins=bins, range=(lo, hi))
    return {
        "mean": y.mean(),
        "std": y.std(ddof=1),
        "quantiles": np.quantile(s, QUANTILES),  # sorted input: numpy's partition is cheap
        "histogram": (counts, edges),
    }


def _floor_ranks(x: np.ndarray) -> np.ndarray:
    r = np.empty(x.size)
    r[np.argsort(x)] = np.arange(1, x.size + 1)  # continuous laws: no ties
    return r


def floor_study(n: int, seed: int = 1, bins: int = 30) -> dict[str, Any]:
    """The preload study in plain numpy: same laws, the floor's equations, same statistics."""
    u = np.clip(np.random.default_rng(seed).random((n, 2)), 1e-12, 1.0 - 1e-12)
    mu_g: Any = MU_G[0] + u[:, 0] * (MU_G[1] - MU_G[0])
    # the normal law truncated to μ_K's declared range 0…1, by its inverse CDF
    mean, sd = MU_K
    pa, pb = special.ndtr(-mean / sd), special.ndtr((1.0 - mean) / sd)
    mu_k: Any = mean + sd * special.ndtri(pa + u[:, 1] * (pb - pa))
    pitch, d2, area = _BOLT["thread_pitch"], _BOLT["pitch_diameter"], _BOLT["stress_area"]
    d0 = np.sqrt(4.0 * area / np.pi)
    dw, dh, rp = _BOLT["bearing_outer_diameter"], _BOLT["hole_diameter"], _BOLT["yield_strength"]
    beta: Any = pl.torsion_factor(pitch, d2, d0, mu_g)
    force: Any = pl.assembly_preload(rp, area, beta)
    torque: Any = pl.vdi_tightening_torque(force, pitch, d2, mu_g, mu_k, dw, dh)
    out = {"assembly_preload": force, "tightening_torque": torque}
    stats = {k: _floor_stats(v, bins) for k, v in out.items()}
    m = min(n, RANK_POINTS)
    rx = [_floor_ranks(x[:m]) for x in (mu_g, mu_k)]
    ranks = {k: [np.corrcoef(r, _floor_ranks(v[:m]))[0, 1] for r in rx] for k, v in out.items()}
    return {"values": out, "stats": stats, "ranks": ranks}


def _row(model: str, case: str, seconds: float, n: int, notes: str, **extra: Any) -> dict[str, Any]:
    return {
        "model": model,
        "method": "study_summary",
        "case": case,
        "time_s": seconds / n,
        "error": None,
        "notes": notes,
        **extra,
    }


def measure(n: int = POINTS) -> list[dict[str, Any]]:
    rows: list[dict[str, Any]] = []
    for spec, study in (
        (engine.get_model("joint.vdi2230"), joint_study(n)),
        (PRELOAD, preload_study(n)),
    ):
        run_study(spec, type(study)(study.variables, study.base, samples=10_000))  # warm
        t = split(spec, study)
        # of the phases run_study goes through (its merge runs inside the evaluation loop,
        # chunk by chunk, and each chunk's partial summary where the chunk runs, so the
        # split times them apart); the partials count as summary work wherever they run
        summarising = t["partials"] + t["merge"] + t["summary"]
        share = summarising / (t["plan"] + t["evaluate"] + summarising)
        figures = ", ".join(
            f"{k} {t[k]:.3f} s"
            for k in (
                "plan",
                "evaluate",
                "partials",
                "merge",
                "quantiles",
                "ranks",
                "summary_rest",
            )
        )
        notes = (
            f"{figures}; run_study {t['run_study']:.2f} s; partials + merge + summary "
            f"{100 * share:.0f} % (target ≤ {100 * SHARE_TARGET:.0f} %)"
        )
        extra: dict[str, Any] = {"split": t, "share": share, "met": share <= SHARE_TARGET}
        if spec is PRELOAD:
            floor_study(10_000)  # warm
            t_floor, _ = _clock(lambda: floor_study(n))
            ratio = t["run_study"] / t_floor
            notes += (
                f"; numpy floor study {t_floor:.3f} s, study/floor ×{ratio:.1f} "
                f"(target ≤ ×{FLOOR_RATIO_TARGET:g})"
            )
            extra.update(floor_s=t_floor, floor_ratio=ratio)
            extra["met"] = extra["met"] and ratio <= FLOOR_RATIO_TARGET
        rows.append(
            _row(
                spec.name,
                f"{n:,}-point Monte Carlo, every output, in-process",
                t["run_study"],
                n,
                notes,
                **extra,
            )
        )
    return rows


if __name__ == "__main__":
    size = int(sys.argv[1]) if len(sys.argv) > 1 else POINTS
    for row in measure(size):
        print(f"{row['model']:20s} {row['notes']}")
