r"""Fasteners as bought: threads, grades, heads, nuts, washers, clamped materials.

An embedded catalogue (no network) and the pure functions that read it:

- threads: ISO metric coarse and fine M1.6…M64 (pitches of ISO 261 / ISO 262,
  basic profile of ISO 68-1 / ISO 724, stress area of ISO 898-1) and Unified
  inch UNC/UNF 1/4…1-1/2 (ASME B1.1 basic pitch diameter, tensile stress area);
- grades: ISO 898-1 property classes (from :mod:`engine.physics.threads`), ISO 3506-1
  stainless A2-70, A4-70, A4-80 (and -50), SAE J429 grades 2/5/8, ASTM A193 B7;
- heads: ISO 4017/4014 hexagon, ISO 4762 hexagon socket, EN 1665 hexagon
  flange, ISO 10642 countersunk socket: bearing diameter d_w, head height k and
  the drive (wrench across flats, or hex-key size with the ISO 2936 key torque);
- nuts ISO 4032/4033/4035 (height, property classes), washers ISO 7089/7092/7093;
- clamped and internal-thread materials: limiting surface pressure p_G
  (VDI 2230-1 Table A9) and shear strength.

And the checks a bought fastener needs beyond its preload: the surface
pressure under head, nut or washer (VDI 2230-1 R10), the length of engagement
that makes the bolt break before a thread strips (VDI 2230-1 R11, after
Alexander's shear-area model) and the torque the drive (hex key) carries.

The catalogue keys sizes in the standards' own units (mm, inch); every public
function takes and returns SI values (m, Pa, m², N, N·m). Lookups that miss
raise :class:`~engine.core.errors.InputOutOfRange` naming the input the caller
should give instead.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..core.errors import InputOutOfRange
from . import threads as th

INCH = 0.0254
KSI = 6.894757293168e6
MPA = 1e6

# --------------------------------------------------------------------------- metric threads

#: ISO 261 coarse pitch [mm], M1.6…M64 (first and second choice; M7 and M11 left out).
METRIC_COARSE_PITCH_MM: dict[float, float] = {
    1.6: 0.35,
    2.0: 0.4,
    2.5: 0.45,
    **th.COARSE_PITCH_MM,
    42.0: 4.5,
    45.0: 4.5,
    48.0: 5.0,
    52.0: 5.0,
    56.0: 5.5,
    60.0: 5.5,
    64.0: 6.0,
}

#: ISO 262 (selected sizes for screws, bolts and nuts) and ISO 261 fine pitches [mm].
METRIC_FINE_PITCHES_MM: dict[float, tuple[float, ...]] = {
    1.6: (0.2,),
    2.0: (0.25,),
    2.5: (0.35,),
    3.0: (0.35,),
    4.0: (0.5,),
    5.0: (0.5,),
    6.0: (0.75,),
    **th.FINE_PITCHES_MM,
    42.0: (3.0, 2.0),
    45.0: (3.0, 2.0),
    48.0: (3.0, 2.0),
    52.0: (4.0, 3.0),
    56.0: (4.0, 2.0),
    60.0: (4.0,),
    64.0: (4.0,),
}

# --------------------------------------------------------------------------- inch threads

#: Unified inch sizes 1/4…1-1/2: name -> (major diameter [in], UNC tpi, UNF tpi).
UNIFIED_SIZES: dict[str, tuple[float, int, int]] = {
    "1/4": (0.25, 20, 28),
    "5/16": (0.3125, 18, 24),
    "3/8": (0.375, 16, 24),
    "7/16": (0.4375, 14, 20),
    "1/2": (0.5, 13, 20),
    "9/16": (0.5625, 12, 18),
    "5/8": (0.625, 11, 18),
    "3/4": (0.75, 10, 16),
    "7/8": (0.875, 9, 14),
    "1": (1.0, 8, 12),
    "1-1/8": (1.125, 7, 12),
    "1-1/4": (1.25, 7, 12),
    "1-3/8": (1.375, 6, 12),
    "1-1/2": (1.5, 6, 12),
}

#: ASME B18.2.1 heavy-hex-free "hex cap screw": width across flats F [in] per size
#: (bearing face taken as 0.95 F, the minimum washer-face diameter of B18.2.1).
UNIFIED_HEX_FLATS_IN: dict[str, float] = {
    "1/4": 7 / 16,
    "5/16": 1 / 2,
    "3/8": 9 / 16,
    "7/16": 5 / 8,
    "1/2": 3 / 4,
    "9/16": 13 / 16,
    "5/8": 15 / 16,
    "3/4": 9 / 8,
    "7/8": 21 / 16,
    "1": 3 / 2,
    "1-1/8": 27 / 16,
    "1-1/4": 15 / 8,
    "1-3/8": 33 / 16,
    "1-1/2": 9 / 4,
}

#: ASME B18.2.1 hex cap screw head height H (basic) [in].
UNIFIED_HEX_HEIGHT_IN: dict[str, float] = {
    "1/4": 5 / 32,
    "5/16": 13 / 64,
    "3/8": 15 / 64,
    "7/16": 9 / 32,
    "1/2": 5 / 16,
    "9/16": 23 / 64,
    "5/8": 25 / 64,
    "3/4": 15 / 32,
    "7/8": 35 / 64,
    "1": 39 / 64,
    "1-1/8": 11 / 16,
    "1-1/4": 25 / 32,
    "1-3/8": 27 / 32,
    "1-1/2": 15 / 16,
}

#: ASME B18.2.8 normal clearance hole [in] for the inch sizes (close fit + 1/64 in).
UNIFIED_CLEARANCE_IN: dict[str, float] = {
    "1/4": 0.281,
    "5/16": 0.344,
    "3/8": 0.406,
    "7/16": 0.469,
    "1/2": 0.531,
    "9/16": 0.594,
    "5/8": 0.656,
    "3/4": 0.781,
    "7/8": 0.938,
    "1": 1.062,
    "1-1/8": 1.188,
    "1-1/4": 1.312,
    "1-3/8": 1.438,
    "1-1/2": 1.562,
}


@dataclass(frozen=True)
class Thread:
    """One thread, resolved: designation, series and the basic geometry [m, m²]."""

    designation: str
    series: str  # "ISO coarse", "ISO fine", "UNC", "UNF"
    diameter: float
    pitch: float
    pitch_diameter: float
    minor_diameter: float
    nut_minor_diameter: float
    stress_area: float
    #: The size's key in the head/nut/washer tables: nominal mm (metric) or the inch name.
    size: str

    @property
    def is_metric(self) -> bool:
        return self.series.startswith("ISO")

    def describe(self) -> dict[str, object]:
        return {
            "designation": self.designation,
            "series": self.series,
            "diameter": self.diameter,
            "pitch": self.pitch,
            "pitch_diameter": self.pitch_diameter,
            "minor_diameter": self.minor_diameter,
            "stress_area": self.stress_area,
        }


def unified_pitch_diameter(diameter: float, pitch: float) -> float:
    r"""Basic pitch diameter of a Unified inch thread (ASME B1.1).

    .. math::
        E = D - 0.649519\,p

    Parameters
    ----------
    diameter : float
        Basic major diameter D, [m]
    pitch : float
        Pitch p = 1/n, [m]

    Returns
    -------
    float
        E, [m]

    Notes
    -----
    ASME B1.1 basic profile (the same 60° profile as ISO 68-1); 1/2-13 UNC is
    tabulated as 0.4500 in.

    Examples
    --------
    >>> round(unified_pitch_diameter(0.5 * INCH, INCH / 13) / INCH, 4)
    0.45
    """
    return diameter - 0.649519 * pitch


def unified_stress_area(diameter: float, pitch: float) -> float:
    r"""Tensile stress area of a Unified inch thread (ASME B1.1, steels up to 100 ksi).

    .. math::
        A_t = \frac{\pi}{4}\left(D - 0.9743\,p\right)^2

    Parameters
    ----------
    diameter : float
        Basic major diameter D, [m]
    pitch : float
        Pitch p = 1/n, [m]

    Returns
    -------
    float
        A_t, [m²]

    Notes
    -----
    0.9743 p = (0.649519 + 1.299038) p / 2: the mean of the basic pitch
    diameter and the minor diameter D − 1.299038 p of the sharp-V external
    thread, the same construction as ISO 898-1's stress area.

    Examples
    --------
    >>> round(unified_stress_area(0.5 * INCH, INCH / 13) / INCH**2, 4)
    0.1419
    """
    return 0.25 * math.pi * (diameter - 0.974279 * pitch) ** 2


def _fmt(x: float) -> str:
    return f"{x:g}"


def metric_thread(
    diameter_mm: float, pitch_mm: float | None = None, *, field: str = "thread"
) -> Thread:
    """The ISO metric thread M``diameter_mm`` (coarse when ``pitch_mm`` is None).

    Raises InputOutOfRange (``field``) for a size or pitch ISO 261/262 does not list.

    Examples
    --------
    >>> t = metric_thread(12, 1.25)
    >>> t.designation, round(t.stress_area * 1e6, 1)
    ('M12x1.25', 92.1)
    """
    key = next((k for k in METRIC_COARSE_PITCH_MM if abs(k - diameter_mm) < 1e-9), None)
    if key is None:
        raise InputOutOfRange(
            f"{field}: M{_fmt(diameter_mm)} is not an ISO 261 size in the catalogue "
            f"(M1.6…M64: {', '.join('M' + _fmt(k) for k in METRIC_COARSE_PITCH_MM)}); "
            "give thread_diameter and thread_pitch instead",
            field=field,
        )
    coarse = METRIC_COARSE_PITCH_MM[key]
    fine = METRIC_FINE_PITCHES_MM.get(key, ())
    if pitch_mm is None or abs(pitch_mm - coarse) < 1e-9:
        pitch, series, name = coarse, "ISO coarse", f"M{_fmt(key)}"
    else:
        match = next((p for p in fine if abs(p - pitch_mm) < 1e-9), None)
        if match is None:
            allowed = ", ".join(_fmt(p) for p in (coarse, *fine))
            raise InputOutOfRange(
                f"{field}: pitch {_fmt(pitch_mm)} mm is not an ISO 261/262 pitch of "
                f"M{_fmt(key)} (allowed: {allowed} mm); a bolt length is not part of the "
                "designation here",
                field=field,
            )
        pitch, series, name = match, "ISO fine", f"M{_fmt(key)}x{_fmt(match)}"
    d, p = key * 1e-3, pitch * 1e-3
    return Thread(
        designation=name,
        series=series,
        diameter=d,
        pitch=p,
        pitch_diameter=th.pitch_diameter(d, p),
        minor_diameter=th.minor_diameter(d, p),
        nut_minor_diameter=th.nut_minor_diameter(d, p),
        stress_area=th.stress_area(d, p),
        size=_fmt(key),
    )


def unified_thread(
    size: str, tpi: int | None = None, series: str | None = None, *, field: str = "thread"
) -> Thread:
    """The Unified inch thread ``size``-``tpi`` (UNC when neither tpi nor series says otherwise).

    Examples
    --------
    >>> t = unified_thread("1/2", 13)
    >>> t.designation, round(t.pitch_diameter / INCH, 4)
    ('1/2-13 UNC', 0.45)
    """
    if size not in UNIFIED_SIZES:
        raise InputOutOfRange(
            f"{field}: {size!r} is not a Unified inch size in the catalogue "
            f"({', '.join(UNIFIED_SIZES)})",
            field=field,
        )
    major, unc, unf = UNIFIED_SIZES[size]
    if tpi is None:
        tpi = unf if series == "UNF" else unc
    if tpi == unc:
        found = "UNC"
    elif tpi == unf:
        found = "UNF"
    else:
        raise InputOutOfRange(
            f"{field}: {size}-{tpi} is not a UNC or UNF thread (allowed: {size}-{unc} UNC, "
            f"{size}-{unf} UNF)",
            field=field,
        )
    if series is not None and series != found:
        raise InputOutOfRange(
            f"{field}: {size}-{tpi} is {found}, not {series}",
            field=field,
        )
    d, p = major * INCH, INCH / tpi
    return Thread(
        designation=f"{size}-{tpi} {found}",
        series=found,
        diameter=d,
        pitch=p,
        pitch_diameter=unified_pitch_diameter(d, p),
        minor_diameter=d - 1.299038 * p,
        nut_minor_diameter=d - 1.082532 * p,
        stress_area=unified_stress_area(d, p),
        size=size,
    )


def all_threads() -> list[Thread]:
    """Every thread of the catalogue: metric coarse and fine, then UNC and UNF."""
    out: list[Thread] = []
    for d_mm, coarse in METRIC_COARSE_PITCH_MM.items():
        out.append(metric_thread(d_mm, coarse))
        out.extend(metric_thread(d_mm, p) for p in METRIC_FINE_PITCHES_MM.get(d_mm, ()))
    for size, (_, unc, unf) in UNIFIED_SIZES.items():
        out.append(unified_thread(size, unc))
        out.append(unified_thread(size, unf))
    return out


#: ISO 273 clearance holes [mm] (fine, medium, coarse) beyond the M3…M39 of engine.physics.threads.
CLEARANCE_HOLE_MM: dict[float, tuple[float, float, float]] = {
    1.6: (1.7, 1.8, 2.0),
    2.0: (2.2, 2.4, 2.6),
    2.5: (2.7, 2.9, 3.1),
    **th.CLEARANCE_HOLE_MM,
    42.0: (43.0, 45.0, 48.0),
    45.0: (46.0, 48.0, 52.0),
    48.0: (50.0, 52.0, 56.0),
    52.0: (54.0, 56.0, 62.0),
    56.0: (58.0, 62.0, 66.0),
    60.0: (62.0, 66.0, 70.0),
    64.0: (66.0, 70.0, 74.0),
}


def clearance_hole(thread: Thread, series: str = "medium") -> float:
    """Clearance hole d_h [m]: ISO 273 (metric) or ASME B18.2.8 normal fit (inch).

    >>> round(clearance_hole(metric_thread(64)) * 1e3, 1)
    70.0
    >>> round(clearance_hole(unified_thread("1/2")) / INCH, 3)
    0.531
    """
    if not thread.is_metric:
        return UNIFIED_CLEARANCE_IN[thread.size] * INCH
    if series not in th.HOLE_SERIES:
        raise InputOutOfRange(
            f"hole_series = {series!r} is not allowed: must be one of {', '.join(th.HOLE_SERIES)}",
            field="hole_series",
        )
    return CLEARANCE_HOLE_MM[float(thread.size)][th.HOLE_SERIES.index(series)] * 1e-3


# --------------------------------------------------------------------------- grades


@dataclass(frozen=True)
class Grade:
    """Minimum strengths of a bolt grade [Pa] over a diameter range [m]."""

    name: str
    standard: str
    yield_strength: float
    tensile_strength: float
    #: Proof stress S_p (ISO 898-1 Table 3, SAE J429) or None where the standard has none.
    proof_stress: float | None
    min_diameter: float
    max_diameter: float
    material: str  # "steel", "stainless"
    yield_kind: str = "R_p0.2"

    def describe(self) -> dict[str, object]:
        return {
            "name": self.name,
            "standard": self.standard,
            "yield_strength": self.yield_strength,
            "tensile_strength": self.tensile_strength,
            "proof_stress": self.proof_stress,
            "min_diameter": self.min_diameter,
            "max_diameter": self.max_diameter,
            "material": self.material,
        }


#: ISO 898-1:2013 Table 3 proof stress S_p,nom [MPa]: (up to the size step, above it).
ISO898_PROOF_STRESS_MPA: dict[str, tuple[float, float]] = {
    "4.6": (225.0, 225.0),
    "4.8": (310.0, 310.0),
    "5.6": (280.0, 280.0),
    "5.8": (380.0, 380.0),
    "6.8": (440.0, 440.0),
    "8.8": (580.0, 600.0),
    "9.8": (650.0, 650.0),
    "10.9": (830.0, 830.0),
    "12.9": (970.0, 970.0),
}


def _iso898_grades() -> list[Grade]:
    out: list[Grade] = []
    for name, cls in th.PROPERTY_CLASSES.items():
        sp_small, sp_large = ISO898_PROOF_STRESS_MPA[name]
        step = cls.size_step_mm if cls.size_step_mm < cls.max_diameter_mm else cls.max_diameter_mm
        out.append(
            Grade(
                name,
                "ISO 898-1",
                cls.yield_small * MPA,
                cls.tensile_small * MPA,
                sp_small * MPA,
                0.0,
                step * 1e-3,
                "steel",
                cls.yield_kind,
            )
        )
        if step < cls.max_diameter_mm:
            out.append(
                Grade(
                    name,
                    "ISO 898-1",
                    cls.yield_large * MPA,
                    cls.tensile_large * MPA,
                    sp_large * MPA,
                    step * 1e-3,
                    cls.max_diameter_mm * 1e-3,
                    "steel",
                    cls.yield_kind,
                )
            )
    return out


#: Every grade row; a name may have several rows (size steps).
GRADES: tuple[Grade, ...] = (
    *_iso898_grades(),
    # ISO 3506-1:2009 Table 3, austenitic A1…A5: -50 up to M39, -70 and -80 up to M24.
    Grade("A2-50", "ISO 3506-1", 210 * MPA, 500 * MPA, None, 0.0, 0.039, "stainless"),
    Grade("A4-50", "ISO 3506-1", 210 * MPA, 500 * MPA, None, 0.0, 0.039, "stainless"),
    Grade("A2-70", "ISO 3506-1", 450 * MPA, 700 * MPA, None, 0.0, 0.024, "stainless"),
    Grade("A4-70", "ISO 3506-1", 450 * MPA, 700 * MPA, None, 0.0, 0.024, "stainless"),
    Grade("A2-80", "ISO 3506-1", 600 * MPA, 800 * MPA, None, 0.0, 0.024, "stainless"),
    Grade("A4-80", "ISO 3506-1", 600 * MPA, 800 * MPA, None, 0.0, 0.024, "stainless"),
    # SAE J429: grade 2 1/4–3/4 and 7/8–1-1/2, grade 5 1/4–1 and 1-1/8–1-1/2, grade 8.
    Grade("SAE 2", "SAE J429", 57 * KSI, 74 * KSI, 55 * KSI, 0.25 * INCH, 0.75 * INCH, "steel"),
    Grade("SAE 2", "SAE J429", 36 * KSI, 60 * KSI, 33 * KSI, 0.75 * INCH, 1.5 * INCH, "steel"),
    Grade("SAE 5", "SAE J429", 92 * KSI, 120 * KSI, 85 * KSI, 0.25 * INCH, 1.0 * INCH, "steel"),
    Grade("SAE 5", "SAE J429", 81 * KSI, 105 * KSI, 74 * KSI, 1.0 * INCH, 1.5 * INCH, "steel"),
    Grade("SAE 8", "SAE J429", 130 * KSI, 150 * KSI, 120 * KSI, 0.25 * INCH, 1.5 * INCH, "steel"),
    # ASTM A193 grade B7 (quenched and tempered Cr-Mo), up to 2-1/2 in.
    Grade("B7", "ASTM A193", 105 * KSI, 125 * KSI, None, 0.0, 2.5 * INCH, "steel"),
)

GRADE_NAMES: tuple[str, ...] = tuple(dict.fromkeys(g.name for g in GRADES))

_GRADE_ALIASES: dict[str, str] = {
    "GRADE 2": "SAE 2",
    "GRADE 5": "SAE 5",
    "GRADE 8": "SAE 8",
    "GR 2": "SAE 2",
    "GR 5": "SAE 5",
    "GR 8": "SAE 8",
    "GR. 5": "SAE 5",
    "SAE J429 2": "SAE 2",
    "SAE J429 5": "SAE 5",
    "SAE J429 8": "SAE 8",
    "SAE GRADE 2": "SAE 2",
    "SAE GRADE 5": "SAE 5",
    "SAE GRADE 8": "SAE 8",
    "ASTM A193 B7": "B7",
    "A193 B7": "B7",
    "A193-B7": "B7",
}


def normalise_grade(text: str, *, field: str = "grade") -> str:
    """The catalogue name of a grade written as a user writes it ("Grade 5", "a2-70").

    >>> normalise_grade("grade 5"), normalise_grade("a4-80"), normalise_grade("12.9")
    ('SAE 5', 'A4-80', '12.9')
    """
    key = re.sub(r"\s+", " ", text.strip().upper())
    key = _GRADE_ALIASES.get(key, key)
    for name in GRADE_NAMES:
        if key == name.upper():
            return name
    raise InputOutOfRange(
        f"{field}: {text!r} is not a known grade (one of {', '.join(GRADE_NAMES)}; "
        "'Grade 5' and 'ASTM A193 B7' are accepted too)",
        field=field,
    )


def grade_strengths(name: str, diameter: float, *, field: str = "grade") -> Grade:
    """The row of grade ``name`` that holds for a bolt of diameter ``diameter`` [m].

    Raises InputOutOfRange (``field``) when the standard does not define the
    grade at that size.

    Examples
    --------
    >>> g = grade_strengths("A2-70", 0.012)
    >>> g.yield_strength / 1e6, g.tensile_strength / 1e6
    (450.0, 700.0)
    >>> round(grade_strengths("SAE 5", 0.5 * INCH).tensile_strength / 1e6, 1)
    827.4
    """
    name = normalise_grade(name, field=field)
    rows = [g for g in GRADES if g.name == name]
    tol = 1e-9
    for g in rows:
        if g.min_diameter * (1 - tol) <= diameter <= g.max_diameter * (1 + tol):
            return g
    lo = min(g.min_diameter for g in rows)
    hi = max(g.max_diameter for g in rows)
    raise InputOutOfRange(
        f"{field}: {name} ({rows[0].standard}) is defined for d = {lo * 1e3:g}…{hi * 1e3:.4g} mm, "
        f"not {diameter * 1e3:.4g} mm; give yield_strength",
        field=field,
    )


# --------------------------------------------------------------------------- heads


@dataclass(frozen=True)
class Head:
    """A head style at one size: bearing diameter, height and drive [m]."""

    standard: str
    style: str  # "hex", "socket", "flange", "countersunk"
    size: str
    bearing_diameter: float
    head_height: float
    drive: str  # "wrench" or "hex key"
    drive_size: float
    #: Countersunk heads: the head's cone angle [rad]; 0 for flat bearing faces.
    cone_angle: float = 0.0

    def describe(self) -> dict[str, object]:
        return {
            "standard": self.standard,
            "style": self.style,
            "size": self.size,
            "bearing_diameter": self.bearing_diameter,
            "head_height": self.head_height,
            "drive": self.drive,
            "drive_size": self.drive_size,
            "cone_angle": self.cone_angle,
        }


#: ISO 4017 (A up to M24, B above) / ISO 4014: s, k (nominal) and d_w,min [mm].
HEX_HEAD_MM: dict[float, tuple[float, float, float]] = {
    1.6: (3.2, 1.1, 2.27),
    2.0: (4.0, 1.4, 3.07),
    2.5: (5.0, 1.7, 4.07),
    3.0: (5.5, 2.0, 4.57),
    3.5: (6.0, 2.4, 5.07),
    4.0: (7.0, 2.8, 5.88),
    5.0: (8.0, 3.5, 6.88),
    6.0: (10.0, 4.0, 8.88),
    8.0: (13.0, 5.3, 11.63),
    10.0: (16.0, 6.4, 14.63),
    12.0: (18.0, 7.5, 16.63),
    14.0: (21.0, 8.8, 19.64),
    16.0: (24.0, 10.0, 22.49),
    18.0: (27.0, 11.5, 25.34),
    20.0: (30.0, 12.5, 28.19),
    22.0: (34.0, 14.0, 31.71),
    24.0: (36.0, 15.0, 33.61),
    27.0: (41.0, 17.0, 38.0),
    30.0: (46.0, 18.7, 42.75),
    33.0: (50.0, 21.0, 46.55),
    36.0: (55.0, 22.5, 51.11),
    39.0: (60.0, 25.0, 55.86),
    42.0: (65.0, 26.0, 59.95),
    45.0: (70.0, 28.0, 64.7),
    48.0: (75.0, 30.0, 69.45),
    52.0: (80.0, 33.0, 74.2),
    56.0: (85.0, 35.0, 78.66),
    60.0: (90.0, 38.0, 83.41),
    64.0: (95.0, 40.0, 88.16),
}

#: ISO 4762 hexagon socket head cap screws: hex key s, head height k = d, d_w,min [mm].
SOCKET_HEAD_MM: dict[float, tuple[float, float, float]] = {
    1.6: (1.5, 1.6, 2.72),
    2.0: (1.5, 2.0, 3.48),
    2.5: (2.0, 2.5, 4.18),
    3.0: (2.5, 3.0, 5.07),
    4.0: (3.0, 4.0, 6.53),
    5.0: (4.0, 5.0, 8.03),
    6.0: (5.0, 6.0, 9.38),
    8.0: (6.0, 8.0, 12.33),
    10.0: (8.0, 10.0, 15.33),
    12.0: (10.0, 12.0, 17.23),
    14.0: (12.0, 14.0, 20.17),
    16.0: (14.0, 16.0, 23.17),
    20.0: (17.0, 20.0, 28.87),
    24.0: (19.0, 24.0, 34.81),
    30.0: (22.0, 30.0, 43.61),
    36.0: (27.0, 36.0, 52.54),
    42.0: (32.0, 42.0, 61.34),
    48.0: (36.0, 48.0, 70.34),
    56.0: (41.0, 56.0, 82.26),
    64.0: (46.0, 64.0, 94.26),
}

#: EN 1665 hexagon bolts with flange: s, k,max, d_w,min [mm] (M5…M20).
FLANGE_HEAD_MM: dict[float, tuple[float, float, float]] = {
    5.0: (8.0, 5.8, 9.8),
    6.0: (10.0, 6.6, 12.2),
    8.0: (13.0, 8.1, 15.8),
    10.0: (16.0, 10.4, 19.6),
    12.0: (18.0, 11.8, 23.8),
    14.0: (21.0, 13.7, 27.6),
    16.0: (24.0, 15.4, 31.9),
    20.0: (30.0, 18.9, 39.9),
}

#: ISO 10642 countersunk socket screws (90° head): hex key s, k,max, d_k,min (actual) [mm].
COUNTERSUNK_HEAD_MM: dict[float, tuple[float, float, float]] = {
    3.0: (2.0, 1.86, 5.54),
    4.0: (2.5, 2.48, 7.53),
    5.0: (3.0, 3.1, 9.43),
    6.0: (4.0, 3.72, 11.34),
    8.0: (5.0, 4.96, 15.24),
    10.0: (6.0, 6.2, 19.22),
    12.0: (8.0, 7.44, 23.12),
    16.0: (10.0, 8.8, 29.01),
    20.0: (12.0, 10.16, 36.05),
}

#: ISO 2936 hexagon socket screw keys: minimum test torque [N·m] per key size s [mm].
HEX_KEY_TORQUE_NM: dict[float, float] = {
    1.5: 0.82,
    2.0: 1.9,
    2.5: 3.8,
    3.0: 6.6,
    4.0: 16.0,
    5.0: 30.0,
    6.0: 52.0,
    8.0: 120.0,
    10.0: 220.0,
    12.0: 370.0,
    14.0: 590.0,
    17.0: 980.0,
    19.0: 1360.0,
    22.0: 2110.0,
    24.0: 2750.0,
    27.0: 3910.0,
}

#: Head standards by name: (style, table, drive).
HEAD_STANDARDS: dict[str, tuple[str, dict[float, tuple[float, float, float]], str]] = {
    "ISO 4017": ("hex", HEX_HEAD_MM, "wrench"),
    "ISO 4014": ("hex", HEX_HEAD_MM, "wrench"),
    "ISO 4762": ("socket", SOCKET_HEAD_MM, "hex key"),
    "EN 1665": ("flange", FLANGE_HEAD_MM, "wrench"),
    "ISO 10642": ("countersunk", COUNTERSUNK_HEAD_MM, "hex key"),
}
HEAD_NAMES: tuple[str, ...] = tuple(HEAD_STANDARDS)
#: The bearing-face style of an inch hex cap screw (ASME B18.2.1).
UNIFIED_HEX = "ASME B18.2.1"


def head(standard: str, thread: Thread, *, field: str = "head") -> Head:
    """The head of ``standard`` for ``thread``'s size.

    Examples
    --------
    >>> h = head("ISO 4762", metric_thread(8))
    >>> round(h.bearing_diameter * 1e3, 2), round(h.drive_size * 1e3, 1)
    (12.33, 6.0)
    """
    if not thread.is_metric:
        if standard not in (UNIFIED_HEX, "hex"):
            raise InputOutOfRange(
                f"{field}: the catalogue has only hex cap screws ({UNIFIED_HEX}) for inch "
                f"threads, not {standard}; give bearing_outer_diameter",
                field=field,
            )
        flats = UNIFIED_HEX_FLATS_IN[thread.size]
        return Head(
            UNIFIED_HEX,
            "hex",
            thread.size,
            0.95 * flats * INCH,
            UNIFIED_HEX_HEIGHT_IN[thread.size] * INCH,
            "wrench",
            flats * INCH,
        )
    if standard not in HEAD_STANDARDS:
        raise InputOutOfRange(
            f"{field}: {standard!r} is not a head standard of the catalogue "
            f"(one of {', '.join(HEAD_NAMES)})",
            field=field,
        )
    style, table, drive = HEAD_STANDARDS[standard]
    key = float(thread.size)
    if key not in table:
        raise InputOutOfRange(
            f"{field}: {standard} has no M{thread.size} in the catalogue (sizes "
            f"{', '.join('M' + _fmt(k) for k in table)}); give bearing_outer_diameter",
            field=field,
        )
    s, k, dw = table[key]
    return Head(
        standard,
        style,
        thread.size,
        dw * 1e-3,
        k * 1e-3,
        drive,
        s * 1e-3,
        math.pi / 2 if style == "countersunk" else 0.0,
    )


def hex_key_torque(key_size: float) -> float | None:
    """ISO 2936 minimum test torque [N·m] of a hex key of size ``key_size`` [m], or None.

    >>> hex_key_torque(0.006)
    52.0
    """
    mm = round(key_size * 1e3, 3)
    return HEX_KEY_TORQUE_NM.get(mm)


def countersunk_friction_factor(cone_angle: float = math.pi / 2) -> float:
    r"""Factor on μ_K for a head bearing on a cone of included angle ``cone_angle``.

    .. math::
        \mu_K' = \frac{\mu_K}{\sin(\alpha/2)}

    The axial force F is the axial component of the normal force on the cone,
    F = N sin(α/2), so the friction force is μ_K F / sin(α/2); its radius is
    that of the projected annulus. 1.414 for the 90° head of ISO 10642.

    Parameters
    ----------
    cone_angle : float
        Included angle α of the countersink, [rad]

    Returns
    -------
    float
        1/sin(α/2), [-]

    Examples
    --------
    >>> round(countersunk_friction_factor(), 4)
    1.4142
    """
    return 1.0 / math.sin(0.5 * cone_angle)


# --------------------------------------------------------------------------- nuts, washers


@dataclass(frozen=True)
class Nut:
    standard: str
    style: str
    size: str
    height: float
    width_across_flats: float
    bearing_diameter: float
    property_classes: tuple[str, ...]

    def describe(self) -> dict[str, object]:
        return {
            "standard": self.standard,
            "style": self.style,
            "size": self.size,
            "height": self.height,
            "width_across_flats": self.width_across_flats,
            "bearing_diameter": self.bearing_diameter,
            "property_classes": list(self.property_classes),
        }


#: Nut heights m,max [mm]: ISO 4032 (style 1), ISO 4033 (style 2), ISO 4035 (thin, chamfered).
NUT_HEIGHT_MM: dict[str, dict[float, float]] = {
    "ISO 4032": {
        1.6: 1.3,
        2.0: 1.6,
        2.5: 2.0,
        3.0: 2.4,
        4.0: 3.2,
        5.0: 4.7,
        6.0: 5.2,
        8.0: 6.8,
        10.0: 8.4,
        12.0: 10.8,
        14.0: 12.8,
        16.0: 14.8,
        20.0: 18.0,
        24.0: 21.5,
        30.0: 25.6,
        36.0: 31.0,
        42.0: 34.0,
        48.0: 38.0,
        56.0: 45.0,
        64.0: 51.0,
    },
    "ISO 4033": {
        5.0: 5.1,
        6.0: 5.7,
        8.0: 7.5,
        10.0: 9.3,
        12.0: 12.0,
        14.0: 14.1,
        16.0: 16.4,
        20.0: 20.3,
        24.0: 23.9,
        30.0: 28.6,
        36.0: 34.7,
    },
    "ISO 4035": {
        1.6: 1.0,
        2.0: 1.2,
        2.5: 1.6,
        3.0: 1.8,
        4.0: 2.2,
        5.0: 2.7,
        6.0: 3.2,
        8.0: 4.0,
        10.0: 5.0,
        12.0: 6.0,
        14.0: 7.0,
        16.0: 8.0,
        20.0: 10.0,
        24.0: 12.0,
        30.0: 15.0,
        36.0: 18.0,
        42.0: 21.0,
        48.0: 24.0,
        56.0: 28.0,
        64.0: 32.0,
    },
}

#: ISO 898-2 property classes each nut standard is made in (04/05: thin nuts, reduced loadability).
NUT_CLASSES: dict[str, tuple[str, tuple[str, ...]]] = {
    "ISO 4032": ("style 1", ("6", "8", "10")),
    "ISO 4033": ("style 2", ("9", "10", "12")),
    "ISO 4035": ("thin", ("04", "05")),
}


def nut(standard: str, thread: Thread, *, field: str = "nut") -> Nut:
    """The hexagon nut of ``standard`` for a metric ``thread``.

    The bearing diameter is the hexagon head's d_w,min of ISO 4017 (ISO 4032
    nuts of the same width across flats have d_w,min within 0.1 mm of it).

    >>> n = nut("ISO 4032", metric_thread(12))
    >>> round(n.height * 1e3, 1), n.property_classes
    (10.8, ('6', '8', '10'))
    """
    if standard not in NUT_HEIGHT_MM:
        raise InputOutOfRange(
            f"{field}: {standard!r} is not a nut standard of the catalogue "
            f"(one of {', '.join(NUT_HEIGHT_MM)})",
            field=field,
        )
    key = float(thread.size) if thread.is_metric else -1.0
    if key not in NUT_HEIGHT_MM[standard]:
        raise InputOutOfRange(
            f"{field}: {standard} has no nut for {thread.designation} in the catalogue",
            field=field,
        )
    s, _, dw = HEX_HEAD_MM[key]
    style, classes = NUT_CLASSES[standard]
    return Nut(
        standard,
        style,
        thread.size,
        NUT_HEIGHT_MM[standard][key] * 1e-3,
        s * 1e-3,
        dw * 1e-3,
        classes,
    )


#: ISO 898-2:1992 (EN 20898-2) stress under proof load S_p [MPa] of nuts with coarse thread,
#: by property class (12 by style: "12" style 1, ISO 4032; "12/2" style 2, ISO 4033) and
#: thread range: (d ≤ 4, 4 < d ≤ 7, 7 < d ≤ 10, 10 < d ≤ 16, 16 < d ≤ 39) mm. Class 4
#: exists above M16 only (None below). Thin nuts 04/05 (ISO 4035) carry 380/500 MPa at
#: every size: their loadability is reduced, they strip before a bolt of any class breaks.
NUT_PROOF_STRESS_MPA: dict[str, tuple[float | None, ...]] = {
    "04": (380.0, 380.0, 380.0, 380.0, 380.0),
    "05": (500.0, 500.0, 500.0, 500.0, 500.0),
    "4": (None, None, None, None, 510.0),
    "5": (520.0, 580.0, 590.0, 610.0, 630.0),
    "6": (600.0, 670.0, 680.0, 700.0, 720.0),
    "8": (800.0, 855.0, 870.0, 880.0, 920.0),
    "9": (900.0, 915.0, 940.0, 950.0, 920.0),
    "10": (1040.0, 1040.0, 1040.0, 1050.0, 1060.0),
    "12": (1140.0, 1140.0, 1140.0, 1170.0, None),
    "12/2": (1150.0, 1150.0, 1160.0, 1190.0, 1200.0),
}

#: Upper ends of the thread ranges of :data:`NUT_PROOF_STRESS_MPA`, [m].
NUT_PROOF_RANGES_M: tuple[float, ...] = (0.004, 0.007, 0.010, 0.016, 0.039)

#: The nut property classes a request may name (ISO 898-2).
NUT_PROPERTY_CLASSES: tuple[str, ...] = ("04", "05", "4", "5", "6", "8", "9", "10", "12")


def nut_proof_stress(property_class: str, diameter: Any, style: str = "style 1") -> Any:
    r"""Stress under proof load S_p of a steel nut (ISO 898-2:1992, coarse thread).

    .. math::
        S_p = S_p(\text{class}, \text{style}, d)

    Parameters
    ----------
    property_class : str
        Nut property class, "04", "05", "4" … "12", [-]
    diameter : float or numpy array
        Nominal thread diameter d, [m]
    style : str
        "style 1" (ISO 4032), "style 2" (ISO 4033) or "thin" (ISO 4035); only class 12
        differs between styles, [-]

    Returns
    -------
    float or numpy array
        S_p, [Pa]; NaN outside M3…M39 or where the class is not made at that size

    Notes
    -----
    ISO 898-2:1992 Table of proof load stresses as reproduced by Bossard (technical
    information, "Nuts property classes 04 to 12") and DIN EN 20898-2 (proof loads
    S_p × A_s): [EN20898-2].

    Examples
    --------
    >>> nut_proof_stress("8", 0.012) / 1e6, nut_proof_stress("04", 0.012) / 1e6
    (880.0, 380.0)
    >>> nut_proof_stress("12", 0.012, "style 2") / 1e6
    1190.0
    """
    key = "12/2" if property_class == "12" and style == "style 2" else property_class
    if not isinstance(diameter, np.ndarray):  # one design: plain float arithmetic
        one = float(diameter)
        if one >= 0.003 * (1 - 1e-9):
            for top, value in zip(NUT_PROOF_RANGES_M, NUT_PROOF_STRESS_MPA[key], strict=True):
                if one <= top * (1 + 1e-9):
                    return math.nan if value is None else value * 1e6
        return math.nan
    row = np.array([np.nan if v is None else v * 1e6 for v in NUT_PROOF_STRESS_MPA[key]])
    d = np.asarray(diameter, dtype=float)
    where = np.searchsorted(np.array(NUT_PROOF_RANGES_M) * (1 + 1e-9), d)
    inside = (d >= 0.003 * (1 - 1e-9)) & (where < row.size)
    return np.where(inside, row[np.minimum(where, row.size - 1)], np.nan)


def nut_proof_load(
    property_class: str, diameter: Any, stress_area: Any, style: str = "style 1"
) -> Any:
    r"""Proof load of a steel nut: the axial force it carries on a hardened mandrel.

    .. math::
        F_{p,M} = S_p A_s

    Parameters
    ----------
    property_class : str
        Nut property class, [-]
    diameter : float or numpy array
        d, [m]
    stress_area : float or numpy array
        A_s of the mating thread, [m²]
    style : str
        Nut style (see :func:`nut_proof_stress`), [-]

    Returns
    -------
    float or numpy array
        F_p,M, [N]; NaN where ISO 898-2 gives no S_p

    Notes
    -----
    ISO 898-2:1992 clause 8 (proof load = S_p × A_s,nom) [EN20898-2]; DIN EN 20898-2 prints
    74 200 N for an M12 class 8 nut (880 MPa × 84.3 mm²).

    Examples
    --------
    >>> round(nut_proof_load("8", 0.012, 84.3e-6))
    74184
    >>> round(nut_proof_load("04", 0.012, 84.3e-6)), round(nut_proof_load("05", 0.012, 84.3e-6))
    (32034, 42150)
    """
    return nut_proof_stress(property_class, diameter, style) * stress_area


def nut_pairs_with_bolt(property_class: str, bolt_tensile_strength: float) -> bool:
    r"""Whether a nut class may be mated with a bolt of tensile strength R_m.

    .. math::
        100\,N \ge R_{m,nom}\ \text{(bolt)},\quad \text{not a thin nut (04, 05)}

    Parameters
    ----------
    property_class : str
        Nut property class N ("8" for a nut of class 8), [-]
    bolt_tensile_strength : float
        R_m of the bolt (its minimum; the class number is R_m,nom/100), [Pa]

    Returns
    -------
    bool

    Notes
    -----
    ISO 898-2:1992 clause 3 and Table 1 [EN20898-2]: a nut of class N is mated with bolts
    of property class up to N.x (8 with 8.8, 10 with 10.9, 12 with 12.9) so that the bolt
    breaks before the threads strip; thin nuts (04, 05) have reduced loadability and pair
    with no class to its full strength.

    Examples
    --------
    >>> nut_pairs_with_bolt("8", 800e6), nut_pairs_with_bolt("8", 1040e6)
    (True, False)
    >>> nut_pairs_with_bolt("05", 400e6)
    False
    """
    if property_class.startswith("0"):
        return False
    return int(property_class) * 100 >= math.floor(bolt_tensile_strength / 1e8 + 1e-9) * 100


@dataclass(frozen=True)
class NutChoice:
    """The nut of a through-bolted joint as ISO 898-2 rates it."""

    standard: str
    style: str
    property_class: str
    #: Whether the request named the class (False: :func:`nut_choice` assumed it).
    given: bool
    #: Whether the class pairs with the bolt's; None where the bolt's R_m is unknown.
    pairs: bool | None


def nut_choice(
    standard: str, property_class: str | None, bolt_tensile_strength: float | None
) -> NutChoice:
    r"""The class of a nut of ``standard``: as given, else the lowest it is made in that
    pairs with the bolt, else the weakest it is made in (the safe side: a stronger nut is
    named by its class).

    .. math::
        N = \min\{N \in \text{classes}(\text{standard}) : 100\,N \ge R_{m,nom}\}

    Parameters
    ----------
    standard : str
        Nut standard, "ISO 4032", "ISO 4033" or "ISO 4035", [-]
    property_class : str or None
        Class as the request names it; None: chosen here, [-]
    bolt_tensile_strength : float or None
        R_m of the bolt; None where unknown (a typed yield strength), [Pa]

    Returns
    -------
    NutChoice

    Notes
    -----
    ISO 898-2:1992 clause 3 and Table 1 [EN20898-2] (pairing, :func:`nut_pairs_with_bolt`);
    the classes each standard is made in are :data:`NUT_CLASSES` ([ISO4032], [ISO4033],
    [ISO4035]). One definition for every model that takes ``nut``.

    Examples
    --------
    >>> nut_choice("ISO 4032", None, 1040e6).property_class   # a 10.9 bolt
    '10'
    >>> c = nut_choice("ISO 4035", None, 1220e6)               # thin nuts pair with none
    >>> c.property_class, c.pairs, c.given
    ('04', False, False)
    """
    style, made = NUT_CLASSES[standard]
    given = property_class is not None
    if property_class is not None:
        cls = property_class
    elif bolt_tensile_strength is not None:
        paired = [c for c in made if nut_pairs_with_bolt(c, bolt_tensile_strength)]
        cls = paired[0] if paired else made[0]
    else:
        cls = made[0]
    pairs = (
        None if bolt_tensile_strength is None else nut_pairs_with_bolt(cls, bolt_tensile_strength)
    )
    return NutChoice(standard, style, cls, given, pairs)


def nut_limited_preload(bolt_preload: Any, nut_proof_load: Any) -> Any:
    r"""The permissible assembly preload F_M,zul held at the nut's proof load.

    .. math::
        F_{M,zul} = \min(F_{M,zul,S},\ F_{p,M})

    Parameters
    ----------
    bolt_preload : float or numpy array
        F_M,zul of the bolt (VDI 2230-1 R7), [N]
    nut_proof_load : float or numpy array
        F_p,M = S_p A_s of the nut (:func:`nut_proof_load`); NaN where ISO 898-2 gives
        none: the bolt's preload stands, [N]

    Returns
    -------
    float or numpy array
        F_M,zul, [N]

    Notes
    -----
    ISO 898-2:1992 [EN20898-2]: the nut carries its proof load without stripping or
    breaking; above it the nut, not the bolt, limits the joint (a thin nut, or a class
    weaker than the bolt's). All arguments may be floats or numpy arrays of one shape.

    Examples
    --------
    M12 12.9 (F_M,zul 74.1 kN) with a class 04 thin nut (380 MPa × 84.27 mm²):

    >>> round(nut_limited_preload(74.1e3, 380e6 * 84.27e-6))
    32023
    >>> nut_limited_preload(74.1e3, float("nan"))
    74100.0
    """
    if isinstance(bolt_preload, np.ndarray) or isinstance(nut_proof_load, np.ndarray):
        return np.where(nut_proof_load < bolt_preload, nut_proof_load, bolt_preload)
    return nut_proof_load if nut_proof_load < bolt_preload else bolt_preload


#: Shear strength over tensile strength of steel threads, τ_B/R_m (FED-STD-H28 practice);
#: the bolt thread's τ_BS and a steel nut thread's τ_BM (VDI 2230-1 R11).
STEEL_SHEAR_RATIO = 0.6


def nut_thread_strip_force(
    diameter: Any,
    pitch: Any,
    pitch_diameter: Any,
    nut_height: float,
    width_across_flats: float,
    nut_proof_stress: Any,
    bolt_tensile_strength: Any,
) -> Any:
    r"""Force at which a steel nut's internal thread shears off at its root (VDI 2230-1 R11).

    .. math::
        F_{SM} = C_1 C_3\,\tau_{BM} A_{SGM},\qquad
        A_{SGM} = \pi d\,(m - 2P)\,\frac{P/2 + (d - D_2)\tan 30°}{P},\qquad
        \tau_{BM} = 0.6\,S_p

    Parameters
    ----------
    diameter, pitch, pitch_diameter : float or numpy array
        d, P, d2 (= D2 basic), [m]
    nut_height : float
        m of the nut (ISO 4032/4033/4035), chamfers included, [m]
    width_across_flats : float
        s of the nut (its dilation factor C1), [m]
    nut_proof_stress : float or numpy array
        S_p of the nut's class (ISO 898-2), taken as the nut material's R_m,M, [Pa]
    bolt_tensile_strength : float or numpy array
        R_m of the bolt: τ_BS = 0.6 R_m enters the strength ratio R_S and C3, [Pa]

    Returns
    -------
    float or numpy array
        F_SM, [N]

    Notes
    -----
    VDI 2230-1 R11 after Alexander as its open implementation [BAT-R11] states it (shear
    area at d, dilation factor C1 for 1.4 ≤ s/d ≤ 1.9, thread-bending factor C3(R_S), the
    length of full threads m − 2P, the 2P for the entry chamfers) with τ_BM = 0.6 R_m,M
    [FED-STD-H28]. The nut material's R_m,M is taken as its proof stress S_p, the least
    stress ISO 898-2 [EN20898-2] certifies it for: a lower bound, so F_SM errs low. Of use
    where the nut does not pair with the bolt (a thin nut, a weaker class); a paired full
    nut is made so that the bolt breaks first (ISO 898-2 clause 3). All numeric arguments
    may be numpy arrays.

    Examples
    --------
    M12 with an ISO 4035 thin nut (m 6 mm, s 18 mm), class 04 (S_p 380 MPa), 12.9 bolt:

    >>> round(nut_thread_strip_force(0.012, 0.00175, 0.0108633, 0.006, 0.018, 380e6, 1220e6))
    16682
    """
    full: Any = nut_height - ENTRY_CHAMFER_PITCHES * pitch
    full = np.maximum(full, 0.0) if isinstance(full, np.ndarray) else max(full, 0.0)
    s = thread_stripping(
        diameter,
        pitch,
        pitch_diameter,
        diameter - 1.082532 * pitch,
        1.0,
        1.0,
        STEEL_SHEAR_RATIO * bolt_tensile_strength,
        STEEL_SHEAR_RATIO * nut_proof_stress,
        full,
        width_across_flats=width_across_flats,
    )
    return s.internal_strip_force


def nut_thread_resistance(
    diameter: Any,
    pitch: Any,
    pitch_diameter: Any,
    part: Nut,
    choice: NutChoice,
    proof_load: Any,
    bolt_tensile_strength: Any,
) -> Any:
    r"""The force a rated steel nut's thread holds: R11's estimate, not below its proof load.

    .. math::
        F_{SM,nut} = \max\left(F_{SM}(\tau_{BM} = 0.6\,S_p,\ m - 2P),\ F_p = S_p A_s\right)

    Parameters
    ----------
    diameter, pitch, pitch_diameter : float or numpy array
        d, P, d2 of the thread, [m]
    part : Nut
        The nut's dimensions (height m, width across flats s), [-]
    choice : NutChoice
        Its class and style (:func:`nut_choice`), [-]
    proof_load : float or numpy array
        F_p of that class and size (:func:`nut_proof_load`), [N]
    bolt_tensile_strength : float or numpy array
        R_m of the bolt, [Pa]

    Returns
    -------
    float or numpy array
        F_SM,nut, [N]

    Notes
    -----
    ISO 898-2 [EN20898-2] loads every nut of a class to its proof load F_p = S_p A_s on a
    hardened test mandrel, and the nut must hold it without stripping: F_p is a certified
    floor of its thread's strength. R11 (:func:`nut_thread_strip_force`) with the nut
    material's R_m taken as S_p and 2P lost to the chamfers is a lower estimate: for an
    M12 ISO 4035 class 04 thin nut on a 12.9 bolt it gives 16.7 kN, half the 32.0 kN the
    standard certifies. The larger of the two is used. On a real bolt thread, softer than
    the mandrel, the nut may hold a few per cent less than F_p (thread bending); the preload
    is capped at F_p anyway (:func:`nut_limited_preload`).

    Examples
    --------
    M12, ISO 4035 class 04 (F_p = 380 MPa × 84.27 mm² = 32.02 kN), 12.9 bolt: the proof load
    governs.

    >>> part = Nut("ISO 4035", "thin", "M12", 0.006, 0.018, 0.0166, ("04", "05"))
    >>> choice = nut_choice("ISO 4035", "04", 1220e6)
    >>> round(nut_thread_resistance(0.012, 0.00175, 0.0108633, part, choice, 32022.0, 1220e6))
    32022
    """
    estimate = nut_thread_strip_force(
        diameter,
        pitch,
        pitch_diameter,
        part.height,
        part.width_across_flats,
        nut_proof_stress(choice.property_class, diameter, choice.style),
        bolt_tensile_strength,
    )
    if isinstance(estimate, np.ndarray) or isinstance(proof_load, np.ndarray):
        return np.maximum(estimate, proof_load)
    return max(float(estimate), float(proof_load))


@dataclass(frozen=True)
class Washer:
    standard: str
    size: str
    inner_diameter: float
    outer_diameter: float
    thickness: float

    def describe(self) -> dict[str, object]:
        return {
            "standard": self.standard,
            "size": self.size,
            "inner_diameter": self.inner_diameter,
            "outer_diameter": self.outer_diameter,
            "thickness": self.thickness,
        }


#: Plain washers d1 (min), d2 (max), h (nominal) [mm]: ISO 7089 normal, ISO 7092 small,
#: ISO 7093-1 large series.
WASHER_MM: dict[str, dict[float, tuple[float, float, float]]] = {
    "ISO 7089": {
        1.6: (1.7, 4.0, 0.3),
        2.0: (2.2, 5.0, 0.3),
        2.5: (2.7, 6.0, 0.5),
        3.0: (3.2, 7.0, 0.5),
        4.0: (4.3, 9.0, 0.8),
        5.0: (5.3, 10.0, 1.0),
        6.0: (6.4, 12.0, 1.6),
        8.0: (8.4, 16.0, 1.6),
        10.0: (10.5, 20.0, 2.0),
        12.0: (13.0, 24.0, 2.5),
        14.0: (15.0, 28.0, 2.5),
        16.0: (17.0, 30.0, 3.0),
        20.0: (21.0, 37.0, 3.0),
        24.0: (25.0, 44.0, 4.0),
        30.0: (31.0, 56.0, 4.0),
        36.0: (37.0, 66.0, 5.0),
        42.0: (45.0, 78.0, 8.0),
        48.0: (52.0, 92.0, 8.0),
        56.0: (62.0, 105.0, 10.0),
        64.0: (70.0, 115.0, 10.0),
    },
    "ISO 7092": {
        1.6: (1.7, 3.5, 0.3),
        2.0: (2.2, 4.5, 0.3),
        2.5: (2.7, 5.0, 0.5),
        3.0: (3.2, 6.0, 0.5),
        4.0: (4.3, 8.0, 0.5),
        5.0: (5.3, 9.0, 1.0),
        6.0: (6.4, 11.0, 1.6),
        8.0: (8.4, 15.0, 1.6),
        10.0: (10.5, 18.0, 1.6),
        12.0: (13.0, 20.0, 2.0),
        14.0: (15.0, 24.0, 2.5),
        16.0: (17.0, 28.0, 2.5),
        20.0: (21.0, 34.0, 3.0),
        24.0: (25.0, 39.0, 4.0),
        30.0: (31.0, 50.0, 4.0),
        36.0: (37.0, 60.0, 5.0),
    },
    "ISO 7093": {
        3.0: (3.2, 9.0, 0.8),
        4.0: (4.3, 12.0, 1.0),
        5.0: (5.3, 15.0, 1.2),
        6.0: (6.4, 18.0, 1.6),
        8.0: (8.4, 24.0, 2.0),
        10.0: (10.5, 30.0, 2.5),
        12.0: (13.0, 37.0, 3.0),
        14.0: (15.0, 44.0, 3.0),
        16.0: (17.0, 50.0, 3.0),
        20.0: (22.0, 60.0, 4.0),
        24.0: (26.0, 72.0, 5.0),
        30.0: (33.0, 92.0, 6.0),
        36.0: (39.0, 110.0, 8.0),
    },
}
WASHER_NAMES: tuple[str, ...] = tuple(WASHER_MM)


def washer(standard: str, thread: Thread, *, field: str = "washer") -> Washer:
    """The plain washer of ``standard`` for a metric ``thread``.

    >>> w = washer("ISO 7089", metric_thread(8))
    >>> round(w.outer_diameter * 1e3, 1), round(w.thickness * 1e3, 1)
    (16.0, 1.6)
    """
    if standard not in WASHER_MM:
        raise InputOutOfRange(
            f"{field}: {standard!r} is not a washer standard of the catalogue "
            f"(one of {', '.join(WASHER_NAMES)})",
            field=field,
        )
    key = float(thread.size) if thread.is_metric else -1.0
    if key not in WASHER_MM[standard]:
        raise InputOutOfRange(
            f"{field}: {standard} has no washer for {thread.designation} in the catalogue",
            field=field,
        )
    d1, d2, h = WASHER_MM[standard][key]
    return Washer(standard, thread.size, d1 * 1e-3, d2 * 1e-3, h * 1e-3)


# --------------------------------------------------------------------------- materials


@dataclass(frozen=True)
class Material:
    """A clamped or internal-thread material [Pa]."""

    name: str
    kind: str  # "steel", "cast iron", "aluminium", "titanium", "magnesium", "plastic"
    limiting_surface_pressure: float
    tensile_strength: float
    shear_strength: float
    source: str

    def describe(self) -> dict[str, object]:
        return {
            "name": self.name,
            "kind": self.kind,
            "limiting_surface_pressure": self.limiting_surface_pressure,
            "tensile_strength": self.tensile_strength,
            "shear_strength": self.shear_strength,
            "source": self.source,
        }


_A9 = "p_G: VDI 2230-1 Table A9; R_m: material standard minimum"


def _m(
    name: str, kind: str, p_g: float, r_m: float, tau_ratio: float, source: str = _A9
) -> Material:
    return Material(name, kind, p_g * MPA, r_m * MPA, tau_ratio * r_m * MPA, source)


#: Clamped / tapped materials. τ_B = 0.6 R_m for wrought metals, 1.1 R_m for grey cast
#: iron (EN 1561 informative annex), 0.9 R_m for nodular iron (EN 1563), 0.6 for plastics.
MATERIALS: dict[str, Material] = {
    m.name: m
    for m in (
        _m("S235JR", "steel", 490, 360, 0.6),
        _m("E295", "steel", 710, 470, 0.6),
        _m("C45 (normalised)", "steel", 770, 620, 0.6),
        _m("42CrMo4 (QT)", "steel", 850, 900, 0.6),
        # 210: the aircraft-structures script's table (X5CrNiMo18-10, annealed); other
        # secondary quotes of VDI 2230 give up to 630 for cold-worked grades: conservative
        _m("X5CrNi18-10", "steel", 210, 500, 0.6, "p_G: lecture script Table 9.12 (conservative)"),
        _m("EN-GJL-250", "cast iron", 850, 250, 1.1),
        _m("EN-GJS-400", "cast iron", 600, 400, 0.9),
        _m("EN-GJS-500", "cast iron", 750, 500, 0.9),
        _m("EN AW-6082 T6", "aluminium", 360, 310, 0.6),
        _m("EN AW-7075 T6", "aluminium", 370, 540, 0.6),
        _m("EN AC-46000 (die cast)", "aluminium", 290, 240, 0.6),
        _m("EN AC-42100 T6", "aluminium", 380, 290, 0.6),
        _m("TiAl6V4", "titanium", 1000, 890, 0.6),
        _m("MgAl9Zn1 (die cast)", "magnesium", 220, 200, 0.6),
        _m(
            "PA66 (conditioned)",
            "plastic",
            60,
            60,
            0.6,
            "p_G: compressive yield, manufacturers' datasheets at 23 °C (no creep)",
        ),
        _m(
            "PA66 GF30 (conditioned)",
            "plastic",
            120,
            130,
            0.6,
            "p_G: compressive yield, manufacturers' datasheets at 23 °C (no creep)",
        ),
        _m(
            "POM",
            "plastic",
            80,
            65,
            0.6,
            "p_G: compressive yield, manufacturers' datasheets at 23 °C (no creep)",
        ),
        _m(
            "PC",
            "plastic",
            70,
            65,
            0.6,
            "p_G: compressive yield, manufacturers' datasheets at 23 °C (no creep)",
        ),
    )
}
MATERIAL_NAMES: tuple[str, ...] = tuple(MATERIALS)


#: Nominal Young's modulus E [GPa] of the catalogue's metals, for the compliance of a tapped
#: thread cut into them (VDI 2230-1 R3, δ_M with E_BI): [EMODULI]. Plastics are left out
#: (their modulus depends on moisture, temperature and time): give nut_youngs_modulus.
MATERIAL_YOUNGS_MODULUS_GPA: dict[str, float] = {
    "S235JR": 210.0,
    "E295": 210.0,
    "C45 (normalised)": 210.0,
    "42CrMo4 (QT)": 210.0,
    "X5CrNi18-10": 200.0,
    "EN-GJL-250": 110.0,
    "EN-GJS-400": 169.0,
    "EN-GJS-500": 169.0,
    "EN AW-6082 T6": 70.0,
    "EN AW-7075 T6": 70.0,
    "EN AC-46000 (die cast)": 70.0,
    "EN AC-42100 T6": 70.0,
    "TiAl6V4": 110.0,
    "MgAl9Zn1 (die cast)": 45.0,
}


def material_youngs_modulus(name: str) -> float | None:
    r"""Nominal Young's modulus of a catalogue material, or None where it is not listed.

    .. math::
        E = E_{nom}(\text{material})

    Parameters
    ----------
    name : str
        A key of :data:`MATERIALS`, [-]

    Returns
    -------
    float or None
        E, [Pa]

    Notes
    -----
    Nominal values of the material standards [EMODULI]: steel 210 GPa (EN 1993-1-1),
    austenitic stainless 200 GPa, aluminium alloys 70 GPa (EN 1999-1-1), grey iron
    EN-GJL-250 110 GPa, ductile iron 169 GPa, Ti-6Al-4V 110 GPa, magnesium 45 GPa.

    Examples
    --------
    >>> material_youngs_modulus("EN AW-6082 T6") / 1e9, material_youngs_modulus("POM")
    (70.0, None)
    """
    e = MATERIAL_YOUNGS_MODULUS_GPA.get(name)
    return None if e is None else e * 1e9


def material(name: str, *, field: str = "material") -> Material:
    """The material ``name`` of the catalogue (InputOutOfRange naming ``field`` otherwise)."""
    if name not in MATERIALS:
        raise InputOutOfRange(
            f"{field}: {name!r} is not in the material table (one of "
            f"{', '.join(MATERIAL_NAMES)}); give the limiting value directly",
            field=field,
        )
    return MATERIALS[name]


# --------------------------------------------------------------------------- at temperature

#: Celsius zero [K]: the tables below are printed in °C (grey iron's in °F).
CELSIUS_ZERO = 273.15

#: Lower yield strength R_eL or 0.2 % proof strength R_p0.2 [MPa] of ISO 898-1 classes at
#: elevated temperature: ISO 898-1 Annex A (informative), as reprinted by [NFG-898T]. The
#: standard gives them as guidance for the loss of strength with temperature, not as
#: requirements. Columns at :data:`PROOF_STRENGTH_TEMPERATURES_C`.
PROOF_STRENGTH_TEMPERATURES_C: tuple[float, ...] = (20.0, 100.0, 200.0, 250.0, 300.0)
PROOF_STRENGTH_AT_TEMPERATURE_MPA: dict[str, tuple[float, ...]] = {
    "5.6": (300.0, 270.0, 230.0, 215.0, 195.0),
    "8.8": (640.0, 590.0, 540.0, 510.0, 480.0),
    "10.9": (940.0, 875.0, 790.0, 745.0, 705.0),
    "12.9": (1100.0, 1020.0, 925.0, 875.0, 825.0),
}

#: Young's modulus E(T) [GPa] by material class: (temperatures [°C], moduli [GPa]).
#: Low-alloy (ferritic) steel, austenitic steel, aluminium alloys and nodular iron
#: (GGG-38 = EN-GJS-400) after Richter's tables as printed by [RICHTER-E]; grey cast iron
#: from ASME B31.1 as printed by [ASME-B31.1-E] (10^6 psi at 70…600 °F, the 70 °F column read
#: as room temperature 20 °C). Only the ratio E(T)/E(20 °C) is used: it scales the modulus a
#: design gives.
YOUNGS_MODULUS_AT_TEMPERATURE_GPA: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    "steel": ((20.0, 200.0, 400.0, 600.0), (212.0, 199.0, 184.0, 164.0)),
    "austenitic steel": ((20.0, 200.0, 400.0, 600.0), (196.0, 186.0, 179.0, 157.0)),
    "aluminium": ((20.0, 200.0), (70.0, 63.0)),
    "nodular cast iron": ((20.0, 200.0, 400.0), (170.0, 168.0, 135.0)),
    "grey cast iron": (
        (20.0, *((f - 32.0) * 5.0 / 9.0 for f in (200.0, 300.0, 400.0, 500.0, 600.0))),
        tuple(m * KSI / 1e6 for m in (13.4, 13.2, 12.9, 12.6, 12.2, 11.7)),
    ),
}

#: The E(T) class of the catalogue's materials (None: no table found for it).
MATERIAL_TEMPERATURE_CLASS: dict[str, str] = {
    "S235JR": "steel",
    "E295": "steel",
    "C45 (normalised)": "steel",
    "42CrMo4 (QT)": "steel",
    "X5CrNi18-10": "austenitic steel",
    "EN-GJL-250": "grey cast iron",
    "EN-GJS-400": "nodular cast iron",
    "EN-GJS-500": "nodular cast iron",
    "EN AW-6082 T6": "aluminium",
    "EN AW-7075 T6": "aluminium",
    "EN AC-46000 (die cast)": "aluminium",
    "EN AC-42100 T6": "aluminium",
}


def temperature_range(temperatures_c: tuple[float, ...]) -> tuple[float, float]:
    r"""The absolute temperatures a table over ``temperatures_c`` covers.

    .. math::
        T_{min} = T_0 + 273.15\,K, \qquad T_{max} = T_{n} + 273.15\,K

    Parameters
    ----------
    temperatures_c : tuple of float
        The table's columns T_0 … T_n, ascending, [°C]

    Returns
    -------
    tuple of float
        (T_min, T_max), [K]

    Notes
    -----
    The range a service temperature is refused outside (the tables' own columns, no
    extrapolation).

    Examples
    --------
    >>> temperature_range(PROOF_STRENGTH_TEMPERATURES_C)
    (293.15, 573.15)
    """
    return temperatures_c[0] + CELSIUS_ZERO, temperatures_c[-1] + CELSIUS_ZERO


def table_ratio(
    temperature: Any, temperatures_c: tuple[float, ...], values: tuple[float, ...]
) -> Any:
    r"""A tabulated property at a temperature over its room-temperature value, interpolated.

    .. math::
        r(T) = \frac{X_i + (X_{i+1} - X_i)\,\frac{T - T_i}{T_{i+1} - T_i}}{X_0},
        \qquad T_i \le T \le T_{i+1}

    Parameters
    ----------
    temperature : float or array
        T, the absolute temperature, [K]
    temperatures_c : tuple of float
        T_i of the table, ascending, T_0 room temperature, [°C]
    values : tuple of float
        X_i, the property at T_i (any unit), [-]

    Returns
    -------
    float or array
        r = X(T)/X(T_0), [-]

    Notes
    -----
    Linear interpolation between the printed columns, as VDI 2230-1 and the tables'
    sources leave it to the user; a temperature outside the table is held at its end here,
    the caller refuses it (:func:`temperature_range`).

    Examples
    --------
    8.8 at 150 °C, half-way between 590 and 540 MPa: 565/640

    >>> round(table_ratio(423.15, *_row("8.8")), 6)
    0.882812
    """
    celsius = np.asarray(temperature, dtype=float) - CELSIUS_ZERO
    ratio = np.interp(celsius, temperatures_c, values) / values[0]
    return ratio if isinstance(temperature, np.ndarray) else float(ratio)


def _row(property_class: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
    return PROOF_STRENGTH_TEMPERATURES_C, PROOF_STRENGTH_AT_TEMPERATURE_MPA[property_class]


def yield_strength_ratio(property_class: str, temperature: Any) -> Any:
    r"""R_p0.2(T)/R_p0.2(20 °C) of an ISO 898-1 property class.

    .. math::
        \frac{R_{p0.2}(T)}{R_{p0.2}(20\,°C)} = r(T)\ \text{of ISO 898-1 Annex A}

    Parameters
    ----------
    property_class : str
        One of :data:`PROOF_STRENGTH_AT_TEMPERATURE_MPA` (5.6, 8.8, 10.9, 12.9), [-]
    temperature : float or array
        Service temperature T, 293.15…573.15 K, [K]

    Returns
    -------
    float or array
        The ratio, applied to the R_p0.2,min of the bolt's size, [-]

    Notes
    -----
    ISO 898-1 Annex A (informative) as reprinted by [NFG-898T], interpolated linearly
    (:func:`table_ratio`). The ratio, not the printed MPa, is applied, so that 8.8 above M16
    (R_p0.2 = 660 MPa) and a typed yield strength of the class scale the same way. Raises
    InputOutOfRange (field ``service_temperature``) for a class without a table.

    Examples
    --------
    >>> round(yield_strength_ratio("10.9", 473.15) * 940, 6)
    790.0
    """
    if property_class not in PROOF_STRENGTH_AT_TEMPERATURE_MPA:
        raise InputOutOfRange(
            f"service_temperature: R_p0.2 at temperature is tabulated for ISO 898-1 classes "
            f"{', '.join(PROOF_STRENGTH_AT_TEMPERATURE_MPA)} only (ISO 898-1 Annex A), not for "
            f"{property_class}: leave service_temperature out and give the bolt's yield "
            "strength at that temperature as yield_strength",
            field="service_temperature",
        )
    return table_ratio(temperature, *_row(property_class))


def youngs_modulus_ratio(material_class: str, temperature: Any) -> Any:
    r"""E(T)/E(20 °C) of a material class (bolt or plate).

    .. math::
        \frac{E(T)}{E(20\,°C)} = r(T)\ \text{of the class's table}

    Parameters
    ----------
    material_class : str
        A key of :data:`YOUNGS_MODULUS_AT_TEMPERATURE_GPA`, [-]
    temperature : float or array
        T, inside the class's table (:func:`temperature_range`), [K]

    Returns
    -------
    float or array
        E_T/E_RT, [-]

    Notes
    -----
    [RICHTER-E] for steels, aluminium and nodular iron, [ASME-B31.1-E] for grey iron,
    interpolated linearly (:func:`table_ratio`). VDI 2230-1 prints its own E(T) table; its
    text was not available to us.

    Examples
    --------
    Steel at 200 °C: 199/212; aluminium at 110 °C: (70 − 7 × 90/180)/70

    >>> round(youngs_modulus_ratio("steel", 473.15), 6), youngs_modulus_ratio("aluminium", 383.15)
    (0.938679, 0.95)
    """
    return table_ratio(temperature, *YOUNGS_MODULUS_AT_TEMPERATURE_GPA[material_class])


# --------------------------------------------------------------------------- the designation


@dataclass(frozen=True)
class Designation:
    """A parsed designation: the thread, and the head standard and grade when it names them."""

    text: str
    thread: Thread
    head: str | None
    grade: str | None


_METRIC = re.compile(r"^M\s*(\d+(?:\.\d+)?)(?:\s*[x×X*]\s*(\d+(?:\.\d+)?))?$")
_INCH = re.compile(
    r"^(\d+(?:-\d+/\d+)?|\d+/\d+)\s*(?:\"|IN)?\s*(?:-\s*(\d+))?\s*(UNC|UNF)?(?:-\d[AB])?$"
)
_HEADS = re.compile(
    r"\b(ISO\s*4017|ISO\s*4014|ISO\s*4762|EN\s*1665|ISO\s*10642|DIN\s*912|DIN\s*931|DIN\s*933|DIN\s*7991)\b"
)
_DIN_TO_ISO = {
    "DIN 912": "ISO 4762",
    "DIN 931": "ISO 4014",
    "DIN 933": "ISO 4017",
    "DIN 7991": "ISO 10642",
}
_GRADE_TAIL = re.compile(
    r"(?:^|\s)((?:SAE\s*(?:J429\s*)?(?:GRADE\s*)?|GRADE\s*|GR\.?\s*)(?:2|5|8)|(?:ASTM\s*)?A193[\s-]*B7|B7"
    r"|A[24]-(?:5|7|8)0|\d{1,2}\.\d)$"
)


def parse_designation(text: str, *, field: str = "thread") -> Designation:
    """Read "M12", "M12x1.25", "M10 ISO 4762 12.9", "1/2-13 UNC", "1/2-13 UNC Grade 5".

    The thread comes first, then (in any order) a head standard and a grade.
    Errors name ``field`` and the part that could not be read.

    Examples
    --------
    >>> d = parse_designation("M10 ISO 4762 12.9")
    >>> d.thread.designation, d.head, d.grade
    ('M10', 'ISO 4762', '12.9')
    >>> parse_designation("1/2-13 UNC").thread.series
    'UNC'
    """
    if not isinstance(text, str) or not text.strip():
        raise InputOutOfRange(
            f"{field}: give a designation such as 'M12' or '1/2-13 UNC'", field=field
        )
    rest = re.sub(r"\s+", " ", text.strip().upper().replace("–", "-"))
    head_name: str | None = None
    match = _HEADS.search(rest)
    if match:
        found = re.sub(r"(ISO|EN|DIN)\s*", r"\1 ", match.group(1))
        head_name = _DIN_TO_ISO.get(found, found)
        rest = (rest[: match.start()] + " " + rest[match.end() :]).strip()
        rest = re.sub(r"\s+", " ", rest)
    grade: str | None = None
    match = _GRADE_TAIL.search(rest)
    if match:
        grade = normalise_grade(match.group(1), field=field)
        rest = rest[: match.start()].strip()
    rest = rest.strip(" ,;")
    metric = _METRIC.match(rest)
    if metric:
        thread = metric_thread(
            float(metric.group(1)),
            float(metric.group(2)) if metric.group(2) else None,
            field=field,
        )
    else:
        inch = _INCH.match(rest)
        if not inch:
            raise InputOutOfRange(
                f"{field}: cannot read the thread in {text!r}: write it as 'M12', 'M12x1.25' "
                "or '1/2-13 UNC', then optionally a head standard (ISO 4017, ISO 4014, "
                "ISO 4762, EN 1665, ISO 10642) and a grade (8.8, A2-70, SAE 5, B7)",
                field=field,
            )
        tpi = int(inch.group(2)) if inch.group(2) else None
        thread = unified_thread(inch.group(1), tpi, inch.group(3), field=field)
    if head_name is not None and not thread.is_metric:
        raise InputOutOfRange(
            f"{field}: {head_name} is a metric head; inch threads take hex cap screws "
            f"({UNIFIED_HEX})",
            field=field,
        )
    return Designation(text, thread, head_name, grade)


# --------------------------------------------------------------------------- surface pressure


def bearing_area(outer_diameter: float, inner_diameter: float) -> float:
    r"""Bearing area under a head, nut or washer (VDI 2230-1 R10).

    .. math::
        A_p = \frac{\pi}{4}\left(d_w^2 - d_h^2\right)

    Parameters
    ----------
    outer_diameter : float
        Outer diameter of the bearing face d_w (head, nut or washer), [m]
    inner_diameter : float
        Inner diameter d_h (clearance hole or washer bore), [m]

    Returns
    -------
    float
        A_p, [m²]; 0 when the face has no width

    Notes
    -----
    For a countersunk head the normal pressure on the cone equals the axial
    force over this projected annulus (the normal force and the cone area both
    grow by 1/sin(α/2)), so the same relation holds with d_w = d_k. Takes
    numpy arrays too (element by element).

    Examples
    --------
    >>> round(bearing_area(0.01233, 0.009) * 1e6, 2)
    55.79
    """
    area = 0.25 * math.pi * (outer_diameter**2 - inner_diameter**2)
    if isinstance(area, np.ndarray):
        return np.maximum(area, 0.0)
    return max(0.0, area)


def surface_pressure(force: float, outer_diameter: float, inner_diameter: float) -> float:
    r"""Surface pressure p = F / A_p under a bearing face (VDI 2230-1 R10).

    .. math::
        p = \frac{F}{\frac{\pi}{4}\left(d_w^2 - d_h^2\right)}

    Parameters
    ----------
    force : float
        Axial force on the face (F_M,max at assembly, F_S,max in service), [N]
    outer_diameter : float
        d_w, [m]
    inner_diameter : float
        d_h, [m]

    Returns
    -------
    float
        p, [Pa]; inf for a face without area (numpy arrays: element by element)

    Examples
    --------
    >>> round(surface_pressure(10000.0, 0.01233, 0.009) / 1e6, 1)
    179.3
    """
    area = bearing_area(outer_diameter, inner_diameter)
    if isinstance(area, np.ndarray) or isinstance(force, np.ndarray):
        has = np.asarray(area) > 0
        return np.where(has, force / np.where(has, area, 1.0), np.inf)
    return force / area if area > 0 else math.inf


# --------------------------------------------------------------------------- thread stripping


def internal_thread_shear_area(
    diameter: float, pitch: float, pitch_diameter: float, length: float
) -> float:
    r"""Shear area of the internal thread (nut or tapped hole), stripped at the bolt's d.

    .. math::
        A_{SN} = \pi d\, L_e \,\frac{P/2 + (d - D_2)\tan 30°}{P}

    Parameters
    ----------
    diameter : float
        Major diameter of the bolt thread d, [m]
    pitch : float
        Pitch P, [m]
    pitch_diameter : float
        Pitch diameter of the internal thread D2, [m]
    length : float
        Length of engagement L_e (full threads), [m]

    Returns
    -------
    float
        A_SN, [m²]

    Notes
    -----
    Alexander's shear-area model (VDI 2230-1 R11; FED-STD-H28/2 with the
    tolerance-free basic dimensions). With basic dimensions d − D2 = 0.6495 P
    and the bracket is 0.875 P: A_SN = 0.875 π d L_e.

    Examples
    --------
    >>> round(internal_thread_shear_area(0.010, 0.0015, 0.009026, 0.010) * 1e6, 1)
    274.9
    """
    return (
        math.pi
        * diameter
        * length
        * (0.5 * pitch + (diameter - pitch_diameter) * math.tan(math.pi / 6))
        / pitch
    )


def external_thread_shear_area(
    pitch: float, pitch_diameter: float, nut_minor_diameter: float, length: float
) -> float:
    r"""Shear area of the bolt thread, stripped at the internal thread's minor diameter.

    .. math::
        A_{SS} = \pi D_1 L_e \,\frac{P/2 + (d_2 - D_1)\tan 30°}{P}

    Parameters
    ----------
    pitch : float
        Pitch P, [m]
    pitch_diameter : float
        Pitch diameter of the bolt d2, [m]
    nut_minor_diameter : float
        Minor diameter of the internal thread D1, [m]
    length : float
        Length of engagement L_e, [m]

    Returns
    -------
    float
        A_SS, [m²]

    Notes
    -----
    VDI 2230-1 R11 after Alexander; basic dimensions give 0.75 π D1 L_e.

    Examples
    --------
    >>> round(external_thread_shear_area(0.0015, 0.009026, 0.008376, 0.010) * 1e6, 1)
    197.4
    """
    return (
        math.pi
        * nut_minor_diameter
        * length
        * (0.5 * pitch + (pitch_diameter - nut_minor_diameter) * math.tan(math.pi / 6))
        / pitch
    )


def nut_dilation_factor(width_across_flats: float | None, diameter: float) -> float:
    r"""Alexander's factor C1 for the radial dilation of a nut (1 for a tapped hole).

    .. math::
        C_1 = -\left(\frac{s}{d}\right)^2 + 3.8\,\frac{s}{d} - 2.61 \quad (1.4 \le s/d \le 1.9)

    Parameters
    ----------
    width_across_flats : float or None
        s of the nut; None for a tapped hole in a large part, [m]
    diameter : float
        Nominal diameter d, [m]

    Returns
    -------
    float
        C1 (1 at s/d ≥ 1.9 and for tapped holes; the value at 1.4 below it), [-]

    Examples
    --------
    >>> round(nut_dilation_factor(0.018, 0.012), 3)
    0.84
    >>> nut_dilation_factor(None, 0.012)
    1.0
    """
    if width_across_flats is None:
        return 1.0
    r = min(max(width_across_flats / diameter, 1.4), 1.9)
    return -(r**2) + 3.8 * r - 2.61


#: Alexander's thread-bending factor where a thread strips at equal strength (R_S = 1).
THREAD_BENDING_FACTOR = 0.897


def thread_bending_factors(strength_ratio: float) -> tuple[float, float]:
    r"""Alexander's thread-bending factors (C2 of the bolt thread, C3 of the internal thread).

    .. math::
        C_3 = 0.728 + 1.769 R_S - 2.896 R_S^2 + 1.296 R_S^3 \quad (0.4 < R_S < 1)

    .. math::
        C_2 = 5.594 - 13.682 R_S + 14.107 R_S^2 - 6.057 R_S^3 + 0.9353 R_S^4 \quad (1 < R_S \le 2.2)

    Parameters
    ----------
    strength_ratio : float
        R_S = τ_BM A_SN / (τ_BS A_SS): internal over external thread strength, [-]

    Returns
    -------
    tuple of float
        (C2, C3), [-]; 0.897 where the relation does not apply; R_S is held
        inside 0.4…2.2 (VDI 2230-1 R11 after Alexander). An array of R_S gives
        arrays, element by element.

    Examples
    --------
    >>> [round(c, 3) for c in thread_bending_factors(1.0)]
    [0.897, 0.897]
    >>> [round(c, 3) for c in thread_bending_factors(0.2)]
    [0.897, 1.055]
    """
    r = strength_ratio
    if isinstance(r, np.ndarray):
        lo, hi = np.maximum(r, 0.4), np.minimum(r, 2.2)
        c3_lo = 0.728 + 1.769 * lo - 2.896 * lo**2 + 1.296 * lo**3
        c2_hi = 5.594 - 13.682 * hi + 14.107 * hi**2 - 6.057 * hi**3 + 0.9353 * hi**4
        return (
            np.where(r > 1.0, c2_hi, THREAD_BENDING_FACTOR),
            np.where(r < 1.0, c3_lo, THREAD_BENDING_FACTOR),
        )
    c2 = c3 = THREAD_BENDING_FACTOR
    if r < 1.0:
        x = max(r, 0.4)
        c3 = 0.728 + 1.769 * x - 2.896 * x**2 + 1.296 * x**3
    elif r > 1.0:
        x = min(r, 2.2)
        c2 = 5.594 - 13.682 * x + 14.107 * x**2 - 6.057 * x**3 + 0.9353 * x**4
    return c2, c3


@dataclass(frozen=True)
class Stripping:
    """Thread-stripping result: forces [N] and the minimum engagement length [m]."""

    bolt_breaking_force: float
    internal_strip_force: float
    external_strip_force: float
    min_engagement_length: float
    min_engagement_internal: float
    min_engagement_external: float
    strength_ratio: float
    c1: float
    c2: float
    c3: float

    @property
    def strip_force(self) -> float:
        if isinstance(self.internal_strip_force, np.ndarray) or isinstance(
            self.external_strip_force, np.ndarray
        ):
            return np.minimum(self.internal_strip_force, self.external_strip_force)
        return min(self.internal_strip_force, self.external_strip_force)

    @property
    def weaker(self) -> str:
        return "internal" if self.internal_strip_force <= self.external_strip_force else "external"


def thread_stripping(
    diameter: float,
    pitch: float,
    pitch_diameter: float,
    nut_minor_diameter: float,
    stress_area: float,
    bolt_tensile_strength: float,
    bolt_shear_strength: float,
    internal_shear_strength: float,
    length: float,
    *,
    width_across_flats: float | None = None,
    c1: float | None = None,
    bending: bool = True,
) -> Stripping:
    r"""Bolt breaking force, stripping forces at ``length`` and the minimum engagement.

    .. math::
        F_B = R_m A_s,\quad
        F_{SN} = C_1 C_3 \tau_{BM} A_{SN}(L_e),\quad
        F_{SS} = C_1 C_2 \tau_{BS} A_{SS}(L_e)

    .. math::
        L_{e,\min} = \max\left(\frac{F_B L_e}{F_{SN}}, \frac{F_B L_e}{F_{SS}}\right)

    Parameters
    ----------
    diameter, pitch, pitch_diameter, nut_minor_diameter : float
        d, P, d2 (= D2 basic), D1, [m]
    stress_area : float
        A_s of the bolt, [m²]
    bolt_tensile_strength : float
        R_m of the bolt (the breaking force the threads must exceed), [Pa]
    bolt_shear_strength : float
        τ_BS of the bolt material, [Pa]
    internal_shear_strength : float
        τ_BM of the nut or tapped material, [Pa]
    length : float
        Length of engagement L_e (full threads, without chamfers), [m]
    width_across_flats : float, optional
        s of a nut (dilation factor C1); None for a tapped hole, [m]
    c1 : float, optional
        Override of C1, [-]
    bending : bool
        Apply Alexander's thread-bending factors C2/C3 (False: C2 = C3 = 1), [-]

    Returns
    -------
    Stripping

    Notes
    -----
    VDI 2230-1 R11 after Alexander (1977): the bolt must break before either
    thread strips. The lengths are full-thread engagement, without the entry
    chamfers and run-out (the open BAT implementation of R11 adds 2 P for
    them). With C1 = C2 = C3 = 1 this is the plain shear-area rule of
    FED-STD-H28. R_S below 0.4 (a much softer internal thread) is held at 0.4,
    where C3 = 1.055. The numeric arguments may be numpy arrays (the forces and
    lengths are then arrays, element by element).

    Examples
    --------
    >>> s = thread_stripping(0.010, 0.0015, 0.009026, 0.008376, 58.0e-6, 830e6,
    ...                      498e6, 186e6, 0.010, c1=1.0, bending=False)
    >>> round(s.min_engagement_length * 1e3, 2)
    9.42
    """
    c1 = nut_dilation_factor(width_across_flats, diameter) if c1 is None else c1
    f_break = bolt_tensile_strength * stress_area
    a_n = internal_thread_shear_area(diameter, pitch, pitch_diameter, 1.0)
    a_s = external_thread_shear_area(pitch, pitch_diameter, nut_minor_diameter, 1.0)
    ratio = internal_shear_strength * a_n / (bolt_shear_strength * a_s)
    c2, c3 = thread_bending_factors(ratio) if bending else (1.0, 1.0)
    per_m_n = c1 * c3 * internal_shear_strength * a_n
    per_m_s = c1 * c2 * bolt_shear_strength * a_s
    l_n = f_break / per_m_n
    l_s = f_break / per_m_s
    return Stripping(
        bolt_breaking_force=f_break,
        internal_strip_force=per_m_n * length,
        external_strip_force=per_m_s * length,
        min_engagement_length=np.maximum(l_n, l_s)
        if isinstance(l_n, np.ndarray) or isinstance(l_s, np.ndarray)
        else max(l_n, l_s),
        min_engagement_internal=l_n,
        min_engagement_external=l_s,
        strength_ratio=ratio,
        c1=c1,
        c2=c2,
        c3=c3,
    )


# --------------------------------------------------------------------------- catalogue


#: The grade the form pairs with an inch thread: inch threads have no default class
#: (ISO 898-1 is metric), and SAE J429 grade 5 is the common inch cap screw.
INCH_PICKER_GRADE = "SAE 5"


def picker_entry(thread: Thread) -> dict[str, object]:
    """A thread as the form's picker offers it, with what the form sends for it [m].

    The thread (:meth:`Thread.describe`), and what a designation resolves to by
    default, for a model that takes numbers instead: ``bearing_diameter``, the
    bearing face d_w,min of the default hexagon head (ISO 4017; ASME B18.2.1 for
    inch threads), ``hole_diameter``, the clearance hole (ISO 273 medium; ASME
    B18.2.8 normal), and ``grade``, sent with an inch designation
    (:data:`INCH_PICKER_GRADE`; None for metric threads, whose property class
    has a default).

    Parameters
    ----------
    thread : Thread
        A catalogue thread (:func:`metric_thread`, :func:`unified_thread`)

    Returns
    -------
    dict
        The thread's description and ``bearing_diameter`` [m], ``hole_diameter`` [m]
        and ``grade``

    Examples
    --------
    >>> e = picker_entry(metric_thread(12))
    >>> e["bearing_diameter"], e["hole_diameter"], e["grade"]
    (0.01663, 0.0135, None)
    >>> e = picker_entry(unified_thread("1/2"))
    >>> round(e["bearing_diameter"] / INCH, 5), round(e["hole_diameter"] / INCH, 3), e["grade"]
    (0.7125, 0.531, 'SAE 5')
    """
    std = "ISO 4017" if thread.is_metric else UNIFIED_HEX
    return {
        **thread.describe(),
        "bearing_diameter": head(std, thread).bearing_diameter,
        "hole_diameter": clearance_hole(thread),
        "grade": None if thread.is_metric else INCH_PICKER_GRADE,
    }


def catalogue() -> dict[str, list[dict[str, object]]]:
    """The whole catalogue, JSON-ready in SI units (``GET /api/v1/fasteners``)."""
    threads = [picker_entry(t) for t in all_threads()]
    heads: list[dict[str, object]] = []
    for std, (_style, table, drive) in HEAD_STANDARDS.items():
        for key in table:
            h = head(std, metric_thread(key))
            entry = h.describe()
            entry["thread"] = f"M{_fmt(key)}"
            if drive == "hex key":
                entry["drive_torque_limit"] = hex_key_torque(h.drive_size)
            heads.append(entry)
    for size in UNIFIED_SIZES:
        entry = head(UNIFIED_HEX, unified_thread(size)).describe()
        entry["thread"] = size
        heads.append(entry)
    nuts = [
        {**nut(std, metric_thread(key)).describe(), "thread": f"M{_fmt(key)}"}
        for std, table in NUT_HEIGHT_MM.items()
        for key in table
    ]
    washers = [
        {**washer(std, metric_thread(key)).describe(), "thread": f"M{_fmt(key)}"}
        for std, table in WASHER_MM.items()
        for key in table
    ]
    return {
        "threads": threads,
        "property_classes": [g.describe() for g in GRADES],
        "heads": heads,
        "nuts": nuts,
        "washers": washers,
        "materials": [m.describe() for m in MATERIALS.values()],
    }


#: VDI 2230-1 R11 sizes the engagement for a bolt at the top of its strength range,
#: R_m,max = 1.2 R_m,min, so that even it breaks before a thread strips (the factor as the
#: 2026-11-26 review quotes open VDI 2230 implementations; [BAT-R11] itself uses R_m,min).
BOLT_UPPER_STRENGTH_FACTOR = 1.2

#: Entry chamfers and run-out of the two threads, in pitches: m_ges = m_eff + 2 P
#: (VDI 2230-1 R11 as [BAT-R11] implements it).
ENTRY_CHAMFER_PITCHES = 2.0


def engagement_for_bolt_failure(
    diameter: Any,
    pitch: Any,
    pitch_diameter: Any,
    nut_minor_diameter: Any,
    stress_area: Any,
    bolt_tensile_strength: Any,
    bolt_shear_strength: Any,
    internal_shear_strength: Any,
    length: Any,
    *,
    width_across_flats: float | None = None,
) -> Stripping:
    r"""VDI 2230-1 R11: the engaged length at which a bolt of upper strength breaks first.

    .. math::
        F_{B} = 1.2\,R_m A_s,\qquad
        m_{ges,min} = \frac{F_B}{C_1 C_3 \tau_{BM} A_{SN}/L} + 2P
        \ \text{(and the bolt thread's the same with } C_2, \tau_{BS})

    Parameters
    ----------
    diameter, pitch, pitch_diameter, nut_minor_diameter : float or numpy array
        d, P, d2, D1, [m]
    stress_area : float or numpy array
        A_s, [m²]
    bolt_tensile_strength : float or numpy array
        R_m,min of the bolt (its class's), [Pa]
    bolt_shear_strength : float or numpy array
        τ_BS of the bolt thread at its minimum strength, [Pa]
    internal_shear_strength : float or numpy array
        τ_BM of the nut or tapped material, [Pa]
    length : float or numpy array
        Engaged length m_ges as built, entry chamfers included, [m]
    width_across_flats : float, optional
        s of a nut (C1); None for a tapped hole, [m]

    Returns
    -------
    Stripping
        :func:`thread_stripping` with F_B at 1.2 R_m A_s, the minimum lengths including
        the 2 P of the chamfers and the strip forces at the full threads of ``length``
        (m_ges − 2 P, not below 0)

    Notes
    -----
    VDI 2230-1 R11 after Alexander, as its open implementation [BAT-R11] states it
    (m_ges = R_m A_s P/(C1 C3 τ_BM (P/2 + (d − D2) tan 30°) π d) + 2 P), with the bolt's
    breaking force taken at its upper strength R_m,max = 1.2 R_m,min: a bolt at the top
    of its class still breaks before a thread strips. The threads' own shear strengths
    stay at their minimum.

    Examples
    --------
    M12 8.8 into S235JR (τ_BM = 0.6 × 360 MPa): 1.2 × 9.28 mm of full thread + 3.5 mm

    >>> s = engagement_for_bolt_failure(0.012, 0.00175, 0.0108633, 0.0101056, 84.27e-6,
    ...                                 800e6, 480e6, 216e6, 0.012)
    >>> round(s.min_engagement_length * 1e3, 2)
    14.64
    """
    chamfers = ENTRY_CHAMFER_PITCHES * pitch
    full: Any = length - chamfers
    full = np.maximum(full, 0.0) if isinstance(full, np.ndarray) else max(full, 0.0)
    s = thread_stripping(
        diameter,
        pitch,
        pitch_diameter,
        nut_minor_diameter,
        stress_area,
        BOLT_UPPER_STRENGTH_FACTOR * bolt_tensile_strength,
        bolt_shear_strength,
        internal_shear_strength,
        full,
        width_across_flats=width_across_flats,
    )
    return replace(
        s,
        min_engagement_length=s.min_engagement_length + chamfers,
        min_engagement_internal=s.min_engagement_internal + chamfers,
        min_engagement_external=s.min_engagement_external + chamfers,
    )
