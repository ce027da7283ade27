"""Where model computations run: two lanes of threads, admission by a short wait, cancellation.

Lanes
-----
* **quick**: closed forms and single points of cheap rungs (microseconds).
  ``ENGINE_THREADS`` run at once, ``ENGINE_QUEUE`` may wait.
* **heavy**: a rung declared ``heavy`` (simulations), and sweeps that loop
  (every sweep without an array path for its rung). ``HEAVY_SLOTS`` run at
  once, ``HEAVY_QUEUE`` may wait, and one client (its address) holds at most
  ``HEAVY_PER_CLIENT`` slots; a freed slot goes to the waiting client that
  holds the fewest, oldest first, so one client sending many sweeps cannot
  take the lane from the others.

Cheap work therefore never waits behind heavy work: the lanes share no
thread and no queue. The heavy kernels release the GIL (numba ``nogil``,
numpy), and pure-Python stepping yields it every ``sys.getswitchinterval()``.

Admission
---------
A request that cannot start within ``ADMISSION_WAIT_S`` (or finds the lane's
queue full) gets 503 with ``Retry-After`` (:class:`Busy`): the server's
state, honestly reported, never blamed on the input. The wall-clock budget
``BUDGET_S`` starts when the computation does, so 422 ``budget_exceeded``
means the computation itself ran past it.

Cancellation
------------
Each request carries a :class:`threading.Event`; the route sets it when the
client disconnects (:func:`watch_disconnect`). The engine tests it at every
budget check (``ctx.check_budget()``, the simulation's chunk loop, each
sweep point) and stops with :class:`engine.Cancelled`; the slot is released
as soon as the thread returns. A waiting request whose client leaves gives
up its place at once.

A hard ceiling remains for a model that ignores its budget: it is waited for
``BUDGET_S + BUDGET_GRACE_S`` at most; the request gets 422
``budget_exceeded`` and the thread finishes in the background, still holding
its slot, so a model that never stops cannot make the process start ever
more threads (the warning names the model so it can be fixed).

Inline
------
A computation of a rung *not* declared ``heavy`` (a closed form: tens to
hundreds of microseconds) skips the thread hop and runs on the event loop
itself (:class:`Inline`), which was measured at ~40 % of such a request
(180–330 µs of queue hand-over and GIL switches). A slow "cheap" computation
must not starve the others, so inline work is time-boxed:

* only a single evaluation of a rung not declared heavy and without a
  ``fallback`` runs inline (sweeps, simulations and studies keep their lanes);
* it runs with ``INLINE_BUDGET_S`` (2 ms) as its wall-clock budget: a model
  that checks its budget and runs past it stops there, and the request runs
  again in the quick lane with the full ``BUDGET_S``;
* each (model, rung) keeps a running mean of its measured time, in either
  path; while that mean is over ``INLINE_BUDGET_S`` (or after any single call
  over 10× it) its requests go to the quick lane, and come back inline once
  the lane measures them cheap again. A closed form that blocks the loop for
  long therefore does so at most once before it is moved off it.

``INLINE_BUDGET_S=0`` turns inline work off (every computation in a lane).

Why threads and not processes: most requests take microseconds, and pickling
a request and its result across a pipe would cost more than the physics;
specs also hold closures that do not pickle. Scale across cores with
``python -m service --workers N``.
"""

from __future__ import annotations

import asyncio
import itertools
import logging
import math
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any, TypeVar

from engine import BudgetExceeded, Cancelled

log = logging.getLogger("service")

T = TypeVar("T")

Receive = Callable[[], Any]


class Busy(Exception):
    """No slot could be had within the admission wait (503 with Retry-After)."""

    def __init__(self, message: str, retry_after: int = 1) -> None:
        super().__init__(message)
        self.retry_after = retry_after


@dataclass
class _Waiter:
    client: str
    seq: int
    granted: asyncio.Future[None]


@dataclass
class Ticket:
    """One request's claim on the engine: its client, and the event that withdraws it."""

    client: str
    cancel: threading.Event = field(default_factory=threading.Event)
    gone: asyncio.Event = field(default_factory=asyncio.Event)

    def withdraw(self) -> None:
        self.cancel.set()
        self.gone.set()


async def watch_disconnect(receive: Receive, ticket: Ticket) -> None:
    """Withdraw ``ticket`` when the client disconnects (after the body has been read)."""
    while True:
        message = await receive()
        if message.get("type") == "http.disconnect":
            ticket.withdraw()
            return


