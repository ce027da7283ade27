"""Benchmark of the rare-impact wrench's stage 1 (issue 6): time per solve against achieved error.

``measure()`` returns one row per (method, case) for the shared bench runner;
``python bench/extra_rare_impact.py`` prints the table. Methods:

* ``fast``: :func:`engine.rare_impact_sim.stage1_fast` (compiled fixed-step
  RK4, 200 steps per oscillation period, Hermite graze detection), timed
  with its set-up (``stage1_problem``), i.e. a whole stage-1 solve;
* ``solve_ivp DOP853 rtol=…``: scipy's solver on the same equation, terminal
  event at h1, ``max_step`` = period/20 (without that bound it can skip the
  first crossing; the ``default steps`` rows show it);
* ``closed_form``: the quasi-static release speed and spin-up time.

The error is max(|Δω/ω|, |Δt/t|) of release speed and spin-up time against a
very tight reference (DOP853, rtol 1e-13, max_step = period/100). Times are
medians per solve on this machine.
"""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN, _release_speed_of
from engine.rare_impact import quasi_static_release_error, spin_up_time
from engine.rare_impact_sim import (
    STEPS_PER_PERIOD,
    stage1_fast,
    stage1_problem,
    stage1_reference,
)

MODEL = "impact.rare"


def _cases() -> dict[str, dict[str, Any]]:
    ref = RARE_IMPACT.validate(REFERENCE_DESIGN)[0]
    linear = RARE_IMPACT.validate({**REFERENCE_DESIGN, "motor_no_load_speed": 400.0})[0]
    return {"reference (constant torque)": ref, "reference, linear motor 3820 rpm": linear}


GRAZE_SHORTFALL = 1e-6


def _graze_case() -> tuple[Any, float, float]:
    """A design whose first crossing of h1 is a graze, and its exact crossing.

    With a motor whose no-load speed is just above the release speed the
    half-coupling's lift-off oscillation outlasts the drift of its equilibrium, so
    z1 rises and falls back; h1 is put GRAZE_SHORTFALL (relative) under the first
    peak (the stage-1 motion does not depend on h1). The reference crossing is the
    root, just before that peak, of a tight DOP853 solution's dense output:
    event location, which only compares step ends, misses it.
    """
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    x = RARE_IMPACT.validate({**REFERENCE_DESIGN, "motor_no_load_speed": 240.0})[0]
    p = stage1_problem(x)

    def rhs(t: float, y: Any) -> list[float]:
        return [y[1], p.accel(t, y[0])]

    def top(t: float, y: Any) -> float:
        return float(y[1])

    top.direction = -1.0  # type: ignore[attr-defined]
    sol = solve_ivp(rhs, (p.t_liftoff, p.t_end), [0.0, 0.0], method="DOP853", rtol=1e-13,
                    atol=1e-16, events=top, dense_output=True, max_step=p.step * 5)  # fmt: skip
    t_pk = next(t for t in sol.t_events[0] if t > p.t_liftoff + p.step)
    level = float(sol.sol(t_pk)[0]) * (1 - GRAZE_SHORTFALL)
    quarter = 0.25 * p.step * STEPS_PER_PERIOD
    t_ref = brentq(lambda t: sol.sol(t)[0] - level, t_pk - quarter, t_pk, xtol=1e-16)
    graze = type(p)(**{**p.__dict__, "h1": level})
    return graze, float(t_ref), float(graze.omega(t_ref))


def _median_time(fn: Callable[[], Any], repeats: int, budget_s: float = 3.0) -> float:
    times = []
    start = time.perf_counter()
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
        if time.perf_counter() - start > budget_s and len(times) >= 3:
            break
    return statistics.median(times)


def _error(t: float, w: float, t_ref: float, w_ref: float) -> float:
    return max(abs(t / t_ref - 1.0), abs(w / w_ref - 1.0))


def _row(method: str, case: str, time_s: float, error: float, notes: str) -> dict[str, Any]:
    return {
        "model": MODEL,
        "method": method,
        "case": case,
        "time_s": time_s,
        "error": error,
        "notes": notes,
    }


