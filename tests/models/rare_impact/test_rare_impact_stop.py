"""Stage 2 with h2 > h1: the half-coupling stops at h1 and the striker goes on alone (issue 29).

The review's design (the reference with h1 = 3 mm, λ1 = 4 mm, h2 = 4 mm) reported full
engagement in 6.56 ms while the half-coupling's lift went to −1.0 mm, through its stop.
With the stop the striker turns back at 3.50 mm < 4 mm: no full blow. The reference here
is stage 2 integrated by scipy's solve_ivp on the equations written out below, from the
release speed each rung computed for itself (stage 1 is held elsewhere).
"""

from __future__ import annotations

import math
from typing import Any

import pytest
from scipy.integrate import solve_ivp

from engine import run
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from engine.procedures.striker_cycle import closed_form_cycle, simulate_cycle, simulate_cycle_scipy

REVIEW = {
    **REFERENCE_DESIGN,
    "release_travel": 0.003,
    "power_spring_preload": 0.004,
    "engagement_height": 0.004,
}


def _stage2(x: dict[str, Any], v_release: float) -> tuple[float, float]:
    """(time from release to y = h2 or inf, farthest y) by solve_ivp, symmetric V (ρ = 1/2).

    y: the striker's travel from the release position towards the anvil.
    A: sandwich M2 = m1 + n·mp + m3 with the shaft m2, backwards from y = 0 and back:
       (M2 + m2)ÿ = (M2 + m2)g + c1(λ1 + h1 − y) + c2(λ2 + h1 − y) − c3(λ3 + y)
    B: the sandwich alone up to the half-coupling's stop at y = h1:
       M2·ÿ = M2·g + c1(λ1 + h1 − y) − c3(λ3 + y)
    C: the striker alone past h1: m3·ÿ = m3·g − c3(λ3 + y)
    """
    g = x["gravity"]
    c1, c2, c3 = x["power_spring_rate"], x["auxiliary_spring_rate"], x["return_spring_rate"]
    l1, l2, l3 = (
        x["power_spring_preload"],
        x["auxiliary_spring_preload"],
        x["return_spring_preload"],
    )
    h1, h2 = x["release_travel"], x["engagement_height"]
    m1, m2, m3 = x["half_coupling_mass"], x["stepped_shaft_mass"], x["striker_mass"]
    nm = x["roller_count"] * x["roller_mass"]
    big = m1 + nm + m3
    v0 = -(m1 + m2 + 0.5 * nm) * v_release / (big + m2)  # the plastic catch at release
    opts = {"rtol": 1e-12, "atol": 1e-15, "method": "DOP853"}

    def at(level: float, direction: float):  # type: ignore[no-untyped-def]
        def ev(t: float, s: list[float]) -> float:
            return s[0] - level

        ev.terminal, ev.direction = True, direction  # type: ignore[attr-defined]
        return ev

    def turn(t: float, s: list[float]) -> float:
        return s[1]

    turn.terminal, turn.direction = True, -1.0  # type: ignore[attr-defined]

    def a(t: float, s: list[float]) -> list[float]:
        y = s[0]
        f = (big + m2) * g + c1 * (l1 + h1 - y) + c2 * (l2 + h1 - y) - c3 * (l3 + y)
        return [s[1], f / (big + m2)]

    t = 0.0
    ra = solve_ivp(a, (0.0, 1.0), [-1e-18, v0], events=[at(0.0, 1.0)], **opts)
    t, v = ra.t_events[0][0], ra.y_events[0][0][1]

    def b(t: float, s: list[float]) -> list[float]:
        y = s[0]
        return [s[1], g + (c1 * (l1 + h1 - y) - c3 * (l3 + y)) / big]

    rb = solve_ivp(b, (t, 1.0), [0.0, v], events=[at(min(h1, h2), 1.0), turn], **opts)
    if len(rb.t_events[1]):
        return math.inf, float(rb.y_events[1][0][0])
    t, v = rb.t_events[0][0], rb.y_events[0][0][1]
    if h2 <= h1:
        return float(t), math.nan

    def c(t: float, s: list[float]) -> list[float]:
        return [s[1], g - c3 * (l3 + s[0]) / m3]

    rc = solve_ivp(c, (t, 1.0), [h1, v], events=[at(h2, 1.0), turn], **opts)
    if len(rc.t_events[0]):
        return float(rc.t_events[0][0]), math.nan
    return math.inf, float(rc.y_events[1][0][0])


def test_the_reviews_design_turns_back_short_of_h2() -> None:
    cf = closed_form_cycle(REVIEW)
    _, reach = _stage2(REVIEW, cf.release_velocity)
    assert reach == pytest.approx(3.495e-3, abs=1e-6)  # the review's 3.50 mm
    assert math.isinf(cf.engagement_time)
    assert cf.max_travel == pytest.approx(reach, rel=1e-9)
    for sim in (simulate_cycle(REVIEW, record=True), simulate_cycle_scipy(REVIEW)[0]):
        _, reach_sim = _stage2(REVIEW, sim.release_velocity)
        assert math.isinf(sim.engagement_time)
        assert sim.max_travel == pytest.approx(reach_sim, rel=1e-6)
    lift = simulate_cycle(REVIEW, record=True).series["half_coupling_lift"]
    assert min(lift) >= 0.0  # never through its stop (the review: −1.0 mm)
    r = run(RARE_IMPACT, REVIEW, fidelity="closed_form")
    assert r.results["full_engagement"] is False


