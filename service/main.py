"""Build the FastAPI application: health, catalogue, one router per model, the form.

Middleware, outermost first: :class:`~service.middleware.FrontDoor` (request
id, security headers, access log, then gzip for answers and files of
:data:`GZIP_MINIMUM_BYTES` or more), CORS when ``CORS_ORIGINS`` names origins (closed
otherwise: no ``Access-Control-*`` header is ever sent), API keys where configured,
:class:`~service.middleware.BodyGuard` (415 for non-JSON bodies, 413 over
``MAX_BODY_BYTES``). A model's POST routes are reached from there directly
(:class:`~service.middleware.ExactRoutes`, their apps applying the exception handlers
themselves); every other request goes on through Starlette's exception layer and the
router. Model computations run in :mod:`service.workers`.

``/manual/`` serves the manual as built by MkDocs (``make run`` builds it into ``site/``;
the container image carries it at ``MANUAL_DIR``), under the same strict CSP as the form:
its pages carry no inline script and fetch nothing from elsewhere. Where it was not built,
``/manual/`` answers a short page saying how to build it.

``/docs`` (Swagger UI) is served from the copy vendored in
``static/vendor/swagger-ui``, so it works offline behind a firewall; ``/redoc``
loads ReDoc from a CDN (online only). Both start with one inline script,
which the page's strict CSP forbids. Rather than weaken the CSP everywhere,
those two pages carry their own: the inline script is allowed only by its
SHA-256 hash (no ``'unsafe-inline'`` for scripts), and /redoc also its CDN.
"""

from __future__ import annotations

import asyncio
import base64
import contextlib
import gc
import hashlib
import importlib.metadata
import os
import re
import signal
import subprocess
import threading
import time
from collections.abc import AsyncIterator, Callable, Sequence
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

from fastapi import FastAPI, Request
from fastapi.middleware.cors import CORSMiddleware
from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html
from fastapi.responses import HTMLResponse, JSONResponse, RedirectResponse
from fastapi.routing import APIRoute
from fastapi.staticfiles import StaticFiles
from starlette.middleware.exceptions import ExceptionMiddleware
from uvicorn.middleware.proxy_headers import ProxyHeadersMiddleware

import engine
from engine import ModelSpec
from engine.studies import kernels as study_kernels

from . import errors, units
from .api import API_PREFIX, Limits, catalogue_router, model_router
from .config import Settings
from .extra import EXTRA_ROUTERS
from .middleware import QUIET, ApiKeys, BodyGuard, ExactRoutes, FrontDoor, document_keys
from .studies import Studies, StudySettings, study_router
from .workers import EnginePool

_CDN = "https://cdn.jsdelivr.net"

#: Answers and files smaller than this go uncompressed (a single answer of a few fields);
#: the form's scripts, the catalogue, series and sweeps are gzipped for a client that asks.
GZIP_MINIMUM_BYTES = 4096
#: zlib level 6: within a few per cent of level 9's size at about a third of its time
#: (the static files are compressed per request).
GZIP_LEVEL = 6


def product_version() -> str:
    """The installed package's version (pyproject.toml), or "unknown" outside an install."""
    try:
        return importlib.metadata.version("tightening-calc")
    except importlib.metadata.PackageNotFoundError:
        return "unknown"


def product_commit() -> str:
    """The commit the service runs: ``COMMIT`` (set by an image build), else the checkout's
    HEAD, else "unknown" (no git, or not a checkout)."""
    if os.environ.get("COMMIT"):
        return os.environ["COMMIT"][:40]
    try:
        out = subprocess.run(
            ["git", "rev-parse", "HEAD"],
            cwd=Path(__file__).resolve().parent,
            capture_output=True,
            text=True,
            timeout=5,
            check=True,
        )
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    head = out.stdout.strip()
    return head if re.fullmatch(r"[0-9a-f]{40}", head) else "unknown"


def docs_csp(html: str, *, cdn: bool = True) -> str:
    """The CSP for a docs page: its inline scripts by hash only, and its CDN if it uses one."""
    hashes = " ".join(
        "'sha256-" + base64.b64encode(hashlib.sha256(m.encode()).digest()).decode() + "'"
        for m in re.findall(r"<script>(.*?)</script>", html, flags=re.S)
    )
    if not cdn:
        return (
            f"default-src 'none'; script-src 'self' {hashes}; "
            "style-src 'self' 'unsafe-inline'; img-src 'self' data:; "
            "connect-src 'self'; worker-src blob:; object-src 'none'; base-uri 'none'; "
            "frame-ancestors 'none'"
        )
    return (
        f"default-src 'none'; script-src 'self' {_CDN} {hashes}; "
        f"style-src 'self' 'unsafe-inline' {_CDN} https://fonts.googleapis.com; "
        "font-src https://fonts.gstatic.com data:; "
        f"img-src 'self' data: {_CDN} https://fastapi.tiangolo.com; "
        "connect-src 'self'; worker-src blob:; object-src 'none'; base-uri 'none'; "
        "frame-ancestors 'none'"
    )


