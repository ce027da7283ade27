"""``GET /jobs/{id}?wait=``: the answer comes when the job ends, not at the next poll."""

from __future__ import annotations

import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

import engine
import service.studies
from service import create_app
from service.studies import MAX_WAIT_S

CLUTCH = engine.get_model("clutch.ball")
BODY = {
    "base": {k: v for k, v in CLUTCH.examples[0].items() if k != "flank_friction"},
    "variables": [{"name": "flank_friction", "low": 0, "high": 0.1}],
    "samples": 64,
    "outputs": ["torque_limit"],
}


@pytest.fixture(scope="module")
def app() -> Iterator[tuple[TestClient, list[threading.Event]]]:
    """An app whose studies run in process and finish only once the test's event is set."""
    gate: list[threading.Event] = []
    real = service.studies.run_study

    def held_study(*args: Any, **kwargs: Any) -> Any:
        assert gate[-1].wait(30), "the test never let the study finish"
        return real(*args, **kwargs)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(service.studies, "run_study", held_study)
        mp.setenv("STUDY_INPROCESS_POINTS", "100000")
        with TestClient(create_app(models=[CLUTCH])) as client:  # the model it studies
            yield client, gate


@pytest.fixture()
def held(
    app: tuple[TestClient, list[threading.Event]],
) -> Iterator[tuple[TestClient, threading.Event]]:
    client, gate = app
    gate.append(threading.Event())
    yield client, gate[-1]
    gate[-1].set()


def test_a_wait_answers_when_the_job_ends(held: tuple[TestClient, threading.Event]) -> None:
    client, release = held
    r = client.post("/api/v1/clutch/ball/study", json=BODY)
    assert r.status_code == 202, r.text
    where = r.headers["location"]
    assert client.get(where).json()["state"] in ("queued", "running")
    # the study ends 0.3 s from now; a wait of 20 s answers then, with the result
    threading.Timer(0.3, release.set).start()
    start = time.monotonic()
    body = client.get(where, params={"wait": 20}).json()
    took = time.monotonic() - start
    assert body["state"] == "done", body
    assert body["result"]["outputs"]["torque_limit"]["count"] == 64
    assert 0.25 <= took < 10.0  # woken by the end, not by the wait running out
    # the same answer as a plain poll of the finished job
    plain = client.get(where).json()
    assert {k: v for k, v in plain.items() if k != "progress"} == {
        k: v for k, v in body.items() if k != "progress"
    }


def test_a_wait_that_runs_out_answers_the_job_as_it_stands(
    held: tuple[TestClient, threading.Event],
) -> None:
    client, release = held
    where = client.post("/api/v1/clutch/ball/study", json=BODY).headers["location"]
    start = time.monotonic()
    body = client.get(where, params={"wait": 0.4}).json()
    assert 0.35 <= time.monotonic() - start < 10.0
    assert body["state"] in ("queued", "running") and "result" not in body
    release.set()
    assert client.get(where, params={"wait": 20}).json()["state"] == "done"
    # a finished job answers at once, whatever the wait
    start = time.monotonic()
    assert client.get(where, params={"wait": 20}).json()["state"] == "done"
    assert time.monotonic() - start < 5.0


def test_a_wait_out_of_range_is_refused_naming_it(
    held: tuple[TestClient, threading.Event],
) -> None:
    client, _ = held
    for bad in (-1, MAX_WAIT_S + 1, "nan", "inf"):
        r = client.get("/api/v1/jobs/nope", params={"wait": bad})
        assert r.status_code == 422, (bad, r.text)
        assert "wait" in r.text
    start = time.monotonic()
    assert client.get("/api/v1/jobs/nope", params={"wait": 20}).status_code == 404
    assert time.monotonic() - start < 5.0  # no job to wait for: answered at once
