"""Two inclined flanks (α′ > 0, [001, fig. 6]): each construction against a derivation
written out here, not with the engine's functions.

(a) free ball: the ball sits half in a groove of the fixed driving half (flank α′) and
half in a groove of the spring-loaded driven half (flank α″). A relative turn x at the
ball circle lets the ball move b along the driven flank and x − b along the driving one;
the halves separate by z(b) and the spring takes the smallest z. Found here by a brute
search over b at a finite x, then F_t x = F_s z (virtual work, f = 0).

(b) pressure disc: the halves stay put, the V between their flanks closes by x and the
ball, touching both flanks, lifts the disc by the smallest z for which neither flank cuts
into it; again a brute search, then F_t x = F_s z.

With flank friction: the equilibrium of the ball under the tilted reactions, solved as a
linear system for each path the ball could take; a free ball takes the path that slips
at the lower torque.
"""

import math

import numpy as np
import pytest

import engine
from engine.models.clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING
from engine.physics import clutch as cl

DEG = math.pi / 180
X = 1e-4  # a finite relative turn at the ball circle, [m]
B = np.linspace(0.0, X, 200_001)  # the ball's share of it along the driven flank

PAPER = dict(BALL_CLUTCH.examples[0])  # D0 = 50 mm, α = 45°, d0 = 4 mm, Δ = 4 mm
C = 8e10 * 0.004**4 / (8 * 0.045**3 * 5)  # the paper's spring rate, [N/m]
F_SPRING = C * 0.004  # 22.47 N at the paper's setting


def free_ball_push(driving, driven):
    """x / z_min: the halves' separation minimised over where the ball rides."""
    z = B / math.tan(driven) + (X - B) / math.tan(driving)
    return X / z.min()


def pressure_disc_push(driving, driven):
    """x / z_min: the disc's lift, the lowest that clears both flanks of the closed V."""
    z = np.maximum(B / math.tan(driven), (X - B) / math.tan(driving))
    return X / z.min()


ANGLES = [(10, 45), (30, 60), (45, 45), (60, 30), (70, 20), (25, 65)]


@pytest.mark.parametrize(("driving", "driven"), ANGLES)
def test_virtual_work_by_finite_displacement(driving, driven):
    a1, a2 = driving * DEG, driven * DEG
    free = free_ball_push(a1, a2)
    disc = pressure_disc_push(a1, a2)
    assert cl.combined_push_factor(a2, 0.0, a1) == pytest.approx(free, rel=1e-9)
    assert cl.combined_push_factor(a2, 0.0, a1, "pressure_disc") == pytest.approx(disc, rel=1e-4)
    # the slip torque of one common spring: F_t D0/2 with F_t = F_s / push
    t_free = cl.torque_limit(F_SPRING, 0.05, a2, driving_groove_angle=a1)
    t_disc = cl.torque_limit(
        F_SPRING, 0.05, a2, driving_groove_angle=a1, construction="pressure_disc"
    )
    assert t_free == pytest.approx(F_SPRING / free * 0.025, rel=1e-9)
    assert t_disc == pytest.approx(F_SPRING / disc * 0.025, rel=1e-4)
    # the max rule never reports less torque than the sum
    assert t_free >= t_disc


def _equilibrium(angles, rho):
    """(F_t, F_a) of a ball sliding up the flanks ``angles`` under unit axial load.

    Each sliding flank's reaction R_k on the ball points at angle α_k − ρ from the
    direction of the tangential force it carries (tilted by ρ against the climb).
    One flank: R cos(α − ρ) = F_t, R sin(α − ρ) = F_a. Two (the V): the tangential
    components balance each other, R1 cos(α′ − ρ) − R2 cos(α″ − ρ) = 0, and the axial
    ones carry the disc, R1 sin(α′ − ρ) + R2 sin(α″ − ρ) = F_a = 1.
    """
    if len(angles) == 1:
        (a,) = angles
        r = 1.0 / math.sin(a - rho)
        return r * math.cos(a - rho), 1.0
    a1, a2 = angles
    m = np.array(
        [
            [math.cos(a1 - rho), -math.cos(a2 - rho)],
            [math.sin(a1 - rho), math.sin(a2 - rho)],
        ]
    )
    r1, _ = np.linalg.solve(m, [0.0, 1.0])
    return r1 * math.cos(a1 - rho), 1.0


@pytest.mark.parametrize(("driving", "driven"), ANGLES)
@pytest.mark.parametrize("f", [0.05, 0.1, 0.2])
def test_with_flank_friction_by_the_balls_equilibrium(driving, driven, f):
    a1, a2, rho = driving * DEG, driven * DEG, math.atan(f)
    # (a) the free ball slips along whichever single flank needs the smaller F_t
    paths = [_equilibrium([a], rho) for a in (a1, a2) if a > rho]
    ft, fa = min(paths)
    assert cl.combined_push_factor(a2, f, a1) == pytest.approx(fa / ft, rel=1e-12)
    # (b) both flanks at once (a V that still closes: both pushes positive here)
    ft, fa = _equilibrium([a1, a2], rho)
    assert cl.combined_push_factor(a2, f, a1, "pressure_disc") == pytest.approx(fa / ft, rel=1e-12)


