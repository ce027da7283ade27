"""The sweep's bookkeeping: a named rung's estimates made when read, the range told by the
least and largest value, and the recommended-range warning, each against hand values."""

import dataclasses
from typing import Any

import numpy as np
import pytest

import engine
from engine import InputOutOfRange, Rung, fixed_error
from engine.core import points
from tests.toys import TOY

BASE = {"diameter": 0.2}


def _counting_toy(calls: list[Any]) -> Any:
    """TOY whose rough rung estimates diameter/10 and records every call (arrays included)."""

    def estimate(x: Any) -> Any:
        calls.append(x["diameter"])
        return x["diameter"] / 10.0

    return dataclasses.replace(
        TOY,
        rungs=(Rung("rough", "off", estimate), Rung("exact", "", fixed_error(0.0))),
        vector_rungs=("rough", "exact"),
    )


def test_a_named_rungs_estimates_are_made_when_read() -> None:
    calls: list[Any] = []
    toy = _counting_toy(calls)
    s = engine.sweep(toy, BASE, "diameter", [0.1, 0.3], outputs=["energy"], fidelity="rough")
    # J = m d²/8 with m = 1 kg, T = ½ J ω² at 100 rad/s (the toy's array path, either rung)
    assert s.results["energy"] == pytest.approx([0.5 * d**2 / 8 * 1e4 for d in (0.1, 0.3)])
    assert calls == []  # the columns alone did not need the estimate
    assert s.error_estimates == pytest.approx([0.01, 0.03], rel=1e-15)
    assert len(calls) == 1 and s.error_array is s.error_array  # once, then kept


def test_auto_still_chooses_per_point_from_the_estimates() -> None:
    calls: list[Any] = []
    s = engine.sweep(_counting_toy(calls), BASE, "diameter", [0.05, 0.5], outputs=["energy"])
    # estimates 0.005 ≤ 0.01 → rough; 0.05 > 0.01 → exact (its own estimate: 0)
    assert s.rungs == ["rough", "exact"] and s.error_estimates == [0.005, 0.0]
    assert len(calls) == 1


@pytest.mark.parametrize("bad", [np.nan, np.inf, -0.1, 0.0, 20.0])
def test_an_out_of_range_value_anywhere_is_refused_naming_the_field(bad: float) -> None:
    values = [0.1, 0.2, bad, 0.3]
    with pytest.raises(InputOutOfRange) as info:
        engine.sweep(TOY, BASE, "diameter", values, fidelity="exact")
    assert info.value.field == "diameter"


