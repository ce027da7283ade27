"""A large array-path study times its first chunk here and stays here when that says the whole
is cheap; a dear or one-by-one study goes to the remote executor, chunk for chunk the same."""

from __future__ import annotations

import threading
from collections.abc import Iterator

import numpy as np
import pytest

import engine
from engine.studies.execute import (
    LOOP_CHUNK,
    VECTOR_CHUNK,
    Budget,
    ChunkArgs,
    HereIfCheap,
    InProcess,
    StudyRun,
    run_study,
)
from engine.studies.plan import ChunkResult, Study, Variable

SPEC = engine.get_model("preload.tightening")


class Recorder:
    """A remote executor that runs its chunks here and keeps their sizes."""

    def __init__(self) -> None:
        self.sizes: list[int] | None = None

    def map(
        self, calls: list[ChunkArgs], cancel: threading.Event, budget: Budget | None = None
    ) -> Iterator[tuple[int, ChunkResult]]:
        self.sizes = [len(next(iter(c[2].values()))) for c in calls]
        return InProcess().map(calls, cancel, budget)


def _study(samples: int) -> Study:
    base = {k: v for k, v in SPEC.examples[0].items() if k != "thread_friction"}
    return Study(
        variables=(Variable("thread_friction", "uniform", low=0.08, high=0.16),),
        base=base,
        samples=samples,
        seed=7,
        fidelity="closed_form",
    )


def _same(a: StudyRun, b: StudyRun) -> None:
    strip = ("elapsed_s", "compute_s")
    assert {k: v for k, v in a.summary.items() if k not in strip} == {
        k: v for k, v in b.summary.items() if k not in strip
    }
    for name, col in a.merged.values.items():
        assert np.array_equal(col, b.merged.values[name], equal_nan=True), name


SAMPLES = 3 * VECTOR_CHUNK + 1000  # four chunks, the last short


@pytest.fixture(scope="module")
def reference() -> StudyRun:
    return run_study(SPEC, _study(SAMPLES), InProcess())


def test_a_cheap_study_stays_here_and_never_asks_for_the_cluster(reference: StudyRun) -> None:
    def remote() -> Recorder:
        raise AssertionError("a cheap study started the cluster")

    executor = HereIfCheap(remote, here_s=60.0)
    _same(run_study(SPEC, _study(SAMPLES), executor), reference)
    assert executor.rest == "here"


def test_a_dear_study_sends_every_chunk_after_the_first_once(reference: StudyRun) -> None:
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=1e-9)  # no chunk is that fast
    _same(run_study(SPEC, _study(SAMPLES), executor), reference)
    assert executor.rest == "remote"
    assert recorder.sizes == [VECTOR_CHUNK, VECTOR_CHUNK, 1000]


def test_with_no_time_here_every_chunk_goes_to_the_remote(reference: StudyRun) -> None:
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=0.0)
    _same(run_study(SPEC, _study(SAMPLES), executor), reference)
    assert recorder.sizes == [VECTOR_CHUNK, VECTOR_CHUNK, VECTOR_CHUNK, 1000]


def test_one_by_one_chunks_are_never_run_here() -> None:
    """A simulation study's chunk may run for a minute: none is timed in the service."""
    spec = engine.get_model("impact.rare")
    ex = dict(spec.examples[0])
    study = Study(
        variables=(
            Variable(
                "power_spring_rate",
                "uniform",
                low=0.9 * ex["power_spring_rate"],
                high=1.1 * ex["power_spring_rate"],
            ),
        ),
        base={k: v for k, v in ex.items() if k != "power_spring_rate"},
        samples=LOOP_CHUNK + 4,
        seed=3,
        fidelity="simulation",
    )
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=1e9)
    _same(run_study(spec, study, executor), run_study(spec, study, InProcess()))
    assert recorder.sizes == [LOOP_CHUNK, 4]
    assert executor.rest == "remote"


def test_a_study_cancelled_in_its_first_chunk_starts_no_cluster() -> None:
    def remote() -> Recorder:
        raise AssertionError("a cancelled study started the cluster")

    cancel = threading.Event()

    def progress(done: int, total: int) -> None:
        if done:
            cancel.set()

    executor = HereIfCheap(remote, here_s=1e-9)
    with pytest.raises(engine.EngineError, match="cancelled after 65536 of"):
        run_study(SPEC, _study(SAMPLES), executor, progress=progress, cancel=cancel)
    assert executor.rest is None
