"""The real app with every registered model, built once per test process, when first asked.

Building it (a request model per model) takes about a second and its OpenAPI document two
more; a module that built its own copy at import made every xdist worker pay for it while
collecting, whether or not it ran that module's tests. The session fixtures ``client`` and
``api`` (tests/conftest.py) hand out clients of this same app: the two differ only in what a
model's crash becomes in the test, so one app (and one OpenAPI document) serves both.
"""

from __future__ import annotations

from functools import cache

from fastapi import FastAPI
from fastapi.testclient import TestClient


@cache
def real_app() -> FastAPI:
    """The real app, every registered model: one per test process."""
    from service import create_app

    return create_app()


@cache
def real_client(raise_server_exceptions: bool = True) -> TestClient:
    """The real app's client; with ``raise_server_exceptions=False`` a model's crash is a 500
    answer instead of an exception in the test."""
    return TestClient(real_app(), raise_server_exceptions=raise_server_exceptions)
