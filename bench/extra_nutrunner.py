"""Benchmark: the nut-runner drive's spin-up quadrature against an ODE integration.

``measure()`` returns one row per (method, case): the median wall time of one
evaluation and the relative error against the closed-form integral of each
curve (exact to rounding). Methods:

* ``quad``: :func:`engine.physics.motor_spinup.spin_up_time`, adaptive QUADPACK on the
  substituted variable (what the ``motor_curve`` rung runs);
* ``solve_ivp``: ``scipy.integrate.solve_ivp`` (RK45, rtol 1e-8) of
  J dω/dt = M(ω) with a terminal event at the working speed, the general way;
* ``profile``: the cumulative 8-point Gauss–Legendre used for the plotted
  series (100 panels);
* ``closed_form`` / ``vectorized``: the paper's rung, one scalar run through
  :func:`engine.run` and per point of a 10⁶-point array sweep.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from bench.timing import median_wall_time
from engine import run
from engine.core.spec import RunContext
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE
from engine.physics.motor_spinup import (
    MotorCurve,
    kloss_breakdown_slip,
    kloss_slip_torque,
    kloss_spin_up_time,
    kloss_torque,
    linear_motor_torque,
    linear_spin_up_time,
    spin_up_profile,
    spin_up_time,
    torque_limited_constant_power_spin_up_time,
)

MODEL = "nutrunner.drive"
W = 1400 * math.pi / 30  # working speed of the example, rad/s
W_SYNC = 1500 * math.pi / 30


def _ivp_time(j: float, curve: MotorCurve, speed: float, rtol: float = 1e-8) -> float:
    """Spin-up time by integrating J dω/dt = M(ω) until ω = speed (terminal event)."""

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        return [float(curve.torque(y[0])) / j]

    def reached(_t: float, y: np.ndarray) -> float:
        return float(y[0] - speed)

    reached.terminal = True  # type: ignore[attr-defined]
    reached.direction = 1  # type: ignore[attr-defined]
    horizon = 1e3 * j * speed / float(curve.torque(0.0))
    sol = solve_ivp(
        rhs, (0.0, horizon), [0.0], events=reached, rtol=rtol, atol=1e-10 * speed, method="RK45"
    )
    if not sol.success or not sol.t_events[0].size:
        raise RuntimeError(f"solve_ivp did not reach the speed: {sol.message}")
    return float(sol.t_events[0][0])


def _cases() -> list[tuple[str, float, MotorCurve, float, float]]:
    """(name, J, curve, speed, exact time)."""
    cases = []
    # 1. the induction example: 1.1 kW, 1400/1500 rpm, breakdown 2.2× rated, J = 0.0162 kg·m²
    j = 0.0035 + 0.001855 + 0.00992 / 0.95 + 0.000384 / (0.95 * 0.97)
    m_k = 2.2 * 1100.0 / W
    s_k = kloss_breakdown_slip(W, W_SYNC, 2.2)
    kloss = MotorCurve(
        "induction",
        lambda w: kloss_torque(w, m_k, W_SYNC, s_k),
        W_SYNC,
        torque_below_limit=lambda g: kloss_slip_torque(g / W_SYNC, m_k, s_k),
    )
    cases.append(
        ("Kloss induction, ω = 0.933 ω_s", j, kloss, W, kloss_spin_up_time(j, m_k, W_SYNC, s_k, W))
    )
    # 2. a linear motor pushed to 0.999 of its no-load speed: the 1/(ω0 − ω) end
    w0 = W / 0.999
    linear = MotorCurve(
        "linear",
        lambda w: linear_motor_torque(w, 30.0, w0),
        w0,
        torque_below_limit=lambda g: 30.0 * g / w0,
    )
    cases.append(
        ("linear, ω = 0.999 ω0", 0.012159, linear, W, linear_spin_up_time(0.012159, 30.0, w0, W))
    )
    # 3. constant power above a 20 N·m limit: a kink at ω_c = 55 rad/s
    cp = MotorCurve("constant_power", lambda w: 1100.0 / np.maximum(w, 55.0), None, (55.0,))
    cases.append(
        (
            "constant power, 20 N·m limit (kink)",
            0.012159,
            cp,
            W,
            torque_limited_constant_power_spin_up_time(0.012159, 1100.0, 20.0, W),
        )
    )
    return cases


def measure() -> list[dict[str, Any]]:
    """Rows {model, method, case, time_s, error, notes} for the bench runner."""
    rows: list[dict[str, Any]] = []
    for name, j, curve, speed, exact in _cases():
        t_q, err_q = spin_up_time(j, curve, speed)
        rows.append(
            {
                "model": MODEL,
                "method": "quad",
                "case": name,
                "time_s": median_wall_time(lambda j=j, c=curve, s=speed: spin_up_time(j, c, s), 50),
                "error": abs(t_q - exact) / exact,
                "notes": "QUADPACK, ω = ω0(1 − e^-x) where M → 0, kinks as breakpoints; "
                f"own estimate {err_q / t_q:.1e}",
            }
        )
        t_i = _ivp_time(j, curve, speed)
        rows.append(
            {
                "model": MODEL,
                "method": "solve_ivp",
                "case": name,
                "time_s": median_wall_time(lambda j=j, c=curve, s=speed: _ivp_time(j, c, s), 5),
                "error": abs(t_i - exact) / exact,
                "notes": "RK45 rtol 1e-8, terminal event at the working speed",
            }
        )
        t_p, _ = spin_up_profile(j, curve, speed)
        rows.append(
            {
                "model": MODEL,
                "method": "profile",
                "case": name,
                "time_s": median_wall_time(
                    lambda j=j, c=curve, s=speed: spin_up_profile(j, c, s), 20
                ),
                "error": abs(float(t_p[-1]) - exact) / exact,
                "notes": "cumulative Gauss–Legendre 8 × 100 panels (the plotted series)",
            }
        )
    rows.append(
        {
            "model": MODEL,
            "method": "closed_form",
            "case": "illustrative light-truck runner, engine.run",
            "time_s": median_wall_time(lambda: run(NUTRUNNER_DRIVE, EXAMPLE_LIGHT_TRUCK), 200),
            "error": 0.0,
            "notes": "the paper's rung; error against its own equations (rounding only)",
        }
    )
    x, _ = NUTRUNNER_DRIVE.validate(EXAMPLE_LIGHT_TRUCK)
    d = np.linspace(0.01, 0.1, 1_000_000)
    ctx = RunContext(
        rung="closed_form",
        outputs=frozenset(o.name for o in NUTRUNNER_DRIVE.outputs if not o.series),
        tolerance=0.01,
    )
    assert NUTRUNNER_DRIVE.vectorized is not None
    vec = NUTRUNNER_DRIVE.vectorized
    total = median_wall_time(lambda: vec({**x, "spindle_diameter": d}, ctx), 5)
    rows.append(
        {
            "model": MODEL,
            "method": "vectorized",
            "case": "1e6-point sweep of spindle_diameter, per point",
            "time_s": total / d.size,
            "error": 0.0,
            "notes": f"all 22 scalar outputs; whole sweep {total * 1e3:.1f} ms",
        }
    )
    return rows


if __name__ == "__main__":
    for row in measure():
        print(
            f"{row['method']:12s} {row['case'][:44]:44s} "
            f"{row['time_s'] * 1e6:10.2f} µs  err {row['error']:.1e}  {row['notes']}"
        )
