"""clutch.spring_design with a disc pack: DIN 2093's printed table, the 60 N·m setting
worked by hand, a bore too small (binding limit and nearest pack).

Almen and László (DIN EN 16983) written out here, not called:
K1 = (1/π) ((δ − 1)/δ)² / ((δ + 1)/(δ − 1) − 2/ln δ), δ = De/Di;
F = 4E/(1 − μ²) · t⁴/(K1 De²) · (s/t) [(h0/t − s/t)(h0/t − s/(2t)) + 1];
σ_OM = −4E/(1 − μ²) · t²/(K1 De²) · (s/t) · 3/π; E = 206 GPa, μ = 0.3.
"""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq

from engine import run
from engine.models.clutch_spring import SIXTY_NM, SPRING_DESIGN
from engine.physics import springs as sp
from engine.procedures import spring_design as sd
from tests.pins import pin

E, MU = 206e9, 0.3

#: DIN 2093 series A as printed (a public reprint of the standard's table): De, Di, t, h0,
#: the deflection f ≈ 0.75 h0 the table prints (mm), the force there (N), σ_OM (MPa).
DIN2093_A = (
    (8.0, 4.2, 0.4, 0.2, 0.15, 210, -1200),
    (10.0, 5.2, 0.5, 0.25, 0.19, 329, -1210),
    (12.5, 6.2, 0.7, 0.3, 0.23, 673, -1280),
    (14.0, 7.2, 0.8, 0.3, 0.23, 813, -1190),
    (16.0, 8.2, 0.9, 0.35, 0.26, 1000, -1160),
    (18.0, 9.2, 1.0, 0.4, 0.3, 1250, -1170),
    (20.0, 10.2, 1.1, 0.45, 0.34, 1530, -1180),
    (22.5, 11.2, 1.25, 0.5, 0.38, 1950, -1170),
    (25.0, 12.2, 1.5, 0.55, 0.41, 2910, -1210),
    (28.0, 14.2, 1.5, 0.65, 0.49, 2850, -1180),
    (31.5, 16.3, 1.75, 0.7, 0.53, 3900, -1190),
)


def _k1(de: float, di: float) -> float:
    d = de / di
    return ((d - 1) / d) ** 2 / ((d + 1) / (d - 1) - 2 / math.log(d)) / math.pi


def _force(s: float, de: float, di: float, t: float, h0: float) -> float:
    u, a = s / t, h0 / t
    return 4 * E / (1 - MU**2) * t**4 / (_k1(de, di) * de**2) * u * ((a - u) * (a - u / 2) + 1)


def _sigma_om(s: float, de: float, di: float, t: float) -> float:
    return -4 * E / (1 - MU**2) * t**2 / (_k1(de, di) * de**2) * (s / t) * 3 / math.pi


#: DIN 2093 group 2 as printed in an open table of the standard ([EN16983] in
#: docs/sources.md): series, De, Di, t, l0 (mm) and the force at s = 0.75 h0 (N), h0 = l0 − t.
DIN2093_GROUP2 = (
    ("A", 31.5, 16.3, 1.75, 2.45, 3870),
    ("A", 40.0, 20.4, 2.25, 3.15, 6500),
    ("A", 45.0, 22.4, 2.5, 3.5, 7720),
    ("A", 50.0, 25.4, 3.0, 4.1, 12000),
    ("A", 56.0, 28.5, 3.0, 4.3, 11400),
    ("A", 63.0, 31.0, 3.5, 4.9, 15000),
    ("A", 71.0, 36.0, 4.0, 5.6, 20500),
    ("A", 80.0, 41.0, 5.0, 6.7, 33600),
    ("A", 90.0, 46.0, 5.0, 7.0, 31400),
    ("A", 100.0, 51.0, 6.0, 8.2, 48000),
    ("B", 31.5, 16.3, 1.25, 2.15, 1910),
    ("B", 40.0, 20.4, 1.5, 2.65, 2620),
    ("B", 45.0, 22.4, 1.75, 3.05, 3650),
    ("B", 50.0, 25.4, 2.0, 3.4, 4760),
    ("B", 56.0, 28.5, 2.0, 3.6, 4440),
    ("B", 63.0, 31.0, 2.5, 4.25, 7190),
    ("B", 71.0, 36.0, 2.5, 4.5, 6720),
    ("B", 80.0, 41.0, 3.0, 5.3, 10500),
    ("B", 90.0, 46.0, 3.5, 6.0, 14200),
    ("B", 100.0, 51.0, 3.5, 6.3, 13100),
)


