"""joint.vdi2230 and its physics: limits, hand checks, the three questions of issue 14, refusals.

Hand checks use the closed forms of VDI 2230-1 R3 (cone/sleeve) and R7/R13 (preload and torque)
written out independently here; the published numbers are in tests/validation/.
"""

import math

import pytest

from engine import run
from engine.core.errors import InputOutOfRange
from engine.core.runner import sweep, sweep_values
from engine.models import get_model
from engine.physics import joint as jt

JOINT = get_model("joint.vdi2230")
CONTROL = get_model("preload.control")
TIGHTENING = get_model("preload.tightening")
PATH = "/api/v1/joint/vdi2230"

M12_2X20 = {"thread_diameter": 0.012, "plate1_thickness": 0.020, "plate2_thickness": 0.020}
DW, DH = 0.01663, 0.0135  # ISO 4017 d_w,min and ISO 273 medium hole of M12
D2 = 0.012 - 0.649519 * 0.00175  # ISO 68-1 pitch diameter of M12


def _vdi_cone(grip, e, dw, dh, da, w):
    """VDI 2230-1 R3 closed forms for one material (w = 1 through, 2 tapped)."""
    beta, y = grip / dw, da / dw
    if w == 1:
        tan = 0.362 + 0.032 * math.log(beta / 2) + 0.153 * math.log(y)
    else:
        tan = 0.348 + 0.013 * math.log(beta) + 0.193 * math.log(y)
    limit = dw + w * grip * tan
    if da >= limit:
        arg = (dw + dh) * (limit - dh) / ((dw - dh) * (limit + dh))
        return 2 * math.log(arg) / (w * e * math.pi * dh * tan)
    arg = (dw + dh) * (da - dh) / ((dw - dh) * (da + dh))
    cone = 2 / (w * dh * tan) * math.log(arg)
    sleeve = 4 / (da**2 - dh**2) * (grip - (da - dw) / (w * tan))
    return (cone + sleeve) / (e * math.pi)


# ----------------------------------------------------------------- compliance physics


@pytest.mark.parametrize("joint", ["through", "tapped"])
@pytest.mark.parametrize("da", [0.020, 0.030, 0.045, 0.080, 0.300])
@pytest.mark.parametrize("grip", [0.004, 0.040, 0.150])
def test_cone_matches_vdi_closed_forms(joint, da, grip):
    w = 1 if joint == "through" else 2
    c = jt.clamped_compliance([grip], [2.1e11], DW, DH, da, joint)
    assert c.total == pytest.approx(_vdi_cone(grip, 2.1e11, DW, DH, da, w), rel=1e-10)


@pytest.mark.parametrize("joint", ["through", "tapped"])
@pytest.mark.parametrize("da", [None, 0.025, 0.2])
def test_one_plate_equals_two_half_plates(joint, da):
    one = jt.clamped_compliance([0.04], [7e10], DW, DH, da, joint).total
    two = jt.clamped_compliance([0.02, 0.02], [7e10, 7e10], DW, DH, da, joint).total
    three = jt.clamped_compliance([0.01, 0.025, 0.005], [7e10] * 3, DW, DH, da, joint).total
    assert two == pytest.approx(one, rel=1e-12)
    assert three == pytest.approx(one, rel=1e-12)


def test_outer_diameter_at_the_bearing_gives_the_sleeve():
    grip, e = 0.03, 2.1e11
    sleeve = 4 * grip / (e * math.pi * (DW**2 - DH**2))
    assert jt.clamped_compliance([grip], [e], DW, DH, DW).total == pytest.approx(sleeve, rel=1e-12)
    near = jt.clamped_compliance([grip], [e], DW, DH, DW * (1 + 1e-9)).total
    assert near == pytest.approx(sleeve, rel=1e-6)


def test_a_plate_of_double_stiffness_halves_its_share():
    soft = jt.clamped_compliance([0.01, 0.03], [7e10, 2.1e11], DW, DH, None)
    stiff = jt.clamped_compliance([0.01, 0.03], [1.4e11, 2.1e11], DW, DH, None)
    assert stiff.per_plate[0] == pytest.approx(soft.per_plate[0] / 2, rel=1e-12)
    assert stiff.per_plate[1] == pytest.approx(soft.per_plate[1], rel=1e-12)


def test_wider_plates_are_stiffer_and_the_unlimited_default_is_the_full_cone():
    c = jt.clamped_compliance([0.04], [2.1e11], DW, DH, None)
    assert c.outer_diameter == pytest.approx(c.limit_diameter, rel=1e-9)
    values = [
        jt.clamped_compliance([0.04], [2.1e11], DW, DH, da).total for da in (0.02, 0.03, 0.05)
    ]
    assert values[0] > values[1] > values[2]


