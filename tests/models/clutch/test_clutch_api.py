"""clutch.ball and clutch.ball_setting over HTTP: values, checks, refusals, sweeps, extremes."""

import itertools
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import engine
from engine.models.clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING
from tests.apps import real_client

DEG = math.pi / 180.0
PAPER = dict(BALL_CLUTCH.examples[0])


def post(path, body):
    return real_client(raise_server_exceptions=False).post("/api/v1/clutch/ball" + path, json=body)


def checks(body):
    return {c["name"]: c for c in body["checks"]}


def test_paper_case_with_display_units():
    body = {
        "ball_circle_diameter": "50 mm",
        "ball_count": 4,
        "ball_diameter": "10 mm",
        "groove_angle": "45 deg",
        "spring_wire_diameter": "4 mm",
        "spring_mean_diameter": "45 mm",
        "spring_active_coils": 5,
        "spring_deflection": "4 mm",
        "shear_modulus": "8e4 MPa",
    }
    r = post("", body)
    assert r.status_code == 200, r.text
    out = r.json()
    # see tests/models/clutch/test_clutch_functions.py for the arithmetic
    assert out["results"]["torque_limit"] == pytest.approx(0.56186557, rel=1e-7)
    assert out["results"]["spring_force"] == pytest.approx(22.4746228, rel=1e-7)
    assert out["units"]["torque_limit"] == "N*m"
    assert all(c["ok"] for c in out["checks"])
    assert any("spring_arrangement = common" in n for n in out["notes"])
    assert any("K_r in the denominator" in n for n in out["notes"])
    assert out["rung"] == "closed_form"


def test_per_ball_reproduces_papers_formula_and_says_so():
    out = post("", {**PAPER, "spring_arrangement": "per_ball"}).json()
    # K_r D0 i G d0⁴ Δ / (16 D³ i_p tan α) = 0.85·0.05·4·20.48·0.004/(16·9.1125e-5·5)
    assert out["results"]["torque_limit"] == pytest.approx(1.91034294, rel=1e-7)
    # the most-loaded ball's axial push equals its own spring's force [001, eq. 3]
    assert out["results"]["ball_axial_force"] == pytest.approx(
        out["results"]["spring_force"], rel=1e-12
    )
    assert any("spring_arrangement = per_ball" in n for n in out["notes"])


def test_ball_forces_at_a_given_torque_and_slip_check():
    out = post("", {**PAPER, "torque": 0.2}).json()["results"]
    # F_t = 2·0.2/(0.85·0.05·4) = 0.4/0.17 = 2.3529412 N; α = 45°: F_a = F_t, F_N = √2 F_t
    assert out["ball_tangential_force"] == pytest.approx(2.3529412, rel=1e-7)
    assert out["ball_axial_force"] == pytest.approx(2.3529412, rel=1e-7)
    assert out["ball_normal_force"] == pytest.approx(2.3529412 * math.sqrt(2), rel=1e-7)
    over = post("", {**PAPER, "torque": 0.6}).json()
    check = checks(over)["torque_below_limit"]
    assert not check["ok"] and "slips" in check["detail"]


def test_friction_raises_the_limit_and_is_reported():
    base = post("", PAPER).json()
    rough = post("", {**PAPER, "flank_friction": 0.1}).json()
    # tan 45° / tan(45° − atan 0.1) = 1 / 0.8181818 = 1.2222222
    ratio = rough["results"]["torque_limit"] / base["results"]["torque_limit"]
    assert ratio == pytest.approx(1.2222222, rel=1e-7)
    assert any("22.2%" in n for n in rough["notes"])
    # estimate: f = 0 assumed -> the 22 % a lubricated flank would add; f given -> ±0.03
    assert base["error_estimate"] == pytest.approx(0.2222222, rel=1e-6)
    assert 0.0 < rough["error_estimate"] < 0.1


def test_never_slips_is_a_plain_422():
    r = post("", {**PAPER, "groove_angle": 10 * DEG, "flank_friction": 0.3})
    assert r.status_code == 422
    (item,) = r.json()["detail"]
    assert item["type"] == "infeasible_design" and "never slips" in item["msg"]
    r = post("_setting", {**BALL_CLUTCH_SETTING.examples[0], "flank_friction": 1.0})
    assert r.status_code == 422 and r.json()["detail"][0]["type"] == "infeasible_design"


