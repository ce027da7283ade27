"""Quantities in sentences, carried as data.

A model writes its checks and notes as sentences with numbers in them ("F_M = 23.8 kN").
The form shows them in the unit system the user chose, so each number must travel as a
value and a unit, not only as digits. :func:`q` writes a quantity for a sentence: the
text reads as the sentence always read once :func:`plain` has taken the marks out, and
:func:`parts` splits the same sentence into text and quantities (SI value, SI unit, the
display unit, the significant digits shown and the text as written).

The marks are three characters of Unicode's private use area, which no sentence of a
model writes otherwise: a quantity is ``OPEN text SEP value SEP display SEP digits SEP
bare CLOSE``. A sentence survives f-strings, joins and concatenation with its quantities
in it; the runner takes the marks out of every check, note and warning before they leave
the engine (:func:`plain`) and keeps the marked sentences, from which a check's
``detail_parts`` and the answer's ``notes_parts`` are read when asked (:func:`parts`): an
API client reads the plain sentence as before and, beside it, the parts. Reading the
marks is splitting on those characters: no pattern is matched against numbers in free
text. Refusals (exceptions) keep plain text (:func:`engine.core.params.quantity`).

>>> s = f"F_M = {q(23790.0, 'kN')} is below F_M,min"
>>> plain(s)
'F_M = 23.8 kN is below F_M,min'
>>> parts(s)[1]["value"], parts(s)[1]["unit"], parts(s)[1]["display_unit"]
(23790.0, 'N', 'kN')
"""

from __future__ import annotations

import math
import re
import struct
from typing import TypedDict

OPEN = "\ue000"
SEP = "\ue001"
CLOSE = "\ue002"

#: Display units of sentences: display unit -> (SI unit as the specs write it, factor
#: from SI, suffix written after the number).
DISPLAY: dict[str, tuple[str, float, str]] = {
    "m": ("m", 1.0, " m"),
    "mm": ("m", 1e3, " mm"),
    "µm": ("m", 1e6, " µm"),
    "mm²": ("m^2", 1e6, " mm²"),
    "s": ("s", 1.0, " s"),
    "ms": ("s", 1e3, " ms"),
    "N": ("N", 1.0, " N"),
    "kN": ("N", 1e-3, " kN"),
    "N*m": ("N*m", 1.0, " N·m"),
    "N*m/rad": ("N*m/rad", 1.0, " N·m/rad"),
    "N/mm": ("N/m", 1e-3, " N/mm"),
    "kN/mm": ("N/m", 1e-6, " kN/mm"),
    "µm/kN": ("m/N", 1e9, " µm/kN"),
    "m/N": ("m/N", 1.0, " m/N"),
    "MPa": ("Pa", 1e-6, " MPa"),
    "GPa": ("Pa", 1e-9, " GPa"),
    "rpm": ("rad/s", 30.0 / math.pi, " rpm"),
    "deg": ("rad", 180.0 / math.pi, "°"),
    "%": ("1", 100.0, " %"),
    "kg": ("kg", 1.0, " kg"),
    "kg*m^2": ("kg*m^2", 1.0, " kg·m²"),
    "J": ("J", 1.0, " J"),
    "W": ("W", 1.0, " W"),
    "m/s": ("m/s", 1.0, " m/s"),
}


#: A quantity's marks as :func:`q` writes them (five fields; the text is the last): the marks
#: alone are matched, never the numbers of free text.
_DATA = re.compile(f"{SEP}[^{OPEN}{CLOSE}]*{CLOSE}")


class Quantity(TypedDict):
    """A number in a sentence: ``value`` in ``unit`` (SI, None if not finite), written
    ``text`` in ``display_unit`` with ``digits`` significant digits; ``bare`` when the text
    is the number alone, its unit written once after a range ("12.3…14.5 kN")."""

    value: float | None
    unit: str
    display_unit: str
    digits: int
    text: str
    bare: bool


#: A sentence as parts: text, and quantities where the sentence has numbers.
Parts = list[str | Quantity]


