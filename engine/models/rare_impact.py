"""The ``impact.rare`` model: inputs, outputs, rungs, checks and notes.

The physics is in :mod:`engine.procedures.striker_cycle` (the Lagrangian stage 1 of
a stated roller geometry and the whole cycle, simulated or in closed form)
and :mod:`engine.physics.rare_impact` (the paper's formulas: eq. 5 coefficients, eq. 6,
the return and re-lock conditions); source [002], scan [003], see
docs/sources.md. This module declares the model and reads every output and
every check from one :class:`~engine.procedures.striker_cycle.CycleOutcome`, so that
times and verdicts cannot contradict each other.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from collections.abc import Set as AbstractSet
from typing import Any, cast

import numpy as np

from ..core.errors import EngineError
from ..core.params import count, friction_coefficient, in_mm, in_ms, in_n_per_mm, in_rpm, positive
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
    Scratch,
    Window,
)
from ..core.text import q
from ..numerics.ode import divide, is_array, pymax, quiet, where
from ..physics.rare_impact import (
    G0,
    engagement_window,
    full_engagement,
    min_return_spring_rate,
    relock_margin,
    spring_height_limit,
    striker_oscillation,
)
from ..procedures.striker_cycle import (
    GEOMETRIES,
    CycleOutcome,
    Release,
    closed_form_cycle,
    closed_form_errors,
    closed_form_release,
    cycle_setups,
    moving_mass,
    release_speed_of,
    relock_friction,
    simulate_cycle,
    simulation_release_velocity_error,
    step_inputs,
)

_SIMULATION_ERROR = 1e-6
_SERIES = (
    "time",
    "flywheel_speed",
    "half_coupling_lift",
    "striker_travel",
    "shaft_lift",
    "roller_position",
    "stage",
)
#: Which error group of the closed form each output belongs to (None: a formula of the
#: paper, no model error of its own; a sum of stage times: the groups of its parts, the
#: relative error of a sum being at most the largest of its parts').
_GROUP = {
    "release_speed": "stage1",
    "spin_up_time": "stage1",
    "release_radius": None,
    "engagement_window": "stage1",
    "engagement_start": "stage1",
    "engagement_end": "stage1",
    "engagement_time": "engagement",
    "engagement_margin": "engagement",
    "full_engagement": "engagement",
    "max_striker_travel": "engagement",
    "blow_time": "stage1",
    "return_time": "return",
    "striker_home_time": ("stage1", "engagement", "return"),
    "relock_time": "relock",
    "cycle_time": ("stage1", "engagement", "return", "relock"),
}
_GEOMETRY_TEXT = {
    "symmetric_v": "symmetric V (both cones, x = x0 + z1/(2 tan α))",
    "single_cone": "single cone (x = x0 + z1/tan α, striker face flat)",
    "paper": "the paper's printed eq. 1",
}


def spring_height_bounds(moving_mass: Any, gravity: Any, c1: Any, c3: Any) -> tuple[Any, Any]:
    r"""Engagement heights the springs allow under [002, eq. 6]'s assumptions: (lower, upper) [m].

    With balanced preloads :math:`c_1\lambda_1 = c_3\lambda_3` and
    :math:`h_1 = h_2 = h`, the reach :math:`2[M_2g + c_1h]/(c_1 + c_3) \ge h`
    is :math:`h(c_3 - c_1) \le 2M_2g`. For :math:`c_3 > c_1` that is the
    paper's upper limit :math:`2M_2g/(c_3 - c_1)`, which is 0 (nothing
    reachable) when gravity does not help (g ≤ 0); for :math:`c_3 < c_1` it is
    a *lower* bound :math:`2M_2|g|/(c_1 - c_3)` when g < 0 and no bound at all
    otherwise; for :math:`c_3 = c_1` any height when g ≥ 0, none when g < 0.
    ``inf`` upper = no upper limit. Floats or arrays of one shape.

    >>> spring_height_bounds(0.85, 9.80665, 50000.0, 52000.0)[1]  # 16.671/2000
    0.0083356525
    >>> spring_height_bounds(0.85, -9.80665, 50000.0, 52000.0)
    (0.0, 0.0)
    >>> spring_height_bounds(0.85, -9.80665, 52000.0, 50000.0)
    (0.0083356525, inf)
    """
    d, w = _spring_height_terms(moving_mass, gravity, c1, c3)
    lower = where((d < 0.0) & (w < 0.0), w / where(d < 0.0, d, -1.0), 0.0)
    return lower, spring_height_upper(moving_mass, gravity, c1, c3)


def _spring_height_terms(moving_mass: Any, gravity: Any, c1: Any, c3: Any) -> tuple[Any, Any]:
    r""":math:`c_3 - c_1` and :math:`2M_2g` of :func:`spring_height_bounds`' inequality
    :math:`h(c_3 - c_1) \le 2M_2g`."""
    return c3 - c1, 2.0 * moving_mass * gravity


def spring_height_upper(moving_mass: Any, gravity: Any, c1: Any, c3: Any) -> Any:
    """The upper of :func:`spring_height_bounds` alone [m] (the ``spring_height_limit``
    output, which reads no lower bound).

    >>> spring_height_upper(0.85, 9.80665, 50000.0, 52000.0)  # 16.671/2000
    0.0083356525
    """
    d, w = _spring_height_terms(moving_mass, gravity, c1, c3)
    # the paper's limit (inf for c3 <= c1), never below 0; none at all for c3 = c1, g < 0
    return where(
        (d == 0.0) & (w < 0.0), 0.0, pymax(spring_height_limit(moving_mass, gravity, c1, c3), 0.0)
    )


def _outcome(x: Mapping[str, Any], ctx: RunContext) -> CycleOutcome:
    if ctx.rung == "simulation":
        setup = None if ctx.prepared is None else ctx.prepared[0]  # _prepare_points'
        return simulate_cycle(
            # a looped point's scratch is its own and nothing else reads its inputs (no
            # error estimate, no geometry note): converted without the scratch's closure,
            # or not at all where its set-up was made for its chunk (ctx.prepared)
            _inputs(x, ctx.scratch) if ctx.sentences else step_inputs(x) if setup is None else x,
            record=ctx.wants(*_SERIES),
            deadline=ctx.deadline,
            max_steps=ctx.max_steps,
            sentences=ctx.sentences,
            setup=setup,
        )
    o = _cycle(x, ctx.scratch)
    if o.refused:
        closed_form_cycle(x)  # raises the refusal with its reason
    return o


def _prepare_points(x: Mapping[str, Any], rung: str) -> list[Any] | None:
    """A study's looped points' work from their inputs alone, made for them at once: a
    (setup, outputs) pair a point, the simulation's set-up
    (:func:`engine.procedures.striker_cycle.cycle_setups`: the kernel's parameters, stage
    1's speeds, times and step, the stages' step sizes, a row per design) and the outputs
    of the inputs alone (:func:`_of_inputs`), either None where the point works it out
    itself; the closed form has none (its points go through the array path).

    The outputs on arrays where numpy raises on a division by zero, an overflow and an
    invalid operation (where one design's floats could raise, the points work them out).
    """
    if rung != "simulation":
        return None
    n = next(len(v) for v in x.values() if isinstance(v, np.ndarray))
    setups = cycle_setups(x) or [None] * n
    try:
        with np.errstate(divide="raise", over="raise", invalid="raise", under="ignore"):
            got = _of_inputs(x, True, frozenset())
    except (ArithmeticError, ValueError):
        return [(setup, None) for setup in setups]
    columns = [v.tolist() if isinstance(v, np.ndarray) else [v] * n for v in got]
    return list(zip(setups, zip(*columns, strict=True), strict=True))


def _cycle(x: Mapping[str, Any], scratch: Scratch) -> CycleOutcome:
    """The closed form's cycle for one design (numbers) or many (arrays), refusals marked.

    Once per request: the rung estimate and the outputs of a run (or of a sweep chunk)
    read the same cycle from the request's ``scratch``, which no other request sees.
    """
    return scratch.once(
        "impact.rare cycle", lambda: closed_form_cycle(_inputs(x, scratch), refuse=False)
    )


def _inputs(x: Mapping[str, Any], scratch: Scratch) -> Mapping[str, Any]:
    """The inputs as the procedure's steps take them, converted once per request."""
    return scratch.once("impact.rare inputs", lambda: step_inputs(x))


def _errors(x: Mapping[str, Any], scratch: Scratch) -> dict[str, Any]:
    """:func:`engine.procedures.striker_cycle.closed_form_errors` of the closed form's cycle."""
    return scratch.once(
        "impact.rare errors", lambda: closed_form_errors(_inputs(x, scratch), _cycle(x, scratch))
    )


def _closed_form_estimate(x: Mapping[str, Any], scratch: Scratch) -> Any:
    """Worst estimated error over the closed form's outputs for these inputs.

    On arrays (a sweep or a study): an array, NaN where one design gives None. The
    cycle it needs is left in the request's ``scratch`` for the run.
    """
    groups = _errors(x, scratch)
    worst = groups["stage1"]
    for group in ("engagement", "return", "relock"):
        # a group with no estimate (NaN: rollers that fly at the blow) leaves none at all
        worst = where(np.isnan(groups[group]), math.nan, pymax(worst, groups[group]))
    if is_array(worst):
        return np.where(np.isfinite(worst), worst, np.nan)
    return float(worst) if math.isfinite(worst) else None


def _groups(output: str) -> tuple[str, ...]:
    """The closed form's error groups an output's estimate is the largest of (:data:`_GROUP`)."""
    group = _GROUP[output]
    return () if group is None else (group,) if isinstance(group, str) else group


#: (output, its groups) for every output of :data:`_GROUP`, read once a run.
_OUTPUT_GROUPS = tuple((name, _groups(name)) for name in _GROUP)


@functools.lru_cache(maxsize=64)
def _groups_asked(wanted: frozenset[str]) -> tuple[str, ...]:
    """The error groups the outputs in ``wanted`` read, each once (by value: a set of outputs
    is asked for again and again, every output by default).

    >>> _groups_asked(frozenset({"cycle_time", "release_speed", "release_radius"}))
    ('stage1', 'engagement', 'return', 'relock')
    >>> _groups_asked(frozenset({"release_radius"}))
    ()
    """
    return tuple(dict.fromkeys(g for n, groups in _OUTPUT_GROUPS if n in wanted for g in groups))


def _output_error(x: Mapping[str, Any], ctx: RunContext) -> float | None:
    """Estimated error of the outputs asked for: the largest of their groups' estimates."""
    errs = _errors(x, ctx.scratch)
    asked = [errs[g] for g in _groups_asked(frozenset(ctx.outputs))]
    if not asked:
        return 0.0
    if not all(math.isfinite(e) for e in asked):
        return None
    return float(max(asked))


def _simulation_estimate(x: Mapping[str, Any]) -> float:
    return _SIMULATION_ERROR  # a constant: broadcast over the points of a sweep


def _of_inputs(x: Mapping[str, Any], every: bool, want: AbstractSet[str]) -> tuple[Any, ...]:
    """The outputs of the inputs alone (:data:`_OF_INPUTS`, in its order; None where not
    asked for in ``want``, unless ``every``), one design (numbers) or many (arrays):
    :func:`_outputs`' lines that read no cycle, which a study's looped chunk runs for its
    points at once (:func:`_prepare_points`)."""
    c1, c3 = x["power_spring_rate"], x["return_spring_rate"]
    g = x["gravity"]
    b = k = limit = c3_min = margin = None
    if every or "engagement_acceleration" in want or "engagement_frequency" in want:
        b, k = striker_oscillation(
            c1,
            x["power_spring_preload"],
            c3,
            x["return_spring_preload"],
            x["release_travel"],
            moving_mass(x),
            g,
        )
    if every or "spring_height_limit" in want:
        limit = spring_height_upper(moving_mass(x), g, c1, c3)
    if every or "min_return_spring_rate" in want:
        c3_min = min_return_spring_rate(
            x["striker_mass"],
            g,
            x["return_spring_preload"],
            x["engagement_height"],
            x["jaw_height"],
        )
    if every or "relock_margin" in want:
        margin = relock_margin(
            x["auxiliary_spring_rate"],
            x["auxiliary_spring_preload"],
            x["stepped_shaft_mass"],
            g,
            relock_friction(x),
        )
    return b, k, limit, c3_min, margin


#: The outputs :func:`_of_inputs` gives, in its order.
_OF_INPUTS = (
    "engagement_acceleration",
    "engagement_frequency",
    "spring_height_limit",
    "min_return_spring_rate",
    "relock_margin",
)


def _outputs(
    x: Mapping[str, Any],
    o: CycleOutcome | Release,
    wanted: AbstractSet[str] | None = None,
    of_inputs: tuple[Any, ...] | None = None,
) -> dict[str, Any]:
    """Every numeric output (and full_engagement) from the inputs and a cycle's outcome.

    One design (numbers) or many (arrays): NaN or inf where the output is null (never
    reached), read by :func:`_compute` as None and by :func:`_vectorized` as NaN.
    ``wanted``: the outputs to give (every one when None; more may come), each line run
    only where its output is asked for (those of the later stages together); a
    :class:`~engine.procedures.striker_cycle.Release` (stage 1 alone) serves the outputs
    of :data:`_RELEASE_OUTPUTS`. ``of_inputs``: what :func:`_of_inputs` gives for ``x`` and
    ``wanted``, where it was worked out already (a study's looped point, its chunk's).
    """
    every = wanted is None
    want: AbstractSet[str] = frozenset() if wanted is None else wanted
    # read only by the lines of the later stages, which a Release is never asked for
    c = cast(CycleOutcome, o)
    out: dict[str, Any] = {}
    with quiet(is_array(o.release_speed)):
        b, k, limit, c3_min, margin = _of_inputs(x, every, want) if of_inputs is None else of_inputs
        window = (
            engagement_window(x["engagement_angle"], o.release_speed)
            if every or not _WINDOW_READERS.isdisjoint(want) or not _CYCLE_READERS.isdisjoint(want)
            else None
        )
        if every or "release_speed" in want:
            out["release_speed"] = o.release_speed
        if every or "spin_up_time" in want:
            out["spin_up_time"] = o.spin_up_time
        if every or "release_radius" in want:
            out["release_radius"] = o.release_radius
        if b is not None:  # in _outputs' order, which run gives
            out["engagement_acceleration"] = b
            out["engagement_frequency"] = k
        if every or not _CYCLE_READERS.isdisjoint(want):
            t_blow = o.spin_up_time + c.engagement_time
            out["max_striker_travel"] = c.max_travel
            out["engagement_time"] = c.engagement_time
        if window is not None:
            out["engagement_window"] = window
            out["engagement_start"] = o.spin_up_time
            out["engagement_end"] = o.spin_up_time + window
        if every or not _CYCLE_READERS.isdisjoint(want):
            out["full_engagement"] = full_engagement(c.blow, c.engagement_time, window)
            out["engagement_margin"] = where(
                c.blow, divide(window - c.engagement_time, window), math.nan
            )
            out["blow_time"] = t_blow
        if limit is not None:
            out["spring_height_limit"] = limit
        if c3_min is not None:
            out["min_return_spring_rate"] = c3_min
        if margin is not None:
            out["relock_margin"] = margin
        if every or not _CYCLE_READERS.isdisjoint(want):
            out["return_time"] = where(c.returns, c.return_time, math.nan)
            out["striker_home_time"] = where(c.returns, t_blow + c.home_time, math.nan)
            out["relock_time"] = where(c.relocks, c.relock_time, math.nan)
            out["cycle_time"] = c.cycle_time
    return out


#: The outputs of the later stages (a :class:`CycleOutcome`'s): asked for one, :func:`_outputs`
#: gives them all, their lines sharing the blow's time.
_CYCLE_READERS = frozenset(
    {
        "max_striker_travel",
        "engagement_time",
        "full_engagement",
        "engagement_margin",
        "blow_time",
        "return_time",
        "striker_home_time",
        "relock_time",
        "cycle_time",
    }
)
#: The outputs of stage 1 that read the engagement window φ_eng/ω_M (every later one does).
_WINDOW_READERS = frozenset({"engagement_window", "engagement_start", "engagement_end"})

#: The outputs :func:`_outputs` gives from stage 1 alone (a
#: :class:`~engine.procedures.striker_cycle.Release`): the release, the window, and the
#: formulas of the inputs alone.
_RELEASE_OUTPUTS = frozenset(
    {
        "release_speed",
        "spin_up_time",
        "release_radius",
        "engagement_acceleration",
        "engagement_frequency",
        "engagement_window",
        "engagement_start",
        "engagement_end",
        "spring_height_limit",
        "min_return_spring_rate",
        "relock_margin",
    }
)


def _verdicts(x: Mapping[str, Any], o: CycleOutcome) -> dict[str, Any]:
    """The verdict of every check (:func:`design_checks`, in its order), one design or many."""
    window = engagement_window(x["engagement_angle"], o.release_speed)
    return {
        "c3 > c1": x["return_spring_rate"] > x["power_spring_rate"],
        "λ1 < λ3": x["power_spring_preload"] < x["return_spring_preload"],
        "eq. 6 (engagement height)": o.blow,
        "return": o.returns,
        "relock": o.relocks,
        "full engagement": full_engagement(o.blow, o.engagement_time, window),
    }


def _nullable(column: Any, dead: np.ndarray) -> np.ndarray:
    """A column as the array contract wants it: NaN where null (float), None where refused (bool).

    A float output the scalar form leaves null (inf: never reached) is NaN, as at a
    refused point; a sweep tells the two apart by the other outputs (a refused point
    has no finite one). A bool output has no NaN: an object column with None at the
    refused points.
    """
    column = np.asarray(column)
    if column.dtype == bool:
        if not dead.any():
            return column
        out = column.astype(object)
        out[dead] = None
        return out
    finite = np.isfinite(column)
    return column if finite.all() else np.where(finite, column, np.nan)


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """The closed form at many points (the array path of sweeps and studies).

    The same lines as a single run (:func:`_outputs`, :func:`_verdicts` on
    :func:`engine.procedures.striker_cycle.closed_form_cycle`); NaN/None where a single
    run refuses the point or leaves the output null, and the verdicts of
    :func:`design_checks` as ``check_arrays``.
    """
    if ctx.rung != "closed_form":
        raise EngineError(f"impact.rare has no array path for the rung {ctx.rung!r}")
    # a sweep reads no checks: where it asks only for outputs of stage 1, stages 2-4 are
    # left out (the same arrays: closed_form_release is closed_form_cycle's stage 1)
    wanted = None if ctx.checks else ctx.outputs
    o: CycleOutcome | Release
    if wanted is not None and wanted <= _RELEASE_OUTPUTS:
        o = closed_form_release(_inputs(x, ctx.scratch))
    else:
        o = _cycle(x, ctx.scratch)
    dead = o.refused
    n = dead.shape
    any_dead = bool(dead.any())
    values: dict[str, Any] = {}
    for name, raw in _outputs(x, o, wanted).items():
        column = np.broadcast_to(np.asarray(raw), n)
        if column.dtype != bool:
            column = column.astype(float, copy=False)
            if any_dead:
                column = np.where(dead, np.nan, column)
        values[name] = _nullable(column, dead)
    # null on the closed form (a single run says why in a note): None, not a column
    values["half_coupling_release_speed"] = None
    checks = {}
    # a point the model refuses reports no check; if every point is refused, no check at all
    # (and none where the caller reads none: a sweep)
    if ctx.checks and not dead.all():
        assert isinstance(o, CycleOutcome)  # every check reads the later stages
        for name, ok in _verdicts(x, o).items():
            code = np.broadcast_to(np.asarray(ok, dtype=np.int8), n)
            checks[name] = np.where(dead, np.int8(-1), code) if any_dead else code

    notes = [
        "closed form: quasi-static spin-up, piecewise-linear stages 2 and 4 started from "
        "the quasi-static release velocity, stage 3 with the half-coupling held; evaluated "
        "on arrays, the same equations as a single run (engine.procedures.striker_cycle)"
    ]
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=None,
        notes=notes,
        check_arrays=checks,
    )


