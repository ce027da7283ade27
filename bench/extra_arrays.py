"""Benchmark: inputs that used to fall off the array path, per point against the array cost.

``measure()`` returns one row per case: the CPU time per point of an
:func:`engine.sweep` over the case's input, against the same model's array
path per point on a sweep of the same length (an input that has always been on
it), and the ratio beside its target (≤ 5×). Cases:

* clutch.ball_setting with a disc stack (target torque swept) against the
  helical spring of its first example;
* the as-built helical setting (clutch.ball_setting's second example) swept
  over its coils, its ball lift and its free length, against the same design
  swept over its drive power;
* nutrunner.drive with an induction motor curve (its closed form's estimate
  compares the constant-power time with the curve's) against the curveless drive.

CPU time (``time.process_time``), medians of interleaved rounds: the machine
is shared. The cost per point is measured on 10,000-point sweeps: a sweep of 2,000 points
(measured too, in the same rounds, and shown beside) counts a fixed cost of each sweep in
its points. The disc stack's is about 1 ms a sweep (its characteristic made once for the
root searches), 0.5 µs of every point of a 2,000-point sweep against its 0.6 µs a point:
there it measured ×3.5 run alone and ×5.1 in a loaded bench, the model's array path
0.24-0.37 µs a point. Each row says its cost a point at 2,000 points too.
Run alone: ``PYTHONPATH=. python -m bench.extra_arrays``.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Callable
from typing import Any

import numpy as np

import engine
from bench.timing import cpu_time
from engine.models.clutch import BALL_CLUTCH_SETTING
from engine.models.nutrunner import NUTRUNNER_DRIVE

POINTS = 10_000
#: The smaller sweep measured beside, for the fixed cost of a sweep.
SMALL = 2_000
ROUNDS = 9
TARGET_RATIO = 5.0

#: A disc-spring limiter (two discs 40/20.4 × 1, h0 = 2 mm, in series) set for a torque.
DISC_SETTING: dict[str, Any] = {
    "target_torque": 60.0,
    "ball_circle_diameter": 0.05,
    "ball_count": 6,
    "ball_diameter": 0.005,
    "groove_angle": math.radians(45.0),
    "flank_friction": 0.1,
    "face_friction": 0.01,
    "spring_type": "disc",
    "disc_outer_diameter": 0.04,
    "disc_inner_diameter": 0.0204,
    "disc_thickness": 0.001,
    "disc_cone_height": 0.002,
    "disc_series": 2,
    "ball_lift": 0.0004,
}

Case = tuple[str, Any, dict[str, Any], str, float, float]


def _cases() -> list[tuple[str, Case, Case]]:
    """(name, the case, its reference on the array path): spec, base, input, low, high."""
    setting = BALL_CLUTCH_SETTING
    helical = dict(setting.examples[0])
    built = dict(setting.examples[1])
    reference = ("as built, drive power", setting, built, "drive_power", 300.0, 450.0)
    nut = NUTRUNNER_DRIVE
    return [
        (
            "disc stack, target torque",
            ("disc", setting, DISC_SETTING, "target_torque", 40.0, 80.0),
            ("helical, target torque", setting, helical, "target_torque", 0.4, 0.6),
        ),
        (
            "as built, active coils",
            ("coils", setting, built, "spring_active_coils", 6.0, 10.0),
            reference,
        ),
        ("as built, ball lift", ("lift", setting, built, "ball_lift", 0.0015, 0.0025), reference),
        (
            "as built, free length",
            ("free", setting, built, "spring_free_length", 0.08, 0.1),
            reference,
        ),
        (
            "induction curve, power",
            ("curve", nut, dict(nut.examples[1]), "motor_power", 1000.0, 1200.0),
            ("no curve, power", nut, dict(nut.examples[0]), "motor_power", 1000.0, 1200.0),
        ),
    ]


def _sweep(case: Case, points: int = POINTS) -> Callable[[], Any]:
    _, spec, base, vary, low, high = case
    values = np.linspace(low, high, points).tolist()
    return lambda: engine.sweep(spec, base, vary, values, budget_s=None)


def measure() -> list[dict[str, Any]]:
    rows = []
    for name, case, reference in _cases():
        runs = [_sweep(case), _sweep(reference), _sweep(case, SMALL), _sweep(reference, SMALL)]
        for run in runs:
            run()  # warm-up: imports, caches
        times: list[list[float]] = [[], [], [], []]
        for _ in range(ROUNDS):  # interleaved, so a busy moment hits each
            for run, kept in zip(runs, times, strict=True):
                kept.append(cpu_time(run))
        big, big_ref, small, small_ref = times
        ratio = statistics.median(t / b for t, b in zip(big, big_ref, strict=True))
        small_ratio = statistics.median(t / b for t, b in zip(small, small_ref, strict=True))
        per_point, base_point = statistics.median(big) / POINTS, statistics.median(big_ref) / POINTS
        small_point = statistics.median(small) / SMALL
        rows.append(
            {
                "model": case[1].name,
                "method": "sweep closed_form",
                "case": name,
                "time_s": per_point,
                "ratio": ratio,
                "target": f"≤ {TARGET_RATIO:g}× the same model's array path per point",
                "target_ratio": TARGET_RATIO,
                "met": ratio <= TARGET_RATIO,
                "notes": (
                    f"{per_point * 1e6:.3g} µs a point against {base_point * 1e6:.3g} µs "
                    f"({reference[0]}), {POINTS:,} points, CPU time, median of {ROUNDS} "
                    f"rounds; at {SMALL:,} points {small_point * 1e6:.3g} µs a point, "
                    f"×{small_ratio:.2f}"
                ),
            }
        )
    return rows


if __name__ == "__main__":
    for row in measure():
        print(f"{row['model']:<22} {row['case']:<26} ×{row['ratio']:8.2f}  {row['notes']}")
