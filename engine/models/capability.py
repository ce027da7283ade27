"""Model spec for the capability of a tightening tool or process (``tool.capability``).

The statistics and indices live in :mod:`engine.physics.capability`; this module reads the
request (torque samples, or their mean and standard deviation; a tolerance as nominal ± or
as two limits), calls those functions and turns the numbers into a verdict with its checks.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.errors import InputOutOfRange
from ..core.params import count, positive, quantity, samples
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
from ..physics import capability as cap

SOURCE = (
    "VDI/VDE 2645-2 (machine capability, Cm and Cmk) and VDI/VDE 2645-3 (process "
    "capability, Cp and Cpk), as public secondary sources print them; worked example [Danikor]; "
    "ISO 5393 hard- and soft-joint runs pooled into one sample [Danikor-ISO5393]"
)

#: Largest torque a sample or a limit may hold, [N*m] (a large bolting tool: 100 kN·m).
MAX_TORQUE = 1e5

#: Per study: (names of the two indices, fewest values the test takes, the test, how it
#: takes them).
STUDIES: dict[str, tuple[str, str, int, str, str]] = {
    "machine": ("Cm", "Cmk", 50, "a machine capability test (VDI/VDE 2645-2)", "in one run"),
    "process": (
        "Cp",
        "Cpk",
        125,
        "a process capability test (VDI/VDE 2645-3)",
        "as 25 subgroups of 5",
    ),
}

INPUTS: tuple[Param, ...] = (
    samples(
        "torque_samples",
        "N*m",
        "Measured torques of the test, one per tightening (paste them, or give mean_torque "
        "and torque_sd instead)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="T_i",
        group="measurements",
    ),
    Param(
        "mean_torque",
        "N*m",
        "Mean of the measured torques, when the samples themselves are not given",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="x̄",
        group="measurements",
    ),
    positive(
        "torque_sd",
        "N*m",
        "Standard deviation (n − 1) of the measured torques, with mean_torque",
        maximum=MAX_TORQUE,
        symbol="s",
        group="measurements",
    ),
    count(
        "sample_count",
        "Number of measured torques behind mean_torque and torque_sd (for the sample-size "
        "check); with the ISO 5393 run means, the tightenings in each run",
        minimum=2,
        maximum=1_000_000,
        symbol="n",
        group="measurements",
    ),
    samples(
        "hard_joint_samples",
        "N*m",
        "ISO 5393 run on the hard test joint: its measured torques (with soft_joint_samples; "
        "the two runs are pooled into one sample)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="T_hard,i",
        group="ISO 5393 runs",
    ),
    samples(
        "soft_joint_samples",
        "N*m",
        "ISO 5393 run on the soft test joint: its measured torques (with hard_joint_samples)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="T_soft,i",
        group="ISO 5393 runs",
    ),
    Param(
        "hard_mean_torque",
        "N*m",
        "Mean torque of the hard-joint run, when its samples are not given (with "
        "hard_torque_sd, the soft run's two and sample_count, the tightenings in each run)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="x̄_hard",
        group="ISO 5393 runs",
    ),
    positive(
        "hard_torque_sd",
        "N*m",
        "Standard deviation (n − 1) of the hard-joint run",
        maximum=MAX_TORQUE,
        symbol="s_hard",
        group="ISO 5393 runs",
    ),
    Param(
        "soft_mean_torque",
        "N*m",
        "Mean torque of the soft-joint run",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="x̄_soft",
        group="ISO 5393 runs",
    ),
    positive(
        "soft_torque_sd",
        "N*m",
        "Standard deviation (n − 1) of the soft-joint run",
        maximum=MAX_TORQUE,
        symbol="s_soft",
        group="ISO 5393 runs",
    ),
    positive(
        "nominal_torque",
        "N*m",
        "Nominal (target) torque; with relative_tolerance it gives the limits "
        "(lower_limit and upper_limit, when given, win)",
        maximum=MAX_TORQUE,
        symbol="T_nom",
        group="tolerance",
    ),
    Param(
        "relative_tolerance",
        "1",
        "Tolerance ± as a share of the nominal torque (0.1 is ±10 %)",
        default=0.1,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        exclusive_maximum=True,
        display_unit="%",
        symbol="±t",
        group="tolerance",
    ),
    Param(
        "lower_limit",
        "N*m",
        "Lower tolerance limit L (with upper_limit, instead of nominal ± tolerance)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        symbol="L",
        group="tolerance",
    ),
    positive(
        "upper_limit",
        "N*m",
        "Upper tolerance limit U (with lower_limit)",
        maximum=MAX_TORQUE,
        symbol="U",
        group="tolerance",
    ),
    Param(
        "study",
        "1",
        "What the values are: one run of one tool (machine: Cm, Cmk, at least 50 values) or "
        "values from production (process: Cp, Cpk, 25 subgroups of 5)",
        default="machine",
        kind="choice",
        choices=tuple(STUDIES),
        choice_labels=("machine capability (Cm, Cmk)", "process capability (Cp, Cpk)"),
        group="test",
    ),
    Param(
        "required_index",
        "1",
        "Index both Cm and Cmk (or Cp and Cpk) must reach: 1.67 is the usual limit, as "
        "secondary sources state it; set your own specification's",
        default=1.67,
        minimum=0.5,
        maximum=5.0,
        symbol="C_req",
        group="test",
    ),
)

OUTPUTS: tuple[Output, ...] = (
    Output(
        "mean_torque",
        "N*m",
        "Mean x̄ of the measured torques",
        label="mean torque x̄",
        symbol="x̄",
        step="VDI/VDE 2645",
    ),
    Output(
        "torque_sd",
        "N*m",
        "Standard deviation s (n − 1)",
        label="standard deviation s",
        symbol="s",
        step="VDI/VDE 2645",
    ),
    Output(
        "sample_count",
        "1",
        "Number of values n (null: not given)",
        kind="int",
        symbol="n",
        step="VDI/VDE 2645",
    ),
    Output(
        "minimum_sample_count",
        "1",
        "Fewest values the chosen test takes",
        kind="int",
        symbol="n_min",
        step="VDI/VDE 2645",
    ),
    Output(
        "min_torque",
        "N*m",
        "Smallest measured torque (null without samples)",
        symbol="x_min",
        step="VDI/VDE 2645",
    ),
    Output(
        "max_torque",
        "N*m",
        "Largest measured torque (null without samples)",
        symbol="x_max",
        step="VDI/VDE 2645",
    ),
    Output("lower_limit", "N*m", "Lower tolerance limit L", symbol="L", step="VDI/VDE 2645"),
    Output("upper_limit", "N*m", "Upper tolerance limit U", symbol="U", step="VDI/VDE 2645"),
    Output(
        "capability_index",
        "1",
        "Cm (machine) or Cp (process): (U − L)/(6s)",
        label="Cm / Cp",
        symbol="C_m/C_p",
        step="VDI/VDE 2645",
    ),
    Output(
        "critical_capability_index",
        "1",
        "Cmk (machine) or Cpk (process): min(U − x̄, x̄ − L)/(3s)",
        label="Cmk / Cpk",
        symbol="C_mk/C_pk",
        step="VDI/VDE 2645",
    ),
    Output(
        "index_names",
        "1",
        "Which pair the two indices are: 'Cm/Cmk' or 'Cp/Cpk'",
        kind="str",
        symbol="",
        step="VDI/VDE 2645",
    ),
    Output("required_index", "1", "The index both must reach", symbol="C_req", step="VDI/VDE 2645"),
    Output(
        "mean_offset",
        "1",
        "Mean's distance from the middle of the tolerance, as a share of half the tolerance",
        symbol="k",
        step="VDI/VDE 2645",
    ),
    Output(
        "outside_ppm",
        "1",
        "Share outside the tolerance if the torques were normal with x̄ and s, in ppm",
        label="outside, normal estimate [ppm]",
        symbol="p_out",
        step="VDI/VDE 2645",
    ),
    Output(
        "torque_scatter",
        "1",
        "The tool's scatter as makers rate it: ±3s over the mean (null at a mean of 0)",
        label="scatter ±3s/x̄",
        display_unit="%",
        symbol="±3s/x̄",
        step="[Danikor]",
    ),
    Output(
        "hard_mean_torque",
        "N*m",
        "Mean of the hard-joint run (null without ISO 5393 runs)",
        symbol="x̄_hard",
        step="ISO 5393",
    ),
    Output(
        "soft_mean_torque",
        "N*m",
        "Mean of the soft-joint run (null without ISO 5393 runs)",
        symbol="x̄_soft",
        step="ISO 5393",
    ),
    Output(
        "hard_torque_sd",
        "N*m",
        "s of the hard-joint run (null without ISO 5393 runs)",
        symbol="s_hard",
        step="ISO 5393",
    ),
    Output(
        "soft_torque_sd",
        "N*m",
        "s of the soft-joint run (null without ISO 5393 runs)",
        symbol="s_soft",
        step="ISO 5393",
    ),
    Output(
        "mean_shift",
        "N*m",
        "Mean shift x̄_soft − x̄_hard between the runs (null without ISO 5393 runs)",
        symbol="Δx̄",
        step="ISO 5393",
    ),
    Output(
        "capable",
        "1",
        "Both indices reach the required index and n is large enough",
        "bool",
        symbol="",
        step="VDI/VDE 2645",
    ),
)


def _points(x: Mapping[str, Any]) -> int:
    """Points of an array request (0 when every input is a scalar)."""
    for v in x.values():
        if isinstance(v, np.ndarray) and v.ndim == 1:
            return int(v.shape[0])
    return 0


def _limits(x: Mapping[str, Any]) -> tuple[Any, Any, str]:
    """(L, U, how they were given) from the limits or the nominal ± tolerance (floats or arrays)."""
    lower, upper = x.get("lower_limit"), x.get("upper_limit")
    if (lower is None) != (upper is None):
        missing = "upper_limit" if upper is None else "lower_limit"
        raise InputOutOfRange(
            f"{missing} is required with {'lower' if upper is None else 'upper'}_limit",
            field=missing,
        )
    if lower is not None and upper is not None:
        if not np.all(np.less(lower, upper)):
            if isinstance(lower, np.ndarray) or isinstance(upper, np.ndarray):
                # some points refused: the loop names each (the array path answers none)
                raise InputOutOfRange("lower_limit must be below upper_limit", field="lower_limit")
            raise InputOutOfRange(
                f"lower_limit = {lower:g} N*m is not allowed: must be below upper_limit = "
                f"{upper:g} N*m",
                field="lower_limit",
            )
        return lower, upper, "limits as given"
    nominal = x.get("nominal_torque")
    if nominal is None:
        raise InputOutOfRange(
            "give the tolerance: nominal_torque (with relative_tolerance), or lower_limit and "
            "upper_limit",
            field="nominal_torque",
        )
    t = x["relative_tolerance"]
    how = (
        "nominal ± tolerance"
        if isinstance(nominal, np.ndarray) or isinstance(t, np.ndarray)
        else f"{quantity(nominal, 'N*m', '.4g')} ± {quantity(t, '%')}"
    )
    return nominal * (1.0 - t), nominal * (1.0 + t), how


@dataclass(frozen=True)
class _Runs:
    """The ISO 5393 hard-joint and soft-joint runs (floats, or arrays in a sweep)."""

    hard_mean: Any
    hard_sd: Any
    soft_mean: Any
    soft_sd: Any
    #: Values in each run (None: not given with the means).
    hard_count: Any
    soft_count: Any


@dataclass(frozen=True)
class _Statistics:
    """x̄, s and n of the test (the runs pooled where ISO 5393 runs are given)."""

    mean: Any
    sd: Any
    count: Any
    values: tuple[float, ...]
    runs: _Runs | None


def _run_samples(name: str, given: Any) -> tuple[float, float, int]:
    values = tuple(given)
    mean = cap.sample_mean(values)
    sd = cap.sample_standard_deviation(values)
    if not sd > 0.0:
        raise InputOutOfRange(
            f"{name}: all {len(values)} values are equal, so s = 0: give the values as measured, "
            "with their full resolution",
            field=name,
        )
    return mean, sd, len(values)


def _runs(x: Mapping[str, Any]) -> _Statistics | None:
    """The two ISO 5393 runs pooled, or None where the request gives no run."""
    sample_names = ("hard_joint_samples", "soft_joint_samples")
    summary_names = ("hard_mean_torque", "hard_torque_sd", "soft_mean_torque", "soft_torque_sd")
    given_samples = [n for n in sample_names if x.get(n) is not None]
    given_summary = [n for n in summary_names if x.get(n) is not None]
    if not given_samples and not given_summary:
        return None
    for name in ("torque_samples", "mean_torque", "torque_sd"):
        if x.get(name) is not None:
            raise InputOutOfRange(
                f"give the ISO 5393 runs (hard_… and soft_…) or {name}, not both", field=name
            )
    if given_samples and given_summary:
        raise InputOutOfRange(
            "give both runs as samples (hard_joint_samples, soft_joint_samples) or both as "
            f"mean and standard deviation, not {given_samples[0]} with {given_summary[0]}",
            field=given_summary[0],
        )
    if given_samples:
        for name in sample_names:
            if x.get(name) is None:
                raise InputOutOfRange(f"{name} is required with the other run", field=name)
        if x.get("sample_count") is not None:
            raise InputOutOfRange(
                "sample_count goes with run means, not with samples", field="sample_count"
            )
        hm, hs, hn = _run_samples("hard_joint_samples", x["hard_joint_samples"])
        sm, ss, sn = _run_samples("soft_joint_samples", x["soft_joint_samples"])
        values = (*x["hard_joint_samples"], *x["soft_joint_samples"])
        runs = _Runs(hm, hs, sm, ss, hn, sn)
        count: Any = hn + sn
    else:
        for name in summary_names:
            if x.get(name) is None:
                raise InputOutOfRange(f"{name} is required with the other run's", field=name)
        n = x.get("sample_count")
        if n is None:
            raise InputOutOfRange(
                "sample_count (the tightenings in each run) is required to pool the two runs",
                field="sample_count",
            )
        values = ()
        runs = _Runs(
            x["hard_mean_torque"],
            x["hard_torque_sd"],
            x["soft_mean_torque"],
            x["soft_torque_sd"],
            n,
            n,
        )
        count = 2 * n
    mean = cap.pooled_mean(runs.hard_mean, runs.hard_count, runs.soft_mean, runs.soft_count)
    sd = cap.pooled_standard_deviation(
        runs.hard_mean, runs.hard_sd, runs.hard_count, runs.soft_mean, runs.soft_sd, runs.soft_count
    )
    return _Statistics(mean, sd, count, values, runs)


def _statistics(x: Mapping[str, Any]) -> _Statistics:
    """(x̄, s, n, samples) from the samples, the mean and σ given, or the ISO 5393 runs."""
    pooled = _runs(x)
    if pooled is not None:
        return pooled
    given = x.get("torque_samples")
    summary = [n for n in ("mean_torque", "torque_sd") if x.get(n) is not None]
    if given is not None:
        if summary or x.get("sample_count") is not None:
            raise InputOutOfRange(
                "give torque_samples, or mean_torque and torque_sd (with sample_count), not both",
                field="mean_torque" if summary else "sample_count",
            )
        values = tuple(given)
        mean = cap.sample_mean(values)
        sd = cap.sample_standard_deviation(values)
        if not sd > 0.0:
            raise InputOutOfRange(
                f"torque_samples: all {len(values)} values are equal, so s = 0 and the indices "
                "are unbounded: give the values as measured, with their full resolution",
                field="torque_samples",
            )
        return _Statistics(mean, sd, len(values), values, None)
    if len(summary) < 2:
        missing = "mean_torque" if x.get("mean_torque") is None else "torque_sd"
        raise InputOutOfRange(
            f"give torque_samples, or mean_torque and torque_sd: {missing} is missing",
            field="torque_samples" if not summary else missing,
        )
    return _Statistics(x["mean_torque"], x["torque_sd"], x.get("sample_count"), (), None)


@dataclass(frozen=True)
class _Evaluation:
    """The numbers of one design or of many (floats or arrays), and each check's verdict."""

    values: dict[str, Any]
    verdicts: dict[str, Any]
    stats: _Statistics
    how: str
    outside_count: Any


