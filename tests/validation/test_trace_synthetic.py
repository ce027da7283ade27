"""trace.analysis against traces from a generator of its own (not the model checking itself).

The generator below writes each trace from its own equations, with known friction, friction
split, compliance and preload: the exact helix thread torque (M_G = F d2/2 tan(ψ + ρ′), not
R13's linearised 0.16 P + 0.58 d2 μ_G), a gap-closing snug region where the preload rises
with the square of the angle, a bolt that stays elastic to 95 % of its yield preload and
then saturates exponentially towards 110 % (plastic bending of the force–angle line), the
torsion of the socket and spindle, a run-down torque that stays on as prevailing torque,
a two-speed controller sampling every millisecond, Gaussian torque noise, quantisation of
torque (0.01 N·m) and angle (0.1°, an encoder), a random angle offset, and the tool's
release after the stop. The joint's true compliance differs from the model's by a random
share within the stated uncertainty (δ_S ± 5 %, δ_P ± 20 %), as a real joint would.

The share of traces whose true preload or true total friction falls outside the stated
bounds is printed and held against the stated confidence (95 %): the bounds are worst-case
over the stated compliance uncertainty; only detection noise may carry a trace out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest

import engine
from engine.models.trace import M12_JOINT
from engine.physics import trace as tr

DEG = math.pi / 180.0
P, D2, D0 = 1.75e-3, 10.86334175e-3, 10.3581605e-3
DW, DH, AS, RP = 16.63e-3, 13.5e-3, 84.26653836e-6, 640e6
JOINT: dict[str, Any] = dict(engine.run(engine.get_model("joint.vdi2230"), M12_JOINT).results)
DS, DP = float(JOINT["bolt_compliance"]), float(JOINT["clamped_compliance"])
MODEL = engine.get_model("trace.analysis")


def analyse(inputs: dict[str, Any]) -> dict[str, Any]:
    """trace.analysis's scalar results (typed for arithmetic)."""
    return dict(engine.run(MODEL, inputs).results)


#: The confidence the bounds are stated with (docs: the rung's typical_exceeded).
CONFIDENCE = 0.95


def exact_k(mu_g: float, mu_k: float) -> float:
    """Torque per newton of preload: exact helix thread torque plus the bearing's."""
    psi = math.atan(P / (math.pi * D2))
    rho = math.atan(mu_g / math.cos(math.radians(30.0)))
    return 0.5 * D2 * math.tan(psi + rho) + mu_k * (DW + DH) / 4.0


def total_friction_of(k: float) -> float:
    """The one μ (μ_G = μ_K) whose exact k is k: bisection on exact_k."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if exact_k(mid, mid) < k else (lo, mid)
    return 0.5 * (lo + hi)


def yield_force(mu_g: float) -> float:
    """VDI 2230-1 R7's preload at R_p0.2 (ν = 1), written out: R_p A_s / β."""
    ratio = 1.5 * D2 / D0 * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30.0)))
    return RP * AS / math.sqrt(1.0 + 3.0 * ratio**2)


@dataclass
class Synthetic:
    inputs: dict[str, Any]
    friction: float  # the true total friction
    preload: float  # the true preload at the peak torque
    gradient_left: float  # the true dF/dθ at the stop over the elastic one (1: elastic)
    knee: tuple[float, float]  # torques where the knee starts and ends (95 %, 110 % F_y)
    rate: float  # the true elastic rate at the nut, [N*m/rad]


