"""The preload models' array paths (issue 21/22) against their scalar paths, point by point.

A sweep or a study hands the model its varied inputs as arrays; the bolt is resolved
once and every number computed on arrays. Here the reference is always the scalar
model: :func:`engine.run` at sampled points, or :func:`engine.studies.plan.evaluate_chunk`
with the array path switched off. Values must agree to 1e-9, refusals must be the
same points (NaN), and the checks must give the same verdicts.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
import pytest

import engine
from engine.core.points import vector
from engine.core.spec import RunContext
from engine.studies.execute import run_study
from engine.studies.plan import (
    CHECK_FAILED,
    CHECK_OK,
    CHECK_UNKNOWN,
    Study,
    Variable,
    evaluate_chunk,
)

TIGHTENING = engine.get_model("preload.tightening")
CONTROL = engine.get_model("preload.control")


def _float_outputs(spec: engine.ModelSpec) -> list[str]:
    return [o.name for o in spec.outputs if not o.series and o.kind in ("float", "bool")]


def _same_as_loop(
    spec: engine.ModelSpec, base: dict[str, Any], columns: dict[str, np.ndarray]
) -> tuple[Any, Any]:
    """Evaluate the points with the array path and with the loop; assert they agree."""
    outputs = _float_outputs(spec)
    looped = dataclasses.replace(spec, vectorized=None, vector_rungs=())
    fast = evaluate_chunk(spec, base, columns, outputs, fidelity="closed_form")
    slow = evaluate_chunk(looped, base, columns, outputs, fidelity="closed_form")
    for name in outputs:
        np.testing.assert_allclose(
            fast.values[name], slow.values[name], rtol=1e-9, atol=0.0, equal_nan=True, err_msg=name
        )
    assert sorted(fast.checks) == sorted(slow.checks)
    for name, verdicts in slow.checks.items():
        np.testing.assert_array_equal(fast.checks[name], verdicts, err_msg=name)
    assert fast.rungs == slow.rungs
    return fast, slow


def _uses_array_path(spec: engine.ModelSpec, base: dict[str, Any], columns: dict) -> None:
    """The array path answers these points itself (it does not hand them back to the loop)."""
    first = {k: float(v[0]) for k, v in columns.items()}
    fixed, _ = spec.validate({**base, **first})
    n = len(next(iter(columns.values())))
    got = vector(spec, {**fixed, **columns}, "closed_form", _float_outputs(spec), 0.01, n)
    assert got is not None


RNG = np.random.default_rng(2026)


def _uniform(lo: float, hi: float, n: int = 40) -> np.ndarray:
    return RNG.uniform(lo, hi, n)


CASES: list[tuple[engine.ModelSpec, dict[str, Any], dict[str, np.ndarray]]] = [
    # friction and utilisation scatter on the VDI 2230 Table A1 bolt, every formula/convention
    *[
        (
            TIGHTENING,
            {
                "thread_diameter": 0.012,
                "property_class": "8.8",
                "torque_formula": formula,
                "preload_convention": convention,
            },
            {
                "thread_friction": _uniform(0.04, 0.4),
                "bearing_friction": _uniform(0.04, 0.4),
                "utilization": _uniform(0.5, 1.0),
            },
        )
        for formula in ("vdi2230", "exact", "approx")
        for convention in ("vdi2230", "elastic")
    ],
    # a given preload (below_yield check, failing at the top), bought parts with a washer
    (
        TIGHTENING,
        {
            "thread": "M8 ISO 4762 12.9",
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "washer": "ISO 7089",
        },
        {
            "preload": _uniform(5e3, 60e3),
            "engagement_length": _uniform(0.004, 0.02),
            "thread_friction": _uniform(0.08, 0.2),
            "working_bolt_force": _uniform(1e3, 4e4),
        },
    ),
    # countersunk head (μ_K × 1/sin 45°) with its hex-key drive check
    (
        TIGHTENING,
        {"thread": "M6 ISO 10642 10.9", "limiting_surface_pressure": 300e6},
        {"bearing_friction": _uniform(0.05, 0.3), "thread_friction": _uniform(0.05, 0.3)},
    ),
    # a numeric bolt whose diameter, pitch, hole and yield strength all vary
    (
        TIGHTENING,
        {"thread_diameter": 0.016, "property_class": "10.9"},
        {
            "thread_pitch": _uniform(0.0015, 0.0025),
            "hole_diameter": _uniform(0.0165, 0.019),
            "bearing_outer_diameter": _uniform(0.02, 0.024),
            "thread_friction": _uniform(0.1, 0.14),
        },
    ),
    # the review's fig. 5 case with every number scattered (the scatter grid per point)
    (
        CONTROL,
        dict(CONTROL.examples[0]),
        {
            "thread_friction": _uniform(0.1, 0.2),
            "thread_friction_min": _uniform(0.08, 0.12),
            "bearing_friction_max": _uniform(0.15, 0.25),
            "scatter_torque": _uniform(60.0, 100.0),
            "hole_diameter": _uniform(0.017, 0.018),
            "required_clamp_force": _uniform(5e3, 20e3),
        },
    ),
    # nut-angle control with a waisted shank and the cone of the clamped parts per point
    (
        CONTROL,
        {
            "thread_diameter": 0.012,
            "method": "nut_angle",
            "shank_diameter": 0.0105,
            "reduced_diameter": 0.009,
        },
        {
            "required_clamp_force": _uniform(10e3, 30e3),
            "clamped_length": _uniform(0.03, 0.15),
            "shank_length": _uniform(0.0, 0.02),
            "reduced_length": _uniform(0.0, 0.02),
            "clamped_youngs_modulus": _uniform(7e10, 2.1e11),
            "nut_height": _uniform(0.006, 0.012),
        },
    ),
    # every bolt method family member as the one asked for, at a given preload
    *[
        (
            CONTROL,
            {
                "thread_diameter": 0.016,
                "method": method,
                "clamped_length": 0.08,
                "clamped_compliance": 1e-9,
            },
            {
                "required_clamp_force": _uniform(5e3, 60e3),
                "preload": _uniform(20e3, 110e3),
                "thread_friction": _uniform(0.08, 0.2),
            },
        )
        for method in ("torque_wrench", "torque_then_angle", "torque_gradient", "ultrasound")
    ],
    # sucker rods: mark displacement on the coupling
    (
        CONTROL,
        {
            "thread_diameter": 0.024,
            "method": "rod_displacement_marks",
            "clamped_length": 0.1,
        },
        {
            "required_clamp_force": _uniform(10e3, 80e3),
            "coupling_outer_diameter": _uniform(0.04, 0.06),
            "youngs_modulus": _uniform(1.9e11, 2.1e11),
        },
    ),
    # bought parts on the control model: socket head into aluminium, engagement scattered
    (
        CONTROL,
        dict(CONTROL.examples[2]),
        {
            "engagement_length": _uniform(0.004, 0.016),
            "required_clamp_force": _uniform(4e3, 20e3),
            "utilization": _uniform(0.6, 0.95),
        },
    ),
]


@pytest.mark.parametrize("k", range(len(CASES)))
def test_array_path_matches_the_loop(k: int) -> None:
    spec, base, columns = CASES[k]
    _uses_array_path(spec, base, columns)
    fast, _ = _same_as_loop(spec, base, columns)
    assert np.isfinite(fast.values[_float_outputs(spec)[0]]).sum() > len(fast.rungs) // 2


def test_refusals_are_the_points_the_scalar_path_refuses() -> None:
    """Off-table sizes, holes smaller than d, too coarse a pitch: NaN there, values elsewhere."""
    d = np.array([0.012, 0.0125, 0.016, 0.010, 0.0013, 0.020, 0.007])
    fast, _ = _same_as_loop(
        TIGHTENING,
        {"thread_friction": 0.12},
        {"thread_diameter": d},
    )
    tabulated = np.isin(d, [0.010, 0.012, 0.016, 0.020])  # M12.5, M1.3 and M7 are not
    assert np.array_equal(np.isfinite(fast.values["assembly_preload"]), tabulated)
    hole = np.array([0.0135, 0.0110, 0.0125, 0.0170, 0.0120])
    pitch = np.array([0.00175, 0.0098, 0.00175, 0.00175, 0.0001])
    fast, _ = _same_as_loop(
        TIGHTENING,
        {"thread_diameter": 0.012, "property_class": "8.8"},
        {"hole_diameter": hole, "thread_pitch": pitch},
    )
    # d_h < d (2nd), d3 ≤ 0 (2nd), D_f = 16.63 mm ≤ d_h (4th): refused
    assert np.isfinite(fast.values["tightening_torque"]).tolist() == [
        True,
        False,
        True,
        False,
        True,
    ]
    # the scatter range upside down at one point, a reduced section without its diameter
    lo = np.array([0.10, 0.25, 0.10])
    fast, _ = _same_as_loop(
        CONTROL,
        {**CONTROL.examples[0], "reduced_diameter": None},
        {"thread_friction_min": lo, "reduced_length": np.array([0.0, 0.0, 0.01])},
    )
    assert np.isfinite(fast.values["scatter_preload_mean"]).tolist() == [True, False, False]
    assert (fast.checks["min_meets_clamp"][1:] == CHECK_UNKNOWN).all()


def test_a_request_refused_whole_is_refused_at_every_point() -> None:
    """An angle method without the grip: the scalar path refuses every point, so does this."""
    fast, _ = _same_as_loop(
        CONTROL,
        {"thread_diameter": 0.012, "method": "nut_angle"},
        {"required_clamp_force": np.array([10e3, 20e3])},
    )
    assert np.isnan(fast.values["target_torque"]).all()
    assert fast.checks == {}


def test_friction_monte_carlo_matches_single_runs_and_its_pass_fractions() -> None:
    """A study of μ_G, μ_K scatter through the array path: single runs at sampled points agree."""
    varied = ("thread_friction", "bearing_friction", "required_clamp_force")
    base = {k: v for k, v in CONTROL.examples[1].items() if k not in varied}
    study = Study(
        variables=(
            Variable("thread_friction", "uniform", low=0.08, high=0.16),
            Variable("bearing_friction", "normal", mean=0.12, sd=0.02, low=0.06, high=0.2),
            Variable("required_clamp_force", "triangular", low=1.5e4, mode=2e4, high=2.6e4),
        ),
        base=base,
        samples=5000,
        seed=3,
        outputs=("target_angle", "preload_min", "target_torque", "min_meets_clamp"),
    )
    result = run_study(CONTROL, study)
    assert result.summary["rungs"] == {"closed_form": 5000}
    columns, values = result.plan.columns, result.merged.values
    for j in RNG.choice(5000, 12, replace=False).tolist():
        point = {**base, **{k: float(v[j]) for k, v in columns.items()}}
        single = engine.run(CONTROL, point, fidelity="closed_form")
        for name in study.outputs:
            assert values[name][j] == pytest.approx(float(single.results[name]), rel=1e-9)
    checks = result.summary["checks"]
    # the bottom of the nut-angle band (±20 %) against υ·F_K: some designs pass, some fail
    meets = np.asarray(values["min_meets_clamp"])
    assert checks["min_meets_clamp"]["passed"] == int((meets == 1.0).sum()) > 0
    assert checks["min_meets_clamp"]["failed"] == int((meets == 0.0).sum()) > 0
    assert set(checks) == {"min_meets_clamp", "max_below_yield", "angle_resolution"}
    assert CHECK_OK != CHECK_FAILED


def test_torque_monte_carlo_converges_to_the_corner_band_and_the_analytic_mean() -> None:
    """At a fixed preload the VDI 2230 torque is linear in μ_G and μ_K (step R13).

    M_A = F (0.16 P + 0.58 d2 μ_G + μ_K D_Km/2): with μ_G, μ_K uniform on 0.10…0.20 its
    mean is the torque at μ = 0.15 and its extremes the corners (0.10, 0.10) and
    (0.20, 0.20). M12: P = 1.75 mm, d2 = 10.863 mm, D_Km = (16.63 + 13.5)/2 mm.
    """
    force = 30e3
    study = Study(
        variables=(
            Variable("thread_friction", "uniform", low=0.10, high=0.20),
            Variable("bearing_friction", "uniform", low=0.10, high=0.20),
        ),
        base={"thread_diameter": 0.012, "preload": force},
        samples=200_000,
        seed=11,
        outputs=("tightening_torque",),
    )
    summary = run_study(TIGHTENING, study).summary["outputs"]["tightening_torque"]

    def torque(mu_g: float, mu_k: float) -> float:
        return force * (0.16 * 0.00175 + 0.58 * 0.010863 * mu_g + mu_k * 0.25 * (0.01663 + 0.0135))

    # 30 kN: 0.28 + 0.945 + 1.130 mm → 70.6 N·m at μ = 0.15
    assert torque(0.15, 0.15) == pytest.approx(70.65, abs=0.01)
    sd = force * np.hypot(0.58 * 0.010863, 0.25 * 0.03013) * 0.1 / np.sqrt(12)
    assert summary["mean"] == pytest.approx(torque(0.15, 0.15), abs=4 * sd / np.sqrt(200_000))
    assert summary["std"] == pytest.approx(sd, rel=0.01)
    assert torque(0.10, 0.10) < summary["min"] < torque(0.10, 0.10) * 1.002
    assert torque(0.20, 0.20) * 0.999 < summary["max"] < torque(0.20, 0.20)


def test_rung_estimate_takes_arrays() -> None:
    """The closed form's error estimate, |M(formula) − M(exact)|/M(exact), on arrays."""
    x, _ = TIGHTENING.validate({"thread_diameter": 0.012})
    mu = np.array([0.04, 0.12, 0.4])
    arr = TIGHTENING.rungs[0].estimate({**x, "thread_friction": mu})
    for m, e in zip(mu.tolist(), np.asarray(arr).tolist(), strict=True):
        assert e == pytest.approx(TIGHTENING.rungs[0].estimate({**x, "thread_friction": m}))
    # VDI 2230's linearised thread torque lies within a few per cent of the exact one
    assert 0.0 < float(np.max(arr)) < 0.05


