"""Hand-computed cases, limits and invariants of engine.physics.preload."""

import math

import numpy as np
import pytest

from engine.physics import preload as pl
from engine.physics import threads as th

M12 = {"d": 0.012, "P": 0.00175, "d2": th.pitch_diameter(0.012, 0.00175)}
M12["d0"] = th.stress_diameter(0.012, 0.00175)
M12["As"] = th.stress_area(0.012, 0.00175)


def test_torsion_factor_vdi_by_hand():
    # M12, μ_G = 0.12: P/(π d2) = 1.75/(π·10.8633) = 0.051277; 1.155·0.12 ≈ 0.138564
    # (3/2)(d2/d0) = 1.5·10.86334/10.35816 = 1.573157; product = 0.298650
    # β = sqrt(1 + 3·0.298650²) = sqrt(1.267576) = 1.125867
    beta = pl.torsion_factor(M12["P"], M12["d2"], M12["d0"], 0.12)
    assert beta == pytest.approx(1.125867, rel=1e-6)


def test_torsion_factor_elastic_by_hand_and_in_source_range():
    # ψ = atan(0.051277) = 2.9354°, ρ' = atan(0.138564) = 7.8889°, tan(10.8243°) = 0.191200
    # τ/σ = 2·(10.86334/10.35816)·0.191200 = 0.401050; β = sqrt(1 + 3·0.160841) = 1.217589
    beta = pl.torsion_factor(M12["P"], M12["d2"], M12["d0"], 0.12, "elastic")
    assert beta == pytest.approx(1.217589, rel=1e-6)
    # [004, eq. 5]: "usually β = 1.19…1.50" for ordinary friction 0.1…0.2
    for mu in (0.10, 0.15, 0.20):
        b = pl.torsion_factor(M12["P"], M12["d2"], M12["d0"], mu, "elastic")
        assert 1.15 < b < 1.55


def test_assembly_preload_by_hand():
    # 0.9·640e6·84.2665e-6 / 1.125872 = 48537.5 / 1.125872 = 43111.2 N
    beta = pl.torsion_factor(M12["P"], M12["d2"], M12["d0"], 0.12)
    force = pl.assembly_preload(640e6, M12["As"], beta, 0.9)
    assert force == pytest.approx(43111.2, rel=1e-5)


def _equivalent_stress_first_principles(force, bolt, mu, convention):
    """σ_red = sqrt(σ² + 3τ²) from σ = F/A0 and τ = k·M_G/W_p, written out independently."""
    d2, d0, pitch = bolt["d2"], bolt["d0"], bolt["P"]
    sigma = force / (math.pi / 4 * d0**2)
    w_p = math.pi * d0**3 / 16
    if convention == "elastic":
        psi = math.atan(pitch / (math.pi * d2))
        rho = math.atan(mu / math.cos(math.radians(30)))
        tau = force * d2 / 2 * math.tan(psi + rho) / w_p
    else:  # VDI 2230: linearised thread torque, torsion reduced to 3/4 (plastic)
        tau = 0.75 * force * d2 / 2 * (pitch / (math.pi * d2) + mu / math.cos(math.radians(30)))
        tau /= w_p
    return math.hypot(sigma, math.sqrt(3) * tau)


@pytest.mark.parametrize("convention", ["vdi2230", "elastic"])
@pytest.mark.parametrize(("d", "p"), [(0.006, 0.001), (0.012, 0.00175), (0.030, 0.002)])
@pytest.mark.parametrize("mu", [0.0, 0.08, 0.14, 0.3])
@pytest.mark.parametrize("nu", [0.5, 0.9, 1.0])
def test_preload_at_nu_is_largest_with_equivalent_stress_nu_yield(convention, d, p, mu, nu):
    bolt = {"d2": th.pitch_diameter(d, p), "d0": th.stress_diameter(d, p), "P": p}
    yield_strength = 640e6
    target = nu * yield_strength
    lo, hi = 0.0, yield_strength * math.pi / 4 * bolt["d0"] ** 2  # σ_red(hi) ≥ R_p0.2 ≥ target
    for _ in range(200):  # bisection on the monotonic σ_red(F)
        mid = 0.5 * (lo + hi)
        if _equivalent_stress_first_principles(mid, bolt, mu, convention) <= target:
            lo = mid
        else:
            hi = mid
    beta = pl.torsion_factor(p, bolt["d2"], bolt["d0"], mu, convention)
    force = pl.assembly_preload(yield_strength, th.stress_area(d, p), beta, nu)
    assert force == pytest.approx(lo, rel=1e-9)
    assert pl.equivalent_stress(force, th.stress_area(d, p), beta) == pytest.approx(target)


def test_thread_torque_without_friction_is_the_ideal_torque():
    # μ = 0: M_p = F (d2/2) tan ψ = F (d2/2) P/(π d2) = F P/(2π)  [004, eq. 10 → eq. 14]
    force = 40e3
    assert pl.thread_torque(force, M12["P"], M12["d2"], 0.0) == pytest.approx(
        pl.ideal_torque(force, M12["P"]), rel=1e-12
    )
    # 40000·0.00175/(2π) = 11.1408 N·m
    assert pl.ideal_torque(force, M12["P"]) == pytest.approx(11.14085, rel=1e-6)


