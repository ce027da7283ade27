"""The ``blow.joint`` model: what a tool's blows (or its clutch) deliver into a joint.

The physics is in :mod:`engine.physics.blow`; the tools' own equations in
:mod:`engine.physics.nutrunner` [000], :mod:`engine.physics.rare_impact` [002] and
:mod:`engine.physics.clutch` [001]; the tightening relation in :mod:`engine.physics.preload`
(VDI 2230-1 R13, [004]). This module picks the source of the blow, the
joint's torque rate, runs the rung and turns the result into values, series,
checks and notes.
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
from collections.abc import Container, Mapping
from typing import Any

import numpy as np

from ..core.errors import EngineError, InfeasibleDesign, InputOutOfRange
from ..core.params import DEG, count, friction_coefficient, length, positive
from ..core.spec import Answer, Check, ModelSpec, Output, Param, Result, RunContext, Rung, Scratch
from ..core.text import q
from ..numerics.ode import sqrt, where
from ..physics import clutch as cl
from ..physics import nutrunner as nr
from ..physics import preload as pl
from ..physics.blow import (
    BlowProblem,
    BlowSeries,
    blow_series,
    clutch_preload_window,
    energy_blow,
    energy_blow_error,
    energy_peak_error,
    held_blow_peak,
    iso5393_rate,
    joint_rate,
    rigid_blow_torque,
)
from ..physics.joint import clamped_compliance as vdi_clamped_compliance
from ..physics.rare_impact import rotating_inertia
from ..procedures.bolt import resolve_bolt, resolve_bolts
from ..procedures.striker_cycle import (
    NOT_HELD,
    closed_form_cycle,
    release_radius_of,
    release_speed_of,
)
from .clutch import BALL_CLUTCH
from .nutrunner import NUTRUNNER_DRIVE
from .preload import (
    TIGHTENING,
    torque_coefficients,
    torque_coefficients_raw,
)
from .rare_impact import RARE_IMPACT
from .rare_impact import REFERENCE_DESIGN as _STRIKER_DEFAULTS

_SIMULATION_ERROR = 1e-6
SOURCES = ("energy", "nutrunner", "rare_impact", "clutch")
RATES = ("iso5393_hard", "iso5393_soft", "joint", "number")

# --------------------------------------------------------------------------- inputs

_NR_NAMES = (
    "motor_speed",
    "coupling_mass",
    "coupling_diameter",
    "motor_pulley_mass",
    "motor_pulley_diameter",
    "flywheel_mass",
    "flywheel_diameter",
    "drive_gear_mass",
    "drive_gear_diameter",
    "spindle_gear_mass",
    "spindle_gear_diameter",
    "spindle_count",
    "shaft_diameter",
    "shaft_length",
    "spindle_diameter",
    "spindle_length",
    "shear_modulus",
    "idle_spindle_friction_torque",
)
_RI_NAMES = (
    "flywheel_inertia",
    "roller_mass",
    "roller_count",
    "roller_radius",
    "cone_angle",
    "power_spring_rate",
    "power_spring_preload",
    "auxiliary_spring_rate",
    "auxiliary_spring_preload",
    "release_travel",
    "roller_geometry",
    "half_coupling_mass",
    "stepped_shaft_mass",
    "gravity",
)
#: The sources' motors, for the time between blows: the nut-runner's power [000, eq. 5],
#: the striker's motor [002, eq. 1] (its defaults kept: impact.rare's reference motor).
_NR_MOTOR = ("motor_power",)
_RI_MOTOR = ("motor_torque", "motor_no_load_speed")
#: Borrowed inputs that keep the tool model's default here (what the striker's release
#: speed reads beyond its springs and rollers; the nut-runner's material; the striker's motor).
_KEEP_DEFAULT = frozenset(
    ("shear_modulus", "half_coupling_mass", "stepped_shaft_mass", "gravity", *_RI_MOTOR)
)
_CL_NAMES = (
    "ball_circle_diameter",
    "groove_angle",
    "ball_count",
    "load_factor",
    "flank_friction",
    "spring_arrangement",
)


def _borrow(spec: ModelSpec, names: tuple[str, ...], group: str) -> tuple[Param, ...]:
    """The tool model's own inputs, optional here (used only by their source)."""
    out = []
    for name in names:
        p = spec.param(name)
        keep_default = p.default if p.kind == "choice" or name in _KEEP_DEFAULT else None
        out.append(
            dataclasses.replace(
                p,
                required=False,
                default=keep_default,
                group=group,
                description=f"{p.description} (source {group})",
            )
        )
    return tuple(out)


_INPUTS: tuple[Param, ...] = (
    Param(
        "source",
        "1",
        "what strikes the joint: a raw energy and inertia ('energy'), the nut-runner's drive "
        "[000] ('nutrunner'), the rare-impact wrench's flywheel and rollers at impact.rare's "
        "release speed [002] ('rare_impact'), or a continuous tool limited by a ball clutch "
        "[001] ('clutch')",
        default="energy",
        kind="choice",
        choices=SOURCES,
        group="source",
    ),
    positive(
        "tool_energy",
        "J",
        "kinetic energy of the tool at the blow (source energy)",
        maximum=1e6,
        group="source",
    ),
    positive(
        "tool_inertia",
        "kg*m^2",
        "inertia of the striking tool J_t (source energy)",
        maximum=1e4,
        group="source",
    ),
    positive(
        "tool_stiffness",
        "N*m/rad",
        "torsional stiffness C between tool inertia and nut (anvil, spindle, socket); "
        "computed from shaft 7 and spindle 8 for the nut-runner [000, eq. 9]",
        maximum=1e9,
        group="source",
    ),
    Param(
        "drive_torque",
        "N*m",
        "torque that keeps driving the tool during the blow (e.g. the motor), at the nut; "
        "absent: none",
        minimum=-1e5,
        maximum=1e5,
        group="source",
    ),
    Param(
        "coupling_slip_torque",
        "N*m",
        "slipping torque of the nut-runner's safety coupling 1 at the motor shaft, fed into "
        "the blow while it slips [000, text] (source nutrunner); absent: none",
        minimum=0.0,
        maximum=1e5,
        group="nut-runner",
    ),
    Param(
        "blow_efficiency",
        "1",
        "fraction of the source's kinetic energy that reaches the blow (jaw engagement losses)",
        default=1.0,
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
    ),
    *_borrow(NUTRUNNER_DRIVE, _NR_NAMES + _NR_MOTOR, "nut-runner"),
    *_borrow(RARE_IMPACT, _RI_NAMES + _RI_MOTOR, "rare-impact"),
    *_borrow(BALL_CLUTCH, _CL_NAMES, "clutch"),
    positive(
        "clutch_spring_force",
        "N",
        "force of the clutch spring (source clutch) [001, eq. 2]",
        maximum=1e6,
        group="clutch",
    ),
    Param(
        "spring_force_tolerance",
        "1",
        "± relative tolerance of the clutch spring force (source clutch)",
        default=0.1,
        minimum=0.0,
        maximum=0.9,
        group="clutch",
    ),
    friction_coefficient(
        "flank_friction_scatter",
        "± scatter of the clutch's flank friction (source clutch)",
        default=0.03,
        maximum=0.5,
        group="clutch",
    ),
    Param(
        "struck_inertia",
        "kg*m^2",
        "inertia of socket, extension and nut J_s (simulation)",
        default=5e-4,
        minimum=1e-9,
        maximum=1e4,
        group="struck side",
    ),
    Param(
        "breakaway_factor",
        "1",
        "b: a nut at rest turns only when the torque exceeds b × the joint torque (static "
        "over kinetic friction)",
        default=1.0,
        minimum=1.0,
        maximum=3.0,
        group="struck side",
    ),
    Param(
        "restitution",
        "1",
        "coefficient of restitution of the blow (1: lossless spring; simulation)",
        default=1.0,
        minimum=0.14,
        maximum=1.0,
        group="struck side",
    ),
    Param(
        "joint_rate_from",
        "1",
        "the joint's torque rate: ISO 5393 hard (30° snug to target) or soft (720°) test "
        "joint, the joint's compliances and thread ('joint'), or a number",
        default="iso5393_hard",
        kind="choice",
        choices=RATES,
        group="joint",
    ),
    Param(
        "joint_rate",
        "N*m/rad",
        "torque rate k_j of the joint ('number'); 0 with snug_torque 0: a free struck side "
        "(the two-flywheel impact, simulation rung)",
        minimum=0.0,
        maximum=1e9,
        group="joint",
    ),
    Param(
        "snug_torque",
        "N*m",
        "joint torque when the blows start",
        default=0.0,
        minimum=0.0,
        maximum=1e6,
        group="joint",
    ),
    positive("target_torque", "N*m", "target joint torque", maximum=1e6, group="joint"),
    positive(
        "target_preload", "N", "target preload (needs the thread)", maximum=1e8, group="joint"
    ),
    positive("preload_min", "N", "lowest acceptable preload", maximum=1e8, group="joint"),
    positive("preload_max", "N", "highest acceptable preload", maximum=1e8, group="joint"),
    length(
        "thread_diameter",
        "nominal thread diameter d (for preload)",
        minimum=1e-3,
        maximum=0.2,
        group="thread",
    ),
    length(
        "thread_pitch",
        "pitch P (ISO 261 coarse when absent)",
        minimum=1e-4,
        maximum=0.01,
        group="thread",
    ),
    friction_coefficient("thread_friction", "μ_G", default=0.12, group="thread"),
    friction_coefficient("bearing_friction", "μ_K", default=0.12, group="thread"),
    friction_coefficient(
        "friction_scatter",
        "± scatter of μ_G and μ_K (clutch window)",
        default=0.02,
        maximum=0.5,
        group="thread",
    ),
    length(
        "bearing_outer_diameter",
        "D_f = d_w (ISO 4017 when absent)",
        minimum=1e-3,
        maximum=0.5,
        group="thread",
    ),
    length(
        "hole_diameter",
        "d_h (ISO 273 medium when absent)",
        minimum=1e-3,
        maximum=0.5,
        group="thread",
    ),
    *(
        dataclasses.replace(TIGHTENING.param(name), group="thread")
        for name in ("property_class", "yield_strength")
    ),
    Param(
        "torque_formula",
        "1",
        "tightening relation",
        default="vdi2230",
        kind="choice",
        choices=("vdi2230", "exact", "approx"),
        group="thread",
    ),
    positive(
        "bolt_compliance",
        "m/N",
        "δ_S (from clamped_length when absent) [004, eq. 4, 7]",
        maximum=1e-3,
        group="joint compliance",
    ),
    positive(
        "clamped_compliance",
        "m/N",
        "δ_P of the clamped parts ('joint'; absent: VDI 2230-1 R3 cone over clamped_length)",
        maximum=1e-3,
        group="joint compliance",
    ),
    length(
        "clamped_length",
        "clamp length l_K (bolt compliance when δ_S is absent)",
        minimum=1e-4,
        maximum=5.0,
        group="joint compliance",
    ),
    positive(
        "youngs_modulus",
        "Pa",
        "E of the bolt (and of the plates for the cone)",
        maximum=1e12,
        default=2.1e11,
        group="joint compliance",
    ),
    count("max_blows", "most blows to try", minimum=1, maximum=1000, default=100),
)

# --------------------------------------------------------------------------- outputs

