"""Pydantic request and response models, generated from each model's spec.

Nothing here knows any physics: field names, units, defaults, ranges and
descriptions all come from :class:`engine.ModelSpec`, so the OpenAPI schema
cannot drift from what the engine enforces. Ranges are checked by the same
:meth:`engine.Param.check` the engine uses.

Every model made here is built on first use (:data:`DEFERRED`): the service declares
some hundred of them when it starts, and most are only ever read by ``/openapi.json``
or by a body that is not plain (:func:`plain_reader`).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    WithJsonSchema,
    create_model,
)
from pydantic.warnings import UnsupportedFieldAttributeWarning
from pydantic_core import PydanticCustomError

from engine import InputOutOfRange, ModelSpec, Param
from engine.core.spec import MAX_TEXT_LENGTH

from .units import (
    MAX_UNIT_STRING,
    TEMPERATURE_CHANGE_UNITS,
    UnitError,
    is_temperature_change,
    to_si,
)

SIValue = float | int | bool | str | list[float] | None

#: The configuration of every model made here: pydantic builds its validator, serialiser
#: and JSON schema on first use, not when the class is made (two thirds of the cost of
#: making the service's request, response and sweep models, measured at start-up).
DEFERRED = ConfigDict(defer_build=True)

# FastAPI makes each route's body field from ``Annotated[model, Field(alias="body")]`` and
# drops pydantic's warning that the alias does nothing there, around the build; a model
# built on first use builds that field later, outside FastAPI's guard (when /openapi.json
# is first made): the same warning, dropped the same way.
warnings.filterwarnings(
    "ignore",
    message="The 'alias' attribute with value 'body'",
    category=UnsupportedFieldAttributeWarning,
)


class QuantityOut(BaseModel):
    """A number in a check's or a note's sentence, as data: the form writes it in the
    unit system the user chose."""

    model_config = DEFERRED

    value: float | None = Field(description="SI value (null: not finite)")
    unit: str = Field(description="SI unit, as the model's outputs write units")
    display_unit: str = Field(description="the unit the plain sentence writes it in")
    digits: int = Field(description="significant digits the plain sentence shows")
    text: str = Field(description="the quantity as the plain sentence writes it")
    bare: bool = Field(
        default=False, description="the text is the number alone (a range's first value)"
    )


#: A sentence as parts: texts, and quantities where it has numbers; joined, the texts
#: and the quantities' ``text`` are the plain sentence.
SentenceParts = list[str | QuantityOut]


class CheckOut(BaseModel):
    model_config = DEFERRED
    name: str
    ok: bool
    detail: str
    #: "requirement": a standard's condition (a failure fails the design); "advice": a rule
    #: of thumb or a recommendation (a failure warns).
    level: Literal["requirement", "advice"] = "requirement"
    detail_parts: SentenceParts = Field(
        default_factory=list, description="detail as texts and quantities (SI values)"
    )


class ErrorItem(BaseModel):
    model_config = DEFERRED
    type: str
    loc: list[str | int]
    msg: str
    field: str | None = None
    ctx: dict[str, Any] | None = None


class ErrorResponse(BaseModel):
    model_config = DEFERRED
    detail: list[ErrorItem]


class LazyJsonSchema:
    """:class:`pydantic.WithJsonSchema` whose schema is made by ``make`` when a JSON schema
    is first asked for (``/openapi.json``), not when the annotated model is declared.

    >>> from pydantic import TypeAdapter
    >>> made = []
    >>> lazy = LazyJsonSchema(lambda: made.append(1) or {"title": "Base", "type": "object"})
    >>> adapter = TypeAdapter(Annotated[dict[str, float], lazy])
    >>> made
    []
    >>> adapter.json_schema()
    {'title': 'Base', 'type': 'object'}
    >>> adapter.json_schema() == adapter.json_schema(), made
    (True, [1])
    """

    def __init__(self, make: Callable[[], dict[str, Any]]) -> None:
        self._make = make
        self._schema: dict[str, Any] | None = None

    def __get_pydantic_json_schema__(self, core_schema: Any, handler: Any) -> dict[str, Any]:
        if self._schema is None:
            self._schema = self._make()
        return self._schema.copy()  # as WithJsonSchema gives its schema


def _literal(values: tuple[str, ...]) -> Any:
    """``Literal[values]`` built at run time (the values come from a spec)."""
    return Literal.__getitem__(values)


def _list_of(item: Any) -> Any:
    return list.__class_getitem__(item)


def _number_schema(p: Param) -> dict[str, Any]:
    schema: dict[str, Any] = {"type": "integer" if p.kind == "int" else "number"}
    if p.minimum is not None:
        schema["exclusiveMinimum" if p.exclusive_minimum else "minimum"] = p.minimum
    if p.maximum is not None:
        schema["exclusiveMaximum" if p.exclusive_maximum else "maximum"] = p.maximum
    return schema


def _field_schema(p: Param) -> dict[str, Any]:
    unit = "dimensionless" if p.unit == "1" else p.unit
    schema: dict[str, Any] = {
        "title": p.label or p.name.replace("_", " "),
        "description": f"{p.description} [{unit}; {p.range_text()}]",
        "anyOf": [
            _number_schema(p),
            {
                "type": "string",
                "maxLength": MAX_UNIT_STRING,
                "description": (
                    f"a temperature change with a unit: {TEMPERATURE_CHANGE_UNITS}, e.g. '3 K'"
                    if is_temperature_change(p)
                    else "a number with a unit, e.g. '45 mm'"
                ),
            },
        ],
        "x-unit": p.unit,
    }
    if not p.required:
        schema["anyOf"].append({"type": "null"})
    if p.default is not None:
        schema["default"] = p.default
    if p.recommended:
        schema["x-recommended"] = list(p.recommended)
    return schema


def _numeric_validator(p: Param) -> Callable[[Any], Any]:
    difference = is_temperature_change(p)

    def validate(value: Any) -> Any:
        if value is None and not p.required:
            return None
        if isinstance(value, str):
            try:
                value = to_si(value, p.unit, difference=difference)
            except UnitError as exc:
                raise PydanticCustomError(
                    "unit_error", "{field}: {reason}", {"field": p.name, "reason": str(exc)}
                ) from None
        elif isinstance(value, bool) or not isinstance(value, int | float):
            raise PydanticCustomError(
                "number_type",
                "{field} must be a number in {unit} or a string with a unit",
                {"field": p.name, "unit": p.unit},
            )
        try:
            return p.check(value)
        except InputOutOfRange as exc:
            raise PydanticCustomError(
                "out_of_range", "{msg}", {"msg": exc.message, **_range_ctx(p)}
            ) from None

    return validate


def _range_ctx(p: Param) -> dict[str, Any]:
    return {
        "minimum": p.minimum,
        "maximum": p.maximum,
        "exclusive_minimum": p.exclusive_minimum,
        "exclusive_maximum": p.exclusive_maximum,
        "unit": p.unit,
    }


def _field(p: Param, *, all_optional: bool = False) -> tuple[Any, Any]:
    """The (type, FieldInfo) pair for one input."""
    description = p.description
    if p.kind == "choice":
        annotation: Any = _literal(p.choices)
        default = p.default
        return (
            annotation if p.required and not all_optional else annotation | None,
            Field(
                default=... if p.required and not all_optional else default, description=description
            ),
        )
    if p.kind == "bool":
        return (
            bool | None,
            Field(default=p.default, description=description, strict=True),
        )
    if p.kind == "text":
        return _text_field(p, required=p.required and not all_optional)
    if p.kind == "samples":
        return _samples_field(p, required=p.required and not all_optional)
    annotated = Annotated[
        Any, BeforeValidator(_numeric_validator(p)), WithJsonSchema(_field_schema(p))
    ]
    required = p.required and not all_optional
    return annotated, Field(default=... if required else p.default, description=description)


def _text_validator(p: Param, *, required: bool) -> Callable[[Any], Any]:
    def validate(value: Any) -> Any:
        if value is None and not required:
            return None
        try:
            return p.check(value)
        except InputOutOfRange as exc:
            raise PydanticCustomError("text_invalid", "{msg}", {"msg": exc.message}) from None

    return validate


def _text_field(p: Param, *, required: bool) -> tuple[Any, Any]:
    """A free-text input (a fastener designation): a string, checked by the engine's Param."""
    validate = _text_validator(p, required=required)
    schema: dict[str, Any] = {
        "title": p.label or p.name.replace("_", " "),
        "description": f"{p.description} [{p.range_text()}]",
        "type": "string",
        "minLength": 1,
        "maxLength": MAX_TEXT_LENGTH,
    }
    if p.choices:
        schema["examples"] = list(p.choices)
    annotated = Annotated[Any, BeforeValidator(validate), WithJsonSchema(schema)]
    return annotated, Field(default=... if required else p.default, description=p.description)


