r"""Time simulation of one impact of the rare-impact wrench [002, eqs. 1-4].

Stage 1 (spin-up) is the only stage that needs an integrator. With the cone
constraint :math:`z_1 = x_1\tan\alpha` the roller force N drops out of
[002, eq. 1] and leaves one linear oscillator with time-varying coefficients,

.. math::
    m_e\ddot z_1 = \frac{n m_p}{2\tan\alpha}\,\omega(t)^2\left(x_0 + \frac{z_1}{\tan\alpha}\right)
        - c_1(\lambda_1 + z_1) - c_2(\lambda_2 + z_1),\qquad
    m_e = m_1 + m_2 + \frac{n m_p}{2\tan^2\alpha}

(:func:`engine.rare_impact.effective_stage1_mass` shows the elimination). The
flywheel speed is analytic, :math:`I_M\dot\omega = M`: :math:`\omega = Mt/I_M`
for a constant torque, :math:`\omega = \omega_{nl}(1 - e^{-t/\tau})`,
:math:`\tau = I_M\omega_{nl}/M`, for a torque falling linearly to zero at the
no-load speed. The half-coupling rests on its stop until the rollers' push
beats the preloads, at the lift-off speed :math:`\omega_0`
(:func:`engine.rare_impact.liftoff_speed`), whose time is analytic too; so
the integration starts there, at rest. Stage 1 ends at the **first** time
:math:`z_1` reaches :math:`h_1`. Stages 2-4 are linear with constant
coefficients and use their exact solutions (no solver).

How stage 1 is integrated, and why
----------------------------------
The half-coupling oscillates about its moving equilibrium with angular
frequency :math:`\Omega = \sqrt{K/m_e}`, :math:`K \le c_1 + c_2`, while the
flywheel spins up; near release the oscillation can graze :math:`h_1` and
fall back. An adaptive solver with default step control steps over such a
graze and reports a later crossing (issue 6 measured 0.85 % errors in time
that no tolerance fixed). So the step is *bounded by the physics*, not only
by the error estimate:

* classic fixed-step RK4 with :math:`h = 2\pi/(N\,\Omega_{max})`,
  :math:`N = 200` steps per shortest oscillation period
  (:math:`\Omega_{max}` bounds :math:`\sqrt{|K|/m_e}` over the whole run), so
  the phase error per period is about :math:`(2\pi/N)^4/120 \approx 8\cdot10^{-9}`;
* after every step the cubic Hermite interpolant through the two end states
  (positions and velocities, O(h⁴)) is checked both for an end above
  :math:`h_1` *and* for an interior maximum above it (a graze inside one
  step); the first root is bracketed and bisected on the cubic, then polished
  by Newton on a real RK4 sub-step from the step's start, so the crossing is
  as accurate as the integrator;
* the kernel is compiled with numba (``cache=True``: numba keeps the cache
  next to this file and falls back to a user cache directory when the package
  is read-only, or set ``NUMBA_CACHE_DIR``; with no writable place at all it
  compiles without caching). The module is imported only when the simulation
  rung runs; its first call in a process costs about 1.5 s (numba import and
  cache load) or 2.5 s (first compile of a fresh install). A fixed-step
  explicit RK4 loop over two state variables is the cheapest thing that
  meets the accuracy target; compiled, it costs a few tens of nanoseconds
  per step; without numba the same code runs as plain Python, about 100×
  slower but identical in result.

The work is bounded: the expected number of steps is known before starting
(span / h) and a run that would exceed ``ctx.max_steps`` stops at once with
BudgetExceeded and the advice to use the closed form, whose error is tiny
exactly when the oscillation is fast (stiff springs, light parts); the
integration runs in chunks between which ``ctx.deadline`` is checked.

:func:`stage1_reference` integrates the same equation with scipy's
``solve_ivp`` (terminal event, bounded ``max_step``); tests and the benchmark
use it to validate the fast integrator.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from .errors import BudgetExceeded, SolverFailed
from .rare_impact import (
    effective_stage1_mass,
    liftoff_speed,
    release_speed,
    spin_up_time,
    striker_oscillation,
)

__all__ = [
    "STEPS_PER_PERIOD",
    "SimulationResult",
    "Stage1Problem",
    "simulate",
    "stage1_fast",
    "stage1_problem",
    "stage1_reference",
]


class Budget(Protocol):
    """What :func:`simulate` needs of the run's context (``engine.spec.RunContext`` fits)."""

    @property
    def deadline(self) -> float | None: ...

    @property
    def max_steps(self) -> int: ...

    def wants(self, *names: str) -> bool: ...


