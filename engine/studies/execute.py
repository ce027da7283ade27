"""Run a :class:`~engine.studies.plan.Study`: chunks in-process or on a Dask cluster.

The points are drawn once (:func:`engine.studies.plan.plan`) and cut into chunks of a
size fixed by the model alone (array-path chunks of 65,536 points, one-by-one
chunks of 256), so the same study gives the same chunks, the same values and
the same summary, bit for bit, whichever executor ran them:

* :class:`InProcess` evaluates the chunks one after another in the calling
  thread (small studies, tests, a Python user);
* :class:`DaskExecutor` sends them to ``dask.distributed`` workers: a local
  cluster sized to the machine (processes, one thread each), started on first
  use, or an existing scheduler at ``address`` (``DASK_SCHEDULER``), whose
  workers must have this package installed;
* :class:`HereIfCheap` runs an array-path study's chunks in the calling thread while they
  show the whole cheap (a cluster's transfers would cost more than the evaluation), and
  the rest on Dask once they do not.

The local cluster is private: its scheduler and workers speak mutual TLS with a key and
a self-signed certificate made in memory when it starts (Dask's
``Security.temporary()``), so a process without them, on this machine or another, cannot
connect, submit work or run code in the service's workers; the client itself reaches that
scheduler, which runs in its own process, in process (``inproc://``, no socket), and
fetches results from the workers over TLS. An existing scheduler is
reached with the certificate files it is given (:class:`TLSFiles`), over TLS.

Progress is reported after every chunk; a cancel event stops the study
between chunks. On Dask a study has a few chunks in flight at once (``IN_FLIGHT_PER_THREAD``
per worker thread) and submits the next as one finishes, and its first chunk has a
higher priority than the spare ones of a study already running, so studies side by side
take turns: a small study submitted behind a large one starts as soon as a worker frees,
where it waited for the whole large study. The window is a client's, not a study's: the
studies of one ``owner`` share it, so a client running two studies has the workers'
share of a client running one, not twice it. A chunk's time budget follows the cost
of the chunks measured before it (:class:`ChunkBudget`), not a fixed 60 s. Pending chunks
are cancelled at once, and a running chunk
stops at its next point (or inside a point's simulation) once it reads the study's
``distributed.Event``, which it asks at most every ``CANCEL_POLL_S``: the workers are
idle within that and one point's time, where they ran a 256-point chunk to its end.
"""

from __future__ import annotations

import contextlib
import copy
import os
import threading
import time
import uuid
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from ..core.errors import BudgetExceeded, Cancelled
from ..core.spec import ModelSpec
from .plan import (
    ChunkResult,
    Merger,
    Plan,
    Study,
    chunks,
    evaluate_chunk,
    one_numbers,
    plan,
    summarize,
    summarize_chunk,
)

VECTOR_CHUNK = 65_536
LOOP_CHUNK = 256
#: How often a chunk on a Dask worker asks whether its study was cancelled [s].
CANCEL_POLL_S = 0.1
#: How long a study waits for the scheduler to answer it [s] (its stop event set, its
#: workers' threads counted): a scheduler that does not answer (stopped, its host lost) must
#: not hold up a cancel nor a study's start for ever.
SCHEDULER_WAIT_S = 10.0
#: Chunks of one study on Dask at once, per worker thread: enough to keep every worker
#: busy, few enough that another study's chunks wait at most about two chunks' time.
IN_FLIGHT_PER_THREAD = 2
#: The least time budget of a chunk [s], and how many times the slowest measured cost per
#: point a chunk may take (:class:`ChunkBudget`).
CHUNK_FLOOR_S = 60.0
CHUNK_MARGIN = 10.0
#: Messages Dask's connections keep for debugging (``distributed.admin.low-level-log-length``,
#: 1,000 by default): the client's log of sent messages held each chunk's arguments, and
#: through them the study's columns, for the last 1,000 sends (~10 MB more RSS for each
#: 10⁶-point study, 344 → 498 MB over 16).
DASK_LOG_LENGTH = 16
#: Blocks a local worker's ``malloc`` takes from its heap, not from fresh mappings, up to
#: this size [bytes] (``MALLOC_MMAP_THRESHOLD_``): eight of a chunk's arrays (65,536
#: values, 512 KiB). Dask starts its workers with ``MALLOC_TRIM_THRESHOLD_=65536`` (to give
#: freed memory back), which also fixes glibc's mmap threshold at 128 KiB: every array of
#: a chunk was a fresh mapping, or a heap top given back and taken again, whose pages the
#: kernel faulted in and zeroed each time, and a 10⁶-point preload study's evaluation took
#: 0.75 s of CPU where it takes 0.22 s in the calling process (measured).
WORKER_MMAP_THRESHOLD = 8 * VECTOR_CHUNK * 8
#: The free top of a local worker's heap it keeps, not gives back [bytes]
#: (``MALLOC_TRIM_THRESHOLD_``): 128 of a chunk's arrays. At twice the mmap threshold
#: (glibc's own rule) a chunk's outputs and temporaries, freed, were given back after each
#: chunk and taken again, every page faulted in and zeroed, by the next: a 65,536-point
#: preload chunk took 14 ms of CPU on a worker (8.5 ms of it in the kernel, 4,400 page
#: faults) against 6 ms (185 faults) with this much kept, measured; a worker holds up
#: to this much more when idle.
WORKER_TRIM_THRESHOLD = 128 * VECTOR_CHUNK * 8

