"""Run a model: validate, choose the rung, time it, and never return NaN or inf.

:func:`run` is the one way every caller (the service, the benchmarks, a
Python user) evaluates a model, so rung selection, timing and the finiteness
guarantee live in one place. :func:`sweep` evaluates one input over a range,
the curves the papers plot.
"""

from __future__ import annotations

import functools
import math
import threading
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from collections.abc import Set as AbstractSet
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from . import points
from .errors import BudgetExceeded, Cancelled, EngineError, InputOutOfRange, SolverFailed
from .spec import Check, ModelSpec, Param, Result, RunContext, Rung, Scratch, Value
from .text import OPEN, Parts, parts, plain, split

DEFAULT_TOLERANCE = 0.01
MAX_SWEEP_POINTS = 2000
DEFAULT_BUDGET_S = 10.0
DEFAULT_MAX_STEPS = 1_000_000


@dataclass
class RunResult:
    """A model evaluation as the service returns it (SI values, units, provenance)."""

    model: str
    results: dict[str, Value]
    units: dict[str, str]
    rung: str
    error_estimate: float | None
    elapsed_s: float
    inputs: dict[str, Any]
    checks: list[Check] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    series: dict[str, list[float]] = field(default_factory=dict)
    #: ``notes`` as the model wrote them, quantities marked (:func:`engine.core.text.q`);
    #: empty when no note has one.
    marked_notes: list[str] = field(default_factory=list, repr=False)
    #: What ``error_estimate`` promises (the rung's :attr:`Rung.estimate_kind`): "bound",
    #: or "typical" (a note then says how often it is exceeded); None with no estimate.
    error_kind: Literal["bound", "typical"] | None = None

    @property
    def notes_parts(self) -> list[Parts]:
        """``notes`` as text and quantities, one entry per note (:func:`engine.core.text.parts`)."""
        return [parts(n) for n in self.marked_notes or self.notes]

    def answer_sentences(self) -> tuple[list[tuple[Check, str, Parts]], list[str], list[Parts]]:
        """The sentences as an answer shows them: each check with its plain ``detail`` and
        its ``detail_parts``, the plain ``notes`` and ``notes_parts``.

        A result whose sentences were not read yet reads each marked one once for its text
        and its parts (:func:`engine.core.text.split`, not plain() then parts()) and is left
        unread: its checks come as the model wrote them (name, verdict and level read from
        them), no :class:`Check` is made again and no field is kept.
        """
        marked = self.__dict__.get("_marked")
        if marked is None:
            return (
                [(c, c.detail, c.detail_parts) for c in self.checks],
                self.notes,
                self.notes_parts,
            )
        written, notes = marked
        checks = [
            (c, *split(c.detail)) if OPEN in c.detail else (c, c.detail, c.detail_parts)
            for c in written
        ]
        read = [split(n) for n in notes]
        return checks, [text for text, _ in read], [ps for _, ps in read]

    @property
    def check_flags(self) -> list[tuple[str, bool]]:
        """Each check's (name, ok), without making the sentences readable: a caller that
        keeps only the verdicts (a study's looped points) does not pay for the texts.

        >>> from engine.core.spec import Check
        >>> r = RunResult._of([Check("c3 > c1", False, "soften the power spring")], [], model="m")
        >>> r.check_flags, "_marked" in r.__dict__
        ([('c3 > c1', False)], True)
        """
        marked = self.__dict__.get("_marked")
        return [(c.name, c.ok) for c in (self.checks if marked is None else marked[0])]

    @classmethod
    def _of(cls, checks: list[Check], notes: list[str], **fields: Any) -> RunResult:
        """A result whose checks and notes are made readable when first read (:func:`run`'s).

        ``checks`` and ``notes`` are as the model wrote them, quantities marked: taking
        the marks out costs about a microsecond a sentence, which a caller that reads only
        the numbers and the warnings (a benchmark, a sweep's looped points, a script) need
        not pay. The fields read the same as if they had been given made.
        """
        self = cls.__new__(cls)
        self.__dict__.update(fields)
        self.__dict__["_marked"] = (checks, notes)
        return self

    if not TYPE_CHECKING:  # the type checker sees the fields as declared

        def __getattr__(self, name: str) -> Any:
            """The sentence fields of a result :meth:`_of` made, on their first reading."""
            made = self.__dict__
            marked = made.get("_marked")
            if marked is None or name not in _SENTENCE_FIELDS:
                # another thread may have made the fields since this lookup missed them
                if name in made:
                    return made[name]
                raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
            made.update(_sentences(*marked))
            made.pop("_marked", None)
            return made[name]


#: The fields of :class:`RunResult` that :meth:`RunResult._of` leaves to their first reading.
_SENTENCE_FIELDS = frozenset({"checks", "notes", "marked_notes"})


def _sentences(checks: list[Check], notes: list[str]) -> dict[str, Any]:
    """The sentence fields of a :class:`RunResult` from the sentences as the model wrote
    them: the marks taken out (:func:`engine.core.text.plain`), the marked ones kept for
    their parts (``notes_parts``, each check's ``detail_parts``, read when asked)."""
    marked = any(OPEN in n for n in notes)
    return {
        "checks": [
            Check(c.name, c.ok, plain(c.detail), c.level, c.detail) if OPEN in c.detail else c
            for c in checks
        ],
        "notes": [plain(n) for n in notes] if marked else notes,
        "marked_notes": notes if marked else [],
    }