def written(value: float, display: str, fmt: str = ".3g") -> str:
    """An SI ``value`` written in the display unit ``display``, with the format ``fmt``.

    >>> written(0.0042, "mm")
    '4.2 mm'
    >>> written(157.07963, "rpm", ".0f")
    '1500 rpm'
    >>> written(math.radians(45.0), "deg")
    '45°'
    """
    return _number(value, display, fmt) + DISPLAY[display][2]


def _number(value: float, display: str, fmt: str) -> str:
    """The number of :func:`written`, without its unit."""
    return f"{value * DISPLAY[display][1]:{fmt}}"


#: Per display unit: the factor from SI, the unit as written after the number (the two
#: columns of :data:`DISPLAY` that :func:`q` reads on every call) and the mark's fields
#: that follow the SI value (the display unit between its separators).
_WRITE: dict[str, tuple[float, str, str]] = {
    k: (v[1], v[2], f"{SEP}{k}{SEP}") for k, v in DISPLAY.items()
}
#: A quantity's SI value as the mark carries it: its 8 bytes (little-endian IEEE 754), in hex.
_DOUBLE = struct.Struct("<d")
_PACK = _DOUBLE.pack


def q(
    value: float,
    display: str,
    digits: int = 3,
    *,
    fmt: str | None = None,
    bare: bool = False,
    suffix: str | None = None,
) -> str:
    """A quantity for a sentence: the SI ``value`` written in ``display`` with ``digits``
    significant digits (or the format ``fmt``, e.g. ``".0f"``), marked so the runner can
    give it to the form as data; ``bare`` writes the number without its unit (the first
    of a range: ``f"{q(lo, 'kN', bare=True)}…{q(hi, 'kN')}"``).

    ``display`` is a key of :data:`DISPLAY`; the SI unit comes from there; ``suffix``
    writes the unit otherwise than :data:`DISPLAY` does (``" N*m"``). The digits the
    parts carry are those the text shows, at least 3 and at most ``digits`` ("12 mm"
    written with ``:g`` carries 3, so 0.472 in, not 0.47 in).

    >>> plain(q(23790.0, "kN"))
    '23.8 kN'
    >>> plain(q(0.0012, "mm", 4))
    '1.2 mm'
    >>> parts(q(0.0012, "mm", 4))[0]["digits"], parts(q(0.001234, "mm", 4))[0]["digits"]
    (3, 4)
    >>> parts(q(201.4, "N*m", fmt=".0f"))[0]["digits"]
    3
    >>> parts(q(2014.0, "N*m", fmt=".1f"))[0]["digits"]
    5
    >>> plain(q(201.4, "N*m", 4, suffix=" N*m"))
    '201.4 N*m'
    """
    value = float(value)
    factor, unit, tail = _WRITE[display]
    if fmt is None:
        if digits == 3:  # most quantities: one format, the digits known
            number, shown = f"{value * factor:.3g}", "3"
        else:
            number = f"{value * factor:.{digits}g}"
            # the digits the parts carry: with ``digits`` ≤ 3 they are ``digits`` whatever
            # the number shows; else parts() counts them in the number (the text's first
            # characters), at most ``digits``
            shown = str(digits) if digits <= 3 else f"{digits}:{len(number)}"
    else:
        number = f"{value * factor:{fmt}}"
        shown = f":{len(number)}"  # counted by parts(), no upper limit
    # the SI value travels as the hex of its 8 bytes: exact, and cheaper to write than repr
    if bare:
        return f"{OPEN}{number}{SEP}{_PACK(value).hex()}{tail}{shown}{SEP}1{CLOSE}"
    unit = unit if suffix is None else suffix
    return f"{OPEN}{number}{unit}{SEP}{_PACK(value).hex()}{tail}{shown}{SEP}{CLOSE}"


