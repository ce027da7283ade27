r"""Rare-impact nut wrench with an axially moving striker: one impact in four stages.

A flywheel spins up; centrifugal rollers between two cones push the
half-coupling and the stepped shaft axially against the power and auxiliary
springs (stage 1) until, at the release speed :math:`\omega_M`, the shaft has
moved the release travel :math:`h_1` and frees the striker. The power spring
then throws striker, half-coupling and rollers towards the anvil (stage 2);
the striker must travel the engagement height :math:`h_2` while the flywheel
turns through the anvil's opening :math:`\varphi_{eng}`, or the jaws meet
edge to edge (an *edge blow*, the failure this analysis prevents). After the
blow the return spring brings the striker back (stage 3) and the auxiliary
spring re-locks the shaft (stage 4). Source: [002] (Vodolazskaya and
Iskritsky, "Dynamics of the percussive mechanism of a rare-impact nut wrench
with an axially moving striker"; [003] is a scan of it); see docs/sources.md.

Every function here is a closed form on SI floats (most also accept numpy
arrays, for sweeps), and they are *the paper's* formulas: stage 1 as printed
in [002, eq. 1] (which does not balance virtual power), stage 2 from rest,
stage 3 without the rollers. The model ``impact.rare`` uses them for the
paper's conditions (eq. 5 coefficients, eq. 6, the return and re-lock rules)
and for its ``paper`` variant; its stage 1 comes from a Lagrangian of a stated
roller geometry and its cycle from :mod:`engine.procedures.striker_cycle`, which
also holds the whole-cycle simulation.

What the source leaves open, and what this module does about it
----------------------------------------------------------------
* The release speed is written [002, after eq. 4] for :math:`\alpha = 45°`
  with ``0,5 n m r`` in the denominator and a single travel ``h``; the same
  quasi-static balance of eq. 1 holds for any cone angle and is used here
  (it reduces to the printed form at 45°). ``r`` is the roller centre radius
  at release, ``roller_radius + release_travel / tan(cone_angle)``.
* Eq. 1 carries no weight term for the half-coupling although eqs. 2 and 4
  show gravity acting against the stage-1 travel; as in the source, stage 1
  is weightless here and the result's notes give the size of the omission.
* The paper asks for :math:`c_3 > c_1` and :math:`\lambda_1 < \lambda_3`
  *together with* balanced preloads :math:`c_1\lambda_1 = c_3\lambda_3`
  [002, before eq. 6]; the three cannot hold at once (balance with
  :math:`c_3 > c_1` forces :math:`\lambda_3 < \lambda_1`). Both conditions
  are reported as the paper states them and the check says so.
* The return condition :math:`c_3 = m_3 g/(h - z_3)` [002, after eq. 6] is a
  static balance. A striker starting at rest from the blow position travels
  twice its offset from equilibrium, so it comes back the jaw height only if
  :math:`2(\lambda_3 + h_2 - m_3 g/c_3) \ge h_3`: that exact condition of
  eq. 3 (half-coupling at rest, rollers unloaded, as the paper takes it)
  is what :func:`min_return_spring_rate` returns.
* The release-speed formula assumes the balance at :math:`h_1` is stable.
  With heavy preloads or a small cone angle the stage-1 stiffness is already
  negative at lift-off and the half-coupling snaps straight to :math:`h_1`
  (:func:`released_at_liftoff`); the release speed is then the lift-off
  speed, above the paper's value. The source does not discuss this.
* Stage 2 starts from rest, as eq. 5 does (the half-coupling's stage-1
  velocity at release is neglected).

Reference design
----------------
The paper gives no numbers. The defaults (``REFERENCE_DESIGN``, the spec's
first example) describe a plausible tool for bolts up to M42 (a class the
paper names, e.g. the ИЭ3112): six 50 g rollers on a 40 mm radius, 45° cones,
a 0.02 kg·m² flywheel driven by a constant 5 N·m, 5 mm release travel, 4 mm
engagement height, 120° anvil opening, power/return springs of 50/52 N/mm.
They were chosen so that every condition of the paper holds (the preloads
are therefore not balanced: c1·λ1 = 100 N, c3·λ3 = 109 N); they are an
example to start from, not data from the source. The second example is the
same tool lying horizontally (gravity 0).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..core.errors import InfeasibleDesign
from ..numerics.ode import asin, divide, is_array, pymax, pymin, quiet, sqrt, where

__all__ = [
    "effective_stage1_mass",
    "engagement_window",
    "liftoff_speed",
    "max_striker_travel",
    "min_return_spring_rate",
    "release_radius",
    "release_speed",
    "relock_margin",
    "relock_time",
    "return_time",
    "spin_up_time",
    "spring_height_limit",
    "stage1_mass_at_slope",
    "striker_oscillation",
    "striker_travel",
    "time_to_travel",
]

G0 = 9.80665


# ---------------------------------------------------------------------------
# Stage 1: spin-up and release
# ---------------------------------------------------------------------------


def release_radius(roller_radius: Any, release_travel: Any, cone_angle: Any) -> Any:
    r"""Roller centre radius when the half-coupling has moved the release travel.

    .. math::
        r = x_0 + \frac{h_1}{\tan\alpha}

    Parameters
    ----------
    roller_radius : float
        Roller centre radius at rest :math:`x_0`, [m]
    release_travel : float
        Axial travel of half-coupling and shaft at release :math:`h_1`, [m]
    cone_angle : float
        Cone angle :math:`\alpha` of half-coupling and striker, [rad]

    Notes
    -----
    The cone constraint :math:`z_1 = x_1 \tan\alpha` of [002, eq. 1].

    Examples
    --------
    >>> round(float(release_radius(0.04, 0.004, math.pi / 4)), 6)
    0.044
    """
    return roller_radius + release_travel / np.tan(cone_angle)


def release_speed(
    power_spring_rate: Any,
    power_spring_preload: Any,
    auxiliary_spring_rate: Any,
    auxiliary_spring_preload: Any,
    release_travel: Any,
    roller_mass: Any,
    roller_count: Any,
    roller_radius: Any,
    cone_angle: Any,
) -> Any:
    r"""Flywheel speed at which the rollers have pushed the half-coupling the release travel.

    .. math::
        \omega_M = \sqrt{\frac{2\tan\alpha\,[c_1(\lambda_1 + h_1) + c_2(\lambda_2 + h_1)]}
                              {n\,m_p\,r}},\qquad r = x_0 + h_1/\tan\alpha

    Parameters
    ----------
    power_spring_rate, auxiliary_spring_rate : float
        Rates :math:`c_1, c_2` of the power and auxiliary springs, [N/m]
    power_spring_preload, auxiliary_spring_preload : float
        Their preload deflections :math:`\lambda_1, \lambda_2`, [m]
    release_travel : float
        :math:`h_1`, [m]
    roller_mass : float
        Mass of one roller :math:`m_p`, [kg]
    roller_count : int
        Number of rollers :math:`n`, [-]
    roller_radius : float
        Roller centre radius at rest :math:`x_0`, [m]
    cone_angle : float
        :math:`\alpha`, [rad]

    Returns
    -------
    float
        :math:`\omega_M`, [rad/s]

    Notes
    -----
    Quasi-static balance of [002, eq. 1] at :math:`z_1 = h_1`: with the
    constraint :math:`z_1 = x_1\tan\alpha` the rollers' centrifugal force
    :math:`m_p r\omega^2` pushes axially with :math:`n m_p r \omega^2/(2\tan\alpha)`
    against the springs. At :math:`\alpha = 45°` this is the printed
    :math:`\omega_M = \sqrt{[c_1(\lambda_1+h)+c_2(\lambda_2+h)]/(0.5 n m r)}`
    [002, after eq. 4]. The flywheel's inertia change is neglected, as in the
    source. Relative error against the full stage-1 dynamics: see
    :func:`engine.procedures.striker_cycle.quasi_static_error`.

    Examples
    --------
    45°: [40000·0.006 + 2000·0.009] / (0.5·6·0.05·0.044) = 258 / 0.0066
    = 39090.9, whose root is 197.71 rad/s:

    >>> round(float(release_speed(40000.0, 0.002, 2000.0, 0.005, 0.004, 0.05, 6, 0.04,
    ...                           math.pi / 4)), 2)
    197.71
    """
    r = release_radius(roller_radius, release_travel, cone_angle)
    force = spring_force_at_release(
        power_spring_rate,
        power_spring_preload,
        auxiliary_spring_rate,
        auxiliary_spring_preload,
        release_travel,
    )
    return np.sqrt(2.0 * np.tan(cone_angle) * force / (roller_count * roller_mass * r))


def rotating_inertia(
    flywheel_inertia: Any,
    roller_count: Any,
    roller_mass: Any,
    radius: Any,
    rollers_counted: bool = True,
) -> Any:
    r"""Inertia of the striker's rotating parts: the flywheel and its rollers at ``radius``.

    .. math::
        I = I_M + n\,m_p\,r^2

    Parameters
    ----------
    flywheel_inertia : float or array
        :math:`I_M`, flywheel with half-coupling, shaft and striker, [kg*m^2]
    roller_count : int or array
        :math:`n`, [-]
    roller_mass : float or array
        :math:`m_p`, one roller, [kg]
    radius : float or array
        :math:`r`, the rollers' centre radius, [m]
    rollers_counted : bool
        False for the paper's printed equation, which leaves the rollers out
        (:math:`I = I_M`, broadcast to the shape of ``radius``)

    Notes
    -----
    The rollers turn with the flywheel at their current radius [002, eq. 1]; the paper's
    printed release-speed equation uses :math:`I_M` alone.

    Examples
    --------
    Six rollers of 50 g at 42.5 mm on a 1e-3 kg·m² flywheel: + 6·0.05·0.0425² = 5.41875e-4

    >>> round(rotating_inertia(1e-3, 6, 0.05, 0.0425), 12)
    0.001541875
    >>> rotating_inertia(1e-3, 6, 0.05, 0.0425, rollers_counted=False)
    0.001
    """
    if not rollers_counted:
        return flywheel_inertia + 0.0 * radius
    return flywheel_inertia + roller_count * roller_mass * radius * radius


def spring_force_at_release(c1: Any, lam1: Any, c2: Any, lam2: Any, h1: Any) -> Any:
    r"""Axial force of power and auxiliary springs at release [N].

    .. math::
        F_M = c_1(\lambda_1 + h_1) + c_2(\lambda_2 + h_1)


    [002, eq. 1] at :math:`z_1 = h_1`.

    >>> spring_force_at_release(40000.0, 0.002, 2000.0, 0.005, 0.004)
    258.0
    """
    return c1 * (lam1 + h1) + c2 * (lam2 + h1)


def liftoff_speed(
    c1: Any, lam1: Any, c2: Any, lam2: Any, roller_mass: Any, roller_count: Any,
    roller_radius: Any, cone_angle: Any,
) -> Any:  # fmt: skip
    r"""Flywheel speed at which the rollers' push first beats the spring preloads [rad/s].

    .. math::
        \omega_0 = \sqrt{\frac{2\tan\alpha\,(c_1\lambda_1 + c_2\lambda_2)}{n m_p x_0}}

    Below it the half-coupling rests on its stop (:math:`z_1 = 0`) [002, eq. 1].

    >>> round(float(liftoff_speed(40000.0, 0.002, 2000.0, 0.005, 0.05, 6, 0.04, math.pi / 4)), 2)
    122.47
    """
    preload = c1 * lam1 + c2 * lam2
    return np.sqrt(
        2.0 * np.tan(cone_angle) * preload / (roller_count * roller_mass * roller_radius)
    )


def effective_stage1_mass(
    half_coupling_mass: Any, stepped_shaft_mass: Any, roller_mass: Any, roller_count: Any,
    cone_angle: Any,
) -> Any:  # fmt: skip
    r"""Mass the stage-1 axial equation moves once the roller force N is eliminated [kg].

    .. math::
        m_e = m_1 + m_2 + \frac{n\,m_p}{2\tan^2\alpha}

    Notes
    -----
    From [002, eq. 1]: the roller equation gives
    :math:`2N\sin\alpha = m_p(x\dot\varphi^2 - \ddot x)`, so the axial push is
    :math:`nN\cos\alpha = n m_p (x\dot\varphi^2 - \ddot x)/(2\tan\alpha)`; with
    :math:`\ddot x = \ddot z_1/\tan\alpha` the :math:`\ddot z_1` term moves to the
    left-hand side as :math:`n m_p/(2\tan^2\alpha)`. The rollers' axial inertia
    therefore grows without bound as :math:`\alpha \to 0`.

    >>> round(float(effective_stage1_mass(0.15, 0.05, 0.05, 6, math.pi / 4)), 6)
    0.35
    """
    return stage1_mass_at_slope(
        half_coupling_mass, stepped_shaft_mass, roller_mass, roller_count, np.tan(cone_angle)
    )


def stage1_mass_at_slope(
    half_coupling_mass: Any, stepped_shaft_mass: Any, roller_mass: Any, roller_count: Any,
    tan_cone: Any,
) -> Any:  # fmt: skip
    r""":func:`effective_stage1_mass` from the cone's slope :math:`\tan\alpha` [kg], for a
    caller that has the tangent already (the striker's cycle works it out once a design).

    Parameters
    ----------
    half_coupling_mass : float or ndarray
        Half-coupling mass :math:`m_1`, [kg]
    stepped_shaft_mass : float or ndarray
        Stepped shaft mass :math:`m_2`, [kg]
    roller_mass : float or ndarray
        Mass of one roller :math:`m_p`, [kg]
    roller_count : float or ndarray
        Number of rollers :math:`n`, [-]
    tan_cone : float or ndarray
        Slope of the cone :math:`\tan\alpha`, [-]

    Examples
    --------
    >>> round(float(stage1_mass_at_slope(0.15, 0.05, 0.05, 6, 1.0)), 6)
    0.35
    """
    t = tan_cone
    return half_coupling_mass + stepped_shaft_mass + roller_count * roller_mass / (2.0 * t * t)


def spin_up_time(
    flywheel_inertia: float,
    motor_torque: float,
    speed: float,
    motor_no_load_speed: float | None = None,
) -> float:
    r"""Time for the flywheel to reach ``speed`` from rest [s].

    .. math::
        t = \frac{I_M\,\omega}{M}\ \text{(constant torque)},\qquad
        t = -\tau\ln\!\left(1 - \frac{\omega}{\omega_{nl}}\right),
        \tau = \frac{I_M\,\omega_{nl}}{M}\ \text{(torque falling linearly to 0 at } \omega_{nl})

    Notes
    -----
    :math:`I_M\ddot\varphi = M` [002, eq. 1], the motor torque constant or a
    straight torque-speed line from the stall torque to the no-load speed.
    Raises InfeasibleDesign when the no-load speed does not exceed ``speed``.

    >>> spin_up_time(0.02, 5.0, 200.0)
    0.8
    >>> round(spin_up_time(0.02, 5.0, 200.0, 400.0), 6)  # τ = 1.6 s, ln 2
    1.109035
    """
    if motor_no_load_speed is None:
        return flywheel_inertia * speed / motor_torque
    if speed >= motor_no_load_speed:
        raise InfeasibleDesign(
            f"the motor never reaches the release speed: its no-load speed "
            f"{motor_no_load_speed * 30 / math.pi:.0f} rpm is not above the release speed "
            f"{speed * 30 / math.pi:.0f} rpm; use a faster motor, heavier or more rollers, "
            f"or weaker power/auxiliary springs",
            field="motor_no_load_speed",
        )
    tau = flywheel_inertia * motor_no_load_speed / motor_torque
    return -tau * math.log1p(-speed / motor_no_load_speed)


# ---------------------------------------------------------------------------
# Stage 2: engagement
# ---------------------------------------------------------------------------


def striker_oscillation(
    power_spring_rate: Any,
    power_spring_preload: Any,
    return_spring_rate: Any,
    return_spring_preload: Any,
    release_travel: Any,
    moving_mass: Any,
    gravity: Any = G0,
) -> tuple[Any, Any]:
    r"""Coefficients B and k of the striker's stage-2 motion.

    .. math::
        B = g + \frac{c_1(\lambda_1 + h_1) - c_3\lambda_3}{M_2},\qquad
        k = \sqrt{\frac{c_1 + c_3}{M_2}},\qquad M_2 = m_1 + n m_p + m_3

    Parameters
    ----------
    power_spring_rate, return_spring_rate : float
        :math:`c_1, c_3`, [N/m]
    power_spring_preload, return_spring_preload : float
        :math:`\lambda_1, \lambda_3`, [m]
    release_travel : float
        :math:`h_1`, [m]
    moving_mass : float
        :math:`M_2`, half-coupling, rollers and striker, [kg]
    gravity : float
        Acceleration of gravity along the stroke (0 for a horizontal tool), [m/s²]

    Returns
    -------
    (B [m/s²], k [rad/s])

    Notes
    -----
    [002, eqs. 2 and 5].

    B = 9.80665 + (50000·0.007 − 52000·0.0021)/0.85 = 9.80665 + 240.8/0.85
    = 293.101; k = √(102000/0.85) = √120000 = 346.410:

    >>> B, k = striker_oscillation(50000.0, 0.002, 52000.0, 0.0021, 0.005, 0.85, 9.80665)
    >>> round(float(B), 3), round(float(k), 3)
    (293.101, 346.41)
    """
    b = (
        gravity
        + (
            power_spring_rate * (power_spring_preload + release_travel)
            - return_spring_rate * return_spring_preload
        )
        / moving_mass
    )
    k = sqrt((power_spring_rate + return_spring_rate) / moving_mass)
    return b, k


def striker_travel(t: Any, b: Any, k: Any) -> Any:
    r"""Striker travel in stage 2, :math:`z_2 = (B/k^2)(1 - \cos kt)` [m].

    Computed as :math:`(2B/k^2)\sin^2(kt/2)`, which keeps full precision for
    small :math:`kt` where :math:`1 - \cos kt` cancels [002, eq. 5].

    >>> round(float(striker_travel(1e-9, 293.101, 346.41)) / 1.465505e-16, 12)  # B t²/2
    1.0
    """
    s = np.sin(0.5 * k * t)
    return 2.0 * b / (k * k) * s * s


def max_striker_travel(b: Any, k: Any) -> Any:
    r"""Largest stage-2 travel, :math:`2B/k^2` [m]; 0 when :math:`B \le 0` (the striker stays).

    [002, eq. 5] at :math:`kt = \pi`.

    >>> round(float(max_striker_travel(293.101, 346.41)), 7)  # 2·293.101/120000
    0.004885
    """
    return np.maximum(2.0 * b / (k * k), 0.0)


def time_to_travel(distance: Any, b: Any, k: Any) -> Any:
    r"""First time the stage-2 motion :math:`(B/k^2)(1-\cos kt)` reaches ``distance`` [s].

    .. math::
        t = \frac{1}{k}\arccos\!\left(1 - \frac{h k^2}{B}\right)
          = \frac{2}{k}\arcsin\sqrt{\frac{h k^2}{2B}}

    The arcsine form is used: it has no cancellation for small travels and
    its argument is clipped at 1, so :math:`h = 2B/k^2` gives exactly
    :math:`\pi/k`. Returns ``inf`` when the travel is never reached
    (:math:`B \le 0` or :math:`h > 2B/k^2`) [002, eq. 5].

    q = 0.004·120000/(2·293.101) = 0.818830, 2·asin(√q)/k = 2·1.131123/346.41:

    >>> round(float(time_to_travel(0.004, 293.101, 346.41)), 7)
    0.0065306
    >>> float(time_to_travel(0.005, 293.101, 346.41))  # beyond 2B/k² = 4.885 mm
    inf
    """
    with quiet(is_array(distance, b, k)):
        q = distance * k * k / (2.0 * where(b > 0.0, b, 1.0))
        never = (b <= 0.0) | (q > 1.0 + 1e-12)
        t = divide(2.0, k) * asin(sqrt(pymin(pymax(q, 0.0), 1.0)))
        out = where(never, math.inf, t)
    return out if is_array(out) else float(out)


def engagement_window(engagement_angle: Any, release_speed: Any) -> Any:
    r"""Time the flywheel takes to turn through the anvil's opening [s].

    .. math::
        t_{eng} = \varphi_{eng}/\omega_M


    [002, after eq. 5]. A release speed of 0 gives inf (numpy's quotient, floats too).

    >>> round(engagement_window(math.pi / 2, 197.71), 6)
    0.007945
    >>> engagement_window(math.pi / 2, 0.0)
    inf
    """
    return divide(engagement_angle, release_speed)


def full_engagement(blow: Any, engagement_time: Any, window: Any) -> Any:
    r"""True where the striker strikes and travels the engagement height within the
    window: :math:`t_e \le t_{eng}` [002, after eq. 5].

    Parameters
    ----------
    blow : bool or array of bool
        True where the striker reaches the engagement height (the cycle's blow), [-]
    engagement_time : float or array
        Time the striker takes to travel the engagement height, :math:`t_e`, [s]
    window : float or array
        Time the flywheel takes to turn through the anvil's opening,
        :func:`engagement_window`, :math:`t_{eng}`, [s]

    Examples
    --------
    >>> full_engagement(True, 0.0065, 0.0079), full_engagement(True, 0.0081, 0.0079)
    (True, False)
    >>> full_engagement(False, 0.0065, 0.0079)
    False
    """
    return blow & (engagement_time <= window)


def spring_height_limit(
    moving_mass: Any, gravity: Any, power_spring_rate: Any, return_spring_rate: Any
) -> Any:
    r"""Largest engagement height the springs allow, :math:`h \le 2M_2g/(c_3 - c_1)` [m].

    [002, eq. 6], derived by the paper with balanced preloads
    :math:`c_1\lambda_1 = c_3\lambda_3` and :math:`h_1 = h_2 = h_3 = h`.
    Returns ``inf`` (no limit) when :math:`c_3 \le c_1`: then the power spring
    alone carries the striker past any height. Near :math:`c_3 = c_1` the limit
    grows without bound, which is the physics, not a numerical artefact.

    >>> round(spring_height_limit(0.85, 9.80665, 50000.0, 52000.0), 6)  # 16.671/2000
    0.008336
    >>> spring_height_limit(0.85, 9.80665, 50000.0, 50000.0)
    inf
    """
    d = return_spring_rate - power_spring_rate
    with quiet(is_array(d)):
        out = where(d > 0.0, 2.0 * moving_mass * gravity / where(d > 0.0, d, 1.0), math.inf)
    return out if is_array(out) else float(out)


# ---------------------------------------------------------------------------
# Stages 3 and 4: return and re-locking
# ---------------------------------------------------------------------------


def min_return_spring_rate(
    striker_mass: Any,
    gravity: Any,
    return_spring_preload: Any,
    engagement_height: Any,
    jaw_height: Any,
) -> Any:
    r"""Smallest return-spring rate that brings the striker back out of the jaws [N/m].

    .. math::
        c_{3,\min} = \frac{m_3 g}{\lambda_3 + h_2 - h_3/2}

    Notes
    -----
    [002, eq. 3] with the half-coupling at rest and the rollers unloaded
    (:math:`\dot\varphi = 0`), as the paper takes it:
    :math:`m_3\ddot z_3 = c_3(\lambda_3 + h_2 - z_3) - m_3 g`, from rest, gives
    :math:`z_3 = D(1-\cos k_3 t)` with :math:`D = \lambda_3 + h_2 - m_3g/c_3`;
    the striker clears the jaw height when :math:`2D \ge h_3`. The paper's
    static form :math:`c_3 = m_3 g/(h - z_3)` (at :math:`z_3 = 0`,
    :math:`\lambda_3 = 0`) only asks the spring to hold the weight, which is
    necessary but half of what a return from rest needs. Returns ``inf`` when
    :math:`\lambda_3 + h_2 \le h_3/2` and gravity pulls the striker in (no
    rate is enough), 0 when gravity helps or is absent.

    >>> round(min_return_spring_rate(0.4, 9.80665, 0.0, 0.005, 0.005), 1)  # 2 m g / h
    1569.1
    """
    arm = return_spring_preload + engagement_height - 0.5 * jaw_height
    load = striker_mass * gravity
    with quiet(is_array(arm, load)):
        out = where(load <= 0.0, 0.0, where(arm > 0.0, load / where(arm > 0.0, arm, 1.0), math.inf))
    return out if is_array(out) else float(out)


def return_time(
    striker_mass: Any,
    gravity: Any,
    return_spring_rate: Any,
    return_spring_preload: Any,
    engagement_height: Any,
    jaw_height: Any,
) -> Any:
    r"""Time for the return spring to bring the striker back the jaw height [s] (inf: never).

    Exact solution of [002, eq. 3] with the half-coupling at rest:
    :math:`z_3 = D(1 - \cos k_3t)`, :math:`k_3 = \sqrt{c_3/m_3}`,
    :math:`D = \lambda_3 + h_2 - m_3 g/c_3`, reaching :math:`h_3` at
    :math:`t = (2/k_3)\arcsin\sqrt{h_3/(2D)}`.

    D = 0.0021 + 0.004 − 0.4·9.80665/52000 = 0.0060246 m, k3 = √(52000/0.4)
    = 360.555 rad/s, t = 2·asin(√(0.0035/(2·0.0060246)))/k3:

    >>> round(return_time(0.4, 9.80665, 52000.0, 0.0021, 0.004, 0.0035), 7)
    0.0031574
    """
    k3 = np.sqrt(np.asarray(return_spring_rate / striker_mass, dtype=float))
    d = return_spring_preload + engagement_height - striker_mass * gravity / return_spring_rate
    out = np.asarray(time_to_travel(jaw_height, d * k3 * k3, k3), dtype=float)
    return float(out) if out.ndim == 0 else out


def relock_time(
    stepped_shaft_mass: Any,
    gravity: Any,
    auxiliary_spring_rate: Any,
    auxiliary_spring_preload: Any,
    release_travel: Any,
    friction_force: Any,
) -> Any:
    r"""Time for the auxiliary spring to push the stepped shaft back the release travel [s].

    Exact solution of [002, eq. 4],

    .. math::
        m_2\ddot z_2 = c_2(\lambda_2 + h_1 - z_2) + m_2 g - c_3\lambda_3 f,

    from rest is :math:`z_2 = D_4(1-\cos k_4 t)`, :math:`k_4 = \sqrt{c_2/m_2}`,
    :math:`D_4 = \lambda_2 + h_1 + (m_2 g - c_3\lambda_3 f)/c_2`; inf when it
    never reaches :math:`h_1`. The friction force is taken constant, as in the
    source.

    D4 = 0.008 + 0.005 + (0.05·9.80665 − 10.92)/2000 = 0.0077853 m,
    k4 = √(2000/0.05) = 200 rad/s, t = 2·asin(√(0.005/(2·0.0077853)))/200:

    >>> round(relock_time(0.05, 9.80665, 2000.0, 0.008, 0.005, 10.92), 7)
    0.0060247
    """
    k4 = sqrt(auxiliary_spring_rate / stepped_shaft_mass)
    d = (
        auxiliary_spring_preload
        + release_travel
        + (stepped_shaft_mass * gravity - friction_force) / auxiliary_spring_rate
    )
    return time_to_travel(release_travel, d * k4 * k4, k4)


def relock_margin(
    auxiliary_spring_rate: Any,
    auxiliary_spring_preload: Any,
    stepped_shaft_mass: Any,
    gravity: Any,
    friction_force: Any,
) -> Any:
    r"""Net force that closes the stepped shaft at the end of re-locking [N] (> 0: it relocks).

    .. math::
        c_2\lambda_2 + m_2 g - c_3\lambda_3 f > 0

    the right-hand side of [002, eq. 4] at :math:`z_2 = h_1`, the end of the travel, where
    the auxiliary spring is weakest. [002, after eq. 6] prints the condition without the
    weight, :math:`c_2\lambda_2 > c_3\lambda_3 f`; eq. 4 and :func:`relock_time` carry
    :math:`m_2 g`, and so does this margin.

    Parameters
    ----------
    auxiliary_spring_rate : float or array
        c2, [N/m]
    auxiliary_spring_preload : float or array
        λ2, [m]
    stepped_shaft_mass : float or array
        m2, [kg]
    gravity : float or array
        g along the axis (negative: gravity opposes), [m/s^2]
    friction_force : float or array
        f·c3·λ3, the friction the shaft meets (``relock_friction``), [N]

    Examples
    --------
    2000·0.008 + 0.05·9.80665 − 0.1·52000·0.0021 = 16 + 0.4903325 − 10.92:

    >>> round(relock_margin(2000.0, 0.008, 0.05, 9.80665, 10.92), 7)
    5.5703325
    """
    return (
        auxiliary_spring_rate * auxiliary_spring_preload
        + stepped_shaft_mass * gravity
        - friction_force
    )
