"""Model spec for the audit window of a torque-tightened joint (``joint.audit``).

The joint is the joint model's (``joint.vdi2230``): its inputs, its bolt resolution
(:func:`engine.procedures.bolt.resolve_bolt`) and its embedding loss F_Z (VDI 2230-1 R4),
taken from a run of that model. The audit torques are :mod:`engine.physics.audit`'s, on the
torque per newton of preload that :func:`engine.physics.preload.tightening_torque_per_preload`
gives, the same split into thread and bearing torque the joint model uses.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from ..core.errors import InputOutOfRange
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    fixed_error,
)
from ..core.text import q
from ..physics import audit as au
from ..physics import joint as jt
from ..physics import preload as pl
from ..procedures.bolt import resolve_bolt
from .joint import JOINT_INPUTS, VDI2230

SOURCE = (
    "VDI 2230-1 R4 (embedding) and R13 (tightening and loosening torque), the joint of "
    "joint.vdi2230; audit methods as public secondary sources describe them [TorqueAudit]; "
    "static friction excess [FrictionTables]; published restart and untightening torques "
    "[Bickford], [BoltScience]"
)

#: Joint inputs that do not change the audit (service loads, fatigue, checks of bought parts).
_NOT_AUDIT = {
    "working_load",
    "working_load_min",
    "slip_interfaces",
    "interface_friction",
    "sealing_clamp_force",
    "temperature_change",
    "plate_temperature_change",
    "bolt_modulus_ratio",
    "plate_modulus_ratio",
    "bolt_expansion",
    "plate1_expansion",
    "plate2_expansion",
    "plate3_expansion",
    "method",
    "tightening_factor",
    "controlled",
    "bridge_joint",
    "rolling",
    "head_standard",
    "washer",
    "nut",
    "clamped_material",
    "limiting_surface_pressure",
    "internal_thread_material",
    "engaged_length",
    "nut_class",
    "drive",
    "utilization",
    "internal_thread_shear_strength",
    "engagement_length",
    "nut_property_class",
    "load_introduction",
}

_JOINT_NAMES = tuple(p.name for p in JOINT_INPUTS if p.name not in _NOT_AUDIT)

INPUTS: tuple[Param, ...] = (
    *(
        replace(
            p,
            required=True,
            description="Torque specification M_A, the tool's nominal torque (including the "
            "prevailing torque)",
        )
        if p.name == "tightening_torque"
        # the friction box's upper ends and the tolerance act on every audit window here,
        # not only with a torque specification as in joint.vdi2230
        else replace(p, used_with=None)
        for p in JOINT_INPUTS
        if p.name in _JOINT_NAMES
    ),
    Param(
        "static_friction_ratio_min",
        "1",
        "Smallest ratio of static to kinetic friction r = μ_static/μ_kinetic at the reading "
        "(1: no excess; lubricated steel on steel, [FrictionTables])",
        default=1.0,
        minimum=1.0,
        maximum=3.0,
        symbol="r_min",
        group="audit",
    ),
    Param(
        "static_friction_ratio_max",
        "1",
        "Largest ratio r = μ_static/μ_kinetic (1.15: dry steel on steel, static 0.45…0.80 "
        "against kinetic 0.40…0.70, [FrictionTables]; measure your own where it matters)",
        default=1.15,
        minimum=1.0,
        maximum=3.0,
        symbol="r_max",
        group="audit",
    ),
)


def _o(name: str, description: str, **kw: Any) -> Output:
    return Output(name, "N*m", description, **kw)


OUTPUTS: tuple[Output, ...] = (
    _o(
        "first_motion_min",
        "First motion in the tightening direction, read at once: least",
        symbol="M_fm,min",
        step="[TorqueAudit]",
    ),
    _o(
        "first_motion_max",
        "First motion, read at once: most",
        symbol="M_fm,max",
        step="[TorqueAudit]",
    ),
    _o(
        "first_motion_embedded_min",
        "First motion after embedding: least",
        symbol="M_fm,Z,min",
        step="[TorqueAudit]",
    ),
    _o(
        "first_motion_embedded_max",
        "First motion after embedding: most",
        symbol="M_fm,Z,max",
        step="[TorqueAudit]",
    ),
    _o(
        "breakaway_min",
        "Breakaway in the loosening direction, read at once: least",
        symbol="M_ba,min",
        step="[TorqueAudit]",
    ),
    _o(
        "breakaway_max",
        "Breakaway (loosening), read at once: most",
        symbol="M_ba,max",
        step="[TorqueAudit]",
    ),
    _o(
        "breakaway_embedded_min",
        "Breakaway (loosening) after embedding: least",
        symbol="M_ba,Z,min",
        step="[TorqueAudit]",
    ),
    _o(
        "breakaway_embedded_max",
        "Breakaway (loosening) after embedding: most",
        symbol="M_ba,Z,max",
        step="[TorqueAudit]",
    ),
    _o(
        "mark_min",
        "Mark torque (back to the mark, turning), read at once: least",
        symbol="M_mk,min",
        step="[TorqueAudit]",
    ),
    _o("mark_max", "Mark torque, read at once: most", symbol="M_mk,max", step="[TorqueAudit]"),
    _o(
        "mark_embedded_min",
        "Mark torque after embedding: least",
        symbol="M_mk,Z,min",
        step="[TorqueAudit]",
    ),
    _o(
        "mark_embedded_max",
        "Mark torque after embedding: most",
        symbol="M_mk,Z,max",
        step="[TorqueAudit]",
    ),
    Output(
        "assembly_preload_min",
        "N",
        "F_M,min the torque band gives (R13)",
        display_unit="kN",
        symbol="F_M,min",
        step="VDI 2230-1 R13",
    ),
    Output(
        "assembly_preload_max",
        "N",
        "F_M,max the torque band gives (R13)",
        display_unit="kN",
        symbol="F_M,max",
        step="VDI 2230-1 R13",
    ),
    Output(
        "embedding_loss",
        "N",
        "F_Z of the joint model (R4)",
        display_unit="kN",
        symbol="F_Z",
        step="VDI 2230-1 R4",
    ),
    Output(
        "residual_preload_min",
        "N",
        "F_M,min − F_Z after embedding",
        display_unit="kN",
        symbol="F_V,min",
        step="VDI 2230-1 R4",
    ),
    Output(
        "residual_preload_max",
        "N",
        "F_M,max − F_Z after embedding",
        display_unit="kN",
        symbol="F_V,max",
        step="VDI 2230-1 R4",
    ),
)


def _joint(x: Mapping[str, Any], ctx: RunContext) -> Mapping[str, Any]:
    """The joint model's numbers for the joint these inputs describe (its F_Z, its F_M)."""
    given = {k: x[k] for k in _JOINT_NAMES if x.get(k) is not None}
    values, _ = VDI2230.validate(given)
    wanted = frozenset({"embedding_loss", "assembly_preload_min", "assembly_preload_max"})
    joint_ctx = RunContext(rung="closed_form", outputs=wanted, tolerance=ctx.tolerance)
    return VDI2230.compute(values, joint_ctx).values