#: RK4 steps per shortest oscillation period of the half-coupling.
STEPS_PER_PERIOD = 200
_CHUNK = 500_000
_SERIES_POINTS = 300


def _jit(func: Callable[..., Any]) -> Callable[..., Any]:
    """Compile with numba when it is installed; the plain function otherwise."""
    try:
        import numba
    except ImportError:  # pragma: no cover - numba is a declared dependency
        return func
    try:
        return numba.njit(cache=True, nogil=True)(func)
    except RuntimeError:  # pragma: no cover - no writable cache directory at all
        return numba.njit(cache=False, nogil=True)(func)


@dataclass(frozen=True)
class Stage1Problem:
    """Stage 1 reduced to numbers.

    :math:`\\ddot z = a\\,\\omega^2(x_0 + z/\\tan\\alpha) - f - c z`, all per unit mass.
    """

    mode: int  # 0: constant torque, 1: torque falling linearly to 0 at w_nl
    beta: float  # M / I_M [rad/s²]
    w_nl: float  # no-load speed [rad/s] (mode 1)
    tau: float  # I_M w_nl / M [s] (mode 1)
    push: float  # n m_p / (2 tan α m_e) [m/kg·...]: per ω² and per metre of radius
    x0: float
    inv_tan: float
    preload: float  # (c1 λ1 + c2 λ2) / m_e [m/s²]
    stiffness: float  # (c1 + c2) / m_e [1/s²]
    h1: float
    t_liftoff: float
    w_release_qs: float  # quasi-static release speed (closed form)
    t_release_qs: float
    t_end: float
    step: float
    snap: bool  # the half-coupling snaps through at lift-off (negative stiffness)

    def omega(self, t: Any) -> Any:
        """Flywheel speed at time ``t`` [rad/s] (analytic)."""
        if self.mode == 0:
            return self.beta * t
        return self.w_nl * -np.expm1(-t / self.tau)

    def accel(self, t: float, z: float) -> float:
        w = self.omega(t)
        return float(
            self.push * w * w * (self.x0 + z * self.inv_tan) - self.preload - self.stiffness * z
        )


def _time_at_speed(mode: int, beta: float, w_nl: float, tau: float, w: float) -> float:
    if mode == 0:
        return w / beta
    return -tau * math.log1p(-w / w_nl)


def stage1_problem(x: Mapping[str, Any]) -> Stage1Problem:
    """Set up stage 1 for the inputs ``x`` (SI); raises InfeasibleDesign for a weak motor."""
    c1, c2 = x["power_spring_rate"], x["auxiliary_spring_rate"]
    lam1, lam2 = x["power_spring_preload"], x["auxiliary_spring_preload"]
    h1, n, mp = x["release_travel"], x["roller_count"], x["roller_mass"]
    x0, alpha = x["roller_radius"], x["cone_angle"]
    inertia, torque = x["flywheel_inertia"], x["motor_torque"]
    w_nl = x.get("motor_no_load_speed")
    tan_a = math.tan(alpha)
    m_e = float(
        effective_stage1_mass(x["half_coupling_mass"], x["stepped_shaft_mass"], mp, n, alpha)
    )
    push = n * mp / (2.0 * tan_a * m_e)
    stiffness = (c1 + c2) / m_e
    w_0 = float(liftoff_speed(c1, lam1, c2, lam2, mp, n, x0, alpha))
    w_m = float(release_speed(c1, lam1, c2, lam2, h1, mp, n, x0, alpha))
    # Negative stiffness at lift-off: the half-coupling snaps to h1 (released_at_liftoff).
    snap = w_0 > w_m
    w_qs = max(w_0, w_m)
    mode = 0 if w_nl is None else 1
    beta = torque / inertia
    tau = 0.0 if w_nl is None else inertia * w_nl / torque
    spin_up_time(inertia, torque, w_qs, w_nl)  # raises InfeasibleDesign for a weak motor
    w_nl_f = 0.0 if w_nl is None else float(w_nl)
    t_l = _time_at_speed(mode, beta, w_nl_f, tau, w_0)
    t_qs = _time_at_speed(mode, beta, w_nl_f, tau, w_qs)
    om_qs = math.sqrt(max(stiffness - push * w_qs * w_qs * 1.0 / tan_a, 0.0))
    slow_period = 2.0 * math.pi / max(om_qs, 1e-300)
    span = max(t_qs - t_l, 0.0)
    t_end = t_qs + span + min(50.0 * slow_period, 10.0 * span + 1.0)
    if mode == 1:
        t_end = t_qs + span + min(50.0 * slow_period, 10.0 * tau + 10.0 * span)
    w_end = float(w_nl_f if mode == 1 else beta * t_end)
    om_max = math.sqrt(max(stiffness, push * w_end * w_end / tan_a))
    step = 2.0 * math.pi / (STEPS_PER_PERIOD * om_max)
    return Stage1Problem(
        mode=mode,
        beta=beta,
        w_nl=w_nl_f,
        tau=tau,
        push=push,
        x0=x0,
        inv_tan=1.0 / tan_a,
        preload=(c1 * lam1 + c2 * lam2) / m_e,
        stiffness=stiffness,
        h1=h1,
        t_liftoff=t_l,
        w_release_qs=w_qs,
        t_release_qs=t_qs,
        t_end=t_end,
        step=step,
        snap=snap,
    )


