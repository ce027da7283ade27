"""The joint model (joint.vdi2230) with bought fasteners: VDI 2230-1 R10 and R11 via the hook."""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models import get_model
from engine.models.preload import TIGHTENING

JOINT = get_model("joint.vdi2230")
ALU = "EN AW-6082 T6"
BASE = {
    "thread": "M8 ISO 4762 12.9",
    "joint_type": "tapped",
    "head": "socket",
    "plate1_thickness": 0.012,
    "plate1_youngs_modulus": 7e10,
    "nut_youngs_modulus": 7e10,
    "working_load": 4e3,
    "clamped_material": ALU,
    "internal_thread_material": ALU,
}


def _check(result, name):
    return next(c for c in result.checks if c.name == name)


def test_the_joint_takes_a_designation_and_checks_surface_pressure_at_both_forces():
    res = run(JOINT, {**BASE, "engagement_length": 0.012})
    assert res.results["smallest_area"] * 1e6 == pytest.approx(36.61, abs=0.01)
    area = math.pi / 4 * (12.33**2 - 9.0**2)
    assembly = _check(res, "surface_pressure_assembly")
    working = _check(res, "surface_pressure_working")
    assert not assembly.ok and not working.ok  # 12.9 on aluminium without a washer
    assert f"(now {area:.4g} mm²)" in assembly.detail
    assert "F_S,max" in working.detail
    washed = run(JOINT, {**BASE, "engagement_length": 0.012, "washer": "ISO 7093"})
    assert _check(washed, "surface_pressure_working").ok
    assert not any("not checked by this model yet" in n for n in res.notes)


def test_the_joint_fails_a_short_engagement_with_the_length_the_preload_model_gives():
    short = run(JOINT, {**BASE, "engagement_length": 0.008})
    check = _check(short, "thread_stripping")
    need = run(TIGHTENING, {"thread": "M8 ISO 4762 12.9", "internal_thread_material": ALU})
    need_mm = need.results["min_engagement_length"] * 1e3
    assert not check.ok and f"{need_mm:.3g} mm needed" in check.detail
    # R11 at 1.2 R_m plus 2P of chamfers: 1.2 × 10.35 + 2.5 = 14.9 mm; 11 mm now falls short
    assert not _check(run(JOINT, {**BASE, "engagement_length": 0.011}), "thread_stripping").ok
    assert _check(run(JOINT, {**BASE, "engagement_length": 0.015}), "thread_stripping").ok


def test_the_hook_says_when_the_head_type_contradicts_the_designation():
    res = run(JOINT, {**BASE, "head": "hex"})
    assert any("set head = 'socket'" in n for n in res.notes)
    assert not any("set head" in n for n in run(JOINT, BASE).notes)


def test_a_torque_specification_is_checked_against_the_key():
    res = run(JOINT, {**BASE, "tightening_torque": 60.0})
    assert not _check(res, "drive_torque").ok  # 6 mm key: 52 N·m (ISO 2936)
