"""/readyz reads the unfinished jobs through one kept SQLite connection, and still says
when the job store cannot be read.

Issue 35: each poll opened a new connection (about half of a poll's CPU). The kept one is
shared by every thread under a lock; it is opened again when ``jobs.sqlite`` is deleted or
replaced and dropped after a database error, so /readyz is 503 "store_error" (not a 500)
while the store fails and ready again once it recovers.
"""

from __future__ import annotations

import shutil
import sqlite3
import threading
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.jobstore import JobStore, StoreError
from service.studies import Job, StudySettings
from tests.toys import TOY


def _job(job_id: str, state: str = "running") -> dict[str, Any]:
    return Job(job_id, TOY.name, "client", 10, False, state=state).row("p")


def test_readyz_is_503_while_the_store_cannot_be_read_and_ready_once_it_can(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("WARM_UP", "0")
    settings = StudySettings(store=str(tmp_path))
    with TestClient(create_app(models=[TOY], study_settings=settings)) as client:
        store = client.app.state.studies.store  # type: ignore[attr-defined]
        assert client.get("/readyz").json()["studies"]["active"] == 0
        store.put(_job("a"))
        assert client.get("/readyz").json()["studies"]["active"] == 1
        with sqlite3.connect(store.path) as db:  # another process breaks the table
            db.execute("DROP TABLE jobs")
        broken = client.get("/readyz")
        assert broken.status_code == 503 and broken.headers["retry-after"] == "1"
        body = broken.json()
        assert body["status"] == "store_error"
        assert body["studies"]["active"] is None
        assert body["studies"]["store_error"] == "OperationalError: no such table: jobs"
        assert client.get("/healthz").status_code == 200  # alive, not ready
        JobStore(tmp_path, 10**9)  # the table made again (a restore)
        again = client.get("/readyz")
        assert again.status_code == 200 and again.json()["status"] == "ready"
        assert "store_error" not in again.json()["studies"]
        assert again.json()["studies"]["active"] == 0
        for name in ("jobs.sqlite", "jobs.sqlite-wal", "jobs.sqlite-shm"):
            (tmp_path / name).unlink(missing_ok=True)  # the database deleted
        gone = client.get("/readyz")
        assert gone.status_code == 503
        assert gone.json()["studies"]["store_error"].startswith(
            "StoreError: the job store jobs.sqlite cannot be read"
        )


def test_the_kept_connection_is_reused_by_every_thread(tmp_path: Path) -> None:
    store = JobStore(tmp_path, 10**9)
    store.active()
    kept = store._reader
    assert kept is not None
    counts: list[list[int]] = [[] for _ in range(4)]
    errors: list[BaseException] = []

    def read(seen: list[int]) -> None:
        try:
            for _ in range(50):
                seen.append(len(store.active()))
        except BaseException as exc:  # a connection used across threads would raise
            errors.append(exc)

    readers = [threading.Thread(target=read, args=(seen,)) for seen in counts]
    for t in readers:
        t.start()
    for i in range(20):  # written meanwhile through the per-transaction connections
        store.put(_job(f"j{i}"))
    for t in readers:
        t.join()
    assert errors == []
    for seen in counts:  # each thread reads 50 times, never a write undone
        assert len(seen) == 50 and seen == sorted(seen) and seen[-1] <= 20
    assert store._reader is kept  # one connection served all four threads
    assert len(store.active()) == 20  # every committed write is read
    store.close()
    assert store._reader is None
    assert len(store.active()) == 20  # opened again


def test_a_replaced_database_is_read_not_the_file_the_connection_opened(tmp_path: Path) -> None:
    here, other = tmp_path / "here", tmp_path / "other"
    store, restored = JobStore(here, 10**9), JobStore(other, 10**9)
    store.put(_job("old"))
    assert [j["id"] for j in store.active()] == ["old"]
    for i in range(3):
        restored.put(_job(f"new{i}"))
    with sqlite3.connect(restored.path) as db:
        db.execute("PRAGMA wal_checkpoint(TRUNCATE)")  # the backup whole in its main file
    for name in ("jobs.sqlite-wal", "jobs.sqlite-shm"):
        (here / name).unlink(missing_ok=True)
    shutil.copy(restored.path, here / "restore.tmp")
    (here / "restore.tmp").replace(store.path)  # a restore: a new file under the same name
    assert sorted(j["id"] for j in store.active()) == ["new0", "new1", "new2"]


def test_a_failed_read_drops_the_connection(tmp_path: Path) -> None:
    store = JobStore(tmp_path, 10**9)
    store.active()
    with sqlite3.connect(store.path) as db:
        db.execute("DROP TABLE jobs")
    with pytest.raises(sqlite3.OperationalError, match="no such table"):
        store.active()
    assert store._reader is None
    store.path.unlink()
    with pytest.raises(StoreError, match="cannot be read"):
        store.active()