def test_bolt_compliance_hand_check_with_waist():
    # M12 8.8, hex head, 10 mm shank d = 12, 25 mm waist d_T = 9, 5 mm free thread, nut
    e, d, d3 = 2.1e11, 0.012, 0.012 - 1.226869 * 0.00175
    a_n, a_3, a_t = math.pi / 4 * d**2, math.pi / 4 * d3**2, math.pi / 4 * 0.009**2
    hand = (
        0.5 * d / a_n + 0.010 / a_n + 0.025 / a_t + 0.005 / a_3 + 0.5 * d / a_3 + 0.4 * d / a_n
    ) / e
    c = jt.bolt_compliance(d, d3, e, [(0.010, d), (0.025, 0.009)], 0.005)
    assert c.total == pytest.approx(hand, rel=1e-12)
    socket = jt.bolt_compliance(d, d3, e, [], 0.04, head="socket", joint="tapped")
    plain = jt.bolt_compliance(d, d3, e, [], 0.04)
    assert plain.total - socket.total == pytest.approx((0.1 + 0.07) * d / (e * a_n), rel=1e-9)


def test_load_factor_vanishes_for_a_very_stiff_joint():
    bolt = jt.bolt_compliance(0.012, 0.009853, 2.1e11, [], 0.04).total
    phis = []
    for e in (2.1e11, 2.1e13, 2.1e15):
        parts = jt.clamped_compliance([0.04], [e], DW, DH, None).total
        phis.append(jt.load_factor(bolt, parts, 1.0))
    assert phis[0] > phis[1] > phis[2]
    assert phis[2] < 3e-5
    assert phis[1] / phis[2] == pytest.approx(100, rel=0.01)  # Φ ∝ δ_P once δ_P ≪ δ_S


def test_embedding_table_rows():
    assert jt.embedding("Rz<10", "axial", 2, 1) == pytest.approx(9.5e-6)
    assert jt.embedding("Rz10-40", "transverse", 1, 2) == pytest.approx((3 + 4.5 + 5) * 1e-6)
    assert jt.embedding("Rz40-160", "axial", 2, 0) == pytest.approx(11e-6)
    with pytest.raises(InputOutOfRange):
        jt.embedding("Rz<1", "axial", 2, 0)


def test_thermal_loss_signs_and_modulus_term():
    # equal expansion, same E: nothing changes
    assert jt.thermal_preload_loss(3e4, 0.04, 1.15e-5, 80, 0.04 * 1.15e-5, 80, 3e-9, 1e-9) == 0.0
    # steel bolt in aluminium heated: the plates grow more, the preload rises
    gain = jt.thermal_preload_loss(3e4, 0.04, 1.15e-5, 80, 0.04 * 2.3e-5, 80, 3e-9, 1e-9)
    assert gain == pytest.approx(-0.04 * 1.15e-5 * 80 / 4e-9, rel=1e-12)
    # E drops 10 % in bolt and plates alike: F_V (1 − 1/1.111) = F_V/10 lost
    soft = jt.thermal_preload_loss(3e4, 0.04, 0.0, 0, 0.0, 0, 3e-9, 1e-9, 0.9, 0.9)
    assert soft == pytest.approx(3e3, rel=1e-12)


def test_torque_window_corners():
    lo, hi = jt.preload_bounds_from_torque(100.0, 0.1, 5.0, 1e-3, 2e-3, prevailing_torque_min=1.0)
    assert lo == pytest.approx((90 - 5) / 2e-3)
    assert hi == pytest.approx((110 - 1) / 1e-3)
    assert jt.preload_bounds_from_torque(1.0, 0.5, 2.0, 1e-3, 2e-3)[0] == 0.0


# ----------------------------------------------------------------- the model


def test_working_load_zero_reproduces_todays_preload_results_exactly():
    for d, cls, mu in ((0.008, "8.8", 0.10), (0.012, "8.8", 0.12), (0.020, "10.9", 0.14)):
        t = run(
            TIGHTENING,
            {
                "thread_diameter": d,
                "property_class": cls,
                "thread_friction": mu,
                "bearing_friction": mu,
            },
        ).results
        j = run(
            JOINT,
            {
                "thread_diameter": d,
                "property_class": cls,
                "plate1_thickness": 3 * d,
                "thread_friction_min": mu,
                "bearing_friction_min": mu,
            },
        ).results
        assert j["permissible_preload"] == t["permissible_preload"]
        assert j["tightening_torque"] == t["tightening_torque"]
        assert j["additional_bolt_load"] == 0.0


