"""The generic model endpoints: one POST and one sweep per registered model.

Routes are a few lines each: turn the validated body into SI inputs, call
:func:`engine.run` or :func:`engine.sweep` in the engine pool
(:mod:`service.workers`) with the request's budgets, return what it gives. A
single evaluation of a cheap rung runs inline on the event loop under a time
box (:class:`service.workers.Inline`); everything else in its lane.
Engine errors become HTTP statuses in :mod:`service.errors`.
"""

import asyncio
import json
import math
import threading
from collections.abc import Awaitable, Callable, Mapping, MutableMapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import orjson
from fastapi import APIRouter, HTTPException, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import Response
from fastapi.routing import APIRoute
from pydantic import BaseModel, ValidationError
from starlette._exception_handler import wrap_app_handling_exceptions
from starlette.requests import ClientDisconnect

import engine
import engine.core.runner
from engine import ModelSpec
from engine.core.runner import DEFAULT_BUDGET_S, DEFAULT_MAX_STEPS

from . import schemas
from .middleware import client_of
from .units import quantity
from .workers import EnginePool, FallBack, Lane, Ticket, watch_disconnect

API_PREFIX = "/api/v1"
_ERRORS: dict[int | str, dict[str, Any]] = {
    400: {"model": schemas.ErrorResponse, "description": "the body is not readable JSON"},
    413: {"model": schemas.ErrorResponse, "description": "request body over MAX_BODY_BYTES"},
    415: {"model": schemas.ErrorResponse, "description": "the body is not application/json"},
    422: {
        "model": schemas.ErrorResponse,
        "description": "invalid input, infeasible design, or a bound exceeded "
        "(wall-clock or step budget, series length)",
    },
    503: {
        "model": schemas.ErrorResponse,
        "description": "no engine slot came free within the admission wait; retry after "
        "the Retry-After header's seconds",
    },
}


class LimitExceeded(engine.EngineError):
    """A result over one of the service's bounds (422, naming the bound)."""

    kind = "limit_exceeded"


@dataclass(frozen=True)
class Limits:
    """The bounds every model call runs under (from :class:`service.config.Settings`)."""

    pool: EnginePool
    budget_s: float = DEFAULT_BUDGET_S
    max_steps: int = DEFAULT_MAX_STEPS
    max_series_points: int = 10_000


def _response(result: engine.RunResult, max_series_points: int) -> dict[str, Any]:
    for name, points in result.series.items():
        if len(points) > max_series_points:
            raise LimitExceeded(
                f"the series {name!r} has {len(points)} points, over the limit of "
                f"{max_series_points} (MAX_SERIES_POINTS); leave it out with `outputs` "
                "or simulate a shorter span",
                field="outputs",
                limit=max_series_points,
                points=len(points),
            )
    checks, notes, notes_parts = result.answer_sentences()  # each sentence read once
    return {
        "model": result.model,
        "results": result.results,
        "units": result.units,
        "rung": result.rung,
        "error_estimate": result.error_estimate,
        "error_kind": result.error_kind,
        "elapsed_s": result.elapsed_s,
        "checks": [
            {
                "name": c.name,
                "ok": c.ok,
                "detail": detail,
                "level": c.level,
                "detail_parts": detail_parts,
            }
            for c, detail, detail_parts in checks
        ],
        "notes": notes,
        "notes_parts": notes_parts,
        "warnings": result.warnings,
        "series": result.series,
        "inputs": result.inputs,
    }


class WrongKind(TypeError):
    """A model returned a result of another kind than it declares: a bug, answered 500."""


def _coerce(kind: str, value: Any) -> Any:
    """A result as the response model's lax mode gave it, or :class:`WrongKind` where that
    model refused it (a model bug is a 500, never a malformed answer).

    ``3.0`` → ``3`` for an int output, ``3`` → ``3.0`` for a float one, ``1`` → ``true``
    for a flag; text only for a text output.
    """
    kind_of = type(value)
    if kind == "float":
        if kind_of is float:
            return value
        if kind_of is int:
            return float(value)
    elif kind == "int":
        if kind_of is int:
            return value
        if kind_of is float and value.is_integer():
            return int(value)
    elif kind == "bool":
        if kind_of is bool:
            return value
        if kind_of is int and value in (0, 1):
            return bool(value)
    elif kind_of is str:
        return value
    raise WrongKind(f"a {kind_of.__name__} where the output is declared {kind}")