@dataclass
class SweepResult:
    """One input varied over ``values``; ``results[name][i]`` belongs to ``values[i]``.

    The sweep keeps its bookkeeping in numpy: ``columns`` holds a float array per
    output (NaN where a point was not computed), or an object array (None there) for
    texts and flags that miss points; the rung of each point is a code into
    ``rung_names`` (``rung_codes``, -1 where the point was refused). ``results``,
    ``values``, ``rungs``, ``rung_array`` and ``error_estimates`` are the same as Python
    lists (an object array for ``rung_array``), made on first use: a caller that encodes
    the arrays itself never builds a Python object per point.
    """

    model: str
    vary: str
    #: The swept values, one per point.
    value_array: np.ndarray
    #: Per output, one entry per point (NaN or None where not computed).
    columns: dict[str, np.ndarray]
    units: dict[str, str]
    rung: str
    elapsed_s: float
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    #: The rung that ran at each point, as an index into ``rung_names`` (-1 where the
    #: point was refused): ``auto`` chooses per point, so a sweep across a regime change
    #: may mix rungs.
    rung_codes: np.ndarray = field(default_factory=lambda: np.empty(0, dtype=np.int8))
    rung_names: tuple[str, ...] = ()
    #: Each point's error estimate (NaN where refused or not known). A sweep whose rung
    #: was named makes it when first read (:meth:`_of`): a caller that reads only the
    #: columns does not pay for the rungs' estimates.
    error_array: np.ndarray = field(default_factory=lambda: np.empty(0))

    @classmethod
    def _of(
        cls,
        errors: Callable[[], np.ndarray],
        codes: Callable[[], np.ndarray] | None = None,
        **fields: Any,
    ) -> SweepResult:
        """A sweep whose ``error_array`` is ``errors()``, made when first read; with
        ``codes``, its ``rung_codes`` are ``codes()``, made when first read too (a column of
        the sweep's own: a caller that reads only the columns does not pay for it)."""
        self = cls(**fields)
        made = self.__dict__
        del made["error_array"]
        made["_errors"] = errors
        if codes is not None:
            del made["rung_codes"]
            made["_codes"] = codes
        return self

    if not TYPE_CHECKING:  # the type checker sees the fields as declared

        def __getattr__(self, name: str) -> Any:
            """``error_array`` or ``rung_codes`` of a sweep :meth:`_of` made, on its first
            reading."""
            made = self.__dict__
            key = _LATER.get(name)
            maker = None if key is None else made.get(key)
            if maker is None:
                # another thread may have made it since this lookup missed it
                if name in made:
                    return made[name]
                raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
            made[name] = value = maker()
            made.pop(key, None)
            return value

    def __getstate__(self) -> dict[str, Any]:
        """The fields, ``error_array`` and ``rung_codes`` made if they were not yet (their
        makers are closures, which do not pickle)."""
        for name, key in _LATER.items():
            if key in self.__dict__:
                getattr(self, name)  # made now, kept in __dict__
        return {k: v for k, v in self.__dict__.items() if k not in _MAKERS}

    @functools.cached_property
    def values(self) -> list[float]:
        return list(self.value_array.astype(float).tolist())

    @functools.cached_property
    def results(self) -> dict[str, list[Value]]:
        return {name: _listed(column) for name, column in self.columns.items()}

    @functools.cached_property
    def rung_array(self) -> np.ndarray:
        """The rung of each point as an object array of names (None where refused)."""
        names = np.array([*self.rung_names, None], dtype=object)
        return names[self.rung_codes]  # code -1 picks the trailing None

    @functools.cached_property
    def rungs(self) -> list[str | None]:
        return list(self.rung_array.tolist())

    @functools.cached_property
    def error_estimates(self) -> list[float | None]:
        return _listed(self.error_array)  # type: ignore[return-value]


#: The fields of :class:`SweepResult` that :meth:`SweepResult._of` may leave to their first
#: reading, each with the key of its maker.
_LATER = {"error_array": "_errors", "rung_codes": "_codes"}
_MAKERS = frozenset(_LATER.values())


def _listed(column: np.ndarray) -> list[Value]:
    """A column as a list: NaN (and inf) of a float column become None."""
    out: list[Value] = column.tolist()
    if column.dtype.kind == "f":
        bad = ~np.isfinite(column)
        if bad.any():
            for i in np.flatnonzero(bad).tolist():
                out[i] = None
    return out


def _rung_counts(codes: np.ndarray, names: Sequence[str]) -> dict[str, int]:
    """How many points each rung ran at, in the order the points first use them.

    Counted with ``np.bincount`` over the codes (-1, a refused point, is not counted).

    >>> _rung_counts(np.array([1, -1, 0, 1, 1], dtype=np.int8), ("closed_form", "simulation"))
    {'simulation': 3, 'closed_form': 1}
    """
    counts = np.bincount(codes[codes >= 0], minlength=len(names))
    used = np.flatnonzero(counts).tolist()
    if len(used) > 1:  # first-seen order, as a reader of the points meets them
        used.sort(key=lambda k: int(np.argmax(codes == k)))
    return {names[k]: int(counts[k]) for k in used}


def _rung_summary(counts: Mapping[str, int]) -> tuple[str, list[str]]:
    """The sweep's ``rung`` field and, when points differ, a note saying how."""
    if len(counts) <= 1:
        return next(iter(counts), ""), []
    return ", ".join(counts), [
        "auto chose the rung per point: "
        + ", ".join(f"{r} at {n} point{'s' if n > 1 else ''}" for r, n in counts.items())
        + " (see rungs)"
    ]


def _declared(spec: ModelSpec, name: str) -> Rung | None:
    """The rung called ``name``, or None where a model names one it does not declare."""
    try:
        return spec.rung(name)
    except KeyError:
        return None


def _caveat(spec: ModelSpec, name: str) -> str:
    """`` (<the rung's caveat>)`` when its error estimate is typical, else ""."""
    rung = _declared(spec, name)
    return f" ({rung.estimate_caveat})" if rung is not None and rung.estimate_caveat else ""


def _fidelity(spec: ModelSpec, fidelity: str | None, tolerance: float | None) -> str:
    """The fidelity asked for: given, else 'auto' when a tolerance is given, else the default."""
    if fidelity is not None:
        return fidelity
    return "auto" if tolerance is not None else spec.default_fidelity


