"""joint.vdi2230's array path (issue 21/22) against single runs, point by point.

The reference is :func:`engine.run` at each point: every scalar output to 1e-9 (NaN where the
single run refuses the point or leaves the output null) and every check's verdict. The cases
go where the array path has to decide per point what the scalar path decides with ``if``:
plates that vanish, transverse loads that appear, refusals, the bought-part checks, bolts of
several sizes in one request.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pytest

from engine import run
from engine.core import points
from engine.core.errors import EngineError, InputOutOfRange
from engine.core.runner import sweep
from engine.core.spec import RunContext
from engine.models import get_model
from engine.models import joint as joint_model
from engine.physics import joint as jt
from engine.procedures import bolt as bolt_procedure
from engine.studies.execute import run_study
from engine.studies.plan import (
    CHECK_FAILED,
    CHECK_OK,
    CHECK_UNKNOWN,
    Study,
    Variable,
    evaluate_chunk,
    plan,
)
from tests.stability.test_array_paths import _columns

JOINT = get_model("joint.vdi2230")
OUTPUTS = [o.name for o in JOINT.outputs if not o.series]
LOOPED = dataclasses.replace(JOINT, vectorized=None, vector_rungs=())

M12_2X20 = {"thread_diameter": 0.012, "plate1_thickness": 0.020, "plate2_thickness": 0.020}
DW, DH = 0.01663, 0.0135  # ISO 4017 d_w,min and ISO 273 medium hole of M12


def _single(base: dict[str, Any], columns: dict[str, np.ndarray], j: int) -> Any:
    point = dict(base)
    for name, col in columns.items():
        v = col[j].item()
        point[name] = int(v) if JOINT.param(name).kind == "int" else v
    try:
        return run(JOINT, point)
    except EngineError:
        return None


def _assert_matches_single_runs(base: dict[str, Any], columns: dict[str, np.ndarray]) -> Any:
    """Evaluate the points through the array path and alone; return the chunk."""
    chunk = evaluate_chunk(JOINT, base, columns, OUTPUTS, fidelity="closed_form")
    n = len(next(iter(columns.values())))
    seen: set[str] = set()
    for j in range(n):
        single = _single(base, columns, j)
        for name in OUTPUTS:
            got = chunk.values[name][j]
            want = None if single is None else single.results.get(name)
            if want is None:
                assert math.isnan(got), f"point {j}: {name} = {got!r}, single run null"
            else:
                assert got == pytest.approx(want, rel=1e-9, abs=1e-300), f"point {j}: {name}"
        verdicts = {} if single is None else {c.name: c.ok for c in single.checks}
        seen |= set(verdicts)
        for name, codes in chunk.checks.items():
            want_code = (
                CHECK_UNKNOWN
                if name not in verdicts
                else (CHECK_OK if verdicts[name] else CHECK_FAILED)
            )
            assert codes[j] == want_code, f"point {j}: check {name}"
    assert set(chunk.checks) == seen, "the array path reports other checks than single runs"
    return chunk


def _uses_array_path(base: dict[str, Any], columns: dict[str, np.ndarray]) -> bool:
    """Whether the chunk ran through ``vectorized`` (a spy counts the per-point computes)."""
    calls = {"compute": 0}

    def counting(x: Any, ctx: Any) -> Any:
        calls["compute"] += 1
        return JOINT.compute(x, ctx)

    spy = dataclasses.replace(JOINT, compute=counting)
    evaluate_chunk(spy, base, columns, OUTPUTS, fidelity="closed_form")
    return calls["compute"] == 0


@pytest.mark.parametrize("k", range(len(JOINT.examples)))
def test_every_example_with_every_float_input_varied_at_once(k):
    """tests/stability/test_array_paths.py's draw without the thread diameter.

    The generic test moves every float input by ±5 %, the thread diameter too, which puts
    every point off the ISO 261 table (refused): its array path then defers to the loop and
    compares nothing. Here the diameter stays on the table and all else moves.
    """
    base = dict(JOINT.examples[k])
    columns = {
        name: col
        for name, col in _columns(JOINT, base, seed=100 + k, rung="closed_form").items()
        if name not in ("thread_diameter", "thread_pitch")
    }
    assert _uses_array_path(base, columns)
    chunk = _assert_matches_single_runs(base, columns)
    assert np.isfinite(chunk.values["max_bolt_force"]).sum() >= 12


def test_monte_carlo_over_friction_and_plate_thickness_matches_single_runs():
    """Issue 22's question on a joint: 80 N·m ± 5 %, μ_G and μ_K scattered, h_1 scattered."""
    study = Study(
        variables=(
            Variable("thread_friction_min", "uniform", low=0.06, high=0.10),
            Variable("thread_friction_max", "uniform", low=0.12, high=0.18),
            Variable("bearing_friction_min", "triangular", low=0.06, mode=0.08, high=0.12),
            Variable("plate1_thickness", "normal", mean=0.020, sd=0.002),
            Variable("working_load", "uniform", low=2e3, high=30e3),
            Variable("tightening_torque", "uniform", low=40.0, high=80.0),
        ),
        base={
            k: v
            for k, v in JOINT.examples[1].items()
            if k
            not in (
                "working_load",
                "tightening_torque",
                "plate1_thickness",
                "thread_friction_min",
                "thread_friction_max",
                "bearing_friction_min",
            )
        },
        samples=60,
        seed=11,
    )
    p = plan(JOINT, study)
    assert _uses_array_path(dict(study.base), p.columns)
    chunk = _assert_matches_single_runs(dict(study.base), p.columns)
    # the draw covers both verdicts of the window check (R7 at the top of the torque box)
    assert set(chunk.checks["R7_max_below_permissible"].tolist()) == {CHECK_OK, CHECK_FAILED}


