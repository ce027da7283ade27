"""Studies that cannot fill memory: quotas before drawing, keep_points honoured, DELETE frees.

Scaled-down reproductions of issue 34's findings: eight refused 2,000,000-point submissions
cost 56 s of CPU and 5.6 GB because every one drew its points before the quota said no; a
finished study kept its raw values whatever ``keep_points`` said; DELETE freed nothing; an
unknown fidelity was accepted and then failed; a job's error showed a Dask worker's address.
"""

from __future__ import annotations

import gc
import time
import weakref
from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

import service.studies
from engine.studies.plan import Study, Variable, plan, study_size
from service import create_app
from service.studies import Job, Studies, StudySettings
from tests.toys import TOY

URL = "/api/v1/toy/disc/study"
SMALL = {
    "base": {"diameter": 0.3},
    "variables": [{"name": "mass", "low": 1, "high": 2}],
    "samples": 50,
    "fidelity": "exact",
    "outputs": ["energy"],
}


@pytest.fixture()
def setup() -> Iterator[tuple[TestClient, Studies]]:
    settings = StudySettings(inprocess_points=100_000, per_client=1, max_active=4)
    with TestClient(create_app(models=[TOY], study_settings=settings)) as client:
        yield client, client.app.state.studies  # type: ignore[attr-defined]


def _settled(client: TestClient, job_id: str) -> dict[str, Any]:
    deadline = time.monotonic() + 30
    while True:
        job = client.get(f"/api/v1/jobs/{job_id}").json()
        if job["state"] not in ("queued", "running"):
            return job
        assert time.monotonic() < deadline, job
        time.sleep(0.02)


@pytest.mark.parametrize(
    ("method", "samples", "expected"),
    [
        ("monte_carlo", 1000, 1000),
        ("lhs", 77, 77),
        ("sobol", 1000, 1024 * (2 + 2)),  # 2^10 base samples, k = 2: A, B and two AB_i
        ("sobol", 1024, 1024 * (2 + 2)),
        ("grid", 0, 5 * 3),
    ],
)
def test_the_size_is_known_before_drawing_and_is_what_plan_draws(
    method: str, samples: int, expected: int
) -> None:
    study = Study(
        variables=(
            Variable("mass", low=1.0, high=2.0, num=5),
            Variable("speed", low=10.0, high=20.0, num=3),
        ),
        base={"diameter": 0.3},
        method=method,
        samples=samples or 1000,
    )
    assert study_size(TOY, study) == expected
    assert plan(TOY, study).n_points == expected


