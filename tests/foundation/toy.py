"""A toy model that exercises the contract without any real physics: a spinning disc.

Rungs: ``rough`` (energy with a fixed 5 % error) and ``exact``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from engine import (
    InfeasibleDesign,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    fixed_error,
)


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    m, d, w = x["mass"], x["diameter"], x["speed"]
    if x["mode"] == "broken":
        raise InfeasibleDesign("this disc is broken by design", field="mode")
    inertia = m * d**2 / 8.0
    energy = 0.5 * inertia * w**2
    values: dict[str, Any] = {}
    if ctx.wants("inertia"):
        values["inertia"] = inertia
    if ctx.wants("energy"):
        values["energy"] = energy * (1.05 if ctx.rung == "rough" else 1.0)
    if ctx.wants("ratio"):
        values["ratio"] = math.inf if x["blowup"] else 1.0
    if ctx.wants("fast"):
        values["fast"] = w > 100.0
    series = {}
    if ctx.wants("spin"):
        series["spin"] = [0.0, w / 2, w]
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.05 if ctx.rung == "rough" else 1e-15,
        notes=["toy"],
        series=series,
    )


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    import numpy as np

    d = np.asarray(x["diameter"], dtype=float)
    energy = 0.5 * x["mass"] * d**2 / 8.0 * x["speed"] ** 2
    energy = np.where(d > 5.0, np.nan, energy)  # pretend big discs burst
    return Result(values={"energy": energy}, rung=ctx.rung, error_estimate=1e-15)


TOY = ModelSpec(
    name="toy.disc",
    path="/toy/disc",
    title="Spinning disc",
    family="toy",
    summary="Kinetic energy of a uniform disc.",
    source="none",
    inputs=(
        Param(
            "mass",
            "kg",
            "disc mass",
            default=1.0,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=1e4,
            display_unit="kg",
        ),
        Param(
            "diameter",
            "m",
            "disc diameter",
            required=True,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=10.0,
            display_unit="mm",
        ),
        Param(
            "speed",
            "rad/s",
            "speed",
            default=100.0,
            minimum=0.0,
            maximum=1e4,
            recommended=(0.0, 500.0),
            display_unit="rpm",
        ),
        Param("count", "1", "how many", default=1, kind="int", minimum=1, maximum=100),
        Param(
            "angle",
            "rad",
            "an angle",
            default=0.5,
            minimum=0.0,
            maximum=math.pi / 2,
            exclusive_minimum=True,
            exclusive_maximum=True,
            display_unit="deg",
        ),
        Param("mode", "1", "mode", default="fine", kind="choice", choices=("fine", "broken")),
        Param("blowup", "1", "make a non-finite output", default=False, kind="bool"),
        Param("extra_load", "N", "optional load", display_unit="N"),
    ),
    outputs=(
        Output("inertia", "kg*m^2", "J = m D² / 8"),
        Output("energy", "J", "T = J ω² / 2"),
        Output("ratio", "1", "a ratio that can blow up"),
        Output("fast", "1", "faster than 100 rad/s", kind="bool"),
        Output("spin", "rad/s", "a tiny series", series=True),
    ),
    rungs=(
        Rung("rough", "5 % off", fixed_error(0.05)),
        Rung("exact", "exact", fixed_error(1e-15)),
    ),
    compute=_compute,
    examples=({"diameter": 0.2},),
    vectorized=_vectorized,
    vector_rungs=("exact",),
)
