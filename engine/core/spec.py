"""How a model declares itself: inputs, outputs, rungs, and the result it returns.

A :class:`ModelSpec` is the one source of truth for a model's inputs, their SI
units, defaults and valid ranges. The service builds its request schema, the
form builds its fields and the docs list the model from the same object; the
engine enforces the same ranges in :meth:`ModelSpec.validate`, so a direct
Python caller gets the same checks as a REST caller.

Units are SI base units written in a syntax the unit library at the edge can
parse: ``m``, ``kg``, ``s``, ``N``, ``N*m``, ``Pa``, ``rad``, ``rad/s``,
``W``, ``J``, ``N/m``, ``N*m/rad``, ``kg*m^2``; ``1`` means dimensionless.
"""

from __future__ import annotations

import functools
import math
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Literal

from .equations import equations_of, equations_of_steps
from .errors import BudgetExceeded, Cancelled, InputOutOfRange
from .sources import SOURCES, cited_ids
from .text import Parts, parts

ParamKind = Literal["float", "int", "choice", "bool", "text", "samples"]
#: Longest value a ``text`` input accepts (a designation such as "M10x1.25 ISO 4762 12.9").
MAX_TEXT_LENGTH = 64
#: Fewest and most values a ``samples`` input accepts unless its declaration says otherwise.
MIN_SAMPLES = 2
MAX_SAMPLES = 10_000
#: The types of a list of JSON numbers that :meth:`Param._check_samples` checks whole.
_FLOATS = frozenset({float})
OutputKind = Literal["float", "int", "bool", "str"]
#: A check of a standard's requirement fails the design; advice (a rule of thumb, a
#: recommendation) only warns.
CheckLevel = Literal["requirement", "advice"]
Value = float | int | bool | str | None


