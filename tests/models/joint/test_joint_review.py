"""The joint items of the 2026-11-26 review (issue 29), each held to a number worked out by
hand here from the VDI 2230-1 relations (not with the engine), the review's figures as a
cross-check."""

import math

import pytest

from engine import run
from engine.models import get_model

JOINT = get_model("joint.vdi2230")

# M12 coarse: ISO 68-1 / ISO 898-1 basics
D, P = 0.012, 0.00175
D2 = D - 0.649519 * P  # 10.863 mm
D3 = D - 1.226869 * P  # 9.853 mm
DS = (D2 + D3) / 2  # stress diameter, 10.358 mm
A_S, A_D3, A_N = math.pi / 4 * DS**2, math.pi / 4 * D3**2, math.pi / 4 * D**2
DW, DH = 0.01663, 0.0135  # ISO 4017 d_w,min, ISO 273 medium hole
E_S = 2.1e11


def _cone(grip, e, da):
    """VDI 2230-1 R3, through-bolted, one material: cones alone where D_A ≥ D_A,Gr."""
    beta, y = grip / DW, da / DW
    tan = 0.362 + 0.032 * math.log(beta / 2) + 0.153 * math.log(y)
    limit = DW + grip * tan
    if da >= limit:
        arg = (DW + DH) * (limit - DH) / ((DW - DH) * (limit + DH))
        return 2 * math.log(arg) / (e * math.pi * DH * tan)
    arg = (DW + DH) * (da - DH) / ((DW - DH) * (da + DH))
    cone = 2 / (DH * tan) * math.log(arg)
    sleeve = 4 / (da**2 - DH**2) * (grip - (da - DW) / tan)
    return (cone + sleeve) / (e * math.pi)


def _bolt_through(grip):
    """VDI 2230-1 R3: hex head 0.5d, free thread l_K, engaged 0.5d, nut 0.4d (steel)."""
    return (0.5 * D / A_N + grip / A_D3 + 0.5 * D / A_D3 + 0.4 * D / A_N) / E_S


def _f_mzul(mu, nu=0.9, rp=640e6):
    """VDI 2230-1 R7 at the stress section."""
    k = 1.5 * D2 / DS * (P / (math.pi * D2) + mu / math.cos(math.radians(30)))
    return nu * rp * A_S / math.sqrt(1 + 3 * k * k)


def _sigma_red(f_s, f_m, mu):
    """VDI 2230-1 R8: σ_z = F_S,max/A_0, τ = M_G/W_P with k_τ = 0.5."""
    m_g = f_m * D2 / 2 * (P / (math.pi * D2) + 1.155 * mu)  # R8/3 as VDI prints it
    tau = m_g / (math.pi * DS**3 / 16)
    return math.sqrt((f_s / A_S) ** 2 + 3 * (0.5 * tau) ** 2)


ALUMINIUM_HOT = {
    "thread_diameter": D,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "plate1_youngs_modulus": 7e10,
    "plate1_expansion": 23e-6,
    "outer_diameter": 0.040,
    "temperature_change": 150.0,
    "working_load": 0.0,
}


def test_r8_counts_the_thermal_preload_gain():
    # ΔF_Vth = l_K (α_S − α_P) ΔT / (δ_S + δ_P): the aluminium grows 0.04 × 11.5e-6 × 150 m
    # more than the bolt, a gain of ≈ 12.9 kN (negative loss)
    delta_s, delta_p = _bolt_through(0.040), _cone(0.040, 7e10, 0.040)
    gain = 0.040 * (11.5e-6 - 23e-6) * 150 / (delta_s + delta_p)
    f_mzul = _f_mzul(0.12)
    f_s_max = f_mzul - gain  # R8/1 with F_A = 0
    sigma = _sigma_red(f_s_max, f_mzul, 0.12)
    r = run(JOINT, ALUMINIUM_HOT)
    v = r.results
    assert v["thermal_loss"] == pytest.approx(gain, rel=1e-9)
    assert v["max_bolt_force"] == pytest.approx(f_s_max, rel=1e-9)
    assert v["working_stress"] == pytest.approx(sigma, rel=1e-9)
    assert v["yield_safety"] == pytest.approx(640e6 / sigma, rel=1e-9)
    # the review's figures: 12.9 kN, F_S,max 56.05 kN, σ_red,B 688 MPa, S_F 0.93
    assert -gain == pytest.approx(12.9e3, abs=0.05e3)
    assert v["max_bolt_force"] == pytest.approx(56.05e3, abs=0.01e3)
    assert v["working_stress"] == pytest.approx(688e6, abs=0.5e6)
    assert round(v["yield_safety"], 2) == 0.93
    check = {c.name: c for c in r.checks}["R8_working_stress"]
    assert not check.ok
    assert "ΔF_Vth" in check.detail


