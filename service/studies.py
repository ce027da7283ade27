"""Design studies as jobs: ``POST <model path>/study`` → 202, then poll, fetch, cancel.

A client polls ``GET /jobs/{id}``, or asks it to ``wait`` (up to ``MAX_WAIT_S``) for the
job to end: the answer comes the moment the job's end is stored, no poll interval added.

A study (:mod:`engine.studies.plan`) can take minutes, so it never runs in a request:
the POST validates it, draws nothing yet, and returns ``202`` with the job's
address. A small pool of job threads drives studies; a study of at most
``STUDY_INPROCESS_POINTS`` points runs in that thread, a larger one on Dask
(:class:`engine.studies.execute.DaskExecutor`): a local cluster sized to the
machine, started when the first large study arrives, or the scheduler named
by ``DASK_SCHEDULER``. A larger study all of whose points are on the array path runs
its chunks in the thread while they show the whole taking at most ``STUDY_INPROCESS_S``
(1 s), and the rest on Dask once they do not: for a cheap study a cluster's transfers
would cost the service more than the evaluation
(:class:`engine.studies.execute.HereIfCheap`). Studies never use the engine pool that
serves single calculations, and their heavy compute (simulations, long studies) runs in
Dask's worker processes, not in the service's interpreter.

Budgets: ``STUDY_MAX_POINTS`` points and ``STUDY_BUDGET_S`` seconds per study;
at most ``STUDY_PER_CLIENT`` unfinished studies per client (its address, or its API key,
whose own quotas then hold) and
``STUDY_MAX_ACTIVE`` in all, and the disk the kept points may take (503 with
Retry-After beyond that), checked before a single point is drawn. Jobs live in the
:class:`~service.jobstore.JobStore` (``STUDY_STORE``), which every server process shares
and a restart keeps: finished jobs keep their summary for ``STUDY_KEEP_S`` seconds (at
most 64 jobs); the raw values only when the study asked for them (``keep_points``), in
a file, never in memory. ``DELETE`` cancels an unfinished job (in whichever process runs
it) and removes a finished one with its file. A value out of its range (a zero
or negative count or time) stops the service at start-up, naming the variable.
"""

from __future__ import annotations

import asyncio
import contextlib
import csv
import ctypes
import io
import json
import logging
import math
import os
import re
import sqlite3
import tempfile
import threading
import time
import uuid
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from fastapi import APIRouter, HTTPException, Query, Request, Response
from fastapi.concurrency import run_in_threadpool
from fastapi.responses import FileResponse, JSONResponse, StreamingResponse
from pydantic import BaseModel, ConfigDict, Field, create_model

import engine
from engine import ModelSpec
from engine.studies.execute import (
    Budget,
    Cancelled,
    ChunkArgs,
    DaskExecutor,
    HereIfCheap,
    InProcess,
    StudyRun,
    run_study,
)
from engine.studies.plan import (
    DISTRIBUTIONS,
    MAX_POINT_COLUMNS,
    METHODS,
    ChunkResult,
    Plan,
    Study,
    Variable,
    plan,
    points_blocks,
    study_size,
)

from . import schemas
from .api import _ERRORS, API_PREFIX
from .config import ApiKey, _float, _int, dask_tls, usable_cpus, usable_memory
from .jobstore import ACTIVE, BEAT_S, Full, open_store
from .middleware import client_of, key_of
from .units import quantity

_KEEP_JOBS = 64
#: The share of the usable memory the local Dask workers may hold between them.
DASK_MEMORY_SHARE = 0.5
#: How often the watchdog looks at this process's running studies [s] (:meth:`Studies.watch`).
WATCHDOG_S = 1.0
#: How long a study on Dask may wait on a cluster without a worker before it fails [s]:
#: long enough for a nanny to restart a worker that died, short beside a study's budget.
NO_WORKERS_S = 10.0
#: Past its budget, how long a study may wait for the chunk that would end it [s].
BUDGET_GRACE_S = 2.0
#: The longest ``GET /jobs/{id}?wait=`` holds its answer for the job to end [s].
MAX_WAIT_S = 30.0

log = logging.getLogger("service.studies")


@dataclass(frozen=True)
class StudySettings:
    """Study bounds and the Dask cluster, from the environment (each has a default)."""

    max_points: int = field(default_factory=lambda: _int("STUDY_MAX_POINTS", 2_000_000))
    budget_s: float = field(default_factory=lambda: _float("STUDY_BUDGET_S", 600.0))
    per_client: int = field(default_factory=lambda: _int("STUDY_PER_CLIENT", 2))
    max_active: int = field(default_factory=lambda: _int("STUDY_MAX_ACTIVE", 4))
    inprocess_points: int = field(default_factory=lambda: _int("STUDY_INPROCESS_POINTS", 2000))
    #: A larger study on the array path runs in the job thread while its chunks show the
    #: whole taking at most this long there (:class:`engine.studies.execute.HereIfCheap`)
    #: [s]; 0: every larger study on Dask.
    inprocess_s: float = field(default_factory=lambda: _float("STUDY_INPROCESS_S", 1.0))
    keep_s: float = field(default_factory=lambda: _float("STUDY_KEEP_S", 3600.0))
    keep_points_max: int = field(default_factory=lambda: _int("STUDY_KEEP_POINTS", 1_000_000))
    #: The job store's folder (SQLite database and points files), shared by every server
    #: process that serves the same jobs and kept across restarts.
    store: str = field(default_factory=lambda: os.environ.get("STUDY_STORE") or default_store())
    #: Disk the stored points may take, reservations of running studies included [bytes].
    disk_bytes: int = field(default_factory=lambda: _int("STUDY_DISK_BYTES", 2 * 10**9))
    dask_scheduler: str | None = field(
        default_factory=lambda: os.environ.get("DASK_SCHEDULER") or None
    )
    dask_workers: int | None = field(default_factory=lambda: _int("DASK_WORKERS", 0) or None)
    #: Memory each local Dask worker may use [bytes]; 0: a share of the memory the process
    #: may really use (cgroup limit), DASK_MEMORY_SHARE of it split between the workers.
    dask_worker_memory: int = field(default_factory=lambda: _int("DASK_WORKER_MEMORY", 0))

    def __post_init__(self) -> None:
        """Refuse a bound that makes no sense at start-up, naming the variable and its range
        (as :class:`service.config.Settings` does), not at the first study."""
        counts = (  # (variable, value, lowest allowed, what the lowest value means)
            ("STUDY_MAX_POINTS", self.max_points, 1, ""),
            ("STUDY_PER_CLIENT", self.per_client, 1, ""),
            ("STUDY_MAX_ACTIVE", self.max_active, 1, ""),
            ("STUDY_INPROCESS_POINTS", self.inprocess_points, 0, "0: every study on Dask"),
            ("STUDY_KEEP_POINTS", self.keep_points_max, 0, "0: raw points never kept"),
            ("STUDY_DISK_BYTES", self.disk_bytes, 0, "0: raw points never kept"),
            ("DASK_WORKERS", self.dask_workers or 0, 0, "0: one worker per usable CPU"),
            ("DASK_WORKER_MEMORY", self.dask_worker_memory, 0, "0: sized from the usable memory"),
        )
        for name, value, lowest, meaning in counts:
            if not value >= lowest:
                note = f" ({meaning})" if meaning else ""
                raise ValueError(f"{name} must be an integer >= {lowest}{note}, not {value!r}")
        if not (0.0 <= self.inprocess_s < math.inf):  # NaN too
            raise ValueError(
                "STUDY_INPROCESS_S must be a number of seconds >= 0 (0: every study of more "
                f"than STUDY_INPROCESS_POINTS points on Dask), not {self.inprocess_s!r}"
            )
        for name, seconds in (("STUDY_BUDGET_S", self.budget_s), ("STUDY_KEEP_S", self.keep_s)):
            if not seconds > 0:  # NaN too
                raise ValueError(f"{name} must be a number of seconds > 0, not {seconds!r}")


