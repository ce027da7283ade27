"""What the benchmarks and the stability suite both need to know about any model.

Everything here reads only the :class:`engine.ModelSpec` contract (inputs with
ranges and kinds, rungs cheapest first with ``estimate``, examples, outputs),
so it works for every model in :data:`engine.MODELS` without knowing its physics.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from engine import ModelSpec, Param, Rung

#: How far inside an exclusive bound (or a bound of 0) the "extreme" values sit,
#: relative to the bound (or to the other end of the range when the bound is 0).
NUDGE = 1e-9


def applicable_rungs(spec: ModelSpec, inputs: Mapping[str, Any]) -> list[tuple[Rung, float]]:
    """The rungs whose a-priori estimate applies to ``inputs``, cheapest first.

    ``inputs`` may be partial (defaults fill the rest); it must be valid.
    """
    values, _ = spec.validate(inputs)
    found = []
    for rung in spec.rungs:
        estimate = rung.estimate(values)
        if estimate is not None and math.isfinite(estimate):
            found.append((rung, float(estimate)))
    return found


def reference_rung(spec: ModelSpec, inputs: Mapping[str, Any]) -> tuple[Rung, float] | None:
    """The most accurate applicable rung (smallest estimate; the later one on a tie)."""
    rungs = applicable_rungs(spec, inputs)
    if not rungs:
        return None
    best = min(estimate for _, estimate in rungs)
    return [item for item in rungs if item[1] == best][-1]


def float_outputs(spec: ModelSpec) -> tuple[str, ...]:
    """Names of the scalar float outputs (the ones an error can be measured on)."""
    return tuple(o.name for o in spec.outputs if o.kind == "float" and not o.series)


def relative_errors(
    spec: ModelSpec, values: Mapping[str, Any], reference: Mapping[str, Any]
) -> dict[str, float]:
    """|a − b| / |b| for each scalar float output both results carry as finite numbers.

    Outputs where the reference is exactly 0 count as 0 when the value is 0 too
    and are skipped otherwise (a relative error has no meaning there).
    """
    errors: dict[str, float] = {}
    for name in float_outputs(spec):
        raw_a, raw_b = values.get(name), reference.get(name)
        if not (_is_number(raw_a) and _is_number(raw_b)):
            continue
        a, b = float(raw_a), float(raw_b)  # type: ignore[arg-type]
        if not (math.isfinite(a) and math.isfinite(b)):
            continue
        if b == 0.0:
            if a == 0.0:
                errors[name] = 0.0
            continue
        errors[name] = abs(a - b) / abs(b)
    return errors


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def extremes(param: Param, example: Any = None) -> tuple[float, float] | None:
    """The smallest and largest values ``param`` accepts (exclusive bounds nudged inside).

    A side without a bound is taken as 10³ times the example (or 10³) away.
    None for non-numeric inputs.
    """
    if not param.is_numeric:
        return None
    scale = abs(float(example)) if _is_number(example) and example else 1.0
    lo = param.minimum if param.minimum is not None else -1e3 * scale
    hi = param.maximum if param.maximum is not None else 1e3 * scale
    if param.kind == "int":
        lo_i = math.ceil(lo) + (1 if param.exclusive_minimum and float(lo).is_integer() else 0)
        hi_i = math.floor(hi) - (1 if param.exclusive_maximum and float(hi).is_integer() else 0)
        return float(lo_i), float(hi_i)
    if param.exclusive_minimum:
        lo = _inside(lo, hi)
    if param.exclusive_maximum:
        hi = _inside(hi, lo)
    return float(lo), float(hi)


def _inside(bound: float, other: float) -> float:
    """A value just inside ``bound`` towards ``other``: relatively close, never equal."""
    step = NUDGE * (abs(bound) if bound != 0.0 else abs(other - bound))
    moved = bound + math.copysign(max(step, 5e-324), other - bound)
    if moved == bound:
        moved = math.nextafter(bound, other)
    return moved


def as_kind(param: Param, value: float) -> float | int:
    """``value`` as the param's kind (ints rounded)."""
    return round(value) if param.kind == "int" else float(value)


def complete_example(spec: ModelSpec, index: int = 0) -> dict[str, Any]:
    """Example ``index`` with every input written out as the runner passes it to compute.

    Optional inputs that were not given are None, as :meth:`ModelSpec.validate` leaves them.
    """
    values, _ = spec.validate(spec.examples[index])
    return values