Progress = Callable[[int, int], None]


@dataclass(frozen=True)
class TLSFiles:
    """PEM files for a TLS scheduler: the authority that signed the cluster's certificates,
    and this client's certificate and key (one file may hold both)."""

    ca_file: str
    cert_file: str
    key_file: str | None = None

    def security(self) -> Any:
        """Dask's ``Security`` for a client of that scheduler, encryption required."""
        from distributed.security import Security

        return Security(
            tls_ca_file=self.ca_file,
            tls_client_cert=self.cert_file,
            tls_client_key=self.key_file,
            require_encryption=True,
        )


@dataclass
class StudyRun:
    """A finished study: the summary, the plan and the raw values (``merged.values``: the
    study's columns, :class:`~engine.studies.plan.Columns`)."""

    summary: dict[str, Any]
    plan: Plan
    merged: ChunkResult
    elapsed_s: float


ChunkArgs = tuple[
    ModelSpec | str, dict[str, Any], dict[str, np.ndarray], tuple[str, ...], Any, Any, Any
]


#: A chunk's time budget [s] from its number of points (:class:`ChunkBudget`).
Budget = Callable[[int], float]


class Executor(Protocol):
    """Runs chunk evaluations; yields ``(index, ChunkResult)`` as they finish. With a
    ``budget``, a chunk's time budget is ``budget(points)`` asked when it starts (the
    ``deadline_s`` in its arguments otherwise)."""

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event, budget: Budget | None = None
    ) -> Iterator[tuple[int, ChunkResult]]: ...


class ChunkBudget:
    r"""A chunk's time budget from the measured cost of the study's chunks before it.

    .. math::
        t_{chunk} = \min\left(\max\left(t_{floor},\; m\, n \max_j \frac{t_j}{n_j}\right),
        \; t_{left}\right)

    with :math:`n` the chunk's points, :math:`t_j / n_j` the cost per point of each chunk
    measured so far (on its worker, queueing excluded), :math:`m` = ``margin``, and
    :math:`t_{left}` what is left of the study's budget (at least 1 s). Before any chunk
    is measured a chunk has the larger of the floor and :math:`t_{left}`. A study slowed
    down by load (a shared machine, a busy cluster) keeps going, where a fixed 60 s let a
    256-point chunk fail the whole study; a chunk stuck far past what its neighbours took
    still stops.

    >>> b = ChunkBudget(floor_s=60.0, margin=10.0)
    >>> b(256)  # nothing measured, no study budget: the floor
    60.0
    >>> b.observe(256, 30.0)  # a chunk took 30 s: the next may take 10 x 30 s
    >>> b(256)
    300.0
    >>> b.observe(128, 1.0)  # a faster one does not lower it: the slowest per point holds
    >>> b(256)
    300.0
    >>> ChunkBudget(60.0, 10.0, deadline=time.perf_counter() + 100.0)(256) <= 100.0
    True
    """

    def __init__(self, floor_s: float, margin: float, deadline: float | None = None) -> None:
        self.floor_s = floor_s
        self.margin = margin
        #: The study's deadline on :func:`time.perf_counter`'s clock (None: no budget).
        self.deadline = deadline
        #: The slowest cost per point measured so far [s].
        self.per_point_s: float | None = None

    def observe(self, points: int, elapsed_s: float) -> None:
        """A chunk of ``points`` points took ``elapsed_s`` seconds."""
        if points > 0 and elapsed_s >= 0.0:
            cost = elapsed_s / points
            self.per_point_s = max(cost, self.per_point_s or 0.0)

    def __call__(self, points: int) -> float:
        left = None if self.deadline is None else max(self.deadline - time.perf_counter(), 1.0)
        if self.per_point_s is None:
            return self.floor_s if left is None else max(self.floor_s, left)
        scaled = max(self.floor_s, self.margin * points * self.per_point_s)
        return scaled if left is None else min(scaled, left)


