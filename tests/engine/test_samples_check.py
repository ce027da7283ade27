"""A samples list is checked whole where it is all floats (Param._check_samples): the same
tuple, the same refusal and index, as checking each value alone as a number of the range."""

from __future__ import annotations

import math
import random
from dataclasses import replace
from typing import Any

import pytest

from engine import InputOutOfRange, Param

PARAMS = [
    Param("t", "N*m", "torques", kind="samples", minimum=0.0),
    Param("t", "N*m", "torques", kind="samples", minimum=0.0, exclusive_minimum=True),
    Param("t", "N*m", "torques", kind="samples", minimum=-1.0, maximum=2.0),
    Param(
        "t",
        "N*m",
        "torques",
        kind="samples",
        minimum=-1.0,
        maximum=2.0,
        exclusive_minimum=True,
        exclusive_maximum=True,
    ),
    Param("t", "1", "anything finite", kind="samples", min_length=1, max_length=50),
]

SPECIAL: list[Any] = [
    0.0,
    -0.0,
    -1.0,
    2.0,
    1e308,
    -1e308,
    5e-324,
    math.nan,
    math.inf,
    -math.inf,
    1,
    0,
    True,
    "1.0",
    None,
    10**400,
]


def _value_by_value(p: Param, value: list[Any]) -> tuple[str, Any]:
    """The rule: each value checked alone as a number of the range, the first refused named."""
    one = replace(p, kind="float")
    checked = []
    for i, item in enumerate(value):
        try:
            checked.append(one.check(item))
        except InputOutOfRange as exc:
            return "refused", (i, str(p._error(item, index=i)), exc.context)
    return "ok", tuple(checked)


def _outcome(p: Param, value: list[Any]) -> tuple[str, Any]:
    one = replace(p, kind="float")
    try:
        got = p.check(value)
    except InputOutOfRange as exc:
        i = exc.context["index"]
        one_exc = None
        try:
            one.check(value[i])
        except InputOutOfRange as e:
            one_exc = e.context
        return "refused", (i, str(exc), one_exc)
    return "ok", got


def _bits(outcome: tuple[str, Any]) -> Any:
    kind, got = outcome
    if kind == "ok":
        return kind, [(type(v), math.copysign(1.0, v), v) for v in got]
    return kind, got[:2]


@pytest.mark.parametrize("p", PARAMS, ids=range(len(PARAMS)))
def test_whole_list_as_value_by_value(p: Param) -> None:
    rng = random.Random(20261127)
    for _ in range(3000):
        n = rng.randint(p.min_length, 12)
        value: list[Any] = [rng.uniform(-1.5, 2.5) for _ in range(n)]
        for _ in range(rng.randint(0, 3)):
            value[rng.randrange(n)] = rng.choice(SPECIAL)
        assert _bits(_outcome(p, value)) == _bits(_value_by_value(p, value)), value


def test_an_overflowing_sum_is_still_accepted() -> None:
    p = PARAMS[4]
    assert p.check([1e308, 1e308, -0.0]) == (1e308, 1e308, 0.0)
    assert math.copysign(1.0, p.check([1e308, -0.0])[1]) == 1.0


def test_a_tuple_and_negative_zeros() -> None:
    p = PARAMS[0]
    got = p.check((0.5, -0.0, 1.5))
    assert got == (0.5, 0.0, 1.5) and math.copysign(1.0, got[1]) == 1.0
    with pytest.raises(InputOutOfRange) as refused:
        p.check([0.5, 1.0, -2.0, math.nan])
    assert refused.value.context["index"] == 2
