"""Every numeric output of impact.rare against a value worked out here, independently.

The reference design (symmetric V at 45°, constant motor torque, gravity along the
stroke) on the closed-form rung, each output recomputed from the paper's equations
[002, eqs. 1-6] as a reader would by hand: explicit formulas, and the stage-2 times as
roots of the written-out motion found by bracketing and bisection (scipy's brentq), not
by the model's own linear_reach. The simulation-only output is held to the same cycle
integrated by scipy's solve_ivp.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from engine import run
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from engine.procedures.striker_cycle import simulate_cycle_scipy
from tests.pins import pin

R = REFERENCE_DESIGN
G = R["gravity"]
N_MP = R["roller_count"] * R["roller_mass"]  # 0.3 kg
TAN = math.tan(R["cone_angle"])  # 45°
KAPPA = 0.5 / TAN  # symmetric V: x = x0 + z1/(2 tan α)
M1, M2, M3 = R["half_coupling_mass"], R["stepped_shaft_mass"], R["striker_mass"]
C1, C2, C3 = R["power_spring_rate"], R["auxiliary_spring_rate"], R["return_spring_rate"]
L1, L2, L3 = R["power_spring_preload"], R["auxiliary_spring_preload"], R["return_spring_preload"]
H1, H2, H3 = R["release_travel"], R["engagement_height"], R["jaw_height"]
BIG = M1 + N_MP + M3  # M2 of [002, eq. 2]: 0.85 kg


def _first_root(f, t_end: float) -> float:  # type: ignore[no-untyped-def]
    """First sign change of f on (0, t_end] on a fine grid, then bisection to 1e-15 s."""
    t = np.linspace(t_end * 1e-9, t_end, 200_001)
    y = f(t)
    k = int(np.argmax(np.sign(y[1:]) != np.sign(y[0])))
    return float(brentq(f, t[k], t[k + 1], xtol=1e-16, rtol=1e-15))


def hand() -> dict[str, float]:
    out: dict[str, float] = {}
    # stage 1 [002, eq. 1] with the Lagrangian of the symmetric V: push A = n·mp·κ,
    # the weight of half-coupling, shaft and the rollers' axial half along the travel
    r = R["roller_radius"] + KAPPA * H1  # 0.0425 m
    weight = (M1 + M2 + N_MP * 0.5) * G
    push = N_MP * KAPPA
    force = C1 * (L1 + H1) + C2 * (L2 + H1) + weight  # 376 N + 0.35 g
    w_m = math.sqrt(force / (push * r))
    w_0 = math.sqrt((C1 * L1 + C2 * L2 + weight) / (push * R["roller_radius"]))
    assert C1 + C2 - push * KAPPA * w_0**2 > 0.0  # no snap-through: the balance holds
    inertia = R["flywheel_inertia"] + N_MP * r * r
    t_spin = inertia * w_m / R["motor_torque"]  # constant torque from rest
    window = R["engagement_angle"] / w_m
    out |= {"release_radius": r, "release_speed": w_m, "spin_up_time": t_spin}
    out |= {"engagement_window": window, "engagement_start": t_spin}
    out["engagement_end"] = t_spin + window
    # [002, eqs. 2 and 5]: B and k of the striker's stage-2 motion
    b = G + (C1 * (L1 + H1) - C3 * L3) / BIG
    k = math.sqrt((C1 + C3) / BIG)
    out |= {"engagement_acceleration": b, "engagement_frequency": k}
    # the half-coupling's lift speed on the quasi-static path, dz/dω·ω̇
    stiffness = C1 + C2 - push * KAPPA * w_m**2
    v_rel = 2.0 * push * w_m * r / stiffness * R["motor_torque"] / inertia
    # stage 2: the plastic catch at release starts the sandwich and the shaft backwards
    v0 = -(M1 + M2 + N_MP * 0.5) * v_rel / (BIG + M2)
    k_a = math.sqrt((C1 + C2 + C3) / (BIG + M2))
    f_a = (BIG + M2) * G + C1 * (L1 + H1) + C2 * (L2 + H1) - C3 * L3

    def back(t):  # type: ignore[no-untyped-def]
        return f_a / (C1 + C2 + C3) * (1.0 - np.cos(k_a * t)) + v0 / k_a * np.sin(k_a * t)

    t_back = _first_root(back, math.pi / k_a)
    assert t_back > 0.0 and L1 + H1 > H2  # the power spring stays in contact up to h2
    v = -v0  # back at the release position as fast as it left (conservative)

    def forward(t):  # type: ignore[no-untyped-def]
        return b / k**2 * (1.0 - np.cos(k * t)) + v / k * np.sin(k * t) - H2

    t_eng = t_back + _first_root(forward, math.pi / k)
    out["engagement_time"] = t_eng
    out["max_striker_travel"] = b / k**2 + math.hypot(b / k**2, v / k)
    out["engagement_margin"] = (window - t_eng) / window
    out["blow_time"] = t_spin + t_eng
    # stage 3 [002, eq. 3] with the half-coupling held and the rollers' inertia:
    # M22 = m3 + n·mp(κ² + 1/4), from rest at h2, y = h2 - D(1 - cos k3 t)
    m22 = M3 + N_MP * (KAPPA**2 + 0.25)
    d3 = (C3 * (L3 + H2) - (M3 + N_MP * 0.5) * G) / C3
    k3 = math.sqrt(C3 / m22)
    out["return_time"] = math.acos(1.0 - H3 / d3) / k3
    t_home = math.acos(1.0 - H2 / d3) / k3
    out["striker_home_time"] = t_spin + t_eng + t_home
    # stage 4 [002, eq. 4]: the shaft back h1 against f·c3·λ3
    d4 = (C2 * (L2 + H1) + M2 * G - R["roller_friction"] * C3 * L3) / C2
    out["relock_time"] = math.acos(1.0 - H1 / d4) / math.sqrt(C2 / M2)
    out["cycle_time"] = out["striker_home_time"] + out["relock_time"]
    # [002, eq. 6], eq. 3 reduced as the paper does, eq. 4's condition
    out["spring_height_limit"] = 2.0 * BIG * G / (C3 - C1)
    out["min_return_spring_rate"] = M3 * G / (L3 + H2 - 0.5 * H3)
    # [002, eq. 4] at z2 = h1: c2·λ2 + m2·g − c3·λ3·f
    out["relock_margin"] = C2 * L2 + M2 * G - C3 * L3 * R["roller_friction"]
    return out


def test_the_hand_values_are_the_ones_written_in_the_paper_s_terms() -> None:
    h = hand()
    assert h["release_radius"] == pytest.approx(0.0425, rel=1e-15)
    # (376 + 0.35·9.80665)/(0.15·0.0425) = 59518.8, root 243.965 rad/s
    assert h["release_speed"] == pytest.approx(243.9647, rel=1e-6)
    assert h["engagement_acceleration"] == pytest.approx(293.1008, rel=1e-6)
    assert h["engagement_frequency"] == pytest.approx(math.sqrt(120000.0), rel=1e-15)
    assert h["spring_height_limit"] == pytest.approx(0.0083356525, rel=1e-12)
    assert h["min_return_spring_rate"] == pytest.approx(3.92266 / 0.00435, rel=1e-12)
    # 2000·0.008 + 0.05·9.80665 − 52000·0.0021·0.1 = 16 + 0.4903325 − 10.92
    assert h["relock_margin"] == pytest.approx(5.5703325, rel=1e-12)
    assert h["relock_time"] == pytest.approx(0.0060247, abs=1e-7)


@pytest.mark.parametrize("name", sorted(hand()))
def test_every_closed_form_output_is_the_hand_value(name: str) -> None:
    r = run(RARE_IMPACT, REFERENCE_DESIGN, fidelity="closed_form")
    # 1e-12 for closed forms; the stage-2 times are brentq roots (to 1e-15 s, relative 1e-12)
    pin("impact.rare", name, r.results[name], hand()[name], rel=1e-11)


def test_every_numeric_output_is_named_here() -> None:
    numeric = {o.name for o in RARE_IMPACT.outputs if o.kind == "float" and not o.series}
    assert numeric - set(hand()) == {"half_coupling_release_speed"}  # the simulation's


def test_full_engagement_is_the_window_against_the_engagement_time() -> None:
    h = hand()
    r = run(RARE_IMPACT, REFERENCE_DESIGN, fidelity="closed_form")
    assert r.results["full_engagement"] is (h["engagement_time"] <= h["engagement_window"])
    assert r.results["full_engagement"] is True


def test_the_simulated_half_coupling_speed_is_solve_ivp_s() -> None:
    r = run(RARE_IMPACT, REFERENCE_DESIGN, fidelity="simulation")
    x, _ = RARE_IMPACT.validate(REFERENCE_DESIGN)
    reference, _ = simulate_cycle_scipy(x, rtol=1e-11)
    speed = r.results["half_coupling_release_speed"]
    assert isinstance(speed, float)
    pin("impact.rare", "half_coupling_release_speed", speed, reference.release_velocity, rel=1e-6)
    assert speed > 0.01  # it still lifts at release


def test_the_report_lists_the_steps_of_the_cycle() -> None:
    # the calculation report's equations are read from the functions the run calls: the
    # closed form's stages must be among them, in the order of the procedure
    from engine.core.equations import equations_of

    names = [e["function"] for e in equations_of(RARE_IMPACT.compute)]
    steps = ["_release_speed", "_time_to_speed", "_release_velocity", "_stage2", "_reach"]
    assert [n for n in names if n in steps] == steps
    assert {"relock_time", "striker_oscillation", "min_return_spring_rate"} <= set(names)
