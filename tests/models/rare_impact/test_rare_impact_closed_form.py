"""The rare-impact wrench's closed forms [002], by hand and through the runner."""

import math

import numpy as np
import pytest

from engine import InfeasibleDesign, run, sweep
from engine.models.rare_impact import (
    HORIZONTAL_DESIGN,
    PAPER_DESIGN,
    RARE_IMPACT,
    REFERENCE_DESIGN,
)
from engine.physics.rare_impact import (
    effective_stage1_mass,
    liftoff_speed,
    max_striker_travel,
    min_return_spring_rate,
    release_speed,
    relock_margin,
    spin_up_time,
    spring_height_limit,
    striker_oscillation,
    striker_travel,
    time_to_travel,
)
from engine.procedures.striker_cycle import quasi_static_error, snaps_at_liftoff

R = REFERENCE_DESIGN


def test_release_speed_45_degrees_matches_the_printed_form():
    # [002, after eq. 4], α = 45°: ω² = [c1(λ1+h) + c2(λ2+h)] / (0.5 n m r)
    # = [50000·0.007 + 2000·0.013] / (0.5·6·0.05·0.045) = 376 / 0.00675 = 55703.7
    w = release_speed(50000.0, 0.002, 2000.0, 0.008, 0.005, 0.05, 6, 0.04, math.pi / 4)
    assert w == pytest.approx(math.sqrt(376.0 / 0.00675), rel=1e-12)
    assert w == pytest.approx(236.0163, rel=1e-6)


def test_release_speed_general_angle():
    # α = 30°: tan = 0.577350, r = 0.04 + 0.005/0.577350 = 0.0486603,
    # ω² = 2·0.577350·376 / (6·0.05·0.0486603) = 434.1673 / 0.01459808 = 29741.6
    w = release_speed(50000.0, 0.002, 2000.0, 0.008, 0.005, 0.05, 6, 0.04, math.pi / 6)
    assert w**2 == pytest.approx(29741.6, rel=1e-5)


def test_liftoff_and_effective_mass():
    # ω0² = 2·1·(100 + 16) / (6·0.05·0.04) = 232 / 0.012 = 19333.3
    w0 = liftoff_speed(50000.0, 0.002, 2000.0, 0.008, 0.05, 6, 0.04, math.pi / 4)
    assert w0**2 == pytest.approx(19333.333, rel=1e-6)
    # m_e = 0.15 + 0.05 + 6·0.05/(2·tan²30°) = 0.2 + 0.3/(2/3) = 0.65
    assert effective_stage1_mass(0.15, 0.05, 0.05, 6, math.pi / 6) == pytest.approx(0.65)


def test_stage2_coefficients_and_travel_by_hand():
    # M2 = 0.15 + 6·0.05 + 0.4 = 0.85; B = g + (50000·0.007 − 52000·0.0021)/0.85
    # = 9.80665 + 240.8/0.85 = 293.10077; k² = 102000/0.85 = 120000
    b, k = striker_oscillation(50000.0, 0.002, 52000.0, 0.0021, 0.005, 0.85, 9.80665)
    assert b == pytest.approx(293.100768, rel=1e-8)
    assert k == pytest.approx(math.sqrt(120000.0), rel=1e-14)
    assert max_striker_travel(b, k) == pytest.approx(2 * 293.100768 / 120000.0, rel=1e-8)
    # arccos form of the paper: t = arccos(1 − h k²/B)/k
    t = time_to_travel(0.004, b, k)
    assert t == pytest.approx(math.acos(1 - 0.004 * 120000.0 / b) / k, rel=1e-12)
    assert striker_travel(t, b, k) == pytest.approx(0.004, rel=1e-12)


def test_time_to_travel_edges():
    b, k = 100.0, 100.0  # 2B/k² = 0.02
    assert time_to_travel(0.02, b, k) == pytest.approx(math.pi / k, rel=1e-15)
    assert time_to_travel(0.02 * (1 + 1e-9), b, k) == math.inf
    assert time_to_travel(0.01, -1.0, k) == math.inf
    # tiny travels: arcsin form keeps precision; z = B t²/2 → t = √(2h/B)
    assert time_to_travel(1e-15, b, k) == pytest.approx(math.sqrt(2e-15 / b), rel=1e-9)
    # 1 − cos kt cancels for small kt; the sin² form does not
    assert striker_travel(1e-8, b, k) == pytest.approx(0.5 * b * 1e-16, rel=1e-12)


def test_spring_height_limit_eq6_and_c3_to_c1():
    # 2·0.85·9.80665 / (52000 − 50000) = 16.671305/2000
    assert spring_height_limit(0.85, 9.80665, 50000.0, 52000.0) == pytest.approx(
        0.00833565, rel=1e-6
    )
    assert spring_height_limit(0.85, 9.80665, 50000.0, 50000.0) == math.inf
    near = spring_height_limit(0.85, 9.80665, 50000.0, 50000.0 * (1 + 1e-12))
    assert math.isfinite(near) and near > 1e3
    # eq. 6 follows from h2 = 2B/k² with c1λ1 = c3λ3 and h1 = h2 = h:
    c1, c3, m2, g = 30000.0, 40000.0, 0.8, 9.80665
    h = spring_height_limit(m2, g, c1, c3)
    b, k = striker_oscillation(c1, 0.004, c3, 0.003, h, m2, g)  # 30000·0.004 = 40000·0.003
    assert max_striker_travel(b, k) == pytest.approx(h, rel=1e-12)


