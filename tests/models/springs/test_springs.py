"""engine.physics.springs: helical springs (EN 13906-1) and disc springs (DIN EN 16983).

Hand-computed values, limits where two forms agree, invariants over grids.
Printed textbook numbers are pinned in tests/validation/test_springs_textbooks.py.
"""

import math

import numpy as np
import pytest

from engine.core.errors import InputOutOfRange
from engine.physics import springs as sp


def test_rate_and_stress_by_hand():
    # G d^4/(8 D^3 n) = 8e10 * 2.56e-10 / (8 * 9.1125e-5 * 5) = 20.48/3.645e-3 = 5618.66 N/m
    assert sp.helical_rate(8e10, 0.004, 0.045, 5) == pytest.approx(5618.6557, rel=1e-7)
    # uncorrected 8FD/(pi d^3): 8*100*0.045/(pi*6.4e-8) = 179.05 MPa
    tau0 = sp.helical_shear_stress(100.0, 0.045, 0.004, "none")
    assert tau0 == pytest.approx(36.0 / (math.pi * 6.4e-8), rel=1e-12)
    # corrected = k * uncorrected for both factors
    for name, fn in sp.CORRECTIONS.items():
        assert sp.helical_shear_stress(100.0, 0.045, 0.004, name) == pytest.approx(
            fn(11.25) * tau0, rel=1e-12
        )


def test_bergstrasser_and_wahl_agree_within_1_5_percent_for_usual_indices():
    w = np.linspace(4.0, 20.0, 161)
    ratio = sp.wahl_factor(w) / sp.bergstrasser_factor(w)
    assert np.all(ratio >= 1.0) and np.all(ratio < 1.015)
    # both tend to 1 for slender coils (curvature vanishes): at w = 1000 within 0.2 %
    assert sp.wahl_factor(1000.0) == pytest.approx(1.0, abs=2e-3)
    assert sp.bergstrasser_factor(1000.0) == pytest.approx(1.0, abs=2e-3)


def test_unknown_correction_is_refused():
    with pytest.raises(ValueError):
        sp.stress_correction_factor(6.0, "goodman")


def test_solid_length_and_clearance():
    assert sp.solid_length(0.004, 5) == pytest.approx(0.028)
    assert sp.solid_length(0.004, 5, ground_ends=False) == pytest.approx(0.034)
    # (0.0015*45^2/4 + 0.4) * 5 = (0.759375 + 0.4) * 5 = 5.796875 mm; dynamic x1.5
    assert sp.minimum_gap_sum(0.004, 0.045, 5) == pytest.approx(5.796875e-3, rel=1e-12)
    assert sp.minimum_gap_sum(0.004, 0.045, 5, dynamic=True) == pytest.approx(
        1.5 * 5.796875e-3, rel=1e-12
    )


def test_buckling_limits():
    # a short fat spring with fixed ends cannot buckle
    assert math.isinf(sp.buckling_deflection(0.05, 0.045, 0.5, 81.5e9, 206e9))
    # more slender (larger nu) buckles earlier; s_K never exceeds the free length
    lengths = np.linspace(0.1, 0.5, 9)
    for nu in (0.5, 0.7, 1.0, 2.0):
        s_k = sp.buckling_deflection(lengths, 0.02, nu, 81.5e9, 206e9)
        finite = np.isfinite(s_k)
        assert np.all(s_k[finite] < lengths[finite])
    assert sp.buckling_deflection(0.3, 0.02, 2.0, 81.5e9, 206e9) < sp.buckling_deflection(
        0.3, 0.02, 1.0, 81.5e9, 206e9
    )
    # at the threshold (root = 0) s_K = L0 * 0.5/(1 - G/E)
    r = 81.5 / 206
    l0 = math.pi * 0.02 / (2.0 * math.sqrt((0.5 + r) / (1 - r)))
    assert sp.buckling_deflection(l0, 0.02, 2.0, 81.5e9, 206e9) == pytest.approx(
        l0 * 0.5 / (1 - r), rel=1e-6
    )


def test_natural_frequency_matches_the_standards_mm_form():
    # EN 13906-1 prints f = 3.56e3 d/(n D^2) sqrt(G/rho) with d, D in mm, G in N/mm^2,
    # rho in kg/dm^3: the SI form here must give the same within the 3-digit constant
    f = sp.helical_natural_frequency(0.004, 0.045, 5, 81.5e9, 7850.0)
    mm_form = 3.56e3 * 4 / (5 * 45**2) * math.sqrt(81500 / 7.85)
    assert f == pytest.approx(mm_form, rel=5e-4)
    # and is half the frequency sqrt(R/m) of the active coils' mass on the rate
    rate = sp.helical_rate(81.5e9, 0.004, 0.045, 5)
    mass = 7850.0 * math.pi**2 * 0.004**2 * 0.045 * 5 / 4
    assert f == pytest.approx(0.5 * math.sqrt(rate / mass), rel=1e-12)