_OUTPUTS: tuple[Output, ...] = (
    Output(
        "tool_energy_used",
        "J",
        "kinetic energy per blow (after the blow efficiency)",
        symbol="E",
        step="[000, eq. 3–4]",
    ),
    Output(
        "tool_inertia_used",
        "kg*m^2",
        "inertia of the striking tool at the nut",
        symbol="J_t",
        step="[000, eq. 3–4]",
    ),
    Output(
        "tool_speed",
        "rad/s",
        "tool speed at the blow",
        display_unit="rpm",
        symbol="ω_t",
        step="[000, eq. 3–4]",
    ),
    Output(
        "tool_stiffness_used",
        "N*m/rad",
        "torsional stiffness C of the tool",
        symbol="C",
        step="[000, eq. 9]",
    ),
    Output(
        "joint_rate_used", "N*m/rad", "torque rate k_j of the joint", symbol="k_j", step="ISO 5393"
    ),
    Output(
        "rigid_torque",
        "N*m",
        "√(2EC) + drive torque: the paper's blow into a fixed end [000, eq. 7–8, 10]",
        symbol="M",
        step="[000, eq. 7–8, 10]",
    ),
    Output(
        "peak_torque",
        "N*m",
        "peak spring torque of the first blow",
        symbol="M_peak",
        step="[000, eq. 7–8]",
    ),
    Output(
        "nut_rotation",
        "rad",
        "nut rotation in the first blow",
        display_unit="deg",
        symbol="φ_t",
        step="[000, eq. 7–8]",
    ),
    Output(
        "torque_after_first_blow",
        "N*m",
        "joint torque after the first blow",
        symbol="T_1",
        step="[000, eq. 7–8]",
    ),
    Output(
        "preload_after_first_blow",
        "N",
        "preload after the first blow",
        display_unit="kN",
        symbol="F_1",
        step="[004, eq. 10–13]",
    ),
    Output(
        "blows_to_target",
        "1",
        "blows until the target torque/preload",
        kind="int",
        symbol="n",
        step="[000, eq. 7–8]",
    ),
    Output(
        "final_torque",
        "N*m",
        "joint torque after the last blow",
        symbol="M_final",
        step="[000, eq. 7–8]",
    ),
    Output(
        "final_preload",
        "N",
        "preload after the last blow",
        display_unit="kN",
        symbol="F_V,final",
        step="[004, eq. 10–13]",
    ),
    Output(
        "saturation_torque",
        "N*m",
        "joint torque above which a blow no longer turns the "
        "nut (energy balance: (N + √(N² + 2EC))/b)",
        symbol="T_sat",
        step="[000, eq. 7–8]",
    ),
    Output(
        "joint_energy_fraction",
        "1",
        "first blow's work into the joint / the tool's kinetic energy E; the drive's work "
        "N·φ_t during the blow is not in E, so with a drive torque it can exceed 1",
        symbol="W_j/E",
        step="[000, eq. 7–8]",
    ),
    Output(
        "energy_supplied", "J", "energy supplied over all blows", symbol="ΣE", step="[000, eq. 3–4]"
    ),
    Output(
        "blow_interval",
        "s",
        "time from one blow to the next: the source's motor spins the flywheel from rest "
        "back to its blow speed (nut-runner T/P [000, eq. 5]; rare impact: impact.rare's "
        "cycle [002]; energy: J_t·ω0/N)",
        symbol="Δt_b",
        step="[000, eq. 5]",
    ),
    Output(
        "blows_per_second",
        "1/s",
        "blows per second, 1/blow_interval",
        symbol="f_b",
        step="[000, eq. 5]",
    ),
    Output(
        "time_to_final",
        "s",
        "time from motor start to the last blow: blows × blow_interval",
        symbol="t_N",
        step="[000, eq. 5]",
    ),
    Output(
        "energy_into_joint",
        "J",
        "work into the joint over all blows",
        symbol="W_j",
        step="[000, eq. 7–8]",
    ),
    Output(
        "preload_verdict",
        "1",
        "final preload against [preload_min, preload_max]",
        kind="str",
        symbol="",
        step="",
    ),
    Output(
        "yield_preload",
        "N",
        "F_M0.2: preload at which the bolt yields, torsion included (VDI 2230-1 R7, ν = 1)",
        display_unit="kN",
        symbol="F_M0.2",
        step="VDI 2230-1 R7",
    ),
    Output(
        "breaking_load",
        "N",
        "F_B = R_m·A_s: the bolt's breaking load",
        display_unit="kN",
        symbol="F_B",
        step="ISO 898-1",
    ),
    Output(
        "bolt_verdict",
        "1",
        "what the blows do to the bolt: 'elastic', 'past yield' or 'past breaking'",
        kind="str",
        symbol="",
        step="VDI 2230-1 R7",
    ),
    Output(
        "clutch_torque_min",
        "N*m",
        "lowest slipping torque (source clutch) [001, eq. 1–3]",
        symbol="T_min",
        step="[001, eq. 1–3]",
    ),
    Output(
        "clutch_torque_max",
        "N*m",
        "highest slipping torque (source clutch)",
        symbol="T_max",
        step="[001, eq. 1–3]",
    ),
    Output(
        "delivered_preload_min",
        "N",
        "lowest preload the clutch gives",
        display_unit="kN",
        symbol="F_M,min",
        step="VDI 2230-1 R13",
    ),
    Output(
        "delivered_preload_max",
        "N",
        "highest preload the clutch gives",
        display_unit="kN",
        symbol="F_M,max",
        step="VDI 2230-1 R13",
    ),
    Output(
        "clutch_spring_force_for_target",
        "N",
        "spring force that sets the clutch for the target preload at nominal friction",
        symbol="F",
        step="[001, eq. 1–3]",
    ),
    Output("blow_number", "1", "blow number", series=True),
    Output("torque_per_blow", "N*m", "joint torque after each blow", series=True, x="blow_number"),
    Output(
        "preload_per_blow",
        "N",
        "preload after each blow",
        series=True,
        x="blow_number",
        display_unit="kN",
    ),
    Output("peak_per_blow", "N*m", "peak torque of each blow", series=True, x="blow_number"),
    Output(
        "rotation_per_blow",
        "rad",
        "nut rotation in each blow",
        series=True,
        x="blow_number",
        display_unit="deg",
    ),
    Output(
        "blow_time",
        "s",
        "time of each blow from motor start (blow_number × blow_interval)",
        series=True,
        x="blow_number",
    ),
    Output(
        "torque_against_time",
        "N*m",
        "joint torque after each blow against its time",
        series=True,
        x="blow_time",
    ),
    Output(
        "preload_against_time",
        "N",
        "preload after each blow against its time",
        series=True,
        x="blow_time",
        display_unit="kN",
    ),
    Output(
        "time_in_blow", "s", "time in the first blow (simulation)", series=True, display_unit="ms"
    ),
    Output(
        "torque_in_blow",
        "N*m",
        "spring torque in the first blow (simulation)",
        series=True,
        x="time_in_blow",
    ),
)

# --------------------------------------------------------------------------- the tool


@dataclasses.dataclass
class _Tool:
    """The striking tool at the nut: floats for one design, arrays for many."""

    energy: Any  # after the blow efficiency [J]
    inertia: Any  # J_t [kg·m²]
    stiffness: Any  # C [N·m/rad]
    drive: Any  # N, net drive during the blow [N·m]
    fails: Any  # where the arithmetic fails (a spindle speed or stiffness that underflows)
    notes: list[str]  # what the source took from the tool model (one design)
    kinetic: Any = None  # the source's kinetic energy before the blow efficiency [J]
    striker: Any = None  # the rare-impact source's striker (_Striker)


def _need(x: Mapping[str, Any], names: tuple[str, ...], why: str) -> None:
    for name in names:
        if x.get(name) is None:
            raise InputOutOfRange(f"{name} is required {why}", field=name)


#: K_r where blow.joint is not given one: the ball clutch model's own default [001, eq. 1].
_LOAD_FACTOR = BALL_CLUTCH.param("load_factor").default


def _clutch_args(x: Mapping[str, Any]) -> tuple[tuple[Any, Any, Any, Any], list[str]]:
    """(D0, α, i, K_r) of the clutch source, and a note where K_r took the clutch's default.

    The borrowed inputs are optional here, so ``load_factor`` may be absent; only the
    per-ball arrangement reads it (until now its absence there raised a TypeError: a 500).
    """
    load = x["load_factor"]
    notes: list[str] = []
    if load is None:
        load = _LOAD_FACTOR
        if x["spring_arrangement"] == "per_ball":
            notes.append(
                f"load_factor not given: K_r = {load:g}, the ball clutch model's default "
                "(0.85…0.9 [001, eq. 1])"
            )
    return (x["ball_circle_diameter"], x["groove_angle"], x["ball_count"], load), notes


@dataclasses.dataclass
class _Striker:
    """The rare-impact source's striker at release (floats or arrays, one design each)."""

    speed: Any  # ω_M [rad/s]
    radius: Any  # r, the rollers' centre radius [m]
    inertia: Any  # I of the rotating parts [kg·m²]
    energy: Any  # ½·I·ω_M² [J]
    refused: Any  # where impact.rare refuses the design
    design: dict[str, Any]  # impact.rare's inputs
    cycle: Any = None  # impact.rare's closed-form cycle of one design, where it was worked out


def _striker(x: Mapping[str, Any], one: bool) -> _Striker:
    r"""The rare-impact source's striker at release, from the striker model's own closed form.

    The release speed :math:`\omega_M` and radius :math:`r` are those of ``impact.rare``'s
    closed-form rung (``engine.procedures.striker_cycle``: the chosen roller geometry, the weight
    of half-coupling, shaft and rollers, the snap-through at lift-off), its stage-1
    functions for one striker, its closed form on arrays where striker inputs vary; the
    energy of the rotating parts at release is

    .. math::
        E = \tfrac{1}{2}\,I\,\omega_M^2

    with :func:`engine.physics.rare_impact.rotating_inertia` [002, after eq. 4]. The striker's
    inputs blow.joint does not borrow take their defaults in ``impact.rare``. One design the
    striker model refuses raises its reason; on arrays ``refused`` marks them.

    >>> s = _striker(RARE_IMPACT_M16, True)  # 6 rollers of 50 g at r = 42.5 mm
    >>> round(s.speed, 2), round(s.inertia, 9), round(s.energy, 2)  # ½·1.541875e-3·243.96²
    (243.96, 0.001541875, 45.89)
    """
    design = {**_STRIKER_DEFAULTS, **{n: x[n] for n in _RI_NAMES}}
    design.update((n, x[n]) for n in _RI_MOTOR if x.get(n) is not None)
    refused: Any = False
    cycle: Any = None
    if one:  # one design: impact.rare's cycle, whose release the blow and whose time it needs
        cycle = closed_form_cycle(design, refuse=False)
        if cycle.refusal == NOT_HELD:
            closed_form_cycle(design)  # raises the refusal with its reason
        w_m, r = float(cycle.release_speed), float(cycle.release_radius)
    elif not any(isinstance(design[n], np.ndarray) for n in _RI_NAMES):
        # one striker in a sweep of anything else: impact.rare's stage 1
        try:
            w_m, r = release_speed_of(design), release_radius_of(design)
        except InfeasibleDesign:
            w_m = r = math.nan
            refused = True
    else:
        cycle = closed_form_cycle(design, refuse=False)
        w_m, r, refused = cycle.release_speed, cycle.release_radius, cycle.refused
    with np.errstate(all="ignore"):
        inertia = rotating_inertia(
            design["flywheel_inertia"],
            design["roller_count"],
            design["roller_mass"],
            r,
            rollers_counted=design["roller_geometry"] != "paper",
        )
        return _Striker(w_m, r, inertia, 0.5 * inertia * w_m * w_m, refused, design, cycle)


