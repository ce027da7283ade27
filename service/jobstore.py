"""The study jobs' store: SQLite for state, progress and summaries; Parquet files for points.

Every server process (``--workers N``) and every restart sees the same jobs: a job is a
row of one SQLite database (the standard library's ``sqlite3``, WAL journal, nothing to
configure) in the folder ``STUDY_STORE``; a study's raw points, when it asked for them
(``keep_points``), are one Parquet file beside it, written once when the study finishes,
so they leave the process's memory then and are streamed from disk by the downloads.

The quotas are checked and the job inserted in one write transaction (``BEGIN
IMMEDIATE``), so two processes cannot both take the last place. Disk: a study that keeps
its points reserves an estimate of its file (8 bytes a value) before a point is drawn;
the reservations and the files written count against ``STUDY_DISK_BYTES``.

A process beats for the jobs it runs (:meth:`JobStore.beat`, every ``BEAT_S``); an
unfinished job whose process stopped beating for ``stale_s`` (a restart, a killed worker)
is answered as failed, and no longer counts against a quota. The beat also carries a
cancel asked in another process (``DELETE`` reaches any worker) to the one that runs it.

Several hosts serving one API share a database server instead: ``JOB_STORE=postgresql://…``
selects :class:`PostgresJobStore`, the same interface and the same SQL on PostgreSQL
(psycopg 3, the optional extra ``[postgres]``); the points files stay under
``STUDY_STORE``, which those hosts must then share (a network file system).
"""

from __future__ import annotations

import json
import os
import sqlite3
import threading
import time
from collections.abc import Iterator
from contextlib import closing, contextmanager
from pathlib import Path
from typing import Any

#: How often a process writes its jobs' progress and reads the cancels asked of them [s].
BEAT_S = 0.25
ACTIVE = ("queued", "running")
_COLUMNS = {
    "id": "TEXT PRIMARY KEY",
    "model": "TEXT NOT NULL",
    "client": "TEXT NOT NULL",
    "total": "INTEGER NOT NULL",
    "keep_points": "INTEGER NOT NULL",
    "state": "TEXT NOT NULL",
    "phase": "TEXT NOT NULL",
    "done": "INTEGER NOT NULL DEFAULT 0",
    "created": "REAL NOT NULL",
    "started": "REAL",
    "finished": "REAL",
    "error": "TEXT",  # JSON
    "summary": "TEXT",  # JSON
    "points": "INTEGER NOT NULL DEFAULT 0",  # 1 when the points file is written
    "disk_bytes": "INTEGER NOT NULL DEFAULT 0",  # the file's size, or its reservation
    "owner": "TEXT NOT NULL",  # the process (Studies instance) running it
    "beat": "REAL NOT NULL",
    "cancel": "INTEGER NOT NULL DEFAULT 0",
}
_JSON = ("error", "summary")
#: What a job whose process stopped says, in place of a progress that never ends.
LOST = {
    "type": "study_lost",
    "msg": "the server process running this study stopped (a restart?); submit it again",
    "field": None,
}


#: Kept connections inherited through a fork: referenced, never closed, in the child.
_INHERITED: list[sqlite3.Connection] = []


class StoreError(sqlite3.DatabaseError):
    """The job store's database failed (a server gone, a lock not granted): whichever
    database holds the jobs, its errors reach the service as this DB-API error, which it
    reports and retries (``sqlite3.Error`` covers both)."""


class Full(Exception):
    """A quota (per client, in all, disk) has no room for the job: the message says which."""