def test_return_rate_and_relock_margin():
    # m3 g / (λ3 + h2 − h3/2) = 0.4·9.80665 / (0.0021 + 0.004 − 0.00175) = 3.92266/0.00435
    assert min_return_spring_rate(0.4, 9.80665, 0.0021, 0.004, 0.0035) == pytest.approx(
        901.76092, rel=1e-6
    )
    assert min_return_spring_rate(0.4, 0.0, 0.0, 0.004, 0.0035) == 0.0
    assert min_return_spring_rate(0.4, 9.80665, 0.0, 0.001, 0.004) == math.inf
    # [002, eq. 4] at z2 = h1: 2000·0.008 + 0.05·9.80665 − 52000·0.0021·0.1
    # = 16 + 0.4903325 − 10.92, by hand
    assert relock_margin(2000.0, 0.008, 0.05, 9.80665, 10.92) == pytest.approx(5.5703325)
    # the margin is eq. 4's force at the end of the travel: relock_time's D4·c2 less c2·h1
    d4 = 0.008 + 0.005 + (0.05 * 9.80665 - 10.92) / 2000.0
    assert relock_margin(2000.0, 0.008, 0.05, 9.80665, 10.92) == pytest.approx(
        2000.0 * (d4 - 0.005), rel=1e-12
    )
    # gravity opposing (g < 0) takes the weight off: 16 − 0.4903325 − 10.92
    assert relock_margin(2000.0, 0.008, 0.05, -9.80665, 10.92) == pytest.approx(4.5896675)


def test_spin_up_time_both_motor_laws():
    assert spin_up_time(0.02, 5.0, 236.0) == pytest.approx(0.944)
    # τ = 0.02·400/5 = 1.6 s; t = −1.6 ln(1 − 236/400) = 1.6·0.891598
    assert spin_up_time(0.02, 5.0, 236.0, 400.0) == pytest.approx(1.6 * 0.8915981, rel=1e-6)
    with pytest.raises(InfeasibleDesign, match="never reaches the release speed"):
        spin_up_time(0.02, 5.0, 236.0, 230.0)


def test_reference_design_through_the_runner():
    # the paper's printed stage 1 reproduces the paper's closed form exactly
    r = run(RARE_IMPACT, PAPER_DESIGN, fidelity="closed_form")
    assert r.rung == "closed_form"
    v = r.results
    assert v["release_speed"] == pytest.approx(236.0163, rel=1e-6)
    assert v["spin_up_time"] == pytest.approx(0.02 * 236.01632 / 5.0, rel=1e-6)
    assert v["engagement_window"] == pytest.approx(math.radians(120) / 236.01632, rel=1e-6)
    assert v["full_engagement"] is True and v["engagement_margin"] > 0.2
    assert all(c.ok for c in r.checks), [c.detail for c in r.checks if not c.ok]
    names = [c.name for c in r.checks]
    assert names == ["c3 > c1", "λ1 < λ3", "eq. 6 (engagement height)", "return", "relock",
                     "full engagement"]  # fmt: skip
    # the return time drops the half-coupling's motion (coupled through the rollers by
    # M12²/(M11·M22) = 0.09/0.45 = 0.2 in this geometry; 3.6 % measured), the spin-up alone
    # is good to a few 1e-3
    assert r.error_estimate > 0.036
    r1 = run(RARE_IMPACT, PAPER_DESIGN, fidelity="closed_form", outputs=["release_speed"])
    assert 1e-4 < r1.error_estimate < 1e-2


def test_default_geometry_release_speed_by_hand():
    # symmetric V, κ = 1/(2 tan 45°) = 0.5, ρ = 0.5: r = 0.04 + 0.5·0.005 = 0.0425 m,
    # weight lifted W = (0.15 + 0.05 + 0.3·0.5)·9.80665 = 3.4323275 N,
    # ω² = (376 + 3.4323275)/(6·0.05·0.5·0.0425) = 379.4323275/0.006375 = 59518.797
    r = run(RARE_IMPACT, R, fidelity="closed_form")
    assert r.results["release_radius"] == pytest.approx(0.0425, rel=1e-14)
    assert r.results["release_speed"] ** 2 == pytest.approx(59518.797, rel=1e-7)
    # the rollers' share of the inertia counts: L = (0.02 + 0.3·0.0425²)·ω = M·t exactly
    w = r.results["release_speed"]
    assert r.results["spin_up_time"] == pytest.approx((0.02 + 0.3 * 0.0425**2) * w / 5.0)
    # horizontal, the paper's 45° closed form: ω² = F/(0.5 n m_p r) = 376/(0.5·0.3·0.0425)
    h = run(RARE_IMPACT, HORIZONTAL_DESIGN, fidelity="closed_form")
    assert h.results["release_speed"] ** 2 == pytest.approx(376.0 / (0.5 * 0.3 * 0.0425))


