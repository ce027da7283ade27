"""An error estimate says what it promises: a bound, or typical with its measured share.

The label (``Rung.estimate_kind``) reaches the catalogue, every result (``error_kind``
and a note), the notes of ``fidelity: "auto"`` when it picks a typical rung by its
estimate, the fallback's note, a sweep's notes and the service's answer. Shown on the
toy disc (tests/toys.py) with its rough rung relabelled typical.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import pytest
from fastapi.testclient import TestClient

import engine
from engine import BudgetExceeded, Result, RunContext, Rung, fixed_error
from service import create_app
from tests.toys import TOY

BASE = {"diameter": 0.2}
SHARE = "18 % of 200 random designs (worst 6.2×)"
CAVEAT = f"the error estimate of 'rough' is typical, not a bound: exceeded in {SHARE}"

#: TOY with its 5 % rung declared typical: cheap and usually, not always, within 5 %.
TYPICAL = replace(
    TOY,
    rungs=(
        Rung(
            "rough", "5 % off", fixed_error(0.05), estimate_kind="typical", typical_exceeded=SHARE
        ),
        Rung("exact", "exact", fixed_error(1e-15)),
    ),
)


def test_a_rung_is_a_bound_unless_declared_typical() -> None:
    assert TOY.rung("rough").estimate_kind == "bound" and TOY.rung("rough").estimate_caveat == ""
    assert TYPICAL.rung("rough").estimate_caveat == CAVEAT
    unmeasured = Rung("r", "", fixed_error(0.1), estimate_kind="typical")
    assert unmeasured.estimate_caveat == (
        "the error estimate of 'r' is typical, not a bound: how often it is exceeded is not "
        "measured"
    )


@pytest.mark.parametrize(
    ("kwargs", "fragment"),
    [
        ({"estimate_kind": "usually"}, "estimate_kind = 'usually' is not allowed"),
        ({"typical_exceeded": "3 % of 200"}, "stated for an estimate declared a bound"),
    ],
)
def test_a_label_that_says_nothing_is_refused(kwargs: dict[str, Any], fragment: str) -> None:
    with pytest.raises(ValueError, match=fragment):
        Rung("r", "", fixed_error(0.1), **kwargs)


def test_the_catalogue_carries_the_kind_and_the_measured_share() -> None:
    rough, exact = TYPICAL.describe()["rungs"]
    assert (rough["estimate_kind"], rough["typical_exceeded"]) == ("typical", SHARE)
    assert (exact["estimate_kind"], exact["typical_exceeded"]) == ("bound", "")


def test_every_registered_rung_declares_a_kind() -> None:
    for spec in engine.MODELS:
        for rung in spec.describe()["rungs"]:
            assert rung["estimate_kind"] in ("bound", "typical"), (spec.name, rung["name"])
            assert (rung["estimate_kind"] == "typical") or rung["typical_exceeded"] == ""


def test_a_result_says_whether_its_estimate_is_a_bound() -> None:
    bound = engine.run(TOY, BASE, fidelity="rough")
    assert bound.error_estimate == 0.05 and bound.error_kind == "bound"
    assert not any("typical" in n for n in bound.notes)
    typical = engine.run(TYPICAL, BASE, fidelity="rough")
    assert typical.error_estimate == 0.05 and typical.error_kind == "typical"
    assert typical.notes.count(CAVEAT) == 1
    exact = engine.run(TYPICAL, BASE, fidelity="exact")
    assert exact.error_kind == "bound" and not any("typical" in n for n in exact.notes)


def test_no_estimate_no_kind() -> None:
    def unknown(x: Mapping[str, Any], ctx: RunContext) -> Result:
        return Result(values={"energy": 1.0}, rung=ctx.rung, error_estimate=None)

    r = engine.run(replace(TYPICAL, compute=unknown), BASE, fidelity="rough")
    assert r.error_estimate is None and r.error_kind is None and CAVEAT not in r.notes


def test_auto_says_when_the_estimate_it_chose_by_is_typical() -> None:
    # tolerance 10 % > rough's 5 %: auto takes the cheap rung, by an estimate that is typical
    loose = engine.run(TYPICAL, BASE, tolerance=0.1)
    assert loose.rung == "rough" and loose.error_kind == "typical"
    assert loose.notes[0] == (
        f"auto: chose 'rough', estimated error 0.05 ≤ tolerance 0.1; {CAVEAT}"
    )
    assert sum(CAVEAT in n for n in loose.notes) == 1  # said once, where the choice is
    # 1 % < 5 %: the exact rung, a bound; nothing to say about the rough one
    tight = engine.run(TYPICAL, BASE, tolerance=0.01)
    assert tight.rung == "exact" and not any("typical" in n for n in tight.notes)


def test_auto_says_so_when_no_rung_meets_the_tolerance() -> None:
    only_rough = replace(TYPICAL, rungs=TYPICAL.rungs[:1])
    r = engine.run(only_rough, BASE, tolerance=0.01)
    assert r.notes[0] == (
        "auto: no rung meets tolerance 0.01; ran the most accurate, 'rough' "
        f"(estimated error 0.05) ({CAVEAT})"
    )
    assert sum(CAVEAT in n for n in r.notes) == 1


def _declines(x: Mapping[str, Any], ctx: RunContext) -> Result:
    if ctx.rung == "exact":
        raise BudgetExceeded("too many steps", expected_steps=1e9, step_budget=1e6)
    return Result(values={"energy": 42.0}, rung=ctx.rung, error_estimate=0.05)


def test_the_fallback_note_says_its_estimate_is_typical() -> None:
    spec = replace(
        TYPICAL,
        compute=_declines,
        rungs=(TYPICAL.rungs[0], Rung("exact", "expensive", fixed_error(1e-2), fallback="rough")),
    )
    r = engine.run(spec, BASE, tolerance=0.02)  # auto: exact (1 %), which declines
    assert r.rung == "rough" and r.error_kind == "typical"
    (note,) = [n for n in r.notes if "declared fallback" in n]
    assert note.endswith(f"error is 0.05: the tolerance 0.02 is not met ({CAVEAT})")
    assert sum(CAVEAT in n for n in r.notes) == 1


def test_a_sweep_says_once_that_the_rung_it_ran_is_typical() -> None:
    s = engine.sweep(TYPICAL, BASE, "diameter", [0.1, 0.2, 0.3], fidelity="rough")
    assert s.rungs == ["rough"] * 3 and s.notes.count(CAVEAT) == 1
    exact = engine.sweep(TYPICAL, BASE, "diameter", [0.1, 0.2], fidelity="exact")
    assert not any("typical" in n for n in exact.notes)


def test_the_service_answer_and_catalogue_carry_the_kind() -> None:
    client = TestClient(create_app(models=[TYPICAL]))
    (m,) = client.get("/api/v1/models").json()["models"]
    assert [(r["estimate_kind"], r["typical_exceeded"]) for r in m["rungs"]] == [
        ("typical", SHARE),
        ("bound", ""),
    ]
    rough = client.post("/api/v1/toy/disc", json={**BASE, "fidelity": "rough"}).json()
    assert (rough["error_estimate"], rough["error_kind"]) == (0.05, "typical")
    assert CAVEAT in rough["notes"]
    exact = client.post("/api/v1/toy/disc", json={**BASE, "fidelity": "exact"}).json()
    assert exact["error_kind"] == "bound"
