"""The generic model endpoints: one POST and one sweep per registered model.

Routes are a few lines each: turn the validated body into SI inputs, call
:func:`engine.run` or :func:`engine.sweep`, return what it gives. Engine
errors become HTTP statuses in :mod:`service.errors`.
"""

from collections.abc import Sequence
from typing import Any

from fastapi import APIRouter, HTTPException
from pydantic import BaseModel

import engine
from engine import ModelSpec

from . import schemas
from .units import UnitError, to_si

API_PREFIX = "/api/v1"
_COMMON = ("fidelity", "tolerance", "outputs")
_ERRORS: dict[int | str, dict[str, Any]] = {
    422: {"model": schemas.ErrorResponse, "description": "invalid input or infeasible design"},
}


def _inputs(body: BaseModel) -> dict[str, Any]:
    return {k: v for k, v in body.model_dump(exclude=set(_COMMON)).items() if v is not None}


def _response(result: engine.RunResult) -> dict[str, Any]:
    return {
        "model": result.model,
        "results": result.results,
        "units": result.units,
        "rung": result.rung,
        "error_estimate": result.error_estimate,
        "elapsed_s": result.elapsed_s,
        "checks": [vars(c) for c in result.checks],
        "notes": result.notes,
        "warnings": result.warnings,
        "series": result.series,
        "inputs": result.inputs,
    }


def _bound(spec: ModelSpec, name: str, value: float | str) -> float:
    """A sweep end point in SI units; unit strings use the varied input's unit."""
    unit = spec.param(name).unit
    if isinstance(value, str):
        try:
            return to_si(value, unit)
        except UnitError as exc:
            raise engine.InputOutOfRange(f"{exc}", field=name) from None
    return float(value)


def model_router(spec: ModelSpec) -> APIRouter:
    """``POST <path>`` and ``POST <path>/sweep`` for one model."""
    router = APIRouter(prefix=API_PREFIX, tags=[spec.family])
    request = schemas.request_model(spec)
    response = schemas.response_model(spec)
    sweep_request = schemas.sweep_request_model(spec)

    def evaluate(body: request) -> Any:  # type: ignore[valid-type]
        result = engine.run(
            spec,
            _inputs(body),
            fidelity=body.fidelity,  # type: ignore[attr-defined]
            tolerance=body.tolerance,  # type: ignore[attr-defined]
            outputs=body.outputs,  # type: ignore[attr-defined]
        )
        return _response(result)

    def sweep(body: sweep_request) -> Any:  # type: ignore[valid-type]
        start = _bound(spec, body.vary, body.start)  # type: ignore[attr-defined]
        stop = _bound(spec, body.vary, body.stop)  # type: ignore[attr-defined]
        values = engine.sweep_values(start, stop, body.num, body.scale)  # type: ignore[attr-defined]
        result = engine.sweep(
            spec,
            {k: v for k, v in body.base.model_dump().items() if v is not None},  # type: ignore[attr-defined]
            body.vary,  # type: ignore[attr-defined]
            values.tolist(),
            outputs=body.outputs,  # type: ignore[attr-defined]
            fidelity=body.fidelity,  # type: ignore[attr-defined]
            tolerance=body.tolerance,  # type: ignore[attr-defined]
        )
        return {
            "model": result.model,
            "vary": result.vary,
            "unit": spec.param(result.vary).unit,
            "values": result.values,
            "results": result.results,
            "units": result.units,
            "rung": result.rung,
            "elapsed_s": result.elapsed_s,
            "notes": result.notes,
            "warnings": result.warnings,
        }

    router.add_api_route(
        spec.path,
        evaluate,
        methods=["POST"],
        response_model=response,
        response_model_exclude_unset=True,
        summary=spec.title,
        description=f"{spec.summary}\n\nSource: {spec.source}",
        operation_id=spec.name.replace(".", "_"),
        responses=_ERRORS,
    )
    router.add_api_route(
        spec.path + "/sweep",
        sweep,
        methods=["POST"],
        response_model=schemas.SweepResponse,
        summary=f"{spec.title}: sweep one input",
        description="Evaluate the model with one input varied over a range; "
        "a point the model refuses is null in every output, with a note.",
        operation_id=spec.name.replace(".", "_") + "_sweep",
        responses=_ERRORS,
    )
    return router


def catalogue_router(models: Sequence[ModelSpec]) -> APIRouter:
    router = APIRouter(prefix=API_PREFIX, tags=["catalogue"])

    @router.get("/models", summary="Every model: inputs, units, ranges, outputs, rungs")
    def list_models() -> dict[str, Any]:
        return {"models": [spec.describe() for spec in models]}

    @router.get("/models/{name}", summary="One model's catalogue entry")
    def get_model(name: str) -> dict[str, Any]:
        for spec in models:
            if spec.name == name:
                return spec.describe()
        raise HTTPException(status_code=404, detail=f"no model named {name!r}")

    return router