# ---------------------------------------------------------------------------
# The compiled kernel
# ---------------------------------------------------------------------------


def _acc(t, z, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness):  # type: ignore[no-untyped-def]
    w = beta * t if mode == 0 else w_nl * (1.0 - math.exp(-t / tau))
    return push * w * w * (x0 + z * inv_tan) - preload - stiffness * z


_acc_c = _jit(_acc)


def _rk4(t, z, v, h, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness):  # type: ignore[no-untyped-def]
    a1 = _acc_c(t, z, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness)
    z2 = z + 0.5 * h * v
    v2 = v + 0.5 * h * a1
    a2 = _acc_c(t + 0.5 * h, z2, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness)
    z3 = z + 0.5 * h * v2
    v3 = v + 0.5 * h * a2
    a3 = _acc_c(t + 0.5 * h, z3, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness)
    z4 = z + h * v3
    v4 = v + h * a3
    a4 = _acc_c(t + h, z4, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness)
    zn = z + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4)
    vn = v + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    return zn, vn


_rk4_c = _jit(_rk4)


def _hermite(s, z0, v0, z1, v1, h):  # type: ignore[no-untyped-def]
    s2 = s * s
    s3 = s2 * s
    return (
        (2.0 * s3 - 3.0 * s2 + 1.0) * z0
        + (s3 - 2.0 * s2 + s) * h * v0
        + (-2.0 * s3 + 3.0 * s2) * z1
        + (s3 - s2) * h * v1
    )


_hermite_c = _jit(_hermite)


def _first_root(z0, v0, z1, v1, h, level):  # type: ignore[no-untyped-def]
    """Fraction s in [0, 1] of the step where the Hermite cubic first reaches ``level``.

    -1 when it stays below ``level`` over the whole step.
    """
    hi = -1.0
    if z1 >= level:
        hi = 1.0
    # An interior maximum (velocity + to −) may graze the level inside the step.
    # p'(s)/h = a s² + b s + v0 with the coefficients of the cubic's derivative.
    a = 3.0 * (2.0 * (z0 - z1) / h + v0 + v1)
    b = 2.0 * (3.0 * (z1 - z0) / h - 2.0 * v0 - v1)
    c = v0
    if v0 > 0.0 and v1 < 0.0:
        if a == 0.0:
            sp = -c / b
        else:
            disc = b * b - 4.0 * a * c
            if disc < 0.0:
                disc = 0.0
            q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
            r1 = q / a
            r2 = c / q if q != 0.0 else -1.0
            sp = 2.0
            if 0.0 <= r1 <= 1.0:
                sp = r1
            if 0.0 <= r2 <= 1.0 and r2 < sp:
                sp = r2
        if 0.0 <= sp <= 1.0 and _hermite_c(sp, z0, v0, z1, v1, h) >= level:
            hi = sp
    if hi < 0.0:
        return -1.0
    lo = 0.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if _hermite_c(mid, z0, v0, z1, v1, h) >= level:
            hi = mid
        else:
            lo = mid
    return hi


_first_root_c = _jit(_first_root)