def _digits(shown: str, text: str) -> int:
    """The digits a quantity's parts carry, from what :func:`q` wrote of them: the number,
    or ``"<at most>:<characters of the number>"`` to count in ``text`` (at least 3).

    >>> _digits("3", "23.8 kN"), _digits("4:3", "1.2 mm"), _digits("4:5", "1.234 mm")
    (3, 3, 4)
    >>> _digits(":6", "2014.0 N·m"), _digits("6:8", "0.001234 mm")
    (5, 4)
    >>> _digits(":6", "0.0450 mm"), _digits("5:9", "-1.50e+03 N"), _digits(":1", "0 mm")
    (3, 3, 3)
    """
    limits = _LIMITS.get(shown)
    if limits is None:
        limits = _limits(shown)
    if isinstance(limits, int):
        return limits
    most, length = limits
    # the significant digits the number shows ("0.0450" → 3, "-1.50e+03" → 3): its
    # mantissa without sign, leading zeros and point, counted in one expression
    found = len(text[:length].partition("e")[0].lstrip("-0.").replace(".", ""))
    if found < 3:
        found = 3
    if most is not None and found > most:
        return most
    return found


#: What :func:`_digits` reads of a quantity's digits field, per field as written: the
#: digits, or ``(at most, characters of the number)`` (None: no upper limit) to count
#: them in the text. q() writes few distinct fields (the digits asked, the number's
#: length), so each is read once. A number of at most 3 characters shows at most 3 digits,
#: counted as 3 (the least), so its field gives them without the text (``"4:2"``: 3): a
#: third of the fields q() writes, read without counting.
_LIMITS: dict[str, int | tuple[int | None, int]] = {"1": 1, "2": 2, "3": 3}


def _limits(shown: str) -> int | tuple[int | None, int]:
    """:data:`_LIMITS`'s entry for ``shown``, kept there (ValueError where it is not a
    digits field, kept nowhere).

    >>> _limits("4"), _limits("4:5"), _limits(":6"), _limits("4:3"), _limits(":2"), _limits("2:3")
    (4, (4, 5), (None, 6), 3, 3, 2)
    """
    most, counted, length = shown.partition(":")
    if not counted:
        limits: int | tuple[int | None, int] = int(most)
    else:
        at_most, characters = (int(most) if most else None, int(length))
        if 0 <= characters <= 3:  # the count would find at most 3: it is 3, or fewer if capped
            limits = 3 if at_most is None else min(3, at_most)
        else:
            limits = (at_most, characters)
    if len(_LIMITS) < 1024 and len(shown) <= 16:  # bounded whatever sentences are read
        _LIMITS[shown] = limits
    return limits


def plain(sentence: str) -> str:
    """``sentence`` as a person reads it: every quantity's text, the marks taken out.

    >>> plain("M_A = " + q(73.51, "N*m") + " at μ_G = 0.1")
    'M_A = 73.5 N·m at μ_G = 0.1'
    >>> plain("no quantity")
    'no quantity'
    """
    if OPEN not in sentence:
        return sentence
    # each quantity's data dropped and its opening mark: two passes in C
    fast = _DATA.sub("", sentence).replace(OPEN, "")
    if SEP not in fast and CLOSE not in fast:
        return fast
    return _joined(parts(sentence))  # stray marks: read as parts() reads them


def _joined(ps: Parts) -> str:
    """The text of a sentence's parts: what a reader sees."""
    return "".join(p if isinstance(p, str) else p["text"] for p in ps)


def parts(sentence: str) -> Parts:
    """``sentence`` split into its text and its quantities, in order.

    >>> parts("a " + q(150.0, "N") + " b")  # doctest: +NORMALIZE_WHITESPACE
    ['a ', {'value': 150.0, 'unit': 'N', 'display_unit': 'N', 'digits': 3, 'text': '150 N',
            'bare': False}, ' b']
    >>> plain(f"{q(12_300.0, 'kN', bare=True)}…{q(14_500.0, 'kN')}")
    '12.3…14.5 kN'
    >>> parts("no quantity")
    ['no quantity']
    >>> parts("a\ue000b" + SEP + "c")  # a stray mark: only dropped
    ['abc']
    """
    return _read(sentence)[1]