def test_r8_credits_no_thermal_loss_and_softening_enters():
    # a steel bolt heated more than steel plates loses preload: F_S,max stays F_M,zul
    cool = {**ALUMINIUM_HOT, "plate1_youngs_modulus": E_S, "plate1_expansion": 11.5e-6}
    cool |= {"plate_temperature_change": 0.0}
    v = run(JOINT, cool).results
    assert v["thermal_loss"] > 0.0
    assert v["max_bolt_force"] == pytest.approx(_f_mzul(0.12), rel=1e-9)
    # the aluminium case with the plates' E at 150 °C 0.9 of room temperature: the bolt force
    # at temperature is F_M (δ_S + δ_P)/(δ_S + δ_P/0.9) − l_K (α_S − α_P) ΔT/(δ_S + δ_P/0.9)
    soft = {**ALUMINIUM_HOT, "plate_modulus_ratio": 0.9}
    delta_s, delta_p = _bolt_through(0.040), _cone(0.040, 7e10, 0.040)
    den = delta_s + delta_p / 0.9
    f_m = _f_mzul(0.12)
    hot = f_m * (delta_s + delta_p) / den - 0.040 * (11.5e-6 - 23e-6) * 150 / den
    assert run(JOINT, soft).results["max_bolt_force"] == pytest.approx(hot, rel=1e-9)


def test_r10_working_pressure_takes_the_hot_bolt_force():
    # p = F / A_p with A_p = π/4 (d_W² − d_h²) = 74.07 mm²: at F_M,zul 582 MPa, at the hot
    # F_S,max 757 MPa; a p_G of 700 MPa holds the first and not the second
    a_p = math.pi / 4 * (DW**2 - DH**2)
    f_s_max = _f_mzul(0.12) - 0.040 * (11.5e-6 - 23e-6) * 150 / (
        _bolt_through(0.040) + _cone(0.040, 7e10, 0.040)
    )
    assert _f_mzul(0.12) / a_p < 700e6 < f_s_max / a_p
    x = {**ALUMINIUM_HOT, "limiting_surface_pressure": 700e6}
    x["thread"] = "M12 ISO 4017 8.8"
    del x["thread_diameter"]
    checks = {c.name: c for c in run(JOINT, x).checks}
    assert checks["surface_pressure_assembly"].ok
    assert not checks["surface_pressure_working"].ok
    assert f"{f_s_max / a_p / 1e6:.4g} MPa" in checks["surface_pressure_working"].detail


# ----------------------------------------------------------------- nut strength, ISO 898-2


def test_nut_proof_loads_match_the_printed_table():
    from engine.physics import fasteners as fa

    # DIN EN 20898-2 (ISO 898-2:1992) prints proof loads S_p × A_s for M12 (A_s 84.3 mm²):
    # class 8 74 200 N, 10 88 500 N, 12 style 1 98 600 N, style 2 100 300 N; thin nuts
    # 04/05 carry 380/500 MPa: 32 034 / 42 150 N
    printed = {("8", "style 1"): 74200, ("10", "style 1"): 88500}
    printed |= {("12", "style 1"): 98600, ("12", "style 2"): 100300}
    for (cls, style), load in printed.items():
        assert fa.nut_proof_load(cls, 0.012, 84.3e-6, style) == pytest.approx(load, abs=50)
    assert fa.nut_proof_load("04", 0.012, 84.3e-6) == pytest.approx(380 * 84.3, rel=1e-12)
    assert fa.nut_proof_load("05", 0.012, 84.3e-6) == pytest.approx(500 * 84.3, rel=1e-12)
    # M20 (A_s 245 mm², > M16): class 8 225 400 N printed (920 MPa)
    assert fa.nut_proof_load("8", 0.020, 245e-6) == pytest.approx(225400, abs=50)
    # out of the table: above M39, class 4 below M16
    assert math.isnan(fa.nut_proof_load("8", 0.042, 1121e-6))
    assert math.isnan(fa.nut_proof_stress("4", 0.012))
    # the pairing of ISO 898-2: class N with bolts up to N.x, thin nuts with none
    assert fa.nut_pairs_with_bolt("8", 830e6) and fa.nut_pairs_with_bolt("10", 830e6)
    assert not fa.nut_pairs_with_bolt("8", 1040e6)
    assert not fa.nut_pairs_with_bolt("10", 1220e6) and fa.nut_pairs_with_bolt("12", 1220e6)
    assert not fa.nut_pairs_with_bolt("05", 400e6)


