"""R9's endurance limit outside its fit (ISO 898-1 8.8–12.9, d ≤ 40 mm): a warning that names
the relation and the value used, for a large bolt and for the rolled-after-heat-treatment form.
"""

import pytest

from engine import run
from engine.models import get_model

JOINT = get_model("joint.vdi2230")
BASE = {"plate1_thickness": 0.050, "plate2_thickness": 0.050, "working_load": 50e3}
BASE["working_load_min"] = 0.0


def test_a_bolt_above_40_mm_is_warned_with_the_value_used():
    # ISO 261 M48 coarse, ISO 4017 d_w,min 69.5 mm, ISO 273 medium hole 52 mm
    bolt = {"thread_diameter": 0.048, "thread_pitch": 0.005, "property_class": "8.8"}
    bolt |= {"bearing_outer_diameter": 0.0695, "hole_diameter": 0.052}
    r = run(JOINT, {**BASE, **bolt})
    sigma = 0.85 * (150 / 48 + 45)  # 40.91 MPa, the fit carried past d = 40 mm
    assert r.results["endurance_limit"] == pytest.approx(sigma * 1e6, rel=1e-12)
    (said,) = [w for w in r.warnings if "outside its range" in w]
    assert "d = 48 mm > 40 mm" in said and f"{sigma:.4g} MPa" in said and "σ_ASV" in said


def test_rolled_after_heat_treatment_names_its_own_relation():
    r = run(
        JOINT,
        {
            **BASE,
            "thread": "M12 ISO 4017 A2-70",
            "rolling": "after_heat_treatment",
            "plate1_thickness": 0.02,
            "plate2_thickness": 0.02,
            "working_load": 5e3,
        },
    )
    (said,) = [w for w in r.warnings if "outside its range" in w]
    assert "σ_ASG" in said
    assert f"{r.results['endurance_limit'] / 1e6:.4g} MPa" in said


def test_inside_the_fit_nothing_is_said():
    r = run(JOINT, {**BASE, "thread": "M36 ISO 4017 10.9"})
    assert not [w for w in r.warnings if "outside its range" in w]


def test_a_typed_yield_strength_without_a_grade_leaves_the_class_unknown():
    # M12 by its numbers with R_p0.2 = 900 MPa typed: the default class "8.8" names nothing,
    # so σ_ASV's fit (8.8–12.9) cannot be said to hold
    bolt = {"thread_diameter": 0.012, "thread_pitch": 0.00175, "yield_strength": 900e6}
    r = run(JOINT, {**BASE, **bolt, "plate1_thickness": 0.02, "plate2_thickness": 0.02})
    (said,) = [w for w in r.warnings if "outside its range" in w]
    assert "property class is unknown" in said
    named = run(JOINT, {**BASE, "thread_diameter": 0.012, "thread_pitch": 0.00175})
    assert not [w for w in named.warnings if "outside its range" in w]
