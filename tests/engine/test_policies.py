"""One policy per concern, declared in the spec and carried out by the runner.

Output filtering (models return what they computed; the runner keeps what was
asked), rung fallback (``Rung.fallback``), static assumptions
(``ModelSpec.assumptions``) and plot metadata (``Output.plot``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import pytest

import engine
from engine import BudgetExceeded, Output, Plot, Result, RunContext, Rung, Window, fixed_error
from tests.toys import TOY

BASE = {"diameter": 0.2}


def _everything(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """Returns every output and series whatever was asked: the runner must filter."""
    return Result(
        values={"inertia": 1.0, "energy": 2.0, "ratio": 3.0, "fast": True},
        rung=ctx.rung,
        error_estimate=0.0,
        series={"spin": [0.0, 1.0]},
    )


def test_the_runner_keeps_only_the_outputs_asked_for():
    spec = replace(TOY, compute=_everything)
    r = engine.run(spec, BASE, outputs=["energy"])
    assert r.results == {"energy": 2.0} and r.series == {} and set(r.units) == {"energy"}
    r = engine.run(spec, BASE, outputs=["spin"])
    assert r.results == {} and r.series == {"spin": [0.0, 1.0]}
    r = engine.run(spec, BASE)
    # series only when asked for (issue 21: model only what the scene requires)
    assert set(r.results) == {"inertia", "energy", "ratio", "fast"} and r.series == {}
    r = engine.run(spec, BASE, series=True)
    assert set(r.results) == {"inertia", "energy", "ratio", "fast"} and "spin" in r.series


def test_no_registered_model_filters_its_own_outputs():
    """The runner filters; a model that also filtered would hide a second policy."""
    import inspect

    for spec in engine.MODELS:
        source = inspect.getsource(inspect.getmodule(spec.compute))  # type: ignore[arg-type]
        assert "if ctx.wants(k)}" not in source and "if ctx.wants(n)}" not in source


def _declines(x: Mapping[str, Any], ctx: RunContext) -> Result:
    if ctx.rung == "exact":
        raise BudgetExceeded("would take 1e9 steps", field="fidelity", expected_steps=1e9)
    return Result(values={"energy": 42.0}, rung=ctx.rung, error_estimate=1e-3)


def _spec(rough_error: float, fallback: str | None = "rough") -> engine.ModelSpec:
    return replace(
        TOY,
        compute=_declines,
        rungs=(
            Rung("rough", "cheap", fixed_error(rough_error)),
            Rung("exact", "expensive", fixed_error(1e-2), fallback=fallback),
        ),
    )


def test_a_rung_that_declines_up_front_runs_its_declared_fallback_and_says_so():
    r = engine.run(_spec(1e-3), BASE, fidelity="exact")
    assert r.rung == "rough" and r.results["energy"] == 42.0
    assert any("would need about 1e+09 steps" in n and "'rough' instead" in n for n in r.notes)


def test_no_fallback_when_it_would_be_less_accurate_or_none_is_declared():
    with pytest.raises(BudgetExceeded):
        engine.run(_spec(0.5), BASE, fidelity="exact")  # 0.5 > the exact rung's 1e-2
    with pytest.raises(BudgetExceeded):
        engine.run(_spec(1e-3, fallback=None), BASE, fidelity="exact")


def test_a_deadline_overrun_part_way_is_not_rescued():
    def overran(x: Mapping[str, Any], ctx: RunContext) -> Result:
        raise BudgetExceeded("stopped at its wall-clock budget")

    spec = replace(_spec(1e-3), compute=overran)
    with pytest.raises(BudgetExceeded, match="wall-clock"):
        engine.run(spec, BASE, fidelity="exact")


def test_rare_impact_declares_its_fallback():
    rare = engine.get_model("impact.rare")
    assert rare.rung("simulation").fallback == "closed_form"
    assert rare.describe()["rungs"][1]["fallback"] == "closed_form"


def test_assumptions_reach_every_answer_and_the_catalogue():
    spec = replace(TOY, assumptions=("discs are uniform",))
    r = engine.run(spec, BASE)
    assert "discs are uniform" in r.notes
    assert spec.describe()["assumptions"] == ["discs are uniform"]
    for model in engine.MODELS:
        notes = engine.run(model, dict(model.examples[0])).notes
        assert all(a in notes for a in model.assumptions), model.name


def test_plot_metadata_is_declared_and_checked():
    rare = engine.get_model("impact.rare")
    time = next(o for o in rare.outputs if o.name == "time")
    assert time.describe()["plot"]["windows"][0] == {
        "label": "engagement window",
        "start": "engagement_start",
        "end": "engagement_end",
    }
    counts = next(o for o in engine.get_model("preload.control").outputs if o.x == "preload_bins")
    assert counts.plot is not None and counts.plot.bars
    bad_window = Output(
        "spin", "rad/s", "s", series=True, plot=Plot(windows=(Window("w", "a", "b"),))
    )
    with pytest.raises(ValueError, match="window 'w' names 'a'"):
        replace(TOY, outputs=(*TOY.outputs[:-1], bad_window))
    with pytest.raises(ValueError, match="plotted against 'nothing'"):
        replace(
            TOY, outputs=(*TOY.outputs[:-1], Output("spin", "1", "s", series=True, x="nothing"))
        )
    with pytest.raises(ValueError, match="falls back to unknown 'nope'"):
        replace(TOY, rungs=(Rung("rough", "r", fixed_error(0.1), fallback="nope"),))