def choose_rung(
    spec: ModelSpec,
    inputs: Mapping[str, Any],
    fidelity: str,
    tolerance: float,
    scratch: Scratch | None = None,
) -> tuple[str, list[str]]:
    """Pick the rung to run and say why.

    A named rung runs as asked. ``"auto"`` takes the cheapest rung (the spec
    lists them cheapest first) whose a-priori error estimate is within
    ``tolerance``; if none is, the most accurate applicable rung runs and the
    note says the tolerance was not met. Where the chosen rung's estimate is typical,
    not a bound (:attr:`Rung.estimate_kind`), the note says so and how often it is exceeded.
    The estimates leave their work in ``scratch`` (the request's) for the compute.
    """
    if fidelity != "auto":
        if fidelity not in spec.rung_names:
            raise InputOutOfRange(
                f"fidelity = {fidelity!r} is not allowed: must be 'auto' or one of "
                + ", ".join(repr(r) for r in spec.rung_names),
                field="fidelity",
            )
        return fidelity, []
    applicable: list[tuple[str, float]] = []
    shared = Scratch() if scratch is None else scratch
    for rung in spec.rungs:
        estimate = rung.estimate_in(inputs, shared)
        if estimate is None or not math.isfinite(estimate):
            continue
        if estimate <= tolerance:  # the common case: the first rung that applies meets it
            why = (
                f"auto: chose {rung.name!r}, estimated error {estimate:.2g} "
                f"≤ tolerance {tolerance:.2g}"
            )
            if applicable:
                why += "; cheaper rungs estimated " + ", ".join(
                    f"{n} {e:.2g}" for n, e in applicable
                )
            if rung.estimate_kind != "bound":  # a typical estimate: its caveat follows
                why += f"; {rung.estimate_caveat}"
            return rung.name, [why]
        applicable.append((rung.name, estimate))
    if not applicable:
        name = spec.rungs[-1].name
        return name, [f"auto: no rung gave an error estimate; ran {name!r}"]
    name, estimate = min(applicable, key=lambda item: item[1])
    return name, [
        f"auto: no rung meets tolerance {tolerance:.2g}; ran the most accurate, {name!r} "
        f"(estimated error {estimate:.2g}){_caveat(spec, name)}"
    ]


def _fallback(
    spec: ModelSpec,
    rung: str,
    inputs: Mapping[str, Any],
    exc: BudgetExceeded,
    *,
    auto: bool = False,
    scratch: Scratch | None = None,
) -> tuple[str, float, float] | None:
    """The rung to run instead of ``rung`` after ``exc`` (per :attr:`Rung.fallback`), or None.

    Returns the fallback's name, the declining rung's estimate and the fallback's.

    Only a rung that declined up front (``expected_steps`` in the error: it would need
    more steps than allowed) falls back, and only to a rung whose estimated error for
    these inputs is no larger than the declining rung's own: the answer still meets
    what was asked of it. A deadline overrun part-way is not rescued. Under ``auto``
    the fallback runs even when its estimate is larger (auto's promise is the best
    answer within the budget; the caller's note then says the tolerance was not met).
    """
    declining = spec.rung(rung)
    if declining.fallback is None or "expected_steps" not in exc.context:
        return None
    shared = Scratch() if scratch is None else scratch
    own = declining.estimate_in(inputs, shared)
    theirs = spec.rung(declining.fallback).estimate_in(inputs, shared)
    if own is None or theirs is None or not math.isfinite(theirs):
        return None
    if theirs > own and not auto:
        return None
    return declining.fallback, own, theirs


def _wanted(spec: ModelSpec, asked: set[str], *, named: bool, series: bool) -> set[str]:
    """The outputs to compute: only what the scene requires (nothing no output needs).

    Every scalar output when none is named; series only when named or when
    ``series`` asks for all of them.
    """
    wanted = set(asked) if named else {o.name for o in spec.outputs if not o.series}
    if series:
        wanted |= {o.name for o in spec.outputs if o.series}
    return wanted


def _finite(value: Value) -> bool:
    return not isinstance(value, float) or math.isfinite(value)


class _arithmetic_refused:
    """A safety net under the declared ranges: a combination of extreme inputs that
    overflows or divides by zero is refused (SolverFailed, 422), never a crash (500).
    numpy's overflow/invalid warnings are silenced: a non-finite result becomes null with a
    note (numpy's error state is per thread). A class, not a generator context manager:
    it wraps every evaluation. ``silenced``: the caller holds numpy's error state at
    ``all="ignore"`` already (a study's chunk enters it once for its looped points, where
    making and entering one a point cost 2 µs of the striker's study): only the refusal."""

    __slots__ = ("spec", "state")

    def __init__(self, spec: ModelSpec, *, silenced: bool = False) -> None:
        self.spec = spec
        self.state = None if silenced else np.errstate(all="ignore")

    def __enter__(self) -> None:
        if self.state is not None:
            self.state.__enter__()

    def __exit__(
        self, kind: type[BaseException] | None, exc: BaseException | None, tb: Any
    ) -> None:
        if self.state is not None:
            self.state.__exit__(kind, exc, tb)
        if kind is not None and issubclass(kind, ArithmeticError):
            raise SolverFailed(
                f"{self.spec.name} cannot be evaluated for these inputs: the arithmetic failed "
                f"({kind.__name__}); values this extreme lie outside what the model "
                "computes reliably",
                error=kind.__name__,
            ) from None


@dataclass(frozen=True)
class Prepared:
    """A request validated and its rung chosen (:func:`prepare`), ready for :func:`run`."""

    values: dict[str, Any]
    warnings: list[str]
    tolerance: float
    fidelity: str
    rung: str
    notes: tuple[str, ...]
    #: The request's shared work: what the rung estimates computed for these values,
    #: for the compute of the same request (:class:`~engine.core.spec.Scratch`).
    scratch: Scratch


