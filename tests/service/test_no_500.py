"""No 500 from any input: issue 20's eleven reproductions, each with its right status.

Before the fix every one of these was a 500 (with ~10 kB of traceback in the
log and the keep-alive connection dropped). Now: 422 naming the field, or, for
a sweep, the failing point null with a note. A 500 that still happens (a
model bug) sends ``Connection: close`` and logs one line with the request id.
"""

from __future__ import annotations

import dataclasses
import logging
import math
import warnings
from typing import Any

import pytest
from fastapi.testclient import TestClient

import engine
from engine import RunContext
from service import create_app
from service.config import Settings
from tests.apps import real_client
from tests.toys import TOY, TOY_CRASH

BIG_INT = "9" * 400  # an integer literal of 309-4300 digits: float() overflows

REPRODUCTIONS: list[tuple[str, str, str]] = [
    # (path, raw JSON body, the field the 422 must name)
    ("/api/v1/impact/rare", '{"flywheel_inertia": ' + BIG_INT + "}", "flywheel_inertia"),
    ("/api/v1/clutch/ball", '{"ball_count": ' + BIG_INT + "}", "ball_count"),
    (
        "/api/v1/impact/rare/sweep",
        '{"vary": "motor_torque", "start": "1 m*dB", "stop": 5}',
        "start",
    ),
    (
        "/api/v1/impact/rare/sweep",
        '{"vary": "motor_torque", "start": 1, "stop": "1 m*dB"}',
        "stop",
    ),
    ("/api/v1/impact/rare", '{"flywheel_inertia": 1e-300}', "flywheel_inertia"),
    (
        "/api/v1/impact/rare",
        '{"flywheel_inertia": 1e-300, "fidelity": "simulation"}',
        "flywheel_inertia",
    ),
    ("/api/v1/impact/rare", '{"roller_mass": 1e-320}', "roller_mass"),
    ("/api/v1/impact/rare", '{"cone_angle": 1e-300}', "cone_angle"),
    ("/api/v1/clutch/ball", '{"load_factor": 1e-200}', "load_factor"),
    (
        "/api/v1/nutrunner/drive",
        '{"motor_curve": "induction", "rated_torque": 1e-150}',
        "rated_torque",
    ),
    ("/api/v1/preload/control", '{"youngs_modulus": 5e-324}', "youngs_modulus"),
]


@pytest.fixture(scope="module")
def real() -> TestClient:
    """The session's real app (tests/apps.py), not one more built for this module."""
    return real_client(raise_server_exceptions=False)


@pytest.mark.parametrize(("path", "body", "field"), REPRODUCTIONS)
def test_each_reproduction_is_422_naming_its_field(
    real: TestClient, path: str, body: str, field: str
) -> None:
    r = real.post(path, content=body, headers={"content-type": "application/json"})
    assert r.status_code == 422, r.text
    fields = [item["field"] for item in r.json()["detail"]]
    assert field in fields, r.text
    if "9999" in body:
        assert "an integer of 400 digits" in r.text  # not the 400 digits themselves


def test_numbers_beyond_any_float_and_non_finite_are_422(real: TestClient) -> None:
    for literal in (BIG_INT, "-" + BIG_INT, "NaN", "Infinity", "-Infinity", "1e999"):
        r = real.post(
            "/api/v1/clutch/ball",
            content='{"ball_circle_diameter": ' + literal + "}",
            headers={"content-type": "application/json"},
        )
        assert r.status_code == 422, (literal, r.text)
        assert r.json()["detail"][0]["field"] == "ball_circle_diameter"


