"""joint.clamp_capability: closed-form cases, independent integrals, properties, refusals.

The M12 8.8 numbers are written out from the standards (ISO 724: d2 = d − 0.649519 P,
d3 = d − 1.226869 P; ISO 898-1: R_p0.2 = 640 MPa; hex head d_W = 16.63 mm, medium hole
d_h = 13.5 mm) and VDI 2230-1 R7/R13's formulas are typed here as the independent
reference, not taken from the engine.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, stats

from engine import InputOutOfRange, get_model, run
from engine.models.clamp import CLAMP_CAPABILITY, M12_JOINT
from tests.pins import pin

MODEL = "joint.clamp_capability"
P, D = 1.75e-3, 12e-3
D2 = D - 0.649519 * P
D3 = D - 1.226869 * P
DS = 0.5 * (D2 + D3)
AS = math.pi / 4 * DS**2
RP, DW, DH = 640e6, 16.63e-3, 13.5e-3
M_U = 0.4  # the example's prevailing torque


def k_total(mu_g: float, mu_k: float) -> float:
    """VDI 2230-1 R13 per newton: 0.16 P + 0.58 d2 μ_G + μ_K (d_W + d_h)/4."""
    return 0.16 * P + 0.58 * D2 * mu_g + mu_k * (DW + DH) / 4


def f_zul(mu_g: float, nu: float = 0.9) -> float:
    """VDI 2230-1 R7: ν R_p A_s / √(1 + 3 (1.5 d2/d_s (P/(π d2) + 1.155 μ_G))²)."""
    ratio = 1.5 * D2 / DS * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30)))
    return nu * RP * AS / math.sqrt(1 + 3 * ratio**2)


def fixed_friction(mu: float) -> dict[str, object]:
    return {
        "thread_friction_law": "fixed",
        "thread_friction_mean": mu,
        "bearing_friction_law": "fixed",
        "bearing_friction_mean": mu,
    }


def test_normal_torque_and_fixed_friction_give_a_normal_preload() -> None:
    """F_M = (M_A − M_ü)/k is normal with mean (80 − 0.4)/k and sd 4/k: every output in
    closed form, to 1e-9."""
    r = run(CLAMP_CAPABILITY, {**M12_JOINT, "torque_sd": 4.0, **fixed_friction(0.12)})
    res = r.results
    k = k_total(0.12, 0.12)
    mean, sd = 79.6 / k, 4.0 / k
    pin("joint.clamp_capability", "mean_torque", res["mean_torque"], 80.0)
    pin("joint.clamp_capability", "torque_sd", res["torque_sd"], 4.0)
    pin("joint.clamp_capability", "preload_mean", res["preload_mean"], mean, rel=1e-9)
    pin("joint.clamp_capability", "preload_sd", res["preload_sd"], sd, rel=1e-9)

    def at(q: float) -> float:
        return float(mean + sd * stats.norm.ppf(q))

    pin("joint.clamp_capability", "preload_q1e-6", res["preload_q1e-6"], at(1e-6), rel=1e-9)
    pin("joint.clamp_capability", "preload_q00135", res["preload_q00135"], at(0.00135), rel=1e-9)
    pin("joint.clamp_capability", "preload_median", res["preload_median"], mean, rel=1e-9)
    pin("joint.clamp_capability", "preload_q99865", res["preload_q99865"], at(0.99865), rel=1e-9)
    pin("joint.clamp_capability", "preload_q1-1e-6", res["preload_q1-1e-6"], at(1 - 1e-6), rel=1e-9)
    # ν = F_M / F_M,zul(μ_G) × 0.9 is normal too
    nu_mean, nu_sd = 0.9 * mean / f_zul(0.12), 0.9 * sd / f_zul(0.12)
    nu_at = {q: nu_mean + nu_sd * stats.norm.ppf(q) for q in (0.99865, 1 - 1e-6)}
    pin(
        "joint.clamp_capability", "utilisation_median", res["utilisation_median"], nu_mean, rel=1e-7
    )
    pin(
        "joint.clamp_capability",
        "utilisation_q99865",
        res["utilisation_q99865"],
        nu_at[0.99865],
        rel=1e-7,
    )
    pin(
        "joint.clamp_capability",
        "utilisation_q1-1e-6",
        res["utilisation_q1-1e-6"],
        nu_at[1 - 1e-6],
        rel=1e-7,
    )
    pin(
        "joint.clamp_capability",
        "permissible_preload",
        res["permissible_preload"],
        f_zul(0.12),
        rel=1e-9,
    )
    high = stats.norm.sf((f_zul(0.12) - mean) / sd)
    pin("joint.clamp_capability", "high_ppm", res["high_ppm"], high * 1e6, rel=1e-9)
    pin("joint.clamp_capability", "high_ppm_error", res["high_ppm_error"], 0.0, abs=1e-9)
    f_min = res["required_preload_min"]
    pin(
        "joint.clamp_capability",
        "low_ppm",
        res["low_ppm"],
        stats.norm.cdf((f_min - mean) / sd) * 1e6,
        rel=1e-9,
    )
    pin("joint.clamp_capability", "low_ppm_error", res["low_ppm_error"], 0.0, abs=1e-9)
    cpk = min(f_zul(0.12) - mean, mean - f_min) / (3 * sd)
    pin("joint.clamp_capability", "clamp_force_cpk", res["clamp_force_cpk"], cpk, rel=1e-9)
    z = stats.norm.ppf(0.99865)
    pin(
        "joint.clamp_capability",
        "tightening_factor",
        res["tightening_factor"],
        (mean + z * sd) / (mean - z * sd),
    )
    pin("joint.clamp_capability", "friction_copula", res["friction_copula"], 0.0)
    # Cmk of N(80, 4) at ±10 %: 8/(3 × 4)
    pin(
        "joint.clamp_capability",
        "tool_critical_index",
        res["tool_critical_index"],
        8 / 12,
        rel=1e-12,
    )
    pin("joint.clamp_capability", "quadrature_panels", res["quadrature_panels"], 16)


def test_the_joint_requirement_is_joint_vdi2230s() -> None:
    """F_M,min required is joint.vdi2230's R5 for the same joint (no thermal term here, so
    the torque and friction box do not enter it)."""
    ours = run(CLAMP_CAPABILITY, dict(CLAMP_CAPABILITY.examples[0])).results
    theirs = run(get_model("joint.vdi2230"), dict(get_model("joint.vdi2230").examples[1]))
    pin(
        "joint.clamp_capability",
        "required_preload_min",
        ours["required_preload_min"],
        theirs.results["required_preload_min"],
        rel=1e-12,
    )


def _independent_high(mean_t: float, sd_t: float, lo: float, hi: float) -> float:
    """P(ν > 0.9) for μ_G, μ_K independent uniform on lo…hi and a normal torque, by
    scipy's adaptive dblquad over the frictions themselves (no scores, no copula)."""

    def integrand(mu_k: float, mu_g: float) -> float:
        torque = f_zul(mu_g) * k_total(mu_g, mu_k) + M_U
        return float(stats.norm.sf((torque - mean_t) / sd_t)) / (hi - lo) ** 2

    value, _ = integrate.dblquad(integrand, lo, hi, lo, hi, epsabs=1e-13, epsrel=1e-10)
    return float(value)