#: Per output kind, the type :func:`_coerce` passes through unchanged (text: ``str``).
_EXACT: dict[str, type] = {"float": float, "int": int, "bool": bool}


def _encoder(spec: ModelSpec) -> Any:
    """``answer dict -> JSON bytes`` for one model's single evaluation, as its response model
    (``schemas.response_model``, published for the route) serialised it.

    The engine already gives Python values, finite or None (:func:`engine.run`); what the
    response model added was a coercion of each result to its declared kind
    (:func:`_coerce`, which refuses another kind as the model did: a 500), a
    check's three fields and texts for notes. Encoding the dict with orjson, without
    validating it again, saves ~25 µs a request; tests/service/
    test_answer_encoding.py holds every model's answers, every rung and output, to the
    response model's own encoding, type for type.
    """
    kinds = {o.name: o.kind for o in spec.outputs if not o.series}
    # the type a result of each kind already has where _coerce leaves it as it is: the
    # common case answered without a call per result
    exact = {name: _EXACT.get(kind, str) for name, kind in kinds.items()}

    def encode(answer: dict[str, Any]) -> bytes:
        results = answer["results"]
        for name, value in results.items():
            if value is not None and type(value) is not exact[name]:
                results[name] = _coerce(kinds[name], value)
        checks = answer["checks"]
        for i, c in enumerate(checks):
            if not (type(c["name"]) is str and type(c["detail"]) is str):
                raise WrongKind("a check's name and detail are texts")
            # as _response made it (these five keys, in this order): kept as it is where
            # the response model would change nothing, else made again as it made it
            if type(c["ok"]) is not bool or "level" not in c or not c.get("detail_parts"):
                checks[i] = {
                    "name": c["name"],
                    "ok": c["ok"] if type(c["ok"]) is bool else _coerce("bool", c["ok"]),
                    "detail": c["detail"],
                    "level": c.get("level", "requirement"),
                    "detail_parts": c.get("detail_parts") or [c["detail"]],
                }
        for text in (*answer["notes"], *answer["warnings"]):
            if type(text) is not str:
                raise WrongKind("notes and warnings are texts")
        return orjson.dumps(answer, default=_plain, option=orjson.OPT_SERIALIZE_NUMPY)

    return encode


async def _body(request: Request) -> bytes:
    """The request body, as :meth:`starlette.requests.Request.body` reads it (the same
    messages taken, :class:`ClientDisconnect` on a disconnect, the request marked read
    as it marks it), without its async generator and its closing context: a body of
    one message, every API request's, is one ``receive``."""
    receive = request.receive
    message = await receive()
    if message["type"] == "http.request" and not message.get("more_body", False):
        raw = message.get("body", b"")  # the whole body at once
    else:
        chunks: list[bytes] = []
        while True:
            if message["type"] == "http.request":
                chunks.append(message.get("body", b""))
                if not message.get("more_body", False):
                    break
            elif message["type"] == "http.disconnect":
                request._is_disconnected = True
                raise ClientDisconnect()
            message = await receive()
        raw = b"".join(chunks)
    request._stream_consumed = True
    request._body = raw
    return raw


async def _json(request: Request) -> Any:
    """The request body parsed as FastAPI's own body handling parses it (the values its
    JSON parser gives, :func:`_parsed`; the same errors and their ``loc``), without its
    dependency machinery (~30 µs a request). The error handlers in :mod:`service.errors`
    turn what this raises into the same 400/422 answers."""
    raw = await _body(request)  # BodyGuard has checked the content type and the size
    if not raw:
        raise RequestValidationError(
            [{"type": "missing", "loc": ("body",), "msg": "Field required", "input": None}]
        )
    try:
        return _parsed(raw)
    except json.JSONDecodeError as exc:
        raise RequestValidationError(
            [
                {
                    "type": "json_invalid",
                    "loc": ("body", exc.pos),
                    "msg": "JSON decode error",
                    "input": {},
                    "ctx": {"error": exc.msg},
                }
            ]
        ) from exc
    except Exception as exc:  # not UTF-8, nested too deeply, a number of 4,300+ digits
        raise HTTPException(status_code=400, detail="There was an error parsing the body") from exc