def _windows(
    x: Mapping[str, Any], k_p: float, k_lo: float, k_hi: float, f_z: float
) -> dict[str, float]:
    """Each method's window before and after embedding, over the prevailing torques given."""
    torque, tol = float(x["tightening_torque"]), float(x["torque_tolerance"])
    m_u = float(x["prevailing_torque"])
    m_u_min = m_u if x.get("prevailing_torque_min") is None else float(x["prevailing_torque_min"])
    r_lo, r_hi = float(x["static_friction_ratio_min"]), float(x["static_friction_ratio_max"])
    methods = {
        "first_motion": (au.TIGHTENING, r_lo, r_hi),
        "breakaway": (au.LOOSENING, r_lo, r_hi),
        "mark": (au.TIGHTENING, 1.0, 1.0),  # the fastener turns: kinetic friction
    }
    out: dict[str, float] = {}
    for name, (direction, ra, rb) in methods.items():
        for suffix, loss in (("", 0.0), ("_embedded", f_z)):
            lows, highs = [], []
            for prevailing in {m_u, m_u_min}:
                lo, hi = au.audit_window(
                    torque * (1.0 - tol),
                    torque * (1.0 + tol),
                    prevailing,
                    k_p,
                    k_lo - k_p,
                    k_hi - k_p,
                    ra,
                    rb,
                    loss,
                    direction,
                )
                lows.append(float(lo))
                highs.append(float(hi))
            out[f"{name}{suffix}_min"] = min(lows)
            out[f"{name}{suffix}_max"] = max(highs)
    return out