class Lane:
    """Bounded slots with a short admission wait and a per-client share.

    Everything but the worker threads runs on the event loop, so the counters
    need no lock; a thread's end is handed back with ``call_soon_threadsafe``.
    """

    def __init__(
        self,
        name: str,
        *,
        slots: int,
        queue: int,
        per_client: int,
        wait_s: float,
        grace_s: float,
    ) -> None:
        self.name = name
        self.slots = slots
        self.queue = queue
        self.per_client = max(1, min(per_client, slots))
        self.wait_s = wait_s
        self.grace_s = grace_s
        self.running = 0
        self._by_client: dict[str, int] = {}
        self._waiters: list[_Waiter] = []
        self._seq = itertools.count()
        self._ends: list[float] = []  # when each running computation's budget runs out
        self._executor: ThreadPoolExecutor | None = None
        self._lock = threading.Lock()
        self._running: set[threading.Event] = set()  # the cancel events of running work
        #: Set on SIGTERM once open work had its time to finish (:meth:`stop`).
        self.stopping = False

    # --- state -----------------------------------------------------------------------------
    @property
    def waiting(self) -> int:
        return len(self._waiters)

    @property
    def in_flight(self) -> int:
        """Computations running (abandoned ones included) or waiting for a slot."""
        return self.running + len(self._waiters)

    def can_admit(self) -> bool:
        """True while a new request would get a slot or a place in the queue."""
        return self.running < self.slots or len(self._waiters) < self.queue

    def state(self) -> dict[str, Any]:
        return {
            "slots": self.slots,
            "running": self.running,
            "waiting": len(self._waiters),
            "queue": self.queue,
        }

    def retry_after(self) -> int:
        """Seconds until the soonest running computation must end (at least 1)."""
        if not self._ends:
            return 1
        return max(1, math.ceil(min(self._ends) - time.perf_counter()))

    # --- slots -----------------------------------------------------------------------------
    def _eligible(self, client: str) -> bool:
        return self.running < self.slots and self._by_client.get(client, 0) < self.per_client

    def _take(self, client: str) -> None:
        self.running += 1
        self._by_client[client] = self._by_client.get(client, 0) + 1

    def _release(self, client: str, end: float, cancel: threading.Event) -> None:
        self._running.discard(cancel)
        self.running -= 1
        left = self._by_client[client] - 1
        if left:
            self._by_client[client] = left
        else:
            del self._by_client[client]
        self._ends.remove(end)
        self._grant()

    def _grant(self) -> None:
        while self.running < self.slots and self._waiters:
            eligible = [w for w in self._waiters if self._eligible(w.client)]
            if not eligible:
                return
            best = min(eligible, key=lambda w: (self._by_client.get(w.client, 0), w.seq))
            self._waiters.remove(best)
            self._take(best.client)
            best.granted.set_result(None)

    def _busy(self, what: str, why: str) -> Busy:
        return Busy(
            f"the server is busy: {why} in the {self.name} lane; {what} was not started, "
            "retry in a moment",
            retry_after=self.retry_after(),
        )

    def _stopped(self, what: str) -> Busy:
        return Busy(
            f"the server is stopping: {what} was not finished; retry, another server "
            "process or the restarted one answers it",
            retry_after=1,
        )

    async def _acquire(self, ticket: Ticket, what: str) -> None:
        if self.stopping:
            raise self._stopped(what)
        if not self._waiters and self._eligible(ticket.client):
            self._take(ticket.client)
            return
        if len(self._waiters) >= self.queue:
            raise self._busy(what, f"{self.running} computations run and {self.queue} wait")
        waiter = _Waiter(ticket.client, next(self._seq), asyncio.get_running_loop().create_future())
        self._waiters.append(waiter)
        self._grant()  # a free slot that waiters ahead cannot use (at their share) is ours
        gone: asyncio.Future[Any] = asyncio.ensure_future(ticket.gone.wait())
        both: set[asyncio.Future[Any]] = {waiter.granted, gone}
        try:
            await asyncio.wait(both, timeout=self.wait_s, return_when="FIRST_COMPLETED")
        except BaseException:
            self._abandon(waiter)
            raise
        finally:
            gone.cancel()
        if not waiter.granted.done():
            self._abandon(waiter)
            if ticket.cancel.is_set():
                raise Cancelled(f"{what} was withdrawn: the client disconnected")
            raise self._busy(what, f"no slot came free within {self.wait_s:g} s (ADMISSION_WAIT_S)")
        if ticket.cancel.is_set():
            self._release_now(ticket.client)
            raise Cancelled(f"{what} was withdrawn: the client disconnected")

    def _abandon(self, waiter: _Waiter) -> None:
        if waiter in self._waiters:
            self._waiters.remove(waiter)
        elif waiter.granted.done() and not waiter.granted.cancelled():
            self._release_now(waiter.client)  # granted in the same turn: hand it on
        waiter.granted.cancel()

    def _release_now(self, client: str) -> None:
        self.running -= 1
        left = self._by_client[client] - 1
        if left:
            self._by_client[client] = left
        else:
            del self._by_client[client]
        self._grant()

    # --- running ---------------------------------------------------------------------------
    async def run(
        self,
        fn: Callable[[float, threading.Event], T],
        budget_s: float,
        what: str,
        ticket: Ticket,
    ) -> T:
        """``fn(budget_s, cancel)`` in a thread of this lane, once a slot is had."""
        await self._acquire(ticket, what)
        if self.stopping:  # a waiter granted a slot after the stop: it does not start
            self._release_now(ticket.client)
            raise self._stopped(what)
        end = time.perf_counter() + budget_s
        self._ends.append(end)
        self._running.add(ticket.cancel)
        loop = asyncio.get_running_loop()
        try:
            with self._lock:
                if self._executor is None:
                    self._executor = ThreadPoolExecutor(
                        self.slots, thread_name_prefix=f"engine-{self.name}"
                    )
                future = self._executor.submit(fn, budget_s, ticket.cancel)
        except BaseException:
            self._release(ticket.client, end, ticket.cancel)
            raise

        # The thread's end comes back to the loop once (one call_soon_threadsafe, one wake-up)
        # and does both things there: frees the slot and hands the outcome to ``waiter``;
        # the ceiling is one timer. This was ``wait_for(wrap_future(future), ceiling)``,
        # which made two more futures and chained them with a second call from the thread:
        # a hand-off of a computation doing nothing took ~49 µs of processor time (32 on
        # the loop's thread), ~40 this way (measured, 9 rounds of 300).
        waiter: asyncio.Future[T] = loop.create_future()

        def finish() -> None:
            self._release(ticket.client, end, ticket.cancel)
            if waiter.done():  # timed out, or the request was cancelled
                return
            if future.cancelled():
                waiter.cancel()
                return
            exc = future.exception()
            if exc is None:
                waiter.set_result(future.result())
            else:
                waiter.set_exception(exc)

        def done(_: Future[Any]) -> None:
            if not loop.is_closed():  # a test's loop may end before an abandoned thread
                loop.call_soon_threadsafe(finish)

        def expire() -> None:
            if not waiter.done():
                waiter.set_exception(TimeoutError())

        future.add_done_callback(done)
        timer = loop.call_later(budget_s + self.grace_s, expire)
        try:
            return await waiter
        except Cancelled:
            if self.stopping and not ticket.gone.is_set():
                raise self._stopped(what) from None  # an answer the client can act on
            raise
        except TimeoutError:
            future.cancel()  # as wait_for did (a computation that has started goes on)
            log.warning(
                "%s ignored its %g s deadline; left running in the background", what, budget_s
            )
            raise BudgetExceeded(
                f"{what} did not finish within its {budget_s:g} s wall-clock budget (BUDGET_S)",
                budget_s=budget_s,
            ) from None
        except asyncio.CancelledError:
            future.cancel()  # as wait_for did: work not started yet never starts
            raise
        finally:
            timer.cancel()

    def stop(self) -> None:
        """The server is stopping (SIGTERM): running work stops at its next budget check and
        answers 503 with Retry-After, and nothing more is admitted, so every open request
        gets an answer before uvicorn's graceful-shutdown timeout closes its connection."""
        self.stopping = True
        for cancel in list(self._running):
            cancel.set()

    def shutdown(self) -> None:
        """Cancel running work (it stops at its next budget check), drop queued work.

        The process can then exit within its stop timeout instead of waiting up to
        BUDGET_S for each running computation; a later call starts a fresh pool.
        """
        for cancel in list(self._running):
            cancel.set()
        with self._lock:
            executor, self._executor = self._executor, None
        if executor is not None:
            executor.shutdown(wait=False, cancel_futures=True)


