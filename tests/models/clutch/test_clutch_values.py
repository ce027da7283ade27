"""Every numeric output of clutch.ball and clutch.ball_setting against a hand calculation.

The arithmetic is written out here from the equations of [001] (eq. 1–3), EN 13906-1
(helical springs), DIN EN 16983 (Almen–László disc springs) and the sizing rules of
torque-limiter makers, without calling the engine's functions; the examples are the
models' own (``BALL_CLUTCH.examples``, ``BALL_CLUTCH_SETTING.examples``).
"""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models.clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING

DEG = math.pi / 180.0

# The ordinary limiter (examples[3]): D0 = 50 mm, i = 4, d = 10 mm, α = 45°, f = 0.1,
# face friction 0.01; EN 10270-1 DH wire d0 = 4 mm (G = 81.5 GPa, E = 206 GPa,
# ρ = 7850 kg/m³, R_m = 1740 MPa), D = 32 mm, i_p = 8, L0 = 90 mm, set Δ = 30 mm; the
# balls rise h = 2 mm along the flank; one common spring; K_r = 0.85 (default).
G_DH = 81.5e9
RATE = G_DH * 0.004**4 / (8 * 0.032**3 * 8)  # c = G d0⁴/(8 D³ i_p) = 9948.73 N/m
PUSH = (1 - 0.1) / (1 + 0.1)  # tan(45° − atan 0.1) = (1 − f)/(1 + f) = 0.818182
INDEX = 0.032 / 0.004  # 8
WAHL = (4 * INDEX - 1) / (4 * INDEX - 4) + 0.615 / INDEX  # 31/28 + 0.076875 = 1.184018
RIM = 0.005 * (1 - math.sin(45 * DEG))  # over the rim the ball rises r(1 − sin α)


def _tau(force: float, mean: float = 0.032, wire: float = 0.004, kw: float = WAHL) -> float:
    """τ_k = 8 F D K_w/(π d0³), EN 13906-1."""
    return 8 * force * mean * kw / (math.pi * wire**3)


def test_every_output_of_the_ordinary_helical_limiter():
    v = run(BALL_CLUTCH, BALL_CLUTCH.examples[3]).results
    force = RATE * 0.03  # 298.462 N
    limit = 0.05 * force / (2 * PUSH)  # T = D0 F/(2 tan(α − ρ)) = 9.11967 N·m
    tangential = 2 * limit / (0.85 * 0.05 * 4)  # F_t = 2T/(K_r D0 i) = 107.290 N
    assert v["spring_rate"] == pytest.approx(9948.73, rel=1e-6)
    assert v["spring_rate"] == pytest.approx(RATE, rel=1e-12)
    assert v["spring_force"] == pytest.approx(force, rel=1e-12)
    assert v["torque_limit"] == pytest.approx(9.11967, rel=1e-6)
    assert v["torque_limit"] == pytest.approx(limit, rel=1e-12)
    assert v["ball_tangential_force"] == pytest.approx(tangential, rel=1e-12)
    assert v["ball_axial_force"] == pytest.approx(tangential * PUSH, rel=1e-12)  # 87.78 N
    normal = tangential / (math.cos(45 * DEG) + 0.1 * math.sin(45 * DEG))  # 137.94 N
    assert v["ball_normal_force"] == pytest.approx(normal, rel=1e-12)
    assert v["spring_index"] == INDEX
    assert v["wahl_factor"] == pytest.approx(1.184018, rel=1e-6)
    assert v["spring_shear_stress"] == pytest.approx(_tau(force), rel=1e-12)  # 449.9 MPa
    # over the lift: the torque D0 c (Δ + lift)/(2 tan(β − ρ)) falls past the rim here
    # (r cos α/(Δ + h) = 0.11 < 1/(sin cos)(α − ρ) = 2.04), so the peak is at the rim
    at_rim = RATE * (0.03 + 0.002)
    assert v["peak_torque"] == pytest.approx(0.05 * at_rim / (2 * PUSH), rel=1e-12)  # 9.7276
    assert v["torque_at_rim"] == v["peak_torque"]
    assert v["lift_at_peak"] == pytest.approx(0.002, rel=1e-12)
    assert v["flank_lift"] == pytest.approx(0.002, rel=1e-12)
    assert v["total_lift"] == pytest.approx(0.002 + RIM, rel=1e-12)  # 3.4645 mm
    assert v["spring_force_at_peak"] == pytest.approx(at_rim, rel=1e-12)  # 318.36 N
    most = RATE * (0.03 + 0.002 + RIM)  # riding on the face: 332.93 N
    assert v["spring_force_max"] == pytest.approx(most, rel=1e-12)
    assert v["spring_stress_at_peak"] == pytest.approx(_tau(at_rim), rel=1e-12)  # 479.9 MPa
    assert v["spring_stress_max"] == pytest.approx(_tau(most), rel=1e-12)  # 501.9 MPa
    # T_res = μ_face F_max D0/2 with one spring: 0.01·332.93·0.025 = 0.08323 N·m
    assert v["residual_torque"] == pytest.approx(0.01 * most * 0.025, rel=1e-12)
    assert v["self_locking_margin"] == pytest.approx(math.pi / 4 - math.atan(0.1), rel=1e-12)
    # dT/df = T/tan(α − ρ) · sec²(α − ρ)/(1 + f²), sec² = 1 + tan²: 18.4236 N·m
    sensitivity = limit / PUSH * (1 + PUSH**2) / (1 + 0.1**2)
    assert v["friction_sensitivity"] == pytest.approx(sensitivity, rel=1e-12)
    assert v["friction_sensitivity"] == pytest.approx(18.4236, rel=1e-5)
    assert v["solid_length"] == pytest.approx((8 + 2) * 0.004, rel=1e-12)  # ground ends
    # f_e = d0/(2π i_p D²) √(G/(2ρ)) = 0.0777124 · 2278.39 = 177.06 Hz
    f_e = 0.004 / (2 * math.pi * 8 * 0.032**2) * math.sqrt(G_DH / (2 * 7850))
    assert v["natural_frequency"] == pytest.approx(f_e, rel=1e-12)
    assert v["natural_frequency"] == pytest.approx(177.059, rel=1e-5)
    assert v["tensile_strength"] == 1740e6  # EN 10270-1 DH, 4 mm
    assert v["permissible_stress"] == 870e6  # 0.5 R_m
    # both ends fixed (the default seating, ν = 0.5): this spring cannot buckle
    assert v["buckling_deflection"] is None


