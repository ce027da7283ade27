"""Every numeric output of preload.tightening and preload.control against a hand calculation.

Each value below is worked out here from the relations and table values written out
in the test (ISO 68-1 thread geometry, ISO 898-1 A_s and strengths, ISO 4762/4032 and
ISO 273 dimensions, VDI 2230-1 R7/R10/R13, [004] eq. 2–19), never by calling the
engine's own formulas; ``pin`` names each output it holds
(tests/test_every_output_pinned.py counts them).
"""

from __future__ import annotations

import math

import pytest

from engine import run
from engine.models.preload import CONTROL, TIGHTENING
from tests.pins import pin

REL = 1e-9
COS30 = math.cos(math.radians(30.0))


def _num(value: object) -> float:
    assert isinstance(value, float), value
    return value


def _iso_thread(d: float, p: float) -> tuple[float, float, float, float]:
    """d2, d3, d_S, A_s of an ISO 68-1 thread (ISO 898-1 stress area)."""
    d2 = d - 0.649519 * p
    d3 = d - 1.226869 * p
    ds = 0.5 * (d2 + d3)
    return d2, d3, ds, math.pi / 4 * ds * ds


def _beta(p: float, d2: float, d0: float, mu_g: float) -> float:
    """VDI 2230-1 R7: β = √(1 + 3 (3/2 · d2/d0 · (P/(π d2) + μ_G/cos 30°))²)."""
    return math.sqrt(1 + 3 * (1.5 * d2 / d0 * (p / (math.pi * d2) + mu_g / COS30)) ** 2)


def _exact_k(p: float, d2: float, outer: float, hole: float, mu_g: float, mu_k: float) -> float:
    """[004, eq. 10–12]: k_G = d2/2 tan(ψ + ρ'), k_K = μ_K R_T (annular face)."""
    psi, rho = math.atan(p / (math.pi * d2)), math.atan(mu_g / COS30)
    r_t = (outer**3 - hole**3) / (3 * (outer**2 - hole**2))
    return 0.5 * d2 * math.tan(psi + rho) + mu_k * r_t


