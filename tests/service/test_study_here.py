"""A large study on the array path that its first chunk shows cheap runs in the job thread:
no cluster started, the values of the in-process study."""

from __future__ import annotations

from pathlib import Path

from fastapi.testclient import TestClient

import engine
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable
from service import create_app
from service.studies import StudySettings


def test_a_cheap_large_study_needs_no_cluster(tmp_path: Path) -> None:
    spec = engine.get_model("preload.tightening")
    base = {k: v for k, v in spec.examples[0].items() if k != "thread_friction"}
    body = {
        "base": base,
        "variables": [{"name": "thread_friction", "low": 0.08, "high": 0.16}],
        "samples": 150_000,
        "seed": 11,
        "fidelity": "closed_form",
    }
    # 1,000 points at most without the timing; the default 1 s for the whole study here
    app = create_app(study_settings=StudySettings(store=str(tmp_path), inprocess_points=1000))
    with TestClient(app) as client:
        posted = client.post("/api/v1/preload/tightening/study", json=body)
        assert posted.status_code == 202, posted.text
        done = client.get(f"/api/v1/jobs/{posted.json()['job']}", params={"wait": 30}).json()
        assert done["state"] == "done", done
        assert app.state.studies._dask is None  # the cluster was never asked for
    alone = run_study(
        spec,
        Study(
            variables=(Variable("thread_friction", "uniform", low=0.08, high=0.16),),
            base=base,
            samples=150_000,
            seed=11,
            fidelity="closed_form",
        ),
    )
    got = done["result"]["outputs"]["assembly_preload"]
    want = alone.summary["outputs"]["assembly_preload"]
    assert got["quantiles"] == want["quantiles"]
    assert got["mean"] == want["mean"]
