"""Benchmark: the service's speed targets, in process, each beside its measured ratio.

Every request is driven straight into the ASGI app (no socket, no HTTP parser,
no client library), so what is measured is the service's own share: routing,
body validation, the lane or inline hand-over, the engine, response validation
and JSON encoding, the middleware.

* **Closed-form request vs the bare-FastAPI floor**: each model's cheapest rung
  on its first example, against two FastAPI apps with one route each, measured in
  the same rounds: the *same-payload* floor (FastAPI reads the same JSON body into a
  ``dict`` and answers the dict the real route answered, through its own response
  encoding: what FastAPI costs for this request and this answer, the target's "bare
  FastAPI endpoint of the same payload"; the target's verdict), and the stricter
  *no-body* floor (the same answer, the body not read). No validation, no
  middleware in either. Interleaved rounds on the same event loop; each figure is
  the median of the per-round ratios (robust to the load of a shared machine).
  Target ≤ 1.3.
  Beside it, in the same rounds, :func:`engine.run` alone on the same inputs (warm;
  validation, rung choice, physics, estimate and checks), and the request without it
  against the floor: the service's own share (body and response validation, JSON,
  routing, middleware), which is what the service layer can still shave; the engine's
  part is the model's physics.
* **A 2,000-point closed-form sweep through the app** (the case of
  ``bench/extra_targets.py``): target ≤ 20 ms (over HTTP: ``scripts/loadtest.py``).

Run alone: ``PYTHONPATH=. python -m bench.extra_service``.
"""

from __future__ import annotations

import asyncio
import functools
import json
import statistics
import time
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

import engine
from engine.models import MODELS

ROUNDS = 15
CALLS_PER_ROUND = 30
FLOOR_TARGET = 1.3
SWEEP_HTTP_TARGET_S = 20e-3

ASGIApp = Callable[[MutableMapping[str, Any], Any, Any], Awaitable[None]]


async def call(app: ASGIApp, method: str, path: str, body: bytes = b"") -> tuple[int, bytes]:
    """One request into ``app``: (status, body)."""
    scope = {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": method,
        "scheme": "http",
        "path": path,
        "raw_path": path.encode(),
        "query_string": b"",
        "root_path": "",
        "headers": [
            (b"host", b"bench"),
            (b"content-type", b"application/json"),
            (b"content-length", str(len(body)).encode()),
        ],
        "client": ("127.0.0.1", 50000),
        "server": ("127.0.0.1", 80),
    }
    sent = False
    done = asyncio.Event()
    status = 0
    chunks: list[bytes] = []

    async def receive() -> dict[str, Any]:
        nonlocal sent
        if not sent:
            sent = True
            return {"type": "http.request", "body": body, "more_body": False}
        await done.wait()  # the client stays connected until the answer is complete
        return {"type": "http.disconnect"}

    async def send(message: MutableMapping[str, Any]) -> None:
        nonlocal status
        if message["type"] == "http.response.start":
            status = message["status"]
        elif message["type"] == "http.response.body":
            chunks.append(message.get("body", b""))

    await app(scope, receive, send)
    done.set()
    return status, b"".join(chunks)


async def _per_call(app: ASGIApp, method: str, path: str, body: bytes, n: int) -> float:
    start = time.perf_counter()
    for _ in range(n):
        await call(app, method, path, body)
    return (time.perf_counter() - start) / n


def bare_app(path: str, payload: Any) -> ASGIApp:
    """The no-body floor: FastAPI with one POST route returning ``payload`` (defaults
    everywhere), the request body not read."""
    from fastapi import FastAPI

    app = FastAPI()

    async def answer() -> Any:
        return payload

    app.add_api_route(path, answer, methods=["POST"])
    return app


def same_payload_app(path: str, payload: Any) -> ASGIApp:
    """The same-payload floor: FastAPI with one POST route that reads the request's JSON
    body into a ``dict`` (FastAPI's parser and validation) and returns ``payload``."""
    from fastapi import Body, FastAPI

    app = FastAPI()

    async def answer(body: dict[str, Any] = Body(...)) -> Any:  # noqa: B008 - FastAPI's idiom
        return payload

    app.add_api_route(path, answer, methods=["POST"])
    return app


def _cheapest(spec: engine.ModelSpec) -> str:
    return next((r.name for r in spec.rungs if not r.heavy), spec.rung_names[0])


