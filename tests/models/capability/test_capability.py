"""tool.capability: statistics from samples, the tolerance forms, the checks and refusals.

Expected values are worked out by hand in each test (sums written out), not by the
engine's functions.
"""

from __future__ import annotations

import math

import pytest

from engine import InputOutOfRange, get_model, run
from engine.models.capability import CAPABILITY, RUN_OF_50
from tests.pins import pin

MODEL = "tool.capability"
#: Ten readings around 20 N·m: sum 200.0, squared deviations sum 0.40 (by hand below).
TEN = [19.8, 20.1, 20.0, 19.9, 20.2, 20.0, 20.1, 19.9, 20.0, 20.0]


def test_ten_samples_by_hand() -> None:
    # deviations: -0.2 0.1 0 -0.1 0.2 0 0.1 -0.1 0 0 -> squares 0.04+0.01+0.01+0.04+0.01+0.01 = 0.12
    s = math.sqrt(0.12 / 9)
    r = run(CAPABILITY, {"torque_samples": TEN, "lower_limit": 19.0, "upper_limit": 21.5})
    pin("tool.capability", "mean_torque", r.results["mean_torque"], 20.0, rel=1e-12)
    pin("tool.capability", "torque_sd", r.results["torque_sd"], s, rel=1e-12)
    pin(
        "tool.capability",
        "capability_index",
        r.results["capability_index"],
        2.5 / (6 * s),
        rel=1e-12,
    )
    # the lower limit is nearer: (20 − 19)/(3s)
    pin(
        "tool.capability",
        "critical_capability_index",
        r.results["critical_capability_index"],
        1.0 / (3 * s),
        rel=1e-12,
    )
    pin("tool.capability", "min_torque", r.results["min_torque"], 19.8)
    pin("tool.capability", "max_torque", r.results["max_torque"], 20.2)
    # middle 20.25, half tolerance 1.25: (20 − 20.25)/1.25
    pin("tool.capability", "mean_offset", r.results["mean_offset"], -0.2, rel=1e-12)
    pin("tool.capability", "sample_count", r.results["sample_count"], 10)
    assert r.results["capable"] is False  # 10 < 50
    assert {c.name: c.ok for c in r.checks}["samples_within_limits"] is True


def test_a_uniform_run_of_fifty() -> None:
    """RUN_OF_50 holds 50 + 0.9 (k − 24.5)/24.5 for k = 0…49 (rounded to 0.001 N·m):
    mean 50, s = (0.9/24.5)·√(50·51/12) (the variance of 0…49 with divisor n − 1)."""
    assert sorted(RUN_OF_50)[0] == 49.1 and sorted(RUN_OF_50)[-1] == 50.9
    s = 0.9 / 24.5 * math.sqrt(50 * 51 / 12)
    r = run(
        CAPABILITY,
        {"torque_samples": RUN_OF_50, "nominal_torque": 50.0, "relative_tolerance": 0.05},
    )
    pin("tool.capability", "mean_torque", r.results["mean_torque"], 50.0, rel=1e-6)
    pin("tool.capability", "torque_sd", r.results["torque_sd"], s, rel=1e-4)
    pin(
        "tool.capability",
        "capability_index",
        r.results["capability_index"],
        5.0 / (6 * s),
        rel=1e-4,
    )
    assert r.results["capable"] is False  # Cm 1.56 < 1.67
    r = run(
        CAPABILITY,
        {"torque_samples": RUN_OF_50, "nominal_torque": 50.0, "relative_tolerance": 0.06},
    )
    assert r.results["capable"] is True  # Cm = 6/(6·0.5355) = 1.87, n = 50
    pin("tool.capability", "required_index", r.results["required_index"], 1.67)


def test_process_study_names_cp_cpk_and_needs_125() -> None:
    r = run(
        CAPABILITY,
        {
            "mean_torque": 81.0,
            "torque_sd": 1.5,
            "sample_count": 124,
            "lower_limit": 72.0,
            "upper_limit": 88.0,
            "study": "process",
        },
    )
    assert r.results["index_names"] == "Cp/Cpk"
    pin("tool.capability", "minimum_sample_count", r.results["minimum_sample_count"], 125)
    pin("tool.capability", "capability_index", r.results["capability_index"], 16.0 / 9.0, rel=1e-12)
    pin(
        "tool.capability",
        "critical_capability_index",
        r.results["critical_capability_index"],
        7.0 / 4.5,
        rel=1e-12,
    )
    assert {c.name: c.ok for c in r.checks} == {
        "capability_index": True,
        "critical_capability_index": False,
        "sample_size": False,
    }
    assert "re-centre" in next(c.detail for c in r.checks if c.name == "critical_capability_index")


