"""Benchmark: what :func:`engine.run` adds to a model's own work, beside issue 35's targets.

For each model's first example, on the rung ``auto`` chooses for it (closed forms only:
a simulation's bookkeeping is lost in its integration), three things are timed in the
same interleaved rounds, in CPU time (``time.process_time``: the machine is shared):

* the model's compute alone: ``spec.compute`` on the validated inputs with a fresh
  request scratch, as the runner calls it (its sentences written, not read);
* ``engine.run`` with that rung named;
* ``engine.run`` at the default fidelity (``auto``: the rung chosen from the estimates).

Rows: **the runner's share** (named run minus compute, over compute; target ≤ 1: "engine.run
minus its model's compute ≤ the compute itself") and **auto over named** (target ≤ 1.1:
"a default-auto request ≤ 1.1 × the same request with the chosen rung named"). Each
figure is the median of the per-round ratios.

Run alone: ``PYTHONPATH=. python -m bench.extra_runner``.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from typing import Any

import engine
from bench.timing import us
from engine.core.runner import prepare
from engine.core.spec import ModelSpec, RunContext, Scratch
from engine.models import MODELS

ROUNDS = 9
SHARE_TARGET = 1.0
AUTO_TARGET = 1.1


def _per_call(fn: Callable[[], Any], n: int) -> float:
    """CPU seconds per call of ``fn``, over ``n`` calls."""
    start = time.process_time()
    for _ in range(n):
        fn()
    return (time.process_time() - start) / n


def _calls_in(fn: Callable[[], Any], seconds: float = 0.02) -> int:
    """How many calls of ``fn`` take about ``seconds`` of CPU time (at least 1)."""
    fn()
    start, n = time.process_time(), 0
    while time.process_time() - start < seconds:
        fn()
        n += 1
    return max(n, 1)


def _case(spec: ModelSpec) -> tuple[Callable[[], Any], Callable[[], Any], Callable[[], Any], str]:
    """The compute alone, the named run and the auto run of ``spec``'s first example."""
    example = spec.examples[0]
    rung = prepare(spec, example).rung
    values = prepare(spec, example, rung).values
    outputs = spec.scalar_outputs

    def compute() -> Any:
        ctx = RunContext(rung=rung, outputs=outputs, tolerance=0.01, scratch=Scratch())
        return spec.compute(values, ctx)

    return (
        compute,
        lambda: engine.run(spec, example, fidelity=rung),
        lambda: engine.run(spec, example),
        rung,
    )


def measure() -> list[dict[str, Any]]:
    rows: list[dict[str, Any]] = []
    for spec in MODELS:
        if not spec.examples:
            continue
        try:
            compute, named, auto, rung = _case(spec)
        except engine.EngineError:
            continue
        if spec.rung(rung).heavy:
            continue
        n = _calls_in(named)
        shares, autos, times = [], [], []
        for _ in range(ROUNDS):
            c, r, a = _per_call(compute, n), _per_call(named, n), _per_call(auto, n)
            shares.append((r - c) / c)
            autos.append(a / r)
            times.append((c, r, a))
        c, r, a = (statistics.median(t) for t in zip(*times, strict=True))
        share, over = statistics.median(shares), statistics.median(autos)
        timing = f"compute {us(c)}, run named {us(r)}, run auto {us(a)} (CPU time)"
        rows.append(
            {
                "model": spec.name,
                "method": f"run {rung}",
                "case": "engine.run − compute",
                "time_s": r - c,
                "ratio": share,
                "target": "engine.run minus its model's compute ≤ the compute itself",
                "target_ratio": SHARE_TARGET,
                "met": share <= SHARE_TARGET,
                "notes": timing,
            }
        )
        rows.append(
            {
                "model": spec.name,
                "method": f"run auto→{rung}",
                "case": "auto / rung named",
                "time_s": a,
                "ratio": over,
                "target": "a default-auto request ≤ 1.1 × the same with its rung named",
                "target_ratio": AUTO_TARGET,
                "met": over <= AUTO_TARGET,
                "notes": timing,
            }
        )
    return rows


if __name__ == "__main__":
    for row in measure():
        met = "met" if row["met"] else "MISSED"
        print(
            f"{row['model']:<24} {row['case']:<22} ×{row['ratio']:5.2f} "
            f"≤ ×{row['target_ratio']:<4} {met:<6} {row['notes']}"
        )
