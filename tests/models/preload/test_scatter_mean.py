"""The friction-scatter band and mean of ``preload.control`` (issue 22's validation).

F(μ_G, μ_K) = M / (k_G(μ_G) + k_K(μ_K)) with μ_G, μ_K independent and uniform
([004, fig. 5], eq. 13). :func:`engine.physics.preload.friction_scatter_band` gives its extremes
at the corners and its mean by a closed form in μ_K and Gauss–Legendre in μ_G. Here it
is held to methods that share none of that: scipy's adaptive ``dblquad`` of F itself,
the double antiderivative of a linear k_G in 60-digit decimal arithmetic, ``quad`` in
μ_G, plain Monte Carlo sampling of F, and a design study of ``preload.tightening``
through the study engine.
"""

from __future__ import annotations

import math
from decimal import Decimal, localcontext
from typing import Any

import numpy as np
import pytest
from scipy import integrate

import engine
from engine.physics import preload as pl
from engine.physics import threads as th
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable

FORMULAS = ("vdi2230", "exact", "approx")

#: [004, fig. 5]: 5/8"-11 UNC bolts at 80 N·m (washer face 22.6 mm, hole 17.5 mm).
UNC_PITCH = 0.0254 / 11
FIG5: dict[str, Any] = {
    "torque": 80.0,
    "pitch": UNC_PITCH,
    "pitch_diameter": th.pitch_diameter(0.015875, UNC_PITCH),
    "diameter": 0.015875,
    "thread_friction_range": (0.10, 0.20),
    "bearing_friction_range": (0.10, 0.20),
    "bearing_outer_diameter": 0.0226,
    "hole_diameter": 0.0175,
}

#: M12 coarse, as VDI 2230 R13 (tests/models/preload/test_preload_arrays.py): P, d2, d, D_f, d_h.
M12 = (0.00175, 0.010863, 0.012, 0.01663, 0.0135)


def _preload(args: dict[str, Any], mu_g: Any, mu_k: Any, formula: str) -> Any:
    """F at (μ_G, μ_K), straight from the per-newton torques."""
    k_g, k_k = pl.tightening_torque_per_preload(
        args["pitch"],
        args["pitch_diameter"],
        args["diameter"],
        mu_g,
        mu_k,
        args["bearing_outer_diameter"],
        args["hole_diameter"],
        formula,
    )
    return args["torque"] / (k_g + k_k)


def _band(args: dict[str, Any], formula: str) -> tuple[float, float, float]:
    return pl.friction_scatter_band(**args, formula=formula)


def _m12(g: tuple[float, float], k: tuple[float, float], pitch: float = M12[0]) -> dict:
    return {
        "torque": 1.0,
        "pitch": pitch,
        "pitch_diameter": M12[1],
        "diameter": M12[2],
        "thread_friction_range": g,
        "bearing_friction_range": k,
        "bearing_outer_diameter": M12[3],
        "hole_diameter": M12[4],
    }


@pytest.mark.parametrize("formula", FORMULAS)
@pytest.mark.parametrize(
    "args",
    [FIG5, _m12((0.0, 1.0), (0.0, 1.0)), _m12((0.0, 0.3), (0.0, 0.05), pitch=2e-4)],
    ids=["fig5", "m12-wide", "fine-pitch-from-zero"],
)
def test_mean_equals_scipy_dblquad_of_the_preload(args: dict[str, Any], formula: str) -> None:
    """An independent numerical method (adaptive QUADPACK in both coefficients) to 1e-10."""
    (g_lo, g_hi), (k_lo, k_hi) = args["thread_friction_range"], args["bearing_friction_range"]
    total, err = integrate.dblquad(
        lambda mu_k, mu_g: float(_preload(args, mu_g, mu_k, formula)),
        g_lo,
        g_hi,
        k_lo,
        k_hi,
        epsabs=0.0,
        epsrel=1e-13,
    )
    reference = total / ((g_hi - g_lo) * (k_hi - k_lo))
    _, _, mean = _band(args, formula)
    assert err < 1e-11 * abs(total)
    assert mean == pytest.approx(reference, rel=1e-10)


def _closed_form(a: float, b: float, c: float, g: tuple, k: tuple) -> float:
    """Mean of 1/(a + b μ_G + c μ_K) over the box: the double antiderivative s ln s, 60 digits."""
    with localcontext() as ctx:
        ctx.prec = 60
        d = Decimal
        g_lo, g_hi, k_lo, k_hi, a_, b_, c_ = map(d, (*g, *k, a, b, c))

        def phi(s: Decimal) -> Decimal:
            return s * s.ln()

        lo_g, hi_g = a_ + b_ * g_lo, a_ + b_ * g_hi
        lo_k, hi_k = c_ * k_lo, c_ * k_hi
        second = phi(hi_g + hi_k) - phi(lo_g + hi_k) - phi(hi_g + lo_k) + phi(lo_g + lo_k)
        return float(second / ((hi_g - lo_g) * (hi_k - lo_k)))


