"""The job store's contract, held by both stores: SQLite (the default) and PostgreSQL.

Issue 34: several hosts serving one API need a database server they share;
``JOB_STORE=postgresql://…`` selects :class:`~service.jobstore.PostgresJobStore`, the same
interface as the SQLite store. Each contract test runs against both: against a real
PostgreSQL this module starts in a temporary folder when ``initdb``, ``pg_ctl`` and
psycopg are found (``pip install -e '.[postgres]'``), and is skipped, saying why, where
they are not (CI does not depend on PostgreSQL).
"""

from __future__ import annotations

import glob
import os
import pwd
import shutil
import subprocess
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.jobstore import LOST, Full, JobStore, PostgresJobStore, StoreError, open_store
from service.studies import Job, StudySettings
from tests.service.servers import free_port
from tests.toys import TOY

Store = Callable[..., JobStore]


def _postgres_bin() -> Path | None:
    found = shutil.which("initdb")
    if found:
        return Path(found).resolve().parent
    versions = sorted(glob.glob("/usr/lib/postgresql/*/bin/initdb"))
    return Path(versions[-1]).parent if versions else None


@pytest.fixture(scope="module")
def postgres() -> Iterator[str]:
    """A PostgreSQL server of this module's own, on a Unix socket in a temporary folder."""
    pytest.importorskip("psycopg", reason="psycopg not installed (the [postgres] extra)")
    bin_dir = _postgres_bin()
    if bin_dir is None:
        pytest.skip("no PostgreSQL here (initdb, pg_ctl not on PATH nor in /usr/lib/postgresql)")
    # a folder of its own under the system's temporary directory (pytest's are private to
    # this user, and the server may run as another)
    root = Path(tempfile.mkdtemp(prefix="job-store-postgres-"))
    data, sockets = root / "data", root / "run"
    sockets.mkdir()
    user: dict[str, Any] = {}
    if os.geteuid() == 0:  # initdb refuses root: run the server as the postgres user
        try:
            entry = pwd.getpwnam("postgres")
        except KeyError:
            pytest.skip("running as root and there is no postgres user to run PostgreSQL as")
        os.chown(root, entry.pw_uid, entry.pw_gid)
        os.chown(sockets, entry.pw_uid, entry.pw_gid)
        user = {"user": entry.pw_uid, "group": entry.pw_gid}
    run = {"check": True, "capture_output": True, "text": True, "timeout": 120, **user}
    subprocess.run(
        [bin_dir / "initdb", "-D", data, "-U", "postgres", "--auth=trust", "-E", "UTF8"], **run
    )
    port = free_port()
    options = f"-k {sockets} -p {port} -c listen_addresses=''"
    log = root / "log"
    subprocess.run([bin_dir / "pg_ctl", "-D", data, "-l", log, "-o", options, "-w", "start"], **run)
    try:
        yield f"postgresql://postgres@/postgres?host={sockets}&port={port}"
    finally:
        subprocess.run([bin_dir / "pg_ctl", "-D", data, "-m", "immediate", "stop"], **run)
        shutil.rmtree(root, ignore_errors=True)


@pytest.fixture(params=["sqlite", "postgresql"])
def store(request: pytest.FixtureRequest, tmp_path: Path) -> Store:
    """Make a store on one database (two calls: two server processes on the same jobs)."""
    if request.param == "sqlite":
        return lambda disk=10**9, stale_s=20.0: JobStore(tmp_path, disk, stale_s)
    url = request.getfixturevalue("postgres")
    import psycopg

    with psycopg.connect(url, autocommit=True) as conn:  # each test its own empty table
        conn.execute("DROP TABLE IF EXISTS jobs")
    return lambda disk=10**9, stale_s=20.0: PostgresJobStore(url, tmp_path, disk, stale_s)


def _job(job_id: str, client: str, state: str = "running", disk: int = 0) -> dict[str, Any]:
    job = Job(job_id, "toy.disc", client, 10, bool(disk), state=state)
    job.disk_bytes = disk
    return job.row("p")


def test_two_processes_share_the_quotas(store: Store) -> None:
    a, b = store(), store()
    a.admit(_job("j1", "alice"), per_client=1, max_active=3)
    with pytest.raises(Full, match="1 of your studies and 1 in all"):
        b.admit(_job("j2", "alice"), per_client=1, max_active=3)
    b.admit(_job("j3", "bob"), per_client=1, max_active=3)
    b.admit(_job("j4", "carol"), per_client=1, max_active=3)
    with pytest.raises(Full, match="0 of your studies and 3 in all"):
        a.admit(_job("j5", "dave"), per_client=1, max_active=3)
    assert {j["id"] for j in a.active()} == {"j1", "j3", "j4"}
    assert (b.get("j1") or {})["client"] == "alice" and b.get("j2") is None


