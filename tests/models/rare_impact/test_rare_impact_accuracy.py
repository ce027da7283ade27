"""What bench/accuracy_striker.py measures, held (issue 29, "Estimates that bound").

200 seeded random designs against the simulation at 4000 RK4 steps a period: every estimate
labelled a bound is exceeded by none; the closed form's return group, labelled typical, by
no more than the model's label says (0.8 %, worst 98×).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[3]))

from bench.accuracy_striker import rows
from engine.models.rare_impact import CLOSED_FORM_EXCEEDED, RARE_IMPACT


@pytest.mark.slow
def test_the_striker_estimates_bound_or_say_how_often_not() -> None:
    table = rows(200, 0)
    assert len(table) == 15
    for row in table:
        assert row["skipped"] == 0
        if row["kind"] == "bound":
            assert row["exceeded"] == 0, row
            assert row["n"] == 200, row
        else:  # the closed form's return group
            assert row["rung"] == "closed_form" and row["output"] in (
                "return_time", "striker_home_time", "cycle_time"
            )  # fmt: skip
            assert row["exceeded"] <= 1 and row["worst_ratio"] < 100.0, row
            assert row["n"] + row["no_claim"] == 200
    assert "0.8 % of 123" in CLOSED_FORM_EXCEEDED
    rung = RARE_IMPACT.rungs[0]
    assert getattr(rung, "estimate_kind", "typical") == "typical"