def test_centred_cp_one_leaves_2700_ppm() -> None:
    """Cp = Cpk = 1: U − L = 6s, both tails at 3σ: 2 Φ(−3) = 0.0026998 (normal tables)."""
    r = run(
        CAPABILITY, {"mean_torque": 10.0, "torque_sd": 1.0, "lower_limit": 7.0, "upper_limit": 13.0}
    )
    pin("tool.capability", "outside_ppm", r.results["outside_ppm"], 2699.796, rel=1e-6)
    pin("tool.capability", "capability_index", r.results["capability_index"], 1.0, rel=1e-12)
    assert r.results["sample_count"] is None
    assert {c.name: c.ok for c in r.checks}["sample_size"] is False


def test_samples_outside_the_tolerance_fail_their_check() -> None:
    r = run(
        CAPABILITY, {"torque_samples": [10.0, 10.2, 12.5], "lower_limit": 9.0, "upper_limit": 12.0}
    )
    check = next(c for c in r.checks if c.name == "samples_within_limits")
    assert not check.ok and check.detail.startswith("1 of 3")


@pytest.mark.parametrize(
    ("inputs", "field", "fragment"),
    [
        ({"nominal_torque": 10.0}, "torque_samples", "give torque_samples"),
        ({"mean_torque": 10.0, "nominal_torque": 10.0}, "torque_sd", "torque_sd is missing"),
        (
            {
                "torque_samples": [1.0, 2.0],
                "mean_torque": 1.5,
                "torque_sd": 0.5,
                "nominal_torque": 2.0,
            },
            "mean_torque",
            "not both",
        ),
        (
            {"torque_samples": [5.0, 5.0, 5.0], "nominal_torque": 5.0},
            "torque_samples",
            "all 3 values are equal",
        ),
        ({"torque_samples": [5.0, 5.1]}, "nominal_torque", "give the tolerance"),
        (
            {"torque_samples": [5.0, 5.1], "lower_limit": 4.0},
            "upper_limit",
            "upper_limit is required",
        ),
        (
            {"torque_samples": [5.0, 5.1], "lower_limit": 6.0, "upper_limit": 4.0},
            "lower_limit",
            "below upper_limit",
        ),
        ({"torque_samples": [5.0], "nominal_torque": 5.0}, "torque_samples", "has 1 value"),
        (
            {"torque_samples": [5.0, -1.0], "nominal_torque": 5.0},
            "torque_samples",
            "torque_samples[1] = -1",
        ),
        (
            {"torque_samples": [5.0, math.nan], "nominal_torque": 5.0},
            "torque_samples",
            "torque_samples[1] = nan",
        ),
        ({"torque_samples": "5 6 7", "nominal_torque": 5.0}, "torque_samples", "a str"),
    ],
)
def test_refusals_name_the_field(inputs: dict, field: str, fragment: str) -> None:
    with pytest.raises(InputOutOfRange) as info:
        run(get_model(MODEL), inputs)
    assert info.value.field == field
    assert fragment in info.value.message


def test_sample_refusal_states_the_allowed_range() -> None:
    with pytest.raises(InputOutOfRange) as info:
        run(CAPABILITY, {"torque_samples": [5.0, 2e5], "nominal_torque": 5.0})
    assert info.value.message == (
        "torque_samples[1] = 200000 N*m is not allowed: must be a list of 2 to 10000 finite "
        "numbers ≥ 0 N*m and ≤ 100000 N*m"
    )
    assert info.value.context["index"] == 1


def test_ten_thousand_samples_are_taken_and_one_more_refused() -> None:
    many = [20.0 + 0.001 * (i % 7) for i in range(10_000)]
    r = run(CAPABILITY, {"torque_samples": many, "nominal_torque": 20.0})
    assert r.results["sample_count"] == 10_000
    with pytest.raises(InputOutOfRange, match="has 10001 values"):
        run(CAPABILITY, {"torque_samples": [*many, 20.0], "nominal_torque": 20.0})
