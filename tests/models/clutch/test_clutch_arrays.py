"""The clutch models' array paths: every output and check of the scalar compute, point by point.

A design study evaluates its points through ``spec.vectorized``; the reference is the
scalar compute run point by point (:func:`engine.run`, or :func:`engine.studies.plan.evaluate_chunk`
with the array path switched off). Wide spreads here (±30 %, extreme angles and wires)
make checks fail and points refuse, so verdicts and NaN placement are tested, not only
the easy middle. The peak setting's closed form (the characteristic's lines in δ) is
held to the scalar model's own root search (scipy brentq on the 81-point curve): two
independent algorithms for the same number.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import engine
from engine.core.errors import InputOutOfRange
from engine.core.points import vector
from engine.core.spec import ModelSpec, RunContext
from engine.models.clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING
from engine.physics import springs as sp
from engine.procedures import clutch_asbuilt as asbuilt
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable, evaluate_chunk, plan

DEG = math.pi / 180
FLOATS = {
    BALL_CLUTCH.name: [o.name for o in BALL_CLUTCH.outputs if not o.series],
    BALL_CLUTCH_SETTING.name: [o.name for o in BALL_CLUTCH_SETTING.outputs if not o.series],
}


def _spread(spec: ModelSpec, example: dict, n: int, spread: float, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    cols = {}
    for p in spec.inputs:
        v = example.get(p.name)
        if p.kind == "float" and isinstance(v, float) and v:
            col = v * (1.0 + rng.uniform(-spread, spread, n))
            hi = p.maximum if p.maximum is not None else np.inf
            cols[p.name] = np.clip(col, p.minimum or 0.0, hi * (1 - 1e-12))
    return cols


def _loop(spec: ModelSpec) -> ModelSpec:
    return dataclasses.replace(spec, vectorized=None, vector_rungs=())


def _compare(spec: ModelSpec, base: dict, cols: dict) -> tuple[dict, dict]:
    """Array path against the loop at the same points; returns the array path's checks."""
    outputs = FLOATS[spec.name]
    fast = evaluate_chunk(spec, base, cols, outputs, fidelity="closed_form")
    slow = evaluate_chunk(_loop(spec), base, cols, outputs, fidelity="closed_form")
    for name in outputs:
        np.testing.assert_allclose(
            fast.values[name], slow.values[name], rtol=1e-9, atol=0, equal_nan=True, err_msg=name
        )
    assert sorted(fast.checks) == sorted(slow.checks)
    for name, verdicts in slow.checks.items():
        np.testing.assert_array_equal(fast.checks[name], verdicts, err_msg=name)
    return fast.checks, fast.values


def _array_path_used(spec: ModelSpec, base: dict, cols: dict) -> frozenset[str]:
    """The outputs the array path computed (it must not hand the points to the loop)."""
    x, _ = spec.validate(base)
    n = len(next(iter(cols.values())))
    vec = vector(spec, {**x, **cols}, "closed_form", FLOATS[spec.name], 0.01, n)
    assert vec is not None, f"{spec.name}: the array path declined, the points would loop"
    return vec.computed


@pytest.mark.parametrize("spec", [BALL_CLUTCH, BALL_CLUTCH_SETTING], ids=lambda s: s.name)
def test_every_example_runs_on_the_array_path_and_matches_the_loop(spec):
    failed_somewhere = set()
    for k, example in enumerate(spec.examples):
        cols = _spread(spec, example, 60 if spec is BALL_CLUTCH else 24, 0.3, seed=k)
        computed = _array_path_used(spec, example, cols)
        one = engine.run(spec, {**example, **{c: float(v[0]) for c, v in cols.items()}})
        # every output the scalar compute gives at the first point, the array path gives
        assert set(one.results) <= computed, set(one.results) - computed
        checks, _ = _compare(spec, example, cols)
        assert checks, f"example {k}: no checks reported"
        failed_somewhere |= {n for n, v in checks.items() if (v == 1).any() and (v == 0).any()}
    # the spread is wide enough that verdicts differ between points (the test can fail)
    assert failed_somewhere