def generate(
    rng: np.random.Generator,
    *,
    mu_g: float | None = None,
    split: float | None = None,
    plates_error: float | None = None,
    bolt_error: float | None = None,
    past_yield: bool | None = None,
) -> Synthetic:
    mu_g = rng.uniform(0.08, 0.16) if mu_g is None else mu_g
    split = rng.uniform(0.7, 1.4) if split is None else split  # μ_K/μ_G
    mu_k = split * mu_g
    e_p = rng.uniform(-0.2, 0.2) if plates_error is None else plates_error
    e_s = rng.uniform(-0.05, 0.05) if bolt_error is None else bolt_error
    delta = DS * (1 + e_s) + DP * (1 + e_p)
    k = exact_k(mu_g, mu_k)
    c = P / (2 * math.pi * delta)  # dF/dθ once snug, [N/rad]
    f_y = yield_force(mu_g)
    f_p, f_u = 0.95 * f_y, 1.10 * f_y
    m_run = rng.uniform(0.2, 1.0)  # run-down torque, stays on as prevailing torque
    gap = rng.uniform(3.0, 10.0) * DEG  # the snug region's angle
    c_t = rng.uniform(1500.0, 6000.0)  # socket and spindle, [N*m/rad]
    past_yield = rng.random() < 0.3 if past_yield is None else past_yield

    def force(phi: np.ndarray) -> np.ndarray:
        lin = np.where(phi < gap, c * np.maximum(phi, 0.0) ** 2 / (2 * gap), c * (phi - gap / 2))
        top = f_u - f_p
        return np.where(lin > f_p, f_p + top * (1 - np.exp(-(lin - f_p) / top)), lin)

    # a two-speed controller: fast run-down, slow from half the target, 1 ms samples
    fast, slow = rng.uniform(120.0, 360.0) * DEG, rng.uniform(20.0, 60.0) * DEG  # [rad/s]
    if past_yield:
        stop_at = (f_p / c + gap / 2) + rng.uniform(5.0, 15.0) * DEG  # angle control
        target = math.inf
    else:
        target = rng.uniform(0.55, 0.85) * k * f_y + m_run  # torque control
        stop_at = math.inf
    start = -rng.uniform(20.0, 60.0) * DEG  # the run-down's angle before contact
    phi = start
    angles: list[float] = []
    torques: list[float] = []
    half = 0.5 * (target if math.isfinite(target) else k * f_y)
    while True:
        t = m_run + k * float(force(np.array(phi)))
        if t >= target or phi >= stop_at or len(angles) > 9000:
            break
        angles.append(phi)
        torques.append(t)
        phi += (slow if t > half else fast) * 1e-3
    peak_force = (torques[-1] - m_run) / k
    linear = c * (phi - gap / 2)  # the elastic line's force at the stop
    left = math.exp(-(linear - f_p) / (f_u - f_p)) if linear > f_p else 1.0
    theta = np.array(angles)
    torque = np.array(torques)
    torque = torque + rng.normal(0.0, 0.002 * torque.max() + 0.02, torque.size)
    tool = theta + torque / c_t + rng.uniform(-180.0, 180.0) * DEG  # wind-up, offset
    # the release: torque falls to nothing in 8 ms, the angle stays
    tool = np.concatenate([tool, np.full(8, tool[-1])])
    torque = np.concatenate([torque, torque[-1] * np.linspace(0.8, 0.0, 8)])
    torque = np.round(torque, 2)
    tool = np.round(tool / (0.1 * DEG)) * (0.1 * DEG)
    inputs = {
        **M12_JOINT,
        "prevailing_torque": m_run,
        "angle": tool.tolist(),
        "torque": torque.tolist(),
        "time": (np.arange(tool.size) * 1e-3).tolist(),
        "tool_stiffness": c_t,
        "yield_allowed": True,
    }
    return Synthetic(
        inputs,
        total_friction_of(k),
        peak_force,
        left,
        (m_run + k * f_p, m_run + k * f_u),
        k * c,
    )


def _run(n: int, seed: int) -> dict[str, Any]:
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(n):
        s = generate(rng)
        r = analyse(s.inputs)
        rows.append(
            {
                "friction_error": float(r["total_friction"]) - s.friction,
                "friction_inside": r["total_friction_min"] <= s.friction <= r["total_friction_max"],
                "preload_error": float(r["preload"]) / s.preload - 1.0,
                "preload_inside": r["preload_min"] <= s.preload <= r["preload_max"],
                "rate_error": float(r["elastic_rate"]) / s.rate - 1.0,
                # the gradient at the stop below 40 % (yielded) or above 50 % (not): between,
                # the 50 % point lies within the last gradient window, where no rule can see it
                "yield_clear": not 0.4 <= s.gradient_left <= 0.5,
                "yield_right": bool(r["yield_detected"]) == (s.gradient_left < 0.5),
                "yield_in_knee": r["yield_torque"] is None
                or s.knee[0] * 0.98 <= float(r["yield_torque"]) <= s.knee[1],
            }
        )
    return {key: np.array([row[key] for row in rows]) for key in rows[0]}


def _report(n: int, stats: dict[str, Any]) -> tuple[float, float]:
    out_f = 1.0 - stats["friction_inside"].mean()
    out_p = 1.0 - stats["preload_inside"].mean()
    clear = stats["yield_clear"]
    print(
        f"\n{n} synthetic traces: outside the stated bounds: total friction {out_f:.1%}, "
        f"preload {out_p:.1%} (stated confidence {CONFIDENCE:.0%}); "
        f"friction error {np.abs(stats['friction_error']).max():.4f} at most, "
        f"preload error {stats['preload_error'].min():+.1%}…{stats['preload_error'].max():+.1%}, "
        f"rate error {stats['rate_error'].min():+.2%}…{stats['rate_error'].max():+.2%}; "
        f"yield called right in {stats['yield_right'][clear].sum()} of {clear.sum()} clear "
        f"traces ({(~clear).sum()} with the 50 % point in the last window), found in the knee in "
        f"{stats['yield_in_knee'].sum()} of {n}"
    )
    return out_f, out_p


