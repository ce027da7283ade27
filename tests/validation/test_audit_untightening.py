"""joint.audit's breakaway read at once against a published figure [BoltScience].

Bolt Science, *Untightening of nuts & bolts*: untightened immediately after tightening, a
nut usually needs "about 20 % less" torque than it was tightened with, because the part of
the torque that stretched the bolt acts in the untightening direction. The model's breakaway
at once with no static excess (r = 1) is M_A (−0.16 P + k_μ)/(0.16 P + k_μ): for an M12 at
μ = 0.14…0.16 (a common range for oiled steel) 22…25 % less. A sign error in the pitch term
would give 0 % (or more torque than tightening).
"""

from __future__ import annotations

import pytest

from engine import run
from engine.models.audit import AUDIT, M12_AT_80


@pytest.mark.parametrize("mu", [0.14, 0.15, 0.16])
def test_untightening_at_once_needs_about_a_fifth_less(mu: float) -> None:
    inputs = {
        **M12_AT_80,
        "torque_tolerance": 0.0,
        "thread_friction_min": mu,
        "thread_friction_max": mu,
        "bearing_friction_min": mu,
        "bearing_friction_max": mu,
        "static_friction_ratio_max": 1.0,
    }
    v = run(AUDIT, inputs).results
    assert v["breakaway_min"] == pytest.approx(v["breakaway_max"], rel=1e-12)
    less = 1.0 - v["breakaway_min"] / 80.0
    assert less == pytest.approx(0.20, abs=0.06), less
    # the mark and the first motion at r = 1 read the tightening torque itself
    assert v["mark_min"] == pytest.approx(80.0, rel=1e-12)
    assert v["first_motion_max"] == pytest.approx(80.0, rel=1e-12)