def _parsed(raw: bytes) -> Any:
    """``json.loads(raw)``: by orjson where that gives the same value, which costs a fifth
    to a third of it (a request's body of 8 inputs 2.0 -> 0.3 µs; trace.analysis's two
    lists of 281 values 35 -> 8.5 µs, trace.batch's 16.5 kB 116 -> 36 µs), else by json.

    orjson reads every float as json does (0 of 287,597 lists of random literals differed,
    halfway cases and subnormals among them) and every integer that fits 64 bits. It is
    not asked where it would read otherwise: an integer literal of 19 digits or more
    (orjson gives a float past 64 bits where json gives the int, and json refuses 4,300
    digits), or a body of :data:`_NESTED` brackets or more (json refuses a nesting its
    recursion limit cannot reach, orjson only past 1,024). A body orjson refuses (a
    lone surrogate, a byte order mark, NaN, a number past the double's range, invalid
    JSON) goes to json, which reads it or raises the error it always raised.
    tests/service/test_body_parse.py holds the two to the same values.
    """
    if raw.count(b"[") + raw.count(b"{") < _NESTED and _LONG not in raw.translate(_DIGITS):
        try:
            return orjson.loads(raw)
        except orjson.JSONDecodeError:
            pass
    return json.loads(raw)


#: Every digit read as "0" (:func:`_parsed` looks for a run of 19: a long integer literal).
_DIGITS = bytes.maketrans(b"0123456789", b"0000000000")
_LONG = b"0" * 19
#: Bodies with this many brackets or more are read by json alone (:func:`_parsed`).
_NESTED = 200


def _model(data: Any, model: type[BaseModel]) -> Any:
    """``data`` validated as ``model``, errors located in the body as FastAPI locates them."""
    try:
        return model.model_validate(data, from_attributes=True)  # as FastAPI validates a body
    except ValidationError as exc:
        raise RequestValidationError(
            [{**err, "loc": ("body", *err["loc"])} for err in exc.errors(include_url=False)]
        ) from None


async def _validated(request: Request, model: type[BaseModel]) -> Any:
    """The request body read (:func:`_json`) and validated as ``model``."""
    return _model(await _json(request), model)


def _column(column: np.ndarray) -> Any:
    """A sweep column as orjson encodes it: float64/int/bool arrays as they are (a
    non-finite float becomes null, as :func:`engine.core.runner._listed` makes it None);
    object columns (texts, flags with None) as lists."""
    kind = column.dtype.kind
    if kind == "f":  # float32 would print its short repr; orjson takes C-contiguous arrays only
        return np.ascontiguousarray(column, dtype=np.float64)
    if kind in "iub":
        return np.ascontiguousarray(column)
    return column.tolist()