def test_material_tables():
    assert sp.tensile_strength("EN10270-1-DH", 0.004) == 1740e6
    assert sp.tensile_strength("EN10270-1-SH", 0.004) == sp.tensile_strength("EN10270-1-DH", 0.004)
    # between rows: the next larger tabulated diameter (the lower strength, safe side)
    assert sp.tensile_strength("EN10270-1-SH", 0.0041) == 1690e6
    assert sp.tensile_strength("1.4310", 0.001) == 1900e6
    assert sp.permissible_shear_stress("1.4310", 0.001) == 950e6
    for m in sp.MATERIALS.values():
        rows = [rm for _, rm in m.strength]
        assert rows == sorted(rows, reverse=True), "strength falls with wire size"
    with pytest.raises(InputOutOfRange):
        sp.tensile_strength("1.4310", 0.012)  # EN 10270-3 stops at 10 mm
    with pytest.raises(InputOutOfRange):
        sp.tensile_strength("unobtainium", 0.001)


def test_standard_wire_sizes():
    assert sp.nearest_standard_wire(0.00425) == (pytest.approx(0.00425), True)
    near, ok = sp.nearest_standard_wire(0.0044)
    assert not ok and near == pytest.approx(0.0045)
    assert list(sp.STANDARD_WIRE_DIAMETERS) == sorted(sp.STANDARD_WIRE_DIAMETERS)


GEOM = dict(outer_diameter=0.040, inner_diameter=0.0204, thickness=0.00225, cone_height=0.0009)


def test_disc_force_at_flat_is_the_closed_form():
    for h0_t in (0.4, 0.75, 1.3, 2.0):
        g = {**GEOM, "cone_height": h0_t * GEOM["thickness"]}
        assert sp.disc_force(g["cone_height"], **g) == pytest.approx(
            sp.disc_force_flat(**g), rel=1e-12
        )


def test_disc_force_small_deflection_is_linear_with_the_cone_rate():
    # dF/ds at s = 0: 4E/(1-mu^2) t^3/(K1 De^2) (h0^2/t^2 + 1)
    k1, _, _ = sp.disc_factors(0.040, 0.0204)
    slope = 4 * 206e9 / 0.91 * 0.00225**3 / (k1 * 0.04**2) * ((0.9 / 2.25) ** 2 + 1)
    s = 1e-9
    assert sp.disc_force(s, **GEOM) / s == pytest.approx(slope, rel=1e-5)


def test_disc_stress_om_is_linear_and_compressive():
    s = np.linspace(0.0, 0.0009, 10)[1:]
    om = sp.disc_stresses(s, **GEOM)["OM"]
    assert np.all(om < 0)
    assert np.allclose(om / s, om[0] / s[0], rtol=1e-12)


def test_falling_region_is_where_the_rate_is_negative():
    t, h0 = 0.001, 0.002
    lo, hi = sp.disc_falling_region(t, h0)
    g = dict(outer_diameter=0.05, inner_diameter=0.0254, thickness=t, cone_height=h0)
    eps = 1e-7
    rate = lambda s: (sp.disc_force(s + eps, **g) - sp.disc_force(s - eps, **g)) / (2 * eps)  # noqa: E731
    assert rate(lo) == pytest.approx(0.0, abs=1e-3 * rate(0.0))
    assert rate(0.5 * (lo + hi)) < 0 < rate(0.5 * lo)
    assert math.isnan(sp.disc_falling_region(0.001, 0.00141)[0])  # h0/t just below sqrt(2)
    assert not math.isnan(sp.disc_falling_region(0.001, 0.00142)[0])
    # on arrays: the same per entry, NaN where the force rises everywhere
    lo_arr, _ = sp.disc_falling_region(np.array([t, 0.001]), np.array([h0, 0.00141]))
    assert lo_arr[0] == lo and math.isnan(lo_arr[1])


def test_stack_friction_raises_loading_and_lowers_unloading():
    up = sp.stack_force(1000.0, 3, 0.03, 0.03, loading=True)
    down = sp.stack_force(1000.0, 3, 0.03, 0.03, loading=False)
    assert up == pytest.approx(3000 / 0.91) and down == pytest.approx(3000 / 1.09)
    assert sp.stack_force(1000.0, 3) == 3000.0


def test_k4_is_one_without_flats_and_grows_with_the_reduction():
    for l0 in (0.0100, 0.0106, 0.0120):
        assert sp.disc_k4(0.008, 0.008, l0) == pytest.approx(1.0, abs=1e-12)
    k = [sp.disc_k4(0.008, t, 0.0106) for t in (0.0080, 0.0078, 0.0076, 0.0075)]
    assert k == sorted(k) and k[-1] > 1.0
    # with K4 the flats disc (t', h0' = l0 - t') is stiffer than the same t', h0' without
    t_r = 0.0075
    h0r = 0.0106 - t_r
    args = (0.125, 0.064, t_r, h0r)
    assert sp.disc_force(0.5 * h0r, *args, k4=sp.disc_k4(0.008, t_r, 0.0106)) > sp.disc_force(
        0.5 * h0r, *args
    )
