"""Benchmark: a 10⁴-design simulation study of the striker, time beyond its kernels.

Issue 35's target: a 10⁴-design simulation study of the striker's reference design ±10 %
(power spring rate and preload, roller mass, motor torque; uniform, Monte Carlo) at the
product's default tolerance spends ≤ 10 % beyond its kernels' time. The study runs in
process with the simulation rung named. The compiled kernels
(``striker_cycle._stages_c``: the cycle from lift-off, the logic between the stages'
events with the calls of the cycle kernel ``_advance_c`` and of ``_one_sided_c``, the
one-sided stage 3 with its event loop and contact sets; those two where called alone) are
wrapped for the run by a counter that adds up the CPU time of each call; everything else
(the stages' set-up from the inputs, the runner, validation, the outputs and verdicts, the
summary) is the overhead. A study's looped point keeps no error estimate nor sentences, so
the model makes none (``RunContext.sentences``); its simulation's set-up from the inputs and
the outputs of the inputs alone are made for its chunk at once (``ModelSpec.prepare_points``:
``striker_cycle.cycle_setups``), which the "study" layer counts.
Times are CPU seconds (``time.process_time``): the machine is shared.

``STRIKER_STUDY_POINTS`` sets the study's size (default 10,000);
``python bench/extra_striker_study.py`` prints the figures and the profile's top lines
with ``--profile``.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import engine
from engine.procedures import striker_cycle
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable

MODEL = "impact.rare"
VARIED = ("power_spring_rate", "power_spring_preload", "roller_mass", "motor_torque")
KERNELS = ("_advance_c", "_one_sided_c", "_stages_c")
TARGET_OVERHEAD = 0.10


def study(n: int, seed: int = 3) -> tuple[Study, engine.ModelSpec]:
    """The reference design ±10 % on the four inputs, ``n`` designs, simulation rung."""
    spec = engine.get_model(MODEL)
    ex = dict(spec.examples[0])
    return (
        Study(
            variables=tuple(
                Variable(k, "uniform", low=0.9 * ex[k], high=1.1 * ex[k]) for k in VARIED
            ),
            base={k: v for k, v in ex.items() if k not in VARIED},
            samples=n,
            seed=seed,
            fidelity="simulation",
        ),
        spec,
    )


class _Timed:
    """A compiled function with its calls' CPU time added up."""

    def __init__(self, fn: Any) -> None:
        self.fn = fn
        self.seconds = 0.0
        self.calls = 0

    def __getattr__(self, name: str) -> Any:
        return getattr(self.fn, name)

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        t0 = time.process_time()
        out = self.fn(*args, **kwargs)
        self.seconds += time.process_time() - t0
        self.calls += 1
        return out


@contextmanager
def timed_kernels() -> Iterator[list[_Timed]]:
    """Wrap the striker's kernels for the block; yields the counters."""
    saved = {k: getattr(striker_cycle, k) for k in KERNELS}
    wrapped = [_Timed(saved[k]) for k in KERNELS]
    try:
        for k, w in zip(KERNELS, wrapped, strict=True):
            setattr(striker_cycle, k, w)
        yield wrapped
    finally:
        for k, fn in saved.items():
            setattr(striker_cycle, k, fn)


@contextmanager
def timed_layers() -> Iterator[dict[str, _Timed]]:
    """Wrap the layers around the kernels for the block: the cycle's driver
    (``simulate_cycle`` as the model calls it) and one point's evaluation as the study
    calls it (``run_point``, or ``engine.run`` where a point goes through it); yields their
    counters (each includes what it calls)."""
    from engine.models import rare_impact
    from engine.studies import plan

    layers = {
        "cycle": (rare_impact, "simulate_cycle"),
        "run": (plan, "run"),
        "run_point": (plan, "run_point"),
    }
    saved = {k: getattr(mod, name) for k, (mod, name) in layers.items()}
    timed = {k: _Timed(fn) for k, fn in saved.items()}
    try:
        for k, (mod, name) in layers.items():
            setattr(mod, name, timed[k])
        yield timed
    finally:
        for k, (mod, name) in layers.items():
            setattr(mod, name, saved[k])


def overhead(n: int) -> dict[str, Any]:
    """One in-process study of ``n`` designs: total and kernel CPU seconds, kernel calls."""
    s, spec = study(n)
    run_study(spec, study(64, seed=1)[0])  # load the kernels
    with timed_kernels() as counters:
        t0 = time.process_time()
        result = run_study(spec, s)
        total = time.process_time() - t0
    kernel = sum(c.seconds for c in counters)
    # where the rest goes, in a second run (its timers would weigh on the first's figure)
    with timed_kernels() as again, timed_layers() as layers:
        t0 = time.process_time()
        run_study(spec, s)
        total2 = time.process_time() - t0
    kernel2 = sum(c.seconds for c in again)
    cycle = layers["cycle"].seconds
    one = layers["run"].seconds + layers["run_point"].seconds
    return {
        "total_s": total,
        "kernel_s": kernel,
        "calls": sum(c.calls for c in counters),
        "overhead": total / kernel - 1.0,
        "rungs": result.summary["rungs"],
        # per design [s]: the cycle driver's Python, the run and model adapter's, the study's
        "layers_s": {
            "driver": (cycle - kernel2) / n,
            "run": (one - cycle) / n,
            "study": (total2 - one) / n,
        },
    }


def measure() -> list[dict[str, Any]]:
    n = int(os.environ.get("STRIKER_STUDY_POINTS", "10000"))
    f = overhead(n)
    return [
        {
            "model": MODEL,
            "method": "study_sim_overhead",
            "case": f"{n}-design simulation study, beyond kernels",
            "time_s": f["total_s"] / n,
            # the share beyond the kernels, as the target states it (the page prints a
            # ratio under a "%" goal as a percentage): total / kernels - 1, not the quotient
            "ratio": f["overhead"],
            "share": True,
            "target_ratio": TARGET_OVERHEAD,
            "met": f["overhead"] <= TARGET_OVERHEAD,
            "error": None,
            "notes": f"{f['total_s']:.2f} s CPU in all, kernels {f['kernel_s']:.2f} s "
            f"({f['calls']} calls): {f['overhead'] * 100:.0f} % beyond the kernels "
            f"(target ≤ {TARGET_OVERHEAD * 100:.0f} %); load {os.getloadavg()[0]:.1f}; "
            f"rungs {f['rungs']}; per design beyond the kernels' "
            f"{f['kernel_s'] / n * 1e6:.0f} µs: "
            + ", ".join(f"{k} {v * 1e6:.0f} µs" for k, v in f["layers_s"].items())
            + f" (the cycle's Python driver around its {f['calls'] / n:.0f} kernel call(s); "
            "a point's run with the model's outputs and verdicts (a study keeps no error "
            "estimate); the study's loop with its validation)",
        }
    ]


def _profile(n: int, show: Callable[[str], None] = print) -> None:
    import cProfile
    import io
    import pstats

    s, spec = study(n)
    run_study(spec, study(64, seed=1)[0])
    prof = cProfile.Profile()
    prof.runcall(run_study, spec, s)
    out = io.StringIO()
    pstats.Stats(prof, stream=out).sort_stats("tottime").print_stats(30)
    show(out.getvalue())


if __name__ == "__main__":
    if "--profile" in sys.argv:
        _profile(int(os.environ.get("STRIKER_STUDY_POINTS", "10000")))
    else:
        for row in measure():
            print(f"{row['method']}: {row['time_s'] * 1e6:.1f} µs/design  {row['notes']}")
