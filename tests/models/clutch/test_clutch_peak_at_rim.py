"""A helical characteristic that peaks at the rim, told without the lift grid.

:func:`engine.physics.clutch.rim_torque_slope` ≤ 0 says the torque falls from the rim on
(its notes prove one maximum at most over the rim). Held here against the grid itself:
the peak's place on a 401-point grid, the outputs the 41-point grid gives, and the
estimate the band's peaks give, over seeded random designs of bench/accuracy_clutch.py.
"""

import math
from typing import Any

import numpy as np
import pytest

import engine
from bench.accuracy_clutch import draw
from engine.core.errors import EngineError
from engine.models import clutch as model
from engine.models.clutch import BALL_CLUTCH
from engine.physics.clutch import rim_torque_slope
from engine.procedures import clutch_asbuilt as asbuilt

DEG = math.pi / 180


def _designs(n: int, seed: int) -> list[dict[str, Any]]:
    rng = np.random.default_rng(seed)
    out: list[dict[str, Any]] = []
    i = 0
    while len(out) < n:
        d = draw(rng, i)
        if i % 3 == 0:
            d["face_friction"] = 0.01  # the residual torque too
        if i % 4 == 1:  # a short setting and lift: a peak beyond the rim
            d["ball_lift"] = 0.02 * d["ball_diameter"]
            d["spring_deflection"] = 0.01 * d["ball_diameter"]
        i += 1
        try:
            engine.run(BALL_CLUTCH, d, fidelity="closed_form")
        except EngineError:
            continue
        out.append(BALL_CLUTCH.validate(d)[0])
    return out


DESIGNS = _designs(120, seed=7)


def test_slope_by_hand_with_friction_and_a_pressure_disc() -> None:
    # α = 40°, f = 0.1 (ρ = 5.711°), α′ = 50° under a pressure disc: p = tan 34.289° +
    # tan 44.289° = 0.68188 + 0.97550 = 1.65738; cos²(34.289°) = 0.68261;
    # (d/2) cos α / s_h = 0.004 · 0.76604 / 0.003 = 1.02139: rising, 0.13749
    rho = math.atan(0.1)
    p = math.tan(40 * DEG - rho) + math.tan(50 * DEG - rho)
    hand = 0.004 * math.cos(40 * DEG) / 0.003 - 1 / (p * math.cos(40 * DEG - rho) ** 2)
    assert hand == pytest.approx(1.02139 - 1 / (1.65738 * 0.68261), abs=2e-5)
    assert hand == pytest.approx(0.13749, abs=1e-5)
    assert rim_torque_slope(0.003, 0.008, 40 * DEG, 0.1, p) == pytest.approx(hand, rel=1e-14)


def test_the_slope_tells_where_the_fine_grid_peaks() -> None:
    at_rim = beyond = 0
    for x in DESIGNS:
        spring = asbuilt.Spring(x)
        curve = asbuilt.characteristic(x, spring, curves=True, points=4001)
        torque, lift = curve["_torque"], curve["_lift"]
        rim = 4000  # the flank's last point: the ball at the rim
        assert float(lift[rim]) == pytest.approx(float(asbuilt.lift_of(x)), rel=1e-15)
        peak = int(np.argmax(torque))
        assert peak >= rim  # along the flank the torque rises with the spring force
        # the slope against the curve's own: ln T over the first rim step in β
        ride = float(asbuilt._ride(x))
        step = (math.pi / 2 - ride) / 4000
        own = (math.log(torque[rim + 1]) - math.log(torque[rim])) / step
        f = x["flank_friction"]
        push = engine.physics.clutch.combined_push_factor(
            ride, f, x["driving_groove_angle"], x["flank_construction"]
        )
        slope = rim_torque_slope(
            x["spring_deflection"] + asbuilt.lift_of(x), x["ball_diameter"], ride, f, push
        )
        assert own == pytest.approx(slope, abs=0.05 * max(1.0, abs(float(slope))))
        if bool(asbuilt.peak_at_rim(x)):
            at_rim += 1
            assert peak == rim
        elif slope > 0.1:
            beyond += 1
            assert peak > rim
        # one maximum at most over the rim: the torque rises, then falls
        steps = np.sign(np.diff(torque[rim:]))
        steps = steps[steps != 0]
        assert np.count_nonzero(np.diff(steps) != 0) <= 1
    assert at_rim > 50 and beyond > 5  # both kinds drawn


def test_the_rim_values_are_the_grid_s() -> None:
    shortcut = 0
    for x in DESIGNS:
        spring = asbuilt.Spring(x)
        grid = asbuilt.characteristic(x, spring, curves=True)  # the curves: never the shortcut
        fast = asbuilt.characteristic(x, spring)
        shortcut += bool(asbuilt.peak_at_rim(x))
        for key, value in fast.items():
            assert float(value) == pytest.approx(float(grid[key]), rel=1e-14), key
        assert set(fast) == {k for k in grid if not k.startswith("_")}
    assert shortcut > 50


def test_a_swept_input_gives_each_point_s_values() -> None:
    x = DESIGNS[0]
    spring = asbuilt.Spring(x)
    deflections = np.linspace(0.5, 1.5, 5) * x["spring_deflection"]
    many = asbuilt.characteristic({**x, "spring_deflection": deflections}, spring)
    for j, delta in enumerate(deflections):
        one = asbuilt.characteristic({**x, "spring_deflection": float(delta)}, spring)
        for key, value in one.items():
            assert np.shape(many[key]) in ((5,), ()), key
            assert float(np.broadcast_to(many[key], (5,))[j]) == pytest.approx(
                float(value), rel=1e-14
            ), key


def test_the_estimate_is_the_band_peaks_where_it_is_skipped_too() -> None:
    # where every band friction peaks at the rim the estimate skips the peak's grids:
    # it must be what they would give (the zero-lift shift), elsewhere their shift
    for x in DESIGNS:
        estimate = model._estimate_ball(x)
        if estimate is None:
            continue
        low, high = model._friction_band(x["flank_friction"])
        with np.errstate(all="ignore"):
            peak = float(asbuilt.peak_friction_shift(x, low.item(), high.item()))
        zero_lift = model._estimate(x)
        assert estimate == pytest.approx(max(zero_lift, peak), rel=1e-12)


def test_a_stiff_spring_s_estimate_takes_the_peak_beyond_the_rim() -> None:
    # 0.3 mm of setting with a 0.2 mm lift: the torque still rises over the rim, and at
    # f' = 0.1 (the band of f = 0) more than at zero lift
    x = {**BALL_CLUTCH.examples[0], "spring_deflection": 0.0003, "ball_lift": 0.0002}
    values, _ = BALL_CLUTCH.validate(x)
    assert not bool(asbuilt.peak_at_rim(values))
    r = engine.run(BALL_CLUTCH, x, fidelity="closed_form")
    assert r.error_estimate is not None
    zero_lift = 1 / math.tan(45 * DEG - math.atan(0.1)) - 1  # p(0)/p(0.1) − 1 = 0.2222
    assert zero_lift == pytest.approx(0.2222222, rel=1e-6)
    assert float(r.results["lift_at_peak"]) > 0.0008  # type: ignore[arg-type]
    assert r.error_estimate > zero_lift * 1.01
    assert r.error_estimate == pytest.approx(
        float(asbuilt.peak_friction_shift(values, 0.0, 0.1)), rel=1e-12
    )
