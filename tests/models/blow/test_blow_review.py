"""blow.joint against the independent review's items (issue 29), each held by a derivation
written out here: the energy fraction's denominator, the free struck side, the blows
against time."""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models.blow import BLOW, ENERGY_M16
from tests.pins import pin


def test_joint_energy_fraction_is_the_work_over_the_tools_energy_and_may_exceed_one() -> None:
    # ENERGY_M16 on the energy rung: E = 6 J, N = 5 N·m, C = 2e4 N·m/rad, T0 = 30 N·m,
    # b = 1.1. The balance E + N·φ_t = Tp²/2C + (Tp² − T0²)/2k_j with
    # φ_t = Tp/C + (Tp − T0)/k_j, solved for Tp by hand; the work into the joint
    # W = (Tp² − T0²)/2k_j exceeds E by N·φ_t − Tp²/2C: the drive's work is not in E.
    r = run(BLOW, ENERGY_M16, fidelity="energy")
    k = float(r.results["joint_rate_used"])  # type: ignore[arg-type]
    e, n, c, t0 = 6.0, 5.0, 2e4, 30.0
    a = 0.5 * (1.0 / c + 1.0 / k)
    tp = n + math.sqrt(n * n + (e + t0 * t0 / (2 * k) - n * t0 / k) / a)
    assert tp > 1.1 * t0  # the nut breaks away: no held blow
    work = (tp * tp - t0 * t0) / (2 * k)
    phi = tp / c + (tp - t0) / k
    pin(
        "blow.joint",
        "joint_energy_fraction",
        r.results["joint_energy_fraction"],
        work / e,
        rel=1e-12,
    )
    assert work / e == pytest.approx(1.0 + (n * phi - tp * tp / (2 * c)) / e, rel=1e-12)
    assert float(r.results["joint_energy_fraction"]) > 1.0  # type: ignore[arg-type]
    assert any("not in the tool's energy E" in note for note in r.notes)
    label = next(o.description for o in BLOW.outputs if o.name == "joint_energy_fraction")
    assert "not in E" in label and "exceed 1" in label