@pytest.mark.parametrize("angle", ["0 deg", "90 deg", "-5 deg", "95 deg"])
def test_groove_angle_refused_at_or_beyond_0_and_90(angle):
    r = post("", {**PAPER, "groove_angle": angle})
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "groove_angle"


def test_wire_thicker_than_coil_refused_naming_the_wire():
    r = post("", {**PAPER, "spring_wire_diameter": "45 mm"})
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "spring_wire_diameter"


def test_warnings_and_failing_checks():
    out = post(
        "",
        {
            **PAPER,
            "groove_angle": "15 deg",
            "load_factor": 0.7,
            "spring_wire_diameter": "2 mm",
            "spring_deflection": "7 mm",
            "allowable_shear_stress": "10 MPa",
        },
    ).json()
    assert any("groove_angle" in w for w in out["warnings"])
    assert any("load_factor" in w for w in out["warnings"])
    c = checks(out)
    assert not c["spring_index"]["ok"] and "22.5" in c["spring_index"]["detail"]
    assert not c["groove_depth"]["ok"] and "ball radius" in c["groove_depth"]["detail"]
    assert not c["groove_angle"]["ok"] and "< 20°" in c["groove_angle"]["detail"]
    # τ at F = 22.47 N · (2/4)⁴ · 7/4 = 2.458 N, d0 = 2 mm, D = 45 mm: ≈ 16 MPa > 10 MPa
    assert not c["spring_shear_stress"]["ok"]
    tight = checks(post("", {**PAPER, "spring_wire_diameter": "15 mm"}).json())
    assert not tight["spring_index"]["ok"] and "< 4" in tight["spring_index"]["detail"]


def test_setting_is_the_inverse_over_http():
    ex = BALL_CLUTCH_SETTING.examples[0]
    out = post("_setting", ex).json()
    res = out["results"]
    # F = 2 T tan 45° / D0 = 2·0.5/0.05 = 20 N; Δ = 20/5618.6557 = 3.5595703 mm;
    # d0 = (8·20·0.045³·5/(8e10·0.004))^¼ = (2.278125e-10)^¼ = 3.8850301 mm
    assert res["required_spring_force"] == pytest.approx(20.0, rel=1e-12)
    assert res["required_deflection"] == pytest.approx(3.5595703e-3, rel=1e-7)
    assert res["required_wire_diameter"] == pytest.approx(3.8850301e-3, rel=1e-7)
    for key, value in (("spring_deflection", res["required_deflection"]),):
        forward = post("", {**PAPER, key: value}).json()["results"]
        assert forward["torque_limit"] == pytest.approx(0.5, rel=1e-12)
    forward = post("", {**PAPER, "spring_wire_diameter": res["required_wire_diameter"]}).json()
    assert forward["results"]["torque_limit"] == pytest.approx(0.5, rel=1e-12)


def test_setting_needs_wire_or_deflection_and_gives_what_it_can():
    ex = dict(BALL_CLUTCH_SETTING.examples[0])
    only_wire = {k: v for k, v in ex.items() if k != "spring_deflection"}
    res = post("_setting", only_wire).json()["results"]
    assert "required_deflection" in res and "required_wire_diameter" not in res
    neither = {k: v for k, v in only_wire.items() if k != "spring_wire_diameter"}
    r = post("_setting", neither)
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "spring_wire_diameter"


def test_setting_flags_a_deflection_deeper_than_the_ball_radius():
    out = post("_setting", {**BALL_CLUTCH_SETTING.examples[0], "target_torque": 2.0}).json()
    # F = 80 N -> Δ = 80/5618.66 = 14.2 mm > d/2 = 5 mm (and > d)
    c = checks(out)["required_deflection_groove_depth"]
    assert not c["ok"] and "whole ball" in c["detail"]