Number = float | str


class VariableIn(BaseModel):
    """One varied input: a grid axis or a distribution; numbers SI or strings with a unit."""

    model_config = ConfigDict(extra="forbid")
    name: str = Field(max_length=80, description="the input to vary")
    distribution: Literal["uniform", "normal", "triangular", "lognormal"] = Field(
        default="uniform", description="for Monte Carlo, LHS and Sobol' (ignored by a grid)"
    )
    low: Number | None = Field(default=None, description="lower end (grid, uniform, triangular)")
    high: Number | None = Field(default=None, description="upper end")
    mean: Number | None = Field(default=None, description="normal, lognormal: mean")
    sd: Number | None = Field(
        default=None, description="normal, lognormal: standard deviation (arithmetic)"
    )
    mode: Number | None = Field(default=None, description="triangular: most likely value")
    num: int = Field(default=11, ge=2, le=1000, description="grid: points on this axis")
    scale: Literal["linear", "log"] = Field(default="linear", description="grid: spacing")


class CorrelationIn(BaseModel):
    """Two varied inputs joined by a Gaussian copula of this rank (Spearman) correlation."""

    model_config = ConfigDict(extra="forbid")
    a: str = Field(max_length=80, description="one varied input")
    b: str = Field(max_length=80, description="another varied input")
    rank_correlation: float = Field(
        ge=-0.99, le=0.99, allow_inf_nan=False, description="Spearman's ρ_S, −0.99…0.99"
    )


#: Designs an explicit-point study may list (JSON rows or CSV lines); the body's size
#: (MAX_BODY_BYTES) bounds them too.
MAX_POINT_ROWS = 100_000


#: A study's fixed inputs as read (each model's route publishes them typed:
#: :func:`study_request`).
StudyBase = dict[str, float | int | bool | str | list[float]]


class StudyIn(BaseModel):
    # built on first use, as the models of service.schemas: each model's study route
    # declares its own subclass (study_request)
    model_config = ConfigDict(extra="forbid", defer_build=True)
    base: StudyBase = Field(
        default_factory=dict, description="inputs held fixed (defaults fill the rest)"
    )
    variables: list[VariableIn] = Field(
        default_factory=list,
        max_length=12,
        description="the inputs to vary and how (every method but 'points')",
    )
    method: Literal["grid", "monte_carlo", "lhs", "sobol", "points"] = Field(
        default="monte_carlo",
        description="how the designs are made; 'points': the designs listed in `points` or "
        "`points_csv` (set by giving either)",
    )
    points: list[dict[str, float | str]] | None = Field(
        default=None,
        min_length=1,
        max_length=MAX_POINT_ROWS,
        description="explicit designs, one object per design: the same numeric inputs in "
        "each, numbers in SI or strings with a unit as in a single run ('45 mm'); the other "
        "inputs from `base`",
    )
    points_csv: str | None = Field(
        default=None,
        description="explicit designs as CSV text: a header of input names, each with an "
        "optional unit in brackets ('clamp_length [mm]'), then one design a line; a cell is "
        "a number (in the column's unit, SI without one) or a number with its own unit",
    )
    samples: int = Field(default=1000, ge=2, le=2_000_000)
    seed: int = Field(default=0, ge=0, lt=2**63)
    fidelity: str | None = Field(default=None, max_length=40)
    tolerance: float | None = Field(default=None, gt=0, lt=1, allow_inf_nan=False)
    outputs: list[str] | None = Field(default=None, max_length=200)
    bins: int = Field(default=30, ge=1, le=200)
    feasible_when: str | None = Field(default=None, max_length=80)
    correlations: list[CorrelationIn] = Field(
        default_factory=list,
        max_length=66,
        description="rank correlations between varied inputs (Monte Carlo and LHS only)",
    )
    keep_points: bool = Field(
        default=False,
        description=(
            "keep the raw points for GET /api/v1/jobs/{id}/points.csv and /points.parquet"
        ),
    )


