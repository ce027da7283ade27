r"""Double-action ball safety clutch (torque limiter) of a nut-runner [001].

Half-couplings 1 (driving) and 2 (driven) carry grooves whose flanks make the
angle α with the axis (the flank normal makes α with the plane of rotation);
``i`` balls on a circle of diameter D0 sit in the grooves, pressed by a disk
and a spring whose compression Δ is set by a nut. Above the set torque the
balls climb out of the grooves, lift the disk and roll on the end face: the
clutch slips and clicks.

The source is Malashchenko, Semenyuk, Lysiak, "Parameters of double action
ball overturn coupling" ([001], a scan whose Cyrillic came out as Latin
look-alikes). Its equations, as read:

* [001, eq. 1] forces on one ball, K_r = 0.85…0.9 the load non-uniformity
  factor: F_t = 2T / (K_r D0 i), F_a = F_t tan α, F_N = F_t / cos α
* [001, eq. 2] spring force: F_spring = G d0⁴ Δ / (8 D³ i_p)
* [001, eq. 3] balance, friction neglected: F_a = F_spring
* [001, after eq. 3] the printed result T = D0 i G d0⁴ Δ / (16 K_r D³ i_p tan α)

Two things in the source do not hold together, and this module says which way
it goes:

1. **K_r is on the wrong side of the printed result.** Substituting eq. 1 into
   eq. 3 gives T = K_r D0 i F_spring / (2 tan α): K_r multiplies. The scan
   shows it dividing, which would make a *less* uniform load share (smaller
   K_r) *raise* the torque at which the most-loaded ball escapes; that is
   backwards. We follow eq. 1–3; the printed formula is 1/K_r² (= 1.38 at
   K_r = 0.85) times ours.
2. **Eq. 3 sets one ball's axial force equal to the whole spring force.** That
   is right only if every ball has its own spring (``arrangement="per_ball"``).
   The clutch of the paper's figure 1 has ONE spring pressing one disk on all
   balls (``arrangement="common"``, the default). Then the disk lifts when the
   *sum* of the balls' axial pushes reaches the spring force. The sum of the
   tangential forces is fixed by statics, Σ F_t,j · D0/2 = T, however unevenly
   the balls share it, so Σ F_a,j = 2T tan α / D0 and

   .. math::
       T = \frac{D_0 F_{spring}}{2 \tan(\alpha - \rho)}

   with **no K_r**: the non-uniformity factor only matters where each ball is
   held by its own spring (the most-loaded ball escapes first) and for the
   design force on one ball (eq. 1), which is how it is used here.

Flank friction (the paper's second half argues it is small but present): with a
Coulomb coefficient f on the flanks, ρ = atan f, the flank's reaction tilts by
ρ against the ball's climb and the axial push per unit tangential force becomes
tan(α − ρ) instead of tan α. f = 0 is the paper. Where α ≤ ρ the push never
overcomes the friction: the clutch never slips (InfeasibleDesign).

Groove depth: the paper sets the spring deflection Δ equal to the groove depth
and says only that it must be "agreed with the ball diameter d". We take the
groove to be too deep when Δ > d/2: the ball's centre then sits below the rim,
it cannot protrude far enough to carry the other half-coupling, and climbing
out it meets the rim with its upper half and wedges (the paper's fig. 6 edge
case). This is a failing check, not a refusal. Of the paper's own range
(Δ = 4…10 mm with d = 10 mm) only Δ ≤ 5 mm passes.

Spring checks (not in the paper; standard helical compression spring design):
spring index C = D/d0, Wahl factor K_w = (4C − 1)/(4C − 4) + 0.615/C, wire
shear stress τ = 8 F D K_w / (π d0³).

The clutch as built (beyond the paper; the paper's eq. 1–3 are its zero-lift
point): the ball climbs the flank by the lift h (the groove depth, which the
paper equates with the spring's setting Δ) and then rolls over the rim, rising
(d/2)(1 − sin α) more (:func:`rim_rise`, :func:`lift_points`); the spring is
compressed by the lift, so the torque follows :func:`torque_against_lift` and
peaks where the spring force and the contact angle balance (at the rim for a
helical spring; at the start for disc springs set past their force maximum,
:mod:`engine.physics.springs`). In the paper's case the spring reaches c(Δ + Δ) at the
peak: its stress doubles, 45.4 → 90.8 MPa. An inclined driving flank α′ ([001,
fig. 6]) adds its own push (:func:`combined_push_factor`); the margin to
self-locking and dT/df (:func:`friction_sensitivity`); the residual torque on
the face (:func:`residual_torque`); sizing from the drive
(:func:`rated_torque`, :func:`acceleration_torque`, :func:`required_slip_torque`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from . import springs

FloatArray = float | npt.NDArray[np.float64]
Arrangement = Literal["common", "per_ball"]

ARRANGEMENTS: tuple[str, ...] = ("common", "per_ball")

#: Groove (flank) angle range the source recommends [001, text after eq. 1].
RECOMMENDED_GROOVE_ANGLE = (math.radians(20.0), math.radians(70.0))
#: Load non-uniformity factor range the source gives [001, eq. 1].
RECOMMENDED_LOAD_FACTOR = (0.85, 0.9)
#: Spring index range in which helical compression springs are readily coiled
#: and stable (common spring-design practice, not from the source).
WORKABLE_SPRING_INDEX = (4.0, 12.0)


def _out(value: Any) -> FloatArray:
    """A Python float for scalar input, a float array otherwise."""
    if type(value) is np.float64:  # what numpy gives for scalar inputs: no array made
        return float(value)
    arr = np.asarray(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr


def _where_pushing(push: np.ndarray, value: Callable[[Any], Any]) -> FloatArray:
    """``value(push)`` where the push is positive, NaN where it is not (the balls wedge).

    A positive push given as one number (the groove fixed, a torque or force varied)
    needs no mask: the same numbers without a pass over the points.

    >>> _where_pushing(np.asarray(0.5), lambda p: 2.0 * p)
    1.0
    >>> _where_pushing(np.array([0.5, -0.1]), lambda p: 2.0 * p).tolist()
    [1.0, nan]
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        if push.ndim == 0 and push > 0.0:
            return _out(value(push))
        return _out(np.where(push > 0.0, value(np.where(push > 0.0, push, 1.0)), np.nan))


# --------------------------------------------------------------------------
# Ball forces [001, eq. 1] with flank friction
# --------------------------------------------------------------------------


def flank_push_factor(groove_angle: FloatArray, flank_friction: FloatArray = 0.0) -> FloatArray:
    r"""Axial push on a ball per unit tangential force, at impending slip.

    .. math::
        \frac{F_a}{F_t} = \tan(\alpha - \rho), \qquad \rho = \arctan f

    Parameters
    ----------
    groove_angle : float
        Flank angle α of the grooves, [rad]
    flank_friction : float, optional
        Coulomb friction coefficient f between ball and flank, [-]

    Returns
    -------
    push : float
        F_a / F_t; zero or negative where α ≤ atan f (the ball never climbs), [-]

    Notes
    -----
    [001, eq. 1] has F_a = F_t tan α (f = 0). With friction the flank's
    reaction N(cos α + f sin α, sin α − f cos α) (tangential, axial) tilts by
    ρ against the ball's climb, so F_a / F_t = tan(α − ρ).

    Examples
    --------
    >>> round(flank_push_factor(math.radians(45.0)), 12)
    1.0
    >>> round(flank_push_factor(math.radians(45.0), 0.1), 4)
    0.8182
    """
    rho = np.arctan(flank_friction)
    return _out(np.tan(np.asarray(groove_angle) - rho))


