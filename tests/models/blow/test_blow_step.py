"""One blow of the rigid and energy rungs, written once for one design or many
(engine.physics.blow.blow_step, energy_blow): hand values, and arrays equal to single runs."""

from __future__ import annotations

import math

import numpy as np
import pytest

from engine.core.errors import InfeasibleDesign
from engine.physics.blow import blow_gains_nothing, blow_step, energy_blow


def test_energy_blow_by_hand() -> None:
    # E 100 J, C 2e4 N·m/rad, k_j 1000 N·m/rad, T0 60 N·m, N 0:
    # a = (1/C + 1/k)/2 = 5.25e-4; rhs = E + T0²/(2k) = 101.8; T_p = sqrt(rhs/a) = 440.346
    tp = math.sqrt((100.0 + 60.0**2 / 2000.0) / (0.5 * (1 / 2.0e4 + 1 / 1000.0)))
    peak, after, rot, work = energy_blow(100.0, 2.0e4, 1000.0, 60.0)
    assert peak == pytest.approx(tp, rel=1e-14) and after == pytest.approx(tp, rel=1e-14)
    assert rot == pytest.approx((tp - 60.0) / 1000.0, rel=1e-14)
    assert work == pytest.approx((tp**2 - 60.0**2) / 2000.0, rel=1e-14)
    # energy conserved: E = T_p²/(2C) + work
    assert tp**2 / 4.0e4 + work == pytest.approx(100.0, rel=1e-13)


def test_a_constant_joint_torque_by_hand_and_refused_where_the_nut_never_stops() -> None:
    # k_j = 0: rot = (E + N T0/C − T0²/(2C))/(T0 − N) = (100 − 0.09)/60
    peak, after, rot, work = energy_blow(100.0, 2.0e4, 0.0, 60.0)
    assert (peak, after) == (60.0, 60.0)
    assert rot == pytest.approx(99.91 / 60.0, rel=1e-14)
    assert work == pytest.approx(99.91, rel=1e-14)
    with pytest.raises(InfeasibleDesign) as err:
        energy_blow(100.0, 2.0e4, 0.0, 60.0, drive_torque=80.0)
    assert err.value.field == "joint_rate"
    arr = energy_blow(100.0, 2.0e4, np.array([0.0, 0.0]), 60.0, drive_torque=np.array([0.0, 80.0]))
    assert arr[2][0] == pytest.approx(rot, rel=1e-15)
    assert all(math.isnan(float(v[1])) for v in arr)  # masked, not a wrong number


def test_the_rigid_step_by_hand() -> None:
    # M = sqrt(2·100·2e4) = 2000 N·m; the joint from 60 to 2000 N·m at 1000 N·m/rad
    assert blow_step("rigid", 100.0, 2.0e4, 1000.0, 60.0) == (2000.0, 2000.0, 1.94, 1998.2)
    # a joint already above the blow's peak does not move
    assert blow_step("rigid", 100.0, 2.0e4, 1000.0, 2500.0) == (2000.0, 2500.0, 0.0, 0.0)
    # no torque rate: rotation and work are not defined by the rigid rung, reported 0
    assert blow_step("rigid", 100.0, 2.0e4, 0.0, 60.0)[2:] == (0.0, 0.0)


@pytest.mark.parametrize("method", ["rigid", "energy"])
def test_arrays_give_each_point_its_single_value(method: str) -> None:
    rng = np.random.default_rng(7)
    n = 200
    e = rng.uniform(1.0, 500.0, n)
    c = rng.uniform(1e3, 1e5, n)
    k = rng.uniform(0.0, 5e3, n)
    t0 = rng.uniform(0.0, 3000.0, n)
    b = rng.uniform(1.0, 1.5, n)
    drive = rng.uniform(0.0, 50.0, n)
    many = blow_step(method, e, c, k, t0, b, drive)
    for i in range(n):
        try:
            one = blow_step(method, e[i], c[i], k[i], t0[i], b[i], drive[i])
        except InfeasibleDesign:
            assert all(math.isnan(float(col[i])) for col in many)
            continue
        for col, value in zip(many, one, strict=True):
            assert float(col[i]) == pytest.approx(value, rel=1e-14, abs=1e-300)


def test_saturation_rule() -> None:
    assert blow_gains_nothing(1e-13, 2.0, 1.0)  # the nut did not turn
    assert blow_gains_nothing(0.1, 1000.0 + 1e-10, 1000.0)  # no gain within 1e-12 relative
    assert not blow_gains_nothing(0.1, 1000.1, 1000.0)
    stuck = blow_gains_nothing(np.array([0.0, 0.1]), np.array([5.0, 6.0]), np.array([5.0, 5.0]))
    assert stuck.tolist() == [True, False]