def test_histogram_only_when_its_series_is_asked_for() -> None:
    """The scatter figures come by default; the 64×64 grid is built only for the series."""
    plain = engine.run(CONTROL, CONTROL.examples[0])
    assert plain.series == {}
    # the corners 19.79 and 36.27 kN: ±29.4 % (the 64×64 grid's corner cells gave ±28.8 %)
    assert plain.results["scatter_relative"] == pytest.approx(0.2939, abs=2e-4)
    with_series = engine.run(CONTROL, CONTROL.examples[0], series=True)
    assert sum(with_series.series["preload_counts"]) == pytest.approx(38.0)
    for name in ("scatter_preload_min", "scatter_preload_max", "scatter_preload_mean"):
        assert with_series.results[name] == plain.results[name]
    # the array path leaves the series to the scalar path
    x, _ = CONTROL.validate(CONTROL.examples[0])
    ctx = RunContext("closed_form", frozenset({"preload_bins", "preload_counts"}), 0.01)
    got = CONTROL.vectorized({**x, "thread_friction": np.array([0.12, 0.13])}, ctx)  # type: ignore[misc]
    assert got.series == {}


#: A sweep's outputs of each model (the bench's), with designs that take every branch of
#: the array path: a plain bolt, bought parts with their checks, a given preload, a nut.
NO_CHECK_CASES = [
    (TIGHTENING, {"thread_diameter": 0.012}, ("assembly_preload", "tightening_torque")),
    (TIGHTENING, dict(TIGHTENING.examples[4]), ("assembly_preload", "tightening_torque")),
    (TIGHTENING, {"thread_diameter": 0.012, "preload": 30e3}, ("equivalent_stress",)),
    (
        TIGHTENING,
        {"thread": "M12 ISO 4762 12.9", "nut": "ISO 4035"},
        ("assembly_preload", "permissible_preload"),
    ),
    (CONTROL, dict(CONTROL.examples[0]), ("nominal_preload", "target_torque")),
    (CONTROL, dict(CONTROL.examples[2]), ("nominal_preload", "target_force")),
    (CONTROL, dict(CONTROL.examples[1]), ("target_angle", "target_torque")),
    (
        CONTROL,
        {"thread_diameter": 0.012, "required_clamp_force": 20e3, "method": "torque_gradient"},
        ("nominal_preload", "target_torque"),
    ),
]


