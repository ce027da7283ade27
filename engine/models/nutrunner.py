"""The ``nutrunner.drive`` model: inputs, outputs, rungs, checks and notes.

The equations are in :mod:`engine.physics.nutrunner` (source [000], see docs/sources.md);
this module declares the model the service serves and turns a request into
calls of those functions, checks and sentences.
"""

from __future__ import annotations

import math
from collections.abc import Container, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.errors import InfeasibleDesign, InputOutOfRange
from ..core.params import RPM, count, friction_coefficient, length, positive
from ..core.spec import Answer, Check, ModelSpec, Output, Param, Result, RunContext, Rung
from ..core.text import q
from ..physics.clutch import (
    acceleration_torque,
    friction_clutch_torque,
    rated_torque,
    required_slip_torque,
)
from ..physics.motor_spinup import (
    MotorCurve,
    kloss_breakdown_slip,
    kloss_slip_torque,
    kloss_spin_up_time,
    kloss_torque,
    linear_motor_torque,
    linear_spin_up_time,
    spin_up_profile,
    spin_up_time,
    torque_limited_constant_power_spin_up_time,
)
from ..physics.nutrunner import (
    STEEL_SHEAR_MODULUS,
    WHEEL_NUT_TORQUE,
    acceleration_time,
    disc_inertia,
    drive_inertia,
    flywheel_speed,
    gear_ratio_torque_change,
    impact_torque,
    impact_torque_geared,
    max_spindle_torque,
    part_energies,
    rotational_energy,
    shaft_shear_stress,
    spindle_gear_spacing,
    spindle_speed,
    spindle_torque_reserve,
    torsional_stiffness,
    twist_angle,
)

# ---------------------------------------------------------------------------
# The model spec
# ---------------------------------------------------------------------------

_DIAMETER: dict[str, Any] = {"minimum": 1e-4, "maximum": 2.0, "display_unit": "mm"}
_MASS: dict[str, Any] = {"minimum": 0.0, "maximum": 1e3, "display_unit": "kg"}


def _nm(torque: float) -> str:
    """A torque [N·m] for a check or a note, 4 significant digits, written "N*m" as here."""
    return q(torque, "N*m", 4, suffix=" N*m")


def _friction_clutch_params() -> tuple[Param, ...]:
    """The idle spindles' friction clutches by their clamp [000]: optional, give all or none."""
    return (
        positive(
            "friction_clutch_clamp_force",
            "N",
            "F, force nut 12 clamps each diaphragm friction clutch with [000]; given, M_tr = "
            "z_f μ F (D + d)/4 replaces idle_spindle_friction_torque (uniform wear)",
            maximum=1e7,
            symbol="F",
            group="friction clutches",
        ),
        friction_coefficient(
            "friction_clutch_friction",
            "μ of the friction clutch faces (about 0.1 oiled … 0.15–0.2 dry steel)",
            symbol="μ",
            group="friction clutches",
        ),
        length(
            "friction_clutch_outer_diameter",
            "D, outer diameter of the friction face",
            minimum=1e-3,
            maximum=2.0,
            symbol="D",
            group="friction clutches",
        ),
        length(
            "friction_clutch_inner_diameter",
            "d, inner diameter of the friction face (0 for a full disc), below D",
            minimum=0.0,
            maximum=2.0,
            symbol="d",
            group="friction clutches",
        ),
        count(
            "friction_clutch_faces",
            "z_f, friction faces the clamp force passes through",
            minimum=1,
            maximum=20,
            default=1,
            symbol="z_f",
            group="friction clutches",
        ),
    )


_FRICTION_CLUTCH = (
    "friction_clutch_clamp_force",
    "friction_clutch_friction",
    "friction_clutch_outer_diameter",
    "friction_clutch_inner_diameter",
)


def _with_friction_clutch(x: Mapping[str, Any]) -> tuple[dict[str, Any], Any, list[str]]:
    """``x`` with M_tr from the clutches' clamp where all of it is given; that M_tr; warnings.

    Part of the clamp alone leaves idle_spindle_friction_torque in use (a warning says
    what is missing); the whole clamp replaces it (a warning if it was given too).
    """
    given = [name for name in _FRICTION_CLUTCH if x[name] is not None]
    if len(given) < len(_FRICTION_CLUTCH):
        missing = [name for name in _FRICTION_CLUTCH if x[name] is None]
        warn = (
            [
                f"{', '.join(given)} given without {', '.join(missing)}: M_tr is "
                "idle_spindle_friction_torque"
            ]
            if given
            else []
        )
        return dict(x), x["idle_spindle_friction_torque"], warn
    if np.any(
        np.asarray(x["friction_clutch_inner_diameter"])
        >= np.asarray(x["friction_clutch_outer_diameter"])
    ):
        raise InputOutOfRange(
            "friction_clutch_inner_diameter must be below friction_clutch_outer_diameter "
            f"({np.max(x['friction_clutch_outer_diameter']) * 1e3:g} mm)",
            field="friction_clutch_inner_diameter",
        )
    m_tr = friction_clutch_torque(
        x["friction_clutch_clamp_force"],
        x["friction_clutch_friction"],
        x["friction_clutch_outer_diameter"],
        x["friction_clutch_inner_diameter"],
        x["friction_clutch_faces"],
    )
    warn = []
    if np.any(np.asarray(x["idle_spindle_friction_torque"]) != 0.0):
        warn.append(
            "idle_spindle_friction_torque is not used: M_tr comes from the friction clutches' "
            "clamp (friction_clutch_clamp_force …)"
        )
    return {**x, "idle_spindle_friction_torque": m_tr}, m_tr, warn


def _part(name: str, label: str, group: str, eq: str, mass: bool, **kw: Any) -> Param:
    """A mass or diameter of one of the discs 1…5 (``label`` like "the flywheel 3")."""
    if mass:
        text = f"Mass of {label}, a solid uniform disc"
    elif "gear" in label:
        text = f"Pitch diameter of {label}, also taken as its disc diameter"
    elif "pulley" in label:
        text = f"Diameter of {label}, also taken as the belt's pitch diameter"
    else:
        text = f"Outer diameter of {label}, a solid uniform disc"
    bounds = _MASS if mass else _DIAMETER
    return Param(
        name,
        "kg" if mass else "m",
        f"{text} [000, {eq}]",
        required=True,
        group=group,
        **{**bounds, **kw},
    )


