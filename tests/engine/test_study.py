"""The study engine: sampling, evaluation paths, statistics, sensitivity, cancellation.

Reference numbers that this code did not compute: the Ishigami function's analytic
Sobol' indices (Ishigami & Homma 1990; Saltelli et al. 2008, §4.8), and single runs of
the same model (engine.run) at the corners and sampled points of a study.
"""

from __future__ import annotations

import dataclasses
import json
import math
import threading

import numpy as np
import pytest
from scipy.integrate import quad

import engine
from engine.core.errors import InputOutOfRange
from engine.studies.execute import LOOP_CHUNK, Cancelled, run_study
from engine.studies.plan import Study, Variable, plan

from .study_toys import ISHIGAMI_S1, ISHIGAMI_ST, TOY_SA

CLUTCH = engine.get_model("clutch.ball")
RARE = engine.get_model("impact.rare")
NUTRUNNER = engine.get_model("nutrunner.drive")


def _without(example: dict, *names: str) -> dict:
    return {k: v for k, v in example.items() if k not in names}


def _same(a: dict, b: dict) -> str:
    strip = {"elapsed_s", "compute_s"}
    return json.dumps({k: v for k, v in a.items() if k not in strip}, sort_keys=True) == json.dumps(
        {k: v for k, v in b.items() if k not in strip}, sort_keys=True
    )


def test_sobol_indices_of_ishigami_match_the_analytic_values() -> None:
    study = Study(
        variables=tuple(Variable(k, low=-math.pi, high=math.pi) for k in ("x1", "x2", "x3")),
        method="sobol",
        samples=8192,
        seed=3,
    )
    got = run_study(TOY_SA, study).summary["sensitivity"]["indices"]["ishigami"]
    for i, name in enumerate(("x1", "x2", "x3")):
        assert got[name]["first"] == pytest.approx(ISHIGAMI_S1[i], abs=0.02)
        assert got[name]["total"] == pytest.approx(ISHIGAMI_ST[i], abs=0.02)


def test_sobol_indices_of_an_additive_model_are_its_variance_shares() -> None:
    # y = x1 + 2 x2 + 0 x3, x ~ U(0, 1): S1 = ST = 1/5, 4/5, 0
    study = Study(
        variables=tuple(Variable(k, low=0.0, high=1.0) for k in ("x1", "x2", "x3")),
        method="sobol",
        samples=1000,
        seed=1,
    )
    result = run_study(TOY_SA, study).summary
    assert result["points"] == 1024 * 5  # rounded up to a power of two, N (k + 2) runs
    assert any("rounded up" in n for n in result["notes"])
    got = result["sensitivity"]["indices"]["additive"]
    for name, share in (("x1", 0.2), ("x2", 0.8), ("x3", 0.0)):
        assert got[name]["first"] == pytest.approx(share, abs=0.02)
        assert got[name]["total"] == pytest.approx(share, abs=0.02)


def test_monte_carlo_of_flank_friction_converges_to_the_corner_band_and_the_mean() -> None:
    """The slip torque under flank-friction scatter: band = single runs at the corners,
    mean = the integral of the single-run torque over the uniform law."""
    base = _without(dict(CLUTCH.examples[0]), "flank_friction")
    lo, hi = 0.0, 0.15

    def torque(f: float) -> float:
        return float(engine.run(CLUTCH, {**base, "flank_friction": f}).results["torque_limit"])

    study = Study(
        variables=(Variable("flank_friction", "uniform", low=lo, high=hi),),
        base=base,
        samples=40_000,
        seed=11,
        outputs=("torque_limit",),
    )
    stats = run_study(CLUTCH, study).summary["outputs"]["torque_limit"]
    assert stats["min"] == pytest.approx(torque(lo), rel=2e-4)
    assert stats["max"] == pytest.approx(torque(hi), rel=2e-4)
    mean = quad(torque, lo, hi)[0] / (hi - lo)
    assert stats["mean"] == pytest.approx(mean, rel=2e-3)
    assert stats["count"] == 40_000
    assert sum(stats["histogram"]["counts"]) == 40_000