@pytest.mark.parametrize("row", DIN2093_A, ids=lambda r: f"A{r[0]:g}")
def test_the_table_s_series_a_discs_give_din_2093_s_printed_force_and_stress(row) -> None:
    de, di, t, h0, f, force, om = row
    assert (de, di, t, h0) in sd.DISC_TABLE["A"]
    mm = 1e-3
    # the force printed to three figures, σ_OM to 10 MPa: both within 0.5 %
    assert sp.disc_force(f * mm, de * mm, di * mm, t * mm, h0 * mm) == pytest.approx(
        force, rel=5e-3
    )
    # and by the relation written out above, independently of the physics module
    assert _force(f * mm, de * mm, di * mm, t * mm, h0 * mm) == pytest.approx(force, rel=5e-3)
    s = sp.disc_stresses(f * mm, de * mm, di * mm, t * mm, h0 * mm)["OM"]
    assert s / 1e6 == pytest.approx(om, rel=5e-3)


@pytest.mark.parametrize("row", DIN2093_GROUP2, ids=lambda r: f"{r[0]}{r[1]:g}")
def test_the_table_s_group_2_discs_give_the_printed_force_at_three_quarters_h0(row) -> None:
    series, de, di, t, l0, force = row
    h0 = round(l0 - t, 6)
    assert (de, di, t, h0) in sd.DISC_TABLE[series]
    mm = 1e-3
    s = 0.75 * h0 * mm
    # printed to three figures: within 0.5 %, by the module and by the relation above
    assert sp.disc_force(s, de * mm, di * mm, t * mm, h0 * mm) == pytest.approx(force, rel=5e-3)
    assert _force(s, de * mm, di * mm, t * mm, h0 * mm) == pytest.approx(force, rel=5e-3)


def test_every_row_of_the_table_is_one_a_source_prints() -> None:
    # nothing unconfirmed: every (De, Di, t, h0) is a row of one of the two printed tables
    printed = {("A", *r[:4]) for r in DIN2093_A} | {
        (r[0], r[1], r[2], r[3], round(r[4] - r[3], 6)) for r in DIN2093_GROUP2
    }
    ours = {(k, *row) for k, rows in sd.DISC_TABLE.items() for row in rows}
    assert ours == printed
    assert len(ours) == 30  # A 8…31.5 (11) + A 40…100 (9) + B 31.5…100 (10)


@pytest.mark.parametrize(
    ("series", "de_t", "h0_t"),
    [
        ("A", (15.5, 20.5), (0.33, 0.5)),
        ("B", (25.0, 29.0), (0.68, 0.84)),
    ],
)
def test_every_row_of_the_table_keeps_its_series_ratios(series, de_t, h0_t) -> None:
    # DIN 2093: A De/t ≈ 18, h0/t ≈ 0.4; B ≈ 28, ≈ 0.75; De/Di ≈ 1.9…2.03
    for de, di, t, h0 in sd.DISC_TABLE[series]:
        assert de_t[0] <= de / t <= de_t[1], (de, di, t, h0)
        assert h0_t[0] <= h0 / t <= h0_t[1], (de, di, t, h0)
        assert 1.85 <= de / di <= 2.05, (de, di)
        assert t <= 6.0  # groups 1 and 2: no contact flats
        assert h0 / t < math.sqrt(2)  # the force rises over the whole deflection


