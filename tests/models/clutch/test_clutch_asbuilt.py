"""clutch.ball and clutch.ball_setting as built: lift characteristic, springs, checks, inverse.

Hand-computed values and limits: zero lift and α′ → 0 give the paper's results exactly,
the peak-force stress of the paper's case, a 30 mm preloaded ordinary spring, a
disc-spring clutch in the falling part of its curve.
"""

import math

import numpy as np
import pytest

import engine
from engine.models.clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING
from engine.physics import clutch as cl
from engine.physics import springs as sp
from tests.pins import pin

DEG = math.pi / 180
PAPER = dict(BALL_CLUTCH.examples[0])
C = 8e10 * 0.004**4 / (8 * 0.045**3 * 5)  # paper spring rate, 5618.66 N/m
TODAY = 0.05 * C * 0.004 / 2  # today's torque limit, 0.5618656 N·m


def run(spec, base=None, **kw):
    return engine.run(spec, {**(base or {}), **kw}, series=True)


def checks(result):
    return {c.name: c for c in result.checks}


def test_paper_case_stress_at_the_peak_force():
    r = run(BALL_CLUTCH, PAPER)
    v = r.results
    assert v["torque_limit"] == pytest.approx(TODAY, rel=1e-12)  # unchanged
    # the ball climbs the groove depth Δ = 4 mm: the spring reaches c (Δ + Δ)
    assert v["spring_force_at_peak"] == pytest.approx(2 * C * 0.004, rel=1e-12)
    assert v["peak_torque"] == pytest.approx(2 * TODAY, rel=1e-12)
    assert v["lift_at_peak"] == pytest.approx(0.004, rel=1e-12)
    kw = (4 * 11.25 - 1) / (4 * 11.25 - 4) + 0.615 / 11.25
    tau_peak = 8 * 2 * C * 0.004 * 0.045 * kw / (math.pi * 0.004**3)
    assert v["spring_stress_at_peak"] == pytest.approx(tau_peak, rel=1e-12)
    assert tau_peak / 1e6 == pytest.approx(90.77, abs=0.005)  # vs 45.38 MPa at the setting
    assert v["spring_stress_at_peak"] == pytest.approx(2 * v["spring_shear_stress"], rel=1e-12)
    # over the rim the ball rises (d/2)(1 − sin 45°) = 1.4645 mm more: the spring's maximum
    rim = 0.005 * (1 - math.sin(45 * DEG))
    assert v["total_lift"] == pytest.approx(0.004 + rim, rel=1e-12)
    assert v["spring_force_max"] == pytest.approx(C * (0.008 + rim), rel=1e-12)
    assert v["spring_stress_max"] / 1e6 == pytest.approx(107.39, abs=0.01)
    assert set(r.series) == {"lift", "torque_curve", "spring_force_curve", "spring_stress_curve"}
    # the torque is 0 (f = 0) when the balls ride on the face
    assert r.series["torque_curve"][-1] == pytest.approx(0.0, abs=1e-12)


def test_zero_lift_gives_todays_torque_limit_exactly():
    for f in (0.0, 0.1):
        v = run(BALL_CLUTCH, PAPER, ball_lift=0.0, flank_friction=f).results
        assert v["peak_torque"] == v["torque_limit"]
        assert v["spring_force_at_peak"] == v["spring_force"]
    assert run(BALL_CLUTCH, PAPER, ball_lift=0.0).results["torque_limit"] == pytest.approx(
        TODAY, rel=1e-12
    )


def test_driving_flank_angle_limits():
    # a driving wall parallel to the axis, no friction: today's eq. 1 exactly
    v = run(BALL_CLUTCH, PAPER, driving_groove_angle=0.0).results
    assert v["torque_limit"] == pytest.approx(TODAY, rel=1e-12)
    # under a pressure disc, equal inclined flanks: the ball climbs both, twice the push,
    # half the torque
    disc = {**PAPER, "flank_construction": "pressure_disc"}
    v = run(BALL_CLUTCH, disc, driving_groove_angle=45 * DEG).results
    assert v["torque_limit"] == pytest.approx(TODAY / 2, rel=1e-12)
    # α′ = 30°, α″ = 60°: push tan 30° + tan 60° = 4/√3
    v = run(BALL_CLUTCH, {**disc, "groove_angle": 60 * DEG}, driving_groove_angle=30 * DEG)
    assert v.results["torque_limit"] == pytest.approx(
        0.05 * C * 0.004 / 2 / (4 / math.sqrt(3)), rel=1e-12
    )
    # a free ball (the default) rides the flatter flank: push max(tan 30°, tan 60°) = √3
    v = run(BALL_CLUTCH, {**PAPER, "groove_angle": 60 * DEG}, driving_groove_angle=30 * DEG)
    assert v.results["torque_limit"] == pytest.approx(
        0.05 * C * 0.004 / 2 / math.sqrt(3), rel=1e-12
    )


def _numbers(result):
    return {k: v for k, v in result.results.items() if isinstance(v, float)}


def test_a_free_ball_is_the_one_flank_clutch_of_the_flatter_flank():
    # α′ ≤ α″: the ball never leaves the driving groove, every number is the plain clutch's
    plain = run(BALL_CLUTCH, ORDINARY)
    steep = run(BALL_CLUTCH, ORDINARY, driving_groove_angle=20 * DEG)
    assert _numbers(steep) == _numbers(plain)
    # α′ > α″: it rides the driving flank and over its rim, as a clutch of groove angle α′
    flat = run(BALL_CLUTCH, ORDINARY, groove_angle=40 * DEG, driving_groove_angle=55 * DEG)
    same = run(BALL_CLUTCH, ORDINARY, groove_angle=55 * DEG)
    assert _numbers(flat) == pytest.approx(_numbers(same), rel=1e-14)
    rate = 81.5e9 * 0.004**4 / (8 * 0.032**3 * 8)
    # by hand: peak at the rim, force c (30 + 2) mm over tan(55° − atan 0.1)
    peak = 0.05 * rate * 0.032 / (2 * math.tan(55 * DEG - math.atan(0.1)))
    assert flat.results["peak_torque"] == pytest.approx(peak, rel=1e-12)
    assert flat.results["total_lift"] == pytest.approx(
        0.002 + 0.005 * (1 - math.sin(55 * DEG)), rel=1e-12
    )
    note = next(n for n in flat.notes if "free_ball" in n)
    assert "rides the driving flank" in note