_INPUTS: tuple[Param, ...] = (
    Param(
        "motor_power",
        "W",
        "Motor power P, delivered at constant power during spin-up [000, eq. 2, 5]",
        required=True,
        minimum=1.0,
        maximum=1e6,
        recommended=(250.0, 3e4),
        display_unit="kW",
        symbol="P",
        group="motor",
    ),
    Param(
        "motor_speed",
        "rad/s",
        "Motor shaft speed ω at the end of spin-up (the working speed at impact) [000, eq. 3–5]",
        required=True,
        minimum=0.1,
        maximum=1e4,
        recommended=(50.0, 320.0),
        display_unit="rpm",
        symbol="ω",
        group="motor",
    ),
    _part("coupling_mass", "the safety coupling 1", "drive", "eq. 3–4", True, symbol="m1"),
    _part("coupling_diameter", "the safety coupling 1", "drive", "eq. 3–4", False, symbol="D1"),
    _part("motor_pulley_mass", "the motor pulley 2", "drive", "eq. 3–4", True, symbol="m2"),
    _part("motor_pulley_diameter", "the motor pulley 2", "drive", "eq. 3–5", False, symbol="D2"),
    Param(
        "flywheel_mass",
        "kg",
        "Mass of the flywheel 3 (the driven pulley), a solid uniform disc [000, eq. 3–4]",
        required=True,
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e3,
        display_unit="kg",
        symbol="m3",
        group="drive",
    ),
    _part(
        "flywheel_diameter",
        "the flywheel 3 (the driven pulley)",
        "drive",
        "eq. 3–5",
        False,
        symbol="D3",
    ),
    _part("drive_gear_mass", "the drive gear 4", "drive", "eq. 3–4", True, symbol="m4"),
    _part("drive_gear_diameter", "the drive gear 4", "drive", "eq. 3–5", False, symbol="D4"),
    _part("spindle_gear_mass", "one spindle gear 5", "drive", "eq. 3–4", True, symbol="m5"),
    _part("spindle_gear_diameter", "one spindle gear 5", "drive", "eq. 3–5", False, symbol="D5"),
    count(
        "spindle_count",
        "Number of spindles z (one per wheel nut) [000, eq. 4, 10]",
        required=True,
        minimum=1,
        maximum=32,
        recommended=(4, 12),
        symbol="z",
        group="drive",
    ),
    Param(
        "shaft_diameter",
        "m",
        "Diameter of the flywheel shaft 7 [000, eq. 9]",
        required=True,
        **_DIAMETER,
        symbol="d7",
        group="shafts",
    ),
    Param(
        "shaft_length",
        "m",
        "Twisted length of the flywheel shaft 7 [000, eq. 9]",
        required=True,
        minimum=1e-4,
        maximum=5.0,
        display_unit="mm",
        symbol="l7",
        group="shafts",
    ),
    Param(
        "spindle_diameter",
        "m",
        "Diameter of a spindle 8 [000, eq. 9]",
        required=True,
        **_DIAMETER,
        symbol="d8",
        group="shafts",
    ),
    Param(
        "spindle_length",
        "m",
        "Twisted length of a spindle 8 [000, eq. 9]",
        required=True,
        minimum=1e-4,
        maximum=5.0,
        display_unit="mm",
        symbol="l8",
        group="shafts",
    ),
    Param(
        "shear_modulus",
        "Pa",
        "Shear modulus G of shaft and spindle; 8·10¹⁰ Pa (steel) in the source [000, eq. 9]",
        default=STEEL_SHEAR_MODULUS,
        minimum=1e9,
        maximum=5e11,
        recommended=(7.5e10, 8.3e10),
        display_unit="GPa",
        symbol="G",
        group="shafts",
    ),
    Param(
        "idle_spindle_friction_torque",
        "N*m",
        "Friction-clutch torque M_tr of each idle spindle, taken off the blow [000, eq. 10]",
        default=0.0,
        minimum=0.0,
        maximum=1e5,
        display_unit="N*m",
        symbol="M_tr",
        group="shafts",
    ),
    *_friction_clutch_params(),
    Param(
        "wheel_nut_torque",
        "N*m",
        "Torque the wheel nut needs: its tightening torque, or the larger torque that breaks "
        "it loose; set for each make of vehicle [000]; 600 N*m (a truck's M20×1.5 wheel nut) "
        "when absent",
        default=WHEEL_NUT_TORQUE,
        minimum=1.0,
        maximum=1e5,
        display_unit="N*m",
        symbol="M_nut",
        group="shafts",
    ),
    Param(
        "shear_yield_strength",
        "Pa",
        "Optional shear yield strength of shaft and spindle steel; when given, a check "
        "says whether the blow keeps them elastic (the source's model needs that)",
        minimum=1e6,
        maximum=5e9,
        display_unit="MPa",
        symbol="τ_y",
        group="shafts",
    ),
    Param(
        "motor_curve",
        "1",
        "Torque–speed curve for the motor_curve rung: 'none'; 'linear' (stall_torque, "
        "no_load_speed); 'induction' (Kloss formula from rated_torque, rated_speed, "
        "breakdown_torque, synchronous_speed); 'constant_power' (motor_power above the "
        "torque limit stall_torque). Not in the source.",
        default="none",
        kind="choice",
        choices=("none", "linear", "induction", "constant_power"),
        group="motor curve",
    ),
    Param(
        "stall_torque",
        "N*m",
        "Linear curve: torque at standstill; constant_power curve: the torque limit",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e6,
        display_unit="N*m",
        group="motor curve",
    ),
    Param(
        "no_load_speed",
        "rad/s",
        "Linear curve: speed at which the torque falls to zero",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=2e4,
        display_unit="rpm",
        group="motor curve",
    ),
    Param(
        "rated_torque",
        "N*m",
        "Induction curve: rated torque (default motor_power / rated_speed)",
        minimum=1e-3,  # 1 mN*m; 1e-150 once crashed the motor curve
        maximum=1e6,
        display_unit="N*m",
        group="motor curve",
    ),
    Param(
        "rated_speed",
        "rad/s",
        "Induction curve: rated speed (default motor_speed)",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=2e4,
        display_unit="rpm",
        group="motor curve",
    ),
    Param(
        "breakdown_torque",
        "N*m",
        "Induction curve: breakdown (pull-out) torque, above the rated torque",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e6,
        display_unit="N*m",
        group="motor curve",
    ),
    Param(
        "synchronous_speed",
        "rad/s",
        "Induction curve: synchronous speed (1500 rpm for a 4-pole 50 Hz motor)",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=2e4,
        display_unit="rpm",
        group="motor curve",
    ),
    Param(
        "rotor_inertia",
        "kg*m^2",
        "Motor rotor inertia, added to the spin-up (not to the blow: coupling 1 slips)",
        default=0.0,
        minimum=0.0,
        maximum=1e3,
        group="motor curve",
    ),
    Param(
        "belt_efficiency",
        "1",
        "V-belt efficiency while accelerating (1 = the source's lossless drive)",
        default=1.0,
        minimum=0.01,  # 1 %; 1e-30 once divided the motor torque down to zero
        maximum=1.0,
        recommended=(0.85, 1.0),
        group="motor curve",
    ),
    Param(
        "gear_efficiency",
        "1",
        "Gear mesh 4–5 efficiency while accelerating (1 = the source's lossless drive)",
        default=1.0,
        minimum=0.01,  # 1 %; 1e-30 once divided the motor torque down to zero
        maximum=1.0,
        recommended=(0.9, 1.0),
        group="motor curve",
    ),
    # the slip torque of safety coupling 1 (a torque limiter, sized as makers do)
    Param(
        "coupling_service_factor",
        "1",
        "service factor K on the motor's rated torque P/ω for the slip torque of the safety "
        "coupling 1; 1.5 (smooth) … 3 (shocks), as torque-limiter makers advise",
        default=2.0,
        minimum=1.0,
        maximum=10.0,
        recommended=(1.5, 3.0),
        group="coupling 1",
    ),
)

