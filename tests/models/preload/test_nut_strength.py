"""The nut in the preload models: ISO 898-2's proof load caps F_M,zul, the class pairs with
the bolt's, and a nut that does not pair is checked for stripping (VDI 2230-1 R11).

The expected values are worked out here from the printed tables: ISO 898-2:1992 proof
stresses (M10 < d ≤ M16: class 04 380 MPa, 05 500 MPa, 8 880 MPa), the ISO 68-1 thread,
ISO 4035's thin nut (m = 6 mm, s = 18 mm for M12) and Alexander's R11 factors.
"""

import math

import pytest

from engine import run
from engine.models import get_model
from tests.pins import pin

TIGHTENING = get_model("preload.tightening")
CONTROL = get_model("preload.control")

D, P = 0.012, 0.00175
D2 = D - 0.649519 * P
D3 = D - 1.226869 * P
AS = math.pi / 4 * (0.5 * (D2 + D3)) ** 2  # 84.27 mm²

THIN_04 = {"thread": "M12 12.9", "nut": "ISO 4035", "nut_property_class": "04"}


def thin_nut_strip_force_by_hand(nut_class_sp: float, bolt_rm: float) -> float:
    """R11 after Alexander for the M12 ISO 4035 nut's thread, step by step."""
    m, s = 0.006, 0.018
    full = m - 2 * P  # the 2P of the entry chamfers off the nut's height: 2.5 mm
    a_n = math.pi * D * (P / 2 + (D - D2) * math.tan(math.radians(30))) / P  # per metre
    d1 = D - 1.082532 * P
    a_s = math.pi * d1 * (P / 2 + (D2 - d1) * math.tan(math.radians(30))) / P
    tau_m, tau_s = 0.6 * nut_class_sp, 0.6 * bolt_rm
    r_s = tau_m * a_n / (tau_s * a_s)  # 0.4315: the nut's thread is the weaker
    assert 0.4 < r_s < 1.0
    c3 = 0.728 + 1.769 * r_s - 2.896 * r_s**2 + 1.296 * r_s**3
    c1 = -((s / D) ** 2) + 3.8 * (s / D) - 2.61  # s/d = 1.5: 0.84
    return c1 * c3 * tau_m * a_n * full


def test_the_hand_calculation_reads_as_expected():
    # 0.84 × 1.0562 × 228 MPa × 82.47 mm² = 16.68 kN for class 04 with a 12.9 bolt
    assert thin_nut_strip_force_by_hand(380e6, 1220e6) == pytest.approx(16682, rel=1e-4)


def test_a_thin_nut_caps_the_preload_with_a_failing_check_and_a_warning():
    bolt_alone = run(TIGHTENING, {"thread": "M12 12.9"}).results
    r = run(TIGHTENING, THIN_04)
    proof = 380e6 * AS  # 32.02 kN
    pin("preload.tightening", "nut_proof_load", r.results["nut_proof_load"], proof, rel=1e-9)
    assert bolt_alone["permissible_preload"] == pytest.approx(74.1e3, rel=2e-3)
    assert r.results["permissible_preload"] == pytest.approx(proof, rel=1e-9)
    assert r.results["assembly_preload"] == pytest.approx(proof, rel=1e-9)
    # the torque is built on the capped preload: M_A scales with F
    ratio = proof / bolt_alone["permissible_preload"]
    assert r.results["tightening_torque"] == pytest.approx(
        bolt_alone["tightening_torque"] * ratio, rel=1e-9
    )
    checks = {c.name: c.ok for c in r.checks}
    assert checks["nut_strength"] is False
    assert checks["nut_class_pairing"] is False
    assert any("limits the preload" in w and "32.02 kN" in w for w in r.warnings)


def test_a_thin_nut_thread_holds_its_proof_load_where_r11_estimates_less():
    # R11 gives 16.7 kN, but ISO 898-2 loads every class 04 nut's thread to its proof load
    # 32.0 kN without stripping: the certified floor governs, and the capped preload passes
    r = run(TIGHTENING, THIN_04)
    by_hand = thin_nut_strip_force_by_hand(380e6, 1220e6)
    proof = 380e6 * AS
    assert by_hand < proof
    pin(
        "preload.tightening",
        "nut_stripping_force",
        r.results["nut_stripping_force"],
        proof,
        rel=1e-9,
    )
    checks = {c.name: c.ok for c in r.checks}
    assert checks["nut_thread_stripping"] is True  # F_M = F_p, held
    assert checks["nut_strength"] is False  # the bolt alone would take 74.1 kN


