"""The VDI 2230-1 steps R1–R12 of engine.physics.joint that the model once wrote inline, each held
to a value worked out by hand here (inputs → the step's relation → the number), on floats
and on arrays."""

import math

import numpy as np
import pytest

from engine.physics import joint as jt


def test_r2_required_clamp_force_is_the_larger_requirement():
    # F_KQ = 2000 / (1 × 0.15) = 13 333.3 N against a sealing F_KP of 5 kN and 20 kN
    f_kq = 2000.0 / (1 * 0.15)
    assert jt.required_clamp_force(f_kq, 5e3) == pytest.approx(13333.333, rel=1e-6)
    assert jt.required_clamp_force(f_kq, 20e3) == 20e3
    got = jt.required_clamp_force(np.array([f_kq, f_kq]), np.array([5e3, 20e3]))
    assert got.tolist() == pytest.approx([13333.333, 20e3], rel=1e-6)


def test_r4_locations_settlement_and_expansion_length():
    # two plates through-bolted: head and nut faces (2), one inner interface; tapped: 1 face,
    # each plate's interface with the next or with the tapped part
    assert jt.embedding_locations("through", 2) == (2, 1)
    assert jt.embedding_locations("tapped", 2) == (1, 2)
    # Rz 10–40, Table 5.4/1: axial 3 + 2 × 3 + 1 × 2 = 11 µm; transverse 3 + 2 × 4.5 + 2.5 = 14.5
    assert jt.embedding_for_load("Rz10-40", 0.0, 2, 1) == pytest.approx(11e-6, rel=1e-12)
    assert jt.embedding_for_load("Rz10-40", 1.0, 2, 1) == pytest.approx(14.5e-6, rel=1e-12)
    both = jt.embedding_for_load("Rz10-40", np.array([0.0, 1.0]), 2, 1)
    assert both.tolist() == pytest.approx([11e-6, 14.5e-6], rel=1e-12)
    # 10 mm steel + 30 mm aluminium: 0.01 × 11.5e-6 + 0.03 × 23e-6 = 8.05e-7 m/K
    assert jt.plates_expansion_length([0.01, 0.03], [11.5e-6, 23e-6]) == pytest.approx(
        8.05e-7, rel=1e-12
    )


def test_r4_r5_losses_credit_no_thermal_gain():
    assert jt.preload_losses(2600.0, 1500.0) == 4100.0
    assert jt.preload_losses(2600.0, -900.0) == 2600.0  # a gain is not credited
    assert jt.preload_losses(np.array([2600.0]), np.array([-900.0])).tolist() == [2600.0]


def test_r3_load_split_and_r8_bolt_force():
    # Φ_n = 0.2, F_A = 10 kN: the bolt takes 2 kN, the plates are relieved by 8 kN
    assert jt.additional_bolt_load(0.2, 10e3) == pytest.approx(2000.0)
    assert jt.clamp_load_reduction(0.2, 10e3) == pytest.approx(8000.0)
    assert jt.max_bolt_force(40e3, 2000.0) == 42e3


def test_r5_r12_residual_clamp_force_and_the_balance_it_closes():
    # F_KR = 30 000 − 0.8 × 10 000 − 2 600 − 400 = 19 000 N
    assert jt.residual_clamp_force(30e3, 10e3, 0.2, 2600.0, 400.0) == pytest.approx(19e3)
    # a thermal gain (−400) is not credited: 30 000 − 8 000 − 2 600 = 19 400
    assert jt.residual_clamp_force(30e3, 10e3, 0.2, 2600.0, -400.0) == pytest.approx(19.4e3)
    # R5 is the same balance solved for F_M,min: starting from it leaves exactly F_K,erf
    f_m_min = jt.minimum_assembly_preload(12e3, 10e3, 0.2, 2600.0, 400.0)
    assert f_m_min == pytest.approx(12e3 + 8e3 + 2600 + 400)
    assert jt.residual_clamp_force(f_m_min, 10e3, 0.2, 2600.0, 400.0) == pytest.approx(12e3)


def test_r12_separation_and_r5_r7_largest_working_load():
    # F_A,sep = (30 000 − 3 000) / (1 − 0.2) = 33 750 N; Φ_n = 1: the plates never unload
    assert jt.separation_load(30e3, 3000.0, 0.2) == pytest.approx(33750.0)
    assert jt.separation_load(30e3, 3000.0, 1.0) == math.inf
    assert jt.separation_load(2e3, 3000.0, 0.2) == 0.0  # the losses eat the preload
    arr = jt.separation_load(np.array([30e3, 30e3]), 3000.0, np.array([0.2, 1.0]))
    assert arr.tolist() == [pytest.approx(33750.0), math.inf]
    # F_A,max = (43 100/1.6 − 10 000 − 3 000)/(1 − 0.2) = (26 937.5 − 13 000)/0.8 = 17 421.875
    assert jt.max_working_load(43.1e3, 1.6, 10e3, 3000.0, 0.2) == pytest.approx(17421.875)


