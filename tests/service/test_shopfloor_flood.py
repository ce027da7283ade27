"""Trickling sockets from many addresses do not lock other clients out.

Issue 34's full-scale figures (bench/shopfloor.py, ``flood_10_addresses``): 10 addresses
x 100 sockets, each trickling a request body, filled ``MAX_CONNECTIONS`` (1,000) without
passing the per-address cap (100); another client then had 14 % of its requests
answered. Connections waiting for their request now hold at most half of
``MAX_CONNECTIONS`` (:class:`service.connections.HeadDeadline`): beyond it the longest
part-sent one is shed. Here at a tenth of the scale, limits scaled alike (100 in all, 10
per address): before, the other client had 0 of 51 requests answered.
"""

from __future__ import annotations

import select
import socket
import time
from pathlib import Path

import httpx
import pytest

from bench.shopfloor import Service, fig_flood
from tests.service.servers import toy_server

pytestmark = pytest.mark.slow


def test_ten_trickling_addresses_leave_room_for_a_prompt_client(tmp_path: Path) -> None:
    limits = {"MAX_CONNECTIONS": "100", "MAX_CONNECTIONS_PER_CLIENT": "10"}
    with Service(tmp_path / "flood10", env=limits) as svc:
        figures = fig_flood(svc, 0.1, spread=10)
    assert figures["sockets"] == 100 and figures["addresses"] == 10
    # the flood was on: the attacker's sockets were opened (and shed and opened again)
    assert figures["attacker"]["opened"] >= 100
    # every 503 of the other client is gone; a rare reset under load is tolerated
    assert figures["other_client_requests"] >= 10
    assert figures["other_client_success"] >= 0.9, figures["other_client_codes"]
    assert "503" not in figures["other_client_codes"], figures["other_client_codes"]


def test_idle_sockets_beyond_half_the_limit_are_shed_oldest_first() -> None:
    """59 sockets that send nothing, from three addresses within their caps, beside a
    limit of 60: before, a new client's /healthz got 503; now the idle ones beyond 30 are
    shed, the oldest first, and the new client is answered."""
    settings = {"MAX_CONNECTIONS": "60", "MAX_CONNECTIONS_PER_CLIENT": "20"}
    with toy_server(settings, keep_output=False) as (port, _):
        held = [
            socket.create_connection(
                ("127.0.0.1", port), timeout=5, source_address=(f"127.0.0.{3 + i // 20}", 0)
            )
            for i in range(59)
        ]
        time.sleep(0.5)
        answer = httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=5)
        assert answer.status_code == 200
        time.sleep(0.5)
        readable, _, _ = select.select(held, [], [], 0)  # closed by the server: EOF to read
        closed = [s in readable and s.recv(1) == b"" for s in held]
        for s in held:
            s.close()
        # 29 shed by the others' arrival, one by the client's connection (and one more if
        # its connection waits idle for a next request before the client closes it): the
        # oldest, in order
        assert closed[:30] == [True] * 30 and closed[31:] == [False] * 28