def _striker_note(s: _Striker) -> str:
    """What the rare-impact source took from the striker model (one design)."""
    geometry = s.design["roller_geometry"]
    return (
        f"rare-impact: one blow per release at impact.rare's closed-form release speed "
        f"ω_M = {q(float(s.speed), 'rpm', fmt='.0f')} ({geometry} roller geometry, "
        f"g = {s.design['gravity']:g} m/s²) [002, after eq. 4]; the flywheel "
        + (
            "alone (the paper's geometry)"
            if geometry == "paper"
            else f"with the rollers at r = {q(float(s.radius), 'mm', 4)}"
        )
        + f", I = {q(float(s.inertia), 'kg*m^2', 4)}, "
        f"carries E = ½·I·ω_M² = {q(float(s.energy), 'J', 4)}"
    )


def _tool(x: Mapping[str, Any], one: bool) -> _Tool:
    """The source's tool: energy (after the efficiency), inertia, stiffness and drive.

    One procedure for one design (floats) and many (arrays of one shape); ``fails``
    marks the designs where the arithmetic fails (a spindle speed or a stiffness that
    underflows to 0 with inputs at their declared extremes), and a striker the striker
    model refuses raises its reason for one design.
    """
    src = x["source"]
    notes: list[str] = []
    drive = _or_zero(x["drive_torque"])
    fails: Any = False
    if src == "energy":
        _need(x, ("tool_energy", "tool_inertia", "tool_stiffness"), "with source 'energy'")
        e, j, c = x["tool_energy"], x["tool_inertia"], x["tool_stiffness"]
    elif src == "nutrunner":
        _need(x, _NR_NAMES, "with source 'nutrunner'")
        w = x["motor_speed"]
        e = nr.kinetic_energy(w, *(x[n] for n in _NR_NAMES[1:12]))
        w3 = nr.flywheel_speed(w, x["motor_pulley_diameter"], x["flywheel_diameter"])
        w5 = nr.spindle_speed(w3, x["drive_gear_diameter"], x["spindle_gear_diameter"])
        g = x["shear_modulus"]
        c7 = nr.torsional_stiffness(g, x["shaft_diameter"], x["shaft_length"])
        c8 = nr.torsional_stiffness(g, x["spindle_diameter"], x["spindle_length"])
        fails = (w5 * w5 == 0.0) | (c7 + c8 == 0.0)
        if one and fails:
            raise ZeroDivisionError("the spindle speed or the shaft stiffness underflows to 0")
        with _quiet(not one):
            j = 2.0 * e / (w5 * w5)
            c = c7 * c8 / (c7 + c8)
            drag = (x["spindle_count"] - 1) * x["idle_spindle_friction_torque"]
            feed = _or_zero(x["coupling_slip_torque"]) * w / w5
        drive = drive + (feed - drag)
        if one:
            notes.append(
                f"nut-runner: drive energy T = {q(float(e), 'J', 4)} [000, eq. 3–4] at spindle "
                f"speed {q(float(w5), 'rpm', fmt='.0f')}, "
                f"i.e. J_t = 2T/ω5² = {q(float(j), 'kg*m^2', 4)} "
                f"at the spindle; C = C7·C8/(C7 + C8) = {q(float(c), 'N*m/rad', 4)} [000, eq. 7–9] "
                "(the paper's convention, gear ratio ignored); idle spindles take (z − 1)·M_tr "
                f"= {q(float(drag), 'N*m', 4)} [000, eq. 10]"
                + (
                    f", the slipping coupling 1 feeds {q(float(feed), 'N*m', 4)} [000, text]"
                    if feed
                    else ""
                )
            )
    elif src == "rare_impact":
        _need(x, (*_RI_NAMES, "tool_stiffness"), "with source 'rare_impact'")
        striker = _striker(x, one)  # one design the striker model refuses raises here
        j, e, fails = striker.inertia, striker.energy, striker.refused
        c = x["tool_stiffness"]
        if one:
            notes.append(_striker_note(striker))
    else:
        raise AssertionError(src)
    return _Tool(
        x["blow_efficiency"] * e,
        j,
        c,
        drive,
        fails,
        notes,
        e,
        striker if src == "rare_impact" else None,
    )


def _blow_interval(x: Mapping[str, Any], s: _Setup) -> tuple[Any, str]:
    r"""Time from one blow to the next: the source's motor brings the flywheel back.

    Each blow is taken to leave the flywheel at rest (its energy spent on the joint, the
    tool's spring and the contact; a rebound is not driven back); the source's own motor
    then spins it up to the blow speed again:

    .. math::
        \Delta t = \frac{T}{P}\ \text{(nut-runner [000, eq. 5])},\qquad
        \Delta t = t_{cycle}\ \text{(rare impact [002]: spin-up to re-lock)},\qquad
        \Delta t = \frac{J_t\,\omega_0}{N}\ \text{(energy: the drive torque N)}

    (T the drive's kinetic energy at working speed, P the motor power; t_cycle impact.rare's
    closed-form cycle from motor start to re-lock with the striker's motor; J_t ω0/N a
    constant torque N on J_t from rest to ω0). Floats or arrays; NaN where the source has
    no motor (the second value says why, one design).
    """
    src = x["source"]
    tool = s.tool
    if src == "nutrunner":
        power = x.get("motor_power")
        if power is None:
            return math.nan, "give motor_power for the time between blows"
        return nr.acceleration_time(tool.kinetic, power), (
            "the drive's energy T restored at constant motor power P after each blow, "
            "Δt = T/P [000, eq. 5]"
        )
    if src == "rare_impact":
        cycle = tool.striker.cycle or closed_form_cycle(tool.striker.design, refuse=False)
        one = not isinstance(cycle.refusal, np.ndarray)
        if one and cycle.refused:
            return math.nan, (
                "impact.rare refuses the striker's cycle (its motor never reaches the release "
                "speed, or the preloads do not hold the half-coupling)"
            )
        t_cycle = cycle.cycle_time  # a property summing the stages: read it once
        if one and not math.isfinite(t_cycle):
            return math.nan, "the striker's cycle never re-locks (impact.rare)"
        return t_cycle, (
            "one impact.rare cycle per blow, from motor start to re-lock (spin-up "
            "[002, eq. 1], engagement, return, re-lock [002, eq. 4])"
        )
    drive = tool.drive
    with _quiet(s.many):  # arrays: 0/0 and overflow are NaN and inf, as wanted
        dt = where(drive > 0.0, tool.inertia * s.speed / where(drive > 0.0, drive, 1.0), math.nan)
    return dt, (
        "the drive torque N spins the tool from rest to ω0 after each blow, Δt = J_t·ω0/N"
        if isinstance(drive, np.ndarray) or drive > 0.0
        else "give a positive drive_torque for the time between blows (source 'energy')"
    )


# --------------------------------------------------------------------------- the joint


def _bolt_inputs(x: Mapping[str, Any]) -> dict[str, Any]:
    """The inputs :func:`resolve_bolt` (or ``resolve_bolts``) reads for the joint."""
    return {
        name: x.get(name)
        for name in (
            "thread_diameter",
            "thread_pitch",
            "bearing_outer_diameter",
            "hole_diameter",
            "property_class",
            "yield_strength",
        )
    }


def _clutch_bolt_inputs(x: Mapping[str, Any]) -> dict[str, Any]:
    """:func:`_bolt_inputs` for the clutch, whose window does not read the strength."""
    return {**_bolt_inputs(x), "yield_strength": 1.0}  # skips the class lookup


def _bolt_notes(notes: list[str]) -> list[str]:
    """The bolt's notes less the placeholder strength's."""
    return [n for n in notes if not n.startswith("yield strength")]


def _bolt_strength(bolt: Any, thread_friction: float) -> tuple[float, float]:
    """(F_M0.2, F_B): the bolt's yield preload and breaking load, [N].

    F_M0.2 is VDI 2230-1 R7's assembly preload at ν = 1, the thread's torsion β
    included (:func:`engine.physics.preload.assembly_preload`); F_B = R_m·A_s, ISO 898-1's
    minimum ultimate tensile load (NaN where only R_p0.2 is known).
    """
    beta = pl.torsion_factor(bolt.pitch, bolt.pitch_diameter, bolt.stress_diameter, thread_friction)
    f_y = float(pl.assembly_preload(bolt.yield_strength, bolt.stress_area, beta, 1.0))
    r_m = bolt.tensile_strength
    f_b = math.nan if r_m is None else float(pl.assembly_preload(r_m, bolt.stress_area, 1.0, 1.0))
    return f_y, f_b


def _thread(x: Mapping[str, Any]) -> tuple[Any, float, list[str], float, float] | None:
    """(bolt, k_G + k_K, notes, F_M0.2, F_B), or None without a thread."""
    if x.get("thread_diameter") is None:
        return None
    bolt, notes = resolve_bolt(_bolt_inputs(x))
    kg, kk, _ = torque_coefficients(
        bolt, x["thread_friction"], x["bearing_friction"], x["torque_formula"]
    )
    return bolt, kg + kk, notes, *_bolt_strength(bolt, x["thread_friction"])


def _target(x: Mapping[str, Any], per_preload: Any) -> Any:
    """The target joint torque (floats or arrays; None without a target)."""
    if x.get("target_torque") is not None:
        return x["target_torque"]
    if x.get("target_preload") is not None:
        if per_preload is None:
            raise InputOutOfRange(
                "target_preload needs the thread (thread_diameter) for the tightening relation",
                field="thread_diameter",
            )
        return _times(x["target_preload"], per_preload)
    return None


def _times(a: Any, b: Any) -> Any:
    """a·b; where each is one number, or one number broadcast over the points (a group
    :func:`_per_group` resolved once), the product is worked out once and broadcast.

    >>> one = np.broadcast_to(np.array([2.0]), (3,))
    >>> _times(one, 1.5).tolist(), _times(one, np.array([1.0, 2.0, 3.0])).tolist()
    ([3.0, 3.0, 3.0], [2.0, 4.0, 6.0])
    """
    if a.__class__ is not np.ndarray and b.__class__ is not np.ndarray:  # one design
        return a * b
    arrays = [v for v in (a, b) if isinstance(v, np.ndarray)]
    shapes = {v.shape for v in arrays}
    if len(shapes) == 1 and all(v.size and not any(v.strides) for v in arrays):
        first = [v.flat[0] if isinstance(v, np.ndarray) else v for v in (a, b)]
        return np.broadcast_to(first[0] * first[1], shapes.pop())
    return a * b


def _rate(x: Mapping[str, Any], target: Any, from_joint: Any) -> Any:
    """The joint's torque rate k_j (floats or arrays): as given, an ISO 5393 test joint's,
    or ``from_joint`` (:func:`_joint_rate`, worked out per bolt)."""
    how = x["joint_rate_from"]
    if how == "number":
        _need(x, ("joint_rate",), "with joint_rate_from 'number'")
        return x["joint_rate"]
    if how.startswith("iso5393"):
        if target is None:
            raise InputOutOfRange(
                "an ISO 5393 test joint is set up for a target: give target_torque (or "
                "target_preload and the thread)",
                field="target_torque",
            )
        return iso5393_rate(target, how.split("_")[1])
    return from_joint


