"""Cold start: /readyz waits for the warm-up (the compiled kernels loaded), /healthz does not.

* In process: /readyz is 503 "warming" with Retry-After and JSON while the warm-up runs,
  200 "ready" once it is done; at once with WARM_UP=0; done however the warm-up ends.
* In a fresh process: after :func:`service.main.warm_up`, every example of every model at
  every rung loads or compiles no further kernel (the warm-up reaches them all).
* A real server on an empty numba cache (slow): "warming" while the kernels compile, then
  ready, and the first simulation after ready is fast.
"""

from __future__ import annotations

import gc
import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import httpx
import pytest
from fastapi.testclient import TestClient

import service.main
from service.config import Settings
from service.main import WarmUp, create_app
from tests.toys import TOY

from .servers import ROOT, free_port


def test_readyz_says_warming_with_retry_after_until_the_warm_up_is_done(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    gate = threading.Event()
    calls: list[list[str]] = []

    def held_warm_up(models: list[object]) -> None:  # the real one, held until the gate
        calls.append([m.name for m in models])  # type: ignore[attr-defined]
        assert gate.wait(10)

    monkeypatch.setattr(service.main, "warm_up", held_warm_up)
    app = create_app(models=[TOY], settings=Settings(warm_up=True, access_log=False))
    with TestClient(app) as client:
        warming = client.get("/readyz")
        assert warming.status_code == 503
        assert warming.headers["retry-after"] == "1"
        assert warming.headers["content-type"] == "application/json"
        assert warming.json()["status"] == "warming"
        assert warming.json()["warm_up"] == "warming"
        assert client.get("/healthz").status_code == 200  # liveness does not wait
        gate.set()
        assert app.state.warm_up.wait(10)
        ready = client.get("/readyz")
    assert calls == [[TOY.name]]
    assert ready.status_code == 200
    assert ready.json()["status"] == "ready" and ready.json()["warm_up"] == "done"
    assert "retry-after" not in ready.headers


def test_a_service_started_without_the_collector_turns_it_on_once_warmed_up(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """``python -m service`` starts with the collector off; it stays off while the
    warm-up loads the kernels and is on (start-up's objects frozen) before /readyz says
    ready."""
    gate = threading.Event()
    monkeypatch.setattr(service.main, "warm_up", lambda models: gate.wait(10))
    app = create_app(models=[TOY], settings=Settings(warm_up=True, access_log=False))
    gc.disable()
    try:
        with TestClient(app) as client:
            assert client.get("/readyz").json()["status"] == "warming"
            assert not gc.isenabled()
            gate.set()
            assert app.state.warm_up.wait(10)
            assert gc.isenabled()
            assert gc.get_freeze_count() > 0
            assert client.get("/readyz").status_code == 200
    finally:
        gc.unfreeze()
        gc.enable()


def test_without_warm_up_the_collector_is_on_at_start() -> None:
    app = create_app(models=[TOY], settings=Settings(warm_up=False, access_log=False))
    gc.disable()
    try:
        with TestClient(app) as client:
            assert gc.isenabled()
            assert client.get("/readyz").status_code == 200
    finally:
        gc.unfreeze()
        gc.enable()


def test_without_warm_up_readyz_is_ready_at_once() -> None:
    app = create_app(models=[TOY], settings=Settings(warm_up=False, access_log=False))
    with TestClient(app) as client:
        r = client.get("/readyz")
    assert r.status_code == 200
    assert r.json()["status"] == "ready" and r.json()["warm_up"] == "off"


def test_a_warm_up_that_fails_still_ends_warming(monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(models: object) -> None:
        raise RuntimeError("a model blew up while warming")

    monkeypatch.setattr(service.main, "warm_up", broken)
    warm = WarmUp([TOY], enabled=True)
    assert warm.state == "warming"
    with pytest.raises(RuntimeError):
        warm.run()
    assert warm.done and warm.state == "done"
    assert warm.seconds is not None and warm.seconds >= 0.0


#: In a fresh process: the kernels after the warm-up, then after every example of every
#: model at every rung (a kernel the warm-up missed would appear, or gain a signature).
_EVERY_RUNG = """
import json, engine, service.main as m
m.warm_up(engine.MODELS)
after_warm_up = m.kernel_cache()
for spec in engine.MODELS:
    for example in spec.examples:
        for rung in spec.rung_names:
            try:
                engine.run(spec, example, fidelity=rung)
            except engine.EngineError:
                pass
print(json.dumps([after_warm_up, m.kernel_cache()]))
"""


@pytest.mark.slow
def test_the_warm_up_loads_every_kernel_the_models_reach() -> None:
    out = subprocess.run(
        [sys.executable, "-c", _EVERY_RUNG],
        cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        capture_output=True,
        text=True,
        timeout=600,
        check=True,
    )
    after_warm_up, after_all = json.loads(out.stdout.splitlines()[-1])
    # both kernel families: the striker's cycle and the blow
    assert "engine.procedures.striker_cycle._stages_c" in after_warm_up  # the cycle's driver
    assert "engine.physics.blow._blow_kernel_c" in after_warm_up
    assert after_all == after_warm_up


def _readyz(port: int) -> httpx.Response | None:
    try:
        return httpx.get(f"http://127.0.0.1:{port}/readyz", timeout=5)
    except httpx.HTTPError:
        return None


@pytest.mark.slow
def test_a_cold_server_is_warming_until_its_kernels_compile_then_simulates_at_once(
    tmp_path: Path,
) -> None:
    """An empty numba cache (a container on a new CPU): compiling takes seconds, /readyz
    says "warming" all along, and the first simulation after ready pays none of it."""
    port = free_port()
    env = {
        **os.environ,
        "WARM_UP": "1",
        "ACCESS_LOG": "0",
        "PYTHONPATH": str(ROOT),
        "NUMBA_CACHE_DIR": str(tmp_path / "numba"),
    }
    proc = subprocess.Popen(
        [sys.executable, "-m", "service", "--port", str(port)],
        cwd=ROOT,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        seen: list[tuple[int, str]] = []
        deadline = time.monotonic() + 300
        while time.monotonic() < deadline:
            assert proc.poll() is None, "the service exited"
            r = _readyz(port)
            if r is not None:
                seen.append((r.status_code, r.json()["status"]))
                if r.status_code == 200:
                    break
                assert r.headers["retry-after"] == "1"
            time.sleep(0.05)
        assert seen and seen[-1] == (200, "ready"), seen[-3:]
        assert seen[0] == (503, "warming")
        assert set(seen[:-1]) == {(503, "warming")}
        assert any((tmp_path / "numba").rglob("*.nbi"))  # compiled into the cache
        assert httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=5).status_code == 200
        models = httpx.get(f"http://127.0.0.1:{port}/api/v1/models", timeout=10).json()
        for name in ("impact.rare", "blow.joint"):
            model = next(m for m in models["models"] if m["name"] == name)
            body = {**model["examples"][0], "fidelity": "simulation"}
            url = f"http://127.0.0.1:{port}/api/v1{model['path']}"
            start = time.perf_counter()
            r = httpx.post(url, json=body, timeout=60)
            first = time.perf_counter() - start
            assert r.status_code == 200, r.text
            assert r.json()["rung"] == "simulation"
            # compiling took seconds; a loaded kernel takes milliseconds (generous bound
            # for a shared machine)
            assert first < 1.0, (name, first)
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
