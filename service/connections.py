"""Connection-level guards uvicorn lacks: a deadline for each request head, a quiet log.

* :class:`HeadDeadline` (mixed into uvicorn's h11 and httptools protocols): a
  connection must deliver a complete request head (request line and headers)
  within ``HEADER_TIMEOUT_S`` of being opened or of its previous answer; else
  it is closed. A client that sends half a request and stalls (the issue: 200
  of 200 such connections still open after 60 s) is dropped. uvicorn's own
  ``timeout_keep_alive`` stops as soon as one byte arrives. The body has its
  own per-chunk deadline, ``BODY_TIMEOUT_S``, in :class:`service.middleware.BodyGuard`.
* :class:`FloodGuard`: a logging filter that lets each kind of line (logger and
  message template) through at most ``burst`` times per ``window_s`` and then
  counts the rest, reporting the count once the window ends. At the
  file-descriptor limit the accept loop logs one error per attempt (the issue:
  82 MB in 10 s); with this filter, a few lines.
"""

from __future__ import annotations

import asyncio
import logging
import os
import time
from typing import Any

from uvicorn.protocols.http.h11_impl import H11Protocol

HEADER_TIMEOUT_S = float(os.environ.get("HEADER_TIMEOUT_S", "10"))


class HeadDeadline:
    """Close the connection when a request head takes longer than ``header_timeout_s``."""

    header_timeout_s = HEADER_TIMEOUT_S
    _head_timer: asyncio.TimerHandle | None = None
    # provided by the uvicorn protocol this is mixed into
    loop: asyncio.AbstractEventLoop
    transport: asyncio.Transport
    cycle: Any

    def _arm(self) -> None:
        if self._head_timer is None:
            self._head_timer = self.loop.call_later(self.header_timeout_s, self._head_expired)

    def _disarm(self) -> None:
        if self._head_timer is not None:
            self._head_timer.cancel()
            self._head_timer = None

    def _head_expired(self) -> None:
        self._head_timer = None
        if self.cycle is None or self.cycle.response_complete:
            self.transport.close()  # no complete head in time: drop the connection

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        super().connection_made(transport)  # type: ignore[misc]
        self._arm()

    def data_received(self, data: bytes) -> None:
        super().data_received(data)  # type: ignore[misc]
        if self.cycle is not None and not self.cycle.response_complete:
            self._disarm()  # a head arrived; its body has BODY_TIMEOUT_S per chunk

    def on_response_complete(self) -> None:
        super().on_response_complete()  # type: ignore[misc]
        self._arm()  # the next request's head, if any, is on the clock

    def connection_lost(self, exc: Exception | None) -> None:
        self._disarm()
        super().connection_lost(exc)  # type: ignore[misc]


class GuardedH11Protocol(HeadDeadline, H11Protocol):
    """uvicorn's h11 protocol with a request-head deadline."""


try:
    from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol

    class GuardedHttpToolsProtocol(HeadDeadline, HttpToolsProtocol):
        """uvicorn's httptools protocol with a request-head deadline."""

    FAST_PROTOCOL: type[asyncio.Protocol] | None = GuardedHttpToolsProtocol
except ImportError:  # httptools not installed: h11
    FAST_PROTOCOL = None


def protocol() -> type[asyncio.Protocol]:
    """httptools when installed (faster parser), else h11; both with the head deadline."""
    return FAST_PROTOCOL or GuardedH11Protocol


class FloodGuard(logging.Filter):
    """At most ``burst`` lines of one kind per ``window_s``; the rest counted, then reported."""

    def __init__(self, burst: int = 5, window_s: float = 10.0) -> None:
        super().__init__()
        self.burst = burst
        self.window_s = window_s
        self._seen: dict[tuple[str, str], list[float]] = {}  # key -> [window start, count]

    def filter(self, record: logging.LogRecord) -> bool:
        if record.levelno < logging.WARNING:
            return True
        key = (record.name, str(record.msg))
        now = time.monotonic()
        slot = self._seen.get(key)
        if slot is None or now - slot[0] > self.window_s:
            dropped = int(slot[1]) - self.burst if slot is not None else 0
            self._seen[key] = [now, 1]
            if len(self._seen) > 1000:  # bounded memory: forget the oldest kinds
                for old in sorted(self._seen, key=lambda k: self._seen[k][0])[:500]:
                    del self._seen[old]
            if dropped > 0:
                record.msg = f"{record.msg} [{dropped} more like this in the last window]"
            return True
        slot[1] += 1
        return slot[1] <= self.burst
