"""Model spec for the bolted joint after VDI 2230 Part 1 (``joint.vdi2230``).

The physics lives in :mod:`engine.physics.joint` (one function per VDI step), the
bolt data in :mod:`engine.physics.threads`, the tightening relations in
:mod:`engine.physics.preload` and the bolt resolution in the preload declarations;
this module turns a request into a joint, runs the steps R0–R13 in order and
says which step every number comes from.

Surface pressure (VDI R10) and the length of engagement / thread stripping
(VDI R11) belong to the fastener catalogue; they plug in through
:data:`CHECK_HOOKS` without touching this module's compute.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import partial
from typing import Any, NamedTuple

import numpy as np

from ..core.errors import InputOutOfRange
from ..core.points import all_finite, swept_ends
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    fixed_error,
)
from ..core.text import q
from ..physics import fasteners as fa
from ..physics import joint as jt
from ..physics import preload as pl
from ..physics import threads as th
from ..physics.preload_methods import METHODS, get_method
from ..procedures import bolt as fz
from ..procedures.bolt import Bolt, resolve_bolt, resolve_bolts
from .preload import (
    BOLT_INPUTS,
    NUT_CLASS_INPUT,
    nut_class_pairing_text,
    nut_limit_warning,
    nut_paired_note,
    nut_strength_text,
    nut_stripping_text,
)

SOURCE = (
    "VDI 2230-1:2015 steps R0–R13 (text paywalled: relations as reproduced in "
    "ECSS-E-HB-32-23A §6–7 and the open implementation misams/BAT); [004] eq. 2–8 for the "
    "review's preload rules; ISO 68-1, 261, 273, 898-1, 4017; nut proof loads of ISO 898-2:1992 "
    "(EN 20898-2)"
)

#: Bolt-family control methods (the sucker-rod ones do not tighten a bolted joint).
BOLT_METHOD_KEYS: tuple[str, ...] = tuple(m.key for m in METHODS if m.family == "bolt")

#: Steel: Young's modulus [Pa] and thermal expansion [1/K] used as defaults.
STEEL_E = 2.1e11
STEEL_ALPHA = 11.5e-6

MAX_PLATES = 3

#: VDI 2230-1's scope in temperature: −40 °C up to the top of ISO 898-1 Annex A (300 °C) [K].
#: Below 20 °C the tables' 20 °C ratio 1 holds (R_p0.2 and E rise in the cold: conservative).
COLDEST_SERVICE_K = fa.CELSIUS_ZERO - 40.0
#: The relative slack on those bounds, for a temperature converted from °F or °C (68 °F is
#: 293.1499999999992 K, −40 °C is 233.14999999999998 K).
TEMPERATURE_BOUND_SLACK = 1e-9

# --------------------------------------------------------------------------- inputs

_BOLT_NAMES = (
    "thread",  # a designation ("M12 ISO 4762 10.9", "1/2-13 UNC"): a bought part
    "grade",
    "thread_diameter",
    "thread_pitch",
    "property_class",
    "yield_strength",
    "bearing_outer_diameter",
    "hole_diameter",
    "hole_series",
    "utilization",
)


def _length(name: str, description: str, **kw: Any) -> Param:
    kw.setdefault("maximum", 10.0)
    return Param(name, "m", description, display_unit="mm", **kw)


def _plate_inputs(i: int) -> tuple[Param, ...]:
    first = i == 1
    return (
        _length(
            f"plate{i}_thickness",
            f"Thickness h_{i} of clamped plate {i} (from the head side)"
            + ("" if first else "; absent or 0: no such plate"),
            required=first,
            minimum=0.0,
            exclusive_minimum=first,
            group="plates",
        ),
        Param(
            f"plate{i}_youngs_modulus",
            "Pa",
            f"Young's modulus E_{i} of plate {i}"
            + (" (steel 210 GPa)" if first else "; plate 1's when absent"),
            default=STEEL_E if first else None,
            minimum=1e8,
            maximum=1e12,
            display_unit="GPa",
            group="plates",
        ),
        Param(
            f"plate{i}_expansion",
            "1/K",
            f"Thermal expansion coefficient α_{i} of plate {i}"
            + (
                " (steel 11.5e-6 /K; type e.g. '23e-6 K^-1')"
                if first
                else "; plate 1's when absent"
            ),
            default=STEEL_ALPHA if first else None,
            minimum=0.0,
            maximum=1e-3,
            group="plates",
        ),
        *(
            ()
            if first
            else (
                _length(
                    f"plate{i}_outer_diameter",
                    f"Outer diameter D_A,{i} of plate {i} (VDI 2230-1 R3: its part of the cone "
                    "is capped there, a sleeve below d_W); outer_diameter (plate 1's) when "
                    "absent",
                    minimum=0.0,
                    exclusive_minimum=True,
                    symbol=f"D_A,{i}",
                    group="plates",
                ),
            )
        ),
    )


JOINT_INPUTS: tuple[Param, ...] = (
    *(p for p in BOLT_INPUTS if p.name in _BOLT_NAMES),
    Param(
        "head",
        "1",
        "Head type: 'hex' (l_SK = 0.5 d) or 'socket' (0.4 d), VDI 2230-1 R3",
        default="hex",
        kind="choice",
        choices=tuple(jt.HEAD_LENGTH_FACTOR),
        group="bolt",
    ),
    Param(
        "joint_type",
        "1",
        "'through': bolt and nut (DSV); 'tapped': screwed into the last part (ESV)",
        default="through",
        kind="choice",
        choices=tuple(jt.NUT_LENGTH_FACTOR),
        group="joint",
    ),
    _length(
        "shank_length",
        "Length of plain shank inside the grip; the rest of the grip is free thread",
        default=0.0,
        minimum=0.0,
        group="bolt",
    ),
    _length(
        "shank_diameter",
        "Plain shank diameter; d when absent",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        group="bolt",
    ),
    _length(
        "reduced_length",
        "Length of a reduced (waisted) shank inside the grip",
        default=0.0,
        minimum=0.0,
        group="bolt",
    ),
    _length(
        "reduced_diameter",
        "Diameter d_T of the reduced shank (needed when reduced_length > 0); the strength "
        "limit F_M,zul is taken at the smallest section (VDI 2230-1 R7)",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        group="bolt",
    ),
    Param(
        "youngs_modulus",
        "Pa",
        "Young's modulus of the bolt E_S",
        default=STEEL_E,
        minimum=1e9,
        maximum=1e12,
        display_unit="GPa",
        group="bolt",
    ),
    Param(
        "nut_youngs_modulus",
        "Pa",
        "Young's modulus E_M of the nut or of the part with the tapped thread; E_S when absent",
        minimum=1e8,
        maximum=1e12,
        display_unit="GPa",
        group="bolt",
    ),
    Param(
        "bolt_expansion",
        "1/K",
        "Thermal expansion coefficient α_S of the bolt",
        default=STEEL_ALPHA,
        minimum=0.0,
        maximum=1e-3,
        group="bolt",
    ),
    *_plate_inputs(1),
    *_plate_inputs(2),
    *_plate_inputs(3),
    _length(
        "outer_diameter",
        "Outer diameter D_A of the clamped parts (equivalent); absent: plates wide enough "
        "for the full deformation cone. Must be ≥ the bearing diameter d_W",
        minimum=0.0,
        exclusive_minimum=True,
        group="plates",
    ),
    Param(
        "load_introduction",
        "1",
        "Load-introduction factor n (VDI 2230-1 R3): 1 under the head and nut, "
        "0.5 typical, lower when the load enters near the interface",
        default=0.5,
        minimum=0.0,
        maximum=1.0,
        symbol="n",
        group="loads",
    ),
    _length(
        "bolt_offset",
        "Eccentric clamping (VDI 2230-1 §5.3.2): distance s_sym of the bolt axis from the axis "
        "O–O of the clamped body, positive towards the working load's line; 0: concentric",
        default=0.0,
        minimum=-1.0,
        maximum=1.0,
        symbol="s_sym",
        group="eccentric",
    ),
    _length(
        "load_lever",
        "Eccentric loading: distance a of the working load's line from the axis O–O; 0: the "
        "load acts on the body's axis",
        default=0.0,
        minimum=0.0,
        symbol="a",
        group="eccentric",
    ),
    _length(
        "opening_edge",
        "Distance u from O–O of the interface edge that opens first (on the load's side); 0: "
        "no opening requirement F_KA",
        default=0.0,
        minimum=0.0,
        symbol="u",
        group="eccentric",
    ),
    _length(
        "interface_length",
        "Length c_T of the interface in the bending plane (needed with s_sym, a or u ≠ 0)",
        minimum=0.0,
        exclusive_minimum=True,
        symbol="c_T",
        group="eccentric",
    ),
    _length(
        "interface_width",
        "Width b of the interface across the bending plane (needed with c_T)",
        minimum=0.0,
        exclusive_minimum=True,
        symbol="b",
        group="eccentric",
    ),
    Param(
        "working_load",
        "N",
        "Axial working load F_A,max per bolt (0: preload only)",
        default=0.0,
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        symbol="F_A",
        group="loads",
    ),
    Param(
        "working_load_min",
        "N",
        "Lower axial working load F_A,min of an alternating load; static (= F_A,max) when absent",
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        group="loads",
    ),
    Param(
        "transverse_load",
        "N",
        "Transverse load F_Q,max per bolt carried by interface friction",
        default=0.0,
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        symbol="F_Q",
        group="loads",
    ),
    Param(
        "slip_interfaces",
        "1",
        "Number q_F of interfaces that carry the transverse load",
        default=1,
        kind="int",
        minimum=1,
        maximum=20,
        group="loads",
    ),
    _length(
        "fitted_diameter",
        "Fitted bolt: diameter d_τ of the fitted shank that carries F_Q in shear and bearing "
        "(VDI 2230-1 R12); absent: the interfaces carry F_Q by friction alone",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        symbol="d_τ",
        group="loads",
    ),
    Param(
        "torsional_moment",
        "N*m",
        "Torsional moment M_Y,max about the bolt axis carried by interface friction (VDI "
        "2230-1 R2/R12); needs friction_radius",
        default=0.0,
        minimum=0.0,
        maximum=1e7,
        symbol="M_Y",
        group="loads",
    ),
    Param(
        "torque_interfaces",
        "1",
        "Number q_M of interfaces that carry the torsional moment",
        default=1,
        kind="int",
        minimum=1,
        maximum=20,
        group="loads",
    ),
    _length(
        "friction_radius",
        "Friction radius r_a of the interface for the torsional moment (needed with M_Y > 0)",
        minimum=0.0,
        exclusive_minimum=True,
        symbol="r_a",
        group="loads",
    ),
    Param(
        "interface_friction",
        "1",
        "Smallest interface friction coefficient μ_T,min (VDI 2230-1 Table A6: 0.1…0.2 dry steel)",
        default=0.15,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        group="loads",
    ),
    Param(
        "sealing_clamp_force",
        "N",
        "Clamp force F_KP that must remain for sealing or other reasons (added to the "
        "friction requirement's maximum, VDI 2230-1 R2)",
        default=0.0,
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        group="loads",
    ),
    Param(
        "surface_roughness",
        "1",
        "Mean roughness depth class of the bearing faces and interfaces (embedding, VDI R4)",
        default="Rz10-40",
        kind="choice",
        choices=jt.ROUGHNESS_CLASSES,
        group="losses",
    ),
    Param(
        "temperature_change",
        "K",
        "Service temperature minus assembly temperature of the bolt ΔT_S",
        default=0.0,
        minimum=-300.0,
        maximum=1000.0,
        group="losses",
    ),
    Param(
        "plate_temperature_change",
        "K",
        "Temperature change of the plates ΔT_P; ΔT_S when absent",
        minimum=-300.0,
        maximum=1000.0,
        group="losses",
    ),
    Param(
        "bolt_modulus_ratio",
        "1",
        "E of the bolt at service temperature / at room temperature",
        default=1.0,
        minimum=0.1,
        maximum=1.5,
        group="losses",
    ),
    Param(
        "plate_modulus_ratio",
        "1",
        "E of the plates at service temperature / at room temperature",
        default=1.0,
        minimum=0.1,
        maximum=1.5,
        group="losses",
    ),
    Param(
        "service_temperature",
        "K",
        "Absolute temperature of bolt and plates in service (e.g. '150 degC'); absent: room "
        "temperature; −40…300 °C (below 20 °C the 20 °C values, conservative). At it R_p0.2 "
        "of the bolt's class (ISO 898-1 Annex A: 5.6, 8.8, 10.9, "
        "12.9) sets R8 (R7 stays at room temperature: the bolt is tightened cold), and E of "
        "bolt and plates (tables by material) set the thermal "
        "preload loss in place of bolt_modulus_ratio and plate_modulus_ratio",
        minimum=COLDEST_SERVICE_K * (1.0 - TEMPERATURE_BOUND_SLACK),
        maximum=fa.temperature_range(fa.PROOF_STRENGTH_TEMPERATURES_C)[1]
        * (1.0 + TEMPERATURE_BOUND_SLACK),
        symbol="T",
        group="losses",
    ),
    Param(
        "thread_friction_min",
        "1",
        "Smallest thread friction μ_G,min (sets F_M,zul and the highest preload)",
        default=0.12,
        minimum=0.0,
        maximum=1.0,
        group="friction",
    ),
    Param(
        "thread_friction_max",
        "1",
        "Largest thread friction μ_G,max (sets the lowest preload at a torque); μ_G,min "
        "when absent",
        minimum=0.0,
        maximum=1.0,
        group="friction",
        used_with="tightening_torque",
    ),
    Param(
        "bearing_friction_min",
        "1",
        "Smallest bearing-face friction μ_K,min",
        default=0.12,
        minimum=0.0,
        maximum=1.0,
        group="friction",
    ),
    Param(
        "bearing_friction_max",
        "1",
        "Largest bearing-face friction μ_K,max; μ_K,min when absent",
        minimum=0.0,
        maximum=1.0,
        group="friction",
        used_with="tightening_torque",
    ),
    Param(
        "method",
        "1",
        "Tightening method: its scatter gives α_A (GET /api/v1/preload/methods)",
        default="torque_wrench",
        kind="choice",
        choices=BOLT_METHOD_KEYS,
        group="tightening",
    ),
    Param(
        "tightening_factor",
        "1",
        "α_A = F_M,max/F_M,min (VDI 2230-1 R1, Table A8); the method's when absent",
        minimum=1.0,
        maximum=5.0,
        symbol="α_A",
        group="tightening",
    ),
    Param(
        "tightening_torque",
        "N*m",
        "Torque specification M_A (including the prevailing torque): when given, the "
        "assembly preload range comes from it and the friction box",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e6,
        group="tightening",
    ),
    Param(
        "torque_tolerance",
        "1",
        "Relative torque tolerance ± of the tool (0.05 for ±5 %)",
        default=0.0,
        minimum=0.0,
        maximum=0.9,
        group="tightening",
        used_with="tightening_torque",
    ),
    Param(
        "prevailing_torque",
        "N*m",
        "Prevailing (locking) torque M_ü that produces no preload",
        default=0.0,
        minimum=0.0,
        maximum=1e5,
        group="tightening",
    ),
    Param(
        "prevailing_torque_min",
        "N*m",
        "Smallest prevailing torque M_ü,min (sets the highest preload); prevailing_torque when "
        "absent",
        minimum=0.0,
        maximum=1e5,
        group="tightening",
    ),
    Param(
        "controlled",
        "1",
        "Tightened with a controlled method (false: by feel, [004] warns of over-tightening "
        "below M10)",
        default=True,
        kind="bool",
        group="tightening",
    ),
    Param(
        "bridge_joint",
        "1",
        "High-strength bridge joint: [004] allows σ0 = 0.8…0.9 σ_T",
        default=False,
        kind="bool",
        group="tightening",
    ),
    Param(
        "rolling",
        "1",
        "Thread rolled before or after heat treatment (endurance limit, VDI 2230-1 R9)",
        default="before_heat_treatment",
        kind="choice",
        choices=("before_heat_treatment", "after_heat_treatment"),
        group="fatigue",
    ),
    # bought-part checks: surface pressure VDI 2230-1 R10, engagement R11
    *(p for p in fz.CHECK_INPUTS if p.name != "working_bolt_force"),
    NUT_CLASS_INPUT,
)

# --------------------------------------------------------------------------- hooks

#: Further checks on the solved joint: each hook takes the inputs and the solved
#: :class:`JointSolution` and returns checks and notes. Surface pressure under head
#: and nut (VDI 2230-1 R10) and the length of engagement / thread stripping (R11)
#: are meant to plug in here from the fastener catalogue.
CheckHook = Callable[[Mapping[str, Any], "JointSolution"], tuple[list[Check], list[str]]]
CHECK_HOOKS: list[CheckHook] = [fz.joint_check_hook]


class JointSolution(NamedTuple):
    """The solved joint a check hook sees (SI; a named tuple: immutable, and cheap to build
    on every single-design run)."""

    bolt: Bolt
    grip: float
    bearing_diameter: float
    hole_diameter: float
    assembly_preload_max: float
    max_bolt_force: float
    joint_type: str
    #: D_A of the plate under the nut (the last plate's, or plate 1's), None: wide plates.
    nut_outer_diameter: float | None = None


_INPUTS_BY_NAME = {p.name: p for p in JOINT_INPUTS}

#: Each plate's input names: (number, thickness, E, α, D_A), plate 1 first.
_PLATE_FIELDS = tuple(
    (
        i,
        f"plate{i}_thickness",
        f"plate{i}_youngs_modulus",
        f"plate{i}_expansion",
        f"plate{i}_outer_diameter",
    )
    for i in range(1, MAX_PLATES + 1)
)


def _nut_side_outer(x: Mapping[str, Any], read: Callable[[str], Any]) -> Any:
    """D_A of the plate the nut bears on: the last plate's own, else plate 1's; None: wide."""
    own = "plate1_outer_diameter"
    for _, thickness, _, _, outer in _PLATE_FIELDS:
        if x.get(thickness) is not None:
            own = outer
    if x.get(own) is not None:
        return read(own)
    return None if x.get("outer_diameter") is None else read("outer_diameter")


# --------------------------------------------------------------------------- helpers


def _kn(force: float) -> str:
    return q(force, "kN", 4)


# --------------------------------------------------------------------------- the procedure
#
# One procedure for one design or many: ``_solve`` runs the VDI 2230-1 steps R0–R13 on
# floats (a single run: :func:`_compute`) or on numpy arrays, one entry per point (a sweep,
# a study's chunk: :func:`_vectorized`). Every relation is a function of engine.physics.joint or
# engine.physics.preload; the adapters below only turn inputs into columns and the solved joint
# into a result. A point the physics refuses is refused by the same line on both paths:
# alone it raises (InputOutOfRange naming the field, or an arithmetic error the runner
# reports), among many it is masked and null in every output.


class _Refusals:
    """The points a procedure refuses: raises at once for one design, masks for many."""

    __slots__ = ("many", "mask")

    def __init__(self, mask: Any, many: bool) -> None:
        self.mask = mask
        self.many = many

    def add(self, where: Any, field: str, message: Callable[..., str], *args: Any) -> None:
        """Refuse where ``where`` holds, naming ``field`` and the allowed range
        (``message(*args)``: made only when one design is refused)."""
        if self.many:
            self._mask(where)
        elif where:
            raise InputOutOfRange(message(*args), field=field)

    def arithmetic(self, where: Any, what: str) -> None:
        """Refuse where the arithmetic fails (alone: as Python's float arithmetic does)."""
        if self.many:
            self._mask(where)
        elif where:
            raise ZeroDivisionError(what)

    def _mask(self, where: Any) -> None:
        # a condition that refuses nothing (a fixed input's one value, or no point of a
        # varied one) leaves the mask as it is: no new mask of the points is made
        if where.any() if isinstance(where, np.ndarray) else where:
            self.mask = self.mask | where


_TOO_WIDE = "{0} = {1:g} mm exceeds the thread diameter d = {2:g} mm: must be ≤ {2:g} mm"


def _larger(a: Any, b: Any) -> Any:
    if type(a) is float and type(b) is float:  # one design: what max(a, b) returns
        return b if b > a else a
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.maximum(a, b)
    return max(a, b)


def _pick(condition: Any, a: Any, b: Any) -> Any:
    if isinstance(condition, np.ndarray) or isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.where(condition, a, b)
    return a if condition else b


def _nut_choice(
    x: Mapping[str, Any], bolt_tensile_strength: float | None, thread: fa.Thread | None
) -> tuple[fa.NutChoice, fa.Nut | None, float | None] | None:
    """The nut's class (:func:`engine.physics.fasteners.nut_choice`), where the thread is a
    catalogue one its dimensions (height and width across flats, for R11's stripping), and
    the bolt's R_m it was rated with."""
    if x.get("nut") is None:
        return None
    cls = x.get("nut_property_class")
    choice = fa.nut_choice(str(x["nut"]), None if cls is None else str(cls), bolt_tensile_strength)
    part = None if thread is None else fa.nut(choice.standard, thread)
    return choice, part, bolt_tensile_strength


#: What the error estimate of 0 leaves out (said with every answer, on both paths).
MODEL_FORM_NOTE = (
    "error estimate 0 (typical, not a bound): the arithmetic of VDI 2230's model is exact here, "
    "the model is not; "
    "its empirical parts (the cone-angle fit behind δ_P, the embedding amounts f_Z of Table "
    "5.4/1, the load-introduction factor n, the friction range) carry an uncertainty that no "
    "number here includes: read Φ_n, F_Z and the safeties as nominal"
)

#: The bolts VDI 2230-1 R9's σ_ASV = 0.85 (150/d + 45) was fitted to: ISO 898-1 classes.
_R9_CLASSES = ("8.8", "9.8", "10.9", "12.9")


def _r9_outside(x: Mapping[str, Any], bolt: Bolt) -> str | None:
    """Why R9's endurance limit does not hold for this bolt (None: it does)."""
    fastener = bolt.fastener
    grade = fastener.grade.name if fastener is not None and fastener.grade is not None else None
    # a typed yield strength overrides the class (whose default then names nothing)
    typed = x.get("yield_strength") is not None or x.get("property_class") is None
    name = grade or (None if typed else str(x["property_class"]))
    why = []
    if name is None:
        why.append("the bolt's property class is unknown (yield_strength given)")
    elif name not in _R9_CLASSES:
        why.append(f"{name} is not an ISO 898-1 class 8.8–12.9")
    if fastener is not None and fastener.thread is not None and not fastener.thread.is_metric:
        why.append("an inch thread")
    if bolt.diameter > 0.040 + 1e-12:
        why.append(f"d = {bolt.diameter * 1e3:g} mm > 40 mm")
    return "; ".join(why) or None


def _tapped_modulus(x: Mapping[str, Any]) -> float | None:
    """E of the part a tapped joint's thread is cut into, from ``internal_thread_material``
    (None: a through joint's nut, or a material without a listed modulus: E_S)."""
    if x["joint_type"] != "tapped" or x.get("internal_thread_material") is None:
        return None
    return fa.material_youngs_modulus(str(x["internal_thread_material"]))


def _plain(value: Any) -> Any:
    """A numpy scalar as a Python float (its arithmetic is several times faster); arrays as is."""
    return value if isinstance(value, np.ndarray) else float(value)


def _finite_or(value: Any, other: Any) -> Any:
    if isinstance(value, np.ndarray):
        return np.where(np.isfinite(value), value, other)
    return value if math.isfinite(value) else other


def _overflows_squared(value: Any) -> Any:
    """Where a finite value's square overflows (Python floats raise there; arrays give inf)."""
    if isinstance(value, np.ndarray):
        square = value * value
        if all_finite(square):
            return False  # no square is inf (nor NaN): none overflows
        return np.isfinite(value) & ~np.isfinite(square)
    return False  # a float that overflows has raised OverflowError already


def _varied_alone(value: Any, *others: Any) -> bool:
    """Whether ``value`` is an array (many points) and none of ``others`` is."""
    return isinstance(value, np.ndarray) and not any(isinstance(o, np.ndarray) for o in others)


def _declared(name: str) -> tuple[float, float]:
    """The least and the largest value input ``name`` is declared to take (±inf where
    open): the runner and the study pass no value outside it."""
    param = _INPUTS_BY_NAME[name]
    low = -math.inf if param.minimum is None else float(param.minimum)
    return low, math.inf if param.maximum is None else float(param.maximum)


def _exceeds(value: Any, varied: Any, name: str) -> Any:
    """``value > varied`` at each point, ``varied`` being input ``name``; False without a
    pass over the points where ``value`` is one number not above its declared least."""
    if type(varied) is not float and _varied_alone(varied, value) and value <= _declared(name)[0]:
        return False
    return value > varied


class _Extremes:
    """A varied input's range: as declared (no pass over the points), or its least and
    largest value at the points not refused so far (one pass each, once per mask; NaN
    where a value is NaN or every point is refused). ``known``: the least and largest at
    every point, where the caller read them (a sweep): no pass while no point is refused."""

    __slots__ = ("known", "name", "refusals", "seen", "values")

    def __init__(
        self,
        values: Any,
        name: str,
        refusals: _Refusals,
        known: tuple[float, float] | None = None,
    ) -> None:
        self.values = values
        self.name = name
        self.refusals = refusals
        self.known = known
        self.seen: dict[str, tuple[Any, float]] = {}  # "min"/"max": (mask, value)

    def declared(self) -> np.ndarray:
        return np.array(_declared(self.name))

    def points(self) -> Any:
        """The values at the points not refused."""
        mask = self.refusals.mask
        if isinstance(mask, np.ndarray):
            return self.values[~mask]
        return self.values[:0] if mask else self.values

    def _end(self, which: str) -> float:
        mask = self.refusals.mask
        if self.known is not None and not isinstance(mask, np.ndarray) and not mask:
            return self.known[0 if which == "min" else 1]  # every point, none refused
        seen = self.seen.get(which)
        if seen is None or seen[0] is not mask:
            values = self.points()
            end = float(getattr(values, which)()) if values.size else math.nan
            self.seen[which] = seen = (mask, end)
        return seen[1]

    def low(self) -> float:
        return self._end("min")

    def high(self) -> float:
        return self._end("max")


def _least_clamp_force(f_kr: Callable[[Any], Any], loads: _Extremes) -> Any:
    """F_KR (``f_kr`` of F_A) where it is least among the points not refused, F_A swept alone.

    F_KR is monotone in F_A (every rounding too): where it is ≥ 0 at both ends of F_A's
    declared range, no point has opened; else it is least at the largest F_A where it falls
    with F_A, at the least where it rises (both where that is not told), and at every point
    where a value of F_A is NaN.
    """
    bounds = f_kr(loads.declared())
    if bool(np.all(bounds >= 0.0)):
        return bounds
    falls, rises = bounds[1] <= bounds[0], bounds[1] > bounds[0]
    # each end read only where it is needed: each is a pass over the points
    ends = ([] if falls else [loads.low()]) + ([] if rises else [loads.high()])
    if any(end != end for end in ends):
        return f_kr(loads.points())
    return f_kr(np.array(ends))


def _no_stress_refusal(ranges: tuple[Callable[[], Any], ...], others: tuple[Any, ...]) -> bool:
    """Whether R8 refuses no point for σ_red,B (:func:`engine.physics.joint.service_stress` of
    F_S,max and ``others``), told without a pass over the points.

    ``ranges``: ways to a least and a largest F_S,max that bound those of the points not
    refused, cheapest first, where nothing reads σ_red,B and F_S,max is its only varied
    argument. σ_red,B grows with |F_S,max| (σ_z = F_S/A_0, then squares and a root, every
    rounding monotone), so where both ends have one sign and give a finite σ_red,B > 0, no
    point gives 0 or a square that overflows. False where no range tells it.
    """
    for ends_of in ranges:
        ends = ends_of()
        if bool(np.all(ends > 0.0)) or bool(np.all(ends < 0.0)):
            at_ends = jt.service_stress(ends, *others).equivalent
            if bool(np.all((at_ends > 0.0) & (at_ends < math.inf))):
                return True
    return False


#: The E(T) class a plate is read as from its own room-temperature E [Pa], where no material
#: is named for it (the classes' E at 20 °C: steel 212, grey iron 92…110, nodular iron 170,
#: aluminium 70 GPa): steel 190…220 GPa, grey cast iron 100…150 GPa, nodular cast iron
#: 150…175 GPa, aluminium 65…75 GPa; outside every band a plate keeps its room-temperature E.
PLATE_MODULUS_BANDS: tuple[tuple[str, float, float], ...] = (
    ("steel", 190e9, 220e9),
    ("nodular cast iron", 150e9, 175e9),
    ("grey cast iron", 100e9, 150e9),
    ("aluminium", 65e9, 75e9),
)


def _modulus_band(kind: str) -> tuple[float, float] | None:
    """The band of room-temperature E [Pa] of an E(T) class (austenitic steel: steel's)."""
    kind = "steel" if kind == "austenitic steel" else kind
    return next(((lo, hi) for k, lo, hi in PLATE_MODULUS_BANDS if k == kind), None)


def _in_band(modulus: Any, low: float, high: float) -> Any:
    """Where a modulus lies in [low, high] (1e-9 slack, for a value converted from GPa or psi)."""
    return (modulus >= low * (1.0 - 1e-9)) & (modulus <= high * (1.0 + 1e-9))


def _material_plates(x: Mapping[str, Any], numbers: list[int]) -> set[int]:
    """The plates clamped_material names: under the head (plate 1) and, through-bolted, under
    the nut (the last plate)."""
    if x.get("clamped_material") is None or not numbers:
        return set()
    return {numbers[0], numbers[-1]} if x["joint_type"] == "through" else {numbers[0]}


def _strength_class(x: Mapping[str, Any], bolt: Bolt | None) -> str | None:
    """The bolt's ISO 898-1 class (or grade) whose R_p0.2(T) applies; None where a typed
    yield strength names no class."""
    fastener = None if bolt is None else bolt.fastener
    if fastener is not None and fastener.grade is not None:
        return fastener.grade.name
    if x.get("yield_strength") is not None:  # it overrides the class, as in R9's scope
        return None
    return str(x.get("property_class") or "8.8")


def _plate_temperature_class(x: Mapping[str, Any]) -> str | None:
    """The E(T) class of the plates named by clamped_material (None: not named, or no table)."""
    name = x.get("clamped_material")
    return None if name is None else fa.MATERIAL_TEMPERATURE_CLASS.get(str(name))


@dataclass(frozen=True)
class _AtTemperature:
    """The ratios a service temperature sets (all 1 at room temperature, no input)."""

    yield_ratio: Any
    bolt_modulus_ratio: Any
    plate_modulus_ratios: list[Any]


def _at_temperature(
    x: Mapping[str, Any],
    col: Callable[[str], Any],
    b: Mapping[str, Any],
    moduli: list[Any],
    numbers: list[int],
    refusals: _Refusals,
) -> _AtTemperature | None:
    """R_p0.2(T)/R_p0.2 and E(T)/E of bolt and each plate at ``service_temperature``.

    The bolt's R_p0.2 from ISO 898-1 Annex A for its class, its E from the steel table. The
    plates under head and nut take clamped_material's class where it is given (its room E
    without a table); every other plate is read by its own E (:data:`PLATE_MODULUS_BANDS`),
    and keeps its room-temperature E outside every band (said in a note).
    """
    if x.get("service_temperature") is None:
        return None
    for name in ("bolt_modulus_ratio", "plate_modulus_ratio"):
        if float(np.max(col(name))) != 1.0 or float(np.min(col(name))) != 1.0:
            raise InputOutOfRange(
                f"{name} is set by service_temperature from the E(T) tables: give one of them, "
                f"leave {name} at 1",
                field=name,
            )
    cls = b.get("_strength_class")
    if cls is None:
        raise InputOutOfRange(
            "service_temperature needs the bolt's property class (R_p0.2 at temperature is "
            "tabulated per class, and a typed yield_strength overrides property_class): give grade "
            "(e.g. '10.9') with it",
            field="service_temperature",
        )
    t = col("service_temperature")
    yield_ratio = fa.yield_strength_ratio(str(cls), t)
    steel = fa.youngs_modulus_ratio("steel", t)
    named = _material_plates(x, numbers)
    kind = _plate_temperature_class(x)

    def beyond(where: Any, what: str, kind: str) -> None:
        high = fa.temperature_range(fa.YOUNGS_MODULUS_AT_TEMPERATURE_GPA[kind][0])[1]
        low = COLDEST_SERVICE_K
        refusals.add(
            where & (t > high * (1.0 + TEMPERATURE_BOUND_SLACK)),
            "service_temperature",
            lambda: (
                f"service_temperature = {t:g} K is beyond the E(T) table of {kind} ({what}): "
                f"must be {low:g}…{high:g} K ({low - fa.CELSIUS_ZERO:g}…"
                f"{high - fa.CELSIUS_ZERO:g} °C)"
            ),
        )

    if kind is not None:
        beyond(True, str(x["clamped_material"]), kind)
    plates: list[Any] = []
    for i, e in zip(numbers, moduli, strict=True):
        if i in named:
            plates.append(1.0 if kind is None else fa.youngs_modulus_ratio(kind, t))
            continue
        ratio: Any = 1.0  # outside every band: E at room temperature
        for band, low, high in reversed(PLATE_MODULUS_BANDS):
            inside = _in_band(e, low, high)
            beyond(inside, f"plate {i}, E = {e / 1e9:g} GPa", band)
            ratio = _pick(inside, fa.youngs_modulus_ratio(band, t), ratio)
        plates.append(ratio)
    return _AtTemperature(yield_ratio, steel, plates)


def _solve(
    x: Mapping[str, Any],
    col: Callable[[str], Any],
    b: Mapping[str, Any],
    refusals: _Refusals,
    outputs: frozenset[str] | None = None,
    load_ends: tuple[float, float] | None = None,
) -> dict[str, Any]:
    """The VDI 2230-1 chain R0–R13 for the inputs ``x`` and the bolt columns ``b``.

    ``col(name)`` is an input as a float (one design) or a float array (many); text and
    choice inputs are read from ``x``. Returns every output under its name plus the
    intermediate values the checks, notes and series need (keys starting with ``_``), and
    per check ``(applies, passes)`` under ``_checks``. Given ``outputs`` (an array run
    that reads no check), a late step that no output in it needs and that refuses no
    point is left out: its outputs are NaN and ``_checks`` is empty. ``load_ends``: the
    least and largest working load over every point, where the caller read them.
    """

    def col_or(name: str, other: Any) -> Any:
        return other if x.get(name) is None else col(name)

    def need(*names: str) -> bool:
        """Whether a step whose outputs are ``names`` (and the checks) is read."""
        return outputs is None or any(name in outputs for name in names)

    nan: Any = math.nan
    full = outputs is None

    joint_type = str(x["joint_type"])
    d, d_w, d_h, pitch = b["diameter"], b["bearing_outer_diameter"], b["hole_diameter"], b["pitch"]
    d2, yield_strength, a_s = b["pitch_diameter"], b["yield_strength"], b["stress_area"]

    # R0/R3 geometry (a plate of thickness 0 adds exactly 0) -----------------------------------
    e1, a1 = col("plate1_youngs_modulus"), col("plate1_expansion")
    thick, moduli, alphas = [], [], []
    outers: list[Any] = []  # D_A,i of plates 2 and 3 where given (None: plate 1's D_A)
    numbers: list[int] = []
    for i, thickness, modulus, expansion, outer_name in _PLATE_FIELDS:
        if x.get(thickness) is None:
            if i > 1 and x.get(outer_name) is not None:
                raise InputOutOfRange(
                    f"plate{i}_outer_diameter is given without plate{i}_thickness: give "
                    f"plate{i}_thickness (> 0 mm) for plate {i}, or leave its D_A out",
                    field=outer_name,
                )
            continue
        thick.append(_larger(col(thickness), 0.0))
        moduli.append(col_or(modulus, e1))
        alphas.append(col_or(expansion, a1))
        outers.append(col_or(outer_name, None) if i > 1 else None)
        numbers.append(i)
    plates = sum(h > 0.0 for h in thick)
    grip = sum(thick)
    outer = None if x.get("outer_diameter") is None else col("outer_diameter")
    if outer is not None:
        refusals.add(
            outer <= d_h,
            "outer_diameter",
            lambda: (
                f"outer_diameter D_A = {outer * 1e3:g} mm leaves no wall around the hole "
                f"d_h = {d_h * 1e3:g} mm: must be > {d_h * 1e3:g} mm (D_A ≤ d_W = "
                f"{d_w * 1e3:g} mm is VDI's sleeve)"
            ),
        )
    for i, own in zip(numbers, outers, strict=True):
        if own is not None:
            refusals.add(
                own <= d_h,
                f"plate{i}_outer_diameter",
                "plate{0}_outer_diameter D_A,{0} = {1:g} mm leaves no wall around the hole "
                "d_h = {2:g} mm: must be > {2:g} mm".format,
                i,
                own * 1e3,
                d_h * 1e3,
            )
    l_shank, l_reduced = col("shank_length"), col("reduced_length")
    refusals.add(
        l_shank + l_reduced > grip * (1.0 + 1e-12),
        "shank_length",
        "shank_length + reduced_length = {0:g} mm exceeds the grip l_K = {1:g} mm (sum of "
        "the plates): must be ≤ {1:g} mm".format,
        (l_shank + l_reduced) * 1e3,
        grip * 1e3,
    )
    if x.get("reduced_diameter") is None:
        refusals.add(
            l_reduced > 0.0,
            "reduced_diameter",
            "reduced_diameter is required when reduced_length > 0".format,
        )
    shank_d, reduced_d = col_or("shank_diameter", d), col_or("reduced_diameter", d)
    for name, value in (("shank_diameter", shank_d), ("reduced_diameter", reduced_d)):
        if x.get(name) is not None:
            refusals.add(
                value > d * (1 + 1e-12),
                name,
                _TOO_WIDE.format,
                name,
                value * 1e3,
                d * 1e3,
            )
    sections = [(l_shank, shank_d), (l_reduced, reduced_d)]
    free_thread = _larger(grip - l_shank - l_reduced, 0.0)
    e_nut = col_or("nut_youngs_modulus", _tapped_modulus(x))  # E_M (None: E_S)
    bolt_c = jt.bolt_compliance(
        d,
        b["minor_diameter"],
        col("youngs_modulus"),
        sections,
        free_thread,
        str(x["head"]),
        joint_type,
        e_nut,
    )
    own_outers = outers if any(o is not None for o in outers) else None
    parts = jt.clamped_compliance(
        thick, moduli, d_w, d_h, outer, joint_type, plate_outer_diameters=own_outers
    )
    delta_s, delta_p = bolt_c.total, parts.total
    hot = _at_temperature(x, col, b, moduli, numbers, refusals)
    # R8 only: the bolt is tightened cold (R7, F_M,zul and the torque at room temperature) and
    # meets R_p0.2(T) in service, under the F_S,max built from the cold F_M,max
    yield_t = yield_strength if hot is None else yield_strength * hot.yield_ratio

    # R3 eccentric clamping and loading (VDI 2230-1 §5.3.2); zero offsets: concentric --------------
    s_sym, lever, edge = col("bolt_offset"), col("load_lever"), col("opening_edge")
    eccentric = x.get("interface_length") is not None and x.get("interface_width") is not None
    i_bers: Any = math.nan
    beta_p: Any = 0.0
    beta_s: Any = math.nan
    k_ab: Any = 0.0
    if eccentric:
        c_t, b_t = col("interface_length"), col("interface_width")
        refusals.add(
            b_t <= d_h,
            "interface_width",
            lambda: (
                f"interface_width b = {b_t * 1e3:g} mm leaves no interface beside the hole d_h = "
                f"{d_h * 1e3:g} mm: must be > {d_h * 1e3:g} mm"
            ),
        )
        refusals.add(
            abs(s_sym) + 0.5 * d_h > 0.5 * c_t,
            "bolt_offset",
            lambda: (
                f"bolt_offset s_sym = {s_sym * 1e3:g} mm puts the hole (d_h = {d_h * 1e3:g} mm) "
                f"outside the interface c_T = {c_t * 1e3:g} mm: |s_sym| must be ≤ "
                f"{0.5 * (c_t - d_h) * 1e3:g} mm"
            ),
        )
        refusals.add(
            edge > 0.5 * c_t * (1.0 + 1e-12),
            "opening_edge",
            lambda: (
                f"opening_edge u = {edge * 1e3:g} mm lies outside the interface c_T = "
                f"{c_t * 1e3:g} mm: must be ≤ {0.5 * c_t * 1e3:g} mm"
            ),
        )
        cone_d = _pick(
            parts.outer_diameter < parts.limit_diameter, parts.outer_diameter, parts.limit_diameter
        )
        i_bers = jt.substitute_bending_inertia(
            grip, d_w, cone_d, parts.tangent, s_sym, b_t, c_t, joint_type
        )
        beta_p = jt.clamped_bending_compliance(thick, moduli, i_bers)
        beta_s = jt.bolt_bending_compliance(
            d,
            b["minor_diameter"],
            col("youngs_modulus"),
            sections,
            free_thread,
            str(x["head"]),
            joint_type,
            e_nut,
        )
        area_d, inertia_t = jt.interface_section(b_t, c_t, d_h)
        # the clamp force must act inside the interface's kern, or the preload alone lifts u
        refusals.add(
            inertia_t / area_d + s_sym * edge <= 0.0,
            "bolt_offset",
            lambda: (
                f"bolt_offset s_sym = {s_sym * 1e3:g} mm lies outside the interface's kern for "
                f"the edge u = {edge * 1e3:g} mm (I_BT/A_D + s_sym u ≤ 0): the preload alone "
                "opens that edge; bring the bolt towards the load's side"
            ),
        )
        k_ab = jt.opening_ratio(lever, s_sym, edge, area_d, inertia_t)
    else:
        for name, value in (("bolt_offset", s_sym), ("load_lever", lever), ("opening_edge", edge)):
            refusals.add(
                value != 0.0,
                "interface_length",
                "{0} = {1:g} mm needs the interface: give interface_length c_T and "
                "interface_width b (> 0 mm), or {0} = 0 for a concentric joint".format,
                name,
                value * 1e3,
            )
    delta_p1 = jt.eccentric_compliance(delta_p, beta_p, s_sym, s_sym)  # δ*_P
    delta_p2 = jt.eccentric_compliance(delta_p, beta_p, s_sym, lever)  # δ**_P
    phi_k = jt.load_factor(delta_s, delta_p1, 1.0, delta_p2)
    phi_n = jt.load_factor(delta_s, delta_p1, col("load_introduction"), delta_p2)

    # R2 required clamp force (the opening requirement F_KA once F_A is read) --------------------
    f_q, q_f, mu_t = col("transverse_load"), col("slip_interfaces"), col("interface_friction")
    m_y, q_m = col("torsional_moment"), col("torque_interfaces")
    if x.get("friction_radius") is None:
        r_a: Any = 1.0  # unused: M_Y must be 0 then
        refusals.add(
            m_y > 0.0,
            "friction_radius",
            "torsional_moment = {0:g} N*m needs friction_radius r_a (> 0 mm)".format,
            m_y,
        )
    else:
        r_a = col("friction_radius")
    f_kq = jt.transverse_clamp_force(f_q, q_f, mu_t, m_y, q_m, r_a)
    f_kp = col("sealing_clamp_force")
    f_kerf_grip = jt.required_clamp_force(f_kq, f_kp)

    # R1 friction box, loads --------------------------------------------------------------------
    method = get_method(str(x["method"]))
    method_factor = method.tightening_factor
    mu_g_lo, mu_k_lo = col("thread_friction_min"), col("bearing_friction_min")
    mu_g_hi = col_or("thread_friction_max", mu_g_lo)
    mu_k_hi = col_or("bearing_friction_max", mu_k_lo)
    for name, lo, hi in (
        ("thread_friction", mu_g_lo, mu_g_hi),
        ("bearing_friction", mu_k_lo, mu_k_hi),
    ):
        refusals.add(
            hi < lo,
            f"{name}_max",
            "{0}_max = {1:g} is below {0}_min = {2:g}: must be ≥ {2:g}".format,
            name,
            hi,
            lo,
        )
    f_a = col("working_load")
    f_a_min = col_or("working_load_min", f_a)
    refusals.add(
        _exceeds(f_a_min, f_a, "working_load"),
        "working_load_min",
        "working_load_min = {0:g} N exceeds working_load = {1:g} N: must be ≤ {1:g} N".format,
        f_a_min,
        f_a,
    )
    # concentric (k_ab = 0): F_KA = 0 at every point, one number (F_A is finite and ≥ 0)
    f_ka = jt.opening_clamp_force(f_a, k_ab) if eccentric else 0.0
    f_kerf = jt.required_clamp_force(f_kq, f_kp, f_ka)

    # R4 embedding --------------------------------------------------------------------------------
    faces, interfaces = jt.embedding_locations(joint_type, plates)
    # the transverse column of Table 5.4/1 wherever the interfaces carry shear (F_Q or M_Y)
    f_z_len = jt.embedding_for_load(str(x["surface_roughness"]), f_kq, faces, interfaces)
    f_z = jt.embedding_loss(f_z_len, delta_s, delta_p1)

    # R7 permissible preload at the smallest section ---------------------------------------------
    d0, where = jt.smallest_section(b["stress_diameter"], sections)
    a0 = jt.smallest_area(d0, a_s, where)
    nu = col("utilization")
    beta = _plain(pl.torsion_factor(pitch, d2, d0, mu_g_lo, "vdi2230"))
    f_mzul_bolt = pl.assembly_preload(yield_strength, a0, beta, nu)
    f_myield = pl.assembly_preload(yield_strength, a0, beta, 1.0)
    # the nut's proof load (ISO 898-2) caps the preload a through bolt may be given
    nut, nut_part, tensile = b.get("_nut") or (None, None, None)
    f_nut: Any = math.nan
    if nut is not None:
        f_nut = _plain(fa.nut_proof_load(nut.property_class, d, a_s, nut.style))
    nut_limits = f_nut < f_mzul_bolt  # False where ISO 898-2 gives no S_p (NaN)
    f_mzul = fa.nut_limited_preload(f_mzul_bolt, f_nut)

    # R1/R13 assembly preload range: torque specification, or tightened to F_M,zul ---------------
    m_u = col("prevailing_torque")
    m_u_min = col_or("prevailing_torque_min", m_u)
    refusals.add(
        m_u_min > m_u,
        "prevailing_torque_min",
        "prevailing_torque_min = {0:g} N*m exceeds prevailing_torque = {1:g} N*m: must be "
        "≤ {1:g} N*m".format,
        m_u_min,
        m_u,
    )
    torque_given = x.get("tightening_torque") is not None
    kt_low, kb_low = pl.tightening_torque_per_preload(pitch, d2, d, mu_g_lo, mu_k_lo, d_w, d_h)
    if torque_given:
        k_low = kt_low + kb_low
        k_high = sum(pl.tightening_torque_per_preload(pitch, d2, d, mu_g_hi, mu_k_hi, d_w, d_h))
        torque = col("tightening_torque")
        fm_min, fm_max = jt.preload_bounds_from_torque(
            torque, col("torque_tolerance"), m_u, k_low, k_high, m_u_min
        )
        alpha_a = jt.torque_tightening_factor(fm_min, fm_max)
    else:
        given = x.get("tightening_factor") is not None
        alpha_a = col("tightening_factor") if given else method_factor
        fm_min, fm_max = jt.design_preload_range(f_mzul, alpha_a)
        torque = jt.tightening_torque(f_mzul, kt_low, kb_low, m_u)

    # R4 thermal loss at the lowest service preload -----------------------------------------------
    dt_s = col("temperature_change")
    # VDI 2230-1 5.4.2.3: δ_S, δ_P at room temperature (assembly, Φ_n, F_Z); E at T only here
    modulus_s, modulus_p = col("bolt_modulus_ratio"), col("plate_modulus_ratio")
    if hot is not None:
        modulus_s = hot.bolt_modulus_ratio
        modulus_p = delta_p / sum(
            c / r for c, r in zip(parts.per_plate, hot.plate_modulus_ratios, strict=True)
        )
    thermal = partial(
        jt.thermal_preload_loss,
        grip=grip,
        bolt_expansion=col("bolt_expansion"),
        bolt_temperature_change=dt_s,
        clamped_expansion_length=jt.plates_expansion_length(thick, alphas),
        plate_temperature_change=col_or("plate_temperature_change", dt_s),
        bolt=delta_s,
        clamped=delta_p1,
        bolt_modulus_ratio=modulus_s,
        clamped_modulus_ratio=modulus_p,
    )
    th_loss = thermal(fm_min - f_z)
    th_top = thermal(fm_max)  # R8: the change at the largest assembly preload
    loss = jt.preload_losses(f_z, th_loss)

    # R5/R6 required window, R7 against it ---------------------------------------------------------
    alpha_req = _finite_or(alpha_a, method_factor)
    req_min = jt.minimum_assembly_preload(f_kerf, f_a, phi_n, f_z, th_loss)
    req_max = jt.required_preload_max(alpha_req, req_min) if need("required_preload_max") else nan
    fa_limit = nan
    if need("max_working_load"):
        fa_limit = jt.max_working_load(f_mzul, alpha_req, f_kerf_grip, loss, phi_n, k_ab, f_kp)
    fa_sep_any = jt.separation_load(f_mzul, loss, phi_n, k_ab) if full else nan
    # the "joint opens" warning reads F_KR at every point; where nothing else does and F_A is
    # its only varied argument, at the two ends of F_A alone (below, after the last refusal)
    # F_A swept alone (every other argument of R5–R8 one number): F_KR, F_S,max and σ_red,B
    # are monotone in F_A or in |F_S,max| (so is every rounding), and a decision that reads
    # only their least or largest value (the warning, R8's refusals) reads them at the ends
    # of F_A over the points not refused
    f_a_alone = type(f_a) is not float and _varied_alone(
        f_a, fm_min, fm_max, phi_n, f_z, th_loss, th_top, pitch, d2, d0, mu_g_lo
    )
    f_a_range: Any = _Extremes(f_a, "working_load", refusals, load_ends) if f_a_alone else None
    read_kr = need("residual_clamp_force_min", "slip_safety")
    f_kr_ends = f_a_alone and not read_kr
    f_kr_raw: Any = None if f_kr_ends else jt.residual_clamp_force(fm_min, f_a, phi_n, f_z, th_loss)
    # a joint that opens has no clamp force left (the linear diagram's negative value is not
    # a force): F_KR,min and S_G are held at 0 there and the checks fail on the raw value
    f_kr_min = _larger(f_kr_raw, 0.0) if read_kr else nan
    fa_sep = jt.separation_load(fm_min, loss, phi_n, k_ab) if need("separation_load") else nan
    checks: dict[str, tuple[Any, Any]] = {}
    if full:
        checks["R7_window_fits"] = (True, req_max <= f_mzul * (1.0 + 1e-12))
        checks["separation_avoidable"] = (True, f_a < fa_sep_any)
        checks["residual_clamp_force"] = (
            True,
            (f_kr_raw >= f_kerf * (1.0 - 1e-12)) & (f_kr_raw > 0.0),
        )
    if full and torque_given:
        checks["R7_max_below_permissible"] = (True, fm_max <= f_mzul * (1.0 + 1e-12))

    # R8 working stress ---------------------------------------------------------------------------
    add_load = jt.additional_bolt_load(phi_n, f_a)
    f_s_max = jt.max_bolt_force(fm_max, add_load, th_top)
    read_stress = need("working_stress", "yield_safety")
    force_ranges: tuple[Callable[[], Any], ...] = ()

    def force_at(loads: Callable[[], Any]) -> Callable[[], Any]:
        return lambda: jt.max_bolt_force(fm_max, jt.additional_bolt_load(phi_n, loads()), th_top)

    if f_a_alone and not read_stress:  # F_S,max over F_A's declared range, else the points'
        force_ranges = (
            force_at(f_a_range.declared),
            force_at(lambda: np.array([f_a_range.low(), f_a_range.high()])),
        )
    stress: Any = None
    if read_stress or not _no_stress_refusal(force_ranges, (fm_max, pitch, d2, d0, mu_g_lo)):
        stress = jt.service_stress(f_s_max, fm_max, pitch, d2, d0, mu_g_lo)
        refusals.arithmetic(stress.equivalent == 0.0, "σ_red,B = 0")
        refusals.arithmetic(
            _overflows_squared(stress.axial)
            | _overflows_squared(jt.TORSION_REDUCTION_IN_SERVICE * stress.torsional),
            "σ_red,B overflows",
        )
    s_f: Any = nan
    if stress is not None and need("yield_safety"):
        s_f = jt.yield_safety(yield_t, stress.equivalent)
    if full:
        checks["R8_working_stress"] = (True, s_f >= 1.0)
    if full and nut is not None:
        checks["nut_strength"] = (
            f_nut == f_nut,  # ISO 898-2 covers the size
            (f_mzul_bolt <= f_nut) & (f_s_max <= f_nut * (1.0 + 1e-12)),
        )
        if nut.pairs is not None:
            checks["nut_class_pairing"] = (True, nut.pairs)
    # R11 for the nut's thread where the nut does not pair with the bolt (thin, weaker class)
    f_strip: Any = math.nan
    if nut is not None and nut.pairs is False and nut_part is not None and tensile is not None:
        f_strip = _plain(fa.nut_thread_resistance(d, pitch, d2, nut_part, nut, f_nut, tensile))
        if full:
            checks["nut_thread_stripping"] = (f_strip == f_strip, f_strip >= f_s_max)

    # R9 alternating stress -----------------------------------------------------------------------
    fatigue = ("stress_amplitude", "endurance_limit", "fatigue_safety")
    phi_b = phi_n
    if eccentric and need("additional_bolt_stress", *fatigue):
        phi_b = jt.eccentric_stress_factor(
            phi_n, lever, s_sym, beta_p, beta_s, b["stress_diameter"]
        )
    sigma_a = sigma_as = s_d = nan
    if need(*fatigue):
        sigma_a = jt.stress_amplitude(phi_b, f_a, f_a_min, a_s)
        f_sm = jt.mean_bolt_force(fm_max, phi_n, f_a, f_a_min)
        sigma_as = jt.endurance_limit(d, str(x["rolling"]), f_sm, a_s * yield_strength)
        s_d = jt.fatigue_safety(sigma_as, sigma_a)
    if full:
        checks["R9_fatigue"] = (sigma_a > 0.0, s_d >= 1.2)
        # §5.3.2: σ_SAb and Φ*_en hold while the interface stays closed (F_A ≤ F_Aab at F_M,min)
        checks["opening_limit"] = (eccentric, f_a <= fa_sep * (1.0 + 1e-12))

    # R12 slipping -----------------------------------------------------------------------
    s_g = jt.slip_safety(f_kr_min, q_f, mu_t, f_q, m_y, q_m, r_a) if need("slip_safety") else nan
    tau_q: Any = math.nan
    s_a: Any = math.nan
    p_q: Any = math.nan
    fitted = ("fitted_shear_stress", "fitted_shear_safety", "fitted_bearing_pressure")
    if x.get("fitted_diameter") is not None and need(*fitted):
        d_tau = col("fitted_diameter")
        h_min: Any = math.inf
        for h in thick:
            h_min = _pick(h > 0.0, _pick(h < h_min, h, h_min), h_min)
        r_m = b.get("tensile_strength")
        tau_q = jt.fitted_shank_shear_stress(f_q, q_f, d_tau)
        s_a = jt.fitted_shear_safety(math.nan if r_m is None else r_m, tau_q)
        p_q = jt.fitted_bearing_pressure(f_q, d_tau, h_min)
        if full:
            checks["R12_fitted_shear"] = ((f_q > 0.0) & (s_a == s_a), s_a >= 1.1)
    need_slip: Any = nan
    if full:
        need_slip = jt.required_slip_safety(f_a, f_a_min)
        checks["R12_slip"] = ((f_q > 0.0) | (m_y > 0.0), s_g >= need_slip)

    # [004] rules and the tightening targets [004, eq. 6–9] ----------------------------------------
    nominal = jt.nominal_preload(fm_min, fm_max)
    ratio0 = jt.preload_stress_ratio(nominal, a0, yield_strength)
    rule = _seed_004_rule(x, method, torque_given)
    if full:
        checks["seed_004_preload_stress"] = (True, ratio0 <= rule[1] + 1e-12)
    if f_kr_ends:  # every refusal is made
        f_kr_raw = _least_clamp_force(
            lambda loads: jt.residual_clamp_force(fm_min, loads, phi_n, f_z, th_loss), f_a_range
        )
    # F_A swept alone, F_K,erf one number: F_SA, F_PA, F_M,min and F_S,max are monotone in
    # F_A (every rounding too), so where they are finite at both ends of F_A's declared range
    # (no point lies outside it) they are finite at every point, told without a pass over them
    finite: frozenset[str] = frozenset()
    if f_a_alone and not isinstance(f_kerf, np.ndarray) and outputs is not None:
        ends = f_a_range.declared
        at_ends = {
            "additional_bolt_load": lambda: jt.additional_bolt_load(phi_n, ends()),
            "clamp_load_reduction": lambda: jt.clamp_load_reduction(phi_n, ends()),
            "required_preload_min": lambda: jt.minimum_assembly_preload(
                f_kerf, ends(), phi_n, f_z, th_loss
            ),
            "max_bolt_force": force_at(ends),
        }
        finite = frozenset(
            name
            for name, value in at_ends.items()
            if name in outputs and bool(np.isfinite(value()).all())
        )

    return {
        "tightening_factor": alpha_a,
        "required_clamp_force": f_kerf,
        "transverse_clamp_force": f_kq,
        "bolt_compliance": delta_s,
        "bolt_compliance_head": bolt_c.head,
        "bolt_compliance_shank": bolt_c.shank,
        "bolt_compliance_free_thread": bolt_c.free_thread,
        "bolt_compliance_engaged": bolt_c.engaged,
        "clamped_compliance": delta_p,
        "eccentric_clamped_compliance": delta_p1,
        "substitute_bending_inertia": i_bers,
        "clamped_bending_compliance": beta_p if eccentric else math.nan,
        "bolt_bending_compliance": beta_s,
        "opening_clamp_force": f_ka,
        "additional_bolt_stress": (
            jt.additional_bolt_stress(phi_b, f_a, a_s) if need("additional_bolt_stress") else nan
        ),
        "cone_tangent": parts.tangent,
        "cone_limit_diameter": parts.limit_diameter,
        "outer_diameter_used": parts.outer_diameter,
        "grip": grip,
        "load_factor_k": phi_k,
        "load_factor": phi_n,
        "additional_bolt_load": add_load,
        "clamp_load_reduction": (
            jt.clamp_load_reduction(phi_n, f_a) if need("clamp_load_reduction") else nan
        ),
        "embedding_settlement": f_z_len,
        "embedding_loss": f_z,
        "thermal_loss": th_loss,
        "required_preload_min": req_min,
        "required_preload_max": req_max,
        "smallest_diameter": d0,
        "smallest_area": a0,
        "permissible_preload": f_mzul,
        "yield_preload": f_myield,
        "assembly_preload_min": fm_min,
        "assembly_preload_max": fm_max,
        "tightening_torque": torque,
        "residual_clamp_force_min": f_kr_min,
        "separation_load": fa_sep,
        "max_working_load": fa_limit,
        "max_bolt_force": f_s_max,
        "working_stress": stress.equivalent if stress is not None else nan,
        "yield_safety": s_f,
        "stress_amplitude": sigma_a,
        "endurance_limit": sigma_as,
        "fatigue_safety": s_d,
        "slip_safety": s_g,
        "fitted_shear_stress": tau_q,
        "fitted_shear_safety": s_a,
        "fitted_bearing_pressure": p_q,
        "preload_stress_ratio": ratio0,
        "bolt_elongation": pl.elongation(nominal, delta_s),
        "target_angle": pl.nut_rotation_angle(nominal, delta_s + delta_p, pitch),
        "rigid_joint_angle": pl.nut_rotation_angle(nominal, delta_s, pitch),
        "nut_stripping_force": f_strip,
        "yield_strength_at_temperature": math.nan if hot is None else yield_t,
        "bolt_modulus_ratio_at_temperature": math.nan if hot is None else modulus_s,
        "plate_modulus_ratio_at_temperature": math.nan if hot is None else modulus_p,
        # what the sentences, hooks and series read
        "_yield_t": yield_t,
        "_checks": checks,
        "_where": where,
        "_alpha_req": alpha_req,
        "_fa_sep_any": fa_sep_any,
        "_need_slip": need_slip,
        "_rule": rule,
        "_method": method,
        "_mu": (mu_g_lo, mu_g_hi, mu_k_lo, mu_k_hi),
        "_m_u": m_u,
        "_f_kr_raw": f_kr_raw,
        "_f_kr_ends": f_kr_ends,
        "_finite": finite,
        "_nut": (nut, f_nut, f_mzul_bolt, nut_limits),
    }


def _seed_004_rule(
    x: Mapping[str, Any], method: Any, torque_given: bool
) -> tuple[float, float, str]:
    """[004, eq. 6]'s band of σ0/σ_T for this joint: (low, high, why)."""
    if bool(x["bridge_joint"]):
        return 0.8, 0.9, "bridge joint"
    if method.scatter <= 0.10 + 1e-12 and not torque_given:
        return 0.5, 0.7, f"{method.key}, ±{method.scatter:.0%}"
    return 0.4, 0.5, "method less accurate than ±10 %"


# --------------------------------------------------------------------------- one design


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    bolt, notes = resolve_bolt(x)
    b: dict[str, Any] = {f: getattr(bolt, f) for f in _BOLT_FIELDS}
    b["_strength_class"] = _strength_class(x, bolt)
    b["_nut"] = _nut_choice(
        x, bolt.tensile_strength, None if bolt.fastener is None else bolt.fastener.thread
    )
    # validated numeric inputs are Python numbers already: read them as they are
    s = _solve(x, x.__getitem__, b, _Refusals(np.False_, many=False))
    values: dict[str, Any] = {}
    for name in _SCALARS:  # Python floats out (some are numpy's)
        value = s[name]
        if type(value) is not float:
            s[name] = value = float(value)
        values[name] = value
    for name in _READ_AS_FLOATS:
        if type(s[name]) is not float:
            s[name] = float(s[name])
    warnings: list[str] = []
    d = bolt.diameter
    f_mzul, fm_min, fm_max = (
        s["permissible_preload"],
        s["assembly_preload_min"],
        s["assembly_preload_max"],
    )
    mu_g_lo, mu_g_hi, mu_k_lo, mu_k_hi = s["_mu"]
    method = s["_method"]
    if x.get("outer_diameter") is None:
        notes.append(
            f"D_A not given: plates taken just wide enough for the full cone, D_A = D_A,Gr = "
            f"{q(s['outer_diameter_used'], 'mm', 4)} (our convention; VDI's cone-angle fit "
            "needs a D_A); a wider plate is stiffer by that fit"
        )
    if (
        x.get("outer_diameter") is not None
        and float(x["outer_diameter"]) < bolt.bearing_outer_diameter
    ):
        warnings.append(
            f"D_A = {q(float(x['outer_diameter']), 'mm', 4)} < d_W = "
            f"{q(bolt.bearing_outer_diameter, 'mm', 4)}: the plates are VDI's sleeve "
            "(δ_P = 4 l_K/(E π (D_A² − d_h²))); the head bears on the sleeve's face only, so "
            "the surface pressure (R10), computed on d_W, is higher than stated"
        )
    nut_outer = _nut_side_outer(x, lambda name: float(x[name]))
    if x.get("nut") is not None and bolt.fastener is not None and nut_outer is not None:
        thread = bolt.fastener.thread
        nut_w = None if thread is None else fa.nut(str(x["nut"]), thread).bearing_diameter
        if nut_w is not None and nut_outer < nut_w:
            warnings.append(
                f"D_A = {q(nut_outer, 'mm', 4)} under the nut < its d_W = {nut_w * 1e3:.4g} "
                "mm: the nut bears on the plate's face only; R10 under the nut takes "
                "A_p = π/4 (D_A² − d_h²)"
            )
    warnings += _interface_limit_warning(x, bolt)
    if s["cone_tangent"] <= jt.MIN_CONE_TANGENT:
        warnings.append(
            f"plates very thin against d_W: the cone tangent is held at {jt.MIN_CONE_TANGENT}"
        )
    own = [i for i, _, _, _, name in _PLATE_FIELDS[1:] if x.get(name) is not None]
    if own:
        notes.append(
            "D_A per plate: plate "
            + ", ".join(
                f"{i} D_A,{i} = {float(x[f'plate{i}_outer_diameter']) * 1e3:.4g} mm" for i in own
            )
            + "; each plate's part of the cone is capped at its own D_A (a sleeve below d_W), "
            f"tan φ = {s['cone_tangent']:.4g} from plate 1's D_A = "
            f"{q(s['outer_diameter_used'], 'mm', 4)} (VDI 2230-1 R3)"
        )
    if x.get("service_temperature") is not None:
        hot_notes, hot_warnings = _temperature_notes(x, s, bolt)
        notes += hot_notes
        warnings += hot_warnings
    if s["_where"] == "shank":
        notes.append(
            f"smallest section is the shank, d_0 = {q(s['smallest_diameter'], 'mm', 4)} < d_S = "
            f"{q(bolt.stress_diameter, 'mm', 4)}: F_M,zul = {_kn(f_mzul)} at A_0 = "
            f"{q(s['smallest_area'], 'mm²', 4)} (VDI 2230-1 R7)"
        )
    if x.get("tightening_torque") is not None:
        tol, m_u = float(x["torque_tolerance"]), s["_m_u"]
        notes.append(
            f"torque {q(s['tightening_torque'], 'N*m', 4)} ± {tol:.0%}, "
            f"prevailing {q(m_u, 'N*m')}, "
            f"μ_G {mu_g_lo:g}…{mu_g_hi:g}, μ_K {mu_k_lo:g}…{mu_k_hi:g}: F_M = {_kn(fm_min)} "
            f"(M_A,min at μ_max) … {_kn(fm_max)} (M_A,max at μ_min), VDI 2230-1 R13 inverted"
        )
        if x.get("tightening_factor") is not None:
            notes.append(
                "tightening_factor ignored: the torque specification sets the preload range"
            )
    else:
        notes.append(
            f"no torque given: tightened to F_M,zul = {_kn(f_mzul)} with α_A = "
            f"{s['tightening_factor']:.3g} "
            f"({method.key if x.get('tightening_factor') is None else 'as given'}); "
            f"M_A = {q(s['tightening_torque'], 'N*m', 4)} at μ_G,min, μ_K,min (VDI 2230-1 R13)"
        )
    if x.get("nut_property_class") is not None and x.get("nut") is None:
        notes.append("nut_property_class ignored: no nut given (a tapped joint, or give nut)")
    e_tapped = _tapped_modulus(x)
    if x.get("nut_youngs_modulus") is None and e_tapped is not None:
        notes.append(
            f"E_M = {q(e_tapped, 'GPa', 4)} of {x['internal_thread_material']} for the tapped "
            "thread's compliance δ_M (VDI 2230-1 R3); give nut_youngs_modulus to override"
        )
    elif (
        x.get("nut_youngs_modulus") is None
        and x["joint_type"] == "tapped"
        and x.get("internal_thread_material") is not None
    ):
        notes.append(
            f"no modulus listed for {x['internal_thread_material']}: the tapped thread's δ_M "
            "takes the bolt's E_S; give nut_youngs_modulus"
        )
    nut, f_nut, f_mzul_bolt, nut_limits = s["_nut"]
    if nut is not None and nut.pairs:
        notes.append(nut_paired_note(nut))
    if nut is not None and bool(nut_limits):
        warnings.append(
            nut_limit_warning(nut, f_nut, f_mzul_bolt)
            + "; the preload window and the torque are built on it"
        )
    elif nut is not None and f_nut != f_nut:
        notes.append(
            f"nut strength not checked: ISO 898-2 gives no proof load for class "
            f"{nut.property_class} at d = {q(d, 'mm', 6)}"
        )
    sentences = _sentences(x, s, bolt)
    checks = [
        Check(name, bool(ok), sentences[name])
        for name, (applies, ok) in s["_checks"].items()
        if applies
    ]
    if not bool(x["controlled"]) and d < 0.010:
        warnings.append(
            f"d = {q(d, 'mm', 6)} < 10 mm tightened without control: [004] warns of "
            "over-tightening; lower the admissible load or control the tightening"
        )

    # hooks (R10 surface pressure, R11 engagement)
    solution = JointSolution(
        bolt,
        s["grip"],
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        fm_max,
        s["max_bolt_force"],
        str(x["joint_type"]),
        nut_outer,
    )
    for hook in CHECK_HOOKS:
        more_checks, more_notes = hook(x, solution)
        checks.extend(more_checks)
        notes.extend(more_notes)
    if not CHECK_HOOKS:
        notes.append(
            "surface pressure under head and nut (VDI R10) and length of engagement / thread "
            "stripping (VDI R11) are not checked by this model yet"
        )

    if not math.isfinite(values["nut_stripping_force"]):
        del values["nut_stripping_force"]  # the nut pairs with the bolt, or there is none
    for name in _GIVEN_ONLY:
        if not math.isfinite(values[name]):
            del values[name]  # a concentric joint (no interface), or no fitted shank
    for name in ("tightening_factor", "fatigue_safety", "slip_safety"):
        if not math.isfinite(values[name]):
            values[name] = None
    if values["fatigue_safety"] is None:
        notes.append("static working load: no alternating stress, fatigue_safety null (R9)")
    notes.append(MODEL_FORM_NOTE)
    outside = _r9_outside(x, bolt)
    if outside is not None:
        relation = (
            "σ_ASG = (2 − F_Sm/F_0.2,min) · 0.85 (150/d + 45) MPa"
            if x["rolling"] == "after_heat_treatment"
            else "σ_ASV = 0.85 (150/d + 45) MPa"
        )
        said = (
            f"R9's endurance limit {relation} = {q(values['endurance_limit'], 'MPa', 4)} "
            "(the value used) is VDI 2230's fit for metric ISO 898-1 bolts of class 8.8–12.9, "
            f"d ≤ 40 mm; here {outside}: it is applied outside its range"
        )
        if values["fatigue_safety"] is None:
            notes.append(said)
        else:
            warnings.append(
                said + f", so S_D = {values['fatigue_safety']:.3g} is not backed by it (stainless "
                "and lower classes have other, often lower, endurance limits; larger bolts a "
                "lower one): take σ_AS from the bolt's maker or a fatigue test"
            )
    if values["slip_safety"] is None:
        notes.append("no transverse load or torsional moment: slip_safety null (R12)")
    if s["_f_kr_raw"] < 0.0:
        warnings.append(
            f"the joint opens: F_A = {_kn(float(x['working_load']))} exceeds the separation "
            f"load {_kn(s['separation_load'])} at F_M,min; no clamp force is left "
            "(residual_clamp_force_min 0"
            + ("" if values["slip_safety"] is None else ", slip_safety 0")
            + ") and the bolt carries all of F_A beyond it, which Φ_n's linear diagram "
            "does not model"
        )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=_series(ctx, s, x),
    )