class JobStore:
    """Jobs in ``folder/jobs.sqlite``, their points in ``folder/points/<job>.parquet``.

    Transactions open a connection each (:meth:`_db`); the readiness probe's read of the
    unfinished jobs (:meth:`active`, every poll of ``/readyz``) reuses one kept connection
    instead (:meth:`_read`), which saves the connection's opening, about half the CPU of
    a poll.
    """

    def __init__(self, folder: Path, disk_bytes: int, stale_s: float = 20.0) -> None:
        self.folder = folder
        self.files = folder / "points"
        self.files.mkdir(parents=True, exist_ok=True)
        self.path = folder / "jobs.sqlite"
        self.disk_bytes = disk_bytes
        self.stale_s = stale_s
        self._reader: sqlite3.Connection | None = None
        self._reader_of: tuple[int, int, int] = (0, 0, 0)  # (process, device, inode)
        self._reader_lock = threading.Lock()
        with closing(sqlite3.connect(self.path, timeout=30.0, isolation_level=None)) as db:
            db.execute("PRAGMA journal_mode=WAL")  # readers never wait for the writer
        with self._db(immediate=True) as db:
            columns = ", ".join(f"{k} {v}" for k, v in _COLUMNS.items())
            db.execute(f"CREATE TABLE IF NOT EXISTS jobs ({self._types(columns)})")
            db.execute("CREATE INDEX IF NOT EXISTS jobs_state ON jobs (state, client)")

    @contextmanager
    def _db(self, immediate: bool = False) -> Iterator[sqlite3.Connection]:
        """One connection for one transaction (cheap with SQLite; safe across threads and
        processes), committed on success."""
        with closing(sqlite3.connect(self.path, timeout=30.0, isolation_level=None)) as db:
            db.row_factory = sqlite3.Row
            db.execute("PRAGMA synchronous=NORMAL")
            db.execute("BEGIN IMMEDIATE" if immediate else "BEGIN")
            try:
                yield db
            except BaseException:
                db.execute("ROLLBACK")
                raise
            db.execute("COMMIT")

    @contextmanager
    def _read(self) -> Iterator[Any]:
        """The kept connection, for one read-only statement (autocommit: the statement is
        its own transaction, reading the last committed state; WAL: it never waits for a
        writer).

        One connection serves every thread (``check_same_thread=False``), one statement at
        a time under a lock: ``/readyz`` reads on the event loop, the studies' threads
        elsewhere. It is opened again in a process other than the one that opened it (a
        fork) and when ``jobs.sqlite`` is no longer the file it opened (deleted or
        replaced: a fresh connection then finds what a transaction would), and dropped
        after any database error, so a failing store fails every read, as a connection
        opened per read would, and a store that recovers is read afresh.
        """
        with self._reader_lock:
            try:
                stat = os.stat(self.path)
            except OSError as exc:
                self._close_reader()
                raise StoreError(f"the job store {self.path.name} cannot be read: {exc}") from exc
            of = (os.getpid(), stat.st_dev, stat.st_ino)
            if self._reader is None or self._reader_of != of:
                self._close_reader()
                self._reader = sqlite3.connect(
                    self.path, timeout=30.0, isolation_level=None, check_same_thread=False
                )
                self._reader.row_factory = sqlite3.Row
                self._reader_of = of
            try:
                yield self._reader
            except sqlite3.Error:
                self._close_reader()
                raise

    def _close_reader(self) -> None:
        """Close the kept connection; one a parent opened before a fork is kept unclosed
        (closing its file here would release the parent's locks on the database)."""
        reader, self._reader = self._reader, None
        if reader is not None and self._reader_of[0] == os.getpid():
            reader.close()
        elif reader is not None:
            _INHERITED.append(reader)

    def close(self) -> None:
        """Close the kept read connection (a later read opens it again)."""
        with self._reader_lock:
            self._close_reader()

    @staticmethod
    def _types(columns: str) -> str:
        """The table's column types in this database's names."""
        return columns

    def points_path(self, job_id: str) -> Path:
        return self.files / f"{job_id}.parquet"

    @staticmethod
    def _row(row: Any) -> dict[str, Any]:
        out = dict(row)
        for key in _JSON:
            out[key] = None if out[key] is None else json.loads(out[key])
        out["keep_points"] = bool(out["keep_points"])
        return out

    def _live(self, now: float) -> str:
        """SQL: an unfinished job whose process still beats."""
        return f"state IN {ACTIVE!r} AND beat > {now - self.stale_s!r}"

    def put(self, job: dict[str, Any]) -> None:
        """Insert or replace a job (its fields as :data:`_COLUMNS` names them)."""
        row = {k: job.get(k) for k in _COLUMNS}
        for key in _JSON:
            row[key] = None if row[key] is None else json.dumps(row[key])
        for key in ("done", "points", "disk_bytes", "cancel"):
            row[key] = int(row[key] or 0)
        with self._db() as db:
            names = ", ".join(row)
            marks = ", ".join("?" for _ in row)
            db.execute("DELETE FROM jobs WHERE id = ?", (row["id"],))
            db.execute(f"INSERT INTO jobs ({names}) VALUES ({marks})", list(row.values()))

    def admit(self, job: dict[str, Any], *, per_client: int, max_active: int) -> None:
        """Insert ``job`` if the client, the server and the disk have room; else :class:`Full`.

        One write transaction: a concurrent admission in another process waits for it.
        """
        now = time.time()
        with self._db(immediate=True) as db:
            live = self._live(now)
            active = db.execute(f"SELECT count(*) AS n FROM jobs WHERE {live}").fetchone()["n"]
            mine = db.execute(
                f"SELECT count(*) AS n FROM jobs WHERE {live} AND client = ?", (job["client"],)
            ).fetchone()["n"]
            if mine >= per_client or active >= max_active:
                raise Full(
                    f"{mine} of your studies and {active} in all are running "
                    f"(limits {per_client} per client, {max_active} in all); retry when one "
                    "finishes or cancel one"
                )
            need = int(job.get("disk_bytes") or 0)
            if need:
                # int(): PostgreSQL sums a bigint column as numeric (a Decimal)
                total = "SELECT coalesce(sum(disk_bytes), 0) AS n FROM jobs"
                used = int(db.execute(total).fetchone()["n"])
                if used + need > self.disk_bytes:
                    raise Full(
                        f"keeping this study's points needs about {need / 1e6:.0f} MB and the "
                        f"job store has {max(0, self.disk_bytes - used) / 1e6:.0f} MB free of "
                        f"{self.disk_bytes / 1e6:.0f} MB (STUDY_DISK_BYTES); retry when older "
                        "jobs expire, delete one, or run it without keep_points"
                    )
            row = {k: job.get(k) for k in _COLUMNS}
            row.update(beat=now, created=now, cancel=0, points=0, done=0)
            for key in _JSON:
                row[key] = None if row[key] is None else json.dumps(row[key])
            names, marks = ", ".join(row), ", ".join("?" for _ in row)
            db.execute(f"INSERT INTO jobs ({names}) VALUES ({marks})", list(row.values()))

    def update(self, job_id: str, **fields: Any) -> None:
        if not fields:
            return
        values = [json.dumps(v) if k in _JSON and v is not None else v for k, v in fields.items()]
        sets = ", ".join(f"{k} = ?" for k in fields)
        with self._db() as db:
            db.execute(f"UPDATE jobs SET {sets} WHERE id = ?", [*values, job_id])

    def get(self, job_id: str) -> dict[str, Any] | None:
        """The job, or None; an unfinished one whose process stopped beating is failed here."""
        now = time.time()
        with self._db() as db:
            row = db.execute("SELECT * FROM jobs WHERE id = ?", (job_id,)).fetchone()
            if row is None:
                return None
            job = self._row(row)
            if job["state"] in ACTIVE and job["beat"] <= now - self.stale_s:
                job.update(state="failed", error=LOST, finished=now)
                db.execute(
                    "UPDATE jobs SET state = 'failed', error = ?, finished = ? WHERE id = ?",
                    (json.dumps(LOST), now, job_id),
                )
        return job

    def active(self) -> list[dict[str, Any]]:
        """The unfinished jobs of every live process (without their summaries)."""
        with self._read() as db:
            rows = db.execute(
                f"SELECT id, client, state, owner FROM jobs WHERE {self._live(time.time())}"
            ).fetchall()
        return [dict(r) for r in rows]

    def remove(self, job_id: str) -> None:
        """Forget a job and delete its points file."""
        with self._db() as db:
            db.execute("DELETE FROM jobs WHERE id = ?", (job_id,))
        self.points_path(job_id).unlink(missing_ok=True)

    def prune(self, keep_s: float, keep_jobs: int) -> None:
        """Remove finished jobs older than ``keep_s`` and all but the newest ``keep_jobs``
        finished ones, with their files."""
        now = time.time()
        with self._db() as db:
            finished = db.execute(
                f"SELECT id, finished FROM jobs WHERE state NOT IN {ACTIVE!r} "
                "ORDER BY finished DESC, created DESC"
            ).fetchall()
            gone = [
                r["id"]
                for i, r in enumerate(finished)
                if i >= keep_jobs or now - (r["finished"] or now) > keep_s
            ]
            db.executemany("DELETE FROM jobs WHERE id = ?", [(g,) for g in gone])
        for job_id in gone:
            self.points_path(job_id).unlink(missing_ok=True)

    def beat(self, owner: str, progress: list[tuple[str, int, str]]) -> set[str]:
        """Write the progress ``(job, done, phase)`` of the jobs ``owner`` runs and mark them
        alive; answer those of them a cancel was asked of (here or in another process)."""
        now = time.time()
        with self._db() as db:
            db.executemany(
                "UPDATE jobs SET beat = ?, done = ?, phase = ? "
                f"WHERE id = ? AND state IN {ACTIVE!r}",
                [(now, done, phase, job_id) for job_id, done, phase in progress],
            )
            rows = db.execute(
                "SELECT id FROM jobs WHERE owner = ? AND cancel = 1", (owner,)
            ).fetchall()
        return {r["id"] for r in rows}

    def ask_cancel(self, job_id: str) -> dict[str, Any] | None:
        """Ask the process running ``job_id`` to stop it; a job still queued is cancelled
        here at once. Answers the job as it stands."""
        now = time.time()
        with self._db(immediate=True) as db:
            db.execute("UPDATE jobs SET cancel = 1 WHERE id = ?", (job_id,))
            db.execute(
                "UPDATE jobs SET state = 'cancelled', finished = ? "
                "WHERE id = ? AND state = 'queued'",
                (now, job_id),
            )
        return self.get(job_id)