def test_refused_points_are_nan_and_their_checks_unknown():
    # α from 2° to 88° with f = 0.3 (ρ = 16.7°): the steep flanks wedge, the scalar refuses
    base = {**BALL_CLUTCH.examples[3], "flank_friction": 0.3}
    alpha = np.linspace(2 * DEG, 88 * DEG, 45)
    checks, values = _compare(BALL_CLUTCH, base, {"groove_angle": alpha})
    locked = alpha <= math.atan(0.3)
    assert locked.any() and (~locked).any()
    assert np.isnan(values["torque_limit"][locked]).all()
    assert np.isfinite(values["torque_limit"][~locked]).all()
    assert all((v[locked] == -1).all() for v in checks.values())
    assert (checks["self_locking"][~locked] == 0).any() and (checks["self_locking"] == 1).any()


def test_a_catalogue_wire_varied_across_and_off_its_table():
    # EN 10270-1 DH: 0.3…20 mm tabulated; the coil is 32 mm, so 32 mm and more is no coil
    base = dict(BALL_CLUTCH.examples[3])
    wire = np.geomspace(1e-4, 0.05, 61)
    cols = {"spring_wire_diameter": wire}
    assert "tensile_strength" in _array_path_used(BALL_CLUTCH, base, cols)
    checks, values = _compare(BALL_CLUTCH, base, cols)
    off = (wire > 0.020 * (1 + 1e-9)) | (wire >= base["spring_mean_diameter"])
    assert np.isnan(values["spring_force"][off]).all()
    assert np.isfinite(values["tensile_strength"][~off]).all()
    assert (checks["spring_index"][~off] == 0).any() and (checks["spring_index"] == 1).any()
    assert (checks["solid_length"][~off] == 0).any()


def test_tensile_strength_on_arrays_is_the_table_row_by_row():
    # the table read the slow way (first row whose upper diameter covers d, a linear
    # scan), against the binary search on arrays and on floats
    for name, material in sp.MATERIALS.items():
        wires = [u * f * 1e-3 for u, _ in material.strength for f in (1 - 2e-9, 1, 1 + 2e-9)]
        wires += np.linspace(0.0, 0.03, 301).tolist()
        got = sp.tensile_strength(name, np.array(wires))
        lo, hi = material.diameter_range
        for d, g in zip(wires, got, strict=True):
            d_mm = d * 1e3
            if not lo * 1e3 * (1 - 1e-9) - 1.0 <= d_mm <= hi * 1e3 * (1 + 1e-9):
                assert math.isnan(g), (name, d)
                with pytest.raises(InputOutOfRange, match="outside the"):
                    sp.tensile_strength(name, d)
                continue
            want = next(rm for upper, rm in material.strength if d_mm <= upper * (1 + 1e-9))
            assert g == want * 1e6 == sp.tensile_strength(name, d), (name, d)


def test_disc_stack_varied_runs_on_the_array_path():
    base = dict(BALL_CLUTCH.examples[4])
    n = 40
    rng = np.random.default_rng(5)
    cols = {
        "spring_deflection": rng.uniform(0.0005, 0.005, n),
        "disc_cone_height": rng.uniform(0.0008, 0.0025, n),
        "disc_inner_diameter": rng.uniform(0.015, 0.04, n),  # some rings too narrow: refused
    }
    assert "disc_force_flat" in _array_path_used(BALL_CLUTCH, base, cols)
    checks, values = _compare(BALL_CLUTCH, base, cols)
    narrow = cols["disc_inner_diameter"] * 1.05 >= base["disc_outer_diameter"]
    assert narrow.any() and np.isnan(values["peak_torque"][narrow]).all()
    for name in ("disc_not_past_flat", "falling_curve"):
        assert (checks[name][~narrow] == 0).any() and (checks[name][~narrow] == 1).any(), name


def test_setting_extremes_no_coil_no_peak_setting_no_suggested_wire():
    base = dict(BALL_CLUTCH_SETTING.examples[1])
    base["target_torque"] = 1.0
    # 0.01…1e5 N·m: the wire at the given deflection grows past the coil (no coil), the
    # given spring's peak setting runs out, no preferred wire reaches the largest targets
    cols = {"target_torque": np.geomspace(1e-2, 1e5, 21), "spring_deflection": np.full(21, 0.01)}
    assert "required_peak_setting" in _array_path_used(BALL_CLUTCH_SETTING, base, cols)
    checks, values = _compare(BALL_CLUTCH_SETTING, base, cols)
    assert np.isnan(values["required_wire_shear_stress"]).any()
    assert np.isfinite(values["required_wire_shear_stress"]).any()
    assert (checks["required_wire_spring_index"] == 0).any()
    for name in ("suggested_wire_diameter", "required_peak_setting"):
        assert np.isnan(values[name]).any() and np.isfinite(values[name]).any(), name