def _interface_limit_warning(x: Mapping[str, Any], bolt: Bolt) -> list[str]:
    """VDI 2230-1's limit c_T ≤ G of the eccentric relations, where c_T exceeds it (one design)."""
    if x.get("interface_length") is None or x.get("interface_width") is None:
        return []
    c_t, d_w = float(x["interface_length"]), bolt.bearing_outer_diameter
    tapped = x["joint_type"] == "tapped"
    plates = [x.get(f"plate{i}_thickness") for i in range(1, MAX_PLATES + 1)]
    given = [float(h) for h in plates if h is not None and float(h) > 0.0]
    # h_min: the thinner of the two outer plates, the ones that carry the interface to head and
    # nut ("the smallest thickness of two clamped plates", [STEELPY-VDI]), not a thin middle shim
    h_min = min(given[0], given[-1]) if given else 0.0
    limit = float(jt.interface_limit(d_w, h_min, str(x["joint_type"])))
    if c_t <= limit * (1.0 + 1e-12):
        return []
    low, high = jt.TAPPED_INTERFACE_LIMIT
    rule = (
        f"G' = ({low:g}…{high:g}) d_W = {low * d_w * 1e3:.4g}…{q(high * d_w, 'mm', 4)} of a "
        f"tapped joint (d_W = {q(d_w, 'mm', 4)}; the lower end applied)"
        if tapped
        else f"G = d_W + h_min = {d_w * 1e3:.4g} + {h_min * 1e3:.4g} = {q(limit, 'mm', 4)} of "
        "a through-bolted joint"
    )
    return [
        f"interface_length c_T = {q(c_t, 'mm', 4)} exceeds VDI 2230-1's limit {rule}: its "
        "eccentric relations (I_Bers, I_BT, Φ*_en, F_KA, σ_SAb) hold only for c_T ≤ G; the "
        f"interface beyond G is not clamped by this bolt. Give c_T ≤ {q(limit, 'mm', 4)} (the "
        "part beyond G taken as not clamped), or read the eccentric figures as outside VDI's range"
    ]


