"""Plain ASGI middleware (no per-request objects beyond a closure): cheap enough for every call.

* :class:`FrontDoor` (outermost): a request id, security headers on every
  response, redirects to a path on this server (never the request's Host), one
  JSON access-log line per request (never the body), and gzip for a client that
  accepts it, for answers and files of a minimum size (Starlette's GZipMiddleware,
  asked only where it can help: one layer, not two, on every request).
* :class:`BodyGuard`: JSON bodies only (415 otherwise) and at most
  ``MAX_BODY_BYTES`` (413), counted as the bytes arrive, so a chunked body
  without ``content-length`` is cut off as soon as it passes the limit; the whole
  body within ``BODY_TIMEOUT_S`` (408).
* :class:`ApiKeys`: with API keys configured, every ``/api/v1`` request carries a known
  one (401 otherwise) and its name becomes the client's identity (:func:`client_of`).
"""

from __future__ import annotations

import asyncio
import hashlib
import hmac
import itertools
import json
import logging
import os
import re
import time
from collections.abc import Awaitable, Callable, MutableMapping
from json.encoder import encode_basestring_ascii as _string
from typing import Any
from urllib.parse import urlsplit

from starlette.exceptions import HTTPException
from starlette.middleware.gzip import GZipMiddleware
from starlette.requests import ClientDisconnect

from .config import ApiKey

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

access_log = logging.getLogger("service.access")
error_log = logging.getLogger("service")

#: The page and every API answer: nothing but our own files, no frames, no plugins.
STRICT_CSP = (
    "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
    "connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'; "
    "form-action 'self'"
)

#: Sent with every response (the CSP only when the route did not set its own, see /docs).
SECURITY_HEADERS: tuple[tuple[bytes, bytes], ...] = (
    (b"x-content-type-options", b"nosniff"),
    (b"x-frame-options", b"DENY"),
    (b"referrer-policy", b"no-referrer"),
    (b"cross-origin-opener-policy", b"same-origin"),
)
_CSP = b"content-security-policy"
_REQUEST_ID = re.compile(rb"[A-Za-z0-9._-]{1,64}")


def security_headers(request_id: str | None = None) -> dict[str, str]:
    """The same headers as a dict, for responses sent outside the middleware (500s)."""
    headers = {k.decode(): v.decode() for k, v in SECURITY_HEADERS}
    headers[_CSP.decode()] = STRICT_CSP
    if request_id:
        headers["x-request-id"] = request_id
    return headers


class Quiet:
    """How many HTTP requests are open in this process and when the last one ended, so
    that work the service does once it is ready (building the unit registry) can wait for
    a quiet moment instead of taking the processor from the first requests.

    :class:`FrontDoor` counts every request, on the event loop's thread; another thread
    only reads the two numbers.

    >>> q = Quiet(); q.begin(); q.open
    1
    >>> q.wait(quiet_s=0.0, limit_s=0.05)  # one request open: waits to its limit
    False
    >>> q.end(); q.wait(quiet_s=0.0, limit_s=1.0)
    True
    """

    def __init__(self) -> None:
        self.open = 0
        self.last = time.monotonic()

    def begin(self) -> None:
        self.open += 1

    def end(self) -> None:
        self.open -= 1
        self.last = time.monotonic()

    def wait(self, quiet_s: float, limit_s: float, poll_s: float = 0.02) -> bool:
        """Block until no request has been open for ``quiet_s`` [s], at most ``limit_s``
        [s]; whether it found that moment."""
        deadline = time.monotonic() + limit_s
        while True:
            now = time.monotonic()
            if self.open == 0 and now - self.last >= quiet_s:
                return True
            if now >= deadline:
                return False
            time.sleep(poll_s)


#: The process's requests, counted by every :class:`FrontDoor`.
QUIET = Quiet()


