"""Issue 34's shop-floor figures, taken against a started service as a user starts it.

Each figure starts ``python -m service`` on a free loopback port with the embedded
defaults (a job store in a temporary folder of its own, nothing else set) and drives it
over HTTP, as the reproductions of issue 34 did; ``--scale 1.0`` is the issue's full
size, a smaller scale shrinks point counts, sockets and durations (the slow tests in
tests/service hold scaled-down versions with bounds). Each figure carries the machine's
1-minute load average when it was taken (the machine may be shared: a figure's times are
wall times and grow with the load; CPU times are the service process's own).

* ``memory``: the service's RSS after ten finished 1,000,000-point joint studies (was
  351 MB → 3.4 GB after three 2,000,000-point ones), and after DELETE of all ten;
* ``refused``: the cost of a submission refused by the per-client limit (was eight
  2,000,000-point refusals: 56 s of CPU, 5.6 GB);
* ``csv``: the CSV of a 1,000,000-point study, its size, time and the RSS it adds, and
  ``/healthz`` latency meanwhile (was 861 MB, 43 s, +3 GB, stalls up to 1.4 s);
* ``flood``: 1,000 sockets from one address trickling request bodies a byte every 2–4 s
  for 40 s, and another client's success rate meanwhile (was 503 for all of it);
* ``lookups``: job lookups with ``--workers 2`` and after a restart (was about half 404,
  and a restart lost every job);
* ``delete``: time from DELETE of a running simulation study to idle Dask workers (was
  about 50 s);
* ``fairness``: a second client's 2,500-point study beside a 100,000-point one (was no
  progress for 60 s), and beside two large studies of one client.

Run: ``PYTHONPATH=. python -m bench.shopfloor [--scale 1.0] [--only memory,csv]
[--out bench/shopfloor.json]``. Figures print as they are taken; the JSON gathers them.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import random
import select
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import httpx

from bench.cold_start import free_port

ROOT = Path(__file__).resolve().parents[1]
API = "/api/v1"
JOINT = f"{API}/joint/vdi2230/study"
RARE = f"{API}/impact/rare/study"
MB = 1e6

#: Today's figures, from issue 34's "Why" (the service at base 862a898 and after).
BEFORE = {
    "memory": "351 MB -> 3.4 GB after three 2,000,000-point joint studies (raw values kept "
    "an hour whatever keep_points said; DELETE freed nothing)",
    "refused": "eight refused 2,000,000-point submissions: 56 s of CPU and 5.6 GB before "
    "their 503s (every one drew its points first)",
    "csv": "861 MB in 43 s, +3 GB RSS; /healthz stalls up to 1.4 s",
    "flood": "1,000 trickling sockets: every other client 503 for the whole 40 s",
    "lookups": "--workers 2: about half of lookups 404; a restart lost every job",
    "delete": "workers kept computing about 50 s after DELETE",
    "fairness": "another client's 2,500-point study: no progress for 60 s behind a "
    "100,000-point one",
}


def load() -> float:
    return round(os.getloadavg()[0], 2)


def rss_mb(pid: int) -> float:
    """A process's resident memory [MB], from /proc (0 once it is gone)."""
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024 / MB
    except OSError:
        pass
    return 0.0


