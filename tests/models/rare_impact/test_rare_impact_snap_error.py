"""The quasi-static stage 1's error where the half-coupling snaps through at lift-off, by hand.

:func:`engine.procedures.striker_cycle.quasi_static_error`'s snap branch on the reference
design with λ1 = 90 mm (it snaps: test_rare_impact_closed_form) and a linear motor
(ω_nl = 1500 rad/s), so that the spin-up's time scale t_0 and the flywheel's rate at
lift-off are not each other's ratio, and the rollers' share of the inertia counts:

    t_s = (6 h1 m_e / (2 A x0 ω0 ω̇0))^(1/3)     (the snap's duration)
    δω = 3 (ω̇0 t_s/ω0 + (J_r − J_0)/J_r)
    δt = max(3 t_s/t_0 + 3 a (J_r − J_0)/J_r, δω),  t_0 = −(J_r ω_nl/M) ln(1 − ω0/ω_nl)
    δv = 3 h1 √(−K0/m_e),  K0 = c1 + c2 − A κ ω0²

with a = max(u/((1 − u)(−ln(1 − u))), 1), u = ω_M/ω_nl, ω_M = ω0 J_0/J_r (the snap keeps
the angular momentum), J_0 and J_r the flywheel with the rollers at x0 and at r = x0 + κ h1.
"""

from __future__ import annotations

import math

import pytest

from engine.models.rare_impact import REFERENCE_DESIGN
from engine.procedures.striker_cycle import quasi_static_error, snaps_at_liftoff

X = {**REFERENCE_DESIGN, "power_spring_preload": 0.09, "motor_no_load_speed": 1500.0}


def test_the_snap_through_errors_by_hand() -> None:
    assert snaps_at_liftoff(X)
    nm = X["roller_count"] * X["roller_mass"]  # 0.3 kg
    kap, a_h = 0.5 / math.tan(X["cone_angle"]), 0.5  # symmetric V
    push = nm * kap  # A = n·mp·κ
    x0, h1, j = X["roller_radius"], X["release_travel"], X["flywheel_inertia"]
    r = x0 + kap * h1
    j_r, j_0 = j + nm * r * r, j + nm * x0 * x0
    m_e = X["half_coupling_mass"] + X["stepped_shaft_mass"] + nm * (kap**2 + a_h**2)
    c1, c2 = X["power_spring_rate"], X["auxiliary_spring_rate"]
    weight = (X["half_coupling_mass"] + X["stepped_shaft_mass"] + nm * a_h) * X["gravity"]
    held = c1 * X["power_spring_preload"] + c2 * X["auxiliary_spring_preload"] + weight
    w0 = math.sqrt(held / (push * x0))
    assert w0 == pytest.approx(867.89, abs=0.01)  # √(4519.43/0.006)
    k0 = c1 + c2 - push * kap * w0 * w0
    assert k0 < 0.0
    torque, w_nl = X["motor_torque"], X["motor_no_load_speed"]
    wd0 = torque / j_r * (1.0 - w0 / w_nl)
    t_s = (6.0 * h1 * m_e / (2.0 * push * x0 * w0 * wd0)) ** (1.0 / 3.0)
    dw = 3.0 * (wd0 * t_s / w0 + (j_r - j_0) / j_r)
    t_0 = -(j_r * w_nl / torque) * math.log1p(-w0 / w_nl)
    u = w0 * j_0 / j_r / w_nl
    amplify = max(u / ((1.0 - u) * -math.log1p(-u)), 1.0)
    dt = max(3.0 * t_s / t_0 + 3.0 * amplify * (j_r - j_0) / j_r, dw)
    assert dt > dw  # the time's own term decides: t_0 is in the answer
    dv = 3.0 * h1 * math.sqrt(-k0 / m_e)
    assert list(quasi_static_error(X)) == pytest.approx([dw, dt, dv], rel=1e-12)
