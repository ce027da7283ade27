"""Do the striker's stated error estimates bound its errors? (issue 29, "Estimates that bound").

``rows(n, seed)`` draws ``n`` designs of ``impact.rare`` and returns one row per (model,
rung, output): the stated claim, whether it is a ``bound`` or ``typical``, how many designs
exceed it and the worst ratio of error to estimate. ``python bench/accuracy_striker.py``
prints them.

Designs: every positive input of the reference design times 4^U(−1, 1) (a factor 1/4 to 4,
uniform in its logarithm), the cone angle uniform in its recommended 15°–75°, 2 to 8
rollers, the roller geometry one of the three, gravity uniform in ±9.81 m/s², the roller
friction in 0.05–0.2. The declared ranges themselves span up to 12 decades (spring rates to
1e9 N/m): a uniform draw over them is almost all refusals and budget stops, so the box is
the one the model is used in, declared here.

Reference: the same hybrid simulation with 4000 RK4 steps per shortest period instead of 200
(a fixed-step RK4's error falls as h⁴: 20⁴ = 1.6e5 times tighter, events located to the last
bit on each step's cubic). A design whose reference cannot be computed (refused, budget) is
skipped and counted; a closed-form design whose estimate says the rung does not apply (NaN,
``None`` in a result) makes no claim and is counted apart.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from engine.core.errors import EngineError
from engine.models.rare_impact import _SIMULATION_ERROR, REFERENCE_DESIGN, _groups
from engine.procedures.striker_cycle import (
    GEOMETRIES,
    CycleOutcome,
    closed_form_cycle,
    closed_form_errors,
    simulate_cycle,
    simulation_release_velocity_error,
)

MODEL = "impact.rare"
REFERENCE_STEPS = 4000
#: Outputs compared: the CycleOutcome field, the model's output name, its closed-form group.
OUTPUTS = (
    ("release_speed", "release_speed"),
    ("spin_up_time", "spin_up_time"),
    ("engagement_time", "engagement_time"),
    ("return_time", "return_time"),
    ("striker_home_time", "striker_home_time"),
    ("relock_time", "relock_time"),
    ("cycle_time", "cycle_time"),
)
_POSITIVE = (
    "flywheel_inertia", "motor_torque", "roller_mass", "roller_radius", "half_coupling_mass",
    "stepped_shaft_mass", "striker_mass", "power_spring_rate", "auxiliary_spring_rate",
    "return_spring_rate", "power_spring_preload", "auxiliary_spring_preload",
    "return_spring_preload", "release_travel", "engagement_height", "jaw_height",
    "engagement_angle",
)  # fmt: skip
REFERENCE_TEXT = (
    f"the same hybrid simulation at {REFERENCE_STEPS} RK4 steps per period instead of 200 "
    "(error ∝ h⁴: 1.6e5× tighter than the simulation, far more than the closed form)"
)


def designs(n: int, seed: int) -> list[dict[str, Any]]:
    """``n`` designs of the box in the module notes, seeded."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        x = dict(REFERENCE_DESIGN)
        for k in _POSITIVE:
            x[k] = float(REFERENCE_DESIGN[k] * 4.0 ** rng.uniform(-1.0, 1.0))
        x["cone_angle"] = math.radians(float(rng.uniform(15.0, 75.0)))
        x["roller_count"] = int(rng.integers(2, 9))
        x["roller_geometry"] = GEOMETRIES[int(rng.integers(0, len(GEOMETRIES)))]
        x["gravity"] = float(rng.uniform(-9.81, 9.81))
        x["roller_friction"] = float(rng.uniform(0.05, 0.2))
        out.append(x)
    return out


def _value(o: CycleOutcome, field: str) -> float:
    """A CycleOutcome field, or a model output summed from them (as the model does)."""
    if field == "striker_home_time":
        return float(o.spin_up_time + o.engagement_time + o.home_time)
    if field == "cycle_time":
        return float(o.spin_up_time + o.engagement_time + o.home_time + o.relock_time)
    return float(getattr(o, field))