def cpu_s(pid: int) -> float:
    """A process's user + system CPU time [s], from /proc (0 once it is gone)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    except OSError:
        return 0.0
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def descendants(pid: int) -> list[int]:
    """Every process started by ``pid``, and by those, from /proc."""
    parents: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                ppid = int((entry / "stat").read_text().rpartition(")")[2].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            parents.setdefault(ppid, []).append(int(entry.name))
    found, todo = [], [pid]
    while todo:
        for child in parents.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


class Service:
    """``python -m service`` on a free port, its job store in ``store``, its output in a
    log file; stopped with SIGTERM (killed after 30 s) on exit."""

    def __init__(self, store: Path, *args: str, env: dict[str, str] | None = None) -> None:
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.log = open(store.parent / f"service-{self.port}.log", "w")  # noqa: SIM115
        environ = {**os.environ, "PYTHONPATH": str(ROOT), "STUDY_STORE": str(store), **(env or {})}
        self.popen = subprocess.Popen(
            [sys.executable, "-m", "service", "--port", str(self.port), *args],
            cwd=ROOT,
            env=environ,
            stdout=self.log,
            stderr=subprocess.STDOUT,
        )
        self.pid = self.popen.pid
        start = time.monotonic()
        while True:
            try:
                if httpx.get(self.url + "/readyz", timeout=2).status_code == 200:
                    break
            except httpx.HTTPError:
                pass
            if self.popen.poll() is not None or time.monotonic() - start > 300:
                self.stop()
                raise RuntimeError(f"the service did not start: see {self.log.name}")
            time.sleep(0.2)
        self.start_s = time.monotonic() - start

    def rss(self) -> float:
        """The service process's resident memory [MB] (its Dask workers are apart)."""
        return rss_mb(self.pid)

    def tree_rss(self) -> float:
        """The service and every process it started (Dask workers) [MB]."""
        return sum(rss_mb(p) for p in [self.pid, *descendants(self.pid)])

    def cpu(self) -> float:
        """The service process's CPU time so far [s]."""
        return cpu_s(self.pid)

    def workers_cpu(self) -> float:
        """The CPU time of every process the service started (Dask workers) [s]."""
        return sum(cpu_s(p) for p in descendants(self.pid))

    def stop(self) -> None:
        if self.popen.poll() is None:
            self.popen.send_signal(signal.SIGTERM)
            try:
                self.popen.wait(30)
            except subprocess.TimeoutExpired:
                self.popen.kill()
                self.popen.wait()
        self.log.close()

    def __enter__(self) -> Service:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()


def client(url: str, source: str = "127.0.0.1", timeout: float = 60.0) -> httpx.Client:
    """An HTTP client whose connections come from ``source`` (127.x.y.z: another client)."""
    transport = httpx.HTTPTransport(local_address=source)
    return httpx.Client(base_url=url, transport=transport, timeout=timeout)


def joint_study(samples: int, keep_points: bool = False, seed: int = 0) -> dict[str, Any]:
    return {
        "base": {"thread_diameter": 0.012, "plate1_thickness": 0.02, "plate2_thickness": 0.02},
        "variables": [
            {"name": "working_load", "low": 5000, "high": 10000},
            {"name": "transverse_load", "low": 1000, "high": 3000},
        ],
        "samples": samples,
        "seed": seed,
        "keep_points": keep_points,
    }


def rare_study(samples: int, seed: int = 0) -> dict[str, Any]:
    """The rare-impact striker's simulation: about 1 ms of CPU a point, 256 a chunk."""
    return {
        "variables": [{"name": "motor_torque", "low": 4.5, "high": 5.5}],
        "samples": samples,
        "seed": seed,
        "fidelity": "simulation",
        "outputs": ["engagement_time"],
    }


def submit(c: httpx.Client, path: str, body: dict[str, Any]) -> str:
    r = c.post(path, json=body)
    if r.status_code != 202:
        raise RuntimeError(f"{path}: {r.status_code} {r.text[:300]}")
    return str(r.json()["job"])


def job(c: httpx.Client, job_id: str) -> dict[str, Any]:
    return dict(c.get(f"{API}/jobs/{job_id}").json())


def settled(c: httpx.Client, job_id: str, timeout: float = 1800.0) -> dict[str, Any]:
    end = time.monotonic() + timeout
    while True:
        j = job(c, job_id)
        if j.get("state") not in ("queued", "running"):  # no state: a 404, removed
            return j
        if time.monotonic() > end:
            raise RuntimeError(f"job {job_id} still {j['state']} after {timeout} s")
        time.sleep(0.25)


def until(predicate: Callable[[], bool], timeout: float, step: float = 0.05) -> float:
    """Seconds until ``predicate()`` held (raises past ``timeout``)."""
    start = time.monotonic()
    while not predicate():
        if time.monotonic() - start > timeout:
            raise RuntimeError("timed out")
        time.sleep(step)
    return time.monotonic() - start


class Sampler:
    """A thread calling ``probe()`` every ``every`` seconds, keeping what it returns."""

    def __init__(self, probe: Callable[[], Any], every: float) -> None:
        self.values: list[Any] = []
        self._stop = threading.Event()

        def run() -> None:
            while not self._stop.is_set():
                self.values.append(probe())
                self._stop.wait(every)

        self._thread = threading.Thread(target=run, daemon=True)

    def __enter__(self) -> Sampler:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join(30)


