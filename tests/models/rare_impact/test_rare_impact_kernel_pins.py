"""The simulation's times pinned to 1e-12 across a change of its compiled kernels.

Taken from the kernels before their events' Newton refinement moved into
:func:`engine.numerics.ode.newton_fraction` (both the cycle kernel and the one-sided
stage 3 call it since): the same floats then, as the refactoring was to keep them. The
designs: the reference in each roller geometry (the symmetric V's rollers leave face B
near home: the one-sided stage 3 runs), the contact test's worst design (it flies at the
blow) and a seeded random one of bench/accuracy_striker.py where face B lets go 1.32 ms
after the blow (level events of both kernels, reaction events of the one-sided one).
"""

from __future__ import annotations

from typing import Any

import pytest

from engine.models.rare_impact import REFERENCE_DESIGN
from engine.numerics.ode import newton_fraction
from engine.procedures.striker_cycle import simulate_cycle
from tests.models.rare_impact.test_rare_impact_contact import WORST

FIELDS = ("release_speed", "spin_up_time", "engagement_time", "return_time", "home_time")
#: bench/accuracy_striker.designs(150, 11)[32]
RANDOM = {
    **REFERENCE_DESIGN,
    "flywheel_inertia": 0.014070850588981911, "motor_torque": 13.978703979206701,
    "roller_mass": 0.14091164908479964, "roller_count": 8, "roller_radius": 0.0183070332655461,
    "cone_angle": 0.9246679761542134, "half_coupling_mass": 0.08011848262526232,
    "stepped_shaft_mass": 0.08610448294990974, "striker_mass": 0.23359982549865227,
    "power_spring_rate": 176685.70315419222, "auxiliary_spring_rate": 1375.8555959061825,
    "return_spring_rate": 98445.24304137353, "power_spring_preload": 0.003553326145613497,
    "auxiliary_spring_preload": 0.003616476719815316,
    "return_spring_preload": 0.005793003076316256, "release_travel": 0.003109794498187995,
    "engagement_height": 0.0013568838925974648, "jaw_height": 0.0010055552689540671,
    "engagement_angle": 1.8325573900605245, "roller_friction": 0.09012737039838495,
    "gravity": 6.708326281761687,
}  # fmt: skip
CASES: list[tuple[dict[str, Any], tuple[float, ...], int]] = [
    (
        {**REFERENCE_DESIGN, "roller_geometry": "symmetric_v"},
        (244.12351025025174, 1.0029509264240932, 0.006558220350671329,
         0.0037121449303971765, 0.004004776770983209),
        5542,
    ),
    (
        {**REFERENCE_DESIGN, "roller_geometry": "single_cone"},
        (166.9556695453968, 0.6881077920313045, 0.006546104550153364,
         0.005207337396352818, 0.005584742374091234),
        3640,
    ),
    (
        {**REFERENCE_DESIGN, "roller_geometry": "paper"},
        (235.98619340551463, 0.9439447736220501, 0.006548842941377475,
         0.005207337396352818, 0.005584742374091234),
        4940,
    ),
    (
        WORST,
        (825.4229581465478, 26.215679206839937, 0.0008922419420436256,
         0.0035678853368992236, 0.0035678853368992236),
        336469,
    ),
    (
        RANDOM,
        (379.71013259164727, 0.39383251721180734, 0.002683505726297053,
         0.001209195540776642, 0.001444096225162561),
        1818,
    ),
]  # fmt: skip


@pytest.mark.parametrize(("x", "times", "steps"), CASES)
def test_the_simulation_keeps_its_times(
    x: dict[str, Any], times: tuple[float, ...], steps: int
) -> None:
    o = simulate_cycle(x)
    assert [getattr(o, f) for f in FIELDS] == pytest.approx(list(times), rel=1e-12)
    assert o.steps == steps


def test_the_one_sided_stage_3_ran_where_pinned() -> None:
    for x in (CASES[0][0], WORST, RANDOM):
        assert any("would have to pull" in n for n in simulate_cycle(x).notes)


def test_newton_fraction_refuses_a_step_out_of_the_step() -> None:
    # z(s) = s − 1.01 (rate 1, h = 1): from 0.99 the root is past the step's end; from
    # 0.01 with z = s + 0.01 it is before its start: s kept, the refinement stops
    assert newton_fraction(0.99, -0.02, 1.0, 1.0) == (0.99, False)
    assert newton_fraction(0.01, 0.02, 1.0, 1.0) == (0.01, False)
    # an update of exactly 0.05 of the step is taken; a rate of 2 per step halves it
    assert newton_fraction(0.5, -0.05, 1.0, 1.0) == pytest.approx((0.55, True))
    assert newton_fraction(0.5, -0.05, 2.0, 1.0) == pytest.approx((0.525, True))
    assert newton_fraction(0.5, -0.05, 1.0, 2.0) == pytest.approx((0.525, True))
    # below 1e-15 the update is taken and the refinement stops
    assert newton_fraction(0.5, 5e-16, 1.0, 1.0) == (0.5 - 5e-16, False)
