"""Design studies as jobs: ``POST <model path>/study`` → 202, then poll, fetch, cancel.

A study (:mod:`engine.studies.plan`) can take minutes, so it never runs in a request:
the POST validates it, draws nothing yet, and returns ``202`` with the job's
address. A small pool of job threads drives studies; a study of at most
``STUDY_INPROCESS_POINTS`` points runs in that thread, a larger one on Dask
(:class:`engine.studies.execute.DaskExecutor`): a local cluster sized to the
machine, started when the first large study arrives, or the scheduler named
by ``DASK_SCHEDULER``. Studies never use the engine pool that serves single
calculations, and their heavy compute runs in Dask's worker processes, not in
the service's interpreter.

Budgets: ``STUDY_MAX_POINTS`` points and ``STUDY_BUDGET_S`` seconds per study;
at most ``STUDY_PER_CLIENT`` unfinished studies per client address and
``STUDY_MAX_ACTIVE`` in all (503 with Retry-After beyond that), checked before a
single point is drawn. Finished jobs keep their summary for ``STUDY_KEEP_S`` seconds
(at most 64 jobs); the raw values only when the study asked for them
(``keep_points``). ``DELETE`` cancels an unfinished job and removes a finished one
with its data. A value out of its range (a zero
or negative count or time) stops the service at start-up, naming the variable.
"""

from __future__ import annotations

import csv
import io
import json
import logging
import math
import os
import re
import threading
import time
import uuid
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from fastapi import APIRouter, HTTPException, Request, Response
from fastapi.concurrency import run_in_threadpool
from fastapi.responses import JSONResponse
from pydantic import BaseModel, ConfigDict, Field

import engine
from engine import ModelSpec
from engine.studies.execute import Cancelled, DaskExecutor, InProcess, StudyRun, run_study
from engine.studies.plan import (
    DISTRIBUTIONS,
    METHODS,
    Plan,
    Study,
    Variable,
    plan,
    points_table,
    study_size,
)

from . import schemas
from .api import _ERRORS, API_PREFIX
from .config import _float, _int, usable_cpus, usable_memory
from .units import quantity

_KEEP_JOBS = 64
#: The share of the usable memory the local Dask workers may hold between them.
DASK_MEMORY_SHARE = 0.5

log = logging.getLogger("service.studies")


@dataclass(frozen=True)
class StudySettings:
    """Study bounds and the Dask cluster, from the environment (each has a default)."""

    max_points: int = field(default_factory=lambda: _int("STUDY_MAX_POINTS", 2_000_000))
    budget_s: float = field(default_factory=lambda: _float("STUDY_BUDGET_S", 600.0))
    per_client: int = field(default_factory=lambda: _int("STUDY_PER_CLIENT", 2))
    max_active: int = field(default_factory=lambda: _int("STUDY_MAX_ACTIVE", 4))
    inprocess_points: int = field(default_factory=lambda: _int("STUDY_INPROCESS_POINTS", 2000))
    keep_s: float = field(default_factory=lambda: _float("STUDY_KEEP_S", 3600.0))
    keep_points_max: int = field(default_factory=lambda: _int("STUDY_KEEP_POINTS", 1_000_000))
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
            ("DASK_WORKERS", self.dask_workers or 0, 0, "0: one worker per usable CPU"),
            ("DASK_WORKER_MEMORY", self.dask_worker_memory, 0, "0: sized from the usable memory"),
        )
        for name, value, lowest, meaning in counts:
            if not value >= lowest:
                note = f" ({meaning})" if meaning else ""
                raise ValueError(f"{name} must be an integer >= {lowest}{note}, not {value!r}")
        for name, seconds in (("STUDY_BUDGET_S", self.budget_s), ("STUDY_KEEP_S", self.keep_s)):
            if not seconds > 0:  # NaN too
                raise ValueError(f"{name} must be a number of seconds > 0, not {seconds!r}")


Number = float | str


class VariableIn(BaseModel):
    """One varied input: a grid axis or a distribution; numbers SI or strings with a unit."""

    model_config = ConfigDict(extra="forbid")
    name: str = Field(max_length=80, description="the input to vary")
    distribution: Literal["uniform", "normal", "triangular"] = Field(
        default="uniform", description="for Monte Carlo, LHS and Sobol' (ignored by a grid)"
    )
    low: Number | None = Field(default=None, description="lower end (grid, uniform, triangular)")
    high: Number | None = Field(default=None, description="upper end")
    mean: Number | None = Field(default=None, description="normal: mean")
    sd: Number | None = Field(default=None, description="normal: standard deviation")
    mode: Number | None = Field(default=None, description="triangular: most likely value")
    num: int = Field(default=11, ge=2, le=1000, description="grid: points on this axis")
    scale: Literal["linear", "log"] = Field(default="linear", description="grid: spacing")


