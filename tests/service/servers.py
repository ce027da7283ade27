"""A real service process on loopback for the tests that need its connection layer."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path

import httpx

ROOT = Path(__file__).resolve().parents[2]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@contextmanager
def toy_server(
    settings: Mapping[str, str],
    *,
    keep_output: bool = True,
    args: Sequence[str] = (),
    start_s: float = 30.0,
) -> Iterator[tuple[int, subprocess.Popen[str]]]:
    """``python -m service`` serving the test toys on a free port with ``settings`` in its
    environment (no warm-up, no access log); its output piped for the caller to read
    (``keep_output``) or dropped (a test that floods it and never reads must not fill the
    pipe); ``args`` for ``python -m service`` (``--workers 2``); killed on exit if alive."""
    port = free_port()
    env = {**os.environ, "WARM_UP": "0", "ACCESS_LOG": "0", "PYTHONPATH": str(ROOT), **settings}
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "service",
            "--port",
            str(port),
            "--factory",
            "tests.toys:crash_app",
            *args,
        ],
        cwd=ROOT,
        env=env,
        stdout=subprocess.PIPE if keep_output else subprocess.DEVNULL,
        stderr=subprocess.STDOUT,
        text=True,
    )
    deadline = time.monotonic() + start_s
    while True:
        try:
            if httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=1).status_code == 200:
                break
        except httpx.HTTPError:
            if time.monotonic() > deadline:
                proc.kill()
                raise RuntimeError("server did not start") from None
            time.sleep(0.1)
    try:
        yield port, proc
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