class FrontDoor:
    """Request id, security headers and a structured access log for every HTTP request.

    The request id is the caller's ``X-Request-ID`` when it is a short token
    (letters, digits, ``._-``), else a fresh one; it is echoed in the
    response header, kept in ``scope["state"]["request_id"]`` for error
    handlers, and written in the log line::

        {"method": "POST", "path": "/api/v1/toy/disc", "status": 200,
         "duration_ms": 1.42, "request_id": "3f2a…"}
    """

    #: Files that are compressed already (the form's and the manual's images, fonts).
    PACKED = (".png", ".jpg", ".jpeg", ".gif", ".webp", ".avif", ".ico", ".woff", ".woff2", ".gz")

    def __init__(
        self,
        app: ASGIApp,
        *,
        log_requests: bool = True,
        gzip_minimum_size: int | None = None,
        gzip_level: int = 6,
    ) -> None:
        self.app = app
        self.log_requests = log_requests
        self._csp = STRICT_CSP.encode()
        #: gzip, inside the headers and the log (they go on either body): Starlette's
        #: :class:`GZipMiddleware` around the same ``app``, asked only when the client
        #: accepts gzip and the path is not an already-compressed file (judged by its
        #: extension here, instead of its content type per response): it costs ~25 µs a
        #: request even for an answer it leaves alone. None: never compress.
        self.gzip: ASGIApp | None = (
            None
            if gzip_minimum_size is None
            else GZipMiddleware(
                app,
                minimum_size=gzip_minimum_size,
                compresslevel=gzip_level,
                exclude_content_types=(),
            )
        )

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        start = time.perf_counter()
        # one pass over the headers: the caller's request id, and whether it takes gzip
        # (the first of each)
        given = encoding = None
        for key, value in scope.get("headers") or ():
            if key == b"accept-encoding":
                if encoding is None:
                    encoding = value
            elif given is None and key.lower() == b"x-request-id":
                given = bytes(value)
        rid = given if given and _REQUEST_ID.fullmatch(given) else _fresh_id()
        # gzip's wrapper where it can help, else the app
        inner = (
            self.gzip
            if self.gzip is not None
            and encoding is not None
            and b"gzip" in encoding
            and not scope["path"].endswith(self.PACKED)
            else self.app
        )
        request_id = rid.decode()
        scope.setdefault("state", {})["request_id"] = request_id
        status = 500
        started = False
        QUIET.begin()

        async def send_with_headers(message: Message) -> None:
            nonlocal status, started
            if message["type"] == "http.response.start":
                started = True
                status = message["status"]
                message["headers"] = _with_ours(message.get("headers", ()), self._csp, rid)
            await send(message)

        try:
            await inner(scope, receive, send_with_headers)
        except ClientDisconnect:
            # the client left while its body was being read: there is no one to answer,
            # and nothing went wrong here; logged as 499 (client closed request)
            status = 499
        except Exception as exc:  # the one place every unexpected error ends
            status = 500
            # one line, no traceback: the type and where it was raised are enough to
            # find it, and a flood of bad requests cannot flood the log
            tb = exc.__traceback__
            while tb is not None and tb.tb_next is not None:
                tb = tb.tb_next
            where = f"{tb.tb_frame.f_code.co_filename}:{tb.tb_lineno}" if tb else "?"
            error_log.error(
                "internal error %s at %s on %s %s (request %s)",
                type(exc).__name__,
                where,
                scope.get("method"),
                scope.get("path"),
                request_id,
            )
            if not started:
                await _send_500(send, request_id, rid)
            # else: the answer is half sent; returning without finishing it makes the
            # server close the connection, which is all a client can be told now
        finally:
            QUIET.end()
            if self.log_requests and access_log.isEnabledFor(logging.INFO):
                _log_access(scope, status, time.perf_counter() - start, request_id)