def _temperature_notes(
    x: Mapping[str, Any], s: Mapping[str, Any], bolt: Bolt
) -> tuple[list[str], list[str]]:
    """What a service temperature changed, and which E each step uses (one design)."""
    t = float(x["service_temperature"])
    celsius = t - fa.CELSIUS_ZERO
    material = x.get("clamped_material")
    kind = _plate_temperature_class(x)
    numbers = [i for i in range(1, MAX_PLATES + 1) if x.get(f"plate{i}_thickness") is not None]
    named = _material_plates(x, numbers)
    read = []
    warnings = []
    for i in numbers:
        e = float(x.get(f"plate{i}_youngs_modulus") or x["plate1_youngs_modulus"])
        by_e = next((k for k, lo, hi in PLATE_MODULUS_BANDS if _in_band(e, lo, hi)), None)
        if i in named:
            read.append(f"plate {i} {material} as {kind or 'no table: room E'}")
            band = None if kind is None else _modulus_band(kind)
            if band is not None and not _in_band(e, *band):
                warnings.append(
                    f"plate {i}: E = {q(e, 'GPa', 4)} contradicts clamped_material = "
                    f"{material} ({kind}, {band[0] / 1e9:g}…{band[1] / 1e9:g} GPa): its E(T) "
                    f"is {kind}'s; name the material under head and nut or correct "
                    f"plate{i}_youngs_modulus"
                )
        else:
            read.append(f"plate {i} ({q(e, 'GPa', 4)}) as {by_e or 'no band: room E'}")
    plates = (
        ", ".join(read)
        + "; by E: "
        + ", ".join(f"{k} {lo / 1e9:g}…{hi / 1e9:g} GPa" for k, lo, hi in PLATE_MODULUS_BANDS)
    )
    notes = [
        f"at T = {t:.5g} K ({celsius:.4g} °C): R_p0.2 = {q(s['_yield_t'], 'MPa', 4)} "
        f"({q(bolt.yield_strength, 'MPa', 4)} × {s['_yield_t'] / bolt.yield_strength:.4f}, "
        "ISO 898-1 Annex A [NFG-898T], linear between its columns) in R8 (S_F; R7's F_M,zul "
        "and the torque at room temperature, the bolt is tightened cold); "
        f"E_S,T/E_S,RT = {s['bolt_modulus_ratio_at_temperature']:.4f} (steel) and "
        f"E_P,T/E_P,RT = {s['plate_modulus_ratio_at_temperature']:.4f} ({plates}; "
        "[RICHTER-E], [ASME-B31.1-E]) in the thermal loss ΔF_Vth only (VDI 2230-1 5.4.2.3): "
        "δ_S, δ_P, Φ_n and F_Z are the assembly's, at room temperature; R9's F_0.2 and R10's "
        "p_G stay at room temperature (no public table of p_G at temperature found)"
    ]
    if celsius < 20.0:
        notes.append(
            f"below 20 °C ({celsius:.4g} °C, VDI 2230-1's scope reaches −40 °C) R_p0.2 and E "
            "keep their 20 °C values (ratio 1): both rise in the cold, so this is conservative"
        )
    if float(x["temperature_change"]) == 0.0 and abs(celsius - 20.0) > 1.0:
        warnings.append(
            f"service_temperature = {celsius:.4g} °C but temperature_change ΔT_S = 0: the "
            "expansion mismatch of bolt and plates is not in ΔF_Vth; give temperature_change "
            "= T − T_assembly (and plate_temperature_change) for it"
        )
    return notes, warnings