def test_self_locking_check_and_sensitivity():
    locked = run(BALL_CLUTCH, {**PAPER, "groove_angle": 30 * DEG}, flank_friction=0.577)
    c = checks(locked)["self_locking"]
    assert not c.ok and "friction" in c.detail
    assert locked.results["self_locking_margin"] == pytest.approx(30 * DEG - math.atan(0.577))
    fine = run(BALL_CLUTCH, PAPER, flank_friction=0.1)
    assert checks(fine)["self_locking"].ok
    # dT/df against a central difference of the torque limit
    h = 1e-6
    up = run(BALL_CLUTCH, PAPER, flank_friction=0.1 + h).results["torque_limit"]
    down = run(BALL_CLUTCH, PAPER, flank_friction=0.1 - h).results["torque_limit"]
    assert fine.results["friction_sensitivity"] == pytest.approx((up - down) / (2 * h), rel=1e-6)


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


def test_an_ordinary_30_mm_preloaded_spring_passes():
    r = run(BALL_CLUTCH, ORDINARY)
    assert all(c.ok for c in r.checks), [c for c in r.checks if not c.ok]
    v = r.results
    rate = 81.5e9 * 0.004**4 / (8 * 0.032**3 * 8)
    assert v["spring_force"] == pytest.approx(rate * 0.030, rel=1e-12)
    assert v["permissible_stress"] == 870e6  # 0.5 × 1740 MPa, EN 10270-1 at 4 mm
    assert v["tensile_strength"] == 1740e6
    assert v["solid_length"] == pytest.approx(0.040)  # (8 + 2) × 4 mm
    assert v["buckling_deflection"] is None  # fixed ends, L0/D = 2.8: cannot buckle
    # peak at the rim: force c (30 + 2) mm; tan(45° − atan 0.1) = 0.81818
    assert v["peak_torque"] == pytest.approx(0.05 * rate * 0.032 / (2 * 0.8181818181818), rel=1e-9)
    assert v["residual_torque"] == pytest.approx(
        0.01 * rate * (0.032 + 0.005 * (1 - math.sin(45 * DEG))) * 0.025, rel=1e-12
    )
    assert not r.warnings


def test_helical_spring_checks_fail_where_they_should():
    slender = run(
        BALL_CLUTCH, **{**ORDINARY, "spring_free_length": 0.30, "spring_seating": "fixed_free"}
    )
    assert not checks(slender)["buckling"].ok
    short = run(BALL_CLUTCH, {**ORDINARY, "spring_free_length": 0.075})
    assert not checks(short)["solid_length"].ok
    weak = run(BALL_CLUTCH, {**ORDINARY, "spring_material": "1.4310", "spring_deflection": 0.06})
    assert not checks(weak)["spring_stress_max"].ok
    odd = run(BALL_CLUTCH, {**ORDINARY, "spring_wire_diameter": 0.0041})
    assert any("4.25 mm" not in w and "not a preferred size" in w for w in odd.warnings)
    # Bergsträsser's factor gives a (slightly) lower stress than Wahl's
    b = run(BALL_CLUTCH, ORDINARY, stress_correction="bergstrasser").results
    w = run(BALL_CLUTCH, ORDINARY).results
    assert 0.985 < b["spring_stress_max"] / w["spring_stress_max"] < 1.0


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


def test_disc_spring_clutch_falls_after_breakaway():
    r = run(BALL_CLUTCH, DISC)
    v = r.results
    assert all(c.ok for c in r.checks), [c for c in r.checks if not c.ok]
    # setting 1.2 mm per disc, past the force maximum at 2 − √6/3 = 1.1835 mm
    single = sp.disc_force(0.0012, 0.040, 0.0204, 0.001, 0.002)
    assert v["spring_force"] == pytest.approx(single, rel=1e-12)
    assert v["torque_limit"] == pytest.approx(
        0.05 * single / (2 * math.tan(45 * DEG - math.atan(0.1))), rel=1e-12
    )
    assert v["peak_torque"] == v["torque_limit"] and v["lift_at_peak"] == 0.0
    flank = np.asarray(r.series["torque_curve"][:41])
    assert np.all(np.diff(flank) < 0)  # falls all along the flank
    assert v["torque_at_rim"] == pytest.approx(flank[-1], rel=1e-12)
    assert v["torque_at_rim"] < v["peak_torque"]
    assert v.get("spring_index") is None and v.get("spring_shear_stress") is None
    assert v["disc_force_flat"] == pytest.approx(
        sp.disc_force_flat(0.040, 0.0204, 0.001, 0.002), rel=1e-12
    )
    # a rising disc (h0/t = 1) fails the falling-curve check; pressing past flat fails too
    rising = run(BALL_CLUTCH, {**DISC, "disc_cone_height": 0.001, "spring_deflection": 0.001})
    assert not checks(rising)["falling_curve"].ok
    flat = run(BALL_CLUTCH, {**DISC, "disc_series": 1, "spring_deflection": 0.0012})
    assert not checks(flat)["disc_not_past_flat"].ok


def test_setting_for_a_target_peak_torque_round_trips():
    setting = run(
        BALL_CLUTCH_SETTING,
        **{k: v for k, v in ORDINARY.items() if k != "spring_deflection"},
        target_torque=8.0,
    )
    v = setting.results
    back = run(BALL_CLUTCH, {**ORDINARY, "spring_deflection": v["required_peak_setting"]})
    assert back.results["peak_torque"] == pytest.approx(8.0, rel=1e-9)
    assert v["peak_setting_stress_max"] == pytest.approx(
        back.results["spring_stress_max"], rel=1e-9
    )
    # the suggested wire is a preferred size that reaches the target within 0.5 R_m
    d = v["suggested_wire_diameter"]
    assert sp.nearest_standard_wire(d)[1]
    trial = {
        **ORDINARY,
        "spring_wire_diameter": d,
        "spring_deflection": v["suggested_wire_setting"],
    }
    res = run(BALL_CLUTCH, **trial).results
    assert res["peak_torque"] == pytest.approx(8.0, rel=1e-9)
    assert res["spring_stress_max"] <= res["permissible_stress"]
    # the next thinner preferred wire does not
    thinner = sp.STANDARD_WIRE_DIAMETERS[sp.STANDARD_WIRE_DIAMETERS.index(round(d * 1e3, 2)) - 1]
    if 0.032 / (thinner * 1e-3) <= 12:
        s2 = run(
            BALL_CLUTCH_SETTING,
            {k: v for k, v in ORDINARY.items() if k != "spring_deflection"},
            spring_wire_diameter=thinner * 1e-3,
            target_torque=8.0,
        ).results
        too_weak = s2["peak_setting_stress_max"] > 0.5 * sp.tensile_strength(
            "EN10270-1-DH", thinner * 1e-3
        )
        d2 = thinner * 1e-3
        travel = s2["required_peak_setting"] + 0.002 + 0.005 * (1 - math.sin(45 * DEG))
        room = sp.solid_length(d2, 8.0) + sp.minimum_gap_sum(d2, 0.032, 8.0)
        assert too_weak or 0.090 - travel < room  # over-stressed, or it would go solid