def _read(sentence: str) -> tuple[str | None, Parts]:
    """``sentence``'s parts, and its text as :func:`plain` gives it where no mark stands
    outside a quantity :func:`q` wrote (None otherwise): the texts between the quantities
    and the quantities' texts, joined once."""
    if OPEN not in sentence:
        return sentence, [sentence]
    head, *marked = sentence.split(OPEN)
    out: Parts = [head] if head else []
    seen = [head]  # what a reader sees, piece by piece
    append = out.append
    see = seen.append
    unit_of = _SI_UNIT
    known = _LIMITS
    unpack = _DOUBLE.unpack
    fromhex = bytes.fromhex
    for piece in marked:
        payload, close, rest = piece.partition(CLOSE)
        fields = payload.split(SEP)
        if not close or len(fields) != 5:
            return None, _parts_marked(sentence)  # a mark outside a quantity q() wrote
        text, raw, display, shown, flag = fields
        unit = unit_of.get(display)
        if unit is None:
            return None, _parts_marked(sentence)  # a display unit this module does not write
        try:
            (value,) = unpack(fromhex(raw))
            if value - value == 0.0:  # finite
                digits = known.get(shown)  # the common case: the field gives the digits
                if digits.__class__ is not int:
                    digits = _digits(shown, text)
            else:
                value, digits = None, 3
        except (ValueError, struct.error):
            return None, _parts_marked(sentence)
        append(
            {
                "value": value,
                "unit": unit,
                "display_unit": display,
                "digits": digits,
                "text": text,
                "bare": flag == "1",
            }
        )
        see(text)
        if rest:  # after a quantity: no text to join it to
            append(rest)
            see(rest)
    text = "".join(seen)
    if SEP in text or CLOSE in text:  # in the texts between: plain() reads it otherwise
        return None, out
    return text, out


#: Per display unit, its SI unit (the first column of :data:`DISPLAY`).
_SI_UNIT: dict[str, str] = {k: v[0] for k, v in DISPLAY.items()}


def _parts_marked(sentence: str) -> Parts:
    """:func:`parts` of a sentence with a mark outside a quantity :func:`q` wrote: each
    piece between opening marks read on its own; what is not a quantity keeps what a
    reader would see.

    >>> _parts_marked("a" + OPEN + "b" + SEP + "c" + CLOSE + " d")
    ['abc d']
    """
    head, *marked = sentence.split(OPEN)
    out: Parts = [head] if head else []

    def add(text: str) -> None:  # neighbouring texts joined
        if out and isinstance(out[-1], str):
            out[-1] += text
        elif text:
            out.append(text)

    for piece in marked:
        payload, close, rest = piece.partition(CLOSE)
        fields = payload.split(SEP)
        if not close or len(fields) != 5 or fields[2] not in DISPLAY:
            # not a quantity this module wrote: keep what a reader would see
            add(piece.replace(SEP, "").replace(CLOSE, ""))
            continue
        text, raw, display, shown, flag = fields
        try:
            (value,) = _DOUBLE.unpack(bytes.fromhex(raw))
            finite = math.isfinite(value)
            digits = _digits(shown, text) if finite else 3
        except (ValueError, struct.error):
            add(text + rest)
            continue
        out.append(
            {
                "value": value if finite else None,
                "unit": DISPLAY[display][0],
                "display_unit": display,
                "digits": digits,
                "text": text,
                "bare": flag == "1",
            }
        )
        if rest:  # after a quantity: no text to join it to
            out.append(rest)
    return out or [""]


def split(sentence: str) -> tuple[str, Parts]:
    """``(plain(sentence), parts(sentence))``, the sentence read once where it has no stray
    mark: for a reader of both (the service's answer), about a quarter less than the two apart.

    >>> text, (head, quantity) = split("F_K = " + q(11900.0, "kN"))
    >>> text, head, quantity["value"], quantity["text"]
    ('F_K = 11.9 kN', 'F_K = ', 11900.0, '11.9 kN')
    """
    text, ps = _read(sentence)
    return plain(sentence) if text is None else text, ps
