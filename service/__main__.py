"""``python -m service [--host H] [--port P]``: serve the API and the form with uvicorn."""

from __future__ import annotations

import argparse

import uvicorn

from .config import Settings


def main(argv: list[str] | None = None) -> None:
    settings = Settings()
    parser = argparse.ArgumentParser(prog="python -m service", description=__doc__)
    parser.add_argument("--host", default=settings.host, help="bind address (HOST)")
    parser.add_argument("--port", type=int, default=settings.port, help="port (PORT)")
    parser.add_argument("--workers", type=int, default=1, help="worker processes")
    args = parser.parse_args(argv)
    uvicorn.run(
        "service.main:create_app",
        factory=True,
        host=args.host,
        port=args.port,
        workers=args.workers,
        log_level=settings.log_level,
        server_header=False,
        date_header=False,
    )


if __name__ == "__main__":
    main()
