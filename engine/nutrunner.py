r"""Drive of a multi-spindle impact nut-runner: spin-up time and impact torque.

Source [000]: the parameters of a multi-spindle wheel-nut runner's drive
(seeds/000, MODELS.md §1). A motor 6 (power :math:`P`, shaft speed
:math:`\omega`) turns a safety jaw coupling 1 and a motor pulley 2; a V-belt
drives the flywheel 3 (the driven pulley) on shaft 7, which carries the drive
gear 4; the drive gear meshes with :math:`z` spindle gears 5, each coupled to
its spindle 8 by a jaw clutch (the blow) and a friction clutch (a small
run-down torque :math:`M_{tr}`). Parts 1…5 are solid uniform discs.

The paper gives two models:

* the spin-up time from the work–energy theorem, :math:`t = T/P`
  [000, eq. 1–5], constant power from standstill;
* the impact torque from energy conservation, the kinetic energy of parts
  1…5 being stored as elastic twist of shaft 7 and spindle 8
  [000, eq. 6–10].

This module holds those equations as pure functions on SI floats (or numpy
arrays), two refinements the catalogue asks for (the gear ratio between shaft
and spindle, and a real motor's torque–speed curve integrated by quadrature in
:mod:`engine.motor_spinup`),
and the :data:`NUTRUNNER_DRIVE` spec that the service serves at
``/nutrunner/drive``.

Where the source is unclear (its eq. 3–5 and 7–8 are illegible or garbled in
the only copy), the reconstruction follows MODELS.md §1 and is said so in the
docstrings and in each result's notes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .errors import InfeasibleDesign, InputOutOfRange
from .motor_spinup import (
    MotorCurve,
    kloss_breakdown_slip,
    kloss_slip_torque,
    kloss_torque,
    linear_motor_torque,
    spin_up_profile,
    spin_up_time,
)
from .spec import Check, ModelSpec, Output, Param, Result, RunContext, Rung

__all__ = [
    "NUTRUNNER_DRIVE",
    "acceleration_time",
    "disc_inertia",
    "equivalent_inertia",
    "flywheel_speed",
    "impact_torque",
    "impact_torque_geared",
    "kinetic_energy",
    "max_spindle_torque",
    "part_energies",
    "shaft_shear_stress",
    "spindle_speed",
    "torsional_stiffness",
    "twist_angle",
]

STEEL_SHEAR_MODULUS = 8.0e10
"""Shear modulus of steel the source uses, [Pa] [000, after eq. 9]."""


# ---------------------------------------------------------------------------
# Kinematics and energy [000, eq. 1–5]
# ---------------------------------------------------------------------------


def disc_inertia(mass: Any, diameter: Any) -> Any:
    r"""Moment of inertia of a solid uniform disc about its axis.

    .. math::
        J = \frac{m D^2}{8}

    Parameters
    ----------
    mass : float
        Mass of the disc, [kg]
    diameter : float
        Outer diameter of the disc, [m]

    Returns
    -------
    J : float
        Moment of inertia, [kg*m^2]

    Notes
    -----
    The source treats parts 1…5 (coupling, pulley, flywheel, gears) as solid
    uniform discs [000, before eq. 1]; a rimmed flywheel has up to twice this.

    Examples
    --------
    >>> disc_inertia(12.0, 0.25)
    0.09375
    """
    return mass * diameter**2 / 8.0


def flywheel_speed(motor_speed: Any, motor_pulley_diameter: Any, flywheel_diameter: Any) -> Any:
    r"""Speed of the flywheel 3 (and drive gear 4) driven through the V-belt.

    .. math::
        \omega_3 = \omega_4 = \omega \frac{D_2}{D_3}

    Parameters
    ----------
    motor_speed : float
        Motor shaft speed :math:`\omega`, [rad/s]
    motor_pulley_diameter : float
        Diameter of the motor pulley 2, :math:`D_2`, [m]
    flywheel_diameter : float
        Diameter of the flywheel 3 (the driven pulley), :math:`D_3`, [m]

    Returns
    -------
    omega_3 : float
        Flywheel speed, [rad/s]

    Notes
    -----
    Kinematic chain of [000, fig. 1]; belt slip is ignored, as in the source.
    The pulley diameters stand in for the belt's pitch diameters.

    Examples
    --------
    >>> flywheel_speed(150.0, 0.08, 0.24)
    50.0
    """
    return motor_speed * motor_pulley_diameter / flywheel_diameter


def spindle_speed(flywheel_speed: Any, drive_gear_diameter: Any, spindle_gear_diameter: Any) -> Any:
    r"""Speed of the spindle gears 5 driven by the drive gear 4.

    .. math::
        \omega_5 = \omega_3 \frac{D_4}{D_5} = u\,\omega_3

    Parameters
    ----------
    flywheel_speed : float
        Speed of the flywheel shaft 7, :math:`\omega_3`, [rad/s]
    drive_gear_diameter : float
        Pitch diameter of the drive gear 4, :math:`D_4`, [m]
    spindle_gear_diameter : float
        Pitch diameter of a spindle gear 5, :math:`D_5`, [m]

    Returns
    -------
    omega_5 : float
        Spindle gear speed, [rad/s]

    Notes
    -----
    Kinematic chain of [000, fig. 1]; :math:`u = D_4/D_5` is the gear ratio.

    Examples
    --------
    >>> spindle_speed(50.0, 0.1, 0.05)
    100.0
    """
    return flywheel_speed * drive_gear_diameter / spindle_gear_diameter


def part_energies(
    motor_speed: Any,
    coupling_mass: Any,
    coupling_diameter: Any,
    motor_pulley_mass: Any,
    motor_pulley_diameter: Any,
    flywheel_mass: Any,
    flywheel_diameter: Any,
    drive_gear_mass: Any,
    drive_gear_diameter: Any,
    spindle_gear_mass: Any,
    spindle_gear_diameter: Any,
    spindle_count: Any,
) -> tuple[Any, Any, Any, Any, Any]:
    r"""Kinetic energy of each rotating part at the working speed.

    .. math::
        T_k = \tfrac12 J_k \omega_k^2 = \tfrac{1}{16} m_k D_k^2 \omega_k^2,
        \qquad T_5 = \tfrac{z}{16} m_5 D_5^2 \omega_5^2

    with :math:`\omega_1 = \omega_2 = \omega`, :math:`\omega_3 = \omega_4 =
    \omega D_2/D_3`, :math:`\omega_5 = \omega_3 D_4/D_5`.

    Parameters
    ----------
    motor_speed : float
        Motor shaft speed :math:`\omega`, [rad/s]
    coupling_mass, coupling_diameter : float
        Safety coupling 1, [kg], [m]
    motor_pulley_mass, motor_pulley_diameter : float
        Motor pulley 2, [kg], [m]
    flywheel_mass, flywheel_diameter : float
        Flywheel 3 (driven pulley), [kg], [m]
    drive_gear_mass, drive_gear_diameter : float
        Drive gear 4 on the flywheel shaft, [kg], [m]
    spindle_gear_mass, spindle_gear_diameter : float
        One spindle gear 5, [kg], [m]
    spindle_count : int
        Number of spindles :math:`z`, [-]

    Returns
    -------
    energies : tuple of float
        :math:`(T_1, T_2, T_3, T_4, T_5)`, [J]; :math:`T_5` is all :math:`z`
        spindle gears together.

    Notes
    -----
    The terms of [000, eq. 3–4]; the printed equations are illegible, so the
    form follows MODELS.md §1 (the theorem the paper names and its kinematic
    chain).

    Examples
    --------
    >>> [round(e, 4) for e in part_energies(100.0, 1, 0.1, 1, 0.1, 8, 0.2, 1, 0.1, 1, 0.1, 2)]
    [6.25, 6.25, 50.0, 1.5625, 3.125]
    """
    w = motor_speed
    w3 = flywheel_speed(w, motor_pulley_diameter, flywheel_diameter)
    w5 = spindle_speed(w3, drive_gear_diameter, spindle_gear_diameter)
    t1 = 0.5 * disc_inertia(coupling_mass, coupling_diameter) * w**2
    t2 = 0.5 * disc_inertia(motor_pulley_mass, motor_pulley_diameter) * w**2
    t3 = 0.5 * disc_inertia(flywheel_mass, flywheel_diameter) * w3**2
    t4 = 0.5 * disc_inertia(drive_gear_mass, drive_gear_diameter) * w3**2
    t5 = 0.5 * spindle_count * disc_inertia(spindle_gear_mass, spindle_gear_diameter) * w5**2
    return t1, t2, t3, t4, t5


def kinetic_energy(*args: Any) -> Any:
    r"""Kinetic energy of all rotating parts of the drive [000, eq. 3–4].

    .. math::
        T = \frac{1}{16}\left[m_1 D_1^2\omega_1^2 + m_2 D_2^2\omega_2^2
            + m_3 D_3^2\omega_3^2 + m_4 D_4^2\omega_4^2 + z\,m_5 D_5^2\omega_5^2\right]

    Parameters
    ----------
    *args
        As :func:`part_energies` (motor speed, then mass and diameter of
        parts 1…5, then the spindle count).

    Returns
    -------
    T : float
        Kinetic energy, [J]

    Notes
    -----
    The sum of :func:`part_energies`; reconstructed form, see there.

    Examples
    --------
    >>> round(kinetic_energy(100.0, 1, 0.1, 1, 0.1, 8, 0.2, 1, 0.1, 1, 0.1, 2), 4)
    67.1875
    """
    t1, t2, t3, t4, t5 = part_energies(*args)
    return t1 + t2 + t3 + t4 + t5


def equivalent_inertia(
    coupling_inertia: Any,
    motor_pulley_inertia: Any,
    flywheel_inertia: Any,
    drive_gear_inertia: Any,
    spindle_gear_inertia: Any,
    spindle_count: Any,
    belt_ratio: Any,
    gear_ratio: Any,
    rotor_inertia: Any = 0.0,
    belt_efficiency: Any = 1.0,
    gear_efficiency: Any = 1.0,
) -> Any:
    r"""Moment of inertia of the drive referred to the motor shaft.

    .. math::
        J_{eq} = J_r + J_1 + J_2 + \frac{(J_3 + J_4)\, i_b^2}{\eta_b}
            + \frac{z J_5\, i_b^2 u^2}{\eta_b \eta_g},
        \qquad i_b = \frac{D_2}{D_3},\; u = \frac{D_4}{D_5}

    Parameters
    ----------
    coupling_inertia, motor_pulley_inertia, flywheel_inertia : float
        :math:`J_1, J_2, J_3`, [kg*m^2]
    drive_gear_inertia, spindle_gear_inertia : float
        :math:`J_4` and one :math:`J_5`, [kg*m^2]
    spindle_count : int
        :math:`z`, [-]
    belt_ratio : float
        :math:`i_b = \omega_3/\omega = D_2/D_3`, [-]
    gear_ratio : float
        :math:`u = \omega_5/\omega_3 = D_4/D_5`, [-]
    rotor_inertia : float, optional
        Motor rotor :math:`J_r`, [kg*m^2]; the source leaves it out.
    belt_efficiency, gear_efficiency : float, optional
        :math:`\eta_b, \eta_g` while accelerating, [-]; 1 in the source.

    Returns
    -------
    J_eq : float
        Equivalent inertia at the motor shaft, [kg*m^2]

    Notes
    -----
    With :math:`J_r = 0` and :math:`\eta = 1`, :math:`T = J_{eq}\omega^2/2`
    is the energy of [000, eq. 3–4]. Dividing a driven inertia by the
    efficiency of the transmission it is accelerated through is the usual
    reduction of electric-drive dynamics; it is not in the source.

    Examples
    --------
    >>> round(equivalent_inertia(0.001, 0.001, 0.04, 0.001, 0.0001, 4, 0.5, 2.0), 8)
    0.01265
    """
    ib2 = belt_ratio**2
    return (
        rotor_inertia
        + coupling_inertia
        + motor_pulley_inertia
        + (flywheel_inertia + drive_gear_inertia) * ib2 / belt_efficiency
        + spindle_count
        * spindle_gear_inertia
        * ib2
        * gear_ratio**2
        / (belt_efficiency * gear_efficiency)
    )


def acceleration_time(kinetic_energy: Any, motor_power: Any) -> Any:
    r"""Time to spin the drive up from rest at constant motor power [000, eq. 5].

    .. math::
        t = \frac{T}{P}

    Parameters
    ----------
    kinetic_energy : float
        Kinetic energy at the working speed, :math:`T`, [J]
    motor_power : float
        Motor power :math:`P`, [W]

    Returns
    -------
    t : float
        Acceleration time, [s]

    Notes
    -----
    From the work–energy theorem :math:`T_1 - T_0 = A = P t`, :math:`T_0 = 0`
    [000, eq. 1–2]. The printed eq. 5 is garbled; this form follows from the
    theorem and the chain (MODELS.md §1). Constant power from standstill is an
    idealisation (it needs infinite torque at :math:`\omega = 0`); see
    :func:`engine.motor_spinup.spin_up_time` for a real motor.

    Examples
    --------
    >>> acceleration_time(132.0, 1100.0)
    0.12
    """
    return kinetic_energy / motor_power


# ---------------------------------------------------------------------------
# Elastic twist and impact torque [000, eq. 6–10]
# ---------------------------------------------------------------------------


def torsional_stiffness(shear_modulus: Any, diameter: Any, length: Any) -> Any:
    r"""Torsional stiffness of a solid round shaft [000, eq. 9].

    .. math::
        C = \frac{\pi G d^4}{32\, l}

    Parameters
    ----------
    shear_modulus : float
        Shear modulus :math:`G`, [Pa] (8e10 for steel in the source)
    diameter : float
        Shaft diameter :math:`d`, [m]
    length : float
        Twisted length :math:`l`, [m]

    Returns
    -------
    C : float
        Torsional stiffness, [N*m/rad]

    Notes
    -----
    :math:`G I_p / l` with :math:`I_p = \pi d^4/32` [000, eq. 9].

    Examples
    --------
    >>> round(torsional_stiffness(8e10, 0.04, 0.4))
    50265
    """
    return math.pi * shear_modulus * diameter**4 / (32.0 * length)


def impact_torque(kinetic_energy: Any, shaft_stiffness: Any, spindle_stiffness: Any) -> Any:
    r"""Peak torque on a spindle when the drive's energy twists shaft and spindle.

    .. math::
        M = \sqrt{\frac{2 T C_7 C_8}{C_7 + C_8}}

    Parameters
    ----------
    kinetic_energy : float
        Energy of the rotating parts at impact :math:`T`, [J]
    shaft_stiffness : float
        Torsional stiffness of the flywheel shaft 7, :math:`C_7`, [N*m/rad]
    spindle_stiffness : float
        Torsional stiffness of the spindle 8, :math:`C_8`, [N*m/rad]

    Returns
    -------
    M : float
        Impact torque, [N*m]

    Notes
    -----
    Energy conservation :math:`T = M\varphi_7/2 + M\varphi_8/2`
    [000, eq. 7–8; the printed form is illegible, reconstructed in MODELS.md
    §1]. The same torque acts on shaft and spindle, as in the source, which
    ignores the gear ratio between them (see :func:`impact_torque_geared`).
    Socket, nut and joint compliance and all losses are ignored, so this is an
    upper bound valid while both parts stay elastic.

    Examples
    --------
    >>> round(impact_torque(268.5, 57446.0, 25447.0), 1)
    3077.3
    """
    c7, c8 = shaft_stiffness, spindle_stiffness
    return (2.0 * kinetic_energy * c7 * c8 / (c7 + c8)) ** 0.5


def impact_torque_geared(
    kinetic_energy: Any, shaft_stiffness: Any, spindle_stiffness: Any, gear_ratio: Any
) -> Any:
    r"""Peak spindle torque when the shaft carries the gear-ratio multiple of it.

    .. math::
        T = \frac{(uM)^2}{2C_7} + \frac{M^2}{2C_8}
        \;\Rightarrow\;
        M = \sqrt{\frac{2T}{u^2/C_7 + 1/C_8}}

    Parameters
    ----------
    kinetic_energy : float
        :math:`T`, [J]
    shaft_stiffness : float
        :math:`C_7`, [N*m/rad]
    spindle_stiffness : float
        :math:`C_8`, [N*m/rad]
    gear_ratio : float
        :math:`u = D_4/D_5`, [-]; the shaft torque is :math:`uM`.

    Returns
    -------
    M : float
        Impact torque on the spindle, [N*m]

    Notes
    -----
    The energy balance of [000, eq. 7–8] with the torque on shaft 7 equal to
    :math:`u M` (gear 4 drives gear 5; MODELS.md §1 notes). Equals
    :func:`impact_torque` when :math:`u = 1`.

    Examples
    --------
    >>> round(impact_torque_geared(268.5, 57446.0, 25447.0, 1.0), 1)
    3077.3
    >>> round(impact_torque_geared(268.5, 57446.0, 25447.0, 2.0), 1)
    2220.3
    """
    compliance = gear_ratio**2 / shaft_stiffness + 1.0 / spindle_stiffness
    return (2.0 * kinetic_energy / compliance) ** 0.5


def twist_angle(torque: Any, stiffness: Any) -> Any:
    r"""Elastic twist of a shaft under a torque [000, eq. 6].

    .. math::
        \varphi = \frac{M}{C}

    Parameters
    ----------
    torque : float
        Torque :math:`M`, [N*m]
    stiffness : float
        Torsional stiffness :math:`C`, [N*m/rad]

    Returns
    -------
    phi : float
        Twist angle, [rad]

    Notes
    -----
    [000, eq. 6], used for shaft 7 and spindle 8.

    Examples
    --------
    >>> twist_angle(3000.0, 60000.0)
    0.05
    """
    return torque / stiffness


def max_spindle_torque(impact_torque: Any, spindle_count: Any, idle_friction_torque: Any) -> Any:
    r"""Torque left for the nut after the idle spindles' friction clutches [000, eq. 10].

    .. math::
        M_{max} = M - (z - 1) M_{tr}

    Parameters
    ----------
    impact_torque : float
        Impact torque :math:`M`, [N*m]
    spindle_count : int
        Number of spindles :math:`z`, [-]
    idle_friction_torque : float
        Friction-clutch torque of one idle spindle :math:`M_{tr}`, [N*m]

    Returns
    -------
    M_max : float
        Maximum torque on the struck spindle, [N*m]; zero or negative means
        the friction of the idle spindles absorbs the whole blow.

    Notes
    -----
    During a blow the other :math:`z-1` spindles stand still and their
    diaphragm friction clutches slip, each taking :math:`M_{tr}` [000, eq. 10].

    Examples
    --------
    >>> max_spindle_torque(2500.0, 6, 10.0)
    2450.0
    """
    return impact_torque - (spindle_count - 1) * idle_friction_torque


def shaft_shear_stress(torque: Any, diameter: Any) -> Any:
    r"""Peak shear stress in a solid round shaft under torque.

    .. math::
        \tau = \frac{16 M}{\pi d^3}

    Parameters
    ----------
    torque : float
        Torque, [N*m]
    diameter : float
        Shaft diameter, [m]

    Returns
    -------
    tau : float
        Peak shear stress at the surface, [Pa]

    Notes
    -----
    Textbook torsion of a round bar, not in the source; it tells whether the
    elastic model of [000, eq. 6–9] holds (stress below the shear yield).

    Examples
    --------
    >>> round(shaft_shear_stress(1000.0, 0.04) / 1e6, 2)
    79.58
    """
    return 16.0 * torque / (math.pi * diameter**3)


# ---------------------------------------------------------------------------
# The model spec
# ---------------------------------------------------------------------------

_DIAMETER: dict[str, Any] = {"minimum": 1e-4, "maximum": 2.0, "display_unit": "mm"}
_MASS: dict[str, Any] = {"minimum": 0.0, "maximum": 1e3, "display_unit": "kg"}
_RPM = math.pi / 30.0


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
    Param(
        "spindle_count",
        "1",
        "Number of spindles z (one per wheel nut) [000, eq. 4, 10]",
        required=True,
        kind="int",
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
        minimum=0.0,
        exclusive_minimum=True,
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
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        recommended=(0.85, 1.0),
        group="motor curve",
    ),
    Param(
        "gear_efficiency",
        "1",
        "Gear mesh 4–5 efficiency while accelerating (1 = the source's lossless drive)",
        default=1.0,
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        recommended=(0.9, 1.0),
        group="motor curve",
    ),
)

_OUTPUTS: tuple[Output, ...] = (
    Output(
        "kinetic_energy", "J", "Kinetic energy T of parts 1…5 at the working speed [000, eq. 3–4]"
    ),
    Output("acceleration_time", "s", "Spin-up time: T/P [000, eq. 5], or ∫J dω/M(ω) (motor_curve)"),
    Output(
        "shaft_stiffness", "N*m/rad", "Torsional stiffness C7 of the flywheel shaft [000, eq. 9]"
    ),
    Output("spindle_stiffness", "N*m/rad", "Torsional stiffness C8 of a spindle [000, eq. 9]"),
    Output(
        "impact_torque",
        "N*m",
        "Peak torque M on the struck spindle [000, eq. 7–8]; with the gear ratio in the "
        "gear_ratio and motor_curve rungs",
    ),
    Output("max_spindle_torque", "N*m", "M_max = M − (z−1)·M_tr [000, eq. 10]"),
    Output(
        "shaft_twist", "rad", "Twist of shaft 7 during the blow [000, eq. 6]", display_unit="deg"
    ),
    Output(
        "spindle_twist",
        "rad",
        "Twist of spindle 8 during the blow [000, eq. 6]",
        display_unit="deg",
    ),
    Output("shaft_torque", "N*m", "Torque on shaft 7 during the blow: M (source) or u·M (geared)"),
    Output("coupling_energy", "J", "Kinetic energy of coupling 1 [000, eq. 3]"),
    Output("motor_pulley_energy", "J", "Kinetic energy of motor pulley 2 [000, eq. 3]"),
    Output("flywheel_energy", "J", "Kinetic energy of flywheel 3 [000, eq. 3]"),
    Output("drive_gear_energy", "J", "Kinetic energy of drive gear 4 [000, eq. 3]"),
    Output("spindle_gears_energy", "J", "Kinetic energy of all z spindle gears 5 [000, eq. 3]"),
    Output(
        "equivalent_inertia",
        "kg*m^2",
        "Inertia of parts 1…5 referred to the motor shaft, 2T/ω² [000, eq. 3–4]",
    ),
    Output("flywheel_speed", "rad/s", "Flywheel speed ω3 = ω·D2/D3", display_unit="rpm"),
    Output("spindle_gear_speed", "rad/s", "Spindle gear speed ω5 = ω3·D4/D5", display_unit="rpm"),
    Output("gear_ratio", "1", "u = D4/D5, shaft torque over spindle torque"),
    Output(
        "gear_ratio_torque_change",
        "1",
        "Relative change of the impact torque when the gear ratio is taken into account: "
        "M(u)/M(source) − 1",
    ),
    Output(
        "shaft_shear_stress",
        "Pa",
        "Peak shear stress in shaft 7, 16·M7/(π d7³)",
        display_unit="MPa",
    ),
    Output(
        "spindle_shear_stress",
        "Pa",
        "Peak shear stress in spindle 8, 16·M/(π d8³)",
        display_unit="MPa",
    ),
    Output(
        "drive_inertia",
        "kg*m^2",
        "motor_curve: inertia accelerated by the motor at its shaft (rotor, parts 1…5, "
        "divided by the belt and gear efficiencies)",
    ),
    Output(
        "constant_power_time", "s", "motor_curve: the source's constant-power time T/P [000, eq. 5]"
    ),
    Output(
        "time_vs_constant_power",
        "1",
        "motor_curve: spin-up time over the constant-power time, minus 1",
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
    w_s = need("synchronous_speed")
    m_k = need("breakdown_torque")
    w_n = float(x["rated_speed"] if x.get("rated_speed") is not None else x["motor_speed"])
    if not w_n < w_s:
        raise InputOutOfRange(
            f"rated_speed = {w_n:.4g} rad/s must be below synchronous_speed = {w_s:.4g} rad/s "
            "(an induction motor runs with slip)",
            field="rated_speed" if x.get("rated_speed") is not None else "synchronous_speed",
        )
    m_n = float(x["rated_torque"]) if x.get("rated_torque") is not None else x["motor_power"] / w_n
    if not m_k > m_n:
        raise InputOutOfRange(
            f"breakdown_torque = {m_k:.4g} N*m must exceed the rated torque {m_n:.4g} N*m",
            field="breakdown_torque",
        )
    s_k = kloss_breakdown_slip(w_n, w_s, m_k / m_n)
    return MotorCurve(
        kind,
        lambda w: kloss_torque(w, m_k, w_s, s_k),
        w_s,
        torque_below_limit=lambda gap: kloss_slip_torque(gap / w_s, m_k, s_k),
    )


@dataclass(frozen=True)
class _Drive:
    """Everything the closed forms give, for one design (floats or arrays)."""

    energies: tuple[Any, Any, Any, Any, Any]
    energy: Any
    w3: Any
    w5: Any
    u: Any
    c7: Any
    c8: Any
    m_paper: Any
    m_geared: Any


def _drive(x: Mapping[str, Any]) -> _Drive:
    w = x["motor_speed"]
    energies = part_energies(
        w,
        x["coupling_mass"],
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
    energy = energies[0] + energies[1] + energies[2] + energies[3] + energies[4]
    w3 = flywheel_speed(w, x["motor_pulley_diameter"], x["flywheel_diameter"])
    u = x["drive_gear_diameter"] / x["spindle_gear_diameter"]
    g = x["shear_modulus"]
    c7 = torsional_stiffness(g, x["shaft_diameter"], x["shaft_length"])
    c8 = torsional_stiffness(g, x["spindle_diameter"], x["spindle_length"])
    return _Drive(
        energies=energies,
        energy=energy,
        w3=w3,
        w5=w3 * u,
        u=u,
        c7=c7,
        c8=c8,
        m_paper=impact_torque(energy, c7, c8),
        m_geared=impact_torque_geared(energy, c7, c8, u),
    )


def _gear_effect(d: _Drive) -> Any:
    """M(u)/M(source) − 1 = √((1/C7 + 1/C8)/(u²/C7 + 1/C8)) − 1, free of T."""
    return np.sqrt((1.0 / d.c7 + 1.0 / d.c8) / (d.u**2 / d.c7 + 1.0 / d.c8)) - 1.0


def _closed_values(x: Mapping[str, Any], d: _Drive, geared: bool) -> dict[str, Any]:
    m = d.m_geared if geared else d.m_paper
    m7 = d.u * m if geared else m
    t1, t2, t3, t4, t5 = d.energies
    return {
        "kinetic_energy": d.energy,
        "acceleration_time": acceleration_time(d.energy, x["motor_power"]),
        "shaft_stiffness": d.c7,
        "spindle_stiffness": d.c8,
        "impact_torque": m,
        "max_spindle_torque": max_spindle_torque(
            m, x["spindle_count"], x["idle_spindle_friction_torque"]
        ),
        "shaft_twist": twist_angle(m7, d.c7),
        "spindle_twist": twist_angle(m, d.c8),
        "shaft_torque": m7,
        "coupling_energy": t1,
        "motor_pulley_energy": t2,
        "flywheel_energy": t3,
        "drive_gear_energy": t4,
        "spindle_gears_energy": t5,
        "equivalent_inertia": 2.0 * d.energy / x["motor_speed"] ** 2,
        "flywheel_speed": d.w3,
        "spindle_gear_speed": d.w5,
        "gear_ratio": d.u,
        "gear_ratio_torque_change": _gear_effect(d),
        "shaft_shear_stress": shaft_shear_stress(m7, x["shaft_diameter"]),
        "spindle_shear_stress": shaft_shear_stress(m, x["spindle_diameter"]),
    }


def _drive_inertia(x: Mapping[str, Any], d: _Drive) -> float:
    w = x["motor_speed"]
    return float(
        equivalent_inertia(
            disc_inertia(x["coupling_mass"], x["coupling_diameter"]),
            disc_inertia(x["motor_pulley_mass"], x["motor_pulley_diameter"]),
            disc_inertia(x["flywheel_mass"], x["flywheel_diameter"]),
            disc_inertia(x["drive_gear_mass"], x["drive_gear_diameter"]),
            disc_inertia(x["spindle_gear_mass"], x["spindle_gear_diameter"]),
            x["spindle_count"],
            d.w3 / w,
            d.u,
            x["rotor_inertia"],
            x["belt_efficiency"],
            x["gear_efficiency"],
        )
    )


def _curve_time_ratio(x: Mapping[str, Any]) -> float | None:
    """Constant-power time over motor-curve time, minus 1 (None without a curve)."""
    curve = _motor_curve(x)
    if curve is None:
        return None
    d = _drive(x)
    t_curve, _ = spin_up_time(_drive_inertia(x, d), curve, float(x["motor_speed"]), rtol=1e-6)
    return float(acceleration_time(d.energy, x["motor_power"]) / t_curve - 1.0)


def _idealisation_error(x: Mapping[str, Any]) -> float:
    """How far the constant-power time is from the motor curve's (0 without a curve)."""
    try:
        ratio = _curve_time_ratio(x)
    except (InfeasibleDesign, InputOutOfRange):
        return 1.0  # the constant-power time is meaningless if the motor cannot get there
    return 0.0 if ratio is None else abs(ratio)


