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
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from scipy.special import erfc

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
    return 0.5 * (erfc((mean - lower_limit) / scale) + erfc((upper_limit - mean) / scale))


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


__all__ = [
    "capability_index",
    "critical_capability_index",
    "mean_shift",
    "normal_fraction_outside",
    "pooled_mean",
    "pooled_standard_deviation",
    "relative_scatter",
    "sample_mean",
    "sample_standard_deviation",
]
