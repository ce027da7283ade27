r"""Drive of a multi-spindle impact nut-runner: spin-up time and impact torque.

Source [000]: the parameters of a multi-spindle wheel-nut runner's drive
(see docs/sources.md and :mod:`engine.core.sources`). A motor 6 (power :math:`P`, shaft speed
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
:mod:`engine.physics.motor_spinup`),
and the :data:`NUTRUNNER_DRIVE` spec that the service serves at
``/nutrunner/drive``.

Where the source is unclear (its eq. 3–5 and 7–8 are illegible or garbled in
the only copy), the reconstruction is described under [000] in docs/sources.md
and is said so in the
docstrings and in each result's notes.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..numerics.ode import sqrt

__all__ = [
    "WHEEL_NUT_TORQUE",
    "acceleration_time",
    "disc_inertia",
    "drive_inertia",
    "equivalent_inertia",
    "flywheel_speed",
    "gear_ratio_torque_change",
    "impact_torque",
    "impact_torque_geared",
    "kinetic_energy",
    "max_spindle_torque",
    "part_energies",
    "rotational_energy",
    "shaft_shear_stress",
    "spindle_gear_spacing",
    "spindle_speed",
    "spindle_torque_reserve",
    "torsional_stiffness",
    "twist_angle",
]

STEEL_SHEAR_MODULUS = 8.0e10
"""Shear modulus of steel the source uses, [Pa] [000, after eq. 9]."""


def _root(value: Any) -> Any:
    """Square root of a value its caller has just computed and owns.

    An array's root is taken in place: a sweep of 10⁶ points then allocates no second
    array for it (a fresh array's pages cost as much as the root itself). Anything else
    goes to :func:`engine.numerics.ode.sqrt` (a float stays a float; NaN below 0).

    >>> _root(np.array([4.0, 2.25])).tolist(), _root(6.25), _root(-1.0)
    ([2.0, 1.5], 2.5, nan)
    """
    if value.__class__ is float:  # one design: no call beyond the root's own
        return math.sqrt(value) if value >= 0.0 else math.nan
    if isinstance(value, np.ndarray) and value.ndim:
        return np.sqrt(value, out=value)
    return sqrt(value)


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
    return mass * (diameter * diameter) / 8.0  # a product, not a power: floats and arrays agree


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
    form follows from the theorem the paper names and its kinematic chain
    (reconstruction described under [000] in docs/sources.md).

    Examples
    --------
    >>> [round(e, 4) for e in part_energies(100.0, 1, 0.1, 1, 0.1, 8, 0.2, 1, 0.1, 1, 0.1, 2)]
    [6.25, 6.25, 50.0, 1.5625, 3.125]
    """
    w = motor_speed
    w3 = flywheel_speed(w, motor_pulley_diameter, flywheel_diameter)
    w5 = spindle_speed(w3, drive_gear_diameter, spindle_gear_diameter)
    return (
        rotational_energy(disc_inertia(coupling_mass, coupling_diameter), w),
        rotational_energy(disc_inertia(motor_pulley_mass, motor_pulley_diameter), w),
        rotational_energy(disc_inertia(flywheel_mass, flywheel_diameter), w3),
        rotational_energy(disc_inertia(drive_gear_mass, drive_gear_diameter), w3),
        rotational_energy(
            spindle_count * disc_inertia(spindle_gear_mass, spindle_gear_diameter), w5
        ),
    )


def rotational_energy(inertia: Any, speed: Any) -> Any:
    r"""Kinetic energy of a body turning about its axis [000, eq. 3].

    .. math::
        T = \tfrac12 J \omega^2

    Parameters
    ----------
    inertia : float
        Moment of inertia :math:`J` about the axis, [kg*m^2]
    speed : float
        Angular speed :math:`\omega`, [rad/s]

    Returns
    -------
    T : float
        Kinetic energy, [J]

    Notes
    -----
    The term of each part in [000, eq. 3]; with the drive's inertia referred to the
    motor shaft (:func:`drive_inertia`) and the motor speed, the whole drive's energy
    [000, eq. 3–4]. Computed as :math:`(J/2)\,(\omega\,\omega)`: on arrays of speeds
    with one inertia, two passes over the points; floats and arrays give the same bits.

    Examples
    --------
    >>> rotational_energy(0.09375, 40.0)  # by hand: 0.09375 * 1600 / 2 = 75
    75.0
    """
    return 0.5 * inertia * (speed * speed)


def drive_inertia(
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
    rotor_inertia: Any = 0.0,
    belt_efficiency: Any = 1.0,
    gear_efficiency: Any = 1.0,
) -> Any:
    r"""Inertia of parts 1…5 referred to the motor shaft, from their masses and diameters.

    .. math::
        J_{eq} = \frac18\left[m_1 D_1^2 + m_2 D_2^2 + (m_3 D_3^2 + m_4 D_4^2)\,i_b^2
            + z\,m_5 D_5^2\,i_b^2 u^2\right],
        \qquad i_b = \frac{D_2}{D_3},\; u = \frac{D_4}{D_5}

    Parameters
    ----------
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
    Parts 1…5 as solid discs (:func:`disc_inertia`) reduced to the motor shaft through
    the belt and gear ratios of the kinematic chain (:func:`equivalent_inertia`), so
    that :math:`T = J_{eq}\omega^2/2` (:func:`rotational_energy`) is the drive's energy
    of [000, eq. 3–4]. A design's fixed parts give one number, whatever the speed.

    Examples
    --------
    >>> # by hand: [1·0.01 + 1·0.01 + (8·0.04 + 1·0.01)·0.25 + 2·1·0.01·0.25·1]/8
    >>> # = 0.1075/8 = 0.0134375
    >>> round(drive_inertia(1, 0.1, 1, 0.1, 8, 0.2, 1, 0.1, 1, 0.1, 2), 12)
    0.0134375
    """
    return equivalent_inertia(
        disc_inertia(coupling_mass, coupling_diameter),
        disc_inertia(motor_pulley_mass, motor_pulley_diameter),
        disc_inertia(flywheel_mass, flywheel_diameter),
        disc_inertia(drive_gear_mass, drive_gear_diameter),
        disc_inertia(spindle_gear_mass, spindle_gear_diameter),
        spindle_count,
        motor_pulley_diameter / flywheel_diameter,
        drive_gear_diameter / spindle_gear_diameter,
        rotor_inertia,
        belt_efficiency,
        gear_efficiency,
    )


def kinetic_energy(
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
) -> Any:
    r"""Kinetic energy of all rotating parts of the drive [000, eq. 3–4].

    .. math::
        T = \frac{1}{16}\left[m_1 D_1^2\omega_1^2 + m_2 D_2^2\omega_2^2
            + m_3 D_3^2\omega_3^2 + m_4 D_4^2\omega_4^2 + z\,m_5 D_5^2\omega_5^2\right]
          = \tfrac12 J_{eq}\,\omega^2

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
    T : float
        Kinetic energy, [J]

    Notes
    -----
    The sum of :func:`part_energies`, taken in the cheaper order: the inertia of parts
    1…5 referred to the motor shaft (:func:`drive_inertia`, one number for a design)
    times :math:`\omega^2/2` (:func:`rotational_energy`); reconstructed form, see
    :func:`part_energies`.

    Examples
    --------
    >>> # by hand: 0.0134375 * 100**2 / 2 = 67.1875, the sum of part_energies
    >>> round(kinetic_energy(100.0, 1, 0.1, 1, 0.1, 8, 0.2, 1, 0.1, 1, 0.1, 2), 10)
    67.1875
    """
    inertia = drive_inertia(
        coupling_mass,
        coupling_diameter,
        motor_pulley_mass,
        motor_pulley_diameter,
        flywheel_mass,
        flywheel_diameter,
        drive_gear_mass,
        drive_gear_diameter,
        spindle_gear_mass,
        spindle_gear_diameter,
        spindle_count,
    )
    return rotational_energy(inertia, motor_speed)


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
    ib2 = belt_ratio * belt_ratio
    return (
        rotor_inertia
        + coupling_inertia
        + motor_pulley_inertia
        + (flywheel_inertia + drive_gear_inertia) * ib2 / belt_efficiency
        + spindle_count
        * spindle_gear_inertia
        * ib2
        * (gear_ratio * gear_ratio)
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
    theorem and the chain (reconstruction: [000] in docs/sources.md).
    Constant power from standstill is an idealisation (it needs infinite
    torque at :math:`\omega = 0`); see
    :func:`engine.physics.motor_spinup.spin_up_time` for a real motor.

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
    # d⁴ as (d·d)², not a power: floats and arrays then give the same bits
    d_sq = diameter * diameter
    return math.pi * shear_modulus * (d_sq * d_sq) / (32.0 * length)


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
    [000, eq. 7–8; the printed form is illegible, reconstructed as described
    under [000] in docs/sources.md]. The same torque acts on shaft and
    spindle, as in the source, which ignores the gear ratio between them
    (see :func:`impact_torque_geared`).
    Socket, nut and joint compliance and all losses are ignored, so this is an
    upper bound valid while both parts stay elastic.

    Examples
    --------
    >>> round(impact_torque(268.5, 57446.0, 25447.0), 1)
    3077.3
    """
    c7, c8 = shaft_stiffness, spindle_stiffness
    # the stiffnesses' factor first: one number for a design's fixed shaft and spindle
    return _root(kinetic_energy * (2.0 * c7 * c8 / (c7 + c8)))


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
    :math:`u M` (gear 4 drives gear 5, which the source ignores). Equals
    :func:`impact_torque` when :math:`u = 1`.

    Examples
    --------
    >>> round(impact_torque_geared(268.5, 57446.0, 25447.0, 1.0), 1)
    3077.3
    >>> round(impact_torque_geared(268.5, 57446.0, 25447.0, 2.0), 1)
    2220.3
    """
    compliance = gear_ratio * gear_ratio / shaft_stiffness + 1.0 / spindle_stiffness
    return _root(kinetic_energy * (2.0 / compliance))


def gear_ratio_torque_change(shaft_stiffness: Any, spindle_stiffness: Any, gear_ratio: Any) -> Any:
    r"""Relative change of the impact torque when the gear ratio is taken into account.

    .. math::
        \frac{M(u)}{M(1)} - 1
        = \sqrt{\frac{1/C_7 + 1/C_8}{u^2/C_7 + 1/C_8}} - 1

    Parameters
    ----------
    shaft_stiffness : float
        :math:`C_7`, [N*m/rad]
    spindle_stiffness : float
        :math:`C_8`, [N*m/rad]
    gear_ratio : float
        :math:`u = D_4/D_5`, [-]

    Returns
    -------
    change : float
        :math:`M(u)/M(1) - 1`, [-]; 0 when :math:`u = 1`.

    Notes
    -----
    The ratio of :func:`impact_torque_geared` at :math:`u` to the source's
    torque (:math:`u = 1`) [000, eq. 7–8], taken at unit energy: the energy
    cancels, so the change is defined whatever the energy. All arguments may
    be floats or numpy arrays.

    Examples
    --------
    >>> # by hand: sqrt((1/57446 + 1/25447) / (4/57446 + 1/25447)) - 1 = -0.278489
    >>> round(gear_ratio_torque_change(57446.0, 25447.0, 2.0), 5)
    -0.27849
    >>> gear_ratio_torque_change(57446.0, 25447.0, 1.0)
    0.0
    """
    geared = impact_torque_geared(1.0, shaft_stiffness, spindle_stiffness, gear_ratio)
    return geared / impact_torque_geared(1.0, shaft_stiffness, spindle_stiffness, 1.0) - 1.0


def spindle_gear_spacing(
    drive_gear_diameter: Any, spindle_gear_diameter: Any, spindle_count: Any
) -> Any:
    r"""Distance between the centres of neighbouring spindle gears around the drive gear.

    .. math::
        s = (D_4 + D_5) \sin\frac{\pi}{z}

    Parameters
    ----------
    drive_gear_diameter : float
        Pitch diameter of the drive gear 4, :math:`D_4`, [m]
    spindle_gear_diameter : float
        Pitch diameter of a spindle gear 5, :math:`D_5`, [m]
    spindle_count : int
        Number of spindles :math:`z`, [-]; meaningful for :math:`z \ge 2`.

    Returns
    -------
    s : float
        Chord between neighbouring gear centres, [m]; the gears overlap
        unless :math:`s > D_5`.

    Notes
    -----
    The :math:`z` spindle gears mesh with gear 4, so their centres lie on a
    circle of diameter :math:`D_4 + D_5`, evenly spaced [000, fig. 1];
    geometry, not in the source's equations. Floats or numpy arrays.

    Examples
    --------
    >>> round(float(spindle_gear_spacing(0.10, 0.05, 6)), 12)
    0.075
    """
    return (drive_gear_diameter + spindle_gear_diameter) * np.sin(np.pi / spindle_count)


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


#: The wheel nut's torque when none is given [N*m]: a truck's M20×1.5 wheel nut (the
#: project's reference case, blow.joint's nut-runner example); [000] gives none, it says the
#: torques are set for each make of vehicle.
WHEEL_NUT_TORQUE = 600.0


def spindle_torque_reserve(max_spindle_torque: Any, wheel_nut_torque: Any) -> Any:
    r"""How many times the torque reaching the nut covers the torque the wheel nut needs.

    .. math::
        k = \frac{M_{max}}{M_{nut}}

    Parameters
    ----------
    max_spindle_torque : float or numpy array
        M_max on the struck spindle [000, eq. 10], [N*m]
    wheel_nut_torque : float or numpy array
        M_nut, the torque the wheel nut needs: its tightening torque, or the larger
        torque that breaks it loose, [N*m]

    Returns
    -------
    float or numpy array
        k, [-]; k ≥ 1: the blow tightens (or frees) the nut

    Notes
    -----
    [000], statement of the problem: the spindle torque is the drive's main parameter; it
    must free the wheel nut from its tightening when unscrewing and give the tightening
    torque the nut needs when screwing on; both are set for each make of vehicle.

    Examples
    --------
    >>> spindle_torque_reserve(2450.0, 600.0)
    4.083333333333333
    """
    return max_spindle_torque / wheel_nut_torque


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
    return 16.0 * torque / (math.pi * (diameter * diameter * diameter))  # the same bits on arrays
