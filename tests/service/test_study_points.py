"""A study's raw points: the Parquet download holds the CSV's numbers, nulls and units.

``GET /api/v1/jobs/{id}/points.parquet`` beside ``points.csv``: the same columns (inputs,
then outputs, SI), the same numbers to the last bit, null where the CSV cell is empty (a
refused point), each column's unit in the schema, and the same refusals for a job that is
unknown, not finished, or run without ``keep_points``.
"""

from __future__ import annotations

import csv
import io
import json
import math
import time
from collections.abc import Iterator
from typing import Any

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient

from service.studies import PARQUET, Job, Studies, StudySettings, study_router
from tests.toys import TOY

MASS, SPEED = 2.0, 50.0


@pytest.fixture()
def setup() -> Iterator[tuple[TestClient, Studies]]:
    studies = Studies(StudySettings(inprocess_points=100_000, per_client=5, max_active=2))
    app = FastAPI()
    app.include_router(study_router([TOY], studies))
    with TestClient(app) as client:
        yield client, studies
    studies.shutdown()


def _done(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    r = client.post("/api/v1/toy/disc/study", json=body)
    assert r.status_code == 202, r.text
    deadline = time.monotonic() + 30
    while True:
        job = client.get(f"/api/v1/jobs/{r.json()['job']}").json()
        if job["state"] not in ("queued", "running"):
            assert job["state"] == "done", job
            return job
        assert time.monotonic() < deadline
        time.sleep(0.02)


def _csv(client: TestClient, job: dict[str, Any]) -> tuple[list[str], list[list[str]]]:
    r = client.get(job["links"]["points_csv"])
    assert r.status_code == 200
    header, *rows = list(csv.reader(io.StringIO(r.text)))
    return header, rows


def _parquet(client: TestClient, job: dict[str, Any]) -> pa.Table:
    r = client.get(job["links"]["points_parquet"])
    assert r.status_code == 200
    assert r.headers["content-type"] == PARQUET
    assert r.headers["content-disposition"] == f'attachment; filename="study-{job["job"]}.parquet"'
    return pq.read_table(io.BytesIO(r.content))


def test_a_grid_with_refused_points_gives_the_csv_numbers_and_nulls(
    setup: tuple[TestClient, Studies],
) -> None:
    client, _ = setup
    # toy.disc's array path refuses discs over 5 m (NaN): diameters 6..9 m are refused
    job = _done(
        client,
        {
            "base": {"mass": MASS, "speed": SPEED},
            "variables": [{"name": "diameter", "low": "1000 mm", "high": 9, "num": 9}],
            "method": "grid",
            "fidelity": "exact",
            "outputs": ["energy"],
            "keep_points": True,
        },
    )
    assert job["result"]["refused"] == 4
    header, rows = _csv(client, job)
    table = _parquet(client, job)
    assert table.column_names == header == ["diameter", "energy"]
    assert table.num_rows == len(rows) == 9
    assert table.schema.field("diameter").type == pa.float64()
    d = table.column("diameter").to_pylist()
    energy = table.column("energy").to_pylist()
    assert d == [float(k) for k in range(1, 10)]
    # T = m D² ω² / 16 for D ≤ 5 m; null (an empty CSV cell) where refused
    assert energy[:5] == pytest.approx([MASS * k**2 * SPEED**2 / 16 for k in range(1, 6)])
    assert energy[5:] == [None] * 4
    assert table.column("energy").null_count == 4
    assert [r[1] for r in rows[5:]] == [""] * 4
    # a reader that turns nulls into NaN (numpy, pandas) sees NaN for the refused points
    as_numpy = table.column("energy").to_numpy(zero_copy_only=False)
    assert np.isnan(as_numpy[5:]).all() and np.isfinite(as_numpy[:5]).all()
    # units: per field and in the schema, as the summary states them (SI)
    assert table.schema.field("diameter").metadata == {b"unit": b"m"}
    assert table.schema.field("energy").metadata == {b"unit": b"J"}
    meta = table.schema.metadata
    assert json.loads(meta[b"units"]) == {"diameter": "m", "energy": "J"}
    assert meta[b"model"] == b"toy.disc" and meta[b"job"] == job["job"].encode()


def test_a_monte_carlo_round_trips_bit_for_bit(setup: tuple[TestClient, Studies]) -> None:
    client, _ = setup
    job = _done(
        client,
        {
            "base": {"diameter": 0.3},
            "variables": [
                {"name": "mass", "distribution": "normal", "mean": 2, "sd": 0.1},
                {"name": "speed", "low": "100 rpm", "high": "3000 rpm"},
            ],
            "samples": 300,
            "seed": 7,
            "fidelity": "exact",
            "outputs": ["energy"],
            "keep_points": True,
        },
    )
    header, rows = _csv(client, job)
    table = _parquet(client, job)
    assert table.column_names == header == ["mass", "speed", "energy"]
    for i, name in enumerate(header):
        from_csv = [float(r[i]) for r in rows]  # the CSV writes repr(): exact
        assert table.column(name).to_pylist() == from_csv
    mass, speed, energy = (np.array(table.column(n).to_pylist()) for n in header)
    np.testing.assert_allclose(energy, mass * 0.3**2 / 8 * speed**2 / 2, rtol=1e-14)
    # the summary's extremes are rows of the file
    top = job["result"]["extremes"]["energy"]["max"]
    k = int(np.argmax(energy))
    assert top["value"] == energy[k] and top["inputs"] == {"mass": mass[k], "speed": speed[k]}
    # the CSV's and the file's speeds are SI (rad/s), drawn between 100 and 3000 rpm
    assert 100 * math.pi / 30 <= speed.min() < speed.max() <= 3000 * math.pi / 30


def test_no_points_is_refused_as_the_csv_route_refuses_it(
    setup: tuple[TestClient, Studies],
) -> None:
    client, studies = setup

    def both(job_id: str) -> tuple[int, Any]:
        csv_r = client.get(f"/api/v1/jobs/{job_id}/points.csv")
        pq_r = client.get(f"/api/v1/jobs/{job_id}/points.parquet")
        assert (pq_r.status_code, pq_r.json()) == (csv_r.status_code, csv_r.json())
        return pq_r.status_code, pq_r.json()["detail"]

    assert both("nope") == (404, "no job 'nope'")
    # a study still running: no points yet
    running = Job("running", TOY.name, "testclient", 10, keep_points=True, state="running")
    studies.store.put(running.row("a process"))
    status, detail = both("running")
    assert status == 404 and "not done" in detail
    # a finished study run without keep_points: no links, no points
    job = _done(
        client,
        {
            "base": {"diameter": 0.3},
            "variables": [{"name": "mass", "low": 1, "high": 2}],
            "samples": 10,
            "fidelity": "exact",
        },
    )
    assert "points_parquet" not in job["links"] and "points_csv" not in job["links"]
    status, detail = both(job["job"])
    assert status == 404 and "keep_points" in detail


def test_the_openapi_schema_names_the_parquet_media_type(
    setup: tuple[TestClient, Studies],
) -> None:
    client, _ = setup
    paths = client.get("/openapi.json").json()["paths"]
    ok = paths["/api/v1/jobs/{job_id}/points.parquet"]["get"]["responses"]["200"]
    assert list(ok["content"]) == [PARQUET]
