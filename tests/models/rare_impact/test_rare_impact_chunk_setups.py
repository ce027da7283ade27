"""A study's looped simulation points take their set-up made for the chunk at once.

:func:`engine.procedures.striker_cycle.cycle_setups` works out, on arrays, what
:func:`simulate_cycle` works out from one design's inputs before its compiled driver (the
kernel's parameters, stage 1's speeds, times and step, the stages' step sizes); a design's
row must be the numbers it makes alone to the last bit, a design the cycle refuses (or
whose numbers are not all finite) must set itself up, and the chunk's points must be
each point alone, refusals and their reasons included.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pytest

import engine
from engine.core.runner import run_point
from engine.models.rare_impact import REFERENCE_DESIGN
from engine.procedures import striker_cycle as sc
from engine.studies.plan import CHECK_FAILED, CHECK_OK, evaluate_chunk, refusal_key

SPEC = engine.get_model("impact.rare")
#: Inputs scaled by up to e^±0.6 around the reference design, a design at a time.
VARIED = (
    "motor_torque",
    "roller_mass",
    "half_coupling_mass",
    "striker_mass",
    "power_spring_rate",
    "return_spring_rate",
    "power_spring_preload",
    "return_spring_preload",
    "engagement_height",
    "stepped_shaft_mass",
)


def _chunk(geometry: str, n: int, seed: int) -> dict[str, Any]:
    """The reference design with ``VARIED`` drawn per design (arrays), the rest as numbers;
    a few designs snap at lift-off (a power-spring preload of 90 mm) or reach past h1."""
    rng = np.random.default_rng(seed)
    x: dict[str, Any] = dict(REFERENCE_DESIGN, roller_geometry=geometry)
    for name in VARIED:
        x[name] = REFERENCE_DESIGN[name] * np.exp(rng.uniform(-0.6, 0.6, n))
    x["power_spring_preload"][:3] = 0.09  # snaps
    x["engagement_height"][3:6] = 1.5 * REFERENCE_DESIGN["release_travel"]  # stops at h1
    return x


def _one(x: dict[str, Any], j: int) -> dict[str, Any]:
    return {k: float(v[j]) if isinstance(v, np.ndarray) else v for k, v in x.items()}


def _bits(a: np.ndarray) -> bytes:
    return np.asarray(a, dtype=float).tobytes()


@pytest.mark.parametrize("geometry", sc.GEOMETRIES)
def test_a_designs_row_is_its_own_set_up_and_its_cycle(geometry: str) -> None:
    """Each row holds the design's own kernel and contact parameters bit for bit, and the
    cycle run on it is the cycle run alone, field by field (notes and warnings included)."""
    x = _chunk(geometry, 40, seed=7)
    rows = sc.cycle_setups(x)
    assert rows is not None and all(row is not None for row in rows)
    for j, row in enumerate(rows):
        alone = sc.step_inputs(_one(x, j))
        g = sc._geo(alone)
        assert _bits(row[: sc.NPAR]) == _bits(sc._params(alone, g))
        assert _bits(row[sc._SETUP_PU : sc._SETUP_TAIL]) == _bits(sc._contact_params(alone, g))
        own = sc.simulate_cycle(_one(x, j), sentences=False)
        made = sc.simulate_cycle(_one(x, j), sentences=False, setup=row)
        assert repr(dataclasses.asdict(made)) == repr(dataclasses.asdict(own))
    snaps = [sc.simulate_cycle(_one(x, j)).snap for j in range(6)]
    assert snaps[:3] == [True] * 3 and snaps[3:] == [False] * 3


def test_a_refused_design_sets_itself_up_and_is_refused_as_alone() -> None:
    """A design whose preloads do not hold the half-coupling has no row (the cycle refuses
    it itself); in the chunk it is refused with the reason it has alone, its neighbours
    answered as alone."""
    x = _chunk("symmetric_v", 4, seed=3)
    x["gravity"] = -100.0
    x["power_spring_preload"][1] = 1e-6
    rows = sc.cycle_setups(x)
    assert rows is not None
    assert [row is None for row in rows] == [False, True, False, False]
    with pytest.raises(engine.EngineError) as alone:
        sc.simulate_cycle(_one(x, 1))
    base = {k: v for k, v in x.items() if not isinstance(v, np.ndarray)}
    columns = {k: v for k, v in x.items() if isinstance(v, np.ndarray)}
    outputs = tuple(SPEC.scalar_output_names)
    chunk = evaluate_chunk(SPEC, base, columns, outputs, "simulation", 0.05)
    assert chunk.rungs == ["simulation", None, "simulation", "simulation"]
    (reason,) = chunk.refusals
    assert reason == refusal_key(alone.value)
    for j in (0, 2, 3):
        values, _ = SPEC.validate(_one(x, j))
        _, point, _ = run_point(SPEC, values, "simulation", outputs, tolerance=0.05, budget_s=None)
        got = [chunk.values[k][j] for k in outputs]
        want = [math.nan if point[k] is None else float(point[k]) for k in outputs]
        assert _bits(np.array(got)) == _bits(np.array(want))


@pytest.mark.parametrize("given", ["cone_angle", "motor_no_load_speed"])
def test_no_rows_where_numpys_tan_or_log1p_would_be_read(given: str) -> None:
    """A varied cone angle (tan) or a motor's no-load speed (log1p): numpy's own need not be
    libm's to the last bit, so every design sets itself up."""
    x = _chunk("symmetric_v", 4, seed=5)
    if given == "cone_angle":
        x["cone_angle"] = np.linspace(0.6, 0.9, 4)
    else:
        x["motor_no_load_speed"] = 2000.0
    assert sc.cycle_setups(x) is None


