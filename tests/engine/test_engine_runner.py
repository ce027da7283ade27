import dataclasses
import math
from typing import Any

import numpy as np
import pytest

import engine
from engine import InfeasibleDesign, InputOutOfRange, Rung, fixed_error
from tests.toys import TOY
from tests.toys import _disc as toy_compute

BASE = {"diameter": 0.2}


def test_defaults_filled_and_exact_value():
    r = engine.run(TOY, BASE, fidelity="exact")
    # J = 1 * 0.2² / 8 = 0.005; T = 0.5 * 0.005 * 100² = 25
    assert r.results["inertia"] == pytest.approx(0.005, rel=1e-15)
    assert r.results["energy"] == pytest.approx(25.0, rel=1e-15)
    assert r.inputs["mass"] == 1.0 and r.inputs["extra_load"] is None
    assert r.units["energy"] == "J"
    assert r.rung == "exact" and r.elapsed_s >= 0


def test_auto_picks_cheapest_rung_meeting_tolerance():
    loose = engine.run(TOY, BASE, tolerance=0.1)
    tight = engine.run(TOY, BASE, tolerance=1e-3)
    assert loose.rung == "rough" and "auto: chose 'rough'" in loose.notes[0]
    assert tight.rung == "exact" and "rough 0.05" in tight.notes[0]
    assert loose.results["energy"] == pytest.approx(25.0 * 1.05)


def test_outputs_limit_the_work():
    r = engine.run(TOY, BASE, outputs=["inertia"])
    assert set(r.results) == {"inertia"} and r.series == {}


def test_non_finite_becomes_null_with_note():
    r = engine.run(TOY, {**BASE, "blowup": True})
    assert r.results["ratio"] is None
    assert any("ratio could not be computed" in n for n in r.notes)


@pytest.mark.parametrize(
    ("inputs", "field"),
    [
        ({"diameter": -1.0}, "diameter"),
        ({"diameter": 0.0}, "diameter"),
        ({"diameter": math.nan}, "diameter"),
        ({"diameter": math.inf}, "diameter"),
        ({"diameter": 0.1, "count": 2.5}, "count"),
        ({"diameter": 0.1, "angle": math.pi / 2}, "angle"),
        ({"diameter": 0.1, "mode": "other"}, "mode"),
        ({"diameter": 0.1, "colour": 1}, "colour"),
        ({}, "diameter"),
    ],
)
def test_out_of_range_names_field(inputs, field):
    with pytest.raises(InputOutOfRange) as info:
        engine.run(TOY, inputs)
    assert info.value.field == field
    assert field in info.value.message


def test_recommended_range_warns():
    r = engine.run(TOY, {**BASE, "speed": 600.0})
    assert any("recommends" in w for w in r.warnings)


def test_infeasible_raises():
    with pytest.raises(InfeasibleDesign):
        engine.run(TOY, {**BASE, "mode": "broken"})


def test_sweep_matches_single_runs():
    values = engine.sweep_values(0.1, 0.3, 5)
    s = engine.sweep(TOY, BASE, "diameter", values.tolist(), outputs=["energy"], fidelity="exact")
    for d, e in zip(s.values, s.results["energy"], strict=True):
        assert e == pytest.approx(0.5 * d**2 / 8 * 100.0**2)


def test_sweep_log_and_bounds():
    assert engine.sweep_values(1e-3, 1.0, 4, "log").tolist() == pytest.approx([1e-3, 1e-2, 1e-1, 1])
    with pytest.raises(InputOutOfRange):
        engine.sweep_values(0, 1, engine.MAX_SWEEP_POINTS + 1)


def test_vectorized_sweep_equals_loop_and_nulls_bad_points():
    values = [0.1, 1.0, 6.0]
    fast = engine.sweep(TOY, BASE, "diameter", values, outputs=["energy"], fidelity="exact")
    assert fast.results["energy"][:2] == pytest.approx([0.5 * d**2 / 8 * 1e4 for d in values[:2]])
    assert fast.results["energy"][2] is None and "1 of 3 points" in fast.notes[-1]
    slow = engine.sweep(TOY, BASE, "diameter", values[:2], outputs=["energy"], fidelity="rough")
    assert slow.rung == "rough" and slow.results["energy"][0] == pytest.approx(
        1.05 * 0.5 * 0.01 / 8 * 1e4
    )


