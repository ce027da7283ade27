"""Property tests over decades of every input: never NaN, never inf, never a 500."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine import EngineError, run
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE

SPEC = NUTRUNNER_DRIVE


def _decades(lo: float, hi: float) -> st.SearchStrategy[float]:
    """Log-uniform floats in [lo, hi]."""
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0**e)


LENGTH = _decades(1e-3, 1.0)  # 1 mm … 1 m
MASS = _decades(0.1, 100.0)  # 0.1 … 100 kg

DESIGN = st.fixed_dictionaries(
    {
        "motor_power": _decades(10.0, 1e5),
        "motor_speed": _decades(1.0, 1e3),
        "coupling_mass": MASS,
        "coupling_diameter": LENGTH,
        "motor_pulley_mass": MASS,
        "motor_pulley_diameter": LENGTH,
        "flywheel_mass": MASS,
        "flywheel_diameter": LENGTH,
        "drive_gear_mass": MASS,
        "drive_gear_diameter": LENGTH,
        "spindle_gear_mass": MASS,
        "spindle_gear_diameter": LENGTH,
        "spindle_count": st.integers(1, 32),
        "shaft_diameter": LENGTH,
        "shaft_length": LENGTH,
        "spindle_diameter": LENGTH,
        "spindle_length": LENGTH,
        "idle_spindle_friction_torque": st.one_of(st.just(0.0), _decades(1e-3, 1e4)),
    }
)

CURVE = st.one_of(
    st.fixed_dictionaries(
        {
            "motor_curve": st.just("linear"),
            "stall_torque": _decades(0.01, 1e4),
            "no_load_speed": _decades(1.0, 2e3),
        }
    ),
    st.fixed_dictionaries(
        {
            "motor_curve": st.just("induction"),
            "synchronous_speed": _decades(1.0, 2e3),
            "breakdown_torque": _decades(0.01, 1e5),
            "rotor_inertia": _decades(1e-6, 1.0),
            "belt_efficiency": st.floats(0.5, 1.0),
            "gear_efficiency": st.floats(0.5, 1.0),
        }
    ),
    st.fixed_dictionaries(
        {"motor_curve": st.just("constant_power"), "stall_torque": _decades(0.01, 1e5)}
    ),
)


# Induction motors scaled to the design (most absolute draws are refused as inconsistent):
# synchronous speed 1.0001…3× the working speed, breakdown 1.05…4× the rated torque.
SCALED_INDUCTION = st.tuples(_decades(1.0001, 3.0), _decades(1.05, 4.0), _decades(1e-6, 1.0))


def _scaled(x, ratios):
    sync, overload, rotor = ratios
    return {
        "motor_curve": "induction",
        "synchronous_speed": x["motor_speed"] * sync,
        "breakdown_torque": overload * x["motor_power"] / x["motor_speed"],
        "rotor_inertia": rotor,
    }


def _all_finite(values):
    for name, v in values.items():
        assert v is not None, name
        assert not isinstance(v, float) or math.isfinite(v), name


@settings(max_examples=300, deadline=None)
@given(DESIGN)
def test_closed_forms_finite_everywhere(x):
    for rung in ("closed_form", "gear_ratio"):
        r = run(SPEC, x, fidelity=rung)
        _all_finite(r.results)
        v = r.results
        assert v["max_spindle_torque"] <= v["impact_torque"]
        assert v["impact_torque"] > 0 and v["acceleration_time"] > 0
        # T = ½ J_eq ω² and the twist stores it (energy balance of eq. 7, with u on the shaft)
        stored = (
            0.5 * v["shaft_torque"] * v["shaft_twist"]
            + 0.5 * v["impact_torque"] * (v["spindle_twist"])
        )
        assert stored == pytest.approx(v["kinetic_energy"], rel=1e-9)
        assert (v["max_spindle_torque"] > 0) == all(
            c.ok for c in r.checks if c.name == "max_spindle_torque_positive"
        )


@settings(max_examples=200, deadline=None)
@given(DESIGN, st.one_of(CURVE, SCALED_INDUCTION))
def test_motor_curve_finite_or_a_clear_engine_error(x, curve):
    if isinstance(curve, tuple):
        curve = _scaled(x, curve)
    try:
        r = run(SPEC, {**x, **curve}, fidelity="motor_curve")
    except EngineError as exc:
        assert exc.message and exc.field
        return
    _all_finite(r.results)
    assert r.results["acceleration_time"] > 0
    assert r.error_estimate is not None and r.error_estimate < 1e-6
    assert all(math.isfinite(p) for s in r.series.values() for p in s)
    # auto never crashes either
    run(SPEC, {**x, **curve}, fidelity="auto")


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(
    DESIGN,
    st.one_of(st.none(), CURVE),
    st.sampled_from(["closed_form", "gear_ratio", "motor_curve", "auto"]),
)
def test_http_never_500(api, x, curve, fidelity):
    r = api.post("/api/v1/nutrunner/drive", json={**x, **(curve or {}), "fidelity": fidelity})
    assert r.status_code in (200, 422), r.text
    assert "NaN" not in r.text and "Infinity" not in r.text
    if r.status_code == 422:
        assert r.json()["detail"][0]["msg"]


@pytest.mark.parametrize(
    "name",
    [p.name for p in SPEC.inputs if p.is_numeric and p.maximum is not None],
)
def test_each_input_at_its_hard_limits(name):
    """Every numeric input at its minimum and maximum, the rest the example's."""
    p = SPEC.param(name)
    for value in (p.minimum, p.maximum):
        if value is None:
            continue
        if p.exclusive_minimum and value == p.minimum:
            value = math.nextafter(value, math.inf) if value else 1e-9 * (p.maximum or 1.0)
        if p.kind == "int":
            value = int(value)
        r = run(SPEC, {**EXAMPLE_LIGHT_TRUCK, name: value}, fidelity="gear_ratio")
        _all_finite(r.results)
