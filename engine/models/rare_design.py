"""Model spec for the striker's nearest passing design (``impact.rare_design``).

The design's inputs are impact.rare's own declarations; the verdicts are impact.rare's
closed form through its array path (:data:`engine.models.rare_impact.RARE_IMPACT`'s
``vectorized``), the search :mod:`engine.procedures.striker_design`'s.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..core.params import in_mm, in_n_per_mm
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
)
from ..procedures import striker_design as sd
from .rare_impact import RARE_IMPACT, REFERENCE_DESIGN

#: What a designer may change, each with its weight in Δ: the springs' rates and
#: preloads (the striker's parts and the drive are taken as given); with
#: ``vary_striker_mass`` the striker's mass too.
SPRINGS = (
    "power_spring_rate",
    "power_spring_preload",
    "return_spring_rate",
    "return_spring_preload",
    "auxiliary_spring_rate",
    "auxiliary_spring_preload",
)
VARIABLES = (*SPRINGS, "striker_mass")
WEIGHTS = dict.fromkeys(VARIABLES, 1.0)
_SYMBOL = {
    "power_spring_rate": "c1",
    "power_spring_preload": "λ1",
    "return_spring_rate": "c3",
    "return_spring_preload": "λ3",
    "auxiliary_spring_rate": "c2",
    "auxiliary_spring_preload": "λ2",
    "striker_mass": "m3",
}

INPUTS: tuple[Param, ...] = (
    *RARE_IMPACT.inputs,
    Param(
        "change_limit",
        "1",
        "L, the largest relative change of any one variable: each stays within "
        "x0 (1 − L) … x0 (1 + L) and its own input range",
        default=0.5,
        minimum=0.001,
        maximum=0.9,
        symbol="L",
        group="search",
    ),
    Param(
        "min_engagement_margin",
        "1",
        "the engagement margin (t_w − t_e)/t_w the design found must keep beyond impact.rare's "
        "full engagement check: the closed form the search judges by is within about 1 % of "
        "the simulation, so a design on the edge may land an edge blow",
        default=0.02,
        minimum=0.0,
        maximum=0.9,
        symbol="m_min",
        group="search",
    ),
    Param(
        "vary_striker_mass",
        "1",
        "let the search change the striker's mass m3 as well as the six spring rates and preloads",
        default=False,
        kind="bool",
        group="search",
    ),
    Param(
        "search_samples",
        "1",
        "random designs judged before the refinement (shells around the design, the "
        "nearest densest)",
        default=4000,
        minimum=100,
        maximum=50000,
        kind="int",
        group="search",
    ),
)

OUTPUTS: tuple[Output, ...] = (
    *(
        Output(
            f"new_{n}",
            p.unit,
            f"{_SYMBOL[n]} of the design found ({p.description.split(':')[0]})",
            display_unit=p.display_unit,
            symbol=_SYMBOL[n],
            step="[002]",
        )
        for n in VARIABLES
        for p in (RARE_IMPACT.param(n),)
    ),
    *(
        Output(
            f"change_{n}",
            "1",
            f"relative change of {_SYMBOL[n]}: (new − old)/old",
            symbol="",
            step="",
        )
        for n in VARIABLES
    ),
    Output(
        "design_change",
        "1",
        "Δ = √Σ((x − x0)/x0)², the weighted relative change",
        symbol="Δ",
        step="",
    ),
    Output(
        "engagement_margin",
        "1",
        "impact.rare's engagement margin of the design found: ≥ 0, no edge blow",
        symbol="(t_eng − t_2)/t_eng",
        step="[002, after eq. 5]",
    ),
    Output(
        "relock_margin",
        "N",
        "impact.rare's static re-lock margin of the design found",
        symbol="c_2 λ_2 + m_2 g − c_3 λ_3 f",
        step="[002, eq. 4]",
    ),
    Output(
        "cycle_time",
        "s",
        "impact.rare's cycle time of the design found",
        display_unit="ms",
        symbol="t_c",
        step="[002, eq. 4]",
    ),
    Output(
        "found", "1", "a design in the ranges passes every check", kind="bool", symbol="", step=""
    ),
    Output(
        "binding_checks",
        "1",
        "where none passes: the checks the nearest try fails (empty when one passes)",
        kind="str",
        symbol="",
        step="",
    ),
    Output(
        "designs_evaluated",
        "1",
        "designs judged by impact.rare's closed form",
        kind="int",
        symbol="",
        step="",
    ),
    Output(
        "designs_passing",
        "1",
        "random designs of the search that pass",
        kind="int",
        symbol="",
        step="",
    ),
)


def _limits(names: tuple[str, ...]) -> dict[str, tuple[float, float]]:
    out = {}
    for n in names:
        p = RARE_IMPACT.param(n)
        lo = float(p.minimum if p.minimum is not None else -math.inf)
        out[n] = (lo, float(p.maximum if p.maximum is not None else math.inf))
    return out


#: The check this model adds to impact.rare's: the engagement margin kept.
MARGIN_CHECK = "engagement margin"


def _margin_check(margin: Any, least: float) -> Any:
    """1 where the engagement margin is at least ``least``, 0 where not or null (no blow)."""
    m = np.asarray(margin, dtype=float)
    with np.errstate(invalid="ignore"):
        return np.where(np.isfinite(m) & (m >= least), 1, 0).astype(np.int8)


def _verdicts(x: Mapping[str, Any], least: float, ctx: RunContext) -> Any:
    """impact.rare's check verdicts of many designs (its array path, closed form), and the
    engagement margin kept."""

    def evaluate(designs: Mapping[str, Any]) -> Mapping[str, Any]:
        ctx.check_budget("the design search")
        sub = RunContext("closed_form", frozenset({"engagement_margin"}), 0.01)
        r = RARE_IMPACT.vectorized({**x, **designs}, sub)  # type: ignore[misc]
        if not r.check_arrays:
            return {}
        return {
            **r.check_arrays,
            MARGIN_CHECK: _margin_check(r.values["engagement_margin"], least),
        }

    return evaluate


def _scalar(x: Mapping[str, Any]) -> Result:
    """impact.rare's own single run (closed form) of one design."""
    ctx = RunContext("closed_form", frozenset(RARE_IMPACT.scalar_outputs), 0.01)
    return RARE_IMPACT.compute(x, ctx)


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    names = VARIABLES if x["vary_striker_mass"] else SPRINGS
    base = {p.name: x[p.name] for p in RARE_IMPACT.inputs}
    _scalar(base)  # a design impact.rare refuses is refused here, with its reason
    x0, lo, hi = sd.design_box(base, names, float(x["change_limit"]), _limits(names))
    weights = np.array([WEIGHTS[n] for n in names])
    least = float(x["min_engagement_margin"])
    evaluate = _verdicts(base, least, ctx)
    search = sd.nearest_passing(names, x0, lo, hi, weights, evaluate, int(x["search_samples"]))
    design = search.design
    if search.found and search.change > 0.0:

        def passes(d: np.ndarray) -> bool:
            v = evaluate({n: np.array([d[i]]) for i, n in enumerate(names)})
            return all(int(np.asarray(a).reshape(-1)[0]) == 1 for a in v.values())

        design = sd.rounded(design, x0, passes)
    new = {**base, **{n: float(design[i]) for i, n in enumerate(names)}}
    run = _scalar(new)
    values: dict[str, Any] = {}
    for n in VARIABLES:
        old = float(base[n])
        values[f"new_{n}"] = new[n]
        values[f"change_{n}"] = (new[n] - old) / old if old != 0.0 else 0.0
    change = float(sd.relative_change(design, x0, weights))
    values.update(
        design_change=change,
        engagement_margin=run.values["engagement_margin"],
        relock_margin=run.values["relock_margin"],
        cycle_time=run.values["cycle_time"],
        found=search.found,
        binding_checks=", ".join(search.failing),
        designs_evaluated=search.evaluated,
        designs_passing=search.passing,
    )
    changed = [
        f"{_SYMBOL[n]} {_fmt(n, float(base[n]))} → {_fmt(n, new[n])}"
        for n in names
        if new[n] != float(base[n])
    ]
    if search.found and not changed:
        verdict = (
            f"the design passes every check of impact.rare and keeps the engagement margin "
            f"{least:g} as it stands: nothing to change"
        )
    elif search.found:
        verdict = (
            f"the nearest design that passes every check of impact.rare and keeps the "
            f"engagement margin {least:g} (Δ = {change:.3g}): " + "; ".join(changed)
        )
    else:
        verdict = (
            f"no design within ±{100 * x['change_limit']:.3g} % of "
            + ", ".join(_SYMBOL[n] for n in names)
            + f" passes every check of impact.rare with the engagement margin {least:g}; the "
            "binding checks (failed by the "
            f"nearest try that fails the fewest): {values['binding_checks']}"
            + ("; it would change " + "; ".join(changed) if changed else "")
        )
    passed = ", ".join(f"{c} {k}" for c, k in search.passing_by_check.items())
    notes = [
        verdict,
        f"search: {search.evaluated} designs judged by impact.rare's closed form (its array "
        f"path); of the random ones, per check: {passed}",
        "a local search: the nearest design it met, not a proven global minimum; the checks "
        "below are impact.rare's single run of the design found (the nearest try where none "
        f"passes); the design found lies on the edge of what bound it, the engagement margin "
        f"kept being {least:g} (the closed form is within about 1 % of the simulation: run "
        "impact.rare with fidelity simulation to confirm)",
    ]
    checks = [Check(c.name, c.ok, c.detail) for c in run.checks]
    raw = run.values["engagement_margin"]
    margin = float(raw) if isinstance(raw, (int, float)) else None
    kept = margin is not None and margin >= least
    checks.append(
        Check(
            MARGIN_CHECK,
            bool(kept),
            (
                f"engagement margin {margin:.3g} "
                if margin is not None
                else "no blow, so no engagement margin "
            )
            + ("≥" if kept else "below")
            + f" the {least:.3g} asked for (the closed form's error is about 1 %)",
        )
    )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=run.error_estimate,
        checks=checks,
        notes=notes,
        warnings=list(run.warnings),
    )


