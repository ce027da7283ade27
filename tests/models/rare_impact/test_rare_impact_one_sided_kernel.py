"""The one-sided stage 3's compiled pieces against their definitions, worked by hand.

The contacts of the symmetric V at 45° (t_A = t_B = 1), q = (y_h, y_s, x − x0, y_r):
g_H = −y_h, g_J = h2 − y_s, g_B = y_r − y_h − (x − x0), g_A = y_s − y_r − (x − x0).
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from engine.models.rare_impact import REFERENCE_DESIGN as R
from engine.procedures import striker_cycle as C


def _setup() -> tuple[np.ndarray, np.ndarray]:
    x = C.step_inputs({**R, "roller_geometry": "symmetric_v"})
    p = C._contact_params(x, C._geo(x))
    return p, C._jacobian_matrix(p)


def test_the_jacobian_and_parameters_are_the_contacts_written_out() -> None:
    p, jac = _setup()
    # masses 0.15, 0.4, 6·0.05; h2 = 4 mm; both slopes tan 45° = 1
    assert p[C.U_M1] == 0.15 and p[C.U_M3] == 0.4 and p[C.U_NM] == pytest.approx(0.3, rel=1e-15)
    assert p[C.U_TA] == pytest.approx(1.0, rel=1e-15) and p[C.U_H2] == 0.004
    t = p[C.U_TB]
    assert jac.tolist() == [
        [-1.0, 0.0, 0.0, 0.0],
        [0.0, -1.0, 0.0, 0.0],
        [-1.0, 0.0, -t, 1.0],
        [0.0, 1.0, -p[C.U_TA], -1.0],
    ]


def test_touching_contacts_and_their_rates_by_hand() -> None:
    p, jac = _setup()
    # every gap 0: y_h = 0, y_s = h2, x − x0 = 2 mm, y_r = 2 mm (t = 1 up to an ulp: tol 1e-15)
    q = np.array([0.0, 0.004, 0.002, 0.002])
    v = np.array([0.1, -0.2, 0.05, 0.3])
    cand, rate = np.zeros(4, dtype=np.bool_), np.empty(4)
    scale = C._contact_rates_c(p, jac, q, v, 1e-15, cand, rate)
    assert cand.tolist() == [True, True, True, True]
    # J v = (−0.1, 0.2, 0.3 − 0.1 − 0.05, −0.2 − 0.05 − 0.3)
    assert rate == pytest.approx([-0.1, 0.2, 0.15, -0.55], rel=1e-14)
    assert scale == pytest.approx(0.55, rel=1e-14)
    # 1 µm further the jaws' bottom and face A open
    cand2 = np.zeros(4, dtype=np.bool_)
    C._contact_rates_c(p, jac, q - [0.0, 1e-6, 0.0, 0.0], v, 1e-9, cand2, rate)
    assert cand2.tolist() == [True, False, True, False]


def _enumerated(
    p: np.ndarray, jac: np.ndarray, q: np.ndarray, still: tuple[int, ...]
) -> list[bool] | None:
    """The contact set by its definition: the first subset (larger first, combinations'
    order, the empty one last) whose reactions push and leave the others opening."""
    acc, lam = np.empty(4), np.empty(4)
    wk, idx = np.empty((6, 5)), np.empty(4, dtype=np.int64)
    subsets = [c for k in range(len(still), -1, -1) for c in itertools.combinations(still, k)]
    for s in subsets:
        act = np.array([i in s for i in range(4)])
        C._contact_accel_c(p, act, q, acc, lam, wk, idx)
        ascale = max(*np.abs(acc).tolist(), 1e-300)
        if (lam >= 0.0).all() and all(jac[i] @ acc >= -1e-12 * ascale for i in still if i not in s):
            return act.tolist()
    return None


@pytest.mark.parametrize(
    ("y_h", "expected"),
    [
        # on its stop the power spring holds the half-coupling; the striker leaves the
        # jaws' bottom under its return spring and face A alone carries the rollers
        (0.0, [True, False, False, True]),
        # 1 mm off the stop: the rollers between both faces (the two-degree-of-freedom
        # stage 3), the half-coupling and the striker each free of their stops
        (-0.001, [False, False, True, True]),
    ],
)
def test_the_compiled_contact_set_is_the_first_consistent_subset(
    y_h: float, expected: list[bool]
) -> None:
    p, jac = _setup()
    # at rest (every touching contact still), on the stop or 1 mm off it
    # both faces touching: x − x0 = (y_s − y_h)/2 (t = 1), y_r midway
    q = np.array([y_h, 0.004, (0.004 - y_h) / 2.0, (y_h + 0.004) / 2.0])
    v = np.zeros(4)
    cand, rate = np.zeros(4, dtype=np.bool_), np.empty(4)
    scale = C._contact_rates_c(p, jac, q, v, 1e-12, cand, rate)
    active = np.zeros(4, dtype=np.bool_)
    args = (np.empty(4), np.empty(4), np.empty((6, 5)), np.empty(4, dtype=np.int64))
    assert C._active_set_c(p, jac, q, rate, scale, cand, active, *args)
    still = tuple(i for i in range(4) if cand[i])
    assert len(still) == 4 + int(y_h < 0.0) * -1  # the stop touches only at y_h = 0
    assert active.tolist() == _enumerated(p, jac, q, still) == expected


def test_a_plastic_catch_stops_the_closing_gaps_with_pushing_impulses() -> None:
    p, jac = _setup()
    minv = 1.0 / p[[C.U_M1, C.U_M3, C.U_NM, C.U_NM]]
    # face B closing at 0.3 m/s, the stop closing at 0.1 m/s, the others opening
    v = np.array([0.1, -0.5, 0.0, -0.2])
    cand = [0, 2, 3]
    rate = jac @ v
    assert rate[0] < 0.0 and rate[2] < 0.0
    after = C._catch(p, v, cand, jac, float(np.abs(rate).max()))
    rate_after = jac @ after
    assert all(rate_after[i] >= -1e-12 for i in cand)  # none closes any more
    # M(v+ − v) = J_Sᵀ P with P ≥ 0 over the contacts that took an impulse
    impulse, *_ = np.linalg.lstsq(jac[cand].T, (after - v) / minv, rcond=None)
    assert np.allclose(jac[cand].T @ impulse, (after - v) / minv, rtol=0, atol=1e-12)
    assert (impulse >= -1e-12).all() and impulse.max() > 0.0
    # a contact with a positive impulse ends still (plastic), not rebounding
    for i, imp in zip(cand, impulse, strict=True):
        if imp > 1e-12:
            assert abs(rate_after[i]) <= 1e-12


def test_the_one_sided_kernel_comes_back_for_a_catch_and_takes_the_new_velocities() -> None:
    p, jac = _setup()
    # the state above: a catch first (code 1), then the run goes on once v is replaced
    q = np.array([0.0, 0.004, 0.002, 0.002])
    v = np.array([0.1, -0.5, 0.0, -0.2])
    fs = np.array([0.0, 0.0, 0.05, 1e-6, 0.0005, np.inf, np.inf, 1e-14, np.nan, np.nan,
                   0.0, 0.0, 1e-14, 0.0])  # fmt: skip
    st = np.zeros(C._U_NI, dtype=np.int64)
    st[C._U_MAX] = 10**7
    active, cand = np.zeros(4, dtype=np.bool_), np.zeros(4, dtype=np.bool_)
    buf = np.empty(1)
    code = C._one_sided_c(p, jac, fs, st, active, cand, q, v, buf, buf, buf, buf)
    assert code == C._U_CATCH and cand.tolist() == [True, True, True, True]
    v0 = v.copy()
    v[:] = C._catch(p, v, [0, 1, 2, 3], jac, float(fs[C._U_VSCALE]))
    assert not np.array_equal(v, v0)
    steps = []
    for _ in range(50):  # as the driver does: a catch or a look at the clock, then on
        code = C._one_sided_c(p, jac, fs, st, active, cand, q, v, buf, buf, buf, buf)
        steps.append(int(st[C._U_STEPS]))
        if code == C._U_CATCH:
            v[:] = C._catch(p, v, [i for i in range(4) if cand[i]], jac, float(fs[C._U_VSCALE]))
        elif code != C._U_CHUNK:
            break
    assert code == C._U_DONE
    assert steps[0] > 0 and steps == sorted(steps) and st[C._U_SEGS] >= 1
    # the striker came home (y_s = 0: the run stops there), clear of the jaws (y_s = 0.5 mm)
    # before that
    assert q[1] == pytest.approx(0.0, abs=1e-12)
    assert fs[C._U_THOME] == fs[C._U_T] - fs[C._U_TBLOW] < 0.05
    assert 0.0 < fs[C._U_TRET] < fs[C._U_THOME]


def test_a_step_of_zero_at_the_ranges_ends_is_a_solver_failure_not_a_budget_of_inf_steps():
    # the smallest striker mass the range admits (5e-324, its open lower end) with the
    # auxiliary spring and the engagement height at theirs: stage 3's step comes out 0, so
    # its expected steps (t_end - t) / h are not finite; the kernel hands that back as a
    # failed integration (as the Python loop's ZeroDivisionError was), never as "about inf
    # steps" with inf in the refusal's context, nor a NaN compared and cast to a stride
    from engine import run
    from engine.core.errors import SolverFailed
    from engine.models.rare_impact import RARE_IMPACT

    design = {
        **R,
        "flywheel_inertia": 0.014297243376671143,
        "motor_torque": 4.72788998148474,
        "roller_mass": 0.04371795793105644,
        "roller_count": 8,
        "roller_radius": 0.031943850303395374,
        "cone_angle": 1.283660495065539,
        "half_coupling_mass": 0.09823363818909049,
        "stepped_shaft_mass": 0.025675017651020118,
        "striker_mass": 5e-324,
        "power_spring_rate": 73956.36393176674,
        "auxiliary_spring_rate": 5e-324,
        "return_spring_rate": 84801.91853230752,
        "power_spring_preload": 0.0022145508125792157,
        "auxiliary_spring_preload": 0.013082684590930215,
        "return_spring_preload": 0.001966807039543231,
        "release_travel": 0.0035852071597096634,
        "engagement_height": 5e-324,
        "jaw_height": 0.006174986343746396,
        "engagement_angle": 0.0017453292519943296,
        "roller_friction": 0.0,
        "gravity": 9.879827335116762,
        "roller_geometry": "symmetric_v",
    }
    with pytest.raises(SolverFailed, match="diverged in stage 3"):
        run(RARE_IMPACT, design, fidelity="simulation")
