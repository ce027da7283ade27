"""A request body is read by orjson where that gives what json.loads gives (service.api._parsed):
the same values, types and bits, the same key order, and json's own errors otherwise."""

from __future__ import annotations

import json
import math
import random
import struct
from typing import Any

import pytest

from service.api import _NESTED, _parsed


def _same(raw: bytes) -> None:
    try:
        expected: Any = ("value", json.loads(raw))
    except Exception as exc:  # the error itself is compared
        expected = ("error", type(exc), str(exc))
    try:
        got: Any = ("value", _parsed(raw))
    except Exception as exc:
        got = ("error", type(exc), str(exc))
    assert _typed(got) == _typed(expected), raw[:200]


def _typed(value: Any) -> list[Any]:
    """The value flattened (no recursion: bodies nest deep), every number with its type and
    bits, every key in order."""
    out: list[Any] = []
    stack = [value]
    while stack:
        v = stack.pop()
        if isinstance(v, dict):
            out.append(("dict", list(v)))
            stack.extend(reversed(list(v.values())))
        elif isinstance(v, list | tuple):
            out.append((type(v).__name__, len(v)))
            stack.extend(reversed(v))
        elif type(v) is float:
            out.append(("float", "nan" if math.isnan(v) else struct.pack("<d", v)))
        else:
            out.append((type(v).__name__, v))
    return out


EDGES = [
    b'{"a":1,"b":2,"a":3}',
    b"-0",
    b"[-0.0, 0.0, -0]",
    b" \t\n\r1 ",
    b"\x0c1",
    b'"\\u00e9\\ud83d\\ude00"',
    '{"é": "ü"}'.encode(),
    b"[1e5, 1E-5, 0.1e1, 1.0]",
    b'"\\/"',
    b"1 2",
    b"[]]",
    b"[1,]",
    b"",
    b"\xef\xbb\xbf{}",  # a byte order mark
    '{"a": 1}'.encode("utf-16"),
    b'"\xed\xa0\x80"',  # a surrogate encoded in UTF-8: json lets it pass
    b'"\\ud800"',  # a lone surrogate escaped
    b"NaN",
    b"[Infinity, -Infinity]",
    b"1e400",
    b"-1e400",
    b"123456789012345678",
    b"1234567890123456789",
    b"9223372036854775807",
    b"9223372036854775808",
    b"18446744073709551615",
    b"18446744073709551616",
    b"-9223372036854775809",
    b"[0.1234567890123456789012]",
    b"1" * 4301,
    b"1.7976931348623157e308",
    b"4.9e-324",
    b"2.4703282292062328e-324",
    b"2.4703282292062327e-324",
    b'{"torque": 20.5, "fidelity": "closed_form", "outputs": ["a"], "series": true}',
    b'{"samples": {"values": [1, 2.5, -3e-3], "unit": "N*m"}, "x": null}',
]


@pytest.mark.parametrize("raw", EDGES, ids=range(len(EDGES)))
def test_edges(raw: bytes) -> None:
    _same(raw)


def test_nesting() -> None:
    for depth in (10, _NESTED - 1, _NESTED, 900, 1000, 1023, 1024, 1100, 5000):
        _same(b"[" * depth + b"]" * depth)
        _same(b'{"a":' * depth + b"1" + b"}" * depth)


def _number(rng: random.Random) -> str:
    k = rng.random()
    if k < 0.3:
        x = struct.unpack("<d", rng.getrandbits(64).to_bytes(8, "little"))[0]
        if not math.isfinite(x):
            x = 1.0
        return rng.choice([repr(x), f"{x:.17g}", f"{x:.15g}", f"{x:.20e}"])
    if k < 0.6:
        whole = "".join(rng.choice("0123456789") for _ in range(rng.randint(1, 25))).lstrip("0")
        frac = "".join(rng.choice("0123456789") for _ in range(rng.randint(0, 25)))
        exp = rng.choice(["", f"e{rng.randint(-330, 310)}", f"E+{rng.randint(0, 30)}"])
        return rng.choice(["", "-"]) + (whole or "0") + (f".{frac}" if frac else "") + exp
    if k < 0.8:  # near a halfway case
        m = rng.randint(10**16, 10**17 - 1)
        return f"{m}5{'0' * rng.randint(0, 20)}1e{rng.randint(-340, 300)}"
    return str(rng.randint(-(2**70), 2**70))


def test_random_numbers() -> None:
    rng = random.Random(20261127)
    for _ in range(20_000):
        _same(("[" + ",".join(_number(rng) for _ in range(4)) + "]").encode())
        _same(('{"x": ' + _number(rng) + ', "fidelity": "auto"}').encode())