def test_tightening_m10_socket_head_12_9_every_output() -> None:
    """M10 ISO 4762 12.9 into S235JR, a nut ISO 4032 class 10 too (strong enough, though
    ISO 898-2 does not pair it with 12.9); μ_G = μ_K = 0.12, ν = 0.9."""
    x = {
        "thread": "M10 ISO 4762 12.9",
        "clamped_material": "S235JR",
        "internal_thread_material": "S235JR",
        "engagement_length": 0.012,
        "working_bolt_force": 30e3,
        "nut": "ISO 4032",
        "nut_property_class": "10",
    }
    r = run(TIGHTENING, x).results
    d, p = 0.010, 0.0015
    d2, d3, ds, a_s = _iso_thread(d, p)
    r_p, r_m = 1100e6, 1220e6  # ISO 898-1, 12.9
    outer, hole = 15.33e-3, 11e-3  # ISO 4762 d_w,min; ISO 273 medium
    beta = _beta(p, d2, ds, 0.12)
    f = 0.9 * r_p * a_s / beta
    k_g = 0.16 * p + 0.58 * d2 * 0.12  # VDI 2230-1 R13
    k_k = 0.12 * (outer + hole) / 4
    total = f * (k_g + k_k)
    ideal = f * p / (2 * math.pi)
    thumb, thumb_yield = 0.2 * f * d, 0.07 * r_p * d**3  # [004, eq. 16, 18]
    area = math.pi / 4 * (outer**2 - hole**2)
    nut_area = math.pi / 4 * (14.63e-3**2 - hole**2)  # ISO 4032 M10 d_w,min 14.63 mm
    pin("preload.tightening", "assembly_preload", r["assembly_preload"], f, rel=REL)
    pin("preload.tightening", "permissible_preload", r["permissible_preload"], f, rel=REL)
    pin("preload.tightening", "tightening_torque", r["tightening_torque"], total, rel=REL)
    pin("preload.tightening", "thread_torque", r["thread_torque"], f * k_g, rel=REL)
    pin("preload.tightening", "bearing_torque", r["bearing_torque"], f * k_k, rel=REL)
    pin("preload.tightening", "ideal_torque", r["ideal_torque"], ideal, rel=REL)
    pin("preload.tightening", "ideal_torque_share", r["ideal_torque_share"], ideal / total, rel=REL)
    pin("preload.tightening", "friction_radius", r["friction_radius"], (outer + hole) / 4, rel=REL)
    pin("preload.tightening", "stress_area", r["stress_area"], a_s, rel=REL)
    pin("preload.tightening", "pitch_diameter", r["pitch_diameter"], d2, rel=REL)
    pin("preload.tightening", "minor_diameter", r["minor_diameter"], d3, rel=REL)
    pin("preload.tightening", "thread_pitch", r["thread_pitch"], p, rel=REL)
    pin("preload.tightening", "torsion_factor", r["torsion_factor"], beta, rel=REL)
    pin("preload.tightening", "equivalent_stress", r["equivalent_stress"], beta * f / a_s, rel=REL)
    pin("preload.tightening", "yield_strength", r["yield_strength"], r_p, rel=REL)
    pin("preload.tightening", "stress_utilization", r["stress_utilization"], 0.9, rel=REL)
    pin("preload.tightening", "bearing_outer_diameter", r["bearing_outer_diameter"], outer, rel=REL)
    pin("preload.tightening", "hole_diameter", r["hole_diameter"], hole, rel=REL)
    pin(
        "preload.tightening",
        "torque_formula_deviation",
        r["torque_formula_deviation"],
        abs(k_g + k_k - _exact_k(p, d2, outer, hole, 0.12, 0.12))
        / _exact_k(p, d2, outer, hole, 0.12, 0.12),
        rel=REL,
    )
    pin("preload.tightening", "rule_of_thumb_torque", r["rule_of_thumb_torque"], thumb, rel=REL)
    pin(
        "preload.tightening",
        "rule_of_thumb_deviation",
        r["rule_of_thumb_deviation"],
        (thumb - total) / total,
        rel=REL,
    )
    pin("preload.tightening", "yield_rule_torque", r["yield_rule_torque"], thumb_yield, rel=REL)
    pin(
        "preload.tightening",
        "yield_rule_deviation",
        r["yield_rule_deviation"],
        (thumb_yield - total) / total,
        rel=REL,
    )
    pin("preload.tightening", "bearing_area", r["bearing_area"], area, rel=REL)
    pin(
        "preload.tightening", "surface_pressure_head", r["surface_pressure_head"], f / area, rel=REL
    )
    pin(
        "preload.tightening",
        "surface_pressure_head_working",
        r["surface_pressure_head_working"],
        30e3 / area,
        rel=REL,
    )
    pin(
        "preload.tightening",
        "surface_pressure_nut",
        r["surface_pressure_nut"],
        f / nut_area,
        rel=REL,
    )
    # S235JR, VDI 2230-1 Table A9
    pin(
        "preload.tightening",
        "limiting_surface_pressure",
        r["limiting_surface_pressure"],
        490e6,
        rel=REL,
    )
    # R11 sizes on the bolt's upper strength 1.2 R_m
    pin(
        "preload.tightening",
        "bolt_breaking_force",
        r["bolt_breaking_force"],
        1.2 * r_m * a_s,
        rel=REL,
    )
    # ISO 2936, 8 mm key of the M10 ISO 4762 head
    pin("preload.tightening", "drive_torque_limit", r["drive_torque_limit"], 120.0, rel=REL)
    # R11: the shortest engagement is the one at which the thread strips at 1.2 R_m A_s,
    # and the stripping force grows in proportion to the full threads, m − 2P (P 1.5 mm)
    at_min = run(TIGHTENING, {**x, "engagement_length": r["min_engagement_length"]}).results
    assert at_min["stripping_force"] == pytest.approx(1.2 * r_m * a_s, rel=1e-12)
    assert r["stripping_force"] == pytest.approx(
        1.2 * r_m * a_s * (0.012 - 3e-3) / (_num(r["min_engagement_length"]) - 3e-3), rel=1e-12
    )


