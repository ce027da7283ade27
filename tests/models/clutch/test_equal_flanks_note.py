"""A free ball between two flanks of the same angle: the note states the rolling ball's limit.

With α′ = α = 45° the ball touches the flanks at opposite points; its moment balance admits
no friction there, so a rolling ball pushes with tan α: T_roll/T = tan(α − ρ)/tan α. With
f = 0.1 (ρ = 5.7106°): tan(39.2894°)/tan(45°) = 0.81818, 18.2 % below the model's limit.
"""

import math

from engine import run
from engine.models import get_model

BALL = get_model("clutch.ball")


def test_equal_flanks_with_friction_state_the_rolling_limit() -> None:
    x = {**BALL.examples[0], "driving_groove_angle": math.radians(45.0), "flank_friction": 0.1}
    rolling = math.tan(math.radians(45.0) - math.atan(0.1)) / math.tan(math.radians(45.0))
    assert abs(rolling - 0.81818) < 1e-5
    r = run(BALL, x)
    (note,) = [n for n in r.notes if "inclined alike" in n]
    assert f"{1.0 - rolling:.1%} below" in note  # 18.2 % below


def test_unequal_flanks_or_no_friction_say_nothing_of_it() -> None:
    base = BALL.examples[0]
    for extra in (
        {"driving_groove_angle": math.radians(20.0), "flank_friction": 0.1},
        {"driving_groove_angle": math.radians(45.0), "flank_friction": 0.0},
        {"flank_friction": 0.1},
    ):
        r = run(BALL, {**base, **extra})
        assert not [n for n in r.notes if "inclined alike" in n], extra