def _evaluate(x: Mapping[str, Any]) -> _Evaluation:
    """The statistics, indices and verdicts: the same lines for one design and for many."""
    st = _statistics(x)
    lower, upper, how = _limits(x)
    name, name_k, n_min, _, _ = STUDIES[str(x["study"])]
    required = x["required_index"]
    c = cap.capability_index(upper, lower, st.sd)
    ck = cap.critical_capability_index(upper, lower, st.mean, st.sd)
    outside = cap.normal_fraction_outside(upper, lower, st.mean, st.sd)
    offset = (st.mean - 0.5 * (upper + lower)) / (0.5 * (upper - lower))
    verdicts: dict[str, Any] = {
        "capability_index": np.greater_equal(c, required),
        "critical_capability_index": np.greater_equal(ck, required),
        "sample_size": False if st.count is None else np.greater_equal(st.count, n_min),
    }
    outside_count: Any = None
    if st.values:
        v = np.asarray(st.values)
        lo, hi = np.asarray(lower)[..., None], np.asarray(upper)[..., None]
        outside_count = np.sum((v < lo) | (v > hi), axis=-1)
        verdicts["samples_within_limits"] = outside_count == 0
    capable: Any = np.True_
    for verdict in verdicts.values():
        capable = np.logical_and(capable, verdict)
    runs = st.runs
    values: dict[str, Any] = {
        "mean_torque": st.mean,
        "torque_sd": st.sd,
        "sample_count": st.count,
        "minimum_sample_count": n_min,
        "min_torque": min(st.values) if st.values else None,
        "max_torque": max(st.values) if st.values else None,
        "lower_limit": lower,
        "upper_limit": upper,
        "capability_index": c,
        "critical_capability_index": ck,
        "index_names": f"{name}/{name_k}",
        "required_index": required,
        "mean_offset": offset,
        "outside_ppm": outside * 1e6,
        "torque_scatter": _scatter(st.mean, st.sd),
        "hard_mean_torque": None if runs is None else runs.hard_mean,
        "soft_mean_torque": None if runs is None else runs.soft_mean,
        "hard_torque_sd": None if runs is None else runs.hard_sd,
        "soft_torque_sd": None if runs is None else runs.soft_sd,
        "mean_shift": None if runs is None else cap.mean_shift(runs.hard_mean, runs.soft_mean),
        "capable": capable,
    }
    return _Evaluation(values, verdicts, st, how, outside_count)