def _rate_note(x: Mapping[str, Any], target: float | None) -> str | None:
    """What the torque rate is, for one design (the 'joint' rate's note is its group's)."""
    how = x["joint_rate_from"]
    if how == "number":
        return "torque rate as given"
    if how.startswith("iso5393"):
        kind = how.split("_")[1]
        return (
            f"ISO 5393 {kind} test joint: target "
            f"{q(math.nan if target is None else target, 'N*m', 4)} reached "
            f"{'30' if kind == 'hard' else '720'}° after snug"
        )
    return None


def _joint_rate(x: Mapping[str, Any], thread: Any) -> tuple[float, str]:
    """The torque rate of the joint from its compliances and thread, one bolt [004, eq. 8]."""
    if thread is None:
        raise InputOutOfRange(
            "joint_rate_from 'joint' needs thread_diameter", field="thread_diameter"
        )
    bolt, per_preload = thread[0], thread[1]
    delta_p = x.get("clamped_compliance")
    how_p = "as given"
    if delta_p is None:
        _need(x, ("clamped_length",), "with joint_rate_from 'joint' (or give clamped_compliance)")
        delta_p = vdi_clamped_compliance(
            [x["clamped_length"]],
            [x["youngs_modulus"]],
            bolt.bearing_outer_diameter,
            bolt.hole_diameter,
        ).total
        how_p = "VDI 2230-1 R3 deformation cone, one plate of l_K, wide plates, through bolt"
    delta_s = x.get("bolt_compliance")
    how_s = "as given"
    if delta_s is None:
        _need(x, ("clamped_length",), "to compute the bolt compliance (or give bolt_compliance)")
        d, d3 = bolt.diameter, bolt.minor_diameter
        delta_s = pl.axial_compliance(
            [x["clamped_length"], 0.8 * d / 3.0], [d, d3], x["youngs_modulus"]
        )
        how_s = "plain shank over l_K plus a third of the nut height at d3 [004, eq. 4, 7]"
    k = joint_rate(per_preload, bolt.pitch, float(delta_s), float(delta_p))
    return k, (
        f"joint: k_j = (k_G + k_K)·P/(2π(δ_S + δ_P)) = {q(k, 'N*m/rad', 4)} with k_G + k_K = "
        f"{q(per_preload, 'mm', 4)} (tightening relation), δ_S = {q(float(delta_s), 'm/N', 4)} "
        f"({how_s}), δ_P = {q(float(delta_p), 'm/N', 4)} ({how_p}) [004, eq. 8]"
    )


# --------------------------------------------------------------------------- rungs


@dataclasses.dataclass
class _Setup:
    """A request's tool and joint: floats for one design, arrays for many (one each)."""

    tool: _Tool
    energy: Any  # E = ½·J_t·ω0², after the blow efficiency [J]
    speed: Any  # ω0 [rad/s]
    rate: Any  # k_j [N·m/rad]
    per: Any  # k_G + k_K [m]; None without a thread
    target: Any  # the target joint torque [N·m]; None without one
    yield_preload: Any  # F_M0.2 [N]; None without a thread
    breaking_load: Any  # F_B = R_m·A_s [N]; None without a thread (NaN: R_m unknown)
    refused: Any  # the designs the physics refuses (False for one design: it raises)
    notes: list[str]  # the rate's and the thread's (one design)

    @property
    def many(self) -> bool:
        """Whether this is the setup of many designs (arrays), not of one (floats)."""
        return isinstance(self.refused, np.ndarray)

    @property
    def yield_torque(self) -> Any:
        """T_y = (k_G + k_K)·F_M0.2, where the joint's torque–angle line bends over [N·m]."""
        return math.inf if self.per is None else _times(self.per, self.yield_preload)

    def problem(self, x: Mapping[str, Any]) -> BlowProblem:
        """The blow of one design."""
        return BlowProblem(
            float(self.tool.inertia),
            float(x["struck_inertia"]),
            float(self.tool.stiffness),
            float(self.speed),
            float(self.rate),
            float(x["breakaway_factor"]),
            float(self.tool.drive),
            float(x["restitution"]),
        )


def _setup(x: Mapping[str, Any], scratch: Scratch) -> _Setup:
    """The tool, the thread's torque per preload, the target and the joint's torque rate.

    One procedure for one design (floats) and many (arrays of one shape). The bolt and a
    'joint' rate are resolved once per distinct combination of the inputs they read
    (:func:`_per_group`). For one design a refusal raises its reason; for many the refused
    designs are marked in ``refused`` (a sweep runs them alone, to say why). Worked out
    once per request: the rung's estimate and the compute share it through the request's
    ``scratch`` (:class:`~engine.core.spec.Scratch`), which lives for one run or one chunk.
    """
    return scratch.once("blow.setup", lambda: _setup_of(x))


def _setup_of(x: Mapping[str, Any]) -> _Setup:
    """:func:`_setup` worked out."""
    one = not _is_array(x)
    tool = _tool(x, one)
    names = _THREAD_INPUTS + (_JOINT_INPUTS if x["joint_rate_from"] == "joint" else ())
    got, refused, notes, error = _per_group(x, names, _thread_and_joint, 4, one)
    threaded = x.get("thread_diameter") is not None
    per = got[0] if threaded else None
    f_y, f_b = (got[2], got[3]) if threaded else (None, None)
    target = _target(x, per)  # first: a target preload without a thread says so
    if one and error is not None:
        raise error
    k = _rate(x, target, got[1])
    with _quiet(not one):
        speed = sqrt(2.0 * tool.energy / tool.inertia)
        energy = 0.5 * tool.inertia * speed**2
        overflow = _squares_overflow(speed) | _squares_overflow(tool.drive)
    if one:
        if overflow:
            raise OverflowError("the tool's speed or drive torque squared overflows a float")
        per = None if per is None else float(per)
        target = None if target is None else float(target)
        note = _rate_note(x, target)
        return _Setup(
            tool,
            float(energy),
            float(speed),
            float(k),
            per,
            target,
            None if f_y is None else float(f_y),
            None if f_b is None else float(f_b),
            False,
            ([note] if note else []) + notes,
        )
    refused = np.broadcast_to(refused | tool.fails | overflow, _points(x))
    return _Setup(tool, energy, speed, k, per, target, f_y, f_b, refused, notes)


def _setup_or_none(x: Mapping[str, Any], scratch: Scratch) -> _Setup | None:
    """:func:`_setup`, or None where it refuses (an estimate then has none)."""
    try:
        return _setup(x, scratch)
    except (ArithmeticError, ValueError):  # EngineError is a ValueError
        return None


#: The outputs :func:`_tool_values` gives (the tool and the joint alone, no blow run).
_TOOL_VALUES = (
    "tool_energy_used",
    "tool_inertia_used",
    "tool_speed",
    "tool_stiffness_used",
    "joint_rate_used",
    "rigid_torque",
    "saturation_torque",
)

#: The outputs that need the blows run (every one :func:`_tool_values` does not give).
_NEED_BLOWS = tuple(o.name for o in _OUTPUTS if o.name not in _TOOL_VALUES)


def _tool_values(x: Mapping[str, Any], s: _Setup) -> dict[str, Any]:
    """The outputs that follow from the tool and the joint alone (floats or arrays).

    Its keys are :data:`_TOOL_VALUES`, in that order.
    """
    e, c, drive = s.energy, s.tool.stiffness, s.tool.drive
    with _quiet(s.many):
        return {
            "tool_energy_used": e,
            "tool_inertia_used": s.tool.inertia,
            "tool_speed": s.speed,
            "tool_stiffness_used": c,
            "joint_rate_used": s.rate,
            "rigid_torque": rigid_blow_torque(e, c) + drive,
            # the energy balance's blow into a held nut over b
            "saturation_torque": held_blow_peak(e, c, drive) / x["breakaway_factor"],
        }


#: The outputs :func:`_blow_values` gives where it is not told which are asked.
_EVERY_BLOW_VALUE = frozenset(
    (
        *("peak_torque", "torque_after_first_blow", "final_torque", "energy_supplied"),
        *("nut_rotation", "joint_energy_fraction", "energy_into_joint"),
        *("preload_after_first_blow", "final_preload"),
    )
)


def _blow_values(
    rung: str,
    s: _Setup,
    *,
    peak: Any,
    rotation: Any,
    after: Any,
    work: Any,
    final: Any,
    blows: Any,
    joint_work: Any,
    outputs: Container[str] | None = None,
) -> dict[str, Any]:
    """The outputs of the blows (floats for one design, arrays for many).

    From the first blow (peak, rotation, joint torque after, work into the joint), the
    last blow's joint torque, the number of blows and the work of all of them: the
    preloads through the tightening relation (with a thread) and the energy account (not
    on the rigid rung, whose joint torque does not follow from an energy balance).
    With ``outputs`` given, only those are worked out (the others' inputs may be None).
    """
    want = _EVERY_BLOW_VALUE if outputs is None else outputs
    values: dict[str, Any] = {}
    if "peak_torque" in want:
        values["peak_torque"] = peak
    if "torque_after_first_blow" in want:
        values["torque_after_first_blow"] = after
    if "final_torque" in want:
        values["final_torque"] = final
    if "energy_supplied" in want:
        values["energy_supplied"] = s.energy * blows
    if rung != "rigid":
        if "nut_rotation" in want:
            values["nut_rotation"] = rotation
        if "joint_energy_fraction" in want:
            values["joint_energy_fraction"] = work / s.energy
        if "energy_into_joint" in want:
            values["energy_into_joint"] = joint_work
    if s.per is not None:
        if "preload_after_first_blow" in want:
            values["preload_after_first_blow"] = after / s.per
        if "final_preload" in want:
            values["final_preload"] = final / s.per
    return values


#: The scalar outputs of the blows' sources, in their order (the clutch's are its own).
_BLOW_OUTPUTS = tuple(
    o.name for o in _OUTPUTS if not o.series and not o.name.startswith(("clutch", "delivered"))
)

#: The rigid rung on a joint whose torque does not rise (k_j = 0): refused, by name.
_RIGID_NEEDS_A_RATE = (
    "the rigid rung takes the joint to the blow's torque √(2EC) along its torque rate; with "
    "joint_rate 0 the joint's torque does not rise (a free struck side or a constant "
    "torque): use fidelity 'simulation'"
)

#: Outputs that need the time between blows (:func:`_blow_interval`).
_TIME_OUTPUTS = (
    "blow_interval",
    "blows_per_second",
    "time_to_final",
    "blow_time",
    "torque_against_time",
    "preload_against_time",
)

#: Outputs of the tool and the first blow alone (:func:`_tool_values`, :func:`_blow_values`):
#: a sweep asking for these only runs one blow.
_FIRST_BLOW_OUTPUTS = frozenset(
    (
        *_TOOL_VALUES,
        "peak_torque",
        "torque_after_first_blow",
        "nut_rotation",
        "joint_energy_fraction",
        "preload_after_first_blow",
        "blow_interval",
        "blows_per_second",
        "yield_preload",
        "breaking_load",
    )
)

#: The first-blow outputs that read the blow itself, and the :class:`BlowSeries` field
#: each reads (the others are the tool's, the thread's or the time between blows).
_FIRST_BLOW_FIELDS = (
    ("peak_torque", "peak"),
    ("torque_after_first_blow", "torque_after"),
    ("preload_after_first_blow", "torque_after"),
    ("nut_rotation", "rotation"),
    ("joint_energy_fraction", "work"),
)

#: Outputs whose energy-rung error is the nut's kick (energy_peak_error), not the torque's.
_PEAK_OUTPUTS = ("peak_torque", "peak_per_blow")


