"""The eccentric joint (VDI 2230-1 §5.3.2) in joint.vdi2230, worked by hand.

An M12 8.8 bolt 5 mm off the axis of a 30 × 50 mm flange section, two 20 mm steel plates
(D_A = 30 mm, so the cone stops inside the grip and a sleeve follows), F_A 0…8 kN at a = 20 mm,
the edge at u = 25 mm: every eccentric relation written out again below from VDI's own form
(I_V,Bers as (D_A − d_W) d_W³ D_A³/(D_A³ − d_W³), σ_SAb with its l_ers), no engine function.
With zero offsets the eccentric chain must give the concentric answers (to 1e-12).
"""

import math

import pytest

from engine import run, sweep
from engine.core.errors import InputOutOfRange
from engine.models import get_model
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
E = 2.1e11
D, P = 0.012, 0.00175
D2 = D - 0.649519 * P
D3 = D - 1.226869 * P
DS = 0.5 * (D2 + D3)
AS = math.pi / 4 * DS**2
AN, AD3 = math.pi / 4 * D**2, math.pi / 4 * D3**2
IN, I3 = math.pi / 64 * D**4, math.pi / 64 * D3**4
RP, DW, DH = 640e6, 0.01663, 0.0135

BASE = {
    "thread_diameter": D,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "outer_diameter": 0.030,
    "working_load": 8e3,
    "working_load_min": 0.0,
}
ECCENTRIC = {
    **BASE,
    "bolt_offset": 0.005,
    "load_lever": 0.020,
    "opening_edge": 0.025,
    "interface_length": 0.050,
    "interface_width": 0.030,
}


def by_hand():
    grip, n, f_a, s, a, u, c_t, b = 0.040, 0.5, 8e3, 0.005, 0.020, 0.025, 0.050, 0.030
    da = 0.030
    # R3 bolt: hexagon head 0.5 d, all free thread, engaged 0.5 d, nut 0.4 d
    delta_s = (0.5 * D / AN + grip / AD3 + 0.5 * D / AD3 + 0.4 * D / AN) / E
    # R3 plates: cone fit at y = D_A/d_W, D_A < D_A,Gr: cone to D_A, then a sleeve (w = 1)
    tan = 0.362 + 0.032 * math.log(grip / DW / 2) + 0.153 * math.log(da / DW)
    assert da < DW + grip * tan
    cone = 2 / (DH * tan) * math.log((DW + DH) * (da - DH) / ((DW - DH) * (da + DH)))
    sleeve = 4 / (da**2 - DH**2) * (grip - (da - DW) / tan)
    delta_p = (cone + sleeve) / (E * math.pi)
    # §5.3.2 substitute inertia: cone (Steiner to O–O) and sleeve b c_T³/12 in series
    i_v = 0.147 * (da - DW) * DW**3 * da**3 / (da**3 - DW**3)
    i_ve = i_v + s**2 * math.pi / 4 * da**2
    i_h = b * c_t**3 / 12
    l_v = (da - DW) / (2 * tan)
    l_h = grip - 2 * l_v
    i_bers = grip / (2 * l_v / i_ve + l_h / i_h)
    beta_p = grip / (E * i_bers)
    d1 = delta_p + s * s * beta_p  # δ*_P
    d2 = delta_p + s * a * beta_p  # δ**_P
    phi = n * d2 / (delta_s + d1)
    # R2 opening: A_D = b c_T − hole, I_BT = b c_T³/12
    a_d = b * c_t - math.pi / 4 * DH**2
    k = (a - s) * u / (i_h / a_d + s * u)
    f_ka = k * f_a
    # R4 embedding, Rz 10–40 axial: 3 + 2 × 3 + 1 × 2 µm, over δ_S + δ*_P
    f_z = 11e-6 / (delta_s + d1)
    # R7, R1: F_M,zul at μ_G = 0.12, ν = 0.9; torque wrench α_A = 1.3/0.7
    beta = math.sqrt(
        1 + 3 * (1.5 * D2 / DS * (P / (math.pi * D2) + 0.12 / math.cos(math.pi / 6))) ** 2
    )
    fm_min = 0.9 * RP * AS / beta / (1.3 / 0.7)
    # §5.3.2 opening limit at F_M,min: F_V − (1 − Φ*_en) F_A = k F_A
    f_aab = (fm_min - f_z) / ((1 - phi) + k)
    # R9: σ_SAb in VDI's form, l_ers = β_S E_S π d_S⁴/64
    beta_s = (0.5 * D / IN + grip / I3 + 0.5 * D / I3 + 0.4 * D / IN) / E
    l_ers = beta_s * E * math.pi * DS**4 / 64
    bend = (1 / phi - s / a) * (grip / l_ers) * (E / E) * math.pi * a * DS**3 / (8 * i_bers)
    sigma_sab = (1 + bend) * phi * f_a / AS
    return {
        "substitute_bending_inertia": i_bers,
        "clamped_bending_compliance": beta_p,
        "bolt_bending_compliance": beta_s,
        "clamped_compliance": delta_p,
        "eccentric_clamped_compliance": d1,
        "load_factor": phi,
        "load_factor_k": phi / n,
        "opening_clamp_force": f_ka,
        "required_clamp_force": f_ka,
        "embedding_loss": f_z,
        "separation_load": f_aab,
        "additional_bolt_stress": sigma_sab,
        "stress_amplitude": sigma_sab / 2,  # F_A,min = 0: (σ_SAbo − 0)/2
        "residual_clamp_force_min": fm_min - (1 - phi) * f_a - f_z,
    }