def _rel(a: float, b: float) -> float:
    """|a − b|/|b|, 0 where both are the same infinity, inf where one only is finite."""
    if math.isinf(a) or math.isinf(b):
        return 0.0 if a == b else math.inf
    return abs(a - b) / abs(b) if b != 0.0 else abs(a - b)


def measure(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    """Per design: the reference, the two rungs, the closed form's estimates (or why not)."""
    out = []
    for x in designs(n, seed):
        try:
            ref = simulate_cycle(x, steps_per_period=REFERENCE_STEPS, max_steps=50_000_000)
        except EngineError as e:
            out.append({"skip": type(e).__name__})
            continue
        row: dict[str, Any] = {"x": x, "ref": ref}
        try:
            row["sim"] = simulate_cycle(x)
        except EngineError as e:
            row["sim_error"] = type(e).__name__
        try:
            cf = closed_form_cycle(x)
            row["cf"], row["cf_est"] = cf, closed_form_errors(x, cf)
        except EngineError as e:
            row["cf_error"] = type(e).__name__
        out.append(row)
    return out


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    """One dict per (model, rung, output): the claim, its kind, the share exceeded."""
    runs = measure(n, seed)
    skipped = sum(1 for r in runs if "skip" in r)
    table = []
    for field, name in (*OUTPUTS, ("release_velocity", "half_coupling_release_speed")):
        exceeded, worst, count, no_claim = 0, 0.0, 0, 0
        for r in runs:
            if "sim" not in r:
                continue
            est = _SIMULATION_ERROR
            if field == "release_velocity":
                est = max(est, simulation_release_velocity_error(r["x"], r["sim"]))
                if not math.isfinite(est):
                    no_claim += 1
                    continue
            err = _rel(_value(r["sim"], field), _value(r["ref"], field))
            count += 1
            exceeded += err > est
            worst = max(worst, err / est)
        stated = f"{_SIMULATION_ERROR:g} relative"
        if field == "release_velocity":
            stated = "N·(2π/200)⁵/120·δv_qs/|v| per design, at least " + stated
        table.append(
            {
                "model": MODEL, "rung": "simulation", "output": name, "stated": stated,
                "kind": "bound", "n": count, "exceeded": exceeded, "worst_ratio": worst,
                "reference": REFERENCE_TEXT, "skipped": skipped, "no_claim": no_claim,
            }
        )  # fmt: skip
    for field, name in OUTPUTS:
        groups = _groups(name)
        exceeded, worst, count, no_claim = 0, 0.0, 0, 0
        for r in runs:
            if "cf" not in r:
                continue
            parts = [float(r["cf_est"][g]) for g in groups]
            est = max(parts) if all(math.isfinite(e) for e in parts) else math.nan
            if not math.isfinite(est):
                no_claim += 1
                continue
            err = _rel(_value(r["cf"], field), _value(r["ref"], field))
            count += 1
            exceeded += err > est
            worst = max(worst, err / est)
        table.append(
            {
                "model": MODEL, "rung": "closed_form", "output": name,
                "stated": f"estimate per design ({', '.join(groups)})",
                "kind": "bound", "n": count,
                "exceeded": exceeded, "worst_ratio": worst, "reference": REFERENCE_TEXT,
                "skipped": skipped, "no_claim": no_claim,
            }
        )  # fmt: skip
    return table


if __name__ == "__main__":
    for row in rows(int(sys.argv[1]) if len(sys.argv) > 1 else 200):
        print(
            f"{row['rung']:12s} {row['output']:28s} {row['kind']:8s} n={row['n']:4d} "
            f"exceeded={row['exceeded']:4d} worst={row['worst_ratio']:.3g} "
            f"skipped={row['skipped']} no_claim={row.get('no_claim', 0)}"
        )