def _first_blow(x: Mapping[str, Any], s: _Setup) -> tuple[Any, Any]:
    """(peak torque, joint torque after) of the energy rung's first blow.

    The energy balance of :func:`~engine.physics.blow.energy_blow` on floats or arrays (on
    arrays it raises nothing: a point without a root is NaN); the value at a rate ≤ 0 or
    where the balance has no root is not used (NaN).
    """
    args = (s.energy, s.tool.stiffness, where(s.rate > 0.0, s.rate, 1.0), x["snug_torque"])
    try:
        blow = energy_blow(*args, x["breakaway_factor"], s.tool.drive)
    except (ArithmeticError, ValueError):  # one design without a root (EngineError is one)
        return math.nan, math.nan
    return blow[0], blow[1]


def _energy_errors(
    x: Mapping[str, Any], s: _Setup, first: tuple[Any, Any] | None = None
) -> tuple[Any, Any]:
    """(error of the joint torques, error of the peak torques) of the energy rung.

    Floats or arrays as ``s``; NaN where the rung has no estimate (a refused design, a
    joint with no torque rate). ``first``: the energy rung's first blow where the caller
    has it (:func:`_first_blow` otherwise).
    """
    peak, _ = _first_blow(x, s) if first is None else first
    k = s.rate
    with _quiet(s.many):
        kk = where(k > 0.0, k, 1.0)
        # the breakaway's jump at the first blow's start (snug)
        after = energy_blow_error(
            s.tool.inertia,
            x["struck_inertia"],
            s.tool.stiffness,
            kk,
            x["restitution"],
            x["breakaway_factor"],
            x["snug_torque"],
            s.energy,
        )
        blow = BlowProblem(s.tool.inertia, x["struck_inertia"], s.tool.stiffness, s.speed, kk)
        peak_error = after + energy_peak_error(blow, peak)
    bad = s.refused | where(k > 0.0, False, True)  # no estimate without a torque rate
    return where(bad, math.nan, after), where(bad, math.nan, peak_error)


def _rigid_error(x: Mapping[str, Any], s: _Setup) -> Any:
    """The rigid rung's error: its torque against the energy rung's, plus the latter's error."""
    first = _first_blow(x, s)
    after_error, peak_error = _energy_errors(x, s, first)
    with _quiet(s.many):
        after = first[1]
        rigid = rigid_blow_torque(s.energy, s.tool.stiffness) + s.tool.drive
        base = where(peak_error > after_error, peak_error, after_error)
        bad = s.refused | where(s.rate > 0.0, False, True)
        return where(bad, math.nan, abs(rigid - after) / after + base)


def _energy_error(x: Mapping[str, Any], s: _Setup, first: Any = None, peak: bool = True) -> Any:
    """The energy rung's estimate: of the peak torques (the larger) or of the joint torques.

    For one design an arithmetic failure (floats raise where arrays give inf or NaN) is
    no estimate (NaN), as on arrays.
    """
    try:
        after, at_peak = _energy_errors(x, s, first)
    except (ArithmeticError, ValueError):
        return math.nan
    return where(at_peak > after, at_peak, after) if peak else after


def _rigid_estimate_of(x: Mapping[str, Any], s: _Setup) -> Any:
    """:func:`_rigid_error`; for one design an arithmetic failure is no estimate (NaN)."""
    try:
        return _rigid_error(x, s)
    except (ArithmeticError, ValueError):
        return math.nan


def _estimate(s: _Setup, value: Any) -> Any:
    """An estimate as the runner takes it: a float or None for one design, else an array.

    One design or many as the setup ``s`` says (not a second scan of the inputs).
    """
    if s.many:
        return value
    v = float(value)
    return v if math.isfinite(v) else None


def _energy_estimate(x: Mapping[str, Any], scratch: Scratch | None = None) -> Any:
    if x["source"] == "clutch":
        return None
    s = _setup_or_none(x, Scratch() if scratch is None else scratch)
    if s is None:
        return np.full(_points(x), np.nan) if _is_array(x) else None
    return _estimate(s, _energy_error(x, s))


def _rigid_estimate(x: Mapping[str, Any], scratch: Scratch | None = None) -> Any:
    if x["source"] == "clutch":
        return None
    s = _setup_or_none(x, Scratch() if scratch is None else scratch)
    if s is None:
        return np.full(_points(x), np.nan) if _is_array(x) else None
    return _estimate(s, _rigid_estimate_of(x, s))


#: With damping the contact force is clipped at zero inside a step (the jaws part): RK4
#: loses order at that kink; measured ~1e-5 on the rebound speed (tests).
_DAMPED_SIMULATION_ERROR = 5e-5


def _simulation_estimate(x: Mapping[str, Any]) -> Any:
    if x["source"] == "clutch":
        return None
    if isinstance(x["restitution"], np.ndarray):
        return np.where(x["restitution"] >= 1.0, _SIMULATION_ERROR, _DAMPED_SIMULATION_ERROR)
    return _SIMULATION_ERROR if x["restitution"] >= 1.0 else _DAMPED_SIMULATION_ERROR


# --------------------------------------------------------------------------- compute


_WINDOW_LABELS = np.array(["within", "below", "above"], dtype=object)
_BOLT_LABELS = np.array(["elastic", "past yield", "past breaking"], dtype=object)


def _window_verdict(preload: Any, lo: Any, hi: Any) -> Any:
    """'below', 'within' or 'above' the window [lo, hi] (either limit may be None).

    A str for one design, an object array for many; a preload above the upper limit
    is 'above' even where it is also below the lower one (a window given upside down).

    >>> _window_verdict(80e3, 70e3, 100e3), _window_verdict(60e3, 70e3, None)
    ('within', 'below')
    >>> _window_verdict(np.array([60e3, 80e3, 120e3]), 70e3, 100e3).tolist()
    ['below', 'within', 'above']
    """
    code = _window_code(preload, lo, hi)
    return _WINDOW_LABELS[code] if isinstance(code, np.ndarray) else str(_WINDOW_LABELS[code])


def _window_code(preload: Any, lo: Any, hi: Any) -> Any:
    """:func:`_window_verdict` as an index into its labels: 0 within, 1 below, 2 above."""
    below = False if lo is None else preload < lo
    above = False if hi is None else preload > hi
    if isinstance(below, np.ndarray) or isinstance(above, np.ndarray):
        return np.where(above, 2, np.asarray(below, dtype=np.int8))
    return 2 if above else int(below)


def _clutch_verdict(f_lo: Any, f_hi: Any, lo: Any, hi: Any) -> tuple[Any, Any]:
    """(within, verdict) of the clutch's preloads [f_lo, f_hi] against [lo, hi].

    Within when the whole delivered window lies inside; else 'below' where a non-zero
    lower limit is undercut, 'above' otherwise. Floats (a bool and a str back) or arrays.

    >>> _clutch_verdict(15e3, 28e3, 15e3, 30e3), _clutch_verdict(14e3, 31e3, 15e3, 30e3)
    ((True, 'within'), (False, 'below'))
    >>> ok, v = _clutch_verdict(np.array([16e3, 16e3]), np.array([28e3, 31e3]), 15e3, None)
    >>> ok.tolist(), v.tolist()
    ([True, True], ['within', 'within'])
    """
    ok = np.logical_and(True if lo is None else f_lo >= lo, True if hi is None else f_hi <= hi)
    below = False if lo is None else np.logical_and(lo != 0.0, f_lo < lo)
    verdict = np.where(ok, "within", np.where(below, "below", "above"))
    if verdict.ndim == 0:
        return bool(ok), str(verdict)
    return ok, verdict.astype(object)


def _verdict(
    x: Mapping[str, Any], preload: float | None, notes: list[str]
) -> tuple[Any, list[Check]]:
    lo, hi = x.get("preload_min"), x.get("preload_max")
    if lo is None and hi is None:
        return None, []
    if preload is None:
        notes.append("preload_verdict is null: the preload needs the thread (thread_diameter)")
        return None, []
    if lo is not None and hi is not None and lo > hi:
        raise InputOutOfRange("preload_min must not exceed preload_max", field="preload_min")
    verdict = _window_verdict(preload, lo, hi)
    window = f"[{q(lo or 0.0, 'kN')}, {q(hi, 'kN') if hi else '∞'}]"
    check = Check(
        "preload_window",
        verdict == "within",
        f"final preload {q(preload, 'kN')} is {verdict} the window {window}"
        + (
            ""
            if verdict == "within"
            else (
                "; fewer blows, less energy per blow or a clutch-limited tool"
                if verdict == "above"
                else "; more blows or more energy per blow"
            )
        ),
    )
    return verdict, [check]


def _bolt_verdict(yielded: Any, demand: Any, breaking_load: Any) -> Any:
    """'elastic', 'past yield' or 'past breaking' (a str, or an object array for many).

    ``demand`` is the preload the yielding blow would have reached on the elastic line;
    past breaking where it exceeds F_B (the ideally plastic law has no hardening to break
    on, so this is the blow's elastic overshoot measured against F_B).

    >>> _bolt_verdict(False, math.nan, 125.6e3), _bolt_verdict(True, 110e3, 125.6e3)
    ('elastic', 'past yield')
    >>> _bolt_verdict(np.array([False, True]), np.array([np.nan, 254.9e3]), 125.6e3).tolist()
    ['elastic', 'past breaking']
    """
    code = _bolt_code(yielded, demand, breaking_load)
    return _BOLT_LABELS[code] if isinstance(code, np.ndarray) else str(_BOLT_LABELS[code])


def _bolt_code(yielded: Any, demand: Any, breaking_load: Any) -> Any:
    """:func:`_bolt_verdict` as an index into its labels (elastic, past yield, past breaking)."""
    broken = yielded & (demand > breaking_load)  # NaN: not past
    if isinstance(broken, np.ndarray):
        return np.add(yielded, broken, dtype=np.int8)
    return int(yielded) + int(broken)


def _bolt_checks(s: _Setup, series: BlowSeries, warnings: list[str]) -> tuple[Any, list[Check]]:
    """The bolt's verdict and its checks for one design (None and none without a thread)."""
    if s.per is None:
        return None, []
    f_y, f_b = s.yield_preload, s.breaking_load
    yielded = series.yield_blow > 0
    demand = series.elastic_demand / s.per  # NaN: the bolt stayed elastic
    verdict = _bolt_verdict(yielded, demand, f_b)
    at = f"blow {series.yield_blow}" if yielded else ""
    checks = [
        Check(
            "bolt_yield",
            not yielded,
            f"{at} takes the bolt to its yield preload F_M0.2 = {q(f_y, 'kN')} "
            f"(torque {q(s.yield_torque, 'N*m', 4)}): it stretches plastically; less energy per "
            "blow, fewer blows or a stronger bolt"
            if yielded
            else f"the blows stay below the yield preload F_M0.2 = {q(f_y, 'kN')}",
        )
    ]
    if math.isfinite(f_b):
        broken = verdict == "past breaking"
        checks.append(
            Check(
                "bolt_break",
                not broken,
                f"{at} would take an elastic bolt to {q(demand, 'kN')}, past its "
                f"breaking load F_B = R_m·A_s = {q(f_b, 'kN')}: the bolt may break"
                if broken
                else f"the blows stay below the breaking load F_B = {q(f_b, 'kN')}",
            )
        )
    if yielded:
        warnings.append(
            f"the bolt yields: {at} reaches F_M0.2 = {q(f_y, 'kN')}"
            + (
                f" and on the elastic line would reach {q(demand, 'kN')}, past the "
                f"breaking load {q(f_b, 'kN')}"
                if verdict == "past breaking"
                else ""
            )
            + "; the preload stays at F_M0.2 (elastic–ideally-plastic bolt); that blow's "
            "peak torque, nut rotation and energy account are the elastic line's"
        )
    return verdict, checks