def _with_ours(
    headers: Any, csp: bytes, rid: bytes, _server: bytes = b"server", _location: bytes = b"location"
) -> list[tuple[bytes, bytes]]:
    """A response's headers as they leave: ``server`` dropped, a redirect's ``location``
    made local (:func:`_local`), the strict CSP unless the route set its own, the security
    headers and the request id after them; one pass.

    >>> _with_ours([(b"Server", b"x"), (b"location", b"http://h/a"), (b"x-a", b"1")], b"C", b"r")
    ... # doctest: +NORMALIZE_WHITESPACE
    [(b'location', b'/a'), (b'x-a', b'1'), (b'content-security-policy', b'C'),
     (b'x-content-type-options', b'nosniff'), (b'x-frame-options', b'DENY'),
     (b'referrer-policy', b'no-referrer'), (b'cross-origin-opener-policy', b'same-origin'),
     (b'x-request-id', b'r')]
    >>> [k for k, _ in _with_ours([(b"Content-Security-Policy", b"own")], b"C", b"r")][:2]
    [b'Content-Security-Policy', b'x-content-type-options']
    """
    out = []
    own_csp = False
    for key, value in headers:
        name = key.lower()
        if name == _server:
            continue
        if name == _location:
            value = _local(value)
        elif name == _CSP:
            own_csp = True
        out.append((key, value))
    if not own_csp:
        out.append((_CSP, csp))
    out += SECURITY_HEADERS
    out.append((b"x-request-id", rid))
    return out


def _access_line(method: Any, path: Any, status: int, seconds: float, request_id: str) -> str:
    """The access log's JSON line, as ``json.dumps`` of its dict writes it, at a fifth of
    its cost: the two texts a client chose through json's own C string encoder, the
    numbers as json writes them; the request id is a token of ``[A-Za-z0-9._-]`` only.

    >>> line = _access_line("POST", '/a"b\u00e9', 200, 0.0012345, "id-1")
    >>> line == json.dumps({"method": "POST", "path": '/a"b\u00e9', "status": 200,
    ...                     "duration_ms": 1.234, "request_id": "id-1"})
    True
    >>> json.loads(_access_line(None, "/", 500, 0.5, "x"))["method"] is None
    True
    """
    m = _string(method) if type(method) is str else json.dumps(method)
    p = _string(path) if type(path) is str else json.dumps(path)
    ms = round(seconds * 1e3, 3)
    return (
        f'{{"method": {m}, "path": {p}, "status": {status:d}, "duration_ms": {ms!r}, '
        f'"request_id": "{request_id}"}}'
    )


def _log_access(scope: Scope, status: int, seconds: float, request_id: str) -> None:
    """One access line on ``service.access`` at INFO, its caller already asked whether the
    logger takes INFO.

    Where the logger is set up as ``python -m service`` sets it up (:func:`_bare_stream`:
    one stream handler writing the bare message, nothing else that could see a record),
    the line is written to that handler's stream as its ``emit`` writes it (the same
    bytes, its terminator, under its lock, flushed), without a record: making the record,
    filtering and formatting it were most of the line's cost (~20 µs of a request,
    measured). Any other set-up (filters, other handlers, a parent's handlers, a
    formatter of its own, a record factory that adds fields) gets a record, as
    :meth:`logging.Logger.info` would make, without ``info``'s search of the stack for its
    caller, which no access line shows.
    """
    line = _access_line(scope.get("method"), scope.get("path"), status, seconds, request_id)
    handler = _bare_stream(access_log)
    if handler is not None:
        handler.acquire()
        try:
            stream = handler.stream
            stream.write(line + handler.terminator)
            if stream and hasattr(stream, "flush"):  # as StreamHandler.flush
                stream.flush()
        except RecursionError:  # as StreamHandler.emit
            raise
        except Exception:
            handler.handleError(_access_record(line))
        finally:
            handler.release()
        return
    access_log.handle(_access_record(line))


def _access_record(line: str) -> logging.LogRecord:
    """The access line as a record, made by the record factory in force
    (:func:`logging.setLogRecordFactory`), as every record is."""
    return logging.getLogRecordFactory()(
        access_log.name, logging.INFO, __file__, 0, line, None, None, "FrontDoor.__call__"
    )