def _geometry_note(x: Mapping[str, Any], w_m: float) -> str:
    """The model-form difference between the roller geometries for this design."""
    geo = x["roller_geometry"]
    parts = []
    for other in GEOMETRIES:
        if other == geo:
            continue
        try:
            w_o = release_speed_of(x, other)
        except EngineError:
            continue
        parts.append(
            f"{_GEOMETRY_TEXT[other]} {in_rpm(w_o)} ({100.0 * (divide(w_o, w_m) - 1.0):+.1f} %)"
        )
    text = (
        f"roller geometry: {_GEOMETRY_TEXT[geo]}; the quasi-static release speed under the "
        "other readings of [002, eq. 1] would be " + ", ".join(parts)
    )
    if geo == "paper":
        text += (
            "; the printed eq. 1 does not balance virtual power (the cones take "
            "n·2N·sin α·ẋ from the rollers and pass n·N·sin α·ẋ to the half-coupling): use it "
            "only to reproduce the paper"
        )
    return text


def design_checks(x: Mapping[str, Any], o: CycleOutcome) -> list[Check]:
    """The paper's conditions and the cycle's verdicts, each read from ``o``.

    c3 > c1 and λ1 < λ3 [002, after eq. 6] are the paper's design rules; the
    reach, return, re-lock and full-engagement checks say what the cycle
    (``o``, either rung) does, and quote the paper's condition as well.
    """
    c1, c2, c3 = x["power_spring_rate"], x["auxiliary_spring_rate"], x["return_spring_rate"]
    lam1, lam2, lam3 = (
        x["power_spring_preload"],
        x["auxiliary_spring_preload"],
        x["return_spring_preload"],
    )
    h2, h3, g = x["engagement_height"], x["jaw_height"], x["gravity"]
    ok = _verdicts(x, o)
    checks: list[Check] = []
    # a quantity two sentences quote is written once
    c3_text, h2_text = in_n_per_mm(c3), in_mm(h2)
    if ok["c3 > c1"]:
        checks.append(
            Check(
                "c3 > c1",
                True,
                f"the return spring ({c3_text}) is stiffer than the power spring "
                f"({in_n_per_mm(c1)}), as [002, eq. 6] asks",
            )
        )
    else:
        checks.append(
            Check(
                "c3 > c1",
                False,
                f"the return spring ({c3_text}) is not stiffer than the power spring "
                f"({in_n_per_mm(c1)}); the paper asks c3 > c1 [002, eq. 6] (for a vertical tool "
                "with balanced preloads): raise the return-spring rate or soften the power spring",
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
            bool(ok["λ1 < λ3"]),
            (
                f"the power-spring preload ({in_mm(lam1)}) is below the return-spring preload "
                f"({in_mm(lam3)}), as the paper asks [002, after eq. 6]"
                if ok["λ1 < λ3"]
                else f"the power-spring preload ({in_mm(lam1)}) is not below the return-spring "
                f"preload ({in_mm(lam3)}); the paper asks λ1 < λ3 [002, after eq. 6]: lower λ1 "
                "or raise λ3" + (contradiction if balanced else "")
            ),
        )
    )
    reach = o.max_travel
    checks.append(
        Check(
            "eq. 6 (engagement height)",
            bool(ok["eq. 6 (engagement height)"]),
            (
                f"the springs carry the striker to the engagement height {h2_text} (they "
                f"would carry it {in_mm(reach)}) [002, eqs. 5-6]"
                if o.blow
                else f"the springs carry the striker only {in_mm(reach)}, less than the "
                f"engagement height {h2_text} [002, eqs. 5-6]: it never engages. Raise the "
                "power spring's force at release c1(λ1 + h1), lower the return-spring preload "
                "c3·λ3 or the engagement height"
            ),
        )
    )
    c3_min = float(min_return_spring_rate(x["striker_mass"], g, lam3, h2, h3))
    paper_return = (
        f"; the paper's reduction (half-coupling at rest, rollers unloaded) asks c3 ≥ "
        f"{in_n_per_mm(c3_min)} [002, eq. 3]"
        if math.isfinite(c3_min)
        else ""
    )
    if not o.blow:
        checks.append(Check("return", False, "no blow, so no return (see eq. 6)"))
    elif ok["return"]:
        checks.append(
            Check(
                "return",
                True,
                f"the return spring ({c3_text}) brings the striker back the jaw height "
                f"{in_mm(h3)} in {in_ms(o.return_time)}" + paper_return,
            )
        )
    else:
        checks.append(
            Check(
                "return",
                False,
                f"the return spring ({c3_text}) does not bring the striker back the jaw "
                f"height {in_mm(h3)}: raise c3 or λ3" + paper_return,
            )
        )
    ff = relock_friction(x)
    ff_text = q(ff, "N")
    weight = x["stepped_shaft_mass"] * x["gravity"]
    margin = float(relock_margin(c2, lam2, x["stepped_shaft_mass"], x["gravity"], ff))
    paper_relock = (
        f"the condition c2·λ2 + m2·g = {q(c2 * lam2 + weight, 'N')} > c3·λ3·f = {ff_text} "
        + ("holds" if margin > 0.0 else f"fails by {q(-margin, 'N')}")
        + " [002, eq. 4]"
    )
    if not o.returns or not math.isfinite(o.home_time):
        checks.append(
            Check("relock", False, "the striker does not come home, so the shaft cannot re-lock")
        )
    elif ok["relock"]:
        extra = (
            ""
            if margin > 0.0
            else "; it gets there on its momentum only, so wear or friction scatter may stop it"
        )
        checks.append(
            Check(
                "relock",
                True,
                f"the auxiliary spring pushes the shaft back h1 in {in_ms(o.relock_time)} against "
                f"the friction {ff_text}; " + paper_relock + extra,
            )
        )
    else:
        checks.append(
            Check(
                "relock",
                False,
                f"the auxiliary spring does not push the shaft back h1 against the friction "
                f"{ff_text}: the shaft will not re-lock; {paper_relock}: raise c2·λ2",
            )
        )
    window = engagement_window(x["engagement_angle"], o.release_speed)
    if ok["full engagement"]:
        checks.append(
            Check(
                "full engagement",
                True,
                f"the striker travels the engagement height {h2_text} in "
                f"{in_ms(o.engagement_time)}, inside the {in_ms(window)} the flywheel takes to "
                "turn through the anvil's opening [002, after eq. 5]",
            )
        )
    elif o.blow:
        checks.append(
            Check(
                "full engagement",
                False,
                f"edge blow: the striker needs {in_ms(o.engagement_time)} to travel {h2_text} "
                f"but the anvil's opening passes in {in_ms(window)} at {in_rpm(o.release_speed)} "
                "[002, after eq. 5]; make the power spring stiffer or the moving parts lighter, "
                "widen the opening, or lower the release speed",
            )
        )
    else:
        checks.append(
            Check(
                "full engagement",
                False,
                f"edge blow: the striker never reaches the engagement height {h2_text} (it "
                f"travels at most {in_mm(reach)}) [002, eq. 5]; see the eq. 6 check",
            )
        )
    return checks