def _plain(value: Any) -> Any:
    """orjson's fallback: whatever numpy object a column or note still holds, as Python."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not JSON")


def _sweep_answer(result: engine.SweepResult, unit: str) -> Response:
    """The sweep's JSON, encoded from its numpy columns (no Python object per point).

    The shape is :class:`schemas.SweepResponse` (published as the route's response model);
    FastAPI does not re-validate a Response, so the tests hold every answer to that schema
    and to the list encoding point by point (tests/service/test_sweep_encoding.py).
    """
    body = {
        "model": result.model,
        "vary": result.vary,
        "unit": unit,
        "values": _column(result.value_array),
        "results": {name: _column(col) for name, col in result.columns.items()},
        "units": result.units,
        "rung": result.rung,
        "elapsed_s": result.elapsed_s,
        "notes": result.notes,
        "warnings": result.warnings,
        "rungs": _column(result.rung_array),
        "error_estimates": _column(result.error_array),
    }
    return Response(
        orjson.dumps(body, default=_plain, option=orjson.OPT_SERIALIZE_NUMPY),
        media_type="application/json",
    )


def _bound(spec: ModelSpec, name: str, value: float | str, end: str) -> float:
    """A sweep end point (``end``: start or stop) in SI units; unit strings use the varied
    input's unit (one reader with the study's law parameters: :func:`units.quantity`)."""
    return quantity(spec.param(name), value, end, field=end)


def _sweep_points(spec: ModelSpec, body: Any) -> list[float]:
    start = _bound(spec, body.vary, body.start, "start")
    stop = _bound(spec, body.vary, body.stop, "stop")
    if not math.isfinite(stop - start):
        # linspace over ±1e308 overflows to inf/nan; no input range is that wide
        param = spec.param(body.vary)
        raise engine.InputOutOfRange(
            f"{body.vary}: start and stop must lie within {param.range_text()}", field=body.vary
        )
    with np.errstate(all="ignore"):  # geomspace over 1e308 overflows: refused below
        values: list[float] = engine.sweep_values(start, stop, body.num, body.scale).tolist()
    if not all(math.isfinite(v) for v in values):
        param = spec.param(body.vary)
        raise engine.InputOutOfRange(
            f"{body.vary}: start and stop must lie within {param.range_text()}", field=body.vary
        )
    return values


def _fidelity_of(spec: ModelSpec, body: Any) -> str:
    if body.fidelity is not None:
        return str(body.fidelity)
    return "auto" if body.tolerance is not None else spec.default_fidelity


def _prepared(
    spec: ModelSpec, body: Any, inputs: dict[str, Any]
) -> engine.core.runner.Prepared | None:
    """The request validated and its rung chosen, once (None if refused: that is quick).

    A single evaluation hands it to :func:`engine.run`, which then neither validates nor
    chooses again.
    """
    try:
        return engine.core.runner.prepare(spec, inputs, body.fidelity, body.tolerance)
    except Exception:
        return None


@dataclass(frozen=True)
class _Rungs:
    """What routing asks of a model's rungs, found once when its routes are built."""

    heavy: frozenset[str]  #: rungs declared heavy (simulations): the heavy lane
    fallback: frozenset[str]  #: rungs with a fallback rung: never inline

    @classmethod
    def of(cls, spec: ModelSpec) -> "_Rungs":
        return cls(
            frozenset(r.name for r in spec.rungs if r.heavy),
            frozenset(r.name for r in spec.rungs if r.fallback is not None),
        )


def _route(
    spec: ModelSpec,
    body: Any,
    inputs: dict[str, Any],
    pool: EnginePool,
    sweep: bool,
    rungs: _Rungs | None = None,
) -> tuple[Lane, str | None, engine.core.runner.Prepared | None]:
    """The lane; for a single evaluation that may run inline, the rung it will run; and
    the request as :func:`_prepared` made it, where the rung had to be chosen to route it.

    The rung is None where inline is out: a heavy rung, a rung with a fallback,
    a sweep, inputs the rung choice refused. Without heavy rungs the fidelity
    asked for names the rung ("auto" then picks among cheap ones only). ``rungs``:
    the model's :class:`_Rungs`, found here where not given.
    """
    if rungs is None:
        rungs = _Rungs.of(spec)
    heavy = rungs.heavy
    prepared = None
    if not heavy and not sweep:
        rung: str | None = _fidelity_of(spec, body)
    else:
        fidelity = _fidelity_of(spec, body)
        if fidelity != "auto" and sweep:
            rung = fidelity
        else:
            prepared = _prepared(spec, body, inputs)
            rung = None if prepared is None else prepared.rung
        if rung in heavy:
            return pool.heavy, None, prepared
        if sweep:
            if spec.vectorized is None or rung not in spec.vector_rungs:
                return pool.heavy, None, None
            return pool.quick, None, None
    fallback = rungs.fallback
    if rung is None or rung in fallback or (rung == "auto" and fallback):
        return pool.quick, None, prepared
    return pool.quick, rung, prepared


async def _in_lane(request: Request, lane: Lane, fn: Any, budget_s: float, what: str) -> Any:
    """Run ``fn`` in ``lane``, withdrawing it if the client disconnects meanwhile."""
    ticket = Ticket(client_of(request.scope))  # the key's name, or the address
    watcher = asyncio.create_task(watch_disconnect(request.receive, ticket))
    try:
        return await lane.run(fn, budget_s, what, ticket)
    finally:
        watcher.cancel()


