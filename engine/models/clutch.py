"""The ``clutch.ball`` and ``clutch.ball_setting`` models: inputs, outputs, rungs, checks, notes.

The equations are in :mod:`engine.physics.clutch` (source [001], see docs/sources.md);
this module declares the two models and turns a request into calls of those
functions, checks and sentences.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import numpy.typing as npt

from ..core.errors import InfeasibleDesign, InputOutOfRange
from ..core.params import DEG, count, friction_coefficient, length
from ..core.spec import Answer, Check, ModelSpec, Output, Param, Result, RunContext, Rung
from ..core.text import q
from ..physics.clutch import (
    ARRANGEMENTS,
    RECOMMENDED_GROOVE_ANGLE,
    RECOMMENDED_LOAD_FACTOR,
    WORKABLE_SPRING_INDEX,
    ball_normal_force,
    ball_tangential_force,
    combined_push_factor,
    flank_push_factor,
    riding_flank_angle,
    spring_deflection_for_force,
    spring_force_for_torque,
    spring_index,
    spring_rate,
    spring_shear_stress,
    torque_limit,
    torque_sharing,
    wahl_factor,
    wire_diameter_for_force,
)
from ..procedures import clutch_asbuilt as asbuilt

# --------------------------------------------------------------------------
# Model specs: clutch.ball (forward) and clutch.ball_setting (inverse)
# --------------------------------------------------------------------------

#: Friction coefficient of lubricated steel flanks, used to say how much an
#: ignored friction would move the result (f = 0 is the paper's idealisation).
TYPICAL_FLANK_FRICTION = 0.1
#: Scatter assumed for a friction coefficient the user gives.
FLANK_FRICTION_SCATTER = 0.03


def _common_params(*, deflection_required: bool) -> tuple[Param, ...]:
    return (
        length(
            "ball_circle_diameter",
            "D0, diameter of the circle of ball centres [001, eq. 1]",
            minimum=1e-3,
            maximum=2.0,
            required=True,
            symbol="D0",
            group="balls",
        ),
        count(
            "ball_count",
            "i, number of balls [001, eq. 1]",
            required=True,
            minimum=1,
            maximum=100,
            symbol="i",
            group="balls",
        ),
        length(
            "ball_diameter",
            "d, ball diameter; the groove depth (= Δ in the source) is checked against "
            "d/2 [001, text after eq. 1]",
            minimum=1e-4,
            maximum=0.2,
            required=True,
            symbol="d",
            group="balls",
        ),
        Param(
            "groove_angle",
            "rad",
            "α, flank angle of the grooves; F_a = F_t tan α [001, eq. 1]; "
            "the source recommends 20…70°",
            required=True,
            minimum=0.0,
            maximum=math.pi / 2,
            exclusive_minimum=True,
            exclusive_maximum=True,
            recommended=RECOMMENDED_GROOVE_ANGLE,
            display_unit="deg",
            symbol="α",
            group="balls",
        ),
        Param(
            "load_factor",
            "1",
            "K_r, load non-uniformity factor between the balls, 0.85…0.9 [001, eq. 1]",
            default=0.85,
            minimum=0.1,  # a tenth of a fair share; 1e-200 once crashed the model
            maximum=1.0,
            recommended=RECOMMENDED_LOAD_FACTOR,
            symbol="K_r",
            group="balls",
        ),
        friction_coefficient(
            "flank_friction",
            "f, Coulomb friction between ball and flank; the axial push becomes "
            "F_t tan(α − atan f); 0 is the paper's frictionless case [001, eq. 3]",
            default=0.0,
            symbol="f",
            group="balls",
        ),
        length(
            "spring_wire_diameter",
            "d0, wire diameter of the helical spring [001, eq. 2]",
            minimum=1e-5,
            maximum=0.05,
            required=False,
            symbol="d0",
            group="spring",
        ),
        length(
            "spring_mean_diameter",
            "D, mean coil diameter of the helical spring [001, eq. 2]",
            minimum=1e-4,
            maximum=0.5,
            symbol="D",
            group="spring",
        ),
        Param(
            "spring_active_coils",
            "1",
            "i_p, number of active coils of the helical spring [001, eq. 2]",
            minimum=1.0,
            maximum=1000.0,
            symbol="i_p",
            group="spring",
        ),
        length(
            "spring_deflection",
            "Δ, spring compression with the balls seated (the nut setting); the paper also "
            "takes it as the groove depth [001, eq. 2], which ball_lift separates",
            minimum=1e-6,
            maximum=0.5,
            required=deflection_required,
            symbol="Δ",
            group="spring",
        ),
        Param(
            "shear_modulus",
            "Pa",
            "G, shear modulus of the spring wire; 8·10⁴ MPa for steel [001, eq. 2]",
            default=8e10,
            minimum=1e9,
            maximum=5e11,
            display_unit="MPa",
            symbol="G",
            group="spring",
        ),
        Param(
            "spring_arrangement",
            "1",
            "'common': one spring presses all balls through the disk (the paper's fig. 1), "
            "T = D0 F/(2 tan(α−ρ)); 'per_ball': each ball has its own spring, "
            "T = K_r D0 i F/(2 tan(α−ρ)), the paper's published formula [001, eq. 3]",
            default="common",
            kind="choice",
            choices=ARRANGEMENTS,
            group="spring",
        ),
    )


def _allowable_param() -> Param:
    return Param(
        "allowable_shear_stress",
        "Pa",
        "allowable wire shear stress, compared with the stress corrected by "
        "stress_correction (Wahl or Bergsträsser, EN 13906-1); optional, checked when given",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e10,
        display_unit="MPa",
        group="spring",
    )


def _estimate(x: Mapping[str, Any]) -> Any:
    """Relative error of the closed form from the flank friction it is given: a bound.

    The closed form is exact for its idealisation (rigid parts, quasi-static,
    Coulomb friction on the flanks only). Its largest real uncertainty is the
    friction: with f = 0 (the paper) the band a lubricated steel flank spans,
    f' in [0, 0.1]; with f given, a scatter f' in [f − 0.03, f + 0.03] (not below 0).
    The push p(f) falls with f, the torque goes as 1/p and the spring force a
    setting needs as p, so over the band every one moves by at most
    max(p(f)/p(f_hi) − 1, p(f_lo)/p(f) − 1) of itself: the estimate, the term
    the closed form neglects evaluated at the band's ends (at f = 0 the upper end's,
    as before). Measured over random designs in bench/accuracy_clutch.py.
    NaN-free: None where the shifted friction locks. On arrays (a sweep or a study
    choosing ``auto`` per point): the same per point, NaN where a scalar call gives None.
    """
    return _band_estimate(_band_pushes(x)[1])


def _band_pushes(x: Mapping[str, Any]) -> tuple[Any, Any]:
    """The flank frictions f, f_hi, f_lo (:func:`_friction_band`) stacked on a first axis,
    and the push of the flanks the ball slides on at each, as the torque limit takes it."""
    f = np.asarray(x["flank_friction"], dtype=float)
    low, high = _friction_band(f)
    frictions = np.stack(np.broadcast_arrays(f, high, low))
    if frictions.ndim == 1 and _array_inputs(x) is not None:
        frictions = frictions[:, None]  # the three against every design
    with np.errstate(all="ignore"):
        push = combined_push_factor(
            x["groove_angle"], frictions, x["driving_groove_angle"], x["flank_construction"]
        )
    return frictions, np.asarray(push)


def _band_estimate(pushes: Any) -> Any:
    """:func:`_estimate` from the pushes at f, f_hi, f_lo (:func:`_band_pushes`)."""
    push, upper, lower = pushes
    with np.errstate(all="ignore"):
        shift = np.maximum(push / upper - 1.0, lower / push - 1.0)
        estimate = np.where((push > 0.0) & (upper > 0.0), shift, np.nan)
    if estimate.ndim == 0:
        return None if math.isnan(estimate) else float(estimate)
    return estimate


def _friction_band(f: Any) -> tuple[Any, Any]:
    """The flank frictions the estimate covers: [0, 0.1] at f = 0, else f ± 0.03 (≥ 0)."""
    f = np.asarray(f, dtype=float)
    given = f != 0.0
    low = np.where(given, np.maximum(f - FLANK_FRICTION_SCATTER, 0.0), 0.0)
    high = np.where(given, f + FLANK_FRICTION_SCATTER, TYPICAL_FLANK_FRICTION)
    return low, high


#: Points of one design the peak's estimate evaluates at once (801 lifts each).
_ESTIMATE_CHUNK = 2000


def _estimate_ball(x: Mapping[str, Any]) -> Any:
    """clutch.ball's estimate: :func:`_estimate`, or the peak torque's shift if larger.

    The peak over the lift sits where the spring force and the contact angle balance;
    over the rim the contact angle is steeper than the flank's and the friction moves
    the torque more there, so the zero-lift shift need not cover the peak
    (bench/accuracy_clutch.py found it exceeded in 6 of 1200 random designs, worst 1.18×).
    :func:`asbuilt.peak_friction_shift` evaluates the peak at the band's ends, with the
    grid's error, on the designs whose peak may leave the rim (elsewhere,
    :func:`asbuilt.peak_at_rim`, the zero-lift shift is the peak's too). Inputs that do
    not describe a spring yet: :func:`_estimate` alone.
    """
    frictions, pushes = _band_pushes(x)
    base = _band_estimate(pushes)
    helical = x["spring_type"] == "helical"
    needed = (
        ("spring_wire_diameter", "spring_mean_diameter", "spring_active_coils")
        if helical
        else ("disc_outer_diameter", "disc_inner_diameter", "disc_thickness", "disc_cone_height")
    )
    if base is None or any(x[name] is None for name in needed):
        return base
    # where the peak is the torque at the rim for every band friction, it scales with
    # the friction exactly as the zero-lift torque does, on every grid: the peak's shift
    # is the zero-lift one (its lower side at most) and need not be evaluated
    at_rim = np.all(asbuilt.peak_at_rim(x, frictions, push=pushes), axis=0)
    _, high, low = frictions
    n = _array_inputs(x)
    with np.errstate(all="ignore"):
        if n is None:  # one design
            if at_rim:
                return base
            peak = asbuilt.peak_friction_shift(x, low.item(), high.item())
            estimate = float(np.fmax(base, peak))
            return None if math.isnan(estimate) else estimate
        many = np.array(np.broadcast_to(np.asarray(base, dtype=float), (n,)))
        todo = np.flatnonzero(~np.broadcast_to(at_rim, (n,)) & ~np.isnan(many))
        lo, hi = np.broadcast_to(low, (n,)), np.broadcast_to(high, (n,))
        for i in range(0, todo.size, _ESTIMATE_CHUNK):
            part = todo[i : i + _ESTIMATE_CHUNK]
            chunk = {
                k: (v[part] if isinstance(v, np.ndarray) and v.shape == (n,) else v)
                for k, v in x.items()
            }
            peak = asbuilt.peak_friction_shift(chunk, lo[part], hi[part])
            many[part] = np.fmax(many[part], np.asarray(peak, dtype=float))
    return many


_RUNG = Rung(
    "closed_form",
    "Closed form of [001, eq. 1–3] with flank friction: quasi-static, rigid parts, "
    "ball inertia and the friction of disk, spring and ball rolling neglected, spring "
    "force constant while the ball climbs. Error estimate: the largest relative shift "
    "of the torque or the spring force over a band of flank friction (0…0.1 if f = 0 "
    "was assumed, else ±0.03 on the given f), a bound on that uncertainty.",
    _estimate,
    typical_error="0…25 % from friction when f = 0 is assumed; a few % with f given",
    typical_time="< 1 ms",
)
#: clutch.ball's rung: the same closed form, its estimate covering the peak torque too.
_BALL_RUNG = dataclasses.replace(
    _RUNG,
    description=_RUNG.description.replace(
        "a bound on that uncertainty.",
        "and of the peak torque over the lift (with its grid's error), a bound on that "
        "uncertainty.",
    ),
    estimate=_estimate_ball,
)


def _refused(x: Mapping[str, Any], wire: Any) -> dict[str, Any]:
    """Where the physics refuses a design, by reason: True where refused (floats or arrays).

    The one statement of each condition: a single run raises on it, naming the field
    (:func:`_require_workable`, :func:`asbuilt.require_spring`); the array paths mask
    those points and say how many each reason took (:func:`_refusal_notes`).
    """
    with np.errstate(all="ignore"):
        push = combined_push_factor(
            x["groove_angle"],
            x["flank_friction"],
            x["driving_groove_angle"],
            x["flank_construction"],
        )
    # α ≤ atan f for one flank; with α′ the push of the construction (a free ball wedges
    # only where both flanks lock; the pushes under a pressure disc may cancel)
    out: dict[str, Any] = {"groove_angle": ~(np.asarray(push) > 0.0)}
    if wire is not None:
        out["spring_wire_diameter"] = wire >= x["spring_mean_diameter"]
    out.update(asbuilt.refused(x))
    return out


#: What each refusal of :func:`_refused` means, by the field it names.
_REFUSALS = {
    "groove_angle": "the balls wedge: no axial push from groove_angle (and "
    "driving_groove_angle) at atan(flank_friction)",
    "spring_wire_diameter": "no coil: spring_wire_diameter is not below spring_mean_diameter",
    "spring_wire_diameter_table": "spring_wire_diameter is outside the spring_material's table",
    "disc_inner_diameter": "disc_inner_diameter is not below disc_outer_diameter / 1.05",
    "spring_elastic_modulus": "spring_elastic_modulus is outside 2…3 times shear_modulus",
}


def _refusal_notes(refused: Mapping[str, Any], n: int) -> list[str]:
    """One note per reason that refuses some of the ``n`` points of an array path."""
    notes = []
    for reason, where in refused.items():
        count = int(np.count_nonzero(where)) if np.ndim(where) else n * bool(where)
        if count:
            notes.append(f"{count} of {n} points refused: {_REFUSALS[reason]}")
    return notes


def _require_workable(x: Mapping[str, Any], wire: float | None) -> None:
    """Cross-field refusals shared by both specs (scalar inputs), on :func:`_refused`."""
    alpha, f = x["groove_angle"], x["flank_friction"]
    refused = _refused(x, wire)
    if refused["groove_angle"] and x["driving_groove_angle"] is not None:
        rho, a1 = math.atan(f), x["driving_groove_angle"]
        raise InfeasibleDesign(
            f"the clutch never slips: with flank_construction = {x['flank_construction']}, "
            f"the driven flank α = {alpha / DEG:.3g}° and the driving flank "
            f"α′ = {a1 / DEG:.3g}° give no axial push at the friction angle atan f = "
            f"{rho / DEG:.3g}°, so the balls wedge at any torque; make the flanks flatter "
            "(larger α or α′) or reduce the flank friction",
            field="groove_angle",
        )
    if refused["groove_angle"]:
        rho = math.atan(f)
        raise InfeasibleDesign(
            f"the clutch never slips: the flank angle α = {alpha / DEG:.3g}° is not above the "
            f"friction angle atan f = {rho / DEG:.3g}°, so the balls wedge in the grooves at "
            "any torque; make the flanks flatter (larger α) or reduce the flank friction",
            field="groove_angle",
        )
    if wire is not None and refused["spring_wire_diameter"]:
        raise InputOutOfRange(
            f"spring_wire_diameter = {wire * 1e3:g} mm is not below the spring's mean coil "
            f"diameter D = {x['spring_mean_diameter'] * 1e3:g} mm: such a coil cannot exist "
            "(spring index D/d0 must exceed 1)",
            field="spring_wire_diameter",
        )


def _index_check(name: str, index: float, kw: float, ok: bool) -> Check:
    lo, hi = WORKABLE_SPRING_INDEX
    if ok:
        detail = f"spring index D/d0 = {index:.4g} is within {lo:g}…{hi:g}"
    elif index < lo:
        detail = (
            f"spring index D/d0 = {index:.4g} < {lo:g}: hard to coil and the inner fibre is "
            f"over-stressed (Wahl factor {kw:.3g}); use a larger coil diameter or thinner wire"
        )
    else:
        detail = (
            f"spring index D/d0 = {index:.4g} > {hi:g}: a slender, floppy coil that buckles and "
            "tangles; use thicker wire or a smaller coil diameter"
        )
    return Check(name, ok, detail)


def _stress_check(
    name: str, stress: float, allowable: float | None, ok: bool, which: str = "wire"
) -> list[Check]:
    if allowable is None:
        return []
    detail = (
        f"{which} shear stress {q(stress, 'MPa', 4)} "
        + ("≤" if ok else ">")
        + f" allowable {q(allowable, 'MPa', 4)}"
        + ("" if ok else ": use thicker wire, a smaller coil diameter or a lower setting")
    )
    return [Check(name, ok, detail)]


def _groove_check(name: str, depth: float, ball_diameter: float, what: str, ok: bool) -> Check:
    """Groove depth (= spring deflection Δ in the source) against the ball radius.

    A ball sunk deeper than its radius has its centre below the groove rim: it
    can no longer protrude far enough to carry the other half-coupling's
    flank, and climbing out it meets the rim with its upper half, which wedges
    rather than lifts it. So the depth must not exceed d/2 (``ok``, from the verdicts).
    """
    if ok:
        detail = (
            f"groove depth ({what}) {q(depth, 'mm', 4)} ≤ ball radius "
            f"{q(ball_diameter / 2, 'mm', 4)}"
        )
    else:
        deeper = (
            f"even the whole ball (d = {q(ball_diameter, 'mm', 4)})"
            if depth >= ball_diameter
            else f"the ball radius (d/2 = {q(ball_diameter / 2, 'mm', 4)})"
        )
        detail = (
            f"groove depth ({what}) {q(depth, 'mm', 4)} exceeds {deeper}: the ball's "
            "centre would sit below the rim, so it cannot climb out cleanly (it wedges on "
            "the rim); use larger balls, a shallower groove, or a stiffer spring with less "
            "deflection"
        )
    return Check(name, ok, detail)


def _angle_check(alpha: float, ok: bool) -> Check:
    lo = RECOMMENDED_GROOVE_ANGLE[0]
    if ok:
        detail = f"groove angle {alpha / DEG:.4g}° is within the source's 20…70°"
    elif alpha < lo:
        detail = (
            f"groove angle {alpha / DEG:.4g}° < 20°: steep flanks make the limit very "
            "sensitive to friction and wear (the clutch may lock); use 20…70° [001]"
        )
    else:
        detail = (
            f"groove angle {alpha / DEG:.4g}° > 70°: shallow flanks need a very strong "
            "spring and the balls ride out under small shocks; use 20…70° [001]"
        )
    return Check("groove_angle", ok, detail)


def _arrangement_notes(x: Mapping[str, Any], force: float) -> list[str]:
    i, kr = x["ball_count"], x["load_factor"]
    common = torque_limit(
        force,
        x["ball_circle_diameter"],
        x["groove_angle"],
        i,
        kr,
        x["flank_friction"],
        "common",
        x["driving_groove_angle"],
        x["flank_construction"],
    )
    per_ball = torque_sharing("per_ball", i, kr) * common
    if x["spring_arrangement"] == "common":
        first = (
            f"spring_arrangement = common: one spring presses all {i} balls through the "
            "disk (the paper's fig. 1), T = D0 F_spring / (2 tan(α − ρ)) with no K_r, because "
            "statics fixes the sum of the balls' tangential forces however unevenly they "
            "share it. The paper's eq. 3 sets ONE ball's axial force equal to the WHOLE "
            f"spring force, which holds only for one spring per ball: it would give "
            f"K_r i = {kr * i:.4g} times more, {q(float(per_ball), 'N*m', 4)}."
        )
    else:
        first = (
            f"spring_arrangement = per_ball: each of the {i} balls has its own spring of "
            "these dimensions (the paper's eq. 3, F_a = F_spring for the most-loaded ball), "
            "T = K_r D0 i F_spring / (2 tan(α − ρ)). With one common spring, as the paper's "
            f"fig. 1 draws, the same spring would give K_r i = {kr * i:.4g} times less, "
            f"{q(float(common), 'N*m', 4)}."
        )
    return [
        first,
        "The scanned final formula [001, after eq. 3] shows K_r in the denominator, "
        "contrary to its own eq. 1; this follows eq. 1–3 (K_r multiplies; the printed "
        f"formula would give 1/K_r² = {1.0 / kr**2:.3g} times the per-ball value).",
    ]


def _equal_flanks_note(x: Mapping[str, Any]) -> list[str]:
    """The free ball's limit where both flanks are inclined alike (its moment neglected).

    A free ball between two flanks of equal angle touches them at opposite points: its
    moment balance then admits no friction at either, so a rolling ball pushes with the
    frictionless tan α. The model takes friction on the flank the ball rides (the seed's
    single-flank law), which gives the higher limit; the note states the lower one.
    """
    alpha, f, driving = x["groove_angle"], x["flank_friction"], x["driving_groove_angle"]
    if driving is None or f == 0.0 or x["flank_construction"] != "free_ball":
        return []
    if not math.isclose(driving, alpha, rel_tol=0.0, abs_tol=math.radians(5.0)):
        return []
    low = combined_push_factor(alpha, f, driving, "free_ball") / combined_push_factor(
        alpha, 0.0, driving, "free_ball"
    )
    return [
        f"both flanks are inclined alike (α′ = {math.degrees(driving):.3g}°, α = "
        f"{math.degrees(alpha):.3g}°): a free ball then touches them at opposite points and "
        "may roll, its moment balance admitting no flank friction; a rolling ball slips "
        f"{1.0 - float(low):.1%} below the limit given here (friction taken on the ridden "
        "flank, the ball's own moment neglected)"
    ]


def _friction_note(alpha: float, f: float) -> str:
    if f == 0.0:
        typical = flank_push_factor(alpha) / flank_push_factor(alpha, TYPICAL_FLANK_FRICTION) - 1.0
        return (
            "flank_friction = 0, the paper's frictionless case: with lubricated steel flanks "
            f"(f ≈ {TYPICAL_FLANK_FRICTION:g}) the limit would be {typical:.1%} higher; give "
            "flank_friction to include it."
        )
    rise = flank_push_factor(alpha) / flank_push_factor(alpha, f) - 1.0
    return (
        f"flank friction f = {f:g} (ρ = {math.degrees(math.atan(f)):.3g}°) raises the limit "
        f"by {rise:.1%} over the paper's frictionless formula."
    )


_SPRING_NOTE = (
    "required_spring_force and the deflection or wire that give it set the torque at which "
    "the balls start to move (zero lift, [001, eq. 3]); while they climb the spring is "
    "compressed further, see required_peak_setting and the stresses over the lift."
)

#: True of every answer of both clutch models (the runner adds it to the notes).
ASSUMPTIONS = (
    (
        "Quasi-static, rigid parts, ball inertia neglected. torque_limit is the paper's "
        "zero-lift value [001, eq. 3]; while the balls climb the spring is compressed by the "
        "lift, so the torque and the spring force and stress follow the characteristic "
        "(peak_torque, spring_stress_max)."
    ),
)


def _forward_values(
    x: Mapping[str, Any],
    as_built: bool = True,
    peak: bool = True,
    forces: bool = True,
    wanted: frozenset[str] | None = None,
) -> dict[str, Any]:
    """Every output of clutch.ball, on floats or arrays (one input may be an array).

    ``as_built=False`` leaves out the characteristic (81 lifts per point), for long
    sweeps that ask only for the paper's outputs; ``peak=False`` leaves out only the
    outputs at the characteristic's peak (:data:`asbuilt.PEAK_OUTPUTS`);
    ``forces=False`` the ball forces (:data:`_BALL_FORCES`), which no check reads.
    ``wanted``: the helical spring's index, Wahl factor, stress and rate only where
    named (an array path whose caller reads no checks); None gives them all.
    """
    spring = asbuilt.Spring(x)
    alpha, f, kr = x["groove_angle"], x["flank_friction"], x["load_factor"]
    force = spring.force(x["spring_deflection"])
    driving, construction = x["driving_groove_angle"], x["flank_construction"]
    # with α′: the push of the two flanks by the construction, T at zero lift
    limit = torque_limit(
        force,
        x["ball_circle_diameter"],
        alpha,
        x["ball_count"],
        kr,
        f,
        x["spring_arrangement"],
        driving,
        construction,
    )
    values: dict[str, Any] = {"spring_force": force, "torque_limit": limit}
    if forces:
        at = limit if x["torque"] is None else x["torque"]
        tangential = ball_tangential_force(at, x["ball_circle_diameter"], x["ball_count"], kr)
        values["ball_tangential_force"] = tangential
        values["ball_axial_force"] = np.asarray(tangential) * combined_push_factor(
            alpha, f, driving, construction
        )
        # on the flank the ball slides on (a free ball: the one it rides)
        values["ball_normal_force"] = ball_normal_force(
            tangential, riding_flank_angle(alpha, driving, construction), f
        )
    if spring.kind == "helical":
        d0, dm = x["spring_wire_diameter"], x["spring_mean_diameter"]

        def want(name: str) -> bool:
            return wanted is None or name in wanted

        if want("spring_index") or want("wahl_factor"):
            index = spring_index(dm, d0)
            values["spring_index"] = index
            values["wahl_factor"] = wahl_factor(index)
        if want("spring_shear_stress"):
            values["spring_shear_stress"] = spring_shear_stress(
                force, dm, d0, x["stress_correction"]
            )
        if want("spring_rate"):
            values["spring_rate"] = spring_rate(
                spring.shear_modulus, d0, dm, x["spring_active_coils"]
            )
    if as_built:
        values.update(asbuilt.extra_values(x, spring, limit, peak))
    return values


def _compute_ball(x: Mapping[str, Any], ctx: RunContext) -> Result:
    asbuilt.require_spring(x, wire_needed=True)
    helical = x["spring_type"] == "helical"
    _require_workable(x, x["spring_wire_diameter"] if helical else None)
    with np.errstate(all="ignore"):
        v: dict[str, Any] = {
            k: None if val is None else float(val) for k, val in _forward_values(x).items()
        }
    alpha, f = x["groove_angle"], x["flank_friction"]
    spring = asbuilt.Spring(x)
    passed = {k: bool(ok) for k, ok in _ball_verdicts(x, v, spring).items()}
    checks: list[Check] = []
    if helical:
        checks.append(
            _index_check(
                "spring_index", v["spring_index"], v["wahl_factor"], passed["spring_index"]
            )
        )
        checks += _stress_check(
            "spring_shear_stress",
            v["spring_shear_stress"],
            x["allowable_shear_stress"],
            passed.get("spring_shear_stress", True),
        )
    checks += [
        _groove_check(
            "groove_depth",
            asbuilt.lift_of(x),
            x["ball_diameter"],
            "= spring deflection Δ" if x["ball_lift"] is None else "= ball lift h",
            passed["groove_depth"],
        ),
        _angle_check(alpha, passed["groove_angle"]),
    ]
    where = "at the torque limit"
    if x["torque"] is not None:
        where = f"at the given torque {q(x['torque'], 'N*m', 4)}"
        ok = passed["torque_below_limit"]
        checks.append(
            Check(
                "torque_below_limit",
                ok,
                f"torque {q(x['torque'], 'N*m', 4)} "
                + ("≤" if ok else ">")
                + f" torque limit {q(v['torque_limit'], 'N*m', 4)}"
                + ("" if ok else ": the clutch slips at this torque"),
            )
        )
    checks += asbuilt.checks(x, spring, v, passed)
    notes = [
        *_arrangement_notes(x, v["spring_force"]),
        _friction_note(alpha, f),
        *_equal_flanks_note(x),
        f"ball forces are for the most-loaded ball (K_r = {x['load_factor']:g}) {where}; "
        "F_a = F_t tan(α − ρ), F_N = F_t / (cos α + f sin α) [001, eq. 1].",
        *asbuilt.notes(x, spring, v),
    ]
    if helical and x["allowable_shear_stress"] is None and x["spring_material"] == "custom":
        notes.append(
            "give allowable_shear_stress or spring_material to check the spring wire's strength"
        )
    wanted_series = {"lift", "torque_curve", "spring_force_curve", "spring_stress_curve"}
    series = asbuilt.series(x, spring) if any(ctx.wants(n) for n in wanted_series) else {}
    return Result(
        values=dict(v),
        rung=ctx.rung,
        error_estimate=_estimate_ball(x),
        checks=checks,
        notes=notes,
        warnings=asbuilt.warnings(x),
        series=series,
    )


def _feasible(x: Mapping[str, Any], wire: Any) -> tuple[npt.NDArray[np.bool_], list[str]]:
    """Where a single run would not refuse the point, and notes on the points it would."""
    refused = _refused(x, wire)
    ok = np.asarray(True)
    for where in refused.values():
        ok = ok & ~np.asarray(where, dtype=bool)
    if ok.ndim == 0 and ok:  # one design, or fixed inputs no reason refuses: no note to count
        return ok, []
    n = _array_inputs(x) or 1
    return ok, _refusal_notes(refused, n)


def _masked(values: Mapping[str, Any], ok: npt.NDArray[np.bool_]) -> dict[str, Any]:
    if ok.all():  # the common case in a study: nothing refused, no copies
        return {k: np.asarray(v, dtype=float) for k, v in values.items()}
    return {k: np.where(ok, np.asarray(v, dtype=float), np.nan) for k, v in values.items()}


def _array_inputs(x: Mapping[str, Any]) -> int | None:
    """The length of the varied inputs (equal-length columns), or None where none varies."""
    sizes = {v.shape[0] for v in x.values() if isinstance(v, np.ndarray) and v.ndim == 1}
    return sizes.pop() if len(sizes) == 1 else None


def _with_absent(
    values: dict[str, Any], scalars: tuple[str, ...], skip: tuple[str, ...] = ()
) -> dict[str, Any]:
    """``values`` with None for every scalar output the scalar compute does not give here.

    The array paths mirror the scalar compute's branches (which outputs exist depends only
    on inputs that are the same at every point), so an output they leave out is one the
    scalar compute leaves out too: None tells :func:`engine.core.points.vector` so, sparing a
    scalar run to find out. ``scalars``: the spec's scalar outputs
    (:attr:`ModelSpec.scalar_output_names`); ``skip``: outputs left out for speed (the caller
    loops if asked).
    """
    out: dict[str, Any] = dict(values)
    for name in scalars:
        if name not in out and name not in skip:
            out[name] = None
    return out


def _verdicts(ok: Any, where: Any) -> npt.NDArray[np.int8]:
    """int8 verdicts: 1 passes, 0 fails, -1 where the point is refused (``where`` False)."""
    return np.where(where, np.asarray(ok, dtype=np.int8), np.int8(-1)).astype(np.int8)


def _ball_verdicts(
    x: Mapping[str, Any], v: Mapping[str, Any], spring: asbuilt.Spring
) -> dict[str, Any]:
    """Every check of clutch.ball, on floats or arrays: True where it passes.

    The one place the checks compare numbers: a single run words these verdicts
    (:func:`_compute_ball`), the array path reports them per point.
    """
    lo, hi = WORKABLE_SPRING_INDEX
    out: dict[str, Any] = {}
    if spring.kind == "helical":
        index = v["spring_index"]
        out["spring_index"] = (lo <= index) & (index <= hi)
        if x["allowable_shear_stress"] is not None:
            out["spring_shear_stress"] = v["spring_shear_stress"] <= x["allowable_shear_stress"]
    out["groove_depth"] = asbuilt.lift_of(x) <= x["ball_diameter"] / 2.0
    a_lo, a_hi = RECOMMENDED_GROOVE_ANGLE
    alpha = x["groove_angle"]
    out["groove_angle"] = (a_lo <= alpha) & (alpha <= a_hi)
    if x["torque"] is not None:
        out["torque_below_limit"] = x["torque"] <= v["torque_limit"]
    out.update(asbuilt.verdicts(x, spring, v))
    return out


def _vectorized_ball(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """clutch.ball on arrays: every output and check the scalar compute gives, point by point.

    Several inputs may vary at once (a design study); helical springs of any material
    and disc stacks. A point the scalar compute refuses (the balls wedge, no coil, a
    wire off the material's table, a disc ring too narrow) is NaN in every output and
    -1 in every check. Inputs missing for the spring type go to the scalar compute
    (it names the field).
    """
    helical = x["spring_type"] == "helical"
    needed = (
        ("spring_wire_diameter", "spring_mean_diameter", "spring_active_coils")
        if helical
        else ("disc_outer_diameter", "disc_inner_diameter", "disc_thickness", "disc_cone_height")
    )
    if any(x[name] is None for name in needed):
        return Result(values={}, rung=ctx.rung, error_estimate=None)
    wire = x["spring_wire_diameter"] if helical else None
    finite: frozenset[str] = frozenset()
    with np.errstate(all="ignore"):
        ok, refusals = _feasible(x, wire)
        spring = asbuilt.Spring(x)
        # the as-built values only where an output or a check reads them, and the
        # 81-point characteristic only where one needs its peak
        reads = ctx.checks and asbuilt.verdicts_read_values(x, spring)
        as_built = ctx.wants(*_AS_BUILT) or reads
        peak = not helical or x["face_friction"] is not None or ctx.wants(*asbuilt.PEAK_OUTPUTS)
        forces = ctx.wants(*_BALL_FORCES)
        if as_built:
            values = _chunked_forward(x, peak, forces)
            skip: tuple[str, ...] = () if peak else asbuilt.PEAK_OUTPUTS
        else:  # the paper's outputs, and the margin the self-locking check reads
            # a caller reading no checks (a sweep) gets the outputs it asked for alone
            wanted = None if ctx.checks else ctx.outputs
            values = _forward_values(x, as_built=False, forces=forces, wanted=wanted)
            finite = _finite_over_deflection(x, forces, wanted) if helical else frozenset()
            if ctx.checks or ctx.wants("self_locking_margin"):
                values["self_locking_margin"] = asbuilt.margin(x)
            skip = _AS_BUILT
        skip += () if forces else _BALL_FORCES
        check_arrays = (
            {k: _verdicts(c, ok) for k, c in _ball_verdicts(x, values, spring).items()}
            if ctx.checks
            else {}
        )
        values = _masked({k: v for k, v in values.items() if v is not None}, ok)
    return Result(
        values=_with_absent(values, BALL_CLUTCH.scalar_output_names, skip),
        rung=ctx.rung,
        error_estimate=None,
        notes=[
            f"spring_arrangement = {x['spring_arrangement']}; see a single run's notes",
            *refusals,
        ],
        check_arrays=check_arrays,
        finite=finite if ok.all() else frozenset(),
    )


#: Points from which the paper's outputs over a swept deflection are told finite from the
#: deflection's declared ends (:func:`_finite_over_deflection`): below, a pass over the points
#: costs less than the outputs at the two ends.
FINITE_ENDS_FROM = 8192


def _finite_over_deflection(
    x: Mapping[str, Any], forces: bool, wanted: frozenset[str] | None
) -> frozenset[str]:
    """The paper's outputs (:func:`_forward_values` without the characteristic) finite at
    every point, told from the ends of spring_deflection's declared range where the
    deflection alone varies over :data:`FINITE_ENDS_FROM` points or more (empty otherwise).

    With a helical spring each of them is the deflection times factors fixed by the other
    inputs (F = c Δ [001, eq. 2], T ∝ F [eq. 3], the ball forces ∝ T [eq. 1], τ ∝ F) or does
    not depend on it: monotone in Δ, every rounding too, so finite at both ends of the range
    no point lies outside, they are finite at every point, told without a pass over them.
    """
    deflection = x["spring_deflection"]
    if not isinstance(deflection, np.ndarray) or deflection.size < FINITE_ENDS_FROM:
        return frozenset()
    if any(isinstance(v, np.ndarray) for k, v in x.items() if k != "spring_deflection"):
        return frozenset()
    declared = BALL_CLUTCH.param("spring_deflection")
    if declared.minimum is None or declared.maximum is None:
        return frozenset()
    ends = np.array([declared.minimum, declared.maximum], dtype=float)
    at_ends = _forward_values(
        {**x, "spring_deflection": ends}, as_built=False, forces=forces, wanted=wanted
    )
    return frozenset(
        name
        for name, value in at_ends.items()
        if value is not None and bool(np.isfinite(value).all())
    )


#: The forces on the most-loaded ball (clutch.ball's [001, eq. 1]).
_BALL_FORCES = ("ball_tangential_force", "ball_axial_force", "ball_normal_force")
#: clutch.ball's as-built outputs (:func:`asbuilt.extra_values`).
_AS_BUILT = tuple(o.name for o in asbuilt.outputs() if not o.series)

#: Points evaluated at once (the characteristic holds 81 per point).
_CHUNK = 20_000


def _chunked_forward(
    x: Mapping[str, Any], peak: bool = True, forces: bool = True
) -> dict[str, Any]:
    """:func:`_forward_values` over long varied inputs, a chunk at a time (bounded memory)."""
    if not peak:  # without the 81-point curve: no chunks needed
        return _forward_values(x, peak=peak, forces=forces)
    return _in_chunks(
        lambda part: _forward_values(part, peak=peak, forces=forces), _array_inputs(x), x
    )


def _in_chunks(fn: Callable[..., dict[str, Any]], n: int | None, *args: Any) -> dict[str, Any]:
    """``fn(*args)`` on :data:`_CHUNK` points at a time, its columns joined.

    ``args`` are inputs (mappings) or columns; every array of ``n`` elements is cut,
    the rest passed whole. Memory stays bounded where ``fn`` holds a characteristic
    (81 values) per point; the numbers are those of one call on all points.
    """
    if n is None or n <= _CHUNK:
        return fn(*args)

    def cut(a: Any, i: int) -> Any:
        if isinstance(a, Mapping):
            return {k: cut(v, i) for k, v in a.items()}
        return a[i : i + _CHUNK] if isinstance(a, np.ndarray) and a.shape == (n,) else a

    parts = [fn(*(cut(a, i) for a in args)) for i in range(0, n, _CHUNK)]
    return {
        k: None
        if parts[0][k] is None
        else np.concatenate(
            [
                np.broadcast_to(np.asarray(p[k], dtype=float), (min(_CHUNK, n - i * _CHUNK),))
                for i, p in enumerate(parts)
            ]
        )
        for k in parts[0]
    }


BALL_CLUTCH = ModelSpec(
    name="clutch.ball",
    advice=frozenset(("spring_index", "groove_angle", "self_locking", "residual_torque")),
    answer=(
        Answer("torque_limit", "T"),
        Answer("peak_torque", "T_max"),
        Answer(
            "spring_stress_max",
            "τ_k,max",
            check="spring_stress_max",
            relation="≤",
            bound="permissible_stress",
            bound_symbol="τ_zul",
        ),
        Answer("residual_torque", "T_R", check="residual_torque"),
    ),
    title="Ball safety clutch: torque limit",
    family="clutch",
    summary=(
        "Slipping torque of a double-action ball safety clutch (torque limiter) from its "
        "ball circle, groove angle and spring; ball and spring forces at the limit or at a "
        "given torque, with spring index, Wahl factor and wire stress checks."
    ),
    source=(
        "[001] Malashchenko V.O., Semenyuk V.F., Lysiak B.R., Parameters of double action "
        "ball overturn coupling, eq. 1–3; spring checks after Wahl; helical springs to "
        "EN 13906-1 with wire to EN 10270-1 and EN 10270-3; disc springs to DIN EN 16983"
    ),
    inputs=(
        *_common_params(deflection_required=True),
        Param(
            "torque",
            "N*m",
            "optional: torque at which to give the ball forces (instead of at the limit)",
            minimum=0.0,
            maximum=1e6,
            display_unit="N*m",
            symbol="T",
        ),
        _allowable_param(),
        *asbuilt.params(),
    ),
    outputs=(
        Output(
            "spring_force",
            "N",
            "spring force at the setting Δ: G d0⁴ Δ / (8 D³ i_p) [001, eq. 2], or the disc "
            "stack's (DIN EN 16983)",
            symbol="F",
            step="[001, eq. 2]",
        ),
        Output(
            "torque_limit",
            "N*m",
            "slipping torque: common D0 F/(2 tan(α−ρ)); per_ball K_r i D0 F/(2 tan(α−ρ)) "
            "[001, eq. 3]",
            display_unit="N*m",
            symbol="T",
            step="[001, eq. 3]",
        ),
        Output(
            "ball_tangential_force",
            "N",
            "F_t = 2T/(K_r D0 i) on the most-loaded ball, at the limit or at `torque` [001, eq. 1]",
            symbol="F_t",
            step="[001, eq. 1]",
        ),
        Output(
            "ball_axial_force",
            "N",
            "F_a = F_t tan(α − atan f) [001, eq. 1 with friction]; with α′ the push of "
            "flank_construction (max or sum of the two flanks')",
            symbol="F_a",
            step="[001, eq. 1]",
        ),
        Output(
            "ball_normal_force",
            "N",
            "F_N = F_t/(cos α + f sin α), normal to the flank [001, eq. 1 with friction]",
            symbol="F_N",
            step="[001, eq. 1]",
        ),
        Output("spring_index", "1", "C = D/d0", symbol="C", step="EN 13906-1"),
        Output("wahl_factor", "1", "K_w = (4C−1)/(4C−4) + 0.615/C", symbol="K_w", step="Wahl"),
        Output(
            "spring_shear_stress",
            "Pa",
            "τ = 8 F D k/(π d0³) at the spring force, k Wahl's K_w or Bergsträsser's "
            "(w + 0.5)/(w − 0.75) as stress_correction chooses (EN 13906-1)",
            display_unit="MPa",
            symbol="τ_k",
            step="EN 13906-1",
        ),
        Output(
            "spring_rate",
            "N/m",
            "c = G d0⁴/(8 D³ i_p) [001, eq. 2]",
            display_unit="N/mm",
            symbol="c",
            step="[001, eq. 2]",
        ),
        *asbuilt.outputs(),
    ),
    rungs=(_BALL_RUNG,),
    compute=_compute_ball,
    # one rung: by default run it plainly; "auto" would note that the frictionless
    # default cannot meet 1 % (the estimate is the effect of neglected flank friction)
    default_fidelity="closed_form",
    assumptions=ASSUMPTIONS,
    examples=(
        # [001] worked case: D0 = 50 mm, i = 4, d = 10 mm, D = 45 mm, i_p = 5, α = 45°,
        # G = 8·10⁴ MPa; d0 = 0.5…4 mm and Δ = 4…10 mm: d0 = 4 mm, Δ = 4 mm is the one
        # point of those ranges whose spring index (11.25) and groove depth (≤ d/2) pass.
        {
            "ball_circle_diameter": 0.05,
            "ball_count": 4,
            "ball_diameter": 0.01,
            "groove_angle": math.radians(45.0),
            "load_factor": 0.85,
            "spring_wire_diameter": 0.004,
            "spring_mean_diameter": 0.045,
            "spring_active_coils": 5.0,
            "spring_deflection": 0.004,
            "shear_modulus": 8e10,
            "spring_arrangement": "common",
            "flank_friction": 0.0,
        },
        {
            "ball_circle_diameter": 0.05,
            "ball_count": 4,
            "ball_diameter": 0.01,
            "groove_angle": math.radians(45.0),
            "spring_wire_diameter": 0.004,
            "spring_mean_diameter": 0.045,
            "spring_active_coils": 5.0,
            "spring_deflection": 0.004,
            "spring_arrangement": "per_ball",
        },
        {
            "ball_circle_diameter": 0.05,
            "ball_count": 4,
            "ball_diameter": 0.01,
            "groove_angle": math.radians(45.0),
            "spring_wire_diameter": 0.004,
            "spring_mean_diameter": 0.045,
            "spring_active_coils": 5.0,
            "spring_deflection": 0.004,
            "flank_friction": 0.1,
            "torque": 0.5,
            "allowable_shear_stress": 5e8,
        },
        # an ordinary limiter: a DH spring preloaded 30 mm by the nut, a 2 mm groove
        {
            "ball_circle_diameter": 0.05,
            "ball_count": 4,
            "ball_diameter": 0.01,
            "groove_angle": math.radians(45.0),
            "flank_friction": 0.1,
            "face_friction": 0.01,
            "spring_wire_diameter": 0.004,
            "spring_mean_diameter": 0.032,
            "spring_active_coils": 8.0,
            "spring_free_length": 0.09,
            "spring_deflection": 0.03,
            "ball_lift": 0.002,
            "spring_material": "EN10270-1-DH",
        },
        # a disc-spring limiter set past the discs' force maximum: the torque falls
        {
            "ball_circle_diameter": 0.05,
            "ball_count": 6,
            "ball_diameter": 0.005,
            "groove_angle": math.radians(45.0),
            "flank_friction": 0.1,
            "face_friction": 0.01,
            "spring_type": "disc",
            "disc_outer_diameter": 0.04,
            "disc_inner_diameter": 0.0204,
            "disc_thickness": 0.001,
            "disc_cone_height": 0.002,
            "disc_series": 2,
            "spring_deflection": 0.0024,
            "ball_lift": 0.0004,
        },
    ),
    vectorized=_vectorized_ball,
    vector_rungs=("closed_form",),
)


def _required_force(x: Mapping[str, Any]) -> Any:
    """Spring force that sets the slipping torque to ``target_torque`` [001, eq. 1–3]."""
    return spring_force_for_torque(
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


def _setting_values(
    x: Mapping[str, Any], stresses: bool = True, wanted: frozenset[str] | None = None
) -> dict[str, Any]:
    """Every output of clutch.ball_setting, on floats or arrays.

    ``stresses=False`` leaves out the wire stresses, for an array path whose asked
    outputs and checks do not read them (no allowable stress given). ``wanted``: the
    outputs past the required force only where named (an array path whose caller reads
    no checks: the required wire's fourth root only where asked); None gives them all.
    """

    def want(*names: str) -> bool:
        return wanted is None or any(n in wanted for n in names)

    # the material's modulus where one is chosen, as the as-built outputs take it
    g = asbuilt.Spring(x).shear_modulus
    dm, ip = x["spring_mean_diameter"], x["spring_active_coils"]
    force = _required_force(x)
    out: dict[str, Any] = {"required_spring_force": force}
    wire, deflection = x["spring_wire_diameter"], x["spring_deflection"]
    if wire is not None:
        if want("spring_rate"):
            out["spring_rate"] = spring_rate(g, wire, dm, ip)
        if want("required_deflection"):
            out["required_deflection"] = spring_deflection_for_force(force, g, wire, dm, ip)
        if want("spring_index"):
            out["spring_index"] = spring_index(dm, wire)
        if stresses and want("spring_shear_stress"):
            out["spring_shear_stress"] = spring_shear_stress(
                force, dm, wire, x["stress_correction"]
            )
    if deflection is not None and want(*_REQUIRED_WIRE):
        new_wire = wire_diameter_for_force(force, g, dm, ip, deflection)
        out["required_wire_diameter"] = new_wire
        new_index = spring_index(dm, new_wire)
        out["required_wire_spring_index"] = new_index
        if stresses:
            # No coil exists for C <= 1 (the wire would fill the coil): no stress there.
            out["required_wire_shear_stress"] = np.where(
                np.asarray(new_index) > 1.0,
                spring_shear_stress(force, dm, new_wire, x["stress_correction"]),
                np.nan,
            )
    return out


def _compute_setting(x: Mapping[str, Any], ctx: RunContext) -> Result:
    drive = asbuilt.sizing(x)
    drive_notes: list[str] = []
    if x["target_torque"] is None:
        if not drive:
            raise InputOutOfRange(
                "give target_torque, or the drive: drive_torque, or drive_power and drive_speed",
                field="target_torque",
            )
        x = {**x, "target_torque": drive["required_slip_torque"]}
        drive_notes.append(
            f"target torque = required slip torque {q(drive['required_slip_torque'], 'N*m', 4)} = "
            f"max(K T_N, T_a) with K = {x['service_factor']:g}, T_N = "
            f"{q(drive['rated_drive_torque'], 'N*m', 4)}"
            + (f", T_a = {q(drive['start_torque'], 'N*m', 4)}" if "start_torque" in drive else "")
        )
    wire, deflection = x["spring_wire_diameter"], x["spring_deflection"]
    helical = x["spring_type"] == "helical"
    if helical and wire is None and deflection is None:
        raise InputOutOfRange(
            "give spring_wire_diameter (to get the deflection that sets the target torque) "
            "or spring_deflection (to get the wire diameter), or both",
            field="spring_wire_diameter",
        )
    asbuilt.require_spring(x, wire_needed=False)
    _require_workable(x, wire if helical else None)
    if helical:
        with np.errstate(all="ignore"):
            v: dict[str, Any] = {k: float(val) for k, val in _setting_values(x).items()}
    else:
        force = _required_force(x)
        v = {"required_spring_force": float(force)}
        setting = asbuilt.disc_breakaway_setting(x, float(force))
        v["required_deflection"] = None if math.isnan(setting) else setting
    extra, extra_notes = asbuilt.setting_values(x, v["required_spring_force"])
    v.update(extra)
    v.update(drive)
    extra_notes = drive_notes + extra_notes
    no_coil = helical and deflection is not None and v["required_wire_spring_index"] <= 1.0
    if no_coil:
        # no coil exists for C <= 1: its stress is not a number, say so rather than NaN
        v["required_wire_shear_stress"] = None
    alpha, f = x["groove_angle"], x["flank_friction"]
    allow = x["allowable_shear_stress"]
    verdicts = _setting_verdicts(x, v, drive, not drive_notes)
    passed = {k: bool(c == 1) for k, c in verdicts.items() if c != -1}
    checks: list[Check] = []
    if helical and wire is not None:
        kw = float(wahl_factor(v["spring_index"]))
        checks.append(_index_check("spring_index", v["spring_index"], kw, passed["spring_index"]))
        checks += _stress_check(
            "spring_shear_stress",
            v["spring_shear_stress"],
            allow,
            passed.get("spring_shear_stress", True),
            f"given wire ({q(wire, 'mm', 4)}) at the required deflection,",
        )
        checks.append(
            _groove_check(
                "required_deflection_groove_depth",
                asbuilt.lift_of(x, v["required_deflection"]),
                x["ball_diameter"],
                "= required deflection" if x["ball_lift"] is None else "= ball lift h",
                passed["required_deflection_groove_depth"],
            )
        )
    if helical and deflection is not None:
        idx = v["required_wire_spring_index"]
        if no_coil:
            checks.append(
                Check(
                    "required_wire_spring_index",
                    False,
                    f"the required wire ({q(v['required_wire_diameter'], 'mm', 4)}) is not "
                    f"thinner than the coil (D = {q(x['spring_mean_diameter'], 'mm', 6)}): no "
                    "such spring exists; use a larger coil, more deflection or fewer coils",
                )
            )
        else:
            checks.append(
                _index_check(
                    "required_wire_spring_index",
                    idx,
                    float(wahl_factor(idx)),
                    passed["required_wire_spring_index"],
                )
            )
            checks += _stress_check(
                "required_wire_shear_stress",
                v["required_wire_shear_stress"],
                allow,
                passed.get("required_wire_shear_stress", True),
                f"required wire ({q(v['required_wire_diameter'], 'mm', 4)})",
            )
        checks.append(
            _groove_check(
                "groove_depth",
                asbuilt.lift_of(x, deflection),
                x["ball_diameter"],
                "= given deflection" if x["ball_lift"] is None else "= ball lift h",
                passed["groove_depth"],
            )
        )
    if "peak_setting_stress_max" in passed:
        limit = float(asbuilt.Spring(x).permissible())
        ok = passed["peak_setting_stress_max"]
        checks.append(
            Check(
                "peak_setting_stress_max",
                ok,
                f"largest spring stress over the lift at the peak setting "
                f"{q(v['peak_setting_stress_max'], 'MPa', 4)} "
                + ("≤" if ok else ">")
                + f" permissible {q(limit, 'MPa', 4)}",
            )
        )
    checks.append(_angle_check(alpha, passed["groove_angle"]))
    if "target_covers_drive" in passed:
        ok = passed["target_covers_drive"]
        checks.append(
            Check(
                "target_covers_drive",
                ok,
                f"target {q(x['target_torque'], 'N*m', 4)} "
                + ("≥" if ok else "<")
                + f" required slip torque {q(drive['required_slip_torque'], 'N*m', 4)}"
                + ("" if ok else ": the clutch would slip in normal work or at every start"),
            )
        )
    notes = [
        *_arrangement_notes(x, v["required_spring_force"]),
        _friction_note(alpha, f),
        "required_deflection is the nut setting (spring compression) that gives the target "
        "torque with the given wire; required_wire_diameter gives it at the given "
        "deflection, d0 = (8 F D³ i_p / (G Δ))^¼ [001, eq. 2]; round it to a stock wire "
        "size and re-set the deflection.",
        _SPRING_NOTE,
        *extra_notes,
    ]
    if no_coil:
        notes.append(
            "required_wire_shear_stress is null: the wire that would give the target torque "
            "at this deflection is as thick as the coil itself (spring index ≤ 1)"
        )
    return Result(
        values=v,
        rung=ctx.rung,
        error_estimate=_estimate(x),
        checks=checks,
        notes=notes,
    )


def _vectorized_setting(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """clutch.ball_setting on arrays: every output and check of the scalar compute, helical.

    Several inputs may vary at once; the same functions as a single run
    (:func:`asbuilt.setting_values`, :func:`asbuilt.disc_breakaway_setting`,
    :func:`asbuilt.sizing`). NaN (and -1 in the checks) where the scalar compute
    refuses the point or leaves an output null. Inputs missing for the spring or the
    target go to the scalar compute (it names them).
    """
    helical = x["spring_type"] == "helical"
    wire, deflection = x["spring_wire_diameter"], x["spring_deflection"]
    needed = ("spring_mean_diameter", "spring_active_coils") if helical else _DISC_INPUTS
    if any(x[name] is None for name in needed) or (helical and wire is None and deflection is None):
        return Result(values={}, rung=ctx.rung, error_estimate=None)
    with np.errstate(all="ignore"):
        drive = asbuilt.sizing(x)
        target_given = x["target_torque"] is not None
        if not target_given:
            if not drive:
                return Result(values={}, rung=ctx.rung, error_estimate=None)
            x = {**x, "target_torque": drive["required_slip_torque"]}
        ok, refusals = _feasible(x, wire if helical else None)
        if helical:
            stresses = x["allowable_shear_stress"] is not None or ctx.wants(*_STRESSES)
            # a caller reading no checks (a sweep) gets the outputs it asked for alone
            wanted = None if ctx.checks else ctx.outputs
            v: dict[str, Any] = dict(_setting_values(x, stresses, wanted))
        else:
            force = _required_force(x)
            v = {
                "required_spring_force": force,
                "required_deflection": asbuilt.disc_breakaway_setting(x, force),
            }
        if _setting_read(x, ctx) if ctx.checks else ctx.wants(*_AS_BUILT_SETTING):
            # the setting's lines hold 81 values per point: a chunk of points at a time
            v.update(
                _in_chunks(
                    lambda part, force: asbuilt.setting_values(part, force)[0],
                    _array_inputs(x),
                    x,
                    v["required_spring_force"],
                )
            )
        v.update(drive)
        check_arrays = (
            {k: _verdicts(c, ok) for k, c in _setting_verdicts(x, v, drive, target_given).items()}
            if ctx.checks
            else {}
        )
        values = _masked(v, ok)
    return Result(
        values=_with_absent(values, BALL_CLUTCH_SETTING.scalar_output_names),
        rung=ctx.rung,
        error_estimate=None,
        notes=refusals,
        check_arrays=check_arrays,
    )


#: The outputs of the wire a given compression needs (clutch.ball_setting).
_REQUIRED_WIRE = (
    "required_wire_diameter",
    "required_wire_spring_index",
    "required_wire_shear_stress",
)
#: The wire stresses of clutch.ball_setting (read by a check only with an allowable stress).
_STRESSES = ("spring_shear_stress", "required_wire_shear_stress")
#: clutch.ball_setting's outputs from the as-built setting (:func:`asbuilt.setting_values`).
_AS_BUILT_SETTING = tuple(o.name for o in asbuilt.setting_outputs())


def _setting_read(x: Mapping[str, Any], ctx: RunContext) -> bool:
    """Whether an asked output or a check reads the as-built setting on the array path.

    The setting (the peak setting's root search over the characteristic, the suggested
    wire or discs) is most of the array path's work; a sweep or study asking only for
    the paper's outputs (the required force, deflection or wire) leaves it out. The
    check of the stress at the peak setting reads it wherever the spring has a
    permissible stress (and, helical, a given wire), so its verdicts stay complete.
    """
    if ctx.wants(*_AS_BUILT_SETTING):
        return True
    if x["spring_type"] == "helical" and x["spring_wire_diameter"] is None:
        return False
    return asbuilt.Spring(x).permissible() is not None


#: The inputs a disc stack needs (:func:`asbuilt.require_spring` names a missing one).
_DISC_INPUTS = ("disc_outer_diameter", "disc_inner_diameter", "disc_thickness", "disc_cone_height")


def _setting_verdicts(
    x: Mapping[str, Any],
    v: Mapping[str, Any],
    drive: Mapping[str, Any],
    target_given: bool,
) -> dict[str, Any]:
    """Every check of clutch.ball_setting, on floats or arrays: int8, 1 passes, 0 fails.

    -1 where the check is not reported (no coil for the required wire, no peak
    setting). The one place the checks compare numbers: a single run words these
    verdicts (:func:`_compute_setting`), the array path reports them per point.
    """
    lo, hi = WORKABLE_SPRING_INDEX
    allow = x["allowable_shear_stress"]
    d_half = np.asarray(x["ball_diameter"]) / 2.0
    helical = x["spring_type"] == "helical"
    out: dict[str, Any] = {}
    if helical and x["spring_wire_diameter"] is not None:
        index = np.asarray(v["spring_index"])
        out["spring_index"] = (lo <= index) & (index <= hi)
        if allow is not None:
            out["spring_shear_stress"] = np.asarray(v["spring_shear_stress"]) <= allow
        lift = asbuilt.lift_of(x, v["required_deflection"])
        out["required_deflection_groove_depth"] = np.asarray(lift) <= d_half
    if helical and x["spring_deflection"] is not None:
        index = np.asarray(v["required_wire_spring_index"])
        no_coil = index <= 1.0
        out["required_wire_spring_index"] = (lo <= index) & (index <= hi) & ~no_coil
        if allow is not None:
            stress = np.asarray(v["required_wire_shear_stress"], dtype=float)
            out["required_wire_shear_stress"] = np.where(no_coil, -1, stress <= allow)
        lift = asbuilt.lift_of(x, x["spring_deflection"])
        out["groove_depth"] = np.asarray(lift) <= d_half
    if v.get("peak_setting_stress_max") is not None:
        limit = asbuilt.Spring(x).permissible()
        if limit is not None:
            peak = np.asarray(v["peak_setting_stress_max"], dtype=float)
            out["peak_setting_stress_max"] = np.where(np.isnan(peak), -1, peak <= limit)
    a_lo, a_hi = RECOMMENDED_GROOVE_ANGLE
    alpha = np.asarray(x["groove_angle"])
    out["groove_angle"] = (a_lo <= alpha) & (alpha <= a_hi)
    if drive and target_given:
        required = np.asarray(drive["required_slip_torque"])
        out["target_covers_drive"] = np.asarray(x["target_torque"]) >= required
    return {name: np.asarray(verdict).astype(np.int8) for name, verdict in out.items()}


BALL_CLUTCH_SETTING = ModelSpec(
    name="clutch.ball_setting",
    advice=frozenset(("spring_index", "required_wire_spring_index", "groove_angle")),
    answer=(
        Answer("required_spring_force", "F"),
        Answer("required_deflection", "Δ", check="required_deflection_groove_depth"),
        Answer("suggested_wire_diameter", "d_0"),
        Answer("peak_setting_stress_max", "τ_k,max", check="peak_setting_stress_max"),
    ),
    title="Ball safety clutch: setting for a target torque",
    family="clutch",
    summary=(
        "The inverse of clutch.ball: the spring force a target slipping torque needs, the "
        "spring compression (nut setting) that gives it with a given wire, and the wire "
        "diameter that gives it at a chosen compression."
    ),
    source=BALL_CLUTCH.source,
    inputs=(
        Param(
            "target_torque",
            "N*m",
            "the slipping torque wanted [001, eq. 3 solved for the spring]; absent, the "
            "required slip torque from the drive (drive_torque or drive_power and drive_speed)",
            minimum=0.0,
            exclusive_minimum=True,
            maximum=1e6,
            display_unit="N*m",
            symbol="T",
        ),
        *_common_params(deflection_required=False),
        _allowable_param(),
        *asbuilt.params(),
        *asbuilt.sizing_params(),
    ),
    outputs=(
        Output(
            "required_spring_force",
            "N",
            "F = 2 T tan(α−ρ)/(D0 s), s = 1 (common) or K_r i (per_ball) [001, eq. 1–3]",
            symbol="F",
            step="[001, eq. 1–3]",
        ),
        Output(
            "required_deflection",
            "m",
            "Δ = 8 F D³ i_p/(G d0⁴) with the given wire: the nut setting [001, eq. 2]",
            display_unit="mm",
            symbol="Δ",
            step="[001, eq. 2]",
        ),
        Output(
            "required_wire_diameter",
            "m",
            "d0 = (8 F D³ i_p/(G Δ))^¼ at the given deflection [001, eq. 2]",
            display_unit="mm",
            symbol="d_0",
            step="[001, eq. 2]",
        ),
        Output(
            "spring_rate",
            "N/m",
            "rate of the given wire's spring",
            display_unit="N/mm",
            symbol="c",
            step="[001, eq. 2]",
        ),
        Output("spring_index", "1", "D/d0 of the given wire", symbol="C", step="EN 13906-1"),
        Output(
            "spring_shear_stress",
            "Pa",
            "wire stress of the given wire at the required force",
            display_unit="MPa",
            symbol="τ_k",
            step="EN 13906-1",
        ),
        Output(
            "required_wire_spring_index",
            "1",
            "D/d0 of the required wire",
            symbol="C",
            step="EN 13906-1",
        ),
        Output(
            "required_wire_shear_stress",
            "Pa",
            "wire stress of the required wire at the required force",
            display_unit="MPa",
            symbol="τ_k",
            step="EN 13906-1",
        ),
        *asbuilt.setting_outputs(),
        *asbuilt.sizing_outputs(),
    ),
    rungs=(_RUNG,),
    compute=_compute_setting,
    # one rung: by default run it plainly; "auto" would note that the frictionless
    # default cannot meet 1 % (the estimate is the effect of neglected flank friction)
    default_fidelity="closed_form",
    assumptions=ASSUMPTIONS,
    examples=(
        # The paper's clutch (D0 = 50 mm, i = 4, d = 10 mm, D = 45 mm, i_p = 5, α = 45°,
        # d0 = 4 mm) set for 0.5 N·m; the wire for Δ = 4 mm.
        {
            "target_torque": 0.5,
            "ball_circle_diameter": 0.05,
            "ball_count": 4,
            "ball_diameter": 0.01,
            "groove_angle": math.radians(45.0),
            "spring_wire_diameter": 0.004,
            "spring_mean_diameter": 0.045,
            "spring_active_coils": 5.0,
            "spring_deflection": 0.004,
        },
        # an ordinary limiter sized from its drive: 0.37 kW at 1450 rpm, service factor 2,
        # a motor starting at 6 N·m against three times its own inertia
        {
            "ball_circle_diameter": 0.05,
            "ball_count": 4,
            "ball_diameter": 0.01,
            "groove_angle": math.radians(45.0),
            "flank_friction": 0.1,
            "spring_wire_diameter": 0.004,
            "spring_mean_diameter": 0.032,
            "spring_active_coils": 8.0,
            "spring_free_length": 0.09,
            "ball_lift": 0.002,
            "spring_material": "EN10270-1-DH",
            "drive_power": 370.0,
            "drive_speed": 1450.0 * math.pi / 30.0,
            "service_factor": 2.0,
            "drive_start_torque": 6.0,
            "drive_inertia": 1e-3,
            "load_inertia": 3e-3,
        },
    ),
    vectorized=_vectorized_setting,
    vector_rungs=("closed_form",),
)
