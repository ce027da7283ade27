"""Every numeric output of joint.vdi2230 against a hand calculation written out here.

The first example (M12 8.8 through two 20 mm steel plates, F_A 0…8 kN, F_Q 2 kN, torque wrench,
μ 0.12) is worked through VDI 2230-1 R0–R13 from the ISO thread and property-class data alone,
with no engine function: inputs → the step's relation → the number. The torque example and the
waisted tapped example then pin what the first one cannot (a torque box, a shank, w = 2).
"""

import math

import pytest

from engine import run
from engine.models import get_model
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
E = 2.1e11  # steel, the model's default [Pa]

# ISO 68-1 / 261 M12 coarse, ISO 898-1 8.8 (d ≤ 16), ISO 4017 d_w,min, ISO 273 medium hole
D, P = 0.012, 0.00175
D2 = D - 0.649519 * P  # 10.863 mm
D3 = D - 1.226869 * P  # 9.853 mm
DS = 0.5 * (D2 + D3)  # stress diameter 10.358 mm
AS = math.pi / 4 * DS**2  # 84.27 mm²
AD3, AN = math.pi / 4 * D3**2, math.pi / 4 * D**2
RP = 640e6
DW, DH = 0.01663, 0.0135


def _cone_tangent(grip, w):
    """VDI 2230-1 R3 cone tangent for D_A = D_A,Gr (the fixed point D_A = d_W + w l_K tan φ)."""
    tan = 0.5
    for _ in range(200):
        y = (DW + w * grip * tan) / DW
        if w == 1:
            tan = 0.362 + 0.032 * math.log(grip / DW / 2) + 0.153 * math.log(y)
        else:
            tan = 0.348 + 0.013 * math.log(grip / DW) + 0.193 * math.log(y)
    return tan


def _cone_compliance(grip, e, tan, w):
    """δ_P of a full cone (D_A ≥ D_A,Gr), VDI 2230-1 R3 eq. (5.1/24)."""
    limit = DW + w * grip * tan
    arg = (DW + DH) * (limit - DH) / ((DW - DH) * (limit + DH))
    return 2 * math.log(arg) / (w * e * math.pi * DH * tan)


def _torsion(d0, mu):
    """R7's root: √(1 + 3 [3/2 · d2/d0 · (P/(π d2) + μ_G/cos 30°)]²) (VDI rounds 1/cos 30° to
    1.155; the model keeps it exact here, and R8 below uses VDI's 1.155 as printed)."""
    return math.sqrt(
        1 + 3 * (1.5 * D2 / d0 * (P / (math.pi * D2) + mu / math.cos(math.pi / 6))) ** 2
    )