def test_arithmetic_that_would_raise_for_one_design_leaves_the_chunk_to_its_designs() -> None:
    """Where numpy raises on the arrays (a division by zero one design's floats would
    raise), no design takes a row: stage 4's step sizes raise under the chunk's error
    state (the guard makes them NaN, as for one design), and no row is all finite."""
    x = _chunk("symmetric_v", 4, seed=9)
    x["auxiliary_spring_rate"] = 0.0  # stage 4's period divides by it
    assert sc.cycle_setups(x) == [None] * 4
    x["roller_radius"] = 0.0  # the lift-off speed divides by the rollers' push at rest
    with pytest.raises(ZeroDivisionError):
        sc.simulate_cycle(_one(x, 0))
    assert sc.cycle_setups(x) is None


def test_a_looped_point_with_its_row_is_run_point_alone() -> None:
    """A chunk's looped simulation points, given their rows, equal run_point on each design
    alone, every output and verdict."""
    x = _chunk("single_cone", 12, seed=11)
    base = {k: v for k, v in x.items() if not isinstance(v, np.ndarray)}
    columns = {k: v for k, v in x.items() if isinstance(v, np.ndarray)}
    outputs = tuple(SPEC.scalar_output_names)
    chunk = evaluate_chunk(SPEC, base, columns, outputs, "simulation", 0.05)
    assert chunk.rungs == ["simulation"] * 12 and not chunk.refusals
    for j in range(12):
        values, _ = SPEC.validate(_one(x, j))
        _, point, verdicts = run_point(
            SPEC, values, "simulation", outputs, tolerance=0.05, budget_s=None
        )
        got = [chunk.values[k][j] for k in outputs]
        want = [math.nan if point[k] is None else float(point[k]) for k in outputs]
        assert _bits(np.array(got)) == _bits(np.array(want))
        for name, ok in verdicts:
            assert chunk.checks[name][j] == (CHECK_OK if ok else CHECK_FAILED)


def test_the_outputs_of_the_inputs_alone_are_each_designs_own() -> None:
    """_prepare_points' outputs of the inputs alone are _of_inputs' of each design alone,
    bit for bit and in their order (an int roller count varied as an int array included);
    where numpy raises on them, the points work them out."""
    from engine.models import rare_impact as ri

    x = _chunk("paper", 30, seed=13)
    x["roller_count"] = np.arange(30, dtype=np.int64) % 6 + 2
    x["gravity"] = -9.80665
    prepared = ri._prepare_points(x, "simulation")
    assert prepared is not None and ri._prepare_points(x, "closed_form") is None
    for j, (setup, known) in enumerate(prepared):
        one = {k: (v[j].item() if isinstance(v, np.ndarray) else v) for k, v in x.items()}
        alone = ri._of_inputs(one, True, frozenset())
        assert setup is not None and len(known) == len(alone) == len(ri._OF_INPUTS)
        assert repr(known) == repr(alone) and None not in known
    x["striker_mass"] = 0.0 * x["striker_mass"]
    x["half_coupling_mass"] = 0.0
    x["roller_mass"] = 0.0 * x["roller_mass"]  # the moving mass divides: 0
    assert all(known is None for _, known in ri._prepare_points(x, "simulation"))


def test_a_design_whose_release_speed_has_no_root_leaves_its_neighbours_their_rows() -> None:
    """Springs of 10 N/m under g = -100: the preloads do not hold the half-coupling and
    the release speed's root is of a negative number (NaN on one design's floats, refused;
    numpy's raising state raised for the whole chunk, which took every design's row): the
    design sets itself up and is refused, its neighbours keep their rows."""
    x = _chunk("symmetric_v", 6, seed=11)
    x["gravity"] = -100.0
    x["power_spring_rate"][2] = 10.0
    x["auxiliary_spring_rate"] = np.full(6, REFERENCE_DESIGN["auxiliary_spring_rate"])
    x["auxiliary_spring_rate"][2] = 10.0
    rows = sc.cycle_setups(x)
    assert rows is not None
    assert [row is None for row in rows] == [False, False, True, False, False, False]
    with pytest.raises(engine.InfeasibleDesign, match="do not hold the half-coupling"):
        sc.simulate_cycle(_one(x, 2))
    for j in (0, 1, 3, 4, 5):
        own = sc.simulate_cycle(_one(x, j), sentences=False)
        made = sc.simulate_cycle(_one(x, j), sentences=False, setup=rows[j])
        assert repr(dataclasses.asdict(made)) == repr(dataclasses.asdict(own))
