"""A torsional moment about the bolt axis in R2 and R12 (VDI 2230-1), worked by hand.

The first example (M12 8.8, 2 × 20 mm steel, F_A 0…8 kN, F_Q 2 kN) with 30 N·m more about the
bolt axis, carried by one interface at r_a = 20 mm: R2 adds M_Y/(q_M r_a μ_T) to F_KQ, R12 counts
M_Y as the transverse load it equals on the q_F interfaces. The preload does not depend on
F_K,erf (tightened to F_M,zul), so F_KR,min is the first example's, held by hand in
test_joint_outputs.py.
"""

import pytest

from engine import run
from engine.core.errors import InputOutOfRange
from engine.models import get_model
from tests.models.joint.test_joint_outputs import HAND
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
TORSION = {**JOINT.examples[0], "torsional_moment": 30.0, "friction_radius": 0.020}


def test_torsion_adds_to_the_friction_requirement_and_lowers_the_slip_safety():
    got = run(JOINT, TORSION).results
    f_kq = 2e3 / (1 * 0.15) + 30.0 / (1 * 0.020 * 0.15)  # 13.33 + 10 kN
    pin("joint.vdi2230", "transverse_clamp_force", got["transverse_clamp_force"], f_kq, rel=1e-12)
    pin("joint.vdi2230", "required_clamp_force", got["required_clamp_force"], f_kq, rel=1e-12)
    f_kr = HAND["residual_clamp_force_min"]
    assert got["residual_clamp_force_min"] == pytest.approx(f_kr, rel=1e-9)
    s_g = f_kr * 1 * 0.15 / (2e3 + 30.0 * 1 / (1 * 0.020))  # M_Y as 1.5 kN on q_F = 1
    pin("joint.vdi2230", "slip_safety", got["slip_safety"], s_g, rel=1e-9)


def test_torsion_alone_is_checked_in_r12():
    # shear on the interfaces: the transverse column of the embedding table, as with F_Q
    got = run(JOINT, {**TORSION, "transverse_load": 0.0})
    assert {c.name for c in got.checks} >= {"R12_slip"}
    assert got.results["slip_safety"] == pytest.approx(
        HAND["residual_clamp_force_min"] * 0.15 / 1500.0, rel=1e-9
    )


def test_two_interfaces_carry_the_torsion_at_half_the_clamp_force():
    got = run(JOINT, {**TORSION, "transverse_load": 0.0, "torque_interfaces": 2}).results
    assert got["transverse_clamp_force"] == pytest.approx(30.0 / (2 * 0.020 * 0.15), rel=1e-12)


def test_torsion_needs_the_friction_radius():
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**JOINT.examples[0], "torsional_moment": 30.0})
    assert err.value.field == "friction_radius"
