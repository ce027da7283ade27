"""The probability laws written once (engine.numerics.laws) and the studies that draw
through them: scipy.stats as the independent reference, the old laws' draws unchanged to
the bit, lognormal and correlated inputs in a study."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

import engine
from engine import InputOutOfRange
from engine.numerics import laws
from engine.studies.plan import Study, Variable, plan

CLUTCH = engine.get_model("clutch.ball")
BASE = {k: v for k, v in CLUTCH.examples[0].items() if k not in ("flank_friction", "load_factor")}
U = np.linspace(1e-9, 1 - 1e-9, 2001)


def test_lognormal_cdf_ppf_pdf_against_scipy() -> None:
    median, gsd = 0.12, 1.15
    ref = stats.lognorm(s=math.log(gsd), scale=median)
    x = np.linspace(0.01, 0.4, 500)
    assert np.allclose(laws.lognormal_cdf(x, median, gsd), ref.cdf(x), rtol=1e-12, atol=0)
    assert np.allclose(laws.lognormal_sf(x, median, gsd), ref.sf(x), rtol=1e-10, atol=1e-300)
    assert np.allclose(laws.lognormal_pdf(x, median, gsd), ref.pdf(x), rtol=1e-12)
    assert np.allclose(laws.lognormal_ppf(U, median, gsd), ref.ppf(U), rtol=1e-12)
    # mean and sd in, the same law out: E = x̃ exp(s²/2), sd = E √(exp(s²) − 1)
    m, g = laws.lognormal_from_mean_sd(0.12, 0.02)
    mean, sd = stats.lognorm(s=math.log(g), scale=m).stats(moments="mv")
    assert (float(mean), math.sqrt(float(sd))) == pytest.approx((0.12, 0.02), rel=1e-12)
    assert laws.Law("lognormal", median=m, gsd=g).moments() == pytest.approx((0.12, 0.02))


@pytest.mark.parametrize(
    "law, ref",
    [
        (laws.Law("uniform", low=0.08, high=0.16), stats.uniform(0.08, 0.08)),
        (laws.Law("normal", mean=0.12, sd=0.0133), stats.norm(0.12, 0.0133)),
        (
            laws.Law("truncated_normal", mean=0.12, sd=0.02, low=0.09, high=0.2),
            stats.truncnorm(-1.5, 4.0, loc=0.12, scale=0.02),
        ),
        (laws.Law("triangular", low=0.08, mode=0.1, high=0.16), stats.triang(0.25, 0.08, 0.08)),
        (laws.Law("lognormal", median=0.12, gsd=1.2), stats.lognorm(math.log(1.2), scale=0.12)),
    ],
    ids=lambda v: getattr(v, "kind", ""),
)
def test_each_law_against_scipy(law: laws.Law, ref: object) -> None:
    x = ref.ppf(np.linspace(0.001, 0.999, 301))  # type: ignore[attr-defined]
    assert np.allclose(law.cdf(x), ref.cdf(x), rtol=1e-10, atol=1e-14)  # type: ignore[attr-defined]
    assert np.allclose(law.sf(x), ref.sf(x), rtol=1e-10, atol=1e-14)  # type: ignore[attr-defined]
    assert np.allclose(law.pdf(x), ref.pdf(x), rtol=1e-10)  # type: ignore[attr-defined]
    assert np.allclose(law.ppf(U), ref.ppf(U), rtol=1e-10, atol=1e-15)  # type: ignore[attr-defined]
    # the normal score and its inverse go round, deep into both tails
    z = np.linspace(-7.0, 7.0, 57)
    back = law.score(law.from_score(z))
    inside = np.isfinite(back)
    assert inside.sum() > 20
    assert np.allclose(back[inside], z[inside], atol=1e-6)
    mean, sd = law.moments()
    assert (mean, sd) == pytest.approx((float(ref.mean()), float(ref.std())), rel=1e-9)  # type: ignore[attr-defined]


def test_symmetric_laws_are_symmetric() -> None:
    law = laws.Law("triangular", low=0.0, mode=1.0, high=2.0)
    x = np.linspace(0.0, 1.0, 11)
    assert np.allclose(law.cdf(x), law.sf(2.0 - x), atol=1e-15)
    assert np.allclose(laws.normal_cdf(-x, 0.0, 1.0), laws.normal_sf(x, 0.0, 1.0), atol=0)


def test_copula_rank_correlation_by_kruskal() -> None:
    # ρ_S = (6/π) asin(ρ/2): ρ = 1 gives 1, ρ = 0.5 gives 6/π · π/12 ·… = 0.4826
    assert float(laws.spearman_from_copula(1.0)) == pytest.approx(1.0, rel=1e-15)
    assert float(laws.spearman_from_copula(0.5)) == pytest.approx(
        6 / math.pi * math.asin(0.25), rel=1e-15
    )
    rng = np.random.default_rng(4)
    w = rng.standard_normal((200_000, 2))
    z = laws.correlate_scores(w, np.array([[1.0, 0.6], [0.6, 1.0]]))
    x = laws.Law("uniform", low=0.0, high=1.0).from_score(z[:, 0])
    y = laws.Law("lognormal", median=1.0, gsd=2.0).from_score(z[:, 1])
    rank = stats.spearmanr(x, y).statistic
    # the sample's standard error is about 0.0017
    assert rank == pytest.approx(float(laws.spearman_from_copula(0.6)), abs=0.01)


def test_the_old_laws_draw_what_they_drew_before() -> None:
    """The planner's uniform, triangular and (truncated) normal draws equal scipy's calls as
    the planner made them before the laws moved, to the bit."""
    p = plan(
        CLUTCH,
        Study(
            variables=(
                Variable("flank_friction", "triangular", low=0.0, mode=0.05, high=0.2),
                Variable("load_factor", "normal", mean=0.85, sd=0.05, low=0.7),
            ),
            base=BASE,
            samples=500,
            seed=11,
        ),
    )
    u = np.clip(np.random.default_rng(11).random((500, 2)), 1e-12, 1 - 1e-12)
    tri = stats.triang.ppf(u[:, 0], 0.25, loc=0.0, scale=0.2)
    assert np.array_equal(p.columns["flank_friction"], np.clip(tri, 0.0, 0.2))
    # the truncated normal is inverted by our own ppf now: the same points to its last bits
    nor = stats.truncnorm.ppf(u[:, 1], (0.7 - 0.85) / 0.05, (1.0 - 0.85) / 0.05, 0.85, 0.05)
    ours = laws.truncated_normal_ppf(u[:, 1], 0.85, 0.05, 0.7, 1.0)
    assert np.array_equal(p.columns["load_factor"], np.clip(ours, 0.7, 1.0))
    assert np.allclose(ours, nor, rtol=1e-14, atol=0.0)
    q = plan(
        CLUTCH,
        Study(variables=(Variable("flank_friction", low=0.0, high=0.2),), base=BASE, seed=2),
    )
    u1 = np.clip(np.random.default_rng(2).random((1000, 1)), 1e-12, 1 - 1e-12)[:, 0]
    assert np.array_equal(q.columns["flank_friction"], np.clip(0.0 + u1 * 0.2, 0.0, 0.2))


def test_a_lognormal_and_correlated_study() -> None:
    p = plan(
        CLUTCH,
        Study(
            variables=(
                Variable("flank_friction", "lognormal", mean=0.1, sd=0.02),
                Variable("load_factor", low=0.7, high=0.9),
            ),
            base=BASE,
            samples=20_000,
            seed=5,
            correlations=(("flank_friction", "load_factor", -0.5),),
        ),
    )
    mu, lf = p.columns["flank_friction"], p.columns["load_factor"]
    # mean 0.1 and sd 0.02 (the truncation at the declared 0…1 removes nothing)
    assert mu.mean() == pytest.approx(0.1, rel=0.01)
    assert mu.std() == pytest.approx(0.02, rel=0.03)
    assert stats.spearmanr(mu, lf).statistic == pytest.approx(-0.5, abs=0.02)
    assert lf.min() >= 0.7 and lf.max() <= 0.9
    assert any("Gaussian copula" in n for n in p.notes)


@pytest.mark.parametrize(
    "kw, field",
    [
        ({"correlations": (("flank_friction", "flank_friction", 0.5),)}, "correlations"),
        ({"correlations": (("flank_friction", "load_factor", 1.0),)}, "correlations"),
        ({"correlations": (("flank_friction", "nope", 0.2),)}, "correlations"),
        (
            {"method": "sobol", "correlations": (("flank_friction", "load_factor", 0.2),)},
            "correlations",
        ),
    ],
)
def test_correlation_refusals_name_the_field(kw: dict[str, object], field: str) -> None:
    study = Study(
        variables=(
            Variable("flank_friction", low=0.0, high=0.2),
            Variable("load_factor", low=0.7, high=0.9),
        ),
        base=BASE,
        **kw,  # type: ignore[arg-type]
    )
    with pytest.raises(InputOutOfRange) as err:
        plan(CLUTCH, study)
    assert err.value.field == field


def test_contradicting_correlations_are_refused() -> None:
    names = ("flank_friction", "load_factor", "groove_angle")
    study = Study(
        variables=tuple(
            Variable(n, low=lo, high=hi)
            for n, lo, hi in zip(names, (0, 0.7, 0.5), (0.2, 0.9, 0.9), strict=True)
        ),
        base={k: v for k, v in BASE.items() if k != "groove_angle"},
        correlations=(
            (names[0], names[1], 0.9),
            (names[1], names[2], 0.9),
            (names[0], names[2], -0.9),
        ),
    )
    with pytest.raises(InputOutOfRange, match="positive definite"):
        plan(CLUTCH, study)


def test_a_lognormal_law_needs_a_positive_mean() -> None:
    study = Study(
        variables=(Variable("flank_friction", "lognormal", mean=-0.1, sd=0.02),), base=BASE
    )
    with pytest.raises(InputOutOfRange, match="lognormal"):
        plan(CLUTCH, study)


def test_a_correlated_lognormal_study_over_http(monkeypatch: pytest.MonkeyPatch) -> None:
    """The Study schema takes the lognormal law and rank correlations; a refusal names
    ``correlations``."""
    import time

    from fastapi.testclient import TestClient

    from service import create_app

    monkeypatch.setenv("STUDY_INPROCESS_POINTS", "100000")
    body = {
        "base": BASE,
        "variables": [
            {"name": "flank_friction", "distribution": "lognormal", "mean": 0.1, "sd": 0.02},
            {"name": "load_factor", "low": 0.7, "high": 0.9},
        ],
        "samples": 300,
        "outputs": ["torque_limit"],
        "correlations": [{"a": "flank_friction", "b": "load_factor", "rank_correlation": 0.6}],
    }
    with TestClient(create_app(models=[CLUTCH])) as client:  # the model it studies
        r = client.post("/api/v1/clutch/ball/study", json=body)
        assert r.status_code == 202, r.text
        job = r.json()["job"]
        deadline = time.monotonic() + 30
        while (state := client.get(f"/api/v1/jobs/{job}").json())["state"] in ("queued", "running"):
            assert time.monotonic() < deadline
            time.sleep(0.02)
        assert state["state"] == "done", state
        assert any("Gaussian copula" in n for n in state["result"]["notes"])
        bad = {**body, "method": "sobol"}
        refused = client.post("/api/v1/clutch/ball/study", json=bad)
        assert refused.status_code == 422, refused.text
        assert "correlations" in refused.text


#: (α, β, u, z): the standard normal truncated to [α, β], its quantile z at u, from mpmath at
#: 60 digits (findroot on Φ(z) − Φ(α) = u (Φ(β) − Φ(α)), or on the upper tail's 1 − Φ(z)
#: where the point lies above the median), rounded to double. 0.6744897501960817 is the
#: half-normal's median Φ⁻¹(¾) of the printed tables.
TRUNCATED_NORMAL_QUANTILES = (
    (-1.5, 4.0, 0.001, -1.492833695019277),
    (-1.5, 4.0, 0.5, 0.08378865289341855),
    (-1.5, 4.0, 0.999, 3.100849295091483),
    (0.0, math.inf, 0.5, 0.6744897501960817),
    (0.0, math.inf, 1e-12, 1.2533141373155002e-12),
    (0.0, math.inf, 0.999999999999, 7.130509892879273),
    (-math.inf, math.inf, 1e-12, -7.034483825301132),
    (-math.inf, math.inf, 0.999999999999, 7.0344869100478356),
    (-math.inf, math.inf, 0.3, -0.5244005127080408),
    # u = 1 − 2⁻⁵³: scipy 1.17's truncnorm.ppf gives 8.2095 (0.25 % low) and inf here
    (-1.0, math.inf, 0.9999999999999999, 8.230254527416001),
    (-0.1, 20.0, 0.9999999999999999, 8.283242630209834),
    (3.0, math.inf, 0.5, 3.2051549205989334),
    (8.0, 9.0, 0.25, 8.035339621905017),
    (20.0, 35.0, 0.9, 20.114517324364595),
    (-35.0, -20.0, 0.1, -20.114517324364595),
    (-math.inf, -8.0, 1e-12, -10.893038042514783),
    (-math.inf, -8.0, 0.999999, -8.000000123132024),
    (5.0, 5.000001, 0.5, 5.000000499999375),
    (-3.0, -1.0, 0.75, -1.1783481738218142),
    (0.5, 1.0, 0.125, 0.5539625055642615),
    (-0.1, 0.0, 1.1102230246251565e-16, -0.09999999999999999),
    (-8.0, 8.0, 0.5, 0.0),
)


@pytest.mark.parametrize(("alpha", "beta", "u", "z"), TRUNCATED_NORMAL_QUANTILES)
def test_the_truncated_normal_quantile_against_60_digits(
    alpha: float, beta: float, u: float, z: float
) -> None:
    got = float(laws.truncated_normal_ppf(u, 0.0, 1.0, alpha, beta))
    # scipy's ndtri alone is up to 3.7 ε off near p = 0.14; the worst found is 4.3 ε
    assert abs(got - z) <= 5 * np.finfo(float).eps * max(1.0, abs(z)), (got, z)
    # scaled and shifted: x = m + s z
    x = float(laws.truncated_normal_ppf(u, 0.12, 0.02, 0.12 + 0.02 * alpha, 0.12 + 0.02 * beta))
    assert x == pytest.approx(0.12 + 0.02 * z, rel=1e-14, abs=1e-17)


def test_the_truncated_normal_quantile_against_scipy_inside_and_in_the_tails() -> None:
    rng = np.random.default_rng(5)
    u = np.concatenate([rng.random(5000), 10 ** -rng.uniform(0, 12, 500)])
    u = np.clip(np.concatenate([u, 1 - 10 ** -rng.uniform(6, 12, 500)]), 1e-12, 1 - 1e-6)
    limits = (-math.inf, -30.0, -8.0, -3.0, -1.0, -0.1, 0.0, 0.5, 3.0, 8.0, 30.0, math.inf)
    for alpha in limits:
        for beta in limits:
            if not alpha < beta:
                continue
            z = laws.truncated_normal_ppf(u, 0.0, 1.0, alpha, beta)
            ref = stats.truncnorm.ppf(u, alpha, beta)
            # scipy's own error reaches 2e-12 relative where the point lies above the median
            # of a law cut below 0 (-0.1…8 at u = 1 − 1e-6, against mpmath)
            assert np.all(np.abs(z - ref) <= 5e-12 * np.maximum(1.0, np.abs(ref))), (alpha, beta)
            assert np.all((z >= alpha) & (z <= beta))
            assert np.all(np.diff(z[np.argsort(u)]) >= 0.0), (alpha, beta)  # monotone in u


def test_the_truncated_normal_quantile_is_its_own_mirror() -> None:
    # X on [α, β] at u is −X on [−β, −α] at 1 − u (u dyadic, so 1 − u is exact)
    u = np.arange(1, 64) / 64.0
    for alpha, beta in ((-1.5, 4.0), (0.0, math.inf), (3.0, 9.0), (-30.0, -29.0)):
        z = laws.truncated_normal_ppf(u, 0.0, 1.0, alpha, beta)
        mirror = laws.truncated_normal_ppf(1.0 - u, 0.0, 1.0, -beta, -alpha)
        assert np.allclose(z, -mirror, rtol=4 * np.finfo(float).eps, atol=1e-300)


def test_a_truncated_normal_with_a_subnormal_share_is_left_to_scipy() -> None:
    # both limits beyond 35.8 sd: u Z could be subnormal, so scipy's log-space ppf answers
    u = np.array([1e-12, 0.5, 1 - 1e-12])
    z = laws.truncated_normal_ppf(u, 0.0, 1.0, 36.0, 36.5)
    assert np.allclose(z, stats.truncnorm.ppf(u, 36.0, 36.5), rtol=1e-15, atol=0.0)
    assert laws._normal_mass(36.0, 36.5) < laws._SMALLEST_MASS < laws._normal_mass(35.0, 36.0)


@pytest.mark.parametrize(
    ("alpha", "beta"),
    [
        (20.082358186426227, 20.08235821335025),  # ndtri's last bit lands 3.6e-15 beyond β
        (36.56435402478574, 36.56435439035847),  # scipy's (the fallback's), 7.1e-15 beyond
    ],
)
def test_a_quantile_stays_inside_a_narrow_law(alpha: float, beta: float) -> None:
    z = laws.truncated_normal_ppf(np.array([1e-12, 0.5, 1 - 1e-12]), 0.0, 1.0, alpha, beta)
    assert np.all((z >= alpha) & (z <= beta)), z - alpha
