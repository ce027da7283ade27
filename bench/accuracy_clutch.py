"""Do the ball clutch's stated error estimates bound its errors? (issue 29, "Estimates that bound").

``rows(n, seed)`` draws ``n`` designs of ``clutch.ball`` and ``clutch.ball_setting`` and
returns one row per (model, rung, output): the stated claim, ``bound`` or ``typical``,
how many designs exceed it and the worst ratio of error to estimate.
``python bench/accuracy_clutch.py`` prints them.

The claim. Both models have one rung, ``closed_form``; its estimate is the relative shift
of the result that a flank friction within a band would cause: f' in [0, 0.1] when f = 0
(the paper's frictionless case) is assumed, f' in [f − 0.03, f + 0.03] (not below 0) when
f is given. The closed form solves its model exactly, so what the estimate has to cover is
the friction the user does not know, and, for the peak torque, the 81-point lift grid.

Designs: every input the claim depends on uniform in its declared range (ball circle,
ball count, ball diameter, groove angle, load factor, flank friction, wire, coil diameter,
coils, setting, shear modulus, ball lift or none, driving groove angle or none, both
constructions, both arrangements), a helical spring of custom wire (a disc stack's or a
tabulated wire's force is the same for every friction, so the claim does not depend on
it). The flank friction is 0 (its default, where the estimate takes another band) in
every second design. A design the model refuses (no coil, balls that wedge) is drawn again;
one whose estimate is None (the shifted friction locks a flank: no claim) is counted apart.

Reference: written here without the engine's functions: the spring force G d⁴ (Δ + z)/(8
D³ n); the push F_a/F_t from the ball's equilibrium under the tilted flank reactions (one
flank, the larger of the two for a free ball, a 2×2 linear solve for two flanks under a
pressure disc); the torque s D0 F/(2 p). The peak over the lift on 20 001 contact angles
over the rim (the engine takes 41): its grid error is (41/20 001)² ≈ 4e-6 of the engine's,
and the algebra is exact to rounding (1e-13), far more than 100× inside the estimates
(0.02 and up). Each result is compared with the reference at 11 frictions across the band
(both ends included; the torque is monotone in f, so the ends are the extremes). A design
is exceeded when max |result − reference| / |result| > estimate (1 + 1e-9).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import engine
from engine.core.errors import EngineError
from engine.models.clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING

BAND_POINTS = 11
RIM_POINTS = 20_001
TIE = 1e-9
STATED = (
    "estimate per design: the shift of a flank friction in [0, 0.1] when f = 0, "
    "in f ± 0.03 when f is given (relative)"
)
REFERENCE = (
    "ball equilibrium under tilted flank reactions, spring force by hand, peak on 20 001 "
    "rim angles (engine 41), 11 frictions across the band; its own error <= 1e-8 relative "
    "(grid), the smallest estimate {smallest:.2g}: >= {factor:.0e}x tighter"
)
#: (model, output) measured.
OUTPUTS = (
    ("clutch.ball", "torque_limit"),
    ("clutch.ball", "peak_torque"),
    ("clutch.ball_setting", "required_spring_force"),
)


def _uniform(rng: np.random.Generator, name: str, spec: Any = BALL_CLUTCH) -> float:
    p = spec.param(name)
    lo, hi = float(p.minimum), float(p.maximum)
    value = float(rng.uniform(lo, hi))
    while (p.exclusive_minimum and value <= lo) or (p.exclusive_maximum and value >= hi):
        value = float(rng.uniform(lo, hi))
    return value


def draw(rng: np.random.Generator, i: int) -> dict[str, Any]:
    """One design of clutch.ball, uniform in the declared ranges (see the module's text)."""
    x: dict[str, Any] = {
        name: _uniform(rng, name)
        for name in (
            "ball_circle_diameter",
            "ball_diameter",
            "groove_angle",
            "load_factor",
            "spring_wire_diameter",
            "spring_mean_diameter",
            "spring_active_coils",
            "spring_deflection",
            "shear_modulus",
        )
    }
    x["ball_count"] = int(rng.integers(1, 101))
    x["flank_friction"] = 0.0 if i % 2 == 0 else _uniform(rng, "flank_friction")
    x["spring_arrangement"] = str(rng.choice(["common", "per_ball"]))
    x["flank_construction"] = str(rng.choice(["free_ball", "pressure_disc"]))
    if rng.random() < 2 / 3:
        x["driving_groove_angle"] = _uniform(rng, "driving_groove_angle")
    if rng.random() < 1 / 2:
        x["ball_lift"] = _uniform(rng, "ball_lift")
    return x


def band(f: float) -> np.ndarray:
    """The frictions the estimate covers for a design given ``f``."""
    lo, hi = (0.0, 0.1) if f == 0.0 else (max(f - 0.03, 0.0), f + 0.03)
    return np.linspace(lo, hi, BAND_POINTS)


def push(beta: Any, f: float, x: Mapping[str, Any]) -> Any:
    """F_a / F_t of the ball at driven-flank contact angle ``beta``, by its equilibrium.

    A flank's reaction on a ball sliding up it points at β − ρ above the tangential
    direction: F_t = R cos(β − ρ), F_a = R sin(β − ρ). Two flanks under a pressure disc:
    R′ cos(α′ − ρ) = R″ cos(β − ρ) (tangential balance of the ball between them) and
    F_a = R′ sin(α′ − ρ) + R″ sin(β − ρ) with F_t = R″ cos(β − ρ) the driven one's.
    A free ball slides on one flank only: the one that lets it go at the lower torque.
    """
    rho = math.atan(f)
    beta = np.asarray(beta, float)
    one = np.sin(beta - rho) / np.cos(beta - rho)
    a1 = x.get("driving_groove_angle")
    if a1 is None:
        return one
    other = math.sin(a1 - rho) / math.cos(a1 - rho)
    if x["flank_construction"] == "free_ball":
        return np.maximum(one, other)
    # the 2x2 balance, unit driven reaction R'' = 1: R' from the tangential row
    r1 = np.cos(beta - rho) / math.cos(a1 - rho)
    fa = r1 * math.sin(a1 - rho) + np.sin(beta - rho)
    return fa / np.cos(beta - rho)


def _sharing(x: Mapping[str, Any]) -> float:
    return 1.0 if x["spring_arrangement"] == "common" else x["load_factor"] * x["ball_count"]


def _rate(x: Mapping[str, Any]) -> float:
    g, d, dm, n = (
        x["shear_modulus"],
        x["spring_wire_diameter"],
        x["spring_mean_diameter"],
        x["spring_active_coils"],
    )
    return g * d**4 / (8.0 * dm**3 * n)


def reference(x: Mapping[str, Any], f: float) -> dict[str, float]:
    """torque_limit and peak_torque of clutch.ball, required_spring_force per N·m target."""
    c, s, d0 = _rate(x), _sharing(x), x["ball_circle_diameter"]
    a2, a1 = x["groove_angle"], x.get("driving_groove_angle")
    ride = a2 if a1 is None or x["flank_construction"] == "pressure_disc" else max(a1, a2)
    delta = x["spring_deflection"]
    h = x.get("ball_lift", delta)
    p0 = float(push(ride if x["flank_construction"] == "free_ball" else a2, f, x))
    # over the rim: the contact angle from the riding flank's to 90°; the flank's top is
    # its first point (the force rises along the flank, the push is constant there)
    beta = np.linspace(ride, math.pi / 2.0, RIM_POINTS)
    lift = h + x["ball_diameter"] / 2.0 * (np.sin(beta) - math.sin(ride))
    with np.errstate(all="ignore"):
        torque = s * d0 * c * (delta + lift) / (2.0 * push(beta, f, x))
        flank_start = s * d0 * c * delta / (2.0 * p0)
    peak = float(np.max(np.concatenate([[flank_start], torque])))
    return {
        "torque_limit": s * d0 * c * delta / (2.0 * p0),
        "peak_torque": peak,
        "required_spring_force": 2.0 * p0 / (d0 * s),  # per N·m of target
    }


def _claims(x: dict[str, Any]) -> tuple[float | None, dict[str, Any]]:
    """The rung's estimate and the engine's results for one design (raises if refused)."""
    r = engine.run(BALL_CLUTCH, x, fidelity="closed_form")
    target = 1.0
    setting = engine.run(
        BALL_CLUTCH_SETTING,
        {k: v for k, v in x.items() if k != "spring_deflection"} | {"target_torque": target},
        fidelity="closed_form",
    )
    force = setting.results["required_spring_force"]
    got = {
        "torque_limit": r.results["torque_limit"],
        "peak_torque": r.results["peak_torque"],
        "required_spring_force": None if force is None else float(force) / target,
    }
    return r.error_estimate, got


def measure(n: int = 200, seed: int = 0) -> dict[str, Any]:
    """Per output: ratios error/estimate over ``n`` designs with a claim; counts of the rest."""
    rng = np.random.default_rng(seed)
    ratios: dict[str, list[float]] = {name: [] for _, name in OUTPUTS}
    estimates: list[float] = []
    refused = no_claim = ref_failed = i = 0
    while len(ratios["torque_limit"]) < n:
        x = draw(rng, i)
        i += 1
        try:
            estimate, got = _claims(x)
        except EngineError:
            refused += 1
            continue
        if estimate is None or any(v is None or not math.isfinite(v) for v in got.values()):
            no_claim += 1
            continue
        refs = [reference(x, float(fb)) for fb in band(x["flank_friction"])]
        if not all(math.isfinite(v) and v > 0 for ref in refs for v in ref.values()):
            ref_failed += 1
            continue
        estimates.append(estimate)
        for _, name in OUTPUTS:
            err = max(abs(got[name] - ref[name]) for ref in refs) / abs(got[name])
            ratios[name].append(err / estimate)
    return {
        "ratios": ratios,
        "refused": refused,
        "no_claim": no_claim,
        "skipped": ref_failed,
        "smallest": min(estimates) if estimates else math.nan,
    }


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    """One row per (model, rung, output), in the shared accuracy convention."""
    m = measure(n, seed)
    out = []
    for model, name in OUTPUTS:
        r = np.asarray(m["ratios"][name])
        declared = engine.get_model(model).rung("closed_form")
        out.append(
            {
                "model": model,
                "rung": "closed_form",
                "output": name,
                "stated": STATED,
                "kind": getattr(declared, "estimate_kind", "bound"),
                "n": int(r.size),
                "exceeded": int(np.sum(r > 1.0 + TIE)),
                "worst_ratio": float(np.max(r)) if r.size else None,
                "reference": REFERENCE.format(smallest=m["smallest"], factor=m["smallest"] / 1e-8)
                + f"; {m['refused']} refused designs redrawn, {m['no_claim']} without a claim",
                "skipped": m["skipped"],
            }
        )
    return out


if __name__ == "__main__":
    for row in rows():
        print(
            f"{row['model']:22} {row['output']:22} {row['kind']:8} n={row['n']:4} "
            f"exceeded={row['exceeded']:4} worst={row['worst_ratio']:.4g}  "
            f"skipped={row['skipped']}"
        )