@pytest.mark.parametrize("bad", [np.nan, np.inf, -0.1, 0.0, 20.0])
@pytest.mark.parametrize("where", [0, 2, 3, 9])
def test_a_long_array_is_refused_at_a_bad_value_anywhere_and_kept_as_the_sweeps_own(
    bad: float, where: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A float array longer than a block is copied with its ends read block by block
    (blocks of 3 here: a bad value first, at a block's edge or last is refused); a good one
    is the sweep's own copy, equal to the caller's and unchanged when the caller's changes."""
    monkeypatch.setattr(points, "FINITE_BLOCK", 3)
    values = np.linspace(0.1, 0.3, 10)
    bad_values = values.copy()
    bad_values[where] = bad
    with pytest.raises(InputOutOfRange) as info:
        engine.sweep(TOY, BASE, "diameter", bad_values, fidelity="exact")
    assert info.value.field == "diameter"
    s = engine.sweep(TOY, BASE, "diameter", values, fidelity="exact", outputs=["energy"])
    assert s.value_array.tolist() == values.tolist()
    assert not np.shares_memory(s.value_array, values)
    values[where] = bad  # the caller reuses its array
    assert s.value_array.tolist() == np.linspace(0.1, 0.3, 10).tolist()
    assert s.results["energy"] == pytest.approx([0.5 * d**2 / 8 * 1e4 for d in s.values])


@pytest.mark.parametrize("block", [1, 3, 1 << 16])
def test_copy_with_ends_equals_a_copy_and_its_min_and_max(
    block: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The blocked copy equals the values, its ends their min() and max() (NaN where a value
    is NaN, at the first, a block's edge or the last place; ±inf kept)."""
    monkeypatch.setattr(points, "FINITE_BLOCK", block)
    rng = np.random.default_rng(11)
    cases = [rng.normal(size=10), np.array([-0.0, 0.0]), np.array([5.0])]
    for bad in (np.nan, np.inf, -np.inf):
        for where in (0, 2, 3, 9):
            column = rng.normal(size=10)
            column[where] = bad
            cases.append(column)
    for column in cases:
        got, low, high = points.copy_with_ends(column)
        assert np.array_equal(got, column, equal_nan=True) and not np.shares_memory(got, column)
        assert np.array_equal([low, high], [column.min(), column.max()], equal_nan=True)


def test_the_recommended_range_warning_counts_the_points_outside() -> None:
    # the toy's speed: recommended 0…500 rad/s, allowed up to 1e4
    inside = engine.sweep(TOY, BASE, "speed", [0.0, 500.0], fidelity="exact")
    assert not any("recommends" in w for w in inside.warnings)
    outside = engine.sweep(TOY, BASE, "speed", [0.0, 500.0, 750.0], fidelity="exact")
    assert [w for w in outside.warnings if "recommends" in w] == [
        "speed is outside the range the source recommends (0…500 rad/s) at 1 of 3 points"
    ]


@pytest.mark.parametrize(
    ("model", "vary", "values", "asked"),
    [
        (
            "preload.tightening",
            "thread_friction",
            (0.10, 0.12, 0.14),
            ("assembly_preload", "tightening_torque"),
        ),
        (
            "preload.control",
            "thread_friction",
            (0.10, 0.12, 0.14),
            ("nominal_preload", "target_torque"),
        ),
        (
            "joint.vdi2230",
            "working_load",
            (6e3, 8e3, 1e4),
            ("additional_bolt_load", "required_preload_min", "max_bolt_force"),
        ),
    ],
)
def test_the_array_paths_give_only_the_outputs_asked_for(
    model: str, vary: str, values: tuple[float, ...], asked: tuple[str, ...]
) -> None:
    spec = engine.get_model(model)
    x, _ = spec.validate(spec.examples[0])
    ctx = engine.core.spec.RunContext("closed_form", frozenset(asked), 0.01)
    got = spec.vectorized({**x, vary: np.array(values)}, ctx)  # type: ignore[misc]
    assert set(got.values) == set(asked)
    for j, v in enumerate(values):  # each the single run's, to the last bit
        one = engine.run(spec, {**spec.examples[0], vary: v}, outputs=asked)
        assert [got.values[name][j] for name in asked] == [one.results[name] for name in asked]


def test_the_nutrunner_array_path_leaves_the_drive_details_out() -> None:
    spec = engine.get_model("nutrunner.drive")
    asked = ("kinetic_energy", "acceleration_time", "impact_torque")
    x, _ = spec.validate(spec.examples[0])
    speed = np.array([130.0, 146.6, 160.0])
    ctx = engine.core.spec.RunContext("closed_form", frozenset(asked), 0.01)
    got = spec.vectorized({**x, "motor_speed": speed}, ctx)  # type: ignore[misc]
    # the energy, the time and the torques (the checks read the spindle torque), no details
    assert set(got.values) == set(asked) | {
        "shaft_stiffness",
        "spindle_stiffness",
        "max_spindle_torque",
        "spindle_torque_reserve",
        "friction_clutch_torque",
    }
    for j, w in enumerate(speed.tolist()):  # each the single run's, to the last bit
        one = engine.run(spec, {**spec.examples[0], "motor_speed": w}, outputs=asked)
        assert [got.values[name][j] for name in asked] == [one.results[name] for name in asked]


def test_a_blow_sweep_of_first_blow_outputs_equals_the_full_series() -> None:
    """A sweep asking for the first blow's outputs runs one blow: the same first blow as the
    first of the whole series (a study, which reads the checks, runs the whole series)."""
    spec = engine.get_model("blow.joint")
    first = ("peak_torque", "torque_after_first_blow")
    t0 = [54.0, 60.0, 66.0]
    alone = engine.sweep(
        spec, spec.examples[0], "snug_torque", t0, outputs=first, fidelity="energy"
    )
    every = engine.sweep(spec, spec.examples[0], "snug_torque", t0, fidelity="energy")
    for name in first:
        assert alone.results[name] == every.results[name]
    assert every.results["blows_to_target"] != [1, 1, 1]  # the series is longer than one blow
    for j, v in enumerate(t0):
        one = engine.run(spec, {**spec.examples[0], "snug_torque": v}, fidelity="energy")
        assert [alone.results[name][j] for name in first] == [one.results[name] for name in first]


def test_a_named_rungs_estimates_are_of_the_values_swept_not_of_the_callers_array_later() -> None:
    """The estimates of a named rung are made when first read; the sweep keeps its own
    copy of the values, so a caller changing its array in between does not change them,
    and the result pickles before they are read (with them made)."""
    import pickle

    spec = engine.get_model("preload.tightening")
    example = spec.examples[0]
    values = np.linspace(0.08, 0.16, 5)
    first = engine.sweep(spec, example, "thread_friction", values, fidelity=spec.rung_names[0])
    expected = np.array(first.error_array)
    again = engine.sweep(spec, example, "thread_friction", values, fidelity=spec.rung_names[0])
    values *= 1.2  # the caller reuses its array before reading the estimates
    assert np.array_equal(again.error_array, expected, equal_nan=True)
    third = engine.sweep(
        spec, example, "thread_friction", values / 1.2, fidelity=spec.rung_names[0]
    )
    copied = pickle.loads(pickle.dumps(third))
    assert np.array_equal(copied.error_array, expected, equal_nan=True)
    assert np.array_equal(copied.columns["tightening_torque"], first.columns["tightening_torque"])


def _two_column_toy(energy: Any, inertia: Any) -> Any:
    """TOY whose array path gives ``energy(d)`` and ``inertia(d)`` of the diameters d."""

    def vectorized(x: Any, ctx: Any) -> Any:
        d = np.asarray(x["diameter"], dtype=float)
        return engine.Result(
            values={"energy": energy(d), "inertia": inertia(d)}, rung=ctx.rung, error_estimate=0.0
        )

    return dataclasses.replace(TOY, vectorized=vectorized)


@pytest.mark.parametrize(
    ("energy", "inertia", "want_energy", "want_inertia", "refused"),
    [
        # finite values whose sum overflows: told value by value, none refused
        (
            lambda d: np.where(d > 0.2, 1e308, d),
            lambda d: np.where(d > 0.2, 1e308, 2.0 * d),
            [0.1, 1e308, 1e308],
            [0.2, 1e308, 1e308],
            0,
        ),
        # a NaN beside a finite output is a null, not a refused point
        (
            lambda d: np.where(d == 0.3, np.nan, d),
            lambda d: 2.0 * d,
            [0.1, None, 0.4],
            [0.2, 0.6, 0.8],
            0,
        ),
        # NaN in every output: the point is refused (no rung), the others kept
        (
            lambda d: np.where(d == 0.3, np.nan, d),
            lambda d: np.where(d == 0.3, np.nan, 2.0 * d),
            [0.1, None, 0.4],
            [0.2, None, 0.8],
            1,
        ),
    ],
)
def test_a_point_is_refused_only_where_every_output_is_nan(
    energy: Any, inertia: Any, want_energy: list[Any], want_inertia: list[Any], refused: int
) -> None:
    toy = _two_column_toy(energy, inertia)
    s = engine.sweep(
        toy, BASE, "diameter", [0.1, 0.3, 0.4], outputs=["energy", "inertia"], fidelity="exact"
    )
    assert s.results == {"energy": want_energy, "inertia": want_inertia}
    assert s.rungs == ["exact", None if refused else "exact", "exact"]
    said = [n for n in s.notes if "could not be computed" in n]
    assert said == ([f"{refused} of 3 points could not be computed; null there"] if refused else [])


@pytest.mark.parametrize(("rung", "code"), [("rough", 0), ("exact", 1)])
def test_one_rung_everywhere_codes_every_point_with_it(rung: str, code: int) -> None:
    # rung 0 everywhere is the allocator's zeros; a later rung a filled column
    s = engine.sweep(
        _counting_toy([]), BASE, "diameter", [0.1, 0.2, 0.3], outputs=["energy"], fidelity=rung
    )
    assert s.rung_codes.dtype == np.int8 and s.rung_codes.tolist() == [code] * 3
    assert s.rung_names == ("rough", "exact") and s.rungs == [rung] * 3 and s.rung == rung
    assert s.rung_codes.flags.writeable  # a column of the sweep's own, not a broadcast view


@pytest.mark.parametrize("block", [1, 3, 1 << 16])
def test_all_finite_says_no_exactly_where_a_value_is_nan_or_infinite(
    block: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The blocked test equals a whole-column mask's on columns with one bad value at the
    first, a block's edge or the last place, on finite values whose sum overflows, on ±0,
    subnormals and empty or two-dimensional arrays."""
    monkeypatch.setattr(points, "FINITE_BLOCK", block)
    rng = np.random.default_rng(7)
    cases = [np.empty(0), np.array([-0.0, 0.0, 5e-324]), np.full(7, 1e308), rng.random((3, 5))]
    for bad in (np.nan, np.inf, -np.inf):
        for where in (0, 2, 3, 6, 9):
            column = rng.random(10)
            column[where] = bad
            cases.append(column)
    for column in cases:
        assert points.all_finite(column) == bool(np.isfinite(column).all())


def test_a_swept_negative_zero_answers_as_a_single_run_of_it():
    """A single run folds -0.0 to 0.0 (Param.check); a sweep folds its values the same way,
    on the short path and on the long one (copied with its ends, over 65,536 values), so
    F_SA at F_A = -0.0 is +0.0 either way, and the swept values' largest is +0.0."""
    import math

    import numpy as np

    import engine
    from engine.core import points

    spec = engine.get_model("joint.vdi2230")
    base = dict(spec.examples[0])
    single = engine.run(spec, {**base, "working_load": -0.0}).results["additional_bolt_load"]
    assert single == 0.0 and math.copysign(1.0, single) == 1.0
    long = np.r_[np.full(points.FINITE_BLOCK + 5, -0.0), 0.0]
    for values in ([-0.0, 100.0], long):
        sweep = engine.sweep(spec, base, "working_load", values)
        assert math.copysign(1.0, sweep.value_array[0]) == 1.0
        column = sweep.columns["additional_bolt_load"]
        assert column[0] == 0.0 and math.copysign(1.0, column[0]) == 1.0
    copied, low, high = points.copy_with_ends(long)
    assert (low, high) == (0.0, 0.0) and math.copysign(1.0, high) == 1.0
    assert not np.signbit(copied).any()
