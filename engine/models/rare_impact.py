"""The ``impact.rare_impact`` model: inputs, outputs, rungs, checks and notes.

The closed forms are in :mod:`engine.rare_impact`, the time simulation in
:mod:`engine.rare_impact_sim` (source [002], scan [003], see docs/sources.md);
this module declares the model and chooses between them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..rare_impact import (
    G0,
    engagement_window,
    liftoff_speed,
    max_striker_travel,
    min_return_spring_rate,
    quasi_static_release_error,
    release_speed,
    relock_margin,
    relock_time,
    return_time,
    spin_up_time,
    spring_force_at_release,
    spring_height_limit,
    striker_oscillation,
    time_to_travel,
)
from ..rare_impact_sim import simulate
from ..spec import Check, ModelSpec, Output, Param, Plot, Result, RunContext, Rung, Window
from ._common import count, friction_coefficient, in_mm, in_ms, in_n_per_mm, in_rpm, positive

# ---------------------------------------------------------------------------
# The model: inputs, outputs, rungs
# ---------------------------------------------------------------------------

_SIMULATION_ERROR = 1e-6
#: Outputs that need the spin-up (stage 1); the others come from stages 2-4 alone.
_STAGE1_OUTPUTS = (
    "release_speed",
    "spin_up_time",
    "engagement_window",
    "engagement_start",
    "engagement_end",
    "full_engagement",
    "engagement_margin",
    "time",
    "flywheel_speed",
    "z1",
    "z2",
    "z3",
    "z4",
)


def _moving_mass(x: Mapping[str, Any]) -> Any:
    """:math:`M_2 = m_1 + n m_p + m_3` [002, eq. 2]."""
    return x["half_coupling_mass"] + x["roller_count"] * x["roller_mass"] + x["striker_mass"]


def _release_speed_of(x: Mapping[str, Any]) -> Any:
    """Quasi-static release speed, with the snap-through case (see :func:`released_at_liftoff`)."""
    return np.maximum(_paper_release_speed(x), _liftoff_speed_of(x))


def _liftoff_speed_of(x: Mapping[str, Any]) -> Any:
    return liftoff_speed(
        x["power_spring_rate"],
        x["power_spring_preload"],
        x["auxiliary_spring_rate"],
        x["auxiliary_spring_preload"],
        x["roller_mass"],
        x["roller_count"],
        x["roller_radius"],
        x["cone_angle"],
    )


def released_at_liftoff(x: Mapping[str, Any]) -> Any:
    r"""True where the half-coupling snaps straight to :math:`h_1` at the lift-off speed.

    The stage-1 stiffness :math:`K = c_1 + c_2 - n m_p\omega^2/(2	an^2lpha)`
    (:func:`quasi_static_release_error`) is already negative at lift-off when
    :math:`c_1\lambda_1 + c_2\lambda_2 > (c_1 + c_2)\,x_0	anlpha`: then the
    equilibrium at :math:`h_1` that the paper's formula describes is unstable,
    the half-coupling runs away to :math:`h_1` as soon as it lifts off, and
    the release speed is the lift-off speed, above the paper's value. This
    happens with heavy preloads or small cone angles; the source does not
    discuss it.
    """
    preload = (
        x["power_spring_rate"] * x["power_spring_preload"]
        + x["auxiliary_spring_rate"] * x["auxiliary_spring_preload"]
    )
    stiff = x["power_spring_rate"] + x["auxiliary_spring_rate"]
    return preload > stiff * x["roller_radius"] * np.tan(x["cone_angle"])


def _paper_release_speed(x: Mapping[str, Any]) -> Any:
    return release_speed(
        x["power_spring_rate"],
        x["power_spring_preload"],
        x["auxiliary_spring_rate"],
        x["auxiliary_spring_preload"],
        x["release_travel"],
        x["roller_mass"],
        x["roller_count"],
        x["roller_radius"],
        x["cone_angle"],
    )


def _closed_form_estimate(x: Mapping[str, Any]) -> float | None:
    try:
        dw, dt = quasi_static_release_error(x)
    except (ArithmeticError, ValueError):
        return None
    err = max(dw, dt)
    return err if math.isfinite(err) else None


def _closed_form_output_error(x: Mapping[str, Any], ctx: RunContext) -> float | None:
    """Estimated error of the outputs asked for (stage 2-4 outputs alone are exact)."""
    if not ctx.wants(*_STAGE1_OUTPUTS):
        return 0.0
    try:
        dw, dt = quasi_static_release_error(x)
    except (ArithmeticError, ValueError):
        return None
    err = max(dw, dt) if ctx.wants("spin_up_time") else dw
    return err if math.isfinite(err) else None


def _simulation_estimate(x: Mapping[str, Any]) -> float:
    return _SIMULATION_ERROR


def design_checks(x: Mapping[str, Any], omega_m: float) -> list[Check]:
    """The paper's conditions for this design, each with a sentence a designer can act on.

    c3 > c1 and λ1 < λ3 [002, after eq. 6]; the engagement height the springs
    reach, of which eq. 6 is the balanced-preload special case; the return of
    the striker [002, eq. 3]; re-locking [002, eq. 4]; full engagement inside
    the anvil's opening [002, after eq. 5].
    """
    c1, c2, c3 = x["power_spring_rate"], x["auxiliary_spring_rate"], x["return_spring_rate"]
    lam1, lam2, lam3 = (
        x["power_spring_preload"],
        x["auxiliary_spring_preload"],
        x["return_spring_preload"],
    )
    h1, h2, h3, g = x["release_travel"], x["engagement_height"], x["jaw_height"], x["gravity"]
    m2_total = float(_moving_mass(x))
    b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2_total, g)
    reach = float(max_striker_travel(b, k))
    limit = spring_height_limit(m2_total, g, c1, c3)
    checks: list[Check] = []
    if c3 > c1:
        checks.append(
            Check(
                "c3 > c1",
                True,
                f"the return spring ({in_n_per_mm(c3)}) is stiffer than the power spring "
                f"({in_n_per_mm(c1)}), as [002, eq. 6] asks",
            )
        )
    else:
        checks.append(
            Check(
                "c3 > c1",
                False,
                f"the return spring ({in_n_per_mm(c3)}) is not stiffer than the power "
                f"spring ({in_n_per_mm(c1)}); the paper asks c3 > c1 [002, eq. 6] (for a vertical "
                "tool with balanced preloads): raise the return-spring rate or soften the power "
                "spring",
            )
        )
    balanced = math.isclose(c1 * lam1, c3 * lam3, rel_tol=1e-3)
    contradiction = (
        " Note: with the balanced preloads c1·λ1 = c3·λ3 that the paper assumes for eq. 6, "
        "λ1 < λ3 and c3 > c1 cannot both hold; the source's conditions contradict each other."
    )
    checks.append(
        Check(
            "λ1 < λ3",
            lam1 < lam3,
            (
                f"the power-spring preload ({in_mm(lam1)}) is below the return-spring preload "
                f"({in_mm(lam3)}), as the paper asks [002, after eq. 6]"
                if lam1 < lam3
                else f"the power-spring preload ({in_mm(lam1)}) is not below the return-spring "
                f"preload ({in_mm(lam3)}); the paper asks λ1 < λ3 [002, after eq. 6]: lower λ1 "
                "or raise λ3" + (contradiction if balanced else "")
            ),
        )
    )
    limit_text = (
        "eq. 6 sets no limit (c3 ≤ c1)"
        if not math.isfinite(limit)
        else f"eq. 6's balanced-preload limit 2M2g/(c3 − c1) is {in_mm(limit)}"
    )
    checks.append(
        Check(
            "eq. 6 (engagement height)",
            reach >= h2,
            (
                f"the springs carry the striker up to 2B/k² = {in_mm(reach)} ≥ the engagement "
                f"height {in_mm(h2)} [002, eq. 5-6]; {limit_text}"
                if reach >= h2
                else f"the springs carry the striker only 2B/k² = {in_mm(reach)}, less than the "
                f"engagement height {in_mm(h2)} [002, eq. 5-6]: it can never engage fully. Raise "
                f"the power spring's force at release c1(λ1 + h1), lower the return-spring "
                f"preload c3·λ3 or the engagement height; {limit_text}"
            ),
        )
    )
    c3_min = float(min_return_spring_rate(x["striker_mass"], g, lam3, h2, h3))
    checks.append(
        Check(
            "return",
            c3 >= c3_min,
            (
                f"the return spring ({in_n_per_mm(c3)}) brings the striker back out of the jaws "
                f"(needs ≥ {in_n_per_mm(c3_min)}) [002, eq. 3]"
                if c3 >= c3_min
                else (
                    f"the return spring ({in_n_per_mm(c3)}) cannot bring the striker back the "
                    f"jaw height {in_mm(h3)} (needs ≥ {in_n_per_mm(c3_min)}) [002, eq. 3]: "
                    "raise c3 or λ3"
                    if math.isfinite(c3_min)
                    else f"no return-spring rate brings the striker back the jaw height "
                    f"{in_mm(h3)} from a preload λ3 = {in_mm(lam3)} [002, eq. 3]: raise λ3 or h2"
                )
            ),
        )
    )
    margin = float(relock_margin(c2, lam2, c3, lam3, x["roller_friction"]))
    checks.append(
        Check(
            "relock",
            margin > 0.0,
            (
                f"the auxiliary spring's end force c2·λ2 = {c2 * lam2:.3g} N beats the "
                f"friction c3·λ3·f = {c3 * lam3 * x['roller_friction']:.3g} N by "
                f"{margin:.3g} N [002, eq. 4]"
                if margin > 0.0
                else f"the auxiliary spring's end force c2·λ2 = {c2 * lam2:.3g} N does not beat "
                f"the friction c3·λ3·f = {c3 * lam3 * x['roller_friction']:.3g} N [002, eq. 4]:"
                f" the shaft will not re-lock; raise c2·λ2 by at least {-margin:.3g} N"
            ),
        )
    )
    t_eng = float(time_to_travel(h2, b, k))
    window = float(engagement_window(x["engagement_angle"], omega_m))
    if math.isfinite(t_eng) and t_eng <= window:
        checks.append(
            Check(
                "full engagement",
                True,
                f"the striker travels the engagement height {in_mm(h2)} in {in_ms(t_eng)}, inside "
                f"the {in_ms(window)} the flywheel takes to turn through the anvil's opening "
                f"[002, after eq. 5]",
            )
        )
    elif math.isfinite(t_eng):
        checks.append(
            Check(
                "full engagement",
                False,
                f"edge blow: the striker needs {in_ms(t_eng)} to travel {in_mm(h2)} but the "
                f"anvil's opening passes in {in_ms(window)} at {in_rpm(omega_m)} [002, after "
                "eq. 5]; make the power spring stiffer or the moving parts lighter, widen the "
                "opening, or lower the release speed",
            )
        )
    else:
        checks.append(
            Check(
                "full engagement",
                False,
                f"edge blow: the striker never reaches the engagement height {in_mm(h2)} (it "
                f"travels at most {in_mm(reach)}) [002, eq. 5]; see the eq. 6 check",
            )
        )
    return checks


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    omega_m = float(_release_speed_of(x))
    notes: list[str] = []
    if released_at_liftoff(x):
        notes.append(
            "the preloads c1·λ1 + c2·λ2 exceed (c1 + c2)·x0·tan α: the half-coupling snaps to "
            "h1 as soon as the rollers lift off, so the release speed is the lift-off speed, "
            f"above the paper's formula ({float(_paper_release_speed(x)) * 30 / math.pi:.0f} "
            "rpm), which assumes a stable balance"
        )
    warnings: list[str] = []
    series: dict[str, list[float]] = {}
    w_nl = x["motor_no_load_speed"]
    stage1_needed = ctx.wants(*_STAGE1_OUTPUTS)
    if ctx.rung == "simulation" and not stage1_needed:
        notes.append(
            "simulation: no requested output depends on the spin-up, so stage 1 was not "
            "integrated; stages 2-4 are exact and the checks use the quasi-static release speed"
        )
    sim = None
    if ctx.rung == "simulation" and stage1_needed:
        # Too many oscillations to integrate raises BudgetExceeded(expected_steps=...): exactly
        # where the quasi-static closed form is accurate, the rung's declared fallback.
        sim = simulate(x, ctx)
    if sim is not None:
        omega_rel, t_spin = sim.release_speed, sim.spin_up_time
        error: float | None = _SIMULATION_ERROR
        notes += sim.notes
        warnings += sim.warnings
        series = sim.series
        durations = sim.stage_durations
    else:
        omega_rel = omega_m
        t_spin = spin_up_time(x["flywheel_inertia"], x["motor_torque"], omega_m, w_nl)
        if ctx.rung == "simulation":
            error = _SIMULATION_ERROR
        else:
            error = _closed_form_output_error(x, ctx)
            angle = (
                ", equal to the paper's 45° form)"
                if math.isclose(x["cone_angle"], math.pi / 4)
                else ")"
            )
            notes.append(
                "closed form: quasi-static spin-up [002, after eq. 4] (general-angle balance"
                + angle
                + (
                    f"; estimated error {error:.2g}"
                    if error is not None
                    else "; its error could not be estimated for these inputs"
                )
            )
        durations = None
    m2_total = float(_moving_mass(x))
    c1, c3 = x["power_spring_rate"], x["return_spring_rate"]
    lam1, lam3 = x["power_spring_preload"], x["return_spring_preload"]
    h1, h2, g = x["release_travel"], x["engagement_height"], x["gravity"]
    b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2_total, g)
    b, k = float(b), float(k)
    t_eng = float(time_to_travel(h2, b, k))
    window = float(engagement_window(x["engagement_angle"], omega_rel))
    values: dict[str, Any] = {
        "release_speed": omega_rel,
        "spin_up_time": t_spin,
        "oscillation_B": b,
        "oscillation_k": k,
        "max_striker_travel": float(max_striker_travel(b, k)),
        "engagement_window": window,
        "engagement_start": t_spin,
        "engagement_end": t_spin + window,
        "full_engagement": bool(t_eng <= window),
        "spring_height_limit": float(spring_height_limit(m2_total, g, c1, c3)),
        "min_return_spring_rate": float(
            min_return_spring_rate(x["striker_mass"], g, lam3, h2, x["jaw_height"])
        ),
        "relock_margin": float(
            relock_margin(
                x["auxiliary_spring_rate"],
                x["auxiliary_spring_preload"],
                c3,
                lam3,
                x["roller_friction"],
            )
        ),
    }
    if math.isfinite(t_eng):
        values["engagement_time"] = t_eng
        values["engagement_margin"] = (window - t_eng) / window
    else:
        values["engagement_time"] = None
        values["engagement_margin"] = None
        notes.append(
            "the striker never reaches the engagement height: engagement_time and "
            "engagement_margin are null (see the eq. 6 and full engagement checks)"
        )
    if not math.isfinite(values["spring_height_limit"]):
        values["spring_height_limit"] = None
        notes.append("spring_height_limit is null: with c3 ≤ c1 eq. 6 sets no limit")
    if ctx.wants("min_return_spring_rate") and g != 0.0:
        notes.append(
            "min_return_spring_rate is the exact condition of [002, eq. 3] for a striker that "
            "starts its return at rest, m3·g/(λ3 + h2 − h3/2); the paper's static "
            "c3 = m3·g/(h − z3) only holds the weight (with λ3 = 0 and h2 = h3 = h it asks "
            "m3·g/h, half the 2·m3·g/h a return from rest needs)"
        )
    if not math.isfinite(values["min_return_spring_rate"]):
        values["min_return_spring_rate"] = None
        notes.append(
            "min_return_spring_rate is null: with λ3 + h2 ≤ h3/2 no rate brings the "
            "striker back the jaw height against its weight"
        )
    if durations is None:
        t_ret = return_time(x["striker_mass"], g, c3, lam3, h2, x["jaw_height"])
        t_lock = relock_time(
            x["stepped_shaft_mass"],
            g,
            x["auxiliary_spring_rate"],
            x["auxiliary_spring_preload"],
            h1,
            c3 * lam3 * x["roller_friction"],
        )
    else:
        t_ret, t_lock = durations[2], durations[3]
    values["return_time"] = t_ret if math.isfinite(t_ret) else None
    values["relock_time"] = t_lock if math.isfinite(t_lock) else None
    if values["return_time"] is None:
        notes.append("return_time is null: the striker does not come back the jaw height")
    if values["relock_time"] is None:
        notes.append("relock_time is null: the stepped shaft does not travel back h1")
    if g != 0.0:
        m12 = x["half_coupling_mass"] + x["stepped_shaft_mass"]
        force = float(
            spring_force_at_release(
                c1, lam1, x["auxiliary_spring_rate"], x["auxiliary_spring_preload"], h1
            )
        )
        notes.append(
            "stage 1 leaves out the weight of half-coupling and shaft, as [002, eq. 1] does "
            "(eqs. 2 and 4 show it acting against the stage-1 travel); counting it would raise "
            f"the release speed by about {50.0 * m12 * g / force:.2g} %"
        )
    checks = design_checks(x, omega_rel)
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=error,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=series,
    )


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """Closed form on arrays (one input varied); NaN where a point cannot be computed."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        omega_m = np.asarray(_release_speed_of(x), dtype=float)
        inertia, torque = x["flywheel_inertia"], x["motor_torque"]
        w_nl = x.get("motor_no_load_speed")
        if w_nl is None:
            t_spin = inertia * omega_m / torque
        else:
            ratio = omega_m / w_nl
            safe = np.where(ratio < 1.0, ratio, 0.0)
            t_spin = np.where(ratio < 1.0, -(inertia * w_nl / torque) * np.log1p(-safe), np.nan)
        m2_total = _moving_mass(x)
        c1, c3 = x["power_spring_rate"], x["return_spring_rate"]
        lam1, lam3 = x["power_spring_preload"], x["return_spring_preload"]
        h1, h2, g = x["release_travel"], x["engagement_height"], x["gravity"]
        b, k = striker_oscillation(c1, lam1, c3, lam3, h1, m2_total, g)
        t_eng = np.asarray(time_to_travel(h2, b, k), dtype=float)
        window = x["engagement_angle"] / omega_m
        values: dict[str, Any] = {
            "release_speed": omega_m,
            "spin_up_time": t_spin,
            "oscillation_B": b,
            "oscillation_k": k,
            "max_striker_travel": max_striker_travel(b, k),
            "engagement_time": t_eng,
            "engagement_window": window,
            "engagement_start": t_spin,
            "engagement_end": t_spin + window,
            "full_engagement": t_eng <= window,
            "engagement_margin": (window - t_eng) / window,
            "spring_height_limit": spring_height_limit(m2_total, g, c1, c3),
            "min_return_spring_rate": min_return_spring_rate(
                x["striker_mass"], g, lam3, h2, x["jaw_height"]
            ),
            "relock_margin": relock_margin(
                x["auxiliary_spring_rate"],
                x["auxiliary_spring_preload"],
                c3,
                lam3,
                x["roller_friction"],
            ),
            "return_time": return_time(x["striker_mass"], g, c3, lam3, h2, x["jaw_height"]),
            "relock_time": relock_time(
                x["stepped_shaft_mass"],
                g,
                x["auxiliary_spring_rate"],
                x["auxiliary_spring_preload"],
                h1,
                c3 * lam3 * x["roller_friction"],
            ),
        }
    shape = np.broadcast(*[np.asarray(v) for v in x.values() if v is not None]).shape
    out = {
        n: np.broadcast_to(np.asarray(v, dtype=bool if n == "full_engagement" else float), shape)
        for n, v in values.items()
    }
    if w_nl is not None:
        # where the motor never reaches the release speed the scalar model refuses the whole
        # design (spin_up_time raises InfeasibleDesign): no output of that point stands
        never = np.broadcast_to(np.asarray(omega_m) >= w_nl, shape)
        if never.any():
            refused = np.asarray(None, dtype=object)  # a bool output has no NaN: null it
            out = {
                n: np.where(never, refused if v.dtype == bool else np.nan, v)
                for n, v in out.items()
            }
    values_out: dict[str, Any] = dict(out)
    return Result(values=values_out, rung=ctx.rung, error_estimate=None)


