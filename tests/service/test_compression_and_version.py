"""Compressed static files and large answers (small answers stay plain), with the security
headers and ETags intact; the product's version and commit named by the catalogue, which
is all the form fetches to start."""

from __future__ import annotations

import gzip
import re
import tomllib
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from service.main import GZIP_MINIMUM_BYTES, product_commit

ROOT = Path(__file__).resolve().parents[2]
VERSION = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
GZIP = {"accept-encoding": "gzip"}
PLAIN = {"accept-encoding": "identity"}


def _raw(client: TestClient, path: str, headers: dict[str, str]) -> Any:
    """The response as sent: its body not decoded by the client."""
    with client.stream("GET", path, headers=headers) as r:
        r.raw_body = b"".join(r.iter_raw())
        return r


def test_the_form_script_goes_gzipped_with_its_csp_and_etag(client: TestClient) -> None:
    plain = _raw(client, "/app.js", PLAIN)
    packed = _raw(client, "/app.js", GZIP)
    assert "content-encoding" not in plain.headers
    assert packed.headers["content-encoding"] == "gzip"
    assert packed.headers["vary"] == "Accept-Encoding"
    assert (
        gzip.decompress(packed.raw_body) == plain.raw_body == (ROOT / "static/app.js").read_bytes()
    )
    assert len(packed.raw_body) < len(plain.raw_body) / 3
    for r in (plain, packed):
        assert r.headers["content-security-policy"].startswith("default-src 'self'")
        assert r.headers["etag"] == plain.headers["etag"]
    # the ETag still answers 304, without a body
    again = client.get("/app.js", headers={**GZIP, "if-none-match": plain.headers["etag"]})
    assert again.status_code == 304 and again.content == b""
    assert again.headers["content-security-policy"].startswith("default-src 'self'")


def test_a_small_answer_stays_plain_and_a_large_one_is_compressed(client: TestClient) -> None:
    with client.stream(
        "POST",
        "/api/v1/preload/tightening",
        headers=GZIP,
        json={"thread": "M12 8.8", "outputs": ["tightening_torque"]},
    ) as r:
        body = b"".join(r.iter_raw())
    assert r.status_code == 200 and "content-encoding" not in r.headers
    assert len(body) < GZIP_MINIMUM_BYTES
    models = _raw(client, "/api/v1/models", GZIP)
    assert models.headers["content-encoding"] == "gzip"
    whole = gzip.decompress(models.raw_body)
    assert len(whole) > GZIP_MINIMUM_BYTES and len(models.raw_body) < len(whole) / 5


def test_the_catalogue_names_the_version_commit_and_other_catalogues(client: TestClient) -> None:
    service = client.get("/api/v1/models").json()["service"]
    assert service["version"] == VERSION
    assert service["commit"] == "unknown" or re.fullmatch(r"[0-9a-f]{40}", service["commit"])
    assert service["catalogues"] == {
        "preload_methods": "/api/v1/preload/methods",
        "fasteners": "/api/v1/fasteners",
    }
    for path in service["catalogues"].values():
        assert client.get(path).status_code == 200
    assert client.get("/openapi.json").json()["info"]["version"] == VERSION


def test_an_image_build_names_its_commit(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("COMMIT", "0123456789abcdef0123456789abcdef01234567")
    assert product_commit() == "0123456789abcdef0123456789abcdef01234567"
    monkeypatch.delenv("COMMIT")
    monkeypatch.setenv("PATH", "/nonexistent")  # no git to ask
    assert product_commit() == "unknown"
