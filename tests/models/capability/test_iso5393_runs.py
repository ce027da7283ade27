"""tool.capability with ISO 5393 hard-joint and soft-joint runs, and its array path.

The two runs are pooled into one sample; the expected values are the statistics of the
runs' values put together, summed by hand in each test.
"""

from __future__ import annotations

import math
import timeit

import numpy as np
import pytest

from engine import InputOutOfRange, run, sweep
from engine.models.capability import CAPABILITY
from tests.pins import pin

MODEL = "tool.capability"
HARD = [50.0, 50.4, 50.2, 50.2]  # mean 50.2; squared deviations 0.04 + 0.04 = 0.08
SOFT = [49.5, 49.7, 49.6, 49.6]  # mean 49.6; squared deviations 0.01 + 0.01 = 0.02


def test_sample_runs_pool_into_one_sample() -> None:
    r = run(
        CAPABILITY,
        {
            "hard_joint_samples": HARD,
            "soft_joint_samples": SOFT,
            "nominal_torque": 50.0,
            "relative_tolerance": 0.05,
        },
    )
    # all eight values: mean (200.8 + 198.4)/8 = 49.9; squared deviations about 49.9:
    # hard 0.01 + 0.25 + 0.09 + 0.09 = 0.44, soft 0.16 + 0.04 + 0.09 + 0.09 = 0.38
    s = math.sqrt((0.44 + 0.38) / 7)
    pin("tool.capability", "mean_torque", r.results["mean_torque"], 49.9, rel=1e-12)
    pin("tool.capability", "torque_sd", r.results["torque_sd"], s, rel=1e-12)
    pin("tool.capability", "hard_mean_torque", r.results["hard_mean_torque"], 50.2, rel=1e-12)
    pin("tool.capability", "soft_mean_torque", r.results["soft_mean_torque"], 49.6, rel=1e-12)
    pin(
        "tool.capability",
        "hard_torque_sd",
        r.results["hard_torque_sd"],
        math.sqrt(0.08 / 3),
        rel=1e-12,
    )
    pin(
        "tool.capability",
        "soft_torque_sd",
        r.results["soft_torque_sd"],
        math.sqrt(0.02 / 3),
        rel=1e-12,
    )
    pin("tool.capability", "mean_shift", r.results["mean_shift"], -0.6, rel=1e-12)
    pin("tool.capability", "torque_scatter", r.results["torque_scatter"], 3 * s / 49.9, rel=1e-12)
    pin("tool.capability", "sample_count", r.results["sample_count"], 8)
    pin("tool.capability", "min_torque", r.results["min_torque"], 49.5)
    pin("tool.capability", "max_torque", r.results["max_torque"], 50.4)
    # tolerance 47.5…52.5: Cm = 5/(6s); the lower limit is nearer: (49.9 − 47.5)/(3s)
    pin(
        "tool.capability",
        "capability_index",
        r.results["capability_index"],
        5.0 / (6 * s),
        rel=1e-12,
    )
    pin(
        "tool.capability",
        "critical_capability_index",
        r.results["critical_capability_index"],
        2.4 / (3 * s),
        rel=1e-12,
    )
    assert any("ISO 5393 runs pooled" in n for n in r.notes)


def test_run_means_give_the_same_pooled_statistics_as_their_samples() -> None:
    # runs of 25 on each joint, given as mean and s: the pooled s from the sums of squares
    n = 25
    hard_mean, hard_sd, soft_mean, soft_sd = 50.2, 0.35, 49.6, 0.45
    r = run(CAPABILITY, {**dict(CAPABILITY.examples[3])})
    # (n−1)s² of each run plus the shift's n·n/(2n)·Δ² = 12.5 · 0.36 = 4.5, over 2n − 1 = 49
    ss = 24 * 0.35**2 + 24 * 0.45**2 + 12.5 * 0.6**2
    s = math.sqrt(ss / 49)
    pin("tool.capability", "mean_torque", r.results["mean_torque"], 49.9, rel=1e-12)
    pin("tool.capability", "torque_sd", r.results["torque_sd"], s, rel=1e-12)
    pin("tool.capability", "sample_count", r.results["sample_count"], 2 * n)
    pin("tool.capability", "mean_shift", r.results["mean_shift"], soft_mean - hard_mean, rel=1e-12)
    pin("tool.capability", "hard_torque_sd", r.results["hard_torque_sd"], hard_sd)
    pin("tool.capability", "soft_torque_sd", r.results["soft_torque_sd"], soft_sd)
    # 25 + 25 = 50 reaches the machine test's 50 values
    assert {c.name: c.ok for c in r.checks}["sample_size"] is True


