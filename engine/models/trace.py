"""Model specs for a tightening trace read against the joint (``trace.analysis``) and the
controller program derived from the joint (``trace.program``).

The detection and the rate relations live in :mod:`engine.physics.trace`; the joint's
compliance, its preload window and its bolt come from the joint model (``joint.vdi2230``,
whose input declarations these models take as they are), the yield law and the snug torque
of torque-then-angle from :mod:`engine.physics.preload` and
:mod:`engine.physics.preload_methods`. This module reads the request, splits the trace into
steps, refuses what cannot be read, and turns the numbers into verdicts.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..core.errors import InputOutOfRange
from ..core.params import DEG, positive, quantity, samples
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Plot,
    Result,
    RunContext,
    Rung,
    Window,
    fixed_error,
)
from ..core.text import q
from ..physics import joint as jt
from ..physics import preload as pl
from ..physics import trace as tr
from ..physics.preload_methods import torque_then_angle
from ..procedures.bolt import Bolt, resolve_bolt
from .joint import JOINT_INPUTS
from .joint import VDI2230 as JOINT
from .preload import CONTROL as PRELOAD_CONTROL

SOURCE = (
    "[004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's "
    "compliance and torque coefficient); gradient-drop yield detection as controllers do it "
    "[Desoutter-CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 "
    "R0–R13 (joint.vdi2230)"
)

#: Fewest samples a trace (and its analysed step) may have.
MIN_TRACE_SAMPLES = 20
#: Fewest samples the elastic window must hold for a rate.
MIN_WINDOW_SAMPLES = 5
MAX_TORQUE = 1e5

# --------------------------------------------------------------------------- inputs

TRACE_INPUTS: tuple[Param, ...] = (
    samples(
        "angle",
        "rad",
        "Angle of each sample as the tool recorded it (give {'values': [...], 'unit': 'deg'} "
        "for degrees)",
        required=True,
        minimum=-1e4,
        maximum=1e4,
        min_length=MIN_TRACE_SAMPLES,
        symbol="θ",
        group="trace",
    ),
    samples(
        "torque",
        "N*m",
        "Torque of each sample, as many as angles; a loosening is negative",
        required=True,
        minimum=-MAX_TORQUE,
        maximum=MAX_TORQUE,
        min_length=MIN_TRACE_SAMPLES,
        symbol="T",
        group="trace",
    ),
    samples(
        "time",
        "s",
        "Time of each sample (optional), as many as angles, never decreasing",
        minimum=0.0,
        maximum=1e6,
        min_length=MIN_TRACE_SAMPLES,
        symbol="t",
        group="trace",
    ),
    positive(
        "tool_stiffness",
        "N*m/rad",
        "Torsional stiffness c_t of spindle, socket and extensions between the angle "
        "encoder and the nut (in series); absent: rigid",
        maximum=1e9,
        symbol="c_t",
        group="tool",
    ),
    Param(
        "step",
        "1",
        "Which step of a multi-step trace to analyse, counted from 1; 0: the last",
        default=0,
        kind="int",
        minimum=0,
        maximum=100,
        group="analysis",
    ),
    Param(
        "angle_tolerance",
        "rad",
        "Largest backward jitter of the angle within a step before the step is refused",
        default=0.5 * DEG,
        minimum=0.0,
        maximum=10.0 * DEG,
        display_unit="deg",
        group="analysis",
    ),
    Param(
        "gradient_window",
        "rad",
        "Angle span of the sliding least-squares gradient",
        default=2.0 * DEG,
        minimum=0.05 * DEG,
        maximum=90.0 * DEG,
        display_unit="deg",
        group="analysis",
    ),
    Param(
        "elastic_window_low",
        "1",
        "Lower end of the elastic window, as a share of the step's peak torque",
        default=tr.ELASTIC_WINDOW[0],
        minimum=0.05,
        maximum=0.9,
        group="analysis",
    ),
    Param(
        "elastic_window_high",
        "1",
        "Upper end of the elastic window, as a share of the step's peak torque",
        default=tr.ELASTIC_WINDOW[1],
        minimum=0.1,
        maximum=0.95,
        group="analysis",
    ),
    Param(
        "yield_gradient_fraction",
        "1",
        "Yield point: the gradient has fallen to this share of the elastic rate (50 % as "
        "controllers default to it)",
        default=tr.YIELD_GRADIENT_FRACTION,
        minimum=0.1,
        maximum=0.95,
        group="analysis",
    ),
    Param(
        "snug_gradient_fraction",
        "1",
        "Snug point: the gradient first reaches this share of the elastic rate",
        default=tr.SNUG_GRADIENT_FRACTION,
        minimum=0.05,
        maximum=0.95,
        group="analysis",
    ),
    Param(
        "bolt_compliance_uncertainty",
        "1",
        "Relative uncertainty ± of the bolt's compliance δ_S",
        default=0.05,
        minimum=0.0,
        maximum=0.9,
        display_unit="%",
        group="uncertainty",
    ),
    Param(
        "clamped_compliance_uncertainty",
        "1",
        "Relative uncertainty ± of the clamped parts' compliance δ_P (the cone model's)",
        default=0.2,
        minimum=0.0,
        maximum=0.9,
        display_unit="%",
        group="uncertainty",
    ),
    Param(
        "friction_split_min",
        "1",
        "Smallest ratio μ_K/μ_G of bearing to thread friction thought possible",
        default=0.5,
        minimum=0.05,
        maximum=20.0,
        group="uncertainty",
    ),
    Param(
        "friction_split_max",
        "1",
        "Largest ratio μ_K/μ_G of bearing to thread friction thought possible",
        default=2.0,
        minimum=0.05,
        maximum=20.0,
        group="uncertainty",
    ),
    Param(
        "yield_allowed",
        "1",
        "The strategy tightens into yield (yield or angle control past yield): a yield point "
        "is then no fault",
        default=False,
        kind="bool",
        group="analysis",
    ),
)

# the joint's inputs as the trace models read them: the friction box's upper ends and the
# torque tolerance bound the predicted envelope here whether or not a torque is specified
_JOINT_INPUTS = tuple(replace(p, used_with=None) for p in JOINT_INPUTS)

INPUTS: tuple[Param, ...] = (*TRACE_INPUTS, *_JOINT_INPUTS)
_JOINT_NAMES = frozenset(p.name for p in JOINT_INPUTS)

# --------------------------------------------------------------------------- the joint


@dataclass(frozen=True)
class JointFacts:
    """What the trace is read against: the bolt, compliances, friction box and windows."""

    bolt: Bolt
    bolt_compliance: float
    clamped_compliance: float
    smallest_area: float
    smallest_diameter: float
    assembly_preload_min: float
    permissible_preload: float
    friction_box: tuple[float, float, float, float]  # μ_G,min, μ_G,max, μ_K,min, μ_K,max
    prevailing_torque: float
    utilization: float
    notes: tuple[str, ...]


def _torque_per_preload(j: JointFacts, thread: Any, bearing: Any) -> Any:
    """k(μ_G, μ_K) of VDI 2230-1 R13 for the joint's bolt, [m]."""
    b = j.bolt
    kt, kb = pl.tightening_torque_per_preload(
        b.pitch,
        b.pitch_diameter,
        b.diameter,
        thread,
        bearing,
        b.bearing_outer_diameter,
        b.hole_diameter,
    )
    return kt + kb


