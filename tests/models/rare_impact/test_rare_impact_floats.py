"""One design runs the closed form on Python floats, many on arrays: the same numbers.

:mod:`engine.procedures.striker_cycle` takes one design as Python floats (``math``, no
numpy scalars) and many as arrays (numpy), through the same lines. Python's floats raise
where numpy gives inf or NaN (a division by zero, a square that overflows), so the
procedure guards those lines; here 300 random designs, a fifth of their inputs at the ends
of the declared ranges, go through both paths and every field of the cycle, of its error
estimate and of the model's outputs must agree to 1e-13 relative (inf with inf, NaN with
NaN), the single design's as Python floats.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from engine import EngineError, run
from engine.core.spec import RunContext
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from engine.procedures.striker_cycle import (
    GEOMETRIES,
    HELD,
    closed_form_cycle,
    closed_form_errors,
    step_inputs,
)

FIELDS = (
    "release_speed",
    "spin_up_time",
    "release_radius",
    "release_velocity",
    "engagement_time",
    "max_travel",
    "return_time",
    "home_time",
    "relock_time",
)
OUTPUTS = [o.name for o in RARE_IMPACT.outputs if not o.series and o.kind == "float"]
REL = 1e-13
#: Designs per (geometry, motor) group: 3 geometries × with and without a no-load speed.
PER_GROUP = 50


def _bounds(name: str) -> tuple[float, float]:
    p = RARE_IMPACT.param(name)
    lo = -1e3 if p.minimum is None else p.minimum
    hi = 1e3 if p.maximum is None else p.maximum
    if p.exclusive_minimum:
        lo = math.nextafter(lo, math.inf) if lo == 0.0 else lo * (1.0 + 1e-12)
    if p.exclusive_maximum:
        hi = hi * (1.0 - 1e-12)
    return float(lo), float(hi)


def _designs(rng: np.random.Generator, geometry: str, motor: bool) -> list[dict[str, Any]]:
    """PER_GROUP designs: each input ×e^±1.5 about the reference, 20 % at a range's end."""
    names = [p.name for p in RARE_IMPACT.inputs if p.is_numeric and p.name in REFERENCE_DESIGN]
    out = []
    for _ in range(PER_GROUP):
        d: dict[str, Any] = {**REFERENCE_DESIGN, "roller_geometry": geometry}
        for name in names:
            lo, hi = _bounds(name)
            ref = float(REFERENCE_DESIGN[name])
            u = rng.random()
            if u < 0.1:
                v = lo
            elif u < 0.2:
                v = hi
            elif ref > 0.0:
                v = ref * math.exp(rng.uniform(-1.5, 1.5))
            else:
                v = rng.uniform(max(lo, -20.0), min(hi, 20.0))
            v = min(max(v, lo), hi)
            d[name] = round(v) if RARE_IMPACT.param(name).kind == "int" else v
        if motor:
            d["motor_no_load_speed"] = 1000.0 * math.exp(rng.uniform(-1.5, 2.5))
        out.append(d)
    return out


def _same(a: Any, b: Any) -> bool:
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return a == b or abs(a - b) <= REL * max(abs(a), abs(b))


def _columns(designs: list[dict[str, Any]]) -> dict[str, Any]:
    x = {
        k: np.array([d[k] for d in designs], dtype=float)
        for k in designs[0]
        if k != "roller_geometry"
    }
    return {**x, "roller_geometry": designs[0]["roller_geometry"]}


@pytest.mark.parametrize("motor", [False, True])
@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_one_design_on_floats_gives_the_array_paths_numbers(geometry: str, motor: bool) -> None:
    rng = np.random.default_rng(2026 + 7 * GEOMETRIES.index(geometry) + motor)
    designs = _designs(rng, geometry, motor)
    xs = step_inputs(_columns(designs))
    many = closed_form_cycle(xs, refuse=False)
    errors = closed_form_errors(xs, many)
    held = 0
    for i, d in enumerate(designs):
        x1 = step_inputs(RARE_IMPACT.validate(d)[0])
        one = closed_form_cycle(x1, refuse=False)
        assert int(one.refusal) == int(many.refusal[i]), d
        if one.refusal != HELD:
            continue
        held += 1
        for name in FIELDS:
            value = getattr(one, name)
            assert type(value) is float, (name, type(value))  # no numpy scalar on one design
            assert _same(value, getattr(many, name)[i]), (name, value, getattr(many, name)[i], d)
        assert bool(one.snap) == bool(many.snap[i]) and bool(one.flies) == bool(many.flies[i])
        for group, value in closed_form_errors(x1, one).items():
            assert type(value) is float, (group, type(value))
            assert _same(value, errors[group][i]), (group, value, errors[group][i], d)
    assert held >= PER_GROUP // 3, held  # the comparison is not vacuous


@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_a_run_gives_the_outputs_of_the_array_path(geometry: str) -> None:
    """engine.run (one design, floats) against the model's array path at the same points."""
    rng = np.random.default_rng(41 + GEOMETRIES.index(geometry))
    designs = _designs(rng, geometry, motor=False)
    ctx = RunContext(
        rung="closed_form", outputs=frozenset(OUTPUTS) | {"full_engagement"}, tolerance=1e-2
    )
    assert RARE_IMPACT.vectorized is not None
    columns: dict[str, Any] = dict(RARE_IMPACT.vectorized(_columns(designs), ctx).values)
    # null on the closed form at every point (no column): half_coupling_release_speed
    outputs = [name for name in OUTPUTS if columns[name] is not None]
    assert len(outputs) == len(OUTPUTS) - 1
    compared = 0
    for i, d in enumerate(designs):
        try:
            single: dict[str, Any] = dict(run(RARE_IMPACT, d, fidelity="closed_form").results)
        except EngineError:
            assert all(math.isnan(columns[name][i]) for name in outputs)
            continue
        for name in outputs:
            value, column = single[name], columns[name][i]
            if value is None:
                assert not math.isfinite(column), (name, column)
            else:
                assert _same(value, column), (name, value, column, d)
                compared += 1
        assert single["full_engagement"] == bool(columns["full_engagement"][i])
    assert compared >= 10 * len(outputs)