class StudyIn(BaseModel):
    model_config = ConfigDict(extra="forbid")
    base: dict[str, float | int | bool | str | list[float]] = Field(
        default_factory=dict, description="inputs held fixed (defaults fill the rest)"
    )
    variables: list[VariableIn] = Field(min_length=1, max_length=12)
    method: Literal["grid", "monte_carlo", "lhs", "sobol"] = "monte_carlo"
    samples: int = Field(default=1000, ge=2, le=2_000_000)
    seed: int = Field(default=0, ge=0, lt=2**63)
    fidelity: str | None = Field(default=None, max_length=40)
    tolerance: float | None = Field(default=None, gt=0, lt=1, allow_inf_nan=False)
    outputs: list[str] | None = Field(default=None, max_length=200)
    bins: int = Field(default=30, ge=1, le=200)
    feasible_when: str | None = Field(default=None, max_length=80)
    keep_points: bool = Field(
        default=False,
        description=(
            "keep the raw points for GET /api/v1/jobs/{id}/points.csv and /points.parquet"
        ),
    )


@dataclass
class Job:
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
    #: The summary of a finished study (small: statistics, histograms, extremes).
    summary: dict[str, Any] | None = None
    #: The raw values, only where the study asked for them (``keep_points``).
    run: StudyRun | None = None
    cancel: threading.Event = field(default_factory=threading.Event)
    #: Set when the job thread is done with the job (finished, failed, cancelled or skipped).
    settled: bool = False

    @property
    def active(self) -> bool:
        # a job counts until its thread has let it go: a queued job that was cancelled still
        # holds its place in the pool until the pool reaches it and drops it
        return not self.settled

    def describe(self) -> dict[str, Any]:
        now = time.time()
        elapsed = 0.0 if self.started is None else (self.finished or now) - self.started
        rate = self.done / elapsed if elapsed > 0 else None
        left = None
        if rate and self.state == "running":
            left = (self.total - self.done) / rate
        body: dict[str, Any] = {
            "job": self.id,
            "model": self.model,
            "state": self.state,
            "phase": self.phase if self.state in ("queued", "running") else self.state,
            "progress": {
                "done": self.done,
                "total": self.total,
                "fraction": self.done / self.total if self.total else 1.0,
                "rate_per_s": rate,
                "elapsed_s": elapsed,
                "eta_s": left,
            },
            "links": {"self": f"{API_PREFIX}/jobs/{self.id}"},
        }
        if self.error is not None:
            body["error"] = self.error
        if self.summary is not None:
            body["result"] = self.summary
            if self.run is not None:
                body["links"]["points_csv"] = f"{API_PREFIX}/jobs/{self.id}/points.csv"
                body["links"]["points_parquet"] = f"{API_PREFIX}/jobs/{self.id}/points.parquet"
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


