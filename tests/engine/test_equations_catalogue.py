"""The catalogue's equations (for the calculation report) and choice labels."""

from __future__ import annotations

import dataclasses

import pytest

import engine
from engine import preload
from engine.equations import equations_of
from engine.spec import Param
from tests.toys import TOY


def test_equations_follow_the_calls_and_keep_their_source() -> None:
    eqs = equations_of(preload.thread_torque)
    assert [e["function"] for e in eqs] == ["thread_torque", "lead_angle", "thread_friction_angle"]
    assert eqs[0]["latex"] == ["M_p = F_0 \\frac{d_2}{2}\\tan(\\psi + \\rho')"]
    assert eqs[0]["source"] == "[004, eq. 10]"
    assert eqs[0]["summary"].startswith("Torque to turn the nut against the thread")


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_every_model_lists_its_equations(spec) -> None:
    eqs = spec.describe()["equations"]
    # each registered model documents the equations it uses, each with its LaTeX
    assert 3 <= len(eqs) <= 16, [e["function"] for e in eqs]
    assert all(e["latex"] and all(x.strip() for x in e["latex"]) for e in eqs)
    assert len({e["function"] for e in eqs}) == len(eqs)


def test_the_preload_model_uses_the_stress_area_and_the_torque() -> None:
    spec = next(s for s in engine.MODELS if s.name == "preload.tightening")
    names = [e["function"] for e in spec.describe()["equations"]]
    assert "stress_area" in names and "thread_torque" in names and "friction_radius" in names


def test_choice_labels_are_described_and_must_match_the_choices() -> None:
    p = Param("mode", "1", "mode", kind="choice", choices=("a", "b"), choice_labels=("A", "B"))
    assert p.describe()["choice_labels"] == ["A", "B"]
    assert Param("x", "m", "x").describe()["choice_labels"] is None
    bad = dataclasses.replace(p, name="mode_2", choice_labels=("A",))
    with pytest.raises(ValueError, match="one choice label per choice"):
        dataclasses.replace(TOY, inputs=(*TOY.inputs, bad))
