"""The ball clutch's pure functions [001, eq. 1–3]: hand values, limits, invariants, inverses."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.physics.clutch import (
    ball_axial_force,
    ball_normal_force,
    ball_tangential_force,
    flank_push_factor,
    spring_deflection_for_force,
    spring_deflection_for_torque,
    spring_force,
    spring_force_for_torque,
    spring_index,
    spring_rate,
    spring_shear_stress,
    torque_limit,
    wahl_factor,
    wire_diameter_for_force,
    wire_diameter_for_torque,
)

DEG = math.pi / 180.0


def test_hand_computed_paper_spring_and_torque():
    # d0 = 4 mm, D = 45 mm, i_p = 5, G = 8e10 Pa, Δ = 4 mm [001, eq. 2]:
    # d0⁴ = 2.56e-10 m⁴, G d0⁴ = 20.48 N·m², 8 D³ i_p = 8 · 9.1125e-5 · 5 = 3.645e-3 m³
    # c = 20.48 / 3.645e-3 = 5618.6557 N/m, F = c Δ = 22.474623 N
    assert spring_rate(8e10, 4e-3, 45e-3, 5) == pytest.approx(5618.655693, rel=1e-9)
    force = spring_force(8e10, 4e-3, 45e-3, 5, 4e-3)
    assert force == pytest.approx(22.4746228, rel=1e-8)
    # common spring, α = 45°: T = D0 F / (2 tan 45°) = 0.05 · 22.474623 / 2 = 0.56186557 N·m
    assert torque_limit(force, 0.05, 45 * DEG) == pytest.approx(0.56186557, rel=1e-7)
    # per ball: K_r i = 0.85 · 4 = 3.4 times that = 1.91034294 N·m, i.e. the paper's
    # T = K_r D0 i G d0⁴ Δ / (16 D³ i_p tan α) = 0.85·0.05·4·20.48·0.004/(16·9.1125e-5·5·1)
    paper = 0.85 * 0.05 * 4 * 20.48 * 0.004 / (16 * 9.1125e-5 * 5 * 1.0)
    assert paper == pytest.approx(1.91034294, rel=1e-8)
    per_ball = torque_limit(force, 0.05, 45 * DEG, 4, 0.85, arrangement="per_ball")
    assert per_ball == pytest.approx(paper, rel=1e-12)


def test_hand_computed_ball_forces_and_spring_stress():
    # at T = 0.56186557 N·m: F_t = 2T/(K_r D0 i) = 1.12373114/(0.85·0.05·4 = 0.17) = 6.6101832 N
    ft = ball_tangential_force(0.56186557, 0.05, 4, 0.85)
    assert ft == pytest.approx(6.6101832, rel=1e-7)
    # α = 30°: F_a = F_t tan 30° = 6.6101832 · 0.57735027 = 3.8163911 N
    assert ball_axial_force(ft, 30 * DEG) == pytest.approx(3.8163911, rel=1e-7)
    # F_N = F_t / cos 30° = 6.6101832 / 0.86602540 = 7.6327821 N
    assert ball_normal_force(ft, 30 * DEG) == pytest.approx(7.6327821, rel=1e-7)
    # C = 45/4 = 11.25; K_w = 44/41 + 0.615/11.25 = 1.0731707 + 0.0546667 = 1.1278374
    assert spring_index(45e-3, 4e-3) == pytest.approx(11.25)
    assert wahl_factor(11.25) == pytest.approx(1.1278374, rel=1e-7)
    # τ = 8 F D K_w / (π d0³) = 8·22.474623·0.045·1.1278374 / (π·6.4e-8) = 45.384918 MPa
    assert spring_shear_stress(22.474623, 45e-3, 4e-3) == pytest.approx(45.384918e6, rel=1e-7)


def test_frictionless_limit_reproduces_eq_1():
    alpha = np.linspace(1.0, 89.0, 89) * DEG
    assert np.allclose(flank_push_factor(alpha, 0.0), np.tan(alpha), rtol=1e-14)
    assert np.allclose(ball_axial_force(3.0, alpha, 0.0), 3.0 * np.tan(alpha), rtol=1e-14)
    assert np.allclose(ball_normal_force(3.0, alpha, 0.0), 3.0 / np.cos(alpha), rtol=1e-14)
    assert np.allclose(
        torque_limit(10.0, 0.05, alpha, 4, 0.85, 0.0), 0.05 * 10.0 / (2 * np.tan(alpha))
    )


@pytest.mark.parametrize(
    ("f", "alpha_deg"),
    [
        (f, a)
        for f in (0.0, 0.05, 0.2, 0.6)
        for a in (10.0, 35.0, 45.0, 62.0, 85.0)
        if a * DEG > math.atan(f)
    ],
)
def test_flank_forces_balance_with_coulomb_friction(f, alpha_deg):
    # The flank acts on the ball with N along its normal (cos α, sin α) (tangential, axial)
    # and f N along the flank against the ball's climb, i.e. along (sin α, −cos α).
    alpha = alpha_deg * DEG
    normal = ball_normal_force(5.0, alpha, f)
    tangential = normal * (math.cos(alpha) + f * math.sin(alpha))
    axial = normal * (math.sin(alpha) - f * math.cos(alpha))
    assert tangential == pytest.approx(5.0, rel=1e-12)
    assert ball_axial_force(5.0, alpha, f) == pytest.approx(axial, rel=1e-12)


def test_common_spring_limit_is_independent_of_load_sharing():
    # One spring balances the SUM of the balls' axial pushes; however unevenly the
    # torque is shared (any weights), ΣF_t = 2T/D0, so the limit has no K_r and no i.
    rng = np.random.default_rng(1)
    alpha, f, spring, d0 = 40 * DEG, 0.08, 120.0, 0.06
    limit = torque_limit(spring, d0, alpha, 6, 0.85, f)
    for _ in range(20):
        share = rng.random(6)
        share /= share.sum()
        tangential = share * 2.0 * limit / d0
        assert ball_axial_force(tangential, alpha, f).sum() == pytest.approx(spring, rel=1e-12)
    assert torque_limit(spring, d0, alpha, 3, 0.9, f) == limit
    # per ball: the most-loaded ball (F_t = 2T/(K_r D0 i)) carries exactly its spring's force
    per_ball = torque_limit(spring, d0, alpha, 6, 0.85, f, "per_ball")
    worst = ball_tangential_force(per_ball, d0, 6, 0.85)
    assert ball_axial_force(worst, alpha, f) == pytest.approx(spring, rel=1e-12)
    assert per_ball / limit == pytest.approx(0.85 * 6, rel=1e-12)


def test_torque_limit_strictly_decreasing_in_angle_and_increasing_in_friction():
    for f in (0.0, 0.1, 0.3):
        alpha = np.linspace(math.atan(f) + 1e-3, math.pi / 2 - 1e-3, 400)
        t = torque_limit(50.0, 0.05, alpha, 4, 0.85, f)
        assert np.all(np.isfinite(t)) and np.all(np.diff(t) < 0.0)
    for alpha_deg in (20.0, 45.0, 70.0):
        alpha = alpha_deg * DEG
        f = np.linspace(0.0, math.tan(alpha) * 0.999, 400)
        t = torque_limit(50.0, 0.05, alpha, 4, 0.85, f, "per_ball")
        assert np.all(np.isfinite(t)) and np.all(np.diff(t) > 0.0)


def test_no_slip_where_angle_not_above_friction_angle():
    # tan(α − atan f) ≤ 0: the push never overcomes friction; the formula gives NaN, the
    # model raises InfeasibleDesign (tested over HTTP).
    assert math.isnan(torque_limit(10.0, 0.05, 10 * DEG, 4, 0.85, 0.5))
    assert math.isnan(spring_force_for_torque(1.0, 0.05, 10 * DEG, 4, 0.85, 0.5))
    assert flank_push_factor(math.atan(0.3), 0.3) == pytest.approx(0.0, abs=1e-15)


def test_wahl_factor_limits():
    # → 1 for a slender coil, large for a tight one
    assert wahl_factor(1e6) == pytest.approx(1.0, abs=1e-5)
    assert wahl_factor(2.0) == pytest.approx(7 / 4 + 0.3075)


def test_arrangement_name_checked():
    with pytest.raises(ValueError, match="arrangement"):
        torque_limit(1.0, 0.05, 0.5, arrangement="both")


arrangement = st.sampled_from(["common", "per_ball"])


@settings(max_examples=200, deadline=None)
@given(
    alpha=st.floats(1 * DEG, 89 * DEG),
    f=st.floats(0.0, 1.0),
    d0=st.floats(1e-4, 0.02),
    coil_ratio=st.floats(1.05, 100.0),
    coils=st.floats(1.0, 50.0),
    deflection=st.floats(1e-6, 0.1),
    g=st.floats(1e9, 5e11),
    ring=st.floats(1e-3, 2.0),
    balls=st.integers(1, 100),
    kr=st.floats(0.5, 1.0),
    arr=arrangement,
)
def test_inverse_of_forward_is_identity(
    alpha, f, d0, coil_ratio, coils, deflection, g, ring, balls, kr, arr
):
    if alpha <= math.atan(f) + 1e-6:
        return
    mean = d0 * coil_ratio
    force = spring_force(g, d0, mean, coils, deflection)
    torque = torque_limit(force, ring, alpha, balls, kr, f, arr)
    assert math.isfinite(torque) and torque > 0.0
    back = spring_force_for_torque(torque, ring, alpha, balls, kr, f, arr)
    assert back == pytest.approx(force, rel=1e-9)
    assert spring_deflection_for_force(back, g, d0, mean, coils) == pytest.approx(
        deflection, rel=1e-9
    )
    assert wire_diameter_for_force(back, g, mean, coils, deflection) == pytest.approx(d0, rel=1e-9)
    assert spring_deflection_for_torque(
        torque, ring, alpha, g, d0, mean, coils, balls, kr, f, arr
    ) == pytest.approx(deflection, rel=1e-9)
    assert wire_diameter_for_torque(
        torque, ring, alpha, g, mean, coils, deflection, balls, kr, f, arr
    ) == pytest.approx(d0, rel=1e-9)
