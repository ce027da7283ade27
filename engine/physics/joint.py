r"""The bolted joint after VDI 2230 Part 1: compliances, service loads, losses, preload window.

Pure functions on SI floats, one per calculation step of VDI 2230-1:2015
(steps R0–R13). The model (``engine.models.joint``) runs them in one procedure
for a single design and for a sweep or study alike, so they also take numpy
arrays, one entry per point (a sweep's or a study's): math for floats (a single run's speed
and exceptions), numpy for arrays, one formula each; ``joint_diagram`` stays
scalar (a series for one design). VDI 2230's
own text is paywalled and was not available to us; every relation here is
the one reproduced, with VDI's step and equation symbols, in the open
secondary sources named in each docstring:

* ECSS-E-HB-32-23A (ESA, *Threaded fasteners handbook*, 2010), §6.3 (preload,
  embedding, thermal), §7.5–7.6 (bolt and clamped-part compliance), which
  reproduces the VDI 2230 cone/sleeve model and the VDI embedding table;
* the open implementation misams/BAT (ECSS-E-HB-32-23A with VDI 2230
  nomenclature), read for its formulas and run side by side in
  ``tests/validation/test_joint_compliance.py``;
* the preload and torque relations of VDI 2230 steps R7 and R13 already in
  :mod:`engine.physics.preload` (reused here, not rewritten).

Where the brief for this model and VDI's numbering differ: VDI 2230-1 numbers
the alternating stress R9, the surface pressure R10, the length of engagement
(thread stripping) R11 and slipping R12. Surface pressure and thread stripping
are not computed here (see :data:`engine.models.joint.CHECK_HOOKS`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple

import numpy as np

from ..core.errors import InputOutOfRange

#: Head length factor l_SK/d of VDI 2230-1 R3 (ECSS-E-HB-32-23A Table 7-1): hexagon 0.5, socket 0.4.
HEAD_LENGTH_FACTOR: dict[str, float] = {"hex": 0.5, "socket": 0.4}

#: Engaged-thread length factor l_G/d (VDI 2230-1 R3).
ENGAGED_THREAD_FACTOR = 0.5

#: Nut / tapped-thread length factor l_M/d (VDI 2230-1 R3): 0.4 for a nut (through-bolted
#: joint, DSV), 0.33 for a tapped thread (ESV); ECSS-E-HB-32-23A §7.5.5 uses the same.
NUT_LENGTH_FACTOR: dict[str, float] = {"through": 0.4, "tapped": 0.33}

#: Embedding f_Z [µm] per location, VDI 2230-1:2015 Table 5.4/1 (as reproduced in
#: ECSS-E-HB-32-23A Table 6-3): roughness class -> load -> (thread, each bearing face,
#: each inner interface).
EMBEDDING_UM: dict[str, dict[str, tuple[float, float, float]]] = {
    "Rz<10": {"axial": (3.0, 2.5, 1.5), "transverse": (3.0, 3.0, 2.0)},
    "Rz10-40": {"axial": (3.0, 3.0, 2.0), "transverse": (3.0, 4.5, 2.5)},
    "Rz40-160": {"axial": (3.0, 4.0, 3.0), "transverse": (3.0, 6.5, 3.5)},
}
ROUGHNESS_CLASSES: tuple[str, ...] = tuple(EMBEDDING_UM)

#: Torsional stress share kept in service (VDI 2230-1 R8): k_τ = 0.5.
TORSION_REDUCTION_IN_SERVICE = 0.5

#: τ_B/R_m of a fitted shank in shear (VDI 2230-1 R12; the ratio the engine also takes for
#: the bolt's thread in shear).
SHANK_SHEAR_RATIO = 0.6

#: Smallest cone tangent used: the VDI fit is not meant for plates far thinner than d_W.
MIN_CONE_TANGENT = 0.1


def _area(diameter: float) -> float:
    return 0.25 * math.pi * diameter * diameter


# Float or array: every function below takes SI floats (math, the scalar path's speed and
# its exceptions kept) or numpy arrays (one request's points at once). The
# helpers pick math or numpy by the arguments' type, so each formula is written once; each
# tests for Python numbers first (``type(x) is float`` costs no call), the case of every
# single-design run, and otherwise decides as before.

#: The types a helper takes for a plain Python number (no numpy involved).
_NUMBER = frozenset((float, bool, int))


def _arrays(*values: object) -> bool:
    for v in values:  # noqa: SIM110 (a loop, not any(...): it runs on every scalar call)
        if isinstance(v, np.ndarray):
            return True
    return False


def _log(value: Any) -> Any:
    if type(value) is float:
        return math.log(value)
    return np.log(value) if isinstance(value, np.ndarray) else math.log(value)


def _sqrt(value: Any) -> Any:
    return np.sqrt(value) if isinstance(value, np.ndarray) else math.sqrt(value)


def _max(a: Any, b: Any) -> Any:
    if type(a) is float and type(b) is float:
        return b if b > a else a  # what max(a, b) returns, without its call
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.maximum(a, b)
    return b if b > a else a


def _where(condition: Any, a: Any, b: Any) -> Any:
    if type(condition) is bool and type(a) in _NUMBER and type(b) in _NUMBER:
        return a if condition else b
    if isinstance(condition, np.ndarray) or isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.where(condition, a, b)
    return a if condition else b


def _quotient(ok: Any, numerator: Any, denominator: Any, otherwise: float) -> Any:
    """numerator/denominator where ``ok``, ``otherwise`` elsewhere (floats: not divided there)."""
    if type(ok) is bool and type(numerator) in _NUMBER and type(denominator) in _NUMBER:
        return numerator / denominator if ok else otherwise
    if _arrays(ok, numerator, denominator):
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(ok, numerator / denominator, otherwise)
    return numerator / denominator if ok else otherwise


def _largest(value: Any) -> Any:
    if type(value) is float:
        return value
    return value.max(initial=0.0) if isinstance(value, np.ndarray) else value


def _every(flags: Any) -> bool:
    if type(flags) is bool:
        return flags
    return bool(flags.all()) if isinstance(flags, np.ndarray) else bool(flags)


def _min(a: Any, b: Any) -> Any:
    if type(a) is float and type(b) is float:
        return b if b < a else a  # what min(a, b) returns, without its call
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.minimum(a, b)
    return b if b < a else a


# In place on the arrays a step makes itself: a sum of terms over many points costs one new
# array, not one per term. The operations and their order are the formula's (IEEE addition
# commutes bit for bit), so a point gives what it gives alone.


def _fits(made: Any, other: Any) -> bool:
    """Whether ``made`` (an array the calling step computed itself, no one else's) can hold
    its elementwise result with ``other``: float64, of the result's shape."""
    return (
        isinstance(made, np.ndarray)
        and made.dtype == np.float64
        and (not isinstance(other, np.ndarray) or other.shape == made.shape)
    )


def _add_to(made: Any, other: Any) -> Any:
    """``made + other`` (equal bit for bit to ``other + made``), into ``made`` where it fits."""
    if type(made) is float or not _fits(made, other):
        return made + other
    return np.add(made, other, out=made)


def _subtract_from(made: Any, other: Any) -> Any:
    """``made - other``, into ``made`` where it fits (x − (+0) is x, every x: no pass)."""
    if type(made) is float or not _fits(made, other):
        return made - other
    if isinstance(other, float) and other == 0.0 and math.copysign(1.0, other) > 0.0:
        return made
    return np.subtract(made, other, out=made)


def _subtract_into(other: Any, made: Any) -> Any:
    """``other - made``, into ``made`` where it fits."""
    if type(made) is float or not _fits(made, other):
        return other - made
    return np.subtract(other, made, out=made)


class BoltCompliance(NamedTuple):
    """The bolt's axial compliance by section (VDI 2230-1 R3), [m/N].

    A named tuple, not a frozen dataclass: as immutable, and built in a third of the time
    on every single-design run (the results below are NamedTuples for the same reason).
    """

    head: float
    shank: float
    free_thread: float
    engaged_thread: float
    nut: float

    @property
    def total(self) -> float:
        """δ_S, the sum of the sections, [m/N]."""
        return self.head + self.shank + self.free_thread + self.engaged_thread + self.nut

    @property
    def engaged(self) -> float:
        """δ_GM = δ_G + δ_M, the engaged thread with the nut or tapped part, [m/N]."""
        return self.engaged_thread + self.nut


def bolt_compliance(
    diameter: float,
    minor_diameter: float,
    youngs_modulus: float,
    sections: Sequence[tuple[float, float]],
    free_thread_length: float,
    head: str = "hex",
    joint: str = "through",
    nut_youngs_modulus: float | None = None,
) -> BoltCompliance:
    r"""Axial compliance of a bolt from its sections, head, engaged thread and nut.

    .. math::
        \delta_S = \frac{l_{SK}}{E_S A_N} + \sum_i \frac{l_i}{E_S A_i}
            + \frac{l_{Gew}}{E_S A_{d3}} + \frac{0.5\,d}{E_S A_{d3}}
            + \frac{l_M}{E_M A_N}

    with A_N = π d²/4, A_d3 = π d3²/4, l_SK = 0.5 d (hexagon head) or 0.4 d
    (socket head), l_M = 0.4 d (nut) or 0.33 d (tapped thread).

    Parameters
    ----------
    diameter : float
        Nominal diameter d, [m]
    minor_diameter : float
        Minor diameter d3, [m]
    youngs_modulus : float
        E_S of the bolt, [Pa]
    sections : sequence of (float, float)
        (length l_i [m], diameter d_i [m]) of the plain and reduced shank sections
    free_thread_length : float
        l_Gew, loaded thread between the shank and the nut (or tapped hole), [m]
    head : str
        ``"hex"`` or ``"socket"``
    joint : str
        ``"through"`` (bolt and nut, DSV) or ``"tapped"`` (tapped thread, ESV)
    nut_youngs_modulus : float, optional
        E_M of the nut or of the part with the tapped thread; E_S when None, [Pa]

    Returns
    -------
    BoltCompliance
        The compliance of each part, [m/N]

    Notes
    -----
    VDI 2230-1:2015 step R3, eq. (5.1/3)–(5.1/13), as reproduced in
    ECSS-E-HB-32-23A §7.5.5 and Table 7-1 (which use 0.4 d for the head of
    every bolt and put the engaged thread into l_M; VDI's split 0.5 d thread +
    0.4 d/0.33 d nut is used here).

    Examples
    --------
    M12 hexagon bolt, 40 mm grip all free thread, nut:

    >>> c = bolt_compliance(0.012, 0.009853, 2.1e11, [], 0.040)
    >>> round(c.total * 1e9, 4)
    3.3276
    """
    if head not in HEAD_LENGTH_FACTOR:
        raise InputOutOfRange(
            f"head = {head!r} is not allowed: must be 'hex' or 'socket'", field="head"
        )
    if joint not in NUT_LENGTH_FACTOR:
        raise InputOutOfRange(
            f"joint_type = {joint!r} is not allowed: must be 'through' or 'tapped'",
            field="joint_type",
        )
    return _bolt_sections(
        _area,
        diameter,
        minor_diameter,
        youngs_modulus,
        sections,
        free_thread_length,
        head,
        joint,
        nut_youngs_modulus,
    )


def _bolt_sections(
    section: Callable[[Any], Any],
    diameter: float,
    minor_diameter: float,
    youngs_modulus: float,
    sections: Sequence[tuple[float, float]],
    free_thread_length: float,
    head: str,
    joint: str,
    nut_youngs_modulus: float | None,
) -> BoltCompliance:
    """Σ l_i/(E S_i) over VDI 2230-1 R3's bolt sections, S the area (axial) or the second
    moment (bending) of each section's diameter: one list of sections for both."""
    e_nut = youngs_modulus if nut_youngs_modulus is None else nut_youngs_modulus
    a_n, a_d3 = section(diameter), section(minor_diameter)
    return BoltCompliance(
        head=HEAD_LENGTH_FACTOR[head] * diameter / (youngs_modulus * a_n),
        shank=sum((li / (youngs_modulus * section(di)) for li, di in sections), 0.0),
        free_thread=free_thread_length / (youngs_modulus * a_d3),
        engaged_thread=ENGAGED_THREAD_FACTOR * diameter / (youngs_modulus * a_d3),
        nut=NUT_LENGTH_FACTOR[joint] * diameter / (e_nut * a_n),
    )


def _second_moment(diameter: Any) -> Any:
    return math.pi / 64.0 * diameter**4


def bolt_bending_compliance(
    diameter: float,
    minor_diameter: float,
    youngs_modulus: float,
    sections: Sequence[tuple[float, float]],
    free_thread_length: float,
    head: str = "hex",
    joint: str = "through",
    nut_youngs_modulus: float | None = None,
) -> float:
    r"""Bending compliance β_S of the bolt from the same sections as its axial compliance.

    .. math::
        \beta_S = \frac{l_{SK}}{E_S I_N} + \sum_i \frac{l_i}{E_S I_i}
            + \frac{l_{Gew}}{E_S I_{d3}} + \frac{0.5\,d}{E_S I_{d3}}
            + \frac{l_M}{E_M I_N}, \qquad I = \frac{\pi}{64} d^4

    Parameters
    ----------
    diameter : float
        Nominal diameter d, [m]
    minor_diameter : float
        Minor diameter d3, [m]
    youngs_modulus : float
        E_S of the bolt, [Pa]
    sections : sequence of (float, float)
        (length l_i [m], diameter d_i [m]) of the plain and reduced shank sections
    free_thread_length : float
        l_Gew, [m]
    head : str
        ``"hex"`` or ``"socket"``
    joint : str
        ``"through"`` or ``"tapped"``
    nut_youngs_modulus : float, optional
        E_M of the nut or the tapped part; E_S when None, [Pa]

    Returns
    -------
    float
        β_S, [1/(N*m)]

    Notes
    -----
    VDI 2230-1:2015 §5.1.1.2 (bending resilience of the bolt, the sections and
    substitute lengths of R3 with I instead of A), as the open implementation
    h18340637145/vdi2230 sums it. It enters the additional bending stress of
    :func:`eccentric_stress_factor`.

    Examples
    --------
    M12 hexagon bolt, 40 mm grip all free thread, nut: 6 mm/I_N + 40 mm/I_d3
    + 6 mm/I_d3 + 4.8 mm/I_N over E_S

    >>> round(bolt_bending_compliance(0.012, 0.009853, 2.1e11, [], 0.040) * 1e3, 4)
    0.524
    """
    return _bolt_sections(
        _second_moment,
        diameter,
        minor_diameter,
        youngs_modulus,
        sections,
        free_thread_length,
        head,
        joint,
        nut_youngs_modulus,
    ).total


def cone_tangent(
    grip: float,
    bearing_diameter: float,
    outer_diameter: float,
    joint: str = "through",
) -> float:
    r"""Tangent of the deformation-cone angle φ (VDI 2230-1 R3).

    .. math::
        \text{through (DSV):}\ \tan\varphi_D = 0.362 + 0.032 \ln\frac{\beta_L}{2} + 0.153 \ln y
        \qquad
        \text{tapped (ESV):}\ \tan\varphi_E = 0.348 + 0.013 \ln\beta_L + 0.193 \ln y

    with β_L = l_K/d_W and y = D_A'/d_W.

    Parameters
    ----------
    grip : float
        Clamp length l_K, [m]
    bearing_diameter : float
        d_W, the outer diameter of the head's bearing face, [m]
    outer_diameter : float
        D_A', the outer diameter of the clamped parts at the interface, [m]
    joint : str
        ``"through"`` or ``"tapped"``

    Returns
    -------
    float
        tan φ, [-] (not below 0.1: the fit is not meant for plates far
        thinner than d_W)

    Notes
    -----
    VDI 2230-1:2015 eq. (5.1/21)–(5.1/22); the through-bolted form is the one
    ECSS-E-HB-32-23A eq. 7.6.8 and misams/BAT use. For the tapped joint BAT
    uses another fit (1.295 − 0.246 ln β_L + 0.94 ln y) from ECSS; we keep
    VDI's.

    Examples
    --------
    M12 through 2 × 20 mm, d_W = 16.63 mm, D_A = 40 mm:

    >>> round(cone_tangent(0.040, 0.01663, 0.040), 4)
    0.5022
    """
    beta_l = grip / bearing_diameter
    y = outer_diameter / bearing_diameter
    arrays = not (type(beta_l) is float and type(y) is float) and (
        isinstance(beta_l, np.ndarray) or isinstance(y, np.ndarray)
    )
    log = np.log if arrays else math.log  # the D_A iteration calls this ~6 times a run
    if joint == "through":
        tan = 0.362 + 0.032 * log(beta_l / 2.0) + _CONE_Y_SLOPE[joint] * log(y)
    else:
        tan = 0.348 + 0.013 * log(beta_l) + _CONE_Y_SLOPE[joint] * log(y)
    if arrays:
        clipped: Any = np.maximum(tan, MIN_CONE_TANGENT)
        return clipped
    return MIN_CONE_TANGENT if tan < MIN_CONE_TANGENT else tan  # max(tan, 0.1)


#: ∂ tan φ / ∂ ln y of the fits above (VDI 2230-1 eq. 5.1/21–22).
_CONE_Y_SLOPE: dict[str, float] = {"through": 0.153, "tapped": 0.193}


def cone_limit_diameter(
    grip: float, bearing_diameter: float, tangent: float, joint: str = "through"
) -> float:
    r"""Outer diameter D_A,Gr at which the deformation cone is fully developed.

    .. math::
        D_{A,Gr} = d_W + w\,l_K \tan\varphi, \qquad w = 1\ \text{(through)},\ 2\ \text{(tapped)}

    Parameters
    ----------
    grip : float
        l_K, [m]
    bearing_diameter : float
        d_W, [m]
    tangent : float
        tan φ, [-]
    joint : str
        ``"through"`` or ``"tapped"``

    Returns
    -------
    float
        D_A,Gr, [m]

    Notes
    -----
    VDI 2230-1:2015 eq. (5.1/23); ECSS-E-HB-32-23A eq. 7.6.9.

    Examples
    --------
    >>> round(cone_limit_diameter(0.040, 0.01663, 0.5022) * 1e3, 2)
    36.72
    """
    w = 1.0 if joint == "through" else 2.0
    return bearing_diameter + w * grip * tangent


def unlimited_outer_diameter(grip: float, bearing_diameter: float, joint: str = "through") -> float:
    r"""D_A for plates 'wide enough': the diameter at which the cone just develops fully.

    .. math::
        D_A = D_{A,Gr}(\tan\varphi(y)),\qquad y = D_A/d_W

    solved by fixed-point iteration.

    Parameters
    ----------
    grip : float
        l_K, [m]
    bearing_diameter : float
        d_W, [m]
    joint : str
        ``"through"`` or ``"tapped"``

    Returns
    -------
    float
        D_A, [m]

    Notes
    -----
    Our convention, not VDI's: the cone-angle fit grows without bound with
    y = D_A/d_W, so an 'unlimited' plate needs a D_A. We take the smallest
    plate in which the cone develops fully (D_A = D_A,Gr); a wider plate
    gives a stiffer joint by VDI's fit (M12 through 2 × 20 mm:
    δ_P is 13 % lower at D_A = 2 D_A,Gr). Give the outer diameter when known.

    Examples
    --------
    >>> round(unlimited_outer_diameter(0.040, 0.01663) * 1e3, 2)
    36.09

    Floats and arrays run the same steps (a few Newton steps, then the fixed-point
    iteration, each point stopping where it converges):

    >>> d = unlimited_outer_diameter(np.array([0.040, 0.010]), 0.01663)
    >>> d.tolist() == [unlimited_outer_diameter(0.040, 0.01663),
    ...                unlimited_outer_diameter(0.010, 0.01663)]
    True
    """
    grips: Any = grip
    bearing: Any = bearing_diameter
    if _arrays(grip, bearing_diameter):
        grips, bearing = np.broadcast_arrays(
            np.asarray(grip, dtype=float), np.asarray(bearing_diameter, dtype=float)
        )
    w = 1.0 if joint == "through" else 2.0
    lever = w * grips * _CONE_Y_SLOPE[joint]  # the map's slope is lever/D where tan φ > 0.1
    outer: Any = bearing * 2.0
    # a few safeguarded Newton steps on D − D_A,Gr(D) (where the map's slope w l_K ∂tanφ/∂D
    # is below ½; a plain step elsewhere), kept at D ≥ d_W where the cone lives: ~5 passes
    # instead of ~16 of the plain iteration
    for _ in range(8):
        tan = cone_tangent(grips, bearing, outer, joint)
        new = cone_limit_diameter(grips, bearing, tan, joint)
        slope = _where(tan > MIN_CONE_TANGENT, lever / outer, 0.0)
        step = (new - outer) / _where(slope < 0.5, 1.0 - slope, 1.0)
        outer = _max(outer + step, bearing)
        if not _largest(abs(step)) > 1e-13 * _largest(outer):
            break
    # then the plain fixed-point iteration, each point stopping where it converges
    settled: Any = False
    for _ in range(200):
        tan = cone_tangent(grips, bearing, outer, joint)
        new = cone_limit_diameter(grips, bearing, tan, joint)
        done = _where(abs(new - outer) > 1e-12 * new, False, True)  # NaN: nothing to refine
        outer = _where(settled, outer, new)  # a settled point keeps its value
        settled = settled | done
        if _every(settled):
            break
    return outer


def _one_sided(
    start: float,
    end: float,
    bearing_diameter: float,
    hole_diameter: float,
    tangent: float,
    outer_diameter: float,
) -> float:
    """∫ dz / A(z) over [start, end] of a cone from d_W at z = 0, capped at D_A (1/m).

    Floats or arrays (the same lines); an empty interval (end ≤ start) gives 0.
    """
    d_h = hole_diameter
    empty = end <= start
    if _every(empty):  # e.g. the far half of a through-bolted joint for a near plate
        zero: Any = np.zeros(np.shape(empty)) if isinstance(empty, np.ndarray) else 0.0
        return zero
    z_cap = (outer_diameter - bearing_diameter) / (2.0 * tangent)
    a, b = start, _min(end, z_cap)
    # both pieces everywhere (z ≥ 0 keeps the logarithm's argument positive), each kept
    # where its interval is not empty
    cone = _where(
        b > a,
        (
            _cone_log(b, bearing_diameter, d_h, tangent)
            - _cone_log(a, bearing_diameter, d_h, tangent)
        )
        / (math.pi * d_h * tangent),
        0.0,
    )
    a = _max(start, z_cap)
    sleeve = (end - a) / (0.25 * math.pi * (outer_diameter**2 - hole_diameter**2))
    both: Any = (0.0 + cone) + _where(end > a, sleeve, 0.0)
    return both


def _cone_log(z: Any, bearing_diameter: Any, hole_diameter: Any, tangent: Any) -> Any:
    """ln((D − d_h)/(D + d_h)) at the cone's diameter D = d_W + 2 z tan φ: the antiderivative
    of 1/A(z) up to the factor π d_h tan φ."""
    diameter = bearing_diameter + 2.0 * z * tangent
    return _log((diameter - hole_diameter) / (diameter + hole_diameter))


class ClampedCompliance(NamedTuple):
    """Compliance of the clamped parts (VDI 2230-1 R3)."""

    per_plate: tuple[float, ...]
    tangent: float
    limit_diameter: float
    outer_diameter: float

    @property
    def total(self) -> float:
        """δ_P, [m/N]."""
        return sum(self.per_plate)

    @property
    def sleeve_only(self) -> bool:
        """True where D_A ≤ d_W: no cone at all, a plain sleeve."""
        return self.outer_diameter <= self.limit_diameter and self.tangent <= 0.0


def clamped_compliance(
    thicknesses: Sequence[float],
    youngs_moduli: Sequence[float],
    bearing_diameter: float,
    hole_diameter: float,
    outer_diameter: float | None = None,
    joint: str = "through",
    tangent: float | None = None,
    plate_outer_diameters: Sequence[Any] | None = None,
) -> ClampedCompliance:
    r"""Compliance of the clamped plates by VDI 2230's deformation cone and sleeve.

    .. math::
        \delta_P = \sum_i \frac{1}{E_i}
            \int_{z_i}^{z_{i+1}}\frac{dz}{\tfrac{\pi}{4}(D(z)^2 - d_h^2)},
        \qquad D(z) = \min(d_W + 2 s(z)\tan\varphi,\ D_A)

    where s(z) is the distance from the nearer bearing face (through-bolted:
    two cones meeting at mid-grip) or from the head (tapped: one cone). With
    one material it is VDI's closed form, e.g. for D_A ≥ D_A,Gr

    .. math::
        \delta_P = \frac{2\ln\left[\frac{(d_W + d_h)(d_W + w l_K\tan\varphi - d_h)}
            {(d_W - d_h)(d_W + w l_K\tan\varphi + d_h)}\right]}{w\,E_P\,\pi\,d_h\tan\varphi}

    and for d_W < D_A < D_A,Gr the cone part up to D_A plus a sleeve of length
    l_K − (D_A − d_W)/(w tan φ); D_A ≤ d_W leaves the sleeve
    4 l_K / (E_P π (D_A² − d_h²)) (VDI 2230-1 R3, d_h < D_A ≤ d_W).

    Parameters
    ----------
    thicknesses : sequence of float
        Plate thicknesses h_i from the head side, [m]
    youngs_moduli : sequence of float
        E_i of each plate, [Pa]
    bearing_diameter : float
        d_W, [m]
    hole_diameter : float
        d_h, the clearance hole, [m]
    outer_diameter : float, optional
        D_A, the plates' outer diameter (equivalent); None: wide plates,
        see :func:`unlimited_outer_diameter`, [m]
    joint : str
        ``"through"`` or ``"tapped"``
    tangent : float, optional
        tan φ to use instead of VDI's fit (for comparisons), [-]
    plate_outer_diameters : sequence of float or None, optional
        D_A,i of each plate, None for an entry (or the whole): the first plate's D_A; each
        plate's part of the cone is capped at its own D_A,i (its sleeve below d_W), [m]

    Returns
    -------
    ClampedCompliance
        Per-plate compliances [m/N], tan φ, D_A,Gr and D_A used [m] (the first plate's)

    Notes
    -----
    VDI 2230-1:2015 step R3, eq. (5.1/24)–(5.1/26) for one material;
    several materials by integrating each plate's part of the same cone and
    sleeve with its own E (VDI 2230-1:2015 §5.1.2.2; ECSS-E-HB-32-23A §7.6.3
    and misams/BAT instead spread one substitute area over the plates, which
    differs where the plates differ). Each half-cone's angle uses the whole grip and its
    own side's D_A (VDI's y = D_A'/d_W per side: the head's from the first plate's D_A, a
    through-bolted joint's nut half from the last plate's), so a mirrored joint gives the
    same δ_P; tan φ and D_A,Gr returned are the head side's. A plate of its own D_A,i caps
    its part of its half-cone there (our reading of §5.1.2.2 plate by plate: VDI's text
    was not available). The nut's bearing face is taken as large as the head's.

    Examples
    --------
    M12 through 2 × 20 mm steel, d_W = 16.63 mm, d_h = 13.5 mm, D_A = 40 mm:

    >>> c = clamped_compliance([0.02, 0.02], [2.1e11, 2.1e11], 0.01663, 0.0135, 0.040)
    >>> round(c.total * 1e9, 4)
    0.6676

    The second plate of 15 mm outer diameter, below d_W: a sleeve of h_2 = 20 mm,
    4 h_2/(E π (D_A,2² − d_h²)) = 2.8365e-9 m/N

    >>> c2 = clamped_compliance([0.02, 0.02], [2.1e11, 2.1e11], 0.01663, 0.0135, 0.040,
    ...                         plate_outer_diameters=[None, 0.015])
    >>> round(c2.per_plate[1] * 1e9, 4)
    2.8365

    Mirrored (15 mm under the head, 40 mm under the nut) it gives the same δ_P:

    >>> c3 = clamped_compliance([0.02, 0.02], [2.1e11, 2.1e11], 0.01663, 0.0135, 0.015,
    ...                         plate_outer_diameters=[None, 0.040])
    >>> abs(c3.total - c2.total) < 1e-12 * c2.total
    True
    """
    if len(thicknesses) != len(youngs_moduli) or not thicknesses:
        raise InputOutOfRange("give one Young's modulus per plate", field="plate1_thickness")
    grip = sum(thicknesses)
    grip = grip if isinstance(grip, np.ndarray) else float(grip)
    if outer_diameter is None:
        outer = unlimited_outer_diameter(grip, bearing_diameter, joint)
    else:
        outer = outer_diameter  # below d_W: VDI's sleeve, no cone (the cap lies behind z = 0)
    tan = cone_tangent(grip, bearing_diameter, outer, joint) if tangent is None else tangent
    limit = cone_limit_diameter(grip, bearing_diameter, tan, joint)
    own = plate_outer_diameters or [None] * len(thicknesses)
    caps = [outer if plate_outer is None else plate_outer for plate_outer in own]
    # the nut's half-cone takes its angle from the nut side's D_A (the last plate of some
    # thickness), as the head's from the head side's: a mirrored joint gives the same δ_P
    tan_nut = tan
    if (
        joint == "through"
        and tangent is None
        and plate_outer_diameters
        and any(o is not None for o in own)
    ):
        nut_outer = outer
        for h, cap in zip(thicknesses, caps, strict=True):
            nut_outer = _where(h > 0.0, cap, nut_outer)
        tan_nut = cone_tangent(grip, bearing_diameter, nut_outer, joint)
    per_plate = []
    z = 0.0
    half = 0.5 * grip
    for h, e, cap in zip(thicknesses, youngs_moduli, caps, strict=True):
        a, b = z, z + h
        if joint == "through":
            integral = _one_sided(
                _min(a, half), _min(b, half), bearing_diameter, hole_diameter, tan, cap
            ) + _one_sided(
                grip - _max(b, half),
                grip - _max(a, half),
                bearing_diameter,
                hole_diameter,
                tan_nut,
                cap,
            )
        else:
            integral = _one_sided(a, b, bearing_diameter, hole_diameter, tan, cap)
        per_plate.append(integral / e)
        z = b
    return ClampedCompliance(tuple(per_plate), tan, limit, outer)


def load_factor(
    bolt: float,
    clamped: float,
    load_introduction: float = 1.0,
    clamped_loaded: float | None = None,
) -> float:
    r"""Load factor Φ_n (Φ*_en): the share of the working load that adds to the bolt force.

    .. math::
        \Phi_n = n\,\frac{\delta_P}{\delta_S + \delta_P},
        \qquad
        \Phi^*_{en} = n\,\frac{\delta^{**}_P}{\delta_S + \delta^*_P}

    Parameters
    ----------
    bolt : float
        δ_S, [m/N]
    clamped : float
        δ_P, or δ*_P = δ_P + s_sym² β_P of an eccentrically clamped joint
        (:func:`eccentric_compliance`), [m/N]
    load_introduction : float
        n, the load-introduction factor (1: under the head and nut; VDI 2230-1
        Table 5.2/1 gives 0.1…0.7 for loads introduced inside the plates), [-]
    clamped_loaded : float, optional
        δ**_P = δ_P + a s_sym β_P of an eccentrically loaded joint; ``clamped``
        when None (the load acts where the clamping does), [m/N]

    Returns
    -------
    float
        Φ_n or Φ*_en, [-]

    Notes
    -----
    VDI 2230-1:2015 step R3, eq. (5.2/1)–(5.2/2) (concentric clamping and
    loading; ECSS-E-HB-32-23A eq. 7.3.2) and §5.3.2 for eccentric clamping and
    loading (Φ*_en with δ*_P in the denominator and δ**_P in the numerator, the
    form the open implementation h18340637145/vdi2230 runs too). With
    s_sym = a = 0 both compliances are δ_P and Φ*_en = Φ_n to the bit.

    Examples
    --------
    >>> round(load_factor(3.0e-9, 0.6e-9, 0.5), 4)
    0.0833

    Bolt 5 mm off the body's axis, load 20 mm out, β_P = 2e-6 /(N m):
    δ*_P = 0.6e-9 + 0.005² × 2e-6, δ**_P = 0.6e-9 + 0.02 × 0.005 × 2e-6

    >>> round(load_factor(3.0e-9, 0.65e-9, 1.0, 0.8e-9), 4)
    0.2192
    """
    loaded = clamped if clamped_loaded is None else clamped_loaded
    return load_introduction * loaded / (bolt + clamped)


def embedding(roughness: str, load: str, bearing_faces: int, interfaces: int) -> float:
    r"""Plastic settlement f_Z of the joint by embedding (VDI table).

    .. math::
        f_Z = f_{Z,thread} + n_K f_{Z,bearing} + n_T f_{Z,interface}

    Parameters
    ----------
    roughness : str
        ``"Rz<10"``, ``"Rz10-40"`` or ``"Rz40-160"`` (mean roughness depth)
    load : str
        ``"axial"`` or ``"transverse"``
    bearing_faces : int
        n_K: 2 for head and nut, 1 for a tapped joint, [-]
    interfaces : int
        n_T: inner interfaces between clamped parts (and the tapped part), [-]

    Returns
    -------
    float
        f_Z, [m]

    Notes
    -----
    VDI 2230-1:2015 step R4, Table 5.4/1, as reproduced in ECSS-E-HB-32-23A
    Table 6-3 (misams/BAT carries the larger of the axial and transverse
    columns, which are the transverse values here).

    Examples
    --------
    Two plates through-bolted, Rz < 10 µm, axial load: 3 + 2 × 2.5 + 1 × 1.5

    >>> round(embedding("Rz<10", "axial", 2, 1) * 1e6, 2)
    9.5
    """
    try:
        thread, bearing, interface = EMBEDDING_UM[roughness][load]
    except KeyError:
        raise InputOutOfRange(
            f"surface_roughness = {roughness!r}, load = {load!r} is not in the VDI table: "
            f"roughness one of {', '.join(ROUGHNESS_CLASSES)}, load 'axial' or 'transverse'",
            field="surface_roughness",
        ) from None
    return (thread + bearing_faces * bearing + interfaces * interface) * 1e-6


def embedding_loss(settlement: float, bolt: float, clamped: float) -> float:
    r"""Preload lost by embedding.

    .. math::
        F_Z = \frac{f_Z}{\delta_S + \delta_P}

    Parameters
    ----------
    settlement : float
        f_Z, [m]
    bolt : float
        δ_S, [m/N]
    clamped : float
        δ_P, [m/N]

    Returns
    -------
    float
        F_Z, [N]

    Notes
    -----
    VDI 2230-1:2015 step R4, eq. (5.4/3); ECSS-E-HB-32-23A eq. 6.3.19.

    Examples
    --------
    >>> round(embedding_loss(9.5e-6, 3.0e-9, 0.6e-9))
    2639
    """
    return settlement / (bolt + clamped)


def thermal_preload_loss(
    preload: float,
    grip: float,
    bolt_expansion: float,
    bolt_temperature_change: float,
    clamped_expansion_length: float,
    plate_temperature_change: float,
    bolt: float,
    clamped: float,
    bolt_modulus_ratio: float = 1.0,
    clamped_modulus_ratio: float = 1.0,
) -> float:
    r"""Preload lost (positive) or gained (negative) when bolt and plates change temperature.

    .. math::
        \Delta F_{th} = F_V\left(1 - \frac{\delta_S + \delta_P}
            {\delta_S E_{S,RT}/E_{S,T} + \delta_P E_{P,RT}/E_{P,T}}\right)
            + \frac{l_K \alpha_S \Delta T_S - \sum_i h_i \alpha_i \Delta T_P}
            {\delta_S E_{S,RT}/E_{S,T} + \delta_P E_{P,RT}/E_{P,T}}

    Parameters
    ----------
    preload : float
        F_V, the preload at room temperature, [N]
    grip : float
        l_K, [m]
    bolt_expansion : float
        α_S, [1/K]
    bolt_temperature_change : float
        ΔT_S, [K]
    clamped_expansion_length : float
        Σ h_i α_i, the plates' thermal length coefficient, [m/K]
    plate_temperature_change : float
        ΔT_P, [K]
    bolt : float
        δ_S at room temperature, [m/N]
    clamped : float
        δ_P at room temperature, [m/N]
    bolt_modulus_ratio : float
        E_S,T / E_S,RT, [-]
    clamped_modulus_ratio : float
        E_P,T / E_P,RT, [-]

    Returns
    -------
    float
        ΔF_th, positive for a loss, [N]

    Notes
    -----
    VDI 2230-1:2015 step R4, eq. (5.4/… "ΔF'_Vth"), as misams/BAT implements
    it ("VDI method") after ECSS-E-HB-32-23A §6.3.5. A bolt that expands
    more than the plates (α_S ΔT > α_P ΔT) loses preload.

    Examples
    --------
    Steel bolt through aluminium, +50 K, 40 mm grip: the aluminium expands more,
    so the preload rises (negative loss)

    >>> round(thermal_preload_loss(30e3, 0.04, 11.5e-6, 50, 0.04 * 23e-6, 50, 3e-9, 1.7e-9))
    -4894
    """
    denominator = bolt / bolt_modulus_ratio + clamped / clamped_modulus_ratio
    mismatch = grip * bolt_expansion * bolt_temperature_change - (
        clamped_expansion_length * plate_temperature_change
    )
    return preload * (1.0 - (bolt + clamped) / denominator) + mismatch / denominator


def transverse_clamp_force(
    transverse_load: float,
    interfaces: int,
    slip_friction: float,
    torsional_moment: float = 0.0,
    torque_interfaces: int = 1,
    friction_radius: float = 1.0,
) -> float:
    r"""Clamp force that carries a transverse load and a torsional moment by friction.

    .. math::
        F_{KQ} = \frac{F_{Q,max}}{q_F\,\mu_{T,min}} + \frac{M_{Y,max}}{q_M\,r_a\,\mu_{T,min}}

    Parameters
    ----------
    transverse_load : float
        F_Q,max, [N]
    interfaces : int
        q_F, the number of interfaces that transmit it, [-]
    slip_friction : float
        μ_T,min, the interface friction coefficient, [-]
    torsional_moment : float
        M_Y,max, a torsional moment about the bolt axis the interfaces carry, [N*m]
    torque_interfaces : int
        q_M, the number of interfaces that carry M_Y, [-]
    friction_radius : float
        r_a, the interface's friction radius for M_Y, [m]

    Returns
    -------
    float
        F_KQ, [N]

    Notes
    -----
    VDI 2230-1:2015 step R2, eq. (R2/1); ECSS-E-HB-32-23A eq. 8.2.2 for the
    transverse part. With M_Y = 0 it is F_Q/(q_F μ_T) to the bit.

    Examples
    --------
    >>> transverse_clamp_force(3000.0, 1, 0.15)
    20000.0

    Plus 30 N·m at r_a = 20 mm on one interface: 30/(0.02 × 0.15) = 10 kN more

    >>> round(transverse_clamp_force(3000.0, 1, 0.15, 30.0, 1, 0.020), 6)
    30000.0
    """
    friction = transverse_load / (interfaces * slip_friction)
    return friction + torsional_moment / (torque_interfaces * friction_radius * slip_friction)


def minimum_assembly_preload(
    required_clamp_force: float,
    working_load_max: float,
    load_factor_n: float,
    embedding_force: float,
    thermal_loss: float,
) -> float:
    r"""Smallest assembly preload that still leaves the required clamp force in service.

    .. math::
        F_{M,min} = F_{K,erf} + (1 - \Phi_n) F_{A,max} + F_Z + \max(\Delta F_{th}, 0)

    Parameters
    ----------
    required_clamp_force : float
        F_K,erf, [N]
    working_load_max : float
        F_A,max, [N]
    load_factor_n : float
        Φ_n, [-]
    embedding_force : float
        F_Z, [N]
    thermal_loss : float
        ΔF_th (positive: a loss; a gain is not credited), [N]

    Returns
    -------
    float
        F_M,min, [N]

    Notes
    -----
    VDI 2230-1:2015 step R5, eq. (R5/1). Summed as (1 − Φ_n) F_A,max + (F_K,erf + F_Z +
    max(ΔF_th, 0)): where F_A alone varies (a sweep of the working load) the terms that do
    not vary are one number, and the points take one product and one sum, in place.

    Examples
    --------
    >>> minimum_assembly_preload(10e3, 8e3, 0.1, 2.6e3, 0.0)
    19800.0
    """
    fixed = _add_to(preload_losses(embedding_force, thermal_loss), required_clamp_force)
    reduction = clamp_load_reduction(load_factor_n, working_load_max)
    if isinstance(reduction, np.ndarray):
        return _add_to(reduction, fixed)
    return _add_to(fixed, reduction)


def tightening_torque(
    preload: float, thread_per_newton: float, bearing_per_newton: float, prevailing_torque: float
) -> float:
    r"""Tightening torque for an assembly preload: thread, bearing face and prevailing torque.

    .. math::
        M_A = F_M k_G + F_M k_K + M_{\ddot u},\qquad
        k_G = 0.16 P + 0.58\,d_2\,\mu_G,\quad k_K = \mu_K \frac{D_{Km}}{2}

    with k_G, k_K from :func:`engine.physics.preload.tightening_torque_per_preload`
    (``"vdi2230"``: the coefficients the preload models use too).

    Parameters
    ----------
    preload : float
        F_M, [N]
    thread_per_newton : float
        k_G, thread torque per newton of preload, [m]
    bearing_per_newton : float
        k_K, bearing-face torque per newton of preload, [m]
    prevailing_torque : float
        M_ü, the prevailing (locking) torque, [N*m]

    Returns
    -------
    float
        M_A, [N*m]

    Notes
    -----
    VDI 2230-1:2015 step R13, eq. (R13/1) plus the prevailing torque; the
    joint states it at F_M,zul and μ_G,min, μ_K,min (the torque that reaches
    the permissible preload with the least friction).

    Examples
    --------
    M12 8.8 at F_M,zul = 43.11 kN, μ = 0.12: k_G = 0.16 × 1.75 + 0.58 × 10.863
    × 0.12 = 1.0361 mm, k_K = 0.12 × (16.63 + 13.5)/4 = 0.9039 mm

    >>> round(tightening_torque(43110.0, 1.0361e-3, 0.9039e-3, 0.0), 2)
    83.63
    """
    return preload * thread_per_newton + preload * bearing_per_newton + prevailing_torque


def smallest_section(
    stress_diameter: float, sections: Sequence[tuple[float, float]]
) -> tuple[float, str]:
    r"""Diameter d_0 of the bolt's smallest cross-section, and which section it is.

    .. math::
        d_0 = \min(d_S,\ d_{T,i})

    Parameters
    ----------
    stress_diameter : float
        d_S = (d2 + d3)/2, the thread's stress diameter, [m]
    sections : sequence of (float, float)
        (length [m], diameter [m]) of the shank sections; zero-length ones are ignored

    Returns
    -------
    tuple of (float, str)
        d_0 [m] and ``"thread"`` or ``"shank"``

    Notes
    -----
    VDI 2230-1:2015 step R7: A_0 is the smallest cross-section (A_S for a
    full-shank bolt, A_T = π d_T²/4 for a waisted one), and d_0 the diameter
    of the torsional section modulus W_p = π d_0³/16; [004, eq. 3–4] says
    the same of a stepped shank.

    Examples
    --------
    >>> smallest_section(0.010358, [(0.05, 0.0075)])
    (0.0075, 'shank')

    On arrays, ``which`` is an array of the same words:

    >>> d0, which = smallest_section(0.010358, [(np.array([0.05, 0.0]), 0.0075)])
    >>> d0.tolist(), which.tolist()
    ([0.0075, 0.010358], ['shank', 'thread'])
    """
    d0: Any = stress_diameter
    shank: Any = False
    for length, diameter in sections:
        smaller = (length > 0.0) & (diameter < d0)
        d0 = _where(smaller, diameter, d0)
        shank = shank | smaller
    if _arrays(d0, shank):
        words: Any = np.where(np.broadcast_to(shank, np.shape(d0)), "shank", "thread")
        return d0, words
    return d0, "shank" if shank else "thread"


def preload_bounds_from_torque(
    torque: float,
    torque_tolerance: float,
    prevailing_torque: float,
    per_newton_low_friction: float,
    per_newton_high_friction: float,
    prevailing_torque_min: float | None = None,
) -> tuple[float, float]:
    r"""Assembly preload range from a torque specification and the friction box.

    .. math::
        F_{M,min} = \frac{M_A (1 - t) - M_{\ddot u,max}}{k(\mu_{G,max}, \mu_{K,max})},
        \qquad
        F_{M,max} = \frac{M_A (1 + t) - M_{\ddot u,min}}{k(\mu_{G,min}, \mu_{K,min})}

    where k = M/F is the torque per newton of preload (thread plus bearing).

    Parameters
    ----------
    torque : float
        M_A, the specified tightening torque including the prevailing torque, [N*m]
    torque_tolerance : float
        t, the tool's relative torque tolerance (±), [-]
    prevailing_torque : float
        M_ü,max, the largest prevailing (locking) torque, which produces no preload, [N*m]
    per_newton_low_friction : float
        k at the low-friction corner (μ_G,min, μ_K,min), [m]
    per_newton_high_friction : float
        k at the high-friction corner (μ_G,max, μ_K,max), [m]
    prevailing_torque_min : float, optional
        M_ü,min; M_ü,max when None, [N*m]

    Returns
    -------
    tuple of float
        (F_M,min, F_M,max), [N]; F_M,min is 0 when the prevailing torque eats
        the whole lower torque

    Notes
    -----
    VDI 2230-1:2015 step R13 solved for the preload (M_A = F_M k + M_ü); the
    torque is linear in the preload and rises with each friction coefficient,
    so the extremes lie at the corners of the friction box. ECSS-E-HB-32-23A
    eq. 6.3.14–6.3.15 (and misams/BAT) do the same with a min/max prevailing
    torque; with one value the same M_ü is taken at both ends.

    Examples
    --------
    >>> lo, hi = preload_bounds_from_torque(80.0, 0.05, 0.4, 1.30e-3, 2.40e-3)
    >>> round(lo), round(hi)
    (31500, 64308)
    """
    least = prevailing_torque if prevailing_torque_min is None else prevailing_torque_min
    low = _max(torque * (1.0 - torque_tolerance) - prevailing_torque, 0.0)
    high = _max(torque * (1.0 + torque_tolerance) - least, 0.0)
    return low / per_newton_high_friction, high / per_newton_low_friction


class ServiceStress(NamedTuple):
    """Bolt stresses in service (VDI 2230-1 R8)."""

    axial: float
    torsional: float
    equivalent: float


def service_stress(
    bolt_force: float,
    assembly_preload: float,
    pitch: float,
    pitch_diameter: float,
    smallest_diameter: float,
    thread_friction: float,
    torsion_reduction: float = TORSION_REDUCTION_IN_SERVICE,
) -> ServiceStress:
    r"""Largest bolt stress in service: axial load plus the torsion left from tightening.

    .. math::
        \sigma_{z} = \frac{F_{S,max}}{A_0},\quad
        \tau = \frac{F_M \tfrac{d_2}{2}\left(\tfrac{P}{\pi d_2} + 1.155\mu_G\right)}
            {\pi d_0^3/16},\quad
        \sigma_{red,B} = \sqrt{\sigma_z^2 + 3 (k_\tau \tau)^2}

    Parameters
    ----------
    bolt_force : float
        F_S,max = F_M,max + Φ_n F_A,max, [N]
    assembly_preload : float
        F_M that produced the torsion, [N]
    pitch : float
        P, [m]
    pitch_diameter : float
        d2, [m]
    smallest_diameter : float
        d_0, [m]
    thread_friction : float
        μ_G,min, [-]
    torsion_reduction : float
        k_τ, the share of the torsion kept in service (VDI: 0.5), [-]

    Returns
    -------
    ServiceStress
        σ_z, τ and σ_red,B, [Pa]

    Notes
    -----
    VDI 2230-1:2015 step R8, eq. (R8/1)–(R8/4).

    Examples
    --------
    >>> s = service_stress(45e3, 43.1e3, 0.00175, 0.010863, 0.010358, 0.12)
    >>> round(s.equivalent / 1e6, 1)
    562.4
    """
    a0 = _area(smallest_diameter)
    thread_torque = (
        assembly_preload
        * 0.5
        * pitch_diameter
        * (pitch / (math.pi * pitch_diameter) + 1.155 * thread_friction)
    )
    tau = thread_torque / (math.pi * smallest_diameter**3 / 16.0)
    sigma = bolt_force / a0
    return ServiceStress(sigma, tau, _sqrt(sigma**2 + 3.0 * (torsion_reduction * tau) ** 2))


def endurance_limit(
    diameter: float,
    rolling: str = "before_heat_treatment",
    mean_bolt_force: float = 0.0,
    proof_force: float = 1.0,
) -> float:
    r"""Endurance limit (stress amplitude) of the thread of a high-strength bolt.

    .. math::
        \sigma_{ASV} = 0.85\left(\frac{150}{d} + 45\right)\ \text{MPa (d in mm)},
        \qquad
        \sigma_{ASG} = \left(2 - \frac{F_{Sm}}{F_{0.2,min}}\right)\sigma_{ASV}

    Parameters
    ----------
    diameter : float
        d, [m]
    rolling : str
        ``"before_heat_treatment"`` (SV) or ``"after_heat_treatment"`` (SG)
    mean_bolt_force : float
        F_Sm, the mean bolt force (rolled after heat treatment only), [N]
    proof_force : float
        F_0.2,min = A_S R_p0.2,min, [N]

    Returns
    -------
    float
        σ_AS, [Pa]

    Notes
    -----
    VDI 2230-1:2015 step R9 (§5.5.3), for ISO 898-1 bolts d ≤ 40 mm at
    2·10⁶ cycles; the ratio F_Sm/F_0.2,min is clipped to 0…1 (VDI states
    its validity for about 0.3…1). Not checked against a printed VDI copy:
    the same relation is quoted identically by several open VDI 2230
    implementations we read (e.g. for M12, σ_ASV ≈ 48.9 MPa).

    Examples
    --------
    >>> round(endurance_limit(0.012) / 1e6, 2)
    48.88
    """
    base = 0.85 * (150.0 / (diameter * 1e3) + 45.0) * 1e6
    if rolling == "before_heat_treatment":
        return base
    ratio = _min(_max(mean_bolt_force / proof_force, 0.0), 1.0)
    return (2.0 - ratio) * base


# --------------------------------------------------------------------------- R1–R12 in closed form
#
# The steps below were written inline in the model's declaration (twice, once for one design
# and once for arrays); each is one relation here, floats or arrays.


def required_clamp_force(
    transverse_clamp_force: float, sealing_clamp_force: float, opening_clamp_force: float = 0.0
) -> float:
    r"""Clamp force the joint needs in service.

    .. math::
        F_{K,erf} = \max(F_{KQ},\ F_{KP} + F_{KA})

    All arguments may be floats or numpy arrays of one shape.

    Parameters
    ----------
    transverse_clamp_force : float
        F_KQ, the clamp force that carries the transverse load by friction, [N]
    sealing_clamp_force : float
        F_KP, the clamp force needed for sealing or other reasons, [N]
    opening_clamp_force : float
        F_KA, the clamp force that keeps an eccentrically loaded interface from
        opening at its edge (:func:`opening_clamp_force`; 0 concentric), [N]

    Returns
    -------
    float
        F_K,erf, [N]

    Notes
    -----
    VDI 2230-1:2015 step R2, eq. (R2/4): the friction grip or the sealing plus
    the opening requirement, whichever is larger (without the torsion term).

    Examples
    --------
    >>> required_clamp_force(13333.3, 5000.0)
    13333.3
    >>> required_clamp_force(13333.3, 5000.0, 9000.0)
    14000.0
    """
    return _max(transverse_clamp_force, sealing_clamp_force + opening_clamp_force)


def plates_expansion_length(thicknesses: Sequence[float], expansions: Sequence[float]) -> float:
    r"""Thermal length coefficient of the clamped parts.

    .. math::
        \sum_i h_i\,\alpha_i

    Parameters
    ----------
    thicknesses : sequence of float
        h_i of the plates, [m]
    expansions : sequence of float
        α_i of the plates, [1/K]

    Returns
    -------
    float
        Σ h_i α_i, [m/K]

    Notes
    -----
    VDI 2230-1:2015 step R4 (the plates' share of the thermal mismatch in
    :func:`thermal_preload_loss`).

    Examples
    --------
    20 mm of steel and 20 mm of aluminium: 0.02 × 11.5e-6 + 0.02 × 23e-6

    >>> round(plates_expansion_length([0.02, 0.02], [11.5e-6, 23e-6]) * 1e9, 3)
    690.0
    """
    total: Any = 0.0
    for h, a in zip(thicknesses, expansions, strict=True):
        total = total + h * a
    return total


def embedding_locations(joint: str, plates: int) -> tuple[int, int]:
    r"""Bearing faces n_K and inner interfaces n_T that settle by embedding.

    .. math::
        (n_K, n_T) = (2,\ n_P - 1)\ \text{through-bolted},\qquad (1,\ n_P)\ \text{tapped}

    Parameters
    ----------
    joint : str
        ``"through"`` (bolt and nut) or ``"tapped"`` (screwed into the last part)
    plates : int
        n_P, the number of clamped plates, [-]

    Returns
    -------
    tuple of int
        (n_K, n_T), [-]

    Notes
    -----
    VDI 2230-1:2015 step R4, Table 5.4/1 is per location: head and nut are
    two bearing faces; a tapped part has one bearing face and its interface
    with the last plate.

    Examples
    --------
    >>> embedding_locations("through", 2), embedding_locations("tapped", 1)
    ((2, 1), (1, 1))
    """
    return (2, plates - 1) if joint == "through" else (1, plates)


def embedding_for_load(
    roughness: str, transverse_load: float, bearing_faces: int, interfaces: int
) -> float:
    r"""Embedding f_Z with the table's column for the load the joint carries.

    .. math::
        f_Z = f_{Z,transverse}\ \text{if}\ F_Q > 0,\ \text{else}\ f_{Z,axial}

    ``transverse_load`` and the counts may be floats or numpy arrays.

    Parameters
    ----------
    roughness : str
        ``"Rz<10"``, ``"Rz10-40"`` or ``"Rz40-160"``
    transverse_load : float
        F_Q,max, [N]
    bearing_faces : int
        n_K, [-]
    interfaces : int
        n_T, [-]

    Returns
    -------
    float
        f_Z, [m]

    Notes
    -----
    VDI 2230-1:2015 step R4, Table 5.4/1 (see :func:`embedding`).

    Examples
    --------
    Rz 10–40 µm, two plates through-bolted, with a transverse load: 3 + 2 × 4.5 + 2.5

    >>> round(embedding_for_load("Rz10-40", 2e3, 2, 1) * 1e6, 2)
    14.5
    """
    return _where(
        transverse_load > 0.0,
        embedding(roughness, "transverse", bearing_faces, interfaces),
        embedding(roughness, "axial", bearing_faces, interfaces),
    )


def preload_losses(embedding_force: float, thermal_loss: float) -> float:
    r"""Preload lost in service by embedding and temperature (a thermal gain not credited).

    .. math::
        F_Z + \max(\Delta F_{th}, 0)

    Parameters
    ----------
    embedding_force : float
        F_Z, [N]
    thermal_loss : float
        ΔF_th, positive for a loss, [N]

    Returns
    -------
    float
        F_Z + max(ΔF_th, 0), [N]

    Notes
    -----
    VDI 2230-1:2015 steps R4–R5 (the loss terms of eq. R5/1).

    Examples
    --------
    >>> preload_losses(2600.0, 1500.0), preload_losses(2600.0, -900.0)
    (4100.0, 2600.0)
    """
    return embedding_force + _max(thermal_loss, 0.0)


def additional_bolt_load(load_factor_n: float, working_load: float) -> float:
    r"""Share of the working load that adds to the bolt force.

    .. math::
        F_{SA} = \Phi_n F_A

    Parameters
    ----------
    load_factor_n : float
        Φ_n, [-]
    working_load : float
        F_A, [N]

    Returns
    -------
    float
        F_SA, [N]

    Notes
    -----
    VDI 2230-1:2015 step R3, eq. (5.3/1) (used in R8).

    Examples
    --------
    >>> additional_bolt_load(0.1, 8000.0)
    800.0
    """
    return load_factor_n * working_load


def clamp_load_reduction(load_factor_n: float, working_load: float) -> float:
    r"""Share of the working load that unloads the clamped parts.

    .. math::
        F_{PA} = (1 - \Phi_n) F_A

    Parameters
    ----------
    load_factor_n : float
        Φ_n, [-]
    working_load : float
        F_A, [N]

    Returns
    -------
    float
        F_PA, [N]

    Notes
    -----
    VDI 2230-1:2015 step R3, eq. (5.3/2) (used in R5 and R12).

    Examples
    --------
    >>> clamp_load_reduction(0.25, 8000.0)
    6000.0
    """
    return (1.0 - load_factor_n) * working_load


def residual_clamp_force(
    assembly_preload_min: float,
    working_load: float,
    load_factor_n: float,
    embedding_force: float,
    thermal_loss: float,
) -> float:
    r"""Smallest clamp force left at the interface in service.

    .. math::
        F_{KR,min} = F_{M,min} - (1 - \Phi_n) F_{A,max} - F_Z - \max(\Delta F_{th}, 0)

    Parameters
    ----------
    assembly_preload_min : float
        F_M,min, the lowest assembly preload, [N]
    working_load : float
        F_A,max, [N]
    load_factor_n : float
        Φ_n, [-]
    embedding_force : float
        F_Z, [N]
    thermal_loss : float
        ΔF_th, positive for a loss, [N]

    Returns
    -------
    float
        F_KR,min, [N] (negative: the joint has opened)

    Notes
    -----
    VDI 2230-1:2015 step R12, eq. (R12/1); :func:`minimum_assembly_preload`
    is the same balance solved for F_M,min.

    Examples
    --------
    >>> residual_clamp_force(30e3, 8e3, 0.1, 2.6e3, 0.0)
    20200.0
    """
    left = _subtract_into(assembly_preload_min, clamp_load_reduction(load_factor_n, working_load))
    return _subtract_from(left, preload_losses(embedding_force, thermal_loss))


def separation_load(
    assembly_preload: float, losses: float, load_factor_n: float, opening_ratio: float = 0.0
) -> float:
    r"""Working load at which the joint opens: no clamp force left, or the edge lifts.

    .. math::
        F_{A,sep} = \frac{\max(F_M - F_Z - \max(\Delta F_{th}, 0),\ 0)}{1 - \Phi_n},
        \qquad
        F_{Aab} = \frac{\max(F_M - F_Z - \max(\Delta F_{th}, 0),\ 0)}{1 - \Phi^*_{en} + k_{ab}}

    infinite where the denominator is not positive (the plates never unload).
    Floats or arrays.

    Parameters
    ----------
    assembly_preload : float
        F_M, the assembly preload the joint starts from, [N]
    losses : float
        F_Z + max(ΔF_th, 0), see :func:`preload_losses`, [N]
    load_factor_n : float
        Φ_n (Φ*_en), [-]
    opening_ratio : float
        k_ab = F_KA/F_A of an eccentrically loaded interface
        (:func:`opening_ratio`; 0 concentric), [-]

    Returns
    -------
    float
        F_A at which F_KR = F_KA (concentric: F_KR = 0), [N]

    Notes
    -----
    VDI 2230-1:2015 step R12, eq. (R12/1) with F_KR = 0 solved for F_A; for an
    eccentric joint the opening limit F_Aab of §5.3.2, the load at which the
    residual clamp force F_V − (1 − Φ*_en) F_A falls to R2's F_KA = k_ab F_A
    (the interface starts to open at its edge u). With k_ab = 0 it is the
    concentric separation load to the bit.

    Examples
    --------
    >>> round(separation_load(30e3, 2.6e3, 0.1), 1)
    30444.4

    The same joint loaded off its bolt, opening ratio 0.5: 27 400/(0.9 + 0.5)

    >>> round(separation_load(30e3, 2.6e3, 0.1, 0.5), 1)
    19571.4
    """
    denominator = (1.0 - load_factor_n) + opening_ratio
    return _quotient(denominator > 0.0, _max(assembly_preload - losses, 0.0), denominator, math.inf)


def max_working_load(
    permissible_preload: float,
    tightening_factor: float,
    required_clamp_force: float,
    losses: float,
    load_factor_n: float,
    opening_ratio: float = 0.0,
    sealing_clamp_force: float = 0.0,
) -> float:
    r"""Largest working load whose required preload window fits under F_M,zul.

    .. math::
        F_{A,max} = \frac{\max(F_{M,zul}/\alpha_A - F_{K,erf} - F_Z
            - \max(\Delta F_{th}, 0),\ 0)}{1 - \Phi_n}

    and, for an eccentrically loaded joint (k_ab > 0), not above the load whose
    opening requirement F_KP + k_ab F_A fits: (F_M,zul/α_A − F_KP − losses)/(1 − Φ*_en + k_ab).

    Parameters
    ----------
    permissible_preload : float
        F_M,zul, [N]
    tightening_factor : float
        α_A, [-]
    required_clamp_force : float
        F_K,erf without the opening requirement, max(F_KQ, F_KP), [N]
    losses : float
        F_Z + max(ΔF_th, 0), [N]
    load_factor_n : float
        Φ_n (Φ*_en), [-]
    opening_ratio : float
        k_ab = F_KA/F_A (:func:`opening_ratio`; 0 concentric), [-]
    sealing_clamp_force : float
        F_KP, [N]

    Returns
    -------
    float
        F_A,max, [N]

    Notes
    -----
    VDI 2230-1:2015 steps R5–R7: R5 (eq. R5/1) and R6 (F_M,max = α_A
    F_M,min ≤ F_M,zul) solved for F_A; it is :func:`separation_load` from
    F_M,zul/α_A − F_K,erf.

    Examples
    --------
    >>> round(max_working_load(43.1e3, 1.6, 10e3, 2.6e3, 0.1), 1)
    15930.6

    Loaded eccentrically (k_ab = 0.5, no sealing force): 24 337.5/1.4 = 17 383.9 is
    above the friction limit, which holds

    >>> round(max_working_load(43.1e3, 1.6, 10e3, 2.6e3, 0.1, 0.5), 1)
    15930.6
    """
    top = permissible_preload / tightening_factor
    friction = separation_load(top - required_clamp_force, losses, load_factor_n)
    opening = separation_load(top - sealing_clamp_force, losses, load_factor_n, opening_ratio)
    return _where(opening_ratio > 0.0, _min(friction, opening), friction)


def required_preload_max(tightening_factor: float, required_preload_min: float) -> float:
    r"""Largest assembly preload the method's scatter gives when it must reach F_M,min.

    .. math::
        F_{M,max} = \alpha_A F_{M,min}

    Parameters
    ----------
    tightening_factor : float
        α_A, [-]
    required_preload_min : float
        F_M,min from R5, [N]

    Returns
    -------
    float
        F_M,max, [N]

    Notes
    -----
    VDI 2230-1:2015 step R6, eq. (R6/1).

    Examples
    --------
    >>> required_preload_max(1.6, 20e3)
    32000.0
    """
    return tightening_factor * required_preload_min


def design_preload_range(
    permissible_preload: float, tightening_factor: float
) -> tuple[float, float]:
    r"""Assembly preload range of a joint tightened to F_M,zul by a method of factor α_A.

    .. math::
        F_{M,max} = F_{M,zul},\qquad F_{M,min} = F_{M,zul}/\alpha_A

    Parameters
    ----------
    permissible_preload : float
        F_M,zul, [N]
    tightening_factor : float
        α_A, [-]

    Returns
    -------
    tuple of float
        (F_M,min, F_M,max), [N]

    Notes
    -----
    VDI 2230-1:2015 steps R1 and R7 (the design case: the top of the
    scatter band at the permissible preload).

    Examples
    --------
    >>> design_preload_range(40e3, 1.6)
    (25000.0, 40000.0)
    """
    return permissible_preload / tightening_factor, permissible_preload


def torque_tightening_factor(assembly_preload_min: float, assembly_preload_max: float) -> float:
    r"""Tightening factor of a preload range (infinite where F_M,min = 0).

    .. math::
        \alpha_A = F_{M,max}/F_{M,min}

    Parameters
    ----------
    assembly_preload_min : float
        F_M,min, [N]
    assembly_preload_max : float
        F_M,max, [N]

    Returns
    -------
    float
        α_A, [-]

    Notes
    -----
    VDI 2230-1:2015 step R1, eq. (R1/1), for the range a torque
    specification gives over the friction box (:func:`preload_bounds_from_torque`).

    Examples
    --------
    >>> round(torque_tightening_factor(31500.0, 64308.0), 4)
    2.0415
    """
    return _quotient(
        assembly_preload_min > 0.0, assembly_preload_max, assembly_preload_min, math.inf
    )


def smallest_area(smallest_diameter: float, stress_area: float, which: str) -> float:
    r"""Area A_0 of the smallest section: A_S in the thread, π d_0²/4 in a shank.

    .. math::
        A_0 = A_S\ \text{(thread)},\qquad A_0 = \frac{\pi}{4} d_0^2\ \text{(shank)}

    Parameters
    ----------
    smallest_diameter : float
        d_0 from :func:`smallest_section`, [m]
    stress_area : float
        A_S of the thread, [m^2]
    which : str
        ``"thread"`` or ``"shank"`` (an array of them on arrays)

    Returns
    -------
    float
        A_0, [m^2]

    Notes
    -----
    VDI 2230-1:2015 step R7 (A_0 = A_S or A_T); [004, eq. 3–4].

    Examples
    --------
    Waisted M12 with d_T = 7.5 mm: π/4 × 7.5² = 44.18 mm²

    >>> round(smallest_area(0.0075, 84.27e-6, "shank") * 1e6, 2)
    44.18
    """
    return _where(which == "thread", stress_area, _area(smallest_diameter))


def max_bolt_force(
    assembly_preload_max: float, additional_bolt_load: float, thermal_change: float = 0.0
) -> float:
    r"""Largest bolt force in service, with the preload a temperature change adds.

    .. math::
        F_{S,max} = F_{M,max} + \Phi_n F_{A,max} - \min(\Delta F_{Vth}, 0)

    Parameters
    ----------
    assembly_preload_max : float
        F_M,max (F_M,zul when tightened to it), [N]
    additional_bolt_load : float
        F_SA = Φ_n F_A,max, [N]
    thermal_change : float
        ΔF_Vth at F_M,max (:func:`thermal_preload_loss`), positive for a loss,
        negative for a gain, [N]

    Returns
    -------
    float
        F_S,max, [N]

    Notes
    -----
    VDI 2230-1:2015 step R8, eq. (R8/1): F_S,max = F_M,zul + Φ_en F_A,max − ΔF_Vth,
    where ΔF_Vth counts only when negative (the plates expand more than the bolt,
    or the bolt is cooled more, and the preload rises); a thermal loss is not
    credited against the largest bolt force.

    Examples
    --------
    >>> max_bolt_force(43.1e3, 800.0)
    43900.0

    Aluminium plates heated 150 K gain 12.9 kN of preload; a loss adds nothing:

    >>> max_bolt_force(43.1e3, 800.0, -12.9e3), max_bolt_force(43.1e3, 800.0, 5e3)
    (56800.0, 43900.0)
    """
    return _subtract_from(assembly_preload_max + additional_bolt_load, _min(thermal_change, 0.0))


def yield_safety(yield_strength: float, working_stress: float) -> float:
    r"""Safety against yield in service.

    .. math::
        S_F = \frac{R_{p0.2}}{\sigma_{red,B}}

    Parameters
    ----------
    yield_strength : float
        R_p0.2,min, [Pa]
    working_stress : float
        σ_red,B from :func:`service_stress`, [Pa]

    Returns
    -------
    float
        S_F, [-] (VDI asks ≥ 1.0)

    Notes
    -----
    VDI 2230-1:2015 step R8, eq. (R8/5).

    Examples
    --------
    >>> round(yield_safety(640e6, 562.4e6), 4)
    1.138
    """
    return yield_strength / working_stress


def stress_amplitude(
    load_factor_n: float, working_load: float, working_load_min: float, stress_area: float
) -> float:
    r"""Stress amplitude in the thread under an alternating working load.

    .. math::
        \sigma_a = \frac{\Phi_n (F_{A,max} - F_{A,min})}{2 A_S}

    Parameters
    ----------
    load_factor_n : float
        Φ_n, [-]
    working_load : float
        F_A,max, [N]
    working_load_min : float
        F_A,min, [N]
    stress_area : float
        A_S, [m^2]

    Returns
    -------
    float
        σ_a, [Pa]

    Notes
    -----
    VDI 2230-1:2015 step R9, eq. (R9/1) (concentric loading).

    Examples
    --------
    >>> round(stress_amplitude(0.1, 8000.0, 0.0, 84.27e-6) / 1e6, 3)
    4.747
    """
    return load_factor_n * (working_load - working_load_min) / (2.0 * stress_area)


def mean_bolt_force(
    assembly_preload_max: float, load_factor_n: float, working_load: float, working_load_min: float
) -> float:
    r"""Mean bolt force under an alternating working load.

    .. math::
        F_{Sm} = F_{M,max} + \Phi_n \frac{F_{A,max} + F_{A,min}}{2}

    Parameters
    ----------
    assembly_preload_max : float
        F_M,max, [N]
    load_factor_n : float
        Φ_n, [-]
    working_load : float
        F_A,max, [N]
    working_load_min : float
        F_A,min, [N]

    Returns
    -------
    float
        F_Sm, [N]

    Notes
    -----
    VDI 2230-1:2015 step R9 (the mean load of σ_ASG, §5.5.3).

    Examples
    --------
    >>> mean_bolt_force(43.1e3, 0.1, 8000.0, 0.0)
    43500.0
    """
    return assembly_preload_max + load_factor_n * 0.5 * (working_load + working_load_min)


def fatigue_safety(endurance_limit: float, stress_amplitude: float) -> float:
    r"""Safety against fatigue; infinite for a static load (σ_a = 0).

    .. math::
        S_D = \frac{\sigma_{AS}}{\sigma_a}

    Parameters
    ----------
    endurance_limit : float
        σ_AS, [Pa]
    stress_amplitude : float
        σ_a, [Pa]

    Returns
    -------
    float
        S_D, [-] (VDI asks ≥ 1.2)

    Notes
    -----
    VDI 2230-1:2015 step R9, eq. (R9/2).

    Examples
    --------
    >>> round(fatigue_safety(48.88e6, 4.747e6), 3)
    10.297
    """
    return _quotient(stress_amplitude > 0.0, endurance_limit, stress_amplitude, math.inf)


def slip_safety(
    residual_clamp_force: float,
    slip_interfaces: int,
    interface_friction: float,
    transverse_load: float,
    torsional_moment: float = 0.0,
    torque_interfaces: int = 1,
    friction_radius: float = 1.0,
) -> float:
    r"""Safety of the interfaces against slipping; infinite without a transverse load.

    .. math::
        S_G = \frac{F_{KR,min}\, q_F\, \mu_{T,min}}{F_{Q,max} + M_{Y,max}\,q_F/(q_M r_a)}

    All arguments may be floats or numpy arrays of one shape.

    Parameters
    ----------
    residual_clamp_force : float
        F_KR,min, [N]
    slip_interfaces : int
        q_F, [1]
    interface_friction : float
        μ_T,min, [1]
    transverse_load : float
        F_Q,max, [N]
    torsional_moment : float
        M_Y,max about the bolt axis, [N*m]
    torque_interfaces : int
        q_M, [1]
    friction_radius : float
        r_a, [m]

    Returns
    -------
    float
        S_G, [-]

    Notes
    -----
    VDI 2230-1:2015 step R12, eq. (R12/2): F_KR,min over the F_KQ of
    :func:`transverse_clamp_force`, the torsional moment as the transverse load
    it equals on the q_F interfaces. Without M_Y it is F_KR q_F μ_T/F_Q to the bit.

    Examples
    --------
    >>> round(slip_safety(20e3, 1, 0.15, 2e3), 3)
    1.5

    Plus 30 N·m at r_a = 20 mm: 3000/(2000 + 1500)

    >>> round(slip_safety(20e3, 1, 0.15, 2e3, 30.0, 1, 0.020), 4)
    0.8571
    """
    torsion = torsional_moment * slip_interfaces / (torque_interfaces * friction_radius)
    demand = transverse_load + torsion
    return _quotient(
        demand > 0.0,
        residual_clamp_force * slip_interfaces * interface_friction,
        demand,
        math.inf,
    )


def required_slip_safety(working_load: float, working_load_min: float) -> float:
    r"""The slip safety VDI 2230 asks for: 1.8 under an alternating load, 1.2 static.

    .. math::
        S_{G,erf} = 1.8\ (F_{A,min} < F_{A,max}),\qquad 1.2\ \text{otherwise}

    Parameters
    ----------
    working_load : float
        F_A,max, [N]
    working_load_min : float
        F_A,min, [N]

    Returns
    -------
    float
        S_G,erf, [-]

    Notes
    -----
    VDI 2230-1:2015 step R12 (recommended S_G ≥ 1.2 static, ≥ 1.8 under
    alternating transverse or axial load).

    Examples
    --------
    >>> required_slip_safety(8e3, 0.0), required_slip_safety(8e3, 8e3)
    (1.8, 1.2)
    """
    return _where(working_load_min < working_load, 1.8, 1.2)


def nominal_preload(assembly_preload_min: float, assembly_preload_max: float) -> float:
    r"""Nominal (mean) assembly preload of a scatter band.

    .. math::
        F_{M,nom} = \frac{F_{M,min} + F_{M,max}}{2}

    Parameters
    ----------
    assembly_preload_min : float
        F_M,min, [N]
    assembly_preload_max : float
        F_M,max, [N]

    Returns
    -------
    float
        F_M,nom, [N]

    Notes
    -----
    [004, eq. 6] states its preload rule at the nominal preload; the middle of
    the band VDI 2230-1 R1 defines with α_A.

    Examples
    --------
    >>> nominal_preload(25e3, 40e3)
    32500.0
    """
    return 0.5 * (assembly_preload_min + assembly_preload_max)


def preload_stress_ratio(preload: float, smallest_area: float, yield_strength: float) -> float:
    r"""Tensile stress of the preload over the yield strength.

    .. math::
        \frac{\sigma_0}{\sigma_T} = \frac{F_{M,nom}}{A_0\,\sigma_T}

    Parameters
    ----------
    preload : float
        F_M,nom, [N]
    smallest_area : float
        A_0, [m^2]
    yield_strength : float
        σ_T = R_p0.2, [Pa]

    Returns
    -------
    float
        σ0/σ_T, [-]

    Notes
    -----
    [004, eq. 6] (0.4…0.5 σ_T, 0.5…0.7 with an accurate method, 0.8…0.9
    for bridge joints).

    Examples
    --------
    >>> round(preload_stress_ratio(32.5e3, 84.27e-6, 640e6), 4)
    0.6026
    """
    return preload / smallest_area / yield_strength


def joint_diagram(
    preload: float,
    bolt: float,
    clamped: float,
    working_load: float,
    load_factor_n: float,
    embedding_force: float,
    points: int = 41,
) -> dict[str, list[float]]:
    r"""The joint diagram as lines on one deformation axis.

    .. math::
        F_S = \frac{f}{\delta_S}, \qquad F_P = F_M - \frac{f - F_M\delta_S}{\delta_P}

    Parameters
    ----------
    preload : float
        F_M, [N]
    bolt : float
        δ_S, [m/N]
    clamped : float
        δ_P, [m/N]
    working_load : float
        F_A, [N]
    load_factor_n : float
        Φ_n, [-]
    embedding_force : float
        F_Z, [N]
    points : int
        Number of points on the deformation axis, [-]

    Returns
    -------
    dict of str to list of float
        ``deformation`` [m], the x axis from 0 to F_M (δ_S + δ_P); on it, in N:
        ``bolt_line`` (F = f/δ_S), ``clamped_line`` (through F_M at f_SM),
        ``embedded_clamped_line`` (the same after the settlement f_Z, through
        F_V = F_M − F_Z), and the levels ``preload_level`` (F_M),
        ``service_preload_level`` (F_V), ``working_bolt_force_level``
        (F_V + Φ_n F_A) and ``residual_clamp_level`` (F_V − (1 − Φ_n) F_A,
        not below 0). The lines are clipped to 0…1.2 × the largest level so
        they stay on the plot. Two segments of two points each, as VDI draws
        them: ``working_deformation``/``working_force``, F_A split by Φ_n at the
        working point f_SV + Φ_n F_A δ_S (from F_KR up to F_S), and
        ``opening_deformation``/``opening_force``, the same at the separation load
        F_V/(1 − Φ_n) (from 0 up to the bolt force there; empty where Φ_n ≥ 1).

    Notes
    -----
    VDI 2230-1:2015 §3.2 (the joint diagram). F_A is the vertical distance
    between the working bolt force and the residual clamp force levels at
    the working point; F_Z the distance between F_M and F_V.

    Examples
    --------
    >>> d = joint_diagram(30e3, 3e-9, 1e-9, 10e3, 0.25, 2e3)
    >>> d["bolt_line"][-1], d["clamped_line"][-1], d["working_bolt_force_level"][0]
    (36600.0, 0.0, 30500.0)

    F_A = 10 kN from 20.5 kN (F_KR) up to 30.5 kN (F_S) at 84 + 7.5 µm; the joint separates
    at F_V/(1 − Φ_n) = 37.33 kN, where the bolt carries 37.33 kN:

    >>> [round(v * 1e6, 3) for v in d["working_deformation"]], d["working_force"]
    ([91.5, 91.5], [20500.0, 30500.0])
    >>> [round(v, 1) for v in d["opening_force"]]
    [0.0, 37333.3]
    """
    f_sm = preload * bolt
    f_end = f_sm + preload * clamped
    service = preload - embedding_force
    f_sv = service * bolt
    bolt_force = service + load_factor_n * working_load
    residual = max(service - (1.0 - load_factor_n) * working_load, 0.0)
    top = 1.2 * max(preload, bolt_force)

    def clip(v: float) -> float:
        return min(max(v, 0.0), top)

    xs = [f_end * i / (points - 1) for i in range(points)]
    f_work = f_sv + load_factor_n * working_load * bolt
    opening: dict[str, list[float]] = {"opening_deformation": [], "opening_force": []}
    if load_factor_n < 1.0:
        f_sep = max(service, 0.0) / (1.0 - load_factor_n)
        top_sep = service + load_factor_n * f_sep
        opening = {
            "opening_deformation": [f_sv + load_factor_n * f_sep * bolt] * 2,
            "opening_force": [0.0, top_sep],
        }
    return {
        "working_deformation": [f_work, f_work],
        "working_force": [service - (1.0 - load_factor_n) * working_load, bolt_force],
        **opening,
        "deformation": xs,
        "bolt_line": [clip(x / bolt) for x in xs],
        "clamped_line": [clip(preload - (x - f_sm) / clamped) for x in xs],
        "embedded_clamped_line": [clip(service - (x - f_sv) / clamped) for x in xs],
        "preload_level": [preload] * points,
        "service_preload_level": [service] * points,
        "working_bolt_force_level": [bolt_force] * points,
        "residual_clamp_level": [residual] * points,
    }


# --------------------------------------------------------------------------- eccentric joint
#
# VDI 2230-1:2015 §5.3.2: the bolt off the axis O–O of the clamped body (s_sym), the working
# load at a lever a from it, the interface's edge u where it opens first. Every relation
# reduces to the concentric one at s_sym = a = u = 0 (to the bit: the offsets multiply).


def cone_bending_inertia(bearing_diameter: float, cone_diameter: float) -> float:
    r"""Second moment of area of VDI's deformation cone about its own axis.

    .. math::
        I_{V,Bers} = 0.147\,\frac{(D_A' - d_W)\,d_W^3\,D_A'^3}{D_A'^3 - d_W^3}
            = 0.147\,\frac{d_W^3\,D_A'^3}{D_A'^2 + D_A' d_W + d_W^2}

    Parameters
    ----------
    bearing_diameter : float
        d_W, [m]
    cone_diameter : float
        D_A' = min(D_A, D_A,Gr), where the cone ends, [m]

    Returns
    -------
    float
        I_V,Bers, [m^4]

    Notes
    -----
    VDI 2230-1:2015 §5.3.2 (substitute moment of inertia of the cone), as the
    open implementation h18340637145/vdi2230 states it; written in the second,
    factored form so that D_A' = d_W gives its limit 0.049 d_W⁴ (≈ π d_W⁴/64)
    instead of 0/0.

    Examples
    --------
    >>> round(cone_bending_inertia(0.01663, 0.03609) * 1e12, 1)
    14583.2
    """
    d_w, outer = bearing_diameter, cone_diameter
    return 0.147 * d_w**3 * outer**3 / (outer * outer + outer * d_w + d_w * d_w)


def substitute_bending_inertia(
    grip: float,
    bearing_diameter: float,
    cone_diameter: float,
    tangent: float,
    bolt_offset: float,
    interface_width: float,
    interface_length: float,
    joint: str = "through",
) -> float:
    r"""Substitute second moment I_Bers of the clamped body about its axis O–O.

    .. math::
        I_{ve,Bers} = I_{V,Bers} + s_{sym}^2\,\frac{\pi}{4} D_A'^2,\quad
        I_{H,Bers} = \frac{b\,c_T^3}{12},\quad
        l_V = \frac{D_A' - d_W}{2\tan\varphi},\quad l_H = l_K - \frac{2 l_V}{w}

    .. math::
        I_{Bers} = \frac{l_K}{\dfrac{2 l_V}{w\,I_{ve,Bers}} + \dfrac{l_H}{I_{H,Bers}}}

    Parameters
    ----------
    grip : float
        l_K, [m]
    bearing_diameter : float
        d_W, [m]
    cone_diameter : float
        D_A' = min(D_A, D_A,Gr), [m]
    tangent : float
        tan φ of the cone, [-]
    bolt_offset : float
        s_sym, the bolt axis's distance from the body's axis O–O, [m]
    interface_width : float
        b, the interface's width across the bending plane, [m]
    interface_length : float
        c_T, the interface's length in the bending plane, [m]
    joint : str
        ``"through"`` (w = 1, two cones) or ``"tapped"`` (w = 2, one)

    Returns
    -------
    float
        I_Bers, [m^4]

    Notes
    -----
    VDI 2230-1:2015 §5.3.2: the cone (shifted to O–O by Steiner's term) and the
    sleeve of the prismatic body b × c_T in series along the grip; a fully
    developed cone (D_A ≥ D_A,Gr, l_H = 0) gives I_ve,Bers alone. The open
    implementation h18340637145/vdi2230 combines them the same way (it writes
    l_V without the parentheses around D_A − d_W; we take the cone height).

    Examples
    --------
    M12, l_K = 40 mm through, D_A' = 30 mm < D_A,Gr, tan φ = 0.5, bolt 10 mm off
    the axis of a 40 × 60 mm interface (b = 40, c_T = 60):

    >>> round(substitute_bending_inertia(0.040, 0.01663, 0.030, 0.5, 0.010, 0.040, 0.060)
    ...       * 1e12)
    115543
    """
    w = 1.0 if joint == "through" else 2.0
    cone = cone_bending_inertia(bearing_diameter, cone_diameter) + bolt_offset**2 * _area(
        cone_diameter
    )
    sleeve = interface_width * interface_length**3 / 12.0
    cone_length = _max((cone_diameter - bearing_diameter) / (2.0 * tangent), 0.0)  # 0: a sleeve
    sleeve_length = _max(grip - 2.0 * cone_length / w, 0.0)
    return grip / (2.0 * cone_length / (w * cone) + sleeve_length / sleeve)


def clamped_bending_compliance(
    thicknesses: Sequence[float], youngs_moduli: Sequence[float], inertia: float
) -> float:
    r"""Bending compliance β_P of the clamped parts.

    .. math::
        \beta_P = \frac{1}{I_{Bers}} \sum_i \frac{h_i}{E_i}
            \quad\left(= \frac{l_K}{E_P I_{Bers}}\ \text{for one material}\right)

    Parameters
    ----------
    thicknesses : sequence of float
        h_i, [m]
    youngs_moduli : sequence of float
        E_i, [Pa]
    inertia : float
        I_Bers (:func:`substitute_bending_inertia`); inf gives β_P = 0, [m^4]

    Returns
    -------
    float
        β_P, [1/(N*m)]

    Notes
    -----
    VDI 2230-1:2015 §5.3.2, β_P = l_K/(E_P I_Bers); plates of several moduli in
    series along the grip, each over the same I_Bers (our extension of VDI's one E_P).

    Examples
    --------
    >>> round(clamped_bending_compliance([0.02, 0.02], [2.1e11, 2.1e11], 2.4e-7) * 1e6, 4)
    0.7937
    """
    length: Any = 0.0
    for h, e in zip(thicknesses, youngs_moduli, strict=True):
        length = length + h / e
    return length / inertia


def eccentric_compliance(clamped: float, bending: float, bolt_offset: float, lever: float) -> float:
    r"""Axial compliance of eccentrically clamped (δ*_P) or loaded (δ**_P) plates.

    .. math::
        \delta^*_P = \delta_P + s_{sym}^2\,\beta_P,\qquad
        \delta^{**}_P = \delta_P + s_{sym}\,a\,\beta_P

    Parameters
    ----------
    clamped : float
        δ_P, [m/N]
    bending : float
        β_P, [1/(N*m)]
    bolt_offset : float
        s_sym, [m]
    lever : float
        s_sym for δ*_P, the load's lever a for δ**_P, [m]

    Returns
    -------
    float
        δ*_P or δ**_P, [m/N]

    Notes
    -----
    VDI 2230-1:2015 §5.3.2 (eq. 5.3/… for δ*_P and δ**_P); zero offsets give δ_P.

    Examples
    --------
    >>> round(eccentric_compliance(0.6e-9, 2e-6, 0.005, 0.005) * 1e9, 4)
    0.65
    >>> round(eccentric_compliance(0.6e-9, 2e-6, 0.005, 0.02) * 1e9, 4)
    0.8
    """
    return clamped + bolt_offset * lever * bending


def interface_section(width: float, length: float, hole_diameter: float) -> tuple[float, float]:
    r"""Area and second moment of the interface (the bending plane's section of the joint).

    .. math::
        A_D = b\,c_T - \frac{\pi}{4} d_h^2,\qquad I_{BT} = \frac{b\,c_T^3}{12}

    Parameters
    ----------
    width : float
        b, [m]
    length : float
        c_T, [m]
    hole_diameter : float
        d_h, [m]

    Returns
    -------
    tuple of float
        (A_D [m^2], I_BT [m^4])

    Notes
    -----
    VDI 2230-1:2015 R2 (the opening requirement's section of a rectangular
    interface; the hole is left out of I_BT, as VDI's and the open
    implementation h18340637145/vdi2230's b c_T³/12).

    Examples
    --------
    >>> a, i = interface_section(0.040, 0.060, 0.0135)
    >>> round(a * 1e6, 2), round(i * 1e12)
    (2256.86, 720000)
    """
    return width * length - _area(hole_diameter), width * length**3 / 12.0


#: VDI 2230-1's G' = (1.5…2) d_W of a tapped joint, as multiples of d_W (the lower end is
#: the one the open implementations apply without a counterbore).
TAPPED_INTERFACE_LIMIT = (1.5, 2.0)


def interface_limit(bearing_diameter: Any, thinnest_plate: Any, joint_type: str) -> Any:
    r"""The widest interface c_T the eccentric relations hold for, VDI 2230-1's G.

    .. math::
        G = d_W + h_{min}\ \text{(through-bolted)},\qquad
        G' = 1.5\,d_W\ \text{(tapped; VDI gives } (1.5 \ldots 2)\,d_W)

    Parameters
    ----------
    bearing_diameter : float or array
        d_W, outer diameter of the head's (or nut's) bearing face, [m]
    thinnest_plate : float or array
        h_min, the thinner of the outer clamped plates (under head and nut; unused for a
        tapped joint), [m]
    joint_type : str
        ``"through"`` or ``"tapped"``, [-]

    Returns
    -------
    float or array
        G (through) or the lower end of G' (tapped), [m]

    Notes
    -----
    VDI 2230-1 R0 and eqs. (5.1/38), (5.1/39) as the open implementations
    [STEELPY-VDI] (G = h_min + d_W, G' = (1.5…2) d_W) and h18340637145/vdi2230
    (G = d_W + h_min, 1.5 d_W tapped) reproduce them. The eccentric relations
    (I_Bers, I_BT, Φ*_en, F_KA) hold for c_T ≤ G; beyond it the interface
    is not clamped by this bolt alone.

    Examples
    --------
    >>> round(interface_limit(0.01663, 0.020, "through") * 1e3, 2)
    36.63
    >>> round(interface_limit(0.01663, 0.020, "tapped") * 1e3, 3)
    24.945
    """
    if joint_type == "tapped":
        return TAPPED_INTERFACE_LIMIT[0] * bearing_diameter
    return bearing_diameter + thinnest_plate


def opening_ratio(
    load_lever: float,
    bolt_offset: float,
    edge_distance: float,
    interface_area: float,
    interface_inertia: float,
) -> float:
    r"""Clamp force per newton of working load that keeps the interface's edge closed.

    .. math::
        k_{ab} = \max\left(\frac{(a - s_{sym})\,u}{I_{BT}/A_D + s_{sym}\,u},\ 0\right)
            = \frac{F_{KA}}{F_A}

    Parameters
    ----------
    load_lever : float
        a, the working load's distance from the axis O–O, [m]
    bolt_offset : float
        s_sym, [m]
    edge_distance : float
        u, the distance from O–O of the interface edge that opens first, [m]
    interface_area : float
        A_D, [m^2]
    interface_inertia : float
        I_BT, [m^4]

    Returns
    -------
    float
        k_ab, [-] (0 where the load line is not beyond the bolt: the edge does
        not open before the whole interface separates)

    Notes
    -----
    VDI 2230-1:2015 step R2, eq. (R2/3) with M_B = 0: F_KA = F_A (a u − s_sym u)
    /(I_BT/A_D + s_sym u), the linear pressure of the interface falling to zero
    at the edge; the open implementation h18340637145/vdi2230 computes the same.

    Examples
    --------
    Load 40 mm out, bolt 10 mm off, edge 30 mm, 40 × 60 mm interface:

    >>> round(opening_ratio(0.040, 0.010, 0.030, 2256.86e-6, 720000e-12), 4)
    1.4539
    """
    moment = (load_lever - bolt_offset) * edge_distance
    ratio = moment / (interface_inertia / interface_area + bolt_offset * edge_distance)
    return _max(ratio, 0.0)


def opening_clamp_force(working_load: float, opening_ratio: float) -> float:
    r"""Clamp force F_KA that keeps an eccentrically loaded interface from opening.

    .. math::
        F_{KA} = k_{ab}\,F_{A,max}

    Parameters
    ----------
    working_load : float
        F_A,max, [N]
    opening_ratio : float
        k_ab (:func:`opening_ratio`), [-]

    Returns
    -------
    float
        F_KA, [N]

    Notes
    -----
    VDI 2230-1:2015 step R2, eq. (R2/3) (M_B = 0); it adds to the sealing
    force F_KP in F_K,erf (:func:`required_clamp_force`).

    Examples
    --------
    >>> round(opening_clamp_force(8e3, 1.4539), 1)
    11631.2
    """
    return opening_ratio * working_load


def eccentric_stress_factor(
    load_factor_en: float,
    load_lever: float,
    bolt_offset: float,
    clamped_bending: float,
    bolt_bending: float,
    stress_diameter: float,
) -> float:
    r"""Share Φ_b of the working load that the bolt's thread sees as stress, with bending.

    .. math::
        \sigma_{SAb} = \Phi_b \frac{F_A}{A_S},\qquad
        \Phi_b = \Phi^*_{en} + (a - s_{sym}\Phi^*_{en})\,
            \frac{\beta_P}{\beta_S}\,\frac{A_S}{W_S},\quad W_S = \frac{\pi}{32} d_S^3

    which is VDI's σ_SAb = [1 + (1/Φ*_en − s_sym/a)(l_K/l_ers)(E_S/E_P)
    π a d_S³/(8 I_Bers)] Φ*_en F_A/A_S with l_ers = β_S E_S π d_S⁴/64.

    Parameters
    ----------
    load_factor_en : float
        Φ*_en, [-]
    load_lever : float
        a, [m]
    bolt_offset : float
        s_sym, [m]
    clamped_bending : float
        β_P, [1/(N*m)]
    bolt_bending : float
        β_S, [1/(N*m)]
    stress_diameter : float
        d_S, [m]

    Returns
    -------
    float
        Φ_b, [-] (Φ*_en where a = s_sym = 0)

    Notes
    -----
    VDI 2230-1:2015 step R9, eq. (R9/… σ_SAb) for F_A ≤ F_Aab: the bending moment
    (a − s_sym Φ*_en) F_A that the plates take turns them by β_P per N·m, and the
    bolt, bent through the same angle, carries β_P/β_S of it at its section
    modulus W_S. VDI writes the bolt's bending compliance through a substitute
    length l_ers; taking it at the stress section (l_ers = β_S E_S π d_S⁴/64) is
    what makes its relation this beam result; the open implementation
    h18340637145/vdi2230 refers l_ers to the nominal section instead (π d⁴/64)
    and leaves the engaged thread out of it, which gives a bending term 0.63 times
    ours for M12 through 40 mm (tests/validation/test_joint_eccentric.py).

    Examples
    --------
    Φ*_en = 0.2, a = 20 mm, s_sym = 5 mm, β_P = 2e-6, β_S = 5e-4 /(N m), d_S = 10.358 mm:
    A_S/W_S = 8/d_S

    >>> round(eccentric_stress_factor(0.2, 0.020, 0.005, 2e-6, 5e-4, 0.010358), 4)
    0.2587
    """
    return load_factor_en + (load_lever - bolt_offset * load_factor_en) * (
        clamped_bending / bolt_bending
    ) * (8.0 / stress_diameter)


def additional_bolt_stress(stress_factor: float, working_load: float, stress_area: float) -> float:
    r"""Additional stress in the bolt's thread under the working load, bending included.

    .. math::
        \sigma_{SAb} = \Phi_b \frac{F_{A,max}}{A_S}

    Parameters
    ----------
    stress_factor : float
        Φ_b from :func:`eccentric_stress_factor` (Φ_n for a concentric joint), [-]
    working_load : float
        F_A,max, [N]
    stress_area : float
        A_S, [m^2]

    Returns
    -------
    float
        σ_SAb (σ_SA = Φ_n F_A/A_S concentric), [Pa]

    Notes
    -----
    VDI 2230-1:2015 step R9 (σ_SAbo at F_A,max, valid up to the opening limit F_Aab).

    Examples
    --------
    >>> round(additional_bolt_stress(0.2587, 8e3, 84.27e-6) / 1e6, 2)
    24.56
    """
    return stress_factor * working_load / stress_area


# --------------------------------------------------------------------------- many bolts


def ring_flange_axial_load(
    axial_force: float, bending_moment: float, bolts: int, circle_diameter: float
) -> float:
    r"""Working load of the most loaded bolt of a rigid ring flange of z equal bolts.

    .. math::
        F_{A,max} = \frac{F_{ax}}{z} + \frac{4\,M_B}{z\,D_t}

    Parameters
    ----------
    axial_force : float
        F_ax, the flange's axial (opening) force, [N]
    bending_moment : float
        M_B, the bending moment on the flange about a diameter, [N*m]
    bolts : int
        z, equally spaced on the bolt circle (≥ 3), [1]
    circle_diameter : float
        D_t, the bolt circle diameter, [m]

    Returns
    -------
    float
        F_A of the bolt farthest from the bending axis, [N]

    Notes
    -----
    VDI 2230-1:2015 §3.1 (the single-bolt joint cut from a multi-bolt joint, the
    simplification of VDI 2230 Part 2 for rigid flanges): the interface stays
    closed and the flanges rigid, so the bolt loads are linear in their distance
    from the neutral axis through the circle's centre; for z ≥ 3 equally spaced
    bolts Σ y_i² = z D_t²/8, and the load on a bolt on the bending plane is the
    largest (a bolt half a pitch off it carries cos(π/z) of the bending share).
    It does not hold once the interface opens (tilting about the flange's edge)
    or for flexible flanges and gaskets (VDI 2230 Part 2's models).

    Examples
    --------
    100 kN and 5 kN·m on 8 bolts on a 200 mm circle: 12.5 kN + 12.5 kN

    >>> ring_flange_axial_load(100e3, 5e3, 8, 0.200)
    25000.0
    """
    return axial_force / bolts + 4.0 * bending_moment / (bolts * circle_diameter)


def ring_flange_transverse_load(
    transverse_force: float, torque: float, bolts: int, circle_diameter: float
) -> float:
    r"""Transverse load per bolt of a ring flange under a shear force and a torque.

    .. math::
        F_{Q,max} = \frac{F_Q}{z} + \frac{2\,M_T}{z\,D_t}

    Parameters
    ----------
    transverse_force : float
        F_Q, the flange's shear force, [N]
    torque : float
        M_T, the torque about the flange's axis, [N*m]
    bolts : int
        z, [1]
    circle_diameter : float
        D_t, [m]

    Returns
    -------
    float
        F_Q per bolt, the torque's share tangential and the shear force's added
        to it at the bolt where both point the same way, [N]

    Notes
    -----
    VDI 2230-1:2015 step R2 (F_KQ from the transverse load per bolt; a torque on a
    bolt circle is carried by friction at radius D_t/2, equally by every bolt) with
    the same rigid-flange simplification as :func:`ring_flange_axial_load`.

    Examples
    --------
    2 kN·m on 8 bolts on a 200 mm circle, no shear force: 2 × 2000/(8 × 0.2)

    >>> ring_flange_transverse_load(0.0, 2e3, 8, 0.200)
    2500.0
    """
    return transverse_force / bolts + 2.0 * torque / (bolts * circle_diameter)


# --------------------------------------------------------------------------- fitted bolts


def fitted_shank_shear_stress(
    transverse_load: float, shear_planes: int, fitted_diameter: float
) -> float:
    r"""Shear stress in the fitted shank of a bolt that carries the transverse load itself.

    .. math::
        \tau_Q = \frac{F_{Q,max}}{q_F\,A_\tau},\qquad A_\tau = \frac{\pi}{4} d_\tau^2

    Parameters
    ----------
    transverse_load : float
        F_Q,max, [N]
    shear_planes : int
        q_F, the interfaces the shank crosses (one shear section each), [1]
    fitted_diameter : float
        d_τ, the fitted shank's diameter, [m]

    Returns
    -------
    float
        τ_Q, [Pa]

    Notes
    -----
    VDI 2230-1:2015 step R12 (fitted bolts: τ_Q,max = F_Q,max/A_τ against τ_B with
    S_A ≥ 1.1), the load shared equally by the q_F shear sections.

    Examples
    --------
    20 kN in single shear on a 13 mm fitted shank: 20 000/132.73 mm²

    >>> round(fitted_shank_shear_stress(20e3, 1, 0.013) / 1e6, 2)
    150.68
    """
    return transverse_load / (shear_planes * _area(fitted_diameter))


def fitted_bearing_pressure(
    transverse_load: float, fitted_diameter: float, thinnest_plate: float
) -> float:
    r"""Bearing pressure of a fitted shank on the hole wall of the thinnest plate.

    .. math::
        p_Q = \frac{F_{Q,max}}{d_\tau\,h_{min}}

    Parameters
    ----------
    transverse_load : float
        F_Q,max, [N]
    fitted_diameter : float
        d_τ, [m]
    thinnest_plate : float
        h_min, the thinnest clamped plate, [m]

    Returns
    -------
    float
        p_Q, [Pa]

    Notes
    -----
    VDI 2230-1:2015 step R12 (fitted bolts: the hole wall's bearing, to be held
    against the plate material's bearing strength); the projected area of the
    thinnest plate carrying the whole F_Q is the conservative case.

    Examples
    --------
    >>> round(fitted_bearing_pressure(20e3, 0.013, 0.010) / 1e6, 1)
    153.8
    """
    return transverse_load / (fitted_diameter * thinnest_plate)


def fitted_shear_safety(tensile_strength: float, shear_stress: float) -> float:
    r"""Safety of a fitted shank against shearing off.

    .. math::
        S_A = \frac{\tau_B}{\tau_Q},\qquad \tau_B = 0.6\,R_m

    Parameters
    ----------
    tensile_strength : float
        R_m of the bolt, [Pa]
    shear_stress : float
        τ_Q (:func:`fitted_shank_shear_stress`), [Pa]

    Returns
    -------
    float
        S_A, [-] (VDI asks ≥ 1.1; infinite without a transverse load)

    Notes
    -----
    VDI 2230-1:2015 step R12; τ_B/R_m = 0.6, the ratio the engine takes for the
    bolt's thread shear as well (:data:`engine.procedures.bolt.BOLT_SHEAR_RATIO`).

    Examples
    --------
    >>> round(fitted_shear_safety(800e6, 150.68e6), 3)
    3.186
    """
    return _quotient(
        shear_stress > 0.0, SHANK_SHEAR_RATIO * tensile_strength, shear_stress, math.inf
    )
