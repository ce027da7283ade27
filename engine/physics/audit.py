r"""Audit torques of a tightened joint: what a wrench should read when the joint is checked.

Three audit methods are in use (public secondary sources, listed under [TorqueAudit] in
docs/sources.md): the first motion in the tightening direction (the peak before the
fastener turns on), the breakaway in the loosening direction, and the mark torque (loosen,
then tighten back to a mark; the torque at the mark). Each reads a torque that depends on
the preload left in the joint and on the friction at the moment of reading:

.. math::
    M = F\,(\pm k_P + r\,k_\mu) + M_{\ddot u}

with k_P = 0.16 P the thread's pitch term per newton of preload (VDI 2230-1 R13), k_μ the
friction part of the torque per newton (thread 0.58 d2 μ_G plus bearing μ_K D_Km/2), r the
static friction's excess over the kinetic friction the tightening saw (1 where the fastener
is already moving, as at the mark), + in the tightening and − in the loosening direction
(the pitch term helps loosening: VDI 2230-1 R13's loosening torque), and M_ü the
prevailing torque. The preload is the one the tightening torque gave at that friction,
less the embedding loss F_Z after the joint has settled (VDI 2230-1 R4).

All functions take floats or numpy arrays of one shape.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import joint as jt
from . import preload as pl

#: The directions a wrench turns: +1 tightening (first motion, mark), −1 loosening (breakaway).
TIGHTENING, LOOSENING = 1.0, -1.0


def pitch_torque_per_preload(pitch: Any, pitch_diameter: Any) -> Any:
    r"""The thread's pitch term: thread torque per newton of preload without friction.

    .. math::
        k_P = \frac{M_G(\mu_G = 0)}{F_M} = 0.16\,P

    Parameters
    ----------
    pitch : float
        Thread pitch P, [m]
    pitch_diameter : float
        Pitch diameter d2, [m]

    Returns
    -------
    float
        k_P, [m]

    Notes
    -----
    VDI 2230-1 R13's thread torque (:func:`engine.physics.preload.vdi_thread_torque`) at
    μ_G = 0 per newton: the torque that lifts the load up the helix. It opposes the
    wrench when tightening and helps it when loosening.

    Examples
    --------
    M12 (P = 1.75 mm): 0.16 · 1.75 mm

    >>> round(float(pitch_torque_per_preload(0.00175, 0.010863)) * 1e3, 6)
    0.28
    """
    return pl.vdi_thread_torque(1.0, pitch, pitch_diameter, 0.0)


def audit_torque_per_preload(
    pitch_term: Any, friction_term: Any, static_ratio: Any, direction: float
) -> Any:
    r"""Torque per newton of preload a wrench meets when the fastener starts to turn.

    .. math::
        k_{audit} = \pm k_P + r\,k_\mu

    Parameters
    ----------
    pitch_term : float
        k_P = 0.16 P (:func:`pitch_torque_per_preload`), [m]
    friction_term : float
        k_μ: the friction part of the tightening torque per newton, thread 0.58 d2 μ_G plus
        bearing μ_K D_Km/2, at the kinetic friction of the tightening, [m]
    static_ratio : float
        r = μ_static/μ_kinetic (≥ 1; 1 where the fastener is already turning), [-]
    direction : float
        +1 tightening (first motion, mark), −1 loosening (breakaway), [-]

    Returns
    -------
    float
        k_audit, [m]; negative in the loosening direction where the joint is not
        self-locking (it would turn loose by itself)

    Notes
    -----
    VDI 2230-1 R13: tightening M_A = F_M (0.16 P + 0.58 d2 μ_G + μ_K D_Km/2) and
    loosening M_L = F (−0.16 P + 0.58 d2 μ_G + μ_K D_Km/2); here with both friction
    coefficients raised by the static excess r, the same on thread and bearing face.

    Examples
    --------
    M12, μ = 0.12: k_μ = 0.58 · 10.863 mm · 0.12 + 0.12 · 7.5 mm = 1.65607 mm

    >>> k_mu = 0.58 * 0.010863 * 0.12 + 0.12 * 0.0075
    >>> round(audit_torque_per_preload(0.00028, k_mu, 1.0, LOOSENING) * 1e3, 4)
    1.3761
    """
    return direction * pitch_term + static_ratio * friction_term


def audit_torque(
    torque: Any,
    prevailing_torque: Any,
    pitch_term: Any,
    friction_term: Any,
    static_ratio: Any,
    embedding_loss: Any,
    direction: float,
) -> Any:
    r"""The torque an audit reads on a joint tightened to ``torque``.

    .. math::
        F = \max\!\left(\frac{M_A - M_{\ddot u}}{k_P + k_\mu} - F_Z,\ 0\right), \qquad
        M = F\,(\pm k_P + r\,k_\mu) + M_{\ddot u}

    Parameters
    ----------
    torque : float
        M_A, the tightening torque the tool gave (including the prevailing torque), [N*m]
    prevailing_torque : float
        M_ü, the prevailing (locking) torque, which gives no preload, [N*m]
    pitch_term : float
        k_P = 0.16 P, [m]
    friction_term : float
        k_μ at the kinetic friction of the tightening, [m]
    static_ratio : float
        r = μ_static/μ_kinetic at the reading, [-]
    embedding_loss : float
        F_Z, the preload lost to embedding since the tightening (0: read at once), [N]
    direction : float
        +1 tightening, −1 loosening, [-]

    Returns
    -------
    float
        M, [N*m]

    Notes
    -----
    The preload is VDI 2230-1 R13 solved for F_M at this friction
    (:func:`engine.physics.joint.preload_bounds_from_torque` with one friction corner),
    less F_Z (VDI 2230-1 R4); the reading is :func:`audit_torque_per_preload` times it,
    plus the prevailing torque, which resists turning either way. With r = 1, F_Z = 0 and
    the tightening direction it gives back M_A: the mark torque of a joint read at once.

    Examples
    --------
    Read at once, kinetic friction: the tightening torque itself

    >>> round(float(audit_torque(80.0, 0.0, 0.00028, 0.00165607, 1.0, 0.0, TIGHTENING)), 9)
    80.0

    A joint that lost a third of its preload reads two thirds (tank-tread bolts of
    [Bickford]: 150 lb·ft, stretch 0.0015 in relaxing to 0.001 in, restarted at 100 lb·ft)

    >>> f_m = 150.0 / (0.00028 + 0.00165607)
    >>> round(float(audit_torque(150.0, 0.0, 0.00028, 0.00165607, 1.0, f_m / 3, TIGHTENING)), 6)
    100.0
    """
    per_newton = pitch_term + friction_term
    preload, _ = jt.preload_bounds_from_torque(
        torque, 0.0, prevailing_torque, per_newton, per_newton
    )
    residual = np.maximum(preload - embedding_loss, 0.0)
    reading = audit_torque_per_preload(pitch_term, friction_term, static_ratio, direction)
    return residual * reading + prevailing_torque


def audit_window(
    torque_min: Any,
    torque_max: Any,
    prevailing_torque: Any,
    pitch_term: Any,
    friction_term_min: Any,
    friction_term_max: Any,
    static_ratio_min: Any,
    static_ratio_max: Any,
    embedding_loss: Any,
    direction: float,
) -> tuple[Any, Any]:
    r"""Acceptance limits of an audit: the least and most it can read over the process box.

    .. math::
        [M_{min}, M_{max}] = \left[\min, \max\right]_{M_A,\ k_\mu,\ r}\ M(M_A, k_\mu, r)

    over M_A ∈ [M_A,min, M_A,max], k_μ ∈ [k_μ,min, k_μ,max], r ∈ [r_min, r_max]; M is
    :func:`audit_torque`.

    Parameters
    ----------
    torque_min, torque_max : float
        The tool's torque band, [N*m]
    prevailing_torque : float
        M_ü, [N*m]
    pitch_term : float
        k_P = 0.16 P, [m]
    friction_term_min, friction_term_max : float
        k_μ at the lowest and highest kinetic friction of the lot, [m]
    static_ratio_min, static_ratio_max : float
        The range of r = μ_static/μ_kinetic, [-]
    embedding_loss : float
        F_Z (0 before embedding), [N]
    direction : float
        +1 tightening, −1 loosening, [-]

    Returns
    -------
    tuple of float
        (M_min, M_max), [N*m]

    Notes
    -----
    M is linear in M_A and in r, so their extremes lie at the ends of their ranges. In
    u = k_P + k_μ, M = (a + r u)(T/u − F_Z) + M_ü with T = M_A − M_ü and
    a = ±k_P − r k_P, so M'' = 2 a T/u³: where a < 0 (loosening always; tightening with
    r > 1) M is concave in u and its largest value may lie inside the friction range, at
    u* = √(−a T/(r F_Z)); where the preload is all lost (u ≥ T/F_Z) M = M_ü. The extremes
    are therefore among u_min, u_max, u* and T/F_Z, each clipped to the range: exact, not
    a grid.

    Examples
    --------
    Before embedding, kinetic friction, tightening direction: the torque band itself

    >>> lo, hi = audit_window(76.0, 84.0, 0.0, 0.00028, 0.0011, 0.0022, 1.0, 1.0, 0.0, 1.0)
    >>> round(float(lo), 9), round(float(hi), 9)
    (76.0, 84.0)
    """
    t = np.stack(np.broadcast_arrays(*map(np.asarray, (torque_min, torque_max))))
    r = np.stack(np.broadcast_arrays(*map(np.asarray, (static_ratio_min, static_ratio_max))))
    # corners of M_A and r: axes (torque, ratio, ...design)
    t = t[:, None, ...]
    r = r[None, :, ...]
    k_p = np.asarray(pitch_term)
    f_z = np.asarray(embedding_loss)
    m_u = np.asarray(prevailing_torque)
    u_lo = k_p + np.asarray(friction_term_min)
    u_hi = k_p + np.asarray(friction_term_max)
    lifted = t - m_u
    a = direction * k_p - r * k_p
    with np.errstate(divide="ignore", invalid="ignore"):
        inner = np.sqrt(np.where((a < 0.0) & (f_z > 0.0), -a * lifted / (r * f_z), 0.0))
        lost = np.where(f_z > 0.0, lifted / f_z, u_hi)
    candidates = [u_lo, u_hi, inner, lost]
    readings = []
    for u in candidates:
        u = np.clip(u, u_lo, u_hi)
        k_mu = u - k_p
        readings.append(audit_torque(t, m_u, k_p, k_mu, r, f_z, direction))
    every = np.stack(np.broadcast_arrays(*readings))  # (candidate, torque, ratio, ...design)
    flat = every.reshape((-1, *every.shape[3:]))
    return flat.min(axis=0), flat.max(axis=0)


__all__ = [
    "LOOSENING",
    "TIGHTENING",
    "audit_torque",
    "audit_torque_per_preload",
    "audit_window",
    "pitch_torque_per_preload",
]