_OUTPUTS: tuple[Output, ...] = (
    Output(
        "kinetic_energy",
        "J",
        "Kinetic energy T of parts 1…5 at the working speed [000, eq. 3–4]",
        symbol="T",
        step="[000, eq. 3–4]",
    ),
    Output(
        "acceleration_time",
        "s",
        "Spin-up time: T/P [000, eq. 5], or ∫J dω/M(ω) (motor_curve)",
        symbol="t_a",
        step="[000, eq. 5]",
    ),
    Output(
        "shaft_stiffness",
        "N*m/rad",
        "Torsional stiffness C7 of the flywheel shaft [000, eq. 9]",
        symbol="C_7",
        step="[000, eq. 9]",
    ),
    Output(
        "spindle_stiffness",
        "N*m/rad",
        "Torsional stiffness C8 of a spindle [000, eq. 9]",
        symbol="C_8",
        step="[000, eq. 9]",
    ),
    Output(
        "impact_torque",
        "N*m",
        "Peak torque M on the struck spindle [000, eq. 7–8]; with the gear ratio in the "
        "gear_ratio and motor_curve rungs",
        symbol="M",
        step="[000, eq. 7–8]",
    ),
    Output(
        "max_spindle_torque",
        "N*m",
        "M_max = M − (z−1)·M_tr [000, eq. 10]",
        symbol="M_sp",
        step="[000, eq. 10]",
    ),
    Output(
        "spindle_torque_reserve",
        "1",
        "M_max / M_nut: how many times the torque reaching the nut covers what the wheel nut "
        "needs ([000]: the spindle torque must tighten and free it)",
        symbol="M_sp/M_nut",
        step="[000, eq. 10]",
    ),
    Output(
        "friction_clutch_torque",
        "N*m",
        "M_tr of each idle spindle's friction clutch, as eq. 10 takes it: z_f μ F (D + d)/4 "
        "from the clamp of its nut [000] where friction_clutch_clamp_force is given, else "
        "idle_spindle_friction_torque",
        symbol="M_tr",
        step="[000, eq. 10]",
    ),
    Output(
        "shaft_twist",
        "rad",
        "Twist of shaft 7 during the blow [000, eq. 6]",
        display_unit="deg",
        symbol="φ_7",
        step="[000, eq. 6]",
    ),
    Output(
        "spindle_twist",
        "rad",
        "Twist of spindle 8 during the blow [000, eq. 6]",
        display_unit="deg",
        symbol="φ_8",
        step="[000, eq. 6]",
    ),
    Output(
        "shaft_torque",
        "N*m",
        "Torque on shaft 7 during the blow: M (source) or u·M (geared)",
        symbol="M_7",
        step="[000, eq. 7–8]",
    ),
    Output(
        "coupling_energy",
        "J",
        "Kinetic energy of coupling 1 [000, eq. 3]",
        symbol="T_1",
        step="[000, eq. 3]",
    ),
    Output(
        "motor_pulley_energy",
        "J",
        "Kinetic energy of motor pulley 2 [000, eq. 3]",
        symbol="T_2",
        step="[000, eq. 3]",
    ),
    Output(
        "flywheel_energy",
        "J",
        "Kinetic energy of flywheel 3 [000, eq. 3]",
        symbol="T_3",
        step="[000, eq. 3]",
    ),
    Output(
        "drive_gear_energy",
        "J",
        "Kinetic energy of drive gear 4 [000, eq. 3]",
        symbol="T_4",
        step="[000, eq. 3]",
    ),
    Output(
        "spindle_gears_energy",
        "J",
        "Kinetic energy of all z spindle gears 5 [000, eq. 3]",
        symbol="T_5",
        step="[000, eq. 3]",
    ),
    Output(
        "equivalent_inertia",
        "kg*m^2",
        "Inertia of parts 1…5 referred to the motor shaft, 2T/ω² [000, eq. 3–4]",
        symbol="J_eq",
        step="[000, eq. 3–4]",
    ),
    Output(
        "flywheel_speed",
        "rad/s",
        "Flywheel speed ω3 = ω·D2/D3",
        display_unit="rpm",
        symbol="ω_3",
        step="[000, eq. 3]",
    ),
    Output(
        "spindle_gear_speed",
        "rad/s",
        "Spindle gear speed ω5 = ω3·D4/D5",
        display_unit="rpm",
        symbol="ω_5",
        step="[000, eq. 3]",
    ),
    Output(
        "gear_ratio",
        "1",
        "u = D4/D5, shaft torque over spindle torque",
        symbol="u",
        step="[000, eq. 7–8]",
    ),
    Output(
        "gear_ratio_torque_change",
        "1",
        "Relative change of the impact torque when the gear ratio is taken into account: "
        "M(u)/M(source) − 1",
        symbol="M(u)/M − 1",
        step="[000, eq. 7–8]",
    ),
    Output(
        "shaft_shear_stress",
        "Pa",
        "Peak shear stress in shaft 7, 16·M7/(π d7³)",
        display_unit="MPa",
        symbol="τ_7",
        step="",
    ),
    Output(
        "spindle_shear_stress",
        "Pa",
        "Peak shear stress in spindle 8, 16·M/(π d8³)",
        display_unit="MPa",
        symbol="τ_8",
        step="",
    ),
    Output(
        "drive_inertia",
        "kg*m^2",
        "motor_curve: inertia accelerated by the motor at its shaft (rotor, parts 1…5, "
        "divided by the belt and gear efficiencies)",
        symbol="J_eq",
        step="Kloss",
    ),
    Output(
        "constant_power_time",
        "s",
        "motor_curve: the source's constant-power time T/P [000, eq. 5]",
        symbol="t_P",
        step="[000, eq. 5]",
    ),
    Output(
        "time_vs_constant_power",
        "1",
        "motor_curve: spin-up time over the constant-power time, minus 1",
        symbol="t/t_P − 1",
        step="Kloss",
    ),
    Output("time", "s", "Time during spin-up (x-axis of the speed curves)", series=True),
    Output(
        "motor_speed_curve",
        "rad/s",
        "Motor speed against time during spin-up",
        series=True,
        x="time",
        display_unit="rpm",
    ),
    Output(
        "flywheel_speed_curve",
        "rad/s",
        "Flywheel speed against time during spin-up",
        series=True,
        x="time",
        display_unit="rpm",
    ),
    # safety coupling 1 as a torque limiter (engine.physics.clutch sizing)
    Output(
        "coupling_slip_torque",
        "N*m",
        "slip torque to set on the safety coupling 1: max(K P/ω, T_a), T_a = T_b J_L/(J_A + J_L) "
        "while a motor with breakdown torque T_b and rotor inertia J_A starts parts 2…5 (J_L)",
        symbol="T_R",
        step="",
    ),
)