def test_r1_r6_r7_preload_ranges():
    assert jt.required_preload_max(1.6, 20e3) == pytest.approx(32e3)
    assert jt.design_preload_range(40e3, 1.6) == (25e3, 40e3)
    # a torque box 31.5 … 64.308 kN: α_A = 64 308/31 500 = 2.04152
    assert jt.torque_tightening_factor(31500.0, 64308.0) == pytest.approx(2.041524, rel=1e-6)
    assert jt.torque_tightening_factor(0.0, 64308.0) == math.inf
    arr = jt.torque_tightening_factor(np.array([31500.0, 0.0]), np.array([64308.0, 1.0]))
    assert arr.tolist() == [pytest.approx(2.041524, rel=1e-6), math.inf]
    assert jt.nominal_preload(25e3, 40e3) == 32.5e3


def test_r7_smallest_area():
    assert jt.smallest_area(0.010358, 84.27e-6, "thread") == 84.27e-6
    # d_T = 7.5 mm: π × 7.5² / 4 = 44.179 mm²
    assert jt.smallest_area(0.0075, 84.27e-6, "shank") == pytest.approx(44.179e-6, rel=1e-4)
    arr = jt.smallest_area(np.array([0.0075, 0.010358]), 84.27e-6, np.array(["shank", "thread"]))
    assert arr.tolist() == pytest.approx([44.179e-6, 84.27e-6], rel=1e-4)


def test_r8_r9_safeties_and_stress_amplitude():
    assert jt.yield_safety(640e6, 512e6) == pytest.approx(1.25)
    # σ_a = 0.1 × (8000 − 2000) / (2 × 84.3 mm²) = 600/168.6e-6 = 3.5587 MPa
    assert jt.stress_amplitude(0.1, 8000.0, 2000.0, 84.3e-6) == pytest.approx(3.5587e6, rel=1e-4)
    # F_Sm = 40 000 + 0.1 × (8000 + 2000)/2 = 40 500 N
    assert jt.mean_bolt_force(40e3, 0.1, 8000.0, 2000.0) == pytest.approx(40500.0)
    assert jt.fatigue_safety(48e6, 4e6) == pytest.approx(12.0)
    assert jt.fatigue_safety(48e6, 0.0) == math.inf  # static load
    assert jt.fatigue_safety(48e6, np.array([4e6, 0.0])).tolist() == [12.0, math.inf]


def test_r12_slip_safety_and_what_vdi_asks():
    # S_G = 20 000 × 2 × 0.15 / 3000 = 2.0
    assert jt.slip_safety(20e3, 2, 0.15, 3000.0) == pytest.approx(2.0)
    assert jt.slip_safety(20e3, 2, 0.15, 0.0) == math.inf
    got = jt.slip_safety(np.array([20e3, 20e3]), 2, 0.15, np.array([3000.0, 0.0]))
    assert got.tolist() == [pytest.approx(2.0), math.inf]
    assert jt.required_slip_safety(8e3, 0.0) == 1.8
    assert jt.required_slip_safety(8e3, 8e3) == 1.2
    assert jt.required_slip_safety(np.array([8e3, 8e3]), np.array([0.0, 8e3])).tolist() == [
        1.8,
        1.2,
    ]


def test_seed_004_preload_stress_ratio():
    # σ0/σ_T = 32 500 / (84.27e-6 × 640e6) = 32 500 / 53 932.8 = 0.60260
    assert jt.preload_stress_ratio(32.5e3, 84.27e-6, 640e6) == pytest.approx(0.60260, rel=1e-4)


def test_r13_tightening_torque_adds_thread_bearing_and_prevailing_torque():
    # M12, μ_G = μ_K = 0.12: k_G = 0.16 × 1.75 + 0.58 × 10.863 × 0.12 = 1.03606 mm,
    # k_K = 0.12 × (16.63 + 13.5)/4 = 0.9039 mm; at 40 kN plus M_ü = 2 N·m:
    # 40 000 × (1.03606 + 0.9039) e-3 + 2 = 79.598 N·m
    k_g = 0.16 * 0.00175 + 0.58 * 0.010863 * 0.12
    k_k = 0.12 * (0.01663 + 0.0135) / 4
    assert jt.tightening_torque(40e3, k_g, k_k, 2.0) == pytest.approx(79.598, rel=1e-4)


@pytest.mark.parametrize("joint, w", [("through", 1), ("tapped", 2)])
def test_r3_unlimited_outer_diameter_is_the_cone_s_own_fixed_point(joint, w):
    # D_A = d_W + w l_K tan φ(y = D_A/d_W), with VDI's fits written out here; one design and
    # a sweep run the same steps, so they agree to the last bits
    dw = 0.01663
    grips = np.array([0.002, 0.01, 0.04, 0.2, 1.0])
    got = jt.unlimited_outer_diameter(grips, dw, joint)
    for g, da in zip(grips.tolist(), got.tolist(), strict=True):
        y = da / dw
        if w == 1:
            tan = 0.362 + 0.032 * math.log(g / dw / 2) + 0.153 * math.log(y)
        else:
            tan = 0.348 + 0.013 * math.log(g / dw) + 0.193 * math.log(y)
        assert da == pytest.approx(dw + w * g * max(tan, 0.1), rel=1e-11)
        assert jt.unlimited_outer_diameter(g, dw, joint) == pytest.approx(da, rel=1e-15)
