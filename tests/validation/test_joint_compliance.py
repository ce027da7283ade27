"""joint.vdi2230's compliances against an independent implementation and a handbook example.

Independent implementation: misams/BAT v0.8.4 (https://github.com/misams/BAT, ``src/Ecss.py``,
an ECSS-E-HB-32-23A calculator with VDI 2230 nomenclature). We ran its ``Ecss`` class side by
side with ``engine.physics.joint`` on 2026-11-23 (its own input files, its material and bolt
databases) and pin its outputs here, in mm/N as it prints them:

* its cone/sleeve formula (ECSS eq. 7.6.10/7.6.11, VDI 2230-1 R3) puts the nominal diameter d
  where VDI 2230 has the clearance hole d_h; with d passed as the hole our cone integral
  reproduces BAT to 7 digits in every regime (full cone, wide plate, partial cone + sleeve);
* for a tapped joint BAT uses ECSS's cone fit tan φ = 1.295 − 0.246 ln β_L + 0.94 ln y, not
  VDI's; with that tan φ passed in, our integral reproduces it;
* for plates of different E, BAT spreads one substitute area over the plates; we integrate
  each plate's part of the cone (VDI 2230-1 §5.1.2.2): +5.5 % on its mixed Ti/steel case.

Handbook: ECSS-E-HB-32-23A worked example §7.14 (M6 socket, A286 bolt, 2 + 3 mm 7075-T7351,
13.65 N·m ± 0.65 N·m, prevailing 0.4…2.0 N·m, μ_head 0.176…0.296, μ_thread 0.086…0.176):
F_M,min = 5717.85 N, F_M,max = 12078.55 N (pp. 105–106, as quoted in BAT's tests/tests.py;
BAT itself prints 5717.6 / 12078.1 N).
"""

import math

import pytest

from engine.physics import joint as jt
from engine.physics import preload as pl

MM_PER_N = 1e-3  # BAT prints compliances in mm/N

# (case, d [mm], d_uh [mm], D_A [mm], plates [(h mm, E MPa)], joint, BAT δ_c [mm/N])
BAT_CASES = [
    ("ECSS 7.14 M6, 2+3 mm Al", 6, 10.0, 24, [(2, 71000), (3, 71000)], "through", 1.044217e-06),
    ("M12, 2x20 mm steel, D_A 40", 12, 16.6, 40, [(20, 2e5), (20, 2e5)], "through", 6.062358e-07),
    ("M12, 2x20 mm steel, D_A 200", 12, 16.6, 200, [(20, 2e5), (20, 2e5)], "through", 4.604975e-07),
    ("M10 tapped, 15 mm, D_A 30", 10, 14.6, 30, [(15, 2e5)], "tapped", 1.678373e-07),
]


def _bat_tangent(grip, bearing, outer, joint):
    """ECSS's cone fits as BAT implements them (through = VDI's)."""
    x, y = grip / bearing, outer / bearing
    if joint == "through":
        return 0.362 + 0.032 * math.log(x / 2) + 0.153 * math.log(y)
    return 1.295 - 0.246 * math.log(x) + 0.94 * math.log(y)


@pytest.mark.parametrize(("case", "d", "dw", "da", "plates", "joint", "bat"), BAT_CASES)
def test_cone_and_sleeve_match_bat_side_by_side(case, d, dw, da, plates, joint, bat):
    grip = sum(h for h, _ in plates)
    c = jt.clamped_compliance(
        [h * 1e-3 for h, _ in plates],
        [e * 1e6 for _, e in plates],
        dw * 1e-3,
        d * 1e-3,  # BAT's formula takes d where VDI has d_h
        da * 1e-3,
        joint,
        tangent=_bat_tangent(grip, dw, da, joint),
    )
    assert c.total / MM_PER_N == pytest.approx(bat, rel=2e-6)


def test_through_bolted_cone_angle_is_the_same_fit_as_bat():
    # VDI 2230-1 R3 tan φ_D: identical to BAT's TBJ fit
    assert jt.cone_tangent(0.040, 0.0166, 0.040, "through") == pytest.approx(
        _bat_tangent(40, 16.6, 40, "through"), rel=1e-12
    )


def test_mixed_plates_differ_from_bat_by_its_substitute_area():
    # BAT case M8 hex (d_uh 11.6 mm), Ti 3 mm + S355 5 + 5 mm, D_A 30 mm:
    # BAT prints 7.124590e-07 mm/N
    c = jt.clamped_compliance(
        [0.003, 0.005, 0.005], [110e9, 200e9, 200e9], 0.0116, 0.008, 0.030, "through"
    )
    assert c.total / MM_PER_N == pytest.approx(7.513021e-07, rel=1e-6)
    assert c.total / MM_PER_N / 7.124590e-07 - 1 == pytest.approx(0.0545, abs=5e-4)


def test_real_hole_is_8_percent_softer_than_bat_on_the_ecss_example():
    # VDI's d_h = 6.5 mm instead of d = 6 mm in the log term: δ_P 1.1289e-6 mm/N (+8.1 %)
    c = jt.clamped_compliance([0.002, 0.003], [71e9, 71e9], 0.010, 0.0065, 0.024)
    assert c.total / MM_PER_N == pytest.approx(1.128890e-06, rel=1e-5)
    assert c.total / MM_PER_N / 1.044217e-06 - 1 == pytest.approx(0.0811, abs=5e-4)


def test_ecss_7_14_preload_range_from_torque_and_friction_box():
    # M6 socket (BAT db: d2 = 5.351 mm, P = 1 mm, d_uh = 10 mm), hole 6.5 mm: D_Km = 8.25 mm.
    # ECSS's torque relation: thread d2/2 (tan ψ + tan ρ'), head μ D_Km/2 (a flat head).
    d2, pitch, d_km = 0.005351, 0.001, 0.5 * (0.010 + 0.0065)

    def per_newton(mu_thread, mu_head):
        tan_rho = math.tan(float(pl.thread_friction_angle(mu_thread)))
        return d2 / 2 * (pitch / (math.pi * d2) + tan_rho) + mu_head * d_km / 2

    lo, hi = jt.preload_bounds_from_torque(
        13.65,
        0.65 / 13.65,
        2.0,
        per_newton(0.086, 0.176),
        per_newton(0.176, 0.296),
        prevailing_torque_min=0.4,
    )
    # the handbook's figures, to its 5 digits
    assert lo == pytest.approx(5717.85, rel=1e-4)
    assert hi == pytest.approx(12078.55, rel=1e-4)
