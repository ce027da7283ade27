"""engine.physics.fasteners: the designation parser, catalogue lookups and check relations."""

from __future__ import annotations

import json
import math

import pytest

import engine.physics.fasteners as f
from engine.core.errors import InputOutOfRange

INCH = 0.0254


@pytest.mark.parametrize(
    ("text", "thread", "head", "grade"),
    [
        ("M12", "M12", None, None),
        ("m12", "M12", None, None),
        ("M12x1.25", "M12x1.25", None, None),
        ("M12 x 1.25", "M12x1.25", None, None),
        ("M12x1.75", "M12", None, None),  # the coarse pitch written out is still coarse
        ("M10 ISO 4762 12.9", "M10", "ISO 4762", "12.9"),
        ("M8 DIN 912 A2-70", "M8", "ISO 4762", "A2-70"),
        ("M6 ISO 10642 10.9", "M6", "ISO 10642", "10.9"),
        ("M10 EN 1665 8.8", "M10", "EN 1665", "8.8"),
        ("M1.6", "M1.6", None, None),
        ("M64x4", "M64x4", None, None),
        ("1/2-13 UNC", "1/2-13 UNC", None, None),
        ("1/2-13", "1/2-13 UNC", None, None),
        ("1/2 UNF", "1/2-20 UNF", None, None),
        ("1-1/2-6 UNC", "1-1/2-6 UNC", None, None),
        ("1/2-13 UNC Grade 5", "1/2-13 UNC", None, "SAE 5"),
        ("1/2-13 UNC-2A SAE J429 8", "1/2-13 UNC", None, "SAE 8"),
        ("3/4-10 UNC ASTM A193 B7", "3/4-10 UNC", None, "B7"),
    ],
)
def test_designations_are_read(text, thread, head, grade):
    d = f.parse_designation(text)
    assert (d.thread.designation, d.head, d.grade) == (thread, head, grade)


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("M13", "not an ISO 261 size"),
        ("M12x2", "allowed: 1.75, 1.5, 1.25 mm"),
        ("M10x40", "a bolt length is not part"),
        ("1/2-14", "1/2-13 UNC, 1/2-20 UNF"),
        ("1/2-20 UNC", "is UNF, not UNC"),
        ("2-4-1/2 UNC", "cannot read the thread"),
        ("M10 ISO 4762 13.9", "'13.9' is not a known grade"),
        ("1/2-13 UNC ISO 4762", "metric head"),
        ("", "give a designation"),
        ("bolt", "cannot read the thread"),
    ],
)
def test_bad_designations_name_the_field_and_the_part(text, fragment):
    with pytest.raises(InputOutOfRange) as err:
        f.parse_designation(text, field="thread")
    assert err.value.field == "thread"
    assert fragment in err.value.message


def test_metric_geometry_follows_iso_68_1():
    t = f.metric_thread(12)
    assert t.pitch == pytest.approx(1.75e-3)
    # d2 = d − 0.649519 P, d3 = d − 1.226869 P, D1 = d − 1.082532 P
    assert t.pitch_diameter == pytest.approx(10.863e-3, abs=1e-6)
    assert t.minor_diameter == pytest.approx(9.853e-3, abs=1e-6)
    assert t.nut_minor_diameter == pytest.approx(10.106e-3, abs=1e-6)
    assert f.metric_thread(64).pitch == pytest.approx(6e-3)
    assert f.metric_thread(1.6).pitch == pytest.approx(0.35e-3)


def test_unified_stress_area_is_the_mean_of_pitch_and_sharp_v_minor_diameters():
    t = f.unified_thread("1/2", 13)
    mean = 0.5 * (t.pitch_diameter + t.minor_diameter)
    assert t.stress_area == pytest.approx(math.pi / 4 * mean**2, rel=1e-5)