def test_waisted_m12_permissible_preload_at_the_waist():
    r = run(JOINT, {**M12_2X20, "reduced_length": 0.030, "reduced_diameter": 0.0075})
    # VDI R7 at A_0 = π 7.5²/4 = 44.18 mm²: hand value 20.70 kN (issue 14)
    a0 = math.pi / 4 * 0.0075**2
    ratio = 1.5 * (D2 / 0.0075) * (0.00175 / (math.pi * D2) + 0.12 / math.cos(math.pi / 6))
    hand = 0.9 * 640e6 * a0 / math.sqrt(1 + 3 * ratio**2)
    assert r.results["permissible_preload"] == pytest.approx(hand, rel=1e-6)
    assert r.results["permissible_preload"] == pytest.approx(20.70e3, abs=10)
    assert r.results["smallest_diameter"] == 0.0075


def test_preload_control_waisted_shank_is_honest():
    base = {"thread_diameter": 0.012, "required_clamp_force": 5e3}
    plain = run(CONTROL, base).results
    waisted = run(CONTROL, {**base, "reduced_length": 0.05, "reduced_diameter": 0.0075})
    assert plain["permissible_preload"] == pytest.approx(43.11e3, abs=10)
    assert waisted.results["permissible_preload"] == pytest.approx(20.70e3, abs=10)
    # max_below_yield now compares with the waist's yield preload: σ_red at the waist ≤ R_p0.2
    assert waisted.results["max_below_yield"] is True
    assert waisted.results["preload_max"] <= waisted.results["yield_preload"]
    assert any("smallest section is the shank" in n for n in waisted.notes)


def test_preload_control_angle_uses_the_cone_by_default():
    x = {
        "thread_diameter": 0.012,
        "required_clamp_force": 5e3,
        "method": "nut_angle",
        "clamped_length": 0.04,
    }
    cone = run(CONTROL, x).results
    rigid = run(CONTROL, {**x, "clamped_compliance": 0.0}).results
    typed = run(CONTROL, {**x, "clamped_compliance": 1e-9}).results
    lam_p = jt.clamped_compliance([0.04], [2.1e11], DW, DH, None).total
    assert cone["clamped_compliance"] == pytest.approx(lam_p, rel=1e-12)
    ratio = cone["target_angle"] / rigid["target_angle"]
    assert ratio == pytest.approx(1 + lam_p / cone["bolt_compliance"], rel=1e-12)
    assert 1.2 < ratio < 1.3  # the rigid default was 20 % low for M12 through 2 × 20 mm steel
    assert typed["clamped_compliance"] == 1e-9


def test_the_80_nm_question():
    r = run(
        JOINT,
        {
            **M12_2X20,
            "tightening_torque": 80.0,
            "torque_tolerance": 0.05,
            "prevailing_torque": 0.4,
            "thread_friction_min": 0.08,
            "thread_friction_max": 0.16,
            "bearing_friction_min": 0.08,
            "bearing_friction_max": 0.16,
            "working_load": 10e3,
        },
    )
    res = r.results

    def k(mu):  # VDI R13 torque per newton, D_Km = (16.63 + 13.5)/2 mm
        return 0.16 * 0.00175 + 0.58 * D2 * mu + mu * (DW + DH) / 4

    assert res["assembly_preload_min"] == pytest.approx((76 - 0.4) / k(0.16), rel=1e-12)
    assert res["assembly_preload_max"] == pytest.approx((84 - 0.4) / k(0.08), rel=1e-12)
    assert res["assembly_preload_min"] == pytest.approx(30.32e3, abs=10)
    assert res["assembly_preload_max"] == pytest.approx(60.29e3, abs=10)
    checks = {c.name: c for c in r.checks}
    assert checks["residual_clamp_force"].ok
    assert not checks["R7_max_below_permissible"].ok  # μ 0.08 at 84 N·m over-stretches an 8.8


def test_a_working_load_that_separates_at_any_preload_is_a_failing_check_with_its_number():
    r = run(JOINT, {**M12_2X20, "working_load": 80e3})
    checks = {c.name: c for c in r.checks}
    assert not checks["separation_avoidable"].ok
    limit = (r.results["permissible_preload"] - r.results["embedding_loss"]) / (
        1 - r.results["load_factor"]
    )
    assert f"{limit / 1e3:.4g} kN" in checks["separation_avoidable"].detail
    assert not checks["R7_window_fits"].ok
    assert f"{r.results['max_working_load'] / 1e3:.4g} kN" in checks["R7_window_fits"].detail
    # the joint opens: no clamp force is left (0, not the linear diagram's negative value),
    # the check fails on F_M,min − (1 − Φ_n) F_A − F_Z < 0 and a warning says so
    raw = (
        r.results["assembly_preload_min"]
        - (1 - r.results["load_factor"]) * 80e3
        - r.results["embedding_loss"]
    )
    assert raw < 0 and r.results["residual_clamp_force_min"] == 0.0
    assert not checks["residual_clamp_force"].ok
    assert f"{raw / 1e3:.4g} kN" in checks["residual_clamp_force"].detail
    assert any("the joint opens" in w for w in r.warnings)


