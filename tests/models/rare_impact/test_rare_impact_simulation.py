"""The rare-impact simulation rung: limits, invariants, budgets and extremes [002]."""

import math
import time

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from engine import BudgetExceeded, EngineError, InfeasibleDesign, RunContext, run
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from engine.rare_impact import (
    quasi_static_release_error,
    striker_oscillation,
    striker_travel,
    time_to_travel,
)
from engine.rare_impact_sim import simulate, stage1_fast, stage1_problem, stage1_reference

R = REFERENCE_DESIGN
STIFF = {
    **R,
    "power_spring_rate": 1e7,
    "auxiliary_spring_rate": 1e7,
    "return_spring_rate": 1e7,
    "roller_mass": 0.001,
    "half_coupling_mass": 0.001,
    "stepped_shaft_mass": 0.001,
    "striker_mass": 0.001,
}


def full(x):
    return RARE_IMPACT.validate(x)[0]


def ctx(**kw):
    names = frozenset(o.name for o in RARE_IMPACT.outputs)
    return RunContext(rung="simulation", outputs=names, tolerance=1e-6, **kw)


def test_simulation_reports_series_and_stage_durations():
    r = run(RARE_IMPACT, R, fidelity="simulation", series=True)
    assert r.rung == "simulation" and r.error_estimate == 1e-6
    s = r.series
    n = len(s["time"])
    assert 100 < n < 1000 and all(len(v) == n for v in s.values())
    assert np.all(np.diff(s["time"]) >= 0)
    t_rel = r.results["spin_up_time"]
    i = int(np.searchsorted(s["time"], t_rel))
    assert s["z1"][i] == pytest.approx(R["release_travel"])
    assert max(s["z2"]) == pytest.approx(R["engagement_height"])
    assert s["flywheel_speed"][i] == pytest.approx(r.results["release_speed"])
    total = t_rel + sum(r.results[k] for k in ("engagement_time", "return_time", "relock_time"))
    assert s["time"][-1] == pytest.approx(total, rel=1e-12)


def test_simulation_tends_to_the_closed_form_as_torque_vanishes():
    # Quasi-static limit: the closed form's error is first order in the flywheel's
    # acceleration, so dividing the torque by 10 divides it by about 10.
    errors = []
    for torque in (5.0, 0.5, 0.05):
        x = {**R, "motor_torque": torque}
        sim = run(RARE_IMPACT, x, fidelity="simulation", outputs=["release_speed"])
        cf = run(RARE_IMPACT, x, fidelity="closed_form", outputs=["release_speed"])
        errors.append(abs(cf.results["release_speed"] / sim.results["release_speed"] - 1))
    assert errors[2] < errors[1] < errors[0] < 1e-3
    assert errors[2] < 3e-6


@pytest.mark.parametrize(
    "change",
    [
        {},
        {"motor_no_load_speed": 400.0},
        {"motor_no_load_speed": 240.0},
        {"cone_angle": math.radians(10)},
        {"cone_angle": math.radians(80)},
        {"power_spring_preload": 0.0, "auxiliary_spring_preload": 0.0},
        {"power_spring_preload": 0.05},  # snap-through at lift-off
        {"motor_torque": 0.5},
    ],
)
def test_closed_form_error_estimate_bounds_the_simulated_error(change):
    x = full({**R, **change})
    est_w, est_t = quasi_static_release_error(x)
    sim = run(RARE_IMPACT, x, fidelity="simulation", outputs=["release_speed", "spin_up_time"])
    cf = run(RARE_IMPACT, x, fidelity="closed_form", outputs=["release_speed", "spin_up_time"])
    err_w = abs(cf.results["release_speed"] / sim.results["release_speed"] - 1)
    err_t = abs(cf.results["spin_up_time"] / sim.results["spin_up_time"] - 1)
    assert err_w <= est_w and err_t <= est_t
    assert est_w < 100 * err_w + 1e-5  # a bound, but not a useless one