@dataclass
class Job:
    """A job this process runs: what its thread and its beat need. The job's record,
    which every process reads, is its row in the :class:`~service.jobstore.JobStore`."""

    id: str
    model: str
    client: str
    total: int
    keep_points: bool
    state: str = "queued"
    #: What a running job is doing: starting the cluster, evaluating, summarising.
    phase: str = "waiting for a study thread"
    done: int = 0
    created: float = field(default_factory=time.time)
    started: float | None = None
    finished: float | None = None
    error: dict[str, Any] | None = None
    cancel: threading.Event = field(default_factory=threading.Event)
    #: Set when the job thread is done with the job (finished, failed, cancelled or skipped).
    settled: bool = False
    #: Bytes its points file is expected to take (reserved against the disk quota).
    disk_bytes: int = 0
    #: The Dask executor its chunks wait on (None: in-process), for the watchdog.
    dask: DaskExecutor | None = None
    #: Since when (time.monotonic) the watchdog has seen the cluster without a worker.
    no_workers_since: float | None = None
    #: True once the job's end is in the store (``finished`` is set before it is written).
    stored_end: bool = False
    #: Called once the job's end is in the store (:meth:`Studies.settled`'s waits).
    waiters: list[Callable[[], None]] = field(default_factory=list)

    @property
    def active(self) -> bool:
        # a job counts until its thread has let it go: a queued job that was cancelled still
        # holds its thread's place until the pool reaches it and drops it
        return not self.settled

    def row(self, owner: str) -> dict[str, Any]:
        """The job's fields as the store keeps them."""
        return {
            "id": self.id,
            "model": self.model,
            "client": self.client,
            "total": self.total,
            "keep_points": int(self.keep_points),
            "state": self.state,
            "phase": self.phase,
            "done": self.done,
            "created": self.created,
            "started": self.started,
            "finished": self.finished,
            "error": self.error,
            "disk_bytes": self.disk_bytes,
            "owner": owner,
            "beat": time.time(),
        }


@dataclass(frozen=True)
class ClientShare:
    """The Dask workers as one client's studies use them: its studies share one window
    of chunks in flight (:meth:`DaskExecutor.map`'s ``owner``), so a client running two
    studies has the share of a client running one, not twice it: studies from different
    clients interleave."""

    dask: DaskExecutor
    client: str

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event, budget: Budget | None = None
    ) -> Iterator[tuple[int, ChunkResult]]:
        return self.dask.map(calls, cancel, budget, owner=self.client)


def _malloc_trim() -> Callable[[int], int] | None:
    """glibc's ``malloc_trim``, or None where the C library has none (musl, macOS)."""
    try:
        trim: Callable[[int], int] = ctypes.CDLL(None).malloc_trim
    except (OSError, AttributeError):
        return None
    return trim


_TRIM = _malloc_trim()


def release_memory() -> bool:
    """Give the heap a finished study freed back to the system; False where it cannot.

    glibc keeps freed memory for the process to reuse: after a 1,000,000-point joint study
    (its values ~600 MB) the service stayed at 852 MB where it started at 183 MB, and with
    its values on Dask it crept up 20 MB a study (1,121 MB after ten, measured
    by bench/shopfloor.py). Trimmed, it is back at 308 MB (measured). A few milliseconds,
    on the study's thread, with the GIL released.
    """
    if _TRIM is None:
        return False
    _TRIM(0)
    return True


def describe(job: dict[str, Any]) -> dict[str, Any]:
    """A job's answer (state, progress, result, links) from its stored record."""
    now = time.time()
    started, finished, done, total = job["started"], job["finished"], job["done"], job["total"]
    elapsed = 0.0 if started is None else (finished or now) - started
    rate = done / elapsed if elapsed > 0 else None
    left = None
    if rate and job["state"] == "running":
        left = (total - done) / rate
    body: dict[str, Any] = {
        "job": job["id"],
        "model": job["model"],
        "state": job["state"],
        "phase": job["phase"] if job["state"] in ("queued", "running") else job["state"],
        "progress": {
            "done": done,
            "total": total,
            "fraction": done / total if total else 1.0,
            "rate_per_s": rate,
            "elapsed_s": elapsed,
            "eta_s": left,
        },
        "links": {"self": f"{API_PREFIX}/jobs/{job['id']}"},
    }
    if job["error"] is not None:
        body["error"] = job["error"]
    if job["summary"] is not None:
        body["result"] = job["summary"]
        if job["points"]:
            body["links"]["points_csv"] = f"{API_PREFIX}/jobs/{job['id']}/points.csv"
            body["links"]["points_parquet"] = f"{API_PREFIX}/jobs/{job['id']}/points.parquet"
    return body


#: A network address in an error from Dask ("tcp://10.0.0.5:40123", "127.0.0.1:8786"):
#: where the workers run is nobody's business but the operator's (it is logged).
_ADDRESS = re.compile(
    r"\b[a-z][a-z0-9+.-]*://[^\s'\"<>,)]+"  # tcp://host:port, tls://…, inproc://…
    r"|\b\d{1,3}(?:\.\d{1,3}){3}(?::\d+)?\b"  # IPv4[:port]
    r"|\[[0-9a-fA-F:]+\](?::\d+)?"  # [IPv6]:port
)


def _public(message: str) -> str:
    """An error's text fit for a client: network addresses replaced, at most 300 characters.

    >>> _public("CommClosedError: in <TCP (closed) tcp://127.0.0.1:40213 remote=tcp://10.1.2.3:9>")
    'CommClosedError: in <TCP (closed) <worker> remote=<worker>>'
    >>> _public("KilledWorker: ('evaluate_chunk-1f', <WorkerState '192.168.0.7:4567', status>)")
    "KilledWorker: ('evaluate_chunk-1f', <WorkerState '<worker>', status>)"
    """
    return _ADDRESS.sub("<worker>", message)[:300]


