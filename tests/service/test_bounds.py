"""Every bound on work answers with a status and a message naming the bound, never a hang.

Body size (413, with and without content-length), sweep points (422 ``num``),
series length (422 ``MAX_SERIES_POINTS``), the wall-clock budget (422
``budget_exceeded``, cooperative and hard ceiling), the step budget, and a
full lane (503 with Retry-After: tests/service/test_lanes.py).
"""

from __future__ import annotations

import re
import time
from collections.abc import Iterator

import httpx
import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.config import Settings
from tests.toys import TOY, TOY_ODE, TOY_SPIN, TOY_STUBBORN

MODELS = [TOY, TOY_ODE, TOY_SPIN, TOY_STUBBORN]


def client(**settings: object) -> TestClient:
    app = create_app(models=MODELS, settings=Settings(**settings))  # type: ignore[arg-type]
    return TestClient(app, raise_server_exceptions=False)


@pytest.fixture(scope="module")
def toy() -> TestClient:
    return client(budget_s=0.5, max_steps=5000, max_series_points=1000)


def only_error(r: httpx.Response, status: int) -> dict[str, object]:
    assert r.status_code == status, r.text
    (item,) = r.json()["detail"]
    assert set(item) >= {"type", "loc", "msg", "field"}
    return item


def test_body_over_limit_with_content_length_is_413(toy: TestClient) -> None:
    body = b'{"diameter": 0.1, "pad": "' + b"x" * 300_000 + b'"}'
    item = only_error(
        toy.post("/api/v1/toy/disc", content=body, headers={"content-type": "application/json"}),
        413,
    )
    assert item["type"] == "body_too_large"
    assert item["msg"] == "request body over the 262144-byte limit (MAX_BODY_BYTES)"


def test_chunked_body_without_content_length_is_cut_off_at_the_limit(toy: TestClient) -> None:
    sent = 0

    def chunks() -> Iterator[bytes]:
        nonlocal sent
        yield b'{"diameter": 0.1, "pad": "'
        for _ in range(1000):  # would be 16 MB: the guard stops reading long before
            sent += 1
            yield b"x" * 16_384
        yield b'"}'

    r = toy.post("/api/v1/toy/disc", content=chunks(), headers={"content-type": "application/json"})
    assert "content-length" not in r.request.headers
    assert r.request.headers["transfer-encoding"] == "chunked"
    assert only_error(r, 413)["type"] == "body_too_large"


def test_body_under_limit_passes(toy: TestClient) -> None:
    r = toy.post("/api/v1/toy/disc", json={"diameter": 0.1})
    assert r.status_code == 200


@pytest.mark.parametrize(("num", "status"), [(2000, 200), (2001, 422)])
def test_sweep_points_at_most_2000(toy: TestClient, num: int, status: int) -> None:
    r = toy.post(
        "/api/v1/toy/disc/sweep",
        json={"base": {"diameter": 0.2}, "vary": "speed", "start": 0, "stop": 1, "num": num},
    )
    assert r.status_code == status, r.text
    if status == 422:
        item = only_error(r, 422)
        assert item["field"] == "num" and "less than or equal to 2000" in str(item["msg"])
    else:
        assert len(r.json()["values"]) == 2000


def test_series_longer_than_the_cap_is_422_naming_the_bound(toy: TestClient) -> None:
    r = toy.post("/api/v1/toy/ode", json={"points": 1001, "series": True})
    item = only_error(r, 422)
    assert item["type"] == "limit_exceeded" and item["field"] == "outputs"
    assert "'time' has 1001 points, over the limit of 1000 (MAX_SERIES_POINTS)" in str(item["msg"])
    # the same run without series is fine (the default since issue 21), and at the cap too
    assert (
        toy.post("/api/v1/toy/ode", json={"points": 1001, "outputs": ["final"]}).status_code == 200
    )
    assert toy.post("/api/v1/toy/ode", json={"points": 1001}).status_code == 200
    at_cap = toy.post("/api/v1/toy/ode", json={"points": 1000, "series": True})
    assert len(at_cap.json()["series"]["x"]) == 1000


def test_wall_clock_budget_reaches_the_model(toy: TestClient) -> None:
    start = time.perf_counter()
    item = only_error(toy.post("/api/v1/toy/spin", json={"seconds": 30}), 422)
    assert item["type"] == "budget_exceeded" and "wall-clock budget" in str(item["msg"])
    assert time.perf_counter() - start < 10  # generous: the budget is 0.5 s, the ask 30 s


def test_step_budget_reaches_the_model() -> None:
    # stiffness 1e5 with RK45 over 20 s needs far more than 500 right-hand-side evaluations
    r = client(budget_s=30, max_steps=500).post(
        "/api/v1/toy/ode", json={"stiffness": 1e5, "t_end": 20, "outputs": ["final"]}
    )
    item = only_error(r, 422)
    assert item["type"] == "budget_exceeded"
    assert "step budget of 500 steps" in str(item["msg"])


def test_sweep_stops_at_its_budget(toy: TestClient) -> None:
    r = toy.post(
        "/api/v1/toy/spin/sweep",
        json={"vary": "seconds", "start": 0.1, "stop": 0.1, "num": 50},
    )
    item = only_error(r, 422)
    assert item["type"] == "budget_exceeded" and item["field"] == "num"
    assert re.fullmatch(r"sweep stopped after \d+ of 50 points at its 0\.\d+ s budget", item["msg"])


def test_model_that_ignores_its_deadline_gets_a_hard_ceiling() -> None:
    c = client(budget_s=0.2, budget_grace_s=0.3)
    start = time.perf_counter()
    item = only_error(c.post("/api/v1/toy/stubborn", json={"seconds": 3}), 422)
    elapsed = time.perf_counter() - start
    assert item["type"] == "budget_exceeded"
    assert (
        item["msg"] == "toy.stubborn did not finish within its 0.2 s wall-clock budget (BUDGET_S)"
    )
    assert elapsed < 2.5  # answered at ~0.5 s, long before the model's 3 s


def test_settings_refuse_nonsense_at_start_up(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("BUDGET_S", "2.5")
    monkeypatch.setenv("MAX_SERIES_POINTS", "123")
    s = Settings()
    assert s.budget_s == 2.5 and s.max_series_points == 123
    monkeypatch.setenv("BUDGET_S", "0")
    with pytest.raises(ValueError, match="BUDGET_S must be positive"):
        Settings()
    monkeypatch.setenv("BUDGET_S", "nan")
    with pytest.raises(ValueError, match="BUDGET_S must be positive"):
        Settings()