@pytest.mark.parametrize("spec", [BALL_CLUTCH, BALL_CLUTCH_SETTING])
@pytest.mark.parametrize(
    "vary",
    [
        "spring_wire_diameter",
        "groove_angle",
        "flank_friction",
        "spring_deflection",
        "ball_count",
        "load_factor",
        "torque",
    ],
)
def test_vectorized_sweep_equals_single_runs(spec, vary):
    if vary not in {p.name for p in spec.inputs}:
        vary = "target_torque"
    base = dict(spec.examples[0])
    p = spec.param(vary)
    lo, hi = {
        "groove_angle": (5 * DEG, 85 * DEG),
        "flank_friction": (0.0, 0.9),
        "ball_count": (1, 9),
        "load_factor": (0.5, 1.0),
        "torque": (0.0, 2.0),
        "target_torque": (0.1, 2.0),
    }.get(vary, (0.5e-3, 4e-3))
    values = np.linspace(lo, hi, 9)
    fast = engine.sweep(spec, base, vary, values.tolist())
    names = list(fast.results)
    assert names, p.name
    for i, v in enumerate(values):
        try:
            one = engine.run(spec, {**base, vary: float(v)}).results
        except engine.EngineError:
            assert all(fast.results[n][i] is None for n in names)
            continue
        for n in names:
            if fast.results[n][i] is None:  # null in the sweep: absent from the single run
                assert one.get(n) is None, (n, v)
                continue
            assert fast.results[n][i] == pytest.approx(one[n], rel=1e-12), (n, v)


def test_sweep_across_the_friction_angle_nulls_the_locked_points():
    r = post(
        "/sweep",
        {
            "base": {**PAPER, "flank_friction": 0.3},
            "vary": "groove_angle",
            "start": "5 deg",
            "stop": "85 deg",
            "num": 17,
        },
    )
    assert r.status_code == 200, r.text
    body = r.json()
    torque = body["results"]["torque_limit"]
    locked = [v <= math.atan(0.3) for v in body["values"]]
    assert [t is None for t in torque] == locked and any(locked)
    free = [t for t in torque if t is not None]
    assert all(a > b for a, b in itertools.pairwise(free))


#: Outputs every helical run gives; the others (residual torque, buckling, materials,
#: disc springs) are null unless their inputs are given, and finite when not null.
FINITE_KEYS = [
    o.name
    for o in BALL_CLUTCH.outputs
    if not o.series
    and o.name
    not in {
        "residual_torque",
        "permissible_stress",
        "tensile_strength",
        "buckling_deflection",
        "natural_frequency",
        "disc_force_flat",
    }
]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    alpha=st.one_of(
        st.floats(1e-9, 1e-3),
        st.floats(math.pi / 2 - 1e-3, math.pi / 2 - 1e-9),
        st.floats(0.01, 1.5),
    ),
    wire=st.floats(1e-4, 0.02),
    mean=st.sampled_from([0.045, 0.1, 0.5]),
    f=st.sampled_from([0.0, 0.1, 1.0]),
    arr=st.sampled_from(["common", "per_ball"]),
    torque=st.one_of(st.none(), st.floats(0.0, 1e6)),
)
def test_extremes_never_nan_inf_or_500(alpha, wire, mean, f, arr, torque):
    body = {
        **PAPER,
        "groove_angle": alpha,
        "spring_wire_diameter": wire,
        "spring_mean_diameter": mean,
        "flank_friction": f,
        "spring_arrangement": arr,
        "allowable_shear_stress": 5e8,
    }
    if torque is not None:
        body["torque"] = torque
    r = post("", body)
    assert r.status_code in (200, 422), r.text
    assert "NaN" not in r.text and "Infinity" not in r.text
    if alpha <= math.atan(f):
        assert r.json()["detail"][0]["type"] == "infeasible_design"
        return
    assert r.status_code == 200, r.text
    res = r.json()["results"]
    for key in FINITE_KEYS:
        assert isinstance(res[key], float) and math.isfinite(res[key]), (key, res[key])
    for key, value in res.items():
        assert value is None or math.isfinite(value), (key, value)
    setting = post(
        "_setting",
        {
            **BALL_CLUTCH_SETTING.examples[0],
            "groove_angle": alpha,
            "spring_wire_diameter": wire,
            "spring_mean_diameter": mean,
            "flank_friction": f,
            "spring_arrangement": arr,
            "target_torque": min(max(res["torque_limit"], 1e-9), 1e6),
        },
    )
    assert setting.status_code == 200, setting.text
    assert "NaN" not in setting.text and "Infinity" not in setting.text


@pytest.mark.parametrize("vary", ["groove_angle", "spring_wire_diameter"])
def test_extreme_sweeps_are_finite(vary):
    start, stop = {"groove_angle": (1e-9, math.pi / 2 - 1e-9)}.get(vary, (1e-4, 0.02))
    r = post(
        "/sweep",
        {"base": PAPER, "vary": vary, "start": start, "stop": stop, "num": 200, "scale": "log"},
    )
    assert r.status_code == 200, r.text
    assert "NaN" not in r.text and "Infinity" not in r.text
    assert all(v is not None for v in r.json()["results"]["torque_limit"])
