r"""Capability of a tightening tool or process: sample statistics and the Cm/Cmk (Cp/Cpk) indices.

The indices compare the spread of measured torques with the tolerance. A
machine capability test of a tightening tool (VDI/VDE 2645-2) and a process
capability test (VDI/VDE 2645-3) compute them with the same two formulas; they
differ in the data (one run on one tool under controlled conditions, or
subgroups taken from production), not in the arithmetic. The standards are
not public; the formulas are as public secondary sources print them (listed
under VDI/VDE 2645 in docs/sources.md; the worked example is [Danikor]'s):

.. math::
    C_m = \frac{U - L}{6 s}, \qquad
    C_{mk} = \frac{\min(U - \bar x,\ \bar x - L)}{3 s}

with ``s`` the sample standard deviation (divisor n − 1). All functions take
floats or numpy arrays of one shape.

The second half carries a tool's torque law through a joint to its clamp force: the
preload F_M = (M_A − M_ü)/(k_G(μ_G) + k_K(μ_K)) and the bolt's utilisation
ν = σ_red/R_p0.2 of each tightening (VDI 2230-1 R7 and R13, through the joint's own
functions in :mod:`engine.physics.joint` and :mod:`engine.physics.preload`), and their
distribution when the torque and both friction coefficients scatter (laws from
:mod:`engine.numerics.laws`, the frictions joined by a Gaussian copula). Tail
probabilities are integrals, not samples (see :func:`preload_tail`).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..numerics import laws
from ..numerics.laws import Law
from ..numerics.lazy import LazyModule
from . import joint as jt
from . import preload as pl

#: scipy, imported on first use (engine.numerics.lazy): it weighs on the service's start-up
special = LazyModule("scipy.special")

#: Half the 6σ spread: the index divides a half-tolerance by 3σ.
_SIGMAS_PER_SIDE = 3.0


def sample_mean(values: Sequence[float]) -> float:
    r"""Arithmetic mean of a sample.

    .. math::
        \bar x = \frac{1}{n}\sum_{i=1}^{n} x_i

    Parameters
    ----------
    values : sequence of float
        The measured values x_i (n ≥ 1), [any unit]

    Returns
    -------
    float
        x̄, [the unit of the values]

    Notes
    -----
    VDI/VDE 2645-2: the mean of the test values, as Cmk takes it.

    Examples
    --------
    >>> sample_mean([10.0, 10.5, 9.5, 10.0])
    10.0
    """
    return float(np.mean(np.asarray(values, dtype=float)))


def sample_standard_deviation(values: Sequence[float]) -> float:
    r"""Standard deviation of a sample, with Bessel's divisor n − 1.

    .. math::
        s = \sqrt{\frac{1}{n-1}\sum_{i=1}^{n} (x_i - \bar x)^2}

    Parameters
    ----------
    values : sequence of float
        The measured values x_i (n ≥ 2), [any unit]

    Returns
    -------
    float
        s, [the unit of the values]

    Notes
    -----
    VDI/VDE 2645-2: the indices use the sample standard deviation of the
    test values (the estimate of σ from one run).

    Examples
    --------
    By hand: deviations 0, 0.5, −0.5, 0; squares sum to 0.5; 0.5/3 = 0.1667; √ = 0.4082

    >>> round(sample_standard_deviation([10.0, 10.5, 9.5, 10.0]), 4)
    0.4082
    """
    x = np.asarray(values, dtype=float)
    return float(np.std(x, ddof=1))


def capability_index(upper_limit: Any, lower_limit: Any, standard_deviation: Any) -> Any:
    r"""Potential capability index Cm (a machine) or Cp (a process).

    .. math::
        C_m = \frac{U - L}{6 s}

    Parameters
    ----------
    upper_limit : float
        Upper tolerance limit U, [the unit of the values]
    lower_limit : float
        Lower tolerance limit L, [the unit of the values]
    standard_deviation : float
        Sample standard deviation s (> 0), [the unit of the values]

    Returns
    -------
    float
        Cm (or Cp), [-]

    Notes
    -----
    VDI/VDE 2645-2 (Cm), VDI/VDE 2645-3 (Cp): the tolerance width over the 6s
    spread; it ignores where the mean lies, so a tool set off-centre can show a
    high Cm.

    Examples
    --------
    The published torque example of [Danikor]: 0.8 N·m ± 10 %, s = 0.011 N·m

    >>> round(capability_index(0.88, 0.72, 0.011), 2)
    2.42
    """
    return (upper_limit - lower_limit) / (2.0 * _SIGMAS_PER_SIDE * standard_deviation)


def critical_capability_index(
    upper_limit: Any, lower_limit: Any, mean: Any, standard_deviation: Any
) -> Any:
    r"""Critical capability index Cmk (a machine) or Cpk (a process): the nearer limit counts.

    .. math::
        C_{mk} = \frac{\min(U - \bar x,\ \bar x - L)}{3 s}

    Parameters
    ----------
    upper_limit : float
        Upper tolerance limit U, [the unit of the values]
    lower_limit : float
        Lower tolerance limit L, [the unit of the values]
    mean : float
        Sample mean x̄, [the unit of the values]
    standard_deviation : float
        Sample standard deviation s (> 0), [the unit of the values]

    Returns
    -------
    float
        Cmk (or Cpk), [-]; negative when the mean lies outside the tolerance

    Notes
    -----
    VDI/VDE 2645-2 (Cmk), VDI/VDE 2645-3 (Cpk). Cmk ≤ Cm, equal when the
    mean is centred.

    Examples
    --------
    The published torque example of [Danikor]: x̄ = 0.81 N·m, min(0.07, 0.09)/0.033

    >>> round(float(critical_capability_index(0.88, 0.72, 0.81, 0.011)), 2)
    2.12
    """
    margin = np.minimum(upper_limit - mean, mean - lower_limit)
    return margin / (_SIGMAS_PER_SIDE * standard_deviation)


def normal_fraction_outside(
    upper_limit: Any, lower_limit: Any, mean: Any, standard_deviation: Any
) -> Any:
    r"""Share of a normal population outside the tolerance, below L plus above U.

    .. math::
        p = \Phi\!\left(\frac{L - \bar x}{s}\right) + 1 - \Phi\!\left(\frac{U - \bar x}{s}\right),
        \qquad \Phi(z) = \tfrac12 \operatorname{erfc}(-z/\sqrt2)

    Parameters
    ----------
    upper_limit : float
        U, [the unit of the values]
    lower_limit : float
        L, [the unit of the values]
    mean : float
        x̄, [the unit of the values]
    standard_deviation : float
        s (> 0), [the unit of the values]

    Returns
    -------
    float
        p, [-] (multiply by 10⁶ for ppm)

    Notes
    -----
    Reading the indices as a share assumes the values are normal with the
    sample's mean and standard deviation; the capability tests state the index,
    and this share is what it means under that assumption. Both tails are
    written with erfc, so a share of 10⁻¹⁰ keeps its digits.

    Examples
    --------
    A centred process at Cp = 1 (U − L = 6s) leaves 0.27 % outside:

    >>> round(normal_fraction_outside(3.0, -3.0, 0.0, 1.0) * 1e6)
    2700
    """
    scale = standard_deviation * math.sqrt(2.0)
    return 0.5 * (
        special.erfc((mean - lower_limit) / scale) + special.erfc((upper_limit - mean) / scale)
    )


# --------------------------------------------------------------------------- ISO 5393 runs
#
# A tool tested to ISO 5393 gives two runs, one on a hard and one on a soft test joint.
# The functions below pool them: the mean shift between the runs, the mean and the
# standard deviation of the two runs taken as one sample, and the scatter the tool is
# rated by. They take floats or numpy arrays of one shape.


def mean_shift(hard_mean: Any, soft_mean: Any) -> Any:
    r"""Mean shift of a tool between its soft-joint and hard-joint runs.

    .. math::
        \Delta\bar x = \bar x_{soft} - \bar x_{hard}

    Parameters
    ----------
    hard_mean : float
        Mean torque x̄_hard of the run on the hard test joint, [N*m]
    soft_mean : float
        Mean torque x̄_soft of the run on the soft test joint, [N*m]

    Returns
    -------
    float
        Δx̄, [N*m]; negative where the tool gives less on the soft joint (the usual case
        for a tool that shuts off on torque after the joint has relaxed)

    Notes
    -----
    ISO 5393 runs a tool on a hard and a soft test joint; tool makers quote the
    difference of the two means as the tool's mean shift ([Danikor-ISO5393] on ISO 5393's
    6σ accuracy from hard and soft joints).

    Examples
    --------
    >>> round(mean_shift(50.2, 49.4), 6)
    -0.8
    """
    return soft_mean - hard_mean


def pooled_mean(mean_a: Any, count_a: Any, mean_b: Any, count_b: Any) -> Any:
    r"""Mean of two runs taken as one sample.

    .. math::
        \bar x = \frac{n_a \bar x_a + n_b \bar x_b}{n_a + n_b}

    Parameters
    ----------
    mean_a : float
        Mean of the first run, [the unit of the values]
    count_a : int
        Values in the first run n_a, [-]
    mean_b : float
        Mean of the second run, [the unit of the values]
    count_b : int
        Values in the second run n_b, [-]

    Returns
    -------
    float
        x̄ of the n_a + n_b values, [the unit of the values]

    Notes
    -----
    The sum of all values over their number: exact, not a convention. With runs of
    equal size it is the middle of the two means.

    Examples
    --------
    >>> round(pooled_mean(50.2, 25, 49.4, 25), 6)
    49.8
    """
    return (count_a * mean_a + count_b * mean_b) / (count_a + count_b)


def pooled_standard_deviation(
    mean_a: Any, sd_a: Any, count_a: Any, mean_b: Any, sd_b: Any, count_b: Any
) -> Any:
    r"""Standard deviation (n − 1) of two runs taken as one sample, from each run's statistics.

    .. math::
        s = \sqrt{\frac{(n_a - 1) s_a^2 + (n_b - 1) s_b^2
            + \frac{n_a n_b}{n_a + n_b} (\bar x_a - \bar x_b)^2}{n_a + n_b - 1}}

    Parameters
    ----------
    mean_a, sd_a, count_a : float, float, int
        Mean, standard deviation (n − 1) and number of values of the first run
    mean_b, sd_b, count_b : float, float, int
        The same of the second run

    Returns
    -------
    float
        s of the n_a + n_b values, [the unit of the values]

    Notes
    -----
    The sum of squared deviations about the common mean splits exactly into the
    two runs' own sums and the between-run term n_a n_b/(n_a + n_b) Δx̄²; so this is
    what :func:`sample_standard_deviation` gives on the runs' values put together.
    A mean shift widens the pooled spread: a tool rated on both joints pays for it.

    Examples
    --------
    Two runs of two values each, {1, 3} and {5, 7}: s of {1, 3, 5, 7} is √(20/3)

    >>> round(float(pooled_standard_deviation(2.0, 2**0.5, 2, 6.0, 2**0.5, 2)) ** 2 * 3, 9)
    20.0
    """
    n = count_a + count_b
    delta = mean_a - mean_b
    squares = (count_a - 1) * sd_a**2 + (count_b - 1) * sd_b**2 + count_a * count_b / n * delta**2
    return np.sqrt(squares / (n - 1))


def relative_scatter(mean: Any, standard_deviation: Any) -> Any:
    r"""A tool's torque scatter as tool makers rate it: ±3s as a share of the mean.

    .. math::
        \pm\frac{3 s}{\bar x}

    Parameters
    ----------
    mean : float
        x̄ (> 0), [N*m]
    standard_deviation : float
        s, [N*m]

    Returns
    -------
    float
        The half-width of the 6s band over the mean, [-] (0.05 is ±5 %)

    Notes
    -----
    ISO 5393's "6σ accuracy" as [Danikor-ISO5393] quotes it: the 6σ band of the readings on
    the hard and soft joints, stated as ±3σ over the mean.

    Examples
    --------
    >>> round(relative_scatter(50.0, 0.5), 6)
    0.03
    """
    return _SIGMAS_PER_SIDE * standard_deviation / mean


def index_standard_deviation(upper_limit: Any, lower_limit: Any, capability: Any) -> Any:
    r"""The standard deviation a tool at capability index Cm has for a tolerance U − L.

    .. math::
        s = \frac{U - L}{6\,C_m}

    Parameters
    ----------
    upper_limit : float
        U, [the unit of the values]
    lower_limit : float
        L, [the unit of the values]
    capability : float
        Cm (or Cp), > 0, [-]

    Returns
    -------
    float
        s, [the unit of the values]

    Notes
    -----
    :func:`capability_index` solved for s (VDI/VDE 2645-2): a certificate's Cm at its
    tolerance is a statement of the tool's scatter.

    Examples
    --------
    80 N·m ± 10 % at Cm = 1.67: 16/(6 × 1.67) = 1.5968 N·m

    >>> round(index_standard_deviation(88.0, 72.0, 1.67), 4)
    1.5968
    """
    return (upper_limit - lower_limit) / (2.0 * _SIGMAS_PER_SIDE * capability)


def index_mean_offset(capability: Any, critical_capability: Any, standard_deviation: Any) -> Any:
    r"""How far the mean lies from the middle of the tolerance, from Cm, Cmk and s.

    .. math::
        |\bar x - \tfrac{U + L}{2}| = 3 s\,(C_m - C_{mk})

    Parameters
    ----------
    capability : float
        Cm, [-]
    critical_capability : float
        Cmk ≤ Cm, [-]
    standard_deviation : float
        s, [the unit of the values]

    Returns
    -------
    float
        the offset of the mean (its side is not in the indices), [the unit of the values]

    Notes
    -----
    :func:`capability_index` less :func:`critical_capability_index`, VDI/VDE 2645-2:
    (U − L)/(6s) − min(U − x̄, x̄ − L)/(3s) = |x̄ − (U + L)/2|/(3s).

    Examples
    --------
    >>> round(index_mean_offset(1.67, 1.33, 1.5968), 4)
    1.6287
    """
    return _SIGMAS_PER_SIDE * standard_deviation * (capability - critical_capability)


# --------------------------------------------------------------------------- clamp force


@dataclass(frozen=True)
class ClampJoint:
    """What carries a tightening torque to a preload and a bolt utilisation [m, m², Pa, N*m].

    The thread (pitch P, pitch diameter d2, nominal d), the bearing face (d_W, d_h), the
    smallest section (d_0, A_0), the yield strength R_p0.2 and the prevailing torque M_ü
    of the joint (VDI 2230-1 R7, R13).
    """

    pitch: float
    pitch_diameter: float
    diameter: float
    bearing_outer_diameter: float
    hole_diameter: float
    smallest_diameter: float
    smallest_area: float
    yield_strength: float
    prevailing_torque: float = 0.0


#: The standard M12 8.8 coarse through bolt with a hex head (ISO 898-1, ISO 4032 bearing
#: face, medium hole): for the examples below.
M12_88 = ClampJoint(0.00175, 0.010863, 0.012, 0.01663, 0.0135, 0.010358, 84.27e-6, 640e6)


def torque_per_preload(joint: ClampJoint, thread_friction: Any, bearing_friction: Any) -> Any:
    r"""Thread and bearing torque per newton of preload, (k_G, k_K), of ``joint``.

    .. math::
        k_G = 0.16 P + 0.58\,d_2\,\mu_G,\qquad k_K = \mu_K \frac{d_W + d_h}{4}

    Notes
    -----
    VDI 2230-1 R13 through :func:`engine.physics.preload.tightening_torque_per_preload`
    (``"vdi2230"``), the coefficients joint.vdi2230 uses.

    Examples
    --------
    >>> kg, kk = torque_per_preload(M12_88, 0.12, 0.12)
    >>> round(float(kg) * 1e3, 4), round(float(kk) * 1e3, 4)
    (1.0361, 0.9039)
    """
    j = joint
    return pl.tightening_torque_per_preload(
        j.pitch,
        j.pitch_diameter,
        j.diameter,
        thread_friction,
        bearing_friction,
        j.bearing_outer_diameter,
        j.hole_diameter,
    )


def preload_at_torque(
    joint: ClampJoint, torque: Any, thread_friction: Any, bearing_friction: Any
) -> Any:
    r"""Assembly preload one tightening to ``torque`` gives at these frictions.

    .. math::
        F_M = \frac{\max(M_A - M_{\ddot u}, 0)}{k_G(\mu_G) + k_K(\mu_K)}

    Notes
    -----
    VDI 2230-1 R13 solved for the preload, through
    :func:`engine.physics.joint.preload_bounds_from_torque` with no tolerance (its two
    bounds coincide).

    Examples
    --------
    M12 8.8 at 80 N·m, μ = 0.12: 80/(1.0361 + 0.9039) mm = 41.24 kN

    >>> round(float(preload_at_torque(M12_88, 80.0, 0.12, 0.12)) / 1e3, 2)
    41.24
    """
    k = sum(torque_per_preload(joint, thread_friction, bearing_friction))
    return jt.preload_bounds_from_torque(torque, 0.0, joint.prevailing_torque, k, k)[0]


def permissible_preload_at(joint: ClampJoint, thread_friction: Any, utilisation: Any) -> Any:
    r"""Preload at which the bolt's equivalent stress is ν R_p0.2, at this thread friction.

    .. math::
        F_{M,zul} = \frac{\nu R_{p0.2} A_0}{\beta(\mu_G)}

    Notes
    -----
    VDI 2230-1 R7 through :func:`engine.physics.preload.torsion_factor` (``"vdi2230"``)
    and :func:`engine.physics.preload.assembly_preload`.

    Examples
    --------
    >>> round(float(permissible_preload_at(M12_88, 0.12, 0.9)) / 1e3, 2)
    43.11
    """
    j = joint
    beta = pl.torsion_factor(j.pitch, j.pitch_diameter, j.smallest_diameter, thread_friction)
    return pl.assembly_preload(j.yield_strength, j.smallest_area, beta, utilisation)


def bolt_utilisation(joint: ClampJoint, preload: Any, thread_friction: Any) -> Any:
    r"""Share of the yield strength the bolt's equivalent stress uses after tightening.

    .. math::
        \nu = \frac{\sigma_{red,M}}{R_{p0.2}} = \frac{\beta(\mu_G)\,F_M}{A_0 R_{p0.2}}

    Notes
    -----
    VDI 2230-1 R7 (σ_red,M of :func:`engine.physics.preload.equivalent_stress`); ν > 0.9
    is the preload above F_M,zul.

    Examples
    --------
    At F_M,zul itself ν is 0.9:

    >>> round(float(bolt_utilisation(M12_88, permissible_preload_at(M12_88, 0.12, 0.9), 0.12)), 12)
    0.9
    >>> round(float(bolt_utilisation(M12_88, 43110.0, 0.12)), 4)  # Table A1's 43.1 kN
    0.8999
    """
    j = joint
    beta = pl.torsion_factor(j.pitch, j.pitch_diameter, j.smallest_diameter, thread_friction)
    return pl.equivalent_stress(preload, j.smallest_area, beta) / j.yield_strength


@dataclass(frozen=True)
class Scatter:
    """The laws of one tightening: torque, thread friction μ_G, bearing friction μ_K, and the
    Gaussian copula's correlation ρ of the two frictions' normal scores (|ρ| < 1)."""

    torque: Law
    thread: Law
    bearing: Law
    correlation: float = 0.0


#: Half-width of the integration range in normal scores: P(|Z| > 9) = 2e-19.
SCORE_SPAN = 9.0
#: Gauss-Legendre nodes per panel.
PANEL_NODES = 8
#: Levels at which :func:`tail_quantiles` tabulates a tail.
TABLE_LEVELS = 16


@functools.lru_cache(maxsize=16)
def score_rule(panels: int) -> tuple[np.ndarray, np.ndarray]:
    r"""Nodes z and weights w·φ(z) of composite Gauss-Legendre on [−9, 9] for E[g(Z)], Z ~ N(0, 1).

    ``panels`` equal panels of :data:`PANEL_NODES` nodes; the standard normal density is in
    the weights, so Σ w_i g(z_i) ≈ E[g(Z)].

    Examples
    --------
    E[1] = E[Z²] = 1 (8 panels: to 1e-11; 16: to the last digits):

    >>> z, w = score_rule(8)
    >>> round(float(w.sum()), 10), round(float((w * z * z).sum()), 10)
    (1.0, 1.0)
    >>> z, w = score_rule(16)
    >>> round(float(w.sum()), 14), round(float((w * z * z).sum()), 14)
    (1.0, 1.0)
    """
    x, w = np.polynomial.legendre.leggauss(PANEL_NODES)
    edges = np.linspace(-SCORE_SPAN, SCORE_SPAN, panels + 1)
    half = 0.5 * np.diff(edges)
    mid = 0.5 * (edges[1:] + edges[:-1])
    z = (mid[:, None] + half[:, None] * x[None, :]).ravel()
    weights = (half[:, None] * w[None, :]).ravel() * laws.normal_pdf(z, 0.0, 1.0)
    z.flags.writeable = False
    weights.flags.writeable = False
    return z, weights


def _friction_grid(scatter: Scatter, panels: int) -> tuple[Any, Any, Any, Any]:
    """μ_G, μ_K and weights on the (z_G, w) grid, z_K = ρ z_G + √(1 − ρ²) w."""
    z, w = score_rule(panels)
    rho = scatter.correlation
    z_g, z_w = z[:, None], z[None, :]
    z_k = rho * z_g + math.sqrt(1.0 - rho * rho) * z_w
    mu_g = scatter.thread.from_score(z_g)
    mu_k = scatter.bearing.from_score(z_k)
    return mu_g, mu_k, w[:, None] * w[None, :], z_g


def _tail(
    joint: ClampJoint,
    scatter: Scatter,
    level: Callable[[Any], Any],
    upper: bool,
    panels: int,
) -> Any:
    """P(F_M > level) (``upper``) or P(F_M ≤ level) for each row of levels, by quadrature.

    ``level(mu_g)`` gives the levels against μ_G's nodes, shape (levels, nodes). Over the
    scores of the torque and of μ_G, the bearing friction that reaches the level in closed
    form (k_K is linear in μ_K), conditioned on μ_G's score through the copula. A fixed
    bearing friction: over μ_G's score, the torque that reaches the level in closed form.
    """
    z, w = score_rule(panels)
    mu_g = scatter.thread.from_score(z)
    x: Any = np.atleast_2d(level(mu_g))
    if scatter.bearing.kind == "fixed":
        k_g, k_k = torque_per_preload(joint, mu_g, scatter.bearing.mean)
        needed = jt.tightening_torque(x, k_g, k_k, joint.prevailing_torque)
        p = scatter.torque.sf(needed) if upper else scatter.torque.cdf(needed)
        return np.sum(w * p, axis=-1)
    if scatter.torque.kind == "fixed":
        torque, w_t = np.array([scatter.torque.mean]), np.ones(1)
    else:
        torque, w_t = np.asarray(scatter.torque.from_score(z)), w
    k_g, unit_k = torque_per_preload(joint, mu_g, 1.0)
    least = np.asarray(jt.tightening_torque(x, k_g, 0.0, joint.prevailing_torque))
    with np.errstate(divide="ignore", invalid="ignore"):
        # F_M > x  ⟺  M_A > x k_G + x μ_K k_K(1) + M_ü  ⟺  μ_K < (M_A − that)/(x k_K(1))
        spare = torque[None, :, None] - least[:, None, :]
        mu_k = np.where(x[:, None, :] > 0.0, spare / (x * unit_k)[:, None, :], np.inf)
    score = scatter.bearing.score(mu_k)
    rho = scatter.correlation
    if upper:
        p = laws.conditional_normal_cdf(score, z, rho)
    else:
        p = laws.conditional_normal_cdf(-score, -z, rho)
    return np.einsum("t,g,ltg->l", w_t, w, p)


def preload_tail(
    joint: ClampJoint, scatter: Scatter, preload: float, upper: bool = True, panels: int = 16
) -> float:
    r"""P(F_M > x) (``upper``) or P(F_M ≤ x) of one tightening, by quadrature.

    .. math::
        P(F_M > x) = \int\!\!\int \varphi(z_G)\,\varphi(w)\;
            S_T\!\big(M_A^*(x, \mu_G, \mu_K)\big)\,dz_G\,dw,\qquad
        M_A^* = x\,(k_G + k_K) + M_{\ddot u}

    with μ_G = F_G⁻¹(Φ(z_G)), μ_K = F_K⁻¹(Φ(ρ z_G + √(1−ρ²) w)) (the copula) and S_T the
    torque law's survival. With a fixed torque the inner variable is μ_K instead:
    P = ∫ φ(z_G) Φ((z_K* − ρ z_G)/√(1 − ρ²)) dz_G, z_K* the score of the bearing friction
    at which F_M = x.

    Parameters
    ----------
    joint : ClampJoint
    scatter : Scatter
    preload : float
        x, [N]
    upper : bool
        the upper tail (True) or the lower
    panels : int
        Gauss-Legendre panels on each score axis (8 nodes each) over [−9, 9]

    Returns
    -------
    float
        the probability, [-]

    Notes
    -----
    F_M is smooth and monotone in (M_A, μ_G, μ_K), so the tail to 10⁻⁶ is an integral of
    a smooth function over the frictions' normal scores, written directly (no sampling);
    :func:`tail_with_error` states its error from two panel counts. The torque law's
    survival and the copula are :mod:`engine.numerics.laws`'.

    Examples
    --------
    A normal torque and fixed frictions: F_M is normal, so P(F_M > mean + 3 sd) is Φ(−3):

    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("normal", mean=80.0, sd=2.0), fixed, fixed)
    >>> k = sum(torque_per_preload(M12_88, 0.12, 0.12))
    >>> round(preload_tail(M12_88, s, 86.0 / k) * 1e6, 1)
    1349.9
    """
    return float(preload_tails(joint, scatter, np.array([preload]), upper, panels)[0])


def preload_tails(
    joint: ClampJoint, scatter: Scatter, preloads: Any, upper: bool, panels: int
) -> Any:
    """:func:`preload_tail` at each of an array of levels, in one evaluation.

    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("normal", mean=80.0, sd=2.0), fixed, fixed)
    >>> k = sum(torque_per_preload(M12_88, 0.12, 0.12))
    >>> (preload_tails(M12_88, s, np.array([74.0, 86.0]) / k, False, 16) * 1e6).round(1).tolist()
    [1349.9, 998650.1]
    """
    levels = np.asarray(preloads, dtype=float)[:, None]
    return _tail(joint, scatter, lambda mu_g: levels + 0.0 * mu_g, upper, panels)


def utilisation_tail(
    joint: ClampJoint, scatter: Scatter, utilisation: float, upper: bool = True, panels: int = 16
) -> float:
    r"""P(ν > ν₀) (``upper``) or P(ν ≤ ν₀): the share of bolts above a utilisation.

    .. math::
        P(\nu > \nu_0) = P\big(F_M > F_{M,zul}(\mu_G, \nu_0)\big)

    each bolt against the permissible preload at its own thread friction
    (:func:`permissible_preload_at`), integrated as :func:`preload_tail`.

    Examples
    --------
    A fixed torque and fixed frictions: every bolt at 80 N·m and μ = 0.12 has
    ν = 0.9 × 41.24/43.11 = 0.861, so none lies above 0.9 and all above 0.85:

    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("fixed", mean=80.0), fixed, fixed)
    >>> utilisation_tail(M12_88, s, 0.9), utilisation_tail(M12_88, s, 0.85)
    (0.0, 1.0)
    """
    return float(utilisation_tails(joint, scatter, np.array([utilisation]), upper, panels)[0])


def utilisation_tails(
    joint: ClampJoint, scatter: Scatter, utilisations: Any, upper: bool, panels: int
) -> Any:
    """:func:`utilisation_tail` at each of an array of levels, in one evaluation.

    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("fixed", mean=80.0), fixed, fixed)
    >>> utilisation_tails(M12_88, s, np.array([0.85, 0.9]), True, 8).round(9).tolist()
    [1.0, 0.0]
    """
    levels = np.asarray(utilisations, dtype=float)[:, None]
    return _tail(
        joint, scatter, lambda mu_g: permissible_preload_at(joint, mu_g, levels), upper, panels
    )


def tail_with_error(
    tail: Callable[[int], float], target: float = 1e-3, most_panels: int = 128
) -> tuple[float, float, int]:
    r"""A tail probability and its relative error from two panel counts.

    ``tail(panels)`` is evaluated at 8, 16, 32, … panels until two successive values agree
    to ``target`` (relative) or ``most_panels`` is reached.

    .. math::
        \varepsilon = \frac{|P_{2N} - P_N|}{\max(P_{2N}, 10^{-12})}

    Returns
    -------
    tuple
        (P_2N, ε, 2N): the finer value, its estimated relative error (the change from the
        coarser, an overestimate for a rule that converges faster than linearly), the
        panels used; probabilities under 10⁻¹² (10⁻⁶ ppm) are stated to that absolute level.

    Examples
    --------
    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("normal", mean=80.0, sd=2.0), fixed, fixed)
    >>> p, err, n = tail_with_error(lambda k: preload_tail(M12_88, s, 43000.0, True, k))
    >>> err < 1e-9, n
    (True, 16)
    """
    panels = 8
    coarse = tail(panels)
    while True:
        fine = tail(2 * panels)
        error = abs(fine - coarse) / max(fine, 1e-12)
        panels *= 2
        if error <= target or panels >= most_panels:
            return fine, error, panels
        coarse = fine


def preload_moments(joint: ClampJoint, scatter: Scatter, panels: int = 16) -> tuple[float, float]:
    r"""Mean and standard deviation of F_M over the torque law and the frictions.

    .. math::
        E[F_M^n] = E\big[(M_A - M_{\ddot u})_+^n\big]\;E\big[(k_G + k_K)^{-n}\big]

    the torque independent of the frictions, each expectation by the quadrature of
    :func:`score_rule` (the frictions over their copula).

    Examples
    --------
    A normal torque and fixed frictions: F_M is normal, mean 80/k, sd 2/k:

    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("normal", mean=80.0, sd=2.0), fixed, fixed)
    >>> k = sum(torque_per_preload(M12_88, 0.12, 0.12))
    >>> mean, sd = preload_moments(M12_88, s)
    >>> round(mean * k, 9), round(sd * k, 9)
    (80.0, 2.0)
    """
    z, w = score_rule(panels)
    torque = scatter.torque.from_score(z)
    unit = jt.preload_bounds_from_torque(torque, 0.0, joint.prevailing_torque, 1.0, 1.0)[0]
    mu_g, mu_k, weight, _ = _friction_grid(scatter, panels)
    inverse = 1.0 / sum(torque_per_preload(joint, mu_g, mu_k))
    first = float(np.sum(w * unit)) * float(np.sum(weight * inverse))
    second = float(np.sum(w * unit * unit)) * float(np.sum(weight * inverse * inverse))
    return first, math.sqrt(max(second - first * first, 0.0))


def _refine(gap: Callable[[Any], Any], low: float, guess: float, high: float) -> float:
    """The root of a rising ``gap`` in [low, high] from ``guess``: regula falsi (Illinois),
    the bracket kept, until a step moves x by less than 1e-9 (at most 8 evaluations)."""
    g = float(gap(np.array([guess]))[0])
    # the other end of the bracket, on the finer rule too
    other = high if g < 0.0 else low
    g_other = float(gap(np.array([other]))[0])
    if (g < 0.0) == (g_other < 0.0):  # the finer rule moved the root off the coarse bracket
        return guess
    g_low, g_high = (g, g_other) if g < 0.0 else (g_other, g)
    x = guess
    side = 0
    for _ in range(8):
        if g == 0.0 or not math.isfinite(g):
            break
        if g < 0.0:
            low, g_low = x, g
            if side == -1:
                g_high *= 0.5
            side = -1
        else:
            high, g_high = x, g
            if side == 1:
                g_low *= 0.5
            side = 1
        step = high - g_high * (high - low) / (g_high - g_low) - x
        x += step
        if abs(step) <= 1e-9 * abs(x):
            break
        g = float(gap(np.array([x]))[0])
    return x


def tail_quantiles(
    tails: Callable[[Any, bool, int], Any],
    probabilities: Sequence[float],
    low: float,
    high: float,
    panels: int = 8,
) -> list[float]:
    r"""The x with P(X ≤ x) = q for each q, from a batched ``tails(x, upper, panels)``.

    Both tails are tabulated at :data:`TABLE_LEVELS` levels from ``low`` to ``high`` on a
    quarter rule (4 panels); each quantile is interpolated linearly in the tail's normal
    score Φ⁻¹(P) between the two levels around it (exact where X is normal), then refined
    on ``panels`` by regula falsi within those two levels. The lower tail serves
    q < 0.5 and the upper tail 1 − q otherwise (no cancellation at 1 − 10⁻⁶). ``low``
    when even it holds a share q (an atom at 0).

    Examples
    --------
    >>> fixed = Law("fixed", mean=0.12)
    >>> s = Scatter(Law("normal", mean=80.0, sd=2.0), fixed, fixed)
    >>> k = sum(torque_per_preload(M12_88, 0.12, 0.12))
    >>> tails = lambda x, up, n: preload_tails(M12_88, s, x, up, n)
    >>> [round(x * k, 6) for x in tail_quantiles(tails, [0.00135, 0.5], 60.0 / k, 100.0 / k)]
    [74.000046, 80.0]

    (Φ⁻¹(0.00135) = −2.999977, so 80 − 2.999977 × 2 = 74.000046.)
    """
    x = [float(v) for v in np.linspace(low, high, TABLE_LEVELS)]
    levels = np.array(x)
    table: dict[bool, Any] = {}

    def score(p: Any, upper: bool) -> Any:
        s = special.ndtri(np.clip(p, 1e-300, 1.0 - 1e-16))
        return -s if upper else s  # rising with x either way

    out = []
    for q in probabilities:
        upper = q >= 0.5
        if upper not in table:
            table[upper] = np.asarray(tails(levels, upper, 4))
        target = float(special.ndtri(1.0 - q if upper else q)) * (-1.0 if upper else 1.0)
        g = score(table[upper], upper) - target
        above = np.flatnonzero(g >= 0.0)
        if above.size == 0:
            out.append(high)
            continue
        i = int(above[0])
        if i == 0:
            out.append(low)
            continue
        x0, x1, g0, g1 = x[i - 1], x[i], float(g[i - 1]), float(g[i])
        guess = float(x0 - g0 * (x1 - x0) / (g1 - g0))

        def gap(v: Any, up: bool = upper, aim: float = target) -> Any:
            return score(tails(v, up, panels), up) - aim

        out.append(_refine(gap, x0, guess, x1))
    return out


__all__ = [
    "M12_88",
    "ClampJoint",
    "Scatter",
    "bolt_utilisation",
    "capability_index",
    "critical_capability_index",
    "index_mean_offset",
    "index_standard_deviation",
    "mean_shift",
    "normal_fraction_outside",
    "permissible_preload_at",
    "pooled_mean",
    "pooled_standard_deviation",
    "preload_at_torque",
    "preload_moments",
    "preload_tail",
    "preload_tails",
    "relative_scatter",
    "sample_mean",
    "sample_standard_deviation",
    "score_rule",
    "tail_quantiles",
    "tail_with_error",
    "torque_per_preload",
    "utilisation_tail",
    "utilisation_tails",
]
