"""clutch.spring_design: the chosen spring checked by hand to EN 13906-1, the issue's 60 N·m
clutch, a pocket too small (binding limit and nearest spring), monotonicity in the force.

EN 13906-1 written out here, not called: R = G d⁴/(8 D³ n); τ_k = k 8 F D/(π d³) with
k = (w + 0.5)/(w − 0.75); L_c = (n + 2) d; S_a = (0.0015 D²/d + 0.1 d) n; s_K from
L0, D, ν = 0.5 and G/E; τ_zul = 0.5 R_m (EN 10270-1 DH, 7 mm row: 1540 MPa).
"""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models.clutch_spring import SIXTY_NM, SPRING_DESIGN
from tests.pins import pin

G, E, RHO = 81.5e9, 206e9, 7850.0


def test_sixty_nm_names_a_spring_and_every_check_holds_by_hand() -> None:
    r = run(SPRING_DESIGN, SIXTY_NM)
    v = r.results
    # the clutch's force and stroke, by hand: F1 = 2 T tan(α − ρ)/D0, s_h = h + (d_b/2)(1 − sin α)
    f1 = 2 * 60.0 * math.tan(math.radians(45.0) - math.atan(0.1)) / 0.05
    s_h = 0.002 + 0.005 * (1 - math.sin(math.radians(45.0)))
    pin("clutch.spring_design", "set_force", v["set_force"], f1, rel=1e-12)
    assert f1 == pytest.approx(1963.6364, rel=1e-7)  # 2·60·(9/11)/0.05
    pin("clutch.spring_design", "stroke", v["stroke"], s_h, rel=1e-12)
    # the spring it names (the thinnest wire of the 78 that pass, its lightest spring)
    d, dm, n = 0.007, 0.028, 5.5
    pin("clutch.spring_design", "wire_diameter", v["wire_diameter"], d, rel=1e-12)
    pin("clutch.spring_design", "mean_diameter", v["mean_diameter"], dm, rel=1e-9)
    pin("clutch.spring_design", "active_coils", v["active_coils"], n)
    pin("clutch.spring_design", "total_coils", v["total_coils"], n + 2)
    rate = G * d**4 / (8 * dm**3 * n)
    pin("clutch.spring_design", "rate", v["rate"], rate, rel=1e-9)
    s1 = f1 / rate
    f2 = f1 + rate * s_h
    l1 = 0.080
    pin("clutch.spring_design", "set_length", v["set_length"], l1)
    pin("clutch.spring_design", "set_deflection", v["set_deflection"], s1, rel=1e-9)
    pin("clutch.spring_design", "stroke_force", v["stroke_force"], f2, rel=1e-9)
    pin("clutch.spring_design", "free_length", v["free_length"], l1 + s1, rel=1e-9)
    pin("clutch.spring_design", "stroke_length", v["stroke_length"], l1 - s_h, rel=1e-12)
    w = dm / d
    k = (w + 0.5) / (w - 0.75)
    tau_zul = 0.5 * 1540e6
    t1 = k * 8 * f1 * dm / (math.pi * d**3)
    t2 = k * 8 * f2 * dm / (math.pi * d**3)
    pin("clutch.spring_design", "permissible_stress", v["permissible_stress"], tau_zul)
    pin("clutch.spring_design", "shear_stress_set", v["shear_stress_set"], t1, rel=1e-9)
    pin("clutch.spring_design", "shear_stress_stroke", v["shear_stress_stroke"], t2, rel=1e-9)
    pin(
        "clutch.spring_design",
        "stress_utilisation_set",
        v["stress_utilisation_set"],
        t1 / tau_zul,
        rel=1e-9,
    )
    pin(
        "clutch.spring_design",
        "stress_utilisation_stroke",
        v["stress_utilisation_stroke"],
        t2 / tau_zul,
        rel=1e-9,
    )
    assert t2 < tau_zul < t2 * 1.01  # the fewest coils: just within the limit
    lc = (n + 2) * d
    sa = (0.0015 * dm**2 / d + 0.1 * d) * n
    pin("clutch.spring_design", "solid_length", v["solid_length"], lc, rel=1e-12)
    pin("clutch.spring_design", "gap_sum", v["gap_sum"], sa, rel=1e-9)
    # buckling: ν π D/L0 is large enough that the root is imaginary (a short, fat spring)
    l0 = l1 + s1
    ratio = G / E
    assert 1 - (1 - ratio) / (0.5 + ratio) * (math.pi * dm / (0.5 * l0)) ** 2 < 0
    assert v["buckling_deflection"] is None
    pin(
        "clutch.spring_design",
        "mass",
        v["mass"],
        RHO * math.pi * d**2 / 4 * math.pi * dm * (n + 2),
        rel=1e-9,
    )
    margins = {
        "spring_index": min(w / 4 - 1, 1 - w / 20),
        "outer_diameter": 1 - (dm + d) / 0.040,
        "inner_diameter": 1 - 0.020 / (dm - d),
        "stress_at_set": 1 - t1 / tau_zul,
        "stress_at_stroke": 1 - t2 / tau_zul,
        "coil_gaps": 1 - (lc + sa) / (l1 - s_h),
        "buckling": 1.0,
    }
    assert min(margins.values()) >= 0.0
    pin(
        "clutch.spring_design",
        "margin_spring_index",
        v["margin_spring_index"],
        margins["spring_index"],
        rel=1e-9,
        abs=1e-12,
    )
    pin(
        "clutch.spring_design",
        "margin_outer_diameter",
        v["margin_outer_diameter"],
        margins["outer_diameter"],
        rel=1e-9,
        abs=1e-12,
    )
    pin(
        "clutch.spring_design",
        "margin_inner_diameter",
        v["margin_inner_diameter"],
        margins["inner_diameter"],
        rel=1e-9,
        abs=1e-12,
    )
    pin(
        "clutch.spring_design",
        "margin_stress_at_set",
        v["margin_stress_at_set"],
        margins["stress_at_set"],
        rel=1e-9,
        abs=1e-12,
    )
    pin(
        "clutch.spring_design",
        "margin_stress_at_stroke",
        v["margin_stress_at_stroke"],
        margins["stress_at_stroke"],
        rel=1e-9,
        abs=1e-12,
    )
    pin(
        "clutch.spring_design",
        "margin_coil_gaps",
        v["margin_coil_gaps"],
        margins["coil_gaps"],
        rel=1e-9,
        abs=1e-12,
    )
    pin("clutch.spring_design", "margin_buckling", v["margin_buckling"], 1.0)
    assert all(c.ok for c in r.checks)
    assert v["binding_limit"] == "spring_index"  # w = 4: on the edge of the range
    pin("clutch.spring_design", "candidates_checked", v["candidates_checked"], 7050)
    pin("clutch.spring_design", "candidates_passing", v["candidates_passing"], 78)
    assert "60 N·m" in " ".join(r.notes)


