"""One outer diameter D_A per plate (VDI 2230-1 R3, the cone and sleeve plate by plate), by hand.

M12 8.8 through 2 × 20 mm steel (d_W = 16.63 mm, d_h = 13.5 mm, E = 210 GPa). Each half of a
through joint is a cone from its bearing face to mid-grip, its angle from its own side's D_A
(head: plate 1's, nut: the last plate's); plate i's part is capped at its own D_A,i. A fully
developed half cone is VDI's closed form
ln[(d_W + d_h)(d_W + 2 z tan φ − d_h)/((d_W − d_h)(d_W + 2 z tan φ + d_h))]/(E π d_h tan φ) with
z = l_K/2; a plate with D_A,i ≤ d_W is a sleeve 4 h_i/(E π (D_A,i² − d_h²)).
"""

import math

import pytest

from engine import run, sweep
from engine.core.errors import InputOutOfRange
from engine.models import get_model
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
BASE = {**JOINT.examples[0], "outer_diameter": 0.040}
E, D_W, D_H, H = 2.1e11, 0.01663, 0.0135, 0.020


def _half_cone(tan: float) -> float:
    top = D_W + 2.0 * H * tan
    ratio = (D_W + D_H) * (top - D_H) / ((D_W - D_H) * (top + D_H))
    return math.log(ratio) / (E * math.pi * D_H * tan)


def test_the_first_plate_s_diameter_for_both_is_today_s_answer_to_the_bit():
    same = run(JOINT, {**BASE, "plate2_outer_diameter": 0.040}).results
    assert same == run(JOINT, BASE).results


def test_a_narrow_second_plate_is_a_sleeve_by_hand():
    got = run(JOINT, {**BASE, "plate2_outer_diameter": 0.015}).results
    tan = got["cone_tangent"]  # VDI's fit at D_A,1 = 40 mm (D_A,Gr = 36.7 mm: full cone)
    sleeve = 4.0 * H / (E * math.pi * (0.015**2 - D_H**2))
    pin(
        "joint.vdi2230",
        "clamped_compliance",
        got["clamped_compliance"],
        _half_cone(tan) + sleeve,
        rel=1e-12,
    )


def _vdi_tangent(outer: float) -> float:
    """VDI 2230-1 eq. (5.1/21), through-bolted: 0.362 + 0.032 ln(β_L/2) + 0.153 ln y."""
    return 0.362 + 0.032 * math.log(2 * H / D_W / 2.0) + 0.153 * math.log(outer / D_W)


def test_a_wide_second_plate_keeps_the_full_cone_by_hand():
    """Each half-cone's angle from its own side's D_A: the head's at 40 mm, the nut's at
    100 mm (both fully developed: D_A,Gr ≈ 37 mm)."""
    got = run(JOINT, {**BASE, "plate2_outer_diameter": 0.100}).results
    assert got["cone_tangent"] == pytest.approx(_vdi_tangent(0.040), rel=1e-12)
    pin(
        "joint.vdi2230",
        "clamped_compliance",
        got["clamped_compliance"],
        _half_cone(_vdi_tangent(0.040)) + _half_cone(_vdi_tangent(0.100)),
        rel=1e-12,
    )


def test_a_mirrored_joint_gives_the_same_answer():
    """The first example with 15 mm under the head and 60 mm under the nut, and mirrored: the
    60 mm half is a full cone at VDI's angle for y = 60/16.63, the 15 mm half a sleeve."""
    narrow_head = run(
        JOINT, {**JOINT.examples[0], "outer_diameter": 0.015, "plate2_outer_diameter": 0.060}
    ).results
    narrow_nut = run(
        JOINT, {**JOINT.examples[0], "outer_diameter": 0.060, "plate2_outer_diameter": 0.015}
    ).results
    sleeve = 4.0 * H / (E * math.pi * (0.015**2 - D_H**2))
    by_hand = _half_cone(_vdi_tangent(0.060)) + sleeve
    for got in (narrow_head, narrow_nut):
        pin("joint.vdi2230", "clamped_compliance", got["clamped_compliance"], by_hand, rel=1e-12)
    for name in ("load_factor", "embedding_loss", "assembly_preload_min", "yield_safety"):
        assert narrow_head[name] == pytest.approx(narrow_nut[name], rel=1e-12), name


def test_a_diameter_inside_the_hole_is_refused_naming_the_plate():
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**BASE, "plate2_outer_diameter": 0.013})
    assert err.value.field == "plate2_outer_diameter" and "13.5 mm" in str(err.value)


def test_a_sweep_over_the_second_diameter_runs_the_same_lines():
    values = [0.014, 0.016, 0.030, 0.060]
    many = sweep(JOINT, BASE, "plate2_outer_diameter", values)
    for i, d in enumerate(values):
        one = run(JOINT, {**BASE, "plate2_outer_diameter": d}).results
        for name in ("clamped_compliance", "load_factor", "embedding_loss"):
            got = float(many.columns[name][i])
            assert got == pytest.approx(one[name], rel=1e-12), name


def test_a_diameter_for_a_plate_not_given_is_refused():
    """Plate 3's D_A without plate 3 (two plates): refused, naming the field (it was ignored
    while the note said it was used)."""
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**BASE, "plate3_outer_diameter": 0.030})
    assert err.value.field == "plate3_outer_diameter"
    assert "plate3_thickness" in str(err.value)


@pytest.mark.parametrize("index", range(len(JOINT.examples)))
def test_every_example_with_equal_diameters_is_the_single_d_a_answer_to_the_bit(index):
    """Each plate's own D_A equal to plate 1's gives every output, check and warning of the
    single-D_A joint bit for bit (the nut half-cone's angle is then the head's)."""
    example = {**JOINT.examples[index]}
    example.setdefault("outer_diameter", 0.036)
    own = {
        f"plate{i}_outer_diameter": example["outer_diameter"]
        for i in range(2, 4)
        if example.get(f"plate{i}_thickness") is not None
    }
    single = run(JOINT, example)
    each = run(JOINT, {**example, **own})
    assert each.results == single.results  # == on floats: bit for bit
    assert [(c.name, c.ok, c.detail) for c in each.checks] == [
        (c.name, c.ok, c.detail) for c in single.checks
    ]
    assert each.warnings == single.warnings