@pytest.mark.parametrize("k", range(len(NO_CHECK_CASES)))
def test_a_caller_reading_no_checks_gets_the_asked_outputs_alone_and_the_same(k: int) -> None:
    """A sweep reads no checks: the array path then leaves out the band's ends, the yield
    preload, σ_red and the bought parts' numbers that no asked output needs, and gives
    the asked outputs to the last bit as with the checks and as the single run."""
    spec, base, asked = NO_CHECK_CASES[k]
    x, _ = spec.validate(base)
    mu = np.array([0.08, 0.12, 0.16])
    point = {**x, "thread_friction": mu}
    plain = spec.vectorized(point, RunContext("closed_form", frozenset(asked), 0.01, checks=False))  # type: ignore[misc]
    full = spec.vectorized(point, RunContext("closed_form", frozenset(asked), 0.01))  # type: ignore[misc]
    assert set(plain.values) == set(asked) and plain.check_arrays == {}
    assert full.check_arrays or spec is TIGHTENING  # the control model always checks its band
    for name in asked:
        np.testing.assert_array_equal(plain.values[name], full.values[name], err_msg=name)
    for j, m in enumerate(mu.tolist()):
        one = engine.run(spec, {**base, "thread_friction": m}, outputs=asked)
        got = [np.asarray(plain.values[name])[j] for name in asked]
        assert got == [one.results[name] for name in asked]


