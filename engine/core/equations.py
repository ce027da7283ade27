"""The equations a model uses, read from the docstrings of the engine functions it calls.

Every engine function documents its equation in a ``.. math::`` block (the
fluids docstring style). :func:`equations_of` starts at a model's compute
function, follows the engine functions it calls (directly or through an
imported engine module, ``th.stress_area``), depth first in the order they
are named, to any depth and with no cap, and returns each function's summary
line, its LaTeX and its source citation, so the form's calculation report can
print every equation of the procedure, in the order the procedure names its
steps, rather than a list typed by hand that could drift.
"""

from __future__ import annotations

import inspect
import re
import types
from collections.abc import Callable, Sequence
from functools import lru_cache
from typing import Any

_MATH = re.compile(
    r"^(?P<indent>[ \t]*)\.\. math::[ \t]*\n(?P<body>(?:(?:(?P=indent)[ \t]+.*)?\n)+)", re.M
)
_CITE = re.compile(r"\[\d{3}(?:, [^\]\n]*)?\]|(?:VDI|ISO|EN|DIN) \d[\d\-:]*(?: step R\d+)?")


def _blocks(doc: str) -> list[str]:
    """The LaTeX of every ``.. math::`` block in a docstring, lines joined."""
    out = []
    for m in _MATH.finditer(inspect.cleandoc(doc) + "\n"):
        lines = [ln.strip() for ln in m.group("body").splitlines() if ln.strip()]
        if lines:
            out.append(" ".join(lines))
    return out


def _names(code: types.CodeType) -> list[str]:
    names = list(code.co_names)
    for const in code.co_consts:
        if isinstance(const, types.CodeType):
            names += _names(const)
    return list(dict.fromkeys(names))


def _callees(fn: Callable[..., Any]) -> list[Callable[..., Any]]:
    """Engine functions ``fn`` names: globals, and attributes of imported engine modules."""
    code = getattr(fn, "__code__", None)
    if code is None:
        return []
    glb = getattr(fn, "__globals__", {})
    names = _names(code)
    found: list[Callable[..., Any]] = []
    for n in names:
        obj = glb.get(n)
        if isinstance(obj, types.ModuleType) and obj.__name__.startswith("engine."):
            found += [getattr(obj, a) for a in names if inspect.isfunction(getattr(obj, a, None))]
        elif inspect.isfunction(obj) and obj.__module__.startswith("engine."):
            found.append(obj)
    return found


@lru_cache(maxsize=64)
def equations_of(fn: Callable[..., Any]) -> tuple[dict[str, Any], ...]:
    """``({"function", "module", "summary", "latex": [...], "source"}, ...)`` for ``fn`` and
    every engine function it calls, directly or not.

    Each function once, in the order first reached depth first (a step's own
    equations before the next step's); functions whose docstring has no
    ``.. math::`` block (drivers, helpers) are followed but not listed.

    >>> from engine.physics import preload
    >>> eqs = equations_of(preload.thread_torque)
    >>> [e["function"] for e in eqs]
    ['thread_torque', 'lead_angle', 'thread_friction_angle']
    >>> eqs[1]["latex"], eqs[1]["source"]
    (['\\\\psi = \\\\arctan\\\\frac{P}{\\\\pi d_2}'], '[004, eq. 10]')
    """
    seen: set[Callable[..., Any]] = set()
    out: list[dict[str, Any]] = []

    def visit(f: Callable[..., Any]) -> None:
        if f in seen:
            return
        seen.add(f)
        doc = inspect.getdoc(f) or ""
        latex = _blocks(doc)
        if latex:
            summary = doc.strip().split("\n\n")[0].replace("\n", " ")
            cites = list(dict.fromkeys(c.strip() for c in _CITE.findall(doc)))
            # a bare "[004]" says less than "[004, eq. 10]" beside it
            cites = [
                c for c in cites if not any(o != c and o.startswith(c[:-1] + ",") for o in cites)
            ]
            out.append(
                {
                    "function": f.__name__,
                    "module": f.__module__,
                    "summary": summary,
                    "latex": latex,
                    "source": ", ".join(cites[:3]),
                }
            )
        for g in _callees(f):
            visit(g)

    visit(fn)
    return tuple(out)


def equations_of_steps(steps: Sequence[Callable[..., Any]]) -> tuple[dict[str, Any], ...]:
    """:func:`equations_of` of each step in turn, each function once: the equations of a
    procedure declared as its ordered steps (:attr:`engine.core.spec.Rung.steps`).

    >>> from engine.physics import preload
    >>> eqs = equations_of_steps([preload.lead_angle, preload.thread_torque])
    >>> [e["function"] for e in eqs]
    ['lead_angle', 'thread_torque', 'thread_friction_angle']
    """
    seen: set[tuple[str, str]] = set()
    out: list[dict[str, Any]] = []
    for step in steps:
        for e in equations_of(step):
            key = (e["module"], e["function"])
            if key not in seen:
                seen.add(key)
                out.append(e)
    return tuple(out)