def test_the_disk_quota_counts_reservations_and_files(store: Store) -> None:
    s = store(disk=1000)
    s.admit(_job("a", "alice", disk=600), per_client=5, max_active=5)
    with pytest.raises(Full, match="needs about 0 MB and the job store has 0 MB free"):
        s.admit(_job("b", "bob", disk=500), per_client=5, max_active=5)
    s.update("a", state="done", disk_bytes=300, finished=time.time())  # the file's size
    s.admit(_job("b", "bob", disk=500), per_client=5, max_active=5)  # 300 + 500 ≤ 1000


def test_a_stopped_process_s_job_is_failed_and_a_beat_carries_cancels(store: Store) -> None:
    s = store(stale_s=0.3)
    s.admit(_job("lost", "alice"), per_client=1, max_active=1)
    time.sleep(0.4)  # no beat: the process running it is gone
    s.admit(_job("next", "alice"), per_client=1, max_active=1)
    lost = s.get("lost")
    assert lost is not None and lost["state"] == "failed" and lost["error"] == LOST
    s.ask_cancel("next")
    assert s.beat("p", [("next", 5, "evaluating")]) == {"next"}
    again = s.get("next")
    assert again is not None and (again["done"], again["phase"]) == (5, "evaluating")


def test_records_round_trip_and_finished_jobs_are_pruned(store: Store) -> None:
    s = store()
    summary = {"outputs": {"energy": {"mean": 1.25, "q": [0.5, 2.0]}}, "n": 10}
    for i, finished in enumerate((1.0, time.time() - 10, time.time())):
        row = _job(f"f{i}", "alice", state="done")
        row.update(summary=summary, finished=finished, points=1, created=1.5 + i)
        s.put(row)
        s.points_path(f"f{i}").write_bytes(b"x")
    s.put({**_job("f2", "alice", state="done"), "finished": time.time(), "summary": summary})
    got = s.get("f2")
    assert got is not None and got["summary"] == summary and got["keep_points"] is False
    assert isinstance(got["created"], float) and got["finished"] > 1.7e9  # double precision
    s.prune(keep_s=60.0, keep_jobs=1)  # f0 is too old, f1 beyond the newest one
    assert [s.get(f"f{i}") is not None for i in range(3)] == [False, False, True]
    assert sorted(p.name for p in s.files.iterdir()) == ["f2.parquet"]
    s.remove("f2")
    assert s.get("f2") is None and list(s.files.iterdir()) == []


def test_job_store_names_the_database(tmp_path: Path, postgres: str) -> None:
    """``JOB_STORE`` selects PostgreSQL; a study run by one app there is answered, with its
    points, by another app on the same database (another host, or a restart)."""
    assert isinstance(open_store(tmp_path, 10**6, url=postgres), PostgresJobStore)
    with pytest.raises(StoreError):  # a server that is not there: the store's error
        open_store(tmp_path, 10**6, url="postgresql://postgres@/x?host=/nonexistent&port=1")
    body = {
        "base": {"diameter": 0.3},
        "variables": [{"name": "mass", "low": 1, "high": 2}],
        "samples": 20,
        "fidelity": "exact",
        "outputs": ["energy"],
        "keep_points": True,
    }
    settings = StudySettings(store=str(tmp_path), inprocess_points=10**6)
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("JOB_STORE", postgres)
        with TestClient(create_app(models=[TOY], study_settings=settings)) as first:
            job = first.post("/api/v1/toy/disc/study", json=body).json()["job"]
            deadline = time.monotonic() + 60
            while (state := first.get(f"/api/v1/jobs/{job}").json())["state"] != "done":
                assert time.monotonic() < deadline and state["state"] in ("queued", "running"), (
                    state
                )
                time.sleep(0.05)
        with TestClient(create_app(models=[TOY], study_settings=settings)) as second:
            again = second.get(f"/api/v1/jobs/{job}").json()
            assert again["result"] == state["result"]
            csv = second.get(again["links"]["points_csv"]).text.splitlines()
            assert len(csv) == 21 and csv[0] == "mass,energy"
    assert not (tmp_path / "jobs.sqlite").exists()  # nothing went to SQLite
