"""Fasteners as bought, for the preload models: designation inputs and the bought-part checks.

The catalogue and the relations live in :mod:`engine.physics.fasteners`; this module
declares the inputs that name a catalogue part (``thread``, ``grade``,
``head_standard``, ``nut``, ``washer``, materials), resolves them into the numbers the
preload models need, and adds the checks of a bought fastener: surface
pressure under head and nut/washer (VDI 2230-1 R10), thread stripping
(VDI 2230-1 R11 after Alexander) and the hex-key drive torque (ISO 2936).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from ..core.errors import EngineError, InputOutOfRange
from ..core.params import positive
from ..core.spec import Check, Output, Param
from ..core.text import q
from ..physics import fasteners as fa
from ..physics import threads as th

SOURCE_TEXT = (
    "ISO 261, ISO 262, ISO 3506-1, SAE J429, ASTM A193, ASME B1.1, ASME B18.2.1, "
    "ISO 4762, EN 1665, ISO 10642, ISO 2936, VDI 2230-1 R10 and R11 (Alexander)"
)

#: Bolt shear strength over tensile strength τ_BS/R_m (FED-STD-H28 practice, 0.6).
BOLT_SHEAR_RATIO = 0.6

#: Suggestions for the free-text inputs (the form's datalist; any catalogue entry is accepted).
THREAD_EXAMPLES: tuple[str, ...] = (
    "M12",
    "M12x1.25",
    "M10 ISO 4762 12.9",
    "M8 ISO 4762 12.9",
    "M6 ISO 10642 10.9",
    "M10 EN 1665 10.9",
    "M8 A2-70",
    "1/2-13 UNC",
    "1/2-20 UNF",
    "3/4-10 UNC B7",
)

THREAD_INPUTS: tuple[Param, ...] = (
    Param(
        "thread",
        "1",
        "Designation instead of thread_diameter: 'M12', 'M12x1.25', 'M10 ISO 4762 12.9', "
        "'1/2-13 UNC', '1/2-13 UNC Grade 5' (ISO M1.6…M64 coarse and fine, UNC/UNF "
        "1/4…1-1/2; GET /api/v1/fasteners lists them). A head standard or grade in it "
        "sets head_standard and grade",
        kind="text",
        choices=THREAD_EXAMPLES,
        group="bolt",
    ),
    Param(
        "grade",
        "1",
        "Bolt grade, overriding property_class: ISO 898-1 (8.8…12.9), ISO 3506-1 (A2-70, "
        "A4-70, A4-80), SAE J429 ('SAE 5', 'Grade 8'), ASTM A193 'B7'",
        kind="text",
        choices=fa.GRADE_NAMES,
        group="bolt",
    ),
)

CHECK_INPUTS: tuple[Param, ...] = (
    Param(
        "head_standard",
        "1",
        "Head standard (bearing diameter d_w, drive): hexagon ISO 4017/4014 when absent "
        "(ASME B18.2.1 hex for inch threads)",
        kind="choice",
        choices=fa.HEAD_NAMES,
        group="fastener",
    ),
    Param(
        "washer",
        "1",
        "Plain washer under the head (spreads the pressure on the clamped part)",
        kind="choice",
        choices=fa.WASHER_NAMES,
        group="fastener",
    ),
    Param(
        "nut",
        "1",
        "Hexagon nut (a through-bolted joint: surface pressure under the nut); absent: tapped",
        kind="choice",
        choices=tuple(fa.NUT_HEIGHT_MM),
        group="fastener",
    ),
    Param(
        "clamped_material",
        "1",
        "Material under the head and nut: its limiting surface pressure p_G (VDI 2230-1 "
        "Table A9; plastics: compressive yield)",
        kind="choice",
        choices=fa.MATERIAL_NAMES,
        group="fastener",
    ),
    positive(
        "limiting_surface_pressure",
        "Pa",
        "Limiting surface pressure p_G of the clamped part; overrides clamped_material",
        maximum=1e10,
        display_unit="MPa",
        symbol="p_G",
        group="fastener",
    ),
    Param(
        "internal_thread_material",
        "1",
        "Material of the tapped hole: its shear strength τ_BM for the stripping check",
        kind="choice",
        choices=fa.MATERIAL_NAMES,
        group="fastener",
    ),
    positive(
        "internal_thread_shear_strength",
        "Pa",
        "Shear strength τ_BM of the internal thread; overrides internal_thread_material",
        maximum=1e10,
        display_unit="MPa",
        symbol="τ_BM",
        group="fastener",
    ),
    positive(
        "engagement_length",
        "m",
        "Length of thread engagement in the tapped hole as built, entry chamfers included "
        "(VDI 2230-1 R11: m_ges = m_eff + 2P)",
        maximum=1.0,
        display_unit="mm",
        symbol="m_eff",
        group="fastener",
    ),
    positive(
        "working_bolt_force",
        "N",
        "Largest bolt force in service F_S,max (surface pressure in service, VDI 2230-1 R10)",
        maximum=1e8,
        display_unit="kN",
        symbol="F_S,max",
        group="fastener",
    ),
)

CHECK_OUTPUTS: tuple[Output, ...] = (
    Output(
        "fastener",
        "1",
        "The fastener resolved from the inputs",
        kind="str",
        symbol="",
        step="ISO 4017",
    ),
    Output(
        "surface_pressure_head",
        "Pa",
        "Surface pressure under the head (or washer) at the largest assembly preload, "
        "p = F_M,max / A_p (VDI 2230-1 R10)",
        display_unit="MPa",
        symbol="p_M",
        step="VDI 2230-1 R10",
    ),
    Output(
        "surface_pressure_head_working",
        "Pa",
        "Surface pressure under the head (or washer) at working_bolt_force (VDI 2230-1 R10)",
        display_unit="MPa",
        symbol="p_B",
        step="VDI 2230-1 R10",
    ),
    Output(
        "surface_pressure_nut",
        "Pa",
        "Surface pressure under the nut at the largest assembly preload (VDI 2230-1 R10)",
        display_unit="MPa",
        symbol="p_M,nut",
        step="VDI 2230-1 R10",
    ),
    Output(
        "limiting_surface_pressure",
        "Pa",
        "Limiting surface pressure p_G used (clamped_material or as given)",
        display_unit="MPa",
        symbol="p_G",
        step="VDI 2230-1 R10",
    ),
    Output(
        "bearing_area",
        "m^2",
        "Bearing area A_p on the clamped part under the head/washer",
        symbol="A_p",
        step="VDI 2230-1 R10",
    ),
    Output(
        "min_engagement_length",
        "m",
        "Shortest engagement, entry chamfers (2P) included, for which a bolt at its upper "
        "strength 1.2 R_m breaks before a thread strips (VDI 2230-1 R11, Alexander)",
        display_unit="mm",
        symbol="m_eff,min",
        step="VDI 2230-1 R11",
    ),
    Output(
        "stripping_force",
        "N",
        "Force that strips the weaker thread at engagement_length (VDI 2230-1 R11)",
        display_unit="kN",
        symbol="F_mGM",
        step="VDI 2230-1 R11",
    ),
    Output(
        "bolt_breaking_force",
        "N",
        "1.2 R_m A_s: the upper breaking force the threads must exceed (VDI 2230-1 R11)",
        display_unit="kN",
        symbol="F_mS",
        step="VDI 2230-1 R11",
    ),
    Output(
        "drive_torque_limit",
        "N*m",
        "Test torque of the hex key the head takes (ISO 2936): the drive's limit",
        symbol="M_prüf",
        step="ISO 2936",
    ),
)


class Fastener(NamedTuple):
    """What the catalogue says about the bolt of a request (None where it does not know).

    A named tuple, like :class:`Bolt`: a request builds one.
    """

    label: str
    thread: fa.Thread | None
    head: fa.Head | None
    grade: fa.Grade | None


@functools.lru_cache(maxsize=256)
def _catalogue_thread(d: float, pitch: float | None) -> fa.Thread | None:
    """The catalogue's metric thread for a numeric diameter/pitch, or None.

    Kept by value (a thread is frozen, the catalogue fixed): a request repeats the sizes
    of the last, and a size the catalogue lacks otherwise costs a refusal's sentence.
    """
    try:
        return fa.metric_thread(round(d * 1e3, 6), None if pitch is None else round(pitch * 1e3, 6))
    except InputOutOfRange:
        return None


def resolve(x: Mapping[str, Any]) -> tuple[dict[str, Any], Fastener, list[str]]:
    """Bolt numbers from ``thread``/``grade``/``head`` (or the numeric inputs).

    Returns the fields the preload model's bolt takes from the catalogue (always
    diameter; any of pitch, pitch_diameter, minor_diameter, stress_diameter,
    stress_area, yield_strength, tensile_strength, bearing_outer_diameter,
    hole_diameter, bearing_friction_factor), the fastener, and notes.
    Numeric inputs the caller gave win over the catalogue.
    """
    notes: list[str] = []
    fields: dict[str, Any] = {}
    text = x.get("thread")
    head_name = x.get("head_standard")
    grade_name = x.get("grade")
    thread: fa.Thread | None
    if text is not None:
        if x.get("thread_diameter") is not None:
            raise InputOutOfRange(
                "give thread or thread_diameter, not both", field="thread_diameter"
            )
        if x.get("thread_pitch") is not None:
            raise InputOutOfRange(
                "thread_pitch cannot be combined with a thread designation: write the pitch in "
                "it ('M12x1.25')",
                field="thread_pitch",
            )
        des = fa.parse_designation(str(text), field="thread")
        thread = des.thread
        if des.head is not None:
            if head_name is not None and head_name != des.head:
                raise InputOutOfRange(
                    f"head_standard = {head_name!r} contradicts the designation's {des.head}",
                    field="head_standard",
                )
            head_name = des.head
        if des.grade is not None:
            if grade_name is not None and fa.normalise_grade(str(grade_name)) != des.grade:
                raise InputOutOfRange(
                    f"grade = {grade_name!r} contradicts the designation's {des.grade}",
                    field="grade",
                )
            grade_name = des.grade
        t = thread
        fields.update(
            diameter=t.diameter,
            pitch=t.pitch,
            pitch_diameter=t.pitch_diameter,
            minor_diameter=t.minor_diameter,
            stress_diameter=(t.stress_area * 4 / 3.141592653589793) ** 0.5,
            stress_area=t.stress_area,
        )
        notes.append(_thread_note(t))
    else:
        if x.get("thread_diameter") is None:
            raise InputOutOfRange(
                "give thread (a designation such as 'M12' or '1/2-13 UNC') or thread_diameter",
                field="thread",
            )
        fields["diameter"] = float(x["thread_diameter"])
        pitch = x.get("thread_pitch")
        thread = _catalogue_thread(
            float(x["thread_diameter"]), None if pitch is None else float(pitch)
        )

    grade: fa.Grade | None = None
    if grade_name is not None:
        d = float(fields["diameter"])
        grade = fa.grade_strengths(str(grade_name), d, field="grade")
        if x.get("yield_strength") is None:
            fields.update(
                yield_strength=grade.yield_strength, tensile_strength=grade.tensile_strength
            )
            notes.append(
                f"grade {grade.name} ({grade.standard}) at d = {q(d, 'mm', 4)}: "
                f"yield {q(grade.yield_strength, 'MPa', 4)}, "
                f"R_m {q(grade.tensile_strength, 'MPa', 4)} (minimum values)"
            )
    elif thread is not None and not thread.is_metric and x.get("yield_strength") is None:
        raise InputOutOfRange(
            f"{thread.designation} is an inch thread: give grade (SAE 2, SAE 5, SAE 8, B7) or "
            "yield_strength; ISO 898-1 classes are metric",
            field="grade",
        )

    head: fa.Head | None = None
    if thread is not None and (head_name is not None or text is not None):
        std = (
            str(head_name)
            if head_name is not None
            else ("ISO 4017" if thread.is_metric else fa.UNIFIED_HEX)
        )
        head = fa.head(std, thread, field="head_standard")
        if x.get("bearing_outer_diameter") is None:
            fields["bearing_outer_diameter"] = head.bearing_diameter
            what = "d_k,min of the countersunk head" if head.style == "countersunk" else "d_w,min"
            notes.append(f"bearing face D_f = {what} = {q(head.bearing_diameter, 'mm', 4)} ({std})")
        if head.style == "countersunk":
            factor = fa.countersunk_friction_factor(head.cone_angle)
            fields["bearing_friction_factor"] = factor
            notes.append(
                f"countersunk head ({std}): the bearing friction acts on the 90° cone, so μ_K is "
                f"taken ×1/sin 45° = ×{factor:.3f} at the radius of the projected annulus"
            )
    elif head_name is not None:
        raise InputOutOfRange(
            "head_standard needs a catalogue thread: give thread, or a thread_diameter/"
            "thread_pitch of ISO 261/262",
            field="head_standard",
        )
    if thread is not None and x.get("hole_diameter") is None and (text is not None):
        if thread.is_metric:
            series = str(x.get("hole_series") or "medium")
            fields["hole_diameter"] = fa.clearance_hole(thread, series)
            notes.append(
                f"clearance hole d_h = {q(fields['hole_diameter'], 'mm', fmt='g')} "
                f"(ISO 273 {series})"
            )
        else:
            fields["hole_diameter"] = fa.clearance_hole(thread)
            notes.append(
                f"clearance hole d_h = {fields['hole_diameter'] / fa.INCH:.3f} in "
                "(ASME B18.2.8 normal)"
            )
    parts = [
        thread.designation
        if thread is not None
        else f"d = {float(x['thread_diameter']) * 1e3:g} mm"
    ]
    if head is not None:
        parts.append(head.standard)
    parts.append(grade.name if grade is not None else str(x.get("property_class") or "8.8"))
    return fields, Fastener(" ".join(parts), thread, head, grade), notes


# --------------------------------------------------------------------------- the bolt
#
# One resolution for one design or many: :func:`resolve_bolt` (one design, with a note
# per standard value and a refusal naming the field) and :func:`resolve_bolts` (``n``
# points whose numeric inputs may be arrays, a refused point marked) run the same
# step, :func:`_bolt_numbers`, after the catalogue's :func:`resolve`.


class Bolt(NamedTuple):
    """A bolt resolved from a request: standard data unless overridden [m, m², Pa].

    A named tuple (immutable, as a frozen dataclass is, and about ten times cheaper to
    build: a request builds one).
    """

    diameter: float
    pitch: float
    pitch_diameter: float
    minor_diameter: float
    stress_diameter: float
    stress_area: float
    yield_strength: float
    tensile_strength: float | None
    bearing_outer_diameter: float
    hole_diameter: float
    #: μ_K multiplier of the bearing face (1/sin 45° on a countersunk head).
    bearing_friction_factor: float = 1.0
    #: The catalogue's fastener (thread, head, grade) where the request names one.
    fastener: Fastener | None = None


# The notes naming a standard value are kept by value, like the catalogue's threads: they
# depend only on the size and class a request names, which the next request repeats, and
# each costs a few marked quantities (q()) to write.


@functools.lru_cache(maxsize=256)
def _class_note(name: str, diameter: float, yield_strength: float, tensile: float) -> str:
    """Where a property class's strengths come from: ISO 898-1, or its M39 values carried on."""
    kind = th.PROPERTY_CLASSES[name].yield_kind
    values = f"{kind} = {q(yield_strength, 'MPa', fmt='g')}, R_m = {q(tensile, 'MPa', fmt='g')}"
    if th.beyond_iso898(name, diameter):
        return (
            f"property class {name}, d = {q(diameter, 'mm', fmt='g')}: ISO 898-1 defines the class "
            f"only up to M39; its M39 minimum values {values} are taken here (an assumption: "
            "larger bolts are made to the class by agreement); give yield_strength for the "
            "bolt's certified values"
        )
    return (
        f"property class {name}, d = {q(diameter, 'mm', fmt='g')}: {values} "
        "(ISO 898-1 minimum values)"
    )


