r"""Spin-up of an inertia by an electric motor: torque–speed curves and quadrature.

Not in the source [000]: its eq. 5 assumes constant power from standstill,
which needs infinite torque at zero speed. A real motor has a torque–speed
curve :math:`M(\omega)`; the rigid drive obeys :math:`J\,d\omega/dt =
M(\omega)`, which separates, so the spin-up time is a single quadrature
:math:`t = \int_0^\omega J\,d\omega'/M(\omega')`, the higher-fidelity variant of [000, eq. 5].
Curves offered: a straight line (stall torque, no-load speed), an induction
motor by the simplified Kloss formula, and constant power above a torque
limit (the honest version of the source's idealisation). Closed forms of the
integral for each are here too, to check the quadrature.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.errors import InfeasibleDesign, SolverFailed
from ..numerics.lazy import LazyModule

#: scipy, imported on first use (engine.numerics.lazy): it weighs on the service's start-up
integrate = LazyModule("scipy.integrate")

__all__ = [
    "MotorCurve",
    "kloss_breakdown_slip",
    "kloss_slip_torque",
    "kloss_spin_up_time",
    "kloss_torque",
    "linear_motor_torque",
    "linear_spin_up_time",
    "spin_up_profile",
    "spin_up_time",
    "torque_limited_constant_power_spin_up_time",
]


def linear_motor_torque(speed: Any, stall_torque: float, no_load_speed: float) -> Any:
    r"""Torque of a motor with a straight torque–speed line (DC, universal, linearised).

    .. math::
        M(\omega) = M_{st}\left(1 - \frac{\omega}{\omega_0}\right)

    Parameters
    ----------
    speed : float
        Shaft speed :math:`\omega`, [rad/s]
    stall_torque : float
        Torque at standstill :math:`M_{st}`, [N*m]
    no_load_speed : float
        Speed at zero torque :math:`\omega_0`, [rad/s]

    Returns
    -------
    M : float
        Motor torque, [N*m]

    Examples
    --------
    >>> linear_motor_torque(50.0, 20.0, 200.0)
    15.0
    """
    return stall_torque * (1.0 - speed / no_load_speed)


def kloss_breakdown_slip(rated_speed: Any, synchronous_speed: Any, overload_ratio: Any) -> Any:
    r"""Breakdown (critical) slip of an induction motor from its catalogue data.

    .. math::
        s_n = 1 - \frac{\omega_n}{\omega_s}, \qquad
        s_k = s_n\left(\lambda + \sqrt{\lambda^2 - 1}\right),
        \qquad \lambda = \frac{M_k}{M_n}

    All arguments may be floats or numpy arrays of one shape.

    Parameters
    ----------
    rated_speed : float
        Rated speed :math:`\omega_n`, [rad/s]
    synchronous_speed : float
        Synchronous speed :math:`\omega_s`, [rad/s]
    overload_ratio : float
        Breakdown over rated torque :math:`\lambda > 1`, [-]

    Returns
    -------
    s_k : float
        Breakdown slip, [-]

    Notes
    -----
    The simplified Kloss formula (stator resistance neglected), solved for
    :math:`s_k` at the rated point.

    Examples
    --------
    >>> round(float(kloss_breakdown_slip(1400.0, 1500.0, 2.5)), 4)
    0.3194
    """
    s_n = 1.0 - rated_speed / synchronous_speed
    return s_n * (overload_ratio + np.sqrt(overload_ratio**2 - 1.0))


def kloss_slip_torque(slip: Any, breakdown_torque: float, breakdown_slip: float) -> Any:
    r"""Torque of an induction motor at a given slip, simplified Kloss formula.

    .. math::
        M(s) = \frac{2 M_k}{s/s_k + s_k/s} = \frac{2 M_k s s_k}{s^2 + s_k^2}

    Parameters
    ----------
    slip : float
        Slip :math:`s = 1 - \omega/\omega_s`, [-]
    breakdown_torque : float
        Maximum (pull-out) torque :math:`M_k`, [N*m]
    breakdown_slip : float
        Slip at maximum torque :math:`s_k`, [-]

    Returns
    -------
    M : float
        Motor torque, [N*m]

    Examples
    --------
    >>> kloss_slip_torque(0.3, 20.0, 0.3)
    20.0
    """
    return 2.0 * breakdown_torque * slip * breakdown_slip / (slip**2 + breakdown_slip**2)


def kloss_torque(
    speed: Any, breakdown_torque: float, synchronous_speed: float, breakdown_slip: float
) -> Any:
    r"""Torque of an induction motor by the simplified Kloss formula.

    .. math::
        M(s) = \frac{2 M_k}{s/s_k + s_k/s}, \qquad s = 1 - \frac{\omega}{\omega_s}

    Parameters
    ----------
    speed : float
        Shaft speed :math:`\omega`, [rad/s]
    breakdown_torque : float
        Maximum (pull-out) torque :math:`M_k`, [N*m]
    synchronous_speed : float
        Synchronous speed :math:`\omega_s`, [rad/s]
    breakdown_slip : float
        Slip at maximum torque :math:`s_k`, [-]

    Returns
    -------
    M : float
        Motor torque, [N*m]

    Notes
    -----
    Neglects stator resistance and skin effect; for cage motors it
    under-estimates the starting torque (often by 20–40 %), so spin-up
    times from it are on the long side.

    Examples
    --------
    >>> round(kloss_torque(0.0, 20.0, 157.0, 1.0), 6)
    20.0
    """
    return kloss_slip_torque(1.0 - speed / synchronous_speed, breakdown_torque, breakdown_slip)


def linear_spin_up_time(
    equivalent_inertia: Any, stall_torque: Any, no_load_speed: Any, speed: Any
) -> Any:
    r"""Closed-form spin-up time of an inertia on a linear torque–speed line.

    .. math::
        t = \int_0^{\omega} \frac{J\,d\omega'}{M_{st}(1 - \omega'/\omega_0)}
          = \frac{J\omega_0}{M_{st}}\ln\frac{\omega_0}{\omega_0 - \omega}

    All arguments may be floats or numpy arrays of one shape.

    Parameters
    ----------
    equivalent_inertia : float
        :math:`J` at the motor shaft, [kg*m^2]
    stall_torque : float
        :math:`M_{st}`, [N*m]
    no_load_speed : float
        :math:`\omega_0 > \omega`, [rad/s]
    speed : float
        Speed to reach :math:`\omega`, [rad/s]

    Returns
    -------
    t : float
        Spin-up time, [s]

    Examples
    --------
    >>> round(float(linear_spin_up_time(0.01, 10.0, 200.0, 100.0)), 6)
    0.138629
    """
    return equivalent_inertia * no_load_speed / stall_torque * -np.log1p(-speed / no_load_speed)


def kloss_spin_up_time(
    equivalent_inertia: Any,
    breakdown_torque: Any,
    synchronous_speed: Any,
    breakdown_slip: Any,
    speed: Any,
) -> Any:
    r"""Closed-form spin-up time of an inertia on the Kloss curve.

    .. math::
        t = \frac{J\omega_s}{2M_k}\left[\frac{1 - s_e^2}{2 s_k} + s_k\ln\frac{1}{s_e}\right],
        \qquad s_e = 1 - \frac{\omega}{\omega_s}

    All arguments may be floats or numpy arrays of one shape.

    Parameters
    ----------
    equivalent_inertia : float
        :math:`J` at the motor shaft, [kg*m^2]
    breakdown_torque : float
        :math:`M_k`, [N*m]
    synchronous_speed : float
        :math:`\omega_s > \omega`, [rad/s]
    breakdown_slip : float
        :math:`s_k`, [-]
    speed : float
        Speed to reach :math:`\omega`, [rad/s]

    Returns
    -------
    t : float
        Spin-up time, [s]

    Notes
    -----
    :math:`\int J\,d\omega/M` with :math:`d\omega = -\omega_s ds`; used to
    check the quadrature of :func:`spin_up_time`.

    Examples
    --------
    >>> round(float(kloss_spin_up_time(0.05, 20.0, 157.08, 0.3, 146.6)), 4)
    0.4853
    """
    s_e = 1.0 - speed / synchronous_speed
    return (
        equivalent_inertia
        * synchronous_speed
        / (2.0 * breakdown_torque)
        * ((1.0 - s_e**2) / (2.0 * breakdown_slip) - breakdown_slip * np.log(s_e))
    )


def torque_limited_constant_power_spin_up_time(
    equivalent_inertia: Any, motor_power: Any, torque_limit: Any, speed: Any
) -> Any:
    r"""Spin-up time of a motor giving constant power above a torque limit.

    .. math::
        M(\omega) = \min(M_c, P/\omega),\quad \omega_c = P/M_c:\qquad
        t = \frac{J\omega^2}{2P}\left[1 + \left(\frac{\omega_c}{\omega}\right)^2\right]
        \quad (\omega \ge \omega_c)

    All arguments may be floats or numpy arrays of one shape.

    Parameters
    ----------
    equivalent_inertia : float
        :math:`J`, [kg*m^2]
    motor_power : float
        :math:`P`, [W]
    torque_limit : float
        :math:`M_c`, [N*m]
    speed : float
        Speed to reach :math:`\omega`, [rad/s]

    Returns
    -------
    t : float
        Spin-up time, [s]

    Notes
    -----
    The honest version of the source's constant power from standstill
    [000, eq. 5]: it exceeds :math:`T/P` by exactly
    :math:`(\omega_c/\omega)^2`, which vanishes as the torque limit grows.
    Below :math:`\omega_c` the time is :math:`J\omega/M_c`.

    Examples
    --------
    >>> round(float(torque_limited_constant_power_spin_up_time(0.01, 1000.0, 100.0, 100.0)), 6)
    0.0505
    """
    w_c = motor_power / torque_limit
    t = np.where(
        speed <= w_c,
        equivalent_inertia * speed / torque_limit,
        equivalent_inertia * (speed**2 + w_c**2) / (2.0 * motor_power),
    )
    return float(t) if t.ndim == 0 else t


@dataclass(frozen=True)
class MotorCurve:
    """A motor torque–speed curve for :func:`spin_up_time`.

    ``torque(ω)`` in N·m for ω in rad/s (numpy-vectorised); ``limit_speed`` is
    the speed where the torque falls to zero (None if it never does);
    ``kinks`` are speeds where the curve has a corner. ``torque_below_limit(g)``
    optionally gives the torque at ``limit_speed - g`` computed from the gap
    ``g`` itself, free of the cancellation in ``1 - ω/ω0`` close to the limit.
    """

    kind: str
    torque: Callable[[Any], Any]
    limit_speed: float | None = None
    kinks: tuple[float, ...] = ()
    torque_below_limit: Callable[[Any], Any] | None = None

    def torque_at_gap(self, gap: Any) -> Any:
        """Torque at ``limit_speed - gap``, [N*m]."""
        assert self.limit_speed is not None
        if self.torque_below_limit is not None:
            return self.torque_below_limit(gap)
        return self.torque(self.limit_speed - gap)


def spin_up_time(
    equivalent_inertia: float, curve: MotorCurve, speed: float, *, rtol: float = 1e-10
) -> tuple[float, float]:
    r"""Time for a motor to spin an inertia up to ``speed``, by adaptive quadrature.

    .. math::
        t = \int_0^{\omega} \frac{J_{eq}\,d\omega'}{M(\omega')}

    Parameters
    ----------
    equivalent_inertia : float
        :math:`J_{eq}` at the motor shaft, [kg*m^2]
    curve : MotorCurve
        The motor's torque–speed curve, [N*m] against [rad/s]
    speed : float
        Speed to reach, [rad/s]
    rtol : float, optional
        Relative tolerance asked of the quadrature, [-]

    Returns
    -------
    t : float
        Spin-up time, [s]
    abserr : float
        Absolute error estimate of the quadrature, [s]

    Raises
    ------
    InfeasibleDesign
        When the torque is zero or negative somewhere on the way (the motor
        never reaches ``speed``).
    SolverFailed
        When QUADPACK warns and its error estimate exceeds 1e-6 of the time
        (a curve without ``torque_below_limit`` evaluated within ~1e-10 of
        its limit speed, say).

    Notes
    -----
    :math:`J\,d\omega/dt = M(\omega)` separates, so the time is a single
    quadrature (``scipy.integrate.quad``, QUADPACK) rather than an ODE.
    Where the torque falls to zero at :math:`\omega_0` (no-load or
    synchronous speed) the integrand grows like :math:`1/(\omega_0-\omega)`;
    the substitution :math:`\omega = \omega_0(1 - e^{-x})`,
    :math:`d\omega = (\omega_0 - \omega)\,dx` turns it into the bounded
    :math:`J(\omega_0-\omega)/M(\omega)` on a finite interval
    :math:`[0, -\ln(1-\omega/\omega_0)]`, so working speeds close to
    :math:`\omega_0` stay accurate. Not in the source, whose eq. 5 assumes
    constant power from standstill.

    Examples
    --------
    >>> curve = MotorCurve("linear", lambda w: linear_motor_torque(w, 10.0, 200.0), 200.0)
    >>> t, err = spin_up_time(0.01, curve, 100.0)
    >>> round(t, 6), err < 1e-12
    (0.138629, True)
    """
    _check_reaches(curve, speed)
    j = equivalent_inertia
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", integrate.IntegrationWarning)
        if curve.limit_speed is not None:
            w0 = curve.limit_speed
            x_end = -math.log1p(-speed / w0)

            def integrand_x(x: float) -> float:
                gap = w0 * math.exp(-x)
                return float(j * gap / curve.torque_at_gap(gap))

            t, err = integrate.quad(integrand_x, 0.0, x_end, epsabs=0.0, epsrel=rtol, limit=200)
        else:
            points = [k for k in curve.kinks if 0.0 < k < speed] or None

            def integrand_w(w: float) -> float:
                return float(j / curve.torque(w))

            t, err = integrate.quad(
                integrand_w, 0.0, speed, epsabs=0.0, epsrel=rtol, limit=200, points=points
            )
    if not (math.isfinite(t) and math.isfinite(err)) or (caught and err > 1e-6 * abs(t)):
        why = str(caught[0].message).split("\n")[0] if caught else "non-finite result"
        raise SolverFailed(
            f"the spin-up quadrature did not converge ({why}); "
            f"t ≈ {t:.4g} s with error {err:.2g} s",
            field="motor_curve",
        )
    return float(t), float(err)


def spin_up_profile(
    equivalent_inertia: float, curve: MotorCurve, speed: float, points: int = 101
) -> tuple[np.ndarray, np.ndarray]:
    """Motor speed against time during spin-up, for a plot.

    Cumulative 8-point Gauss–Legendre over ``points - 1`` sub-intervals (in
    the substituted variable of :func:`spin_up_time` where the torque falls
    to zero; the curve's kinks are added as grid points). Returns
    ``(time [s], motor speed [rad/s])``, both starting at 0.

    Parameters
    ----------
    equivalent_inertia : float
        Inertia of the drive referred to the motor shaft, [kg*m^2]
    curve : MotorCurve
        The motor's torque–speed curve
    speed : float
        Motor speed to reach, [rad/s]
    points : int
        Points of the profile, [-]

    Examples
    --------
    >>> curve = MotorCurve("linear", lambda w: linear_motor_torque(w, 10.0, 200.0), 200.0)
    >>> t, w = spin_up_profile(0.01, curve, 100.0, points=5)
    >>> round(float(t[-1]), 6), float(w[-1])
    (0.138629, 100.0)
    """
    _check_reaches(curve, speed)
    nodes, weights = np.polynomial.legendre.leggauss(8)
    j = equivalent_inertia
    if curve.limit_speed is not None:
        w0 = curve.limit_speed
        x = np.linspace(0.0, -math.log1p(-speed / w0), points)
        a, b = x[:-1, None], x[1:, None]
        xq = 0.5 * (a + b) + 0.5 * (b - a) * nodes
        gap = w0 * np.exp(-xq)
        f = j * gap / curve.torque(w0 - gap)
        w = w0 * -np.expm1(-x)
    else:
        kinks = [k for k in curve.kinks if 0.0 < k < speed]
        w = np.unique(np.concatenate((np.linspace(0.0, speed, points), kinks)))
        a, b = w[:-1, None], w[1:, None]
        wq = 0.5 * (a + b) + 0.5 * (b - a) * nodes
        f = j / curve.torque(wq)
    dt = 0.5 * (b - a)[:, 0] * (f @ weights)
    t = np.concatenate(([0.0], np.cumsum(dt)))
    w[-1] = speed
    return t, w


def _check_reaches(curve: MotorCurve, speed: float) -> None:
    """Raise InfeasibleDesign if the torque is not positive all the way to ``speed``."""
    if curve.limit_speed is not None and speed >= curve.limit_speed:
        raise InfeasibleDesign(
            f"the motor can never reach the working speed {speed:.4g} rad/s "
            f"({speed * 30 / math.pi:.0f} rpm): its torque falls to zero at "
            f"{curve.limit_speed:.4g} rad/s ({curve.limit_speed * 30 / math.pi:.0f} rpm); "
            "lower the working speed or choose a faster motor",
            field="motor_speed",
        )
    probe = np.linspace(0.0, speed, 257)
    torque = np.asarray(curve.torque(probe), dtype=float)
    if not np.all(torque > 0.0):
        bad = float(probe[np.argmax(~(torque > 0.0))])
        raise InfeasibleDesign(
            f"the motor can never reach the working speed {speed:.4g} rad/s: its torque is "
            f"not positive at {bad:.4g} rad/s; choose a stronger motor or a lower speed",
            field="motor_curve",
        )
