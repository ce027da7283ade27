"""impact.rare_design: the design found passes impact.rare itself, a passing design is
returned unchanged, a range too narrow reports "none" with its binding check.

The issue's situation (EDGE_BLOW): at c1 = 60 N/mm the striker lands an edge blow; a
stiffer power spring clears it at 65 N/mm, and c3 = 65.5 N/mm stops being above c1 at
66 N/mm. Changing c1 to 65 and c3 to 66 N/mm passes every check (held below), a change of
Δ = √((5/60)² + (0.5/65.5)²) = 0.0837: the nearest design cannot be farther than that.
"""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models.rare_design import EDGE_BLOW, RARE_DESIGN, SPRINGS, VARIABLES
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from tests.pins import pin

M = "impact.rare_design"


def _impact(design: dict) -> dict:
    r = run(RARE_IMPACT, design, fidelity="closed_form")
    return {c.name: c.ok for c in r.checks} | {"_results": r.results}


def _found(r) -> dict:
    return {**EDGE_BLOW, **{n: r.results[f"new_{n}"] for n in VARIABLES}}


def test_the_issue_case_fails_and_a_known_change_passes() -> None:
    before = _impact(EDGE_BLOW)
    assert not before["full engagement"] and before["c3 > c1"]
    stiffer = _impact({**EDGE_BLOW, "power_spring_rate": 66000.0})
    assert stiffer["full engagement"] and not stiffer["c3 > c1"]
    known = _impact({**EDGE_BLOW, "power_spring_rate": 65000.0, "return_spring_rate": 66000.0})
    assert all(v for k, v in known.items() if k != "_results")


def test_the_design_found_passes_every_check_of_impact_rare_itself() -> None:
    r = run(RARE_DESIGN, EDGE_BLOW)
    v = r.results
    assert v["found"] is True and v["binding_checks"] == ""
    found = _impact(_found(r))
    assert all(ok for k, ok in found.items() if k != "_results"), found
    assert all(c.ok for c in r.checks) and len(r.checks) == 6
    # no farther than the known passing change (c1 65, c3 66 N/mm), and not nothing
    bound = math.hypot(5.0 / 60.0, 0.5 / 65.5)
    assert bound == pytest.approx(0.08373, rel=1e-3)
    assert 0.0 < v["design_change"] <= bound
    # Δ by hand from the changes it reports
    delta = math.sqrt(sum(v[f"change_{n}"] ** 2 for n in SPRINGS))
    pin(M, "design_change", v["design_change"], delta, rel=1e-9)
    for n in VARIABLES:
        pin(M, f"change_{n}", v[f"change_{n}"], v[f"new_{n}"] / EDGE_BLOW[n] - 1.0, rel=1e-9)
    # the striker's mass is not a variable unless asked: unchanged
    pin(M, "new_striker_mass", v["new_striker_mass"], 0.4, rel=0)
    pin(M, "change_striker_mass", v["change_striker_mass"], 0.0, abs=0)
    # its outputs are impact.rare's single run of the design found
    res = found["_results"]
    pin(M, "engagement_margin", v["engagement_margin"], res["engagement_margin"], rel=1e-12)
    assert v["engagement_margin"] >= 0.0
    # re-lock margin by hand, [002, eq. 4]: c2 λ2 + m2 g − c3 λ3 f
    relock = (
        v["new_auxiliary_spring_rate"] * v["new_auxiliary_spring_preload"]
        + 0.05 * 9.80665
        - v["new_return_spring_rate"] * v["new_return_spring_preload"] * 0.1
    )
    pin(M, "relock_margin", v["relock_margin"], relock, rel=1e-9)
    pin(M, "cycle_time", v["cycle_time"], res["cycle_time"], rel=1e-12)
    # every change within the declared ±50 %
    assert all(abs(v[f"change_{n}"]) <= 0.5 for n in VARIABLES)
    assert v["designs_passing"] > 0 and v["designs_evaluated"] > 4001


def test_a_passing_design_is_returned_with_zero_change() -> None:
    r = run(RARE_DESIGN, REFERENCE_DESIGN)
    v = r.results
    for n in VARIABLES:
        pin(M, f"new_{n}", v[f"new_{n}"], REFERENCE_DESIGN[n], rel=0)
        pin(M, f"change_{n}", v[f"change_{n}"], 0.0, abs=0)
    pin(M, "design_change", v["design_change"], 0.0, abs=0)
    pin(M, "designs_evaluated", v["designs_evaluated"], 1)  # the base alone
    pin(M, "designs_passing", v["designs_passing"], 1)
    assert v["found"] is True and v["binding_checks"] == ""
    # the reference design's re-lock margin by hand: 2000·0.008 + 0.05·9.80665 − 52000·0.0021·0.1
    pin(M, "relock_margin", v["relock_margin"], 16.0 + 0.4903325 - 10.92, rel=1e-12)
    assert "nothing to change" in r.notes[1]


def test_a_range_too_narrow_reports_none_and_the_binding_check() -> None:
    # ±2 %: the edge blow needs c1 up by about 8 % (it clears between 64 and 65 N/mm)
    r = run(RARE_DESIGN, {**EDGE_BLOW, "change_limit": 0.02})
    v = r.results
    assert v["found"] is False
    assert v["binding_checks"] == "full engagement"
    pin(M, "designs_passing", v["designs_passing"], 0)
    pin(M, "designs_evaluated", v["designs_evaluated"], 4001)  # the base and 4000 samples
    assert not all(c.ok for c in r.checks)
    assert any("no design within ±2 %" in n for n in r.notes)


def test_the_striker_mass_moves_only_when_asked() -> None:
    r = run(RARE_DESIGN, {**EDGE_BLOW, "vary_striker_mass": True})
    v = r.results
    assert v["found"] is True
    found = _impact(_found(r))
    assert all(ok for k, ok in found.items() if k != "_results")
    assert abs(v["change_striker_mass"]) <= 0.5