def test_required_window_is_vdi_r5_r6():
    r = run(
        JOINT,
        {**M12_2X20, "working_load": 5e3, "transverse_load": 1.5e3, "interface_friction": 0.15},
    )
    res = r.results
    f_kq = 1.5e3 / 0.15
    assert res["required_clamp_force"] == pytest.approx(f_kq)
    req = f_kq + (1 - res["load_factor"]) * 5e3 + res["embedding_loss"]
    assert res["required_preload_min"] == pytest.approx(req, rel=1e-12)
    assert res["required_preload_max"] == pytest.approx(res["tightening_factor"] * req, rel=1e-12)
    # embedding: transverse load, two bearing faces, one interface, Rz 10-40: 3 + 2·4.5 + 2.5 µm
    assert res["embedding_settlement"] == pytest.approx(14.5e-6)


def test_joint_diagram_lines_cross_at_the_preload():
    r = run(JOINT, {**M12_2X20, "working_load": 5e3}, series=True)
    s, res = r.series, r.results
    x = s["diagram_deformation"]
    f_sm = res["assembly_preload_min"] * res["bolt_compliance"]
    assert x[-1] == pytest.approx(
        res["assembly_preload_min"] * (res["bolt_compliance"] + res["clamped_compliance"])
    )
    assert s["diagram_bolt_line"][-1] >= s["diagram_preload_level"][0]
    assert s["diagram_clamped_line"][-1] == 0.0
    i = min(range(len(x)), key=lambda j: abs(x[j] - f_sm))
    slope = 1 / res["bolt_compliance"]
    assert s["diagram_bolt_line"][i] == pytest.approx(x[i] * slope, rel=1e-12)
    level = s["diagram_working_bolt_force_level"][0] - s["diagram_residual_clamp_level"][0]
    assert level == pytest.approx(5e3, rel=1e-9)  # F_A between the two levels
    assert len(s["window_required_min"]) == len(s["window_working_load"])


@pytest.mark.parametrize(
    ("extra", "field"),
    [
        ({"outer_diameter": 0.0135}, "outer_diameter"),  # D_A = d_h: no wall left
        ({"plate1_thickness": -0.01}, "plate1_thickness"),
        ({"plate2_thickness": -0.01}, "plate2_thickness"),
        ({"shank_length": 0.05}, "shank_length"),
        ({"reduced_length": 0.01}, "reduced_diameter"),
        ({"working_load": 1e3, "working_load_min": 2e3}, "working_load_min"),
        ({"thread_friction_min": 0.14, "thread_friction_max": 0.1}, "thread_friction_max"),
        ({"prevailing_torque": 0.1, "prevailing_torque_min": 0.2}, "prevailing_torque_min"),
        ({"shank_diameter": 0.013, "shank_length": 0.01}, "shank_diameter"),
    ],
)
def test_bad_input_is_a_422_naming_the_field(client, extra, field):
    resp = client.post(PATH, json={**M12_2X20, **extra})
    assert resp.status_code == 422, resp.text
    assert resp.json()["detail"][0]["field"] == field


def test_every_example_answers_over_http_with_checks(client):
    for example in JOINT.examples:
        body = client.post(PATH, json={**example, "series": True}).json()
        assert body["results"]["permissible_preload"] > 0
        assert body["series"]["diagram_bolt_line"]
        for name, out in ((o.name, o) for o in JOINT.outputs if not o.series):
            assert out.description.split(":")[0].strip().startswith(("R", "[004")), name


@pytest.mark.parametrize(
    ("vary", "start", "stop"),
    [("plate1_thickness", 1e-4, 0.5), ("working_load", 0.0, 2e5), ("outer_diameter", DW, 0.5)],
)
def test_sweeps_have_no_refused_point(vary, start, stop):
    points = sweep_values(start, stop, 60)
    out = sweep(JOINT, M12_2X20, vary, points, outputs=["load_factor", "residual_clamp_force_min"])
    for name in ("load_factor", "residual_clamp_force_min"):
        assert all(v is not None and math.isfinite(v) for v in out.results[name]), name