@pytest.mark.parametrize("pitch", [3e-3, 1.75e-3, 2e-4, 1e-6, 1e-12, 1e-20])
@pytest.mark.parametrize(
    ("g", "k"),
    [
        ((0.0, 1.0), (0.0, 1.0)),
        ((0.0, 1.0), (0.0, 1e-3)),
        ((0.10, 0.20), (0.10, 0.20)),
        ((0.0, 1e-3), (0.0, 1.0)),
        ((0.5, 1.0), (0.3, 0.3000001)),
        ((0.0, 0.3), (0.0, 1e-12)),
    ],
)
def test_vdi2230_mean_equals_the_double_antiderivative(pitch: float, g: tuple, k: tuple) -> None:
    """VDI 2230 R13: k_G = 0.16 P + 0.58 d2 μ_G, k_K = μ_K D_Km/2, linear in both.

    Down to pitches of 1e-20 m (the integrand's singularity 1e-18 below μ_G = 0, many
    panels) and ranges of 1e-12, to 1e-13 relative.
    """
    args = _m12(g, k, pitch)
    a, b, c = 0.16 * pitch, 0.58 * M12[1], 0.25 * (M12[3] + M12[4])
    _, _, mean = _band(args, "vdi2230")
    assert mean == pytest.approx(_closed_form(a, b, c, g, k), rel=1e-13)


def test_exact_formula_mean_equals_quad_over_the_thread_friction() -> None:
    """Random bolts and ranges, ``exact`` k_G (tan(ψ + ρ')): against scipy ``quad`` in μ_G.

    The μ_K mean is ln(1 + cΔ_K/u)/(cΔ_K) (k_K linear); ``quad`` integrates it over μ_G
    adaptively, with no change of variable, to 1e-13.
    """
    rng = np.random.default_rng(7)
    for _ in range(60):
        d = rng.uniform(0.003, 0.06)
        pitch = d * 10 ** rng.uniform(-2.5, -0.8)
        args = {
            "torque": 1.0,
            "pitch": pitch,
            "pitch_diameter": d - 0.649519 * pitch,
            "diameter": d,
            "bearing_outer_diameter": d * rng.uniform(1.3, 2.2),
            "hole_diameter": d * rng.uniform(1.0, 1.2),
        }
        g = tuple(sorted(rng.uniform(0.0, 1.0, 2).tolist()))
        k = tuple(sorted(rng.uniform(0.0, 1.0, 2).tolist()))
        args |= {"thread_friction_range": g, "bearing_friction_range": k}
        k_lo, span = (_preload_parts(args, 0.0, v)[1] for v in (k[0], k[1] - k[0]))

        def inner(mu_g: float, args: dict = args, k_lo: float = k_lo, span: float = span) -> float:
            u = _preload_parts(args, mu_g, 0.0)[0] + k_lo
            return math.log1p(span / u) / span

        total, err = integrate.quad(inner, *g, epsabs=0.0, epsrel=2e-14, limit=200)
        assert err < 1e-12 * total
        _, _, mean = _band(args, "exact")
        assert mean == pytest.approx(total / (g[1] - g[0]), rel=1e-12), (args, g, k)


def _preload_parts(args: dict[str, Any], mu_g: float, mu_k: float) -> tuple[float, float]:
    k_g, k_k = pl.tightening_torque_per_preload(
        args["pitch"],
        args["pitch_diameter"],
        args["diameter"],
        mu_g,
        mu_k,
        args["bearing_outer_diameter"],
        args["hole_diameter"],
        "exact",
    )
    return float(k_g), float(k_k)


@pytest.mark.parametrize("formula", FORMULAS)
def test_monte_carlo_of_a_million_bolts_converges_to_band_and_mean(formula: str) -> None:
    """10⁶ bolts with μ_G, μ_K uniform on 0.10…0.20 ([004, fig. 5]): sample mean within 4
    standard errors of the exact mean; every sample inside the corner band, the extremes
    within 0.2 % of the corners (10⁶ points leave ~1e-3 of each range uncovered)."""
    rng = np.random.default_rng(22)
    mu = rng.uniform(0.10, 0.20, size=(2, 1_000_000))
    forces = _preload(FIG5, mu[0], mu[1], formula)
    low, high, mean = _band(FIG5, formula)
    error = forces.std() / math.sqrt(forces.size)
    assert abs(forces.mean() - mean) < 4.0 * error
    assert error < 1.5e-4 * mean  # the test would see a bias of 6e-4
    assert low <= forces.min() < low * 1.002
    assert high * 0.998 < forces.max() <= high


