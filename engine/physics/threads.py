r"""Metric ISO bolt data, embedded: threads, hexagon heads, clearance holes, property classes.

Everything a preload calculation needs about a standard bolt, without a
network or a catalogue: the basic profile of ISO 68-1 (pitch, pitch and
minor diameters), the coarse and common fine pitches of ISO 261, the stress
area of ISO 898-1, the minimum bearing-face diameter ``d_w`` of a hexagon head
(ISO 4017), the clearance holes of ISO 273 and the minimum strengths of the
property classes of ISO 898-1. Sizes are keyed by the nominal diameter in
millimetres (the standards' own tables); the public functions take and
return SI values (m, Pa, m²).

Every value here can be overridden by the caller; the lookups raise
:class:`~engine.core.errors.InputOutOfRange` naming the input the caller should
give when the standard has no value for the size asked.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from ..core.errors import InputOutOfRange

#: ISO 261 coarse pitch [mm] per nominal diameter [mm], M3…M39 (M7 left out:
#: second choice, without an ISO 4017 head or a common clearance-hole row).
COARSE_PITCH_MM: dict[float, float] = {
    3.0: 0.5,
    3.5: 0.6,
    4.0: 0.7,
    5.0: 0.8,
    6.0: 1.0,
    8.0: 1.25,
    10.0: 1.5,
    12.0: 1.75,
    14.0: 2.0,
    16.0: 2.0,
    18.0: 2.5,
    20.0: 2.5,
    22.0: 2.5,
    24.0: 3.0,
    27.0: 3.0,
    30.0: 3.5,
    33.0: 3.5,
    36.0: 4.0,
    39.0: 4.0,
}

#: ISO 261 fine pitches [mm] in common use (the ones ISO 8765/8676 bolts are made with).
FINE_PITCHES_MM: dict[float, tuple[float, ...]] = {
    8.0: (1.0,),
    10.0: (1.25, 1.0),
    12.0: (1.5, 1.25),
    14.0: (1.5,),
    16.0: (1.5,),
    18.0: (2.0, 1.5),
    20.0: (2.0, 1.5),
    22.0: (2.0, 1.5),
    24.0: (2.0,),
    27.0: (2.0,),
    30.0: (2.0,),
    33.0: (2.0,),
    36.0: (3.0,),
    39.0: (3.0,),
}

#: Minimum bearing-face diameter d_w,min [mm] of a hexagon head, ISO 4017
#: (product grade A up to M24, grade B above). Hexagon nuts of ISO 4032 have
#: nearly the same d_w,min; give ``bearing_outer_diameter`` for any other head.
HEX_BEARING_DIAMETER_MM: dict[float, float] = {
    3.0: 4.57,
    3.5: 5.07,
    4.0: 5.88,
    5.0: 6.88,
    6.0: 8.88,
    8.0: 11.63,
    10.0: 14.63,
    12.0: 16.63,
    14.0: 19.64,
    16.0: 22.49,
    18.0: 25.34,
    20.0: 28.19,
    22.0: 31.71,
    24.0: 33.61,
    27.0: 38.0,
    30.0: 42.75,
    33.0: 46.55,
    36.0: 51.11,
    39.0: 55.86,
}

#: ISO 273 clearance holes [mm]: (fine, medium, coarse) per nominal diameter.
CLEARANCE_HOLE_MM: dict[float, tuple[float, float, float]] = {
    3.0: (3.2, 3.4, 3.6),
    3.5: (3.7, 3.9, 4.2),
    4.0: (4.3, 4.5, 4.8),
    5.0: (5.3, 5.5, 5.8),
    6.0: (6.4, 6.6, 7.0),
    8.0: (8.4, 9.0, 10.0),
    10.0: (10.5, 11.0, 12.0),
    12.0: (13.0, 13.5, 14.5),
    14.0: (15.0, 15.5, 16.5),
    16.0: (17.0, 17.5, 18.5),
    18.0: (19.0, 20.0, 21.0),
    20.0: (21.0, 22.0, 24.0),
    22.0: (23.0, 24.0, 26.0),
    24.0: (25.0, 26.0, 28.0),
    27.0: (28.0, 30.0, 32.0),
    30.0: (31.0, 33.0, 35.0),
    33.0: (34.0, 36.0, 38.0),
    36.0: (37.0, 39.0, 42.0),
    39.0: (40.0, 42.0, 45.0),
}

HOLE_SERIES: tuple[str, ...] = ("fine", "medium", "coarse")


@dataclass(frozen=True)
class PropertyClass:
    """Minimum strengths of one ISO 898-1 property class [MPa].

    ``yield_small``/``tensile_small`` hold for d ≤ ``size_step_mm``,
    ``yield_large``/``tensile_large`` above it (only 8.8 has such a step);
    ``max_diameter_mm`` is the largest size the class is defined for.
    """

    name: str
    yield_small: float
    tensile_small: float
    yield_large: float
    tensile_large: float
    size_step_mm: float = 39.0
    max_diameter_mm: float = 39.0
    yield_kind: str = "R_p0.2"


#: ISO 898-1:2013 Table 3, minimum values. 4.6 and 5.6 have a lower yield
#: strength R_eL; 4.8, 5.8 and 6.8 the stress R_pf at 0.0048 d non-proportional
#: elongation of a full-size bolt; 8.8 and up the 0.2 % proof stress R_p0.2.
PROPERTY_CLASSES: dict[str, PropertyClass] = {
    "4.6": PropertyClass("4.6", 240.0, 400.0, 240.0, 400.0, yield_kind="R_eL"),
    "4.8": PropertyClass("4.8", 340.0, 420.0, 340.0, 420.0, yield_kind="R_pf"),
    "5.6": PropertyClass("5.6", 300.0, 500.0, 300.0, 500.0, yield_kind="R_eL"),
    "5.8": PropertyClass("5.8", 420.0, 520.0, 420.0, 520.0, yield_kind="R_pf"),
    "6.8": PropertyClass("6.8", 480.0, 600.0, 480.0, 600.0, yield_kind="R_pf"),
    "8.8": PropertyClass("8.8", 640.0, 800.0, 660.0, 830.0, size_step_mm=16.0),
    "9.8": PropertyClass("9.8", 720.0, 900.0, 720.0, 900.0, max_diameter_mm=16.0),
    "10.9": PropertyClass("10.9", 940.0, 1040.0, 940.0, 1040.0),
    "12.9": PropertyClass("12.9", 1100.0, 1220.0, 1100.0, 1220.0),
}

PROPERTY_CLASS_NAMES: tuple[str, ...] = tuple(PROPERTY_CLASSES)

#: ISO 898-1 specifies the classes only up to M39. Larger bolts (ISO 262 goes on to M64)
#: are made to these classes by agreement; so that every catalogue size computes, a class
#: ISO 898-1 defines up to M39 is taken at its M39 minimum values up to M64, and the
#: result says so (:func:`beyond_iso898`). A size above M64 still needs yield_strength.
CARRIED_TO_MM = 64.0


def _size_key(diameter: float, table: Mapping[float, object]) -> float | None:
    """The table key (mm) matching ``diameter`` [m], or None (tolerates unit round-off)."""
    mm = diameter * 1e3
    if mm in table:  # the size as tabulated (the common case): no scan
        return mm
    for key in table:
        if abs(mm - key) <= 1e-6 * key:
            return key
    return None


def pitch_diameter(diameter: float, pitch: float) -> float:
    r"""Pitch (flank) diameter of an ISO metric external thread.

    .. math::
        d_2 = d - 0.649519\,P

    Parameters
    ----------
    diameter : float
        Nominal (major) diameter d, [m]
    pitch : float
        Thread pitch P, [m]

    Returns
    -------
    float
        d2, [m]

    Notes
    -----
    Basic profile of ISO 68-1 / ISO 724: d2 = d − (3/8)·2H with H = (√3/2) P.

    Examples
    --------
    >>> round(pitch_diameter(0.012, 0.00175) * 1e3, 3)
    10.863
    """
    return diameter - 0.649519 * pitch


def minor_diameter(diameter: float, pitch: float) -> float:
    r"""Minor diameter d3 of an ISO metric external thread (bolt root).

    .. math::
        d_3 = d - 1.226869\,P

    Parameters
    ----------
    diameter : float
        Nominal diameter d, [m]
    pitch : float
        Thread pitch P, [m]

    Returns
    -------
    float
        d3, [m]

    Notes
    -----
    ISO 68-1 / ISO 724 with the basic root radius H/6 of the bolt.

    Examples
    --------
    >>> round(minor_diameter(0.012, 0.00175) * 1e3, 3)
    9.853
    """
    return diameter - 1.226869 * pitch


def nut_minor_diameter(diameter: float, pitch: float) -> float:
    r"""Minor diameter D1 = d1 of the basic profile (the nut's bore).

    .. math::
        d_1 = d - 1.082532\,P

    Parameters
    ----------
    diameter : float
        Nominal diameter d, [m]
    pitch : float
        Thread pitch P, [m]

    Returns
    -------
    float
        d1, [m]

    Notes
    -----
    ISO 68-1 / ISO 724: d1 = d − (5/8)·2H.

    Examples
    --------
    >>> round(nut_minor_diameter(0.012, 0.00175) * 1e3, 3)
    10.106
    """
    return diameter - 1.082532 * pitch


def stress_diameter(diameter: float, pitch: float) -> float:
    r"""Stress diameter d0 = d_S, the mean of pitch and minor diameters.

    .. math::
        d_0 = \frac{d_2 + d_3}{2}

    Parameters
    ----------
    diameter : float
        Nominal diameter d, [m]
    pitch : float
        Thread pitch P, [m]

    Returns
    -------
    float
        d0, [m]

    Notes
    -----
    ISO 898-1; VDI 2230 calls it d_S and uses it as d0 for a bolt whose
    shank is not thinner than the thread.

    Examples
    --------
    >>> round(stress_diameter(0.012, 0.00175) * 1e3, 3)
    10.358
    """
    return 0.5 * (pitch_diameter(diameter, pitch) + minor_diameter(diameter, pitch))


def stress_area(diameter: float, pitch: float) -> float:
    r"""Nominal stress area of an ISO metric bolt.

    .. math::
        A_s = \frac{\pi}{4}\left(\frac{d_2 + d_3}{2}\right)^2

    Parameters
    ----------
    diameter : float
        Nominal diameter d, [m]
    pitch : float
        Thread pitch P, [m]

    Returns
    -------
    float
        A_s, [m²]

    Notes
    -----
    ISO 898-1 (tabulated there as 84.3 mm² for M12, 58.0 mm² for M10).

    Examples
    --------
    >>> round(stress_area(0.012, 0.00175) * 1e6, 1)
    84.3
    >>> round(stress_area(0.010, 0.0015) * 1e6, 1)
    58.0
    """
    return 0.25 * math.pi * stress_diameter(diameter, pitch) ** 2


def coarse_pitch(diameter: float) -> float:
    """ISO 261 coarse pitch [m] for a nominal diameter [m].

    Raises InputOutOfRange (field ``thread_pitch``) for a diameter that has
    no tabulated coarse pitch.

    Parameters
    ----------
    diameter : float
        Nominal thread diameter d, [m]

    Examples
    --------
    >>> coarse_pitch(0.012)
    0.00175
    """
    key = _size_key(diameter, COARSE_PITCH_MM)
    if key is None:
        sizes = ", ".join(f"M{k:g}" for k in COARSE_PITCH_MM)
        raise InputOutOfRange(
            f"no ISO 261 coarse pitch is tabulated for d = {diameter * 1e3:g} mm "
            f"(sizes {sizes}); give thread_pitch",
            field="thread_pitch",
        )
    return COARSE_PITCH_MM[key] * 1e-3


def standard_pitches(diameter: float) -> tuple[float, ...]:
    """Coarse then common fine ISO 261 pitches [m] for a size (empty if none).

    Parameters
    ----------
    diameter : float
        Nominal thread diameter d, [m]

    Examples
    --------
    >>> [round(p * 1e3, 2) for p in standard_pitches(0.012)]
    [1.75, 1.5, 1.25]
    """
    out: list[float] = []
    key = _size_key(diameter, COARSE_PITCH_MM)
    if key is not None:
        out.append(COARSE_PITCH_MM[key] * 1e-3)
    key = _size_key(diameter, FINE_PITCHES_MM)
    if key is not None:
        out.extend(p * 1e-3 for p in FINE_PITCHES_MM[key])
    return tuple(out)


def hex_bearing_diameter(diameter: float) -> float:
    """Minimum bearing-face diameter d_w [m] of an ISO 4017 hexagon head.

    Raises InputOutOfRange (field ``bearing_outer_diameter``) for a size
    without a tabulated head.

    Parameters
    ----------
    diameter : float
        Nominal thread diameter d, [m]

    Examples
    --------
    >>> hex_bearing_diameter(0.010)
    0.01463
    """
    key = _size_key(diameter, HEX_BEARING_DIAMETER_MM)
    if key is None:
        raise InputOutOfRange(
            f"no ISO 4017 hexagon head is tabulated for d = {diameter * 1e3:g} mm; "
            "give bearing_outer_diameter",
            field="bearing_outer_diameter",
        )
    return HEX_BEARING_DIAMETER_MM[key] * 1e-3


def clearance_hole(diameter: float, series: str = "medium") -> float:
    """ISO 273 clearance-hole diameter d_h [m] for a size and series.

    Raises InputOutOfRange (field ``hole_diameter``) for a size without a
    tabulated hole, (field ``hole_series``) for an unknown series.

    Parameters
    ----------
    diameter : float
        Nominal thread diameter d, [m]
    series : str
        "fine", "medium" or "coarse"

    Examples
    --------
    >>> clearance_hole(0.012, "medium")
    0.0135
    """
    if series not in HOLE_SERIES:
        raise InputOutOfRange(
            f"hole_series = {series!r} is not allowed: must be one of {', '.join(HOLE_SERIES)}",
            field="hole_series",
        )
    key = _size_key(diameter, CLEARANCE_HOLE_MM)
    if key is None:
        raise InputOutOfRange(
            f"no ISO 273 clearance hole is tabulated for d = {diameter * 1e3:g} mm; "
            "give hole_diameter",
            field="hole_diameter",
        )
    return CLEARANCE_HOLE_MM[key][HOLE_SERIES.index(series)] * 1e-3


def _largest_mm(cls: PropertyClass) -> float:
    """The largest size computed for a class: its ISO 898-1 range, M39 classes to M64."""
    return CARRIED_TO_MM if cls.max_diameter_mm >= 39.0 else cls.max_diameter_mm


def beyond_iso898(name: str, diameter: float) -> bool:
    """Whether class ``name`` at ``diameter`` [m] takes ISO 898-1's M39 values beyond its range.

    True above M39 (up to M64, :data:`CARRIED_TO_MM`), where
    :func:`property_class_strengths` carries the M39 minimum strengths on as a
    stated assumption; False where ISO 898-1 itself defines the class.

    Parameters
    ----------
    name : str
        Property class, e.g. "8.8"
    diameter : float
        Nominal thread diameter d, [m]

    Returns
    -------
    bool
        Whether the strengths are ISO 898-1's M39 values carried beyond M39

    Examples
    --------
    >>> beyond_iso898("8.8", 0.039), beyond_iso898("8.8", 0.042)
    (False, True)
    """
    cls = PROPERTY_CLASSES.get(name)
    return cls is not None and diameter * 1e3 > cls.max_diameter_mm * (1 + 1e-9)


def property_class_strengths(name: str, diameter: float) -> tuple[float, float]:
    """Minimum yield (R_eL, R_pf or R_p0.2) and tensile strength R_m [Pa] of a class.

    Applies the size step of ISO 898-1 (8.8: 640/800 MPa up to M16,
    660/830 MPa above). ISO 898-1 stops at M39: a class it defines up to M39
    keeps its M39 values up to M64 (:data:`CARRIED_TO_MM`, an assumption the
    caller states, :func:`beyond_iso898`). Raises InputOutOfRange (field
    ``property_class``) for an unknown class or a size beyond that (9.8 above M16,
    any class above M64).

    Parameters
    ----------
    name : str
        Property class, e.g. "8.8"
    diameter : float
        Nominal thread diameter d, [m]

    Examples
    --------
    >>> property_class_strengths("8.8", 0.016)
    (640000000.0, 800000000.0)
    >>> property_class_strengths("8.8", 0.020)
    (660000000.0, 830000000.0)
    >>> property_class_strengths("10.9", 0.048)  # beyond M39: the M39 values
    (940000000.0, 1040000000.0)
    """
    cls = PROPERTY_CLASSES.get(name)
    if cls is None:
        raise InputOutOfRange(
            f"property_class = {name!r} is not allowed: must be one of "
            + ", ".join(PROPERTY_CLASSES),
            field="property_class",
        )
    mm = diameter * 1e3
    if mm > _largest_mm(cls) * (1 + 1e-9):
        carried = (
            f" (its M39 values are taken up to M{CARRIED_TO_MM:g})"
            if _largest_mm(cls) > cls.max_diameter_mm
            else ""
        )
        raise InputOutOfRange(
            f"property class {name} is defined by ISO 898-1 only up to "
            f"M{cls.max_diameter_mm:g}{carried}; give yield_strength for d = {mm:g} mm",
            field="property_class",
        )
    if mm <= cls.size_step_mm * (1 + 1e-9):
        return cls.yield_small * 1e6, cls.tensile_small * 1e6
    return cls.yield_large * 1e6, cls.tensile_large * 1e6


def largest_diameter(name: str) -> float:
    """The largest diameter [m] :func:`property_class_strengths` answers for class ``name``.

    Parameters
    ----------
    name : str
        Property class, e.g. "8.8"

    Returns
    -------
    float
        M64 for a class ISO 898-1 defines up to M39, else its own limit (9.8: M16), [m]

    Examples
    --------
    >>> largest_diameter("8.8"), largest_diameter("9.8")
    (0.064, 0.016)
    """
    return _largest_mm(PROPERTY_CLASSES[name]) * 1e-3
