"""Benchmark: cold start. Spawn to ``/readyz`` against a bare uvicorn + FastAPI app, and the
first simulation request after ready against the steady one.

Each round spawns, on free loopback ports, a bare app (``uvicorn`` serving one FastAPI route,
``/readyz`` answering 200), the floor (the bare app that first imports numba and loads one
small compiled RK4 kernel from numba's disk cache: what any service with compiled kernels
pays before it can be ready, :data:`FLOOR_APP`) and the service as ``make run`` starts it
(``python -m service``, the access log on, ``WARM_UP`` at its default), one after the
other, and polls ``/readyz`` every 5 ms from just before the spawn until it answers 200.
Each spawn is timed in wall time and in the CPU time the process had used when it was
first seen ready (``/proc/<pid>/stat``; the wall time of a machine shared with other work
is several-fold an idle machine's, its CPU time much less so). For the service it
then posts each simulation model's first example with the simulation rung named, once
(the first request after ready) and :data:`STEADY_CALLS` times more (the steady request,
their median). Figures are medians over the rounds; the ratios are medians of the
per-round ratios (robust to the load of a machine shared with other work).

Targets: spawn to ``/readyz`` ≤ 2× the bare app's in the same rounds; the first
simulation after ready ≤ 2× the steady one. The floor's own ratio to the bare app is
printed beside the first: where it is above 2, no service with these kernels meets it.

Every spawn may write Python's bytecode (``PYTHONDONTWRITEBYTECODE`` is dropped from its
environment, as ``make test-fast`` drops it), so each measured start, like a restart of an
installed service (pip compiles the bytecode at install), reads it: with the variable set,
as on the machine ``make bench`` runs on, every start would compile the engine's and the
service's sources again (0.34 s of CPU for their ~55,000 lines, measured), a cost the bare
app, one short file, does not have.

Run alone: ``python -m bench.cold_start [--rounds N] [--root DIR]`` (``--root``: the
checkout whose service is spawned, this one by default; the numba cache and the bytecode it
uses are that checkout's ``__pycache__``, warm after its first start).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
ROUNDS = 5
STEADY_CALLS = 7
READY_TARGET = 2.0
FIRST_TARGET = 2.0
#: Give up on a spawn after this long [s].
SPAWN_TIMEOUT_S = 120.0
#: The simulations timed, with the rung named (one per compiled kernel family).
SIMULATIONS = (("impact.rare", "simulation"), ("blow.joint", "simulation"))

BARE_APP = """
from fastapi import FastAPI

app = FastAPI()


@app.get("/readyz")
async def readyz() -> dict[str, str]:
    return {"status": "ready"}
"""


#: The floor: the bare app that, before it listens, imports numba and loads a compiled
#: kernel from numba's cache (written next to this file by the unmeasured first round).
#: numba's first cache load in a process sets up its compiler's registries, which import
#: numba's numpy and linear-algebra support and scipy.linalg (numba's BLAS check): the
#: size of the kernel barely matters (the blow's kernel, loaded second, takes ~4 ms).
FLOOR_APP = (
    """
import numba
import numpy as np


@numba.njit(cache=True, nogil=True)
def kernel(y, h, n):
    for _ in range(n):
        k1 = -y
        k2 = -(y + 0.5 * h * k1)
        k3 = -(y + 0.5 * h * k2)
        k4 = -(y + h * k3)
        y = y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
    return y


