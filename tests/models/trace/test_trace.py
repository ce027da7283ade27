"""trace.analysis and trace.program against hand calculations written out here.

The joint is the issue's M12 8.8 through 2 × 20 mm steel, μ_G = μ_K = 0.08…0.16. Its bolt
data are ISO 261/898-1's (d2 = 10.863 mm, d0 = 10.358 mm, A_s = 84.27 mm², R_p0.2 = 640 MPa)
and its head's (d_W = 16.63 mm, d_h = 13.5 mm); its compliances δ_S, δ_P and window are the
joint model's outputs for the same inputs (held by the joint's own tests).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import engine
from engine.models.trace import M12_JOINT
from tests.pins import pin

A = "trace.analysis"
PROG = "trace.program"
DEG = math.pi / 180.0
P, D2, D0 = 1.75e-3, 10.86334175e-3, 10.3581605e-3
DW, DH, AS, RP = 16.63e-3, 13.5e-3, 84.26653836e-6, 640e6
JOINT: dict[str, Any] = dict(engine.run(engine.get_model("joint.vdi2230"), dict(M12_JOINT)).results)
DS, DP = float(JOINT["bolt_compliance"]), float(JOINT["clamped_compliance"])
DELTA = DS + DP


def run(model: str, inputs: dict[str, Any]) -> dict[str, Any]:
    """The model's scalar results (typed for arithmetic in the tests)."""
    return dict(engine.run(engine.get_model(model), inputs).results)


def k_of(mu_g: float, mu_k: float) -> float:
    """VDI 2230-1 R13 per newton: 0.16 P + 0.58 d2 μ_G + μ_K (d_W + d_h)/4."""
    return 0.16 * P + 0.58 * D2 * mu_g + mu_k * (DW + DH) / 4


def mu_g_of(k: float, split: float = 1.0) -> float:
    """R13 solved for μ_G with μ_K = split · μ_G."""
    return (k - 0.16 * P) / (0.58 * D2 + split * (DW + DH) / 4)


def yield_preload(mu_g: float) -> float:
    """R_p0.2 A_s / β, β = √(1 + 3 (1.5 d2/d0 (P/(π d2) + μ_G/cos 30°))²) (VDI 2230-1 R7)."""
    ratio = 1.5 * D2 / D0 * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30.0)))
    return RP * AS / math.sqrt(1.0 + 3.0 * ratio**2)


def rate_of(k: float, delta: float = DELTA) -> float:
    """dT/dθ = k P / (2π δ), [N·m/rad]."""
    return k * P / (2.0 * math.pi * delta)


def test_the_issue_m12_numbers_from_the_joint() -> None:
    """The issue's M12: 1.68–3.02 N·m/°, 69.6–113 N·m to yield, 37–41° snug to yield."""
    r = run(A, {**M12_JOINT, **_bilinear(0.10)})
    pin("trace.analysis", "predicted_rate_min", r["predicted_rate_min"], 1.68 / DEG, rel=0.003)
    pin("trace.analysis", "predicted_rate_max", r["predicted_rate_max"], 3.02 / DEG, rel=0.002)
    pin(
        "trace.analysis",
        "predicted_yield_torque_min",
        r["predicted_yield_torque_min"],
        69.6,
        rel=0.001,
    )
    pin(
        "trace.analysis",
        "predicted_yield_torque_max",
        r["predicted_yield_torque_max"],
        113.0,
        rel=0.001,
    )
    pin(
        "trace.analysis",
        "predicted_snug_to_yield_min",
        r["predicted_snug_to_yield_min"],
        37.4 * DEG,
        rel=0.002,
    )
    pin(
        "trace.analysis",
        "predicted_snug_to_yield_max",
        r["predicted_snug_to_yield_max"],
        41.4 * DEG,
        rel=0.002,
    )
    # and the same from the relations written out here
    assert r["predicted_rate_min"] == pytest.approx(rate_of(k_of(0.08, 0.08)), rel=1e-9)
    assert r["predicted_rate_max"] == pytest.approx(rate_of(k_of(0.16, 0.16)), rel=1e-9)
    assert r["predicted_yield_torque_min"] == pytest.approx(
        k_of(0.08, 0.08) * yield_preload(0.08), rel=1e-9
    )
    assert r["predicted_snug_to_yield_max"] == pytest.approx(
        2 * math.pi * yield_preload(0.08) * DELTA / P, rel=1e-9
    )