def quantiles(values: list[float]) -> dict[str, float]:
    ordered = sorted(values)
    if not ordered:
        return {}
    return {
        "n": len(ordered),
        "median_ms": round(1e3 * statistics.median(ordered), 2),
        "p99_ms": round(1e3 * ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))], 2),
        "max_ms": round(1e3 * ordered[-1], 2),
    }


# --- the figures ------------------------------------------------------------------------


def fig_memory(svc: Service, scale: float) -> dict[str, Any]:
    """Ten finished studies one after another (a client's limit is 2 at once), default
    keep_points (false); RSS before, after each, after all, and after DELETE of all."""
    n = max(2, int(1_000_000 * scale))
    out: dict[str, Any] = {"points_per_study": n, "studies": 10}
    with client(svc.url) as c:
        out["rss_start_mb"] = round(svc.rss(), 1)
        out["tree_rss_start_mb"] = round(svc.tree_rss(), 1)
        peak = [svc.rss()]
        times, after, ids = [], [], []
        with Sampler(lambda: peak.append(svc.rss()), 0.2):
            for i in range(10):
                t = time.monotonic()
                jid = submit(c, JOINT, joint_study(n, seed=i))
                done = settled(c, jid)
                assert done["state"] == "done", done
                times.append(round(time.monotonic() - t, 2))
                after.append(round(svc.rss(), 1))
                ids.append(jid)
        out["study_wall_s"] = times
        out["rss_after_each_mb"] = after
        out["rss_after_ten_mb"] = after[-1]
        out["rss_peak_mb"] = round(max(peak), 1)
        out["tree_rss_after_ten_mb"] = round(svc.tree_rss(), 1)
        for jid in ids:
            c.delete(f"{API}/jobs/{jid}")
        time.sleep(1.0)
        out["rss_after_delete_mb"] = round(svc.rss(), 1)
        out["lookups_after_delete"] = sorted({c.get(f"{API}/jobs/{j}").status_code for j in ids})
    out["load"] = load()
    return out


def fig_csv(svc: Service, scale: float) -> dict[str, Any]:
    """A study kept with keep_points, its CSV streamed while /healthz is asked every 50 ms
    from another connection; the service's RSS sampled meanwhile."""
    n = max(2, int(1_000_000 * scale))
    out: dict[str, Any] = {"points": n}
    with client(svc.url) as c:
        jid = submit(c, JOINT, joint_study(n, keep_points=True, seed=99))
        done = settled(c, jid)
        assert done["state"] == "done", done
        base_lat = []
        with client(svc.url) as h:
            for _ in range(40):
                t = time.perf_counter()
                h.get("/healthz")
                base_lat.append(time.perf_counter() - t)
                time.sleep(0.025)
        out["healthz_idle"] = quantiles(base_lat)
        lat: list[float] = []
        codes: list[int] = []
        rss0 = svc.rss()
        rss = [rss0]

        def probe() -> None:
            with contextlib.suppress(httpx.HTTPError):
                t = time.perf_counter()
                codes.append(h2.get("/healthz").status_code)
                lat.append(time.perf_counter() - t)
            rss.append(svc.rss())

        size = 0
        with client(svc.url) as h2, Sampler(probe, 0.05):
            t = time.monotonic()
            with c.stream(
                "GET", done["links"]["points_csv"], headers={"accept-encoding": "identity"}
            ) as r:
                assert r.status_code == 200, r.status_code
                for block in r.iter_raw():
                    size += len(block)
            out["download_s"] = round(time.monotonic() - t, 2)
        out["csv_mb"] = round(size / MB, 1)
        out["mb_per_s"] = round(size / MB / out["download_s"], 1)
        out["rss_before_mb"] = round(rss0, 1)
        out["rss_added_peak_mb"] = round(max(rss) - rss0, 1)
        out["healthz_during"] = quantiles(lat)
        out["healthz_non_200"] = sum(code != 200 for code in codes)
        t = time.monotonic()
        r = c.get(done["links"]["points_parquet"])
        out["parquet_mb"] = round(len(r.content) / MB, 1)
        out["parquet_s"] = round(time.monotonic() - t, 2)
        c.delete(f"{API}/jobs/{jid}")
    out["load"] = load()
    return out


