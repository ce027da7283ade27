"""The joint at its service temperature (R_p0.2 and E at T), by hand.

ISO 898-1 Annex A [NFG-898T] gives 8.8 640/590/540 MPa at 20/100/200 °C and 12.9
1100/1020/925 MPa; Richter's E(T) [RICHTER-E] steel 212/199 GPa and aluminium 70/63 GPa at
20/200 °C. F_M,zul = ν R_p0.2 A_0/β (R7) and S_F = R_p0.2/σ_red,B (R8) are linear in R_p0.2;
with ΔT = 0 and both E falling by r, ΔF_Vth = F_V (1 − (δ_S + δ_P)/(δ_S/r + δ_P/r)) =
F_V (1 − r) (VDI 2230-1 5.4.2.3).
"""

import math

import pytest

from engine import run, sweep
from engine.core.errors import InputOutOfRange
from engine.models import get_model
from engine.physics import joint as jt
from tests.pins import pin

JOINT = get_model("joint.vdi2230")
AT_TEMPERATURE = (
    "yield_strength_at_temperature",
    "bolt_modulus_ratio_at_temperature",
    "plate_modulus_ratio_at_temperature",
)
#: The torque-specified M12 8.8 (second example): the preload range does not depend on R_p0.2.
TORQUE = JOINT.examples[1]


@pytest.mark.parametrize("index", range(len(JOINT.examples)))
def test_room_temperature_answers_as_no_temperature_to_the_bit(index):
    example = JOINT.examples[index]
    cold = run(JOINT, example)
    room = run(JOINT, {**example, "service_temperature": 293.15})
    assert not set(AT_TEMPERATURE) & set(cold.results)
    same = {k: v for k, v in room.results.items() if k not in AT_TEMPERATURE}
    assert same == cold.results  # == on floats: bit for bit
    assert [(c.name, c.ok) for c in room.checks] == [(c.name, c.ok) for c in cold.checks]
    pin("joint.vdi2230", "bolt_modulus_ratio_at_temperature", room.results[AT_TEMPERATURE[1]], 1.0)


def test_an_8_8_bolt_at_200_c_by_hand():
    cold = run(JOINT, TORQUE).results
    hot = run(JOINT, {**TORQUE, "service_temperature": 473.15}).results
    pin("joint.vdi2230", "yield_strength_at_temperature", hot[AT_TEMPERATURE[0]], 540e6, rel=1e-12)
    ratio = 540.0 / 640.0
    pin(
        "joint.vdi2230",
        "permissible_preload",
        hot["permissible_preload"],
        cold["permissible_preload"] * ratio,
        rel=1e-12,
    )
    # the torque sets F_M,max; a thermal loss does not add to F_S,max: σ_red,B is the same
    assert hot["working_stress"] == pytest.approx(cold["working_stress"], rel=1e-12)
    pin(
        "joint.vdi2230",
        "yield_safety",
        hot["yield_safety"],
        cold["yield_safety"] * ratio,
        rel=1e-12,
    )
    r = 199.0 / 212.0
    pin("joint.vdi2230", "bolt_modulus_ratio_at_temperature", hot[AT_TEMPERATURE[1]], r, rel=1e-12)
    pin("joint.vdi2230", "plate_modulus_ratio_at_temperature", hot[AT_TEMPERATURE[2]], r, rel=1e-12)
    f_v = cold["assembly_preload_min"] - cold["embedding_loss"]
    pin("joint.vdi2230", "thermal_loss", hot["thermal_loss"], f_v * (1.0 - r), rel=1e-12)
    assert cold["thermal_loss"] == 0.0
    # what assembly fixes stays: compliances, Φ_n, F_Z (room temperature)
    for name in ("bolt_compliance", "clamped_compliance", "load_factor", "embedding_loss"):
        assert hot[name] == cold[name]