def first_example_by_hand():
    grip, mu, nu, n_load = 0.040, 0.12, 0.9, 0.5
    f_a, f_a_min, f_q = 8e3, 0.0, 2e3
    # R3 bolt: head 0.5 d, the whole grip free thread, engaged thread 0.5 d, nut 0.4 d
    head = 0.5 * D / (E * AN)
    free = grip / (E * AD3)
    engaged = 0.5 * D / (E * AD3) + 0.4 * D / (E * AN)
    delta_s = head + free + engaged
    # R3 plates: through-bolted (w = 1), plates just wide enough for the full cone
    tan = _cone_tangent(grip, 1)
    limit = DW + grip * tan
    delta_p = _cone_compliance(grip, E, tan, 1)
    phi_k = delta_p / (delta_s + delta_p)
    phi_n = n_load * phi_k
    # R2: friction carries F_Q across one interface at μ_T = 0.15
    f_kq = f_q / (1 * 0.15)
    # R4: Rz 10–40, transverse load, 2 bearing faces + 1 interface: 3 + 2 × 4.5 + 2.5 µm
    f_z_len = (3 + 2 * 4.5 + 2.5) * 1e-6
    f_z = f_z_len / (delta_s + delta_p)
    # R7 at the thread (no shank): F_M,zul = ν R_p0.2 A_S / β
    beta = _torsion(DS, mu)
    f_mzul = nu * RP * AS / beta
    f_myield = RP * AS / beta
    # R1: torque wrench ±30 %: α_A = 1.3/0.7; tightened to F_M,zul
    alpha = 1.3 / 0.7
    fm_max, fm_min = f_mzul, f_mzul / alpha
    # R13 at μ_G,min = μ_K,min = 0.12, D_Km = (d_W + d_h)/2
    torque = f_mzul * (0.16 * P + 0.58 * D2 * mu + mu * (DW + DH) / 4)
    # R5/R6 (no thermal loss: ΔT = 0)
    req_min = f_kq + (1 - phi_n) * f_a + f_z
    req_max = alpha * req_min
    f_kr = fm_min - (1 - phi_n) * f_a - f_z
    f_a_sep = (fm_min - f_z) / (1 - phi_n)
    f_a_max = max((f_mzul / alpha - f_kq - f_z) / (1 - phi_n), 0.0)
    # R8: σ_red,B with k_τ = 0.5 on d_0 = d_S
    f_s_max = fm_max + phi_n * f_a
    sigma_z = f_s_max / AS
    tau = fm_max * D2 / 2 * (P / (math.pi * D2) + 1.155 * mu) / (math.pi * DS**3 / 16)
    sigma_red = math.sqrt(sigma_z**2 + 3 * (0.5 * tau) ** 2)
    # R9: rolled before heat treatment, σ_ASV = 0.85 (150/d + 45) MPa
    sigma_a = phi_n * (f_a - f_a_min) / (2 * AS)
    sigma_asv = 0.85 * (150 / 12 + 45) * 1e6
    # [004, eq. 6–9] at the nominal preload
    nominal = 0.5 * (fm_min + fm_max)
    return {
        "tightening_factor": alpha,
        "required_clamp_force": f_kq,
        "transverse_clamp_force": f_kq,
        "bolt_compliance": delta_s,
        "bolt_compliance_head": head,
        "bolt_compliance_shank": 0.0,
        "bolt_compliance_free_thread": free,
        "bolt_compliance_engaged": engaged,
        "clamped_compliance": delta_p,
        "eccentric_clamped_compliance": delta_p,  # concentric: δ*_P = δ_P
        "opening_clamp_force": 0.0,  # concentric: no edge to open
        "additional_bolt_stress": phi_n * f_a / AS,  # concentric: σ_SA = Φ_n F_A/A_S
        "cone_tangent": tan,
        "cone_limit_diameter": limit,
        "outer_diameter_used": limit,
        "grip": grip,
        "load_factor_k": phi_k,
        "load_factor": phi_n,
        "additional_bolt_load": phi_n * f_a,
        "clamp_load_reduction": (1 - phi_n) * f_a,
        "embedding_settlement": f_z_len,
        "embedding_loss": f_z,
        "thermal_loss": 0.0,
        "required_preload_min": req_min,
        "required_preload_max": req_max,
        "smallest_diameter": DS,
        "smallest_area": AS,
        "permissible_preload": f_mzul,
        "yield_preload": f_myield,
        "assembly_preload_min": fm_min,
        "assembly_preload_max": fm_max,
        "tightening_torque": torque,
        "residual_clamp_force_min": f_kr,
        "separation_load": f_a_sep,
        "max_working_load": f_a_max,
        "max_bolt_force": f_s_max,
        "working_stress": sigma_red,
        "yield_safety": RP / sigma_red,
        "stress_amplitude": sigma_a,
        "endurance_limit": sigma_asv,
        "fatigue_safety": sigma_asv / sigma_a,
        "slip_safety": f_kr * 1 * 0.15 / f_q,
        "preload_stress_ratio": nominal / AS / RP,
        "bolt_elongation": nominal * delta_s,
        "target_angle": 2 * math.pi * nominal * (delta_s + delta_p) / P,
        "rigid_joint_angle": 2 * math.pi * nominal * delta_s / P,
    }


HAND = first_example_by_hand()
FIRST = run(JOINT, JOINT.examples[0]).results


