"""The compiled-ODE kit (engine/numerics/ode.py): event location and budgets, against hand values.

The compiled functions are the ones the kernels call; each is held to numbers worked out
here (a cubic's own values and roots) and to its pure-Python source.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from engine.numerics.ode import StepCost, first_rise, first_rise_c, hermite, hermite_c, step_budget


def _cubic(t: float) -> tuple[float, float]:
    # z = (t - 0.3)(t - 1.1)(t - 2.5) = t³ - 3.9t² + 3.83t - 0.825, z' = 3t² - 7.8t + 3.83
    return (t - 0.3) * (t - 1.1) * (t - 2.5), 3.0 * t * t - 7.8 * t + 3.83


@pytest.mark.parametrize("fn", [hermite, hermite_c])
def test_hermite_reproduces_a_cubic_from_its_ends(fn) -> None:  # type: ignore[no-untyped-def]
    # over [t0, t0 + h] the interpolant of a cubic is the cubic itself
    t0, h = 0.2, 1.7
    z0, v0 = _cubic(t0)
    z1, v1 = _cubic(t0 + h)
    for s in np.linspace(0.0, 1.0, 11):
        want = (t0 + s * h - 0.3) * (t0 + s * h - 1.1) * (t0 + s * h - 2.5)
        assert fn(s, z0, v0, z1, v1, h) == pytest.approx(want, abs=1e-14)
    # the midpoint by hand: t = 1.05, (0.75)(-0.05)(-1.45) = 0.054375
    assert fn(0.5, z0, v0, z1, v1, h) == pytest.approx(0.054375, abs=1e-14)


@pytest.mark.parametrize("fn", [first_rise, first_rise_c])
def test_first_rise_finds_the_first_upward_root_of_a_cubic(fn) -> None:  # type: ignore[no-untyped-def]
    # from t = 0 (z = -0.825, rising) the cubic crosses 0 upwards first at t = 0.3
    z0, v0 = _cubic(0.0)
    z1, v1 = _cubic(0.5)
    assert fn(z0, v0, z1, v1, 0.5) * 0.5 == pytest.approx(0.3, abs=1e-14)
    # a step over both the up- and down-crossing (0.3 and 1.1) ending below 0: an
    # interior graze the ends do not show; its first root is still t = 0.3
    z1, v1 = _cubic(1.5)
    assert z1 < 0.0
    assert fn(z0, v0, z1, v1, 1.5) * 1.5 == pytest.approx(0.3, abs=1e-14)
    # the same cubic lowered by 0.3 (its maximum 0.2915 at t = 0.6571 stays below 0)
    assert fn(z0 - 0.3, v0, z1 - 0.3, v1, 1.5) == -1.0
    # from just after the down-crossing the next upward root is the third, t = 2.5
    z0, v0 = _cubic(1.2)
    z1, v1 = _cubic(2.6)
    assert 1.2 + fn(z0, v0, z1, v1, 1.4) * 1.4 == pytest.approx(2.5, abs=1e-14)


def test_the_maximum_of_the_graze_is_where_the_derivative_vanishes() -> None:
    # z' = 0 at t = (7.8 - sqrt(7.8² - 12·3.83))/6 = 0.65709..., z there 0.29147...
    t_max = (7.8 - math.sqrt(7.8**2 - 12.0 * 3.83)) / 6.0
    z_max = _cubic(t_max)[0]
    assert (t_max, z_max) == pytest.approx((0.65709, 0.29147), abs=1e-5)
    z0, v0 = _cubic(0.0)
    z1, v1 = _cubic(1.5)
    # just below the top: no crossing; just above: a crossing just left of the top
    assert first_rise_c(z0 - z_max - 1e-9, v0, z1 - z_max - 1e-9, v1, 1.5) == -1.0
    s = first_rise_c(z0 - z_max + 1e-9, v0, z1 - z_max + 1e-9, v1, 1.5)
    assert 0.0 < t_max - s * 1.5 < 1e-3


def test_step_budget_is_the_time_left_over_the_cost_of_a_step() -> None:
    assert step_budget(None, 1234, 1e-6) == 1234
    assert step_budget(time.perf_counter() - 1.0, 10**9, 1e-6) == 0
    # 0.5 of 400 s at 200 µs a step: 1e6 steps, less the time since the call: the 0.1 %
    # allowed is 0.4 s, not the 4 ms of 4 s at 2 µs (one scheduler pause on a loaded machine)
    n = step_budget(time.perf_counter() + 400.0, 0, 2e-4)
    assert 999_000 < n <= 1_000_000
    assert step_budget(time.perf_counter() + 400.0, 0, 2e-4, 0.25) > 0.25 * 400.0 / 2e-4 * 0.999
    assert step_budget(time.perf_counter() + 1.0, 0, 1e-300) == 10**15  # the cap


def test_step_cost_ignores_the_compiling_call_and_caps_a_pause() -> None:
    """The kernel's first call (numba compiling, seconds long) must not shrink later budgets."""
    cost = StepCost()
    cost.measured(20_000, 3.0)  # the first call compiles: not counted
    assert cost.seconds == 1e-6
    cost.measured(20_000, 3.0)  # a 3 s pause over 20,000 steps: capped at 1e-5 s a step
    assert cost.seconds == pytest.approx(0.7e-6 + 0.3 * 1e-5, rel=1e-12)
    cost.measured(20_000, 20_000 * 2e-7)  # an ordinary chunk pulls it back down
    assert cost.seconds == pytest.approx(0.7 * (0.7e-6 + 3e-6) + 0.3 * 2e-7, rel=1e-12)
    cost.measured(9_999, 1.0)  # too short a chunk to time: ignored
    assert cost.seconds == pytest.approx(0.7 * (0.7e-6 + 3e-6) + 0.3 * 2e-7, rel=1e-12)
    left = time.perf_counter() + 1.0
    most = step_budget(left, 0, cost.seconds)  # first: the later call has less time left
    assert cost.budget(left, 0) <= most


def test_each_kernel_keeps_its_own_step_cost() -> None:
    from engine.physics import blow
    from engine.procedures import striker_cycle

    assert isinstance(blow._COST, StepCost) and isinstance(striker_cycle._COST, StepCost)
    assert blow._COST is not striker_cycle._COST
    assert blow.step_budget(None, 5) == striker_cycle.step_budget(None, 5) == 5
