"""Model spec for the clamp-force capability of a joint (``joint.clamp_capability``).

The joint is joint.vdi2230's (its inputs reused, not copied: :data:`INPUTS` takes them
from :data:`engine.models.joint.JOINT_INPUTS`, less the friction box and the torque
specification, which laws replace here). The tool is a torque law: a mean and σ, a
certificate's Cm/Cmk at a tolerance, or measured torques. The frictions μ_G and μ_K are
laws of their own, joined by a Gaussian copula. The distribution of the preload and of
the bolt's utilisation, and the tails against the joint's F_M,min and F_M,zul in ppm,
come from :mod:`engine.physics.capability` (quadrature, no sampling).
"""

from __future__ import annotations

import math
import threading
from collections.abc import Mapping
from typing import Any

from ..core.errors import InputOutOfRange
from ..core.params import positive, samples
from ..core.runner import run
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    fixed_error,
)
from ..core.text import q
from ..numerics import laws
from ..numerics.laws import Law
from ..physics import capability as cap
from ..procedures.bolt import resolve_bolt
from .joint import JOINT_INPUTS
from .joint import VDI2230 as JOINT

SOURCE = (
    "VDI 2230-1 R7 and R13 (the joint's preload at a torque and its permissible preload), "
    "VDI/VDE 2645-2 (Cm, Cmk of the tool), VDI/VDE 2862 as a public secondary source states "
    "its categories' minimum [CSP2862]; the copula's rank correlation after [Kruskal1958]"
)

#: joint.vdi2230's inputs this model does not take: the friction box and the torque
#: specification (the laws below replace them) and the [004] rule's flags.
REPLACED = (
    "thread_friction_min",
    "thread_friction_max",
    "bearing_friction_min",
    "bearing_friction_max",
    "method",
    "tightening_factor",
    "tightening_torque",
    "torque_tolerance",
    "prevailing_torque_min",
    "controlled",
    "bridge_joint",
)
_JOINT_TAKEN = tuple(p for p in JOINT_INPUTS if p.name not in REPLACED)

LAW_KINDS = ("uniform", "normal", "truncated_normal", "lognormal", "triangular", "fixed")
LAW_LABELS = (
    "uniform low…high",
    "normal (mean, sd)",
    "normal (mean, sd) truncated to low…high",
    "lognormal (arithmetic mean, sd)",
    "triangular low, mode, high",
    "fixed (mean)",
)
#: Categories of VDI/VDE 2862 and the torque Cmk/Cpk [CSP2862] states for each (None: no
#: minimum stated).
CATEGORY_MINIMUM: dict[str, float | None] = {"A": 1.67, "B": 1.33, "C": None}
#: The quantiles of the preload the result states, by output name.
PRELOAD_QUANTILES = (
    ("preload_q1e-6", 1e-6),
    ("preload_q00135", 0.00135),
    ("preload_median", 0.5),
    ("preload_q99865", 0.99865),
    ("preload_q1-1e-6", 1.0 - 1e-6),
)
UTILISATION_QUANTILES = (
    ("utilisation_median", 0.5),
    ("utilisation_q99865", 0.99865),
    ("utilisation_q1-1e-6", 1.0 - 1e-6),
)
#: The relative error a tail must reach; the quadrature refines to 128 panels at most.
TAIL_TARGET = 1e-3
#: Panels per score axis for the moments and quantiles.
QUANTILE_PANELS = 8
MAX_TORQUE = 1e5


