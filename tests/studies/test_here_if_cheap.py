"""A large array-path study runs here while its chunks show the whole cheap; a dear one goes
to the remote executor once they do not, and a study that may simulate points one by one goes
there from the first: chunk for chunk the same values."""

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
    array_only,
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
    assert executor.here == 4


def test_a_dear_study_sends_every_chunk_after_the_first_once(reference: StudyRun) -> None:
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=1e-9)  # no chunk is that fast
    _same(run_study(SPEC, _study(SAMPLES), executor), reference)
    assert executor.here == 1
    assert recorder.sizes == [VECTOR_CHUNK, VECTOR_CHUNK, 1000]


def test_chunks_dearer_than_the_first_go_remote_once_they_show_it(reference: StudyRun) -> None:
    """Designs in a given order, the first chunks cheap: the time here stays within the
    limit and one chunk (on the first chunk alone it would stay here for all four)."""
    ticks = iter([0.0, 0.01, 0.01, 0.51, 0.51, 1.51])  # chunks of 0.01 s, then 0.5 s
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=1.0, clock=lambda: next(ticks))
    _same(run_study(SPEC, _study(SAMPLES), executor), reference)
    # after two chunks: 0.51 s / 2 x 4 chunks = 1.02 s > 1 s
    assert executor.here == 2
    assert recorder.sizes == [VECTOR_CHUNK, 1000]


def test_with_no_time_here_every_chunk_goes_to_the_remote(reference: StudyRun) -> None:
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=0.0)
    _same(run_study(SPEC, _study(SAMPLES), executor), reference)
    assert recorder.sizes == [VECTOR_CHUNK, VECTOR_CHUNK, VECTOR_CHUNK, 1000]
    assert executor.here == 0


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
    assert executor.here == 0


def test_an_auto_study_that_may_simulate_is_never_run_here() -> None:
    """At a tolerance, impact.rare's points take the closed form or the simulation: its
    chunks are of the array path's size (its first points take the closed form) and
    might still simulate some of their 65,536 points one by one, for minutes."""
    spec = engine.get_model("impact.rare")
    ex = dict(spec.examples[0])
    rate = ex.pop("power_spring_rate")
    study = Study(
        variables=(Variable("power_spring_rate", "uniform", low=rate, high=1.5 * rate),),
        base=ex,
        samples=VECTOR_CHUNK + 10,
        seed=3,
        tolerance=0.05,
    )
    recorder = Recorder()
    executor = HereIfCheap(lambda: recorder, here_s=1e9)
    run = run_study(spec, study, executor)
    assert recorder.sizes == [VECTOR_CHUNK, 10]  # array-path chunks, all sent
    assert executor.here == 0
    assert run.summary["points"] == VECTOR_CHUNK + 10


@pytest.mark.parametrize(
    ("model", "fidelity", "tolerance", "expected"),
    [
        ("preload.tightening", "closed_form", None, True),
        ("preload.tightening", None, None, True),
        ("impact.rare", "closed_form", None, True),
        ("impact.rare", "simulation", None, False),
        ("impact.rare", None, 0.05, False),  # auto: some points may be simulated
        ("impact.rare", "closed_form", 0.05, True),  # the rung named: no fallback
    ],
)
def test_which_studies_are_on_the_array_path_alone(
    model: str, fidelity: str | None, tolerance: float | None, expected: bool
) -> None:
    assert array_only(engine.get_model(model), fidelity, tolerance) is expected
    assert array_only(model, fidelity, tolerance) is False  # a name: not known here


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
    assert executor.here == 0  # cancelled as its first chunk came in: nothing more here
