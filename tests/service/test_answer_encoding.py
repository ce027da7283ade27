"""A single evaluation's answer is encoded with orjson straight from the engine's result
(issue 21), and says exactly what the route's published response model said when FastAPI
validated and serialised it: the same keys, the same values, the same JSON types (an int
output stays an int), for every model, example, rung and output, series included.

The lean body reading (``service.api._validated``) is held to FastAPI's own answers by
tests/service/test_hostile.py and test_service_contract.py (statuses, ``type``, ``loc``).
"""

from __future__ import annotations

import json
from typing import Any

import pytest

import engine
from engine.models import MODELS
from service import schemas
from service.api import WrongKind, _coerce, _encoder, _response

CASES = [
    (spec, i, rung)
    for spec in MODELS
    for i in range(len(spec.examples))
    for rung in spec.rung_names
]


def _typed(value: Any) -> Any:
    """``value`` with each number tagged by its JSON type (1 and 1.0 differ)."""
    if isinstance(value, dict):
        return {k: _typed(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_typed(v) for v in value]
    return (type(value).__name__, value)


def _both(spec: engine.ModelSpec, result: engine.RunResult) -> tuple[Any, Any]:
    """(ours, the response model's) for one result, each parsed back from its JSON."""
    model = schemas.response_model(spec)
    theirs = model.model_validate(_response(result, 10**6)).model_dump_json(exclude_unset=True)
    ours = _encoder(spec)(_response(result, 10**6))
    return json.loads(ours), json.loads(theirs)


@pytest.mark.parametrize(
    "spec, example, rung", CASES, ids=[f"{s.name}-{i}-{r}" for s, i, r in CASES]
)
def test_answer_equals_the_response_models_encoding(
    spec: engine.ModelSpec, example: int, rung: str
) -> None:
    try:
        result = engine.run(spec, spec.examples[example], fidelity=rung, series=True)
    except engine.EngineError:
        pytest.skip("the rung refuses this example")
    ours, theirs = _both(spec, result)
    assert _typed(ours) == _typed(theirs)
    assert set(ours["results"]) == set(result.results)
    assert ours["series"].keys() == result.series.keys()


def test_named_outputs_only() -> None:
    spec = next(s for s in MODELS if s.name == "nutrunner.drive")
    names = [o.name for o in spec.outputs if not o.series][:2]
    result = engine.run(spec, spec.examples[0], outputs=names)
    ours, theirs = _both(spec, result)
    assert _typed(ours) == _typed(theirs)
    assert list(ours["results"]) == names and ours["series"] == {}


def test_kinds_are_coerced_as_the_response_model_did() -> None:
    """An int output computed as 3.0 is sent as 3; a float output computed as 3 as 3.0; a
    flag computed as 1 as true; None stays null; what the response model refused is refused
    (a 500: tests/service/test_no_500.py), never truncated or sent. Stricter than its lax
    mode in two ways, both model bugs: a flag where a number is declared (True → 1.0), a
    float where a flag is (1.0 → true)."""
    spec = next(s for s in MODELS if any(o.kind == "int" for o in s.outputs))
    int_out = next(o.name for o in spec.outputs if o.kind == "int" and not o.series)
    float_out = next(o.name for o in spec.outputs if o.kind == "float" and not o.series)
    result = engine.RunResult(
        model=spec.name,
        results={int_out: 3.0, float_out: 3},
        units={int_out: "1", float_out: "1"},
        rung=spec.rung_names[0],
        error_estimate=None,
        elapsed_s=1e-4,
        inputs={"x": 1.5, "label": "M12"},
        checks=[engine.Check("a", True, "fine")],
    )
    ours, theirs = _both(spec, result)
    assert _typed(ours) == _typed(theirs)
    assert _typed(ours["results"]) == {int_out: ("int", 3), float_out: ("float", 3.0)}
    assert ours["checks"] == [
        {
            "name": "a",
            "ok": True,
            "detail": "fine",
            "level": "requirement",
            "detail_parts": ["fine"],
        }
    ]
    assert ours["error_estimate"] is None
    assert _coerce("bool", 1) is True and _coerce("bool", 0) is False
    for kind, wrong in [("int", 2.5), ("bool", 2), ("float", "lots"), ("str", 1.0),
                        ("float", True), ("int", [1]), ("bool", 1.0)]:  # fmt: skip
        with pytest.raises(WrongKind):
            _coerce(kind, wrong)