def test_setting_sized_from_the_drive_on_arrays():
    base = dict(BALL_CLUTCH_SETTING.examples[1])
    cols = {
        "drive_power": np.linspace(100.0, 1500.0, 12),
        "load_inertia": np.linspace(1e-4, 1e-2, 12),
    }
    _, values = _compare(BALL_CLUTCH_SETTING, base, cols)
    rated = cols["drive_power"] / base["drive_speed"]
    start = 6.0 * cols["load_inertia"] / (1e-3 + cols["load_inertia"])
    np.testing.assert_allclose(values["rated_drive_torque"], rated, rtol=1e-15)
    np.testing.assert_allclose(values["required_slip_torque"], np.maximum(2 * rated, start))
    # with a target given as well, the target is checked against the drive
    checks, _ = _compare(BALL_CLUTCH_SETTING, {**base, "target_torque": 5.0}, cols)
    assert (checks["target_covers_drive"] == 0).any() and (checks["target_covers_drive"] == 1).any()


def test_peak_setting_lines_against_the_scalar_root_search():
    # the closed form min_k over the characteristic's lines against brentq on the curve
    x, _ = BALL_CLUTCH_SETTING.validate(BALL_CLUTCH_SETTING.examples[1])
    for lift in (None, 0.0, 0.002):
        for driving in (None, 40 * DEG):
            xx = {**x, "ball_lift": lift, "driving_groove_angle": driving}
            spring = asbuilt.Spring(xx)
            rate = float(spring.force(1.0))
            for target in (0.5, 2.0, 8.0):
                force = 2 * target * math.tan(45 * DEG - math.atan(0.1)) / 0.05
                got, stress = asbuilt.peak_setting(xx, spring, target, force)
                # on an array of one point: the same numbers
                got_1, stress_1 = asbuilt.peak_setting(xx, spring, np.array([target]), force)
                np.testing.assert_array_equal([got, stress], [got_1[0], stress_1[0]])
                upper = max(force / rate, 1e-9) * 1.000001
                want = asbuilt.solve_setting(xx, spring, target, upper)
                if want is None:
                    assert math.isnan(got) and math.isnan(stress)
                else:
                    top = asbuilt.characteristic(xx, spring, want)["spring_stress_max"]
                    assert got == pytest.approx(want, rel=1e-12)
                    assert stress == pytest.approx(float(top), rel=1e-12)


def test_study_pass_fractions_equal_single_runs():
    """A Monte Carlo study's pass fractions (array path) against single runs at its points."""
    spec = BALL_CLUTCH
    ex = dict(spec.examples[3])  # DH wire, free length, face friction: every as-built check
    study = Study(
        variables=(
            Variable("groove_angle", "uniform", low=15 * DEG, high=60 * DEG),
            Variable("flank_friction", "uniform", low=0.0, high=0.3),
            Variable("spring_deflection", "normal", mean=0.03, sd=0.008),
            Variable("spring_wire_diameter", "uniform", low=0.0032, high=0.0048),
        ),
        base={
            k: v
            for k, v in ex.items()
            if k
            not in ("groove_angle", "flank_friction", "spring_deflection", "spring_wire_diameter")
        },
        samples=300,
        seed=11,
        outputs=("torque_limit", "peak_torque"),
    )
    result = run_study(spec, study)
    points = plan(spec, study).columns
    counts: dict[str, list[int]] = {}
    for j in range(study.samples):
        point = {**study.base, **{k: float(v[j]) for k, v in points.items()}}
        try:
            single = engine.run(spec, point, outputs=["torque_limit"])
        except engine.EngineError:
            continue
        for c in single.checks:
            counts.setdefault(c.name, [0, 0])[0 if c.ok else 1] += 1
    summary = result.summary["checks"]
    assert sorted(summary) == sorted(counts)
    mixed = 0
    for name, (passed, failed) in counts.items():
        assert summary[name]["passed"] == passed, name
        assert summary[name]["failed"] == failed, name
        mixed += passed > 0 and failed > 0
    assert mixed >= 2  # several checks are split by the study, so the comparison bites
    assert result.summary["feasible"]["fraction"] is not None


