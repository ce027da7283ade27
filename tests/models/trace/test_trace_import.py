"""Each importer reads its sample file in tests/data/ (made by us: the same M12 trace in four
exports) back to the trace it was written from, and the analysis reads the same rate."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

import engine
from engine.models.trace import M12_JOINT
from engine.procedures import trace_import as ti

DATA = Path(__file__).resolve().parents[2] / "data"
N = 200
DEG = math.pi / 180.0
#: The trace the four files hold: 0.3° and 1 ms a sample, 0.4 N·m run-down, 2.2 N·m/° from
#: 20°, 0.2 N·m/° past 56° (a yielding bolt); torques to 0.01 N·m as a controller logs them.
ANGLE_DEG = [round(0.3 * i, 1) for i in range(N)]
TORQUE = [
    round(max(0.4, 2.2 * (a - 20.0)) if a < 56 else 2.2 * 36 + 0.2 * (a - 56), 2) for a in ANGLE_DEG
]
TIME = [0.001 * i for i in range(N)]


def _same(trace: ti.Trace, *, time: bool = True) -> None:
    assert trace.angle == pytest.approx([a * DEG for a in ANGLE_DEG], abs=1e-12)
    assert trace.torque == pytest.approx(TORQUE, abs=1e-9)
    if time:
        assert trace.time == pytest.approx(TIME, abs=1e-12)


def test_csv_with_column_mapping_units_and_decimal_commas() -> None:
    text = (DATA / "trace_m12.csv").read_text(encoding="utf-8")
    trace = ti.read_csv(
        text, "Angle", "Torque", "Time", angle_unit="deg", torque_unit="Nm", time_unit="ms",
        decimal_comma=True,
    )  # fmt: skip
    _same(trace)
    in_ncm = ti.read_csv(
        text, "Angle", "Torque", angle_unit="°", torque_unit="N*cm", decimal_comma=True
    )
    assert in_ncm.torque[-1] == pytest.approx(TORQUE[-1] / 100) and in_ncm.time is None


def test_csv_refusals_name_the_field() -> None:
    text = (DATA / "trace_m12.csv").read_text(encoding="utf-8")
    cases: tuple[tuple[dict[str, Any], str], ...] = (
        ({"angle_column": "Winkel"}, "angle_column"),
        ({"torque_unit": "kgf"}, "torque_unit"),
        ({"decimal_comma": False}, "csv"),
    )
    for kwargs, field in cases:
        with pytest.raises(engine.InputOutOfRange) as caught:
            ti.read_csv(text, **{"angle_column": "Angle", "torque_column": "Torque", **kwargs})
        assert caught.value.field == field


def test_open_protocol_mid_0900_messages() -> None:
    messages = json.loads((DATA / "trace_m12_mid0900.json").read_text(encoding="utf-8"))
    _same(ti.read_open_protocol(messages))
    wrong = [{**messages[0], "unit": "077"}, messages[1]]
    with pytest.raises(engine.InputOutOfRange) as caught:
        ti.read_open_protocol(wrong)
    assert caught.value.field == "unit" and "'077'" in caught.value.message
    with pytest.raises(engine.InputOutOfRange) as caught:
        ti.read_open_protocol(messages[1:])
    assert caught.value.field == "traceType"


def test_opc_ua_step_traces_in_the_order_of_their_offsets() -> None:
    steps = json.loads((DATA / "trace_m12_opcua.json").read_text(encoding="utf-8"))
    assert steps[0]["StartTimeOffset"] > steps[1]["StartTimeOffset"]  # stored out of order
    _same(ti.read_opc_ua(steps))
    unit_ids = json.loads(json.dumps(steps))
    for s in unit_ids:
        for c in s["StepTraceContent"]:
            del c["EngineeringUnits"]["DisplayName"]  # UNECE codes NU and DD left
    _same(ti.read_opc_ua(unit_ids))


def test_rexroth_result_json() -> None:
    result = json.loads((DATA / "trace_m12_rexroth.json").read_text(encoding="utf-8"))
    _same(ti.read_rexroth(result))


@pytest.mark.parametrize(
    "read",
    [
        lambda: ti.read_rexroth(json.loads((DATA / "trace_m12_rexroth.json").read_text("utf-8"))),
        lambda: ti.read_opc_ua(json.loads((DATA / "trace_m12_opcua.json").read_text("utf-8"))),
    ],
)
def test_an_imported_trace_is_read_by_the_analysis(read: Any) -> None:
    r = engine.run(engine.get_model("trace.analysis"), {**M12_JOINT, **read().inputs()})
    assert r.results["elastic_rate"] == pytest.approx(2.2 / DEG, rel=0.01)
    assert r.results["yield_detected"] is True
    assert r.results["yield_angle"] == pytest.approx(56.0 * DEG, abs=1.0 * DEG)
