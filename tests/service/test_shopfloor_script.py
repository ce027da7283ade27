"""bench/shopfloor.py runs end to end at a small scale and its figures hold the issue's
targets: a refused submission costs next to nothing, a DELETE leaves the workers idle at
once, every job lookup is answered with two workers and after a restart."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_shopfloor_script_smoke(tmp_path: Path) -> None:
    out = tmp_path / "shopfloor.json"
    args = ["--scale", "0.01", "--only", "refused,delete,lookups", "--out", str(out)]
    done = subprocess.run(
        [sys.executable, "-m", "bench.shopfloor", *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    figures = json.loads(out.read_text())
    refused = figures["refused"]
    # eight submissions of 20,000 points over the client's limit: 503 before any drawing
    assert refused["statuses"] == [503] and refused["retry_after"] == ["5"]
    assert refused["service_cpu_s"] < 1.0 and refused["rss_added_mb"] < 50
    delete = figures["delete"]
    assert delete["delete_status"] == 200 and delete["state"] == "cancelled"
    assert delete["delete_to_idle_s"] is not None and delete["delete_to_idle_s"] < 10
    lookups = figures["lookups"]
    assert lookups["workers2_answered_200"] == lookups["workers2_lookups"] == 10 * lookups["jobs"]
    assert lookups["restart_done"] == lookups["jobs"] and lookups["restart_csv_same"] is True
    assert all(isinstance(figures[k]["load"], float) for k in ("refused", "delete", "lookups"))