def test_a_12_9_screw_in_aluminium_at_150_c_by_hand():
    example = JOINT.examples[3]  # M8 ISO 4762 12.9 into EN AW-6082 T6
    hot = run(JOINT, {**example, "service_temperature": 423.15}).results
    # 12.9 at 150 °C: half-way between 1020 and 925 MPa, on R_p0.2 = 1100 MPa
    pin(
        "joint.vdi2230", "yield_strength_at_temperature", hot[AT_TEMPERATURE[0]], 972.5e6, rel=1e-12
    )
    # aluminium at 150 °C: 70 − 7 × 130/180 GPa over 70 GPa
    aluminium = (70.0 - 7.0 * 130.0 / 180.0) / 70.0
    pin("joint.vdi2230", "plate_modulus_ratio_at_temperature", hot[AT_TEMPERATURE[2]], aluminium)
    steel = (212.0 - 13.0 * 130.0 / 180.0) / 212.0
    pin("joint.vdi2230", "bolt_modulus_ratio_at_temperature", hot[AT_TEMPERATURE[1]], steel)


def test_steel_and_an_aluminium_plate_without_a_material_by_hand():
    design = {**TORQUE, "plate2_youngs_modulus": 7e10, "service_temperature": 473.15}
    hot = run(JOINT, design)
    # plate 1 (210 GPa) is read as steel, plate 2 (70 GPa, no clamped_material) keeps its E:
    # E_P,T/E_P,RT = δ_P/(δ_1/r + δ_2), δ_i from the cone and sleeve of the joint's D_A,Gr
    parts = jt.clamped_compliance([0.02, 0.02], [2.1e11, 7e10], 0.01663, 0.0135)
    r = 199.0 / 212.0
    d1, d2 = parts.per_plate
    expected = (d1 + d2) / (d1 / r + d2)
    pin(
        "joint.vdi2230",
        "plate_modulus_ratio_at_temperature",
        hot.results[AT_TEMPERATURE[2]],
        expected,
        rel=1e-9,
    )
    assert any("plates of E ≥ 190 GPa as steel" in n for n in hot.notes)
    assert any("temperature_change ΔT_S = 0" in w for w in hot.warnings)


@pytest.mark.parametrize(
    ("extra", "field", "says"),
    [
        ({"service_temperature": 523.15}, "service_temperature", "293.15…473.15 K"),
        ({"service_temperature": 373.15, "grade": "A4-70"}, "service_temperature", "5.6, 8.8"),
        ({"service_temperature": 373.15, "bolt_modulus_ratio": 0.9}, "bolt_modulus_ratio", "1"),
    ],
)
def test_refusals_name_the_field_and_the_range(extra, field, says):
    design = {**JOINT.examples[3], **extra}
    if "grade" in extra:
        design["thread"] = "M8"
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, design)
    assert err.value.field == field and says in str(err.value)


def test_a_typed_yield_strength_needs_its_class():
    design = {**TORQUE, "yield_strength": 7e8, "service_temperature": 373.15}
    with pytest.raises(InputOutOfRange, match="property class") as err:
        run(JOINT, design)
    assert err.value.field == "service_temperature"
    ok = run(JOINT, {**design, "grade": "10.9"}).results
    pin("joint.vdi2230", "yield_strength_at_temperature", ok[AT_TEMPERATURE[0]], 7e8 * 875 / 940)


@pytest.mark.parametrize("outside", [290.0, 580.0])
def test_the_declared_range_is_the_table(outside):
    with pytest.raises(InputOutOfRange) as err:
        run(JOINT, {**TORQUE, "service_temperature": outside})
    assert err.value.field == "service_temperature"


def test_a_sweep_over_the_temperature_runs_the_same_lines():
    values = [293.15, 373.15, 448.15, 573.15]
    many = sweep(JOINT, TORQUE, "service_temperature", values)
    for i, t in enumerate(values):
        one = run(JOINT, {**TORQUE, "service_temperature": t}).results
        for name in ("yield_safety", "thermal_loss", *AT_TEMPERATURE):
            got = float(many.columns[name][i])
            assert math.isclose(got, one[name], rel_tol=1e-12, abs_tol=1e-9), name