def _fmt(name: str, value: float) -> str:
    if name.endswith("_rate"):
        return in_n_per_mm(value)
    if name.endswith("_preload"):
        return in_mm(value)
    return f"{value * 1e3:.4g} g"


def _closed_form_estimate(x: Mapping[str, Any]) -> float | None:
    """impact.rare's closed-form error estimate for the design as given."""
    design = {p.name: x[p.name] for p in RARE_IMPACT.inputs}
    return RARE_IMPACT.rung("closed_form").estimate(design)


SEARCH = Rung(
    "closed_form",
    "random designs in shells around the design, judged at once by impact.rare's closed "
    "form (its array path), then the nearest passing one pulled towards the design (line, "
    "shrinking random steps, one variable at a time); its changes rounded to 3, 4 or 5 "
    "significant digits, the fewest where the rounded design still passes",
    _closed_form_estimate,
    typical_error="impact.rare's closed form's (1e-3 to 1e-2, bench/accuracy_striker.py) for "
    "the design found, which keeps the engagement margin asked for (0.02) beyond it; the "
    "search is local",
    typical_time="1–15 ms (the examples; up to some 7,000 designs)",
    steps=(
        sd.design_box,
        sd.shell_samples,
        sd.relative_change,
        sd.nearest_passing,
        sd.rounded,
        *RARE_IMPACT.rung("closed_form").steps,
    ),
)