# a bilinear trace: 0 up to θ0, the elastic line of μ to T_top, then 2 % of the rate (a
# bolt that yields) to 70°
THETA0, STEP_DEG, END, PLASTIC = 20.0 * DEG, 0.1, 70.0 * DEG, 0.02


def _bilinear(mu: float, top: float = 75.0) -> dict[str, list[float]]:
    rate = rate_of(k_of(mu, mu))
    theta = np.arange(0.0, 70.0 + 1e-9, STEP_DEG) * DEG
    elastic = rate * np.maximum(theta - THETA0, 0.0)
    torque = np.minimum(elastic, top) + PLASTIC * np.maximum(elastic - top, 0.0)
    return {"angle": theta.tolist(), "torque": torque.tolist()}


def test_a_bilinear_trace_read_against_the_joint() -> None:
    mu, top = 0.10, 60.0
    k = k_of(mu, mu)
    rate = rate_of(k)
    knee = THETA0 + top / rate
    one = STEP_DEG * DEG  # one sample
    final = top + PLASTIC * rate * (END - knee)  # the peak, at the end
    r = engine.run(engine.get_model(A), {**M12_JOINT, **_bilinear(mu, top)})
    v: dict[str, Any] = dict(r.results)
    pin("trace.analysis", "steps_found", v["steps_found"], 1)
    pin("trace.analysis", "step_analysed", v["step_analysed"], 1)
    pin("trace.analysis", "elastic_rate", v["elastic_rate"], rate, rel=1e-9)
    pin("trace.analysis", "zero_preload_angle", v["zero_preload_angle"], THETA0, abs=1e-9)
    pin("trace.analysis", "snug_angle", v["snug_angle"], THETA0, abs=one)
    pin("trace.analysis", "snug_torque", v["snug_torque"], 0.0, abs=rate * one)
    pin(
        "trace.analysis",
        "elastic_window_start",
        v["elastic_window_start"],
        THETA0 + 0.3 * final / rate,
        abs=one,
    )
    pin(
        "trace.analysis",
        "elastic_window_end",
        v["elastic_window_end"],
        THETA0 + 0.7 * final / rate,
        abs=one,
    )
    # the gradient over the window halves at the knee (from R to 0.02 R): one sample past it
    pin("trace.analysis", "yield_angle", v["yield_angle"], knee, abs=2 * one)
    pin("trace.analysis", "yield_torque", v["yield_torque"], top, abs=rate * one)
    pin("trace.analysis", "snug_to_yield_angle", v["snug_to_yield_angle"], top / rate, abs=2 * one)
    pin("trace.analysis", "final_angle", v["final_angle"], END, abs=1e-12)
    pin("trace.analysis", "final_torque", v["final_torque"], final, rel=1e-9)
    pin("trace.analysis", "torque_per_preload", v["torque_per_preload"], k, rel=1e-9)
    pin("trace.analysis", "total_friction", v["total_friction"], mu, rel=1e-9)
    lo, hi = DS * 0.95 + DP * 0.8, DS * 1.05 + DP * 1.2  # δ_S ± 5 %, δ_P ± 20 %
    k_lo, k_hi = k * lo / DELTA, k * hi / DELTA
    pin("trace.analysis", "total_friction_min", v["total_friction_min"], mu_g_of(k_lo), rel=1e-9)
    pin("trace.analysis", "total_friction_max", v["total_friction_max"], mu_g_of(k_hi), rel=1e-9)
    pin(
        "trace.analysis",
        "thread_friction_low",
        v["thread_friction_low"],
        mu_g_of(k_lo, 2.0),
        rel=1e-9,
    )
    pin(
        "trace.analysis",
        "thread_friction_high",
        v["thread_friction_high"],
        mu_g_of(k_hi, 0.5),
        rel=1e-9,
    )
    pin("trace.analysis", "preload", v["preload"], final / k, rel=1e-9)
    pin("trace.analysis", "preload_min", v["preload_min"], final / k_hi, rel=1e-9)
    pin("trace.analysis", "preload_max", v["preload_max"], final / k_lo, rel=1e-9)
    pin(
        "trace.analysis",
        "yield_preload_min",
        v["yield_preload_min"],
        yield_preload(mu_g_of(k_hi, 0.5)),
        rel=1e-9,
    )
    pin(
        "trace.analysis",
        "assembly_preload_min",
        v["assembly_preload_min"],
        JOINT["assembly_preload_min"],
    )
    pin(
        "trace.analysis",
        "permissible_preload",
        v["permissible_preload"],
        JOINT["permissible_preload"],
    )
    assert v["yield_detected"] is True and v["preload_in_window"] is True
    checks = {c.name: c.ok for c in r.checks}
    assert checks == {
        "preload_above_minimum": True,
        "preload_below_permissible": True,
        "friction_in_joint_range": True,
        "yield": False,  # reached, and the default strategy was not to
    }


