"""Every numeric output of blow.joint against a hand calculation, at each source's first example.

The expected numbers are worked out here from the source equations, written out
(not through the engine's functions): the tool of each source ([000] the
nut-runner's drive, [002] the rare-impact striker, the raw energy), the thread's
torque per preload (VDI 2230-1 R13), the joint's torque rate [004, eq. 8] with the
bolt's and the plates' compliances (VDI 2230-1 R3), the energy balance blow after
blow, and the ball clutch's slipping torque [001, eq. 1–3].
"""

from __future__ import annotations

import math
from typing import Any

import pytest

from engine import run
from engine.models.blow import BLOW, CLUTCH_M10, ENERGY_M16, NUTRUNNER_HARD, RARE_IMPACT_M16
from tests.pins import pin

E_STEEL = 2.1e11
REL = 1e-9


def _torque_per_preload(
    d: float, p: float, d_w: float, d_h: float, mu_g: float, mu_k: float
) -> float:
    """k_G + k_K = 0.16·P + 0.58·d2·μ_G + D_Km/2·μ_K with d2 = d − 0.649519·P (VDI 2230-1 R13)."""
    d2 = d - 0.649519 * p
    return 0.16 * p + 0.58 * d2 * mu_g + 0.25 * (d_w + d_h) * mu_k


def _bolt_compliance(l_k: float, d: float, p: float) -> float:
    """δ_S: shank d over l_K plus a third of the nut height 0.8·d at d3 = d − 1.226869·P."""
    d3 = d - 1.226869 * p
    return 4.0 / (E_STEEL * math.pi) * (l_k / d**2 + 0.8 * d / 3.0 / d3**2)


def _cone_compliance(l_k: float, d_w: float, d_h: float) -> float:
    """δ_P of one plate of l_K, through bolt, plates wide enough for the whole cone (R3).

    tan φ = 0.362 + 0.032·ln(β_L/2) + 0.153·ln y, β_L = l_K/d_W, y = D_A/d_W with
    D_A = d_W + l_K·tan φ (the smallest plate the cone fills: a fixed point), then
    δ_P = 2 ln[(d_W + d_h)(d_W + l_K tan φ − d_h)/((d_W − d_h)(d_W + l_K tan φ + d_h))]
          / (E π d_h tan φ).
    """
    d_a = 3.0 * d_w
    for _ in range(200):
        tan = 0.362 + 0.032 * math.log(l_k / d_w / 2.0) + 0.153 * math.log(d_a / d_w)
        d_a = d_w + l_k * tan
    top = (d_w + d_h) * (d_w + l_k * tan - d_h)
    bottom = (d_w - d_h) * (d_w + l_k * tan + d_h)
    return 2.0 * math.log(top / bottom) / (E_STEEL * math.pi * d_h * tan)


def _joint_rate(per: float, p: float, delta_s: float, delta_p: float) -> float:
    """k_j = (k_G + k_K)·P/(2π(δ_S + δ_P)) [004, eq. 8]."""
    return per * p / (2.0 * math.pi * (delta_s + delta_p))


def _energy_blows(
    e: float, c: float, k: float, t0: float, b: float, n: float, target: float, most: int = 100
) -> dict[str, list[float]]:
    """Blow after blow by the energy balance E + N·φ_t = T_p²/(2C) + (T_p² − T_0²)/(2k)."""
    out: dict[str, list[float]] = {"peak": [], "after": [], "rot": [], "work": []}
    for _ in range(most):
        held = n + math.sqrt(n * n + 2.0 * e * c)
        if held <= b * t0:  # the nut holds: the peak of a blow into a fixed end
            peak, tp, rot, work = held, t0, 0.0, 0.0
        else:
            a = 0.5 * (1.0 / c + 1.0 / k)
            tp = n + math.sqrt(n * n + (e + t0 * t0 / (2.0 * k) - n * t0 / k) / a)
            peak, rot, work = max(b * t0, tp), (tp - t0) / k, 0.5 * (tp * tp - t0 * t0) / k
        for key, v in zip(("peak", "after", "rot", "work"), (peak, tp, rot, work), strict=True):
            out[key].append(v)
        if tp >= target or rot <= 1e-12:
            break
        t0 = tp
    return out


