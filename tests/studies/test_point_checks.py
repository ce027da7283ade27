"""A study's looped points: the checks made once a chunk give what each point's own checks
gave, a chunk whose checks refuse refuses each point as before, a study's tolerance is
refused as engine.run refuses it, and the cycle without its sentences is the same cycle."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import engine
from engine.core.runner import DEFAULT_MAX_STEPS, point_outputs, run_point
from engine.models.rare_impact import REFERENCE_DESIGN
from engine.procedures import striker_cycle
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable, evaluate_chunk

SPEC = engine.get_model("impact.rare")
EXAMPLE = dict(SPEC.examples[0])
OUTPUTS = ("release_speed", "engagement_time", "half_coupling_release_speed")


def _point(rung: str, checked: frozenset[str] | None) -> tuple[str, dict, list]:
    return run_point(
        SPEC,
        dict(EXAMPLE),
        rung,
        OUTPUTS,
        tolerance=0.05,
        budget_s=None,
        max_steps=DEFAULT_MAX_STEPS,
        checked=checked,
    )


@pytest.mark.parametrize("rung", ["closed_form", "simulation"])
def test_a_point_checked_once_a_chunk_is_the_point_checked_alone(rung: str) -> None:
    checked = point_outputs(SPEC, EXAMPLE, rung, OUTPUTS, 0.05)
    assert checked == frozenset(OUTPUTS)
    alone = _point(rung, None)
    assert _point(rung, checked) == alone
    assert alone[0] == rung
    # the reference design's release speed, 244 rad/s (the cycle's doctest)
    assert alone[1]["release_speed"] == pytest.approx(244.1, abs=0.5)


def test_the_chunk_checks_refuse_as_each_point_did() -> None:
    """A tolerance out of its range on a named looped rung: every point refused, naming it."""
    m = EXAMPLE["roller_mass"]
    columns = {"roller_mass": np.array([0.95 * m, m, 1.05 * m])}
    base = {k: v for k, v in EXAMPLE.items() if k != "roller_mass"}
    part = evaluate_chunk(SPEC, base, columns, OUTPUTS, "simulation", 2.0)
    assert part.rungs == [None, None, None]
    assert sum(part.refusals.values()) == 3
    (reason,) = part.refusals
    assert reason == "InputOutOfRange: tolerance = … is not allowed"
    assert np.isnan(part.values["release_speed"]).all()
    bad = evaluate_chunk(SPEC, base, columns, ("no_such_output",), "simulation", 0.05)
    assert sum(bad.refusals.values()) == 3
    assert "unknown output(s) no_such_output" in next(iter(bad.refusals))


@pytest.mark.parametrize("fidelity", ["closed_form", "simulation"])
def test_a_studys_tolerance_is_refused_as_a_run_refuses_it(fidelity: str) -> None:
    m = EXAMPLE["roller_mass"]
    study = Study(
        variables=(Variable("roller_mass", "uniform", low=0.9 * m, high=1.1 * m),),
        base={k: v for k, v in EXAMPLE.items() if k != "roller_mass"},
        samples=5,
        seed=1,
        fidelity=fidelity,
        tolerance=2.0,
    )
    with pytest.raises(engine.EngineError, match="tolerance = 2 is not allowed") as study_err:
        run_study(SPEC, study)
    with pytest.raises(engine.EngineError, match="tolerance = 2 is not allowed") as run_err:
        engine.run(SPEC, EXAMPLE, fidelity=fidelity, tolerance=2.0)
    assert study_err.value.field == run_err.value.field == "tolerance"


#: A design near the reference whose return goes one-sided (the rollers let go at the blow),
#: so the note left out without sentences is there with them.
ONE_SIDED = {
    "flywheel_inertia": 1.115797, "motor_torque": 0.831794, "roller_mass": 0.692656,
    "roller_radius": 0.679242, "cone_angle": 1.284817, "half_coupling_mass": 1.391253,
    "stepped_shaft_mass": 1.089053, "striker_mass": 1.201532, "power_spring_rate": 1.035516,
    "auxiliary_spring_rate": 1.416314, "return_spring_rate": 1.287475,
    "power_spring_preload": 0.67179, "auxiliary_spring_preload": 1.330991,
    "return_spring_preload": 0.688575, "release_travel": 1.201685,
    "engagement_height": 0.771456, "jaw_height": 1.337154, "engagement_angle": 1.033725,
    "roller_friction": 0.851947,
}  # fmt: skip


@pytest.mark.parametrize("design", ["reference", "one_sided"])
def test_the_cycle_without_sentences_is_the_same_cycle(design: str) -> None:
    x = {**REFERENCE_DESIGN, "roller_geometry": "symmetric_v"}
    if design == "one_sided":
        x.update({k: REFERENCE_DESIGN[k] * f for k, f in ONE_SIDED.items()})
    said = striker_cycle.simulate_cycle(x)
    quiet = striker_cycle.simulate_cycle(x, sentences=False)
    assert dataclasses.replace(said, notes=[]) == dataclasses.replace(quiet, notes=[])
    assert set(quiet.notes) <= set(said.notes)
    if design == "one_sided":
        assert any("one-sided" in n for n in said.notes)
        assert not any("one-sided" in n for n in quiet.notes)


@pytest.mark.parametrize("rung", ["closed_form", "simulation"])
def test_a_point_under_the_chunks_error_state_is_the_point_alone(rung: str) -> None:
    """run_point(silenced=True) under the chunk's one np.errstate gives what it gives alone,
    every output (nulls included) and verdict; a refusal of failed arithmetic still refuses."""
    outputs = tuple(o.name for o in SPEC.outputs if not o.series)
    designs = [dict(EXAMPLE), {**EXAMPLE, "return_spring_rate": 0.5 * EXAMPLE["power_spring_rate"]}]
    for values in designs:
        alone = run_point(SPEC, dict(values), rung, outputs, tolerance=0.05, budget_s=None)
        with np.errstate(all="ignore"):
            quiet = run_point(
                SPEC, dict(values), rung, outputs, tolerance=0.05, budget_s=None, silenced=True
            )
        assert repr(quiet) == repr(alone)
        assert list(quiet[1]) == list(outputs)


@pytest.mark.parametrize("rung", ["closed_form", "simulation"])
def test_a_looped_point_is_engine_run_field_by_field(rung: str) -> None:
    """Every output of a looped point (run_point, no sentences, the values as computed and
    converted once) equals engine.run's, nulls included: the simulation's speed of the
    half-coupling at release, and None for it on the closed form."""
    every = tuple(SPEC.scalar_output_names)
    _, point, _ = run_point(
        SPEC, dict(EXAMPLE), rung, every, tolerance=0.05, budget_s=None, max_steps=DEFAULT_MAX_STEPS
    )
    alone = engine.run(SPEC, EXAMPLE, fidelity=rung, outputs=list(every)).results
    assert point == {k: alone[k] for k in every}
    speed = point["half_coupling_release_speed"]
    if rung == "simulation":
        assert isinstance(speed, float) and speed > 0.0
    else:
        assert speed is None


def test_a_chunks_loop_runs_its_points_under_numpys_quiet_error_state(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The chunk enters numpy's error state for its loop (run_point(silenced=True) relies
    on it), and leaves the caller's as it was."""
    from engine.studies import plan as plan_module

    seen: list[dict[str, str]] = []
    kept = plan_module.run_point

    def looked(*args, **kwargs):  # type: ignore[no-untyped-def]
        seen.append(np.geterr())
        assert kwargs.get("silenced") is True
        return kept(*args, **kwargs)

    monkeypatch.setattr(plan_module, "run_point", looked)
    m = EXAMPLE["roller_mass"]
    base = {k: v for k, v in EXAMPLE.items() if k != "roller_mass"}
    with np.errstate(all="raise"):
        part = evaluate_chunk(
            SPEC, base, {"roller_mass": np.array([m, 1.05 * m])}, OUTPUTS, "simulation", 0.05
        )
        assert np.geterr()["divide"] == "raise"
    assert part.rungs == ["simulation", "simulation"]
    assert len(seen) == 2
    assert all(set(state.values()) == {"ignore"} for state in seen)


@pytest.mark.parametrize("silenced", [False, True])
def test_failed_arithmetic_is_refused_silenced_or_not(silenced: bool) -> None:
    """_arithmetic_refused enters numpy's quiet error state unless told the caller holds it,
    and turns failed arithmetic into a refusal either way."""
    from engine.core.runner import _arithmetic_refused

    with np.errstate(all="raise"):
        with _arithmetic_refused(SPEC, silenced=silenced):
            inside = np.geterr()["over"]
        assert inside == ("raise" if silenced else "ignore")
        with (
            pytest.raises(engine.EngineError, match="cannot be evaluated") as err,
            _arithmetic_refused(SPEC, silenced=silenced),
        ):
            raise ZeroDivisionError("float division by zero")
    assert err.value.kind == "solver_failed"