def measure() -> list[dict[str, Any]]:
    """Rows {model, method, case, time_s, error, notes} for the bench runner."""
    rows: list[dict[str, Any]] = []
    cases: dict[str, tuple[Any, Any, float, float]] = {}
    for name, x in _cases().items():
        p = stage1_problem(x)
        t_ref, w_ref, _ = stage1_reference(p, rtol=1e-13, max_step_fraction=0.01)
        cases[name] = (x, p, t_ref, w_ref)
    graze, t_g, w_g = _graze_case()
    cases[f"graze (h1 = first peak - {GRAZE_SHORTFALL:g})"] = (None, graze, t_g, w_g)
    stage1_fast(graze)  # compile or load the cache before timing
    for case, (x, p, t_ref, w_ref) in cases.items():

        def fast(p: Any = p, x: Any = x) -> Any:
            return stage1_fast(stage1_problem(x) if x is not None else p)

        r = fast()
        rows.append(
            _row(
                "fast",
                case,
                _median_time(fast, 300),
                _error(r.t_release, r.w_release, t_ref, w_ref),
                f"numba RK4, {STEPS_PER_PERIOD} steps/period, {r.steps} steps, set-up included",
            )
        )
        for bounded in (True, False):
            frac = 0.05 if bounded else None
            for rtol in (1e-6, 1e-8, 1e-10):
                res = stage1_reference(p, rtol=rtol, max_step_fraction=frac)
                t_ivp = _median_time(
                    lambda p=p, rtol=rtol, frac=frac: stage1_reference(
                        p, rtol=rtol, max_step_fraction=frac
                    ),
                    7,
                )
                rows.append(
                    _row(
                        f"solve_ivp DOP853 rtol={rtol:g}"
                        + (" max_step=T/20" if bounded else " default steps"),
                        case,
                        t_ivp,
                        _error(res[0], res[1], t_ref, w_ref),
                        f"{res[2]} RHS evaluations",
                    )
                )
        if x is None:
            continue

        def closed(x: Any = x) -> tuple[float, float]:
            w = float(_release_speed_of(x))
            t = spin_up_time(x["flywheel_inertia"], x["motor_torque"], w, x["motor_no_load_speed"])
            return w, t

        w_cf, t_cf = closed()
        rows.append(
            _row(
                "closed_form",
                case,
                _median_time(closed, 2000),
                _error(t_cf, w_cf, t_ref, w_ref),
                "quasi-static release speed [002, after eq. 4] and analytic spin-up; "
                f"a-priori error estimate {max(quasi_static_release_error(x)):.1e}",
            )
        )
    return rows


def summary(rows: list[dict[str, Any]]) -> list[str]:
    """Speed-up of ``fast`` over the fastest DOP853 run that meets the 1e-6 target, per case."""
    lines = []
    for case in dict.fromkeys(r["case"] for r in rows):
        fast = next(r for r in rows if r["case"] == case and r["method"] == "fast")
        rivals = [
            r
            for r in rows
            if r["case"] == case and r["method"].startswith("solve_ivp") and r["error"] <= 1e-6
        ]
        head = f"{case}: fast {fast['time_s'] * 1e3:.3f} ms at error {fast['error']:.1e}"
        if rivals:
            best = min(rivals, key=lambda r: r["time_s"])
            lines.append(
                f"{head}; fastest DOP853 within 1e-6: {best['method']} "
                f"{best['time_s'] * 1e3:.1f} ms at {best['error']:.1e}: "
                f"{best['time_s'] / fast['time_s']:.0f}x faster"
            )
        else:
            lines.append(f"{head}; no DOP853 run reached 1e-6 (all missed the first crossing)")
    return lines


if __name__ == "__main__":
    table = measure()
    print(f"{'case':36} {'method':40} {'time/solve':>12} {'error':>9}")
    for row in table:
        ms = row["time_s"] * 1e3
        print(f"{row['case']:36} {row['method']:40} {ms:10.4f} ms {row['error']:9.1e}")
    print()
    for line in summary(table):
        print(line)
