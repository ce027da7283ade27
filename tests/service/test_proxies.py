"""Client identity: X-Forwarded-For is believed from the proxies in TRUSTED_PROXIES alone.

Issue 34: X-Forwarded-For was trusted from loopback (uvicorn's default), so one client
could pose as many; behind a proxy every user shared the proxy's one identity and one
connection cap. Now no address is trusted by default; from a configured proxy the
forwarded client is the identity of the study quota and of the connection cap.
"""

from __future__ import annotations

import asyncio
import contextlib
import select
import socket
import time
from collections.abc import Iterator

import httpx
import pytest

from service import create_app
from service.config import Settings
from service.studies import Job, StudySettings
from tests.service.servers import toy_server
from tests.toys import TOY

URL = "/api/v1/toy/disc/study"
STUDY = {
    "base": {"diameter": 0.3},
    "variables": [{"name": "mass", "low": 1, "high": 2}],
    "samples": 20,
    "fidelity": "exact",
    "outputs": ["energy"],
}


def _submit(proxies: str, monkeypatch: pytest.MonkeyPatch) -> tuple[int, int]:
    """Two studies from a loopback peer that says it forwards for two other clients, with
    the proxy's own study already running (one study per client)."""
    monkeypatch.setenv("TRUSTED_PROXIES", proxies)
    app = create_app(
        models=[TOY],
        settings=Settings(warm_up=False),
        study_settings=StudySettings(per_client=1, inprocess_points=1000),
    )
    busy = Job("busy", TOY.name, "127.0.0.1", 10, False, state="running")
    app.state.studies.store.put(busy.row("a process"))

    async def run() -> tuple[int, int]:
        transport = httpx.ASGITransport(app=app, client=("127.0.0.1", 40000))
        async with httpx.AsyncClient(transport=transport, base_url="http://t") as c:
            a = await c.post(URL, json=STUDY, headers={"x-forwarded-for": "203.0.113.9"})
            b = await c.post(URL, json=STUDY, headers={"x-forwarded-for": "198.51.100.4"})
            return a.status_code, b.status_code

    try:
        return asyncio.run(run())
    finally:
        app.state.studies.shutdown()


def test_x_forwarded_for_from_loopback_is_not_believed_by_default(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    assert _submit("", monkeypatch) == (503, 503)  # both are the loopback peer, which is busy


def test_x_forwarded_for_from_a_configured_proxy_names_the_client(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    assert _submit("127.0.0.1", monkeypatch) == (202, 202)
    assert _submit("10.0.0.0/8", monkeypatch) == (503, 503)  # another proxy's network


PER_CLIENT = 3
HELD = (
    b"POST /api/v1/toy/disc HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
    b"Content-Length: 100\r\nX-Forwarded-For: %s\r\n\r\n{"
)  # a head, then a body that waits for its deadline: a request in flight


@pytest.fixture(scope="module")
def proxied() -> Iterator[int]:
    settings = {
        "TRUSTED_PROXIES": "127.0.0.1",
        "MAX_CONNECTIONS_PER_CLIENT": str(PER_CLIENT),
        "BODY_TIMEOUT_S": "5",
        "HEADER_TIMEOUT_S": "5",
    }
    with toy_server(settings, keep_output=False) as (port, _):
        yield port


def _hold(port: int, forwarded: bytes, source: str = "127.0.0.1") -> socket.socket:
    s = socket.create_connection(("127.0.0.1", port), timeout=5, source_address=(source, 0))
    s.sendall(HELD % forwarded)
    return s


@pytest.mark.slow
def test_the_connection_cap_counts_a_proxys_requests_per_forwarded_client(
    proxied: int,
) -> None:
    """Through the proxy: ten users with one request each are all held (the proxy's address
    is not capped), one user's requests beyond its share get the JSON 503; a direct peer
    that sends the header itself is still capped by its own address."""
    users = [_hold(proxied, b"203.0.113.%d" % i) for i in range(10)]
    greedy = [_hold(proxied, b"198.51.100.7") for _ in range(PER_CLIENT + 2)]
    poser = [_hold(proxied, b"192.0.2.%d" % i, source="127.0.0.2") for i in range(PER_CLIENT + 2)]
    time.sleep(0.5)
    everyone = users + greedy + poser
    readable, _, _ = select.select(everyone, [], [], 0.5)
    refused = set()
    for s in readable:
        first = s.recv(65536)
        assert first.startswith(b"HTTP/1.1 503"), first[:200]
        assert b"retry-after: 1" in first.lower() and b"MAX_CONNECTIONS_PER_CLIENT" in first
        refused.add(s)
    assert refused.isdisjoint(users)
    assert len(refused & set(greedy)) == 2 and len(refused & set(poser)) == 2
    for s in everyone:
        with contextlib.suppress(OSError):
            s.close()
    time.sleep(0.3)
    assert httpx.get(f"http://127.0.0.1:{proxied}/healthz").status_code == 200