def _stage1_kernel(  # type: ignore[no-untyped-def]
    t, z, v, h, n_max, t_end, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness,
    level, stride, out_t, out_z, n_rec,
):  # fmt: skip
    """Integrate from (t, z, v) for at most n_max steps.

    Returns (status, t, z, v, steps, n_rec): status 1 = crossed (t, z, v at the
    crossing), 2 = reached t_end without crossing, 0 = used n_max steps.
    """
    cap = out_t.shape[0]
    for i in range(n_max):
        hh = h
        if t + hh > t_end:
            hh = t_end - t
            if hh <= 0.0:
                return 2, t, z, v, i, n_rec
        zn, vn = _rk4_c(t, z, v, hh, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness)
        s = _first_root_c(z, v, zn, vn, hh, level)
        if s >= 0.0:
            # Polish on a real RK4 sub-step (Newton on z(s) = level).
            for _ in range(3):
                zs, vs = _rk4_c(
                    t, z, v, s * hh, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness
                )
                if vs <= 0.0:
                    break
                ds = (zs - level) / (vs * hh)
                if abs(ds) > 0.05 or s - ds < 0.0 or s - ds > 1.0:
                    break
                s -= ds
                if abs(ds) < 1e-15:
                    break
            zs, vs = _rk4_c(
                t, z, v, s * hh, mode, beta, w_nl, tau, push, x0, inv_tan, preload, stiffness
            )
            return 1, t + s * hh, zs, vs, i + 1, n_rec
        t = t + hh
        z = zn
        v = vn
        if z < 0.0:  # the stop under the half-coupling (inelastic)
            z = 0.0
            if v < 0.0:
                v = 0.0
        if stride > 0 and i % stride == 0 and n_rec < cap:
            out_t[n_rec] = t
            out_z[n_rec] = z
            n_rec += 1
    return 0, t, z, v, n_max, n_rec


_stage1_kernel_c = _jit(_stage1_kernel)


@dataclass
class Stage1Result:
    """The first crossing of h1 and, if asked, a decimated trajectory."""

    t_release: float
    w_release: float
    steps: int
    t: np.ndarray
    z: np.ndarray


def stage1_fast(
    problem: Stage1Problem,
    *,
    record: bool = False,
    deadline: float | None = None,
    max_steps: int = 1_000_000,
    steps_per_period: int | None = None,
) -> Stage1Result:
    """Integrate stage 1 with the compiled fixed-step RK4 (see the module notes).

    Returns the first crossing of :math:`z_1 = h_1` [002, eq. 1]: release time
    (the spin-up time, from motor start) and flywheel speed there.

    Examples
    --------
    The reference design: the quasi-static closed form says 236.0163 rad/s
    at 0.944065 s; the half-coupling's lag and oscillation release it at

    >>> from engine.models.rare_impact import REFERENCE_DESIGN
    >>> r = stage1_fast(stage1_problem(REFERENCE_DESIGN))
    >>> round(r.w_release, 4), round(r.t_release, 6)
    (235.9862, 0.943945)
    """
    p = problem
    h = p.step if steps_per_period is None else p.step * STEPS_PER_PERIOD / steps_per_period
    expected = (p.t_release_qs - p.t_liftoff) / h
    if expected > max_steps:
        raise BudgetExceeded(
            f"the simulation would take about {expected:.2g} steps (budget {max_steps:g}): the "
            f"half-coupling would oscillate about {expected / STEPS_PER_PERIOD:.2g} times "
            "before release (stiff springs, light parts or a slow spin-up), which is exactly "
            "where the quasi-static closed form is accurate; use fidelity 'closed_form' or "
            "'auto'",
            field="fidelity",
            expected_steps=expected,
        )
    stride = max(1, int(expected / _SERIES_POINTS)) if record else 0
    cap = _SERIES_POINTS * 3 + 8 if record else 1
    out_t = np.empty(cap)
    out_z = np.empty(cap)
    out_t[0], out_z[0] = p.t_liftoff, 0.0
    n_rec = 1 if record else 0
    t, z, v = p.t_liftoff, 0.0, 0.0
    steps = 0
    while True:
        if deadline is not None and time.perf_counter() > deadline:
            raise BudgetExceeded(
                f"the stage-1 simulation stopped at its time budget after {steps} steps "
                f"(t = {t:.4g} s of about {p.t_release_qs:.4g} s)",
                field="fidelity",
            )
        chunk = min(_CHUNK, max_steps - steps)
        if chunk <= 0:
            raise BudgetExceeded(
                f"the stage-1 simulation used its budget of {max_steps} steps before the "
                "half-coupling reached h1; use fidelity 'closed_form'",
                field="fidelity",
            )
        status, t, z, v, used, n_rec = _stage1_kernel_c(
            t, z, v, h, chunk, p.t_end, p.mode, p.beta, p.w_nl, p.tau, p.push, p.x0,
            p.inv_tan, p.preload, p.stiffness, p.h1, stride, out_t, out_z, n_rec,
        )  # fmt: skip
        steps += int(used)
        if status == 1:
            break
        if status == 2:
            raise SolverFailed(
                f"the half-coupling did not reach h1 by t = {p.t_end:.4g} s although the "
                f"quasi-static release is at {p.t_release_qs:.4g} s; report this design",
                field="fidelity",
            )
    if not (math.isfinite(t) and math.isfinite(z)):
        raise SolverFailed("the stage-1 integration diverged", field="fidelity")
    return Stage1Result(
        t_release=float(t),
        w_release=float(p.omega(t)),
        steps=steps,
        t=out_t[:n_rec].copy(),
        z=out_z[:n_rec].copy(),
    )