def prepare(
    spec: ModelSpec,
    inputs: Mapping[str, Any],
    fidelity: str | None = None,
    tolerance: float | None = None,
) -> Prepared:
    """Validate ``inputs`` and choose the rung, once: :func:`run` takes the result.

    Raises InputOutOfRange for an invalid input or tolerance, as :func:`run` does.
    """
    return Prepared(*_prepare(spec, inputs, fidelity, tolerance, guarded=False))


def check_tolerance(tol: float) -> None:
    """Refuse a tolerance outside (0, 1), naming the field."""
    if not (math.isfinite(tol) and 0.0 < tol < 1.0):
        raise InputOutOfRange(
            f"tolerance = {tol:g} is not allowed: must be > 0 and < 1", field="tolerance"
        )


def _check_outputs(spec: ModelSpec, asked: AbstractSet[str]) -> None:
    """Refuse output names ``spec`` does not offer, listing the ones it does."""
    unknown = sorted(asked - spec.units.keys())
    if unknown:
        raise InputOutOfRange(
            f"unknown output(s) {', '.join(unknown)}; {spec.name} offers "
            + ", ".join(sorted(spec.units)),
            field="outputs",
        )


def _prepare(
    spec: ModelSpec,
    inputs: Mapping[str, Any],
    fidelity: str | None,
    tolerance: float | None,
    *,
    guarded: bool,
) -> tuple[dict[str, Any], list[str], float, str, str, tuple[str, ...], Scratch]:
    """:func:`prepare`'s fields, in :class:`Prepared`'s order; ``guarded``: the caller holds
    :class:`_arithmetic_refused` already. A tuple: :func:`run` reads them once and makes no
    :class:`Prepared` of its own (a frozen dataclass: ~0.6 µs a call)."""
    values, warnings = spec.validate(inputs)
    tol = DEFAULT_TOLERANCE if tolerance is None else float(tolerance)
    check_tolerance(tol)
    asked = _fidelity(spec, fidelity, tolerance)
    scratch = Scratch()
    if asked == "auto" and not guarded:  # the estimates run: one numpy error state for them
        with _arithmetic_refused(spec):
            rung, notes = choose_rung(spec, values, asked, tol, scratch)
    else:  # a named rung is only checked against the declared names
        rung, notes = choose_rung(spec, values, asked, tol, scratch)
    return values, warnings, tol, asked, rung, tuple(notes), scratch


def _computed(
    spec: ModelSpec, values: dict[str, Any], ctx: RunContext, auto: bool, notes: list[str]
) -> Result:
    """``spec.compute`` on ``ctx``, or on the rung's declared fallback where the rung declines
    up front (:func:`_fallback`; the note saying so is added to ``notes``)."""
    try:
        return spec.compute(values, ctx)
    except BudgetExceeded as exc:
        rung, tol = ctx.rung, ctx.tolerance
        found = _fallback(spec, rung, values, exc, auto=auto, scratch=ctx.scratch)
        if found is None:
            raise
        fallback, own, theirs = found
        notes.append(
            f"{rung!r} would need about {exc.context['expected_steps']:.2g} steps (budget "
            f"{exc.context.get('step_budget', ctx.max_steps):g}); ran its declared fallback "
            f"{fallback!r} instead, whose estimated "
            + (
                f"error {theirs:.2g} is within {rung!r}'s own {own:.2g}"
                if theirs <= own
                else f"error is {theirs:.2g}"
            )
            + (f": the tolerance {tol:.2g} is not met" if auto and theirs > tol else "")
            + _caveat(spec, fallback)
        )
        return spec.compute(values, replace(ctx, rung=fallback))


def _scalar(value: Value) -> Value:
    """A scalar output as :func:`run` gives it: a numpy scalar as its Python value, None
    where it is not finite (run's note says so)."""
    kind = type(value)
    if kind is float:
        return value if math.isfinite(value) else None  # type: ignore[arg-type]
    if not (kind is int or kind is str or kind is bool or value is None):
        if isinstance(value, np.generic):
            value = value.item()
        if not _finite(value):
            return None
    return value


def point_outputs(
    spec: ModelSpec,
    values: Mapping[str, Any],
    rung: str,
    outputs: Sequence[str],
    tolerance: float,
) -> frozenset[str]:
    """The checks :func:`run_point` makes of what is the same for every point of a study's
    chunk (the tolerance, the rung's name, the output names), and ``outputs`` as the set its
    context reads; raises what :func:`run_point` would raise for each point. ``values``:
    a point's inputs (a named rung is only checked against the declared names).
    """
    check_tolerance(tolerance)
    choose_rung(spec, values, rung, tolerance)  # refuses an unknown rung name
    asked = frozenset(outputs)  # _wanted's set: outputs named, no series
    _check_outputs(spec, asked)
    return asked


