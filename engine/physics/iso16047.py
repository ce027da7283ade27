r"""Friction coefficients from a torque/clamp-force test (ISO 16047).

A test tightens a bolt in a fixture that measures the tightening torque T, the
thread torque T_th (the torque the bolt's shank carries) and the clamp force F.
The thread and bearing torques of an ISO metric thread,

.. math::
    T_{th} = F\left(\frac{P}{2\pi} + \frac{d_2}{2\cos 30^\circ}\,\mu_{th}\right),
    \qquad T - T_{th} = F \frac{D_b}{2} \mu_b,

solved for the coefficients give ISO 16047's evaluation. The standard is not
public: the relations are the ones it evaluates, in the form of VDI 2230-1 R13
(:func:`engine.physics.preload.vdi_thread_torque`, whose 0.16 and 0.58 are
1/(2π) and 1/(2 cos 30°) rounded); the exact constants are used here (see
ISO 16047 in docs/sources.md). All functions take floats or numpy arrays (one
test per element).
"""

from __future__ import annotations

import math
from typing import Any

#: P/(2π): the pitch's share of the thread torque per newton, per metre of pitch.
_LEAD_FACTOR = 1.0 / (2.0 * math.pi)
#: d2/(2 cos 30°): the thread friction's lever per metre of pitch diameter (60° thread).
_FLANK_FACTOR = 1.0 / (2.0 * math.cos(math.radians(30.0)))


def mean_bearing_diameter(outer_diameter: Any, inner_diameter: Any) -> Any:
    r"""Mean diameter of the bearing face, the lever of the bearing friction.

    .. math::
        D_b = \frac{d_o + d_i}{2}

    Parameters
    ----------
    outer_diameter : float
        Outside diameter d_o of the bearing contact (d_w of the head or nut), [m]
    inner_diameter : float
        Inside diameter d_i of the bearing contact (the hole of the test washer), [m]

    Returns
    -------
    float
        D_b, [m]

    Notes
    -----
    ISO 16047 (D_Km = (d_w + d_h)/2 in VDI 2230-1 R13).

    Examples
    --------
    M10 hexagon head on a medium clearance hole: (16.63 + 11) / 2

    >>> round(mean_bearing_diameter(0.01663, 0.011) * 1e3, 3)
    13.815
    """
    return 0.5 * (outer_diameter + inner_diameter)


def torque_coefficient(tightening_torque: Any, clamp_force: Any, diameter: Any) -> Any:
    r"""Torque coefficient (nut factor) of one test.

    .. math::
        K = \frac{T}{F\,d}

    Parameters
    ----------
    tightening_torque : float
        T, [N*m]
    clamp_force : float
        F (> 0), [N]
    diameter : float
        Nominal thread diameter d, [m]

    Returns
    -------
    float
        K, [-]

    Notes
    -----
    ISO 16047.

    Examples
    --------
    >>> round(torque_coefficient(50.0, 25e3, 0.010), 3)
    0.2
    """
    return tightening_torque / (clamp_force * diameter)


def thread_friction_from_test(
    thread_torque: Any, clamp_force: Any, pitch: Any, pitch_diameter: Any
) -> Any:
    r"""Thread friction coefficient from the thread torque of a test.

    .. math::
        \mu_{th} = \frac{T_{th}/F - P/(2\pi)}{d_2/(2\cos 30^\circ)}

    Parameters
    ----------
    thread_torque : float
        T_th, [N*m]
    clamp_force : float
        F (> 0), [N]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]

    Returns
    -------
    float
        μ_th, [-]

    Notes
    -----
    ISO 16047 (its constants 0.159 and 0.577 are 1/(2π) and 1/(2 cos 30°)).
    The relation drops the product tan ψ tan ρ′ of the exact helix relation
    :func:`engine.physics.preload.thread_torque`, so it reads μ_th about
    1 % high at μ = 0.12 on an M10 (tests/validation/test_iso16047_derivation.py).

    Examples
    --------
    M10: P = 1.5 mm, d2 = 9.026 mm; F = 20 kN and T_th = 17.3 N·m:
    (0.865e-3 − 0.2387e-3) / 5.2112e-3

    >>> round(thread_friction_from_test(17.3, 20e3, 0.0015, 0.009026), 4)
    0.1202
    """
    return (thread_torque / clamp_force - _LEAD_FACTOR * pitch) / (_FLANK_FACTOR * pitch_diameter)


def bearing_friction_from_test(
    tightening_torque: Any, thread_torque: Any, clamp_force: Any, bearing_diameter: Any
) -> Any:
    r"""Bearing (under-head) friction coefficient from the torques of a test.

    .. math::
        \mu_b = \frac{T - T_{th}}{F\,D_b/2}

    Parameters
    ----------
    tightening_torque : float
        T, [N*m]
    thread_torque : float
        T_th, [N*m]
    clamp_force : float
        F (> 0), [N]
    bearing_diameter : float
        Mean bearing diameter D_b (:func:`mean_bearing_diameter`), [m]

    Returns
    -------
    float
        μ_b, [-]

    Notes
    -----
    ISO 16047. The bearing face is taken as a thin ring at D_b/2; the
    friction radius of a full annulus under uniform pressure
    (:func:`engine.physics.preload.friction_radius`) is a little larger.

    Examples
    --------
    (40 − 17.3) / (20e3 × 6.9075e-3)

    >>> round(bearing_friction_from_test(40.0, 17.3, 20e3, 0.013815), 4)
    0.1643
    """
    return (tightening_torque - thread_torque) / (clamp_force * 0.5 * bearing_diameter)


def total_friction_from_test(
    tightening_torque: Any,
    clamp_force: Any,
    pitch: Any,
    pitch_diameter: Any,
    bearing_diameter: Any,
) -> Any:
    r"""Total friction coefficient: one μ for thread and bearing that gives the test's torque.

    .. math::
        \mu_{tot} = \frac{T/F - P/(2\pi)}{d_2/(2\cos 30^\circ) + D_b/2}

    Parameters
    ----------
    tightening_torque : float
        T, [N*m]
    clamp_force : float
        F (> 0), [N]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    bearing_diameter : float
        Mean bearing diameter D_b, [m]

    Returns
    -------
    float
        μ_tot, [-]

    Notes
    -----
    ISO 16047: T = F (P/(2π) + μ_tot (d2/(2 cos 30°) + D_b/2)) solved for μ_tot;
    it lies between μ_th and μ_b, weighted by their levers.

    Examples
    --------
    (2e-3 − 0.2387e-3) / (5.2112e-3 + 6.9075e-3)

    >>> round(total_friction_from_test(40.0, 20e3, 0.0015, 0.009026, 0.013815), 4)
    0.1453
    """
    return (tightening_torque / clamp_force - _LEAD_FACTOR * pitch) / (
        _FLANK_FACTOR * pitch_diameter + 0.5 * bearing_diameter
    )


__all__ = [
    "bearing_friction_from_test",
    "mean_bearing_diameter",
    "thread_friction_from_test",
    "torque_coefficient",
    "total_friction_from_test",
]