def test_rho_zero_is_the_independent_integral() -> None:
    r = run(CLAMP_CAPABILITY, {**M12_JOINT, "nominal_torque": 80.0, "torque_sd": 3.0})
    ref = _independent_high(80.0, 3.0, 0.08, 0.16)
    # within the error the result states (the change from half the panels: 3.6e-5)
    error = r.results["high_ppm_error"]
    assert 0 < error < 1e-3
    assert r.results["high_ppm"] == pytest.approx(ref * 1e6, rel=error)


def test_a_deep_tail_against_the_independent_integral() -> None:
    """At 62 N·m with a normal friction lot some 16 ppm lie above F_M,zul: the composite
    Gauss-Legendre quadrature agrees with a Gauss-Hermite rule within the error it states."""
    law = {"mean": 0.12, "sd": 0.0133}
    x = {
        **M12_JOINT,
        "nominal_torque": 62.0,
        "torque_sd": 1.6,
        **{f"{w}_friction_law": "normal" for w in ("thread", "bearing")},
        **{f"{w}_friction_{k}": v for w in ("thread", "bearing") for k, v in law.items()},
    }
    res = run(CLAMP_CAPABILITY, x).results
    assert 10 < res["high_ppm"] < 30

    # the reference: a 160 × 160 Gauss-Hermite rule over the two frictions' scores
    z, w = np.polynomial.hermite_e.hermegauss(160)
    w = w / math.sqrt(2 * math.pi)
    mu_g, mu_k = 0.12 + 0.0133 * z[:, None], 0.12 + 0.0133 * z[None, :]
    ratio = 1.5 * D2 / DS * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30)))
    zul = 0.9 * RP * AS / np.sqrt(1 + 3 * ratio**2)
    torque = zul * (0.16 * P + 0.58 * D2 * mu_g + mu_k * (DW + DH) / 4) + M_U
    ref = float(np.sum(w[:, None] * w[None, :] * stats.norm.sf((torque - 62.0) / 1.6)))
    assert res["high_ppm"] == pytest.approx(ref * 1e6, rel=max(res["high_ppm_error"], 1e-6))


