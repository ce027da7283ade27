"""The plain reader (``service.schemas.plain_reader``, issue 21) reads a single-evaluation
body without pydantic. It may decline any body (the request model then validates it), but a
body it reads must be one the request model accepts, read to the same values: the same
inputs after the engine fills its defaults, the same fidelity, tolerance, outputs and
series flag. And it must read the plain bodies clients send (every model's examples, with
unit strings), or it saves nothing.
"""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pydantic import BaseModel, ValidationError

import engine
from engine.models import MODELS
from service import schemas

SPECS = [s for s in MODELS if s.examples]
#: Each model's request model, built once for the module (a build is some 25 ms of pydantic's
#: work, and the examples' test reads every example three ways).
_REQUEST_MODELS: dict[str, type[BaseModel]] = {}


def _request_model(spec: engine.ModelSpec) -> type[BaseModel]:
    if spec.name not in _REQUEST_MODELS:
        _REQUEST_MODELS[spec.name] = schemas.request_model(spec)
    return _REQUEST_MODELS[spec.name]


def _same_reading(spec: engine.ModelSpec, data: dict[str, Any]) -> schemas.Body | None:
    """The plain reading of ``data``, asserted equal to the request model's when there is one."""
    plain = schemas.plain_reader(spec)(data)
    if plain is None:
        return None
    try:
        model = _request_model(spec).model_validate(data, from_attributes=True)
    except ValidationError as exc:  # pragma: no cover - the failure this test looks for
        pytest.fail(f"the plain reader read a body the request model refuses: {exc}")
    full = schemas.body_of(model)
    assert (plain.fidelity, plain.tolerance, plain.outputs, plain.series) == (
        full.fidelity,
        full.tolerance,
        full.outputs,
        full.series,
    )
    for name, value in plain.inputs.items():  # the given inputs, converted alike
        assert full.inputs[name] == value and type(full.inputs[name]) is type(value), name
    try:
        ours = spec.validate(plain.inputs)
    except engine.EngineError:
        with pytest.raises(engine.EngineError):
            spec.validate(full.inputs)
        return plain
    assert ours == spec.validate(full.inputs)  # and the same once the defaults are in
    return plain


@pytest.mark.parametrize("spec", SPECS, ids=[s.name for s in SPECS])
def test_the_examples_are_read_plainly(spec: engine.ModelSpec) -> None:
    for example in spec.examples:
        for extra in ({}, {"fidelity": spec.rung_names[0]}, {"tolerance": 0.05, "series": True}):
            assert _same_reading(spec, {**example, **extra}) is not None, (example, extra)


def test_unit_strings_and_ints_are_read_plainly() -> None:
    spec = next(s for s in SPECS if s.name == "preload.control")
    body = _same_reading(spec, {"thread": "M12", "required_clamp_force": "20 kN"})
    assert body is not None and body.inputs["required_clamp_force"] == 20_000.0
    assert type(body.inputs["required_clamp_force"]) is float
    count = next(p for s in SPECS for p in s.inputs if p.kind == "int")
    owner = next(s for s in SPECS if count in s.inputs)
    value = int(count.minimum or 0) + 1
    read = _same_reading(owner, {**owner.examples[0], count.name: float(value)})
    assert read is not None and read.inputs[count.name] == value
    assert type(read.inputs[count.name]) is int


@pytest.mark.parametrize(
    "data",
    [
        [0.1],
        "x",
        {"unknown_input": 1.0},
        {"fidelity": "warp"},
        {"tolerance": "0.01"},
        {"tolerance": 0},
        {"tolerance": True},
        {"outputs": "energy"},
        {"outputs": ["no_such_output"]},
        {"series": 1},
        {"series": "true"},
    ],
    ids=repr,
)
def test_what_is_not_plain_is_left_to_the_request_model(data: Any) -> None:
    spec = SPECS[0]
    body = {**spec.examples[0], **data} if isinstance(data, dict) else data
    assert schemas.plain_reader(spec)(body) is None


_ODD = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(10**20), max_value=10**20),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(["45 mm", "1450 rpm", "0.5", "20 kN", "M12", "8.8", "abc", "", " 3 ", "1e400"]),
    st.lists(st.integers(), max_size=2),
)


@st.composite
def _bodies(draw: Any) -> tuple[engine.ModelSpec, dict[str, Any]]:
    spec = draw(st.sampled_from(SPECS))
    data = dict(draw(st.sampled_from(spec.examples)))
    names = [p.name for p in spec.inputs]
    for _ in range(draw(st.integers(0, 4))):
        name = draw(st.sampled_from([*names, "fidelity", "tolerance", "outputs", "series", "x"]))
        if draw(st.booleans()) and name in data:
            del data[name]
            continue
        p = spec.param(name) if name in names else None
        choices = list(p.choices) if p is not None and p.choices else []
        if p is not None and p.is_numeric:
            nearby = [data.get(name) or p.default or 1.0]
            choices += [v * f for v in nearby if isinstance(v, int | float) for f in (0.5, 2, -1)]
        if name == "fidelity":
            choices += ["auto", *spec.rung_names]
        if name == "outputs":
            choices += [[o.name for o in spec.outputs[:2]], []]
        data[name] = draw(st.one_of(st.sampled_from(choices), _ODD) if choices else _ODD)
    return spec, data


@settings(max_examples=600, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_bodies())
def test_a_body_read_plainly_reads_as_the_request_model_reads_it(case: Any) -> None:
    spec, data = case
    _same_reading(spec, data)