@functools.lru_cache(maxsize=256)
def _thread_note(t: fa.Thread) -> str:
    """The catalogue thread's pitch and stress area, as its standard gives them."""
    if t.is_metric:
        return (
            f"thread {t.designation}: P = {q(t.pitch, 'mm', fmt='g')} (ISO 261/262), "
            f"A_s = {q(t.stress_area, 'mm²', 4)} (ISO 898-1)"
        )
    return (
        f"thread {t.designation}: d = {t.diameter / fa.INCH:g} in, "
        f"E = {t.pitch_diameter / fa.INCH:.4f} in, "
        f"A_t = {t.stress_area / fa.INCH**2:.4f} in² "
        "(ASME B1.1); minor diameter d − 1.299038 p"
    )


@functools.lru_cache(maxsize=256)
def _coarse_pitch_note(diameter: float, pitch: float) -> str:
    """The ISO 261 coarse pitch taken for a thread diameter."""
    return f"pitch P = {q(pitch, 'mm', fmt='g')}: ISO 261 coarse thread M{diameter * 1e3:g}"


@functools.lru_cache(maxsize=256)
def _hex_bearing_note(outer: float) -> str:
    """The ISO 4017 bearing face taken for a hexagon head."""
    return f"bearing face D_f = d_w,min = {q(outer, 'mm', fmt='g')} (ISO 4017 hexagon head)"


