"""A study's ``base`` is typed per model in the OpenAPI document (issue 34: it was an
untyped dict, so a generated client knew nothing of the inputs a study holds fixed)."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient
from pydantic import ValidationError

import engine
from service import create_app, schemas
from service.config import Settings
from tests.apps import real_app
from tests.toys import TOY


@pytest.fixture(scope="module")
def document() -> dict[str, Any]:
    """The real app's OpenAPI document (tests/apps.py: the session's app, whose document is
    built once per test process), where the study routes of every model are published."""
    return real_app().openapi()


def _resolve(doc: dict[str, Any], schema: dict[str, Any]) -> dict[str, Any]:
    while "$ref" in schema:
        schema = doc["components"]["schemas"][schema["$ref"].rsplit("/", 1)[1]]
    return schema


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_each_models_study_base_names_that_models_inputs(
    document: dict[str, Any], spec: engine.ModelSpec
) -> None:
    body = document["paths"][f"/api/v1{spec.path}/study"]["post"]["requestBody"]
    request = _resolve(document, body["content"]["application/json"]["schema"])
    base = _resolve(document, request["properties"]["base"])
    assert base.get("additionalProperties") is False
    assert set(base["properties"]) == {p.name for p in spec.inputs}
    assert "required" not in base  # every input optional: defaults fill the rest
    numeric = next((p for p in spec.inputs if p.is_numeric and p.unit != "1"), None)
    if numeric is not None:  # the unit and range come with the input, as for a single run
        field = _resolve(document, base["properties"][numeric.name])
        shown = str(field)
        assert numeric.unit in shown, shown


BASES = [
    {"diameter": "300 mm"},
    {"diameter": 0.3, "count": 2, "mode": "broken", "blowup": True},
    {"diameter": "30 m"},
    {"diameter": "5 kg"},
    {"diametre": 0.3},
    {"diameter": 0.3, "count": 1.5},
    {"diameter": 0.3, "mode": "cracked"},
]


def test_the_route_takes_the_bases_its_published_schema_takes() -> None:
    """The route reads a base as a study's law (units.quantity, the engine's ranges), not
    through the published model: the two agree on what they take, and a refusal names the
    input."""
    published = schemas.inputs_model(TOY, all_optional=True)
    app = create_app(models=[TOY], settings=Settings(warm_up=False))
    study = {"variables": [{"name": "mass", "low": 1, "high": 2}], "samples": 10}
    try:
        with TestClient(app) as c:
            answers = [
                c.post("/api/v1/toy/disc/study", json={**study, "base": base}) for base in BASES
            ]
    finally:
        app.state.studies.shutdown()
    for base, answer in zip(BASES, answers, strict=True):
        try:
            published.model_validate(base)
            takes = True
        except ValidationError:
            takes = False
        assert (answer.status_code == 202) == takes, (base, answer.text)
    assert [a.status_code for a in answers] == [202, 202] + [422] * 5
    fields = [a.json()["detail"][0]["field"] for a in answers[2:]]
    assert fields == ["diameter", "diameter", "base", "count", "mode"]
