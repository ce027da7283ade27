"""The rare-impact cycle: Lagrangian stage 1, the hybrid simulation, verdicts, budgets [002]."""

import math
import time

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from engine import BudgetExceeded, EngineError, InfeasibleDesign, run
from engine.models.rare_impact import PAPER_DESIGN, RARE_IMPACT, REFERENCE_DESIGN
from engine.numerics.ode import TIME_SHARE
from engine.procedures import striker_cycle as C

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
#: The issue's stiff design: a 5e6 N/m power spring on a 20 g half-coupling.
STIFF_POWER = {**R, "power_spring_rate": 5e6, "half_coupling_mass": 0.02}
#: RK4 steps the issue's design with a 2e7 N/m power spring takes, at most (2,653,313).
STIFF_STEPS = 2_700_000


def full(x):
    return dict(RARE_IMPACT.validate(x)[0])


# ---------------------------------------------------------------------------
# Stage 1 is a mechanical system: energy and virtual work
# ---------------------------------------------------------------------------


def _physical_energy(x, kappa, a_h, w, z, zd):
    """Energy of the stated kinematics x = x0 + κz, roller axial a_h·z (g = 0)."""
    nm = x["roller_count"] * x["roller_mass"]
    xr = x["roller_radius"] + kappa * z
    kin = 0.5 * (x["flywheel_inertia"] + nm * xr * xr) * w * w
    kin += 0.5 * (x["half_coupling_mass"] + x["stepped_shaft_mass"]) * zd * zd
    kin += 0.5 * nm * (kappa * kappa + a_h * a_h) * zd * zd
    pot = 0.5 * x["power_spring_rate"] * (x["power_spring_preload"] + z) ** 2
    pot += 0.5 * x["auxiliary_spring_rate"] * (x["auxiliary_spring_preload"] + z) ** 2
    return kin + pot