def _docs_page(page: HTMLResponse, *, cdn: bool = True) -> HTMLResponse:
    text = bytes(page.body).decode()
    return HTMLResponse(text, headers={"content-security-policy": docs_csp(text, cdn=cdn)})


def warm_up(models: Sequence[ModelSpec]) -> None:
    """Evaluate each model's first example once per rung, ignoring every outcome.

    Some rungs pay a one-off cost on their first call in a process (the
    rare-impact and blow simulations load their numba-compiled kernels, 0.3-0.5 s
    from numba's disk cache, seconds to compile without it); paying it here, in a
    background thread at start-up, keeps it off the first request. ``/readyz``
    answers "warming" until it has run (:class:`WarmUp`). The compiled passes of a
    study's summary (:mod:`engine.studies.kernels`) are loaded here too, off a user's
    first study of 50,000 points or more.
    """
    for spec in models:
        for example in spec.examples[:1]:
            for rung in spec.rung_names:
                with contextlib.suppress(Exception):
                    engine.run(spec, example, fidelity=rung)
    with contextlib.suppress(Exception):  # 0.01-0.02 s once numba is loaded (measured)
        study_kernels.warm()


def kernel_cache() -> dict[str, dict[str, int]]:
    """Every numba-compiled function of the engine that this process has called from
    Python: its signatures, how many of them came from numba's disk cache (``loaded``) and
    how many were compiled here (``compiled``). Functions only ever called from inside
    another kernel are compiled into it and are not listed.

    After :func:`warm_up` in a process whose cache is warm, every kernel is loaded and
    none compiled (the image build checks this; ``tests/service/test_cold_start.py``).

    >>> kernel_cache() == {} or all(k["signatures"] > 0 for k in kernel_cache().values())
    True
    """
    import sys

    try:
        from numba.core.dispatcher import Dispatcher
    except ImportError:  # pragma: no cover - numba is a declared dependency
        return {}
    found: dict[str, dict[str, int]] = {}
    for name, module in list(sys.modules.items()):
        if name != "engine" and not name.startswith("engine."):
            continue
        for attr, value in list(vars(module).items()):
            if isinstance(value, Dispatcher) and value.signatures:
                stats = value.stats
                found[f"{name}.{attr}"] = {
                    "signatures": len(value.signatures),
                    "loaded": sum(stats.cache_hits.values()),
                    "compiled": sum(stats.cache_misses.values()),
                }
    return found


#: The warm-up builds the unit registry once no request has been open this long [s], or at
#: the latest this long after it said ready [s] (a service that is never quiet).
REGISTRY_QUIET_S = 0.25
REGISTRY_WAIT_LIMIT_S = 10.0