def test_grade_size_steps():
    assert f.grade_strengths("8.8", 0.016).yield_strength == pytest.approx(640e6)
    assert f.grade_strengths("8.8", 0.020).yield_strength == pytest.approx(660e6)
    assert f.grade_strengths("SAE 5", 1.0 * INCH).tensile_strength == pytest.approx(
        120 * 6.894757e6, rel=1e-6
    )
    assert f.grade_strengths("SAE 5", 1.25 * INCH).tensile_strength == pytest.approx(
        105 * 6.894757e6, rel=1e-6
    )
    assert f.grade_strengths("SAE 2", 1.0 * INCH).yield_strength == pytest.approx(
        36 * 6.894757e6, rel=1e-6
    )
    assert f.grade_strengths("B7", 0.5 * INCH).yield_strength == pytest.approx(
        105 * 6.894757e6, rel=1e-6
    )
    with pytest.raises(
        InputOutOfRange, match=r"A2-70 .ISO 3506-1. is defined for d = 0…24 mm"
    ) as err:
        f.grade_strengths("A2-70", 0.030)
    assert err.value.field == "grade"
    with pytest.raises(InputOutOfRange, match="not 6 mm"):
        f.grade_strengths("SAE 5", 0.006)  # SAE J429 starts at 1/4 in


def test_heads_differ_where_the_standards_differ():
    m8 = f.metric_thread(8)
    hex_, socket, flange, csk = (
        f.head(s, m8) for s in ("ISO 4017", "ISO 4762", "EN 1665", "ISO 10642")
    )
    assert (
        hex_.bearing_diameter
        < socket.bearing_diameter
        < csk.bearing_diameter
        < flange.bearing_diameter
    )
    assert socket.drive == "hex key" and socket.drive_size == pytest.approx(6e-3)
    assert csk.drive_size == pytest.approx(5e-3) and csk.cone_angle == pytest.approx(math.pi / 2)
    assert hex_.drive == "wrench" and hex_.drive_size == pytest.approx(13e-3)
    assert f.head(f.UNIFIED_HEX, f.unified_thread("1/2")).bearing_diameter == pytest.approx(
        0.95 * 0.75 * INCH
    )
    with pytest.raises(InputOutOfRange, match="EN 1665 has no M3") as err:
        f.head("EN 1665", f.metric_thread(3), field="head")
    assert err.value.field == "head"


def test_hex_key_torques_rise_with_key_size():
    sizes = sorted(f.HEX_KEY_TORQUE_NM)
    torques = [f.HEX_KEY_TORQUE_NM[s] for s in sizes]
    assert torques == sorted(torques)
    assert f.hex_key_torque(0.006) == 52.0 and f.hex_key_torque(0.0061) is None


def test_nuts_and_washers():
    m12 = f.metric_thread(12)
    heights = [f.nut(s, m12).height for s in ("ISO 4035", "ISO 4032", "ISO 4033")]
    assert heights == sorted(heights)  # thin < style 1 < style 2
    small, normal, large = (f.washer(s, m12) for s in ("ISO 7092", "ISO 7089", "ISO 7093"))
    assert small.outer_diameter < normal.outer_diameter < large.outer_diameter
    assert normal.inner_diameter == pytest.approx(13e-3)
    with pytest.raises(InputOutOfRange) as err:
        f.washer("ISO 7093", f.metric_thread(1.6))
    assert err.value.field == "washer"


def test_bearing_area_and_pressure():
    # A_p = π/4 (d_w² − d_h²): M10 ISO 4762 on an ISO 273 medium hole (11 mm)
    area = f.bearing_area(15.33e-3, 11e-3)
    assert area == pytest.approx(math.pi / 4 * (15.33**2 - 11**2) * 1e-6)
    assert f.surface_pressure(40e3, 15.33e-3, 11e-3) == pytest.approx(40e3 / area)
    assert f.surface_pressure(1.0, 10e-3, 10e-3) == math.inf
    assert f.countersunk_friction_factor(math.pi / 2) == pytest.approx(math.sqrt(2))
    assert f.countersunk_friction_factor(math.pi) == pytest.approx(1.0)  # a flat face