def fig_refused(svc: Service, scale: float) -> dict[str, Any]:
    """The client holds its two places (STUDY_PER_CLIENT's default) with slow simulation
    studies; then eight submissions of STUDY_MAX_POINTS points: each one's answer, time,
    and the service process's CPU and RSS over all eight."""
    n = max(2, int(2_000_000 * scale))
    out: dict[str, Any] = {"points_per_refused_study": n, "refused": 8}
    with client(svc.url) as c:
        holders = [submit(c, RARE, rare_study(40 * 256, seed=s)) for s in (1, 2)]
        time.sleep(1.0)
        cpu0, rss0 = svc.cpu(), svc.rss()
        statuses, times, retry = [], [], set()
        for i in range(8):
            t = time.perf_counter()
            r = c.post(JOINT, json=joint_study(n, seed=100 + i))
            times.append(time.perf_counter() - t)
            statuses.append(r.status_code)
            retry.add(r.headers.get("retry-after"))
        out["service_cpu_s"] = round(svc.cpu() - cpu0, 3)
        out["rss_added_mb"] = round(svc.rss() - rss0, 1)
        out["statuses"] = sorted(set(statuses))
        out["retry_after"] = sorted(str(x) for x in retry)
        out["answer"] = quantiles(times)
        for jid in holders:
            c.delete(f"{API}/jobs/{jid}")
        for jid in holders:
            settled(c, jid, 120)
    out["load"] = load()
    return out


def _busy(svc: Service, window: float = 0.25) -> float:
    """The Dask workers' CPU over ``window`` seconds, as a share of one core."""
    a = svc.workers_cpu()
    time.sleep(window)
    return (svc.workers_cpu() - a) / window


def fig_delete(svc: Service, scale: float) -> dict[str, Any]:
    """A running simulation study (its chunks 256 points, ~0.3 s of CPU each, alone)
    deleted mid-chunk; the time until the Dask workers' CPU falls under 10 % of a core."""
    n = max(3000, int(100_000 * scale))
    out: dict[str, Any] = {"points": n}
    with client(svc.url) as c:
        jid = submit(c, RARE, rare_study(n, seed=7))
        until(lambda: job(c, jid)["progress"]["done"] >= 512, 600, 0.1)
        out["busy_before_cores"] = round(_busy(svc), 2)
        time.sleep(0.15)
        t = time.monotonic()
        answer = c.delete(f"{API}/jobs/{jid}")
        out["delete_status"] = answer.status_code
        idle = None
        while time.monotonic() - t < 120:
            if _busy(svc, 0.1) < 0.1:
                idle = time.monotonic() - t
                break
        out["delete_to_idle_s"] = None if idle is None else round(idle, 2)
        end = settled(c, jid, 120)
        out["state"] = end.get("state", end)
        out["delete_to_cancelled_s"] = round(time.monotonic() - t, 2)
        out["done_at_cancel"] = end["progress"]["done"]
    out["load"] = load()
    return out


def _progress(c: httpx.Client, jid: str) -> tuple[str, int]:
    j = job(c, jid)
    if "state" not in j:
        raise RuntimeError(f"job {jid}: {j}")
    return j["state"], int(j["progress"]["done"])


def fig_fairness(svc: Service, scale: float) -> dict[str, Any]:
    """Client A (127.0.0.1) runs a 100,000-point simulation study; once it computes,
    client B (127.0.0.2) submits a 2,500-point one: B's first progress and its end, and
    A's points meanwhile. Then the same with A running two large studies (its limit)."""
    large = max(3000, int(100_000 * scale))
    small = max(2500, int(2500 * scale))  # over STUDY_INPROCESS_POINTS: on Dask too
    out: dict[str, Any] = {"large_points": large, "small_points": small}
    for holders in (1, 2):
        with client(svc.url) as a, client(svc.url, "127.0.0.2") as b:
            big = [submit(a, RARE, rare_study(large, seed=20 + i)) for i in range(holders)]

            def running(big: list[str] = big) -> bool:
                return all(_progress(a, j)[1] >= 512 for j in big)

            until(running, 600, 0.1)
            a0 = sum(_progress(a, j)[1] for j in big)
            t = time.monotonic()
            sid = submit(b, RARE, rare_study(small, seed=30))
            first = None
            while True:
                state, done = _progress(b, sid)
                if first is None and done > 0:
                    first = time.monotonic() - t
                if state not in ("queued", "running"):
                    break
                if time.monotonic() - t > 900:
                    break
                time.sleep(0.1)
            took = time.monotonic() - t
            a1 = sum(_progress(a, j)[1] for j in big)
            for j in big:
                a.delete(f"{API}/jobs/{j}")
            for j in big:
                settled(a, j, 120)
        out[f"beside_{holders}_large"] = {
            "small_state": state,
            "small_first_progress_s": None if first is None else round(first, 2),
            "small_done_s": round(took, 2),
            "small_points_per_s": round(small / took, 1),
            "large_points_meanwhile": a1 - a0,
            "small_share": round(small / (small + a1 - a0), 3),
            "load": load(),
        }
    return out