_FLOOR = 1e-12  # float rounding of the closed forms


def _estimate_closed_form(x: Mapping[str, Any]) -> float:
    """Largest relative change the gear ratio makes to any torque output, either way round.

    Spindle quantities scale with M_paper/M_geared, shaft quantities (torque, twist,
    stress) with M_paper/(u·M_geared), and M_max with the ratio of the torques left
    after the idle spindles' friction (while both stay positive). Each ratio r counts
    as max(|r − 1|, |1/r − 1|), so the estimate bounds the difference whichever rung
    is taken as the reference. With a motor curve, the constant-power idealisation of
    the spin-up time counts too.
    """
    d = _drive(x)
    m_paper, m_geared = float(d.m_paper), float(d.m_geared)
    ratios = [m_paper / m_geared, m_paper / (float(d.u) * m_geared)]
    friction = (x["spindle_count"] - 1) * x["idle_spindle_friction_torque"]
    if min(m_paper, m_geared) > friction:
        ratios.append((m_paper - friction) / (m_geared - friction))
    gear = max(max(abs(r - 1.0), abs(1.0 / r - 1.0)) for r in ratios)
    return max(_FLOOR, gear, _idealisation_error(x))


def _estimate_gear_ratio(x: Mapping[str, Any]) -> float:
    """With a motor curve: the constant-power idealisation; else rounding only."""
    return max(_FLOOR, _idealisation_error(x))