class WarmUp:
    """The start-up warm-up (:func:`warm_up`) on its own thread, and whether it is done.

    ``/readyz`` answers 503 "warming" until :attr:`done`: a load balancer or an
    orchestrator waiting on it sends no request before the compiled kernels are loaded.
    Off (``WARM_UP=0``) it is done at once. It is done however it ends: a model that
    fails while warming up does not keep the service unready.

    >>> off = WarmUp([], enabled=False)
    >>> off.done, off.state
    (True, 'off')
    >>> on = WarmUp([], enabled=True)
    >>> on.done, on.state
    (False, 'warming')
    >>> on.run(); on.done, on.state, on.seconds is not None
    (True, 'done', True)

    Once it says so, it builds the unit registry (:func:`service.units.registry`) too, at the
    first quiet moment (:data:`REGISTRY_QUIET_S` without an open request).

    ``after`` runs once it is done, before it says so (at once when off):

    >>> seen = []
    >>> late = WarmUp([], enabled=True)
    >>> late.start(after=lambda: seen.append(late.done)); late.wait(10), seen
    (True, [False])
    """

    def __init__(self, models: Sequence[ModelSpec], *, enabled: bool) -> None:
        self.models = models
        self.enabled = enabled
        self.seconds: float | None = None  #: how long it took, once done [s]
        self._done = threading.Event()
        self._after: Callable[[], None] | None = None
        if not enabled:
            self._done.set()

    @property
    def done(self) -> bool:
        return self._done.is_set()

    @property
    def state(self) -> str:
        """``off``, ``warming`` or ``done``."""
        return "off" if not self.enabled else "done" if self.done else "warming"

    def start(self, after: Callable[[], None] | None = None) -> None:
        """Run it on a daemon thread, then ``after`` (at once when off or already done)."""
        if self.done:
            if after is not None:
                after()
            return
        self._after = after
        threading.Thread(target=self.run, name="warm-up", daemon=True).start()

    def run(self) -> None:
        start = time.perf_counter()
        try:
            warm_up(self.models)
        finally:
            self.seconds = time.perf_counter() - start
            try:
                if self._after is not None:
                    self._after()
            finally:
                self._done.set()
        # then, ready already, the unit registry (pint, 0.2-0.3 s of CPU): the form sends
        # unit strings, and its first request should not pay for it; one that comes sooner
        # waits on the registry's lock, as it would without this. Built at the first quiet
        # moment: built at once, it took the processor from the first requests after ready
        # (a rare-impact simulation took 11-16 ms against its steady 3-6 ms, bench.cold_start)
        QUIET.wait(REGISTRY_QUIET_S, REGISTRY_WAIT_LIMIT_S)
        with contextlib.suppress(Exception):
            units.registry()

    def wait(self, timeout: float | None = None) -> bool:
        """Block until done or ``timeout`` [s]; whether it is done."""
        return self._done.wait(timeout)


def collector_on() -> None:
    """Freeze every object made so far out of the collector's scans and turn it on.

    Start-up (imports, the app, the loaded kernels) makes some million objects that live
    as long as the process: frozen, they are never scanned again.
    """
    gc.freeze()
    gc.enable()


#: On SIGTERM, open work gets the shutdown timeout less this to finish; then it is stopped
#: and answers 503 before uvicorn closes the connections at the timeout [s].
STOP_MARGIN_S = 1.0


def after_stop_signal(callback: Callable[[], None]) -> Callable[[], None]:
    """Call ``callback`` when SIGTERM or SIGINT arrives, then the handler already set (the
    server's: uvicorn's starts its graceful shutdown; Python's raises KeyboardInterrupt);
    answers a function that puts the handlers back. Nothing is set outside the main
    thread (a test client's lifespan)."""
    if threading.current_thread() is not threading.main_thread():
        return lambda: None
    previous = {sig: signal.getsignal(sig) for sig in (signal.SIGTERM, signal.SIGINT)}

    def handler(sig: int, frame: object) -> None:
        before = previous[signal.Signals(sig)]
        with contextlib.suppress(RuntimeError):  # the app's loop closed: nothing to stop
            callback()
        if callable(before):
            before(sig, frame)  # type: ignore[arg-type]

    for sig in previous:
        signal.signal(sig, handler)

    def undo() -> None:
        for sig, before in previous.items():
            if signal.getsignal(sig) is handler:
                signal.signal(sig, before)

    return undo


def static_dir() -> Path:
    """``service/static`` in an installed wheel, ``static/`` beside the package in a checkout."""
    here = Path(__file__).resolve().parent
    for candidate in (here / "static", here.parent / "static"):
        if (candidate / "index.html").is_file():
            return candidate
    raise RuntimeError("static/index.html not found next to the service package")