def _friction_inputs(which: str, symbol: str, label: str) -> tuple[Param, ...]:
    g = f"{which}_friction"
    return (
        Param(
            f"{g}_law",
            "1",
            f"Law of the {label} friction {symbol} over the bolts of the lot",
            default="uniform",
            kind="choice",
            choices=LAW_KINDS,
            choice_labels=LAW_LABELS,
            group="friction",
        ),
        Param(
            f"{g}_low",
            "1",
            f"{symbol}: lower end (uniform, triangular) or truncation (truncated normal)",
            default=0.08,
            minimum=0.0,
            maximum=1.0,
            group="friction",
        ),
        Param(
            f"{g}_high",
            "1",
            f"{symbol}: upper end (uniform, triangular) or truncation (truncated normal)",
            default=0.16,
            minimum=0.0,
            maximum=1.0,
            group="friction",
        ),
        Param(
            f"{g}_mean",
            "1",
            f"{symbol}: mean (normal, truncated normal, lognormal, fixed)",
            minimum=0.0,
            maximum=1.0,
            exclusive_minimum=True,
            group="friction",
        ),
        Param(
            f"{g}_sd",
            "1",
            f"{symbol}: standard deviation (normal, truncated normal, lognormal)",
            minimum=0.0,
            maximum=1.0,
            exclusive_minimum=True,
            group="friction",
        ),
        Param(
            f"{g}_mode",
            "1",
            f"{symbol}: most likely value (triangular)",
            minimum=0.0,
            maximum=1.0,
            group="friction",
        ),
    )


TOOL_INPUTS: tuple[Param, ...] = (
    positive(
        "nominal_torque",
        "N*m",
        "Torque the tool is set to (the middle of its tolerance)",
        maximum=MAX_TORQUE,
        default=80.0,
        symbol="M_A",
        group="tool",
    ),
    Param(
        "mean_torque",
        "N*m",
        "Mean torque the tool gives, when it is not the nominal (with torque_sd)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        exclusive_minimum=True,
        group="tool",
    ),
    Param(
        "torque_sd",
        "N*m",
        "Standard deviation of the tool's torque (0: a perfect tool)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="σ_M",
        group="tool",
    ),
    Param(
        "capability_index",
        "1",
        "The tool's Cm at relative_tolerance (instead of torque_sd): σ = 2 t M_A/(6 Cm)",
        minimum=0.1,
        maximum=20.0,
        symbol="C_m",
        group="tool",
    ),
    Param(
        "critical_capability_index",
        "1",
        "The tool's Cmk (≤ Cm); its mean then lies 3σ(Cm − Cmk) above the nominal (the "
        "side that loads the bolt more); Cm when absent",
        minimum=0.0,
        maximum=20.0,
        symbol="C_mk",
        group="tool",
    ),
    Param(
        "relative_tolerance",
        "1",
        "Torque tolerance ± of the tool's Cm/Cmk and of the category check (0.1 is ±10 %)",
        default=0.1,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        exclusive_maximum=True,
        display_unit="%",
        group="tool",
    ),
    samples(
        "torque_samples",
        "N*m",
        "Measured torques of the tool (instead of torque_sd or Cm): their mean and s",
        minimum=0.0,
        maximum=MAX_TORQUE,
        group="tool",
    ),
)

CORRELATION_INPUTS: tuple[Param, ...] = (
    Param(
        "friction_correlation",
        "1",
        "Rank (Spearman) correlation of μ_G and μ_K over the lot, through a Gaussian copula",
        default=0.0,
        minimum=-0.99,
        maximum=0.99,
        symbol="ρ_S",
        group="friction",
    ),
)

CHECK_INPUTS: tuple[Param, ...] = (
    Param(
        "allowed_ppm",
        "1",
        "Share of bolts you accept below F_M,min or above F_M,zul, in ppm (your limit; no "
        "standard sets one)",
        default=1.0,
        minimum=0.0,
        maximum=1e6,
        group="checks",
    ),
    Param(
        "category",
        "1",
        "VDI/VDE 2862 category of the joint, for the tool's minimum Cmk as [CSP2862] states it",
        default="none",
        kind="choice",
        choices=("none", *CATEGORY_MINIMUM),
        choice_labels=("not classified", "A (safety)", "B (function)", "C (other)"),
        group="checks",
    ),
)

