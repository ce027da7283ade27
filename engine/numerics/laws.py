r"""Probability laws written once: cdf, survival, ppf (inverse cdf) and pdf, vectorised.

The design studies draw their points through these functions (:mod:`engine.studies.plan`)
and the clamp-force capability integrates over them (:mod:`engine.physics.capability`),
so a law means the same thing wherever it is used. Every function takes floats or numpy
arrays of one shape.

* uniform on [a, b];
* normal N(m, s);
* truncated normal: N(m, s) restricted to [a, b] (the cdf, sf and pdf are scipy's
  ``truncnorm``; the ppf inverts Φ from the side of the law where the point lies, checked
  against ``truncnorm.ppf``);
* lognormal, **given by its median and geometric standard deviation** (ln X is normal with
  mean ln(median) and sd ln(gsd)); :func:`lognormal_from_mean_sd` converts an arithmetic
  mean and sd to them;
* triangular on [a, b] with mode c;
* two variables joined by a **Gaussian copula**: each variable's normal score
  z = Φ⁻¹(F(x)) (:meth:`Law.score`), the two scores bivariate normal with correlation ρ
  (the Pearson correlation *of the scores*); the rank (Spearman) correlation of the two
  variables, whatever their laws, is ρ_S = (6/π) asin(ρ/2) [Kruskal1958].

:class:`Law` bundles one law's parameters and dispatches to these functions; its
:meth:`Law.score` and :meth:`Law.from_score` keep the digits of tails of 10⁻¹⁵ (a normal or
lognormal score is computed without going through Φ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .lazy import LazyModule

#: scipy, imported on first use (engine.numerics.lazy): it weighs on the service's start-up
special = LazyModule("scipy.special")
stats = LazyModule("scipy.stats")

#: The laws :class:`Law` knows, by ``kind``.
KINDS = ("uniform", "normal", "truncated_normal", "lognormal", "triangular", "fixed")

_SQRT2PI = math.sqrt(2.0 * math.pi)


# --------------------------------------------------------------------------- uniform


def uniform_cdf(x: Any, low: Any, high: Any) -> Any:
    r"""Cumulative probability of the uniform law on [a, b].

    .. math::
        F(x) = \min\!\left(1, \max\!\left(0, \frac{x - a}{b - a}\right)\right)

    >>> round(float(uniform_cdf(0.10, 0.08, 0.16)), 12)
    0.25
    """
    return np.clip((np.asarray(x, dtype=float) - low) / (high - low), 0.0, 1.0)


def uniform_sf(x: Any, low: Any, high: Any) -> Any:
    r"""Survival 1 − F(x) of the uniform law on [a, b], written as (b − x)/(b − a).

    >>> float(uniform_sf(0.10, 0.08, 0.16))
    0.75
    """
    return np.clip((high - np.asarray(x, dtype=float)) / (high - low), 0.0, 1.0)


def uniform_ppf(u: Any, low: Any, high: Any) -> Any:
    r"""Quantile of the uniform law on [a, b]: x = a + u (b − a).

    >>> float(uniform_ppf(0.25, 0.08, 0.16))
    0.1
    """
    return low + u * (high - low)


def uniform_pdf(x: Any, low: Any, high: Any) -> Any:
    r"""Density 1/(b − a) on [a, b], 0 outside.

    >>> float(uniform_pdf(0.1, 0.08, 0.16))
    12.5
    """
    x = np.asarray(x, dtype=float)
    return np.where((x >= low) & (x <= high), 1.0 / (high - low), 0.0)


# --------------------------------------------------------------------------- normal


def normal_cdf(x: Any, mean: Any, sd: Any) -> Any:
    r"""Cumulative probability of N(m, s): Φ((x − m)/s).

    >>> round(float(normal_cdf(-3.0, 0.0, 1.0)), 7)
    0.0013499
    """
    return special.ndtr((np.asarray(x, dtype=float) - mean) / sd)


def normal_sf(x: Any, mean: Any, sd: Any) -> Any:
    r"""Survival of N(m, s): Φ((m − x)/s), without the cancellation of 1 − Φ.

    >>> float(normal_sf(8.0, 0.0, 1.0)) > 0.0
    True
    """
    return special.ndtr((mean - np.asarray(x, dtype=float)) / sd)


def normal_ppf(u: Any, mean: Any, sd: Any) -> Any:
    r"""Quantile of N(m, s): m + s Φ⁻¹(u).

    Φ⁻¹(0.00135) = −3.000 (the 3σ point):

    >>> round(float(normal_ppf(0.00135, 10.0, 2.0)), 3)
    4.0
    """
    return mean + sd * special.ndtri(u)


def normal_pdf(x: Any, mean: Any, sd: Any) -> Any:
    r"""Density of N(m, s): exp(−z²/2)/(s √(2π)), z = (x − m)/s.

    >>> round(float(normal_pdf(0.0, 0.0, 1.0)), 6)
    0.398942
    """
    z = (np.asarray(x, dtype=float) - mean) / sd
    return np.exp(-0.5 * z * z) / (sd * _SQRT2PI)


# --------------------------------------------------------------------------- truncated normal


def _truncated(mean: Any, sd: Any, low: Any, high: Any) -> tuple[Any, Any]:
    return (low - mean) / sd, (high - mean) / sd


def truncated_normal_cdf(x: Any, mean: Any, sd: Any, low: Any, high: Any) -> Any:
    r"""Cumulative probability of N(m, s) truncated to [a, b].

    .. math::
        F(x) = \frac{\Phi(\frac{x-m}{s}) - \Phi(\alpha)}{\Phi(\beta) - \Phi(\alpha)},\quad
        \alpha = \frac{a-m}{s},\ \beta = \frac{b-m}{s}

    >>> round(float(truncated_normal_cdf(0.0, 0.0, 1.0, -1.0, 1.0)), 12)
    0.5
    """
    a, b = _truncated(mean, sd, low, high)
    return stats.truncnorm.cdf(x, a, b, loc=mean, scale=sd)


def truncated_normal_sf(x: Any, mean: Any, sd: Any, low: Any, high: Any) -> Any:
    r"""Survival 1 − F(x) of the truncated normal (scipy's ``truncnorm.sf``).

    (Φ(1) − Φ(0.5))/(Φ(1) − Φ(−1)) = (0.841345 − 0.691462)/0.682689 = 0.21955

    >>> round(float(truncated_normal_sf(0.5, 0.0, 1.0, -1.0, 1.0)), 4)
    0.2195
    """
    a, b = _truncated(mean, sd, low, high)
    return stats.truncnorm.sf(x, a, b, loc=mean, scale=sd)


#: Below this mass Z, u Z (u ≥ 2⁻⁵³) could fall among the subnormal numbers and lose digits:
#: :func:`truncated_normal_ppf` then leaves the law to scipy's log-space ``truncnorm.ppf``
#: (limits beyond about 35.8 standard deviations on one side).
_SMALLEST_MASS = 1e-280


def _normal_mass(alpha: Any, beta: Any) -> Any:
    r"""Φ(β) − Φ(α) (α ≤ β), each difference taken on the side where both terms are small.

    Both limits above 0: Φ(−α) − Φ(−β); both below: Φ(β) − Φ(α); across 0:
    1 − Φ(α) − Φ(−β). No term near 1 is subtracted, so a far-tail interval keeps its digits.
    """
    lower = special.ndtr(alpha)
    upper = special.ndtr(-beta)
    return np.where(
        beta <= 0.0,
        special.ndtr(beta) - lower,
        np.where(alpha >= 0.0, special.ndtr(-alpha) - upper, (1.0 - lower) - upper),
    )


def truncated_normal_ppf(u: Any, mean: Any, sd: Any, low: Any, high: Any) -> Any:
    r"""Quantile of N(m, s) truncated to [a, b]: the inverse of :func:`truncated_normal_cdf`.

    .. math::
        z = \begin{cases}
        \Phi^{-1}\bigl(\Phi(\alpha) + u Z\bigr) & \text{if } \Phi(\alpha) + u Z \le \tfrac12\\
        -\Phi^{-1}\bigl(\Phi(-\beta) + (1 - u) Z\bigr) & \text{otherwise}
        \end{cases},\qquad Z = \Phi(\beta) - \Phi(\alpha),\quad x = m + s z

    Each point is inverted from the side of the law where its probability is at most ½, the
    mass below it (lower half) or above it (upper half), so Φ⁻¹ never receives a probability
    near 1 and an upper-tail draw keeps its digits; Z comes from :func:`_normal_mass`. For
    u ≥ ½ the 1 − u is exact (below ½ the upper half is reached only in a law cut just below
    its mean, and the rounding is inside the error below). z is clipped to [α, β]: near a
    limit the last bit can fall outside (3.6e-15 beyond β = 20.08 sd). One Φ⁻¹ a point
    (scipy's ``ndtri``), about 5 times faster than ``scipy.stats.truncnorm.ppf``.

    Accuracy, against 60-digit mpmath inversions (limits to 37 sd, u from 2⁻⁵³ to 1 − 2⁻⁵³;
    10,230 points of ours and 134,000 of an independent review): within 4.3 ε·max(1, |z|),
    of which ``ndtri`` itself is up to 3.7 ε near p = 0.14; within 2.8 ε for the planner's
    u (10⁻¹² … 1 − 10⁻¹²). scipy 1.17's ``truncnorm.ppf`` was up to 6.4 ε off inside, and in
    the upper tail of a law cut just below its mean 6e-5 sd off at u = 1 − 10⁻¹², 0.25 % off
    or infinite at u = 1 − 2⁻⁵³ (``tests/studies/test_laws.py`` holds the reference).

    u is a probability of at least 2⁻⁵³ (the planner's are ≥ 10⁻¹²): a smaller u can make
    u Z subnormal and lose digits (u = 1e-300 below −9.3 sd: 6e-6 off), and a u outside
    [0, 1] is not refused (it lands on a limit or is NaN). A law with less mass than
    ``_SMALLEST_MASS`` (both limits beyond about 35.8 sd on one side, where u Z could be
    subnormal for any u) is left to ``truncnorm.ppf``, clipped the same way.

    >>> round(float(truncated_normal_ppf(0.5, 0.0, 1.0, -1.0, 1.0)), 12)
    0.0

    One-sided, u = ½: the median of the half-normal above 0 is Φ⁻¹(¾) = 0.674490

    >>> round(float(truncated_normal_ppf(0.5, 0.0, 1.0, 0.0, math.inf)), 6)
    0.67449
    """
    a, b = _truncated(mean, sd, low, high)
    mass = _normal_mass(a, b)
    if not np.all(mass > _SMALLEST_MASS):
        return mean + sd * np.clip(stats.truncnorm.ppf(u, a, b), a, b)
    # three arrays of the points' size, each written in place: a fresh one per operation
    # (twelve) cost the first touch of its pages in a study's draw, more than the
    # arithmetic; and numpy's where takes a branch per value, which a half chosen at random
    # mispredicts half the time (a select and a sign flip of 65,536 values 420 µs, on
    # their bits 80 µs, measured)
    u = np.asarray(u, dtype=float)
    shape = np.broadcast_shapes(u.shape, np.shape(mass))  # the answer's
    below = np.atleast_1d(u * mass)
    below += special.ndtr(a)  # Φ(α) + u Z
    lower_half = below <= 0.5
    z = np.atleast_1d(1.0 - u) * mass  # the mass above the point, Φ(−β) + (1 − u) Z
    z += special.ndtr(-b)
    # the probability each point is inverted from: Φ(α) + u Z in the lower half, else the
    # mass above it (the bits of ``below`` put in ``z`` where ``lower_half``)
    mask = lower_half.astype(np.int64)
    np.negative(mask, out=mask)  # every bit set in the lower half
    bits, other = below.view(np.int64), z.view(np.int64)
    bits ^= other
    bits &= mask
    other ^= bits
    special.ndtri(z, out=z)
    np.invert(mask, out=mask)  # every bit set in the upper half: −z there (its sign bit)
    mask &= np.iinfo(np.int64).min
    other ^= mask
    np.clip(z, a, b, out=z)
    z *= sd
    z += mean
    return z.reshape(shape)[()]


def truncated_normal_pdf(x: Any, mean: Any, sd: Any, low: Any, high: Any) -> Any:
    r"""Density of the truncated normal: φ((x − m)/s)/(s (Φ(β) − Φ(α))) on [a, b].

    >>> round(float(truncated_normal_pdf(0.0, 0.0, 1.0, -1.0, 1.0)), 6)
    0.584369
    """
    a, b = _truncated(mean, sd, low, high)
    return stats.truncnorm.pdf(x, a, b, loc=mean, scale=sd)


# --------------------------------------------------------------------------- lognormal


def lognormal_from_mean_sd(mean: Any, sd: Any) -> tuple[Any, Any]:
    r"""Median and geometric standard deviation of the lognormal law with this mean and sd.

    .. math::
        \sigma_{\ln}^2 = \ln(1 + s^2/m^2),\qquad
        \tilde x = \frac{m}{\sqrt{1 + s^2/m^2}},\qquad \mathrm{gsd} = e^{\sigma_{\ln}}

    cv = 0.1: median 0.12/√1.01 = 0.119404, gsd = exp(√ln 1.01) = exp(0.099751) = 1.104896

    >>> median, gsd = lognormal_from_mean_sd(0.12, 0.012)
    >>> round(float(median), 6), round(float(gsd), 6)
    (0.119404, 1.104896)
    """
    ratio = 1.0 + (sd / mean) ** 2
    return mean / np.sqrt(ratio), np.exp(np.sqrt(np.log(ratio)))


def lognormal_cdf(x: Any, median: Any, gsd: Any) -> Any:
    r"""Cumulative probability of the lognormal law: Φ(ln(x/x̃)/ln gsd), 0 for x ≤ 0.

    >>> float(lognormal_cdf(0.12, 0.12, 1.1))
    0.5
    """
    return special.ndtr(_log_score(x, median, gsd))


def lognormal_sf(x: Any, median: Any, gsd: Any) -> Any:
    r"""Survival of the lognormal law: Φ(−ln(x/x̃)/ln gsd).

    >>> float(lognormal_sf(0.12, 0.12, 1.1))
    0.5
    """
    return special.ndtr(-_log_score(x, median, gsd))


def lognormal_ppf(u: Any, median: Any, gsd: Any) -> Any:
    r"""Quantile of the lognormal law: x̃ · gsd^{Φ⁻¹(u)}.

    >>> round(float(lognormal_ppf(0.8413447460685429, 0.12, 1.1)), 6)
    0.132
    """
    return median * np.exp(np.log(gsd) * special.ndtri(u))


def lognormal_pdf(x: Any, median: Any, gsd: Any) -> Any:
    r"""Density of the lognormal law: φ(z)/(x ln gsd), z = ln(x/x̃)/ln gsd; 0 for x ≤ 0.

    >>> round(float(lognormal_pdf(1.0, 1.0, math.e)), 6)
    0.398942
    """
    x = np.asarray(x, dtype=float)
    z = _log_score(x, median, gsd)
    with np.errstate(divide="ignore", invalid="ignore"):
        dens = np.exp(-0.5 * z * z) / (np.where(x > 0.0, x, 1.0) * np.log(gsd) * _SQRT2PI)
    return np.where(x > 0.0, dens, 0.0)


def truncated_lognormal_ppf(u: Any, median: Any, gsd: Any, low: Any, high: Any) -> Any:
    r"""Quantile of the lognormal law truncated to [a, b] (0 ≤ a < b).

    ln X is the normal law N(ln x̃, ln gsd) truncated to [ln a, ln b], so
    x = exp(:func:`truncated_normal_ppf` (u, ln x̃, ln gsd, ln a, ln b)).

    Without truncation it is the lognormal quantile:

    >>> round(float(truncated_lognormal_ppf(0.8413447460685429, 0.12, 1.1, 0.0, math.inf)), 6)
    0.132
    """
    with np.errstate(divide="ignore"):
        log_low = np.log(np.maximum(low, 0.0))
    return np.exp(truncated_normal_ppf(u, np.log(median), np.log(gsd), log_low, np.log(high)))


def _log_score(x: Any, median: Any, gsd: Any) -> Any:
    x = np.asarray(x, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.log(np.where(x > 0.0, x, 0.0) / median) / np.log(gsd)
    return np.where(x > 0.0, z, -np.inf)


# --------------------------------------------------------------------------- triangular


def _standard_mode(low: Any, mode: Any, high: Any) -> Any:
    return (mode - low) / (high - low)


def triangular_cdf(x: Any, low: Any, mode: Any, high: Any) -> Any:
    r"""Cumulative probability of the triangular law on [a, b] with mode c.

    .. math::
        F(x) = \frac{(x-a)^2}{(b-a)(c-a)}\ (x \le c),\qquad
        1 - \frac{(b-x)^2}{(b-a)(b-c)}\ (x > c)

    >>> float(triangular_cdf(1.0, 0.0, 1.0, 2.0))
    0.5
    """
    return stats.triang.cdf(x, _standard_mode(low, mode, high), loc=low, scale=high - low)


def triangular_sf(x: Any, low: Any, mode: Any, high: Any) -> Any:
    r"""Survival 1 − F(x) of the triangular law.

    >>> float(triangular_sf(1.5, 0.0, 1.0, 2.0))
    0.125
    """
    return stats.triang.sf(x, _standard_mode(low, mode, high), loc=low, scale=high - low)


def triangular_ppf(u: Any, low: Any, mode: Any, high: Any) -> Any:
    r"""Quantile of the triangular law: the inverse of :func:`triangular_cdf`.

    >>> float(triangular_ppf(0.125, 0.0, 1.0, 2.0))
    0.5
    """
    return stats.triang.ppf(u, _standard_mode(low, mode, high), loc=low, scale=high - low)


def triangular_pdf(x: Any, low: Any, mode: Any, high: Any) -> Any:
    r"""Density of the triangular law: 2(x − a)/((b − a)(c − a)) rising, mirrored falling.

    >>> float(triangular_pdf(1.0, 0.0, 1.0, 2.0))
    1.0
    """
    return stats.triang.pdf(x, _standard_mode(low, mode, high), loc=low, scale=high - low)


# --------------------------------------------------------------------------- copula


def spearman_from_copula(rho: Any) -> Any:
    r"""Rank (Spearman) correlation of two variables joined by a Gaussian copula of ρ.

    .. math::
        \rho_S = \frac{6}{\pi} \arcsin\frac{\rho}{2}

    Notes
    -----
    [Kruskal1958]: for a bivariate normal pair the rank correlation is this function of
    the product-moment one; ranks do not change under the monotone maps of a copula, so it
    holds for any two marginal laws.

    >>> round(float(spearman_from_copula(0.5)), 4)
    0.4826
    """
    return 6.0 / math.pi * np.arcsin(0.5 * np.asarray(rho, dtype=float))


def copula_from_spearman(rank_correlation: Any) -> Any:
    r"""The Gaussian copula's ρ that gives a rank correlation ρ_S: ρ = 2 sin(π ρ_S/6).

    >>> round(float(copula_from_spearman(spearman_from_copula(0.3))), 12)
    0.3
    """
    return 2.0 * np.sin(math.pi / 6.0 * np.asarray(rank_correlation, dtype=float))


def conditional_normal_cdf(z: Any, given: Any, rho: Any) -> Any:
    r"""P(Z₂ ≤ z | Z₁ = given) for two standard normal scores of correlation ρ (|ρ| < 1).

    .. math::
        P = \Phi\!\left(\frac{z - \rho z_1}{\sqrt{1 - \rho^2}}\right)

    >>> float(conditional_normal_cdf(0.0, 0.0, 0.9))
    0.5
    >>> round(float(conditional_normal_cdf(1.0, 0.0, 0.0)), 6)
    0.841345
    """
    if np.ndim(rho) == 0 and rho == 0.0:  # independent: the given score does not enter
        return special.ndtr(z)
    return special.ndtr((z - rho * given) / np.sqrt(1.0 - rho * rho))


def correlate_scores(scores: Any, correlation: Any) -> Any:
    r"""Independent standard normal scores (columns) made correlated: Z = W Lᵀ, R = L Lᵀ.

    ``correlation`` is the scores' correlation matrix R (symmetric, positive definite).

    >>> w = np.array([[1.0, 0.0]])
    >>> correlate_scores(w, np.array([[1.0, 0.6], [0.6, 1.0]])).round(6).tolist()
    [[1.0, 0.6]]
    """
    return np.asarray(scores, dtype=float) @ np.linalg.cholesky(correlation).T


# --------------------------------------------------------------------------- one law


@dataclass(frozen=True)
class Law:
    """One law and its parameters (SI units), dispatching to the functions above.

    ``uniform``: low, high. ``normal``: mean, sd. ``truncated_normal``: mean, sd, low, high.
    ``lognormal``: median, gsd (> 1). ``triangular``: low, mode, high. ``fixed``: the one
    value ``mean`` (a law with no scatter; its score is ±∞ either side).
    """

    kind: str
    mean: float = math.nan
    sd: float = math.nan
    low: float = -math.inf
    high: float = math.inf
    mode: float = math.nan
    median: float = math.nan
    gsd: float = math.nan

    def cdf(self, x: Any) -> Any:
        """F(x)."""
        k = self.kind
        if k == "uniform":
            return uniform_cdf(x, self.low, self.high)
        if k == "normal":
            return normal_cdf(x, self.mean, self.sd)
        if k == "truncated_normal":
            return truncated_normal_cdf(x, self.mean, self.sd, self.low, self.high)
        if k == "lognormal":
            return lognormal_cdf(x, self.median, self.gsd)
        if k == "triangular":
            return triangular_cdf(x, self.low, self.mode, self.high)
        return np.where(np.asarray(x, dtype=float) >= self.mean, 1.0, 0.0)

    def sf(self, x: Any) -> Any:
        """1 − F(x), computed on its own side (no cancellation in an upper tail)."""
        k = self.kind
        if k == "uniform":
            return uniform_sf(x, self.low, self.high)
        if k == "normal":
            return normal_sf(x, self.mean, self.sd)
        if k == "truncated_normal":
            return truncated_normal_sf(x, self.mean, self.sd, self.low, self.high)
        if k == "lognormal":
            return lognormal_sf(x, self.median, self.gsd)
        if k == "triangular":
            return triangular_sf(x, self.low, self.mode, self.high)
        return np.where(np.asarray(x, dtype=float) >= self.mean, 0.0, 1.0)

    def ppf(self, u: Any) -> Any:
        """x with F(x) = u."""
        k = self.kind
        if k == "uniform":
            return uniform_ppf(u, self.low, self.high)
        if k == "normal":
            return normal_ppf(u, self.mean, self.sd)
        if k == "truncated_normal":
            return truncated_normal_ppf(u, self.mean, self.sd, self.low, self.high)
        if k == "lognormal":
            return lognormal_ppf(u, self.median, self.gsd)
        if k == "triangular":
            return triangular_ppf(u, self.low, self.mode, self.high)
        return np.full(np.shape(u), self.mean)

    def pdf(self, x: Any) -> Any:
        """Density f(x) (a fixed value has none: 0 everywhere but an atom)."""
        k = self.kind
        if k == "uniform":
            return uniform_pdf(x, self.low, self.high)
        if k == "normal":
            return normal_pdf(x, self.mean, self.sd)
        if k == "truncated_normal":
            return truncated_normal_pdf(x, self.mean, self.sd, self.low, self.high)
        if k == "lognormal":
            return lognormal_pdf(x, self.median, self.gsd)
        if k == "triangular":
            return triangular_pdf(x, self.low, self.mode, self.high)
        return np.zeros(np.shape(x))

    def score(self, x: Any) -> Any:
        """Normal score z = Φ⁻¹(F(x)); exact for normal and lognormal, else from the nearer tail.

        >>> Law("uniform", low=0.0, high=1.0).score(np.array([0.5, 0.0, 1.0])).tolist()
        [0.0, -inf, inf]
        """
        if self.kind == "normal":
            return (np.asarray(x, dtype=float) - self.mean) / self.sd
        if self.kind == "lognormal":
            return _log_score(x, self.median, self.gsd)
        if self.kind == "uniform":  # the nearer tail's share, 0…0.5, straight from x
            u = (np.asarray(x, dtype=float) - self.low) / (self.high - self.low)
            with np.errstate(divide="ignore"):
                z = special.ndtri(np.clip(np.minimum(u, 1.0 - u), 0.0, 0.5))
            return np.where(u <= 0.5, z, -z)
        lower = np.asarray(self.cdf(x), dtype=float)
        upper = np.asarray(self.sf(x), dtype=float)
        with np.errstate(divide="ignore"):
            z = special.ndtri(np.minimum(lower, upper))
        return np.where(lower <= upper, z, -z)

    def from_score(self, z: Any) -> Any:
        """x with normal score z: ppf(Φ(z)), the upper half through Φ(−z) for its digits.

        >>> float(Law("normal", mean=1.0, sd=2.0).from_score(1.5))
        4.0
        """
        z = np.asarray(z, dtype=float)
        if self.kind == "normal":
            return self.mean + self.sd * z
        if self.kind == "lognormal":
            return self.median * np.exp(np.log(self.gsd) * z)
        if self.kind == "fixed":
            return np.full(z.shape, self.mean)
        lower = self.ppf(special.ndtr(np.minimum(z, 0.0)))
        upper = self.ppf(1.0 - special.ndtr(-np.maximum(z, 0.0)))
        return np.where(z <= 0.0, lower, upper)

    @property
    def support(self) -> tuple[float, float]:
        """(lowest, highest) value the law takes."""
        if self.kind in ("uniform", "truncated_normal", "triangular"):
            return self.low, self.high
        if self.kind == "lognormal":
            return 0.0, math.inf
        if self.kind == "fixed":
            return self.mean, self.mean
        return -math.inf, math.inf

    def moments(self) -> tuple[float, float]:
        """(mean, standard deviation) of the law.

        >>> [round(v, 6) for v in Law("uniform", low=0.08, high=0.16).moments()]
        [0.12, 0.023094]
        """
        k = self.kind
        if k == "uniform":
            return 0.5 * (self.low + self.high), (self.high - self.low) / math.sqrt(12.0)
        if k in ("normal", "fixed"):
            return self.mean, 0.0 if k == "fixed" else self.sd
        if k == "truncated_normal":
            a, b = _truncated(self.mean, self.sd, self.low, self.high)
            m, v = stats.truncnorm.stats(a, b, loc=self.mean, scale=self.sd, moments="mv")
            return float(m), math.sqrt(float(v))
        if k == "lognormal":
            s2 = math.log(self.gsd) ** 2
            mean = self.median * math.exp(0.5 * s2)
            return mean, mean * math.sqrt(math.expm1(s2))
        a, c, b = self.low, self.mode, self.high
        var = (a * a + b * b + c * c - a * b - a * c - b * c) / 18.0
        return (a + b + c) / 3.0, math.sqrt(var)


__all__ = [
    "KINDS",
    "Law",
    "conditional_normal_cdf",
    "copula_from_spearman",
    "correlate_scores",
    "lognormal_cdf",
    "lognormal_from_mean_sd",
    "lognormal_pdf",
    "lognormal_ppf",
    "lognormal_sf",
    "normal_cdf",
    "normal_pdf",
    "normal_ppf",
    "normal_sf",
    "spearman_from_copula",
    "triangular_cdf",
    "triangular_pdf",
    "triangular_ppf",
    "triangular_sf",
    "truncated_lognormal_ppf",
    "truncated_normal_cdf",
    "truncated_normal_pdf",
    "truncated_normal_ppf",
    "truncated_normal_sf",
    "uniform_cdf",
    "uniform_pdf",
    "uniform_ppf",
    "uniform_sf",
]