def test_friction_radius_by_hand_and_both_forms():
    # D = 20, d = 10 mm: (8000 − 1000)/(3·(400 − 100)) = 7000/900 = 7.7778 mm
    assert pl.friction_radius(0.020, 0.010) == pytest.approx(7.77778e-3, rel=1e-6)
    # solid face (d_h = 0): R_T = D/3
    assert pl.friction_radius(0.018, 0.0) == pytest.approx(0.006, rel=1e-12)


@pytest.mark.parametrize("gap", [1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 0.0])
def test_friction_radius_stays_exact_as_the_face_vanishes(gap):
    inner = 0.0135
    outer = inner * (1 + gap)
    r = pl.friction_radius(outer, inner)
    assert math.isfinite(r)
    # limit (D_f + d_h)/4 plus the exact excess (D_f − d_h)²/(12(D_f + d_h))
    expected = (outer + inner) / 4 + (outer - inner) ** 2 / (12 * (outer + inner))
    assert r == pytest.approx(expected, rel=1e-14)


def test_friction_radius_exceeds_half_mean_diameter_by_known_amount():
    for outer, inner in [(0.01663, 0.0135), (0.03361, 0.026), (0.02, 0.0)]:
        excess = pl.friction_radius(outer, inner) - (outer + inner) / 4
        assert excess == pytest.approx((outer - inner) ** 2 / (12 * (outer + inner)), rel=1e-10)


@pytest.mark.parametrize("size", [3.0, 6.0, 10.0, 16.0, 24.0, 39.0])
@pytest.mark.parametrize("mu", [0.0, 0.04, 0.12, 0.2, 0.3])
def test_vdi_and_exact_torques_agree_within_their_known_difference(size, mu):
    d = size * 1e-3
    for p in th.standard_pitches(d):
        d2 = th.pitch_diameter(d, p)
        dw, dh = th.hex_bearing_diameter(d), th.clearance_hole(d)
        kg_v, kk_v = pl.tightening_torque_per_preload(p, d2, d, mu, mu, dw, dh, "vdi2230")
        kg_e, kk_e = pl.tightening_torque_per_preload(p, d2, d, mu, mu, dw, dh, "exact")
        # thread: VDI drops tanψ·tanρ' from tan(ψ+ρ') = (tanψ + tanρ')/(1 − tanψ tanρ')
        # and rounds 1/(2π) to 0.16 (+0.53 %) and 1/(2 cos 30°) to 0.58 (+0.46 %)
        t_psi, t_rho = p / (math.pi * d2), mu / math.cos(math.radians(30))
        bound = t_psi * t_rho / (1 - t_psi * t_rho) + 0.0054
        assert abs(kg_v / kg_e - 1) <= bound
        # bearing: D_Km/2 against R_T differs by exactly (D−d)²/(12(D+d))
        assert kk_e - kk_v == pytest.approx(mu * (dw - dh) ** 2 / (12 * (dw + dh)), abs=1e-15)


def test_vdi_tightening_torque_by_hand():
    # M12 8.8, μ = 0.12, F = 43111.2 N: 0.16·1.75 = 0.28; 0.58·10.863342·0.12 = 0.756089;
    # D_Km = (16.63 + 13.5)/2 = 15.065, 0.12·15.065/2 = 0.9039 → 1.939989 mm · 43111.2 N
    torque = pl.vdi_tightening_torque(43111.2, 0.00175, M12["d2"], 0.12, 0.12, 0.01663, 0.0135)
    assert torque == pytest.approx(43111.2 * 1.939989e-3, rel=1e-6)


def test_approximate_torque_and_rule_of_thumb():
    # [004, eq. 15] with f = 0.15, R_T = 0.7 d, P = d/8:
    # F d [0.5 (1/(8π) + 1.15·0.15) + 0.15·0.7] = F d [0.5·(0.039789 + 0.1725) + 0.105]
    # = 0.211145 F d, which the review rounds to 0.2 F d [004, eq. 16]
    d, force = 0.016, 50e3
    approx = pl.approximate_tightening_torque(force, d, d / 8, 0.15, 0.15, 0.7 * d)
    assert approx == pytest.approx(0.211145 * force * d, rel=1e-5)
    assert pl.rule_of_thumb_torque(force, d) == pytest.approx(0.2 * force * d)
    # eq. 19 with one coefficient gives the same number as eq. 15
    single = pl.single_friction_tightening_torque(force, d, d / 8, 0.15, 0.7 * d)
    assert single == pytest.approx(approx, rel=1e-12)


