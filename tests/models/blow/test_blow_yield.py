"""The blow's bolt yields: the torque–angle line bends over at F_M0.2, and past yield or past
breaking is a failing check and a warning (issue 29, the review's 438.65 J into an M16).

The bolt's strength is worked out here by hand: ISO 898-1 8.8 up to M16, R_p0.2 = 640 MPa and
R_m = 800 MPa; the stress area A_s = π/4·((d2 + d3)/2)²; VDI 2230-1 R7's torsion factor
β = √(1 + 3(3/2·d2/d_S·(P/(π d2) + μ_G/cos 30°))²); F_M0.2 = R_p0.2·A_s/β (ν = 1);
F_B = R_m·A_s. The blow by the energy balance [000, eq. 7–8] with the joint in series.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from engine import run
from engine.models.blow import BLOW
from engine.physics.blow import bolt_joint_torque
from engine.studies.plan import CHECK_FAILED, CHECK_OK, evaluate_chunk

D, P, MU = 0.016, 0.002, 0.12
D2, D3 = D - 0.649519 * P, D - 1.226869 * P
A_S = math.pi / 4.0 * ((D2 + D3) / 2.0) ** 2  # 156.67 mm²
BETA = math.sqrt(
    1.0
    + 3.0
    * (1.5 * D2 / ((D2 + D3) / 2.0) * (P / (math.pi * D2) + MU / math.cos(math.radians(30.0)))) ** 2
)  # 1.1144
F_Y = 640e6 * A_S / BETA  # 89.97 kN
F_B = 800e6 * A_S  # 125.33 kN
#: k_G + k_K (VDI 2230-1 R13) with d_w = 22.5 mm, d_h = 17.5 mm
PER = 0.16 * P + 0.58 * D2 * MU + 0.25 * (0.0225 + 0.0175) * MU
C, T0, TARGET = 2e4, 20.0, 200.0
K = TARGET / math.radians(30.0)  # ISO 5393 hard joint: the target 30° after snug

#: The review's case: an energy source of 438.65 J into an M16 on an ISO 5393 hard joint.
REVIEW = {
    "source": "energy",
    "tool_energy": 438.65,
    "tool_inertia": 0.004,
    "tool_stiffness": C,
    "joint_rate_from": "iso5393_hard",
    "thread_diameter": D,
    "thread_pitch": P,
    "bearing_outer_diameter": 0.0225,
    "hole_diameter": 0.0175,
    "snug_torque": T0,
    "target_torque": TARGET,
}


def _elastic_peak(energy: float, k: float = K) -> float:
    """T_p of one blow on the elastic line: E = T_p²/2C + (T_p² − T_0²)/2k_j (N = 0)."""
    return math.sqrt((2.0 * energy + T0 * T0 / k) / (1.0 / C + 1.0 / k))


def _yield_energy(k: float) -> float:
    """The energy at which one blow just reaches T_y = (k_G + k_K)·F_M0.2 on the elastic line."""
    t_y = PER * F_Y
    return 0.5 * t_y * t_y * (1.0 / C + 1.0 / k) - T0 * T0 / (2.0 * k)


#: The ISO 5393 hard joint's rate for a target of 300 N·m (above T_y = 228.8 N·m)
K300 = 300.0 / math.radians(30.0)


def test_hand_strength_is_the_reviews() -> None:
    # the review: "an 8.8 M16 yields at ≈ 100 kN and breaks at ≈ 126 kN" (A_s·R, no torsion)
    assert abs(640e6 * A_S / 100e3 - 1.0) < 3e-3
    assert abs(F_B / 126e3 - 1.0) < 6e-3
    assert abs(F_Y / 89.975e3 - 1.0) < 1e-4


@pytest.mark.parametrize("rung", ["rigid", "energy", "simulation"])
def test_the_reviews_blow_yields_and_breaks_the_bolt(rung: str) -> None:
    # on the elastic line the blow would reach 226 kN (the review: 219.7 kN with its own
    # tool numbers), past F_B
    assert _elastic_peak(438.65) / PER > F_B
    r = run(BLOW, REVIEW, fidelity=rung)
    assert r.results["yield_preload"] == pytest.approx(F_Y, rel=1e-9)
    assert r.results["breaking_load"] == pytest.approx(F_B, rel=1e-9)
    assert r.results["final_preload"] == pytest.approx(F_Y, rel=1e-9)
    assert r.results["final_torque"] == pytest.approx(F_Y * PER, rel=1e-9)
    assert r.results["bolt_verdict"] == "past breaking"
    checks = {c.name: c.ok for c in r.checks}
    assert checks["bolt_yield"] is False and checks["bolt_break"] is False
    assert any("the bolt yields" in w and "breaking load" in w for w in r.warnings)
    # a verdict without a preload window
    assert r.results["preload_verdict"] is None


def test_the_line_bends_over_exactly_at_yield() -> None:
    e_y = _yield_energy(K300)
    one = {**REVIEW, "target_torque": 300.0, "max_blows": 1}
    below = run(BLOW, {**one, "tool_energy": 0.99 * e_y}, fidelity="energy")
    assert below.results["bolt_verdict"] == "elastic"
    assert {c.name: c.ok for c in below.checks}["bolt_yield"] is True
    assert below.results["torque_after_first_blow"] == pytest.approx(
        _elastic_peak(0.99 * e_y, K300), rel=1e-9
    )
    above = run(BLOW, {**one, "tool_energy": 1.01 * e_y}, fidelity="energy")
    assert above.results["bolt_verdict"] == "past yield"  # 1 % over: far below F_B
    assert above.results["final_preload"] == pytest.approx(F_Y, rel=1e-9)
    assert above.results["blows_to_target"] is None
    assert {c.name: c.ok for c in above.checks} == {
        "bolt_yield": False,
        "bolt_break": True,
        "target_reached": False,
    }


def test_a_given_yield_strength_has_no_breaking_load() -> None:
    r = run(BLOW, {**REVIEW, "yield_strength": 900e6}, fidelity="energy")
    assert r.results["yield_preload"] == pytest.approx(900e6 * A_S / BETA, rel=1e-9)
    assert r.results["breaking_load"] is None
    assert "bolt_break" not in {c.name for c in r.checks}


def test_the_law_is_elastic_then_flat() -> None:
    angle = np.linspace(0.0, 1.0, 11)
    t = bolt_joint_torque(T0 + K * angle, PER * F_Y)
    assert t[0] == T0 and t[-1] == pytest.approx(PER * F_Y, rel=1e-15)
    assert np.all(np.diff(t) >= 0.0) and np.all(t <= PER * F_Y)


@pytest.mark.parametrize("rung", ["rigid", "energy"])
def test_the_array_path_gives_each_points_own_verdict(rung: str) -> None:
    e_y = _yield_energy(K300)
    energies = np.array([0.5 * e_y, 1.01 * e_y, 438.65])
    base = {k: v for k, v in REVIEW.items() if k != "tool_energy"}
    base["target_torque"], base["max_blows"] = 300.0, 1
    outputs = ["final_preload", "yield_preload", "breaking_load"]
    chunk = evaluate_chunk(BLOW, base, {"tool_energy": energies}, outputs, rung)
    for j, e in enumerate(energies):
        single = run(BLOW, {**base, "tool_energy": float(e)}, fidelity=rung)
        for name in outputs:
            assert chunk.values[name][j] == pytest.approx(single.results[name], rel=1e-12)
        ok = {c.name: c.ok for c in single.checks}
        for name in ("bolt_yield", "bolt_break"):
            assert chunk.checks[name][j] == (CHECK_OK if ok[name] else CHECK_FAILED)
        want = ["elastic", "past yield", "past breaking"][j]
        assert single.results["bolt_verdict"] == want or rung == "rigid"
