"""Validation against [001] (docs/sources.md): Malashchenko, Semenyuk, Lysiak,
"Parameters of double action ball overturn coupling".

The paper's worked case: D0 = 50 mm, i = 4, d = 10 mm, d0 = 0.5…4 mm, Δ = 4…10 mm,
D = 45 mm, i_p = 5, α = 45°, G = 8·10⁴ MPa. Its figures 4 and 5 plot the spring force
and the clutch torque against d0 for several Δ. In the scan the figures survive only as
axis ticks (d0 = 0, 0.5 … 3.5 mm; "T, N·m"): no curve value is legible, so the curves are
checked against the paper's own equations evaluated here independently (eq. 2 and the
result after eq. 3), through the sweep endpoint a user would call.
"""

import math

import pytest

from tests.apps import real_client


def app():
    """The real app's client, built once per test process when a test first asks for it."""
    return real_client(raise_server_exceptions=False)


G, D, IP, D0, NB, KR = 8e10, 0.045, 5.0, 0.05, 4, 0.85
ALPHA = math.radians(45.0)
PAPER = {
    "ball_circle_diameter": "50 mm",
    "ball_count": NB,
    "ball_diameter": "10 mm",
    "groove_angle": "45 deg",
    "spring_wire_diameter": "4 mm",
    "spring_mean_diameter": "45 mm",
    "spring_active_coils": IP,
    "spring_deflection": "4 mm",
    "shear_modulus": "8e4 MPa",
    "load_factor": KR,
}
WIRES_MM = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]


def paper_spring_force(d0, delta):
    """[001, eq. 2]: F = G d0⁴ Δ / (8 D³ i_p)."""
    return G * d0**4 * delta / (8 * D**3 * IP)


def paper_torque(d0, delta):
    """[001, after eq. 3], with K_r multiplying as eq. 1 requires."""
    return KR * D0 * NB * G * d0**4 * delta / (16 * D**3 * IP * math.tan(ALPHA))


def sweep(delta_mm, arrangement):
    r = app().post(
        "/api/v1/clutch/ball/sweep",
        json={
            "base": {
                **PAPER,
                "spring_deflection": f"{delta_mm} mm",
                "spring_arrangement": arrangement,
            },
            "vary": "spring_wire_diameter",
            "start": "0.5 mm",
            "stop": "4 mm",
            "num": len(WIRES_MM),
            "outputs": ["spring_force", "torque_limit"],
        },
    )
    assert r.status_code == 200, r.text
    return r.json()


def test_worked_case_single_point():
    r = app().post("/api/v1/clutch/ball", json=PAPER)
    assert r.status_code == 200, r.text
    res = r.json()["results"]
    # eq. 2: 8e10·(4e-3)⁴·4e-3/(8·0.045³·5) = 0.08192/3.645e-3 = 22.474623 N
    assert res["spring_force"] == pytest.approx(22.474623, rel=1e-7)
    # common spring (fig. 1): 0.05·22.474623/2 = 0.5618656 N·m
    assert res["torque_limit"] == pytest.approx(0.5618656, rel=1e-6)
    per_ball = app().post("/api/v1/clutch/ball", json={**PAPER, "spring_arrangement": "per_ball"})
    # the paper's formula: 3.4 × 0.5618656 = 1.9103429 N·m
    assert per_ball.json()["results"]["torque_limit"] == pytest.approx(
        paper_torque(4e-3, 4e-3), rel=1e-12
    )
    assert paper_torque(4e-3, 4e-3) == pytest.approx(1.9103429, rel=1e-7)


@pytest.mark.parametrize("delta_mm", [4, 6, 8, 10])
def test_figure_4_spring_force_against_wire_diameter(delta_mm):
    body = sweep(delta_mm, "common")
    assert body["values"] == pytest.approx([w * 1e-3 for w in WIRES_MM], rel=1e-12)
    got = body["results"]["spring_force"]
    want = [paper_spring_force(w * 1e-3, delta_mm * 1e-3) for w in WIRES_MM]
    assert got == pytest.approx(want, rel=1e-12)
    # the figure's shape: a quartic in d0, 2⁴ = 16 times from 2 mm to 4 mm
    assert got[-1] / got[3] == pytest.approx(16.0, rel=1e-12)
    # end values: Δ = 4 mm -> 22.47 N at 4 mm wire, 0.0055 N at 0.5 mm
    assert got[-1] == pytest.approx(22.474623 * delta_mm / 4, rel=1e-7)
    assert got[0] == pytest.approx(22.474623 * delta_mm / 4 / 4096, rel=1e-7)


@pytest.mark.parametrize("delta_mm", [4, 6, 8, 10])
def test_figure_5_torque_against_wire_diameter(delta_mm):
    per_ball = sweep(delta_mm, "per_ball")["results"]["torque_limit"]
    want = [paper_torque(w * 1e-3, delta_mm * 1e-3) for w in WIRES_MM]
    assert per_ball == pytest.approx(want, rel=1e-12)
    # Δ = 10 mm, d0 = 4 mm: 1.9103429 · 10/4 = 4.7758573 N·m (the top of fig. 5 by eq. 3)
    assert per_ball[-1] == pytest.approx(1.9103429 * delta_mm / 4, rel=1e-7)
    # the clutch the paper draws (one spring): K_r i = 3.4 times less
    common = sweep(delta_mm, "common")["results"]["torque_limit"]
    assert [p / c for p, c in zip(per_ball, common, strict=True)] == pytest.approx(
        [KR * NB] * len(WIRES_MM), rel=1e-12
    )
    # the formula as printed (K_r dividing) would be 1/K_r² = 1.384 times the per-ball curve
    printed = D0 * NB * G * (4e-3) ** 4 * delta_mm * 1e-3 / (16 * KR * D**3 * IP)
    assert printed / per_ball[-1] == pytest.approx(1 / KR**2, rel=1e-12)


def test_worked_case_stress_at_the_peak_force():
    """[001]'s Δ is both the nut setting and the groove depth: climbing out, the ball
    compresses the spring by another Δ, so the spring reaches c(Δ + Δ) = 44.95 N at the
    peak torque and the wire stress doubles, 45.38 → 90.77 MPa (Wahl-corrected); rolling
    over the rim adds (d/2)(1 − sin 45°) = 1.46 mm more, 107.4 MPa on the face."""
    r = app().post("/api/v1/clutch/ball", json={**PAPER, "series": True})
    assert r.status_code == 200, r.text
    body = r.json()
    res = body["results"]
    assert res["spring_shear_stress"] == pytest.approx(45.3849e6, rel=1e-5)
    assert res["spring_force_at_peak"] == pytest.approx(2 * paper_spring_force(4e-3, 4e-3))
    assert res["spring_stress_at_peak"] == pytest.approx(90.7698e6, rel=1e-5)
    assert res["spring_stress_max"] == pytest.approx(107.386e6, rel=1e-5)
    assert res["peak_torque"] == pytest.approx(2 * 0.5618656, rel=1e-6)
    # the characteristic is in the answer for the form's plot: 81 points, seated to face
    series = body["series"]
    assert len(series["lift"]) == len(series["torque_curve"]) == 81
    assert series["torque_curve"][0] == pytest.approx(res["torque_limit"], rel=1e-12)
