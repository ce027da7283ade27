"""Stage 3 with one-sided roller contacts: a face that would have to pull lets the rollers go.

Held on both cones as an equality, the rollers can pull: in the design below the striker
"returns" in 0.667 ms (the two-degree-of-freedom model before this change) where on its
own it needs 3.568 ms. Here the reference is the same stage written out from the
equations (symmetric V, t = tan α, the n rollers as one body n·mp) and integrated piece
by piece with scipy's solve_ivp and its events:

1. at the blow (all at rest, y_h = h2 − h1, y_s = h2) face A would have to pull
   (the two-degree-of-freedom face forces of test_rare_impact_stop), so the rollers ride
   face B with the half-coupling, x − x0 = X, y_r = y_h + t·X:
   T = ½m1·ẏh² + ½n·mp(Ẋ² + (ẏh + t·Ẋ)²),
   Q = (c1(λ1 − y_h) + (m1 + n·mp)g, n·mp·g·t),
   and the striker is alone, m3·ÿs = m3·g − c3(λ3 + ys);
2. the half-coupling reaches its stop y_h = 0 (plastic): it stops, the rollers keep their
   velocity (a face only pushes) and fly free, X = X_s + Ẋ·τ, y_r = Y_s + Ẏ·τ + ½g·τ²;
3. the striker comes home (y_s = 0) without meeting them again.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from engine.models.rare_impact import REFERENCE_DESIGN
from engine.procedures.striker_cycle import simulate_cycle
from tests.models.rare_impact.test_rare_impact_stop import _face_forces

#: The design of a seeded random draw (each input ×4^U(−1, 1) about the reference) where
#: the equality contact pulled hardest; c3 < c1, like every such design of the review.
WORST = {
    **REFERENCE_DESIGN,
    "flywheel_inertia": 0.068, "motor_torque": 2.17, "roller_mass": 0.0925, "roller_count": 7,
    "roller_radius": 0.0345, "cone_angle": 1.2545, "half_coupling_mass": 0.062,
    "stepped_shaft_mass": 0.176, "striker_mass": 0.2, "power_spring_rate": 129000.0,
    "auxiliary_spring_rate": 596.0, "return_spring_rate": 22140.0,
    "power_spring_preload": 0.00146, "auxiliary_spring_preload": 0.01676,
    "return_spring_preload": 0.000623, "release_travel": 0.0195, "engagement_height": 0.00116,
    "jaw_height": 0.0014, "engagement_angle": 0.667, "roller_friction": 0.174, "gravity": -7.87,
}  # fmt: skip
OPTS: dict[str, Any] = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-16}


def _event(fn: Any, direction: float) -> Any:
    fn.terminal, fn.direction = True, direction
    return fn


def _one_sided_return(x: dict[str, Any]) -> float:
    """Time from the blow until the striker is home, by the three pieces of the module notes."""
    t_a = math.tan(x["cone_angle"])
    nm = x["roller_count"] * x["roller_mass"]
    m1, m3, g = x["half_coupling_mass"], x["striker_mass"], x["gravity"]
    c1, l1 = x["power_spring_rate"], x["power_spring_preload"]
    c3, l3 = x["return_spring_rate"], x["return_spring_preload"]
    h1, h2 = x["release_travel"], x["engagement_height"]
    mass = np.array([[m1 + nm, nm * t_a], [nm * t_a, nm * (1.0 + t_a * t_a)]])

    def piece1(t: float, s: np.ndarray) -> np.ndarray:
        yh, _, ys, vh, vx, vs = s
        q = np.array([c1 * (l1 - yh) + (m1 + nm) * g, nm * g * t_a])
        ah, ax = np.linalg.solve(mass, q)
        return np.array([vh, vx, vs, ah, ax, g - c3 * (l3 + ys) / m3])

    def face_b(t: float, s: np.ndarray) -> float:  # n·mp(ÿr − g), ÿr = ÿh + t·Ẍ
        d = piece1(t, s)
        return float(d[3] + t_a * d[4] - g)

    def gap_a(t: float, s: np.ndarray) -> float:  # y_s − y_r − t·X with y_r = y_h + t·X
        return float(s[2] - s[0] - 2.0 * t_a * s[1])

    stop = _event(lambda t, s: s[0], 1.0)
    home = _event(lambda t, s: s[2], -1.0)
    start = [h2 - h1, h1 / (2.0 * t_a), h2, 0.0, 0.0, 0.0]
    events = [stop, home, _event(face_b, -1.0), _event(gap_a, -1.0)]
    r1 = solve_ivp(piece1, (0.0, 1.0), start, events=events, **OPTS)
    assert len(r1.t_events[0]) == 1, "the half-coupling reaches its stop first"
    assert not any(len(e) for e in r1.t_events[1:]), "face B pushes, face A stays open"
    t_s = float(r1.t_events[0][0])
    yh, xx, ys, vh, vx, vs = r1.y_events[0][0]
    assert c1 * l1 + m1 * g > 0.0  # the power spring holds the half-coupling on its stop
    yr, vr = yh + t_a * xx, vh + t_a * vx
    assert vr - t_a * vx > 0.0  # face B stops, the rollers go on: that gap opens

    def piece2(t: float, s: np.ndarray) -> list[float]:
        return [s[1], g - c3 * (l3 + s[0]) / m3]

    def roller(t: float) -> tuple[float, float]:
        return xx + vx * (t - t_s), yr + vr * (t - t_s) + 0.5 * g * (t - t_s) ** 2

    def gap_a2(t: float, s: np.ndarray) -> float:
        xr, y = roller(t)
        return float(s[0] - y - t_a * xr)

    def gap_b2(t: float, s: np.ndarray) -> float:
        xr, y = roller(t)
        return float(y - t_a * xr)

    home2 = _event(lambda t, s: s[0], -1.0)
    r2 = solve_ivp(
        piece2, (t_s, 1.0), [ys, vs], events=[home2, _event(gap_a2, -1.0),
                                               _event(gap_b2, -1.0)], **OPTS
    )  # fmt: skip
    assert not len(r2.t_events[1]) and not len(r2.t_events[2]), "no face meets the rollers"
    return float(r2.t_events[0][0])


def test_the_worst_design_returns_as_the_striker_alone() -> None:
    x = WORST
    na, nb = _face_forces(x, x["engagement_height"] - x["release_travel"], x["engagement_height"])
    assert na < 0.0 < nb  # held as an equality, face A would pull at once
    t_ref = _one_sided_return(x)
    # the striker is alone all along: from h2 at rest about its balance c = (m3·g − c3·λ3)/c3,
    # home where cos(ωt) = −c/(h2 − c), ω = √(c3/m3)
    c = x["striker_mass"] * x["gravity"] - x["return_spring_rate"] * x["return_spring_preload"]
    c /= x["return_spring_rate"]
    w = math.sqrt(x["return_spring_rate"] / x["striker_mass"])
    t_alone = math.acos(-c / (x["engagement_height"] - c)) / w
    assert t_ref == pytest.approx(t_alone, rel=1e-10)
    assert t_ref == pytest.approx(3.5679e-3, rel=1e-4)
    o = simulate_cycle(x)
    assert o.home_time == pytest.approx(t_ref, rel=1e-8)
    assert o.return_time == o.home_time  # the jaws (1.4 mm) are higher than h2 (1.16 mm)
    assert any(
        n.startswith("stage 3: 0 ms after the blow face A would have to pull") for n in o.notes
    )


#: Return and home times of designs whose roller contacts push throughout stage 3, as the
#: two-degree-of-freedom model gave them before the one-sided contacts (to the last bits).
UNCHANGED = [
    ({"gravity": 0.0}, 0.0036765537111647095, 0.003965570744425273),
    ({"roller_geometry": "single_cone"}, 0.005207337396352818, 0.005584742374091234),
    ({"roller_geometry": "paper"}, 0.005207337396352818, 0.005584742374091234),
    ({"gravity": -9.80665}, 0.0036419773785001386, 0.003927510372690124),
    ({"cone_angle": math.pi / 6}, 0.004303817742913552, 0.004623010102559499),
]


@pytest.mark.parametrize(("change", "t_ret", "t_home"), UNCHANGED)
def test_designs_whose_contacts_push_are_unchanged(
    change: dict[str, Any], t_ret: float, t_home: float
) -> None:
    o = simulate_cycle({**REFERENCE_DESIGN, **change})
    assert not any(n.startswith("stage 3:") for n in o.notes)
    assert o.return_time == pytest.approx(t_ret, rel=1e-12, abs=0.0)
    assert o.home_time == pytest.approx(t_home, rel=1e-12, abs=0.0)
