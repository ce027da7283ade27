"""Springs against printed numbers (engine/physics/springs.py).

Sources (see docs/sources.md):

* [Bhandari] V. B. Bhandari, *Design of Machine Elements*, Tata McGraw-Hill: chapter
  "Springs", Example 10.1 (a helical compression spring designed for P = 1250 N,
  δ = 30 mm, C = 6, S_ut = 1090 N/mm², τ = 0.5 S_ut, G = 81370 N/mm², squared and
  ground ends, 1 mm gap between coils) and Example 10.3 (a table of Wahl factors for
  C = 5…8), as worked in the FOSSEE Scilab Textbook Companion (book 764, chapter 10,
  files EX10.1.b/result10_1.txt and EX10.3.a/data10_3.sci), which print the results.
* [Carvill] J. Carvill, *Mechanical Engineer's Data Handbook*, Butterworth-Heinemann,
  1993, §1.5 "Belleville washer spring": a table of the factors k1, k2, k3 against
  Do/Di = 1.4…5.0, printed to two decimals.
* DIN EN 16983 (Almen–László): the force at flat has the closed form
  4E/(1 − μ²)·t³h0/(K1 De²); a disc sized to flatten at a given force must do so.
"""

import math

import pytest

from engine.physics import springs as sp

N_MM2 = 1e6


def test_bhandari_example_10_1_helical_spring():
    p, c, sut, g = 1250.0, 6.0, 1090.0, 81370.0
    tau = 0.5 * sut  # permissible shear stress, N/mm²
    k = sp.wahl_factor(c)
    # printed: wire diameter 6.625083 mm, rounded up to 7 mm
    d = math.sqrt(8 * k * p * c / (math.pi * tau))
    assert d == pytest.approx(6.625083, abs=5e-7)
    d, dm, n, nt = 7.0e-3, 42.0e-3, 8, 10  # printed: D = 42 mm, N = 8, Nt = 10
    rate = sp.helical_rate(g * N_MM2, d, dm, n)
    deflection = p / rate
    # printed free length 109.337611 mm = solid length Nt d + (Nt - 1) gaps of 1 mm + δ
    solid = sp.solid_length(d, n)  # squared and ground ends: n_t = n + 2 = Nt
    assert solid == pytest.approx(nt * d, rel=1e-12)
    assert (solid + (nt - 1) * 1e-3 + deflection) * 1e3 == pytest.approx(109.337611, abs=1e-6)
    # and the stress at 1250 N in the 7 mm wire stays below the permissible 545 N/mm²
    assert sp.helical_shear_stress(p, dm, d) / N_MM2 == pytest.approx(488.2, abs=0.05)


@pytest.mark.parametrize(
    ("index", "printed"),
    [(5, 1.311), (6, 1.253), (7, 1.213), (8, 1.184), (7.5, 1.197), (7.1, 1.210),
     (7.2, 1.206), (7.3, 1.203)],
)  # fmt: skip
def test_bhandari_example_10_3_wahl_factor_table(index, printed):
    # printed to three decimals (the companion's data file has "1,184" for C = 8, a typo)
    assert sp.wahl_factor(index) == pytest.approx(printed, abs=6e-4)


@pytest.mark.parametrize(
    ("ratio", "k1", "k2", "k3"),
    [(1.4, 0.46, 1.07, 1.14), (1.8, 0.64, 1.18, 1.30), (2.2, 0.73, 1.27, 1.46),
     (2.6, 0.76, 1.35, 1.60), (3.0, 0.78, 1.43, 1.74), (3.4, 0.80, 1.50, 1.88),
     (3.8, 0.80, 1.57, 2.00), (4.2, 0.80, 1.64, 2.14), (4.6, 0.80, 1.71, 2.26),
     (5.0, 0.79, 1.77, 2.38)],
)  # fmt: skip
def test_carvill_belleville_factor_table(ratio, k1, k2, k3):
    got = sp.disc_factors(ratio * 0.01, 0.01)
    # the table is printed to two decimals and read off the Almen–László curves: it
    # agrees with the closed forms to within one unit of its last digit (0.012 worst,
    # k3 at 4.2 and k2 at 1.8, 2.2)
    assert got == pytest.approx((k1, k2, k3), abs=0.012)


def test_disc_sized_to_flatten_at_a_given_force():
    # a DIN EN 16983 series-B proportion (h0/t = 0.75), De = 50 mm, Di = 25.4 mm, to be
    # flat at 5 kN: size the thickness, then the force at flat must be 5 kN exactly and
    # equal the Almen–László force at s = h0
    t = sp.disc_thickness_for_flat_force(5000.0, 0.050, 0.0254, 0.75)
    h0 = 0.75 * t
    assert sp.disc_force_flat(0.050, 0.0254, t, h0) == pytest.approx(5000.0, rel=1e-12)
    assert sp.disc_force(h0, 0.050, 0.0254, t, h0) == pytest.approx(5000.0, rel=1e-12)
    # closed form by hand: F_c = 4E/(1-mu^2) t^3 h0/(K1 De^2)
    k1, _, _ = sp.disc_factors(0.050, 0.0254)
    assert 4 * 206e9 / 0.91 * t**3 * h0 / (k1 * 0.05**2) == pytest.approx(5000.0, rel=1e-12)