@dataclass(frozen=True)
class Param:
    """One named input of a model.

    ``minimum``/``maximum`` are the hard range (refused outside it, in SI
    units); ``recommended`` is the range the source recommends (a warning
    outside it). A param with ``default=None`` and ``required=False`` is
    optional: absent means "not given", and the model decides what that means.
    A ``text`` param takes a free string of at most :data:`MAX_TEXT_LENGTH`
    characters (a fastener designation); its ``choices`` are suggestions, not
    a limit, and the model parses the text (InputOutOfRange naming the field).
    A ``samples`` param takes a list of ``min_length``…``max_length`` finite
    numbers in its one ``unit`` (measured torques), each within ``minimum`` and
    ``maximum``; it is checked into a tuple of floats, and a refusal names the
    index of the first bad value. It is not numeric: sweeps and studies refuse it.

    >>> p = Param("torques", "N*m", "measured torques", kind="samples", minimum=0.0)
    >>> p.check([10, 10.5, 9.75])
    (10.0, 10.5, 9.75)
    >>> p.range_text()
    'a list of 2 to 10000 finite numbers ≥ 0 N*m'
    >>> try:
    ...     p.check([10.0, -1.0])
    ... except InputOutOfRange as exc:
    ...     print(exc.message)
    torques[1] = -1 N*m is not allowed: must be a list of 2 to 10000 finite numbers ≥ 0 N*m
    """

    name: str
    unit: str
    description: str
    default: float | int | str | bool | None = None
    required: bool = False
    minimum: float | None = None
    maximum: float | None = None
    exclusive_minimum: bool = False
    exclusive_maximum: bool = False
    recommended: tuple[float, float] | None = None
    kind: ParamKind = "float"
    choices: tuple[str, ...] = ()
    label: str | None = None
    symbol: str | None = None
    display_unit: str | None = None
    group: str | None = None
    #: Readable names of ``choices``, in the same order (optional; the form shows them).
    choice_labels: tuple[str, ...] = ()
    #: For a ``samples`` param: the fewest and the most values it takes.
    min_length: int = MIN_SAMPLES
    max_length: int = MAX_SAMPLES
    #: The input this one takes effect with: while that one is not given, this one changes
    #: nothing (the form disables it and says so). ``"name=value"``: only while that choice
    #: input has that value (a disc pack's inputs with ``spring_kind`` "disc_pack").
    used_with: str | None = None

    @property
    def used_with_input(self) -> str | None:
        """The name of the input this one takes effect with (``used_with`` up to ``=``)."""
        return None if self.used_with is None else self.used_with.split("=", 1)[0]

    @property
    def used_with_value(self) -> str | None:
        """The choice of :attr:`used_with_input` this one takes effect at, if one is named."""
        if self.used_with is None or "=" not in self.used_with:
            return None
        return self.used_with.split("=", 1)[1]

    @property
    def is_numeric(self) -> bool:
        """A single number (``float`` or ``int``): what a sweep or a study may vary."""
        return self.kind in ("float", "int")

    @property
    def has_unit(self) -> bool:
        """Whether values of this param carry its unit (a number or a list of numbers)."""
        return self.kind in ("float", "int", "samples")

    def range_text(self) -> str:
        """The allowed range in words, e.g. ``> 0 m and ≤ 1 m``."""
        if self.kind == "choice":
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.kind == "text":
            shown = ", ".join(repr(c) for c in self.choices[:3])
            return f"a text of at most {MAX_TEXT_LENGTH} characters" + (
                f", e.g. {shown}" if shown else ""
            )
        if self.kind == "bool":
            return "true or false"
        unit = "" if self.unit == "1" else f" {self.unit}"
        parts: list[str] = []
        if self.minimum is not None:
            parts.append(f"{'>' if self.exclusive_minimum else '≥'} {self.minimum:g}{unit}")
        if self.maximum is not None:
            parts.append(f"{'<' if self.exclusive_maximum else '≤'} {self.maximum:g}{unit}")
        what = {
            "int": "an integer",
            "samples": f"a list of {self.min_length} to {self.max_length} finite numbers",
        }.get(self.kind, "a finite number")
        return what + (" " + " and ".join(parts) if parts else "")

    def check(self, value: Any) -> Any:
        """Return ``value`` converted to this param's kind, or raise InputOutOfRange."""
        kind = self.kind
        if type(value) is float and kind == "float":  # the common case: a JSON number
            if not -math.inf < value < math.inf:  # NaN and ±inf
                raise self._error(value)
            if value == 0.0:
                value = 0.0  # fold -0.0
        elif kind != "float" and kind != "int":  # numbers first: most inputs are numbers
            return self._check_other(value)
        elif isinstance(value, bool) or not isinstance(value, int | float):
            raise self._error(value)
        elif kind == "int":
            if isinstance(value, float):
                if not value.is_integer():
                    raise self._error(value)
                value = int(value)
        else:
            try:
                value = float(value)
            except OverflowError:  # an integer literal of 309+ digits
                raise self._error(value) from None
            if not math.isfinite(value):
                raise self._error(value)
            if value == 0.0:
                value = 0.0  # fold -0.0
        lo, hi = self.minimum, self.maximum
        if lo is not None and (value <= lo if self.exclusive_minimum else value < lo):
            raise self._error(value)
        if hi is not None and (value >= hi if self.exclusive_maximum else value > hi):
            raise self._error(value)
        return value

    def _check_other(self, value: Any) -> Any:
        """:meth:`check` for a choice, a flag, a text or a list of samples."""
        if self.kind == "choice":
            if value not in self.choices:
                raise self._error(value)
            return value
        if self.kind == "bool":
            if not isinstance(value, bool):
                raise self._error(value)
            return value
        if self.kind == "text":
            if not isinstance(value, str) or not value.strip() or len(value) > MAX_TEXT_LENGTH:
                raise self._error(value)
            return value.strip()
        return self._check_samples(value)

    def _check_samples(self, value: Any) -> tuple[float, ...]:
        """A list of numbers checked as each of its values would be checked alone; the
        refusal names the first bad index.

        A list of floats only (what JSON gives) is checked whole, in C loops: finite if its
        sum is, within the range if its least and greatest values are; -0.0 folded as
        :meth:`check` folds it. Anything else, or a list refused, is checked value by
        value: a measured trace of 997 torques and angles took 110 µs a list that way,
        ~40 µs whole (checked twice a request: the service's reader and the engine's
        validation). tests/engine/test_samples_check.py holds the two to the same answers.
        """
        if isinstance(value, str | bytes) or not isinstance(value, list | tuple):
            raise self._error(value)
        n = len(value)
        if not self.min_length <= n <= self.max_length:
            raise InputOutOfRange(
                f"{self.name} has {n} value{'' if n == 1 else 's'}: must be {self.range_text()}",
                field=self.name,
                min_length=self.min_length,
                max_length=self.max_length,
                unit=self.unit,
            )
        one = self._each
        if set(map(type, value)) == _FLOATS:  # a JSON list of numbers: all of it at once
            total = sum(value)  # not finite if one value is NaN or ±inf (or on an overflow)
            if -math.inf < total < math.inf:
                try:  # every value within the range if the least and the greatest are
                    one.check(min(value))
                    one.check(max(value))
                except InputOutOfRange:
                    pass  # the value by value check below names the first one refused
                else:
                    # as check() gives each: the value itself, -0.0 folded
                    if 0.0 in value:
                        return tuple(0.0 if v == 0.0 else v for v in value)
                    return tuple(value)
        checked = []
        for i, item in enumerate(value):
            try:
                checked.append(one.check(item))
            except InputOutOfRange as exc:
                raise self._error(item, index=i) from exc
        return tuple(checked)

    @functools.cached_property
    def _each(self) -> Param:
        """What each value of a samples list is checked as: a number of this range. Made on
        the first list checked and kept (a list of 5 values took ~4 µs more making it
        again)."""
        return replace(self, kind="float")

    def advice(self, value: Any) -> list[str]:
        """A warning if a checked ``value`` lies outside the source's recommended range."""
        if not (self.recommended and self.is_numeric):
            return []
        lo, hi = self.recommended
        if lo <= value <= hi:
            return []
        unit = "" if self.unit == "1" else f" {self.unit}"
        return [
            f"{self.name} = {value:g}{unit} is outside the range the source "
            f"recommends ({lo:g}…{hi:g}{unit})"
        ]

    def _error(self, value: Any, index: int | None = None) -> InputOutOfRange:
        shown = f"{value:g}" if isinstance(value, float) else repr(value)
        if isinstance(value, int) and len(shown) > 20:
            shown = f"an integer of {len(shown)} digits"
        listed = self.kind == "samples" and not isinstance(value, int | float)
        if listed and index is None:  # the whole value refused (not a list): say what it was
            kind = "a list" if isinstance(value, list | tuple) else type(value).__name__
            shown = f"{kind} of {len(value)} values" if kind == "a list" else f"a {kind}"
        elif listed and len(shown) > 40:  # one value of the list, not a number
            shown = shown[:37] + "..."
        unit = "" if self.unit == "1" or not self.has_unit or listed else f" {self.unit}"
        where = self.name if index is None else f"{self.name}[{index}]"
        extra = {} if index is None else {"index": index}
        return InputOutOfRange(
            f"{where} = {shown}{unit} is not allowed: must be {self.range_text()}",
            field=self.name,
            **extra,
            minimum=self.minimum,
            maximum=self.maximum,
            exclusive_minimum=self.exclusive_minimum,
            exclusive_maximum=self.exclusive_maximum,
            unit=self.unit,
        )

    def describe(self) -> dict[str, Any]:
        """JSON-ready description for the model catalogue."""
        return {
            "name": self.name,
            "label": self.label or self.name.replace("_", " "),
            "symbol": self.symbol,
            "kind": self.kind,
            "unit": self.unit,
            "display_unit": self.display_unit or self.unit,
            "default": self.default,
            "required": self.required,
            "minimum": self.minimum,
            "maximum": self.maximum,
            "exclusive_minimum": self.exclusive_minimum,
            "exclusive_maximum": self.exclusive_maximum,
            "recommended": list(self.recommended) if self.recommended else None,
            "choices": list(self.choices) or None,
            "choice_labels": list(self.choice_labels) or None,
            "range": self.range_text(),
            "group": self.group,
            "description": self.description,
            "used_with": self.used_with,
            **(
                {"min_length": self.min_length, "max_length": self.max_length}
                if self.kind == "samples"
                else {}
            ),
        }