def test_tightening_given_preload_exact_formula() -> None:
    """M16 10.9, F0 = 60 kN, 'exact' [004, eq. 10–13]: the torque is the exact one and
    deviates from itself by 0; σ_red = β F0 / A_s."""
    r = run(
        TIGHTENING,
        {
            "thread_diameter": 0.016,
            "property_class": "10.9",
            "preload": 60e3,
            "torque_formula": "exact",
        },
    ).results
    d2, _, ds, a_s = _iso_thread(0.016, 0.002)
    outer, hole = 22.49e-3, 17.5e-3  # ISO 4017 d_w,min, ISO 273 medium
    k = _exact_k(0.002, d2, outer, hole, 0.12, 0.12)
    beta = _beta(0.002, d2, ds, 0.12)
    pin("preload.tightening", "assembly_preload", r["assembly_preload"], 60e3, rel=REL)
    pin(
        "preload.tightening",
        "permissible_preload",
        r["permissible_preload"],
        0.9 * 940e6 * a_s / beta,
        rel=REL,
    )
    pin("preload.tightening", "tightening_torque", r["tightening_torque"], 60e3 * k, rel=REL)
    pin(
        "preload.tightening",
        "friction_radius",
        r["friction_radius"],
        (outer**3 - hole**3) / (3 * (outer**2 - hole**2)),
        rel=REL,
    )
    pin(
        "preload.tightening",
        "equivalent_stress",
        r["equivalent_stress"],
        beta * 60e3 / a_s,
        rel=REL,
    )
    pin(
        "preload.tightening",
        "stress_utilization",
        r["stress_utilization"],
        beta * 60e3 / a_s / 940e6,
        rel=REL,
    )
    pin(
        "preload.tightening",
        "torque_formula_deviation",
        r["torque_formula_deviation"],
        0.0,
        rel=REL,
    )


def test_control_torque_wrench_with_friction_scatter() -> None:
    """[004, fig. 5]: 5/8"-11 UNC typed as numbers, R_p0.2 = 640 MPa, μ 0.10…0.20 at 80 N·m.

    Torque wrench: s = 0.3 [004]; the band's top is the permissible preload. The mean
    preload at a fixed torque M over μ_G, μ_K uniform is the closed-form double integral
    of M / (a + b μ_G + c μ_K) (VDI 2230 R13 torque: a = 0.16 P, b = 0.58 d2,
    c = (D_f + d_h)/4).
    """
    x = dict(CONTROL.examples[0])
    r = run(CONTROL, x).results
    d, p = 0.015875, 0.0254 / 11
    d2, _, ds, a_s = _iso_thread(d, p)
    outer, hole, mu = 0.0226, 0.0175, 0.15
    beta = _beta(p, d2, ds, mu)
    permissible, at_yield = 0.9 * 640e6 * a_s / beta, 640e6 * a_s / beta
    s = 0.3
    nominal = permissible / (1 + s)
    a, b, c = 0.16 * p, 0.58 * d2, (outer + hole) / 4
    torque = nominal * (a + (b + c) * mu)
    m = 80.0
    low, high = m / (a + (b + c) * 0.20), m / (a + (b + c) * 0.10)

    def prim(alpha: float, g: float) -> float:  # ∫ ln(α + b g) dg
        u = alpha + b * g
        return (u * math.log(u) - u) / b

    integral = sum(
        sign * (prim(a + c * k, 0.20) - prim(a + c * k, 0.10))
        for sign, k in ((1, 0.20), (-1, 0.10))
    )
    mean = m * integral / (c * 0.1 * 0.1)
    pin("preload.control", "target_torque", r["target_torque"], torque, rel=REL)
    pin("preload.control", "target_force", r["target_force"], nominal, rel=REL)
    pin("preload.control", "nominal_preload", r["nominal_preload"], nominal, rel=REL)
    pin("preload.control", "preload_min", r["preload_min"], nominal * (1 - s), rel=REL)
    pin("preload.control", "preload_max", r["preload_max"], nominal * (1 + s), rel=REL)
    pin("preload.control", "scatter", r["scatter"], s, rel=REL)
    pin("preload.control", "tightening_factor", r["tightening_factor"], (1 + s) / (1 - s), rel=REL)
    # υ = 1.25, the steady range's bottom [004, eq. 2]
    pin("preload.control", "required_preload", r["required_preload"], 1.25 * 15e3, rel=REL)
    pin("preload.control", "preload_factor", r["preload_factor"], 1.25, rel=REL)
    pin("preload.control", "permissible_preload", r["permissible_preload"], permissible, rel=REL)
    pin("preload.control", "yield_preload", r["yield_preload"], at_yield, rel=REL)
    pin("preload.control", "scatter_torque_applied", r["scatter_torque_applied"], m, rel=REL)
    pin("preload.control", "scatter_preload_min", r["scatter_preload_min"], low, rel=REL)
    pin("preload.control", "scatter_preload_max", r["scatter_preload_max"], high, rel=REL)
    pin(
        "preload.control",
        "scatter_relative",
        r["scatter_relative"],
        (high - low) / (high + low),
        rel=REL,
    )
    pin("preload.control", "scatter_preload_mean", r["scatter_preload_mean"], mean, rel=1e-11)