def run_point(
    spec: ModelSpec,
    values: dict[str, Any],
    rung: str,
    outputs: Sequence[str],
    *,
    tolerance: float,
    budget_s: float | None,
    max_steps: int = DEFAULT_MAX_STEPS,
    cancel: threading.Event | None = None,
    checked: frozenset[str] | None = None,
    silenced: bool = False,
    prepared: Any = None,
) -> tuple[str, dict[str, Value], list[tuple[str, bool]]]:
    """One point as a study keeps it: the rung that ran, the ``outputs`` and the checks'
    verdicts, what :func:`run` gives for the same point without its sentences.

    ``values`` are validated inputs (:meth:`ModelSpec.validate`'s) and ``rung`` a rung
    named, not ``"auto"`` (a study's chunk validates its points as arrays and picks the rung
    once); the model is told it need not write its sentences (``RunContext.sentences``).
    The same compute, fallback, nulls (None where run gives null) and refusals as
    :func:`run`. ``checked``: what :func:`point_outputs` gave for the same ``spec``,
    ``rung``, ``outputs`` and ``tolerance`` (a caller that runs many points checks them
    once); None: they are checked here. ``silenced``: the caller runs it under
    ``np.errstate(all="ignore")`` (a chunk's loop, entered once), which :func:`run` and
    this enter otherwise. ``prepared``: the point's entry of the model's
    :attr:`~engine.core.spec.ModelSpec.prepare_points` (``ctx.prepared``).
    """
    with _arithmetic_refused(spec, silenced=silenced):
        asked = (
            point_outputs(spec, values, rung, outputs, tolerance) if checked is None else checked
        )
        ctx = RunContext.of_request(
            rung,
            asked,
            tolerance,
            None if budget_s is None else time.perf_counter() + budget_s,
            max_steps,
            cancel,
            Scratch(),
            sentences=False,
            prepared=prepared,
        )
        result = _computed(spec, values, ctx, False, [])
    got = result.values.get  # None where not given: _scalar keeps it
    isfinite = math.isfinite
    scalars = {
        name: v if v.__class__ is float and isfinite(v) else _scalar(v)
        for name, v in zip(outputs, map(got, outputs), strict=True)
    }
    verdicts = result.verdicts  # the level does not come into a verdict
    if verdicts is None:
        verdicts = [(c.name, c.ok) for c in spec.levelled(result.checks)]
    return result.rung, scalars, verdicts


def run(
    spec: ModelSpec,
    inputs: Mapping[str, Any],
    *,
    fidelity: str | None = None,
    tolerance: float | None = None,
    outputs: Iterable[str] | None = None,
    budget_s: float | None = DEFAULT_BUDGET_S,
    max_steps: int = DEFAULT_MAX_STEPS,
    series: bool = False,
    cancel: threading.Event | None = None,
    prepared: Prepared | None = None,
) -> RunResult:
    """Evaluate ``spec`` on SI ``inputs``.

    ``outputs`` limits the work to the named outputs and series (every scalar
    output when None). Series are computed only when asked for: named in
    ``outputs``, or all of them with
    ``series=True``. Non-finite values never leave: they become None with a note.
    ``budget_s`` and ``max_steps`` reach the model as ``ctx.deadline`` and
    ``ctx.max_steps``; a model past either raises BudgetExceeded. ``cancel``
    reaches it as ``ctx.cancel``: once set, the model stops at its next budget
    check with :class:`Cancelled`. ``prepared`` is what :func:`prepare` made of the same
    ``inputs``, ``fidelity`` and ``tolerance`` (a caller that chose its lane by the rung
    does not validate and choose again).
    """
    with _arithmetic_refused(spec):  # one numpy error state for the estimates and the model
        if prepared is None:
            values, warnings, tol, asked, rung, made, scratch = _prepare(
                spec, inputs, fidelity, tolerance, guarded=True
            )
        else:
            values, warnings, tol, asked, rung, made = (
                prepared.values,
                prepared.warnings,
                prepared.tolerance,
                prepared.fidelity,
                prepared.rung,
                prepared.notes,
            )
            scratch = prepared.scratch
        notes = list(made)
        units = spec.units
        if outputs is None:
            wanted = spec.scalar_outputs | spec.series_outputs if series else spec.scalar_outputs
        else:
            asked_for = set(outputs)
            _check_outputs(spec, asked_for)
            wanted = frozenset(_wanted(spec, asked_for, named=True, series=series))
        start = time.perf_counter()
        ctx = RunContext.of_request(
            rung,
            wanted,
            tol,
            None if budget_s is None else start + budget_s,
            max_steps,
            cancel,
            scratch,
        )
        result = _computed(spec, values, ctx, asked == "auto", notes)
    elapsed = time.perf_counter() - start

    scalars: dict[str, Value] = {}
    curves: dict[str, list[float]] = {}
    notes += spec.assumptions  # the run's own list (made from the prepared notes above)
    notes += result.notes
    isfinite = math.isfinite
    for name, value in result.values.items():
        if name not in wanted:
            continue
        kind = type(value)
        if kind is float:  # the common case (a float subclass, np.float64, goes below)
            if not isfinite(value):  # type: ignore[arg-type]  # a float: its type is float
                notes.append(f"{name} could not be computed for these inputs (non-finite); null")
                value = None
        elif not (kind is int or kind is str or kind is bool or value is None):
            if isinstance(value, np.generic):
                value = value.item()
            if not _finite(value):
                notes.append(f"{name} could not be computed for these inputs (non-finite); null")
                value = None
        scalars[name] = value
    if outputs is not None:
        for name in sorted(wanted - scalars.keys() - spec.series_outputs):
            scalars[name] = None
            notes.append(f"{name} is not computed by {result.rung!r} for these inputs; null")
    for name, seq in result.series.items():
        if name not in wanted:
            continue
        arr = np.asarray(seq, dtype=float)
        if not np.all(np.isfinite(arr)):
            notes.append(f"series {name} had non-finite points; omitted")
            continue
        curves[name] = arr.tolist()
    error = result.error_estimate
    if error is not None and not math.isfinite(error):
        notes.append("the error estimate is unbounded for these inputs; null")
        error = None
    ran = _declared(spec, result.rung)
    error_kind = None if error is None or ran is None else ran.estimate_kind
    if error_kind == "typical" and ran is not None:
        caveat = ran.estimate_caveat  # a sentence made on each call: made once here
        if not any(caveat in n for n in notes):
            notes.append(caveat)
    given_units = {name: units[name] for name in scalars}  # each one given: its unit
    for name in curves:
        given_units[name] = units[name]
    return RunResult._of(
        spec.levelled(result.checks),
        notes,
        model=spec.name,
        results=scalars,
        units=given_units,
        rung=result.rung,
        error_estimate=error,
        elapsed_s=elapsed,
        inputs=values,
        series=curves,
        error_kind=error_kind,
        warnings=[plain(w) for w in warnings + result.warnings],
    )


