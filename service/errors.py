"""Every error leaves as JSON of one shape: ``{"detail": [{type, loc, msg, field, ctx}]}``.

* invalid input (pydantic) and engine errors: 422, ``loc`` is the field path
  (``["body", "ball_diameter"]``) and ``msg`` names the allowed range;
* an infeasible design: 422 with ``type: "infeasible_design"`` and a plain sentence;
* HTTP errors (404, 405, 413): their status, same shape;
* anything unexpected: 500 with a generic message; the trace goes to the log only.
"""

from __future__ import annotations

import logging
import math
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from starlette.exceptions import HTTPException as StarletteHTTPException

from engine import EngineError

log = logging.getLogger("service")


def _json_safe(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, str | int | float | bool) or value is None:
        return value
    if isinstance(value, dict):
        return {str(k): _json_safe(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_json_safe(v) for v in value]
    return str(value)


def error_body(
    kind: str, msg: str, loc: list[Any], ctx: dict[str, Any] | None = None
) -> dict[str, Any]:
    field = ".".join(str(p) for p in loc[1:]) if len(loc) > 1 and loc[0] == "body" else None
    item: dict[str, Any] = {"type": kind, "loc": loc, "msg": msg, "field": field}
    if ctx:
        item["ctx"] = _json_safe(ctx)
    return {"detail": [item]}


async def _validation(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestValidationError)
    items = []
    for err in exc.errors():
        loc = [p for p in err.get("loc", ()) if p not in ("function-after", "function-before")]
        ctx = err.get("ctx")
        items.append(
            error_body(err.get("type", "invalid"), err.get("msg", "invalid"), loc, ctx)["detail"][0]
        )
    return JSONResponse(status_code=422, content={"detail": items})


async def _engine(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, EngineError)
    loc: list[Any] = ["body", exc.field] if exc.field else ["body"]
    return JSONResponse(
        status_code=422, content=error_body(exc.kind, exc.message, loc, exc.context)
    )


async def _http(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, StarletteHTTPException)
    return JSONResponse(
        status_code=exc.status_code,
        content=error_body("http_error", str(exc.detail), []),
        headers=getattr(exc, "headers", None),
    )


async def _unexpected(request: Request, exc: Exception) -> JSONResponse:
    log.exception("unhandled error on %s %s", request.method, request.url.path, exc_info=exc)
    return JSONResponse(
        status_code=500,
        content=error_body("internal_error", "internal error; it was logged on the server", []),
    )


def install(app: FastAPI) -> None:
    app.add_exception_handler(RequestValidationError, _validation)
    app.add_exception_handler(EngineError, _engine)
    app.add_exception_handler(StarletteHTTPException, _http)
    app.add_exception_handler(Exception, _unexpected)