INPUTS: tuple[Param, ...] = (
    *_JOINT_TAKEN,
    *TOOL_INPUTS,
    *_friction_inputs("thread", "μ_G", "thread"),
    *_friction_inputs("bearing", "μ_K", "bearing-face"),
    *CORRELATION_INPUTS,
    *CHECK_INPUTS,
)


def _out(name: str, unit: str, description: str, **kw: Any) -> Output:
    return Output(name, unit, description, **kw)


OUTPUTS: tuple[Output, ...] = (
    _out(
        "mean_torque",
        "N*m",
        "Mean of the tool's torque law",
        symbol="M_A,mean",
        step="VDI/VDE 2645",
    ),
    _out(
        "torque_sd",
        "N*m",
        "Standard deviation of the tool's torque law",
        symbol="s_M",
        step="VDI/VDE 2645",
    ),
    _out(
        "preload_mean",
        "N",
        "Mean assembly preload F_M",
        display_unit="kN",
        symbol="F_M,mean",
        step="VDI 2230-1 R13",
    ),
    _out(
        "preload_sd",
        "N",
        "Standard deviation of F_M",
        display_unit="kN",
        symbol="s_FM",
        step="VDI 2230-1 R13",
    ),
    *(
        _out(
            name,
            "N",
            f"F_M exceeded by a share {1 - q:.6g} of the bolts",
            display_unit="kN",
            symbol=f"F_M,{q:.6g}",
            step="VDI 2230-1 R13",
        )
        for name, q in PRELOAD_QUANTILES
    ),
    *(
        _out(
            name,
            "1",
            f"Bolt utilisation ν = σ_red,M/R_p0.2 at the quantile {q:.6g}",
            symbol=f"ν_{q:.6g}",
            step="VDI 2230-1 R7",
        )
        for name, q in UTILISATION_QUANTILES
    ),
    _out(
        "required_preload_min",
        "N",
        "F_M,min the joint requires (VDI 2230-1 R5: F_K,erf, the working load's share, "
        "embedding and thermal losses)",
        display_unit="kN",
        symbol="F_M,min",
        step="VDI 2230-1 R5",
    ),
    _out(
        "permissible_preload",
        "N",
        "F_M,zul at the median thread friction (each bolt is judged at its own μ_G)",
        display_unit="kN",
        symbol="F_M,zul",
        step="VDI 2230-1 R7",
    ),
    _out(
        "low_ppm",
        "1",
        "Bolts below F_M,min, in ppm",
        label="below F_M,min [ppm]",
        symbol="p(F_M < F_M,min)",
        step="VDI 2230-1 R5",
    ),
    _out(
        "low_ppm_error",
        "1",
        "Estimated relative error of low_ppm: the change from half the panels, a typical "
        "estimate (exceeded in 7 of 124 random designs against a 16× finer rule; the "
        "rung's 10 % held in all)",
        symbol="ε_low",
        step="",
    ),
    _out(
        "high_ppm",
        "1",
        "Bolts above F_M,zul (utilisation above ν), in ppm",
        label="above F_M,zul [ppm]",
        symbol="p(F_M > F_M,zul)",
        step="VDI 2230-1 R7",
    ),
    _out(
        "high_ppm_error",
        "1",
        "Estimated relative error of high_ppm: the change from half the panels, a typical "
        "estimate (exceeded in 7 of 124 random designs against a 16× finer rule; the "
        "rung's 10 % held in all)",
        symbol="ε_high",
        step="",
    ),
    _out(
        "clamp_force_cpk",
        "1",
        "Cpk of the preload between F_M,min and F_M,zul: min(U − mean, mean − L)/(3 sd)",
        symbol="C_pk,F",
        step="VDI/VDE 2645",
    ),
    _out(
        "tightening_factor",
        "1",
        "α_A this process has: F_M at 0.99865 over F_M at 0.00135 (±3σ equivalents)",
        label="α_A",
        symbol="α_A",
        step="VDI 2230-1 R1",
    ),
    _out(
        "friction_copula",
        "1",
        "The Gaussian copula's ρ for the rank correlation given",
        symbol="ρ",
        step="Kruskal1958",
    ),
    _out(
        "tool_critical_index",
        "1",
        "Cmk of the tool's torque law at relative_tolerance (null for a perfect tool)",
        symbol="C_mk",
        step="VDI/VDE 2645",
    ),
    _out(
        "quadrature_panels",
        "1",
        "Gauss-Legendre panels per score axis used",
        kind="int",
        symbol="",
        step="",
    ),
    _out(
        "category_minimum_met",
        "1",
        "The tool reaches the category's minimum Cmk as [CSP2862] states it (null: none)",
        kind="bool",
        symbol="",
        step="[CSP2862]",
    ),
)