def _check_blow(
    results: dict[str, Any],
    series: dict[str, list[float]],
    *,
    e: float,
    j: float,
    c: float,
    k: float,
    t0: float,
    b: float,
    n: float,
    per: float,
    target: float,
    window: tuple[float, float],
) -> None:
    """Every numeric output of the energy rung against the hand-worked blows."""
    blows = _energy_blows(e, c, k, t0, b, n, target)
    count = len(blows["after"])
    want = {
        "tool_energy_used": e,
        "tool_inertia_used": j,
        "tool_speed": math.sqrt(2.0 * e / j),
        "tool_stiffness_used": c,
        "joint_rate_used": k,
        "rigid_torque": math.sqrt(2.0 * e * c) + n,  # [000, eq. 7–8, 10]
        "saturation_torque": (n + math.sqrt(n * n + 2.0 * e * c)) / b,
        "peak_torque": blows["peak"][0],
        "nut_rotation": blows["rot"][0],
        "torque_after_first_blow": blows["after"][0],
        "preload_after_first_blow": blows["after"][0] / per,
        "final_torque": blows["after"][-1],
        "final_preload": blows["after"][-1] / per,
        "joint_energy_fraction": blows["work"][0] / e,
        "energy_supplied": e * count,
        "energy_into_joint": sum(blows["work"]),
    }
    for name, value in want.items():
        pin("blow.joint", name, results[name], value, rel=REL)
    assert results["blows_to_target"] == count
    assert blows["after"][-1] >= target
    assert count == 1 or blows["after"][-2] < target
    lo, hi = window
    final = blows["after"][-1] / per
    assert results["preload_verdict"] == (
        "below" if final < lo else "above" if final > hi else "within"
    )
    assert series["blow_number"] == [float(i + 1) for i in range(count)]
    for name, key in (
        ("torque_per_blow", "after"),
        ("peak_per_blow", "peak"),
        ("rotation_per_blow", "rot"),
    ):
        assert series[name] == pytest.approx(blows[key], rel=REL), name
    assert series["preload_per_blow"] == pytest.approx([t / per for t in blows["after"]], rel=REL)


def test_energy_source_by_hand() -> None:
    # M16×2 given whole: d2 = 16 − 1.299038 = 14.700962 mm, D_Km = (22.5 + 17.5)/2 = 20 mm:
    # k_G + k_K = 0.32 + 0.58·14.700962·0.12 + 10·0.12 = 2.543187 mm
    per = _torque_per_preload(0.016, 0.002, 0.0225, 0.0175, 0.12, 0.12)
    assert per == pytest.approx(2.543187e-3, rel=1e-6)
    k = _joint_rate(
        per, 0.002, _bolt_compliance(0.05, 0.016, 0.002), _cone_compliance(0.05, 0.0225, 0.0175)
    )
    r = run(BLOW, ENERGY_M16, fidelity="energy", series=True)
    _check_blow(
        r.results,
        r.series,
        e=6.0,
        j=0.004,
        c=2e4,
        k=k,
        t0=30.0,
        b=1.1,
        n=5.0,
        per=per,
        target=80e3 * per,
        window=(70e3, 100e3),
    )
    assert r.results["blows_to_target"] == 8  # the example's docstring: about eight blows


def test_nutrunner_source_by_hand() -> None:
    x = NUTRUNNER_HARD
    w1 = x["motor_speed"]  # 1400 rpm
    w3 = w1 * 0.08 / 0.25  # belt D2/D3
    w5 = w3 * 0.1 / 0.05  # gears D4/D5
    # [000, eq. 3–4]: T = (1/16)·Σ m·D²·ω² (solid discs), z = 6 spindle gears
    energy = (
        1.2 * 0.09**2 * w1**2
        + 0.8 * 0.08**2 * w1**2
        + 12.0 * 0.25**2 * w3**2
        + 2.5 * 0.1**2 * w3**2
        + 6 * 0.5 * 0.05**2 * w5**2
    ) / 16.0
    # [000, eq. 9]: C = πGd⁴/(32 l); in series C7·C8/(C7 + C8)
    c7 = math.pi * 8e10 * 0.045**4 / (32 * 0.2)
    c8 = math.pi * 8e10 * 0.032**4 / (32 * 0.3)
    c = c7 * c8 / (c7 + c8)
    drag = (6 - 1) * 10.0  # [000, eq. 10]: idle spindles
    # M20×1.5: d_w,min = 28.19 mm (ISO 4017), d_h = 22 mm (ISO 273 medium)
    per = _torque_per_preload(0.020, 0.0015, 0.02819, 0.022, 0.12, 0.12)
    k = 600.0 / math.radians(30.0)  # ISO 5393 hard joint: the target 30° after snug
    r = run(BLOW, x, fidelity="energy", series=True)
    assert r.results["tool_energy_used"] == pytest.approx(130.6716, rel=1e-6)
    _check_blow(
        r.results,
        r.series,
        e=energy,
        j=2.0 * energy / w5**2,
        c=c,
        k=k,
        t0=60.0,
        b=1.1,
        n=-drag,
        per=per,
        target=600.0,
        window=(150e3, 260e3),
    )


def test_rare_impact_source_by_hand() -> None:
    # the striker: see test_blow_striker.py (243.96 rad/s, I = 1.541875e-3 kg·m², 45.89 J)
    weight = (0.15 + 0.05 + 6 * 0.05 * 0.5) * 9.80665
    speed = math.sqrt((350.0 + 26.0 + weight) / (6 * 0.05 * 0.5 * 0.0425))
    inertia = 1e-3 + 6 * 0.05 * 0.0425**2
    # M16 coarse: P = 2 mm, d_w,min = 22.49 mm (ISO 4017), d_h = 17.5 mm (ISO 273 medium)
    per = _torque_per_preload(0.016, 0.002, 0.02249, 0.0175, 0.12, 0.12)
    k = _joint_rate(per, 0.002, _bolt_compliance(0.04, 0.016, 0.002), 2.5e-10)
    r = run(BLOW, RARE_IMPACT_M16, fidelity="energy", series=True)
    _check_blow(
        r.results,
        r.series,
        e=0.5 * inertia * speed**2,
        j=inertia,
        c=2e4,
        k=k,
        t0=20.0,
        b=1.1,
        n=0.0,
        per=per,
        target=80e3 * per,
        window=(70e3, 100e3),
    )