def test_study_pass_fractions_equal_those_of_single_runs():
    study = Study(
        variables=(
            Variable("working_load", "uniform", low=0.0, high=40e3),
            Variable("transverse_load", "uniform", low=0.0, high=6e3),
            Variable("interface_friction", "uniform", low=0.1, high=0.2),
            Variable("slip_interfaces", "uniform", low=1, high=3),  # an int input
        ),
        base={
            k: v
            for k, v in JOINT.examples[0].items()
            if k not in ("working_load", "transverse_load")
        },
        samples=80,
        seed=5,
    )
    result = run_study(JOINT, study)
    p = plan(JOINT, study)
    passed: dict[str, list[bool]] = {}
    for j in range(p.n_points):
        single = _single(dict(study.base), p.columns, j)
        assert single is not None
        for c in single.checks:
            passed.setdefault(c.name, []).append(c.ok)
    summary = result.summary["checks"]
    assert set(summary) == set(passed)
    for name, verdicts in passed.items():
        assert summary[name]["passed"] == sum(verdicts), name
        assert summary[name]["failed"] == len(verdicts) - sum(verdicts), name
    # the window is tight for M12 8.8 at up to 40 kN: both verdicts occur
    assert 0 < summary["R7_window_fits"]["passed"] < p.n_points


def test_refused_points_are_nan_and_unreported_not_garbage():
    """Points the scalar compute refuses, each for another reason, in one request."""
    base = {
        **M12_2X20,
        "tightening_torque": 80.0,
        "working_load_min": 0.0,
        "thread_friction_max": 0.16,
        "shank_length": 0.010,
    }
    columns = {
        # 1: F_A,min > F_A; 2: μ_G,max < μ_G,min; 3: shank longer than the grip;
        # 4: prevailing torque eats the whole torque and F_A = 0 (σ_red,B = 0: division by 0)
        "working_load": np.array([5e3, 0.0, 5e3, 5e3, 0.0, 8e3]),
        "working_load_min": np.array([0.0, 1e3, 0.0, 0.0, 0.0, 2e3]),
        "thread_friction_min": np.array([0.1, 0.1, 0.2, 0.1, 0.1, 0.1]),
        "plate1_thickness": np.array([0.02, 0.02, 0.02, 0.004, 0.02, 0.02]),
        "plate2_thickness": np.array([0.02, 0.02, 0.02, 0.004, 0.02, 0.02]),
        "prevailing_torque": np.array([0.4, 0.4, 0.4, 0.4, 90.0, 0.4]),
    }
    chunk = _assert_matches_single_runs(base, columns)
    table = np.vstack([chunk.values[o] for o in OUTPUTS])
    assert np.isnan(table[:, 1:5]).all()
    assert np.isfinite(chunk.values["grip"][[0, 5]]).all()
    for codes in chunk.checks.values():
        assert (codes[1:5] == CHECK_UNKNOWN).all()