def _law(x: Mapping[str, Any], which: str) -> Law:
    """The law of μ_G (``thread``) or μ_K (``bearing``) from its inputs."""
    g = f"{which}_friction"
    kind = str(x[f"{g}_law"])

    def need(*names: str) -> list[float]:
        got = []
        for n in names:
            value = x.get(f"{g}_{n}")
            if value is None:
                raise InputOutOfRange(f"{g}_{n} is required with a {kind} law", field=f"{g}_{n}")
            got.append(float(value))
        return got

    if kind in ("uniform", "triangular", "truncated_normal"):
        low, high = need("low", "high")
        if not low < high:
            raise InputOutOfRange(
                f"{g}_high = {high:g} is not allowed: must be above {g}_low = {low:g}",
                field=f"{g}_high",
            )
    if kind == "uniform":
        return Law("uniform", low=low, high=high)
    if kind == "triangular":
        (mode,) = need("mode")
        if not low <= mode <= high:
            raise InputOutOfRange(
                f"{g}_mode = {mode:g} is not allowed: must be {low:g}…{high:g}",
                field=f"{g}_mode",
            )
        return Law("triangular", low=low, mode=mode, high=high)
    if kind == "fixed":
        (mean,) = need("mean")
        return Law("fixed", mean=mean)
    mean, sd = need("mean", "sd")
    if kind == "normal":
        if mean < 6.0 * sd:
            raise InputOutOfRange(
                f"{g}_sd = {sd:g} is not allowed for an untruncated normal law: must be ≤ "
                f"mean/6 = {mean / 6:g}, or a friction below 0 has more than 1e-9 of the "
                "lot (use truncated_normal or lognormal)",
                field=f"{g}_sd",
            )
        return Law("normal", mean=mean, sd=sd)
    if kind == "lognormal":
        median, gsd = laws.lognormal_from_mean_sd(mean, sd)
        return Law("lognormal", median=float(median), gsd=float(gsd))
    if (low - mean) / sd > 8.0 or (high - mean) / sd < -8.0:
        raise InputOutOfRange(
            f"{g}_mean = {mean:g}: the normal law has no mass inside {low:g}…{high:g}",
            field=f"{g}_mean",
        )
    return Law("truncated_normal", mean=mean, sd=sd, low=low, high=high)


