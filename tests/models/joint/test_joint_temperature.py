"""The joint at its service temperature (R_p0.2 and E at T), by hand.

ISO 898-1 Annex A [NFG-898T] gives 8.8 640/590/540 MPa at 20/100/200 °C and 12.9
1100/1020/925 MPa; Richter's E(T) [RICHTER-E] steel 212/199 GPa and aluminium 70/63 GPa at
20/200 °C. The bolt is tightened cold: F_M,zul = ν R_p0.2 A_0/β (R7) and the torque keep the
room-temperature R_p0.2; only S_F = R_p0.2(T)/σ_red,B (R8, in service) takes it at T;
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
    # R7 is the assembly's, cold: F_M,zul and F_M0.2 do not move with the service temperature
    for name in ("permissible_preload", "yield_preload", "tightening_torque"):
        assert hot[name] == cold[name], name
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
    """The reviewer's case: the second example with plate 2 at 70 GPa, 200 °C, no material.

    Plate 1 (210 GPa) is read as steel, 199/212; plate 2 (70 GPa) as aluminium, 63/70 = 0.9:
    E_P,T/E_P,RT = δ_P/(δ_1/r_S + δ_2/r_Al) ≈ 0.9094 and, with ΔT = 0,
    ΔF_Vth = F_V (1 − (δ_S + δ_P)/(δ_S/r_S + δ_P/r_P)) ≈ 1959 N.
    """
    design = {**TORQUE, "plate2_youngs_modulus": 7e10, "service_temperature": 473.15}
    hot = run(JOINT, design)
    cold = run(JOINT, {**TORQUE, "plate2_youngs_modulus": 7e10}).results
    parts = jt.clamped_compliance([0.02, 0.02], [2.1e11, 7e10], 0.01663, 0.0135)
    r_s, r_al = 199.0 / 212.0, 63.0 / 70.0
    d1, d2 = parts.per_plate
    r_p = (d1 + d2) / (d1 / r_s + d2 / r_al)
    pin(
        "joint.vdi2230",
        "plate_modulus_ratio_at_temperature",
        hot.results[AT_TEMPERATURE[2]],
        r_p,
        rel=1e-9,
    )
    assert hot.results[AT_TEMPERATURE[2]] == pytest.approx(0.9094, abs=5e-5)
    d_s, d_p = cold["bolt_compliance"], cold["clamped_compliance"]
    f_v = cold["assembly_preload_min"] - cold["embedding_loss"]
    loss = f_v * (1.0 - (d_s + d_p) / (d_s / r_s + d_p / r_p))
    pin("joint.vdi2230", "thermal_loss", hot.results["thermal_loss"], loss, rel=1e-9)
    assert hot.results["thermal_loss"] == pytest.approx(1959.0, abs=1.0)
    assert any("plate 2 (70 GPa) as aluminium" in n for n in hot.notes)
    assert any("temperature_change ΔT_S = 0" in w for w in hot.warnings)


def test_a_middle_plate_is_read_by_its_own_modulus():
    """clamped_material (S235JR, steel) covers the plates under head and nut; the middle one,
    a 70 GPa aluminium spacer, takes aluminium's 63/70 (Richter) by its own E."""
    design = {
        **TORQUE,
        "plate3_thickness": 0.01,
        "plate2_youngs_modulus": 7e10,
        "clamped_material": "S235JR",
        "service_temperature": 473.15,
    }
    hot = run(JOINT, design)
    parts = jt.clamped_compliance([0.02, 0.02, 0.01], [2.1e11, 7e10, 2.1e11], 0.01663, 0.0135)
    r_s, r_al = 199.0 / 212.0, 63.0 / 70.0
    d1, d2, d3 = parts.per_plate
    expected = (d1 + d2 + d3) / (d1 / r_s + d2 / r_al + d3 / r_s)
    pin(
        "joint.vdi2230",
        "plate_modulus_ratio_at_temperature",
        hot.results[AT_TEMPERATURE[2]],
        expected,
        rel=1e-9,
    )
    assert not any("contradicts" in w for w in hot.warnings)


def test_a_modulus_that_contradicts_the_material_is_warned():
    """EN AW-6082 T6 under the head but plate 1 typed at 210 GPa: aluminium's E(T) (the named
    material) is used, 63/70 at 200 °C, and a warning names both."""
    design = {**JOINT.examples[3], "plate1_youngs_modulus": 2.1e11, "service_temperature": 473.15}
    hot = run(JOINT, design)
    pin(
        "joint.vdi2230",
        "plate_modulus_ratio_at_temperature",
        hot.results[AT_TEMPERATURE[2]],
        0.9,
        rel=1e-12,
    )
    assert any("plate 1: E = 210 GPa contradicts clamped_material" in w for w in hot.warnings)