def test_vectorized_sweep_checks_range():
    with pytest.raises(InputOutOfRange):
        engine.sweep(TOY, BASE, "diameter", [0.1, 20.0], fidelity="exact")


def test_vectorized_sweep_loops_when_the_array_path_lacks_an_asked_output():
    # the toy's array version gives only energy; inertia belongs to the rung, so the loop runs
    s = engine.sweep(TOY, BASE, "diameter", [0.1, 0.2], outputs=["inertia"], fidelity="exact")
    assert s.results["inertia"] == pytest.approx([0.1**2 / 8, 0.2**2 / 8])


def _speed_sensitive_toy():
    """TOY whose rough rung is 5 % off and says so only above 10 rad/s (estimate speed/1000)."""
    return dataclasses.replace(
        TOY,
        rungs=(
            Rung("rough", "off at speed", lambda x: x["speed"] / 1000.0),
            Rung("exact", "exact", fixed_error(1e-15)),
        ),
        vectorized=None,
    )


def test_auto_sweep_chooses_the_rung_per_point_and_says_so():
    toy = _speed_sensitive_toy()
    s = engine.sweep(toy, BASE, "speed", [1.0, 5.0, 50.0, 100.0], outputs=["energy"])
    # estimates 0.001, 0.005 ≤ 0.01 → rough; 0.05, 0.1 > 0.01 → exact
    assert s.rungs == ["rough", "rough", "exact", "exact"]
    assert s.error_estimates == pytest.approx([0.05, 0.05, 1e-15, 1e-15])
    assert s.rung == "rough, exact" and "rough at 2 points, exact at 2 points" in s.notes[0]
    e = [0.5 * 0.2**2 / 8 * w**2 for w in (1.0, 5.0, 50.0, 100.0)]
    assert s.results["energy"] == pytest.approx([1.05 * e[0], 1.05 * e[1], e[2], e[3]])
    # the same points swept the other way give the same values
    back = engine.sweep(toy, BASE, "speed", [100.0, 50.0, 5.0, 1.0], outputs=["energy"])
    assert back.results["energy"] == pytest.approx(s.results["energy"][::-1])


def test_auto_array_sweep_loops_when_points_choose_different_rungs():
    toy = dataclasses.replace(
        TOY,
        rungs=(Rung("rough", "off", lambda x: x["diameter"]), Rung("exact", "", fixed_error(0))),
        vector_rungs=("rough", "exact"),
    )
    s = engine.sweep(toy, BASE, "diameter", [0.001, 0.5], outputs=["energy"])
    assert s.rungs == ["rough", "exact"]  # not the first point's choice everywhere
    fixed = engine.sweep(toy, BASE, "diameter", [0.001, 0.5], outputs=["energy"], fidelity="rough")
    assert fixed.rungs == ["rough", "rough"] and fixed.error_estimates == [0.001, 0.5]


def test_tolerance_without_fidelity_means_auto():
    toy = dataclasses.replace(_speed_sensitive_toy(), default_fidelity="rough")
    assert engine.run(toy, BASE).rung == "rough"  # the default rung
    r = engine.run(toy, BASE, tolerance=0.01)  # speed 100: rough estimates 0.1
    assert r.rung == "exact" and r.notes[0].startswith("auto:")


def test_an_output_asked_by_name_comes_back_null_with_a_note_when_not_computed():
    def compute(x, ctx):
        return engine.Result(values={"inertia": 1.0}, rung=ctx.rung, error_estimate=0.0)

    toy = dataclasses.replace(TOY, compute=compute)
    r = engine.run(toy, BASE, outputs=["inertia", "energy"])
    assert r.results == {"inertia": 1.0, "energy": None}
    assert any("energy is not computed" in n for n in r.notes)
    assert "energy" not in engine.run(toy, BASE).results  # all outputs: only what was computed


def test_sweep_nulls_points_that_break_a_cross_field_range_and_names_them():
    def compute(x, ctx):
        if x["speed"] > 50.0:
            raise InputOutOfRange("mass must exceed speed / 50", field="mass")
        return toy_compute(x, ctx)

    toy = dataclasses.replace(TOY, compute=compute, vectorized=None)
    s = engine.sweep(toy, BASE, "speed", [10.0, 100.0], outputs=["energy"], fidelity="exact")
    assert s.results["energy"][1] is None and s.rungs == ["exact", None]
    assert "speed = 100: mass must exceed" in s.notes[-1]
    with pytest.raises(InputOutOfRange) as info:  # every point refused: the fixed input is at fault
        engine.sweep(toy, BASE, "speed", [60.0, 100.0], fidelity="exact")
    assert info.value.field == "mass"


