"""Every test-only model, in one module (``from tests.toys import TOY, SPRING, ...``).

Each toy exercises one part of the contract without real physics, so the
generic suites (engine, service, stability, e2e) bite on an empty registry too.

* toy.disc: the contract without physics.
* toy.spring: the real models' numerical hazards.
* toy.ode, toy.spin, toy.stubborn, toy.crash: budgets, isolation, crashes.
* toy.striker: series, a shaded window and a histogram for the browser.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping
from typing import Any

import numpy as np
from fastapi import FastAPI
from scipy.integrate import solve_ivp

from engine import (
    BudgetExceeded,
    Check,
    InfeasibleDesign,
    ModelSpec,
    Output,
    Param,
    Plot,
    Result,
    RunContext,
    Rung,
    SolverFailed,
    Window,
    fixed_error,
)
from service import create_app
from service.config import Settings
from service.studies import StudySettings

# ---------------------------------------------------------------------------
# toy.disc: the contract without physics
# ---------------------------------------------------------------------------

# A toy model that exercises the contract without any real physics: a spinning disc.
#
# Rungs: ``rough`` (energy with a fixed 5 % error) and ``exact``.


def _disc(x: Mapping[str, Any], ctx: RunContext) -> Result:
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


def _disc_vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    import numpy as np

    d = np.asarray(x["diameter"], dtype=float)
    energy = 0.5 * x["mass"] * d**2 / 8.0 * x["speed"] ** 2
    energy = np.where(d > 5.0, np.nan, energy)  # pretend big discs burst
    return Result(values={"energy": energy}, rung=ctx.rung, error_estimate=1e-15)


TOY = ModelSpec(
    name="toy.disc",
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
    compute=_disc,
    examples=({"diameter": 0.2},),
    vectorized=_disc_vectorized,
    vector_rungs=("exact",),
)


# ---------------------------------------------------------------------------
# toy.spring: the real models' numerical hazards
# ---------------------------------------------------------------------------

# Test-only toy specs with the hazards of the real models, so the generic suite bites today.
#
# ``toy.spring``: a mass on a spring pushed from rest by a constant force F;
# when does it first reach the height h, and how fast is it going there?
#
# .. math::
#     x(t) = \frac{F}{k}(1 - \cos\omega t), \quad \omega = \sqrt{k/m},
#     \quad u = \frac{h k}{F} \in (0, 2]
#
# Three rungs, cheapest first, as the real models have them: ``rigid`` (no
# spring: t = √(2mh/F), error ≈ u/12 in time and u/4 in speed), ``exact``
# (closed form, written with 2 sin²(θ/2) for 1 − cos θ and with arcsin kept
# inside [−1, 1]) and ``simulation`` (scipy's solve_ivp with the step bounded to
# a fraction of the period, so it cannot step over the crossing). The hazards:
# stiff springs with light masses, u → 0 (1 − cos of a small angle), u → 2 (the
# mass only grazes h: arcsin at 1 and a tangent crossing) and u > 2 (a force
# too weak to lift the mass to h: a clear InfeasibleDesign, not a hang).

#: The simulation's event at a tangent crossing is ill-conditioned; it declines above this u.
GRAZING_U = 1.99


def _spring_ratio(x: Mapping[str, Any]) -> float:
    return x["height"] * x["stiffness"] / x["force"]


def _spring_rigid_estimate(x: Mapping[str, Any]) -> float | None:
    u = _spring_ratio(x)
    # speed is the worse output: 1/sqrt(1 - u/2) - 1 <= u/3 for u <= 0.5 (u/4 as u -> 0)
    return u / 3.0 if u <= 0.5 else None


def _spring_simulation_estimate(x: Mapping[str, Any]) -> float | None:
    return 1e-6 if _spring_ratio(x) <= GRAZING_U else None


def _spring(x: Mapping[str, Any], ctx: RunContext) -> Result:
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
        estimate = _spring_rigid_estimate(x)
    elif ctx.rung == "exact":
        theta = 2.0 * math.asin(min(1.0, math.sqrt(u / 2.0)))
        values["time"] = theta / omega
        values["speed"] = math.sqrt(max(0.0, h * (2.0 * f - k * h) / m))
        estimate = 1e-12
    else:
        values["time"], values["speed"] = _spring_simulate(m, k, f, h, ctx)
        estimate = 1e-6
    if ctx.wants("peak"):
        values["peak"] = 2.0 * f / k
    return Result(
        values={n: v for n, v in values.items() if ctx.wants(n)},
        rung=ctx.rung,
        error_estimate=estimate,
        notes=notes,
    )


def _spring_simulate(
    m: float, k: float, f: float, h: float, ctx: RunContext
) -> tuple[float, float]:
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


def _spring_vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
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
        Rung(
            "rigid",
            "no spring: t = √(2mh/F); error ≈ u/12 (time), u/4 (speed)",
            _spring_rigid_estimate,
        ),
        Rung("exact", "closed form", fixed_error(1e-12)),
        Rung("simulation", "solve_ivp, DOP853, bounded step", _spring_simulation_estimate),
    ),
    compute=_spring,
    examples=(
        {"mass": 0.1, "stiffness": 100.0, "force": 10.0, "height": 0.01},
        {"mass": 0.1, "stiffness": 1000.0, "force": 10.0, "height": 0.015},
        {"mass": 1e-3, "stiffness": 1e8, "force": 1e4, "height": 1e-4},
    ),
    vectorized=_spring_vectorized,
    vector_rungs=("exact",),
)

TOYS: tuple[ModelSpec, ...] = (SPRING,)


# ---------------------------------------------------------------------------
# toy.ode, toy.spin, toy.stubborn, toy.crash: budgets, isolation, crashes
# ---------------------------------------------------------------------------

# Test-only model specs for the hardening tests and the load-test fallback.
#
# * ``TOY_ODE``: a damped oscillator integrated with scipy's ``solve_ivp``: a
#   real (small) simulation that honours ``ctx.deadline`` and ``ctx.max_steps``
#   and returns time series. ``stiffness`` makes it as stiff as asked.
# * ``TOY_SPIN``: burns CPU in pure Python for ``seconds`` (holding the GIL
#   between switches), checking its deadline cooperatively like a real solver.
# * ``TOY_STUBBORN``: sleeps ``seconds`` and ignores its deadline (a buggy model).
# * ``TOY_CRASH``: raises an unexpected exception (a model bug: must be a clean 500).


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
    """The service over the well-behaved toys (``python -m service --factory ...:toy_app``).

    Design studies stay small and in-process (no Dask cluster from a test's toys).
    """
    small = StudySettings(max_points=4000, inprocess_points=4000, budget_s=2.0)
    return create_app(models=WELL_BEHAVED, settings=settings, study_settings=small)


# ---------------------------------------------------------------------------
# toy.striker: series, a shaded window and a histogram for the browser
# ---------------------------------------------------------------------------

# A second toy model for the browser test: time series, a shaded window and a histogram.
#
# No physics: a mass on a spring released at t = 0 (travel z = h (1 − cos k t) / 2,
# k = √(c/m)), a flywheel spinning up exponentially, and a binomial "preload
# scatter" histogram. It returns what the real models return (series with an
# ``x`` axis, bin edges one longer than the counts, an ``engagement_start`` /
# ``engagement_end`` pair, passing and failing checks, a warning) so the page's
# plots can be tested before those models are merged.

STRIKER_POINTS = 61
STRIKER_BINS = 11


def _striker(x: Mapping[str, Any], ctx: RunContext) -> Result:
    h, c, m, w = x["stroke"], x["spring_rate"], x["mass"], x["speed"]
    k = math.sqrt(c / m)
    t_end = math.pi / k  # half a period: the striker reaches h
    times = [t_end * i / (STRIKER_POINTS - 1) for i in range(STRIKER_POINTS)]
    travel = [h * (1.0 - math.cos(k * t)) / 2.0 for t in times]
    tau = t_end / 3.0
    speed = [w * (1.0 - math.exp(-t / tau)) for t in times]
    f0 = x["preload"]
    edges = [f0 * (0.7 + 0.6 * i / STRIKER_BINS) for i in range(STRIKER_BINS + 1)]
    counts = [float(math.comb(STRIKER_BINS - 1, i)) for i in range(STRIKER_BINS)]
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
        Output(
            "time",
            "s",
            "time",
            series=True,
            display_unit="ms",
            plot=Plot(windows=(Window("engagement", "engagement_start", "engagement_end"),)),
        ),
        Output("travel", "m", "striker travel", series=True, x="time", display_unit="mm"),
        Output(
            "flywheel_speed", "rad/s", "flywheel speed", series=True, x="time", display_unit="rpm"
        ),
        Output("preload_bins", "N", "bin edges", series=True, display_unit="kN"),
        Output(
            "preload_count",
            "1",
            "bolts per bin",
            series=True,
            x="preload_bins",
            plot=Plot(bars=True),
        ),
    ),
    rungs=(
        Rung("rough", "2 % off", fixed_error(0.02), typical_error="2 %"),
        Rung("exact", "closed form", fixed_error(1e-12), typical_error="1e-12"),
    ),
    compute=_striker,
    examples=({"stroke": 0.01, "spring_rate": 3.0e4, "mass": 0.4},),
)