class FallBack(Exception):
    """An inline computation ran past its time box: run it again in a lane."""


#: A computation's cost as :class:`Inline` measures it: the processor time of its thread.
_cpu = time.thread_time


class Inline:
    """Cheap computations on the event loop, time-boxed, with a per-key running mean.

    ``key`` names what is measured (the service uses model, rung and whether
    series were asked for). The mean is exponentially weighted (the newest
    call counts ``alpha``), so a key moves off the loop after a few slow calls
    or one very slow one (over ``10 × budget_s``), and back once the lane
    measures it cheap again.

    A call that took longer than ``budget_s`` by the wall clock counts the processor
    time of the thread that ran it (:func:`time.thread_time`): what the computation
    itself needed. On a busy machine the wall clock also counts the time the process
    waited for a processor, and one such wait (20 ms: ``10 × budget_s``) sent a
    0.6 ms computation to the lane for many calls (98 of 500 requests of
    clutch.spring_design, 67 of joint.audit, measured with two other processes
    taking the two cores), each paying a thread hand-off. A call within ``budget_s``
    counts its wall-clock time (no more than its processor time can change about
    it, and the clock costs 0.06 µs where the thread's costs 0.5 µs). A call
    stopped by its budget (wall clock, :class:`BudgetExceeded`) still counts as
    very slow.
    """

    def __init__(self, budget_s: float, alpha: float = 0.25) -> None:
        self.budget_s = budget_s
        self.alpha = alpha
        self._mean: dict[Any, float] = {}
        self.ran = 0  # inline computations (for tests and /readyz)
        self.fell_back = 0

    def allows(self, key: Any) -> bool:
        return self.budget_s > 0 and self._mean.get(key, 0.0) <= self.budget_s

    def record(self, key: Any, seconds: float) -> None:
        """One measured computation of ``key`` (inline or in a lane; any thread)."""
        if seconds > 10 * self.budget_s:
            mean = seconds
        else:
            mean = (1 - self.alpha) * self._mean.get(key, 0.0) + self.alpha * seconds
        self._mean[key] = mean

    def mean(self, key: Any) -> float:
        return self._mean.get(key, 0.0)

    def run(
        self, fn: Callable[[float, threading.Event | None], T], key: Any, full_budget_s: float
    ) -> T:
        """``fn(budget, None)`` here and now, with the time box as its budget: it runs on the
        loop, to its end or its budget, so nothing could cancel it (no event to make).

        Raises :class:`FallBack` when ``fn`` stops with BudgetExceeded after using
        the time box (it checks its budget and needs longer): the caller runs it
        again in a lane with the full budget.
        """
        box = min(self.budget_s, full_budget_s)
        start = time.perf_counter()
        cpu = _cpu()
        try:
            result = fn(box, None)
        except BudgetExceeded:
            seconds = time.perf_counter() - start  # the budget's own clock
            self.record(key, max(_cpu() - cpu, 10 * self.budget_s + 1e-9))
            if seconds >= 0.9 * box and box < full_budget_s:
                self.fell_back += 1
                raise FallBack from None
            raise
        except BaseException:
            self.record(key, self._spent(start, cpu))
            raise
        self.record(key, self._spent(start, cpu))  # a wait for the processor not counted
        self.ran += 1
        return result

    def _spent(self, start: float, cpu: float) -> float:
        """A call's measure from its start on the two clocks: the wall clock's time
        within the time box, else the processor time of the thread."""
        seconds = time.perf_counter() - start
        return seconds if seconds <= self.budget_s else _cpu() - cpu

    def timed(
        self, fn: Callable[[float, threading.Event | None], T], key: Any
    ) -> Callable[[float, threading.Event], T]:
        """``fn`` measuring itself into ``key``'s mean (for the lane path)."""

        def call(budget_s: float, cancel: threading.Event) -> T:
            start, cpu = time.perf_counter(), _cpu()  # cpu: the lane's thread's
            try:
                return fn(budget_s, cancel)
            finally:
                self.record(key, self._spent(start, cpu))

        return call


