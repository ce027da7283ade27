"""Model specs for preload selection (``preload.tightening``) and its control (``preload.control``).

The physics lives in :mod:`engine.preload`, the bolt data in
:mod:`engine.threads` and the control methods in :mod:`engine.preload_methods`;
this module turns a request into a bolt (standard values unless overridden),
calls those functions and says where every number came from.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

from .. import joint as jt
from .. import preload as pl
from .. import threads as th
from ..errors import EngineError, InputOutOfRange
from ..preload_methods import METHOD_KEYS, METHODS, ControlMethod, get_method
from ..spec import Check, ModelSpec, Output, Param, Plot, Result, RunContext, Rung
from . import _fasteners as fz
from ._common import count, friction_coefficient

SOURCE = (
    "[004] review of preload selection and tightening control, eq. 2–19, "
    "fig. 1–9; VDI 2230-1:2015 steps R7 and R13, Table A8;"
    " ISO 68-1, ISO 261, ISO 273, ISO 898-1, ISO 4017; " + fz.SOURCE_TEXT
)

#: Angle-reading error of [004] (10…15°), taken at its upper end.
ANGLE_READING_ERROR = math.radians(15.0)

# --------------------------------------------------------------------------- inputs

BOLT_INPUTS: tuple[Param, ...] = (
    *fz.THREAD_INPUTS,
    Param(
        "thread_diameter",
        "m",
        "Nominal thread diameter d, when no thread designation is given (ISO 261 M3…M39 "
        "have tabulated data; other sizes need thread_pitch, bearing_outer_diameter, "
        "hole_diameter and yield_strength)",
        maximum=1.0,
        display_unit="mm",
        symbol="d",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "thread_pitch",
        "m",
        "Thread pitch P; ISO 261 coarse pitch when absent",
        maximum=0.1,
        display_unit="mm",
        symbol="P",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "property_class",
        "1",
        "ISO 898-1 property class: minimum yield and tensile strength (8.8: 640/800 MPa "
        "up to M16, 660/830 MPa above)",
        default="8.8",
        kind="choice",
        choices=th.PROPERTY_CLASS_NAMES,
        group="bolt",
    ),
    Param(
        "yield_strength",
        "Pa",
        "Minimum yield strength R_p0.2 (σ_T in [004]); overrides the property class",
        maximum=5e9,
        display_unit="MPa",
        symbol="R_p0.2",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    friction_coefficient(
        "thread_friction",
        "Thread friction coefficient μ_G (f_p in [004])",
        default=0.12,
        recommended=(0.04, 0.4),
        symbol="μ_G",
        group="friction",
    ),
    friction_coefficient(
        "bearing_friction",
        "Bearing-face friction coefficient μ_K (f_T in [004])",
        default=0.12,
        recommended=(0.04, 0.4),
        symbol="μ_K",
        group="friction",
    ),
    Param(
        "bearing_outer_diameter",
        "m",
        "Outer diameter D_f of the bearing face; ISO 4017 hexagon head d_w,min when absent",
        maximum=2.0,
        display_unit="mm",
        symbol="D_f",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "hole_diameter",
        "m",
        "Clearance-hole diameter d_h (inner diameter of the bearing face); ISO 273 of "
        "hole_series when absent",
        minimum=0.0,
        maximum=2.0,
        display_unit="mm",
        symbol="d_h",
        group="bolt",
    ),
    Param(
        "hole_series",
        "1",
        "ISO 273 clearance-hole series used when hole_diameter is absent",
        default="medium",
        kind="choice",
        choices=th.HOLE_SERIES,
        group="bolt",
    ),
    Param(
        "utilization",
        "1",
        "ν: share of the yield strength the equivalent stress may use at assembly "
        "(VDI 2230: 0.9; [004, eq. 3]: ξ/n_T, 0.71…0.83)",
        default=0.9,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        symbol="ν",
        group="preload",
    ),
    Param(
        "preload_convention",
        "1",
        "'vdi2230': β of VDI 2230 step R7 (plastic torsion, factor 3/2); "
        "'elastic': β of [004, eq. 5] with τ/σ = 2(d2/d0)·tan(ψ+ρ')",
        default="vdi2230",
        kind="choice",
        choices=("vdi2230", "elastic"),
        group="preload",
    ),
    Param(
        "torque_formula",
        "1",
        "'vdi2230': M_A = F(0.16P + 0.58 d2 μ_G + μ_K D_Km/2); 'exact': [004, eq. 10–13] "
        "with the annular friction radius; 'approx': [004, eq. 15/19] with d2 ≈ d",
        default="vdi2230",
        kind="choice",
        choices=("vdi2230", "exact", "approx"),
        group="preload",
    ),
    Param(
        "preload",
        "N",
        "Preload F0 to use instead of the largest permissible assembly preload",
        maximum=1e8,
        display_unit="kN",
        symbol="F0",
        group="preload",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    *fz.CHECK_INPUTS,
)

# --------------------------------------------------------------------------- the bolt


@dataclass(frozen=True)
class Bolt:
    """A bolt resolved from a request: standard data unless overridden [m, m², Pa]."""

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
    #: μ_K multiplier of the bearing face (1/sin 45° on a countersunk head, issue 15).
    bearing_friction_factor: float = 1.0
    #: The catalogue's fastener (thread, head, grade) where the request names one.
    fastener: fz.Fastener | None = None


def resolve_bolt(x: Mapping[str, Any]) -> tuple[Bolt, list[str]]:
    """The bolt a request describes, and notes naming each standard value used."""
    cat, fastener, notes = fz.resolve(x)
    d = float(cat["diameter"])
    mm = d * 1e3
    if "pitch" in cat:
        pitch = float(cat["pitch"])
    elif x.get("thread_pitch") is None:
        pitch = th.coarse_pitch(d)
        notes.append(f"pitch P = {pitch * 1e3:g} mm: ISO 261 coarse thread M{mm:g}")
    else:
        pitch = float(x["thread_pitch"])
        if d - 1.226869 * pitch <= 0.0:
            raise InputOutOfRange(
                f"thread_pitch = {pitch * 1e3:g} mm is too coarse for d = {mm:g} mm: the "
                f"minor diameter d3 = d − 1.226869 P must stay > 0 (P < {d / 1.226869 * 1e3:g} mm)",
                field="thread_pitch",
            )
    if x.get("yield_strength") is not None:
        yield_strength, tensile = float(x["yield_strength"]), None
        notes.append(f"yield strength R_p0.2 = {yield_strength / 1e6:g} MPa as given")
    elif "yield_strength" in cat:
        yield_strength, tensile = float(cat["yield_strength"]), float(cat["tensile_strength"])
    else:
        cls = str(x.get("property_class") or "8.8")
        yield_strength, tensile = th.property_class_strengths(cls, d)
        kind = th.PROPERTY_CLASSES[cls].yield_kind
        notes.append(
            f"property class {cls}, d = {mm:g} mm: {kind} = {yield_strength / 1e6:g} MPa, "
            f"R_m = {tensile / 1e6:g} MPa (ISO 898-1 minimum values)"
        )
    given_outer = x.get("bearing_outer_diameter") is not None
    if given_outer:
        outer = float(x["bearing_outer_diameter"])
    elif "bearing_outer_diameter" in cat:
        outer = float(cat["bearing_outer_diameter"])
    else:
        outer = th.hex_bearing_diameter(d)
        notes.append(f"bearing face D_f = d_w,min = {outer * 1e3:g} mm (ISO 4017 hexagon head)")
    if x.get("hole_diameter") is not None:
        hole = float(x["hole_diameter"])
        if hole < d:
            raise InputOutOfRange(
                f"hole_diameter d_h = {hole * 1e3:g} mm is smaller than the thread diameter "
                f"d = {d * 1e3:g} mm: the bolt would not pass through the clamped part",
                field="hole_diameter",
            )
    elif "hole_diameter" in cat:
        hole = float(cat["hole_diameter"])
    else:
        series = str(x.get("hole_series") or "medium")
        hole = th.clearance_hole(d, series)
        notes.append(f"clearance hole d_h = {hole * 1e3:g} mm (ISO 273 {series})")
    if outer <= hole:
        field = "bearing_outer_diameter" if given_outer else "hole_diameter"
        raise InputOutOfRange(
            f"bearing_outer_diameter D_f = {outer * 1e3:g} mm must exceed hole_diameter "
            f"d_h = {hole * 1e3:g} mm: the bearing face would have no area",
            field=field,
        )
    return (
        Bolt(
            diameter=d,
            pitch=pitch,
            pitch_diameter=cat.get("pitch_diameter", th.pitch_diameter(d, pitch)),
            minor_diameter=cat.get("minor_diameter", th.minor_diameter(d, pitch)),
            stress_diameter=cat.get("stress_diameter", th.stress_diameter(d, pitch)),
            stress_area=cat.get("stress_area", th.stress_area(d, pitch)),
            yield_strength=yield_strength,
            tensile_strength=tensile,
            bearing_outer_diameter=outer,
            hole_diameter=hole,
            bearing_friction_factor=cat.get("bearing_friction_factor", 1.0),
            fastener=fastener,
        ),
        notes,
    )


def torque_coefficients(
    bolt: Bolt, thread_friction: float, bearing_friction: float, formula: str
) -> tuple[float, float, float]:
    """(k_G, k_K, R) of the chosen torque formula: torques per newton and the friction radius."""
    k_thread, k_bearing = pl.tightening_torque_per_preload(
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.diameter,
        thread_friction,
        bearing_friction * bolt.bearing_friction_factor,
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        formula,
    )
    if formula == "exact":
        radius = pl.friction_radius(bolt.bearing_outer_diameter, bolt.hole_diameter)
    else:
        radius = 0.25 * (bolt.bearing_outer_diameter + bolt.hole_diameter)
    return float(k_thread), float(k_bearing), float(radius)


def _torsion(bolt: Bolt, x: Mapping[str, Any]) -> float:
    return float(
        pl.torsion_factor(
            bolt.pitch,
            bolt.pitch_diameter,
            bolt.stress_diameter,
            float(x["thread_friction"]),
            str(x["preload_convention"]),
        )
    )


def _formula_deviation(bolt: Bolt, x: Mapping[str, Any]) -> float:
    """Relative difference of the chosen torque formula from the exact [004, eq. 10–13]."""
    mu_g, mu_k = float(x["thread_friction"]), float(x["bearing_friction"])
    chosen = sum(torque_coefficients(bolt, mu_g, mu_k, str(x["torque_formula"]))[:2])
    exact = sum(torque_coefficients(bolt, mu_g, mu_k, "exact")[:2])
    return abs(chosen - exact) / exact


def _rung_estimate(x: Mapping[str, Any]) -> float | None:
    try:
        bolt, _ = resolve_bolt(x)
        return _formula_deviation(bolt, x)
    except (EngineError, KeyError, TypeError, ValueError):
        return None


CLOSED_FORM = Rung(
    "closed_form",
    "Closed-form relations; the error estimate is how far the chosen torque formula lies "
    "from the exact thread and annular-face relations of [004, eq. 10–13] for these inputs "
    "(0 for 'exact'). It does not include the scatter of the friction coefficients, which "
    "dominates in practice (±30 % at a fixed torque, [004, fig. 5]).",
    _rung_estimate,
    typical_error="0 (exact) … ~1 % (vdi2230) … a few % (approx), against the exact relations",
    typical_time="< 1 ms",
)

# --------------------------------------------------------------------------- tightening


def _add_bought_part_checks(
    x: Mapping[str, Any],
    bolt: Bolt,
    max_preload: float,
    torque: float,
    values: dict[str, Any],
    checks: list[Check],
    notes: list[str],
) -> None:
    """Surface pressure, thread stripping and drive torque (issue 15), into the result."""
    fastener = bolt.fastener or fz.Fastener("", None, None, None)
    more, more_checks, more_notes = fz.bought_part_checks(
        x,
        fastener,
        diameter=bolt.diameter,
        pitch=bolt.pitch,
        pitch_diameter=bolt.pitch_diameter,
        stress_area=bolt.stress_area,
        tensile_strength=bolt.tensile_strength,
        bearing_outer_diameter=bolt.bearing_outer_diameter,
        hole_diameter=bolt.hole_diameter,
        max_assembly_preload=max_preload,
        tightening_torque=torque,
    )
    values.update(more)
    checks.extend(more_checks)
    notes.extend(more_notes)


def _tightening(x: Mapping[str, Any], ctx: RunContext) -> Result:
    bolt, notes = resolve_bolt(x)
    warnings: list[str] = []
    checks: list[Check] = []
    mu_g, mu_k = float(x["thread_friction"]), float(x["bearing_friction"])
    nu, formula = float(x["utilization"]), str(x["torque_formula"])
    beta = _torsion(bolt, x)
    permissible = pl.assembly_preload(bolt.yield_strength, bolt.stress_area, beta, nu)
    if x.get("preload") is not None:
        force = float(x["preload"])
        notes.append(f"preload F0 = {force / 1e3:.4g} kN as given (not the permissible one)")
    else:
        force = permissible
    sigma_eq = pl.equivalent_stress(force, bolt.stress_area, beta)
    k_thread, k_bearing, radius = torque_coefficients(bolt, mu_g, mu_k, formula)
    m_thread, m_bearing = force * k_thread, force * k_bearing
    total = m_thread + m_bearing
    ideal = pl.ideal_torque(force, bolt.pitch)
    thumb = pl.rule_of_thumb_torque(force, bolt.diameter)
    thumb_yield = pl.rule_of_thumb_torque_from_yield(bolt.yield_strength, bolt.diameter)
    deviation = _formula_deviation(bolt, x)
    share = ideal / total if total > 0 else 1.0
    if x.get("preload") is not None:
        ok = sigma_eq <= bolt.yield_strength
        checks.append(
            Check(
                "below_yield",
                ok,
                f"equivalent stress {sigma_eq / 1e6:.4g} MPa is "
                f"{sigma_eq / bolt.yield_strength:.1%} of the yield strength"
                + ("" if ok else ": lower the preload, or choose a stronger property class"),
            )
        )
    if not 0.05 <= share <= 0.15:
        notes.append(
            f"the frictionless torque is {share:.1%} of the total; [004, eq. 14] says "
            "5…15 % is usual"
        )
    if x["preload_convention"] == "elastic":
        notes.append(
            f"elastic convention [004, eq. 3, 5]: ν = ξ/n_T; with a plain shank (ξ = 1) "
            f"ν = {nu:g} means a safety factor on yield n_T = {1 / nu:.3g} ([004]: 1.2…1.4). "
            "A0 is the stress area here; [004, eq. 6] takes d0 = d1"
        )
    if formula == "approx":
        notes.append(
            "approx: [004, eq. 15] with d2 ≈ d and R_T ≈ 0.25 (D_f + d_h); with one "
            "friction coefficient it is [004, eq. 19]"
        )
    values: dict[str, Any] = {
        "assembly_preload": force,
        "permissible_preload": permissible,
        "tightening_torque": total,
        "thread_torque": m_thread,
        "bearing_torque": m_bearing,
        "ideal_torque": ideal,
        "ideal_torque_share": share,
        "friction_radius": radius,
        "stress_area": bolt.stress_area,
        "pitch_diameter": bolt.pitch_diameter,
        "minor_diameter": bolt.minor_diameter,
        "thread_pitch": bolt.pitch,
        "torsion_factor": beta,
        "equivalent_stress": sigma_eq,
        "yield_strength": bolt.yield_strength,
        "stress_utilization": sigma_eq / bolt.yield_strength,
        "bearing_outer_diameter": bolt.bearing_outer_diameter,
        "hole_diameter": bolt.hole_diameter,
        "torque_formula_deviation": deviation,
        "rule_of_thumb_torque": thumb,
        "rule_of_thumb_deviation": (thumb - total) / total if total > 0 else math.inf,
        "yield_rule_torque": thumb_yield,
        "yield_rule_deviation": (thumb_yield - total) / total if total > 0 else math.inf,
    }
    _add_bought_part_checks(x, bolt, force, total, values, checks, notes)
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=deviation,
        checks=checks,
        notes=notes,
        warnings=warnings,
    )


TIGHTENING_OUTPUTS: tuple[Output, ...] = (
    Output(
        "assembly_preload",
        "N",
        "Preload F_M used: the permissible one (below) unless preload was given",
        display_unit="kN",
    ),
    Output(
        "permissible_preload",
        "N",
        "Largest preload whose equivalent stress is ν·R_p0.2: F = ν R_p0.2 A_s / β "
        "(VDI 2230 R7; [004, eq. 3])",
        display_unit="kN",
    ),
    Output(
        "tightening_torque",
        "N*m",
        "Wrench torque M_A = thread + bearing torque ([004, eq. 13]) by torque_formula",
    ),
    Output(
        "thread_torque", "N*m", "Thread torque M_p ([004, eq. 10]; VDI: F(0.16P + 0.58 d2 μ_G))"
    ),
    Output("bearing_torque", "N*m", "Bearing-face torque M_T = μ_K F R ([004, eq. 11])"),
    Output("ideal_torque", "N*m", "Frictionless torque M* = F P / (2π) ([004, eq. 14])"),
    Output("ideal_torque_share", "1", "M* / M_A; [004] says usually 0.05…0.15"),
    Output(
        "friction_radius",
        "m",
        "Bearing friction radius used: exact R_T ([004, eq. 12]) for 'exact', (D_f + d_h)/4 "
        "otherwise",
        display_unit="mm",
    ),
    Output("stress_area", "m^2", "Stress area A_s = π/4 ((d2 + d3)/2)² (ISO 898-1)"),
    Output("pitch_diameter", "m", "d2 = d − 0.649519 P (ISO 68-1)", display_unit="mm"),
    Output("minor_diameter", "m", "d3 = d − 1.226869 P (ISO 68-1)", display_unit="mm"),
    Output("thread_pitch", "m", "Pitch P used", display_unit="mm"),
    Output("torsion_factor", "1", "β = σ_red/σ ([004, eq. 5]; VDI 2230 R7)"),
    Output(
        "equivalent_stress",
        "Pa",
        "σ_red = β F / A_s during tightening",
        display_unit="MPa",
    ),
    Output("yield_strength", "Pa", "R_p0.2 used", display_unit="MPa"),
    Output("stress_utilization", "1", "σ_red / R_p0.2 at the preload used"),
    Output("bearing_outer_diameter", "m", "D_f used", display_unit="mm"),
    Output("hole_diameter", "m", "d_h used", display_unit="mm"),
    Output(
        "torque_formula_deviation",
        "1",
        "|M(chosen formula) − M(exact)| / M(exact) for these inputs",
    ),
    Output("rule_of_thumb_torque", "N*m", "0.2 F0 d ([004, eq. 16])"),
    Output("rule_of_thumb_deviation", "1", "(0.2 F0 d − M_A) / M_A"),
    Output(
        "yield_rule_torque",
        "N*m",
        "0.07 σ_T d³ ([004, eq. 18]; assumes σ0 = 0.6 σ_T, not the preload used here)",
    ),
    Output("yield_rule_deviation", "1", "(0.07 σ_T d³ − M_A) / M_A"),
    *fz.CHECK_OUTPUTS,
)

#: True of every preload.tightening answer (the runner adds it to the notes).
TIGHTENING_ASSUMPTIONS = (
    "[004, eq. 10 and 12] are missing from the review's text; the standard thread-torque "
    "and annular friction-radius relations stand in",
)

TIGHTENING = ModelSpec(
    name="preload.tightening",
    title="Bolt preload and tightening torque",
    family="preload",
    summary=(
        "The largest assembly preload a metric bolt takes at a share ν of its yield "
        "strength, and the torque that gives it: thread, bearing and frictionless parts, "
        "by the VDI 2230 formula, the review's exact relations or its approximation, "
        "with the review's rules of thumb beside them."
    ),
    source=SOURCE,
    inputs=BOLT_INPUTS,
    outputs=TIGHTENING_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_tightening,
    assumptions=TIGHTENING_ASSUMPTIONS,
    examples=(
        # VDI 2230 Table A1 case: M12 8.8, μ_G = μ_K = 0.12, ν = 0.9
        {"thread_diameter": 0.012, "property_class": "8.8", "thread_friction": 0.12},
        {
            "thread_diameter": 0.010,
            "thread_pitch": 0.00125,
            "property_class": "8.8",
            "thread_friction": 0.12,
            "bearing_friction": 0.12,
        },
        {
            "thread_diameter": 0.016,
            "property_class": "10.9",
            "thread_friction": 0.15,
            "bearing_friction": 0.15,
            "torque_formula": "exact",
            "preload_convention": "elastic",
            "utilization": 0.7,
        },
        # bought parts (issue 15): a designation, no dimension typed
        {"thread": "M10 ISO 4762 12.9"},
        {
            "thread": "M8 ISO 4762 12.9",
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "engagement_length": 0.008,
            "washer": "ISO 7089",
        },
        {"thread": "1/2-13 UNC", "grade": "SAE 5", "clamped_material": "S235JR"},
    ),
)

# --------------------------------------------------------------------------- control

CONTROL_INPUTS: tuple[Param, ...] = (
    *(
        replace(
            p,
            description="Nominal preload (middle of the method's band); when absent the "
            "band's top is the permissible preload (yield control: the preload at yield)",
        )
        if p.name == "preload"
        else p
        for p in BOLT_INPUTS
    ),
    Param(
        "required_clamp_force",
        "N",
        "Clamp force the joint needs in service (tightness, no separation)",
        required=True,
        maximum=1e8,
        display_unit="kN",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "load_type",
        "1",
        "'steady' (υ = 1.25…2.0) or 'varying' (υ = 2.5…4.0) load [004, eq. 2]",
        default="steady",
        kind="choice",
        choices=("steady", "varying"),
        group="joint",
    ),
    Param(
        "preload_factor",
        "1",
        "υ of [004, eq. 2]: minimum preload = υ × clamp force; the lower end of the "
        "load type's range when absent",
        minimum=1.0,
        maximum=10.0,
        symbol="υ",
        group="joint",
    ),
    Param(
        "method",
        "1",
        "Control method (GET /api/v1/preload/methods lists them with their scatter)",
        default="torque_wrench",
        kind="choice",
        choices=METHOD_KEYS,
        group="control",
    ),
    Param(
        "clamped_length",
        "m",
        "Clamped (grip) length l_k: needed for angle, elongation and displacement targets",
        maximum=10.0,
        display_unit="mm",
        symbol="l_k",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "shank_length",
        "m",
        "Length of plain shank inside the grip; the rest of the grip is free thread (d3)",
        default=0.0,
        minimum=0.0,
        maximum=10.0,
        display_unit="mm",
        group="joint",
    ),
    Param(
        "shank_diameter",
        "m",
        "Plain shank diameter; d when absent",
        maximum=1.0,
        display_unit="mm",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "reduced_length",
        "m",
        "Length of a reduced (waisted) shank section inside the grip",
        default=0.0,
        minimum=0.0,
        maximum=10.0,
        display_unit="mm",
        group="joint",
    ),
    Param(
        "reduced_diameter",
        "m",
        "Diameter of the reduced shank section (needed when reduced_length > 0)",
        maximum=1.0,
        display_unit="mm",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "nut_height",
        "m",
        "Nut height m; [004] adds m/3 at the minor diameter to the stretched length; "
        "0.8 d when absent",
        minimum=0.0,
        maximum=1.0,
        display_unit="mm",
        group="joint",
    ),
    Param(
        "youngs_modulus",
        "Pa",
        "Young's modulus of the bolt E_b",
        default=2.1e11,
        maximum=1e12,
        display_unit="GPa",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "clamped_compliance",
        "m/N",
        "Compliance of the clamped parts λ_p ([004, eq. 8]); when absent, bolts get VDI 2230 "
        "R3's deformation cone through clamped_length of one material (wide plates, "
        "through-bolted), sucker rods 0 (rigid, [004, eq. 9]); 0 for a rigid joint",
        minimum=0.0,
        maximum=1.0,
        group="joint",
    ),
    Param(
        "clamped_youngs_modulus",
        "Pa",
        "Young's modulus of the clamped parts for the cone model; youngs_modulus when absent",
        minimum=1e8,
        maximum=1e12,
        display_unit="GPa",
        group="joint",
    ),
    Param(
        "coupling_outer_diameter",
        "m",
        "Sucker-rod coupling outside diameter: turns the make-up angle into the "
        "circumferential displacement of the marks",
        maximum=1.0,
        display_unit="mm",
        group="control",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    friction_coefficient(
        "thread_friction_min",
        "Friction scatter: lowest μ_G (with thread_friction_max, gives the preload "
        "histogram at a fixed torque)",
        group="scatter",
    ),
    friction_coefficient(
        "thread_friction_max",
        "Friction scatter: highest μ_G",
        group="scatter",
    ),
    friction_coefficient(
        "bearing_friction_min",
        "Friction scatter: lowest μ_K (bearing_friction when absent)",
        group="scatter",
    ),
    friction_coefficient(
        "bearing_friction_max",
        "Friction scatter: highest μ_K",
        group="scatter",
    ),
    Param(
        "scatter_torque",
        "N*m",
        "Fixed wrench torque for the friction-scatter histogram; the target torque when absent",
        maximum=1e7,
        group="scatter",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    count(
        "histogram_bins",
        "Number of preload bins",
        default=10,
        minimum=2,
        maximum=100,
        group="scatter",
    ),
    count(
        "sample_size",
        "Bolts the histogram counts are scaled to (38 in [004, fig. 5])",
        default=38,
        minimum=1,
        maximum=1_000_000,
        group="scatter",
    ),
)


def _grip_sections(bolt: Bolt, x: Mapping[str, Any]) -> tuple[list[float], list[float]]:
    """Lengths and diameters of the stretched sections [004, eq. 4, 7]."""
    grip = float(x["clamped_length"])
    l_shank, l_reduced = float(x["shank_length"]), float(x["reduced_length"])
    free = grip - l_shank - l_reduced
    if free < -1e-12 * grip:
        raise InputOutOfRange(
            f"shank_length + reduced_length = {(l_shank + l_reduced) * 1e3:g} mm exceeds "
            f"clamped_length = {grip * 1e3:g} mm",
            field="shank_length",
        )
    shank_d = x.get("shank_diameter")
    shank_d = bolt.diameter if shank_d is None else float(shank_d)
    if l_reduced > 0 and x.get("reduced_diameter") is None:
        raise InputOutOfRange(
            "reduced_diameter is required when reduced_length > 0", field="reduced_diameter"
        )
    nut = x.get("nut_height")
    nut = 0.8 * bolt.diameter if nut is None else float(nut)
    lengths = [l_shank, l_reduced, max(free, 0.0), nut / 3.0]
    diameters = [
        shank_d,
        float(x["reduced_diameter"] or bolt.diameter),
        bolt.minor_diameter,
        bolt.minor_diameter,
    ]
    kept = [(li, di) for li, di in zip(lengths, diameters, strict=True) if li > 0]
    return [li for li, _ in kept], [di for _, di in kept]


def _smallest_section(bolt: Bolt, x: Mapping[str, Any], notes: list[str]) -> tuple[float, float]:
    """d_0 and A_0 of the smallest section: thread, plain or reduced shank (VDI 2230-1 R7)."""
    sections = []
    if float(x["shank_length"]) > 0.0 and x.get("shank_diameter") is not None:
        sections.append((float(x["shank_length"]), float(x["shank_diameter"])))
    if float(x["reduced_length"]) > 0.0:
        if x.get("reduced_diameter") is None:
            raise InputOutOfRange(
                "reduced_diameter is required when reduced_length > 0", field="reduced_diameter"
            )
        sections.append((float(x["reduced_length"]), float(x["reduced_diameter"])))
    d0, where = jt.smallest_section(bolt.stress_diameter, sections)
    area0 = bolt.stress_area if where == "thread" else 0.25 * math.pi * d0 * d0
    if where == "shank":
        notes.append(
            f"smallest section is the shank, d_0 = {d0 * 1e3:.4g} mm < d_S = "
            f"{bolt.stress_diameter * 1e3:.4g} mm: the permissible and yield preloads use "
            f"A_0 = {area0 * 1e6:.4g} mm² and W_p = π d_0³/16 (VDI 2230-1 R7; [004, eq. 3–4])"
        )
    return d0, area0


def _clamped_compliance(
    bolt: Bolt, x: Mapping[str, Any], method: ControlMethod, notes: list[str]
) -> float:
    """λ_p: the value given, else VDI 2230 R3's cone for bolts (0 for sucker rods)."""
    if x.get("clamped_compliance") is not None:
        return float(x["clamped_compliance"])
    if method.family != "bolt":
        return 0.0
    grip = float(x["clamped_length"])
    e_p = x.get("clamped_youngs_modulus")
    e_p = float(x["youngs_modulus"]) if e_p is None else float(e_p)
    cone = jt.clamped_compliance(
        [grip], [e_p], bolt.bearing_outer_diameter, bolt.hole_diameter, None, "through"
    )
    notes.append(
        f"clamped parts λ_p = {cone.total * 1e9:.4g} µm/kN from "
        f"VDI 2230-1 R3's deformation cone (l_K = {grip * 1e3:g} mm, E_p = {e_p / 1e9:g} GPa, "
        f"d_W = {bolt.bearing_outer_diameter * 1e3:g} mm, d_h = {bolt.hole_diameter * 1e3:g} mm, "
        "through-bolted, wide plates); give clamped_compliance to override (0: rigid)"
    )
    return cone.total


