"""Connections a slow or greedy client cannot hold, against a real server process.

Scaled-down reproductions of issue 34's findings (bounded: at most ~100 sockets on
127.0.0.x, a few seconds each):

* a body trickled one byte at a time kept its connection forever (the deadline was per
  chunk): now the whole body has BODY_TIMEOUT_S;
* request heads had no size limit (20 × 10 MB held 200 MB): now MAX_HEAD_BYTES, a 431;
* 1,000 trickling sockets from one client gave every other client 503 for 40 s: now one
  address holds at most MAX_CONNECTIONS_PER_CLIENT connections and others are served;
* the 503 beyond the connection limit was plain text without Retry-After: now JSON.

Loopback answers on every 127.x.y.z address, so a socket bound to 127.0.0.2 is another
client to the server.
"""

from __future__ import annotations

import contextlib
import json
import select
import socket
import time
from collections.abc import Iterator

import httpx
import pytest

from tests.service.servers import toy_server

pytestmark = pytest.mark.slow

PER_CLIENT = 20
TOTAL = 60
HEAD_BYTES = 8192
BODY_S = 1.0
HEAD_HOLD = b"GET /healthz HTTP/1.1\r\nHost: t\r\nX-Slow: "  # a head that never ends


@pytest.fixture(scope="module")
def server() -> Iterator[tuple[str, int]]:
    settings = {
        "HEADER_TIMEOUT_S": "10",
        "BODY_TIMEOUT_S": str(BODY_S),
        "MAX_CONNECTIONS": str(TOTAL),
        "MAX_CONNECTIONS_PER_CLIENT": str(PER_CLIENT),
        "MAX_HEAD_BYTES": str(HEAD_BYTES),
        # idle sockets may fill the server here (by default half of it sheds the oldest):
        # the 503 at the limit itself is under test
        "MAX_WAITING_CONNECTIONS": str(TOTAL),
    }
    with toy_server(settings, keep_output=False) as (port, _):
        yield "127.0.0.1", port


def _connect(port: int, source: str = "127.0.0.1") -> socket.socket:
    return socket.create_connection(("127.0.0.1", port), timeout=5, source_address=(source, 0))


def _answer(sock: socket.socket, seconds: float = 5.0) -> tuple[int, dict[str, str], bytes]:
    """Status, headers and body of one answer, read until the server closes."""
    sock.settimeout(seconds)
    data = b""
    try:
        while chunk := sock.recv(65536):
            data += chunk
    except (TimeoutError, ConnectionResetError):
        pass
    head, _, body = data.partition(b"\r\n\r\n")
    lines = head.decode("latin-1").split("\r\n")
    headers = {k.lower(): v for k, _, v in (line.partition(": ") for line in lines[1:])}
    return int(lines[0].split()[1]), headers, body


def _closed(sock: socket.socket, seconds: float) -> bool:
    sock.settimeout(seconds)
    try:
        while sock.recv(65536):
            pass
        return True
    except ConnectionResetError:
        return True
    except TimeoutError:
        return False


def test_a_trickled_body_meets_one_deadline_for_the_whole_body(server: tuple[str, int]) -> None:
    _, port = server
    s = _connect(port)
    s.sendall(
        b"POST /api/v1/toy/disc HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
        b"Content-Length: 100\r\n\r\n"
    )
    start = time.monotonic()
    answered = None
    for byte in b'{"diameter": 0.2, "mass": 1.0' * 3:  # one byte every 0.2 s: each piece in time
        try:
            s.sendall(bytes([byte]))
        except (BrokenPipeError, ConnectionResetError):
            break
        time.sleep(0.2)
        s.setblocking(False)
        try:
            if s.recv(1, socket.MSG_PEEK):
                answered = time.monotonic() - start
                break
        except BlockingIOError:
            pass
        finally:
            s.setblocking(True)
        assert time.monotonic() - start < 4 * BODY_S, "the trickle is still being read"
    assert answered is not None and answered < BODY_S + 1.0
    status, headers, body = _answer(s)
    assert status == 408 and headers["content-type"] == "application/json"
    assert json.loads(body)["detail"][0]["type"] == "body_timeout"
    s.close()


def test_an_oversized_head_gets_431_and_the_connection_closes(server: tuple[str, int]) -> None:
    _, port = server
    socks = [_connect(port) for _ in range(20)]
    big = b"GET /healthz HTTP/1.1\r\nHost: t\r\nX-Big: " + b"a" * 1_000_000 + b"\r\n\r\n"
    for s in socks:
        # refused before all of it was sent: the answer is still waiting to be read
        with contextlib.suppress(BrokenPipeError, ConnectionResetError):
            s.sendall(big)
    for s in socks:
        status, headers, body = _answer(s)
        assert status == 431 and headers["connection"] == "close"
        assert f"{HEAD_BYTES} bytes" in json.loads(body)["detail"][0]["msg"]
        s.close()
    # a head just under the limit is served
    ok = httpx.get(f"http://127.0.0.1:{port}/healthz", headers={"x-pad": "a" * (HEAD_BYTES // 2)})
    assert ok.status_code == 200


def test_one_client_cannot_take_every_connection(server: tuple[str, int]) -> None:
    """100 trickling sockets from 127.0.0.2: it keeps 20, the rest get a JSON 503 with
    Retry-After, and every request of another client is answered 200 meanwhile."""
    _, port = server
    flood = [_connect(port, "127.0.0.2") for _ in range(100)]
    for s in flood:
        s.sendall(HEAD_HOLD)
    time.sleep(0.5)  # the refusals are sent at once; the held ones wait for their heads
    readable, _, _ = select.select(flood, [], [], 0.5)
    for s in readable:
        first = s.recv(65536)
        status_line, _, rest = first.partition(b"\r\n")
        assert status_line == b"HTTP/1.1 503 Service Unavailable", first[:200]
        assert b"retry-after: 1" in rest.lower() and b"application/json" in rest
        assert b"MAX_CONNECTIONS_PER_CLIENT" in rest
    assert len(readable) == 100 - PER_CLIENT
    codes = []
    with httpx.Client(base_url=f"http://127.0.0.1:{port}", timeout=5) as other:
        end = time.monotonic() + 1.5
        while time.monotonic() < end:
            for s in set(flood) - set(readable):
                s.send(b"a")  # the held ones keep trickling their endless heads
            codes.append(other.get("/healthz").status_code)
    assert len(codes) > 10 and set(codes) == {200}
    for s in flood:
        s.close()


def test_the_503_at_the_connection_limit_is_json_with_retry_after(
    server: tuple[str, int],
) -> None:
    _, port = server
    time.sleep(0.5)  # the previous test's sockets are gone
    held = [
        _connect(port, f"127.0.0.{3 + i // PER_CLIENT}") for i in range(TOTAL - 1)
    ]  # from three addresses, within each one's share
    time.sleep(0.3)
    s = _connect(port)
    s.sendall(b"GET /healthz HTTP/1.1\r\nHost: t\r\n\r\n")
    status, headers, body = _answer(s)
    assert status == 503, body
    assert headers["content-type"] == "application/json" and headers["retry-after"] == "1"
    assert json.loads(body)["detail"][0]["type"] == "too_many_connections"
    for h in held:
        h.close()
    s.close()
    time.sleep(0.3)
    time.sleep(0.3)
    assert httpx.get(f"http://127.0.0.1:{port}/healthz").status_code == 200
