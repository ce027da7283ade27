"""joint.clamp_capability's tails against a 10⁸-point Monte Carlo reference.

Two M12 8.8 cases (joint.vdi2230's second example) whose share above F_M,zul lies
between 1e-6 and 1e-5: (A) a friction lot normal 0.12 ± 0.0133 in thread and bearing,
independent, and a tool at Cm 1.67 (±10 %) set to 61 N·m; (B) μ_G normal, μ_K lognormal
with the same mean and sd, rank correlation 0.5, a tool at Cm 1.0 set to 58 N·m. The
reference draws the torque and both frictions with numpy (the copula by hand: z_K =
ρ z_G + √(1 − ρ²) w), computes F_M and ν with VDI 2230-1 R13 and R7 typed here, not the
engine's, and counts ν > 0.9, in chunks of 2·10⁶. Its standard error is √(p(1 − p)/n).

    python -m bench.capability_tails [points]      # default 10⁸ per case, ~1-2 min each
"""

from __future__ import annotations

import math
import sys
import time
from typing import Any

import numpy as np

from engine import run
from engine.models.clamp import CLAMP_CAPABILITY, M12_JOINT

P, D = 1.75e-3, 12e-3
D2 = D - 0.649519 * P
DS = 0.5 * (D2 + D - 1.226869 * P)
AS = math.pi / 4 * DS**2
RP, DW, DH, M_U = 640e6, 16.63e-3, 13.5e-3, 0.4
CHUNK = 2_000_000

NORMAL_LOT = {
    **{f"{w}_friction_law": "normal" for w in ("thread", "bearing")},
    **{
        f"{w}_friction_{k}": v
        for w in ("thread", "bearing")
        for k, v in (("mean", 0.12), ("sd", 0.0133))
    },
}
CASES: dict[str, dict[str, Any]] = {
    "A normal lot, Cm 1.67, 61 N·m": {
        **M12_JOINT,
        **NORMAL_LOT,
        "nominal_torque": 61.0,
        "capability_index": 1.67,
    },
    "B μ_K lognormal, ρ_S 0.5, Cm 1.0, 58 N·m": {
        **M12_JOINT,
        **NORMAL_LOT,
        "bearing_friction_law": "lognormal",
        "friction_correlation": 0.5,
        "nominal_torque": 58.0,
        "capability_index": 1.0,
    },
}


def share_above(x: dict[str, Any], n: int, seed: int = 0) -> tuple[float, float]:
    """(p, standard error) of ν > 0.9 from ``n`` independent draws."""
    rng = np.random.default_rng(seed)
    sd_t = 2 * 0.1 * x["nominal_torque"] / (6 * x["capability_index"])
    rank = x.get("friction_correlation", 0.0)
    rho = 2 * math.sin(math.pi * rank / 6)
    cv2 = 1 + (0.0133 / 0.12) ** 2
    median, s_ln = 0.12 / math.sqrt(cv2), math.sqrt(math.log(cv2))
    hits = 0
    done = 0
    while done < n:
        m = min(CHUNK, n - done)
        t = x["nominal_torque"] + sd_t * rng.standard_normal(m)
        z_g = rng.standard_normal(m)
        z_k = rho * z_g + math.sqrt(1 - rho * rho) * rng.standard_normal(m)
        mu_g = 0.12 + 0.0133 * z_g
        if x.get("bearing_friction_law") == "lognormal":
            mu_k = median * np.exp(s_ln * z_k)
        else:
            mu_k = 0.12 + 0.0133 * z_k
        f = (t - M_U) / (0.16 * P + 0.58 * D2 * mu_g + mu_k * (DW + DH) / 4)
        ratio = 1.5 * D2 / DS * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30)))
        hits += int(np.count_nonzero(f * np.sqrt(1 + 3 * ratio**2) > 0.9 * RP * AS))
        done += m
    p = hits / n
    return p, math.sqrt(p * (1 - p) / n)


def main(n: int) -> list[dict[str, Any]]:
    rows = []
    for name, x in CASES.items():
        started = time.perf_counter()
        res = run(CLAMP_CAPABILITY, x).results
        model_s = time.perf_counter() - started
        started = time.perf_counter()
        p, se = share_above(x, n)
        mc_s = time.perf_counter() - started
        model = float(res["high_ppm"]) / 1e6  # type: ignore[arg-type]
        within = abs(model - p) <= 3 * se
        rows.append(
            {
                "case": name,
                "model_ppm": model * 1e6,
                "model_stated_error": res["high_ppm_error"],
                "model_s": model_s,
                "mc_ppm": p * 1e6,
                "mc_se_ppm": se * 1e6,
                "mc_points": n,
                "mc_s": mc_s,
                "z": (model - p) / se if se else math.inf,
                "within_3_se": within,
            }
        )
        r = rows[-1]
        print(
            f"{name}: model {r['model_ppm']:.4g} ppm (stated error {r['model_stated_error']:.1e}, "
            f"{model_s * 1e3:.0f} ms); Monte Carlo {r['mc_ppm']:.4g} ± {r['mc_se_ppm']:.2g} ppm "
            f"({n:.0e} points, {mc_s:.0f} s); z = {r['z']:+.2f}, "
            f"{'within' if within else 'OUTSIDE'} 3 SE"
        )
    return rows


def measure() -> list[dict[str, Any]]:
    """The rows ``make bench`` prints: both cases against a 10⁸-point reference each."""
    return [
        {
            "method": "joint.clamp_capability",
            "case": f"tail above F_M,zul, {r['case']}",
            "time_s": r["model_s"],
            "notes": (
                f"model {r['model_ppm']:.4g} ppm; Monte Carlo {r['mc_ppm']:.4g} ± "
                f"{r['mc_se_ppm']:.2g} ppm ({r['mc_points']:.0e} points, {r['mc_s']:.0f} s); "
                f"z = {r['z']:+.2f}, {'within' if r['within_3_se'] else 'OUTSIDE'} 3 SE"
            ),
        }
        for r in main(100_000_000)
    ]


if __name__ == "__main__":
    main(int(float(sys.argv[1])) if len(sys.argv) > 1 else 100_000_000)