def _motor_curve(x: Mapping[str, Any]) -> MotorCurve | None:
    """The motor curve described by the inputs, or None for 'none'.

    Raises InputOutOfRange naming the missing or inconsistent field.
    """
    kind = x["motor_curve"]
    if kind == "none":
        return None

    def need(name: str) -> float:
        value = x.get(name)
        if value is None:
            raise InputOutOfRange(f"{name} is required when motor_curve = {kind!r}", field=name)
        return float(value)

    if kind == "linear":
        m_st, w0 = need("stall_torque"), need("no_load_speed")
        return MotorCurve(
            kind,
            lambda w: linear_motor_torque(w, m_st, w0),
            w0,
            torque_below_limit=lambda gap: m_st * gap / w0,
        )
    if kind == "constant_power":
        m_c, power = need("stall_torque"), float(x["motor_power"])
        w_c = power / m_c
        return MotorCurve(kind, lambda w: power / np.maximum(w, w_c), None, (w_c,))
    need("synchronous_speed"), need("breakdown_torque")
    w_n, w_s, m_n, m_k = (float(v) for v in _induction_data(x))
    if not w_n < w_s:
        raise InputOutOfRange(
            f"rated_speed = {w_n:.4g} rad/s must be below synchronous_speed = {w_s:.4g} rad/s "
            "(an induction motor runs with slip)",
            field="rated_speed" if x.get("rated_speed") is not None else "synchronous_speed",
        )
    if not m_k > m_n:
        raise InputOutOfRange(
            f"breakdown_torque = {m_k:.4g} N*m must exceed the rated torque {m_n:.4g} N*m",
            field="breakdown_torque",
        )
    s_k = float(kloss_breakdown_slip(w_n, w_s, m_k / m_n))
    return MotorCurve(
        kind,
        lambda w: kloss_torque(w, m_k, w_s, s_k),
        w_s,
        torque_below_limit=lambda gap: kloss_slip_torque(gap / w_s, m_k, s_k),
    )


def _induction_data(x: Mapping[str, Any]) -> tuple[Any, Any, Any, Any]:
    """(ω_n, ω_s, M_n, M_k) of the induction curve; rated speed and torque default to
    the motor's speed and P/ω_n. Floats or arrays."""
    w_n = x["rated_speed"] if x.get("rated_speed") is not None else x["motor_speed"]
    m_n = x["rated_torque"] if x.get("rated_torque") is not None else x["motor_power"] / w_n
    return w_n, x["synchronous_speed"], m_n, x["breakdown_torque"]


#: The inputs each motor curve needs (:func:`_motor_curve` names the missing one).
_CURVE_INPUTS = {
    "linear": ("stall_torque", "no_load_speed"),
    "constant_power": ("stall_torque",),
    "induction": ("synchronous_speed", "breakdown_torque"),
}


def _curve_time(x: Mapping[str, Any], inertia: Any) -> Any:
    """Spin-up time J∫dω/M(ω) on the given motor curve, by the curve's closed form.

    Floats or arrays. NaN where :func:`_motor_curve` or :func:`spin_up_time` refuses
    the point: an induction motor without slip or whose breakdown torque is not above
    the rated one, a torque that falls to zero before the working speed. The
    closed forms equal the quadrature the motor_curve rung runs to ~2e-14
    (``tests/models/nutrunner/test_estimate_arrays.py``).
    """
    kind, w = x["motor_curve"], x["motor_speed"]
    if kind == "linear":
        w0 = x["no_load_speed"]
        t = linear_spin_up_time(inertia, x["stall_torque"], w0, w)
        ok: Any = np.asarray(w) < w0
    elif kind == "constant_power":
        t = torque_limited_constant_power_spin_up_time(
            inertia, x["motor_power"], x["stall_torque"], w
        )
        ok = True
    else:
        w_n, w_s, m_n, m_k = _induction_data(x)
        ok = (np.asarray(w_n) < w_s) & (np.asarray(m_k) > m_n) & (np.asarray(w) < w_s)
        s_k = kloss_breakdown_slip(w_n, w_s, m_k / m_n)
        t = kloss_spin_up_time(inertia, m_k, w_s, s_k, w)
    return np.where(ok, t, np.nan)


@dataclass(frozen=True)
class _Drive:
    """Everything the closed forms give, for one design (floats or arrays).

    A field :func:`_drive` was asked to leave out is None.
    """

    energies: tuple[Any, Any, Any, Any, Any] | None
    inertia: Any
    energy: Any
    w3: Any
    w5: Any
    u: Any
    c7: Any
    c8: Any
    m_paper: Any
    m_geared: Any


