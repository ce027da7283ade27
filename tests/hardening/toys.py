"""Test-only model specs for the hardening tests and the load-test fallback.

* ``TOY_ODE``: a damped oscillator integrated with scipy's ``solve_ivp``: a
  real (small) simulation that honours ``ctx.deadline`` and ``ctx.max_steps``
  and returns time series. ``stiffness`` makes it as stiff as asked.
* ``TOY_SPIN``: burns CPU in pure Python for ``seconds`` (holding the GIL
  between switches), checking its deadline cooperatively like a real solver.
* ``TOY_STUBBORN``: sleeps ``seconds`` and ignores its deadline (a buggy model).
* ``TOY_CRASH``: raises an unexpected exception (a model bug: must be a clean 500).
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from typing import Any

import numpy as np
from fastapi import FastAPI
from scipy.integrate import solve_ivp

from engine import (
    BudgetExceeded,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    fixed_error,
)
from service import create_app
from service.config import Settings
from tests.foundation.toy import TOY


def _ode(x: Mapping[str, Any], ctx: RunContext) -> Result:
    k, c, t_end, n = x["stiffness"], x["damping"], x["t_end"], x["points"]
    steps = 0

    def rhs(_: float, y: np.ndarray) -> np.ndarray:
        nonlocal steps
        steps += 1
        if steps > ctx.max_steps:
            raise BudgetExceeded(f"stopped at its step budget of {ctx.max_steps} steps")
        if ctx.deadline is not None and time.perf_counter() > ctx.deadline:
            raise BudgetExceeded("stopped at its wall-clock budget")
        return np.array([y[1], -k * y[0] - c * y[1]])

    t = np.linspace(0.0, t_end, n)
    sol = solve_ivp(rhs, (0.0, t_end), [1.0, 0.0], t_eval=t, method=ctx.rung, rtol=1e-6)
    values: dict[str, Any] = {}
    if ctx.wants("final"):
        values["final"] = float(sol.y[0, -1])
    if ctx.wants("evaluations"):
        values["evaluations"] = int(steps)
    series = {}
    if ctx.wants("x"):
        series["time"] = t.tolist()
        series["x"] = sol.y[0].tolist()
    return Result(values=values, rung=ctx.rung, error_estimate=1e-6, series=series)


TOY_ODE = ModelSpec(
    name="toy.ode",
    path="/toy/ode",
    title="Damped oscillator (simulation)",
    family="toy",
    summary="x'' + c x' + k x = 0 from x = 1, integrated numerically.",
    source="none",
    inputs=(
        Param(
            "stiffness",
            "N/m",
            "spring rate per unit mass",
            default=100.0,
            minimum=1e-3,
            maximum=1e5,
        ),
        Param("damping", "1/s", "damping per unit mass", default=1.0, minimum=0.0, maximum=1e6),
        Param("t_end", "s", "simulated time", default=1.0, minimum=1e-3, maximum=20.0),
        Param(
            "points", "1", "output points", default=200, kind="int", minimum=2, maximum=1_000_000
        ),
    ),
    outputs=(
        Output("final", "m", "x at t_end"),
        Output("evaluations", "1", "right-hand-side evaluations", kind="int"),
        Output("time", "s", "time", series=True),
        Output("x", "m", "displacement", series=True, x="time"),
    ),
    rungs=(
        Rung("RK45", "explicit", fixed_error(1e-6)),
        Rung("LSODA", "stiff-aware", fixed_error(1e-6)),
    ),
    compute=_ode,
    default_fidelity="RK45",
    examples=({},),
)


def _spin(x: Mapping[str, Any], ctx: RunContext) -> Result:
    end = time.perf_counter() + x["seconds"]
    n = 0
    while time.perf_counter() < end:
        n += 1
        if n % 1000 == 0 and ctx.deadline is not None and time.perf_counter() > ctx.deadline:
            raise BudgetExceeded("spin stopped at its wall-clock budget", field="seconds")
    return Result(values={"loops": float(n)}, rung=ctx.rung, error_estimate=None)


def _sleep(x: Mapping[str, Any], ctx: RunContext) -> Result:
    time.sleep(x["seconds"])  # ignores ctx.deadline on purpose
    return Result(values={"loops": 0.0}, rung=ctx.rung, error_estimate=None)


def _crash(x: Mapping[str, Any], ctx: RunContext) -> Result:
    raise ZeroDivisionError("secret internal detail")


def _timed(name: str, compute: Any) -> ModelSpec:
    return ModelSpec(
        name=f"toy.{name}",
        path=f"/toy/{name}",
        title=name,
        family="toy",
        summary="test-only",
        source="none",
        inputs=(Param("seconds", "s", "how long", default=0.0, minimum=0.0, maximum=60.0),),
        outputs=(Output("loops", "1", "loops done"),),
        rungs=(Rung("only", "the only one", fixed_error(0.0)),),
        compute=compute,
        examples=({},),
    )


TOY_SPIN = _timed("spin", _spin)
TOY_STUBBORN = _timed("stubborn", _sleep)
TOY_CRASH = _timed("crash", _crash)

#: Well-behaved test models (the fuzzer and the load test run over these).
WELL_BEHAVED = (TOY, TOY_ODE)


def toy_app(settings: Settings | None = None) -> FastAPI:
    """The service over the well-behaved toys (``python -m service --factory ...:toy_app``)."""
    return create_app(models=WELL_BEHAVED, settings=settings)