def test_a_study_asking_no_peak_output_skips_the_curve_with_the_same_verdicts():
    # example 2: allowable stress given, no face friction: the checks need no peak
    spec = BALL_CLUTCH
    base = dict(spec.examples[2])
    cols = _spread(spec, base, 50, 0.3, seed=3)
    outs = ["torque_limit", "spring_shear_stress"]
    fast = evaluate_chunk(spec, base, cols, outs, fidelity="closed_form")
    slow = evaluate_chunk(_loop(spec), base, cols, outs, fidelity="closed_form")
    assert sorted(fast.checks) == sorted(slow.checks)
    for name, verdicts in slow.checks.items():
        np.testing.assert_array_equal(fast.checks[name], verdicts, err_msg=name)
    ctx = RunContext("closed_form", frozenset(outs), 0.01)
    x, _ = spec.validate(base)
    got = spec.vectorized({**x, **cols}, ctx)
    assert "peak_torque" not in got.values  # left out for speed, not declared absent


def _study_as_the_loop_then_array_values(
    spec: ModelSpec, base: dict[str, object], outs: list[str], seed: int
) -> dict[str, object]:
    """A 60-design study of ``outs`` equals the point-by-point loop's (values and check
    verdicts); then the array path's values for a caller that reads no checks."""
    cols = _spread(spec, base, 60, 0.3, seed=seed)
    fast = evaluate_chunk(spec, base, cols, outs, fidelity="closed_form")
    slow = evaluate_chunk(_loop(spec), base, cols, outs, fidelity="closed_form")
    for name in outs:
        np.testing.assert_array_equal(fast.values[name], slow.values[name], err_msg=name)
    assert sorted(fast.checks) == sorted(slow.checks)
    for name, verdicts in slow.checks.items():
        np.testing.assert_array_equal(fast.checks[name], verdicts, err_msg=name)
    x, _ = spec.validate(base)
    return dict(
        spec.vectorized({**x, **cols}, RunContext("closed_form", frozenset(outs), 0.01)).values
    )


@pytest.mark.parametrize(
    ("example", "skipped", "kept"),
    [
        # custom wire, no allowable stress, free length or face friction: no check reads
        # an as-built value but the self-locking margin, none the ball forces
        (0, ("spring_stress_max", "total_lift", "ball_normal_force"), ()),
        # a free length and a face friction: their checks read the travel and the peak
        (3, ("ball_axial_force",), ("total_lift", "residual_torque", "peak_torque")),
    ],
)
def test_a_ball_study_asking_the_paper_outputs_skips_what_no_check_reads(example, skipped, kept):
    spec = BALL_CLUTCH
    base = dict(spec.examples[example])
    got = _study_as_the_loop_then_array_values(spec, base, ["spring_force", "torque_limit"], 9)
    for name in skipped:  # left out for speed
        assert got.get(name) is None, name
    for name in kept:
        assert np.isfinite(got[name]).any(), name


@pytest.mark.parametrize(
    ("example", "extra", "skipped"),
    [
        # no allowable stress, custom wire: no check reads the stresses or the setting
        (0, {}, ("required_peak_setting", "spring_shear_stress", "required_wire_shear_stress")),
        # an allowable stress: its checks read the stresses and the peak setting's
        (0, {"allowable_shear_stress": 3e8}, ()),
    ],
)
def test_a_setting_study_asking_the_paper_outputs_skips_what_no_check_reads(
    example, extra, skipped
):
    spec = BALL_CLUTCH_SETTING
    base = {**spec.examples[example], **extra}
    outs = ["required_spring_force", "required_deflection"]
    got = _study_as_the_loop_then_array_values(spec, base, outs, 5)
    for name in skipped:  # left out for speed (declared absent only as unasked)
        assert got.get(name) is None, name
    if not skipped:
        assert np.isfinite(got["peak_setting_stress_max"]).any()


def test_rung_estimate_takes_arrays():
    x, _ = BALL_CLUTCH.validate(BALL_CLUTCH.examples[0])
    alpha = np.linspace(1 * DEG, 89 * DEG, 89)
    friction = np.tile([0.0, 0.1, 0.5, 0.9], 23)[:89]
    est = np.asarray(
        BALL_CLUTCH.rungs[0].estimate({**x, "groove_angle": alpha, "flank_friction": friction})
    )
    for j in range(89):
        one = BALL_CLUTCH.rungs[0].estimate(
            {**x, "groove_angle": float(alpha[j]), "flank_friction": float(friction[j])}
        )
        if one is None:
            assert math.isnan(est[j])
        else:
            assert est[j] == pytest.approx(one, rel=1e-12)
    assert np.isnan(est).any() and np.isfinite(est).any()


