"""Study settings from the environment: nonsense stops the service at start-up, naming the
variable and the allowed range (as service.config.Settings does), not at the first study."""

from __future__ import annotations

import re

import pytest

from service import create_app
from service.studies import StudySettings


def test_good_values_are_read(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("STUDY_MAX_POINTS", "5000")
    monkeypatch.setenv("STUDY_BUDGET_S", "12.5")
    monkeypatch.setenv("STUDY_INPROCESS_POINTS", "0")  # allowed: every study on Dask
    monkeypatch.setenv("STUDY_KEEP_POINTS", "0")  # allowed: raw points never kept
    monkeypatch.setenv("DASK_WORKERS", "0")  # allowed: one worker per core
    monkeypatch.setenv("STUDY_INPROCESS_S", "0")  # allowed: no larger study in the job thread
    s = StudySettings()
    assert (s.max_points, s.budget_s, s.inprocess_points, s.keep_points_max) == (5000, 12.5, 0, 0)
    assert s.inprocess_s == 0.0
    assert s.dask_workers is None


@pytest.mark.parametrize(
    ("variable", "value", "message"),
    [
        ("STUDY_MAX_POINTS", "0", "STUDY_MAX_POINTS must be an integer >= 1, not 0"),
        ("STUDY_PER_CLIENT", "-2", "STUDY_PER_CLIENT must be an integer >= 1, not -2"),
        ("STUDY_MAX_ACTIVE", "0", "STUDY_MAX_ACTIVE must be an integer >= 1, not 0"),
        (
            "STUDY_INPROCESS_POINTS",
            "-1",
            "STUDY_INPROCESS_POINTS must be an integer >= 0 (0: every study on Dask), not -1",
        ),
        (
            "STUDY_KEEP_POINTS",
            "-5",
            "STUDY_KEEP_POINTS must be an integer >= 0 (0: raw points never kept), not -5",
        ),
        (
            "DASK_WORKERS",
            "-1",
            "DASK_WORKERS must be an integer >= 0 (0: one worker per usable CPU), not -1",
        ),
        ("STUDY_BUDGET_S", "0", "STUDY_BUDGET_S must be a number of seconds > 0, not 0.0"),
        ("STUDY_BUDGET_S", "nan", "STUDY_BUDGET_S must be a number of seconds > 0, not nan"),
        ("STUDY_KEEP_S", "-1", "STUDY_KEEP_S must be a number of seconds > 0, not -1.0"),
        (
            "STUDY_INPROCESS_S",
            "-0.5",
            "STUDY_INPROCESS_S must be a number of seconds >= 0 (0: every study of more than "
            "STUDY_INPROCESS_POINTS points on Dask), not -0.5",
        ),
        (
            "STUDY_INPROCESS_S",
            "nan",
            "STUDY_INPROCESS_S must be a number of seconds >= 0 (0: every study of more than "
            "STUDY_INPROCESS_POINTS points on Dask), not nan",
        ),
        (
            "STUDY_INPROCESS_S",
            "inf",
            "STUDY_INPROCESS_S must be a number of seconds >= 0 (0: every study of more than "
            "STUDY_INPROCESS_POINTS points on Dask), not inf",
        ),
        ("STUDY_MAX_POINTS", "lots", "STUDY_MAX_POINTS must be an integer, not 'lots'"),
        ("STUDY_KEEP_S", "1 h", "STUDY_KEEP_S must be a number, not '1 h'"),
    ],
)
def test_nonsense_is_refused_naming_the_variable_and_range(
    monkeypatch: pytest.MonkeyPatch, variable: str, value: str, message: str
) -> None:
    monkeypatch.setenv(variable, value)
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        StudySettings()
    # at start-up: building the app reads the settings and stops there
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        create_app(models=[])


def test_settings_given_in_python_are_checked_too() -> None:
    with pytest.raises(ValueError, match=r"^STUDY_MAX_ACTIVE must be an integer >= 1, not 0$"):
        StudySettings(max_active=0)