kernel(np.ones(2), 1e-3, 10)
"""
    + BARE_APP
)


def cpu_seconds(pid: int) -> float:
    """CPU time (user + system) process ``pid`` has used so far [s]; NaN off Linux.

    This process's, against Python's own count (the kernel counts in clock ticks):

    >>> abs(cpu_seconds(os.getpid()) - time.process_time()) < 0.05
    True
    """
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return float("nan")
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _get(url: str, timeout: float = 2.0) -> int:
    try:
        with urllib.request.urlopen(url, timeout=timeout) as r:
            return int(r.status)
    except urllib.error.HTTPError as e:
        return e.code


def post(url: str, body: object, timeout: float = 60.0) -> tuple[int, float, bytes]:
    """Status, seconds and body of one JSON POST."""
    req = urllib.request.Request(
        url, data=json.dumps(body).encode(), headers={"content-type": "application/json"}
    )
    start = time.perf_counter()
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            data, status = r.read(), int(r.status)
    except urllib.error.HTTPError as e:
        data, status = e.read(), e.code
    return status, time.perf_counter() - start, data


@contextlib.contextmanager
def spawned(
    argv: Sequence[str], cwd: Path, env: dict[str, str], port: int
) -> Iterator[tuple[float, float, float]]:
    """Start ``argv`` and wait for ``/readyz`` 200: (seconds to the first HTTP answer, to
    ready, and the CPU seconds the process had used when ready); stopped on leaving."""
    start = time.perf_counter()
    proc = subprocess.Popen(
        argv, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    try:
        listening: float | None = None
        url = f"http://127.0.0.1:{port}/readyz"
        while True:
            if proc.poll() is not None:
                raise RuntimeError(f"{argv} exited with {proc.returncode} before ready")
            if time.perf_counter() - start > SPAWN_TIMEOUT_S:
                raise RuntimeError(f"{argv} not ready after {SPAWN_TIMEOUT_S} s")
            try:
                status = _get(url)
            except OSError:  # not listening yet
                status = 0
            if status and listening is None:
                listening = time.perf_counter() - start
            if status == 200:
                ready = time.perf_counter() - start
                cpu = cpu_seconds(proc.pid)
                break
            time.sleep(0.005)
        yield listening if listening is not None else ready, ready, cpu
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def _examples(root: Path) -> dict[str, dict[str, Any]]:
    """Each timed simulation's request body: its model's first example, the rung named."""
    code = (
        "import json, engine; print(json.dumps({n: [engine.get_model(n).path, "
        "engine.get_model(n).examples[0]] for n in %r}))" % [n for n, _ in SIMULATIONS]
    )
    out = subprocess.run(
        [sys.executable, "-c", code],
        cwd=root,
        env={**os.environ, "PYTHONPATH": str(root)},
        capture_output=True,
        text=True,
        check=True,
    )
    found = json.loads(out.stdout)
    return {
        name: {"path": found[name][0], "body": {**found[name][1], "fidelity": rung}}
        for name, rung in SIMULATIONS
    }


def one_round(
    root: Path, bare_dir: Path, cases: dict[str, dict[str, Any]], *, strict: bool = True
) -> dict[str, Any]:
    """The bare app, the floor, then the service: spawn to ready, and the service's
    requests (a steady request refused fails the round when ``strict``)."""
    spawn_env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env = {**spawn_env, "PYTHONPATH": str(root)}
    env.pop("WARM_UP", None)
    env.pop("ACCESS_LOG", None)
    row: dict[str, Any] = {}
    for app in ("bare", "floor"):
        port = free_port()
        argv = [sys.executable, "-m", "uvicorn", f"{app}:app", "--port", str(port)]
        with spawned(argv, bare_dir, {**spawn_env, "PYTHONPATH": str(bare_dir)}, port) as (
            _,
            ready,
            cpu,
        ):
            row.update({f"{app}_s": ready, f"{app}_cpu_s": cpu})
    port = free_port()
    service_argv = [sys.executable, "-m", "service", "--port", str(port)]
    with spawned(service_argv, root, env, port) as (listening, ready, cpu):
        row.update(service_s=ready, listening_s=listening, service_cpu_s=cpu)
        for name, case in cases.items():
            url = f"http://127.0.0.1:{port}/api/v1{case['path']}"
            # the first may fail (a kernel still compiling past the budget): timed anyway
            status, first, _ = post(url, case["body"])
            steady_calls = [post(url, case["body"]) for _ in range(STEADY_CALLS)]
            failed = [(s, b[:300]) for s, _, b in steady_calls if s != 200]
            if failed and strict:
                raise RuntimeError(f"{name}: {failed[0]!r}")
            steady = statistics.median(t for _, t, _ in steady_calls)
            if not strict:  # the first start of a cold cache: let it finish compiling
                for _ in range(int(SPAWN_TIMEOUT_S)):
                    if post(url, case["body"])[0] == 200:
                        break
                    time.sleep(1.0)
            row[name] = {"first_s": first, "first_ok": status == 200, "steady_s": steady}
    return row


def measure(rounds: int = ROUNDS, root: Path = ROOT) -> list[dict[str, Any]]:
    cases = _examples(root)
    with tempfile.TemporaryDirectory() as tmp:
        bare_dir = Path(tmp)
        (bare_dir / "bare.py").write_text(BARE_APP)
        (bare_dir / "floor.py").write_text(FLOOR_APP)
        # one unmeasured round: the numba cache, the bytecode and the OS's file cache as a
        # restart finds them
        one_round(root, bare_dir, cases, strict=False)
        runs = [one_round(root, bare_dir, cases) for _ in range(rounds)]
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")

    def median(key: str, over: str = "") -> float:
        return statistics.median(r[key] / (r[over] if over else 1.0) for r in runs)

    bare, floor, service = median("bare_s"), median("floor_s"), median("service_s")
    listening = median("listening_s")
    ratio = median("service_s", "bare_s")
    cpu = {k: median(f"{k}_cpu_s") for k in ("bare", "floor", "service")}
    cpu_ratio = median("service_cpu_s", "bare_cpu_s")
    floor_ratio, floor_cpu_ratio = median("floor_s", "bare_s"), median("floor_cpu_s", "bare_cpu_s")
    machine = f"{rounds} alternating rounds, load average {load:.1f} on {os.cpu_count()} CPUs"
    rows: list[dict[str, Any]] = [
        {
            "model": "service",
            "method": "cold start",
            "case": "spawn to /readyz",
            "time_s": service,
            "ratio": ratio,
            "target_ratio": READY_TARGET,
            "met": ratio <= READY_TARGET,
            "baseline_s": bare,
            "listening_s": listening,
            "floor_s": floor,
            "floor_ratio": floor_ratio,
            "cpu_s": cpu["service"],
            "cpu_ratio": cpu_ratio,
            "baseline_cpu_s": cpu["bare"],
            "floor_cpu_s": cpu["floor"],
            "floor_cpu_ratio": floor_cpu_ratio,
            "notes": (
                f"python -m service {service:.2f} s (answering from {listening:.2f} s) vs a "
                f"bare uvicorn + FastAPI app {bare:.2f} s; in CPU time {cpu['service']:.2f} s "
                f"vs {cpu['bare']:.2f} s (×{cpu_ratio:.2f}); the floor (the bare app + numba + "
                f"one cached kernel) {floor:.2f} s, ×{floor_ratio:.2f} the bare app "
                f"(CPU {cpu['floor']:.2f} s, ×{floor_cpu_ratio:.2f}); {machine}"
            ),
        }
    ]
    for name, _ in SIMULATIONS:
        first = statistics.median(r[name]["first_s"] for r in runs)
        steady = statistics.median(r[name]["steady_s"] for r in runs)
        ratio = statistics.median(r[name]["first_s"] / r[name]["steady_s"] for r in runs)
        failed = sum(not r[name]["first_ok"] for r in runs)
        rows.append(
            {
                "model": name,
                "method": "cold start",
                "case": "first simulation after ready",
                "time_s": first,
                "ratio": ratio,
                "target_ratio": FIRST_TARGET,
                "met": ratio <= FIRST_TARGET,
                "steady_s": steady,
                "notes": (
                    f"first {first * 1e3:.1f} ms vs steady {steady * 1e3:.1f} ms over HTTP"
                    + (f" ({failed} first request(s) refused)" if failed else "")
                    + f"; {machine}"
                ),
            }
        )
    return rows


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(prog="python -m bench.cold_start", description=__doc__)
    parser.add_argument("--rounds", type=int, default=ROUNDS, help="alternating rounds")
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout to spawn")
    args = parser.parse_args(argv)
    for row in measure(args.rounds, args.root.resolve()):
        met = "met" if row["met"] else "MISSED"
        print(
            f"{row['model']:<12} {row['case']:<30} ×{row['ratio']:.2f} "
            f"target ≤ ×{row['target_ratio']:g} {met:<6} {row['notes']}"
        )


if __name__ == "__main__":
    main()