def ball_tangential_force(
    torque: FloatArray,
    ball_circle_diameter: FloatArray,
    ball_count: FloatArray,
    load_factor: FloatArray = 0.85,
) -> FloatArray:
    r"""Circumferential force on the most-loaded ball [001, eq. 1].

    .. math::
        F_t = \frac{2 T}{K_r D_0 i}

    Parameters
    ----------
    torque : float
        Torque through the clutch, [N*m]
    ball_circle_diameter : float
        Diameter D0 of the circle of ball centres, [m]
    ball_count : int
        Number of balls i, [-]
    load_factor : float, optional
        Load non-uniformity factor K_r (0.85…0.9 in the source), [-]

    Returns
    -------
    force : float
        Tangential force on one ball, [N]

    Notes
    -----
    [001, eq. 1]. K_r < 1 raises the force above the mean share 2T/(D0 i) to
    cover uneven sharing between the balls (manufacturing scatter).

    Examples
    --------
    >>> round(ball_tangential_force(0.5618655, 0.05, 4, 0.85), 4)
    6.6102
    """
    return _out(
        2.0 * np.asarray(torque) / (np.asarray(load_factor) * ball_circle_diameter * ball_count)
    )


def ball_axial_force(
    tangential_force: FloatArray, groove_angle: FloatArray, flank_friction: FloatArray = 0.0
) -> FloatArray:
    r"""Axial push of one ball on the pressure disk at impending slip [001, eq. 1].

    .. math::
        F_a = F_t \tan(\alpha - \arctan f)

    Parameters
    ----------
    tangential_force : float
        Tangential force F_t on the ball, [N]
    groove_angle : float
        Flank angle α, [rad]
    flank_friction : float, optional
        Flank friction coefficient f, [-]

    Returns
    -------
    force : float
        Axial force, [N]

    Notes
    -----
    [001, eq. 1] F_a = F_t tan α for f = 0; friction as in
    :func:`flank_push_factor`.

    Examples
    --------
    >>> round(ball_axial_force(10.0, math.radians(30.0)), 4)
    5.7735
    """
    return _out(np.asarray(tangential_force) * flank_push_factor(groove_angle, flank_friction))


def ball_normal_force(
    tangential_force: FloatArray, groove_angle: FloatArray, flank_friction: FloatArray = 0.0
) -> FloatArray:
    r"""Normal (contact) force between one ball and a groove flank [001, eq. 1].

    .. math::
        F_N = \frac{F_t \cos\rho}{\cos(\alpha - \rho)}
            = \frac{F_t}{\cos\alpha + f \sin\alpha}

    Parameters
    ----------
    tangential_force : float
        Tangential force F_t on the ball, [N]
    groove_angle : float
        Flank angle α, [rad]
    flank_friction : float, optional
        Flank friction coefficient f, [-]

    Returns
    -------
    force : float
        Force normal to the flank (the one that loads the contact), [N]

    Notes
    -----
    [001, eq. 1] F_N = F_t / cos α for f = 0. With friction the flank carries
    N normally and fN along itself; F_t = N (cos α + f sin α).

    Examples
    --------
    >>> round(ball_normal_force(10.0, math.radians(45.0)), 4)
    14.1421
    """
    a = np.asarray(groove_angle)
    return _out(np.asarray(tangential_force) / (np.cos(a) + np.asarray(flank_friction) * np.sin(a)))


# --------------------------------------------------------------------------
# The spring [001, eq. 2] and its checks
# --------------------------------------------------------------------------


def spring_rate(
    shear_modulus: FloatArray,
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
) -> FloatArray:
    r"""Axial rate of a helical compression spring [001, eq. 2].

    .. math::
        c = \frac{G d_0^4}{8 D^3 i_p}

    Parameters
    ----------
    shear_modulus : float
        Shear modulus G of the wire (8·10¹⁰ Pa for spring steel), [Pa]
    wire_diameter : float
        Wire diameter d0, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    active_coils : float
        Number of active coils i_p, [-]

    Returns
    -------
    rate : float
        Force per unit deflection, [N/m]

    Notes
    -----
    [001, eq. 2] divided by Δ. Shear deformation of the wire and coil
    curvature are neglected (the usual approximation, good for C ≳ 4).

    Examples
    --------
    >>> round(spring_rate(8e10, 0.004, 0.045, 5), 3)
    5618.656
    """
    # the same relation as EN 13906-1's rate: one implementation, in engine.physics.springs
    return springs.helical_rate(shear_modulus, wire_diameter, mean_diameter, active_coils)


def spring_force(
    shear_modulus: FloatArray,
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
    deflection: FloatArray,
) -> FloatArray:
    r"""Force of the clutch spring compressed by Δ [001, eq. 2].

    .. math::
        F_{spring} = \frac{G d_0^4 \Delta}{8 D^3 i_p}

    Parameters
    ----------
    shear_modulus : float
        Shear modulus G, [Pa]
    wire_diameter : float
        Wire diameter d0, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    active_coils : float
        Active coils i_p, [-]
    deflection : float
        Axial compression Δ (the source sets it equal to the groove depth), [m]

    Returns
    -------
    force : float
        Spring force, [N]

    Notes
    -----
    [001, eq. 2]. The source takes Δ equal to the groove depth and the force
    constant while the ball climbs; the real force grows by c·h over a climb
    of h, which this closed form neglects (see the result's notes).

    Examples
    --------
    >>> round(spring_force(8e10, 0.004, 0.045, 5, 0.004), 4)
    22.4746
    """
    return _out(
        spring_rate(shear_modulus, wire_diameter, mean_diameter, active_coils)
        * np.asarray(deflection)
    )


def spring_index(mean_diameter: FloatArray, wire_diameter: FloatArray) -> FloatArray:
    r"""Spring index C = D / d0.

    .. math::
        C = \frac{D}{d_0}

    Parameters
    ----------
    mean_diameter : float
        Mean coil diameter D, [m]
    wire_diameter : float
        Wire diameter d0, [m]

    Returns
    -------
    index : float
        Spring index, [-]

    Notes
    -----
    Not in the source; springs coil well and stay stable for C ≈ 4…12.

    Examples
    --------
    >>> spring_index(0.045, 0.004)
    11.25
    """
    return _out(np.asarray(mean_diameter) / np.asarray(wire_diameter))


def wahl_factor(index: FloatArray) -> FloatArray:
    r"""Wahl stress-correction factor of a helical spring of index C.

    .. math::
        K_w = \frac{4C - 1}{4C - 4} + \frac{0.615}{C}

    Parameters
    ----------
    index : float
        Spring index C = D/d0, must be > 1, [-]

    Returns
    -------
    factor : float
        Ratio of the peak wire shear stress (inner fibre) to the nominal
        8FD/(πd0³), [-]

    Notes
    -----
    Wahl (1963), the standard correction for wire curvature and direct shear;
    not in the source. Diverges as C → 1 (a coil with no hole).

    Examples
    --------
    >>> round(wahl_factor(11.25), 5)
    1.12784
    """
    return springs.wahl_factor(index)