M12_129_THIN = {
    "thread": "M12 ISO 4017 12.9",
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "working_load": 5e3,
    "nut": "ISO 4035",
    "nut_property_class": "04",
}


def test_a_thin_nut_limits_the_preload_and_fails():
    # bolt alone: F_M,zul = 0.9 × 1100 MPa × A_s / √(1 + 3 k²) ≈ 74.1 kN (R7, μ_G 0.12);
    # the class 04 nut's proof load 380 MPa × A_s = 32.02 kN caps it
    bolt_alone = _f_mzul(0.12, rp=1100e6)
    nut = 380e6 * A_S
    assert bolt_alone == pytest.approx(74.1e3, abs=0.05e3)
    alone = run(JOINT, {k: v for k, v in M12_129_THIN.items() if not k.startswith("nut")})
    r = run(JOINT, M12_129_THIN)
    assert alone.results["permissible_preload"] == pytest.approx(bolt_alone, rel=1e-9)
    assert r.results["permissible_preload"] == pytest.approx(nut, rel=1e-9)
    # the torque is built on it: M_A ∝ F_M,zul with no prevailing torque
    ratio = r.results["tightening_torque"] / alone.results["tightening_torque"]
    assert ratio == pytest.approx(nut / bolt_alone, rel=1e-9)
    checks = {c.name: c for c in r.checks}
    assert not checks["nut_strength"].ok and not checks["nut_class_pairing"].ok
    assert any("limits the preload" in w and "32.02 kN" in w for w in r.warnings)
    # an unnamed thin-nut class is taken as the weaker one made (04: 380 MPa, the safe side)
    # and says so
    x = {k: v for k, v in M12_129_THIN.items() if k != "nut_property_class"}
    r04 = run(JOINT, x)
    assert r04.results["permissible_preload"] == pytest.approx(380e6 * A_S, rel=1e-9)
    assert "class 04 (assumed)" in {c.name: c for c in r04.checks}["nut_strength"].detail


def test_a_paired_full_nut_leaves_the_bolt_alone_and_a_weak_class_fails_pairing():
    full = {**M12_129_THIN, "thread": "M12 ISO 4017 8.8", "nut": "ISO 4032"}
    del full["nut_property_class"]
    r = run(JOINT, full)
    assert r.results["permissible_preload"] == pytest.approx(_f_mzul(0.12), rel=1e-9)
    checks = {c.name: c for c in r.checks}
    assert checks["nut_strength"].ok and checks["nut_class_pairing"].ok
    assert "class 8 (assumed)" in checks["nut_class_pairing"].detail
    # a 12.9 bolt in an ISO 4032 nut of no named class: no class it is made in pairs with
    # 12.9, so the weakest made is assumed (6: 700 MPa × A_s = 58.99 kN < the bolt's 74.1 kN)
    r = run(JOINT, {**full, "thread": "M12 ISO 4017 12.9"})
    checks = {c.name: c for c in r.checks}
    assert not checks["nut_strength"].ok and not checks["nut_class_pairing"].ok
    assert "class 6 (assumed)" in checks["nut_strength"].detail
    assert r.results["permissible_preload"] == pytest.approx(700e6 * A_S, rel=1e-9)
    # named class 10 (1050 MPa × A_s = 88.5 kN) carries the bolt's 74.1 kN but does not pair
    r = run(JOINT, {**full, "thread": "M12 ISO 4017 12.9", "nut_property_class": "10"})
    checks = {c.name: c for c in r.checks}
    assert checks["nut_strength"].ok and not checks["nut_class_pairing"].ok
    assert r.results["permissible_preload"] == pytest.approx(_f_mzul(0.12, rp=1100e6), rel=1e-9)


def test_nut_checks_on_the_array_path_match_single_runs():
    import numpy as np

    from tests.models.joint.test_joint_arrays import _assert_matches_single_runs

    base = {**M12_129_THIN, "nut_property_class": "05"}
    # F_S,max = F_p + Φ_n F_A crosses nothing here; the check fails at every point, the
    # outputs follow the capped F_M,zul
    chunk = _assert_matches_single_runs(base, {"working_load": np.array([0.0, 5e3, 20e3])})
    assert chunk.values["permissible_preload"][0] == pytest.approx(500e6 * A_S, rel=1e-9)


