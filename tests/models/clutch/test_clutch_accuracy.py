"""The ball clutch's error estimates are bounds: bench/accuracy_clutch.py over 200 seeded
random designs in the declared ranges, against its independent reference (the ball's
equilibrium, the spring force by hand, a 500× finer lift grid, the whole friction band).
"""

import math

import pytest

import engine
from bench import accuracy_clutch
from engine.models.clutch import BALL_CLUTCH


@pytest.mark.slow
def test_no_design_exceeds_the_stated_bound():
    rows = accuracy_clutch.rows(200, seed=0)
    assert {(r["model"], r["output"]) for r in rows} == set(accuracy_clutch.OUTPUTS)
    for row in rows:
        assert row["kind"] == "bound"
        assert row["n"] == 200 and row["skipped"] == 0, row
        assert row["exceeded"] == 0, row
        # tight: the band's end is where the estimate is taken
        assert 0.999 < row["worst_ratio"] <= 1 + 1e-9, row


def test_the_reference_is_the_engine_s_closed_form_at_the_band_ends():
    # one design by hand: the paper's clutch with f = 0.1, band 0.07…0.13; the torque
    # D0 F/(2 tan(45° − atan f)) at each end, the estimate the larger relative shift
    x = {**BALL_CLUTCH.examples[0], "flank_friction": 0.1, "flank_construction": "free_ball"}
    f_spring = 8e10 * 0.004**4 * 0.004 / (8 * 0.045**3 * 5)
    t = [0.05 * f_spring / (2 * math.tan(math.pi / 4 - math.atan(f))) for f in (0.07, 0.1, 0.13)]
    refs = [accuracy_clutch.reference(x, f)["torque_limit"] for f in (0.07, 0.1, 0.13)]
    assert refs == pytest.approx(t, rel=1e-13)
    r = engine.run(BALL_CLUTCH, x)
    zero_lift = max(t[2] / t[1] - 1, t[1] / t[0] - 1)
    assert r.results["torque_limit"] == pytest.approx(t[1], rel=1e-13)
    # the peak (at the rim, f_spring doubled) shifts by the same ratio: the estimate
    assert r.error_estimate == pytest.approx(zero_lift, rel=1e-9)
    # tan(45° − atan f) = 0.86916, 0.81818, 0.76991 at f = 0.07, 0.1, 0.13: 6.27 % up
    assert r.error_estimate == pytest.approx(0.81818 / 0.76991 - 1, abs=5e-5)