def _tool(x: Mapping[str, Any]) -> tuple[float, float, str]:
    """(mean, σ, how they were given) of the tool's torque."""
    nominal = float(x["nominal_torque"])
    t = float(x["relative_tolerance"])
    given = [n for n in ("torque_sd", "capability_index", "torque_samples") if x.get(n) is not None]
    if len(given) > 1:
        raise InputOutOfRange(
            f"give one of torque_sd, capability_index or torque_samples, not {' and '.join(given)}",
            field=given[1],
        )
    if x.get("critical_capability_index") is not None and "capability_index" not in given:
        raise InputOutOfRange(
            "critical_capability_index needs capability_index", field="critical_capability_index"
        )
    how = given[0] if given else "none"
    if how == "torque_samples":
        if x.get("mean_torque") is not None:
            raise InputOutOfRange(
                "mean_torque is not taken with torque_samples (their mean is)", field="mean_torque"
            )
        values = tuple(x["torque_samples"])
        sd = cap.sample_standard_deviation(values)
        if not sd > 0.0:
            raise InputOutOfRange(
                "torque_samples: all values are equal; give them as measured",
                field="torque_samples",
            )
        return cap.sample_mean(values), sd, f"{len(values)} measured torques"
    mean = nominal if x.get("mean_torque") is None else float(x["mean_torque"])
    if how == "capability_index":
        cm = float(x["capability_index"])
        cmk = (
            cm
            if x.get("critical_capability_index") is None
            else float(x["critical_capability_index"])
        )
        if cmk > cm:
            raise InputOutOfRange(
                f"critical_capability_index = {cmk:g} is not allowed: must be ≤ "
                f"capability_index = {cm:g}",
                field="critical_capability_index",
            )
        sd = float(cap.index_standard_deviation(nominal * (1 + t), nominal * (1 - t), cm))
        mean += float(cap.index_mean_offset(cm, cmk, sd))
        return mean, sd, f"Cm = {cm:g}, Cmk = {cmk:g} at ±{t:.3g}"
    if how == "torque_sd":
        return mean, float(x["torque_sd"]), "mean and σ given"
    return mean, 0.0, "no scatter given: a perfect tool"


_Distribution = tuple[tuple[float, float, int], tuple[float, float], dict[str, float | None]]
#: The last designs' :func:`_distribution`, by its (frozen) arguments, oldest first.
_KEPT: dict[tuple[Any, ...], _Distribution] = {}
_KEPT_SIZE = 64
_KEPT_LOCK = threading.Lock()


