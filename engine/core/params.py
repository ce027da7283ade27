"""The shared vocabulary of the model declarations.

Param builders for the kinds of input every family has (a length, a friction
coefficient, a count, a positive quantity), one formatter for quantities in
sentences (checks, notes, warnings) and the constants more than one family
uses. A declaration module imports these instead of spelling out the same
``Param(...)`` keywords or f-string scalings again.
"""

from __future__ import annotations

import math
from typing import Any

from .spec import Param
from .text import q, written

#: One degree, [rad].
DEG = math.pi / 180.0
#: One revolution per minute, [rad/s].
RPM = math.pi / 30.0


def quantity(value: float, unit: str, fmt: str = ".3g") -> str:
    """An SI ``value`` written in ``unit`` for a sentence, e.g. ``quantity(0.0042, "mm")``.

    Plain text, for refusals and warnings; a check or a note writes its quantities with
    :func:`engine.core.text.q`, which the form shows in the unit system chosen.

    >>> quantity(0.0042, "mm")
    '4.2 mm'
    >>> quantity(50000.0, "N/mm", ".4g")
    '50 N/mm'
    >>> quantity(157.07963, "rpm", ".0f")
    '1500 rpm'
    >>> quantity(math.radians(45.0), "deg")
    '45°'
    """
    return written(value, unit, fmt)


def length(name: str, description: str, *, minimum: float, maximum: float, **kw: Any) -> Param:
    """A length input, [m], shown in mm on the form."""
    kw.setdefault("display_unit", "mm")
    return Param(name, "m", description, minimum=minimum, maximum=maximum, **kw)


def positive(name: str, unit: str, description: str, *, maximum: float, **kw: Any) -> Param:
    """A quantity that must be strictly positive and at most ``maximum`` (SI ``unit``)."""
    return Param(
        name, unit, description, minimum=0.0, exclusive_minimum=True, maximum=maximum, **kw
    )


def friction_coefficient(name: str, description: str, **kw: Any) -> Param:
    """A Coulomb friction coefficient, dimensionless, 0…1 unless ``maximum`` says otherwise."""
    kw.setdefault("minimum", 0.0)
    kw.setdefault("maximum", 1.0)
    return Param(name, "1", description, **kw)


def count(name: str, description: str, *, minimum: int, maximum: int, **kw: Any) -> Param:
    """A whole number of things (balls, spindles, rollers, bins)."""
    return Param(name, "1", description, kind="int", minimum=minimum, maximum=maximum, **kw)


def samples(name: str, unit: str, description: str, **kw: Any) -> Param:
    """A list of measured values in one SI ``unit`` (2…10,000 of them unless ``min_length``
    and ``max_length`` say otherwise), each checked against ``minimum``/``maximum``."""
    return Param(name, unit, description, kind="samples", **kw)


def in_mm(value: float) -> str:
    """A length [m] in mm, 3 significant digits, for a check or a note (:func:`q`):
    ``plain(in_mm(0.0042))`` is ``'4.2 mm'``."""
    return q(value, "mm")


def in_ms(value: float) -> str:
    """A time [s] in ms, 3 significant digits, for a check or a note."""
    return q(value, "ms")


def in_n_per_mm(value: float) -> str:
    """A spring rate [N/m] in N/mm, 4 significant digits, for a check or a note."""
    return q(value, "N/mm", 4)


def in_rpm(value: float) -> str:
    """An angular speed [rad/s] in whole rpm, for a check or a note."""
    return q(value, "rpm", fmt=".0f")