def test_plates_that_vanish_and_loads_that_appear_change_the_checks_per_point():
    """h_2 = 0 drops the plate (and an interface's embedding); F_Q = 0 drops R12 there."""
    base = {
        "thread_diameter": 0.012,
        "plate3_thickness": 0.010,
        "plate2_youngs_modulus": 7e10,
        "working_load_min": 0.0,
    }
    columns = {
        "plate1_thickness": np.array([0.02, 0.02, 0.015, 0.03]),
        "plate2_thickness": np.array([0.0, 0.01, 0.0, 0.02]),
        "transverse_load": np.array([0.0, 2e3, 1e3, 0.0]),
        "working_load": np.array([0.0, 5e3, 5e3, 8e3]),
        "outer_diameter": np.array([0.020, 0.030, 0.100, 0.040]),
    }
    chunk = _assert_matches_single_runs(base, columns)
    assert chunk.checks["R12_slip"].tolist()[0] == CHECK_UNKNOWN
    assert chunk.checks["R9_fatigue"].tolist()[0] == CHECK_UNKNOWN
    # 3 plates through-bolted: 2 interfaces (Rz10-40 axial: 3 + 2·3 + 2·2 µm); 2 plates: 1
    assert chunk.values["embedding_settlement"][3] == pytest.approx(13e-6)
    assert chunk.values["embedding_settlement"][0] == pytest.approx(11e-6)


def test_tapped_waisted_joint_with_bolts_of_several_sizes():
    """Diameter varied: one bolt resolution per distinct size; an off-table size refuses."""
    base = {k: v for k, v in JOINT.examples[2].items() if k != "bearing_outer_diameter"}
    columns = {
        "thread_diameter": np.array([0.012, 0.016, 0.012, 0.0123, 0.016]),
        "reduced_diameter": np.array([0.0075, 0.011, 0.0080, 0.0075, 0.0105]),
        "working_load": np.array([5e3, 9e3, 6e3, 5e3, 1e4]),
        "temperature_change": np.array([0.0, 50.0, -20.0, 0.0, 80.0]),
    }
    chunk = _assert_matches_single_runs(base, columns)
    assert np.isnan(chunk.values["grip"][3])  # M12.3 has no ISO 261 coarse pitch
    assert chunk.values["smallest_diameter"][1] == pytest.approx(0.011)


def test_bought_part_checks_on_arrays():
    """Surface pressure (R10) and stripping (R11) with p_G, τ_BM and the engagement varied."""
    base = {k: v for k, v in JOINT.examples[3].items() if k != "engagement_length"}
    rng = np.random.default_rng(3)
    n = 24
    columns = {
        "engagement_length": rng.uniform(0.004, 0.016, n),
        "limiting_surface_pressure": rng.uniform(150e6, 400e6, n),
        "tightening_torque": rng.uniform(20.0, 80.0, n),  # the 6 mm key's ISO 2936 limit 52
        "working_load": rng.uniform(1e3, 12e3, n),
    }
    chunk = _assert_matches_single_runs(base, columns)
    for name in ("surface_pressure_assembly", "thread_stripping", "drive_torque"):
        assert set(chunk.checks[name].tolist()) == {CHECK_OK, CHECK_FAILED}, name