#: A slipping torque so large that the preload it gives is not a float (a groove angle
#: near 0 makes tan(α − ρ) underflow): the clutch never slips on this joint. Found by
#: review: the window was "inf kN…inf kN" and its verdict "within".
_OVERFLOW = (
    "the preload the clutch gives overflows (slipping torque {t:.4g} N·m): a clutch that "
    "never slips on this joint; use a steeper groove_angle or a weaker spring"
)


def _clutch_window(
    x: Mapping[str, Any], bolt: Any, args: tuple[Any, Any, Any, Any]
) -> dict[str, Any]:
    """The clutch source's numbers on floats or arrays (one design per element).

    The slipping torque at the low and the high corner of the spring tolerance and the
    flank friction [001, eq. 1–3], the torque per preload at the low and the high corner
    of μ_G and μ_K (VDI 2230-1 R13), the preload window between them, and with a target
    preload the spring force that sets it at nominal friction. ``bolt`` is a
    :class:`~engine.models.preload.Bolt` or ``BoltArrays``; non-finite values are left for
    the caller to refuse (the scalar code) or mask (the array path).
    """
    f, df = _or_zero(x["flank_friction"]), x["flank_friction_scatter"]
    force, tol = x["clutch_spring_force"], x["spring_force_tolerance"]
    arr = x["spring_arrangement"]
    mu, mu_k, dmu = x["thread_friction"], x["bearing_friction"], x["friction_scatter"]
    formula = x["torque_formula"]
    t_min = cl.torque_limit(force * (1 - tol), *args, np.maximum(f - df, 0.0), arr)
    t_max = cl.torque_limit(force * (1 + tol), *args, f + df, arr)
    low = torque_coefficients_raw(
        bolt, np.maximum(mu - dmu, 0.0), np.maximum(mu_k - dmu, 0.0), formula
    )
    high = torque_coefficients_raw(bolt, mu + dmu, mu_k + dmu, formula)
    f_lo, f_hi = clutch_preload_window(t_min, t_max, low[0] + low[1], high[0] + high[1])
    out: dict[str, Any] = {
        "clutch_torque_min": t_min,
        "clutch_torque_max": t_max,
        "delivered_preload_min": f_lo,
        "delivered_preload_max": f_hi,
        "final_torque": 0.5 * (t_min + t_max),
        "final_preload": 0.5 * (f_lo + f_hi),
    }
    if x.get("target_preload") is not None:
        nominal = torque_coefficients_raw(bolt, mu, mu_k, formula)
        out["clutch_spring_force_for_target"] = cl.spring_force_for_torque(
            x["target_preload"] * (nominal[0] + nominal[1]), *args, f, arr
        )
    return out


def _require_clutch(x: Mapping[str, Any]) -> None:
    """What the clutch source needs, refused by name (a single run and the array path)."""
    _need(x, ("clutch_spring_force", *_CL_NAMES[:3]), "with source 'clutch'")
    if x.get("thread_diameter") is None:
        raise InputOutOfRange("source 'clutch' needs thread_diameter", field="thread_diameter")


def _compute_clutch(x: Mapping[str, Any], ctx: RunContext) -> Result:
    _require_clutch(x)
    bolt, bolt_notes = resolve_bolt(_clutch_bolt_inputs(x))
    args, load_notes = _clutch_args(x)
    values: dict[str, Any] = {k: float(v) for k, v in _clutch_window(x, bolt, args).items()}
    t_min, t_max = values["clutch_torque_min"], values["clutch_torque_max"]
    if not (math.isfinite(t_min) and math.isfinite(t_max)):
        raise InputOutOfRange(
            "the clutch never slips at the highest flank friction (α ≤ atan f): lower "
            "flank_friction or its scatter, or a steeper groove_angle",
            field="flank_friction",
        )
    f_lo, f_hi = values["delivered_preload_min"], values["delivered_preload_max"]
    if not (math.isfinite(f_lo) and math.isfinite(f_hi)):
        raise InputOutOfRange(_OVERFLOW.format(t=t_max), field="groove_angle")
    f, df = float(x["flank_friction"] or 0.0), float(x["flank_friction_scatter"])
    tol, dmu = float(x["spring_force_tolerance"]), x["friction_scatter"]
    notes = [
        "clutch: a continuous tool stops turning the nut when its clutch slips; the slipping "
        f"torque spans {q(t_min, 'N*m', 4, bare=True)}…{q(t_max, 'N*m', 4)} "
        f"(spring force ±{tol:.0%}, flank friction "
        f"{f:g} ± {df:g}) [001, eq. 1–3], and the preload follows through the tightening "
        f"relation with μ ± {dmu:g} (VDI 2230-1 R13); dynamic overshoot at the end of the "
        "run-down is neglected (no error estimate)",
        *load_notes,
        *_bolt_notes(bolt_notes),
    ]
    checks: list[Check] = []
    lo, hi = x.get("preload_min"), x.get("preload_max")
    if lo is not None or hi is not None:
        ok, values["preload_verdict"] = _clutch_verdict(f_lo, f_hi, lo, hi)
        checks.append(
            Check(
                "preload_window",
                ok,
                f"the clutch gives {q(f_lo, 'kN')}…{q(f_hi, 'kN')}"
                + ("" if ok else "; narrow the spring tolerance or the friction"),
            )
        )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=None,
        checks=checks,
        notes=notes,
    )


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    if x["source"] == "clutch":
        return _compute_clutch(x, ctx)
    s = _setup(x, ctx.scratch)
    p = s.problem(x)
    t0 = float(x["snug_torque"])
    notes = s.tool.notes + s.notes
    per, target = s.per, s.target
    max_blows = int(x["max_blows"])
    if target is not None and t0 >= target:
        raise InputOutOfRange("snug_torque must be below the target torque", field="snug_torque")
    if ctx.rung == "rigid" and s.rate <= 0.0:
        raise InputOutOfRange(_RIGID_NEEDS_A_RATE, field="joint_rate")
    e = s.energy
    tool_values: dict[str, Any] = {n: float(v) for n, v in _tool_values(x, s).items()}
    saturation = tool_values["saturation_torque"]
    if not ctx.wants(*_NEED_BLOWS):
        notes.append("no requested output needs the blows: none was run")
        return Result(
            values=tool_values,
            rung=ctx.rung,
            error_estimate=0.0,
            notes=notes,
        )
    want_series = ctx.wants(*_SERIES_OUTPUTS)  # each blow's numbers kept only for a series
    series = blow_series(
        p,
        t0,
        ctx.rung,
        target_torque=target,
        max_blows=max_blows,
        record_first=ctx.wants("time_in_blow", "torque_in_blow"),
        max_steps=ctx.max_steps,
        deadline=ctx.deadline,
        yield_torque=s.yield_torque,
        history=want_series,
    )

    n = series.blows
    if e == 0.0:  # the energy account divides by it (on arrays: the point is refused)
        raise ZeroDivisionError("the tool's energy underflows to 0 J")
    found = {
        **tool_values,
        **_blow_values(
            ctx.rung,
            s,
            peak=series.peak,
            rotation=series.rotation,
            after=series.torque_after,
            work=series.work,
            final=series.final_torque,
            blows=n,
            joint_work=series.joint_work,
        ),
        "blows_to_target": series.blows_to_target or None,
    }
    interval = math.nan
    if ctx.wants(*_TIME_OUTPUTS):
        interval, why = _blow_interval(x, s)
        interval = float(interval)
        if math.isfinite(interval) and interval > 0.0:
            found["blow_interval"] = interval
            found["blows_per_second"] = 1.0 / interval
            found["time_to_final"] = n * interval
            notes.append(f"time: {why}; the blows' own duration (ms) is not added")
        else:
            notes.append(f"blow_interval is null: {why}")
    if per is not None:
        found["yield_preload"] = s.yield_preload
        # null where only R_p0.2 is given
        found["breaking_load"] = s.breaking_load if math.isfinite(s.breaking_load) else None
    # null: the preloads without a thread, the energy account on the rigid rung
    values = {name: found.get(name) for name in _BLOW_OUTPUTS}
    verdict, checks = _verdict(x, values["final_preload"], notes)
    values["preload_verdict"] = verdict
    warnings: list[str] = []
    values["bolt_verdict"], bolt_checks = _bolt_checks(s, series, warnings)
    checks.extend(bolt_checks)
    if target is not None and not series.blows_to_target:
        why = (
            f"the bolt yields at {q(series.final_torque, 'N*m', 4)}"
            if series.yield_blow
            else f"the joint holds against the blow at {q(series.final_torque, 'N*m', 4)}"
            if series.saturated
            else f"not reached in max_blows = {max_blows}"
        )
        notes.append(
            f"blows_to_target is null: {why}; the blows saturate near {q(saturation, 'N*m', 4)} "
            f"(energy balance), below the target {q(target, 'N*m', 4)}"
            if saturation < target
            else f"blows_to_target is null: {why}"
        )
        checks.append(Check("target_reached", False, f"target {q(target, 'N*m', 4)}: {why}"))
    elif target is not None:
        checks.append(
            Check(
                "target_reached",
                True,
                f"target {q(target, 'N*m', 4)} after {series.blows_to_target} blow(s)",
            )
        )
    if per is None:
        notes.append("preloads are null: give thread_diameter for the tightening relation")
    fraction = values.get("joint_energy_fraction")
    if fraction is not None and fraction > 1.0:
        notes.append(
            f"joint_energy_fraction {fraction:.4g} > 1: the drive torque "
            f"{q(float(s.tool.drive), 'N*m', 4)} works on the tool during the blow, and that work "
            "is not in the tool's energy E it is divided by"
        )
    if ctx.rung == "rigid":
        notes.append(
            "rigid: the struck end fixed, M = √(2EC) [000, eq. 7–8] less the idle friction "
            "[000, eq. 10]; the joint is taken to reach M in one blow, which over-states what "
            "one blow does on a compliant joint; nut_rotation and the energy account are null "
            "(M does not follow from an energy balance with the joint); see 'energy' and "
            "'simulation'"
        )
        error = _estimate(s, _rigid_estimate_of(x, s))
    elif ctx.rung == "energy":
        # the estimate from the first blow the rung ran (energy_blow: the same balance)
        blow1 = (series.peak, series.torque_after)
        error = _estimate(s, _energy_error(x, s, blow1, peak=ctx.wants(*_PEAK_OUTPUTS)))
        notes.append(
            "energy: E + N·φ_t = T_p²/(2C) + (T_p² − T_0²)/(2k_j) per blow, struck inertia and "
            "damping neglected; the estimated error concerns the joint torque after each blow, "
            "the peak torque of a blow is under-stated by up to the nut's kick ω0·√(C·J_r)"
        )
    else:
        error = _simulation_estimate(x)
        first = series.first
        assert first is not None
        notes.append(
            f"simulation: two-mass stick-slip model, compiled RK4, {series.steps} steps over "
            f"{n} blow(s); first blow lasted {q(first.duration, 'ms')}, energy balance "
            f"closes to {abs(first.joint_work + first.energy_left + first.damping_loss - e - first.drive_work) / e:.1e}"  # noqa: E501
        )
    out_series = _out_series(ctx.rung, series, per, interval) if want_series else {}
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=error,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=out_series,
    )


#: The series outputs of the blows' sources (none is built unless one is asked for).
_SERIES_OUTPUTS = tuple(o.name for o in _OUTPUTS if o.series)


