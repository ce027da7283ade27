"""BodyGuard's time box on each piece of a body (service.middleware._within): a piece that
is there already is taken without a timer; one that waits is timed, and only the timer's
own cancellation becomes a 408."""

from __future__ import annotations

import asyncio
from typing import Any

import pytest

from service.middleware import BodyTimeout, _within

PIECE = {"type": "http.request", "body": b"{}", "more_body": False}


def test_a_piece_that_is_there_is_taken_without_a_timer() -> None:
    async def ready() -> dict[str, Any]:
        return PIECE

    async def main() -> tuple[Any, int]:
        loop = asyncio.get_running_loop()
        before = len(loop._scheduled)  # type: ignore[attr-defined]
        got = await _within(ready, 5.0, 10.0)
        return got, len(loop._scheduled) - before  # type: ignore[attr-defined]

    got, timers = asyncio.run(main())
    assert got is PIECE and timers == 0


def test_a_piece_that_comes_later_is_waited_for_and_its_timer_cancelled() -> None:
    async def later() -> dict[str, Any]:
        await asyncio.sleep(0.01)
        await asyncio.sleep(0)
        return PIECE

    async def main() -> tuple[Any, bool]:
        loop = asyncio.get_running_loop()
        got = await _within(later, 5.0, 10.0)
        timers = [h for h in loop._scheduled if not h.cancelled()]  # type: ignore[attr-defined]
        return got, any(h.when() > loop.time() + 1.0 for h in timers)

    got, pending = asyncio.run(main())
    assert got is PIECE and not pending


def test_a_piece_that_never_comes_is_a_body_timeout_naming_the_whole_budget() -> None:
    async def never() -> dict[str, Any]:
        await asyncio.Event().wait()
        raise AssertionError("unreachable")

    with pytest.raises(BodyTimeout) as caught:
        asyncio.run(_within(never, 0.02, 7.0))
    assert "7 s" in caught.value.detail and caught.value.status_code == 408


def test_a_cancellation_from_elsewhere_goes_on_as_it_came() -> None:
    async def never() -> dict[str, Any]:
        await asyncio.Event().wait()
        raise AssertionError("unreachable")

    async def main() -> None:
        task = asyncio.create_task(_within(never, 5.0, 10.0))
        await asyncio.sleep(0.01)
        task.cancel()
        await task

    with pytest.raises(asyncio.CancelledError):
        asyncio.run(main())


def test_an_error_from_receive_comes_through_either_way() -> None:
    async def fails_at_once() -> dict[str, Any]:
        raise ConnectionResetError("gone")

    async def fails_later() -> dict[str, Any]:
        await asyncio.sleep(0.005)
        raise ConnectionResetError("gone later")

    for receive in (fails_at_once, fails_later):
        with pytest.raises(ConnectionResetError):
            asyncio.run(_within(receive, 5.0, 10.0))
