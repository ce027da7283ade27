"""joint.audit's and preload.ultrasonic's error estimates against independent references.

Both models state an error of 0 against their relations. ``rows(n, seed)`` draws ``n``
designs each (ISO coarse threads M6…M24, two plates of 0.75…3 d each, friction boxes within
0.06…0.2, torque tolerances 0…10 %, static excess up to 1.4; for the ultrasonic model a
preload up to 0.7 R_p0.2 A_s, stress factor 0.2…0.4, a temperature change of ±10 K) and
compares:

- joint.audit's twelve window limits with a bounded scalar search (scipy's
  ``minimize_scalar``, xatol 1e-13 of the range) of the reading written out here,
  F = (M_A − M_ü)/(k_P + k_μ) − F_Z, M = F (±k_P + r k_μ) + M_ü, over k_μ for each corner
  of M_A and r, plus the ends of the range: a reference whose error in the value is of
  order (1e-13)², compared at 1e-9 relative;
- preload.ultrasonic's time of flight and the preload read back from it, with the chain
  Δt = 2 (F δ_S/S_F + τ L_U ΔT)/V in exact rationals on the model's own δ_S, compared at
  1e-12 relative.
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from typing import Any

import numpy as np
from scipy.optimize import minimize_scalar

from engine import run
from engine.core.errors import EngineError
from engine.models import get_model
from engine.procedures.bolt import resolve_bolt

AUDIT = get_model("joint.audit")
ULTRASONIC = get_model("preload.ultrasonic")
THREADS = ("M6", "M8", "M10", "M12", "M16", "M20", "M24")
AUDIT_TOL = 1e-9
ULTRASONIC_TOL = 1e-12
METHODS = {"first_motion": 1.0, "breakaway": -1.0, "mark": 1.0}


def _audit_case(rng: np.random.Generator) -> dict[str, Any]:
    thread = str(rng.choice(THREADS))
    d = float(thread[1:]) * 1e-3
    mu_lo = float(rng.uniform(0.06, 0.14))
    mu_hi = mu_lo + float(rng.uniform(0.0, 0.06))
    force = float(rng.uniform(0.3, 0.8)) * 0.6 * 640e6 * np.pi / 4 * (0.85 * d) ** 2
    return {
        "thread": thread,
        "plate1_thickness": float(rng.uniform(0.75, 3.0)) * d,
        "plate2_thickness": float(rng.uniform(0.75, 3.0)) * d,
        "tightening_torque": force * 0.17 * d,
        "torque_tolerance": float(rng.uniform(0.0, 0.1)),
        "thread_friction_min": mu_lo,
        "thread_friction_max": mu_hi,
        "bearing_friction_min": mu_lo,
        "bearing_friction_max": mu_hi,
        "static_friction_ratio_max": float(rng.uniform(1.0, 1.4)),
    }


def _reading(torque: float, k_p: float, k_mu: float, r: float, f_z: float, sign: float) -> float:
    preload = max(torque / (k_p + k_mu) - f_z, 0.0)
    return preload * (sign * k_p + r * k_mu)


def _interior(
    torque: float, k_p: float, box: tuple[float, float], r: float, loss: float, sign: float
) -> list[float]:
    """The reading at its least and most inside the friction box (bounded scalar search)."""

    def reading(k: float) -> float:
        return _reading(torque, k_p, k, r, loss, sign)

    found = []
    for s in (1.0, -1.0):
        best = minimize_scalar(
            lambda k, s=s: -s * reading(k),
            bounds=box,
            method="bounded",
            options={"xatol": 1e-13 * (box[1] - box[0])},
        )
        found.append(reading(float(best.x)))
    return found


def _audit_reference(x: dict[str, Any], f_z: float) -> dict[str, float]:
    bolt, _ = resolve_bolt(x)
    d2, pitch = bolt.pitch_diameter, bolt.pitch
    radius = (bolt.bearing_outer_diameter + bolt.hole_diameter) / 4
    k_p = 0.16 * pitch
    lo = 0.58 * d2 * x["thread_friction_min"] + x["bearing_friction_min"] * radius
    hi = 0.58 * d2 * x["thread_friction_max"] + x["bearing_friction_max"] * radius
    band = (
        x["tightening_torque"] * (1 - x["torque_tolerance"]),
        x["tightening_torque"] * (1 + x["torque_tolerance"]),
    )
    ref: dict[str, float] = {}
    for name, sign in METHODS.items():
        ratios = (1.0, 1.0) if name == "mark" else (1.0, x["static_friction_ratio_max"])
        for suffix, loss in (("", 0.0), ("_embedded", f_z)):
            values = []
            for torque, r in itertools.product(band, ratios):
                values += [_reading(torque, k_p, k, r, loss, sign) for k in (lo, hi)]
                if hi > lo:
                    values += _interior(torque, k_p, (lo, hi), r, loss, sign)
            ref[f"{name}{suffix}_min"] = min(values)
            ref[f"{name}{suffix}_max"] = max(values)
    return ref


def _ultrasonic_case(rng: np.random.Generator) -> dict[str, Any]:
    thread = str(rng.choice(THREADS))
    d = float(thread[1:]) * 1e-3
    return {
        "thread": thread,
        "plate1_thickness": float(rng.uniform(1.0, 4.0)) * d,
        "preload": float(rng.uniform(0.1, 0.7)) * 640e6 * np.pi / 4 * (0.85 * d) ** 2,
        "sound_velocity": float(rng.uniform(5700.0, 6100.0)),
        "stress_factor": float(rng.uniform(0.2, 0.4)),
        "temperature_factor": float(rng.uniform(50e-6, 150e-6)),
        "reading_temperature_change": float(rng.uniform(-10.0, 10.0)),
        "ultrasonic_length": float(rng.uniform(3.0, 8.0)) * d,
    }


def _row(
    model: str, output: str, errors: list[float], tol: float, skipped: int, ref: str
) -> dict[str, Any]:
    e = np.array(errors)
    return {
        "model": model,
        "rung": "closed_form",
        "output": output,
        "stated": f"0 (exact against its relations; compared at {tol:g} relative)",
        "kind": "bound",
        "n": int(e.size),
        "skipped": skipped,
        "exceeded": int(np.sum(e > tol)),
        "worst_ratio": float(np.max(e) / tol) if e.size else 0.0,
        "reference": ref,
    }


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    rng = np.random.default_rng(seed)
    names = [f"{m}{s}_{e}" for m in METHODS for s in ("", "_embedded") for e in ("min", "max")]
    errors: dict[str, list[float]] = {k: [] for k in names}
    skipped = 0
    for _ in range(n):
        x = _audit_case(rng)
        try:
            got = run(AUDIT, x).results
        except EngineError:
            skipped += 1
            continue
        ref = _audit_reference(x, float(got["embedding_loss"]))  # type: ignore[arg-type]
        for k in names:
            scale = max(abs(ref[k]), 1e-300)
            errors[k].append(abs(float(got[k]) - ref[k]) / scale)  # type: ignore[arg-type]
    out = [
        _row(
            AUDIT.name,
            k,
            v,
            AUDIT_TOL,
            skipped,
            "the reading written out, bounded scalar search over the friction box per corner "
            "(value error ~1e-26 relative)",
        )
        for k, v in errors.items()
    ]
    tof_err: list[float] = []
    back_err: list[float] = []
    skipped = 0
    for _ in range(n):
        x = _ultrasonic_case(rng)
        try:
            got = run(ULTRASONIC, x).results
        except EngineError:
            skipped += 1
            continue
        q = {k: Fraction(v) for k, v in x.items() if isinstance(v, float)}
        delta_s = Fraction(float(got["bolt_compliance"]))  # type: ignore[arg-type]
        change = q["preload"] * delta_s / q["stress_factor"]
        thermal = q["temperature_factor"] * q["ultrasonic_length"]
        thermal *= q["reading_temperature_change"]
        tof = float(2 * (change + thermal) / q["sound_velocity"])
        tof_err.append(abs(float(got["time_of_flight_change"]) - tof) / abs(tof))  # type: ignore[arg-type]
        back = {k: v for k, v in x.items() if k != "preload"}
        back["time_of_flight_change"] = tof
        force = run(ULTRASONIC, back).results["preload"]
        back_err.append(abs(float(force) - x["preload"]) / x["preload"])  # type: ignore[arg-type]
    chain = "the chain 2 (F δ_S/S_F + τ L_U ΔT)/V in exact rationals on the model's δ_S"
    out.append(
        _row(ULTRASONIC.name, "time_of_flight_change", tof_err, ULTRASONIC_TOL, skipped, chain)
    )
    out.append(_row(ULTRASONIC.name, "preload", back_err, ULTRASONIC_TOL, skipped, chain))
    return out
