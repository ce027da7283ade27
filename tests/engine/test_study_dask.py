"""Studies on Dask: the same result, bit for bit, in-process, on a local cluster and on a
separate scheduler with two workers that this test starts (all on 127.0.0.1)."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import engine
from engine.studies.execute import LOOP_CHUNK, VECTOR_CHUNK, DaskExecutor, StudyRun, run_study
from engine.studies.plan import Study, Variable

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
RARE = engine.get_model("impact.rare")


def _study() -> Study:
    ex = dict(RARE.examples[0])
    return Study(
        variables=(
            Variable(
                "power_spring_rate",
                "normal",
                mean=ex["power_spring_rate"],
                sd=0.1 * ex["power_spring_rate"],
            ),
            Variable(
                "power_spring_preload",
                "uniform",
                low=0.5 * ex["power_spring_preload"],
                high=2.0 * ex["power_spring_preload"],
            ),
        ),
        base={
            k: v for k, v in ex.items() if k not in ("power_spring_rate", "power_spring_preload")
        },
        method="lhs",
        samples=3 * LOOP_CHUNK + 17,  # four chunks, the last one short
        seed=42,
        fidelity="simulation",
        feasible_when="full_engagement",
    )


def _equal(a: StudyRun, b: StudyRun) -> None:
    strip = ("elapsed_s", "compute_s")
    sa = {k: v for k, v in a.summary.items() if k not in strip}
    sb = {k: v for k, v in b.summary.items() if k not in strip}
    assert sa == sb
    for name, col in a.merged.values.items():
        assert np.array_equal(col, b.merged.values[name], equal_nan=True), name


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture(scope="module")
def reference() -> StudyRun:
    return run_study(RARE, _study())


def test_a_local_cluster_gives_the_in_process_result(reference: StudyRun) -> None:
    executor = DaskExecutor(n_workers=2)
    try:
        executor.client()
        # the local scheduler runs in this process: count the results it relays (a chunk's
        # values decrypted, encrypted again and decrypted once more here, where the
        # client can take them from the worker that holds them)
        scheduler = executor._cluster.scheduler
        gather = scheduler.handlers["gather"]
        relayed: list[Any] = []

        def counted(*args: Any, **kwargs: Any) -> Any:
            relayed.append(kwargs.get("keys"))
            return gather(*args, **kwargs)

        scheduler.handlers["gather"] = counted
        _equal(reference, run_study(RARE, _study(), executor))
        assert relayed == []
        # the client speaks to the scheduler in this process, with no socket (a chunk's
        # inputs are not encrypted and decrypted here on their way to a worker); the
        # workers, and the client's fetches from them, over the cluster's TLS
        client = executor.client()
        assert client.scheduler.address.startswith("inproc://")
        assert executor._cluster.scheduler_address.startswith("tls://")
        workers = client.scheduler_info()["workers"]
        assert len(workers) == 2 and all(w.startswith("tls://") for w in workers)

        def faults() -> int:
            # a chunk's column made and freed 50 times: from the heap, its pages are
            # faulted in once; from a fresh mapping each time, 128 pages each time
            import resource

            import numpy

            before = resource.getrusage(resource.RUSAGE_THREAD).ru_minflt
            for _ in range(50):
                column = numpy.ones(LOOP_CHUNK * 256)
                del column
            return resource.getrusage(resource.RUSAGE_THREAD).ru_minflt - before

        per_worker = executor.client().run(faults)
        assert len(per_worker) == 2
        assert all(n < 10 * 128 for n in per_worker.values()), per_worker

        def chunk_faults() -> int:
            # a chunk's worth of columns (40 of VECTOR_CHUNK values, 20 MiB) made and freed
            # 10 times: with the freed heap top kept, only the first round faults its 5,120
            # pages in; given back after each round, every round does
            import resource

            import numpy

            before = resource.getrusage(resource.RUSAGE_THREAD).ru_minflt
            for _ in range(10):
                columns = [numpy.ones(VECTOR_CHUNK) for _ in range(40)]
                del columns
            return resource.getrusage(resource.RUSAGE_THREAD).ru_minflt - before

        per_worker = executor.client().run(chunk_faults)
        assert len(per_worker) == 2
        assert all(n < 2 * 5_120 for n in per_worker.values()), per_worker
    finally:
        executor.close()


@pytest.fixture()
def scheduler(cluster_processes: tuple[str, list[subprocess.Popen[bytes]]]) -> str:
    return cluster_processes[0]


@pytest.fixture()
def cluster_processes() -> Iterator[tuple[str, list[subprocess.Popen[bytes]]]]:
    """A scheduler and two one-thread workers, the address and the processes (scheduler
    first)."""
    port = _free_port()
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    bindir = Path(sys.executable).parent
    procs = [
        subprocess.Popen(
            [
                str(bindir / "dask"),
                "scheduler",
                "--host",
                "127.0.0.1",
                "--port",
                str(port),
                "--no-dashboard",
            ],
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
    ]
    address = f"tcp://127.0.0.1:{port}"
    procs.append(
        subprocess.Popen(
            [
                str(bindir / "dask"),
                "worker",
                address,
                "--nworkers",
                "2",
                "--nthreads",
                "1",
                "--no-dashboard",
                "--host",
                "127.0.0.1",
            ],
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
    )
    try:
        yield address, procs
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()


def _two_workers(executor: DaskExecutor) -> None:
    """Wait (up to a minute) for the separate scheduler's two workers to register."""
    client = executor.client()
    deadline = time.monotonic() + 60
    while len(client.scheduler_info()["workers"]) < 2:
        assert time.monotonic() < deadline, "the two workers did not register"
        time.sleep(0.2)


