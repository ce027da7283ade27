"""Test-only toy specs with the hazards of the real models, so the generic suite bites today.

``toy.spring``: a mass on a spring pushed from rest by a constant force F;
when does it first reach the height h, and how fast is it going there?

.. math::
    x(t) = \\frac{F}{k}(1 - \\cos\\omega t), \\quad \\omega = \\sqrt{k/m},
    \\quad u = \\frac{h k}{F} \\in (0, 2]

Three rungs, cheapest first, as the real models have them: ``rigid`` (no
spring: t = √(2mh/F), error ≈ u/12 in time and u/4 in speed), ``exact``
(closed form, written with 2 sin²(θ/2) for 1 − cos θ and with arcsin kept
inside [−1, 1]) and ``simulation`` (scipy's solve_ivp with the step bounded to
a fraction of the period, so it cannot step over the crossing). The hazards:
stiff springs with light masses, u → 0 (1 − cos of a small angle), u → 2 (the
mass only grazes h: arcsin at 1 and a tangent crossing) and u > 2 (a force
too weak to lift the mass to h: a clear InfeasibleDesign, not a hang).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from engine import (
    BudgetExceeded,
    InfeasibleDesign,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    SolverFailed,
    fixed_error,
)

#: The simulation's event at a tangent crossing is ill-conditioned; it declines above this u.
GRAZING_U = 1.99


def _ratio(x: Mapping[str, Any]) -> float:
    return x["height"] * x["stiffness"] / x["force"]


def _rigid_estimate(x: Mapping[str, Any]) -> float | None:
    u = _ratio(x)
    # speed is the worse output: 1/sqrt(1 - u/2) - 1 <= u/3 for u <= 0.5 (u/4 as u -> 0)
    return u / 3.0 if u <= 0.5 else None


def _simulation_estimate(x: Mapping[str, Any]) -> float | None:
    return 1e-6 if _ratio(x) <= GRAZING_U else None


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    m, k, f, h = x["mass"], x["stiffness"], x["force"], x["height"]
    u = h * k / f
    if u > 2.0:
        raise InfeasibleDesign(
            f"the force lifts the mass at most 2F/k = {2 * f / k:.3g} m, below h = {h:.3g} m: "
            "raise the force or soften the spring",
            field="height",
        )
    omega = math.sqrt(k / m)
    values: dict[str, Any] = {}
    notes: list[str] = []
    estimate: float | None = 0.0  # peak alone is exact on every rung
    if not ctx.wants("time", "speed"):
        pass  # the peak alone needs no rung's work, least of all the simulation
    elif ctx.rung == "rigid":
        values["time"] = math.sqrt(2.0 * m * h / f)
        values["speed"] = math.sqrt(2.0 * f * h / m)
        estimate = _rigid_estimate(x)
    elif ctx.rung == "exact":
        theta = 2.0 * math.asin(min(1.0, math.sqrt(u / 2.0)))
        values["time"] = theta / omega
        values["speed"] = math.sqrt(max(0.0, h * (2.0 * f - k * h) / m))
        estimate = 1e-12
    else:
        values["time"], values["speed"] = _simulate(m, k, f, h, ctx)
        estimate = 1e-6
    if ctx.wants("peak"):
        values["peak"] = 2.0 * f / k
    return Result(
        values={n: v for n, v in values.items() if ctx.wants(n)},
        rung=ctx.rung,
        error_estimate=estimate,
        notes=notes,
    )


def _simulate(m: float, k: float, f: float, h: float, ctx: RunContext) -> tuple[float, float]:
    """solve_ivp in the units of the problem (x/h, ω t) so stiffness spans no decades."""
    omega = math.sqrt(k / m)
    u = h * k / f

    def rhs(tau: float, y: np.ndarray) -> list[float]:
        # y = (x/h, dx/dτ / h), τ = ω t:  x'' = (F/k)/h − x
        return [y[1], 1.0 / u - y[0]]

    def reach(tau: float, y: np.ndarray) -> float:
        return y[0] - 1.0

    reach.terminal = True  # type: ignore[attr-defined]
    reach.direction = 1.0  # type: ignore[attr-defined]
    if ctx.deadline is not None and ctx.deadline <= 0:
        raise BudgetExceeded("no time left for the simulation")
    sol = solve_ivp(
        rhs,
        (0.0, math.pi * 1.01),
        [0.0, 0.0],
        method="DOP853",
        events=reach,
        rtol=1e-11,
        atol=1e-13,
        max_step=2.0 * math.pi / 64,  # never step over a crossing: 1/64 of a period
    )
    if not sol.success or not sol.t_events[0].size:
        raise SolverFailed("the simulation did not reach the height h before the first peak")
    tau = float(sol.t_events[0][0])
    velocity = float(sol.y_events[0][0][1])
    return tau / omega, max(velocity, 0.0) * h * omega


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    m, k, f, h = (np.asarray(x[n], dtype=float) for n in ("mass", "stiffness", "force", "height"))
    u = h * k / f
    ok = u <= 2.0
    s = np.sqrt(np.where(ok, u, 0.0) / 2.0)
    theta = 2.0 * np.arcsin(np.minimum(s, 1.0))
    time = np.where(ok, theta / np.sqrt(k / m), np.nan)
    speed = np.where(ok, np.sqrt(np.maximum(0.0, h * (2.0 * f - k * h) / m)), np.nan)
    values = {"time": time, "speed": speed, "peak": np.where(ok, 2.0 * f / k, np.nan)}
    return Result(
        values={n: v for n, v in values.items() if ctx.wants(n)},
        rung=ctx.rung,
        error_estimate=1e-12,
    )


SPRING = ModelSpec(
    name="toy.spring",
    path="/toy/spring",
    title="Mass on a spring lifted by a constant force (test toy)",
    family="toy",
    summary="Time and speed at which a mass pushed by a constant force against a spring "
    "first reaches a height.",
    source="undamped oscillator, x = (F/k)(1 − cos ωt)",
    inputs=(
        Param("mass", "kg", "moving mass", default=0.1, minimum=1e-4, maximum=1e3),
        Param("stiffness", "N/m", "spring rate", default=100.0, minimum=1e-3, maximum=1e9),
        Param(
            "force",
            "N",
            "constant push",
            default=10.0,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=1e6,
        ),
        Param(
            "height",
            "m",
            "height to reach",
            default=0.01,
            minimum=0.0,
            exclusive_minimum=True,
            maximum=1.0,
        ),
    ),
    outputs=(
        Output("time", "s", "time to first reach h: t = 2 arcsin(√(u/2)) / ω"),
        Output("speed", "m/s", "speed at h: v = √(h (2F − k h) / m)"),
        Output("peak", "m", "highest point 2F/k"),
    ),
    rungs=(
        Rung("rigid", "no spring: t = √(2mh/F); error ≈ u/12 (time), u/4 (speed)", _rigid_estimate),
        Rung("exact", "closed form", fixed_error(1e-12)),
        Rung("simulation", "solve_ivp, DOP853, bounded step", _simulation_estimate),
    ),
    compute=_compute,
    examples=(
        {"mass": 0.1, "stiffness": 100.0, "force": 10.0, "height": 0.01},
        {"mass": 0.1, "stiffness": 1000.0, "force": 10.0, "height": 0.015},
        {"mass": 1e-3, "stiffness": 1e8, "force": 1e4, "height": 1e-4},
    ),
    vectorized=_vectorized,
    vector_rungs=("exact",),
)

TOYS: tuple[ModelSpec, ...] = (SPRING,)
