r"""A tightening trace (torque against angle) read against the joint it tightened.

Two halves. The prediction: the elastic torque rate a joint gives, from its compliance and
its torque coefficient, and its inverse, the torque coefficient (and so the friction) a
measured rate implies. The detection: on arrays of angle and torque as a controller records
them, the steps of a multi-step program, the gradient, the elastic rate by a robust line,
the snug point and the yield point by gradient drop.

The prediction is [004, eq. 8] differentiated: once snug, the nut turns 360° to move the
preload by P/(δ_S + δ_P), so

.. math::
    \frac{dF}{d\theta} = \frac{P}{2\pi(\delta_S + \delta_P)},\qquad
    \frac{dT}{d\theta} = k\,\frac{dF}{d\theta},\qquad
    k = \frac{T - M_{\ddot u}}{F} = 0.16\,P + 0.58\,d_2\,\mu_G + \frac{D_{Km}}{2}\,\mu_K

with k of VDI 2230-1 R13 (:func:`engine.physics.preload.tightening_torque_per_preload`).
The angle the tool records includes the twist of its socket and spindle, T/c_t, which
:func:`nut_angle` takes off. The twist of the bolt itself under its thread torque is not
modelled (it is part of the compliance uncertainty the analysis states).

Detection functions take one trace as 1-D arrays or many traces of one length as 2-D arrays
(one trace a row); the sample axis is the last.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .capability import (
    capability_index,
    critical_capability_index,
    sample_mean,
    sample_standard_deviation,
)
from .preload import nut_rotation_angle, tightening_torque_per_preload

#: Share of the elastic rate below which the gradient marks the yield point: the default
#: of yield-point-controlled tightening in [Desoutter-CVIR] (X % = 50).
YIELD_GRADIENT_FRACTION = 0.5
#: Share of the elastic rate the gradient reaches at the snug point (our rule, named).
SNUG_GRADIENT_FRACTION = 0.5
#: The elastic window: torques between these shares of the step's peak torque.
ELASTIC_WINDOW = (0.3, 0.7)
#: A step: a run of samples whose torque stays above this share of the trace's peak.
STEP_ZERO_FRACTION = 0.02
#: Residuals beyond this many robust standard deviations (1.4826 MAD) leave the elastic fit.
OUTLIER_CUT = 3.0


# --------------------------------------------------------------------------- prediction


def elastic_torque_rate(torque_per_preload: Any, total_compliance: Any, pitch: Any) -> Any:
    r"""Torque rate dT/dθ of the elastic part of a tightening, [N*m/rad].

    .. math::
        \frac{dT}{d\theta} = \frac{k\,P}{2\pi\,(\delta_S + \delta_P)}

    Parameters
    ----------
    torque_per_preload : float or numpy array
        k = (T − M_ü)/F, thread plus bearing torque per newton of preload, [m]
    total_compliance : float or numpy array
        δ_S + δ_P, bolt plus clamped parts, [m/N]
    pitch : float or numpy array
        P, [m]

    Returns
    -------
    float or numpy array
        dT/dθ, [N*m/rad]

    Notes
    -----
    [004, eq. 8] (the nut angle that gives a preload, :func:`engine.physics.preload.
    nut_rotation_angle`) per newton, times the torque per newton of VDI 2230-1 R13. Valid
    from the snug point to the onset of yield; all arguments may be arrays.

    Examples
    --------
    M12 × 1.75 through 2 × 20 mm steel (δ_S + δ_P = 4.0099 µm/kN), μ_G = μ_K = 0.08,
    k = 1.3867 mm: 1.3867e-3 · 1.75e-3 / (2π · 4.0099e-9) = 96.31 N·m/rad = 1.681 N·m/°

    >>> import math
    >>> round(elastic_torque_rate(1.38666e-3, 4.00995e-9, 0.00175) * math.pi / 180, 3)
    1.681
    """
    return torque_per_preload / nut_rotation_angle(1.0, total_compliance, pitch)


def torque_per_preload_from_rate(rate: Any, total_compliance: Any, pitch: Any) -> Any:
    r"""Torque coefficient k a measured elastic rate implies, [m]: :func:`elastic_torque_rate`
    solved for k.

    .. math::
        k = \frac{dT}{d\theta}\,\frac{2\pi\,(\delta_S + \delta_P)}{P}

    Parameters
    ----------
    rate : float or numpy array
        Measured dT/dθ at the nut, [N*m/rad]
    total_compliance : float or numpy array
        δ_S + δ_P, [m/N]
    pitch : float or numpy array
        P, [m]

    Returns
    -------
    float or numpy array
        k, [m]

    Notes
    -----
    [004, eq. 8] inverted. A compliance wrong by a share e gives k wrong by the same share.

    Examples
    --------
    >>> round(torque_per_preload_from_rate(96.31, 4.00995e-9, 0.00175) * 1e3, 4)
    1.3866
    """
    return rate * nut_rotation_angle(1.0, total_compliance, pitch)


def friction_from_torque_per_preload(
    torque_per_preload: Any,
    pitch: float,
    pitch_diameter: float,
    diameter: float,
    bearing_outer_diameter: float,
    hole_diameter: float,
    bearing_to_thread: Any = 1.0,
) -> Any:
    r"""Thread friction μ_G that gives a torque coefficient k when μ_K = r μ_G.

    .. math::
        \mu_G = \frac{k - k(0, 0)}{k(1, r) - k(0, 0)},\qquad \mu_K = r\,\mu_G

    Parameters
    ----------
    torque_per_preload : float or numpy array
        k, [m]
    pitch, pitch_diameter, diameter : float
        P, d2, d, [m]
    bearing_outer_diameter, hole_diameter : float
        d_W and d_h of the bearing face, [m]
    bearing_to_thread : float or numpy array
        r = μ_K/μ_G, the friction split; 1 gives the total friction μ_ges, [-]

    Returns
    -------
    float or numpy array
        μ_G, [-]

    Notes
    -----
    VDI 2230-1 R13's k(μ_G, μ_K) (:func:`engine.physics.preload.tightening_torque_per_preload`)
    is linear in both coefficients; this solves it along μ_K = r μ_G through two of its
    values. With r = 1 it is the total friction μ_ges that VDI 2230 and ISO 16047 use.

    Examples
    --------
    M12, d_W = 16.63 mm, d_h = 13.5 mm: k = 1.9400 mm is μ_ges = 0.12

    >>> round(friction_from_torque_per_preload(1.94e-3, 0.00175, 0.010863, 0.012,
    ...                                        0.01663, 0.0135), 4)
    0.12
    """
    geometry = (pitch, pitch_diameter, diameter)
    bearing = (bearing_outer_diameter, hole_diameter)
    k0 = sum(tightening_torque_per_preload(*geometry, 0.0, 0.0, *bearing))
    k1 = sum(tightening_torque_per_preload(*geometry, 1.0, bearing_to_thread, *bearing))
    return (torque_per_preload - k0) / (k1 - k0)


def nut_angle(angle: Any, torque: Any, tool_stiffness: float | None) -> Any:
    r"""Angle of the nut from the angle the tool recorded, [rad].

    .. math::
        \theta_{nut} = \theta_{tool} - \frac{T}{c_t}

    Parameters
    ----------
    angle : float or numpy array
        Angle the tool's encoder recorded, [rad]
    torque : float or numpy array
        Torque at that sample, [N*m]
    tool_stiffness : float or None
        c_t, torsional stiffness of spindle, socket and extension in series between the
        encoder and the nut, [N*m/rad]; None: rigid

    Returns
    -------
    float or numpy array
        θ_nut, [rad]

    Notes
    -----
    Linear torsion of the drive train (the stiffnesses in series, 1/c_t = Σ 1/c_i); a
    measured elastic rate R_tool becomes 1/(1/R_tool − 1/c_t) at the nut.

    Examples
    --------
    50 N·m through a drive train of 2000 N·m/rad: 0.025 rad (1.43°) of wind-up

    >>> round(nut_angle(1.0, 50.0, 2000.0), 4)
    0.975
    """
    if tool_stiffness is None:
        return angle
    return angle - torque / tool_stiffness


def preload_from_torque(torque: Any, torque_per_preload: Any, prevailing_torque: Any = 0.0) -> Any:
    r"""Preload at a torque for a torque coefficient, [N].

    .. math::
        F = \frac{T - M_{\ddot u}}{k}

    Parameters
    ----------
    torque : float or numpy array
        T, [N*m]
    torque_per_preload : float or numpy array
        k, [m]
    prevailing_torque : float or numpy array
        M_ü, the torque that makes no preload, [N*m]

    Returns
    -------
    float or numpy array
        F, [N]

    Notes
    -----
    VDI 2230-1 R13 solved for the preload. It holds past yield too: the friction torques
    follow the preload whatever stretches the bolt.

    Examples
    --------
    >>> round(preload_from_torque(83.64, 1.94e-3))
    43113
    """
    return (torque - prevailing_torque) / torque_per_preload


# --------------------------------------------------------------------------- detection


def split_steps(
    torque: Any,
    angle: Any = None,
    zero_fraction: float = STEP_ZERO_FRACTION,
    min_samples: int = 3,
) -> list[tuple[int, int]]:
    r"""The steps of a multi-step tightening: runs whose torque stays above a floor.

    .. math::
        \text{step} = \{\,i : T_i > z\,\max_j T_j\,\}\ \text{(maximal runs)}

    Parameters
    ----------
    torque : numpy array
        T of one trace, [N*m]
    angle : numpy array or None
        θ of the same samples, [rad]: a step reaches back over the low torques before it
        (the run-down, the snug region) while the angle does not fall
    zero_fraction : float
        z, the share of the peak torque below which the tool is taken as off the joint
        (a pause, a loosening: torque at or below zero), [-]
    min_samples : int
        Shortest run that counts as a step

    Returns
    -------
    list of (start, stop)
        Index ranges ``torque[start:stop]``, in order

    Notes
    -----
    Our rule: a program's steps (run-down, loosen, retighten) are separated where the
    torque drops to about zero, as a controller's step restriction ends a step. A run that
    never reaches a tenth of the peak torque (the run-down's prevailing torque, noise) is
    not a step. Each step reaches back to the end of the one before it over samples whose
    torque is above −z T_max and whose angle does not fall, so the snug region belongs to it.

    Examples
    --------
    >>> split_steps(np.array([0.0, 5, 9, 10, 0, -3, 0, 4, 12, 20, 19]))
    [(1, 4), (7, 11)]
    >>> split_steps(np.array([0.0, 5, 9, 10, 0, -3, 0, 4, 12, 20, 19]), np.arange(11.0))
    [(0, 4), (6, 11)]
    """
    t = np.asarray(torque, dtype=float)
    peak = float(np.max(t)) if t.size else 0.0
    if not peak > 0.0:
        return []
    on = np.concatenate(([False], t > zero_fraction * peak, [False]))
    edges = np.flatnonzero(np.diff(on.astype(np.int8)))
    runs = zip(edges[::2].tolist(), edges[1::2].tolist(), strict=True)
    steps = [
        (a, b) for a, b in runs if b - a >= min_samples and float(np.max(t[a:b])) >= 0.1 * peak
    ]
    if angle is None:
        return steps
    theta = np.asarray(angle, dtype=float)
    floor = -zero_fraction * peak
    reached: list[tuple[int, int]] = []
    before = 0
    for a, b in steps:
        while a > before and t[a - 1] > floor and theta[a - 1] <= theta[a]:
            a -= 1
        reached.append((a, b))
        before = b
    return reached


def first_backward(angle: Any, tolerance: float) -> int:
    r"""Index of the first sample whose angle lies more than a tolerance behind the largest
    angle before it; −1 if the angle never runs backwards.

    .. math::
        \max_{j<i}\theta_j - \theta_i > \Delta\theta_{tol}

    Parameters
    ----------
    angle : numpy array
        θ of one step, [rad]
    tolerance : float
        Δθ_tol, the encoder's jitter allowed, [rad]

    Returns
    -------
    int
        The index, or −1

    Notes
    -----
    Our rule: within one step the nut turns one way; a loosening is a step of its own
    (:func:`split_steps`).

    Examples
    --------
    >>> first_backward(np.array([0.0, 0.1, 0.2, 0.19, 0.3, 0.1]), 0.05)
    5
    """
    a = np.asarray(angle, dtype=float)
    behind = np.maximum.accumulate(a) - a > tolerance
    hits = np.flatnonzero(behind)
    return int(hits[0]) if hits.size else -1


def local_gradient(angle: Any, torque: Any, window: int) -> np.ndarray:
    r"""Torque gradient dT/dθ at each sample: the least-squares slope over a centred window.

    .. math::
        g_i = \frac{n\sum\theta T - \sum\theta\sum T}{n\sum\theta^2 - (\sum\theta)^2}
        \quad\text{over } j = i - h \ldots i + h,\ n = 2h + 1

    Parameters
    ----------
    angle : numpy array
        θ, one trace (1-D) or one a row (2-D), [rad]
    torque : numpy array
        T, the same shape, [N*m]
    window : int
        n, samples in the window (odd; an even n is made one larger)

    Returns
    -------
    numpy array
        g, [N*m/rad], NaN within h samples of either end or where the window's angles
        do not spread

    Notes
    -----
    Controllers compute the gradient as the torque difference over an angle distance after
    a sliding-average filter ([AtlasCopco-PF], [Desoutter-CVIR]); the least-squares slope over the
    same span is that filter and difference in one, and takes unevenly spaced angles (a
    controller samples in time). Sums by cumulative sums: O(samples) for any window.

    Examples
    --------
    >>> g = local_gradient(np.arange(7.0), 2.0 * np.arange(7.0) ** 2, 3)
    >>> g.round(6).tolist()
    [nan, 4.0, 8.0, 12.0, 16.0, 20.0, nan]
    """
    x = np.asarray(angle, dtype=float)
    y = np.asarray(torque, dtype=float)
    h = max(int(window) // 2, 1)
    n = 2 * h + 1
    x0 = x - x[..., :1]  # sums of angles near the origin keep their digits
    pad = [(0, 0)] * (x.ndim - 1) + [(1, 0)]

    def window_sum(v: np.ndarray) -> np.ndarray:
        c = np.pad(np.cumsum(v, axis=-1), pad)
        return c[..., n:] - c[..., :-n]

    sx, sy = window_sum(x0), window_sum(y)
    sxx, sxy = window_sum(x0 * x0), window_sum(x0 * y)
    den = n * sxx - sx * sx
    spread = den > 1e-12 * np.maximum(sx * sx, 1e-300)
    with np.errstate(divide="ignore", invalid="ignore"):
        inner = np.where(spread, (n * sxy - sx * sy) / np.where(spread, den, 1.0), np.nan)
    out = np.full(x.shape, np.nan)
    out[..., h : x.shape[-1] - h] = inner
    return out


def elastic_window(
    torque: Any, low: float = ELASTIC_WINDOW[0], high: float = ELASTIC_WINDOW[1]
) -> Any:
    r"""Which samples lie in the elastic window: torque between two shares of the peak,
    before the peak.

    .. math::
        a\,T_{max} \le T_i \le b\,T_{max},\quad i \le \arg\max T

    Parameters
    ----------
    torque : numpy array
        T, one trace or one a row, [N*m]
    low, high : float
        a and b, [-]

    Returns
    -------
    numpy array of bool
        The window, the shape of ``torque``

    Notes
    -----
    Our rule (the window a torque-rate check in a controller is set on): above the snug
    region's gap closing and below the onset of yield for a trace tightened to or past
    yield (the onset lies above 85 % of its peak torque in steel bolts).

    Examples
    --------
    >>> elastic_window(np.array([0.0, 2, 4, 6, 8, 10, 9])).tolist()
    [False, False, True, True, False, False, False]
    """
    t = np.asarray(torque, dtype=float)
    peak_at = np.argmax(t, axis=-1)[..., None]
    peak = np.take_along_axis(t, peak_at, axis=-1)
    before = np.arange(t.shape[-1]) <= peak_at
    return (t >= low * peak) & (t <= high * peak) & before


def robust_line(
    angle: Any, torque: Any, mask: Any, cut: float = OUTLIER_CUT, passes: int = 2
) -> tuple[Any, Any]:
    r"""Slope and intercept of T = a + R θ over the masked samples, outliers refused.

    .. math::
        R = \frac{\sum w (\theta - \bar\theta)(T - \bar T)}{\sum w (\theta - \bar\theta)^2},
        \quad w_i = 0 \text{ where } |r_i| > c \cdot 1.4826\,\mathrm{MAD}(r)

    Parameters
    ----------
    angle, torque : numpy array
        θ [rad] and T [N*m], one trace or one a row
    mask : numpy array of bool
        The samples to fit (:func:`elastic_window`)
    cut : float
        c, robust standard deviations beyond which a sample is refused
    passes : int
        Refits after refusing

    Returns
    -------
    (R, a)
        Slope [N*m/rad] and intercept [N*m]; NaN where fewer than 3 samples remain

    Notes
    -----
    Least squares, then least squares again without the samples whose residual exceeds c
    times the median absolute deviation scaled to a normal σ (Hampel's rule): a quantisation
    step or a spike does not tilt the line.

    Examples
    --------
    >>> th = np.linspace(0.0, 1.0, 11); t = 3.0 + 2.0 * th; t[5] += 5.0
    >>> r, a = robust_line(th, t, np.ones(11, bool))
    >>> round(float(r), 6), round(float(a), 6)
    (2.0, 3.0)
    """
    x = np.asarray(angle, dtype=float)
    y = np.asarray(torque, dtype=float)
    w = np.asarray(mask, dtype=bool)
    slope = intercept = np.full(x.shape[:-1], np.nan)
    for k in range(passes + 1):
        n = w.sum(axis=-1)
        ok = n >= 3
        nn = np.maximum(n, 1)
        xm = np.where(w, x, 0.0).sum(axis=-1) / nn
        ym = np.where(w, y, 0.0).sum(axis=-1) / nn
        dx = np.where(w, x - xm[..., None], 0.0)
        dy = np.where(w, y - ym[..., None], 0.0)
        sxx = (dx * dx).sum(axis=-1)
        good = ok & (sxx > 0.0)
        slope = np.where(good, (dx * dy).sum(axis=-1) / np.where(good, sxx, 1.0), np.nan)
        intercept = ym - slope * xm
        if k == passes:
            break
        resid = y - (intercept[..., None] + slope[..., None] * x)
        limit = cut * 1.4826 * _masked_median(np.abs(resid), w, n)
        w = w & ~(np.abs(resid) > limit[..., None])
    if slope.ndim == 0:
        return float(slope), float(intercept)
    return slope, intercept


def _masked_median(values: np.ndarray, mask: np.ndarray, count: Any) -> Any:
    """Median of each row's masked values (inf where a row has none)."""
    ordered = np.sort(np.where(mask, values, np.inf), axis=-1)
    n = np.asarray(count)[..., None]
    low = np.take_along_axis(ordered, np.maximum((n - 1) // 2, 0), axis=-1)
    high = np.take_along_axis(ordered, np.maximum(n // 2, 0), axis=-1)
    with np.errstate(invalid="ignore"):
        return (0.5 * (low + high))[..., 0]


def first_at_or_above(values: Any, level: Any, start: Any = 0, stop: Any = None) -> Any:
    r"""Index of the first sample in [start, stop) whose value is at or above a level; −1
    where none is.

    .. math::
        i^* = \min\{\,i \in [i_0, i_1) : v_i \ge \ell\,\}

    Parameters
    ----------
    values : numpy array
        One trace or one a row (NaN never counts)
    level : float or numpy array
        ℓ, one per row
    start, stop : int or numpy array
        The range searched, one per row (stop None: to the end)

    Returns
    -------
    int or numpy array of int

    Examples
    --------
    >>> first_at_or_above(np.array([0.0, 1, 3, 2, 5]), 2.5, start=3)
    4
    """
    v = np.asarray(values, dtype=float)
    idx = np.arange(v.shape[-1])
    lvl = np.asarray(level, dtype=float)[..., None]
    lo = np.asarray(start)[..., None]
    hi = np.asarray(v.shape[-1] if stop is None else stop)[..., None]
    hit = (v >= lvl) & (idx >= lo) & (idx < hi)
    found = hit.any(axis=-1)
    first = np.where(found, np.argmax(hit, axis=-1), -1)
    return int(first) if first.ndim == 0 else first


def yield_index(
    gradient: Any, rate: Any, start: Any, stop: Any, fraction: float = YIELD_GRADIENT_FRACTION
) -> Any:
    r"""Index of the yield point: the first sample past the elastic window whose gradient has
    dropped below a fraction of the elastic rate; −1 where it never does.

    .. math::
        i_y = \min\{\,i \ge i_0 : g_i < f\,R\,\}

    Parameters
    ----------
    gradient : numpy array
        g from :func:`local_gradient`, [N*m/rad]
    rate : float or numpy array
        R, the elastic rate (the reference or maximum gradient), one per row, [N*m/rad]
    start, stop : int or numpy array
        i_0 (the end of the elastic window) and the end of the search (the peak torque)
    fraction : float
        f, [-]

    Returns
    -------
    int or numpy array of int

    Notes
    -----
    Yield-point control as controllers do it: the torque rate is compared with a reference
    rate taken in the elastic region, and the yield point is where it has fallen to X % of it,
    X = 50 by default [Desoutter-CVIR]; [AtlasCopco-PF] compares with the largest gradient
    met so far. OPC 40450 (its YIELD tag) calls the point where the linear growth of torque
    against angle drops an approximation any system reports. Here the reference is the
    robust elastic fit (:func:`robust_line`), not a single noisy gradient.

    Examples
    --------
    >>> yield_index(np.array([2.0, 2, 2, 1.9, 1.5, 0.9, 0.5]), 2.0, 1, 7)
    5
    """
    g = np.asarray(gradient, dtype=float)
    below = np.where(np.isnan(g), np.inf, -g)  # NaN never counts as a drop
    return first_at_or_above(below, -fraction * np.asarray(rate, dtype=float), start, stop)


@dataclass(frozen=True)
class Detection:
    """What :func:`detect` finds: floats for one trace, arrays (one a row) for many."""

    rate: Any  # R, [N*m/rad]
    intercept: Any  # a of T = a + R θ, [N*m]
    zero_angle: Any  # θ where the elastic line meets M_ü, [rad]
    snug: Any  # index of the snug point
    yield_at: Any  # index of the yield point, −1: none
    peak: Any  # index of the peak torque
    window_first: Any  # first and last index of the elastic window (−1: empty)
    window_last: Any
    gradient: Any  # g at each sample, [N*m/rad]


def detect(
    angle: Any,
    torque: Any,
    window: int,
    *,
    window_low: float = ELASTIC_WINDOW[0],
    window_high: float = ELASTIC_WINDOW[1],
    snug_fraction: float = SNUG_GRADIENT_FRACTION,
    yield_fraction: float = YIELD_GRADIENT_FRACTION,
    prevailing_torque: Any = 0.0,
) -> Detection:
    r"""The points of one step of a trace (1-D) or of many of one length (2-D, one a row).

    .. math::
        R = \text{robust slope over } aT_{max} \le T \le bT_{max},\quad
        \theta_0 = \frac{M_{\ddot u} - a_0}{R},\quad
        i_{snug} = \min\{i : g_i \ge s R\},\quad i_y = \min\{i > i_{b} : g_i \le f R\}

    Parameters
    ----------
    angle, torque : numpy array
        θ at the nut [rad] and T [N*m] of one step
    window : int
        Samples of the gradient window (:func:`local_gradient`)
    window_low, window_high : float
        a and b of the elastic window (:func:`elastic_window`)
    snug_fraction, yield_fraction : float
        s and f, shares of the elastic rate
    prevailing_torque : float
        M_ü, the torque with no preload, [N*m]

    Returns
    -------
    Detection

    Notes
    -----
    The steps in order: :func:`local_gradient`, :func:`elastic_window`, :func:`robust_line`,
    the snug point (first sample, up to the window, whose gradient reaches s R; the window's
    first sample if none does), the yield point (:func:`yield_index`, searched from the
    window's end to the last sample whose gradient window ends at the peak torque: the
    tool's release after the stop is no yield).

    Examples
    --------
    A bilinear trace, 2 N·m/rad from θ = 1 rad, flat from 3 rad:

    >>> th = np.linspace(0.0, 4.0, 401)
    >>> t = np.clip(2.0 * (th - 1.0), 0.0, 4.0) + 0.001 * th
    >>> d = detect(th, t, 5)
    >>> round(float(d.rate), 3), round(float(d.zero_angle), 3), round(float(th[d.yield_at]), 2)
    (2.001, 1.0, 3.01)
    """
    x = np.asarray(angle, dtype=float)
    y = np.asarray(torque, dtype=float)
    g = local_gradient(x, y, window)
    mask = elastic_window(y, window_low, window_high)
    rate, intercept = robust_line(x, y, mask)
    rate_a = np.asarray(rate, dtype=float)
    has = mask.any(axis=-1)
    first = np.where(has, np.argmax(mask, axis=-1), -1)
    last = np.where(has, x.shape[-1] - 1 - np.argmax(mask[..., ::-1], axis=-1), -1)
    peak = np.argmax(y, axis=-1)
    snug = first_at_or_above(g, snug_fraction * rate_a, 0, np.maximum(first, 0) + 1)
    snug = np.where(np.asarray(snug) < 0, np.maximum(first, 0), snug)
    # a gradient whose window reaches past the peak (the tool's release) is no yield
    found = yield_index(g, rate_a, last + 1, peak + 1 - max(int(window) // 2, 1), yield_fraction)
    with np.errstate(divide="ignore", invalid="ignore"):
        zero = (prevailing_torque - np.asarray(intercept)) / rate_a
    if x.ndim == 1:
        return Detection(
            float(rate_a),
            float(intercept),
            float(zero),
            int(snug),
            int(found),
            int(peak),
            int(first),
            int(last),
            g,
        )
    return Detection(rate_a, intercept, zero, snug, found, peak, first, last, g)


#: A robust z beyond which a trace's friction is an outlier (Iglewicz and Hoaglin's 3.5).
OUTLIER_Z = 3.5


@dataclass(frozen=True)
class BatchSummary:
    """What many traces of one joint say together."""

    friction_mean: float
    friction_sd: float
    preload_mean: float
    preload_sd: float
    outliers: tuple[int, ...]  # indices of traces whose friction is far from the others'
    capability_index: float  # Cp of the preload against F_M,min…F_M,zul
    critical_capability_index: float  # Cpk


def batch_summary(
    friction: Any, preload: Any, preload_window: tuple[float, float], z: float = OUTLIER_Z
) -> BatchSummary:
    r"""Distribution of the friction and preload many traces gave, their outliers, and the
    capability of the clamp force against the joint's window.

    .. math::
        z_i = \frac{0.6745\,(\mu_i - \tilde\mu)}{\mathrm{MAD}(\mu)},\qquad
        C_p = \frac{F_{M,zul} - F_{M,min}}{6 s_F},\qquad
        C_{pk} = \frac{\min(F_{M,zul} - \bar F, \bar F - F_{M,min})}{3 s_F}

    Parameters
    ----------
    friction : sequence of float
        μ_ges of each trace, [-]
    preload : sequence of float
        F of each trace, [N]
    preload_window : (float, float)
        F_M,min and F_M,zul of the joint, [N]
    z : float
        Robust z beyond which a friction is an outlier

    Returns
    -------
    BatchSummary

    Notes
    -----
    The modified z-score of Iglewicz and Hoaglin (median and median absolute deviation) marks
    a lot's odd friction without letting it move the mark; the capability indices are those
    of ``tool.capability`` ([ECSS-E-HB-32-23A] as VDI/VDE 2645 prints them,
    :mod:`engine.physics.capability`) with the joint's window as the tolerance of the clamp
    force. Needs at least two traces.

    Examples
    --------
    Five traces, the last with a lot's odd friction: s_F = √(82/4) kN = 4.528 kN, so
    C_p = 20/(6 · 4.528) = 0.74 and C_pk = min(7, 13)/(3 · 4.528) = 0.52

    >>> s = batch_summary([0.12, 0.121, 0.119, 0.12, 0.2], [40e3, 41e3, 39e3, 40e3, 30e3],
    ...                   (25e3, 45e3))
    >>> s.outliers, round(s.friction_mean, 4), round(s.capability_index, 2)
    ((4,), 0.136, 0.74)
    >>> round(s.critical_capability_index, 2)
    0.52
    """
    mu = np.asarray(friction, dtype=float)
    f = np.asarray(preload, dtype=float)
    centre = float(np.median(mu))
    mad = float(np.median(np.abs(mu - centre)))
    robust = 0.6745 * (mu - centre) / mad if mad > 0.0 else np.zeros_like(mu)
    low, high = preload_window
    f_mean, f_sd = sample_mean(f.tolist()), sample_standard_deviation(f.tolist())
    return BatchSummary(
        friction_mean=sample_mean(mu.tolist()),
        friction_sd=sample_standard_deviation(mu.tolist()),
        preload_mean=f_mean,
        preload_sd=f_sd,
        outliers=tuple(int(i) for i in np.flatnonzero(np.abs(robust) > z)),
        capability_index=float(capability_index(high, low, f_sd)),
        critical_capability_index=float(critical_capability_index(high, low, f_mean, f_sd)),
    )
