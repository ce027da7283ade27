r"""The compiled-ODE kit the fixed-step kernels share: compilation, event location, budgets.

The striker's whole cycle (:mod:`engine.procedures.striker_cycle`) and the blow
(:mod:`engine.physics.blow`) each integrate their own right-hand sides with a fixed-step
RK4 compiled by numba; what is not model-specific is here, once:

* :func:`jit`: compile with numba (cached on disk, GIL released), the plain
  function where numba is missing;
* :func:`hermite` and :func:`first_rise`: the cubic Hermite interpolant of one
  step and the first point where it reaches zero from below, end crossings and
  grazes inside the step alike (the event location of a position level);
  :func:`newton_fraction`, one guarded Newton update of that point on a real
  sub-step (the kernels take their sub-steps themselves: numba's disk cache refuses
  a compiled function handed another as a value);
* :func:`step_budget` and :class:`StepCost`: a simulation's budget in time, as
  steps at the kernel's measured cost per step;
* :func:`as_numbers`, :func:`where`, :func:`sqrt`, ...: what lets one procedure take
  one design (Python floats, ``math``) or many (arrays, numpy) through the same lines.

The right-hand sides, the RK4 steps over each model's state and the kernels'
event loops stay with their models.

numba's disk cache keys a compiled function on its own source file: a kernel
that calls :func:`hermite_c`, :func:`first_rise_c` or :func:`newton_fraction_c` is
not recompiled when only this file changes (numba does not track callees), so clear
``__pycache__`` after editing a compiled function here.
"""

from __future__ import annotations

import contextlib
import math
import threading
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np

__all__ = [
    "STEP_COST_CAP",
    "TIME_SHARE",
    "StepCost",
    "all_true",
    "any_true",
    "as_numbers",
    "asin",
    "atan2",
    "divide",
    "first_rise",
    "first_rise_c",
    "hermite",
    "hermite_c",
    "hypot",
    "is_array",
    "isfinite",
    "jit",
    "log1p",
    "negate",
    "newton_fraction",
    "newton_fraction_c",
    "pymax",
    "pymin",
    "quiet",
    "sqrt",
    "step_budget",
    "tan",
    "where",
]

#: Share of the time left that a simulation may plan to use up front (the rest covers a
#: slower machine than measured and the answer's own bookkeeping).
TIME_SHARE = 0.5
#: A chunk's measured cost per step is capped here (10x the prior): a pause of the whole
#: process (a collection, a busy machine) must not shrink every later budget, [s].
STEP_COST_CAP = 1e-5


def jit(
    func: Callable[..., Any],
    *,
    error_model: Literal["python", "numpy"] = "python",
    inline: bool = False,
) -> Callable[..., Any]:
    """Compile ``func`` with numba when it is installed; ``func`` itself otherwise.

    Parameters
    ----------
    func : callable
        A function numba's nopython mode can compile
    error_model : str
        numba's error model: ``"python"`` raises on a division by zero,
        ``"numpy"`` gives inf/NaN as numpy does
    inline : bool
        Inline ``func`` into every compiled caller (numba's ``inline="always"``): for the
        small functions a kernel calls every step, whose calls LLVM does not always inline

    Notes
    -----
    Compiled with ``cache=True`` (loaded from ``__pycache__`` in later processes) and
    ``nogil=True``; without a writable cache directory, compiled in memory.

    >>> jit(lambda a, b: a * b + 1.0)(2.0, 3.0)
    7.0
    """
    try:
        import numba
    except ImportError:  # pragma: no cover - numba is a declared dependency
        return func
    how: Literal["always", "never"] = "always" if inline else "never"
    try:
        return numba.njit(cache=True, nogil=True, error_model=error_model, inline=how)(func)
    except RuntimeError:  # pragma: no cover - no writable cache directory at all
        return numba.njit(cache=False, nogil=True, error_model=error_model, inline=how)(func)


