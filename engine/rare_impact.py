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
with an axially moving striker"; [003] is a scan of it), catalogue MODELS.md §3.

Every function here is a closed form on SI floats (most also accept numpy
arrays, for sweeps). The full time simulation is in
:mod:`engine.rare_impact_sim`.

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
from collections.abc import Mapping
from typing import Any

import numpy as np

from .errors import BudgetExceeded, InfeasibleDesign
from .spec import Check, ModelSpec, Output, Param, Result, RunContext, Rung

__all__ = [
    "RARE_IMPACT",
    "effective_stage1_mass",
    "engagement_window",
    "liftoff_speed",
    "max_striker_travel",
    "min_return_spring_rate",
    "quasi_static_release_error",
    "release_radius",
    "release_speed",
    "released_at_liftoff",
    "relock_margin",
    "relock_time",
    "return_time",
    "spin_up_time",
    "spring_height_limit",
    "striker_oscillation",
    "striker_travel",
    "time_to_travel",
]

G0 = 9.80665
#: Factor on the first-order error bound of the quasi-static spin-up (see
#: :func:`quasi_static_release_error`).
SAFETY = 2.0


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
    :func:`quasi_static_release_error`.

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
    t = np.tan(cone_angle)
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


def quasi_static_release_error(x: Mapping[str, Any]) -> tuple[float, float]:
    r"""A-priori relative error of the quasi-static release speed and spin-up time.

    Returns ``(error_in_release_speed, error_in_spin_up_time)``, both relative.

    Derivation
    ----------
    Eliminating N from [002, eq. 1] (see :func:`effective_stage1_mass`) leaves
    a linear oscillator with slowly varying coefficients,

    .. math::
        m_e\ddot z_1 + K(\omega)\,z_1 = A\omega^2 x_0 - F_0,\quad
        A = \frac{n m_p}{2\tan\alpha},\ K = c_1 + c_2 - \frac{A\omega^2}{\tan\alpha},\
        F_0 = c_1\lambda_1 + c_2\lambda_2,

    whose equilibrium :math:`z_e(\omega) = (A\omega^2x_0 - F_0)/K` is the
    quasi-static path (:math:`z_e = h_1` gives :math:`\omega_M`). Writing
    :math:`u = \omega^2`, :math:`dz_e/du = A r/K` and
    :math:`d^2z_e/du^2 = (2A/(K\tan\alpha))\,dz_e/du`. The half-coupling
    leaves its stop at :math:`\omega_0` (:func:`liftoff_speed`) at rest while
    the equilibrium already moves at :math:`\dot z_e`; it then oscillates
    about :math:`z_e` with amplitude
    :math:`a_0 = \dot z_e/\Omega_0 + \ddot z_e/\Omega_0^2`,
    :math:`\Omega = \sqrt{K/m_e}`, which the adiabatic invariant
    :math:`E/\Omega` carries to release as :math:`a_M = a_0\sqrt{\Omega_0/\Omega_M}`,
    plus the inertial lag :math:`\ddot z_e/\Omega_M^2`. A displacement error
    :math:`e` at release moves the crossing by :math:`e/\dot z_e`, i.e. the
    release speed by

    .. math::
        \frac{\delta\omega}{\omega_M} = \frac{e}{\omega_M\,dz_e/d\omega}
            = \frac{e\,K_M}{2F_M},\qquad F_M = c_1(\lambda_1+h_1)+c_2(\lambda_2+h_1),

    and the spin-up time by :math:`\delta\omega/(\dot\omega_M t_M)`. The
    ratio :math:`\dot z_e/(\Omega\,\cdot)` is the flywheel's acceleration
    measured against the roller/half-coupling natural frequency: slow spin-up
    or stiff springs make the closed form exact. The oscillation's phase at
    release is unknown, so this bounds the magnitude; over 448 random designs
    the simulated error reached up to 0.9996 of the first-order bound, so it
    is multiplied by ``SAFETY = 2`` to cover the neglected higher orders (the
    tests check the bound against the simulation, also on random designs).
    """
    c1, c2 = x["power_spring_rate"], x["auxiliary_spring_rate"]
    lam1, lam2 = x["power_spring_preload"], x["auxiliary_spring_preload"]
    h1, n, mp = x["release_travel"], x["roller_count"], x["roller_mass"]
    x0, alpha = x["roller_radius"], x["cone_angle"]
    inertia, torque = x["flywheel_inertia"], x["motor_torque"]
    w_nl = x.get("motor_no_load_speed")
    tan_a = math.tan(alpha)
    a_push = n * mp / (2.0 * tan_a)
    stiff = c1 + c2
    f0 = c1 * lam1 + c2 * lam2
    f_m = spring_force_at_release(c1, lam1, c2, lam2, h1)
    r_m = x0 + h1 / tan_a
    m_e = float(
        effective_stage1_mass(x["half_coupling_mass"], x["stepped_shaft_mass"], mp, n, alpha)
    )
    w_m = math.sqrt(f_m / (a_push * r_m))
    w_0 = math.sqrt(f0 / (a_push * x0))
    if w_0 >= w_m:
        # Snap-through at lift-off (released_at_liftoff): the push at z = 0 grows
        # like 2 A x0 ω0 ω̇ t, so z ≈ (that rate) t³/(6 m_e) reaches h1 after t_s;
        # the flywheel gains ω̇ t_s meanwhile (the negative stiffness only shortens it).
        wd_0 = torque / inertia if w_nl is None else torque / inertia * (1.0 - w_0 / w_nl)
        if wd_0 <= 0.0:
            return math.inf, math.inf
        t_s = (6.0 * h1 * m_e / (2.0 * a_push * x0 * w_0 * wd_0)) ** (1.0 / 3.0)
        dw = SAFETY * wd_0 * t_s / w_0
        t_0 = spin_up_time(inertia, torque, w_0, w_nl)
        return dw, SAFETY * t_s / t_0

    def accel(w: float) -> float:
        return torque / inertia if w_nl is None else torque / inertia * (1.0 - w / w_nl)

    def rates(w: float, r: float) -> tuple[float, float, float]:
        k = stiff - a_push * w * w / tan_a
        dz_du = a_push * r / k
        d2z_du2 = 2.0 * a_push / (k * tan_a) * dz_du
        wd = accel(w)
        wdd = 0.0 if w_nl is None else -torque / inertia / w_nl * wd
        dz_dw = 2.0 * w * dz_du
        d2z_dw2 = 2.0 * dz_du + 4.0 * w * w * d2z_du2
        return k, dz_dw * wd, d2z_dw2 * wd * wd + dz_dw * wdd

    k_0, zd_0, zdd_0 = rates(w_0, x0)
    k_m, _, zdd_m = rates(w_m, r_m)
    om_0, om_m = math.sqrt(k_0 / m_e), math.sqrt(k_m / m_e)
    amp = (abs(zd_0) / om_0 + abs(zdd_0) / om_0**2) * math.sqrt(om_0 / om_m)
    err = amp + abs(zdd_m) / om_m**2
    dw = SAFETY * err * k_m / (2.0 * f_m)
    wd_m = accel(w_m)
    t_m = spin_up_time(inertia, torque, w_m, w_nl)
    dt = dw * w_m / (wd_m * t_m) if wd_m > 0 else math.inf
    return dw, dt


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
    k = np.sqrt((power_spring_rate + return_spring_rate) / moving_mass)
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
    if isinstance(distance, float) and isinstance(b, float) and isinstance(k, float):
        if b <= 0.0:
            return math.inf
        qs = distance * k * k / (2.0 * b)
        if qs > 1.0 + 1e-12:
            return math.inf
        return 2.0 / k * math.asin(math.sqrt(min(max(qs, 0.0), 1.0)))
    b_arr = np.asarray(b, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = np.asarray(distance * k * k / (2.0 * b_arr), dtype=float)
        never = (b_arr <= 0.0) | (q > 1.0 + 1e-12)
        t = 2.0 / k * np.arcsin(np.sqrt(np.clip(q, 0.0, 1.0)))
    out = np.where(never, np.inf, t)
    return float(out) if out.ndim == 0 else out


def engagement_window(engagement_angle: Any, release_speed: Any) -> Any:
    r"""Time the flywheel takes to turn through the anvil's opening [s].

    .. math::
        t_{eng} = \varphi_{eng}/\omega_M


    [002, after eq. 5].

    >>> round(engagement_window(math.pi / 2, 197.71), 6)
    0.007945
    """
    return engagement_angle / release_speed


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
    if all(isinstance(v, float) for v in (moving_mass, gravity, power_spring_rate,
                                          return_spring_rate)):  # fmt: skip
        d = return_spring_rate - power_spring_rate
        return 2.0 * moving_mass * gravity / d if d > 0.0 else math.inf
    diff = np.asarray(return_spring_rate - power_spring_rate, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(
            diff > 0.0, 2.0 * moving_mass * gravity / np.where(diff > 0, diff, 1.0), np.inf
        )
    return float(out) if out.ndim == 0 else out


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
    if all(isinstance(v, float) for v in (striker_mass, gravity, return_spring_preload,
                                          engagement_height, jaw_height)):  # fmt: skip
        arm = return_spring_preload + engagement_height - 0.5 * jaw_height
        load = striker_mass * gravity
        return 0.0 if load <= 0.0 else (load / arm if arm > 0.0 else math.inf)
    lever = np.asarray(return_spring_preload + engagement_height - 0.5 * jaw_height, dtype=float)
    weight = np.asarray(striker_mass * gravity, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(
            weight <= 0.0,
            0.0,
            np.where(lever > 0.0, weight / np.where(lever > 0, lever, 1.0), np.inf),
        )
    return float(out) if out.ndim == 0 else out


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

    Exact solution of [002, eq. 4]:
    :math:`m_2\ddot z_2 = c_2(\lambda_2 + h_1 - z_2) + m_2 g - c_3\lambda_3 f`
    from rest is :math:`z_2 = D_4(1-\cos k_4 t)`, :math:`k_4 = \sqrt{c_2/m_2}`,
    :math:`D_4 = \lambda_2 + h_1 + (m_2 g - c_3\lambda_3 f)/c_2`; inf when it
    never reaches :math:`h_1`. The friction force is taken constant, as in the
    source.

    D4 = 0.008 + 0.005 + (0.05·9.80665 − 10.92)/2000 = 0.0077853 m,
    k4 = √(2000/0.05) = 200 rad/s, t = 2·asin(√(0.005/(2·0.0077853)))/200:

    >>> round(relock_time(0.05, 9.80665, 2000.0, 0.008, 0.005, 10.92), 7)
    0.0060247
    """
    k4 = np.sqrt(np.asarray(auxiliary_spring_rate / stepped_shaft_mass, dtype=float))
    d = (
        auxiliary_spring_preload
        + release_travel
        + (stepped_shaft_mass * gravity - friction_force) / auxiliary_spring_rate
    )
    out = np.asarray(time_to_travel(release_travel, d * k4 * k4, k4), dtype=float)
    return float(out) if out.ndim == 0 else out


def relock_margin(
    auxiliary_spring_rate: Any,
    auxiliary_spring_preload: Any,
    return_spring_rate: Any,
    return_spring_preload: Any,
    roller_friction: Any,
) -> Any:
    r"""Auxiliary spring force at the end of re-locking minus the friction it must beat [N].

    .. math::
        c_2\lambda_2 - c_3\lambda_3 f > 0

    [002, after eq. 6], from eq. 4.

    >>> round(relock_margin(2000.0, 0.008, 52000.0, 0.0021, 0.1), 2)  # 16 − 10.92
    5.08
    """
    return (
        auxiliary_spring_rate * auxiliary_spring_preload
        - return_spring_rate * return_spring_preload * roller_friction
    )


# ---------------------------------------------------------------------------
# The model: inputs, outputs, rungs
# ---------------------------------------------------------------------------

_SIMULATION_ERROR = 1e-6
#: Outputs that need the spin-up (stage 1); the others come from stages 2-4 alone.
_STAGE1_OUTPUTS = (
    "release_speed",
    "spin_up_time",
    "engagement_window",
    "engagement_start",
    "engagement_end",
    "full_engagement",
    "engagement_margin",
    "time",
    "flywheel_speed",
    "z1",
    "z2",
    "z3",
    "z4",
)


def _moving_mass(x: Mapping[str, Any]) -> Any:
    """:math:`M_2 = m_1 + n m_p + m_3` [002, eq. 2]."""
    return x["half_coupling_mass"] + x["roller_count"] * x["roller_mass"] + x["striker_mass"]


def _release_speed_of(x: Mapping[str, Any]) -> Any:
    """Quasi-static release speed, with the snap-through case (see :func:`released_at_liftoff`)."""
    return np.maximum(_paper_release_speed(x), _liftoff_speed_of(x))


def _liftoff_speed_of(x: Mapping[str, Any]) -> Any:
    return liftoff_speed(
        x["power_spring_rate"],
        x["power_spring_preload"],
        x["auxiliary_spring_rate"],
        x["auxiliary_spring_preload"],
        x["roller_mass"],
        x["roller_count"],
        x["roller_radius"],
        x["cone_angle"],
    )


def released_at_liftoff(x: Mapping[str, Any]) -> Any:
    r"""True where the half-coupling snaps straight to :math:`h_1` at the lift-off speed.

    The stage-1 stiffness :math:`K = c_1 + c_2 - n m_p\omega^2/(2	an^2lpha)`
    (:func:`quasi_static_release_error`) is already negative at lift-off when
    :math:`c_1\lambda_1 + c_2\lambda_2 > (c_1 + c_2)\,x_0	anlpha`: then the
    equilibrium at :math:`h_1` that the paper's formula describes is unstable,
    the half-coupling runs away to :math:`h_1` as soon as it lifts off, and
    the release speed is the lift-off speed, above the paper's value. This
    happens with heavy preloads or small cone angles; the source does not
    discuss it.
    """
    preload = (
        x["power_spring_rate"] * x["power_spring_preload"]
        + x["auxiliary_spring_rate"] * x["auxiliary_spring_preload"]
    )
    stiff = x["power_spring_rate"] + x["auxiliary_spring_rate"]
    return preload > stiff * x["roller_radius"] * np.tan(x["cone_angle"])


def _paper_release_speed(x: Mapping[str, Any]) -> Any:
    return release_speed(
        x["power_spring_rate"],
        x["power_spring_preload"],
        x["auxiliary_spring_rate"],
        x["auxiliary_spring_preload"],
        x["release_travel"],
        x["roller_mass"],
        x["roller_count"],
        x["roller_radius"],
        x["cone_angle"],
    )


def _closed_form_estimate(x: Mapping[str, Any]) -> float | None:
    try:
        dw, dt = quasi_static_release_error(x)
    except (ArithmeticError, ValueError):
        return None
    err = max(dw, dt)
    return err if math.isfinite(err) else None


def _closed_form_output_error(x: Mapping[str, Any], ctx: RunContext) -> float | None:
    """Estimated error of the outputs asked for (stage 2-4 outputs alone are exact)."""
    if not ctx.wants(*_STAGE1_OUTPUTS):
        return 0.0
    try:
        dw, dt = quasi_static_release_error(x)
    except (ArithmeticError, ValueError):
        return None
    err = max(dw, dt) if ctx.wants("spin_up_time") else dw
    return err if math.isfinite(err) else None


def _simulation_estimate(x: Mapping[str, Any]) -> float:
    return _SIMULATION_ERROR


def _mm(v: float) -> str:
    return f"{v * 1e3:.3g} mm"


def _nmm(v: float) -> str:
    return f"{v * 1e-3:.4g} N/mm"


def _ms(v: float) -> str:
    return f"{v * 1e3:.3g} ms"


def _rpm(v: float) -> str:
    return f"{v * 30.0 / math.pi:.0f} rpm"


def design_checks(x: Mapping[str, Any], omega_m: float) -> list[Check]:
    """The paper's conditions for this design, each with a sentence a designer can act on.

    c3 > c1 and λ1 < λ3 [002, after eq. 6]; the engagement height the springs
    reach, of which eq. 6 is the balanced-preload special case; the return of
    the striker [002, eq. 3]; re-locking [002, eq. 4]; full engagement inside
    the anvil's opening [002, after eq. 5].
    """
    c1, c2, c3 = x["power_spring_rate"], x["auxiliary_spring_rate"], x["return_spring_rate"]
    lam1, lam2, lam3 = (
        x["power_spring_preload"],
        x["auxiliary_spring_preload"],
        x["return_spring_preload"],
    )
    h1, h2, h3, g = x["release_travel"], x["engagement_height"], x["jaw_height"], x["gravity"]
    m2_total = float(_moving_mass(x))
    b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2_total, g)
    reach = float(max_striker_travel(b, k))
    limit = spring_height_limit(m2_total, g, c1, c3)
    checks: list[Check] = []
    if c3 > c1:
        checks.append(
            Check(
                "c3 > c1",
                True,
                f"the return spring ({_nmm(c3)}) is stiffer than the power spring "
                f"({_nmm(c1)}), as [002, eq. 6] asks",
            )
        )
    else:
        checks.append(
            Check(
                "c3 > c1",
                False,
                f"the return spring ({_nmm(c3)}) is not stiffer than the power spring "
                f"({_nmm(c1)}); the paper asks c3 > c1 [002, eq. 6] (for a vertical tool with "
                "balanced preloads): raise the return-spring rate or soften the power spring",
            )
        )
    balanced = math.isclose(c1 * lam1, c3 * lam3, rel_tol=1e-3)
    contradiction = (
        " Note: with the balanced preloads c1·λ1 = c3·λ3 that the paper assumes for eq. 6, "
        "λ1 < λ3 and c3 > c1 cannot both hold; the source's conditions contradict each other."
    )
    checks.append(
        Check(
            "λ1 < λ3",
            lam1 < lam3,
            (
                f"the power-spring preload ({_mm(lam1)}) is below the return-spring preload "
                f"({_mm(lam3)}), as the paper asks [002, after eq. 6]"
                if lam1 < lam3
                else f"the power-spring preload ({_mm(lam1)}) is not below the return-spring "
                f"preload ({_mm(lam3)}); the paper asks λ1 < λ3 [002, after eq. 6]: lower λ1 "
                "or raise λ3" + (contradiction if balanced else "")
            ),
        )
    )
    limit_text = (
        "eq. 6 sets no limit (c3 ≤ c1)"
        if not math.isfinite(limit)
        else f"eq. 6's balanced-preload limit 2M2g/(c3 − c1) is {_mm(limit)}"
    )
    checks.append(
        Check(
            "eq. 6 (engagement height)",
            reach >= h2,
            (
                f"the springs carry the striker up to 2B/k² = {_mm(reach)} ≥ the engagement "
                f"height {_mm(h2)} [002, eq. 5-6]; {limit_text}"
                if reach >= h2
                else f"the springs carry the striker only 2B/k² = {_mm(reach)}, less than the "
                f"engagement height {_mm(h2)} [002, eq. 5-6]: it can never engage fully. Raise "
                f"the power spring's force at release c1(λ1 + h1), lower the return-spring "
                f"preload c3·λ3 or the engagement height; {limit_text}"
            ),
        )
    )
    c3_min = float(min_return_spring_rate(x["striker_mass"], g, lam3, h2, h3))
    checks.append(
        Check(
            "return",
            c3 >= c3_min,
            (
                f"the return spring ({_nmm(c3)}) brings the striker back out of the jaws "
                f"(needs ≥ {_nmm(c3_min)}) [002, eq. 3]"
                if c3 >= c3_min
                else (
                    f"the return spring ({_nmm(c3)}) cannot bring the striker back the jaw "
                    f"height {_mm(h3)} (needs ≥ {_nmm(c3_min)}) [002, eq. 3]: raise c3 or λ3"
                    if math.isfinite(c3_min)
                    else f"no return-spring rate brings the striker back the jaw height "
                    f"{_mm(h3)} from a preload λ3 = {_mm(lam3)} [002, eq. 3]: raise λ3 or h2"
                )
            ),
        )
    )
    margin = float(relock_margin(c2, lam2, c3, lam3, x["roller_friction"]))
    checks.append(
        Check(
            "relock",
            margin > 0.0,
            (
                f"the auxiliary spring's end force c2·λ2 = {c2 * lam2:.3g} N beats the "
                f"friction c3·λ3·f = {c3 * lam3 * x['roller_friction']:.3g} N by "
                f"{margin:.3g} N [002, eq. 4]"
                if margin > 0.0
                else f"the auxiliary spring's end force c2·λ2 = {c2 * lam2:.3g} N does not beat "
                f"the friction c3·λ3·f = {c3 * lam3 * x['roller_friction']:.3g} N [002, eq. 4]:"
                f" the shaft will not re-lock; raise c2·λ2 by at least {-margin:.3g} N"
            ),
        )
    )
    t_eng = float(time_to_travel(h2, b, k))
    window = float(engagement_window(x["engagement_angle"], omega_m))
    if math.isfinite(t_eng) and t_eng <= window:
        checks.append(
            Check(
                "full engagement",
                True,
                f"the striker travels the engagement height {_mm(h2)} in {_ms(t_eng)}, inside "
                f"the {_ms(window)} the flywheel takes to turn through the anvil's opening "
                f"[002, after eq. 5]",
            )
        )
    elif math.isfinite(t_eng):
        checks.append(
            Check(
                "full engagement",
                False,
                f"edge blow: the striker needs {_ms(t_eng)} to travel {_mm(h2)} but the anvil's "
                f"opening passes in {_ms(window)} at {_rpm(omega_m)} [002, after eq. 5]; make "
                "the power spring stiffer or the moving parts lighter, widen the opening, or "
                "lower the release speed",
            )
        )
    else:
        checks.append(
            Check(
                "full engagement",
                False,
                f"edge blow: the striker never reaches the engagement height {_mm(h2)} (it "
                f"travels at most {_mm(reach)}) [002, eq. 5]; see the eq. 6 check",
            )
        )
    return checks


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    omega_m = float(_release_speed_of(x))
    notes: list[str] = []
    if released_at_liftoff(x):
        notes.append(
            "the preloads c1·λ1 + c2·λ2 exceed (c1 + c2)·x0·tan α: the half-coupling snaps to "
            "h1 as soon as the rollers lift off, so the release speed is the lift-off speed, "
            f"above the paper's formula ({float(_paper_release_speed(x)) * 30 / math.pi:.0f} "
            "rpm), which assumes a stable balance"
        )
    warnings: list[str] = []
    series: dict[str, list[float]] = {}
    w_nl = x["motor_no_load_speed"]
    stage1_needed = ctx.wants(*_STAGE1_OUTPUTS)
    if ctx.rung == "simulation" and not stage1_needed:
        notes.append(
            "simulation: no requested output depends on the spin-up, so stage 1 was not "
            "integrated; stages 2-4 are exact and the checks use the quasi-static release speed"
        )
    sim = None
    if ctx.rung == "simulation" and stage1_needed:
        from .rare_impact_sim import simulate

        try:
            sim = simulate(x, ctx)
        except BudgetExceeded as exc:
            # Too many oscillations to integrate: exactly where the quasi-static closed form
            # is accurate. Run it instead when it meets the simulation's own target.
            estimate = _closed_form_estimate(x)
            if "expected_steps" not in exc.context or estimate is None:
                raise
            if estimate > _SIMULATION_ERROR:
                raise
            ctx = RunContext(
                rung="closed_form",
                outputs=ctx.outputs,
                tolerance=ctx.tolerance,
                deadline=ctx.deadline,
                max_steps=ctx.max_steps,
            )
            notes.append(
                f"simulation: would need about {exc.context['expected_steps']:.2g} steps (the "
                "half-coupling oscillates very fast against the spin-up); ran the closed form "
                f"instead, whose estimated error {estimate:.2g} is within the simulation's "
                f"{_SIMULATION_ERROR:g}; no time series"
            )
    if sim is not None:
        omega_rel, t_spin = sim.release_speed, sim.spin_up_time
        error: float | None = _SIMULATION_ERROR
        notes += sim.notes
        warnings += sim.warnings
        series = sim.series
        durations = sim.stage_durations
    else:
        omega_rel = omega_m
        t_spin = spin_up_time(x["flywheel_inertia"], x["motor_torque"], omega_m, w_nl)
        if ctx.rung == "simulation":
            error = _SIMULATION_ERROR
        else:
            error = _closed_form_output_error(x, ctx)
            angle = (
                ", equal to the paper's 45° form)"
                if math.isclose(x["cone_angle"], math.pi / 4)
                else ")"
            )
            notes.append(
                "closed form: quasi-static spin-up [002, after eq. 4] (general-angle balance"
                + angle
                + (
                    f"; estimated error {error:.2g}"
                    if error is not None
                    else "; its error could not be estimated for these inputs"
                )
            )
        durations = None
    m2_total = float(_moving_mass(x))
    c1, c3 = x["power_spring_rate"], x["return_spring_rate"]
    lam1, lam3 = x["power_spring_preload"], x["return_spring_preload"]
    h1, h2, g = x["release_travel"], x["engagement_height"], x["gravity"]
    b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2_total, g)
    b, k = float(b), float(k)
    t_eng = float(time_to_travel(h2, b, k))
    window = float(engagement_window(x["engagement_angle"], omega_rel))
    values: dict[str, Any] = {
        "release_speed": omega_rel,
        "spin_up_time": t_spin,
        "oscillation_B": b,
        "oscillation_k": k,
        "max_striker_travel": float(max_striker_travel(b, k)),
        "engagement_window": window,
        "engagement_start": t_spin,
        "engagement_end": t_spin + window,
        "full_engagement": bool(t_eng <= window),
        "spring_height_limit": float(spring_height_limit(m2_total, g, c1, c3)),
        "min_return_spring_rate": float(
            min_return_spring_rate(x["striker_mass"], g, lam3, h2, x["jaw_height"])
        ),
        "relock_margin": float(
            relock_margin(
                x["auxiliary_spring_rate"],
                x["auxiliary_spring_preload"],
                c3,
                lam3,
                x["roller_friction"],
            )
        ),
    }
    if math.isfinite(t_eng):
        values["engagement_time"] = t_eng
        values["engagement_margin"] = (window - t_eng) / window
    else:
        values["engagement_time"] = None
        values["engagement_margin"] = None
        notes.append(
            "the striker never reaches the engagement height: engagement_time and "
            "engagement_margin are null (see the eq. 6 and full engagement checks)"
        )
    if not math.isfinite(values["spring_height_limit"]):
        values["spring_height_limit"] = None
        notes.append("spring_height_limit is null: with c3 ≤ c1 eq. 6 sets no limit")
    if ctx.wants("min_return_spring_rate") and g != 0.0:
        notes.append(
            "min_return_spring_rate is the exact condition of [002, eq. 3] for a striker that "
            "starts its return at rest, m3·g/(λ3 + h2 − h3/2); the paper's static "
            "c3 = m3·g/(h − z3) only holds the weight (with λ3 = 0 and h2 = h3 = h it asks "
            "m3·g/h, half the 2·m3·g/h a return from rest needs)"
        )
    if not math.isfinite(values["min_return_spring_rate"]):
        values["min_return_spring_rate"] = None
        notes.append(
            "min_return_spring_rate is null: with λ3 + h2 ≤ h3/2 no rate brings the "
            "striker back the jaw height against its weight"
        )
    if durations is None:
        t_ret = return_time(x["striker_mass"], g, c3, lam3, h2, x["jaw_height"])
        t_lock = relock_time(
            x["stepped_shaft_mass"],
            g,
            x["auxiliary_spring_rate"],
            x["auxiliary_spring_preload"],
            h1,
            c3 * lam3 * x["roller_friction"],
        )
    else:
        t_ret, t_lock = durations[2], durations[3]
    values["return_time"] = t_ret if math.isfinite(t_ret) else None
    values["relock_time"] = t_lock if math.isfinite(t_lock) else None
    if values["return_time"] is None:
        notes.append("return_time is null: the striker does not come back the jaw height")
    if values["relock_time"] is None:
        notes.append("relock_time is null: the stepped shaft does not travel back h1")
    if g != 0.0:
        m12 = x["half_coupling_mass"] + x["stepped_shaft_mass"]
        force = float(
            spring_force_at_release(
                c1, lam1, x["auxiliary_spring_rate"], x["auxiliary_spring_preload"], h1
            )
        )
        notes.append(
            "stage 1 leaves out the weight of half-coupling and shaft, as [002, eq. 1] does "
            "(eqs. 2 and 4 show it acting against the stage-1 travel); counting it would raise "
            f"the release speed by about {50.0 * m12 * g / force:.2g} %"
        )
    checks = design_checks(x, omega_rel)
    return Result(
        values={n: v for n, v in values.items() if ctx.wants(n)},
        rung=ctx.rung,
        error_estimate=error,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series={n: s for n, s in series.items() if ctx.wants(n)},
    )


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """Closed form on arrays (one input varied); NaN where a point cannot be computed."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        omega_m = np.asarray(_release_speed_of(x), dtype=float)
        inertia, torque = x["flywheel_inertia"], x["motor_torque"]
        w_nl = x.get("motor_no_load_speed")
        if w_nl is None:
            t_spin = inertia * omega_m / torque
        else:
            ratio = omega_m / w_nl
            safe = np.where(ratio < 1.0, ratio, 0.0)
            t_spin = np.where(ratio < 1.0, -(inertia * w_nl / torque) * np.log1p(-safe), np.nan)
        m2_total = _moving_mass(x)
        c1, c3 = x["power_spring_rate"], x["return_spring_rate"]
        lam1, lam3 = x["power_spring_preload"], x["return_spring_preload"]
        h1, h2, g = x["release_travel"], x["engagement_height"], x["gravity"]
        b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2_total, g)
        t_eng = np.asarray(time_to_travel(h2, b, k), dtype=float)
        window = x["engagement_angle"] / omega_m
        values: dict[str, Any] = {
            "release_speed": omega_m,
            "spin_up_time": t_spin,
            "oscillation_B": b,
            "oscillation_k": k,
            "max_striker_travel": max_striker_travel(b, k),
            "engagement_time": t_eng,
            "engagement_window": window,
            "engagement_start": t_spin,
            "engagement_end": t_spin + window,
            "full_engagement": t_eng <= window,
            "engagement_margin": (window - t_eng) / window,
            "spring_height_limit": spring_height_limit(m2_total, g, c1, c3),
            "min_return_spring_rate": min_return_spring_rate(
                x["striker_mass"], g, lam3, h2, x["jaw_height"]
            ),
            "relock_margin": relock_margin(
                x["auxiliary_spring_rate"],
                x["auxiliary_spring_preload"],
                c3,
                lam3,
                x["roller_friction"],
            ),
            "return_time": return_time(x["striker_mass"], g, c3, lam3, h2, x["jaw_height"]),
            "relock_time": relock_time(
                x["stepped_shaft_mass"],
                g,
                x["auxiliary_spring_rate"],
                x["auxiliary_spring_preload"],
                h1,
                c3 * lam3 * x["roller_friction"],
            ),
        }
    shape = np.broadcast(*[np.asarray(v) for v in x.values() if v is not None]).shape
    out = {
        n: np.broadcast_to(np.asarray(v, dtype=bool if n == "full_engagement" else float), shape)
        for n, v in values.items()
        if ctx.wants(n)
    }
    if w_nl is not None:
        # where the motor never reaches the release speed the scalar model refuses the whole
        # design (spin_up_time raises InfeasibleDesign): no output of that point stands
        never = np.broadcast_to(np.asarray(omega_m) >= w_nl, shape)
        if never.any():
            refused = np.asarray(None, dtype=object)  # a bool output has no NaN: null it
            out = {
                n: np.where(never, refused if v.dtype == bool else np.nan, v)
                for n, v in out.items()
            }
    values_out: dict[str, Any] = dict(out)
    return Result(values=values_out, rung=ctx.rung, error_estimate=None)


def _positive(name: str, unit: str, description: str, default: float, maximum: float,
              display: str, **kw: Any) -> Param:  # fmt: skip
    return Param(
        name,
        unit,
        description,
        default=default,
        minimum=0.0,
        exclusive_minimum=True,
        maximum=maximum,
        display_unit=display,
        **kw,
    )


def _preload(name: str, description: str, default: float, symbol: str) -> Param:
    return Param(
        name,
        "m",
        description,
        default=default,
        minimum=0.0,
        maximum=0.5,
        display_unit="mm",
        symbol=symbol,
        group="springs",
    )


_INPUTS: tuple[Param, ...] = (
    _positive(
        "flywheel_inertia",
        "kg*m^2",
        "I_M: moment of inertia of the flywheel with half-coupling, shaft and striker [002, eq. 1]",
        0.02,
        100.0,
        "kg*m^2",
        symbol="I_M",
        group="drive",
    ),
    _positive(
        "motor_torque",
        "N*m",
        "M: motor torque on the flywheel (the stall torque when a no-load speed is given) "
        "[002, eq. 1]",
        5.0,
        1e5,
        "N*m",
        symbol="M",
        group="drive",
    ),
    Param(
        "motor_no_load_speed",
        "rad/s",
        "ω_nl: optional; given, the motor torque falls linearly from the stall torque to 0 at "
        "this speed; absent, the torque is constant",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e5,
        display_unit="rpm",
        symbol="ω_nl",
        group="drive",
    ),
    _positive(
        "roller_mass",
        "kg",
        "m_p: mass of one centrifugal roller [002, eq. 1]",
        0.05,
        100.0,
        "g",
        symbol="m_p",
        group="rollers",
    ),
    Param(
        "roller_count",
        "1",
        "n: number of centrifugal rollers [002, eq. 1]",
        default=6,
        kind="int",
        minimum=1,
        maximum=64,
        symbol="n",
        group="rollers",
    ),
    _positive(
        "roller_radius",
        "m",
        "x_0: radius of the rollers' centres at rest [002, eq. 1]",
        0.04,
        2.0,
        "mm",
        symbol="x_0",
        group="rollers",
    ),
    Param(
        "cone_angle",
        "rad",
        "α: angle of the conical faces of half-coupling and striker [002, eq. 1]; the paper's "
        "closed form is for 45°",
        default=math.pi / 4,
        minimum=0.0,
        maximum=math.pi / 2,
        exclusive_minimum=True,
        exclusive_maximum=True,
        recommended=(math.radians(15.0), math.radians(75.0)),
        display_unit="deg",
        symbol="α",
        group="rollers",
    ),
    _positive(
        "half_coupling_mass",
        "kg",
        "m_1: mass of the half-coupling [002, eq. 1]",
        0.15,
        1e3,
        "kg",
        symbol="m_1",
        group="masses",
    ),
    _positive(
        "stepped_shaft_mass",
        "kg",
        "m_2: mass of the stepped central shaft [002, eq. 1]",
        0.05,
        1e3,
        "kg",
        symbol="m_2",
        group="masses",
    ),
    _positive(
        "striker_mass",
        "kg",
        "m_3: mass of the striker [002, eq. 2]",
        0.4,
        1e3,
        "kg",
        symbol="m_3",
        group="masses",
    ),
    _positive(
        "power_spring_rate",
        "N/m",
        "c_1: rate of the power spring [002, eq. 1]",
        50000.0,
        1e9,
        "N/mm",
        symbol="c_1",
        group="springs",
    ),
    _positive(
        "auxiliary_spring_rate",
        "N/m",
        "c_2: rate of the auxiliary spring [002, eq. 1]",
        2000.0,
        1e9,
        "N/mm",
        symbol="c_2",
        group="springs",
    ),
    _positive(
        "return_spring_rate",
        "N/m",
        "c_3: rate of the return spring [002, eq. 2]",
        52000.0,
        1e9,
        "N/mm",
        symbol="c_3",
        group="springs",
    ),
    _preload(
        "power_spring_preload",
        "λ_1: preload deflection of the power spring [002, eq. 1]",
        0.002,
        "λ_1",
    ),
    _preload(
        "auxiliary_spring_preload",
        "λ_2: preload deflection of the auxiliary spring [002, eq. 1]",
        0.008,
        "λ_2",
    ),
    _preload(
        "return_spring_preload",
        "λ_3: preload deflection of the return spring [002, eq. 2]",
        0.0021,
        "λ_3",
    ),
    _positive(
        "release_travel",
        "m",
        "h_1: axial travel of half-coupling and shaft at which the striker is released "
        "[002, eq. 1]",
        0.005,
        0.5,
        "mm",
        symbol="h_1",
        group="geometry",
    ),
    _positive(
        "engagement_height",
        "m",
        "h_2: travel of the striker into full engagement with the anvil [002, eq. 2]",
        0.004,
        0.5,
        "mm",
        symbol="h_2",
        group="geometry",
    ),
    _positive(
        "jaw_height",
        "m",
        "h_3: height of the anvil's jaws, the striker's return travel [002, eq. 3]",
        0.0035,
        0.5,
        "mm",
        symbol="h_3",
        group="geometry",
    ),
    Param(
        "engagement_angle",
        "rad",
        "φ_eng: the anvil's opening, the angle the flywheel turns while the striker must "
        "engage [002, after eq. 5]",
        default=math.radians(120.0),
        minimum=0.0,
        exclusive_minimum=True,
        maximum=2.0 * math.pi,
        display_unit="deg",
        symbol="φ_eng",
        group="geometry",
    ),
    Param(
        "roller_friction",
        "1",
        "f: friction coefficient of the rollers on the cones [002, eq. 4]",
        default=0.1,
        minimum=0.0,
        maximum=1.0,
        symbol="f",
        group="springs",
    ),
    Param(
        "gravity",
        "m/s^2",
        "g: gravity along the stroke towards the anvil [002, eqs. 2-4]; 9.80665 for the "
        "paper's vertical tool, 0 for a horizontal one, negative for a tool pointing up",
        default=G0,
        minimum=-100.0,
        maximum=100.0,
        display_unit="m/s^2",
        symbol="g",
        group="geometry",
    ),
)

_OUTPUTS: tuple[Output, ...] = (
    Output(
        "release_speed",
        "rad/s",
        "ω_M: flywheel speed when the half-coupling reaches h_1 and frees the striker "
        "[002, after eq. 4] (simulation: the first crossing of h_1)",
        display_unit="rpm",
    ),
    Output(
        "spin_up_time",
        "s",
        "time from motor start to release [002, eq. 1]",
        display_unit="ms",
    ),
    Output("oscillation_B", "m/s^2", "B of the striker's stage-2 motion [002, eq. 5]"),
    Output("oscillation_k", "rad/s", "k of the striker's stage-2 motion [002, eq. 5]"),
    Output(
        "max_striker_travel",
        "m",
        "2B/k²: the farthest the springs carry the striker in stage 2 [002, eq. 5]",
        display_unit="mm",
    ),
    Output(
        "engagement_time",
        "s",
        "time for the striker to travel h_2, arccos(1 − h_2k²/B)/k [002, eq. 5]; null if never",
        display_unit="ms",
    ),
    Output(
        "engagement_window",
        "s",
        "φ_eng/ω_M: time the anvil's opening takes to pass [002, after eq. 5]",
        display_unit="ms",
    ),
    Output(
        "engagement_start",
        "s",
        "time from motor start at which the striker is freed and the engagement window "
        "opens (= spin_up_time); with engagement_end it places the window on the time series",
        display_unit="ms",
    ),
    Output(
        "engagement_end",
        "s",
        "time from motor start at which the anvil's opening has passed: "
        "spin_up_time + engagement_window",
        display_unit="ms",
    ),
    Output(
        "full_engagement",
        "1",
        "true when the striker reaches h_2 inside the window (no edge blow)",
        kind="bool",
    ),
    Output(
        "engagement_margin",
        "1",
        "(window − engagement time)/window: the spare fraction of the window; negative means "
        "an edge blow",
    ),
    Output(
        "spring_height_limit",
        "m",
        "2M_2g/(c_3 − c_1): the paper's height limit for balanced preloads [002, eq. 6]; null "
        "when c_3 ≤ c_1 (no limit)",
        display_unit="mm",
    ),
    Output(
        "min_return_spring_rate",
        "N/m",
        "smallest c_3 that brings the striker back the jaw height from rest [002, eq. 3]",
        display_unit="N/mm",
    ),
    Output(
        "relock_margin",
        "N",
        "c_2λ_2 − c_3λ_3f: must be positive for the shaft to re-lock [002, eq. 4]",
    ),
    Output(
        "return_time",
        "s",
        "duration of stage 3, the striker's return over h_3 [002, eq. 3]",
        display_unit="ms",
    ),
    Output(
        "relock_time",
        "s",
        "duration of stage 4, the stepped shaft's travel back over h_1 [002, eq. 4]",
        display_unit="ms",
    ),
    Output("time", "s", "time from motor start (simulation)", series=True, display_unit="ms"),
    Output(
        "flywheel_speed",
        "rad/s",
        "flywheel speed: spin-up, ω_M during engagement, 0 after the blow (simulation)",
        series=True,
        x="time",
        display_unit="rpm",
    ),
    Output(
        "z1",
        "m",
        "z_1: half-coupling travel in stage 1, held at h_1 afterwards (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "z2",
        "m",
        "z_2: striker travel towards the anvil in stage 2, held at h_2 afterwards (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "z3",
        "m",
        "z_3: striker return travel in stage 3, held afterwards (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "z4",
        "m",
        "stepped shaft's return travel in stage 4 (the paper's z_2 of eq. 4) (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
)

REFERENCE_DESIGN: dict[str, Any] = {p.name: p.default for p in _INPUTS if p.default is not None}

HORIZONTAL_DESIGN: dict[str, Any] = {**REFERENCE_DESIGN, "gravity": 0.0}

RARE_IMPACT = ModelSpec(
    name="impact.rare",
    path="/impact/rare",
    title="Rare-impact wrench: striker engagement",
    family="impact",
    summary=(
        "Release speed, spin-up time and whether the axially moving striker engages the "
        "anvil fully (no edge blow), with the paper's spring conditions checked."
    ),
    source=(
        "[002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a "
        "rare-impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. "
        "The paper gives no numeric example: the defaults are a plausible reference design."
    ),
    inputs=_INPUTS,
    outputs=_OUTPUTS,
    rungs=(
        Rung(
            "closed_form",
            "quasi-static spin-up (the paper's release speed, any cone angle) and the exact "
            "stage 2-4 solutions",
            _closed_form_estimate,
            typical_error="1e-3 in release speed (estimated per design from the spin-up rate)",
            typical_time="~60 µs",
        ),
        Rung(
            "simulation",
            "stage 1 integrated in time (flywheel from rest, first crossing of h_1), stages "
            "2-4 exact; time series",
            _simulation_estimate,
            typical_error="≤ 1e-6 (measured ~1e-9 against a tight DOP853 reference)",
            typical_time="~0.3 ms (plus a one-off 1-3 s numba load in a fresh process)",
        ),
    ),
    compute=_compute,
    examples=(REFERENCE_DESIGN, HORIZONTAL_DESIGN),
    vectorized=_vectorized,
    vector_rungs=("closed_form",),
)
