"""Optional API keys (issue 34): off by default; with keys configured every /api/v1 route
refuses a missing or unknown key with a JSON 401, the pages and /healthz stay open, and the
key's name is the client's identity for its quotas (studies at once, points per study)."""

from __future__ import annotations

import asyncio
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest

from service import create_app
from service.config import ApiKey, Settings, read_api_keys
from service.studies import Job, StudySettings
from tests.toys import TOY

SECRET_A = "a-secret-of-line-3-0123456789"
SECRET_B = "b-secret-of-line-4-9876543210"
SECRET_C = "c-secret-of-line-5-5555555555"
KEYS = (
    ApiKey.of("line-3", SECRET_A, studies=1),
    ApiKey.of("line-4", SECRET_B, points=10),
    ApiKey.of("line-5", SECRET_C),
)
STUDY = {
    "base": {"diameter": 0.3},
    "variables": [{"name": "mass", "low": 1, "high": 2}],
    "samples": 20,
    "fidelity": "exact",
    "outputs": ["energy"],
}
STUDY_URL = "/api/v1/toy/disc/study"


def _calls(
    keys: tuple[ApiKey, ...], calls: list[tuple[str, str, dict[str, str]]], busy: str = ""
) -> list[Any]:
    """The answers of ``calls`` (method, path, headers) to an app with ``keys``, from one
    address (so only a key can tell the clients apart), with a study of client ``busy``
    running."""
    app = create_app(
        models=[TOY],
        settings=Settings(warm_up=False, api_keys=keys),
        study_settings=StudySettings(per_client=2, inprocess_points=1000),
    )
    if busy:
        job = Job("busy", TOY.name, busy, 10, False, state="running")
        app.state.studies.store.put(job.row("a process"))

    async def run() -> list[httpx.Response]:
        transport = httpx.ASGITransport(app=app, client=("127.0.0.1", 40000))
        async with httpx.AsyncClient(transport=transport, base_url="http://t") as c:
            out = []
            for method, path, headers in calls:
                body = STUDY if path.endswith("/study") else None
                out.append(await c.request(method, path, json=body, headers=headers))
            return out

    try:
        return asyncio.run(run())
    finally:
        app.state.studies.shutdown()


def test_the_api_is_open_without_keys() -> None:
    (models,) = _calls((), [("GET", "/api/v1/models", {})])
    assert models.status_code == 200


def test_with_keys_a_missing_or_unknown_key_is_refused_with_a_json_401() -> None:
    bearer = {"authorization": f"Bearer {SECRET_A}"}
    answers = _calls(
        KEYS,
        [
            ("GET", "/api/v1/models", {}),
            ("GET", "/api/v1/models", {"authorization": "Bearer not-a-key-of-this-server"}),
            ("GET", "/api/v1/models", {"x-api-key": SECRET_A[:-1]}),
            ("POST", "/api/v1/toy/disc", {}),
            ("GET", "/api/v1/jobs/abc", {"authorization": SECRET_A}),  # no "Bearer"
            ("GET", "/api/v1/models", bearer),
            ("GET", "/api/v1/models", {"authorization": f"bearer  {SECRET_B}"}),
            ("GET", "/api/v1/models", {"x-api-key": SECRET_B}),
            ("GET", "/healthz", {}),
            ("GET", "/openapi.json", {}),
            ("GET", "/", {}),
        ],
    )
    statuses = [a.status_code for a in answers]
    assert statuses == [401] * 5 + [200] * 6
    missing, unknown = answers[0], answers[1]
    assert missing.headers["www-authenticate"] == "Bearer"
    assert missing.json()["detail"][0]["type"] == "unauthorized"
    assert "X-API-Key" in missing.json()["detail"][0]["msg"]
    assert "invalid_token" in unknown.headers["www-authenticate"]
    assert unknown.json()["detail"][0]["msg"] == "the API key sent is not known here"
    assert SECRET_A not in missing.text + unknown.text


