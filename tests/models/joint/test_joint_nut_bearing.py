"""R10 under the nut where the last plate is narrower than the nut's bearing face, by hand.

M12 ISO 4014 8.8 through 2 × 20 mm S235JR (p_G = 490 MPa, VDI 2230-1 Table A9) with an
ISO 4032 nut (d_W = 16.63 mm, d_h = 13.5 mm), tightened to F_M,zul. With plate 2 of
D_A,2 = 15 mm the nut bears on π/4 (15² − 13.5²) mm² = 33.58 mm² only: p = F_M,max/A_p
≈ 1,284 MPa (before: 582 MPa on the nut's full face).
"""

import math

import numpy as np

from engine import run
from engine.models import get_model
from engine.studies.plan import CHECK_FAILED, CHECK_OK, evaluate_chunk

JOINT = get_model("joint.vdi2230")
DESIGN = {
    "thread": "M12 ISO 4014 8.8",
    "nut": "ISO 4032",
    "clamped_material": "S235JR",
    "plate1_thickness": 0.02,
    "plate2_thickness": 0.02,
    "outer_diameter": 0.040,
    "working_load": 8000.0,
}


def _nut_check(result):
    return next(c for c in result.checks if c.name == "surface_pressure_nut")


def test_a_narrow_last_plate_carries_the_nut_on_its_face_by_hand():
    narrow = run(JOINT, {**DESIGN, "plate2_outer_diameter": 0.015})
    f_m_max = narrow.results["assembly_preload_max"]
    area = math.pi / 4.0 * (15.0**2 - 13.5**2)  # mm²
    p = f_m_max / area  # N/mm² = MPa
    assert round(p) == 1284
    check = _nut_check(narrow)
    assert not check.ok and f"{p:.4g} MPa" in check.detail and "33.58 mm²" in check.detail
    assert any("under the nut < its d_W = 16.63 mm" in w for w in narrow.warnings)


def test_a_wide_last_plate_keeps_the_nut_s_face():
    wide = run(JOINT, {**DESIGN, "plate2_outer_diameter": 0.040})
    area = math.pi / 4.0 * (16.63**2 - 13.5**2)
    p = wide.results["assembly_preload_max"] / area
    assert f"{p:.4g} MPa" in _nut_check(wide).detail
    assert not any("under the nut" in w for w in wide.warnings)


def test_the_array_path_gives_the_same_verdicts():
    """Limit p_G = 1,000 MPa: passes at D_A,2 = 16 mm (p ≈ 43.1 kN/57.9 mm² ≈ 745 MPa), fails
    at 15 mm (≈ 1,284 MPa); the array path agrees with single runs."""
    design = {k: v for k, v in DESIGN.items() if k != "clamped_material"}
    design["limiting_surface_pressure"] = 1e9
    values = np.array([0.015, 0.016, 0.040])
    singles = [_nut_check(run(JOINT, {**design, "plate2_outer_diameter": v})).ok for v in values]
    assert singles == [False, True, True]
    chunk = evaluate_chunk(
        JOINT, design, {"plate2_outer_diameter": values}, ["yield_safety"], fidelity="closed_form"
    )
    codes = chunk.checks["surface_pressure_nut"].tolist()
    assert codes == [CHECK_OK if ok else CHECK_FAILED for ok in singles]
