"""Studies over HTTP: 202 and a job, progress, the result, raw points, cancel, limits."""

from __future__ import annotations

import time
from typing import Any

import pytest
from fastapi.testclient import TestClient

import engine
from service import create_app
from service.studies import StudySettings

CLUTCH = engine.get_model("clutch.ball")
BASE = {k: v for k, v in CLUTCH.examples[0].items() if k != "flank_friction"}
RARE = engine.get_model("impact.rare")


def _wait(client: TestClient, job: str, seconds: float = 30.0) -> dict[str, Any]:
    deadline = time.monotonic() + seconds
    while True:
        body = client.get(f"/api/v1/jobs/{job}").json()
        if body["state"] not in ("queued", "running"):
            return body
        assert time.monotonic() < deadline, body
        time.sleep(0.02)


@pytest.fixture()
def app_client(monkeypatch: pytest.MonkeyPatch) -> TestClient:
    monkeypatch.setenv("STUDY_PER_CLIENT", "1")
    monkeypatch.setenv("STUDY_INPROCESS_POINTS", "100000")  # no Dask in these tests
    # the routes of the two models these tests study (a whole app builds every model's
    # request models, a second of CPU, and warms every model up)
    with TestClient(create_app(models=[CLUTCH, RARE])) as c:
        yield c


def test_a_study_runs_as_a_job_and_gives_statistics_and_points(app_client: TestClient) -> None:
    r = app_client.post(
        "/api/v1/clutch/ball/study",
        json={
            "base": {**BASE, "ball_circle_diameter": "50 mm"},
            "variables": [{"name": "flank_friction", "low": 0, "high": "0.1"}],
            "samples": 400,
            "seed": 3,
            "outputs": ["torque_limit"],
            "keep_points": True,
        },
    )
    assert r.status_code == 202, r.text
    assert r.headers["location"] == f"/api/v1/jobs/{r.json()['job']}"
    body = _wait(app_client, r.json()["job"])
    assert body["state"] == "done"
    assert body["progress"]["done"] == body["progress"]["total"] == 400
    stats = body["result"]["outputs"]["torque_limit"]
    lo = engine.run(CLUTCH, {**BASE, "flank_friction": 0.0}).results["torque_limit"]
    hi = engine.run(CLUTCH, {**BASE, "flank_friction": 0.1}).results["torque_limit"]
    assert lo <= stats["min"] < stats["mean"] < stats["max"] <= hi
    assert body["result"]["sensitivity"]["indices"]["torque_limit"]["flank_friction"] > 0.99
    csv = app_client.get(body["links"]["points_csv"])
    assert csv.status_code == 200
    lines = csv.text.strip().splitlines()
    assert lines[0] == "flank_friction,torque_limit"
    assert len(lines) == 401


def test_a_study_is_refused_at_once_naming_the_field(app_client: TestClient) -> None:
    r = app_client.post(
        "/api/v1/clutch/ball/study",
        json={"base": BASE, "variables": [{"name": "flank_friction", "low": -1, "high": 0.1}]},
    )
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "flank_friction"
    r = app_client.post(
        "/api/v1/clutch/ball/study",
        json={"base": BASE, "variables": [{"name": "flank_friction", "low": "1 mm", "high": 1}]},
    )
    assert r.status_code == 422
    r = app_client.post("/api/v1/clutch/ball/study", json={"base": BASE, "variables": []})
    assert r.status_code == 422
    assert app_client.get("/api/v1/jobs/nope").status_code == 404