def _json_clean(value: Any) -> Any:
    """Summaries are built from finite values, but a NaN must never reach JSON."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _json_clean(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_json_clean(v) for v in value]
    return value


def default_store() -> str:
    """``STUDY_STORE``'s default: a folder of this user's under the system's temporary
    directory, shared by every server process of the user on this machine."""
    return os.path.join(tempfile.gettempdir(), f"tightening-calc-jobs-{os.getuid()}")


class Studies:
    """The job store, this process's job threads and its beat, and the Dask executor."""

    def __init__(self, settings: StudySettings) -> None:
        self.settings = settings
        # SQLite in STUDY_STORE, or the PostgreSQL server JOB_STORE names
        self.store = open_store(Path(settings.store), settings.disk_bytes)
        #: Certificates for DASK_SCHEDULER (DASK_TLS_*), checked here, at start-up.
        self.dask_tls = dask_tls(settings.dask_scheduler)
        #: This process's share of the store: the jobs its threads run.
        self.owner = uuid.uuid4().hex
        self.jobs: dict[str, Job] = {}
        self.lock = threading.Lock()
        self.threads = ThreadPoolExecutor(
            max_workers=max(1, settings.max_active), thread_name_prefix="study"
        )
        self._dask: DaskExecutor | None = None
        self._next_watch = 0.0
        self._stop = threading.Event()
        self._beat = threading.Thread(target=self._beating, name="study-beat", daemon=True)
        self._beat.start()

    def dask(self) -> DaskExecutor:
        with self.lock:
            if self._dask is None:
                # one worker per CPU this process may use (affinity, cgroup quota), not one
                # per CPU of the host: 2 in a 2-CPU container on a 64-CPU machine
                workers = self.settings.dask_workers or usable_cpus()
                # and memory from what the process may use (cgroup memory.max), half of it
                # for the workers: 1 GB each in a 4 GB, 2-CPU container on a 24 GB host
                memory = self.settings.dask_worker_memory or int(
                    DASK_MEMORY_SHARE * usable_memory() / workers
                )
                self._dask = DaskExecutor(
                    self.settings.dask_scheduler,
                    n_workers=workers,
                    memory_limit=memory,
                    tls=self.dask_tls,
                )
            return self._dask

    def _beating(self) -> None:
        """Every BEAT_S: the progress of this process's jobs to the store, the cancels
        asked of them (in any process) to their threads."""
        while not self._stop.wait(BEAT_S):
            self.beat()

    def beat(self) -> None:
        with self.lock:
            mine = [j for j in self.jobs.values() if j.active]
            for j in [j for j in self.jobs.values() if not j.active]:
                del self.jobs[j.id]  # settled and written: the store has it
        if not mine:
            return
        now = time.monotonic()
        if now >= self._next_watch:
            self._next_watch = now + WATCHDOG_S
            for j in mine:
                self.watch(j, now)
        try:
            cancels = self.store.beat(self.owner, [(j.id, j.done, j.phase) for j in mine])
        except sqlite3.Error as exc:  # a locked or full disk: said, and tried again
            log.warning("the job store did not take the beat: %s", exc)
            return
        for j in mine:
            if j.id in cancels:
                j.cancel.set()

    def watch(self, job: Job, now: float) -> None:
        """Fail a running study that can no longer end by itself: past its budget with no
        chunk back (the budget is otherwise checked only when one comes back), or on a
        Dask cluster that has had no worker for ``NO_WORKERS_S`` (workers killed, or never
        started under load: a study sat at 0 points for 527 s). The job's error names the
        cause, its place in the quotas is freed at once, and its chunks are cancelled."""
        if job.state != "running" or job.started is None or job.done >= job.total:
            return  # not started, or summarising: no chunk is awaited
        where = f"after {job.done} of {job.total} points"
        budget = self.settings.budget_s
        if time.time() - job.started > budget + BUDGET_GRACE_S:
            self._fail(
                job,
                "budget_exceeded",
                f"the study passed its {budget:g} s budget (STUDY_BUDGET_S) {where} with no "
                "chunk back from the workers",
                field="samples",
            )
            return
        if job.dask is None:
            return
        if job.dask.workers() > 0:
            job.no_workers_since = None
        elif job.no_workers_since is None:
            job.no_workers_since = now
        elif now - job.no_workers_since >= NO_WORKERS_S:
            self._fail(
                job,
                "no_workers",
                f"the Dask cluster has had no worker for {NO_WORKERS_S:g} s: the study "
                f"stopped {where}; retry later",
            )

    def _fail(self, job: Job, kind: str, msg: str, field: str | None = None) -> None:
        """The watchdog's end of a job: failed in the store (its quota freed), its chunks
        stopped; the job's thread, when its executor lets it go, finds it finished."""
        error = {"type": kind, "msg": msg, "field": field}
        if self._finish(job, "failed", error=error, disk_bytes=0):
            log.warning("study %s failed: %s", job.id, msg)
            job.cancel.set()

    def state(self) -> dict[str, Any]:
        """Studies running and queued here, the unfinished ones in all, and the limits
        (for ``/readyz``); when the job store cannot be read, ``active`` is None and
        ``store_error`` says why (``/readyz`` is then not ready)."""
        with self.lock:
            here = [j for j in self.jobs.values() if j.active]
        state: dict[str, Any] = {
            "running": sum(j.state == "running" for j in here),
            "queued": sum(j.state == "queued" for j in here),
            "active": None,
            "max_active": self.settings.max_active,
            "per_client": self.settings.per_client,
        }
        try:
            state["active"] = len(self.store.active())
        except sqlite3.Error as exc:  # StoreError too: a database gone, locked, or broken
            log.warning("readiness: the job store cannot be read: %s", exc)
            state["store_error"] = f"{type(exc).__name__}: {exc}"[:200]
        return state

    def _prune(self) -> None:
        self.store.prune(self.settings.keep_s, _KEEP_JOBS)

    def submit(
        self,
        spec: ModelSpec,
        study: Study,
        client: str,
        keep_points: bool,
        key: ApiKey | None = None,
    ) -> Job:
        """Check the study, then the limits and quotas, and only then draw its points.

        Every refusal that needs no drawing (a 422: a bad law, an unknown fidelity, too
        many points) and the quotas (503: per client, in all, disk) come before
        :func:`engine.studies.plan.plan`, which takes seconds and gigabytes for a study of
        millions of points; a refusal that needs the drawn points (the base with the
        first point) frees the job's place. A client with an API ``key`` has the key's
        quotas where it names them (studies at once, points per study), the server's
        otherwise.
        """
        n_points = study_size(spec, study)
        max_points, limit = self.settings.max_points, "this server's limit"
        if key is not None and key.points is not None:
            max_points, limit = key.points, f"the limit of the API key {key.name!r}"
        if n_points > max_points:
            raise engine.InputOutOfRange(
                f"the study has {n_points} points, over {limit} of {max_points}"
                + (" (STUDY_MAX_POINTS)" if max_points == self.settings.max_points else ""),
                field="samples",
            )
        if keep_points and n_points > self.settings.keep_points_max:
            raise engine.InputOutOfRange(
                f"keep_points is allowed up to {self.settings.keep_points_max} points",
                field="keep_points",
            )
        job = Job(uuid.uuid4().hex, spec.name, client, n_points, keep_points)
        if keep_points:  # the file's float64 columns: the varied inputs, then the outputs
            varied = len(study.points) if study.points is not None else len(study.variables)
            columns = varied + len(study.outputs or spec.outputs)
            job.disk_bytes = 8 * n_points * columns
        self._prune()
        try:
            self.store.admit(
                job.row(self.owner),
                per_client=self.settings.per_client
                if key is None or key.studies is None
                else key.studies,
                max_active=self.settings.max_active,
            )
        except Full as exc:
            raise HTTPException(
                status_code=503, detail=str(exc), headers={"retry-after": "5"}
            ) from None
        with self.lock:
            self.jobs[job.id] = job
        try:
            p = plan(spec, study)
        except BaseException:
            with self.lock:
                self.jobs.pop(job.id, None)
            self.store.remove(job.id)
            raise
        self.threads.submit(self._work, job, spec, study, p)
        return job

    def _finish(self, job: Job, state: str, **fields: Any) -> bool:
        """End ``job`` in ``state`` with the stored ``fields``, once: False (nothing
        written) when it has already ended (the watchdog failed it meanwhile)."""
        with self.lock:
            if job.finished is not None:
                return False
            job.state, job.finished = state, time.time()
            job.error = fields.get("error", job.error)
        try:
            self.store.update(
                job.id, state=job.state, done=job.done, finished=job.finished, **fields
            )
        except sqlite3.Error as exc:
            log.warning("study %s: the job store did not take its end: %s", job.id, exc)
        with self.lock:
            job.stored_end = True
            waiters = list(job.waiters)
        for wake in waiters:
            wake()
        return True

    async def settled(self, job_id: str, seconds: float) -> None:
        """Return once the job is no longer queued or running (or gone), or after
        ``seconds``: woken by its end where this process runs it, and reading the store
        every ``BEAT_S`` otherwise (a job of another process, a cancel asked there)."""
        loop = asyncio.get_running_loop()
        deadline = loop.time() + seconds
        ended = asyncio.Event()

        def wake() -> None:
            with contextlib.suppress(RuntimeError):  # the loop closed: nobody waits
                loop.call_soon_threadsafe(ended.set)

        with self.lock:
            job = self.jobs.get(job_id)
            if job is not None:
                if job.stored_end:
                    return
                job.waiters.append(wake)
        try:
            while (left := deadline - loop.time()) > 0:
                with contextlib.suppress(TimeoutError):
                    await asyncio.wait_for(ended.wait(), min(BEAT_S, left))
                    return
                record = await run_in_threadpool(self.store.get, job_id)
                if record is None or record["state"] not in ACTIVE:
                    return
        finally:
            if job is not None:
                with self.lock, contextlib.suppress(ValueError):
                    job.waiters.remove(wake)

    def _work(self, job: Job, spec: ModelSpec, study: Study, p: Plan | None = None) -> None:
        try:
            self._run(job, spec, study, p)
        finally:
            job.settled = True
            # the study's values are freed: give the memory back, not keep it in the RSS
            release_memory()

    def _run(self, job: Job, spec: ModelSpec, study: Study, p: Plan | None) -> None:
        if job.cancel.is_set():  # cancelled while it waited for a thread
            self._finish(job, "cancelled")
            return
        job.state, job.started = "running", time.time()
        self.store.update(job.id, state="running", started=job.started, phase=job.phase)

        def progress(done: int, total: int) -> None:
            job.done = done
            job.phase = "summarising" if done == total else "evaluating"

        try:

            def remote() -> ClientShare:
                dask = self.dask()
                job.phase = "starting the Dask workers"
                dask.client()
                job.dask = dask
                return ClientShare(dask, job.client)

            if job.total <= self.settings.inprocess_points:
                executor: InProcess | HereIfCheap = InProcess()
            else:
                executor = HereIfCheap(remote, self.settings.inprocess_s)
            result = run_study(
                spec,
                study,
                executor,
                progress=progress,
                cancel=job.cancel,
                budget_s=self.settings.budget_s,
                planned=p,
            )
            summary = _json_clean(result.summary)
            written = 0
            path = self.store.points_path(job.id)
            if job.keep_points:  # the raw values go to disk, never stay in memory
                job.phase = "writing the points"
                write_points(path, job.id, result)
                written = path.stat().st_size
            del result
            if (
                not self._finish(
                    job, "done", summary=summary, points=int(job.keep_points), disk_bytes=written
                )
                and written
            ):
                path.unlink(missing_ok=True)  # the watchdog failed it first: nothing kept
        except Cancelled:
            self._finish(job, "cancelled", disk_bytes=0)
        except engine.EngineError as exc:
            error = {"type": exc.kind, "msg": exc.message, "field": exc.field}
            self._finish(job, "failed", error=error, disk_bytes=0)
        except Exception as exc:  # a worker that died, a lost scheduler: said, not hidden
            log.warning("study %s failed: %s: %s", job.id, type(exc).__name__, exc)
            error = {"type": "study_failed", "msg": _public(f"{type(exc).__name__}: {exc}")}
            self._finish(job, "failed", error=error, disk_bytes=0)

    def record(self, job_id: str, client: str | None = None) -> dict[str, Any]:
        """The stored job, or 404; with a ``client`` (a key's identity, where the server has
        API keys) only a job of that client: another key's job is not there for it."""
        job = self.store.get(job_id)
        if job is None or (client is not None and job["client"] != client):
            raise HTTPException(status_code=404, detail=f"no job {job_id[:40]!r}")
        return job

    def get(self, job_id: str, client: str | None = None) -> dict[str, Any]:
        """The job's answer (state, progress, result, links), from any process's store."""
        return describe(self.record(job_id, client))

    def cancel(self, job_id: str, client: str | None = None) -> dict[str, Any]:
        """Cancel an unfinished job; remove a finished one with its summary and points.

        The answer is the job as it stood; a removed job answers 404 from then on. A job
        another process runs is stopped by that process at its next beat.
        """
        job = self.record(job_id, client)
        if job["state"] not in ACTIVE:
            self.store.remove(job_id)
            body = describe(job)
            body["links"] = {}
            body["deleted"] = True
            return body
        with self.lock:
            local = self.jobs.get(job_id)
        if local is not None:
            local.cancel.set()
            if local.state == "queued":
                local.state = "cancelled"
        return describe(self.store.ask_cancel(job_id) or job)

    def shutdown(self) -> None:
        self._stop.set()
        with self.lock:
            mine = list(self.jobs.values())
        for job in mine:
            job.cancel.set()
        self.threads.shutdown(wait=False, cancel_futures=True)
        for job in mine:  # what never ran is said, not left "queued" in the store
            if job.state == "queued":
                self._finish(job, "cancelled")
        if self._dask is not None:
            self._dask.close()
        self.store.close()


