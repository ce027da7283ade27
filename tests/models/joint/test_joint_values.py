"""The VDI 2230 tables and constants of engine.physics.joint, row by row, and their lookups.

Written out again from VDI 2230-1:2015 (Table 5.4/1 for embedding, R3 for the length
factors, eq. 5.1/21-22 for the cone) so that a changed digit fails.
"""

import math

import numpy as np
import pytest

from engine.core.errors import InputOutOfRange
from engine.physics import joint as jt

# VDI 2230-1:2015 Table 5.4/1 [µm]: (thread, each bearing face, each inner interface)
EMBEDDING = {
    "Rz<10": {"axial": (3.0, 2.5, 1.5), "transverse": (3.0, 3.0, 2.0)},
    "Rz10-40": {"axial": (3.0, 3.0, 2.0), "transverse": (3.0, 4.5, 2.5)},
    "Rz40-160": {"axial": (3.0, 4.0, 3.0), "transverse": (3.0, 6.5, 3.5)},
}


def test_length_factors_and_constants_are_vdi_2230s():
    assert jt.HEAD_LENGTH_FACTOR == {"hex": 0.5, "socket": 0.4}
    assert jt.NUT_LENGTH_FACTOR == {"through": 0.4, "tapped": 0.33}
    assert jt.ENGAGED_THREAD_FACTOR == 0.5
    assert jt.TORSION_REDUCTION_IN_SERVICE == 0.5
    assert jt.MIN_CONE_TANGENT == 0.1
    assert jt.ROUGHNESS_CLASSES == ("Rz<10", "Rz10-40", "Rz40-160")


@pytest.mark.parametrize("roughness", list(EMBEDDING))
@pytest.mark.parametrize("load", ["axial", "transverse"])
def test_every_embedding_row(roughness, load):
    thread, bearing, interface = EMBEDDING[roughness][load]
    assert jt.EMBEDDING_UM[roughness][load] == (thread, bearing, interface)
    for n_k, n_t in ((2, 1), (1, 1), (2, 3), (1, 0)):
        expected = (thread + n_k * bearing + n_t * interface) * 1e-6
        assert jt.embedding(roughness, load, n_k, n_t) == pytest.approx(expected, rel=1e-12)
    # the column follows the load the joint carries, for one design and for many
    other = "axial" if load == "transverse" else "transverse"
    f_q = 1.0 if load == "transverse" else 0.0
    assert jt.embedding_for_load(roughness, f_q, 2, 1) == pytest.approx(
        jt.embedding(roughness, load, 2, 1), rel=1e-12
    )
    many = jt.embedding_for_load(roughness, np.array([f_q, 1.0 - f_q]), 2, 1)
    assert many == pytest.approx(
        [jt.embedding(roughness, load, 2, 1), jt.embedding(roughness, other, 2, 1)], rel=1e-12
    )


def test_unknown_roughness_or_load_is_refused_by_name():
    for args in (("Rz<5", "axial"), ("Rz<10", "torsion")):
        with pytest.raises(InputOutOfRange) as err:
            jt.embedding(*args, 2, 1)
        assert err.value.field == "surface_roughness"


@pytest.mark.parametrize(
    ("joint", "plates", "expected"),
    [("through", 2, (2, 1)), ("through", 4, (2, 3)), ("tapped", 1, (1, 1)), ("tapped", 3, (1, 3))],
)
def test_embedding_locations(joint, plates, expected):
    assert jt.embedding_locations(joint, plates) == expected


@pytest.mark.parametrize(
    ("grip", "dw", "da", "joint"),
    [
        (0.040, 0.01663, 0.040, "through"),
        (0.010, 0.01663, 0.025, "through"),
        (0.040, 0.01663, 0.040, "tapped"),
        (0.060, 0.0228, 0.030, "tapped"),
    ],
)
def test_cone_tangent_by_hand(grip, dw, da, joint):
    # VDI 2230-1 eq. 5.1/21 (through) and 5.1/22 (tapped), β_L = l_K/d_W, y = D_A/d_W
    beta, y = grip / dw, da / dw
    if joint == "through":
        tan = 0.362 + 0.032 * math.log(beta / 2) + 0.153 * math.log(y)
    else:
        tan = 0.348 + 0.013 * math.log(beta) + 0.193 * math.log(y)
    assert jt.cone_tangent(grip, dw, da, joint) == pytest.approx(tan, rel=1e-12)
    assert jt.cone_tangent(np.array([grip]), dw, da, joint) == pytest.approx([tan], rel=1e-12)


def test_cone_tangent_is_held_at_0_1():
    # a grip far shorter than d_W with no outer margin: the fit falls below 0.1
    raw = 0.362 + 0.032 * math.log(1e-6 / 0.02 / 2) + 0.153 * math.log(1.0)
    assert raw < 0.1
    assert jt.cone_tangent(1e-6, 0.02, 0.02) == 0.1
    assert jt.cone_tangent(np.array([1e-6, 0.040]), 0.02, 0.02).tolist()[0] == 0.1


def test_load_factor_by_hand_with_and_without_load_introduction():
    # Φ_n = n δ_P / (δ_S + δ_P): 1e-9 / 4e-9 = 0.25, n = 1 unless given
    assert jt.load_factor(3e-9, 1e-9) == pytest.approx(0.25, rel=1e-12)
    assert jt.load_factor(3e-9, 1e-9, 0.5) == pytest.approx(0.125, rel=1e-12)