def _out_series(
    rung: str, series: BlowSeries, per: float | None, interval: float
) -> dict[str, list[float]]:
    """The series of one design's blows: per blow, against time, and the first blow's torque.

    Built only where some series is asked for (the runner keeps those asked for): a run of
    35 blows otherwise spends on lists no one reads.
    """
    n = series.blows
    out: dict[str, list[float]] = {
        "blow_number": [float(i + 1) for i in range(n)],
        "torque_per_blow": list(series.per_blow["torque"]),
        "peak_per_blow": list(series.per_blow["peak"]),
    }
    if rung != "rigid":
        out["rotation_per_blow"] = list(series.per_blow["rotation"])
    if per is not None:
        out["preload_per_blow"] = [t / per for t in series.per_blow["torque"]]
    if math.isfinite(interval) and interval > 0.0:
        out["blow_time"] = [(i + 1) * interval for i in range(n)]
        out["torque_against_time"] = list(series.per_blow["torque"])
        if per is not None:
            out["preload_against_time"] = [t / per for t in series.per_blow["torque"]]
    if series.first is not None and len(series.first.time):
        out["time_in_blow"] = series.first.time.tolist()
        out["torque_in_blow"] = series.first.torque.tolist()
    return out


# --------------------------------------------------------------------------- array path
#
# The rigid and energy rungs at many points (sweeps and studies): the same equations as
# _compute in the same order, numeric inputs as equal-length arrays. The choices (source,
# joint_rate_from, torque_formula, ...) are one per request; the bolt and the joint's
# compliances are resolved once per distinct combination of the inputs they depend on
# (once for a sweep of anything else).

#: Inputs the thread's torque per preload (and a 'joint' rate) depends on.
_THREAD_INPUTS = (
    "thread_diameter",
    "thread_pitch",
    "bearing_outer_diameter",
    "hole_diameter",
    "thread_friction",
    "bearing_friction",
    "yield_strength",
)
_JOINT_INPUTS = ("clamped_compliance", "clamped_length", "bolt_compliance", "youngs_modulus")


#: What :func:`_quiet` enters for one design (reusable: it does nothing).
_AS_IS = contextlib.nullcontext()


def _quiet(many: bool) -> contextlib.AbstractContextManager[Any]:
    """numpy's 0/0 and overflow silenced (NaN and inf, as wanted) for many designs' arrays.

    One design's numbers need no error state of their own: Python's floats raise where
    they fail (the refusal the single design gives), and the runner's error state covers
    the numpy calls; entering a state costs about what one small step does.
    """
    return np.errstate(all="ignore") if many else _AS_IS


def _is_array(x: Mapping[str, Any]) -> bool:
    """Whether ``x`` holds many designs (some input an array) rather than one."""
    return np.ndarray in map(type, x.values())  # the scan runs in C: a single run asks often


def _points(x: Mapping[str, Any]) -> tuple[int, ...]:
    return np.broadcast_shapes(*(np.shape(v) for v in x.values() if isinstance(v, np.ndarray)))


def _or_zero(v: Any) -> Any:
    """``float(v or 0.0)`` of the scalar code, for an array or None."""
    return (
        0.0
        if v is None
        else (np.asarray(v, dtype=float) if isinstance(v, np.ndarray) else float(v))
    )


def _squares_overflow(v: Any) -> Any:
    """Where Python's ``v**2`` raises OverflowError (a finite value whose square is not)."""
    if not isinstance(v, np.ndarray):
        f = float(v)
        return math.isfinite(f) and not math.isfinite(f * f)
    return np.isfinite(v) & ~np.isfinite(np.asarray(v, dtype=float) ** 2)


def _per_group(
    x: Mapping[str, Any], names: tuple[str, ...], fn: Any, width: int, one: bool
) -> tuple[Any, Any, list[str], EngineError | None]:
    """``fn`` (scalar inputs -> (floats, notes)) once per distinct combination of ``names``.

    Returns (values of shape (width, points), refused per point, the first group's notes,
    the first refusal); a group ``fn`` refuses (EngineError) is NaN and refused. One
    design (``one``: no array among the inputs) is one group: a list of floats.
    """
    notes: list[str] = []
    if one:  # one design: one group, no arrays to fill
        try:
            got, notes = fn(x)
        except EngineError as exc:
            return [math.nan] * width, True, notes, exc
        return [float(v) for v in got], False, notes, None
    varied = [k for k in names if isinstance(x.get(k), np.ndarray)]
    n = _points(x)
    if not varied:  # one group: its values broadcast over the points (read-only, no copies)
        try:
            got, notes = fn(x)
        except EngineError as exc:
            return np.full((width, *n), np.nan), np.ones(n, dtype=bool), notes, exc
        column = np.asarray(got, dtype=float).reshape(width, *([1] * len(n)))
        return np.broadcast_to(column, (width, *n)), np.zeros(n, dtype=bool), notes, None
    out = np.full((width, *n), np.nan)
    refused = np.zeros(n, dtype=bool)
    error: EngineError | None = None
    table = np.stack([np.broadcast_to(np.asarray(x[k], dtype=float), n) for k in varied], axis=-1)
    rows, inverse = np.unique(table.reshape(-1, len(varied)), axis=0, return_inverse=True)
    inverse = inverse.reshape(n)
    scalar = {k: (v.flat[0].item() if isinstance(v, np.ndarray) else v) for k, v in x.items()}
    for r, row in enumerate(rows):
        at = inverse == r
        point = dict(scalar)
        for k, v in zip(varied, row.tolist(), strict=True):
            point[k] = v
        try:
            got, group_notes = fn(point)
        except EngineError as exc:
            refused |= at
            error = error or exc
            continue
        notes = notes or group_notes
        out[:, at] = np.asarray(got, dtype=float).reshape(width, 1)
    return out, refused, notes, error


def _thread_and_joint(
    x: Mapping[str, Any],
) -> tuple[tuple[float, float, float, float], list[str]]:
    """(k_G + k_K, the 'joint' torque rate, F_M0.2, F_B) of one point (NaN where none)."""
    thread = _thread(x)
    per, f_y, f_b = (math.nan,) * 3 if thread is None else (thread[1], thread[3], thread[4])
    k = math.nan
    notes = [] if thread is None else list(thread[2])
    if x["joint_rate_from"] == "joint":
        k, note = _joint_rate(x, thread)
        notes.insert(0, note)
    return (per, k, f_y, f_b), notes


def _nullable(column: Any, null: np.ndarray) -> np.ndarray:
    """An object column with None where ``null`` (the column itself where nothing is null)."""
    if not null.any():
        return np.asarray(column)
    out = np.asarray(column).astype(object)
    out[null] = None
    return out


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """The rigid and energy rungs at many points (the array path of sweeps and studies)."""
    if ctx.rung not in ("rigid", "energy"):
        raise EngineError(f"blow.joint has no array path for the rung {ctx.rung!r}")
    if x["source"] == "clutch":
        return _vectorized_clutch(x, ctx)
    s = _setup(x, ctx.scratch)
    n = _points(x)
    t0 = x["snug_torque"]
    dead = s.refused.copy()
    if s.target is not None:
        dead |= t0 >= s.target  # "snug_torque must be below the target"
    lo, hi = x.get("preload_min"), x.get("preload_max")
    if s.per is not None and lo is not None and hi is not None:
        dead |= lo > hi  # "preload_min must not exceed preload_max"
    e, c, drive = s.energy, s.tool.stiffness, s.tool.drive
    dead |= e == 0.0  # joint_energy_fraction divides by it: refused (|= broadcasts)
    if ctx.rung == "energy":  # energy_blow refuses a massless nut that never stops
        dead |= (s.rate <= 0.0) & (t0 <= drive)
    elif ctx.rung == "rigid":
        dead |= s.rate <= 0.0  # _RIGID_NEEDS_A_RATE
    with np.errstate(all="ignore"):
        p = BlowProblem(
            s.tool.inertia,
            x["struck_inertia"],
            c,
            s.speed,
            s.rate,
            x["breakaway_factor"],
            drive,
            x["restitution"],
        )
        # outputs of the first blow alone and no checks read (a sweep): one blow is the
        # same first blow as the first of many, and the rest of the series is not needed
        first_only = not ctx.checks and ctx.outputs <= _FIRST_BLOW_OUTPUTS
        series = blow_series(
            p,
            t0,
            ctx.rung,
            target_torque=s.target,
            max_blows=np.minimum(x["max_blows"], 1) if first_only else x["max_blows"],
            yield_torque=s.yield_torque,
            # the first blow's numbers the asked outputs read, and nothing else
            need=[f for o, f in _FIRST_BLOW_FIELDS if o in ctx.outputs] if first_only else None,
        )
        raw: dict[str, Any] = {
            **_tool_values(x, s),
            **_blow_values(
                ctx.rung,
                s,
                peak=series.peak,
                rotation=series.rotation,
                after=series.torque_after,
                work=series.work,
                final=series.final_torque,
                blows=series.blows,
                joint_work=series.joint_work,
                outputs=ctx.outputs if first_only else None,
            ),
        }
        reached: Any = None if first_only else np.broadcast_to(series.blows_to_target, n)
        if ctx.wants(*_TIME_OUTPUTS[:3]):
            interval = np.asarray(_blow_interval(x, s)[0], dtype=float)
            interval = np.where(np.isfinite(interval) & (interval > 0.0), interval, np.nan)
            raw["blow_interval"] = interval
            raw["blows_per_second"] = 1.0 / interval
            if not first_only:  # the whole series' time: no first-blow output
                raw["time_to_final"] = series.blows * interval
        if s.per is not None:
            raw["yield_preload"] = s.yield_preload
            raw["breaking_load"] = s.breaking_load
            if not first_only:  # a bolt verdict is no first-blow output, and no check is read
                yielded = np.broadcast_to(series.yield_blow > 0, n)
                bolt_code = _bolt_code(yielded, series.elastic_demand / s.per, s.breaking_load)
    # every column asked for (and the final preload where its verdict is) at once: a
    # refused point is NaN, and a non-finite value is null in a single run's answer (the
    # runner's rule), so NaN here
    window = s.per is not None and (lo is not None or hi is not None)
    verdicts = ctx.checks or ctx.wants("preload_verdict")
    kept = [k for k in raw if k in ctx.outputs or (k == "final_preload" and window and verdicts)]
    table = np.empty((len(kept), *n))
    for row, name in zip(table, kept, strict=True):
        row[...] = raw[name]  # one number for all points is broadcast
    table[:, dead] = np.nan
    table[~np.isfinite(table)] = np.nan
    values: dict[str, Any] = dict(zip(kept, table, strict=True))
    if reached is not None and ctx.wants("blows_to_target"):
        values["blows_to_target"] = _nullable(reached, dead | (reached == 0))
    checks: dict[str, np.ndarray] = {}
    # a point the model refuses reports no check; if every point is refused, no check at all
    reports = ctx.checks and not bool(dead.all())
    if window and verdicts:
        code = np.broadcast_to(_window_code(values["final_preload"], lo, hi), n)
        if ctx.wants("preload_verdict"):
            verdict = _WINDOW_LABELS[code]
            verdict[dead] = None
            values["preload_verdict"] = verdict
        if reports:
            checks["preload_window"] = np.where(dead, -1, code == 0).astype(np.int8)
    if s.target is not None and reports:
        checks["target_reached"] = np.where(dead, -1, reached > 0).astype(np.int8)
    if s.per is not None and not first_only:
        bolt_code = np.broadcast_to(bolt_code, n)
        if ctx.wants("bolt_verdict"):
            bolt = _BOLT_LABELS[bolt_code]
            bolt[dead] = None
            values["bolt_verdict"] = bolt
        if reports:
            checks["bolt_yield"] = np.where(dead, -1, ~yielded).astype(np.int8)
            has_rm = np.broadcast_to(np.isfinite(s.breaking_load), n)
            checks["bolt_break"] = np.where(dead | ~has_rm, -1, bolt_code != 2).astype(np.int8)
    for o in _OUTPUTS:  # what a single run leaves null here: None (no scalar probe)
        if not o.series and o.name not in values:
            values[o.name] = None
    notes = [
        f"{ctx.rung}: evaluated on arrays, the same equations as a single run "
        "(engine.physics.blow.blow_series)",
        *s.notes,
    ]
    return Result(
        values=values, rung=ctx.rung, error_estimate=None, notes=notes, check_arrays=checks
    )


