"""Property-based fuzzing of the HTTP API from its own OpenAPI schema (schemathesis).

Every operation of the schema (health, catalogue, each model's evaluate and
sweep) gets generated requests, valid and invalid; every answer must be no
5xx, documented in the schema (status code) and match the schema (body).
Runs over the real app (``service.create_app()``: every registered model)
and over the test toys (a closed form and an ODE simulation), so the model
routes are fuzzed even before real models are registered. Bounded and
derandomised: ~30 examples per operation, same every run.
"""

from __future__ import annotations

import pytest
import schemathesis
from hypothesis import HealthCheck, settings
from schemathesis.checks import (
    not_a_server_error,
    response_schema_conformance,
    status_code_conformance,
)

from service import create_app
from service.config import Settings
from service.studies import StudySettings
from tests.toys import toy_app

pytestmark = pytest.mark.fuzz

CHECKS = [not_a_server_error, status_code_conformance, response_schema_conformance]
BUDGET = settings(
    max_examples=30,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=list(HealthCheck),
)

# A 1 s budget: generated inputs that would simulate for long get the documented
# 422 budget_exceeded quickly instead of taking the default 10 s each.
FAST = Settings(budget_s=1.0, budget_grace_s=0.5)
# studies stay small and in-process: generated bodies must not start a Dask cluster
SMALL_STUDIES = StudySettings(max_points=4000, inprocess_points=4000, budget_s=2.0)
real = schemathesis.openapi.from_asgi(
    "/openapi.json", create_app(settings=FAST, study_settings=SMALL_STUDIES)
)
toys = schemathesis.openapi.from_asgi("/openapi.json", toy_app(FAST))


@real.parametrize()
@BUDGET
def test_real_app_schema(case: schemathesis.Case) -> None:
    case.call_and_validate(checks=CHECKS)


@toys.parametrize()
@BUDGET
def test_toy_models_schema(case: schemathesis.Case) -> None:
    case.call_and_validate(checks=CHECKS)