def _distribution(
    clamp: cap.ClampJoint, scatter: cap.Scatter, nu: float, wanted: tuple[str, ...]
) -> _Distribution:
    """What depends on the tool, the frictions and the bolt only, not on F_M,min: the share
    above ν with its error and panels, the moments of F_M and the quantiles in ``wanted``.

    Kept for the last designs (a pure function of its frozen arguments): a sweep or study
    over the joint's loads or plates leaves these unchanged and reads them again.
    """
    key = (clamp, scatter, nu, wanted)
    with _KEPT_LOCK:
        kept = _KEPT.get(key)
    if kept is not None:
        return kept

    def above(panels: int) -> float:
        return cap.utilisation_tail(clamp, scatter, nu, upper=True, panels=panels)

    high = cap.tail_with_error(above, TAIL_TARGET)
    torque, thread, bearing = scatter.torque, scatter.thread, scatter.bearing
    # the moments on 16 panels, the quantiles on 8: a quantile moves by the tail's relative
    # error divided by d ln P/d ln x, which is large in a tail (bench/capability_tails.py)
    mean_f, sd_f = cap.preload_moments(clamp, scatter, 16)
    # every quantile to 1 − 1e-6 lies between the extremes at ±6 scores of each law
    corners = [
        (t, g, k)
        for t in (float(torque.from_score(-6.0)), float(torque.from_score(6.0)))
        for g in (float(thread.from_score(-6.0)), float(thread.from_score(6.0)))
        for k in (float(bearing.from_score(-6.0)), float(bearing.from_score(6.0)))
    ]
    f_corners = [float(cap.preload_at_torque(clamp, t, g, k)) for t, g, k in corners]
    nu_corners = [
        float(cap.bolt_utilisation(clamp, f, c[1])) for f, c in zip(f_corners, corners, strict=True)
    ]
    quantiles: dict[str, float | None] = dict.fromkeys(
        [n for n, _ in (*PRELOAD_QUANTILES, *UTILISATION_QUANTILES)]
    )
    # α_A reads the ±3σ-equivalent quantiles
    alpha_needs = ("preload_q00135", "preload_q99865") if "tightening_factor" in wanted else ()
    chosen = [(n, q) for n, q in PRELOAD_QUANTILES if n in wanted or n in alpha_needs]
    if chosen:
        found = cap.tail_quantiles(
            lambda v, up, n: cap.preload_tails(clamp, scatter, v, up, n),
            [q for _, q in chosen],
            min(f_corners),
            max(f_corners),
            QUANTILE_PANELS,
        )
        quantiles.update(zip([n for n, _ in chosen], found, strict=True))
    chosen = [(n, q) for n, q in UTILISATION_QUANTILES if n in wanted]
    if chosen:
        found = cap.tail_quantiles(
            lambda v, up, n: cap.utilisation_tails(clamp, scatter, v, up, n),
            [q for _, q in chosen],
            min(nu_corners),
            max(nu_corners),
            QUANTILE_PANELS,
        )
        quantiles.update(zip([n for n, _ in chosen], found, strict=True))
    made: _Distribution = (high, (mean_f, sd_f), quantiles)
    with _KEPT_LOCK:
        _KEPT[key] = made
        while len(_KEPT) > _KEPT_SIZE:
            del _KEPT[next(iter(_KEPT))]
    return made


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    mean_t, sd_t, how = _tool(x)
    thread, bearing = _law(x, "thread"), _law(x, "bearing")
    rank = float(x["friction_correlation"])
    rho = float(laws.copula_from_spearman(rank))
    torque = Law("fixed", mean=mean_t) if sd_t == 0.0 else Law("normal", mean=mean_t, sd=sd_t)
    if sd_t > 0.0 and mean_t < 6.0 * sd_t:
        raise InputOutOfRange(
            f"the tool's σ = {sd_t:.4g} N*m is over a sixth of its mean {mean_t:.4g} N*m: a "
            "normal torque law would give negative torques",
            field="torque_sd",
        )
    m_u = float(x["prevailing_torque"])
    if m_u >= mean_t - 6.0 * sd_t:
        raise InputOutOfRange(
            f"prevailing_torque = {m_u:g} N*m is not allowed: must be below the tool's mean "
            f"torque less 6σ, {mean_t - 6.0 * sd_t:.4g} N*m (the torque left for preload)",
            field="prevailing_torque",
        )
    scatter = cap.Scatter(torque, thread, bearing, rho)
    notes: list[str] = []
    warnings: list[str] = []
    # joint.vdi2230 at the mean torque, the tool's ±3σ and the laws' ±3σ friction box: its
    # F_M,min required (R5) and smallest section (R7), from its own chain
    bolt, _ = resolve_bolt(x)
    joint_x = {p.name: x[p.name] for p in _JOINT_TAKEN if x.get(p.name) is not None}
    box = {
        "thread_friction_min": float(thread.from_score(-3.0)),
        "thread_friction_max": float(thread.from_score(3.0)),
        "bearing_friction_min": float(bearing.from_score(-3.0)),
        "bearing_friction_max": float(bearing.from_score(3.0)),
    }
    joint = run(
        JOINT,
        {
            **joint_x,
            **box,
            "tightening_torque": mean_t,
            "torque_tolerance": min(3.0 * sd_t / mean_t, 0.9),
        },
        budget_s=None,
    ).results
    required = float(joint["required_preload_min"])  # type: ignore[arg-type]
    # F_M,zul and ν are the assembly's (VDI 2230-1 R7, tightened cold): the room-temperature
    # R_p0.2 at any service_temperature, which moves only the F_M,min required (ΔF_Vth, R5)
    hot = x.get("service_temperature") is not None
    yield_strength = bolt.yield_strength
    clamp = cap.ClampJoint(
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.diameter,
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        float(joint["smallest_diameter"]),  # type: ignore[arg-type]
        float(joint["smallest_area"]),  # type: ignore[arg-type]
        yield_strength,
        m_u,
    )
    nu = float(x["utilization"])

    def below(panels: int) -> float:
        if required <= 0.0:
            return 0.0
        return cap.preload_tail(clamp, scatter, required, upper=False, panels=panels)

    p_low, e_low, n_low = cap.tail_with_error(below, TAIL_TARGET)
    wanted = tuple(sorted(ctx.outputs))
    (p_high, e_high, n_high), (mean_f, sd_f), quantiles = _distribution(clamp, scatter, nu, wanted)
    panels = max(n_low, n_high)
    mu_g_median = float(thread.from_score(0.0))
    f_zul = float(cap.permissible_preload_at(clamp, mu_g_median, nu))
    cpk = float(cap.critical_capability_index(f_zul, required, mean_f, sd_f)) if sd_f else math.inf
    top, bottom = quantiles["preload_q99865"], quantiles["preload_q00135"]
    alpha = None if top is None or bottom is None else top / bottom
    t = float(x["relative_tolerance"])
    nominal = float(x["nominal_torque"])
    tool_index = (
        float(cap.critical_capability_index(nominal * (1 + t), nominal * (1 - t), mean_t, sd_t))
        if sd_t > 0.0
        else math.inf
    )
    allowed = float(x["allowed_ppm"])
    checks = [
        Check(
            "below_required_preload",
            p_low * 1e6 <= allowed,
            f"{p_low * 1e6:.3g} ppm below F_M,min = {q(required, 'kN', fmt='.4g')} "
            f"({'≤' if p_low * 1e6 <= allowed else '>'} {allowed:g} ppm allowed)",
        ),
        Check(
            "above_permissible_preload",
            p_high * 1e6 <= allowed,
            f"{p_high * 1e6:.3g} ppm above F_M,zul (ν > {nu:g}) "
            f"({'≤' if p_high * 1e6 <= allowed else '>'} {allowed:g} ppm allowed)"
            + ("" if p_high * 1e6 <= allowed else ": lower the torque or narrow the friction"),
        ),
        Check(
            "tail_accuracy",
            max(e_low, e_high) <= 0.1,
            f"tail probabilities to a relative {max(e_low, e_high):.2g} (10 % required)",
        ),
    ]
    category = str(x["category"])
    met: bool | None = None
    if category != "none":
        minimum = CATEGORY_MINIMUM[category]
        if minimum is None:
            notes.append(f"category {category}: [CSP2862] states no minimum capability for it")
        else:
            met = tool_index >= minimum
            checks.append(
                Check(
                    "category_minimum",
                    met,
                    f"category {category}: the tool's Cmk = {tool_index:.3g} at ±{t:.3g} "
                    f"{'≥' if met else '<'} {minimum:g} (VDI/VDE 2862 as [CSP2862] states it)",
                )
            )
    notes += [
        f"tool: {how}; torque N({mean_t:.4g}, {sd_t:.3g}) N·m, independent of the frictions",
        f"μ_G {thread.kind}, μ_K {bearing.kind}, rank correlation {rank:g} (Gaussian copula "
        f"ρ = {rho:.4g}, [Kruskal1958])",
        "tails by Gauss-Legendre quadrature over the frictions' normal scores (the torque law "
        f"in closed form), {panels} panels of 8 nodes per axis on ±9; each error is the change "
        "from half the panels; the quantiles from 8 panels, to about 1e-4 relative",
        "F_M,zul per bolt at its own μ_G (VDI 2230-1 R7); F_M,min required from joint.vdi2230 "
        "at the mean torque and the laws' ±3σ friction box (VDI 2230-1 R5); a nut's proof "
        "load, where joint.vdi2230 caps F_M,zul by it, is not applied here",
    ]
    if hot:
        notes.append(
            "F_M,zul and ν at assembly, at room temperature (R_p0.2 = "
            f"{q(yield_strength, 'MPa', 4)}; the bolt is tightened cold, VDI 2230-1 "
            "R7); service_temperature sets only the F_M,min required (thermal loss, R5)"
        )
    if category in ("A", "B"):
        notes.append(
            "VDI/VDE 2862 itself was not read: its minimum is as one public secondary source "
            "states it [CSP2862], for the tool's torque, not the clamp force"
        )
    if max(e_low, e_high) > 0.1:
        warnings.append(
            "a tail probability could not be resolved to 10 % with 128 panels (a law with no "
            "scatter where the others have some); read it as an order of magnitude"
        )
    values: dict[str, Any] = {
        "mean_torque": mean_t,
        "torque_sd": sd_t,
        "preload_mean": mean_f,
        "preload_sd": sd_f,
        **quantiles,
        "required_preload_min": required,
        "permissible_preload": f_zul,
        "low_ppm": p_low * 1e6,
        "low_ppm_error": e_low,
        "high_ppm": p_high * 1e6,
        "high_ppm_error": e_high,
        "clamp_force_cpk": cpk,
        "tightening_factor": alpha,
        "friction_copula": rho,
        "tool_critical_index": tool_index,
        "quadrature_panels": panels,
    }
    if met is not None:  # only where a category was asked for: no null in the answer
        values["category_minimum_met"] = met
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=max(e_low, e_high),
        checks=checks,
        notes=notes,
        warnings=warnings,
    )