class InProcess:
    """Evaluate chunks one after another in the calling thread."""

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event, budget: Budget | None = None
    ) -> Iterator[tuple[int, ChunkResult]]:
        for i, args in enumerate(calls):
            if cancel.is_set():
                return
            deadline = args[6] if budget is None else budget(len(next(iter(args[2].values()))))
            yield i, summarize_chunk(evaluate_chunk(*args[:6], deadline, cancel=cancel))


class HereIfCheap:
    r"""An array-path study's chunks here while they show the whole study cheap, the rest
    on ``remote()`` (Dask).

    With :math:`t_j` the wall time of the :math:`j`-th chunk run in the calling thread
    (evaluated, summarised, and taken in by the study), :math:`m` the chunks run here so
    far and :math:`k` the study's chunks, the next chunk runs here while

    .. math:: \frac{k}{m} \sum_{j \le m} t_j \le t_{here}

    (``here_s``), and all that are left go to ``remote()`` once it is not. A cheap study
    then needs no cluster: its values are not sent to a worker and back, which cost a
    10⁶-point preload study more of the service's CPU than its evaluation (7.5 MB of
    values a chunk over TLS). The time here stays below :math:`t_{here}` and one chunk,
    even where the first chunks are cheaper than the others (designs given in an order).
    Only a study whose every point is on the array path (:func:`array_only`: a named
    array rung, or ``auto`` on a model without a looped rung) runs here at all: an
    ``auto`` study's chunk may simulate some of its points one by one (up to a chunk's
    budget), and it goes to ``remote()`` from the first. The chunks are the same whichever
    runs them, so the values are too (bit for bit).
    """

    def __init__(
        self,
        remote: Callable[[], Executor],
        here_s: float,
        clock: Callable[[], float] = time.perf_counter,
    ) -> None:
        self.remote = remote
        self.here_s = here_s
        self.clock = clock
        #: The study's chunks that ran in the calling thread.
        self.here = 0

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event, budget: Budget | None = None
    ) -> Iterator[tuple[int, ChunkResult]]:
        k = len(calls)
        spent = 0.0
        if self.here_s > 0 and calls and array_only(*_asked(calls[0])):
            here = InProcess()
            while self.here < k:
                i = self.here
                t0 = self.clock()
                for _, part in here.map(calls[i : i + 1], cancel, budget):
                    yield i, part
                spent += self.clock() - t0
                if cancel.is_set():
                    return
                self.here += 1
                if spent / self.here * k > self.here_s:
                    break
        if self.here == k:
            return
        m = self.here
        for i, part in self.remote().map(calls[m:], cancel, budget):
            yield i + m, part


def _asked(args: ChunkArgs) -> tuple[ModelSpec | str, str | None, float | None]:
    """A chunk's model, fidelity and tolerance."""
    return args[0], args[4], args[5]


def _rung(spec: ModelSpec, fidelity: str | None, tolerance: float | None) -> str:
    """The rung a study asks for: the one named, ``auto`` with a tolerance, or the model's
    default."""
    return fidelity or ("auto" if tolerance is not None else spec.default_fidelity)


def array_only(spec: ModelSpec | str, fidelity: str | None, tolerance: float | None) -> bool:
    """Whether every point of a study of ``spec`` asked at ``fidelity`` (or ``auto`` at
    ``tolerance``) is computed on the array path: its rung is an array rung, or ``auto``
    on a model all of whose rungs are (a model named by its name: not known here, False).
    """
    if isinstance(spec, str) or spec.vectorized is None:
        return False
    rung = _rung(spec, fidelity, tolerance)
    if rung != "auto":
        return rung in spec.vector_rungs
    return set(spec.rung_names) <= set(spec.vector_rungs)