def test_basic_shear_areas_reduce_to_the_textbook_ratios():
    t = f.metric_thread(16)
    l_e = 10e-3
    # basic profile: A_SN = 0.875 π d L_e, A_SS = 0.75 π D1 L_e
    assert f.internal_thread_shear_area(
        t.diameter, t.pitch, t.pitch_diameter, l_e
    ) == pytest.approx(0.875 * math.pi * t.diameter * l_e, rel=1e-5)
    assert f.external_thread_shear_area(
        t.pitch, t.pitch_diameter, t.nut_minor_diameter, l_e
    ) == pytest.approx(0.75 * math.pi * t.nut_minor_diameter * l_e, rel=1e-5)


def test_alexander_factors():
    assert f.nut_dilation_factor(None, 0.012) == 1.0
    assert f.nut_dilation_factor(0.030, 0.012) == pytest.approx(1.0, abs=1e-12)  # s/d ≥ 1.9
    # C1 rises with s/d between 1.4 and 1.9
    assert f.nut_dilation_factor(0.0168, 0.012) < f.nut_dilation_factor(0.018, 0.012) < 1.0
    c2, c3 = f.thread_bending_factors(0.7)
    assert c2 == pytest.approx(0.897) and c3 == pytest.approx(
        0.728 + 1.769 * 0.7 - 2.896 * 0.49 + 1.296 * 0.343
    )
    c2, c3 = f.thread_bending_factors(5.0)  # held at 2.2
    assert c3 == pytest.approx(0.897) and c2 == pytest.approx(f.thread_bending_factors(2.2)[0])


def test_stripping_length_scales_with_the_softer_thread():
    t = f.metric_thread(8)
    args = (
        t.diameter,
        t.pitch,
        t.pitch_diameter,
        t.nut_minor_diameter,
        t.stress_area,
        1220e6,
        732e6,
    )
    steel = f.thread_stripping(*args, 0.6 * 620e6, 8e-3)
    alu = f.thread_stripping(*args, 0.6 * 310e6, 8e-3)
    assert alu.min_engagement_length > steel.min_engagement_length
    assert alu.weaker == "internal" and alu.internal_strip_force < alu.bolt_breaking_force
    # at the minimum length the weaker thread carries exactly the breaking force
    at_min = f.thread_stripping(*args, 0.6 * 310e6, alu.min_engagement_length)
    assert at_min.strip_force == pytest.approx(at_min.bolt_breaking_force, rel=1e-12)
    # the stripping forces are linear in the length
    double = f.thread_stripping(*args, 0.6 * 310e6, 16e-3)
    assert double.internal_strip_force == pytest.approx(2 * alu.internal_strip_force)


def test_catalogue_is_json_ready_and_complete():
    c = f.catalogue()
    assert set(c) == {"threads", "property_classes", "heads", "nuts", "washers", "materials"}
    json.dumps(c, allow_nan=False)
    names = {t["designation"] for t in c["threads"]}
    assert {"M1.6", "M64", "M12x1.25", "1/4-20 UNC", "1-1/2-12 UNF"} <= names
    assert {"diameter", "pitch", "series", "stress_area"} <= set(c["threads"][0])
    assert {"name", "yield_strength", "tensile_strength", "standard"} <= set(
        c["property_classes"][0]
    )
    assert {"name", "limiting_surface_pressure", "shear_strength"} <= set(c["materials"][0])
    grades = {g["name"] for g in c["property_classes"]}
    assert {"8.8", "12.9", "A2-70", "A4-70", "A4-80", "SAE 2", "SAE 5", "SAE 8", "B7"} <= grades
    kinds = {m["kind"] for m in c["materials"]}
    assert {"steel", "cast iron", "aluminium", "titanium", "plastic"} <= kinds