QUADRATURE = Rung(
    "quadrature",
    "Deterministic quadrature of the preload's tails over the frictions' normal scores "
    "(composite Gauss-Legendre, the torque law in closed form); the estimate is the larger "
    "relative change of the two ppm figures from half the panels",
    fixed_error(0.1),
    typical_error="≤ 10 % on the ppm figures (usually < 0.1 %)",
    typical_time="0.5–35 ms (about 6 ms for a typical design)",
    heavy=True,
)

#: The M12 8.8 joint of joint.vdi2230's second example.
M12_JOINT = {
    "thread_diameter": 0.012,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "prevailing_torque": 0.4,
    "working_load": 10e3,
}

CLAMP_CAPABILITY = ModelSpec(
    answer=(
        Answer("low_ppm", "p(F_M < F_M,min)", check="below_required_preload"),
        Answer("high_ppm", "p(F_M > F_M,zul)", check="above_permissible_preload"),
        Answer("clamp_force_cpk", "C_pk,F"),
        Answer("tightening_factor", "α_A"),
        Answer("preload_median", "F_M,0.5"),
    ),
    name="joint.clamp_capability",
    title="Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint",
    family="joint",
    summary=(
        "A joint (as joint.vdi2230), the tool's torque law (σ, or Cm/Cmk at a tolerance, "
        "or measured torques) and the friction laws of the lot (uniform, normal, "
        "truncated, lognormal, triangular; correlated): the distribution of the assembly "
        "preload and of the bolt's utilisation, the share of bolts below F_M,min and above "
        "F_M,zul in ppm with their error, Cpk on clamp force and the α_A the process has."
    ),
    source=SOURCE,
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(QUADRATURE,),
    compute=_compute,
    examples=(
        # the question: M12 8.8 at 80 N·m, μ 0.08…0.16, a tool at Cm 1.67 (±10 %)
        {**M12_JOINT, "nominal_torque": 80.0, "capability_index": 1.67},
        # a friction lot normal 0.12 ± 0.0133 (0.08…0.16 as ±3σ), a poorer tool, category A
        {
            **M12_JOINT,
            "nominal_torque": 70.0,
            "capability_index": 1.2,
            "critical_capability_index": 1.0,
            "thread_friction_law": "normal",
            "thread_friction_mean": 0.12,
            "thread_friction_sd": 0.0133,
            "bearing_friction_law": "lognormal",
            "bearing_friction_mean": 0.12,
            "bearing_friction_sd": 0.0133,
            "friction_correlation": 0.5,
            "category": "A",
        },
    ),
)
