"""tool.capability's and friction.iso16047's error estimates against exact arithmetic.

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


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    return [
        *_rows_of(CAPABILITY, CAP_OUTPUTS, _capability_case, n, seed),
        *_rows_of(ISO16047, ISO_OUTPUTS, _iso_case, n, seed),
    ]


if __name__ == "__main__":
    for row in rows():
        print(row)