_Scope = MutableMapping[str, Any]
_Receive = Callable[[], Awaitable[MutableMapping[str, Any]]]
_Send = Callable[[MutableMapping[str, Any]], Awaitable[None]]
_ASGIApp = Callable[[_Scope, _Receive, _Send], Awaitable[None]]


def lean_endpoint(handler: Callable[[Request], Awaitable[bytes | Response]]) -> _ASGIApp:
    """A route's ASGI app for ``handler``, which answers JSON bytes (sent with status 200)
    or a :class:`Response`: :func:`starlette.routing.request_response` without the wrapper
    it builds around every request.

    An exception from ``handler`` goes through Starlette's own handling
    (``wrap_app_handling_exceptions``, with the handlers the scope carries): the same
    handler and answer, or raised on where none applies. The answer is sent outside it, as
    nothing was sent before; sending raises none of the exceptions that have a handler
    (those come from reading the body, validating and the engine). Bytes go as
    :class:`Response` sends them: ``content-length``, then ``content-type``.
    """

    async def app(scope: _Scope, receive: _Receive, send: _Send) -> None:
        request = Request(scope, receive, send)
        try:
            answer = await handler(request)
        except Exception as exc:
            await wrap_app_handling_exceptions(_raising(exc), request)(scope, receive, send)
            return
        if type(answer) is bytes:
            headers = [(b"content-length", str(len(answer)).encode()), _JSON_TYPE]
            await send({"type": "http.response.start", "status": 200, "headers": headers})
            await send({"type": "http.response.body", "body": answer})
        else:
            assert isinstance(answer, Response)
            await answer(scope, receive, send)

    return app


_JSON_TYPE = (b"content-type", b"application/json")


def _raising(exc: Exception) -> _ASGIApp:
    """An app that raises ``exc``: the handler's error, for Starlette's handling."""

    async def app(scope: _Scope, receive: _Receive, send: _Send) -> None:
        raise exc

    return app