def test_an_aluminium_plate_by_its_modulus_beyond_its_table_is_refused():
    """Richter's aluminium row ends at 200 °C: a 70 GPa plate at 250 °C is refused."""
    design = {**TORQUE, "plate2_youngs_modulus": 7e10, "service_temperature": 523.15}
    with pytest.raises(InputOutOfRange, match="plate 2, E = 70 GPa") as err:
        run(JOINT, design)
    assert err.value.field == "service_temperature" and "473.15 K" in str(err.value)


@pytest.mark.parametrize(
    ("extra", "field", "says"),
    [
        ({"service_temperature": 523.15}, "service_temperature", "233.15…473.15 K"),
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


@pytest.mark.parametrize("outside", [233.0, 233.15 * (1 - 2e-9), 573.15 * (1 + 2e-9), 580.0])
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


def test_tightened_cold_to_f_m_zul_and_yield_safety_at_300_c_by_hand():
    """VDI 2230-1 R7 at assembly, R8 in service: the first example (M12 8.8, tightened to F_M,zul).

    M12: d_2 = 10.863 mm, d_3 = 9.853 mm, P = 1.75 mm; d_0 = d_S = (d_2 + d_3)/2 = 10.358 mm,
    A_0 = π d_0²/4; μ_G,min = 0.12, ν = 0.9, R_p0.2 = 640 MPa (room temperature);
    F_M,zul = ν R_p0.2 A_0 / √(1 + 3 (3/2 d_2/d_0 (P/(π d_2) + 1.155 μ_G))²) ≈ 43.11 kN, the
    same at 300 °C; there S_F = 480 MPa / σ_red,B with σ_red,B of the cold F_M,max ≈ 0.875.
    """
    d2, d3, p = 10.863e-3, 9.853e-3, 1.75e-3
    d0 = 0.5 * (d2 + d3)
    k = 1.5 * d2 / d0 * (p / (math.pi * d2) + 1.155 * 0.12)
    f_mzul = 0.9 * 640e6 * math.pi / 4.0 * d0**2 / math.sqrt(1.0 + 3.0 * k**2)
    example = JOINT.examples[0]
    cold = run(JOINT, example).results
    hot = run(JOINT, {**example, "service_temperature": 573.15}).results
    pin("joint.vdi2230", "permissible_preload", hot["permissible_preload"], f_mzul, rel=1e-4)
    assert hot["permissible_preload"] == cold["permissible_preload"]
    assert hot["tightening_torque"] == cold["tightening_torque"]
    assert hot["working_stress"] == cold["working_stress"]  # F_S,max from the cold F_M,max
    pin("joint.vdi2230", "yield_strength_at_temperature", hot[AT_TEMPERATURE[0]], 480e6)
    s_f = 480e6 / cold["working_stress"]
    pin("joint.vdi2230", "yield_safety", hot["yield_safety"], s_f, rel=1e-12)
    assert hot["yield_safety"] == pytest.approx(0.875, abs=5e-4)  # 480/548.8: below 1
    assert not next(
        c
        for c in run(JOINT, {**example, "service_temperature": 573.15}).checks
        if c.name == "R8_working_stress"
    ).ok


@pytest.mark.parametrize(
    "kelvin",
    [
        (68.0 - 32.0) * 5.0 / 9.0 + 273.15,  # 68 °F = 293.1499999999992 K
        -40.0 + 273.15,  # 233.14999999999998 K, VDI 2230-1's coldest
        300.0 + 273.15,
        573.15 * (1 + 5e-10),
    ],
)
def test_the_bounds_take_a_converted_temperature(kelvin):
    run(JOINT, {**TORQUE, "service_temperature": kelvin})


def test_in_the_cold_the_room_temperature_values_hold():
    """At −20 °C R_p0.2 and E keep their 20 °C values (ratio 1, conservative): S_F, F_M,zul
    and the thermal loss are the room temperature's, and a note says why."""
    cold = run(JOINT, TORQUE)
    frozen = run(JOINT, {**TORQUE, "service_temperature": 253.15})
    pin("joint.vdi2230", "yield_strength_at_temperature", frozen.results[AT_TEMPERATURE[0]], 640e6)
    pin(
        "joint.vdi2230",
        "plate_modulus_ratio_at_temperature",
        frozen.results[AT_TEMPERATURE[2]],
        1.0,
    )
    for name in ("yield_safety", "permissible_preload", "thermal_loss"):
        assert frozen.results[name] == cold.results[name], name
    assert any("conservative" in n and "−40 °C" in n for n in frozen.notes)
