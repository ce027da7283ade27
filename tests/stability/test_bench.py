"""The benchmark's own arithmetic and its pipeline, on the toys (figures are not asserted)."""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest

from bench import run as bench
from bench.generic import extremes, reference_rung, relative_errors
from engine import Param, Result, RunContext
from tests.toys import SPRING, TOY


def test_relative_errors_over_common_float_outputs():
    # energy: |26.25 − 25| / 25 = 0.05; inertia 0 vs 0 counts as 0; a bool is never compared;
    # an output missing from either side, or a reference of exactly 0, is skipped
    got = relative_errors(
        TOY,
        {"energy": 26.25, "inertia": 0.0, "fast": True, "ratio": 2.0},
        {"energy": 25.0, "inertia": 0.0, "fast": False, "ratio": 0.0},
    )
    assert got == {"energy": pytest.approx(0.05), "inertia": 0.0}


def test_extremes_nudge_exclusive_bounds_inside():
    angle = TOY.param("angle")  # (0, π/2) exclusive both ends
    lo, hi = extremes(angle)
    assert 0.0 < lo < 1e-8 and math.pi / 2 * (1 - 2e-9) < hi < math.pi / 2
    angle.check(lo), angle.check(hi)
    assert extremes(TOY.param("count")) == (1.0, 100.0)
    assert extremes(
        Param("n", "1", "n", kind="int", minimum=0, maximum=5, exclusive_minimum=True)
    ) == (
        1.0,
        5.0,
    )
    assert extremes(Param("free", "m", "unbounded"), 2.0) == (-2000.0, 2000.0)
    assert extremes(TOY.param("mode")) is None


def test_reference_is_the_most_accurate_applicable_rung():
    # u = 0.01·100/10 = 0.1: every rung applies; exact's 1e-12 is the smallest estimate
    assert reference_rung(SPRING, SPRING.examples[0])[0].name == "exact"
    # u = 1.5: rigid does not apply
    assert [r.name for r, _ in bench.applicable_rungs(SPRING, SPRING.examples[1])] == [
        "exact",
        "simulation",
    ]


def _crash(x: Mapping[str, Any], ctx: RunContext) -> Result:
    raise RuntimeError("a model bug")  # not arithmetic: the runner refuses that with a 422


def test_pipeline_writes_rows_sweeps_and_extras(tmp_path: Path):
    extra = tmp_path / "extra_fake.py"
    extra.write_text(
        "def measure():\n"
        "    return [{'model': 'toy.spring', 'method': 'solve_ivp DOP853', 'case': 'ref',\n"
        "             'time_s': 1e-3, 'error': 1e-7, 'notes': 'baseline'}]\n"
    )
    broken = tmp_path / "extra_broken.py"
    broken.write_text("def measure():\n    raise RuntimeError('no solver')\n")
    crash = dataclasses.replace(SPRING, name="toy.crash", compute=_crash)
    results = bench.collect([SPRING, crash], seconds=0.005, extras=[extra, broken])
    json.dumps(results, allow_nan=False)
    rungs = [r for r in results["rows"] if r["kind"] == "rung"]
    # three examples: all three rungs on the first, exact and simulation on the other two
    assert len(rungs) == 7
    rigid = next(r for r in rungs if r["method"] == "rigid")
    # rigid at u = 0.1: speed off by 1/√(1 − u/2) − 1 = 0.02598, within its estimate u/3
    assert rigid["error"] == pytest.approx(1 / math.sqrt(0.95) - 1, rel=1e-6)
    assert rigid["honest"] is True and rigid["outputs_compared"] == ["peak", "speed", "time"]
    assert all(r["honest"] is None for r in rungs if r["method"] == "exact")
    (baseline,) = [r for r in results["rows"] if r["kind"] == "extra"]
    assert bench.is_baseline(baseline) and baseline["source"] == "extra_fake.py"
    # a model or an extra that crashes is reported and the rest still measured
    failed = [f.split(":")[0] for f in results["failures"]]
    assert failed == ["toy.crash rungs", "toy.crash sweeps", "toy.crash outputs", "extra_broken.py"]
    assert "no solver" in results["failures"][-1]
    swept = {(s["method"], s["points"]) for s in results["sweeps"]}
    assert swept == {("exact", 1_000_000), ("rigid", 200), ("simulation", 200), ("exact", 200)}
    assert {o["output"] for o in results["outputs"]} == {"time", "speed", "peak"}
    assert "rigid" in bench.table(results)
    pytest.importorskip("matplotlib")
    bench.plot(results["rows"], tmp_path / "pareto.png")
    assert (tmp_path / "pareto.png").stat().st_size > 10_000


def test_median_time_repeats_and_batches():
    calls = []
    per_call, reps = bench.median_time(lambda: calls.append(1), seconds=0.01, min_reps=5)
    # warm-up once, then at least five batches; a no-op is batched (≥ 1 ms per batch)
    assert reps >= 5 and len(calls) == reps + 1 and 0.0 < per_call < 1e-3


def test_issue_21_targets_are_printed_beside_the_measured_figures():
    from bench import extra_targets
    from engine.models import get_model

    # the sweep case is one every point of which computes, on the model's array rung
    _, vary, values, rung = extra_targets.sweep_case(get_model("nutrunner.drive"))
    assert values.size == extra_targets.POINTS and rung == "closed_form"
    results = {
        "rows": [
            {
                "model": "nutrunner.drive",
                "method": "sweep closed_form",
                "case": f"2000 pts of {vary}",
                "time_s": 1.1e-3,
                "target_s": 2e-3,
                "met": True,
                "notes": "array path alone 0.015 ms, plain numpy 0.023 ms",
            }
        ],
        "sweeps": [],
        "outputs": [],
        "rungs_order": {},
        "failures": [],
    }
    text = bench.table(results)
    assert "Speed targets: measured against target" in text
    line = next(s for s in text.splitlines() if s.startswith("nutrunner.drive") and "target" in s)
    assert "1.1 ms" in line and "target ≤ 2 ms met" in line and "plain numpy" in line


def test_the_same_payload_floor_reads_the_body_the_no_body_floor_does_not():
    """Issue 21's floors: the same-payload app parses the JSON body (a broken one is its
    422), the no-body app answers without reading it; both answer the payload given."""
    import asyncio

    from bench import extra_service

    payload = {"model": "x", "results": {"a": 1.5}}
    same = extra_service.same_payload_app("/p", payload)
    bare = extra_service.bare_app("/p", payload)

    async def both(body: bytes) -> list[tuple[int, bytes]]:
        return [await extra_service.call(app, "POST", "/p", body) for app in (same, bare)]

    (s_ok, s_answer), (b_ok, b_answer) = asyncio.run(both(b'{"thread": "M12"}'))
    assert s_ok == b_ok == 200 and json.loads(s_answer) == json.loads(b_answer) == payload
    (s_bad, _), (b_bad, _) = asyncio.run(both(b'{"thread": '))
    assert (s_bad, b_bad) == (422, 200)


def test_loadtest_engine_ceiling_times_the_model_and_skips_unknown_ones():
    import importlib.util

    root = Path(__file__).resolve().parents[2]
    spec = importlib.util.spec_from_file_location("loadtest", root / "scripts" / "loadtest.py")
    assert spec is not None and spec.loader is not None
    loadtest = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(loadtest)
    body = {"thread": "M12", "fidelity": "closed_form"}
    ms = loadtest.engine_run_ms("preload.tightening", body, seconds=0.01)
    assert ms is not None and 1e-4 < ms < 50  # a warm closed form: microseconds, not zero
    assert loadtest.engine_run_ms("no.such_model", body) is None