class Studies:
    """The job table, the job threads and the Dask executor, for one app."""

    def __init__(self, settings: StudySettings) -> None:
        self.settings = settings
        self.jobs: dict[str, Job] = {}
        self.lock = threading.Lock()
        self.threads = ThreadPoolExecutor(
            max_workers=max(1, settings.max_active), thread_name_prefix="study"
        )
        self._dask: DaskExecutor | None = None

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
                    self.settings.dask_scheduler, n_workers=workers, memory_limit=memory
                )
            return self._dask

    def state(self) -> dict[str, Any]:
        """Studies running and queued here, the unfinished ones in all, and the limits
        (for ``/readyz``)."""
        with self.lock:
            active = [j for j in self.jobs.values() if j.active]
        running = sum(j.state == "running" for j in active)
        return {
            "running": running,
            "queued": len(active) - running,
            "active": len(active),
            "max_active": self.settings.max_active,
            "per_client": self.settings.per_client,
        }

    def _prune(self) -> None:
        now = time.time()
        done = sorted(
            (j for j in self.jobs.values() if not j.active), key=lambda j: j.finished or 0.0
        )
        excess = max(0, len(done) - _KEEP_JOBS)
        for i, j in enumerate(done):
            if i < excess or now - (j.finished or now) > self.settings.keep_s:
                del self.jobs[j.id]

    def submit(self, spec: ModelSpec, study: Study, client: str, keep_points: bool) -> Job:
        """Check the study, then the limits and quotas, and only then draw its points.

        Every refusal that needs no drawing (a 422: a bad law, an unknown fidelity, too
        many points) and the quotas (503) come before :func:`engine.studies.plan.plan`, which
        takes seconds and gigabytes for a study of millions of points; a refusal that
        needs the drawn points (the base with the first point) frees the job's place.
        """
        n_points = study_size(spec, study)
        if n_points > self.settings.max_points:
            raise engine.InputOutOfRange(
                f"the study has {n_points} points, over this server's limit of "
                f"{self.settings.max_points} (STUDY_MAX_POINTS)",
                field="samples",
            )
        if keep_points and n_points > self.settings.keep_points_max:
            raise engine.InputOutOfRange(
                f"keep_points is allowed up to {self.settings.keep_points_max} points",
                field="keep_points",
            )
        with self.lock:
            self._prune()
            active = [j for j in self.jobs.values() if j.active]
            mine = [j for j in active if j.client == client]
            if len(mine) >= self.settings.per_client or len(active) >= self.settings.max_active:
                raise HTTPException(
                    status_code=503,
                    detail=(
                        f"{len(mine)} of your studies and {len(active)} in all are running "
                        f"(limits {self.settings.per_client} per client, "
                        f"{self.settings.max_active} in all); retry when one finishes or "
                        "cancel one"
                    ),
                    headers={"retry-after": "5"},
                )
            job = Job(uuid.uuid4().hex, spec.name, client, n_points, keep_points)
            self.jobs[job.id] = job  # holds its place while the points are drawn
        try:
            p = plan(spec, study)
        except BaseException:
            with self.lock:
                self.jobs.pop(job.id, None)
            raise
        self.threads.submit(self._work, job, spec, study, p)
        return job

    def _work(self, job: Job, spec: ModelSpec, study: Study, p: Plan | None = None) -> None:
        if job.cancel.is_set():  # cancelled while it waited for a thread
            job.settled = True
            return
        job.state, job.started = "running", time.time()

        def progress(done: int, total: int) -> None:
            job.done = done
            job.phase = "summarising" if done == total else "evaluating"

        try:
            if job.total <= self.settings.inprocess_points:
                executor: InProcess | DaskExecutor = InProcess()
            else:
                executor = self.dask()
                job.phase = "starting the Dask workers"
                executor.client()
            result = run_study(
                spec,
                study,
                executor,
                progress=progress,
                cancel=job.cancel,
                budget_s=self.settings.budget_s,
                planned=p,
            )
            job.summary = _json_clean(result.summary)
            # the raw values leave memory once summarised unless the study asked for them
            job.run = result if job.keep_points else None
            job.state = "done"
        except Cancelled:
            job.state = "cancelled"
        except engine.EngineError as exc:
            job.state = "failed"
            job.error = {"type": exc.kind, "msg": exc.message, "field": exc.field}
        except Exception as exc:  # a worker that died, a lost scheduler: said, not hidden
            log.warning("study %s failed: %s: %s", job.id, type(exc).__name__, exc)
            job.state = "failed"
            job.error = {"type": "study_failed", "msg": _public(f"{type(exc).__name__}: {exc}")}
        finally:
            job.finished = time.time()
            job.settled = True

    def get(self, job_id: str) -> Job:
        with self.lock:
            job = self.jobs.get(job_id)
        if job is None:
            raise HTTPException(status_code=404, detail=f"no job {job_id[:40]!r}")
        return job

    def cancel(self, job_id: str) -> dict[str, Any]:
        """Cancel an unfinished job; remove a finished one with its summary and points.

        The answer is the job as it stood; a removed job answers 404 from then on.
        """
        job = self.get(job_id)
        with self.lock:
            if not job.active:
                self.jobs.pop(job.id, None)
                body = job.describe()
                body["links"] = {}
                body["deleted"] = True
                job.summary = job.run = None
                return body
        job.cancel.set()
        if job.state == "queued":
            job.state, job.finished = "cancelled", time.time()
        return job.describe()

    def shutdown(self) -> None:
        for job in list(self.jobs.values()):
            job.cancel.set()
        self.threads.shutdown(wait=False, cancel_futures=True)
        if self._dask is not None:
            self._dask.close()


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
    return Study(
        variables=variables,
        base=base,
        method=body.method,
        samples=body.samples,
        seed=body.seed,
        fidelity=body.fidelity,
        tolerance=body.tolerance,
        outputs=None if body.outputs is None else tuple(body.outputs),
        bins=body.bins,
        feasible_when=body.feasible_when,
    )