def test_control_nut_angle_through_a_shank_bolt() -> None:
    """M12 8.8, l_K = 120 mm with an 80 mm shank; nut rotation [004, eq. 4, 7–9].

    λ_b = Σ l_i/(E A_i) over shank (d), free thread (d3) and m/3 = 0.8 d/3 at d3;
    λ_p from VDI 2230-1 R3's cone for wide plates (D_A = D_A,Gr, our convention) through
    one steel: tan φ_D = 0.362 + 0.032 ln(β_L/2) + 0.153 ln y, y = D_A/d_W,
    δ_P = 2 ln[(d_W + d_h)(d_W + l_K tan φ − d_h) / ((d_W − d_h)(d_W + l_K tan φ + d_h))]
    / (E π d_h tan φ).
    """
    x = dict(CONTROL.examples[1])
    r = run(CONTROL, x).results
    d, p = 0.012, 0.00175
    d2, d3, ds, a_s = _iso_thread(d, p)
    e = 2.1e11
    lengths, diameters = (0.08, 0.04, 0.8 * d / 3), (d, d3, d3)
    lam_b = sum(li / (e * math.pi / 4 * di**2) for li, di in zip(lengths, diameters, strict=True))
    d_eq = math.sqrt(
        sum(lengths) / sum(li / di**2 for li, di in zip(lengths, diameters, strict=True))
    )
    d_w, d_h, grip = 16.63e-3, 13.5e-3, 0.12
    outer = d_w
    for _ in range(200):  # the cone's own D_A: D_A = d_W + l_K tan φ(D_A / d_W)
        tan = 0.362 + 0.032 * math.log(grip / d_w / 2) + 0.153 * math.log(outer / d_w)
        outer = d_w + grip * tan
    tan = 0.362 + 0.032 * math.log(grip / d_w / 2) + 0.153 * math.log(outer / d_w)
    top = (d_w + d_h) * (d_w + grip * tan - d_h)
    lam_p = 2 * math.log(top / ((d_w - d_h) * (d_w + grip * tan + d_h))) / (e * math.pi * d_h * tan)
    permissible = 0.9 * 640e6 * a_s / _beta(p, d2, ds, 0.12)  # 8.8 up to M16, VDI 2230-1 R7
    nominal = permissible / 1.2  # nut angle: s = 0.2
    pin("preload.control", "bolt_compliance", r["bolt_compliance"], lam_b, rel=REL)
    pin(
        "preload.control",
        "equivalent_shank_diameter",
        r["equivalent_shank_diameter"],
        d_eq,
        rel=REL,
    )
    pin("preload.control", "target_elongation", r["target_elongation"], nominal * lam_b, rel=REL)
    pin(
        "preload.control",
        "target_angle",
        r["target_angle"],
        2 * math.pi * nominal * (lam_b + lam_p) / p,
        rel=REL,
    )
    pin("preload.control", "permissible_preload", r["permissible_preload"], permissible, rel=REL)
    pin("preload.control", "clamped_compliance", r["clamped_compliance"], lam_p, rel=1e-8)


