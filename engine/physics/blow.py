r"""What one blow of a tool does to a joint: peak torque, nut rotation, torque and preload after it.

The tool models stop at the tool: the nut-runner's impact torque
:math:`M = \sqrt{2T C_7C_8/(C_7 + C_8)}` [000, eq. 7–8] assumes the struck end
is fixed and has no inertia, the rare-impact wrench [002] reports its release
speed, the ball clutch [001] its slipping torque. This module carries the
blow into the joint.

The blow
--------
A tool inertia :math:`J_t` turning at :math:`\omega_0` (kinetic energy
:math:`E = \tfrac12 J_t\omega_0^2`) strikes through a torsional stiffness
:math:`C` (shafts, spindle, anvil; one-sided: the jaws push, never pull) the
struck side: socket, extension and nut with inertia :math:`J_s`. The joint
resists the nut with the torque

.. math::
    T_j(\theta) = T_0 + k_j\,\theta

(:math:`\theta` the nut's rotation in this blow, :math:`T_0` the joint torque
when the blow starts, :math:`k_j` the joint's torque rate). A turning nut
feels :math:`T_j`; a nut at rest stays at rest while the spring torque is
below :math:`b\,T_j`, the breakaway factor :math:`b \ge 1` standing for
static friction above kinetic. A net drive torque :math:`N` may act on the
tool during the blow (the nut-runner's slipping safety coupling 1 keeps
feeding its torque, the idle spindles' friction clutches take
:math:`(z-1)M_{tr}` off [000, eq. 10]).

Three rungs, cheapest first:

* ``rigid``: the struck end fixed, :math:`M = \sqrt{2EC}` [000, eq. 7–8]
  (less the idle spindles' friction [000, eq. 10]); the joint is taken to
  reach :math:`M` in one blow, as tool makers' "maximum torque" implies.
* ``energy``: struck inertia neglected, the nut turning while the spring
  torque equals the joint torque, energy balanced:
  :math:`E + N\varphi_t = T_p^2/(2C) + (T_p^2 - T_0^2)/(2k_j)`
  (:func:`energy_blow`), blow after blow.
* ``simulation``: the two-mass torsional model with stick-slip of the nut
  (:func:`simulate_blow`), integrated by a numba-compiled fixed-step RK4 with
  events located by bisection on RK4 sub-steps, blow after blow.

The joint's torque rate :math:`k_j` comes from a number, from the ISO 5393
test joints (:func:`iso5393_rate`) or from the joint itself: torque per
preload (the tightening relation, VDI 2230-1 R13 or [004, eq. 10–13]) times
preload per angle, :math:`dF/d\varphi = P/(2\pi(\delta_S + \delta_P))`
[004, eq. 8] (:func:`joint_rate`).

Limits the tests pin: a nut held fast (or an infinite struck inertia) gives the
rigid wall, :math:`\sqrt{2EC}`; a free struck inertia (:math:`T_0 = k_j = 0`)
gives the two-mass result :math:`\sqrt{2EC\,J_s/(J_t + J_s)}`; a lossless
blow conserves energy to the integrator's tolerance.
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..core.errors import BudgetExceeded, InfeasibleDesign, InputOutOfRange, SolverFailed
from ..numerics.ode import StepCost, is_array, jit, pymax, sqrt, where

__all__ = [
    "ISO5393_ANGLE",
    "STEPS_PER_PERIOD",
    "BlowOutcome",
    "BlowProblem",
    "BlowSeries",
    "blow_series",
    "bolt_joint_torque",
    "clutch_preload_window",
    "contact_restitution",
    "damping_for_restitution",
    "energy_blow",
    "energy_blow_error",
    "energy_peak_error",
    "iso5393_rate",
    "joint_rate",
    "preload_per_angle",
    "rigid_blow_torque",
    "simulate_blow",
    "simulate_blow_reference",
]

#: Angle from snug to target torque of the ISO 5393 test joints, [rad]
#: (ISO 5393:2017, clause 3: hard joint 30°, soft joint 720°; the standard also
#: states them from 10 % to 100 % of the target, 27° and 648°, the same rate).
ISO5393_ANGLE = {"hard": math.radians(30.0), "soft": math.radians(720.0)}

#: RK4 steps per shortest oscillation period of the two-mass model.
STEPS_PER_PERIOD = 200
_BISECT = 60
_SERIES_CAP = 400

_ARRAY = np.ndarray

#: The blow kernel's measured cost per RK4 step in this process (budgets in
#: time, not steps); the prior is a slow machine's figure (~0.3 µs measured on the 2-core
#: CI box, about 3× that).
_COST = StepCost()
#: Steps the blow kernel may take before ``deadline`` (:func:`engine.numerics.ode.step_budget`
#: at :data:`_COST`), or ``max_steps`` without one.
step_budget = _COST.budget


# ---------------------------------------------------------------------------
# The struck side: torque rate of the joint
# ---------------------------------------------------------------------------


def iso5393_rate(target_torque: float, joint: str) -> float:
    r"""Torque rate of an ISO 5393 test joint set up for a target torque.

    .. math::
        k_j = \frac{T_{target}}{\varphi_{joint}},\qquad
        \varphi_{hard} = 30°,\ \varphi_{soft} = 720°

    Parameters
    ----------
    target_torque : float
        Target torque the test joint is set for, [N*m]
    joint : str
        ``"hard"`` or ``"soft"``

    Returns
    -------
    k_j : float
        Torque rate, [N*m/rad]

    Notes
    -----
    ISO 5393:2017, clause 3: a hard joint reaches the target torque 30° after
    snug, a soft joint 720°; stated from 10 % to 100 % of the target they are
    27° and 648°, the same linear rate.

    Examples
    --------
    >>> round(iso5393_rate(600.0, "hard"), 2)
    1145.92
    >>> round(iso5393_rate(600.0, "soft"), 3)
    47.746
    """
    return target_torque / ISO5393_ANGLE[joint]


def preload_per_angle(pitch: float, bolt_compliance: float, clamped_compliance: float) -> float:
    r"""Preload gained per radian of nut rotation once the joint is snug.

    .. math::
        \frac{dF}{d\varphi} = \frac{P}{2\pi(\delta_S + \delta_P)}

    Parameters
    ----------
    pitch : float
        Thread pitch P, [m]
    bolt_compliance : float
        δ_S, [m/N]
    clamped_compliance : float
        δ_P, [m/N]

    Returns
    -------
    float
        dF/dφ, [N/rad]

    Notes
    -----
    [004, eq. 8] differentiated: φ = 2π F Σλ / P.

    Examples
    --------
    >>> round(preload_per_angle(0.002, 1.0e-9, 0.25e-9))
    254648
    """
    return pitch / (2.0 * math.pi * (bolt_compliance + clamped_compliance))


def joint_rate(
    torque_per_preload: float, pitch: float, bolt_compliance: float, clamped_compliance: float
) -> float:
    r"""Torque rate of a real joint: torque per preload times preload per angle.

    .. math::
        k_j = \frac{dT}{dF}\,\frac{dF}{d\varphi}
            = (k_G + k_K)\,\frac{P}{2\pi(\delta_S + \delta_P)}

    Parameters
    ----------
    torque_per_preload : float
        k_G + k_K of the tightening relation (VDI 2230-1 R13 or [004, eq. 10–13]), [m]
    pitch : float
        P, [m]
    bolt_compliance, clamped_compliance : float
        δ_S and δ_P, [m/N]

    Returns
    -------
    k_j : float
        [N*m/rad]

    Notes
    -----
    Both factors are constant once the joint is snug (linear elastic bolt and
    clamped parts, constant friction), so the torque rises linearly with the
    nut's angle.

    Examples
    --------
    M16, k_G + k_K = 2.6 mm, δ_S + δ_P = 1.25e-9 m/N:

    >>> round(joint_rate(0.0026, 0.002, 1.0e-9, 0.25e-9), 1)
    662.1
    """
    return torque_per_preload * preload_per_angle(pitch, bolt_compliance, clamped_compliance)


# ---------------------------------------------------------------------------
# Rungs 1 and 2: rigid end and energy balance
# ---------------------------------------------------------------------------


def rigid_blow_torque(energy: Any, stiffness: Any) -> Any:
    r"""Peak torque of a blow into a fixed struck end.

    .. math::
        M = \sqrt{2 E C}

    Arguments may be floats (a float back) or numpy arrays of one shape.

    Parameters
    ----------
    energy : float or array
        Kinetic energy of the tool at the blow, [J]
    stiffness : float or array
        Torsional stiffness between tool inertia and nut, [N*m/rad]

    Returns
    -------
    M : float or array
        [N*m]

    Notes
    -----
    [000, eq. 7–8] with :math:`C = C_7C_8/(C_7 + C_8)` (reconstructed form, see
    [000] in docs/sources.md).

    Examples
    --------
    The two-flywheel case (21.07 kg·m² at 150 rpm through 203.4 N·m/rad):

    >>> round(float(rigid_blow_torque(0.5 * 21.07 * (150 * math.pi / 30) ** 2, 203.4)), 1)
    1028.3
    """
    return sqrt(2.0 * energy * stiffness)


def held_blow_peak(energy: Any, stiffness: Any, drive_torque: Any = 0.0) -> Any:
    r"""Peak spring torque of a blow into a nut that does not turn (floats or numpy arrays).

    .. math::
        T_h = N + \sqrt{N^2 + 2EC}

    The energy balance of :func:`energy_blow` with the joint side held: the tool's energy
    and the drive's work over the spring's wind-up go into the spring.

    Parameters
    ----------
    energy : float or array
        E, [J]
    stiffness : float or array
        C, [N*m/rad]
    drive_torque : float or array, optional
        N, net torque driving the tool during the blow, [N*m]

    Examples
    --------
    >>> round(float(held_blow_peak(100.0, 2.0e4)), 6)  # √(2·100·2e4)
    2000.0
    >>> round(float(held_blow_peak(100.0, 2.0e4, 10.0)), 3)  # 10 + √(100 + 4e6)
    2010.025
    """
    return drive_torque + _sqrt(drive_torque * drive_torque + 2.0 * energy * stiffness)


def energy_blow(
    energy: Any,
    stiffness: Any,
    rate: Any,
    start_torque: Any,
    breakaway: Any = 1.0,
    drive_torque: Any = 0.0,
    held_peak: Any = None,
    motion: bool = True,
) -> tuple[Any, Any, Any, Any]:
    r"""One blow by energy balance, struck inertia neglected (floats or numpy arrays).

    With a massless nut turning while the spring torque equals the joint
    torque, the tool turns :math:`\varphi_t = T_p/C + (T_p - T_0)/k_j` and

    .. math::
        E + N\varphi_t = \frac{T_p^2}{2C} + \frac{T_p^2 - T_0^2}{2k_j}
        \;\Rightarrow\;
        T_p = N + \sqrt{N^2 + \frac{2E + T_0^2/k_j - 2NT_0/k_j}{1/C + 1/k_j}}

    The nut turns only if the peak of a blow into a held nut,
    :math:`N + \sqrt{N^2 + 2EC}`, exceeds :math:`bT_0`; otherwise that is the peak.

    Parameters
    ----------
    energy : float or array
        E, [J]
    stiffness : float or array
        C, [N*m/rad]
    rate : float or array
        k_j, [N*m/rad]
    start_torque : float or array
        T_0, joint torque when the blow starts, [N*m]
    breakaway : float or array, optional
        b ≥ 1, static over kinetic friction, [-]
    drive_torque : float or array, optional
        N, net torque driving the tool during the blow (feed less drag), [N*m]
    held_peak : float, array or None, optional
        :func:`held_blow_peak` of (E, C, N) where the caller has it (a run of blows: the
        same for every blow of a design), [N*m]
    motion : bool, optional
        On arrays, False leaves the nut rotation and the work out (None in their places)
        where the caller reads the torques only; one design always has all four

    Returns
    -------
    tuple of float or array
        (peak spring torque [N*m], joint torque after the blow [N*m],
        nut rotation [rad], work into the joint [J]); floats when every input is one

    Raises
    ------
    InfeasibleDesign
        A single design with :math:`k_j \le 0` and :math:`T_0 \le N` (a massless nut never
        stops); on arrays such a point is NaN in every output.

    Notes
    -----
    The energy balance of [000, eq. 7–8] with the joint's rate in series with
    the tool's stiffness. With b > 1 a massless nut breaks away at
    :math:`bT_0` and jumps until the spring torque equals the joint torque; the
    balance still holds, and the peak is :math:`\max(bT_0, T_p)`. With
    :math:`k_j \le 0` (a constant joint torque :math:`T_0`) the nut turns until the
    tool's energy is spent: :math:`\varphi = (E + NT_0/C - T_0^2/2C)/(T_0 - N)`.

    Examples
    --------
    >>> [round(v, 3) for v in energy_blow(100.0, 2.0e4, 1000.0, 60.0)]
    [440.346, 440.346, 0.38, 95.152]
    >>> [round(float(v[0]), 3) for v in energy_blow(np.array([100.0]), 2.0e4, 1000.0, 60.0)]
    [440.346, 440.346, 0.38, 95.152]
    >>> [round(v, 3) for v in energy_blow(100.0, 2.0e4, 0.0, 60.0)]  # constant joint torque
    [60.0, 60.0, 1.665, 99.91]
    >>> [v if v is None else v.round(3).tolist() for v in energy_blow(
    ...     np.array([100.0, 100.0]), 2.0e4, np.array([1000.0, 0.0]), 60.0, motion=False)]
    [[440.346, 60.0], [440.346, 60.0], None, None]
    """
    e, c, k, t0, b, n = energy, stiffness, rate, start_torque, breakaway, drive_torque
    if not (  # one design (is_array's test, spelled out: this runs once per blow)
        e.__class__ is _ARRAY
        or c.__class__ is _ARRAY
        or k.__class__ is _ARRAY
        or t0.__class__ is _ARRAY
        or b.__class__ is _ARRAY
        or n.__class__ is _ARRAY
    ):  # one design: the same steps without numpy's per-call cost (35 blows ×)
        held = held_blow_peak(e, c, n) if held_peak is None else held_peak
        if held <= b * t0:
            return held, t0, 0.0, 0.0
        if k <= 0.0:
            if t0 <= n:
                raise InfeasibleDesign(
                    "the energy rung needs a joint that stops the nut: with a zero torque rate "
                    "and a joint torque not above the drive torque a massless nut never stops; "
                    "give a torque rate or use fidelity 'simulation'",
                    field="joint_rate",
                )
            rot = _constant_torque_rotation(e, c, t0, n)
            return max(b * t0, t0), t0, rot, t0 * rot
        tp, rot, work = _rising_joint_blow(e, c, k, t0, n)
        peak = b * t0 if tp <= b * t0 else tp  # NaN stays NaN, as np.maximum on arrays
        return peak, tp, rot, work
    with np.errstate(all="ignore"):
        held = held_blow_peak(e, c, n) if held_peak is None else held_peak
        b_t0 = b * t0
        holds = held <= b_t0
        flat = k <= 0.0
        # the flat joint's branch only where some point has one (where it picks nothing,
        # np.where(flat, ·, v) is v itself)
        some_flat = bool(flat.any()) if flat.__class__ is _ARRAY else bool(flat)
        k_rising = np.where(flat, 1.0, k) if some_flat else k
        tp, rot, work = _rising_joint_blow(e, c, k_rising, t0, n, motion)
        if some_flat:
            stops = t0 > n  # a constant joint torque stops the nut only above the drive torque
            tp = np.where(flat, np.where(stops, t0, np.nan), tp)
        peak = np.maximum(tp, b_t0)  # NaN where the nut never stops
        torques = (np.where(holds, held, peak), np.where(holds, t0, tp))
        if not motion:
            return (*torques, None, None)
        if some_flat:
            rot_flat = np.where(stops, _constant_torque_rotation(e, c, t0, n), np.nan)
            rot = np.where(flat, rot_flat, rot)
            work = np.where(flat, t0 * rot_flat, work)
        return (*torques, np.where(holds, 0.0, rot), np.where(holds, 0.0, work))


def _rising_joint_blow(
    e: Any, c: Any, k: Any, t0: Any, n: Any, motion: bool = True
) -> tuple[Any, Any, Any]:
    """(T_p, rotation, work) of :func:`energy_blow`'s balance on a joint of rate k > 0
    (rotation and work None where ``motion`` is False)."""
    a = 0.5 * (1.0 / c + 1.0 / k)
    rhs = e + t0 * t0 / (2.0 * k) - n * t0 / k
    tp = n + _sqrt(n * n + rhs / a)
    if not motion:
        return tp, None, None
    return tp, (tp - t0) / k, 0.5 * (tp * tp - t0 * t0) / k


def _sqrt(v: Any) -> Any:
    """:func:`engine.numerics.ode.sqrt` that keeps a Python float a Python float.

    The blow loop of one design stays in plain floats, whose arithmetic costs a twentieth
    of numpy scalars'; any other value goes to ``sqrt`` as it is.

    >>> _sqrt(2.25), _sqrt(-1.0), _sqrt(np.array([4.0])).tolist()
    (1.5, nan, [2.0])
    """
    if v.__class__ is float:
        return math.sqrt(v) if v >= 0.0 else math.nan
    return sqrt(v)


def _constant_torque_rotation(e: Any, c: Any, t0: Any, n: Any) -> Any:
    """Nut rotation of :func:`energy_blow` on a joint of constant torque T_0 > N."""
    return (e + n * t0 / c - t0 * t0 / (2.0 * c)) / (t0 - n)


def blow_step(
    method: str,
    energy: Any,
    stiffness: Any,
    rate: Any,
    start_torque: Any,
    breakaway: Any = 1.0,
    drive_torque: Any = 0.0,
) -> tuple[Any, Any, Any, Any]:
    r"""One blow of the ``rigid`` or ``energy`` rung (floats or numpy arrays).

    ``rigid`` ([000, eq. 7–8, 10]): the joint is taken to the peak of a blow into a fixed
    struck end, :math:`M = \sqrt{2EC} + N`, if that is above its torque; with
    :math:`k_j > 0` the nut turns :math:`(T - T_0)/k_j` and the joint takes
    :math:`(T^2 - T_0^2)/2k_j`. ``energy``: :func:`energy_blow`.

    Parameters
    ----------
    method : str
        ``rigid`` or ``energy``
    energy : float or array
        E, [J]
    stiffness : float or array
        C, [N*m/rad]
    rate : float or array
        k_j, [N*m/rad]
    start_torque : float or array
        T_0, joint torque when the blow starts, [N*m]
    breakaway : float or array, optional
        b ≥ 1, static over kinetic friction (energy rung), [-]
    drive_torque : float or array, optional
        N, net torque driving the tool during the blow, [N*m]

    Returns
    -------
    tuple
        (peak spring torque [N*m], joint torque after the blow [N*m], nut rotation [rad],
        work into the joint [J])

    Examples
    --------
    >>> [round(float(v), 3) for v in blow_step("rigid", 100.0, 2.0e4, 1000.0, 60.0)]
    [2000.0, 2000.0, 1.94, 1998.2]
    >>> [round(float(v), 3) for v in blow_step("energy", 100.0, 2.0e4, 1000.0, 60.0)]
    [440.346, 440.346, 0.38, 95.152]
    """
    if method != "rigid":
        return energy_blow(energy, stiffness, rate, start_torque, breakaway, drive_torque)
    m = rigid_blow_torque(energy, stiffness) + drive_torque
    new = pymax(m, start_torque)
    rising = rate > 0.0
    with np.errstate(all="ignore"):
        k = where(rising, rate, 1.0)
        rot = where(rising, (new - start_torque) / k, 0.0)
        work = where(rising, 0.5 * (new * new - start_torque * start_torque) / k, 0.0)
    if is_array(m, new, rot, work):
        return m, new, rot, work
    return float(m), float(new), float(rot), float(work)


def bolt_joint_torque(elastic_torque: Any, yield_torque: Any) -> Any:
    r"""Joint torque of an elastic–ideally-plastic bolt: the torque–angle line bends over at yield.

    .. math::
        T_j(\theta) = \min\left(T_0 + k_j\,\theta,\; T_y\right),\qquad
        T_y = (k_G + k_K)\,F_{M0.2}

    Parameters
    ----------
    elastic_torque : float or array
        T_0 + k_j·θ, the joint torque on the elastic line, [N*m]
    yield_torque : float or array
        T_y, the joint torque at which the bolt yields (``inf``: no yield), [N*m]

    Returns
    -------
    float or array
        T_j, [N*m]

    Notes
    -----
    An elastic–ideally-plastic (Prandtl) bolt, the simplest law with a yield point
    (textbook plasticity; no hardening): up to its yield preload F_M0.2 (VDI 2230-1
    R7 at ν = 1, the thread's torsion included) the joint follows its elastic torque
    rate; past it the nut turns at the constant torque T_y and the bolt stretches
    plastically. Up to T_y the two laws are the same line, so a blow reaches T_y on
    one exactly when it does on the other: the joint torque after a blow is the
    elastic blow's, bent over at T_y.

    Examples
    --------
    >>> float(bolt_joint_torque(400.0, 350.0)), float(bolt_joint_torque(300.0, 350.0))
    (350.0, 300.0)
    >>> bolt_joint_torque(np.array([300.0, 400.0]), 350.0).tolist()
    [300.0, 350.0]
    """
    # pymin's rule: NaN stays NaN; one design's floats without a call (once per blow)
    if elastic_torque.__class__ is not _ARRAY and yield_torque.__class__ is not _ARRAY:
        return yield_torque if yield_torque < elastic_torque else elastic_torque
    return np.where(yield_torque < elastic_torque, yield_torque, elastic_torque)


def blow_gains_nothing(rotation: Any, torque_after: Any, torque_before: Any) -> Any:
    r"""Whether a blow no longer turns the nut: the run of blows has saturated.

    .. math::
        \varphi \le 10^{-12}\ \text{rad} \quad\lor\quad
        T - T_0 \le 10^{-12}\max(|T|, 1\ \text{N}\cdot\text{m})

    Parameters
    ----------
    rotation : float or array
        Nut rotation in the blow, [rad]
    torque_after : float or array
        T, joint torque after the blow, [N*m]
    torque_before : float or array
        T_0, joint torque before the blow, [N*m]

    Examples
    --------
    >>> blow_gains_nothing(0.0, 100.0, 100.0), blow_gains_nothing(0.1, 101.0, 100.0)
    (True, False)
    """
    scale = abs(torque_after)
    if (  # one design
        scale.__class__ is not _ARRAY
        and rotation.__class__ is not _ARRAY
        and torque_before.__class__ is not _ARRAY
    ):
        return bool(
            rotation <= 1e-12
            or torque_after - torque_before <= 1e-12 * (scale if scale > 1.0 else 1.0)
        )
    return (rotation <= 1e-12) | (
        torque_after - torque_before <= 1e-12 * np.where(scale > 1.0, scale, 1.0)
    )


def energy_blow_error(
    tool_inertia: float,
    struck_inertia: float,
    stiffness: float,
    rate: float,
    restitution: float = 1.0,
    breakaway: float = 1.0,
    start_torque: float = 0.0,
    energy: float = math.inf,
) -> float:
    r"""Typical relative error of :func:`energy_blow` against the two-mass simulation.

    .. math::
        \varepsilon = 2\,\frac{J_s}{J_t}\left(\frac{C}{C + k_j}\right)^2
            + \frac{1 - e^2}{2} + \frac{\left((b - 1)T_0\right)^2}{(C + k_j)\,E}

    The first term is twice the kinetic energy a turning nut would carry
    (nut speed :math:`\omega_t C/(C + k_j)` in the massless solution) relative
    to the tool's; the second the energy a blow with restitution e dissipates
    in its loading half, which the balance ignores; the third twice the work the
    massless nut's jump at breakaway leaves out: the spring stands at :math:`bT_0`,
    the joint at :math:`T_0`, and the jump to where they are equal,
    :math:`\theta^* = (b-1)T_0/(C + k_j)`, takes
    :math:`\int_0^{\theta^*}\left((b-1)T_0 - (C + k_j)\theta\right)d\theta
    = ((b-1)T_0)^2/(2(C + k_j))` that a nut with inertia turns into its own motion.
    It is a typical error, not a bound: a real nut that sticks again within the blow
    needs :math:`bT_j` to move on, which no term here follows. Over 800 random
    designs (tests) it is exceeded in 3–4 % (without the third term 6–9 %), worst
    about 10×; with a free struck side (:math:`k_j = T_0 = 0`) it exceeds 1: the
    energy rung does not apply.

    Parameters
    ----------
    tool_inertia, struck_inertia : float
        J_t and J_s, [kg*m^2]
    stiffness : float
        C, [N*m/rad]
    rate : float
        k_j, [N*m/rad]
    restitution : float, optional
        e, [-]
    breakaway : float, optional
        b ≥ 1, static over kinetic friction, [-]
    start_torque : float, optional
        T_0, the joint torque when the blow starts, [N*m]
    energy : float, optional
        E, the blow's energy, [J]

    Returns
    -------
    float
        Relative error of the joint torque after a blow, [-]

    Examples
    --------
    2·(0.001/0.03)·(2e4/2.1e4)² = 0.060469; with b = 1.5, T_0 = 60 N·m, E = 100 J the
    jump adds 30²/(2.1e4·100) = 0.000429:

    >>> round(energy_blow_error(0.03, 0.001, 2.0e4, 1000.0), 4)
    0.0605
    >>> round(energy_blow_error(0.03, 0.001, 2.0e4, 1000.0, 1.0, 1.5, 60.0, 100.0), 6)
    0.060897
    """
    ratio = stiffness / (stiffness + rate)
    jump = (breakaway - 1.0) * start_torque
    return (
        2.0 * struck_inertia / tool_inertia * ratio * ratio
        + 0.5 * (1.0 - restitution**2)
        + jump * jump / ((stiffness + rate) * energy)
    )


def contact_restitution(damping_ratio: float) -> float:
    r"""Coefficient of restitution of a linear spring-dashpot contact that parts at zero force.

    .. math::
        e = e^{-\zeta\omega_n t_s}\left(\cos\phi + \frac{\zeta}{\sqrt{1-\zeta^2}}\sin\phi
            \right),\quad \phi = \operatorname{atan2}\left(2\zeta\sqrt{1-\zeta^2},\
            1 - 2\zeta^2\right),\quad \omega_n t_s = \frac{\pi - \phi}{\sqrt{1-\zeta^2}}

    The relative motion of the two sides is a damped oscillator from zero
    twist; the jaws part when the contact force :math:`Cu + c\dot u` (not the
    twist) returns to zero, at :math:`t_s`. The often quoted
    :math:`e = \exp(-\pi\zeta/\sqrt{1-\zeta^2})` assumes parting at zero twist,
    which needs the dashpot to pull; with a one-sided contact it understates
    e (0.80 asks ζ = 0.071 by that formula, which really gives 0.81). e cannot
    fall below about 0.135 (critical damping) in this model.

    Parameters
    ----------
    damping_ratio : float
        ζ of the contact's relative motion, 0 ≤ ζ < 1, [-]

    Returns
    -------
    e : float
        Coefficient of restitution, [-]

    Examples
    --------
    >>> contact_restitution(0.0)
    1.0
    >>> round(contact_restitution(0.2), 4)
    0.5717
    """
    z = damping_ratio
    wd = math.sqrt(1.0 - z * z)
    phi = math.atan2(2.0 * z * wd, 1.0 - 2.0 * z * z)
    ts = (math.pi - phi) / wd
    return math.exp(-z * ts) * (math.cos(phi) + z * math.sin(phi) / wd)


#: The smallest restitution :func:`contact_restitution` reaches (ζ = 0.99).
MIN_RESTITUTION = contact_restitution(0.99)


def damping_for_restitution(
    restitution: float, tool_inertia: float, struck_inertia: float, stiffness: float
) -> float:
    r"""Viscous damping of the tool's spring that gives a coefficient of restitution.

    .. math::
        c = 2\zeta\sqrt{C\,J_r},\quad J_r = \frac{J_t J_s}{J_t + J_s},\qquad
        e(\zeta) = \text{restitution}

    with :math:`e(\zeta)` of :func:`contact_restitution`, inverted by bisection.

    Parameters
    ----------
    restitution : float
        e in [0.14, 1], [-]
    tool_inertia, struck_inertia : float
        J_t, J_s, [kg*m^2]
    stiffness : float
        C, [N*m/rad]

    Returns
    -------
    c : float
        [N*m*s/rad]

    Notes
    -----
    A free two-mass blow through this contact rebounds with relative speed e
    times the approach speed (the test checks it on the simulation). e = 1 is
    a lossless blow.

    Examples
    --------
    >>> damping_for_restitution(1.0, 1.0, 1.0, 100.0)
    0.0
    >>> round(damping_for_restitution(0.5717400275847768, 1.0, 1.0, 100.0), 6)
    2.828427
    """
    if restitution >= 1.0:
        return 0.0
    if restitution < MIN_RESTITUTION:
        raise InputOutOfRange(
            f"restitution = {restitution:g} is not allowed: a spring-dashpot contact gives at "
            f"least {MIN_RESTITUTION:.3f}",
            field="restitution",
        )
    zeta = _damping_ratio(restitution)
    jr = tool_inertia * struck_inertia / (tool_inertia + struck_inertia)
    return 2.0 * zeta * math.sqrt(stiffness * jr)


@functools.lru_cache(maxsize=256)
def _damping_ratio(restitution: float) -> float:
    """ζ with :func:`contact_restitution` (ζ) = restitution, by 60 bisections on [0, 0.99].

    Kept per restitution: a simulation asks for it blow after blow (some 60 µs of Python
    each time otherwise, the cost of hundreds of the kernel's steps).

    >>> round(contact_restitution(_damping_ratio(0.5)), 12)
    0.5
    """
    lo, hi = 0.0, 0.99
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if contact_restitution(mid) > restitution:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


# ---------------------------------------------------------------------------
# Rung 3: the two-mass simulation (compiled kernel)
# ---------------------------------------------------------------------------


def _rates(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n):  # type: ignore[no-untyped-def]
    """Derivatives of (u, wt, th, ws, Wj, Wd, Wc) and the spring torque at one state."""
    du = wt - ws
    ts = 0.0
    up = 0.0
    if u > 0.0:
        up = u
        ts = c * u + cd * du
        if ts < 0.0:
            ts = 0.0
    dwt = (n - ts) / jt
    tj = t0 + k * th
    dth = 0.0
    dws = 0.0
    pj = 0.0
    if mode == 1:
        dth = ws
        dws = (ts - tj) / js
        pj = tj * ws
    return du, dwt, dth, dws, pj, n * wt, (ts - c * up) * du, ts


_rates_c = jit(_rates, inline=True)


def _rk4(u, wt, th, ws, wj, wn, wc, h, mode, jt, js, c, cd, k, t0, n):  # type: ignore[no-untyped-def]
    """One RK4 step of length h from the seven states: the seven states after it.

    The states are scalars in and out (a tuple back): no array is touched per step.
    """
    f = 0.5 * h
    r1 = _rates_c(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
    a = ws + f * r1[3] if mode == 1 else 0.0
    r2 = _rates_c(u + f * r1[0], wt + f * r1[1], th + f * r1[2], a, mode, jt, js, c, cd, k, t0, n)
    a = ws + f * r2[3] if mode == 1 else 0.0
    r3 = _rates_c(u + f * r2[0], wt + f * r2[1], th + f * r2[2], a, mode, jt, js, c, cd, k, t0, n)
    a = ws + h * r3[3] if mode == 1 else 0.0
    r4 = _rates_c(u + h * r3[0], wt + h * r3[1], th + h * r3[2], a, mode, jt, js, c, cd, k, t0, n)
    g = h / 6.0
    return (
        u + g * (r1[0] + 2.0 * r2[0] + 2.0 * r3[0] + r4[0]),
        wt + g * (r1[1] + 2.0 * r2[1] + 2.0 * r3[1] + r4[1]),
        th + g * (r1[2] + 2.0 * r2[2] + 2.0 * r3[2] + r4[2]),
        ws + g * (r1[3] + 2.0 * r2[3] + 2.0 * r3[3] + r4[3]) if mode == 1 else 0.0,
        wj + g * (r1[4] + 2.0 * r2[4] + 2.0 * r3[4] + r4[4]),
        wn + g * (r1[5] + 2.0 * r2[5] + 2.0 * r3[5] + r4[5]),
        wc + g * (r1[6] + 2.0 * r2[6] + 2.0 * r3[6] + r4[6]),
    )


_rk4_c = jit(_rk4, inline=True)


def _spring(u, wt, ws, c, cd):  # type: ignore[no-untyped-def]
    """Spring torque T_s = max(0, C u + c u') on the contact (u > 0), 0 off it."""
    if u <= 0.0:
        return 0.0
    ts = c * u + cd * (wt - ws)
    return ts if ts > 0.0 else 0.0


_spring_c = jit(_spring, inline=True)


def _event(u, wt, th, ws, mode, jt, js, c, cd, k, t0, b, n, started):  # type: ignore[no-untyped-def]
    """Which event a state shows: 0 none, 1 stick, 2 breakaway, 3 end of blow."""
    tj = t0 + k * th
    if mode == 1:
        if ws < 0.0:
            return 1
        # jaws apart, the nut running away faster and decelerating no faster than the tool
        if started and u < 0.0 and wt <= ws and n * js + tj * jt <= 0.0:
            return 3
        return 0
    if _spring_c(u, wt, ws, c, cd) > b * tj:
        return 2
    if started and wt <= 0.0:
        return 3  # tool turning back, nut at rest: the spring torque only falls from here
    return 0


_event_c = jit(_event, inline=True)


def _torque_rate(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n):  # type: ignore[no-untyped-def]
    """dT_s/dt = C u' + c u'' on the contact, 0 off it."""
    r = _rates_c(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
    if u <= 0.0:
        return 0.0
    return c * r[0] + cd * (r[1] - r[3])


_torque_rate_c = jit(_torque_rate, inline=True)


def _blow_kernel(  # type: ignore[no-untyped-def]
    st, h, max_steps, jt, js, c, cd, k, t0, b, n, stride, out_t, out_ts, info,
):  # fmt: skip
    """Integrate one blow from state st (modified in place) to its end.

    info carries in [.., mode, started] and receives [status, steps, t_end, peak torque,
    t_peak, records, mode, started]: status 1 = the blow ended, 0 = max_steps used.
    The state lives in local variables between the steps (st is read once and written
    once); the torque's rate at a step's start is the one at the previous step's end
    unless an event changed the mode; events and maxima are bisected only on the steps
    whose end shows them.
    """
    mode = int(info[6])
    started = info[7] > 0.0
    t = 0.0
    peak = 0.0
    t_peak = 0.0
    u, wt, th, ws, wj, wn, wc = st[0], st[1], st[2], st[3], st[4], st[5], st[6]
    cap = out_t.shape[0]
    n_rec = 0
    if stride > 0 and cap > 0:
        out_t[0] = 0.0
        out_ts[0] = _spring_c(u, wt, ws, c, cd)
        n_rec = 1
    steps = 0
    status = 0
    r0 = _torque_rate_c(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
    while steps < max_steps:
        x = _rk4_c(u, wt, th, ws, wj, wn, wc, h, mode, jt, js, c, cd, k, t0, n)
        steps += 1
        ev = _event_c(x[0], x[1], x[2], x[3], mode, jt, js, c, cd, k, t0, b, n,
                      started or x[0] > 0.0)  # fmt: skip
        frac = 1.0
        if ev != 0:
            lo = 0.0
            hi = 1.0
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                y = _rk4_c(u, wt, th, ws, wj, wn, wc, mid * h, mode, jt, js, c, cd, k, t0, n)
                if _event_c(y[0], y[1], y[2], y[3], mode, jt, js, c, cd, k, t0, b, n,
                            started or y[0] > 0.0) == ev:  # fmt: skip
                    hi = mid
                else:
                    lo = mid
            frac = hi
            x = _rk4_c(u, wt, th, ws, wj, wn, wc, frac * h, mode, jt, js, c, cd, k, t0, n)
        # a torque maximum inside the step: locate it on RK4 sub-steps
        r1 = _torque_rate_c(x[0], x[1], x[2], x[3], mode, jt, js, c, cd, k, t0, n)
        if r0 > 0.0 and r1 <= 0.0:
            lo = 0.0
            hi = frac
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                y = _rk4_c(u, wt, th, ws, wj, wn, wc, mid * h, mode, jt, js, c, cd, k, t0, n)
                if _torque_rate_c(y[0], y[1], y[2], y[3], mode, jt, js, c, cd, k, t0, n) > 0.0:
                    lo = mid
                else:
                    hi = mid
            y = _rk4_c(u, wt, th, ws, wj, wn, wc, lo * h, mode, jt, js, c, cd, k, t0, n)
            tsm = _spring_c(y[0], y[1], y[3], c, cd)
            if tsm > peak:
                peak = tsm
                t_peak = t + lo * h
        u, wt, th, ws, wj, wn, wc = x
        r0 = r1
        t += frac * h
        if u > 0.0:
            started = True
        ts = _spring_c(u, wt, ws, c, cd)
        if ts > peak:
            peak = ts
            t_peak = t
        if stride > 0 and (steps % stride == 0 or ev != 0) and n_rec < cap:
            out_t[n_rec] = t
            out_ts[n_rec] = ts
            n_rec += 1
        if ev == 3:
            status = 1
            break
        if ev == 1:
            ws = 0.0
            mode = 0
            # stuck: does the spring already hold enough to break away again?
            if _spring_c(u, wt, ws, c, cd) > b * (t0 + k * th):
                mode = 1
            elif wt <= 0.0 and started:
                status = 1
                break
            r0 = _torque_rate_c(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
        elif ev == 2:
            mode = 1
            r0 = _torque_rate_c(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
    st[0], st[1], st[2], st[3], st[4], st[5], st[6] = u, wt, th, ws, wj, wn, wc
    info[0] = status
    info[1] = steps
    info[2] = t
    info[3] = peak
    info[4] = t_peak
    info[5] = n_rec
    info[6] = mode
    info[7] = 1.0 if started else 0.0


_blow_kernel_c = jit(_blow_kernel)


@dataclass(frozen=True)
class BlowProblem:
    """One blow reduced to numbers (SI): floats, or arrays of one shape for many designs.

    The simulation takes one design (floats); :func:`blow_series`' rigid and energy rungs
    and :func:`energy_peak_error` take many.
    """

    tool_inertia: Any  # J_t [kg m²]
    struck_inertia: Any  # J_s [kg m²]
    stiffness: Any  # C [N m/rad]
    speed: Any  # ω_0 [rad/s]
    rate: Any  # k_j [N m/rad]
    breakaway: Any = 1.0  # b [-]
    drive_torque: Any = 0.0  # N [N m]
    restitution: Any = 1.0  # e [-]

    @property
    def energy(self) -> Any:
        """Kinetic energy of the tool, [J]."""
        return 0.5 * self.tool_inertia * self.speed**2

    @property
    def damping(self) -> float:
        """Viscous damping of the tool's spring, [N m s/rad]."""
        return damping_for_restitution(
            self.restitution, self.tool_inertia, self.struck_inertia, self.stiffness
        )

    @property
    def step(self) -> float:
        """RK4 step: STEPS_PER_PERIOD per shortest period, [s]."""
        jt, js, c, k, cd = (
            self.tool_inertia,
            self.struck_inertia,
            self.stiffness,
            self.rate,
            self.damping,
        )
        omega = math.sqrt(c / jt + (c + k) / js)
        omega = max(omega, cd * (1.0 / jt + 1.0 / js))
        return 2.0 * math.pi / (STEPS_PER_PERIOD * omega)


@dataclass
class BlowOutcome:
    """What one simulated blow did."""

    peak_torque: float  # [N m]
    rotation: float  # nut rotation [rad]
    torque_after: float  # joint torque after the blow [N m]
    joint_work: float  # ∫T_j dθ [J]
    drive_work: float  # ∫N ω_t dt [J]
    damping_loss: float  # [J]
    energy_left: float  # kinetic + elastic energy at the end of the blow [J]
    duration: float  # [s]
    time_of_peak: float  # [s]
    steps: int
    time: np.ndarray = field(default_factory=lambda: np.empty(0))
    torque: np.ndarray = field(default_factory=lambda: np.empty(0))


def simulate_blow(
    p: BlowProblem,
    start_torque: float,
    *,
    record: bool = False,
    max_steps: int = 1_000_000,
    deadline: float | None = None,
    steps_per_period: int | None = None,
) -> BlowOutcome:
    r"""One blow of the two-mass torsional model with stick-slip of the nut.

    .. math::
        J_t\dot\omega_t = N - T_s,\qquad
        T_s = \max(0,\ C u + c\dot u)\ (u > 0),\quad \dot u = \omega_t - \omega_s

        J_s\dot\omega_s = T_s - (T_0 + k_j\theta)\ \text{(nut turning)},\qquad
        \omega_s = 0\ \text{while}\ T_s \le b\,(T_0 + k_j\theta)

    Integrated by RK4 with a fixed step of :data:`STEPS_PER_PERIOD` per
    shortest period :math:`2\pi/\sqrt{C/J_t + (C + k_j)/J_s}`; the nut
    sticking (:math:`\omega_s` reaching 0), breaking away (:math:`T_s`
    reaching :math:`bT_j`), the end of the blow (the tool turning back with the
    nut at rest, or the jaws separating) and each torque maximum are located
    by bisection on RK4 sub-steps from the step's start, so to the
    integrator's accuracy. The work into the joint, of the drive torque and of
    the damping are integrated alongside (energy check).

    Parameters
    ----------
    p : BlowProblem
        Tool, struck side and joint
    start_torque : float
        T_0, joint torque when the blow starts, [N*m]
    record : bool
        Keep about 400 points of the spring torque against time
    max_steps : int
        Step budget of the blow, [-]; BudgetExceeded past it
    deadline : float or None
        ``time.perf_counter()`` value after which the run stops (BudgetExceeded), [s]
    steps_per_period : int or None
        Override of :data:`STEPS_PER_PERIOD` (convergence tests), [-]

    Returns
    -------
    BlowOutcome

    Examples
    --------
    The two-flywheel case, struck side free (T_0 = k_j = 0): the two-mass
    peak is √(2E·C·J_s/(J_t + J_s)) = 890.6 N·m.

    >>> p = BlowProblem(21.07, 63.21, 203.4, 150 * math.pi / 30, 0.0)
    >>> round(simulate_blow(p, 0.0).peak_torque, 2)
    890.55
    """
    h = p.step if steps_per_period is None else p.step * STEPS_PER_PERIOD / steps_per_period
    st = np.zeros(7)
    st[1] = p.speed
    info = np.zeros(8)
    cap = _SERIES_CAP + 64 if record else 0
    out_t = np.empty(max(cap, 1))
    out_ts = np.empty(max(cap, 1))
    # a first guess of the blow's length for the recording stride: a quarter period
    # of the tool on the series of C and the joint's rate
    k_eff = p.stiffness if p.rate <= 0 else p.stiffness * p.rate / (p.stiffness + p.rate)
    guess = 0.5 * math.pi * math.sqrt(p.tool_inertia / k_eff) if k_eff > 0 else 1.0
    stride = max(1, int(guess / h / (_SERIES_CAP / 2))) if record else 0
    total = 0
    cd = p.damping
    t_peak_abs = 0.0
    peak = 0.0
    t_total = 0.0
    while True:
        if deadline is not None and time.perf_counter() > deadline:
            if st[0] <= 0.0 and st[3] > 0.0:
                raise _coasting(f"its time budget after {total} steps", p, start_torque)
            raise BudgetExceeded(
                f"the blow simulation stopped at its time budget after {total} steps",
                field="fidelity",
            )
        chunk = min(200_000, max_steps - total)
        if chunk <= 0:
            if st[0] <= 0.0 and st[3] > 0.0:
                raise _coasting(f"its budget of {max_steps} steps", p, start_torque)
            raise BudgetExceeded(
                f"one blow used its budget of {max_steps} steps without ending (a nut much "
                "lighter than the tool on a stiff joint, or a joint that never stops it); use "
                "fidelity 'energy', which is accurate exactly when the nut is light",
                field="fidelity",
                expected_steps=float(max_steps),
            )
        began = time.perf_counter()
        _blow_kernel_c(
            st, h, chunk, p.tool_inertia, p.struck_inertia, p.stiffness, cd, p.rate,
            start_torque, p.breakaway, p.drive_torque, stride if total == 0 else 0,
            out_t, out_ts, info,
        )  # fmt: skip
        used = int(info[1])
        _COST.measured(used, time.perf_counter() - began)
        if info[3] > peak:
            peak = float(info[3])
            t_peak_abs = t_total + float(info[4])
        t_total += float(info[2])
        total += used
        if info[0] == 1:
            break
    if not all(math.isfinite(v) for v in st):
        raise SolverFailed("the blow simulation diverged", field="fidelity")
    n_rec = int(info[5]) if record else 0
    u, wt, th, ws = st[0], st[1], st[2], st[3]
    left = 0.5 * p.tool_inertia * wt * wt + 0.5 * p.struck_inertia * ws * ws
    left += 0.5 * p.stiffness * max(u, 0.0) ** 2
    return BlowOutcome(
        peak_torque=peak,
        rotation=float(th),
        torque_after=start_torque + p.rate * float(th),
        joint_work=float(st[4]),
        drive_work=float(st[5]),
        damping_loss=float(st[6]),
        energy_left=float(left),
        duration=t_total,
        time_of_peak=t_peak_abs,
        steps=total,
        time=out_t[:n_rec].copy(),
        torque=out_ts[:n_rec].copy(),
    )


def _coasting(budget: str, p: BlowProblem, start_torque: float) -> BudgetExceeded:
    """The budget ran out with the jaws apart and the nut still turning: say so."""
    return BudgetExceeded(
        f"one blow used {budget} with the nut still coasting after the jaws parted: the "
        f"joint's torque (T_0 = {start_torque:.4g} N·m, k_j = {p.rate:.4g} N·m/rad) barely "
        "slows it; for a free struck side give joint_rate 0 and snug_torque 0 (the blow then "
        "ends when the jaws part)",
        field="joint_rate",
    )


def simulate_blow_reference(
    p: BlowProblem, start_torque: float, *, rtol: float = 1e-10, method: str = "DOP853"
) -> tuple[float, float, int]:
    """The same blow by scipy's ``solve_ivp``, one solve per stick/slip phase with terminal events.

    Independent of the compiled kernel (its own right-hand side and scipy's
    event location); the peak is found on a 2001-point grid of each phase's
    dense output and refined by Brent's bounded search between the grid
    points beside it (the dense output's own accuracy, not the grid's ~1e-6).

    Parameters
    ----------
    p : BlowProblem
        Tool, struck side and joint
    start_torque : float
        T_0, [N*m]
    rtol : float
        Relative tolerance of the solver, [-]
    method : str
        solve_ivp method

    Returns
    -------
    tuple
        (peak torque [N*m], nut rotation [rad], RHS evaluations [-])
    """
    from scipy.integrate import solve_ivp
    from scipy.optimize import minimize_scalar

    jt, js, c, k, b, n = (
        p.tool_inertia,
        p.struck_inertia,
        p.stiffness,
        p.rate,
        p.breakaway,
        p.drive_torque,
    )
    cd = p.damping
    t0 = start_torque

    def spring(y: Any) -> float:
        if y[0] <= 0.0:
            return 0.0
        return max(c * y[0] + cd * (y[1] - y[3]), 0.0)

    def slide(t: float, y: Any) -> list[float]:
        ts = spring(y)
        return [y[1] - y[3], (n - ts) / jt, y[3], (ts - t0 - k * y[2]) / js]

    def stick(t: float, y: Any) -> list[float]:
        ts = spring(y)
        return [y[1], (n - ts) / jt, 0.0, 0.0]

    def ev_stop(t: float, y: Any) -> float:
        return float(y[3])

    def ev_break(t: float, y: Any) -> float:
        return spring(y) - b * (t0 + k * y[2])

    def ev_back(t: float, y: Any) -> float:
        return float(y[1])

    def ev_sep(t: float, y: Any) -> float:
        # the jaws part for good: only when nothing slows the nut more than the tool
        return float(y[0]) if n * js + (t0 + k * y[2]) * jt <= 0.0 and t > 0.0 else 1.0

    for f, d in ((ev_stop, -1.0), (ev_break, 1.0), (ev_back, -1.0), (ev_sep, -1.0)):
        f.terminal = True  # type: ignore[attr-defined]
        f.direction = d  # type: ignore[attr-defined]
    y = np.array([0.0, p.speed, 0.0, 0.0])
    t = 0.0
    mode = 0
    peak = 0.0
    nfev = 0
    span = 1e3 * math.sqrt(jt / c) + 1.0
    for _ in range(10_000):
        period = 2.0 * math.pi / math.sqrt(c / jt + (c + k) / js)
        if mode == 0:
            sol = solve_ivp(stick, (t, t + span), y, method=method, rtol=rtol,
                            atol=rtol * 1e-6, events=(ev_break, ev_back),
                            dense_output=True, max_step=period)  # fmt: skip
        else:
            sol = solve_ivp(slide, (t, t + span), y, method=method, rtol=rtol,
                            atol=rtol * 1e-6, events=(ev_stop, ev_sep),
                            dense_output=True, max_step=period)  # fmt: skip
        nfev += int(sol.nfev)
        grid = np.linspace(sol.t[0], sol.t[-1], 2001)
        dense = sol.sol(grid)
        twist = dense[0]
        torque = np.where(twist > 0.0, c * twist + cd * (dense[1] - dense[3]), 0.0)
        j = int(np.argmax(torque))
        peak = max(peak, float(torque[j]))
        if torque[j] > 0.0:  # refine between the grid points beside the grid's maximum
            lo, hi = grid[max(j - 1, 0)], grid[min(j + 1, len(grid) - 1)]
            found = minimize_scalar(
                lambda t, s=sol: -spring(s.sol(t)),
                bounds=(lo, hi),
                method="bounded",
                options={"xatol": 1e-15 * max(abs(hi), 1e-300)},
            )
            peak = max(peak, -float(found.fun))
        y = sol.y[:, -1].copy()
        t = float(sol.t[-1])
        hit = [i for i, e in enumerate(sol.t_events) if len(e)]
        if not hit:
            raise SolverFailed("solve_ivp: the blow did not end")
        which = hit[0]
        if mode == 0:
            if which == 0:
                mode = 1
                continue
            return peak, float(y[2]), nfev
        if which == 0:
            y[3] = 0.0
            mode = 0
            if spring(y) > b * (t0 + k * y[2]):
                mode = 1
            elif y[1] <= 0.0:
                return peak, float(y[2]), nfev
            continue
        return peak, float(y[2]), nfev
    raise SolverFailed("solve_ivp: too many stick/slip phases")


# ---------------------------------------------------------------------------
# A clutch-limited continuous tool: the preload window it gives
# ---------------------------------------------------------------------------


def clutch_preload_window(
    torque_min: Any, torque_max: Any, per_preload_min: Any, per_preload_max: Any
) -> tuple[Any, Any]:
    r"""Preload window on a joint from a window of clutch slipping torque.

    .. math::
        F_{min} = \frac{T_{min}}{(k_G + k_K)_{max}},\qquad
        F_{max} = \frac{T_{max}}{(k_G + k_K)_{min}}

    Parameters
    ----------
    torque_min, torque_max : float or array
        Lowest and highest slipping torque of the clutch (flank friction and
        spring tolerance, [001, eq. 1–3]), [N*m]
    per_preload_min, per_preload_max : float or array
        Torque per preload of the joint at its lowest and highest friction
        (VDI 2230-1 R13), [m]

    Returns
    -------
    tuple of float or array
        (F_min, F_max), [N]

    Notes
    -----
    A continuous tool stops turning the nut when its clutch slips, so the
    joint's torque is the clutch's slipping torque (dynamic overshoot of the
    run-down neglected) and the preload follows through the tightening
    relation, as in the torque-controlled method of [004].

    Examples
    --------
    >>> [round(v) for v in clutch_preload_window(90.0, 110.0, 0.0022, 0.0028)]
    [32143, 50000]
    """
    return torque_min / per_preload_max, torque_max / per_preload_min


# ---------------------------------------------------------------------------
# Blow after blow
# ---------------------------------------------------------------------------


@dataclass
class BlowSeries:
    """A run of blows on one joint or many, each blow starting from the torque the last one left.

    Floats for one design, arrays of one shape for many (one design each). ``blows_to_target``
    and ``yield_blow`` are 0 where the target is not reached and the bolt stays elastic;
    ``per_blow`` holds each blow's numbers in order where the run kept them (``history``).
    """

    peak: Any  # the first blow's peak spring torque [N m]
    rotation: Any  # the first blow's nut rotation [rad]
    torque_after: Any  # the joint torque after the first blow [N m]
    work: Any  # the first blow's work into the joint [J]
    final_torque: Any  # the joint torque after the last blow [N m]
    joint_work: Any  # the work of all blows into the joint, summed in their order [J]
    blows: Any  # blows run [-]
    blows_to_target: Any  # the blow that reached the target, 1-based (0: not reached)
    saturated: Any  # the last blow no longer turned the nut
    #: The blow that reached the bolt's yield torque, 1-based (0: the bolt stayed elastic)
    yield_blow: Any
    #: The joint torque that blow would have reached on the elastic line, [N*m] (NaN: none)
    elastic_demand: Any
    steps: int = 0
    first: BlowOutcome | None = None
    #: Each blow's "peak", "rotation", "torque" (after it) and "work", in order
    per_blow: dict[str, list[Any]] = field(default_factory=dict)


def energy_peak_error(p: BlowProblem, peak: Any) -> Any:
    r"""A-priori relative error of the energy rung's *peak spring torque*.

    .. math::
        \varepsilon_{peak} = \frac{\omega_0\sqrt{C J_r}}{T_p},\qquad
        J_r = \frac{J_t J_s}{J_t + J_s}

    The energy rung lets a massless nut follow the tool; a real nut is kicked
    first, and the kick's torque scale is the two-mass impact torque
    :math:`\omega_0\sqrt{CJ_r}`. The joint torque after the blow is much less
    sensitive (:func:`energy_blow_error`).

    Parameters
    ----------
    p : BlowProblem
        Tool, struck side and joint (its numbers may be arrays of one shape, one
        design each)
    peak : float or array
        The energy rung's peak torque T_p, [N*m]

    Returns
    -------
    float
        Relative error of the peak torque, [-]

    >>> round(float(energy_peak_error(BlowProblem(0.03, 0.001, 2.0e4, 90.0, 1000.0), 484.6)), 3)
    0.817
    """
    jr = p.tool_inertia * p.struck_inertia / (p.tool_inertia + p.struck_inertia)
    tiny = np.maximum(peak, 1e-300) if isinstance(peak, np.ndarray) else max(peak, 1e-300)
    return p.speed * sqrt(p.stiffness * jr) / tiny


def blow_series(
    p: BlowProblem,
    start_torque: Any,
    method: str,
    *,
    target_torque: Any = None,
    max_blows: Any = 100,
    record_first: bool = False,
    max_steps: int = 1_000_000,
    deadline: float | None = None,
    yield_torque: Any = math.inf,
    history: bool | None = None,
    need: Collection[str] | None = None,
) -> BlowSeries:
    """Blows by ``method`` until the target or no gain, for one design or many.

    Stops at the first blow that brings the joint torque to ``target_torque``,
    when a blow no longer turns the nut (the joint holds against the blow:
    saturation), at the blow that takes the bolt to its yield torque, or after
    ``max_blows``. The rigid rung takes the joint to the blow's peak torque in one
    blow ([000, eq. 7–8, 10]: √(2EC) + N).

    Parameters
    ----------
    p : BlowProblem
        Tool, struck side and joint; its numbers may be arrays of one shape (one design
        each) on the ``rigid`` and ``energy`` rungs
    start_torque : float or array
        Joint torque before the first blow (snug), [N*m]
    method : str
        ``rigid``, ``energy`` or ``simulation`` (one design)
    target_torque : float, array or None
        Stop at the first blow that reaches it, [N*m]
    max_blows : int or array
        Most blows, [-]
    record_first : bool
        Keep the torque against time of the first blow (simulation)
    max_steps : int
        Step budget of all blows together without a deadline, [-]; with one, the step
        budget is what the time left affords (:func:`engine.numerics.ode.step_budget`)
    deadline : float or None
        ``time.perf_counter()`` value after which the run stops, [s]
    yield_torque : float or array
        T_y, the joint torque at which the bolt yields (:func:`bolt_joint_torque`);
        the run stops at the blow that reaches it (further blows only stretch the
        bolt at T_y), [N*m]
    history : bool or None
        Keep each blow's numbers in ``per_blow`` (default: for one design only)
    need : collection of str or None
        The fields of the result the caller reads (default: all). On arrays, a series of
        one blow (``max_blows`` 1, one number) on the energy rung then works out these
        alone, without the loop's bookkeeping, and leaves the others None

    Returns
    -------
    BlowSeries

    Notes
    -----
    One loop for one design and many: each blow is :func:`blow_step` (or
    :func:`simulate_blow`) on the designs still running, bent over at yield by
    :func:`bolt_joint_torque`, and stopped by the same rules; on arrays the designs
    that have stopped drop out of the next blow.

    Examples
    --------
    M = √(2·100·2e4) = 2000 N·m on the rigid rung; the energy rung's first blow is
    :func:`energy_blow`'s 440.346 N·m, and two designs reach 600 N·m in 2 and 5 blows:

    >>> s = blow_series(BlowProblem(0.02, 1e-3, 2.0e4, 100.0, 1000.0), 60.0, "energy",
    ...                 target_torque=600.0)
    >>> round(s.torque_after, 3), s.blows_to_target, len(s.per_blow["torque"])
    (440.346, 2, 2)
    >>> two = BlowProblem(0.02, 1e-3, 2.0e4, np.array([100.0, 50.0 * math.sqrt(2.0)]), 1000.0)
    >>> blow_series(two, 60.0, "energy", target_torque=600.0).blows_to_target.tolist()
    [2, 5]
    """
    e, c, k, b, n = p.energy, p.stiffness, p.rate, p.breakaway, p.drive_torque
    given = (e, c, k, b, n, start_torque, target_torque, max_blows, yield_torque)
    many = is_array(*given)
    keep = not many if history is None else history
    # floats for one design, flat arrays over the designs for many
    peak0: Any
    rot0: Any
    after0: Any
    work0: Any
    demand: Any
    total: Any
    blows: Any
    reached: Any
    yielded: Any
    saturated: Any
    torque: Any
    if many:
        if method == "simulation":
            raise ValueError("the simulation rung runs one design at a time")
        shape = np.broadcast_shapes(*(np.shape(v) for v in given if v is not None))
        if (
            need is not None
            and method == "energy"
            and not isinstance(max_blows, np.ndarray)
            and int(max_blows) == 1
            and not history
        ):
            return _one_energy_blow(p, start_torque, target_torque, yield_torque, need, shape)

        def full(v: Any) -> np.ndarray:
            return np.array(np.broadcast_to(np.asarray(v, dtype=float), shape)).ravel()

        def flat(v: Any) -> Any:  # an input of many designs flat; one number as it is
            return full(v) if isinstance(v, np.ndarray) else v

        e, c, k, b, n, ty = flat(e), flat(c), flat(k), flat(b), flat(n), flat(yield_torque)
        held = held_blow_peak(e, c, n)
        torque = full(start_torque)
        target = None if target_torque is None else flat(target_torque)
        limit = full(max_blows)
        peak0, rot0, after0, work0, demand = (np.full(limit.size, np.nan) for _ in range(5))
        total = np.zeros(limit.size)
        blows, reached, yielded = (np.zeros(limit.size, dtype=np.int64) for _ in range(3))
        saturated = np.zeros(limit.size, dtype=bool)
        idx = np.flatnonzero(limit > 0)
        top = int(limit.max(initial=0))
    else:
        torque, ty, target, top = start_torque, yield_torque, target_torque, int(max_blows)
        held = held_blow_peak(e, c, n)
        peak0 = rot0 = after0 = work0 = demand = math.nan
        total, blows, reached, yielded, saturated = 0.0, 0, 0, 0, False
    budget = step_budget(deadline, max_steps) if method == "simulation" else max_steps
    steps = 0
    first: BlowOutcome | None = None
    per_blow: dict[str, list[Any]] = {"peak": [], "rotation": [], "torque": [], "work": []}
    kept_peak, kept_rot, kept_torque, kept_work = per_blow.values()
    for i in range(top):
        if many:  # the designs still running (a slice while it is all of them: no copies)
            at: Any = slice(None) if idx.size == limit.size else idx
            t0 = torque[at]
            ty_i, target_i, held_i = _at(ty, at), _at(target, at), _at(held, at)
            args = (_at(e, at), _at(c, at), _at(k, at), t0, _at(b, at), _at(n, at))
        else:
            t0, ty_i, target_i, args, held_i = torque, ty, target, (e, c, k, torque, b, n), held
        if method == "energy":  # blow_step's energy branch, with the held peak worked out once
            peak, elastic, rot, work = energy_blow(*args, held_i)
        elif method == "rigid":
            peak, elastic, rot, work = blow_step(method, *args)
        else:
            left = budget - steps
            if left <= 0:
                raise BudgetExceeded(
                    f"the blows used the step budget ({budget}"
                    + ("" if deadline is None else " steps, what the time budget affords")
                    + f") after {i} blows; use fidelity 'energy' or fewer max_blows",
                    field="fidelity",
                    expected_steps=float(budget),
                )
            out = simulate_blow(
                p, t0, record=record_first and i == 0, max_steps=left, deadline=deadline
            )
            steps += out.steps
            if i == 0:
                first = out
            peak, elastic, rot, work = (
                out.peak_torque,
                out.torque_after,
                out.rotation,
                out.joint_work,
            )
        new = bolt_joint_torque(elastic, ty_i)
        past = elastic >= ty_i  # the bolt yields: another blow only stretches it at T_y
        hit = False if target_i is None else new >= target_i
        # the rigid rung's joint cannot rise past the blow's torque: one blow
        stuck = True if method == "rigid" else blow_gains_nothing(rot, new, t0)
        if keep:  # on arrays, each blow's row of all designs (NaN: stopped before it)
            blow = (
                (peak, rot, new, work)
                if not many
                else _rows(idx, limit.size, shape, peak, rot, new, work)
            )
            kept_peak.append(blow[0])
            kept_rot.append(blow[1])
            kept_torque.append(blow[2])
            kept_work.append(blow[3])
        if many:
            if i == 0:
                peak0[at], rot0[at], after0[at], work0[at] = peak, rot, new, work
            total[at] += work
            blows[at] = i + 1
            torque[at] = new
            # a mask over the running designs picks from idx; over all of them, it is one
            yielded[_pick(at, idx, past)] = i + 1
            demand[_pick(at, idx, past)] = elastic[past]
            reached[_pick(at, idx, hit)] = i + 1
            saturated[at] = stuck
            idx = idx[~(hit | past | stuck | (limit[at] <= i + 1))]
            if not idx.size:
                break
        else:
            if i == 0:
                peak0, rot0, after0, work0 = peak, rot, new, work
            total += work
            blows, torque = i + 1, new
            if past:
                yielded, demand = i + 1, elastic
            if hit:
                reached = i + 1
            saturated = stuck
            if hit or past or stuck:
                break
    # saturated: the last blow gained nothing, and neither the target nor yield stopped it
    saturated = saturated & (reached == 0) & (yielded == 0)
    found = (peak0, rot0, after0, work0, torque, total, blows, reached, saturated, yielded, demand)
    if many:
        found = tuple(v.reshape(shape) for v in found)
    return BlowSeries(*found, steps=steps, first=first, per_blow=per_blow if keep else {})


def _one_energy_blow(
    p: BlowProblem,
    start_torque: Any,
    target_torque: Any,
    yield_torque: Any,
    need: Collection[str],
    shape: tuple[int, ...],
) -> BlowSeries:
    """:func:`blow_series` of one energy blow on arrays: the fields in ``need`` alone.

    The same steps as the loop's first blow (:func:`energy_blow` with the held peak,
    bent over at yield by :func:`bolt_joint_torque`, stopped by the same rules), each
    worked out only where a field in ``need`` reads it; the others are None.

    At 50 rad/s, E = ½·0.02·50² = 25 J and T = √((25 + 60²/2000)/(½(1/2e4 + 1/1000)))
    = √(26.8/5.25e-4) = 225.937 N·m:

    >>> two = BlowProblem(0.02, 1e-3, 2.0e4, np.array([100.0, 50.0]), 1000.0)
    >>> s = blow_series(two, 60.0, "energy", max_blows=1, need=("peak", "torque_after"))
    >>> s.torque_after.round(3).tolist(), s.rotation
    ([440.346, 225.937], None)
    >>> full = blow_series(two, 60.0, "energy", max_blows=1)
    >>> bool((full.torque_after == s.torque_after).all() and (full.peak == s.peak).all())
    True
    """
    e, c, k, b, n = p.energy, p.stiffness, p.rate, p.breakaway, p.drive_torque
    t0 = np.asarray(start_torque, dtype=float)
    motion = not {"rotation", "work", "joint_work", "saturated"}.isdisjoint(need)
    peak, elastic, rot, work = energy_blow(e, c, k, t0, b, n, held_blow_peak(e, c, n), motion)
    fields: dict[str, Any] = dict.fromkeys(
        (
            *("peak", "rotation", "torque_after", "work", "final_torque", "joint_work"),
            *("blows", "blows_to_target", "saturated", "yield_blow", "elastic_demand"),
        )
    )

    def put(name: str, v: Any) -> None:  # an array of the designs' shape
        fields[name] = np.array(np.broadcast_to(v, shape)) if np.shape(v) != shape else v

    new = bolt_joint_torque(elastic, yield_torque)
    past: Any = None
    hit: Any = None
    if not {"yield_blow", "elastic_demand", "saturated"}.isdisjoint(need):
        past = elastic >= yield_torque  # the bolt yields
    if not {"blows_to_target", "saturated"}.isdisjoint(need):
        hit = np.zeros(shape, dtype=bool) if target_torque is None else new >= target_torque
    for name, v in (("peak", peak), ("rotation", rot), ("torque_after", new), ("work", work)):
        if name in need:
            put(name, v)
    if "final_torque" in need:
        put("final_torque", new)
    if "joint_work" in need:
        put("joint_work", 0.0 + work)  # the loop's sum from 0 over one blow
    if "blows" in need:
        fields["blows"] = np.ones(shape, dtype=np.int64)
    reached = None if hit is None else np.where(hit, 1, 0).astype(np.int64)
    yielded = None if past is None else np.where(past, 1, 0).astype(np.int64)
    if "blows_to_target" in need:
        put("blows_to_target", reached)
    if "yield_blow" in need:
        put("yield_blow", yielded)
    if "elastic_demand" in need:
        put("elastic_demand", np.where(past, elastic, np.nan))
    if "saturated" in need:
        stuck = blow_gains_nothing(rot, new, t0)
        put("saturated", stuck & (reached == 0) & (yielded == 0))
    return BlowSeries(**fields)


def _at(v: Any, at: Any) -> Any:
    """The designs ``at`` (indices or a slice) of an input of many; one number as it is."""
    return v[at] if isinstance(v, np.ndarray) else v


def _pick(at: Any, idx: np.ndarray, mask: Any) -> Any:
    """The designs where ``mask`` (over the running ones) holds, as an index into all."""
    return mask if isinstance(at, slice) else idx[mask]


def _rows(idx: np.ndarray, size: int, shape: tuple[int, ...], *values: np.ndarray) -> list[Any]:
    """One blow's values of the designs ``idx`` as rows over all designs (NaN elsewhere)."""
    rows = []
    for v in values:
        row = np.full(size, np.nan)
        row[idx] = v
        rows.append(row.reshape(shape))
    return rows
