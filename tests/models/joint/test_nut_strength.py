"""The joint's nut that does not pair with the bolt: R11 for the nut's own thread.

M12 12.9 through two 20 mm steel plates with an ISO 4035 class 04 thin nut (m 6 mm, s 18 mm):
the nut's proof load caps F_M,zul (tests/models/joint/test_joint_review.py), and its thread,
sheared at the root over m − 2P with τ_BM = 0.6 S_p, strips at 16.7 kN by R11 (worked out
below): below the 32.0 kN proof load ISO 898-2 tests every such nut's thread to, which governs.
"""

import math

import pytest

from engine import run
from engine.models import get_model
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
D, P = 0.012, 0.00175
D2 = D - 0.649519 * P
D1 = D - 1.082532 * P

M12_129_THIN = {
    "thread": "M12 ISO 4017 12.9",
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "working_load": 5e3,
    "nut": "ISO 4035",
    "nut_property_class": "04",
}


def test_the_thin_nut_strips_at_the_hand_calculated_force():
    tan30 = math.tan(math.radians(30))
    a_n = math.pi * D * (P / 2 + (D - D2) * tan30) / P  # internal thread's shear area per m
    a_s = math.pi * D1 * (P / 2 + (D2 - D1) * tan30) / P  # bolt thread's per m
    tau_m, tau_s = 0.6 * 380e6, 0.6 * 1220e6  # class 04 S_p; 12.9 R_m
    r_s = tau_m * a_n / (tau_s * a_s)
    c3 = 0.728 + 1.769 * r_s - 2.896 * r_s**2 + 1.296 * r_s**3
    c1 = -(1.5**2) + 3.8 * 1.5 - 2.61  # s/d = 18/12
    by_hand = c1 * c3 * tau_m * a_n * (0.006 - 2 * P)
    assert by_hand == pytest.approx(16.68e3, rel=1e-3)
    proof = 380e6 * math.pi / 4 * ((D2 + (D - 1.226869 * P)) / 2) ** 2  # S_p A_s, 32.02 kN
    assert proof == pytest.approx(32.02e3, rel=1e-3)
    r = run(JOINT, M12_129_THIN)
    held = max(by_hand, proof)  # the certified proof load governs
    pin("joint.vdi2230", "nut_stripping_force", r.results["nut_stripping_force"], held, rel=1e-9)
    checks = {c.name: c.ok for c in r.checks}
    # F_S,max = F_p + Φ_n F_A is above what the thread holds
    assert r.results["max_bolt_force"] > held
    assert checks["nut_thread_stripping"] is False


def test_a_paired_nut_has_no_stripping_force():
    paired = {k: v for k, v in M12_129_THIN.items() if k != "nut_property_class"}
    r = run(JOINT, {**paired, "thread": "M12 ISO 4017 8.8", "nut": "ISO 4032"})
    assert "nut_stripping_force" not in r.results
    assert "nut_thread_stripping" not in {c.name for c in r.checks}
    assert any("bolt breaks before its thread strips" in n for n in r.notes)


def test_a_sweep_gives_the_stripping_force_at_every_point():
    from engine.core.runner import sweep

    one = run(JOINT, M12_129_THIN).results["nut_stripping_force"]
    r = sweep(JOINT, dict(M12_129_THIN), "working_load", [0.0, 5e3])
    assert list(r.results["nut_stripping_force"]) == pytest.approx([one, one], rel=1e-12)
