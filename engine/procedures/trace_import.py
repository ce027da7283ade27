"""Traces as tools export them, read into angle [rad], torque [N*m] and time [s].

Four formats, each parsed from text or decoded JSON with no other dependency:

* CSV with a column mapping and the units of the columns (:func:`read_csv`);
* Open Protocol MID 0900 trace messages decoded to JSON, one per trace type
  (:func:`read_open_protocol`; field layout as in docs/sources.md [OpenProtocol]);
* the OPC UA tightening ``StepTraceDataType`` written as JSON (:func:`read_opc_ua`;
  OPC 40450);
* the Bosch Rexroth result JSON (:func:`read_rexroth`; layout as pyscrew reads it).

A unit or a field that cannot be read is refused (:class:`InputOutOfRange` naming it), never
guessed. The result's :meth:`Trace.inputs` are the trace inputs of ``trace.analysis``.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..core.errors import InputOutOfRange

#: Factor to SI of each unit text a trace may carry (case and spaces as written).
ANGLE_UNITS = {
    "deg": math.pi / 180.0,
    "°": math.pi / 180.0,
    "degree": math.pi / 180.0,
    "rad": 1.0,
    "radian": 1.0,
    "rev": 2.0 * math.pi,
    "turn": 2.0 * math.pi,
}
TORQUE_UNITS = {
    "N*m": 1.0, "Nm": 1.0, "N·m": 1.0, "N.m": 1.0, "N m": 1.0,
    "N*cm": 0.01, "Ncm": 0.01, "N·cm": 0.01,
    "kN*m": 1e3, "kNm": 1e3,
    "lbf*ft": 0.45359237 * 9.80665 * 0.3048, "ft*lbf": 0.45359237 * 9.80665 * 0.3048,
    "ft·lbf": 0.45359237 * 9.80665 * 0.3048, "lbf·ft": 0.45359237 * 9.80665 * 0.3048,
    "lbf*in": 0.45359237 * 9.80665 * 0.0254, "in*lbf": 0.45359237 * 9.80665 * 0.0254,
    "lbf·in": 0.45359237 * 9.80665 * 0.0254,
}  # fmt: skip
TIME_UNITS = {"s": 1.0, "sec": 1.0, "ms": 1e-3, "min": 60.0}

#: Open Protocol unit codes [OpenProtocol] -> (quantity, factor to SI).
OPEN_PROTOCOL_UNITS: dict[str, tuple[str, float]] = {
    "001": ("torque", 1.0),
    "002": ("torque", TORQUE_UNITS["lbf*ft"]),
    "003": ("torque", TORQUE_UNITS["lbf*in"]),
    "008": ("torque", 0.01),
    "050": ("angle", math.pi / 180.0),
    "051": ("angle", 1.0),
    "200": ("time", 1.0),
    "201": ("time", 60.0),
    "202": ("time", 1e-3),
}
#: Open Protocol trace types [OpenProtocol].
OPEN_PROTOCOL_TRACE_TYPES = {1: "angle", 2: "torque"}
#: The data field holding the sample time interval of a MID 0900 trace.
TIME_INTERVAL_PID = "02213"


@dataclass(frozen=True)
class Trace:
    """One trace in SI: angle [rad], torque [N*m], time [s] or None."""

    angle: tuple[float, ...]
    torque: tuple[float, ...]
    time: tuple[float, ...] | None
    source: str

    def inputs(self) -> dict[str, list[float]]:
        """The trace inputs of ``trace.analysis``."""
        given = {"angle": list(self.angle), "torque": list(self.torque)}
        return given if self.time is None else {**given, "time": list(self.time)}


def _factor(table: Mapping[str, float], unit: str, field: str) -> float:
    text = str(unit).strip()
    for key, value in table.items():
        if text == key or text.lower() == key.lower():
            return value
    raise InputOutOfRange(
        f"{field} = {text!r} is not a unit we read: must be one of {', '.join(table)}",
        field=field,
    )


def _numbers(values: Any, field: str) -> list[float]:
    if isinstance(values, str | bytes) or not isinstance(values, Sequence):
        raise InputOutOfRange(
            f"{field}: must be a list of numbers (an encoded string is not read)", field=field
        )
    out = []
    for i, v in enumerate(values):
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            raise InputOutOfRange(f"{field}[{i}] = {v!r} is not a finite number", field=field)
        out.append(float(v))
    return out


def _trace(angle: list[float], torque: list[float], time: list[float] | None, source: str) -> Trace:
    if len(angle) != len(torque) or (time is not None and len(time) != len(angle)):
        raise InputOutOfRange(
            f"{source}: {len(angle)} angles, {len(torque)} torques"
            + ("" if time is None else f", {len(time)} times")
            + ": must be as many of each",
            field="torque",
        )
    return Trace(tuple(angle), tuple(torque), None if time is None else tuple(time), source)


# --------------------------------------------------------------------------- CSV


def _number(text: str, decimal_comma: bool) -> float:
    return float(text.replace(",", ".") if decimal_comma else text)


def read_csv(
    text: str,
    angle_column: str = "angle",
    torque_column: str = "torque",
    time_column: str | None = None,
    *,
    angle_unit: str = "deg",
    torque_unit: str = "N*m",
    time_unit: str = "s",
    delimiter: str | None = None,
    decimal_comma: bool = False,
) -> Trace:
    """A trace from CSV text with a header row: the named columns in the given units.

    The delimiter is sniffed (comma, semicolon, tab) unless given; a column is found by its
    header text, or by a header that starts with it ("Angle [deg]" for "Angle"), case
    ignored.

    >>> t = read_csv("Angle [deg];Torque [Nm]\\n0;0.5\\n90;10\\n", "Angle", "Torque",
    ...              angle_unit="deg", torque_unit="Nm")
    >>> [round(a, 6) for a in t.angle], t.torque
    ([0.0, 1.570796], (0.5, 10.0))
    """
    a_factor = _factor(ANGLE_UNITS, angle_unit, "angle_unit")
    t_factor = _factor(TORQUE_UNITS, torque_unit, "torque_unit")
    s_factor = _factor(TIME_UNITS, time_unit, "time_unit") if time_column else 1.0
    if delimiter is None:
        head = text.splitlines()[0] if text.strip() else ""
        delimiter = max((";", "\t", ","), key=head.count)
    rows = [
        r for r in csv.reader(io.StringIO(text), delimiter=delimiter) if any(c.strip() for c in r)
    ]
    if len(rows) < 2:
        raise InputOutOfRange(
            "csv: a header row and at least one row of values are needed", field="csv"
        )
    header = [h.strip().lower() for h in rows[0]]

    def column(name: str, field: str) -> int:
        want = name.strip().lower()
        for i, h in enumerate(header):
            if h == want:
                return i
        for i, h in enumerate(header):
            if h.startswith(want):
                return i
        raise InputOutOfRange(
            f"{field} = {name!r} is not a column of the CSV: its columns are {', '.join(rows[0])}",
            field=field,
        )

    wanted = [
        (column(angle_column, "angle_column"), a_factor),
        (column(torque_column, "torque_column"), t_factor),
    ]
    if time_column:
        wanted.append((column(time_column, "time_column"), s_factor))
    values: list[list[float]] = [[] for _ in wanted]
    for line, row in enumerate(rows[1:], start=2):
        for k, (i, factor) in enumerate(wanted):
            try:
                values[k].append(_number(row[i].strip(), decimal_comma) * factor)
            except (IndexError, ValueError):
                raise InputOutOfRange(
                    f"csv line {line}, column {rows[0][i]!r}: {row[i] if i < len(row) else ''!r} "
                    "is not a number",
                    field="csv",
                    line=line,
                ) from None
    return _trace(values[0], values[1], values[2] if time_column else None, "csv")


# --------------------------------------------------------------------------- Open Protocol


def _interval(message: Mapping[str, Any]) -> float | None:
    """The sample time interval [s] of a decoded MID 0900, from its PID 02213 field or its
    first resolution field."""
    for key in ("dataFields", "parameterFields"):
        for f in message.get(key) or ():
            if str(f.get("pid", f.get("parameterID", ""))).zfill(5) == TIME_INTERVAL_PID:
                _, factor = _op_unit(f.get("unit", "202"), "unit")
                return float(f.get("value", f.get("dataValue"))) * factor
    for f in message.get("resolutionFields") or ():
        _, factor = _op_unit(f.get("unit", "202"), "unit")
        return float(f.get("timeValue", f.get("value"))) * factor
    return None


def _op_unit(code: Any, field: str) -> tuple[str, float]:
    text = str(code).strip().zfill(3)
    if text not in OPEN_PROTOCOL_UNITS:
        raise InputOutOfRange(
            f"{field} = {code!r} is an Open Protocol unit code we do not read: must be one of "
            f"{', '.join(OPEN_PROTOCOL_UNITS)}",
            field=field,
        )
    return OPEN_PROTOCOL_UNITS[text]


def read_open_protocol(messages: Sequence[Mapping[str, Any]]) -> Trace:
    """A trace from decoded Open Protocol MID 0900 messages: one angle trace (type 1) and one
    torque trace (type 2) of one tightening, sampled at the same interval; MID 0901 messages
    (plotting parameters) among them are passed over.

    Each message: ``mid`` 900, ``traceType``, ``unit`` (code), ``traceSample`` (the values,
    times ``coefficient`` when given), and the time interval as data field PID 02213 or as
    the first resolution field ([OpenProtocol]).

    >>> msg = {"mid": 900, "traceType": 2, "unit": "001", "traceSample": [1, 2],
    ...        "dataFields": [{"pid": "02213", "value": 1, "unit": "202"}]}
    >>> t = read_open_protocol([msg, {**msg, "traceType": 1, "unit": "050"}])
    >>> t.torque, t.time
    ((1.0, 2.0), (0.0, 0.001))
    """
    traces: dict[str, tuple[list[float], float | None]] = {}
    for i, m in enumerate(messages):
        if int(m.get("mid", 900)) == 901:
            continue
        if int(m.get("mid", 900)) != 900:
            raise InputOutOfRange(
                f"messages[{i}]: mid = {m.get('mid')!r}: must be 900 or 901", field="mid"
            )
        kind = OPEN_PROTOCOL_TRACE_TYPES.get(int(m.get("traceType", 0)))
        if kind is None:
            continue  # current, gradient, stroke, force: not read
        quantity, factor = _op_unit(m.get("unit"), "unit")
        if quantity != kind:
            raise InputOutOfRange(
                f"messages[{i}]: unit code {m.get('unit')!r} is a {quantity} unit for a {kind} "
                "trace",
                field="unit",
            )
        scale = float(m.get("coefficient", 1.0))
        values = [v * scale * factor for v in _numbers(m.get("traceSample"), "traceSample")]
        traces[kind] = (values, _interval(m))
    missing = [k for k in ("angle", "torque") if k not in traces]
    if missing:
        raise InputOutOfRange(
            f"traceType: no {' and no '.join(missing)} trace (MID 0900 trace type "
            f"{'1' if 'angle' in missing else '2'}) among the messages",
            field="traceType",
        )
    (angle, da), (torque, dt) = traces["angle"], traces["torque"]
    step = dt if dt is not None else da
    if da is not None and dt is not None and not math.isclose(da, dt, rel_tol=1e-9):
        raise InputOutOfRange(
            f"the angle trace is sampled every {da:g} s and the torque trace every {dt:g} s: "
            "must be the same",
            field="dataFields",
        )
    time = None if step is None else [k * step for k in range(len(torque))]
    return _trace(angle, torque, time, "Open Protocol MID 0900")


# --------------------------------------------------------------------------- OPC UA


def _unit_text(eu: Any) -> str:
    """The unit of an EUInformation as text (its DisplayName, else its UNECE code's)."""
    if eu is None:
        return ""
    if isinstance(eu, str):
        return eu
    name = eu.get("DisplayName")
    if isinstance(name, Mapping):
        name = name.get("Text")
    if name:
        return str(name)
    unit_id = eu.get("UnitId")
    codes = {"NU": "N*m", "DD": "deg", "C81": "rad", "SEC": "s", "C26": "ms"}
    for code, text in codes.items():
        number = 0
        for ch in code:
            number = (number << 8) | ord(ch)
        if unit_id == number:
            return text
    return ""


def read_opc_ua(step_traces: Mapping[str, Any] | Sequence[Mapping[str, Any]]) -> Trace:
    """A trace from OPC UA ``StepTraceDataType`` values written as JSON (one, or a list of the
    steps of one tightening, put in order of their ``StartTimeOffset``) [OPC40450].

    Each ``StepTraceContent`` entry is told apart by its ``Name`` (torque, angle, time) and
    read in the unit of its ``EngineeringUnits``; without a time entry the times are
    ``SamplingInterval`` apart from ``StartTimeOffset``.

    >>> step = {"NumberOfTracePoints": 2, "SamplingInterval": 0.002, "StepTraceContent": [
    ...     {"Name": "Torque", "Values": [1.0, 2.0], "EngineeringUnits": {"DisplayName":
    ...      {"Text": "N·m"}}},
    ...     {"Name": "Angle", "Values": [0.0, 1.0], "EngineeringUnits": {"DisplayName":
    ...      {"Text": "rad"}}}]}
    >>> read_opc_ua(step).time
    (0.0, 0.002)
    """
    steps = [step_traces] if isinstance(step_traces, Mapping) else list(step_traces)
    steps.sort(key=lambda s: float(s.get("StartTimeOffset") or 0.0))
    angle: list[float] = []
    torque: list[float] = []
    time: list[float] = []
    for n, s in enumerate(steps):
        content = s.get("StepTraceContent")
        if not isinstance(content, Sequence) or not content:
            raise InputOutOfRange(
                f"steps[{n}]: StepTraceContent is missing", field="StepTraceContent"
            )
        found: dict[str, list[float]] = {}
        for entry in content:
            name = str(entry.get("Name") or "").lower()
            kind = next((k for k in ("torque", "angle", "time") if k in name), None)
            if kind is None:
                continue
            table = {"torque": TORQUE_UNITS, "angle": ANGLE_UNITS, "time": TIME_UNITS}[kind]
            unit = _unit_text(entry.get("EngineeringUnits")) or {"time": "s"}.get(kind, "")
            factor = _factor(table, unit, "EngineeringUnits")
            found[kind] = [v * factor for v in _numbers(entry.get("Values"), "Values")]
        for kind in ("angle", "torque"):
            if kind not in found:
                raise InputOutOfRange(
                    f"steps[{n}]: no StepTraceContent entry named {kind!r}",
                    field="StepTraceContent",
                )
        count = len(found["torque"])
        declared = s.get("NumberOfTracePoints")
        if declared is not None and int(declared) != count:
            raise InputOutOfRange(
                f"steps[{n}]: NumberOfTracePoints = {declared} but {count} torque values",
                field="NumberOfTracePoints",
            )
        start = float(s.get("StartTimeOffset") or 0.0)
        if "time" in found:
            times = [start + t for t in found["time"]]
        elif s.get("SamplingInterval") is not None:
            times = [start + k * float(s["SamplingInterval"]) for k in range(count)]
        else:
            raise InputOutOfRange(
                f"steps[{n}]: neither a time entry nor SamplingInterval", field="SamplingInterval"
            )
        angle += found["angle"]
        torque += found["torque"]
        time += times
    return _trace(angle, torque, time, "OPC UA StepTraceDataType")


# --------------------------------------------------------------------------- Rexroth


def read_rexroth(result: Mapping[str, Any]) -> Trace:
    """A trace from a Bosch Rexroth result JSON: the ``graph`` of each of its ``tightening
    steps`` in order, angles in degrees, torques in N·m, times in s (the layout pyscrew
    reads). A step whose angles start again below the last step's end is shifted to go on
    from it (the controller counts each step's angle from its own start).

    >>> g1 = {"angle values": [0, 90], "torque values": [0.5, 5], "time values": [0, 0.1]}
    >>> g2 = {"angle values": [0, 90], "torque values": [5, 9], "time values": [0.1, 0.2]}
    >>> r = {"tightening steps": [{"graph": g1}, {"graph": g2}]}
    >>> [round(a, 4) for a in read_rexroth(r).angle]
    [0.0, 1.5708, 1.5708, 3.1416]
    """
    steps = result.get("tightening steps")
    if not isinstance(steps, Sequence) or not steps:
        raise InputOutOfRange("'tightening steps' is missing or empty", field="tightening steps")
    angle: list[float] = []
    torque: list[float] = []
    time: list[float] | None = []
    for s in steps:
        graph = s.get("graph") or {}
        a = [v * math.pi / 180.0 for v in _numbers(graph.get("angle values"), "angle values")]
        t = _numbers(graph.get("torque values"), "torque values")
        if angle and a and a[0] < angle[-1]:
            shift = angle[-1] - a[0]
            a = [v + shift for v in a]
        angle += a
        torque += t
        given = graph.get("time values")
        if given is None or time is None:
            time = None
        else:
            time += _numbers(given, "time values")
    return _trace(angle, torque, time, "Rexroth result JSON")