def _samples_validator(p: Param, *, required: bool) -> Callable[[Any], Any]:
    """A list of numbers in SI, or ``{"values": [...], "unit": "lbf*ft"}`` with one unit for
    the whole list; each value checked by the engine's Param (the refusal names the index)."""
    difference = is_temperature_change(p)

    def validate(value: Any) -> Any:
        if value is None and not required:
            return None
        if isinstance(value, dict):
            if set(value) != {"values", "unit"} or not isinstance(value["unit"], str):
                raise PydanticCustomError(
                    "samples_invalid",
                    "{field}: give a list of numbers in {unit}, or an object with exactly "
                    "'values' (the list) and 'unit' (a text such as 'N*m')",
                    {"field": p.name, "unit": p.unit},
                )
            value = _samples_to_si(p, value["values"], value["unit"], difference=difference)
        try:
            return p.check(value)
        except InputOutOfRange as exc:
            raise PydanticCustomError(
                "out_of_range", "{msg}", {"msg": exc.message, **_range_ctx(p), **_index_ctx(exc)}
            ) from None

    return validate


def _index_ctx(exc: InputOutOfRange) -> dict[str, Any]:
    """The index of the refused value of a list (and the list's length limits), for ``ctx``."""
    keys = ("index", "min_length", "max_length")
    return {k: exc.context[k] for k in keys if k in exc.context}


