"""Model specs for preload selection (``preload.tightening``) and its control (``preload.control``).

The physics lives in :mod:`engine.physics.preload`, the bolt data in
:mod:`engine.physics.threads` and the control methods in :mod:`engine.physics.preload_methods`;
this module turns a request into a bolt (standard values unless overridden),
calls those functions and says where every number came from.
"""

from __future__ import annotations

import math
from collections.abc import Container, Iterable, Mapping
from dataclasses import fields, replace
from typing import Any, NamedTuple

import numpy as np

from ..core.errors import EngineError, InputOutOfRange
from ..core.params import count, friction_coefficient
from ..core.points import all_finite, one_number
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Plot,
    Result,
    RunContext,
    Rung,
    Scratch,
)
from ..core.text import q
from ..numerics.ode import negate
from ..physics import fasteners as fa
from ..physics import joint as jt
from ..physics import preload as pl
from ..physics import threads as th
from ..physics.preload_methods import (
    METHOD_KEYS,
    METHODS,
    SNUG_FRACTION,
    ControlMethod,
    get_method,
    torque_then_angle,
)
from ..procedures import bolt as fz
from ..procedures.bolt import Bolt, BoltArrays, resolve_bolt, resolve_bolts

SOURCE = (
    "[004] review of preload selection and tightening control, eq. 2–19, "
    "fig. 1–9; VDI 2230-1:2015 steps R7 and R13, Table A8;"
    " ISO 68-1, ISO 261, ISO 273, ISO 898-1, ISO 4017; " + fz.SOURCE_TEXT
)

#: Angle-reading error of [004] (10…15°), taken at its upper end.
ANGLE_READING_ERROR = math.radians(15.0)

# --------------------------------------------------------------------------- inputs