def spring_shear_stress(
    force: FloatArray,
    mean_diameter: FloatArray,
    wire_diameter: FloatArray,
    correction: str = "wahl",
) -> FloatArray:
    r"""Peak shear stress in the wire of a helical spring carrying ``force``.

    .. math::
        \tau = \frac{8 F D k}{\pi d_0^3}, \qquad
        k = K_w \;\text{(Wahl)} \;\text{or}\; \frac{w + 0.5}{w - 0.75}
        \;\text{(Bergsträsser, EN 13906-1)}

    Parameters
    ----------
    force : float
        Spring force F, [N]
    mean_diameter : float
        Mean coil diameter D, [m]
    wire_diameter : float
        Wire diameter d0, [m]
    correction : {"wahl", "bergstrasser"}, optional
        Stress-correction factor k of the index w = D/d0: Wahl's or
        Bergsträsser's, the one EN 13906-1 gives, [-]

    Returns
    -------
    stress : float
        Shear stress at the inner fibre of the coil, [Pa]

    Notes
    -----
    EN 13906-1, corrected shear stress τ_k = k 8FD/(πd³) (torsion of the wire
    times the correction factor; the standard gives Bergsträsser's, Wahl (1963)
    is the older textbook one); not in the source, which gives no strength check
    for its spring. :func:`engine.physics.springs.helical_shear_stress` is the
    one implementation.

    Examples
    --------
    >>> round(spring_shear_stress(22.4746, 0.045, 0.004) / 1e6, 2)
    45.38
    >>> round(spring_shear_stress(22.4746, 0.045, 0.004, "bergstrasser") / 1e6, 2)
    45.03
    """
    return springs.helical_shear_stress(force, mean_diameter, wire_diameter, correction)


# --------------------------------------------------------------------------
# Torque limit [001, eq. 3] for both spring arrangements, and its inverses
# --------------------------------------------------------------------------


def torque_sharing(arrangement: str, ball_count: FloatArray, load_factor: FloatArray) -> FloatArray:
    r"""Torque multiplier of the spring arrangement.

    .. math::
        s = 1 \;\text{(one common spring)}, \qquad s = K_r\, i \;\text{(a spring per ball)}

    Parameters
    ----------
    arrangement : str
        ``"common"`` or ``"per_ball"``, [-]
    ball_count : int or array
        i, [-]
    load_factor : float or array
        K_r, share of the most-loaded ball, [-]

    Returns
    -------
    s : float or array
        T = s D0 F/(2 tan(α − ρ)), [-]

    Notes
    -----
    [001, eq. 1–3]: with a spring per ball the most-loaded ball's axial force is
    the spring force, so the torque is K_r i times that of one common spring,
    whose force statics fixes however unevenly the balls share it.

    Examples
    --------
    >>> torque_sharing("common", 4, 0.85), round(torque_sharing("per_ball", 4, 0.85), 12)
    (1.0, 3.4)
    """
    if arrangement == "common":
        return 1.0
    if arrangement == "per_ball":
        return _out(np.asarray(load_factor) * np.asarray(ball_count))
    raise ValueError(f"arrangement must be one of {ARRANGEMENTS}, not {arrangement!r}")