def test_a_pocket_too_short_names_the_binding_limit_and_the_nearest_spring() -> None:
    r = run(SPRING_DESIGN, {**SIXTY_NM, "max_set_length": 0.030})
    v = r.results
    assert v["candidates_passing"] == 0
    failed = [c.name for c in r.checks if not c.ok]
    assert failed == [v["binding_limit"]]  # the nearest spring passes every other check
    assert v["binding_limit"] in ("coil_gaps", "stress_at_stroke")
    assert "no spring in the bounds" in r.notes[1]


def test_margin_objective_gives_more_stress_margin_than_the_thinnest() -> None:
    light = run(SPRING_DESIGN, SIXTY_NM).results
    most = run(SPRING_DESIGN, {**SIXTY_NM, "objective": "margin"}).results
    assert most["margin_stress_at_stroke"] > light["margin_stress_at_stroke"]
    assert most["mass"] >= light["mass"]


@pytest.mark.parametrize("objective", ["thinnest", "margin"])
def test_a_larger_force_never_gives_a_thinner_wire_at_equal_space(objective: str) -> None:
    torques = [1.0 + 2.5 * i for i in range(30)]  # 1…73.5 N·m in the same pocket
    wires = [
        run(SPRING_DESIGN, {**SIXTY_NM, "target_torque": t, "objective": objective}).results[
            "wire_diameter"
        ]
        for t in torques
    ]
    assert wires == sorted(wires)
    assert wires[0] < wires[-1]


def test_a_slender_spring_buckles_at_en_13906_1s_deflection() -> None:
    """The second example (0.5 N·m, a 40 mm pocket): a slender spring, s_K by hand."""
    v = run(SPRING_DESIGN, SPRING_DESIGN.examples[1]).results
    l0, dm = v["free_length"], v["mean_diameter"]
    ratio = G / E
    root = 1 - (1 - ratio) / (0.5 + ratio) * (math.pi * dm / (0.5 * l0)) ** 2
    s_k = l0 * 0.5 / (1 - ratio) * (1 - math.sqrt(root))
    pin("clutch.spring_design", "buckling_deflection", v["buckling_deflection"], s_k, rel=1e-9)
    s2 = v["set_deflection"] + v["stroke"]
    pin("clutch.spring_design", "margin_buckling", v["margin_buckling"], 1 - s2 / s_k, rel=1e-9)
    assert 0.0 <= v["margin_buckling"] < 0.05  # the thinnest wire sits near its buckling


def test_no_thinner_preferred_wire_fits_the_sixty_nm_pocket_by_hand() -> None:
    """d = 6.5 mm (the preferred size below 7) at its best coil, D = 4 d (the coils needed rise
    with D, and D/d < 4 fails the index): the coils that keep
    τ_k at full stroke within 0.5 R_m leave no room for S_a in the 80 mm pocket."""
    f1 = 2 * 60.0 * (9 / 11) / 0.05  # tan(45° − atan 0.1) = 0.9/1.1
    s_h = 0.002 + 0.005 * (1 - math.sin(math.radians(45.0)))
    d = 0.0065
    dm = 4 * d
    k = (4 + 0.5) / (4 - 0.75)
    f_zul = math.pi * d**3 * 0.5 * 1540e6 / (8 * k * dm)
    n = math.ceil(2 * G * d**4 * s_h / (8 * dm**3 * (f_zul - f1))) / 2
    room = 0.080 - s_h
    assert (n + 2) * d + (0.0015 * dm**2 / d + 0.1 * d) * n > room
    assert run(SPRING_DESIGN, SIXTY_NM).results["wire_diameter"] == 0.007