def _sentences(x: Mapping[str, Any], s: Mapping[str, Any], bolt: Bolt) -> dict[str, str]:
    """The sentence of each check of one solved design."""
    f_mzul, fm_min, fm_max = (
        s["permissible_preload"],
        s["assembly_preload_min"],
        s["assembly_preload_max"],
    )
    alpha_req, req_min, req_max = (
        s["_alpha_req"],
        s["required_preload_min"],
        s["required_preload_max"],
    )
    window_ok = s["_checks"]["R7_window_fits"][1]
    no_sep = s["_checks"]["separation_avoidable"][1]
    clamp_ok = s["_checks"]["residual_clamp_force"][1]
    f_a, f_kerf, nu = float(x["working_load"]), s["required_clamp_force"], float(x["utilization"])
    lo_rule, hi_rule, why = s["_rule"]
    stress, s_f = s["working_stress"], s["yield_safety"]
    sigma0 = s["preload_stress_ratio"] * bolt.yield_strength  # σ0 = F_M,nom/A_0
    need = s["_need_slip"]
    out = {
        "R7_window_fits": f"required F_M,max = α_A F_M,min = {alpha_req:.3g} × {_kn(req_min)} = "
        f"{_kn(req_max)} vs F_M,zul = {_kn(f_mzul)}"
        + (
            ""
            if window_ok
            else f": the largest F_A this bolt can carry with α_A = {alpha_req:.3g} is "
            f"{_kn(s['max_working_load'])}; use a more accurate method, a larger or stronger bolt"
        ),
        "separation_avoidable": f"F_A = {_kn(f_a)} vs {_kn(s['_fa_sep_any'])}, the load that "
        "separates the joint even at F_M,zul after embedding and thermal loss "
        "((F_M,zul − F_Z − ΔF_th)/(1 − Φ_n))"
        + ("" if no_sep else ": no admissible preload keeps this joint closed"),
        "residual_clamp_force": "F_KR,min = F_M,min − (1 − Φ_n) F_A − F_Z − ΔF_th = "
        f"{_kn(s['_f_kr_raw'])} vs required F_K,erf = {_kn(f_kerf)}"
        + (
            ""
            if clamp_ok
            else (
                ": the joint opens (F_A above the separation load at F_M,min), F_KR,min is "
                "reported as 0"
                if s["_f_kr_raw"] <= 0.0
                else ""
            )
            + ": raise the preload floor (torque, method) or lower F_A"
        ),
        "R8_working_stress": f"σ_red,B = {q(stress, 'MPa', 4)} at F_S,max = "
        "F_M,max + Φ_n F_A − ΔF_Vth (a thermal gain only) = "
        f"{_kn(s['max_bolt_force'])} vs R_p0.2 = {q(s['_yield_t'], 'MPa', 4)}"
        + ("" if x.get("service_temperature") is None else " at the service temperature")
        + f": S_F = {s_f:.3g} (≥ 1.0)",
        "R12_slip": "S_G = F_KR,min q_F μ_T / (F_Q + M_Y q_F/(q_M r_a)) = "
        f"{s['slip_safety']:.3g} (VDI asks ≥ {need:g} "
        f"for {'alternating' if need > 1.2 else 'static'} load)",
        "seed_004_preload_stress": f"σ0 = F_M,nom/A_0 = {q(sigma0, 'MPa', 4)} = "
        f"{s['preload_stress_ratio']:.2f} σ_T; [004, eq. 6] allows {lo_rule:g}…{hi_rule:g} σ_T "
        f"({why}); VDI 2230 R7 instead limits the equivalent stress to ν R_p0.2 (ν = {nu:g}), "
        "which allows more",
    }
    if s["_checks"]["R9_fatigue"][0]:  # a static load has no R9 check (nor its sentence)
        out["R9_fatigue"] = (
            "σ_a = Φ_n (F_A,max − F_A,min)/(2 A_S) = "
            f"{q(s['stress_amplitude'], 'MPa')} vs σ_AS = {q(s['endurance_limit'], 'MPa')}: "
            f"S_D = {s['fatigue_safety']:.3g} (VDI asks ≥ 1.2)"
        )
    if "R12_fitted_shear" in s["_checks"] and s["_checks"]["R12_fitted_shear"][0]:
        out["R12_fitted_shear"] = (
            f"fitted shank: τ_Q = F_Q/(q_F A_τ) = {q(s['fitted_shear_stress'], 'MPa', 4)} vs "
            f"τ_B = 0.6 R_m: S_A = {s['fitted_shear_safety']:.3g} (VDI asks ≥ 1.1); bearing "
            f"p_Q = {q(s['fitted_bearing_pressure'], 'MPa', 4)} on the thinnest plate, to hold "
            "against the plate's bearing strength"
        )
    if s["_checks"]["opening_limit"][0]:
        opens_ok = bool(s["_checks"]["opening_limit"][1])
        out["opening_limit"] = (
            f"F_A = {_kn(f_a)} vs the opening limit F_Aab = {_kn(s['separation_load'])} at "
            f"F_M,min (Φ*_en = {s['load_factor']:.4g}, F_KA = {_kn(s['opening_clamp_force'])}, "
            "VDI 2230-1 §5.3.2)"
            + (
                ""
                if opens_ok
                else ": the interface opens at its edge, where Φ*_en and σ_SAb no longer hold "
                "(VDI's nonlinear range); raise the preload or bring the bolt nearer the load"
            )
        )
    nut, f_nut, f_mzul_bolt, _ = s["_nut"]
    if "nut_strength" in s["_checks"]:
        out["nut_strength"] = nut_strength_text(
            nut,
            f_nut,
            f"the bolt's F_M,zul = {_kn(f_mzul_bolt)} and F_S,max = {_kn(s['max_bolt_force'])}",
            bool(s["_checks"]["nut_strength"][1]),
        )
    if "nut_class_pairing" in s["_checks"]:
        out["nut_class_pairing"] = nut_class_pairing_text(
            nut, bolt.tensile_strength or 0.0, bool(s["_checks"]["nut_class_pairing"][1])
        )
    if "nut_thread_stripping" in s["_checks"]:
        out["nut_thread_stripping"] = nut_stripping_text(
            nut,
            s["nut_stripping_force"],
            f"F_S,max = {_kn(s['max_bolt_force'])}",
            bool(s["_checks"]["nut_thread_stripping"][1]),
        )
    if "R7_max_below_permissible" in s["_checks"]:
        top_ok = s["_checks"]["R7_max_below_permissible"][1]
        out["R7_max_below_permissible"] = (
            f"F_M,max = {_kn(fm_max)} from the torque vs F_M,zul = {_kn(f_mzul)} "
            f"(ν = {nu:g} at μ_G,min)"
            + ("" if top_ok else ": lower the torque or narrow its tolerance")
        )
    del fm_min
    return out