def test_a_sweep_names_the_rung_where_only_an_optional_output_is_null():
    # example 3's spring cannot buckle (buckling_deflection null at every point): the points
    # are computed all the same; only the wedged ones (α ≤ atan f) are refused
    base = {**BALL_CLUTCH.examples[3], "flank_friction": 0.5}
    alphas = np.linspace(0.1, 1.5, 8).tolist()
    s = engine.sweep(BALL_CLUTCH, base, "groove_angle", alphas)
    for j, a in enumerate(alphas):
        try:
            want = engine.run(BALL_CLUTCH, {**base, "groove_angle": a}).rung
        except engine.EngineError:
            want = None
        assert s.rungs[j] == want, a
    assert s.results["buckling_deflection"] == [None] * 8
    assert None in s.rungs and "closed_form" in s.rungs


def test_long_columns_are_evaluated_in_chunks_with_the_same_numbers():
    from engine.models.clutch import _CHUNK, _forward_values

    n = 2 * _CHUNK + 123
    x, _ = BALL_CLUTCH.validate(BALL_CLUTCH.examples[3])
    rng = np.random.default_rng(9)
    cols = {
        "groove_angle": rng.uniform(30 * DEG, 60 * DEG, n),
        "spring_wire_diameter": rng.uniform(0.0035, 0.0045, n),
    }
    ctx = RunContext("closed_form", frozenset(FLOATS[BALL_CLUTCH.name]), 0.01)
    got = BALL_CLUTCH.vectorized({**x, **cols}, ctx).values
    whole = _forward_values({**x, **cols})
    for name in ("peak_torque", "lift_at_peak", "spring_stress_max", "residual_torque"):
        np.testing.assert_array_equal(got[name], whole[name], err_msg=name)


def test_a_driving_flank_steeper_than_the_friction_angle_falls_back_per_point():
    # α′ = 0.6° < ρ = 16.7° under a pressure disc (the pushes add): the driving flank
    # pulls, some lines fall with δ; those points are solved by the scalar root search
    # inside the array path, the rest by the lines (a free ball rides the driven flank:
    # every line rises there)
    base = {
        **BALL_CLUTCH_SETTING.examples[1],
        "flank_construction": "pressure_disc",
        "driving_groove_angle": 0.01,
        "flank_friction": 0.3,
        "target_torque": 2.0,
    }
    cols = {"groove_angle": np.linspace(0.35, 1.5, 12), "target_torque": np.linspace(0.5, 5, 12)}
    x, _ = BALL_CLUTCH_SETTING.validate(base)
    regular = asbuilt.SettingGrid({**x, **cols}).regular
    assert regular.any() and not regular.all()
    _array_path_used(BALL_CLUTCH_SETTING, base, cols)
    _, values = _compare(BALL_CLUTCH_SETTING, base, cols)
    assert np.isfinite(values["required_peak_setting"]).any()


def test_setting_with_a_varied_allowable_stress_stays_on_the_array_path():
    base = {**BALL_CLUTCH_SETTING.examples[0], "allowable_shear_stress": 6e8}
    cols = {
        "allowable_shear_stress": np.linspace(2e8, 9e8, 12),
        "target_torque": np.linspace(0.3, 3.0, 12),
        "spring_mean_diameter": np.linspace(0.02, 0.05, 12),
    }
    assert "suggested_wire_diameter" in _array_path_used(BALL_CLUTCH_SETTING, base, cols)
    _, values = _compare(BALL_CLUTCH_SETTING, base, cols)
    # thicker wires for the larger coils and targets: the suggestion moves with the point
    assert len(set(values["suggested_wire_diameter"].tolist())) > 6