HAND = by_hand()
GOT = run(JOINT, ECCENTRIC)


@pytest.mark.parametrize("name", sorted(HAND))
def test_eccentric_outputs_equal_the_hand_calculation(name):
    pin("joint.vdi2230", name, GOT.results[name], HAND[name], rel=1e-9)


def test_eccentric_magnitudes_and_checks():
    # the bending raises Φ and the thread's stress; F_KA sets F_K,erf; the interface stays closed
    concentric = run(JOINT, BASE).results
    assert GOT.results["load_factor"] > concentric["load_factor"]
    assert GOT.results["additional_bolt_stress"] > 2 * concentric["additional_bolt_stress"]
    assert GOT.results["separation_load"] < concentric["separation_load"]
    checks = {c.name: c for c in GOT.checks}
    assert HAND["separation_load"] > 8e3  # F_Aab ≈ 10.8 kN: closed at F_A = 8 kN
    assert checks["opening_limit"].ok is True
    opened = run(JOINT, {**ECCENTRIC, "working_load": 12e3})
    assert {c.name: c.ok for c in opened.checks}["opening_limit"] is False
    assert "F_Aab" in checks["opening_limit"].detail
    assert "opening_limit" not in {c.name for c in run(JOINT, BASE).checks}


def test_zero_offsets_give_the_concentric_answers():
    # the interface given but s_sym = a = u = 0: every shared output as the concentric run
    concentric = run(JOINT, BASE).results
    zero = run(JOINT, {**ECCENTRIC, "bolt_offset": 0.0, "load_lever": 0.0, "opening_edge": 0.0})
    shared = set(concentric) & set(zero.results)
    assert len(shared) >= 45
    for name in shared:
        want, got = concentric[name], zero.results[name]
        if want is None:
            assert got is None, name
        else:
            assert got == pytest.approx(want, rel=1e-12, abs=1e-300), name
    # the bending outputs exist only with an interface
    assert "substitute_bending_inertia" not in concentric
    assert zero.results["substitute_bending_inertia"] > 0


def test_offsets_need_the_interface_and_stay_inside_it():
    for name in ("bolt_offset", "load_lever", "opening_edge"):
        with pytest.raises(InputOutOfRange) as err:
            run(JOINT, {**BASE, name: 0.01})
        assert err.value.field == "interface_length"
        assert "interface_length" in str(err.value)
    # the hole inside the interface: |s_sym| ≤ (c_T − d_h)/2 = 18.25 mm
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**ECCENTRIC, "bolt_offset": 0.0183})
    assert err.value.field == "bolt_offset" and "18.25 mm" in str(err.value)
    # the interface wider than the hole
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**ECCENTRIC, "interface_width": 0.013})
    assert err.value.field == "interface_width"
    # the bolt outside the kern away from the load: I_BT/A_D + s_sym u ≤ 0 (c_T²/12 ≈ 2.1e-4,
    # −0.018 × 0.025 = −4.5e-4)
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**ECCENTRIC, "bolt_offset": -0.018})
    assert err.value.field == "bolt_offset" and "kern" in str(err.value)
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**ECCENTRIC, "opening_edge": 0.026})
    assert err.value.field == "opening_edge"


def test_a_sweep_over_the_bolt_offset_runs_the_same_lines():
    offsets = [-0.005, 0.0, 0.005, 0.015]
    many = sweep(JOINT, ECCENTRIC, "bolt_offset", offsets)
    for i, s in enumerate(offsets):
        one = run(JOINT, {**ECCENTRIC, "bolt_offset": s}).results
        for name in ("load_factor", "separation_load", "additional_bolt_stress"):
            got = float(many.columns[name][i])
            assert got == pytest.approx(one[name], rel=1e-12), (name, s)
