"""Validation of nutrunner.drive against its source, [000] (docs/sources.md).

Source: "Parameters of the drive of a multi-spindle nut-runner" ([000] in docs/sources.md,
Ukrainian). The paper derives eq. 1–10 symbolically and prints no worked
numbers, so there is no published case to reproduce. What can be validated is
each equation as the paper states it (where legible) or as docs/sources.md
reconstructs it (eq. 3–5, 7–8), on hand-computed numbers, plus the one
numeric case the shared style guide quotes for eq. 7–8.
"""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models.nutrunner import EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE
from engine.physics.nutrunner import (
    STEEL_SHEAR_MODULUS,
    impact_torque,
    max_spindle_torque,
    torsional_stiffness,
    twist_angle,
)


def test_eq9_stiffness_with_the_papers_steel():
    """[000, eq. 9] C = πGd⁴/(32 l), G = 8·10¹⁰ Pa (stated after eq. 9)."""
    assert STEEL_SHEAR_MODULUS == 8e10
    # d = 40 mm, l = 400 mm: π·8e10·2.56e-6/12.8 = 50 265.5 N·m/rad
    assert torsional_stiffness(8e10, 0.040, 0.400) == pytest.approx(50265.48, rel=1e-6)


def test_eq7_8_style_guide_case():
    """[000, eq. 7–8] M = √(2T C7 C8/(C7 + C8)); STYLE.md quotes 3077.3 N·m."""
    # 2·268.5·57446·25447/(57446 + 25447) = 9 469 961 → √ = 3077.3
    assert impact_torque(268.5, 57446.0, 25447.0) == pytest.approx(3077.3, abs=0.05)


def test_eq6_7_twist_stores_the_kinetic_energy():
    """[000, eq. 6–7]: φ = M/C and T = Mφ7/2 + Mφ8/2 close for the paper's own form."""
    t, c7, c8 = 268.5, 57446.0, 25447.0
    m = impact_torque(t, c7, c8)
    assert 0.5 * m * twist_angle(m, c7) + 0.5 * m * twist_angle(m, c8) == pytest.approx(t)


def test_eq10_friction_of_idle_spindles():
    """[000, eq. 10] M_max = M − (z − 1) M_tr: 3077.3 − 7·15 = 2972.3 N·m for z = 8."""
    assert max_spindle_torque(3077.3, 8, 15.0) == pytest.approx(2972.3)


def test_eq5_reduces_as_models_md_says():
    """[000, eq. 3–5] as reconstructed: all speed ratios 1 give t = ω²/(16P)·Σ m_k D_k² (z·m5)."""
    x = {
        **EXAMPLE_LIGHT_TRUCK,
        "motor_pulley_diameter": 0.2,
        "flywheel_diameter": 0.2,
        "drive_gear_diameter": 0.07,
        "spindle_gear_diameter": 0.07,
    }
    w, p = x["motor_speed"], x["motor_power"]
    # Σ m D² = 1.2·0.09² + 0.8·0.2² + 12·0.2² + 2.5·0.07² + 6·0.5·0.07²
    #       = 0.00972 + 0.032 + 0.48 + 0.01225 + 0.0147 = 0.54867 kg·m²
    s = 1.2 * 0.09**2 + 0.8 * 0.2**2 + 12 * 0.2**2 + 2.5 * 0.07**2 + 6 * 0.5 * 0.07**2
    assert s == pytest.approx(0.54867)
    r = run(NUTRUNNER_DRIVE, x)
    assert r.results["acceleration_time"] == pytest.approx(w**2 / (16 * p) * s, rel=1e-12)
    assert any("reconstructed" in n for n in r.notes)


def test_eq1_2_work_energy_theorem():
    """[000, eq. 1–2] T1 − T0 = P t with T0 = 0: the spin-up delivers exactly T."""
    v = run(NUTRUNNER_DRIVE, EXAMPLE_LIGHT_TRUCK).results
    assert v["acceleration_time"] * EXAMPLE_LIGHT_TRUCK["motor_power"] == pytest.approx(
        v["kinetic_energy"], rel=1e-14
    )
    assert v["kinetic_energy"] == pytest.approx(
        0.5 * v["equivalent_inertia"] * EXAMPLE_LIGHT_TRUCK["motor_speed"] ** 2, rel=1e-14
    )


def test_paper_form_vs_gear_ratio_is_reported():
    """[000] (docs/sources.md): the paper ignores u = D4/D5; the result says by how much."""
    r = run(NUTRUNNER_DRIVE, EXAMPLE_LIGHT_TRUCK)
    # u = 2: √((1/C7 + 1/C8)/(4/C7 + 1/C8)) − 1 = −16.58 %
    c7 = math.pi * 8e10 * 0.045**4 / 6.4
    c8 = math.pi * 8e10 * 0.032**4 / 9.6
    change = math.sqrt((1 / c7 + 1 / c8) / (4 / c7 + 1 / c8)) - 1
    assert r.results["gear_ratio_torque_change"] == pytest.approx(change, rel=1e-12)
    assert any("-16.58%" in n for n in r.notes)
