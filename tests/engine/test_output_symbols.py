"""Every scalar result declares its symbol and the step it comes from (the report prints both).

An auditor reads "F_M,zul · VDI 2230-1 R7" beside each number; the form no longer guesses
them from the description. A count, a flag or a label may declare symbol "" deliberately,
and a result no source states (an error estimate, a textbook stress) step "".
"""

from __future__ import annotations

from pathlib import Path

import pytest

from engine.core.sources import SOURCES, cited_ids
from engine.core.spec import Answer, ModelSpec, Output
from engine.models import MODELS


def problems(o: Output) -> list[str]:
    """What is wrong with one scalar output's symbol and step ([] when nothing)."""
    found = []
    if o.symbol is None:
        found.append("no symbol declared (give symbol='' for a count, a flag or a label)")
    elif o.symbol != o.symbol.strip() or "=" in o.symbol:
        found.append(f"symbol {o.symbol!r} is not a symbol")
    if o.step is None:
        found.append("no step declared")
    elif o.step:
        ids = cited_ids(o.step)
        if not ids:
            found.append(f"step {o.step!r} cites no source")
        unknown = sorted(ids - set(SOURCES))
        if unknown:
            found.append(f"step {o.step!r} cites {unknown}, not in engine/core/sources.py")
    elif cited_ids(o.description):
        found.append(f"its description cites {sorted(cited_ids(o.description))}: step is ''")
    return found


SCALARS = [(m.name, o) for m in MODELS for o in m.outputs if not o.series]


@pytest.mark.parametrize(("model", "output"), SCALARS, ids=[f"{m}.{o.name}" for m, o in SCALARS])
def test_every_scalar_output_declares_its_symbol_and_step(model: str, output: Output) -> None:
    assert problems(output) == []


def test_the_check_catches_what_it_is_for() -> None:
    """Undeclared, a formula for a symbol, an unknown or absent citation: each is reported."""
    assert len(problems(Output("x", "N", "a force"))) == 2
    assert problems(Output("x", "N", "a force", symbol="F = m a", step="VDI 2230-1 R7")) == [
        "symbol 'F = m a' is not a symbol"
    ]
    assert problems(Output("x", "N", "a force", symbol="F", step="[999, eq. 1]")) == [
        "step '[999, eq. 1]' cites ['999'], not in engine/core/sources.py"
    ]
    assert problems(Output("x", "N", "a force", symbol="F", step="the handbook")) == [
        "step 'the handbook' cites no source"
    ]
    assert problems(Output("x", "N", "F ([004, eq. 2])", symbol="F", step="")) == [
        "its description cites ['004']: step is ''"
    ]
    assert problems(Output("n", "1", "count", kind="int", symbol="", step="")) == []


def test_the_joint_cites_the_vdi_steps_as_the_standard_numbers_them() -> None:
    """Published step numbers of VDI 2230-1:2015 for the joint's headline results."""
    joint = {o.name: o for o in next(m for m in MODELS if m.name == "joint.vdi2230").outputs}
    expected = {
        "required_clamp_force": ("F_K,erf", "VDI 2230-1 R2"),
        "load_factor": ("Φ_n", "VDI 2230-1 R3"),
        "embedding_loss": ("F_Z", "VDI 2230-1 R4"),
        "required_preload_min": ("F_M,min", "VDI 2230-1 R5"),
        "permissible_preload": ("F_M,zul", "VDI 2230-1 R7"),
        "working_stress": ("σ_red,B", "VDI 2230-1 R8"),
        "fatigue_safety": ("S_D", "VDI 2230-1 R9"),
        "slip_safety": ("S_G", "VDI 2230-1 R12"),
        "tightening_torque": ("M_A", "VDI 2230-1 R13"),
    }
    assert {n: (joint[n].symbol, joint[n].step) for n in expected} == expected


def test_the_catalogue_carries_symbol_and_step() -> None:
    tightening = next(m for m in MODELS if m.name == "preload.tightening").describe()
    torque = next(o for o in tightening["outputs"] if o["name"] == "tightening_torque")
    assert (torque["symbol"], torque["step"]) == ("M_A", "[004, eq. 13]")
    # a series has no row in the table: it still carries the keys, empty
    joint = next(m for m in MODELS if m.name == "joint.vdi2230").describe()
    series = next(o for o in joint["outputs"] if o["series"])
    assert (series["symbol"], series["step"]) == ("", "")


def test_no_engine_source_holds_a_control_character() -> None:
    """A docstring's \\frac or \\text in a string that is not raw becomes a form feed or a
    tab: the printed report then shows "rac{T}{P} ext{…}" (the blow's time between blows did)."""
    engine_dir = Path(__file__).resolve().parents[2] / "engine"
    bad = [
        (str(f.relative_to(engine_dir)), n)
        for f in sorted(engine_dir.rglob("*.py"))
        for n, line in enumerate(f.read_text(encoding="utf-8").split("\n"), 1)
        if any(ord(c) < 32 and c != "\r" for c in line)
    ]
    assert bad == []


ANSWERS = [(m, a) for m in MODELS for a in m.answer]


@pytest.mark.parametrize(
    ("model", "answer"), ANSWERS, ids=[f"{m.name}.{a.output}" for m, a in ANSWERS]
)
def test_the_answer_card_writes_each_result_with_the_symbol_the_table_does(
    model: ModelSpec, answer: Answer
) -> None:
    """One symbol per result: the card's "C_m/C_p = 1.9 ≥ C_req" reads as the table's rows."""
    outputs = {o.name: o for o in model.outputs}
    assert answer.symbol == outputs[answer.output].symbol
    if isinstance(answer.bound, str):  # a bound that is another result is written as it is
        assert answer.bound_symbol == outputs[answer.bound].symbol