def _named_series(o: CycleOutcome) -> dict[str, list[float]]:
    """The recorded series under their output names (none when nothing was recorded)."""
    if not o.series.get("time"):
        return {}
    out = {k: v for k, v in o.series.items() if k != "roller_radius_series"}
    out["roller_position"] = o.series["roller_radius_series"]
    return out


def _error(x: Mapping[str, Any], ctx: RunContext, o: CycleOutcome) -> float | None:
    """The run's error estimate: the simulation's (with the half-coupling's speed at release
    its own bound), or the closed form's over the outputs asked for."""
    if ctx.rung != "simulation":
        return _output_error(x, ctx)
    if not ctx.wants("half_coupling_release_speed"):
        return _SIMULATION_ERROR
    # the speed at release is a small difference of an oscillation: its own bound
    speed_error = simulation_release_velocity_error(_inputs(x, ctx.scratch), o)
    return max(_SIMULATION_ERROR, speed_error) if math.isfinite(speed_error) else None


def _values(x: Mapping[str, Any], o: CycleOutcome, rung: str) -> dict[str, Any]:
    """One design's outputs as a run gives them (:func:`_raw_values` converted): None where
    never reached (inf or NaN), the half-coupling's speed at release after the release
    radius."""
    raw = _raw_values(x, o, rung)
    speed = raw.pop("half_coupling_release_speed")
    values: dict[str, Any] = {}
    for name, v in raw.items():
        if name == "full_engagement":
            values[name] = bool(v)
        else:  # inf or NaN: never reached, null
            values[name] = float(v) if math.isfinite(v) else None
        if name == "release_radius":
            values["half_coupling_release_speed"] = speed
    return values