def _method_band(
    method: ControlMethod, permissible: float, at_yield: float, given: float | None
) -> tuple[float, float, float]:
    """(nominal, min, max) preload a method gives [N].

    With a given preload it is the middle of the band; otherwise the middle is
    set so the top of the band is the permissible preload (yield control: the
    preload at yield).
    """
    s = method.scatter
    top = at_yield if method.controls == "yield" else permissible
    nominal = given if given is not None else top / (1.0 + s)
    return nominal, nominal * (1.0 - s), nominal * (1.0 + s)


def _control(x: Mapping[str, Any], ctx: RunContext) -> Result:
    bolt, notes = resolve_bolt(x)
    warnings: list[str] = []
    checks: list[Check] = []
    method = get_method(str(x["method"]))
    mu_g, mu_k = float(x["thread_friction"]), float(x["bearing_friction"])
    nu, formula = float(x["utilization"]), str(x["torque_formula"])
    # VDI 2230-1 R7: the strength limit is at the smallest cross-section ([004, eq. 3-4]).
    d0, area0 = _smallest_section(bolt, x, notes)
    beta = float(
        pl.torsion_factor(bolt.pitch, bolt.pitch_diameter, d0, mu_g, str(x["preload_convention"]))
    )
    permissible = pl.assembly_preload(bolt.yield_strength, area0, beta, nu)
    at_yield = pl.assembly_preload(bolt.yield_strength, area0, beta, 1.0)
    given = None if x.get("preload") is None else float(x["preload"])

    lo_factor, hi_factor = pl.preload_factor_range(str(x["load_type"]))
    factor = lo_factor if x.get("preload_factor") is None else float(x["preload_factor"])
    if not lo_factor <= factor <= hi_factor:
        warnings.append(
            f"preload_factor υ = {factor:g} is outside {lo_factor:g}…{hi_factor:g}, the range "
            f"[004, eq. 2] gives for {x['load_type']} load"
        )
    required = factor * float(x["required_clamp_force"])

    nominal, f_min, f_max = _method_band(method, permissible, at_yield, given)
    k_thread, k_bearing, _ = torque_coefficients(bolt, mu_g, mu_k, formula)
    torque = nominal * (k_thread + k_bearing)

    values: dict[str, Any] = {
        "controlled_quantity": method.controls,
        "target_torque": torque,
        "target_force": nominal,
        "nominal_preload": nominal,
        "preload_min": f_min,
        "preload_max": f_max,
        "scatter": method.scatter,
        "tightening_factor": method.tightening_factor,
        "required_preload": required,
        "preload_factor": factor,
        "permissible_preload": permissible,
        "yield_preload": at_yield,
    }

    # Elongation and angle through one compliance [004, eq. 4, 7, 8, 9].
    needs_grip = method.controls in ("angle", "elongation", "displacement")
    stretch: float | None = None  # bolt + parts compliance, when the grip is known
    if x.get("clamped_length") is not None:
        lengths, diameters = _grip_sections(bolt, x)
        youngs = float(x["youngs_modulus"])
        compliance = pl.axial_compliance(lengths, diameters, youngs)
        parts = _clamped_compliance(bolt, x, method, notes)
        stretch = compliance + parts
        angle = pl.nut_rotation_angle(nominal, stretch, bolt.pitch)
        values.update(
            bolt_compliance=compliance,
            clamped_compliance=parts,
            equivalent_shank_diameter=pl.equivalent_shank_diameter(lengths, diameters),
            target_elongation=pl.elongation(nominal, compliance),
            target_angle=angle,
        )
        if x.get("coupling_outer_diameter") is not None:
            values["target_displacement"] = angle * 0.5 * float(x["coupling_outer_diameter"])
        if parts == 0.0 and method.controls in ("angle", "displacement", "elongation"):
            notes.append(
                "clamped parts taken as rigid ([004, eq. 9]); give clamped_compliance for "
                "[004, eq. 8] — the angle is then larger"
            )
        if method.controls in ("angle", "displacement"):
            big_enough = angle * method.scatter >= ANGLE_READING_ERROR
            checks.append(
                Check(
                    "angle_resolution",
                    big_enough,
                    f"target angle {math.degrees(angle):.0f}° against a reading error of "
                    f"15° ([004]): "
                    + (
                        f"the reading error stays within the method's ±{method.scatter:.0%}"
                        if big_enough
                        else f"needs ≥ {math.degrees(ANGLE_READING_ERROR / method.scatter):.0f}° "
                        "for the method's accuracy; "
                        + (
                            "the bolt is too short for angle control ([004]): use torque or "
                            "elongation control"
                            if method.controls == "angle"
                            else "the make-up turn is too small to read from the marks: use "
                            "the dynamometric wrench or the locking ring"
                        )
                    ),
                )
            )
        grip = float(x["clamped_length"])
        if method.controls == "elongation" and grip < 6.0 * bolt.diameter:
            warnings.append(
                f"clamped length {grip * 1e3:g} mm < 6 d: the elongation is only "
                f"{values['target_elongation'] * 1e6:.0f} µm; [004] warns of large "
                "measuring errors on short bolts"
            )
    elif needs_grip:
        raise InputOutOfRange(
            f"method {method.key!r} sets the {method.controls}; give clamped_length",
            field="clamped_length",
        )
    if method.controls == "displacement" and x.get("coupling_outer_diameter") is None:
        raise InputOutOfRange(
            f"method {method.key!r} sets a circumferential displacement; give "
            "coupling_outer_diameter",
            field="coupling_outer_diameter",
        )

    _add_bought_part_checks(x, bolt, f_max, torque, values, checks, notes)
    meets = f_min >= required
    below = f_max <= at_yield * (1.0 + 1e-12)
    values["min_meets_clamp"] = meets
    values["max_below_yield"] = below
    checks.append(
        Check(
            "min_meets_clamp",
            meets,
            f"minimum preload {f_min / 1e3:.4g} kN vs required υ·F_K = {required / 1e3:.4g} kN"
            + (
                ""
                if meets
                else ": choose a more accurate method, a larger or stronger bolt, or more bolts"
            ),
        )
    )
    checks.append(
        Check(
            "max_below_yield",
            below,
            f"maximum preload {f_max / 1e3:.4g} kN vs {at_yield / 1e3:.4g} kN at yield"
            + ("" if below else ": lower the target preload or choose a more accurate method"),
        )
    )
    if method.controls == "yield":
        notes.append(
            "torque-gradient control tightens to the yield point; the band's top is the preload "
            "at yield (minimum R_p0.2) and the bolt must be ductile ([004])"
        )

    passing: list[ControlMethod] = []
    for other in METHODS:
        if other.family != method.family:
            continue
        if other.controls in ("angle", "displacement", "elongation") and stretch is None:
            continue
        if other.controls == "displacement" and x.get("coupling_outer_diameter") is None:
            continue
        o_nominal, o_min, o_max = _method_band(other, permissible, at_yield, given)
        if other.controls in ("angle", "displacement") and stretch is not None:
            o_angle = pl.nut_rotation_angle(o_nominal, stretch, bolt.pitch)
            if o_angle * other.scatter < ANGLE_READING_ERROR:
                continue  # too short for angle control, as the check above says
        if o_min >= required and o_max <= at_yield * (1.0 + 1e-12):
            passing.append(other)
    passing.sort(key=lambda m: (m.cost_rank, m.key))
    cheaper = [m.key for m in passing if m.cost_rank < method.cost_rank]
    values["cheaper_methods"] = ", ".join(cheaper) if cheaper else "none"
    values["passing_methods"] = ", ".join(m.key for m in passing) if passing else "none"
    notes.append(f"scatter of {method.key}: {method.scatter_source}")
    if method.key == "torque_then_angle":
        notes.append(
            "the snug torque and the angle come from the joint's experimental torque–angle "
            "diagram ([004]); the angle here counts from the snug point"
        )

    series: dict[str, list[float]] = {}
    scatter_wanted = ctx.wants(
        "preload_bins",
        "preload_counts",
        "scatter_preload_min",
        "scatter_preload_max",
        "scatter_preload_mean",
        "scatter_relative",
    )
    has_range = (
        x.get("thread_friction_min") is not None or x.get("bearing_friction_min") is not None
    )
    if scatter_wanted and has_range:
        g_range = _range(x, "thread_friction", mu_g)
        k_range = _range(x, "bearing_friction", mu_k)
        if bolt.bearing_friction_factor != 1.0:  # a countersunk head: μ_K acts on the cone
            k_range = (
                k_range[0] * bolt.bearing_friction_factor,
                k_range[1] * bolt.bearing_friction_factor,
            )
        fixed = torque if x.get("scatter_torque") is None else float(x["scatter_torque"])
        hist = pl.friction_scatter_histogram(
            fixed,
            bolt.pitch,
            bolt.pitch_diameter,
            bolt.diameter,
            g_range,
            k_range,
            bolt.bearing_outer_diameter,
            bolt.hole_diameter,
            formula,
            bins=int(x["histogram_bins"]),
            sample_size=int(x["sample_size"]),
        )
        series = {"preload_bins": hist.bin_centres.tolist(), "preload_counts": hist.counts.tolist()}
        spread = (hist.maximum - hist.minimum) / (hist.maximum + hist.minimum)
        values.update(
            scatter_preload_min=hist.minimum,
            scatter_preload_max=hist.maximum,
            scatter_preload_mean=hist.mean,
            scatter_relative=spread,
        )
        notes.append(
            f"friction scatter at {fixed:.4g} N·m: μ_G {g_range[0]:g}…{g_range[1]:g}, "
            f"μ_K {k_range[0]:g}…{k_range[1]:g} (independent, uniform; midpoint grid) give "
            f"preload {hist.minimum / 1e3:.4g}…{hist.maximum / 1e3:.4g} kN, ±{spread:.0%} "
            '([004, fig. 5]: ±30 % for 38 bolts 5/8" at 80 N·m)'
        )
    elif scatter_wanted and (
        x.get("thread_friction_max") is not None or x.get("bearing_friction_max") is not None
    ):
        raise InputOutOfRange(
            "give thread_friction_min with thread_friction_max (and bearing_friction_min with "
            "bearing_friction_max)",
            field="thread_friction_min",
        )
    elif scatter_wanted:
        notes.append(
            "no friction range given (thread_friction_min/max, bearing_friction_min/max): "
            "no preload histogram"
        )

    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=_formula_deviation(bolt, x),
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=series,
    )