def test_a_perfect_tool_is_the_limit_of_a_small_scatter() -> None:
    base = {**M12_JOINT, "nominal_torque": 80.0}
    perfect = run(CLAMP_CAPABILITY, {**base, "torque_sd": 0.0}).results
    almost = run(CLAMP_CAPABILITY, {**base, "torque_sd": 1e-4}).results
    assert perfect["high_ppm"] == pytest.approx(almost["high_ppm"], rel=1e-4)
    assert perfect["preload_sd"] == pytest.approx(almost["preload_sd"], rel=1e-6)

    # a perfect tool: P(ν > 0.9) is the share of the (μ_G, μ_K) square where
    # F_M > F_M,zul(μ_G), by dblquad on the indicator's boundary in μ_K
    def share(mu_g: float) -> float:
        mu_k = ((79.6 / f_zul(mu_g)) - 0.16 * P - 0.58 * D2 * mu_g) / ((DW + DH) / 4)
        return min(max((mu_k - 0.08) / 0.08, 0.0), 1.0) / 0.08

    ref, _ = integrate.quad(share, 0.08, 0.16, epsabs=1e-12, limit=200)
    assert perfect["high_ppm"] == pytest.approx(ref * 1e6, rel=1e-6)


def test_a_perfect_tools_quantiles_by_the_corner_triangle() -> None:
    """A perfect tool and μ_G, μ_K uniform on 0.08…0.16: F_M = 79.6/k with k linear in
    both, so P(F_M ≤ x) near the smallest F_M is the triangle s²/(2AB) of the unit square,
    A = 0.58 d2 × 0.08, B = 0.08 (d_W + d_h)/4, s = k_max − 79.6/x. The quantiles come
    from 8 panels: to 1e-4 here, where the kinks of the uniform laws meet in the corner."""
    res = run(CLAMP_CAPABILITY, {**M12_JOINT, "torque_sd": 0.0}).results
    a, b = 0.58 * D2 * 0.08, 0.08 * (DW + DH) / 4
    k_max, k_min = k_total(0.16, 0.16), k_total(0.08, 0.08)
    s = math.sqrt(2 * a * b * 1e-6)
    pin(
        "joint.clamp_capability",
        "preload_q1e-6",
        res["preload_q1e-6"],
        79.6 / (k_max - s),
        rel=1e-4,
    )
    pin(
        "joint.clamp_capability",
        "preload_q1-1e-6",
        res["preload_q1-1e-6"],
        79.6 / (k_min + s),
        rel=1e-4,
    )


def test_symmetry_of_a_normal_preload() -> None:
    """A normal F_M: the quantiles at q and 1 − q lie symmetric about the median."""
    res = run(CLAMP_CAPABILITY, {**M12_JOINT, "torque_sd": 2.0, **fixed_friction(0.1)}).results
    m = res["preload_median"]
    assert res["preload_q99865"] - m == pytest.approx(m - res["preload_q00135"], rel=1e-9)
    assert res["preload_q1-1e-6"] - m == pytest.approx(m - res["preload_q1e-6"], rel=1e-9)


def test_monotone_in_torque_scatter_and_correlation() -> None:
    base = {**M12_JOINT, "capability_index": 1.67}
    highs, lows = [], []
    for torque in (60.0, 70.0, 80.0):
        res = run(CLAMP_CAPABILITY, {**base, "nominal_torque": torque}).results
        highs.append(res["high_ppm"])
        lows.append(res["preload_q1e-6"])
    assert highs == sorted(highs) and lows == sorted(lows)
    # more correlated frictions spread the preload more (k_G + k_K varies more)
    sds = [
        run(CLAMP_CAPABILITY, {**base, "friction_correlation": rho}).results["preload_sd"]
        for rho in (-0.5, 0.5, 0.9)
    ]
    assert sds == sorted(sds)
    # a worse tool spreads it too
    spread = [
        run(CLAMP_CAPABILITY, {**M12_JOINT, "capability_index": cm}).results["preload_sd"]
        for cm in (2.0, 1.67, 0.8)
    ]
    assert spread == sorted(spread)


