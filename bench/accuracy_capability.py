"""tool.capability's and friction.iso16047's error estimates against exact arithmetic;
joint.clamp_capability's tail probabilities against the same quadrature refined 16×.

Both models state an error of 0 ("exact arithmetic" of the standards' definitions): what
can be measured is that arithmetic, against the same definitions evaluated here in exact
rational numbers (:class:`fractions.Fraction`; one square root in floats at the end) and
compared at float rounding. ``rows(n, seed)`` draws ``n`` series each: tool capability
from 2…200 torque readings about a random nominal with a random tolerance; ISO 16047 from
2…30 tests of (T, T_th, F) on a random thread (d 3…40 mm, P 0.08…0.2 d, bearing diameter
1.2…2 d) with friction coefficients 0.04…0.3. The model form (normality behind Cm/Cmk and
the ppm; the standard's linear thread relation) is not measured here: its sources say it.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from engine import run
from engine.core.errors import EngineError
from engine.models import get_model
from engine.models.clamp import M12_JOINT
from engine.models.clamp import _law as clamp_law
from engine.models.clamp import _tool as clamp_tool
from engine.numerics import laws
from engine.physics import capability as cap
from engine.procedures.bolt import resolve_bolt

CAPABILITY = get_model("tool.capability")
ISO16047 = get_model("friction.iso16047")
#: The stated error 0 plus this, relative: float rounding of a few dozen operations.
ROUNDING = 1e-12
CAP_OUTPUTS = ("mean_torque", "torque_sd", "capability_index", "critical_capability_index")
ISO_OUTPUTS = (
    "torque_coefficient_mean",
    "thread_friction_mean",
    "bearing_friction_mean",
    "total_friction_mean",
)
_COS30 = math.cos(math.radians(30.0))


def _mean_sd(values: list[float]) -> tuple[float, float]:
    """Mean and s (n − 1) in exact rationals; the root taken last, in floats."""
    q = [Fraction(v) for v in values]
    mean = sum(q, Fraction(0)) / len(q)
    var = sum(((v - mean) ** 2 for v in q), Fraction(0)) / (len(q) - 1)
    return float(mean), math.sqrt(float(var))


def _capability_case(rng: np.random.Generator) -> tuple[dict[str, Any], dict[str, float]]:
    nominal = float(rng.uniform(1.0, 500.0))
    tol = float(rng.uniform(0.02, 0.25))
    n = int(rng.integers(2, 201))
    values = [float(v) for v in nominal * (1 + rng.normal(0.0, tol / 6, n))]
    mean, sd = _mean_sd(values)
    lo, hi = nominal * (1 - tol), nominal * (1 + tol)
    ref = {
        "mean_torque": mean,
        "torque_sd": sd,
        "capability_index": (hi - lo) / (6 * sd),
        "critical_capability_index": min(hi - mean, mean - lo) / (3 * sd),
    }
    x = {"torque_samples": values, "nominal_torque": nominal, "relative_tolerance": tol}
    return x, ref


def _iso_case(rng: np.random.Generator) -> tuple[dict[str, Any], dict[str, float]]:
    d = float(rng.uniform(0.003, 0.040))
    p = float(rng.uniform(0.08, 0.2)) * d
    d2 = d - 0.649519 * p
    db = float(rng.uniform(1.2, 2.0)) * d
    n = int(rng.integers(2, 31))
    forces = rng.uniform(0.2, 1.0, n) * 600e6 * math.pi / 4 * d * d
    mu_th, mu_b = rng.uniform(0.04, 0.3, n), rng.uniform(0.04, 0.3, n)
    t_th = forces * (p / (2 * math.pi) + d2 / (2 * _COS30) * mu_th)
    t = t_th + forces * db / 2 * mu_b
    tests = [(float(a), float(b), float(c)) for a, b, c in zip(t, t_th, forces, strict=True)]
    # the standard's definitions, each coefficient per test, averaged, in exact rationals
    pi, cos30 = Fraction(math.pi), Fraction(_COS30)
    per: dict[str, list[Fraction]] = {k: [] for k in ISO_OUTPUTS}
    for tt, tth, f in tests:
        tt_q, tth_q, f_q = Fraction(tt), Fraction(tth), Fraction(f)
        lead = Fraction(p) / (2 * pi)
        flank = Fraction(d2) / (2 * cos30)
        per["torque_coefficient_mean"].append(tt_q / (f_q * Fraction(d)))
        per["thread_friction_mean"].append((tth_q / f_q - lead) / flank)
        per["bearing_friction_mean"].append((tt_q - tth_q) / (f_q * Fraction(db) / 2))
        per["total_friction_mean"].append((tt_q / f_q - lead) / (flank + Fraction(db) / 2))
    ref = {k: float(sum(v, Fraction(0)) / len(v)) for k, v in per.items()}
    x = {
        "tightening_torques": [a for a, _, _ in tests],
        "thread_torques": [b for _, b, _ in tests],
        "clamp_forces": [c for _, _, c in tests],
        "thread_diameter": d,
        "thread_pitch": p,
        "pitch_diameter": d2,
        "bearing_diameter": db,
    }
    return x, ref


def _rows_of(
    model: Any, outputs: tuple[str, ...], case: Any, n: int, seed: int
) -> list[dict[str, Any]]:
    rng = np.random.default_rng(seed)
    errors: dict[str, list[float]] = {k: [] for k in outputs}
    skipped = 0
    for _ in range(n):
        x, ref = case(rng)
        try:
            got = run(model, x, outputs=outputs).results
        except EngineError:
            skipped += 1
            continue
        for k in outputs:
            errors[k].append(abs(float(got[k]) - ref[k]) / abs(ref[k]))  # type: ignore[arg-type]
    out = []
    for name, errs in errors.items():
        e = np.array(errs)
        out.append(
            {
                "model": model.name,
                "rung": "closed_form",
                "output": name,
                "stated": f"0 (exact arithmetic; compared at {ROUNDING:g} relative)",
                "kind": "bound",
                "n": int(e.size),
                "skipped": skipped,
                "exceeded": int(np.sum(e > ROUNDING)),
                "worst_ratio": float(np.max(e) / ROUNDING) if e.size else 0.0,
                "reference": "the standard's definitions in exact rational arithmetic "
                "(fractions.Fraction), the square root last in floats (error <= 1e-16)",
            }
        )
    return out


CLAMP = get_model("joint.clamp_capability")
#: The a-priori claim of joint.clamp_capability's rung on its ppm figures.
CLAMP_STATED = 0.1
#: Panels of the reference quadrature (each result refines to 128 at most, usually 16).
CLAMP_REFERENCE_PANELS = 256


def _clamp_case(rng: np.random.Generator) -> dict[str, Any]:
    """An M12 8.8 joint with a random tool and random friction laws of a lot."""
    x: dict[str, Any] = {**M12_JOINT, "nominal_torque": float(rng.uniform(40.0, 95.0))}
    # loads that raise F_M,min into the preload's range, for the lower tail
    x["working_load"] = float(rng.uniform(5e3, 50e3))
    x["transverse_load"] = float(rng.uniform(0.0, 6e3))
    tool = int(rng.integers(3))
    if tool == 0:
        x["torque_sd"] = 0.0
    elif tool == 1:
        x["capability_index"] = float(rng.uniform(0.8, 2.5))
    else:
        x["torque_sd"] = float(rng.uniform(0.005, 0.05)) * x["nominal_torque"]
    for which in ("thread", "bearing"):
        g = f"{which}_friction"
        kind = str(rng.choice(["uniform", "normal", "lognormal", "triangular"]))
        lo = float(rng.uniform(0.05, 0.12))
        hi = lo + float(rng.uniform(0.02, 0.1))
        x[f"{g}_law"] = kind
        if kind in ("uniform", "triangular"):
            x[f"{g}_low"], x[f"{g}_high"] = lo, hi
            x[f"{g}_mode"] = float(rng.uniform(lo, hi))
        else:
            x[f"{g}_mean"] = 0.5 * (lo + hi)
            x[f"{g}_sd"] = (hi - lo) / 6
    x["friction_correlation"] = float(rng.uniform(-0.9, 0.9))
    return x


def _clamp_reference(x: dict[str, Any], required: float) -> dict[str, float]:
    """The two tails on :data:`CLAMP_REFERENCE_PANELS` panels per axis."""
    mean_t, sd_t, _ = clamp_tool(x)
    torque = (
        laws.Law("fixed", mean=mean_t) if sd_t == 0 else laws.Law("normal", mean=mean_t, sd=sd_t)
    )
    rho = float(laws.copula_from_spearman(x["friction_correlation"]))
    scatter = cap.Scatter(torque, clamp_law(x, "thread"), clamp_law(x, "bearing"), rho)
    bolt, _ = resolve_bolt(x)
    joint = cap.ClampJoint(
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.diameter,
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        bolt.stress_diameter,
        bolt.stress_area,
        bolt.yield_strength,
        x["prevailing_torque"],
    )
    n = CLAMP_REFERENCE_PANELS
    return {
        "high_ppm": cap.utilisation_tail(joint, scatter, 0.9, True, n) * 1e6,
        "low_ppm": cap.preload_tail(joint, scatter, required, False, n) * 1e6,
    }


def clamp_rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    """joint.clamp_capability's ppm figures against the quadrature refined to 256 panels,
    on designs whose reference share is at least 1e-9 (0.001 ppm)."""
    rng = np.random.default_rng(seed)
    errors: dict[str, list[float]] = {"high_ppm": [], "low_ppm": []}
    own: dict[str, list[float]] = {"high_ppm": [], "low_ppm": []}
    beyond_own: dict[str, int] = {"high_ppm": 0, "low_ppm": 0}
    skipped = 0
    for _ in range(n):
        x = _clamp_case(rng)
        try:
            res = run(CLAMP, x)
        except EngineError:
            skipped += 1
            continue
        required = float(res.results["required_preload_min"])  # type: ignore[arg-type]
        ref = _clamp_reference(dict(res.inputs), required)
        for k, r in ref.items():
            if r >= 1e-3:
                errors[k].append(abs(float(res.results[k]) - r) / r)  # type: ignore[arg-type]
                own[k].append(float(res.results[f"{k}_error"]))  # type: ignore[arg-type]
                beyond_own[k] += errors[k][-1] > max(own[k][-1], 1e-12)
    out = []
    for name, errs in errors.items():
        e = np.array(errs)
        out.append(
            {
                "model": CLAMP.name,
                "rung": "quadrature",
                "output": name,
                "stated": f"{CLAMP_STATED:g} relative (each result states its own: here at most "
                f"{max(own[name], default=0.0):.1g})",
                "kind": "bound",
                "n": int(e.size),
                "skipped": skipped + (n - skipped - int(e.size)),
                "exceeded": int(np.sum(e > CLAMP_STATED)),
                "worst_ratio": float(np.max(e) / CLAMP_STATED) if e.size else 0.0,
                "reference": f"the same composite Gauss-Legendre rule on {CLAMP_REFERENCE_PANELS} "
                "panels per axis (16× those a result uses; designs with a share < 1e-9 skipped); "
                f"{beyond_own[name]} of {e.size} beyond the error their result stated",
            }
        )
    return out


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    return [
        *_rows_of(CAPABILITY, CAP_OUTPUTS, _capability_case, n, seed),
        *_rows_of(ISO16047, ISO_OUTPUTS, _iso_case, n, seed),
        *clamp_rows(n, seed),
    ]


if __name__ == "__main__":
    for row in rows():
        print(row)
