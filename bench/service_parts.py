"""Diagnostic: a closed-form request's service share taken apart, per model.

``bench/extra_service.py`` gives the service's share as (request − ``engine.run``) / the
same-payload FastAPI floor. That difference holds three things, which this script separates
by driving the same app (access log on, as there) with :func:`engine.run` replaced by the
answer it gave for the model's first example at its cheapest rung, made afresh for every
request as the runner makes it (sentences still marked, read when the route asks):

* **service**: the request with that instant engine: routing, body reading and validation,
  the inline or lane hand-over, reading the sentences (each quantity of a check or note
  becomes its text and its parts, :meth:`engine.RunResult.answer_sentences`), encoding, the
  middleware and the access log;
* **service, sentences read beforehand**: the same, the sentences given already read: what
  reading them costs is the difference (measured: 1.8-2.0 µs a quantity in the request, the
  plain sentences' share included; 1.2 µs a quantity in a tight loop);
* what neither holds is the cost of running the two together: the real request less the
  service alone and ``engine.run`` alone (caches shared by the engine and the service's code,
  and, for a computation in a lane, the thread hand-off and the worker's cold start).

Each figure is the median of interleaved rounds in processor time (``time.process_time``),
beside the same-payload floor measured in the same rounds. A model sent to a lane by the
inline time box alone (``trace.batch``, ``impact.rare_design``) runs inline here once its
instant stand-in has brought its running mean under the box; a heavy rung
(``joint.clamp_capability``) stays in its lane, so its figure holds the hand-off (measured:
+126 µs of processor time a request for an instant computation, 67 on the loop's thread).

Run: ``PYTHONPATH=. python -m bench.service_parts [model,model,...]``.
"""

from __future__ import annotations

import asyncio
import json
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import engine
from engine.core.runner import RunResult
from engine.core.text import OPEN
from engine.models import MODELS

from .extra_service import ASGIApp, _cheapest, access_log_on, call, same_payload_app

ROUNDS = 9
CALLS_PER_ROUND = 100


class _Read(RunResult):
    """A result whose sentences come read already (the figure without reading them)."""

    read: Any = None

    def answer_sentences(self) -> Any:
        return self.read


def _stand_ins(result: RunResult) -> tuple[Callable[..., RunResult], Callable[..., RunResult]]:
    """Two replacements of :func:`engine.run` answering ``result`` afresh on every call: its
    sentences marked as the runner leaves them, and read already."""
    marked = result.__dict__["_marked"]
    fields = {k: v for k, v in result.__dict__.items() if k != "_marked"}
    read = RunResult._of(*marked, **fields).answer_sentences()

    def instant(*_: Any, **__: Any) -> RunResult:
        return RunResult._of(*marked, **{**fields, "results": dict(fields["results"])})

    def instant_read(*_: Any, **__: Any) -> RunResult:
        made = _Read._of(*marked, **{**fields, "results": dict(fields["results"])})
        assert isinstance(made, _Read)
        made.read = read
        return made

    return instant, instant_read


async def _per_call(app: ASGIApp, path: str, body: bytes) -> float:
    start = time.process_time()
    for _ in range(CALLS_PER_ROUND):
        await call(app, "POST", path, body)
    return (time.process_time() - start) / CALLS_PER_ROUND


async def _measure(names: set[str] | None) -> list[dict[str, Any]]:
    from service.config import Settings
    from service.main import create_app

    app = create_app(settings=Settings(warm_up=False, access_log=True))
    real = engine.run
    rows = []
    async with app.router.lifespan_context(app):
        for spec in MODELS:
            if not spec.examples or (names is not None and spec.name not in names):
                continue
            rung = _cheapest(spec)
            path = "/api/v1" + spec.path
            body = json.dumps({**spec.examples[0], "fidelity": rung}).encode()
            result = real(spec, dict(spec.examples[0]), fidelity=rung)
            if "_marked" not in result.__dict__:
                continue
            status, answer = await call(app, "POST", path, body)
            if status != 200:
                continue
            floor = same_payload_app(path, json.loads(answer))
            checks, notes = result.__dict__["_marked"]
            quantities = sum(s.count(OPEN) for s in [c.detail for c in checks] + list(notes))
            instant, instant_read = _stand_ins(result)
            timed: dict[str, list[float]] = {"service": [], "read": [], "floor": []}
            try:
                for i in range(ROUNDS):
                    order = ("service", "read", "floor")
                    for what in order if i % 2 == 0 else order[::-1]:
                        if what == "floor":
                            timed[what].append(await _per_call(floor, path, body))
                            continue
                        engine.run = instant if what == "service" else instant_read
                        for _ in range(10):  # its inline mean at the stand-in's
                            await call(app, "POST", path, body)
                        timed[what].append(await _per_call(app, path, body))
            finally:
                engine.run = real
            per_round = list(zip(timed["service"], timed["read"], timed["floor"], strict=True))
            rows.append(
                {
                    "model": spec.name,
                    "bytes": len(answer),
                    "quantities": quantities,
                    "service_s": statistics.median(timed["service"]),
                    "without_reading_s": statistics.median(timed["read"]),
                    "floor_s": statistics.median(timed["floor"]),
                    "service_ratio": statistics.median(s / f for s, _, f in per_round),
                    "without_reading_ratio": statistics.median(r / f for _, r, f in per_round),
                }
            )
    return rows


def measure(names: set[str] | None = None) -> list[dict[str, Any]]:
    with access_log_on():
        return asyncio.run(_measure(names))


if __name__ == "__main__":
    chosen = set(sys.argv[1].split(",")) if len(sys.argv) > 1 else None
    print(f"{'model':24s} {'B':>6s} {'q':>3s}  service (÷ floor)  without reading  floor")
    for row in measure(chosen):
        print(
            f"{row['model']:24s} {row['bytes']:6d} {row['quantities']:3d}  "
            f"{row['service_s'] * 1e6:5.0f} µs (×{row['service_ratio']:.2f})  "
            f"{row['without_reading_s'] * 1e6:5.0f} µs (×{row['without_reading_ratio']:.2f})  "
            f"{row['floor_s'] * 1e6:4.0f} µs"
        )
