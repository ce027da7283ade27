r"""The spring for a clutch setting: a helical compression spring found to EN 13906-1.

The clutch's duty comes from the clutch's own functions: the spring force at the
setting is the force that makes the balls start to move at the target torque
(:func:`engine.physics.clutch.spring_force_for_torque`, [001, eq. 1–3]); the stroke
is the balls' whole lift, up the flank and over the rim
(:func:`engine.physics.clutch.rim_rise`). The space is the pocket: the largest
outer diameter, the smallest inner diameter (the shaft) and the largest length of
the spring at the setting.

The procedure, as named steps:

1. :func:`clutch_duty`: F₁ at the setting and the stroke s_h.
2. :func:`candidate_grid`: every preferred wire d (EN 10270-1 sizes the material's
   table covers) against mean diameters D on a grid, 3 ≤ D/d ≤ 24 (a little wider
   than the check's 4…20, so that a near miss can still be named).
3. :func:`coils`: per candidate, the active coils n in half coils: the fewest that
   keep the corrected shear stress at full stroke within τ_zul ("thinnest"), or the
   most that leave EN 13906-1's minimum gap sum at full stroke ("margin"); never
   fewer than 2.
4. :func:`evaluate`: every candidate at once (numpy): rate, free length L₀ with the
   spring at the pocket's length at the setting (L₁ = L_set,max), stresses with
   Bergsträsser's factor at the setting and at full stroke against τ_zul = 0.5 R_m(d),
   solid length with S_a, buckling, the margin of every check.
5. :func:`choose`: among the springs that pass every check, the thinnest wire and of
   its springs the lightest (so a larger force never gets a thinner wire), or the one
   with the most stress margin at full stroke; where none passes, the limit that
   binds and the nearest spring that passes every other check.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import numpy.typing as npt

from ..core.errors import InputOutOfRange
from ..physics import springs as sp
from ..physics.clutch import riding_flank_angle, rim_rise, spring_force_for_torque

Array = npt.NDArray[np.float64]

#: Spring index range the design checks (EN 13906-1's range for cold-coiled springs).
INDEX_RANGE = (4.0, 20.0)
#: Spring index range of the candidate grid: wider than the check so near misses stay.
GRID_INDEX = (3.0, 24.0)
#: Fewest active coils EN 13906-1 admits.
MIN_ACTIVE_COILS = 2.0
#: Mean diameters on the grid per wire (a step of 0.1 mm or (D_max − D_min)/this).
MEAN_DIAMETER_STEPS = 400
OBJECTIVES = ("thinnest", "margin")
#: The checks, in the order they are reported; each margin is ≥ 0 where it passes.
CHECKS = (
    "spring_index",
    "outer_diameter",
    "inner_diameter",
    "stress_at_set",
    "stress_at_stroke",
    "coil_gaps",
    "buckling",
)


def clutch_duty(x: Mapping[str, Any]) -> tuple[Any, Any]:
    r"""Spring force at the setting and the stroke of a ball clutch, from its own functions.

    .. math::
        F_1 = \frac{2 T \tan(\alpha - \rho)}{D_0 \, s}, \qquad
        s_h = h + \frac{d_b}{2}\,(1 - \sin\alpha_{ride})

    Parameters
    ----------
    x : mapping
        The clutch inputs: ``target_torque`` [N*m], ``ball_circle_diameter`` [m],
        ``groove_angle`` [rad], ``ball_count``, ``load_factor``, ``flank_friction``,
        ``spring_arrangement``, ``driving_groove_angle`` [rad], ``flank_construction``,
        ``ball_diameter`` [m] and ``ball_lift`` h [m]; floats or numpy arrays

    Returns
    -------
    force, stroke : float
        F₁, the spring force that sets the zero-lift slipping torque to T [N], and s_h,
        the further compression while the balls climb the flank and roll over the
        rim [m]

    Notes
    -----
    [001, eq. 1–3] through :func:`engine.physics.clutch.spring_force_for_torque` (the
    function clutch.ball_setting's required_spring_force calls) and the rim of
    :func:`engine.physics.clutch.rim_rise` on the flank the ball rides.

    Examples
    --------
    >>> f, s = clutch_duty({"target_torque": 0.5, "ball_circle_diameter": 0.05,
    ...     "groove_angle": math.radians(45.0), "ball_count": 4, "load_factor": 0.85,
    ...     "flank_friction": 0.0, "spring_arrangement": "common",
    ...     "driving_groove_angle": None, "flank_construction": "free_ball",
    ...     "ball_diameter": 0.01, "ball_lift": 0.002})
    >>> round(f, 6), round(s * 1e3, 4)
    (20.0, 3.4645)
    """
    force = spring_force_for_torque(
        x["target_torque"],
        x["ball_circle_diameter"],
        x["groove_angle"],
        x["ball_count"],
        x["load_factor"],
        x["flank_friction"],
        x["spring_arrangement"],
        x["driving_groove_angle"],
        x["flank_construction"],
    )
    ride = riding_flank_angle(x["groove_angle"], x["driving_groove_angle"], x["flank_construction"])
    stroke = np.asarray(x["ball_lift"]) + np.asarray(rim_rise(x["ball_diameter"], ride))
    return force, float(stroke) if stroke.ndim == 0 else stroke


def candidate_grid(
    material: str, max_outer_diameter: float, min_inner_diameter: float
) -> tuple[Array, Array]:
    r"""Every preferred wire d against a grid of mean diameters D, flattened.

    .. math::
        D \in [D_{min}, D_{max}], \quad D_{min} = D_{i,min} + d_{min}, \quad
        D_{max} = D_{e,max} - d_{min}, \quad 3 \le D/d \le 24

    Parameters
    ----------
    material : str
        Wire material (its table bounds the wire sizes), [-]
    max_outer_diameter : float
        D_e,max, [m]
    min_inner_diameter : float
        D_i,min, 0 for none, [m]

    Returns
    -------
    wire, mean : ndarray
        d and D of every candidate, [m]

    Notes
    -----
    Wires: :data:`engine.physics.springs.STANDARD_WIRE_DIAMETERS` within the
    material's EN 10270 table. D: :data:`MEAN_DIAMETER_STEPS` steps or 0.1 mm,
    whichever is coarser. The space itself is checked by :func:`evaluate`, so a
    spring a little too wide stays a candidate to name when nothing fits.

    Examples
    --------
    >>> d, D = candidate_grid("EN10270-1-DH", 0.040, 0.020)
    >>> d.size == D.size, round(float(D.min()) * 1e3, 6), float((D / d).max()) <= 24.0
    (True, 20.3, True)
    """
    lo, hi = sp.MATERIALS[material].diameter_range
    wires = np.array([w * 1e-3 for w in sp.STANDARD_WIRE_DIAMETERS])
    wires = wires[(wires >= lo * (1 - 1e-9)) & (wires <= hi * (1 + 1e-9))]
    d_min = float(wires.min())
    d_lo = max(min_inner_diameter + d_min, GRID_INDEX[0] * d_min)
    d_hi = max_outer_diameter - d_min
    if d_hi <= d_lo:
        raise InputOutOfRange(
            f"max_outer_diameter {max_outer_diameter * 1e3:.4g} mm leaves no coil around "
            f"min_inner_diameter {min_inner_diameter * 1e3:.4g} mm with the thinnest wire "
            f"({d_min * 1e3:g} mm)",
            field="max_outer_diameter",
        )
    step = max(1e-4, (d_hi - d_lo) / MEAN_DIAMETER_STEPS)
    means = np.round(np.arange(d_lo, d_hi + 0.5 * step, step), 7)  # whole 0.1 µm
    wire, mean = (a.ravel() for a in np.meshgrid(wires, means, indexing="ij"))
    index = mean / wire
    keep = (index >= GRID_INDEX[0]) & (index <= GRID_INDEX[1])
    if not keep.any():
        raise InputOutOfRange(
            f"between min_inner_diameter {min_inner_diameter * 1e3:.4g} mm and "
            f"max_outer_diameter {max_outer_diameter * 1e3:.4g} mm no preferred wire "
            f"({wires.min() * 1e3:g}…{wires.max() * 1e3:g} mm) makes a coil of spring index "
            f"{GRID_INDEX[0]:g}…{GRID_INDEX[1]:g}",
            field="min_inner_diameter",
        )
    return wire[keep], mean[keep]


def _half_up(n: Array) -> Array:
    return np.ceil(2.0 * n - 1e-9) / 2.0


def _half_down(n: Array) -> Array:
    return np.floor(2.0 * n + 1e-9) / 2.0


def coils(
    wire: Array,
    mean: Array,
    force: float,
    stroke: float,
    set_length: float,
    material: str,
    objective: str = "thinnest",
    dynamic: bool = False,
) -> Array:
    r"""Active coils per candidate, in half coils, for the objective.

    .. math::
        n_\tau = \frac{G d^4 s_h}{8 D^3 (F_{zul} - F_1)}, \quad
        F_{zul} = \frac{\pi d^3 \tau_{zul}}{8 k D}; \qquad
        n_L = \frac{L_1 - s_h - 2d}{d + 0.0015 D^2/d + 0.1 d}

    Parameters
    ----------
    wire, mean : ndarray
        d and D of the candidates, [m]
    force : float
        F₁ at the setting, [N]
    stroke : float
        s_h, [m]
    set_length : float
        L₁, the spring's length at the setting, [m]
    material : str
        Wire material, [-]
    objective : {"thinnest", "margin"}
        Fewest coils that keep τ_k at full stroke within τ_zul (rounded up), or most
        coils that leave S_a at full stroke (rounded down), [-]
    dynamic : bool
        S_a × 1.5 (EN 13906-1, dynamic load)

    Returns
    -------
    n : ndarray
        Active coils, ≥ 2, [-]

    Notes
    -----
    EN 13906-1: F₂ = F₁ + R s_h ≤ F_zul with R = G d⁴/(8 D³ n) gives n ≥ n_τ (no n
    where F₁ ≥ F_zul already: the stress at the setting fails); L₂ = L₁ − s_h ≥
    L_c + S_a with L_c = (n + 2) d (closed, ground ends) gives n ≤ n_L. Where the
    fewest has no n_τ it takes n_L, and the other way round.

    Examples
    --------
    >>> n = coils(np.array([0.0045]), np.array([0.027]), 800.0, 0.004, 0.06, "EN10270-1-DH")
    >>> float(n[0])
    8.5
    """
    m = sp.MATERIALS[material]
    tau = sp.permissible_shear_stress(material, wire)
    k = sp.bergstrasser_factor(mean / wire)
    f_zul = np.pi * wire**3 * tau / (8.0 * k * mean)
    with np.errstate(divide="ignore", invalid="ignore"):
        n_tau = np.where(
            f_zul > force,
            m.shear_modulus * wire**4 * stroke / (8.0 * mean**3 * (f_zul - force)),
            np.inf,
        )
    gap = (0.0015 * mean**2 / wire + 0.1 * wire) * (1.5 if dynamic else 1.0)
    n_len = (set_length - stroke - 2.0 * wire) / (wire + gap)
    fewest = np.where(np.isfinite(n_tau), _half_up(n_tau), _half_down(n_len))
    most = np.where(n_len > 0.0, _half_down(n_len), _half_up(n_tau))
    n = fewest if objective == "thinnest" else most
    n = np.where(np.isfinite(n), n, MIN_ACTIVE_COILS)
    return np.maximum(n, MIN_ACTIVE_COILS)


def evaluate(
    wire: Any,
    mean: Any,
    active: Any,
    force: float,
    stroke: float,
    set_length: float,
    space: Mapping[str, Any],
) -> dict[str, Any]:
    r"""Every EN 13906-1 quantity and check margin of the candidates, all at once.

    .. math::
        R = \frac{G d^4}{8 D^3 n}, \; s_1 = \frac{F_1}{R}, \; F_2 = F_1 + R s_h, \;
        L_0 = L_1 + s_1, \; L_2 = L_1 - s_h, \\
        \tau_{k,i} = k \frac{8 F_i D}{\pi d^3}, \; k = \frac{w + 0.5}{w - 0.75}, \;
        L_c = (n + 2) d, \; S_a = \left(0.0015 \frac{D^2}{d} + 0.1 d\right) n

    Parameters
    ----------
    wire, mean, active : ndarray
        d [m], D [m], n [-] of the candidates
    force : float
        F₁ at the setting, [N]
    stroke : float
        s_h, [m]
    set_length : float
        L₁, [m]
    space : mapping
        ``max_outer_diameter``, ``min_inner_diameter`` [m], ``spring_material``,
        ``spring_seating``, ``dynamic_load``

    Returns
    -------
    values : dict
        The quantities (``rate``, ``free_length``, ``shear_stress_set``, …) and
        ``margin_<check>`` for each of :data:`CHECKS`: 1 − used/allowed, ≥ 0 passes

    Notes
    -----
    EN 13906-1 through :mod:`engine.physics.springs`: :func:`~engine.physics.springs.helical_rate`,
    :func:`~engine.physics.springs.helical_shear_stress` (Bergsträsser),
    :func:`~engine.physics.springs.permissible_shear_stress`,
    :func:`~engine.physics.springs.solid_length`,
    :func:`~engine.physics.springs.minimum_gap_sum`,
    :func:`~engine.physics.springs.buckling_deflection` (s₂ ≤ s_K; margin 1 where it
    cannot buckle), :func:`~engine.physics.springs.helical_mass`. Index margin
    min(w/4 − 1, 1 − w/20); outer 1 − (D + d)/D_e,max; inner 1 − D_i,min/(D − d).

    Examples
    --------
    >>> v = evaluate(0.0045, 0.027, 8.5, 800.0, 0.004, 0.06,
    ...     {"max_outer_diameter": 0.035, "min_inner_diameter": 0.02,
    ...      "spring_material": "EN10270-1-DH", "spring_seating": "fixed_fixed",
    ...      "dynamic_load": False})
    >>> round(v["rate"] / 1e3, 3), round(v["margin_stress_at_stroke"], 4)
    (24.969, 0.0052)
    """
    material = sp.MATERIALS[space["spring_material"]]
    d, dm, n = (np.asarray(a, dtype=float) for a in (wire, mean, active))
    rate = np.asarray(sp.helical_rate(material.shear_modulus, d, dm, n))
    s1 = force / rate
    f2 = force + rate * stroke
    free = set_length + s1
    l2 = set_length - stroke
    tau = np.asarray(sp.permissible_shear_stress(material.name, d))
    t1 = np.asarray(sp.helical_shear_stress(force, dm, d, "bergstrasser"))
    t2 = np.asarray(sp.helical_shear_stress(f2, dm, d, "bergstrasser"))
    solid = np.asarray(sp.solid_length(d, n))
    gaps = np.asarray(sp.minimum_gap_sum(d, dm, n, bool(space["dynamic_load"])))
    s_k = np.asarray(
        sp.buckling_deflection(
            free,
            dm,
            sp.SEATING_COEFFICIENTS[space["spring_seating"]],
            material.shear_modulus,
            material.elastic_modulus,
        )
    )
    w = dm / d
    lo, hi = INDEX_RANGE
    inner = float(space["min_inner_diameter"])
    with np.errstate(divide="ignore", invalid="ignore"):
        margins = {
            "spring_index": np.minimum(w / lo - 1.0, 1.0 - w / hi),
            "outer_diameter": 1.0 - (dm + d) / float(space["max_outer_diameter"]),
            "inner_diameter": 1.0 - inner / (dm - d),
            "stress_at_set": 1.0 - t1 / tau,
            "stress_at_stroke": 1.0 - t2 / tau,
            "coil_gaps": 1.0 - (solid + gaps) / l2,
            "buckling": np.where(np.isfinite(s_k), 1.0 - (s1 + stroke) / s_k, 1.0),
        }
    out: dict[str, Any] = {
        "wire_diameter": d,
        "mean_diameter": dm,
        "active_coils": n,
        "total_coils": n + 2.0,
        "rate": rate,
        "set_deflection": s1,
        "stroke_force": f2,
        "free_length": free,
        "stroke_length": l2 + 0.0 * d,
        "solid_length": solid,
        "gap_sum": gaps,
        "permissible_stress": tau,
        "shear_stress_set": t1,
        "shear_stress_stroke": t2,
        "buckling_deflection": s_k,
        "mass": np.asarray(sp.helical_mass(d, dm, n + 2.0, material.density)),
        **{f"margin_{c}": m for c, m in margins.items()},
    }
    return {k: float(v) if np.ndim(v) == 0 else v for k, v in out.items()}


def choose(
    values: Mapping[str, Array],
    objective: str,
    order: tuple[str, str] = ("wire_diameter", "mass"),
    most: str = "margin_stress_at_stroke",
) -> tuple[int, str, int]:
    r"""The spring to name, the limit that binds, and how many candidates pass.

    .. math::
        \text{pass}_j = \min_c m_{c,j} \ge 0; \quad
        j^* = \arg\min_{\text{pass}} (d, m) \;\text{or}\;
        \arg\max_{\text{pass}} m_{\tau,stroke}

    Parameters
    ----------
    values : mapping
        :func:`evaluate` of every candidate
    objective : {"thinnest", "margin"}
        Thinnest wire (then the lightest of its springs), or most stress margin at
        full stroke, [-]
    order : (str, str)
        The values "thinnest" ranks by, first then second (a disc pack: the fewest
        discs, then the smallest disc)
    most : str
        The margin "margin" maximises

    Returns
    -------
    index : int
        The chosen candidate
    binding : str
        The check with the smallest margin (where one passes) or the one it fails
    passing : int
        How many candidates pass every check

    Notes
    -----
    Where none passes: per check, the candidates that pass every *other* check,
    and among them the one that comes closest to passing this one; the check whose
    nearest spring comes closest binds. Where no candidate fails only one check,
    the candidate whose worst margin is least bad, and its worst check.

    Examples
    --------
    >>> v = {"wire_diameter": np.array([0.002, 0.002, 0.001]),
    ...      "mass": np.array([2.0, 1.0, 3.0]), "margin_stress_at_stroke":
    ...      np.array([0.3, -0.1, 0.2]), "margin_coil_gaps": np.array([0.1, 0.5, 0.4])}
    >>> choose(v, "thinnest"), choose(v, "margin")
    ((2, 'stress_at_stroke', 2), (0, 'coil_gaps', 2))
    """
    names = [k for k in values if k.startswith("margin_")]
    m = np.stack([np.asarray(values[k], dtype=float) for k in names])
    m = np.where(np.isnan(m), -np.inf, m)
    ok = (m >= 0.0).all(axis=0)
    passing = int(ok.sum())
    if passing:
        if objective == "thinnest":
            first = np.where(ok, np.asarray(values[order[0]], dtype=float), np.inf)
            j = int(np.lexsort((np.asarray(values[order[1]]), first))[0])
        else:
            j = int(np.argmax(np.where(ok, np.asarray(values[most]), -np.inf)))
        return j, names[int(np.argmin(m[:, j]))][len("margin_") :], passing
    best, best_c, best_j = -np.inf, 0, -1
    for c in range(len(names)):
        others = np.delete(m, c, axis=0)
        cand = (others >= 0.0).all(axis=0)
        if cand.any():
            j = int(np.argmax(np.where(cand, m[c], -np.inf)))
            if m[c, j] > best:
                best, best_c, best_j = float(m[c, j]), c, j
    if best_j < 0:
        best_j = int(np.argmax(m.min(axis=0)))
        best_c = int(np.argmin(m[:, best_j]))
    return best_j, names[best_c][len("margin_") :], 0


# --------------------------------------------------------------------------
# Disc packs (DIN EN 16983, DIN 2093 standard discs)
# --------------------------------------------------------------------------

SPRING_KINDS = ("helical", "disc_pack")
DISC_SERIES = ("any", "A", "B")
#: The checks of a disc pack, in the order they are reported; each margin ≥ 0 passes.
DISC_CHECKS = (
    "outer_diameter",
    "inner_diameter",
    "disc_preload",
    "disc_deflection",
    "disc_stress_om",
    "stack_length",
)
#: Largest deflection of a disc in use, as a share of h0: DIN 2093 tabulates the force
#: and stresses at 0.75 h0, and the measured curve leaves the Almen–László line nearer
#: flat (the discs roll on their edges).
DISC_MAX_DEFLECTION = 0.75
#: Smallest deflection at the setting under fatigue loading, as a share of h0
#: (DIN 2093: 0.15…0.20 h0, so that no crack starts at the upper inner edge).
DISC_MIN_PRELOAD = 0.15
#: Discs nested in parallel the search tries (more makes the friction of the pack large).
MAX_PARALLEL = 4
#: E and μ of the discs (DIN 2093's table: spring steel, 206 GPa, 0.3).
DISC_ELASTIC_MODULUS = 206e9
DISC_POISSON = 0.3

#: DIN 2093 standard disc springs of groups 1 and 2 (t ≤ 6 mm, no contact flats):
#: (De, Di, t, h0) in mm per series: A (De/t ≈ 18, h0/t ≈ 0.4), B (≈ 28, ≈ 0.75).
#: Group 3 (t > 6 mm, with contact flats and K4) is left out. Only rows a public reprint
#: of the standard's table confirms are kept ([EN16983] in docs/sources.md; each row's
#: printed force is reproduced in tests/models/clutch_spring/test_disc_pack.py):
#: series A 8…31.5 from a manufacturer's reprint (f ≈ 0.75 h0, F and σ_OM), series A
#: 31.5…100 and B 31.5…100 from an open table of group 2 (l0 and F at 0.75 h0).
#: A 35.5, A 112, B 8…28, B 35.5, B 112…160 and the whole of series C had no source in
#: hand and are not offered.
DISC_TABLE: dict[str, tuple[tuple[float, float, float, float], ...]] = {
    "A": (
        (8.0, 4.2, 0.4, 0.2),
        (10.0, 5.2, 0.5, 0.25),
        (12.5, 6.2, 0.7, 0.3),
        (14.0, 7.2, 0.8, 0.3),
        (16.0, 8.2, 0.9, 0.35),
        (18.0, 9.2, 1.0, 0.4),
        (20.0, 10.2, 1.1, 0.45),
        (22.5, 11.2, 1.25, 0.5),
        (25.0, 12.2, 1.5, 0.55),
        (28.0, 14.2, 1.5, 0.65),
        (31.5, 16.3, 1.75, 0.7),
        (40.0, 20.4, 2.25, 0.9),
        (45.0, 22.4, 2.5, 1.0),
        (50.0, 25.4, 3.0, 1.1),
        (56.0, 28.5, 3.0, 1.3),
        (63.0, 31.0, 3.5, 1.4),
        (71.0, 36.0, 4.0, 1.6),
        (80.0, 41.0, 5.0, 1.7),
        (90.0, 46.0, 5.0, 2.0),
        (100.0, 51.0, 6.0, 2.2),
    ),
    "B": (
        (31.5, 16.3, 1.25, 0.9),
        (40.0, 20.4, 1.5, 1.15),
        (45.0, 22.4, 1.75, 1.3),
        (50.0, 25.4, 2.0, 1.4),
        (56.0, 28.5, 2.0, 1.6),
        (63.0, 31.0, 2.5, 1.75),
        (71.0, 36.0, 2.5, 2.0),
        (80.0, 41.0, 3.0, 2.3),
        (90.0, 46.0, 3.5, 2.5),
        (100.0, 51.0, 3.5, 2.8),
    ),
}


def disc_designation(series: str, outer: float, inner: float, t: float, h0: float) -> str:
    """The disc as DIN 2093 names it, with its dimensions in mm.

    >>> disc_designation("B", 0.040, 0.0204, 0.0015, 0.00115)
    'DIN 2093 B 40 (40 × 20.4 × 1.5, h0 1.15)'
    """
    mm = [f"{v * 1e3:g}" for v in (outer, inner, t, h0)]
    return f"DIN 2093 {series} {mm[0]} ({mm[0]} × {mm[1]} × {mm[2]}, h0 {mm[3]})"


def disc_candidates(series: str) -> dict[str, Any]:
    r"""Every standard disc of the series, each with 1…4 discs nested in parallel.

    .. math::
        (D_e, D_i, t, h_0) \in \text{DIN 2093 A, B}, \quad n = 1 \dots 4

    Parameters
    ----------
    series : {"any", "A", "B"}
        The series to search, [-]

    Returns
    -------
    candidates : dict
        ``outer``, ``inner``, ``thickness``, ``cone_height`` [m], ``parallel`` [-]
        arrays, and ``series`` (the letter of each)

    Notes
    -----
    :data:`DISC_TABLE`; the space is checked by :func:`evaluate_discs`, so a disc a
    little too large stays a candidate to name when nothing fits.

    Examples
    --------
    >>> c = disc_candidates("B")
    >>> c["outer"].size, float(c["parallel"].max())
    (40, 4.0)
    """
    rows = [(k, r) for k in ("A", "B") if series in ("any", k) for r in DISC_TABLE[k]]
    dims = np.array([r for _, r in rows]) * 1e-3
    par = np.arange(1.0, MAX_PARALLEL + 1.0)
    idx, n = (a.ravel() for a in np.meshgrid(np.arange(len(rows)), par, indexing="ij"))
    return {
        "outer": dims[idx, 0],
        "inner": dims[idx, 1],
        "thickness": dims[idx, 2],
        "cone_height": dims[idx, 3],
        "parallel": n,
        "series": np.array([rows[i][0] for i in idx]),
    }


def disc_set_deflection(force: float, c: Mapping[str, Any]) -> Array:
    r"""Deflection of each disc at which the pack carries the force at the setting.

    .. math::
        n\,F(s_1) = F_1, \quad 0 \le s_1 \le 2 h_0

    Parameters
    ----------
    force : float
        F₁, [N]
    c : mapping
        :func:`disc_candidates`

    Returns
    -------
    s1 : ndarray
        Per disc, [m]; 2 h0 where even that does not carry F₁

    Notes
    -----
    :func:`engine.physics.springs.disc_force` and
    :func:`engine.physics.springs.stack_force` (frictionless) solved by bisection, all
    candidates at once. The discs of DIN 2093 have h0/t ≤ 1.33 < √2: their force rises
    over the whole deflection, so the root is unique.

    Examples
    --------
    >>> c = {"outer": np.array([0.040]), "inner": np.array([0.0204]),
    ...      "thickness": np.array([0.00225]), "cone_height": np.array([0.0009]),
    ...      "parallel": np.array([1.0])}
    >>> round(float(disc_set_deflection(6500.0, c)[0]) * 1e3, 4)  # F(0.675 mm) = 6500 N
    0.675
    """
    lo = np.zeros_like(c["outer"])
    hi = 2.0 * c["cone_height"]

    def pack(s: Array) -> Array:
        single = sp.disc_force(
            s,
            c["outer"],
            c["inner"],
            c["thickness"],
            c["cone_height"],
            DISC_ELASTIC_MODULUS,
            DISC_POISSON,
        )
        return np.asarray(sp.stack_force(single, 1) * c["parallel"])

    enough = pack(hi) >= force
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        below = pack(mid) < force
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return np.where(enough, 0.5 * (lo + hi), 2.0 * c["cone_height"])


def discs_in_series(
    c: Mapping[str, Any], s1: Array, stroke: float, set_length: float, objective: str
) -> Array:
    r"""Discs (or packs) in series per candidate, for the objective.

    .. math::
        i_s = \frac{s_h}{0.75 h_0 - s_1}, \qquad
        i_L = \frac{L_1}{h_0 + n t - s_1}

    Parameters
    ----------
    c : mapping
        :func:`disc_candidates`
    s1 : ndarray
        Per-disc deflection at the setting, [m]
    stroke : float
        s_h, [m]
    set_length : float
        L₁, the pocket, [m]
    objective : {"thinnest", "margin"}
        Fewest packs that keep every disc within 0.75 h0 at full stroke (rounded up),
        or most that fit the pocket at the setting (rounded down), [-]

    Returns
    -------
    i : ndarray
        Packs in series, ≥ 1, [-]

    Notes
    -----
    The stroke shares out over the i packs in series: s₂ = s₁ + s_h/i per disc
    (DIN EN 16983, stacks in series). Where s₁ ≥ 0.75 h0 already no i keeps the
    deflection (the pack is too weak): the fewest takes i_L, and the other way round.

    Examples
    --------
    >>> c = {"thickness": np.array([0.0015]), "cone_height": np.array([0.00115]),
    ...      "parallel": np.array([1.0])}
    >>> discs_in_series(c, np.array([0.0005]), 0.003, 0.08, "thinnest").tolist()  # 3/0.3625
    [9.0]
    """
    room = DISC_MAX_DEFLECTION * c["cone_height"] - s1
    with np.errstate(divide="ignore", invalid="ignore"):
        i_s = np.where(room > 0.0, stroke / room, np.inf)
        i_l = set_length / (c["cone_height"] + c["parallel"] * c["thickness"] - s1)
    fewest = np.where(np.isfinite(i_s), np.ceil(i_s - 1e-9), np.floor(i_l + 1e-9))
    most = np.where(np.isfinite(i_l) & (i_l >= 1.0), np.floor(i_l + 1e-9), np.ceil(i_s - 1e-9))
    i = fewest if objective == "thinnest" else most
    return np.maximum(np.where(np.isfinite(i), i, 1.0), 1.0)


def evaluate_discs(
    c: Mapping[str, Any],
    s1: Array,
    series: Array,
    force: float,
    stroke: float,
    space: Mapping[str, Any],
) -> dict[str, Any]:
    r"""Every DIN EN 16983 quantity and check margin of the disc packs, all at once.

    .. math::
        s_2 = s_1 + \frac{s_h}{i}, \; F_2 = n F(s_2), \;
        L_0 = i (h_0 + n t), \; L_1 = L_0 - i s_1, \; L_2 = L_1 - s_h, \;
        L_c = i n t, \; |\sigma_{OM}(s_2)| \le R_e

    Parameters
    ----------
    c : mapping
        :func:`disc_candidates`
    s1, series : ndarray
        Per-disc deflection at the setting [m], packs in series i [-]
    force : float
        F₁, [N]
    stroke : float
        s_h, [m]
    space : mapping
        ``max_outer_diameter``, ``min_inner_diameter``, ``max_set_length`` [m],
        ``disc_yield_strength`` [Pa], ``dynamic_load``

    Returns
    -------
    values : dict
        The pack's quantities and ``margin_<check>`` for each of :data:`DISC_CHECKS`,
        arrays of the candidates' shape

    Notes
    -----
    DIN EN 16983 through :func:`~engine.physics.springs.disc_force`,
    :func:`~engine.physics.springs.stack_force` and
    :func:`~engine.physics.springs.disc_stresses` (σ_OM, the static check, against
    R_e). Margins: outer 1 − De/D_e,max; inner 1 − D_i,min/Di; deflection
    1 − s₂/(0.75 h0); preload (s₁ − s_min)/h0 with s_min = 0.15 h0 under dynamic
    load (DIN 2093), else 0; σ_OM 1 − |σ_OM|/R_e; length 1 − L₁/L_set (a shim fills
    the rest of the pocket).

    Examples
    --------
    >>> c = {"outer": np.array([0.040]), "inner": np.array([0.0204]),
    ...      "thickness": np.array([0.00225]), "cone_height": np.array([0.0009]),
    ...      "parallel": np.array([1.0])}
    >>> v = evaluate_discs(c, np.array([0.0003]), np.array([2.0]), 3000.0, 0.00075,
    ...     {"max_outer_diameter": 0.041, "min_inner_diameter": 0.02,
    ...      "max_set_length": 0.01, "disc_yield_strength": 1.4e9, "dynamic_load": False})
    >>> round(float(v["disc_stroke_deflection"][0]) * 1e3, 9)  # 0.3 + 0.75/2
    0.675
    >>> round(float(v["free_length"][0]) * 1e3, 9)  # 2 (0.9 + 2.25)
    6.3
    """
    de, di, t, h0, n = (
        np.asarray(c[k], dtype=float)
        for k in ("outer", "inner", "thickness", "cone_height", "parallel")
    )
    i = np.asarray(series, dtype=float)
    s2 = s1 + stroke / i
    single = sp.disc_force(s2, de, di, t, h0, DISC_ELASTIC_MODULUS, DISC_POISSON)
    f2 = np.asarray(sp.stack_force(single, 1)) * n
    om = np.asarray(sp.disc_stresses(s2, de, di, t, h0, DISC_ELASTIC_MODULUS, DISC_POISSON)["OM"])
    free = i * (h0 + n * t)
    l1 = free - i * s1
    r_e = float(space["disc_yield_strength"])
    s_min = DISC_MIN_PRELOAD * h0 if space["dynamic_load"] else 0.0 * h0
    margins = {
        "outer_diameter": 1.0 - de / float(space["max_outer_diameter"]),
        "inner_diameter": 1.0 - float(space["min_inner_diameter"]) / di,
        "disc_preload": (s1 - s_min) / h0,
        "disc_deflection": 1.0 - s2 / (DISC_MAX_DEFLECTION * h0),
        "disc_stress_om": 1.0 - np.abs(om) / r_e,
        "stack_length": 1.0 - l1 / float(space["max_set_length"]),
    }
    out: dict[str, Any] = {
        "disc_outer_diameter": de,
        "disc_inner_diameter": di,
        "disc_thickness": t,
        "disc_cone_height": h0,
        "discs_parallel": n,
        "discs_series": i,
        "disc_count": n * i,
        "disc_set_deflection": s1 + 0.0 * de,
        "disc_stroke_deflection": s2,
        "disc_stress_om": np.abs(om),
        "set_deflection": i * s1,
        "stroke_force": f2,
        "free_length": free,
        "set_length": l1,
        "stroke_length": l1 - stroke,
        "solid_length": i * n * t,
        "shim_length": float(space["max_set_length"]) - l1,
        "permissible_stress": r_e + 0.0 * de,
        **{f"margin_{k}": m for k, m in margins.items()},
    }
    return {k: np.asarray(v, dtype=float) for k, v in out.items()}


def disc_pack_design(x: Mapping[str, Any], force: float, stroke: float) -> dict[str, Any]:
    """The clutch's disc pack: candidates, deflection at the setting, packs in series,
    checks, choice (the disc steps above)."""
    c = disc_candidates(str(x["disc_series"]))
    s1 = disc_set_deflection(force, c)
    i = discs_in_series(c, s1, stroke, float(x["max_set_length"]), x["objective"])
    values = evaluate_discs(c, s1, i, force, stroke, x)
    j, binding, passing = choose(
        values, x["objective"], ("disc_count", "disc_outer_diameter"), "margin_disc_stress_om"
    )
    out: dict[str, Any] = {k: float(np.asarray(v)[j]) for k, v in values.items()}
    for k in ("discs_parallel", "discs_series", "disc_count"):
        out[k] = int(out[k])
    out["disc_designation"] = disc_designation(
        str(c["series"][j]),
        out["disc_outer_diameter"],
        out["disc_inner_diameter"],
        out["disc_thickness"],
        out["disc_cone_height"],
    )
    out.update(
        binding_limit=binding,
        candidates_checked=int(c["outer"].size),
        candidates_passing=passing,
    )
    return out


def spring_design(x: Mapping[str, Any]) -> dict[str, Any]:
    """The clutch's spring: duty, grid, coils, checks, choice (steps 1–5 above).

    Returns the chosen candidate's :func:`evaluate` values as floats, with
    ``set_force``, ``stroke``, ``set_length``, ``binding_limit``,
    ``candidates_checked`` and ``candidates_passing``.
    """
    force, stroke = clutch_duty(x)
    force, stroke = float(force), float(stroke)
    if not math.isfinite(force):
        raise InputOutOfRange(
            "the flank never pushes the balls out (groove angle ≤ atan f): no spring force "
            "sets a slipping torque",
            field="flank_friction",
        )
    set_length = float(x["max_set_length"])
    if x.get("spring_kind", "helical") == "disc_pack":
        pack = disc_pack_design(x, force, stroke)
        pack.update(set_force=force, stroke=stroke)
        return pack
    if set_length <= stroke:
        raise InputOutOfRange(
            f"max_set_length {set_length * 1e3:.4g} mm must exceed the stroke "
            f"{stroke * 1e3:.4g} mm (ball lift plus the rise over the rim)",
            field="max_set_length",
        )
    wire, mean = candidate_grid(
        x["spring_material"], float(x["max_outer_diameter"]), float(x["min_inner_diameter"])
    )
    active = coils(
        wire,
        mean,
        force,
        stroke,
        set_length,
        x["spring_material"],
        x["objective"],
        bool(x["dynamic_load"]),
    )
    values = evaluate(wire, mean, active, force, stroke, set_length, x)
    j, binding, passing = choose(values, x["objective"])
    out: dict[str, Any] = {k: float(np.asarray(v)[j]) for k, v in values.items()}
    out.update(
        set_force=force,
        stroke=stroke,
        set_length=set_length,
        binding_limit=binding,
        candidates_checked=int(wire.size),
        candidates_passing=passing,
    )
    return out