def test_buckling_deflection_of_a_hinged_spring():
    v = run(BALL_CLUTCH, {**BALL_CLUTCH.examples[3], "spring_seating": "hinged_hinged"}).results
    # EN 13906-1: s_K = L0 0.5/(1 − G/E) [1 − √(1 − (1 − G/E)/(0.5 + G/E) (π D/(ν L0))²)]
    ratio = G_DH / 206e9  # 0.395631
    slender = math.pi * 0.032 / (1.0 * 0.09)  # 1.117011
    root = 1 - (1 - ratio) / (0.5 + ratio) * slender**2  # 0.158050
    s_k = 0.09 * 0.5 / (1 - ratio) * (1 - math.sqrt(root))  # 44.86 mm
    assert v["buckling_deflection"] == pytest.approx(s_k, rel=1e-12)
    assert v["buckling_deflection"] == pytest.approx(0.044857, rel=1e-4)


def test_disc_stack_force_and_force_at_flat():
    # examples[4]: discs De = 40, Di = 20.4, t = 1, h0 = 2 mm, two in series, Δ = 2.4 mm
    v = run(BALL_CLUTCH, BALL_CLUTCH.examples[4]).results
    delta = 0.04 / 0.0204
    k1 = ((delta - 1) / delta) ** 2 / ((delta + 1) / (delta - 1) - 2 / math.log(delta)) / math.pi
    scale = 4 * 206e9 / (1 - 0.3**2) / (k1 * 0.04**2)  # 4E/((1 − μ²) K1 De²)
    flat = scale * 0.001**3 * 0.002  # F_c = 4E t³ h0/((1 − μ²) K1 De²) = 1649.6 N
    assert v["disc_force_flat"] == pytest.approx(flat, rel=1e-12)
    assert v["disc_force_flat"] == pytest.approx(1649.61, rel=1e-5)
    # s = 1.2 mm per disc: F = scale t⁴ (s/t)[(h0/t − s/t)(h0/t − s/(2t)) + 1] = 1.272 F_c
    assert v["spring_force"] == pytest.approx(flat * 1.2 * ((2 - 1.2) * (2 - 0.6) + 1) / 2)


