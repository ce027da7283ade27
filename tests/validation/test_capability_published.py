"""tool.capability against a published Cm/Cmk worked example ([Danikor], docs/sources.md).

A tightening tool set to 0.8 N·m ± 10 % (0.72…0.88 N·m) gave 25 readings with mean
0.81 N·m and standard deviation 0.011 N·m; the page prints Cm = (0.88 − 0.72)/(6 × 0.011)
= 2.42. Its Cmk line breaks off in the copy read: Cmk is recomputed here from the page's
own formula and numbers, min(0.88 − 0.81, 0.81 − 0.72)/(3 × 0.011) = 0.07/0.033.
"""

from __future__ import annotations

import math

from engine import get_model, run
from tests.pins import pin

MODEL = "tool.capability"
DANIKOR = {
    "mean_torque": 0.81,
    "torque_sd": 0.011,
    "sample_count": 25,
    "nominal_torque": 0.8,
    "relative_tolerance": 0.1,
}


def test_the_published_example_is_the_models_reference_case() -> None:
    assert dict(get_model(MODEL).examples[0]) == DANIKOR


def test_danikor_cm_and_cmk() -> None:
    r = run(get_model(MODEL), DANIKOR)
    pin(
        "tool.capability",
        "capability_index",
        round(float(r.results["capability_index"] or 0.0), 2),
        2.42,
        abs=1e-12,
    )
    pin(
        "tool.capability",
        "capability_index",
        r.results["capability_index"],
        0.16 / 0.066,
        rel=1e-12,
    )
    pin(
        "tool.capability",
        "critical_capability_index",
        r.results["critical_capability_index"],
        0.07 / 0.033,
        rel=1e-12,
    )
    pin("tool.capability", "lower_limit", r.results["lower_limit"], 0.72, rel=1e-12)
    pin("tool.capability", "upper_limit", r.results["upper_limit"], 0.88, rel=1e-12)
    assert r.results["index_names"] == "Cm/Cmk"


def test_danikor_verdict_counts_the_run_short_of_fifty() -> None:
    """Both indices pass 1.67, but 25 readings are half the 50 of a VDI/VDE 2645-2 run."""
    r = run(get_model(MODEL), DANIKOR)
    checks = {c.name: c.ok for c in r.checks}
    assert checks == {
        "capability_index": True,
        "critical_capability_index": True,
        "sample_size": False,
    }
    assert r.results["capable"] is False
    assert any("only 25 values" in w for w in r.warnings)
    pin("tool.capability", "minimum_sample_count", r.results["minimum_sample_count"], 50)
    pin("tool.capability", "sample_count", r.results["sample_count"], 25)


def test_danikor_normal_tails_in_ppm() -> None:
    """Below L: z = 0.09/0.011 = 8.18; above U: z = 0.07/0.011 = 6.36; Φ(−z) by erfc."""
    r = run(get_model(MODEL), DANIKOR)
    below = 0.5 * math.erfc(0.09 / 0.011 / math.sqrt(2))
    above = 0.5 * math.erfc(0.07 / 0.011 / math.sqrt(2))
    pin("tool.capability", "outside_ppm", r.results["outside_ppm"], (below + above) * 1e6, rel=1e-9)
    ppm = r.results["outside_ppm"]
    assert isinstance(ppm, float) and 9.8e-5 < ppm < 9.9e-5  # about 1e-10: Cmk 2.12 is 6.36 σ
