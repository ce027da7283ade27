"""Model spec for a ring flange of z bolts (``joint.flange``): the most loaded bolt, VDI 2230.

A rigid ring flange of z equal bolts on a bolt circle carries an axial force, a bending moment,
a shear force and a torque. VDI 2230-1 cuts the most loaded bolt out of it (the simplification
of VDI 2230 Part 2 for rigid flanges whose interface stays closed): its working and transverse
loads (:func:`engine.physics.joint.ring_flange_axial_load`,
:func:`engine.physics.joint.ring_flange_transverse_load`) then go through the single-bolt chain
R0–R13 of ``joint.vdi2230`` unchanged, with every input of that model.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..core.errors import InputOutOfRange
from ..core.spec import Answer, ModelSpec, Output, Param, Result, RunContext
from ..core.text import q
from ..physics import joint as jt
from .joint import CLOSED_FORM, JOINT_INPUTS, JOINT_OUTPUTS, VDI2230
from .joint import _compute as _single_bolt  # the chain R0–R13, its equations listed with ours

#: The single bolt's loads, which the flange's loads set.
_BOLT_LOADS = ("working_load", "working_load_min", "transverse_load")

_FLANGE_INPUTS: tuple[Param, ...] = (
    Param(
        "bolts",
        "1",
        "Number z of equal bolts, equally spaced on the bolt circle",
        default=8,
        kind="int",
        minimum=3,
        maximum=200,
        symbol="z",
        group="flange",
    ),
    Param(
        "bolt_circle_diameter",
        "m",
        "Bolt circle diameter D_t",
        required=True,
        minimum=0.0,
        exclusive_minimum=True,
        maximum=20.0,
        display_unit="mm",
        symbol="D_t",
        group="flange",
    ),
    Param(
        "axial_force",
        "N",
        "Axial force F_ax on the flange, opening the joint (0: none)",
        default=0.0,
        minimum=0.0,
        maximum=1e9,
        display_unit="kN",
        group="flange",
    ),
    Param(
        "axial_force_min",
        "N",
        "Lower axial force of an alternating load; static (= axial_force) when absent",
        minimum=0.0,
        maximum=1e9,
        display_unit="kN",
        group="flange",
    ),
    Param(
        "bending_moment",
        "N*m",
        "Bending moment M_B on the flange about a diameter",
        default=0.0,
        minimum=0.0,
        maximum=1e9,
        group="flange",
    ),
    Param(
        "bending_moment_min",
        "N*m",
        "Lower bending moment of an alternating load (same sense); static when absent",
        minimum=0.0,
        maximum=1e9,
        group="flange",
    ),
    Param(
        "transverse_force",
        "N",
        "Shear force F_Q on the flange, carried by interface friction",
        default=0.0,
        minimum=0.0,
        maximum=1e9,
        display_unit="kN",
        group="flange",
    ),
    Param(
        "torque",
        "N*m",
        "Torque M_T about the flange's axis, carried by interface friction on the bolt circle",
        default=0.0,
        minimum=0.0,
        maximum=1e9,
        group="flange",
    ),
)

FLANGE_INPUTS: tuple[Param, ...] = (
    *_FLANGE_INPUTS,
    *(p for p in JOINT_INPUTS if p.name not in _BOLT_LOADS),
)

#: The single-bolt results the flange reports for its most loaded bolt.
_PASSED = (
    "load_factor",
    "permissible_preload",
    "assembly_preload_min",
    "assembly_preload_max",
    "tightening_torque",
    "required_clamp_force",
    "residual_clamp_force_min",
    "separation_load",
    "max_working_load",
    "max_bolt_force",
    "working_stress",
    "yield_safety",
    "stress_amplitude",
    "fatigue_safety",
    "slip_safety",
)

FLANGE_OUTPUTS: tuple[Output, ...] = (
    Output(
        "bolt_working_load",
        "N",
        "F_A of the most loaded bolt: F_ax/z + 4 M_B/(z D_t)",
        display_unit="kN",
        symbol="F_A",
        step="VDI 2230-1 §3.1",
    ),
    Output(
        "bolt_working_load_min",
        "N",
        "Its lower load: F_ax,min/z + 4 M_B,min/(z D_t)",
        display_unit="kN",
        symbol="F_A,min",
        step="VDI 2230-1 §3.1",
    ),
    Output(
        "bolt_transverse_load",
        "N",
        "F_Q per bolt: F_Q/z + 2 M_T/(z D_t)",
        display_unit="kN",
        symbol="F_Q",
        step="VDI 2230-1 §3.1",
    ),
    *(o for o in JOINT_OUTPUTS if o.name in _PASSED),
)

SIMPLIFICATION = (
    "most loaded bolt of a rigid ring flange (VDI 2230-1's single bolt cut from VDI 2230 "
    "Part 2): rigid flanges, a closed interface, z equal bolts equally spaced, loads linear "
    "in the distance from the bending axis through the circle's centre; a flexible flange, a "
    "gasket or an opening interface (tilting about the flange's edge) need VDI 2230 Part 2"
)


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    z, d_t = int(x["bolts"]), float(x["bolt_circle_diameter"])
    for low, high in (("axial_force_min", "axial_force"), ("bending_moment_min", "bending_moment")):
        if x.get(low) is not None and float(x[low]) > float(x[high]):
            raise InputOutOfRange(
                f"{low} = {float(x[low]):g} exceeds {high} = {float(x[high]):g}: must be ≤ "
                f"{float(x[high]):g}",
                field=low,
            )
    f_ax, m_b = float(x["axial_force"]), float(x["bending_moment"])
    f_ax_min = f_ax if x.get("axial_force_min") is None else float(x["axial_force_min"])
    m_b_min = m_b if x.get("bending_moment_min") is None else float(x["bending_moment_min"])
    f_a = jt.ring_flange_axial_load(f_ax, m_b, z, d_t)
    f_a_min = jt.ring_flange_axial_load(f_ax_min, m_b_min, z, d_t)
    f_q = jt.ring_flange_transverse_load(float(x["transverse_force"]), float(x["torque"]), z, d_t)
    limit = next(p.maximum for p in JOINT_INPUTS if p.name == "working_load")
    if not max(f_a, f_q) <= (limit or math.inf):
        raise InputOutOfRange(
            f"the most loaded bolt would carry F_A = {f_a:.4g} N, F_Q = {f_q:.4g} N, beyond one "
            f"bolt's {limit:g} N: give a larger bolt_circle_diameter (now {d_t * 1e3:g} mm), "
            "more bolts or smaller loads",
            field="bolt_circle_diameter",
        )
    single = {p.name: x.get(p.name) for p in JOINT_INPUTS}
    single.update(working_load=f_a, working_load_min=f_a_min, transverse_load=f_q)
    one = _single_bolt(single, ctx)
    values: dict[str, Any] = {
        "bolt_working_load": f_a,
        "bolt_working_load_min": f_a_min,
        "bolt_transverse_load": f_q,
    }
    values.update({name: one.values.get(name) for name in _PASSED})
    notes = [
        f"most loaded of z = {z} bolts on D_t = {q(d_t, 'mm', 6)}: F_A = {q(f_a, 'kN', 4)} "
        f"(F_A,min {q(f_a_min, 'kN', 4)}), F_Q = {q(f_q, 'kN', 4)}, worked through "
        "joint.vdi2230's steps R0–R13",
        *one.notes,
    ]
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=one.error_estimate,
        checks=one.checks,
        notes=notes,
        warnings=one.warnings,
    )


FLANGE = ModelSpec(
    requirements_of="VDI 2230",
    advice=frozenset(("seed_004_preload_stress", "nut_class_pairing")),
    answer=(
        Answer("bolt_working_load", "F_A"),
        Answer("tightening_torque", "M_A"),
        Answer("assembly_preload_min", "F_M,min"),
        Answer("permissible_preload", "F_M,zul", check="R7_window_fits"),
        Answer("residual_clamp_force_min", "F_KR,min", check="residual_clamp_force"),
        Answer("yield_safety", "S_F", check="R8_working_stress", relation="≥", bound=1.0),
        Answer("fatigue_safety", "S_D", check="R9_fatigue", relation="≥", bound=1.2),
        Answer("slip_safety", "S_G", check="R12_slip"),
    ),
    name="joint.flange",
    title="Ring flange of z bolts: the most loaded bolt through VDI 2230",
    family="joint",
    summary=(
        "A rigid ring flange of z equal bolts on a bolt circle under an axial force, a "
        "bending moment, a shear force and a torque: the most loaded bolt's working and "
        "transverse loads, then that bolt through the single-bolt chain of joint.vdi2230 "
        "(preload window, working and alternating stress, slipping, opening)."
    ),
    source=(
        "VDI 2230-1:2015 §3.1 and steps R0–R13 (the most loaded bolt of a rigid flange, the "
        "simplification of VDI 2230 Part 2); the single-bolt chain as in joint.vdi2230"
    ),
    inputs=FLANGE_INPUTS,
    outputs=FLANGE_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_compute,
    assumptions=(SIMPLIFICATION, *VDI2230.assumptions),
    examples=(
        # 8 × M12 8.8 on a 200 mm circle through 2 × 20 mm steel: 40 kN 0…40 kN, 1 kN·m, 0.5 kN·m
        {
            "axial_force": 40e3,
            "axial_force_min": 0.0,
            "bending_moment": 1e3,
            "torque": 500.0,
            "bolts": 8,
            "bolt_circle_diameter": 0.200,
            "thread_diameter": 0.012,
            "plate1_thickness": 0.020,
            "plate2_thickness": 0.020,
        },
    ),
)