def _scatter(mean: Any, sd: Any) -> Any:
    """±3s/x̄ where the mean is positive; none (NaN in an array) at a mean of 0."""
    if isinstance(mean, np.ndarray) or isinstance(sd, np.ndarray):
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(np.greater(mean, 0.0), cap.relative_scatter(mean, sd), np.nan)
    return cap.relative_scatter(mean, sd) if mean > 0.0 else None


def _plain(value: Any) -> Any:
    """A numpy scalar as the Python number (or bool) the scalar path returns."""
    if isinstance(value, np.generic | np.ndarray):
        return value.item()
    return value


def _capability(x: Mapping[str, Any], ctx: RunContext) -> Result:
    ev = _evaluate(x)
    values = {k: _plain(v) for k, v in ev.values.items()}
    st = ev.stats
    n = None if st.count is None else int(st.count)
    study = str(x["study"])
    name, name_k, n_min, test, how_taken = STUDIES[study]
    required = float(x["required_index"])
    c, ck = values["capability_index"], values["critical_capability_index"]
    lower, upper = values["lower_limit"], values["upper_limit"]
    checks = [
        Check(
            "capability_index",
            c >= required,
            f"{name} = {c:.3g} {'≥' if c >= required else '<'} {required:g}"
            + ("" if c >= required else ": the tool scatters too much for this tolerance"),
        ),
        Check(
            "critical_capability_index",
            ck >= required,
            f"{name_k} = {ck:.3g} {'≥' if ck >= required else '<'} {required:g}"
            + (
                ""
                if ck >= required
                else (
                    ": the mean lies off the middle of the tolerance; re-centre the setting"
                    if c >= required
                    else ""
                )
            ),
        ),
    ]
    warnings: list[str] = []
    if n is None:
        checks.append(
            Check(
                "sample_size",
                False,
                f"sample_count not given: {test} takes at least {n_min} values {how_taken}",
            )
        )
    else:
        enough = n >= n_min
        checks.append(
            Check(
                "sample_size",
                enough,
                f"n = {n} values; {test} takes at least {n_min} {how_taken}"
                + ("" if enough else f": {n_min - n} more before the verdict counts"),
            )
        )
        if not enough:
            warnings.append(
                f"only {n} values where {test} takes {n_min}: an index from fewer values "
                "scatters widely"
            )
    notes = [
        f"tolerance {q(lower, 'N*m', fmt='.4g')} … {q(upper, 'N*m', fmt='.4g')} ({ev.how})",
        f"{name} and {name_k} use the sample standard deviation (n − 1); the ppm figure assumes "
        "normally distributed torques",
    ]
    if st.runs is not None:
        notes.append(
            f"ISO 5393 runs pooled as one sample of {n} values: hard joint x̄ = "
            f"{values['hard_mean_torque']:.4g} N·m, soft joint x̄ = "
            f"{values['soft_mean_torque']:.4g} N·m, mean shift "
            f"{values['mean_shift']:+.3g} N·m; the pooled s includes the shift. ISO 5393's own "
            "evaluation text was not read [Danikor-ISO5393]: the pooling is exact arithmetic"
        )
    if st.values:
        count = int(ev.outside_count)
        total = len(st.values)
        checks.append(
            Check(
                "samples_within_limits",
                count == 0,
                f"{count} of {total} measured torques lie outside the tolerance"
                if count
                else f"all {total} measured torques lie within the tolerance",
            )
        )
    values["capable"] = all(ch.ok for ch in checks)
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        warnings=warnings,
    )


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """The array path: :func:`_evaluate` on the columns of a sweep or a study's chunk."""
    n = _points(x) or 1
    ev = _evaluate(x)
    values: dict[str, Any] = {}
    for name, v in ev.values.items():
        if v is None:
            values[name] = None
        elif isinstance(v, np.ndarray) and v.shape == (n,):
            values[name] = v
        else:
            values[name] = np.broadcast_to(np.asarray(v), (n,)).copy()
    checks = {k: np.broadcast_to(np.asarray(v, dtype=bool), (n,)) for k, v in ev.verdicts.items()}
    name, name_k = STUDIES[str(x["study"])][:2]
    notes = [
        f"{name} and {name_k} use the sample standard deviation (n − 1); the ppm figure assumes "
        "normally distributed torques"
    ]
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        notes=notes,
        check_arrays=checks,
    )