def _drive(x: Mapping[str, Any], *, parts: bool = True, torque: str = "both") -> _Drive:
    """The closed forms of drive ``x`` [000, eq. 1–9], on floats or arrays.

    The energy is the inertia of parts 1…5 at the motor shaft (one number where the parts
    do not vary) times ω²/2, in every path. ``parts``: the part energies and the flywheel
    and spindle-gear speeds too (else None). ``torque``: "paper", "geared", "both" or
    "none" of the impact-torque forms (the others None). On arrays each left-out
    quantity is a pass over the points.
    """
    w = x["motor_speed"]
    inertia = _inertia(x)
    energy = rotational_energy(inertia, w)
    energies = w3 = w5 = None
    if parts:
        energies = part_energies(w, *_parts(x))
        w3 = flywheel_speed(w, x["motor_pulley_diameter"], x["flywheel_diameter"])
        w5 = spindle_speed(w3, x["drive_gear_diameter"], x["spindle_gear_diameter"])
    u = x["drive_gear_diameter"] / x["spindle_gear_diameter"]
    g = x["shear_modulus"]
    c7 = torsional_stiffness(g, x["shaft_diameter"], x["shaft_length"])
    c8 = torsional_stiffness(g, x["spindle_diameter"], x["spindle_length"])
    return _Drive(
        energies=energies,
        inertia=inertia,
        energy=energy,
        w3=w3,
        w5=w5,
        u=u,
        c7=c7,
        c8=c8,
        m_paper=impact_torque(energy, c7, c8) if torque in ("paper", "both") else None,
        m_geared=impact_torque_geared(energy, c7, c8, u) if torque in ("geared", "both") else None,
    )


def _closed_values(
    x: Mapping[str, Any],
    d: _Drive,
    geared: bool,
    wanted: Container[str] | None = None,
    every: bool = True,
) -> dict[str, Any]:
    """The closed-form outputs of drive ``d`` [000, eq. 1–10], on floats or arrays.

    ``wanted``: the outputs asked for (every one when None); the drive's details (twists,
    part energies, speeds, stresses, the coupling's slip torque) are left out where none
    of them is: on arrays each is a pass over the points. ``every``: False leaves out the
    energy, time, torques and reserve not in ``wanted`` too (a caller reading no checks).
    """
    m = d.m_geared if geared else d.m_paper
    values: dict[str, Any] = {}
    if every or wanted is None or "kinetic_energy" in wanted:
        values["kinetic_energy"] = d.energy
    if every or wanted is None or "acceleration_time" in wanted:
        values["acceleration_time"] = acceleration_time(d.energy, x["motor_power"])
    values["shaft_stiffness"] = d.c7
    values["spindle_stiffness"] = d.c8
    if every or wanted is None or "impact_torque" in wanted:
        values["impact_torque"] = m
    if (
        every
        or wanted is None
        or "max_spindle_torque" in wanted
        or "spindle_torque_reserve" in wanted
    ):
        m_max = max_spindle_torque(m, x["spindle_count"], x["idle_spindle_friction_torque"])
        values["max_spindle_torque"] = m_max
        reserve = spindle_torque_reserve(m_max, x["wheel_nut_torque"])
        values["spindle_torque_reserve"] = reserve
    if wanted is not None and not any(name in wanted for name in _DRIVE_DETAILS):
        return values
    m7 = d.u * m if geared else m
    assert d.energies is not None  # the details read the part energies
    t1, t2, t3, t4, t5 = d.energies
    values.update(
        {
            "shaft_twist": twist_angle(m7, d.c7),
            "spindle_twist": twist_angle(m, d.c8),
            "shaft_torque": m7,
            "coupling_energy": t1,
            "motor_pulley_energy": t2,
            "flywheel_energy": t3,
            "drive_gear_energy": t4,
            "spindle_gears_energy": t5,
            "equivalent_inertia": d.inertia,
            "flywheel_speed": d.w3,
            "spindle_gear_speed": d.w5,
            "gear_ratio": d.u,
            "gear_ratio_torque_change": gear_ratio_torque_change(d.c7, d.c8, d.u),
            "shaft_shear_stress": shaft_shear_stress(m7, x["shaft_diameter"]),
            "spindle_shear_stress": shaft_shear_stress(m, x["spindle_diameter"]),
            "coupling_slip_torque": _coupling_slip_torque(x, d),
        }
    )
    return values


#: The outputs of :func:`_closed_values` beyond the energy, the time and the torques.
_DRIVE_DETAILS = (
    "shaft_twist",
    "spindle_twist",
    "shaft_torque",
    "coupling_energy",
    "motor_pulley_energy",
    "flywheel_energy",
    "drive_gear_energy",
    "spindle_gears_energy",
    "equivalent_inertia",
    "flywheel_speed",
    "spindle_gear_speed",
    "gear_ratio",
    "gear_ratio_torque_change",
    "shaft_shear_stress",
    "spindle_shear_stress",
    "coupling_slip_torque",
)


def _coupling_slip_torque(x: Mapping[str, Any], d: _Drive) -> Any:
    """Slip torque of coupling 1: K P/ω, or the start torque through it if larger."""
    rated = rated_torque(x["motor_power"], x["motor_speed"])
    start: Any = 0.0
    if x["breakdown_torque"] is not None and x["rotor_inertia"] is not None:
        # parts 2…5 are the load; the coupling's own inertia counts with the motor's side
        load = _inertia(x, coupling=False)
        drive = x["rotor_inertia"] + disc_inertia(x["coupling_mass"], x["coupling_diameter"])
        start = acceleration_torque(x["breakdown_torque"], drive, load)
    return required_slip_torque(rated, x["coupling_service_factor"], start)


def _inertia(x: Mapping[str, Any], *, coupling: bool = True, **motor: Any) -> Any:
    """Inertia of parts 1…5 (or 2…5) at the motor shaft; ``motor``: rotor and efficiencies."""
    return drive_inertia(*_parts(x, coupling=coupling), **motor)


def _parts(x: Mapping[str, Any], *, coupling: bool = True) -> tuple[Any, ...]:
    """Mass and diameter of parts 1…5 and the spindle count, in the order the drive's
    energy and inertia functions take them (``coupling`` False: part 1's mass 0)."""
    return (
        x["coupling_mass"] if coupling else 0.0,
        x["coupling_diameter"],
        x["motor_pulley_mass"],
        x["motor_pulley_diameter"],
        x["flywheel_mass"],
        x["flywheel_diameter"],
        x["drive_gear_mass"],
        x["drive_gear_diameter"],
        x["spindle_gear_mass"],
        x["spindle_gear_diameter"],
        x["spindle_count"],
    )


def _drive_inertia(x: Mapping[str, Any]) -> Any:
    """What the motor accelerates: rotor, parts 1…5, through the belt and gear losses."""
    return _inertia(
        x,
        rotor_inertia=x["rotor_inertia"],
        belt_efficiency=x["belt_efficiency"],
        gear_efficiency=x["gear_efficiency"],
    )


