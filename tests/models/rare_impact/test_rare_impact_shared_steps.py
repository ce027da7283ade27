"""impact.rare's steps share one request's work and still give the same numbers.

A request converts its inputs once (:func:`step_inputs`) and the cycle, its error
estimate and the geometry note reuse the stage-1 speeds, stage 2's coefficients and the
roller geometries derived from them. Each step given a plain mapping converts and
derives everything anew: the two must agree to the last bit, design by design, and the
array path (many designs at once) must agree with both.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from engine.models.rare_impact import REFERENCE_DESIGN
from engine.procedures.striker_cycle import (
    GEOMETRIES,
    CycleOutcome,
    closed_form_cycle,
    closed_form_errors,
    release_speed_of,
    step_inputs,
)

#: Inputs scaled by up to e^±0.7 around the reference design (gravity and cone angle drawn).
_SCALED = (
    "flywheel_inertia",
    "motor_torque",
    "roller_mass",
    "roller_radius",
    "half_coupling_mass",
    "stepped_shaft_mass",
    "striker_mass",
    "power_spring_rate",
    "auxiliary_spring_rate",
    "return_spring_rate",
    "power_spring_preload",
    "auxiliary_spring_preload",
    "return_spring_preload",
    "release_travel",
    "engagement_height",
    "jaw_height",
    "roller_friction",
)
_FIELDS = (
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


def _designs(n: int, geometry: str, no_load: bool, seed: int) -> list[dict[str, Any]]:
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        x = dict(REFERENCE_DESIGN, roller_geometry=geometry)
        for name in _SCALED:
            x[name] = float(REFERENCE_DESIGN[name] * math.exp(rng.uniform(-0.7, 0.7)))
        x["cone_angle"] = float(rng.uniform(0.3, 1.2))
        x["gravity"] = float(rng.uniform(-15.0, 15.0))
        if no_load:
            x["motor_no_load_speed"] = float(rng.uniform(200.0, 2000.0))
        out.append(x)
    return out


def _same(a: Any, b: Any) -> bool:
    """Equal to the bit, NaN equal to NaN."""
    a, b = float(a), float(b)
    return a == b or (math.isnan(a) and math.isnan(b))


def _fields(o: CycleOutcome) -> list[Any]:
    return [getattr(o, f) for f in _FIELDS] + [o.refusal, o.snap, o.flies]


CASES = [(geo, no_load) for geo in GEOMETRIES for no_load in (False, True)]


@pytest.mark.parametrize(("geometry", "no_load"), CASES)
def test_shared_work_gives_each_design_the_numbers_it_gives_alone(
    geometry: str, no_load: bool
) -> None:
    """84 designs per case, 504 in all: the shared and the from-scratch steps agree bit for bit."""
    designs = _designs(84, geometry, no_load, seed=2 * GEOMETRIES.index(geometry) + no_load)
    blows = 0
    for x in designs:
        alone = closed_form_cycle(x, refuse=False)
        shared_x = step_inputs(x)
        shared = closed_form_cycle(shared_x, refuse=False)
        assert all(map(_same, _fields(shared), _fields(alone))), x
        e_alone, e_shared = closed_form_errors(x, alone), closed_form_errors(shared_x, shared)
        assert e_alone.keys() == e_shared.keys()
        assert all(_same(e_shared[k], e_alone[k]) for k in e_alone), x
        for other in GEOMETRIES:
            if alone.refused:
                break
            want = release_speed_of({**x, "roller_geometry": other})
            assert _same(release_speed_of(shared_x, other), want), (x, other)
        blows += bool(alone.blow) and not alone.refused
    assert blows > 10  # the later stages ran for many of them, not only refusals


@pytest.mark.parametrize(("geometry", "no_load"), CASES)
def test_the_array_path_gives_each_design_its_single_numbers(geometry: str, no_load: bool) -> None:
    """The same designs as arrays (one call, no sharing across designs): within 1e-15."""
    designs = _designs(84, geometry, no_load, seed=2 * GEOMETRIES.index(geometry) + no_load)
    columns: dict[str, Any] = {
        k: np.array([x[k] for x in designs]) if isinstance(v, float) else v
        for k, v in designs[0].items()
    }
    many = closed_form_cycle(columns)
    for j, x in enumerate(designs):
        one = closed_form_cycle(step_inputs(x), refuse=False)
        if one.refused:
            assert many.refused[j]
            continue
        for f in _FIELDS:
            a, b = float(getattr(many, f)[j]), float(getattr(one, f))
            assert _same(a, b) or abs(a - b) <= 1e-15 * abs(b), (f, j, a, b)


def test_a_different_design_is_never_answered_from_another_ones_work() -> None:
    """Two requests, two conversions: the second design's speed is its own, not the first's."""
    first = step_inputs(REFERENCE_DESIGN)
    second = step_inputs({**REFERENCE_DESIGN, "power_spring_rate": 75000.0})
    w1 = closed_form_cycle(first).release_speed
    w2 = closed_form_cycle(second).release_speed
    assert round(w1, 2) == 243.96
    assert w2 == closed_form_cycle({**REFERENCE_DESIGN, "power_spring_rate": 75000.0}).release_speed
    assert w2 > w1 * 1.1


def test_the_inputs_say_whether_they_are_arrays_on_the_first_read() -> None:
    """step_inputs looks at its values' classes when ``many`` is first read: arrays anywhere
    make it True, numbers alone False, and the answer is kept."""
    from engine.procedures.striker_cycle import step_inputs

    one = step_inputs(dict(REFERENCE_DESIGN))
    assert one.many is False and one.many is False  # type: ignore[attr-defined]
    many = step_inputs({**REFERENCE_DESIGN, "roller_mass": np.array([0.04, 0.05])})
    assert many.many is True  # type: ignore[attr-defined]


def test_a_release_speed_that_does_not_snap_is_the_array_paths() -> None:
    """One design's quasi-static release speed (no snap: where's other side left out) equals
    the array path's at that point, and a snapping design's too."""
    from engine.procedures.striker_cycle import release_speed_of

    for lam1 in (0.002, 0.09):  # 0.09: snaps at lift-off (snaps_at_liftoff's doctest)
        x = {**REFERENCE_DESIGN, "power_spring_preload": lam1, "roller_geometry": "symmetric_v"}
        arrays = {**x, "power_spring_preload": np.array([lam1, lam1])}
        assert release_speed_of(x) == float(release_speed_of(arrays)[0])