def test_setting_without_lift_keeps_todays_numbers():
    ex = dict(BALL_CLUTCH_SETTING.examples[0])
    v = run(BALL_CLUTCH_SETTING, **ex).results
    # today's: Δ = 8 F D³ i_p/(G d0⁴) with F = 2 T tan α / D0 = 20 N
    assert v["required_spring_force"] == pytest.approx(20.0, rel=1e-12)
    assert v["required_deflection"] == pytest.approx(20.0 / C, rel=1e-12)
    # the peak setting with the paper's lift (= Δ): the spring reaches 2cΔ at the rim
    assert v["required_peak_setting"] == pytest.approx(10.0 / C, rel=1e-9)


def test_disc_setting_and_suggested_pack():
    base = {k: v for k, v in DISC.items() if k != "spring_deflection"}
    v = run(BALL_CLUTCH_SETTING, **base, target_torque=60.0).results
    back = run(BALL_CLUTCH, {**DISC, "spring_deflection": v["required_deflection"]}).results
    assert back["torque_limit"] == pytest.approx(60.0, rel=1e-9)
    peak = run(BALL_CLUTCH, {**DISC, "spring_deflection": v["required_peak_setting"]})
    assert peak.results["peak_torque"] == pytest.approx(60.0, rel=1e-9)
    assert v["suggested_disc_parallel"] == 1
    more = run(BALL_CLUTCH_SETTING, **base, target_torque=100.0).results
    assert more["suggested_disc_parallel"] == 2
    pack = run(
        BALL_CLUTCH,
        **{**DISC, "disc_parallel": 2, "spring_deflection": more["suggested_disc_setting"]},
    ).results
    assert pack["peak_torque"] == pytest.approx(100.0, rel=1e-9)


def test_sizing_from_the_drive():
    # 1.5 kW at 1500 rpm: 9.549 N·m; service factor 2
    tn = cl.rated_torque(1500.0, 1500 * math.pi / 30)
    assert tn == pytest.approx(9.5493, rel=1e-4)
    # a motor of 2.5 T_N starting a load of twice its inertia: 2/3 of it through the coupling
    ta = cl.acceleration_torque(2.5 * tn, 0.01, 0.02)
    assert ta == pytest.approx(2.5 * tn * 2 / 3, rel=1e-12)
    # 2 T_N = 19.1 N·m covers the start (15.9 N·m); with factor 1.5 the start governs
    assert cl.required_slip_torque(tn, 2.0, ta) == pytest.approx(2 * tn)
    assert cl.required_slip_torque(tn, 1.5, ta) == pytest.approx(ta)
    assert cl.required_slip_torque(tn, 2.0, 0.0) == pytest.approx(2 * tn)
    # a load torque shares by the other inertia: T_L J_A/(J_A + J_L)
    assert cl.acceleration_torque(0.0, 0.01, 0.03, 4.0) == pytest.approx(1.0)


def test_nutrunner_coupling_1_gets_its_slip_torque():
    from engine.models.nutrunner import NUTRUNNER_DRIVE

    ex = dict(NUTRUNNER_DRIVE.examples[0])
    v = engine.run(NUTRUNNER_DRIVE, ex).results
    # K P/ω = 2 × 1100 W / 146.6 rad/s = 15.006 N·m
    assert v["coupling_slip_torque"] == pytest.approx(
        2.0 * ex["motor_power"] / ex["motor_speed"], rel=1e-12
    )
    k3 = engine.run(NUTRUNNER_DRIVE, {**ex, "coupling_service_factor": 3.0}).results
    assert k3["coupling_slip_torque"] == pytest.approx(1.5 * v["coupling_slip_torque"])
    # a motor with a large breakdown torque: the start through the coupling governs
    strong = engine.run(
        NUTRUNNER_DRIVE, {**ex, "breakdown_torque": 200.0, "rotor_inertia": 1e-3}
    ).results
    j_load = v["equivalent_inertia"] - 2 * v["coupling_energy"] / ex["motor_speed"] ** 2
    j_drive = 1e-3 + 2 * v["coupling_energy"] / ex["motor_speed"] ** 2
    assert strong["coupling_slip_torque"] == pytest.approx(
        max(200.0 * j_load / (j_drive + j_load), v["coupling_slip_torque"]), rel=1e-9
    )


def _first_bracket_one_by_one(x, spring, target, upper):
    """The setting search's bracket as it was before issue 21's one-call grid: a
    characteristic per grid point, the first at or past the target (the reference);
    None where none reaches it, (0, 0) where the seated peak is the target."""
    from engine.procedures import clutch_asbuilt as asbuilt

    def peak(delta):
        return float(asbuilt.characteristic(x, spring, delta)["peak_torque"]) - target

    lo_val = peak(0.0)
    if lo_val >= 0.0:
        return (0.0, 0.0) if lo_val == 0.0 else None
    grid = np.linspace(0.0, upper, 65)
    prev = 0.0
    for g in grid[1:]:
        if peak(float(g)) >= 0.0:
            return prev, float(g)
        prev = float(g)
    return None


def _crosses_within(x, spring, target, root, tol):
    """True where the peak torque crosses the target within ``tol`` of ``root``: below it
    at root − tol (or at the bracket's low end), at or above it at root + tol."""
    from engine.procedures import clutch_asbuilt as asbuilt

    def peak(delta):
        return float(asbuilt.characteristic(x, spring, delta)["peak_torque"]) - target

    return peak(max(root - tol, 0.0)) <= 0.0 <= peak(root + tol)


def test_the_setting_search_on_one_grid_call_is_the_point_by_point_search():
    # disc stacks whose peak torque rises, flattens and falls with the setting (h0/t from
    # 1 to 2.2, 1 to 3 in series, 1 to 3 in parallel) and targets across and beyond their
    # reach: no later than the first grid point a characteristic per grid point finds
    # at or past the target, and a root within Newton's stated tolerance (1e-12 m) of
    # where the peak crosses the target
    from engine.procedures import clutch_asbuilt as asbuilt

    rng = np.random.default_rng(11)
    found = missed = 0
    for _ in range(40):
        design = {
            **DISC,
            "disc_cone_height": float(rng.uniform(1.0, 2.2)) * DISC["disc_thickness"],
            "disc_series": int(rng.integers(1, 4)),
            "disc_parallel": int(rng.integers(1, 4)),
            "ball_lift": float(rng.uniform(0.0001, 0.0008)),
        }
        x, _ = BALL_CLUTCH.validate(design)
        spring = asbuilt.Spring(x)
        upper = float(x["disc_series"] * x["disc_cone_height"])
        top = float(asbuilt.characteristic(x, spring, upper)["peak_torque"])
        for target in rng.uniform(0.05, 1.3, 3) * max(top, 1.0):
            want = _first_bracket_one_by_one(x, spring, float(target), upper)
            got = asbuilt.solve_setting(x, spring, float(target), upper)
            # no later than the grid's first crossing (earlier where the peak reaches the
            # target between grid points: test_the_setting_is_the_first_crossing_*)
            assert want is None or (got is not None and got <= want[1]), (design, target)
            if got is not None:
                assert _crosses_within(x, spring, float(target), got, 1e-12), (design, target)
            found += want is not None
            missed += want is None
    assert found >= 40 and missed >= 10, (found, missed)