def _samples_to_si(p: Param, values: Any, unit: str, *, difference: bool) -> Any:
    """``values`` given in ``unit``, in SI; anything not a list of numbers is left for
    :meth:`Param.check` to refuse with the index of the first bad value."""
    try:
        offset = to_si(f"0 {unit}", p.unit, difference=difference)
        factor = to_si(f"1 {unit}", p.unit, difference=difference) - offset
    except UnitError as exc:
        raise PydanticCustomError(
            "unit_error", "{field}: {reason}", {"field": p.name, "reason": str(exc)}
        ) from None
    if not isinstance(values, list) or len(values) > p.max_length:
        return values
    return [
        v * factor + offset if isinstance(v, int | float) and not isinstance(v, bool) else v
        for v in values
    ]


def _samples_field(p: Param, *, required: bool) -> tuple[Any, Any]:
    """A list of measured values: SI numbers, or values with one unit for the list."""
    number = _number_schema(p)
    items = {"type": "array", "items": number, "minItems": p.min_length, "maxItems": p.max_length}
    schema: dict[str, Any] = {
        "title": p.label or p.name.replace("_", " "),
        "description": f"{p.description} [{p.unit}; {p.range_text()}]",
        "anyOf": [
            items,
            {
                "type": "object",
                "properties": {
                    "values": items,
                    "unit": {"type": "string", "maxLength": MAX_UNIT_STRING},
                },
                "required": ["values", "unit"],
                "additionalProperties": False,
            },
        ],
        "x-unit": p.unit,
    }
    if not required:
        schema["anyOf"].append({"type": "null"})
    validate = _samples_validator(p, required=required)
    annotated = Annotated[Any, BeforeValidator(validate), WithJsonSchema(schema)]
    return annotated, Field(default=... if required else p.default, description=p.description)


def _class_name(spec: ModelSpec, suffix: str) -> str:
    return "".join(part.capitalize() for part in spec.name.replace("/", ".").split(".")) + suffix


#: A body's configuration: unknown fields are refused; built on first use.
_CLOSED = ConfigDict(extra="forbid", defer_build=True)


def _input_fields(spec: ModelSpec, *, all_optional: bool = False) -> dict[str, Any]:
    return {p.name: _field(p, all_optional=all_optional) for p in spec.inputs}


def inputs_model(spec: ModelSpec, *, all_optional: bool = False) -> type[BaseModel]:
    """A model holding only ``spec``'s inputs (unknown fields are refused)."""
    suffix = "SweepBase" if all_optional else "Inputs"
    return create_model(
        _class_name(spec, suffix),
        __config__=_CLOSED,
        **_input_fields(spec, all_optional=all_optional),
    )


def _fidelity_type(spec: ModelSpec) -> Any:
    return _literal(("auto", *spec.rung_names))