def test_capability_in_and_the_mean_offset() -> None:
    """Cm 1.2 and Cmk 1.0 at 70 N·m ± 10 %: σ = 14/(6 × 1.2) = 1.9444 N·m and the mean
    3σ(1.2 − 1.0) = 1.1667 N·m above 70; a category A minimum of 1.67 is missed."""
    r = run(CLAMP_CAPABILITY, dict(CLAMP_CAPABILITY.examples[1]))
    res = r.results
    pin("joint.clamp_capability", "torque_sd", res["torque_sd"], 14 / 7.2, rel=1e-12)
    pin(
        "joint.clamp_capability",
        "mean_torque",
        res["mean_torque"],
        70 + 3 * 14 / 7.2 * 0.2,
        rel=1e-12,
    )
    pin("joint.clamp_capability", "tool_critical_index", res["tool_critical_index"], 1.0, rel=1e-12)
    pin(
        "joint.clamp_capability",
        "friction_copula",
        res["friction_copula"],
        2 * math.sin(math.pi * 0.5 / 6),
    )
    assert res["category_minimum_met"] is False
    assert {c.name: c.ok for c in r.checks}["category_minimum"] is False


def test_samples_give_the_tool() -> None:
    values = [79.0, 80.0, 81.0, 80.0]  # mean 80, s = √(2/3)
    res = run(CLAMP_CAPABILITY, {**M12_JOINT, "torque_samples": values}).results
    pin("joint.clamp_capability", "torque_sd", res["torque_sd"], math.sqrt(2 / 3), rel=1e-12)


def test_monte_carlo_agrees_at_a_share_it_resolves() -> None:
    """200,000 draws resolve a share of ~35 % to ±0.1 %: within 4 standard errors."""
    res = run(CLAMP_CAPABILITY, dict(CLAMP_CAPABILITY.examples[0])).results
    rng = np.random.default_rng(7)
    n = 200_000
    torque = rng.normal(80.0, 16 / (6 * 1.67), n)
    mu_g, mu_k = rng.uniform(0.08, 0.16, (2, n))
    f = (torque - M_U) / (0.16 * P + 0.58 * D2 * mu_g + mu_k * (DW + DH) / 4)
    ratio = 1.5 * D2 / DS * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30)))
    share = float(np.mean(f > 0.9 * RP * AS / np.sqrt(1 + 3 * ratio**2)))
    se = math.sqrt(share * (1 - share) / n)
    assert abs(res["high_ppm"] / 1e6 - share) < 4 * se


@pytest.mark.parametrize(
    "extra, field",
    [
        ({"torque_sd": 1.0, "capability_index": 1.67}, "capability_index"),
        ({"capability_index": 1.0, "critical_capability_index": 1.2}, "critical_capability_index"),
        ({"critical_capability_index": 1.2}, "critical_capability_index"),
        ({"torque_sd": 20.0}, "torque_sd"),
        ({"thread_friction_law": "normal", "thread_friction_mean": 0.12}, "thread_friction_sd"),
        (
            {
                "thread_friction_law": "normal",
                "thread_friction_mean": 0.05,
                "thread_friction_sd": 0.02,
            },
            "thread_friction_sd",
        ),
        ({"bearing_friction_low": 0.2}, "bearing_friction_high"),
        (
            {"bearing_friction_law": "triangular", "bearing_friction_mode": 0.3},
            "bearing_friction_mode",
        ),
        ({"torque_samples": [80.0, 80.0]}, "torque_samples"),
        ({"torque_samples": [79.0, 81.0], "mean_torque": 80.0}, "mean_torque"),
    ],
)
def test_refusals_name_the_field(extra: dict[str, object], field: str) -> None:
    with pytest.raises(InputOutOfRange) as err:
        run(CLAMP_CAPABILITY, {**M12_JOINT, **extra})
    assert err.value.field == field
