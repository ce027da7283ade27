"""Connection-level guards uvicorn lacks: deadlines, a head size limit, a per-client cap.

* :class:`HeadDeadline` (mixed into uvicorn's h11 and httptools protocols):

  - a connection must deliver a complete request head (request line and headers)
    within ``HEADER_TIMEOUT_S`` of being opened or of its previous answer; else it
    is closed. A client that sends half a request and stalls (without this: 200 of 200
    such connections still open after 60 s) is dropped. uvicorn's own
    ``timeout_keep_alive`` stops as soon as one byte arrives. The whole body has its
    own deadline, ``BODY_TIMEOUT_S``, in :class:`service.middleware.BodyGuard`;
  - a request head over ``MAX_HEAD_BYTES`` gets a JSON 431 and the connection is
    closed (httptools has no limit of its own: 20 heads of 10 MB held 200 MB);
  - one client address holds at most ``MAX_CONNECTIONS_PER_CLIENT`` connections;
    a connection beyond that gets a JSON 503 with Retry-After and is closed, so one
    client trickling bytes on a thousand sockets cannot take every slot;
  - connections still waiting for their request (head or body not yet in, or idle
    between requests) hold at most ``WAITING_SHARE`` of ``MAX_CONNECTIONS``
    (``MAX_WAITING_CONNECTIONS`` where set): beyond it,
    a new connection sheds the one whose request has been coming in longest (an idle
    one, with no byte of a request yet, only when no request is part-sent), so many
    addresses each under the per-client cap cannot fill the server with trickling
    sockets either (measured: 10 addresses x 100 sockets left another client 14 % of
    its requests). A request that arrives promptly is never among the longest
    coming, a client's idle keep-alive connection is spared while tricklers remain,
    and ``/healthz`` keeps answering.

* :func:`service_unavailable`: uvicorn's answer beyond ``MAX_CONNECTIONS`` in all,
  JSON with Retry-After like every other 503 of the service (uvicorn's own is plain
  text without Retry-After).
* :class:`FloodGuard`: a logging filter that lets each kind of line (logger and
  message template) through at most ``burst`` times per ``window_s`` and then
  counts the rest, reporting the count once the window ends. At the
  file-descriptor limit the accept loop logs one error per attempt (measured:
  82 MB in 10 s); with this filter, a few lines.

The per-client cap keys on the TCP peer address, except for a connection from a
reverse proxy named in ``TRUSTED_PROXIES`` (:class:`Proxies`): there each request
counts for the client its ``X-Forwarded-For`` names while it is answered, so the
proxy's many users do not share one cap, and a client cannot pose as many by
sending the header itself (no address is trusted by default, loopback included).
"""

from __future__ import annotations

import asyncio
import ipaddress
import itertools
import json
import logging
import time
from collections import Counter
from typing import Any, ClassVar

import uvicorn.protocols.http.h11_impl as h11_impl
from uvicorn.protocols.http.h11_impl import H11Protocol

from .config import Settings
from .errors import error_body
from .middleware import SECURITY_HEADERS

_SETTINGS = Settings()  # read once per server process; nonsense stops it at start-up
HEADER_TIMEOUT_S = _SETTINGS.header_timeout_s
MAX_HEAD_BYTES = _SETTINGS.max_head_bytes
MAX_CONNECTIONS_PER_CLIENT = _SETTINGS.max_connections_per_client
#: The share of ``MAX_CONNECTIONS`` that connections waiting for their request may hold
#: (unless ``MAX_WAITING_CONNECTIONS`` says how many).
WAITING_SHARE = 0.5
MAX_WAITING = _SETTINGS.max_waiting_connections or max(
    1, int(WAITING_SHARE * _SETTINGS.max_connections)
)
#: Seconds a client is asked to wait before it tries again after a 503.
RETRY_AFTER_S = 1

log = logging.getLogger("service.connections")


def refusal(status: int, reason: str, kind: str, msg: str) -> bytes:
    r"""A whole HTTP/1.1 answer, JSON in the service's error shape, that closes the
    connection; a 503 says when to retry. Written straight to the transport by the
    protocol, where no ASGI app runs.

    >>> print(refusal(431, "Request Header Fields Too Large", "head_too_large", "big")
    ...       .decode().split("\r\n\r\n")[1])
    {"detail": [{"type": "head_too_large", "loc": [], "msg": "big", "field": null}]}
    """
    body = json.dumps(error_body(kind, msg, [])).encode()
    headers = [
        (b"content-type", b"application/json"),
        (b"content-length", str(len(body)).encode()),
        (b"connection", b"close"),
        *([(b"retry-after", str(RETRY_AFTER_S).encode())] if status == 503 else []),
        *SECURITY_HEADERS,
    ]
    head = f"HTTP/1.1 {status} {reason}\r\n".encode()
    head += b"".join(k + b": " + v + b"\r\n" for k, v in headers)
    return head + b"\r\n" + body