@pytest.mark.parametrize("h2", [0.0031, 0.0033])
def test_past_the_stop_the_striker_engages_alone(h2: float) -> None:
    x = {**REVIEW, "engagement_height": h2}
    cf = closed_form_cycle(x)
    t_ref, _ = _stage2(x, cf.release_velocity)
    assert math.isfinite(t_ref)
    assert cf.engagement_time == pytest.approx(t_ref, rel=1e-8)
    sim = simulate_cycle(x)
    t_sim, _ = _stage2(x, sim.release_velocity)
    assert sim.engagement_time == pytest.approx(t_sim, rel=1e-6)


def test_below_h1_nothing_changes() -> None:
    # the reference design (h2 = 4 mm < h1 = 5 mm): the sandwich engages together
    cf = closed_form_cycle(REFERENCE_DESIGN)
    t_ref, _ = _stage2(REFERENCE_DESIGN, cf.release_velocity)
    assert cf.engagement_time == pytest.approx(t_ref, rel=1e-8)


def _face_forces(x: dict[str, Any], y_h: float, y_s: float) -> tuple[float, float]:
    """(N_A, N_B) per roller mass at rest in stage 3, symmetric V, by hand.

    Lagrangian of stage 3 with the rollers as point masses at x = x0 + κ(y_s − y_h),
    y_r = (y_h + y_s)/2, κ = 1/(2 tan α):
    T = ½m1·ẏh² + ½m3·ẏs² + ½n·mp(ẋ² + ẏr²), so at rest M·q̈ = Q with
    M = [[m1 + n·mp(κ² + ¼), n·mp(¼ − κ²)], [n·mp(¼ − κ²), m3 + n·mp(κ² + ¼)]],
    Q = [c1(λ1 − y_h) + (m1 + n·mp/2)g, −c3(λ3 + y_s) + (m3 + n·mp/2)g].
    A roller: mp(ẍ, ÿr − g) = N_A(−sin α, −cos α) + N_B(−sin α, cos α).
    """
    a = x["cone_angle"]
    kap = 0.5 / math.tan(a)
    nm = x["roller_count"] * x["roller_mass"]
    m1, m3, g = x["half_coupling_mass"], x["striker_mass"], x["gravity"]
    m11, m22 = m1 + nm * (kap**2 + 0.25), m3 + nm * (kap**2 + 0.25)
    m12 = nm * (0.25 - kap**2)
    qh = x["power_spring_rate"] * (x["power_spring_preload"] - y_h) + (m1 + nm / 2) * g
    qs = -x["return_spring_rate"] * (x["return_spring_preload"] + y_s) + (m3 + nm / 2) * g
    det = m11 * m22 - m12 * m12
    ah, as_ = (m22 * qh - m12 * qs) / det, (m11 * qs - m12 * qh) / det
    xdd, ydd = kap * (as_ - ah), 0.5 * (ah + as_) - g
    total, diff = -xdd / math.sin(a), ydd / math.cos(a)  # N_A + N_B, N_B − N_A
    return 0.5 * (total - diff), 0.5 * (total + diff)


def test_a_roller_contact_that_would_pull_lets_the_rollers_go() -> None:
    # a steep cone (α = 85.4°): at the blow (at rest, y_h = h2 − h1) a face would already
    # have to pull a roller with more than its weight: the one-sided stage 3 takes over
    # (test_rare_impact_contact holds its times)
    x = {**REFERENCE_DESIGN, "cone_angle": 1.49, "roller_mass": 0.05}
    na, nb = _face_forces(x, x["engagement_height"] - x["release_travel"], x["engagement_height"])
    assert min(na, nb) < -x["gravity"]
    sim = simulate_cycle(x)
    assert any(
        n.startswith("stage 3: 0 ms after the blow face A would have to pull") for n in sim.notes
    )
    assert not any(w.startswith("stage 3:") for w in sim.warnings)
    # the reference: both faces push at the blow; on the stop (y_h = 0) the rollers' weight
    # alone takes g/(2 cos 45°) = 6.93 m/s² off face B, which lets them go near home
    r = REFERENCE_DESIGN
    na, nb = _face_forces(r, r["engagement_height"] - r["release_travel"], r["engagement_height"])
    assert min(na, nb) > 0.0
    ref = simulate_cycle(r)
    assert not any(w.startswith("stage 3:") for w in ref.warnings)
    assert any(n.startswith("stage 3:") and "face B would have to pull" in n for n in ref.notes)