def test_a_mean_shift_widens_the_pooled_scatter() -> None:
    base = {"hard_torque_sd": 0.4, "soft_torque_sd": 0.4, "sample_count": 25}
    tol = {"nominal_torque": 50.0, "relative_tolerance": 0.05}
    same = run(CAPABILITY, {**base, **tol, "hard_mean_torque": 50.0, "soft_mean_torque": 50.0})
    shifted = run(CAPABILITY, {**base, **tol, "hard_mean_torque": 50.5, "soft_mean_torque": 49.5})
    # no shift: s² = 48 · 0.16 / 49; a shift of 1 N·m adds 12.5 · 1 / 49
    pin(
        "tool.capability",
        "torque_sd",
        same.results["torque_sd"],
        math.sqrt(48 * 0.16 / 49),
        rel=1e-12,
    )
    pin(
        "tool.capability",
        "torque_sd",
        shifted.results["torque_sd"],
        math.sqrt((48 * 0.16 + 12.5) / 49),
        rel=1e-12,
    )
    assert shifted.results["capability_index"] < same.results["capability_index"]


@pytest.mark.parametrize(
    ("inputs", "field"),
    [
        ({"hard_joint_samples": HARD}, "soft_joint_samples"),
        ({"hard_mean_torque": 50.0, "hard_torque_sd": 0.3}, "soft_mean_torque"),
        (
            {
                "hard_mean_torque": 50.0,
                "hard_torque_sd": 0.3,
                "soft_mean_torque": 50.0,
                "soft_torque_sd": 0.3,
            },
            "sample_count",
        ),
        ({"hard_joint_samples": HARD, "soft_mean_torque": 49.0}, "soft_mean_torque"),
        (
            {"hard_joint_samples": HARD, "soft_joint_samples": SOFT, "mean_torque": 5.0},
            "mean_torque",
        ),
    ],
)
def test_incomplete_or_mixed_runs_are_refused_by_name(inputs: dict, field: str) -> None:
    with pytest.raises(InputOutOfRange) as err:
        run(CAPABILITY, {**inputs, "nominal_torque": 50.0})
    assert err.value.field == field


def test_the_array_path_gives_the_loop_numbers_and_is_fast() -> None:
    base = dict(CAPABILITY.examples[0])
    values = np.linspace(0.75, 0.85, 2000)
    swept = sweep(CAPABILITY, base, "mean_torque", values)
    for j in (0, 777, 1999):
        one = run(CAPABILITY, {**base, "mean_torque": float(values[j])})
        for name in ("critical_capability_index", "outside_ppm", "mean_offset", "capable"):
            assert swept.results[name][j] == pytest.approx(one.results[name], rel=1e-12), name
    # 57 ms a sweep of 2,000 points when it looped; the array path takes about 1 ms
    best = min(
        timeit.repeat(lambda: sweep(CAPABILITY, base, "mean_torque", values), number=1, repeat=5)
    )
    assert best < 0.02


def test_a_sweep_over_a_run_mean_is_vectorised_and_matches_single_runs() -> None:
    base = dict(CAPABILITY.examples[3])
    values = np.linspace(49.0, 51.0, 101)
    swept = sweep(CAPABILITY, base, "soft_mean_torque", values)
    for j in (0, 50, 100):
        one = run(CAPABILITY, {**base, "soft_mean_torque": float(values[j])})
        for name in ("torque_sd", "mean_shift", "critical_capability_index", "torque_scatter"):
            assert swept.results[name][j] == pytest.approx(one.results[name], rel=1e-12), name