@pytest.mark.parametrize("geometry", C.GEOMETRIES)
def test_stage1_energy_balance_holds_for_the_lagrangian_and_fails_for_the_printed_eq1(geometry):
    # Motor off, no gravity: the mechanism's energy must stay constant along the stage-1
    # motion. The energy is built from the geometry's own constraint (the paper's is
    # z1 = x1 tan α: κ = 1/tan α, no axial roller motion). The printed eq. 1 gives the
    # rollers' push half of what that constraint's virtual work gives, and leaves the
    # rollers' inertia n m_p x² out of the flywheel: its energy drifts.
    x = full({**R, "roller_geometry": geometry, "gravity": 0.0})  # motor off: p[MT] = 0 below
    g = C.geometry(geometry, x["cone_angle"])
    p = C._params(x, g)
    p[C.MT] = 0.0
    mode = C.S1P if g.paper else C.S1

    def rhs(t, y):
        dw, a0, _ = C._rhs(mode, p, y[0], y[1], 0.0, y[2], 0.0)
        return [dw, y[2], a0]

    w0 = 1.2 * C.liftoff_speed_of(x)  # lifted off, swinging about its balance
    sol = solve_ivp(rhs, (0.0, 0.02), [w0, 0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14)
    e = [_physical_energy(x, g.kappa, g.a_h, *sol.y[:, i]) for i in range(sol.y.shape[1])]
    drift = (max(e) - min(e)) / e[0]
    assert max(sol.y[1]) > 1e-4  # the half-coupling really moved
    if g.paper:
        assert drift > 1e-3
    else:
        assert drift < 1e-10


@pytest.mark.parametrize("geometry", ["symmetric_v", "single_cone"])
@pytest.mark.parametrize("angle", [20.0, 45.0, 70.0])
def test_stage1_push_is_the_virtual_work_of_the_centrifugal_forces(geometry, angle):
    # At rest (ż = 0) the axial push per metre of travel must equal the centrifugal
    # force's work n m_p x ω² · dx/dz over the constraint; the printed eq. 1 gives half.
    x = full({**R, "roller_geometry": geometry, "gravity": 0.0, "cone_angle": math.radians(angle)})
    g = C.geometry(geometry, x["cone_angle"])
    p = C._params(x, g)
    w, z = 200.0, 0.002
    _, a0, _ = C._rhs(C.S1, p, w, z, 0.0, 0.0, 0.0)
    springs = x["power_spring_rate"] * (x["power_spring_preload"] + z) + x[
        "auxiliary_spring_rate"
    ] * (x["auxiliary_spring_preload"] + z)
    push = C.stage1_effective_mass(x) * a0 + springs
    nm = x["roller_count"] * x["roller_mass"]
    xr = x["roller_radius"] + g.kappa * z
    assert push == pytest.approx(nm * xr * w * w * g.kappa, rel=1e-12)
    _, a_paper, _ = C._rhs(C.S1P, p, w, z, 0.0, 0.0, 0.0)
    t = math.tan(x["cone_angle"])
    paper_push = p[C.MEP] * a_paper + springs
    radius_p = x["roller_radius"] + z / t
    assert paper_push == pytest.approx(0.5 * nm * radius_p * w * w / t, rel=1e-12)


def test_reference_design_figures_under_each_geometry():
    # horizontal (g = 0), closed forms: symmetric V ω² = 376/(0.5·0.3·0.0425), paper
    # ω² = 376/(0.5·0.3·0.045), single cone ω² = 376/(0.3·0.045): +2.9 % and −29.3 %
    h = {**R, "gravity": 0.0}
    v = C.release_speed_of(full({**h, "roller_geometry": "symmetric_v"}))
    s = C.release_speed_of(full({**h, "roller_geometry": "single_cone"}))
    p = C.release_speed_of(full({**h, "roller_geometry": "paper"}))
    assert p == pytest.approx(math.sqrt(376.0 / (0.5 * 0.3 * 0.045)), rel=1e-14)
    assert v / p - 1 == pytest.approx(math.sqrt(0.045 / 0.0425) - 1, rel=1e-12)  # +2.899 %
    assert s / p - 1 == pytest.approx(math.sqrt(0.5) - 1, rel=1e-12)  # −29.29 %


# ---------------------------------------------------------------------------
# The hybrid simulation
# ---------------------------------------------------------------------------


def test_simulation_reports_the_whole_cycle_with_stage_boundaries():
    r = run(RARE_IMPACT, R, fidelity="simulation", series=True)
    # 1e-6 for the times; the half-coupling's speed at release, asked with every output, has
    # its own bound N·(2π/200)⁵/120·δv_qs/|v| (bench/accuracy_striker.py holds it)
    assert r.rung == "simulation" and 1e-6 < r.error_estimate < 2e-6
    s = r.series
    n = len(s["time"])
    assert 100 < n < 2000 and all(len(v) == n for v in s.values())
    t = np.asarray(s["time"])
    stage = np.asarray(s["stage"])
    assert np.all(np.diff(t) >= 0) and np.all(np.diff(stage) >= 0)
    assert set(stage) == {1.0, 2.0, 3.0, 4.0}
    v = r.results
    # stage boundaries where the scalar outputs say
    assert t[stage == 1][-1] == pytest.approx(v["spin_up_time"], rel=1e-12)
    assert t[stage == 2][-1] == pytest.approx(v["blow_time"], rel=1e-12)
    assert t[stage == 3][-1] == pytest.approx(v["striker_home_time"], rel=1e-12)
    assert t[-1] == pytest.approx(v["cycle_time"], rel=1e-12)
    lift = np.asarray(s["half_coupling_lift"])
    assert lift[stage == 1][-1] == pytest.approx(R["release_travel"], rel=1e-9)
    assert max(s["striker_travel"]) == pytest.approx(R["engagement_height"], rel=1e-9)
    assert np.asarray(s["shaft_lift"])[-1] == pytest.approx(0.0, abs=1e-12)
    assert s["flywheel_speed"][int(np.argmax(stage == 2))] == pytest.approx(v["release_speed"])


def test_stage_switches_carry_the_state():
    # the half-coupling still lifts at release; stage 2 starts backwards with the merged
    # momentum, which the closed form of stage 2 reproduces from the simulated release
    # speed to the integrator's accuracy, and which costs engagement time against a start
    # from rest (the paper's eq. 5)
    x = full(R)
    sim = C.simulate_cycle(x)
    assert sim.release_velocity > 0.01
    g = C.geometry("symmetric_v", x["cone_angle"])
    carried = C._stage2(C.as_numbers(x), sim.release_velocity, g)[0]
    at_rest = C._stage2(C.as_numbers(x), 0.0, g)[0]
    assert sim.engagement_time == pytest.approx(carried, rel=1e-7)
    assert sim.engagement_time > at_rest * 1.003
    # the paper's eq. 5 from rest: 6.5306 ms
    assert at_rest == pytest.approx(0.0065306, rel=1e-4)


def test_old_against_new_return_and_engagement_times():
    # old (paper's reductions): engagement 6.531 ms from rest, return 3.157 ms with the
    # half-coupling at rest and the rollers unloaded. New, symmetric V: the rollers'
    # inertia in stage 3 (M22 = m3 + n m_p/2 = 0.55 kg, exactly decoupled at 45°):
    # D = λ3 + h2 − (m3 + n m_p/2)g/c3, k3 = √(c3/M22), t = 2 asin(√(h3/2D))/k3
    r = run(RARE_IMPACT, R, fidelity="simulation").results
    m22 = 0.4 + 0.3 * 0.5
    d = 0.0021 + 0.004 - m22 * 9.80665 / 52000.0
    t_ret = 2.0 * math.asin(math.sqrt(0.0035 / (2 * d))) / math.sqrt(52000.0 / m22)
    assert r["return_time"] == pytest.approx(t_ret, rel=1e-7)
    assert r["return_time"] == pytest.approx(3.712e-3, rel=1e-3)
    assert r["engagement_time"] == pytest.approx(6.558e-3, rel=1e-3)


def test_simulation_agrees_with_solve_ivp_over_the_whole_cycle():
    for change in ({}, {"roller_geometry": "single_cone"}, {"roller_geometry": "paper"},
                   {"cone_angle": math.radians(30), "gravity": -9.80665},
                   {"motor_no_load_speed": 400.0}):  # fmt: skip
        x = full({**R, **change})
        fast = C.simulate_cycle(x)
        ref, _ = C.simulate_cycle_scipy(x, rtol=1e-12)
        for name in ("release_speed", "spin_up_time", "engagement_time", "return_time",
                     "home_time", "relock_time"):  # fmt: skip
            assert getattr(fast, name) == pytest.approx(getattr(ref, name), rel=2e-7), name


def _first_peak(x):
    """Time and height of the half-coupling's first lift-off peak (tight DOP853, dense).

    The peak comes 16 ms after lift-off here: 30 ms of integration hold it nearly twice over
    (the test fails loudly, at ``next``, if a design moves it later); the right-hand side is
    the kernel's compiled one (some 20,000 calls)."""
    g = C.geometry(x["roller_geometry"], x["cone_angle"])
    p = C._params(x, g)
    w0 = C.liftoff_speed_of(x)
    t0 = C._time_to_speed(x, C._inertia(x, g, x["roller_radius"]), w0)

    def rhs(t, y):
        dw, a0, _ = C._rhs_c(C.S1, p, y[0], y[1], 0.0, y[2], 0.0)
        return [dw, y[2], a0]

    def top(t, y):
        return y[2]

    top.direction = -1.0
    sol = solve_ivp(rhs, (t0, t0 + 0.03), [w0, 0.0, 0.0], method="DOP853", rtol=1e-13,
                    atol=1e-16, events=top, dense_output=True, max_step=2e-5)  # fmt: skip
    t_pk = next(t for t in sol.t_events[0] if t > t0 + 1e-4)
    return p, t0, w0, t_pk, float(sol.sol(t_pk)[1]), sol.sol


def test_grazing_first_crossing_is_not_skipped():
    # A motor whose no-load speed is just above the release speed slows the drift of the
    # equilibrium while the lift-off oscillation persists: z1 rises and falls back. A
    # level a hair below the first peak is crossed by a graze, and the next crossing
    # comes a whole oscillation later. The kernel must stop at the graze.
    x = full({**R, "motor_no_load_speed": 255.0})
    p, t0, w0, t_pk, z_pk, dense = _first_peak(x)
    assert z_pk < R["release_travel"]
    h = 2e-6
    for shortfall in (1e-4, 1e-7, 1e-12):
        level = z_pk * (1 - shortfall)
        t_cross = brentq(lambda t, lv=level: dense(t)[1] - lv, t_pk - 2e-3, t_pk, xtol=1e-15)
        # one event row (kind, c0, c1, level, direction): z1 rising through the level
        ev = (np.array([0]), np.array([1.0]), np.array([0.0]), np.array([level]), np.array([1.0]))
        bufs = (np.empty(1),) * 4
        out = C._advance_c(C.S1, p, t0, w0, 0.0, 0.0, 0.0, 0.0, h, 10**7, t0 + 1.0, *ev,
                           True, 0, *bufs, 0)  # fmt: skip
        status, t_hit = out[0], out[2]
        assert status == 1
        # at a graze dz/dt → 0, so the time is ill-conditioned: judge it by the position
        assert dense(t_hit)[1] == pytest.approx(level, abs=2e-8 * level)
        assert abs(t_hit - t_cross) < 1e-4  # this peak, not one a period later


def test_never_reaching_h2_gets_one_verdict():
    for rung in ("closed_form", "simulation"):
        r = run(RARE_IMPACT, {**R, "engagement_height": 0.0049}, fidelity=rung)
        v = r.results
        assert v["engagement_time"] is None and v["full_engagement"] is False
        assert v["return_time"] is None and v["relock_time"] is None
        assert v["blow_time"] is None and v["cycle_time"] is None
        checks = {c.name: c.ok for c in r.checks}
        assert not checks["eq. 6 (engagement height)"] and not checks["full engagement"]
        assert not checks["return"] and not checks["relock"]


@pytest.mark.parametrize("gravity", [-30.0, -9.80665, 0.0, 9.80665, 30.0])
@pytest.mark.parametrize("rung", ["closed_form", "simulation"])
def test_checks_and_times_never_contradict_for_gravity_of_either_sign(gravity, rung):
    for change in ({}, {"auxiliary_spring_preload": 0.001}, {"return_spring_preload": 0.0},
                   {"roller_geometry": "single_cone"}):  # fmt: skip
        try:
            r = run(RARE_IMPACT, {**R, **change, "gravity": gravity}, fidelity=rung)
        except EngineError:
            continue
        v = r.results
        checks = {c.name: c.ok for c in r.checks}
        assert checks["full engagement"] == v["full_engagement"]
        assert checks["eq. 6 (engagement height)"] == (v["engagement_time"] is not None)
        assert checks["return"] == (v["return_time"] is not None)
        assert checks["relock"] == (v["relock_time"] is not None)
        limit = v["spring_height_limit"]
        assert limit is None or limit >= 0.0
        if not checks["relock"] and v["relock_margin"] > 0 and checks["return"]:
            raise AssertionError("static margin holds but the shaft does not get back")


def test_relock_check_follows_the_motion_and_quotes_the_paper():
    # c2·λ2 = 2000·0.004 = 8 N < c3·λ3·f = 10.92 N: the paper's static rule fails, yet the
    # shaft starts with c2(λ2 + h1) + m2 g = 18.5 N > 10.92 N and gets back on its way
    x = {**R, "auxiliary_spring_preload": 0.004}
    for rung in ("closed_form", "simulation"):
        r = run(RARE_IMPACT, x, fidelity=rung)
        check = next(c for c in r.checks if c.name == "relock")
        assert r.results["relock_margin"] < 0
        assert check.ok == (r.results["relock_time"] is not None)
        assert "fails by" in check.detail


def test_stage1_gravity_sign_moves_the_release_speed_by_the_weight():
    # the weight W = (m1 + m2 + n m_p/2)·g joins the spring force at release: ω² ∝ F + W,
    # so ω(+g)² + ω(−g)² = 2 ω(0)² exactly (closed form), and the simulation follows
    ws = {g: C.release_speed_of(full({**R, "gravity": g})) for g in (-9.80665, 0.0, 9.80665)}
    assert ws[9.80665] ** 2 + ws[-9.80665] ** 2 == pytest.approx(2 * ws[0.0] ** 2, rel=1e-13)
    # the printed eq. 1 leaves the weight out: no dependence on g at all
    wp = [C.release_speed_of(full({**PAPER_DESIGN, "gravity": g})) for g in (-30.0, 30.0)]
    assert wp[0] == wp[1]


def test_weak_linear_motor_is_infeasible_in_both_rungs():
    x = {**R, "motor_no_load_speed": 240.0}  # below the 244 rad/s release speed
    for rung in ("closed_form", "simulation"):
        with pytest.raises(InfeasibleDesign, match="never reaches the release speed"):
            run(RARE_IMPACT, x, fidelity=rung)


def test_preloads_that_do_not_hold_the_parts_are_refused():
    x = {**R, "power_spring_preload": 0.0, "auxiliary_spring_preload": 0.0, "gravity": -9.8}
    for rung in ("closed_form", "simulation"):
        with pytest.raises(InfeasibleDesign, match="do not hold"):
            run(RARE_IMPACT, x, fidelity=rung)


def test_a_stage_without_a_step_count_is_declined_up_front_with_or_without_series():
    # an auxiliary spring of 5e-324 N/m (in range) under a shaft heavy enough to beat the
    # friction: stage 4's period and step are inf, its expected steps NaN. NaN passed the step
    # budget's comparison, so the stage integrated non-finite states until its budget was
    # spent (200,000 steps here, the whole time budget by default: about 5 s of CPU), and with
    # series the stride's int(NaN) raised a ValueError (a 500). Both are now declined before
    # the stage runs, as a stage needing more steps than its budget is.
    x = {**R, "auxiliary_spring_rate": 5e-324, "stepped_shaft_mass": 2.0}
    said = []
    for record in (False, True):
        with pytest.raises(BudgetExceeded, match="cannot count its RK4 steps ahead") as got:
            C.simulate_cycle(C.step_inputs(x), record=record, max_steps=200_000)
        said.append(got.value.message)
        assert got.value.context["expected_steps"] == math.inf
    assert said[0] == said[1]
    with pytest.raises(BudgetExceeded, match="cannot count its RK4 steps ahead"):
        run(RARE_IMPACT, x, fidelity="simulation", series=True, budget_s=None)
    # under auto the declared fallback answers, and its note says why
    r = run(RARE_IMPACT, x, series=True, budget_s=None, tolerance=1e-7)
    assert r.rung == "closed_form"
    assert any("would need about inf steps" in n for n in r.notes)


# ---------------------------------------------------------------------------
# Budgets
# ---------------------------------------------------------------------------


def test_the_issue_stiff_design_finishes_or_is_refused_quickly():
    start = time.perf_counter()
    try:
        r = run(RARE_IMPACT, STIFF_POWER, fidelity="simulation")
    except BudgetExceeded as exc:
        assert time.perf_counter() - start < 0.1
        assert "closed_form" in str(exc)
    else:
        assert r.rung in ("simulation", "closed_form")
        assert time.perf_counter() - start < 2.0


def test_a_design_needing_millions_of_steps_runs_when_the_time_budget_allows():
    # issue 21: "a stiff design needing 4.8e6 steps is refused because the budget counts
    # steps (1e6) while the same kernel would finish in ~0.14 s". The step budget is now
    # the time left over the kernel's measured cost per step: this design needs ~2.65e6
    # steps (0.2 to 0.4 s on the 2-core CI machine). Its budget is ten times what they
    # take at the cost this process measured, not the default 10 s: under load one chunk
    # paused by the scheduler is folded into the cost (up to STEP_COST_CAP), and half of
    # 10 s at 3 us a step is fewer steps than the design needs
    stiff = {**STIFF_POWER, "power_spring_rate": 2e7}
    run(RARE_IMPACT, R, fidelity="simulation")  # the kernel loaded and its cost measured
    allows = 10 * STIFF_STEPS * C._COST.seconds / TIME_SHARE
    start = time.perf_counter()
    r = run(RARE_IMPACT, stiff, fidelity="simulation", max_steps=1_000_000, budget_s=allows)
    elapsed = time.perf_counter() - start
    assert r.rung == "simulation"
    steps = int(next(n for n in r.notes if n.startswith("simulation:")).split("(")[1].split()[0])
    assert 2_000_000 < steps <= STIFF_STEPS, "more steps than the old fixed budget of 1e6"
    assert elapsed < 5.0  # 0.2 to 0.4 s: the budget is not what it takes
    # the same design with a budget its steps do not fit in is declined up front, at once
    # (a 422 that says why when the simulation is asked by name; under auto the declared
    # fallback answers and the runner's note names the budget in steps)
    start = time.perf_counter()
    with pytest.raises(BudgetExceeded, match="its time budget leaves"):
        run(RARE_IMPACT, stiff, fidelity="simulation", budget_s=0.02)
    assert time.perf_counter() - start < 0.5
    r = run(RARE_IMPACT, stiff, tolerance=1e-7, budget_s=0.02)
    assert r.rung == "closed_form"
    assert any("fallback 'closed_form'" in n and "(budget 1e+06)" not in n for n in r.notes)


def test_stiff_springs_with_light_parts_fall_back_to_the_closed_form_at_once():
    start = time.perf_counter()
    r = run(RARE_IMPACT, STIFF, tolerance=1e-6)
    assert time.perf_counter() - start < 5.0
    assert r.rung == "closed_form"
    assert any("fallback 'closed_form'" in n for n in r.notes)
    assert r.series == {}
    # named, the simulation falls back only to an answer that keeps its 1e-6; the closed
    # form's return estimate here is above it (the rollers' weight lifts them off face B
    # near home, which its bound counts), so the budget refusal stands, at once
    start = time.perf_counter()
    with pytest.raises(BudgetExceeded, match="its time budget leaves"):
        run(RARE_IMPACT, STIFF, fidelity="simulation")
    assert time.perf_counter() - start < 5.0


def test_auto_returns_its_best_with_a_note_when_no_rung_meets_the_tolerance():
    # 1e-9 is beyond both rungs: auto runs the most accurate, and where that one cannot
    # run in the budget it returns the closed form saying the tolerance was not met
    r = run(RARE_IMPACT, R, tolerance=1e-9)
    assert r.rung == "simulation"
    assert any("no rung meets tolerance" in n for n in r.notes)
    # a time budget the simulation cannot meet (the steps it affords are the time left over
    # the kernel's measured cost per step): the closed form, not a 422
    r = run(RARE_IMPACT, R, tolerance=1e-9, budget_s=1e-5)
    assert r.rung == "closed_form" and r.error_estimate > 1e-6
    assert any("the tolerance 1e-09 is not met" in n for n in r.notes)
    # asked by name, the simulation's budget refusal stands (a 422 that says why)
    with pytest.raises(BudgetExceeded, match="its time budget leaves"):
        run(RARE_IMPACT, R, fidelity="simulation", budget_s=1e-5)
    # without a deadline the step budget is the caller's
    with pytest.raises(BudgetExceeded, match="budget 1000"):
        run(RARE_IMPACT, R, fidelity="simulation", max_steps=1000, budget_s=None)


def test_every_solve_is_bounded_by_steps_and_deadline():
    x = full(R)
    with pytest.raises(BudgetExceeded):
        C.simulate_cycle(x, max_steps=100)
    with pytest.raises(BudgetExceeded, match="time budget"):
        C.simulate_cycle(x, deadline=time.perf_counter() - 1.0)


@pytest.mark.parametrize(
    "change",
    [
        STIFF,
        STIFF_POWER,
        {"cone_angle": math.radians(10)},
        {"cone_angle": math.radians(80)},
        {"cone_angle": math.radians(89.9)},
        {"cone_angle": math.radians(0.5)},
        {"return_spring_rate": 50000.0 * (1 + 1e-12)},
        {"return_spring_rate": 50000.0},
        {"motor_torque": 1e-6},
        {"motor_no_load_speed": 244.2},
        {"gravity": -100.0, "return_spring_preload": 0.0},
        {"gravity": 100.0, "return_spring_rate": 100.0},
        {"power_spring_preload": 0.5, "auxiliary_spring_preload": 0.5},
        {"engagement_height": 0.02, "jaw_height": 0.03},
        {"roller_geometry": "paper", "cone_angle": math.radians(0.5)},
        {"roller_geometry": "single_cone", "roller_friction": 1.0},
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
    gravity=st.floats(-50.0, 50.0),
    geometry=st.sampled_from(C.GEOMETRIES),
)
def test_property_any_design_gives_finite_results_or_a_clean_refusal(
    c1, c3, c2, lam, alpha, mp, torque, h1, gravity, geometry
):
    x = {**R, "power_spring_rate": c1, "return_spring_rate": c3, "auxiliary_spring_rate": c2,
         "power_spring_preload": lam, "cone_angle": alpha, "roller_mass": mp,
         "motor_torque": torque, "release_travel": h1, "gravity": gravity,
         "roller_geometry": geometry}  # fmt: skip
    for rung in ("closed_form", "simulation"):
        try:
            r = run(RARE_IMPACT, x, fidelity=rung, budget_s=5.0)
        except EngineError:
            continue
        for v in r.results.values():
            assert v is None or isinstance(v, bool) or math.isfinite(v)
        assert r.error_estimate is None or math.isfinite(r.error_estimate)
        checks = {c.name: c.ok for c in r.checks}
        assert checks["return"] == (r.results["return_time"] is not None)
        assert checks["relock"] == (r.results["relock_time"] is not None)


# ---------------------------------------------------------------------------
# Rung agreement: the closed form within its estimate of the simulation
# ---------------------------------------------------------------------------


def _rel(a, b):
    if a is None and b is None:
        return 0.0
    if a is None or b is None:
        return math.inf
    return abs(a / b - 1.0) if b else abs(a)


GROUPS = {
    "stage1": ("release_speed", "spin_up_time"),
    "engagement": ("engagement_time",),
    "return": ("return_time",),
    "relock": ("relock_time",),
}


@pytest.mark.parametrize("geometry", C.GEOMETRIES)
@pytest.mark.parametrize("angle", [20.0, 45.0, 70.0])
@pytest.mark.parametrize("gravity", [-9.80665, 9.80665])
@pytest.mark.parametrize("m1", [0.05, 0.5])
def test_closed_form_within_its_estimate_over_a_grid(geometry, angle, gravity, m1):
    x = full({**R, "roller_geometry": geometry, "cone_angle": math.radians(angle),
              "gravity": gravity, "half_coupling_mass": m1})  # fmt: skip
    cf = run(RARE_IMPACT, x, fidelity="closed_form")
    sim = run(RARE_IMPACT, x, fidelity="simulation")
    errs = C.closed_form_errors(x, C.closed_form_cycle(x))
    flies = math.isnan(errs["return"])
    # rollers that fly at the blow: the closed form says it does not apply, and claims nothing
    assert flies == any(w.startswith("stage 3: at the blow a face would") for w in cf.warnings)
    for group, names in GROUPS.items():
        if group == "return" and flies:
            continue
        for name in names:
            assert _rel(cf.results[name], sim.results[name]) <= errs[group], (name, errs)
    assert flies or errs["return"] > 0
    assert errs["relock"] > 0  # never claimed exact


def test_rungs_agree_as_the_spin_up_slows():
    # the quasi-static stage 1 is exact in the limit of a slow spin-up (the a-priori error
    # is first order in the flywheel's acceleration); at 45° in the symmetric V stage 3 is
    # decoupled and stage 4 exact, so the rungs meet
    prev = math.inf
    for torque in (5.0, 0.5, 0.05):
        x = {**R, "motor_torque": torque}
        cf = run(RARE_IMPACT, x, fidelity="closed_form").results
        sim = run(RARE_IMPACT, x, fidelity="simulation").results
        err = _rel(cf["release_speed"], sim["release_speed"])
        assert err < prev
        prev = err
        assert _rel(cf["return_time"], sim["return_time"]) < 1e-7
        assert _rel(cf["relock_time"], sim["relock_time"]) < 1e-7
    assert prev < 1e-5


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
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
    geometry=st.sampled_from(C.GEOMETRIES),
)
# heavy rollers on a light flywheel, no power-spring preload, a soft c2: the estimate once
# took the flywheel's acceleration at lift-off on the inertia at release (half of it here)
# and missed the closed form's release-speed error by 1.38x
@example(c1=334100.0, c2=100.0, lam1=0.0, lam2=0.00391, alpha=0.125, mp=0.5, n=4, x0=0.0569,
         inertia=0.015625, torque=0.125, h1=0.015625, no_load=None,
         geometry="symmetric_v")  # fmt: skip
def test_property_quasi_static_stage1_within_its_estimate(
    c1, c2, lam1, lam2, alpha, mp, n, x0, inertia, torque, h1, no_load, geometry
):
    x = {**R, "power_spring_rate": c1, "auxiliary_spring_rate": c2, "power_spring_preload": lam1,
         "auxiliary_spring_preload": lam2, "cone_angle": alpha, "roller_mass": mp,
         "roller_count": n, "roller_radius": x0, "flywheel_inertia": inertia,
         "motor_torque": torque, "release_travel": h1, "motor_no_load_speed": no_load,
         "roller_geometry": geometry}  # fmt: skip
    wanted = ["release_speed", "spin_up_time"]
    try:
        sim = run(RARE_IMPACT, x, fidelity="simulation", outputs=wanted)
    except EngineError:
        return
    if sim.rung != "simulation":
        return
    cf = run(RARE_IMPACT, x, fidelity="closed_form", outputs=wanted)
    est_w, est_t, _ = C.quasi_static_error(full(x))
    # |cf - true| <= est and |sim - true| <= e_sim, so |cf - sim| <= est + e_sim: the
    # simulation's own error counts (one case differed by 6e-8 more than est alone)
    e_sim = sim.error_estimate or 0.0
    assert _rel(cf.results["release_speed"], sim.results["release_speed"]) <= est_w + e_sim
    assert _rel(cf.results["spin_up_time"], sim.results["spin_up_time"]) <= est_t + e_sim


def test_a_step_budget_refusal_names_more_steps_than_its_budget() -> None:
    """The reference design under step budgets from 10³ to 3·10⁵: each refusal's expected
    steps are over its budget, in the budget's steps. The one-sided stage 3 weighs each of
    its steps as _CONTACT_STEP_COST of the kernel's, and its refusal said the steps
    unweighed: "about 2e+04 RK4 steps in stage 3 (budget 7e+04)", at 14 of these budgets
    (and the runner's fallback note repeated it)."""
    said = set()
    for max_steps in np.geomspace(1e3, 3e5, 60).astype(int).tolist():
        try:
            C.simulate_cycle(C.step_inputs(R), max_steps=max_steps)
        except BudgetExceeded as exc:
            said.add(exc.message.split(" RK4")[1][:40])
            assert exc.context["expected_steps"] > exc.context["step_budget"], exc.message
    assert any("stage 3's contacts" in s for s in said), said  # the one-sided stage's refused