def _si(spec: ModelSpec, name: str, value: Number | None, part: str) -> float | None:
    """A law's ``part`` (low, high, mean, sd, mode) in SI units: one reader with the sweep's
    ends (:func:`units.quantity`)."""
    if value is None:
        return None
    try:
        param = spec.param(name)
    except KeyError:
        raise engine.InputOutOfRange(
            f"variables: {name!r} is not an input of {spec.name}", field="variables"
        ) from None
    return quantity(param, value, part, field="variables", spread=part == "sd")


_HEADER = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[([^\]]+)\])?\s*")


def _point_param(spec: ModelSpec, name: str, where: str, field: str) -> Any:
    """The numeric input ``name`` a design gives, or a refusal naming ``where``."""
    try:
        param = spec.param(name)
    except KeyError:
        raise engine.InputOutOfRange(
            f"{where}: {name[:80]!r} is not an input of {spec.name}", field=field
        ) from None
    if not param.is_numeric:
        raise engine.InputOutOfRange(
            f"{where}: {name} is not a numeric input of {spec.name}; give it in base",
            field=field,
        )
    return param


def _csv_rows(text: str) -> Iterator[tuple[str, dict[str, float | str]]]:
    """The designs of ``points_csv``, each with its place (``points_csv line N``): a cell
    that is a plain number takes its column's unit from the header, where there is one.
    Text that is not CSV (a NUL byte, an unclosed quote over a huge field) is refused."""
    try:
        yield from _csv_read(text)
    except csv.Error as exc:
        raise engine.InputOutOfRange(
            f"points_csv: not readable as CSV ({str(exc)[:120]})", field="points_csv"
        ) from None


