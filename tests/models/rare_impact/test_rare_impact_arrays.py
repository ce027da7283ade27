"""impact.rare's array path: a study of the closed form is the single runs, point by point.

The array path (``RARE_IMPACT.vectorized``) and the array-capable estimate of the
closed form are an optimisation; :func:`engine.run` is the reference. Here a grid
study, an ``auto`` study and a study at the extremes of the declared ranges are
evaluated through :func:`engine.studies.plan.evaluate_chunk` with the point-by-point loop
forbidden, and every point is compared with its own single run.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import engine.studies.plan as study_module
from engine import EngineError, run, sweep
from engine.core.points import auto_index, rung_estimates
from engine.core.spec import RunContext
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from engine.procedures.striker_cycle import (
    HELD,
    NEVER_FAST_ENOUGH,
    NOT_HELD,
    closed_form_cycle,
    linear_reach,
)
from engine.studies.plan import (
    CHECK_FAILED,
    CHECK_OK,
    CHECK_UNKNOWN,
    Study,
    Variable,
    evaluate_chunk,
)
from engine.studies.plan import plan as study_plan

OUTPUTS = [o.name for o in RARE_IMPACT.outputs if not o.series and o.kind == "float"]


@pytest.fixture
def no_loop(monkeypatch: pytest.MonkeyPatch) -> None:
    """Fail if a study evaluates a point one by one (the array path must take them all)."""

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("evaluate_chunk looped over a point instead of the array path")

    monkeypatch.setattr(study_module, "run", refuse)


def _point(columns: dict[str, np.ndarray], j: int) -> dict[str, float]:
    return {k: float(v[j]) for k, v in columns.items()}


def _same(got: float, want: object, where: str) -> None:
    if want is None:
        assert math.isnan(got), f"{where}: array {got!r}, single run null"
    else:
        assert isinstance(want, float | int), where
        assert got == pytest.approx(want, rel=1e-9, abs=1e-300), where


def test_grid_map_of_full_engagement_matches_single_runs(no_loop: None) -> None:
    # issue 22's validation: the grid map of the striker's full engagement matches single
    # runs at sampled points; the grid spans edge blows and full engagement both
    study = Study(
        variables=(
            Variable("power_spring_rate", "grid", low=2e4, high=9e4, num=8),
            Variable(
                "engagement_angle", "grid", low=math.radians(20.0), high=math.radians(150.0), num=6
            ),
            Variable("striker_mass", "grid", low=0.2, high=1.2, num=4),
        ),
        base={
            k: v
            for k, v in REFERENCE_DESIGN.items()
            if k not in ("power_spring_rate", "engagement_angle", "striker_mass")
        },
        method="grid",
        fidelity="closed_form",
    )
    p = study_plan(RARE_IMPACT, study)
    chunk = evaluate_chunk(RARE_IMPACT, REFERENCE_DESIGN, p.columns, OUTPUTS, "closed_form")
    engaged = chunk.checks["full engagement"]
    assert {CHECK_OK, CHECK_FAILED} <= set(engaged.tolist()), "the grid should span both"
    rng = np.random.default_rng(7)
    for j in rng.choice(p.n_points, 40, replace=False).tolist():
        single = run(
            RARE_IMPACT, {**REFERENCE_DESIGN, **_point(p.columns, j)}, fidelity="closed_form"
        )
        for name in OUTPUTS:
            _same(chunk.values[name][j], single.results.get(name), f"point {j}: {name}")
        for check in single.checks:
            code = engaged if check.name == "full engagement" else chunk.checks[check.name]
            assert code[j] == (CHECK_OK if check.ok else CHECK_FAILED), f"{j}: {check.name}"
        assert single.results["full_engagement"] == (engaged[j] == CHECK_OK)
        assert chunk.rungs[j] == "closed_form"


def test_auto_chooses_the_rung_per_point_as_a_single_run_does() -> None:
    # a spread of flywheel inertias and motor torques: slow spin-ups make the closed form
    # exact, fast ones do not; the tolerance splits the points between the rungs
    rng = np.random.default_rng(3)
    n = 40
    columns = {
        "flywheel_inertia": np.geomspace(2e-4, 0.2, n)[rng.permutation(n)],
        "motor_torque": rng.uniform(1.0, 40.0, n),
    }
    validated, _ = RARE_IMPACT.validate(REFERENCE_DESIGN)
    x = {**validated, **columns}
    estimates = rung_estimates(RARE_IMPACT, x, n)
    assert estimates is not None
    closed = estimates[0]
    assert closed is not None and np.isfinite(closed).all()
    tol = float(np.median(closed))
    index = auto_index(RARE_IMPACT, estimates, n, tol)
    assert set(index.tolist()) == {0, 1}, "the tolerance should split the points"
    for j in range(n):
        point = {**REFERENCE_DESIGN, **_point(columns, j)}
        # the estimate on arrays is the scalar estimate, point by point
        assert closed[j] == pytest.approx(RARE_IMPACT.rungs[0].estimate(point), rel=1e-12)
        want = engine_choice(point, tol)
        assert RARE_IMPACT.rung_names[index[j]] == want, f"point {j}"
    chunk = evaluate_chunk(RARE_IMPACT, REFERENCE_DESIGN, columns, ["release_speed"], tolerance=tol)
    assert chunk.rungs == [RARE_IMPACT.rung_names[i] for i in index.tolist()]


def engine_choice(point: dict[str, float], tol: float) -> str:
    return run(RARE_IMPACT, point, fidelity="auto", tolerance=tol, outputs=["release_speed"]).rung


def test_extreme_inputs_are_nan_where_refused_never_garbage(no_loop: None) -> None:
    # every float input drawn at its declared extremes (log-uniform between), gravity of
    # both signs: the array path gives finite numbers equal to the single run, or NaN
    # where the single run refuses the point or leaves the output null; never inf
    rng = np.random.default_rng(11)
    n = 60
    columns: dict[str, np.ndarray] = {}
    for p in RARE_IMPACT.inputs:
        if p.kind != "float" or p.minimum is None or p.maximum is None:
            continue
        lo = math.nextafter(p.minimum, math.inf) if p.exclusive_minimum else p.minimum
        hi = math.nextafter(p.maximum, -math.inf) if p.exclusive_maximum else p.maximum
        if lo > 0:  # down to the subnormal 5e-324 where the range is "> 0"
            col = np.exp(rng.uniform(math.log(lo), math.log(hi), n))
        else:
            col = rng.uniform(lo, hi, n)
        col[: n // 4] = np.where(rng.random(n // 4) < 0.5, lo, hi)  # exact extremes
        columns[p.name] = col
    chunk = evaluate_chunk(RARE_IMPACT, REFERENCE_DESIGN, columns, OUTPUTS, "closed_form")
    refused = 0
    for j in range(n):
        for name in OUTPUTS:
            assert not math.isinf(chunk.values[name][j]), f"point {j}: {name} is inf"
        try:
            single = run(
                RARE_IMPACT, {**REFERENCE_DESIGN, **_point(columns, j)}, fidelity="closed_form"
            )
        except EngineError:
            refused += 1
            assert all(math.isnan(chunk.values[o][j]) for o in OUTPUTS), f"point {j}"
            assert all(c[j] == CHECK_UNKNOWN for c in chunk.checks.values()), f"point {j}"
            continue
        for name in OUTPUTS:
            _same(chunk.values[name][j], single.results.get(name), f"point {j}: {name}")
    assert 0 < refused < n, "the extremes should hold refused and computed designs"


def test_an_infeasible_design_is_nan_with_no_estimate() -> None:
    # preloads that do not hold the half-coupling against gravity pointing away [002, eq. 1]
    x = {**REFERENCE_DESIGN, "gravity": np.array([9.80665, -100.0, -9.80665])}
    x["power_spring_preload"] = np.array([0.002, 1e-6, 0.002])
    x["auxiliary_spring_preload"] = np.array([0.008, 1e-6, 0.008])
    o = closed_form_cycle(x)
    assert o.refused.tolist() == [False, True, False]
    assert math.isnan(o.release_speed[1]) and math.isnan(o.engagement_time[1])
    est = np.asarray(RARE_IMPACT.rungs[0].estimate(x))
    assert math.isnan(est[1]) and np.isfinite(est[[0, 2]]).all()
    with pytest.raises(EngineError):
        closed_form_cycle({k: (v[1] if isinstance(v, np.ndarray) else v) for k, v in x.items()})


def test_linear_reach_lands_on_the_level_of_the_motion_it_solves() -> None:
    # y(t) = y0 + c(1 - cos kt) + (v0/k) sin kt, c = acc/w², k = √w² (harmonic), or
    # y0 + v0 t + acc t²/2 (w² = 0): at the returned time the motion is at the level with
    # the returned velocity, and no earlier crossing (checked on a fine grid before it)
    rng = np.random.default_rng(5)
    y0, v0 = rng.uniform(-1e-3, 1e-3, 200), rng.uniform(-2.0, 2.0, 200)
    acc, w2 = rng.uniform(-400.0, 400.0, 200), np.exp(rng.uniform(0.0, 14.0, 200))
    w2[::7] = 0.0  # the parabolic branch (a rate that underflows)
    acc[::21] = 0.0
    level = rng.uniform(-6e-3, 6e-3, 200)
    t, v = linear_reach(y0, v0, acc, w2, level)

    def motion(j: int, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if w2[j] == 0.0:
            return y0[j] + v0[j] * tt + 0.5 * acc[j] * tt * tt, v0[j] + acc[j] * tt
        k, c = math.sqrt(w2[j]), acc[j] / w2[j]
        y = y0[j] + c * (1.0 - np.cos(k * tt)) + v0[j] / k * np.sin(k * tt)
        return y, c * k * np.sin(k * tt) + v0[j] * np.cos(k * tt)

    reached = 0
    for j in range(200):
        # one design: floats, the same lines (math's functions where numpy's serve arrays)
        one = linear_reach(y0[j], v0[j], acc[j], w2[j], level[j])
        assert isinstance(one[0], float) and one[0] == pytest.approx(t[j], rel=1e-14), j
        if math.isinf(t[j]):
            assert math.isnan(v[j]), j
            continue
        reached += 1
        y, vel = motion(j, np.array([t[j]]))
        assert y[0] == pytest.approx(level[j], abs=1e-12), j
        assert vel[0] == pytest.approx(v[j], rel=1e-6, abs=1e-9), j
        before, _ = motion(j, np.linspace(0.0, t[j], 400)[:-2])
        side = np.sign(before - level[j])
        assert np.all(side == side[0]), f"{j}: an earlier crossing"
    assert 50 < reached < 200, "the draws should hold reached and unreached levels"


def test_a_2000_point_sweep_runs_on_the_array_path() -> None:
    values = np.linspace(0.01, 0.05, 2000).tolist()
    result = sweep(
        RARE_IMPACT, REFERENCE_DESIGN, "flywheel_inertia", values, fidelity="closed_form"
    )
    assert result.rungs == ["closed_form"] * 2000
    single = run(
        RARE_IMPACT, {**REFERENCE_DESIGN, "flywheel_inertia": values[777]}, fidelity="closed_form"
    )
    assert result.results["spin_up_time"][777] == pytest.approx(
        single.results["spin_up_time"], rel=1e-12
    )


def test_a_reused_input_buffer_gives_the_new_designs_answer() -> None:
    # a caller that refills its input array in place between calls must get the answer
    # for the new values (an array-identity cache once returned the previous design's);
    # each request has its own RunContext, whose scratch the estimate shares with the run
    validated, _ = RARE_IMPACT.validate(REFERENCE_DESIGN)
    buf = np.array([5e4, 6e4])
    x = {**validated, "power_spring_rate": buf}
    rung = RARE_IMPACT.rungs[0]
    assert RARE_IMPACT.vectorized is not None

    def request() -> np.ndarray:
        ctx = RunContext(rung="closed_form", outputs=frozenset(OUTPUTS), tolerance=1e-2)
        rung.estimate_in(x, ctx.scratch)
        assert RARE_IMPACT.vectorized is not None
        return np.asarray(RARE_IMPACT.vectorized(x, ctx).values["release_speed"])

    first = request()
    assert first[0] == pytest.approx(243.96474431890402, rel=1e-12)
    buf[:] = 8e4
    again = request()
    # symmetric V, κ = 1/2: ω² = [c1(λ1 + h1) + c2(λ2 + h1) + (m1 + m2 + n·mp/2)·g]/(n·mp·κ·r)
    # = (8e4·0.007 + 2000·0.013 + 0.35·9.80665)/(6·0.05·0.5·0.0425) = 589.4323275/0.006375
    hand = math.sqrt((560.0 + 26.0 + 0.35 * 9.80665) / 0.006375)
    assert again.tolist() == pytest.approx([hand, hand], rel=1e-12)
    assert hand == pytest.approx(304.0723, abs=1e-4)


def test_a_refused_point_carries_its_reason_on_both_paths() -> None:
    # point 1: preloads that do not hold the half-coupling against gravity pointing away;
    # point 2: a motor whose no-load speed (100 rad/s) is below the release speed (244)
    x = {**REFERENCE_DESIGN, "gravity": np.array([9.80665, -100.0, 9.80665])}
    x["power_spring_preload"] = np.array([0.002, 1e-6, 0.002])
    x["auxiliary_spring_preload"] = np.array([0.008, 1e-6, 0.008])
    x["motor_no_load_speed"] = np.array([1e4, 1e4, 100.0])
    o = closed_form_cycle(x)
    assert o.refusal.tolist() == [HELD, NOT_HELD, NEVER_FAST_ENOUGH]
    assert np.isnan(o.release_speed[1:]).all() and np.isfinite(o.release_speed[0])
    fields = {NOT_HELD: "power_spring_preload", NEVER_FAST_ENOUGH: "motor_no_load_speed"}
    for j in (1, 2):
        one = {k: (v[j] if isinstance(v, np.ndarray) else v) for k, v in x.items()}
        alone = closed_form_cycle(one, refuse=False)  # the same lines on one design: marked
        assert alone.refusal == o.refusal[j]
        with pytest.raises(EngineError) as refused:  # and raised with its reason
            closed_form_cycle(one)
        assert refused.value.field == fields[int(o.refusal[j])]


def test_a_sweep_of_stage_1_outputs_runs_stage_1_alone_with_the_same_numbers(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # held, not held (gravity pulls the half-coupling off its stop harder than the
    # preloads hold it) and a motor too slow (no-load 100 rad/s below the release speed)
    x = {**REFERENCE_DESIGN, "gravity": np.array([9.80665, -100.0, 9.80665, 0.0])}
    x["power_spring_preload"] = np.array([0.002, 1e-6, 0.002, 0.002])
    x["auxiliary_spring_preload"] = np.array([0.008, 1e-6, 0.008, 0.008])
    x["motor_no_load_speed"] = np.array([1e4, 1e4, 100.0, 1e4])
    validated = {**RARE_IMPACT.validate(REFERENCE_DESIGN)[0], **x}
    assert RARE_IMPACT.vectorized is not None
    stage1 = ["release_speed", "spin_up_time", "release_radius", "engagement_window"]

    def values(asked: list[str]) -> dict[str, Any]:
        ctx = RunContext(rung="closed_form", outputs=frozenset(asked), tolerance=1e-2, checks=False)
        assert RARE_IMPACT.vectorized is not None
        return RARE_IMPACT.vectorized(validated, ctx).values

    whole = values(OUTPUTS)  # the whole cycle: an output of stage 3 is asked

    def no_cycle(*args: object, **kwargs: object) -> None:
        raise AssertionError("stage 1's outputs ran the whole cycle")

    monkeypatch.setattr("engine.models.rare_impact.closed_form_cycle", no_cycle)
    alone = values(stage1)
    for name in stage1:  # bit for bit, NaN at the refused points
        np.testing.assert_array_equal(alone[name], whole[name], strict=True)
    assert np.isnan(alone["release_speed"][1:3]).all()
    # g = 0, symmetric V: ω² = (5e4·0.007 + 2000·0.013)/(6·0.05·0.5·0.0425) = 376/0.006375
    assert alone["release_speed"][3] == pytest.approx(math.sqrt(376.0 / 0.006375), rel=1e-12)
    assert alone["release_speed"][3] == pytest.approx(242.8588, abs=1e-4)
    # nothing asked beyond them: the stage-2 formulas of the inputs are left out too
    assert "engagement_acceleration" not in alone and "cycle_time" not in alone
