"""The real app with every registered model, built once per test process, when first asked.

Building it (a request model per model) takes about a second and its OpenAPI document two
more; a module that built its own copy at import made every xdist worker pay for it while
collecting, whether or not it ran that module's tests. The session fixtures ``client`` and
``api`` (tests/conftest.py) hand out these same clients.
"""

from __future__ import annotations

from functools import cache

from fastapi.testclient import TestClient


@cache
def real_client(raise_server_exceptions: bool = True) -> TestClient:
    """The real app's client; with ``raise_server_exceptions=False`` a model's crash is a 500
    answer instead of an exception in the test."""
    from service import create_app

    return TestClient(create_app(), raise_server_exceptions=raise_server_exceptions)
