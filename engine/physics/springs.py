r"""Springs: helical compression springs to EN 13906-1, disc springs to DIN EN 16983.

Pure functions on SI floats (or numpy arrays). The clutch of [001] presses its
balls with a helical spring; torque limiters on the market (ball-detent
limiters) mostly use disc springs, often set in the falling part of their
curve so that the torque drops once the balls leave their detents. Both are
here, each with the checks a spring maker makes.

Helical compression springs (EN 13906-1)
    rate R = G d⁴ / (8 D³ n); shear stress τ = 8 F D / (π d³) and the corrected
    τ_k = k τ with Bergsträsser's k = (w + 0.5)/(w − 0.75) (the standard's
    factor) or Wahl's (4w − 1)/(4w − 4) + 0.615/w (older textbooks; the two
    differ by < 1.5 % for w ≥ 4); solid length, the minimum sum of gaps S_a,
    buckling by the seating coefficient ν, the first natural frequency.
    Materials: patented drawn spring steel wire EN 10270-1 grades SH and DH
    (the same strength table; DH is the dynamic-duty grade) and stainless
    X10CrNi18-8, 1.4310 (EN 10270-3, grade NS), with the minimum tensile
    strength R_m by wire diameter and the permissible static shear stress
    τ_zul = 0.5 R_m (EN 13906-1, cold-coiled springs).

Disc springs (DIN EN 16983, the former DIN 2092; Almen and László)
    force F(s) = 4E/(1 − μ²) · t⁴/(K1 De²) · K4² · (s/t) ·
    [K4² (h0/t − s/t)(h0/t − s/(2t)) + 1] and the stresses at the points OM, I,
    II, III, IV; stacks of i discs in series and n in parallel, with the
    friction factors of a parallel pack optional. For h0/t > √2 (K4 = 1) the
    curve has a falling part between its maximum and minimum.

Where a figure comes from a table transcribed into this module, the table's
docstring says from where and how far it was checked.
"""

from __future__ import annotations

import bisect
import math
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

from ..core.errors import InputOutOfRange

FloatArray = float | npt.NDArray[np.float64]

__all__ = [
    "CORRECTIONS",
    "MATERIALS",
    "SEATING_COEFFICIENTS",
    "STANDARD_WIRE_DIAMETERS",
    "DiscLaw",
    "SpringMaterial",
    "bergstrasser_factor",
    "buckling_deflection",
    "disc_factors",
    "disc_falling_region",
    "disc_force",
    "disc_force_flat",
    "disc_force_of",
    "disc_k4",
    "disc_law",
    "disc_rate",
    "disc_rate_of",
    "disc_stress_om",
    "disc_stresses",
    "disc_thickness_for_flat_force",
    "helical_mass",
    "helical_natural_frequency",
    "helical_rate",
    "helical_shear_stress",
    "minimum_gap_sum",
    "nearest_standard_wire",
    "permissible_shear_stress",
    "solid_length",
    "stack_force",
    "stress_correction_factor",
    "tensile_strength",
    "wahl_factor",
]


