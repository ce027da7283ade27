"""Toy models with known analytic answers, for the study engine's tests.

``ishigami``: y = sin x1 + a sin² x2 + b x3⁴ sin x1 on [−π, π]³ (a = 7, b = 0.1), the
standard test function of global sensitivity analysis, whose Sobol' indices are known in
closed form (Ishigami & Homma 1990; Saltelli et al. 2008, *Global Sensitivity Analysis:
The Primer*, §4.8): S1 = 0.3139, 0.4424, 0; ST = 0.5576, 0.4424, 0.2437.

``additive``: y = x1 + 2 x2 + 0·x3 with x uniform on [0, 1]: var = 1/12 + 4/12, so
S1 = ST = 1/5, 4/5, 0 exactly.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from engine import ModelSpec, Output, Param, Result, RunContext, Rung, fixed_error

A, B = 7.0, 0.1
ISHIGAMI_S1 = (0.3139, 0.4424, 0.0)
ISHIGAMI_ST = (0.5576, 0.4424, 0.2437)


def _ishigami(x: Mapping[str, Any], ctx: RunContext) -> Result:
    x1, x2, x3 = (np.asarray(x[k], dtype=float) for k in ("x1", "x2", "x3"))
    y = np.sin(x1) + A * np.sin(x2) ** 2 + B * x3**4 * np.sin(x1)
    add = x1 + 2.0 * x2 + 0.0 * x3
    values: dict[str, Any] = {"ishigami": y, "additive": add, "positive": y > 0.0}
    if y.ndim == 0:
        values = {k: v.item() for k, v in values.items()}
    return Result(values=values, rung=ctx.rung, error_estimate=0.0)


def _param(name: str, lo: float, hi: float) -> Param:
    return Param(name, "1", name, default=0.0, minimum=lo, maximum=hi)


TOY_SA = ModelSpec(
    name="toy.ishigami",
    title="Ishigami function",
    family="toy",
    summary="Sensitivity-analysis test functions with analytic Sobol' indices.",
    source="Ishigami & Homma 1990",
    inputs=(
        _param("x1", -math.pi, math.pi),
        _param("x2", -math.pi, math.pi),
        _param("x3", -math.pi, math.pi),
    ),
    outputs=(
        Output("ishigami", "1", "sin x1 + 7 sin² x2 + 0.1 x3⁴ sin x1"),
        Output("additive", "1", "x1 + 2 x2"),
        Output("positive", "1", "ishigami > 0", kind="bool"),
    ),
    rungs=(Rung("exact", "exact", fixed_error(0.0)),),
    compute=_ishigami,
    vectorized=_ishigami,
    vector_rungs=("exact",),
    default_fidelity="exact",
)