def hermite(s, z0, v0, z1, v1, h):  # type: ignore[no-untyped-def]
    r"""Cubic Hermite interpolant of one step at the fraction ``s`` of the step.

    .. math::
        z(s) = (2s^3 - 3s^2 + 1)z_0 + (s^3 - 2s^2 + s)h v_0 + (-2s^3 + 3s^2)z_1 + (s^3 - s^2)h v_1

    Parameters
    ----------
    s : float
        Fraction of the step, 0 at its start and 1 at its end, [-]
    z0, z1 : float
        Value at the start and the end of the step, [any unit]
    v0, v1 : float
        Rate of change at the start and the end, [unit/s]
    h : float
        Step length, [s]

    Notes
    -----
    The cubic matching value and slope at both ends; with the ends of an RK4 step
    its error is of the order :math:`h^4`. It is exact for a cubic:
    :math:`z = t^3 - t` over :math:`t \in [0, 2]` (h = 2) has z(0) = 0, z'(0) = -1,
    z(2) = 6, z'(2) = 11, and at t = 1.5 (s = 0.75) :math:`1.5^3 - 1.5 = 1.875`:

    >>> hermite(0.75, 0.0, -1.0, 6.0, 11.0, 2.0)
    1.875
    """
    s2 = s * s
    s3 = s2 * s
    return (
        (2.0 * s3 - 3.0 * s2 + 1.0) * z0
        + (s3 - 2.0 * s2 + s) * h * v0
        + (-2.0 * s3 + 3.0 * s2) * z1
        + (s3 - s2) * h * v1
    )


hermite_c = jit(hermite, error_model="numpy")


def first_rise(z0, v0, z1, v1, h):  # type: ignore[no-untyped-def]
    r"""First fraction s of a step where its Hermite cubic reaches 0 from below; -1 if none.

    Parameters
    ----------
    z0, z1 : float
        Value at the start (below 0, or 0 and falling) and the end of the step, [any unit]
    v0, v1 : float
        Rate of change at the start and the end, [unit/s]
    h : float
        Step length, [s]

    Notes
    -----
    A crossing at the end (:math:`z_1 \ge 0`) is bracketed by [0, 1]; a graze inside the
    step (rising at the start, falling at the end, :math:`z_1 < 0`) by the cubic's
    interior maximum :math:`s^*`, a root of
    :math:`z'(s)/h = a s^2 + b s + c`, :math:`a = 3[2(z_0 - z_1)/h + v_0 + v_1]`,
    :math:`b = 2[3(z_1 - z_0)/h - 2v_0 - v_1]`, :math:`c = v_0`, taken without
    cancellation. The crossing is then bisected 60 times on the cubic (to the last bit).

    :math:`z = t^2 - 1` over [0, 2] (a parabola is a cubic, exact): root at t = 1, s = 0.5.
    :math:`z = -(t - 1)^2 + 0.25` over [0, 2] never at 0 at the ends (-0.75 both), rises
    to 0.25 at t = 1 inside: the first root is t = 0.5, s = 0.25. Lowered to -0.01 at the
    top it never reaches 0:

    >>> first_rise(-1.0, 0.0, 3.0, 4.0, 2.0)
    0.5
    >>> round(first_rise(-0.75, 2.0, -0.75, -2.0, 2.0), 12)
    0.25
    >>> first_rise(-1.01, 2.0, -1.01, -2.0, 2.0)
    -1.0
    """
    hi = -1.0
    if z1 >= 0.0:
        hi = 1.0
    a = 3.0 * (2.0 * (z0 - z1) / h + v0 + v1)
    b = 2.0 * (3.0 * (z1 - z0) / h - 2.0 * v0 - v1)
    c = v0
    if v0 > 0.0 and v1 < 0.0:  # an interior maximum may graze 0 inside the step
        if a == 0.0:
            sp = -c / b if b != 0.0 else 2.0
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
        if 0.0 <= sp <= 1.0 and hermite_c(sp, z0, v0, z1, v1, h) >= 0.0:
            hi = sp
    if hi < 0.0:
        return -1.0
    lo = 0.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if hermite_c(mid, z0, v0, z1, v1, h) >= 0.0:
            hi = mid
        else:
            lo = mid
    return hi