@dataclass(frozen=True)
class Window:
    """A span to shade on a chart: between the values of two scalar outputs."""

    label: str
    #: Scalar outputs in the unit of the chart's x axis (e.g. "engagement_start").
    start: str
    end: str

    def describe(self) -> dict[str, Any]:
        return {"label": self.label, "start": self.start, "end": self.end}


@dataclass(frozen=True)
class Plot:
    """How the form draws a series output (it reads this instead of guessing from names).

    A series is drawn against the series its :attr:`Output.x` names; curves with
    the same x series and unit share a chart. ``bars`` draws it as a histogram
    (its x series holds bin centres, or bin edges one longer). ``windows`` on an
    x-axis series shades those spans on every chart drawn against it.
    """

    bars: bool = False
    windows: tuple[Window, ...] = ()

    def describe(self) -> dict[str, Any]:
        return {"bars": self.bars, "windows": [w.describe() for w in self.windows]}


@dataclass(frozen=True)
class Output:
    """One named result of a model (scalar) or one time series (``series=True``)."""

    name: str
    unit: str
    description: str
    kind: OutputKind = "float"
    series: bool = False
    label: str | None = None
    display_unit: str | None = None
    #: For a series: the name of the series it is plotted against (e.g. "time").
    x: str | None = None
    #: For a series: how the form draws it (histogram, shaded windows).
    plot: Plot | None = None
    #: The symbol as the standard or source writes it ("F_M,zul", "Φ*_en", "ω_M"; the
    #: first "_" starts the subscript); "" for a count, a flag or a label; None: undeclared.
    symbol: str | None = None
    #: The step or equation it comes from, citing a source of :mod:`engine.core.sources`
    #: ("VDI 2230-1 R7", "[004, eq. 13]", "EN 13906-1 eq. (8)"); "" only with symbol "".
    step: str | None = None

    def describe(self) -> dict[str, Any]:
        """The catalogue's entry (``GET /api/v1/models``).

        >>> o = Output("permissible_preload", "N", "R7: F_M,zul = ν R_p0.2 A_0/β",
        ...            symbol="F_M,zul", step="VDI 2230-1 R7")
        >>> {k: o.describe()[k] for k in ("label", "symbol", "step")}
        {'label': 'permissible preload', 'symbol': 'F_M,zul', 'step': 'VDI 2230-1 R7'}
        """
        return {
            "name": self.name,
            "label": self.label or self.name.replace("_", " "),
            "kind": self.kind,
            "series": self.series,
            "x": self.x,
            "plot": self.plot.describe() if self.plot else None,
            "unit": self.unit,
            "display_unit": self.display_unit or self.unit,
            "description": self.description,
            "symbol": self.symbol or "",
            "step": self.step or "",
        }


