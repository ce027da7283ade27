"""bench/accuracy_audit.py's measurement held as a test: joint.audit's windows and
preload.ultrasonic's chain agree with their independent references to float rounding, the
error 0 they state."""

import pytest

from bench import accuracy_audit


@pytest.mark.slow
def test_no_estimate_is_exceeded_on_100_random_designs():
    rows = accuracy_audit.rows(100, seed=0)
    assert {r["model"] for r in rows} == {"joint.audit", "preload.ultrasonic"}
    assert len(rows) == 14
    for row in rows:
        where = f"{row['model']} {row['rung']} {row['output']}"
        assert row["n"] == 100, where
        assert row["exceeded"] == 0, where
        assert row["worst_ratio"] <= 1.0, where
        assert row["kind"] == "bound", where
