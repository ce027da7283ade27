"""D_A < d_W: the clamped parts as VDI 2230-1 R3's sleeve, worked by hand.

M12 through 2 × 20 mm steel in a 15 mm sleeve (d_W = 16.63 mm, d_h = 13.5 mm): no cone, the
sleeve's compliance 4 l_K/(E π (D_A² − d_h²)); with the interface given, I_Bers is the
section's b c_T³/12 alone (no cone length). D_A ≤ d_h leaves no wall and is refused.
"""

import math

import pytest

from engine import run
from engine.core.errors import InputOutOfRange
from engine.models import get_model
from engine.physics import joint as jt
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
E, DW, DH = 2.1e11, 0.01663, 0.0135
SLEEVE = {
    "thread_diameter": 0.012,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "outer_diameter": 0.015,
    "working_load": 5e3,
}


def test_the_sleeve_compliance():
    r = run(JOINT, SLEEVE)
    want = 4 * 0.040 / (E * math.pi * (0.015**2 - DH**2))
    pin("joint.vdi2230", "clamped_compliance", r.results["clamped_compliance"], want, rel=1e-12)
    assert r.results["outer_diameter_used"] == 0.015
    assert any("VDI's sleeve" in w for w in r.warnings)
    # continuous at D_A = d_W with the cone-and-sleeve integral
    at = jt.clamped_compliance([0.02, 0.02], [E, E], DW, DH, DW).total
    assert at == pytest.approx(4 * 0.040 / (E * math.pi * (DW**2 - DH**2)), rel=1e-12)


def test_the_eccentric_sleeve_bends_as_its_section():
    got = run(
        JOINT,
        {**SLEEVE, "bolt_offset": 0.0005, "interface_length": 0.015, "interface_width": 0.015},
    ).results
    i_h = 0.015 * 0.015**3 / 12
    pin("joint.vdi2230", "substitute_bending_inertia", got["substitute_bending_inertia"], i_h)
    assert got["clamped_bending_compliance"] == pytest.approx(0.040 / (E * i_h), rel=1e-12)


def test_no_wall_is_refused():
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**SLEEVE, "outer_diameter": DH})
    assert err.value.field == "outer_diameter" and "13.5 mm" in str(err.value)
