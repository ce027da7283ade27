"""The app's pydantic models and its catalogue are made on first use, not at start-up.

* Building the app builds no model route's request, response or sweep model (nor a study
  route's): pydantic builds each when a body is first validated with it or when
  ``/openapi.json`` is first made.
* The OpenAPI document is the same whichever models a request built before it.
* ``/models`` and ``/models/{name}`` give each model's catalogue entry, whichever of them
  is asked first.
* ``python -m service``'s warnings: a deferred body field's build says nothing.
"""

from __future__ import annotations

import json
import subprocess
import sys
from typing import cast

import pytest
from fastapi.routing import APIRoute
from fastapi.testclient import TestClient
from pydantic import BaseModel

import engine
from service.config import Settings
from service.main import create_app
from service.schemas import SweepResponse
from tests.toys import SPRING, TOY

from .servers import ROOT

#: Inputs of every kind: numbers, choices, flags, texts (a real model besides the toys).
MODELS = (TOY, SPRING, engine.get_model("joint.vdi2230"))
OFF = Settings(warm_up=False, access_log=False)


def _route_models(app: object) -> list[type[BaseModel]]:
    """The request models of the routes of :data:`MODELS`, and their single evaluations'
    response models (a sweep's, :class:`~service.schemas.SweepResponse`, is one class for
    every model: another test may have built it)."""
    paths = {f"/api/v1{spec.path}{end}" for spec in MODELS for end in ("", "/sweep", "/study")}
    found: list[type[BaseModel]] = []
    for route in app.router.routes:  # type: ignore[attr-defined]
        if isinstance(route, APIRoute) and route.path in paths:
            if route.body_field is not None:
                found.append(cast(type[BaseModel], route.body_field.field_info.annotation))
            if route.response_model not in (None, SweepResponse):
                found.append(route.response_model)
    return found


def test_building_the_app_builds_no_route_model_until_a_body_needs_it() -> None:
    app = create_app(models=MODELS, settings=OFF)
    models = _route_models(app)
    assert len(models) == 3 * len(MODELS) + len(MODELS)  # bodies; responses
    assert not any(m.__pydantic_complete__ for m in models)
    with TestClient(app) as client:
        # a wrong unit is not plain: the request model validates the body, naming the field
        body = {**TOY.examples[0], "mass": "2 m"}
        refused = client.post(f"/api/v1{TOY.path}", json=body)
    assert refused.status_code == 422
    assert [e["loc"] for e in refused.json()["detail"]] == [["body", "mass"]]
    request_model = next(m for m in models if m.__name__ == "ToyDiscRequest")
    assert request_model.__pydantic_complete__
    assert sum(m.__pydantic_complete__ for m in models) == 1  # that one alone


def _openapi(client: TestClient) -> bytes:
    answer = client.get("/openapi.json")
    assert answer.status_code == 200
    return answer.content


def test_the_openapi_document_is_the_same_whichever_models_were_built_before_it() -> None:
    with TestClient(create_app(models=MODELS, settings=OFF)) as client:
        first = _openapi(client)
    with TestClient(create_app(models=MODELS, settings=OFF)) as client:
        for spec in MODELS:  # each body refused after its model has validated it
            path = f"/api/v1{spec.path}"
            assert client.post(path, json={"fidelity": 1}).status_code == 422
            assert client.post(f"{path}/sweep", json={"num": 1}).status_code == 422
            assert client.post(f"{path}/study", json={"samples": 1}).status_code == 422
        after = _openapi(client)
    assert first == after
    document = json.loads(first)
    # the study's base, published from the sweep's base when the document is made
    base = document["components"]["schemas"]["ToyDiscStudyRequest"]["properties"]["base"]
    assert base["title"] == "ToyDiscStudyBase"
    assert set(base["properties"]) == {p.name for p in TOY.inputs}


def test_each_catalogue_entry_is_the_models_description_whichever_is_asked_first() -> None:
    described = json.loads(json.dumps([spec.describe() for spec in MODELS]))
    with TestClient(create_app(models=MODELS, settings=OFF)) as client:
        one = client.get(f"/api/v1/models/{SPRING.name}")
        missing = client.get("/api/v1/models/no.such")
        every = client.get("/api/v1/models").json()
    assert one.status_code == 200 and one.json() == described[1]
    assert missing.status_code == 404
    assert every["models"] == described
    assert set(every["service"]) == {"version", "commit", "catalogues"}


@pytest.mark.slow
def test_making_the_openapi_document_warns_of_nothing() -> None:
    """FastAPI silences pydantic's warning about its body fields' alias while it builds
    them; built later (deferred), the service silences it as FastAPI does."""
    code = (
        "from service.main import create_app; from service.config import Settings; "
        "from tests.toys import TOY; "
        "create_app(models=[TOY], settings=Settings(warm_up=False)).openapi()"
    )
    done = subprocess.run(
        [sys.executable, "-W", "error", "-c", code],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr[-2000:]