def sweep_values(start: float, stop: float, num: int, scale: str = "linear") -> np.ndarray:
    """The points of a sweep; ``scale="log"`` spaces them geometrically."""
    if not 2 <= num <= MAX_SWEEP_POINTS:
        raise InputOutOfRange(
            f"num = {num} is not allowed: a sweep has 2…{MAX_SWEEP_POINTS} points", field="num"
        )
    if scale == "log":
        if start <= 0 or stop <= 0:
            raise InputOutOfRange("a log sweep needs start > 0 and stop > 0", field="start")
        return np.geomspace(start, stop, num)
    return np.linspace(start, stop, num)


def sweep(
    spec: ModelSpec,
    base: Mapping[str, Any],
    vary: str,
    values: Sequence[float],
    *,
    outputs: Iterable[str] | None = None,
    fidelity: str | None = None,
    tolerance: float | None = None,
    budget_s: float | None = DEFAULT_BUDGET_S,
    max_steps: int = DEFAULT_MAX_STEPS,
    cancel: threading.Event | None = None,
) -> SweepResult:
    """Evaluate ``spec`` with ``vary`` set to each of ``values``, the rest from ``base``.

    A point that the model refuses (an infeasible design, say) is None in
    every output, with one note naming the point and the reason. ``cancel`` stops
    the sweep with :class:`Cancelled` at the next point that runs on its own.
    """
    try:
        param = spec.param(vary)
    except KeyError:
        raise InputOutOfRange(
            f"vary = {vary!r} is not an input of {spec.name}", field="vary"
        ) from None
    if not param.is_numeric:
        raise InputOutOfRange(f"vary = {vary!r} is not a numeric input", field="vary")
    wanted = list(outputs) if outputs is not None else None
    start = time.perf_counter()
    arr, low, high = _sweep_column(param, values)
    n = int(arr.size)
    # the fixed inputs (refused here if out of range) with the first point's varied one
    first, warnings = spec.validate({**base, vary: arr[0].item()})
    warnings = [w for w in warnings if not w.startswith(f"{vary} = ")]
    warnings += _recommended(param, arr, low, high)
    x: dict[str, Any] = {**first, vary: arr}
    tol = DEFAULT_TOLERANCE if tolerance is None else float(tolerance)
    asked = _fidelity(spec, fidelity, tolerance)
    notes: list[str] = []
    scratch = Scratch()  # the estimates' work on x, for the array path on the same x
    points.keep_ends(scratch, vary, low, high)  # read once here, for the array path
    check_tolerance(tol)
    # each rung group: its rung, the points it holds (None: every point)
    groups: list[tuple[int, np.ndarray | None]]
    estimates: Mapping[int, np.ndarray | None] | None
    # the points an estimate refuses, run alone to say why: only ``auto`` makes the estimates
    # here, so a named rung's sweep spends no column on them
    refused: np.ndarray | None = None
    if asked == "auto":  # the estimates choose the rung per point: needed now
        refused = np.zeros(n, dtype=bool)
        estimates = points.rung_estimates(
            spec, x, n, point=lambda j: points.at(x, n, j), refused=refused, scratch=scratch
        )
        assert estimates is not None
        index = points.auto_index(spec, estimates, n, tol)
        groups = [(k, (index == k) & ~refused) for k in range(len(spec.rung_names))]
    else:
        # a named rung runs everywhere: its estimates are wanted only by a caller that
        # reads them (``error_array``), so they are computed then, not here
        choose_rung(spec, first, asked, tol)  # refuses an unknown rung name
        estimates = None
        index = None
        groups = [(spec.rung_names.index(asked), None)]
    known = spec.scalar_outputs
    scalar_names = spec.scalar_output_names if wanted is None else [o for o in wanted if o in known]
    # per output: a float column (NaN where not computed), or an object column (None) for
    # texts and flags that miss points, filled from the array groups and the looped points
    columns: dict[str, np.ndarray] = {}
    computed: dict[str, None] = {}  # the outputs given, in the order first given
    names = list(spec.rung_names)
    # the rung of each point, an index into names (-1 where refused): made at the first
    # group that gives values, or before the loop; where one rung ran at every point
    # (``one_rung``, the common case), when first read
    codes: np.ndarray | None = None
    one_rung: int | None = None
    # for the error estimates, made when read: (rung, its points or None, where refused)
    given: list[tuple[int, np.ndarray | None, np.ndarray | None]] = []
    looped_errors: dict[int, float] = {}
    # the points that run alone (None: none yet): those refused, where an estimate refused any
    loop = None if refused is None or not refused.any() else refused.copy()
    counts_of_groups: dict[str, int] = {}
    bad_total = 0
    for k, sel in groups:
        m = n if sel is None else int(np.count_nonzero(sel))
        if not m:
            continue
        whole = m == n
        sub = x if whole or sel is None else points.take(x, n, sel)
        try:
            with _arithmetic_refused(spec):
                vec = points.vector(
                    spec,
                    sub,
                    spec.rung_names[k],
                    scalar_names,
                    tol,
                    m,
                    dtype=None,
                    scratch=scratch if whole else None,
                    read_checks=False,  # a sweep keeps the outputs, not the checks
                )
        except SolverFailed:
            vec = None  # loop instead: the points that fail are null, with a note
        except EngineError:
            raise
        except Exception:
            # the array path is an optimisation and the scalar model the reference: where
            # the array path fails on inputs the scalar one refuses or handles (fuzzing
            # found one), the loop answers
            vec = None
        if vec is None:
            if loop is None:
                loop = np.zeros(n, dtype=bool)
            if sel is None:
                loop[:] = True
            else:
                loop |= sel
            continue
        # a point the array path refuses is NaN in every float output it computed (the
        # study's rule); one NaN beside finite outputs is a null the scalar path gives too
        some_finite: np.ndarray | None = None
        every_finite = False
        for name in scalar_names:
            if name not in vec.computed:
                continue
            column = vec.values[name]
            computed[name] = None
            if column.dtype.kind == "f" and not every_finite:
                # no NaN in it (the model tested it, or a pass here): every point has a value
                if name in vec.finite or points.all_finite(column):
                    every_finite = True
                else:
                    finite = np.isfinite(column)
                    some_finite = finite if some_finite is None else some_finite | finite
                    every_finite = bool(some_finite.all())
            _put(columns, name, column, sel, whole)
        bad = None if some_finite is None or every_finite else ~some_finite
        if codes is None and one_rung is None and whole and bad is None:
            one_rung = k  # the common case: one rung ran at every point
        else:
            if codes is None:
                codes = _codes_so_far(n, one_rung)
            codes[slice(None) if whole else sel] = k if bad is None else np.where(bad, -1, k)
        given.append((k, None if whole else sel, bad))
        refused_here = 0 if bad is None else int(np.count_nonzero(bad))
        if m > refused_here:
            counts_of_groups[spec.rung_names[k]] = m - refused_here
        bad_total += refused_here
        for note in vec.notes:
            if note not in notes:
                notes.append(note)
        for w in vec.warnings:
            if w not in warnings:
                warnings.append(w)
    if bad_total:
        notes.append(f"{bad_total} of {n} points could not be computed; null there")
    deadline = None if budget_s is None else start + budget_s
    first_refusal: EngineError | None = None
    looped = [] if loop is None else np.flatnonzero(loop).tolist()
    if codes is None and (one_rung is None or looped):
        # no group gave values (the loop sets the points it computes), or points loop
        codes = _codes_so_far(n, one_rung)
    any_point = n - len(looped) > 0
    for count, j in enumerate(looped):
        if cancel is not None and cancel.is_set():
            raise Cancelled(f"sweep cancelled after {n - len(looped) + count} of {n} points")
        remaining = None if deadline is None else deadline - time.perf_counter()
        if remaining is not None and remaining <= 0:
            raise BudgetExceeded(
                f"sweep stopped after {n - len(looped) + count} of {n} points at its "
                f"{budget_s:g} s budget",
                field="num",
            )
        value = arr[j].item()
        try:
            point = run(
                spec,
                {**base, vary: value},
                fidelity=asked
                if index is None or refused is None or refused[j]
                else spec.rung_names[int(index[j])],
                tolerance=tolerance,
                outputs=wanted,
                budget_s=remaining,
                max_steps=max_steps,
                cancel=cancel,
            )
        except Cancelled:
            raise  # the whole sweep was withdrawn, not this point refused
        except EngineError as exc:
            # a point the model refuses (infeasible, or a cross-field range that this
            # value breaks) is null; if every point is refused, the first refusal stands
            first_refusal = first_refusal or exc
            notes.append(f"{vary} = {value:g}: {exc.message}")
            continue
        any_point = True
        if point.rung not in names:
            names.append(point.rung)
        assert codes is not None  # made above wherever points loop
        codes[j] = names.index(point.rung)
        looped_errors[j] = np.nan if point.error_estimate is None else point.error_estimate
        for name, v in point.results.items():
            computed[name] = None
            _set(columns, name, j, v, n)
        for w in point.warnings:
            if w not in warnings and not w.startswith(f"{vary} = "):
                warnings.append(w)
    if not any_point:
        if isinstance(first_refusal, InputOutOfRange) and first_refusal.field != vary:
            raise first_refusal  # the fixed inputs themselves are out of range
        notes.append("no point of the sweep could be computed")
    order = [o for o in scalar_names if o in computed] + [o for o in computed if o not in known]
    # one array group and no loop: its count is known; else count the codes
    counts = (
        counts_of_groups
        if codes is None or (not looped and len(given) <= 1)
        else _rung_counts(codes, names)
    )
    rung, mixed = _rung_summary(counts)
    if asked == "auto" and not mixed and rung:
        notes.insert(0, f"auto: chose {rung!r} at every point (tolerance {tol:.2g})")
    for name in counts:
        ran = _declared(spec, name)
        if ran is not None and ran.estimate_caveat and ran.estimate_caveat not in notes:
            notes.append(ran.estimate_caveat)  # the points it ran at: ``rungs``
    units = spec.units  # the spec's own table: read here, not changed
    # a large sweep does not keep its array path's work alive for its estimates
    kept = scratch if n <= MAX_SWEEP_POINTS else None

    def errors() -> np.ndarray:
        """Each point's error estimate: the array groups' rungs at their points, the
        looped points' own (NaN where refused or not known)."""
        found = estimates
        if found is None:
            found = points.rung_estimates(
                spec,
                x,
                n,
                [k for k, _, _ in given],
                point=lambda j: points.at(x, n, j),
                refused=np.zeros(n, dtype=bool),
                scratch=Scratch() if kept is None else kept,
            )
            assert found is not None
        out = np.full(n, np.nan)
        for k, sel, bad in given:
            est = found.get(k)
            if est is None:
                continue
            part = est if sel is None else est[sel]
            out[slice(None) if sel is None else sel] = (
                part if bad is None else np.where(bad, np.nan, part)
            )
        for j, e in looped_errors.items():
            out[j] = e
        return out

    later: Callable[[], np.ndarray] | None = None
    if codes is None:  # one rung at every point, no point looped: the codes made when read
        assert one_rung is not None
        later = functools.partial(_one_rung, n, one_rung)
    result = SweepResult._of(
        errors,
        later,
        model=spec.name,
        vary=vary,
        value_array=arr,
        columns={name: columns[name] for name in order},
        units={name: units[name] for name in order},
        rung=rung,
        elapsed_s=time.perf_counter() - start,
        notes=mixed + notes,
        warnings=warnings,
        rung_codes=codes,
        rung_names=tuple(names),
    )
    if estimates is not None:
        result.error_array  # noqa: B018  (auto's estimates are made: keep the errors, not them)
    return result