def test_auto_picks_the_cheapest_rung_that_meets_the_tolerance():
    assert run(RARE_IMPACT, R).rung == "closed_form"
    tight = run(RARE_IMPACT, R, tolerance=1e-5, outputs=["release_speed"])
    assert tight.rung == "simulation" and "auto" in tight.notes[0]
    # Stiff springs with light parts: the closed form is near exact, so auto never simulates.
    assert run(RARE_IMPACT, STIFF, tolerance=1e-6).rung == "closed_form"


def test_stage2_exact_solution_matches_a_tight_integration():
    m2 = 0.15 + 6 * 0.05 + 0.4
    c1, lam1, c3, lam3, h1, g = 50000.0, 0.002, 52000.0, 0.0021, 0.005, 9.80665
    b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2, g)

    def rhs(t, y):  # [002, eq. 2]
        return [y[1], g + (c1 * (lam1 + h1 - y[0]) - c3 * (lam3 + y[0])) / m2]

    t = np.linspace(0.0, 2 * math.pi / k, 201)
    sol = solve_ivp(rhs, (0, t[-1]), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-16,
                    t_eval=t)  # fmt: skip
    assert np.allclose(striker_travel(t, b, k), sol.y[0], rtol=0, atol=1e-12)


def test_stage2_energy_bookkeeping():
    # Kinetic energy = work of gravity and the power spring − energy stored in the return spring.
    m2, c1, lam1, c3, lam3, h1, g = 0.85, 50000.0, 0.002, 52000.0, 0.0021, 0.005, 9.80665
    b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2, g)
    t = np.linspace(0.0, math.pi / k, 50)
    z = striker_travel(t, b, k)
    v = b / k * np.sin(k * t)  # d/dt of (B/k²)(1 − cos kt)
    kinetic = 0.5 * m2 * v**2
    power = 0.5 * c1 * ((lam1 + h1) ** 2 - (lam1 + h1 - z) ** 2)
    stored = 0.5 * c3 * ((lam3 + z) ** 2 - lam3**2)
    assert np.allclose(kinetic, m2 * g * z + power - stored, rtol=0, atol=1e-12)
    assert kinetic[-1] == pytest.approx(0.0, abs=1e-12)  # at rest at 2B/k²


