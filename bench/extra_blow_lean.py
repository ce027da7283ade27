"""The blow's compiled kernel against a lean kernel of the same equations, per step (issue 35).

The lean kernel below is the floor: the two-mass blow of
:func:`engine.physics.blow.simulate_blow` (the same right-hand side, the same seven states
u, ω_t, θ, ω_s, W_j, W_N, W_c, the same fixed RK4 step, the same stick, breakaway and
end-of-blow events and the same torque-maximum search, each bisected 60 times on RK4
sub-steps from the step's start) written as one numba function with the state in local
variables: no arrays, no recording, no budget. It is kept here, not in the engine, only
to be measured against.

``measure()`` times both kernels per step (CPU time, medians of interleaved rounds, the
product's kernel called as :func:`~engine.physics.blow.simulate_blow` calls it) on three
blows and returns one row per blow beside the target "product ≤ 2× lean"; it also checks
that the two give the same peak torque and rotation (to 1e-9 relative: the same
equations, the same steps). ``python bench/extra_blow_lean.py`` prints the rows.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numba
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from engine.physics.blow import BlowProblem, _blow_kernel_c

MODEL = "blow.joint"
TARGET_RATIO = 2.0
ROUNDS = 7
ROUND_S = 0.15


@numba.njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _lean_step(u, wt, th, ws, wj, wn, wc, h, mode, jt, js, c, cd, k, t0, n):  # type: ignore[no-untyped-def]
    """One RK4 step of the seven states (the blow's right-hand side written in line)."""
    x0, x1, x2, x3 = u, wt, th, ws
    acc0 = acc1 = acc2 = acc3 = acc4 = acc5 = acc6 = 0.0
    for stage in range(4):
        du = x1 - x3
        ts = 0.0
        up = 0.0
        if x0 > 0.0:
            up = x0
            ts = c * x0 + cd * du
            if ts < 0.0:
                ts = 0.0
        dwt = (n - ts) / jt
        tj = t0 + k * x2
        dth = 0.0
        dws = 0.0
        pj = 0.0
        if mode == 1:
            dth = x3
            dws = (ts - tj) / js
            pj = tj * x3
        pn = n * x1
        pc = (ts - c * up) * du
        w = 1.0 if stage == 0 or stage == 3 else 2.0
        acc0 += w * du
        acc1 += w * dwt
        acc2 += w * dth
        acc3 += w * dws
        acc4 += w * pj
        acc5 += w * pn
        acc6 += w * pc
        f = h if stage == 2 else 0.5 * h
        x0 = u + f * du
        x1 = wt + f * dwt
        x2 = th + f * dth
        x3 = ws + f * dws if mode == 1 else 0.0
    g = h / 6.0
    return (
        u + g * acc0,
        wt + g * acc1,
        th + g * acc2,
        ws + g * acc3 if mode == 1 else 0.0,
        wj + g * acc4,
        wn + g * acc5,
        wc + g * acc6,
    )


@numba.njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _lean_spring(u, wt, ws, c, cd):  # type: ignore[no-untyped-def]
    if u <= 0.0:
        return 0.0
    ts = c * u + cd * (wt - ws)
    return ts if ts > 0.0 else 0.0


@numba.njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _lean_event(u, wt, th, ws, mode, js, jt, c, cd, k, t0, b, n, started):  # type: ignore[no-untyped-def]
    tj = t0 + k * th
    if mode == 1:
        if ws < 0.0:
            return 1
        if started and u < 0.0 and wt <= ws and n * js + tj * jt <= 0.0:
            return 3
        return 0
    if _lean_spring(u, wt, ws, c, cd) > b * tj:
        return 2
    if started and wt <= 0.0:
        return 3
    return 0


@numba.njit(cache=True, nogil=True, error_model="numpy", inline="always")
def _lean_rate(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n):  # type: ignore[no-untyped-def]
    """dT_s/dt on the contact (0 off it)."""
    if u <= 0.0:
        return 0.0
    ts = c * u + cd * (wt - ws)
    if ts < 0.0:
        ts = 0.0
    dws = (ts - (t0 + k * th)) / js if mode == 1 else 0.0
    return c * (wt - ws) + cd * ((n - ts) / jt - dws)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def lean_blow(h, speed, jt, js, c, cd, k, t0, b, n, max_steps):  # type: ignore[no-untyped-def]
    """One blow from rest on the jaws: (peak torque, rotation, steps, duration)."""
    u, wt, th, ws, wj, wn, wc = 0.0, speed, 0.0, 0.0, 0.0, 0.0, 0.0
    mode = 0
    started = False
    t = 0.0
    peak = 0.0
    steps = 0
    r0 = _lean_rate(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
    while steps < max_steps:
        v = _lean_step(u, wt, th, ws, wj, wn, wc, h, mode, jt, js, c, cd, k, t0, n)
        steps += 1
        ev = _lean_event(
            v[0], v[1], v[2], v[3], mode, js, jt, c, cd, k, t0, b, n, started or v[0] > 0.0
        )
        frac = 1.0
        if ev != 0:
            lo, hi = 0.0, 1.0
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                q = _lean_step(u, wt, th, ws, wj, wn, wc, mid * h, mode, jt, js, c, cd, k, t0, n)
                e = _lean_event(
                    q[0], q[1], q[2], q[3], mode, js, jt, c, cd, k, t0, b, n, started or q[0] > 0.0
                )
                if e == ev:
                    hi = mid
                else:
                    lo = mid
            frac = hi
            v = _lean_step(u, wt, th, ws, wj, wn, wc, frac * h, mode, jt, js, c, cd, k, t0, n)
        r1 = _lean_rate(v[0], v[1], v[2], v[3], mode, jt, js, c, cd, k, t0, n)
        if r0 > 0.0 and r1 <= 0.0:  # a torque maximum inside the step
            lo, hi = 0.0, frac
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                q = _lean_step(u, wt, th, ws, wj, wn, wc, mid * h, mode, jt, js, c, cd, k, t0, n)
                if _lean_rate(q[0], q[1], q[2], q[3], mode, jt, js, c, cd, k, t0, n) > 0.0:
                    lo = mid
                else:
                    hi = mid
            q = _lean_step(u, wt, th, ws, wj, wn, wc, lo * h, mode, jt, js, c, cd, k, t0, n)
            tsm = _lean_spring(q[0], q[1], q[3], c, cd)
            if tsm > peak:
                peak = tsm
        u, wt, th, ws, wj, wn, wc = v
        t += frac * h
        if u > 0.0:
            started = True
        ts = _lean_spring(u, wt, ws, c, cd)
        if ts > peak:
            peak = ts
        if ev == 3:
            break
        if ev == 1:
            ws = 0.0
            mode = 0
            if _lean_spring(u, wt, ws, c, cd) > b * (t0 + k * th):
                mode = 1
            elif wt <= 0.0 and started:
                break
        elif ev == 2:
            mode = 1
        r0 = _lean_rate(u, wt, th, ws, mode, jt, js, c, cd, k, t0, n)
    return peak, th, steps, t


def _cases() -> dict[str, tuple[BlowProblem, float]]:
    return {
        "two flywheels (free struck side)": (
            BlowProblem(21.07, 63.21, 203.4, 150 * math.pi / 30, 0.0),
            0.0,
        ),
        "ISO 5393 hard joint, b = 1.1": (
            BlowProblem(0.0297, 1e-3, 2.32e4, 93.8, 600 / math.radians(30), 1.1),
            60.0,
        ),
        "stick-slip, b = 1.3, e = 0.5": (
            BlowProblem(0.03, 1e-3, 2e4, 90.0, 1000.0, 1.3, 0.0, 0.5),
            60.0,
        ),
    }


def _product(p: BlowProblem, t0: float) -> Callable[[], tuple[float, float, int]]:
    """The product's kernel on one blow, called as simulate_blow calls it (no recording)."""
    h, cd = p.step, p.damping
    out = np.empty(1)
    st = np.zeros(7)
    info = np.zeros(8)
    args = (p.tool_inertia, p.struck_inertia, p.stiffness, cd, p.rate, t0, p.breakaway)

    def run() -> tuple[float, float, int]:
        st[:] = 0.0
        st[1] = p.speed
        info[:] = 0.0
        _blow_kernel_c(st, h, 10**7, *args, p.drive_torque, 0, out, out, info)
        return float(info[3]), float(st[2]), int(info[1])

    return run


def _lean(p: BlowProblem, t0: float) -> Callable[[], tuple[float, float, int]]:
    h, cd = p.step, p.damping
    args = (p.tool_inertia, p.struck_inertia, p.stiffness, cd, p.rate, t0, p.breakaway)

    def run() -> tuple[float, float, int]:
        peak, rot, steps, _ = lean_blow(h, p.speed, *args, p.drive_torque, 10**7)
        return float(peak), float(rot), int(steps)

    return run


def _per_call(fn: Callable[[], Any]) -> float:
    """CPU seconds per call over one round of about ROUND_S."""
    n = 0
    c0 = time.process_time()
    while True:
        fn()
        n += 1
        spent = time.process_time() - c0
        if spent >= ROUND_S:
            return spent / n


def measure() -> list[dict[str, Any]]:
    """One row per blow: the product's ns per step over the lean kernel's, target ≤ 2."""
    rows: list[dict[str, Any]] = []
    for case, (p, t0) in _cases().items():
        product, lean = _product(p, t0), _lean(p, t0)
        (pk, pr, steps), (lk, lr, lsteps) = product(), lean()
        same = abs(pk / lk - 1.0) <= 1e-9 and abs(pr - lr) <= 1e-9 * max(abs(lr), 1e-300)
        ratios, prod_ns, lean_ns = [], [], []
        for _ in range(ROUNDS):
            a = _per_call(product) / steps
            b = _per_call(lean) / lsteps
            ratios.append(a / b)
            prod_ns.append(a * 1e9)
            lean_ns.append(b * 1e9)
        ratio = statistics.median(ratios)
        rows.append(
            {
                "model": MODEL,
                "method": "blow kernel / lean kernel",
                "case": case,
                "time_s": statistics.median(prod_ns) * 1e-9 * steps,
                "ratio": ratio,
                "target": f"blow kernel ≤ {TARGET_RATIO:g}× a lean kernel per step",
                "target_ratio": TARGET_RATIO,
                "met": bool(ratio <= TARGET_RATIO and same),
                "notes": (
                    f"{statistics.median(prod_ns):.0f} ns/step against "
                    f"{statistics.median(lean_ns):.0f} ns/step lean, {steps} steps, "
                    f"CPU time, median of {ROUNDS} interleaved rounds; same peak and rotation: "
                    f"{'yes' if same else f'NO ({pk!r} vs {lk!r}, {pr!r} vs {lr!r})'}"
                ),
            }
        )
    return rows


if __name__ == "__main__":
    for row in measure():
        print(
            f"{row['case']:34} ×{row['ratio']:.2f} (target ≤ ×{row['target_ratio']:g}) "
            f"{row['notes']}"
        )
