"""Model spec for the capability of a tightening tool or process (``tool.capability``).

The statistics and indices live in :mod:`engine.physics.capability`; this module reads the
request (torque samples, or their mean and standard deviation; a tolerance as nominal ± or
as two limits), calls those functions and turns the numbers into a verdict with its checks.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

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
from ..physics import capability as cap

SOURCE = (
    "VDI/VDE 2645-2 (machine capability, Cm and Cmk) and VDI/VDE 2645-3 (process "
    "capability, Cp and Cpk), as public secondary sources print them; worked example [Danikor]"
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
        "Number of measured torques behind mean_torque and torque_sd (for the sample-size check)",
        minimum=2,
        maximum=1_000_000,
        symbol="n",
        group="measurements",
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
    Output("mean_torque", "N*m", "Mean x̄ of the measured torques", label="mean torque x̄"),
    Output("torque_sd", "N*m", "Standard deviation s (n − 1)", label="standard deviation s"),
    Output("sample_count", "1", "Number of values n (null: not given)", kind="int"),
    Output("minimum_sample_count", "1", "Fewest values the chosen test takes", kind="int"),
    Output("min_torque", "N*m", "Smallest measured torque (null without samples)"),
    Output("max_torque", "N*m", "Largest measured torque (null without samples)"),
    Output("lower_limit", "N*m", "Lower tolerance limit L"),
    Output("upper_limit", "N*m", "Upper tolerance limit U"),
    Output(
        "capability_index",
        "1",
        "Cm (machine) or Cp (process): (U − L)/(6s)",
        label="Cm / Cp",
    ),
    Output(
        "critical_capability_index",
        "1",
        "Cmk (machine) or Cpk (process): min(U − x̄, x̄ − L)/(3s)",
        label="Cmk / Cpk",
    ),
    Output("index_names", "1", "Which pair the two indices are: 'Cm/Cmk' or 'Cp/Cpk'", kind="str"),
    Output("required_index", "1", "The index both must reach"),
    Output(
        "mean_offset",
        "1",
        "Mean's distance from the middle of the tolerance, as a share of half the tolerance",
    ),
    Output(
        "outside_ppm",
        "1",
        "Share outside the tolerance if the torques were normal with x̄ and s, in ppm",
        label="outside, normal estimate [ppm]",
    ),
    Output("capable", "1", "Both indices reach the required index and n is large enough", "bool"),
)


def _limits(x: Mapping[str, Any]) -> tuple[float, float, str]:
    """(L, U, how they were given) from the limits or the nominal ± tolerance."""
    lower, upper = x.get("lower_limit"), x.get("upper_limit")
    if (lower is None) != (upper is None):
        missing = "upper_limit" if upper is None else "lower_limit"
        raise InputOutOfRange(
            f"{missing} is required with {'lower' if upper is None else 'upper'}_limit",
            field=missing,
        )
    if lower is not None and upper is not None:
        if not lower < upper:
            raise InputOutOfRange(
                f"lower_limit = {lower:g} N*m is not allowed: must be below upper_limit = "
                f"{upper:g} N*m",
                field="lower_limit",
            )
        return float(lower), float(upper), "limits as given"
    nominal = x.get("nominal_torque")
    if nominal is None:
        raise InputOutOfRange(
            "give the tolerance: nominal_torque (with relative_tolerance), or lower_limit and "
            "upper_limit",
            field="nominal_torque",
        )
    t = float(x["relative_tolerance"])
    return (
        nominal * (1.0 - t),
        nominal * (1.0 + t),
        f"{quantity(nominal, 'N*m', '.4g')} ± {quantity(t, '%')}",
    )


def _statistics(x: Mapping[str, Any]) -> tuple[float, float, int | None, tuple[float, ...]]:
    """(x̄, s, n, samples) from the samples, or from the mean and σ given."""
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
        return mean, sd, len(values), values
    if len(summary) < 2:
        missing = "mean_torque" if x.get("mean_torque") is None else "torque_sd"
        raise InputOutOfRange(
            f"give torque_samples, or mean_torque and torque_sd: {missing} is missing",
            field="torque_samples" if not summary else missing,
        )
    n = x.get("sample_count")
    return float(x["mean_torque"]), float(x["torque_sd"]), None if n is None else int(n), ()


def _capability(x: Mapping[str, Any], ctx: RunContext) -> Result:
    mean, sd, n, values = _statistics(x)
    lower, upper, how = _limits(x)
    study = str(x["study"])
    name, name_k, n_min, test, how_taken = STUDIES[study]
    required = float(x["required_index"])
    c = float(cap.capability_index(upper, lower, sd))
    ck = float(cap.critical_capability_index(upper, lower, mean, sd))
    outside = float(cap.normal_fraction_outside(upper, lower, mean, sd))
    half = 0.5 * (upper - lower)
    offset = (mean - 0.5 * (upper + lower)) / half
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
        f"tolerance {quantity(lower, 'N*m', '.4g')} … {quantity(upper, 'N*m', '.4g')} ({how})",
        f"{name} and {name_k} use the sample standard deviation (n − 1); the ppm figure assumes "
        "normally distributed torques",
    ]
    if values:
        outside_count = sum(1 for v in values if not lower <= v <= upper)
        if outside_count:
            checks.append(
                Check(
                    "samples_within_limits",
                    False,
                    f"{outside_count} of {len(values)} measured torques lie outside the tolerance",
                )
            )
        else:
            checks.append(
                Check(
                    "samples_within_limits",
                    True,
                    f"all {len(values)} measured torques lie within the tolerance",
                )
            )
    capable = all(ch.ok for ch in checks)
    return Result(
        values={
            "mean_torque": mean,
            "torque_sd": sd,
            "sample_count": n,
            "minimum_sample_count": n_min,
            "min_torque": min(values) if values else None,
            "max_torque": max(values) if values else None,
            "lower_limit": lower,
            "upper_limit": upper,
            "capability_index": c,
            "critical_capability_index": ck,
            "index_names": f"{name}/{name_k}",
            "required_index": required,
            "mean_offset": offset,
            "outside_ppm": outside * 1e6,
            "capable": capable,
        },
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        warnings=warnings,
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
            "C_m",
            check="capability_index",
            relation="≥",
            bound="required_index",
            bound_symbol="C_m,req",
        ),
        Answer(
            "critical_capability_index",
            "C_mk",
            check="critical_capability_index",
            relation="≥",
            bound="required_index",
            bound_symbol="C_mk,req",
        ),
        Answer("mean_torque", "M̄"),
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
    ),
)
