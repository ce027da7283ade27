"""The catalogue's equations (for the calculation report) and choice labels."""

from __future__ import annotations

import dataclasses

import pytest

import engine
from engine.core.equations import equations_of
from engine.core.spec import Param
from engine.physics import preload
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
    assert len(eqs) >= 3, [e["function"] for e in eqs]
    assert all(e["latex"] and all(x.strip() for x in e["latex"]) for e in eqs)
    assert all(e["module"].startswith("engine.") for e in eqs)
    assert len({(e["module"], e["function"]) for e in eqs}) == len(eqs)


def _chain(n: int) -> list:
    """n engine-like functions, each documenting an equation and calling the next."""
    glb: dict = {"__name__": "engine.chain"}
    for i in reversed(range(n)):
        call = f"step_{i + 1}(x)" if i < n - 1 else "x"
        src = f'def step_{i}(x):\n    r"""Step {i}.\n\n    .. math::\n        y_{i} = x\n    """\n'
        exec(src + f"    return {call}\n", glb)
    return [glb[f"step_{i}"] for i in range(n)]


def test_the_list_has_no_cap_and_no_depth_limit() -> None:
    # 40 steps, each called by the one before: all listed, in the order they are reached
    steps = _chain(40)
    eqs = equations_of(steps[0])
    assert [e["function"] for e in eqs] == [f"step_{i}" for i in range(40)]
    assert eqs[-1]["latex"] == ["y_39 = x"] and eqs[-1]["module"] == "engine.chain"


#: Steps each model's procedure runs that its report must show (engine function names).
KNOWN_STEPS = {
    # VDI 2230-1: R3 load factor, R4 embedding, R5 minimum preload, R8 working stress,
    # R9 endurance, R13 torque: in the order of the procedure
    "joint.vdi2230": (
        "stress_area",
        "bolt_compliance",
        "load_factor",
        "embedding_loss",
        "minimum_assembly_preload",
        "service_stress",
        "endurance_limit",
        "tightening_torque_per_preload",
    ),
    # the most loaded bolt's loads, then joint.vdi2230's chain for it
    "joint.flange": (
        "ring_flange_axial_load",
        "ring_flange_transverse_load",
        "stress_area",
        "bolt_compliance",
        "load_factor",
        "embedding_loss",
        "minimum_assembly_preload",
        "service_stress",
    ),
    "preload.tightening": ("stress_area", "assembly_preload", "thread_torque", "friction_radius"),
    "preload.control": ("stress_area", "assembly_preload", "thread_torque", "thread_stripping"),
    "nutrunner.drive": ("flywheel_speed", "impact_torque", "spin_up_time"),
    "clutch.ball": ("torque_limit", "ball_tangential_force", "spring_rate"),
    "clutch.ball_setting": ("spring_force_for_torque", "spring_deflection_for_force"),
    "clutch.spring_design": (
        "spring_force_for_torque",
        "rim_rise",
        "helical_rate",
        "helical_shear_stress",
        "solid_length",
        "minimum_gap_sum",
        "buckling_deflection",
    ),
    "impact.rare": ("release_speed_of", "min_return_spring_rate", "relock_margin"),
    "impact.rare_design": ("design_box", "nearest_passing", "rounded"),
    "blow.joint": (
        "stress_area",
        "torque_limit",
        "_release_speed",  # the striker's release, inside impact.rare's cycle
        "rotating_inertia",
        "energy_blow",
        "acceleration_time",  # the nut-runner's motor between blows [000, eq. 5]
    ),
    "tool.capability": (
        "sample_mean",
        "sample_standard_deviation",
        "capability_index",
        "critical_capability_index",
    ),
    # ISO 16047: the bearing lever, then K, μ_th, μ_b, μ_tot per test, then the statistics
    "friction.iso16047": (
        "mean_bearing_diameter",
        "torque_coefficient",
        "thread_friction_from_test",
        "bearing_friction_from_test",
        "total_friction_from_test",
        "sample_mean",
    ),
    # R13 per newton, the pitch term, the preload band, then each audit window
    "joint.audit": (
        "tightening_torque_per_preload",
        "pitch_torque_per_preload",
        "preload_bounds_from_torque",
        "audit_window",
    ),
    # a reading: the temperature's share off, the ultrasonic change, ΔL, then F = ΔL/δ_S
    "preload.ultrasonic": (
        "thermal_length_change",
        "ultrasonic_length_change",
        "mechanical_elongation",
        "preload_from_elongation",
    ),
    # a trace: steps, the tool's wind-up, detection, then the joint's rate and its inverse
    "trace.analysis": (
        "split_steps",
        "nut_angle",
        "local_gradient",
        "robust_line",
        "yield_index",
        "tightening_torque_per_preload",
        "elastic_torque_rate",
        "torque_per_preload_from_rate",
        "preload_from_torque",
    ),
    # each trace as trace.analysis reads it, then the batch's spread, outliers and C_p, C_pk
    "trace.batch": (
        "split_steps",
        "robust_line",
        "torque_per_preload_from_rate",
        "preload_from_torque",
        "batch_summary",
        "capability_index",
        "critical_capability_index",
    ),
    "trace.program": (
        "tightening_torque_per_preload",
        "elastic_torque_rate",
        "nominal_preload",
        "torque_then_angle",
    ),
    # the tool's σ from Cm, then the tails with their error, by the preload and the utilisation
    "joint.clamp_capability": (
        "index_standard_deviation",
        "tail_with_error",
        "preload_tail",
        "utilisation_tail",
    ),
}


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_the_report_lists_the_known_steps_in_the_order_of_the_procedure(spec) -> None:
    names = [e["function"] for e in spec.describe()["equations"]]
    known = KNOWN_STEPS[spec.name]
    assert set(known) <= set(names), sorted(set(known) - set(names))
    assert sorted(known, key=names.index) == list(known), names


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


def _names(eqs) -> list[str]:
    return [e["function"] for e in eqs]


@pytest.mark.parametrize(
    "spec", [s for s in engine.MODELS if any(r.steps for r in s.rungs)], ids=lambda s: s.name
)
def test_the_rungs_steps_cover_everything_the_compute_reaches(spec) -> None:
    """A rung's declared steps leave out no equation of the model's compute: together the
    rungs list every one, so a report of any rung shows what its procedure ran."""
    together = {n for r in spec.rungs for n in _names(spec.equations(r.name))}
    missing = [n for n in _names(spec.equations()) if n not in together]
    assert not missing


def test_a_rung_s_own_steps_appear_only_when_that_rung_ran() -> None:
    spec = engine.get_model("impact.rare")
    x = spec.examples[0]
    closed = engine.run(spec, x, fidelity="closed_form")
    simulated = engine.run(spec, x, fidelity="simulation")
    closed_list = _names(spec.equations(closed.rung))
    simulated_list = _names(spec.equations(simulated.rung))
    # stage 4's closed-form relock (ref. [002]) is a step of the closed form only; the
    # simulation integrates the return instead
    assert "relock_time" in closed_list and "relock_time" not in simulated_list
    # the steps both rungs run (the striker's oscillation, the outputs) are in both lists
    assert "striker_oscillation" in closed_list and "striker_oscillation" in simulated_list
    # the catalogue carries each rung's list for the report
    rungs = {r["name"]: r for r in spec.describe()["rungs"]}
    assert _names(rungs["closed_form"]["equations"]) == closed_list
    assert _names(rungs["simulation"]["equations"]) == simulated_list