def stage1_reference(
    problem: Stage1Problem,
    *,
    method: str = "DOP853",
    rtol: float = 1e-12,
    atol: float | None = None,
    max_step_fraction: float | None = 0.05,
) -> tuple[float, float, int]:
    """Stage 1 by scipy's ``solve_ivp`` with a terminal event at z1 = h1.

    ``max_step_fraction`` bounds the step to that fraction of the shortest
    oscillation period (None: scipy's default step control, which can skip a
    grazing first crossing). Returns (release time, release speed, RHS evaluations).
    """
    from scipy.integrate import solve_ivp

    p = problem
    period = p.step * STEPS_PER_PERIOD

    def rhs(t: float, y: np.ndarray) -> list[float]:
        return [y[1], p.accel(t, y[0])]

    def crossed(t: float, y: np.ndarray) -> float:
        return float(y[0] - p.h1)

    crossed.terminal = True  # type: ignore[attr-defined]
    crossed.direction = 1.0  # type: ignore[attr-defined]
    kwargs: dict[str, Any] = {}
    if max_step_fraction is not None:
        kwargs["max_step"] = max_step_fraction * period
    sol = solve_ivp(
        rhs,
        (p.t_liftoff, p.t_end),
        [0.0, 0.0],
        method=method,
        rtol=rtol,
        atol=atol if atol is not None else rtol * p.h1,
        events=crossed,
        **kwargs,
    )
    if not sol.success or len(sol.t_events[0]) == 0:
        raise SolverFailed(f"solve_ivp did not reach h1: {sol.message}")
    t_rel = float(sol.t_events[0][0])
    return t_rel, float(p.omega(t_rel)), int(sol.nfev)


# ---------------------------------------------------------------------------
# Stages 2-4 (exact) and the whole impact
# ---------------------------------------------------------------------------


@dataclass
class SimulationResult:
    """What the simulation rung adds to the closed forms."""

    release_speed: float
    spin_up_time: float
    liftoff_time: float
    stage_durations: tuple[float, float, float, float]
    steps: int
    series: dict[str, list[float]] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def _cosine_motion(t: np.ndarray, amplitude: float, k: float) -> np.ndarray:
    """:math:`D(1 - \\cos kt)` as :math:`2D\\sin^2(kt/2)`."""
    s = np.sin(0.5 * k * t)
    return 2.0 * amplitude * s * s


def _travel_time(distance: float, amplitude: float, k: float) -> float:
    """First time :math:`D(1-\\cos kt)` reaches ``distance``; inf if never."""
    if amplitude <= 0.0:
        return math.inf
    q = distance / (2.0 * amplitude)
    if q > 1.0 + 1e-12:
        return math.inf
    return 2.0 / k * math.asin(math.sqrt(min(max(q, 0.0), 1.0)))