def _never_scalar(x, ctx):
    raise AssertionError("a sweep on an array rung must not run points one by one")


def test_short_sweep_runs_the_array_path_and_estimates_each_point():
    # every sweep size takes the array path (was: loop below 2,001 points)
    toy = dataclasses.replace(TOY, compute=_never_scalar)
    s = engine.sweep(toy, BASE, "diameter", [0.1, 0.2, 0.3], outputs=["energy"], fidelity="exact")
    assert s.results["energy"] == pytest.approx([0.5 * d**2 / 8 * 1e4 for d in (0.1, 0.2, 0.3)])
    assert s.rungs == ["exact"] * 3 and s.error_estimates == [1e-15] * 3


def test_auto_array_sweep_groups_points_by_rung_in_order():
    # rough is an array rung (energy 5 % high), exact is not: each group takes its own path
    def rough_vectorized(x, ctx):
        r = toy_compute({**x, "diameter": 1.0}, ctx)  # the scalar toy for d = 1, scaled by d²
        return engine.Result(
            values={"energy": r.values["energy"] * np.asarray(x["diameter"]) ** 2},
            rung=ctx.rung,
            error_estimate=0.05,
        )

    calls = []

    def counted(x, ctx):
        calls.append(x["diameter"])
        return toy_compute(x, ctx)

    toy = dataclasses.replace(
        TOY,
        rungs=(
            Rung("rough", "off", lambda x: x["diameter"] / 10),
            Rung("exact", "", fixed_error(0)),
        ),
        compute=counted,
        vectorized=rough_vectorized,
        vector_rungs=("rough",),
    )
    d = [0.05, 0.5, 0.01, 0.9]  # estimates 0.005, 0.05, 0.001, 0.09 against tolerance 0.01
    s = engine.sweep(toy, BASE, "diameter", d, outputs=["energy"])
    assert s.rungs == ["rough", "exact", "rough", "exact"]
    assert s.error_estimates == pytest.approx([0.005, 0.0, 0.001, 0.0])
    assert sorted(calls) == [0.5, 0.9]  # only the exact points ran one by one
    e = [0.5 * v**2 / 8 * 1e4 for v in d]
    assert s.results["energy"] == pytest.approx([1.05 * e[0], e[1], 1.05 * e[2], e[3]])
    assert "rough at 2 points, exact at 2 points" in s.notes[0]


def test_estimates_that_cannot_take_arrays_are_called_per_point():
    calls = []

    def scalar_only(x):
        calls.append(1)
        return math.sqrt(x["diameter"]) / 10  # math.sqrt refuses an array: TypeError

    toy = dataclasses.replace(
        TOY,
        rungs=(Rung("rough", "off", scalar_only), Rung("exact", "", fixed_error(0))),
        vector_rungs=("rough", "exact"),
    )
    s = engine.sweep(toy, BASE, "diameter", [0.0025, 0.04], outputs=["energy"])
    # √0.0025 / 10 = 0.005 ≤ 0.01 → rough; √0.04 / 10 = 0.02 → exact
    assert s.rungs == ["rough", "exact"] and s.error_estimates == pytest.approx([0.005, 0.0])
    assert len(calls) == 3  # one failed array call, then one per point


def test_sweep_results_are_plain_python_lists_with_null_where_not_finite():
    s = engine.sweep(TOY, BASE, "diameter", [0.1, 6.0, 0.2], outputs=["energy"], fidelity="exact")
    energy = s.results["energy"]
    assert type(energy) is list and energy[1] is None
    assert all(type(v) is float for v in (energy[0], energy[2]))
    assert s.rungs == ["exact", None, "exact"] and s.error_estimates == [1e-15, None, 1e-15]