async def _measure() -> list[dict[str, Any]]:
    from bench.extra_targets import POINTS, sweep_case
    from service.config import Settings
    from service.main import create_app

    app = create_app(settings=Settings(warm_up=False, access_log=False))
    rows: list[dict[str, Any]] = []
    async with app.router.lifespan_context(app):
        for spec in MODELS:
            if not spec.examples:
                continue
            rung = _cheapest(spec)
            path = "/api/v1" + spec.path
            body = json.dumps({**spec.examples[0], "fidelity": rung}).encode()
            status, answer = await call(app, "POST", path, body)
            if status != 200:
                continue
            bare = bare_app(path, json.loads(answer))
            same = same_payload_app(path, json.loads(answer))
            for _ in range(CALLS_PER_ROUND):  # warm all three (caches, inline means)
                await call(app, "POST", path, body)
                await call(bare, "POST", path, body)
                await call(same, "POST", path, body)
            ratios, strict, mine, floor, floor_same, engine_s, shares = [], [], [], [], [], [], []
            inputs = {k: v for k, v in spec.examples[0].items()}
            warm = functools.partial(engine.run, spec, inputs, fidelity=rung)
            for _ in range(ROUNDS):
                a = await _per_call(app, "POST", path, body, CALLS_PER_ROUND)
                b = await _per_call(bare, "POST", path, body, CALLS_PER_ROUND)
                f = await _per_call(same, "POST", path, body, CALLS_PER_ROUND)
                c = _per_run(warm, CALLS_PER_ROUND)
                ratios.append(a / f)
                strict.append(a / b)
                shares.append((a - c) / f)
                mine.append(a)
                floor.append(b)
                floor_same.append(f)
                engine_s.append(c)
            ratio = statistics.median(ratios)
            share = statistics.median(shares)
            compute = statistics.median(engine_s)
            # the best ratio a service costing nothing beyond FastAPI itself could reach:
            # the same-payload floor plus the model's own work (why a ratio cannot reach its target)
            bound = statistics.median(
                (f + c) / f for f, c in zip(floor_same, engine_s, strict=True)
            )
            rows.append(
                {
                    "model": spec.name,
                    "method": f"request {rung}",
                    "case": "request / bare FastAPI",
                    "time_s": statistics.median(mine),
                    "ratio": ratio,
                    "ratio_no_body": statistics.median(strict),
                    "target": "closed-form request ≤ 1.3 × the bare-FastAPI floor (in process)",
                    "target_ratio": FLOOR_TARGET,
                    "met": ratio <= FLOOR_TARGET,
                    "service_share_ratio": share,
                    "access_log": False,  # the app below is built with it off
                    "engine_s": compute,
                    "ratio_engine_bound": bound,
                    "notes": (
                        f"request {_us(statistics.median(mine))}; floors: same payload "
                        f"{_us(statistics.median(floor_same))}, no body "
                        f"{_us(statistics.median(floor))} (×{statistics.median(strict):.2f}); "
                        f"engine.run (warm, validation included) {_us(compute)}; without it "
                        f"the request is ×{share:.2f} the same-payload floor, and a service "
                        f"adding nothing to FastAPI would be ×{bound:.2f}; {len(answer)} B"
                    ),
                }
            )
        for spec in MODELS:
            try:
                case = sweep_case(spec)
            except engine.EngineError:
                case = None
            if case is None:
                continue
            base, vary, values, rung = case
            path = "/api/v1" + spec.path + "/sweep"
            body = json.dumps(
                {
                    "base": base,
                    "vary": vary,
                    "start": float(values[0]),
                    "stop": float(values[-1]),
                    "num": POINTS,
                    "fidelity": rung,
                }
            ).encode()
            status, answer = await call(app, "POST", path, body)
            if status != 200:
                continue
            times = [await _per_call(app, "POST", path, body, 1) for _ in range(9)]
            t = statistics.median(times)
            rows.append(
                {
                    "model": spec.name,
                    "method": f"sweep {rung}",
                    "case": f"{POINTS}-pt sweep via the app",
                    "time_s": t,
                    "target": f"{POINTS}-point closed-form sweep ≤ 20 ms over HTTP",
                    "target_s": SWEEP_HTTP_TARGET_S,
                    "met": t <= SWEEP_HTTP_TARGET_S,
                    "notes": f"in process (no socket); {len(answer) / 1e3:.0f} kB answer",
                }
            )
    return rows


def _per_run(fn: Callable[[], Any], n: int) -> float:
    """Seconds per call of ``fn`` (the engine alone, as the route calls it)."""
    start = time.perf_counter()
    for _ in range(n):
        fn()
    return (time.perf_counter() - start) / n


def measure() -> list[dict[str, Any]]:
    return asyncio.run(_measure())


def _us(seconds: float) -> str:
    return f"{seconds * 1e6:.0f} µs"


if __name__ == "__main__":
    for row in measure():
        figure = f"×{row['ratio']:.2f}" if "ratio" in row else f"{row['time_s'] * 1e3:.2f} ms"
        goal = f"≤ ×{row['target_ratio']}" if "ratio" in row else f"≤ {row['target_s'] * 1e3:g} ms"
        met = "met" if row["met"] else "MISSED"
        print(f"{row['model']:<22} {row['case']:<26} {figure:>9} {goal:>9} {met:<6} {row['notes']}")