def _trickler(
    port: int, source: str, sockets: int, seconds: float, stop: threading.Event
) -> dict[str, int]:
    """``sockets`` connections from ``source``, each a POST whose body comes a byte every
    2–4 s; a connection the server closes is opened again at once (a persistent attacker)."""
    head = (
        b"POST /api/v1/joint/vdi2230 HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
        b"Content-Length: 1000\r\n\r\n"
    )
    rng = random.Random(1)
    counts = {"opened": 0, "closed_by_server": 0, "refused_503": 0, "answered_408": 0}
    live: dict[socket.socket, float] = {}

    def open_one() -> None:
        try:
            s = socket.create_connection(("127.0.0.1", port), timeout=2, source_address=(source, 0))
            s.sendall(head)
            s.setblocking(False)
        except OSError:
            return
        counts["opened"] += 1
        live[s] = time.monotonic() + rng.uniform(2, 4)

    end = time.monotonic() + seconds
    for _ in range(sockets):
        open_one()
    while time.monotonic() < end and not stop.is_set():
        readable, _, _ = select.select(list(live), [], [], 0.05)
        for s in readable:
            try:
                data = s.recv(65536)
            except OSError:
                data = b""
            if data.startswith(b"HTTP/1.1 503"):
                counts["refused_503"] += 1
            elif data.startswith(b"HTTP/1.1 408"):
                counts["answered_408"] += 1
            counts["closed_by_server"] += 1
            live.pop(s, None)
            s.close()
            open_one()
        now = time.monotonic()
        for s, due in list(live.items()):
            if due <= now:
                try:
                    s.send(b" ")
                    live[s] = now + rng.uniform(2, 4)
                except OSError:
                    counts["closed_by_server"] += 1
                    live.pop(s, None)
                    s.close()
                    open_one()
    for s in live:
        s.close()
    return counts


