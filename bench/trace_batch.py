"""Benchmark: a batch of 1,000 traces of 2,000 samples read at once, beside a numpy floor.

``python -m bench.trace_batch`` prints the times; ``measure()`` returns the rows
``make bench`` (``bench/run.py``) adds to its table: {model, method, case, time_s, error,
notes}.

* ``batch_detection``: :func:`engine.physics.trace.detect` on the 1,000 × 2,000 arrays (the
  sliding gradient, the elastic window, the robust line with its outlier passes, the snug and
  yield points), then the friction and the preload of every trace from the joint's
  compliance (:func:`~engine.physics.trace.torque_per_preload_from_rate`,
  :func:`~engine.physics.trace.friction_from_torque_per_preload`,
  :func:`~engine.physics.trace.preload_from_torque`);
* ``numpy_floor``: the least numpy that gives the same points: the same sliding slope by
  cumulative sums, one plain least-squares line over the same window, the first drop below
  half the slope: no outlier passes, no snug point, no checks. The ratio of the two is what
  the robustness costs.

The traces are made here (an elastic line from a random snug angle and rate, a knee at a
random torque, noise): what is timed is the reading, not the making.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from bench.timing import median_wall_time
from engine.physics import trace as tr

TRACES, SAMPLES = 1000, 2000
DEG = math.pi / 180.0
#: The M12 joint of the examples: δ_S + δ_P [m/N], P, d2, d, d_W, d_h [m].
DELTA, PITCH, D2, D, DW, DH = 4.00995e-9, 1.75e-3, 10.86334175e-3, 0.012, 16.63e-3, 13.5e-3
WINDOW = 41  # 2° of 0.05° samples


def batch(n: int = TRACES, m: int = SAMPLES, seed: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """n traces of m samples: 0.05° apart, snug at 10…30°, 1.7…3.0 N·m/°, a knee at
    60…100 N·m, noise 0.05 N·m."""
    rng = np.random.default_rng(seed)
    theta = np.broadcast_to(np.arange(m) * 0.05 * DEG, (n, m))
    snug = rng.uniform(10.0, 30.0, (n, 1)) * DEG
    rate = rng.uniform(1.7, 3.0, (n, 1)) / DEG
    knee = rng.uniform(60.0, 100.0, (n, 1))
    lin = rate * np.maximum(theta - snug, 0.0)
    top = 0.15 * knee
    torque = np.where(lin > knee, knee + top * (1.0 - np.exp(-(lin - knee) / top)), lin)
    torque = torque + rng.normal(0.0, 0.05, (n, m))
    return np.ascontiguousarray(theta), torque


def read(angle: np.ndarray, torque: np.ndarray) -> dict[str, Any]:
    """The analysis of every trace: points, friction and preload."""
    d = tr.detect(angle, torque, WINDOW)
    k = tr.torque_per_preload_from_rate(d.rate, DELTA, PITCH)
    peak = np.take_along_axis(torque, d.peak[:, None], axis=-1)[:, 0]
    return {
        "rate": d.rate,
        "yield_at": d.yield_at,
        "friction": tr.friction_from_torque_per_preload(k, PITCH, D2, D, DW, DH),
        "preload": tr.preload_from_torque(peak, k),
    }


def floor(angle: np.ndarray, torque: np.ndarray) -> dict[str, Any]:
    """The same points by the least numpy: no outlier passes, no snug point, no checks."""
    n = WINDOW
    h = n // 2
    x = angle - angle[:, :1]
    c = np.pad(
        np.cumsum(np.stack([x, torque, x * x, x * torque]), axis=-1), ((0, 0), (0, 0), (1, 0))
    )
    sx, sy, sxx, sxy = c[..., n:] - c[..., :-n]
    g = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    peak_at = np.argmax(torque, axis=-1)
    peak = torque[np.arange(torque.shape[0]), peak_at]
    mask = (torque >= 0.3 * peak[:, None]) & (torque <= 0.7 * peak[:, None])
    w = mask.sum(axis=-1)
    xm = (x * mask).sum(axis=-1) / w
    ym = (torque * mask).sum(axis=-1) / w
    rate = ((x - xm[:, None]) * (torque - ym[:, None]) * mask).sum(axis=-1) / (
        ((x - xm[:, None]) ** 2 * mask).sum(axis=-1)
    )
    last = x.shape[-1] - 1 - np.argmax(mask[:, ::-1], axis=-1)
    idx = np.arange(h, x.shape[-1] - h)
    drop = (g <= 0.5 * rate[:, None]) & (idx > last[:, None]) & (idx <= peak_at[:, None] - h)
    k = rate * 2.0 * math.pi * DELTA / PITCH
    k0 = 0.16 * PITCH
    return {
        "rate": rate,
        "yield_at": np.where(drop.any(axis=-1), np.argmax(drop, axis=-1) + h, -1),
        "friction": (k - k0) / (0.58 * D2 + (DW + DH) / 4),
        "preload": peak / k,
    }


def measure() -> list[dict[str, Any]]:
    angle, torque = batch()
    ours, base = read(angle, torque), floor(angle, torque)
    agree = float(np.nanmax(np.abs(ours["friction"] - base["friction"])))
    t_ours = median_wall_time(lambda: read(angle, torque), 3)
    t_floor = median_wall_time(lambda: floor(angle, torque), 3)
    case = f"{TRACES} traces x {SAMPLES} samples"
    return [
        {
            "model": "trace.analysis",
            "method": "batch_detection",
            "case": case,
            "time_s": t_ours,
            "error": None,
            "notes": f"{t_ours / TRACES * 1e6:.0f} µs a trace; {t_ours / t_floor:.1f}× the floor",
        },
        {
            "model": "trace.analysis",
            "method": "numpy_floor",
            "case": case,
            "time_s": t_floor,
            "error": agree,
            "notes": "plain least squares, no outlier passes; error: largest friction "
            "difference from the batch detection",
        },
    ]


if __name__ == "__main__":
    for row in measure():
        print(f"{row['method']:>16}  {row['case']}: {row['time_s']:.3f} s  ({row['notes']})")
