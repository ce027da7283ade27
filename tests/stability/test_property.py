"""Any request within the declared ranges, any rung: a finite answer or a clear refusal.

Hypothesis draws every input of every model (log-uniformly over positive
ranges, so decades and the extremes get their share) and runs each rung and
``auto``. The verdict is in :func:`tests.stability.common.run_checked`:
an allowed EngineError with a message, or every value and the error estimate
finite, within the budget; never any other exception. Then the same through
HTTP: never a 500, never NaN or Infinity in a body.
"""

from __future__ import annotations

import json
import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from engine import ModelSpec
from service import create_app

from .common import MODELS_UNDER_TEST, fidelities, ids, requests, run_checked

SETTINGS = settings(
    max_examples=60,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
@SETTINGS
@given(data=st.data())
def test_engine_run_is_finite_or_refuses(spec: ModelSpec, data: st.DataObject) -> None:
    request = data.draw(requests(spec), label="request")
    fidelity = data.draw(fidelities(spec), label="fidelity")
    tolerance = data.draw(st.sampled_from((None, 0.3, 1e-3, 1e-9)), label="tolerance")
    result = run_checked(spec, request, fidelity=fidelity, tolerance=tolerance)
    event("refused" if result is None else "answered")  # --hypothesis-show-statistics
    if result is not None:
        assert result.rung in spec.rung_names
        for name, value in result.results.items():
            assert value is None or isinstance(value, bool | int | float | str), (
                f"{spec.name}: {name} = {value!r} is not a JSON scalar"
            )


@pytest.fixture(scope="module")
def client() -> TestClient:
    return TestClient(create_app(models=MODELS_UNDER_TEST), raise_server_exceptions=False)


def _no_nan(text: str) -> Any:
    def refuse(constant: str) -> Any:
        raise AssertionError(f"{constant} in a JSON body: {text[:300]}")

    return json.loads(text, parse_constant=refuse)


def post(client: TestClient, path: str, body: dict[str, Any]) -> Any:
    """POST and check the contract every response keeps: 200 or 422, strict JSON."""
    response = client.post(path, json=body)
    assert response.status_code in (200, 422), (
        f"{path} answered {response.status_code} to {body}: {response.text[:500]}"
    )
    parsed = _no_nan(response.text)
    if response.status_code == 422:
        assert parsed["detail"] and parsed["detail"][0]["msg"], response.text
    return parsed


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
@settings(SETTINGS, max_examples=25)
@given(data=st.data())
def test_api_never_500_never_nan(client: TestClient, spec: ModelSpec, data: st.DataObject) -> None:
    request = data.draw(requests(spec), label="request")
    fidelity = data.draw(fidelities(spec), label="fidelity")
    body = post(client, "/api/v1" + spec.path, {**request, "fidelity": fidelity})
    for value in body.get("results", {}).values():
        assert not isinstance(value, float) or math.isfinite(value)
