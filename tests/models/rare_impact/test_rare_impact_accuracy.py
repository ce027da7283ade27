"""What bench/accuracy_striker.py measures, held (issue 29, "Estimates that bound").

200 seeded random designs against the simulation at 4000 RK4 steps a period: every estimate
is a bound and none is exceeded; a closed-form design with no estimate (rollers that fly at
the blow, a turning point too near a level) makes no claim and is counted apart.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[3]))

from bench.accuracy_striker import rows
from engine.models.rare_impact import RARE_IMPACT


@pytest.mark.slow
def test_the_striker_estimates_bound() -> None:
    table = rows(200, 0)
    assert len(table) == 15
    for row in table:
        assert row["skipped"] == 0
        assert row["kind"] == "bound"
        assert row["exceeded"] == 0, row
        assert row["worst_ratio"] < 1.0, row
        assert row["n"] + row["no_claim"] == 200, row
        if row["rung"] == "simulation" or row["output"] not in (
            "return_time", "striker_home_time", "cycle_time"
        ):  # fmt: skip
            assert row["no_claim"] == 0, row
    for rung in RARE_IMPACT.rungs:
        assert getattr(rung, "estimate_kind", "bound") == "bound"