def test_a_grid_map_matches_single_runs_at_sampled_points() -> None:
    ex = dict(RARE.examples[0])
    c1, lam1 = ex["power_spring_rate"], ex["power_spring_preload"]
    study = Study(
        variables=(
            Variable("power_spring_rate", low=0.5 * c1, high=2.0 * c1, num=7),
            Variable("power_spring_preload", low=0.5 * lam1, high=3.0 * lam1, num=6),
        ),
        base=_without(ex, "power_spring_rate", "power_spring_preload"),
        method="grid",
        fidelity="closed_form",
        feasible_when="full_engagement",
        outputs=("release_speed", "full_engagement"),
    )
    grid = run_study(RARE, study).summary["grid"]
    assert grid["shape"] == [7, 6]
    feasible = np.array(grid["feasible"])
    assert 0 < (feasible == 1).sum() < feasible.size  # the map crosses the boundary
    rng = np.random.default_rng(0)
    for i, j in rng.integers(0, [7, 6], size=(8, 2)).tolist():
        point = {
            **ex,
            "power_spring_rate": grid["axes"]["power_spring_rate"][i],
            "power_spring_preload": grid["axes"]["power_spring_preload"][j],
        }
        single = engine.run(RARE, point, fidelity="closed_form").results
        assert grid["maps"]["release_speed"][i][j] == pytest.approx(
            single["release_speed"], rel=1e-12
        )
        assert feasible[i, j] == int(single["full_engagement"])


def test_the_array_path_and_the_point_by_point_path_agree() -> None:
    looped = dataclasses.replace(NUTRUNNER, vectorized=None, vector_rungs=())
    ex = dict(NUTRUNNER.examples[0])
    study = Study(
        variables=(
            Variable("motor_speed", "normal", mean=ex["motor_speed"], sd=0.05 * ex["motor_speed"]),
            Variable(
                "motor_power",
                "triangular",
                low=0.8 * ex["motor_power"],
                mode=ex["motor_power"],
                high=1.3 * ex["motor_power"],
            ),
        ),
        base=_without(ex, "motor_speed", "motor_power"),
        method="lhs",
        samples=300,
        seed=5,
    )
    fast, slow = run_study(NUTRUNNER, study), run_study(looped, study)
    assert fast.summary["rungs"] == slow.summary["rungs"] == {"closed_form": 300}
    for name in fast.plan.outputs:
        np.testing.assert_allclose(
            fast.merged.values[name], slow.merged.values[name], rtol=1e-12, equal_nan=True
        )
    assert slow.summary["checks"]  # the array path reports the same checks, same verdicts
    assert fast.summary["checks"] == slow.summary["checks"]


def test_a_study_repeats_exactly_and_the_seed_matters() -> None:
    base = _without(dict(CLUTCH.examples[0]), "groove_angle")
    make = lambda seed: Study(  # noqa: E731
        variables=(Variable("groove_angle", "normal", mean=0.78, sd=0.05),),
        base=base,
        samples=5000,
        seed=seed,
    )
    a, b, c = (run_study(CLUTCH, make(s)).summary for s in (1, 1, 2))
    assert _same(a, b)
    assert a["outputs"]["torque_limit"]["mean"] != c["outputs"]["torque_limit"]["mean"]


def test_a_normal_law_is_truncated_to_the_declared_range() -> None:
    param = CLUTCH.param("flank_friction")
    study = Study(
        variables=(Variable("flank_friction", "normal", mean=0.0, sd=0.05),),
        base=_without(dict(CLUTCH.examples[0]), "flank_friction"),
        samples=20_000,
        seed=4,
    )
    x = plan(CLUTCH, study).columns["flank_friction"]
    assert x.min() >= param.minimum
    # half of a normal law folded at its mean: E|X| = σ √(2/π)
    assert x.mean() == pytest.approx(0.05 * math.sqrt(2 / math.pi), rel=0.02)


def test_refused_points_are_counted_and_left_out_of_the_statistics() -> None:
    # α ≤ atan f never slips: a 422 for a single run, a refused point in a study
    base = _without(dict(CLUTCH.examples[0]), "flank_friction", "groove_angle")
    looped = dataclasses.replace(CLUTCH, vectorized=None, vector_rungs=())
    study = Study(
        variables=(
            Variable("flank_friction", low=0.0, high=1.0, num=5),
            Variable("groove_angle", low=0.4, high=1.0, num=4),
        ),
        base=base,
        method="grid",
        outputs=("torque_limit",),
    )
    for spec in (CLUTCH, looped):
        s = run_study(spec, study).summary
        refused = sum(
            1
            for f in np.linspace(0, 1, 5)
            for a in np.linspace(0.4, 1.0, 4)
            if a <= math.atan(f) + 1e-12
        )
        assert s["refused"] == refused > 0
        assert s["outputs"]["torque_limit"]["count"] == 20 - refused
        maps = np.array(s["grid"]["maps"]["torque_limit"], dtype=object)
        assert sum(v is None for v in maps.ravel()) == refused