@pytest.mark.parametrize(
    "given",
    [
        {"internal_thread_shear_strength": 150e6, "limiting_surface_pressure": 260e6},
        {"internal_thread_material": "EN AW-6082 T6", "clamped_material": "EN AW-6082 T6"},
    ],
)
def test_bought_part_checks_with_their_limits_fixed(given):
    base = {
        k: v
        for k, v in JOINT.examples[3].items()
        if k not in ("internal_thread_material", "clamped_material", "working_load")
    }
    base.update(given, tightening_torque=30.0)
    columns = {
        "working_load": np.linspace(1e3, 12e3, 8),
        "engagement_length": np.linspace(0.004, 0.016, 8),
    }
    assert _uses_array_path(base, columns)
    chunk = _assert_matches_single_runs(base, columns)
    assert {"thread_stripping", "surface_pressure_working", "drive_torque"} <= set(chunk.checks)


def test_a_check_hook_without_an_array_form_sends_the_points_to_the_loop(monkeypatch):
    def extra(x: Any, solution: Any) -> Any:
        return [joint_model.Check("grip_below_50_mm", solution.grip < 0.05, "test hook")], []

    monkeypatch.setattr(joint_model, "CHECK_HOOKS", [*joint_model.CHECK_HOOKS, extra])
    columns = {"plate1_thickness": np.array([0.02, 0.04])}
    assert not _uses_array_path(dict(M12_2X20), columns)
    chunk = _assert_matches_single_runs(dict(M12_2X20), columns)
    assert chunk.checks["grip_below_50_mm"].tolist() == [CHECK_OK, CHECK_FAILED]


def test_sweep_over_the_grip_is_the_array_path_and_equals_single_runs():
    values = np.geomspace(1e-4, 5.0, 40).tolist()
    swept = sweep(JOINT, M12_2X20, "plate1_thickness", values, budget_s=None)
    for i, h in enumerate(values):
        single = run(JOINT, {**M12_2X20, "plate1_thickness": h})
        for name in ("clamped_compliance", "outer_diameter_used", "target_angle"):
            assert swept.results[name][i] == pytest.approx(single.results[name], rel=1e-9)


@pytest.mark.parametrize("joint", ["through", "tapped"])
@pytest.mark.parametrize("bearing", [0.005, 0.01663, 0.1])
def test_unlimited_outer_diameter_on_arrays_is_the_scalar_fixed_point(joint, bearing):
    grips = np.geomspace(1e-8, 10.0, 300)
    got = jt.unlimited_outer_diameter(grips, bearing, joint)
    want = np.array([jt.unlimited_outer_diameter(g, bearing, joint) for g in grips.tolist()])
    np.testing.assert_allclose(got, want, rtol=1e-12)
    # and it is a fixed point: D_A = D_A,Gr(tan φ(D_A))
    tan = jt.cone_tangent(grips, bearing, got, joint)
    np.testing.assert_allclose(jt.cone_limit_diameter(grips, bearing, tan, joint), got, rtol=1e-12)


def test_array_relations_equal_the_scalar_ones():
    """Every relation the array path calls, on a grid, against the float call."""
    rng = np.random.default_rng(0)
    grip = rng.uniform(0.002, 0.2, 50)
    da = rng.uniform(0.017, 0.08, 50)
    for joint in ("through", "tapped"):
        arr = jt.clamped_compliance([0.4 * grip, 0.6 * grip], [2.1e11, 7e10], DW, DH, da, joint)
        for j in range(50):
            one = jt.clamped_compliance(
                [0.4 * grip[j], 0.6 * grip[j]], [2.1e11, 7e10], DW, DH, float(da[j]), joint
            )
            assert arr.total[j] == pytest.approx(one.total, rel=1e-12)
            assert arr.tangent[j] == pytest.approx(one.tangent, rel=1e-12)
    force = rng.uniform(0.0, 8e4, 50)
    s = jt.service_stress(force, 0.9 * force, 0.00175, 0.010863, 0.010358, 0.12)
    lo, hi = jt.preload_bounds_from_torque(force * 1e-3, 0.05, 0.4, 1.3e-3, 2.4e-3)
    lim = jt.endurance_limit(0.012, "after_heat_treatment", force, 5e4)
    for j in range(50):
        f = float(force[j])
        assert s.equivalent[j] == pytest.approx(
            jt.service_stress(f, 0.9 * f, 0.00175, 0.010863, 0.010358, 0.12).equivalent,
            rel=1e-12,
        )
        assert (lo[j], hi[j]) == pytest.approx(
            jt.preload_bounds_from_torque(f * 1e-3, 0.05, 0.4, 1.3e-3, 2.4e-3), rel=1e-12
        )
        assert lim[j] == pytest.approx(
            jt.endurance_limit(0.012, "after_heat_treatment", f, 5e4), rel=1e-12
        )