def test_sixty_nm_names_a_disc_pack_and_every_check_holds_by_hand() -> None:
    r = run(SPRING_DESIGN, {**SIXTY_NM, "spring_kind": "disc_pack"})
    v = r.results
    f1 = 2 * 60.0 * math.tan(math.radians(45.0) - math.atan(0.1)) / 0.05
    s_h = 0.002 + 0.005 * (1 - math.sin(math.radians(45.0)))
    pin("clutch.spring_design", "set_force", v["set_force"], f1, rel=1e-12)
    # the pack it names: series A 40 × 20.4 × 2.25, h0 0.9, one disc per pack
    de, di, t, h0 = 0.040, 0.0204, 0.00225, 0.0009
    assert v["disc_designation"] == "DIN 2093 A 40 (40 × 20.4 × 2.25, h0 0.9)"
    pin("clutch.spring_design", "disc_outer_diameter", v["disc_outer_diameter"], de, rel=1e-12)
    pin("clutch.spring_design", "disc_inner_diameter", v["disc_inner_diameter"], di, rel=1e-12)
    pin("clutch.spring_design", "disc_thickness", v["disc_thickness"], t, rel=1e-12)
    pin("clutch.spring_design", "disc_cone_height", v["disc_cone_height"], h0, rel=1e-12)
    pin("clutch.spring_design", "discs_parallel", v["discs_parallel"], 1)
    # s1 by hand: F(s1) = F1 (one disc per pack); then i = ceil(s_h/(0.75 h0 − s1))
    s1 = brentq(lambda s: _force(s, de, di, t, h0) - f1, 0.0, h0, xtol=1e-15)
    assert s1 == pytest.approx(0.18772e-3, rel=1e-4)
    pin("clutch.spring_design", "disc_set_deflection", v["disc_set_deflection"], s1, rel=1e-9)
    i = math.ceil(s_h / (0.75 * h0 - s1))
    assert i == 8  # 3.4645/(0.675 − 0.1877) = 7.11
    pin("clutch.spring_design", "discs_series", v["discs_series"], i)
    pin("clutch.spring_design", "disc_count", v["disc_count"], 8)
    s2 = s1 + s_h / i
    pin("clutch.spring_design", "disc_stroke_deflection", v["disc_stroke_deflection"], s2, rel=1e-9)
    pin(
        "clutch.spring_design",
        "stroke_force",
        v["stroke_force"],
        _force(s2, de, di, t, h0),
        rel=1e-9,
    )
    om = abs(_sigma_om(s2, de, di, t))
    pin("clutch.spring_design", "disc_stress_om", v["disc_stress_om"], om, rel=1e-9)
    pin(
        "clutch.spring_design",
        "disc_stress_utilisation",
        v["disc_stress_utilisation"],
        om / 1400e6,
        rel=1e-9,
    )
    # the stack: 8 packs of (h0 + t) free, pressed by 8 s1 at the setting
    free = 8 * (h0 + t)
    pin("clutch.spring_design", "free_length", v["free_length"], 0.0252, rel=1e-12)
    pin("clutch.spring_design", "set_deflection", v["set_deflection"], 8 * s1, rel=1e-9)
    pin("clutch.spring_design", "set_length", v["set_length"], free - 8 * s1, rel=1e-9)
    pin("clutch.spring_design", "stroke_length", v["stroke_length"], free - 8 * s1 - s_h, rel=1e-9)
    pin("clutch.spring_design", "solid_length", v["solid_length"], 8 * t, rel=1e-12)
    pin("clutch.spring_design", "shim_length", v["shim_length"], 0.080 - (free - 8 * s1), rel=1e-9)
    # every margin by hand (≥ 0 passes)
    pin("clutch.spring_design", "margin_outer_diameter", v["margin_outer_diameter"], 0.0, abs=1e-12)
    pin(
        "clutch.spring_design",
        "margin_inner_diameter",
        v["margin_inner_diameter"],
        1 - 0.020 / di,
        rel=1e-9,
    )
    pin("clutch.spring_design", "margin_disc_preload", v["margin_disc_preload"], s1 / h0, rel=1e-9)
    pin(
        "clutch.spring_design",
        "margin_disc_deflection",
        v["margin_disc_deflection"],
        1 - s2 / (0.75 * h0),
        rel=1e-9,
    )
    pin(
        "clutch.spring_design",
        "margin_disc_stress_om",
        v["margin_disc_stress_om"],
        1 - om / 1400e6,
        rel=1e-9,
    )
    pin(
        "clutch.spring_design",
        "margin_stack_length",
        v["margin_stack_length"],
        1 - (free - 8 * s1) / 0.08,
        rel=1e-9,
    )
    assert all(c.ok for c in r.checks) and [c.name for c in r.checks] == list(sd.DISC_CHECKS)
    # 20 + 10 discs of series A and B, each with 1…4 in parallel
    pin("clutch.spring_design", "candidates_checked", v["candidates_checked"], 120)
    assert v["candidates_passing"] > 0 and v["binding_limit"] == "outer_diameter"
    # the helical spring's values are null for a disc pack
    assert v["wire_diameter"] is None and v["rate"] is None