def _raw_values(
    x: Mapping[str, Any], o: CycleOutcome, rung: str, of_inputs: tuple[Any, ...] | None = None
) -> dict[str, Any]:
    """:func:`_values` before its conversion (inf or NaN where never reached), for a caller
    that reads no sentences: :func:`engine.core.runner.run_point` makes each value what a
    run gives (a float, None where not finite) as it takes it, which converted them a
    second time (21 ``math.isfinite`` a point of the striker's study, twice). The
    half-coupling's speed at release is the simulation's (None on the closed form), last.
    ``of_inputs``: :func:`_of_inputs`' of ``x`` where its chunk made them."""
    values = _outputs(x, o, None, of_inputs)
    values["half_coupling_release_speed"] = (
        float(o.release_velocity) if rung == "simulation" else None
    )
    return values


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    o = _outcome(x, ctx)
    if not ctx.sentences:
        # the values and the verdicts alone (a study's looped point, which keeps no error
        # estimate: the simulation's bound re-derived stage 1's quasi-static terms, 4 µs a
        # design of a 3000-design study's 77 µs beyond its kernels)
        verdict = _verdicts(x, o)
        return Result(
            values=_raw_values(x, o, ctx.rung, None if ctx.prepared is None else ctx.prepared[1]),
            rung=ctx.rung,
            error_estimate=None,
            verdicts=list(zip(verdict.keys(), map(bool, verdict.values()), strict=True)),
        )
    error = _error(x, ctx, o)
    notes = list(o.notes)
    warnings = list(o.warnings)
    if ctx.rung == "simulation":
        notes.append(
            f"simulation: the whole cycle, one compiled RK4 with {200} steps per shortest "
            f"period and every switch located on the step's cubic ({o.steps} steps); the "
            "state (positions, velocities) is carried across release, blow and return"
        )
    else:
        notes.append(
            "closed form: quasi-static spin-up, piecewise-linear stages 2 and 4 started from "
            "the quasi-static release velocity, stage 3 with the half-coupling held"
            + (
                f"; estimated error {error:.2g} (measured against the simulation)"
                if error is not None
                else "; its error could not be estimated for these inputs"
            )
        )
    if ctx.rung != "simulation" and o.flies:
        warnings.append(
            "stage 3: at the blow a face would have to pull the rollers, so they fly free; the "
            "closed form holds them on both faces and does not apply to this return: "
            "return_time, striker_home_time and cycle_time have no error estimate here, ask "
            "the simulation (it follows one-sided contacts)"
        )
    if ctx.rung != "simulation" and ctx.wants("half_coupling_release_speed"):
        notes.append(
            "half_coupling_release_speed is null: the closed form's quasi-static value "
            f"{q(o.release_velocity, 'm/s')} leaves out the half-coupling's oscillation, which can "
            "double it; ask the simulation"
        )
    notes.append(_geometry_note(_inputs(x, ctx.scratch), o.release_speed))
    if o.snap:
        notes.append(
            "the stage-1 stiffness c1 + c2 − A·κ·ω² is already negative when the rollers lift "
            "off: the half-coupling snaps to h1 at once, so the release speed is the lift-off "
            "speed, above the balance the paper's formula assumes"
        )
    c1, c3 = x["power_spring_rate"], x["return_spring_rate"]
    lam1, h1, g = x["power_spring_preload"], x["release_travel"], x["gravity"]
    values = _values(x, o, ctx.rung)
    lower, upper = spring_height_bounds(moving_mass(x), g, c1, c3)
    if not o.blow:
        notes.append(
            "the striker never reaches the engagement height: engagement_time, "
            "engagement_margin, blow_time and every later time are null (see the eq. 6 and "
            "full engagement checks)"
        )
    if upper == 0.0:
        notes.append(
            "spring_height_limit is 0: with g ≤ 0 and c3 ≥ c1, [002, eq. 6]'s balanced design "
            "reaches no engagement height"
        )
    elif not math.isfinite(upper):
        notes.append(
            "spring_height_limit is null: [002, eq. 6] sets no upper limit for c3 ≤ c1"
            + (f" (it asks h ≥ {in_mm(lower)} when gravity points up)" if lower > 0.0 else "")
        )
    if ctx.wants("min_return_spring_rate") and g > 0.0:
        notes.append(
            "min_return_spring_rate is [002, eq. 3] reduced as the paper does (half-coupling at "
            "rest, rollers unloaded) for a striker starting its return at rest, "
            "m3·g/(λ3 + h2 − h3/2); the return check and return_time use the whole stage 3 "
            "with the rollers"
        )
    if values["return_time"] is None and o.blow:
        notes.append("return_time is null: the striker does not come back the jaw height")
    if values["relock_time"] is None and o.returns:
        notes.append("relock_time is null: the stepped shaft does not get back to re-lock")
    if g != 0.0 and x["roller_geometry"] == "paper":
        m12 = x["half_coupling_mass"] + x["stepped_shaft_mass"]
        force = c1 * (lam1 + h1) + x["auxiliary_spring_rate"] * (x["auxiliary_spring_preload"] + h1)
        notes.append(
            "the paper's stage 1 leaves out the weight of half-coupling and shaft ([002, eq. 1]; "
            "eqs. 2 and 4 show it acting against the stage-1 travel); counting it would raise "
            f"the release speed by about {50.0 * m12 * g / force:.2g} %"
        )
    checks = design_checks(x, o)
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=error,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=_named_series(o),
    )


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
    Param(
        "flywheel_inertia",
        "kg*m^2",
        "I_M: moment of inertia of the flywheel with half-coupling, shaft and striker [002, eq. 1]",
        default=0.02,
        # 1e-6 kg*m^2 (a 20 g disc of 2 cm radius); 1e-300 crashed the model (hostile inputs)
        minimum=1e-6,
        maximum=100.0,
        display_unit="kg*m^2",
        symbol="I_M",
        group="drive",
    ),
    Param(
        "motor_torque",
        "N*m",
        "M: motor torque on the flywheel (the stall torque when a no-load speed is given) "
        "[002, eq. 1]",
        default=5.0,
        minimum=1e-3,  # 1 mN*m; 5e-324 made the simulation's step count NaN (hostile inputs)
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
    Param(
        "roller_mass",
        "kg",
        "m_p: mass of one centrifugal roller [002, eq. 1]",
        default=0.05,
        minimum=1e-4,  # 0.1 g; 1e-320 divided by zero (hostile inputs)
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
    Param(
        "roller_radius",
        "m",
        "x_0: radius of the rollers' centres at rest [002, eq. 1]",
        default=0.04,
        minimum=1e-4,  # 0.1 mm; 5e-324 divided by zero (hostile inputs)
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
        # 1°: a flatter cone has no axial push to speak of (1e-300 divided by zero)
        minimum=math.radians(1.0),
        maximum=math.pi / 2,
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
        minimum=math.radians(0.1),  # 0.1°; 5e-324 divided by zero (hostile inputs)
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
    Param(
        "roller_geometry",
        "1",
        "how the rollers sit between the cones (engine/procedures/striker_cycle.py draws them): "
        "'symmetric_v' both faces conical, x = x0 + z1/(2 tan α), the paper's 45° release "
        "speed; 'single_cone' only the half-coupling's face conical, the printed constraint "
        "z1 = x1 tan α with consistent forces; 'paper' the printed [002, eq. 1] as it stands "
        "(its forces do not balance; for reproducing the paper)",
        default="symmetric_v",
        kind="choice",
        choices=GEOMETRIES,
        group="rollers",
    ),
)

_OUTPUTS: tuple[Output, ...] = (
    Output(
        "release_speed",
        "rad/s",
        "ω_M: flywheel speed when the half-coupling reaches h_1 and frees the striker "
        "[002, after eq. 4] for the chosen roller geometry (simulation: the first crossing of h_1)",
        display_unit="rpm",
        symbol="ω_r",
        step="[002, after eq. 4]",
    ),
    Output(
        "spin_up_time",
        "s",
        "time from motor start to release [002, eq. 1]",
        display_unit="ms",
        symbol="t_1",
        step="[002, eq. 1]",
    ),
    Output(
        "release_radius",
        "m",
        "r: roller centre radius at release, x_0 + κ·h_1 for the chosen geometry",
        display_unit="mm",
        symbol="r",
        step="[002, after eq. 4]",
    ),
    Output(
        "half_coupling_release_speed",
        "m/s",
        "axial speed of the half-coupling (away from the anvil) at release, carried into stage 2",
        symbol="ż_1",
        step="[002, eq. 1]",
    ),
    Output(
        "engagement_acceleration",
        "m/s^2",
        "B: the striker's acceleration at the start of stage 2 [002, eq. 5] (was oscillation_B)",
        symbol="B",
        step="[002, eq. 5]",
    ),
    Output(
        "engagement_frequency",
        "rad/s",
        "k: angular frequency of the striker's stage-2 motion [002, eq. 5] (was oscillation_k)",
        symbol="k",
        step="[002, eq. 5]",
    ),
    Output(
        "max_striker_travel",
        "m",
        "the farthest the springs carry the striker in stage 2 (2B/k² from rest [002, eq. 5], "
        "more with the release velocity)",
        display_unit="mm",
        symbol="z_2,max",
        step="[002, eq. 5]",
    ),
    Output(
        "engagement_time",
        "s",
        "time from release for the striker to travel h_2 [002, eq. 5]; null if never",
        display_unit="ms",
        symbol="t_e",
        step="[002, eq. 5]",
    ),
    Output(
        "engagement_window",
        "s",
        "φ_eng/ω_M: time the anvil's opening takes to pass [002, after eq. 5]",
        display_unit="ms",
        symbol="t_eng",
        step="[002, after eq. 5]",
    ),
    Output(
        "engagement_start",
        "s",
        "time from motor start at which the striker is freed and the engagement window "
        "opens (= spin_up_time)",
        display_unit="ms",
        symbol="t_start",
        step="[002, eq. 1]",
    ),
    Output(
        "engagement_end",
        "s",
        "time from motor start at which the anvil's opening has passed: "
        "spin_up_time + engagement_window",
        display_unit="ms",
        symbol="t_end",
        step="[002, after eq. 5]",
    ),
    Output(
        "full_engagement",
        "1",
        "true when the striker reaches h_2 inside the window (no edge blow)",
        kind="bool",
        symbol="",
        step="[002, after eq. 5]",
    ),
    Output(
        "engagement_margin",
        "1",
        "(window − engagement time)/window: the spare fraction of the window; negative means "
        "an edge blow",
        symbol="(t_eng − t_2)/t_eng",
        step="[002, after eq. 5]",
    ),
    Output(
        "blow_time",
        "s",
        "time from motor start of the blow (striker at h_2): the end of stage 2",
        display_unit="ms",
        symbol="t_blow",
        step="[002, eq. 2]",
    ),
    Output(
        "spring_height_limit",
        "m",
        "the upper engagement height [002, eq. 6] allows for balanced preloads, "
        "2M_2g/(c_3 − c_1), 0 when nothing is reachable (g ≤ 0); null when there is no upper "
        "limit (c_3 ≤ c_1)",
        display_unit="mm",
        symbol="h_max",
        step="[002, eq. 6]",
    ),
    Output(
        "min_return_spring_rate",
        "N/m",
        "smallest c_3 that brings the striker back the jaw height from rest in the paper's "
        "reduction of [002, eq. 3] (half-coupling at rest, rollers unloaded)",
        display_unit="N/mm",
        symbol="c_3,min",
        step="[002, eq. 3]",
    ),
    Output(
        "relock_margin",
        "N",
        "c_2λ_2 + m_2g − c_3λ_3f: the static re-lock condition, [002, eq. 4] at the end of "
        "the travel (the relock check also follows the shaft's motion)",
        symbol="c_2 λ_2 + m_2 g − c_3 λ_3 f",
        step="[002, eq. 4]",
    ),
    Output(
        "return_time",
        "s",
        "stage 3: time from the blow until the striker is back the jaw height h_3 "
        "[002, eq. 3], rollers and half-coupling moving",
        display_unit="ms",
        symbol="t_3",
        step="[002, eq. 3]",
    ),
    Output(
        "striker_home_time",
        "s",
        "time from motor start at which the striker is home and the balls can re-lock it: the "
        "end of stage 3",
        display_unit="ms",
        symbol="t_home",
        step="[002, eq. 3]",
    ),
    Output(
        "relock_time",
        "s",
        "stage 4: time for the stepped shaft to travel back h_1 against the cone friction "
        "[002, eq. 4]",
        display_unit="ms",
        symbol="t_4",
        step="[002, eq. 4]",
    ),
    Output(
        "cycle_time",
        "s",
        "time from motor start to the re-lock: the end of stage 4 and of the impact",
        display_unit="ms",
        symbol="t_c",
        step="[002, eq. 4]",
    ),
    Output(
        "time",
        "s",
        "time from motor start (simulation)",
        series=True,
        display_unit="ms",
        plot=Plot(
            windows=(
                Window("engagement window", "engagement_start", "engagement_end"),
                Window("stage 2: engagement", "engagement_start", "blow_time"),
                Window("stage 3: return", "blow_time", "striker_home_time"),
                Window("stage 4: re-lock", "striker_home_time", "cycle_time"),
            )
        ),
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
        "half_coupling_lift",
        "m",
        "half-coupling's lift away from the anvil: up to h_1 in stage 1, down with the striker "
        "in stage 2, back to its stop in stage 3 (simulation; was z1)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "striker_travel",
        "m",
        "striker's travel towards the anvil: out to h_2 in stage 2, back home in stage 3 "
        "(simulation; was z2 and z3)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "shaft_lift",
        "m",
        "stepped shaft's lift away from the anvil: h_1 at release, held by the balls, back to "
        "0 in stage 4 (simulation; was z4, the return travel)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "roller_position",
        "m",
        "roller centre radius over the cycle (simulation)",
        series=True,
        x="time",
        display_unit="mm",
    ),
    Output(
        "stage",
        "1",
        "stage of the cycle at each time: 1 spin-up, 2 engagement, 3 return, 4 re-lock "
        "(simulation; the boundaries are the steps)",
        series=True,
        x="time",
    ),
)

REFERENCE_DESIGN: dict[str, Any] = {p.name: p.default for p in _INPUTS if p.default is not None}

HORIZONTAL_DESIGN: dict[str, Any] = {**REFERENCE_DESIGN, "gravity": 0.0}

PAPER_DESIGN: dict[str, Any] = {**REFERENCE_DESIGN, "roller_geometry": "paper"}

RARE_IMPACT = ModelSpec(
    name="impact.rare",
    answer=(
        Answer(
            "engagement_time",
            "t_e",
            check="full engagement",
            relation="≤",
            bound="engagement_window",
            bound_symbol="t_eng",
        ),
        Answer("release_speed", "ω_r"),
        Answer("cycle_time", "t_c"),
    ),
    title="Rare-impact wrench: striker engagement",
    family="impact",
    summary=(
        "Release speed, spin-up time and whether the axially moving striker engages the "
        "anvil fully (no edge blow), returns and re-locks, over one whole impact cycle."
    ),
    source=(
        "[002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a "
        "rare-impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. "
        "Stage 1 is derived from a Lagrangian of a stated roller geometry (the printed eq. 1 "
        "does not balance). The paper gives no numeric example: the defaults are a plausible "
        "reference design."
    ),
    inputs=_INPUTS,
    outputs=_OUTPUTS,
    rungs=(
        Rung(
            "closed_form",
            "quasi-static spin-up of the chosen geometry, piecewise-linear stages 2 and 4 from "
            "the quasi-static release velocity, stage 3 with the half-coupling held",
            lambda x: _closed_form_estimate(x, Scratch()),
            typical_error="1e-3 to 1e-2 (a bound per design and output, derived from the terms "
            "the closed form leaves out; none where the rollers fly at the blow; "
            "bench/accuracy_striker.py)",
            typical_time="~0.1 ms",
            shared_estimate=_closed_form_estimate,
            steps=(
                closed_form_cycle,
                closed_form_errors,
                _outputs,
                design_checks,
                _geometry_note,
            ),
        ),
        Rung(
            "simulation",
            "the whole cycle as one hybrid simulation: stages 1→4, state carried across "
            "release, blow and return, unilateral springs and stops; time series",
            _simulation_estimate,
            typical_error="1e-6 for the times (RK4 at 200 steps a period lags θ⁴/120 = 8e-9); "
            "the half-coupling's speed at release per design (bench/accuracy_striker.py)",
            typical_time="~0.6 ms (plus a one-off numba load in a fresh process)",
            heavy=True,
            fallback="closed_form",
            steps=(
                simulate_cycle,
                simulation_release_velocity_error,
                _outputs,
                design_checks,
                _geometry_note,
            ),
        ),
    ),
    compute=_compute,
    examples=(REFERENCE_DESIGN, HORIZONTAL_DESIGN, PAPER_DESIGN),
    vectorized=_vectorized,
    prepare_points=_prepare_points,
    vector_rungs=("closed_form",),
)