def test_rigid_rung_by_hand() -> None:
    # one blow to M = √(2EC) + N: the joint at M, rotation and energy account null
    # (194.6 kN on the elastic line), bent over at the 8.8 bolt's yield preload F_M0.2
    r = run(BLOW, ENERGY_M16, fidelity="rigid", series=True)
    m = math.sqrt(2.0 * 6.0 * 2e4) + 5.0  # 494.898 N·m
    per = _torque_per_preload(0.016, 0.002, 0.0225, 0.0175, 0.12, 0.12)
    f_y = 89974.549  # 640 MPa · A_s / β: test_blow_yield.py works it out
    assert r.results["rigid_torque"] == pytest.approx(m, rel=REL)
    assert r.results["peak_torque"] == pytest.approx(m, rel=REL)
    assert m / per > 125.3e3  # past even F_B = 800 MPa · A_s on the elastic line
    assert r.results["torque_after_first_blow"] == pytest.approx(f_y * per, rel=1e-8)
    assert r.results["final_torque"] == pytest.approx(f_y * per, rel=1e-8)
    assert r.results["final_preload"] == pytest.approx(f_y, rel=1e-8)
    assert r.results["bolt_verdict"] == "past breaking"
    assert r.results["blows_to_target"] == 1
    assert r.results["energy_supplied"] == pytest.approx(6.0, rel=REL)
    assert r.results["nut_rotation"] is None and r.results["energy_into_joint"] is None


def test_simulation_rung_meets_the_energy_balance_within_its_estimate() -> None:
    # the two rungs must agree within the energy rung's own estimate (the struck inertia
    # and the restitution it neglects); the torque in the first blow peaks at its peak
    sim = run(BLOW, ENERGY_M16, fidelity="simulation", series=True)
    energy = run(BLOW, ENERGY_M16, fidelity="energy")
    bound = energy.error_estimate
    assert bound is not None
    first_sim = sim.results["torque_after_first_blow"]
    first_energy = energy.results["torque_after_first_blow"]
    assert abs(first_sim / first_energy - 1.0) <= bound
    # the recorded samples straddle the located peak: none above it, the highest within 1 %
    highest = max(sim.series["torque_in_blow"])
    assert sim.results["peak_torque"] * 0.99 <= highest <= sim.results["peak_torque"] * (1 + 1e-9)
    assert sim.series["time_in_blow"][0] == 0.0
    assert sim.series["time_in_blow"] == sorted(sim.series["time_in_blow"])


def test_clutch_source_by_hand() -> None:
    # [001, eq. 1–3] common spring: T = D0·F/(2·tan(α − ρ)), ρ = atan f
    def slip(force: float, f: float) -> float:
        return 0.05 * force / (2.0 * math.tan(math.radians(45.0) - math.atan(f)))

    t_min, t_max = slip(1100.0 * 0.9, 0.07), slip(1100.0 * 1.1, 0.13)
    # M10: P = 1.5 mm, d_w,min = 14.63 mm (ISO 4017), d_h = 11 mm (ISO 273 medium);
    # the preload window at the friction box's corners μ = 0.12 ∓ 0.02 (VDI 2230-1 R13)
    per_lo = _torque_per_preload(0.010, 0.0015, 0.01463, 0.011, 0.10, 0.10)
    per_hi = _torque_per_preload(0.010, 0.0015, 0.01463, 0.011, 0.14, 0.14)
    per = _torque_per_preload(0.010, 0.0015, 0.01463, 0.011, 0.12, 0.12)
    f_lo, f_hi = t_min / per_hi, t_max / per_lo
    r = run(BLOW, CLUTCH_M10).results
    want = {
        "clutch_torque_min": t_min,
        "clutch_torque_max": t_max,
        "delivered_preload_min": f_lo,
        "delivered_preload_max": f_hi,
        "final_torque": 0.5 * (t_min + t_max),
        "final_preload": 0.5 * (f_lo + f_hi),
        # the spring force whose slipping torque at f = 0.1 tightens to 20 kN at μ = 0.12
        "clutch_spring_force_for_target": 20e3
        * per
        * 2.0
        * math.tan(math.radians(45.0) - math.atan(0.1))
        / 0.05,
    }
    for name, value in want.items():
        pin("blow.joint", name, r[name], value, rel=REL)
    assert f_lo >= 15e3 and f_hi <= 30e3
    assert r["preload_verdict"] == "within"