def _series(ctx: RunContext, s: Mapping[str, Any], x: Mapping[str, Any]) -> dict[str, list[float]]:
    """The joint diagram and the preload window of one solved design, when asked for."""
    series: dict[str, list[float]] = {}
    fm_min, fm_max, f_mzul = (
        s["assembly_preload_min"],
        s["assembly_preload_max"],
        s["permissible_preload"],
    )
    f_a, phi_n, f_z = float(x["working_load"]), s["load_factor"], s["embedding_loss"]
    if ctx.wants(*_DIAGRAM):
        diagram = jt.joint_diagram(
            fm_min, s["bolt_compliance"], s["eccentric_clamped_compliance"], f_a, phi_n, f_z
        )
        series.update({f"diagram_{k}": v for k, v in diagram.items()})
    if ctx.wants(*_WINDOW):
        fa_sep_any = s["_fa_sep_any"]
        top = max(2.0 * f_a, min(fa_sep_any, 1e9) if math.isfinite(fa_sep_any) else 2.0 * f_a)
        top = top if top > 0.0 else f_mzul
        loads = [top * i / 40 for i in range(41)]
        f_kerf, th_loss = s["required_clamp_force"], s["thermal_loss"]
        # R5 and R6 over the 41 loads at once (the same operations on each, as floats)
        grid: Any = np.array(loads)
        req: Any = jt.minimum_assembly_preload(f_kerf, grid, phi_n, f_z, th_loss)
        req_max: Any = jt.required_preload_max(s["_alpha_req"], req)
        series.update(
            window_working_load=loads,
            window_required_min=req.tolist(),
            window_required_max=req_max.tolist(),
            window_permissible=[f_mzul] * len(loads),
            window_assembly_min=[fm_min] * len(loads),
            window_assembly_max=[fm_max] * len(loads),
        )
    return series