def fig_flood(svc: Service, scale: float, spread: int = 1) -> dict[str, Any]:
    """1,000 trickling sockets for 40 s (from one address, or ``spread`` addresses),
    while another client (127.0.0.1) asks /healthz and a joint calculation in turn."""
    sockets, seconds = max(10, int(1000 * scale)), max(5.0, 40.0 * scale)
    out: dict[str, Any] = {"sockets": sockets, "seconds": seconds, "addresses": spread}
    stop = threading.Event()
    results: list[dict[str, int]] = []
    threads = [
        threading.Thread(
            target=lambda k=k: results.append(
                _trickler(svc.port, f"127.0.1.{2 + k}", sockets // spread, seconds, stop)
            ),
            daemon=True,
        )
        for k in range(spread)
    ]
    for th in threads:
        th.start()
    time.sleep(min(3.0, seconds / 4))  # the sockets are open and trickling
    calc = {"thread_diameter": 0.012, "plate1_thickness": 0.02, "plate2_thickness": 0.02}
    codes: list[int | str] = []
    lat: list[float] = []
    end = time.monotonic() + seconds - min(3.0, seconds / 4) - 1.0
    with client(svc.url, timeout=10) as c:
        i = 0
        while time.monotonic() < end:
            t = time.perf_counter()
            try:
                r = c.get("/healthz") if i % 2 == 0 else c.post(f"{API}/joint/vdi2230", json=calc)
                codes.append(r.status_code)
            except httpx.HTTPError as exc:
                codes.append(type(exc).__name__)
            lat.append(time.perf_counter() - t)
            i += 1
            time.sleep(0.05)
    stop.set()
    for th in threads:
        th.join(60)
    out["attacker"] = {k: sum(r[k] for r in results) for k in results[0]} if results else {}
    out["other_client_requests"] = len(codes)
    out["other_client_success"] = round(sum(code == 200 for code in codes) / max(1, len(codes)), 4)
    out["other_client_codes"] = {str(k): codes.count(k) for k in set(codes)}
    out["other_client_latency"] = quantiles(lat)
    out["load"] = load()
    return out


def fig_lookups(root: Path, scale: float) -> dict[str, Any]:
    """Studies submitted to a ``--workers 2`` service, each from a fresh connection, then
    looked up 10 times each from fresh connections; the service stopped and started again
    (one worker) on the same store, and every job looked up again with its CSV."""
    store = root / "lookups"
    n_jobs = max(4, int(20 * scale))
    out: dict[str, Any] = {"jobs": n_jobs}
    jobs: list[str] = []
    with Service(store, "--workers", "2") as svc:
        out["workers2_start_s"] = round(svc.start_s, 1)
        for i in range(n_jobs):
            with client(svc.url) as fresh:
                jobs.append(submit(fresh, JOINT, joint_study(1000, keep_points=True, seed=i)))
            with client(svc.url) as fresh:
                settled(fresh, jobs[-1], 120)
        codes = []
        for _ in range(10):
            for jid in jobs:
                with client(svc.url) as fresh:
                    codes.append(fresh.get(f"{API}/jobs/{jid}").status_code)
        out["workers2_lookups"] = len(codes)
        out["workers2_answered_200"] = codes.count(200)
        with client(svc.url) as c:
            csv = c.get(f"{API}/jobs/{jobs[0]}/points.csv").content
    with Service(store) as svc, client(svc.url) as c:
        states = [job(c, jid).get("state") for jid in jobs]
        out["restart_lookups"] = len(states)
        out["restart_done"] = states.count("done")
        out["restart_csv_same"] = c.get(f"{API}/jobs/{jobs[0]}/points.csv").content == csv
    out["load"] = load()
    return out


FIGURES = ("memory", "csv", "refused", "fairness", "delete", "flood", "lookups")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scale", type=float, default=1.0, help="1.0: issue 34's full size")
    parser.add_argument("--only", default=",".join(FIGURES), help="figures, comma-separated")
    parser.add_argument("--out", default="", help="write the figures here as JSON")
    args = parser.parse_args(argv)
    wanted = [f for f in args.only.split(",") if f]
    unknown = set(wanted) - set(FIGURES)
    if unknown:
        parser.error(f"unknown figures {sorted(unknown)}; known: {', '.join(FIGURES)}")
    figures: dict[str, Any] = {
        "scale": args.scale,
        "started": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "cpus": os.cpu_count(),
        "before": {k: BEFORE[k] for k in wanted},
    }

    def say(name: str, value: Any) -> None:
        figures[name] = value
        print(json.dumps({name: value}), flush=True)

    with tempfile.TemporaryDirectory(prefix="shopfloor-") as tmp:
        root = Path(tmp)
        if {"memory", "csv"} & set(wanted):
            with Service(root / "memory") as svc:
                if "memory" in wanted:
                    say("memory", fig_memory(svc, args.scale))
                if "csv" in wanted:
                    say("csv", fig_csv(svc, args.scale))
        if {"refused", "fairness", "delete"} & set(wanted):
            with Service(root / "studies") as svc:
                for name, fig in (
                    ("refused", fig_refused),
                    ("fairness", fig_fairness),
                    ("delete", fig_delete),
                ):
                    if name in wanted:
                        say(name, fig(svc, args.scale))
        if "flood" in wanted:
            # the connection limits scaled with the sockets, so a reduced run fills them too
            limits = {
                "MAX_CONNECTIONS": str(max(10, int(1000 * args.scale))),
                "MAX_CONNECTIONS_PER_CLIENT": str(max(1, int(100 * args.scale))),
            }
            with Service(root / "flood", env=limits) as svc:
                say("flood", fig_flood(svc, args.scale))
            with Service(root / "flood10", env=limits) as svc:
                say("flood_10_addresses", fig_flood(svc, args.scale, spread=10))
        if "lookups" in wanted:
            say("lookups", fig_lookups(root, args.scale))
    if args.out:
        Path(args.out).write_text(json.dumps(figures, indent=1) + "\n")


if __name__ == "__main__":
    main()