def test_the_hand_calculation_covers_every_numeric_output():
    # nut_stripping_force is given only for a nut that does not pair with the bolt: held by
    # tests/models/joint/test_nut_strength.py's hand calculation; the bending outputs only for
    # an eccentric joint: held by tests/models/joint/test_joint_eccentric.py's; the fitted
    # shank's only with fitted_diameter: held by test_joint_fitted.py's; the service
    # temperature's only with service_temperature: held by test_joint_temperature.py's
    eccentric = {
        "yield_strength_at_temperature",
        "bolt_modulus_ratio_at_temperature",
        "plate_modulus_ratio_at_temperature",
        "substitute_bending_inertia",
        "clamped_bending_compliance",
        "bolt_bending_compliance",
        "fitted_shear_stress",
        "fitted_shear_safety",
        "fitted_bearing_pressure",
    }
    numeric = {o.name for o in JOINT.outputs if not o.series} - {"nut_stripping_force", *eccentric}
    assert set(HAND) == numeric


@pytest.mark.parametrize("name", sorted(HAND))
def test_first_example_output_equals_the_hand_calculation(name):
    # the cone's fixed point converges to ~1e-12 here; everything else is closed form
    pin("joint.vdi2230", name, FIRST[name], HAND[name], rel=1e-9, abs=1e-18)


def test_first_example_magnitudes_a_reader_can_check():
    # a few of the numbers above in engineering units, to three figures
    assert HAND["permissible_preload"] == pytest.approx(43.11e3, rel=1e-3)
    assert HAND["tightening_torque"] == pytest.approx(83.6, rel=1e-3)
    assert HAND["assembly_preload_min"] == pytest.approx(23.21e3, rel=1e-3)
    assert HAND["endurance_limit"] == pytest.approx(48.875e6, rel=1e-9)


def test_torque_example_takes_its_preload_range_from_the_friction_box():
    # 80 N·m ± 5 %, M_ü 0.4 N·m, μ 0.08…0.16: R13 inverted at the friction corners
    got = run(JOINT, JOINT.examples[1]).results

    def per_newton(mu):
        return 0.16 * P + 0.58 * D2 * mu + mu * (DW + DH) / 4

    fm_min = (80 * 0.95 - 0.4) / per_newton(0.16)
    fm_max = (80 * 1.05 - 0.4) / per_newton(0.08)
    assert got["assembly_preload_min"] == pytest.approx(fm_min, rel=1e-12)
    assert got["assembly_preload_max"] == pytest.approx(fm_max, rel=1e-12)
    assert got["tightening_factor"] == pytest.approx(fm_max / fm_min, rel=1e-12)
    assert got["tightening_torque"] == 80.0  # the torque given
    # F_M,zul at μ_G,min = 0.08; F_S,max = F_M,max + Φ_n F_A with F_A = 10 kN
    assert got["permissible_preload"] == pytest.approx(0.9 * RP * AS / _torsion(DS, 0.08))
    assert got["max_bolt_force"] == pytest.approx(fm_max + got["load_factor"] * 10e3, rel=1e-12)
    assert got["fatigue_safety"] is None  # static load: F_A,min = F_A,max
    assert got["slip_safety"] is None  # no transverse load


def test_waisted_tapped_example_takes_the_shank_as_the_smallest_section():
    # 50 mm of d_T = 7.5 mm inside a 60 mm grip, socket head (0.4 d), nut thread in aluminium
    got = run(JOINT, JOINT.examples[2]).results
    a_t = math.pi / 4 * 0.0075**2
    assert got["smallest_diameter"] == 0.0075
    assert got["smallest_area"] == pytest.approx(a_t, rel=1e-12)
    assert got["bolt_compliance_shank"] == pytest.approx(0.050 / (E * a_t), rel=1e-12)
    assert got["bolt_compliance_free_thread"] == pytest.approx(0.010 / (E * AD3), rel=1e-12)
    assert got["bolt_compliance_head"] == pytest.approx(0.4 * D / (E * AN), rel=1e-12)
    # tapped (ESV): engaged thread 0.5 d in the bolt, 0.33 d of the aluminium's thread
    assert got["bolt_compliance_engaged"] == pytest.approx(
        0.5 * D / (E * AD3) + 0.33 * D / (7e10 * AN), rel=1e-12
    )
    # R7 at d_0 = d_T: F_M,zul = ν R_p0.2 A_T / β(d_0)
    assert got["permissible_preload"] == pytest.approx(0.9 * RP * a_t / _torsion(0.0075, 0.12))
    # 1 bearing face + 1 interface (tapped), axial load: 3 + 3 + 2 µm
    assert got["embedding_settlement"] == pytest.approx(8e-6, rel=1e-12)


