"""A fitted bolt carrying the transverse load in shear and bearing (VDI 2230-1 R12), by hand.

The first example (M12 8.8, 2 × 20 mm steel, F_Q = 2 kN on one interface) with a 13 mm fitted
shank: τ_Q = F_Q/(q_F π d_τ²/4), S_A = 0.6 R_m/τ_Q with R_m = 800 MPa (ISO 898-1, 8.8, d ≤ 16),
p_Q = F_Q/(d_τ h_min) on a 20 mm plate.
"""

import math

import pytest

from engine import run, sweep
from engine.models import get_model
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
FITTED = {**JOINT.examples[0], "fitted_diameter": 0.013}


def test_shear_and_bearing_by_hand():
    got = run(JOINT, FITTED)
    tau = 2e3 / (1 * math.pi / 4 * 0.013**2)  # 15.07 MPa
    pin("joint.vdi2230", "fitted_shear_stress", got.results["fitted_shear_stress"], tau, rel=1e-12)
    s_a = 0.6 * 800e6 / tau  # 31.86
    pin("joint.vdi2230", "fitted_shear_safety", got.results["fitted_shear_safety"], s_a, rel=1e-12)
    p_q = 2e3 / (0.013 * 0.020)  # 7.69 MPa
    pin(
        "joint.vdi2230",
        "fitted_bearing_pressure",
        got.results["fitted_bearing_pressure"],
        p_q,
        rel=1e-12,
    )
    checks = {c.name: c.ok for c in got.checks}
    assert checks["R12_fitted_shear"] is True


def test_double_shear_halves_the_stress_and_a_thin_plate_raises_the_bearing():
    got = run(
        JOINT, {**FITTED, "slip_interfaces": 2, "plate2_thickness": 0.005, "transverse_load": 40e3}
    ).results
    assert got["fitted_shear_stress"] == pytest.approx(
        40e3 / (2 * math.pi / 4 * 0.013**2), rel=1e-12
    )
    assert got["fitted_bearing_pressure"] == pytest.approx(40e3 / (0.013 * 0.005), rel=1e-12)


def test_without_a_fitted_shank_nothing_is_said():
    got = run(JOINT, JOINT.examples[0])
    assert not [k for k in got.results if k.startswith("fitted_")]
    assert "R12_fitted_shear" not in {c.name for c in got.checks}


def test_a_sweep_over_the_fitted_diameter_runs_the_same_lines():
    values = [0.012, 0.013, 0.016]
    many = sweep(JOINT, FITTED, "fitted_diameter", values)
    for i, d in enumerate(values):
        one = run(JOINT, {**FITTED, "fitted_diameter": d}).results
        got = float(many.columns["fitted_shear_safety"][i])
        assert got == pytest.approx(one["fitted_shear_safety"], rel=1e-12)