class Scratch:
    """Work one request shares between its steps, for the inputs of that request only.

    The runner makes one for each :func:`engine.run` (its rung estimates and its
    compute) and one for each array evaluation of a sweep chunk; it dies with the
    request, so nothing a model leaves here reaches another request. A model keys what
    it leaves by a name of its own (the inputs are the request's, the same for every
    step that sees this scratch):

    >>> s = Scratch()
    >>> calls = []
    >>> s.once("bolt", lambda: calls.append(1) or 42), s.once("bolt", lambda: 0), calls
    (42, 42, [1])
    """

    __slots__ = ("_memo",)

    def __init__(self) -> None:
        self._memo: dict[str, Any] = {}

    def once(self, key: str, compute: Callable[[], Any]) -> Any:
        """``compute()`` the first time ``key`` is asked for in this request, then its value."""
        memo = self._memo
        if key in memo:
            return memo[key]
        value = memo[key] = compute()
        return value

    def get(self, key: str) -> Any:
        """What :meth:`once` keeps under ``key``, None where nothing was computed yet (and
        nothing is computed here)."""
        return self._memo.get(key)


@dataclass(frozen=True)
class Rung:
    """One way of computing a model, cheapest first in :attr:`ModelSpec.rungs`.

    ``estimate`` gives the a-priori relative error for given inputs, or None
    where the rung does not apply to them (``fidelity: "auto"`` skips it).
    ``estimate_kind`` says what that number promises: ``"bound"``, the result lies
    within it for every design in the declared ranges (measured against a reference
    at least 100× tighter over random designs: docs/accuracy.md); ``"typical"``, it
    usually does, and ``typical_exceeded`` says how often it does not.

    >>> r = Rung("closed_form", "algebra", lambda x: 0.01, estimate_kind="typical",
    ...          typical_exceeded="18 % of 158 random designs (worst 62×)")
    >>> for part in r.estimate_caveat.split(": "):
    ...     print(part)
    the error estimate of 'closed_form' is typical, not a bound
    exceeded in 18 % of 158 random designs (worst 62×)
    >>> Rung("exact", "closed form", lambda x: 0.0).estimate_caveat
    ''
    """

    name: str
    description: str
    estimate: Callable[[Mapping[str, Any]], float | None]
    typical_error: str = ""
    typical_time: str = ""
    #: Milliseconds or more per call (a simulation, an iteration): the service runs it in
    #: its heavy lane, so cheap rungs never queue behind it.
    heavy: bool = False
    #: A rung the runner runs instead when this one declines up front for lack of
    #: budget (BudgetExceeded with ``expected_steps``: it would need more steps than
    #: allowed), provided that rung's estimated error for these inputs is no larger
    #: than this one's. The result names the rung that ran and says why.
    fallback: str | None = None
    #: ``"bound"``: ``estimate`` bounds the error; ``"typical"``: it is exceeded for some
    #: designs, as ``typical_exceeded`` states.
    estimate_kind: Literal["bound", "typical"] = "bound"
    #: For a typical estimate, how often random designs in the declared ranges exceed it,
    #: measured (bench/accuracy_*.py), written to follow "exceeded in": e.g.
    #: "18 % of 158 random designs (worst 62×)".
    typical_exceeded: str = ""

    def __post_init__(self) -> None:
        if self.estimate_kind not in ("bound", "typical"):
            raise ValueError(
                f"rung {self.name!r}: estimate_kind = {self.estimate_kind!r} is not allowed: "
                "must be 'bound' or 'typical'"
            )
        if self.typical_exceeded and self.estimate_kind != "typical":
            raise ValueError(
                f"rung {self.name!r}: typical_exceeded is stated for an estimate declared a bound"
            )

    @property
    def estimate_caveat(self) -> str:
        """The sentence a result carries when this rung's estimate is typical ("" for a bound)."""
        if self.estimate_kind == "bound":
            return ""
        how_often = (
            f"exceeded in {self.typical_exceeded}"
            if self.typical_exceeded
            else "how often it is exceeded is not measured"
        )
        return f"the error estimate of {self.name!r} is typical, not a bound: {how_often}"

    #: ``estimate`` with the request's :class:`Scratch`: work it does for the inputs (a
    #: resolved bolt, a cycle) is left there for the compute of the same request. When
    #: given, the runner calls this instead of :attr:`estimate` (which then serves
    #: callers without a request, as the same function on a scratch of its own).
    shared_estimate: Callable[[Mapping[str, Any], Scratch], Any] | None = None
    #: The procedure this rung runs, in its order: the functions (a procedure's steps,
    #: the adapter's output lines) whose equations, and their callees', the calculation
    #: report lists when this rung produced the result. Empty: the model's compute,
    #: every rung's steps together.
    steps: tuple[Callable[..., Any], ...] = ()

    def estimate_in(self, inputs: Mapping[str, Any], scratch: Scratch) -> Any:
        """The estimate for ``inputs`` within a request whose work ``scratch`` holds."""
        if self.shared_estimate is None:
            return self.estimate(inputs)
        return self.shared_estimate(inputs, scratch)

    def describe(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "description": self.description,
            "typical_error": self.typical_error,
            "typical_time": self.typical_time,
            "fallback": self.fallback,
            "estimate_kind": self.estimate_kind,
            "typical_exceeded": self.typical_exceeded,
            # the equations of this rung's steps, for the report of a result it produced
            **(
                {"equations": [dict(e) for e in equations_of_steps(self.steps)]}
                if self.steps
                else {}
            ),
        }


