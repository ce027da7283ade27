"""Every error leaves as JSON of one shape: ``{"detail": [{type, loc, msg, field, ctx}]}``.

* invalid input (pydantic) and engine errors: 422, ``loc`` is the field path
  (``["body", "ball_diameter"]``) and ``msg`` names the allowed range;
* an infeasible design: 422 with ``type: "infeasible_design"`` and a plain sentence;
* HTTP errors (400 unreadable body, 404, 405, 413, 415): their status, same shape;
* no engine slot within the admission wait: 503 with ``Retry-After``;
* a computation withdrawn because its client disconnected: 499 (access log only);
* anything unexpected: 500 with a generic message and the request id, and
  ``Connection: close`` (:class:`service.middleware.FrontDoor`); one log line.
"""

from __future__ import annotations

import logging
import math
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from starlette.exceptions import HTTPException as StarletteHTTPException

from engine import Cancelled, EngineError

from .workers import Busy

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
    field = (
        ".".join(str(p) for p in loc[1:])
        if len(loc) > 1 and loc[0] == "body" and isinstance(loc[1], str)
        else None
    )
    item: dict[str, Any] = {"type": kind, "loc": loc, "msg": msg, "field": field}
    if ctx:
        item["ctx"] = _json_safe(ctx)
    return {"detail": [item]}


async def _validation(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestValidationError)
    items = []
    for err in exc.errors():
        if err.get("type") == "json_invalid":
            # malformed JSON is a bad request, like a body that is not UTF-8: 400, no field
            position = err.get("loc", ("body", "?"))[-1]
            reason = (err.get("ctx") or {}).get("error", "JSON decode error")
            return JSONResponse(
                status_code=400,
                content=error_body(
                    "json_invalid", f"the body is not valid JSON: {reason} (at {position})", []
                ),
            )
        loc = [p for p in err.get("loc", ()) if p not in ("function-after", "function-before")]
        ctx = err.get("ctx")
        items.append(
            error_body(err.get("type", "invalid"), err.get("msg", "invalid"), loc, ctx)["detail"][0]
        )
    return JSONResponse(status_code=422, content={"detail": items})


async def _engine(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, EngineError)
    loc: list[Any] = ["body", exc.field] if exc.field else ["body"]
    # 499 (nginx's "client closed request"): nobody reads it, the access log shows it
    status = 499 if isinstance(exc, Cancelled) else 422
    return JSONResponse(
        status_code=status, content=error_body(exc.kind, exc.message, loc, exc.context)
    )


def _unreadable(exc: BaseException | None) -> str | None:
    """Why FastAPI could not parse a body (it says only "error parsing the body")."""
    if isinstance(exc, RecursionError):
        return "the JSON body is nested too deeply"
    if isinstance(exc, UnicodeDecodeError):
        return f"the body is not valid UTF-8 (byte {exc.start})"
    if isinstance(exc, ValueError) and "digits" in str(exc):
        return "a number in the JSON body has too many digits"
    if exc is not None:
        return "the body is not valid JSON"
    return None


async def _http(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, StarletteHTTPException)
    msg = str(exc.detail)
    kind = getattr(exc, "kind", "http_error")
    if exc.status_code == 400:
        reason = _unreadable(exc.__cause__)
        if reason:
            msg, kind = reason, "json_invalid"
    return JSONResponse(
        status_code=exc.status_code,
        content=error_body(kind, msg, []),
        headers=getattr(exc, "headers", None),
    )


async def _busy(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, Busy)
    return JSONResponse(
        status_code=503,
        content=error_body("busy", str(exc), []),
        headers={"retry-after": str(exc.retry_after)},
    )


def install(app: FastAPI) -> None:
    app.add_exception_handler(RequestValidationError, _validation)
    app.add_exception_handler(EngineError, _engine)
    app.add_exception_handler(StarletteHTTPException, _http)
    app.add_exception_handler(Busy, _busy)
    # Anything else is caught by service.middleware.FrontDoor: 500, one log line,
    # Connection: close.
