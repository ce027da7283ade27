"""The load-test script runs end to end on a tiny budget and writes its results file."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_loadtest_script_smoke(tmp_path: Path) -> None:
    out = tmp_path / "loadtest.json"
    args = ["--requests", "40", "--seconds", "3", "--concurrency", "2", "--out", str(out)]
    done = subprocess.run(
        [sys.executable, "scripts/loadtest.py", *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        # every model's closed form runs between two /healthz runs (19 models, up to 3 s a
        # run): about 100 s on an idle machine, past 120 s on a loaded one
        timeout=400,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    report = json.loads(out.read_text())
    endpoints = report["endpoints"]
    assert {"healthz", "closed_form", "simulation"} <= set(endpoints)
    for r in endpoints.values():
        assert r["requests"] == 40 and r["statuses"] == {"200": 40}
        assert 0 < r["p50_ms"] <= r["p99_ms"] <= r["max_ms"]
        assert r["requests_per_s"] > 0
    assert set(report["targets"]) >= {"throughput_target_met", "p99_target_met"}


def test_loadtest_refuses_non_loopback_urls() -> None:
    done = subprocess.run(
        [sys.executable, "scripts/loadtest.py", "--url", "http://example.com:8000"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode != 0 and "loopback" in done.stderr
