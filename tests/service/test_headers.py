"""Security headers on every response, CSP, CORS closed by default, no banner, access log."""

from __future__ import annotations

import base64
import hashlib
import json
import logging
import os
import re
import socket
import subprocess
import sys
import time
from pathlib import Path

import httpx
import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.config import Settings
from service.middleware import STRICT_CSP
from tests.toys import TOY, TOY_CRASH

ROOT = Path(__file__).resolve().parents[2]
SECURITY = {
    "x-content-type-options": "nosniff",
    "x-frame-options": "DENY",
    "referrer-policy": "no-referrer",
}


@pytest.fixture(scope="module")
def toy() -> TestClient:
    return TestClient(create_app(models=[TOY, TOY_CRASH]), raise_server_exceptions=False)


def assert_secure(r: httpx.Response, csp: str = STRICT_CSP) -> None:
    for name, value in SECURITY.items():
        assert r.headers.get(name) == value, (r.request.url, name, dict(r.headers))
    assert r.headers.get("content-security-policy") == csp, r.request.url
    assert re.fullmatch(r"[A-Za-z0-9._-]{1,64}", r.headers["x-request-id"])
    assert "server" not in r.headers


def test_strict_csp_is_the_one_asked_for() -> None:
    for directive in (
        "default-src 'self'",
        "script-src 'self'",
        "style-src 'self'",
        "img-src 'self' data:",
        "connect-src 'self'",
        "object-src 'none'",
        "base-uri 'none'",
        "frame-ancestors 'none'",
    ):
        assert directive in STRICT_CSP.split("; ")
    assert "unsafe" not in STRICT_CSP


@pytest.mark.parametrize(
    ("method", "path", "body", "status"),
    [
        ("GET", "/", None, 200),
        ("GET", "/app.js", None, 200),
        ("GET", "/healthz", None, 200),
        ("GET", "/api/v1/models", None, 200),
        ("GET", "/openapi.json", None, 200),
        ("GET", "/api/v1/models/nope", None, 404),
        ("GET", "/nope.html", None, 404),
        ("DELETE", "/api/v1/toy/disc", None, 405),
        ("POST", "/api/v1/toy/disc", {"diameter": 0.2}, 200),
        ("POST", "/api/v1/toy/disc", {"diameter": -1}, 422),
        ("POST", "/api/v1/toy/crash", {}, 500),
    ],
)
def test_every_response_carries_the_security_headers(
    toy: TestClient, method: str, path: str, body: object, status: int
) -> None:
    r = toy.request(method, path, json=body)
    assert r.status_code == status
    assert_secure(r)


def test_413_and_415_carry_them_too(toy: TestClient) -> None:
    r = toy.post("/api/v1/toy/disc", content=b"x" * 300_000, headers={"content-type": "a/b"})
    assert r.status_code == 415
    assert_secure(r)
    big = b"{" + b" " * 300_000 + b"}"
    r = toy.post("/api/v1/toy/disc", content=big, headers={"content-type": "application/json"})
    assert r.status_code == 413
    assert_secure(r)


def test_500_hides_the_error_and_names_the_request(toy: TestClient) -> None:
    r = toy.post("/api/v1/toy/crash", json={}, headers={"x-request-id": "trace-42"})
    assert r.status_code == 500
    (item,) = r.json()["detail"]
    assert item["type"] == "internal_error"
    assert item["msg"] == "internal error; it was logged on the server (request id trace-42)"
    assert "secret internal detail" not in r.text and "ZeroDivision" not in r.text
    assert r.headers["x-request-id"] == "trace-42"


def test_request_id_echoed_when_sane_replaced_when_not(toy: TestClient) -> None:
    assert (
        toy.get("/healthz", headers={"x-request-id": "abc.DEF-1_2"}).headers["x-request-id"]
        == "abc.DEF-1_2"
    )
    for bad in ("a b", "x" * 65, '"}{', "\xe9\xe9"):
        rid = toy.get("/healthz", headers={"x-request-id": bad.encode("latin-1")})
        assert rid.headers["x-request-id"] != bad and len(rid.headers["x-request-id"]) == 32


def test_docs_pages_get_their_own_csp_with_the_inline_script_hashed(toy: TestClient) -> None:
    for path in ("/docs", "/redoc"):
        r = toy.get(path)
        assert r.status_code == 200
        csp = r.headers["content-security-policy"]
        script_src = next(d for d in csp.split("; ") if d.startswith("script-src "))
        assert "'unsafe-inline'" not in script_src and "'unsafe-eval'" not in script_src
        assert "frame-ancestors 'none'" in csp and "object-src 'none'" in csp
        for inline in re.findall(r"<script>(.*?)</script>", r.text, flags=re.S):
            digest = base64.b64encode(hashlib.sha256(inline.encode()).digest()).decode()
            assert f"'sha256-{digest}'" in script_src
        for name, value in SECURITY.items():
            assert r.headers[name] == value
    assert "sha256-" in toy.get("/docs").headers["content-security-policy"]


def test_cors_closed_by_default(toy: TestClient) -> None:
    r = toy.get("/api/v1/models", headers={"origin": "https://evil.example"})
    assert r.status_code == 200 and "access-control-allow-origin" not in r.headers
    pre = toy.options(
        "/api/v1/toy/disc",
        headers={
            "origin": "https://evil.example",
            "access-control-request-method": "POST",
            "access-control-request-headers": "content-type",
        },
    )
    assert pre.status_code == 405 and "access-control-allow-origin" not in pre.headers


