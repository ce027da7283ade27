"""A model's POST routes are reached from the innermost middleware (service.middleware
.ExactRoutes with the exception handlers), skipping Starlette's exception layer, FastAPI's
exit stack and the router: each request answers exactly as it does through them."""

from __future__ import annotations

import asyncio
import json
from collections.abc import MutableMapping
from typing import Any

import pytest
from starlette.middleware.exceptions import ExceptionMiddleware

from bench.extra_service import call
from service import create_app
from service.middleware import ExactRoutes
from tests.service.asgi import json_post_scope
from tests.toys import TOY

BODIES = [
    json.dumps(TOY.examples[0]).encode(),  # an answer
    b'{"x": ',  # not JSON: 400
    b"[1, 2]",  # not an object: 422
    b"",  # no body: 422
    json.dumps({**TOY.examples[0], "fidelity": "no-such-rung"}).encode(),  # refused: 422
]


def _front(app: Any) -> ExactRoutes:
    asyncio.run(call(app, "GET", "/healthz"))  # the middleware stack is built on first use
    layer = app.middleware_stack
    while not isinstance(layer, ExactRoutes):
        layer = layer.app
    return layer


def _without_timing(body: bytes) -> Any:
    answer = json.loads(body)
    if isinstance(answer, dict):
        answer.pop("elapsed_s", None)
    return answer


@pytest.mark.parametrize("body", BODIES)
@pytest.mark.parametrize("suffix", ["", "/sweep"])
def test_a_model_route_answers_as_through_the_router(body: bytes, suffix: str) -> None:
    front = _front(create_app(models=[TOY]))
    assert isinstance(front.app, ExceptionMiddleware) and front.handlers is not None
    path = "/api/v1" + TOY.path + suffix
    assert path in front.routes
    direct = asyncio.run(call(front, "POST", path, body))
    routed = asyncio.run(call(front.app, "POST", path, body))  # the exception layer, the router
    assert direct[0] == routed[0] and direct[0] in (200, 400, 422)
    assert _without_timing(direct[1]) == _without_timing(routed[1])


def test_a_client_that_leaves_mid_body_is_no_internal_error(
    caplog: pytest.LogCaptureFixture,
) -> None:
    """The body's first part arrives, then the client disconnects: nothing is sent (no one
    is there), no internal error is logged, and the access line says 499."""
    app = create_app(models=[TOY])
    asyncio.run(call(app, "GET", "/healthz"))
    messages: list[dict[str, Any]] = [
        {"type": "http.request", "body": b'{"x": ', "more_body": True},
        {"type": "http.disconnect"},
    ]
    sent: list[MutableMapping[str, Any]] = []

    async def receive() -> dict[str, Any]:
        return messages.pop(0) if messages else {"type": "http.disconnect"}

    async def send(message: MutableMapping[str, Any]) -> None:
        sent.append(message)

    scope = json_post_scope("/api/v1" + TOY.path, host="test", client=("127.0.0.1", 1234))
    with caplog.at_level("INFO"):
        asyncio.run(app(scope, receive, send))
    assert sent == []
    assert not [r for r in caplog.records if "internal error" in r.getMessage()]
    lines = [json.loads(r.getMessage()) for r in caplog.records if r.name == "service.access"]
    assert [line["status"] for line in lines] == [499]
