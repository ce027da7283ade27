"""Each test module's studies in a job store of their own (``STUDY_STORE``), so a study one
test leaves running never counts against another's quota, and no test reads a store a
service on this machine uses."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest


@pytest.fixture(autouse=True, scope="module")
def _job_store(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    folder = tmp_path_factory.mktemp("jobs")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("STUDY_STORE", str(folder))
        yield folder


@pytest.fixture(autouse=True)
def _test_job_store(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A store of each test's own for the apps a test builds itself."""
    folder = tmp_path / "jobs"
    monkeypatch.setenv("STUDY_STORE", str(folder))
    return folder