def test_cors_opens_for_configured_origins_only() -> None:
    settings = Settings(cors_origins=("https://tools.example",))
    c = TestClient(create_app(models=[TOY], settings=settings))
    pre = c.options(
        "/api/v1/toy/disc",
        headers={
            "origin": "https://tools.example",
            "access-control-request-method": "POST",
            "access-control-request-headers": "content-type",
        },
    )
    assert pre.status_code == 200
    assert pre.headers["access-control-allow-origin"] == "https://tools.example"
    r = c.post(
        "/api/v1/toy/disc", json={"diameter": 0.1}, headers={"origin": "https://tools.example"}
    )
    assert r.headers["access-control-allow-origin"] == "https://tools.example"
    other = c.post(
        "/api/v1/toy/disc", json={"diameter": 0.1}, headers={"origin": "https://evil.example"}
    )
    assert "access-control-allow-origin" not in other.headers
    assert_secure(r)


def test_cors_origins_from_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("CORS_ORIGINS", "https://a.example, https://b.example")
    assert Settings().cors_origins == ("https://a.example", "https://b.example")
    monkeypatch.delenv("CORS_ORIGINS")
    assert Settings().cors_origins == ()


def test_access_log_is_one_json_line_without_the_body(
    toy: TestClient, caplog: pytest.LogCaptureFixture
) -> None:
    secret = "SECRET-BODY-7f3a"
    with caplog.at_level(logging.INFO, logger="service.access"):
        r = toy.post(
            "/api/v1/toy/disc",
            json={"diameter": f"{secret} mm", "note": secret},
            headers={"x-request-id": "log-test-1"},
        )
    assert r.status_code == 422
    lines = [rec.getMessage() for rec in caplog.records if rec.name == "service.access"]
    (line,) = lines
    entry = json.loads(line)
    assert set(entry) == {"method", "path", "status", "duration_ms", "request_id"}
    assert entry["method"] == "POST" and entry["path"] == "/api/v1/toy/disc"
    assert entry["status"] == 422 and entry["request_id"] == "log-test-1"
    assert isinstance(entry["duration_ms"], float) and entry["duration_ms"] >= 0
    assert all(secret not in rec.getMessage() for rec in caplog.records)


def test_access_log_records_a_500(toy: TestClient, caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.INFO, logger="service.access"):
        toy.post("/api/v1/toy/crash", json={}, headers={"x-request-id": "crash-1"})
    (line,) = [rec.getMessage() for rec in caplog.records if rec.name == "service.access"]
    assert json.loads(line)["status"] == 500 and json.loads(line)["request_id"] == "crash-1"


def test_access_log_can_be_switched_off(caplog: pytest.LogCaptureFixture) -> None:
    c = TestClient(create_app(models=[TOY], settings=Settings(access_log=False)))
    with caplog.at_level(logging.INFO, logger="service.access"):
        c.get("/healthz")
    assert not [rec for rec in caplog.records if rec.name == "service.access"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.mark.slow
def test_real_server_sends_no_banner_and_logs_json_lines(tmp_path: Path) -> None:
    port = _free_port()
    log_path = tmp_path / "out.log"
    out = log_path.open("wb")
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    factory = "tests.toys:toy_app"
    proc = subprocess.Popen(
        [sys.executable, "-m", "service", "--port", str(port), "--factory", factory],
        cwd=ROOT,
        stdout=out,
        stderr=subprocess.STDOUT,
        env=env,
    )
    try:
        url = f"http://127.0.0.1:{port}"
        for _ in range(200):
            try:
                r = httpx.get(url + "/healthz", headers={"x-request-id": "real-1"})
                break
            except httpx.TransportError:
                time.sleep(0.05)
        else:
            pytest.fail("the server did not start")
        assert r.status_code == 200 and "server" not in r.headers and "date" not in r.headers
        assert_secure(r)
        post = httpx.post(url + "/api/v1/toy/disc", json={"diameter": "SECRET-9 mm"})
        assert post.status_code == 422
    finally:
        proc.terminate()
        proc.wait(timeout=10)
        out.close()
    log = log_path.read_text()
    entries = [json.loads(line) for line in log.splitlines() if line.startswith("{")]
    assert {"method": "GET", "path": "/healthz", "status": 200, "request_id": "real-1"}.items() <= (
        entries[0].items()
    )
    assert entries[1]["status"] == 422 and "SECRET-9" not in log


def test_docs_work_offline_from_the_vendored_swagger_ui(toy: TestClient) -> None:
    page = toy.get("/docs")
    csp = page.headers["content-security-policy"]
    # every script and stylesheet the page names is served here; the CSP allows no other host
    assets = re.findall(r"""(?:src|href)=["']([^"']+)["']""", page.text)
    assert "/vendor/swagger-ui/swagger-ui-bundle.js" in assets
    for url in assets:
        assert url.startswith("/"), url
        assert toy.get(url).status_code == 200, url
    assert "http" not in csp


def test_fresh_request_ids_are_unique_and_renewed_after_a_fork() -> None:
    """Ids are a random per-process prefix and a counter (no system call per request); the
    hook a forked worker runs (``os.register_at_fork``) draws a new prefix, so two workers
    never hand out the same id. (The hook is called here, not through a fork: forking a
    test process with threads can deadlock.)"""
    from service import middleware

    ids = [middleware._fresh_id() for _ in range(1000)]
    assert len(set(ids)) == 1000 and all(len(i) == 32 for i in ids)
    assert all(re.fullmatch(rb"[0-9a-f]{32}", i) for i in ids[:3])
    before = middleware._fresh_id()
    middleware._new_id_prefix()
    after = middleware._fresh_id()
    assert after[:16] != before[:16] and after[16:] == b"%016x" % 1