def request_model(spec: ModelSpec) -> type[BaseModel]:
    """The body of ``POST /api/v1<path>``: inputs plus fidelity, tolerance and outputs
    (one class: the fields :func:`inputs_model` holds, then these four)."""
    output_names = _literal(spec.output_names)
    return create_model(
        _class_name(spec, "Request"),
        __config__=_CLOSED,
        **_input_fields(spec),
        fidelity=(
            _fidelity_type(spec) | None,
            Field(
                default=None,
                description="'auto' picks the cheapest rung whose error estimate meets "
                f"`tolerance`; or name a rung. Absent: {spec.default_fidelity!r}, or "
                "'auto' when a tolerance is given",
            ),
        ),
        tolerance=(
            float | None,
            Field(
                default=None,
                gt=0,
                lt=1,
                allow_inf_nan=False,
                description="relative tolerance for 'auto' (0.01)",
            ),
        ),
        outputs=(
            _list_of(output_names) | None,
            Field(
                default=None,
                max_length=len(spec.outputs),
                description="compute only these outputs and series (every scalar output "
                "when absent)",
            ),
        ),
        series=(
            bool,
            Field(
                default=False,
                description="true: compute and send every series too (absent/false: only "
                "the series named in `outputs`)",
            ),
        ),
    )


def results_model(spec: ModelSpec) -> type[BaseModel]:
    """The ``results`` object: each scalar output, present when it was asked for."""
    kinds: dict[str, Any] = {"float": float, "int": int, "bool": bool, "str": str}
    fields: dict[str, Any] = {}
    for o in spec.outputs:
        if o.series:
            continue
        unit = "dimensionless" if o.unit == "1" else o.unit
        fields[o.name] = (
            kinds[o.kind] | None,
            Field(default=None, description=f"{o.description} [{unit}]"),
        )
    return create_model(_class_name(spec, "Results"), __config__=DEFERRED, **fields)


#: What a result's error estimate promises (engine.RunResult.error_kind).
_ERROR_KIND: Any = Literal["bound", "typical"] | None


def response_model(spec: ModelSpec) -> type[BaseModel]:
    return create_model(
        _class_name(spec, "Response"),
        __config__=DEFERRED,
        model=(str, Field(description="model name")),
        results=(results_model(spec), Field(description="requested outputs, SI values")),
        units=(dict[str, str], Field(description="SI unit of each result and series")),
        rung=(str, Field(description="the rung that ran")),
        error_estimate=(
            float | None,
            Field(description="estimated relative error of the results (null: not known)"),
        ),
        error_kind=(
            _ERROR_KIND,
            Field(
                default=None,
                description="what error_estimate promises: 'bound' (no design in the declared "
                "ranges exceeds it, measured: docs/accuracy.md) or 'typical' (some do; a note "
                "says how often); null with no estimate",
            ),
        ),
        elapsed_s=(float, Field(description="compute time, seconds")),
        checks=(list[CheckOut], Field(default_factory=list)),
        notes=(list[str], Field(default_factory=list)),
        notes_parts=(
            list[SentenceParts],
            Field(
                default_factory=list,
                description="each note as texts and quantities (SI values), as notes",
            ),
        ),
        warnings=(list[str], Field(default_factory=list)),
        series=(
            dict[str, list[float]],
            Field(default_factory=dict, description="time series for plots, SI values"),
        ),
        inputs=(
            dict[str, SIValue],
            Field(default_factory=dict, description="every input used, defaults filled, SI"),
        ),
    )


def sweep_request_model(spec: ModelSpec) -> type[BaseModel]:
    numeric = tuple(p.name for p in spec.inputs if p.is_numeric)
    scalar_outputs = tuple(o.name for o in spec.outputs if not o.series)
    base = inputs_model(spec, all_optional=True)
    return create_model(
        _class_name(spec, "SweepRequest"),
        __config__=_CLOSED,
        base=(
            base,
            # a model instance, not a dict: the route calls base.model_dump() (found by fuzzing)
            Field(default_factory=base, description="inputs held fixed (defaults fill the rest)"),
        ),
        vary=(_literal(numeric), Field(description="the input to vary")),
        start=(
            float | str,
            Field(description="first value: SI number or string with a unit"),
        ),
        stop=(float | str, Field(description="last value: SI number or string with a unit")),
        num=(int, Field(default=50, ge=2, le=2000, description="number of points")),
        scale=(_literal(("linear", "log")), Field(default="linear")),
        outputs=(
            _list_of(_literal(scalar_outputs)) | None,
            Field(default=None, max_length=len(scalar_outputs)),
        ),
        fidelity=(
            _fidelity_type(spec) | None,
            Field(
                default=None,
                description=f"as for a single evaluation (absent: {spec.default_fidelity!r}, "
                "or 'auto' when a tolerance is given); auto chooses per point",
            ),
        ),
        tolerance=(float | None, Field(default=None, gt=0, lt=1, allow_inf_nan=False)),
    )