def _curve_time_ratio(x: Mapping[str, Any], energy: float) -> float | None:
    """Constant-power time over motor-curve time, minus 1 (None without a curve).

    One design of drive energy ``energy``; raises, naming the field, where the curve
    is refused.
    """
    curve = _motor_curve(x)
    if curve is None:
        return None
    j = float(_drive_inertia(x))
    with np.errstate(all="ignore"):
        t_curve = float(_curve_time(x, j))
    if math.isnan(t_curve):
        spin_up_time(j, curve, float(x["motor_speed"]))  # raises: why the motor cannot
    return float(acceleration_time(energy, x["motor_power"]) / t_curve - 1.0)


def _idealisation_error(x: Mapping[str, Any], energy: Any = None) -> Any:
    """How far the constant-power time is from the motor curve's (0 without a curve).

    |T/P / t_curve − 1|, 1 where the curve is refused (the constant-power time is
    meaningless if the motor cannot get there). Floats or arrays (a sweep or a study):
    the curves' closed forms (:func:`_curve_time`), every point at once. ``energy``:
    the drive's, where the caller has it.
    """
    kind = x["motor_curve"]
    if kind == "none":
        return 0.0
    if any(x.get(name) is None for name in _CURVE_INPUTS[kind]):
        return 1.0
    if energy is None:
        energy = _drive(x, parts=False, torque="none").energy
    with np.errstate(all="ignore"):
        t_curve = _curve_time(x, _drive_inertia(x))
        ratio = np.abs(acceleration_time(energy, x["motor_power"]) / t_curve - 1.0)
    error = np.where(np.isnan(t_curve), 1.0, ratio)
    return float(error) if error.ndim == 0 else error


_FLOOR = 1e-12  # float rounding of the closed forms


def _estimate_closed_form(x: Mapping[str, Any], drive: _Drive | None = None) -> Any:
    """Largest relative change the gear ratio makes to any torque output, either way round.

    Spindle quantities scale with M_paper/M_geared, shaft quantities (torque, twist,
    stress) with M_paper/(u·M_geared), and M_max with the ratio of the torques left
    after the idle spindles' friction (while both stay positive). Each ratio r counts
    as max(|r − 1|, |1/r − 1|), so the estimate bounds the difference whichever rung
    is taken as the reference. With a motor curve, the constant-power idealisation of
    the spin-up time counts too.
    """
    d = _drive(x, parts=False) if drive is None else drive  # the torques alone
    # numpy scalars for one design (their arithmetic is cheap), arrays for many
    m_paper = np.asarray(d.m_paper, dtype=float)[()]
    m_geared = np.asarray(d.m_geared, dtype=float)[()]
    friction = (x["spindle_count"] - 1) * x["idle_spindle_friction_torque"]
    with np.errstate(all="ignore"):  # array-capable: a sweep estimates every point at once
        gear = np.maximum(_spread(m_paper / m_geared), _spread(m_paper / (d.u * m_geared)))
        after_friction = _spread((m_paper - friction) / (m_geared - friction))
    gear = np.where(
        np.minimum(m_paper, m_geared) > friction, np.maximum(gear, after_friction), gear
    )
    estimate = np.maximum(np.maximum(_FLOOR, gear), _idealisation_error(x, d.energy))
    return float(estimate) if estimate.ndim == 0 else estimate


def _spread(r: Any) -> Any:
    """max(|r − 1|, |1/r − 1|): a ratio's relative change, either way round."""
    return np.maximum(abs(r - 1.0), abs(1.0 / r - 1.0))


def _estimate_gear_ratio(x: Mapping[str, Any]) -> Any:
    """With a motor curve: the constant-power idealisation; else rounding only (arrays too)."""
    estimate = np.maximum(_FLOOR, _idealisation_error(x))
    return float(estimate) if estimate.ndim == 0 else estimate


def _estimate_motor_curve(x: Mapping[str, Any]) -> float | None:
    """Quadrature tolerance; None when no motor curve is given (the same at every point)."""
    return None if x["motor_curve"] == "none" else 1e-8


def _verdicts(x: Mapping[str, Any], values: Mapping[str, Any]) -> dict[str, Any]:
    """Each check's verdict, on floats or arrays: a bool, or int8 with -1 where not reported.

    The one place the checks compare numbers: a single run turns these verdicts into
    sentences (:func:`_checks`), a sweep or a study reports them per point.
    """
    positive = values["max_spindle_torque"] > 0.0
    enough = values["spindle_torque_reserve"] >= 1.0
    out: dict[str, Any] = {"max_spindle_torque_positive": positive}
    # where no torque reaches the nut, max_spindle_torque_positive says so alone
    if isinstance(positive, bool | np.bool_):
        if positive:
            out["wheel_nut_torque"] = enough
    elif positive.any():
        out["wheel_nut_torque"] = np.where(positive, enough, -1).astype(np.int8)
    z, d5 = x["spindle_count"], x["spindle_gear_diameter"]
    applies = z >= 2  # a single spindle has no neighbouring gear to hit
    every = isinstance(applies, bool) or np.ndim(applies) == 0  # one count at every point
    if applies if every else applies.any():
        fits = spindle_gear_spacing(x["drive_gear_diameter"], d5, z) > d5
        out["spindle_gears_fit"] = fits if every else np.where(applies, fits, -1).astype(np.int8)
    tau_y = x.get("shear_yield_strength")
    if tau_y is not None:
        for key in ("shaft_shear_stress", "spindle_shear_stress"):
            out[f"{key.removesuffix('_shear_stress')}_elastic"] = values[key] <= tau_y
    return out