def test_refused_submissions_draw_nothing(
    setup: tuple[TestClient, Studies], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Eight 2,000,000-point submissions beyond the client's quota: 503 each, no point drawn."""
    client, studies = setup
    busy = Job("busy", TOY.name, "testclient", 10, False, state="running")
    studies.store.put(busy.row("another process"))  # the client's one study is running
    drawn: list[int] = []
    real = service.studies.plan

    def counted(spec: Any, study: Any) -> Any:
        drawn.append(study.samples)
        return real(spec, study)

    monkeypatch.setattr(service.studies, "plan", counted)
    big = {**SMALL, "samples": 2_000_000}
    start = time.perf_counter()
    for _ in range(8):
        r = client.post(URL, json=big)
        assert r.status_code == 503, r.text
        assert r.headers["retry-after"] == "5"
    assert drawn == []
    # drawing 2·10^6 points once takes seconds; eight refusals without drawing take far less
    assert time.perf_counter() - start < 2.0
    assert [j["id"] for j in studies.store.active()] == ["busy"]


def test_a_study_refused_after_drawing_frees_its_place(setup: tuple[TestClient, Studies]) -> None:
    client, studies = setup
    r = client.post(URL, json={**SMALL, "base": {"diameter": -1.0}})  # the base is checked
    assert r.status_code == 422, r.text  # with the first drawn point: after the quota
    assert r.json()["detail"][0]["field"] == "diameter"
    assert studies.store.active() == []
    ok = client.post(URL, json=SMALL)  # one study per client here: the place is free
    assert ok.status_code == 202, ok.text


def test_an_unknown_fidelity_is_refused_at_submit(setup: tuple[TestClient, Studies]) -> None:
    client, studies = setup
    r = client.post(URL, json={**SMALL, "fidelity": "psychic"})
    assert r.status_code == 422, r.text
    (item,) = r.json()["detail"]
    assert item["field"] == "fidelity"
    assert "'rough', 'exact', 'auto'" in item["msg"]
    assert studies.store.active() == []
    for rung in ("rough", "exact", "auto"):
        r = client.post(URL, json={**SMALL, "fidelity": rung})
        assert r.status_code == 202, r.text
        assert _settled(client, r.json()["job"])["state"] == "done"


def test_raw_values_leave_memory_unless_kept(
    setup: tuple[TestClient, Studies], monkeypatch: pytest.MonkeyPatch
) -> None:
    client, studies = setup
    merged: list[weakref.ref[Any]] = []
    real = service.studies.run_study

    def watched(*args: Any, **kwargs: Any) -> Any:
        run = real(*args, **kwargs)
        merged.append(weakref.ref(run.merged))
        return run

    monkeypatch.setattr(service.studies, "run_study", watched)
    r = client.post(URL, json=SMALL)
    job = _settled(client, r.json()["job"])
    assert job["state"] == "done" and job["result"]["points"] == 50
    assert "points_csv" not in job["links"]
    gc.collect()
    assert merged[0]() is None  # summarised, then dropped: keep_points was not asked

    kept = client.post(URL, json={**SMALL, "keep_points": True})
    job = _settled(client, kept.json()["job"])
    gc.collect()
    assert merged[1]() is None  # kept on disk, not in memory
    stored = studies.store.points_path(job["job"])
    assert stored.is_file()
    csv = client.get(job["links"]["points_csv"])
    assert csv.status_code == 200 and len(csv.text.splitlines()) == 1 + 50
    # DELETE removes a finished job with its data, its file included
    d = client.delete(f"/api/v1/jobs/{job['job']}")
    assert d.status_code == 200
    assert d.json()["deleted"] is True and d.json()["state"] == "done"
    assert client.get(f"/api/v1/jobs/{job['job']}").status_code == 404
    assert client.get(f"/api/v1/jobs/{job['job']}/points.csv").status_code == 404
    assert client.delete(f"/api/v1/jobs/{job['job']}").status_code == 404
    assert studies.store.get(job["job"]) is None and not stored.exists()


def test_a_job_error_does_not_show_a_worker_address(
    setup: tuple[TestClient, Studies], monkeypatch: pytest.MonkeyPatch
) -> None:
    client, _ = setup

    def lost(*args: Any, **kwargs: Any) -> Any:
        raise OSError(
            "Timed out trying to connect to tcp://10.20.30.40:8786 after 10 s "
            "(worker 'tls://[fe80::1]:40123', nanny 192.168.1.7:39001)"
        )

    monkeypatch.setattr(service.studies, "run_study", lost)
    r = client.post(URL, json=SMALL)
    job = _settled(client, r.json()["job"])
    assert job["state"] == "failed"
    msg = job["error"]["msg"]
    assert msg.startswith("OSError: Timed out trying to connect to <worker> after 10 s")
    for leak in ("10.20.30.40", "8786", "fe80", "192.168", "tcp://", "tls://"):
        assert leak not in msg


def test_readyz_reports_running_studies(setup: tuple[TestClient, Studies]) -> None:
    client, studies = setup
    idle = client.get("/readyz").json()["studies"]
    assert idle == {"running": 0, "queued": 0, "active": 0, "max_active": 4, "per_client": 1}
    studies.jobs["busy"] = Job("busy", TOY.name, "x", 10, False, state="running")
    studies.jobs["next"] = Job("next", TOY.name, "y", 10, False)
    for job in (*studies.jobs.values(), Job("there", TOY.name, "z", 10, False)):
        studies.store.put(job.row("a process"))  # one more runs in another process
    r = client.get("/readyz")
    assert r.status_code == 200  # studies run on their own threads: reported, not gated
    assert r.json()["studies"] == {**idle, "running": 1, "queued": 1, "active": 3}
    studies.jobs.clear()