def test_the_suggested_pack_reuses_the_given_stacks_search_and_finds_what_a_fresh_search_finds():
    # the given stack's own number of discs in parallel is not searched twice; the answer
    # is still the fewest discs, each count searched from scratch (the reference)
    from engine.procedures import clutch_asbuilt as asbuilt

    rng = np.random.default_rng(3)
    counts = set()
    for _ in range(30):
        design = {
            **DISC,
            "disc_parallel": int(rng.integers(1, 4)),
            "disc_cone_height": float(rng.uniform(1.2, 2.0)) * DISC["disc_thickness"],
        }
        x, _ = BALL_CLUTCH.validate(design)
        target = float(rng.uniform(20.0, 400.0))
        setting = {k: v for k, v in design.items() if k != "spring_deflection"}
        force = run(BALL_CLUTCH_SETTING, {**setting, "target_torque": target}).results[
            "required_spring_force"
        ]
        values, _ = asbuilt.setting_values({**x, "target_torque": target}, force)
        want: dict = {}
        for n in range(1, 9):
            trial = {**x, "target_torque": target, "disc_parallel": n}
            delta, stress = asbuilt.peak_setting(trial, asbuilt.Spring(trial), target, force)
            if not math.isnan(delta) and stress <= float(x["disc_yield_strength"]):
                want = {"suggested_disc_parallel": n, "suggested_disc_setting": delta}
                break
        got = {k: values[k] for k in want} if want else {}
        assert got == want, (design, target)
        assert ("suggested_disc_parallel" in values) == bool(want)
        counts.add(want.get("suggested_disc_parallel"))
    assert len(counts) >= 3, counts  # packs of several sizes, and some with none


def test_the_suggestions_are_the_first_candidates_that_pass_by_a_search_of_our_own():
    """The suggested wire is the thinnest preferred size (index 4…12) whose peak setting for
    the target keeps the spring within its permissible stress and off its solid length; the
    suggested pack the fewest discs in parallel within the disc's yield strength. Both found
    here by a search of the test's own over the candidates, each candidate's peak setting
    checked in clutch.ball (the forward model), and compared as values."""
    target = 8.0
    base = {k: v for k, v in ORDINARY.items() if k != "spring_deflection"}
    got = run(BALL_CLUTCH_SETTING, base, target_torque=target).results
    want_wire = want_setting = None
    for d_mm in sp.STANDARD_WIRE_DIAMETERS:
        d = d_mm * 1e-3
        if not 4.0 <= 0.032 / d <= 12.0:
            continue
        one = run(BALL_CLUTCH_SETTING, base, spring_wire_diameter=d, target_torque=target)
        delta = one.results.get("required_peak_setting")
        if delta is None:
            continue
        v = run(BALL_CLUTCH, {**base, "spring_wire_diameter": d, "spring_deflection": delta})
        at = v.results
        assert at["peak_torque"] == pytest.approx(target, rel=1e-9)
        room = sp.solid_length(d, 8.0) + sp.minimum_gap_sum(d, 0.032, 8.0)
        fits = 0.090 - (delta + at["total_lift"]) >= room
        if at["spring_stress_max"] <= at["permissible_stress"] and fits:
            want_wire, want_setting = d, delta
            break
    assert want_wire is not None
    wire, setting = got["suggested_wire_diameter"], got["suggested_wire_setting"]
    pin("clutch.ball_setting", "suggested_wire_diameter", wire, want_wire, rel=1e-12)
    pin("clutch.ball_setting", "suggested_wire_setting", setting, want_setting, rel=1e-9)

    disc = {k: v for k, v in DISC.items() if k != "spring_deflection"}
    yield_strength = BALL_CLUTCH_SETTING.param("disc_yield_strength").default
    more = run(BALL_CLUTCH_SETTING, disc, target_torque=100.0).results
    want_pack = None
    for n in range(1, 9):
        one = run(BALL_CLUTCH_SETTING, disc, disc_parallel=n, target_torque=100.0).results
        delta = one.get("required_peak_setting")
        if delta is None or one["peak_setting_stress_max"] > yield_strength:
            continue
        at = run(BALL_CLUTCH, {**DISC, "disc_parallel": n, "spring_deflection": delta}).results
        assert at["peak_torque"] == pytest.approx(100.0, rel=1e-9)
        want_pack = (n, delta)
        break
    assert want_pack is not None and more["suggested_disc_parallel"] == want_pack[0]
    pack = more["suggested_disc_setting"]
    pin("clutch.ball_setting", "suggested_disc_setting", pack, want_pack[1], rel=1e-9)


def test_the_wire_stress_follows_the_chosen_correction():
    # EN 13906-1: τ_k = k 8 F D/(π d³); w = 32/4 = 8, Bergsträsser k = 8.5/7.25, Wahl
    # k = 31/28 + 0.615/8; the ordinary spring at 30 mm
    rate = 81.5e9 * 0.004**4 / (8 * 0.032**3 * 8)
    nominal = 8 * rate * 0.030 * 0.032 / (math.pi * 0.004**3)
    k_b, k_w = 8.5 / 7.25, 31 / 28 + 0.615 / 8
    b = run(BALL_CLUTCH, ORDINARY, stress_correction="bergstrasser").results
    w = run(BALL_CLUTCH, ORDINARY).results
    pin("clutch.ball", "spring_shear_stress", b["spring_shear_stress"], k_b * nominal, rel=1e-12)
    pin("clutch.ball", "spring_shear_stress", w["spring_shear_stress"], k_w * nominal, rel=1e-12)
    assert k_b * nominal / 1e6 == pytest.approx(445.53, abs=0.01)  # vs 449.94 (Wahl)
    # the setting's stresses too: the required force 2 T tan(45° − atan 0.1)/D0 at 1 N·m
    design = {k: v for k, v in ORDINARY.items() if k != "spring_deflection"}
    s = run(BALL_CLUTCH_SETTING, design, target_torque=1.0, stress_correction="bergstrasser")
    force = 2 * 1.0 * math.tan(45 * DEG - math.atan(0.1)) / 0.05
    pin(
        "clutch.ball_setting",
        "spring_shear_stress",
        s.results["spring_shear_stress"],
        k_b * 8 * force * 0.032 / (math.pi * 0.004**3),
        rel=1e-12,
    )