def _bare_stream(logger: logging.Logger) -> logging.StreamHandler[Any] | None:
    """The one handler of ``logger`` where writing a line to its stream is all that
    handling a record of it would do: no filter on the logger or the handler, no parent's
    handlers, a plain :class:`logging.StreamHandler` taking INFO whose formatter writes
    the bare message (``%(message)s``, the default's format), records made by
    :class:`logging.LogRecord` itself. None otherwise.

    >>> import io
    >>> log = logging.getLogger("doctest.access")
    >>> handler = logging.StreamHandler(io.StringIO())
    >>> handler.setFormatter(logging.Formatter("%(message)s"))
    >>> log.handlers[:], log.propagate = [handler], False
    >>> _bare_stream(log) is handler
    True
    >>> handler.setFormatter(logging.Formatter("%(levelname)s %(message)s"))
    >>> _bare_stream(log) is None
    True
    """
    handlers = logger.handlers
    if len(handlers) != 1 or logger.propagate or logger.filters:
        return None
    handler = handlers[0]
    if type(handler) is not logging.StreamHandler or handler.filters or handler.level > _INFO:
        return None
    formatter = handler.formatter
    if formatter is not None and (
        type(formatter) is not logging.Formatter
        or type(formatter._style) is not logging.PercentStyle
        or formatter._style._fmt != _BARE
        or getattr(formatter._style, "_defaults", None)  # Formatter(defaults=...)
    ):
        return None
    if logging.getLogRecordFactory() is not logging.LogRecord:
        return None
    return handler


_INFO = logging.INFO
_BARE = "%(message)s"


async def _send_500(send: Send, request_id: str, rid: bytes) -> None:
    """500 with the request id, the security headers, and ``Connection: close``.

    The connection is closed after it: whatever state the failure left behind,
    the next request on this keep-alive connection starts on a fresh one.
    """
    from .errors import error_body  # errors imports this module

    body = json.dumps(
        error_body(
            "internal_error",
            f"internal error; it was logged on the server (request id {request_id})",
            [],
        )
    ).encode()
    headers = [
        (b"content-type", b"application/json"),
        (b"content-length", str(len(body)).encode()),
        (b"connection", b"close"),
        (_CSP, STRICT_CSP.encode()),
        *SECURITY_HEADERS,
        (b"x-request-id", rid),
    ]
    await send({"type": "http.response.start", "status": 500, "headers": headers})
    await send({"type": "http.response.body", "body": body})


_ID_PREFIX = os.urandom(8).hex()
_ID_COUNTER = itertools.count(1)


def _new_id_prefix() -> None:  # a forked worker must not repeat its parent's ids
    global _ID_PREFIX, _ID_COUNTER
    _ID_PREFIX, _ID_COUNTER = os.urandom(8).hex(), itertools.count(1)


os.register_at_fork(after_in_child=_new_id_prefix)


def _fresh_id() -> bytes:
    """A request id unique to this process and, by its random prefix, across processes:
    32 hex digits like a UUID's, without a system call per request (uuid4 took ~2 µs, a
    sizeable share of a cheap request). Not a secret: it names a request in the logs."""
    return f"{_ID_PREFIX}{next(_ID_COUNTER):016x}".encode()


def _local(location: bytes) -> bytes:
    """A redirect's target as a path on this server, never naming a host.

    Starlette builds absolute redirects (a directory's trailing slash, ``/.`` to ``/./``)
    from the request's Host header, so a forged Host came back in ``Location``; the
    service only ever redirects to itself, so the scheme and host are dropped.

    >>> _local(b"http://evil.example/./")
    b'/./'
    >>> _local(b"//evil.example/a?b=1#c")
    b'/a?b=1#c'
    >>> _local(b"./#view=report")
    b'./#view=report'
    """
    parts = urlsplit(location.decode("latin-1"))
    if not (parts.scheme or parts.netloc):
        return location
    path = "/" + parts.path.lstrip("/")  # "//host" in the path would name a host again
    local = path + (f"?{parts.query}" if parts.query else "")
    return (local + (f"#{parts.fragment}" if parts.fragment else "")).encode("latin-1")


def _header(scope: Scope, name: bytes) -> bytes | None:
    for key, value in scope.get("headers") or ():
        if key.lower() == name:
            return bytes(value)
    return None


