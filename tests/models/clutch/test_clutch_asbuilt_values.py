"""engine.procedures.clutch_asbuilt: the numbers its check sentences state, by hand.

The sentences are what the report prints; each figure in them is computed here from the
design (EN 13906-1 for the helical spring, DIN EN 16983 for the discs).
"""

import math

import engine
from engine.models.clutch import BALL_CLUTCH
from engine.procedures import clutch_asbuilt as asbuilt

DEG = math.pi / 180

ORDINARY = dict(
    ball_circle_diameter=0.05,
    ball_count=4,
    ball_diameter=0.01,
    groove_angle=45 * DEG,
    flank_friction=0.1,
    face_friction=0.01,
    spring_wire_diameter=0.004,
    spring_mean_diameter=0.032,
    spring_active_coils=8.0,
    spring_free_length=0.090,
    spring_deflection=0.030,
    ball_lift=0.002,
    spring_material="EN10270-1-DH",
)

DISC = dict(
    ball_circle_diameter=0.05,
    ball_count=6,
    ball_diameter=0.005,
    groove_angle=45 * DEG,
    flank_friction=0.1,
    face_friction=0.01,
    spring_type="disc",
    disc_outer_diameter=0.040,
    disc_inner_diameter=0.0204,
    disc_thickness=0.001,
    disc_cone_height=0.002,
    disc_series=2,
    spring_deflection=0.0024,
    ball_lift=0.0004,
)


def checks(x):
    return {c.name: c for c in engine.run(BALL_CLUTCH, x).checks}


def test_helical_sentences_state_the_lengths_and_stresses():
    c = checks(ORDINARY)
    # travel = setting 30 mm + lift 2 mm + rim rise 5 (1 − sin 45°) = 33.4645 mm;
    # shortest 90 − 33.4645 = 56.54 mm; L_c + S_a = (8 + 2) 4 + (0.0015 · 32²/4 + 0.4) 8
    travel = 30 + 2 + 5 * (1 - math.sin(45 * DEG))
    need = 40 + (0.0015 * 32**2 / 4 + 0.1 * 4) * 8
    assert c["solid_length"].ok
    assert f"shortest working length {90 - travel:.4g} mm ≥" in c["solid_length"].detail
    assert f"L_c + S_a = {need:.4g} mm (EN 13906-1)" in c["solid_length"].detail
    # τ_zul = 0.5 R_m = 0.5 × 1740 MPa (EN 10270-1 DH at 4 mm)
    assert "permissible 870 MPa (at peak torque" in c["spring_stress_max"].detail
    assert "the spring cannot buckle (seating fixed_fixed)" in c["buckling"].detail


def test_disc_sentences_say_where_the_force_maximum_is_passed():
    # Almen–László, dF/ds = 0: s = h0 − √((h0² − 2t²)/3) = 2 − √6/3 mm for h0 = 2, t = 1 mm
    s_max = 2 - math.sqrt(6) / 3
    at_setting = checks(DISC)["falling_curve"]  # 2.4 mm over 2 discs: 1.2 mm each
    assert at_setting.ok
    assert f"(s = {s_max:.4g} mm per disc) at the setting" in at_setting.detail
    within = checks({**DISC, "spring_deflection": 0.0022})["falling_curve"]  # 1.1 mm each
    assert within.ok
    assert f"(s = {s_max:.4g} mm per disc) within the lift" in within.detail
    stress = checks(DISC)["spring_stress_max"]
    assert "permissible 1400 MPa" in stress.detail  # DISC_YIELD_DEFAULT, C60S/51CrV4


def test_the_disc_yield_strength_is_bounded_at_5_gpa():
    p = {q.name: q for q in asbuilt.params()}["disc_yield_strength"]
    assert p.maximum == 5e9 and p.default == 1400e6 == asbuilt.DISC_YIELD_DEFAULT


def test_a_disc_without_both_diameters_is_left_to_require_spring():
    for inner, outer in ((None, 0.040), (0.0204, None), (None, None)):
        x = {"spring_type": "disc", "disc_inner_diameter": inner, "disc_outer_diameter": outer}
        assert asbuilt.refused(x) == {}
    # a ring narrower than 5 % of its bore is refused by its inner diameter
    x = {"spring_type": "disc", "disc_inner_diameter": 0.039, "disc_outer_diameter": 0.040}
    assert asbuilt.refused(x) == {"disc_inner_diameter": True}
    x = {"spring_type": "disc", "disc_inner_diameter": 0.0204, "disc_outer_diameter": 0.040}
    assert asbuilt.refused(x) == {"disc_inner_diameter": False}


def test_warnings_name_the_proportions_and_the_nearest_wire():
    narrow = engine.run(BALL_CLUTCH, {**DISC, "disc_inner_diameter": 0.0267}).warnings
    assert any("De/Di = 1.5 is outside 1.75…2.5" in w for w in narrow)  # 40/26.7 = 1.498
    wide = engine.run(BALL_CLUTCH, {**DISC, "disc_inner_diameter": 0.0145}).warnings
    assert any("De/Di = 2.76 is outside 1.75…2.5" in w for w in wide)  # 40/14.5 = 2.759
    assert not any("De/Di" in w for w in engine.run(BALL_CLUTCH, DISC).warnings)  # 1.96
    odd = engine.run(BALL_CLUTCH, {**ORDINARY, "spring_wire_diameter": 0.0041}).warnings
    assert (
        "spring_wire_diameter = 4.1 mm is not a preferred size of EN 10270-1; "
        "the nearest is 4 mm" in odd
    )


def test_the_self_locking_sentence_states_the_angles_in_degrees():
    # α − atan f = 45° − atan 0.1 = 39.29°, against the 10° margin
    c = checks(ORDINARY)["self_locking"]
    assert c.ok
    assert c.detail.startswith(f"α − atan f = {45 - math.degrees(math.atan(0.1)):.3g}° ≥ 10°")
    # at 15° flanks with f = 0.1 the margin is 9.29° < 10°: the sentence says what to change
    tight = checks({**ORDINARY, "groove_angle": 15 * DEG})["self_locking"]
    assert not tight.ok
    assert tight.detail.startswith(f"α − atan f = {15 - math.degrees(math.atan(0.1)):.3g}° < 10°")
    assert "use flatter flanks" in tight.detail