def test_a_point_whose_estimate_refuses_is_null_with_the_reason_and_the_rest_computed():
    def picky(x):
        d = x["diameter"]
        if np.ndim(d):
            raise InputOutOfRange("diameter too big for the estimate", field="diameter")
        if d > 0.4:
            raise InputOutOfRange("diameter too big for the estimate", field="diameter")
        return 0.001

    toy = dataclasses.replace(
        TOY,
        rungs=(Rung("rough", "off", picky), Rung("exact", "", fixed_error(0))),
        vector_rungs=("rough", "exact"),
    )
    s = engine.sweep(toy, BASE, "diameter", [0.1, 0.5, 0.2], outputs=["energy"])
    assert s.rungs == ["rough", None, "rough"] and s.results["energy"][1] is None
    # the toy's array path ignores the rung: the exact energy at the computed points
    assert s.results["energy"][::2] == pytest.approx([0.5 * d**2 / 8 * 1e4 for d in (0.1, 0.2)])
    assert any(n.startswith("diameter = 0.5: diameter too big") for n in s.notes)


def test_a_prepared_request_is_validated_and_its_rung_chosen_once(monkeypatch: Any) -> None:
    """The service routes a request by its rung (engine.core.runner.prepare) and hands that to
    engine.run: one validation and one rung choice per request, and the same answer as an
    unprepared run."""
    import engine.core.runner as runner
    from engine import get_model
    from engine.core.spec import ModelSpec

    spec = get_model("impact.rare")
    example = spec.examples[0]
    plain = engine.run(spec, example, fidelity="simulation")
    calls = {"validate": 0, "choose": 0}
    validate, choose = ModelSpec.validate, runner.choose_rung

    def counted_validate(self: ModelSpec, raw: Any) -> Any:
        calls["validate"] += 1
        return validate(self, raw)

    def counted_choose(*a: Any, **k: Any) -> Any:
        calls["choose"] += 1
        return choose(*a, **k)

    monkeypatch.setattr(ModelSpec, "validate", counted_validate)
    monkeypatch.setattr(runner, "choose_rung", counted_choose)
    prepared = runner.prepare(spec, example, "simulation", None)
    again = engine.run(spec, example, fidelity="simulation", prepared=prepared)
    assert calls == {"validate": 1, "choose": 1}
    assert again.rung == plain.rung == "simulation"
    assert again.results == plain.results
    assert again.notes == plain.notes


def test_the_service_validates_an_auto_request_once(monkeypatch: Any) -> None:
    from fastapi.testclient import TestClient

    from engine import get_model
    from engine.core.spec import ModelSpec
    from service import create_app

    spec = get_model("impact.rare")
    client = TestClient(create_app(models=[spec]))
    body = {**spec.examples[0], "tolerance": 1e-4}  # auto: chooses the simulation
    assert client.post("/api/v1/impact/rare", json=body).status_code == 200  # warm
    calls = []
    validate = ModelSpec.validate

    def counted(self: ModelSpec, raw: Any) -> Any:
        calls.append(self.name)
        return validate(self, raw)

    monkeypatch.setattr(ModelSpec, "validate", counted)
    answer = client.post("/api/v1/impact/rare", json=body)
    assert answer.status_code == 200, answer.text
    assert answer.json()["rung"] == "simulation"
    assert calls == ["impact.rare"]


def test_a_float_input_is_checked_alike_on_the_plain_float_path_and_the_general_one() -> None:
    """A JSON number (a Python float) takes a shorter path through Param.check; it refuses
    and converts exactly as the general path does for an int or a numpy float."""
    from engine.core.spec import Param

    p = Param("x", "m", "a length", minimum=0.0, maximum=1.0, exclusive_minimum=True)
    for given in (0.5, 1.0, 5e-324):
        for same in (given, np.float64(given)):
            got = p.check(same)
            assert type(got) is float and got == given
    assert p.check(1) == 1.0 and type(p.check(1)) is float
    for bad in (0.0, -0.0, 1.0000000001, math.nan, math.inf, -math.inf, np.float64(math.nan)):
        with pytest.raises(InputOutOfRange) as refused:
            p.check(bad)
        assert (
            refused.value.field == "x"
            and "must be a finite number > 0 m and ≤ 1 m" in refused.value.message
        )
    free = Param("y", "m", "a length")
    assert math.copysign(1.0, free.check(-0.0)) == 1.0  # -0.0 folded to 0.0
    assert math.copysign(1.0, free.check(np.float64(-0.0))) == 1.0
    with pytest.raises(InputOutOfRange):
        free.check(math.inf)
