"""Build the FastAPI application: health, catalogue, one router per model, the form."""

from __future__ import annotations

import json
from collections.abc import Awaitable, Callable, MutableMapping, Sequence
from pathlib import Path
from typing import Any

from fastapi import FastAPI
from fastapi.middleware.cors import CORSMiddleware
from fastapi.staticfiles import StaticFiles

import engine
from engine import ModelSpec

from . import errors
from .api import catalogue_router, model_router
from .config import Settings
from .extra import EXTRA_ROUTERS

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]


def static_dir() -> Path:
    """``service/static`` in an installed wheel, ``static/`` beside the package in a checkout."""
    here = Path(__file__).resolve().parent
    for candidate in (here / "static", here.parent / "static"):
        if (candidate / "index.html").is_file():
            return candidate
    raise RuntimeError("static/index.html not found next to the service package")


class BodyLimit:
    """Refuse request bodies over ``limit`` bytes with 413, before they are read whole."""

    def __init__(self, app: ASGIApp, limit: int) -> None:
        self.app = app
        self.limit = limit

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = dict(scope.get("headers") or [])
        length = headers.get(b"content-length")
        if length is not None and (not length.isdigit() or int(length) > self.limit):
            await self._refuse(send)
            return
        seen = 0

        async def limited() -> Message:
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.limit:
                    raise _TooLarge
            return message

        try:
            await self.app(scope, limited, send)
        except _TooLarge:
            await self._refuse(send)

    async def _refuse(self, send: Send) -> None:
        body = json.dumps(
            errors.error_body(
                "body_too_large", f"request body over the {self.limit}-byte limit", []
            )
        ).encode()
        await send(
            {
                "type": "http.response.start",
                "status": 413,
                "headers": [(b"content-type", b"application/json")],
            }
        )
        await send({"type": "http.response.body", "body": body})


class _TooLarge(Exception):
    pass


def create_app(
    models: Sequence[ModelSpec] | None = None, settings: Settings | None = None
) -> FastAPI:
    models = engine.MODELS if models is None else models
    settings = settings or Settings()
    app = FastAPI(
        title="Tightening-tool calculator",
        version="1.0",
        summary="Validated engineering models of threaded-joint assembly tools.",
        description="Every input is a number in SI base units or a string with a unit "
        "('45 mm', '1450 rpm'); every result is SI, with its unit alongside. "
        "See GET /api/v1/models for the catalogue.",
    )
    errors.install(app)

    @app.get("/healthz", tags=["service"], summary="Liveness")
    def healthz() -> dict[str, str]:
        return {"status": "ok"}

    app.include_router(catalogue_router(models))
    for spec in models:
        app.include_router(model_router(spec))
    for router in EXTRA_ROUTERS:
        app.include_router(router)
    if settings.cors_origins:
        app.add_middleware(
            CORSMiddleware,
            allow_origins=list(settings.cors_origins),
            allow_methods=["GET", "POST"],
            allow_headers=["content-type"],
        )
    app.add_middleware(BodyLimit, limit=settings.max_body_bytes)
    app.mount("/", StaticFiles(directory=static_dir(), html=True), name="static")
    return app
