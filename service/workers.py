"""Where model computations run: a bounded pool of threads, each call with a deadline.

Why threads and not processes
-----------------------------
* Most requests are closed forms that take microseconds. A process pool would
  pickle every request and result across a pipe (hundreds of microseconds to
  milliseconds), which would cost more than the physics and break the
  throughput target for closed forms; specs also hold closures that do not
  pickle, so a process pool would have to re-import the registry by name.
* The heavy rungs are numpy/scipy: their kernels release the GIL, and pure
  Python stepping yields it every ``sys.getswitchinterval()`` (5 ms), so the
  event loop and quick requests keep running beside a slow one (shown in
  ``tests/service/test_isolation.py``).
* The engine already has a cooperative budget: :func:`engine.run` hands every
  model ``ctx.deadline`` and ``ctx.max_steps``, and a model past either raises
  :class:`engine.BudgetExceeded` (422, naming the budget).

What the pool adds on top
-------------------------
* The deadline counts from the moment the request is admitted, queueing
  included: the model gets what is left of ``BUDGET_S``.
* A hard ceiling: a computation that ignores its deadline is waited for
  ``BUDGET_S + BUDGET_GRACE_S`` at most; the request then gets 422
  ``budget_exceeded`` and the thread finishes in the background. It still
  holds its slot until it does, so a model that never stops cannot make the
  process start ever more threads.
* Bounded admission: at most ``ENGINE_THREADS`` computations run and
  ``ENGINE_QUEUE`` wait; one more gets 503 with ``Retry-After`` at once
  instead of an unbounded queue.

Cost: the hop to a thread and back is about 0.1 ms of CPU per request
(measured in-process on preload.tightening: ~0.37 ms through the pool against
~0.26 ms inline), the price of never running a computation on the event loop.

A thread cannot be killed, so a model that ignores its deadline forever would
keep its slot: the warning logged on every hard timeout names the model so it
can be fixed. Scale across cores with ``python -m service --workers N``.
"""

from __future__ import annotations

import asyncio
import logging
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor
from typing import Any, TypeVar

from engine import BudgetExceeded

log = logging.getLogger("service")

T = TypeVar("T")


class Busy(Exception):
    """Every worker slot and queue place is taken (503)."""


class EnginePool:
    """Run ``fn(remaining_budget_s)`` in a bounded thread pool with a wall-clock budget."""

    def __init__(self, threads: int, queue: int, grace_s: float) -> None:
        self.threads = threads
        self.capacity = threads + queue
        self.grace_s = grace_s
        self._executor: ThreadPoolExecutor | None = None
        self._lock = threading.Lock()
        self._in_flight = 0

    @property
    def in_flight(self) -> int:
        """Computations admitted and not finished (running, queued or abandoned)."""
        return self._in_flight

    def _release(self, _: Future[Any]) -> None:
        with self._lock:
            self._in_flight -= 1

    async def run(self, fn: Callable[[float], T], budget_s: float, what: str) -> T:
        """``fn`` gets the seconds left of ``budget_s`` when a thread picks it up."""
        with self._lock:
            if self._in_flight >= self.capacity:
                raise Busy(
                    f"the server is busy: {self.capacity} computations are already "
                    "running or queued; retry in a moment"
                )
            self._in_flight += 1
        deadline = time.perf_counter() + budget_s

        def job() -> T:
            remaining = deadline - time.perf_counter()
            if remaining <= 0:
                raise BudgetExceeded(
                    f"{what} waited its whole {budget_s:g} s wall-clock budget (BUDGET_S) "
                    "for a free worker",
                    budget_s=budget_s,
                )
            return fn(remaining)

        with self._lock:
            if self._executor is None:
                self._executor = ThreadPoolExecutor(self.threads, thread_name_prefix="engine")
            future = self._executor.submit(job)
        future.add_done_callback(self._release)
        try:
            return await asyncio.wait_for(asyncio.wrap_future(future), budget_s + self.grace_s)
        except TimeoutError:
            log.warning(
                "%s ignored its %g s deadline; left running in the background", what, budget_s
            )
            raise BudgetExceeded(
                f"{what} did not finish within its {budget_s:g} s wall-clock budget (BUDGET_S)",
                budget_s=budget_s,
            ) from None

    def shutdown(self) -> None:
        """Drop queued work and let the threads end; a later call starts a fresh pool."""
        with self._lock:
            executor, self._executor = self._executor, None
        if executor is not None:
            executor.shutdown(wait=False, cancel_futures=True)
