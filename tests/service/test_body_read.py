"""The model routes read their body as Starlette's ``Request.body`` does (service.api._body)."""

from __future__ import annotations

import asyncio
from typing import Any

import pytest
from starlette.requests import ClientDisconnect, Request

from service.api import _body

SCOPE = {"type": "http", "method": "POST", "path": "/p", "headers": []}


def _request(messages: list[dict[str, Any]]) -> Request:
    queue = list(messages)

    async def receive() -> dict[str, Any]:
        return queue.pop(0)

    return Request(dict(SCOPE), receive)


def _read(reader: Any, messages: list[dict[str, Any]]) -> tuple[Any, Request]:
    request = _request(messages)
    try:
        return asyncio.run(reader(request)), request
    except ClientDisconnect as exc:
        return exc, request


def _starlette(request: Request) -> Any:
    return request.body()


@pytest.mark.parametrize(
    "messages",
    [
        [{"type": "http.request", "body": b'{"a": 1}', "more_body": False}],
        [{"type": "http.request", "body": b'{"a": 1}'}],  # more_body absent: the last
        [{"type": "http.request"}],  # no body at all
        [
            {"type": "http.request", "body": b'{"a"', "more_body": True},
            {"type": "http.request", "body": b"", "more_body": True},
            {"type": "http.request", "body": b": 12}", "more_body": False},
        ],
    ],
)
def test_the_body_read_is_starlettes(messages: list[dict[str, Any]]) -> None:
    mine, request = _read(_body, messages)
    theirs, _ = _read(_starlette, messages)
    assert mine == theirs == b"".join(m.get("body", b"") for m in messages)
    assert asyncio.run(request.body()) == mine  # read once: Starlette's cache answers again


@pytest.mark.parametrize(
    "messages",
    [
        [{"type": "http.disconnect"}],
        [{"type": "http.request", "body": b"{", "more_body": True}, {"type": "http.disconnect"}],
    ],
)
def test_a_disconnect_mid_body_is_starlettes_client_disconnect(
    messages: list[dict[str, Any]],
) -> None:
    mine, request = _read(_body, messages)
    theirs, theirs_request = _read(_starlette, messages)
    assert isinstance(mine, ClientDisconnect) and isinstance(theirs, ClientDisconnect)
    assert request._is_disconnected and theirs_request._is_disconnected