def _buckling_by_hand(l0, dm, nu, g, e):
    """EN 13906-1: s_K = L0 (1 − √(1 − (1 − G/E)/(0.5 + G/E) (π D/(ν L0))²)) 0.5/(1 − G/E)."""
    ratio = g / e
    root = 1 - (1 - ratio) / (0.5 + ratio) * (math.pi * dm / (nu * l0)) ** 2
    return l0 * 0.5 / (1 - ratio) * (1 - math.sqrt(root))


def test_a_custom_wires_elastic_modulus_is_an_input():
    slender = {
        **ORDINARY,
        "spring_material": "custom",
        "shear_modulus": 8e10,
        "allowable_shear_stress": 8e8,
        "spring_free_length": 0.30,
        "spring_seating": "fixed_free",
    }
    # absent: E = 2 G (1 + 0.3) = 208 GPa, said in the notes
    r = run(BALL_CLUTCH, slender)
    want = _buckling_by_hand(0.30, 0.032, 2.0, 8e10, 208e9)
    pin("clutch.ball", "buckling_deflection", r.results["buckling_deflection"], want, rel=1e-12)
    assert any("E = 208 GPa = 2 G (1 + ν)" in n for n in r.notes)
    # given: EN 13906-1's 206 GPa for spring steel moves s_K
    r = run(BALL_CLUTCH, slender, spring_elastic_modulus=206e9)
    want = _buckling_by_hand(0.30, 0.032, 2.0, 8e10, 206e9)
    pin("clutch.ball", "buckling_deflection", r.results["buckling_deflection"], want, rel=1e-12)
    assert r.results["buckling_deflection"] * 1e3 == pytest.approx(want * 1e3)
    # a material's E overrides it (EN 13906-1: 206 GPa for DH wire)
    dh = run(BALL_CLUTCH, ORDINARY, spring_free_length=0.30, spring_seating="fixed_free")
    with_e = run(
        BALL_CLUTCH,
        ORDINARY,
        spring_free_length=0.30,
        spring_seating="fixed_free",
        spring_elastic_modulus=190e9,
    )
    want = _buckling_by_hand(0.30, 0.032, 2.0, 81.5e9, 206e9)
    assert dh.results["buckling_deflection"] == pytest.approx(want, rel=1e-12)
    assert with_e.results["buckling_deflection"] == dh.results["buckling_deflection"]
    # outside 2 G … 3 G (Poisson's ratio 0…0.5): refused, naming the field and the range
    for e in (1.5e11, 2.5e11):
        with pytest.raises(engine.InputOutOfRange, match="160000 … 240000 MPa") as err:
            run(BALL_CLUTCH, slender, spring_elastic_modulus=e)
        assert err.value.field == "spring_elastic_modulus"


def test_disc_stack_setting_on_the_array_path_equals_single_runs():
    # targets across the stack's reach, and parallel packs of 1…3 and steep cones: the
    # root searches of a sweep take the same steps as a single run's
    from tests.models.clutch.test_clutch_arrays import FLOATS, _array_path_used

    base = {k: v for k, v in DISC.items() if k != "spring_deflection"}
    for changes in ({}, {"ball_lift": None}, {"disc_parallel": 3}, {"disc_cone_height": 0.0013}):
        design = {**base, **changes, "target_torque": 50.0}
        targets = np.geomspace(0.5, 1500.0, 11)
        assert "required_peak_setting" in _array_path_used(
            BALL_CLUTCH_SETTING, design, {"target_torque": targets}
        )
        s = engine.sweep(BALL_CLUTCH_SETTING, design, "target_torque", targets.tolist()).results
        for j, t in enumerate(targets.tolist()):
            one = run(BALL_CLUTCH_SETTING, {**design, "target_torque": t}).results
            for name in FLOATS[BALL_CLUTCH_SETTING.name]:
                assert s.get(name, [None] * 11)[j] == one.get(name), (changes, t, name)
        for name in ("required_peak_setting", "required_deflection", "suggested_disc_setting"):
            found = [v is not None for v in s[name]]
            assert any(found) and not all(found), (changes, name)  # reached, and not


def test_a_setting_search_over_targets_alone_scans_the_shared_grid_once_to_the_same_roots():
    # a varied target leaves the characteristic the same at every point (one grid scan
    # for all); a varied geometry bisects each point's own grid where its peak rises and
    # scans on from there: the same roots to the last bit where the geometry varies in
    # name only, and the same nulls, for rising, falling and past-flat negative discs
    from engine.procedures import clutch_asbuilt as asbuilt

    rng = np.random.default_rng(5)
    cases = [(r, lift) for r in (1.0, 1.2, 1.6, 2.0, 2.2, 3.0) for lift in (0.0004, None)]
    for ratio, lift in cases:
        design = {**DISC, "disc_cone_height": ratio * DISC["disc_thickness"], "ball_lift": lift}
        x, _ = BALL_CLUTCH.validate(design)
        upper = float(x["disc_series"] * x["disc_cone_height"])
        top = float(asbuilt.characteristic(x, asbuilt.Spring(x), upper)["peak_torque"])
        targets = rng.uniform(0.05, 1.3, 40) * top
        shared = asbuilt.setting_roots({**x, "target_torque": targets}, targets, upper)
        thickness = np.full(40, x["disc_thickness"])  # varied in name: each point scanned
        scanned = asbuilt.setting_roots(
            {**x, "target_torque": targets, "disc_thickness": thickness}, targets, upper
        )
        np.testing.assert_array_equal(shared, scanned)
        assert np.isfinite(shared).sum() >= 10 and np.isnan(shared).sum() >= 2, ratio


def test_a_disc_stacks_end_values_are_the_characteristics():
    # |σ_OM| grows with the deflection and the lift along the grid: its largest value
    # over the 81 points is the last point's, the same float
    from engine.procedures import clutch_asbuilt as asbuilt

    for lift in (0.0004, None):
        x, _ = BALL_CLUTCH.validate({**DISC, "ball_lift": lift})
        spring = asbuilt.Spring(x)
        settings = np.linspace(0.0, 0.004, 17)
        c = asbuilt.characteristic({**x, "spring_deflection": settings}, spring, settings)
        total_lift, stress = asbuilt._disc_stack_end(x, spring, settings)
        np.testing.assert_array_equal(total_lift, c["total_lift"])
        np.testing.assert_array_equal(stress, c["spring_stress_max"])