def _yield_preload(j: JointFacts, thread_friction: Any, utilization: float = 1.0) -> Any:
    """F at which the equivalent stress reaches ν R_p0.2 at μ_G (VDI 2230-1 R7), [N]."""
    b = j.bolt
    beta = pl.torsion_factor(b.pitch, b.pitch_diameter, j.smallest_diameter, thread_friction)
    return pl.assembly_preload(b.yield_strength, j.smallest_area, beta, utilization)


def _friction(j: JointFacts, k: Any, split: Any = 1.0) -> Any:
    """μ_G for a torque coefficient k with μ_K = split · μ_G (split 1: μ_ges)."""
    b = j.bolt
    return tr.friction_from_torque_per_preload(
        k, b.pitch, b.pitch_diameter, b.diameter, b.bearing_outer_diameter, b.hole_diameter, split
    )


def _joint(x: Mapping[str, Any], ctx: RunContext) -> JointFacts:
    """The joint model run on the joint's inputs of this request (once per request)."""

    def solve() -> JointFacts:
        xj = {k: v for k, v in x.items() if k in _JOINT_NAMES}
        inner = RunContext(
            rung=JOINT.rungs[0].name,
            outputs=frozenset(JOINT.scalar_outputs),
            tolerance=ctx.tolerance,
            deadline=ctx.deadline,
            cancel=ctx.cancel,
        )
        r = JOINT.compute(xj, inner)
        bolt, _ = resolve_bolt(xj)
        v = r.values
        mu_g = float(x["thread_friction_min"])
        mu_k = float(x["bearing_friction_min"])
        mu_g_hi = mu_g if x.get("thread_friction_max") is None else float(x["thread_friction_max"])
        mu_k_hi = (
            mu_k if x.get("bearing_friction_max") is None else float(x["bearing_friction_max"])
        )
        return JointFacts(
            bolt=bolt,
            bolt_compliance=float(v["bolt_compliance"]),  # type: ignore[arg-type]
            clamped_compliance=float(v["clamped_compliance"]),  # type: ignore[arg-type]
            smallest_area=float(v["smallest_area"]),  # type: ignore[arg-type]
            smallest_diameter=float(v["smallest_diameter"]),  # type: ignore[arg-type]
            assembly_preload_min=float(v["assembly_preload_min"]),  # type: ignore[arg-type]
            permissible_preload=float(v["permissible_preload"]),  # type: ignore[arg-type]
            friction_box=(mu_g, mu_g_hi, mu_k, mu_k_hi),
            prevailing_torque=float(x["prevailing_torque"]),
            utilization=float(x["utilization"]),
            notes=tuple(n for n in r.notes if "D_A not given" in n),
        )

    facts: JointFacts = ctx.once("trace.joint", solve)
    return facts


def _compliance_range(j: JointFacts, x: Mapping[str, Any]) -> tuple[float, float, float]:
    """(δ nominal, δ low, δ high) from the stated uncertainties of δ_S and δ_P."""
    u_s, u_p = float(x["bolt_compliance_uncertainty"]), float(x["clamped_compliance_uncertainty"])
    ds, dp = j.bolt_compliance, j.clamped_compliance
    return ds + dp, ds * (1 - u_s) + dp * (1 - u_p), ds * (1 + u_s) + dp * (1 + u_p)


def _split_range(x: Mapping[str, Any]) -> tuple[float, float]:
    lo, hi = float(x["friction_split_min"]), float(x["friction_split_max"])
    if hi < lo:
        raise InputOutOfRange(
            f"friction_split_max = {hi:g} is below friction_split_min = {lo:g}: must be ≥ {lo:g}",
            field="friction_split_max",
        )
    return lo, hi


# --------------------------------------------------------------------------- the trace


@dataclass(frozen=True)
class Step:
    """The analysed step: its samples at the nut, and where it lies in the trace."""

    angle: np.ndarray  # at the nut, [rad]
    torque: np.ndarray
    start: int
    count: int  # steps found
    number: int  # 1-based


def _read_trace(x: Mapping[str, Any]) -> Step:
    """The trace checked, split into steps, one step chosen and put at the nut."""
    angle = np.asarray(x["angle"], dtype=float)
    torque = np.asarray(x["torque"], dtype=float)
    n = angle.size
    if torque.size != n:
        raise InputOutOfRange(
            f"torque has {torque.size} values and angle {n}: must have one torque per angle",
            field="torque",
        )
    if x.get("time") is not None:
        time = np.asarray(x["time"], dtype=float)
        if time.size != n:
            raise InputOutOfRange(
                f"time has {time.size} values and angle {n}: must have one time per angle",
                field="time",
            )
        late = np.flatnonzero(np.diff(time) < 0.0)
        if late.size:
            i = int(late[0]) + 1
            raise InputOutOfRange(
                f"time[{i}] = {time[i]:g} s is before time[{i - 1}] = {time[i - 1]:g} s: the "
                "times must not decrease",
                field="time",
                index=i,
            )
    steps = tr.split_steps(torque, angle)
    if not steps:
        raise InputOutOfRange(
            "torque: no step found (no run of samples above 2 % of the peak torque reaching a "
            "tenth of it): the trace holds no tightening",
            field="torque",
        )
    chosen = int(x["step"])
    if chosen > len(steps):
        raise InputOutOfRange(
            f"step = {chosen} is not allowed: the trace has {len(steps)} step"
            f"{'' if len(steps) == 1 else 's'}; must be 0 (the last) to {len(steps)}",
            field="step",
        )
    number = chosen or len(steps)
    a, b = steps[number - 1]
    if b - a < MIN_TRACE_SAMPLES:
        raise InputOutOfRange(
            f"angle: step {number} holds {b - a} samples (indices {a}…{b - 1}): must hold at "
            f"least {MIN_TRACE_SAMPLES} to be analysed; record at a finer interval",
            field="angle",
        )
    back = tr.first_backward(angle[a:b], float(x["angle_tolerance"]))
    if back >= 0:
        i = a + back
        raise InputOutOfRange(
            f"angle[{i}] = {angle[i] / DEG:.4g}° runs backwards within step {number} (more than "
            f"{quantity(float(x['angle_tolerance']), 'deg')} behind the largest angle before "
            "it): a step must turn one way; a loosening is a step of its own",
            field="angle",
            index=i,
        )
    stiffness = x.get("tool_stiffness")
    at_nut = tr.nut_angle(angle[a:b], torque[a:b], None if stiffness is None else float(stiffness))
    return Step(np.asarray(at_nut), torque[a:b], a, len(steps), number)


