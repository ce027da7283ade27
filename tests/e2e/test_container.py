"""The Dockerfile's steps, run without Docker: install as it does, start with its CMD.

No Docker engine runs on the CI machines, so this repeats what the image does
in a fresh virtual environment: ``pip install .`` (no dev extras) from a copy
of the files the Dockerfile COPYs, then the CMD from outside the source tree,
and asks /healthz, the catalogue and the form.
"""

from __future__ import annotations

import json
import re
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
pytestmark = [pytest.mark.slow, pytest.mark.install]


def _dockerfile() -> tuple[list[str], list[str]]:
    text = (ROOT / "Dockerfile").read_text()
    copies = [
        src for line in re.findall(r"^COPY\s+(.+)$", text, flags=re.M) for src in line.split()[:-1]
    ]
    (cmd,) = re.findall(r"^CMD\s+(\[.*\])\s*$", text, flags=re.M)
    return copies, json.loads(cmd)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _get(url: str) -> tuple[int, bytes]:
    with urllib.request.urlopen(url, timeout=5) as r:
        return r.status, r.read()


def test_dockerfile_install_and_cmd(tmp_path: Path) -> None:
    copies, cmd = _dockerfile()
    app = tmp_path / "app"
    app.mkdir()
    for item in copies:
        src = ROOT / item
        if src.is_dir():
            shutil.copytree(src, app / item, ignore=shutil.ignore_patterns("__pycache__"))
        else:
            shutil.copy2(src, app / item)
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    python = venv / "bin" / "python"
    subprocess.run(
        [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(app)],
        check=True,
        timeout=900,
    )
    assert cmd[:3] == ["python", "-m", "service"], cmd
    port = _free_port()
    args = [str(python), *cmd[1:]]
    args[args.index("--host") + 1] = "127.0.0.1"
    args[args.index("--port") + 1] = str(port)
    home = tmp_path / "home"
    home.mkdir()
    log = (tmp_path / "service.log").open("wb")
    proc = subprocess.Popen(args, cwd=home, stdout=log, stderr=subprocess.STDOUT)
    try:
        base = f"http://127.0.0.1:{port}"
        for _ in range(200):
            try:
                status, body = _get(base + "/healthz")
                break
            except OSError:
                if proc.poll() is not None:
                    out = (tmp_path / "service.log").read_text()
                    pytest.fail(f"service exited early:\n{out}")
                time.sleep(0.1)
        else:
            pytest.fail("service did not answer /healthz within 20 s")
        assert status == 200 and json.loads(body) == {"status": "ok"}
        status, body = _get(base + "/api/v1/models")
        assert status == 200 and "models" in json.loads(body)
        status, body = _get(base + "/")
        assert status == 200 and b"<html" in body
    finally:
        proc.terminate()
        proc.wait(timeout=10)
        log.close()
