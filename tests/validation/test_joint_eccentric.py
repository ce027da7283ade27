"""joint.vdi2230's eccentric relations (VDI 2230-1 §5.3.2) beside an open implementation.

No worked example of an eccentrically clamped and loaded joint with its printed Φ*_en,
σ_SAb and F_Aab could be read from a public source (VDI 2230-1's Annex B is paywalled; the
lecture scripts and vendor manuals we found stop at the concentric joint). What stands here
instead is the open implementation h18340637145/vdi2230 (a C# VDI 2230 calculator,
``WindowsFormsApp1/VDISolution/R2.cs``, ``R3.cs``, ``R9.cs``, read on 2026-11-26; it was not
run, its relations are written out below as it states them, in mm and N):

* I_V,Bers = 0.147 (D_A − d_W) d_W³ D_A³/(D_A³ − d_W³), D_A held at D_A,Gr; I_ve,Bers =
  I_V,Bers + s_sym² π D_A²/4; δ*_P = δ_P + s_sym² l_K/(E_P I_Bers), δ**_P = δ_P + s_sym a
  l_K/(E_P I_Bers); Φ = n δ**_P/(δ*_P + δ_S); F_KA = F_A A_D (a u − s_sym u)/(b c_T³/12 +
  s_sym u A_D): ours agree to rounding (1e-12) for a fully developed cone. In its sleeve
  branch it writes l_V = D_A − d_W/(2 tan φ) and I_Bers = l_K/(2 l_V/w/I_ve) + l_H/I_H
  (operator precedence); we take VDI's cone height and the series sum.
* σ_SAb = [1 + (1/Φ − s_sym/a) l_K π a d³ E_S/(l_ers E_P 8 I_Bers)] Φ F_A/A_S with
  l_ers = d⁴ (0.5/d³ + l_1/d_T⁴ + l_Gew/d_3⁴ + 0.4/d³): the bending length referred to the
  nominal section, without the engaged thread's 0.5 d. We refer l_ers to the stress section
  (l_ers = β_S E_S π d_S⁴/64), which makes VDI's relation the beam result σ_b =
  M β_P/(β_S W_S); on the M12 case below its bending term is 0.63 times ours, exactly the
  ratio of the two bending lengths ((d_S/d)⁴ = 0.555 from the reference section, the rest
  from the engaged thread it leaves out): the two σ_SAb differ on the bending part only,
  ours the larger (the conservative side).
"""

import math

import pytest

from engine import run
from engine.models import get_model
from engine.physics import joint as jt

JOINT = get_model("joint.vdi2230")
E = 2.1e11
D, P = 0.012, 0.00175
D2, D3 = D - 0.649519 * P, D - 1.226869 * P
DS = 0.5 * (D2 + D3)
AS = math.pi / 4 * DS**2
DW, DH = 0.01663, 0.0135

# M12 8.8 through two 20 mm steel plates, wide plates (the cone fully developed), the bolt
# 6 mm off the axis of a 40 × 60 mm section, F_A = 6 kN at a = 24 mm, the edge at u = 28 mm
CASE = {
    "thread_diameter": D,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "working_load": 6e3,
    "working_load_min": 0.0,
    "load_introduction": 0.5,
    "bolt_offset": 0.006,
    "load_lever": 0.024,
    "opening_edge": 0.028,
    "interface_length": 0.060,
    "interface_width": 0.040,
}


def open_implementation(got):
    """h18340637145/vdi2230's relations (mm, N), fed with our δ_S, δ_P, D_A,Gr."""
    mm = 1e3
    d, d3, dw, lk = D * mm, D3 * mm, DW * mm, 40.0
    s, a, u, b, ct, n, fa = 6.0, 24.0, 28.0, 40.0, 60.0, 0.5, 6e3
    ep = es = E / 1e6
    da = got["cone_limit_diameter"] * mm  # D_A held at D_A,Gr
    delta_s, delta_p = got["bolt_compliance"] * mm, got["clamped_compliance"] * mm  # mm/N
    i_v = 0.147 * (da - dw) * dw**3 * da**3 / (da**3 - dw**3)
    i_bers = i_v + s**2 * math.pi * da**2 / 4  # the cone alone (D_A ≥ D_A,Gr)
    star = delta_p + s * s * lk / ep / i_bers
    star2 = delta_p + s * a * lk / ep / i_bers
    phi = n * star2 / (star + delta_s)
    ad = b * ct - math.pi * (DH * mm) ** 2 / 4
    f_ka = fa * ad * (a * u - s * u) / (b * ct**3 / 12 + s * u * ad)
    l_ers = d**4 * (0.5 / d**3 + lk / d3**4 + 0.4 / d**3)
    bend = (1 / phi - s / a) * lk * es * math.pi * a * (DS * mm) ** 3 / (l_ers * ep * 8 * i_bers)
    return {"i_bers": i_bers * 1e-12, "phi": phi, "f_ka": f_ka, "bend": bend}


GOT = run(JOINT, CASE).results
THEIRS = open_implementation(GOT)


def test_the_cone_is_fully_developed_here():
    assert GOT["outer_diameter_used"] == pytest.approx(GOT["cone_limit_diameter"], rel=1e-9)


def test_substitute_inertia_load_factor_and_opening_force_agree():
    assert GOT["substitute_bending_inertia"] == pytest.approx(THEIRS["i_bers"], rel=1e-12)
    assert GOT["load_factor"] == pytest.approx(THEIRS["phi"], rel=1e-12)
    assert GOT["opening_clamp_force"] == pytest.approx(THEIRS["f_ka"], rel=1e-12)


def test_bending_term_differs_by_the_two_bending_lengths():
    # ours: σ_SAb = (1 + x) Φ F_A/A_S; theirs the same with x' = x · l_ers,ours/l_ers,theirs
    phi = GOT["load_factor"]
    ours = GOT["additional_bolt_stress"] / (phi * 6e3 / AS) - 1.0
    l_ours = GOT["bolt_bending_compliance"] * E * math.pi * DS**4 / 64  # m
    mm = 1e3
    l_theirs = (D * mm) ** 4 * (0.5 / (D * mm) ** 3 + 40 / (D3 * mm) ** 4 + 0.4 / (D * mm) ** 3)
    assert THEIRS["bend"] == pytest.approx(ours * l_ours * mm / l_theirs, rel=1e-12)
    assert THEIRS["bend"] / ours == pytest.approx(0.63, abs=0.005)


def test_opening_limit_is_where_the_residual_force_meets_f_ka():
    # F_Aab at F_M,min: F_V − (1 − Φ*_en) F_Aab = (F_KA/F_A) F_Aab
    f_v = GOT["assembly_preload_min"] - GOT["embedding_loss"]
    k = GOT["opening_clamp_force"] / 6e3
    f_aab = GOT["separation_load"]
    assert f_v - (1 - GOT["load_factor"]) * f_aab == pytest.approx(k * f_aab, rel=1e-12)
    assert jt.separation_load(f_v, 0.0, GOT["load_factor"], k) == pytest.approx(f_aab, rel=1e-12)
