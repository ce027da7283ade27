"""joint.flange: a ring flange's most loaded bolt, then the single-bolt chain of joint.vdi2230.

The per-bolt loads are worked by hand (a rigid flange, a closed interface: bolt forces linear
in the distance from the bending axis, Σ y_i² = z D_t²/8 for z ≥ 3 equally spaced bolts; a
torque carried at radius D_t/2 by every bolt alike); the rest must be joint.vdi2230's answer
for one bolt with those loads (whose every output is held by hand in test_joint_outputs.py).
"""

import math

import pytest

from engine import run, sweep
from engine.core.errors import InputOutOfRange
from engine.models import get_model
from engine.models.flange import _PASSED
from tests.pins import pin

FLANGE = get_model("joint.flange")
JOINT = get_model("joint.vdi2230")
FIRST = FLANGE.examples[0]


def _bolt_loads(f_ax, f_ax_min, m_b, m_t, z, d_t):
    # bending: the bolt on the bending plane sits at y = D_t/2; Σ y² = z (D_t/2)²/2
    sum_y2 = sum((d_t / 2 * math.cos(2 * math.pi * i / z)) ** 2 for i in range(z))
    assert sum_y2 == pytest.approx(z * d_t**2 / 8, rel=1e-12)
    per_moment = m_b * (d_t / 2) / sum_y2
    return f_ax / z + per_moment, f_ax_min / z + per_moment, m_t / (z * d_t / 2)


F_A, F_A_MIN, F_Q = _bolt_loads(40e3, 0.0, 1e3, 500.0, 8, 0.200)
GOT = run(FLANGE, FIRST).results
SINGLE = run(
    JOINT,
    {
        "thread_diameter": 0.012,
        "plate1_thickness": 0.020,
        "plate2_thickness": 0.020,
        "working_load": F_A,
        "working_load_min": F_A_MIN,
        "transverse_load": F_Q,
    },
).results


def test_most_loaded_bolt_by_hand():
    expected = {"F_A": 7500.0, "F_A,min": 2500.0, "F_Q": 625.0}  # 5 + 2.5, 0 + 2.5, 0.625 kN
    assert dict(zip(expected, (F_A, F_A_MIN, F_Q), strict=True)) == pytest.approx(expected)
    pin("joint.flange", "bolt_working_load", GOT["bolt_working_load"], F_A, rel=1e-12)
    pin("joint.flange", "bolt_working_load_min", GOT["bolt_working_load_min"], F_A_MIN, rel=1e-12)
    pin("joint.flange", "bolt_transverse_load", GOT["bolt_transverse_load"], F_Q, rel=1e-12)


PASSED = (
    "load_factor",
    "permissible_preload",
    "assembly_preload_min",
    "assembly_preload_max",
    "tightening_torque",
    "required_clamp_force",
    "residual_clamp_force_min",
    "separation_load",
    "max_working_load",
    "max_bolt_force",
    "working_stress",
    "yield_safety",
    "stress_amplitude",
    "fatigue_safety",
    "slip_safety",
)


def test_the_flange_reports_these_single_bolt_outputs():
    assert set(PASSED) == set(_PASSED)


@pytest.mark.parametrize("name", PASSED)
def test_the_bolt_goes_through_the_single_bolt_chain(name):
    assert SINGLE[name] is not None
    pin("joint.flange", name, GOT[name], SINGLE[name], rel=1e-12)


def test_checks_and_refusals():
    r = run(FLANGE, FIRST)
    assert {c.name for c in r.checks} >= {"R7_window_fits", "R9_fatigue", "R12_slip"}
    assert any("most loaded of z = 8 bolts" in n for n in r.notes)
    assert any("rigid ring flange" in n for n in r.notes)
    with pytest.raises(InputOutOfRange) as err:
        run(FLANGE, {**FIRST, "axial_force_min": 50e3})
    assert err.value.field == "axial_force_min"
    with pytest.raises(InputOutOfRange) as err:
        run(FLANGE, {**FIRST, "bolts": 2})
    assert err.value.field == "bolts"
    # 1 GN·m on a 1 mm circle: far beyond what one bolt is declared for
    with pytest.raises(InputOutOfRange) as err:
        run(FLANGE, {**FIRST, "bending_moment": 1e9, "bolt_circle_diameter": 1e-3})
    assert err.value.field == "bolt_circle_diameter"


def test_more_bolts_share_the_load():
    # twice the bolts on the same circle: each carries half
    twice = run(FLANGE, {**FIRST, "bolts": 16}).results
    assert twice["bolt_working_load"] == pytest.approx(F_A / 2, rel=1e-12)
    assert twice["bolt_transverse_load"] == pytest.approx(F_Q / 2, rel=1e-12)
    assert twice["yield_safety"] > GOT["yield_safety"]


def test_a_sweep_over_the_axial_force():
    many = sweep(FLANGE, FIRST, "axial_force", [20e3, 40e3, 80e3])
    for i, f in enumerate((20e3, 40e3, 80e3)):
        want = f / 8 + 4 * 1e3 / (8 * 0.200)
        assert float(many.columns["bolt_working_load"][i]) == pytest.approx(want, rel=1e-12)
