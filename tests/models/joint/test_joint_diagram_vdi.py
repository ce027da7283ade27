"""The joint diagram's working point and separation as VDI 2230-1 §3.2 draws them.

At the working point F_A stands between the plates' line and the bolt's line: from
F_KR = F_V − (1 − Φ) F_A up to F_S = F_V + Φ F_A at f_SV + Φ F_A δ_S; with n = 1 the lower end
lies on the embedded plate line itself (the invariant of VDI's diagram), and at the separation
load the plate line reaches zero.
"""

import numpy as np
import pytest

from engine import run
from engine.models import get_model

JOINT = get_model("joint.vdi2230")
CASE = {**JOINT.examples[0], "load_introduction": 1.0}


def _plate_line_at(s, f):
    """The embedded plate line where it is not clipped, as a straight line, at f."""
    x, y = s["diagram_deformation"], s["diagram_embedded_clamped_line"]
    inside = (y > 0) & (y < y.max())
    return np.polyval(np.polyfit(x[inside], y[inside], 1), f)


def _diagram(inputs):
    r = run(JOINT, inputs, series=True)
    return r.results, {k: np.asarray(v, dtype=float) for k, v in r.series.items()}


def test_working_segment_is_f_a_split_by_phi_on_the_lines():
    res, s = _diagram(CASE)
    phi, f_a = res["load_factor"], 8e3
    f_v = res["assembly_preload_min"] - res["embedding_loss"]
    x, lo_hi = s["diagram_working_deformation"], s["diagram_working_force"]
    assert lo_hi.tolist() == pytest.approx([f_v - (1 - phi) * f_a, f_v + phi * f_a], rel=1e-12)
    assert lo_hi[1] - lo_hi[0] == pytest.approx(f_a, rel=1e-12)
    assert x[0] == x[1] == pytest.approx((f_v + phi * f_a) * res["bolt_compliance"], rel=1e-12)
    # the ends on the lines: the bolt line f/δ_S and the embedded plate line (n = 1)
    assert lo_hi[1] == pytest.approx(x[0] / res["bolt_compliance"], rel=1e-12)
    assert _plate_line_at(s, x[0]) == pytest.approx(lo_hi[0], rel=1e-9)


def test_opening_segment_ends_where_the_plates_unload():
    res, s = _diagram(CASE)
    x, force = s["diagram_opening_deformation"], s["diagram_opening_force"]
    assert force[0] == 0.0
    f_v = res["assembly_preload_min"] - res["embedding_loss"]
    assert force[1] == pytest.approx(f_v / (1 - res["load_factor"]), rel=1e-12)  # = F_A,sep
    assert _plate_line_at(s, x[0]) == pytest.approx(0.0, abs=1e-9 * f_v)


def test_the_eccentric_diagram_uses_the_eccentric_plates():
    ecc = {
        **CASE,
        "bolt_offset": 0.005,
        "load_lever": 0.02,
        "interface_length": 0.05,
        "interface_width": 0.04,
    }
    res, s = _diagram(ecc)
    # the embedded plate line's slope is −1/δ*_P
    x, y = s["diagram_deformation"], s["diagram_embedded_clamped_line"]
    inside = (y > 0) & (y < y.max())
    slope = np.polyfit(x[inside], y[inside], 1)[0]
    assert slope == pytest.approx(-1 / res["eccentric_clamped_compliance"], rel=1e-9)