def model_router(spec: ModelSpec, limits: Limits | None = None) -> APIRouter:
    """``POST <path>`` and ``POST <path>/sweep`` for one model.

    Each route publishes its typed request and response models in OpenAPI, but runs a
    lean handler, for speed: the body is parsed by :func:`_json` (FastAPI's parser and
    errors); a single evaluation's plain body is read by :func:`schemas.plain_reader`
    (the request model's own field validators, without pydantic), anything else is
    validated by the request model (:func:`_model`, FastAPI's error ``loc``). The answer
    is encoded with orjson: a single evaluation by :func:`_encoder` (the response model's
    coercions and kind checks, without validating it again), a sweep from its numpy
    columns (:func:`_sweep_answer`). The tests hold each to what it replaces
    (tests/service/test_plain_reader.py, test_answer_encoding.py, test_sweep_encoding.py,
    schemathesis over every route).
    """
    if limits is None:
        limits = Limits(pool=EnginePool())
    lim = limits
    router = APIRouter(prefix=API_PREFIX, tags=[spec.family])
    request_model = schemas.request_model(spec)
    response = schemas.response_model(spec)
    sweep_request = schemas.sweep_request_model(spec)

    encode = _encoder(spec)
    plain = schemas.plain_reader(spec)
    rungs = _Rungs.of(spec)
    inline = lim.pool.inline
    name = spec.name

    async def evaluate(request: Request) -> bytes:
        data = await _json(request)
        body = plain(data) or schemas.body_of(_model(data, request_model))
        inputs = body.inputs

        lane, rung, prepared = _route(spec, body, inputs, lim.pool, False, rungs)

        def work(budget_s: float, cancel: threading.Event | None) -> bytes:
            result = engine.run(
                spec,
                inputs,
                fidelity=body.fidelity,
                tolerance=body.tolerance,
                outputs=body.outputs,
                budget_s=budget_s,
                max_steps=lim.max_steps,
                series=body.series,
                cancel=cancel,
                prepared=prepared,
            )
            return encode(_response(result, lim.max_series_points))

        if rung is None:
            answer: bytes = await _in_lane(request, lane, work, lim.budget_s, name)
            return answer
        key = (name, rung, bool(body.series or body.outputs))
        if inline.allows(key):
            try:
                return inline.run(work, key, lim.budget_s)
            except FallBack:  # it checks its budget and needs longer than the time box
                pass
        answer = await _in_lane(request, lane, inline.timed(work, key), lim.budget_s, name)
        return answer

    async def sweep(request: Request) -> Response:
        body: Any = await _validated(request, sweep_request)
        values = _sweep_points(spec, body)
        base = {k: v for k, v in body.base.model_dump().items() if v is not None}

        def work(budget_s: float, cancel: threading.Event) -> Response:
            result = engine.sweep(
                spec,
                base,
                body.vary,
                values,
                outputs=body.outputs,
                fidelity=body.fidelity,
                tolerance=body.tolerance,
                budget_s=budget_s,
                max_steps=lim.max_steps,
                cancel=cancel,
            )
            return _sweep_answer(result, spec.param(result.vary).unit)

        point = {**base, body.vary: values[0]}
        lane, _, _ = _route(spec, body, point, lim.pool, True, rungs)
        return await _in_lane(request, lane, work, lim.budget_s, f"{spec.name} sweep")

    # What OpenAPI publishes: the typed signatures (request and response models). What
    # runs: the handlers above, each reading its body itself (:func:`_validated`).
    async def evaluate_doc(body: request_model) -> Any:  # type: ignore[valid-type]
        raise NotImplementedError  # pragma: no cover - never routed

    async def sweep_doc(body: sweep_request) -> Any:  # type: ignore[valid-type]
        raise NotImplementedError  # pragma: no cover - never routed

    router.add_api_route(
        spec.path,
        evaluate_doc,
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
        sweep_doc,
        methods=["POST"],
        response_model=schemas.SweepResponse,
        summary=f"{spec.title}: sweep one input",
        description="Evaluate the model with one input varied over a range; "
        "a point the model refuses is null in every output, with a note.",
        operation_id=spec.name.replace(".", "_") + "_sweep",
        responses=_ERRORS,
    )
    handlers: tuple[Callable[[Request], Awaitable[bytes | Response]], ...] = (evaluate, sweep)
    for route, handler in zip(router.routes[-2:], handlers, strict=True):
        assert isinstance(route, APIRoute)
        route.app = lean_endpoint(handler)
    return router


def catalogue_router(
    models: Sequence[ModelSpec], about: Mapping[str, Any] | None = None
) -> APIRouter:
    """``/models`` (every model, and ``service``: what the form needs besides the models,
    so it fetches nothing else to start: the product's version and commit, and the paths
    of the other catalogues it offers), ``/models/{name}`` and ``/sources``."""
    router = APIRouter(prefix=API_PREFIX, tags=["catalogue"])

    service = dict(about or {})  # fixed once the app is built
    # the entries are made on the first request that reads them (~0.07 s of a start-up,
    # measured, which /readyz does not need), then kept
    catalogue: dict[str, Any] = {}
    entries: dict[str, dict[str, Any]] = {}
    describing = threading.Lock()

    def described() -> dict[str, Any]:
        with describing:
            if not catalogue:
                made = [spec.describe() for spec in models]
                entries.update((spec.name, e) for spec, e in zip(models, made, strict=True))
                catalogue.update(models=made, service=service)
        return catalogue

    @router.get(
        "/models",
        operation_id="list_models",
        summary="Every model: inputs, units, ranges, outputs, rungs",
    )
    def list_models() -> dict[str, Any]:
        return described()

    @router.get(
        "/models/{name}",
        operation_id="get_model",
        summary="One model's catalogue entry",
        responses={404: {"model": schemas.ErrorResponse, "description": "no such model"}},
    )
    def get_model(name: str) -> dict[str, Any]:
        described()
        if name in entries:
            return entries[name]
        raise HTTPException(status_code=404, detail=f"no model named {name[:80]!r}")

    sources = {"sources": engine.core.sources.catalogue()}

    @router.get(
        "/sources",
        operation_id="list_sources",
        summary="Every cited source: [000, eq. 5] resolves here",
    )
    def list_sources() -> dict[str, Any]:
        return sources

    return router
