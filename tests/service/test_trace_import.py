"""POST /api/v1/trace/import: each sample export of tests/data/ read over REST into the
inputs trace.analysis takes, the analysis of every one reading the same rate, and whatever
cannot be read a 422 naming the field, never a 500."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from engine.models.trace import M12_JOINT
from tests.apps import real_client

URL = "/api/v1/trace/import"
DATA = Path(__file__).resolve().parents[1] / "data"
DEG = math.pi / 180.0
N = 200
#: The trace the four sample files hold (tests/models/trace/test_trace_import.py): 0.3° and
#: 1 ms a sample; 2.2 N·m/° from 20° to 56°.
ANGLE = [round(0.3 * i, 1) * DEG for i in range(N)]
TIME = [0.001 * i for i in range(N)]
CSV = {
    "format": "csv",
    "angle_column": "Angle",
    "torque_column": "Torque",
    "time_column": "Time",
    "angle_unit": "deg",
    "torque_unit": "Nm",
    "time_unit": "ms",
    "decimal_comma": True,
}


@pytest.fixture(scope="module")
def real() -> TestClient:
    """The session's real app (tests/apps.py), not one more built for this module."""
    return real_client(raise_server_exceptions=False)


def _text(name: str) -> str:
    return (DATA / name).read_text(encoding="utf-8")


def _bodies() -> dict[str, dict[str, Any]]:
    return {
        "csv": {**CSV, "content": _text("trace_m12.csv")},
        "open_protocol": {
            "format": "open_protocol",
            "content": json.loads(_text("trace_m12_mid0900.json")),
        },
        "opc_ua": {"format": "opc_ua", "content": _text("trace_m12_opcua.json")},  # as text
        "rexroth": {"format": "rexroth", "content": json.loads(_text("trace_m12_rexroth.json"))},
    }


@pytest.mark.parametrize("fmt", ["csv", "open_protocol", "opc_ua", "rexroth"])
def test_each_sample_reads_into_the_analysis_inputs(real: TestClient, fmt: str) -> None:
    r = real.post(URL, json=_bodies()[fmt])
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["format"] == fmt and out["samples"] == N
    assert out["units"] == {"angle": "rad", "torque": "N*m", "time": "s"}
    inputs = out["inputs"]
    assert inputs["angle"] == pytest.approx(ANGLE, abs=1e-12)
    assert inputs["time"] == pytest.approx(TIME, abs=1e-12)
    assert inputs["torque"][0] == pytest.approx(0.4) and inputs["torque"][100] == pytest.approx(
        2.2 * (30.0 - 20.0)
    )
    # ready to send: the rate the analysis reads is the file's 2.2 N·m/°
    a = real.post("/api/v1/trace/analysis", json={**M12_JOINT, **inputs})
    assert a.status_code == 200, a.text
    assert a.json()["results"]["elastic_rate"] * DEG == pytest.approx(2.2, rel=0.002)


def _refusal(real: TestClient, body: Any) -> dict[str, Any]:
    r = real.post(URL, json=body)
    assert r.status_code == 422, (r.status_code, r.text)
    item: dict[str, Any] = r.json()["detail"][0]
    return item


def test_unreadable_traces_are_422_naming_the_field(real: TestClient) -> None:
    b = _bodies()
    cases: list[tuple[dict[str, Any], str, str]] = [
        ({**b["csv"], "angle_column": "Winkel"}, "angle_column", "not a column"),
        ({**b["csv"], "torque_unit": "kgf"}, "torque_unit", "not a unit we read"),
        ({**b["csv"], "decimal_comma": False}, "content", "is not a number"),
        ({**b["csv"], "content": {"a": 1}}, "content", "CSV text"),
        ({**b["csv"], "format": "xml"}, "format", ""),
        ({"format": "csv"}, "content", ""),
        ({**b["csv"], "wheels": 3}, "wheels", ""),
        ({**b["opc_ua"], "content": "{not json"}, "content", "is not JSON"),
        ({**b["rexroth"], "content": [1, 2]}, "content", "a result object"),
        ({**b["rexroth"], "content": {"tightening steps": "x"}}, "content", "not a readable"),
        ({**b["rexroth"], "content": {"tightening steps": []}}, "content.tightening steps",
         "missing or empty"),
        ({**b["open_protocol"], "content": b["open_protocol"]["content"][1:]},
         "content.traceType", "no angle trace"),
        ({**b["open_protocol"], "content": [{**b["open_protocol"]["content"][0], "unit": "077"},
                                            b["open_protocol"]["content"][1]]},
         "content.unit", "'077'"),
        ({**b["open_protocol"], "content": [{"mid": "abc"}]}, "content", "not a readable"),
        ({**b["opc_ua"], "content": [{"StepTraceContent": [{"Name": "Torque", "Values": 5,
                                                          "EngineeringUnits": "N*m"}]}]},
         "content.Values", "list of numbers"),
        ({**b["rexroth"], "content": {"tightening steps": [{"graph": {
            "angle values": list(range(5)), "torque values": list(range(5))}}]}},
         "content", "must hold 20 to 10000"),
    ]  # fmt: skip
    for body, field, words in cases:
        item = _refusal(real, body)
        assert item["field"] == field, (field, item)
        assert words in item["msg"], (words, item)


HOSTILE: list[Any] = [
    {},
    [],
    "text",
    {"format": "open_protocol", "content": [{"mid": 900, "traceType": "1", "unit": None}]},
    {"format": "open_protocol", "content": [{"mid": 900, "traceType": 1, "unit": "050",
                                             "coefficient": 1e308, "traceSample": [1e308] * 30},
                                            {"mid": 900, "traceType": 2, "unit": "001",
                                             "traceSample": [1.0] * 30}]},
    {"format": "open_protocol", "content": [{"mid": 900, "traceType": 1, "unit": "050",
                                             "coefficient": "nan", "traceSample": [1] * 30,
                                             "dataFields": [{"pid": "02213", "value": "x"}]}]},
    {"format": "opc_ua", "content": {"StepTraceContent": [{"Name": None}], "StartTimeOffset": []}},
    {"format": "opc_ua", "content": [{"StartTimeOffset": "soon"}, {"StartTimeOffset": 1}]},
    {"format": "opc_ua", "content": [[1, 2]]},
    {"format": "rexroth", "content": {"tightening steps": [None, 5, "x"]}},
    {"format": "rexroth", "content": {"tightening steps": [{"graph": []}]}},
    {"format": "rexroth", "content": "[" * 100_000},
    {"format": "csv", "content": "angle,torque\n" + "nan,inf\n" * 30},
    {"format": "csv", "content": "angle,torque\n" + "1e400,1\n" * 30},
    {"format": "csv", "content": ""},
    {"format": "csv", "content": "\x00\x01", "delimiter": "\x00"},
    {"format": "csv", "content": "a", "delimiter": ";;"},
]  # fmt: skip


@pytest.mark.parametrize("body", HOSTILE, ids=range(len(HOSTILE)))
def test_hostile_content_is_a_clean_422(real: TestClient, body: Any) -> None:
    r = real.post(URL, json=body)
    assert r.status_code == 422, (r.status_code, r.text)
    detail = r.json()["detail"]
    assert detail and all(d["msg"] for d in detail)


def test_the_route_is_named_and_published(real: TestClient) -> None:
    doc = real.get("/openapi.json").json()["paths"][URL]["post"]
    assert doc["operationId"] == "import_trace"
    assert {"200", "400", "413", "415", "422"} <= set(doc["responses"])