class RemoteCancel(threading.Event):
    """A study's cancel as a chunk on a Dask worker sees it: the ``distributed.Event``
    named for the study, asked at most every ``CANCEL_POLL_S`` (the chunk asks at each
    point and inside each simulation; a scheduler round trip each time would cost more
    than the point)."""

    def __init__(self, name: str) -> None:
        super().__init__()
        self.name = name
        self._next = 0.0
        self._event: Any = None

    def is_set(self) -> bool:
        if super().is_set():
            return True
        now = time.monotonic()
        if now >= self._next:
            self._next = now + CANCEL_POLL_S
            try:
                if self._event is None:
                    from distributed import Event

                    self._event = Event(self.name)
                if self._event.is_set():
                    self.set()
            except Exception:  # outside a worker, or the scheduler gone: the chunk goes on
                self._next = now + 10 * CANCEL_POLL_S
        return super().is_set()


def evaluate_remote(
    cancel_name: str,
    spec: str,
    base: dict[str, Any],
    columns: dict[str, np.ndarray],
    outputs: tuple[str, ...],
    fidelity: str | None,
    tolerance: float | None,
    deadline_s: float | None,
) -> ChunkResult:
    """:func:`evaluate_chunk` on a Dask worker, stopped when the study's event is set, with
    its partial summary (:func:`summarize_chunk`) made there too, and its outputs of one
    number sent as that number (:func:`one_numbers`)."""
    cancel = RemoteCancel(cancel_name)
    return one_numbers(
        summarize_chunk(
            evaluate_chunk(spec, base, columns, outputs, fidelity, tolerance, deadline_s, cancel)
        )
    )