def test_monte_carlo_of_the_friction_box_converges_to_its_corners_and_its_mean():
    """Issue 22's validation on the joint: μ_G, μ_K uniform in 0.08…0.16 at 80 N·m.

    The assembly preload F = (M_A − M_ü)/k(μ_G, μ_K) falls with each coefficient, so the
    study's extremes must approach the single run's torque-box corners (VDI 2230-1 R13
    inverted over the box), and its mean the box average of 1/k, integrated here with
    scipy from R13's k = 0.16 P + 0.58 d2 μ_G + μ_K (d_W + d_h)/4 written out anew.
    """
    from scipy.integrate import dblquad

    torque, prevailing = 80.0, 0.4
    base = {**M12_2X20, "tightening_torque": torque, "prevailing_torque": prevailing}
    study = Study(
        variables=(
            Variable("thread_friction_min", "uniform", low=0.08, high=0.16),
            Variable("bearing_friction_min", "uniform", low=0.08, high=0.16),
        ),
        base=base,
        samples=100_000,
        seed=2,
        outputs=("assembly_preload_min",),
    )
    stats = run_study(JOINT, study).summary["outputs"]["assembly_preload_min"]
    box = run(
        JOINT,
        {
            **base,
            "thread_friction_min": 0.08,
            "thread_friction_max": 0.16,
            "bearing_friction_min": 0.08,
            "bearing_friction_max": 0.16,
        },
    ).results
    # the nearest of 10⁵ uniform points lies ~0.08/√10⁵ ≈ 2.5e-4 from a corner in each μ:
    # k and F move ~0.25 % (at μ = 0.08) from the corner value; allow 1 %
    assert stats["min"] == pytest.approx(box["assembly_preload_min"], rel=1e-2)
    assert stats["max"] == pytest.approx(box["assembly_preload_max"], rel=1e-2)
    assert stats["min"] >= box["assembly_preload_min"] * (1 - 1e-12)
    assert stats["max"] <= box["assembly_preload_max"] * (1 + 1e-12)

    pitch, d2 = 0.00175, 0.012 - 0.649519 * 0.00175  # ISO 261 / ISO 68-1, M12

    def preload(mu_k: float, mu_g: float) -> float:
        return (torque - prevailing) / (0.16 * pitch + 0.58 * d2 * mu_g + mu_k * (DW + DH) / 4)

    mean, _ = dblquad(preload, 0.08, 0.16, 0.08, 0.16)
    mean /= 0.08**2
    standard_error = stats["std"] / math.sqrt(stats["count"])
    assert abs(stats["mean"] - mean) < 4.0 * standard_error


def test_scattered_strength_face_and_hole_resolve_the_bolt_once(monkeypatch):
    """R_p0.2, D_f and d_h scattered (values the bolt only carries): no resolution per point,
    and the points resolve_bolt refuses (d_h < d, D_f ≤ d_h) are refused here too."""
    calls = {"n": 0}
    resolve = bolt_procedure.resolve

    def counting(x: Any) -> Any:
        calls["n"] += 1
        return resolve(x)

    monkeypatch.setattr(bolt_procedure, "resolve", counting)
    rng = np.random.default_rng(8)
    n = 40
    columns = {
        "yield_strength": rng.uniform(500e6, 1100e6, n),
        "hole_diameter": rng.uniform(0.0115, 0.0175, n),  # below d = 12 mm at some points
        "bearing_outer_diameter": rng.uniform(0.015, 0.022, n),  # below d_h at some
        "working_load": rng.uniform(2e3, 20e3, n),
    }
    base = {**M12_2X20, "working_load_min": 0.0, "transverse_load": 1e3}
    chunk = evaluate_chunk(JOINT, base, columns, OUTPUTS, fidelity="closed_form")
    # the catalogue read once by the arrays' resolution, once by the check hook's probe,
    # and nothing per point
    assert 1 <= calls["n"] <= 2
    monkeypatch.setattr(bolt_procedure, "resolve", resolve)
    again = _assert_matches_single_runs(base, columns)
    np.testing.assert_array_equal(chunk.values["grip"], again.values["grip"])
    refused = np.isnan(chunk.values["grip"])
    expect = (columns["hole_diameter"] < 0.012) | (
        columns["bearing_outer_diameter"] <= columns["hole_diameter"]
    )
    np.testing.assert_array_equal(refused, expect)
    assert 0 < refused.sum() < n


