"""One reader for the numbers a sweep or a study gives for a varied input (sweep ends, a
law's low, high, mean, mode, sd): the same message style everywhere, naming the input, the
part, the value as written, and the allowed range."""

from __future__ import annotations

import json
from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.studies import StudySettings
from tests.toys import TOY

SPEED_RANGE = (
    "allowed: a finite number ≥ 0 rad/s and ≤ 10000 rad/s, in rad/s or as a string with a unit"
)


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    app = create_app(models=[TOY], study_settings=StudySettings(inprocess_points=1000))
    with TestClient(app) as c:
        yield c


def _detail(r) -> dict:  # type: ignore[no-untyped-def]
    assert r.status_code == 422, r.text
    (item,) = r.json()["detail"]
    return item


def test_a_sweep_end_and_a_study_bound_are_refused_in_the_same_words(client: TestClient) -> None:
    sweep = client.post(
        "/api/v1/toy/disc/sweep",
        json={"base": {"diameter": 0.2}, "vary": "speed", "start": 0, "stop": "5 kg", "num": 3},
    )
    study = client.post(
        "/api/v1/toy/disc/study",
        json={
            "base": {"diameter": 0.2},
            "variables": [{"name": "speed", "low": 0, "high": "5 kg"}],
        },
    )
    wrong = "'kg' has the wrong dimension: expected rad/s (write products as 'N*m')"
    s, t = _detail(sweep), _detail(study)
    assert s["field"] == "stop" and s["msg"] == f"speed (stop) = '5 kg': {wrong}; {SPEED_RANGE}"
    assert t["field"] == "variables"
    assert t["msg"] == f"speed (high) = '5 kg': {wrong}; {SPEED_RANGE}"


def test_non_finite_numbers_and_unreadable_strings(client: TestClient) -> None:
    raw = {"base": {"diameter": 0.2}, "vary": "speed", "start": 0, "num": 3}
    r = client.post(
        "/api/v1/toy/disc/sweep",
        content=json.dumps(raw).encode()[:-1] + b', "stop": NaN}',
        headers={"content-type": "application/json"},
    )
    item = _detail(r)
    assert item["msg"] == f"speed (stop) = nan: not a finite number; {SPEED_RANGE}"
    r = client.post(
        "/api/v1/toy/disc/study",
        json={
            "base": {"diameter": 0.2},
            "variables": [{"name": "speed", "low": "1e999 rpm", "high": 5}],
        },
    )
    assert _detail(r)["msg"] == (
        f"speed (low) = '1e999 rpm': '1e999 rpm' is not a finite quantity; {SPEED_RANGE}"
    )


def test_a_standard_deviation_is_a_width_not_a_value_of_the_input(client: TestClient) -> None:
    r = client.post(
        "/api/v1/toy/disc/study",
        json={
            "base": {"diameter": 0.2},
            "variables": [{"name": "speed", "distribution": "normal", "mean": 100, "sd": "2 m"}],
        },
    )
    assert _detail(r)["msg"] == (
        "speed (sd) = '2 m': 'm' has the wrong dimension: expected rad/s "
        "(write products as 'N*m'); "
        "allowed: a finite number > 0, in rad/s or as a string with a unit"
    )


def test_a_study_base_value_in_a_wrong_unit_names_its_input(client: TestClient) -> None:
    r = client.post(
        "/api/v1/toy/disc/study",
        json={"base": {"diameter": "3 kg"}, "variables": [{"name": "speed", "low": 1, "high": 5}]},
    )
    item = _detail(r)
    assert item["field"] == "diameter"
    assert item["msg"].startswith("diameter (base) = '3 kg': ")
    assert item["msg"].endswith(
        "allowed: a finite number > 0 m and ≤ 10 m, in m or as a string with a unit"
    )
    # strings in units convert: 100 rpm to 3000 rpm is a valid law for the speed
    ok = client.post(
        "/api/v1/toy/disc/study",
        json={
            "base": {"diameter": "200 mm"},
            "variables": [{"name": "speed", "low": "100 rpm", "high": "3000 rpm"}],
            "samples": 5,
            "fidelity": "exact",
        },
    )
    assert ok.status_code == 202, ok.text