def test_a_paired_full_nut_changes_nothing_and_passes():
    bolt_alone = run(TIGHTENING, {"thread": "M12 8.8"}).results
    r = run(TIGHTENING, {"thread": "M12 8.8", "nut": "ISO 4032"})
    # class 8 assumed (the lowest ISO 4032 class that pairs with 8.8); DIN EN 20898-2 prints
    # 74 200 N for the M12 class 8 nut
    assert r.results["nut_proof_load"] == pytest.approx(74_200, rel=1e-3)
    assert r.results["permissible_preload"] == bolt_alone["permissible_preload"]
    assert "nut_stripping_force" not in r.results  # a paired nut: the bolt breaks first
    checks = {c.name: c.ok for c in r.checks}
    assert checks["nut_strength"] and checks["nut_class_pairing"]
    assert "nut_thread_stripping" not in checks
    assert any("bolt breaks before its thread strips" in n for n in r.notes)
    assert not r.warnings


def test_a_weaker_full_nut_class_fails_the_pairing_and_is_checked_for_stripping():
    r = run(TIGHTENING, {"thread": "M12 10.9", "nut": "ISO 4032", "nut_property_class": "8"})
    checks = {c.name: c.ok for c in r.checks}
    assert checks["nut_class_pairing"] is False  # class 8 with a 10.9 bolt (R_m 1040 MPa)
    # ISO 4032 M12: m = 10.8 mm, s = 18 mm; class 8 S_p 880 MPa against R_m 1040 MPa
    m, s = 0.0108, 0.018
    a_n = math.pi * D * (P / 2 + (D - D2) * math.tan(math.radians(30))) / P
    d1 = D - 1.082532 * P
    a_s = math.pi * d1 * (P / 2 + (D2 - d1) * math.tan(math.radians(30))) / P
    r_s = 0.6 * 880e6 * a_n / (0.6 * 1040e6 * a_s)
    assert r_s > 1.0  # 1.17: the bolt's thread is the weaker, the nut's C3 is Alexander's 0.897
    c3 = 0.897
    c1 = -((s / D) ** 2) + 3.8 * (s / D) - 2.61
    by_hand = c1 * c3 * 0.6 * 880e6 * a_n * (m - 2 * P)
    assert r.results["nut_stripping_force"] == pytest.approx(by_hand, rel=1e-6)
    assert checks["nut_thread_stripping"] is (by_hand >= r.results["assembly_preload"])


def test_control_builds_its_band_under_the_nut_proof_load():
    r = run(CONTROL, {**THIN_04, "required_clamp_force": 10e3, "method": "torque_wrench"})
    proof = 380e6 * AS
    pin("preload.control", "nut_proof_load", r.results["nut_proof_load"], proof, rel=1e-9)
    pin(
        "preload.control",
        "nut_stripping_force",
        r.results["nut_stripping_force"],
        max(thin_nut_strip_force_by_hand(380e6, 1220e6), proof),
        rel=1e-9,
    )
    # torque wrench ±30 %: the top of the band is F_M,zul, here the nut's proof load
    assert r.results["preload_max"] == pytest.approx(proof, rel=1e-9)
    assert r.results["nominal_preload"] == pytest.approx(proof / 1.3, rel=1e-9)
    checks = {c.name: c.ok for c in r.checks}
    assert checks["nut_strength"] is False and checks["nut_class_pairing"] is False
    assert any("limits the preload" in w for w in r.warnings)


def test_a_sweep_says_the_same_per_point():
    from engine.core.runner import sweep

    r = sweep(TIGHTENING, dict(THIN_04), "thread_friction", [0.08, 0.12, 0.16])
    proof = 380e6 * AS
    assert list(r.results["permissible_preload"]) == pytest.approx([proof] * 3, rel=1e-9)
    assert any("limits the preload at some points" in w for w in r.warnings)