def _holds(n: int, stats: dict[str, Any]) -> None:
    out_f, out_p = _report(n, stats)
    allowed = 1.0 - CONFIDENCE
    assert out_f <= allowed and out_p <= allowed
    assert np.abs(stats["rate_error"]).max() < 0.02
    assert stats["yield_right"][stats["yield_clear"]].all()
    assert stats["yield_in_knee"].all()


def test_twenty_synthetic_traces_within_the_stated_bounds() -> None:
    _holds(20, _run(20, seed=2026))


@pytest.mark.slow
def test_two_hundred_synthetic_traces_within_the_stated_bounds() -> None:
    _holds(200, _run(200, seed=33))


@pytest.mark.parametrize("mu", [0.08, 0.12, 0.16])
@pytest.mark.parametrize("plates_error", [-0.2, 0.2])
def test_the_issue_m12_friction_with_the_plates_20_percent_off(
    mu: float, plates_error: float
) -> None:
    """The issue's M12: the slope of a full synthetic trace gives μ_ges within what the plates'
    20 % moves it, ±0.005 at μ = 0.12 (±0.003 at 0.08, ±0.006 at 0.16), plus 0.001 for the
    detection and 0.0005 for R13's linear thread torque against the exact helix (0.16045
    for 0.16); the preload within 3.4 % plus the noise on the peak torque, and inside its
    bounds."""
    rng = np.random.default_rng(int(mu * 1000) + int(plates_error * 100))
    s = generate(rng, mu_g=mu, split=1.0, plates_error=plates_error, bolt_error=0.0)
    r = analyse(s.inputs)
    share = 0.2 * DP / (DS + DP)  # k follows δ: the plates' 20 % is this share of k
    shift = exact_k(mu, mu) * share / (0.58 * D2 + (DW + DH) / 4)  # over R13's lever
    if mu == 0.12:
        assert shift < 0.005  # the issue's claim, from the slope itself
    assert abs(float(r["total_friction"]) - s.friction) < shift + 0.0015
    assert abs(float(r["preload"]) / s.preload - 1.0) < share + 0.01
    assert r["preload_min"] <= s.preload <= r["preload_max"]


@pytest.mark.parametrize(("mu", "rate", "yield_torque"), [(0.08, 1.68, 69.6), (0.16, 3.02, 113.0)])
def test_the_issue_m12_rate_and_yield_from_a_synthetic_trace(
    mu: float, rate: float, yield_torque: float
) -> None:
    """At the joint's own compliance, the measured rate is the issue's 1.68 / 3.02 N·m/° and
    the yield point (gradient at 50 %) lies at the knee just past the R7 yield torque."""
    rng = np.random.default_rng(7)
    s = generate(rng, mu_g=mu, split=1.0, plates_error=0.0, bolt_error=0.0, past_yield=True)
    r = analyse(s.inputs)
    assert float(r["elastic_rate"]) * DEG == pytest.approx(rate, rel=0.02)
    m_u = float(s.inputs["prevailing_torque"])
    # the 50 % gradient lies where the knee's exponential has used ln 2 of its reach:
    # F = 0.95 F_y + 0.15 F_y/2 = 1.025 F_y; R13's linear k is within 1 % of the exact one
    assert float(r["yield_torque"]) - m_u == pytest.approx(1.025 * yield_torque, rel=0.03)
    predicted = 2 * math.pi * yield_force(mu) * (DS + DP) / P
    assert float(r["snug_to_yield_angle"]) > 0.98 * predicted
    assert float(r["snug_to_yield_angle"]) < 1.12 * predicted


def test_a_lot_of_traces_summarised_finds_the_odd_one() -> None:
    """Twelve tightenings of one lot (μ 0.12 ± 0.004) and one dry part (μ 0.2): the batch's
    outlier is the dry one, its friction mean is the true one's within 0.003, and the clamp
    force's C_p from the read preloads is within 15 % of the true preloads'."""
    rng = np.random.default_rng(12)
    lot = [float(m) for m in rng.normal(0.12, 0.004, 12)] + [0.2]
    made = [generate(rng, mu_g=m, split=1.0, past_yield=False) for m in lot]
    read = [analyse(s.inputs) for s in made]
    window = (float(JOINT["assembly_preload_min"]), float(JOINT["permissible_preload"]))
    ours = tr.batch_summary(
        [r["total_friction"] for r in read], [r["preload"] for r in read], window
    )
    truth = tr.batch_summary([s.friction for s in made], [s.preload for s in made], window)
    assert ours.outliers == truth.outliers == (12,)
    assert abs(ours.friction_mean - truth.friction_mean) < 0.003
    assert ours.capability_index == pytest.approx(truth.capability_index, rel=0.15)