class Proxies:
    """The reverse proxies whose ``X-Forwarded-For`` is believed: addresses or networks.

    >>> p = Proxies(("10.0.0.0/8", "::1"))
    >>> "10.1.2.3" in p, "127.0.0.1" in p, "::1" in p, "unknown" in p
    (True, False, True, False)
    >>> p.client("10.0.0.2", "203.0.113.9, 10.0.0.7")  # the nearest address not a proxy's
    '203.0.113.9'
    >>> p.client("10.0.0.2", "")  # no header: the proxy itself
    '10.0.0.2'
    """

    def __init__(self, entries: tuple[str, ...]) -> None:
        self.networks = [ipaddress.ip_network(e, strict=False) for e in entries]

    def __contains__(self, host: str) -> bool:
        try:
            address = ipaddress.ip_address(host)
        except ValueError:
            return False
        return any(address in net for net in self.networks)

    def client(self, peer: str, forwarded: str) -> str:
        """The client a proxy at ``peer`` forwards for: the right-most ``X-Forwarded-For``
        entry that is not itself a trusted proxy (entries left of it are the client's word)."""
        for entry in reversed([e.strip() for e in forwarded.split(",") if e.strip()]):
            if entry not in self:
                return entry[:64]
        return peer


class HeadDeadline:
    """Close a connection whose request head is late or too large, or whose client
    already holds its share of connections."""

    header_timeout_s = HEADER_TIMEOUT_S
    max_head_bytes = MAX_HEAD_BYTES
    max_per_client = MAX_CONNECTIONS_PER_CLIENT
    max_waiting = MAX_WAITING
    #: Connections waiting for their request, in this server process, in the order they
    #: began to wait: idle (no byte of a request yet) and part-sent (a request begun).
    idle: ClassVar[dict[HeadDeadline, None]] = {}
    partial: ClassVar[dict[HeadDeadline, None]] = {}
    proxies = Proxies(_SETTINGS.trusted_proxies)
    #: Open connections per client address, in this server process.
    per_client: ClassVar[Counter[str]] = Counter()
    _head_timer: asyncio.TimerHandle | None = None
    _head_bytes = 0
    _client: str | None = None  # set while this connection is counted for its client
    _proxy: str | None = None  # a trusted proxy's address: its requests count per client
    _forwarded: str | None = None  # the client a proxied request in flight is counted for
    _refused = False
    # provided by the uvicorn protocol this is mixed into
    loop: asyncio.AbstractEventLoop
    transport: asyncio.Transport
    cycle: Any

    def _wait(self) -> None:
        """This connection waits for a request (at the end of the line); shed the longest
        waiting beyond ``max_waiting``: part-sent requests first, the longest coming."""
        self._served()
        self.idle[self] = None
        while len(self.idle) + len(self.partial) > self.max_waiting:
            line = itertools.chain(self.partial, self.idle)
            oldest = next((c for c in line if c is not self), None)
            if oldest is None:
                return
            oldest._shed()

    def _begun(self) -> None:
        """Bytes of its request came and it is not all in: part-sent, at the end of the line."""
        if self in self.idle:
            del self.idle[self]
            self.partial[self] = None

    def _served(self) -> None:
        """Its request is in (head and body), or it is closed: no longer waiting."""
        self.idle.pop(self, None)
        self.partial.pop(self, None)

    def _shed(self) -> None:
        """Close a connection that waited longest while the server is short of room: a
        part-sent head gets the JSON 503 (no app is running for it), an idle or a
        part-sent body is closed (the app reading it sees the client gone)."""
        self._served()
        log.warning("a slow connection shed: %d wait for their requests", self.max_waiting)
        if self._head_bytes and (self.cycle is None or self.cycle.response_complete):
            self._refuse(
                503,
                "Service Unavailable",
                "too_many_connections",
                f"over {self.max_waiting} connections are waiting for their requests; send a "
                "request promptly once connected, or retry after the Retry-After seconds",
            )
        else:
            self._disarm()
            self.transport.close()

    def _arm(self, seconds: float | None = None) -> None:
        if self._head_timer is None:
            self._head_bytes = 0
            self._head_timer = self.loop.call_later(
                self.header_timeout_s if seconds is None else seconds, self._head_expired
            )

    def _disarm(self) -> None:
        if self._head_timer is not None:
            self._head_timer.cancel()
            self._head_timer = None

    def _head_expired(self) -> None:
        self._head_timer = None
        if self._refused or self.cycle is None or self.cycle.response_complete:
            self.transport.close()  # no complete head in time: drop the connection

    def _refuse(self, status: int, reason: str, kind: str, msg: str) -> None:
        self._refused = True
        self._disarm()
        if not self.transport.is_closing():
            self.transport.write(refusal(status, reason, kind, msg))
            self.transport.close()

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        super().connection_made(transport)  # type: ignore[misc]
        peer = transport.get_extra_info("peername")
        client = str(peer[0]) if isinstance(peer, tuple) and peer else "unknown"
        if client in self.proxies:
            self._proxy = client  # counted per forwarded client, request by request
            self._arm()
            self._wait()
            return
        if self.per_client[client] >= self.max_per_client:
            # over the cap: answered (503) as soon as its request starts, and given only a
            # moment to start it, so such connections never pile up
            self._refused = True
            self._arm(min(1.0, self.header_timeout_s))
            log.warning("connection refused: a client holds %d connections", self.max_per_client)
            return
        self._client = client
        self.per_client[client] += 1
        self._arm()
        self._wait()

    def data_received(self, data: bytes) -> None:
        if self._refused:
            self._refuse(
                503,
                "Service Unavailable",
                "too_many_connections",
                f"this client has {self.max_per_client} connections open "
                "(MAX_CONNECTIONS_PER_CLIENT); reuse one, or retry after the Retry-After "
                "seconds",
            )
            return
        waiting = self.cycle is None or self.cycle.response_complete
        super().data_received(data)  # type: ignore[misc]
        if self.cycle is not None and not self.cycle.response_complete:
            self._disarm()  # a head arrived; its body has BODY_TIMEOUT_S in all
            self._head_bytes = 0
            if not self.cycle.more_body:
                self._served()  # the whole request is in
            else:
                self._begun()  # its body is still coming
            if self._proxy is not None and self._forwarded is None:
                self._count_forwarded(self._proxy)
        elif waiting and not self.transport.is_closing():
            self._head_bytes += len(data)  # still no complete head: count what it holds
            self._begun()
            if self._head_bytes > self.max_head_bytes:
                self._refuse(
                    431,
                    "Request Header Fields Too Large",
                    "head_too_large",
                    f"the request head is over {self.max_head_bytes} bytes (MAX_HEAD_BYTES)",
                )

    def _count_forwarded(self, proxy: str) -> None:
        """Count a proxied request for the client it is forwarded for, or refuse it (503)
        when that client already has its share in flight."""
        forwarded = b", ".join(
            v for k, v in self.cycle.scope["headers"] if k == b"x-forwarded-for"
        ).decode("latin-1")
        client = self.proxies.client(proxy, forwarded)
        if self.per_client[client] >= self.max_per_client:
            self._refuse(
                503,
                "Service Unavailable",
                "too_many_connections",
                f"this client has {self.max_per_client} requests open "
                "(MAX_CONNECTIONS_PER_CLIENT); retry after the Retry-After seconds",
            )
            return
        self._forwarded = client
        self.per_client[client] += 1

    def _uncount(self, attribute: str) -> None:
        client = getattr(self, attribute)
        if client is not None:
            self.per_client[client] -= 1
            if self.per_client[client] <= 0:
                del self.per_client[client]
            setattr(self, attribute, None)

    def on_response_complete(self) -> None:
        super().on_response_complete()  # type: ignore[misc]
        self._uncount("_forwarded")
        self._arm()  # the next request's head, if any, is on the clock
        if not self.transport.is_closing():
            self._wait()

    def connection_lost(self, exc: Exception | None) -> None:
        self._served()
        self._disarm()
        self._uncount("_client")
        self._uncount("_forwarded")
        super().connection_lost(exc)  # type: ignore[misc]


async def service_unavailable(scope: Any, receive: Any, send: Any) -> None:
    """uvicorn's answer beyond ``MAX_CONNECTIONS``: JSON with Retry-After, like every 503."""
    _, _, headers_and_body = refusal(
        503,
        "Service Unavailable",
        "too_many_connections",
        "the server has MAX_CONNECTIONS connections open; retry after the Retry-After seconds",
    ).partition(b"\r\n")
    head, _, body = headers_and_body.partition(b"\r\n\r\n")
    headers = [tuple(line.split(b": ", 1)) for line in head.split(b"\r\n")]
    await send({"type": "http.response.start", "status": 503, "headers": headers})
    await send({"type": "http.response.body", "body": body, "more_body": False})


# uvicorn's protocols look the name up in their own module at the limit: ours answers.
h11_impl.service_unavailable = service_unavailable


class GuardedH11Protocol(HeadDeadline, H11Protocol):
    """uvicorn's h11 protocol with a request-head deadline."""


try:
    import uvicorn.protocols.http.httptools_impl as httptools_impl
    from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol

    httptools_impl.service_unavailable = service_unavailable

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