@pytest.mark.parametrize(
    "base",
    [
        # bought parts: washer and surface pressure on the scattered hole
        {
            "thread": "M10 ISO 4762 12.9",
            "plate1_thickness": 0.015,
            "washer": "ISO 7089",
            "clamped_material": "EN AW-6082 T6",
            "tightening_torque": 50.0,
        },
        # an inch thread without grade: leaving R_p0.2 out of the resolution refuses, so the
        # bolt is resolved per distinct value instead (and still matches)
        {"thread": "1/2-13 UNC", "plate1_thickness": 0.02, "plate2_thickness": 0.02},
    ],
)
def test_scattered_bolt_values_with_catalogue_parts(base):
    rng = np.random.default_rng(9)
    n = 16
    columns = {
        "yield_strength": rng.uniform(600e6, 900e6, n),
        "hole_diameter": rng.uniform(0.0131, 0.0140, n),
        "working_load": rng.uniform(1e3, 10e3, n),
    }
    if base["thread"].startswith("1/2"):
        columns["hole_diameter"] = rng.uniform(0.0135, 0.0145, n)
    assert _uses_array_path(base, columns)
    _assert_matches_single_runs(base, columns)


@pytest.mark.parametrize(
    ("given", "varied", "named"),
    [
        # F_A swept alone: F_SA, F_PA, F_M,min and F_S,max finite at F_A's declared ends
        (
            {},
            {},
            {
                "additional_bolt_load",
                "clamp_load_reduction",
                "required_preload_min",
                "max_bolt_force",
            },
        ),
        # F_A below F_A,min refused: null there, so no column is finite at every point
        ({"working_load_min": 5e3}, {}, set()),
        # F_K,erf varies with F_A: tested point by point, every value finite
        (
            {},
            {"transverse_load": np.linspace(0.0, 9e3, 9)},
            {
                "additional_bolt_load",
                "clamp_load_reduction",
                "required_preload_min",
                "max_bolt_force",
            },
        ),
    ],
)
def test_the_columns_named_finite_are_finite_at_every_point(
    given: dict[str, float], varied: dict[str, Any], named: set[str]
) -> None:
    """The array path names the columns finite at every point (Result.finite, what the
    sweep then does not test again), told from F_A's declared ends where F_A is swept alone
    or from the points; each named column is finite and equals single runs, point by point."""
    asked = (*FLOOR_OUTPUTS, "clamp_load_reduction")
    x, _ = JOINT.validate({**JOINT.examples[0], **given})
    loads = np.linspace(0.0, 20e3, 9)
    ctx = RunContext(rung="closed_form", outputs=frozenset(asked), tolerance=0.01, checks=False)
    got = joint_model._vectorized({**x, "working_load": loads, **varied}, ctx)
    assert got.finite == named
    for name in named:
        assert np.isfinite(got.values[name]).all(), name
    for j in (0, 4, 8):
        point = {**JOINT.examples[0], **given, "working_load": float(loads[j])}
        point.update({k: float(v[j]) for k, v in varied.items()})
        try:
            alone = run(JOINT, point, outputs=asked).results
        except EngineError:
            assert all(math.isnan(got.values[name][j]) for name in asked)
            continue
        for name in asked:
            assert got.values[name][j] == alone[name], (name, j)