@dataclass(frozen=True)
class Check:
    """A design condition and whether this design meets it, with an actionable sentence.

    ``level`` says what a failure means: ``"requirement"`` (a standard's or the
    source's condition: the design fails) or ``"advice"`` (a rule of thumb or a
    recommendation: a warning). The runner sets it from :attr:`ModelSpec.advice`.
    """

    name: str
    ok: bool
    detail: str
    level: CheckLevel = "requirement"
    #: ``detail`` as the model wrote it, its quantities marked (:func:`engine.core.text.q`):
    #: the runner keeps it here and gives ``detail`` plain; "" when the two are the same.
    marked: str = field(default="", compare=False, repr=False)

    @property
    def detail_parts(self) -> Parts:
        """``detail`` as text and quantities (:func:`engine.core.text.parts`)."""
        return parts(self.marked or self.detail)


@dataclass(frozen=True)
class Answer:
    """One number that answers a model's question, for the answer card above the results.

    ``output`` is a scalar output; ``symbol`` its symbol in the standard; ``check`` the
    check that judges it (its verdict shown beside it), and ``relation`` with ``bound``
    the required value: a number in the output's unit or the name of another output
    (``"≥", "required_clamp_force"`` reads "≥ F_K,erf"), ``bound_symbol`` its symbol.
    """

    output: str
    symbol: str
    check: str | None = None
    relation: Literal["≥", "≤", ""] = ""
    bound: float | str | None = None
    bound_symbol: str | None = None

    def describe(self) -> dict[str, Any]:
        return {
            "output": self.output,
            "symbol": self.symbol,
            "check": self.check,
            "relation": self.relation or None,
            "bound": self.bound,
            "bound_symbol": self.bound_symbol,
        }


@dataclass
class Result:
    """What a model's compute function returns (the runner adds timing and units)."""

    values: dict[str, Value]
    rung: str
    error_estimate: float | None
    checks: list[Check] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    series: dict[str, list[float]] = field(default_factory=dict)
    #: Array paths only (:attr:`ModelSpec.vectorized`): per check name, which points pass,
    #: as a bool array (or int8: 1 passes, 0 fails, -1 does not apply at that point).
    #: The same names and verdicts the scalar compute gives in ``checks`` point by point.
    check_arrays: dict[str, Any] = field(default_factory=dict)
    #: Array paths only: the float columns of ``values`` the path has tested and found to
    #: hold no NaN nor inf at any point; a caller need not test them again (a pass over
    #: the points each).
    finite: frozenset[str] = frozenset()
    #: Where the caller reads no sentences (:attr:`RunContext.sentences` False): the checks'
    #: verdicts as (name, passes) pairs, in place of ``checks`` (a :class:`Check` costs
    #: about a µs to make, which a study's looped point paid six times for two values).
    verdicts: list[tuple[str, bool]] | None = None