def study_router(models: Sequence[ModelSpec], studies: Studies) -> APIRouter:
    """``POST <path>/study`` per model, and ``/jobs/{id}`` to poll, fetch and cancel."""
    router = APIRouter(prefix=API_PREFIX, tags=["studies"])

    def add(spec: ModelSpec) -> None:
        async def submit(body: StudyIn, request: Request) -> JSONResponse:
            study = to_study(spec, body)
            client = request.client.host if request.client else "unknown"
            # drawing up to STUDY_MAX_POINTS points takes a while: off the event loop
            job = await run_in_threadpool(studies.submit, spec, study, client, body.keep_points)
            return JSONResponse(
                job.describe(),
                status_code=202,
                headers={"location": f"{API_PREFIX}/jobs/{job.id}"},
            )

        router.add_api_route(
            spec.path + "/study",
            submit,
            methods=["POST"],
            status_code=202,
            summary=f"{spec.title}: a design study (grid, Monte Carlo, LHS, Sobol')",
            description=(
                "Vary up to 12 inputs (a grid: up to 3) by distribution "
                f"({', '.join(DISTRIBUTIONS)}) with method one of {', '.join(METHODS)}; "
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
                    "description": "too many unfinished studies (per client or in all); retry",
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
        responses=_404,
    )
    def get_job(job_id: str) -> dict[str, Any]:
        return studies.get(job_id).describe()

    @router.delete(
        "/jobs/{job_id}",
        operation_id="delete_job",
        summary="Cancel a study and free its workers, or remove a finished one and its data",
        responses=_404,
    )
    def cancel_job(job_id: str) -> dict[str, Any]:
        return studies.cancel(job_id)

    def finished(job_id: str) -> tuple[Job, StudyRun]:
        job = studies.get(job_id)
        if job.run is None or not job.keep_points:
            raise HTTPException(
                status_code=404,
                detail="no points: the study is not done, or was run without keep_points",
            )
        return job, job.run

    @router.get(
        "/jobs/{job_id}/points.csv",
        operation_id="get_job_points_csv",
        summary="The raw points of a finished study (asked with keep_points)",
        response_class=Response,
        responses={**_404, 200: {"content": {"text/csv": {}}, "description": "the points"}},
    )
    def points(job_id: str) -> Response:
        job, run = finished(job_id)
        header, matrix = points_table(run.plan, run.merged)
        out = io.StringIO()
        writer = csv.writer(out)
        writer.writerow(header)
        for row in matrix.tolist():
            writer.writerow(["" if not math.isfinite(v) else repr(v) for v in row])
        return Response(
            out.getvalue(),
            media_type="text/csv",
            headers={"content-disposition": f'attachment; filename="study-{job.id}.csv"'},
        )

    @router.get(
        "/jobs/{job_id}/points.parquet",
        operation_id="get_job_points_parquet",
        summary="The raw points of a finished study as Parquet (asked with keep_points)",
        description=(
            "The columns of points.csv (inputs, then outputs, SI), float64, null where a "
            "point was refused; each field's `unit` metadata and the schema's `units` say "
            "the units."
        ),
        response_class=Response,
        responses={
            **_404,
            200: {"content": {PARQUET: {}}, "description": "the points"},
        },
    )
    def points_parquet(job_id: str) -> Response:
        job, run = finished(job_id)
        return Response(
            parquet_points(job.id, run),
            media_type=PARQUET,
            headers={"content-disposition": f'attachment; filename="study-{job.id}.parquet"'},
        )

    return router


#: The media type registered for Parquet (IANA, 2024).
PARQUET = "application/vnd.apache.parquet"


def parquet_points(job_id: str, run: StudyRun) -> bytes:
    """The raw points of a study as a Parquet file: the CSV's columns, float64, SI units.

    A point the model refused is null (the CSV leaves the cell empty); each field carries
    its unit in its metadata (``unit``), and the schema names the model, the job and every
    column's unit (``units``, JSON) so a reader that drops field metadata still has them.
    """
    import pyarrow as pa  # imported on first use: the service starts without it loaded
    import pyarrow.parquet as pq

    header, matrix = points_table(run.plan, run.merged)
    units = {**run.summary.get("input_units", {}), **run.summary.get("units", {})}
    fields, arrays = [], []
    for i, name in enumerate(header):
        col = np.ascontiguousarray(matrix[:, i], dtype=np.float64)
        arrays.append(pa.array(col, type=pa.float64(), mask=~np.isfinite(col)))
        fields.append(pa.field(name, pa.float64(), metadata={"unit": units.get(name, "")}))
    schema = pa.schema(
        fields,
        metadata={
            "model": run.summary.get("model", ""),
            "job": job_id,
            "units": json.dumps({name: units.get(name, "") for name in header}),
        },
    )
    out = io.BytesIO()
    pq.write_table(pa.Table.from_arrays(arrays, schema=schema), out)
    return out.getvalue()


__all__ = ["Studies", "StudySettings", "study_router", "to_study"]