def _checks(x: Mapping[str, Any], values: Mapping[str, Any]) -> tuple[list[Check], list[str]]:
    """The checks of one design as sentences, on the verdicts of :func:`_verdicts`."""
    verdicts = _verdicts(x, values)
    checks: list[Check] = []
    warnings: list[str] = []
    m = float(values["impact_torque"])
    m_max = float(values["max_spindle_torque"])
    z, m_tr = int(x["spindle_count"]), float(x["idle_spindle_friction_torque"])
    if bool(verdicts["max_spindle_torque_positive"]):
        checks.append(
            Check(
                "max_spindle_torque_positive",
                True,
                f"the idle spindles' friction takes {_nm((z - 1) * m_tr)} of the "
                f"{_nm(m)} blow; {_nm(m_max)} reach the nut",
            )
        )
    else:
        detail = (
            f"the friction of the {z - 1} idle spindles, {_nm((z - 1) * m_tr)}, absorbs "
            f"the whole {_nm(m)} blow (M_max = {_nm(m_max)}): lower the friction-clutch "
            f"torque below {_nm(m / max(z - 1, 1))} per spindle, or raise the blow energy"
        )
        checks.append(Check("max_spindle_torque_positive", False, detail))
        warnings.append("no torque reaches the nut: " + detail)
    need = float(x["wheel_nut_torque"])
    enough = bool(verdicts.get("wheel_nut_torque", False))
    if "wheel_nut_torque" in verdicts:
        checks.append(
            Check(
                "wheel_nut_torque",
                enough,
                f"{_nm(m_max)} reach the nut against the {_nm(need)} the wheel nut needs "
                f"(×{m_max / need:.3g}; [000]: the spindle torque must tighten and free it)"
                + (
                    ""
                    if enough
                    else ": raise the blow energy (a heavier or faster flywheel), stiffen shaft "
                    "and spindle, or lower the idle spindles' friction torque"
                ),
            )
        )
    if "wheel_nut_torque" in verdicts and not enough:
        warnings.append(f"the blow gives {_nm(m_max)}, less than the wheel nut's {_nm(need)}")
    fit = int(verdicts.get("spindle_gears_fit", -1))
    if fit >= 0:
        d4, d5 = float(x["drive_gear_diameter"]), float(x["spindle_gear_diameter"])
        pitch = float(spindle_gear_spacing(d4, d5, z))
        checks.append(
            Check(
                "spindle_gears_fit",
                bool(fit),
                f"neighbouring spindle gears' centres are {q(pitch, 'mm', 4)} apart on the "
                f"{q(d4 + d5, 'mm', 4)} circle; a gear is {q(d5, 'mm', 4)} across"
                + ("" if fit else ": they overlap, use smaller spindle gears or fewer"),
            )
        )
    tau_y = x.get("shear_yield_strength")
    if tau_y is not None:
        for part, key in (("shaft 7", "shaft_shear_stress"), ("spindle 8", "spindle_shear_stress")):
            tau = float(values[key])
            name = f"{key.removesuffix('_shear_stress')}_elastic"
            ok = bool(verdicts[name])
            checks.append(
                Check(
                    name,
                    ok,
                    f"{part}: peak shear stress {q(tau, 'MPa', 4)} vs yield {q(tau_y, 'MPa', 4)}"
                    + (
                        ""
                        if ok
                        else "; it yields, so the elastic model over-states the torque: "
                        "thicken it or lower the blow energy"
                    ),
                )
            )
    return checks, warnings


def _constant_power_note(x: Mapping[str, Any], energy: float) -> str:
    """What the given motor curve says about this rung's constant-power spin-up time."""
    try:
        ratio = _curve_time_ratio(x, energy)
    except (InfeasibleDesign, InputOutOfRange) as exc:
        return f"the motor curve given is not used by this rung, and it fails: {exc.message}"
    assert ratio is not None
    if not (math.isfinite(ratio) and 1.0 + ratio > 0.0):
        return (
            "this rung assumes constant power from standstill [000, eq. 5]; the "
            f"{x['motor_curve']} motor curve given cannot be compared with it for these "
            "inputs (its spin-up time is not finite): use rung motor_curve"
        )
    return (
        "this rung assumes constant power from standstill [000, eq. 5]; the "
        f"{x['motor_curve']} motor curve given changes the spin-up time by "
        f"{1.0 / (1.0 + ratio) - 1.0:+.1%} (rung motor_curve)"
    )


#: True of every answer (the runner adds them to the notes; the catalogue lists them).
ASSUMPTIONS = (
    "eq. 3–5 and 7–8 of the source are illegible; T and t = T/P are reconstructed from "
    "the work–energy theorem and the kinematic chain it names (see [000] in docs/sources.md)",
    "the impact torque ignores socket, nut and joint compliance and all losses, as the "
    "source does: an upper bound while shaft and spindle stay elastic",
)


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    x, m_tr, clutch_warnings = _with_friction_clutch(x)
    d = _drive(x)
    geared = ctx.rung != "closed_form"
    values = _closed_values(x, d, geared)
    values["friction_clutch_torque"] = m_tr
    notes: list[str] = []
    effect = float(values["gear_ratio_torque_change"])
    if ctx.rung == "closed_form":
        notes.append(
            f"as in the source, shaft 7 and spindle 8 carry the same torque; with the gear "
            f"ratio u = D4/D5 = {d.u:.4g} the spindle torque would change by {effect:+.2%} "
            f"and the shaft torque (twist, stress) by {d.u * (1.0 + effect) - 1.0:+.2%} "
            "(rung gear_ratio); the error estimate is the larger change, either way round"
        )
        error: float | None = _estimate_closed_form(x, d)
    else:
        notes.append(
            f"shaft 7 carries u·M with u = D4/D5 = {d.u:.4g}; this moves the spindle torque by "
            f"{effect:+.2%} from the source's form (which puts M on both)"
        )
        error = _estimate_gear_ratio(x) if ctx.rung == "gear_ratio" else None
    if ctx.rung != "motor_curve" and x["motor_curve"] != "none":
        notes.append(_constant_power_note(x, d.energy))
    series: dict[str, list[float]] = {}
    wants_series = ctx.wants("time", "motor_speed_curve", "flywheel_speed_curve")
    w = float(x["motor_speed"])
    if ctx.rung == "motor_curve":
        curve = _motor_curve(x)
        if curve is None:
            raise InputOutOfRange(
                "the motor_curve rung needs a torque–speed curve: set motor_curve to "
                "'linear', 'induction' or 'constant_power' with its inputs",
                field="motor_curve",
            )
        j_drive = float(_drive_inertia(x))
        t_curve, abserr = spin_up_time(j_drive, curve, w)
        t_cp = float(values["acceleration_time"])
        error = max(abserr / t_curve, 1e-15)
        values["acceleration_time"] = t_curve
        values["drive_inertia"] = j_drive
        values["constant_power_time"] = t_cp
        values["time_vs_constant_power"] = t_curve / t_cp - 1.0
        notes.append(
            f"spin-up by quadrature of J dω/M(ω) on the {curve.kind} curve: {q(t_curve, 's', 4)}, "
            f"{t_curve / t_cp - 1.0:+.1%} against the source's constant-power {q(t_cp, 's', 4)}"
        )
        if curve.kind == "induction":
            notes.append(
                "the Kloss formula neglects stator resistance and under-estimates a cage "
                "motor's starting torque, so this time is on the long side"
            )
        m_end = float(curve.torque(w))
        m_peak = float(np.max(curve.torque(np.linspace(0.0, w, 257))))
        check = Check(
            "motor_reaches_speed",
            True,
            f"the motor reaches {q(w, 'rpm', fmt='.0f')} in {q(t_curve, 's')}; its torque "
            f"there is {_nm(m_end)} ({m_end / m_peak:.0%} of its peak on the way)",
        )
        if wants_series:
            times, speeds = spin_up_profile(j_drive, curve, w)
            series = {"time": times.tolist(), "motor_speed_curve": speeds.tolist()}
    else:
        check = None
        if wants_series:
            # constant power: T ∝ ω² grows linearly in time, so ω(t) = ω·√(t/t_end)
            speeds = np.linspace(0.0, w, 101)
            times = float(values["acceleration_time"]) * (speeds / w) ** 2
            series = {"time": times.tolist(), "motor_speed_curve": speeds.tolist()}
    if series:
        series["flywheel_speed_curve"] = (
            np.asarray(series["motor_speed_curve"]) * float(d.w3) / w
        ).tolist()
    checks, warnings = _checks(x, values)
    if check is not None:
        checks.insert(0, check)
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=error,
        checks=checks,
        notes=notes,
        warnings=[*clutch_warnings, *warnings],
        series=series,
    )


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """Closed forms on arrays (one input varied), for sweeps."""
    arrays = {
        k: (np.asarray(v, dtype=float) if isinstance(v, np.ndarray) else v) for k, v in x.items()
    }
    arrays, m_tr, clutch_warnings = _with_friction_clutch(arrays)
    geared = ctx.rung != "closed_form"
    wanted = ctx.outputs
    # the checks (:func:`_verdicts`) read the shear stresses where a yield strength is given
    if ctx.checks and x.get("shear_yield_strength") is not None:
        wanted = wanted | {"shaft_shear_stress", "spindle_shear_stress"}
    # a caller reading no checks (a sweep) gets the outputs it asked for alone: the rung's
    # torque form, and the part energies and speeds only where a detail reads them
    details = ctx.checks or any(name in wanted for name in _DRIVE_DETAILS)
    torque = "both" if ctx.checks else ("geared" if geared else "paper")
    d = _drive(arrays, parts=details, torque=torque)
    values = _closed_values(arrays, d, geared=geared, wanted=wanted, every=ctx.checks)
    values["friction_clutch_torque"] = m_tr
    warnings = list(clutch_warnings)
    if "max_spindle_torque" in values:
        m_max = np.asarray(values["max_spindle_torque"])
        if np.any(m_max <= 0.0):
            warnings.append(
                f"at {int(np.sum(m_max <= 0.0))} points the idle spindles' friction absorbs "
                "the whole blow (max_spindle_torque ≤ 0)"
            )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=None,
        warnings=warnings,
        check_arrays=_verdicts(arrays, values) if ctx.checks else {},
    )