def _out(value: Any) -> FloatArray:
    arr = np.asarray(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr


# --------------------------------------------------------------------------
# Helical compression springs, EN 13906-1
# --------------------------------------------------------------------------


def helical_rate(
    shear_modulus: FloatArray,
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
) -> FloatArray:
    r"""Axial rate of a cylindrical helical compression spring (EN 13906-1).

    .. math::
        R = \frac{G d^4}{8 D^3 n}

    Parameters
    ----------
    shear_modulus : float
        Shear modulus G of the wire, [Pa]
    wire_diameter : float
        Wire diameter d, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    active_coils : float
        Number of active coils n, [-]

    Returns
    -------
    rate : float
        Force per unit deflection, [N/m]

    Notes
    -----
    EN 13906-1, spring rate; the same relation as [001, eq. 2].

    Examples
    --------
    >>> round(helical_rate(81.37e9, 0.007, 0.042, 8) / 1e3, 3)
    41.203
    """
    return _out(
        np.asarray(shear_modulus)
        * np.asarray(wire_diameter) ** 4
        / (8.0 * np.asarray(mean_diameter) ** 3 * np.asarray(active_coils))
    )


def wahl_factor(index: FloatArray) -> FloatArray:
    r"""Wahl's stress-correction factor of a helical spring of index w = D/d.

    .. math::
        k_W = \frac{4w - 1}{4w - 4} + \frac{0.615}{w}

    Parameters
    ----------
    index : float
        Spring index w = D/d, > 1, [-]

    Returns
    -------
    factor : float
        Peak (inner-fibre) shear stress over 8FD/(πd³), [-]

    Notes
    -----
    Wahl (1963). Diverges as w → 1.

    Examples
    --------
    >>> round(wahl_factor(6.0), 4)
    1.2525
    """
    w = np.asarray(index, dtype=float)
    return _out((4.0 * w - 1.0) / (4.0 * w - 4.0) + 0.615 / w)


def bergstrasser_factor(index: FloatArray) -> FloatArray:
    r"""Bergsträsser's stress-correction factor, the one EN 13906-1 uses.

    .. math::
        k = \frac{w + 0.5}{w - 0.75}

    Parameters
    ----------
    index : float
        Spring index w = D/d, > 0.75, [-]

    Returns
    -------
    factor : float
        Peak (inner-fibre) shear stress over 8FD/(πd³), [-]

    Notes
    -----
    EN 13906-1, stress correction factor k. Within 1.5 % of Wahl's factor
    for w ≥ 4 (Bergsträsser's is the smaller).

    Examples
    --------
    >>> round(bergstrasser_factor(6.0), 4)
    1.2381
    """
    w = np.asarray(index, dtype=float)
    return _out((w + 0.5) / (w - 0.75))


#: Stress-correction choices: name -> factor function of the index.
CORRECTIONS = {"wahl": wahl_factor, "bergstrasser": bergstrasser_factor}


def stress_correction_factor(index: FloatArray, correction: str = "wahl") -> FloatArray:
    r"""The chosen stress-correction factor: ``"wahl"``, ``"bergstrasser"`` or ``"none"``.

    .. math::
        k = k_W(w) \;\text{or}\; \frac{w + 0.5}{w - 0.75} \;\text{or}\; 1

    Parameters
    ----------
    index : float
        Spring index w = D/d, [-]
    correction : str, optional
        Which factor; ``"none"`` gives 1 (the uncorrected τ EN 13906-1 checks
        for static load), [-]

    Returns
    -------
    factor : float
        Stress-correction factor, [-]

    Notes
    -----
    EN 13906-1 (Bergsträsser) or Wahl (1963).

    Examples
    --------
    >>> stress_correction_factor(6.0, "none")
    1.0
    """
    if correction == "none":
        return _out(np.ones_like(np.asarray(index, dtype=float)))
    try:
        return CORRECTIONS[correction](index)
    except KeyError:
        msg = f"correction must be wahl, bergstrasser or none, not {correction!r}"
        raise ValueError(msg) from None


def helical_shear_stress(
    force: FloatArray,
    mean_diameter: FloatArray,
    wire_diameter: FloatArray,
    correction: str = "wahl",
) -> FloatArray:
    r"""Shear stress in the wire of a helical compression spring carrying ``force``.

    .. math::
        \tau_k = k \, \frac{8 F D}{\pi d^3}

    Parameters
    ----------
    force : float
        Spring force F, [N]
    mean_diameter : float
        Mean coil diameter D, [m]
    wire_diameter : float
        Wire diameter d, [m]
    correction : str, optional
        ``"wahl"`` (default), ``"bergstrasser"`` or ``"none"``, [-]

    Returns
    -------
    stress : float
        Shear stress at the inner fibre, [Pa]

    Notes
    -----
    EN 13906-1, shear stress and corrected shear stress.

    Examples
    --------
    >>> round(helical_shear_stress(1250.0, 0.042, 0.007) / 1e6, 1)
    488.2
    """
    d = np.asarray(wire_diameter, dtype=float)
    dm = np.asarray(mean_diameter, dtype=float)
    k = stress_correction_factor(dm / d, correction)
    return _out(k * 8.0 * np.asarray(force) * dm / (np.pi * d**3))


def solid_length(
    wire_diameter: FloatArray, active_coils: FloatArray, ground_ends: bool = True
) -> FloatArray:
    r"""Solid length of a cold-coiled spring with closed ends (EN 13906-1).

    .. math::
        L_c = n_t \, d \;\text{(ground)}, \qquad L_c = (n_t + 1.5)\, d
        \;\text{(not ground)}, \qquad n_t = n + 2

    Parameters
    ----------
    wire_diameter : float
        Wire diameter d, [m]
    active_coils : float
        Active coils n, [-]
    ground_ends : bool, optional
        Closed and ground ends (default) or closed, not ground

    Returns
    -------
    length : float
        Solid length L_c, [m]

    Notes
    -----
    EN 13906-1, solid length, with one inactive closed coil at each end
    (n_t = n + 2), the usual cold-coiled form.

    Examples
    --------
    >>> round(solid_length(0.007, 8) * 1e3, 3)
    70.0
    """
    total = np.asarray(active_coils) + 2.0
    extra = 0.0 if ground_ends else 1.5
    return _out((total + extra) * np.asarray(wire_diameter))


def minimum_gap_sum(
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
    dynamic: bool = False,
) -> FloatArray:
    r"""Minimum sum of the gaps between active coils at the largest working force.

    .. math::
        S_a = \left(0.0015 \frac{D^2}{d} + 0.1 d\right) n \quad
        (\times 1.5 \text{ under dynamic load})

    Parameters
    ----------
    wire_diameter : float
        Wire diameter d, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    active_coils : float
        Active coils n, [-]
    dynamic : bool, optional
        Dynamic loading (1.5 times the static clearance)

    Returns
    -------
    clearance : float
        S_a; the spring at its largest working force must be at least
        L_c + S_a long, [m]

    Notes
    -----
    EN 13906-1, minimum clearance between active coils (printed for mm; the
    coefficients are dimensionless, so it holds in metres unchanged).

    Examples
    --------
    >>> round(minimum_gap_sum(0.004, 0.045, 5) * 1e3, 4)
    5.7969
    """
    d = np.asarray(wire_diameter, dtype=float)
    dm = np.asarray(mean_diameter, dtype=float)
    # the coefficient 0.0015 is dimensionless: the form holds in mm and in m alike
    sa = (0.0015 * dm**2 / d + 0.1 * d) * np.asarray(active_coils)
    return _out(sa * (1.5 if dynamic else 1.0))


#: Seating coefficient ν of EN 13906-1 (buckling), by end condition.
SEATING_COEFFICIENTS = {
    "fixed_free": 2.0,
    "hinged_hinged": 1.0,
    "fixed_hinged": 0.7,
    "fixed_fixed": 0.5,
}


def buckling_deflection(
    free_length: FloatArray,
    mean_diameter: FloatArray,
    seating_coefficient: FloatArray,
    shear_modulus: FloatArray,
    elastic_modulus: FloatArray,
) -> FloatArray:
    r"""Deflection at which a helical compression spring buckles (EN 13906-1).

    .. math::
        s_K = L_0 \frac{0.5}{1 - G/E}\left[1 - \sqrt{1 - \frac{1 - G/E}{0.5 + G/E}
              \left(\frac{\pi D}{\nu L_0}\right)^2}\right]

    Parameters
    ----------
    free_length : float
        Free (unloaded) length L_0, [m]
    mean_diameter : float
        Mean coil diameter D, [m]
    seating_coefficient : float
        ν: 2 one end free, 1 both ends hinged, 0.7 one fixed one hinged,
        0.5 both fixed (parallel guided ends), [-]
    shear_modulus : float
        G, [Pa]
    elastic_modulus : float
        E, [Pa]

    Returns
    -------
    deflection : float
        s_K; inf where the root is imaginary (the spring cannot buckle), [m]

    Notes
    -----
    EN 13906-1, buckling. A spring guided on a mandrel or in a sleeve does not
    buckle; the formula is for a free spring.

    Examples
    --------
    >>> round(buckling_deflection(0.2, 0.02, 2.0, 81.5e9, 206e9) * 1e3, 3)
    1.383
    >>> buckling_deflection(0.05, 0.045, 0.5, 81.5e9, 206e9)
    inf
    """
    ratio = np.asarray(shear_modulus) / np.asarray(elastic_modulus)
    l0 = np.asarray(free_length, dtype=float)
    slender = np.pi * np.asarray(mean_diameter) / (np.asarray(seating_coefficient) * l0)
    root = 1.0 - (1.0 - ratio) / (0.5 + ratio) * slender**2
    with np.errstate(invalid="ignore"):
        s_k = l0 * 0.5 / (1.0 - ratio) * (1.0 - np.sqrt(np.where(root >= 0.0, root, 0.0)))
    return _out(np.where(root >= 0.0, s_k, np.inf))


def helical_natural_frequency(
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    active_coils: FloatArray,
    shear_modulus: FloatArray,
    density: FloatArray,
) -> FloatArray:
    r"""First natural frequency of a spring held between two parallel plates.

    .. math::
        f_e = \frac{d}{2 \pi n D^2} \sqrt{\frac{G}{2 \rho}}

    Parameters
    ----------
    wire_diameter : float
        d, [m]
    mean_diameter : float
        D, [m]
    active_coils : float
        n, [-]
    shear_modulus : float
        G, [Pa]
    density : float
        ρ of the wire, [kg/m^3]

    Returns
    -------
    frequency : float
        f_e, [Hz]

    Notes
    -----
    EN 13906-1, natural frequency: f_e = 3.56·10³ d/(n D²)·√(G/ρ) with d, D in
    mm, G in N/mm², ρ in kg/dm³, the same relation (half the frequency of the
    active coils' mass on the rate R, fixed-fixed surge).

    Examples
    --------
    >>> round(helical_natural_frequency(0.004, 0.045, 5, 81.5e9, 7850.0), 1)
    143.3
    """
    d = np.asarray(wire_diameter, dtype=float)
    return _out(
        d
        / (2.0 * np.pi * np.asarray(active_coils) * np.asarray(mean_diameter) ** 2)
        * np.sqrt(np.asarray(shear_modulus) / (2.0 * np.asarray(density)))
    )


# --------------------------------------------------------------------------
# Materials and standard wire sizes
# --------------------------------------------------------------------------


class SpringMaterial:
    """A spring wire: moduli, density and minimum tensile strength by diameter."""

    def __init__(
        self,
        name: str,
        standard: str,
        shear_modulus: float,
        elastic_modulus: float,
        density: float,
        strength: tuple[tuple[float, float], ...],
    ) -> None:
        self.name = name
        self.standard = standard
        self.shear_modulus = shear_modulus
        self.elastic_modulus = elastic_modulus
        self.density = density
        #: (largest wire diameter of the row [mm], minimum R_m [MPa]), ascending.
        self.strength = strength
        # the table as :func:`tensile_strength` reads it: each row's top diameter with
        # a 1e-9 tolerance [mm] (the last row open-ended: beyond it is refused by the
        # range), its R_m [Pa], and the diameters it covers [mm]
        self.row_tops = np.array([upper * (1 + 1e-9) for upper, _ in strength[:-1]] + [np.inf])
        self.row_strengths = np.array([rm * 1e6 for _, rm in strength])
        lo, hi = self.diameter_range
        self.covered_mm = (lo * 1e3 * (1 - 1e-9) - 1.0, hi * 1e3 * (1 + 1e-9))

    @property
    def diameter_range(self) -> tuple[float, float]:
        """Smallest and largest tabulated wire diameter, [m]."""
        return self.strength[0][0] * 1e-3, self.strength[-1][0] * 1e-3


# EN 10270-1, grades SH and DH (same strength), minimum of each row's range.
# Checked against a public transcription of the standard's table for d = 0.30,
# 0.32, 0.34 mm (2660, 2640, 2610 MPa); the SM grade's full table was checked
# against another and runs 200-290 MPa below these rows at every diameter, as
# the standard's grades do. The other rows are transcribed, not re-checked here.
_EN10270_1_SH_DH = (
    (0.30, 2660.0),
    (0.32, 2640.0),
    (0.34, 2610.0),
    (0.40, 2560.0),
    (0.50, 2480.0),
    (0.60, 2410.0),
    (0.70, 2350.0),
    (0.80, 2310.0),
    (0.90, 2270.0),
    (1.00, 2230.0),
    (1.20, 2170.0),
    (1.40, 2100.0),
    (1.60, 2050.0),
    (1.80, 2000.0),
    (2.00, 1980.0),
    (2.50, 1890.0),
    (3.00, 1840.0),
    (3.50, 1780.0),
    (4.00, 1740.0),
    (4.50, 1690.0),
    (5.00, 1670.0),
    (6.00, 1590.0),
    (7.00, 1540.0),
    (8.00, 1480.0),
    (9.00, 1440.0),
    (10.00, 1400.0),
    (12.00, 1340.0),
    (14.00, 1290.0),
    (16.00, 1250.0),
    (18.00, 1210.0),
    (20.00, 1170.0),
)

# EN 10270-3, X10CrNi18-8 (1.4310), grade NS, minimum of each row's range
# (transcribed; the standard covers d <= 10 mm).
_EN10270_3_14310 = (
    (0.20, 2200.0),
    (0.30, 2150.0),
    (0.40, 2100.0),
    (0.50, 2050.0),
    (0.65, 2000.0),
    (0.80, 1950.0),
    (1.00, 1900.0),
    (1.25, 1850.0),
    (1.50, 1800.0),
    (1.75, 1750.0),
    (2.00, 1700.0),
    (2.50, 1650.0),
    (3.00, 1600.0),
    (3.50, 1550.0),
    (4.25, 1500.0),
    (5.00, 1450.0),
    (6.00, 1400.0),
    (7.00, 1350.0),
    (8.50, 1300.0),
    (10.00, 1250.0),
)

#: Spring wire materials by name. Moduli and densities: EN 13906-1 reference values.
MATERIALS: dict[str, SpringMaterial] = {
    m.name: m
    for m in (
        SpringMaterial(
            "EN10270-1-SH", "EN 10270-1 grade SH", 81.5e9, 206e9, 7850.0, _EN10270_1_SH_DH
        ),
        SpringMaterial(
            "EN10270-1-DH", "EN 10270-1 grade DH", 81.5e9, 206e9, 7850.0, _EN10270_1_SH_DH
        ),
        SpringMaterial(
            "1.4310", "EN 10270-3 X10CrNi18-8 (1.4310) NS", 70e9, 185e9, 7900.0, _EN10270_3_14310
        ),
    )
}


def _material(name: str) -> SpringMaterial:
    try:
        return MATERIALS[name]
    except KeyError:
        raise InputOutOfRange(
            f"spring material {name!r} is not tabulated; use one of {sorted(MATERIALS)}",
            field="spring_material",
        ) from None


def tensile_strength(material: str, wire_diameter: Any) -> Any:
    r"""Minimum tensile strength R_m of a spring wire of diameter d.

    .. math::
        R_m = R_{m,min}(d_j), \quad d_j = \min\{d_k \ge d\}

    Parameters
    ----------
    material : str
        ``"EN10270-1-SH"``, ``"EN10270-1-DH"`` or ``"1.4310"``, [-]
    wire_diameter : float or array
        Wire diameter d, [m]

    Returns
    -------
    strength : float or array
        Minimum R_m of the row covering d: the next tabulated diameter at or
        above d, the lower (safe) side of the steps, [Pa]

    Notes
    -----
    EN 10270-1 (SH, DH) and EN 10270-3 (1.4310) tables, as transcribed in
    this module; the row is the first whose upper diameter times 1 + 1e-9 is
    at or above d in mm (a binary search, so a design study looks a whole
    column up at once). A diameter outside the table is refused: a float
    raises InputOutOfRange naming it, an array is NaN there.

    Examples
    --------
    >>> tensile_strength("EN10270-1-DH", 0.004) / 1e6
    1740.0
    >>> tensile_strength("EN10270-1-SH", 0.0042) / 1e6
    1690.0
    >>> tensile_strength("EN10270-1-DH", np.array([0.004, 0.0042, 0.03])) / 1e6
    array([1740., 1690.,   nan])
    """
    m = _material(material)
    lo, hi = m.covered_mm
    d_mm = np.multiply(wire_diameter, 1e3)
    row = np.searchsorted(m.row_tops, d_mm, side="left")
    inside = (lo <= d_mm) & (d_mm <= hi)
    if np.ndim(d_mm) == 0:
        if not inside:
            raise InputOutOfRange(
                f"wire diameter {float(d_mm):.4g} mm is outside the {m.standard} table "
                f"(up to {m.strength[-1][0]:g} mm)",
                field="spring_wire_diameter",
            )
        return float(m.row_strengths[row])
    return _out(np.where(inside, m.row_strengths[row], np.nan))


def permissible_shear_stress(material: str, wire_diameter: Any) -> Any:
    r"""Permissible static shear stress of a cold-coiled spring (EN 13906-1).

    .. math::
        \tau_{zul} = 0.5 \, R_m(d)

    Parameters
    ----------
    material : str
        Material name, as in :func:`tensile_strength`, [-]
    wire_diameter : float
        d, [m]

    Returns
    -------
    stress : float
        τ_zul, [Pa]

    Notes
    -----
    EN 13906-1, permissible shear stress at solid length for cold-coiled
    springs of patented drawn and stainless wire: 0.5 R_m. The standard
    compares the *uncorrected* τ with it for static load; the clutch models
    compare the corrected τ_k, which is stricter (every slip cycles the
    spring).

    Examples
    --------
    >>> permissible_shear_stress("EN10270-1-DH", 0.004) / 1e6
    870.0
    """
    return 0.5 * tensile_strength(material, wire_diameter)


#: Preferred wire diameters, [mm] (EN 10270-1 sizes; the same R'20-like series
#: spring makers stock).
STANDARD_WIRE_DIAMETERS: tuple[float, ...] = (
    0.30, 0.32, 0.34, 0.36, 0.38, 0.40, 0.43, 0.45, 0.48, 0.50, 0.53, 0.56, 0.60, 0.63,
    0.65, 0.70, 0.75, 0.80, 0.85, 0.90, 0.95, 1.00, 1.05, 1.10, 1.20, 1.25, 1.30, 1.40,
    1.50, 1.60, 1.70, 1.80, 1.90, 2.00, 2.10, 2.25, 2.40, 2.50, 2.60, 2.80, 3.00, 3.20,
    3.40, 3.60, 3.80, 4.00, 4.25, 4.50, 4.75, 5.00, 5.30, 5.60, 6.00, 6.30, 6.50, 7.00,
    7.50, 8.00, 8.50, 9.00, 9.50, 10.00, 10.50, 11.00, 12.00, 12.50, 13.00, 14.00, 15.00,
    16.00, 17.00, 18.00, 19.00, 20.00,
)  # fmt: skip


def nearest_standard_wire(wire_diameter: float) -> tuple[float, bool]:
    r"""The preferred wire diameter nearest to d, and whether d is one.

    .. math::
        d^* = \arg\min_{d_k} |d_k - d|

    Parameters
    ----------
    wire_diameter : float
        d, [m]

    Returns
    -------
    nearest : float
        Nearest preferred diameter, [m]
    standard : bool
        True when d is a preferred size (within 0.1 µm), [-]

    Notes
    -----
    Preferred sizes of EN 10270-1 (``STANDARD_WIRE_DIAMETERS``).

    Examples
    --------
    >>> nearest_standard_wire(0.004)
    (0.004, True)
    >>> nearest_standard_wire(0.0041)
    (0.004, False)
    """
    d_mm = wire_diameter * 1e3
    sizes = STANDARD_WIRE_DIAMETERS
    if math.isfinite(d_mm):  # the two neighbours of d in the sorted sizes (ties: the smaller)
        i = bisect.bisect_left(sizes, d_mm)
        sizes = sizes[max(i - 1, 0) : i + 1]
    best = min(sizes, key=lambda s: abs(s - d_mm))
    return best * 1e-3, abs(best - d_mm) < 1e-4


# --------------------------------------------------------------------------
# Disc springs, DIN EN 16983 (Almen and László)
# --------------------------------------------------------------------------


def disc_factors(
    outer_diameter: FloatArray, inner_diameter: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray]:
    r"""The factors K1, K2, K3 of a disc spring of diameter ratio δ = De/Di.

    .. math::
        K_1 = \frac{1}{\pi}\frac{\left(\frac{\delta - 1}{\delta}\right)^2}
              {\frac{\delta + 1}{\delta - 1} - \frac{2}{\ln\delta}}, \quad
        K_2 = \frac{6}{\pi}\frac{\frac{\delta - 1}{\ln\delta} - 1}{\ln\delta}, \quad
        K_3 = \frac{3}{\pi}\frac{\delta - 1}{\ln\delta}

    Parameters
    ----------
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di < De, [m]

    Returns
    -------
    K1 : float
        Force factor, [-]
    K2 : float
        Bending-stress factor, [-]
    K3 : float
        Membrane-stress factor, [-]

    Notes
    -----
    DIN EN 16983 (formerly DIN 2092), after Almen and László (1936).

    Examples
    --------
    >>> [round(k, 3) for k in disc_factors(0.040, 0.0204)]
    [0.686, 1.211, 1.363]
    """
    delta = np.asarray(outer_diameter, dtype=float) / np.asarray(inner_diameter, dtype=float)
    ln = np.log(delta)
    k1 = ((delta - 1.0) / delta) ** 2 / ((delta + 1.0) / (delta - 1.0) - 2.0 / ln) / np.pi
    k2 = 6.0 / np.pi * ((delta - 1.0) / ln - 1.0) / ln
    k3 = 3.0 / np.pi * (delta - 1.0) / ln
    return _out(k1), _out(k2), _out(k3)


def _disc_scale(
    outer_diameter: Any, thickness: Any, k1: Any, elastic_modulus: Any, poisson: Any
) -> Any:
    return (
        4.0
        * np.asarray(elastic_modulus)
        / (1.0 - np.asarray(poisson) ** 2)
        / (np.asarray(k1) * np.asarray(outer_diameter) ** 2)
    )


def disc_force(
    deflection: FloatArray,
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    thickness: FloatArray,
    cone_height: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
    k4: FloatArray = 1.0,
) -> FloatArray:
    r"""Force of one disc spring deflected by s (Almen–László, DIN EN 16983).

    .. math::
        F = \frac{4E}{1 - \mu^2}\frac{t^4}{K_1 D_e^2} K_4^2 \frac{s}{t}
            \left[K_4^2\left(\frac{h_0}{t} - \frac{s}{t}\right)
            \left(\frac{h_0}{t} - \frac{s}{2t}\right) + 1\right]

    Parameters
    ----------
    deflection : float
        s, from the free state; s = h0 is flat, [m]
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    thickness : float
        t, [m]
    cone_height : float
        h0, free cone height (free height l0 = t + h0), [m]
    elastic_modulus : float, optional
        E, 206 GPa for spring steel, [Pa]
    poisson : float, optional
        μ, [-]
    k4 : float, optional
        K4, 1 for discs without contact flats (groups 1 and 2), [-]

    Returns
    -------
    force : float
        F, [N]

    Notes
    -----
    DIN EN 16983, force of a single disc. For h0/t > √2 (K4 = 1) the force
    falls between its maximum and its minimum (:func:`disc_falling_region`).

    Examples
    --------
    >>> round(disc_force(0.000675, 0.040, 0.0204, 0.00225, 0.0009))
    6500
    """
    law = disc_law(
        outer_diameter, inner_diameter, thickness, cone_height, elastic_modulus, poisson, k4
    )
    return disc_force_of(law, deflection)


class DiscLaw(NamedTuple):
    """A disc's constants of :func:`disc_force` and :func:`disc_rate` (:func:`disc_law`)."""

    thickness: Any
    #: h0/t
    height_ratio: Any
    #: K4²
    k4_squared: Any
    #: 4E/(1 − μ²) t⁴/(K1 De²) K4², the force's factor
    force_scale: Any
    #: 4E/(1 − μ²) t³/(K1 De²) K4², the rate's factor
    rate_scale: Any


def disc_law(
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    thickness: FloatArray,
    cone_height: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
    k4: FloatArray = 1.0,
) -> DiscLaw:
    """What :func:`disc_force` and :func:`disc_rate` compute before the deflection, once
    (for a stack evaluated at many deflections, in the same order: the same floats):
    4E/(1 − μ²) t⁴/(K1 De²) K4² and the same with t³, h0/t and K4² (a helper of their
    equations, DIN EN 16983, which their docstrings give).

    Parameters
    ----------
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    thickness : float
        t, [m]
    cone_height : float
        h0, [m]
    elastic_modulus : float, optional
        E, [Pa]
    poisson : float, optional
        μ, [-]
    k4 : float, optional
        K4, [-]

    Returns
    -------
    law : DiscLaw
        t [m], h0/t [-], K4² [-], the force's factor [N], the rate's factor [N/m]

    Examples
    --------
    >>> law = disc_law(0.040, 0.0204, 0.00225, 0.0009)
    >>> round(float(law.height_ratio), 6), round(float(disc_force_of(law, 0.000675)))
    (0.4, 6500)
    """
    k1, _, _ = disc_factors(outer_diameter, inner_diameter)
    t = np.asarray(thickness, dtype=float)
    a = np.asarray(cone_height, dtype=float) / t
    k4s = np.asarray(k4, dtype=float) ** 2
    scale = _disc_scale(outer_diameter, t, k1, elastic_modulus, poisson)
    return DiscLaw(t, a, k4s, scale * t**4 * k4s, scale * t**3 * k4s)


def disc_force_of(law: DiscLaw, deflection: FloatArray) -> FloatArray:
    """Force of one disc spring deflected by s, from its :func:`disc_law`: the equation
    of :func:`disc_force` (DIN EN 16983), which is this of the disc's law (its doctests
    hold the numbers).

    Parameters
    ----------
    law : DiscLaw
        The disc's :func:`disc_law`
    deflection : float
        s, from the free state, [m]

    Returns
    -------
    force : float
        F, [N]
    """
    u = np.asarray(deflection, dtype=float) / law.thickness
    a, k4s = law.height_ratio, law.k4_squared
    return _out(law.force_scale * u * (k4s * (a - u) * (a - u / 2.0) + 1.0))


def disc_rate_of(law: DiscLaw, deflection: FloatArray) -> FloatArray:
    """Rate dF/ds of one disc spring deflected by s, from its :func:`disc_law`: the
    equation of :func:`disc_rate` (DIN EN 16983), which is this of the disc's law (its
    doctests hold the numbers).

    Parameters
    ----------
    law : DiscLaw
        The disc's :func:`disc_law`
    deflection : float
        s, from the free state, [m]

    Returns
    -------
    rate : float
        dF/ds, [N/m]
    """
    u = np.asarray(deflection, dtype=float) / law.thickness
    a, k4s = law.height_ratio, law.k4_squared
    return _out(law.rate_scale * (k4s * (a * a - 3.0 * a * u + 1.5 * u * u) + 1.0))


def disc_rate(
    deflection: FloatArray,
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    thickness: FloatArray,
    cone_height: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
    k4: FloatArray = 1.0,
) -> FloatArray:
    r"""Rate dF/ds of one disc spring deflected by s (Almen–László, DIN EN 16983).

    .. math::
        R = \frac{dF}{ds} = \frac{4E}{1 - \mu^2}\frac{t^3}{K_1 D_e^2} K_4^2
            \left[K_4^2\left(\left(\frac{h_0}{t}\right)^2
            - 3\frac{h_0}{t}\frac{s}{t} + \frac{3}{2}\left(\frac{s}{t}\right)^2\right)
            + 1\right]

    Parameters
    ----------
    deflection : float
        s, from the free state, [m]
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    thickness : float
        t, [m]
    cone_height : float
        h0, [m]
    elastic_modulus : float, optional
        E, [Pa]
    poisson : float, optional
        μ, [-]
    k4 : float, optional
        K4, [-]

    Returns
    -------
    rate : float
        R, [N/m]; negative between the force's maximum and minimum
        (:func:`disc_falling_region`)

    Notes
    -----
    DIN EN 16983, the spring rate of a single disc: the derivative of
    :func:`disc_force` in s. Its zeros are :func:`disc_falling_region`'s.

    Examples
    --------
    At s = 0 the rate is (4E/(1 − μ²)) t³/(K1 De²) ((h0/t)² + 1); at the force's
    maximum it is zero; it matches a central difference of :func:`disc_force`:

    >>> k1 = disc_factors(0.040, 0.0204)[0]
    >>> hand = 4 * 206e9 / (1 - 0.3**2) * 0.001**3 / (k1 * 0.040**2) * (2.0**2 + 1)
    >>> round(float(disc_rate(0.0, 0.040, 0.0204, 0.001, 0.002) / hand), 12)
    1.0
    >>> top = disc_falling_region(0.001, 0.002)[0]
    >>> abs(float(disc_rate(top, 0.040, 0.0204, 0.001, 0.002))) < 1e-6
    True
    >>> h = 1e-7
    >>> diff = (disc_force(6e-4 + h, 0.040, 0.0204, 0.001, 0.002)
    ...         - disc_force(6e-4 - h, 0.040, 0.0204, 0.001, 0.002)) / (2 * h)
    >>> round(float(disc_rate(6e-4, 0.040, 0.0204, 0.001, 0.002) / diff), 6)
    1.0
    """
    law = disc_law(
        outer_diameter, inner_diameter, thickness, cone_height, elastic_modulus, poisson, k4
    )
    return disc_rate_of(law, deflection)


def disc_force_flat(
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    thickness: FloatArray,
    cone_height: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
    k4: FloatArray = 1.0,
) -> FloatArray:
    r"""Force of a disc spring pressed flat (s = h0), closed form.

    .. math::
        F_c = \frac{4E}{1 - \mu^2}\frac{t^3 h_0}{K_1 D_e^2} K_4^2

    Parameters
    ----------
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    thickness : float
        t, [m]
    cone_height : float
        h0, [m]
    elastic_modulus : float, optional
        E, [Pa]
    poisson : float, optional
        μ, [-]
    k4 : float, optional
        K4, [-]

    Returns
    -------
    force : float
        F_c, [N]

    Notes
    -----
    DIN EN 16983, force at the flat position: :func:`disc_force` at s = h0.

    Examples
    --------
    >>> round(disc_force_flat(0.040, 0.0204, 0.00225, 0.0009))
    8456
    """
    k1, _, _ = disc_factors(outer_diameter, inner_diameter)
    t = np.asarray(thickness, dtype=float)
    scale = _disc_scale(outer_diameter, t, k1, elastic_modulus, poisson)
    return _out(scale * t**3 * np.asarray(cone_height) * np.asarray(k4) ** 2)


def disc_stresses(
    deflection: FloatArray,
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    thickness: FloatArray,
    cone_height: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
    k4: FloatArray = 1.0,
) -> dict[str, FloatArray]:
    r"""Stresses of a disc spring at the points OM, I, II, III and IV.

    .. math::
        \sigma_{OM} = -\frac{4E}{1 - \mu^2}\frac{t^2}{K_1 D_e^2} K_4 \frac{s}{t}
                      \frac{3}{\pi}, \\
        \sigma_{I,II} = -\frac{4E}{1 - \mu^2}\frac{t^2}{K_1 D_e^2} K_4 \frac{s}{t}
            \left[K_4 K_2\left(\frac{h_0}{t} - \frac{s}{2t}\right) \pm K_3\right], \\
        \sigma_{III,IV} = -\frac{4E}{1 - \mu^2}\frac{t^2}{K_1 D_e^2} K_4 \frac{s}{t}
            \frac{1}{\delta}\left[K_4 (K_2 - 2K_3)\left(\frac{h_0}{t}
            - \frac{s}{2t}\right) \mp K_3\right]

    Parameters
    ----------
    deflection : float
        s, [m]
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    thickness : float
        t, [m]
    cone_height : float
        h0, [m]
    elastic_modulus : float, optional
        E, [Pa]
    poisson : float, optional
        μ, [-]
    k4 : float, optional
        K4, [-]

    Returns
    -------
    stresses : dict
        ``"OM"``, ``"I"``, ``"II"``, ``"III"``, ``"IV"``; negative is
        compression. OM (upper inner edge, the static check), II and III
        (lower side, tension, the fatigue points), [Pa]

    Notes
    -----
    DIN EN 16983, nominal stresses (no residual stresses of presetting or shot
    peening). Point I is the upper inner edge, II the lower inner edge, III the
    lower outer edge, IV the upper outer edge.

    Examples
    --------
    >>> s = disc_stresses(0.000675, 0.040, 0.0204, 0.00225, 0.0009)
    >>> round(s["OM"] / 1e6), round(s["II"] / 1e6), round(s["III"] / 1e6)
    (-1196, 1328, 1112)
    """
    k1, k2, k3 = disc_factors(outer_diameter, inner_diameter)
    delta = np.asarray(outer_diameter, dtype=float) / np.asarray(inner_diameter, dtype=float)
    t = np.asarray(thickness, dtype=float)
    u = np.asarray(deflection, dtype=float) / t
    a = np.asarray(cone_height, dtype=float) / t
    k4_ = np.asarray(k4, dtype=float)
    base = _disc_stress_base(deflection, outer_diameter, t, k1, elastic_modulus, poisson, k4)
    bend = k4_ * np.asarray(k2) * (a - u / 2.0)
    outer = k4_ * (np.asarray(k2) - 2.0 * np.asarray(k3)) * (a - u / 2.0)
    return {
        "OM": _out(_om(base)),
        "I": _out(base * (bend + k3)),
        "II": _out(base * (bend - k3)),
        "III": _out(base / delta * (outer - k3)),
        "IV": _out(base / delta * (outer + k3)),
    }


def _disc_stress_base(
    deflection: Any,
    outer_diameter: Any,
    thickness: Any,
    k1: Any,
    elastic_modulus: Any,
    poisson: Any,
    k4: Any,
) -> Any:
    """−4E/(1 − μ²) t²/(K1 De²) K4 s/t, the factor every disc stress has
    (:func:`disc_stresses`)."""
    t = np.asarray(thickness, dtype=float)
    u = np.asarray(deflection, dtype=float) / t
    scale = _disc_scale(outer_diameter, t, k1, elastic_modulus, poisson)
    return -scale * t**2 * np.asarray(k4, dtype=float) * u


def _om(base: Any) -> Any:
    """σ_OM from :func:`_disc_stress_base`."""
    return base * 3.0 / np.pi


def disc_stress_om(
    deflection: FloatArray,
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    thickness: FloatArray,
    cone_height: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
    k4: FloatArray = 1.0,
) -> FloatArray:
    r"""Stress of a disc spring at the point OM alone (the static check), DIN EN 16983.

    .. math::
        \sigma_{OM} = -\frac{4E}{1 - \mu^2}\frac{t^2}{K_1 D_e^2} K_4 \frac{s}{t}
                      \frac{3}{\pi}

    The same floats as :func:`disc_stresses`' ``"OM"`` without the other four points
    (``cone_height`` is taken, and not needed, for the same arguments).

    Parameters
    ----------
    deflection : float
        s, [m]
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    thickness : float
        t, [m]
    cone_height : float
        h0, [m]
    elastic_modulus : float, optional
        E, [Pa]
    poisson : float, optional
        μ, [-]
    k4 : float, optional
        K4, [-]

    Returns
    -------
    stress : float
        σ_OM, negative is compression, [Pa]

    Examples
    --------
    >>> round(disc_stress_om(0.000675, 0.040, 0.0204, 0.00225, 0.0009) / 1e6)
    -1196
    """
    k1, _, _ = disc_factors(outer_diameter, inner_diameter)
    base = _disc_stress_base(
        deflection, outer_diameter, thickness, k1, elastic_modulus, poisson, k4
    )
    return _out(_om(base))


def disc_falling_region(thickness: Any, cone_height: Any, k4: Any = 1.0) -> tuple[Any, Any]:
    r"""Deflections between which a disc spring's force falls (negative rate).

    .. math::
        \frac{s}{t} = \frac{h_0}{t} \mp \frac{\sqrt{3 (h_0/t)^2 - 6/K_4^2}}{3}

    Parameters
    ----------
    thickness : float
        t, [m]
    cone_height : float
        h0, [m]
    k4 : float, optional
        K4, [-]

    Returns
    -------
    region : tuple of float or array
        (s at the force maximum, s at the force minimum), [m]; NaN where
        h0/t ≤ √2/K4 and the force rises everywhere. All arguments may be
        floats or numpy arrays.

    Notes
    -----
    Zeros of dF/ds of :func:`disc_force`: 1.5u² − 3au + a² + 1/K4² = 0 with
    u = s/t, a = h0/t. The minimum lies beyond flat (s > h0); a disc is
    usually not pressed past flat, so only [s_max, h0] is reachable on its
    seat.

    Examples
    --------
    >>> lo, hi = disc_falling_region(0.001, 0.002)
    >>> round(lo * 1e3, 4), round(hi * 1e3, 4)
    (1.1835, 2.8165)
    >>> disc_falling_region(0.002, 0.002)
    (nan, nan)
    """
    a = np.asarray(cone_height, dtype=float) / thickness
    disc = 3.0 * a * a - 6.0 / (k4 * k4)
    half = np.sqrt(np.where(disc > 0.0, disc, np.nan)) / 3.0
    return _out((a - half) * thickness), _out((a + half) * thickness)


def stack_force(
    single_force: FloatArray,
    parallel: int = 1,
    friction_between: float = 0.0,
    friction_edge: float = 0.0,
    loading: bool = True,
) -> FloatArray:
    r"""Force of a stack: ``parallel`` discs nested in each pack, packs in series.

    .. math::
        F_{stack} = \frac{n F}{1 \mp w_M (n - 1) \mp w_R}

    Parameters
    ----------
    single_force : float
        Force F of one disc at the stack's per-disc deflection, [N]
    parallel : int, optional
        n discs nested in parallel in each pack, [-]
    friction_between : float, optional
        w_M, friction factor between nested discs (0.02…0.03 lubricated), [-]
    friction_edge : float, optional
        w_R, friction factor at the load edges (0.02…0.04), [-]
    loading : bool, optional
        Loading (minus signs, the force rises) or unloading (plus signs)

    Returns
    -------
    force : float
        Stack force, [N]

    Notes
    -----
    DIN EN 16983, stacks with friction. Discs in series carry the same force;
    the stack deflection is the number of packs in series times the per-disc
    deflection. Frictionless (w = 0) is the default.

    Examples
    --------
    >>> stack_force(1000.0, 2)
    2000.0
    >>> round(stack_force(1000.0, 2, 0.03, 0.02), 1)
    2105.3
    """
    sign = -1.0 if loading else 1.0
    n = float(parallel)
    denom = 1.0 + sign * (friction_between * (n - 1.0) + friction_edge)
    return _out(n * np.asarray(single_force) / denom)


def disc_thickness_for_flat_force(
    flat_force: FloatArray,
    outer_diameter: FloatArray,
    inner_diameter: FloatArray,
    height_ratio: FloatArray,
    elastic_modulus: FloatArray = 206e9,
    poisson: FloatArray = 0.3,
) -> FloatArray:
    r"""Thickness of a disc spring that is pressed flat by ``flat_force``.

    .. math::
        t = \left(\frac{F_c K_1 D_e^2 (1 - \mu^2)}{4 E \,(h_0/t)}\right)^{1/4}

    Parameters
    ----------
    flat_force : float
        Force F_c at which the disc is to be flat, [N]
    outer_diameter : float
        De, [m]
    inner_diameter : float
        Di, [m]
    height_ratio : float
        h0/t held fixed (0.4, 0.75, 1.3 for the series A, B, C of DIN EN 16983), [-]
    elastic_modulus : float, optional
        E, [Pa]
    poisson : float, optional
        μ, [-]

    Returns
    -------
    thickness : float
        t; the cone height is then h0 = (h0/t)·t, [m]

    Notes
    -----
    :func:`disc_force_flat` solved for t (K4 = 1): F_c = 4E/(1 − μ²)·t⁴(h0/t)/(K1 De²).

    Examples
    --------
    >>> round(disc_thickness_for_flat_force(8455.53, 0.040, 0.0204, 0.4) * 1e3, 4)
    2.25
    """
    k1, _, _ = disc_factors(outer_diameter, inner_diameter)
    t4 = (
        np.asarray(flat_force)
        * np.asarray(k1)
        * np.asarray(outer_diameter) ** 2
        * (1.0 - np.asarray(poisson) ** 2)
        / (4.0 * np.asarray(elastic_modulus) * np.asarray(height_ratio))
    )
    return _out(t4**0.25)


def disc_k4(
    thickness: FloatArray, reduced_thickness: FloatArray, free_height: FloatArray
) -> FloatArray:
    r"""Factor K4 of a disc spring with contact flats (group 3), DIN EN 16983.

    .. math::
        C_1 = \frac{(t'/t)^2}{\left(\frac{l_0}{4t} - \frac{t'}{t} + \frac34\right)
              \left(\frac{5 l_0}{8t} - \frac{t'}{t} + \frac38\right)}, \quad
        C_2 = \frac{C_1}{(t'/t)^3}\left[\frac{5}{32}\left(\frac{l_0}{t} - 1\right)^2
              + 1\right], \quad
        K_4 = \sqrt{-\frac{C_1}{2} + \sqrt{\left(\frac{C_1}{2}\right)^2 + C_2}}

    Parameters
    ----------
    thickness : float
        t, nominal thickness, [m]
    reduced_thickness : float
        t', thickness reduced for the contact flats (≈ 0.94…0.96 t), [m]
    free_height : float
        l0, free height of the disc (the same with and without flats), [m]

    Returns
    -------
    k4 : float
        K4; 1 for a disc without flats (t' = t), [-]

    Notes
    -----
    DIN EN 16983 (formerly DIN 2092), discs with contact flats: use t' for t and
    h0' = l0 − t' for h0 in :func:`disc_force` and :func:`disc_stresses`, with
    this K4.

    Examples
    --------
    >>> round(disc_k4(0.008, 0.008, 0.0106), 12)
    1.0
    >>> round(disc_k4(0.008, 0.0075, 0.0106), 4)
    1.0834
    """
    ratio = np.asarray(reduced_thickness, dtype=float) / np.asarray(thickness, dtype=float)
    l0_t = np.asarray(free_height, dtype=float) / np.asarray(thickness, dtype=float)
    c1 = ratio**2 / ((l0_t / 4.0 - ratio + 0.75) * (5.0 * l0_t / 8.0 - ratio + 0.375))
    c2 = c1 / ratio**3 * (5.0 / 32.0 * (l0_t - 1.0) ** 2 + 1.0)
    return _out(np.sqrt(-c1 / 2.0 + np.sqrt((c1 / 2.0) ** 2 + c2)))


def helical_mass(
    wire_diameter: FloatArray,
    mean_diameter: FloatArray,
    total_coils: FloatArray,
    density: FloatArray,
) -> FloatArray:
    r"""Mass of a helical spring's wire: its length π D n_t times its section.

    .. math::
        m = \rho \, \frac{\pi d^2}{4} \, \pi D n_t

    Parameters
    ----------
    wire_diameter : float
        d, [m]
    mean_diameter : float
        D, [m]
    total_coils : float
        n_t, active plus end coils, [-]
    density : float
        ρ of the wire, [kg/m^3]

    Returns
    -------
    mass : float
        m, [kg]

    Notes
    -----
    EN 13906-1, spring mass (the wire of the coils as a straight bar of length
    π D n_t; the grinding of the ends is neglected). All arguments may be
    floats or numpy arrays.

    Examples
    --------
    >>> round(helical_mass(0.004, 0.045, 7, 7850.0) * 1e3, 2)
    97.62
    """
    d = np.asarray(wire_diameter, dtype=float)
    return _out(
        np.asarray(density)
        * np.pi
        * d**2
        / 4.0
        * np.pi
        * np.asarray(mean_diameter)
        * np.asarray(total_coils)
    )