@functools.lru_cache(maxsize=256)
def _clearance_hole_note(hole: float, series: str) -> str:
    """The ISO 273 clearance hole taken for the thread."""
    return f"clearance hole d_h = {q(hole, 'mm', fmt='g')} (ISO 273 {series})"


def resolve_bolt(x: Mapping[str, Any]) -> tuple[Bolt, list[str]]:
    """The bolt a request describes, and notes naming each standard value used."""
    cat, fastener, notes = resolve(x)
    numbers, _ = _bolt_numbers(x, cat, notes, None)
    return Bolt(**numbers, fastener=fastener), notes


def _bolt_numbers(
    x: Mapping[str, Any], cat: Mapping[str, Any], notes: list[str], n: int | None
) -> tuple[dict[str, Any], np.ndarray]:
    """The bolt's numbers from the inputs, the catalogue's ``cat`` and the ISO tables.

    One design (``n`` None): floats, a note per standard value used, and a refusal
    (InputOutOfRange naming the field) where the inputs make no bolt. ``n`` points: the
    numeric inputs may be arrays, a tabulated value is looked up per point, and a point
    that would be refused is False in the returned mask (no notes per point).
    """
    one = n is None
    ok: Any = True if n is None else np.ones(n, dtype=bool)

    def need(good: Any, refusal: Callable[[], InputOutOfRange]) -> None:
        nonlocal ok
        if not one:
            ok = ok & good
        elif not good:
            raise refusal()

    def num(v: Any) -> Any:
        return float(v) if one else v

    def note(text: Callable[[], str]) -> None:
        """A note of one design (written only then: on arrays its numbers are arrays)."""
        if one:
            notes.append(text())

    d = num(cat["diameter"])
    per_point = isinstance(d, np.ndarray)
    if "pitch" in cat:
        pitch = num(cat["pitch"])
    elif x.get("thread_pitch") is None:
        if per_point:
            pitch, found = _tabulated(d, th.COARSE_PITCH_MM)
            ok = ok & found
        else:
            pitch = th.coarse_pitch(d)
            note(lambda: _coarse_pitch_note(d, pitch))
    else:
        pitch = num(x["thread_pitch"])
        need(
            d - 1.226869 * pitch > 0.0,
            lambda: InputOutOfRange(
                f"thread_pitch = {pitch * 1e3:g} mm is too coarse for d = {d * 1e3:g} mm: the "
                f"minor diameter d3 = d − 1.226869 P must stay > 0 (P < {d / 1.226869 * 1e3:g} mm)",
                field="thread_pitch",
            ),
        )
    tensile: Any
    if x.get("yield_strength") is not None:
        yield_strength, tensile = num(x["yield_strength"]), None
        note(lambda: f"yield strength R_p0.2 = {q(yield_strength, 'MPa', fmt='g')} as given")
    elif "yield_strength" in cat:
        yield_strength, tensile = num(cat["yield_strength"]), num(cat["tensile_strength"])
    else:
        name = str(x.get("property_class") or "8.8")
        if per_point:
            th.property_class_strengths(name, 0.01)  # refuses an unknown class
            cls = th.PROPERTY_CLASSES[name]
            mm = d * 1e3
            ok = ok & (d <= th.largest_diameter(name) * (1 + 1e-9))
            if np.any(ok & (mm > cls.max_diameter_mm * (1 + 1e-9))):
                widest = float(np.max(d[ok]))
                notes.append(_class_note(name, widest, *th.property_class_strengths(name, widest)))
            small = mm <= cls.size_step_mm * (1 + 1e-9)
            yield_strength = np.where(small, cls.yield_small * 1e6, cls.yield_large * 1e6)
            tensile = np.where(small, cls.tensile_small * 1e6, cls.tensile_large * 1e6)
        else:
            yield_strength, tensile = th.property_class_strengths(name, d)
            note(lambda: _class_note(name, d, yield_strength, tensile))
    given_outer = x.get("bearing_outer_diameter") is not None
    if given_outer:
        outer = num(x["bearing_outer_diameter"])
    elif "bearing_outer_diameter" in cat:
        outer = num(cat["bearing_outer_diameter"])
    elif per_point:
        outer, found = _tabulated(d, th.HEX_BEARING_DIAMETER_MM)
        ok = ok & found
    else:
        outer = th.hex_bearing_diameter(d)
        note(lambda: _hex_bearing_note(outer))
    if x.get("hole_diameter") is not None:
        hole = num(x["hole_diameter"])
        need(
            hole >= d,
            lambda: InputOutOfRange(
                f"hole_diameter d_h = {hole * 1e3:g} mm is smaller than the thread diameter "
                f"d = {d * 1e3:g} mm: the bolt would not pass through the clamped part",
                field="hole_diameter",
            ),
        )
    elif "hole_diameter" in cat:
        hole = num(cat["hole_diameter"])
    else:
        series = str(x.get("hole_series") or "medium")
        if per_point:
            th.clearance_hole(0.012, series)  # refuses an unknown series
            hole, found = _tabulated(d, th.CLEARANCE_HOLE_MM, th.HOLE_SERIES.index(series))
            ok = ok & found
        else:
            hole = th.clearance_hole(d, series)
            note(lambda: _clearance_hole_note(hole, series))
    need(
        outer > hole,
        lambda: InputOutOfRange(
            f"bearing_outer_diameter D_f = {outer * 1e3:g} mm must exceed hole_diameter "
            f"d_h = {hole * 1e3:g} mm: the bearing face would have no area",
            field="bearing_outer_diameter" if given_outer else "hole_diameter",
        ),
    )
    numbers = {
        "diameter": d,
        "pitch": pitch,
        "pitch_diameter": _given_or(cat, "pitch_diameter", th.pitch_diameter, d, pitch),
        "minor_diameter": _given_or(cat, "minor_diameter", th.minor_diameter, d, pitch),
        "stress_diameter": _given_or(cat, "stress_diameter", th.stress_diameter, d, pitch),
        "stress_area": _given_or(cat, "stress_area", th.stress_area, d, pitch),
        "yield_strength": yield_strength,
        "tensile_strength": tensile,
        "bearing_outer_diameter": outer,
        "hole_diameter": hole,
        "bearing_friction_factor": cat.get("bearing_friction_factor", 1.0),
    }
    return numbers, ok