#: What /manual/ answers when the manual was not built (404: there is no manual to show).
MANUAL_MISSING = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Manual not built</title></head>
<body><h1>The manual is not built here</h1>
<p>Build it from a checkout with <code>make manual</code> (or <code>make run</code>, which
builds it first), or with <code>python -m mkdocs build</code> after
<code>pip install -e '.[docs]'</code>; the service serves <code>site/</code>, or the folder
named by <code>MANUAL_DIR</code>. Its sources are <code>docs/</code> in the repository.</p>
<p><a href="/">The calculator</a> · <a href="/docs">API reference</a></p>
</body></html>
"""


def manual_dir(configured: str = "") -> Path | None:
    """The built manual's folder: ``configured`` (``MANUAL_DIR``), else ``site/`` beside the
    package in a checkout; None where neither holds an ``index.html``."""
    here = Path(__file__).resolve().parent
    candidate = Path(configured) if configured else here.parent / "site"
    return candidate if (candidate / "index.html").is_file() else None


def create_app(
    models: Sequence[ModelSpec] | None = None,
    settings: Settings | None = None,
    study_settings: StudySettings | None = None,
) -> FastAPI:
    models = engine.MODELS if models is None else models
    settings = settings or Settings()
    pool = EnginePool(
        settings.engine_threads,
        settings.engine_queue,
        settings.budget_grace_s,
        heavy_slots=settings.heavy_slots,
        heavy_queue=settings.heavy_queue,
        heavy_per_client=settings.heavy_per_client,
        wait_s=settings.admission_wait_s,
        inline_budget_s=settings.inline_budget_s,
    )
    limits = Limits(
        pool=pool,
        budget_s=settings.budget_s,
        max_steps=settings.max_steps,
        max_series_points=settings.max_series_points,
    )

    studies = Studies(study_settings or StudySettings())
    warming = WarmUp(models, enabled=settings.warm_up)

    @asynccontextmanager
    async def lifespan(_: FastAPI) -> AsyncIterator[None]:
        # The collector is off while starting (service.__main__) and stays off until the
        # warm-up has loaded the kernels: numba's first load in a process makes some
        # hundred thousand objects that live as long as it (0.03 s of a 0.4 s warm-up,
        # 2.8 s of a 14 s compile where the cache is cold, measured). What start-up made
        # is then frozen out of later scans.
        warming.start(after=collector_on if not gc.isenabled() else None)
        # on SIGTERM open work may finish for a while, then answers 503 (not a dropped
        # connection at uvicorn's graceful-shutdown timeout)
        loop = asyncio.get_running_loop()
        grace = max(0.0, settings.shutdown_timeout_s - STOP_MARGIN_S)

        def stop_later() -> None:  # in the signal handler: hand it to the loop
            loop.call_soon_threadsafe(loop.call_later, grace, pool.stop)

        undo = after_stop_signal(stop_later)
        yield
        undo()
        pool.shutdown()
        studies.shutdown()

    version = product_version()
    app = FastAPI(
        title="Tightening-tool calculator",
        version=version,
        summary="Validated engineering models of threaded-joint assembly tools.",
        description="Every input is a number in SI base units or a string with a unit "
        "('45 mm', '1450 rpm'); every result is SI, with its unit alongside. "
        "See GET /api/v1/models for the catalogue.",
        docs_url=None,
        redoc_url=None,
        lifespan=lifespan,
    )
    errors.install(app)
    app.state.engine_pool = pool
    app.state.warm_up = warming

    @app.get("/healthz", tags=["service"], summary="Liveness", operation_id="healthz")
    async def healthz() -> dict[str, str]:  # on the loop: a liveness probe needs no thread
        return {"status": "ok"}

    @app.get(
        "/readyz",
        operation_id="readyz",
        tags=["service"],
        summary="Readiness: 503 while warming up or while either engine lane cannot admit work",
        description=(
            '503 "warming" until the start-up warm-up has run every model\'s first example '
            "once per rung (the compiled kernels loaded; at once with WARM_UP=0); then 503 "
            '"busy" while a lane has no free slot and a full queue. Each lane\'s running '
            "and waiting computations, and the studies: running and queued in this process, "
            "and unfinished in all. Studies never make the service busy (they run on their "
            "own threads and workers): they are reported, not gated."
        ),
        responses={
            503: {
                "description": 'not ready, and why in "status": "warming" while the start-up '
                'warm-up runs, "busy" while a lane has no free slot and a full queue, '
                '"store_error" while the study job store cannot be read (studies.store_error '
                "says why); with Retry-After"
            }
        },
    )
    async def readyz() -> JSONResponse:
        admits, study_state = pool.ready(), studies.state()
        stored = "store_error" not in study_state  # the job store can be read
        ready = admits and warming.done and stored
        if ready:
            status = "ready"
        elif not warming.done:
            status = "warming"
        else:  # a store that cannot be read is said before a full lane
            status = "busy" if stored else "store_error"
        return JSONResponse(
            {
                "status": status,
                "warm_up": warming.state,
                "lanes": pool.state(),
                "studies": study_state,
            },
            status_code=200 if ready else 503,
            headers=None if ready else {"retry-after": "1"},
        )

    swagger = _docs_page(
        get_swagger_ui_html(
            openapi_url="/openapi.json",
            title=app.title,
            swagger_js_url="/vendor/swagger-ui/swagger-ui-bundle.js",
            swagger_css_url="/vendor/swagger-ui/swagger-ui.css",
            swagger_favicon_url="/vendor/swagger-ui/favicon-32x32.png",
        ),
        cdn=False,
    )
    redoc = _docs_page(get_redoc_html(openapi_url="/openapi.json", title=app.title))

    @app.get("/docs", include_in_schema=False)
    def docs() -> HTMLResponse:
        return swagger

    @app.get("/redoc", include_in_schema=False)
    def redoc_page() -> HTMLResponse:
        return redoc

    @app.get("/report", include_in_schema=False)
    def report(request: Request) -> RedirectResponse:
        """``/report?m=…&ex=0&…``: the calculation report of a link's query (to archive)."""
        query = request.url.query
        return RedirectResponse(
            "./#" + (query + "&" if query else "") + "view=report", status_code=303
        )

    # the other catalogues the form may read (preload methods, fasteners): named in /models
    others = {
        r.path.removeprefix("/api/v1/").replace("/", "_"): r.path
        for router in EXTRA_ROUTERS
        for r in router.routes
        if isinstance(r, APIRoute) and "GET" in (r.methods or ()) and not r.param_convertors
    }
    about = {"version": version, "commit": product_commit(), "catalogues": others}
    model_routers = [model_router(s, limits) for s in models]
    routers = [catalogue_router(models, about), *model_routers, *EXTRA_ROUTERS]
    studies_router = study_router(models, studies)
    for router in (*routers, studies_router):
        # The routes themselves, not include_router: FastAPI ≥ 0.16x nests an included
        # router and walks every nested router's route table on each request (~15 µs a
        # request with our 11 routers, measured). None of ours has router-level
        # dependencies, responses or callbacks to inherit, so nothing is lost.
        app.router.routes.extend(router.routes)
    app.state.studies = studies
    routers.append(studies_router)
    json_paths = frozenset(
        r.path
        for router in routers
        for r in router.routes
        if isinstance(r, APIRoute) and "POST" in (r.methods or ())
    )
    exact = {
        r.path: r
        for r in app.router.routes
        if isinstance(r, APIRoute) and "POST" in (r.methods or ()) and not r.param_convertors
    }
    app.router.middleware_stack = ExactRoutes(app.router.middleware_stack, app.router, exact)
    # the model routes (service.api.lean_endpoint) from the innermost middleware on
    lean = {r.path: r for router in model_routers for r in router.routes if isinstance(r, APIRoute)}
    build_stack = app.build_middleware_stack

    def build_middleware_stack() -> Any:
        stack = build_stack()
        layer: Any = stack  # each middleware holds the next as .app
        while not isinstance(layer.app, ExceptionMiddleware):
            layer = layer.app
        caught = layer.app
        handlers = (caught._exception_handlers, caught._status_handlers)
        layer.app = ExactRoutes(caught, app.router, lean, handlers)
        return stack

    app.build_middleware_stack = build_middleware_stack  # type: ignore[method-assign]
    app.add_middleware(
        BodyGuard,
        limit=settings.max_body_bytes,
        json_paths=json_paths,
        body_timeout_s=settings.body_timeout_s,
    )
    if settings.api_keys:  # before any body is read: an unknown client costs nothing
        app.add_middleware(ApiKeys, keys=settings.api_keys, prefix=API_PREFIX)
    build_openapi = app.openapi

    def openapi() -> dict[str, Any]:
        if app.openapi_schema is None:
            document_keys(build_openapi(), bool(settings.api_keys), API_PREFIX)
        assert app.openapi_schema is not None
        return app.openapi_schema

    app.openapi = openapi  # type: ignore[method-assign]
    if settings.cors_origins:
        app.add_middleware(
            CORSMiddleware,
            allow_origins=list(settings.cors_origins),
            allow_methods=["GET", "POST"],
            allow_headers=["content-type", "x-request-id", "authorization", "x-api-key"],
            expose_headers=["x-request-id"],
        )
    # compression inside FrontDoor's headers and log: they go on either body
    app.add_middleware(
        FrontDoor,
        log_requests=settings.access_log,
        gzip_minimum_size=GZIP_MINIMUM_BYTES,
        gzip_level=GZIP_LEVEL,
    )
    if settings.trusted_proxies:  # outermost: every guard and quota sees the real client
        app.add_middleware(ProxyHeadersMiddleware, trusted_hosts=list(settings.trusted_proxies))

    @app.get("/manual", include_in_schema=False)
    def manual_root() -> RedirectResponse:
        return RedirectResponse("/manual/", status_code=308)

    manual = manual_dir(settings.manual_dir)
    if manual is not None:
        app.mount("/manual", StaticFiles(directory=manual, html=True), name="manual")
    else:

        @app.get("/manual/{path:path}", include_in_schema=False)
        def manual_missing(path: str) -> HTMLResponse:
            return HTMLResponse(MANUAL_MISSING, status_code=404)

    app.mount("/", StaticFiles(directory=static_dir(), html=True), name="static")
    return app