def _csv_read(text: str) -> Iterator[tuple[str, dict[str, float | str]]]:
    if text.count("\n") > MAX_POINT_ROWS + 1:
        raise engine.InputOutOfRange(
            f"points_csv: at most {MAX_POINT_ROWS} designs", field="points_csv"
        )
    reader = csv.reader(io.StringIO(text.removeprefix("\ufeff")))
    header = next((cells for cells in reader if cells), None)  # blank lines skipped
    columns: list[tuple[str, str | None]] = []
    for cell in header or []:
        match = _HEADER.fullmatch(cell)
        if match is None:
            raise engine.InputOutOfRange(
                f"points_csv line 1: {cell[:80]!r} is not an input name with an optional [unit]",
                field="points_csv",
            )
        columns.append((match.group(1), match.group(2)))
    if not columns:
        raise engine.InputOutOfRange(
            "points_csv: a header of input names, then one design a line", field="points_csv"
        )
    if len(columns) > MAX_POINT_COLUMNS:
        raise engine.InputOutOfRange(
            f"points_csv line 1: at most {MAX_POINT_COLUMNS} inputs", field="points_csv"
        )
    for cells in reader:
        if not cells:  # a blank line
            continue
        where = f"points_csv line {reader.line_num}"
        if len(cells) != len(columns):
            raise engine.InputOutOfRange(
                f"{where}: {len(cells)} values for the header's {len(columns)} inputs",
                field="points_csv",
            )
        row: dict[str, float | str] = {}
        for (name, unit), cell in zip(columns, cells, strict=True):
            cell = cell.strip()
            try:
                number = float(cell)
            except ValueError:
                row[name] = cell  # a number with its own unit, read below
            else:
                row[name] = f"{cell} {unit}" if unit else number
        yield where, row


def _on_csv_line(exc: engine.InputOutOfRange, text: str | None) -> engine.InputOutOfRange:
    """The engine's refusal of a design (its index in ``context["row"]``) as the line of
    ``points_csv`` it came from, where the designs came as CSV; else as it is."""
    row = exc.context.get("row")
    if text is None or exc.field != "points" or not isinstance(row, int):
        return exc
    reader = csv.reader(io.StringIO(text.removeprefix("\ufeff")))
    seen = -2  # the header, then the designs from 0, blank lines skipped as _csv_rows skips
    with contextlib.suppress(csv.Error):  # read whole once already: it is CSV
        for cells in reader:
            seen += bool(cells)
            if seen == row:
                break
    where = f"points_csv line {reader.line_num}"
    msg = re.sub(r"^points: design \d+ \(points\[\d+\]\)", where, exc.message)
    return engine.InputOutOfRange(msg, field="points_csv", **exc.context)


def designs(spec: ModelSpec, body: StudyIn) -> dict[str, np.ndarray] | None:
    """The explicit designs of ``points`` or ``points_csv`` as SI columns (None without).

    Every design gives the same numeric inputs; a value is a number in SI or a string with
    a unit (one reader with a single run's: :func:`units.quantity`). The limits (designs,
    inputs) are checked before a value is read, and a refusal names the design (``points[3]``
    or ``points_csv line 5``) and the input. Ranges are the engine's to check
    (:func:`engine.studies.plan.study_size`).
    """
    if body.points is None and body.points_csv is None:
        if body.method == "points":
            raise engine.InputOutOfRange(
                "points: method 'points' needs the designs, in points or points_csv",
                field="points",
            )
        return None
    if "method" in body.model_fields_set and body.method != "points":
        raise engine.InputOutOfRange(
            f"method: designs listed in points or points_csv are method 'points', not "
            f"{body.method!r}",
            field="method",
        )
    if body.points is not None and body.points_csv is not None:
        raise engine.InputOutOfRange(
            "points: give the designs once, in points or in points_csv", field="points"
        )
    field = "points" if body.points is not None else "points_csv"
    rows: Iterator[tuple[str, dict[str, float | str]]] = (
        ((f"points[{i}]", row) for i, row in enumerate(body.points))
        if body.points is not None
        else _csv_rows(body.points_csv or "")
    )
    names: list[str] = []
    params: dict[str, Any] = {}
    values: dict[str, list[float]] = {}
    for where, row in rows:
        if not names:
            names = list(row)
            if not names or len(names) > MAX_POINT_COLUMNS:
                raise engine.InputOutOfRange(
                    f"{where}: a design gives 1 to {MAX_POINT_COLUMNS} inputs", field=field
                )
            head = "points_csv line 1" if field == "points_csv" else where
            params = {n: _point_param(spec, n, head, field) for n in names}
            values = {n: [] for n in names}
        if row.keys() != params.keys():
            odd = sorted(set(row) ^ set(params))[0]
            said = "is missing" if odd in params else "is not in the first design"
            raise engine.InputOutOfRange(
                f"{where}: {odd[:80]} {said} (every design gives the same inputs)", field=field
            )
        for name, value in row.items():
            values[name].append(quantity(params[name], value, where, field=field))
    if not names:
        raise engine.InputOutOfRange(f"{field}: no design given", field=field)
    return {name: np.asarray(column, dtype=float) for name, column in values.items()}