def _window_samples(angle: np.ndarray, torque: np.ndarray, span: float, low: float) -> int:
    """Samples of the gradient window: the angle span over the mean step of the loaded
    samples (torque above the elastic window's lower end), where a two-speed controller
    runs slow; the mean over the whole loaded span, not a median of steps, which an
    encoder's quantisation (many steps of 0, a few of one count) would mislead."""
    loaded = np.flatnonzero(torque >= low * float(np.max(torque)))
    turned = float(angle[loaded[-1]] - angle[loaded[0]]) if loaded.size > 1 else 0.0
    pitch = turned / (loaded.size - 1) if turned > 0.0 else span
    return int(min(max(round(span / pitch), 3), max(angle.size // 4, 3)))


@dataclass(frozen=True)
class Reading:
    """What the detection found on the analysed step."""

    rate: float
    intercept: float
    zero_angle: float
    snug: int
    yield_at: int
    peak: int
    window: tuple[int, int]
    gradient: np.ndarray


def _detect(step: Step, x: Mapping[str, Any], prevailing: float) -> Reading:
    lo, hi = float(x["elastic_window_low"]), float(x["elastic_window_high"])
    if hi <= lo:
        raise InputOutOfRange(
            f"elastic_window_high = {hi:g} is not above elastic_window_low = {lo:g}: must be "
            f"> {lo:g}",
            field="elastic_window_high",
        )
    theta, torque = step.angle, step.torque
    window = _window_samples(theta, torque, float(x["gradient_window"]), lo)
    found = tr.detect(
        theta,
        torque,
        window,
        window_low=lo,
        window_high=hi,
        snug_fraction=float(x["snug_gradient_fraction"]),
        yield_fraction=float(x["yield_gradient_fraction"]),
        prevailing_torque=prevailing,
    )
    inside = int(found.window_last) - int(found.window_first) + 1
    if inside < MIN_WINDOW_SAMPLES or not float(found.rate) > 0.0:
        raise InputOutOfRange(
            f"angle: the elastic window ({lo:.0%}…{hi:.0%} of the peak torque) holds "
            f"{max(inside, 0)} samples with a rising torque: must hold at least "
            f"{MIN_WINDOW_SAMPLES}; the step does not rise steadily enough to be read",
            field="angle",
        )
    return Reading(
        rate=float(found.rate),
        intercept=float(found.intercept),
        zero_angle=float(found.zero_angle),
        snug=int(found.snug),
        yield_at=int(found.yield_at),
        peak=int(found.peak),
        window=(int(found.window_first), int(found.window_last)),
        gradient=np.asarray(found.gradient),
    )


# --------------------------------------------------------------------------- trace.analysis


def _analysis(x: Mapping[str, Any], ctx: RunContext) -> Result:
    split_lo, split_hi = _split_range(x)
    step = _read_trace(x)
    j = _joint(x, ctx)
    m_u = j.prevailing_torque
    reading = _detect(step, x, m_u)
    bolt = j.bolt
    delta, delta_lo, delta_hi = _compliance_range(j, x)
    pitch = bolt.pitch
    mu_g_lo, mu_g_hi, mu_k_lo, mu_k_hi = j.friction_box

    # the joint's prediction over its friction box
    k_pred_lo = float(_torque_per_preload(j, mu_g_lo, mu_k_lo))
    k_pred_hi = float(_torque_per_preload(j, mu_g_hi, mu_k_hi))
    rate_lo = float(tr.elastic_torque_rate(k_pred_lo, delta, pitch))
    rate_hi = float(tr.elastic_torque_rate(k_pred_hi, delta, pitch))
    fy_lo_mu, fy_hi_mu = float(_yield_preload(j, mu_g_lo)), float(_yield_preload(j, mu_g_hi))
    ty_lo, ty_hi = k_pred_lo * fy_lo_mu + m_u, k_pred_hi * fy_hi_mu + m_u
    sy_lo_mu = float(pl.nut_rotation_angle(fy_lo_mu, delta, pitch))
    sy_hi_mu = float(pl.nut_rotation_angle(fy_hi_mu, delta, pitch))

    # what the measured rate says: k, friction, preload, with the compliance's bounds
    rate = reading.rate
    k = float(tr.torque_per_preload_from_rate(rate, delta, pitch))
    k_lo = float(tr.torque_per_preload_from_rate(rate, delta_lo, pitch))
    k_hi = float(tr.torque_per_preload_from_rate(rate, delta_hi, pitch))
    mu = float(_friction(j, k))
    mu_lo, mu_hi = float(_friction(j, k_lo)), float(_friction(j, k_hi))
    thread = [float(_friction(j, kk, s)) for kk in (k_lo, k_hi) for s in (split_lo, split_hi)]
    mu_g_min, mu_g_max = min(thread), max(thread)
    peak = reading.peak
    t_final, th_final = float(step.torque[peak]), float(step.angle[peak])
    f = float(tr.preload_from_torque(t_final, k, m_u))
    f_lo = float(tr.preload_from_torque(t_final, k_hi, m_u))
    f_hi = float(tr.preload_from_torque(t_final, k_lo, m_u))
    f_yield = float(_yield_preload(j, mu_g_max))  # the lowest yield preload the split allows

    snug_i, yield_i = reading.snug, reading.yield_at
    yielded = yield_i >= 0
    window_a, window_b = reading.window
    values: dict[str, Any] = {
        "steps_found": step.count,
        "step_analysed": step.number,
        "snug_angle": float(step.angle[snug_i]),
        "snug_torque": float(step.torque[snug_i]),
        "zero_preload_angle": reading.zero_angle,
        "elastic_window_start": float(step.angle[window_a]),
        "elastic_window_end": float(step.angle[window_b]),
        "elastic_rate": rate,
        "predicted_rate_min": rate_lo,
        "predicted_rate_max": rate_hi,
        "yield_detected": yielded,
        "yield_angle": float(step.angle[yield_i]) if yielded else None,
        "yield_torque": float(step.torque[yield_i]) if yielded else None,
        "snug_to_yield_angle": (
            float(step.angle[yield_i]) - reading.zero_angle if yielded else None
        ),
        "predicted_yield_torque_min": ty_lo,
        "predicted_yield_torque_max": ty_hi,
        "predicted_snug_to_yield_min": min(sy_lo_mu, sy_hi_mu),
        "predicted_snug_to_yield_max": max(sy_lo_mu, sy_hi_mu),
        "final_angle": th_final,
        "final_torque": t_final,
        "torque_per_preload": k,
        "total_friction": mu,
        "total_friction_min": mu_lo,
        "total_friction_max": mu_hi,
        "thread_friction_low": mu_g_min,
        "thread_friction_high": mu_g_max,
        "preload": f,
        "preload_min": f_lo,
        "preload_max": f_hi,
        "yield_preload_min": f_yield,
        "assembly_preload_min": j.assembly_preload_min,
        "permissible_preload": j.permissible_preload,
    }
    in_window = f_lo >= j.assembly_preload_min * (1 - 1e-12) and f_hi <= j.permissible_preload * (
        1 + 1e-12
    )
    values["preload_in_window"] = in_window
    kn = "kN"
    checks = [
        Check(
            "preload_above_minimum",
            f_lo >= j.assembly_preload_min * (1 - 1e-12),
            f"preload {q(f_lo, kn)}…{q(f_hi, kn)} "
            f"{'≥' if f_lo >= j.assembly_preload_min else 'reaches below'} the joint's "
            f"F_M,min = {q(j.assembly_preload_min, kn)}",
        ),
        Check(
            "preload_below_permissible",
            f_hi <= j.permissible_preload * (1 + 1e-12),
            f"preload {q(f_lo, kn)}…{q(f_hi, kn)} "
            f"{'≤' if f_hi <= j.permissible_preload else 'reaches above'} F_M,zul = "
            f"{q(j.permissible_preload, kn)} (VDI 2230-1 R7)",
        ),
        Check(
            "friction_in_joint_range",
            mu_hi >= float(_friction(j, k_pred_lo)) and mu_lo <= float(_friction(j, k_pred_hi)),
            f"total friction μ_ges = {mu:.3f} ({mu_lo:.3f}…{mu_hi:.3f}) against the joint's "
            f"{float(_friction(j, k_pred_lo)):.3f}…{float(_friction(j, k_pred_hi)):.3f}",
        ),
    ]
    if yielded:
        allowed = bool(x["yield_allowed"])
        checks.append(
            Check(
                "yield",
                allowed,
                f"yield point at {q(float(step.angle[yield_i]), 'deg', fmt='.4g')}, "
                f"{float(step.torque[yield_i]):.4g} N·m (gradient below "
                f"{float(x['yield_gradient_fraction']):.0%} of the elastic rate)"
                + ("" if allowed else ": the strategy was not meant to reach yield"),
            )
        )
    else:
        checks.append(
            Check("yield", True, "no yield point: the gradient never fell to the yield share")
        )
    notes = [
        f"step {step.number} of {step.count} analysed (samples {step.start}…"
        f"{step.start + step.angle.size - 1}); angles at the nut"
        + ("" if x.get("tool_stiffness") is None else ", the tool's wind-up T/c_t taken off"),
        f"elastic rate {rate * DEG:.4g} N·m/° by a robust line over "
        f"{float(x['elastic_window_low']):.0%}…{float(x['elastic_window_high']):.0%} of the peak "
        f"torque; predicted {rate_lo * DEG:.4g}…{rate_hi * DEG:.4g} N·m/° for μ_G "
        f"{mu_g_lo:g}…{mu_g_hi:g}, μ_K {mu_k_lo:g}…{mu_k_hi:g}",
        f"bounds from δ_S ± {float(x['bolt_compliance_uncertainty']):.0%} and δ_P ± "
        f"{float(x['clamped_compliance_uncertainty']):.0%}; the preload F = (T − M_ü)/k does "
        "not depend on the friction split, μ_G and the yield preload do (μ_K/μ_G "
        f"{split_lo:g}…{split_hi:g})",
        "snug point: the gradient first reaches "
        f"{float(x['snug_gradient_fraction']):.0%} of the elastic rate; zero-preload angle: "
        "the elastic line at the prevailing torque",
        *j.notes,
    ]
    warnings: list[str] = []
    if rate_lo > 0 and not (0.5 * rate_lo <= rate <= 2.0 * rate_hi):
        warnings.append(
            f"the measured rate {rate * DEG:.3g} N·m/° lies far outside the joint's "
            f"{rate_lo * DEG:.3g}…{rate_hi * DEG:.3g} N·m/°: check the joint's inputs, the "
            "tool's stiffness and the angle unit"
        )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=None,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=_series(ctx, step, reading, rate_lo, rate_hi, m_u),
    )


def _series(
    ctx: RunContext, step: Step, reading: Reading, rate_lo: float, rate_hi: float, m_u: float
) -> dict[str, list[float]]:
    if not ctx.wants("trace_angle", "trace_torque", "envelope_low", "envelope_high", "gradient"):
        return {}
    theta = step.angle
    rise = np.maximum(theta - reading.zero_angle, 0.0)
    finite = np.isfinite(reading.gradient)
    where = np.arange(theta.size)
    grad = (
        np.interp(where, where[finite], reading.gradient[finite])  # the ends: nearest value
        if finite.any()
        else np.zeros(theta.size)
    )
    return {
        "trace_angle": theta.tolist(),
        "trace_torque": step.torque.tolist(),
        "envelope_low": (m_u + rate_lo * rise).tolist(),
        "envelope_high": (m_u + rate_hi * rise).tolist(),
        "gradient": grad.tolist(),
    }


def _o(name: str, unit: str, description: str, **kw: Any) -> Output:
    display = {"rad": "deg", "N": "kN", "N*m/rad": "N*m/deg"}.get(unit)
    if display is not None:
        kw.setdefault("display_unit", display)
    return Output(name, unit, description, **kw)


ANALYSIS_OUTPUTS: tuple[Output, ...] = (
    _o(
        "steps_found",
        "1",
        "Steps the trace splits into (torque dropping to about zero)",
        kind="int",
        symbol="",
        step="",
    ),
    _o("step_analysed", "1", "The step analysed, counted from 1", kind="int", symbol="", step=""),
    _o(
        "snug_angle",
        "rad",
        "Snug point: nut angle where the gradient first reaches its share",
        symbol="θ_snug",
        step="[Desoutter-CVIR]",
    ),
    _o("snug_torque", "N*m", "Torque at the snug point", symbol="M_snug", step="[Desoutter-CVIR]"),
    _o(
        "zero_preload_angle",
        "rad",
        "Nut angle where the elastic line meets M_ü (preload 0)",
        symbol="θ_0",
        step="VDI 2230-1 R13",
    ),
    _o(
        "elastic_window_start",
        "rad",
        "Nut angle where the elastic window begins",
        symbol="θ_el,start",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "elastic_window_end",
        "rad",
        "Nut angle where the elastic window ends",
        symbol="θ_el,end",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "elastic_rate",
        "N*m/rad",
        "Elastic torque rate dT/dθ at the nut, robust fit",
        symbol="dM/dθ",
        step="[004, eq. 8]",
    ),
    _o(
        "predicted_rate_min",
        "N*m/rad",
        "Rate the joint predicts at its lowest friction",
        symbol="dT/dθ_min",
        step="[004, eq. 8]",
    ),
    _o(
        "predicted_rate_max",
        "N*m/rad",
        "Rate the joint predicts at its highest friction",
        symbol="dT/dθ_max",
        step="[004, eq. 8]",
    ),
    _o(
        "yield_detected",
        "1",
        "A yield point was found (gradient drop)",
        kind="bool",
        symbol="",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "yield_angle",
        "rad",
        "Nut angle of the yield point (null: none)",
        symbol="θ_y",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "yield_torque",
        "N*m",
        "Torque at the yield point (null: none)",
        symbol="M_y",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "snug_to_yield_angle",
        "rad",
        "Yield angle minus the zero-preload angle (null: none)",
        symbol="θ_y − θ_0",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "predicted_yield_torque_min",
        "N*m",
        "Torque at F_M at R_p0.2 (ν = 1), lowest friction",
        symbol="M_A0.2,min",
        step="VDI 2230-1 R7/R13",
    ),
    _o(
        "predicted_yield_torque_max",
        "N*m",
        "Torque at F_M at R_p0.2 (ν = 1), highest friction",
        symbol="M_A0.2,max",
        step="VDI 2230-1 R7/R13",
    ),
    _o(
        "predicted_snug_to_yield_min",
        "rad",
        "Angle from zero preload to yield, predicted, least",
        symbol="Δθ_y,min",
        step="[004, eq. 8]",
    ),
    _o(
        "predicted_snug_to_yield_max",
        "rad",
        "Angle from zero preload to yield, predicted, most",
        symbol="Δθ_y,max",
        step="[004, eq. 8]",
    ),
    _o(
        "final_angle",
        "rad",
        "Nut angle at the step's peak torque",
        symbol="θ_f",
        step="[Desoutter-CVIR]",
    ),
    _o("final_torque", "N*m", "Peak torque of the step", symbol="M_end", step="[Desoutter-CVIR]"),
    _o(
        "torque_per_preload",
        "m",
        "k = (T − M_ü)/F the measured rate implies",
        display_unit="mm",
        symbol="k",
        step="VDI 2230-1 R13",
    ),
    _o(
        "total_friction",
        "1",
        "Total friction μ_ges (μ_G = μ_K) from the measured rate",
        symbol="μ_ges",
        step="VDI 2230-1 R13",
    ),
    _o(
        "total_friction_min",
        "1",
        "μ_ges at the stiff end of the compliance's uncertainty",
        symbol="μ_ges,min",
        step="VDI 2230-1 R13",
    ),
    _o(
        "total_friction_max",
        "1",
        "μ_ges at the soft end of the compliance's uncertainty",
        symbol="μ_ges,max",
        step="VDI 2230-1 R13",
    ),
    _o(
        "thread_friction_low",
        "1",
        "Lowest μ_G over compliance and friction split",
        symbol="μ_G,min",
        step="VDI 2230-1 R13",
    ),
    _o(
        "thread_friction_high",
        "1",
        "Highest μ_G over compliance and friction split",
        symbol="μ_G,max",
        step="VDI 2230-1 R13",
    ),
    _o(
        "preload",
        "N",
        "Preload at the final torque, F = (T − M_ü)/k",
        symbol="F_V",
        step="VDI 2230-1 R13",
    ),
    _o(
        "preload_min",
        "N",
        "Preload's lower bound (soft end of the compliance)",
        symbol="F_M,min",
        step="VDI 2230-1 R13",
    ),
    _o(
        "preload_max",
        "N",
        "Preload's upper bound (stiff end of the compliance)",
        symbol="F_M,max",
        step="VDI 2230-1 R13",
    ),
    _o(
        "yield_preload_min",
        "N",
        "Preload at R_p0.2 (ν = 1) at the highest μ_G the split allows",
        symbol="F_M0.2,min",
        step="VDI 2230-1 R7",
    ),
    _o(
        "assembly_preload_min",
        "N",
        "The joint's F_M,min (lower end of its window)",
        symbol="F_M,min",
        step="VDI 2230-1 R5",
    ),
    _o(
        "permissible_preload",
        "N",
        "The joint's F_M,zul (upper end of its window)",
        symbol="F_M,zul",
        step="VDI 2230-1 R7",
    ),
    _o(
        "preload_in_window",
        "1",
        "Preload bounds within F_M,min…F_M,zul",
        kind="bool",
        symbol="",
        step="VDI 2230-1 R5/R7",
    ),
    _o(
        "trace_angle",
        "rad",
        "Nut angle of each sample of the step",
        series=True,
        plot=Plot(
            windows=(
                Window("elastic window", "elastic_window_start", "elastic_window_end"),
                Window("yield…stop", "yield_angle", "final_angle"),
            )
        ),
    ),
    _o("trace_torque", "N*m", "Torque of each sample of the step", series=True, x="trace_angle"),
    _o(
        "envelope_low",
        "N*m",
        "Torque the joint predicts at its lowest friction, from the zero-preload angle",
        series=True,
        x="trace_angle",
    ),
    _o(
        "envelope_high",
        "N*m",
        "Torque the joint predicts at its highest friction, from the zero-preload angle",
        series=True,
        x="trace_angle",
    ),
    _o(
        "gradient",
        "N*m/rad",
        "Sliding gradient dT/dθ (0 at the ends)",
        series=True,
        x="trace_angle",
    ),
)

ANALYSIS_RUNG = Rung(
    "detection",
    "Gradient and robust elastic line on the samples, the joint's compliance and R13's torque "
    "coefficient inverted. Its estimate, 0, is the arithmetic's; the answer's uncertainty is "
    "in its bounds (compliance, friction split), measured over 200 synthetic traces from an "
    "independent generator (tests/validation/test_trace_synthetic.py): the true preload and "
    "total friction inside the bounds in 200 of 200, the rate within ±0.8 %, the yield point "
    "called right in 196 of 196 traces whose 50 % point did not fall in the last window",
    fixed_error(0.0),
    estimate_kind="typical",
    typical_exceeded="0 of 200 synthetic traces for the preload's and friction's bounds",
    typical_error="typical: 0 for the arithmetic; the bounds carry the compliance's uncertainty",
    typical_time="about 0.5 ms (280 samples, the joint solved once)",
)


def _example_trace() -> dict[str, tuple[float, ...]]:
    """An M12 8.8 trace through 2 × 20 mm steel (made up, rounded as a controller logs it):
    run-down at 0.3 N·m, a 2° snug knee at 20°, the rate of R13 with μ = 0.12 (2.35 N·m/°),
    a bolt yielding at about 93 N·m. For the form and the tests; not a measurement."""
    rate = 2.351  # N·m/°, the made-up joint's
    t_yield = 93.0
    angles = [0.25 * i for i in range(281)]  # 0…70°
    torques = []
    for a in angles:
        soft = 1.0 * math.log1p(math.exp((a - 20.0) / 1.0))  # softplus knee, ° past snug
        elastic = 0.3 + rate * soft
        plastic_from = 0.85 * t_yield
        if elastic > plastic_from:
            top = 1.1 * t_yield - plastic_from
            elastic = plastic_from + top * (1.0 - math.exp(-(elastic - plastic_from) / top))
        torques.append(round(elastic, 2))
    return {"angle": tuple(round(a * DEG, 6) for a in angles), "torque": tuple(torques)}


#: The M12 example's joint: the joint model's second example (μ 0.08…0.16, 0.4 N·m M_ü off).
M12_JOINT: dict[str, Any] = {
    "thread": "M12 8.8",
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "thread_friction_min": 0.08,
    "thread_friction_max": 0.16,
    "bearing_friction_min": 0.08,
    "bearing_friction_max": 0.16,
}

ANALYSIS = ModelSpec(
    answer=(
        Answer("preload", "F_V", check="preload_below_permissible"),
        Answer("total_friction", "μ_ges", check="friction_in_joint_range"),
        Answer("elastic_rate", "dM/dθ"),
        Answer("final_torque", "M_end"),
        Answer("yield_torque", "M_y", check="yield"),
    ),
    name="trace.analysis",
    title="Tightening trace read against the joint: snug, rate, yield, friction and preload",
    family="trace",
    summary=(
        "A torque–angle trace as a nut-runner records it, with the joint it tightened: the "
        "steps, the snug point, the elastic torque rate and the rate the joint predicts, "
        "the yield point by gradient drop, the total friction the rate implies through the "
        "joint's compliance, the preload at the end with bounds from the compliance's and "
        "the friction split's uncertainty, and verdicts against F_M,min…F_M,zul and yield."
    ),
    source=SOURCE,
    inputs=INPUTS,
    outputs=ANALYSIS_OUTPUTS,
    rungs=(ANALYSIS_RUNG,),
    compute=_analysis,
    assumptions=(
        "once snug the preload rises linearly with the nut angle ([004, eq. 8]); the bolt's "
        "own twist under the thread torque is not modelled (it is within the compliance's "
        "uncertainty)",
    ),
    examples=(
        {**M12_JOINT, **_example_trace()},
        {**M12_JOINT, **_example_trace(), "tool_stiffness": 20000.0, "yield_allowed": True},
    ),
)


# --------------------------------------------------------------------------- trace.program

STRATEGIES = ("torque_angle", "yield")
_SHARED = {p.name: p for p in TRACE_INPUTS}

PROGRAM_INPUTS: tuple[Param, ...] = (
    Param(
        "strategy",
        "1",
        "Tightening strategy: torque then angle to the middle of the joint's window, or "
        "yield-point control (gradient drop)",
        default="torque_angle",
        kind="choice",
        choices=STRATEGIES,
        choice_labels=("torque then angle", "yield point (gradient)"),
        group="program",
    ),
    next(p for p in PRELOAD_CONTROL.inputs if p.name == "snug_fraction"),
    _SHARED["yield_gradient_fraction"],
    _SHARED["bolt_compliance_uncertainty"],
    _SHARED["clamped_compliance_uncertainty"],
    *_JOINT_INPUTS,
)

PROGRAM_OUTPUTS: tuple[Output, ...] = (
    _o(
        "strategy",
        "1",
        "The strategy the settings are for",
        kind="str",
        symbol="",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "target_preload",
        "N",
        "Preload aimed at: the middle of F_M,min…F_M,zul, or yield",
        symbol="F_M,target",
        step="VDI 2230-1 R5/R7",
    ),
    _o(
        "snug_torque",
        "N*m",
        "Snug torque: where the angle count starts (with M_ü)",
        symbol="M_snug",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "final_angle",
        "rad",
        "Angle from snug to stop (torque_angle; null for yield)",
        symbol="θ_A",
        step="[004, eq. 8]",
    ),
    _o(
        "angle_min",
        "rad",
        "Angle window from snug, lower limit",
        symbol="θ_min",
        step="[004, eq. 8]",
    ),
    _o(
        "angle_max",
        "rad",
        "Angle window from snug, upper limit",
        symbol="θ_max",
        step="[004, eq. 8]",
    ),
    _o(
        "torque_min",
        "N*m",
        "Torque monitoring window at the stop, lower limit",
        symbol="M_min",
        step="VDI 2230-1 R13",
    ),
    _o(
        "torque_max",
        "N*m",
        "Torque monitoring window at the stop, upper limit",
        symbol="M_max",
        step="VDI 2230-1 R13",
    ),
    _o(
        "rate_min",
        "N*m/rad",
        "Elastic torque rate expected at the lowest friction",
        symbol="dT/dθ_min",
        step="[004, eq. 8]",
    ),
    _o(
        "rate_max",
        "N*m/rad",
        "Elastic torque rate expected at the highest friction",
        symbol="dT/dθ_max",
        step="[004, eq. 8]",
    ),
    _o(
        "gradient_threshold_min",
        "N*m/rad",
        "Yield gradient: the share of rate_min",
        symbol="g_min",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "gradient_threshold_max",
        "N*m/rad",
        "Yield gradient: the share of rate_max",
        symbol="g_max",
        step="[Desoutter-CVIR]",
    ),
    _o(
        "preload_min",
        "N",
        "Lowest preload the program gives over friction and compliance",
        symbol="F_M,min",
        step="VDI 2230-1 R13",
    ),
    _o(
        "preload_max",
        "N",
        "Highest preload the program gives over friction and compliance",
        symbol="F_M,max",
        step="VDI 2230-1 R13",
    ),
    _o(
        "window_fits",
        "1",
        "The program keeps the preload within F_M,min…F_M,zul",
        kind="bool",
        symbol="",
        step="VDI 2230-1 R5/R7",
    ),
)


def _program(x: Mapping[str, Any], ctx: RunContext) -> Result:
    j = _joint(x, ctx)
    pitch, m_u = j.bolt.pitch, j.prevailing_torque
    delta, delta_lo, delta_hi = _compliance_range(j, x)
    mu_g_lo, mu_g_hi, mu_k_lo, mu_k_hi = j.friction_box
    k_lo = float(_torque_per_preload(j, mu_g_lo, mu_k_lo))
    k_hi = float(_torque_per_preload(j, mu_g_hi, mu_k_hi))
    k_mid = float(_torque_per_preload(j, 0.5 * (mu_g_lo + mu_g_hi), 0.5 * (mu_k_lo + mu_k_hi)))
    rate_lo = float(tr.elastic_torque_rate(k_lo, delta, pitch))
    rate_hi = float(tr.elastic_torque_rate(k_hi, delta, pitch))
    share = float(x["yield_gradient_fraction"])
    strategy = str(x["strategy"])
    f_min, f_zul = j.assembly_preload_min, j.permissible_preload
    per_radian = 1.0 / pl.nut_rotation_angle(1.0, 1.0, pitch)  # P/(2π), [m/rad]
    corners = [(k, d) for k in (k_lo, k_hi) for d in (delta_lo, delta_hi)]
    snug_share = float(x["snug_fraction"])
    notes: list[str] = [*j.notes]
    if strategy == "torque_angle":
        target = float(jt.nominal_preload(f_min, f_zul))
        plan = torque_then_angle(target, k_mid, delta, pitch, snug_share)
        m_snug = float(plan.snug_torque)
        # the snug preload each corner reaches, then the angle's preload on top of it
        angle_min = max(
            float(pl.nut_rotation_angle(f_min - m_snug / k, d, pitch)) for k, d in corners
        )
        angle_max = min(
            float(pl.nut_rotation_angle(f_zul - m_snug / k, d, pitch)) for k, d in corners
        )
        final = float(plan.angle)
        reached = [m_snug / k + final * per_radian / d for k, d in corners]
        torques = [k * f + m_u for (k, _), f in zip(corners, reached, strict=True)]
        f_lo, f_hi = min(reached), max(reached)
        notes.append(
            f"torque then angle: snug at {snug_share:.0%} of the target "
            f"{q(target, 'kN')} at the middle friction, then "
            f"{q(final, 'deg', fmt='.3g')}; the window holds F_M,min…F_M,zul at every "
            "corner of friction and compliance ([004, eq. 8])"
        )
        final_out: float | None = final
    else:
        f_y = [float(_yield_preload(j, mu)) for mu in (mu_g_lo, mu_g_hi)]
        target = max(f_y)
        m_snug = snug_share * min(f_y) * k_mid
        angles = [
            float(pl.nut_rotation_angle(fy - m_snug / k, d, pitch))
            for fy in f_y
            for k, d in corners
        ]
        angle_min, angle_max = min(angles), max(angles)
        torques = [k_lo * f_y[0] + m_u, k_hi * f_y[1] + m_u]
        f_lo, f_hi = min(f_y), max(f_y)
        final_out = None
        notes.append(
            f"yield point control: stop where the gradient falls to {share:.0%} of the rate met "
            "in the elastic region [Desoutter-CVIR]; the preload is the bolt's at R_p0.2 "
            "(ν = 1, VDI 2230-1 R7) over μ_G, the window reaches past F_M,zul by design"
        )
    fits = f_lo >= f_min * (1 - 1e-12) and f_hi <= f_zul * (1 + 1e-12)
    if strategy == "yield":
        fits = f_lo >= f_min * (1 - 1e-12)
    checks = [
        Check(
            "window_fits",
            fits,
            f"preload {q(f_lo, 'kN')}…{q(f_hi, 'kN')} against F_M,min = "
            f"{q(f_min, 'kN')}"
            + ("" if strategy == "yield" else f" and F_M,zul = {q(f_zul, 'kN')}"),
        ),
        Check(
            "angle_window_open",
            angle_min <= angle_max,
            f"angle window {q(angle_min, 'deg', fmt='.3g')}…{q(angle_max, 'deg', fmt='.3g')}"
            + ("" if angle_min <= angle_max else ": empty, the friction box is too wide"),
        ),
    ]
    values: dict[str, Any] = {
        "strategy": strategy,
        "target_preload": target,
        "snug_torque": m_snug + m_u,
        "final_angle": final_out,
        "angle_min": angle_min,
        "angle_max": angle_max,
        "torque_min": min(torques),
        "torque_max": max(torques),
        "rate_min": rate_lo,
        "rate_max": rate_hi,
        "gradient_threshold_min": share * rate_lo,
        "gradient_threshold_max": share * rate_hi,
        "preload_min": f_lo,
        "preload_max": f_hi,
        "window_fits": fits,
    }
    return Result(values=values, rung=ctx.rung, error_estimate=0.0, checks=checks, notes=notes)


PROGRAM = ModelSpec(
    answer=(
        Answer("snug_torque", "M_snug"),
        Answer("final_angle", "θ_A"),
        Answer("angle_min", "θ_min", check="angle_window_open"),
        Answer("angle_max", "θ_max"),
        Answer("torque_min", "M_min"),
        Answer("torque_max", "M_max", check="window_fits"),
    ),
    name="trace.program",
    title="Controller program from the joint: snug torque, angle, torque and gradient windows",
    family="trace",
    summary=(
        "From the joint (its compliance, friction box and window F_M,min…F_M,zul): the settings "
        "of a torque-then-angle or yield-point program in plain parameters: snug torque, "
        "final angle and its window, the torque monitoring window, the elastic rate expected "
        "and the yield-gradient threshold."
    ),
    source=SOURCE,
    inputs=PROGRAM_INPUTS,
    outputs=PROGRAM_OUTPUTS,
    rungs=(
        Rung(
            "closed_form",
            "[004, eq. 8] and VDI 2230-1 R7/R13 at the corners of the friction box and of "
            "the compliance's stated uncertainty",
            fixed_error(0.0),
            typical_error="exact arithmetic at the corners",
            typical_time="< 1 ms",
        ),
    ),
    compute=_program,
    examples=(
        M12_JOINT,
        {**M12_JOINT, "strategy": "yield"},
    ),
)


# --------------------------------------------------------------------------- trace.batch

#: Most traces one batch holds, and most samples all of them together hold.
MAX_BATCH_TRACES = 500
MAX_BATCH_SAMPLES = 500_000
_ONE_TRACE = {p.name: p for p in TRACE_INPUTS}


def _concatenated(name: str) -> Param:
    """A trace input of ``trace.analysis`` taking every trace of a batch one after another."""
    p = _ONE_TRACE[name]
    return replace(
        p,
        description=f"{p.description}; every trace of the batch one after another, "
        "as trace_lengths splits them",
        min_length=2 * MIN_TRACE_SAMPLES,
        max_length=MAX_BATCH_SAMPLES,
    )


BATCH_INPUTS: tuple[Param, ...] = (
    _concatenated("angle"),
    _concatenated("torque"),
    _concatenated("time"),
    samples(
        "trace_lengths",
        "1",
        "Samples of each trace, in the order angle and torque hold them (whole numbers "
        "adding up to the samples given)",
        required=True,
        minimum=MIN_TRACE_SAMPLES,
        maximum=MAX_BATCH_SAMPLES,
        min_length=2,
        max_length=MAX_BATCH_TRACES,
        group="trace",
    ),
    Param(
        "required_index",
        "1",
        "Index C_p and C_pk of the preload must reach (1.33 is a common process-capability "
        "limit; set your own specification's)",
        default=1.33,
        minimum=0.5,
        maximum=5.0,
        symbol="C_req",
        group="analysis",
    ),
    *(p for p in TRACE_INPUTS if p.name not in ("angle", "torque", "time")),
    *JOINT_INPUTS,
)


def _trace_bounds(x: Mapping[str, Any]) -> list[tuple[int, int]]:
    """Where each trace of the batch starts and ends in the concatenated samples."""
    lengths = x["trace_lengths"]
    for i, n in enumerate(lengths):
        if not float(n).is_integer():
            raise InputOutOfRange(
                f"trace_lengths[{i}] = {n:g} is not a whole number of samples",
                field="trace_lengths",
                index=i,
            )
    total, given = int(sum(lengths)), len(x["angle"])
    if total != given:
        raise InputOutOfRange(
            f"trace_lengths add up to {total} samples and angle holds {given}: must be equal",
            field="trace_lengths",
        )
    ends = [0, *np.cumsum([int(n) for n in lengths]).tolist()]
    return list(itertools.pairwise(ends))


def _one_of_batch(
    x: Mapping[str, Any], ctx: RunContext, number: int, a: int, b: int
) -> Mapping[str, Any]:
    """``trace.analysis``'s scalar results for the batch's trace ``number`` (samples a…b−1),
    the joint solved once for the batch (the request's scratch); a refusal names the trace
    and its sample index in the batch."""
    one = {k: v for k, v in x.items() if k not in ("trace_lengths", "required_index")}
    for name in ("angle", "torque", "time"):
        if x.get(name) is not None:
            one[name] = x[name][a:b]
    inner = RunContext(
        rung=ANALYSIS_RUNG.name,
        outputs=ANALYSIS.scalar_outputs,
        tolerance=ctx.tolerance,
        deadline=ctx.deadline,
        max_steps=ctx.max_steps,
        cancel=ctx.cancel,
        scratch=ctx.scratch,
    )
    try:
        return _analysis(one, inner).values
    except InputOutOfRange as exc:
        where = dict(exc.context)
        if isinstance(where.get("index"), int):
            where["index"] += a
        raise InputOutOfRange(
            f"trace {number} (samples {a}…{b - 1}): {exc.message}",
            field=exc.field,
            **{**where, "trace": number},
        ) from None


def _batch(x: Mapping[str, Any], ctx: RunContext) -> Result:
    bounds = _trace_bounds(x)
    j = _joint(x, ctx)
    friction, preload, inside = [], [], 0
    for number, (a, b) in enumerate(bounds, start=1):
        ctx.check_budget(f"trace {number} of the batch")
        v = _one_of_batch(x, ctx, number, a, b)
        friction.append(float(v["total_friction"]))
        preload.append(float(v["preload"]))
        inside += bool(v["preload_in_window"])
    if max(preload) == min(preload):
        raise InputOutOfRange(
            f"torque: the {len(bounds)} traces give one preload, "
            f"{quantity(preload[0], 'kN', '.6g')}: a capability needs a spread (are they "
            "copies of one trace?)",
            field="torque",
        )
    window = (j.assembly_preload_min, j.permissible_preload)
    s = tr.batch_summary(friction, preload, window)
    n = len(bounds)
    required = float(x["required_index"])
    capable = s.critical_capability_index >= required
    numbers = ", ".join(str(i + 1) for i in s.outliers)
    values: dict[str, Any] = {
        "traces": n,
        "friction_mean": s.friction_mean,
        "friction_sd": s.friction_sd,
        "preload_mean": s.preload_mean,
        "preload_sd": s.preload_sd,
        "preload_lowest": min(preload),
        "preload_highest": max(preload),
        "outlier_count": len(s.outliers),
        "outlier_traces": numbers,
        "traces_in_window": inside,
        "capability_index": s.capability_index,
        "critical_capability_index": s.critical_capability_index,
        "assembly_preload_min": j.assembly_preload_min,
        "permissible_preload": j.permissible_preload,
    }
    kn = "kN"
    checks = [
        Check(
            "no_outliers",
            not s.outliers,
            "no trace's friction lies apart from the others'"
            if not s.outliers
            else f"trace{'s' if len(s.outliers) > 1 else ''} {numbers}: friction apart from "
            f"the others' (robust z beyond {tr.OUTLIER_Z:g}): check the parts' lot or the "
            "lubrication",
        ),
        Check(
            "all_in_window",
            inside == n,
            f"{inside} of {n} traces have their preload bounds within F_M,min = "
            f"{q(j.assembly_preload_min, kn)} … F_M,zul = "
            f"{q(j.permissible_preload, kn)}",
        ),
        Check(
            "capability",
            capable,
            f"C_p = {s.capability_index:.3g}, C_pk = {s.critical_capability_index:.3g} of the "
            f"preload against F_M,min…F_M,zul {'≥' if capable else '<'} {required:g}",
        ),
    ]
    notes = [
        "each trace read as trace.analysis reads it (its step, its elastic rate, the total "
        "friction μ_ges the rate implies, the preload at its peak torque), the joint solved "
        "once for the batch",
        f"outliers: modified z-score of the friction beyond {tr.OUTLIER_Z:g} (median and "
        "median absolute deviation); C_p and C_pk of the preloads against the joint's "
        "F_M,min…F_M,zul, sample standard deviation (n − 1)",
        *j.notes,
    ]
    warnings = (
        [f"only {n} traces: a capability index from fewer than 25 values scatters widely"]
        if n < 25
        else []
    )
    series: dict[str, list[float]] = {}
    if ctx.wants("trace_number", "trace_friction", "trace_preload"):
        series = {
            "trace_number": [float(i) for i in range(1, n + 1)],
            "trace_friction": friction,
            "trace_preload": preload,
        }
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=None,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=series,
    )


BATCH_OUTPUTS: tuple[Output, ...] = (
    _o("traces", "1", "Traces read", kind="int", symbol="", step=""),
    _o("friction_mean", "1", "Mean of the traces' total friction μ_ges",
       symbol="μ_ges,mean", step="VDI 2230-1 R13"),
    _o("friction_sd", "1", "Sample standard deviation of μ_ges",
       symbol="s_μ", step="VDI 2230-1 R13"),
    _o("preload_mean", "N", "Mean of the traces' preload at their peak torque",
       symbol="F_V,mean", step="VDI 2230-1 R13"),
    _o("preload_sd", "N", "Sample standard deviation of the preload",
       symbol="s_FM", step="VDI 2230-1 R13"),
    _o("preload_lowest", "N", "Lowest preload of the batch",
       symbol="F_V,low", step="VDI 2230-1 R13"),
    _o("preload_highest", "N", "Highest preload of the batch",
       symbol="F_M,high", step="VDI 2230-1 R13"),
    _o("outlier_count", "1", "Traces whose friction lies apart from the others'", kind="int",
       symbol="n_out", step=""),
    _o(
        "outlier_traces",
        "1",
        "Those traces, counted from 1 as trace_number, comma-separated (empty: none)",
        kind="str", symbol="", step="",
    ),
    _o(
        "traces_in_window",
        "1",
        "Traces whose preload bounds lie within F_M,min…F_M,zul",
        kind="int", symbol="", step="VDI 2230-1 R5/R7",
    ),
    _o("capability_index", "1", "C_p of the preload against F_M,min…F_M,zul",
       symbol="C_p", step="VDI/VDE 2645"),
    _o("critical_capability_index", "1", "C_pk of the preload against F_M,min…F_M,zul",
       symbol="C_pk,F", step="VDI/VDE 2645"),
    _o("assembly_preload_min", "N", "The joint's F_M,min (lower end of its window)",
       symbol="F_M,min", step="VDI 2230-1 R5"),
    _o("permissible_preload", "N", "The joint's F_M,zul (upper end of its window)",
       symbol="F_M,zul", step="VDI 2230-1 R7"),
    _o("trace_number", "1", "Each trace, counted from 1", series=True),
    _o("trace_friction", "1", "Total friction μ_ges of each trace", series=True, x="trace_number"),
    _o("trace_preload", "N", "Preload of each trace at its peak torque", series=True,
       x="trace_number"),
)  # fmt: skip


def _example_batch() -> dict[str, Any]:
    """Five made-up torque-controlled tightenings of the M12 example to 70 N·m: its trace
    with the torques scaled by 0.96…1.04 (a lot's friction scatter) and cut at the target,
    one after another. Not a measurement."""
    one = _example_trace()
    angles: list[float] = []
    torques: list[float] = []
    lengths: list[float] = []
    for scale in (0.96, 0.98, 1.0, 1.02, 1.04):
        kept = [round(t * scale, 2) for t in one["torque"] if t * scale <= 70.0]
        angles += one["angle"][: len(kept)]
        torques += kept
        lengths.append(float(len(kept)))
    return {"angle": tuple(angles), "torque": tuple(torques), "trace_lengths": tuple(lengths)}


BATCH = ModelSpec(
    answer=(
        Answer("friction_mean", "μ_ges,mean"),
        Answer("preload_mean", "F_V,mean"),
        Answer("preload_lowest", "F_V,low", check="all_in_window"),
        Answer("outlier_count", "n_out", check="no_outliers"),
        Answer("critical_capability_index", "C_pk,F", check="capability"),
    ),
    name="trace.batch",
    title="Many tightening traces of one joint: friction and preload spread, outliers, C_p",
    family="trace",
    summary=(
        "Many torque–angle traces of one joint, each read as trace.analysis reads it: the "
        "distribution of the total friction and of the preload they imply, the traces whose "
        "friction lies apart from the others', and the capability C_p, C_pk of the preload "
        "against the joint's window F_M,min…F_M,zul."
    ),
    source=SOURCE + "; modified z-score (Iglewicz and Hoaglin); C_p, C_pk as "
    "[ECSS-E-HB-32-23A] prints them",
    inputs=BATCH_INPUTS,
    outputs=BATCH_OUTPUTS,
    rungs=(
        Rung(
            "detection",
            "Each trace through trace.analysis's detection, then the batch's statistics",
            fixed_error(0.0),
            estimate_kind="typical",
            typical_exceeded=ANALYSIS_RUNG.typical_exceeded,
            typical_error=ANALYSIS_RUNG.typical_error,
            typical_time="about 0.4 ms a trace of 200 samples, the joint solved once (2 ms for "
            "the five-trace example)",
        ),
    ),
    compute=_batch,
    assumptions=ANALYSIS.assumptions,
    examples=(
        {**M12_JOINT, **_example_batch()},
        {**M12_JOINT, **_example_batch(), "tool_stiffness": 20000.0, "yield_allowed": True},
    ),
)