def simulate(x: Mapping[str, Any], ctx: Budget) -> SimulationResult:
    """All four stages: stage 1 integrated, stages 2-4 exact; series if asked."""
    problem = stage1_problem(x)
    want_series = ctx.wants("time", "flywheel_speed", "z1", "z2", "z3", "z4")
    s1 = stage1_fast(problem, record=want_series, deadline=ctx.deadline, max_steps=ctx.max_steps)
    notes = [
        f"simulation: stage 1 by compiled RK4, {STEPS_PER_PERIOD} steps per oscillation "
        f"period ({s1.steps} steps), first crossing of h1 located on the Hermite "
        "interpolant and polished by Newton; stages 2-4 exact"
    ]
    if problem.t_liftoff > 0.0:
        rpm = problem.omega(problem.t_liftoff) * 30.0 / math.pi
        notes.append(
            f"the half-coupling rests on its stop until t = {problem.t_liftoff:.4g} s, when the "
            f"flywheel reaches the lift-off speed {rpm:.0f} rpm"
        )
    warnings: list[str] = []
    if problem.snap:
        notes.append(
            "the preloads exceed (c1 + c2)·x0·tan α: once the rollers lift off the half-"
            "coupling's stiffness is negative and it snaps to h1 at the lift-off speed, "
            "earlier than the paper's release-speed formula says"
        )
    g = x["gravity"]
    m2_total = x["half_coupling_mass"] + x["roller_count"] * x["roller_mass"] + x["striker_mass"]
    c1, c2, c3 = x["power_spring_rate"], x["auxiliary_spring_rate"], x["return_spring_rate"]
    lam2, lam3 = x["auxiliary_spring_preload"], x["return_spring_preload"]
    h1, h2, h3 = x["release_travel"], x["engagement_height"], x["jaw_height"]
    b, k = striker_oscillation(c1, x["power_spring_preload"], c3, lam3, h1, m2_total, g)
    b, k = float(b), float(k)
    d2 = b / (k * k)
    t2 = _travel_time(h2, d2, k)
    k3 = math.sqrt(c3 / x["striker_mass"])
    d3 = lam3 + h2 - x["striker_mass"] * g / c3
    t3 = _travel_time(h3, d3, k3) if math.isfinite(t2) else math.inf
    k4 = math.sqrt(c2 / x["stepped_shaft_mass"])
    d4 = lam2 + h1 + (x["stepped_shaft_mass"] * g - c3 * lam3 * x["roller_friction"]) / c2
    t4 = _travel_time(h1, d4, k4) if math.isfinite(t3) else math.inf
    if not math.isfinite(t2):
        warnings.append(
            "the striker never reaches the engagement height: no blow, an edge blow at best; "
            "stages 3 and 4 are not reached"
        )
    elif not math.isfinite(t3):
        warnings.append("the return spring does not bring the striker back the jaw height")
    elif not math.isfinite(t4):
        warnings.append("the auxiliary spring does not push the stepped shaft back: no re-lock")
    series: dict[str, list[float]] = {}
    if want_series:
        series = _series(problem, s1, (t2, t3, t4), (d2, k), (d3, k3), (d4, k4), h2, h3, h1)
    return SimulationResult(
        release_speed=s1.w_release,
        spin_up_time=s1.t_release,
        liftoff_time=problem.t_liftoff,
        stage_durations=(s1.t_release, t2, t3, t4),
        steps=s1.steps,
        series=series,
        notes=notes,
        warnings=warnings,
    )


def _series(
    p: Stage1Problem,
    s1: Stage1Result,
    durations: tuple[float, float, float],
    st2: tuple[float, float],
    st3: tuple[float, float],
    st4: tuple[float, float],
    h2: float,
    h3: float,
    h1: float,
) -> dict[str, list[float]]:
    """A few hundred points over the four stages, each coordinate held after its stage."""
    n_stage = 60
    t_dwell = np.linspace(0.0, p.t_liftoff, 20, endpoint=False)
    t1 = np.concatenate([t_dwell, s1.t, [s1.t_release]])
    z1 = np.concatenate([np.zeros_like(t_dwell), s1.z, [h1]])
    parts_t = [t1]
    w = [np.asarray(p.omega(t1), dtype=float)]
    zs = {
        "z1": [z1],
        "z2": [np.zeros_like(t1)],
        "z3": [np.zeros_like(t1)],
        "z4": [np.zeros_like(t1)],
    }
    start = s1.t_release
    held = {"z1": h1, "z2": 0.0, "z3": 0.0, "z4": 0.0}
    specs = [("z2", st2, h2, s1.w_release), ("z3", st3, h3, 0.0), ("z4", st4, h1, 0.0)]
    for (name, (amp, k), target, speed), dur in zip(specs, durations, strict=True):
        span = dur if math.isfinite(dur) else 2.0 * math.pi / k
        tau = np.linspace(0.0, span, n_stage + 1)[1:]
        motion = _cosine_motion(tau, amp, k) if amp > 0 else np.zeros_like(tau)
        if math.isfinite(dur):
            motion[-1] = target
        parts_t.append(start + tau)
        w.append(np.full_like(tau, speed))
        for other in zs:
            zs[other].append(motion if other == name else np.full_like(tau, held[other]))
        held[name] = float(motion[-1])
        start += span
        if not math.isfinite(dur):
            break
    out = {"time": np.concatenate(parts_t), "flywheel_speed": np.concatenate(w)}
    for name, pieces in zs.items():
        out[name] = np.concatenate(pieces)
    return {n: a.tolist() for n, a in out.items()}