def _audit(x: Mapping[str, Any], ctx: RunContext) -> Result:
    if float(x["static_friction_ratio_min"]) > float(x["static_friction_ratio_max"]):
        raise InputOutOfRange(
            f"static_friction_ratio_min = {x['static_friction_ratio_min']:g} is not allowed: "
            f"must be ≤ static_friction_ratio_max = {x['static_friction_ratio_max']:g}",
            field="static_friction_ratio_min",
        )
    joint = _joint(x, ctx)
    bolt, notes = resolve_bolt(x)
    mu_g_lo, mu_k_lo = float(x["thread_friction_min"]), float(x["bearing_friction_min"])
    mu_g_hi = mu_g_lo if x.get("thread_friction_max") is None else float(x["thread_friction_max"])
    mu_k_hi = mu_k_lo if x.get("bearing_friction_max") is None else float(x["bearing_friction_max"])
    d, d2, pitch = bolt.diameter, bolt.pitch_diameter, bolt.pitch
    d_w, d_h = bolt.bearing_outer_diameter, bolt.hole_diameter
    k_lo = float(sum(pl.tightening_torque_per_preload(pitch, d2, d, mu_g_lo, mu_k_lo, d_w, d_h)))
    k_hi = float(sum(pl.tightening_torque_per_preload(pitch, d2, d, mu_g_hi, mu_k_hi, d_w, d_h)))
    k_p = float(au.pitch_torque_per_preload(pitch, d2))
    f_z = float(joint["embedding_loss"])
    m_u = float(x["prevailing_torque"])
    m_u_min = None if x.get("prevailing_torque_min") is None else float(x["prevailing_torque_min"])
    fm_min, fm_max = (
        float(f)
        for f in jt.preload_bounds_from_torque(
            float(x["tightening_torque"]), float(x["torque_tolerance"]), m_u, k_lo, k_hi, m_u_min
        )
    )
    values: dict[str, Any] = _windows(x, k_p, k_lo, k_hi, f_z)
    values.update(
        assembly_preload_min=fm_min,
        assembly_preload_max=fm_max,
        embedding_loss=f_z,
        residual_preload_min=max(fm_min - f_z, 0.0),
        residual_preload_max=max(fm_max - f_z, 0.0),
    )
    r_lo = float(x["static_friction_ratio_min"])
    locking = float(au.audit_torque_per_preload(k_p, k_lo - k_p, r_lo, au.LOOSENING))
    checks = [
        Check(
            "self_locking",
            locking > 0.0,
            f"loosening torque per newton at μ_min and r = {r_lo:g}: −0.16 P + friction = "
            f"{locking * 1e3:.4g} N·m/kN"
            + (
                " > 0: the thread holds the preload"
                if locking > 0.0
                else ": the joint can turn loose under its own preload (VDI 2230-1 R13)"
            ),
        ),
        Check(
            "preload_after_embedding",
            fm_min > f_z,
            f"F_M,min = {fm_min / 1e3:.4g} kN against F_Z = {f_z / 1e3:.4g} kN"
            + ("" if fm_min > f_z else ": embedding can take the whole preload"),
        ),
    ]
    torque, tol = float(x["tightening_torque"]), float(x["torque_tolerance"])
    warnings: list[str] = []
    if values["first_motion_max"] > torque * (1.0 + tol) * (1.0 + 1e-12):
        warnings.append(
            "rule of thumb, not a standard: auditors often read first motion as the installed "
            f"torque [TorqueAudit]; here it can read up to {values['first_motion_max']:.4g} N·m, "
            f"above the specification's {torque * (1.0 + tol):.4g} N·m (static friction): take "
            "the audit limits from this window, not from the specification"
        )
    notes.extend(
        [
            f"torque band {q(torque * (1 - tol), 'N*m', fmt='.4g')} … "
            f"{q(torque * (1 + tol), 'N*m', fmt='.4g')}; friction μ_G {mu_g_lo:g}…{mu_g_hi:g}, "
            f"μ_K {mu_k_lo:g}…{mu_k_hi:g}; static excess r = "
            f"{x['static_friction_ratio_min']:g}…{x['static_friction_ratio_max']:g}",
            f"embedding loss F_Z = {f_z / 1e3:.4g} kN from the joint model (VDI 2230-1 R4); "
            "'after embedding' windows assume the joint has settled fully",
            "first motion: the peak before the fastener turns on, static friction; breakaway: "
            "the same in the loosening direction, where the thread's pitch helps (−0.16 P); mark: "
            "loosened and turned back to the mark, read while turning (kinetic friction) "
            "[TorqueAudit]",
        ]
    )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        warnings=warnings,
    )