class _Postgres:
    """A psycopg connection that takes the store's SQL as written for SQLite (``?`` marks)."""

    def __init__(self, conn: Any) -> None:
        self.conn = conn

    def execute(self, sql: str, params: Any = ()) -> Any:
        return self.conn.execute(sql.replace("?", "%s"), params)

    def executemany(self, sql: str, params: Any) -> None:
        with self.conn.cursor() as cur:
            cur.executemany(sql.replace("?", "%s"), params)


#: The advisory lock that serialises the store's writers on PostgreSQL, as ``BEGIN
#: IMMEDIATE`` does on SQLite (an arbitrary number of this store's own).
_PG_LOCK = 3_402_026


class PostgresJobStore(JobStore):
    """Jobs in a PostgreSQL database (``url``), their points in ``folder/points``.

    The interface, the SQL and the semantics of :class:`JobStore`: an admission holds the
    store's transaction lock (``pg_advisory_xact_lock``) as SQLite's ``BEGIN IMMEDIATE``
    does, so two hosts cannot both take the last place; times are double precision.
    """

    def __init__(self, url: str, folder: Path, disk_bytes: int, stale_s: float = 20.0) -> None:
        try:
            import psycopg  # noqa: F401
        except ImportError:
            raise ValueError(
                "JOB_STORE=postgresql://… needs psycopg: pip install 'tightening-calc[postgres]'"
            ) from None
        self.url = url
        self.folder = folder
        self.files = folder / "points"
        self.files.mkdir(parents=True, exist_ok=True)
        self.disk_bytes = disk_bytes
        self.stale_s = stale_s
        with self._db(immediate=True) as db:
            columns = ", ".join(f"{k} {v}" for k, v in _COLUMNS.items())
            db.execute(f"CREATE TABLE IF NOT EXISTS jobs ({self._types(columns)})")
            db.execute("CREATE INDEX IF NOT EXISTS jobs_state ON jobs (state, client)")

    @contextmanager
    def _read(self) -> Iterator[Any]:
        """A connection of its own for the read (as :meth:`_db`): a kept psycopg connection
        would need reconnecting after a server restart, which this store does not do."""
        with self._db() as db:
            yield db

    def close(self) -> None:
        """Nothing kept open."""

    @staticmethod
    def _types(columns: str) -> str:
        # PostgreSQL's REAL is single precision and its INTEGER 32 bits: times need double
        # precision, disk sizes beyond 2 GB a bigint
        return columns.replace("REAL", "DOUBLE PRECISION").replace("INTEGER", "BIGINT")

    @contextmanager
    def _db(self, immediate: bool = False) -> Iterator[Any]:
        """One connection for one transaction, committed on success, rolled back on error."""
        import psycopg
        from psycopg.rows import dict_row

        try:
            with psycopg.connect(self.url, row_factory=dict_row, connect_timeout=10) as conn:
                if immediate:
                    conn.execute("SELECT pg_advisory_xact_lock(%s)", (_PG_LOCK,))
                yield _Postgres(conn)
        except psycopg.Error as exc:
            raise StoreError(f"{type(exc).__name__}: {exc}") from exc