def test_the_compliance_twenty_percent_wrong_moves_friction_by_less_than_0_005() -> None:
    """The issue's claim: δ_P 20 % wrong, μ_ges within ±0.005, preload within a few %."""
    r = run(A, {**M12_JOINT, **_bilinear(0.12)})
    assert r["total_friction"] == pytest.approx(0.12, rel=1e-9)
    only_plates = {"bolt_compliance_uncertainty": 0.0}
    r = run(A, {**M12_JOINT, **_bilinear(0.12), **only_plates})
    assert 0.0 < 0.12 - r["total_friction_min"] < 0.005
    assert 0.0 < r["total_friction_max"] - 0.12 < 0.005
    # F = T/k with k ∝ δ: δ_P ± 20 % is (1 ∓ 0.2 δ_P/δ)^-1 on the preload
    share = DP / DELTA
    assert r["preload_min"] / r["preload"] == pytest.approx(1 / (1 + 0.2 * share), rel=1e-9)
    assert r["preload_max"] / r["preload"] == pytest.approx(1 / (1 - 0.2 * share), rel=1e-9)


def test_the_tools_wind_up_is_taken_off() -> None:
    """A drive train of c_t in series: the tool sees 1/(1/R + 1/c_t); the nut R again."""
    mu, c_t = 0.10, 3000.0
    rate = rate_of(k_of(mu, mu))
    trace = _bilinear(mu)
    tool = [a + t / c_t for a, t in zip(trace["angle"], trace["torque"], strict=True)]
    r = run(
        A,
        {**M12_JOINT, "angle": tool, "torque": trace["torque"], "tool_stiffness": c_t},
    )
    assert r["elastic_rate"] == pytest.approx(rate, rel=1e-9)
    r = run(A, {**M12_JOINT, "angle": tool, "torque": trace["torque"]})
    assert r["elastic_rate"] == pytest.approx(1 / (1 / rate + 1 / c_t), rel=1e-9)


def test_a_multi_step_program_is_split_and_the_last_step_read() -> None:
    """Run down to 30 N·m, release, loosen (angle back), retighten past the first angle."""
    rate = rate_of(k_of(0.10, 0.10))
    up = np.arange(0.0, 40.0, 0.1) * DEG
    first = np.minimum(rate * np.maximum(up - THETA0, 0.0), 30.0)
    back = np.linspace(up[-1], up[-1] - 5 * DEG, 30)
    again = np.arange(up[-1] - 5 * DEG, 70.0 * DEG, 0.1 * DEG)
    last = np.minimum(rate * np.maximum(again - THETA0 - 2 * DEG, 0.0), 75.0)
    angle = np.concatenate([up, back, again])
    torque = np.concatenate([first, np.full(30, -5.0), last])
    x = {**M12_JOINT, "angle": angle.tolist(), "torque": torque.tolist()}
    r = run(A, x)
    assert (r["steps_found"], r["step_analysed"]) == (2, 2)
    assert r["elastic_rate"] == pytest.approx(rate, rel=1e-9)
    r = run(A, {**x, "step": 1})
    assert r["step_analysed"] == 1 and r["final_torque"] == pytest.approx(30.0)


@pytest.mark.parametrize(
    ("change", "field", "words"),
    [
        (
            {"angle": [0.01 * i for i in range(19)], "torque": [float(i) for i in range(19)]},
            "angle",
            "has 19 values",
        ),
        ({"torque": [1.0] * 30}, "torque", "one torque per angle"),
        ({"time": [0.001 * i for i in range(30)]}, "time", "one time per angle"),
        ({"step": 3}, "step", "the trace has 1 step"),
        ({"torque": [0.0] * 701}, "torque", "no step found"),
        ({"friction_split_min": 2.0, "friction_split_max": 1.0}, "friction_split_max", "below"),
    ],
)
def test_refusals_name_the_field(change: dict[str, Any], field: str, words: str) -> None:
    x = {**M12_JOINT, **_bilinear(0.10), **change}
    with pytest.raises(engine.InputOutOfRange) as caught:
        run(A, x)
    assert caught.value.field == field and words in caught.value.message