def test_a_wall_parallel_to_the_axis_is_the_paper_either_way():
    # α′ = 0 (frictionless): [001, eq. 1–3], T = D0 F/(2 tan α) with one common spring
    today = 0.05 * F_SPRING / (2 * math.tan(45 * DEG))
    for construction in ("free_ball", "pressure_disc"):
        r = engine.run(
            BALL_CLUTCH, {**PAPER, "driving_groove_angle": 0.0, "flank_construction": construction}
        )
        assert r.results["torque_limit"] == pytest.approx(today, rel=1e-12)
    # and so does a steeper driving groove under a free ball, friction or not
    for f in (0.0, 0.1):
        plain = engine.run(BALL_CLUTCH, {**PAPER, "flank_friction": f}).results
        steep = engine.run(
            BALL_CLUTCH, {**PAPER, "flank_friction": f, "driving_groove_angle": 30 * DEG}
        ).results
        assert steep["torque_limit"] == plain["torque_limit"]


def test_the_reviews_case_equal_flanks_differ_by_two():
    # equal 45° flanks: the sum halves the seed's torque, the free ball keeps it; a spring
    # sized on the sum would slip at twice the target on a free-ball clutch
    today = 0.05 * F_SPRING / 2
    free = engine.run(BALL_CLUTCH, {**PAPER, "driving_groove_angle": 45 * DEG}).results
    disc = engine.run(
        BALL_CLUTCH,
        {**PAPER, "driving_groove_angle": 45 * DEG, "flank_construction": "pressure_disc"},
    ).results
    assert free["torque_limit"] == pytest.approx(today, rel=1e-12)
    assert disc["torque_limit"] == pytest.approx(today / 2, rel=1e-12)


@pytest.mark.parametrize("construction", ["free_ball", "pressure_disc"])
def test_the_setting_slips_at_its_target(construction):
    # clutch.ball_setting sizes the spring with the same push: set the nut as it says,
    # and clutch.ball slips at the target; F = 2 T p / D0 by hand
    target, a1, a2, f = 0.8, 50 * DEG, 35 * DEG, 0.1
    rho = math.atan(f)
    pushes = (math.tan(a1 - rho), math.tan(a2 - rho))
    p = max(pushes) if construction == "free_ball" else sum(pushes)
    design = {
        **PAPER,
        "groove_angle": a2,
        "flank_friction": f,
        "driving_groove_angle": a1,
        "flank_construction": construction,
    }
    s = engine.run(BALL_CLUTCH_SETTING, {**design, "target_torque": target}).results
    assert s["required_spring_force"] == pytest.approx(2 * target * p / 0.05, rel=1e-12)
    back = engine.run(BALL_CLUTCH, {**design, "spring_deflection": s["required_deflection"]})
    assert back.results["torque_limit"] == pytest.approx(target, rel=1e-12)


def test_a_free_ball_rides_out_on_the_driving_flank_where_the_driven_one_locks():
    # α = 20° below ρ = atan 0.5 = 26.6°, α′ = 50°: the free ball slips along the driving
    # flank, T = D0 F/(2 tan(50° − 26.57°)); under a pressure disc the pushes
    # tan(−6.57°) + tan(23.43°) = 0.3183 still lift the disc; with α′ = 25° too both lock
    design = {**PAPER, "groove_angle": 20 * DEG, "flank_friction": 0.5}
    free = engine.run(BALL_CLUTCH, {**design, "driving_groove_angle": 50 * DEG}).results
    rho = math.atan(0.5)
    want = 0.05 * F_SPRING / (2 * math.tan(50 * DEG - rho))
    assert free["torque_limit"] == pytest.approx(want, rel=1e-12)
    disc = engine.run(
        BALL_CLUTCH,
        {**design, "driving_groove_angle": 50 * DEG, "flank_construction": "pressure_disc"},
    ).results
    push = math.tan(20 * DEG - rho) + math.tan(50 * DEG - rho)
    assert disc["torque_limit"] == pytest.approx(0.05 * F_SPRING / (2 * push), rel=1e-12)
    for construction in ("free_ball", "pressure_disc"):
        with pytest.raises(engine.InfeasibleDesign) as err:
            engine.run(
                BALL_CLUTCH,
                {**design, "driving_groove_angle": 25 * DEG, "flank_construction": construction},
            )
        assert err.value.field == "groove_angle"
    # and without α′ the driven flank alone locks, as before
    with pytest.raises(engine.InfeasibleDesign):
        engine.run(BALL_CLUTCH, design)


def test_the_self_locking_margin_is_the_sliding_flanks():
    # free ball: it slides on the flatter flank only, 50° − 26.57°; pressure disc: on
    # both, the steeper locks first, 20° − 26.57° < 0
    design = {**PAPER, "groove_angle": 20 * DEG, "flank_friction": 0.5}
    rho = math.atan(0.5)
    free = engine.run(BALL_CLUTCH, {**design, "driving_groove_angle": 50 * DEG})
    assert free.results["self_locking_margin"] == pytest.approx(50 * DEG - rho, rel=1e-12)
    assert "max(α, α′) − atan f = 23.4°" in next(
        c.detail for c in free.checks if c.name == "self_locking"
    )
    disc = engine.run(
        BALL_CLUTCH,
        {**design, "driving_groove_angle": 50 * DEG, "flank_construction": "pressure_disc"},
    )
    assert disc.results["self_locking_margin"] == pytest.approx(20 * DEG - rho, rel=1e-12)
    assert not next(c.ok for c in disc.checks if c.name == "self_locking")