def test_cancel_stops_between_chunks() -> None:
    ex = dict(RARE.examples[0])
    cancel = threading.Event()
    seen: list[int] = []

    def progress(done: int, total: int) -> None:
        seen.append(done)
        if done >= LOOP_CHUNK:
            cancel.set()

    study = Study(
        variables=(
            Variable("motor_torque", low=0.8 * ex["motor_torque"], high=1.2 * ex["motor_torque"]),
        ),
        base=_without(ex, "motor_torque"),
        samples=4 * LOOP_CHUNK,
        fidelity="simulation",
    )
    with pytest.raises(Cancelled):
        run_study(RARE, study, progress=progress, cancel=cancel)
    assert seen[-1] == LOOP_CHUNK


@pytest.mark.parametrize(
    ("variables", "field"),
    [
        ((Variable("nope", low=0, high=1),), "variables"),
        ((Variable("flank_friction", low=0.5, high=0.1),), "variables"),
        ((Variable("flank_friction", low=0.0, high=2.0),), "flank_friction"),
        ((Variable("flank_friction", "normal", mean=5.0, sd=0.01),), "variables"),
        ((Variable("spring_arrangement", low=0, high=1),), "variables"),
    ],
)
def test_bad_studies_are_refused_naming_the_field(variables: tuple, field: str) -> None:
    base = _without(dict(CLUTCH.examples[0]), "flank_friction")
    with pytest.raises(InputOutOfRange) as err:
        plan(CLUTCH, Study(variables=variables, base=base, samples=10))
    assert err.value.field == field


def test_a_grid_varies_at_most_three_inputs_and_sizes_are_bounded() -> None:
    three = tuple(Variable(k, low=0.0, high=1.0, num=2) for k in ("x1", "x2", "x3"))
    assert plan(TOY_SA, Study(variables=three, method="grid")).n_points == 8
    ex = dict(CLUTCH.examples[0])
    names = ("flank_friction", "load_factor", "groove_angle", "spring_deflection")
    four = tuple(Variable(k, low=0.9 * ex[k] + 0.01, high=ex[k] + 0.02, num=2) for k in names)
    with pytest.raises(InputOutOfRange, match="at most 3"):
        plan(CLUTCH, Study(variables=four, base=_without(ex, *names), method="grid"))
    with pytest.raises(InputOutOfRange, match="over the limit"):
        plan(TOY_SA, Study(variables=three[:1], samples=10**8))


def test_a_study_varies_at_most_twelve_inputs() -> None:
    spec = engine.get_model("joint.vdi2230")
    numeric = [p for p in spec.inputs if p.is_numeric and p.minimum is not None]
    assert len(numeric) > 12
    variables = tuple(Variable(p.name, low=p.minimum, high=p.minimum + 1e-9) for p in numeric[:13])
    with pytest.raises(InputOutOfRange, match="at most 12"):
        plan(spec, Study(variables=variables, samples=10))


def test_a_looped_chunk_keeps_each_points_check_verdicts_as_a_single_run_gives_them() -> None:
    """The study's one-by-one points read only the checks' verdicts (no sentence is made):
    each code is the single run's ok, point by point, for a failing check as for a passing."""
    from engine.studies.plan import CHECK_FAILED, CHECK_OK, evaluate_chunk

    ex = dict(RARE.examples[0])
    c1 = ex["power_spring_rate"]
    # the return spring's rate is 52 N/mm in the example: c3 > c1 fails above it
    rates = np.array([0.5 * c1, 40_000.0, 60_000.0])
    chunk = evaluate_chunk(
        RARE,
        _without(ex, "power_spring_rate"),
        {"power_spring_rate": rates},
        ("release_speed",),
        fidelity="simulation",
    )
    for j, rate in enumerate(rates.tolist()):
        alone = engine.run(RARE, {**ex, "power_spring_rate": rate}, fidelity="simulation")
        for check in alone.checks:
            assert chunk.checks[check.name][j] == (CHECK_OK if check.ok else CHECK_FAILED)
    assert chunk.checks["c3 > c1"].tolist() == [CHECK_OK, CHECK_OK, CHECK_FAILED]


