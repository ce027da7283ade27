"""engine.physics.clutch: the inverses' defaults and dT/df with two flanks, by hand [001]."""

import math

import numpy as np
import pytest

from engine.physics import clutch as cl

DEG = math.pi / 180


def test_the_inverse_defaults_are_one_common_spring_without_friction():
    # F = 2 T tan α / D0 with s = 1 (common spring): the defaults ball_count 1, K_r 0.85,
    # f = 0 and "common" leave no trace; per ball with the defaults, s = 0.85 × 1
    t, d0, a = 2.0, 0.05, 40 * DEG
    common = 2 * t * math.tan(a) / d0
    assert cl.spring_force_for_torque(t, d0, a) == pytest.approx(common, rel=1e-12)
    per_ball = cl.spring_force_for_torque(t, d0, a, arrangement="per_ball")
    assert per_ball == pytest.approx(common / 0.85, rel=1e-12)
    assert cl.spring_force_for_torque(t, d0, a, 4, 0.9, 0.0, "per_ball") == pytest.approx(
        common / 3.6, rel=1e-12
    )


def test_wire_for_torque_defaults_match_the_explicit_call():
    args = (2.0, 0.05, 40 * DEG, 8e10, 0.03, 6.0, 0.01)
    explicit = cl.wire_diameter_for_torque(*args, 1, 0.85, 0.0, "common")
    assert cl.wire_diameter_for_torque(*args) == pytest.approx(explicit, rel=1e-12)
    per_ball = cl.wire_diameter_for_torque(*args, arrangement="per_ball")
    assert per_ball == pytest.approx(
        cl.wire_diameter_for_torque(*args, 1, 0.85, 0.0, "per_ball"), rel=1e-12
    )
    # per ball with s = 0.85: the spring force is 1/0.85 of the common one; d ∝ F^(1/4)
    assert per_ball == pytest.approx(explicit * (1 / 0.85) ** 0.25, rel=1e-9)


def test_friction_sensitivity_with_a_driving_flank_by_hand():
    # balls lifting a pressure disc (both flanks at once): p = tan(α′ − ρ) + tan(α″ − ρ),
    # dT/df = T/p · (sec²(α″ − ρ) + sec²(α′ − ρ)) / (1 + f²)
    t, a2, a1, f = 1.5, 45 * DEG, 30 * DEG, 0.1
    rho = math.atan(f)
    p = math.tan(a1 - rho) + math.tan(a2 - rho)
    expected = t / p * (1 / math.cos(a2 - rho) ** 2 + 1 / math.cos(a1 - rho) ** 2) / (1 + f * f)
    disc = cl.friction_sensitivity(t, a2, f, a1, "pressure_disc")
    assert disc == pytest.approx(expected, rel=1e-12)
    many = cl.friction_sensitivity(np.array([t, t]), a2, f, a1, "pressure_disc")
    assert many == pytest.approx([expected, expected], rel=1e-12)
    # one inclined flank: T/tan(α″ − ρ) · sec²(α″ − ρ)/(1 + f²)
    one = t / math.tan(a2 - rho) / math.cos(a2 - rho) ** 2 / (1 + f * f)
    assert cl.friction_sensitivity(t, a2, f) == pytest.approx(one, rel=1e-12)
    # a free ball (the default) pushes by the larger of the two, here the 45° flank's:
    # the same as that flank alone, 1.5/0.81818 · 1.66942/1.01 = 3.0303 N·m
    assert cl.friction_sensitivity(t, a2, f, a1) == pytest.approx(one, rel=1e-12)
    assert one == pytest.approx(3.030303, rel=1e-6)


@pytest.mark.parametrize("name", ["single", "Per_ball", "zeta", "", "common "])
def test_torque_sharing_takes_its_two_arrangements_only(name):
    assert cl.torque_sharing("common", 4, 0.85) == 1.0
    assert cl.torque_sharing("per_ball", 4, 0.85) == pytest.approx(3.4, rel=1e-12)
    with pytest.raises(ValueError, match="arrangement must be one of"):
        cl.torque_sharing(name, 4, 0.85)


def test_the_om_stress_alone_is_disc_stresses_om_to_the_bit():
    # σ_OM = −4E/(1 − μ²) t²/(K1 De²) K4 (s/t) 3/π, by hand for De/Di = 40/20.4
    # (K1 = 0.6858...), and the same floats as the five-point function's OM
    from engine.physics import springs as sp

    s = np.linspace(0.0, 0.002, 57)
    om = sp.disc_stress_om(s, 0.040, 0.0204, 0.001, 0.002)
    np.testing.assert_array_equal(om, sp.disc_stresses(s, 0.040, 0.0204, 0.001, 0.002)["OM"])
    d = 0.040 / 0.0204
    k1 = ((d - 1) / d) ** 2 / ((d + 1) / (d - 1) - 2 / math.log(d)) / math.pi
    hand = -4 * 206e9 / (1 - 0.3**2) * 0.001**2 / (k1 * 0.040**2) * (0.0015 / 0.001) * 3 / math.pi
    assert float(sp.disc_stress_om(0.0015, 0.040, 0.0204, 0.001, 0.002)) == pytest.approx(
        hand, rel=1e-13
    )
