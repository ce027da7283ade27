"""A second toy model for the browser test: time series, a shaded window and a histogram.

No physics: a mass on a spring released at t = 0 (travel z = h (1 − cos k t) / 2,
k = √(c/m)), a flywheel spinning up exponentially, and a binomial "preload
scatter" histogram. It returns what the real models return (series with an
``x`` axis, bin edges one longer than the counts, an ``engagement_start`` /
``engagement_end`` pair, passing and failing checks, a warning) so the page's
plots can be tested before those models are merged.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from engine import Check, ModelSpec, Output, Param, Result, RunContext, Rung, fixed_error

N_POINTS = 61
N_BINS = 11


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    h, c, m, w = x["stroke"], x["spring_rate"], x["mass"], x["speed"]
    k = math.sqrt(c / m)
    t_end = math.pi / k  # half a period: the striker reaches h
    times = [t_end * i / (N_POINTS - 1) for i in range(N_POINTS)]
    travel = [h * (1.0 - math.cos(k * t)) / 2.0 for t in times]
    tau = t_end / 3.0
    speed = [w * (1.0 - math.exp(-t / tau)) for t in times]
    f0 = x["preload"]
    edges = [f0 * (0.7 + 0.6 * i / N_BINS) for i in range(N_BINS + 1)]
    counts = [float(math.comb(N_BINS - 1, i)) for i in range(N_BINS)]
    window = x["window"]
    start = t_end - window
    values: dict[str, Any] = {
        "peak_travel": h,
        "travel_time": t_end,
        "engagement_start": start,
        "engagement_end": t_end,
        "stiffness_ratio": c / (m * 1e3),
        "reaches": window > 0.2 * t_end,
    }
    checks = [
        Check("full stroke", True, "the striker travels its whole stroke inside the window"),
        Check(
            "window margin",
            window > 0.5 * t_end,
            "widen the window or stiffen the spring: the margin is under half the travel time",
        ),
    ]
    return Result(
        values={k_: v for k_, v in values.items() if ctx.wants(k_)},
        rung=ctx.rung,
        error_estimate=1e-12 if ctx.rung == "exact" else 0.02,
        checks=checks,
        notes=["toy model for the browser test"],
        warnings=["this is not a real tool"] if h > 0.02 else [],
        series={
            "time": times,
            "travel": travel,
            "flywheel_speed": speed,
            "preload_bins": edges,
            "preload_count": counts,
        },
    )


STRIKER = ModelSpec(
    name="toy.striker",
    path="/toy/striker",
    title="Toy striker with plots",
    family="toy-plots",
    summary="A spring-driven striker, a spinning flywheel and a scatter histogram (test only).",
    source="none (test fixture)",
    inputs=(
        Param(
            "stroke",
            "m",
            "striker stroke",
            default=0.012,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=0.1,
            recommended=(0.001, 0.02),
            display_unit="mm",
            group="Striker",
            symbol="h",
        ),
        Param(
            "spring_rate",
            "N/m",
            "spring rate",
            default=2.0e4,
            minimum=1.0,
            maximum=1e8,
            display_unit="N/mm",
            group="Striker",
            symbol="c",
        ),
        Param(
            "mass",
            "kg",
            "striker mass",
            default=0.5,
            minimum=1e-3,
            maximum=100.0,
            display_unit="kg",
            group="Striker",
        ),
        Param(
            "speed",
            "rad/s",
            "flywheel speed",
            default=150.0,
            minimum=0.0,
            maximum=2e3,
            display_unit="rpm",
            group="Flywheel",
        ),
        Param(
            "window",
            "s",
            "engagement window",
            default=0.004,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=1.0,
            display_unit="ms",
            group="Flywheel",
        ),
        Param(
            "preload",
            "N",
            "nominal preload",
            default=2.0e4,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=1e7,
            display_unit="kN",
            group="Bolt",
        ),
    ),
    outputs=(
        Output("peak_travel", "m", "z_max = h", display_unit="mm"),
        Output("travel_time", "s", "t = π/k", display_unit="ms"),
        Output("engagement_start", "s", "window opens", display_unit="ms"),
        Output("engagement_end", "s", "window closes", display_unit="ms"),
        Output("stiffness_ratio", "1", "c / (1000 m)"),
        Output("reaches", "1", "the striker reaches h in the window", kind="bool"),
        Output("time", "s", "time", series=True, display_unit="ms"),
        Output("travel", "m", "striker travel", series=True, x="time", display_unit="mm"),
        Output(
            "flywheel_speed", "rad/s", "flywheel speed", series=True, x="time", display_unit="rpm"
        ),
        Output("preload_bins", "N", "bin edges", series=True, display_unit="kN"),
        Output("preload_count", "1", "bolts per bin", series=True, x="preload_bins"),
    ),
    rungs=(
        Rung("rough", "2 % off", fixed_error(0.02), typical_error="2 %"),
        Rung("exact", "closed form", fixed_error(1e-12), typical_error="1e-12"),
    ),
    compute=_compute,
    examples=({"stroke": 0.01, "spring_rate": 3.0e4, "mass": 0.4},),
)
