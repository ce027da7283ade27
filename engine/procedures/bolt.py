"""Fasteners as bought, for the preload models: designation inputs and the bought-part checks.

The catalogue and the relations live in :mod:`engine.physics.fasteners`; this module
declares the inputs that name a catalogue part (``thread``, ``grade``,
``head_standard``, ``nut``, ``washer``, materials), resolves them into the numbers the
preload models need, and adds the checks of a bought fastener: surface
pressure under head and nut/washer (VDI 2230-1 R10), thread stripping
(VDI 2230-1 R11 after Alexander) and the hex-key drive torque (ISO 2936).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.errors import InputOutOfRange
from ..core.params import positive, quantity
from ..core.spec import Check, Output, Param
from ..physics import fasteners as fa

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
    Output("fastener", "1", "The fastener resolved from the inputs", kind="str"),
    Output(
        "surface_pressure_head",
        "Pa",
        "Surface pressure under the head (or washer) at the largest assembly preload, "
        "p = F_M,max / A_p (VDI 2230-1 R10)",
        display_unit="MPa",
    ),
    Output(
        "surface_pressure_head_working",
        "Pa",
        "Surface pressure under the head (or washer) at working_bolt_force (VDI 2230-1 R10)",
        display_unit="MPa",
    ),
    Output(
        "surface_pressure_nut",
        "Pa",
        "Surface pressure under the nut at the largest assembly preload (VDI 2230-1 R10)",
        display_unit="MPa",
    ),
    Output(
        "limiting_surface_pressure",
        "Pa",
        "Limiting surface pressure p_G used (clamped_material or as given)",
        display_unit="MPa",
    ),
    Output("bearing_area", "m^2", "Bearing area A_p on the clamped part under the head/washer"),
    Output(
        "min_engagement_length",
        "m",
        "Shortest engagement, entry chamfers (2P) included, for which a bolt at its upper "
        "strength 1.2 R_m breaks before a thread strips (VDI 2230-1 R11, Alexander)",
        display_unit="mm",
    ),
    Output(
        "stripping_force",
        "N",
        "Force that strips the weaker thread at engagement_length (VDI 2230-1 R11)",
        display_unit="kN",
    ),
    Output(
        "bolt_breaking_force",
        "N",
        "1.2 R_m A_s: the upper breaking force the threads must exceed (VDI 2230-1 R11)",
        display_unit="kN",
    ),
    Output(
        "drive_torque_limit",
        "N*m",
        "Test torque of the hex key the head takes (ISO 2936): the drive's limit",
    ),
)


@dataclass(frozen=True)
class Fastener:
    """What the catalogue says about the bolt of a request (None where it does not know)."""

    label: str
    thread: fa.Thread | None
    head: fa.Head | None
    grade: fa.Grade | None


def _catalogue_thread(d: float, pitch: float | None) -> fa.Thread | None:
    """The catalogue's metric thread for a numeric diameter/pitch, or None."""
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
        if t.is_metric:
            notes.append(
                f"thread {t.designation}: P = {t.pitch * 1e3:g} mm (ISO 261/262), "
                f"A_s = {t.stress_area * 1e6:.4g} mm² (ISO 898-1)"
            )
        else:
            notes.append(
                f"thread {t.designation}: d = {t.diameter / fa.INCH:g} in, "
                f"E = {t.pitch_diameter / fa.INCH:.4f} in, "
                f"A_t = {t.stress_area / fa.INCH**2:.4f} in² "
                "(ASME B1.1); minor diameter d − 1.299038 p"
            )
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
                f"grade {grade.name} ({grade.standard}) at d = {d * 1e3:.4g} mm: "
                f"yield {quantity(grade.yield_strength, 'MPa', '.4g')}, "
                f"R_m {quantity(grade.tensile_strength, 'MPa', '.4g')} (minimum values)"
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
            notes.append(
                f"bearing face D_f = {what} = {head.bearing_diameter * 1e3:.4g} mm ({std})"
            )
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
                f"clearance hole d_h = {fields['hole_diameter'] * 1e3:g} mm (ISO 273 {series})"
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


@dataclass(frozen=True)
class _Parts:
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
) -> _Parts:
    """Surface pressure (VDI 2230-1 R10), thread stripping (R11) and the hex key (ISO 2936).

    The one set of lines :func:`bought_part_checks` (one design, with its sentences) and
    :func:`bought_part_arrays` (many designs) both run; the numbers may be floats or
    numpy arrays, the catalogue parts are the same for every design.
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
        pressures["surface_pressure_nut"] = fa.surface_pressure(
            max_assembly_preload, nut.bearing_diameter, hole_diameter
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
            f"{parts.inner * 1e3:.3g}…{parts.outer * 1e3:.3g} mm (taken as spreading over its "
            "whole face; true for a hardened washer, optimistic for a thin soft one)"
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
        area = values["bearing_area"]
        for name, p in parts.pressures.items():
            face = "nut" if name == "surface_pressure_nut" else where
            force_name = "F_S,max" if name == "surface_pressure_working" else "F_M,max"
            ok = bool(verdicts[name])
            need = parts.working_force if force_name == "F_S,max" else max_assembly_preload
            checks.append(
                Check(
                    name,
                    ok,
                    f"surface pressure under the {face} at {force_name}: "
                    f"{quantity(p, 'MPa', '.4g')} vs p_G = {quantity(limit, 'MPa', '.4g')} ({src}; "
                    "VDI 2230-1 R10)"
                    + (
                        ""
                        if ok
                        else f": needs a bearing area ≥ {need / limit * 1e6:.4g} mm² (now "
                        f"{area * 1e6:.4g} mm²): a washer (ISO 7093), a flange head (EN 1665) "
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
            f"{quantity(parts.tau, 'MPa', '.4g')} ({parts.tau_source}), τ_BS = "
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
                    f"engagement {quantity(length, 'mm')} vs the "
                    f"{quantity(s.min_engagement_length, 'mm')} needed for the bolt "
                    f"({quantity(s.bolt_breaking_force, 'kN', '.4g')}) to break before the "
                    f"{s.weaker} thread strips ({quantity(s.strip_force, 'kN', '.4g')} at this "
                    "length)"
                    + (
                        ""
                        if ok
                        else f": engage at least {quantity(s.min_engagement_length, 'mm')} of "
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
        assert head is not None and tightening_torque is not None
        ok = bool(verdicts["drive_torque"])
        checks.append(
            Check(
                "drive_torque",
                ok,
                f"tightening torque {tightening_torque:.3g} N·m vs {parts.key_limit:g} N·m, the "
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


def bought_part_arrays(
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
    ``max_bolt_force`` (F_S,max): surface pressure at both (VDI 2230-1 R10) and
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
    "Fastener",
    "bought_part_arrays",
    "bought_part_checks",
    "joint_check_hook",
    "resolve",
]
