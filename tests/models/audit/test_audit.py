"""joint.audit: audit windows by hand, against a brute-force search, and against the joint model.

The M12 numbers are written out: P = 1.75 mm, d2 = d − 0.649519 P (ISO 724), d_w = 16.63 mm
(ISO 4017), d_h = 13.5 mm (ISO 273 medium), so D_Km/2 = (16.63 + 13.5)/4 = 7.5325 mm.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from engine import InputOutOfRange, get_model, run
from engine.models.audit import AUDIT, M12_AT_80
from engine.physics import audit as au
from tests.pins import pin

K_P = 0.16 * 1.75e-3  # VDI 2230-1 R13 pitch term [m]
D2 = 12e-3 - 0.649519 * 1.75e-3  # 10.8633 mm


def k_mu(mu_g: float, mu_k: float) -> float:
    """Friction part of the R13 torque per newton, written out: 0.58 d2 μ_G + μ_K D_Km/2."""
    return 0.58 * D2 * mu_g + mu_k * (16.63e-3 + 13.5e-3) / 4


LO, HI = k_mu(0.08, 0.08), k_mu(0.16, 0.16)


def test_windows_read_at_once_by_hand() -> None:
    r = run(AUDIT, M12_AT_80)
    v = r.results
    # mark, read at once while turning: the torque band itself
    pin("joint.audit", "mark_min", v["mark_min"], 76.0, rel=1e-12)
    pin("joint.audit", "mark_max", v["mark_max"], 84.0, rel=1e-12)
    # first motion: M_A (k_P + r k_μ)/(k_P + k_μ); rises with r and with friction
    pin("joint.audit", "first_motion_min", v["first_motion_min"], 76.0, rel=1e-12)
    pin(
        "joint.audit",
        "first_motion_max",
        v["first_motion_max"],
        84.0 * (K_P + 1.15 * HI) / (K_P + HI),
        rel=1e-12,
    )
    # breakaway: M_A (−k_P + r k_μ)/(k_P + k_μ)
    pin(
        "joint.audit",
        "breakaway_min",
        v["breakaway_min"],
        76.0 * (-K_P + LO) / (K_P + LO),
        rel=1e-12,
    )
    pin(
        "joint.audit",
        "breakaway_max",
        v["breakaway_max"],
        84.0 * (-K_P + 1.15 * HI) / (K_P + HI),
        rel=1e-12,
    )
    # the preload band: M_A,min/k(μ_max), M_A,max/k(μ_min)
    pin("joint.audit", "assembly_preload_min", v["assembly_preload_min"], 76.0 / (K_P + HI))
    pin("joint.audit", "assembly_preload_max", v["assembly_preload_max"], 84.0 / (K_P + LO))
    assert r.warnings and "rule of thumb" in r.warnings[0]


def test_the_joint_model_gives_the_preload_band_and_the_embedding_loss() -> None:
    r = run(AUDIT, M12_AT_80)
    j = run(get_model("joint.vdi2230"), M12_AT_80)
    f_z = j.results["embedding_loss"]
    pin("joint.audit", "embedding_loss", r.results["embedding_loss"], f_z, rel=1e-12)
    for name in ("assembly_preload_min", "assembly_preload_max"):
        pin("joint.audit", name, r.results[name], j.results[name], rel=1e-12)
    pin(
        "joint.audit",
        "residual_preload_min",
        r.results["residual_preload_min"],
        j.results["assembly_preload_min"] - f_z,
        rel=1e-12,
    )
    pin(
        "joint.audit",
        "residual_preload_max",
        r.results["residual_preload_max"],
        j.results["assembly_preload_max"] - f_z,
        rel=1e-12,
    )


def _brute_force(f_z: float, direction: float, ratios: tuple[float, float]) -> tuple[float, float]:
    """The reading written out on a fine grid of friction (μ_G × μ_K) and the band's corners."""
    mus = np.linspace(0.08, 0.16, 81)
    g, k = np.meshgrid(mus, mus)
    friction = 0.58 * D2 * g + k * (16.63e-3 + 13.5e-3) / 4
    readings = []
    for torque, ratio in itertools.product((76.0, 84.0), ratios):
        preload = np.maximum(torque / (K_P + friction) - f_z, 0.0)
        readings.append(preload * (direction * K_P + ratio * friction))
    every = np.concatenate([x.ravel() for x in readings])
    return float(every.min()), float(every.max())


@pytest.mark.parametrize(
    ("name", "direction", "ratios"),
    [
        ("first_motion", 1.0, (1.0, 1.15)),
        ("breakaway", -1.0, (1.0, 1.15)),
        ("mark", 1.0, (1.0, 1.0)),
    ],
)
def test_windows_after_embedding_hold_a_brute_force_search(name, direction, ratios) -> None:
    r = run(AUDIT, M12_AT_80)
    f_z = r.results["embedding_loss"]
    lo, hi = _brute_force(f_z, direction, ratios)
    got_lo, got_hi = r.results[f"{name}_embedded_min"], r.results[f"{name}_embedded_max"]
    # the exact extremes bound the grid's and lie within the grid's spacing of them
    assert got_lo <= lo + 1e-9 and got_hi >= hi - 1e-9
    assert got_lo == pytest.approx(lo, rel=1e-4)
    assert got_hi == pytest.approx(hi, rel=1e-4)