def test_cancel_frees_the_client_slot(app_client: TestClient) -> None:
    rare = engine.get_model("impact.rare")
    ex = dict(rare.examples[0])
    body = {
        "base": {k: v for k, v in ex.items() if k != "motor_torque"},
        "variables": [
            {
                "name": "motor_torque",
                "low": 0.9 * ex["motor_torque"],
                "high": 1.1 * ex["motor_torque"],
            }
        ],
        "samples": 50_000,
        "fidelity": "simulation",
    }
    first = app_client.post("/api/v1/impact/rare/study", json=body)
    assert first.status_code == 202
    busy = app_client.post("/api/v1/impact/rare/study", json=body)
    assert busy.status_code == 503  # one study per client in this test
    assert busy.headers["retry-after"]
    job = first.json()["job"]
    start = time.monotonic()
    assert app_client.delete(f"/api/v1/jobs/{job}").status_code == 200
    final = _wait(app_client, job, seconds=5)
    assert final["state"] == "cancelled"
    assert time.monotonic() - start < 2.0
    assert final["progress"]["done"] < 50_000
    again = app_client.post("/api/v1/impact/rare/study", json={**body, "samples": 10})
    assert again.status_code == 202
    assert _wait(app_client, again.json()["job"])["state"] == "done"


def test_study_settings_have_embedded_defaults() -> None:
    s = StudySettings()
    assert s.max_points == 2_000_000 and s.dask_scheduler is None


def test_a_queued_study_that_is_cancelled_never_runs_and_holds_its_place() -> None:
    import engine as eng
    from engine.studies.plan import Study, Variable
    from service.studies import Job, Studies

    rare = eng.get_model("impact.rare")
    ex = dict(rare.examples[0])
    long = Study(
        variables=(Variable("motor_torque", low=4.5, high=5.5),),
        base={k: v for k, v in ex.items() if k != "motor_torque"},
        samples=20_000,
        fidelity="simulation",
    )
    studies = Studies(StudySettings(max_active=2, per_client=5, inprocess_points=10**6))
    try:
        first = studies.submit(rare, long, "a", False)
        # a job cancelled before a thread reaches it never runs; the store says cancelled
        queued = Job("queued", rare.name, "b", 20_000, False)
        studies.store.put(queued.row(studies.owner))
        studies.jobs[queued.id] = queued
        assert studies.cancel(queued.id)["state"] == "cancelled"
        assert queued.state == "cancelled" and queued.cancel.is_set()
        assert queued.active  # its thread's place is held until the pool drops it
        studies._work(queued, rare, long)
        assert not queued.active and queued.started is None and queued.done == 0
        assert studies.get(queued.id)["state"] == "cancelled"
        studies.cancel(first.id)
        deadline = time.monotonic() + 10
        while first.active:
            assert time.monotonic() < deadline
            time.sleep(0.01)
        assert first.state == "cancelled" and first.done < 20_000
        assert studies.get(first.id)["state"] == "cancelled"
        # pruning keeps at most 64 finished jobs, the oldest go first
        for i in range(100):
            job = Job(f"old{i}", "x", "c", 1, False, state="done", settled=True)
            job.finished = time.time() - 100 + i
            studies.store.put(job.row("a process"))
        studies._prune()
        kept = {i for i in range(100) if studies.store.get(f"old{i}") is not None}
        # the 100 old ones and the two above: the newest 64 stay
        assert kept == set(range(38, 100))
    finally:
        studies.shutdown()


def test_a_submitted_study_draws_its_points_once(
    app_client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The service plans a study to refuse a bad one at once; the job runs that plan and
    does not draw the points again (about 11 % of a 10^6-point study's time)."""
    import engine.studies.execute
    import service.studies

    calls: list[int] = []
    real = service.studies.plan

    def counted(spec: Any, study: Any) -> Any:
        calls.append(study.samples)
        return real(spec, study)

    monkeypatch.setattr(service.studies, "plan", counted)
    monkeypatch.setattr(engine.studies.execute, "plan", counted)
    r = app_client.post(
        "/api/v1/clutch/ball/study",
        json={
            "base": BASE,
            "variables": [{"name": "flank_friction", "low": 0, "high": "0.1"}],
            "samples": 64,
            "outputs": ["torque_limit"],
        },
    )
    assert r.status_code == 202, r.text
    body = _wait(app_client, r.json()["job"])
    assert body["state"] == "done"
    assert body["progress"]["total"] == 64
    assert calls == [64]