def _is_json(content_type: bytes | None) -> bool:
    if not content_type:
        return False
    media = content_type.split(b";", 1)[0].strip().lower()
    return media == b"application/json" or (
        media.startswith(b"application/") and media.endswith(b"+json")
    )


class BodyGuard:
    """Refuse non-JSON bodies (415) and bodies over ``limit`` bytes (413), before they are read."""

    def __init__(
        self,
        app: ASGIApp,
        limit: int,
        json_paths: frozenset[str] | None = None,
        body_timeout_s: float = 10.0,
    ) -> None:
        self.app = app
        self.limit = limit
        self.body_timeout_s = body_timeout_s
        #: Paths that take a JSON body by POST; any other path or method goes to the router
        #: unchecked, which answers 404/405 (None: every POST, PUT and PATCH is checked).
        self.json_paths = json_paths

    def _wants_json(self, scope: Scope) -> bool:
        if self.json_paths is None:
            return scope.get("method") in ("POST", "PUT", "PATCH")
        return scope.get("method") == "POST" and scope.get("path") in self.json_paths

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        if (
            self.json_paths is not None
            and scope.get("path") in self.json_paths
            and scope.get("method") not in ("POST", "OPTIONS")
        ):
            # the form's static mount at "/" would answer 404 for these: say 405
            await _refuse(
                send, 405, "method_not_allowed", "this path takes POST", [(b"allow", b"POST")]
            )
            return
        if self._wants_json(scope) and not _is_json(_header(scope, b"content-type")):
            await _refuse(
                send,
                415,
                "unsupported_media_type",
                "send the body as JSON with the header content-type: application/json",
            )
            return
        length = _header(scope, b"content-length")
        if length is not None and (not length.isdigit() or int(length) > self.limit):
            await self._too_large(send)
            return
        seen = 0
        started = False
        complete = False
        loop = asyncio.get_running_loop()
        deadline = loop.time() + self.body_timeout_s  # for the whole body, not each piece

        async def limited() -> Message:
            nonlocal seen, complete
            if complete:  # the body is in: what follows is http.disconnect, whenever it comes
                return await receive()
            left = deadline - loop.time()
            if left <= 0:
                raise BodyTimeout(self.body_timeout_s)
            message = await _within(receive, left, self.body_timeout_s)
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.limit:
                    raise BodyTooLarge(self.limit)
                complete = not message.get("more_body", False)
            return message

        async def watch(message: Message) -> None:
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, limited, watch)
        except BodyTooLarge:
            if started:  # pragma: no cover - every route reads its body before answering
                raise
            await self._too_large(send)
        except BodyTimeout as exc:
            if started:  # pragma: no cover
                raise
            await _refuse(send, 408, BodyTimeout.kind, exc.detail, [(b"connection", b"close")])

    async def _too_large(self, send: Send) -> None:
        await _refuse(send, 413, BodyTooLarge.kind, BodyTooLarge(self.limit).detail)


async def _within(receive: Receive, timeout_s: float, budget_s: float) -> Message:
    """``await receive()``, or :class:`BodyTimeout` (naming the body's whole ``budget_s``)
    after ``timeout_s``, what is left of it.

    A message that is there already (a small body arrives with its head: every API
    request's) is taken without a timer. Otherwise one timer handle cancels the task, not
    ``asyncio.timeout`` (its context object and rescheduling cost ~8 µs a request) nor
    ``wait_for`` (a task per call, ~15 µs). A cancellation that is not the timer's goes
    on as it came.
    """
    waiting = receive().__await__()
    try:
        first = waiting.send(None)
    except StopIteration as done:  # it did not wait: nothing to time
        message: Message = done.value
        return message
    task = asyncio.current_task()
    assert task is not None
    expired: list[bool] = []

    def expire() -> None:
        expired.append(True)
        task.cancel()

    handle = asyncio.get_running_loop().call_later(timeout_s, expire)
    try:
        return await _Resumed(waiting, first)
    except asyncio.CancelledError:
        if expired:
            task.uncancel()
            raise BodyTimeout(budget_s) from None
        raise
    finally:
        handle.cancel()