def test_a_looped_chunk_on_a_named_rung_gives_each_point_what_a_single_run_gives() -> None:
    """Points on a named rung run without engine.run's validation and sentences
    (engine.core.runner.run_point): each value, null, rung, verdict and refusal is still the
    single run's, bit for bit. The motor's no-load speed 260 rad/s is above the reference
    release speed (244 rad/s) but below the 265 rad/s of a 60 N/mm power spring (refused:
    never fast enough); at 40 N/mm the shaft does not re-lock (relock_time null)."""
    from engine.studies.plan import CHECK_FAILED, CHECK_OK, CHECK_UNKNOWN, evaluate_chunk

    ex = {**RARE.examples[0], "motor_no_load_speed": 260.0}
    varied = {
        "power_spring_rate": np.array([40_000.0, 60_000.0, 50_000.0, 45_000.0]),
        "motor_torque": np.array([5.0, 5.5, 2.5, 4.0]),
    }
    outputs = ("release_speed", "half_coupling_release_speed", "cycle_time", "relock_time")
    chunk = evaluate_chunk(RARE, _without(ex, *varied), varied, outputs, fidelity="simulation")
    refused = 0
    for j in range(4):
        point = {**ex, **{k: float(v[j]) for k, v in varied.items()}}
        try:
            alone = engine.run(RARE, point, fidelity="simulation", outputs=outputs)
        except engine.EngineError as exc:
            assert "never reaches the release speed" in exc.message
            refused += 1
            assert chunk.rungs[j] is None
            assert all(math.isnan(chunk.values[name][j]) for name in outputs)
            assert all(codes[j] == CHECK_UNKNOWN for codes in chunk.checks.values())
            continue
        assert chunk.rungs[j] == alone.rung == "simulation"
        for name in outputs:
            got, want = chunk.values[name][j], alone.results[name]
            assert math.isnan(got) if want is None else got == want
        for check in alone.checks:
            assert chunk.checks[check.name][j] == (CHECK_OK if check.ok else CHECK_FAILED)
    assert refused == 1 and math.isnan(chunk.values["release_speed"][1])
    assert math.isnan(chunk.values["relock_time"][0]) and chunk.values["relock_time"][3] > 0.0
    assert chunk.refusals == {"InfeasibleDesign: the motor never reaches the release speed": 1}
    assert chunk.checks["c3 > c1"].tolist() == [CHECK_OK, CHECK_UNKNOWN, CHECK_OK, CHECK_OK]
    assert chunk.checks["relock"].tolist() == [CHECK_FAILED, CHECK_UNKNOWN, CHECK_OK, CHECK_OK]


def test_an_auto_study_the_array_path_cannot_answer_is_cut_into_looped_chunks() -> None:
    """At a tolerance only the simulation meets every point goes one by one: the study is
    cut as a simulation study is (it was one chunk of up to 65,536 points, which one
    worker ran while the others waited); at a loose one the closed form answers on arrays."""
    from engine.studies.execute import VECTOR_CHUNK, chunk_size

    ex = dict(RARE.examples[0])
    c1 = ex["power_spring_rate"]

    def study(tolerance: float) -> Study:
        return Study(
            variables=(Variable("power_spring_rate", "uniform", low=0.9 * c1, high=1.1 * c1),),
            base=_without(ex, "power_spring_rate"),
            samples=3 * LOOP_CHUNK,
            seed=3,
            tolerance=tolerance,
        )

    tight, loose = study(1e-6), study(0.5)
    assert engine.run(RARE, ex, tolerance=1e-6).rung == "simulation"
    assert engine.run(RARE, ex, tolerance=0.5).rung == "closed_form"
    assert chunk_size(RARE, tight, plan(RARE, tight)) == LOOP_CHUNK
    assert chunk_size(RARE, loose, plan(RARE, loose)) == VECTOR_CHUNK
    assert chunk_size(RARE, tight) == VECTOR_CHUNK  # without its points: as before