# ----------------------------------------------------------------- the smaller items


M8_INTO_6082 = {
    "thread": "M8 ISO 4762 12.9",
    "joint_type": "tapped",
    "head": "socket",
    "plate1_thickness": 0.012,
    "plate1_youngs_modulus": 7e10,
    "working_load": 4e3,
    "internal_thread_material": "EN AW-6082 T6",
    "engagement_length": 0.016,
}


def test_a_tapped_thread_takes_the_modulus_of_its_material():
    # VDI 2230-1 R3, tapped, socket head, all 12 mm of grip free thread:
    # δ_S = (0.4 d/A_N + l/A_d3 + 0.5 d/A_d3)/E_S + 0.33 d/(E_M A_N), E_M = 70 GPa (6082)
    d, p = 0.008, 0.00125
    a_n, a_d3 = math.pi / 4 * d**2, math.pi / 4 * (d - 1.226869 * p) ** 2
    bolt_part = (0.4 * d / a_n + 0.012 / a_d3 + 0.5 * d / a_d3) / E_S
    aluminium = bolt_part + 0.33 * d / (7e10 * a_n)
    steel = bolt_part + 0.33 * d / (E_S * a_n)
    r = run(JOINT, M8_INTO_6082)
    assert r.results["bolt_compliance"] == pytest.approx(aluminium, rel=1e-9)
    assert r.results["bolt_compliance_engaged"] == pytest.approx(
        0.5 * d / (E_S * a_d3) + 0.33 * d / (7e10 * a_n), rel=1e-9
    )
    assert any("E_M = 70 GPa of EN AW-6082 T6" in n for n in r.notes)
    # the steel modulus under-stated δ_S by (aluminium − steel)/aluminium ≈ 14 %
    assert 1 - steel / aluminium == pytest.approx(0.14, abs=0.01)
    # typed, the modulus wins; a through joint's nut stays steel
    typed = run(JOINT, {**M8_INTO_6082, "nut_youngs_modulus": E_S})
    assert typed.results["bolt_compliance"] == pytest.approx(steel, rel=1e-9)


def test_a_separated_joint_reports_no_clamp_force_and_no_slip_safety():
    # M12 8.8, 40 N·m, 80 kN axial and 2 kN transverse: F_M,min − (1 − Φ_n) F_A − F_Z < 0
    x = {
        "thread_diameter": D,
        "plate1_thickness": 0.020,
        "plate2_thickness": 0.020,
        "working_load": 80e3,
        "transverse_load": 2e3,
        "tightening_torque": 40.0,
    }
    r = run(JOINT, x)
    v = r.results
    raw = v["assembly_preload_min"] - (1 - v["load_factor"]) * 80e3 - v["embedding_loss"]
    assert raw < 0.0
    assert v["residual_clamp_force_min"] == 0.0 and v["slip_safety"] == 0.0
    checks = {c.name: c for c in r.checks}
    assert not checks["residual_clamp_force"].ok and not checks["R12_slip"].ok
    assert any("the joint opens" in w and "slip_safety 0" in w for w in r.warnings)
    # just closed (F_A 10 kN): F_KR,min and S_G = F_KR q μ/F_Q as before, positive
    v = run(JOINT, {**x, "working_load": 10e3}).results
    f_kr = v["assembly_preload_min"] - (1 - v["load_factor"]) * 10e3 - v["embedding_loss"]
    assert v["residual_clamp_force_min"] == pytest.approx(f_kr, rel=1e-12)
    assert v["slip_safety"] == pytest.approx(f_kr * 1 * 0.15 / 2e3, rel=1e-12)


def test_r9_says_when_its_endurance_limit_is_applied_outside_its_range():
    base = {"plate1_thickness": 0.020, "plate2_thickness": 0.020, "working_load": 5e3}
    base["working_load_min"] = 0.0
    # σ_ASV = 0.85 (150/12 + 45) = 48.875 MPa, fitted to ISO 898-1 8.8–12.9, d ≤ 40 mm
    for thread in ("M12 ISO 4017 A2-70", "M12 ISO 4017 4.6"):
        r = run(JOINT, {**base, "thread": thread})
        assert r.results["endurance_limit"] == pytest.approx(0.85 * (150 / 12 + 45) * 1e6)
        assert any("applied outside its range" in w for w in r.warnings), thread
    assert not any(
        "outside" in w for w in run(JOINT, {**base, "thread": "M12 ISO 4017 8.8"}).warnings
    )
    inch = run(JOINT, {**base, "thread": "1/2-13 UNC", "grade": "SAE 5"})
    assert any("an inch thread" in w for w in inch.warnings)