def _first_peak(problem, t_stop):
    """First local maximum of z1 (a tight dense reference), or None."""

    def rhs(t, y):
        return [y[1], problem.accel(t, y[0])]

    def top(t, y):
        return y[1]

    top.direction = -1.0
    sol = solve_ivp(rhs, (problem.t_liftoff, t_stop), [0.0, 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-15, events=top, dense_output=True,
                    max_step=problem.step * 10)  # fmt: skip
    for t_pk in sol.t_events[0]:
        if t_pk > problem.t_liftoff + problem.step:
            return float(t_pk), float(sol.sol(t_pk)[0]), sol.sol
    raise AssertionError("no peak")


def test_grazing_first_crossing_is_not_skipped():
    # A motor whose no-load speed is just above the release speed slows the drift of the
    # equilibrium while the lift-off oscillation persists: z1 rises and falls back. Put
    # h1 a hair below the first peak, so the first crossing is a graze (z1 stays above
    # h1 for ~1e-4 of a period) and the next one comes a whole oscillation later. The
    # stage-1 motion does not depend on h1. (scipy's event location, which only looks
    # at step ends, misses this graze even with max_step = period/100.)
    base = stage1_problem(full({**R, "motor_no_load_speed": 240.0}))
    t_pk, z_pk, dense = _first_peak(base, base.t_end)
    assert z_pk < R["release_travel"]
    for shortfall in (1e-4, 1e-7, 1e-12):
        level = z_pk * (1 - shortfall)
        p = type(base)(**{**base.__dict__, "h1": level})
        quarter = 0.25 * base.step * 200
        t_cross = brentq(lambda t, lv=level: dense(t)[0] - lv, t_pk - quarter, t_pk, xtol=1e-15)
        fast = stage1_fast(p)
        # At a graze dz/dt → 0, so the crossing time is ill-conditioned; judge it by the
        # position there (the integrator's error is ~1e-9 of the travel) and its order.
        assert dense(fast.t_release)[0] == pytest.approx(level, abs=2e-8 * level)
        # ... and it is this first peak, not the crossing one oscillation later
        assert abs(fast.t_release - t_cross) < 0.01 * quarter


def test_fast_stage1_agrees_with_a_tight_reference():
    for change in ({}, {"motor_no_load_speed": 400.0}, {"cone_angle": math.radians(30)}):
        p = stage1_problem(full({**R, **change}))
        fast = stage1_fast(p)
        t_ref, w_ref, _ = stage1_reference(p, rtol=1e-12, max_step_fraction=0.02)
        assert fast.t_release == pytest.approx(t_ref, rel=1e-7)
        assert fast.w_release == pytest.approx(w_ref, rel=1e-7)


def test_weak_linear_motor_is_infeasible_in_both_rungs():
    x = {**R, "motor_no_load_speed": 230.0}  # below the 236 rad/s release speed
    for rung in ("closed_form", "simulation"):
        with pytest.raises(InfeasibleDesign, match="never reaches the release speed"):
            run(RARE_IMPACT, x, fidelity=rung)


def test_stiff_springs_with_light_parts_fall_back_to_the_closed_form_at_once():
    # 1e7 N/m on 1 g parts: ~1e8 RK4 steps. The closed form's estimated error there is
    # below the simulation's own 1e-6, so the rung runs it and says so, without integrating.
    start = time.perf_counter()
    r = run(RARE_IMPACT, STIFF, fidelity="simulation")
    assert time.perf_counter() - start < 5.0  # generous: nothing is integrated
    assert r.rung == "closed_form" and r.error_estimate < 1e-6
    assert any("ran its declared fallback 'closed_form' instead" in n for n in r.notes)
    assert r.series == {}
    for v in r.results.values():
        assert v is None or isinstance(v, bool) or math.isfinite(v)


def test_budget_refusal_names_the_way_out():
    with pytest.raises(BudgetExceeded, match="closed_form") as info:
        stage1_fast(stage1_problem(full(STIFF)))
    assert info.value.context["expected_steps"] > 1e6


def test_every_solve_is_bounded_by_steps_and_deadline():
    x = full(R)
    with pytest.raises(BudgetExceeded):
        simulate(x, ctx(max_steps=100))
    with pytest.raises(BudgetExceeded, match="time budget"):
        simulate(x, ctx(deadline=time.perf_counter() - 1.0))


def test_striker_that_never_reaches_h2_gets_a_verdict():
    r = run(RARE_IMPACT, {**R, "engagement_height": 0.006}, fidelity="simulation", series=True)
    assert r.results["engagement_time"] is None and r.results["full_engagement"] is False
    assert r.results["return_time"] is None and r.results["relock_time"] is None
    assert any("never reaches the engagement height" in w for w in r.warnings)
    assert len(r.series["time"]) > 100


@pytest.mark.parametrize(
    "change",
    [
        STIFF,
        {"cone_angle": math.radians(10)},
        {"cone_angle": math.radians(80)},
        {"cone_angle": math.radians(89.9)},
        {"cone_angle": math.radians(0.5)},
        {"return_spring_rate": 50000.0 * (1 + 1e-12)},
        {"return_spring_rate": 50000.0},
        {"motor_torque": 1e-6},
        {"motor_no_load_speed": 236.02},
        {"gravity": -100.0, "return_spring_preload": 0.0},
        {"power_spring_preload": 0.5, "auxiliary_spring_preload": 0.5},
    ],
)
def test_extremes_never_hang_nan_or_500(client, change):
    for rung in ("closed_form", "simulation"):
        start = time.perf_counter()
        r = client.post("/api/v1/impact/rare", json={**R, **change, "fidelity": rung})
        assert time.perf_counter() - start < 20.0
        assert r.status_code in (200, 422), r.text
        if r.status_code == 200:
            body = r.json()
            for v in body["results"].values():
                assert v is None or isinstance(v, bool) or math.isfinite(v)


_pos = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    c1=st.floats(1e2, 1e8),
    c3=st.floats(1e2, 1e8),
    c2=st.floats(1e1, 1e7),
    lam=st.floats(0.0, 0.02),
    alpha=st.floats(0.01, 1.56),
    mp=st.floats(1e-4, 1.0),
    torque=st.floats(1e-3, 1e3),
    h1=st.floats(1e-5, 0.02),
)
def test_property_any_design_gives_finite_results_or_a_clean_refusal(
    c1, c3, c2, lam, alpha, mp, torque, h1
):
    x = {**R, "power_spring_rate": c1, "return_spring_rate": c3, "auxiliary_spring_rate": c2,
         "power_spring_preload": lam, "cone_angle": alpha, "roller_mass": mp,
         "motor_torque": torque, "release_travel": h1}  # fmt: skip
    for rung in ("closed_form", "simulation"):
        try:
            r = run(RARE_IMPACT, x, fidelity=rung, budget_s=5.0)
        except EngineError:
            continue
        for v in r.results.values():
            assert v is None or isinstance(v, bool) or math.isfinite(v)
        assert r.error_estimate is None or math.isfinite(r.error_estimate)