def test_every_output_of_the_papers_setting():
    # examples[0]: the paper's clutch (G = 80 GPa, D = 45 mm, i_p = 5, f = 0) set for
    # T = 0.5 N·m with one common spring: F = 2 T tan α/D0 = 20 N
    v = run(BALL_CLUTCH_SETTING, BALL_CLUTCH_SETTING.examples[0]).results
    rate = 8e10 * 0.004**4 / (8 * 0.045**3 * 5)  # 5618.66 N/m
    assert v["required_spring_force"] == pytest.approx(20.0, rel=1e-12)
    assert v["spring_rate"] == pytest.approx(rate, rel=1e-12)
    assert v["spring_rate"] == pytest.approx(5618.66, rel=1e-6)
    assert v["required_deflection"] == pytest.approx(20.0 / rate, rel=1e-12)  # 3.5596 mm
    index = 0.045 / 0.004  # 11.25
    kw = (4 * index - 1) / (4 * index - 4) + 0.615 / index  # 1.127837
    assert v["spring_index"] == pytest.approx(index, rel=1e-12)
    assert v["spring_shear_stress"] == pytest.approx(_tau(20.0, 0.045, 0.004, kw), rel=1e-12)
    # d0 = (8 F D³ i_p/(G Δ))^¼ at Δ = 4 mm: (2.278125e-10)^¼ = 3.8851 mm
    wire = (8 * 20.0 * 0.045**3 * 5 / (8e10 * 0.004)) ** 0.25
    assert v["required_wire_diameter"] == pytest.approx(wire, rel=1e-12)
    assert v["required_wire_diameter"] == pytest.approx(3.8851e-3, rel=1e-4)
    index_req = 0.045 / wire
    kw_req = (4 * index_req - 1) / (4 * index_req - 4) + 0.615 / index_req
    assert v["required_wire_spring_index"] == pytest.approx(index_req, rel=1e-12)
    assert v["required_wire_shear_stress"] == pytest.approx(
        _tau(20.0, 0.045, wire, kw_req), rel=1e-12
    )
    # the groove depth is the setting itself (no ball_lift): at the rim the spring is
    # compressed 2δ and the torque D0 c 2δ/(2 tan α) is the peak (r cos α/(2δ) = 0.99
    # < 1/(sin α cos α) = 2), so δ = T tan α/(D0 c) = 1.7798 mm
    peak_setting = 0.5 / (0.05 * rate)
    assert v["required_peak_setting"] == pytest.approx(peak_setting, rel=1e-12)
    assert v["required_peak_setting"] == pytest.approx(1.7798e-3, rel=1e-4)
    most = rate * (2 * peak_setting + 0.005 * (1 - math.sin(45 * DEG)))
    assert v["peak_setting_stress_max"] == pytest.approx(_tau(most, 0.045, 0.004, kw), rel=1e-12)


def test_setting_from_the_drive():
    # examples[1]: 0.37 kW at 1450 rpm, K = 2; the motor starts at 6 N·m, J_A = 1e-3,
    # J_L = 3e-3 kg·m²: T_N = P/ω = 2.43672 N·m, T_a = 6·3/(1 + 3) = 4.5 N·m,
    # target = max(K T_N, T_a) = 4.87343 N·m
    v = run(BALL_CLUTCH_SETTING, BALL_CLUTCH_SETTING.examples[1]).results
    rated = 370.0 / (1450 * math.pi / 30)
    assert v["rated_drive_torque"] == pytest.approx(rated, rel=1e-12)
    assert v["rated_drive_torque"] == pytest.approx(2.43672, rel=1e-5)
    assert v["start_torque"] == pytest.approx(4.5, rel=1e-12)
    assert v["required_slip_torque"] == pytest.approx(2 * rated, rel=1e-12)
    # F = 2 T tan(α − ρ)/D0 with f = 0.1: 2·4.87343·0.818182/0.05 = 159.494 N
    force = 2 * 2 * rated * PUSH / 0.05
    assert v["required_spring_force"] == pytest.approx(force, rel=1e-12)
    rate = RATE
    assert v["spring_rate"] == pytest.approx(rate, rel=1e-12)
    assert v["required_deflection"] == pytest.approx(force / rate, rel=1e-12)
    assert v["spring_shear_stress"] == pytest.approx(_tau(force), rel=1e-12)
    # with ball_lift h = 2 mm the peak is at the rim (as in the limiter above), where
    # the spring is compressed δ + h: δ = 2 T tan(α − ρ)/(D0 c) − h
    peak_setting = force / rate - 0.002
    assert v["required_peak_setting"] == pytest.approx(peak_setting, rel=1e-9)
    most = rate * (peak_setting + 0.002 + RIM)
    assert v["peak_setting_stress_max"] == pytest.approx(_tau(most), rel=1e-9)


def test_the_characteristic_curves_of_the_ordinary_limiter():
    r = run(BALL_CLUTCH, BALL_CLUTCH.examples[3], series=True)
    lift = r.series["lift"]
    # 41 points up the 2 mm flank, then 40 over the rim evenly in β from α to 90°
    betas = [45 * DEG + k / 40 * (90 - 45) * DEG for k in range(1, 41)]
    want = [k / 40 * 0.002 for k in range(41)]
    want += [0.002 + 0.005 * (math.sin(b) - math.sin(45 * DEG)) for b in betas]
    assert lift == pytest.approx(want, rel=1e-12, abs=1e-18)
    forces = [RATE * (0.03 + z) for z in want]
    assert r.series["spring_force_curve"] == pytest.approx(forces, rel=1e-12)
    assert r.series["spring_stress_curve"] == pytest.approx([_tau(f) for f in forces], rel=1e-12)
    # T = D0 F/(2 tan(β − ρ)): tan(α − ρ) on the flank; over the rim tan(β − atan 0.1)
    pushes = [PUSH] * 41 + [math.tan(b - math.atan(0.1)) for b in betas]
    torques = [0.05 * f / (2 * p) for f, p in zip(forces, pushes, strict=True)]
    assert r.series["torque_curve"] == pytest.approx(torques, rel=1e-9)
    # on the face (β = 90°) the ball slides: T = f D0 F/2 = 0.1·0.025·332.93 = 0.8323 N·m
    assert r.series["torque_curve"][-1] == pytest.approx(0.1 * 0.025 * forces[-1], rel=1e-9)