def test_a_refusal_is_the_same_line_alone_and_among_many():
    """One procedure refuses: alone with the field and the range, among many as a masked
    point; where every point is refused the array path says why (the first point's reason)."""
    base = {**M12_2X20, "working_load": 5e3}
    with pytest.raises(InputOutOfRange) as alone:
        run(JOINT, {**base, "working_load_min": 6e3})
    assert alone.value.field == "working_load_min"
    assert "must be ≤ 5000 N" in alone.value.message
    got = sweep(JOINT, base, "working_load_min", [1e3, 6e3])
    assert got.results["grip"][0] == pytest.approx(0.04) and got.results["grip"][1] is None
    x, _ = JOINT.validate({**base, "working_load_min": 6e3})
    ctx = RunContext(rung="closed_form", outputs=JOINT.scalar_outputs, tolerance=0.01)
    with pytest.raises(InputOutOfRange) as many:
        joint_model._vectorized({**x, "working_load_min": np.array([6e3, 7e3])}, ctx)
    assert many.value.field == "working_load_min"
    assert many.value.message == alone.value.message


@pytest.mark.parametrize(
    ("vary", "low", "high"),
    [
        ("working_load", 0.0, 60_000.0),  # the joint opens above about 20 kN
        ("shank_length", 0.0, 0.08),  # refused beyond the grip, 40 mm
        ("plate1_thickness", 0.004, 0.05),
        ("transverse_load", 0.0, 9e3),
    ],
)
def test_an_output_asked_alone_equals_its_column_among_all(
    vary: str, low: float, high: float
) -> None:
    """A sweep that reads no check leaves out the late steps no asked output needs (R9, R12,
    the checks' comparisons): each output asked alone is bit-identical to its column when
    every output is asked, refused points (null) included, and a swept range that refuses
    some points and opens the joint at others keeps its warnings."""
    base = dict(JOINT.examples[0])
    values = list(np.linspace(low, high, 41))
    every = sweep(JOINT, base, vary, values, outputs=OUTPUTS, budget_s=None)
    for name in OUTPUTS:
        alone = sweep(JOINT, base, vary, values, outputs=(name,), budget_s=None)
        np.testing.assert_array_equal(alone.columns[name], every.columns[name], err_msg=name)
        assert alone.warnings == every.warnings
    assert np.isnan(every.columns["max_bolt_force"]).any() == (vary == "shank_length")


FLOOR_OUTPUTS = ("additional_bolt_load", "required_preload_min", "max_bolt_force")


