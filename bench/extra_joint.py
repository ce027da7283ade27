"""Benchmark: joint.vdi2230's array path (for sweeps and studies) against its per-point loop.

``measure()`` returns rows {model, method, case, time_s, error, notes}:

* ``sweep``: :func:`engine.sweep` of 2,000 points of plate 1's thickness (the case
  :mod:`bench.extra_targets` sweeps), beside the same sweep with the array path switched
  off (what it cost before);
* ``array_path``: the model's ``vectorized`` called once on those points, per call;
* ``loop_2000``: the same 2,000 points one by one through :func:`engine.run`, per point
  (what every sweep and study of this model cost before the array path);
* ``study_mc_array``: a Monte Carlo study of 10⁶ designs in-process (friction box,
  plate thickness, working load and torque scattered; two outputs collected), per point,
  with the total in the notes. ``JOINT_BENCH_POINTS`` sets its size.
"""

from __future__ import annotations

import dataclasses
import functools
import os
import time
from typing import Any

import engine
from bench.extra_targets import POINTS, _median, sweep_case
from engine.core.spec import RunContext
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable

SPEC = engine.get_model("joint.vdi2230")


def monte_carlo(n: int) -> Study:
    """The 80 N·m question of the examples with its scatter (the friction study)."""
    varied = ("thread_friction_min", "bearing_friction_min", "plate1_thickness", "working_load")
    return Study(
        variables=(
            Variable("thread_friction_min", "uniform", low=0.06, high=0.10),
            Variable("bearing_friction_min", "triangular", low=0.06, mode=0.08, high=0.12),
            Variable("plate1_thickness", "normal", mean=0.020, sd=0.001),
            Variable("working_load", "uniform", low=5e3, high=15e3),
        ),
        base={k: v for k, v in SPEC.examples[1].items() if k not in varied},
        samples=n,
        seed=1,
        outputs=("assembly_preload_min", "residual_clamp_force_min"),
    )


def measure() -> list[dict[str, Any]]:
    rows: list[dict[str, Any]] = []
    case = sweep_case(SPEC)
    assert case is not None
    base, vary, values, rung = case
    first, _ = SPEC.validate(base)
    x = {**first, vary: values}
    names = frozenset(o.name for o in SPEC.outputs if not o.series)
    ctx = RunContext(rung=rung, outputs=names, tolerance=1e-3)
    assert SPEC.vectorized is not None
    t_array = _median(functools.partial(SPEC.vectorized, x, ctx))
    t_sweep = _median(
        functools.partial(engine.sweep, SPEC, base, vary, values.tolist(), budget_s=None)
    )
    looped = dataclasses.replace(SPEC, vectorized=None, vector_rungs=())
    t_before = _median(
        functools.partial(engine.sweep, looped, base, vary, values.tolist(), budget_s=None)
    )
    rows.append(
        {
            "model": SPEC.name,
            "method": "sweep",
            "case": f"{POINTS} pts of {vary} through engine.sweep",
            "time_s": t_sweep,
            "error": None,
            "notes": f"without the array path (per-point loop) {t_before * 1e3:.3g} ms, "
            f"×{t_before / t_sweep:.0f}",
        }
    )
    rows.append(
        {
            "model": SPEC.name,
            "method": "array_path",
            "case": f"{POINTS} pts of {vary}",
            "time_s": t_array,
            "error": None,
            "notes": f"engine.sweep of the same points {t_sweep * 1e3:.3g} ms",
        }
    )
    listed = values.tolist()[:200]
    t0 = time.perf_counter()
    for v in listed:
        engine.run(SPEC, {**base, vary: v})
    per = (time.perf_counter() - t0) / len(listed)
    rows.append(
        {
            "model": SPEC.name,
            "method": "loop",
            "case": "one point through engine.run",
            "time_s": per,
            "error": None,
            "notes": f"{POINTS} points one by one ≈ {per * POINTS * 1e3:.0f} ms",
        }
    )
    n = int(os.environ.get("JOINT_BENCH_POINTS", "1000000"))
    run_study(SPEC, monte_carlo(10_000))  # warm
    t0 = time.perf_counter()
    result = run_study(SPEC, monte_carlo(n))
    total = time.perf_counter() - t0
    rows.append(
        {
            "model": SPEC.name,
            "method": "study_mc_array",
            "case": f"{n}-point Monte Carlo, in-process",
            "time_s": total / n,
            "target_s": 2e-6,  # per point, as time_s: 2 s for 10⁶ points
            "met": total / n <= 2e-6,
            "error": None,
            "notes": f"{total:.2f} s for {n} points; rungs {result.summary['rungs']}; "
            f"feasible {result.summary['feasible']['fraction']}",
        }
    )
    return rows


if __name__ == "__main__":
    for row in measure():
        print(f"{row['method']:16s} {row['time_s'] * 1e6:10.2f} µs  {row['notes']}")