def _vectorized_clutch(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """:func:`_compute_clutch` at many points: the same equations in the same order.

    The bolt is resolved once (:func:`resolve_bolts`; a varied thread size is
    looked up on arrays), the slipping torques [001, eq. 1–3] and the torques per
    preload at the friction box's corners (VDI 2230-1 R13) are array expressions. A
    point the scalar compute refuses (the clutch never slips at the highest flank
    friction, a bolt it cannot resolve) is NaN in every output and reports no check.
    Where the scalar code refuses the whole request (an input missing, no thread, a
    bolt that cannot be resolved with nothing varied) this raises the same error.
    """
    _require_clutch(x)
    n = _points(x)
    bolt, bolt_notes = resolve_bolts(_clutch_bolt_inputs(x), math.prod(n), labels=False)
    args, load_notes = _clutch_args(x)
    with np.errstate(all="ignore"):
        raw = _clutch_window(x, bolt, args)
    t_min, t_max = raw["clutch_torque_min"], raw["clutch_torque_max"]
    f_lo, f_hi = raw["delivered_preload_min"], raw["delivered_preload_max"]
    dead = ~np.broadcast_to(bolt.ok, n)
    finite = np.isfinite(t_min) & np.isfinite(t_max) & np.isfinite(f_lo) & np.isfinite(f_hi)
    dead = dead | ~np.broadcast_to(finite, n)  # the scalar code's two refusals (_OVERFLOW)
    any_dead = bool(dead.any())
    values: dict[str, Any] = {}
    for name, column in raw.items():
        column = np.broadcast_to(np.asarray(column, dtype=float), n)
        if any_dead:
            column = np.where(dead, np.nan, column)
        # a non-finite value is null in a single run's answer (the runner's rule)
        values[name] = np.where(np.isfinite(column), column, np.nan)
    checks: dict[str, np.ndarray] = {}
    lo, hi = x.get("preload_min"), x.get("preload_max")
    if lo is not None or hi is not None:
        f_lo, f_hi = values["delivered_preload_min"], values["delivered_preload_max"]
        ok, verdict = _clutch_verdict(f_lo, f_hi, lo, hi)
        ok = np.broadcast_to(ok, n)
        verdict = np.broadcast_to(verdict, n).copy()
        verdict[dead] = None
        values["preload_verdict"] = verdict
        if not bool(dead.all()):  # a refused point reports no check; all refused: none
            checks["preload_window"] = np.where(dead, -1, ok).astype(np.int8)
    for o in _OUTPUTS:  # what a single run leaves null here: None (no scalar probe)
        if not o.series and o.name not in values:
            values[o.name] = None
    notes = [
        f"{ctx.rung}, clutch: evaluated on arrays, the same equations as a single run; the "
        "joint's torque is the clutch's slipping torque window (spring force tolerance, "
        "flank friction scatter) [001, eq. 1–3], the preload follows through the tightening "
        "relation at the friction box's corners (VDI 2230-1 R13); dynamic overshoot "
        "neglected (no error estimate)",
        *load_notes,
        *_bolt_notes(bolt_notes),
    ]
    return Result(
        values=values, rung=ctx.rung, error_estimate=None, notes=notes, check_arrays=checks
    )


# --------------------------------------------------------------------------- examples

_NUTRUNNER = {n: NUTRUNNER_DRIVE.examples[0][n] for n in _NR_NAMES + _NR_MOTOR}
#: Nut-runner of nutrunner.drive's reference case on an M20×1.5 wheel nut, target 600 N·m.
NUTRUNNER_HARD: dict[str, Any] = {
    "source": "nutrunner",
    **_NUTRUNNER,
    "struck_inertia": 1e-3,
    "breakaway_factor": 1.1,
    "joint_rate_from": "iso5393_hard",
    "snug_torque": 60.0,
    "target_torque": 600.0,
    "thread_diameter": 0.020,
    "thread_pitch": 0.0015,
    "property_class": "10.9",  # a wheel bolt's class
    "preload_min": 150e3,
    "preload_max": 260e3,
}
NUTRUNNER_SOFT: dict[str, Any] = {**NUTRUNNER_HARD, "joint_rate_from": "iso5393_soft"}
#: Rare-impact mechanism of impact.rare (a lighter 0.001 kg·m² flywheel) on an M16 10.9 joint
#: (an 8.8 bolt yields at 90.0 kN: its first blow, 91.6 kN, would take it past F_M0.2).
RARE_IMPACT_M16: dict[str, Any] = {
    "source": "rare_impact",
    **{n: RARE_IMPACT.examples[0][n] for n in _RI_NAMES},
    "flywheel_inertia": 1e-3,
    "tool_stiffness": 2e4,
    "struck_inertia": 2e-4,
    "breakaway_factor": 1.1,
    "joint_rate_from": "joint",
    "thread_diameter": 0.016,
    "property_class": "10.9",
    "clamped_length": 0.04,
    "clamped_compliance": 2.5e-10,
    "snug_torque": 20.0,
    "target_preload": 80e3,
    "preload_min": 70e3,
    "preload_max": 100e3,
}
CLUTCH_M10: dict[str, Any] = {
    "source": "clutch",
    "clutch_spring_force": 1100.0,
    "ball_circle_diameter": 0.05,
    "groove_angle": 45 * DEG,
    "ball_count": 6,
    "flank_friction": 0.1,
    "thread_diameter": 0.010,
    "target_preload": 20e3,
    "preload_min": 15e3,
    "preload_max": 30e3,
}

#: A raw blow (6 J from 0.004 kg·m² through 20 N·m/rad, restitution 0.8) on an M16×2 joint
#: whose thread and bearing face are all given (no table lookup): about eight blows to
#: 80 kN by the energy rung, nine simulated.
ENERGY_M16: dict[str, Any] = {
    "source": "energy",
    "tool_energy": 6.0,
    "tool_inertia": 0.004,
    "tool_stiffness": 2e4,
    "drive_torque": 5.0,
    "struck_inertia": 3e-4,
    "breakaway_factor": 1.1,
    "restitution": 0.8,
    "joint_rate_from": "joint",
    "thread_diameter": 0.016,
    "thread_pitch": 0.002,
    "bearing_outer_diameter": 0.0225,
    "hole_diameter": 0.0175,
    "clamped_length": 0.05,
    "snug_torque": 30.0,
    "target_preload": 80e3,
    "preload_min": 70e3,
    "preload_max": 100e3,
}

#: What bench/accuracy_blow.py measures over 200 random first blows (seed 0) against
#: scipy's DOP853 at rtol 1e-12, per rung: (designs exceeding the estimate on the joint
#: torque after the blow, on the peak torque, the worst ratio of error to estimate).
MEASURED_EXCEEDED: dict[str, tuple[int, int, float]] = {
    "rigid": (10, 10, 2.23),
    "energy": (16, 10, 358.0),
    "simulation": (32, 29, 24.3),
}
MEASURED_DESIGNS = 200


def _exceeded(rung: str) -> str:
    """The measured share exceeded, as a rung states it ("… % of N random designs …")."""
    after, peak, worst = MEASURED_EXCEEDED[rung]
    n = MEASURED_DESIGNS
    share = max(after, peak) / n
    return f"{share:.0%} of {n} random designs (worst {worst:.3g}×; bench/accuracy_blow.py)"


def _typical(rung: str) -> dict[str, Any]:
    """The rung's label of a typical (not bounding) estimate, where :class:`Rung` has one."""
    if "estimate_kind" not in getattr(Rung, "__dataclass_fields__", {}):
        return {}
    return {"estimate_kind": "typical", "typical_exceeded": _exceeded(rung)}


BLOW = ModelSpec(
    name="blow.joint",
    answer=(
        Answer("blows_to_target", "n"),
        Answer("final_torque", "M_final"),
        Answer("final_preload", "F_V,final", check="preload_window"),
        Answer("peak_torque", "M_peak"),
    ),
    title="Blow into a joint: torque and preload per blow, blows to target",
    family="blow",
    summary=(
        "What a tool delivers into a joint: peak torque and nut rotation per blow, joint "
        "torque and preload after each blow, blows to reach a target, energy into the joint, "
        "and the preload window a clutch-limited tool gives."
    ),
    source=(
        "Tools: [000] (nut-runner drive energy and stiffness), [002] (rare-impact release "
        "speed and energy, from impact.rare's closed form), [001] (ball clutch slipping "
        "torque); joint: ISO 5393 test joints, the "
        "tightening relation VDI 2230-1 R13 and the angle relation [004, eq. 8]; the blow: "
        "two-mass torsional impact with stick-slip of the nut (textbook mechanics)."
    ),
    inputs=_INPUTS,
    outputs=_OUTPUTS,
    rungs=(
        Rung(
            "rigid",
            "struck end fixed: M = √(2EC) [000, eq. 7–8]; the joint reaches M in one blow",
            _rigid_estimate,
            shared_estimate=_rigid_estimate,
            typical_error="10 %…10× (a compliant joint takes many blows); typical, not a "
            f"bound: exceeded in {_exceeded('rigid')}",
            typical_time="~50 µs",
            **_typical("rigid"),
        ),
        Rung(
            "energy",
            "energy balance per blow with the joint's rate in series with the tool, struck "
            "inertia neglected; blow after blow",
            _energy_estimate,
            shared_estimate=_energy_estimate,
            typical_error="typical, not a bound: 2·J_s/J_t·(C/(C+k_j))² + (1 − e²)/2 + "
            "((b − 1)·T_0)²/((C + k_j)·E) on the joint torque (a nut that sticks mid-blow "
            "needs b·T_j again, which no term follows); plus ω0·√(C·J_r)/T_p on the peak "
            f"torque (the nut's kick); exceeded in {_exceeded('energy')}",
            typical_time="~0.1 ms",
            **_typical("energy"),
        ),
        Rung(
            "simulation",
            "two-mass torsional model with stick-slip of the nut, compiled RK4 with located "
            "events; blow after blow; torque against time",
            _simulation_estimate,
            typical_error="1e-6 lossless, 5e-5 with restitution < 1, typical, not a bound "
            "(RK4 at 200 steps per period loses order at a damped contact's kink): exceeded "
            f"in {_exceeded('simulation')}",
            typical_time="~0.5 ms per blow (one-off numba load in a fresh process)",
            heavy=True,  # blow after blow: the service's heavy lane
            **_typical("simulation"),
        ),
    ),
    compute=_compute,
    examples=(NUTRUNNER_HARD, NUTRUNNER_SOFT, RARE_IMPACT_M16, CLUTCH_M10, ENERGY_M16),
    vectorized=_vectorized,
    vector_rungs=("rigid", "energy"),
)