def test_a_refused_point_is_masked_with_its_reason_on_both_paths():
    # f = 0.5: atan f = 26.57°, so the balls wedge at α = 20° and 25° and slip at 30°…60°;
    # a single run refuses the wedged design naming groove_angle, and a sweep masks those
    # points (null everywhere) and says how many the same reason took
    base = {**BALL_CLUTCH.examples[3], "flank_friction": 0.5}
    angles = [20 * DEG, 25 * DEG, 30 * DEG, 45 * DEG, 60 * DEG]
    with pytest.raises(engine.InfeasibleDesign) as refused:
        engine.run(BALL_CLUTCH, {**base, "groove_angle": 25 * DEG})
    assert refused.value.field == "groove_angle"
    sweep = engine.sweep(BALL_CLUTCH, base, "groove_angle", angles)
    limits = sweep.results["torque_limit"]
    assert limits[:2] == [None, None] and all(v is not None for v in limits[2:])
    assert sweep.rungs[:2] == [None, None]
    assert any("2 of 5 points refused: the balls wedge" in n for n in sweep.notes), sweep.notes
    # a wire thicker than the coil: no coil, refused alone and masked on arrays alike
    wires = [0.004, 0.032, 0.04]
    with pytest.raises(InputOutOfRange) as thick:
        engine.run(BALL_CLUTCH, {**BALL_CLUTCH.examples[0], "spring_wire_diameter": 0.045})
    assert thick.value.field == "spring_wire_diameter"
    sweep = engine.sweep(
        BALL_CLUTCH, {**BALL_CLUTCH.examples[0]}, "spring_wire_diameter", [*wires, 0.045]
    )
    assert sweep.results["torque_limit"][-1] is None
    assert any("1 of 4 points refused: no coil" in n for n in sweep.notes), sweep.notes


@pytest.mark.parametrize(
    "vary, low, high",
    [
        ("spring_active_coils", 4.0, 12.0),
        ("ball_lift", 0.001, 0.004),
        ("spring_free_length", 0.05, 0.12),
    ],
)
def test_as_built_setting_swept_alone_over_its_geometry_stays_on_the_array_path(vary, low, high):
    # one geometry input varied alone (the setting's lines do not see coils or free length):
    # the array path, and every output equal to the single run at its point to 1e-12
    base = dict(BALL_CLUTCH_SETTING.examples[1])
    values = np.linspace(low, high, 17)
    _array_path_used(BALL_CLUTCH_SETTING, base, {vary: values})
    s = engine.sweep(BALL_CLUTCH_SETTING, base, vary, values.tolist())
    moved = set()
    for j, value in enumerate(values.tolist()):
        one = engine.run(BALL_CLUTCH_SETTING, {**base, vary: value})
        for name, got in s.results.items():
            want = one.results.get(name)
            if want is None:
                assert got[j] is None, (name, j)
            else:
                assert got[j] == pytest.approx(want, rel=1e-12), (name, j)
                moved.add(name) if got[j] != s.results[name][0] else None
    assert "suggested_wire_diameter" in moved or "suggested_wire_setting" in moved


def test_long_setting_columns_are_evaluated_in_chunks_with_the_same_numbers(monkeypatch):
    # the setting's lines hold 81 values per point: no array of n x 81 for a long column
    from engine.models import clutch

    n = 3 * 40 + 11
    x, _ = BALL_CLUTCH_SETTING.validate(BALL_CLUTCH_SETTING.examples[1])
    rng = np.random.default_rng(4)
    cols = {
        "drive_power": rng.uniform(200.0, 600.0, n),
        "spring_active_coils": rng.uniform(5.0, 11.0, n),
    }
    ctx = RunContext("closed_form", frozenset(FLOATS[BALL_CLUTCH_SETTING.name]), 0.01)
    whole = BALL_CLUTCH_SETTING.vectorized({**x, **cols}, ctx).values
    widest = []
    setting = asbuilt.SettingGrid.setting

    def spy(self, rate, target, upper):
        widest.append(np.size(self.inverse_gain) + np.size(target) * self.q.size)
        return setting(self, rate, target, upper)

    monkeypatch.setattr(asbuilt.SettingGrid, "setting", spy)
    monkeypatch.setattr(clutch, "_CHUNK", 40)
    got = BALL_CLUTCH_SETTING.vectorized({**x, **cols}, ctx).values
    assert max(widest) <= 2 * 40 * asbuilt.POINTS
    for name in ("required_peak_setting", "suggested_wire_diameter", "suggested_wire_setting"):
        assert np.isfinite(got[name]).any(), name
        np.testing.assert_array_equal(got[name], whole[name], err_msg=name)