@dataclass(frozen=True)
class RunContext:
    """What a compute function is asked for beyond the inputs.

    ``outputs`` is the set of output (and series) names the caller wants;
    compute only what they need. ``deadline`` is a ``time.perf_counter()``
    value after which long computations raise BudgetExceeded.
    """

    rung: str
    outputs: frozenset[str]
    tolerance: float
    deadline: float | None = None
    max_steps: int = 1_000_000
    #: Set by the caller to withdraw the request; long computations test it where they
    #: test ``deadline`` (:meth:`check_budget`) and raise :class:`Cancelled`.
    cancel: threading.Event | None = None
    #: The request's shared work (:class:`Scratch`): a step computed once for the
    #: estimate and the compute of one request, gone when the request is.
    scratch: Scratch = field(default_factory=Scratch)
    #: Whether the caller reads the checks: a sweep reports none (it keeps the outputs),
    #: so an array path may leave out the work only its checks need.
    checks: bool = True
    #: Whether the caller reads the sentences (notes, warnings, the checks' details): a
    #: study's looped points keep the values and the verdicts alone
    #: (:func:`engine.core.runner.run_point`), so a compute may leave the sentences out
    #: and give :attr:`Result.verdicts` for its checks, and leave out the error estimate
    #: too (None: such a caller does not read it); its values may then be as computed (inf,
    #: NaN, numpy scalars), which :func:`engine.core.runner.run_point` converts as a run
    #: does.
    sentences: bool = True
    #: What the model's :attr:`ModelSpec.prepare_points` made for this point of a study's
    #: chunk (None: nothing; the compute works it out itself).
    prepared: Any = None

    @classmethod
    def of_request(
        cls,
        rung: str,
        outputs: frozenset[str],
        tolerance: float,
        deadline: float | None,
        max_steps: int,
        cancel: threading.Event | None,
        scratch: Scratch,
        *,
        sentences: bool = True,
        prepared: Any = None,
    ) -> RunContext:
        """The context of one request, checks read (and the sentences, unless
        ``sentences`` is False: a study's looped point): equal to
        ``RunContext(rung, outputs, ...)`` with these fields, made by filling its fields at
        once where the frozen dataclass's constructor sets them one ``object.__setattr__``
        at a time (1.0 against 0.3 µs, on each :func:`engine.run` and study point).

        >>> s = Scratch()
        >>> made = RunContext.of_request("closed_form", frozenset({"a"}), 0.01, None, 5, None, s)
        >>> made == RunContext("closed_form", frozenset({"a"}), 0.01, None, 5, None, s)
        True
        >>> RunContext.of_request("a", frozenset(), 0.01, None, 5, None, s, sentences=False) == (
        ...     RunContext("a", frozenset(), 0.01, None, 5, None, s, sentences=False))
        True
        """
        self = object.__new__(cls)
        self.__dict__.update(
            rung=rung,
            outputs=outputs,
            tolerance=tolerance,
            deadline=deadline,
            max_steps=max_steps,
            cancel=cancel,
            scratch=scratch,
            checks=True,
            sentences=sentences,
            prepared=prepared,
        )
        return self

    def once(self, key: str, compute: Callable[[], Any]) -> Any:
        """``compute()`` once per request: :meth:`Scratch.once` of :attr:`scratch`."""
        return self.scratch.once(key, compute)

    def check_budget(self, what: str = "the computation") -> None:
        """Raise Cancelled if the caller withdrew, BudgetExceeded past the deadline."""
        if self.cancel is not None and self.cancel.is_set():
            raise Cancelled(f"{what} was cancelled: the client disconnected")
        if self.deadline is not None and time.perf_counter() > self.deadline:
            raise BudgetExceeded(f"{what} stopped at its wall-clock budget")

    def wants(self, *names: str) -> bool:
        """True if any of ``names`` was asked for."""
        return not self.outputs.isdisjoint(names)  # no generator: twice a study's point


Compute = Callable[[Mapping[str, Any], RunContext], Result]