CLOSED_FORM = Rung(
    "closed_form",
    "VDI 2230-1 R13 per newton of preload with the joint model's F_Z; the window's extremes "
    "found exactly (corners and the interior maximum in friction); the estimate does not "
    "include how far real audits scatter beyond friction (operator, speed, settling time)",
    fixed_error(0.0),
    typical_error="exact against the R13 relations",
    typical_time="< 1 ms",
)

#: M12 8.8 through 2 × 20 mm steel at 80 N·m ± 5 %, μ 0.08…0.16 (joint.vdi2230's second case).
M12_AT_80 = {
    "thread_diameter": 0.012,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "tightening_torque": 80.0,
    "torque_tolerance": 0.05,
    "thread_friction_min": 0.08,
    "thread_friction_max": 0.16,
    "bearing_friction_min": 0.08,
    "bearing_friction_max": 0.16,
}

AUDIT = ModelSpec(
    answer=(
        Answer("first_motion_min", "M_fm,min"),
        Answer("first_motion_max", "M_fm,max"),
        Answer("breakaway_min", "M_ba,min"),
        Answer("breakaway_max", "M_ba,max"),
        Answer("mark_min", "M_mk,min"),
        Answer("mark_max", "M_mk,max"),
        Answer("residual_preload_min", "F_V,min", check="preload_after_embedding"),
    ),
    name="joint.audit",
    title="Audit window: first-motion, breakaway and mark torque of a tightened joint",
    family="joint",
    summary=(
        "For a torque specification and a joint: the torque each audit method should read, "
        "as acceptance limits: first motion in the tightening direction, breakaway in the "
        "loosening direction (the thread's pitch helps) and the mark torque, read at once and "
        "after embedding, with the static friction's excess over the kinetic."
    ),
    source=SOURCE,
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_audit,
    examples=(
        M12_AT_80,
        {**M12_AT_80, "prevailing_torque": 0.4, "static_friction_ratio_max": 1.3},
        # a tight band on a lubricated joint: no static excess
        {
            **M12_AT_80,
            "thread_friction_min": 0.10,
            "thread_friction_max": 0.12,
            "bearing_friction_min": 0.10,
            "bearing_friction_max": 0.12,
            "static_friction_ratio_max": 1.0,
        },
    ),
)