def _given_or(cat: Mapping[str, Any], name: str, relation: Any, d: Any, pitch: Any) -> Any:
    """The catalogue's ``name`` where it has one, else the ISO relation on (d, P)."""
    return cat[name] if name in cat else relation(d, pitch)


#: Bolt inputs whose values, not only whether they are given, the bolt resolution reads.
_BOLT_NUMBERS = (
    "thread_diameter",
    "thread_pitch",
    "yield_strength",
    "bearing_outer_diameter",
    "hole_diameter",
)
#: The numbers of a bolt (:class:`Bolt`, :class:`BoltArrays`), as :func:`_bolt_numbers` gives them.
_NUMBER_FIELDS = (
    "diameter",
    "pitch",
    "pitch_diameter",
    "minor_diameter",
    "stress_diameter",
    "stress_area",
    "yield_strength",
    "tensile_strength",
    "bearing_outer_diameter",
    "hole_diameter",
    "bearing_friction_factor",
)
#: Inputs that name catalogue parts (looked up by the thread size).
_CATALOGUE_INPUTS = ("thread", "grade", "head_standard", "washer", "nut")


@dataclass(frozen=True)
class BoltArrays:
    """A bolt for many points: each number a float (the same everywhere) or an array."""

    diameter: Any
    pitch: Any
    pitch_diameter: Any
    minor_diameter: Any
    stress_diameter: Any
    stress_area: Any
    yield_strength: Any
    tensile_strength: Any
    bearing_outer_diameter: Any
    hole_diameter: Any
    bearing_friction_factor: Any
    fastener: Fastener
    #: Where the scalar :func:`resolve_bolt` would refuse the point: False.
    ok: np.ndarray
    #: The ``fastener`` output: one label, or one per point.
    label: Any
    #: Resolved per distinct size (catalogue parts with a varied size): the bolts, and
    #: each point's index into them; None where one catalogue part serves every point.
    rows: tuple[tuple[Bolt | None, ...], np.ndarray] | None = None

    def at(self, j: int) -> Bolt:
        """The bolt of point ``j``, as :func:`resolve_bolt` gives it for that point alone."""
        if self.rows is not None:
            bolt = self.rows[0][int(self.rows[1][j])]
            assert bolt is not None, "a refused point has no bolt"
            return bolt
        n = self.ok.size
        numbers: dict[str, Any] = {
            f: (
                None
                if v is None
                else float(v)
                if not isinstance(v, np.ndarray) or v.ndim == 0
                else float(np.broadcast_to(v, (n,))[j])
            )
            for f in _NUMBER_FIELDS
            for v in (getattr(self, f),)
        }
        return Bolt(**numbers, fastener=self.fastener)

    def distinct(self) -> tuple[list[Bolt], np.ndarray]:
        """The distinct bolts (thread size and catalogue part) among the points ``ok``
        marks, each at its first such point, and each point's index into them (-1 where
        refused): what a check that reads the bolt as a whole runs once per bolt. The
        index is read-only (one bolt at every point: no array of the points is made)."""
        n = self.ok.size
        one_size = self.rows is None and not any(
            isinstance(v, np.ndarray) and v.ndim for v in (self.diameter, self.pitch)
        )
        if one_size and n and self.ok.all():  # one bolt at every point
            return [self.at(0)], np.broadcast_to(np.int64(0), (n,))
        index = np.full(n, -1, dtype=np.int64)
        good = np.flatnonzero(self.ok)
        if good.size == 0:
            return [], index
        if one_size:
            index[good] = 0
            return [self.at(int(good[0]))], index
        if self.rows is not None:
            keys = np.asarray(self.rows[1]).reshape(-1)[good][:, None]
        else:
            keys = np.column_stack(
                [np.broadcast_to(v, (n,))[good] for v in (self.diameter, self.pitch)]
            )
        _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
        index[good] = np.asarray(inverse).reshape(-1)
        return [self.at(int(good[k])) for k in first], index


