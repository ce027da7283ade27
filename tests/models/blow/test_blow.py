"""blow.joint: the physics of engine/physics/blow.py and the model's answers on its examples."""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.core.errors import EngineError
from engine.models.blow import BLOW, CLUTCH_M10, NUTRUNNER_HARD, NUTRUNNER_SOFT, RARE_IMPACT_M16
from engine.physics.blow import (
    BlowProblem,
    blow_series,
    clutch_preload_window,
    energy_blow,
    energy_blow_error,
    iso5393_rate,
    joint_rate,
    simulate_blow,
    simulate_blow_reference,
)

TOOL = BlowProblem(0.03, 0.001, 2.0e4, 90.0, 1000.0, breakaway=1.1)


def test_energy_blow_closes_its_energy_balance():
    # E = T_p²/(2C) + (T_p² − T_0²)/(2k) by hand for E = 100 J, C = 2e4, k = 1e3, T0 = 60
    peak, after, rot, work = energy_blow(100.0, 2.0e4, 1000.0, 60.0)
    assert peak == after
    assert after**2 / 4e4 + (after**2 - 3600.0) / 2000.0 == pytest.approx(100.0, rel=1e-12)
    assert rot == pytest.approx((after - 60.0) / 1000.0)
    assert work == pytest.approx(100.0 - after**2 / 4e4, rel=1e-12)


def test_energy_blow_into_a_held_nut_is_the_rigid_wall():
    # b·T0 above √(2EC): the nut does not turn and the peak is √(2EC) [000, eq. 7–8]
    peak, after, rot, work = energy_blow(100.0, 2.0e4, 1000.0, 2500.0)
    assert peak == pytest.approx(2000.0) and after == 2500.0 and rot == 0.0 and work == 0.0


def test_iso5393_and_joint_rates():
    assert iso5393_rate(100.0, "hard") * math.radians(30.0) == pytest.approx(100.0)
    assert iso5393_rate(100.0, "soft") * math.radians(720.0) == pytest.approx(100.0)
    # dT/dφ = K·P/(2πδ): 1 mm K, 2 mm pitch, 1e-9 m/N → 0.001·0.002/(2π·1e-9)
    assert joint_rate(0.001, 0.002, 0.6e-9, 0.4e-9) == pytest.approx(2.0 / (2 * math.pi) * 1e3)


def test_clutch_window_orders_friction_the_right_way():
    lo, hi = clutch_preload_window(90.0, 110.0, 0.002, 0.003)
    assert lo == pytest.approx(30000.0) and hi == pytest.approx(55000.0)


@pytest.mark.parametrize("t0,b", [(0.0, 1.0), (60.0, 1.0), (60.0, 1.3), (300.0, 1.1)])
def test_simulation_matches_solve_ivp(t0, b):
    p = BlowProblem(0.03, 0.001, 2.0e4, 90.0, 1000.0, breakaway=b)
    fast = simulate_blow(p, t0)
    peak, rot, _ = simulate_blow_reference(p, t0, rtol=1e-11)
    assert fast.peak_torque == pytest.approx(peak, rel=2e-6)
    assert fast.rotation == pytest.approx(rot, rel=2e-6, abs=1e-12)


def test_energy_rung_error_estimate_bounds_the_simulation():
    # the a-priori estimate of the energy rung covers its achieved error on the joint torque
    for t0, k in ((60.0, 1000.0), (60.0, 50.0), (300.0, 5000.0)):
        p = BlowProblem(0.03, 0.001, 2.0e4, 90.0, k, breakaway=1.0)
        sim = simulate_blow(p, t0).torque_after
        en = energy_blow(p.energy, p.stiffness, k, t0)[1]
        assert abs(en - sim) / sim <= energy_blow_error(0.03, 0.001, 2.0e4, k)


def test_restitution_dissipates_and_still_balances():
    p = BlowProblem(0.03, 0.001, 2.0e4, 90.0, 1000.0, restitution=0.6)
    out = simulate_blow(p, 60.0)
    assert out.damping_loss > 0.01 * p.energy
    total = out.joint_work + out.energy_left + out.damping_loss - out.drive_work
    assert total == pytest.approx(p.energy, rel=1e-5)


def test_blows_stop_when_the_joint_holds():
    s = blow_series(TOOL, 60.0, "energy", target_torque=1e5, max_blows=2000)
    assert s.blows_to_target == 0 and s.saturated
    # the energy rung saturates at √(2EC)/b
    assert s.final_torque == pytest.approx(math.sqrt(2 * TOOL.energy * 2e4) / 1.1, rel=1e-3)