_DIAGRAM = tuple(
    f"diagram_{k}"
    for k in (
        "deformation",
        "bolt_line",
        "clamped_line",
        "embedded_clamped_line",
        "preload_level",
        "service_preload_level",
        "working_bolt_force_level",
        "residual_clamp_level",
        "working_deformation",
        "working_force",
        "opening_deformation",
        "opening_force",
    )
)
_WINDOW = (
    "window_working_load",
    "window_required_min",
    "window_required_max",
    "window_permissible",
    "window_assembly_min",
    "window_assembly_max",
)


def _f(name: str, desc: str, **kw: Any) -> Output:
    return Output(name, "N", desc, display_unit="kN", **kw)


JOINT_OUTPUTS: tuple[Output, ...] = (
    Output(
        "tightening_factor",
        "1",
        "R1: α_A = F_M,max/F_M,min (method, given, or torque box)",
        symbol="α_A",
        step="VDI 2230-1 R1",
    ),
    _f(
        "required_clamp_force",
        "R2: F_K,erf = max(F_KQ, F_KP + F_KA)",
        symbol="F_K,erf",
        step="VDI 2230-1 R2",
    ),
    _f(
        "opening_clamp_force",
        "R2: F_KA = F_A (a − s_sym) u/(I_BT/A_D + s_sym u), not below 0 (0 concentric)",
        symbol="F_KA",
        step="VDI 2230-1 R2",
    ),
    _f(
        "transverse_clamp_force",
        "R2: F_KQ = F_Q/(q_F μ_T,min) + M_Y/(q_M r_a μ_T,min)",
        symbol="F_KQ",
        step="VDI 2230-1 R2",
    ),
    Output(
        "bolt_compliance",
        "m/N",
        "R3: δ_S, head + shank + free thread + engaged thread + nut",
        symbol="δ_S",
        step="VDI 2230-1 R3",
    ),
    Output(
        "bolt_compliance_head",
        "m/N",
        "R3: δ_SK = l_SK/(E_S A_N), l_SK = 0.5 d / 0.4 d",
        symbol="δ_SK",
        step="VDI 2230-1 R3",
    ),
    Output(
        "bolt_compliance_shank",
        "m/N",
        "R3: Σ l_i/(E_S A_i) of the plain and reduced shank",
        symbol="δ_i",
        step="VDI 2230-1 R3",
    ),
    Output(
        "bolt_compliance_free_thread",
        "m/N",
        "R3: δ_Gew = l_Gew/(E_S A_d3)",
        symbol="δ_Gew",
        step="VDI 2230-1 R3",
    ),
    Output(
        "bolt_compliance_engaged",
        "m/N",
        "R3: δ_GM = 0.5 d/(E_S A_d3) + l_M/(E_M A_N), l_M = 0.4 d (nut) / 0.33 d (tapped)",
        symbol="δ_GM",
        step="VDI 2230-1 R3",
    ),
    Output(
        "clamped_compliance",
        "m/N",
        "R3: δ_P, deformation cone and sleeve, plate by plate",
        symbol="δ_P",
        step="VDI 2230-1 R3",
    ),
    Output(
        "eccentric_clamped_compliance",
        "m/N",
        "R3 §5.3.2: δ*_P = δ_P + s_sym² β_P (δ_P for a concentric joint)",
        symbol="δ*_P",
        step="VDI 2230-1 R3 §5.3.2",
    ),
    Output(
        "substitute_bending_inertia",
        "m^4",
        "R3 §5.3.2: I_Bers of cone (Steiner-shifted by s_sym) and sleeve b c_T³/12 in series "
        "(null without the interface)",
        symbol="I_Bers",
        step="VDI 2230-1 R3 §5.3.2",
    ),
    Output(
        "clamped_bending_compliance",
        "1/(N*m)",
        "R3 §5.3.2: β_P = Σ h_i/E_i / I_Bers (null without the interface)",
        symbol="β_P",
        step="VDI 2230-1 R3 §5.3.2",
    ),
    Output(
        "bolt_bending_compliance",
        "1/(N*m)",
        "R9 §5.1.1.2: β_S = Σ l_i/(E I_i) over the bolt's sections (null without the interface)",
        symbol="β_S",
        step="VDI 2230-1 R9 §5.1.1.2",
    ),
    Output(
        "cone_tangent",
        "1",
        "R3: tan φ of the deformation cone (VDI fit)",
        symbol="tan φ",
        step="VDI 2230-1 R3",
    ),
    Output(
        "cone_limit_diameter",
        "m",
        "R3: D_A,Gr = d_W + w l_K tan φ",
        display_unit="mm",
        symbol="D_A,Gr",
        step="VDI 2230-1 R3",
    ),
    Output(
        "outer_diameter_used",
        "m",
        "R3: D_A used",
        display_unit="mm",
        symbol="D_A",
        step="VDI 2230-1 R3",
    ),
    Output(
        "grip",
        "m",
        "R3: clamp length l_K = Σ h_i",
        display_unit="mm",
        symbol="l_K",
        step="VDI 2230-1 R3",
    ),
    Output(
        "load_factor_k",
        "1",
        "R3: Φ_K = δ_P/(δ_S + δ_P) (load under head and nut)",
        symbol="Φ_K",
        step="VDI 2230-1 R3",
    ),
    Output(
        "load_factor",
        "1",
        "R3: Φ_n = n Φ_K; eccentric: Φ*_en = n δ**_P/(δ_S + δ*_P), δ**_P = δ_P + a s_sym β_P",
        symbol="Φ_n",
        step="VDI 2230-1 R3",
    ),
    _f("additional_bolt_load", "R3/R8: F_SA = Φ_n F_A,max", symbol="F_SA", step="VDI 2230-1 R3/R8"),
    _f("clamp_load_reduction", "R3: F_PA = (1 − Φ_n) F_A,max", symbol="F_PA", step="VDI 2230-1 R3"),
    Output(
        "embedding_settlement",
        "m",
        "R4: f_Z from the VDI table",
        display_unit="mm",
        symbol="f_Z",
        step="VDI 2230-1 R4",
    ),
    _f("embedding_loss", "R4: F_Z = f_Z/(δ_S + δ_P)", symbol="F_Z", step="VDI 2230-1 R4"),
    _f(
        "thermal_loss",
        "R4: ΔF_th (positive: preload lost) at F_V,min",
        symbol="ΔF_th",
        step="VDI 2230-1 R4",
    ),
    _f(
        "required_preload_min",
        "R5: F_M,min = F_K,erf + (1 − Φ_n) F_A + F_Z + ΔF_th",
        symbol="F_M,min",
        step="VDI 2230-1 R5",
    ),
    _f("required_preload_max", "R6: F_M,max = α_A F_M,min", symbol="F_M,max", step="VDI 2230-1 R6"),
    Output(
        "smallest_diameter",
        "m",
        "R7: d_0 of the smallest section",
        display_unit="mm",
        symbol="d_0",
        step="VDI 2230-1 R7",
    ),
    Output("smallest_area", "m^2", "R7: A_0 = π d_0²/4", symbol="A_0", step="VDI 2230-1 R7"),
    _f(
        "permissible_preload",
        "R7: F_M,zul = ν R_p0.2 A_0/β at the smallest section, μ_G,min",
        symbol="F_M,zul",
        step="VDI 2230-1 R7",
    ),
    _f(
        "yield_preload",
        "R7: preload at σ_red = R_p0.2 (ν = 1)",
        symbol="F_M0.2",
        step="VDI 2230-1 R7",
    ),
    _f(
        "assembly_preload_min",
        "R1/R13: lowest assembly preload (F_M,zul/α_A or torque box)",
        symbol="F_M,min",
        step="VDI 2230-1 R1/R13",
    ),
    _f(
        "assembly_preload_max",
        "R1/R13: highest assembly preload (F_M,zul or torque box)",
        symbol="F_M,max",
        step="VDI 2230-1 R1/R13",
    ),
    Output(
        "tightening_torque",
        "N*m",
        "R13: M_A for F_M,zul at μ_G,min, μ_K,min plus M_ü (VDI 2230-1 R13: the α_A band lies "
        "below F_M,zul), or the torque given; not the torque for a nominal preload at mean "
        "friction (preload.control target_torque)",
        symbol="M_A",
        step="VDI 2230-1 R13",
    ),
    _f(
        "residual_clamp_force_min",
        "R12: F_KR,min = F_M,min − (1 − Φ_n) F_A − F_Z − ΔF_th, 0 where the joint opens",
        symbol="F_KR,min",
        step="VDI 2230-1 R12",
    ),
    _f(
        "separation_load",
        "R5/R12: F_A at which the joint opens from the lowest assembly preload; eccentric: the "
        "opening limit F_Aab = F_V/(1 − Φ*_en + F_KA/F_A)",
        symbol="F_Aab",
        step="VDI 2230-1 R5/R12",
    ),
    _f(
        "max_working_load",
        "R5–R7: largest F_A whose required window fits under F_M,zul",
        symbol="F_A,max",
        step="VDI 2230-1 R5–R7",
    ),
    _f(
        "max_bolt_force",
        "R8: F_S,max = F_M,max + Φ_n F_A,max",
        symbol="F_S,max",
        step="VDI 2230-1 R8",
    ),
    Output(
        "working_stress",
        "Pa",
        "R8: σ_red,B (k_τ = 0.5)",
        display_unit="MPa",
        symbol="σ_red,B",
        step="VDI 2230-1 R8",
    ),
    Output("yield_safety", "1", "R8: S_F = R_p0.2/σ_red,B", symbol="S_F", step="VDI 2230-1 R8"),
    Output(
        "stress_amplitude",
        "Pa",
        "R9: σ_a = Φ_n (F_A,max − F_A,min)/(2 A_S); eccentric: σ_ab = (σ_SAbo − σ_SAbu)/2",
        display_unit="MPa",
        symbol="σ_a",
        step="VDI 2230-1 R9",
    ),
    Output(
        "additional_bolt_stress",
        "Pa",
        "R9: σ_SAb = Φ_b F_A,max/A_S, Φ_b = Φ*_en + (a − s_sym Φ*_en)(β_P/β_S)(A_S/W_S) with the "
        "bending (σ_SA = Φ_n F_A/A_S concentric)",
        display_unit="MPa",
        symbol="σ_SAb",
        step="VDI 2230-1 R9",
    ),
    Output(
        "endurance_limit",
        "Pa",
        "R9: σ_ASV or σ_ASG",
        display_unit="MPa",
        symbol="σ_AS",
        step="VDI 2230-1 R9",
    ),
    Output(
        "fatigue_safety",
        "1",
        "R9: S_D = σ_AS/σ_a (null for static load)",
        symbol="S_D",
        step="VDI 2230-1 R9",
    ),
    Output(
        "slip_safety",
        "1",
        "R12: S_G = F_KR,min q_F μ_T/(F_Q + M_Y q_F/(q_M r_a)) (null without F_Q and M_Y; 0 "
        "where it opens)",
        symbol="S_G",
        step="VDI 2230-1 R12",
    ),
    Output(
        "fitted_shear_stress",
        "Pa",
        "R12 fitted bolt: τ_Q = F_Q/(q_F π d_τ²/4) (null without fitted_diameter)",
        display_unit="MPa",
        symbol="τ_Q",
        step="VDI 2230-1 R12",
    ),
    Output(
        "fitted_shear_safety",
        "1",
        "R12 fitted bolt: S_A = 0.6 R_m/τ_Q, VDI asks ≥ 1.1 (null without fitted_diameter, R_m "
        "or F_Q)",
        symbol="S_A",
        step="VDI 2230-1 R12",
    ),
    Output(
        "fitted_bearing_pressure",
        "Pa",
        "R12 fitted bolt: p_Q = F_Q/(d_τ h_min) on the thinnest plate (null without "
        "fitted_diameter)",
        display_unit="MPa",
        symbol="p_Q",
        step="VDI 2230-1 R12",
    ),
    Output(
        "preload_stress_ratio",
        "1",
        "[004, eq. 6]: σ0/σ_T at the nominal preload, on A_0",
        symbol="σ_0/σ_T",
        step="[004, eq. 6]",
    ),
    Output(
        "bolt_elongation",
        "m",
        "[004, eq. 7]: F_M,nom δ_S",
        display_unit="mm",
        symbol="Δl",
        step="[004, eq. 7]",
    ),
    Output(
        "target_angle",
        "rad",
        "[004, eq. 8]: nut angle from snug to F_M,nom with δ_S + δ_P (R3)",
        display_unit="deg",
        symbol="φ",
        step="[004, eq. 8]",
    ),
    Output(
        "rigid_joint_angle",
        "rad",
        "[004, eq. 9]: the same with rigid plates (what a rigid default gives)",
        display_unit="deg",
        symbol="φ_rigid",
        step="[004, eq. 9]",
    ),
    Output(
        "nut_stripping_force",
        "N",
        "R11 for a nut that does not pair with the bolt (thin, weaker class): F_SM = "
        "C1 C3 τ_BM A_SGM over m − 2P, τ_BM = 0.6 S_p (null where the nut pairs or is absent)",
        display_unit="kN",
        symbol="F_SM",
        step="VDI 2230-1 R11",
    ),
    Output(
        "yield_strength_at_temperature",
        "Pa",
        "R8 at service_temperature: R_p0.2(T) = R_p0.2 × R_p0.2,T/R_p0.2,20°C of the class "
        "(ISO 898-1 Annex A), the yield strength of S_F in service (R7, tightened cold, keeps "
        "R_p0.2 at room temperature; null at room temperature)",
        display_unit="MPa",
        symbol="R_p0.2,T",
        step="VDI 2230-1 R8",
    ),
    Output(
        "bolt_modulus_ratio_at_temperature",
        "1",
        "R4 at service_temperature: E_S,T/E_S,RT of the bolt (steel table), in ΔF_Vth (null at "
        "room temperature)",
        symbol="E_S,T/E_S,RT",
        step="VDI 2230-1 R4",
    ),
    Output(
        "plate_modulus_ratio_at_temperature",
        "1",
        "R4 at service_temperature: E_P,T/E_P,RT of the plates, δ_P/Σ(δ_i E_i,RT/E_i,T), in "
        "ΔF_Vth (null at room temperature)",
        symbol="E_P,T/E_P,RT",
        step="VDI 2230-1 R4",
    ),
    Output(
        "diagram_deformation",
        "m",
        "Joint diagram (VDI §3.2): deformation axis",
        series=True,
        display_unit="mm",
    ),
    _f(
        "diagram_bolt_line",
        "Joint diagram: bolt line F = f/δ_S",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_clamped_line",
        "Joint diagram: clamped-part line through F_M,min",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_embedded_clamped_line",
        "Joint diagram: clamped-part line after embedding (R4)",
        series=True,
        x="diagram_deformation",
    ),
    _f("diagram_preload_level", "Joint diagram: F_M,min", series=True, x="diagram_deformation"),
    _f(
        "diagram_service_preload_level",
        "Joint diagram: F_V = F_M,min − F_Z",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_working_bolt_force_level",
        "Joint diagram: F_V + Φ_n F_A",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_residual_clamp_level",
        "Joint diagram: residual clamp force F_V − (1 − Φ_n) F_A",
        series=True,
        x="diagram_deformation",
    ),
    Output(
        "diagram_working_deformation",
        "m",
        "Joint diagram: the working point's deformation f_SV + Φ_n F_A δ_S (2 points)",
        series=True,
        display_unit="mm",
    ),
    _f(
        "diagram_working_force",
        "Joint diagram: F_A at the working point, from F_KR up to F_S (VDI's split by Φ_n)",
        series=True,
        x="diagram_working_deformation",
    ),
    Output(
        "diagram_opening_deformation",
        "m",
        "Joint diagram: where the joint separates, at F_A = F_V/(1 − Φ_n) (2 points)",
        series=True,
        display_unit="mm",
    ),
    _f(
        "diagram_opening_force",
        "Joint diagram: the bolt force at separation, from 0 up (F_KR = 0)",
        series=True,
        x="diagram_opening_deformation",
    ),
    _f("window_working_load", "Preload window: F_A axis", series=True),
    _f(
        "window_required_min",
        "Preload window: R5 F_M,min(F_A)",
        series=True,
        x="window_working_load",
    ),
    _f(
        "window_required_max",
        "Preload window: R6 α_A F_M,min(F_A)",
        series=True,
        x="window_working_load",
    ),
    _f("window_permissible", "Preload window: R7 F_M,zul", series=True, x="window_working_load"),
    _f(
        "window_assembly_min",
        "Preload window: lowest assembly preload",
        series=True,
        x="window_working_load",
    ),
    _f(
        "window_assembly_max",
        "Preload window: highest assembly preload",
        series=True,
        x="window_working_load",
    ),
)