class SweepResponse(BaseModel):
    model_config = DEFERRED
    model: str
    vary: str
    unit: str
    values: list[float]
    results: dict[str, list[SIValue]]
    units: dict[str, str]
    rung: str
    elapsed_s: float
    notes: list[str] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
    rungs: list[str | None] = Field(
        default_factory=list, description="the rung that ran at each point (null: refused)"
    )
    error_estimates: list[float | None] = Field(
        default_factory=list, description="each point's estimated relative error"
    )


@dataclass(frozen=True)
class Body:
    """A validated single-evaluation body: the inputs given (SI, checked; defaults are the
    engine's to fill) and the four common fields."""

    inputs: dict[str, Any]
    fidelity: str | None = None
    tolerance: float | None = None
    outputs: list[str] | None = None
    series: bool = False


_COMMON = ("fidelity", "tolerance", "outputs", "series")


def body_of(model: BaseModel) -> Body:
    """:class:`Body` from a validated :func:`request_model` instance."""
    dumped = model.model_dump(exclude=set(_COMMON))
    return Body(
        inputs={k: v for k, v in dumped.items() if v is not None},
        fidelity=model.fidelity,  # type: ignore[attr-defined]
        tolerance=model.tolerance,  # type: ignore[attr-defined]
        outputs=model.outputs,  # type: ignore[attr-defined]
        series=model.series,  # type: ignore[attr-defined]
    )


def plain_reader(spec: ModelSpec) -> Callable[[Any], Body | None]:
    """The request body's plain case read without pydantic (which costs ~15–25 µs a request).

    Each input goes through the very validator its :func:`request_model` field runs
    (:func:`_numeric_validator`, :func:`_text_validator`, the choice and flag types), so a
    value it accepts is converted exactly as the model converts it. Anything less plain
    (a null, an unknown key, a number where a flag goes, a string for the tolerance, any
    invalid value) gives None, and the request model then validates the body and names
    every error. tests/service/test_plain_reader.py holds the two to the same answers.
    """
    readers: dict[str, Callable[[Any], Any]] = {}
    # a JSON number for a numeric input: its validator would call Param.check on it and
    # nothing else, so it is called straight (~0.2 µs an input)
    numbers: dict[str, Callable[[Any], Any]] = {
        p.name: p.check for p in spec.inputs if p.is_numeric
    }
    for p in spec.inputs:
        if p.kind == "choice":
            readers[p.name] = _choice_reader(p.choices)
        elif p.kind == "bool":
            readers[p.name] = _flag_reader
        elif p.kind == "text":
            readers[p.name] = _text_validator(p, required=p.required)
        elif p.kind == "samples":
            readers[p.name] = _samples_validator(p, required=p.required)
        else:
            readers[p.name] = _numeric_validator(p)
    required = tuple(p.name for p in spec.inputs if p.required)
    fidelities = frozenset(("auto", *spec.rung_names))
    outputs = frozenset(spec.output_names)
    most = len(spec.outputs)

    def read(data: Any) -> Body | None:
        if type(data) is not dict:
            return None
        inputs: dict[str, Any] = {}
        try:
            for name, value in data.items():
                kind = type(value)
                if kind is float or kind is int:
                    check = numbers.get(name)
                    if check is not None:
                        inputs[name] = check(value)
                        continue
                elif value is None:
                    return None
                reader = readers.get(name)
                if reader is not None:
                    inputs[name] = reader(value)
                elif name not in _COMMON:
                    return None
        except (PydanticCustomError, _NotPlain, InputOutOfRange):
            return None
        if any(name not in inputs for name in required):
            return None
        fidelity = data.get("fidelity")
        if fidelity is not None and not (type(fidelity) is str and fidelity in fidelities):
            return None
        tolerance = data.get("tolerance")
        if tolerance is not None:
            if type(tolerance) not in (float, int) or not 0.0 < tolerance < 1.0:
                return None
            tolerance = float(tolerance)
        asked = data.get("outputs")
        if asked is not None and not (
            type(asked) is list
            and len(asked) <= most
            and all(type(o) is str and o in outputs for o in asked)
        ):
            return None
        series = data.get("series", False)
        if type(series) is not bool:
            return None
        return Body(inputs, fidelity, tolerance, asked, series)

    return read


class _NotPlain(Exception):
    """A value the plain reader leaves to pydantic."""


def _flag_reader(value: Any) -> bool:
    if type(value) is not bool:
        raise _NotPlain
    return value


def _choice_reader(choices: tuple[str, ...]) -> Callable[[Any], str]:
    allowed = frozenset(choices)

    def read(value: Any) -> str:
        if type(value) is not str or value not in allowed:
            raise _NotPlain
        return value

    return read