class DaskExecutor:
    """Evaluate chunks on ``dask.distributed`` workers (local cluster or ``address``)."""

    def __init__(
        self,
        address: str | None = None,
        n_workers: int | None = None,
        memory_limit: int | None = None,
        tls: TLSFiles | None = None,
    ) -> None:
        self.address = address
        #: Certificates for the scheduler at ``address``; None: Dask's own configuration
        #: (``distributed.comm.tls``), plain TCP when it names none.
        self.tls = tls
        self.n_workers = n_workers or os.cpu_count() or 1
        #: Bytes each local worker may hold (Dask pauses, then restarts one beyond it);
        #: None: Dask's default, the machine's memory split between the workers.
        self.memory_limit = memory_limit
        self._client: Any = None
        self._cluster: Any = None
        self._lock = threading.Lock()
        #: Studies on the workers now, per owner (a client): they share its window.
        self._owners: dict[str, int] = {}

    def client(self) -> Any:
        with self._lock:
            if self._client is None:
                import dask
                from dask.distributed import Client, LocalCluster
                from distributed.security import Security

                # read as the client, scheduler and workers are made: short debug logs
                log_length = dask.config.set(
                    {
                        "distributed.admin.low-level-log-length": DASK_LOG_LENGTH,
                        # read by the local nannies, set before each worker starts
                        "distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": str(
                            WORKER_MMAP_THRESHOLD
                        ),
                        "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": str(
                            WORKER_TRIM_THRESHOLD
                        ),
                    }
                )

                if self.address:
                    self._client = Client(
                        self.address,
                        set_as_default=False,
                        timeout="10s",
                        security=self.tls.security() if self.tls else None,
                    )
                else:
                    self._cluster = LocalCluster(
                        # mutual TLS with credentials made for this cluster alone (the
                        # protocol follows: tls://); a client must present them
                        security=Security.temporary(),
                        n_workers=self.n_workers,
                        threads_per_worker=1,
                        processes=True,
                        memory_limit=self.memory_limit or "auto",
                        host="127.0.0.1",
                        # an HTTP port of its own on loopback (None would still take 8787)
                        dashboard_address="127.0.0.1:0",
                        silence_logs=40,
                    )
                    # results fetched from the worker that holds them, not relayed by the
                    # scheduler (Dask's default for a client outside the cluster): the
                    # scheduler runs in this process, so a relayed chunk was decrypted,
                    # encrypted again and decrypted once more here; the workers are on
                    # loopback, so the client reaches them as the scheduler does
                    # and the client speaks to the scheduler, which runs in this process,
                    # in process (inproc://: Python objects handed over, no socket): over
                    # TLS each chunk's inputs were pickled and encrypted here, decrypted,
                    # unpickled, pickled and encrypted again for the worker, all in this
                    # process; the address is reachable from this process alone, and the
                    # workers still reach the scheduler, and the client the workers, over
                    # mutual TLS
                    scheduler = self._cluster.scheduler
                    self._cluster.sync(scheduler.listen, "inproc://")
                    self._client = Client(
                        scheduler.listeners[-1].contact_address,
                        security=self._cluster.security,
                        loop=self._cluster.loop,  # one event loop, as Client(cluster) had
                        set_as_default=False,
                        direct_to_workers=True,
                    )
                    # the local workers share this machine with the service: lower their
                    # priority so single calculations get the cores first
                    self._client.run(os.nice, 10)
                log_length.__exit__(None, None, None)
            return self._client

    def workers(self) -> int:
        """The workers the cluster has now, asked without waiting on a lost scheduler: a
        local cluster's own copy of the scheduler's list, a remote scheduler within 2 s
        (0 when it does not answer); 0 before the cluster is started. For a watchdog: a
        study's chunks wait for ever on a cluster whose workers died or never started."""
        with self._lock:
            client, cluster = self._client, self._cluster
        if client is None:
            return 0
        try:
            if cluster is not None:
                return len(cluster.scheduler_info.get("workers", {}))
            return len(client.sync(client.scheduler.ncores, callback_timeout=2.0))
        except Exception:  # the scheduler gone, or not answering: no workers to count on
            return 0

    def map(
        self,
        calls: list[ChunkArgs],
        cancel: threading.Event,
        budget: Budget | None = None,
        owner: str | None = None,
    ) -> Iterator[tuple[int, ChunkResult]]:
        """The chunks' results as they finish; ``owner`` (a client) shares one window of
        chunks in flight between its studies (None: the study is a client of its own)."""
        client = self.client()
        name = f"study-cancel-{uuid.uuid4().hex}"
        key = owner if owner is not None else name
        with self._lock:
            self._owners[key] = self._owners.get(key, 0) + 1
        try:
            yield from self._map(client, name, key, calls, cancel, budget)
        finally:
            with self._lock:
                self._owners[key] -= 1
                if not self._owners[key]:
                    del self._owners[key]

    def _map(
        self,
        client: Any,
        name: str,
        owner: str,
        calls: list[ChunkArgs],
        cancel: threading.Event,
        budget: Budget | None,
    ) -> Iterator[tuple[int, ChunkResult]]:
        from dask.distributed import as_completed

        # a window of chunks in flight, the next submitted as one finishes: what another
        # study submits meanwhile queues before this one's next chunks (Dask runs equal
        # priorities in the order submitted), so studies take turns, each in proportion to
        # its chunks in flight; the window is the owner's, split between its studies, so
        # clients take turns, not studies; a study's first chunk goes before the spare
        # ones of a study that is running
        try:
            threads = client.sync(client.scheduler.ncores, callback_timeout=SCHEDULER_WAIT_S)
        except TimeoutError:
            raise TimeoutError(
                f"the Dask scheduler did not answer within {SCHEDULER_WAIT_S:g} s"
            ) from None
        window = max(2, IN_FLIGHT_PER_THREAD * sum(threads.values()))

        def share() -> int:
            with self._lock:
                return max(1, window // self._owners.get(owner, 1))

        index: dict[str, int] = {}
        flying: set[Any] = set()
        lock = threading.Lock()

        def submit(i: int) -> Any:
            args = calls[i]
            deadline = args[6] if budget is None else budget(len(next(iter(args[2].values()))))
            # workers look the model up by name in their own registry (a spec's functions
            # need not pickle)
            # a study's first chunk before any study's others: a study just submitted
            # starts as soon as a worker frees, not behind queued chunks; the others all
            # alike, whatever a study's window (a priority from the chunks in flight let
            # the study with the smaller window go first, always)
            priority = 0 if i == 0 else -1
            fut = client.submit(
                evaluate_remote,
                name,
                _name(args[0]),
                *args[1:6],
                deadline,
                pure=False,
                priority=priority,
            )
            index[fut.key] = i
            with lock:
                flying.add(fut)
            return fut

        def in_flight() -> list[Any]:
            with lock:
                return [f for f in flying if not f.done()]

        finished = threading.Event()

        def halt(futures: list[Any]) -> None:
            # the client lets go of the futures at once (no answer awaited), then tells the
            # running chunks through the event, waiting for the scheduler a bounded time: a
            # chunk the event does not reach stops at its deadline; a client closed meanwhile
            # (the watchdog closed a cluster without workers) has nothing left to let go of,
            # and a scheduler that does not answer, or is gone, nothing to tell
            with contextlib.suppress(Exception):
                client.cancel(futures)
                client.sync(
                    client.scheduler.event_set, name=name, callback_timeout=SCHEDULER_WAIT_S
                )

        def watch() -> None:
            # the moment the study is cancelled, not when the next chunk happens to finish:
            # the running chunks read the event, the pending ones are cancelled
            while not finished.wait(0.02):
                if cancel.is_set():
                    halt(in_flight())
                    return

        first = [submit(i) for i in range(min(share(), len(calls)))]
        following = len(first)
        threading.Thread(target=watch, name="study-cancel", daemon=True).start()
        done = as_completed(first, loop=client.loop, with_results=False)
        try:
            for fut in done:
                if cancel.is_set():
                    break
                try:
                    result = _fetch(client, fut, cancel)
                except Cancelled:
                    break
                except BaseException as exc:
                    raise _detached(exc) from None
                with lock:
                    flying.discard(fut)
                yield index[fut.key], result
                # after the caller took the result: its cost is in the next chunk's budget;
                # as many as the owner's share allows now (it grows when another of its
                # studies ends), and one at least
                while following < len(calls) and not cancel.is_set():
                    # submitted and not yet taken: a finished chunk whose result waits to
                    # be collected still holds its place (and its result on a worker)
                    with lock:
                        flying_now = len(flying)
                    if flying_now and flying_now >= share():
                        break
                    done.add(submit(following))
                    following += 1
        finally:
            finished.set()
            pending = in_flight()
            if pending:
                halt(pending)  # a budget or an error ended the study: its chunks stop too

    def close(self) -> None:
        with self._lock:
            if self._client is not None:
                self._client.close()
            if self._cluster is not None:
                self._cluster.close()
            self._client = self._cluster = None


def _fetch(client: Any, fut: Any, cancel: threading.Event) -> ChunkResult:
    """A finished chunk's result, or Cancelled once ``cancel`` is set while it is fetched.

    The values come from the worker through the scheduler, which may stop answering (a
    stopped process, a lost host) while they do: ``Future.result`` then waited for ever,
    and a study cancelled meanwhile never ended (a test stopping the scheduler with
    SIGSTOP caught it 3 times in 4). The fetch runs on the client's loop and is looked at
    every ``CANCEL_POLL_S``; a cancel stops it.
    """
    import asyncio

    pending = asyncio.run_coroutine_threadsafe(
        client.gather(fut, asynchronous=True), client.loop.asyncio_loop
    )
    while True:
        try:
            result: ChunkResult = pending.result(timeout=CANCEL_POLL_S)
            return result
        except TimeoutError:
            if cancel.is_set():
                pending.cancel()
                raise Cancelled("the study was cancelled while a chunk's values came") from None


def _detached(exc: BaseException) -> BaseException:
    """A chunk's error (a worker's exception, a cancel) as a new exception of the same
    type, message and fields, and Dask's own let go of this study.

    Dask keeps the exception a failed future raises for as long as its client knows the
    key, and raising it adds the raiser's frames to its traceback: the study's frames then
    held its inputs, its merged values and the futures (which keep the key known) for the
    client's life, some 100 MB a failed 10⁶-point study. The stored one gets its traceback
    back from Dask each time it is raised.

    >>> stored = ValueError("boom")
    >>> try:
    ...     raise stored
    ... except ValueError as e:
    ...     got = _detached(e)
    >>> got is not stored, str(got), stored.__traceback__ is None
    (True, 'boom', True)
    """
    exc.__traceback__ = None
    try:
        copied = copy.copy(exc)
    except Exception:  # an exception that cannot be remade from its args: raised as it is
        return exc
    return copied if type(copied) is type(exc) and str(copied) == str(exc) else exc


def _name(spec: ModelSpec | str) -> str:
    return spec if isinstance(spec, str) else spec.name


def chunk_size(spec: ModelSpec, study: Study, planned: Plan | None = None) -> int:
    """Points per chunk: fixed by the model, the fidelity and, for ``auto`` on a model with
    a rung off the array path, the rungs its first points take (``planned``: the study's
    points); never by timing (bit-identical runs).

    An ``auto`` study whose points the array path does not compute (a tolerance only the
    simulation meets) goes one point after another; in chunks of 65,536 it was one chunk
    up to that size, which one worker ran while the others waited. If any of its first
    ``PROBE_POINTS`` points takes such a rung (:func:`engine.core.runner.prepare`, the
    rung a single run would choose), its chunks are the looped ones.
    """
    if array_only(spec, study.fidelity, study.tolerance):
        return VECTOR_CHUNK
    if spec.vectorized is None or _rung(spec, study.fidelity, study.tolerance) != "auto":
        return LOOP_CHUNK
    if planned is None:
        return VECTOR_CHUNK
    looped = set(spec.rung_names) - set(spec.vector_rungs)
    return LOOP_CHUNK if _loops(spec, study, planned, looped) else VECTOR_CHUNK


#: Points of an ``auto`` study whose rungs :func:`chunk_size` asks before cutting it.
PROBE_POINTS = 64


def _loops(spec: ModelSpec, study: Study, planned: Plan, looped: set[str]) -> bool:
    """Whether one of the study's first points takes a rung in ``looped`` at ``auto``."""
    from ..core.errors import EngineError
    from ..core.runner import prepare

    base = {k: v for k, v in study.base.items() if v is not None}
    for j in range(min(PROBE_POINTS, planned.n_points)):
        point = {
            k: (int(v[j]) if spec.param(k).kind == "int" else float(v[j]))
            for k, v in planned.columns.items()
        }
        try:
            if prepare(spec, {**base, **point}, "auto", study.tolerance).rung in looped:
                return True
        except EngineError:  # a refused point: the chunk refuses it too, whatever its size
            continue
    return False


def run_study(
    spec: ModelSpec,
    study: Study,
    executor: Executor | None = None,
    *,
    progress: Progress | None = None,
    cancel: threading.Event | None = None,
    budget_s: float | None = None,
    chunk_budget_s: float | None = CHUNK_FLOOR_S,
    planned: Plan | None = None,
) -> StudyRun:
    """Plan, evaluate and summarise ``study``; raise Cancelled or BudgetExceeded when stopped.

    ``planned`` is :func:`engine.studies.plan.plan` of the same study, where the caller has
    already drawn its points (the service does, to refuse a bad study at once): they are
    not drawn again. ``chunk_budget_s`` is a chunk's least time budget; it grows with the
    cost of the chunks measured before it (:class:`ChunkBudget`); None: no chunk budget.
    """
    start = time.perf_counter()
    p = plan(spec, study) if planned is None else planned
    cancel = cancel or threading.Event()
    slices = chunks(p.n_points, chunk_size(spec, study, p))
    base = {k: v for k, v in study.base.items() if v is not None}
    calls: list[ChunkArgs] = [
        (
            spec,
            base,
            {k: v[a:b] for k, v in p.columns.items()},
            p.outputs,
            study.fidelity,
            study.tolerance,
            chunk_budget_s,
        )
        for a, b in slices
    ]
    # each chunk goes to its place as it arrives (the study holds its values once)
    merger = Merger(p.n_points, p.outputs)
    done = 0
    if progress:
        progress(0, p.n_points)
    budget = None
    if chunk_budget_s is not None:
        deadline = None if budget_s is None else start + budget_s
        budget = ChunkBudget(chunk_budget_s, CHUNK_MARGIN, deadline)
    for i, part in (executor or InProcess()).map(calls, cancel, budget):
        a, b = slices[i]
        if budget is not None:
            budget.observe(b - a, part.elapsed_s)
        merger.add(a, part)
        done += b - a
        if progress:
            progress(done, p.n_points)
        if budget_s is not None and time.perf_counter() - start > budget_s:
            cancel.set()
            raise BudgetExceeded(
                f"the study stopped after {done} of {p.n_points} points at its {budget_s:g} s "
                "budget",
                field="samples",
            )
    if cancel.is_set() or merger.received < len(calls):
        raise Cancelled(f"the study was cancelled after {done} of {p.n_points} points")
    merged = merger.result()
    summary = summarize(spec, study, p, merged)
    elapsed = time.perf_counter() - start
    summary["elapsed_s"] = elapsed
    return StudyRun(summary, p, merged, elapsed)
