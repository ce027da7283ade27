"""joint.vdi2230 warns where the eccentric joint's interface c_T exceeds VDI 2230-1's G.

G = d_W + h_min for a through-bolted joint, G' = (1.5…2) d_W for a tapped one (VDI 2230-1
R0, eqs. 5.1/38-39 as the open implementations svortega/steelpy and h18340637145/vdi2230
reproduce them; docs/sources.md). Hand numbers: M12 hex head d_W = 16.63 mm (ISO 4014),
plates 20 and 15 mm, so G = 16.63 + 15 = 31.63 mm; tapped G' = 1.5 × 16.63 = 24.945 mm.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine import run
from engine.models.joint import VDI2230
from engine.physics import joint as jt

D_W = 16.63e-3
G_THROUGH = D_W + 15e-3  # 31.63 mm
G_TAPPED = 1.5 * D_W  # 24.945 mm
ECCENTRIC = {
    "thread_diameter": 0.012,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.015,
    "working_load": 10e3,
    "interface_width": 0.030,
    "bolt_offset": 0.003,
    "load_lever": 0.010,
    "opening_edge": 0.012,
}


def limit_warnings(extra: dict[str, object]) -> list[str]:
    r = run(VDI2230, {**ECCENTRIC, **extra}, budget_s=None)
    return [w for w in r.warnings if "exceeds VDI 2230-1's limit" in w]


def test_g_by_hand() -> None:
    assert jt.interface_limit(D_W, 15e-3, "through") == pytest.approx(31.63e-3, rel=1e-12)
    assert jt.interface_limit(D_W, 15e-3, "tapped") == pytest.approx(24.945e-3, rel=1e-12)
    both = jt.interface_limit(np.array([D_W, 24e-3]), np.array([15e-3, 10e-3]), "through")
    assert both == pytest.approx([31.63e-3, 34e-3], rel=1e-12)


def test_through_joint_warns_beyond_g_only() -> None:
    assert limit_warnings({"interface_length": G_THROUGH - 0.05e-3}) == []
    assert limit_warnings({"interface_length": G_THROUGH}) == []
    (said,) = limit_warnings({"interface_length": 0.0317})
    assert "c_T = 31.7 mm" in said
    assert "G = d_W + h_min = 16.63 + 15 = 31.63 mm" in said
    assert "not clamped" in said and "c_T ≤ 31.63 mm" in said


def test_the_thinnest_plate_sets_g() -> None:
    """With plates of 20 and 12 mm, h_min = 12: G = 28.63 mm, and 30 mm exceeds it."""
    (said,) = limit_warnings({"plate2_thickness": 0.012, "interface_length": 0.030})
    assert "16.63 + 12 = 28.63 mm" in said


def test_a_thin_middle_shim_does_not_set_g() -> None:
    """Plates 20, 2 (a shim) and 15 mm: h_min is the thinner outer plate, 15 mm, so
    G = 16.63 + 15 = 31.63 mm as without the shim (not 16.63 + 2 = 18.63 mm)."""
    shim = {"plate2_thickness": 0.002, "plate3_thickness": 0.015}
    assert limit_warnings({**shim, "interface_length": G_THROUGH}) == []
    (said,) = limit_warnings({**shim, "interface_length": 0.0317})
    assert "16.63 + 15 = 31.63 mm" in said


def test_tapped_joint_uses_one_and_a_half_d_w() -> None:
    assert limit_warnings({"joint_type": "tapped", "interface_length": G_TAPPED - 0.05e-3}) == []
    (said,) = limit_warnings({"joint_type": "tapped", "interface_length": 0.026})
    assert "G' = (1.5…2) d_W" in said
    assert f"c_T ≤ {G_TAPPED * 1e3:.4g} mm" in said
    assert f"…{2 * D_W * 1e3:.4g} mm" in said


def test_a_warning_not_a_refusal_and_the_numbers_stand() -> None:
    """Beyond G the joint still answers, with the numbers of the eccentric chain."""
    r = run(VDI2230, {**ECCENTRIC, "interface_length": 0.050}, budget_s=None)
    assert r.results["load_factor"] is not None
    assert any("exceeds VDI 2230-1's limit" in w for w in r.warnings)


def test_a_concentric_joint_has_no_interface_and_no_warning() -> None:
    r = run(
        VDI2230,
        {
            k: v
            for k, v in ECCENTRIC.items()
            if k in ("thread_diameter", "plate1_thickness", "plate2_thickness", "working_load")
        },
        budget_s=None,
    )
    assert not any("exceeds VDI 2230-1's limit" in w for w in r.warnings)