def test_a_separate_scheduler_with_two_workers_gives_the_same_result(
    reference: StudyRun, scheduler: str
) -> None:
    executor = DaskExecutor(scheduler)
    try:
        _two_workers(executor)
        _equal(reference, run_study(RARE, _study(), executor))
    finally:
        executor.close()


def test_the_service_sends_a_study_to_the_scheduler_it_is_told(
    reference: StudyRun, scheduler: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    from fastapi.testclient import TestClient

    from service import create_app

    monkeypatch.setenv("DASK_SCHEDULER", scheduler)
    monkeypatch.setenv("STUDY_INPROCESS_POINTS", "0")  # every study on Dask
    monkeypatch.setenv("STUDY_INPROCESS_S", "0")  # not even a cheap one in the job thread
    study = _study()
    body = {
        "base": dict(study.base),
        "variables": [
            {k: v for k, v in vars(var).items() if v is not None} for var in study.variables
        ],
        "method": study.method,
        "samples": study.samples,
        "seed": study.seed,
        "fidelity": study.fidelity,
        "feasible_when": study.feasible_when,
    }
    with TestClient(create_app()) as client:
        job = client.post("/api/v1/impact/rare/study", json=body).json()["job"]
        deadline = time.monotonic() + 120
        while (state := client.get(f"/api/v1/jobs/{job}").json())["state"] in ("queued", "running"):
            assert time.monotonic() < deadline, state
            time.sleep(0.1)
    assert state["state"] == "done", state
    strip = ("elapsed_s", "compute_s")
    got = {k: v for k, v in state["result"].items() if k not in strip}
    want = {k: v for k, v in reference.summary.items() if k not in strip}
    assert got == want


def test_a_failed_chunk_leaves_nothing_of_its_study_behind() -> None:
    """A chunk that raises on its worker fails the study with the worker's error, and the
    study's values, futures and keys go with it: Dask keeps the exception it raised for as
    long as the client knows the key, so the study's frames must not end up in it."""
    import gc

    from engine.studies.plan import Merger, chunks, plan

    spec = engine.get_model("preload.tightening")
    ex = dict(spec.examples[0])
    study = Study(
        variables=(Variable("thread_friction", "uniform", low=0.08, high=0.16),),
        base={k: v for k, v in ex.items() if k != "thread_friction"},
        samples=4 * VECTOR_CHUNK,
        seed=5,
    )
    p = plan(spec, study)
    starts = [a for a, _ in chunks(p.n_points, VECTOR_CHUNK)]
    bad = float(p.columns["thread_friction"][starts[2]])  # the third chunk's first point

    def install() -> None:
        import engine.studies.execute as remote

        kept = getattr(remote, "_kept_evaluate_chunk", remote.evaluate_chunk)
        remote._kept_evaluate_chunk = kept  # type: ignore[attr-defined]

        def failing(spec: Any, base: Any, columns: Any, *args: Any, **kwargs: Any) -> Any:
            if float(columns["thread_friction"][0]) == bad:
                raise ValueError("a worker's error in the third chunk")
            return kept(spec, base, columns, *args, **kwargs)

        remote.evaluate_chunk = failing  # type: ignore[assignment]

    executor = DaskExecutor(n_workers=1)
    try:
        client = executor.client()
        client.run(install)
        for _ in range(2):
            with pytest.raises(ValueError, match="a worker's error in the third chunk"):
                run_study(spec, study, executor)
        end = time.monotonic() + 10.0
        while True:
            gc.collect()
            left = (len(client.futures), sum(isinstance(o, Merger) for o in gc.get_objects()))
            if left == (0, 0) or time.monotonic() > end:
                break
            time.sleep(0.1)
        assert left == (0, 0), f"futures the client still knows, studies' values alive: {left}"
    finally:
        executor.close()


def test_a_cancel_ends_the_study_when_the_scheduler_does_not_answer(
    cluster_processes: tuple[str, list[subprocess.Popen[bytes]]],
) -> None:
    """A scheduler stopped (SIGSTOP) while a study runs on it: the cancel ends the study
    within seconds, where setting the study's stop event waited on the scheduler for ever
    and the study's futures, cancelled after it, were never let go."""
    import signal
    import threading

    from engine.core.errors import Cancelled

    address, procs = cluster_processes
    executor = DaskExecutor(address)
    stopped = False
    try:
        _two_workers(executor)
        study = _study()
        study = Study(**{**vars(study), "samples": 40 * LOOP_CHUNK})  # about 10 s of chunks
        cancel = threading.Event()
        progressed = threading.Event()
        ended: list[BaseException | None] = []

        def run() -> None:
            try:
                run_study(
                    RARE,
                    study,
                    executor,
                    cancel=cancel,
                    progress=lambda done, _: done and progressed.set(),
                )
                ended.append(None)
            except BaseException as exc:
                ended.append(exc)

        worker = threading.Thread(target=run, daemon=True)
        worker.start()
        assert progressed.wait(60), "no chunk finished"
        procs[0].send_signal(signal.SIGSTOP)
        stopped = True
        t0 = time.monotonic()
        cancel.set()
        worker.join(20)
        took = time.monotonic() - t0
        assert not worker.is_alive(), "the cancelled study still waits on the scheduler"
        assert isinstance(ended[0], Cancelled), ended
        assert took < 10, took
        # a study started while the scheduler does not answer fails, saying so
        t0 = time.monotonic()
        with pytest.raises(TimeoutError, match="the Dask scheduler did not answer within 10 s"):
            run_study(RARE, study, executor)
        assert time.monotonic() - t0 < 15
    finally:
        if stopped:
            procs[0].send_signal(signal.SIGCONT)
        executor.close()
