"""Torque-then-angle: the snug torque and the angle beyond it ([004] after eq. 19, [004, eq. 8]).

M12 8.8, 60 mm grip of free thread, clamped parts λ_p = 1 µm/kN given: the bolt's compliance
is worked out here ([004, eq. 4, 7]: the grip and a third of the 0.8 d nut at d3), the snug
point at 10 % of the final torque (ISO 5393's start of the angle count), and the angle for the
90 % of the preload still to come.
"""

import math

import pytest

from engine import run
from engine.models import get_model
from tests.pins import pin

CONTROL = get_model("preload.control")
D, P = 0.012, 0.00175
D3 = D - 1.226869 * P
E = 2.1e11
CASE = {
    "thread_diameter": D,
    "required_clamp_force": 20e3,
    "method": "torque_then_angle",
    "clamped_length": 0.060,
    "clamped_compliance": 1e-9,
}


def test_snug_torque_and_angle_by_hand():
    r = run(CONTROL, CASE).results
    lam_b = (0.060 + 0.8 * D / 3) / (E * math.pi / 4 * D3**2)  # 3.947 µm/kN
    assert r["bolt_compliance"] == pytest.approx(lam_b, rel=1e-9)
    # VDI 2230-1 Table A8 α_A 1.4 for the method: s = 0.4/2.4, the band's top at F_M,zul
    f_nom = r["permissible_preload"] / (1 + 0.4 / 2.4)
    assert r["nominal_preload"] == pytest.approx(f_nom, rel=1e-12)
    snug = 0.10 * f_nom
    theta = (f_nom - snug) * (lam_b + 1e-9) / P * 2 * math.pi
    pin("preload.control", "snug_preload", r["snug_preload"], snug, rel=1e-9)
    pin("preload.control", "snug_torque", r["snug_torque"], 0.10 * r["target_torque"], rel=1e-9)
    pin("preload.control", "angle_after_snug", r["angle_after_snug"], theta, rel=1e-9)
    # in degrees, to a reader's three figures: 36.95 kN × 0.9 × 4.947 µm/kN / 1.75 mm × 360°
    assert math.degrees(r["angle_after_snug"]) == pytest.approx(33.8, abs=0.1)


def test_a_given_snug_share_moves_both_settings():
    r = run(CONTROL, {**CASE, "snug_fraction": 0.3}).results
    assert r["snug_torque"] == pytest.approx(0.3 * r["target_torque"], rel=1e-12)
    # the angle beyond snug is 70 % of the angle from zero preload ([004, eq. 8])
    assert r["angle_after_snug"] == pytest.approx(0.7 * r["target_angle"], rel=1e-12)


def test_other_methods_have_no_snug_outputs_and_arrays_agree():
    r = run(CONTROL, {**CASE, "method": "nut_angle"}).results
    assert "snug_torque" not in r and "angle_after_snug" not in r
    from engine.core.runner import sweep

    one = run(CONTROL, CASE).results
    s = sweep(CONTROL, dict(CASE), "required_clamp_force", [10e3, 20e3])
    assert list(s.results["angle_after_snug"]) == pytest.approx([one["angle_after_snug"]] * 2)
    assert list(s.results["snug_torque"]) == pytest.approx([one["snug_torque"]] * 2)