first_rise_c = jit(first_rise, error_model="numpy")


def newton_fraction(s, z, rate, h):  # type: ignore[no-untyped-def]
    r"""One Newton update of a level event's fraction s of a step: (s, go on).

    .. math::
        s \leftarrow s - \frac{z(s)}{\dot z(s)\,h}

    Parameters
    ----------
    s : float
        The fraction so far (first located on the step's cubic, :func:`first_rise`), [-]
    z : float
        The level's residual after a real sub-step of s·h (the kernel's own RK4 from the
        step's start), [unit]
    rate : float
        Its rate there, [unit/s]
    h : float
        Step length, [s]

    Notes
    -----
    The kernels of :mod:`engine.procedures.striker_cycle` refine a position event with up
    to three of these (the cubic's root is within its O(h⁴) error of the sub-step's, so
    one or two reach the last bit), stopping where this says so. An update is refused (s
    kept, stop) where the rate is 0 or where it would move s by more than 0.05 of the step
    or out of [0, 1] (the cubic's root stands); after an update below 1e-15, stop.
    z(s) = s − 0.5 with rate 1 per step (h = 1): from 0.47 the update lands on 0.5; from
    0.4 it (0.1) is refused; at the root the update is 0 and the refinement stops:

    >>> newton_fraction(0.47, -0.03, 1.0, 1.0)
    (0.5, True)
    >>> newton_fraction(0.4, -0.1, 1.0, 1.0), newton_fraction(0.4, -0.1, 0.0, 1.0)
    ((0.4, False), (0.4, False))
    >>> newton_fraction(0.5, 0.0, 1.0, 1.0)
    (0.5, False)
    """
    if rate == 0.0:
        return s, False
    ds = z / (rate * h)
    if abs(ds) > 0.05 or s - ds < 0.0 or s - ds > 1.0:
        return s, False
    return s - ds, abs(ds) >= 1e-15


newton_fraction_c = jit(newton_fraction, error_model="numpy")


def step_budget(
    deadline: float | None, max_steps: int, step_cost: float, share: float = TIME_SHARE
) -> int:
    r"""Steps a kernel may take: what the time left affords, or ``max_steps`` without a deadline.

    .. math::
        n = \min\left(\frac{\text{share}\cdot\max(t_\text{deadline} - t_\text{now}, 0)}
                           {t_\text{step}},\ 10^{15}\right)

    Parameters
    ----------
    deadline : float or None
        ``time.perf_counter()`` value the answer is due by, [s]
    max_steps : int
        The caller's step budget, used only without a deadline, [-]
    step_cost : float
        The kernel's measured cost per step (:class:`StepCost`), [s]
    share : float
        Share of the time left the simulation may plan to use, [-]

    Notes
    -----
    A budget in time, not in steps: a stiff design needing millions of steps
    runs when the kernel finishes them well inside the time left, and one that would
    not is declined up front (the runner's fallback can take over at once).

    >>> step_budget(None, 1000, 1e-6)
    1000
    >>> step_budget(time.perf_counter() - 1.0, 1000, 1e-6)  # past the deadline: no steps
    0
    >>> 990_000 < step_budget(time.perf_counter() + 200.0, 0, 1e-4) <= 1_000_000  # 0.5·200/100 µs
    True
    """
    if deadline is None:
        return max_steps
    left = max(deadline - time.perf_counter(), 0.0)
    return int(min(left * share / step_cost, 1e15))


#: The fewest steps of a kernel call whose time measures the cost of a step
#: (:meth:`StepCost.measured`; shorter calls are measured in sums of this many steps).
MEASURED_STEPS = 10_000