@pytest.mark.parametrize(
    ("given", "high", "refused", "opens"),
    [
        # F_A,min = 5 kN: F_A below it refused (0, 2, 4 kN; 0…4.5 kN in steps of 0.5 kN);
        # the joint opens above about 20 kN
        ({"working_load_min": 5e3}, 60e3, 3, True),
        ({"working_load_min": 5e3}, 15e3, 10, False),
        # none refused: the ends of F_A are the sweep's own least and largest value
        ({}, 60e3, 0, True),
        ({}, 15e3, 0, False),
        # 90 N·m of prevailing torque eat the 80 N·m: F_M = 0, so F_S,max = 0 and σ_red,B = 0
        # at F_A = 0 (refused), and no clamp force is left anywhere (the joint opens)
        ({"tightening_torque": 80.0, "prevailing_torque": 90.0}, 10e3, 1, True),
    ],
)
@pytest.mark.parametrize("asked", [FLOOR_OUTPUTS, ("working_stress",), ("slip_safety",)])
def test_a_sweep_of_the_working_load_refuses_and_warns_as_single_runs(
    given: dict[str, float],
    high: float,
    refused: int,
    opens: bool,
    asked: tuple[str, ...],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """F_A swept alone: where no asked output reads σ_red,B or F_KR per point, R8's refusals
    and the "joint opens" warning are decided at the ends of F_A over the points not refused;
    the refused points, the nulls, every value (bit for bit) and the warning are those of
    single runs of the same points (the columns written in place, as from 8192 points on)."""
    monkeypatch.setattr(joint_model, "IN_PLACE_FROM", 1)
    base = {**JOINT.examples[0], **given}
    values = np.linspace(0.0, high, 31)
    got = sweep(JOINT, base, "working_load", list(values), outputs=asked, budget_s=None)
    nulls, warned = 0, False
    for j, value in enumerate(values.tolist()):
        try:
            alone = run(JOINT, {**base, "working_load": value}, outputs=asked)
        except EngineError:
            nulls += 1
            for name in asked:
                assert math.isnan(got.columns[name][j]), f"point {j}: {name}"
            continue
        warned |= any(w.startswith("the joint opens") for w in alone.warnings)
        for name in asked:
            want = alone.results[name]
            assert got.columns[name][j] == (math.nan if want is None else want) or (
                want is None and math.isnan(got.columns[name][j])
            ), f"point {j}: {name}"
    assert nulls == refused
    assert warned == opens
    assert any(w.startswith("the joint opens at some points") for w in got.warnings) == opens


def test_an_output_that_is_a_swept_input_leaves_the_input_intact(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The array path writes null into the columns it made itself, never into an input:
    M_A is its own output where it is given, and the points whose torque the prevailing
    torque eats (30 and 40 N·m against 40 N·m) are null in the output, not in the values."""
    monkeypatch.setattr(joint_model, "IN_PLACE_FROM", 1)  # as from 8192 points on
    base = {**JOINT.examples[0], "working_load": 0.0, "prevailing_torque": 40.0}
    base["tightening_torque"] = 80.0
    values = [30.0, 40.0, 50.0, 120.0]
    got = sweep(JOINT, base, "tightening_torque", values, outputs=("tightening_torque",))
    assert got.value_array.tolist() == values
    assert np.isnan(got.columns["tightening_torque"][:2]).all()
    assert got.columns["tightening_torque"][2:].tolist() == [50.0, 120.0]


@pytest.mark.parametrize("block", [3, 1 << 16])
@pytest.mark.parametrize("in_place_from", [1, 10**9])
def test_the_columns_null_exactly_the_values_not_finite(
    in_place_from: int, block: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each column is tested value by value, not by a sum (which overflows on large finite
    values): ±inf and NaN become null, the refused points too, and every finite value stays
    (1e308 twice included), in a column written in place and in the copied table alike, in
    one block or in blocks (of 3: the table's second row starts in the middle of one)."""
    monkeypatch.setattr(joint_model, "IN_PLACE_FROM", in_place_from)
    monkeypatch.setattr(points, "FINITE_BLOCK", block)
    s = {
        "large": np.array([1e308, 1e308, 2.0, 3.0]),
        "odd": np.array([1.0, np.inf, -np.inf, np.nan]),
        "fixed": 5.0,
    }
    refused = np.array([False, False, False, True])
    got, finite = joint_model._output_columns(s, ["large", "odd", "fixed"], 4, refused, ())
    assert got["large"][:3].tolist() == [1e308, 1e308, 2.0]
    assert got["odd"][0] == 1.0
    assert np.isnan(got["odd"][1:]).all()
    assert got["fixed"][:3].tolist() == [5.0, 5.0, 5.0]
    assert np.isnan([got["large"][3], got["fixed"][3]]).all()
    assert finite == frozenset()  # a refused point is null in every column
    # no point refused: the columns found finite at every point are named as such, never
    # one that is not (the copied table is tested as one: "odd" leaves every row of it out)
    s["large"] = np.array([1e308, 1e308, 2.0, 3.0])
    s["odd"] = np.array([1.0, np.inf, -np.inf, np.nan])
    got, finite = joint_model._output_columns(s, ["large", "odd", "fixed"], 4, None, ())
    assert finite == ({"large", "fixed"} if in_place_from == 1 else frozenset())
    assert got["large"].tolist() == [1e308, 1e308, 2.0, 3.0]
    assert got["fixed"].tolist() == [5.0] * 4
    assert got["odd"][0] == 1.0 and np.isnan(got["odd"][1:]).all()