def test_an_angle_running_backwards_within_a_step_is_refused() -> None:
    trace = _bilinear(0.10)
    trace["angle"][400] -= 2 * DEG  # torque well up: inside the step
    with pytest.raises(engine.InputOutOfRange) as caught:
        engine.run(engine.get_model(A), {**M12_JOINT, **trace})
    assert caught.value.field == "angle" and caught.value.context["index"] == 400
    assert "runs backwards within step 1" in caught.value.message


def test_the_torque_then_angle_program() -> None:
    s = 0.1
    f_min, f_zul = float(JOINT["assembly_preload_min"]), float(JOINT["permissible_preload"])
    target = 0.5 * (f_min + f_zul)
    k_lo, k_hi, k_mid = k_of(0.08, 0.08), k_of(0.16, 0.16), k_of(0.12, 0.12)
    d_lo, d_hi = DS * 0.95 + DP * 0.8, DS * 1.05 + DP * 1.2
    snug = s * target * k_mid
    final = 2 * math.pi * (target - s * target) * DELTA / P
    per = P / (2 * math.pi)
    r = engine.run(engine.get_model(PROG), dict(M12_JOINT))
    v: dict[str, Any] = dict(r.results)
    assert v["strategy"] == "torque_angle" and v["window_fits"] is True
    pin("trace.program", "target_preload", v["target_preload"], target, rel=1e-12)
    pin("trace.program", "snug_torque", v["snug_torque"], snug, rel=1e-9)
    pin("trace.program", "final_angle", v["final_angle"], final, rel=1e-9)
    pin(
        "trace.program",
        "angle_min",
        v["angle_min"],
        2 * math.pi * (f_min - snug / k_hi) * d_hi / P,
        rel=1e-9,
    )
    pin(
        "trace.program",
        "angle_max",
        v["angle_max"],
        2 * math.pi * (f_zul - snug / k_lo) * d_lo / P,
        rel=1e-9,
    )
    pin("trace.program", "torque_min", v["torque_min"], snug + k_lo * final * per / d_hi, rel=1e-9)
    pin("trace.program", "torque_max", v["torque_max"], snug + k_hi * final * per / d_lo, rel=1e-9)
    pin("trace.program", "rate_min", v["rate_min"], rate_of(k_lo), rel=1e-9)
    pin("trace.program", "rate_max", v["rate_max"], rate_of(k_hi), rel=1e-9)
    pin(
        "trace.program",
        "gradient_threshold_min",
        v["gradient_threshold_min"],
        0.5 * rate_of(k_lo),
        rel=1e-9,
    )
    pin(
        "trace.program",
        "gradient_threshold_max",
        v["gradient_threshold_max"],
        0.5 * rate_of(k_hi),
        rel=1e-9,
    )
    pin(
        "trace.program", "preload_min", v["preload_min"], snug / k_hi + final * per / d_hi, rel=1e-9
    )
    pin(
        "trace.program", "preload_max", v["preload_max"], snug / k_lo + final * per / d_lo, rel=1e-9
    )


def test_the_yield_program() -> None:
    k_lo, k_hi, k_mid = k_of(0.08, 0.08), k_of(0.16, 0.16), k_of(0.12, 0.12)
    d_lo, d_hi = DS * 0.95 + DP * 0.8, DS * 1.05 + DP * 1.2
    fy_lo_mu, fy_hi_mu = yield_preload(0.08), yield_preload(0.16)
    snug = 0.1 * fy_hi_mu * k_mid
    v = run(PROG, {**M12_JOINT, "strategy": "yield"})
    assert v["final_angle"] is None
    assert v["target_preload"] == pytest.approx(fy_lo_mu, rel=1e-9)
    assert v["snug_torque"] == pytest.approx(snug, rel=1e-9)
    assert v["torque_min"] == pytest.approx(k_lo * fy_lo_mu, rel=1e-9)  # 69.6 N·m
    assert v["torque_max"] == pytest.approx(k_hi * fy_hi_mu, rel=1e-9)  # 113 N·m
    assert v["angle_min"] == pytest.approx(
        2 * math.pi * (fy_hi_mu - snug / k_lo) * d_lo / P, rel=1e-9
    )
    assert v["angle_max"] == pytest.approx(
        2 * math.pi * (fy_lo_mu - snug / k_hi) * d_hi / P, rel=1e-9
    )
    assert (v["preload_min"], v["preload_max"]) == pytest.approx((fy_hi_mu, fy_lo_mu), rel=1e-9)
