"""Do blow.joint's stated error estimates bound its errors? (issue 29, "Estimates that bound").

``rows(n, seed)`` draws ``n`` blows and returns one row per (model, rung, output): the stated
claim, whether it is a ``bound`` or ``typical``, how many designs exceed it and the worst
ratio of error to estimate. ``python bench/accuracy_blow.py`` prints them.

Designs: the first blow of a tool on a joint, each number log-uniform in the box the model
is used in (tool energy 1–300 J, tool inertia 1e-3–0.1 kg·m², stiffness 2e3–1e5 N·m/rad,
struck inertia 1e-5–3e-3 kg·m², joint rate 30–3e4 N·m/rad), the breakaway factor uniform
in 1–3, the restitution in 0.14–1 (a quarter of the designs lossless, e = 1), the snug
torque uniform in 0–0.8 of the held blow's peak over b (a nut that turns). The declared
input ranges span up to 15 decades (energies to 1e6 J, rates to 1e9 N·m/rad): a uniform
draw over them is almost all budget stops, so the box is declared here.

Reference: the same two-mass model solved independently of the compiled kernel
(:func:`engine.physics.blow.simulate_blow_reference`: scipy's DOP853 at rtol 1e-12, one
solve per stick/slip phase with terminal events, the peak refined on the dense output),
10⁶ times tighter than the tightest claim checked (the simulation's 1e-6). A design whose
reference or simulation fails (SolverFailed, a budget) is skipped and counted.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from engine.core.errors import EngineError
from engine.models.blow import _DAMPED_SIMULATION_ERROR, _SIMULATION_ERROR
from engine.physics.blow import (
    BlowProblem,
    energy_blow,
    energy_blow_error,
    energy_peak_error,
    rigid_blow_torque,
    simulate_blow,
    simulate_blow_reference,
)

MODEL = "blow.joint"
REFERENCE_RTOL = 1e-12
_REFERENCE = (
    "the same two-mass model by scipy solve_ivp DOP853 at rtol 1e-12 (own right-hand side "
    "and events, peak refined on the dense output): >= 1e6x tighter than the claims"
)


def _draw(rng: np.random.Generator) -> tuple[BlowProblem, float, float]:
    """One blow: (problem, snug torque T0, energy E)."""

    def lu(a: float, b: float) -> float:
        return float(np.exp(rng.uniform(math.log(a), math.log(b))))

    e, jt, c, js = lu(1.0, 300.0), lu(1e-3, 0.1), lu(2e3, 1e5), lu(1e-5, 3e-3)
    k = lu(30.0, 3e4)
    b = float(rng.uniform(1.0, 3.0))
    rest = 1.0 if rng.random() < 0.25 else float(rng.uniform(0.14, 1.0))
    t0 = float(rng.uniform(0.0, 0.8)) * math.sqrt(2.0 * e * c) / b
    return BlowProblem(jt, js, c, math.sqrt(2.0 * e / jt), k, b, 0.0, rest), t0, e


def _reference(p: BlowProblem, t0: float) -> tuple[float, float]:
    """(joint torque after, peak torque) of the first blow by the independent solver."""
    peak, rotation, _ = simulate_blow_reference(p, t0, rtol=REFERENCE_RTOL)
    return t0 + p.rate * rotation, peak


class _Tally:
    """Exceeded count and worst ratio of one (rung, output) row."""

    def __init__(self, rung: str, output: str, stated: str, kind: str) -> None:
        self.rung, self.output, self.stated, self.kind = rung, output, stated, kind
        self.n = self.exceeded = self.skipped = 0
        self.worst = 0.0

    def add(self, error: float, estimate: float) -> None:
        if not (math.isfinite(estimate) and estimate > 0.0):
            self.skipped += 1
            return
        self.n += 1
        self.exceeded += error > estimate
        self.worst = max(self.worst, error / estimate)

    def row(self) -> dict[str, Any]:
        return {
            "model": MODEL,
            "rung": self.rung,
            "output": self.output,
            "stated": self.stated,
            "kind": self.kind,
            "n": self.n,
            "exceeded": self.exceeded,
            "worst_ratio": self.worst if self.n else None,
            "reference": _REFERENCE,
            "skipped": self.skipped,
        }


def _rel(a: float, ref: float) -> float:
    return abs(a - ref) / abs(ref)


def rows(n: int = 200, seed: int = 0) -> list[dict[str, Any]]:
    """One row per (rung, output) over ``n`` drawn blows (see the module's docstring)."""
    rng = np.random.default_rng(seed)
    per_design = "estimate per design"
    tallies = {
        ("rigid", "torque_after_first_blow"): _Tally(
            "rigid", "torque_after_first_blow", per_design, "typical"
        ),
        ("energy", "torque_after_first_blow"): _Tally(
            "energy", "torque_after_first_blow", per_design + " (energy_blow_error)", "typical"
        ),
        ("energy", "peak_torque"): _Tally(
            "energy", "peak_torque", per_design + " (+ the nut's kick)", "typical"
        ),
        ("simulation", "torque_after_first_blow"): _Tally(
            "simulation",
            "torque_after_first_blow",
            f"{_SIMULATION_ERROR:g} lossless, {_DAMPED_SIMULATION_ERROR:g} damped",
            "typical",
        ),
        ("simulation", "peak_torque"): _Tally(
            "simulation",
            "peak_torque",
            f"{_SIMULATION_ERROR:g} lossless, {_DAMPED_SIMULATION_ERROR:g} damped",
            "typical",
        ),
    }
    failed = 0
    for _ in range(n):
        p, t0, e = _draw(rng)
        try:
            sim = simulate_blow(p, t0, max_steps=20_000_000)
            ref = _reference(p, t0)
        except EngineError:
            failed += 1
            continue
        # the energy rung as blow.joint runs it (energy_blow) and its estimates
        e_peak, e_after, _, _ = energy_blow(e, p.stiffness, p.rate, t0, p.breakaway)
        est_after = energy_blow_error(
            p.tool_inertia, p.struck_inertia, p.stiffness, p.rate, p.restitution,
            p.breakaway, t0, e,
        )  # fmt: skip
        est_peak = est_after + float(energy_peak_error(p, e_peak))
        tallies["energy", "torque_after_first_blow"].add(_rel(e_after, ref[0]), est_after)
        tallies["energy", "peak_torque"].add(_rel(e_peak, ref[1]), est_peak)
        # the rigid rung: its torque against the energy rung's, plus the latter's error
        rigid = float(rigid_blow_torque(e, p.stiffness))
        est_rigid = abs(rigid - e_after) / e_after + max(est_after, est_peak)
        tallies["rigid", "torque_after_first_blow"].add(_rel(max(rigid, t0), ref[0]), est_rigid)
        claim = _SIMULATION_ERROR if p.restitution >= 1.0 else _DAMPED_SIMULATION_ERROR
        tallies["simulation", "torque_after_first_blow"].add(_rel(sim.torque_after, ref[0]), claim)
        tallies["simulation", "peak_torque"].add(_rel(sim.peak_torque, ref[1]), claim)
    out = [t.row() for t in tallies.values()]
    for row in out:
        row["skipped"] += failed
    return out


if __name__ == "__main__":
    for r in rows():
        worst = "-" if r["worst_ratio"] is None else f"{r['worst_ratio']:.3g}"
        print(
            f"{r['rung']:10} {r['output']:24} {r['kind']:8} n={r['n']:3} "
            f"exceeded={r['exceeded']:3} worst={worst:>8} skipped={r['skipped']}  {r['stated']}"
        )
