"""``POST /api/v1/trace/import``: a trace as a tool exports it, read into the inputs of
``/api/v1/trace/analysis`` (angle [rad], torque [N*m], time [s]).

The readers are the engine's (:mod:`engine.procedures.trace_import`); this route picks one
by the body's ``format``, decodes JSON given as text, and turns whatever cannot be read
into a 422 naming the field (``content`` and the path inside it, or the CSV option that
failed), never a 500 and never a guess.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Mapping
from typing import Any, Literal

from fastapi import APIRouter
from pydantic import BaseModel, ConfigDict, Field

from engine import EngineError, InputOutOfRange
from engine.models.trace import ANALYSIS
from engine.procedures import trace_import as ti

from . import schemas
from .api import _ERRORS

router = APIRouter(prefix="/api/v1/trace", tags=["trace"])

#: The body's CSV options: a reader's refusal naming one of them names it as it is.
_CSV_OPTIONS = frozenset(
    ("angle_column", "torque_column", "time_column", "angle_unit", "torque_unit", "time_unit")
)
#: Fewest and most samples a trace may have: those of trace.analysis's angle input.
_ANGLE = ANALYSIS.param("angle")
MIN_SAMPLES, MAX_SAMPLES = _ANGLE.min_length, _ANGLE.max_length


class TraceImport(BaseModel):
    """A trace as a tool exported it."""

    model_config = ConfigDict(extra="forbid")

    format: Literal["csv", "open_protocol", "opc_ua", "rexroth"] = Field(
        description="csv: text with a header row; open_protocol: decoded MID 0900 messages "
        "(a list); opc_ua: StepTraceDataType values (one or a list); rexroth: a result JSON"
    )
    content: str | list[Any] | dict[str, Any] = Field(
        description="The CSV text; or the JSON, decoded or as text"
    )
    angle_column: str = Field("angle", max_length=64, description="CSV: the angle's column")
    torque_column: str = Field("torque", max_length=64, description="CSV: the torque's column")
    time_column: str | None = Field(
        None, max_length=64, description="CSV: the time's column (absent: no times)"
    )
    angle_unit: str = Field("deg", max_length=16, description="CSV: unit of the angles")
    torque_unit: str = Field("N*m", max_length=16, description="CSV: unit of the torques")
    time_unit: str = Field("s", max_length=16, description="CSV: unit of the times")
    delimiter: str | None = Field(
        None, min_length=1, max_length=1, description="CSV: the delimiter (absent: sniffed)"
    )
    decimal_comma: bool = Field(False, description="CSV: numbers written 0,5 for 0.5")


class TraceInputs(BaseModel):
    angle: list[float]
    torque: list[float]
    time: list[float] | None = None


class TraceImported(BaseModel):
    format: str
    source: str
    samples: int
    #: The trace inputs of trace.analysis (and, concatenated, of trace.batch), SI.
    inputs: TraceInputs
    units: dict[str, str]


def _refused(message: str, field: str) -> InputOutOfRange:
    return InputOutOfRange(message, field=field)


def _decoded(body: TraceImport) -> Any:
    """The JSON content, decoded where it came as text."""
    content = body.content
    if not isinstance(content, str):
        return content
    try:
        return json.loads(content)
    except json.JSONDecodeError as exc:
        raise _refused(
            f"content is not JSON for format {body.format!r}: {exc.msg} at line {exc.lineno}, "
            f"column {exc.colno}",
            "content",
        ) from None
    except RecursionError:
        raise _refused("content: the JSON is nested too deeply", "content") from None


def _read(body: TraceImport) -> ti.Trace:
    if body.format == "csv":
        if not isinstance(body.content, str):
            raise _refused("content must be the CSV text (a string) for format 'csv'", "content")
        return ti.read_csv(
            body.content,
            body.angle_column,
            body.torque_column,
            body.time_column or None,
            angle_unit=body.angle_unit,
            torque_unit=body.torque_unit,
            time_unit=body.time_unit,
            delimiter=body.delimiter,
            decimal_comma=body.decimal_comma,
        )
    data = _decoded(body)
    shapes: dict[str, tuple[type | tuple[type, ...], str, Callable[[Any], ti.Trace]]] = {
        "open_protocol": (list, "a list of MID 0900 messages", ti.read_open_protocol),
        "opc_ua": ((dict, list), "a StepTraceDataType or a list of them", ti.read_opc_ua),
        "rexroth": (dict, "a result object", ti.read_rexroth),
    }
    kind, what, reader = shapes[body.format]
    if body.format == "open_protocol" and isinstance(data, dict):
        data = [data]  # one message: the reader then names the trace type it lacks
    if not isinstance(data, kind) or (
        isinstance(data, list) and not all(isinstance(d, Mapping) for d in data)
    ):
        raise _refused(f"content must be {what} for format {body.format!r}", "content")
    return reader(data)


def _checked(trace: ti.Trace) -> ti.Trace:
    n = len(trace.angle)
    if not MIN_SAMPLES <= n <= MAX_SAMPLES:
        raise _refused(
            f"content holds {n} samples: a trace must hold {MIN_SAMPLES} to {MAX_SAMPLES}",
            "content",
        )
    for name, values in (("angle", trace.angle), ("torque", trace.torque), ("time", trace.time)):
        for i, v in enumerate(values or ()):
            if not math.isfinite(v):
                raise _refused(
                    f"content: {name}[{i}] is not a finite number once in SI units", "content"
                )
    return trace


def read_trace(body: TraceImport) -> ti.Trace:
    """The trace ``body`` names, or InputOutOfRange naming the field that cannot be read."""
    try:
        return _checked(_read(body))
    except EngineError as exc:
        field = exc.field or "content"
        if field in ("csv", "torque"):  # the CSV text; angles and torques not as many
            field = "content"
        elif field not in _CSV_OPTIONS and field != "content":
            field = f"content.{field}"  # a field of the JSON content
        raise InputOutOfRange(exc.message, field=field, **exc.context) from None
    except (TypeError, ValueError, AttributeError, KeyError, IndexError, OverflowError) as exc:
        # a field of the wrong type deep in the JSON (a text where a number belongs, …)
        raise _refused(
            f"content is not a readable {body.format} export: {type(exc).__name__}: "
            f"{str(exc)[:120]}",
            "content",
        ) from None


@router.post(
    "/import",
    operation_id="import_trace",
    summary="Read a trace as a tool exports it into the inputs of trace.analysis",
    response_model=TraceImported,
    # the body checks every POST route has (400, 413, 415); no engine lane, so no 503
    responses={
        **{status: doc for status, doc in _ERRORS.items() if status != 503},
        422: {"model": schemas.ErrorResponse, "description": "a field or the content unreadable"},
    },
)
def import_trace(body: TraceImport) -> TraceImported:
    """CSV (column mapping and units), Open Protocol MID 0900, OPC UA StepTraceDataType or
    Rexroth result JSON, answered as angle [rad], torque [N*m] and time [s]: merge
    ``inputs`` with the joint's inputs and POST them to /api/v1/trace/analysis."""
    trace = read_trace(body)
    return TraceImported(
        format=body.format,
        source=trace.source,
        samples=len(trace.angle),
        inputs=TraceInputs(
            angle=list(trace.angle),
            torque=list(trace.torque),
            time=None if trace.time is None else list(trace.time),
        ),
        units={"angle": "rad", "torque": "N*m", "time": "s"},
    )
