"""blow.joint's array path (rigid and energy rungs): a study is the single runs, point by point.

:func:`engine.run` is the reference. The studies here are evaluated through
:func:`engine.studies.plan.evaluate_chunk` with the point-by-point loop forbidden, so
every point comes from the array path, and each is compared with its own run.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import engine.studies.plan as study_module
from engine import EngineError, run, sweep
from engine.core.points import auto_index, rung_estimates
from engine.core.runner import choose_rung
from engine.models.blow import BLOW, CLUTCH_M10, ENERGY_M16, NUTRUNNER_HARD, RARE_IMPACT_M16
from engine.physics.blow import BlowProblem, blow_series
from engine.studies.plan import (
    CHECK_FAILED,
    CHECK_OK,
    CHECK_UNKNOWN,
    Study,
    Variable,
    evaluate_chunk,
)
from engine.studies.plan import plan as study_plan

FLOATS = [o.name for o in BLOW.outputs if not o.series and o.kind == "float"]
VARIED = ("tool_energy", "thread_friction", "clamped_length")


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


@pytest.mark.parametrize("rung", ["rigid", "energy"])
def test_monte_carlo_study_matches_single_runs(rung: str, no_loop: None) -> None:
    # three inputs at once, one of them the thread friction (the bolt is resolved once,
    # the torque per preload per distinct friction) and one the clamp length (the joint's
    # compliances per distinct length)
    study = Study(
        variables=(
            Variable("tool_energy", "uniform", low=2.0, high=40.0),
            Variable("thread_friction", "normal", mean=0.12, sd=0.02, low=0.06, high=0.2),
            Variable("clamped_length", "triangular", low=0.02, mode=0.05, high=0.12),
        ),
        # 12.9: F_M0.2 ≈ 155 kN, above the window, so the window's verdicts span both
        base={**{k: v for k, v in ENERGY_M16.items() if k not in VARIED}, "property_class": "12.9"},
        samples=120,
        seed=4,
        fidelity=rung,
    )
    p = study_plan(BLOW, study)
    outputs = [*FLOATS, "blows_to_target"]
    chunk = evaluate_chunk(BLOW, study.base, p.columns, outputs, rung)
    assert chunk.rungs == [rung] * p.n_points
    verdicts = chunk.checks["preload_window"]
    if rung == "energy":
        assert {CHECK_OK, CHECK_FAILED} <= set(verdicts.tolist()), "the study should span both"
    else:  # the rigid rung takes the joint to √(2EC) in one blow: far above the window
        assert set(verdicts.tolist()) == {CHECK_FAILED}
        assert CHECK_FAILED in chunk.checks["bolt_yield"].tolist()  # the strongest blows yield
    blows = set()
    for j in range(0, p.n_points, 3):
        single = run(BLOW, {**study.base, **_point(p.columns, j)}, fidelity=rung)
        for name in outputs:
            _same(chunk.values[name][j], single.results.get(name), f"{rung} {j}: {name}")
        blows.add(single.results["blows_to_target"])
        for check in single.checks:
            code = chunk.checks[check.name][j]
            assert code == (CHECK_OK if check.ok else CHECK_FAILED), f"{j}: {check.name}"
    if rung == "energy":
        assert len(blows) > 3, "the energies should need different numbers of blows"


def test_auto_chooses_the_rung_per_point_as_a_single_run_does() -> None:
    # the energy rung's error grows with the struck inertia (J_s/J_t and the nut's kick):
    # a spread of struck inertias and a tolerance between puts points on both rungs
    n = 30
    rng = np.random.default_rng(2)
    columns = {
        "struck_inertia": np.geomspace(1e-9, 1e-3, n)[rng.permutation(n)],
        "tool_energy": rng.uniform(3.0, 30.0, n),
    }
    base = {**ENERGY_M16, "restitution": 1.0}
    validated, _ = BLOW.validate(base)
    x = {**validated, **columns}
    estimates = rung_estimates(BLOW, x, n)
    assert estimates is not None
    energy = estimates[1]
    assert energy is not None and np.isfinite(energy).all()
    tol = float(np.median(energy))
    index = auto_index(BLOW, estimates, n, tol)
    assert {1, 2} <= set(index.tolist()), "the tolerance should split the points"
    for j in range(n):
        point, _ = BLOW.validate({**base, **_point(columns, j)})
        for k, rung in enumerate(BLOW.rungs):
            est = estimates[k]
            assert est is not None
            assert est[j] == pytest.approx(rung.estimate(point), rel=1e-12), (j, rung.name)
        assert BLOW.rung_names[index[j]] == choose_rung(BLOW, point, "auto", tol)[0], j


def test_extreme_inputs_are_nan_where_refused_never_garbage(no_loop: None) -> None:
    # the blow's numeric inputs drawn across their declared ranges down to the subnormal
    # where the range is "> 0": finite and equal to the single run, or NaN where the single
    # run refuses the point or leaves the output null; never inf
    names = (
        "tool_energy",
        "tool_inertia",
        "tool_stiffness",
        "drive_torque",
        "struck_inertia",
        "breakaway_factor",
        "snug_torque",
        "blow_efficiency",
    )
    rng = np.random.default_rng(9)
    n = 80
    columns: dict[str, np.ndarray] = {}
    for name in names:
        p = BLOW.param(name)
        assert p.minimum is not None and p.maximum is not None
        lo = math.nextafter(p.minimum, math.inf) if p.exclusive_minimum else p.minimum
        hi = p.maximum
        if lo > 0:
            col = np.exp(rng.uniform(math.log(lo), math.log(hi), n))
        else:
            col = rng.uniform(lo, hi, n)
        col[: n // 4] = np.where(rng.random(n // 4) < 0.5, lo, hi)
        columns[name] = col
    base = {k: v for k, v in ENERGY_M16.items() if k not in names}
    base["joint_rate_from"], base["joint_rate"] = "number", 800.0
    base["target_torque"] = 2e5
    base.pop("target_preload")
    for rung in ("rigid", "energy"):
        chunk = evaluate_chunk(BLOW, base, columns, FLOATS, rung)
        computed = refused = 0
        for j in range(n):
            for name in FLOATS:
                assert not math.isinf(chunk.values[name][j]), f"{rung} {j}: {name} is inf"
            try:
                single = run(BLOW, {**base, **_point(columns, j)}, fidelity=rung)
            except EngineError:
                refused += 1
                assert all(math.isnan(chunk.values[o][j]) for o in FLOATS), f"{rung} {j}"
                assert all(c[j] == CHECK_UNKNOWN for c in chunk.checks.values()), f"{j}"
                continue
            computed += 1
            for name in FLOATS:
                _same(chunk.values[name][j], single.results.get(name), f"{rung} {j}: {name}")
        # a snug torque above the target, an energy that underflows to 0 J, … are refused
        assert computed >= n // 8 and refused >= n // 8, (computed, refused)


def test_a_sweep_of_the_friction_resolves_the_bolt_per_value_and_matches_runs() -> None:
    values = np.linspace(0.06, 0.2, 15).tolist()
    swept = sweep(BLOW, ENERGY_M16, "thread_friction", values, fidelity="energy")
    assert swept.rungs == ["energy"] * len(values)
    for i in (0, 7, 14):
        single = run(BLOW, {**ENERGY_M16, "thread_friction": values[i]}, fidelity="energy")
        for name in ("final_preload", "joint_rate_used", "blows_to_target", "preload_verdict"):
            want = single.results[name]
            got = swept.results[name][i]
            assert got == (pytest.approx(want, rel=1e-9) if isinstance(want, float) else want)


def test_a_2000_point_rigid_sweep_runs_on_the_array_path() -> None:
    values = np.linspace(100.0, 200.0, 2000).tolist()
    swept = sweep(BLOW, NUTRUNNER_HARD, "motor_speed", values, fidelity="rigid")
    assert swept.rungs == ["rigid"] * 2000
    single = run(BLOW, {**NUTRUNNER_HARD, "motor_speed": values[1234]}, fidelity="rigid")
    assert swept.results["rigid_torque"][1234] == pytest.approx(
        single.results["rigid_torque"], rel=1e-12
    )


def test_blow_series_on_arrays_stops_each_design_by_its_own_rules() -> None:
    # drive torque, breakaway and a target across the stopping rules (target, saturation,
    # max_blows): one call on arrays, each design against the same function on its floats
    rng = np.random.default_rng(1)
    n = 50
    speed = np.sqrt(2.0 * rng.uniform(1.0, 200.0, n))
    rate = rng.uniform(100.0, 5000.0, n)
    drive = rng.uniform(-20.0, 20.0, n)
    brk = rng.uniform(1.0, 2.0, n)
    stopped = set()
    for method in ("rigid", "energy"):
        p = BlowProblem(1.0, 1e-3, 2e4, speed, rate, brk, drive)
        s = blow_series(p, 40.0, method, target_torque=900.0, max_blows=12)
        for j in range(n):
            pj = BlowProblem(1.0, 1e-3, 2e4, float(speed[j]), rate[j], brk[j], drive[j])
            ref = blow_series(pj, 40.0, method, target_torque=900.0, max_blows=12)
            assert s.blows[j] == ref.blows == len(ref.per_blow["torque"]), (method, j)
            assert s.blows_to_target[j] == ref.blows_to_target, (method, j)
            assert bool(s.saturated[j]) == ref.saturated, (method, j)
            assert s.final_torque[j] == pytest.approx(ref.per_blow["torque"][-1], rel=1e-12)
            assert s.peak[j] == pytest.approx(ref.per_blow["peak"][0], rel=1e-12)
            assert s.joint_work[j] == pytest.approx(sum(ref.per_blow["work"]), rel=1e-12)
            stopped.add(("target" if ref.blows_to_target else "saturated" if ref.saturated
                         else "max_blows") if method == "energy" else "rigid")  # fmt: skip
    assert stopped == {"rigid", "target", "saturated", "max_blows"}


def test_blow_series_keeps_each_blow_of_many_designs_when_asked() -> None:
    # 2 and 5 blows to 600 N·m (the doctest's designs): the second row of each blow is
    # NaN once its design has stopped; the energy of each blow sums to joint_work
    p = BlowProblem(0.02, 1e-3, 2.0e4, np.array([100.0, 50.0 * math.sqrt(2.0)]), 1000.0)
    s = blow_series(p, 60.0, "energy", target_torque=600.0, history=True)
    torque = np.array(s.per_blow["torque"])
    assert torque.shape == (5, 2)
    assert np.isnan(torque[2:, 0]).all() and not np.isnan(torque[:, 1]).any()
    assert torque[0, 0] == pytest.approx(440.346, abs=1e-3)  # energy_blow's hand value
    assert np.nansum(np.array(s.per_blow["work"]), axis=0) == pytest.approx(s.joint_work)


@pytest.mark.parametrize(
    ("example", "varied"),
    [
        (NUTRUNNER_HARD, {"motor_speed": (120.0, 200.0), "flywheel_mass": (10.0, 40.0),
                          "coupling_slip_torque": (0.0, 50.0)}),
        (RARE_IMPACT_M16, {"power_spring_rate": (3e4, 8e4), "cone_angle": (0.5, 1.0),
                           "flywheel_inertia": (5e-4, 3e-3)}),
    ],
    ids=["nutrunner", "rare_impact"],
)  # fmt: skip
@pytest.mark.parametrize("rung", ["rigid", "energy"])
def test_every_tool_source_on_arrays_matches_single_runs(
    example: dict, varied: dict, rung: str, no_loop: None
) -> None:
    rng = np.random.default_rng(6)
    n = 25
    columns = {k: rng.uniform(lo, hi, n) for k, (lo, hi) in varied.items()}
    outputs = [*FLOATS, "blows_to_target"]
    chunk = evaluate_chunk(BLOW, example, columns, outputs, rung)
    assert chunk.rungs == [rung] * n
    for j in range(n):
        single = run(BLOW, {**example, **_point(columns, j)}, fidelity=rung)
        for name in outputs:
            _same(chunk.values[name][j], single.results.get(name), f"{rung} {j}: {name}")
        for check in single.checks:
            code = chunk.checks[check.name][j]
            assert code == (CHECK_OK if check.ok else CHECK_FAILED), f"{j}: {check.name}"


# --------------------------------------------------------------------------- source clutch

CLUTCH_OUTPUTS = (
    "clutch_torque_min",
    "clutch_torque_max",
    "delivered_preload_min",
    "delivered_preload_max",
    "final_torque",
    "final_preload",
    "clutch_spring_force_for_target",
)


def _same_point(chunk_values: dict, j: int, single: object, where: str) -> None:
    for name in CLUTCH_OUTPUTS:
        _same(chunk_values[name][j], single.results.get(name), f"{where}: {name}")  # type: ignore[attr-defined]


@pytest.mark.parametrize("arrangement", ["common", "per_ball"])
def test_a_clutch_limited_tool_on_arrays_is_the_single_runs(
    arrangement: str, no_loop: None
) -> None:
    # spring force, its tolerance, the flank friction and its scatter, both joint frictions
    # and the preload window's lower end at once; eight points whose flank friction with its
    # scatter passes tan 45° are a clutch that never slips: refused, as alone
    rng = np.random.default_rng(5)
    n = 60
    share = 1.0 if arrangement == "common" else 0.85 * CLUTCH_M10["ball_count"]  # K_r·i
    columns = {
        "clutch_spring_force": rng.uniform(500.0, 2500.0, n),
        "spring_force_tolerance": rng.uniform(0.0, 0.2, n),
        "flank_friction": rng.uniform(0.0, 0.9, n),
        "flank_friction_scatter": rng.uniform(0.0, 0.15, n),
        "thread_friction": rng.uniform(0.06, 0.2, n),
        "bearing_friction": rng.uniform(0.06, 0.2, n),
        "preload_min": rng.uniform(0.0, 30e3 * share, n),
    }
    columns["flank_friction"][:8] = 0.85  # ρ = atan(0.85 + 0.3) > α = 45°: never slips
    columns["flank_friction_scatter"][:8] = 0.3
    base = {**CLUTCH_M10, "spring_arrangement": arrangement, "preload_max": 40e3 * share}
    for rung in ("rigid", "energy"):  # a study's outputs are numbers: the verdict by its check
        chunk = evaluate_chunk(BLOW, base, columns, list(CLUTCH_OUTPUTS), rung)
        verdicts, computed, refused = set(), 0, 0
        for j in range(n):
            point = {**base, **_point(columns, j)}
            try:
                single = run(BLOW, point, fidelity=rung)
            except EngineError:
                refused += 1
                assert all(math.isnan(chunk.values[o][j]) for o in CLUTCH_OUTPUTS), j
                assert chunk.checks["preload_window"][j] == CHECK_UNKNOWN, j
                continue
            computed += 1
            _same_point(chunk.values, j, single, f"{rung} {j}")
            verdicts.add(single.results["preload_verdict"])
            (check,) = single.checks
            want = CHECK_OK if check.ok else CHECK_FAILED
            assert chunk.checks["preload_window"][j] == want, j
        assert computed >= n // 2 and refused >= 8, (computed, refused)
        assert {"within", "below", "above"} <= verdicts, verdicts


def test_a_clutch_sweep_takes_the_array_path_and_gives_the_verdicts_of_single_runs() -> None:
    values = np.linspace(300.0, 3000.0, 2000).tolist()
    swept = sweep(BLOW, CLUTCH_M10, "clutch_spring_force", values, fidelity="rigid")
    assert swept.rungs == ["rigid"] * 2000
    assert any("evaluated on arrays" in note for note in swept.notes), swept.notes
    verdicts = swept.results["preload_verdict"]
    assert set(verdicts) == {"below", "within", "above"}
    # the first and last point of each verdict's stretch, and the ends, against single runs
    picks = {0, 1999}
    for verdict in ("below", "within", "above"):
        where = [i for i, v in enumerate(verdicts) if v == verdict]
        picks |= {where[0], where[-1]}
    for i in sorted(picks):
        single = run(BLOW, {**CLUTCH_M10, "clutch_spring_force": values[i]}, fidelity="rigid")
        for name in (*CLUTCH_OUTPUTS, "preload_verdict"):
            want = single.results[name]
            got = swept.results[name][i]
            assert got == (pytest.approx(want, rel=1e-12) if isinstance(want, float) else want)


def test_a_clutch_sweep_over_the_thread_size_refuses_sizes_off_the_table_as_single_runs_do() -> (
    None
):
    # M8…M16 in 0.5 mm steps: the coarse pitch and the hex bearing face come from ISO tables
    # (on arrays), so M8, M10, M12, M14, M16 compute and the half sizes are refused
    values = np.arange(0.008, 0.0161, 0.0005).tolist()
    swept = sweep(BLOW, CLUTCH_M10, "thread_diameter", values, fidelity="energy")
    for i, d in enumerate(values):
        try:
            single = run(BLOW, {**CLUTCH_M10, "thread_diameter": d}, fidelity="energy")
        except EngineError:
            assert swept.rungs[i] is None and swept.results["final_preload"][i] is None, d
            continue
        assert swept.rungs[i] == "energy", d
        assert swept.results["final_preload"][i] == pytest.approx(
            single.results["final_preload"], rel=1e-12
        )
    assert sum(r is not None for r in swept.rungs) >= 5


def test_a_clutch_study_needs_what_a_single_run_needs() -> None:
    # no thread: refused as a whole, with the single run's message and field
    base = {k: v for k, v in CLUTCH_M10.items() if k != "thread_diameter"}
    with pytest.raises(EngineError, match="needs thread_diameter") as alone:
        run(BLOW, base, fidelity="rigid")
    validated, _ = BLOW.validate(base)
    x = {**validated, "clutch_spring_force": np.array([900.0, 1100.0])}
    from engine.core.spec import RunContext

    ctx = RunContext(rung="rigid", outputs=frozenset(CLUTCH_OUTPUTS), tolerance=0.01)
    assert BLOW.vectorized is not None
    with pytest.raises(EngineError, match="needs thread_diameter") as arrays:
        BLOW.vectorized(x, ctx)
    assert arrays.value.field == alone.value.field == "thread_diameter"


def test_a_clutch_whose_preload_overflows_is_refused_alone_and_on_arrays() -> None:
    # a groove angle near 0 makes tan(α − ρ) ~ 1e-300: the slipping torque (1e306 N·m) is
    # a float but the preload it gives on an M3 thread is not. Alone this is refused
    # (it was "inf kN…inf kN", verdict "within"); the sweep and the study agree
    base = {
        **CLUTCH_M10,
        "flank_friction": 0.0,
        "flank_friction_scatter": 0.0,
        "clutch_spring_force": 1e6,
        "ball_circle_diameter": 2.0,
        "thread_diameter": 0.003,
        "preload_min": 15e3,
    }
    base.pop("preload_max")
    with pytest.raises(EngineError, match="overflows") as err:
        run(BLOW, {**base, "groove_angle": 1e-300}, fidelity="rigid")
    assert err.value.field == "groove_angle"
    swept = sweep(BLOW, base, "groove_angle", [1e-3, 1e-300], fidelity="rigid")
    assert swept.results["preload_verdict"] == ["within", None]
    assert swept.rungs == ["rigid", None]
    chunk = evaluate_chunk(
        BLOW, base, {"groove_angle": np.array([1e-3, 1e-300])}, ["final_preload"], "rigid"
    )
    assert chunk.checks["preload_window"].tolist() == [CHECK_OK, CHECK_UNKNOWN]


def test_a_study_of_outputs_the_rung_leaves_null_still_gives_the_checks_of_single_runs() -> None:
    # without a target preload the clutch path leaves clutch_spring_force_for_target null;
    # a study asking only for it has nothing on the array path to tell a refused point
    # by, so the points run alone: every check and rung as a single run gives them
    base = {k: v for k, v in CLUTCH_M10.items() if k != "target_preload"}
    forces = np.array([900.0, 1100.0, 2000.0])
    chunk = evaluate_chunk(
        BLOW, base, {"clutch_spring_force": forces}, ["clutch_spring_force_for_target"], "rigid"
    )
    assert chunk.rungs == ["rigid"] * 3
    for j, force in enumerate(forces.tolist()):
        (check,) = run(BLOW, {**base, "clutch_spring_force": force}, fidelity="rigid").checks
        assert chunk.checks["preload_window"][j] == (CHECK_OK if check.ok else CHECK_FAILED)
    assert np.isnan(chunk.values["clutch_spring_force_for_target"]).all()


def test_a_buffer_refilled_in_place_gives_the_new_designs_answer() -> None:
    # a caller that reuses its input arrays: the estimates and the array path of each
    # request read the values the arrays hold now (an identity-keyed module cache once
    # answered the previous design; the setup now lives in the request's scratch)
    from engine.core.spec import RunContext

    fixed, _ = BLOW.validate(RARE_IMPACT_M16)
    springs = np.array([4e4, 5e4])
    friction = np.array([0.10, 0.12])
    x = {**fixed, "power_spring_rate": springs, "thread_friction": friction}
    energy_rung = BLOW.rung_names.index("energy")
    for rates, mus in (((4e4, 5e4), (0.10, 0.12)), ((6e4, 7e4), (0.14, 0.16))):
        springs[:] = rates
        friction[:] = mus
        # a request of its own: its scratch holds its setup and no other's
        ctx = RunContext(rung="energy", outputs=frozenset(FLOATS), tolerance=0.01)
        estimate = BLOW.rungs[energy_rung].estimate(x)
        got = BLOW.vectorized(x, ctx).values
        for j in range(2):
            alone = run(
                BLOW,
                {**RARE_IMPACT_M16, "power_spring_rate": rates[j], "thread_friction": mus[j]},
                fidelity="energy",
            )
            assert estimate[j] == pytest.approx(alone.error_estimate, rel=1e-12)
            for name in ("tool_speed", "tool_energy_used", "joint_rate_used", "final_preload"):
                assert got[name][j] == pytest.approx(alone.results[name], rel=1e-12), name