#: The scalar outputs, in declaration order.
_SCALARS: tuple[str, ...] = tuple(o.name for o in JOINT_OUTPUTS if not o.series)

#: The intermediate values a single design's sentences and series read, as Python floats.
_READ_AS_FLOATS = ("_alpha_req", "_fa_sep_any", "_f_kr_raw")

#: Outputs only an eccentric joint (interface given) or a fitted bolt has.
_GIVEN_ONLY = (
    "substitute_bending_inertia",
    "clamped_bending_compliance",
    "bolt_bending_compliance",
    # and the fitted bolt's, only with fitted_diameter
    "fitted_shear_stress",
    "fitted_shear_safety",
    "fitted_bearing_pressure",
    # and the service temperature's, only with service_temperature
    "yield_strength_at_temperature",
    "bolt_modulus_ratio_at_temperature",
    "plate_modulus_ratio_at_temperature",
)

# --------------------------------------------------------------------------- array path
#
# ``_vectorized`` runs :func:`_solve` (the lines a single run runs) for a request whose
# numeric inputs may be arrays (a sweep, a study's chunk). The text and choice
# inputs are fixed per request and read once; the bolt comes from the one bolt resolution
# of every model (:func:`engine.procedures.bolt.resolve_bolts`, per distinct size where a
# catalogue part meets a varied size). A point the procedure refuses is NaN in every
# output and unreported in every check. Series (joint diagram, preload window) are not
# part of it: they belong to single runs.

#: Bolt fields carried as arrays ([m, m², Pa]).
_BOLT_FIELDS = (
    "tensile_strength",
    "diameter",
    "pitch",
    "pitch_diameter",
    "minor_diameter",
    "stress_diameter",
    "stress_area",
    "yield_strength",
    "bearing_outer_diameter",
    "hole_diameter",
)


def _size(x: Mapping[str, Any]) -> int:
    sizes = {v.shape[0] for v in x.values() if isinstance(v, np.ndarray) and v.ndim == 1}
    if len(sizes) > 1:
        raise ValueError(f"varied inputs of different lengths {sorted(sizes)}")
    return sizes.pop() if sizes else 1


def _vector_hook_checks(
    x: Mapping[str, Any],
    col: Callable[[str], np.ndarray],
    bolts: list[Bolt],
    index: np.ndarray,
    ok: np.ndarray | None,
    bearing: Any,
    hole: Any,
    fm_max: Any,
    f_s_max: Any,
    probe: Callable[[int], tuple[list[Check], list[str]]],
    verdicts: bool = True,
) -> tuple[dict[str, np.ndarray], list[str]]:
    """The verdicts of ``fz.joint_check_hook`` (VDI 2230-1 R10, R11, ISO 2936) on arrays.

    Which checks a bolt gets is fixed per request and bolt, so the scalar hook runs once
    per distinct bolt (``probe``: at its first computable point) for their names, its notes
    and its refusals; the verdicts are then the same comparisons as
    :func:`engine.procedures.bolt.bought_part_checks`, on arrays. A check name this does
    not know raises TypeError (the caller loops instead). Without ``verdicts`` (a sweep
    reads no check) only the notes are made. ``ok``: the points not refused (None: every
    point).
    """
    n = index.size
    out: dict[str, np.ndarray] = {}
    notes: list[str] = []
    limit: Any = None
    if x.get("limiting_surface_pressure") is not None:
        limit = col("limiting_surface_pressure")
    elif x.get("clamped_material") is not None:
        limit = fa.material(str(x["clamped_material"])).limiting_surface_pressure
    tau: Any = None
    if x.get("internal_thread_shear_strength") is not None:
        tau = np.broadcast_to(col("internal_thread_shear_strength"), (n,))
    elif x.get("internal_thread_material") is not None:
        tau = np.full(n, fa.material(str(x["internal_thread_material"])).shear_strength)
    for k, bolt in enumerate(bolts):
        # one bolt: the index is 0 wherever the bolt resolved, and ok is within that
        sel: Any = ok if len(bolts) == 1 else index == k if ok is None else ok & (index == k)
        if sel is None:  # one bolt, every point
            sel = slice(None)
        elif not sel.any():
            continue
        checks, said = probe(0 if type(sel) is slice else int(np.argmax(sel)))  # its first point
        notes += [s for s in said if s not in notes]
        if not verdicts:
            continue
        fastener = bolt.fastener or fz.Fastener("", None, None, None)
        outer, inner = bearing, hole
        if x.get("washer") is not None and fastener.thread is not None:
            w = fa.washer(str(x["washer"]), fastener.thread)
            outer, inner = w.outer_diameter, np.maximum(w.inner_diameter, hole)
        for check in checks:
            name = check.name
            if name in ("surface_pressure_assembly", "surface_pressure_working"):
                force = fm_max if name == "surface_pressure_assembly" else f_s_max
                verdict = fa.surface_pressure(force, outer, inner) <= limit
            elif name == "surface_pressure_nut" and fastener.thread is not None:
                nut = fa.nut(str(x["nut"]), fastener.thread)
                nut_outer = _nut_side_outer(x, col)
                face = (
                    nut.bearing_diameter
                    if nut_outer is None
                    else np.minimum(nut.bearing_diameter, nut_outer)
                )
                verdict = fa.surface_pressure(fm_max, face, hole) <= limit
            elif (
                name == "thread_stripping" and tau is not None and bolt.tensile_strength is not None
            ):
                verdict = col("engagement_length") >= _min_engagement(bolt, tau, sel)
            elif name == "drive_torque" and fastener.head is not None:
                key = fa.hex_key_torque(fastener.head.drive_size)
                verdict = col("tightening_torque") <= (np.inf if key is None else key)
            else:
                raise TypeError(f"check hook gives {name!r}, which has no array form here")
            codes = out.setdefault(name, np.full(n, -1, dtype=np.int8))
            codes[sel] = np.asarray(verdict, dtype=np.int8)[sel] if np.ndim(verdict) else verdict
    return out, notes


