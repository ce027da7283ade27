"""``python -m service [--host H] [--port P] [--workers N]``: serve the API and the form.

Connections: at most ``MAX_CONNECTIONS`` at once and ``MAX_CONNECTIONS_PER_CLIENT``
from one address (a JSON 503 with Retry-After beyond), each request head within
``HEADER_TIMEOUT_S`` and ``MAX_HEAD_BYTES`` (:mod:`service.connections`), each whole
body within ``BODY_TIMEOUT_S``; on SIGTERM, open requests get
``SHUTDOWN_TIMEOUT_S`` to finish. Error lines are rate-limited per kind.

uvicorn's own access log is off: :class:`service.middleware.FrontDoor` writes
one JSON line per request to stdout instead (method, path, status,
duration_ms, request_id; never a body). ``ACCESS_LOG=0`` silences it.
"""

from __future__ import annotations

import gc

# Run as the program (or as a worker process's copy of it), the collector is off while the
# process imports the engine and builds the app (some million objects, all kept for the
# process's life, scanned again and again: about a quarter of the start-up's time,
# measured); once the app's start-up warm-up has loaded the compiled kernels,
# :func:`service.main.collector_on` freezes them out of later scans and turns it back on.
# Imported (a test reading log_config), nothing changes.
if __name__ in ("__main__", "__mp_main__"):
    gc.disable()

import argparse
import copy
import socket
from typing import Any

import uvicorn
import uvicorn.config
from uvicorn.config import LOGGING_CONFIG

from .config import Settings
from .connections import protocol


def log_config(level: str) -> dict[str, Any]:
    """uvicorn's logging set-up plus the service's loggers (access lines as bare JSON)."""
    config: dict[str, Any] = copy.deepcopy(LOGGING_CONFIG)
    config.setdefault("filters", {})["flood"] = {"()": "service.connections.FloodGuard"}
    config["handlers"]["default"]["filters"] = ["flood"]
    config["loggers"]["asyncio"] = {"handlers": ["default"], "level": "WARNING", "propagate": False}
    config["formatters"]["json_line"] = {"format": "%(message)s"}
    config["handlers"]["json_access"] = {
        "class": "logging.StreamHandler",
        "formatter": "json_line",
        "stream": "ext://sys.stdout",
    }
    config["loggers"]["service"] = {
        "handlers": ["default"],
        "level": level.upper(),
        "propagate": False,
    }
    config["loggers"]["service.access"] = {
        "handlers": ["json_access"],
        "level": level.upper(),
        "propagate": False,
    }
    return config


def main(argv: list[str] | None = None) -> None:
    settings = Settings()
    parser = argparse.ArgumentParser(prog="python -m service", description=__doc__)
    parser.add_argument("--host", default=settings.host, help="bind address (HOST)")
    parser.add_argument("--port", type=int, default=settings.port, help="port (PORT)")
    parser.add_argument("--workers", type=int, default=1, help="worker processes")
    parser.add_argument(
        "--factory",
        default="service.main:create_app",
        help="module:function building the app (tests and the load test serve toy models)",
    )
    args = parser.parse_args(argv)
    if args.workers > 1:
        _listen_with_nodelay()
        # each worker process builds its own app (and turns its collector back on then);
        # this one only supervises them, for as long as the service runs
        gc.freeze()
        gc.enable()
    uvicorn.run(
        args.factory,
        factory=True,
        host=args.host,
        port=args.port,
        workers=args.workers,
        log_level=settings.log_level,
        log_config=log_config(settings.log_level),
        access_log=False,
        server_header=False,
        date_header=False,
        http=protocol(),
        # X-Forwarded-For is read by the app from TRUSTED_PROXIES alone (service.main);
        # uvicorn's own reading would trust loopback (FORWARDED_ALLOW_IPS' default)
        proxy_headers=False,
        h11_max_incomplete_event_size=settings.max_head_bytes,
        limit_concurrency=settings.max_connections,
        timeout_keep_alive=5,
        timeout_graceful_shutdown=settings.shutdown_timeout_s,
        # a worker process imports the engine (numpy, scipy, numba) before it answers the
        # supervisor's ping: ~2 s of CPU, over uvicorn's 5 s default on a loaded machine,
        # where workers were killed and restarted in a loop
        timeout_worker_healthcheck=30,
    )


def _listen_with_nodelay() -> None:
    """Set TCP_NODELAY on the listening socket uvicorn shares between worker processes.

    uvicorn opens it with ``proto=0``, so asyncio does not set TCP_NODELAY on the
    connections, and every keep-alive answer (headers and body sent apart) waits
    ~40 ms for the client's delayed ACK: measured 45 ms per request with
    ``--workers 2`` against 1.5 ms with one worker. Linux copies the option from
    the listening socket to each accepted one.
    """
    original = uvicorn.config.Config.bind_socket

    def bind_socket(self: uvicorn.config.Config) -> socket.socket:
        sock = original(self)
        if sock.family in (socket.AF_INET, socket.AF_INET6):
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        return sock

    uvicorn.config.Config.bind_socket = bind_socket  # type: ignore[method-assign]


if __name__ == "__main__":
    main()
