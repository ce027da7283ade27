from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from service import create_app


@pytest.fixture(scope="session")
def client() -> TestClient:
    """The real app with every registered model."""
    return TestClient(create_app())