class _Resumed:
    """The rest of an awaitable's run, its first step taken already (:func:`_within`):
    what that step yielded goes to the loop first, then every value, result and exception
    passes between the loop and the awaitable as ``await`` would pass them."""

    __slots__ = ("_first", "_waiting")

    def __init__(self, waiting: Any, first: Any) -> None:
        self._waiting = waiting
        self._first = first

    def __await__(self) -> Any:
        waiting, step = self._waiting, self._first
        while True:
            try:
                sent = yield step
            except GeneratorExit:
                waiting.close()
                raise
            except BaseException as exc:  # a cancellation, or another thrown in
                try:
                    step = waiting.throw(exc)
                except StopIteration as done:
                    return done.value
            else:
                try:
                    step = waiting.send(sent)
                except StopIteration as done:
                    return done.value


async def _refuse(
    send: Send, status: int, kind: str, msg: str, extra: list[tuple[bytes, bytes]] | None = None
) -> None:
    from .errors import error_body  # errors imports this module

    body = json.dumps(error_body(kind, msg, [])).encode()
    await send(
        {
            "type": "http.response.start",
            "status": status,
            "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(body)).encode()),
                *(extra or ()),
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})


class BodyTooLarge(HTTPException):
    """Raised from ``receive`` mid-body; FastAPI re-raises HTTP exceptions from body reading,
    so the 413 survives its "error parsing the body" catch-all."""

    kind = "body_too_large"

    def __init__(self, limit: int) -> None:
        super().__init__(413, f"request body over the {limit}-byte limit (MAX_BODY_BYTES)")


class BodyTimeout(HTTPException):
    """The whole body did not arrive within ``BODY_TIMEOUT_S`` of its head (408, connection
    closed): a body trickled a byte at a time no longer holds a connection forever."""

    kind = "body_timeout"

    def __init__(self, timeout_s: float) -> None:
        super().__init__(
            408,
            f"the request body did not arrive within {timeout_s:g} s (BODY_TIMEOUT_S); "
            "send it whole",
        )


class ExactRoutes:
    """A POST to a fixed path goes straight to its route.

    Starlette tries each route's pattern in turn (~1 µs each); a model route near the end
    of the table waited for ~25 of them, a measurable share of a cheap request. Only
    routes without path parameters and with POST among their methods are listed; every
    other request, and a method the route does not take, goes on to ``app`` as before.

    It is used twice. Inside the router (``handlers`` None), for routes run by FastAPI's
    own handler: the exception layer and FastAPI's exit stack are outside it, as for a
    matched route. In front of Starlette's exception layer (``handlers``: that layer's
    exception and status handlers), for the model routes, whose apps apply the handlers
    themselves (:func:`service.api.lean_endpoint`) and open no file for FastAPI's exit
    stack to close: the handlers are put in the scope as that layer puts them, and the
    layer's per-request wrapper, the exit stack and the router are skipped.
    """

    def __init__(
        self,
        app: ASGIApp,
        router: Any,
        routes: dict[str, Any],
        handlers: tuple[dict[Any, Any], dict[int, Any]] | None = None,
    ) -> None:
        self.app = app
        self.router = router
        self.routes = routes
        self.handlers = handlers

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        route = self.routes.get(scope["path"]) if scope["type"] == "http" else None
        if route is None or scope["method"] != "POST" or scope.get("root_path"):
            await self.app(scope, receive, send)
            return
        if self.handlers is not None:
            scope["starlette.exception_handlers"] = self.handlers
        scope["router"] = self.router
        scope["endpoint"] = route.endpoint
        scope["route"] = route
        scope["path_params"] = {}
        await route.app(scope, receive, send)


def client_of(scope: Scope) -> str:
    """The client's identity, for the per-client quotas and the heavy lane's share: the
    name of its API key (``key:<name>``) where keys are configured, else its address (the
    forwarded one behind a proxy in ``TRUSTED_PROXIES``).

    >>> client_of({"client": ("203.0.113.9", 5000), "state": {}})
    '203.0.113.9'
    >>> client_of({"client": ("203.0.113.9", 5000), "state": {"client": "key:line-3"}})
    'key:line-3'
    """
    named = (scope.get("state") or {}).get("client")
    if named:
        return str(named)
    peer = scope.get("client")
    return str(peer[0]) if peer else "unknown"