def _range(x: Mapping[str, Any], name: str, nominal: float) -> tuple[float, float]:
    lo, hi = x.get(f"{name}_min"), x.get(f"{name}_max")
    if lo is None and hi is None:
        return nominal, nominal
    if lo is None or hi is None:
        raise InputOutOfRange(f"give both {name}_min and {name}_max", field=f"{name}_min")
    if lo > hi:
        raise InputOutOfRange(
            f"{name}_min = {lo:g} exceeds {name}_max = {hi:g}", field=f"{name}_min"
        )
    return float(lo), float(hi)


CONTROL_OUTPUTS: tuple[Output, ...] = (
    Output(
        "controlled_quantity",
        "1",
        "What the method sets: torque, angle, elongation, force, displacement or yield",
        kind="str",
    ),
    Output("target_torque", "N*m", "Wrench torque for the nominal preload (torque_formula)"),
    Output(
        "target_angle",
        "rad",
        "Nut rotation from snug for the nominal preload ([004, eq. 8/9])",
        display_unit="deg",
    ),
    Output(
        "target_elongation",
        "m",
        "Bolt elongation at the nominal preload, Δl = F0 λ_b ([004, eq. 7])",
        display_unit="mm",
    ),
    Output(
        "target_displacement",
        "m",
        "Sucker rods: circumferential displacement of the marks on the coupling, φ·D_c/2",
        display_unit="mm",
    ),
    Output(
        "target_force",
        "N",
        "Force the washer/ring is set to (= nominal preload)",
        display_unit="kN",
    ),
    Output("nominal_preload", "N", "Middle of the method's preload band", display_unit="kN"),
    Output("preload_min", "N", "Lowest preload the method gives, F_nom (1 − s)", display_unit="kN"),
    Output(
        "preload_max", "N", "Highest preload the method gives, F_nom (1 + s)", display_unit="kN"
    ),
    Output("scatter", "1", "The method's preload scatter ±s"),
    Output("tightening_factor", "1", "α_A = (1 + s)/(1 − s) (VDI 2230 Table A8)"),
    Output("required_preload", "N", "υ × required clamp force ([004, eq. 2])", display_unit="kN"),
    Output("preload_factor", "1", "υ used"),
    Output("permissible_preload", "N", "Preload at ν·R_p0.2 (VDI 2230 R7)", display_unit="kN"),
    Output(
        "yield_preload", "N", "Preload at which σ_red reaches R_p0.2 (ν = 1)", display_unit="kN"
    ),
    Output("min_meets_clamp", "1", "preload_min ≥ required_preload", kind="bool"),
    Output("max_below_yield", "1", "preload_max ≤ yield_preload", kind="bool"),
    Output(
        "cheaper_methods",
        "1",
        "Cheaper methods of the same family that would also pass both checks ('none' if none)",
        kind="str",
    ),
    Output(
        "passing_methods",
        "1",
        "Every method of the same family that passes both checks, cheapest first",
        kind="str",
    ),
    Output("bolt_compliance", "m/N", "λ_b = Σ l_i/(E A_i) incl. m/3 at d3 ([004, eq. 4, 7])"),
    Output("clamped_compliance", "m/N", "λ_p used"),
    Output(
        "equivalent_shank_diameter",
        "m",
        "d_eq of the stretched length ([004, eq. 4])",
        display_unit="mm",
    ),
    Output("scatter_preload_min", "N", "Friction scatter: lowest preload", display_unit="kN"),
    Output("scatter_preload_max", "N", "Friction scatter: highest preload", display_unit="kN"),
    Output("scatter_preload_mean", "N", "Friction scatter: mean preload", display_unit="kN"),
    Output(
        "scatter_relative",
        "1",
        "Friction scatter: (max − min)/(max + min), the ± of [004, fig. 5]",
    ),
    Output(
        "preload_bins",
        "N",
        "Friction scatter: preload bin centres",
        series=True,
        display_unit="kN",
    ),
    Output(
        "preload_counts",
        "1",
        "Friction scatter: expected number of bolts (of sample_size) per bin",
        series=True,
        x="preload_bins",
        plot=Plot(bars=True),
    ),
    *fz.CHECK_OUTPUTS,
)