def test_control_sucker_rod_marks() -> None:
    """Sucker rods: rigid parts ([004, eq. 9]), the marks move φ D_c/2 on the coupling."""
    r = run(
        CONTROL,
        {
            "thread_diameter": 0.025,
            "thread_pitch": 0.0254 / 10,
            "yield_strength": 586e6,
            "bearing_outer_diameter": 0.046,
            "hole_diameter": 0.0255,
            "required_clamp_force": 30e3,
            "method": "rod_displacement_marks",
            "clamped_length": 0.05,
            "coupling_outer_diameter": 0.046,
        },
    ).results
    p = 0.0254 / 10
    d2, d3, ds, a_s = _iso_thread(0.025, p)
    lam_b = sum(li / (2.1e11 * math.pi / 4 * d3**2) for li in (0.05, 0.8 * 0.025 / 3))
    nominal = 0.9 * 586e6 * a_s / _beta(p, d2, ds, 0.12) / 1.2  # s = 0.2
    angle = 2 * math.pi * nominal * lam_b / p
    pin("preload.control", "clamped_compliance", r["clamped_compliance"], 0.0, rel=REL)
    pin("preload.control", "target_angle", r["target_angle"], angle, rel=REL)
    pin("preload.control", "target_displacement", r["target_displacement"], angle * 0.023, rel=REL)


def test_control_bought_parts_m8_socket_head_in_aluminium() -> None:
    """M8 ISO 4762 12.9 into EN AW-6082 T6: R10 at F_M,max = F_nom (1 + s) = the
    permissible preload, R11, the 6 mm key (ISO 2936: 52 N·m)."""
    x = {
        **CONTROL.examples[2],
        "working_bolt_force": 20e3,
        "nut": "ISO 4032",
        "nut_property_class": "10",
    }
    r = run(CONTROL, x).results
    d, p = 0.008, 0.00125
    d2, _, ds, a_s = _iso_thread(d, p)
    outer, hole = 12.33e-3, 9e-3  # ISO 4762 d_w,min, ISO 273 medium
    permissible = 0.9 * 1100e6 * a_s / _beta(p, d2, ds, 0.12)
    area = math.pi / 4 * (outer**2 - hole**2)
    pin("preload.control", "bearing_area", r["bearing_area"], area, rel=REL)
    pin(
        "preload.control",
        "surface_pressure_head",
        r["surface_pressure_head"],
        permissible / area,
        rel=REL,
    )
    pin(
        "preload.control",
        "surface_pressure_head_working",
        r["surface_pressure_head_working"],
        20e3 / area,
        rel=REL,
    )
    pin(
        "preload.control",
        "surface_pressure_nut",
        r["surface_pressure_nut"],
        permissible / (math.pi / 4 * (11.63e-3**2 - hole**2)),
        rel=REL,
    )
    # EN AW-6082 T6, VDI 2230-1 Table A9
    pin(
        "preload.control",
        "limiting_surface_pressure",
        r["limiting_surface_pressure"],
        360e6,
        rel=REL,
    )
    pin(
        "preload.control",
        "bolt_breaking_force",
        r["bolt_breaking_force"],
        1.2 * 1220e6 * a_s,
        rel=REL,
    )
    pin("preload.control", "drive_torque_limit", r["drive_torque_limit"], 52.0, rel=REL)
    at_min = run(CONTROL, {**x, "engagement_length": r["min_engagement_length"]}).results
    # the bolt at its upper strength 1.2 R_m; full threads m − 2P (P 1.25 mm)
    assert at_min["stripping_force"] == pytest.approx(1.2 * 1220e6 * a_s, rel=1e-12)
    assert r["stripping_force"] == pytest.approx(
        1.2 * 1220e6 * a_s * (0.008 - 2.5e-3) / (_num(r["min_engagement_length"]) - 2.5e-3),
        rel=1e-12,
    )


def test_control_histogram_holds_its_sample() -> None:
    """The histogram's counts add up to sample_size, and its bins lie in the exact band."""
    r = run(CONTROL, CONTROL.examples[0], series=True)
    assert sum(r.series["preload_counts"]) == pytest.approx(38.0, rel=1e-12)
    lo, hi = _num(r.results["scatter_preload_min"]), _num(r.results["scatter_preload_max"])
    assert lo < min(r.series["preload_bins"]) < max(r.series["preload_bins"]) < hi