@pytest.mark.parametrize(
    ("spec", "extra", "outs", "skipped"),
    [
        # the paper's outputs: not the wire stress, index or rate nobody asked for
        (
            BALL_CLUTCH,
            {},
            ("spring_force", "torque_limit"),
            ("spring_shear_stress", "spring_index", "spring_rate", "self_locking_margin"),
        ),
        # an allowable stress: its check would read the stresses and the peak setting,
        # but a caller reading no checks gets neither, nor the required wire's root
        (
            BALL_CLUTCH_SETTING,
            {"allowable_shear_stress": 3e8},
            ("required_spring_force", "required_deflection"),
            ("required_wire_diameter", "spring_shear_stress", "peak_setting_stress_max"),
        ),
    ],
)
def test_a_caller_reading_no_checks_gets_the_asked_outputs_alone_and_the_same(
    spec, extra, outs, skipped
):
    base = {**spec.examples[0], **extra}
    cols = _spread(spec, base, 60, 0.3, seed=11)
    x, _ = spec.validate(base)
    lean = spec.vectorized(
        {**x, **cols}, RunContext("closed_form", frozenset(outs), 0.01, checks=False)
    )
    full = spec.vectorized({**x, **cols}, RunContext("closed_form", frozenset(outs), 0.01))
    slow = evaluate_chunk(_loop(spec), base, cols, list(outs), fidelity="closed_form")
    for name in outs:
        np.testing.assert_array_equal(lean.values[name], full.values[name], err_msg=name)
        np.testing.assert_array_equal(lean.values[name], slow.values[name], err_msg=name)
    assert lean.check_arrays == {} and full.check_arrays
    for name in skipped:  # computed for the checks, left out without them
        assert lean.values.get(name) is None, name
        assert full.values.get(name) is not None, name


PAPER_OUTPUTS = ("spring_force", "torque_limit", "ball_tangential_force", "spring_shear_stress")


@pytest.mark.parametrize(
    ("case", "named"),
    [
        ("alone", set(PAPER_OUTPUTS)),  # Δ alone over a helical spring: told from Δ's ends
        ("refused", set()),  # the balls wedge at some points: null there
        ("with_wire", set()),  # the wire varies too: the runner tests the columns
        ("disc", set()),  # a disc spring's force is not proportional to Δ
    ],
)
def test_the_paper_outputs_named_finite_over_a_deflection_are_finite_and_equal_single_runs(
    case: str, named: set[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Δ swept alone on a helical spring: the paper's outputs are proportional to Δ, so the
    array path names them finite at every point from Δ's declared ends (Result.finite, what
    the sweep then does not test); a named column is finite, and every value equals a single
    run's, bit for bit."""
    from engine.models import clutch as clutch_model

    monkeypatch.setattr(clutch_model, "FINITE_ENDS_FROM", 1)
    example = (
        next(e for e in BALL_CLUTCH.examples if e.get("spring_type", "helical") == case)
        if case == "disc"
        else BALL_CLUTCH.examples[0]
    )
    base = dict(example)
    n = 7
    cols: dict[str, np.ndarray] = {"spring_deflection": np.linspace(0.002, 0.006, n)}
    if case == "with_wire":
        cols["spring_wire_diameter"] = np.full(n, base["spring_wire_diameter"])
    if case == "refused":  # α below the friction angle at the first points: the balls wedge
        base["flank_friction"] = 0.2
        cols["groove_angle"] = np.linspace(5.0, 45.0, n) * DEG
    x, _ = BALL_CLUTCH.validate(base)
    ctx = RunContext(
        rung="closed_form", outputs=frozenset(PAPER_OUTPUTS), tolerance=0.01, checks=False
    )
    got = BALL_CLUTCH.vectorized({**x, **cols}, ctx)
    assert got.finite & set(PAPER_OUTPUTS) == named
    for name in got.finite:  # the three ball forces come together: each named is finite
        assert np.isfinite(np.asarray(got.values[name], dtype=float)).all(), name
    for j in range(n):
        point = {**base, **{k: float(v[j]) for k, v in cols.items()}}
        try:
            alone = engine.run(BALL_CLUTCH, point, outputs=PAPER_OUTPUTS).results
        except engine.EngineError:
            for name in PAPER_OUTPUTS:
                assert math.isnan(np.broadcast_to(got.values[name], (n,))[j]), (name, j)
            continue
        for name in PAPER_OUTPUTS:
            assert np.broadcast_to(got.values[name], (n,))[j] == alone[name], (name, j)