def test_one_bolt_two_torques_under_two_named_conventions():
    # The M12 8.8 torque-wrench joint at μ = 0.10 (issue 28): joint.vdi2230 answers VDI 2230-1
    # R13's M_A for F_M,zul at μ_min, preload.control the torque for its nominal preload
    # F_nom = F_M,zul/(1 + 0.30) at that friction. Both are R13 on the same coefficients
    # k = 0.16 P + 0.58 d2 μ + μ (d_W + d_h)/4, at different preloads; their labels say which.
    mu = 0.10
    joint = run(
        JOINT,
        {**JOINT.examples[0], "thread_friction_min": mu, "bearing_friction_min": mu},
    ).results
    control = run(
        get_model("preload.control"),
        {
            "thread_diameter": D,
            "method": "torque_wrench",
            "thread_friction": mu,
            "bearing_friction": mu,
            "torque_formula": "vdi2230",
            "required_clamp_force": 10e3,
        },
    ).results
    k = 0.16 * P + 0.58 * D2 * mu + mu * (DW + DH) / 4
    f_mzul = 0.9 * RP * AS / _torsion(DS, mu)  # 44.19 kN, the same in both models
    assert joint["permissible_preload"] == pytest.approx(f_mzul, rel=1e-12)
    assert control["permissible_preload"] == pytest.approx(f_mzul, rel=1e-12)
    assert joint["tightening_torque"] == pytest.approx(f_mzul * k, rel=1e-12)  # 73.5 N·m
    assert joint["tightening_torque"] == pytest.approx(73.5, abs=0.05)
    f_nom = f_mzul / 1.3
    assert control["nominal_preload"] == pytest.approx(f_nom, rel=1e-12)
    assert control["target_torque"] == pytest.approx(f_nom * k, rel=1e-12)  # 56.5 N·m
    assert control["target_torque"] == pytest.approx(56.5, abs=0.05)
    # the labels name the convention of each, and each names the other
    labels = {o.name: o.description for o in JOINT.outputs}
    other = {o.name: o.description for o in get_model("preload.control").outputs}
    assert "F_M,zul at μ_G,min, μ_K,min" in labels["tightening_torque"]
    assert "R13" in labels["tightening_torque"]
    assert "nominal preload F_nom" in other["target_torque"]
    assert "given friction" in other["target_torque"]


def _checks(request):
    return {c.name: c.ok for c in run(JOINT, request).checks}


def test_r9_fatigue_check_turns_at_s_d_1_2():
    # S_D = σ_ASV / σ_a with σ_a = Φ_n F_A / (2 A_S) (F_A,min = 0): S_D = 1.2 at
    # F_A = σ_ASV · 2 A_S / (1.2 Φ_n); Φ_n does not depend on F_A
    f_a = HAND["endurance_limit"] * 2 * AS / (1.2 * HAND["load_factor"])
    below = {**JOINT.examples[0], "working_load": 0.99 * f_a}
    above = {**JOINT.examples[0], "working_load": 1.01 * f_a}
    assert run(JOINT, below).results["fatigue_safety"] == pytest.approx(1.2 / 0.99, rel=1e-9)
    assert _checks(below)["R9_fatigue"] is True
    assert _checks(above)["R9_fatigue"] is False


@pytest.mark.parametrize("ratio, ok", [(0.65, True), (0.72, False)])
def test_seed_004_rule_allows_0_7_sigma_t_with_an_accurate_method(ratio, ok):
    # strain gauge (±10 %): α_A = 1.1/0.9, tightened to F_M,zul = ν R_p A_S/β, so
    # F_M,nom = F_M,zul (1/α_A + 1)/2 = F_M,zul/1.1 and σ0/σ_T = ν/(1.1 β); choose ν for it
    nu = ratio * 1.1 * _torsion(DS, 0.12)
    request = {**JOINT.examples[0], "method": "strain_gauge", "utilization": nu}
    assert run(JOINT, request).results["preload_stress_ratio"] == pytest.approx(ratio, rel=1e-9)
    assert _checks(request)["seed_004_preload_stress"] is ok
