"""Model spec for the spring a clutch setting needs (``clutch.spring_design``).

The clutch inputs are clutch.ball_setting's own declarations; the duty (force at the
setting, stroke) and the search are :mod:`engine.procedures.spring_design`'s, the
spring relations :mod:`engine.physics.springs`' (EN 13906-1).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Any

from ..core.params import length
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
from ..physics import springs as sp
from ..procedures import spring_design as sd
from ..procedures.clutch_asbuilt import DISC_YIELD_DEFAULT
from .clutch import BALL_CLUTCH_SETTING

_CLUTCH_NAMES = (
    "target_torque",
    "ball_circle_diameter",
    "ball_count",
    "ball_diameter",
    "groove_angle",
    "load_factor",
    "flank_friction",
    "spring_arrangement",
    "driving_groove_angle",
    "flank_construction",
    "ball_lift",
)


def _clutch_param(p: Param) -> Param:
    if p.name == "target_torque":
        return dataclasses.replace(
            p, required=True, description="T, the slipping torque to set [001, eq. 1–3]"
        )
    if p.name == "ball_lift":
        return dataclasses.replace(
            p,
            required=True,
            minimum=1e-5,
            description="h, rise of the ball (and the pressure disk) along the flank from "
            "seated to the groove's rim; the stroke adds the rise over the rim",
        )
    return p


INPUTS: tuple[Param, ...] = (
    *(_clutch_param(p) for p in BALL_CLUTCH_SETTING.inputs if p.name in _CLUTCH_NAMES),
    length(
        "max_outer_diameter",
        "D_e,max, largest outer diameter of the spring (the bore it sits in)",
        minimum=1e-3,
        maximum=1.0,
        required=True,
        symbol="D_e,max",
        group="space",
    ),
    length(
        "min_inner_diameter",
        "D_i,min, smallest inner diameter of the spring (the shaft it sits on); 0 for none",
        minimum=0.0,
        maximum=1.0,
        default=0.0,
        symbol="D_i,min",
        group="space",
    ),
    length(
        "max_set_length",
        "L_1, the pocket's length: the spring's length at the setting (its free length is "
        "chosen so that it sits at this length)",
        minimum=1e-3,
        maximum=2.0,
        required=True,
        symbol="L_1",
        group="space",
    ),
    Param(
        "spring_kind",
        "1",
        "'helical': a helical compression spring (EN 13906-1); 'disc_pack': a stack of "
        "DIN 2093 standard disc springs, n nested in parallel in each of i packs in series "
        "(DIN EN 16983)",
        default="helical",
        kind="choice",
        choices=sd.SPRING_KINDS,
        choice_labels=("helical spring", "disc pack"),
        group="spring",
    ),
    Param(
        "spring_material",
        "1",
        "spring wire: EN 10270-1 SH or DH, or 1.4310 (EN 10270-3); G, E, ρ and "
        "τ_zul = 0.5 R_m(d) from the tables",
        default="EN10270-1-DH",
        kind="choice",
        choices=tuple(sp.MATERIALS),
        group="spring",
        used_with="spring_kind=helical",
    ),
    Param(
        "spring_seating",
        "1",
        "end seating for buckling: fixed_fixed (ν = 0.5, parallel ground ends), "
        "fixed_hinged (0.7), hinged_hinged (1), fixed_free (2)",
        default="fixed_fixed",
        kind="choice",
        choices=tuple(sp.SEATING_COEFFICIENTS),
        group="spring",
        used_with="spring_kind=helical",
    ),
    Param(
        "dynamic_load",
        "1",
        "the minimum gap sum S_a × 1.5 (EN 13906-1, dynamic load)",
        default=False,
        kind="bool",
        group="spring",
    ),
    Param(
        "objective",
        "1",
        "'thinnest': the thinnest wire that passes every check, with the fewest coils that "
        "keep the stress, and of its springs the lightest (a larger force never gets a "
        "thinner wire); a disc pack: the fewest discs, then the smallest; "
        "'margin': the most coils (packs in series) the pocket allows, the most stress "
        "margin at full stroke",
        default="thinnest",
        kind="choice",
        choices=sd.OBJECTIVES,
        group="spring",
    ),
    Param(
        "disc_series",
        "1",
        "disc pack: the DIN 2093 series to choose from: A (stiff, h0/t ≈ 0.4), B (h0/t ≈ "
        "0.75), or any (the rows a public reprint of the standard's table confirms)",
        default="any",
        kind="choice",
        choices=sd.DISC_SERIES,
        group="disc pack",
        used_with="spring_kind=disc_pack",
    ),
    Param(
        "disc_yield_strength",
        "Pa",
        "disc pack: R_e, the limit of |σ_OM| at full stroke (DIN EN 16983, static or "
        "moderate fatigue load; about 1400…1600 MPa for C60S and 51CrV4)",
        default=DISC_YIELD_DEFAULT,
        minimum=500e6,
        maximum=2500e6,
        display_unit="MPa",
        symbol="R_e",
        group="disc pack",
        used_with="spring_kind=disc_pack",
    ),
)

OUTPUTS: tuple[Output, ...] = (
    Output(
        "wire_diameter",
        "m",
        "d, a preferred EN 10270-1 size",
        display_unit="mm",
        symbol="d",
        step="EN 10270-1",
    ),
    Output(
        "mean_diameter",
        "m",
        "D, mean coil diameter",
        display_unit="mm",
        symbol="D",
        step="EN 13906-1",
    ),
    Output("active_coils", "1", "n, active coils (half coils)", symbol="n", step="EN 13906-1"),
    Output(
        "total_coils", "1", "n_t = n + 2, closed and ground ends", symbol="n_t", step="EN 13906-1"
    ),
    Output(
        "free_length",
        "m",
        "L0 = L1 + s1 (a disc pack: i (h0 + n t))",
        display_unit="mm",
        symbol="L_0",
        step="EN 13906-1",
    ),
    Output("rate", "N/m", "R = G d⁴/(8 D³ n)", display_unit="N/mm", symbol="R", step="EN 13906-1"),
    Output(
        "set_force",
        "N",
        "F1, spring force at the setting [001, eq. 1–3]",
        symbol="F_1",
        step="[001, eq. 1–3]",
    ),
    Output(
        "stroke",
        "m",
        "s_h = h + (d_b/2)(1 − sin α): the balls' whole lift",
        display_unit="mm",
        symbol="s_h",
        step="[001, eq. 1–3]",
    ),
    Output(
        "set_length",
        "m",
        "L1, length at the setting (the pocket; a disc pack: the stack, a shim fills the rest)",
        display_unit="mm",
        symbol="L_1",
        step="EN 13906-1",
    ),
    Output(
        "set_deflection",
        "m",
        "s1 = F1/R, the nut setting",
        display_unit="mm",
        symbol="s_1",
        step="EN 13906-1",
    ),
    Output(
        "stroke_force",
        "N",
        "F2 = F1 + R s_h, force at full stroke",
        symbol="F_2",
        step="EN 13906-1",
    ),
    Output(
        "stroke_length",
        "m",
        "L2 = L1 − s_h, length at full stroke",
        display_unit="mm",
        symbol="L_2",
        step="EN 13906-1",
    ),
    Output(
        "solid_length",
        "m",
        "L_c = n_t d (a disc pack: i n t, pressed flat)",
        display_unit="mm",
        symbol="L_c",
        step="EN 13906-1",
    ),
    Output(
        "gap_sum",
        "m",
        "S_a, minimum sum of gaps at full stroke (EN 13906-1)",
        display_unit="mm",
        symbol="S_a",
        step="EN 13906-1",
    ),
    Output(
        "permissible_stress",
        "Pa",
        "τ_zul = 0.5 R_m(d)",
        display_unit="MPa",
        symbol="τ_zul",
        step="EN 13906-1",
    ),
    Output(
        "shear_stress_set",
        "Pa",
        "τ_k1 = k 8 F1 D/(π d³), Bergsträsser's k",
        display_unit="MPa",
        symbol="τ_k1",
        step="EN 13906-1",
    ),
    Output(
        "shear_stress_stroke",
        "Pa",
        "τ_k2 at F2",
        display_unit="MPa",
        symbol="τ_k2",
        step="EN 13906-1",
    ),
    Output(
        "buckling_deflection",
        "m",
        "s_K; null: it cannot buckle",
        display_unit="mm",
        symbol="s_K",
        step="EN 13906-1",
    ),
    Output("mass", "kg", "m = ρ (π d²/4) π D n_t", display_unit="g", symbol="m", step="EN 13906-1"),
    Output("stress_utilisation_set", "1", "τ_k1/τ_zul", symbol="τ_k1/τ_zul", step="EN 13906-1"),
    Output("stress_utilisation_stroke", "1", "τ_k2/τ_zul", symbol="τ_k2/τ_zul", step="EN 13906-1"),
    Output(
        "disc_designation",
        "1",
        "the standard disc of the pack (DIN 2093)",
        kind="str",
        symbol="",
        step="DIN EN 16983",
    ),
    Output(
        "disc_outer_diameter",
        "m",
        "De of the discs",
        display_unit="mm",
        symbol="D_e",
        step="DIN EN 16983",
    ),
    Output(
        "disc_inner_diameter",
        "m",
        "Di of the discs",
        display_unit="mm",
        symbol="D_i",
        step="DIN EN 16983",
    ),
    Output(
        "disc_thickness", "m", "t of one disc", display_unit="mm", symbol="t", step="DIN EN 16983"
    ),
    Output(
        "disc_cone_height",
        "m",
        "h0, free cone height of one disc",
        display_unit="mm",
        symbol="h_0",
        step="DIN EN 16983",
    ),
    Output(
        "discs_parallel",
        "1",
        "n, discs nested in parallel in each pack",
        kind="int",
        symbol="n",
        step="DIN EN 16983",
    ),
    Output(
        "discs_series",
        "1",
        "i, packs in series (alternately facing)",
        kind="int",
        symbol="i",
        step="DIN EN 16983",
    ),
    Output("disc_count", "1", "n i, discs in the stack", kind="int", symbol="", step=""),
    Output(
        "disc_set_deflection",
        "m",
        "s1 per disc at the setting: n F(s1) = F1 (DIN EN 16983)",
        display_unit="mm",
        symbol="s_1",
        step="DIN EN 16983",
    ),
    Output(
        "disc_stroke_deflection",
        "m",
        "s2 = s1 + s_h/i per disc at full stroke, ≤ 0.75 h0",
        display_unit="mm",
        symbol="s_2",
        step="DIN EN 16983",
    ),
    Output(
        "disc_stress_om",
        "Pa",
        "|σ_OM| at full stroke (DIN EN 16983)",
        display_unit="MPa",
        symbol="σ_OM",
        step="DIN EN 16983",
    ),
    Output(
        "disc_stress_utilisation",
        "1",
        "|σ_OM|/R_e at full stroke",
        symbol="|σ_OM|/R_e",
        step="DIN EN 16983",
    ),
    Output(
        "shim_length",
        "m",
        "the pocket's length less the stack's at the setting",
        display_unit="mm",
        symbol="",
        step="",
    ),
    *(
        Output(
            f"margin_{c}",
            "1",
            f"margin of the {c.replace('_', ' ')} check: ≥ 0 passes",
            symbol="",
            step="EN 13906-1",
        )
        for c in (*sd.CHECKS, *(c for c in sd.DISC_CHECKS if c not in sd.CHECKS))
    ),
    Output(
        "binding_limit",
        "1",
        "the check with the least margin (or the one failed)",
        kind="str",
        symbol="",
        step="",
    ),
    Output("candidates_checked", "1", "springs (d, D) evaluated", kind="int", symbol="", step=""),
    Output(
        "candidates_passing", "1", "springs that pass every check", kind="int", symbol="", step=""
    ),
)

_WHAT = {
    "spring_index": "spring index D/d within 4…20",
    "outer_diameter": "outer diameter D + d within the bore",
    "inner_diameter": "inner diameter D − d clear of the shaft",
    "stress_at_set": "τ_k at the setting within τ_zul",
    "stress_at_stroke": "τ_k at full stroke within τ_zul",
    "coil_gaps": "length at full stroke ≥ L_c + S_a",
    "buckling": "deflection at full stroke within s_K",
    "disc_preload": "deflection per disc at the setting ≥ 0.15 h0 under dynamic load (DIN 2093)",
    "disc_deflection": "deflection per disc at full stroke ≤ 0.75 h0",
    "disc_stress_om": "|σ_OM| at full stroke within R_e (DIN EN 16983)",
    "stack_length": "the stack at the setting within the pocket's length",
}
_WHAT_DISC = {
    **_WHAT,
    "outer_diameter": "disc outer diameter De within the bore",
    "inner_diameter": "disc inner diameter Di clear of the shaft",
}


def _checks(v: Mapping[str, Any], disc: bool = False) -> list[Check]:
    out = []
    what = _WHAT_DISC if disc else _WHAT
    for c in sd.DISC_CHECKS if disc else sd.CHECKS:
        m = v[f"margin_{c}"]
        if m is None:  # e.g. a spring so slender it buckles at no deflection (s_K = 0)
            out.append(Check(c, False, f"{what[c]}: fails beyond any margin"))
        else:
            out.append(
                Check(c, m >= 0.0, f"{what[c]}: margin {m:+.3f}" + ("" if m >= 0.0 else " (fails)"))
            )
    return out


_SCALARS = tuple(o.name for o in OUTPUTS)


def _disc_result(x: Mapping[str, Any], v: dict[str, Any], ctx: RunContext) -> Result:
    """The disc pack's values (the helical spring's left null), checks and notes."""
    v["disc_stress_utilisation"] = v["disc_stress_om"] / v["permissible_stress"]
    values = {k: v.get(k) for k in _SCALARS}
    pack = (
        f"{v['disc_designation']}, {v['discs_parallel']} in parallel × "
        f"{v['discs_series']} in series ({v['disc_count']} discs), stack "
        f"{v['free_length'] * 1e3:.4g} mm free, {v['set_length'] * 1e3:.4g} mm at the setting"
    )
    binding = v["binding_limit"]
    if v["candidates_passing"]:
        verdict = (
            f"{v['candidates_passing']} of {v['candidates_checked']} disc packs (disc and n "
            f"in parallel) pass every check; the chosen ({x['objective']}) is {pack}; the "
            f"least margin is {_WHAT_DISC[binding]}"
        )
    else:
        verdict = (
            f"no disc pack in the bounds passes every check: the binding limit is "
            f"{_WHAT_DISC[binding]}; the nearest pack that passes every other check is {pack}"
        )
    notes = [
        verdict,
        f"F1 = {v['set_force']:.4g} N at {x['target_torque']:g} N·m (clutch.ball_setting's "
        "required_spring_force); frictionless pack: the friction between nested discs raises "
        "the loading force by 1/(1 − w_M (n − 1) − w_R) (DIN EN 16983); run clutch.ball with "
        "this stack (spring_type disc) for the characteristic",
        "the discs' force and σ_OM after Almen and László (DIN EN 16983, E 206 GPa, μ 0.3); "
        "fatigue life is not checked: DIN 2093's endurance diagrams are not transcribed",
    ]
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        checks=_checks(v, disc=True),
        notes=notes,
    )


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    v = sd.spring_design(x)
    if x["spring_kind"] == "disc_pack":
        return _disc_result(x, v, ctx)
    v["stress_utilisation_set"] = v["shear_stress_set"] / v["permissible_stress"]
    v["stress_utilisation_stroke"] = v["shear_stress_stroke"] / v["permissible_stress"]
    if not math.isfinite(v["buckling_deflection"]):
        v["buckling_deflection"] = None
    for c in sd.CHECKS:
        if not math.isfinite(v[f"margin_{c}"]):
            v[f"margin_{c}"] = None
    spring = (
        f"d {q(v['wire_diameter'], 'mm', 6)}, D {q(v['mean_diameter'], 'mm', 4)}, "
        f"n {v['active_coils']:g}, L0 {q(v['free_length'], 'mm', 4)}"
    )
    binding = v["binding_limit"]
    if v["candidates_passing"]:
        verdict = (
            f"{v['candidates_passing']} of {v['candidates_checked']} springs pass every check; "
            f"the chosen ({x['objective']}) is {spring}; the least margin is {_WHAT[binding]}"
        )
    else:
        verdict = (
            f"no spring in the bounds passes every check: the binding limit is "
            f"{_WHAT[binding]}; the nearest spring "
            f"that passes every other check is {spring}"
        )
    notes = [
        verdict,
        f"F1 = {q(v['set_force'], 'N', 4)} is the force that makes the balls start to move at "
        f"{q(x['target_torque'], 'N*m', 6)} (clutch.ball_setting's required_spring_force); while "
        "they climb the spring is compressed by the stroke, so the peak torque is higher: "
        "run clutch.ball with this spring for the characteristic",
        "free length chosen so that the spring sits at the pocket's length L1 at the setting; "
        "the stress at solid length is not checked (a stop at L2 keeps it off solid)",
    ]
    return Result(
        values={k: v.get(k) for k in _SCALARS},
        rung=ctx.rung,
        error_estimate=0.0,
        checks=_checks(v),
        notes=notes,
    )


CLOSED_FORM = Rung(
    "closed_form",
    "EN 13906-1's relations over a grid of preferred wires and mean diameters; the coils "
    "in half coils. Exact against the stated relations; the grid's D step (0.1 mm, or "
    "1/400 of the range) bounds how close to a limit the chosen spring lies; a disc pack: "
    "every DIN 2093 disc with 1…4 in parallel, its deflection at the setting solved to "
    "machine precision and the packs in series counted, to DIN EN 16983",
    fixed_error(0.0),
    typical_error="exact against the stated relations",
    typical_time="1.5–4 ms",
    steps=(
        sd.clutch_duty,
        sd.candidate_grid,
        sd.coils,
        sd.evaluate,
        sd.disc_candidates,
        sd.disc_set_deflection,
        sd.discs_in_series,
        sd.evaluate_discs,
        sd.choose,
    ),
)

#: The issue's clutch (clutch.ball_setting's second example) set for 60 N·m, in a
#: 40 mm bore on a 20 mm shaft, 80 mm long.
SIXTY_NM = {
    "target_torque": 60.0,
    "ball_circle_diameter": 0.05,
    "ball_count": 4,
    "ball_diameter": 0.01,
    "groove_angle": math.radians(45.0),
    "flank_friction": 0.1,
    "ball_lift": 0.002,
    "max_outer_diameter": 0.040,
    "min_inner_diameter": 0.020,
    "max_set_length": 0.080,
}

SPRING_DESIGN = ModelSpec(
    requirements_of="EN 13906-1 / DIN EN 16983",
    answer=(
        Answer("wire_diameter", "d"),
        Answer("mean_diameter", "D", check="spring_index"),
        Answer("active_coils", "n"),
        Answer("free_length", "L_0", check="coil_gaps"),
        Answer("rate", "R"),
        Answer(
            "stress_utilisation_stroke",
            "τ_k2/τ_zul",
            check="stress_at_stroke",
            relation="≤",
            bound=1.0,
        ),
        # a disc pack's (null for a helical spring, and so left off its card)
        Answer("disc_outer_diameter", "D_e", check="outer_diameter"),
        Answer("discs_parallel", "n"),
        Answer("discs_series", "i", check="disc_deflection"),
        Answer(
            "disc_stress_utilisation",
            "|σ_OM|/R_e",
            check="disc_stress_om",
            relation="≤",
            bound=1.0,
        ),
    ),
    name="clutch.spring_design",
    title="Ball safety clutch: the spring for a setting (EN 13906-1, DIN EN 16983)",
    family="clutch",
    summary=(
        "The helical compression spring a ball clutch's setting needs: wire, mean diameter, "
        "coils and free length from the clutch's spring force and stroke and the space, "
        "checked to EN 13906-1 (stress at the setting and at full stroke, solid length with "
        "the minimum gap sum, buckling, spring index); where none fits, the binding limit "
        "and the nearest spring that passes every other check. Or a stack of DIN 2093 "
        "standard disc springs (n in parallel, i in series) to DIN EN 16983: deflection per "
        "disc within 0.75 h0, σ_OM within R_e, the stack within the pocket."
    ),
    source=(
        "[001, eq. 1–3] for the force; EN 13906-1 for the spring; EN 10270-1 wire sizes; "
        "DIN EN 16983 and DIN 2093's standard discs for a disc pack"
    ),
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_compute,
    examples=(
        SIXTY_NM,
        # the paper's clutch at 0.5 N·m: a light spring in a roomy pocket
        {
            **SIXTY_NM,
            "target_torque": 0.5,
            "flank_friction": 0.0,
            "max_outer_diameter": 0.050,
            "min_inner_diameter": 0.0,
            "max_set_length": 0.040,
        },
        # the 60 N·m setting with a stack of disc springs in the same pocket
        {**SIXTY_NM, "spring_kind": "disc_pack"},
    ),
)