def test_required_slip_safety_is_1_8_only_for_a_load_that_alternates():
    # VDI 2230-1 R12: 1.8 where F_A,min < F_A,max, 1.2 otherwise (equal, or given upside down)
    assert jt.required_slip_safety(8e3, 0.0) == 1.8
    assert jt.required_slip_safety(8e3, 8e3) == 1.2
    assert jt.required_slip_safety(8e3, 9e3) == 1.2
    assert jt.required_slip_safety(
        np.array([8e3, 8e3, 8e3]), np.array([0.0, 8e3, 9e3])
    ).tolist() == [
        1.8,
        1.2,
        1.2,
    ]


def test_joint_diagram_lines_by_hand():
    # F_M = 30 kN, δ_S = 3e-9, δ_P = 1e-9 m/N, F_A = 10 kN, Φ_n = 0.25, F_Z = 2 kN:
    # f_SM = 90 µm, the axis ends at F_M (δ_S + δ_P) = 120 µm, so point 30 of 41 is f_SM;
    # F_V = 28 kN at f_SV = 84 µm; the lines are clipped to 1.2 × max(F_M, F_V + Φ_n F_A) = 36.6 kN
    d = jt.joint_diagram(30e3, 3e-9, 1e-9, 10e3, 0.25, 2e3)
    x = d["deformation"]
    assert x[0] == 0.0 and x[-1] == pytest.approx(120e-6, rel=1e-12) and len(x) == 41
    assert x[30] == pytest.approx(90e-6, rel=1e-12)
    clamped, embedded, bolt = d["clamped_line"], d["embedded_clamped_line"], d["bolt_line"]
    assert clamped[30] == pytest.approx(30e3, rel=1e-9)  # through F_M at f_SM
    assert clamped[35] == pytest.approx(30e3 - 15e-6 / 1e-9, rel=1e-9)  # slope −1/δ_P
    assert clamped[20] == pytest.approx(36.6e3, rel=1e-12)  # 30 kN + 30 µm/δ_P, clipped
    assert clamped[-1] == pytest.approx(0.0, abs=1e-6)
    # the embedded line through F_V = 28 kN at f_SV = 84 µm: at 90 µm, 28 kN − 6 µm/δ_P
    assert embedded[30] == pytest.approx(22e3, rel=1e-9)
    assert bolt[30] == pytest.approx(30e3, rel=1e-9) and bolt[-1] == pytest.approx(36.6e3)
    assert d["service_preload_level"] == [28e3] * 41
    assert d["working_bolt_force_level"][0] == pytest.approx(30.5e3)
    assert d["residual_clamp_level"][0] == pytest.approx(28e3 - 0.75 * 10e3)
    assert d["preload_level"] == [30e3] * 41
    # a working load beyond separation: the residual clamp force is held at 0
    assert jt.joint_diagram(30e3, 3e-9, 1e-9, 60e3, 0.25, 2e3)["residual_clamp_level"][0] == 0.0


def test_endurance_limit_rolled_after_heat_treatment_by_hand():
    # σ_ASV = 0.85 (150/d + 45) MPa, d in mm; σ_ASG = (2 − F_Sm/F_0.2) σ_ASV, the ratio in 0…1
    asv = 0.85 * (150 / 12 + 45) * 1e6
    assert jt.endurance_limit(0.012) == pytest.approx(asv, rel=1e-12)
    sg = "after_heat_treatment"
    assert jt.endurance_limit(0.012, sg) == pytest.approx(2 * asv, rel=1e-12)  # F_Sm = 0
    assert jt.endurance_limit(0.012, sg, 30e3, 60e3) == pytest.approx(1.5 * asv, rel=1e-12)
    assert jt.endurance_limit(0.012, sg, 90e3, 60e3) == pytest.approx(asv, rel=1e-12)


def test_a_joint_whose_plates_never_unload_never_separates():
    # F_A,sep = (F_M − losses)/(1 − Φ_n), infinite where Φ_n ≥ 1
    assert jt.separation_load(30e3, 2.6e3, 0.1) == pytest.approx(27.4e3 / 0.9, rel=1e-12)
    assert jt.separation_load(30e3, 2.6e3, 1.0) == math.inf
    assert jt.separation_load(30e3, 2.6e3, 1.2) == math.inf
    assert jt.separation_load(2e3, 2.6e3, 0.1) == 0.0  # the losses exceed the preload
    many = jt.separation_load(np.array([30e3, 30e3]), 2.6e3, np.array([0.1, 1.2]))
    assert many.tolist() == [pytest.approx(27.4e3 / 0.9, rel=1e-12), math.inf]


def test_smallest_section_says_shank_where_any_section_is_thinner():
    # two sections thinner than d_S: the thinnest wins, and it is a shank either way
    assert jt.smallest_section(0.010358, [(0.02, 0.009), (0.03, 0.0075)]) == (0.0075, "shank")
    assert jt.smallest_section(0.010358, [(0.02, 0.011)]) == (0.010358, "thread")
    d0, which = jt.smallest_section(
        0.010358, [(np.array([0.02, 0.0]), 0.009), (np.array([0.03, 0.0]), 0.0075)]
    )
    assert d0.tolist() == [0.0075, 0.010358] and which.tolist() == ["shank", "thread"]