@pytest.mark.parametrize("refine", [1, 8])
@pytest.mark.parametrize("ratio", [1.0, 1.6, 2.2, 3.0])
@pytest.mark.parametrize("size", [65, 3])
def test_the_peak_over_the_curves_that_can_hold_it_is_the_peak_over_all(ratio, size, refine):
    # rising, flattening, falling and past-flat negative discs: at settings across
    # every interval of the search's grid (its ends and its force extrema included),
    # the peak over the few curves the bounds keep is the 81-point peak, to the last bit;
    # on a coarse grid (3 settings) a curve's peak inside an interval must be bounded too
    from engine.procedures import clutch_asbuilt as asbuilt

    design = {**DISC, "disc_cone_height": ratio * DISC["disc_thickness"], "ball_lift": 0.0004}
    x, _ = BALL_CLUTCH.validate(design)
    spring = asbuilt.Spring(x)
    grid = np.linspace(0.0, x["disc_series"] * x["disc_cone_height"], size)
    curves = asbuilt._Curves.of(x, grid, refine)
    assert curves is not None
    if size == 65:
        assert np.max(curves.counts) < 41  # the bounds leave out most curves
    if refine > 1:  # fewer still on the finer grid
        assert np.max(curves.counts) < np.max(asbuilt._Curves.of(x, grid).counts)
    rng = np.random.default_rng(int(ratio * 10))
    span = np.repeat(np.arange(1, size), 400 // size)
    settings = grid[span - 1] + rng.uniform(0.0, 1.0, span.size) * (grid[span] - grid[span - 1])
    extrema = np.asarray(sp.disc_falling_region(x["disc_thickness"], x["disc_cone_height"]))
    settings[: size - 1] = grid[1:]  # the grid points themselves
    span[: size - 1] = np.arange(1, size)
    for s_at in extrema[np.isfinite(extrema)] * x["disc_series"]:
        near = np.clip(np.searchsorted(grid, s_at - curves.lift), 1, size - 1)
        settings = np.concatenate([settings, s_at - curves.lift])
        span = np.concatenate([span, near])
    inside = (settings >= 0.0) & (settings <= grid[-1])
    settings, span = settings[inside], span[inside]
    want = asbuilt.characteristic(x, spring, settings, peak_only=True)["peak_torque"]
    np.testing.assert_array_equal(curves.peak(settings, span), want)


@pytest.mark.parametrize("ratio", [1.0, 2.2, 3.0])
def test_every_curve_stays_within_its_bounds_in_every_interval(ratio):
    # dense settings inside each interval of the grid: no curve leaves the bounds that
    # choose which curves can hold the peak (its force extremum inside included)
    from engine.procedures import clutch_asbuilt as asbuilt

    design = {**DISC, "disc_cone_height": ratio * DISC["disc_thickness"], "ball_lift": 0.0004}
    x, _ = BALL_CLUTCH.validate(design)
    grid = np.linspace(0.0, x["disc_series"] * x["disc_cone_height"], 65)
    curves = asbuilt._Curves.of(x, grid)
    assert curves is not None
    upper, lower, _ = curves.bounds(grid)
    every = np.arange(curves.lift.size)
    tiny = 1e-12 * float(np.max(np.abs(upper)))
    inside_max = 0
    for j in range(64):
        settings = np.linspace(grid[j], grid[j + 1], 101)[:, None]
        torque = curves.torque(settings, every)
        assert np.all(torque <= upper[j] + tiny), j
        assert np.all(torque >= lower[j] - tiny), j
        inside_max += int(np.sum(np.max(torque[1:-1], axis=0) > np.maximum(torque[0], torque[-1])))
    if ratio > 2.0:
        assert inside_max > 0  # some curve peaks inside an interval: the ends alone miss it


def test_newton_on_many_brackets_finds_each_root_alone():
    # a flat start (x³, zero slope at 0), a far overshoot (atan: bisection takes over),
    # roots at the bracket's ends and brackets without a crossing; each lane against
    # its closed-form root, and alone the same float as among the others
    from engine.procedures.clutch_asbuilt import newton_roots

    rng = np.random.default_rng(7)
    c = rng.uniform(0.01, 5.0, 50)
    r = rng.uniform(-5.0, 5.0, 50)

    def f(x, lanes):
        kind = lanes % 2 == 0
        cube = (x**3 - c[lanes], 3 * x**2)
        turn = (np.arctan(x - r[lanes]), 1.0 / (1.0 + (x - r[lanes]) ** 2))
        return np.where(kind, cube[0], turn[0]), np.where(kind, cube[1], turn[1])

    lanes = np.arange(50)
    a = np.where(lanes % 2 == 0, 0.0, -10.0)
    b = np.where(lanes % 2 == 0, 2.0, 30.0)
    fa, fb = f(a, lanes)[0], f(b, lanes)[0]
    got = newton_roots(f, a, b, fa, fb, xtol=1e-12, rtol=1e-12)
    want = np.where(lanes % 2 == 0, np.cbrt(c), r)
    crossing = (fa < 0) & (fb > 0)
    assert crossing.sum() > 30 and np.isnan(got[~crossing]).all()
    assert np.all(np.abs(got - want)[crossing] <= 1e-12 * (1 + np.abs(want[crossing])))
    for j in np.flatnonzero(crossing)[:10]:
        alone = newton_roots(
            lambda x, _, j=j: f(x, np.full(np.size(x), j)), a[j], b[j], fa[j], fb[j], 1e-12, 1e-12
        )
        assert alone[0] == got[j]
    # an end where the function is zero is the root; no crossing: NaN
    ends = newton_roots(f, [0.0, 0.0], [2.0, 2.0], [0.0, -1.0], [1.0, 0.0], 1e-12, 1e-12)
    assert ends.tolist() == [0.0, 2.0]
    assert np.isnan(newton_roots(f, [0.0], [2.0], [1.0], [2.0], 1e-12, 1e-12)).all()


def _disc_setting_case(ratio):
    from engine.procedures import clutch_asbuilt as asbuilt

    design = {**DISC, "disc_cone_height": ratio * DISC["disc_thickness"], "ball_lift": 0.0004}
    x, _ = BALL_CLUTCH.validate(design)
    upper = float(x["disc_series"] * x["disc_cone_height"])
    grid = np.linspace(0.0, upper, 65)
    peaks = asbuilt.characteristic(x, asbuilt.Spring(x), grid, peak_only=True)["peak_torque"]
    return dict(x), upper, grid, np.asarray(peaks)


def test_a_target_on_a_grid_point_at_the_flat_top_or_out_of_reach():
    # the target exactly the peak at a grid point: that point; just under the grid's
    # largest peak of a falling stack (a flat crossing, the slope ~0): within 1e-12 m of
    # the crossing; above the top or at zero (the seated peak overshoots it): NaN; one
    # design as in a sweep
    from engine.procedures import clutch_asbuilt as asbuilt

    x, upper, grid, peaks = _disc_setting_case(2.2)
    spring = asbuilt.Spring(x)
    top = float(np.max(peaks))
    assert 0 < np.argmax(peaks) < 64  # the peak torque falls past its top
    at_point = float(peaks[20])
    assert np.all(np.diff(peaks[:21]) > 0)  # rising up to there: grid point 20 is the first
    targets = np.array([at_point, top * (1 - 1e-9), top * 1.01, 0.0])
    swept = asbuilt.setting_roots({**x, "target_torque": targets}, targets, upper)
    one = [asbuilt.setting_roots({**x, "target_torque": t}, float(t), upper) for t in targets]
    np.testing.assert_array_equal(swept, one)
    assert swept[0] == grid[20]
    assert _crosses_within(x, spring, float(targets[1]), float(swept[1]), 1e-12)
    assert np.isnan(swept[2:]).all()


def test_the_breakaway_setting_on_its_grid_and_against_the_force():
    # forces across the rising branch, one exactly the force at a grid point (that point),
    # one above the stack's largest (NaN); the stack varied in name only (each point its
    # own grid) gives the same floats; each root within the tolerance of the force's
    # crossing (bisection to the neighbouring floats)
    from engine.procedures import clutch_asbuilt as asbuilt

    x, _ = BALL_CLUTCH.validate(DISC)
    x = dict(x)
    spring = asbuilt.Spring(x)
    s_max = float(sp.disc_falling_region(x["disc_thickness"], x["disc_cone_height"])[0])
    upper = x["disc_series"] * s_max
    grid = np.linspace(0.0, upper, 65)
    largest = float(spring.force(upper))
    forces = np.concatenate([np.linspace(0.01, 0.99, 9) * largest, [1.01 * largest]])
    forces[3] = float(spring.force(grid[17]))
    got = asbuilt.disc_breakaway_setting(x, forces)
    varied = {**x, "disc_thickness": np.full(forces.size, x["disc_thickness"])}
    np.testing.assert_array_equal(asbuilt.disc_breakaway_setting(varied, forces), got)
    assert got[3] == grid[17] and np.isnan(got[-1])
    assert asbuilt.disc_breakaway_setting(x, float(forces[5])) == got[5]
    for force, root in zip(forces[:-1].tolist(), got[:-1].tolist(), strict=True):
        lo, hi = 0.0, upper
        while (mid := 0.5 * (lo + hi)) not in (lo, hi):
            lo, hi = (mid, hi) if float(spring.force(mid)) < force else (lo, mid)
        assert abs(root - lo) <= 1e-13 + 1e-12 * root, (force, root, lo)


@pytest.mark.parametrize("ratio", [1.0, 2.2])
def test_a_large_sweep_on_finer_candidates_finds_the_roots_of_small_ones(ratio):
    # from _FINE_LANES points on, the curves' candidates come from a finer grid: the same
    # roots, to the last bit, as the same targets searched a few at a time
    from engine.procedures import clutch_asbuilt as asbuilt

    x, upper, _, peaks = _disc_setting_case(ratio)
    n = asbuilt._FINE_LANES + 100
    targets = np.random.default_rng(3).uniform(0.01, 1.05, n) * float(np.max(peaks))
    big = asbuilt.setting_roots({**x, "target_torque": targets}, targets, upper)
    parts = [targets[i : i + 1000] for i in range(0, n, 1000)]
    small = np.concatenate(
        [asbuilt.setting_roots({**x, "target_torque": t}, t, upper) for t in parts]
    )
    np.testing.assert_array_equal(big, small)
    assert np.isfinite(big).sum() > n // 2 and np.isnan(big).sum() > 100


def _random_disc_cases(seed, count):
    """Random disc-stack clutches (h0/t 1…3, 1…3 in series and in parallel, ball lift
    given or following the setting) with a target each: anywhere under the grid's
    largest peak, just under it (where the peak can rise above it and fall back between
    two grid points) or just over it (reached only between grid points, or not at all).
    """
    from engine.procedures import clutch_asbuilt as asbuilt

    rng = np.random.default_rng(seed)
    for _ in range(count):
        design = {
            **DISC,
            "disc_cone_height": float(rng.uniform(1.0, 3.0)) * DISC["disc_thickness"],
            "disc_series": int(rng.integers(1, 4)),
            "disc_parallel": int(rng.integers(1, 4)),
            "ball_diameter": float(rng.uniform(0.004, 0.008)),
            "groove_angle": float(rng.uniform(35, 55)) * DEG,
            "flank_friction": float(rng.uniform(0.05, 0.2)),
            "ball_lift": None if rng.uniform() < 0.3 else float(rng.uniform(0.0001, 0.0008)),
        }
        x, _ = BALL_CLUTCH.validate(design)
        x = dict(x)
        upper = float(x["disc_series"] * x["disc_cone_height"])
        grid = np.linspace(0.0, upper, 65)
        peaks = asbuilt.characteristic(x, asbuilt.Spring(x), grid, peak_only=True)
        top = float(np.max(peaks["peak_torque"]))
        kind = rng.integers(0, 3)
        if kind == 0:
            target = float(rng.uniform(0.05, 1.0)) * top
        elif kind == 1:
            target = top * (1 - 10 ** rng.uniform(-7, -2))
        else:
            target = top * (1 + 10 ** rng.uniform(-9, -4))
        yield x, upper, target


def _first_crossing_by_scan(x, target, upper, points=100_001):
    """The least setting whose peak torque reaches ``target``, by brute force: the first
    of ``points`` equal steps over [0, upper] at or past it, then bisection to
    neighbouring floats; 0.0 where the seated peak is the target, NaN where it is
    above it or no step reaches it."""
    from engine.procedures import clutch_asbuilt as asbuilt

    spring = asbuilt.Spring(x)

    def peak(delta):
        delta = np.atleast_1d(np.asarray(delta, dtype=float))
        return np.asarray(asbuilt.characteristic(x, spring, delta, peak_only=True)["peak_torque"])

    seated = float(peak(0.0)[0])
    if seated >= target:
        return 0.0 if seated == target else math.nan
    scan = np.linspace(0.0, upper, points)
    values = np.concatenate([peak(scan[i : i + 10_000]) for i in range(0, points, 10_000)])
    reached = np.flatnonzero(values >= target)
    if not reached.size:
        return math.nan
    lo, hi = float(scan[reached[0] - 1]), float(scan[reached[0]])
    while (mid := 0.5 * (lo + hi)) not in (lo, hi):
        lo, hi = (lo, mid) if float(peak(mid)[0]) >= target else (mid, hi)
    return hi


def _the_first_crossing(x, upper, target):
    """The setting search's root for one design, equal to the same point in an array of
    designs (each point's own grid) and within 1e-12 m of the brute-force first
    crossing; returns the root."""
    from engine.procedures import clutch_asbuilt as asbuilt

    got = asbuilt.setting_roots(x, target, upper)
    varied = {**x, "disc_thickness": np.full(3, x["disc_thickness"])}
    aims = np.array([target, target, 0.5 * target])
    np.testing.assert_array_equal(asbuilt.setting_roots(varied, aims, upper)[:2], [got, got])
    want = _first_crossing_by_scan(x, target, upper)
    assert math.isnan(got) == math.isnan(want), (got, want)
    if not math.isnan(want):
        assert abs(got - want) <= 1e-12, (got, want)
    return got


#: Cases of ``_random_disc_cases(2, …)`` whose first crossing the 65-point grid missed:
#: an earlier crossing in the grid interval before the bracket (18: 0.19 mm early, ball
#: lift given; 16: 27 µm, the lift following the setting), or none on the grid at all
#: (15 and 75: the peak reaches the target only between two grid points).
MISSED = (15, 16, 18, 75)


def test_the_setting_is_the_first_crossing_where_the_grid_missed_it():
    from engine.procedures import clutch_asbuilt as asbuilt

    cases = list(_random_disc_cases(2, max(MISSED) + 1))
    for j in MISSED:
        x, upper, target = cases[j]
        grid = np.linspace(0.0, upper, 65)
        got = _the_first_crossing(x, upper, target)
        # the grid's own first crossing: later than the root by more than a step, or none
        peaks = asbuilt.characteristic(x, asbuilt.Spring(x), grid, peak_only=True)
        reached = np.flatnonzero(peaks["peak_torque"] >= target)
        assert not reached.size or grid[reached[0]] > got + 1e-6, j


@pytest.mark.slow
def test_the_setting_is_the_first_crossing_on_random_disc_stacks():
    # a tenth of such cases missed the first crossing on the grid's brackets alone
    from engine.procedures import clutch_asbuilt as asbuilt

    found = early = 0
    for x, upper, target in _random_disc_cases(2, 120):
        got = _the_first_crossing(x, upper, target)
        grid = np.linspace(0.0, upper, 65)
        peaks = asbuilt.characteristic(x, asbuilt.Spring(x), grid, peak_only=True)
        reached = np.flatnonzero(peaks["peak_torque"] >= target)
        found += not math.isnan(got)
        early += not math.isnan(got) and (not reached.size or grid[reached[0] - 1] > got)
    assert found >= 50 and early >= 5, (found, early)


def test_a_target_on_the_grids_top_is_reached_before_it():
    # h0/t = 2.2: the peak torque wavers near its top (each lift point's torque peaks
    # at the stack's force maximum in turn); a target equal to the largest grid peak is
    # reached inside the grid interval before that point, fallen back from and reached
    # again at it: three crossings in the bracket, the first ~10 µm before the grid point
    from engine.procedures import clutch_asbuilt as asbuilt

    x, upper, grid, peaks = _disc_setting_case(2.2)
    j = int(np.argmax(peaks))
    target = float(peaks[j])
    assert np.all(peaks[:j] < target)
    fine = np.linspace(grid[j - 1], grid[j], 4001)
    inside = asbuilt.characteristic(x, asbuilt.Spring(x), fine, peak_only=True)["peak_torque"]
    above = np.asarray(inside) >= target
    assert np.count_nonzero(np.diff(above.astype(int))) == 3 and above[-1]
    got = _the_first_crossing(x, upper, target)
    assert grid[j - 1] < got < grid[j] - 5e-6
    # just under it: the same first crossing, three crossings again
    under = target * (1 - 1e-9)
    above = np.asarray(inside) >= under
    assert np.count_nonzero(np.diff(above.astype(int))) == 3
    assert _the_first_crossing(x, upper, under) <= got


def test_a_bracket_with_several_crossings_gives_the_first():
    # h0/t = 2: near the top the peak rises above and falls below a target several
    # times inside one grid interval (seven crossings); the root is the first
    from engine.procedures import clutch_asbuilt as asbuilt

    x, upper, grid, peaks = _disc_setting_case(2.0)
    j = 32
    fine = np.linspace(grid[j - 1], grid[j], 4001)
    inside = np.asarray(
        asbuilt.characteristic(x, asbuilt.Spring(x), fine, peak_only=True)["peak_torque"]
    )
    target = float(peaks[j] * (1 - 1e-7))  # 6.4 µN·m under the grid point's peak
    assert np.all(peaks[:j] < target) and peaks[j] >= target
    above = inside >= target
    assert np.count_nonzero(np.diff(above.astype(int))) == 7  # up, down, …, up
    got = _the_first_crossing(x, upper, target)
    assert got < fine[np.argmax(above)] and got > fine[np.argmax(above) - 1]


@pytest.mark.parametrize(("given", "lift"), [(1, 0.0004), (2, 0.0004), (1, None)])
def test_a_power_of_two_more_frictionless_discs_is_the_given_stack_at_the_target_over_it(
    given, lift
):
    # k = 2^j p frictionless discs press with exactly 2^j times the force (F = n F_1),
    # so the suggestion found on the given stack's curves at the target over 2^j is the
    # k-disc stack's own peak setting, to the bit (and a 2^j-th of the discs likewise)
    from engine.procedures import clutch_asbuilt as asbuilt

    design = {**DISC, "disc_parallel": given}
    if lift is None:
        del design["ball_lift"]
    x, _ = BALL_CLUTCH.validate(design)
    targets = np.linspace(5.0, 400.0, 300)
    known: dict = {}
    asbuilt.setting_roots(x, targets, x["disc_series"] * x["disc_cone_height"], known)
    for k in (1, 2, 4, 8):
        if k == given:
            continue
        scale = k / given
        via = asbuilt.peak_setting(x, asbuilt.Spring(x), targets / scale, 0.0, known=known)
        trial = {**x, "disc_parallel": k}
        own = asbuilt.peak_setting(trial, asbuilt.Spring(trial), targets, 0.0)
        np.testing.assert_array_equal(via[0], own[0])
        np.testing.assert_array_equal(via[1], own[1])
        assert np.count_nonzero(np.isfinite(own[0])) >= 20  # reached at many targets
    # with friction between the discs the forces are not a power of two apart: the
    # suggestion is searched on the k-disc stack itself, as before
    x, _ = BALL_CLUTCH.validate({**design, "disc_friction": 0.03})
    values, _ = asbuilt.setting_values({**x, "target_torque": targets}, 0.0)
    trial = {**x, "disc_parallel": 2}
    own = asbuilt.peak_setting(trial, asbuilt.Spring(trial), targets, 0.0)[0]
    two = values["suggested_disc_parallel"] == 2
    assert two.any()
    np.testing.assert_array_equal(values["suggested_disc_setting"][two], own[two])