def test_time_to_travel_is_consistent_with_the_simulated_stage2():
    r = run(RARE_IMPACT, R, fidelity="simulation", series=True)
    b, k = r.results["oscillation_B"], r.results["oscillation_k"]
    assert r.results["engagement_time"] == pytest.approx(time_to_travel(0.004, b, k))


def test_stage2_outputs_alone_need_no_stage1_integration():
    r = run(RARE_IMPACT, STIFF, fidelity="simulation", outputs=["oscillation_k", "relock_margin"])
    assert set(r.results) == {"oscillation_k", "relock_margin"}  # no BudgetExceeded: no stage 1
    assert any("not integrated" in n for n in r.notes)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    c1=st.floats(1e3, 1e6),
    c2=st.floats(1e2, 1e5),
    lam1=st.floats(0.0, 0.02),
    lam2=st.floats(1e-4, 0.02),
    alpha=st.floats(0.1, 1.47),
    mp=st.floats(0.005, 0.5),
    n=st.integers(1, 12),
    x0=st.floats(0.01, 0.1),
    inertia=st.floats(1e-3, 1.0),
    torque=st.floats(0.1, 50.0),
    h1=st.floats(5e-4, 0.02),
    no_load=st.one_of(st.none(), st.floats(50.0, 5000.0)),
)
def test_property_closed_form_within_its_estimate_of_the_simulation(
    c1, c2, lam1, lam2, alpha, mp, n, x0, inertia, torque, h1, no_load
):
    x = {**R, "power_spring_rate": c1, "auxiliary_spring_rate": c2, "power_spring_preload": lam1,
         "auxiliary_spring_preload": lam2, "cone_angle": alpha, "roller_mass": mp,
         "roller_count": n, "roller_radius": x0, "flywheel_inertia": inertia,
         "motor_torque": torque, "release_travel": h1, "motor_no_load_speed": no_load}  # fmt: skip
    wanted = ["release_speed", "spin_up_time"]
    try:
        sim = run(RARE_IMPACT, x, fidelity="simulation", outputs=wanted)
    except EngineError:
        return
    if sim.rung != "simulation":
        return
    cf = run(RARE_IMPACT, x, fidelity="closed_form", outputs=wanted)
    est_w, est_t = quasi_static_release_error(full(x))
    assert abs(cf.results["release_speed"] / sim.results["release_speed"] - 1) <= est_w
    assert abs(cf.results["spin_up_time"] / sim.results["spin_up_time"] - 1) <= est_t
