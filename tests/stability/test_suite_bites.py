"""The stability checks fail on the mistakes they exist for (a check that cannot fail is a defect).

Each test breaks the spring toy in one way a real model could be broken and
shows the generic check catching it: the naive 1 − cos form that loses a
small angle, a dishonest error estimate, a non-finite result, a deadline
ignored, an exception that is not an EngineError, and a 500 from the API.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Mapping
from typing import Any

import pytest
from fastapi.testclient import TestClient

from engine import ModelSpec, Result, RunContext
from service import create_app
from tests.toys import SPRING

from .common import BUDGET_S, BUDGET_SLACK_S, run_checked
from .test_property import post
from .test_rungs import assert_rungs_agree

#: u = h k / F = 1e-17: an angle whose 1 − cos θ is lost in double precision.
TINY_LIFT = {"mass": 1.0, "stiffness": 1e-3, "force": 1e3, "height": 1e-11}


def broken(**changes: Any) -> ModelSpec:
    return dataclasses.replace(SPRING, **changes)


def wrapping(patch: Any) -> ModelSpec:
    """SPRING whose compute passes its Result through ``patch(inputs, ctx, result)``."""

    def compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
        return patch(x, ctx, SPRING.compute(x, ctx))

    return broken(compute=compute)


def test_sound_toy_passes_at_the_tiny_angle():
    assert assert_rungs_agree(SPRING, TINY_LIFT) > 0


def test_catches_the_naive_one_minus_cos():
    def naive(x: Mapping[str, Any], ctx: RunContext, result: Result) -> Result:
        if ctx.rung == "exact" and "time" in result.values:
            u = x["height"] * x["stiffness"] / x["force"]
            # θ = arccos(1 − u): 1 − 1e-17 rounds to 1, so θ = 0 and the time is 0
            result.values["time"] = math.acos(1.0 - u) / math.sqrt(x["stiffness"] / x["mass"])
        return result

    with pytest.raises(AssertionError, match="differ by"):
        assert_rungs_agree(wrapping(naive), TINY_LIFT)


def test_catches_a_dishonest_estimate():
    rigid = dataclasses.replace(SPRING.rungs[0], estimate=lambda x: 1e-4)
    spec = broken(rungs=(rigid, *SPRING.rungs[1:]))

    def claim(x: Mapping[str, Any], ctx: RunContext, result: Result) -> Result:
        return dataclasses.replace(result, error_estimate=1e-4 if ctx.rung == "rigid" else 1e-12)

    spec = dataclasses.replace(spec, compute=wrapping(claim).compute)
    with pytest.raises(AssertionError, match="beyond what their estimates"):
        assert_rungs_agree(spec, dict(SPRING.examples[0]))


def test_catches_a_non_finite_value_the_runner_would_hide():
    def overflow(x: Mapping[str, Any], ctx: RunContext, result: Result) -> Result:
        result.values["speed"] = math.inf
        return result

    with pytest.raises(AssertionError, match="non-finite"):
        run_checked(wrapping(overflow), SPRING.examples[0], fidelity="exact")


def test_catches_an_unbounded_error_estimate():
    def unbounded(x: Mapping[str, Any], ctx: RunContext, result: Result) -> Result:
        return dataclasses.replace(result, error_estimate=math.nan)

    with pytest.raises(AssertionError, match="error estimate"):
        run_checked(wrapping(unbounded), SPRING.examples[0], fidelity="exact")


def test_catches_a_run_that_ignores_its_deadline():
    def slow(x: Mapping[str, Any], ctx: RunContext, result: Result) -> Result:
        time.sleep(BUDGET_S + BUDGET_SLACK_S + 0.05)
        return result

    with pytest.raises(AssertionError, match="budget"):
        run_checked(wrapping(slow), SPRING.examples[0], fidelity="exact")


def _divide(x: Mapping[str, Any], ctx: RunContext) -> Result:
    return Result(values={"time": 1.0 / (x["force"] - x["force"])}, rung=ctx.rung, error_estimate=0)


def test_catches_an_exception_that_is_not_an_engine_error():
    with pytest.raises(ZeroDivisionError):
        run_checked(broken(compute=_divide), SPRING.examples[0], fidelity="exact")


def test_catches_a_500():
    spec = broken(compute=_divide)
    client = TestClient(create_app(models=[spec]), raise_server_exceptions=False)
    with pytest.raises(AssertionError, match="answered 500"):
        post(client, "/api/v1" + spec.path, dict(SPRING.examples[0]))


def test_catches_auto_running_the_wrong_rung():
    from .test_rungs import test_auto_picks_the_cheapest_rung_meeting_the_tolerance as check

    def stubborn(x: Mapping[str, Any], ctx: RunContext) -> Result:
        return SPRING.compute(x, dataclasses.replace(ctx, rung="simulation"))

    with pytest.raises(AssertionError, match="auto at tolerance"):
        check(broken(compute=stubborn))