def torque_limit(
    spring_force: FloatArray,
    ball_circle_diameter: FloatArray,
    groove_angle: FloatArray,
    ball_count: FloatArray = 1,
    load_factor: FloatArray = 0.85,
    flank_friction: FloatArray = 0.0,
    arrangement: str = "common",
    driving_groove_angle: FloatArray | None = None,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Torque at which the clutch slips [001, eq. 1–3].

    .. math::
        T_{common} = \frac{D_0 F_{spring}}{2 \tan(\alpha - \rho)}, \qquad
        T_{per\ ball} = \frac{K_r i D_0 F_{spring}}{2 \tan(\alpha - \rho)}

    Parameters
    ----------
    spring_force : float
        Force of the (one common, or each ball's own) spring, [N]
    ball_circle_diameter : float
        Diameter D0 of the circle of ball centres, [m]
    groove_angle : float
        Flank angle α, [rad]
    ball_count : int, optional
        Number of balls i (used by ``per_ball`` only), [-]
    load_factor : float, optional
        Load non-uniformity factor K_r (used by ``per_ball`` only), [-]
    flank_friction : float, optional
        Flank friction coefficient f, ρ = atan f, [-]
    arrangement : {"common", "per_ball"}, optional
        One spring shared by all balls through the disk (the paper's fig. 1),
        or one spring per ball (what the paper's eq. 3 assumes)
    driving_groove_angle : float or None, optional
        α′ of the driving groove; None is [001, eq. 1], see
        :func:`combined_push_factor`, [rad]
    construction : {"free_ball", "pressure_disc"}, optional
        With α′ given: the max or the sum of the two flanks' pushes
        (:func:`combined_push_factor`), [-]

    Returns
    -------
    torque : float
        Slipping torque; NaN where α ≤ atan f (the clutch never slips), [N*m]

    Notes
    -----
    ``per_ball`` is [001, eq. 3] as derived from eq. 1 and 2: the most-loaded
    ball escapes when its own F_a = F_t tan α reaches its spring's force,
    T = K_r D0 i F_spring / (2 tan α); with F_spring from eq. 2 it is the
    paper's T = K_r D0 i G d0⁴ Δ / (16 D³ i_p tan α). The scan prints K_r in
    the denominator, contrary to its own eq. 1; we follow eq. 1.

    With α′ given the push tan(α − ρ) is :func:`combined_push_factor`'s (the
    max or the sum of the two flanks'); α′ absent, or α′ ≤ α with the
    ``free_ball`` construction, is the single flank of [001, eq. 1].

    ``common``: one spring balances the sum of the axial pushes, and statics
    fixes the sum of the tangential forces (ΣF_t,j D0/2 = T) however unevenly
    the balls share it, so K_r drops out: T = D0 F_spring / (2 tan α). This is
    the clutch the paper draws; its eq. 3 over-states its torque by K_r i.

    Examples
    --------
    >>> round(torque_limit(22.4746, 0.05, math.radians(45.0)), 5)
    0.56187
    >>> round(torque_limit(22.4746, 0.05, math.radians(45.0), 4, 0.85,
    ...                    arrangement="per_ball"), 4)
    1.9103
    """
    push = np.asarray(
        combined_push_factor(groove_angle, flank_friction, driving_groove_angle, construction)
    )
    share = torque_sharing(arrangement, ball_count, load_factor)
    return _where_pushing(
        push,
        lambda p: _torque_of_push(
            np.asarray(share), np.asarray(ball_circle_diameter), np.asarray(spring_force), p
        ),
    )


def _torque_of_push(sharing: Any, ball_circle_diameter: Any, spring_force: Any, push: Any) -> Any:
    """T = s D0 F / (2 p) [001, eq. 3], for :func:`torque_limit` and
    :func:`torque_against_lift` (the same numbers at zero lift).

    The factors other than the force first, (s D0 / (2 p)) F: where only the force
    varies (a spring swept, the groove fixed) that is one product over the points, not
    a product and a division. It may differ from s D0 F / (2 p) in the last bit.

    >>> _torque_of_push(1.0, 0.05, 22.4746, 1.0)
    0.561865
    """
    return sharing * ball_circle_diameter / (2.0 * push) * spring_force


def spring_force_for_torque(
    torque: FloatArray,
    ball_circle_diameter: FloatArray,
    groove_angle: FloatArray,
    ball_count: FloatArray = 1,
    load_factor: FloatArray = 0.85,
    flank_friction: FloatArray = 0.0,
    arrangement: str = "common",
    driving_groove_angle: FloatArray | None = None,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Spring force that sets the slipping torque to ``torque`` (inverse of :func:`torque_limit`).

    .. math::
        F_{spring} = \frac{2 T p}{D_0 \, s}, \quad p = \tan(\alpha - \rho), \quad
        s = 1 \text{ (common)}, \; K_r i \text{ (per ball)}

    Parameters
    ----------
    torque : float
        Target slipping torque, [N*m]
    ball_circle_diameter : float
        Diameter D0 of the ball circle, [m]
    groove_angle : float
        Flank angle α, [rad]
    ball_count : int, optional
        Number of balls i (``per_ball`` only), [-]
    load_factor : float, optional
        K_r (``per_ball`` only), [-]
    flank_friction : float, optional
        Flank friction coefficient f, [-]
    arrangement : {"common", "per_ball"}, optional
        Spring arrangement, as in :func:`torque_limit`
    driving_groove_angle : float or None, optional
        α′, as in :func:`torque_limit`, [rad]
    construction : {"free_ball", "pressure_disc"}, optional
        As in :func:`torque_limit`, [-]

    Returns
    -------
    force : float
        Required spring force; NaN where the push p ≤ 0, [N]

    Notes
    -----
    [001, eq. 1–3] solved for F_spring; with α′ the push p is
    :func:`combined_push_factor`'s, the same as :func:`torque_limit` takes, so
    a spring sized here slips at the target.

    Examples
    --------
    >>> round(spring_force_for_torque(0.5618655, 0.05, math.radians(45.0)), 4)
    22.4746
    """
    push = np.asarray(
        combined_push_factor(groove_angle, flank_friction, driving_groove_angle, construction)
    )
    share = torque_sharing(arrangement, ball_count, load_factor)
    return _where_pushing(
        push,
        lambda p: 2.0 * np.asarray(torque) * p / (np.asarray(ball_circle_diameter) * share),
    )


def spring_deflection_for_force(
    force: FloatArray,
    shear_modulus: FloatArray,
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
) -> FloatArray:
    r"""Spring compression (the nut setting) that gives ``force`` [001, eq. 2].

    .. math::
        \Delta = \frac{8 F D^3 i_p}{G d_0^4}

    Parameters
    ----------
    force : float
        Required spring force, [N]
    shear_modulus : float
        Shear modulus G, [Pa]
    wire_diameter : float
        Wire diameter d0, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    active_coils : float
        Active coils i_p, [-]

    Returns
    -------
    deflection : float
        Compression Δ, [m]

    Notes
    -----
    [001, eq. 2] solved for Δ.

    Examples
    --------
    >>> round(spring_deflection_for_force(22.4746, 8e10, 0.004, 0.045, 5) * 1e3, 4)
    4.0
    """
    rate = spring_rate(shear_modulus, wire_diameter, mean_diameter, active_coils)
    return _out(np.asarray(force) / rate)


def wire_diameter_for_force(
    force: FloatArray,
    shear_modulus: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
    deflection: FloatArray,
) -> FloatArray:
    r"""Wire diameter whose spring gives ``force`` at compression Δ [001, eq. 2].

    .. math::
        d_0 = \left(\frac{8 F D^3 i_p}{G \Delta}\right)^{1/4}

    Parameters
    ----------
    force : float
        Required spring force, [N]
    shear_modulus : float
        Shear modulus G, [Pa]
    mean_diameter : float
        Mean coil diameter D (held fixed), [m]
    active_coils : float
        Active coils i_p (held fixed), [-]
    deflection : float
        Chosen compression Δ, [m]

    Returns
    -------
    diameter : float
        Wire diameter d0, [m]

    Notes
    -----
    [001, eq. 2] is a power law in d0, so the inverse is closed form. A
    standard wire size is then chosen and the deflection re-set with
    :func:`spring_deflection_for_force`.

    Examples
    --------
    >>> round(wire_diameter_for_force(22.4746, 8e10, 0.045, 5, 0.004) * 1e3, 4)
    4.0
    """
    ratio = (
        8.0
        * np.asarray(force)
        * np.asarray(mean_diameter) ** 3
        * np.asarray(active_coils)
        / (np.asarray(shear_modulus) * np.asarray(deflection))
    )
    return _out(ratio**0.25)


def spring_deflection_for_torque(
    torque: FloatArray,
    ball_circle_diameter: FloatArray,
    groove_angle: FloatArray,
    shear_modulus: FloatArray,
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
    ball_count: FloatArray = 1,
    load_factor: FloatArray = 0.85,
    flank_friction: FloatArray = 0.0,
    arrangement: str = "common",
) -> FloatArray:
    r"""Nut setting (spring compression) that makes the clutch slip at ``torque``.

    .. math::
        \Delta = \frac{8 D^3 i_p}{G d_0^4} \cdot \frac{2 T \tan(\alpha - \rho)}{D_0 s}

    Parameters
    ----------
    torque : float
        Target slipping torque, [N*m]
    ball_circle_diameter : float
        Diameter D0 of the ball circle, [m]
    groove_angle : float
        Flank angle α, [rad]
    shear_modulus : float
        Shear modulus G, [Pa]
    wire_diameter : float
        Wire diameter d0, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    active_coils : float
        Active coils i_p, [-]
    ball_count : int, optional
        Number of balls i (``per_ball`` only), [-]
    load_factor : float, optional
        K_r (``per_ball`` only), [-]
    flank_friction : float, optional
        Flank friction coefficient f, [-]
    arrangement : {"common", "per_ball"}, optional
        Spring arrangement, as in :func:`torque_limit`

    Returns
    -------
    deflection : float
        Spring compression Δ; NaN where α ≤ atan f, [m]

    Notes
    -----
    [001, eq. 1–3] solved for Δ: :func:`spring_force_for_torque` then
    :func:`spring_deflection_for_force`.

    Examples
    --------
    >>> round(spring_deflection_for_torque(0.5, 0.05, math.radians(45.0),
    ...                                    8e10, 0.004, 0.045, 5) * 1e3, 4)
    3.5596
    """
    force = spring_force_for_torque(
        torque,
        ball_circle_diameter,
        groove_angle,
        ball_count,
        load_factor,
        flank_friction,
        arrangement,
    )
    return spring_deflection_for_force(
        force, shear_modulus, wire_diameter, mean_diameter, active_coils
    )


def wire_diameter_for_torque(
    torque: FloatArray,
    ball_circle_diameter: FloatArray,
    groove_angle: FloatArray,
    shear_modulus: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
    deflection: FloatArray,
    ball_count: FloatArray = 1,
    load_factor: FloatArray = 0.85,
    flank_friction: FloatArray = 0.0,
    arrangement: str = "common",
) -> FloatArray:
    r"""Wire diameter that makes the clutch slip at ``torque`` for a chosen compression Δ.

    .. math::
        d_0 = \left(\frac{8 D^3 i_p}{G \Delta} \cdot
              \frac{2 T \tan(\alpha - \rho)}{D_0 s}\right)^{1/4}

    Parameters
    ----------
    torque : float
        Target slipping torque, [N*m]
    ball_circle_diameter : float
        Diameter D0 of the ball circle, [m]
    groove_angle : float
        Flank angle α, [rad]
    shear_modulus : float
        Shear modulus G, [Pa]
    mean_diameter : float
        Mean coil diameter D (held fixed), [m]
    active_coils : float
        Active coils i_p (held fixed), [-]
    deflection : float
        Chosen compression Δ, [m]
    ball_count : int, optional
        Number of balls i (``per_ball`` only), [-]
    load_factor : float, optional
        K_r (``per_ball`` only), [-]
    flank_friction : float, optional
        Flank friction coefficient f, [-]
    arrangement : {"common", "per_ball"}, optional
        Spring arrangement, as in :func:`torque_limit`

    Returns
    -------
    diameter : float
        Wire diameter d0; NaN where α ≤ atan f, [m]

    Notes
    -----
    [001, eq. 1–3] solved for d0 (a fourth root: eq. 2 is a power law in d0).

    Examples
    --------
    >>> round(wire_diameter_for_torque(0.5, 0.05, math.radians(45.0),
    ...                                8e10, 0.045, 5, 0.004) * 1e3, 4)
    3.885
    """
    force = spring_force_for_torque(
        torque,
        ball_circle_diameter,
        groove_angle,
        ball_count,
        load_factor,
        flank_friction,
        arrangement,
    )
    return wire_diameter_for_force(force, shear_modulus, mean_diameter, active_coils, deflection)


# --------------------------------------------------------------------------
# The clutch as built: two flank angles, the lift characteristic, self-locking,
# sizing from the drive (beyond [001], whose eq. 1-3 are the lift-0 point)
# --------------------------------------------------------------------------

#: Smallest margin α − atan f between the flank angle and the friction angle
#: below which the torque limit is too sensitive to friction to be set: at
#: 10° a change of f by 0.05 moves the limit by about 30 % (α = 30°).
SELF_LOCKING_MARGIN = math.radians(10.0)
#: Service factors torque-limiter makers recommend on the drive's torque.
RECOMMENDED_SERVICE_FACTOR = (1.5, 3.0)


#: The two constructions of a clutch with both grooves inclined (α′ > 0).
CONSTRUCTIONS: tuple[str, ...] = ("free_ball", "pressure_disc")


def combined_push_factor(
    groove_angle: FloatArray,
    flank_friction: FloatArray = 0.0,
    driving_groove_angle: FloatArray | None = None,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Axial push on a ball per unit tangential force, with one or two inclined flanks.

    .. math::
        p = \tan(\alpha'' - \rho) \;\text{(driving wall parallel to the axis)}, \quad
        p_{free\ ball} = \max\bigl(\tan(\alpha' - \rho), \tan(\alpha'' - \rho)\bigr), \quad
        p_{pressure\ disc} = \tan(\alpha' - \rho) + \tan(\alpha'' - \rho)

    Parameters
    ----------
    groove_angle : float
        α″, flank angle of the driven half-coupling's groove, [rad]
    flank_friction : float, optional
        f, ρ = atan f, on both flanks, [-]
    driving_groove_angle : float or None, optional
        α′, flank angle of the driving half-coupling's groove; None when the
        driving half pushes the ball circumferentially (its wall parallel to
        the axis, with no friction term), which is [001, eq. 1], [rad]
    construction : {"free_ball", "pressure_disc"}, optional
        How the two grooves meet the ball (drawings below), [-]

    Returns
    -------
    push : float
        F_a / F_t, the axial force per tangential force at impending slip, [-]

    Notes
    -----
    [001, eq. 1] writes the push of the driven flank only; [001, fig. 6] names
    both angles α′ and α″. Developed onto the ball circle (x along the
    circumference, z along the axis), the two constructions are::

        (a) free_ball: the ball between two grooved halves; half 2 slides
            along the axis against the spring

                      | F_s (spring)
                      v
          ==========.   .==========   half 2 (driven), moves along z
                     \ /    flank a''
                     (o)    ball
                     / \    flank a'
          =========='   '==========   half 1 (driving), fixed along z
                    --> x (half 1 turns)

        (b) pressure_disc: both halves fixed along the axis, side by side;
            the ball sits in the V of half 1's and half 2's flanks and lifts
            a flat disc

                      | F_s (spring)
                      v
          ==========================  pressure disc, moves along z
                     (o)    ball
          ==========\   /===========
            half 1   \ /   half 2
            a' -->    V    a''        (the V closes as half 1 turns by x)

    Virtual work, f = 0, a relative turn dx of the halves at the ball circle
    (F_t dx = F_s dz, so p = F_a/F_t = dx/dz):

    (a) The ball is free between the halves; half 2 separates by z. If the
    ball moves by b along half 2's flank and by x − b along half 1's, the
    halves separate by z = b/tan α″ + (x − b)/tan α′. The spring takes the
    smallest z: z is linear in b, so the ball stays seated in one groove and
    rides the other, the flatter one (the larger angle):
    z = x / max(tan α′, tan α″), p = max(tan α′, tan α″). A steeper driving
    groove changes nothing: α′ ≤ α″ is the clutch of [001, eq. 1–3].

    (b) The halves cannot separate; the ball touches both flanks and lifts the
    disc: z tan α′ + z tan α″ = x (the V closes by x), so
    p = tan α′ + tan α″. Equal angles give twice the push of eq. 1 and half
    the torque for the same spring.

    With flank friction each sliding contact's reaction tilts by ρ against the
    ball's climb, as in :func:`flank_push_factor`: (a) the ball slides on the
    flank it rides, p = tan(max(α′, α″) − ρ); (b) it slides up both,
    R′ cos(α′ − ρ) = R″ cos(α″ − ρ) = F_t and
    F_a = R′ sin(α′ − ρ) + R″ sin(α″ − ρ). The ball's own moment balance (it
    may roll on one flank and slide on the other) is neglected, as in the
    paper. Where both pushes are positive the max is the smaller, so the max
    rule gives the larger slip torque of the two for the same spring: it never
    under-reports the torque the clutch passes, and it is the default.

    Examples
    --------
    >>> round(combined_push_factor(math.radians(45.0)), 12)
    1.0
    >>> round(combined_push_factor(math.radians(45.0), 0.0, math.radians(45.0)), 12)
    1.0
    >>> round(combined_push_factor(math.radians(45.0), 0.0, math.radians(45.0),
    ...                            "pressure_disc"), 12)
    2.0
    """
    push = flank_push_factor(groove_angle, flank_friction)
    if driving_groove_angle is None:
        return _out(push)
    driving = flank_push_factor(driving_groove_angle, flank_friction)
    if construction == "free_ball":
        return _out(np.maximum(push, driving))
    if construction == "pressure_disc":
        return _out(np.asarray(push) + np.asarray(driving))
    raise ValueError(f"construction must be one of {CONSTRUCTIONS}, not {construction!r}")


def riding_flank_angle(
    groove_angle: FloatArray,
    driving_groove_angle: FloatArray | None = None,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Flank angle of the groove the ball climbs out of (the lift geometry's α).

    .. math::
        \alpha_{ride} = \max(\alpha', \alpha'') \;\text{(free ball)}, \qquad
        \alpha_{ride} = \alpha'' \;\text{(pressure disc, or no α′)}

    Parameters
    ----------
    groove_angle : float
        α″ of the driven groove, [rad]
    driving_groove_angle : float or None, optional
        α′ of the driving groove, [rad]
    construction : {"free_ball", "pressure_disc"}, optional
        As in :func:`combined_push_factor`, [-]

    Returns
    -------
    angle : float
        The flank (and rim) the lift follows, [rad]

    Notes
    -----
    A free ball rides the flatter of the two flanks (:func:`combined_push_factor`,
    construction (a)) and then over that groove's rim; under a pressure disc
    only the driven groove's rim is modelled (as before the constructions were
    told apart).

    Examples
    --------
    >>> round(math.degrees(riding_flank_angle(math.radians(30.0), math.radians(50.0))), 9)
    50.0
    >>> round(math.degrees(riding_flank_angle(math.radians(30.0), math.radians(50.0),
    ...                                       "pressure_disc")), 9)
    30.0
    """
    if driving_groove_angle is None or construction == "pressure_disc":
        return _out(groove_angle)
    return _out(np.maximum(np.asarray(groove_angle), np.asarray(driving_groove_angle)))


def self_locking_margin(
    groove_angle: FloatArray,
    flank_friction: FloatArray,
    driving_groove_angle: FloatArray | None = None,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Margin between the flank angle the ball must slide on and the friction angle.

    .. math::
        m = \alpha_{ride} - \rho \;\text{(free ball)}, \qquad
        m = \min(\alpha', \alpha'') - \rho \;\text{(pressure disc)}

    Parameters
    ----------
    groove_angle : float
        α″, [rad]
    flank_friction : float
        f, ρ = atan f, [-]
    driving_groove_angle : float or None, optional
        α′, [rad]
    construction : {"free_ball", "pressure_disc"}, optional
        As in :func:`combined_push_factor`, [-]

    Returns
    -------
    margin : float
        m; at or below 0 a sliding flank self-locks, [rad]

    Notes
    -----
    A free ball slides only on the flank it rides (:func:`riding_flank_angle`);
    under a pressure disc it slides up both, and the steeper locks first.

    Examples
    --------
    >>> round(math.degrees(self_locking_margin(math.radians(45.0), 0.0)), 9)
    45.0
    >>> round(math.degrees(self_locking_margin(math.radians(45.0), 0.0, math.radians(30.0),
    ...                                        "pressure_disc")), 9)
    30.0
    """
    rho = np.arctan(flank_friction)
    if driving_groove_angle is not None and construction == "pressure_disc":
        return _out(np.minimum(np.asarray(groove_angle), np.asarray(driving_groove_angle)) - rho)
    return _out(np.asarray(riding_flank_angle(groove_angle, driving_groove_angle)) - rho)


def rim_rise(ball_diameter: FloatArray, groove_angle: FloatArray) -> FloatArray:
    r"""Rise of the ball's centre while it rolls over the groove's rim onto the face.

    .. math::
        \Delta z_{rim} = \frac{d}{2}\,(1 - \sin\alpha)

    Parameters
    ----------
    ball_diameter : float
        d, [m]
    groove_angle : float
        α, flank angle (its normal makes α with the plane of rotation), [rad]

    Returns
    -------
    rise : float
        Extra lift after the flank, [m]

    Notes
    -----
    Geometry of a sphere pivoting on the rim edge: with the contact normal at
    angle β from the plane of rotation the centre stands r sin β above the
    edge, from β = α (leaving the flank) to β = 90° (on the face). Not in
    [001].

    Examples
    --------
    >>> round(rim_rise(0.01, math.radians(45.0)) * 1e3, 4)
    1.4645
    """
    return _out(np.asarray(ball_diameter) / 2.0 * (1.0 - np.sin(np.asarray(groove_angle))))


def lift_points(
    ball_lift: FloatArray,
    ball_diameter: FloatArray,
    groove_angle: FloatArray,
    points: int = 41,
    from_rim: bool = False,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    r"""Lifts from seated to riding on the face, and the contact angle at each.

    .. math::
        \beta(z) = \alpha \;(z \le h), \qquad
        \sin\beta(z) = \sin\alpha + \frac{z - h}{d/2} \;(z > h)

    Parameters
    ----------
    ball_lift : float
        h, the ball's rise along the flank from seated to the rim, [m]
    ball_diameter : float
        d, [m]
    groove_angle : float
        α of the driven groove, [rad]
    points : int, optional
        Points on the flank and as many over the rim, [-]
    from_rim : bool, optional
        Only the points from the flank's end (z = h) on, [-]

    Returns
    -------
    lift : ndarray
        Lift z of the ball (and of the pressure disk), ascending, [m]
    angle : ndarray
        Contact angle β at each lift, α on the flank, → 90° on the face, [rad]

    Notes
    -----
    On the flank the angle is α ([001, eq. 1]); over the rim it follows
    :func:`rim_rise`. Rim points are spaced evenly in β. The arguments may be
    floats or numpy arrays of one shape: the lifts then run along a last axis
    of ``2 points − 1`` entries.

    Examples
    --------
    >>> z, b = lift_points(0.004, 0.01, math.radians(45.0), 3)
    >>> [round(float(v) * 1e3, 4) for v in z]
    [0.0, 2.0, 4.0, 5.0839, 5.4645]
    >>> lift_points([0.004, 0.002], 0.01, math.radians(45.0), 3)[0].shape
    (2, 5)
    >>> [round(float(v) * 1e3, 4) for v in lift_points(0.004, 0.01, math.radians(45.0), 3, True)[0]]
    [4.0, 5.0839, 5.4645]
    """
    h, d, a = np.broadcast_arrays(
        np.asarray(ball_lift, float),
        np.asarray(ball_diameter, float),
        np.asarray(groove_angle, float),
    )
    h, r, a = h[..., None], d[..., None] / 2.0, a[..., None]
    u = np.linspace(0.0, 1.0, points)
    beta_rim = a + u[1:] * (math.pi / 2.0 - a)
    flank = u[-1:] if from_rim else u
    lift = np.concatenate([flank * h, h + r * (np.sin(beta_rim) - np.sin(a))], axis=-1)
    seated = np.broadcast_to(a, (*a.shape[:-1], flank.size))
    return lift, np.concatenate([seated, beta_rim], axis=-1)


def rim_torque_slope(
    deflection_at_rim: FloatArray,
    ball_diameter: FloatArray,
    riding_angle: FloatArray,
    flank_friction: FloatArray,
    push: FloatArray,
) -> FloatArray:
    r"""Slope of ln T over the rim's contact angle where the ball leaves the flank.

    .. math::
        \left.\frac{d \ln T}{d\beta}\right|_{\beta=\alpha} =
        \frac{(d/2)\cos\alpha}{s_h} - \frac{1}{p(\alpha)\,\cos^2(\alpha - \rho)}

    Parameters
    ----------
    deflection_at_rim : float
        s_h = Δ + h, the helical spring's total deflection with the ball at the rim, [m]
    ball_diameter : float
        d, [m]
    riding_angle : float
        α of the flank the ball climbs (:func:`riding_flank_angle`), [rad]
    flank_friction : float
        f, ρ = atan f, [-]
    push : float
        p(α), :func:`combined_push_factor` at the riding angle, [-]

    Returns
    -------
    slope : float
        d ln T / dβ at β = α; at or below 0 the peak of the characteristic is at the
        rim (see Notes), [1/rad]

    Notes
    -----
    :func:`torque_against_lift` with a helical spring (F = c s) and the lift of
    :func:`lift_points`: T(β) = K c (s_h + (d/2)(sin β − sin α)) / p(β), p =
    tan(β − ρ) + c₀ (c₀ = tan(α′ − ρ) under a pressure disc, else 0: a free ball
    rides the flatter flank, so p = tan(β − ρ) from its rim on), whose logarithmic
    derivative at β = α is the expression above. The sign of dT/dβ over the rim is
    that of φ(β) = (d/2) cos β cos x (sin x + c₀ cos x) − s(β), x = β − ρ, and
    φ′ = −(d/2)(sin x + c₀ cos x)(sin β cos x + 2 cos β sin x) < 0 wherever p > 0 and
    0 < x < 90°: T has at most one maximum over the rim, and along the flank (β = α)
    it rises with the spring force. With slope ≤ 0 and α > ρ the characteristic's
    peak is therefore the torque at the rim, T(h) = T(0) s_h/Δ. Derived here from
    [001, eq. 1–3] and the rim geometry (:func:`rim_rise`); not in [001].

    Examples
    --------
    A 10 mm ball on 45° flanks, 8 mm of deflection at the rim, f = 0 (p = 1):
    5 · 0.7071/8 − 1/(1 · 0.5) = −1.558, the torque falls from the rim on; with 1 mm
    it rises (+1.536):

    >>> round(rim_torque_slope(0.008, 0.01, math.radians(45.0), 0.0, 1.0), 4)
    -1.5581
    >>> round(rim_torque_slope(0.001, 0.01, math.radians(45.0), 0.0, 1.0), 4)
    1.5355
    """
    alpha = np.asarray(riding_angle, dtype=float)
    cos_x = np.cos(alpha - np.arctan(flank_friction))
    return _out(
        np.asarray(ball_diameter) / 2.0 * np.cos(alpha) / np.asarray(deflection_at_rim)
        - 1.0 / (np.asarray(push) * cos_x * cos_x)
    )


def torque_against_lift(
    spring_force: FloatArray,
    contact_angle: FloatArray,
    ball_circle_diameter: FloatArray,
    flank_friction: FloatArray = 0.0,
    driving_groove_angle: FloatArray | None = None,
    sharing: FloatArray = 1.0,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Torque that holds the balls at a lift, from the spring force there.

    .. math::
        T(z) = \frac{s \, D_0 \, F(z)}{2 \, p(\beta(z))}, \qquad
        p = \tan(\beta - \rho) \;\text{or}\; \max(\cdot, \tan(\alpha' - \rho))
        \;\text{or}\; \tan(\beta - \rho) + \tan(\alpha' - \rho)

    Parameters
    ----------
    spring_force : float or array
        Spring force F(z) at each lift, [N]
    contact_angle : float or array
        β(z) from :func:`lift_points`, [rad]
    ball_circle_diameter : float
        D0, [m]
    flank_friction : float, optional
        f, [-]
    driving_groove_angle : float or None, optional
        α′, see :func:`combined_push_factor`, [rad]
    sharing : float, optional
        s = 1 for one common spring, K_r i for one spring per ball, [-]
    construction : {"free_ball", "pressure_disc"}, optional
        With α′: the max or the sum of the pushes (:func:`combined_push_factor`), [-]

    Returns
    -------
    torque : float or array
        T(z), [N*m]

    Notes
    -----
    [001, eq. 1-3] at each lift with the spring force there: at z = 0 it is
    :func:`torque_limit` exactly. Rising spring force raises T along the flank;
    over the rim β → 90° and T falls to f D0 F/2 (sliding on the face); a
    falling disc-spring force lowers T from the start.

    Examples
    --------
    >>> round(torque_against_lift(22.4746, math.radians(45.0), 0.05), 5)
    0.56187
    """
    push = combined_push_factor(contact_angle, flank_friction, driving_groove_angle, construction)
    return _out(
        _torque_of_push(sharing, ball_circle_diameter, np.asarray(spring_force), np.asarray(push))
    )


def residual_torque(
    spring_force: FloatArray,
    ball_circle_diameter: FloatArray,
    face_friction: FloatArray,
    springs: FloatArray = 1.0,
) -> FloatArray:
    r"""Torque while the balls ride on the end face (the clutch slipping).

    .. math::
        T_{res} = n_s \, \mu_f \, F \, \frac{D_0}{2}

    Parameters
    ----------
    spring_force : float
        Spring force at full lift (each spring's, for one spring per ball), [N]
    ball_circle_diameter : float
        D0, [m]
    face_friction : float
        μ_f, effective friction of the balls on the face (rolling with the
        drag in their pockets; ≈ 0.002 free rolling … 0.1 sliding), [-]
    springs : float, optional
        n_s, 1 for one common spring, the ball count for one spring per ball, [-]

    Returns
    -------
    torque : float
        T_res, [N*m]

    Notes
    -----
    Coulomb friction of the spring force on the ball circle; not in [001].

    Examples
    --------
    >>> round(residual_torque(100.0, 0.05, 0.01), 4)
    0.025
    """
    return _out(
        np.asarray(springs)
        * np.asarray(face_friction)
        * np.asarray(spring_force)
        * np.asarray(ball_circle_diameter)
        / 2.0
    )


def friction_sensitivity(
    torque: FloatArray,
    groove_angle: FloatArray,
    flank_friction: FloatArray,
    driving_groove_angle: FloatArray | None = None,
    construction: str = "free_ball",
) -> FloatArray:
    r"""Change of the torque limit per unit change of the flank friction, dT/df.

    .. math::
        \frac{dT}{df} = \frac{T}{p}\,\frac{\sec^2(\alpha_{ride} - \rho)
                        \;[+ \sec^2(\alpha' - \rho)\;\text{pressure disc}]}{1 + f^2}

    Parameters
    ----------
    torque : float
        Torque limit T at f, [N*m]
    groove_angle : float
        α″, [rad]
    flank_friction : float
        f, [-]
    driving_groove_angle : float or None, optional
        α′, [rad]
    construction : {"free_ball", "pressure_disc"}, optional
        As in :func:`combined_push_factor`, [-]

    Returns
    -------
    sensitivity : float
        dT/df, [N*m]

    Notes
    -----
    Derivative of T = s D0 F/(2p) with p from :func:`combined_push_factor`,
    dρ/df = 1/(1 + f²); a free ball slides on its riding flank only
    (:func:`riding_flank_angle`). Near self-locking (α − ρ → 0) it grows without bound.

    Examples
    --------
    >>> round(friction_sensitivity(1.0, math.radians(45.0), 0.0), 6)
    2.0
    """
    rho = np.arctan(flank_friction)
    push = combined_push_factor(groove_angle, flank_friction, driving_groove_angle, construction)
    if construction == "pressure_disc" and driving_groove_angle is not None:
        dpush = 1.0 / np.cos(np.asarray(groove_angle) - rho) ** 2  # d/dρ of tan(α − ρ)
        dpush = dpush + 1.0 / np.cos(np.asarray(driving_groove_angle) - rho) ** 2
    else:  # the one flank the ball slides on
        ride = np.asarray(riding_flank_angle(groove_angle, driving_groove_angle))
        dpush = 1.0 / np.cos(ride - rho) ** 2
    return _out(np.asarray(torque) / push * dpush / (1.0 + np.asarray(flank_friction) ** 2))


def rated_torque(power: FloatArray, speed: FloatArray) -> FloatArray:
    r"""Rated torque of a drive from its power and speed.

    .. math::
        T_N = \frac{P}{\omega}

    Parameters
    ----------
    power : float
        P, [W]
    speed : float
        ω, [rad/s]

    Returns
    -------
    torque : float
        T_N, [N*m]

    Notes
    -----
    Definition of power; the coupling-selection practice of limiter makers
    starts from it.

    Examples
    --------
    >>> round(rated_torque(1500.0, 157.08), 3)
    9.549
    """
    return _out(np.divide(power, speed))


def acceleration_torque(
    drive_torque: FloatArray,
    drive_inertia: FloatArray,
    load_inertia: FloatArray,
    load_torque: FloatArray = 0.0,
) -> FloatArray:
    r"""Torque through a coupling while the drive accelerates the load.

    .. math::
        T_a = T_{drive}\frac{J_L}{J_A + J_L} + T_L \frac{J_A}{J_A + J_L}

    Parameters
    ----------
    drive_torque : float
        Peak torque of the drive (motor) while starting, [N*m]
    drive_inertia : float
        J_A, inertia on the driving side of the coupling, [kg*m^2]
    load_inertia : float
        J_L, inertia on the driven side (referred to the coupling's speed), [kg*m^2]
    load_torque : float, optional
        T_L, steady resisting torque of the load, [N*m]

    Returns
    -------
    torque : float
        T_a, [N*m]

    Notes
    -----
    Two rigid inertias joined by the coupling, both accelerating at
    (T_drive − T_L)/(J_A + J_L): the coupling carries T_L plus the torque that
    accelerates J_L. The same split as the couplings makers' start-up load
    formula. A limiter set below T_a slips at every start.

    Examples
    --------
    >>> acceleration_torque(30.0, 0.01, 0.02)
    20.0
    """
    ja, jl = np.asarray(drive_inertia), np.asarray(load_inertia)
    total = ja + jl
    return _out(np.asarray(drive_torque) * jl / total + np.asarray(load_torque) * ja / total)


def required_slip_torque(
    rated: FloatArray, service_factor: FloatArray, start_torque: FloatArray = 0.0
) -> FloatArray:
    r"""Slip torque a limiter must be set to so that it carries the drive.

    .. math::
        T_{slip} = \max(K \, T_N, \; T_a)

    Parameters
    ----------
    rated : float
        T_N, rated torque of the drive (or its peak working torque), [N*m]
    service_factor : float
        K, 1.5…3 as limiter makers recommend (smooth … shock loads), [-]
    start_torque : float, optional
        T_a from :func:`acceleration_torque`, [N*m]

    Returns
    -------
    torque : float
        Required slip torque, [N*m]

    Notes
    -----
    Torque-limiter selection practice: the set torque covers the working
    torque with a service factor and is not reached while starting.

    Examples
    --------
    >>> required_slip_torque(10.0, 2.0, 25.0)
    25.0
    """
    return _out(np.maximum(np.multiply(rated, service_factor), start_torque))


# --------------------------------------------------------------------------
# The nut-runner's friction clutches [000]: torque from the clamp of their nuts
# --------------------------------------------------------------------------

#: Friction radius laws of an annular friction face.
FRICTION_LAWS: tuple[str, ...] = ("uniform_wear", "uniform_pressure")


def friction_clutch_torque(
    clamp_force: FloatArray,
    friction: FloatArray,
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    faces: FloatArray = 1,
    law: str = "uniform_wear",
) -> FloatArray:
    r"""Torque a plate (diaphragm) friction clutch transmits before it slips.

    .. math::
        M_{tr} = z_f \, \mu \, F \, R_f, \qquad
        R_f = \frac{D + d}{4} \;\text{(uniform wear)}, \qquad
        R_f = \frac{D^3 - d^3}{3 (D^2 - d^2)} \;\text{(uniform pressure)}

    Parameters
    ----------
    clamp_force : float
        F, axial force the nut clamps the friction faces with, [N]
    friction : float
        μ, friction coefficient of the faces, [-]
    outer_diameter : float
        D, outer diameter of the annular contact, [m]
    inner_diameter : float
        d, inner diameter of the annular contact (0 for a full disc), [m]
    faces : int, optional
        z_f, number of friction faces the clamp force passes through, [-]
    law : {"uniform_wear", "uniform_pressure"}, optional
        Pressure distribution over the annulus, [-]

    Returns
    -------
    torque : float
        M_tr, [N*m]

    Notes
    -----
    [000] says the friction clutches (diaphragms 11 pressed against the spindle
    gears 5 by nuts 12) carry a small torque "regulated by the clamp force" and
    gives no formula for it; this is the textbook plate-clutch capacity ([Bhandari],
    chapter "Friction Clutches"): Coulomb friction of the clamp force at the friction
    radius. Uniform wear (a worn-in clutch, p·r constant) gives the smaller
    radius, by at most 1/3 for a full disc.

    Examples
    --------
    >>> round(friction_clutch_torque(1000.0, 0.15, 0.06, 0.03), 6)
    3.375
    >>> round(friction_clutch_torque(1000.0, 0.15, 0.06, 0.03, law="uniform_pressure"), 6)
    3.5
    """
    big, small = np.asarray(outer_diameter, float), np.asarray(inner_diameter, float)
    if law == "uniform_wear":
        radius = (big + small) / 4.0
    elif law == "uniform_pressure":
        radius = (big**3 - small**3) / (3.0 * (big**2 - small**2))
    else:
        raise ValueError(f"law must be one of {FRICTION_LAWS}, not {law!r}")
    return _out(np.asarray(faces) * np.asarray(friction) * np.asarray(clamp_force) * radius)