def test_horizontal_example_runs_and_engages():
    r = run(RARE_IMPACT, HORIZONTAL_DESIGN, fidelity="closed_form")
    assert r.results["spring_height_limit"] == 0.0
    assert r.results["min_return_spring_rate"] == 0.0
    assert r.results["full_engagement"] is True


def test_edge_blow_and_never_reaching_are_reported():
    late = run(RARE_IMPACT, {**R, "engagement_angle": math.radians(60)}, fidelity="closed_form")
    check = next(c for c in late.checks if c.name == "full engagement")
    assert not check.ok and "edge blow" in check.detail
    assert late.results["engagement_margin"] < 0
    never = run(RARE_IMPACT, {**R, "engagement_height": 0.006}, fidelity="closed_form")
    assert never.results["engagement_time"] is None and never.results["full_engagement"] is False
    assert not next(c for c in never.checks if c.name == "eq. 6 (engagement height)").ok


def test_paper_conditions_contradict_when_preloads_balance():
    # c1λ1 = c3λ3 with c3 > c1 forces λ3 < λ1: the λ1 < λ3 check fails and says why.
    r = run(
        RARE_IMPACT, {**R, "return_spring_preload": 50000 * 0.002 / 52000}, fidelity="closed_form"
    )
    check = next(c for c in r.checks if c.name == "λ1 < λ3")
    assert not check.ok and "contradict" in check.detail


def test_snap_through_when_preloads_are_heavy():
    # paper's eq. 1: 2500 N ≫ (c1 + c2)·x0·tan α = 2080 N
    x = {**PAPER_DESIGN, "power_spring_preload": 0.05}
    assert snaps_at_liftoff(x)
    # symmetric V: κ = 0.5, the threshold is (c1 + c2)·x0/κ = 4160 N, not reached by 2500 N
    assert not snaps_at_liftoff({**R, "power_spring_preload": 0.05})
    assert snaps_at_liftoff({**R, "power_spring_preload": 0.09})
    r = run(RARE_IMPACT, x, fidelity="closed_form")
    w0 = liftoff_speed(50000.0, 0.05, 2000.0, 0.008, 0.05, 6, 0.04, math.pi / 4)
    assert r.results["release_speed"] == pytest.approx(w0)
    assert any("snaps" in n for n in r.notes)


def test_error_estimate_shrinks_with_slower_spin_up():
    fast = quasi_static_error(R)[0]
    slow = quasi_static_error({**R, "motor_torque": 0.05})[0]
    assert slow < fast / 50  # first order in the flywheel's acceleration


def test_outputs_limit_the_work():
    r = run(RARE_IMPACT, R, fidelity="closed_form", outputs=["release_speed"])
    assert set(r.results) == {"release_speed"}


def test_weak_linear_motor_is_infeasible():
    with pytest.raises(InfeasibleDesign, match="never reaches the release speed"):
        run(RARE_IMPACT, {**R, "motor_no_load_speed": 200.0})


def test_sweep_matches_pointwise():
    values = np.linspace(0.02, 0.08, 7)
    fast = sweep(RARE_IMPACT, R, "roller_radius", values, fidelity="closed_form")
    assert fast.rung == "closed_form"
    for i, x0 in enumerate(values):
        one = run(RARE_IMPACT, {**R, "roller_radius": float(x0)}, fidelity="closed_form")
        for name in ("release_speed", "spin_up_time", "engagement_time", "engagement_margin"):
            a, b = fast.results[name][i], one.results[name]
            assert (a is None and b is None) or a == pytest.approx(b, rel=1e-12)
        assert fast.results["full_engagement"][i] == one.results["full_engagement"]


def test_sweep_nulls_points_that_never_engage_or_never_spin_up():
    s = sweep(RARE_IMPACT, R, "engagement_height", [0.003, 0.006], fidelity="closed_form")
    assert s.results["engagement_time"][0] is not None and s.results["engagement_time"][1] is None
    s = sweep(RARE_IMPACT, {**R, "motor_no_load_speed": 300.0}, "roller_mass", [0.05, 0.02],
              fidelity="closed_form")  # fmt: skip
    assert s.results["spin_up_time"][0] is not None and s.results["spin_up_time"][1] is None


def test_sweep_over_extreme_angles_is_finite():
    # from the declared minimum (1°: issue 20 found 1e-300 crashing) to just below 90°
    lo = RARE_IMPACT.param("cone_angle").minimum
    assert lo == pytest.approx(math.radians(1.0))
    angles = np.concatenate([np.geomspace(lo, 0.5, 40), math.pi / 2 - np.geomspace(0.5, 1e-6, 40)])
    s = sweep(RARE_IMPACT, R, "cone_angle", angles, fidelity="closed_form")
    for name, column in s.results.items():
        for v in column:
            assert v is None or isinstance(v, bool) or math.isfinite(v), name
    assert all(v is not None for v in s.results["release_speed"])
