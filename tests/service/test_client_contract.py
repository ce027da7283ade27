"""What a client generator sees: named operations, the study's Location, no forged hosts.

openapi-python-client named catalogue and job calls after their paths
(``get_job_api_v1_jobs__job_id__get``); every route now has a chosen operationId. The
study's 202 gives the job's address in ``Location`` (and says so in the schema). A
redirect Starlette builds from the request (``/.`` to ``/./``) named the Host header the
client sent; it is now a path on this server.
"""

from __future__ import annotations

import asyncio
import re
from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.studies import StudySettings
from tests.apps import real_client
from tests.toys import TOY

NAME = re.compile(r"[a-z][a-z0-9_]*")


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    app = create_app(models=[TOY], study_settings=StudySettings(inprocess_points=1000))
    with TestClient(app) as c:
        yield c


def _operations(schema: dict[str, Any]) -> dict[tuple[str, str], str]:
    return {
        (method, path): op["operationId"]
        for path, item in schema["paths"].items()
        for method, op in item.items()
    }


def test_every_operation_has_a_chosen_name() -> None:
    # every real model's routes, as a client sees them (the app the session shares)
    ops = _operations(real_client().get("/openapi.json").json())
    names = list(ops.values())
    assert len(names) == len(set(names))
    for (method, path), name in ops.items():
        assert NAME.fullmatch(name), (method, path, name)
        # FastAPI's generated names end in the method and spell the path out
        assert "api_v1" not in name and not name.endswith(f"_{method}"), (method, path, name)
    assert {
        ("get", "/api/v1/jobs/{job_id}"): "get_job",
        ("delete", "/api/v1/jobs/{job_id}"): "delete_job",
        ("get", "/api/v1/jobs/{job_id}/points.csv"): "get_job_points_csv",
        ("get", "/api/v1/jobs/{job_id}/points.parquet"): "get_job_points_parquet",
        ("get", "/api/v1/models"): "list_models",
        ("get", "/api/v1/models/{name}"): "get_model",
        ("get", "/api/v1/sources"): "list_sources",
        ("get", "/healthz"): "healthz",
        ("get", "/readyz"): "readyz",
        ("post", "/api/v1/joint/vdi2230/study"): "joint_vdi2230_study",
    }.items() <= ops.items()


def test_the_study_202_gives_the_job_in_location(client: TestClient) -> None:
    r = client.post(
        "/api/v1/toy/disc/study",
        json={
            "base": {"diameter": 0.2},
            "variables": [{"name": "speed", "low": 1, "high": 5}],
            "samples": 5,
            "fidelity": "exact",
        },
    )
    assert r.status_code == 202, r.text
    job = r.json()["job"]
    assert r.headers["location"] == r.json()["links"]["self"] == f"/api/v1/jobs/{job}"
    assert client.get(r.headers["location"]).status_code == 200
    doc = client.get("/openapi.json").json()["paths"]["/api/v1/toy/disc/study"]["post"]
    assert "Location" in doc["responses"]["202"]["headers"]


async def _redirect(app: Any, path: str, host: bytes) -> tuple[int, bytes | None]:
    scope = {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": "GET",
        "scheme": "http",
        "path": path,
        "raw_path": path.encode(),
        "root_path": "",
        "query_string": b"",
        "headers": [(b"host", host)],
        "server": ("127.0.0.1", 8000),
        "client": ("127.0.0.1", 40000),
    }
    sent: list[dict[str, Any]] = []

    async def receive() -> dict[str, Any]:
        return {"type": "http.request", "body": b"", "more_body": False}

    async def send(message: dict[str, Any]) -> None:
        sent.append(message)

    await app(scope, receive, send)
    start = sent[0]
    location = dict(start["headers"]).get(b"location")
    return start["status"], location


@pytest.mark.parametrize("path", ["/.", "/vendor/.."])
def test_a_redirect_never_names_the_host_the_client_sent(client: TestClient, path: str) -> None:
    status, location = asyncio.run(_redirect(client.app, path, b"evil.example"))
    assert 300 <= status < 400  # Starlette adds the directory's trailing slash
    assert location is not None
    assert b"evil.example" not in location and location.startswith(b"/")
    assert location == path.encode() + b"/"
