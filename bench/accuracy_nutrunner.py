"""nutrunner.drive's error estimates against independent references (issue 29, "estimates
that bound").

* ``closed_form`` (the source's: one torque M on shaft 7 and spindle 8) states, per design,
  the largest relative change the gear ratio u = D4/D5 makes; the reference is the geared
  energy balance M = √(2T/(u²/C7 + 1/C8)) written out here from [000, eq. 3–9]
  (T = (1/16) Σ m_k D_k² ω_k², C = πGd⁴/(32 l)).
* ``gear_ratio`` states float rounding (1e-12) against the same reference.
* ``motor_curve`` (a linear torque–speed line) states the quadrature's error estimate; the
  reference is the line's closed-form spin-up time t = J ω0/M_s ln(ω0/(ω0 − ω)).

``rows(n, seed)`` draws ``n`` designs uniformly: power and speed in their recommended
ranges (250 W…30 kW, 50…320 rad/s), z in 4…12, G in 75…83 GPa, the masses and diameters
within ×0.5…×2 of the light-truck example (the declared ranges run to 1000 kg and 2 m, which
no drive of the source's kind reaches), M_tr in 0…20 N·m.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from engine import run
from engine.core.errors import EngineError
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE

SCALED = (
    "coupling_mass",
    "coupling_diameter",
    "motor_pulley_mass",
    "motor_pulley_diameter",
    "flywheel_mass",
    "flywheel_diameter",
    "drive_gear_mass",
    "drive_gear_diameter",
    "spindle_gear_mass",
    "spindle_gear_diameter",
    "shaft_diameter",
    "shaft_length",
    "spindle_diameter",
    "spindle_length",
)
#: The references' own rounding (relative): the allowance on each comparison.
REFERENCE_ROUNDING = 1e-14


def _design(rng: np.random.Generator) -> dict[str, Any]:
    x = {k: EXAMPLE_LIGHT_TRUCK[k] * float(rng.uniform(0.5, 2.0)) for k in SCALED}
    x.update(
        motor_power=float(rng.uniform(250.0, 3e4)),
        motor_speed=float(rng.uniform(50.0, 320.0)),
        spindle_count=int(rng.integers(4, 13)),
        shear_modulus=float(rng.uniform(75e9, 83e9)),
        idle_spindle_friction_torque=float(rng.uniform(0.0, 20.0)),
    )
    return x


def geared_torque(x: dict[str, Any]) -> tuple[float, float]:
    """(M on spindle 8, u·M on shaft 7) of the energy balance with the gear ratio."""
    w1 = x["motor_speed"]
    w3 = w1 * x["motor_pulley_diameter"] / x["flywheel_diameter"]
    u = x["drive_gear_diameter"] / x["spindle_gear_diameter"]
    w5 = w3 * u
    t = (
        x["coupling_mass"] * x["coupling_diameter"] ** 2 * w1**2
        + x["motor_pulley_mass"] * x["motor_pulley_diameter"] ** 2 * w1**2
        + x["flywheel_mass"] * x["flywheel_diameter"] ** 2 * w3**2
        + x["drive_gear_mass"] * x["drive_gear_diameter"] ** 2 * w3**2
        + x["spindle_count"] * x["spindle_gear_mass"] * x["spindle_gear_diameter"] ** 2 * w5**2
    ) / 16
    g = x["shear_modulus"]
    c7 = math.pi * g * x["shaft_diameter"] ** 4 / (32 * x["shaft_length"])
    c8 = math.pi * g * x["spindle_diameter"] ** 4 / (32 * x["spindle_length"])
    m = math.sqrt(2 * t / (u**2 / c7 + 1 / c8))
    return m, u * m


def _row(
    rung: str, output: str, stated: str, ratios: list[float], skipped: int, ref: str
) -> dict[str, Any]:
    r = np.array(ratios)
    return {
        "model": "nutrunner.drive",
        "rung": rung,
        "output": output,
        "stated": stated,
        "kind": "bound",
        "n": int(r.size),
        "skipped": skipped,
        "exceeded": int(np.sum(r > 1.0)),
        "worst_ratio": float(r.max()) if r.size else 0.0,
        "reference": ref,
    }


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    rng = np.random.default_rng(seed)
    found: dict[tuple[str, str], list[float]] = {}
    skipped = {"closed_form": 0, "gear_ratio": 0, "motor_curve": 0}
    for _ in range(n):
        x = _design(rng)
        m, m7 = geared_torque(x)
        friction = (x["spindle_count"] - 1) * x["idle_spindle_friction_torque"]
        refs = {"impact_torque": m, "shaft_torque": m7, "max_spindle_torque": m - friction}
        for rung in ("closed_form", "gear_ratio"):
            try:
                r = run(NUTRUNNER_DRIVE, x, fidelity=rung)
            except EngineError:
                skipped[rung] += 1
                continue
            est = float(r.error_estimate or 0.0)
            for name, ref in refs.items():
                if name == "max_spindle_torque" and min(ref, r.results[name]) <= 0.0:
                    continue  # the estimate covers M_max while both stay positive
                err = abs(r.results[name] - ref) / abs(ref)
                found.setdefault((rung, name), []).append(err / (est + REFERENCE_ROUNDING))
        # the motor_curve rung on a linear curve: stall at 2…6× the rated torque P/ω,
        # no-load speed 1.05…1.5 ω
        stall = x["motor_power"] / x["motor_speed"] * float(rng.uniform(2.0, 6.0))
        w0 = x["motor_speed"] * float(rng.uniform(1.05, 1.5))
        curve = {"motor_curve": "linear", "stall_torque": stall, "no_load_speed": w0}
        try:
            r = run(NUTRUNNER_DRIVE, {**x, **curve}, fidelity="motor_curve")
        except EngineError:
            skipped["motor_curve"] += 1
            continue
        w = x["motor_speed"]
        t_ref = r.results["drive_inertia"] * w0 / stall * math.log(w0 / (w0 - w))
        err = abs(r.results["acceleration_time"] - t_ref) / t_ref
        est = float(r.error_estimate or 0.0)
        found.setdefault(("motor_curve", "acceleration_time"), []).append(
            err / (est + REFERENCE_ROUNDING)
        )
    energy = (
        "the geared energy balance M = √(2T/(u²/C7 + 1/C8)) of [000, eq. 3–9] written out "
        f"apart from the engine (float rounding, allowance {REFERENCE_ROUNDING:g} relative, "
        ">= 100x below the stated estimates)"
    )
    out = []
    for (rung, name), ratios in found.items():
        if rung == "closed_form":
            stated, ref = "estimate per design: the gear ratio's largest relative change", energy
        elif rung == "gear_ratio":
            stated, ref = "1e-12 (float rounding of the closed forms)", energy
        else:
            stated = "the quadrature's error estimate per design (at least 1e-15)"
            ref = (
                "the linear curve's closed form t = J ω0/M_s ln(ω0/(ω0 − ω)) with the model's "
                f"J (float rounding, allowance {REFERENCE_ROUNDING:g} relative)"
            )
        out.append(_row(rung, name, stated, ratios, skipped[rung], ref))
    return out


if __name__ == "__main__":
    for row in rows():
        print(row)
