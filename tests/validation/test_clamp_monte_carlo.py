"""joint.clamp_capability against an independent Monte Carlo and the figure that asked for it.

The reference draws the torque and both friction coefficients with numpy and carries each
tightening through VDI 2230-1 R13 (F_M = (M_A − M_ü)/(0.16 P + 0.58 d2 μ_G + μ_K D_Km/2))
and R7 (F_M,zul at ν = 0.9 and the bolt's own μ_G), typed here from the standard for the
M12 8.8 joint (ISO 724 d2 = d − 0.649519 P, d3 = d − 1.226869 P; ISO 898-1 R_p0.2 640 MPa;
hex head d_W 16.63 mm, medium hole d_h 13.5 mm), not taken from the engine. The model
integrates by quadrature; the sampled share must agree within 4 standard errors.

The question came with a measurement made by a 2,000-point study of joint.vdi2230: 35.5 %
of bolts above F_M,zul at 80 N·m, μ 0.08…0.16, a perfect tool (±1.1 % sampling error).
"""

from __future__ import annotations

import math

import numpy as np

from engine import run
from engine.models.clamp import CLAMP_CAPABILITY, M12_JOINT

P, D = 1.75e-3, 12e-3
D2 = D - 0.649519 * P
D3 = D - 1.226869 * P
DS = 0.5 * (D2 + D3)
AS = math.pi / 4 * DS**2
RP, DW, DH = 640e6, 16.63e-3, 13.5e-3


def _sampled_high_share(torque_mean: float, torque_sd: float, n: int, seed: int) -> float:
    rng = np.random.default_rng(seed)
    mu_g, mu_k = rng.uniform(0.08, 0.16, (2, n))
    torque = torque_mean + torque_sd * rng.standard_normal(n)
    preload = (torque - 0.4) / (0.16 * P + 0.58 * D2 * mu_g + mu_k * (DW + DH) / 4)
    ratio = 1.5 * D2 / DS * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30)))
    f_zul = 0.9 * RP * AS / np.sqrt(1 + 3 * ratio**2)
    return float(np.mean(preload > f_zul))


def test_the_share_above_f_m_zul_agrees_with_an_independent_monte_carlo() -> None:
    n = 400_000
    sampled = _sampled_high_share(80.0, 3.0, n, seed=7)
    se = math.sqrt(sampled * (1 - sampled) / n)
    r = run(CLAMP_CAPABILITY, {**M12_JOINT, "nominal_torque": 80.0, "torque_sd": 3.0})
    model = r.results["high_ppm"] * 1e-6
    assert abs(model - sampled) < 4 * se, (model, sampled, se)


def test_a_perfect_tool_reproduces_the_studied_35_5_percent() -> None:
    r = run(CLAMP_CAPABILITY, {**M12_JOINT, "nominal_torque": 80.0, "torque_sd": 0.0})
    share = r.results["high_ppm"] * 1e-6
    assert abs(share - 0.355) < 2 * 0.011, share
    # and the same share drawn here, the tool's scatter being nil
    sampled = _sampled_high_share(80.0, 0.0, 400_000, seed=11)
    assert abs(share - sampled) < 4 * math.sqrt(sampled * (1 - sampled) / 400_000)