def _min_engagement(bolt: Bolt, tau: np.ndarray, sel: np.ndarray) -> np.ndarray:
    """Least length of engagement (VDI 2230-1 R11) per point, once per distinct τ_BM."""
    assert bolt.tensile_strength is not None
    result = np.full(tau.shape, np.nan)
    values, where = np.unique(tau[sel], return_inverse=True)
    lengths = [
        fa.engagement_for_bolt_failure(
            bolt.diameter,
            bolt.pitch,
            bolt.pitch_diameter,
            th.nut_minor_diameter(bolt.diameter, bolt.pitch),
            bolt.stress_area,
            bolt.tensile_strength,
            fz.BOLT_SHEAR_RATIO * bolt.tensile_strength,
            t,
            1.0,
        ).min_engagement_length
        for t in values.tolist()
    ]
    result[sel] = np.asarray(lengths, dtype=float)[np.asarray(where).reshape(-1)]
    return result


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    with np.errstate(all="ignore"):
        try:
            return _vector_solution(x, ctx)
        except (LookupError, AttributeError) as exc:
            # the array path is an optimisation, the scalar compute the reference: an input
            # combination it was not written for goes to the loop (points.vector on TypeError)
            raise TypeError(f"joint array path: {type(exc).__name__}: {exc}") from exc


def _vector_solution(x: Mapping[str, Any], ctx: RunContext) -> Result:
    for name in ("head", "joint_type", "surface_roughness", "method", "rolling", "controlled"):
        if isinstance(x.get(name), np.ndarray):
            raise TypeError(f"{name} is fixed per request on the array path")
    n = _size(x)

    def col(name: str) -> Any:
        """A varied input as a float array, a fixed one as a numpy scalar (broadcast later)."""
        value = x[name]
        if isinstance(value, np.ndarray):
            return value.astype(float, copy=False)
        return np.float64(value)

    resolved, notes = resolve_bolts(x, n, labels=False, per_size=True)
    bolts, bolt_index = resolved.distinct()
    b: dict[str, Any] = {
        f: v.astype(float, copy=False) if isinstance(v, np.ndarray) else np.float64(v)
        for f in _BOLT_FIELDS
        for v in (getattr(resolved, f),)
    }
    refused: Any = np.False_ if resolved.ok.all() else ~resolved.ok  # a mask only where needed
    b["_strength_class"] = _strength_class(x, bolts[0] if bolts else None)
    if x.get("nut") is not None:
        strengths = {k.tensile_strength for k in bolts} - {None}
        if len(strengths) > 1:
            raise TypeError("nut with varied bolt classes: the nut is rated per point")
        threads = {None if k is None or k.fastener is None else k.fastener.thread for k in bolts}
        b["_nut"] = _nut_choice(
            x, strengths.pop() if strengths else None, threads.pop() if len(threads) == 1 else None
        )
    refusals = _Refusals(refused, many=True)
    # a sweep reads no check: the steps only they (and no asked output) read are left out
    s = _solve(
        x,
        col,
        b,
        refusals,
        None if ctx.checks else ctx.outputs,
        swept_ends(ctx.scratch, "working_load"),
    )
    mask = refusals.mask
    every_refused = bool(mask.all()) if isinstance(mask, np.ndarray) else bool(mask)
    any_refused = bool(mask.any()) if isinstance(mask, np.ndarray) else every_refused
    refused = np.broadcast_to(mask, (n,))
    if every_refused:
        # alone, the first point says why it is refused (InputOutOfRange naming the field, or
        # the arithmetic); the caller then runs each point alone
        _compute({k: (v[0].item() if isinstance(v, np.ndarray) else v) for k, v in x.items()}, ctx)
        raise TypeError("every point is refused")  # pragma: no cover (alone it computes)
    warnings: list[str] = []
    joint_type = str(x["joint_type"])
    d_w, d_h = b["bearing_outer_diameter"], b["hole_diameter"]
    fm_max, f_s_max = s["assembly_preload_max"], s["max_bolt_force"]

    def somewhere(condition: Any) -> bool:
        """Whether ``condition`` holds at a point not refused (some point is not)."""
        if np.ndim(condition) == 0:
            return bool(condition)
        return bool(np.any(condition & ~refused if any_refused else condition))

    if x.get("outer_diameter") is None:
        notes.append("D_A not given: plates taken just wide enough for the full cone (D_A,Gr)")
    if somewhere(s["cone_tangent"] <= jt.MIN_CONE_TANGENT):
        warnings.append(
            f"plates very thin against d_W: the cone tangent is held at {jt.MIN_CONE_TANGENT}"
        )
    if not bool(x["controlled"]) and somewhere(b["diameter"] < 0.010):
        warnings.append(
            "d < 10 mm tightened without control: [004] warns of over-tightening; lower the "
            "admissible load or control the tightening"
        )

    # hooks (R10 surface pressure, R11 engagement) -------------------------------------------------
    def probe(j: int) -> tuple[list[Check], list[str]]:
        point = {k: (v[j].item() if isinstance(v, np.ndarray) else v) for k, v in x.items()}
        bolt = resolved.at(j)

        def at(value: Any) -> float:
            if not isinstance(value, np.ndarray) or value.ndim == 0:
                return float(value)
            return float(np.broadcast_to(value, (n,))[j])

        solution = JointSolution(
            bolt,
            at(s["grip"]),
            at(d_w),
            at(d_h),
            at(fm_max),
            at(f_s_max),
            joint_type,
            _nut_side_outer(point, lambda name: float(point[name])),
        )
        return _scalar_hooks(point, solution)

    hook_checks, hook_notes = _vector_hook_checks(
        x,
        col,
        bolts,
        bolt_index,
        ~refused if any_refused else None,
        d_w,
        d_h,
        fm_max,
        f_s_max,
        probe,
        ctx.checks,
    )
    notes += hook_notes
    notes.append(MODEL_FORM_NOTE)
    nut, _, _, nut_limits = s["_nut"]
    if nut is not None and somewhere(nut_limits):
        warnings.append(
            nut_limit_warning(nut, None, None)
            + ", the preload window and the torque are built on it"
        )
    # F_KR at the ends of F_A over the points not refused (_solve), or at every point
    opens = (
        bool((s["_f_kr_raw"] < 0.0).any()) if s["_f_kr_ends"] else somewhere(s["_f_kr_raw"] < 0.0)
    )
    if opens:
        warnings.append(
            "the joint opens at some points (F_A above the separation load at F_M,min): "
            "residual_clamp_force_min and slip_safety are 0 there"
        )

    columns, finite = _output_columns(
        s,
        [name for name in _SCALARS if name in ctx.outputs],
        n,
        refused if any_refused else None,
        (*x.values(), *b.values()),
        s["_finite"],
    )
    values: dict[str, Any] = dict(columns)
    verdicts: dict[str, Any] = {}
    if ctx.checks:  # a sweep reads none of them
        verdicts = {
            name: ok if applies is True else np.where(applies, ok, -1)
            for name, (applies, ok) in s["_checks"].items()
        }
        verdicts.update(hook_checks)
    reported: dict[str, Any] = {}
    for name, verdict in verdicts.items():
        codes = np.empty(n, dtype=np.int8)
        codes[...] = verdict
        if any_refused:
            codes[refused] = -1
        if (codes >= 0).any():  # a check no point reports is not in the scalar answers either
            reported[name] = codes
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        notes=notes,
        warnings=warnings,
        check_arrays=reported,
        finite=finite,
    )


#: Points from which an output array is written in place rather than copied: below, the copy
#: of a column costs less than the calls that test and write it alone.
IN_PLACE_FROM = 8192


def _output_columns(
    s: Mapping[str, Any],
    asked: list[str],
    n: int,
    refused: np.ndarray | None,
    foreign: tuple[Any, ...],
    finite: frozenset[str] = frozenset(),
) -> tuple[dict[str, np.ndarray], frozenset[str]]:
    """The ``asked`` outputs of the solved joint ``s`` as float columns of ``n`` points: null
    (NaN) where not finite, as the runner makes a non-finite value, and at the ``refused``
    points. From :data:`IN_PLACE_FROM` points on, an array the procedure made for this
    request is written in place; the rest (a number, an input or bolt value in ``foreign``,
    a column given already) is copied into one table, each a row, tested for a non-finite
    value in one pass; a column named in ``finite`` (the procedure knows it finite at every
    point) is not tested. With the columns, the names of those finite at every point (none
    where a point is refused): the caller need not test them again."""
    made: dict[str, np.ndarray] = {}
    if n >= IN_PLACE_FROM:
        taken = {id(v) for v in foreign if isinstance(v, np.ndarray)}
        for name in asked:
            value = s[name]
            if (
                isinstance(value, np.ndarray)
                and value.shape == (n,)
                and value.dtype == np.float64
                and value.flags.owndata
                and value.flags.writeable
                and id(value) not in taken
            ):
                made[name] = value
                taken.add(id(value))
    rest = [name for name in asked if name not in made]
    columns = [*made.values()]
    held = [[name] for name in made]  # the names each column holds
    if rest:
        table = np.empty((len(rest), n))
        for row, name in zip(table, rest, strict=True):
            row[...] = s[name]
        columns.append(table)
        held.append(rest)
    found: list[str] = []
    for names, column in zip(held, columns, strict=True):
        if not (finite.issuperset(names) or all_finite(column)):
            column[~np.isfinite(column)] = np.nan  # a NaN or inf: one pass more to find them
        elif refused is None:
            found += names
        if refused is not None:
            column[..., refused] = np.nan
    given = {**made, **(dict(zip(rest, table, strict=True)) if rest else {})}
    return {name: given[name] for name in asked}, frozenset(found)


def _scalar_hooks(x: Mapping[str, Any], solution: JointSolution) -> tuple[list[Check], list[str]]:
    checks: list[Check] = []
    notes: list[str] = []
    for hook in CHECK_HOOKS:
        if hook not in VECTOR_CHECK_HOOKS:
            raise TypeError(f"check hook {hook!r} has no array form")
        more_checks, more_notes = hook(x, solution)
        checks += more_checks
        notes += more_notes
    return checks, notes


#: The hooks whose checks :func:`_vector_hook_checks` knows on arrays; another hook in
#: :data:`CHECK_HOOKS` sends the request to the per-point loop.
VECTOR_CHECK_HOOKS: tuple[CheckHook, ...] = (fz.joint_check_hook,)


#: The rung's estimate is typical, not a bound: it is the arithmetic's, and leaves the model
#: form out (the label is Rung's ``estimate_kind`` where the spec has it).
_TYPICAL: dict[str, Any] = (
    {"estimate_kind": "typical"} if "estimate_kind" in Rung.__dataclass_fields__ else {}
)

CLOSED_FORM = Rung(
    "closed_form",
    "The VDI 2230-1 calculation steps in closed form (cone/sleeve integrals, no iteration "
    "beyond the D_A fixed point). Its error estimate, 0, is that of the arithmetic (the cone "
    "integral against quadrature: within 1e-11 over 200 random joints, worst 6e-14, "
    "bench/accuracy_joint.py); "
    "it is typical, not a bound on the answer: the model's empirical parts, the cone-angle fit "
    "behind δ_P, the embedding amounts f_Z, the load-introduction factor n and the friction "
    "range, carry a model-form uncertainty no number here includes",
    fixed_error(0.0),
    typical_error="typical: 0 for the arithmetic (≤ 1e-11 measured); the model form (cone "
    "fit, f_Z, n, friction) is not in it",
    typical_time="< 1 ms",
    **_TYPICAL,
)

VDI2230 = ModelSpec(
    name="joint.vdi2230",
    requirements_of="VDI 2230",
    advice=frozenset(("seed_004_preload_stress", "nut_class_pairing")),
    answer=(
        Answer("tightening_torque", "M_A"),
        Answer("assembly_preload_min", "F_M,min"),
        Answer(
            "permissible_preload",
            "F_M,zul",
            check="R7_window_fits",
            relation="≥",
            bound="required_preload_max",
            bound_symbol="F_M,max",
        ),
        Answer(
            "residual_clamp_force_min",
            "F_KR,min",
            check="residual_clamp_force",
            relation="≥",
            bound="required_clamp_force",
            bound_symbol="F_K,erf",
        ),
        Answer("yield_safety", "S_F", check="R8_working_stress", relation="≥", bound=1.0),
        Answer("fatigue_safety", "S_D", check="R9_fatigue", relation="≥", bound=1.2),
        Answer("slip_safety", "S_G", check="R12_slip"),
    ),
    title="Bolted joint: stiffness, service loads, losses and the preload window (VDI 2230)",
    family="joint",
    summary=(
        "A single bolted joint through VDI 2230 Part 1: bolt and clamped-part compliance "
        "(cone and sleeve, several plates), load factor, working and transverse loads, "
        "embedding and thermal losses, the required preload window against the permissible "
        "preload at the smallest section, the preload range a torque specification gives "
        "over the friction box, working and alternating stress, slipping, and the joint "
        "diagram."
    ),
    source=SOURCE,
    inputs=JOINT_INPUTS,
    outputs=JOINT_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_compute,
    vectorized=_vectorized,
    vector_rungs=("closed_form",),
    assumptions=(
        "VDI 2230-1's text was not available to us: its relations as reproduced in "
        "ECSS-E-HB-32-23A and implemented in misams/BAT (docs/sources.md)",
        "concentric clamping and loading unless bolt_offset, load_lever or opening_edge is "
        "given with the interface (then VDI 2230-1 §5.3.2's linear eccentric relations, valid "
        "while the interface stays closed, F_A ≤ F_Aab); the nut's bearing face as large as "
        "the head's",
    ),
    examples=(
        # M12 8.8 through 2 × 20 mm steel, 8 kN alternating 0…8 kN, 2 kN transverse
        {
            "thread_diameter": 0.012,
            "plate1_thickness": 0.020,
            "plate2_thickness": 0.020,
            "working_load": 8e3,
            "working_load_min": 0.0,
            "transverse_load": 2e3,
        },
        # the question users bring: 80 N·m ± 5 %, μ 0.08…0.16, 0.4 N·m prevailing torque
        {
            "thread_diameter": 0.012,
            "plate1_thickness": 0.020,
            "plate2_thickness": 0.020,
            "tightening_torque": 80.0,
            "torque_tolerance": 0.05,
            "prevailing_torque": 0.4,
            "thread_friction_min": 0.08,
            "thread_friction_max": 0.16,
            "bearing_friction_min": 0.08,
            "bearing_friction_max": 0.16,
            "working_load": 10e3,
        },
        # waisted M12 8.8 screwed into aluminium
        {
            "thread_diameter": 0.012,
            "joint_type": "tapped",
            "head": "socket",
            "bearing_outer_diameter": 0.0173,
            "plate1_thickness": 0.060,
            "reduced_length": 0.050,
            "reduced_diameter": 0.0075,
            "nut_youngs_modulus": 7e10,
            "working_load": 5e3,
        },
        # bought parts: socket-head M8 12.9 into aluminium, 12 mm of thread
        {
            "thread": "M8 ISO 4762 12.9",
            "joint_type": "tapped",
            "head": "socket",
            "plate1_thickness": 0.012,
            "plate1_youngs_modulus": 7e10,
            "nut_youngs_modulus": 7e10,
            "working_load": 4e3,
            "washer": "ISO 7089",
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "engagement_length": 0.012,
        },
    ),
)