def _estimate_motor_curve(x: Mapping[str, Any]) -> float | None:
    """Quadrature tolerance; None when no motor curve is given."""
    return None if x["motor_curve"] == "none" else 1e-8


def _checks(x: Mapping[str, Any], values: Mapping[str, Any]) -> tuple[list[Check], list[str]]:
    checks: list[Check] = []
    warnings: list[str] = []
    m = float(values["impact_torque"])
    m_max = float(values["max_spindle_torque"])
    z, m_tr = int(x["spindle_count"]), float(x["idle_spindle_friction_torque"])
    if m_max > 0.0:
        checks.append(
            Check(
                "max_spindle_torque_positive",
                True,
                f"the idle spindles' friction takes {(z - 1) * m_tr:.4g} N*m of the "
                f"{m:.4g} N*m blow; {m_max:.4g} N*m reach the nut",
            )
        )
    else:
        detail = (
            f"the friction of the {z - 1} idle spindles, {(z - 1) * m_tr:.4g} N*m, absorbs "
            f"the whole {m:.4g} N*m blow (M_max = {m_max:.4g} N*m): lower the friction-clutch "
            f"torque below {m / max(z - 1, 1):.4g} N*m per spindle, or raise the blow energy"
        )
        checks.append(Check("max_spindle_torque_positive", False, detail))
        warnings.append("no torque reaches the nut: " + detail)
    if z >= 2:
        d4, d5 = float(x["drive_gear_diameter"]), float(x["spindle_gear_diameter"])
        pitch = (d4 + d5) * math.sin(math.pi / z)
        checks.append(
            Check(
                "spindle_gears_fit",
                pitch > d5,
                f"neighbouring spindle gears' centres are {pitch * 1e3:.4g} mm apart on the "
                f"{(d4 + d5) * 1e3:.4g} mm circle; a gear is {d5 * 1e3:.4g} mm across"
                + ("" if pitch > d5 else ": they overlap, use smaller spindle gears or fewer"),
            )
        )
    tau_y = x.get("shear_yield_strength")
    if tau_y is not None:
        for part, key in (("shaft 7", "shaft_shear_stress"), ("spindle 8", "spindle_shear_stress")):
            tau = float(values[key])
            ok = tau <= tau_y
            checks.append(
                Check(
                    f"{key.removesuffix('_shear_stress')}_elastic",
                    ok,
                    f"{part}: peak shear stress {tau / 1e6:.4g} MPa vs yield {tau_y / 1e6:.4g} MPa"
                    + (
                        ""
                        if ok
                        else "; it yields, so the elastic model over-states the torque: "
                        "thicken it or lower the blow energy"
                    ),
                )
            )
    return checks, warnings


