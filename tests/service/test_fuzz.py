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

import copy
from typing import Any

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
# No warm-up: from_asgi enters the app's lifespan at import, and a warm-up thread running
# the models beside the next create_app() raced FastAPI's warnings.catch_warnings (a
# collection error in CI, see pyproject's filterwarnings).
FAST = Settings(budget_s=1.0, budget_grace_s=0.5, warm_up=False)
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


# ---------------------------------------------------------------------------
# Numbers only: every numeric input's schema without its unit-string branch.
# With strings allowed, generated bodies were mostly refused at the unit parser
# and rarely reached a model (issue 20 found eleven 500s this way). Here every
# case that passes validation runs the engine; ≥ 2,000 cases in all, zero 500s.
# ---------------------------------------------------------------------------

NUMBERS_CASES = 170  # per operation; 12 model operations → ≥ 2,040 cases
_ran: list[str] = []


def numbers_only(schema: dict[str, Any]) -> dict[str, Any]:
    """The OpenAPI document with each ``x-unit`` field's string alternative removed."""
    out = copy.deepcopy(schema)
    for component in out.get("components", {}).get("schemas", {}).values():
        for prop in component.get("properties", {}).values():
            if "x-unit" in prop and "anyOf" in prop:
                prop["anyOf"] = [b for b in prop["anyOf"] if b.get("type") != "string"]
    # keep the model operations (the rest is fuzzed above)
    out["paths"] = {p: ops for p, ops in out["paths"].items() if "post" in ops}
    return out


_FAST_APP = create_app(settings=Settings(budget_s=0.3, budget_grace_s=0.5, warm_up=False))
numbers = schemathesis.openapi.from_dict(numbers_only(_FAST_APP.openapi()))
numbers.app = _FAST_APP


@numbers.parametrize()
@settings(
    max_examples=NUMBERS_CASES,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=list(HealthCheck),
)
def test_numbers_only_schema_reaches_the_engine(case: schemathesis.Case) -> None:
    _ran.append(case.operation.label)
    case.call_and_validate(checks=CHECKS)


def test_numbers_only_fuzz_ran_at_least_2000_cases() -> None:
    if not _ran:
        pytest.skip("run with the numbers-only fuzz test")
    assert len(_ran) >= 2000, len(_ran)
