"""Unit strings at the API edge: "45 mm", "1450 rpm", "8e4 MPa", "1.1 kW", "45 deg".

A value arrives either as a number in SI base units or as a string holding a
number and a unit. The string must match a small grammar (a decimal number,
then unit names joined by ``*``, ``/``, ``·`` or spaces, each with an
optional one-digit exponent) before pint sees it; pint then parses only the
unit part, never the number. That keeps pint's expression evaluator, which
would happily compute ``10**10**10`` for minutes, away from user input, and
nothing is ever passed to ``eval``.

A frequency without an angle unit ("50 Hz", "1400 min^-1", "25 1/s") given
for an angular speed is read as a rotational frequency, i.e. revolutions per
unit time (×2π to rad/s), as drive catalogues mean it. Common spellings are
accepted: "Nm", "N.m", "N·m", "kg·m²", "RPM", "rev/min".

A temperature on a scale with an offset ("20 degC", "68 degF", "20 °C") is
converted with its offset where the input is a temperature. Where the input is
a temperature *change* (a param in kelvin that says so, or any width such as a
standard deviation) only kelvin and the difference units ``delta_degC`` and
``delta_degF`` are read: "3 degC" as a change would silently be 276.15 K, so it
is refused with a message naming the units to use.
"""

from __future__ import annotations

import math
import re
import threading
from functools import lru_cache
from pathlib import Path
from typing import Any

from engine import InputOutOfRange, Param

MAX_UNIT_STRING = 64

_NUMBER = r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d{1,3})?"
_ATOM = r"(?:[A-Za-zµμΩ%][A-Za-zµμΩ%_]*|°[CF]?)(?:(?:\^|\*\*)-?\d)?"
_UNIT = rf"{_ATOM}(?:\s*[*/·.]\s*{_ATOM}|\s+{_ATOM})*"
_QUANTITY = re.compile(rf"\s*({_NUMBER})\s*({_UNIT})?\s*")

# Dimensionless inputs (counts, ratios, friction coefficients) accept these only;
# pint treats angles as dimensionless too, and "45 deg" is no friction coefficient.
_DIMENSIONLESS_UNITS = {"%": 0.01, "percent": 0.01, "ppm": 1e-6}

#: pint's cache of its parsed unit definitions (pickles keyed on pint's and Python's versions
#: and the definition files' content), beside the package's bytecode: building the registry
#: from it takes about a quarter of the time of parsing the definitions.
PINT_CACHE = Path(__file__).resolve().parent / "__pycache__" / "pint"


def _unit_registry() -> Any:
    """pint's unit registry, from its definition cache where that can be read or written,
    parsed afresh otherwise (a read-only install, a cache file another process is writing).

    >>> _unit_registry().parse_units("mm")
    <Unit('millimeter')>
    """
    import pint

    try:
        return pint.UnitRegistry(cache_folder=PINT_CACHE)
    except Exception:  # no cache: the same registry, slower
        return pint.UnitRegistry()


_REGISTRY: Any = None
_REGISTRY_LOCK = threading.Lock()


def registry() -> Any:
    """The service's unit registry, built on the first unit string that needs pint.

    pint (0.12 s of CPU to import, and it imports dask whenever dask is installed: 0.08 s
    more) and its registry (0.02 s from the definition cache) are loaded here, not when the
    service starts: a number in SI units, a dimensionless input ("5 %") and a request
    without unit strings never load pint. The start-up warm-up builds it once it has said
    ready, at the first quiet moment (:class:`service.main.WarmUp`), so the form's unit
    strings find it built; without the warm-up the first unit string pays that time, once
    per process. A lock keeps two
    first callers from building two registries.

    >>> registry().parse_units("Nm")
    <Unit('Nm')>
    """
    global _REGISTRY
    if _REGISTRY is None:
        with _REGISTRY_LOCK:
            if _REGISTRY is None:
                units = _unit_registry()
                # spellings workshop users type that pint does not know
                units.define("Nm = newton * meter")
                units.define("RPM = revolution / minute")
                units.define("rev = revolution")
                _REGISTRY = units
    return _REGISTRY


#: pint unit names that carry an angle; a frequency without one ("Hz", "min^-1")
#: given for an angular speed counts revolutions, as engineers mean it.
_ANGLE_UNITS = ("radian", "degree", "rev", "RPM", "rpm", "turn", "arcminute", "arcsecond", "grade")
_SUPERSCRIPTS = {"²": "^2", "³": "^3", "⁴": "^4", "⁻¹": "^-1", "⁻²": "^-2"}


class UnitError(ValueError):
    """A unit string that cannot be read, or whose dimension does not fit."""


def _normalise(unit: str) -> str:
    unit = unit.replace("·", "*").replace("μ", "u").replace("µ", "u")
    unit = re.sub(r"(?<=[A-Za-z])\.(?=[A-Za-z])", "*", unit)  # "N.m"
    return re.sub(r"°", "degree", unit)


def _plain(text: str) -> str:
    """Superscript exponents ("m²", "min⁻¹") written the way the grammar reads them."""
    for sup, plain in _SUPERSCRIPTS.items():
        text = text.replace(sup, plain)
    return text


#: What a temperature change may be given in, said when an offset unit is refused.
TEMPERATURE_CHANGE_UNITS = "K, delta_degC or delta_degF"


def is_temperature_change(param: Param) -> bool:
    """True when ``param`` is a temperature difference (in kelvin, named or described as a
    change or difference), which takes no offset: 3 degC of warming is 3 K, not 276.15 K.

    >>> is_temperature_change(Param("temperature_change", "K", "Service minus assembly ΔT"))
    True
    >>> is_temperature_change(Param("ambient", "K", "Ambient temperature"))
    False
    """
    words = f"{param.name} {param.description}".lower()
    return param.unit == "K" and any(w in words for w in ("change", "difference", "rise", "drop"))