def open_store(
    folder: Path, disk_bytes: int, url: str | None = None, stale_s: float = 20.0
) -> JobStore:
    """The job store ``JOB_STORE`` names (``url`` when given): empty for SQLite in
    ``folder`` (the default, nothing to configure), ``postgresql://…`` for a database
    server that several hosts share; anything else stops the service at start-up.

    >>> import tempfile
    >>> type(open_store(Path(tempfile.mkdtemp()), 10**6, url="")).__name__
    'JobStore'
    >>> open_store(Path(tempfile.mkdtemp()), 10**6, url="mysql://db/jobs")
    Traceback (most recent call last):
    ...
    ValueError: JOB_STORE must be empty (SQLite in STUDY_STORE) or a postgresql:// URL, not 'mysql://...'
    """
    url = os.environ.get("JOB_STORE", "") if url is None else url
    if not url:
        return JobStore(folder, disk_bytes, stale_s)
    if url.startswith(("postgresql://", "postgres://")):
        return PostgresJobStore(url, folder, disk_bytes, stale_s)
    shown = url.split("//", 1)[0] + "//..." if "//" in url else "..."  # never a password
    raise ValueError(
        f"JOB_STORE must be empty (SQLite in STUDY_STORE) or a postgresql:// URL, not {shown!r}"
    )