def test_a_sweep_reading_no_bought_part_number_still_refuses_what_the_single_run_refuses() -> None:
    """ISO 7093 makes no washer for M39: the single run refuses it, so does a sweep that
    asks only for the preload (the bought-part checks' numbers are not computed for it)."""
    base = {"thread_diameter": 0.039, "washer": "ISO 7093"}
    with pytest.raises(engine.InputOutOfRange) as alone:
        engine.run(TIGHTENING, base)
    with pytest.raises(engine.InputOutOfRange) as swept:
        engine.sweep(TIGHTENING, base, "thread_friction", [0.1, 0.12], outputs=["assembly_preload"])
    assert alone.value.field == swept.value.field == "washer"
    assert alone.value.message == swept.value.message


@pytest.mark.parametrize(
    ("spec", "base", "vary", "asked"),
    [
        (
            TIGHTENING,
            {"thread_diameter": 0.012},
            "preload",
            ("assembly_preload", "permissible_preload", "tightening_torque"),
        ),
        (
            TIGHTENING,
            {"thread_diameter": 0.012},
            "thread_friction",
            ("assembly_preload", "permissible_preload"),
        ),
        (
            CONTROL,
            {"thread_diameter": 0.012, "required_clamp_force": 2e4},
            "preload",
            ("nominal_preload", "target_force"),
        ),
        (
            CONTROL,
            {"thread_diameter": 0.012, "required_clamp_force": 2e4},
            "thread_friction",
            ("nominal_preload", "target_force"),
        ),
    ],
)
def test_no_two_columns_of_a_sweep_share_memory(
    spec: engine.ModelSpec, base: dict[str, Any], vary: str, asked: tuple[str, ...]
) -> None:
    """The array path gives the arrays it made as columns without copying them; an input
    (the swept preload is F_M itself) or one array under two names (F_M,zul is F_M without
    a given preload; the target force is the nominal preload) is copied."""
    values = [20e3, 25e3, 30e3] if vary == "preload" else [0.1, 0.12, 0.14]
    got = engine.sweep(spec, base, vary, values, outputs=asked, fidelity="closed_form")
    columns = [got.columns[name] for name in asked]
    for i, column in enumerate(columns):
        assert not np.shares_memory(column, got.value_array), asked[i]
        for other in columns[i + 1 :]:
            assert not np.shares_memory(column, other), asked[i]
    if vary == "preload":  # F_M is the given preload, to the last bit
        assert got.columns[asked[0]].tolist() == values