def key_of(scope: Scope) -> ApiKey | None:
    """The API key the request was let in with (None where the API is open)."""
    key = (scope.get("state") or {}).get("api_key")
    return key if isinstance(key, ApiKey) else None


_BEARER = re.compile(rb"[Bb][Ee][Aa][Rr][Ee][Rr] +(\S+) *")


class ApiKeys:
    """Every request under ``prefix`` must carry one of ``keys``, else 401 (JSON, with
    ``WWW-Authenticate: Bearer``); other paths (the form, the manual, ``/healthz``,
    ``/openapi.json``) stay open.

    The key comes as ``Authorization: Bearer <key>`` or ``X-API-Key: <key>``. The SHA-256
    of what was sent is compared with every key's (:func:`hmac.compare_digest`, all of
    them, no early exit), so neither the time taken nor its length says which part of a
    secret was right. The key's name goes to ``scope["state"]`` (:func:`client_of`).
    """

    def __init__(self, app: ASGIApp, keys: tuple[ApiKey, ...], prefix: str = "/api/v1") -> None:
        self.app = app
        self.keys = keys
        self.prefix = prefix

    def _guarded(self, path: str) -> bool:
        return path == self.prefix or path.startswith(self.prefix + "/")

    def _key(self, scope: Scope) -> tuple[ApiKey | None, bool]:
        """The key matched, and whether one was sent at all."""
        sent = _header(scope, b"x-api-key")
        if sent is None:
            auth = _header(scope, b"authorization")
            match = _BEARER.fullmatch(auth) if auth is not None else None
            sent = match.group(1) if match else None
        if not sent:
            return None, False
        digest = hashlib.sha256(sent).digest()
        found = None
        for key in self.keys:  # every key compared, whichever matches
            if hmac.compare_digest(digest, key.digest):
                found = key
        return found, True

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or not self._guarded(scope["path"]):
            await self.app(scope, receive, send)
            return
        key, sent = self._key(scope)
        if key is None:
            msg = (
                "the API key sent is not known here"
                if sent
                else "this server needs an API key: send the header 'Authorization: Bearer "
                "<key>' or 'X-API-Key: <key>'"
            )
            challenge = b'Bearer realm="api", error="invalid_token"' if sent else b"Bearer"
            await _refuse(send, 401, "unauthorized", msg, [(b"www-authenticate", challenge)])
            return
        state = scope.setdefault("state", {})
        state["client"] = f"key:{key.name}"
        state["api_key"] = key
        await self.app(scope, receive, send)


#: The OpenAPI security schemes of :class:`ApiKeys`: either header carries the key.
SECURITY_SCHEMES: dict[str, dict[str, str]] = {
    "bearer": {
        "type": "http",
        "scheme": "bearer",
        "description": "Authorization: Bearer <key>, where the server has API keys "
        "(API_KEYS_FILE); an open server ignores it",
    },
    "apiKey": {
        "type": "apiKey",
        "in": "header",
        "name": "X-API-Key",
        "description": "the key in X-API-Key instead of Authorization",
    },
}


def document_keys(schema: dict[str, Any], required: bool, prefix: str = "/api/v1") -> None:
    """Add the key's security schemes to an OpenAPI ``schema``; where ``required``, every
    operation under ``prefix`` asks for one of them and lists its 401."""
    schema.setdefault("components", {})["securitySchemes"] = SECURITY_SCHEMES
    if not required:
        return
    unauthorized = {
        "description": "no API key, or one this server does not know",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ErrorResponse"}}},
    }
    for path, operations in schema.get("paths", {}).items():
        if path == prefix or path.startswith(prefix + "/"):
            for operation in operations.values():
                operation["security"] = [{name: []} for name in SECURITY_SCHEMES]
                operation.setdefault("responses", {})["401"] = unauthorized
