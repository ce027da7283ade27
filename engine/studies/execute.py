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
  workers must have this package installed.

The local cluster is private: its scheduler and workers speak mutual TLS with a key and
a self-signed certificate made in memory when it starts (Dask's
``Security.temporary()``), so a process without them, on this machine or another, cannot
connect, submit work or run code in the service's workers. An existing scheduler is
reached with the certificate files it is given (:class:`TLSFiles`), over TLS.

Progress is reported after every chunk; a cancel event stops the study
between chunks. On Dask, pending chunks are cancelled at once, and a running chunk
stops at its next point (or inside a point's simulation) once it reads the study's
``distributed.Event``, which it asks at most every ``CANCEL_POLL_S``: the workers are
idle within that and one point's time, where they ran a 256-point chunk to its end.
"""

from __future__ import annotations

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
    plan,
    summarize,
    summarize_chunk,
)

VECTOR_CHUNK = 65_536
LOOP_CHUNK = 256
#: How often a chunk on a Dask worker asks whether its study was cancelled [s].
CANCEL_POLL_S = 0.1

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
    """A finished study: the summary, the plan and the merged raw values."""

    summary: dict[str, Any]
    plan: Plan
    merged: ChunkResult
    elapsed_s: float


ChunkArgs = tuple[
    ModelSpec | str, dict[str, Any], dict[str, np.ndarray], tuple[str, ...], Any, Any, Any
]


class Executor(Protocol):
    """Runs chunk evaluations; yields ``(index, ChunkResult)`` as they finish."""

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event
    ) -> Iterator[tuple[int, ChunkResult]]: ...


class InProcess:
    """Evaluate chunks one after another in the calling thread."""

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event
    ) -> Iterator[tuple[int, ChunkResult]]:
        for i, args in enumerate(calls):
            if cancel.is_set():
                return
            yield i, summarize_chunk(evaluate_chunk(*args, cancel=cancel))


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
    its partial summary (:func:`summarize_chunk`) made there too."""
    cancel = RemoteCancel(cancel_name)
    return summarize_chunk(
        evaluate_chunk(spec, base, columns, outputs, fidelity, tolerance, deadline_s, cancel)
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

    def client(self) -> Any:
        with self._lock:
            if self._client is None:
                from dask.distributed import Client, LocalCluster
                from distributed.security import Security

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
                    self._client = Client(self._cluster, set_as_default=False)
                    # the local workers share this machine with the service: lower their
                    # priority so single calculations get the cores first
                    self._client.run(os.nice, 10)
            return self._client

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event
    ) -> Iterator[tuple[int, ChunkResult]]:
        from dask.distributed import Event, as_completed

        client = self.client()
        name = f"study-cancel-{uuid.uuid4().hex}"
        stop = Event(name, client=client)
        # workers look the model up by name in their own registry (a spec's functions
        # need not pickle)
        futures = [
            client.submit(evaluate_remote, name, _name(args[0]), *args[1:], pure=False)
            for args in calls
        ]
        index = {f.key: i for i, f in enumerate(futures)}
        finished = threading.Event()

        def watch() -> None:
            # the moment the study is cancelled, not when the next chunk happens to finish:
            # the running chunks read the event, the pending ones are cancelled
            while not finished.wait(0.02):
                if cancel.is_set():
                    stop.set()
                    client.cancel([f for f in futures if not f.done()])
                    return

        threading.Thread(target=watch, name="study-cancel", daemon=True).start()
        try:
            for fut in as_completed(futures, loop=client.loop, with_results=False):
                if cancel.is_set():
                    break
                yield index[fut.key], fut.result()
        finally:
            finished.set()
            pending = [f for f in futures if not f.done()]
            if pending:
                stop.set()  # a budget or an error ended the study: its chunks stop too
                client.cancel(pending)

    def close(self) -> None:
        with self._lock:
            if self._client is not None:
                self._client.close()
            if self._cluster is not None:
                self._cluster.close()
            self._client = self._cluster = None


def _name(spec: ModelSpec | str) -> str:
    return spec if isinstance(spec, str) else spec.name


def chunk_size(spec: ModelSpec, study: Study) -> int:
    """Points per chunk: fixed by the model and fidelity, never by timing (bit-identical runs)."""
    rung = study.fidelity or ("auto" if study.tolerance is not None else spec.default_fidelity)
    vector = spec.vectorized is not None and (rung == "auto" or rung in spec.vector_rungs)
    return VECTOR_CHUNK if vector else LOOP_CHUNK


def run_study(
    spec: ModelSpec,
    study: Study,
    executor: Executor | None = None,
    *,
    progress: Progress | None = None,
    cancel: threading.Event | None = None,
    budget_s: float | None = None,
    chunk_budget_s: float | None = 60.0,
    planned: Plan | None = None,
) -> StudyRun:
    """Plan, evaluate and summarise ``study``; raise Cancelled or BudgetExceeded when stopped.

    ``planned`` is :func:`engine.studies.plan.plan` of the same study, where the caller has
    already drawn its points (the service does, to refuse a bad study at once): they are
    not drawn again.
    """
    start = time.perf_counter()
    p = plan(spec, study) if planned is None else planned
    cancel = cancel or threading.Event()
    slices = chunks(p.n_points, chunk_size(spec, study))
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
    for i, part in (executor or InProcess()).map(calls, cancel):
        a, b = slices[i]
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
