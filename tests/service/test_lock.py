"""The lock files pin every dependency pyproject.toml declares (scripts/lock regenerates them).

The image installs only from requirements.lock and `make test` only from
requirements-dev.lock (with --no-deps for the project), so a dependency added
to pyproject.toml but not locked would be missing there: this test says so.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _name(requirement: str) -> str:
    return re.split(r"[\[<>=!~; ]", requirement, maxsplit=1)[0].lower().replace("_", "-")


def _locked(path: Path) -> dict[str, str]:
    pins = {}
    for line in path.read_text().splitlines():
        if line and not line.startswith("#"):
            name, version = line.split("==")
            pins[name.lower().replace("_", "-")] = version
    return pins


def test_every_declared_dependency_is_pinned() -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    runtime = {_name(r) for r in project["dependencies"]}
    dev = runtime | {_name(r) for r in project["optional-dependencies"]["dev"]}
    run_lock, dev_lock = (
        _locked(ROOT / "requirements.lock"),
        _locked(ROOT / "requirements-dev.lock"),
    )
    assert runtime <= set(run_lock), sorted(runtime - set(run_lock))
    assert dev <= set(dev_lock), sorted(dev - set(dev_lock))
    # one version of each package in both files
    assert all(dev_lock[n] == v for n, v in run_lock.items() if n in dev_lock)