EXAMPLE_LIGHT_TRUCK: dict[str, Any] = {
    "motor_power": 1100.0,
    "motor_speed": 1400.0 * RPM,
    "coupling_mass": 1.2,
    "coupling_diameter": 0.09,
    "motor_pulley_mass": 0.8,
    "motor_pulley_diameter": 0.08,
    "flywheel_mass": 12.0,
    "flywheel_diameter": 0.25,
    "drive_gear_mass": 2.5,
    "drive_gear_diameter": 0.10,
    "spindle_gear_mass": 0.5,
    "spindle_gear_diameter": 0.05,
    "spindle_count": 6,
    "shaft_diameter": 0.045,
    "shaft_length": 0.20,
    "spindle_diameter": 0.032,
    "spindle_length": 0.30,
    "shear_modulus": STEEL_SHEAR_MODULUS,
    "idle_spindle_friction_torque": 10.0,
}
"""Illustrative six-nut light-truck wheel-nut runner: the source gives no worked numbers."""

EXAMPLE_INDUCTION_MOTOR: dict[str, Any] = {
    **EXAMPLE_LIGHT_TRUCK,
    "motor_curve": "induction",
    "synchronous_speed": 1500.0 * RPM,
    "breakdown_torque": 2.2 * 1100.0 / (1400.0 * RPM),
    "rotor_inertia": 0.0035,
    "belt_efficiency": 0.95,
    "gear_efficiency": 0.97,
}
"""The same drive on a 1.1 kW 4-pole cage motor (breakdown 2.2× rated), belt and gear losses."""

NUTRUNNER_DRIVE = ModelSpec(
    name="nutrunner.drive",
    answer=(
        Answer("impact_torque", "M"),
        Answer("max_spindle_torque", "M_sp", check="wheel_nut_torque"),
        Answer("spindle_torque_reserve", "M_sp/M_nut"),
        Answer("acceleration_time", "t_a"),
    ),
    title="Multi-spindle impact nut-runner drive",
    family="nutrunner",
    summary=(
        "Spin-up time of a wheel-nut runner's motor–belt–flywheel–gear drive and the "
        "torque one blow puts on a spindle, from the drive's kinetic energy stored as "
        "elastic twist of the flywheel shaft and the spindle. The source gives no worked "
        "example; examples[0] is an illustrative six-nut light-truck runner."
    ),
    source=(
        "[000] Parameters of the drive of a multi-spindle nut-runner (Ukrainian journal "
        "article), eq. 1–10; reconstructions in docs/sources.md; motor curves by the "
        "Kloss formula"
    ),
    inputs=_INPUTS,
    outputs=_OUTPUTS,
    rungs=(
        Rung(
            "closed_form",
            "The source's model: t = T/P at constant power, one torque M on shaft and "
            "spindle [000, eq. 1–10]",
            _estimate_closed_form,
            typical_error="0 when D4 = D5; the gear-ratio effect (tens of %) otherwise",
            typical_time="~50 µs",
        ),
        Rung(
            "gear_ratio",
            "As closed_form, but shaft 7 carries u·M with u = D4/D5 (the source ignores u)",
            _estimate_gear_ratio,
            typical_error="the constant-power idealisation of the spin-up time",
            typical_time="~50 µs",
        ),
        Rung(
            "motor_curve",
            "gear_ratio torque; spin-up t = ∫J_eq dω/M(ω) by adaptive quadrature on a real "
            "motor curve (linear, Kloss induction, or torque-limited constant power) with "
            "rotor inertia and belt/gear efficiency; needs motor_curve ≠ 'none'",
            _estimate_motor_curve,
            typical_error="quadrature error ~1e-10 (the curve itself is the model)",
            typical_time="~0.1 ms",
        ),
    ),
    compute=_compute,
    default_fidelity="closed_form",
    examples=(EXAMPLE_LIGHT_TRUCK, EXAMPLE_INDUCTION_MOTOR),
    assumptions=ASSUMPTIONS,
    vectorized=_vectorized,
    vector_rungs=("closed_form", "gear_ratio"),
)