def _codes_so_far(n: int, one_rung: int | None) -> np.ndarray:
    """The rung codes of a sweep's ``n`` points where they are first written: ``one_rung``
    at every point where one rung has run at all of them, else -1 (none given yet).

    >>> _codes_so_far(2, None), _codes_so_far(2, 1)
    (array([-1, -1], dtype=int8), array([1, 1], dtype=int8))
    """
    return np.full(n, -1, dtype=np.int8) if one_rung is None else _one_rung(n, one_rung)


def _one_rung(n: int, k: int) -> np.ndarray:
    """The rung codes of ``n`` points that all ran rung ``k``, written once (``k`` != 0)
    or not at all where ``k`` is 0 (the first rung, the common case) and the pages are
    fresh.

    Zeros are the allocator's (``calloc``): a large column taken fresh from the kernel is
    mapped when first read, not written here (from a warm heap, calloc clears it: one
    pass); a column filled with -1 and then given ``k`` was written twice over.

    >>> _one_rung(3, 0), _one_rung(2, 1)
    (array([0, 0, 0], dtype=int8), array([1, 1], dtype=int8))
    """
    return np.zeros(n, dtype=np.int8) if k == 0 else np.full(n, k, dtype=np.int8)


def _objects(column: np.ndarray) -> np.ndarray:
    """A float column as an object column, None where it was NaN or infinite."""
    out = column.astype(object)
    out[~np.isfinite(column)] = None
    return out