@dataclass(frozen=True)
class ModelSpec:
    """A model: its identity, inputs, outputs, rungs and compute function."""

    #: ``<family>.<model>``; the model's URL path is derived from it (see :attr:`path`).
    name: str
    title: str
    family: str
    summary: str
    source: str
    inputs: tuple[Param, ...]
    outputs: tuple[Output, ...]
    rungs: tuple[Rung, ...]
    compute: Compute
    default_fidelity: str = "auto"
    #: Reference input sets (SI, partial: defaults fill the rest); the first is the
    #: reference case (the source's worked case where the source prints one).
    #: Benchmarks, stability tests and the form use them.
    examples: tuple[Mapping[str, Any], ...] = ()
    #: Optional array version of ``compute`` for sweeps: called with the varied
    #: input as a numpy array (others scalar); returns arrays (NaN where a point
    #: cannot be computed). Used only when the chosen rung is in ``vector_rungs``.
    vectorized: Compute | None = None
    vector_rungs: tuple[str, ...] = ()
    #: Optional: for a study's points that run one by one on a named rung
    #: (:func:`engine.studies.plan.evaluate_chunk`), the work each point's ``compute`` does
    #: from its inputs alone, made once for them: called with their validated inputs (the
    #: varied as arrays, others scalar) and the rung, it gives one entry a point (None:
    #: that point does its own), or None for all; a point's entry reaches ``compute`` as
    #: :attr:`RunContext.prepared`, at the rung asked and at its fallback (a compute reads
    #: of it what holds at the rung that runs). Called before the chunk's first point, under
    #: no error state of the chunk's: it must not raise (what it cannot make is None).
    prepare_points: Callable[[Mapping[str, Any], str], Sequence[Any] | None] | None = None
    #: Sentences true of every answer of this model (idealisations the source makes,
    #: reconstructions): the runner adds them to each result's notes, and the
    #: catalogue lists them.
    assumptions: tuple[str, ...] = ()
    #: Names of the checks that are advice (a rule of thumb, a recommendation): a failing
    #: one warns and the design still passes. Every other check is a requirement.
    advice: frozenset[str] = frozenset()
    #: The outputs that answer the model's question, in the order the answer card shows them.
    answer: tuple[Answer, ...] = ()
    #: Whose requirements the checks hold, for the verdict ("passes VDI 2230"); empty:
    #: "passes every requirement".
    requirements_of: str = ""
    #: Derived from :attr:`name`: ``clutch.ball_setting`` is served at ``/clutch/ball_setting``.
    path: str = field(init=False)
    #: Lookup tables derived once from the declaration (every :func:`engine.run` used to
    #: rebuild them: ~5 µs a call).
    _params: dict[str, Param] = field(init=False, repr=False, compare=False)
    _defaults: dict[str, Any] = field(init=False, repr=False, compare=False)
    _units: dict[str, str] = field(init=False, repr=False, compare=False)
    _scalar_outputs: frozenset[str] = field(init=False, repr=False, compare=False)
    _scalar_output_names: tuple[str, ...] = field(init=False, repr=False, compare=False)
    _series_outputs: frozenset[str] = field(init=False, repr=False, compare=False)
    _rung_names: tuple[str, ...] = field(init=False, repr=False, compare=False)
    _required: tuple[str, ...] = field(init=False, repr=False, compare=False)
    _index: dict[str, int] = field(init=False, repr=False, compare=False)
    _advised: frozenset[str] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "path", "/" + self.name.replace(".", "/"))
        scalars = tuple(o.name for o in self.outputs if not o.series)  # declaration order
        tables: dict[str, Any] = {
            "_params": {p.name: p for p in self.inputs},
            "_defaults": {p.name: None if p.required else p.default for p in self.inputs},
            "_units": {o.name: o.unit for o in self.outputs},
            "_scalar_outputs": frozenset(scalars),
            "_scalar_output_names": scalars,
            "_series_outputs": frozenset(o.name for o in self.outputs if o.series),
            "_rung_names": tuple(r.name for r in self.rungs),
            "_required": tuple(p.name for p in self.inputs if p.required),
            "_index": {p.name: i for i, p in enumerate(self.inputs)},
            # the numeric inputs with a recommended range: a warning outside it
            "_advised": frozenset(p.name for p in self.inputs if p.recommended and p.is_numeric),
        }
        for key, value in tables.items():
            object.__setattr__(self, key, value)
        names = [p.name for p in self.inputs]
        if len(set(names)) != len(names):
            raise ValueError(f"{self.name}: duplicate input names")
        reserved = {"fidelity", "tolerance", "outputs"}
        if reserved & set(names):
            raise ValueError(f"{self.name}: inputs may not use the names {sorted(reserved)}")
        if not self.rungs:
            raise ValueError(f"{self.name}: at least one rung is required")
        for p in self.inputs:
            if p.choice_labels and len(p.choice_labels) != len(p.choices):
                raise ValueError(f"{self.name}.{p.name}: one choice label per choice")
            if p.used_with_input is not None and p.used_with_input not in names:
                raise ValueError(f"{self.name}.{p.name}: used with {p.used_with!r}, no input")
            if p.used_with_value is not None:
                other = self.inputs[names.index(str(p.used_with_input))]
                if p.used_with_value not in other.choices:
                    raise ValueError(f"{self.name}.{p.name}: used with {p.used_with!r}, no choice")
        if self.default_fidelity not in ("auto", *self.rung_names):
            raise ValueError(f"{self.name}: unknown default_fidelity {self.default_fidelity!r}")
        for r in self.rungs:
            if r.fallback is not None and r.fallback not in self.rung_names:
                raise ValueError(
                    f"{self.name}: rung {r.name!r} falls back to unknown {r.fallback!r}"
                )
        outputs = {o.name: o for o in self.outputs}
        for a in self.answer:
            for end in (a.output, a.bound if isinstance(a.bound, str) else a.output):
                if end not in outputs or outputs[end].series:
                    raise ValueError(f"{self.name}: answer {a.output!r} names {end!r}, no scalar")
        for o in self.outputs:
            if o.x is not None and not (o.x in outputs and outputs[o.x].series):
                raise ValueError(
                    f"{self.name}: output {o.name!r} is plotted against {o.x!r}, no series"
                )
            for w in o.plot.windows if o.plot else ():
                for end in (w.start, w.end):
                    if end not in outputs or outputs[end].series:
                        raise ValueError(
                            f"{self.name}: window {w.label!r} names {end!r}, no scalar"
                        )

    @property
    def rung_names(self) -> tuple[str, ...]:
        return self._rung_names

    @property
    def units(self) -> dict[str, str]:
        """Each output's SI unit (the spec's own table: do not modify)."""
        return self._units

    @property
    def scalar_outputs(self) -> frozenset[str]:
        return self._scalar_outputs

    @property
    def scalar_output_names(self) -> tuple[str, ...]:
        """The scalar outputs' names in declaration order (:attr:`scalar_outputs` as a set)."""
        return self._scalar_output_names

    @property
    def series_outputs(self) -> frozenset[str]:
        return self._series_outputs

    @property
    def output_names(self) -> tuple[str, ...]:
        return tuple(o.name for o in self.outputs)

    @property
    def sources(self) -> tuple[str, ...]:
        """Ids of the sources (:mod:`engine.core.sources`) that :attr:`source` cites."""
        return tuple(sorted(cited_ids(self.source)))

    def check_level(self, name: str) -> CheckLevel:
        """``"advice"`` for a check named in :attr:`advice`, else ``"requirement"``."""
        return "advice" if name in self.advice else "requirement"

    def levelled(self, checks: list[Check]) -> list[Check]:
        """``checks`` with each one's :attr:`Check.level` as this model declares it."""
        if not self.advice:
            return checks
        advice = self.advice
        return [
            Check(c.name, c.ok, c.detail, "advice", c.marked) if c.name in advice else c
            for c in checks
        ]

    def param(self, name: str) -> Param:
        return self._params[name]

    def rung(self, name: str) -> Rung:
        for r in self.rungs:
            if r.name == name:
                return r
        raise KeyError(name)

    def validate(self, raw: Mapping[str, Any]) -> tuple[dict[str, Any], list[str]]:
        """Check SI inputs against the declared ranges and fill defaults.

        Returns the complete input dict (optional inputs that were not given
        are None) and warnings for values outside the source's recommended
        range. Raises InputOutOfRange naming the first bad field.
        """
        try:
            return self._validate_given(raw)
        except InputOutOfRange:
            pass  # name the first bad field in declaration order, as the loop below does
        values: dict[str, Any] = {}
        warnings: list[str] = []
        for key in raw:
            if key not in self._params:
                raise InputOutOfRange(f"unknown input {key!r} for model {self.name}", field=key)
        for p in self.inputs:
            given = raw.get(p.name)
            if given is None:
                if p.required:
                    raise InputOutOfRange(f"{p.name} is required", field=p.name)
                values[p.name] = p.default
                continue
            values[p.name] = p.check(given)
            warnings.extend(p.advice(values[p.name]))
        return values, warnings

    def _validate_given(self, raw: Mapping[str, Any]) -> tuple[dict[str, Any], list[str]]:
        """:meth:`validate` looking only at the inputs given (a request names a few of a
        model's 20–60): defaults copied from the spec's table, each given input checked.
        Raises on the first bad input it meets; :meth:`validate` then finds the one to name."""
        params, advised = self._params, self._advised
        values = dict(self._defaults)  # declaration order; optional inputs at their default
        advice: list[tuple[int, str]] = []
        for name, given in raw.items():
            p = params.get(name)
            if p is None:
                raise InputOutOfRange(f"unknown input {name!r} for model {self.name}", field=name)
            if given is None:
                continue
            value = values[name] = p.check(given)
            if name in advised:
                advice.extend((self._index[name], w) for w in p.advice(value))
        for name in self._required:
            if values[name] is None:
                raise InputOutOfRange(f"{name} is required", field=name)
        if not advice:  # the common case: every given value within its recommended range
            return values, []
        advice.sort(key=lambda item: item[0])
        return values, [w for _, w in advice]

    def equations(self, rung: str | None = None) -> tuple[dict[str, Any], ...]:
        """The equations the calculation report lists for a result of ``rung``, in the
        order of its procedure: the rung's declared :attr:`Rung.steps`, else (and for
        ``rung`` None) every equation the model's compute reaches."""
        steps = () if rung is None else self.rung(rung).steps
        return equations_of_steps(steps) if steps else equations_of(self.compute)

    def describe(self) -> dict[str, Any]:
        """JSON-ready catalogue entry (``GET /api/v1/models``)."""
        return {
            "name": self.name,
            "path": self.path,
            "title": self.title,
            "family": self.family,
            "summary": self.summary,
            "source": self.source,
            "sources": [
                {"id": i, "reference": SOURCES[i].reference()} for i in self.sources if i in SOURCES
            ],
            "default_fidelity": self.default_fidelity,
            "inputs": [p.describe() for p in self.inputs],
            "outputs": [o.describe() for o in self.outputs],
            "rungs": [r.describe() for r in self.rungs],
            "assumptions": list(self.assumptions),
            "advice": sorted(self.advice),
            "answer": [a.describe() for a in self.answer],
            "requirements_of": self.requirements_of,
            "examples": [dict(e) for e in self.examples],
            # read from the engine functions' docstrings, for the calculation report
            "equations": [dict(e) for e in self.equations()],
        }


def fixed_error(error: float) -> Callable[[Mapping[str, Any]], float]:
    """An ``estimate`` for a rung whose error does not depend on the inputs."""

    def estimate(_: Mapping[str, Any]) -> float:
        return error

    return estimate