def _preload(name: str, description: str, default: float, symbol: str) -> Param:
    return Param(
        name,
        "m",
        description,
        default=default,
        minimum=0.0,
        maximum=0.5,
        display_unit="mm",
        symbol=symbol,
        group="springs",
    )


_INPUTS: tuple[Param, ...] = (
    positive(
        "flywheel_inertia",
        "kg*m^2",
        "I_M: moment of inertia of the flywheel with half-coupling, shaft and striker [002, eq. 1]",
        default=0.02,
        maximum=100.0,
        display_unit="kg*m^2",
        symbol="I_M",
        group="drive",
    ),
    positive(
        "motor_torque",
        "N*m",
        "M: motor torque on the flywheel (the stall torque when a no-load speed is given) "
        "[002, eq. 1]",
        default=5.0,
        maximum=1e5,
        display_unit="N*m",
        symbol="M",
        group="drive",
    ),
    Param(
        "motor_no_load_speed",
        "rad/s",
        "ω_nl: optional; given, the motor torque falls linearly from the stall torque to 0 at "
        "this speed; absent, the torque is constant",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e5,
        display_unit="rpm",
        symbol="ω_nl",
        group="drive",
    ),
    positive(
        "roller_mass",
        "kg",
        "m_p: mass of one centrifugal roller [002, eq. 1]",
        default=0.05,
        maximum=100.0,
        display_unit="g",
        symbol="m_p",
        group="rollers",
    ),
    count(
        "roller_count",
        "n: number of centrifugal rollers [002, eq. 1]",
        default=6,
        minimum=1,
        maximum=64,
        symbol="n",
        group="rollers",
    ),
    positive(
        "roller_radius",
        "m",
        "x_0: radius of the rollers' centres at rest [002, eq. 1]",
        default=0.04,
        maximum=2.0,
        display_unit="mm",
        symbol="x_0",
        group="rollers",
    ),
    Param(
        "cone_angle",
        "rad",
        "α: angle of the conical faces of half-coupling and striker [002, eq. 1]; the paper's "
        "closed form is for 45°",
        default=math.pi / 4,
        minimum=0.0,
        maximum=math.pi / 2,
        exclusive_minimum=True,
        exclusive_maximum=True,
        recommended=(math.radians(15.0), math.radians(75.0)),
        display_unit="deg",
        symbol="α",
        group="rollers",
    ),
    positive(
        "half_coupling_mass",
        "kg",
        "m_1: mass of the half-coupling [002, eq. 1]",
        default=0.15,
        maximum=1e3,
        display_unit="kg",
        symbol="m_1",
        group="masses",
    ),
    positive(
        "stepped_shaft_mass",
        "kg",
        "m_2: mass of the stepped central shaft [002, eq. 1]",
        default=0.05,
        maximum=1e3,
        display_unit="kg",
        symbol="m_2",
        group="masses",
    ),
    positive(
        "striker_mass",
        "kg",
        "m_3: mass of the striker [002, eq. 2]",
        default=0.4,
        maximum=1e3,
        display_unit="kg",
        symbol="m_3",
        group="masses",
    ),
    positive(
        "power_spring_rate",
        "N/m",
        "c_1: rate of the power spring [002, eq. 1]",
        default=50000.0,
        maximum=1e9,
        display_unit="N/mm",
        symbol="c_1",
        group="springs",
    ),
    positive(
        "auxiliary_spring_rate",
        "N/m",
        "c_2: rate of the auxiliary spring [002, eq. 1]",
        default=2000.0,
        maximum=1e9,
        display_unit="N/mm",
        symbol="c_2",
        group="springs",
    ),
    positive(
        "return_spring_rate",
        "N/m",
        "c_3: rate of the return spring [002, eq. 2]",
        default=52000.0,
        maximum=1e9,
        display_unit="N/mm",
        symbol="c_3",
        group="springs",
    ),
    _preload(
        "power_spring_preload",
        "λ_1: preload deflection of the power spring [002, eq. 1]",
        0.002,
        "λ_1",
    ),
    _preload(
        "auxiliary_spring_preload",
        "λ_2: preload deflection of the auxiliary spring [002, eq. 1]",
        0.008,
        "λ_2",
    ),
    _preload(
        "return_spring_preload",
        "λ_3: preload deflection of the return spring [002, eq. 2]",
        0.0021,
        "λ_3",
    ),
    positive(
        "release_travel",
        "m",
        "h_1: axial travel of half-coupling and shaft at which the striker is released "
        "[002, eq. 1]",
        default=0.005,
        maximum=0.5,
        display_unit="mm",
        symbol="h_1",
        group="geometry",
    ),
    positive(
        "engagement_height",
        "m",
        "h_2: travel of the striker into full engagement with the anvil [002, eq. 2]",
        default=0.004,
        maximum=0.5,
        display_unit="mm",
        symbol="h_2",
        group="geometry",
    ),
    positive(
        "jaw_height",
        "m",
        "h_3: height of the anvil's jaws, the striker's return travel [002, eq. 3]",
        default=0.0035,
        maximum=0.5,
        display_unit="mm",
        symbol="h_3",
        group="geometry",
    ),
    Param(
        "engagement_angle",
        "rad",
        "φ_eng: the anvil's opening, the angle the flywheel turns while the striker must "
        "engage [002, after eq. 5]",
        default=math.radians(120.0),
        minimum=0.0,
        exclusive_minimum=True,
        maximum=2.0 * math.pi,
        display_unit="deg",
        symbol="φ_eng",
        group="geometry",
    ),
    friction_coefficient(
        "roller_friction",
        "f: friction coefficient of the rollers on the cones [002, eq. 4]",
        default=0.1,
        symbol="f",
        group="springs",
    ),
    Param(
        "gravity",
        "m/s^2",
        "g: gravity along the stroke towards the anvil [002, eqs. 2-4]; 9.80665 for the "
        "paper's vertical tool, 0 for a horizontal one, negative for a tool pointing up",
        default=G0,
        minimum=-100.0,
        maximum=100.0,
        display_unit="m/s^2",
        symbol="g",
        group="geometry",
    ),
)

