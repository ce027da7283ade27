"""Benchmark of blow.joint's simulation rung: compiled RK4 against scipy's solve_ivp.

``measure()`` returns one row per (method, case): time per blow and its error in
peak torque and nut rotation against a tight reference (solve_ivp DOP853,
rtol 1e-12, one solve per stick/slip phase with terminal events). Methods:

* ``fast``: :func:`engine.physics.blow.simulate_blow` (numba RK4, 200 steps per shortest
  period, events bisected on RK4 sub-steps);
* ``solve_ivp DOP853 rtol=…``: :func:`engine.physics.blow.simulate_blow_reference`.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench.timing import median_wall_time
from engine.physics.blow import BlowProblem, simulate_blow, simulate_blow_reference

MODEL = "blow.joint"

#: Wall seconds after which a case's repeated calls stop (three timed at least).
BUDGET_S = 3.0


def _cases() -> dict[str, tuple[BlowProblem, float]]:
    return {
        "two flywheels (free struck side)": (
            BlowProblem(21.07, 63.21, 203.4, 150 * math.pi / 30, 0.0),
            0.0,
        ),
        "nut-runner on ISO 5393 hard joint, b = 1.1": (
            BlowProblem(0.0297, 1e-3, 2.32e4, 93.8, 600 / math.radians(30), 1.1),
            60.0,
        ),
        "stick-slip, b = 1.3": (BlowProblem(0.03, 1e-3, 2e4, 90.0, 1000.0, 1.3), 60.0),
    }


def _row(method: str, case: str, time_s: float, error: float, notes: str) -> dict[str, Any]:
    return {
        "model": MODEL,
        "method": method,
        "case": case,
        "time_s": time_s,
        "error": error,
        "notes": notes,
    }


def _err(peak: float, rot: float, ref: tuple[float, float, int]) -> float:
    e = abs(peak / ref[0] - 1.0)
    if ref[1] > 0:
        e = max(e, abs(rot / ref[1] - 1.0))
    return e


def measure() -> list[dict[str, Any]]:
    """Rows {model, method, case, time_s, error, notes} for the bench runner."""
    rows: list[dict[str, Any]] = []
    for case, (p, t0) in _cases().items():
        ref = simulate_blow_reference(p, t0, rtol=1e-12)
        simulate_blow(p, t0)  # compile or load the cache before timing
        out = simulate_blow(p, t0)
        rows.append(
            _row(
                "fast",
                case,
                median_wall_time(lambda p=p, t0=t0: simulate_blow(p, t0), 300, BUDGET_S),
                _err(out.peak_torque, out.rotation, ref),
                f"numba RK4, {out.steps} steps",
            )
        )
        for rtol in (1e-6, 1e-8, 1e-10):
            res = simulate_blow_reference(p, t0, rtol=rtol)
            rows.append(
                _row(
                    f"solve_ivp DOP853 rtol={rtol:g}",
                    case,
                    median_wall_time(
                        lambda p=p, t0=t0, r=rtol: simulate_blow_reference(p, t0, rtol=r),
                        7,
                        BUDGET_S,
                    ),
                    _err(res[0], res[1], ref),
                    f"{res[2]} RHS evaluations",
                )
            )
    return rows


def summary(rows: list[dict[str, Any]]) -> list[str]:
    """Speed-up of ``fast`` over the fastest solve_ivp run at least as accurate."""
    lines = []
    for case in dict.fromkeys(r["case"] for r in rows):
        fast = next(r for r in rows if r["case"] == case and r["method"] == "fast")
        rivals = [r for r in rows if r["case"] == case and r["method"].startswith("solve_ivp")]
        matched = [r for r in rivals if r["error"] <= max(fast["error"], 1e-6)]
        best = min(matched or rivals, key=lambda r: r["time_s"] if matched else r["error"])
        lines.append(
            f"{case}: fast {fast['time_s'] * 1e6:.1f} µs at error {fast['error']:.1e}; "
            f"{best['method']} {best['time_s'] * 1e3:.2f} ms at {best['error']:.1e}: "
            f"{best['time_s'] / fast['time_s']:.0f}x faster"
        )
    return lines


if __name__ == "__main__":
    table = measure()
    for row in table:
        print(
            f"{row['case']:44} {row['method']:28} {row['time_s'] * 1e3:10.4f} ms "
            f"{row['error']:9.1e}"
        )
    print()
    for line in summary(table):
        print(line)