@dataclass
class StepCost:
    """One kernel's cost per step in this process: a running mean of its own calls.

    ``seconds`` starts at a slow machine's figure (1 µs; the striker's cycle takes 80-107 ns
    a step on the 2-core CI box)
    and :meth:`measured` folds in every call of 10,000 steps or more, and shorter calls
    in sums of that many steps (a short design's whole cycle is one call: a process that
    ran only those kept the slow prior, and declined designs as too long for a chunk's
    time that take a fifth of it), except the kernel's first call in the process (it
    compiles, or loads from numba's cache: seconds that are not the cost of a step), each
    capped at :data:`STEP_COST_CAP`.

    >>> cost = StepCost()
    >>> cost.measured(20_000, 3.0)  # the first call compiles: not counted
    >>> cost.seconds
    1e-06
    >>> cost.measured(20_000, 3.0)  # a 3 s pause: capped at 1e-5 s a step
    >>> round(cost.seconds, 15)  # 0.7·1e-6 + 0.3·1e-5
    3.7e-06
    >>> for _ in range(5):  # short calls: folded in once they make 10,000 steps
    ...     cost.measured(2_000, 0.0004)
    >>> round(cost.seconds, 15)  # 0.7·3.7e-6 + 0.3·(0.002 s / 10,000)
    2.65e-06
    >>> cost.budget(None, 77)
    77
    """

    seconds: float = 1e-6
    warm: bool = False
    #: Steps and seconds of the short calls not folded in yet.
    short_steps: int = 0
    short_s: float = 0.0
    #: The engine's threads measure calls side by side: a sum is one call's steps and
    #: seconds together.
    lock: threading.Lock = field(default_factory=threading.Lock, repr=False, compare=False)

    def measured(self, used: int, seconds: float) -> None:
        """Fold one call of ``used`` steps that took ``seconds`` into :attr:`seconds`."""
        if not self.warm:
            self.warm = True
            return
        if used <= 0 or not seconds > 0.0:
            return
        with self.lock:
            if used < MEASURED_STEPS:
                self.short_steps += used
                self.short_s += seconds
                if self.short_steps < MEASURED_STEPS:
                    return
                used, seconds = self.short_steps, self.short_s
                self.short_steps, self.short_s = 0, 0.0
            self.seconds = 0.7 * self.seconds + 0.3 * min(seconds / used, STEP_COST_CAP)

    def budget(self, deadline: float | None, max_steps: int) -> int:
        """:func:`step_budget` at this kernel's measured cost per step."""
        return step_budget(deadline, max_steps, self.seconds)


# ---------------------------------------------------------------------------
# One procedure for one design or many: floats or numpy arrays through the same lines
# ---------------------------------------------------------------------------
#
# A procedure written once for a single design and for a sweep takes each input as a
# float or an array. One design runs on Python floats (:func:`as_numbers` makes them so
# at the procedure's door): their arithmetic is numpy's, bit for bit, at a tenth of the
# cost of numpy's scalars, and the functions below take ``math`` for them and numpy for
# arrays, with numpy's answers (NaN, not an exception, outside a function's domain).
# Where Python's floats and numpy's part, the procedure guards its lines so that both
# give the same numbers:
#
# * a division by zero raises ZeroDivisionError on floats (numpy gives inf or NaN):
#   divide by a guarded denominator, ``a / where(b == 0.0, 1.0, b)``, where the quotient
#   is replaced anyway;
# * ``v ** 2`` raises OverflowError on a float whose square overflows (write ``v * v``),
#   and a negative float to a fractional power is complex (numpy: NaN);
# * ``~`` on a Python bool is an integer (-1 or -2): :func:`negate` a mask instead.
#
# Arrays run under ``np.errstate(all="ignore")`` (:func:`quiet`): what is NaN or inf is
# masked by the procedure itself.


_ND = np.ndarray
#: The plain number types :func:`as_numbers` converts to float (bool is not one).
_PLAIN: frozenset[Any] = frozenset((int, float, np.float64, np.float32, np.int64, np.int32))
#: What :func:`quiet` gives for one design: nothing to silence.
_NO_STATE = contextlib.nullcontext()


