"""A finished study gives its memory back to the system, not only to the allocator.

Issue 34's full-scale figures (bench/shopfloor.py): ten finished 1,000,000-point joint
studies left the service at 1,121 MB where it started at 267 MB, and it grew about
20 MB a study. The values were freed (tests/service/test_study_memory.py holds that),
but glibc kept the freed heap for reuse; each study's thread now trims it.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient

import service.studies
from service import create_app
from service.studies import StudySettings, release_memory
from tests.toys import TOY

URL = "/api/v1/toy/disc/study"
STUDY = {
    "base": {"diameter": 0.3},
    "variables": [{"name": "mass", "low": 1, "high": 2}],
    "samples": 50,
    "fidelity": "exact",
    "outputs": ["energy"],
}


def _rss_mb() -> float:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    pytest.skip("no /proc/self/status")


@pytest.fixture()
def client() -> Iterator[TestClient]:
    settings = StudySettings(inprocess_points=100_000)
    with TestClient(create_app(models=[TOY], study_settings=settings)) as c:
        yield c


def test_each_finished_study_releases_the_memory(
    client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Done, failed or cancelled, a study's thread trims the heap once as it lets go."""
    calls: list[str] = []
    monkeypatch.setattr(service.studies, "release_memory", lambda: calls.append("trim"))
    jobs = [client.post(URL, json={**STUDY, "seed": s}).json()["job"] for s in (1, 2)]
    for job_id in jobs:
        deadline = time.monotonic() + 30
        while client.get(f"/api/v1/jobs/{job_id}").json()["state"] in ("queued", "running"):
            assert time.monotonic() < deadline
            time.sleep(0.02)
    deadline = time.monotonic() + 5
    while len(calls) < 2 and time.monotonic() < deadline:  # set as the thread ends
        time.sleep(0.01)
    assert calls == ["trim", "trim"]


def test_the_trim_gives_freed_heap_back() -> None:
    """200 MB in 64 KB blocks (heap, not mmap), nine in ten freed, one in ten kept between
    them: the freed 180 MB stay in the RSS until the trim, which returns most of them."""
    blocks = [np.ones(8192) for _ in range(3200)]  # 64 KB each, every page touched
    kept = blocks[::10]
    del blocks
    before = _rss_mb()
    if not release_memory():
        pytest.skip("no malloc_trim in this C library")
    after = _rss_mb()
    assert before - after > 100, (before, after)
    assert len(kept) == 320


@pytest.mark.slow
def test_dask_does_not_keep_the_arguments_of_past_chunks() -> None:
    """Issue 34 at full scale: ~10 MB more RSS for each 10⁶-point study on Dask (344 →
    498 MB over 16). The client's log of recent messages (1,000 by default) held each
    chunk's submitted arguments, and through them the study's columns. 80 one-chunk
    studies: what is held after 40 is what is held after 80 (before: 4 a study, 320 after
    80), a few logs' worth of ``DASK_LOG_LENGTH`` sends (the client's to the scheduler,
    the in-process scheduler's to the worker, and objects in passage: 36 and 40 were seen
    here)."""
    import gc

    from distributed.protocol.serialize import ToPickle

    import engine
    from engine.studies.execute import DASK_LOG_LENGTH, DaskExecutor, run_study
    from engine.studies.plan import Study, Variable

    joint = engine.get_model("joint.vdi2230")
    base = {"thread_diameter": 0.012, "plate1_thickness": 0.02, "plate2_thickness": 0.02}
    executor = DaskExecutor(n_workers=1)
    try:
        held = []
        for seed in range(80):
            study = Study(
                variables=(Variable("working_load", low=5000.0, high=10000.0),),
                base=base,
                samples=100,
                seed=seed,
            )
            assert run_study(joint, study, executor).summary["points"] == 100
            if seed in (39, 79):
                gc.collect()
                held.append(sum(isinstance(o, ToPickle) for o in gc.get_objects()))
        assert held[1] <= held[0] + 8, held  # no growth (before: +160 over the last 40)
        assert held[1] <= 4 * DASK_LOG_LENGTH, held  # a few logs' worth (before: 320)
    finally:
        executor.close()