def study_request(spec: ModelSpec) -> type[StudyIn]:
    """The body of ``POST <path>/study`` for ``spec``: :class:`StudyIn`, its ``base``
    published as the model's own inputs, each optional (the schema of
    :func:`schemas.inputs_model`, the sweep's base), so the OpenAPI document, and a client
    generated from it, name every input with its unit and range.

    The base is read as before, as a study law's numbers are (:func:`units.quantity`, the
    engine's ranges, a refusal naming the input), and takes what the published schema
    takes (tests/service/test_study_typed_base.py).
    """

    def published() -> dict[str, Any]:  # when /openapi.json is first asked for
        schema = schemas.inputs_model(spec, all_optional=True).model_json_schema()
        schema["title"] = schemas._class_name(spec, "StudyBase")
        return schema

    model: type[StudyIn] = create_model(
        schemas._class_name(spec, "StudyRequest"),
        __base__=StudyIn,
        base=(
            Annotated[StudyBase, schemas.LazyJsonSchema(published)],
            Field(default_factory=dict, description="inputs held fixed (defaults fill the rest)"),
        ),
    )
    return model


def to_study(spec: ModelSpec, body: StudyIn) -> Study:
    """The engine's :class:`Study` from a request body (unit strings → SI)."""
    base: dict[str, Any] = {}
    for name, value in body.base.items():
        try:
            param = spec.param(name)
        except KeyError:
            raise engine.InputOutOfRange(
                f"base: unknown input {name!r} for model {spec.name}", field="base"
            ) from None
        if isinstance(value, str) and param.is_numeric:
            value = quantity(param, value, "base", field=name)
        base[name] = value
    variables = tuple(
        Variable(
            v.name,
            v.distribution,
            low=_si(spec, v.name, v.low, "low"),
            high=_si(spec, v.name, v.high, "high"),
            mean=_si(spec, v.name, v.mean, "mean"),
            sd=_si(spec, v.name, v.sd, "sd"),
            mode=_si(spec, v.name, v.mode, "mode"),
            num=v.num,
            scale=v.scale,
        )
        for v in body.variables
    )
    points = designs(spec, body)
    return Study(
        variables=variables,
        base=base,
        method="points" if points is not None else body.method,
        points=points,
        samples=body.samples,
        seed=body.seed,
        fidelity=body.fidelity,
        tolerance=body.tolerance,
        outputs=None if body.outputs is None else tuple(body.outputs),
        bins=body.bins,
        feasible_when=body.feasible_when,
        correlations=tuple((c.a, c.b, c.rank_correlation) for c in body.correlations),
    )


def _keyed(request: Request) -> str | None:
    """The client whose jobs alone a request may see: its key's identity where the server
    has API keys; None (every job) where the API is open."""
    return client_of(request.scope) if key_of(request.scope) is not None else None


