"""joint.clamp_capability at a service temperature: F_M,zul and ν are assembly quantities,
so they keep the room-temperature R_p0.2 of joint.vdi2230's R7 (the bolt is tightened cold),
and without a temperature nothing changes.

ISO 898-1 Annex A (as [NFG-898T] reprints it) gives class 8.8 R_p0.2 = 640 MPa at 20 °C
(540 MPa at 200 °C, which only R8 uses); VDI 2230-1 R7 is typed here, not taken from the
engine.
"""

from __future__ import annotations

import math

from engine import run
from engine.models.clamp import CLAMP_CAPABILITY, M12_JOINT
from engine.models.joint import VDI2230
from tests.pins import pin

MODEL = "joint.clamp_capability"
P, D = 1.75e-3, 12e-3
D2 = D - 0.649519 * P
D3 = D - 1.226869 * P
AS = math.pi / 4 * (0.5 * (D2 + D3)) ** 2
DW, DH = 16.63e-3, 13.5e-3
RP_20C = 640e6  # ISO 898-1, 8.8 at 20 °C (R7 at assembly)
HOT = 473.15  # 200 °C in K
FIXED = {
    "thread_friction_law": "fixed",
    "thread_friction_mean": 0.12,
    "bearing_friction_law": "fixed",
    "bearing_friction_mean": 0.12,
}


def f_zul(mu_g: float, nu: float, rp: float) -> float:
    """VDI 2230-1 R7: ν R_p A_s / √(1 + 3 (1.5 d2/d_s (P/(π d2) + 1.155 μ_G))²)."""
    d_s = 0.5 * (D2 + D3)
    ratio = 1.5 * D2 / d_s * (P / (math.pi * D2) + mu_g / math.cos(math.radians(30)))
    return nu * rp * AS / math.sqrt(1 + 3 * ratio**2)


def test_at_200_c_f_zul_is_joint_vdi2230s_cold_r7() -> None:
    """At 200 °C the capability's F_M,zul (fixed μ_G = 0.12) is joint.vdi2230's R7 for the same
    joint and friction, both at the room-temperature 640 MPa written out here (tightened cold)."""
    x = {**M12_JOINT, "nominal_torque": 80.0, "torque_sd": 2.0, **FIXED}
    hot = run(CLAMP_CAPABILITY, {**x, "service_temperature": HOT}).results
    joint = run(
        VDI2230,
        {
            **M12_JOINT,
            "thread_friction_min": 0.12,
            "thread_friction_max": 0.12,
            "bearing_friction_min": 0.12,
            "bearing_friction_max": 0.12,
            "tightening_torque": 80.0,
            "service_temperature": HOT,
        },
        budget_s=None,
    ).results
    assert hot["permissible_preload"] == joint["permissible_preload"]
    pin(
        MODEL,
        "permissible_preload",
        hot["permissible_preload"],
        f_zul(0.12, 0.9, RP_20C),
        rel=1e-6,
    )
    # ν of the median preload, F_M = (M_A − M_ü)/k, against the cold R_p0.2
    k = 0.16 * P + 0.58 * D2 * 0.12 + 0.12 * (DW + DH) / 4
    nu = (80.0 - 0.4) / k / f_zul(0.12, 1.0, RP_20C)
    pin(MODEL, "utilisation_median", hot["utilisation_median"], nu, rel=1e-6)
    # the same process: F_M,zul, ν and the share above F_M,zul do not move with T
    cold = run(CLAMP_CAPABILITY, x).results
    for name in ("permissible_preload", "utilisation_median", "high_ppm"):
        assert hot[name] == cold[name], name


def test_20_c_is_room_temperature_in_every_output() -> None:
    """service_temperature = 20 °C (ratios 1) gives every example's outputs bit for bit as
    no temperature does: the room-temperature path is the one the examples always took."""
    for example in CLAMP_CAPABILITY.examples:
        cold = run(CLAMP_CAPABILITY, dict(example)).results
        room = run(CLAMP_CAPABILITY, {**example, "service_temperature": 293.15}).results
        assert room == cold


def test_examples_keep_their_room_temperature_f_zul() -> None:
    """Without a temperature F_M,zul stays R7 at 640 MPa (examples' median μ_G = 0.12)."""
    for example in CLAMP_CAPABILITY.examples:
        r = run(CLAMP_CAPABILITY, dict(example)).results
        pin(
            MODEL,
            "permissible_preload",
            r["permissible_preload"],
            f_zul(0.12, 0.9, 640e6),
            rel=1e-6,
        )