def test_embedded_windows_pinned() -> None:
    v = run(AUDIT, M12_AT_80).results
    f_z = v["embedding_loss"]
    # mark after embedding at kinetic friction: M_A − F_Z (k_P + k_μ); least at M_A,min, μ_max
    pin("joint.audit", "mark_embedded_min", v["mark_embedded_min"], 76.0 - f_z * (K_P + HI))
    pin("joint.audit", "mark_embedded_max", v["mark_embedded_max"], 84.0 - f_z * (K_P + LO))
    # first motion and breakaway at r = 1 least: (M_A,min/(k_P + k_μ) − F_Z)(±k_P + k_μ) at μ_max
    pin(
        "joint.audit",
        "first_motion_embedded_min",
        v["first_motion_embedded_min"],
        (76.0 / (K_P + HI) - f_z) * (K_P + HI),
        rel=1e-12,
    )
    brute_lo, _ = _brute_force(f_z, -1.0, (1.0, 1.15))
    pin("joint.audit", "breakaway_embedded_min", v["breakaway_embedded_min"], brute_lo, rel=1e-9)
    _, brute_hi = _brute_force(f_z, 1.0, (1.0, 1.15))
    pin(
        "joint.audit",
        "first_motion_embedded_max",
        v["first_motion_embedded_max"],
        brute_hi,
        rel=1e-4,
    )
    _, brute_hi = _brute_force(f_z, -1.0, (1.0, 1.15))
    pin("joint.audit", "breakaway_embedded_max", v["breakaway_embedded_max"], brute_hi, rel=1e-4)


def test_the_loosening_relation_against_the_helix_work_balance() -> None:
    """VDI's −0.16 P + 0.58 d2 μ against the exact helix, derived here by a force balance.

    Nut on a thread of lead angle ψ and flank angle 30°, pushed down the helix by the preload
    F while a wrench turns it loose: along the helix the wrench's force M/(d2/2) and the
    load's component F sin ψ drive, friction μ' N resists with N ≈ F cos ψ /cos 30° on the
    flank (μ' = μ/cos 30°). Tangential and axial balance give
    M = F (d2/2) (μ' cos ψ − sin ψ)/(cos ψ + μ' sin ψ) = F (d2/2) tan(ρ' − ψ).
    With no friction the work balance is exact: the load gives back F P per turn, so
    M · 2π = −F P.
    """
    pitch, d2, force = 1.75e-3, 10.863e-3, 40e3
    psi = math.atan(pitch / (math.pi * d2))
    for mu in (0.0, 0.08, 0.12, 0.16):
        mu_flank = mu / math.cos(math.radians(30.0))
        exact = force * d2 / 2 * (mu_flank * math.cos(psi) - math.sin(psi))
        exact /= math.cos(psi) + mu_flank * math.sin(psi)
        thread_only = au.audit_torque_per_preload(
            au.pitch_torque_per_preload(pitch, d2), 0.58 * d2 * mu, 1.0, au.LOOSENING
        )
        vdi = force * thread_only
        if mu == 0.0:
            # work balance: −F P/(2π) against VDI's −0.16 F P (0.16 rounds 1/(2π) = 0.15915)
            assert exact == pytest.approx(-force * pitch / (2 * math.pi), rel=1e-12)
            assert vdi == pytest.approx(exact, rel=0.0054)
        else:
            # VDI linearises tan(ρ' − ψ): within 2 % of the thread torque, plus 0.16 vs 1/(2π)
            assert vdi == pytest.approx(exact, rel=0.02), mu


def test_a_lubricated_joint_with_a_low_friction_floor_is_flagged_not_self_locking() -> None:
    r = run(AUDIT, {**M12_AT_80, "thread_friction_min": 0.02, "bearing_friction_min": 0.0})
    checks = {c.name: c.ok for c in r.checks}
    # −0.28 + 0.58 · 10.863 · 0.02 = −0.154 mm per newton: the thread alone would back off
    assert checks["self_locking"] is False
    assert r.results["breakaway_min"] < 0.0


def test_refusals_name_the_field() -> None:
    with pytest.raises(InputOutOfRange) as err:
        run(
            AUDIT,
            {**M12_AT_80, "static_friction_ratio_min": 1.3, "static_friction_ratio_max": 1.1},
        )
    assert err.value.field == "static_friction_ratio_min"
    bare = {k: v for k, v in M12_AT_80.items() if k != "tightening_torque"}
    with pytest.raises(InputOutOfRange) as err:
        run(AUDIT, bare)
    assert err.value.field == "tightening_torque"
