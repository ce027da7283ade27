"""A study whose chunks never come back fails within a bound, and frees its place.

Issue 34's full-scale figures (bench/shopfloor.py): a study sat in "evaluating" at 0 points
for 527 s with no Dask worker process left (three services starting clusters at load 17):
the study's budget was checked only when a chunk came back. The watchdog
(:meth:`service.studies.Studies.watch`, every ``WATCHDOG_S``) fails it past its budget, or
after ``NO_WORKERS_S`` on a cluster without a worker, with an error naming the cause.
"""

from __future__ import annotations

import re
import threading
import time
from collections.abc import Iterator
from typing import Any, ClassVar

import pytest
from fastapi.testclient import TestClient

import service.studies
from service import create_app
from service.studies import BUDGET_GRACE_S, WATCHDOG_S, StudySettings
from tests.toys import TOY

pytestmark = pytest.mark.slow

URL = "/api/v1/toy/disc/study"
STUDY = {
    "base": {"diameter": 0.3},
    "variables": [{"name": "mass", "low": 1, "high": 2}],
    "samples": 50,
    "fidelity": "exact",
    "outputs": ["energy"],
}


class NeverReturns:
    """An executor whose chunks never come back (until the study is cancelled)."""

    released: ClassVar[list[bool]] = []

    def map(self, calls: list[Any], cancel: threading.Event, budget: Any = None) -> Iterator[Any]:
        cancel.wait(60.0)
        self.released.append(cancel.is_set())
        return
        yield


def _settle(client: TestClient, job_id: str, bound_s: float) -> tuple[dict[str, Any], float]:
    start = time.monotonic()
    while True:
        body = client.get(f"/api/v1/jobs/{job_id}").json()
        if body["state"] not in ("queued", "running"):
            return body, time.monotonic() - start
        assert time.monotonic() - start < bound_s, body
        time.sleep(0.05)


def test_a_study_whose_chunks_never_return_fails_at_its_budget(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Budget 1 s, one study per client: the study fails by budget + grace + one watchdog
    period (+ slack for a loaded machine), the executor is told to stop, and the client's
    next study is admitted at once (its quota freed)."""
    monkeypatch.setattr(service.studies, "InProcess", NeverReturns)
    NeverReturns.released.clear()
    settings = StudySettings(budget_s=1.0, per_client=1, inprocess_points=100_000)
    with TestClient(create_app(models=[TOY], study_settings=settings)) as client:
        first = client.post(URL, json=STUDY)
        assert first.status_code == 202
        body, waited = _settle(client, first.json()["job"], 30.0)
        assert body["state"] == "failed"
        assert body["error"]["type"] == "budget_exceeded"
        assert "STUDY_BUDGET_S" in body["error"]["msg"]
        assert "0 of 50 points" in body["error"]["msg"]
        assert waited <= 1.0 + BUDGET_GRACE_S + WATCHDOG_S + 5.0
        second = client.post(URL, json={**STUDY, "seed": 2})
        assert second.status_code == 202, second.text  # per_client=1: the place was freed
        assert client.get("/healthz").status_code == 200
        deadline = time.monotonic() + 5
        while not NeverReturns.released and time.monotonic() < deadline:
            time.sleep(0.02)
        assert NeverReturns.released[:1] == [True]  # the thread was let go by the cancel


def test_a_study_on_a_cluster_without_workers_fails_naming_the_cause(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The local cluster's only worker removed before the study: its chunks wait for ever.
    With NO_WORKERS_S = 2 it fails within about that, says why, leaks no address, and the
    service answers meanwhile."""
    monkeypatch.setattr(service.studies, "NO_WORKERS_S", 2.0)
    settings = StudySettings(inprocess_points=0, inprocess_s=0, dask_workers=1, per_client=1)
    with TestClient(create_app(models=[TOY], study_settings=settings)) as client:
        studies = client.app.state.studies  # type: ignore[attr-defined]
        dask = studies.dask()
        dask.client()
        assert dask.workers() == 1
        dask._cluster.scale(0)
        deadline = time.monotonic() + 30
        while dask.workers() and time.monotonic() < deadline:
            time.sleep(0.1)
        assert dask.workers() == 0
        job_id = client.post(URL, json=STUDY).json()["job"]
        body, waited = _settle(client, job_id, 30.0)
        assert body["state"] == "failed", body
        assert body["error"]["type"] == "no_workers"
        assert "no worker for 2 s" in body["error"]["msg"]
        assert not re.search(r"\d+\.\d+\.\d+\.\d+|tls://|tcp://", body["error"]["msg"])
        assert 2.0 <= waited <= 2.0 + 2 * WATCHDOG_S + 8.0
        assert client.get("/healthz").status_code == 200
        assert client.post(URL, json={**STUDY, "seed": 3}).status_code == 202