def study_router(models: Sequence[ModelSpec], studies: Studies) -> APIRouter:
    """``POST <path>/study`` per model, and ``/jobs/{id}`` to poll, fetch and cancel."""
    router = APIRouter(prefix=API_PREFIX, tags=["studies"])

    def add(spec: ModelSpec) -> None:
        async def submit(body: StudyIn, request: Request) -> JSONResponse:
            # explicit designs may be many cells with units to read: off the event loop
            study = await run_in_threadpool(to_study, spec, body)
            client, key = client_of(request.scope), key_of(request.scope)
            # drawing up to STUDY_MAX_POINTS points takes a while: off the event loop
            try:
                job = await run_in_threadpool(
                    studies.submit, spec, study, client, body.keep_points, key
                )
            except engine.InputOutOfRange as exc:
                raise _on_csv_line(exc, body.points_csv) from None
            return JSONResponse(
                await run_in_threadpool(studies.get, job.id, None),
                status_code=202,
                headers={"location": f"{API_PREFIX}/jobs/{job.id}"},
            )

        submit.__annotations__["body"] = study_request(spec)  # the model's typed base
        router.add_api_route(
            spec.path + "/study",
            submit,
            methods=["POST"],
            status_code=202,
            summary=f"{spec.title}: a design study (grid, Monte Carlo, LHS, Sobol')",
            description=(
                "Vary up to 12 inputs (a grid: up to 3) by distribution "
                f"({', '.join(DISTRIBUTIONS)}) with method one of {', '.join(METHODS)}, "
                "or list the designs themselves (`points`: JSON rows, or `points_csv`); "
                "returns 202 with a job to poll at GET /api/v1/jobs/{id}."
            ),
            operation_id=spec.name.replace(".", "_") + "_study",
            responses={
                **_ERRORS,
                202: {
                    "description": "accepted: the job to poll (state, progress, links)",
                    "headers": {
                        "Location": {
                            "description": "the job's address, /api/v1/jobs/{job}",
                            "schema": {"type": "string"},
                        }
                    },
                },
                503: {
                    "model": schemas.ErrorResponse,
                    "description": (
                        "too many unfinished studies (per client or in all), or no disk for "
                        "the points to keep; retry after Retry-After"
                    ),
                },
            },
        )

    for spec in models:
        add(spec)

    _404: dict[int | str, dict[str, Any]] = {
        404: {"model": schemas.ErrorResponse, "description": "no such job (or expired)"}
    }

    @router.get(
        "/jobs/{job_id}",
        operation_id="get_job",
        summary="A study's state, progress and, when done, result",
        description=(
            "With `wait`, the answer waits up to that many seconds for an unfinished job "
            "to end, and comes as soon as it has: a client learns of the end at once, "
            "without polling."
        ),
        responses=_404,
    )
    async def get_job(
        job_id: str,
        request: Request,
        wait: Annotated[
            float,
            Query(
                ge=0,
                le=MAX_WAIT_S,
                description=f"seconds to wait for an unfinished job to end, 0…{MAX_WAIT_S:g}",
            ),
        ] = 0.0,
    ) -> dict[str, Any]:
        client = _keyed(request)
        body = await run_in_threadpool(studies.get, job_id, client)
        if wait > 0 and body["state"] in ACTIVE:
            await studies.settled(job_id, wait)
            body = await run_in_threadpool(studies.get, job_id, client)
        return body

    @router.delete(
        "/jobs/{job_id}",
        operation_id="delete_job",
        summary="Cancel a study and free its workers, or remove a finished one and its data",
        responses=_404,
    )
    def cancel_job(job_id: str, request: Request) -> dict[str, Any]:
        return studies.cancel(job_id, _keyed(request))

    def stored_points(job_id: str, request: Request) -> Path:
        job = studies.record(job_id, _keyed(request))
        path = studies.store.points_path(job_id)
        if not job["points"] or not path.is_file():
            raise HTTPException(
                status_code=404,
                detail="no points: the study is not done, or was run without keep_points",
            )
        return path

    @router.get(
        "/jobs/{job_id}/points.csv",
        operation_id="get_job_points_csv",
        summary="The raw points of a finished study (asked with keep_points)",
        description="Streamed from the stored file, a block of rows at a time.",
        response_class=Response,
        responses={**_404, 200: {"content": {"text/csv": {}}, "description": "the points"}},
    )
    def points(job_id: str, request: Request) -> StreamingResponse:
        path = stored_points(job_id, request)
        return StreamingResponse(
            csv_blocks(path),  # a plain iterator: Starlette reads it on a worker thread
            media_type="text/csv",
            headers={"content-disposition": f'attachment; filename="study-{job_id}.csv"'},
        )

    @router.get(
        "/jobs/{job_id}/points.parquet",
        operation_id="get_job_points_parquet",
        summary="The raw points of a finished study as Parquet (asked with keep_points)",
        description=(
            "The columns of points.csv (inputs, then outputs, SI), float64, null where a "
            "point was refused; each field's `unit` metadata and the schema's `units` say "
            "the units. The stored file itself, streamed."
        ),
        response_class=Response,
        responses={
            **_404,
            200: {"content": {PARQUET: {}}, "description": "the points"},
        },
    )
    def points_parquet(job_id: str, request: Request) -> FileResponse:
        return FileResponse(
            stored_points(job_id, request),
            media_type=PARQUET,
            headers={"content-disposition": f'attachment; filename="study-{job_id}.parquet"'},
        )

    return router


#: The media type registered for Parquet (IANA, 2024).
PARQUET = "application/vnd.apache.parquet"


#: Rows of a Parquet row group, read a group at a time for the CSV.
ROWS_PER_BLOCK = 65_536
#: Rows of a piece of the streamed CSV: about 1.7 MB for a joint study (76 columns),
#: where a whole row group's text (55 MB, with its Python floats 200 MB more) added
#: 800 MB to the service's RSS during a 1,000,000-point download (bench/shopfloor.py).
CSV_ROWS_PER_PIECE = 2048


def write_points(path: Path, job_id: str, run: StudyRun) -> None:
    """The raw points of a study as a Parquet file: the CSV's columns, float64, SI units.

    A point the model refused is null (the CSV leaves the cell empty); each field carries
    its unit in its metadata (``unit``), and the schema names the model, the job and every
    column's unit (``units``, JSON) so a reader that drops field metadata still has them.
    Written beside ``path`` and renamed, so a reader never sees half a file.
    """
    import pyarrow as pa  # imported on first use: the service starts without it loaded
    import pyarrow.parquet as pq

    header = [*run.plan.columns, *run.plan.outputs]
    units = {**run.summary.get("input_units", {}), **run.summary.get("units", {})}
    fields = [
        pa.field(name, pa.float64(), metadata={"unit": units.get(name, "")}) for name in header
    ]
    schema = pa.schema(
        fields,
        metadata={
            "model": run.summary.get("model", ""),
            "job": job_id,
            "units": json.dumps({name: units.get(name, "") for name in header}),
        },
    )
    partial = path.with_suffix(".partial")
    # a row group at a time, from the study's chunks: no merged table in memory
    with pq.ParquetWriter(partial, schema) as writer:
        for block in points_blocks(run.plan, run.merged, ROWS_PER_BLOCK):
            arrays = []
            for values in block:
                col = np.ascontiguousarray(values, dtype=np.float64)
                arrays.append(pa.array(col, type=pa.float64(), mask=~np.isfinite(col)))
            writer.write_table(pa.Table.from_arrays(arrays, schema=schema))
    partial.replace(path)


def csv_blocks(path: Path) -> Iterator[bytes]:
    """The points file as CSV, a piece of ``CSV_ROWS_PER_PIECE`` rows at a time (never the
    whole file, nor a whole row group's text, in memory): a header, then each row's values
    as Python writes a float, empty where refused."""
    import pyarrow.parquet as pq

    reader = pq.ParquetFile(path)
    out = io.StringIO()
    writer = csv.writer(out)
    writer.writerow(reader.schema_arrow.names)
    for batch in reader.iter_batches(batch_size=ROWS_PER_BLOCK):
        columns = [c.to_numpy(zero_copy_only=False) for c in batch.columns]
        for start in range(0, batch.num_rows, CSV_ROWS_PER_PIECE):
            piece = [c[start : start + CSV_ROWS_PER_PIECE] for c in columns]
            matrix = np.column_stack(piece) if piece else np.empty((0, 0))
            for row in matrix.tolist():
                writer.writerow(["" if not math.isfinite(v) else repr(v) for v in row])
            yield out.getvalue().encode()
            out.seek(0)
            out.truncate()
    if out.tell():
        yield out.getvalue().encode()


__all__ = ["Studies", "StudySettings", "describe", "study_router", "to_study"]
