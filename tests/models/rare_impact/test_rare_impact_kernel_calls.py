"""The Python around the cycle's kernels: kept event arrays, contact masks, loaded kernels."""

import dataclasses
import math

import numpy as np

from engine.models.rare_impact import REFERENCE_DESIGN as R
from engine.procedures import striker_cycle as C


def test_contact_masks_are_the_bits_of_their_index():
    assert [m.tolist() for m in C._ACTIVE[:4]] == [
        [False, False, False, False],
        [True, False, False, False],
        [False, True, False, False],
        [True, True, False, False],
    ]
    assert C._ACTIVE[0b1101].tolist() == [True, False, True, True]
    assert all(m.dtype == np.bool_ for m in C._ACTIVE)


def test_the_one_sided_return_leaves_the_shared_masks_alone():
    before = [m.copy() for m in C._ACTIVE]
    o = C.simulate_cycle({**R, "roller_geometry": "symmetric_v"})
    assert any("one-sided" in n for n in o.notes)  # the reference design lets a face go
    assert all((a == b).all() for a, b in zip(before, C._ACTIVE, strict=True))
    assert C._kernels_loaded()
    assert C._ensure_compiled(np.zeros(C.NPAR)) == 0.0


class _ShortChunks(C._Run):
    """The driver's own text run by Python with chunks of 50 steps: it comes back after every
    chunk and is called again (the clock's looks of a long stage)."""

    def driver(self):  # type: ignore[no-untyped-def]
        return C._stages_in_python(_CHUNK=50)


def test_the_driver_goes_on_where_it_stopped(monkeypatch):
    # stage 1's thousands of steps in chunks of 50, then stages 2 to 4 and the one-sided stage
    # 3 with its catches: the same outcome bit for bit (a series keeps every stride-th step
    # of a chunk, so its points follow the chunks, as they did)
    x = {**R, "roller_geometry": "symmetric_v"}
    whole = C.simulate_cycle(x)
    recorded = C.simulate_cycle(x, record=True)
    monkeypatch.setattr(C, "_Run_impl", _ShortChunks)
    assert C.simulate_cycle(x) == whole
    chunked = C.simulate_cycle(x, record=True)
    assert chunked.series["stage"][-1] == 4.0 and set(chunked.series["stage"]) == {1, 2, 3, 4}
    assert dataclasses.replace(chunked, series={}) == dataclasses.replace(recorded, series={})
    assert any("one-sided" in n for n in chunked.notes)


def test_the_refusal_of_a_motor_too_slow_names_the_field_whatever_the_motor():
    """A linear motor's refusal names its no-load speed; a motor of constant torque has none,
    and its refusal (a time to speed beyond the floats) names its torque instead of failing
    on the missing input."""
    w = 100.0 * math.pi / 30  # 100 rpm
    linear = C._never_fast_enough({"motor_no_load_speed": 50.0 * math.pi / 30}, w)
    assert linear.field == "motor_no_load_speed"
    assert "no-load speed 50 rpm is not above the release speed 100 rpm" in str(linear)
    constant = C._never_fast_enough({"motor_torque": 1.0}, w)
    assert constant.field == "motor_torque"
    assert "does not reach the release speed 100 rpm in a finite time" in str(constant)


def test_a_shaft_whose_period_rounds_to_zero_is_refused_not_said_to_stay():
    """stepped_shaft_mass has an exclusive minimum of 0: 5e-324 kg passes, and stage 4's
    period 2π·sqrt(m2/c2) rounds to 0. The auxiliary spring does beat the friction (26 N
    against 10.9 N), so the stage has no step count and the design is refused; it must not
    be answered as a shaft the spring does not push back (relock_time inf, 'no re-lock')."""
    import pytest

    from engine import run
    from engine.core.errors import SolverFailed
    from engine.models.rare_impact import RARE_IMPACT

    x = {**R, "roller_geometry": "symmetric_v", "stepped_shaft_mass": 5e-324}
    with pytest.raises(ZeroDivisionError):  # as the count at stage 4's start raised
        C.simulate_cycle(x)
    with pytest.raises(SolverFailed, match="arithmetic"):  # the runner's refusal of it
        run(RARE_IMPACT, x, fidelity="simulation", budget_s=None)
    light = C.simulate_cycle({**x, "stepped_shaft_mass": 1e-300})  # a period of 1e-150 s
    assert light.relock_time == 0.0 and not light.warnings
