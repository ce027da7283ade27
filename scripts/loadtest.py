#!/usr/bin/env python3
"""Load test on loopback: requests/s and p50/p99 latency for /healthz, a closed form, a simulation.

Starts ``python -m service`` on a free 127.0.0.1 port (or uses ``--url``, which
must be a loopback address), picks the endpoints from ``GET /api/v1/models``,
and for each runs a closed loop of ``--concurrency`` clients (httpx, one
keep-alive connection each) until ``--requests`` answers or ``--seconds``
have passed, whichever is first. Writes ``bench/loadtest.json`` and prints a
table. Bounded in count and time; stops the server it started.

Endpoint choice (override with ``--closed /path`` and ``--sim /path``):

* closed form: the model and rung that answer its first example fastest,
  preferring rungs whose names say so (closed, analytic, formula, ...);
* simulation: a rung whose name says it integrates (ode, sim, dynamic,
  numeric, ...), else a model with a time series output, else the slowest.

With an empty registry the server runs the test toys instead
(``tests.toys:toy_app``), so the script works on any checkout.

Targets (issue 8): closed form ≥ 50 % of /healthz throughput, closed-form
p99 < 50 ms. ``--check`` exits 1 when either is missed.

Usage::

    .venv/bin/python scripts/loadtest.py                 # ~1 minute, 2000 requests per endpoint
    .venv/bin/python scripts/loadtest.py --requests 300  # quicker
    .venv/bin/python scripts/loadtest.py --url http://127.0.0.1:8000
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import socket
import statistics
import subprocess
import sys
import threading
import time
from datetime import UTC, datetime
from pathlib import Path
from typing import Any
from urllib.parse import urlparse

import httpx

ROOT = Path(__file__).resolve().parents[1]
CLOSED_WORDS = re.compile(r"closed|analytic|formula|algebraic|static|handbook|simple|rough", re.I)
SIM_WORDS = re.compile(
    r"ode|sim|dynamic|transient|numeric|integrat|solve|rk|lsoda|radau|bdf|fem", re.I
)
LOOPBACK = {"127.0.0.1", "localhost", "::1", "[::1]"}


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def start_server(workers: int, toy: bool) -> tuple[subprocess.Popen[bytes], str]:
    port = free_port()
    cmd = [sys.executable, "-m", "service", "--workers", str(workers)]
    if toy:
        cmd += ["--factory", "tests.toys:toy_app"]
    cmd += ["--host", "127.0.0.1", "--port", str(port)]
    # the access log stays on (it is part of the cost being measured), to a null sink
    proc = subprocess.Popen(
        cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=os.environ.copy()
    )
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise SystemExit(f"the server exited with {proc.returncode}: {' '.join(cmd)}")
        try:
            if httpx.get(url + "/healthz", timeout=1).status_code == 200:
                return proc, url
        except httpx.TransportError:
            time.sleep(0.1)
    proc.kill()
    raise SystemExit("the server did not answer /healthz within 30 s")


def cpu_seconds(pid: int | None) -> float | None:
    """User + system CPU time of ``pid`` and its children (uvicorn workers), from /proc."""
    if pid is None or not Path("/proc").is_dir():
        return None
    tick = os.sysconf("SC_CLK_TCK")
    total = 0.0
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        proc_pid, ppid = int(stat.parent.name), int(fields[1])
        if pid in (proc_pid, ppid):
            total += (int(fields[11]) + int(fields[12])) / tick
    return total


def probe(client: httpx.Client, path: str, body: dict[str, Any], n: int = 5) -> float | None:
    """Median answer time of ``n`` calls (one call when it takes over 0.5 s); None on error."""
    times: list[float] = []
    while len(times) < n:
        t = time.perf_counter()
        r = client.post(path, json=body)
        times.append(time.perf_counter() - t)
        if r.status_code != 200:
            return None
        if times[-1] > 0.5:
            break
    return statistics.median(times)


def choose(url: str) -> tuple[dict[str, Any] | None, dict[str, Any] | None]:
    """(closed-form endpoint, simulation endpoint): each {model, path, rung, body}.

    Deterministic: the first (model, rung) in registry order whose rung name says
    closed form (resp. simulation) and that answers its first example with 200;
    without such names, the fastest (resp. a time-series model, else the slowest).
    """
    with httpx.Client(base_url=url, timeout=30) as client:
        models = client.get("/api/v1/models").json()["models"]
        candidates = []
        for m in models:
            example = dict(m["examples"][0]) if m["examples"] else {}
            for rung in m["rungs"]:
                body = {**example, "fidelity": rung["name"]}
                t = probe(client, "/api/v1" + m["path"], body, n=3)
                if t is not None:
                    candidates.append(
                        {
                            "model": m["name"],
                            "path": "/api/v1" + m["path"],
                            "rung": rung["name"],
                            "body": body,
                            "probe_s": t,
                            "closed_word": bool(CLOSED_WORDS.search(rung["name"])),
                            "sim_word": bool(SIM_WORDS.search(rung["name"])),
                            "series": any(o["series"] for o in m["outputs"]),
                        }
                    )
    if not candidates:
        return None, None
    named = [c for c in candidates if c["closed_word"]]
    closed = named[0] if named else min(candidates, key=lambda c: c["probe_s"])
    rest = [c for c in candidates if c is not closed]
    sims = [c for c in rest if c["sim_word"]] or [c for c in rest if c["series"]]
    sim = sims[0] if sims else (max(rest, key=lambda c: c["probe_s"]) if rest else None)
    return closed, sim


def hammer(
    url: str,
    method: str,
    path: str,
    body: dict[str, Any] | None,
    requests: int,
    seconds: float,
    concurrency: int,
    server_pid: int | None = None,
) -> dict[str, Any]:
    """Closed loop: ``concurrency`` clients until ``requests`` answers or ``seconds`` pass."""
    latencies: list[float] = []
    statuses: dict[int, int] = {}
    lock = threading.Lock()
    issued = 0
    stop_at = time.perf_counter() + seconds

    def client_loop() -> None:
        nonlocal issued
        with httpx.Client(base_url=url, timeout=30) as client:
            for _ in range(20):  # warm the connection and the server's caches
                client.request(method, path, json=body)
            while True:
                with lock:
                    if issued >= requests or time.perf_counter() > stop_at:
                        return
                    issued += 1
                t = time.perf_counter()
                r = client.request(method, path, json=body)
                dt = time.perf_counter() - t
                with lock:
                    latencies.append(dt)
                    statuses[r.status_code] = statuses.get(r.status_code, 0) + 1

    threads = [threading.Thread(target=client_loop) for _ in range(concurrency)]
    cpu_before = cpu_seconds(server_pid)
    start = time.perf_counter()
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    wall = time.perf_counter() - start
    cpu_after = cpu_seconds(server_pid)
    latencies.sort()
    # warm-up requests (20 per client) are included in the CPU but not in the count
    server_cpu_ms = (
        round((cpu_after - cpu_before) * 1e3 / (len(latencies) + 20 * concurrency), 3)
        if cpu_before is not None and cpu_after is not None
        else None
    )

    def pct(p: float) -> float:
        return round(latencies[min(len(latencies) - 1, int(p * len(latencies)))] * 1e3, 2)

    return {
        "method": method,
        "path": path,
        "requests": len(latencies),
        "statuses": {str(k): v for k, v in sorted(statuses.items())},
        "seconds": round(wall, 2),
        "requests_per_s": round(len(latencies) / wall, 1),
        "p50_ms": pct(0.50),
        "p99_ms": pct(0.99),
        "max_ms": round(latencies[-1] * 1e3, 2),
        "server_cpu_ms_per_request": server_cpu_ms,
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", help="an already running server (loopback only)")
    parser.add_argument("--requests", type=int, default=2000, help="per endpoint (≤ 20000)")
    parser.add_argument("--seconds", type=float, default=20.0, help="per endpoint (≤ 120)")
    parser.add_argument("--concurrency", type=int, default=8, help="clients (≤ 64)")
    parser.add_argument("--workers", type=int, default=1, help="server processes it starts")
    parser.add_argument("--closed", help="closed-form endpoint path (POSTs its first example)")
    parser.add_argument("--sim", help="simulation endpoint path")
    parser.add_argument("--out", default=str(ROOT / "bench" / "loadtest.json"))
    parser.add_argument("--check", action="store_true", help="exit 1 if a target is missed")
    args = parser.parse_args(argv)
    requests = max(1, min(args.requests, 20_000))
    seconds = max(1.0, min(args.seconds, 120.0))
    concurrency = max(1, min(args.concurrency, 64))

    proc = None
    if args.url:
        host = urlparse(args.url).hostname or ""
        if host not in LOOPBACK:
            raise SystemExit(f"--url must be a loopback address, not {host!r}")
        url = args.url.rstrip("/")
    else:
        sys.path.insert(0, str(ROOT))
        import engine

        proc, url = start_server(args.workers, toy=not engine.MODELS)
    try:
        closed, sim = choose(url)
        if args.closed or args.sim:
            with httpx.Client(base_url=url) as client:
                models = {
                    "/api/v1" + m["path"]: m for m in client.get("/api/v1/models").json()["models"]
                }
            for key, path in (("closed", args.closed), ("sim", args.sim)):
                if path:
                    m = models[path]
                    chosen = {"model": m["name"], "path": path, "rung": "auto"}
                    chosen["body"] = dict(m["examples"][0]) if m["examples"] else {}
                    closed, sim = (chosen, sim) if key == "closed" else (closed, chosen)
        pid = proc.pid if proc is not None else None
        results: dict[str, Any] = {
            "healthz": hammer(url, "GET", "/healthz", None, requests, seconds, concurrency, pid)
        }
        for key, chosen, n in (("closed_form", closed, requests), ("simulation", sim, requests)):
            if chosen is None:
                continue
            r = hammer(url, "POST", chosen["path"], chosen["body"], n, seconds, concurrency, pid)
            results[key] = {"model": chosen["model"], "rung": chosen["rung"], **r}
    finally:
        if proc is not None:
            proc.terminate()
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()

    targets: dict[str, Any] = {}
    if "closed_form" in results:
        ratio = results["closed_form"]["requests_per_s"] / results["healthz"]["requests_per_s"]
        targets = {
            "closed_form_vs_healthz_throughput": round(ratio, 3),
            "throughput_target_met": ratio >= 0.5,
            "closed_form_p99_ms": results["closed_form"]["p99_ms"],
            "p99_target_met": results["closed_form"]["p99_ms"] < 50.0,
        }
    report = {
        "when": datetime.now(UTC).isoformat(timespec="seconds"),
        "url": url,
        "server_started_by_script": proc is not None,
        "server_workers": args.workers if proc is not None else None,
        "concurrency": concurrency,
        "requests_per_endpoint": requests,
        "machine": {"cpus": os.cpu_count(), "python": platform.python_version()},
        "endpoints": results,
        "targets": targets,
    }
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(report, indent=2) + "\n")
    print(f"{'endpoint':<44} {'req/s':>8} {'p50 ms':>8} {'p99 ms':>8} {'cpu ms':>7}  statuses")
    for key, r in results.items():
        label = f"{key} {r['path']}" + (f" [{r['rung']}]" if "rung" in r else "")
        print(
            f"{label:<44} {r['requests_per_s']:>8} {r['p50_ms']:>8} {r['p99_ms']:>8} "
            f"{r['server_cpu_ms_per_request'] or '-':>7}  {r['statuses']}"
        )
    print(json.dumps(targets), f"-> {out}")
    missed = targets and not (targets["throughput_target_met"] and targets["p99_target_met"])
    return 1 if args.check and missed else 0


if __name__ == "__main__":
    sys.exit(main())