BOLT_INPUTS: tuple[Param, ...] = (
    *fz.THREAD_INPUTS,
    Param(
        "thread_diameter",
        "m",
        "Nominal thread diameter d, when no thread designation is given (ISO 261 M3…M39 "
        "have tabulated data; other sizes need thread_pitch, bearing_outer_diameter, "
        "hole_diameter and yield_strength)",
        maximum=1.0,
        display_unit="mm",
        symbol="d",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "thread_pitch",
        "m",
        "Thread pitch P; ISO 261 coarse pitch when absent",
        maximum=0.1,
        display_unit="mm",
        symbol="P",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "property_class",
        "1",
        "ISO 898-1 property class: minimum yield and tensile strength (8.8: 640/800 MPa "
        "up to M16, 660/830 MPa above)",
        default="8.8",
        kind="choice",
        choices=th.PROPERTY_CLASS_NAMES,
        group="bolt",
    ),
    Param(
        "yield_strength",
        "Pa",
        "Minimum yield strength R_p0.2 (σ_T in [004]); overrides the property class",
        maximum=5e9,
        display_unit="MPa",
        symbol="R_p0.2",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    friction_coefficient(
        "thread_friction",
        "Thread friction coefficient μ_G (f_p in [004])",
        default=0.12,
        recommended=(0.04, 0.4),
        symbol="μ_G",
        group="friction",
    ),
    friction_coefficient(
        "bearing_friction",
        "Bearing-face friction coefficient μ_K (f_T in [004])",
        default=0.12,
        recommended=(0.04, 0.4),
        symbol="μ_K",
        group="friction",
    ),
    Param(
        "bearing_outer_diameter",
        "m",
        "Outer diameter D_f of the bearing face; ISO 4017 hexagon head d_w,min when absent",
        maximum=2.0,
        display_unit="mm",
        symbol="D_f",
        group="bolt",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "hole_diameter",
        "m",
        "Clearance-hole diameter d_h (inner diameter of the bearing face); ISO 273 of "
        "hole_series when absent",
        minimum=0.0,
        maximum=2.0,
        display_unit="mm",
        symbol="d_h",
        group="bolt",
    ),
    Param(
        "hole_series",
        "1",
        "ISO 273 clearance-hole series used when hole_diameter is absent",
        default="medium",
        kind="choice",
        choices=th.HOLE_SERIES,
        group="bolt",
    ),
    Param(
        "utilization",
        "1",
        "ν: share of the yield strength the equivalent stress may use at assembly "
        "(VDI 2230: 0.9; [004, eq. 3]: ξ/n_T, 0.71…0.83)",
        default=0.9,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        symbol="ν",
        group="preload",
    ),
    Param(
        "preload_convention",
        "1",
        "'vdi2230': β of VDI 2230 step R7 (plastic torsion, factor 3/2); "
        "'elastic': β of [004, eq. 5] with τ/σ = 2(d2/d0)·tan(ψ+ρ')",
        default="vdi2230",
        kind="choice",
        choices=("vdi2230", "elastic"),
        group="preload",
    ),
    Param(
        "torque_formula",
        "1",
        "'vdi2230': M_A = F(0.16P + 0.58 d2 μ_G + μ_K D_Km/2); 'exact': [004, eq. 10–13] "
        "with the annular friction radius; 'approx': [004, eq. 15/19] with d2 ≈ d",
        default="vdi2230",
        kind="choice",
        choices=("vdi2230", "exact", "approx"),
        group="preload",
    ),
    Param(
        "preload",
        "N",
        "Preload F0 to use instead of the largest permissible assembly preload",
        maximum=1e8,
        display_unit="kN",
        symbol="F0",
        group="preload",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    *fz.CHECK_INPUTS,
)

#: The nut's ISO 898-2 class, in every model that takes ``nut`` (one definition).
NUT_CLASS_INPUT = Param(
    "nut_property_class",
    "1",
    "Property class of the nut (ISO 898-2; 04/05: thin nuts): its proof load caps F_M,zul; "
    "absent: the lowest class the nut standard is made in that pairs with the bolt",
    kind="choice",
    choices=fa.NUT_PROPERTY_CLASSES,
    group="fastener",
)

BOLT_INPUTS = (*BOLT_INPUTS, NUT_CLASS_INPUT)

# --------------------------------------------------------------------------- the bolt


# --------------------------------------------------------------------------- the nut

#: What the models that take ``nut`` say of it.
NUT_OUTPUTS: tuple[Output, ...] = (
    Output(
        "nut_proof_load",
        "N",
        "ISO 898-2 proof load of the nut, S_p A_s: caps F_M,zul (with a nut)",
        display_unit="kN",
        symbol="F_p",
        step="ISO 898-2",
    ),
    Output(
        "nut_stripping_force",
        "N",
        "Thread strength of a nut that does not pair with the bolt (thin, weaker class): "
        "the larger of R11's F_SM = C1 C3 τ_BM A_SGM over m − 2P (τ_BM = 0.6 S_p) and the "
        "ISO 898-2 proof load the thread is tested to",
        display_unit="kN",
        symbol="F_SM",
        step="VDI 2230-1 R11",
    ),
)
#
# ISO 898-2 rates a nut by its class: its proof load S_p A_s caps the preload a through bolt
# may be given, its class pairs (or not) with the bolt's, and where it does not pair, R11
# says at what force its thread strips (engine.physics.fasteners). The sentences below are
# the joint model's too.


def _kn(force: float) -> str:
    return q(force, "kN", 4)


def nut_limit_warning(
    nut: fa.NutChoice, proof_load: float | None, bolt_preload: float | None
) -> str:
    """The warning when a nut's proof load, not the bolt, sets F_M,zul (without the forces:
    a sweep's or a study's, at some of its points)."""
    head = f"the {nut.standard} nut (class {nut.property_class}) limits the preload"
    if proof_load is None or bolt_preload is None:  # many points
        return head + " at some points: F_M,zul is its ISO 898-2 proof load there"
    return (
        f"{head}: F_M,zul = {_kn(proof_load)}, its ISO 898-2 proof load, instead of the "
        f"bolt's {_kn(bolt_preload)}"
    )


def nut_strength_text(nut: fa.NutChoice, proof_load: float, against: str, ok: bool) -> str:
    """The ``nut_strength`` check's sentence: the proof load against ``against``."""
    return (
        f"proof load of the {nut.standard} nut, class {nut.property_class}"
        f"{'' if nut.given else ' (assumed)'}: F_p = S_p A_s = {_kn(proof_load)} (ISO 898-2) vs "
        f"{against}"
        + (
            ""
            if ok
            else ": the nut strips first; F_M,zul is held at the nut's proof load where the "
            "nut is the weaker; use a full-height nut (ISO 4032/4033) of the class that pairs "
            "with the bolt"
        )
    )


def nut_class_pairing_text(nut: fa.NutChoice, bolt_tensile_strength: float, ok: bool) -> str:
    """The ``nut_class_pairing`` check's sentence (ISO 898-2 clause 3)."""
    cls = nut.property_class
    return (
        f"nut class {cls}{'' if nut.given else ' (assumed)'} with bolt R_m = "
        f"{q(bolt_tensile_strength, 'MPa', 4)}: ISO 898-2 mates a class-N nut with bolts up "
        "to class N.x"
        + (
            ""
            if ok
            else (
                ": a thin nut (04/05) has reduced loadability and pairs with no class"
                if cls.startswith("0")
                else f": class {cls} is too weak for this bolt"
            )
        )
    )


def nut_paired_note(nut: fa.NutChoice) -> str:
    """Why a nut that pairs with the bolt gets no R11 of its own thread."""
    return (
        f"the {nut.standard} nut, class {nut.property_class}, pairs with the bolt: ISO 898-2 "
        "makes such a nut so that the bolt breaks before its thread strips, so R11 is not "
        "worked for the nut's thread"
    )


def nut_stripping_text(nut: fa.NutChoice, strip_force: float, against: str, ok: bool) -> str:
    """The ``nut_thread_stripping`` check's sentence (VDI 2230-1 R11 for the nut's thread)."""
    return (
        f"thread of the {nut.standard} nut, class {nut.property_class}, which does not pair "
        f"with the bolt: it holds F_SM = {_kn(strip_force)}, the larger of VDI 2230-1 R11's "
        f"estimate (τ_BM = {fa.STEEL_SHEAR_RATIO:g} S_p, m − 2P engaged) and the ISO 898-2 proof "
        f"load its thread is tested to, vs {against}"
        + ("" if ok else ": use a full-height nut of the class that pairs with the bolt")
    )


class _NutRating(NamedTuple):
    """A through bolt's nut as ISO 898-2 rates it, on floats or arrays."""

    choice: fa.NutChoice
    #: F_p = S_p A_s [N]; NaN where ISO 898-2 gives no S_p.
    proof_load: Any
    #: F_M,zul of the bolt alone (before the nut caps it) [N].
    bolt_preload: Any
    #: R11's force at which the nut's thread strips (NaN where the nut pairs) [N].
    strip_force: Any


def _scalar_or_none(value: Any) -> float | None:
    """A bolt number the same at every point as a float (None: unknown, or it varies)."""
    if value is None or isinstance(value, float):
        return value
    arr = np.asarray(value, dtype=float)
    if arr.ndim and not np.all(arr == arr.flat[0]):
        return None
    return float(arr.flat[0])


def _nut_rating(
    x: Mapping[str, Any], bolt: Bolt | BoltArrays, bolt_preload: Any
) -> _NutRating | None:
    """The nut's class, proof load and (where it does not pair) R11 stripping force."""
    if x.get("nut") is None:
        return None
    cls = x.get("nut_property_class")
    tensile = _scalar_or_none(bolt.tensile_strength)
    choice = fa.nut_choice(str(x["nut"]), None if cls is None else str(cls), tensile)
    proof = fa.nut_proof_load(choice.property_class, bolt.diameter, bolt.stress_area, choice.style)
    strip: Any = math.nan
    thread = None if bolt.fastener is None else bolt.fastener.thread
    if choice.pairs is False and thread is not None and tensile is not None:
        strip = fa.nut_thread_resistance(
            bolt.diameter,
            bolt.pitch,
            bolt.pitch_diameter,
            fa.nut(choice.standard, thread),
            choice,
            proof,
            tensile,
        )
    return _NutRating(choice, proof, bolt_preload, strip)


def _nut_values(nut: _NutRating | None, largest: Any) -> tuple[dict[str, Any], dict[str, Any]]:
    """The nut's outputs and its checks' verdicts ``(applies, passes)`` at the largest preload."""
    if nut is None:
        return {}, {}
    values: dict[str, Any] = {"nut_proof_load": nut.proof_load}
    verdicts: dict[str, Any] = {
        "nut_strength": (
            nut.proof_load == nut.proof_load,  # ISO 898-2 covers the size
            (nut.bolt_preload <= nut.proof_load) & (largest <= nut.proof_load * (1.0 + 1e-12)),
        )
    }
    if nut.choice.pairs is not None:
        verdicts["nut_class_pairing"] = (True, nut.choice.pairs)
    strip = nut.strip_force
    if not (isinstance(strip, float) and math.isnan(strip)):
        values["nut_stripping_force"] = strip
        verdicts["nut_thread_stripping"] = (strip == strip, strip >= largest)
    return values, verdicts


def _nut_checks(
    nut: _NutRating | None,
    largest: float,
    force_name: str,
    bolt: Bolt,
    checks: list[Check],
    warnings: list[str],
    notes: list[str],
) -> None:
    """The nut's checks as sentences, and the warning when its proof load caps F_M,zul."""
    if nut is None:
        return
    _, verdicts = _nut_values(nut, largest)
    proof, bolt_preload = float(nut.proof_load), float(nut.bolt_preload)
    if proof < bolt_preload:
        warnings.append(nut_limit_warning(nut.choice, proof, bolt_preload))
    elif proof != proof:
        notes.append(
            f"nut strength not checked: ISO 898-2 gives no proof load for class "
            f"{nut.choice.property_class} at d = {q(bolt.diameter, 'mm', 6)}"
        )
    if nut.choice.pairs:
        notes.append(nut_paired_note(nut.choice))
    against = f"the bolt's F_M,zul = {_kn(bolt_preload)} and {force_name} = {_kn(largest)}"
    texts = {
        "nut_strength": lambda ok: nut_strength_text(nut.choice, proof, against, ok),
        "nut_class_pairing": lambda ok: nut_class_pairing_text(
            nut.choice, bolt.tensile_strength or 0.0, ok
        ),
        "nut_thread_stripping": lambda ok: nut_stripping_text(
            nut.choice, float(nut.strip_force), f"{force_name} = {_kn(largest)}", ok
        ),
    }
    for name, (applies, ok) in verdicts.items():
        if applies:
            checks.append(Check(name, bool(ok), texts[name](bool(ok))))


def _nut_verdicts(verdicts: Mapping[str, Any]) -> dict[str, Any]:
    """The array path's verdicts of the nut's checks (one nut and one size at every point:
    a check applies everywhere or nowhere)."""
    return {name: ok for name, (applies, ok) in verdicts.items() if np.all(applies)}


def _where(condition: Any, yes: Any, no: Any) -> Any:
    """``np.where`` for one design or many: one design (a bool) takes its branch directly.

    The same lines serve a single design and arrays; this keeps numpy's per-call cost
    (a few µs) off the single design.
    """
    if isinstance(condition, _ONE_FLAG):
        return yes if condition else no
    return np.where(condition, yes, no)


#: One design's condition (``bool | np.bool_`` would build its union at every call).
_ONE_FLAG = (bool, np.bool_)


def torque_coefficients_raw(
    bolt: Bolt | BoltArrays, thread_friction: Any, bearing_friction: Any, formula: str
) -> tuple[Any, Any, Any]:
    """(k_G, k_K, R) on floats or arrays (one design per element)."""
    k_thread, k_bearing = pl.tightening_torque_per_preload(
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.diameter,
        thread_friction,
        bearing_friction * bolt.bearing_friction_factor,
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        formula,
    )
    if formula == "exact":
        radius = pl.friction_radius(bolt.bearing_outer_diameter, bolt.hole_diameter)
    else:
        radius = 0.25 * (bolt.bearing_outer_diameter + bolt.hole_diameter)
    return k_thread, k_bearing, radius


def torque_coefficients(
    bolt: Bolt, thread_friction: float, bearing_friction: float, formula: str
) -> tuple[float, float, float]:
    """(k_G, k_K, R) of the chosen torque formula: torques per newton and the friction radius."""
    k_thread, k_bearing, radius = torque_coefficients_raw(
        bolt, thread_friction, bearing_friction, formula
    )
    return float(k_thread), float(k_bearing), float(radius)


def _deviation(
    bolt: Bolt | BoltArrays, mu_g: Any, mu_k: Any, formula: str, chosen: Any = None
) -> Any:
    """|M(formula) − M(exact)| / M(exact) on floats or arrays [004, eq. 10–13].

    ``chosen`` is k_G + k_K of ``formula`` where the caller has it already; for
    ``formula == "exact"`` the exact sum is that same sum (the deviation is 0).
    """
    if chosen is None:
        chosen = sum(torque_coefficients_raw(bolt, mu_g, mu_k, formula)[:2])
    exact = (
        chosen
        if formula == "exact"
        else sum(torque_coefficients_raw(bolt, mu_g, mu_k, "exact")[:2])
    )
    return abs(chosen - exact) / exact


class _Design(NamedTuple):
    """One design's bolt and the notes of its resolution, as the rung estimate and the run
    of one request share them."""

    bolt: Bolt
    notes: tuple[str, ...]


def _torque_terms(
    x: Mapping[str, Any], bolt: Bolt | BoltArrays, deviation: bool = True
) -> tuple[tuple[Any, Any, Any], Any]:
    """(k_G, k_K, R) of the torque formula and its deviation from the exact relations
    (None unless ``deviation``).

    VDI 2230-1 R13 / [004, eq. 10–15] on floats or arrays.
    """
    mu_g, mu_k, formula = x["thread_friction"], x["bearing_friction"], str(x["torque_formula"])
    coefficients = torque_coefficients_raw(bolt, mu_g, mu_k, formula)
    if not deviation:
        return coefficients, None
    return coefficients, _deviation(bolt, mu_g, mu_k, formula, coefficients[0] + coefficients[1])


def _request_torque_terms(
    x: Mapping[str, Any],
    bolt: Bolt | BoltArrays,
    scratch: Scratch | None,
    deviation: bool = True,
) -> tuple[tuple[Any, Any, Any], Any]:
    """:func:`_torque_terms` once per request: the rung estimate's, where it ran first.

    Without ``scratch`` (an array path), the deviation is computed only where asked for.
    """
    if scratch is None:
        return _torque_terms(x, bolt, deviation)
    return scratch.once("preload.torque terms", lambda: _torque_terms(x, bolt))


def _resolve_design(x: Mapping[str, Any]) -> _Design:
    """The bolt of a design and the notes naming each standard value used."""
    bolt, notes = resolve_bolt(x)
    return _Design(bolt, tuple(notes))


def _design(x: Mapping[str, Any], scratch: Scratch) -> _Design:
    """The request's design, resolved once: the rung estimate and the run share it.

    Through the request's ``scratch`` (:class:`~engine.core.spec.Scratch`), which lives
    for one run: a later request, or one with other inputs, resolves its own.
    """
    return scratch.once("preload.design", lambda: _resolve_design(x))


def _rung_estimate(x: Mapping[str, Any], scratch: Scratch) -> Any:
    """The closed form's error estimate: a float, or an array where inputs are arrays."""
    try:
        n = _points(x)
        if n:
            # the torque terms with their deviation, left for the array path of the same
            # inputs (which reads them where it gives the deviation)
            bolt_arrays, _ = resolve_bolts(x, n, labels=False)
            _, dev = _request_torque_terms(x, bolt_arrays, scratch)
            return np.where(bolt_arrays.ok, dev, np.nan)
        bolt = _design(x, scratch).bolt
        return float(_request_torque_terms(x, bolt, scratch)[1])
    except (EngineError, KeyError, TypeError, ValueError):
        return None


# --------------------------------------------------------------------------- array path
#
# A sweep or a study hands the model its inputs with the varied ones as
# equal-length numpy arrays. The text and choice inputs (designation, grade, head,
# method, formula …) are the same at every point, so the catalogue is read once; every
# number is then computed with the same engine functions on arrays. A point the scalar
# path refuses is NaN (``ok`` False) and its checks are not counted.


#: The types of a single design's inputs: a request holding values of these types alone
#: holds no array (told in one pass at C speed, not by testing each value in Python).
_SCALAR_TYPES = frozenset({float, int, str, bool, type(None)})


def _points(x: Mapping[str, Any]) -> int:
    """The number of points of an array request (0 when every input is a scalar).

    >>> _points({"d": 0.012, "grade": "8.8", "nut": None}), _points({"d": np.ones(3), "n": 2})
    (0, 3)
    """
    values = x.values()
    if _SCALAR_TYPES.issuperset(map(type, values)):  # one design: the rung estimate's case
        return 0
    for v in values:
        if isinstance(v, np.ndarray) and v.ndim == 1:
            return int(v.shape[0])
    return 0


def _verdicts(verdicts: Mapping[str, Any], ok: np.ndarray, n: int) -> dict[str, np.ndarray]:
    """Check verdicts per point; none at all when every point is refused (as the loop gives)."""
    if not ok.any():
        return {}
    return {k: np.broadcast_to(np.asarray(v, dtype=bool), (n,)) for k, v in verdicts.items()}


def _finish(
    values: Mapping[str, Any],
    ok: np.ndarray,
    n: int,
    wanted: frozenset[str],
    borrowed: Iterable[Any] = (),
) -> tuple[dict[str, Any], frozenset[str]]:
    """The array path's ``wanted`` values: NaN (floats) or None (flags, texts) where a point
    is refused; with them, the names of the float columns tested here and found finite at
    every point (:attr:`Result.finite`: the runner need not test them again).

    Non-finite floats are NaN too: the scalar path returns them as null. A value not asked
    for is left out: each costs a pass over the points. A float column the step made for
    itself, every point of it kept and finite, is given as it is: a copy would cost a pass
    and, at 10⁶ points, 8 MB of fresh pages. A number (a bolt's dimension, most outputs of
    a study) with every point kept is a read-only zero-stride view of it
    (:func:`engine.core.points.one_number`), which :func:`engine.core.points.vector` copies
    for a caller that wants columns of its own. An array the step did not make (an input, a
    bolt number: ``borrowed``) or one already given under another name is copied, so no
    two columns, and no column and an input, share memory.
    """
    out: dict[str, Any] = {}
    finite: list[str] = []
    every = bool(ok.all())
    taken = {id(v) for v in borrowed if isinstance(v, np.ndarray)}
    for name, v in values.items():
        if name not in wanted:
            continue
        arr = np.asarray(v)
        if arr.dtype.kind in "OUSb":
            if every:
                out[name] = v
                continue
            col = np.empty(n, dtype=object)
            col[:] = np.broadcast_to(arr, (n,)).tolist() if arr.ndim else arr.item()
            col[~ok] = None
            out[name] = col
            continue
        if every and _own_column(arr, n, taken) and all_finite(arr):
            out[name] = arr
            taken.add(id(arr))
            finite.append(name)
            continue
        if every and arr.ndim == 0:  # one number at every point: no column of copies
            out[name] = one_number(arr, n)
            continue
        arr = np.broadcast_to(arr.astype(float, copy=False), (n,))
        out[name] = np.where(ok & np.isfinite(arr), arr, np.nan)
    return out, frozenset(finite)


def _borrowed(x: Mapping[str, Any], bolt: BoltArrays) -> list[Any]:
    """What an array path's values may hold without having made it: the inputs, the bolt."""
    return [*x.values(), *(getattr(bolt, f.name) for f in fields(bolt))]


def _own_column(arr: np.ndarray, n: int, taken: Container[int]) -> bool:
    """Whether ``arr`` can be a column as it is: n floats in memory of its own, not
    ``taken`` (borrowed, or given already)."""
    return (
        arr.dtype == np.float64
        and arr.shape == (n,)
        and arr.base is None
        and arr.flags.writeable
        and id(arr) not in taken
    )


CLOSED_FORM = Rung(
    "closed_form",
    "Closed-form relations; the error estimate is how far the chosen torque formula lies "
    "from the exact thread and annular-face relations of [004, eq. 10–13] for these inputs "
    "(0 for 'exact'). It does not include the scatter of the friction coefficients, which "
    "dominates in practice (±30 % at a fixed torque, [004, fig. 5]).",
    lambda x: _rung_estimate(x, Scratch()),
    typical_error="0 (exact) … ~1 % (vdi2230) … a few % (approx), against the exact relations",
    typical_time="< 1 ms",
    shared_estimate=_rung_estimate,
)

# --------------------------------------------------------------------------- tightening


def _part_numbers(bolt: Bolt | BoltArrays, max_preload: Any, torque: Any) -> dict[str, Any]:
    """What the bought-part checks take of a bolt, its largest preload and its torque."""
    return {
        "diameter": bolt.diameter,
        "pitch": bolt.pitch,
        "pitch_diameter": bolt.pitch_diameter,
        "stress_area": bolt.stress_area,
        "tensile_strength": bolt.tensile_strength,
        "bearing_outer_diameter": bolt.bearing_outer_diameter,
        "hole_diameter": bolt.hole_diameter,
        "max_assembly_preload": max_preload,
        "tightening_torque": torque,
    }


def _add_bought_part_checks(
    x: Mapping[str, Any],
    bolt: Bolt,
    max_preload: float,
    torque: float,
    values: dict[str, Any],
    checks: list[Check],
    notes: list[str],
) -> None:
    """Surface pressure, thread stripping and drive torque of bought parts, into the result."""
    fastener = bolt.fastener or fz.Fastener("", None, None, None)
    more, more_checks, more_notes = fz.bought_part_checks(
        x, fastener, **_part_numbers(bolt, max_preload, torque)
    )
    values.update(more)
    checks.extend(more_checks)
    notes.extend(more_notes)


def _tightening_values(
    x: Mapping[str, Any],
    bolt: Bolt | BoltArrays,
    scratch: Scratch | None = None,
    wanted: Container[str] | None = None,
) -> dict[str, Any]:
    """The numbers of ``preload.tightening``, on floats (one design) or arrays (many).

    The single run and the array path both come here, so one set of lines gives
    every number, in the order of the procedure: R7's preload, then R13's torque
    (:func:`_torque_terms`, once per request: with ``scratch``, the rung estimate's).
    ``wanted``: the outputs asked for (every one when None); the torque formula's
    deviation, the equivalent stress and the rules of thumb [004, eq. 14–18] are left out
    where none of theirs is.
    """
    beta = pl.torsion_factor(
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.stress_diameter,
        x["thread_friction"],
        str(x["preload_convention"]),
    )
    bolt_preload = pl.assembly_preload(
        bolt.yield_strength, bolt.stress_area, beta, x["utilization"]
    )
    nut = _nut_rating(x, bolt, bolt_preload)
    permissible = (
        bolt_preload if nut is None else fa.nut_limited_preload(bolt_preload, nut.proof_load)
    )
    force = permissible if x.get("preload") is None else x["preload"]
    sigma_eq = stress_share = _LEFT_OUT
    if wanted is None or any(name in wanted for name in _STRESS):
        sigma_eq = pl.equivalent_stress(force, bolt.stress_area, beta)
        stress_share = sigma_eq / bolt.yield_strength
    deviation_wanted = wanted is None or "torque_formula_deviation" in wanted
    (k_thread, k_bearing, radius), deviation = _request_torque_terms(
        x, bolt, scratch, deviation=deviation_wanted
    )
    terms = wanted is None or any(name in wanted for name in _TORQUE_TERMS)
    m_thread, m_bearing = force * k_thread, force * k_bearing
    total = _add(m_thread, m_bearing, reuse=not terms)  # M_A = M_G + M_K (R13)
    if not terms:
        m_thread = m_bearing = _LEFT_OUT
    rules_wanted = wanted is None or any(name in wanted for name in _RULES)
    ideal = thumb = thumb_yield = share = thumb_dev = yield_dev = _LEFT_OUT
    if rules_wanted:
        ideal = pl.ideal_torque(force, bolt.pitch)
        thumb = pl.rule_of_thumb_torque(force, bolt.diameter)
        thumb_yield = pl.rule_of_thumb_torque_from_yield(bolt.yield_strength, bolt.diameter)
        positive = total > 0
        safe = _where(positive, total, 1.0)
        share = _where(positive, ideal / safe, 1.0)
        thumb_dev = _where(positive, (thumb - total) / safe, math.inf)
        yield_dev = _where(positive, (thumb_yield - total) / safe, math.inf)
    nut_values, nut_verdicts = _nut_values(nut, force)
    values = {
        **nut_values,
        "_nut": (nut, nut_verdicts),
        "assembly_preload": force,
        "permissible_preload": permissible,
        "tightening_torque": total,
        "thread_torque": m_thread,
        "bearing_torque": m_bearing,
        "ideal_torque": ideal,
        "ideal_torque_share": share,
        "friction_radius": radius,
        "stress_area": bolt.stress_area,
        "pitch_diameter": bolt.pitch_diameter,
        "minor_diameter": bolt.minor_diameter,
        "thread_pitch": bolt.pitch,
        "torsion_factor": beta,
        "equivalent_stress": sigma_eq,
        "yield_strength": bolt.yield_strength,
        "stress_utilization": stress_share,
        "bearing_outer_diameter": bolt.bearing_outer_diameter,
        "hole_diameter": bolt.hole_diameter,
        "torque_formula_deviation": deviation if deviation_wanted else _LEFT_OUT,
        "rule_of_thumb_torque": thumb,
        "rule_of_thumb_deviation": thumb_dev,
        "yield_rule_torque": thumb_yield,
        "yield_rule_deviation": yield_dev,
    }
    if wanted is None:  # every value computed
        return values
    return {k: v for k, v in values.items() if v is not _LEFT_OUT}


def _add(a: Any, b: Any, reuse: bool) -> Any:
    """``a + b``; with ``reuse``, written into ``b`` where ``b`` is an array of the sum's
    shape, which the caller made and does not keep (no new array, and its pages are warm).

    >>> b = np.array([1.0, 2.0])
    >>> _add(0.5, b, reuse=True) is b, b.tolist(), _add(0.5, 1.0, reuse=True)
    (True, [1.5, 2.5], 1.5)
    """
    if reuse and isinstance(b, np.ndarray) and np.shape(a) in ((), b.shape):
        return np.add(a, b, out=b)
    return a + b


#: The outputs of the rules of thumb beside the torque formula ([004, eq. 14–18]).
_RULES = (
    "ideal_torque",
    "ideal_torque_share",
    "rule_of_thumb_torque",
    "rule_of_thumb_deviation",
    "yield_rule_torque",
    "yield_rule_deviation",
)
#: The terms of the tightening torque, the thread's and the bearing face's (R13).
_TORQUE_TERMS = ("thread_torque", "bearing_torque")
#: The outputs of the equivalent stress (VDI 2230-1 R7, [004, eq. 5]).
_STRESS = ("equivalent_stress", "stress_utilization")
#: A value :func:`_tightening_values` left out: no output asked for needs it.
_LEFT_OUT = object()


def _tightening(x: Mapping[str, Any], ctx: RunContext) -> Result:
    design = _design(x, ctx.scratch)
    bolt, notes = design.bolt, list(design.notes)
    checks: list[Check] = []
    warnings: list[str] = []
    shared = _tightening_values(x, bolt, ctx.scratch)
    nut, _ = shared.pop("_nut")
    values = {k: float(v) for k, v in shared.items()}
    force, total = values["assembly_preload"], values["tightening_torque"]
    sigma_eq, share = values["equivalent_stress"], values["ideal_torque_share"]
    if x.get("preload") is not None:
        notes.append(f"preload F0 = {_kn(force)} as given (not the permissible one)")
        ok = sigma_eq <= bolt.yield_strength
        checks.append(
            Check(
                "below_yield",
                ok,
                f"equivalent stress {q(sigma_eq, 'MPa', 4)} is "
                f"{sigma_eq / bolt.yield_strength:.1%} of the yield strength"
                + ("" if ok else ": lower the preload, or choose a stronger property class"),
            )
        )
    if not 0.05 <= share <= 0.15:
        notes.append(
            f"the frictionless torque is {share:.1%} of the total; [004, eq. 14] says "
            "5…15 % is usual"
        )
    if x["preload_convention"] == "elastic":
        nu = float(x["utilization"])
        notes.append(
            f"elastic convention [004, eq. 3, 5]: ν = ξ/n_T; with a plain shank (ξ = 1) "
            f"ν = {nu:g} means a safety factor on yield n_T = {1 / nu:.3g} ([004]: 1.2…1.4). "
            "A0 is the stress area here; [004, eq. 6] takes d0 = d1"
        )
    if x["torque_formula"] == "approx":
        notes.append(
            "approx: [004, eq. 15] with d2 ≈ d and R_T ≈ 0.25 (D_f + d_h); with one "
            "friction coefficient it is [004, eq. 19]"
        )
    _add_bought_part_checks(x, bolt, force, total, values, checks, notes)
    _nut_checks(nut, force, "F_M", bolt, checks, warnings, notes)
    return Result(
        values=dict(values),
        rung=ctx.rung,
        error_estimate=values["torque_formula_deviation"],
        checks=checks,
        notes=notes,
        warnings=warnings,
    )


def _bought_part_verdicts(
    x: Mapping[str, Any],
    bolt: BoltArrays,
    max_preload: Any,
    torque: Any,
    values: dict[str, Any],
    verdicts: dict[str, Any],
) -> None:
    """:func:`_add_bought_part_checks` on arrays: values and verdicts, no sentences."""
    more, more_verdicts = fz.bought_part_verdicts(
        x, bolt.fastener, **_part_numbers(bolt, max_preload, torque)
    )
    more["fastener"] = bolt.label
    values.update(more)
    verdicts.update(more_verdicts)


#: The outputs of the bought-part checks (surface pressure, stripping, drive torque).
_BOUGHT_PART_OUTPUTS = tuple(o.name for o in fz.CHECK_OUTPUTS)


def _bought_parts_read(ctx: RunContext) -> bool:
    """Whether an array path's caller reads anything of the bought-part checks."""
    return ctx.checks or ctx.wants(*_BOUGHT_PART_OUTPUTS)


def _bought_part_refusals(x: Mapping[str, Any], bolt: BoltArrays) -> None:
    """The bought-part checks' refusals alone (a washer or a nut without a catalogue
    thread, an unknown material), where no number of theirs is read: the array path
    refuses what the single run refuses. Their forces do not decide a refusal, so a
    zero stands in for them and no array of the points' size is made."""
    fz.bought_part_verdicts(x, bolt.fastener, **_part_numbers(bolt, 0.0, 0.0))


def _tightening_vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """The array path of ``preload.tightening``: its numbers on many points at once."""
    n = _points(x) or 1
    bolt, notes = resolve_bolts(x, n, labels=ctx.wants("fastener"))
    given = x.get("preload") is not None
    below_yield = given and ctx.checks  # the check of a given preload reads σ_red
    # the rung estimate's torque terms, where they are wanted with their deviation (a study
    # of every output): the estimate computed them on the same inputs
    shared = ctx.scratch if "torque_formula_deviation" in ctx.outputs else None
    values = _tightening_values(
        x,
        bolt,
        shared,
        wanted=ctx.outputs | {"equivalent_stress"} if below_yield else ctx.outputs,
    )
    nut, nut_verdicts = values.pop("_nut")
    verdicts: dict[str, Any] = _nut_verdicts(nut_verdicts)
    warnings = []
    if nut is not None and np.any(bolt.ok & (nut.proof_load < nut.bolt_preload)):
        warnings.append(nut_limit_warning(nut.choice, None, None))
    if below_yield:
        verdicts["below_yield"] = values["equivalent_stress"] <= bolt.yield_strength
    if _bought_parts_read(ctx):
        force, total = values["assembly_preload"], values["tightening_torque"]
        _bought_part_verdicts(x, bolt, force, total, values, verdicts)
    else:
        _bought_part_refusals(x, bolt)
    columns, finite = _finish(values, bolt.ok, n, ctx.outputs, _borrowed(x, bolt))
    return Result(
        values=columns,
        rung=ctx.rung,
        error_estimate=None,
        notes=notes,
        warnings=warnings,
        check_arrays=_verdicts(verdicts, bolt.ok, n) if ctx.checks else {},
        finite=finite,
    )


TIGHTENING_OUTPUTS: tuple[Output, ...] = (
    Output(
        "assembly_preload",
        "N",
        "Preload F_M used: the permissible one (below) unless preload was given",
        display_unit="kN",
        symbol="F_M",
        step="VDI 2230-1 R7",
    ),
    Output(
        "permissible_preload",
        "N",
        "Largest preload whose equivalent stress is ν·R_p0.2: F = ν R_p0.2 A_s / β "
        "(VDI 2230 R7; [004, eq. 3])",
        display_unit="kN",
        symbol="F_M,zul",
        step="VDI 2230-1 R7",
    ),
    Output(
        "tightening_torque",
        "N*m",
        "Wrench torque M_A = thread + bearing torque ([004, eq. 13]) by torque_formula",
        symbol="M_A",
        step="[004, eq. 13]",
    ),
    Output(
        "thread_torque",
        "N*m",
        "Thread torque M_p ([004, eq. 10]; VDI: F(0.16P + 0.58 d2 μ_G))",
        symbol="M_p",
        step="[004, eq. 10]",
    ),
    Output(
        "bearing_torque",
        "N*m",
        "Bearing-face torque M_T = μ_K F R ([004, eq. 11])",
        symbol="M_T",
        step="[004, eq. 11]",
    ),
    Output(
        "ideal_torque",
        "N*m",
        "Frictionless torque M* = F P / (2π) ([004, eq. 14])",
        symbol="M*",
        step="[004, eq. 14]",
    ),
    Output(
        "ideal_torque_share",
        "1",
        "M* / M_A; [004] says usually 0.05…0.15",
        symbol="M*/M_A",
        step="[004, eq. 14]",
    ),
    Output(
        "friction_radius",
        "m",
        "Bearing friction radius used: exact R_T ([004, eq. 12]) for 'exact', (D_f + d_h)/4 "
        "otherwise",
        display_unit="mm",
        symbol="R_T",
        step="[004, eq. 12]",
    ),
    Output(
        "stress_area",
        "m^2",
        "Stress area A_s = π/4 ((d2 + d3)/2)² (ISO 898-1)",
        symbol="A_s",
        step="ISO 898-1",
    ),
    Output(
        "pitch_diameter",
        "m",
        "d2 = d − 0.649519 P (ISO 68-1)",
        display_unit="mm",
        symbol="d_2",
        step="ISO 68-1",
    ),
    Output(
        "minor_diameter",
        "m",
        "d3 = d − 1.226869 P (ISO 68-1)",
        display_unit="mm",
        symbol="d_3",
        step="ISO 68-1",
    ),
    Output("thread_pitch", "m", "Pitch P used", display_unit="mm", symbol="P", step="ISO 261"),
    Output(
        "torsion_factor",
        "1",
        "β = σ_red/σ ([004, eq. 5]; VDI 2230 R7)",
        symbol="β",
        step="[004, eq. 5]",
    ),
    Output(
        "equivalent_stress",
        "Pa",
        "σ_red = β F / A_s during tightening",
        display_unit="MPa",
        symbol="σ_red,M",
        step="VDI 2230-1 R7",
    ),
    Output(
        "yield_strength", "Pa", "R_p0.2 used", display_unit="MPa", symbol="R_p0.2", step="ISO 898-1"
    ),
    Output(
        "stress_utilization",
        "1",
        "σ_red / R_p0.2 at the preload used",
        symbol="ν",
        step="VDI 2230-1 R7",
    ),
    Output(
        "bearing_outer_diameter",
        "m",
        "D_f used",
        display_unit="mm",
        symbol="D_f",
        step="[004, eq. 12]",
    ),
    Output("hole_diameter", "m", "d_h used", display_unit="mm", symbol="d_h", step="[004, eq. 12]"),
    Output(
        "torque_formula_deviation",
        "1",
        "|M(chosen formula) − M(exact)| / M(exact) for these inputs",
        symbol="ΔM_A/M_A",
        step="[004, eq. 13]",
    ),
    Output(
        "rule_of_thumb_torque",
        "N*m",
        "0.2 F0 d ([004, eq. 16])",
        symbol="M_A,0.2Fd",
        step="[004, eq. 16]",
    ),
    Output(
        "rule_of_thumb_deviation",
        "1",
        "(0.2 F0 d − M_A) / M_A",
        symbol="ΔM_A/M_A",
        step="[004, eq. 16]",
    ),
    Output(
        "yield_rule_torque",
        "N*m",
        "0.07 σ_T d³ ([004, eq. 18]; assumes σ0 = 0.6 σ_T, not the preload used here)",
        symbol="M_A,σT",
        step="[004, eq. 18]",
    ),
    Output(
        "yield_rule_deviation",
        "1",
        "(0.07 σ_T d³ − M_A) / M_A",
        symbol="ΔM_A/M_A",
        step="[004, eq. 18]",
    ),
    *fz.CHECK_OUTPUTS,
    *NUT_OUTPUTS,
)

#: True of every preload.tightening answer (the runner adds it to the notes).
TIGHTENING_ASSUMPTIONS = (
    "[004, eq. 10 and 12] are missing from the review's text; the standard thread-torque "
    "and annular friction-radius relations stand in",
)

TIGHTENING = ModelSpec(
    name="preload.tightening",
    answer=(
        Answer("tightening_torque", "M_A"),
        Answer("assembly_preload", "F_M"),
        Answer("permissible_preload", "F_M,zul"),
        Answer("stress_utilization", "ν"),
    ),
    title="Bolt preload and tightening torque",
    family="preload",
    summary=(
        "The largest assembly preload a metric bolt takes at a share ν of its yield "
        "strength, and the torque that gives it: thread, bearing and frictionless parts, "
        "by the VDI 2230 formula, the review's exact relations or its approximation, "
        "with the review's rules of thumb beside them."
    ),
    source=SOURCE,
    inputs=BOLT_INPUTS,
    outputs=TIGHTENING_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_tightening,
    vectorized=_tightening_vectorized,
    vector_rungs=("closed_form",),
    assumptions=TIGHTENING_ASSUMPTIONS,
    examples=(
        # VDI 2230 Table A1 case: M12 8.8, μ_G = μ_K = 0.12, ν = 0.9
        {"thread_diameter": 0.012, "property_class": "8.8", "thread_friction": 0.12},
        {
            "thread_diameter": 0.010,
            "thread_pitch": 0.00125,
            "property_class": "8.8",
            "thread_friction": 0.12,
            "bearing_friction": 0.12,
        },
        {
            "thread_diameter": 0.016,
            "property_class": "10.9",
            "thread_friction": 0.15,
            "bearing_friction": 0.15,
            "torque_formula": "exact",
            "preload_convention": "elastic",
            "utilization": 0.7,
        },
        # bought parts: a designation, no dimension typed
        {"thread": "M10 ISO 4762 12.9"},
        {
            "thread": "M8 ISO 4762 12.9",
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "engagement_length": 0.008,
            "washer": "ISO 7089",
        },
        {"thread": "1/2-13 UNC", "grade": "SAE 5", "clamped_material": "S235JR"},
    ),
)

# --------------------------------------------------------------------------- control

CONTROL_INPUTS: tuple[Param, ...] = (
    *(
        replace(
            p,
            description="Nominal preload (middle of the method's band); when absent the "
            "band's top is the permissible preload (yield control: the preload at yield)",
        )
        if p.name == "preload"
        else p
        for p in BOLT_INPUTS
    ),
    Param(
        "required_clamp_force",
        "N",
        "Clamp force the joint needs in service (tightness, no separation)",
        required=True,
        maximum=1e8,
        display_unit="kN",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "load_type",
        "1",
        "'steady' (υ = 1.25…2.0) or 'varying' (υ = 2.5…4.0) load [004, eq. 2]",
        default="steady",
        kind="choice",
        choices=("steady", "varying"),
        group="joint",
    ),
    Param(
        "preload_factor",
        "1",
        "υ of [004, eq. 2]: minimum preload = υ × clamp force; the lower end of the "
        "load type's range when absent",
        minimum=1.0,
        maximum=10.0,
        symbol="υ",
        group="joint",
    ),
    Param(
        "method",
        "1",
        "Control method (GET /api/v1/preload/methods lists them with their scatter)",
        default="torque_wrench",
        kind="choice",
        choices=METHOD_KEYS,
        group="control",
    ),
    Param(
        "snug_fraction",
        "1",
        "torque_then_angle: share of the final torque (and preload) at the snug point, where "
        "the angle count starts; 0.1 as ISO 5393 starts its angles, when absent (better: from "
        "the joint's torque–angle diagram, [004])",
        default=SNUG_FRACTION,
        minimum=0.01,
        maximum=0.9,
        symbol="s_snug",
        group="control",
    ),
    Param(
        "clamped_length",
        "m",
        "Clamped (grip) length l_k: needed for angle, elongation and displacement targets",
        maximum=10.0,
        display_unit="mm",
        symbol="l_k",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "shank_length",
        "m",
        "Length of plain shank inside the grip; the rest of the grip is free thread (d3)",
        default=0.0,
        minimum=0.0,
        maximum=10.0,
        display_unit="mm",
        group="joint",
    ),
    Param(
        "shank_diameter",
        "m",
        "Plain shank diameter; d when absent",
        maximum=1.0,
        display_unit="mm",
        group="joint",
        minimum=1e-4,  # 0.1 mm; a length of 1e-300 once divided by zero
    ),
    Param(
        "reduced_length",
        "m",
        "Length of a reduced (waisted) shank section inside the grip",
        default=0.0,
        minimum=0.0,
        maximum=10.0,
        display_unit="mm",
        group="joint",
    ),
    Param(
        "reduced_diameter",
        "m",
        "Diameter of the reduced shank section (needed when reduced_length > 0)",
        maximum=1.0,
        display_unit="mm",
        group="joint",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    Param(
        "nut_height",
        "m",
        "Nut height m; [004] adds m/3 at the minor diameter to the stretched length; "
        "0.8 d when absent",
        minimum=0.0,
        maximum=1.0,
        display_unit="mm",
        group="joint",
    ),
    Param(
        "youngs_modulus",
        "Pa",
        "Young's modulus of the bolt E_b",
        default=2.1e11,
        maximum=1e12,
        display_unit="GPa",
        group="joint",
        minimum=1e9,  # 1 GPa, below any bolt material; 5e-324 once crashed the model
    ),
    Param(
        "clamped_compliance",
        "m/N",
        "Compliance of the clamped parts λ_p ([004, eq. 8]); when absent, bolts get VDI 2230 "
        "R3's deformation cone through clamped_length of one material (wide plates, "
        "through-bolted), sucker rods 0 (rigid, [004, eq. 9]); 0 for a rigid joint",
        minimum=0.0,
        maximum=1.0,
        group="joint",
    ),
    Param(
        "clamped_youngs_modulus",
        "Pa",
        "Young's modulus of the clamped parts for the cone model; youngs_modulus when absent",
        minimum=1e8,
        maximum=1e12,
        display_unit="GPa",
        group="joint",
    ),
    Param(
        "coupling_outer_diameter",
        "m",
        "Sucker-rod coupling outside diameter: turns the make-up angle into the "
        "circumferential displacement of the marks",
        maximum=1.0,
        display_unit="mm",
        group="control",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    friction_coefficient(
        "thread_friction_min",
        "Friction scatter: lowest μ_G (with thread_friction_max, gives the preload "
        "histogram at a fixed torque)",
        group="scatter",
    ),
    friction_coefficient(
        "thread_friction_max",
        "Friction scatter: highest μ_G",
        group="scatter",
    ),
    friction_coefficient(
        "bearing_friction_min",
        "Friction scatter: lowest μ_K (bearing_friction when absent)",
        group="scatter",
    ),
    friction_coefficient(
        "bearing_friction_max",
        "Friction scatter: highest μ_K",
        group="scatter",
    ),
    Param(
        "scatter_torque",
        "N*m",
        "Fixed wrench torque for the friction-scatter histogram; the target torque when absent",
        maximum=1e7,
        group="scatter",
        minimum=0.0,
        exclusive_minimum=True,
    ),
    count(
        "histogram_bins",
        "Number of preload bins",
        default=10,
        minimum=2,
        maximum=100,
        group="scatter",
    ),
    count(
        "sample_size",
        "Bolts the histogram counts are scaled to (38 in [004, fig. 5])",
        default=38,
        minimum=1,
        maximum=1_000_000,
        group="scatter",
    ),
)


def _grip_sections(
    bolt: Bolt | BoltArrays, x: Mapping[str, Any]
) -> tuple[list[Any], list[Any], Any]:
    """Lengths and diameters of the stretched sections [004, eq. 4, 7], on floats or arrays.

    Shank, reduced shank, free thread (d3) and a third of the nut height at d3 (0.8 d
    when absent); a section of zero length adds nothing to the sums. The third value
    is False where the inputs do not make a grip (shank and reduced lengths beyond
    clamped_length, or a reduced length without its diameter): :func:`_refuse_grip`
    says why.
    """
    grip = x["clamped_length"]
    l_shank, l_reduced = x["shank_length"], x["reduced_length"]
    free = grip - l_shank - l_reduced
    fine = negate(free < -1e-12 * grip)
    if x.get("reduced_diameter") is None:
        fine = fine & negate(l_reduced > 0)
    d = bolt.diameter
    shank_d = d if x.get("shank_diameter") is None else x["shank_diameter"]
    reduced_d = d if x.get("reduced_diameter") is None else x["reduced_diameter"]
    nut = 0.8 * d if x.get("nut_height") is None else x["nut_height"]
    lengths = [l_shank, l_reduced, _where(free > 0.0, free, 0.0), nut / 3.0]
    diameters = [shank_d, reduced_d, bolt.minor_diameter, bolt.minor_diameter]
    return lengths, diameters, fine


def _refuse_grip(x: Mapping[str, Any]) -> None:
    """Why a single design's grip is refused (:func:`_grip_sections` gave False)."""
    grip, l_shank, l_reduced = x["clamped_length"], x["shank_length"], x["reduced_length"]
    if l_reduced > 0 and x.get("reduced_diameter") is None:
        raise InputOutOfRange(
            "reduced_diameter is required when reduced_length > 0", field="reduced_diameter"
        )
    raise InputOutOfRange(
        f"shank_length + reduced_length = {(l_shank + l_reduced) * 1e3:g} mm exceeds "
        f"clamped_length = {grip * 1e3:g} mm",
        field="shank_length",
    )


def _smallest_section(bolt: Bolt | BoltArrays, x: Mapping[str, Any]) -> tuple[Any, Any, Any, Any]:
    """d_0, A_0 of the smallest section (VDI 2230-1 R7), on floats or arrays.

    :func:`engine.physics.joint.smallest_section` over the thread, the plain and the reduced
    shank; also where it is the shank, and False where a reduced length has no
    diameter.
    """
    sections = []
    if x.get("shank_diameter") is not None:
        sections.append((x["shank_length"], x["shank_diameter"]))
    if x.get("reduced_diameter") is not None:
        sections.append((x["reduced_length"], x["reduced_diameter"]))
        fine: Any = True
    else:
        fine = negate(x["reduced_length"] > 0.0)
    d0, where = jt.smallest_section(bolt.stress_diameter, sections)
    shank = where == "shank"  # a word for one design, an array of words for many
    area0 = _where(shank, 0.25 * math.pi * d0 * d0, bolt.stress_area)
    return d0, area0, shank, fine


def _clamped_compliance(
    bolt: Bolt | BoltArrays, x: Mapping[str, Any], method: ControlMethod, ok: Any = True
) -> Any:
    """λ_p: the value given, else VDI 2230 R3's cone for bolts (0 for sucker rods).

    On arrays the cone runs once per distinct design among the points ``ok`` marks.
    """
    if x.get("clamped_compliance") is not None:
        return x["clamped_compliance"]
    if method.family != "bolt":
        return 0.0
    args = (
        x["clamped_length"],
        _clamped_youngs(x),
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
    )

    def cone(g: float, e: float, outer: float, hole: float) -> float:
        return jt.clamped_compliance([g], [e], outer, hole, None, "through").total

    if not isinstance(ok, np.ndarray) or not any(isinstance(a, np.ndarray) for a in args):
        return cone(*(float(a) for a in args))
    n = ok.shape[0]
    table = np.column_stack([np.broadcast_to(np.asarray(a, dtype=float), (n,)) for a in args])
    out = np.full(n, np.nan)
    rows, inverse = np.unique(table[ok], axis=0, return_inverse=True)
    totals = np.array([cone(*row) for row in rows.tolist()])
    out[ok] = totals[inverse.ravel()]
    return out


def _clamped_youngs(x: Mapping[str, Any]) -> Any:
    """E_p of the clamped parts: clamped_youngs_modulus, else the bolt's."""
    e_p = x.get("clamped_youngs_modulus")
    return x["youngs_modulus"] if e_p is None else e_p


def _control_values(
    x: Mapping[str, Any],
    bolt: Bolt | BoltArrays,
    method: ControlMethod,
    section: tuple[Any, Any],
    scratch: Scratch | None = None,
    band: bool = True,
) -> tuple[dict[str, Any], Any]:
    """The preload band and target of ``preload.control``, on floats or arrays.

    ``section`` is (d_0, A_0) of the smallest section. VDI 2230-1 R7 at the smallest
    section ([004, eq. 3–4]), the method's band, [004, eq. 2]'s required preload, then
    R13's torque for the nominal preload (:func:`_torque_terms`, once per request: with
    ``scratch``, the rung estimate's); also the torque formula's deviation from the exact one
    (None without ``scratch``: the array path does not give it). Without ``band`` (an
    array path whose caller reads neither the band's ends nor the checks), the band's
    ends and the yield preload are left out where the nominal preload does not need them.
    """
    d0, area0 = section
    beta = pl.torsion_factor(
        bolt.pitch, bolt.pitch_diameter, d0, x["thread_friction"], str(x["preload_convention"])
    )
    bolt_preload = pl.assembly_preload(bolt.yield_strength, area0, beta, x["utilization"])
    (k_thread, k_bearing, _), deviation = _request_torque_terms(
        x, bolt, scratch, deviation=scratch is not None
    )
    nut = _nut_rating(x, bolt, bolt_preload)
    permissible = (
        bolt_preload if nut is None else fa.nut_limited_preload(bolt_preload, nut.proof_load)
    )
    at_yield: Any = _LEFT_OUT
    if band or method.controls == "yield":
        at_yield = pl.assembly_preload(bolt.yield_strength, area0, beta, 1.0)
    lo_factor, _ = pl.preload_factor_range(str(x["load_type"]))
    factor = lo_factor if x.get("preload_factor") is None else x["preload_factor"]
    nominal, f_min, f_max = _method_band(method, permissible, at_yield, x.get("preload"), band)
    nut_values, nut_verdicts = _nut_values(nut, f_max)
    values = {
        **nut_values,
        "_nut": (nut, nut_verdicts),
        "controlled_quantity": method.controls,
        "target_torque": nominal * (k_thread + k_bearing),
        "target_force": nominal,
        "nominal_preload": nominal,
        "preload_min": f_min,
        "preload_max": f_max,
        "scatter": method.scatter,
        "tightening_factor": method.tightening_factor,
        "required_preload": factor * x["required_clamp_force"],
        "preload_factor": factor,
        "permissible_preload": permissible,
        "yield_preload": at_yield,
    }
    if not band:
        values = {k: v for k, v in values.items() if v is not _LEFT_OUT}
    return values, deviation


def _stretch_values(
    x: Mapping[str, Any],
    bolt: Bolt | BoltArrays,
    lengths: list[Any],
    diameters: list[Any],
    parts: Any,
    nominal: Any,
) -> dict[str, Any]:
    """Compliances, elongation, angle (and mark displacement) at the nominal preload.

    [004, eq. 4, 7–9] on floats or arrays: one compliance λ_b + λ_p for all of them.
    """
    compliance = pl.axial_compliance(lengths, diameters, x["youngs_modulus"])
    angle = pl.nut_rotation_angle(nominal, compliance + parts, bolt.pitch)
    out = {
        "bolt_compliance": compliance,
        "clamped_compliance": parts,
        "equivalent_shank_diameter": pl.equivalent_shank_diameter(lengths, diameters),
        "target_elongation": pl.elongation(nominal, compliance),
        "target_angle": angle,
    }
    if x.get("coupling_outer_diameter") is not None:
        out["target_displacement"] = angle * 0.5 * x["coupling_outer_diameter"]
    return out


def _snug_values(
    x: Mapping[str, Any], bolt: Bolt | BoltArrays, values: Mapping[str, Any], stretch: Any
) -> dict[str, Any]:
    """Torque-then-angle's snug torque and the angle beyond it, at the nominal preload."""
    k = values["target_torque"] / values["nominal_preload"]  # M_A/F of the torque formula
    t = torque_then_angle(values["nominal_preload"], k, stretch, bolt.pitch, x["snug_fraction"])
    return {
        "snug_preload": t.snug_preload,
        "snug_torque": t.snug_torque,
        "angle_after_snug": t.angle,
    }


def _plain(values: Mapping[str, Any]) -> dict[str, Any]:
    """A single design's values as Python numbers (0-d arrays from the shared lines)."""
    return {k: v if type(v) in _PLAIN else v.item() for k, v in values.items()}


#: Types a single design's values may keep as they are.
_PLAIN = frozenset((float, int, bool, str, type(None)))


def _method_band(
    method: ControlMethod,
    permissible: float,
    at_yield: float,
    given: float | None,
    ends: bool = True,
) -> tuple[Any, Any, Any]:
    """(nominal, min, max) preload a method gives [N]; without ``ends``, the nominal alone
    (min and max left out).

    With a given preload it is the middle of the band; otherwise the middle is
    set so the top of the band is the permissible preload (yield control: the
    preload at yield).
    """
    s = method.scatter
    top = at_yield if method.controls == "yield" else permissible
    nominal = given if given is not None else top / (1.0 + s)
    if not ends:
        return nominal, _LEFT_OUT, _LEFT_OUT
    return nominal, nominal * (1.0 - s), nominal * (1.0 + s)


def _control(x: Mapping[str, Any], ctx: RunContext) -> Result:
    design = _design(x, ctx.scratch)
    bolt, notes = design.bolt, list(design.notes)
    warnings: list[str] = []
    checks: list[Check] = []
    method = get_method(str(x["method"]))
    mu_g, mu_k = float(x["thread_friction"]), float(x["bearing_friction"])
    formula = str(x["torque_formula"])
    # VDI 2230-1 R7: the strength limit is at the smallest cross-section ([004, eq. 3-4]).
    d0, area0, shank, fine = _smallest_section(bolt, x)
    if not fine:
        raise InputOutOfRange(
            "reduced_diameter is required when reduced_length > 0", field="reduced_diameter"
        )
    if shank:
        notes.append(
            f"smallest section is the shank, d_0 = {q(d0, 'mm', 4)} < d_S = "
            f"{q(bolt.stress_diameter, 'mm', 4)}: the permissible and yield preloads use "
            f"A_0 = {q(area0, 'mm²', 4)} and W_p = π d_0³/16 (VDI 2230-1 R7; [004, eq. 3–4])"
        )
    shared, deviation = _control_values(x, bolt, method, (d0, area0), ctx.scratch)
    nut, _ = shared.pop("_nut")
    values = _plain(shared)
    permissible, at_yield = values["permissible_preload"], values["yield_preload"]
    nominal, f_min, f_max = values["nominal_preload"], values["preload_min"], values["preload_max"]
    torque, required, factor = (
        values["target_torque"],
        values["required_preload"],
        values["preload_factor"],
    )
    given = x.get("preload")
    lo_factor, hi_factor = pl.preload_factor_range(str(x["load_type"]))
    if not lo_factor <= factor <= hi_factor:
        warnings.append(
            f"preload_factor υ = {factor:g} is outside {lo_factor:g}…{hi_factor:g}, the range "
            f"[004, eq. 2] gives for {x['load_type']} load"
        )

    # Elongation and angle through one compliance [004, eq. 4, 7, 8, 9].
    needs_grip = method.controls in ("angle", "elongation", "displacement")
    stretch: float | None = None  # bolt + parts compliance, when the grip is known
    if x.get("clamped_length") is not None:
        lengths, diameters, fine = _grip_sections(bolt, x)
        if not fine:
            _refuse_grip(x)
        parts = float(_clamped_compliance(bolt, x, method))
        if x.get("clamped_compliance") is None and method.family == "bolt":
            notes.append(
                f"clamped parts λ_p = {q(parts, 'µm/kN', 4)} from VDI 2230-1 R3's "
                f"deformation cone (l_K = {q(x['clamped_length'], 'mm', 6)}, E_p = "
                f"{q(_clamped_youngs(x), 'GPa', 6)}, "
                f"d_W = {q(bolt.bearing_outer_diameter, 'mm', 6)}, "
                f"d_h = {q(bolt.hole_diameter, 'mm', 6)}, through-bolted, wide plates); give "
                "clamped_compliance to override (0: rigid)"
            )
        values.update(_plain(_stretch_values(x, bolt, lengths, diameters, parts, nominal)))
        stretch = values["bolt_compliance"] + parts
        if method.key == "torque_then_angle":
            values.update(_plain(_snug_values(x, bolt, values, stretch)))
        angle = values["target_angle"]
        if parts == 0.0 and method.controls in ("angle", "displacement", "elongation"):
            notes.append(
                "clamped parts taken as rigid ([004, eq. 9]); give clamped_compliance for "
                "[004, eq. 8] — the angle is then larger"
            )
        if method.controls in ("angle", "displacement"):
            big_enough = angle * method.scatter >= ANGLE_READING_ERROR
            checks.append(
                Check(
                    "angle_resolution",
                    big_enough,
                    f"target angle {math.degrees(angle):.0f}° against a reading error of "
                    f"15° ([004]): "
                    + (
                        f"the reading error stays within the method's ±{method.scatter:.0%}"
                        if big_enough
                        else f"needs ≥ {math.degrees(ANGLE_READING_ERROR / method.scatter):.0f}° "
                        "for the method's accuracy; "
                        + (
                            "the bolt is too short for angle control ([004]): use torque or "
                            "elongation control"
                            if method.controls == "angle"
                            else "the make-up turn is too small to read from the marks: use "
                            "the dynamometric wrench or the locking ring"
                        )
                    ),
                )
            )
        grip = float(x["clamped_length"])
        if method.controls == "elongation" and grip < 6.0 * bolt.diameter:
            warnings.append(
                f"clamped length {q(grip, 'mm', 6)} < 6 d: the elongation is only "
                f"{q(values['target_elongation'], 'µm', fmt='.0f')}; [004] warns of large "
                "measuring errors on short bolts"
            )
    elif needs_grip:
        raise InputOutOfRange(
            f"method {method.key!r} sets the {method.controls}; give clamped_length",
            field="clamped_length",
        )
    if method.controls == "displacement" and x.get("coupling_outer_diameter") is None:
        raise InputOutOfRange(
            f"method {method.key!r} sets a circumferential displacement; give "
            "coupling_outer_diameter",
            field="coupling_outer_diameter",
        )

    _add_bought_part_checks(x, bolt, f_max, torque, values, checks, notes)
    _nut_checks(nut, f_max, "F_M,max", bolt, checks, warnings, notes)
    meets = f_min >= required
    below = f_max <= at_yield * (1.0 + 1e-12)
    values["min_meets_clamp"] = meets
    values["max_below_yield"] = below
    checks.append(
        Check(
            "min_meets_clamp",
            meets,
            f"minimum preload {_kn(f_min)} vs required υ·F_K = {_kn(required)}"
            + (
                ""
                if meets
                else ": choose a more accurate method, a larger or stronger bolt, or more bolts"
            ),
        )
    )
    checks.append(
        Check(
            "max_below_yield",
            below,
            f"maximum preload {_kn(f_max)} vs {_kn(at_yield)} at yield"
            + ("" if below else ": lower the target preload or choose a more accurate method"),
        )
    )
    if method.controls == "yield":
        notes.append(
            "torque-gradient control tightens to the yield point; the band's top is the preload "
            "at yield (minimum R_p0.2) and the bolt must be ductile ([004])"
        )

    candidates, passes = _passing(
        x, bolt, method, (permissible, at_yield, given, required), stretch
    )
    chosen = [m for m, ok in zip(candidates, passes, strict=True) if ok]
    values["cheaper_methods"], values["passing_methods"] = _method_text(chosen, method.cost_rank)
    notes.append(f"scatter of {method.key}: {method.scatter_source}")
    if method.key == "torque_then_angle":
        notes.append(
            "[004] takes the snug torque and the angle from the joint's experimental "
            "torque–angle diagram; without one, snug is taken at "
            f"{float(x['snug_fraction']):.0%} of the final torque (ISO 5393 starts its angles "
            "at 10 %) and angle_after_snug turns the preload still to come; target_angle "
            "counts from zero preload"
        )

    series: dict[str, list[float]] = {}
    scatter_wanted = ctx.wants(
        "preload_bins",
        "preload_counts",
        "scatter_preload_min",
        "scatter_preload_max",
        "scatter_preload_mean",
        "scatter_relative",
        "scatter_torque_applied",
    )
    has_range = (
        x.get("thread_friction_min") is not None or x.get("bearing_friction_min") is not None
    )
    if scatter_wanted and has_range:
        g_range = _checked_range(x, "thread_friction", mu_g)
        k_range = _checked_range(x, "bearing_friction", mu_k)
        if bolt.bearing_friction_factor != 1.0:  # a countersunk head: μ_K acts on the cone
            k_range = (
                k_range[0] * bolt.bearing_friction_factor,
                k_range[1] * bolt.bearing_friction_factor,
            )
        fixed = torque if x.get("scatter_torque") is None else float(x["scatter_torque"])
        geometry = (bolt.pitch, bolt.pitch_diameter, bolt.diameter)
        washer = (bolt.bearing_outer_diameter, bolt.hole_diameter)
        # the band's corners and the exact mean (engine.physics.preload.friction_scatter_band); the
        # 64×64 grid only for the histogram, when asked (nothing is computed that no output needs)
        f_lo, f_hi, f_mean = _scatter_band(bolt, formula, fixed, g_range, k_range)
        if ctx.wants("preload_bins", "preload_counts"):
            forces = pl.friction_scatter_preloads(
                fixed, *geometry, g_range, k_range, *washer, formula
            )
            hist = pl.preload_histogram(
                forces, bins=int(x["histogram_bins"]), sample_size=int(x["sample_size"])
            )
            series = {
                "preload_bins": hist.bin_centres.tolist(),
                "preload_counts": hist.counts.tolist(),
            }
        spread = (f_hi - f_lo) / (f_hi + f_lo)
        values.update(
            scatter_preload_min=f_lo,
            scatter_preload_max=f_hi,
            scatter_preload_mean=f_mean,
            scatter_relative=spread,
            scatter_torque_applied=fixed,
        )
        notes.append(
            f"friction scatter at {q(fixed, 'N*m', 4)}: μ_G {g_range[0]:g}…{g_range[1]:g}, "
            f"μ_K {k_range[0]:g}…{k_range[1]:g} (independent, uniform) give "
            f"preload {q(f_lo, 'kN', 4, bare=True)}…{_kn(f_hi)} (the corners), mean "
            f"{_kn(f_mean)}, ±{spread:.0%} "
            '([004, fig. 5]: ±30 % for 38 bolts 5/8" at 80 N·m)'
        )
        notes.append(SCATTER_MEAN_NOTE)
    elif scatter_wanted and (
        x.get("thread_friction_max") is not None or x.get("bearing_friction_max") is not None
    ):
        raise InputOutOfRange(
            "give thread_friction_min with thread_friction_max (and bearing_friction_min with "
            "bearing_friction_max)",
            field="thread_friction_min",
        )
    elif scatter_wanted:
        notes.append(
            "no friction range given (thread_friction_min/max, bearing_friction_min/max): "
            "no preload histogram"
        )

    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=float(deviation),
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=series,
    )


def _range(x: Mapping[str, Any], name: str, nominal: Any) -> tuple[Any, Any, Any]:
    """The friction range (low, high) of ``name``, and where low ≤ high (floats or arrays).

    Both ends absent: the nominal value at both ends.
    """
    lo, hi = x.get(f"{name}_min"), x.get(f"{name}_max")
    if lo is None and hi is None:
        return nominal, nominal, True
    if lo is None or hi is None:
        raise InputOutOfRange(f"give both {name}_min and {name}_max", field=f"{name}_min")
    return lo, hi, negate(lo > hi)


def _checked_range(x: Mapping[str, Any], name: str, nominal: float) -> tuple[float, float]:
    """:func:`_range` of a single design, refused where its low end exceeds its high end."""
    lo, hi, fine = _range(x, name, nominal)
    if not fine:
        raise InputOutOfRange(
            f"{name}_min = {lo:g} exceeds {name}_max = {hi:g}", field=f"{name}_min"
        )
    return lo, hi


#: What the friction-scatter figures are, and what they were (a result note).
SCATTER_MEAN_NOTE = (
    "friction scatter: min and max are the preloads at the corners of the μ_G × μ_K box and "
    "the mean is exact (μ_K integrated in closed form, μ_G by Gauss–Legendre, ~1e-13; "
    "engine.physics.preload.friction_scatter_band); until this version they came from a 64×64 "
    "midpoint grid, whose mean is ~4e-6 relative low and whose band ~1.9 % narrow on the "
    "[004, fig. 5] example; the histogram (preload_bins, preload_counts) is still that grid's"
)


def _scatter_band(
    bolt: Bolt | BoltArrays,
    formula: str,
    torque: Any,
    g_range: tuple[Any, Any],
    k_range: tuple[Any, Any],
) -> tuple[Any, Any, Any]:
    """Lowest, highest and mean preload of the friction scatter, one design or per point.

    :func:`engine.physics.preload.friction_scatter_band`: its corners and exact mean take a few
    operations a point (16 Gauss–Legendre nodes in μ_G), so a bolt varying from point
    to point costs no 64×64 grid.
    """
    return pl.friction_scatter_band(
        torque,
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.diameter,
        g_range,
        k_range,
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        formula,
    )


#: The control methods, cheapest first (the order the method lists are written in).
_BY_COST = tuple(sorted(METHODS, key=lambda m: (m.cost_rank, m.key)))


def _passing(
    x: Mapping[str, Any],
    bolt: Bolt | BoltArrays,
    method: ControlMethod,
    band: tuple[Any, Any, Any, Any],
    stretch: Any,
) -> tuple[list[ControlMethod], list[Any]]:
    """The methods of ``method``'s family worth comparing, cheapest first, and where each
    passes both checks (and reads its angle), on floats or arrays.

    ``band`` is (permissible, yield, given preload or None, required preload).
    """
    permissible, at_yield, given, required = band
    top = at_yield * (1.0 + 1e-12)
    candidates: list[ControlMethod] = []
    passes: list[Any] = []
    for other in _BY_COST:
        if other.family != method.family:
            continue
        if other.controls in ("angle", "displacement", "elongation") and stretch is None:
            continue
        if other.controls == "displacement" and x.get("coupling_outer_diameter") is None:
            continue
        o_nominal, o_min, o_max = _method_band(other, permissible, at_yield, given)
        passing = (o_min >= required) & (o_max <= top)
        if other.controls in ("angle", "displacement") and stretch is not None:
            o_angle = pl.nut_rotation_angle(o_nominal, stretch, bolt.pitch)
            # too short for angle control, as the angle_resolution check says
            passing = passing & negate(o_angle * other.scatter < ANGLE_READING_ERROR)
        candidates.append(other)
        passes.append(passing)
    return candidates, passes


def _method_text(chosen: list[ControlMethod], own_rank: int) -> tuple[str, str]:
    """``cheaper_methods`` and ``passing_methods`` for the methods that pass, cheapest first."""
    cheaper = [m.key for m in chosen if m.cost_rank < own_rank]
    return (
        ", ".join(cheaper) if cheaper else "none",
        ", ".join(m.key for m in chosen) if chosen else "none",
    )


def _method_texts(
    candidates: list[ControlMethod], passes: list[Any], own_rank: int, n: int
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_method_text` per point: each point's pass pattern is a bit code, and the
    texts are built once per distinct code."""
    code = np.zeros(n, dtype=np.int64)
    for k, passing in enumerate(passes):
        code |= np.broadcast_to(np.asarray(passing, dtype=np.int64), (n,)) << k
    seen = np.flatnonzero(np.bincount(code, minlength=1))
    cheaper_text = np.empty(seen.size, dtype=object)
    passing_text = np.empty(seen.size, dtype=object)
    for i, c in enumerate(seen.tolist()):
        chosen = [m for k, m in enumerate(candidates) if c >> k & 1]
        cheaper_text[i], passing_text[i] = _method_text(chosen, own_rank)
    where = np.zeros(int(seen[-1]) + 1, dtype=np.int64)
    where[seen] = np.arange(seen.size)
    index = where[code]
    return cheaper_text[index], passing_text[index]


#: The outputs of ``preload.control`` that read the band's ends or the yield preload.
_BAND_READERS = (
    "preload_min",
    "preload_max",
    "yield_preload",
    "min_meets_clamp",
    "max_below_yield",
    "cheaper_methods",
    "passing_methods",
    *_BOUGHT_PART_OUTPUTS,
)


def _band_verdicts(
    x: Mapping[str, Any],
    bolt: BoltArrays,
    method: ControlMethod,
    stretch: Any,
    values: dict[str, Any],
    verdicts: dict[str, Any],
    ctx: RunContext,
    n: int,
) -> None:
    """The array path's checks of the band (and the bought parts' at its top), into
    ``values`` and ``verdicts``; the cheaper and passing methods where asked for."""
    permissible, at_yield = values["permissible_preload"], values["yield_preload"]
    f_min, f_max = values["preload_min"], values["preload_max"]
    required = values["required_preload"]
    _bought_part_verdicts(x, bolt, f_max, values["target_torque"], values, verdicts)
    top = at_yield * (1.0 + 1e-12)
    meets, below = f_min >= required, f_max <= top
    values["min_meets_clamp"] = meets
    values["max_below_yield"] = below
    verdicts["min_meets_clamp"] = meets
    verdicts["max_below_yield"] = below
    if ctx.wants("cheaper_methods", "passing_methods"):
        candidates, passes = _passing(
            x, bolt, method, (permissible, at_yield, x.get("preload"), required), stretch
        )
        values["cheaper_methods"], values["passing_methods"] = _method_texts(
            candidates, passes, method.cost_rank, n
        )


def _also(ok: np.ndarray, fine: Any) -> np.ndarray:
    """``ok & fine`` per point, as a new array; ``ok`` itself where ``fine`` is one True
    (a condition every point meets costs no pass)."""
    if fine is True or fine is np.True_:
        return ok
    return ok & fine


def _control_vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    """The array path of ``preload.control``: its numbers on many points at once.

    The friction histogram (a series) is not part of it; its min, max and mean are.
    """
    n = _points(x) or 1
    bolt, notes = resolve_bolts(x, n, labels=ctx.wants("fastener"))
    ok = bolt.ok
    verdicts: dict[str, Any] = {}
    method = get_method(str(x["method"]))
    mu_g, mu_k = x["thread_friction"], x["bearing_friction"]
    formula = str(x["torque_formula"])
    d0, area0, _, fine = _smallest_section(bolt, x)
    ok = _also(ok, fine)
    # the band's ends and the yield preload: for the checks and the outputs that read them
    band = ctx.checks or x.get("nut") is not None or ctx.wants(*_BAND_READERS)
    values, _ = _control_values(x, bolt, method, (d0, area0), band=band)
    nut, nut_verdicts = values.pop("_nut")
    verdicts.update(_nut_verdicts(nut_verdicts))
    warnings = []
    if nut is not None and np.any(ok & (nut.proof_load < nut.bolt_preload)):
        warnings.append(nut_limit_warning(nut.choice, None, None))
    nominal, torque = values["nominal_preload"], values["target_torque"]
    stretch: Any = None
    if x.get("clamped_length") is not None:
        lengths, diameters, fine = _grip_sections(bolt, x)
        ok = _also(ok, fine)
        parts = _clamped_compliance(bolt, x, method, ok)
        values.update(_stretch_values(x, bolt, lengths, diameters, parts, nominal))
        stretch = values["bolt_compliance"] + parts
        if method.key == "torque_then_angle":
            values.update(_snug_values(x, bolt, values, stretch))
        angle = values["target_angle"]
        if method.controls in ("angle", "displacement"):
            verdicts["angle_resolution"] = angle * method.scatter >= ANGLE_READING_ERROR
    elif method.controls in ("angle", "elongation", "displacement"):
        raise InputOutOfRange(
            f"method {method.key!r} sets the {method.controls}; give clamped_length",
            field="clamped_length",
        )
    if method.controls == "displacement" and x.get("coupling_outer_diameter") is None:
        raise InputOutOfRange(
            f"method {method.key!r} sets a circumferential displacement; give "
            "coupling_outer_diameter",
            field="coupling_outer_diameter",
        )
    if band:
        _band_verdicts(x, bolt, method, stretch, values, verdicts, ctx, n)
    else:
        _bought_part_refusals(x, bolt)

    scatter_wanted = ctx.wants(
        "scatter_preload_min",
        "scatter_preload_max",
        "scatter_preload_mean",
        "scatter_relative",
        "scatter_torque_applied",
    )
    has_range = (
        x.get("thread_friction_min") is not None or x.get("bearing_friction_min") is not None
    )
    if scatter_wanted and has_range:
        g_lo, g_hi, fine_g = _range(x, "thread_friction", mu_g)
        k_lo, k_hi, fine_k = _range(x, "bearing_friction", mu_k)
        ok = _also(ok, fine_g & fine_k)
        if bolt.bearing_friction_factor != 1.0:  # a countersunk head: μ_K acts on the cone
            k_lo, k_hi = k_lo * bolt.bearing_friction_factor, k_hi * bolt.bearing_friction_factor
        fixed = torque if x.get("scatter_torque") is None else x["scatter_torque"]
        low, high, mean = _scatter_band(bolt, formula, fixed, (g_lo, g_hi), (k_lo, k_hi))
        notes.append(SCATTER_MEAN_NOTE)
        values.update(
            scatter_preload_min=low,
            scatter_preload_max=high,
            scatter_preload_mean=mean,
            scatter_relative=(high - low) / (high + low),
            scatter_torque_applied=fixed,
        )
    elif scatter_wanted and (
        x.get("thread_friction_max") is not None or x.get("bearing_friction_max") is not None
    ):
        raise InputOutOfRange(
            "give thread_friction_min with thread_friction_max (and bearing_friction_min with "
            "bearing_friction_max)",
            field="thread_friction_min",
        )
    columns, finite = _finish(values, ok, n, ctx.outputs, _borrowed(x, bolt))
    return Result(
        values=columns,
        rung=ctx.rung,
        error_estimate=None,
        notes=notes,
        warnings=warnings,
        check_arrays=_verdicts(verdicts, ok, n) if ctx.checks else {},
        finite=finite,
    )


CONTROL_OUTPUTS: tuple[Output, ...] = (
    Output(
        "controlled_quantity",
        "1",
        "What the method sets: torque, angle, elongation, force, displacement or yield",
        kind="str",
        symbol="",
        step="[004, eq. 7–9]",
    ),
    Output(
        "target_torque",
        "N*m",
        "Torque for the nominal preload F_nom (the middle of the method's band: F_M,zul/(1 + "
        "scatter), or the preload given) at the given friction μ_G, μ_K, by torque_formula; not "
        "VDI 2230-1 R13's M_A for F_M,zul at μ_G,min, μ_K,min (joint.vdi2230 tightening_torque)",
        symbol="M_A",
        step="[004, eq. 13]",
    ),
    Output(
        "target_angle",
        "rad",
        "Nut rotation from snug for the nominal preload ([004, eq. 8/9])",
        display_unit="deg",
        symbol="φ",
        step="[004, eq. 8]",
    ),
    Output(
        "snug_torque",
        "N*m",
        "torque_then_angle: torque to snug, M_snug = s_snug × target_torque (the first step, "
        "[004] after eq. 19)",
        symbol="M_snug",
        step="[004, after eq. 19]",
    ),
    Output(
        "snug_preload",
        "N",
        "torque_then_angle: preload at the snug point, s_snug × F_nom",
        display_unit="kN",
        symbol="F_snug",
        step="[004, after eq. 19]",
    ),
    Output(
        "angle_after_snug",
        "rad",
        "torque_then_angle: the angle to turn beyond snug, θ = (F_nom − F_snug)(λ_b + λ_p)/P "
        "· 360° ([004, eq. 8])",
        display_unit="deg",
        symbol="θ",
        step="[004, eq. 8]",
    ),
    Output(
        "target_elongation",
        "m",
        "Bolt elongation at the nominal preload, Δl = F0 λ_b ([004, eq. 7])",
        display_unit="mm",
        symbol="Δl",
        step="[004, eq. 7]",
    ),
    Output(
        "target_displacement",
        "m",
        "Sucker rods: circumferential displacement of the marks on the coupling, φ·D_c/2",
        display_unit="mm",
        symbol="s_c",
        step="[004, sucker rods]",
    ),
    Output(
        "target_force",
        "N",
        "Force the washer/ring is set to (= nominal preload)",
        display_unit="kN",
        symbol="F_0",
        step="[004, measuring washers]",
    ),
    Output(
        "nominal_preload",
        "N",
        "Middle of the method's preload band",
        display_unit="kN",
        symbol="F_nom",
        step="[004, eq. 2]",
    ),
    Output(
        "preload_min",
        "N",
        "Lowest preload the method gives, F_nom (1 − s)",
        display_unit="kN",
        symbol="F_M,min",
        step="VDI 2230-1 R1",
    ),
    Output(
        "preload_max",
        "N",
        "Highest preload the method gives, F_nom (1 + s)",
        display_unit="kN",
        symbol="F_M,max",
        step="VDI 2230-1 R1",
    ),
    Output(
        "scatter",
        "1",
        "The method's preload scatter ±s",
        symbol="±s",
        step="[004, control methods]",
    ),
    Output(
        "tightening_factor",
        "1",
        "α_A = (1 + s)/(1 − s) (VDI 2230 Table A8)",
        symbol="α_A",
        step="VDI 2230-1 Table A8",
    ),
    Output(
        "required_preload",
        "N",
        "υ × required clamp force ([004, eq. 2])",
        display_unit="kN",
        symbol="υ F_K",
        step="[004, eq. 2]",
    ),
    Output("preload_factor", "1", "υ used", symbol="υ", step="[004, eq. 2]"),
    Output(
        "permissible_preload",
        "N",
        "Preload at ν·R_p0.2 (VDI 2230 R7)",
        display_unit="kN",
        symbol="F_M,zul",
        step="VDI 2230-1 R7",
    ),
    Output(
        "yield_preload",
        "N",
        "Preload at which σ_red reaches R_p0.2 (ν = 1)",
        display_unit="kN",
        symbol="F_M0.2",
        step="VDI 2230-1 R7",
    ),
    Output(
        "min_meets_clamp",
        "1",
        "preload_min ≥ required_preload",
        kind="bool",
        symbol="",
        step="[004, eq. 2]",
    ),
    Output(
        "max_below_yield",
        "1",
        "preload_max ≤ yield_preload",
        kind="bool",
        symbol="",
        step="VDI 2230-1 R7",
    ),
    Output(
        "cheaper_methods",
        "1",
        "Cheaper methods of the same family that would also pass both checks ('none' if none)",
        kind="str",
        symbol="",
        step="[004, eq. 7–9]",
    ),
    Output(
        "passing_methods",
        "1",
        "Every method of the same family that passes both checks, cheapest first",
        kind="str",
        symbol="",
        step="[004, eq. 7–9]",
    ),
    Output(
        "bolt_compliance",
        "m/N",
        "λ_b = Σ l_i/(E A_i) incl. m/3 at d3 ([004, eq. 4, 7])",
        symbol="λ_b",
        step="[004, eq. 7]",
    ),
    Output("clamped_compliance", "m/N", "λ_p used", symbol="λ_p", step="[004, eq. 8]"),
    Output(
        "equivalent_shank_diameter",
        "m",
        "d_eq of the stretched length ([004, eq. 4])",
        display_unit="mm",
        symbol="d_eq",
        step="[004, eq. 4]",
    ),
    Output(
        "scatter_torque_applied",
        "N*m",
        "Friction scatter: the tightening torque the histogram and the scatter band are "
        "computed at (the target torque, or scatter_torque where given)",
        display_unit="N*m",
        symbol="M_A",
        step="[004, eq. 13]",
    ),
    Output(
        "scatter_preload_min",
        "N",
        "Friction scatter: lowest preload (μ_G and μ_K at their maximum: the corner)",
        display_unit="kN",
        symbol="F_M,min",
        step="[004, eq. 13]",
    ),
    Output(
        "scatter_preload_max",
        "N",
        "Friction scatter: highest preload (μ_G and μ_K at their minimum: the corner)",
        display_unit="kN",
        symbol="F_M,max",
        step="[004, eq. 13]",
    ),
    Output(
        "scatter_preload_mean",
        "N",
        "Friction scatter: mean preload over μ_G, μ_K independent and uniform (exact)",
        display_unit="kN",
        symbol="F̄_M",
        step="[004, eq. 13]",
    ),
    Output(
        "scatter_relative",
        "1",
        "Friction scatter: (max − min)/(max + min), the ± of [004, fig. 5]",
        symbol="±s",
        step="[004, eq. 13]",
    ),
    Output(
        "preload_bins",
        "N",
        "Friction scatter: preload bin centres of the histogram of a 64×64 midpoint grid of "
        "μ_G × μ_K (the grid's own extremes lie half a cell inside the exact band)",
        series=True,
        display_unit="kN",
    ),
    Output(
        "preload_counts",
        "1",
        "Friction scatter: expected number of bolts (of sample_size) per bin, from the 64×64 "
        "midpoint grid's histogram",
        series=True,
        x="preload_bins",
        plot=Plot(bars=True),
    ),
    *fz.CHECK_OUTPUTS,
    *NUT_OUTPUTS,
)

CONTROL = ModelSpec(
    name="preload.control",
    answer=(
        Answer("target_torque", "M_A"),
        Answer(
            "preload_min",
            "F_M,min",
            check="min_meets_clamp",
            relation="≥",
            bound="required_preload",
            bound_symbol="υ F_K",
        ),
        Answer(
            "preload_max",
            "F_M,max",
            check="max_below_yield",
            relation="≤",
            bound="yield_preload",
            bound_symbol="F_M0.2",
        ),
        Answer("tightening_factor", "α_A"),
    ),
    title="Preload control: target value, preload band and friction scatter",
    family="preload",
    summary=(
        "For a bolt, a required clamp force and a control method: the value to set (torque, "
        "angle, elongation, force or mark displacement), the preload band the method's "
        "scatter gives, whether its bottom clamps and its top stays below yield, cheaper "
        "methods that would also do, and the preload histogram at a fixed torque when the "
        "friction coefficients scatter."
    ),
    source=SOURCE,
    inputs=CONTROL_INPUTS,
    outputs=CONTROL_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_control,
    vectorized=_control_vectorized,
    vector_rungs=("closed_form",),
    examples=(
        # [004, fig. 5]: 5/8"-11 UNC bolts at 80 N·m, friction 0.10…0.20 -> about ±30 %
        {
            "thread_diameter": 0.015875,
            "thread_pitch": 0.0254 / 11,
            "yield_strength": 640e6,
            "bearing_outer_diameter": 0.0226,
            "hole_diameter": 0.0175,
            "thread_friction": 0.15,
            "bearing_friction": 0.15,
            "required_clamp_force": 15e3,
            "method": "torque_wrench",
            "thread_friction_min": 0.10,
            "thread_friction_max": 0.20,
            "bearing_friction_min": 0.10,
            "bearing_friction_max": 0.20,
            "scatter_torque": 80.0,
        },
        {
            "thread_diameter": 0.012,
            "required_clamp_force": 20e3,
            "method": "nut_angle",
            "clamped_length": 0.12,
            "shank_length": 0.08,
        },
        # bought parts: socket head M8 12.9 into aluminium, too short an engagement
        {
            "thread": "M8 ISO 4762 12.9",
            "required_clamp_force": 12e3,
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "engagement_length": 0.008,
        },
        {"thread": "1/2-13 UNC", "grade": "SAE 5", "required_clamp_force": 15e3},
    ),
)