class EnginePool:
    """The two lanes, the inline gate, and whether the engine can admit work (``/readyz``)."""

    def __init__(
        self,
        threads: int = 4,
        queue: int = 64,
        grace_s: float = 1.0,
        *,
        heavy_slots: int = 2,
        heavy_queue: int = 16,
        heavy_per_client: int = 1,
        wait_s: float = 0.5,
        inline_budget_s: float = 0.0,
    ) -> None:
        self.inline = Inline(inline_budget_s)
        self.quick = Lane(
            "quick", slots=threads, queue=queue, per_client=threads, wait_s=wait_s, grace_s=grace_s
        )
        self.heavy = Lane(
            "heavy",
            slots=heavy_slots,
            queue=heavy_queue,
            per_client=heavy_per_client,
            wait_s=wait_s,
            grace_s=grace_s,
        )

    @property
    def in_flight(self) -> int:
        """Computations admitted and not finished, in both lanes (waiting ones included)."""
        return self.quick.in_flight + self.heavy.in_flight

    def ready(self) -> bool:
        return self.quick.can_admit() and self.heavy.can_admit()

    def state(self) -> dict[str, Any]:
        return {"quick": self.quick.state(), "heavy": self.heavy.state()}

    def stop(self) -> None:
        """SIGTERM, once open work had its time: every lane stops (:meth:`Lane.stop`)."""
        self.quick.stop()
        self.heavy.stop()

    def shutdown(self) -> None:
        self.quick.shutdown()
        self.heavy.shutdown()