def as_numbers(x: Mapping[str, Any]) -> dict[str, Any]:
    """The inputs with every plain number as a Python float (arrays and text as they are).

    >>> as_numbers({"a": 1, "b": np.float64(2.5), "c": "v", "d": None, "e": True})
    {'a': 1.0, 'b': 2.5, 'c': 'v', 'd': None, 'e': True}
    """
    # a float as it is first (most inputs are: float() would give the same object back)
    return {
        k: v if v.__class__ is float else float(v) if v.__class__ in _PLAIN else v
        for k, v in x.items()
    }


def is_array(*values: Any) -> bool:
    """True if any of ``values`` is a numpy array (a sweep), False for one design."""
    for v in values:  # noqa: SIM110 - a loop, not any(): it runs hundreds of times a design
        if v.__class__ is _ND:
            return True
    return False


def quiet(many: bool) -> contextlib.AbstractContextManager[Any]:
    """numpy's warnings off (``np.errstate(all="ignore")``) for many designs; none for one.

    One design's floats make no numpy call that could warn, and entering an error state
    costs about what a dozen of their operations do.

    >>> with quiet(True):
    ...     float(np.array([1.0])[0] / np.array([0.0])[0])
    inf
    """
    return np.errstate(all="ignore") if many else _NO_STATE


def where(cond: Any, a: Any, b: Any) -> Any:
    """``a`` where ``cond`` holds, else ``b``: ``np.where`` on arrays, ``if`` on one design.

    >>> where(2.0 > 1.0, "yes", "no"), where(np.array([True, False]), 1.0, 2.0).tolist()
    ('yes', [1.0, 2.0])
    """
    if cond.__class__ is not _ND and a.__class__ is not _ND and b.__class__ is not _ND:
        return a if cond else b  # one design (the hot path: no isinstance calls)
    return np.where(cond, a, b)


def divide(a: Any, b: Any) -> Any:
    """``a / b`` with numpy's answer where ``b`` is 0 (±inf, or NaN for 0/0), floats too.

    For a quotient whose value stands where its denominator can reach 0 (Python raises
    ZeroDivisionError there, numpy gives inf or NaN).

    >>> divide(1.0, 0.0), divide(-1.0, 0.0), divide(1.0, -0.0), divide(0.0, 0.0), divide(3.0, 2.0)
    (inf, -inf, -inf, nan, 1.5)
    >>> with quiet(True):
    ...     divide(np.array([1.0, 0.0]), 0.0).tolist(), divide(1.0, np.array([0.0, 2.0])).tolist()
    ([inf, nan], [inf, 0.5])
    """
    if b.__class__ is _ND or b:  # not a zero number: Python's division is numpy's
        return a / b
    if a.__class__ is _ND:
        return a / np.float64(b)
    if a != a or a == 0.0:
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def negate(mask: Any) -> Any:
    """Not ``mask``, per point (``~`` on arrays; on one design's bool, ``not``).

    >>> negate(1.0 > 2.0), negate(np.array([True, False])).tolist()
    (True, [False, True])
    """
    return ~mask if mask.__class__ is _ND else not mask


def pymax(a: Any, b: Any) -> Any:
    """``max(a, b)`` with Python's NaN rule (``b`` replaces ``a`` only if ``b > a``).

    >>> float(pymax(np.float64("nan"), 1.0)), float(pymax(1.0, np.float64("nan")))
    (nan, 1.0)
    """
    if a.__class__ is not _ND and b.__class__ is not _ND:
        return b if b > a else a  # one design (a hot path)
    return np.where(b > a, b, a)


def pymin(a: Any, b: Any) -> Any:
    """``min(a, b)`` with Python's NaN rule (``b`` replaces ``a`` only if ``b < a``)."""
    if a.__class__ is not _ND and b.__class__ is not _ND:
        return b if b < a else a
    return np.where(b < a, b, a)


def isfinite(v: Any) -> Any:
    """Neither inf nor NaN, per point."""
    return np.isfinite(v) if v.__class__ is _ND else math.isfinite(v)