@lru_cache(maxsize=1024)
def _conversion(unit: str, target: str) -> tuple[float, float]:
    """``(factor, offset)`` taking a value in ``unit`` to ``target`` (both unit
    expressions) as ``value * factor + offset``; the offset is zero except for a
    temperature on a scale with an offset (degC, degF) given for kelvin."""
    import pint

    units = registry()
    try:
        parsed = units.parse_units(_normalise(unit))
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError) as exc:
        raise UnitError(f"unknown unit {unit!r}") from exc
    except Exception as exc:  # pint raises assorted errors on malformed input
        raise UnitError(f"cannot read the unit {unit!r}") from exc
    try:
        offset = units.Quantity(0.0, parsed).to(target).magnitude
        factor = units.Quantity(1.0, parsed).to(target).magnitude - offset
    except pint.errors.DimensionalityError as exc:
        raise UnitError(
            f"{unit!r} has the wrong dimension: expected {target} (write products as 'N*m')"
        ) from exc
    except Exception as exc:  # "m*dB": pint cannot multiply logarithmic or offset units
        raise UnitError(f"cannot convert {unit!r} to {target}") from exc
    names = " ".join(str(name) for name in parsed._units)
    if target.startswith("rad/") and not any(a in names for a in _ANGLE_UNITS):
        factor *= 2.0 * math.pi  # Hz, 1/min for a speed: revolutions per unit time
    return float(factor), float(offset)


def to_si(text: str, target: str, *, difference: bool = False) -> float:
    """Read ``text`` ("45 mm") and return its magnitude in ``target`` (an SI unit).

    >>> round(to_si("1450 rpm", "rad/s"), 3)
    151.844
    >>> to_si("45 mm", "m")
    0.045
    >>> to_si("0.5", "m")
    0.5

    ``difference``: the value is a difference of two values (a temperature change, a
    standard deviation), so a unit with an offset is refused rather than read with it.

    >>> round(to_si("20 degC", "K"), 2)
    293.15
    >>> round(to_si("9 delta_degF", "K", difference=True), 12)
    5.0
    >>> try:
    ...     to_si("3 degF", "K", difference=True)
    ... except UnitError as exc:
    ...     print(exc)  # doctest: +NORMALIZE_WHITESPACE
    'degF' is a temperature on a scale with an offset, not a temperature change: give the
    change in K, delta_degC or delta_degF, e.g. '3 delta_degF'
    """
    if len(text) > MAX_UNIT_STRING:
        raise UnitError(f"a unit string has at most {MAX_UNIT_STRING} characters")
    match = _QUANTITY.fullmatch(_plain(text))
    if match is None:
        raise UnitError(f"cannot read {text!r}: expected a number and a unit, like '45 mm'")
    number, unit = match.group(1), match.group(2)
    value = float(number)
    if not math.isfinite(value):  # "1e999" overflows float
        raise UnitError(f"{text!r} is not a finite quantity")
    if not unit:
        return value
    if target == "1":
        factor, offset = _DIMENSIONLESS_UNITS.get(unit.strip()), 0.0
        if factor is None:
            raise UnitError(f"{unit!r} has the wrong dimension: expected a plain number")
    else:
        factor, offset = _conversion(unit.strip(), target)
        if offset != 0.0 and difference:
            scale = {1.0: "delta_degC", round(5.0 / 9.0, 12): "delta_degF"}.get(round(factor, 12))
            raise UnitError(
                f"{unit.strip()!r} is a temperature on a scale with an offset, not a temperature"
                f" change: give the change in {TEMPERATURE_CHANGE_UNITS}"
                + (f", e.g. '{number} {scale}'" if scale else "")
            )
    result = value * factor + offset
    if not math.isfinite(result):
        raise UnitError(f"{text!r} is not a finite quantity")
    return result


def quantity(
    param: Param, value: float | str, part: str, field: str, spread: bool = False
) -> float:
    """One number the request gives for ``param`` (a sweep end, a study law's low, high,
    mean, mode or standard deviation), in SI units; refused with a message naming the input,
    the part, the value as the user wrote it and the allowed range.

    ``spread``: the value is a width (a standard deviation), not a value of the input, so the
    input's range does not bound it. ``field`` is the request field the error names.

    >>> from engine import Param
    >>> speed = Param("speed", "rad/s", "speed", minimum=0.0, maximum=1e4)
    >>> round(quantity(speed, "1450 rpm", "start", "start"), 3)
    151.844
    >>> try:
    ...     quantity(speed, "5 kg", "stop", "stop")
    ... except InputOutOfRange as exc:
    ...     print(exc.field, "|", exc.message)  # doctest: +NORMALIZE_WHITESPACE
    stop | speed (stop) = '5 kg': 'kg' has the wrong dimension: expected rad/s (write
    products as 'N*m'); allowed: a finite number ≥ 0 rad/s and ≤ 10000 rad/s, in rad/s or
    as a string with a unit
    """
    unit = "a plain number" if param.unit == "1" else f"in {param.unit} or as a string with a unit"
    allowed = f"a finite number > 0, {unit}" if spread else f"{param.range_text()}, {unit}"
    if isinstance(value, str):
        try:
            return to_si(value, param.unit, difference=spread or is_temperature_change(param))
        except UnitError as exc:
            reason = str(exc)
    elif math.isfinite(value):
        return float(value)
    else:
        reason = "not a finite number"
    shown = repr(value) if isinstance(value, str) else f"{value}"
    raise InputOutOfRange(
        f"{param.name} ({part}) = {shown}: {reason}; allowed: {allowed}", field=field
    )