def _table_lookup(
    diameter: np.ndarray, table: Mapping[float, Any]
) -> tuple[np.ndarray, np.ndarray]:
    """Index into ``table``'s keys (mm) per diameter [m], and where one matches.

    The match of :func:`engine.physics.threads._size_key` (relative 1e-6), on arrays: the keys
    are far apart, so only the two keys either side of a size can match it.
    """
    keys = np.fromiter(table, dtype=float)
    order = np.argsort(keys)
    ordered = keys[order]
    mm = np.asarray(diameter) * 1e3
    right = np.clip(np.searchsorted(ordered, mm), 0, keys.size - 1)
    left = np.maximum(right - 1, 0)
    near_left = np.abs(mm - ordered[left]) <= 1e-6 * ordered[left]
    near_right = np.abs(mm - ordered[right]) <= 1e-6 * ordered[right]
    index = order[np.where(near_left, left, right)]
    return index, near_left | near_right


def _tabulated(
    diameter: np.ndarray, table: Mapping[float, Any], column: int | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """A per-size table's value [m] (mm × 1e-3) per diameter [m], NaN where not tabulated."""
    index, found = _table_lookup(diameter, table)
    rows = list(table.values())
    mm = np.array([r if column is None else r[column] for r in rows], dtype=float)
    return np.where(found, mm[index] * 1e-3, np.nan), found


def resolve_bolts(
    x: Mapping[str, Any], n: int, labels: bool = True, per_size: bool = False
) -> tuple[BoltArrays, list[str]]:
    """:func:`resolve_bolt` for ``n`` points whose numeric bolt inputs may be arrays.

    Nothing varied: :func:`resolve_bolt` once. Otherwise the catalogue (designation,
    grade, head) is read once and :func:`_bolt_numbers`, the step the single design
    runs, gives every number on arrays, a point the single design refuses marked False
    in ``ok``. A varied thread diameter or pitch together with a catalogue part needs
    the catalogue per size: with ``per_size`` the bolt is resolved once per distinct
    combination of the varied bolt inputs (``rows``); without, ValueError (the caller,
    whose bought-part checks take one catalogue part for every point, evaluates those
    points one by one). ``labels=False`` skips the per-point ``fastener`` labels of a
    varied size. The notes are the catalogue's; a varied size has no note per point.
    """
    ok = np.ones(n, dtype=bool)
    varied = [k for k in _BOLT_NUMBERS if isinstance(x.get(k), np.ndarray)]
    if not varied:
        bolt, bolt_notes = resolve_bolt(x)
        fastener = bolt.fastener or Fastener("", None, None, None)
        numbers = {f: getattr(bolt, f) for f in _NUMBER_FIELDS}
        return (
            BoltArrays(**numbers, fastener=fastener, ok=ok, label=fastener.label),
            bolt_notes,
        )
    size_varied = "thread_diameter" in varied or "thread_pitch" in varied
    if size_varied and any(x.get(k) is not None for k in _CATALOGUE_INPUTS):
        if not per_size or any(np.ndim(x[k]) != 1 for k in varied):
            raise ValueError("a catalogue part with a varied thread size: evaluate point by point")
        return _resolve_per_size(x, n, varied)
    # the catalogue reads only whether these are given, not their values
    placeholder = {**x, **{k: 1.0 for k in varied}}
    cat: dict[str, Any]
    notes: list[str] = []
    if size_varied:
        if x.get("thread_diameter") is None:
            resolve(placeholder)  # refuses: no thread and no diameter
        cat = {"diameter": x["thread_diameter"]}
        fastener = Fastener("", None, None, None)
    else:
        cat, fastener, found_notes = resolve(placeholder)
        notes.extend(found_notes)
    numbers, ok = _bolt_numbers(x, cat, notes, n)
    label: Any = fastener.label
    if size_varied and labels:
        label = _size_labels(x, numbers["diameter"], n)
    return BoltArrays(**numbers, fastener=fastener, ok=ok, label=label), notes


def _resolve_per_size(
    x: Mapping[str, Any], n: int, varied: list[str]
) -> tuple[BoltArrays, list[str]]:
    """:func:`resolve_bolt` once per distinct combination of the ``varied`` bolt inputs.

    A combination it refuses is refused at its points; the notes are the first point's.
    """
    fixed = {k: v for k, v in x.items() if not isinstance(v, np.ndarray)}
    table = np.column_stack([np.asarray(x[k], dtype=float) for k in varied])
    rows, index = np.unique(table, axis=0, return_inverse=True)
    index = np.asarray(index, dtype=np.int64).reshape(n)
    bolts: list[Bolt | None] = []
    notes: list[str] = []
    for k, row in enumerate(rows):
        try:
            bolt, said = resolve_bolt({**fixed, **dict(zip(varied, row.tolist(), strict=True))})
        except EngineError:
            bolts.append(None)
            continue
        bolts.append(bolt)
        if k == index[0]:
            notes = said
    found = [b for b in bolts if b is not None]
    ok = np.array([b is not None for b in bolts], dtype=bool)[index]

    def column(field: str) -> Any:
        if not found or all(getattr(b, field) is None for b in found):
            return None
        return np.array([np.nan if b is None else getattr(b, field) for b in bolts], dtype=float)[
            index
        ]

    numbers = {f: column(f) for f in _NUMBER_FIELDS}
    if numbers["diameter"] is None:
        numbers = {f: np.full(n, np.nan) for f in _NUMBER_FIELDS}
    label = np.array(
        [None if b is None or b.fastener is None else b.fastener.label for b in bolts],
        dtype=object,
    )[index]
    fastener = (found[0].fastener if found else None) or Fastener("", None, None, None)
    return (
        BoltArrays(**numbers, fastener=fastener, ok=ok, label=label, rows=(tuple(bolts), index)),
        notes,
    )


def _size_labels(x: Mapping[str, Any], diameter: Any, n: int) -> np.ndarray:
    """The ``fastener`` label per point for a varied numeric thread size (no catalogue part).

    As :func:`engine.procedures.bolt.resolve` writes it: the ISO designation where the
    size is a catalogue thread, else "d = … mm", then the property class.
    """
    cls = str(x.get("property_class") or "8.8")
    d = np.broadcast_to(np.asarray(diameter, dtype=float), (n,))
    p_in = x.get("thread_pitch")
    p = None if p_in is None else np.broadcast_to(np.asarray(p_in, dtype=float), (n,))
    _, near = _table_lookup(d, fa.METRIC_COARSE_PITCH_MM)
    out = np.empty(n, dtype=object)
    out[:] = list(map(f"d = %g mm {cls}".__mod__, (d * 1e3).tolist()))
    for j in np.flatnonzero(near).tolist():
        thread = _catalogue_thread(float(d[j]), None if p is None else float(p[j]))
        if thread is not None:
            out[j] = f"{thread.designation} {cls}"
    return out


class _Parts(NamedTuple):
    """The numbers of the bought-part checks, on floats (one design) or arrays (many)."""

    values: dict[str, Any]
    #: Per check name, whether the design passes (bool or bool array).
    verdicts: dict[str, Any]
    outer: Any
    inner: Any
    washer: fa.Washer | None
    nut: fa.Nut | None
    pressures: dict[str, Any]
    limit: Any
    limit_material: fa.Material | None
    working_force: Any
    tau: Any
    tau_source: str
    stripping: fa.Stripping | None
    length: Any
    key_limit: float | None
    #: The nut's bearing face: its d_W, or the nut-side plate's D_A where that is smaller.
    nut_outer: Any = None


def _bought_parts(
    x: Mapping[str, Any],
    fastener: Fastener,
    *,
    diameter: Any,
    pitch: Any,
    pitch_diameter: Any,
    stress_area: Any,
    tensile_strength: Any,
    bearing_outer_diameter: Any,
    hole_diameter: Any,
    max_assembly_preload: Any,
    tightening_torque: Any,
    working_force: Any = None,
    nut_outer_diameter: Any = None,
) -> _Parts:
    """Surface pressure (VDI 2230-1 R10), thread stripping (R11) and the hex key (ISO 2936).

    The one set of lines :func:`bought_part_checks` (one design, with its sentences) and
    :func:`bought_part_verdicts` (many designs) both run; the numbers may be floats or
    numpy arrays, the catalogue parts are the same for every design. ``nut_outer_diameter``
    (D_A of the plate under the nut, None: wide) caps the nut's bearing face: the nut bears
    on min(d_W,nut, D_A) (VDI 2230-1 R10, A_p of the face that carries).
    """
    values: dict[str, Any] = {"fastener": fastener.label}
    verdicts: dict[str, Any] = {}
    thread = fastener.thread
    outer, inner, washer = bearing_outer_diameter, hole_diameter, None
    if x.get("washer") is not None:
        if thread is None:
            raise InputOutOfRange("washer needs a catalogue thread (give thread)", field="washer")
        washer = fa.washer(str(x["washer"]), thread, field="washer")
        outer, inner = washer.outer_diameter, np.maximum(washer.inner_diameter, hole_diameter)
    values["bearing_area"] = fa.bearing_area(outer, inner)
    pressures: dict[str, Any] = {
        "surface_pressure_assembly": fa.surface_pressure(max_assembly_preload, outer, inner)
    }
    values["surface_pressure_head"] = pressures["surface_pressure_assembly"]
    if working_force is None and x.get("working_bolt_force") is not None:
        working_force = x["working_bolt_force"]
    if working_force is not None:
        pressures["surface_pressure_working"] = fa.surface_pressure(working_force, outer, inner)
        values["surface_pressure_head_working"] = pressures["surface_pressure_working"]
    nut = None
    if x.get("nut") is not None:
        if thread is None:
            raise InputOutOfRange("nut needs a catalogue thread (give thread)", field="nut")
        nut = fa.nut(str(x["nut"]), thread, field="nut")
        nut_outer: Any = nut.bearing_diameter
        if nut_outer_diameter is not None:
            nut_outer = np.minimum(nut_outer, nut_outer_diameter)
            nut_outer = nut_outer if isinstance(nut_outer, np.ndarray) else float(nut_outer)
        pressures["surface_pressure_nut"] = fa.surface_pressure(
            max_assembly_preload, nut_outer, hole_diameter
        )
        values["surface_pressure_nut"] = pressures["surface_pressure_nut"]
    limit: Any = None
    material = None
    if x.get("limiting_surface_pressure") is not None:
        limit = x["limiting_surface_pressure"]
    elif x.get("clamped_material") is not None:
        material = fa.material(str(x["clamped_material"]), field="clamped_material")
        limit = material.limiting_surface_pressure
    if limit is not None:
        values["limiting_surface_pressure"] = limit
        for name, p in pressures.items():
            verdicts[name] = p <= limit
    tau: Any = None
    tau_source = ""
    if x.get("internal_thread_shear_strength") is not None:
        tau, tau_source = x["internal_thread_shear_strength"], "as given"
    elif x.get("internal_thread_material") is not None:
        inner_material = fa.material(
            str(x["internal_thread_material"]), field="internal_thread_material"
        )
        tau, tau_source = inner_material.shear_strength, inner_material.name
    stripping = None
    length = x["engagement_length"] if x.get("engagement_length") is not None else 1.0
    if tau is not None and tensile_strength is not None:
        stripping = fa.engagement_for_bolt_failure(
            diameter,
            pitch,
            pitch_diameter,
            diameter - 1.082532 * pitch,
            stress_area,
            tensile_strength,
            BOLT_SHEAR_RATIO * tensile_strength,
            tau,
            length,
        )
        values["min_engagement_length"] = stripping.min_engagement_length
        values["bolt_breaking_force"] = stripping.bolt_breaking_force
        if x.get("engagement_length") is not None:
            values["stripping_force"] = stripping.strip_force
            verdicts["thread_stripping"] = length >= stripping.min_engagement_length
    key_limit = None
    head = fastener.head
    if head is not None and head.drive == "hex key" and tightening_torque is not None:
        key_limit = fa.hex_key_torque(head.drive_size)
        if key_limit is not None:
            values["drive_torque_limit"] = key_limit
            verdicts["drive_torque"] = tightening_torque <= key_limit
    return _Parts(
        values,
        verdicts,
        outer,
        inner,
        washer,
        nut,
        pressures,
        limit,
        material,
        working_force,
        tau,
        tau_source,
        stripping,
        length,
        key_limit,
        None if nut is None else nut_outer,
    )


def bought_part_checks(
    x: Mapping[str, Any],
    fastener: Fastener,
    *,
    diameter: float,
    pitch: float,
    pitch_diameter: float,
    stress_area: float,
    tensile_strength: float | None,
    bearing_outer_diameter: float,
    hole_diameter: float,
    max_assembly_preload: float,
    tightening_torque: float | None,
    working_force: float | None = None,
    nut_outer_diameter: float | None = None,
) -> tuple[dict[str, Any], list[Check], list[str]]:
    """Surface pressure, thread stripping and drive torque of the bolt a request describes.

    ``working_force`` (F_S,max from a joint model) stands in for the
    ``working_bolt_force`` input; without ``tightening_torque`` the drive is not checked.
    The numbers are :func:`_bought_parts`'; this adds the sentences.
    """
    parts = _bought_parts(
        x,
        fastener,
        diameter=diameter,
        pitch=pitch,
        pitch_diameter=pitch_diameter,
        stress_area=stress_area,
        tensile_strength=tensile_strength,
        bearing_outer_diameter=bearing_outer_diameter,
        hole_diameter=hole_diameter,
        max_assembly_preload=max_assembly_preload,
        tightening_torque=tightening_torque,
        working_force=working_force,
        nut_outer_diameter=nut_outer_diameter,
    )
    values, verdicts = parts.values, parts.verdicts
    checks: list[Check] = []
    notes: list[str] = []

    # --- surface pressure under head (or washer) and nut, VDI 2230-1 R10
    where = "head"
    if parts.washer is not None:
        where = f"washer {parts.washer.standard}"
        notes.append(
            f"the clamped part bears on the {parts.washer.standard} washer: d = "
            f"{q(parts.inner, 'mm', bare=True)}…{q(parts.outer, 'mm')} (taken as spreading "
            "over its whole face; true for a hardened washer, optimistic for a thin soft one)"
        )
    if parts.nut is not None and parts.nut.standard == "ISO 4035":
        notes.append(
            "ISO 4035 thin nuts (classes 04/05) carry less than the bolt's proof load "
            "(ISO 898-2): the bolt cannot be used to its strength"
        )
    limit = parts.limit
    if limit is not None:
        material = parts.limit_material
        src = "as given" if material is None else f"{material.name}, {material.source}"
        if material is not None and material.kind == "plastic":
            notes.append(
                f"{material.name}: plastics creep under a bolt head; p_G here is a short-time "
                "compressive yield at 23 °C, so the preload will relax: use a metal sleeve or "
                "give limiting_surface_pressure for your grade and temperature"
            )
        for name, p in parts.pressures.items():
            face = "nut" if name == "surface_pressure_nut" else where
            area = values["bearing_area"]
            if face == "nut":
                area = fa.bearing_area(parts.nut_outer, hole_diameter)
            force_name = "F_S,max" if name == "surface_pressure_working" else "F_M,max"
            ok = bool(verdicts[name])
            need = parts.working_force if force_name == "F_S,max" else max_assembly_preload
            checks.append(
                Check(
                    name,
                    ok,
                    f"surface pressure under the {face} at {force_name}: "
                    f"{q(p, 'MPa', 4)} vs p_G = {q(limit, 'MPa', 4)} ({src}; "
                    "VDI 2230-1 R10)"
                    + (
                        ""
                        if ok
                        else f": needs a bearing area ≥ {q(need / limit, 'mm²', 4)} (now "
                        f"{q(area, 'mm²', 4)}): a washer (ISO 7093), a flange head (EN 1665) "
                        "or a lower preload"
                    ),
                )
            )
    else:
        notes.append(
            "surface pressure not checked: give clamped_material or limiting_surface_pressure"
        )

    # --- thread stripping, VDI 2230-1 R11 (tapped hole)
    s = parts.stripping
    if parts.tau is not None and tensile_strength is None:
        notes.append(
            "thread stripping not checked: R_m of the bolt is unknown (yield_strength given); "
            "give property_class or grade"
        )
    elif s is not None:
        notes.append(
            f"thread stripping (VDI 2230-1 R11 after Alexander): τ_BM = "
            f"{q(parts.tau, 'MPa', 4)} ({parts.tau_source}), τ_BS = "
            f"{BOLT_SHEAR_RATIO:g} R_m, R_S = {s.strength_ratio:.3g}, C1 = {s.c1:.3g} (tapped "
            f"hole), C2 = {s.c2:.3g}, C3 = {s.c3:.3g}; the {s.weaker} thread is the weaker; "
            f"F_B at the bolt's upper strength {fa.BOLT_UPPER_STRENGTH_FACTOR:g} R_m; lengths "
            f"include {fa.ENTRY_CHAMFER_PITCHES:g} P for the entry chamfers"
        )
        if "thread_stripping" in verdicts:
            ok, length = bool(verdicts["thread_stripping"]), parts.length
            checks.append(
                Check(
                    "thread_stripping",
                    ok,
                    f"engagement {q(length, 'mm')} vs the "
                    f"{q(s.min_engagement_length, 'mm')} needed for the bolt "
                    f"({q(s.bolt_breaking_force, 'kN', 4)}) to break before the "
                    f"{s.weaker} thread strips ({q(s.strip_force, 'kN', 4)} at this "
                    "length)"
                    + (
                        ""
                        if ok
                        else f": engage at least {q(s.min_engagement_length, 'mm')} of "
                        "thread (chamfers included), use a thread insert, or a stronger "
                        "internal-thread "
                        "material"
                    ),
                )
            )
    elif x.get("engagement_length") is not None:
        notes.append(
            "engagement_length given without internal_thread_material or "
            "internal_thread_shear_strength: stripping not checked"
        )

    # --- drive torque, ISO 2936 hex keys
    if "drive_torque" in verdicts:
        head = fastener.head
        key_limit = parts.key_limit
        assert head is not None and tightening_torque is not None and key_limit is not None
        ok = bool(verdicts["drive_torque"])
        checks.append(
            Check(
                "drive_torque",
                ok,
                f"tightening torque {q(tightening_torque, 'N*m')} vs "
                f"{q(key_limit, 'N*m', fmt='g')}, the "
                f"ISO 2936 test torque of the {head.drive_size * 1e3:g} mm hex key of the "
                f"{head.standard} head"
                + (
                    ""
                    if ok
                    else ": the key or the socket fails first; lower the preload, or use a "
                    "head with a larger drive (ISO 4762 instead of ISO 10642, or a hexagon "
                    "head)"
                ),
            )
        )
    return values, checks, notes


def bought_part_verdicts(
    x: Mapping[str, Any],
    fastener: Fastener,
    *,
    diameter: Any,
    pitch: Any,
    pitch_diameter: Any,
    stress_area: Any,
    tensile_strength: Any,
    bearing_outer_diameter: Any,
    hole_diameter: Any,
    max_assembly_preload: Any,
    tightening_torque: Any,
    working_force: Any = None,
) -> tuple[dict[str, Any], dict[str, Any]]:
    """:func:`bought_part_checks` for many designs at once: the values and the check verdicts.

    The numbers (and the inputs in ``x``) may be numpy arrays, one design per element;
    the catalogue choices (thread, head, washer, nut, materials) are the same for every
    design. The same lines (:func:`_bought_parts`) as one design, without the sentences.
    """
    parts = _bought_parts(
        x,
        fastener,
        diameter=diameter,
        pitch=pitch,
        pitch_diameter=pitch_diameter,
        stress_area=stress_area,
        tensile_strength=tensile_strength,
        bearing_outer_diameter=bearing_outer_diameter,
        hole_diameter=hole_diameter,
        max_assembly_preload=max_assembly_preload,
        tightening_torque=tightening_torque,
        working_force=working_force,
    )
    return parts.values, {k: np.asarray(v) for k, v in parts.verdicts.items()}


def joint_check_hook(x: Mapping[str, Any], solution: Any) -> tuple[list[Check], list[str]]:
    """The bought-part checks for a solved joint (a ``CHECK_HOOKS`` entry of the joint model).

    ``solution`` has ``bolt`` (the preload models' resolved bolt),
    ``bearing_diameter``, ``hole_diameter``, ``assembly_preload_max`` and
    ``max_bolt_force`` (F_S,max), and may have ``nut_outer_diameter`` (D_A of the plate
    under the nut): surface pressure at both (VDI 2230-1 R10) and
    the engagement (R11), and the hex key against the joint's
    ``tightening_torque`` specification when one is given.
    """
    bolt = solution.bolt
    fastener = getattr(bolt, "fastener", None) or Fastener("", None, None, None)
    _, checks, notes = bought_part_checks(
        x,
        fastener,
        diameter=bolt.diameter,
        pitch=bolt.pitch,
        pitch_diameter=bolt.pitch_diameter,
        stress_area=bolt.stress_area,
        tensile_strength=bolt.tensile_strength,
        bearing_outer_diameter=solution.bearing_diameter,
        hole_diameter=solution.hole_diameter,
        max_assembly_preload=solution.assembly_preload_max,
        tightening_torque=None
        if x.get("tightening_torque") is None
        else float(x["tightening_torque"]),
        working_force=solution.max_bolt_force,
        nut_outer_diameter=getattr(solution, "nut_outer_diameter", None),
    )
    head = fastener.head
    style = x.get("head")
    if head is not None and style in ("hex", "socket"):
        wanted = "socket" if head.style in ("socket", "countersunk") else "hex"
        if style != wanted:
            notes.append(
                f"head = {style!r} (the head's compliance, VDI 2230-1 R3) while the designation "
                f"names a {head.style} head ({head.standard}): set head = {wanted!r}"
            )
    return checks, notes


__all__ = [
    "CHECK_INPUTS",
    "CHECK_OUTPUTS",
    "SOURCE_TEXT",
    "THREAD_INPUTS",
    "Bolt",
    "BoltArrays",
    "Fastener",
    "bought_part_checks",
    "bought_part_verdicts",
    "joint_check_hook",
    "resolve",
    "resolve_bolt",
    "resolve_bolts",
]