def test_yield_rule_of_thumb_follows_from_eq_16_and_17():
    # σ0 = 0.6 σ_T on the core d1 ≈ 0.85 d: F0 = 0.6 σ_T π/4 (0.85 d)²;
    # 0.2 F0 d = 0.2·0.6·π/4·0.7225 σ_T d³ = 0.068094 σ_T d³ ≈ 0.07 σ_T d³ [004, eq. 18]
    sigma, d = 900e6, 0.02
    f0 = 0.6 * sigma * math.pi / 4 * (0.85 * d) ** 2
    from_eq16 = pl.rule_of_thumb_torque(f0, d)
    assert from_eq16 == pytest.approx(0.068094 * sigma * d**3, rel=1e-4)
    assert pl.rule_of_thumb_torque_from_yield(sigma, d) == pytest.approx(from_eq16, rel=0.03)


def test_equivalent_diameter_has_the_same_compliance():
    lengths, diameters = [0.03, 0.05, 0.004], [0.012, 0.009, 0.00985]
    d_eq = pl.equivalent_shank_diameter(lengths, diameters)
    assert pl.axial_compliance([sum(lengths)], [d_eq], 2.1e11) == pytest.approx(
        pl.axial_compliance(lengths, diameters, 2.1e11), rel=1e-12
    )
    # one section: d_eq is its diameter
    assert pl.equivalent_shank_diameter([0.1], [0.01]) == pytest.approx(0.01)


def test_angle_and_elongation_through_one_compliance():
    # [004, eq. 7 and 9]: Δl = F λ_b and φ = 2π F λ_b / P, so Δl = φ P/(2π): the nut
    # advances one pitch per turn and all of it goes into the bolt when the parts are rigid
    lam = pl.axial_compliance([0.08, 0.04], [0.012, 0.00985], 2.1e11)
    force = 35e3
    dl = pl.elongation(force, lam)
    phi = pl.nut_rotation_angle(force, lam, 0.00175)
    assert dl == pytest.approx(phi * 0.00175 / (2 * math.pi), rel=1e-12)
    assert pl.preload_from_elongation(dl, lam) == pytest.approx(force, rel=1e-12)
    # eq. 8 in degrees: φ° = 360 F Σλ / P
    assert math.degrees(phi) == pytest.approx(360 * force * lam / 0.00175, rel=1e-12)


def test_tightening_factor_and_scatter_are_inverse():
    assert pl.tightening_factor(0.30) == pytest.approx(1.3 / 0.7)
    assert pl.tightening_factor(0.10) == pytest.approx(1.1 / 0.9)
    for s in np.linspace(0, 0.9, 10):
        assert pl.scatter_from_tightening_factor(pl.tightening_factor(s)) == pytest.approx(s)


def test_preload_factor_ranges_of_eq_2():
    assert pl.preload_factor_range("steady") == (1.25, 2.0)
    assert pl.preload_factor_range("varying") == (2.5, 4.0)


def _hist(**kw):
    args = dict(
        torque=80.0,
        pitch=0.0254 / 11,
        pitch_diameter=th.pitch_diameter(0.015875, 0.0254 / 11),
        diameter=0.015875,
        thread_friction_range=(0.10, 0.20),
        bearing_friction_range=(0.10, 0.20),
        bearing_outer_diameter=0.0226,
        hole_diameter=0.0175,
    )
    args.update(kw)
    return pl.friction_scatter_histogram(**args)


def test_histogram_is_reproducible_and_counts_add_up():
    a, b = _hist(), _hist()
    assert np.array_equal(a.counts, b.counts) and np.array_equal(a.bin_centres, b.bin_centres)
    assert a.counts.sum() == pytest.approx(38.0)
    assert a.minimum < a.mean < a.maximum
    assert a.bin_centres[0] > a.minimum and a.bin_centres[-1] < a.maximum
    # extremes by hand: F = M / (k_G + k_K) at μ = 0.1 and 0.2 (corners, less half a grid step)
    kg, kk = pl.tightening_torque_per_preload(
        0.0254 / 11, th.pitch_diameter(0.015875, 0.0254 / 11), 0.015875, 0.2, 0.2, 0.0226, 0.0175
    )
    assert a.minimum == pytest.approx(80.0 / (kg + kk), rel=0.01)
    assert a.minimum > 80.0 / (kg + kk)


def test_histogram_without_scatter_is_one_spike():
    h = _hist(thread_friction_range=(0.12, 0.12), bearing_friction_range=(0.12, 0.12), bins=5)
    assert h.counts.sum() == pytest.approx(38.0)
    assert np.count_nonzero(h.counts) == 1
    assert h.minimum == pytest.approx(h.maximum) and h.std == pytest.approx(0.0, abs=1e-6)


def test_histogram_with_zero_friction_stays_finite():
    h = _hist(thread_friction_range=(0.0, 0.0), bearing_friction_range=(0.0, 0.0))
    # only the lead remains: F = 2π M / P
    assert h.mean == pytest.approx(
        2 * math.pi * 80.0 / (0.16 * 2 * math.pi * 0.0254 / 11), rel=1e-9
    )
    assert np.all(np.isfinite(h.bin_centres)) and np.all(np.isfinite(h.counts))