CONTROL = ModelSpec(
    name="preload.control",
    title="Preload control: target value, preload band and friction scatter",
    family="preload",
    summary=(
        "For a bolt, a required clamp force and a control method: the value to set (torque, "
        "angle, elongation, force or mark displacement), the preload band the method's "
        "scatter gives, whether its bottom clamps and its top stays below yield, cheaper "
        "methods that would also do, and the preload histogram at a fixed torque when the "
        "friction coefficients scatter."
    ),
    source=SOURCE,
    inputs=CONTROL_INPUTS,
    outputs=CONTROL_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_control,
    examples=(
        # [004, fig. 5]: 5/8"-11 UNC bolts at 80 N·m, friction 0.10…0.20 -> about ±30 %
        {
            "thread_diameter": 0.015875,
            "thread_pitch": 0.0254 / 11,
            "yield_strength": 640e6,
            "bearing_outer_diameter": 0.0226,
            "hole_diameter": 0.0175,
            "thread_friction": 0.15,
            "bearing_friction": 0.15,
            "required_clamp_force": 15e3,
            "method": "torque_wrench",
            "thread_friction_min": 0.10,
            "thread_friction_max": 0.20,
            "bearing_friction_min": 0.10,
            "bearing_friction_max": 0.20,
            "scatter_torque": 80.0,
        },
        {
            "thread_diameter": 0.012,
            "required_clamp_force": 20e3,
            "method": "nut_angle",
            "clamped_length": 0.12,
            "shank_length": 0.08,
        },
        # bought parts (issue 15): socket head M8 12.9 into aluminium, too short an engagement
        {
            "thread": "M8 ISO 4762 12.9",
            "required_clamp_force": 12e3,
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "engagement_length": 0.008,
        },
        {"thread": "1/2-13 UNC", "grade": "SAE 5", "required_clamp_force": 15e3},
    ),
)