CLOSED_FORM = Rung(
    "closed_form",
    "The sample statistics and the index formulas, exact arithmetic; the estimate does not "
    "include the sampling uncertainty of the indices (an index from 50 values scatters by "
    "about ±10 % or more)",
    fixed_error(0.0),
    typical_error="exact arithmetic",
    typical_time="< 1 ms",
)

#: A 50-value run of a 50 N·m tool (made-up readings, 49.1…50.9 N·m; for the form and tests).
RUN_OF_50 = tuple(round(50.0 + 0.9 * ((i * 37) % 50 - 24.5) / 24.5, 3) for i in range(50))

CAPABILITY = ModelSpec(
    name="tool.capability",
    requirements_of="VDI/VDE 2645-2",
    answer=(
        Answer(
            "capability_index",
            "C_m/C_p",
            check="capability_index",
            relation="≥",
            bound="required_index",
            bound_symbol="C_req",
        ),
        Answer(
            "critical_capability_index",
            "C_mk/C_pk",
            check="critical_capability_index",
            relation="≥",
            bound="required_index",
            bound_symbol="C_req",
        ),
        Answer("mean_torque", "x̄"),
    ),
    title="Tightening tool capability: Cm, Cmk (Cp, Cpk) from measured torques",
    family="tool",
    summary=(
        "From the torques a tool gave in a test (the values, or their mean and standard "
        "deviation) and a tolerance: the mean, the standard deviation, Cm and Cmk (a "
        "machine test) or Cp and Cpk (a process test), the share outside the tolerance "
        "they imply, and whether the tool passes at the index and sample size required."
    ),
    source=SOURCE,
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_capability,
    vectorized=_vectorized,
    vector_rungs=("closed_form",),
    examples=(
        # [Danikor]'s worked example: 0.8 N·m ± 10 %, 25 readings, x̄ = 0.81, s = 0.011 N·m
        {
            "mean_torque": 0.81,
            "torque_sd": 0.011,
            "sample_count": 25,
            "nominal_torque": 0.8,
            "relative_tolerance": 0.1,
        },
        {"torque_samples": RUN_OF_50, "nominal_torque": 50.0, "relative_tolerance": 0.05},
        {
            "mean_torque": 81.0,
            "torque_sd": 1.5,
            "sample_count": 125,
            "lower_limit": 72.0,
            "upper_limit": 88.0,
            "study": "process",
        },
        # ISO 5393 runs of a 50 N·m nutrunner, 25 tightenings on each joint, ±5 %
        {
            "hard_mean_torque": 50.2,
            "hard_torque_sd": 0.35,
            "soft_mean_torque": 49.6,
            "soft_torque_sd": 0.45,
            "sample_count": 25,
            "nominal_torque": 50.0,
            "relative_tolerance": 0.05,
        },
    ),
)