def test_examples_answer_with_blows_and_preload():
    hard = run(BLOW, NUTRUNNER_HARD, fidelity="simulation", series=True)
    soft = run(BLOW, NUTRUNNER_SOFT, fidelity="simulation", series=True)
    assert hard.results["blows_to_target"] == 2
    assert soft.results["blows_to_target"] == 34
    assert len(soft.series["preload_per_blow"]) == 34
    assert soft.series["preload_per_blow"] == sorted(soft.series["preload_per_blow"])
    assert hard.series["time_in_blow"] and hard.series["torque_in_blow"]
    # the striker's release energy (45.9 J with the rollers): one blow lands in the window
    m16 = run(BLOW, RARE_IMPACT_M16, fidelity="simulation")
    assert m16.results["blows_to_target"] == 1
    assert m16.results["preload_verdict"] == "within"
    assert 80e3 < m16.results["preload_after_first_blow"] < 100e3
    # the paper's printed stage 1 (27.9 J, the flywheel alone): the second blow over-tightens
    paper = run(BLOW, {**RARE_IMPACT_M16, "roller_geometry": "paper"}, fidelity="simulation")
    assert paper.results["blows_to_target"] == 2
    assert paper.results["preload_verdict"] == "above"
    assert 60e3 < paper.results["preload_after_first_blow"] < 80e3


def test_clutch_source_sets_the_spring_for_the_target():
    r = run(BLOW, CLUTCH_M10)
    lo, hi = r.results["delivered_preload_min"], r.results["delivered_preload_max"]
    assert lo < 20e3 < hi
    assert r.results["preload_verdict"] == "within"
    # with the spring set to the reported force the nominal preload is the target
    force = r.results["clutch_spring_force_for_target"]
    at_target = run(
        BLOW,
        {
            **CLUTCH_M10,
            "clutch_spring_force": force,
            "spring_force_tolerance": 0.0,
            "flank_friction_scatter": 0.0,
            "friction_scatter": 0.0,
        },
    )
    assert at_target.results["final_preload"] == pytest.approx(20e3, rel=1e-9)


def test_clutch_per_ball_without_a_load_factor_takes_the_clutch_models_default():
    # was a TypeError (a 500 over HTTP): the borrowed load_factor is optional in blow.joint
    per_ball = {**CLUTCH_M10, "spring_arrangement": "per_ball"}
    r = run(BLOW, per_ball)
    given = run(BLOW, {**per_ball, "load_factor": 0.85})
    assert r.results["clutch_torque_min"] == given.results["clutch_torque_min"]
    assert any("K_r = 0.85" in note for note in r.notes)
    assert not any("K_r = 0.85" in note for note in given.notes)
    # the per-ball spring pushes K_r·i = 0.85 × 6 = 5.1 balls' worth: torque × 5.1
    common = run(BLOW, CLUTCH_M10)
    assert r.results["clutch_torque_max"] == pytest.approx(
        5.1 * common.results["clutch_torque_max"], rel=1e-12
    )
    # the common arrangement never reads K_r and says nothing of it
    assert not any("K_r" in note for note in common.notes)


def test_missing_inputs_are_refused_by_name():
    with pytest.raises(EngineError) as err:
        run(BLOW, {"source": "energy", "tool_energy": 10.0, "tool_inertia": 0.01})
    assert err.value.field == "tool_stiffness"
    with pytest.raises(EngineError) as err:
        run(
            BLOW,
            {"source": "energy", "tool_energy": 10.0, "tool_inertia": 0.01, "tool_stiffness": 1e4},
        )
    assert err.value.field == "target_torque"


@pytest.mark.parametrize("rung", ["rigid", "energy", "simulation"])
@pytest.mark.parametrize("scale", [1e-6, 1e6])
def test_extreme_inputs_give_finite_answers_or_refusals(rung, scale):
    x = {
        "source": "energy",
        "tool_energy": 10.0 * scale,
        "tool_inertia": 0.01,
        "tool_stiffness": 1e4,
        "joint_rate_from": "number",
        "joint_rate": 100.0 * scale,
        "target_torque": 50.0,
        "struck_inertia": 1e-4,
    }
    try:
        r = run(BLOW, x, fidelity=rung, max_steps=200_000)
    except EngineError:
        return
    for v in r.results.values():
        assert v is None or not isinstance(v, float) or math.isfinite(v)


@pytest.mark.parametrize("e", [0.9, 0.6, 0.3, 0.15])
def test_free_blow_rebounds_with_the_asked_restitution(e):
    # equal discs, one at rest: relative speed after = e × before (momentum 1, KE from the run)
    out = simulate_blow(BlowProblem(1.0, 1.0, 100.0, 1.0, 0.0, restitution=e), 0.0)
    # the jaws part where the force (not the twist) returns to zero: a kink inside an RK4
    # step, which costs accuracy: the simulation rung claims 5e-5 with damping
    assert math.sqrt(4.0 * out.energy_left - 1.0) == pytest.approx(e, rel=5e-5)


def test_joint_rate_from_the_vdi_cone_when_the_plates_compliance_is_absent():
    from engine.physics.joint import clamped_compliance

    x = {k: v for k, v in RARE_IMPACT_M16.items() if k != "clamped_compliance"}
    r = run(BLOW, x, fidelity="energy", outputs=["joint_rate_used"])
    # M16: d_W = 22.49 mm (ISO 4017), d_h = 17.5 mm (ISO 273 medium), l_K = 40 mm, steel
    plates = clamped_compliance([0.04], [2.1e11], 0.02249, 0.0175).total
    given = run(BLOW, {**x, "clamped_compliance": plates}, fidelity="energy")
    assert r.results["joint_rate_used"] == pytest.approx(given.results["joint_rate_used"], rel=1e-3)
    assert any("deformation cone" in n for n in r.notes)
