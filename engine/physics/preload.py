r"""Bolt preload: how much, what torque gives it, and how elongation and angle relate to it.

Pure functions on SI floats after the review [004] (Ukrainian; the source of
the scatter figures and the control methods) and, where engineers check the
numbers, VDI 2230 Part 1 (2015), whose conventions the service uses by
default. Each function names the equation it implements; where [004] and
VDI 2230 differ, both are offered and the docstring says how.

Three equations of [004] are missing from the text we have (eq. 1, 10 and
12 were lost with the figures): the standard textbook relations stand in for
them: the thread torque ``M_p = F0 (d2/2) tan(ψ + ρ')`` for eq. 10 and the
friction radius of a flat annulus ``R_T = (D_f³ − d_h³) / (3 (D_f² − d_h²))``
for eq. 12. Eq. 1 (the tightness condition) is not needed here.

The functions use numpy ufuncs, so most of them also take arrays.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from ..core.errors import InputOutOfRange
from ..numerics.ode import sqrt, where

#: cos 30°: half the 60° flank angle of an ISO metric thread.
COS_HALF_FLANK = math.cos(math.radians(30.0))

#: [004, eq. 2]: the factor υ by which the design preload exceeds the required clamp force.
PRELOAD_FACTOR_RANGE: dict[str, tuple[float, float]] = {
    "steady": (1.25, 2.0),
    "varying": (2.5, 4.0),
}


def lead_angle(pitch: float, pitch_diameter: float) -> float:
    r"""Lead angle ψ of a single-start thread on its pitch diameter.

    .. math::
        \psi = \arctan\frac{P}{\pi d_2}

    Parameters
    ----------
    pitch : float
        Thread pitch P, [m]
    pitch_diameter : float
        Pitch diameter d2, [m]

    Returns
    -------
    float
        ψ, [rad]

    Notes
    -----
    [004, eq. 10] (the standard relation standing in for the lost equation).

    Examples
    --------
    >>> round(math.degrees(lead_angle(0.00175, 0.010863)), 3)
    2.935
    """
    return np.arctan(pitch / (math.pi * pitch_diameter))


def thread_friction_angle(thread_friction: float) -> float:
    r"""Apparent friction angle ρ' of a 60° thread.

    .. math::
        \rho' = \arctan\frac{\mu_G}{\cos 30°}

    Parameters
    ----------
    thread_friction : float
        Thread friction coefficient μ_G (f_p in [004]), [-]

    Returns
    -------
    float
        ρ', [rad]

    Notes
    -----
    [004, eq. 10]; the flank normal force of a 60° thread is F/cos 30°, so
    the effective coefficient is μ_G/cos 30° = 1.155 μ_G (the 1.155 of VDI 2230
    and of [004, eq. 15]).

    Examples
    --------
    >>> round(math.degrees(thread_friction_angle(0.12)), 3)
    7.889
    """
    return np.arctan(thread_friction / COS_HALF_FLANK)


def torsion_factor(
    pitch: float,
    pitch_diameter: float,
    stress_diameter: float,
    thread_friction: float,
    convention: str = "vdi2230",
) -> float:
    r"""Factor β by which the thread torque raises the equivalent stress of the bolt.

    .. math::
        \beta = \sqrt{1 + 3\left(\frac{\tau}{\sigma}\right)^2}

    with τ/σ of :func:`torsion_stress_ratio` by convention.

    Parameters
    ----------
    pitch : float
        Thread pitch P, [m]
    pitch_diameter : float
        Pitch diameter d2, [m]
    stress_diameter : float
        Diameter d0 of the stressed section (the stress diameter for a plain bolt), [m]
    thread_friction : float
        Thread friction coefficient μ_G, [-]
    convention : str
        ``"vdi2230"`` or ``"elastic"``

    Returns
    -------
    float
        β, [-]

    Notes
    -----
    [004, eq. 5] (``elastic``) and VDI 2230-1:2015 step R7 (``vdi2230``): von Mises'
    σ_red = √(σ² + 3τ²) = β σ. [004] quotes β = 1.19…1.50.

    Examples
    --------
    M12 coarse, μ_G = 0.12: d2 = 10.863 mm, d0 = 10.358 mm

    >>> round(float(torsion_factor(0.00175, 0.010863, 0.010358, 0.12)), 4)
    1.1259
    >>> round(float(torsion_factor(0.00175, 0.010863, 0.010358, 0.12, "elastic")), 4)
    1.2176
    """
    # the ratio is squared where it was made (numpy squares a temporary array in place)
    return sqrt(  # math for a float, numpy for arrays
        1.0
        + 3.0
        * torsion_stress_ratio(pitch, pitch_diameter, stress_diameter, thread_friction, convention)
        ** 2
    )


def torsion_stress_ratio(
    pitch: float,
    pitch_diameter: float,
    stress_diameter: float,
    thread_friction: float,
    convention: str = "vdi2230",
) -> float:
    r"""Ratio τ/σ of the torsional to the axial stress in the bolt while it is tightened.

    .. math::
        \text{vdi2230:}\quad \frac{\tau}{\sigma} = \frac{3}{2}\frac{d_2}{d_0}
            \left(\frac{P}{\pi d_2} + 1.155\,\mu_G\right)
        \qquad
        \text{elastic:}\quad \frac{\tau}{\sigma} = 2\frac{d_2}{d_0}\tan(\psi + \rho')

    Parameters
    ----------
    pitch : float
        Thread pitch P, [m]
    pitch_diameter : float
        Pitch diameter d2, [m]
    stress_diameter : float
        Diameter d0 of the stressed section (the stress diameter for a plain bolt), [m]
    thread_friction : float
        Thread friction coefficient μ_G, [-]
    convention : str
        ``"vdi2230"`` or ``"elastic"``

    Returns
    -------
    float
        τ/σ, [-]

    Notes
    -----
    ``elastic`` is [004, eq. 5]: σ = F/A0 and τ = M_p / (π d0³/16) with the
    thread torque of [004, eq. 10], which gives τ/σ = 2 (d2/d0) tan(ψ + ρ').
    ``vdi2230`` is VDI 2230-1:2015, step R7: the torsional stress is reduced
    to 3/4 of its elastic value (factor 3/2 instead of 2) because the section
    yields partly during tightening, and tan(ψ + ρ') is linearised to
    tan ψ + 1.155 μ_G.

    Examples
    --------
    M12 coarse, μ_G = 0.12: 1.5 · (10.863/10.358) · (1.75/(π · 10.863) + 0.12/cos 30°)

    >>> round(float(torsion_stress_ratio(0.00175, 0.010863, 0.010358, 0.12)), 4)
    0.2986
    """
    if convention == "vdi2230":
        return (
            1.5
            * (pitch_diameter / stress_diameter)
            * (pitch / (math.pi * pitch_diameter) + thread_friction / COS_HALF_FLANK)
        )
    if convention == "elastic":
        return (
            2.0
            * (pitch_diameter / stress_diameter)
            * np.tan(lead_angle(pitch, pitch_diameter) + thread_friction_angle(thread_friction))
        )
    raise InputOutOfRange(
        f"preload_convention = {convention!r} is not allowed: must be 'vdi2230' or 'elastic'",
        field="preload_convention",
    )


def assembly_preload(
    yield_strength: float, stress_area: float, torsion: float, utilization: float = 0.9
) -> float:
    r"""Largest assembly preload whose equivalent stress is ν times the yield strength.

    .. math::
        F_M = \frac{\nu\,R_{p0.2}\,A_0}{\beta}

    Parameters
    ----------
    yield_strength : float
        Minimum yield strength R_p0.2 (σ_T in [004]), [Pa]
    stress_area : float
        Area A0 of the stressed section (the stress area A_s), [m²]
    torsion : float
        Torsion factor β from :func:`torsion_factor`, [-]
    utilization : float
        ν, the share of the yield strength the equivalent stress may use, [-]

    Returns
    -------
    float
        F_M, [N]

    Notes
    -----
    With β of the ``vdi2230`` convention this is F_M,zul of VDI 2230-1:2015,
    step R7 (the basis of its Table A1, ν = 0.9). With the ``elastic`` β it
    is the upper limit of [004, eq. 3], σ0 ≤ ξ σ_T / (n_T β), with
    ν = ξ / n_T (plain shank ξ = 1 and n_T = 1.2…1.4 give ν = 0.71…0.83 and
    the rule σ0 = (0.5…0.7) σ_T of [004, eq. 6]).

    Examples
    --------
    M12 8.8, μ_G = 0.12: 0.9 · 640 MPa · 84.27 mm² / 1.1259

    >>> round(assembly_preload(640e6, 84.27e-6, 1.1259) / 1e3, 2)
    43.11
    """
    return utilization * yield_strength * stress_area / torsion


def equivalent_stress(preload: float, stress_area: float, torsion: float) -> float:
    r"""Von Mises equivalent stress of the bolt during tightening.

    .. math::
        \sigma_{red} = \sqrt{\sigma^2 + 3\tau^2} = \beta\,\frac{F}{A_0}

    Parameters
    ----------
    preload : float
        Bolt force F, [N]
    stress_area : float
        A0, [m²]
    torsion : float
        β, [-]

    Returns
    -------
    float
        σ_red, [Pa]

    Notes
    -----
    [004, eq. 5]; VDI 2230-1:2015 step R7 (σ_red,M).

    Examples
    --------
    >>> round(equivalent_stress(43110.0, 84.27e-6, 1.1259) / 1e6, 1)
    576.0
    """
    return torsion * preload / stress_area


def thread_torque(
    preload: float, pitch: float, pitch_diameter: float, thread_friction: float
) -> float:
    r"""Torque to turn the nut against the thread under a preload (exact relation).

    .. math::
        M_p = F_0 \frac{d_2}{2}\tan(\psi + \rho')

    Parameters
    ----------
    preload : float
        F0, [N]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    thread_friction : float
        μ_G (f_p), [-]

    Returns
    -------
    float
        M_p, [N*m]

    Notes
    -----
    [004, eq. 10], lost from the text; the standard textbook relation
    stands in (see [004] in docs/sources.md).

    Examples
    --------
    M12, μ_G = 0.12, F0 = 40 kN: 40000 · 0.0054315 · tan(2.935° + 7.889°)

    >>> round(float(thread_torque(40e3, 0.00175, 0.010863, 0.12)), 2)
    41.54
    """
    return (
        preload
        * 0.5
        * pitch_diameter
        * np.tan(lead_angle(pitch, pitch_diameter) + thread_friction_angle(thread_friction))
    )


def friction_radius(outer_diameter: float, inner_diameter: float) -> float:
    r"""Friction radius of a flat annular bearing face under uniform pressure.

    .. math::
        R_T = \frac{D_f^3 - d_h^3}{3(D_f^2 - d_h^2)}
            = \frac{D_f^2 + D_f d_h + d_h^2}{3(D_f + d_h)}

    Parameters
    ----------
    outer_diameter : float
        Outer diameter D_f of the bearing face (d_w of the head), [m]
    inner_diameter : float
        Inner diameter d_h (the clearance hole), [m]

    Returns
    -------
    float
        R_T, [m]

    Notes
    -----
    [004, eq. 12], lost from the text; the standard relation stands in. The
    second form divides out the common factor D_f − d_h, so it stays exact
    as D_f → d_h, where R_T → (D_f + d_h)/4, half the mean diameter
    D_Km = (D_f + d_h)/2. R_T exceeds D_Km/2 by (D_f − d_h)² / (12 (D_f + d_h)).

    Examples
    --------
    >>> round(friction_radius(0.01663, 0.0135) * 1e3, 4)
    7.5596
    >>> round(friction_radius(0.01, 0.01), 12)
    0.005
    """
    outer, inner = outer_diameter, inner_diameter
    return (outer * outer + outer * inner + inner * inner) / (3.0 * (outer + inner))


def bearing_torque(preload: float, bearing_friction: float, radius: float) -> float:
    r"""Friction torque under the nut (or head) face.

    .. math::
        M_T = f_T F_0 R_T

    Parameters
    ----------
    preload : float
        F0, [N]
    bearing_friction : float
        μ_K (f_T), [-]
    radius : float
        Friction radius R_T, [m]

    Returns
    -------
    float
        M_T, [N*m]

    Notes
    -----
    [004, eq. 11].

    Examples
    --------
    >>> round(bearing_torque(40e3, 0.12, 0.0075579), 2)
    36.28
    """
    return bearing_friction * preload * radius


def vdi_thread_torque(
    preload: float, pitch: float, pitch_diameter: float, thread_friction: float
) -> float:
    r"""Thread part of the VDI 2230 tightening torque.

    .. math::
        M_G = F_M (0.16 P + 0.58\,d_2\,\mu_G)

    Parameters
    ----------
    preload : float
        F_M, [N]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    thread_friction : float
        μ_G, [-]

    Returns
    -------
    float
        M_G, [N*m]

    Notes
    -----
    VDI 2230-1:2015 step R13: 0.16 ≈ 1/(2π) and 0.58 ≈ 1.155/2 linearise
    (d2/2) tan(ψ + ρ'); the product tan ψ tan ρ' dropped makes it smaller
    than :func:`thread_torque` by a fraction of about tan ψ tan ρ' (< 1 %).

    Examples
    --------
    >>> round(vdi_thread_torque(40e3, 0.00175, 0.010863, 0.12), 2)
    41.44
    """
    return preload * (0.16 * pitch + 0.58 * pitch_diameter * thread_friction)


def vdi_tightening_torque(
    preload: float,
    pitch: float,
    pitch_diameter: float,
    thread_friction: float,
    bearing_friction: float,
    bearing_outer_diameter: float,
    hole_diameter: float,
) -> float:
    r"""Tightening torque by VDI 2230.

    .. math::
        M_A = F_M\left(0.16 P + 0.58\,d_2\,\mu_G + \mu_K \frac{D_{Km}}{2}\right),
        \qquad D_{Km} = \frac{d_w + d_h}{2}

    Parameters
    ----------
    preload : float
        F_M, [N]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    thread_friction : float
        μ_G, [-]
    bearing_friction : float
        μ_K, [-]
    bearing_outer_diameter : float
        d_w, [m]
    hole_diameter : float
        d_h, [m]

    Returns
    -------
    float
        M_A, [N*m]

    Notes
    -----
    VDI 2230-1:2015 step R13 (its Table A1 uses it with ν = 0.9).

    Examples
    --------
    M12 8.8, μ = 0.12, F_M = 43.11 kN, d_w = 16.63 mm, d_h = 13.5 mm

    >>> round(vdi_tightening_torque(43110, 0.00175, 0.010863, 0.12, 0.12, 0.01663, 0.0135), 1)
    83.6
    """
    k_thread, k_bearing = tightening_torque_per_preload(
        pitch,
        pitch_diameter,
        pitch_diameter,  # the nominal diameter enters only the "approx" formula
        thread_friction,
        bearing_friction,
        bearing_outer_diameter,
        hole_diameter,
        "vdi2230",
    )
    return preload * (k_thread + k_bearing)


def approximate_tightening_torque(
    preload: float,
    diameter: float,
    pitch: float,
    thread_friction: float,
    bearing_friction: float,
    radius: float,
) -> float:
    r"""Approximate wrench torque with d2 ≈ d.

    .. math::
        M_w \approx F_0\left[0.5\,d\left(\frac{P}{\pi d} + 1.15 f_p\right) + f_T R_T\right]

    Parameters
    ----------
    preload : float
        F0, [N]
    diameter : float
        Nominal diameter d, [m]
    pitch : float
        P, [m]
    thread_friction : float
        f_p, [-]
    bearing_friction : float
        f_T, [-]
    radius : float
        Friction radius R_T; [004] takes R_T ≈ 0.25 (D_f + d_h), [m]

    Returns
    -------
    float
        M_w, [N*m]

    Notes
    -----
    [004, eq. 15]. With one coefficient f = f_p = f_T it is [004, eq. 19],
    M_w = 0.5 F0 d [P/(π d) + f (1.15 + 2 R_T/d)], the same number.

    Examples
    --------
    >>> round(approximate_tightening_torque(40e3, 0.012, 0.00175, 0.12, 0.12, 0.0075), 2)
    80.26
    """
    return preload * (
        0.5 * diameter * (pitch / (math.pi * diameter) + 1.15 * thread_friction)
        + bearing_friction * radius
    )


def single_friction_tightening_torque(
    preload: float, diameter: float, pitch: float, friction: float, radius: float
) -> float:
    r"""Approximate wrench torque with one friction coefficient for thread and face.

    .. math::
        M_w = 0.5 F_0 d\left[\frac{P}{\pi d} + f\left(1.15 + \frac{2 R_T}{d}\right)\right]

    Parameters
    ----------
    preload : float
        F0, [N]
    diameter : float
        d, [m]
    pitch : float
        P, [m]
    friction : float
        f, the reduced friction coefficient, [-]
    radius : float
        R_T, [m]

    Returns
    -------
    float
        M_w, [N*m]

    Notes
    -----
    [004, eq. 19].

    Examples
    --------
    >>> round(single_friction_tightening_torque(40e3, 0.012, 0.00175, 0.12, 0.0075), 2)
    80.26
    """
    return (
        0.5
        * preload
        * diameter
        * (pitch / (math.pi * diameter) + friction * (1.15 + 2.0 * radius / diameter))
    )


def ideal_torque(preload: float, pitch: float) -> float:
    r"""Wrench torque of a frictionless joint: the work of lifting the thread.

    .. math::
        M^* = \frac{F_0 P}{2\pi}

    Parameters
    ----------
    preload : float
        F0, [N]
    pitch : float
        P, [m]

    Returns
    -------
    float
        M*, [N*m]

    Notes
    -----
    [004, eq. 14]; normally 5…15 % of the wrench torque, the rest is friction.

    Examples
    --------
    >>> round(ideal_torque(40e3, 0.00175), 3)
    11.141
    """
    return preload * pitch / (2.0 * math.pi)


def rule_of_thumb_torque(preload: float, diameter: float) -> float:
    r"""The review's quick estimate of the wrench torque from the preload.

    .. math::
        M_w \approx 0.2\,F_0\,d

    Parameters
    ----------
    preload : float
        F0, [N]
    diameter : float
        d, [m]

    Returns
    -------
    float
        M_w, [N*m]

    Notes
    -----
    [004, eq. 16]: eq. 15 with f_p = f_T = 0.15, R_T ≈ 0.7 d, P/d ≈ 1/8.

    Examples
    --------
    >>> round(rule_of_thumb_torque(40e3, 0.012), 1)
    96.0
    """
    return 0.2 * preload * diameter


def rule_of_thumb_torque_from_yield(yield_strength: float, diameter: float) -> float:
    r"""The review's quick estimate of the wrench torque from the yield strength alone.

    .. math::
        M_w \approx 0.07\,\sigma_T\,d^3

    Parameters
    ----------
    yield_strength : float
        σ_T, [Pa]
    diameter : float
        d, [m]

    Returns
    -------
    float
        M_w, [N*m]

    Notes
    -----
    [004, eq. 17, 18]: eq. 16 with σ0 = 0.6 σ_T on the core section and
    d1 ≈ 0.85 d (0.2 · 0.6 · π/4 · 0.85² = 0.068). It assumes a preload of
    0.6 σ_T, not the one the rest of the calculation uses.

    d³ is written as two products, not a power: numpy's power of an array and
    Python's of a float may round differently (by an ulp), products round alike,
    so a sweep gives the single run's value bit for bit.

    Examples
    --------
    >>> round(rule_of_thumb_torque_from_yield(640e6, 0.012), 1)
    77.4
    >>> import numpy as np
    >>> d = [0.005, 0.01, 0.02]
    >>> rule_of_thumb_torque_from_yield(640e6, np.array(d)).tolist() == [
    ...     rule_of_thumb_torque_from_yield(640e6, v) for v in d
    ... ]
    True
    """
    return 0.07 * yield_strength * (diameter * diameter * diameter)


def tightening_torque_per_preload(
    pitch: float,
    pitch_diameter: float,
    diameter: float,
    thread_friction: float,
    bearing_friction: float,
    bearing_outer_diameter: float,
    hole_diameter: float,
    formula: str = "vdi2230",
) -> tuple[float, float]:
    r"""Thread and bearing torque per newton of preload, by the chosen formula.

    .. math::
        \frac{M}{F} = k_G + k_K

    Parameters
    ----------
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    diameter : float
        d, [m]
    thread_friction : float
        μ_G, [-]
    bearing_friction : float
        μ_K, [-]
    bearing_outer_diameter : float
        D_f = d_w, [m]
    hole_diameter : float
        d_h, [m]
    formula : str
        ``"vdi2230"`` (VDI 2230 step R13), ``"exact"`` ([004, eq. 10–13]) or
        ``"approx"`` ([004, eq. 15/19])

    Returns
    -------
    tuple of float
        (k_G, k_K), thread and bearing torque per unit preload, [m]

    Notes
    -----
    All three are linear in the preload, so the preload at a given torque is
    M / (k_G + k_K); the friction-scatter histogram uses that.

    Examples
    --------
    >>> kg, kk = tightening_torque_per_preload(0.00175, 0.010863, 0.012, 0.12, 0.12,
    ...                                        0.01663, 0.0135, "exact")
    >>> round(float(kg) * 1e3, 4), round(kk * 1e3, 4)
    (1.0385, 0.9072)
    """
    if formula == "vdi2230":  # R13 per newton of preload (vdi_tightening_torque is F times it)
        k_thread = vdi_thread_torque(1.0, pitch, pitch_diameter, thread_friction)
        k_bearing = bearing_friction * 0.25 * (bearing_outer_diameter + hole_diameter)
    elif formula == "exact":
        k_thread = thread_torque(1.0, pitch, pitch_diameter, thread_friction)
        k_bearing = bearing_friction * friction_radius(bearing_outer_diameter, hole_diameter)
    elif formula == "approx":
        k_thread = 0.5 * diameter * (pitch / (math.pi * diameter) + 1.15 * thread_friction)
        k_bearing = bearing_friction * 0.25 * (bearing_outer_diameter + hole_diameter)
    else:
        raise InputOutOfRange(
            f"torque_formula = {formula!r} is not allowed: must be 'vdi2230', 'exact' or 'approx'",
            field="torque_formula",
        )
    return k_thread, k_bearing


def preload_factor_range(load_type: str) -> tuple[float, float]:
    r"""Range of υ, the factor on the preload against relaxation and overload.

    .. math::
        \sigma_{design} = \upsilon\,\sigma_0

    Parameters
    ----------
    load_type : str
        ``"steady"`` (υ = 1.25…2.0) or ``"varying"`` (υ = 2.5…4.0)

    Returns
    -------
    tuple of float
        (υ_min, υ_max), [-]

    Notes
    -----
    [004, eq. 2], from the tightness condition of the joint.

    Examples
    --------
    >>> preload_factor_range("varying")
    (2.5, 4.0)
    """
    try:
        return PRELOAD_FACTOR_RANGE[load_type]
    except KeyError:
        raise InputOutOfRange(
            f"load_type = {load_type!r} is not allowed: must be 'steady' or 'varying'",
            field="load_type",
        ) from None


def equivalent_shank_diameter(lengths: Sequence[float], diameters: Sequence[float]) -> float:
    r"""Diameter of a plain shank with the same compliance as a stepped one.

    .. math::
        \frac{l}{d_{eq}^2} = \sum_i \frac{l_i}{d_i^2}, \qquad l = \sum_i l_i

    Parameters
    ----------
    lengths : sequence of float
        Section lengths l_i, [m]
    diameters : sequence of float
        Section diameters d_i, [m]

    Returns
    -------
    float
        d_eq, [m]

    Notes
    -----
    [004, eq. 4] (equal axial compliance Σ l_i / (E A_i)). Lengths and diameters may
    be numpy arrays (one design per element); a zero length adds nothing.

    Examples
    --------
    >>> round(equivalent_shank_diameter([0.02, 0.02], [0.012, 0.009]) * 1e3, 3)
    10.182
    """
    total = sum(lengths)
    weighted = sum(li / di**2 for li, di in zip(lengths, diameters, strict=True))
    return (total / weighted) ** 0.5


def axial_compliance(
    lengths: Sequence[float], diameters: Sequence[float], youngs_modulus: float
) -> float:
    r"""Axial compliance of a bolt made of cylindrical sections in series.

    .. math::
        \lambda_b = \sum_i \frac{l_i}{E\,A_i}, \qquad A_i = \frac{\pi d_i^2}{4}

    Parameters
    ----------
    lengths : sequence of float
        Section lengths l_i, [m]
    diameters : sequence of float
        Section diameters d_i, [m]
    youngs_modulus : float
        E of the bolt, [Pa]

    Returns
    -------
    float
        λ_b, [m/N]

    Notes
    -----
    [004, eq. 4, 7, 9]. The review adds 1/3 of the nut height, at the minor
    diameter, to the loaded length for the thread's own deformation; the
    caller passes it as one of the sections. VDI 2230 adds further terms for
    the head and the engaged thread, which the review does not. Lengths and
    diameters may be numpy arrays (one design per element); a zero length adds nothing.

    Examples
    --------
    >>> round(axial_compliance([0.04], [0.012], 2.1e11) * 1e9, 4)
    1.6842
    """
    return sum(
        li / (youngs_modulus * 0.25 * math.pi * di**2)
        for li, di in zip(lengths, diameters, strict=True)
    )


def elongation(preload: float, bolt_compliance: float) -> float:
    r"""Bolt elongation under a preload.

    .. math::
        \Delta l = F_0\,\lambda_b

    Parameters
    ----------
    preload : float
        F0, [N]
    bolt_compliance : float
        λ_b, [m/N]

    Returns
    -------
    float
        Δl, [m]

    Notes
    -----
    [004, eq. 7] solved for Δl (F0 = Δl / λ_b).

    Examples
    --------
    >>> round(elongation(40e3, 1.6843e-9) * 1e6, 2)
    67.37
    """
    return preload * bolt_compliance


def preload_from_elongation(elongation_measured: float, bolt_compliance: float) -> float:
    r"""Preload from a measured bolt elongation.

    .. math::
        F_0 = \frac{\Delta l}{\lambda_b}

    Parameters
    ----------
    elongation_measured : float
        Δl, [m]
    bolt_compliance : float
        λ_b, [m/N]

    Returns
    -------
    float
        F0, [N]

    Notes
    -----
    [004, eq. 7].

    Examples
    --------
    >>> round(preload_from_elongation(67.37e-6, 1.6843e-9))
    39999
    """
    return elongation_measured / bolt_compliance


def nut_rotation_angle(preload: float, total_compliance: float, pitch: float) -> float:
    r"""Nut rotation from the snug point that stretches bolt and joint to a preload.

    .. math::
        \varphi = 2\pi\,\frac{F_0 \sum_i \lambda_i}{P}
        \quad\left(\varphi° = \frac{360\,F_0 \sum_i \lambda_i}{P}\right)

    Parameters
    ----------
    preload : float
        F0, [N]
    total_compliance : float
        Σ λ_i, compliance of the bolt plus the clamped parts, [m/N]
    pitch : float
        P, [m]

    Returns
    -------
    float
        φ, [rad]

    Notes
    -----
    [004, eq. 8]; with the clamped parts rigid, Σ λ_i = l_b/(E_b A_b) and it is
    [004, eq. 9]. The angle counts from the point where all gaps are closed
    (φ0 in the review), which the review warns is hard to know.

    Examples
    --------
    >>> round(math.degrees(nut_rotation_angle(40e3, 1.6843e-9, 0.00175)), 2)
    13.86
    """
    return 2.0 * math.pi * preload * total_compliance / pitch


def tightening_factor(scatter: float) -> float:
    r"""Tightening factor α_A implied by a symmetric preload scatter ±s.

    .. math::
        \alpha_A = \frac{F_{max}}{F_{min}} = \frac{1 + s}{1 - s}

    Parameters
    ----------
    scatter : float
        s, the half-width of the preload band relative to its middle, [-], 0 ≤ s < 1

    Returns
    -------
    float
        α_A, [-]

    Notes
    -----
    VDI 2230-1:2015, Table A8 defines α_A = F_M,max / F_M,min and lists the
    scatter ±s = (α_A − 1)/(α_A + 1) beside it.

    Examples
    --------
    >>> round(tightening_factor(0.30), 3)
    1.857
    """
    return (1.0 + scatter) / (1.0 - scatter)


def scatter_from_tightening_factor(factor: float) -> float:
    r"""Symmetric scatter ±s implied by a tightening factor α_A.

    .. math::
        s = \frac{\alpha_A - 1}{\alpha_A + 1}

    Parameters
    ----------
    factor : float
        α_A ≥ 1, [-]

    Returns
    -------
    float
        s, [-]

    Notes
    -----
    Inverse of :func:`tightening_factor` (VDI 2230-1:2015, Table A8).

    Examples
    --------
    >>> round(scatter_from_tightening_factor(1.6), 4)
    0.2308
    """
    return (factor - 1.0) / (factor + 1.0)


@dataclass(frozen=True)
class PreloadHistogram:
    """Preload at one torque over a grid of friction coefficients, binned."""

    bin_centres: np.ndarray
    counts: np.ndarray
    minimum: float
    maximum: float
    mean: float
    std: float


def friction_scatter_preloads(
    torque: float,
    pitch: float,
    pitch_diameter: float,
    diameter: float,
    thread_friction_range: tuple[float, float],
    bearing_friction_range: tuple[float, float],
    bearing_outer_diameter: float,
    hole_diameter: float,
    formula: str = "vdi2230",
    grid: int = 64,
) -> np.ndarray:
    r"""Preload at one wrench torque on a midpoint grid of the two friction coefficients.

    .. math::
        F_0(\mu_{G,j}, \mu_{K,i}) = \frac{M}{k_G(\mu_{G,j}) + k_K(\mu_{K,i})},
        \qquad \mu_j = \mu_{min} + (\mu_{max} - \mu_{min})\frac{j + 1/2}{n}

    Parameters
    ----------
    torque : float
        Wrench torque M, the same for every bolt, [N*m]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    diameter : float
        d, [m]
    thread_friction_range : tuple of float
        (μ_G,min, μ_G,max), [-]
    bearing_friction_range : tuple of float
        (μ_K,min, μ_K,max), [-]
    bearing_outer_diameter : float
        D_f, [m]
    hole_diameter : float
        d_h, [m]
    formula : str
        Torque formula, see :func:`tightening_torque_per_preload`
    grid : int
        Points per friction coefficient, [-]

    Returns
    -------
    numpy.ndarray
        F_0, shape (grid, grid): row i is μ_K,i, column j is μ_G,j, [N]

    Notes
    -----
    [004, fig. 5] and eq. 13: the torque is linear in the preload, with a thread part
    depending on μ_G only and a bearing part on μ_K only, so the grid needs each part on
    ``grid`` values, not ``grid²``. μ_G and μ_K are independent and uniform over their
    ranges (the midpoint rule). The grid is for the histogram: its extremes lie half a
    cell inside the band and its mean is 3.8e-6 low on this example;
    :func:`friction_scatter_band` gives the exact band and mean.

    Examples
    --------
    >>> f = friction_scatter_preloads(80.0, 0.0023091, 0.0143753, 0.015875,
    ...     (0.10, 0.20), (0.10, 0.20), 0.0226, 0.0175)
    >>> f.shape, round(float(f.min()) / 1e3, 1), round(float(f.max()) / 1e3, 1)
    ((64, 64), 19.9, 36.0)
    """
    g_lo, g_hi = thread_friction_range
    k_lo, k_hi = bearing_friction_range
    u = (np.arange(grid) + 0.5) / grid
    k_thread, _ = tightening_torque_per_preload(
        pitch,
        pitch_diameter,
        diameter,
        g_lo + (g_hi - g_lo) * u,  # type: ignore[arg-type]
        0.0,
        bearing_outer_diameter,
        hole_diameter,
        formula,
    )
    _, k_bearing = tightening_torque_per_preload(
        pitch,
        pitch_diameter,
        diameter,
        0.0,
        k_lo + (k_hi - k_lo) * u,  # type: ignore[arg-type]
        bearing_outer_diameter,
        hole_diameter,
        formula,
    )
    per_newton = np.asarray(k_thread)[None, :] + np.asarray(k_bearing)[:, None]
    return torque / per_newton


#: Gauss–Legendre rules of :func:`friction_scatter_band`'s μ_G integral (in the logarithmic
#: variable v): 8 nodes on an interval up to ``SCATTER_MEAN_SHORT`` long, else panels up to
#: ``SCATTER_MEAN_PANEL`` long with 16 nodes each. Chosen against a 64-node rule on 20,000
#: random bolts, ranges and formulas (worst 7e-16 for 8 nodes up to 1.5, 3.8e-15 for 16 up
#: to 6; 8 nodes at 2.0 would give 3e-14); tests/models/preload/test_scatter_mean.py holds
#: the result to a closed form, to scipy's quad and dblquad and to Monte Carlo.
SCATTER_MEAN_SHORT = 1.5
SCATTER_MEAN_PANEL = 6.0
_GL_RULES = {
    n: (0.5 * (t + 1.0), 0.5 * w)
    for n, (t, w) in ((n, np.polynomial.legendre.leggauss(n)) for n in (8, 16))
}


@functools.lru_cache(maxsize=64)
def _panel_rule(panels: int) -> tuple[np.ndarray, np.ndarray]:
    """Nodes τ in 0…1 and weights (summing to 1): 8 nodes for 0 panels, else 16 per panel."""
    nodes, weights = _GL_RULES[8 if panels == 0 else 16]
    m = max(panels, 1)
    tau = ((np.arange(m)[:, None] + nodes[None, :]) / m).ravel()
    return tau, np.tile(weights / m, m)


def _panels(length: Any) -> Any:
    """The rule for a v interval ``length`` long: 0 (8 nodes) or the number of 16-node panels."""
    long = where(length > SCATTER_MEAN_SHORT, length, 0.0)
    return np.ceil(long / SCATTER_MEAN_PANEL).astype(int)


def _log1p_ratio(x: Any) -> Any:
    """ln(1 + x)/x, 1 at x = 0: the mean of 1/(1 + x t) over t in 0…1."""
    x = np.asarray(x, dtype=float)
    zero = x == 0.0
    safe = np.where(zero, 1.0, x)
    return np.where(zero, 1.0, np.log1p(safe) / safe)


def friction_scatter_band(
    torque: Any,
    pitch: Any,
    pitch_diameter: Any,
    diameter: Any,
    thread_friction_range: tuple[Any, Any],
    bearing_friction_range: tuple[Any, Any],
    bearing_outer_diameter: Any,
    hole_diameter: Any,
    formula: str = "vdi2230",
) -> tuple[Any, Any, Any]:
    r"""Lowest, highest and mean preload at one wrench torque when μ_G and μ_K scatter.

    .. math::
        F_{min} = \frac{M}{k_G(\mu_{G,max}) + k_K(\mu_{K,max})},\qquad
        F_{max} = \frac{M}{k_G(\mu_{G,min}) + k_K(\mu_{K,min})}

    .. math::
        \bar F = \frac{1}{\Delta_G}\int_{\mu_{G,min}}^{\mu_{G,max}}
            \frac{M}{u}\,\frac{\ln(1 + c\,\Delta_K/u)}{c\,\Delta_K/u}\,d\mu_G,
        \qquad u = k_G(\mu_G) + c\,\mu_{K,min}

    Parameters
    ----------
    torque : float or numpy.ndarray
        Wrench torque M, the same for every bolt, [N*m]
    pitch : float or numpy.ndarray
        P, [m]
    pitch_diameter : float or numpy.ndarray
        d2, [m]
    diameter : float or numpy.ndarray
        d, [m]
    thread_friction_range : tuple of float or numpy.ndarray
        (μ_G,min, μ_G,max), [-]
    bearing_friction_range : tuple of float or numpy.ndarray
        (μ_K,min, μ_K,max), [-]
    bearing_outer_diameter : float or numpy.ndarray
        D_f, [m]
    hole_diameter : float or numpy.ndarray
        d_h, [m]
    formula : str
        Torque formula, see :func:`tightening_torque_per_preload`

    Returns
    -------
    tuple
        (F_min, F_max, mean F) with μ_G and μ_K independent and uniform on their
        ranges: floats, or arrays of the inputs' broadcast shape, [N]

    Notes
    -----
    [004, fig. 5] and eq. 13: F = M/(k_G(μ_G) + k_K(μ_K)), the thread part k_G
    depending on μ_G only and the bearing part k_K on μ_K only
    (:func:`tightening_torque_per_preload`). Both rise with their coefficient under
    every formula (k_K = c μ_K with c = D_Km/2 or R_T; k_G linear in μ_G, or
    (d2/2) tan(ψ + ρ') with ψ + ρ' < 90°), so the extremes are the corners, exactly.

    The mean is exact to about 1e-13 relative. k_K is linear in μ_K under every
    formula, so the μ_K integral is analytic (the log1p form above; M/u as
    c Δ_K/u → 0). The μ_G integral is Gauss–Legendre in
    v = ln(μ_G − μ_G,min + δ), δ = Δ_G u(μ_G,min)/(k_G(μ_G,max) − k_G(μ_G,min)):
    the integrand's nearest singularity (u = 0) lies δ below μ_G,min for a linear k_G
    and farther for the convex ``exact`` one, so in v it is smooth however close the
    singularity comes (μ_G,min and μ_K,min near 0 on a fine pitch). The v interval is
    ℓ = ln(1 + Δ_G/δ) long: 8 nodes up to ℓ = 1.5 (ranges 0.10…0.20 on ISO threads:
    ℓ ≈ 0.3–0.4), else 16 nodes per panel of ≤ 6 (M12 with both coefficients 0…1:
    ℓ ≈ 3.2; a second panel only for pitches below about 0.01 d2 with both minimum
    coefficients near 0).

    Before this function, ``preload.control`` took the mean of a 64 × 64 midpoint
    grid (:func:`friction_scatter_preloads`) and the band from the grid's corner
    cells, half a cell inside the corners: on [004, fig. 5]'s example (below) that mean
    is 3.8e-6 relative below the exact one (the midpoint rule on a convex integrand)
    and that band 1.9 % narrower (19.86…36.03 kN against 19.79…36.27 kN).

    Examples
    --------
    [004, fig. 5]: 5/8"-11 UNC at 80 N·m, μ_G and μ_K 0.10…0.20

    >>> lo, hi, mean = friction_scatter_band(80.0, 0.0023091, 0.0143753, 0.015875,
    ...     (0.10, 0.20), (0.10, 0.20), 0.0226, 0.0175)
    >>> round(lo / 1e3, 2), round(hi / 1e3, 2), round(mean / 1e3, 3)
    (19.79, 36.27, 25.995)
    """
    g_lo, g_hi = thread_friction_range
    k_lo, k_hi = bearing_friction_range
    geometry = (pitch, pitch_diameter, diameter, bearing_outer_diameter, hole_diameter)
    everything = (torque, g_lo, g_hi, k_lo, k_hi, *geometry)
    with np.errstate(all="ignore"):  # an upside-down range gives NaN; the caller refuses it
        t = _band_terms(torque, geometry, (g_lo, g_hi), (k_lo, k_hi), formula)
        if all(v.__class__ is float or np.ndim(v) == 0 for v in everything):
            # one design: its one rule, without the bookkeeping of many (5x faster here)
            rule = int(_panels(t.length))
            mean = _panel_mean(torque, t, g_lo, geometry, formula, rule)
            return float(t.low), float(t.high), float(mean)
        shape = np.broadcast_shapes(*(np.shape(v) for v in (*everything, t.length)))

        def flat(v: Any) -> Any:
            if np.ndim(v) == 0:
                return float(v)
            return np.broadcast_to(np.asarray(v, dtype=float), shape).ravel()

        size = math.prod(shape)
        flat_terms = _BandTerms(*(flat(v) for v in t))
        every = (flat(torque), flat(g_lo), tuple(flat(v) for v in geometry))
        length = np.zeros(size)
        length[:] = flat_terms.length
        panels = _panels(length)
        mean = np.empty(size)
        for m in np.unique(panels).tolist():
            whole = m == panels[0] and bool((panels == m).all())
            sel: Any = slice(None) if whole else panels == m

            def pick(v: Any, sel: Any = sel) -> Any:
                return v if np.ndim(v) == 0 else v[sel]

            mean[sel] = _panel_mean(
                pick(every[0]),
                _BandTerms(*(pick(v) for v in flat_terms)),
                pick(every[1]),
                tuple(pick(v) for v in every[2]),
                formula,
                m,
            )
    return (
        np.array(np.broadcast_to(t.low, shape)),
        np.array(np.broadcast_to(t.high, shape)),
        mean.reshape(shape),
    )


class _BandTerms(NamedTuple):
    """What :func:`friction_scatter_band` computes before its quadrature (floats or arrays)."""

    #: F_min and F_max, at the range's corners [N].
    low: Any
    high: Any
    #: u at μ_G,min: k_G(μ_G,min) + k_K(μ_K,min) [m].
    u_lo: Any
    #: k_K(μ_K,min) and c Δ_K = k_K(Δ_K) [m].
    bearing_lo: Any
    bearing_span: Any
    #: μ_G = μ_G,min + reach (e^{τℓ} − 1), dμ_G/Δ_G = scale e^{τℓ} dτ, ℓ = length.
    reach: Any
    scale: Any
    length: Any


def _band_terms(
    torque: Any,
    geometry: tuple[Any, Any, Any, Any, Any],
    thread_range: tuple[Any, Any],
    bearing_range: tuple[Any, Any],
    formula: str,
) -> _BandTerms:
    """The corners of :func:`friction_scatter_band` and its μ_G substitution, on floats or
    arrays: k_G and k_K at the corners (:func:`tightening_torque_per_preload`), then
    v = ln(μ_G − μ_G,min + δ) with δ = Δ_G u(μ_G,min)/(k_G(μ_G,max) − k_G(μ_G,min))."""
    p, d2, d, outer, hole = geometry
    (g_lo, g_hi), (k_lo, k_hi) = thread_range, bearing_range
    thread_lo, bearing_lo = tightening_torque_per_preload(
        p, d2, d, g_lo, k_lo, outer, hole, formula
    )
    thread_hi, bearing_hi = tightening_torque_per_preload(
        p, d2, d, g_hi, k_hi, outer, hole, formula
    )
    # k_K = c μ_K under every formula: its span is k_K(Δ_K), no difference taken
    _, bearing_span = tightening_torque_per_preload(
        p, d2, d, 0.0, k_hi - k_lo, outer, hole, formula
    )
    u_lo = thread_lo + bearing_lo
    ratio = (thread_hi - thread_lo) / u_lo  # Δ_G/δ
    # ratio ≤ 1e-17: k_G is constant on the μ_G range to 1e-17, its integral is its value
    flat = np.logical_not(ratio > 1e-17)
    safe = where(flat, 1.0, ratio)
    length = where(flat, 0.0, np.log1p(safe))  # of the v interval
    return _BandTerms(
        low=torque / (thread_hi + bearing_hi),
        high=torque / u_lo,
        u_lo=u_lo,
        bearing_lo=bearing_lo,
        bearing_span=bearing_span,
        reach=where(flat, 0.0, (g_hi - g_lo) / safe),
        scale=where(flat, 1.0, length / safe),
        length=length,
    )


def _panel_mean(
    torque: Any,
    t: _BandTerms,
    thread_friction_min: Any,
    geometry: tuple[Any, ...],
    formula: str,
    panels: int,
) -> Any:
    """The mean preload of :func:`friction_scatter_band` on one rule (:func:`_panel_rule`):
    the nodes τ on a trailing axis of the points' values (floats or 1-D arrays)."""

    def col(v: Any) -> Any:
        return v[:, None] if isinstance(v, np.ndarray) and v.ndim else v

    tau, half_w = _panel_rule(panels)
    grow = np.expm1(tau * col(t.length))  # e^{τℓ} − 1
    mu = col(thread_friction_min) + col(t.reach) * grow
    p, d2, d, outer, hole = (col(v) for v in geometry)
    k_thread, _ = tightening_torque_per_preload(p, d2, d, mu, 0.0, outer, hole, formula)
    u = k_thread + col(t.bearing_lo)
    # the mean of 1/(u + k_K) over the μ_K range: ln(1 + c Δ_K/u)/(c Δ_K); where
    # Δ_K ≤ 1e-17 u everywhere it is 1/u to 1e-17
    spread = t.bearing_span > 1e-17 * t.u_lo
    k_safe = where(spread, t.bearing_span, 1.0)
    inner = where(col(spread), np.log1p(col(t.bearing_span) / u) / col(k_safe), 1.0 / u)
    return torque * t.scale * np.sum(half_w * (1.0 + grow) * inner, axis=-1)


def preload_histogram(
    forces: np.ndarray, bins: int = 10, sample_size: int = 38
) -> PreloadHistogram:
    r"""Equal-width histogram of equally likely preloads, scaled to a sample of bolts.

    .. math::
        n_k = N\,\frac{\#\{F_0 \in \text{bin}_k\}}{\#\{F_0\}}

    Parameters
    ----------
    forces : numpy.ndarray
        Equally likely preloads (e.g. :func:`friction_scatter_preloads`), [N]
    bins : int
        Number of equal-width preload bins, [-]
    sample_size : int
        Number of bolts N the counts are scaled to (38 as in [004, fig. 5]), [-]

    Returns
    -------
    PreloadHistogram
        Bin centres [N], expected counts per bin, min, max, mean and standard deviation [N].

    Notes
    -----
    [004, fig. 5] draws such a histogram for 38 bolts. A band narrower than 1e-9 of
    its top is widened to ±0.5 % so the bins have a width.

    Examples
    --------
    >>> h = preload_histogram(np.array([1.0, 2.0, 2.0, 3.0]), bins=2, sample_size=8)
    >>> h.counts.tolist(), h.bin_centres.tolist()
    ([2.0, 6.0], [1.5, 2.5])
    """
    forces = np.ravel(forces)
    lo, hi = float(forces.min()), float(forces.max())
    if hi - lo <= 1e-9 * max(hi, 1e-300):
        half = max(0.005 * hi, 1e-12)
        lo, hi = lo - half, hi + half
    counts, edges = np.histogram(forces, bins=bins, range=(lo, hi))
    return PreloadHistogram(
        bin_centres=0.5 * (edges[:-1] + edges[1:]),
        counts=counts * (sample_size / forces.size),
        minimum=float(forces.min()),
        maximum=float(forces.max()),
        mean=float(forces.mean()),
        std=float(forces.std()),
    )


def friction_scatter_histogram(
    torque: float,
    pitch: float,
    pitch_diameter: float,
    diameter: float,
    thread_friction_range: tuple[float, float],
    bearing_friction_range: tuple[float, float],
    bearing_outer_diameter: float,
    hole_diameter: float,
    formula: str = "vdi2230",
    bins: int = 10,
    sample_size: int = 38,
    grid: int = 64,
) -> PreloadHistogram:
    r"""How the preload at one wrench torque spreads when the friction coefficients do.

    .. math::
        F_0(\mu_G, \mu_K) = \frac{M}{k_G(\mu_G) + k_K(\mu_K)}

    Parameters
    ----------
    torque : float
        Wrench torque M, the same for every bolt, [N*m]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    diameter : float
        d, [m]
    thread_friction_range : tuple of float
        (μ_G,min, μ_G,max), [-]
    bearing_friction_range : tuple of float
        (μ_K,min, μ_K,max), [-]
    bearing_outer_diameter : float
        D_f, [m]
    hole_diameter : float
        d_h, [m]
    formula : str
        Torque formula, see :func:`tightening_torque_per_preload`
    bins : int
        Number of equal-width preload bins, [-]
    sample_size : int
        Number of bolts the counts are scaled to (38 as in [004, fig. 5]), [-]
    grid : int
        Points per friction coefficient of the quadrature grid, [-]

    Returns
    -------
    PreloadHistogram
        Bin centres [N], expected counts per bin among ``sample_size`` bolts,
        and min, max, mean, standard deviation of the preload [N].

    Notes
    -----
    [004, fig. 5] (Thum and Debus: 38 bolts 5/8" at 80 N·m) shows the spread
    this models; the review reads it as ±30 %. μ_G and μ_K are taken as
    independent and uniform over their ranges and integrated on a midpoint
    grid (deterministic, so the same request gives the same histogram):
    :func:`friction_scatter_preloads` binned by :func:`preload_histogram`. Its minimum,
    maximum and mean are the grid's; :func:`friction_scatter_band` gives the exact ones.

    Examples
    --------
    >>> h = friction_scatter_histogram(80.0, 0.0023091, 0.0143753, 0.015875,
    ...     (0.10, 0.20), (0.10, 0.20), 0.0226, 0.0175)
    >>> round(h.minimum / 1e3, 1), round(h.maximum / 1e3, 1), round(float(h.counts.sum()), 6)
    (19.9, 36.0, 38.0)
    """
    forces = friction_scatter_preloads(
        torque,
        pitch,
        pitch_diameter,
        diameter,
        thread_friction_range,
        bearing_friction_range,
        bearing_outer_diameter,
        hole_diameter,
        formula,
        grid,
    )
    return preload_histogram(forces, bins, sample_size)