def test_quotas_follow_the_key_not_the_address() -> None:
    """Three clients behind one address: line-3 may run one study at once (its own quota;
    the server's is two) and runs one; line-5 (the server's quotas) is not held by it;
    line-4 may run studies of at most 10 points (its own quota)."""
    a, b, c = ({"x-api-key": secret} for secret in (SECRET_A, SECRET_B, SECRET_C))
    first, second, other = _calls(
        KEYS,
        [("POST", STUDY_URL, a), ("POST", STUDY_URL, c), ("POST", STUDY_URL, b)],
        busy="key:line-3",
    )
    assert first.status_code == 503 and "limits 1 per client" in first.text
    assert second.status_code == 202
    assert other.status_code == 422
    detail = other.json()["detail"][0]
    assert detail["field"] == "samples"
    assert "20 points, over the limit of the API key 'line-4' of 10" in detail["msg"]


def test_a_key_sees_its_own_jobs_alone() -> None:
    """With keys, another key's job answers 404 (as an unknown one): its id is no ticket."""
    a, c = {"x-api-key": SECRET_A}, {"x-api-key": SECRET_C}
    job = "/api/v1/jobs/busy"
    answers = _calls(
        KEYS,
        [("GET", job, a), ("GET", job + "/points.csv", a), ("DELETE", job, a), ("GET", job, c)],
        busy="key:line-5",
    )
    assert [r.status_code for r in answers] == [404, 404, 404, 200]
    assert answers[-1].json()["state"] == "running"


def test_the_openapi_document_names_the_key_schemes() -> None:
    open_doc, keyed_doc = (
        _calls(keys, [("GET", "/openapi.json", {})])[0].json() for keys in ((), KEYS)
    )
    for doc in (open_doc, keyed_doc):
        schemes = doc["components"]["securitySchemes"]
        assert schemes["bearer"] == {**schemes["bearer"], "type": "http", "scheme": "bearer"}
        assert schemes["apiKey"]["name"] == "X-API-Key"
    study = keyed_doc["paths"][STUDY_URL]["post"]
    assert study["security"] == [{"bearer": []}, {"apiKey": []}]
    assert "401" in study["responses"]
    assert "security" not in keyed_doc["paths"]["/healthz"]["get"]
    assert all("security" not in op for ops in open_doc["paths"].values() for op in ops.values())


@pytest.fixture
def keys_file(tmp_path: Path) -> Iterator[Path]:
    yield tmp_path / "keys"


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("line-3\n", "line 1: write 'name secret"),
        ("# a comment\nline/3 0123456789abcdef\n", "line 2: write"),
        ("line-3 short\n", "secret of 'line-3' is shorter than 16"),
        ("line-3 0123456789abcdef studies=0\n", "'studies=0' is not studies=N"),
        ("line-3 0123456789abcdef hours=2\n", "'hours=2' is not studies=N"),
        ("a 0123456789abcdef\nb 0123456789abcdef\n", "each name and each secret may appear once"),
    ],
)
def test_a_bad_keys_file_stops_the_service_naming_the_line(
    keys_file: Path, text: str, says: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    keys_file.write_text(text)
    monkeypatch.setenv("API_KEYS_FILE", str(keys_file))
    with pytest.raises(ValueError, match="API_KEYS_FILE") as err:
        Settings()
    assert says in str(err.value)
    assert "0123456789abcdef" not in str(err.value)


def test_the_keys_file_is_read_from_api_keys_file(
    keys_file: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    keys_file.write_text("# shop floor\n\nline-3 0123456789abcdef points=500  # the cell\n")
    monkeypatch.setenv("API_KEYS_FILE", str(keys_file))
    (key,) = Settings().api_keys
    assert (key.name, key.studies, key.points) == ("line-3", None, 500)
    assert key == read_api_keys(keys_file)[0]
    monkeypatch.setenv("API_KEYS_FILE", str(keys_file.with_name("absent")))
    with pytest.raises(ValueError, match="cannot be read"):
        Settings()