def _put(
    columns: dict[str, np.ndarray],
    name: str,
    part: np.ndarray,
    sel: np.ndarray | None,
    whole: bool,
) -> None:
    """One rung group's column ``part`` written at the points ``sel`` of ``columns[name]``
    (every point where ``whole``; ``sel`` may then be None).

    A float column stays float (NaN where no group or point gave a value); a text, flag
    or integer column that misses points becomes an object column (None there).
    """
    have = columns.get(name)
    floats = part.dtype.kind == "f"
    if have is None:
        if whole:
            columns[name] = part  # the common case: the array path's own column, no copy
            return
        assert sel is not None
        n = sel.shape[0]
        have = columns[name] = np.full(n, np.nan) if floats else np.full(n, None, dtype=object)
    elif have.dtype.kind == "f" and not floats:
        have = columns[name] = _objects(have)
    at = slice(None) if sel is None else sel
    if have.dtype.kind == "f":
        have[at] = part
    else:
        have[at] = _objects(part) if floats else part.astype(object)


def _set(columns: dict[str, np.ndarray], name: str, j: int, value: Value, n: int) -> None:
    """A looped point's ``value`` of output ``name`` (NaN or None where null)."""
    plain = value is None or type(value) is float
    have = columns.get(name)
    if have is None:
        have = columns[name] = np.full(n, np.nan) if plain else np.full(n, None, dtype=object)
    elif have.dtype.kind == "f":
        if not plain:
            have = columns[name] = _objects(have)
    elif have.dtype != object:  # a column one array group gave whole: no loop follows it
        have = columns[name] = have.astype(object)
    if have.dtype.kind == "f":
        have[j] = np.nan if value is None else value
    else:
        have[j] = value


def _sweep_column(param: Param, values: Sequence[float]) -> tuple[np.ndarray, float, float]:
    """The swept values as an array, with their least and largest value; refused (naming
    the first bad value) if any is out of range.

    The common case, every value finite and within the range, is told by the least and
    the largest value alone (a NaN makes both NaN); only otherwise is each value tested.
    """
    # a copy, the sweep's own: a named rung's estimates are made from these values when
    # first read, and the caller may have changed its array by then; a long float array is
    # copied with its ends read on the way (one pass over the values, not three). -0.0 is
    # folded to 0.0, as a single run's check folds it: one answer for one input
    if (
        isinstance(values, np.ndarray)
        and values.dtype == np.float64
        and values.ndim == 1
        and values.size > points.FINITE_BLOCK
    ):
        arr, low, high = points.copy_with_ends(values)
    else:
        arr = np.array(values, dtype=float)
        if arr.ndim != 1 or arr.size == 0:
            raise InputOutOfRange(f"a sweep of {param.name} needs at least one value", field="num")
        arr += 0.0  # -0.0 folded (x + 0.0 is x for every other value)
        low, high = float(arr.min()), float(arr.max())
    inside = bool(points.in_range(param, np.array([low, high])).all())
    if not inside or param.kind == "int":
        bad = ~points.in_range(param, arr)
        if param.kind == "int":
            bad |= arr != np.round(arr)
        if bad.any():
            v = arr[int(np.flatnonzero(bad)[0])].item()
            if param.kind == "int" and math.isfinite(v) and v == round(v):
                v = int(v)
            param.check(v)  # raises with the field's range
            raise InputOutOfRange(f"{param.name} = {v!r} is not allowed", field=param.name)
    return (arr.astype(np.int64) if param.kind == "int" else arr), low, high


def _recommended(param: Param, arr: np.ndarray, low: float, high: float) -> list[str]:
    """One warning for the swept values outside the source's recommended range (``low`` and
    ``high``: the least and largest of ``arr``)."""
    if not param.recommended:
        return []
    lo, hi = param.recommended
    if lo <= low and high <= hi:
        return []
    out = (arr < lo) | (arr > hi)
    unit = "" if param.unit == "1" else f" {param.unit}"
    return [
        f"{param.name} is outside the range the source recommends ({lo:g}…{hi:g}{unit}) at "
        f"{int(out.sum())} of {arr.size} points"
    ]