#: The issue's situation: a stiffer power spring clears the edge blow at 65 N/mm and
#: breaks c3 > c1 at 66 N/mm (return spring 65.5 N/mm, a 90° opening).
EDGE_BLOW = {
    **REFERENCE_DESIGN,
    "power_spring_rate": 60000.0,
    "return_spring_rate": 65500.0,
    "engagement_angle": math.radians(90.0),
}

RARE_DESIGN = ModelSpec(
    name="impact.rare_design",
    title="Rare-impact wrench: the nearest design that passes",
    family="impact",
    summary=(
        "For a striker design that fails a check of impact.rare (edge blow, c3 > c1, "
        "λ1 < λ3, reach, return, re-lock): the smallest change of the springs' rates and "
        "preloads (and the striker's mass) that passes every check, or the statement that "
        "none does in the ranges, naming the binding checks."
    ),
    source=(
        "[002] through impact.rare's closed form (its checks and design rules); the search "
        "is this product's"
    ),
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(SEARCH,),
    compute=_compute,
    answer=(
        Answer("design_change", "Δ"),
        Answer("new_power_spring_rate", "c1"),
        Answer("new_return_spring_rate", "c3", check="c3 > c1"),
        Answer("engagement_margin", "(t_eng − t_2)/t_eng", check=MARGIN_CHECK),
    ),
    examples=(
        EDGE_BLOW,
        REFERENCE_DESIGN,
        {**EDGE_BLOW, "change_limit": 0.02},
    ),
)