@pytest.mark.parametrize("formula", FORMULAS)
def test_band_is_the_extremes_of_the_preload_at_the_corners(formula: str) -> None:
    """Min and max are F at (μ_G,max, μ_K,max) and (μ_G,min, μ_K,min), and no grid point
    inside the box lies outside them."""
    corners = [float(_preload(FIG5, g, k, formula)) for g in (0.10, 0.20) for k in (0.10, 0.20)]
    low, high, _ = _band(FIG5, formula)
    assert low == min(corners) == float(_preload(FIG5, 0.20, 0.20, formula))
    assert high == max(corners) == float(_preload(FIG5, 0.10, 0.10, formula))
    grid = np.linspace(0.10, 0.20, 101)
    inside = _preload(FIG5, grid[:, None], grid[None, :], formula)
    assert low <= inside.min() and inside.max() <= high


def test_the_old_midpoint_grid_mean_and_band_against_the_exact_ones() -> None:
    """The figures the note and CHANGELOG give: the 64×64 midpoint grid's mean is 3.8e-6
    low (midpoint rule on a convex integrand) and its band 1.9 % narrow."""
    low, high, mean = _band(FIG5, "vdi2230")
    grid = pl.friction_scatter_preloads(**FIG5)
    assert grid.mean() / mean - 1 == pytest.approx(-3.82e-6, abs=0.02e-6)
    assert (grid.max() - grid.min()) / (high - low) - 1 == pytest.approx(-0.0185, abs=0.0002)
    # the doctest's figures (P = 2.3091, d2 = 14.3753 mm): 19.79…36.27 kN, mean 25.995 kN
    doc = _band(FIG5 | {"pitch": 0.0023091, "pitch_diameter": 0.0143753}, "vdi2230")
    assert doc == pytest.approx((19792.23, 36269.28, 25994.66), abs=0.01)


def test_zero_width_ranges_are_the_limits() -> None:
    """Δ_G = 0: the μ_K mean in closed form; Δ_K = 0 too: F at the point, min = max = mean."""
    args = _m12((0.12, 0.12), (0.10, 0.20))
    k_g, k_lo = _m12_parts(0.12, 0.10)
    c = 0.25 * (M12[3] + M12[4])
    assert k_lo == pytest.approx(0.10 * c, rel=1e-15)  # k_K = μ_K D_Km/2
    expected = math.log((k_g + 0.20 * c) / (k_g + 0.10 * c)) / (0.10 * c)
    assert _band(args, "vdi2230")[2] == pytest.approx(expected, rel=1e-14)
    point = _m12((0.12, 0.12), (0.15, 0.15))
    low, high, mean = _band(point, "vdi2230")
    assert low == high == pytest.approx(1.0 / sum(_m12_parts(0.12, 0.15)), rel=1e-15)
    assert mean == pytest.approx(low, rel=1e-15)
    # a range 1e-15 wide is that limit, not 0/0
    tiny = _m12((0.12, 0.12 + 1e-15), (0.15, 0.15 + 1e-15))
    assert _band(tiny, "vdi2230")[2] == pytest.approx(mean, rel=1e-13)


def _m12_parts(mu_g: float, mu_k: float) -> tuple[float, float]:
    k_g, k_k = pl.tightening_torque_per_preload(*M12[:3], mu_g, mu_k, *M12[3:])
    return float(k_g), float(k_k)


def test_arrays_give_the_scalar_answer_point_by_point() -> None:
    """Points needing one 8-node interval, one 16-node panel and many panels, in one call."""
    pitch = np.array([1.75e-3, 2e-4, 1e-9, 1e-20, 1.75e-3])
    g_lo = np.array([0.10, 0.0, 0.0, 0.0, 0.12])
    g_hi = np.array([0.20, 1.0, 1.0, 0.5, 0.12])
    k_hi = np.array([0.20, 1.0, 0.3, 1e-3, 0.12])
    torque = np.array([50.0, 80.0, 1.0, 2.0, 3.0])
    for formula in FORMULAS:
        got = pl.friction_scatter_band(
            torque, pitch, M12[1], M12[2], (g_lo, g_hi), (0.0, k_hi), M12[3], M12[4], formula
        )
        for j in range(pitch.size):
            one = pl.friction_scatter_band(
                float(torque[j]),
                float(pitch[j]),
                *M12[1:3],
                (float(g_lo[j]), float(g_hi[j])),
                (0.0, float(k_hi[j])),
                *M12[3:],
                formula,
            )
            for arr, value in zip(got, one, strict=True):
                assert arr[j] == pytest.approx(value, rel=1e-14)


