"""A sweep's answer is encoded from its numpy columns (issue 21), and says exactly what the
point-by-point list encoding said: the same floats to the last bit, null where a point was
not computed, never NaN or Infinity, and the shape the route publishes (SweepResponse)."""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient

import engine
from engine.core.runner import SweepResult
from engine.models import MODELS
from service.api import _sweep_answer
from service.schemas import SweepResponse
from tests.apps import real_client

POINTS = 41
#: A model without an array rung is swept through the engine's point-by-point loop (some
#: 25 ms a point for impact.rare_design, twice: the route and the engine): the encoding is
#: the same code, shown on fewer points.
LOOP_POINTS = 7


@pytest.fixture(scope="module")
def client() -> TestClient:
    """The session's real app (tests/apps.py), not one more built for this module."""
    return real_client()


def _case(spec: engine.ModelSpec) -> tuple[dict[str, Any], str, float, float] | None:
    """The first example with a float input given, that input swept ±10 % about its value,
    inside its range (a model of measured series may give only lists and a designation in
    its first example)."""
    for example in spec.examples:
        case = _case_of(spec, dict(example))
        if case is not None:
            return case
    return None


def _case_of(
    spec: engine.ModelSpec, base: dict[str, Any]
) -> tuple[dict[str, Any], str, float, float] | None:
    for p in spec.inputs:
        value = base.get(p.name)
        if p.kind != "float" or not isinstance(value, int | float) or not value:
            continue
        lo, hi = sorted((0.9 * value, 1.1 * value))
        if p.minimum is not None:
            lo = max(lo, p.minimum + 1e-9 * max(abs(p.minimum), 1.0))
        if p.maximum is not None:
            hi = min(hi, p.maximum - 1e-9 * max(abs(p.maximum), 1.0))
        if lo < hi:
            return base, p.name, lo, hi
    return None


def _listed(result: SweepResult, unit: str) -> dict[str, Any]:
    """The answer as the list encoding gave it before issue 21's array encoding."""
    return {
        "model": result.model,
        "vary": result.vary,
        "unit": unit,
        "values": result.values,
        "results": result.results,
        "units": result.units,
        "rung": result.rung,
        "notes": result.notes,
        "warnings": result.warnings,
        "rungs": result.rungs,
        "error_estimates": result.error_estimates,
    }


CASES = [(spec, _case(spec)) for spec in MODELS if spec.examples]


def test_whole_range_log_sweep_of_the_ball_clutch(client: TestClient) -> None:
    """The case that found the strided columns (tests/stability/test_grids.py): 500 before."""
    spec = next(s for s in MODELS if s.name == "clutch.ball")
    base = dict(spec.examples[0])
    body = {"base": base, "vary": "ball_diameter", "start": 1e-4, "stop": 0.2, "num": 25}
    r = client.post("/api/v1/clutch/ball/sweep", json={**body, "scale": "log"})
    assert r.status_code == 200, r.text
    expected = engine.sweep(spec, base, "ball_diameter", np.geomspace(1e-4, 0.2, 25))
    assert r.json()["results"] == json.loads(json.dumps(expected.results))


@pytest.mark.parametrize("spec, case", CASES, ids=[s.name for s, _ in CASES])
def test_sweep_answer_equals_the_list_encoding(client: TestClient, spec: Any, case: Any) -> None:
    assert case is not None, f"{spec.name}: no float input to sweep"
    base, vary, lo, hi = case
    rung = spec.vector_rungs[0] if spec.vector_rungs else spec.rung_names[0]
    points = POINTS if spec.vector_rungs else LOOP_POINTS
    r = client.post(
        f"/api/v1{spec.path}/sweep",
        json={"base": base, "vary": vary, "start": lo, "stop": hi, "num": points, "fidelity": rung},
    )
    assert r.status_code == 200, r.text
    assert r.headers["content-type"] == "application/json"
    assert "NaN" not in r.text and "Infinity" not in r.text
    answer = r.json()
    SweepResponse.model_validate(answer)  # the published shape
    expected = engine.sweep(spec, base, vary, np.linspace(lo, hi, points), fidelity=rung)
    elapsed = answer.pop("elapsed_s")
    assert isinstance(elapsed, float) and elapsed > 0
    want = json.loads(json.dumps(_listed(expected, spec.param(vary).unit)))
    assert answer == want  # float == float: the same doubles, bit for bit
    assert len(answer["values"]) == points
    assert all(len(col) == points for col in answer["results"].values())


def test_non_finite_and_mixed_columns() -> None:
    """NaN and ±inf become null; texts, flags, ints and float32 keep the list encoding's values."""
    columns = {
        "force": np.array([1.5, np.nan, np.inf, -np.inf, 0.1 + 0.2]),
        "label": np.array(["M12 8.8", None, "M16", None, "x"], dtype=object),
        "ok": np.array([True, False, True, False, True]),
        "count": np.array([1, 2, 3, 4, 5]),
        "single": np.array([0.1, 0.2, 0.3, 0.4, 0.5], dtype=np.float32),
        # a strided view (a column taken from a 2-D array): orjson takes C-contiguous only
        "strided": np.arange(10.0).reshape(5, 2)[:, 1],
        "strided_int": np.arange(10).reshape(5, 2)[:, 0],
        "numpy_objects": np.array([np.float64(1.5), np.bool_(True), None, "a", 2], dtype=object),
    }
    result = SweepResult(
        model="m",
        vary="d",
        value_array=np.linspace(0.01, 0.02, 5),
        columns=columns,
        units={k: "1" for k in columns},
        rung="closed_form",
        elapsed_s=1e-3,
        rung_codes=np.array([0, -1, 0, 0, 1], dtype=np.int8),
        rung_names=("closed_form", "a"),
        error_array=np.array([1e-3, np.nan, 0.0, 2e-3, np.inf]),
    )
    raw = _sweep_answer(result, "m").body
    answer = json.loads(raw)
    assert b"NaN" not in raw and b"Infinity" not in raw
    assert answer["results"]["force"] == [1.5, None, None, None, 0.30000000000000004]
    assert answer["results"]["label"] == ["M12 8.8", None, "M16", None, "x"]
    assert answer["results"]["ok"] == [True, False, True, False, True]
    assert answer["results"]["count"] == [1, 2, 3, 4, 5]
    # float32 as the list encoding gave it: the float32 value widened, not its short repr
    assert answer["results"]["single"] == [float(v) for v in columns["single"]]
    assert answer["results"]["single"][0] != 0.1
    assert answer["results"]["strided"] == [1.0, 3.0, 5.0, 7.0, 9.0]
    assert answer["results"]["strided_int"] == [0, 2, 4, 6, 8]
    assert answer["results"]["numpy_objects"] == [1.5, True, None, "a", 2]
    assert answer["error_estimates"] == [1e-3, None, 0.0, 2e-3, None]
    assert answer["rungs"] == ["closed_form", None, "closed_form", "closed_form", "a"]
    assert answer["values"] == np.linspace(0.01, 0.02, 5).tolist()
    for key, col in answer["results"].items():
        if key != "numpy_objects":  # json.dumps cannot take numpy scalars
            assert col == json.loads(json.dumps(result.results[key])), key
    assert all(v is None or not isinstance(v, float) or math.isfinite(v) for v in answer["values"])
    SweepResponse.model_validate(answer)