def test_every_declared_range_extreme_evaluates_or_is_refused() -> None:
    """Each numeric input at the ends of its declared range (just inside an exclusive end),
    at each example and rung: a result or an EngineError (422), never a crash."""
    crashes = []
    for spec in engine.MODELS:
        for p in spec.inputs:
            if not p.is_numeric:
                continue
            ends: list[float] = []
            if p.minimum is not None:
                lo = p.minimum
                ends.append(math.nextafter(lo, math.inf) if p.exclusive_minimum else lo)
            if p.maximum is not None:
                hi = p.maximum
                ends.append(math.nextafter(hi, -math.inf) if p.exclusive_maximum else hi)
            for v in ends:
                value: Any = math.ceil(v) if p.kind == "int" else v
                for example in spec.examples:
                    for rung in spec.rung_names:
                        try:
                            with warnings.catch_warnings():  # numpy's, as in production
                                warnings.simplefilter("ignore")
                                engine.run(
                                    spec, {**example, p.name: value}, fidelity=rung, budget_s=2
                                )
                        except engine.EngineError:
                            pass
                        except Exception as exc:
                            crashes.append((spec.name, p.name, value, rung, repr(exc)[:80]))
    assert not crashes


def test_arithmetic_failure_inside_a_model_is_422_not_500() -> None:
    def divide(x: Any, ctx: RunContext) -> engine.Result:
        energy = 1.0 / (x["diameter"] - 0.5)
        return engine.Result(values={"energy": energy}, rung=ctx.rung, error_estimate=None)

    spec = dataclasses.replace(TOY, compute=divide, vectorized=None)
    with pytest.raises(engine.SolverFailed, match="ZeroDivisionError"):
        engine.run(spec, {"diameter": 0.5}, fidelity="exact")
    # in a sweep that point is null with a note; its neighbours are computed
    sweep = engine.sweep(spec, {}, "diameter", [0.25, 0.5, 0.75], fidelity="exact")
    assert sweep.results["energy"] == [-4.0, None, 4.0]
    assert any("diameter = 0.5" in n and "arithmetic failed" in n for n in sweep.notes)


def test_a_500_closes_the_connection_and_logs_one_line(caplog: pytest.LogCaptureFixture) -> None:
    c = TestClient(
        create_app(models=[TOY, TOY_CRASH], settings=Settings(warm_up=False, access_log=False)),
        raise_server_exceptions=False,
    )
    with caplog.at_level(logging.INFO):
        r = c.post("/api/v1/toy/crash", json={}, headers={"x-request-id": "boom-1"})
    assert r.status_code == 500
    assert r.headers["connection"] == "close"
    assert r.headers["x-request-id"] == "boom-1"
    lines = [rec for rec in caplog.records if rec.levelno >= logging.ERROR]
    assert len(lines) == 1, [rec.getMessage() for rec in lines]
    (rec,) = lines
    assert "boom-1" in rec.getMessage() and "RuntimeError" in rec.getMessage()
    assert rec.exc_info is None and "Traceback" not in rec.getMessage()


def test_post_routes_answer_405_for_a_wrong_method(real: TestClient) -> None:
    for method in ("GET", "PUT", "DELETE"):
        r = real.request(method, "/api/v1/impact/rare")
        assert r.status_code == 405, (method, r.status_code)
    # with a non-JSON body too: the method is wrong before the media type is
    r = real.put("/api/v1/impact/rare", content=b"x=1", headers={"content-type": "text/plain"})
    assert r.status_code == 405


def test_the_response_model_governs_every_answer() -> None:
    """Every answer is held to its route's ``response_model`` at run time (issue 13; since
    issue 21 by ``service.api._encoder``'s kind checks, not FastAPI's validation): a model
    bug that returns text where the schema says number is a 500 with one log line, never
    sent as a malformed answer."""

    def wrong(x: Any, ctx: RunContext) -> engine.Result:
        return engine.Result(values={"energy": "lots"}, rung=ctx.rung, error_estimate=None)

    spec = dataclasses.replace(TOY, compute=wrong, vectorized=None)
    c = TestClient(
        create_app(models=[spec], settings=Settings(warm_up=False, access_log=False)),
        raise_server_exceptions=False,
    )
    r = c.post("/api/v1/toy/disc", json={"diameter": 0.1, "outputs": ["energy"]})
    assert r.status_code == 500 and "lots" not in r.text
    ok = create_app(models=[TOY], settings=Settings(warm_up=False, access_log=False))
    good = TestClient(ok).post("/api/v1/toy/disc", json={"diameter": 0.1, "outputs": ["energy"]})
    assert good.status_code == 200 and set(good.json()["results"]) == {"energy"}