def test_a_study_of_tightening_torques_converges_to_the_band_and_mean() -> None:
    """Issue 22's validation through the study engine: a Monte Carlo of ``preload.tightening``.

    At a fixed preload F0 the torque T(μ_G, μ_K) = F0 (k_G + k_K) (VDI 2230 R13, M12);
    the preload the same bolt reaches at a fixed torque M is F0 M / T. Over 200,000
    uniform (μ_G, μ_K) in 0.10…0.20 its mean converges to the exact mean and its
    extremes to the corner band.
    """
    force, torque, n = 30e3, 70.0, 200_000
    study = Study(
        variables=(
            Variable("thread_friction", "uniform", low=0.10, high=0.20),
            Variable("bearing_friction", "uniform", low=0.10, high=0.20),
        ),
        base={"thread_diameter": 0.012, "preload": force},
        samples=n,
        seed=5,
        outputs=("tightening_torque",),
    )
    result = run_study(engine.get_model("preload.tightening"), study)
    reached = force * torque / np.asarray(result.merged.values["tightening_torque"])
    args = _m12((0.10, 0.20), (0.10, 0.20)) | {"torque": torque}
    low, high, mean = _band(args, "vdi2230")
    error = reached.std() / math.sqrt(n)
    assert abs(reached.mean() - mean) < 4.0 * error
    assert low <= reached.min() * (1 - 1e-12) < low * 1.003
    assert high * 0.997 < reached.max() <= high * (1 + 1e-12)


def test_control_reports_the_exact_figures_and_says_so() -> None:
    """The model's scalar and array answers are the band function's; the note says what changed."""
    spec = engine.get_model("preload.control")
    ex = spec.examples[0]
    run = engine.run(spec, ex)
    args = FIG5 | {"torque": float(ex["scatter_torque"])}
    low, high, mean = _band(args, "vdi2230")
    assert run.results["scatter_preload_min"] == pytest.approx(low, rel=1e-4)
    assert run.results["scatter_preload_max"] == pytest.approx(high, rel=1e-4)
    assert run.results["scatter_preload_mean"] == pytest.approx(mean, rel=1e-4)
    assert any("64×64" in n and "exact" in n for n in run.notes)
    described = {o.name: o.description for o in spec.outputs}
    assert "midpoint grid" in described["preload_bins"]


@pytest.mark.parametrize("formula", FORMULAS)
def test_extreme_ranges_give_finite_ordered_figures_on_both_paths(formula: str) -> None:
    """Zero, subnormal and full ranges, pitches down to 1 nm: finite, min ≤ mean ≤ max, the
    array path equal to the scalar one point by point, no floating-point warning."""
    spec = engine.get_model("preload.control")
    values = [0.0, 5e-324, 1e-300, 1e-17, 0.1, 1.0]
    pairs = [(a, b) for a in values for b in values if a <= b]
    g = np.array([p for p in pairs for _ in pairs])
    k = np.array([q for _ in pairs for q in pairs])
    pitch = np.resize([1e-9, 1e-4, 0.002], len(g))
    base = {**spec.examples[0], "torque_formula": formula}
    x, _ = spec.validate(base)
    columns = {
        "thread_friction_min": g[:, 0],
        "thread_friction_max": g[:, 1],
        "bearing_friction_min": k[:, 0],
        "bearing_friction_max": k[:, 1],
        "thread_pitch": pitch,
    }
    names = ("scatter_preload_min", "scatter_preload_mean", "scatter_preload_max")
    with np.errstate(all="raise"):
        got = spec.vectorized(  # type: ignore[misc]
            {**x, **columns}, engine.core.spec.RunContext("closed_form", frozenset(names), 0.01)
        )
    low, mean, high = (np.asarray(got.values[n]) for n in names)
    assert np.isfinite(low).all() and np.isfinite(mean).all() and np.isfinite(high).all()
    assert (low <= mean * (1 + 1e-13)).all() and (mean <= high * (1 + 1e-13)).all()
    for j in range(0, len(g), 7):
        one = engine.run(spec, {**base, **{c: float(v[j]) for c, v in columns.items()}})
        for name, arr in zip(names, (low, mean, high), strict=True):
            assert arr[j] == pytest.approx(one.results[name], rel=1e-12)