def sqrt(v: Any) -> Any:
    """Square root; NaN below 0. A float gives a float, a numpy number numpy's.

    >>> sqrt(2.25), float(sqrt(np.float64(2.25))), sqrt(-1.0), sqrt(np.float64(-1.0))
    (1.5, 1.5, nan, np.float64(nan))
    """
    if v.__class__ is float:
        return math.sqrt(v) if v >= 0.0 else math.nan
    if isinstance(v, np.ndarray):
        return np.sqrt(v)
    return np.float64(math.sqrt(v)) if v >= 0.0 else np.float64(math.nan)


def _compiled_sqrt() -> None:
    """Let a compiled kernel call :func:`sqrt`: numba compiles it as ``np.sqrt``.

    A function run both by Python (floats or arrays) and compiled in a kernel (such as
    :func:`engine.procedures.striker_cycle.face_forces`) takes its root from :func:`sqrt`.
    """
    try:
        from numba.extending import overload
    except ImportError:  # pragma: no cover - numba is a declared dependency
        return

    @overload(sqrt)
    def _sqrt(v):  # type: ignore[no-untyped-def]
        return lambda v: np.sqrt(v)


_compiled_sqrt()


def hypot(a: Any, b: Any) -> Any:
    r""":math:`\sqrt{a^2 + b^2}` without overflow.

    >>> hypot(3.0, 4.0), hypot(np.float64(3.0), 4.0), hypot(1e200, 1e200) > 1e200
    (5.0, np.float64(5.0), True)
    """
    if a.__class__ is float and b.__class__ is float:
        return math.hypot(a, b)
    if is_array(a, b):
        return np.hypot(a, b)
    return np.float64(math.hypot(a, b))


def atan2(y: Any, x: Any) -> Any:
    """The angle of (x, y), [rad] (-π…π).

    >>> round(atan2(1.0, -1.0) / math.pi, 12), float(atan2(np.float64(0.0), -1.0)) == math.pi
    (0.75, True)
    """
    if y.__class__ is float and x.__class__ is float:
        return math.atan2(y, x)
    if is_array(y, x):
        return np.arctan2(y, x)
    return np.float64(math.atan2(y, x))


def tan(v: Any) -> Any:
    """Tangent of an angle, [rad]; NaN at ±inf.

    >>> round(tan(math.pi / 4), 12), tan(math.inf), float(tan(np.float64(0.0)))
    (1.0, nan, 0.0)
    """
    if v.__class__ is float:
        return math.tan(v) if math.isfinite(v) else math.nan
    if isinstance(v, np.ndarray):
        return np.tan(v)
    return np.float64(math.tan(v)) if math.isfinite(v) else np.float64(math.nan)


def log1p(v: Any) -> Any:
    """:math:`\\ln(1 + v)`, accurate for small v; -inf at -1, NaN below.

    >>> log1p(-1.0), log1p(-2.0), log1p(0.0), float(log1p(np.float64(-1.0)))
    (-inf, nan, 0.0, -inf)
    """
    if isinstance(v, np.ndarray):
        return np.log1p(v)
    out = math.log1p(v) if v > -1.0 else -math.inf if v == -1.0 else math.nan
    return out if v.__class__ is float else np.float64(out)


def any_true(mask: Any) -> bool:
    """True if ``mask`` holds at any point (one design: if it holds)."""
    return bool(mask.any()) if mask.__class__ is _ND else bool(mask)


def all_true(mask: Any) -> bool:
    """True if ``mask`` holds at every point (one design: if it holds)."""
    return bool(mask.all()) if mask.__class__ is _ND else bool(mask)


def asin(v: Any) -> Any:
    """Arcsine, [rad]; NaN outside [-1, 1].

    >>> round(asin(0.5) * 6.0 / math.pi, 12), asin(2.0), float(asin(np.float64(2.0)))
    (1.0, nan, nan)
    """
    if isinstance(v, np.ndarray):
        return np.arcsin(v)
    out = math.asin(v) if -1.0 <= v <= 1.0 else math.nan
    return out if v.__class__ is float else np.float64(out)