def _constant_power_note(x: Mapping[str, Any]) -> str:
    """What the given motor curve says about this rung's constant-power spin-up time."""
    try:
        ratio = _curve_time_ratio(x)
    except (InfeasibleDesign, InputOutOfRange) as exc:
        return f"the motor curve given is not used by this rung, and it fails: {exc.message}"
    assert ratio is not None
    return (
        "this rung assumes constant power from standstill [000, eq. 5]; the "
        f"{x['motor_curve']} motor curve given changes the spin-up time by "
        f"{1.0 / (1.0 + ratio) - 1.0:+.1%} (rung motor_curve)"
    )


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    d = _drive(x)
    geared = ctx.rung != "closed_form"
    values = _closed_values(x, d, geared)
    notes = [
        "eq. 3–5 and 7–8 of the source are illegible; T and t = T/P are reconstructed from "
        "the work–energy theorem and the kinematic chain it names (MODELS.md §1)",
        "the impact torque ignores socket, nut and joint compliance and all losses, as the "
        "source does: an upper bound while shaft and spindle stay elastic",
    ]
    effect = float(values["gear_ratio_torque_change"])
    if ctx.rung == "closed_form":
        notes.append(
            f"as in the source, shaft 7 and spindle 8 carry the same torque; with the gear "
            f"ratio u = D4/D5 = {d.u:.4g} the spindle torque would change by {effect:+.2%} "
            f"and the shaft torque (twist, stress) by {d.u * (1.0 + effect) - 1.0:+.2%} "
            "(rung gear_ratio); the error estimate is the larger change, either way round"
        )
        error: float | None = _estimate_closed_form(x)
    else:
        notes.append(
            f"shaft 7 carries u·M with u = D4/D5 = {d.u:.4g}; this moves the spindle torque by "
            f"{effect:+.2%} from the source's form (which puts M on both)"
        )
        error = _estimate_gear_ratio(x) if ctx.rung == "gear_ratio" else None
    if ctx.rung != "motor_curve" and x["motor_curve"] != "none":
        notes.append(_constant_power_note(x))
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
        j_drive = _drive_inertia(x, d)
        t_curve, abserr = spin_up_time(j_drive, curve, w)
        t_cp = float(values["acceleration_time"])
        error = max(abserr / t_curve, 1e-15)
        values["acceleration_time"] = t_curve
        values["drive_inertia"] = j_drive
        values["constant_power_time"] = t_cp
        values["time_vs_constant_power"] = t_curve / t_cp - 1.0
        notes.append(
            f"spin-up by quadrature of J dω/M(ω) on the {curve.kind} curve: {t_curve:.4g} s, "
            f"{t_curve / t_cp - 1.0:+.1%} against the source's constant-power {t_cp:.4g} s"
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
            f"the motor reaches {w * 30 / math.pi:.0f} rpm in {t_curve:.3g} s; its torque "
            f"there is {m_end:.4g} N*m ({m_end / m_peak:.0%} of its peak on the way)",
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
        values={k: v for k, v in values.items() if ctx.wants(k)},
        rung=ctx.rung,
        error_estimate=error,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=series,
    )


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """Closed forms on arrays (one input varied), for sweeps."""
    arrays = {
        k: (np.asarray(v, dtype=float) if isinstance(v, np.ndarray) else v) for k, v in x.items()
    }
    d = _drive(arrays)
    values = _closed_values(arrays, d, geared=ctx.rung != "closed_form")
    warnings = []
    m_max = np.asarray(values["max_spindle_torque"])
    if np.any(m_max <= 0.0):
        warnings.append(
            f"at {int(np.sum(m_max <= 0.0))} points the idle spindles' friction absorbs the "
            "whole blow (max_spindle_torque ≤ 0)"
        )
    return Result(
        values={k: v for k, v in values.items() if ctx.wants(k)},
        rung=ctx.rung,
        error_estimate=None,
        warnings=warnings,
    )


EXAMPLE_LIGHT_TRUCK: dict[str, Any] = {
    "motor_power": 1100.0,
    "motor_speed": 1400.0 * _RPM,
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
    "synchronous_speed": 1500.0 * _RPM,
    "breakdown_torque": 2.2 * 1100.0 / (1400.0 * _RPM),
    "rotor_inertia": 0.0035,
    "belt_efficiency": 0.95,
    "gear_efficiency": 0.97,
}
"""The same drive on a 1.1 kW 4-pole cage motor (breakdown 2.2× rated), belt and gear losses."""

NUTRUNNER_DRIVE = ModelSpec(
    name="nutrunner.drive",
    path="/nutrunner/drive",
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
        "article, seeds/000), eq. 1–10; MODELS.md §1"
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
            "As closed_form, but shaft 7 carries u·M with u = D4/D5 (MODELS.md §1 notes)",
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
            typical_time="~1 ms",
        ),
    ),
    compute=_compute,
    default_fidelity="closed_form",
    examples=(EXAMPLE_LIGHT_TRUCK, EXAMPLE_INDUCTION_MOTOR),
    vectorized=_vectorized,
    vector_rungs=("closed_form", "gear_ratio"),
)