def test_dynamic_load_asks_for_a_preload_of_0_15_h0() -> None:
    r = run(SPRING_DESIGN, {**SIXTY_NM, "spring_kind": "disc_pack", "dynamic_load": True})
    v = r.results
    # the static choice's s1 = 0.21 h0 passes 0.15 h0: margin (s1 − 0.15 h0)/h0
    assert v["disc_designation"].startswith("DIN 2093 A 40")
    pin(
        "clutch.spring_design",
        "margin_disc_preload",
        v["margin_disc_preload"],
        v["disc_set_deflection"] / 0.0009 - 0.15,
        rel=1e-9,
    )


def test_a_bore_too_small_names_the_binding_limit_and_the_nearest_pack() -> None:
    r = run(SPRING_DESIGN, {**SIXTY_NM, "spring_kind": "disc_pack", "max_outer_diameter": 0.030})
    v = r.results
    pin("clutch.spring_design", "candidates_passing", v["candidates_passing"], 0)
    assert v["binding_limit"] == "outer_diameter"
    # the 40 mm disc passes every other check; 1 − 40/30
    pin(
        "clutch.spring_design",
        "margin_outer_diameter",
        v["margin_outer_diameter"],
        1 - 40 / 30,
        rel=1e-9,
    )
    assert [c.name for c in r.checks if not c.ok] == ["outer_diameter"]
    assert "no disc pack in the bounds" in r.notes[1]


def test_the_helical_spring_is_unchanged_by_the_kind_input() -> None:
    a = run(SPRING_DESIGN, SIXTY_NM).results
    b = run(SPRING_DESIGN, {**SIXTY_NM, "spring_kind": "helical"}).results
    assert a == b and a["disc_designation"] is None and a["wire_diameter"] == 0.007


#: The inputs one spring kind reads and the other does not (``used_with`` in the model):
#: the form disables them for the other kind, so there they must change nothing.
KIND_ONLY = {
    "disc_series": ("disc_pack", ("A", "B")),
    "disc_yield_strength": ("disc_pack", (1000e6, 2000e6)),
    "spring_material": ("helical", ("EN10270-1-DH", "1.4310")),
    "spring_seating": ("helical", ("fixed_fixed", "fixed_free")),
}


def test_each_kind_only_input_declares_its_kind() -> None:
    declared = {p.name: p.used_with for p in SPRING_DESIGN.inputs if p.used_with}
    assert declared == {n: f"spring_kind={k}" for n, (k, _) in KIND_ONLY.items()}


@pytest.mark.parametrize("name", sorted(KIND_ONLY))
def test_a_kind_only_input_changes_nothing_with_the_other_kind_and_acts_with_its_own(
    name: str,
) -> None:
    kind, (a, b) = KIND_ONLY[name]
    other = "helical" if kind == "disc_pack" else "disc_pack"
    off = [run(SPRING_DESIGN, {**SIXTY_NM, "spring_kind": other, name: v}) for v in (a, b)]
    assert off[0].results == off[1].results, name
    assert [(c.name, c.ok) for c in off[0].checks] == [(c.name, c.ok) for c in off[1].checks]
    on = [run(SPRING_DESIGN, {**SIXTY_NM, "spring_kind": kind, name: v}).results for v in (a, b)]
    assert on[0] != on[1], name  # with its own kind it acts
