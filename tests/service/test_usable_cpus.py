"""Worker counts from the CPUs the process may really use, not the host's count.

A container limited to 2 CPUs on a 64-CPU host started 64 Dask workers (~12 GB). The
count comes from the process's affinity capped by its cgroup's CPU quota (v2 ``cpu.max``,
v1 ``cpu.cfs_quota_us / cpu.cfs_period_us``), read here from fake cgroup trees.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

import service.config
import service.studies
from service.config import Settings, cgroup_cpus, cgroup_memory, usable_cpus, usable_memory
from service.studies import Studies, StudySettings

AFFINITY = len(os.sched_getaffinity(0))


def _tree(tmp_path: Path, files: dict[str, str], self_cgroup: str) -> tuple[Path, Path]:
    root = tmp_path / "cgroup"
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)
    proc = tmp_path / "self_cgroup"
    proc.write_text(self_cgroup)
    return root, proc


@pytest.mark.parametrize(
    ("files", "self_cgroup", "cpus"),
    [
        # cgroup v2 at the namespace root: 2 CPUs (200 ms per 100 ms period)
        ({"cpu.max": "200000 100000\n"}, "0::/\n", 2.0),
        # v2, unlimited
        ({"cpu.max": "max 100000\n"}, "0::/\n", None),
        # v2 nested: the group allows 1.5 CPUs, its parent 4: the smaller holds
        (
            {"cpu.max": "max 100000", "a/cpu.max": "400000 100000", "a/b/cpu.max": "150000 100000"},
            "0::/a/b\n",
            1.5,
        ),
        # v1: quota and period in two files under cpu/
        (
            {"cpu/cpu.cfs_quota_us": "300000\n", "cpu/cpu.cfs_period_us": "100000\n"},
            "4:cpu,cpuacct:/\n0::/\n",
            3.0,
        ),
        # v1 in a container: /proc/self/cgroup names the host's path, absent inside
        (
            {"cpu,cpuacct/cpu.cfs_quota_us": "50000", "cpu,cpuacct/cpu.cfs_period_us": "100000"},
            "4:cpuacct,cpu:/docker/0123abcd\n",
            0.5,
        ),
        # v1, no quota
        ({"cpu/cpu.cfs_quota_us": "-1", "cpu/cpu.cfs_period_us": "100000"}, "2:cpu:/\n", None),
        # garbage and nothing at all: no quota
        ({"cpu.max": "lots\n"}, "0::/\n", None),
        ({}, "", None),
    ],
)
def test_the_quota_is_read_from_cgroup_files(
    tmp_path: Path, files: dict[str, str], self_cgroup: str, cpus: float | None
) -> None:
    root, proc = _tree(tmp_path, files, self_cgroup)
    assert cgroup_cpus(root, proc) == cpus


@pytest.mark.parametrize(("quota", "expected"), [("200000 100000", 2), ("50000 100000", 1)])
def test_the_count_is_the_affinity_capped_by_the_quota_rounded_up(
    tmp_path: Path, quota: str, expected: int
) -> None:
    root, proc = _tree(tmp_path, {"cpu.max": quota}, "0::/\n")
    assert usable_cpus(root, proc) == min(AFFINITY, expected)
    # a quota of 64 CPUs does not raise the count above the CPUs the process may run on
    root, proc = _tree(tmp_path, {"cpu.max": "6400000 100000"}, "0::/\n")
    assert usable_cpus(root, proc) == AFFINITY


def test_the_affinity_not_the_host_count_without_a_quota(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1, 2})
    monkeypatch.setattr(os, "cpu_count", lambda: 64)
    assert usable_cpus(tmp_path / "none", tmp_path / "none") == 3


def test_the_dask_workers_and_the_heavy_lane_follow_the_usable_cpus(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(service.config, "usable_cpus", lambda: 2)
    monkeypatch.setattr(service.studies, "usable_cpus", lambda: 2)
    for name in ("HEAVY_SLOTS", "HEAVY_PER_CLIENT", "DASK_WORKERS"):
        monkeypatch.delenv(name, raising=False)
    settings = Settings()
    assert settings.heavy_slots == 2 and settings.heavy_per_client == 1
    studies = Studies(StudySettings())
    try:
        assert studies.dask().n_workers == 2  # the cluster itself starts on first use
        monkeypatch.setenv("DASK_WORKERS", "5")
        explicit = Studies(StudySettings())
        assert explicit.dask().n_workers == 5
        explicit.shutdown()
    finally:
        studies.shutdown()


@pytest.mark.parametrize(
    ("files", "self_cgroup", "limit"),
    [
        ({"memory.max": "4294967296\n"}, "0::/\n", 4 * 2**30),  # v2: 4 GiB
        ({"memory.max": "max\n"}, "0::/\n", None),
        # v2 nested: the parent's 2 GiB holds below the group's 8 GiB
        ({"a/memory.max": str(2 * 2**30), "a/b/memory.max": str(8 * 2**30)}, "0::/a/b\n", 2**31),
        # v1, and v1's "no limit" (a page-rounded 2^63 - 1)
        ({"memory/memory.limit_in_bytes": "1073741824"}, "9:memory:/\n", 2**30),
        ({"memory/memory.limit_in_bytes": "9223372036854771712"}, "9:memory:/\n", None),
        ({}, "", None),
    ],
)
def test_the_memory_limit_is_read_from_cgroup_files(
    tmp_path: Path, files: dict[str, str], self_cgroup: str, limit: int | None
) -> None:
    root, proc = _tree(tmp_path, files, self_cgroup)
    assert cgroup_memory(root, proc) == limit
    physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    assert usable_memory(root, proc) == min(physical, limit or physical)


def test_the_dask_workers_memory_follows_the_usable_memory(monkeypatch: pytest.MonkeyPatch) -> None:
    """2 CPUs and 4 GiB in a container: two workers of 1 GiB each (half the memory), not
    Dask's default share of the host's memory."""
    monkeypatch.setattr(service.studies, "usable_cpus", lambda: 2)
    monkeypatch.setattr(service.studies, "usable_memory", lambda: 4 * 2**30)
    for name in ("DASK_WORKERS", "DASK_WORKER_MEMORY"):
        monkeypatch.delenv(name, raising=False)
    studies = Studies(StudySettings())
    assert (studies.dask().n_workers, studies.dask().memory_limit) == (2, 2**30)
    studies.shutdown()
    monkeypatch.setenv("DASK_WORKER_MEMORY", str(3 * 2**29))
    explicit = Studies(StudySettings())
    assert explicit.dask().memory_limit == 3 * 2**29
    explicit.shutdown()
