"""engine.procedures.bolt: what the resolution says and the bought-part checks at their edges.

The numbers come from the catalogue's standards (ISO 4017, ISO 10642, ISO 273, ASME B18.2.8,
ISO 2936) written out here; the sentences are outputs too (the report prints them).
"""

import math

import pytest

from engine.core.text import plain
from engine.physics import fasteners as fa
from engine.procedures import bolt as fz

INCH = 0.0254


def _resolve(x):
    """fz.resolve with its notes as a person reads them (the quantities' marks taken out)."""
    fields, fastener, notes = fz.resolve(x)
    return fields, fastener, [plain(n) for n in notes]


def test_a_hex_head_bearing_face_is_its_d_w_and_the_hole_iso_273s():
    fields, fastener, notes = _resolve({"thread": "M12"})
    assert fields["bearing_outer_diameter"] == pytest.approx(16.63e-3, rel=1e-12)
    assert fields["hole_diameter"] == pytest.approx(13.5e-3, rel=1e-12)
    assert "bearing face D_f = d_w,min = 16.63 mm (ISO 4017)" in notes
    assert "clearance hole d_h = 13.5 mm (ISO 273 medium)" in notes
    assert "bearing_friction_factor" not in fields
    assert fastener.label == "M12 ISO 4017 8.8"
    # A_s = π/4 d_S², d_S = (d2 + d3)/2 = 12 − 0.938194 × 1.75
    d_s = 12 - 0.938194 * 1.75
    assert fields["stress_diameter"] * 1e3 == pytest.approx(d_s, abs=1e-5)
    assert fields["stress_area"] * 1e6 == pytest.approx(math.pi / 4 * d_s**2, rel=1e-6)


def test_a_countersunk_head_bears_on_its_cone():
    fields, fastener, notes = _resolve({"thread": "M8 ISO 10642 10.9"})
    # ISO 10642 M8: d_k,min 15.24 mm; μ_K acts on the 90° cone, ×1/sin 45° = √2
    assert fields["bearing_outer_diameter"] == pytest.approx(15.24e-3, rel=1e-12)
    assert "bearing face D_f = d_k,min of the countersunk head = 15.24 mm (ISO 10642)" in notes
    assert fields["bearing_friction_factor"] == pytest.approx(math.sqrt(2), rel=1e-12)
    assert any("×1.414 at the radius of the projected annulus" in n for n in notes)
    assert fastener.label == "M8 ISO 10642 10.9"
    assert fields["yield_strength"] == 940e6 and fields["tensile_strength"] == 1040e6


def test_an_inch_thread_reads_its_hole_in_inches():
    fields, _, notes = _resolve({"thread": "1/2-13 UNC", "grade": "SAE 5"})
    assert fields["hole_diameter"] == pytest.approx(0.531 * INCH, rel=1e-12)
    assert "clearance hole d_h = 0.531 in (ASME B18.2.8 normal)" in notes
    # ASME B18.2.1: 3/4 in across flats, the bearing face 0.95 F
    assert fields["bearing_outer_diameter"] == pytest.approx(0.95 * 0.75 * INCH, rel=1e-12)
    assert fields["tensile_strength"] == pytest.approx(120 * fa.KSI, rel=1e-12)


def test_limiting_surface_pressure_is_bounded_at_10_gpa():
    p = {q.name: q for q in fz.CHECK_INPUTS}["limiting_surface_pressure"]
    assert p.maximum == 1e10 and p.minimum == 0.0 and p.exclusive_minimum


def _checks(torque, **x):
    fields, fastener, _ = fz.resolve({"thread": "M8 ISO 4762 12.9", **x})
    return fz.bought_part_checks(
        {"thread": "M8 ISO 4762 12.9", **x},
        fastener,
        diameter=fields["diameter"],
        pitch=fields["pitch"],
        pitch_diameter=fields["pitch_diameter"],
        stress_area=fields["stress_area"],
        tensile_strength=fields["tensile_strength"],
        bearing_outer_diameter=fields["bearing_outer_diameter"],
        hole_diameter=fields["hole_diameter"],
        max_assembly_preload=20e3,
        tightening_torque=torque,
    )


def test_the_hex_key_holds_up_to_its_iso_2936_torque_inclusive():
    # ISO 4762 M8: a 6 mm key, ISO 2936 test torque 52 N·m
    for torque, ok in ((52.0, True), (51.9, True), (52.1, False)):
        values, checks, _ = _checks(torque)
        assert values["drive_torque_limit"] == 52.0
        check = {c.name: c for c in checks}["drive_torque"]
        assert check.ok is ok
        assert "ISO 2936 test torque of the 6 mm hex key of the ISO 4762 head" in check.detail


def test_a_failed_surface_pressure_says_the_bearing_area_it_needs():
    # 20 kN on the ISO 4762 M8 head (d_w 12.33 mm, hole 9 mm) against p_G = 100 MPa:
    # needs 20e3 / 100e6 = 200 mm², has π/4 (12.33² − 9²) = 55.79 mm²
    _, checks, _ = _checks(10.0, limiting_surface_pressure=100e6)
    check = {c.name: c for c in checks}["surface_pressure_assembly"]
    area = math.pi / 4 * (12.33**2 - 9.0**2)
    assert not check.ok
    assert "needs a bearing area ≥ 200 mm²" in plain(check.detail)
    assert f"(now {area:.4g} mm²)" in plain(check.detail)


def test_the_thread_notes_state_pitch_and_stress_area():
    # ISO 898-1: A_s of M12 = π/4 (12 − 0.938194 × 1.75)² = 84.27 mm²; ASME B1.1: A_t of
    # 1/2-13 UNC = π/4 (0.5 − 0.9743/13)² = 0.1419 in², E = 0.5 − 0.649519/13 = 0.4500 in
    _, _, notes = _resolve({"thread": "M12"})
    a_s = math.pi / 4 * (12 - 0.938194 * 1.75) ** 2
    assert notes[0] == f"thread M12: P = 1.75 mm (ISO 261/262), A_s = {a_s:.4g} mm² (ISO 898-1)"
    _, _, notes = _resolve({"thread": "1/2-13 UNC", "grade": "SAE 5"})
    a_t = math.pi / 4 * (0.5 - 0.9743 / 13) ** 2
    assert notes[0].startswith(f"thread 1/2-13 UNC: d = 0.5 in, E = 0.4500 in, A_t = {a_t:.4f} in²")


def test_numeric_inputs_find_the_catalogue_thread_for_a_head_but_keep_their_hole():
    # d and P given as numbers: the catalogue's M12 supplies the ISO 4762 head (d_w 17.23 mm);
    # no designation was typed, so the clearance hole is not taken from ISO 273
    fields, fastener, notes = _resolve(
        {"thread_diameter": 0.012, "thread_pitch": 0.00175, "head_standard": "ISO 4762"}
    )
    assert fields["bearing_outer_diameter"] == pytest.approx(17.23e-3, rel=1e-12)
    assert "hole_diameter" not in fields
    assert fastener.label == "M12 ISO 4762 8.8"
    assert notes == ["bearing face D_f = d_w,min = 17.23 mm (ISO 4762)"]


def test_engagement_length_is_bounded_at_1_m():
    p = {q.name: q for q in fz.CHECK_INPUTS}["engagement_length"]
    assert p.maximum == 1.0 and p.minimum == 0.0 and p.exclusive_minimum