_OUTPUTS: tuple[Output, ...] = (
    Output(
        "release_speed",
        "rad/s",
        "ω_M: flywheel speed when the half-coupling reaches h_1 and frees the striker "
        "[002, after eq. 4] (simulation: the first crossing of h_1)",
        display_unit="rpm",
    ),
    Output(
        "spin_up_time",
        "s",
        "time from motor start to release [002, eq. 1]",
        display_unit="ms",
    ),
    Output("oscillation_B", "m/s^2", "B of the striker's stage-2 motion [002, eq. 5]"),
    Output("oscillation_k", "rad/s", "k of the striker's stage-2 motion [002, eq. 5]"),
    Output(
        "max_striker_travel",
        "m",
        "2B/k²: the farthest the springs carry the striker in stage 2 [002, eq. 5]",
        display_unit="mm",
    ),
    Output(
        "engagement_time",
        "s",
        "time for the striker to travel h_2, arccos(1 − h_2k²/B)/k [002, eq. 5]; null if never",
        display_unit="ms",
    ),
    Output(
        "engagement_window",
        "s",
        "φ_eng/ω_M: time the anvil's opening takes to pass [002, after eq. 5]",
        display_unit="ms",
    ),
    Output(
        "engagement_start",
        "s",
        "time from motor start at which the striker is freed and the engagement window "
        "opens (= spin_up_time); with engagement_end it places the window on the time series",
        display_unit="ms",
    ),
    Output(
        "engagement_end",
        "s",
        "time from motor start at which the anvil's opening has passed: "
        "spin_up_time + engagement_window",
        display_unit="ms",
    ),
    Output(
        "full_engagement",
        "1",
        "true when the striker reaches h_2 inside the window (no edge blow)",
        kind="bool",
    ),
    Output(
        "engagement_margin",
        "1",
        "(window − engagement time)/window: the spare fraction of the window; negative means "
        "an edge blow",
    ),
    Output(
        "spring_height_limit",
        "m",
        "2M_2g/(c_3 − c_1): the paper's height limit for balanced preloads [002, eq. 6]; null "
        "when c_3 ≤ c_1 (no limit)",
        display_unit="mm",
    ),
    Output(
        "min_return_spring_rate",
        "N/m",
        "smallest c_3 that brings the striker back the jaw height from rest [002, eq. 3]",
        display_unit="N/mm",
    ),
    Output(
        "relock_margin",
        "N",
        "c_2λ_2 − c_3λ_3f: must be positive for the shaft to re-lock [002, eq. 4]",
    ),
    Output(
        "return_time",
        "s",
        "duration of stage 3, the striker's return over h_3 [002, eq. 3]",
        display_unit="ms",
    ),
    Output(
        "relock_time",
        "s",
        "duration of stage 4, the stepped shaft's travel back over h_1 [002, eq. 4]",
        display_unit="ms",
    ),
    Output(
        "time",
        "s",
        "time from motor start (simulation)",
        series=True,
        display_unit="ms",
        plot=Plot(windows=(Window("engagement", "engagement_start", "engagement_end"),)),
    ),
    Output(
        "flywheel_speed",
        "rad/s",
        "flywheel speed: spin-up, ω_M during engagement, 0 after the blow (simulation)",
        series=True,
        x="time",
        display_unit="rpm",
    ),
    Output(
        "z1",
        "m",
        "z_1: half-coupling travel in stage 1, held at h_1 afterwards (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "z2",
        "m",
        "z_2: striker travel towards the anvil in stage 2, held at h_2 afterwards (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "z3",
        "m",
        "z_3: striker return travel in stage 3, held afterwards (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "z4",
        "m",
        "stepped shaft's return travel in stage 4 (the paper's z_2 of eq. 4) (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
)

REFERENCE_DESIGN: dict[str, Any] = {p.name: p.default for p in _INPUTS if p.default is not None}

HORIZONTAL_DESIGN: dict[str, Any] = {**REFERENCE_DESIGN, "gravity": 0.0}

RARE_IMPACT = ModelSpec(
    name="impact.rare",
    title="Rare-impact wrench: striker engagement",
    family="impact",
    summary=(
        "Release speed, spin-up time and whether the axially moving striker engages the "
        "anvil fully (no edge blow), with the paper's spring conditions checked."
    ),
    source=(
        "[002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a "
        "rare-impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. "
        "The paper gives no numeric example: the defaults are a plausible reference design."
    ),
    inputs=_INPUTS,
    outputs=_OUTPUTS,
    rungs=(
        Rung(
            "closed_form",
            "quasi-static spin-up (the paper's release speed, any cone angle) and the exact "
            "stage 2-4 solutions",
            _closed_form_estimate,
            typical_error="1e-3 in release speed (estimated per design from the spin-up rate)",
            typical_time="~60 µs",
        ),
        Rung(
            "simulation",
            "stage 1 integrated in time (flywheel from rest, first crossing of h_1), stages "
            "2-4 exact; time series",
            _simulation_estimate,
            typical_error="≤ 1e-6 (measured ~1e-9 against a tight DOP853 reference)",
            typical_time="~0.3 ms (plus a one-off 1-3 s numba load in a fresh process)",
            fallback="closed_form",
        ),
    ),
    compute=_compute,
    examples=(REFERENCE_DESIGN, HORIZONTAL_DESIGN),
    vectorized=_vectorized,
    vector_rungs=("closed_form",),
)
