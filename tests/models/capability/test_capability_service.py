"""Samples through the API: a list in SI, or values with one unit; refusals; no sweep."""

from __future__ import annotations

import math
import time

import pytest
from fastapi.testclient import TestClient

import engine
from service import create_app

URL = "/api/v1/tool/capability"
#: 1 lbf·ft = 0.45359237 kg × 9.80665 m/s² × 0.3048 m, in N·m
LBF_FT = 0.45359237 * 9.80665 * 0.3048


def test_a_list_in_si(client: TestClient) -> None:
    r = client.post(URL, json={"torque_samples": [9.9, 10.0, 10.1], "nominal_torque": 10.0})
    assert r.status_code == 200, r.text
    body = r.json()
    assert math.isclose(body["results"]["mean_torque"], 10.0, rel_tol=1e-12)
    assert body["inputs"]["torque_samples"] == [9.9, 10.0, 10.1]


def test_values_with_one_unit_for_the_list(client: TestClient) -> None:
    r = client.post(
        URL,
        json={
            "torque_samples": {"values": [10, 11, 12], "unit": "lbf*ft"},
            "nominal_torque": "11 lbf*ft",
        },
    )
    assert r.status_code == 200, r.text
    results = r.json()["results"]
    assert math.isclose(results["mean_torque"], 11 * LBF_FT, rel_tol=1e-9)
    assert math.isclose(results["torque_sd"], 1.0 * LBF_FT, rel_tol=1e-9)


def test_refusal_names_field_index_and_range(client: TestClient) -> None:
    r = client.post(URL, json={"torque_samples": [10.0, -2.0, 11.0], "nominal_torque": 10.0})
    assert r.status_code == 422
    item = r.json()["detail"][0]
    assert item["field"] == "torque_samples"
    assert item["msg"].startswith("torque_samples[1] = -2 N*m is not allowed: must be a list of 2")
    assert "≥ 0 N*m" in item["msg"]
    assert (item["ctx"]["index"], item["ctx"]["minimum"], item["ctx"]["unit"]) == (1, 0.0, "N*m")
    r = client.post(URL, json={"torque_samples": [10.0], "nominal_torque": 10.0})
    ctx = r.json()["detail"][0]["ctx"]
    assert (ctx["min_length"], ctx["max_length"]) == (2, 10_000)


def test_wrong_unit_and_wrong_shape_are_422(client: TestClient) -> None:
    r = client.post(
        URL, json={"torque_samples": {"values": [1, 2], "unit": "mm"}, "nominal_torque": 1.0}
    )
    assert r.status_code == 422 and "wrong dimension" in r.text
    r = client.post(URL, json={"torque_samples": {"values": [1, 2]}, "nominal_torque": 1.0})
    assert r.status_code == 422 and "'values'" in r.text
    r = client.post(URL, json={"torque_samples": [1, "x"], "nominal_torque": 1.0})
    assert r.status_code == 422 and "torque_samples[1]" in r.text
    r = client.post(URL, json={"torque_samples": [1, True], "nominal_torque": 1.0})
    assert r.status_code == 422 and "torque_samples[1]" in r.text


def test_a_samples_input_is_not_swept(client: TestClient) -> None:
    r = client.post(
        URL + "/sweep",
        json={"base": {"nominal_torque": 10.0}, "vary": "torque_samples", "start": 1, "stop": 2},
    )
    assert r.status_code == 422
    item = r.json()["detail"][0]
    assert item["field"] == "vary" and "'nominal_torque'" in item["msg"]
    assert "torque_samples" not in item["msg"]


def test_the_catalogue_describes_the_samples_kind(client: TestClient) -> None:
    models = client.get("/api/v1/models").json()["models"]
    spec = next(m for m in models if m["name"] == "tool.capability")
    p = next(i for i in spec["inputs"] if i["name"] == "torque_samples")
    assert (p["kind"], p["min_length"], p["max_length"], p["unit"]) == ("samples", 2, 10_000, "N*m")


def test_a_study_holds_samples_fixed_and_refuses_to_vary_them(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Cmk = min(U − 10, 10 − L)/(3s) with s = 0.1 (samples 9.9, 10, 10.1), L, U = T ∓ 10 %."""
    monkeypatch.setenv("STUDY_INPROCESS_POINTS", "100000")  # no Dask here
    with TestClient(create_app(models=[engine.get_model("tool.capability")])) as c:
        r = c.post(
            URL + "/study",
            json={
                "base": {"torque_samples": [9.9, 10.0, 10.1]},
                "variables": [{"name": "nominal_torque", "low": 9.8, "high": 10.2}],
                "samples": 20,
                "outputs": ["critical_capability_index"],
            },
        )
        assert r.status_code == 202, r.text
        job = r.json()["job"]
        deadline = time.monotonic() + 30
        while (body := c.get(f"/api/v1/jobs/{job}").json())["state"] in ("queued", "running"):
            assert time.monotonic() < deadline
            time.sleep(0.05)
        assert body["state"] == "done", body
        stats = body["result"]["outputs"]["critical_capability_index"]
        # by hand: at T = 9.8, U = 10.78, L = 8.82: min(0.78, 1.18)/0.3 = 2.6; at 10.2: L = 9.18,
        # min(1.22, 0.82)/0.3 = 2.733; the best, 3.33 at T = 10: every point lies in 2.6…3.34
        assert stats["min"] >= 2.6 - 1e-9 and stats["max"] <= 10.0 / 3.0 + 1e-9
        r = c.post(
            URL + "/study",
            json={
                "base": {"nominal_torque": 10.0},
                "variables": [{"name": "torque_samples", "low": 1, "high": 2}],
            },
        )
        assert r.status_code == 422
        assert r.json()["detail"][0]["msg"] == (
            "variables: 'torque_samples' is not a numeric input of tool.capability"
        )