def test_the_error_estimate_of_zero_comes_with_the_model_form_sentence():
    r = run(JOINT, ALUMINIUM_HOT)
    assert r.error_estimate == 0.0
    said = [n for n in r.notes if n.startswith("error estimate 0")]
    assert len(said) == 1 and all(w in said[0] for w in ("cone-angle", "f_Z", "factor n"))


# ----------------------------------------------------------------- R11 thread stripping


def _r11_tapped(r_m, tau_bm, tau_bs):
    """VDI 2230-1 R11 (Alexander) for M12 into a tapped hole, C1 = 1, written out:
    m_ges = 1.2 R_m A_s P / (C3 τ_BM (P/2 + (d − D2) tan 30°) π d) + 2 P, with C3 from
    R_S = τ_BM d (P/2 + (d − D2) tan 30°) / (τ_BS D1 (P/2 + (D2 − D1) tan 30°)) ≥ 0.4,
    or the bolt thread's length where that is longer."""
    d1 = D - 1.082532 * P  # D1 of ISO 68-1
    t30 = math.tan(math.radians(30))
    per_n = math.pi * D * (P / 2 + (D - D2) * t30) / P  # A_SN per metre of engagement
    per_s = math.pi * d1 * (P / 2 + (D2 - d1) * t30) / P  # A_SS per metre
    r_s = max(tau_bm * per_n / (tau_bs * per_s), 0.4)
    assert r_s < 1  # the tapped thread is the weaker: C2 = 1 (bolt thread), C3 from R_S
    c3 = 0.728 + 1.769 * r_s - 2.896 * r_s**2 + 1.296 * r_s**3
    f_b = 1.2 * r_m * A_S
    return max(f_b / (c3 * tau_bm * per_n), f_b / (tau_bs * per_s)) + 2 * P


@pytest.mark.parametrize(
    ("material", "tau", "review_mm"),
    [("S235JR", 0.6 * 360e6, 14.6), ("EN-GJL-250", 1.1 * 250e6, 12.8)],
)
def test_r11_sizes_the_engagement_for_the_bolt_at_its_upper_strength(material, tau, review_mm):
    hand = _r11_tapped(800e6, tau, 0.6 * 800e6)
    assert hand * 1e3 == pytest.approx(review_mm, abs=0.06)  # the review's figures
    tight = get_model("preload.tightening")
    need = run(tight, {"thread": "M12 ISO 4017 8.8", "internal_thread_material": material})
    assert need.results["min_engagement_length"] == pytest.approx(hand, rel=2e-4)
    assert need.results["bolt_breaking_force"] == pytest.approx(1.2 * 800e6 * A_S, rel=1e-9)
    # the joint: 12 mm of engagement now fails into S235JR; the needed length passes
    x = {
        "thread": "M12 ISO 4017 8.8",
        "joint_type": "tapped",
        "plate1_thickness": 0.020,
        "working_load": 5e3,
        "internal_thread_material": material,
    }
    for length in (hand * 0.99, hand * 1.01):
        r = run(JOINT, {**x, "engagement_length": length})
        ok = {c.name: c.ok for c in r.checks}["thread_stripping"]
        assert ok is (length > hand)
    if material == "S235JR":
        r = run(JOINT, {**x, "engagement_length": 0.012})
        assert not {c.name: c.ok for c in r.checks}["thread_stripping"]


def test_a_nut_class_without_a_nut_is_said_to_be_ignored():
    x = {**ALUMINIUM_HOT, "nut_property_class": "8"}
    r = run(JOINT, x)
    assert any(n.startswith("nut_property_class ignored") for n in r.notes)
    assert r.results["permissible_preload"] == pytest.approx(_f_mzul(0.12), rel=1e-9)


def test_a_sweep_warns_of_a_nut_that_limits_and_a_joint_that_opens():
    from engine.core.runner import sweep

    r = sweep(JOINT, dict(M12_129_THIN), "working_load", [0.0, 5e3, 200e3])
    said = " ".join(r.warnings)
    assert "limits the preload at some points" in said
    assert "the joint opens at some points" in said
    assert r.results["residual_clamp_force_min"][2] == 0.0
