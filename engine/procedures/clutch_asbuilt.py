"""The ball clutch as built: its spring (helical or disc), lift characteristic and checks.

Shared by ``clutch.ball`` and ``clutch.ball_setting`` (engine/models/clutch.py). The
equations are in :mod:`engine.physics.clutch` and :mod:`engine.physics.springs`; this module
declares
the extra inputs and outputs, evaluates the torque-against-lift characteristic
(broadcasting over a swept input) and writes the checks and notes.

Lift convention: ``ball_lift`` h is the ball's (and the pressure disk's) rise along
the flank, from seated to the groove's rim; over the rim it rises another
(d/2)(1 − sin α) before riding on the face. Absent, h is the paper's groove depth,
equal to the spring deflection Δ [001, eq. 2].
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from ..core import points
from ..core.errors import InputOutOfRange
from ..core.params import DEG, count, friction_coefficient, length, positive
from ..core.spec import Check, Output, Param, Plot, Window
from ..core.text import q
from ..physics import springs as sp
from ..physics.clutch import (
    CONSTRUCTIONS,
    RECOMMENDED_SERVICE_FACTOR,
    SELF_LOCKING_MARGIN,
    combined_push_factor,
    friction_sensitivity,
    lift_points,
    residual_torque,
    riding_flank_angle,
    rim_rise,
    rim_torque_slope,
    self_locking_margin,
    torque_against_lift,
    torque_sharing,
)
from ..physics.clutch import acceleration_torque as cl_acceleration_torque
from ..physics.clutch import rated_torque as cl_rated_torque
from ..physics.clutch import required_slip_torque as cl_required_slip_torque

#: Points on the flank (and as many over the rim) of the characteristic.
POINTS = 41
#: Residual torque above this share of the peak is flagged (the clutch keeps
#: dragging the load while it slips and heats up).
RESIDUAL_SHARE = 0.10
#: Static limit of σ_OM for the usual disc-spring steels (C60S, 51CrV4) in
#: DIN EN 16983: about their yield strength R_e ≈ 1400…1600 MPa.
DISC_YIELD_DEFAULT = 1400e6

SPRING_TYPES = ("helical", "disc")
MATERIAL_CHOICES = ("custom", *sp.MATERIALS)
CORRECTION_CHOICES = ("wahl", "bergstrasser")
SEATINGS = tuple(sp.SEATING_COEFFICIENTS)


def params() -> tuple[Param, ...]:
    """The as-built inputs, shared by both clutch models."""
    return (
        length(
            "ball_lift",
            "h, rise of the ball (and of the pressure disk) along the flank from seated to "
            "the groove's rim; the ball then rolls over the rim, rising (d/2)(1 − sin α) "
            "more. Absent: the paper's groove depth, equal to the spring deflection Δ",
            minimum=0.0,
            maximum=0.2,
            symbol="h",
            group="balls",
        ),
        Param(
            "driving_groove_angle",
            "rad",
            "α′, flank angle of the driving half-coupling's groove [001, fig. 6]; absent: the "
            "driving half pushes the ball circumferentially, as eq. 1 assumes. Given, "
            "flank_construction says how the two flanks push: a free ball rides the flatter "
            "flank, F_a/F_t = max(tan(α′ − ρ), tan(α − ρ)); under a pressure disc it climbs "
            "both, F_a/F_t = tan(α′ − ρ) + tan(α − ρ)",
            minimum=0.0,
            maximum=math.pi / 2,
            exclusive_maximum=True,
            display_unit="deg",
            symbol="α′",
            group="balls",
        ),
        Param(
            "flank_construction",
            "1",
            "with driving_groove_angle: 'free_ball', a free ball between the grooved driving "
            "half and the spring-loaded grooved half, riding the flank that separates them "
            "least, F_a/F_t = max(tan(α′ − ρ), tan(α − ρ)) (never under-reports the slip "
            "torque); 'pressure_disc', axially fixed halves whose flanks both lift the ball "
            "and a separate pressure disc, F_a/F_t = tan(α′ − ρ) + tan(α − ρ) (virtual work)",
            default="free_ball",
            kind="choice",
            choices=CONSTRUCTIONS,
            group="balls",
        ),
        friction_coefficient(
            "face_friction",
            "μ_f, effective friction of the balls riding on the end face once disengaged "
            "(≈ 0.002 free rolling … 0.1 sliding); gives the residual torque",
            symbol="μ_f",
            group="balls",
        ),
        Param(
            "spring_type",
            "1",
            "'helical' (the paper's spring, [001, eq. 2]) or 'disc' (a stack of disc "
            "springs to DIN EN 16983)",
            default="helical",
            kind="choice",
            choices=SPRING_TYPES,
            group="spring",
        ),
        Param(
            "spring_material",
            "1",
            "helical spring wire: 'custom' (give shear_modulus and allowable_shear_stress) or "
            "EN 10270-1 SH/DH, 1.4310 (EN 10270-3): G and the permissible τ = 0.5 R_m(d) "
            "from the tables",
            default="custom",
            kind="choice",
            choices=MATERIAL_CHOICES,
            group="spring",
        ),
        positive(
            "spring_elastic_modulus",
            "Pa",
            "E of a custom helical spring's wire, used only for its buckling (EN 13906-1); "
            "absent: E = 2 G (1 + ν) with ν = 0.3, i.e. 2.6 G (208 GPa at G = 80 GPa; "
            "EN 13906-1 gives 206 GPa for spring steel, 185 GPa for 1.4310). Must lie within "
            "2 G … 3 G (Poisson's ratio 0…0.5). A chosen spring_material's E overrides it",
            maximum=1.5e12,
            display_unit="MPa",
            symbol="E",
            group="spring",
        ),
        Param(
            "stress_correction",
            "1",
            "stress-correction factor of the helical spring: Wahl or Bergsträsser (EN 13906-1)",
            default="wahl",
            kind="choice",
            choices=CORRECTION_CHOICES,
            group="spring",
        ),
        length(
            "spring_free_length",
            "L0, free length of the helical spring; given, the solid length with its minimum "
            "gap S_a and buckling are checked (EN 13906-1)",
            minimum=1e-4,
            maximum=2.0,
            symbol="L0",
            group="spring",
        ),
        Param(
            "spring_seating",
            "1",
            "end seating of the helical spring for buckling: fixed_fixed (ν = 0.5, parallel "
            "ground ends on nut and disk), fixed_hinged (0.7), hinged_hinged (1), "
            "fixed_free (2)",
            default="fixed_fixed",
            kind="choice",
            choices=SEATINGS,
            group="spring",
        ),
        length(
            "disc_outer_diameter",
            "De, outer diameter of the disc springs",
            minimum=1e-3,
            maximum=1.0,
            symbol="De",
            group="disc spring",
        ),
        length(
            "disc_inner_diameter",
            "Di, inner diameter of the disc springs",
            minimum=1e-4,
            maximum=1.0,
            symbol="Di",
            group="disc spring",
        ),
        length(
            "disc_thickness",
            "t, thickness of one disc",
            minimum=1e-5,
            maximum=0.1,
            symbol="t",
            group="disc spring",
        ),
        length(
            "disc_cone_height",
            "h0, free cone height of one disc (free height t + h0); h0/t > √2 gives a "
            "falling force",
            minimum=1e-6,
            maximum=0.1,
            symbol="h0",
            group="disc spring",
        ),
        count(
            "disc_series",
            "number of discs (or packs) in series, alternately facing; the stack deflection "
            "is this times one disc's",
            minimum=1,
            maximum=200,
            default=1,
            group="disc spring",
        ),
        count(
            "disc_parallel",
            "number of discs nested in parallel in each pack; the force is this times one disc's",
            minimum=1,
            maximum=20,
            default=1,
            group="disc spring",
        ),
        friction_coefficient(
            "disc_friction",
            "w_M, friction factor between nested discs (0.02…0.03 lubricated), DIN EN 16983; "
            "raises the force while the balls climb",
            default=0.0,
            maximum=0.2,
            group="disc spring",
        ),
        positive(
            "disc_elastic_modulus",
            "Pa",
            "E of the disc spring steel",
            maximum=5e11,
            default=206e9,
            display_unit="MPa",
            group="disc spring",
        ),
        positive(
            "disc_yield_strength",
            "Pa",
            "static limit of σ_OM (the disc's yield strength, 1400…1600 MPa for C60S, "
            "51CrV4), DIN EN 16983",
            maximum=5e9,
            default=DISC_YIELD_DEFAULT,
            display_unit="MPa",
            group="disc spring",
        ),
    )


def outputs() -> tuple[Output, ...]:
    """The as-built outputs of clutch.ball (scalars and the lift characteristic)."""
    return (
        Output(
            "peak_torque",
            "N*m",
            "largest torque over the lift from seated to riding on the face: the clutch "
            "disengages above it (= torque_limit at zero lift)",
            display_unit="N*m",
            symbol="T_max",
            step="[001, eq. 1–3]",
        ),
        Output(
            "lift_at_peak",
            "m",
            "lift at the peak torque",
            display_unit="mm",
            symbol="z_peak",
            step="[001, eq. 1–3]",
        ),
        Output(
            "torque_at_rim",
            "N*m",
            "torque when the balls reach the rim (end of the flank); below peak_torque when "
            "the spring force falls (disc springs past their maximum)",
            display_unit="N*m",
            symbol="T_rim",
            step="[001, eq. 1–3]",
        ),
        Output(
            "residual_torque",
            "N*m",
            "torque while the balls ride on the face, n μ_f F D0/2; null without face_friction",
            display_unit="N*m",
            symbol="T_R",
            step="[001, eq. 1–3]",
        ),
        Output(
            "total_lift",
            "m",
            "lift from seated to riding on the face, h + (d/2)(1 − sin α)",
            display_unit="mm",
            symbol="s_h",
            step="[001, eq. 1–3]",
        ),
        Output(
            "spring_force_at_peak",
            "N",
            "spring force at the peak torque",
            symbol="F_peak",
            step="[001, eq. 2]",
        ),
        Output(
            "spring_stress_at_peak",
            "Pa",
            "spring stress at the peak torque: corrected wire shear τ_k (helical) or |σ_OM| (disc)",
            display_unit="MPa",
            symbol="τ_k,peak",
            step="EN 13906-1",
        ),
        Output(
            "spring_force_max",
            "N",
            "largest spring force over the lift",
            symbol="F_max",
            step="[001, eq. 2]",
        ),
        Output(
            "spring_stress_max",
            "Pa",
            "largest spring stress over the lift (every slip cycles the spring to it)",
            display_unit="MPa",
            symbol="τ_k,max",
            step="EN 13906-1",
        ),
        Output(
            "permissible_stress",
            "Pa",
            "permissible spring stress: allowable_shear_stress, 0.5 R_m(d) of the wire "
            "material (EN 13906-1), or the disc's yield strength for σ_OM",
            display_unit="MPa",
            symbol="τ_zul",
            step="EN 13906-1",
        ),
        Output(
            "tensile_strength",
            "Pa",
            "R_m(d) of the helical wire material",
            display_unit="MPa",
            symbol="R_m",
            step="EN 10270-1",
        ),
        Output(
            "self_locking_margin",
            "rad",
            "α − atan f (the smaller over the two flanks); the limit explodes as it → 0",
            display_unit="deg",
            symbol="α − ρ",
            step="[001, eq. 1]",
        ),
        Output(
            "friction_sensitivity",
            "N*m",
            "dT/df, change of the torque limit per unit flank friction",
            display_unit="N*m",
            symbol="dT/df",
            step="[001, eq. 3]",
        ),
        Output(
            "solid_length",
            "m",
            "L_c of the helical spring (EN 13906-1)",
            display_unit="mm",
            symbol="L_c",
            step="EN 13906-1",
        ),
        Output(
            "buckling_deflection",
            "m",
            "s_K, deflection at which the free helical spring buckles (EN 13906-1); null: it "
            "cannot buckle",
            display_unit="mm",
            symbol="s_K",
            step="EN 13906-1",
        ),
        Output(
            "natural_frequency",
            "Hz",
            "first surge frequency of the helical spring (EN 13906-1)",
            symbol="f_e",
            step="EN 13906-1",
        ),
        Output(
            "disc_force_flat",
            "N",
            "force of the disc stack pressed flat (DIN EN 16983 closed form)",
            symbol="F_c",
            step="EN 16983",
        ),
        Output(
            "flank_lift",
            "m",
            "h, lift at which the balls reach the rim (ball_lift, or Δ as in the paper)",
            display_unit="mm",
            symbol="h",
            step="[001, eq. 2]",
        ),
        Output(
            "lift",
            "m",
            "lift of the balls (x-axis of the characteristic)",
            series=True,
            display_unit="mm",
            plot=Plot(windows=(Window("over the rim", "flank_lift", "total_lift"),)),
        ),
        Output(
            "torque_curve",
            "N*m",
            "torque against lift, seated to riding on the face",
            series=True,
            x="lift",
        ),
        Output(
            "spring_force_curve",
            "N",
            "spring force against lift",
            series=True,
            x="lift",
        ),
        Output(
            "spring_stress_curve",
            "Pa",
            "spring stress against lift",
            series=True,
            x="lift",
            display_unit="MPa",
        ),
    )


# --------------------------------------------------------------------------
# The spring: force and stress against its total deflection
# --------------------------------------------------------------------------


class Spring:
    """Force and stress of the clutch spring against its total deflection [m]."""

    def __init__(self, x: Mapping[str, Any]) -> None:
        self.kind = x["spring_type"]
        self.x = x
        if self.kind == "helical":
            material = x["spring_material"]
            self.material = None if material == "custom" else sp.MATERIALS[material]
            self.shear_modulus = (
                x["shear_modulus"] if self.material is None else self.material.shear_modulus
            )
            self.elastic_modulus = elastic_modulus(x, self.material)
        else:
            self.material = None
            self.shear_modulus = x["shear_modulus"]
            self.elastic_modulus = x["disc_elastic_modulus"]
        self._disc: sp.DiscLaw | None = None

    def disc_law(self) -> sp.DiscLaw:
        """One disc's :func:`springs.disc_law`, computed at the first force or rate."""
        if self._disc is None:
            self._disc = sp.disc_law(*self.disc_geometry())
        return self._disc

    def force(self, deflection: Any) -> Any:
        x = self.x
        if self.kind == "helical":
            rate = sp.helical_rate(
                self.shear_modulus,
                x["spring_wire_diameter"],
                x["spring_mean_diameter"],
                x["spring_active_coils"],
            )
            return np.asarray(rate) * np.asarray(deflection)
        single = sp.disc_force_of(self.disc_law(), np.asarray(deflection) / x["disc_series"])
        return sp.stack_force(single, x["disc_parallel"], x["disc_friction"])

    def disc_geometry(self) -> tuple[Any, ...]:
        """One disc's geometry and modulus, in the order the disc functions take them."""
        x = self.x
        return (
            x["disc_outer_diameter"],
            x["disc_inner_diameter"],
            x["disc_thickness"],
            x["disc_cone_height"],
            x["disc_elastic_modulus"],
        )

    def rate(self, deflection: Any) -> Any:
        """dF/d(deflection): the helical rate, or the stack's (the disc's rate at the
        per-disc deflection over the discs in series, through the stack's parallel
        discs and friction as its force)."""
        x = self.x
        if self.kind == "helical":
            return np.asarray(self.force(1.0)) * np.ones(np.shape(deflection))
        single = sp.disc_rate_of(self.disc_law(), np.asarray(deflection) / x["disc_series"])
        return sp.stack_force(
            np.asarray(single) / x["disc_series"], x["disc_parallel"], x["disc_friction"]
        )

    def stress(self, deflection: Any) -> Any:
        x = self.x
        if self.kind == "helical":
            return sp.helical_shear_stress(
                self.force(deflection),
                x["spring_mean_diameter"],
                x["spring_wire_diameter"],
                x["stress_correction"],
            )
        om = sp.disc_stress_om(np.asarray(deflection) / x["disc_series"], *self.disc_geometry())
        return np.abs(om)

    def permissible(self) -> Any:
        """Permissible stress [Pa] (an array when the swept input is), or None."""
        x = self.x
        if self.kind == "disc":
            return x["disc_yield_strength"]
        if self.material is not None:
            # a varied wire: NaN outside the table (refused there); one wire: refused
            return sp.permissible_shear_stress(self.material.name, x["spring_wire_diameter"])
        return x["allowable_shear_stress"]


#: Poisson's ratio of a custom wire when its E is not given (steels 0.27…0.30).
CUSTOM_POISSON = 0.3
#: E/G a custom wire may have: 2 (1 + ν) for ν from 0 to 0.5.
ELASTIC_SHEAR_RATIO = (2.0, 3.0)


def elastic_modulus(x: Mapping[str, Any], material: sp.SpringMaterial | None) -> Any:
    r"""E of the helical spring's wire: the material's, the given one, or 2 G (1 + ν).

    .. math::
        E = 2 G (1 + \nu), \quad \nu = 0.3 \;\text{(custom wire, E not given)}

    EN 13906-1 tabulates E and G of its spring materials (206 and 81.5 GPa for
    patented spring steel, 185 and 70 GPa for 1.4310); for a custom wire whose E is
    not given the isotropic relation with the steels' Poisson's ratio stands in.
    """
    if material is not None:
        return material.elastic_modulus
    if x["spring_elastic_modulus"] is not None:
        return x["spring_elastic_modulus"]
    return 2.0 * (1.0 + CUSTOM_POISSON) * np.asarray(x["shear_modulus"])


def refused(x: Mapping[str, Any]) -> dict[str, Any]:
    """Where the spring's numbers are refused, by the field named: True there (floats or
    arrays). A missing input is refused by :func:`require_spring` alone (it is the same
    at every point of a study)."""
    if x["spring_type"] == "disc":
        if x["disc_inner_diameter"] is None or x["disc_outer_diameter"] is None:
            return {}
        # a ring that narrow is not a disc spring (Almen–László loses all precision)
        return {"disc_inner_diameter": x["disc_inner_diameter"] * 1.05 >= x["disc_outer_diameter"]}
    out: dict[str, Any] = {}
    if x["spring_material"] == "custom" and x["spring_elastic_modulus"] is not None:
        ratio = np.asarray(x["spring_elastic_modulus"]) / np.asarray(x["shear_modulus"])
        lo, hi = ELASTIC_SHEAR_RATIO
        out["spring_elastic_modulus"] = (ratio < lo) | (ratio > hi)
    wire = x["spring_wire_diameter"]
    if wire is None or x["spring_material"] == "custom" or np.ndim(wire) == 0:
        return out  # one wire: tensile_strength refuses it with the table's range
    out["spring_wire_diameter_table"] = np.isnan(sp.tensile_strength(x["spring_material"], wire))
    return out


def require_spring(x: Mapping[str, Any], *, wire_needed: bool) -> None:
    """Refuse a spring description that is incomplete or impossible (scalar inputs)."""
    if x["spring_type"] == "disc":
        for name in ("disc_outer_diameter", "disc_inner_diameter", "disc_thickness"):
            if x[name] is None:
                raise InputOutOfRange(f"spring_type = disc needs {name}", field=name)
        if x["disc_cone_height"] is None:
            raise InputOutOfRange(
                "spring_type = disc needs disc_cone_height", field="disc_cone_height"
            )
        if refused(x)["disc_inner_diameter"]:
            raise InputOutOfRange(
                f"disc_inner_diameter = {x['disc_inner_diameter'] * 1e3:g} mm is not below "
                f"disc_outer_diameter / 1.05 = {x['disc_outer_diameter'] / 1.05 * 1e3:.4g} mm: "
                "a ring that narrow is not a disc spring (Almen–László loses all precision)",
                field="disc_inner_diameter",
            )
        return
    for name in ("spring_mean_diameter", "spring_active_coils"):
        if x[name] is None:
            raise InputOutOfRange(f"a helical spring needs {name}", field=name)
    if wire_needed and x["spring_wire_diameter"] is None:
        raise InputOutOfRange(
            "a helical spring needs spring_wire_diameter", field="spring_wire_diameter"
        )
    wire, material = x["spring_wire_diameter"], x["spring_material"]
    if wire is not None and material != "custom":
        sp.tensile_strength(material, wire)  # refuses a wire outside the material's table
    if refused(x).get("spring_elastic_modulus", False):
        lo, hi = ELASTIC_SHEAR_RATIO
        g = x["shear_modulus"]
        raise InputOutOfRange(
            f"spring_elastic_modulus = {x['spring_elastic_modulus'] / 1e6:.6g} MPa is outside "
            f"{lo:g} G … {hi:g} G = {lo * g / 1e6:.6g} … {hi * g / 1e6:.6g} MPa for "
            f"shear_modulus G = {g / 1e6:.6g} MPa (E = 2 G (1 + ν), Poisson's ratio ν 0…0.5)",
            field="spring_elastic_modulus",
        )


# --------------------------------------------------------------------------
# The characteristic, broadcast over a swept input
# --------------------------------------------------------------------------


def _flank_torque(
    x: Mapping[str, Any], force: Any, beta: Any, shape: Mapping[str, Any] | None = None
) -> Any:
    """:func:`torque_against_lift` of ``force`` at flank angles ``beta`` with the clutch's
    ball circle, flank friction, groove angle, torque sharing and flank construction
    (``shape``: ``x``'s inputs reshaped for a trailing axis, read in its place)."""
    s = x if shape is None else shape
    return torque_against_lift(
        force,
        beta,
        s["ball_circle_diameter"],
        s["flank_friction"],
        s["driving_groove_angle"],
        _sharing(s),
        x["flank_construction"],
    )


def _sharing(x: Mapping[str, Any]) -> Any:
    return torque_sharing(x["spring_arrangement"], x["ball_count"], x["load_factor"])


def _gain_at(x: Mapping[str, Any], beta: Any) -> np.ndarray:
    """The torque per newton of spring force at the flank angles ``beta`` (one row of lift
    points per design: the designs' arrays in ``x`` broadcast against the last axis)
    [torque_against_lift with unit force]."""
    xs = {k: (v[..., None] if isinstance(v, np.ndarray) else v) for k, v in x.items()}
    return np.asarray(_flank_torque(x, 1.0, beta, shape=xs))


def _ride(x: Mapping[str, Any]) -> Any:
    """The flank (and rim) the ball climbs: :func:`riding_flank_angle`."""
    return riding_flank_angle(x["groove_angle"], x["driving_groove_angle"], x["flank_construction"])


def lift_of(x: Mapping[str, Any], deflection: Any = None) -> Any:
    """The flank lift h: ``ball_lift`` or, absent, the paper's Δ."""
    if x["ball_lift"] is not None:
        return x["ball_lift"]
    return x["spring_deflection"] if deflection is None else deflection


def characteristic(
    x: Mapping[str, Any],
    spring: Spring,
    deflection: Any = None,
    curves: bool = False,
    points: int = POINTS,
    peak_only: bool = False,
) -> dict[str, Any]:
    """Torque, spring force and stress against lift; arrays with the lift on the last axis.

    The curves themselves (keys ``_lift``, ``_torque``, ``_force``, ``_stress``) only with
    ``curves=True``; only ``peak_torque`` and ``peak_slope`` with ``peak_only=True`` (a
    root search's function, the same floats, and its derivative in the setting,
    :func:`peak_slope`). ``points`` on the flank and as many over the
    rim (the outputs take :data:`POINTS`; the error estimate a finer grid). A helical
    spring's stress is evaluated only where it is read (at the
    peak torque and at the largest force, where it is largest: it is proportional to the
    force), the same floats the whole curve would hold there.
    """
    flat_spring, given = spring, x
    preload = np.asarray(x["spring_deflection"] if deflection is None else deflection, float)
    if spring.kind == "helical" and not curves and np.all(peak_at_rim(x, deflection=deflection)):
        at_rim = _rim_peak(x, spring, preload, lift_of(x, deflection))
        if peak_only:  # the rim point z = h (h = Δ when ball_lift is absent)
            moves = 0.0 if x["ball_lift"] is not None else 1.0
            compressed = preload + np.asarray(lift_of(x, deflection), float)
            return {
                "peak_torque": at_rim["peak_torque"],
                "peak_slope": peak_slope(x, spring, compressed, _ride(x), moves),
            }
        return at_rim
    # A helical spring's force rises with the lift and the flank's push is constant, so
    # on the flank the torque rises to the rim: the grid's peak and maxima lie from the
    # rim on. Without the curves, only those points are evaluated (the same floats).
    first = points - 1 if spring.kind == "helical" and not curves else 0
    lift, beta = lift_points(
        lift_of(x, deflection), x["ball_diameter"], _ride(x), points, first > 0
    )
    # a swept input (an array) gets a trailing axis so it broadcasts against the lift
    x = {k: (val[..., None] if isinstance(val, np.ndarray) else val) for k, val in x.items()}
    spring = Spring(x)
    total = preload[..., None] + lift
    force = spring.force(total)
    helical = spring.kind == "helical"
    stress: Any = None if (helical and not curves) or peak_only else spring.stress(total)
    # x's arrays already carry the trailing (lift) axis
    torque = np.asarray(_flank_torque(x, force, beta))
    peak = np.argmax(torque, axis=-1)[..., None]

    if torque.ndim == 1:  # a single design: plain indexing, the same floats

        def at(arr: Any, idx: Any) -> Any:
            arr = np.asarray(arr)
            if arr.shape != torque.shape:
                arr = np.broadcast_to(arr, torque.shape)
            return np.asarray(arr[idx[0]])

    else:

        def at(arr: Any, idx: Any) -> Any:
            return np.take_along_axis(np.broadcast_to(arr, torque.shape), idx, axis=-1)[..., 0]

    if peak_only:
        # dz_k/dΔ: 0 where the lift points stay put, the unit flank's lifts where they
        # follow the setting (z = u h on the flank, h + rim rise over it, h = Δ)
        follows: Any = (
            0.0
            if given["ball_lift"] is not None
            else lift_points(1.0, 0.0, 0.0, points, first > 0)[0]
        )
        return {
            "peak_torque": at(torque, peak),
            "peak_slope": peak_slope(
                given, flat_spring, at(total, peak), at(beta, peak), at(follows, peak)
            ),
        }
    rim = np.full_like(peak, points - 1 - first)
    forces = np.broadcast_to(force, torque.shape)
    out: dict[str, Any] = {
        "peak_torque": at(torque, peak),
        "lift_at_peak": at(lift, peak),
        "torque_at_rim": at(torque, rim),
        "total_lift": lift[..., -1],
        "flank_lift": lift[..., points - 1 - first],
        "spring_force_at_peak": at(force, peak),
        "spring_force_max": np.max(forces, axis=-1),
    }
    if helical:
        top = np.argmax(forces, axis=-1)[..., None]
        out["spring_stress_at_peak"] = flat_spring.stress(at(total, peak))
        out["spring_stress_max"] = flat_spring.stress(at(total, top))
    else:
        out["spring_stress_at_peak"] = at(stress, peak)
        out["spring_stress_max"] = np.max(np.broadcast_to(stress, torque.shape), axis=-1)
    if curves:
        out["_lift"] = lift
        out["_torque"] = torque
        out["_force"] = forces
        out["_stress"] = np.broadcast_to(stress, torque.shape)
    if x["face_friction"] is not None:
        springs = x["ball_count"] if x["spring_arrangement"] == "per_ball" else 1.0
        residual = residual_torque(
            np.broadcast_to(force, torque.shape)[..., -1:],
            x["ball_circle_diameter"],
            x["face_friction"],
            springs,
        )
        out["residual_torque"] = np.asarray(residual)[..., 0]
    return out


def peak_slope(x: Mapping[str, Any], spring: Spring, total: Any, beta: Any, follows: Any) -> Any:
    r"""dT_k/dΔ of the lift point k holding the peak: the derivative of the root
    searches' function (:func:`setting_roots`), for Newton's steps.

    .. math::
        \frac{dT_k}{d\Delta} = \left(1 + \frac{dz_k}{d\Delta}\right)
        \frac{s D_0}{2 p(\beta_k)} \frac{dF}{ds}\Big|_{\Delta + z_k}

    T_k = s D0 F(Δ + z_k)/(2 p(β_k)) is linear in the force, so its derivative is
    :func:`torque_against_lift` of the spring's rate (:meth:`Spring.rate`) at the
    compression ``total`` = Δ + z_k, at the contact angle ``beta`` = β_k; ``follows``
    is dz_k/dΔ (0 where the lift points stay put, ``ball_lift`` given). [001, eq. 1–3]
    with EN 16983's rate.

    A helical spring on the paper's 45° flanks without friction (p = 1), 4 balls on a
    50 mm circle sharing one spring: the slope is D0/2 times the rate, twice that
    where the lift follows the setting:

    >>> from engine.models.clutch import BALL_CLUTCH
    >>> x, _ = BALL_CLUTCH.validate({**BALL_CLUTCH.examples[0], "spring_deflection": 0.004})
    >>> spring = Spring(x)
    >>> rate = float(spring.force(1.0))  # F = c s
    >>> round(float(peak_slope(x, spring, 0.005, math.pi / 4, 0.0) / (0.025 * rate)), 12)
    1.0
    >>> round(float(peak_slope(x, spring, 0.005, math.pi / 4, 1.0) / (0.05 * rate)), 12)
    1.0
    """
    push = _flank_torque(x, spring.rate(total), beta)
    return np.asarray((1.0 + np.asarray(follows)) * np.asarray(push))


def peak_at_rim(
    x: Mapping[str, Any], friction: Any = None, deflection: Any = None, push: Any = None
) -> Any:
    """True where a helical spring's characteristic peaks where the ball reaches the rim.

    :func:`rim_torque_slope` ≤ 0 there, with every sliding flank steeper than the
    friction angle (:func:`margin` > 0): the torque rises along the flank and falls
    from the rim on, on any grid of the lift (each has the rim as a point).
    ``friction`` replaces the flank friction (an array of several broadcasts against
    the inputs' arrays), ``push`` its :func:`combined_push_factor` if known. A disc
    spring: False.
    """
    if x["spring_type"] != "helical":
        return np.asarray(False)
    f = x["flank_friction"] if friction is None else friction
    at_rim = np.asarray(
        x["spring_deflection"] if deflection is None else deflection, float
    ) + np.asarray(lift_of(x, deflection), float)
    ride, driving, construction = _ride(x), x["driving_groove_angle"], x["flank_construction"]
    if push is None:
        push = combined_push_factor(ride, f, driving, construction)
    with np.errstate(divide="ignore", invalid="ignore"):
        slope = np.asarray(rim_torque_slope(at_rim, x["ball_diameter"], ride, f, push), float)
    return (slope <= 0.0) & (margin({**x, "flank_friction": f}) > 0.0)


def _rim_peak(x: Mapping[str, Any], spring: Spring, preload: Any, h: Any) -> dict[str, Any]:
    """:func:`characteristic`'s values where its peak is at the rim (:func:`peak_at_rim`).

    The torque at z = h, and the force and stress at the end for the maxima: the floats
    the grid would give at those points, without the grid.
    """
    h = np.asarray(h, float)
    lift = 1.0 * h
    total = preload + lift
    force = spring.force(total)
    torque = np.asarray(_flank_torque(x, force, np.asarray(_ride(x), float)))
    shape = np.broadcast_shapes(torque.shape, np.shape(preload))

    def full(value: Any) -> Any:
        value = np.asarray(value, dtype=float)
        return value if value.shape == shape else np.array(np.broadcast_to(value, shape))

    end = end_values({**x, "spring_deflection": preload}, spring)
    out: dict[str, Any] = {
        "peak_torque": full(torque),
        "lift_at_peak": full(lift),
        "torque_at_rim": full(torque),
        "total_lift": full(end["total_lift"]),
        "flank_lift": full(lift),
        "spring_force_at_peak": full(force),
        "spring_force_max": full(end["spring_force_max"]),
        "spring_stress_at_peak": full(spring.stress(total)),
        "spring_stress_max": full(end["spring_stress_max"]),
    }
    if "residual_torque" in end:
        out["residual_torque"] = full(end["residual_torque"])
    return out


#: Points per branch of the finer characteristic the peak's error estimate compares with.
FINE_POINTS = 401


def peak_friction_shift(x: Mapping[str, Any], low: Any, high: Any) -> Any:
    r"""Largest relative shift of the peak torque over flank frictions in [low, high].

    .. math::
        e = \frac{\max(T^*(f_{hi}) - T(f), \; T(f) - T^*(f_{lo}))
            + \max_{f' \in \{f_{lo}, f, f_{hi}\}} |T^*(f') - T(f')|}{T(f)}

    T the peak on the output's grid (:data:`POINTS`), T* on a 10× finer one
    (:data:`FINE_POINTS`). The peak rises with the friction (every point's torque
    does), so the band's ends are its extremes; the grid's own error T* − T, where it is
    largest over the band (the peak may leave a grid point as the friction changes), is
    added once more for what the finer grid still misses (a quadratic grid error: 1 %
    of it). Floats or arrays, like :func:`characteristic`.
    """

    f = x["flank_friction"]

    def peaks(point: dict[str, Any]) -> tuple[Any, Any]:
        spring = Spring(point)
        coarse = characteristic(point, spring)["peak_torque"]
        fine = characteristic(point, spring, points=FINE_POINTS)["peak_torque"]
        return np.asarray(coarse, float), np.asarray(fine, float)

    if _arrays(x) or np.ndim(f) or np.ndim(low) or np.ndim(high):  # many designs
        (here, at), (up_c, up), (down_c, down) = (
            peaks({**x, "flank_friction": g}) for g in (f, high, low)
        )
    else:  # one design: its three frictions as three elements of one call of each grid
        coarse, fine = peaks({**x, "flank_friction": np.array([f, high, low], dtype=float)})
        (here, up_c, down_c), (at, up, down) = coarse, fine
    grid = np.maximum(np.abs(at - here), np.maximum(np.abs(up - up_c), np.abs(down - down_c)))
    return (np.maximum(up - here, here - down) + grid) / np.abs(here)


def _arrays(x: Mapping[str, Any]) -> list[np.ndarray]:
    """The inputs of ``x`` that are numpy arrays (one design per element)."""
    return [v for v in x.values() if isinstance(v, np.ndarray) and v.ndim]


#: Outputs only the whole characteristic gives (its peak); :func:`end_values` gives the rest.
PEAK_OUTPUTS = (
    "peak_torque",
    "lift_at_peak",
    "torque_at_rim",
    "spring_force_at_peak",
    "spring_stress_at_peak",
)


def end_values(x: Mapping[str, Any], spring: Spring) -> dict[str, Any]:
    """The characteristic's values at its ends, helical springs only (no 81-point grid).

    A helical spring's force and stress rise with its deflection and the lift rises
    along the grid, so their maxima are at the last point (riding on the face): the
    same floats :func:`characteristic` takes from its last column, for a study that
    asks for none of :data:`PEAK_OUTPUTS`.
    """
    h = np.asarray(lift_of(x), float)
    total_lift = h + rim_rise(x["ball_diameter"], _ride(x))
    total = np.asarray(x["spring_deflection"], float) + total_lift
    force = spring.force(total)
    out: dict[str, Any] = {
        "total_lift": total_lift,
        "flank_lift": 1.0 * h,
        "spring_force_max": force,
        "spring_stress_max": spring.stress(total),
    }
    if x["face_friction"] is not None:
        springs = x["ball_count"] if x["spring_arrangement"] == "per_ball" else 1.0
        out["residual_torque"] = residual_torque(
            force, x["ball_circle_diameter"], x["face_friction"], springs
        )
    return out


def margin(x: Mapping[str, Any]) -> Any:
    """Self-locking margin α − atan f over the flanks the ball slides on."""
    return np.asarray(
        self_locking_margin(
            x["groove_angle"],
            x["flank_friction"],
            x["driving_groove_angle"],
            x["flank_construction"],
        )
    )


def extra_values(
    x: Mapping[str, Any], spring: Spring, limit: Any, peak: bool = True
) -> dict[str, Any]:
    """Every as-built scalar of clutch.ball (arrays when inputs are arrays).

    ``peak=False`` (helical springs): all but :data:`PEAK_OUTPUTS`, without the
    81-point characteristic (:func:`end_values`).
    """
    if peak or spring.kind != "helical":
        c = characteristic(x, spring)
        values = {k: v for k, v in c.items() if not k.startswith("_")}
    else:
        values = end_values(x, spring)
    values["self_locking_margin"] = margin(x)
    values["friction_sensitivity"] = friction_sensitivity(
        limit,
        x["groove_angle"],
        x["flank_friction"],
        x["driving_groove_angle"],
        x["flank_construction"],
    )
    if spring.kind == "helical":
        d, dm, n = x["spring_wire_diameter"], x["spring_mean_diameter"], x["spring_active_coils"]
        values["solid_length"] = sp.solid_length(d, n)
        if spring.material is not None:
            values["natural_frequency"] = sp.helical_natural_frequency(
                d, dm, n, spring.shear_modulus, spring.material.density
            )
            values["tensile_strength"] = sp.tensile_strength(spring.material.name, d)
        scalar = all(
            np.ndim(a) == 0 for a in (x["spring_free_length"], dm, values["spring_force_max"])
        )
        if x["spring_free_length"] is not None:
            s_k = sp.buckling_deflection(
                x["spring_free_length"],
                dm,
                sp.SEATING_COEFFICIENTS[x["spring_seating"]],
                spring.shear_modulus,
                spring.elastic_modulus,
            )
            # inf: the spring cannot buckle; said as null (and in the check), never inf;
            # on arrays NaN there (null in a sweep, as the loop gives it)
            if scalar:
                values["buckling_deflection"] = None if math.isinf(float(s_k)) else s_k
            else:
                values["buckling_deflection"] = np.where(np.isinf(s_k), np.nan, s_k)
    else:
        single = sp.disc_force_flat(*spring.disc_geometry())
        values["disc_force_flat"] = single * x["disc_parallel"]
    allow = spring.permissible()
    if allow is not None:
        values["permissible_stress"] = allow
    return values


def series(x: Mapping[str, Any], spring: Spring) -> dict[str, list[float]]:
    """The characteristic as series for the form's plot (scalar inputs only)."""
    c = characteristic(x, spring, curves=True)
    return {
        "lift": np.asarray(c["_lift"]).ravel().tolist(),
        "torque_curve": np.asarray(c["_torque"]).ravel().tolist(),
        "spring_force_curve": np.asarray(c["_force"]).ravel().tolist(),
        "spring_stress_curve": np.asarray(c["_stress"]).ravel().tolist(),
    }


# --------------------------------------------------------------------------
# Checks and notes (scalar inputs)
# --------------------------------------------------------------------------


def verdicts_read_values(x: Mapping[str, Any], spring: Spring) -> bool:
    """Whether :func:`verdicts` reads an as-built value besides the self-locking margin:
    the largest stress (a permissible stress known), the travel (a disc stack, a free
    length given) or the residual torque (a face friction given)."""
    return (
        spring.kind == "disc"
        or x["spring_free_length"] is not None
        or x["face_friction"] is not None
        or spring.permissible() is not None
    )


def verdicts(x: Mapping[str, Any], spring: Spring, v: Mapping[str, Any]) -> dict[str, Any]:
    """The as-built checks' verdicts on floats or arrays: True where a check passes.

    The one place they compare numbers: :func:`checks` words them for a single run,
    the array path reports them per point.
    """
    out: dict[str, Any] = {"self_locking": v["self_locking_margin"] >= SELF_LOCKING_MARGIN}
    allow = spring.permissible()
    if allow is not None:
        out["spring_stress_max"] = v["spring_stress_max"] <= allow
    if spring.kind == "disc":
        travel = x["spring_deflection"] + v["total_lift"]
        m = x["disc_series"]
        out["disc_not_past_flat"] = travel / m <= x["disc_cone_height"]
        s_max = sp.disc_falling_region(x["disc_thickness"], x["disc_cone_height"])[0]
        # NaN (no force maximum) compares False: the torque never falls
        out["falling_curve"] = x["spring_deflection"] / m + v["total_lift"] / m > s_max
    elif x["spring_free_length"] is not None:
        travel = x["spring_deflection"] + v["total_lift"]
        d, dm, n = x["spring_wire_diameter"], x["spring_mean_diameter"], x["spring_active_coils"]
        need = sp.solid_length(d, n) + sp.minimum_gap_sum(d, dm, n)
        out["solid_length"] = x["spring_free_length"] - travel >= need
        # a spring that cannot buckle has no buckling deflection (None, or NaN on arrays)
        s_k = v.get("buckling_deflection")
        out["buckling"] = True if s_k is None else travel < np.where(np.isnan(s_k), np.inf, s_k)
    if x["face_friction"] is not None:
        out["residual_torque"] = v["residual_torque"] <= RESIDUAL_SHARE * v["peak_torque"]
    return out


def checks(
    x: Mapping[str, Any], spring: Spring, v: Mapping[str, Any], passed: Mapping[str, bool]
) -> list[Check]:
    """The as-built checks of one scalar run, worded on the verdicts of :func:`verdicts`."""
    out: list[Check] = []
    m = float(v["self_locking_margin"])
    ok = passed["self_locking"]
    angle = "α"  # the flank the ball slides on (self_locking_margin)
    if x["driving_groove_angle"] is not None:
        angle = "max(α, α′)" if x["flank_construction"] == "free_ball" else "min(α, α′)"
    out.append(
        Check(
            "self_locking",
            ok,
            f"{angle} − atan f = {q(m, 'deg')} "
            + ("≥" if ok else "<")
            + f" {q(SELF_LOCKING_MARGIN, 'deg', fmt='g')}; "
            f"dT/df = {q(float(v['friction_sensitivity']), 'N*m', 4)}"
            + (
                ""
                if ok
                else ": near self-locking the limit follows the friction, not the spring "
                "(a change of f by 0.01 moves it by "
                f"{q(0.01 * float(v['friction_sensitivity']), 'N*m')}); use flatter flanks "
                "(larger α) or less flank friction"
            ),
        )
    )
    if "spring_stress_max" in passed:
        allow = float(spring.permissible())
        s = float(v["spring_stress_max"])
        ok = passed["spring_stress_max"]
        what = "wire shear stress τ_k" if spring.kind == "helical" else "disc stress |σ_OM|"
        out.append(
            Check(
                "spring_stress_max",
                ok,
                f"largest {what} over the lift {q(s, 'MPa', 4)} "
                + ("≤" if ok else ">")
                + f" permissible {q(allow, 'MPa', 4)} (at peak torque "
                + f"{q(float(v['spring_stress_at_peak']), 'MPa', 4)})"
                + (
                    ""
                    if ok
                    else ": every slip cycles the spring to it; use a stronger spring or less lift"
                ),
            )
        )
    if spring.kind == "disc":
        out += _disc_checks(x, v, passed)
    elif x["spring_free_length"] is not None:
        out += _helical_length_checks(x, v, passed)
    if x["face_friction"] is not None:
        res, peak = float(v["residual_torque"]), float(v["peak_torque"])
        ok = passed["residual_torque"]
        out.append(
            Check(
                "residual_torque",
                ok,
                f"residual torque on the face {q(res, 'N*m', 4)} "
                + ("≤" if ok else ">")
                + f" {RESIDUAL_SHARE:.0%} of the peak {q(peak, 'N*m', 4)}"
                + ("" if ok else ": the slipping clutch keeps dragging the load and heats up"),
            )
        )
    return out


def _disc_checks(
    x: Mapping[str, Any], v: Mapping[str, Any], passed: Mapping[str, bool]
) -> list[Check]:
    t, h0, m = x["disc_thickness"], x["disc_cone_height"], x["disc_series"]
    per_disc_max = (x["spring_deflection"] + float(v["total_lift"])) / m
    out = []
    ok = passed["disc_not_past_flat"]
    out.append(
        Check(
            "disc_not_past_flat",
            ok,
            f"largest deflection per disc {q(per_disc_max, 'mm', 4)} "
            + ("≤" if ok else ">")
            + f" cone height h0 = {q(h0, 'mm', 4)}"
            + (
                ""
                if ok
                else ": the discs would be pressed past flat; add discs in series or set less"
            ),
        )
    )
    s_max = float(sp.disc_falling_region(t, h0)[0])
    setting = x["spring_deflection"] / m
    ok = passed["falling_curve"]
    if math.isnan(s_max):
        detail = (
            f"h0/t = {h0 / t:.3g} ≤ √2: the disc force rises over the whole lift, so the "
            "torque does not drop after breakaway; use h0/t > √2 and set the stack past "
            "its force maximum"
        )
    elif ok:
        where = "at the setting" if setting >= s_max else "within the lift"
        detail = (
            f"the discs pass their force maximum (s = {q(s_max, 'mm', 4)} per disc) "
            f"{where}: the torque falls from {q(float(v['peak_torque']), 'N*m', 4, bare=True)} "
            f"to {q(float(v['torque_at_rim']), 'N*m', 4)} at the rim"
        )
    else:
        detail = (
            f"the discs never reach their force maximum (s = {q(s_max, 'mm', 4)} per "
            f"disc; setting {q(setting, 'mm', 4)}): the torque does not fall; set the "
            "stack further"
        )
    out.append(Check("falling_curve", ok, detail))
    return out


def _helical_length_checks(
    x: Mapping[str, Any], v: Mapping[str, Any], passed: Mapping[str, bool]
) -> list[Check]:
    d, dm, n = x["spring_wire_diameter"], x["spring_mean_diameter"], x["spring_active_coils"]
    l0 = x["spring_free_length"]
    travel = x["spring_deflection"] + float(v["total_lift"])
    shortest = l0 - travel
    need = float(sp.solid_length(d, n) + sp.minimum_gap_sum(d, dm, n))
    ok = passed["solid_length"]
    out = [
        Check(
            "solid_length",
            ok,
            f"shortest working length {q(shortest, 'mm', 4)} "
            + ("≥" if ok else "<")
            + f" solid length + minimum gaps L_c + S_a = {q(need, 'mm', 4)} (EN 13906-1)"
            + (
                ""
                if ok
                else ": the spring would go (nearly) solid; use a longer spring or less deflection"
            ),
        )
    ]
    s_k = v.get("buckling_deflection")
    s_k = float(s_k) if s_k is not None else math.inf
    ok = passed["buckling"]
    out.append(
        Check(
            "buckling",
            ok,
            (
                f"largest deflection {q(travel, 'mm', 4)} < buckling deflection "
                f"{q(s_k, 'mm', 4)} (seating {x['spring_seating']})"
                if math.isfinite(s_k)
                else f"the spring cannot buckle (seating {x['spring_seating']})"
            )
            if ok
            else f"largest deflection {q(travel, 'mm', 4)} ≥ buckling deflection "
            f"{q(s_k, 'mm', 4)}: "
            "guide the spring on a mandrel or in a sleeve, or use a shorter, fatter spring",
        )
    )
    return out


def warnings(x: Mapping[str, Any]) -> list[str]:
    """A non-standard wire size or disc proportion is a warning (it can be made, at a price)."""
    if x["spring_type"] == "disc":
        out = []
        delta = x["disc_outer_diameter"] / x["disc_inner_diameter"]
        slender = x["disc_outer_diameter"] / x["disc_thickness"]
        if not 1.75 <= delta <= 2.5:
            out.append(
                f"De/Di = {delta:.3g} is outside 1.75…2.5, the proportions of DIN EN 16983's "
                "series, for which the Almen–László relations were checked"
            )
        if not 16.0 <= slender <= 40.0:
            out.append(f"De/t = {slender:.3g} is outside DIN EN 16983's 16…40")
        return out
    wire = x["spring_wire_diameter"]
    if x["spring_type"] != "helical" or wire is None:
        return []
    near, ok = sp.nearest_standard_wire(wire)
    if ok:
        return []
    return [
        f"spring_wire_diameter = {q(wire, 'mm', 4)} is not a preferred size of EN 10270-1; "
        f"the nearest is {q(near, 'mm', fmt='g')}"
    ]


def notes(x: Mapping[str, Any], spring: Spring, v: Mapping[str, Any]) -> list[str]:
    """The as-built notes of one scalar run."""
    out = []
    if x["ball_lift"] is None:
        out.append(
            "ball_lift not given: the balls rise along the flank by the paper's groove depth, "
            f"equal to the spring deflection Δ = {q(x['spring_deflection'], 'mm', 4)} "
            "[001, eq. 2], then over the rim by (d/2)(1 − sin α) = "
            f"{q(float(v['total_lift']) - x['spring_deflection'], 'mm', 4)}"
        )
    out.append(
        f"torque against lift: {q(float(v['torque_at_rim']), 'N*m', 4)} when the balls reach "
        f"the rim, peak {q(float(v['peak_torque']), 'N*m', 4)} at lift "
        f"{q(float(v['lift_at_peak']), 'mm', 4)}; "
        f"the spring then carries {q(float(v['spring_force_at_peak']), 'N', 4)} "
        f"({q(float(v['spring_stress_at_peak']), 'MPa', 4)}), at most "
        f"{q(float(v['spring_force_max']), 'N', 4)} "
        f"({q(float(v['spring_stress_max']), 'MPa', 4)}) "
        "on the face. torque_limit is the zero-lift point [001, eq. 3]."
    )
    if x["driving_groove_angle"] is not None and x["flank_construction"] == "free_ball":
        a1, a2 = x["driving_groove_angle"] / DEG, x["groove_angle"] / DEG
        rides = "the driving" if a1 > a2 else "the driven"
        out.append(
            f"flank_construction = free_ball, α′ = {q(x['driving_groove_angle'], 'deg', 4)}, "
            f"α = {q(x['groove_angle'], 'deg', 4)}: the free ball "
            f"stays seated in the steeper groove and rides {rides} flank, the one that "
            "separates the halves least (virtual work): F_a/F_t = max(tan(α′ − ρ), "
            "tan(α − ρ)), and over that groove's rim. Were the balls lifting a separate "
            "pressure disc on both flanks at once (flank_construction = pressure_disc), "
            "the pushes would add and the same spring would slip at a lower torque."
        )
    elif x["driving_groove_angle"] is not None:
        out.append(
            "flank_construction = pressure_disc: the halves stay put and the ball climbs both "
            "flanks, lifting the disc: F_a/F_t = tan(α′ − ρ) + tan(α − ρ) (virtual work); "
            "equal angles halve the torque of eq. 1 for the same spring. Over the rim only "
            "the driven groove's rim is modelled. A free ball between a fixed and a "
            "spring-loaded grooved half (free_ball) would ride one flank: max, not the sum."
        )
    if spring.kind == "helical" and spring.material is not None:
        out.append(
            f"spring material {spring.material.standard}: "
            f"G = {q(spring.shear_modulus, 'GPa', fmt='g')} "
            f"(overrides shear_modulus), permissible τ = 0.5 R_m(d) (EN 13906-1), compared with "
            f"the {x['stress_correction']}-corrected stress, stricter than the standard's "
            "static check"
        )
    if spring.kind == "helical" and spring.material is None and x["spring_free_length"]:
        given = x["spring_elastic_modulus"] is not None
        out.append(
            f"custom wire: buckling with E = {q(float(spring.elastic_modulus), 'GPa', 4)} "
            + (
                "(spring_elastic_modulus)"
                if given
                else f"= 2 G (1 + ν), ν = {CUSTOM_POISSON:g}, not given (spring_elastic_modulus)"
            )
        )
    if spring.kind == "disc":
        out.append(
            f"disc springs (DIN EN 16983): {x['disc_series']} in series × {x['disc_parallel']} in "
            f"parallel, h0/t = {x['disc_cone_height'] / x['disc_thickness']:.3g}; "
            "spring_deflection "
            "is the stack's preload deflection; the helical-spring outputs are null"
        )
    if x["face_friction"] is None:
        out.append("give face_friction for the residual torque while the balls ride on the face")
    return out


def newton_roots(
    f: Callable[[Any, Any], tuple[Any, Any]],
    a: Any,
    b: Any,
    fa: Any,
    fb: Any,
    xtol: float,
    rtol: float,
    maxiter: int = 100,
) -> Any:
    r"""Roots of ``f`` in the brackets [a, b], many at once: Newton's method kept inside
    the bracket, lane by lane (a numerical method, not an equation of the model: each step
    is x_{n+1} = x_n − f(x_n)/f'(x_n)).

    ``f(x, lanes)`` gives (value, derivative) of the lanes ``lanes`` (an index array) at
    ``x``; ``fa`` < 0 ≤ ``fb`` are the values at ``a`` < ``b`` (a rising crossing). The
    first point interpolates linearly between the ends; each step narrows the bracket
    to the side of the root and takes Newton's step, or bisects where that step leaves
    the bracket or is not half the step before last (Numerical Recipes' ``rtsafe``).
    A lane stops where the step it takes is shorter than (xtol + rtol |x|)/2 (a
    bisection's midpoint is then that close to the root), or where Newton's next step,
    d_{n+1} ≈ d_n³/d_{n−1}² from the rate of its last two, would be (the root is then
    that close to the point stepped to), or at an exact zero; an end where the function
    is zero is the root. Each lane's steps depend
    on its own values alone: one design and a sweep of many get the same root. NaN
    where the ends hold no such crossing.
    """
    lo = np.array(a, dtype=float, ndmin=1)
    hi = np.array(np.broadcast_to(b, lo.shape), dtype=float)
    flo = np.broadcast_to(np.asarray(fa, dtype=float), lo.shape)
    fhi = np.broadcast_to(np.asarray(fb, dtype=float), lo.shape)
    root = np.where(flo == 0.0, lo, np.where(fhi == 0.0, hi, np.nan))
    active = (flo < 0.0) & (fhi > 0.0)
    with np.errstate(all="ignore"):
        x = lo - flo * (hi - lo) / (fhi - flo)
    x = np.where((x > lo) & (x < hi), x, 0.5 * (lo + hi))
    before = hi - lo  # the step before last: none yet, the bracket
    last = before.copy()
    i = np.flatnonzero(active)
    lo, hi, x, before, last = lo[i], hi[i], x[i], before[i], last[i]
    newer = np.zeros(i.size, dtype=bool)  # the last step was Newton's
    for _ in range(maxiter):
        if not i.size:
            break
        value, slope = f(x, i)
        below = value < 0.0
        lo = np.where(below, x, lo)
        hi = np.where(below, hi, x)
        with np.errstate(all="ignore"):
            step = value / slope
            new = x - step
            moved = np.abs(step)
            newton = (new > lo) & (new < hi) & (moved + moved <= before)
            middle = 0.5 * (lo + hi)
            new = np.where(newton, new, middle)
            moved = np.where(newton, moved, hi - middle)
            # Newton's next step from here, were it taken: the last two steps give the
            # rate of quadratic convergence, d_{n+1} ≈ d_n³/d_{n-1}²
            ahead = np.where(newton & newer, moved * (moved / last) ** 2, moved)
            zero = value == 0.0
            done = np.flatnonzero((ahead < (xtol + rtol * np.abs(x)) * 0.5) | zero)
        if done.size:
            root[i[done]] = np.where(zero[done], x[done], new[done])
            if done.size == i.size:
                break
            go = np.ones(i.size, dtype=bool)
            go[done] = False
            i, lo, hi, new = i[go], lo[go], hi[go], new[go]
            last, moved, newton = last[go], moved[go], newton[go]
        x, before, last, newer = new, last, moved, newton
    return root


#: Inputs that set only a setting's target torque, not the characteristic it is found on.
_TARGET_INPUTS = (
    "target_torque",
    "drive_torque",
    "drive_power",
    "drive_speed",
    "service_factor",
    "drive_start_torque",
    "drive_inertia",
    "load_inertia",
)

#: Designs whose grid of settings is evaluated at once, :data:`_GRID_BLOCK` settings at a
#: time (81 values each): a design whose target is reached early is not evaluated further.
#: 128 keeps each temporary near 0.7 MB: with 1024 (5.3 MB) the allocator handed them
#: back to the system and took them again at every block, and a 2,000-design sweep of
#: the cone height spent about half its time on page faults (each design's lane is
#: its own: the same answers).
_GRID_DESIGNS = 128
_GRID_BLOCK = 8
#: From this many points sharing one disc stack's curves, their candidates are chosen on
#: a grid :data:`_FINE_CANDIDATES` times finer (the same peak, from fewer curves).
_FINE_LANES = 8192
_FINE_CANDIDATES = 8


def setting_roots(
    x: Mapping[str, Any], target: Any, upper: Any, known: dict[Any, Any] | None = None
) -> Any:
    r"""Nut setting Δ whose peak torque is ``target``: the least Δ in [0, upper] where it
    reaches it; NaN where none does.

    .. math::
        \min \{\Delta : \max_k T(\Delta, z_k) \ge T_{target}\}

    The first crossing on a 65-point grid of Δ brackets the root, refined by Newton's
    method on the peak and the slope of the curve holding it (:func:`newton_roots`,
    :func:`peak_slope`), from the linear interpolation between the bracket's ends. The
    peak of a disc stack can rise above the target and fall back between two grid
    points, at the top of a curve (:func:`_curve_tops`, where alone it has its local
    maxima): where the least top at or past the target lies before that root (or none
    of the grid's points reaches the target), the root is found again between it and
    the grid point before it, which then hold one crossing (:func:`_first_top`).
    Floats or arrays (``x``'s arrays one design per element): a float for one design,
    the same number as an element of a sweep. [001, eq. 1–3] on :func:`characteristic`.

    ``known``, a dict kept by the caller for the calls on one design (the same stack at
    other targets): its grid, the peaks there and its curves are evaluated once, at
    the first of them (only where the design is the same at every point).
    """
    n = max([1, *(v.size for v in _arrays(x)), np.size(target), np.size(upper)])
    aims = np.array(np.broadcast_to(np.asarray(target, dtype=float), (n,)))
    tops = np.array(np.broadcast_to(np.asarray(upper, dtype=float), (n,)))
    varied = bool(_arrays(x))
    # the inputs that set only the target (a swept target torque or drive) leave the
    # characteristic the same at every point: its peaks on the grid are found once
    design = {k: v for k, v in x.items() if k not in _TARGET_INPUTS}
    shared = not _arrays(design) and np.ndim(upper) == 0

    def excess_slope(delta: Any, lanes: Any) -> tuple[Any, Any]:
        if curves is not None:  # the peak over the lift points that can hold it there
            peak, slope = curves.peak_slope(delta, span[lanes])
            return peak - aims[lanes], slope
        part = design if shared else points.take(x, n, lanes) if varied else x
        c = characteristic(part, Spring(part), delta, peak_only=True)
        return np.asarray(c["peak_torque"], dtype=float) - aims[lanes], c["peak_slope"]

    def excess(delta: Any, lanes: Any) -> Any:
        part = design if shared else points.take(x, n, lanes) if varied else x
        c = characteristic(part, Spring(part), delta, peak_only=True)
        return np.asarray(c["peak_torque"], dtype=float) - aims[lanes]

    curves: _Curves | None = None
    span = np.zeros(n, dtype=np.intp)  # the grid interval of a shared grid's bracket
    peaks: Any = None
    every: _Curves | None = None
    ends: Any = None
    if known is None or not shared or known.get("upper", float(upper)) != float(upper):
        known = {}
    if shared and "peaks" in known:  # the design's grid, peaks and curves from a call before
        line, every, ends, peaks = known["line"], known["every"], known["ends"], known["peaks"]
        lo_val = peaks[0] - aims
    elif shared:  # one grid for every point, the same floats as each point's own
        line = np.linspace(0.0, float(upper), 65)
        every = _Curves.every(design)
        if every is None:
            peaks = characteristic(design, Spring(design), line, peak_only=True)["peak_torque"]
        else:  # the curves on the grid, kept for their bounds: the peak is their largest
            ends = every.on(line)
            peaks = np.take_along_axis(ends, np.argmax(ends, axis=-1)[:, None], axis=-1)[:, 0]
        peaks = np.asarray(peaks, dtype=float)
        known.update(upper=float(upper), line=line, every=every, ends=ends, peaks=peaks)
        lo_val = peaks[0] - aims  # δ = 0
    else:
        lo_val = excess(np.zeros(n), np.arange(n))
    root = np.where(lo_val == 0.0, 0.0, np.nan)
    todo = pending = np.flatnonzero(lo_val < 0.0)
    # each point's bracket on the grid and the function's values at its ends
    low, high = np.full(n, np.nan), np.full(n, np.nan)
    f_low, f_high = np.full(n, np.nan), np.full(n, np.nan)
    if shared:
        # the first grid point at or past a target: where the running largest peak
        # (a torque that is not a number never reaches it) first reaches it
        running = np.maximum.accumulate(np.where(np.isnan(peaks[1:]), -np.inf, peaks[1:]))
        i = np.searchsorted(running, aims[todo], side="left") + 1
        reached = i <= 64
        at, i = todo[reached], i[reached]
        low[at], high[at] = line[i - 1], line[i]
        f_low[at], f_high[at] = peaks[i - 1] - aims[at], peaks[i] - aims[at]
        span[at] = i
        todo = todo[:0]
        # a large sweep's curves on a finer grid: fewer of them to evaluate at each step
        refine = _FINE_CANDIDATES if at.size >= _FINE_LANES else 1
        if at.size and refine not in known:
            known[refine] = _Curves.of(design, line, refine, every, ends)
        curves = known[refine] if at.size else None
    grid = np.linspace(0.0, tops, 65, axis=-1) if todo.size else tops[:, None]
    begin = np.ones(n, dtype=np.intp)  # the first grid point each point's scan reads
    before = lo_val.copy()  # the function at the grid point before ``begin``
    if todo.size:
        # where the peak rises along the grid, its first crossing is found by bisection;
        # the points it leaves are scanned past the part where it rises below the target
        todo = _bisect_rising(
            x, n, grid, todo, excess, (low, high, f_low, f_high), begin, before, lo_val
        )
    block = np.arange(_GRID_BLOCK)
    for first in range(0, todo.size, _GRID_DESIGNS):
        lanes = todo[first : first + _GRID_DESIGNS]
        # the grid a block of settings at a time, each design until it crosses the target
        while lanes.size:
            index = begin[lanes, None] + block
            on = index <= 64
            index = np.minimum(index, 64)
            settings = grid[lanes[:, None], index]
            values = excess(settings.ravel(), np.repeat(lanes, _GRID_BLOCK))
            values = values.reshape(-1, _GRID_BLOCK)
            above = (values >= 0.0) & on
            reached = above.any(axis=-1)
            k = np.argmax(above, axis=-1)  # the first grid point at or past it, in the block
            i = k + begin[lanes]
            at, rows = lanes[reached], np.flatnonzero(reached)
            low[at], high[at] = grid[at, i[reached] - 1], grid[at, i[reached]]
            f_high[at] = values[rows, k[reached]]
            f_low[at] = np.where(
                k[reached] > 0, values[rows, np.maximum(k[reached] - 1, 0)], before[at]
            )
            before[lanes] = values[:, -1]
            begin[lanes] += _GRID_BLOCK
            lanes = lanes[~reached & (begin[lanes] <= 64)]

    def solve(lanes: Any) -> None:
        if lanes.size:
            root[lanes] = newton_roots(
                lambda delta, part: excess_slope(delta, lanes[part]),
                low[lanes],
                high[lanes],
                f_low[lanes],
                f_high[lanes],
                xtol=1e-12,
                rtol=1e-12,
            )

    solve(np.flatnonzero(np.isfinite(low)))
    if x["spring_type"] == "disc" and pending.size:
        # a curve's top past the target before the root: the first crossing lies below it
        part = design if shared else points.take(x, n, pending) if varied else x
        at_tops = None if curves is None else curves.tops
        found = _first_top(part, pending, aims, tops, root, peaks, excess, at_tops)
        if found is not None:
            lanes, top, f_top = found
            # the grid point before the top: the peak is below the target up to there
            row = np.broadcast_to(line if shared else grid[lanes], (lanes.size, 65))
            j = np.count_nonzero(row < top[:, None], axis=-1) - 1
            low[lanes], high[lanes], f_high[lanes] = row[np.arange(lanes.size), j], top, f_top
            f_low[lanes] = peaks[j] - aims[lanes] if shared else excess(low[lanes], lanes)
            span[lanes] = j + 1
            solve(lanes)
    return root if varied or np.ndim(target) or np.ndim(upper) else float(root[0])


def _curve_tops(x: Mapping[str, Any], lifts: tuple[Any, Any] | None = None) -> tuple[Any, Any]:
    r"""The settings δ where a disc stack's torque at each lift point has an extremum, and
    the torque there: the only places where the peak torque max_k T_k(δ) has its local
    maxima.

    .. math::
        \delta_{kq} = \frac{i\,s_q - b_k}{a_k}, \qquad T_{kq} = c_k\,F(i\,s_q)

    At lift point k the stack is compressed by δ + z_k(δ) = a_k δ + b_k (a_k = 1 where
    ``ball_lift`` is given, else 1 + u on the flank, z = u Δ, and 2 over the rim), so
    T_k(δ) = c_k F(a_k δ + b_k), c_k the torque per newton (:func:`_gain_at`), has its
    extrema where the disc force has its, s_max and s_min
    (:func:`springs.disc_falling_region`; NaN where the force rises everywhere). A local
    maximum of the largest of such curves is one of a curve that holds it: between
    them the largest of rising or falling curves has none. Arrays with (q, k) on two
    last axes, 2 × 81; ``x``'s arrays one design per element; ``lifts`` the lift
    points' b_k and β_k where known (else from :func:`lift_points`). [001, eq. 1–3]
    with EN 16983's force.

    The default disc stack (h0/t = 2, 2 in series, h = 0.4 mm): the seated point k = 0
    reaches the force's maximum at the setting i s_max = 2.367 mm, the last flank point
    (z = h) 0.4 mm earlier:

    >>> from engine.models.clutch import BALL_CLUTCH
    >>> disc = {"spring_type": "disc", "disc_outer_diameter": 0.04,
    ...         "disc_inner_diameter": 0.0204, "disc_thickness": 0.001,
    ...         "disc_cone_height": 0.002, "disc_series": 2, "spring_deflection": 0.002}
    >>> geometry = {"ball_circle_diameter": 0.05, "ball_count": 6, "ball_diameter": 0.005,
    ...             "groove_angle": math.radians(45.0), "flank_friction": 0.1}
    >>> x, _ = BALL_CLUTCH.validate({**geometry, **disc, "ball_lift": 0.0004})
    >>> settings, torque = _curve_tops(x)
    >>> [round(float(v) * 1e3, 4) for v in (settings[0, 0], settings[0, 40])]
    [2.367, 1.967]

    On the flank (one contact angle) every curve's top is the same torque:

    >>> bool(np.all(torque[0, :41] == torque[0, 0]) and torque[0, 41] != torque[0, 0])
    True

    Where the lift follows the setting, the last flank point is compressed by 2 Δ:

    >>> x, _ = BALL_CLUTCH.validate({**geometry, **disc})
    >>> [round(float(v) * 1e3, 4) for v in _curve_tops(x)[0][0, [0, 40]]]
    [2.367, 1.1835]
    """
    given = x["ball_lift"] is not None
    fixed, beta = lifts or lift_points(
        x["ball_lift"] if given else 0.0, x["ball_diameter"], _ride(x), POINTS
    )
    rate: Any = 1.0 if given else 1.0 + lift_points(1.0, 0.0, 0.0, POINTS)[0]
    region = sp.disc_falling_region(x["disc_thickness"], x["disc_cone_height"])
    # the stack's compressions at the force's extrema (maximum, minimum), one per design
    series = np.asarray(x["disc_series"], dtype=float)
    high, low, *_ = np.broadcast_arrays(region[0] * series, region[1] * series, *_arrays(x))
    settings = (np.stack([high, low], axis=-1)[..., None] - fixed[..., None, :]) / rate
    force = np.asarray(Spring(x).force(np.stack([high, low]))).T  # (…, 2)
    return settings, _gain_at(x, beta)[..., None, :] * force[..., None]


def _first_top(
    x: Mapping[str, Any],
    lanes: Any,
    aims: Any,
    uppers: Any,
    root: Any,
    peaks: Any,
    excess: Callable[[Any, Any], Any],
    known: tuple[Any, Any] | None = None,
) -> tuple[Any, Any, Any] | None:
    """The points of ``lanes`` whose peak torque reaches its target at a curve's top
    (:func:`_curve_tops`) in (0, upper] before ``root`` (or where ``root`` is NaN): those
    points, the least such top of each and the function ``excess`` there; None where
    there are none.

    A top counts where the curve's torque there (with a slack of :attr:`_Curves.SLACK`
    for rounding) and the peak torque at its setting both reach the target. Up to the
    least, the peak has no local maximum at or past the target (the tops hold them
    all): between the grid point before it and it, the peak crosses the target once.
    ``x`` the design (``peaks`` not None: one design for every point, whose tops are
    all evaluated once) or the points' designs (each lane's tops evaluated in order of
    the setting until one counts).
    """
    tops = _curve_tops(x) if known is None else known
    settings, torque = (np.reshape(v, (*np.shape(v)[:-2], -1)) for v in tops)
    reach = torque + _Curves.SLACK * np.abs(torque)
    if peaks is not None:  # one design: the least top whose peak reaches each target
        inside = (settings > 0.0) & (settings <= uppers[lanes[0]])
        inside &= reach >= np.min(aims[lanes])  # (a NaN torque reaches none)
        settings, reach = settings[inside], reach[inside]
        # the targets a top before their root may reach: only there is the peak asked for
        limit = np.where(np.isnan(root[lanes]), np.inf, root[lanes])
        ask = np.flatnonzero(
            (aims[lanes] <= np.max(reach, initial=-np.inf))
            & (limit > np.min(settings, initial=np.inf))
        )
        if not ask.size:
            return None
        order = np.argsort(settings, kind="stable")
        settings, reach = settings[order], reach[order]
        before = np.searchsorted(settings, limit[ask])  # the tops before the root
        best = np.maximum.accumulate(reach)
        ask, before = ask[before > 0], before[before > 0]
        keep = best[before - 1] >= aims[lanes[ask]]
        ask, before = ask[keep], before[keep]
        if not ask.size:
            return None
        settings, reach = settings[: np.max(before)], reach[: np.max(before)]
        char = characteristic(x, Spring(x), settings, peak_only=True)["peak_torque"]
        at_top = np.asarray(char, dtype=float)
        counts = np.minimum(reach, at_top)
        running = np.maximum.accumulate(np.where(np.isnan(counts), -np.inf, counts))
        k = np.searchsorted(running, aims[lanes[ask]], side="left")
        hit, k = ask[k < before], k[k < before]  # at a top before the root
        if not hit.size:
            return None
        return lanes[hit], settings[k], at_top[k] - aims[lanes[hit]]
    settings = np.broadcast_to(settings, (lanes.size, settings.shape[-1]))
    reach = np.broadcast_to(reach, settings.shape)
    ok = (
        (reach >= aims[lanes, None])
        & (settings > 0.0)
        & (settings <= uppers[lanes, None])
        & ~(settings >= root[lanes, None])
    )
    rows = np.flatnonzero(ok.any(axis=-1))
    top, f_top = np.full(lanes.size, np.nan), np.full(lanes.size, np.nan)
    while rows.size:  # each lane's tops that count, least first, until one reaches it
        col = np.argmin(np.where(ok[rows], settings[rows], np.inf), axis=-1)
        value = excess(settings[rows, col], lanes[rows])
        hit = value >= 0.0
        top[rows[hit]], f_top[rows[hit]] = settings[rows[hit], col[hit]], value[hit]
        ok[rows[~hit], col[~hit]] = False
        rows = rows[~hit]
        rows = rows[ok[rows].any(axis=-1)]
    found = np.flatnonzero(np.isfinite(top))
    return (lanes[found], top[found], f_top[found]) if found.size else None


class _Curves:
    """One disc-stack design's characteristic as 81 curves T_k(δ) of the nut setting δ.

    With the ball at lift point k (``ball_lift`` given, so the lift points do not move
    with δ) the torque is T_k(δ) = s D0 F((δ + z_k)/i)/(2 p(β_k)), and the peak torque
    is max_k T_k(δ) (:func:`characteristic`). Between two settings of the root search's
    grid, a curve can hold the peak only if its largest value there reaches the
    largest of every curve's smallest: its values at the interval's ends, and at the
    disc force's extrema inside it (:func:`springs.disc_falling_region`), bound it. The
    peak over those curves alone is the same float as over all 81 (the maximum of a
    set that holds it); the bounds carry a slack of 1e-9 of the largest torque.
    """

    #: Relative slack on the bounds (rounding is ~1e-16 of a torque).
    SLACK = 1e-9

    def __init__(
        self, x: Mapping[str, Any], lift: Any, beta: Any, candidates: Any, tops: Any = None
    ) -> None:
        self.x, self.spring = x, Spring(x)
        self.lift, self.beta, self.candidates = lift, beta, candidates
        #: the curves' tops, :func:`_curve_tops`
        self.tops = _curve_tops(x, lifts=(lift, beta)) if tops is None else tops
        # the candidates' grid: ``refine`` intervals in each of the search's, from
        # ``start`` in steps of ``step``
        self.refine, self.start, self.step = 1, 0.0, 1.0
        # the rows of ``candidates`` (one per interval, :meth:`of`): their lengths and starts
        self.counts: Any = None
        self.offsets: Any = None

    @classmethod
    def every(cls, x: Mapping[str, Any]) -> _Curves | None:
        """All 81 curves of a disc stack ``x`` (candidates: every lift point); None where
        the lift points move with the setting (``ball_lift`` absent) or the spring is
        helical (whose setting :class:`SettingGrid` solves)."""
        if x["ball_lift"] is None or x["spring_type"] != "disc":
            return None
        lift, beta = lift_points(x["ball_lift"], x["ball_diameter"], _ride(x), POINTS)
        return cls(x, lift, beta, np.arange(lift.size))

    def on(self, grid: Any) -> Any:
        """Every curve at the settings ``grid``, (settings, 81): the floats
        :func:`characteristic` evaluates there (its peak is their largest)."""
        return self.torque(np.asarray(grid, dtype=float)[:, None], self.candidates)

    @classmethod
    def of(
        cls,
        x: Mapping[str, Any],
        grid: Any,
        refine: int = 1,
        curves: _Curves | None = None,
        ends: Any = None,
    ) -> _Curves | None:
        """The curves of a disc stack ``x`` on the settings ``grid`` (their candidates on
        ``refine`` equal intervals in each of its: fewer curves each, at the price of
        more bounds); None where the lift points move with the setting (``ball_lift``
        absent), a torque is not finite, or the spring is helical (whose setting
        :class:`SettingGrid` solves). ``curves`` and ``ends``: :meth:`every` curve and
        their torques :meth:`on` the grid where known (not evaluated again)."""
        curves = cls.every(x) if curves is None else curves
        if curves is None:
            return None
        lift, beta = curves.lift, curves.beta
        grid = np.asarray(grid, dtype=float)
        intervals = (grid.size - 1) * refine
        if refine > 1:
            grid, ends = np.linspace(grid[0], grid[-1], intervals + 1), None
        bounds = curves.bounds(grid, ends)
        if bounds is None:
            return None
        upper, lower, ends = bounds
        slack = cls.SLACK * float(np.max(np.abs(ends)))
        holds = upper + slack >= np.max(lower, axis=-1, keepdims=True) - slack
        # per interval the curves that may hold the peak, in ascending order, one row
        # after another; row j is the interval ending at grid point j (row 0 unused)
        rows, candidates = np.nonzero(np.concatenate([holds[:1], holds]))
        out = cls(x, lift, beta, candidates, curves.tops)
        out.counts = np.bincount(rows, minlength=holds.shape[0] + 1)
        out.offsets = np.cumsum(out.counts) - out.counts
        out.refine, out.start = refine, float(grid[0])
        out.step = (float(grid[-1]) - out.start) / intervals
        return out

    def bounds(self, grid: Any, ends: Any = None) -> tuple[Any, Any, Any] | None:
        """(largest, smallest) of every curve in every interval of ``grid`` (interval j
        between settings j and j + 1, a row each), and the curves at the settings; None
        where a torque is not finite. Each curve is the disc force of a setting that
        rises with δ, times a constant: its extremes lie at the ends or at the force's
        extrema inside (none where the force rises everywhere). ``ends``: the curves
        :meth:`on` the grid, where known."""
        every = np.arange(self.lift.size)
        ends = self.torque(grid[:, None], every) if ends is None else ends  # (65, 81)
        at = self.tops[0]  # (2, 81): the curves' tops
        inner = self.torque(np.where(np.isfinite(at), at, 0.0), every)
        if not (np.all(np.isfinite(ends)) and np.all(np.isfinite(inner))):
            return None
        lo, hi = ends[:-1], ends[1:]
        upper, lower = np.maximum(lo, hi), np.minimum(lo, hi)
        for setting, value in zip(at, inner, strict=True):
            inside = (grid[:-1, None] < setting) & (setting < grid[1:, None])
            upper = np.where(inside, np.maximum(upper, value), upper)
            lower = np.where(inside, np.minimum(lower, value), lower)
        return upper, lower, ends

    def torque(self, delta: Any, k: Any) -> Any:
        """T_k(δ) as :func:`characteristic` evaluates it (the same floats)."""
        x = self.x
        force = self.spring.force(np.asarray(delta, dtype=float) + self.lift[k])
        return np.asarray(_flank_torque(x, force, self.beta[k]))

    def peak(self, delta: Any, span: Any) -> Any:
        """The peak torque at settings ``delta``, each in the grid interval ending at
        grid point ``span``."""
        return self.peak_slope(delta, span)[0]

    def peak_slope(self, delta: Any, span: Any) -> tuple[Any, Any]:
        """:meth:`peak` and the slope dT_k/dδ of the curve k holding it
        (:func:`peak_slope`, the same floats as :func:`characteristic`'s)."""
        delta = np.asarray(delta, dtype=float)
        if self.refine > 1:  # the candidates' interval that holds each setting
            fine = np.floor((delta - self.start) / self.step).astype(np.intp) + 1
            span = np.clip(fine, (span - 1) * self.refine + 1, span * self.refine)
        # each setting's candidates, one setting after another (``owner`` their setting)
        count = self.counts[span]
        starts = np.cumsum(count) - count
        owner = np.repeat(np.arange(span.size), count)
        flat = np.arange(owner.size)
        k = self.candidates[flat + np.repeat(self.offsets[span] - starts, count)]
        torque = self.torque(delta[owner], k)
        # each setting's first largest torque (its first NaN, if any), as argmax takes it
        largest = np.maximum.reduceat(torque, starts)
        first = (torque == largest[owner]) | np.isnan(torque)
        top = np.minimum.reduceat(np.where(first, flat, owner.size), starts)
        held = k[top]
        slope = peak_slope(self.x, self.spring, delta + self.lift[held], self.beta[held], 0.0)
        return torque[top], slope


def _bisect_rising(
    x: Mapping[str, Any],
    n: int,
    grid: Any,
    todo: Any,
    excess: Callable[[Any, Any], Any],
    brackets: tuple[Any, Any, Any, Any],
    begin: Any,
    before: Any,
    seated: Any,
) -> Any:
    """The grid brackets of the points of ``todo`` whose peak torque rises along the grid.

    A disc stack's force rises up to its maximum s_max (everywhere where h0/t ≤ √2,
    :func:`springs.disc_falling_region`) and every lift point's torque with it (a
    positive push); the peak torque then rises with the setting while the stack's
    largest compression, at the last lift point, stays below i s_max. Over the grid
    points up to there the first at or past the target is found by bisection (the same
    bracket the scan finds: a rising function crosses once). Sets the ``brackets``
    (low, high and the function ``excess`` there) where found, from ``seated``, the
    function at the grid's first point; returns the points left for the scan (not
    rising, or not reached), and sets ``begin`` of those not reached to the grid point
    past the rising part and ``before`` to the function at the point before it.
    """
    if x["spring_type"] != "disc":
        return todo
    part = points.take(x, n, todo) if _arrays(x) else x
    s_max = np.asarray(sp.disc_falling_region(part["disc_thickness"], part["disc_cone_height"])[0])
    settings = grid[todo]  # (m, 65)
    rim = np.asarray(rim_rise(part["ball_diameter"], _ride(part)))
    given = np.asarray(part["ball_lift"] if part["ball_lift"] is not None else settings)
    lift = given[..., None] if part["ball_lift"] is not None else given
    last = settings + lift + rim[..., None]  # the largest compression, at the last point
    rising = np.where(
        np.isnan(s_max)[..., None], True, last <= (s_max * part["disc_series"])[..., None]
    )
    beta = lift_points(0.0, part["ball_diameter"], _ride(part), POINTS)[1]
    gain = _gain_at(part, beta)
    pushing = np.all(np.isfinite(gain) & (gain > 0.0), axis=-1)
    # the last grid point of the rising prefix (0: none), per point
    top = np.broadcast_to(
        np.where(pushing, np.sum(np.cumprod(rising, axis=-1), -1) - 1, 0), todo.shape
    )
    ask = np.flatnonzero(top > 0)
    lanes = todo[ask]
    lo, hi = np.zeros(ask.size, dtype=np.intp), top[ask]
    f_hi = excess(grid[lanes, hi], lanes)
    reached = f_hi >= 0.0
    begin[lanes[~reached]] = hi[~reached] + 1  # below the target up to there
    before[lanes[~reached]] = f_hi[~reached]
    lanes, lo, hi, f_hi = lanes[reached], lo[reached], hi[reached], f_hi[reached]
    f_lo = seated[lanes]
    while lanes.size:
        more = hi - lo > 1
        if not more.any():
            break
        mid = (lo + hi) // 2
        at = np.flatnonzero(more)
        value = excess(grid[lanes[at], mid[at]], lanes[at])
        up = value >= 0.0
        hi[at], f_hi[at] = np.where(up, mid[at], hi[at]), np.where(up, value, f_hi[at])
        lo[at], f_lo[at] = np.where(up, lo[at], mid[at]), np.where(up, f_lo[at], value)
    low, high, f_low, f_high = brackets
    low[lanes], high[lanes] = grid[lanes, lo], grid[lanes, hi]
    f_low[lanes], f_high[lanes] = f_lo, f_hi
    return np.setdiff1d(todo, lanes, assume_unique=True)


def solve_setting(
    x: Mapping[str, Any], spring: Spring, target: float, upper: float
) -> float | None:
    """Nut setting Δ whose peak torque is ``target``; None where none in [0, upper] gives it.

    One design: :func:`setting_roots` (``spring`` is ``Spring(x)``, kept for the callers).
    """
    root = setting_roots(x, target, upper)
    return None if math.isnan(root) else root


Candidate = Callable[[float], Mapping[str, Any]]


# --------------------------------------------------------------------------
# The inverse on the as-built inputs (clutch.ball_setting)
# --------------------------------------------------------------------------


def _disc_stack_end(x: Mapping[str, Any], spring: Spring, deflection: Any) -> tuple[Any, Any]:
    """(total lift, largest |σ_OM| over the lift) of a disc stack set at ``deflection``.

    |σ_OM| grows with the deflection (DIN EN 16983: σ_OM ∝ s) and the lift rises along
    the grid, so the largest is at the last point (riding on the face): the same floats
    :func:`characteristic` takes as its ``total_lift`` and ``spring_stress_max``,
    without the 81-point curve.
    """
    lift, _ = lift_points(lift_of(x, deflection), x["ball_diameter"], _ride(x), POINTS, True)
    total_lift = lift[..., -1]
    return total_lift, spring.stress(np.asarray(deflection, dtype=float) + total_lift)


def setting_outputs() -> tuple[Output, ...]:
    """The as-built outputs of clutch.ball_setting."""
    return (
        Output(
            "required_peak_setting",
            "m",
            "nut setting (spring deflection with the balls seated) whose PEAK torque over the "
            "lift is the target, with the given spring; null where none reaches it",
            display_unit="mm",
            symbol="Δ_peak",
            step="[001, eq. 1–3]",
        ),
        Output(
            "peak_setting_stress_max",
            "Pa",
            "largest spring stress over the lift at required_peak_setting",
            display_unit="MPa",
            symbol="τ_k,max",
            step="EN 13906-1",
        ),
        Output(
            "suggested_wire_diameter",
            "m",
            "smallest preferred wire (EN 10270-1 sizes, index 4…12, same D and i_p) that "
            "reaches the target peak torque within the permissible stress",
            display_unit="mm",
            symbol="d_0",
            step="EN 10270-1",
        ),
        Output(
            "suggested_wire_setting",
            "m",
            "nut setting of the suggested wire for the target peak torque",
            display_unit="mm",
            symbol="Δ",
            step="[001, eq. 1–3]",
        ),
        Output(
            "suggested_disc_parallel",
            "1",
            "fewest discs in parallel per pack (same discs and series count) that reach the "
            "target peak torque within σ_OM ≤ yield and without passing flat",
            kind="int",
            symbol="n_disc",
            step="EN 16983",
        ),
        Output(
            "suggested_disc_setting",
            "m",
            "stack setting with the suggested number of discs in parallel",
            display_unit="mm",
            symbol="s",
            step="EN 16983",
        ),
    )


def _scalar_or_array(value: Any) -> Any:
    """A float for a 0-d result, the array otherwise."""
    arr = np.asarray(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr


def peak_setting(
    x: Mapping[str, Any],
    spring: Spring,
    target: Any,
    force: Any,
    grid: SettingGrid | None = None,
    known: dict[Any, Any] | None = None,
) -> tuple[Any, Any]:
    """(setting, largest stress over the lift) for the target peak torque; NaN where none.

    Floats or arrays. A helical
    spring's characteristic is a set of lines in the setting (:class:`SettingGrid`):
    where they all rise, the setting comes in closed form (one characteristic instead
    of the ~40 a bracketed root search takes; the two agree to 1e-12,
    ``tests/models/clutch/test_clutch_arrays.py``); at a point where they need not
    (a push ≤ 0 on the driving flank), and for a disc stack, by :func:`setting_roots`.
    ``grid`` may be passed in when the same geometry serves several springs; ``known``
    (a disc stack), the :func:`setting_roots` work kept for other targets on it.
    """
    if spring.kind == "disc":
        root = setting_roots(x, target, x["disc_series"] * x["disc_cone_height"], known)
        if np.ndim(root) == 0:  # one design
            if math.isnan(root):
                return math.nan, math.nan
            total_lift, stress_max = _disc_stack_end(x, spring, root)
            if (root + float(total_lift)) / x["disc_series"] > x["disc_cone_height"]:
                return math.nan, math.nan  # reached only past flat
            return root, float(stress_max)
        total_lift, stress_max = _disc_stack_end(x, spring, np.where(np.isnan(root), 0.0, root))
        past = (root + total_lift) / x["disc_series"] > x["disc_cone_height"]
        none = np.isnan(root) | past  # none reaches it, or only past flat
        return np.where(none, np.nan, root), np.where(none, np.nan, stress_max)
    grid = SettingGrid(x) if grid is None else grid
    rate = np.asarray(spring.force(1.0), float)
    upper = np.maximum(np.asarray(force) / rate, 1e-9) * 1.000001
    delta = np.asarray(grid.setting(rate, target, upper))
    stress = np.asarray(end_values({**x, "spring_deflection": delta}, spring)["spring_stress_max"])
    if not np.all(grid.regular):
        n = delta.size if delta.ndim else 0
        delta, stress = np.array(delta, float, ndmin=1), np.array(stress, float, ndmin=1)
        for j in np.flatnonzero(~np.broadcast_to(grid.regular, delta.shape)).tolist():
            point = points.at(x, n, j) if n else dict(x)
            found = solve_setting(
                point,
                Spring(point),
                float(np.broadcast_to(target, delta.shape)[j]),
                float(np.broadcast_to(upper, delta.shape)[j]),
            )
            delta[j], stress[j] = (
                (np.nan, np.nan)
                if found is None
                else (
                    found,
                    float(characteristic(point, Spring(point), found)["spring_stress_max"]),
                )
            )
        if not n:
            delta, stress = delta[0], stress[0]
    return _scalar_or_array(delta), _scalar_or_array(stress)


def setting_values(x: Mapping[str, Any], force: Any) -> tuple[dict[str, Any], list[str]]:
    """As-built outputs of the inverse and, for one design, the notes that explain them.

    Floats or arrays (NaN where an output is null). On floats an output that does not
    exist is left out.
    """
    target = x["target_torque"]
    values: dict[str, Any] = {}
    notes: list[str] = []
    helical = x["spring_type"] == "helical"
    found: tuple[Any, Any] | None = None
    known: dict[Any, Any] = {}  # a disc stack's root-search work, for its suggestion too
    if not helical or x["spring_wire_diameter"] is not None:
        delta, stress = peak_setting(x, Spring(x), target, force, known=known)
        if np.ndim(delta) == 0 and math.isnan(delta):
            notes.append(
                "required_peak_setting is null: no setting of this spring gives the target as "
                "its peak torque (the lift alone overshoots it, or a disc stack would pass flat)"
            )
        else:
            values["required_peak_setting"], values["peak_setting_stress_max"] = delta, stress
            found = (delta, stress)
    if helical and x["spring_mean_diameter"] is not None:
        values.update(suggest_wire(x, target, force, notes))
    if not helical:
        values.update(_suggest_parallel(x, target, force, notes, found, known))
    return values, notes


def suggest_wire(
    x: Mapping[str, Any], target: Any, force: Any, notes: list[str] | None = None
) -> dict[str, Any]:
    """The thinnest preferred wire that reaches the target peak torque, per point.

    Candidates in the order of :data:`springs.STANDARD_WIRE_DIAMETERS` (spring index
    4…12, inside the material's table, a peak setting within the permissible stress,
    not solid at the largest deflection; the same D and i_p). Floats or arrays: NaN
    where none works, and on floats the outputs are then left out. ``notes``, for one
    design, gets the sentences that explain the answer.
    """
    said = [] if notes is None else notes
    if x["spring_material"] == "custom" and x["allowable_shear_stress"] is None:
        said.append("give spring_material or allowable_shear_stress for a suggested wire diameter")
        return {}
    grid = SettingGrid(x)
    dm = np.asarray(x["spring_mean_diameter"], float)
    # every varied input (coils and free length too, which the grid does not see)
    shape = np.broadcast_shapes(
        dm.shape,
        np.shape(target),
        np.shape(force),
        grid.inverse_gain.shape[:-1],
        *(v.shape for v in _arrays(x)),
    )
    wire = np.full(shape, np.nan)
    setting = np.full(shape, np.nan)
    stress_at = np.full(shape, np.nan)
    allow_at = np.full(shape, np.nan)
    open_ = np.ones(shape, dtype=bool)
    for d_mm in sp.STANDARD_WIRE_DIAMETERS:
        d = d_mm * 1e-3
        index = dm / d
        trying = open_ & (index >= 4.0) & (index <= 12.0)
        if not trying.any():
            if not np.any(open_ & (index > 12.0)):
                break  # every open point's coil is too small for this wire and thicker ones
            continue
        trial = {**x, "spring_wire_diameter": d}
        spring = Spring(trial)
        try:
            allow = spring.permissible()
        except InputOutOfRange:
            continue  # outside the material's table
        if allow is None:
            continue
        delta, stress = peak_setting(trial, spring, target, force, grid)
        fits = trying & np.isfinite(delta) & (stress <= np.asarray(allow, float))
        if x["spring_free_length"] is not None:
            total_lift = end_values({**trial, "spring_deflection": delta}, spring)["total_lift"]
            travel = delta + total_lift
            coils = x["spring_active_coils"]
            room = np.asarray(sp.solid_length(d, coils), float) + np.asarray(
                sp.minimum_gap_sum(d, dm, coils), float
            )
            fits &= ~(x["spring_free_length"] - travel < room)
        wire = np.where(fits, d, wire)
        setting = np.where(fits, delta, setting)
        stress_at = np.where(fits, stress, stress_at)
        allow_at = np.where(fits, allow, allow_at)
        open_ &= ~fits
        if not open_.any():
            break
    if wire.ndim:
        return {"suggested_wire_diameter": wire, "suggested_wire_setting": setting}
    if math.isnan(wire):
        said.append("no preferred wire with spring index 4…12 reaches the target within its stress")
        return {}
    if x["spring_free_length"] is None:
        said.append(
            "spring_free_length not given: the suggested wire's setting is not limited by "
            "its solid length"
        )
    said.append(
        f"suggested wire {q(float(wire), 'mm', fmt='g')}: the thinnest preferred size that "
        f"reaches {q(float(target), 'N*m', 4)} at its peak with "
        f"{q(float(stress_at), 'MPa', 4)} ≤ {q(float(allow_at), 'MPa', 4)}"
    )
    return {"suggested_wire_diameter": float(wire), "suggested_wire_setting": float(setting)}


def _suggest_parallel(
    x: Mapping[str, Any],
    target: Any,
    force: Any,
    notes: list[str],
    given: tuple[Any, Any] | None,
    known: dict[Any, Any] | None = None,
) -> dict[str, Any]:
    """The fewest discs in parallel that reach the target; ``given`` is the given stack's
    own :func:`peak_setting` (not searched again for its own number of discs), ``known``
    its root search's work (:func:`setting_roots`).

    Frictionless discs (w_M = 0), 2^j times the given number in parallel (or a 2^j-th
    of it), press with exactly 2^j times its force at every deflection (F = n F_1, a
    power of two scales a float exactly): the torque curves are the given stack's times
    2^j to the last bit, so the setting for the target is the given stack's for the
    target over 2^j, found on its curves (``known``), the same floats.

    Floats or arrays: each count is searched only at the points still without a pack;
    NaN where none of up to 8 works, and on floats the outputs are then left out.
    """
    n = max([1, *(v.size for v in _arrays(x)), np.size(target)])
    one = n == 1 and not _arrays(x) and np.ndim(target) == 0
    aims = np.broadcast_to(np.asarray(target, dtype=float), (n,))
    count, setting = np.full(n, np.nan), np.full(n, np.nan)
    open_ = np.ones(n, dtype=bool)
    limit = np.broadcast_to(np.asarray(x["disc_yield_strength"], dtype=float), (n,))
    delta: Any
    stress: Any
    parallel, friction = x["disc_parallel"], x["disc_friction"]
    frictionless = np.ndim(parallel) == 0 and np.ndim(friction) == 0 and friction == 0.0
    for k in range(1, 9):
        lanes = np.flatnonzero(open_)
        scale = k / parallel if frictionless else 0.0
        if np.ndim(parallel) == 0 and k == parallel:
            if given is None:
                delta, stress = math.nan, math.nan
            else:  # the given stack's own setting, at the points still open
                delta, stress = (np.broadcast_to(g, (n,))[lanes] for g in given)
        elif scale > 0.0 and math.frexp(scale)[0] == 0.5:  # 2^j times the given force
            part = points.take(x, n, lanes) if _arrays(x) else x
            aim = float(aims[0]) / scale if one else aims[lanes] / scale
            delta, stress = peak_setting(part, Spring(part), aim, force, known=known)
        else:
            part = points.take(x, n, lanes) if _arrays(x) else x
            trial = {**part, "disc_parallel": k}
            aim = float(aims[0]) if one else aims[lanes]
            delta, stress = peak_setting(trial, Spring(trial), aim, force)
        fits = np.isfinite(delta) & (np.asarray(stress) <= limit[lanes])
        count[lanes[fits]] = k
        setting[lanes[fits]] = np.broadcast_to(delta, lanes.shape)[fits]
        open_[lanes[fits]] = False
        if not open_.any():
            break
    if not one:
        return {"suggested_disc_parallel": count, "suggested_disc_setting": setting}
    if open_[0]:
        notes.append("no stack of up to 8 of these discs in parallel reaches the target")
        return {}
    return {"suggested_disc_parallel": int(count[0]), "suggested_disc_setting": float(setting[0])}


#: The inputs of a disc stack's force (:class:`Spring`) and of its rising branch.
_DISC_STACK = (
    "disc_outer_diameter",
    "disc_inner_diameter",
    "disc_thickness",
    "disc_cone_height",
    "disc_series",
    "disc_parallel",
    "disc_friction",
    "disc_elastic_modulus",
)


def disc_breakaway_setting(x: Mapping[str, Any], force: Any) -> Any:
    r"""Stack setting whose force is ``force`` on the rising branch; NaN if none gives it.

    .. math::
        F(s) = F_{target}, \quad 0 \le s \le i \min(s_{max}, h_0)

    s_max where the disc's force peaks (none: the cone height). On a 65-point grid of
    the branch (the force rises along it) bisection finds the interval that holds the
    setting (one stack whose grid forces rise: a sorted search of them, the same
    interval), refined by Newton's method on the force and the stack's rate
    (:func:`newton_roots`, :meth:`Spring.rate`). Floats or arrays: a float for one
    design, the same number as an element of a sweep (a stack that is the same at
    every point is evaluated on its grid once). EN 16983.
    """
    n = max([1, *(v.size for v in _arrays(x)), np.size(force)])
    varied = bool(_arrays(x))
    wanted = np.array(np.broadcast_to(np.asarray(force, dtype=float), (n,)))
    s_max = np.asarray(sp.disc_falling_region(x["disc_thickness"], x["disc_cone_height"])[0])
    top = np.where(np.isfinite(s_max), s_max, x["disc_cone_height"])
    upper = np.broadcast_to(
        np.asarray(x["disc_series"] * np.minimum(top, x["disc_cone_height"]), dtype=float), (n,)
    )

    stack = None if varied else Spring(x)

    def excess_rate(delta: Any, lanes: Any) -> tuple[Any, Any]:
        spring = Spring(points.take(x, n, lanes)) if stack is None else stack
        return np.asarray(spring.force(delta), dtype=float) - wanted[lanes], spring.rate(delta)

    forces: Any = None
    if any(isinstance(x[k], np.ndarray) for k in _DISC_STACK):
        grid = np.linspace(0.0, upper, 65, axis=-1)

        def excess(index: Any, lanes: Any) -> Any:
            return excess_rate(grid[lanes, index], lanes)[0]

    else:  # one stack: its forces on the grid once, the same floats
        line = np.linspace(0.0, float(upper[0]), 65)
        grid = np.broadcast_to(line, (n, 65))
        forces = np.asarray((stack or Spring(x)).force(line), dtype=float)

        def excess(index: Any, lanes: Any) -> Any:
            return forces[index] - wanted[lanes]

    every = np.arange(n)
    at_top = excess(np.full(n, 64), every)
    reach = np.flatnonzero(~(at_top < 0.0))
    lo, hi = np.zeros(reach.size, dtype=np.intp), np.full(reach.size, 64)
    f_lo, f_hi = excess(lo, reach), at_top[reach]
    if forces is not None and np.all(forces[1:] > forces[:-1]):
        # one stack whose grid forces rise: the bracket the bisection below finds, at
        # once (the first grid force at or past each point's; a NaN force: the last)
        hi = np.clip(np.searchsorted(forces, wanted[reach], side="left"), 1, 64)
        lo = hi - 1
        f_lo, f_hi = excess(lo, reach), excess(hi, reach)
    while reach.size and np.any(hi - lo > 1):
        mid = (lo + hi) // 2
        value = excess(mid, reach)
        up = value >= 0.0
        hi, f_hi = np.where(up, mid, hi), np.where(up, value, f_hi)
        lo, f_lo = np.where(up, lo, mid), np.where(up, f_lo, value)
    setting = np.full(n, np.nan)
    setting[reach] = newton_roots(
        lambda delta, lanes: excess_rate(delta, reach[lanes]),
        grid[reach, lo],
        grid[reach, hi],
        f_lo,
        f_hi,
        xtol=1e-13,
        rtol=1e-12,
    )
    return setting if varied or np.ndim(force) else float(setting[0])


# --------------------------------------------------------------------------
# Sizing from the drive (clutch.ball_setting)
# --------------------------------------------------------------------------


def sizing_params() -> tuple[Param, ...]:
    """Inputs that give the required slip torque from the drive."""
    return (
        positive(
            "drive_torque",
            "N*m",
            "rated (or peak working) torque of the drive; or give drive_power and drive_speed",
            maximum=1e6,
            display_unit="N*m",
            group="drive",
        ),
        positive("drive_power", "W", "rated power P of the drive", maximum=1e7, group="drive"),
        positive(
            "drive_speed",
            "rad/s",
            "speed ω of the clutch's shaft at rated power",
            maximum=1e5,
            display_unit="rpm",
            group="drive",
        ),
        Param(
            "service_factor",
            "1",
            "K on the rated torque, 1.5 (smooth) … 3 (shocks) as torque-limiter makers advise",
            default=2.0,
            minimum=1.0,
            maximum=10.0,
            recommended=RECOMMENDED_SERVICE_FACTOR,
            group="drive",
        ),
        positive(
            "drive_start_torque",
            "N*m",
            "peak torque of the motor while starting (e.g. its breakdown torque)",
            maximum=1e6,
            display_unit="N*m",
            group="drive",
        ),
        positive(
            "drive_inertia",
            "kg*m^2",
            "J_A, inertia on the driving side of the clutch",
            maximum=1e4,
            group="drive",
        ),
        positive(
            "load_inertia",
            "kg*m^2",
            "J_L, inertia on the driven side, referred to the clutch's speed",
            maximum=1e4,
            group="drive",
        ),
    )


def sizing_outputs() -> tuple[Output, ...]:
    """Outputs of the sizing from the drive."""
    return (
        Output(
            "rated_drive_torque",
            "N*m",
            "T_N: drive_torque, or P/ω",
            display_unit="N*m",
            symbol="T_N",
            step="",
        ),
        Output(
            "start_torque",
            "N*m",
            "T_a = T_start J_L/(J_A + J_L): what the clutch carries while the motor accelerates "
            "the load",
            display_unit="N*m",
            symbol="T_a",
            step="",
        ),
        Output(
            "required_slip_torque",
            "N*m",
            "max(K T_N, T_a); the target torque when target_torque is not given",
            display_unit="N*m",
            symbol="T_R",
            step="",
        ),
    )


def sizing(x: Mapping[str, Any]) -> dict[str, Any]:
    """Rated, start and required slip torque from the drive inputs; {} without a drive.

    Floats or arrays (a float for a single design).
    """
    if x["drive_torque"] is not None:
        rated: Any = _scalar_or_array(x["drive_torque"])
    elif x["drive_power"] is not None and x["drive_speed"] is not None:
        rated = _scalar_or_array(cl_rated_torque(x["drive_power"], x["drive_speed"]))
    else:
        return {}
    out: dict[str, Any] = {"rated_drive_torque": rated}
    start: Any = 0.0
    if all(x[k] is not None for k in ("drive_start_torque", "drive_inertia", "load_inertia")):
        start = _scalar_or_array(
            cl_acceleration_torque(x["drive_start_torque"], x["drive_inertia"], x["load_inertia"])
        )
        out["start_torque"] = start
    out["required_slip_torque"] = _scalar_or_array(
        cl_required_slip_torque(rated, x["service_factor"], start)
    )
    return out


# --------------------------------------------------------------------------
# The setting as lines (helical springs), for one design or many
# --------------------------------------------------------------------------


class SettingGrid:
    """The characteristic of a helical spring as lines in the nut setting δ, for a study.

    With the balls at grid point k of :func:`characteristic` the spring is compressed
    by δ + L_k(δ), L_k = p_k δ + q_k (p_k = 1 from the rim on when the lift is the
    setting itself, ``ball_lift`` absent; else 0), and the torque is T_k = G_k c (δ + L_k),
    G_k = s D0/(2 tan(β_k − ρ)), c the spring rate. Every T_k rises with δ, so the peak
    torque reaches a target T first at δ* = min_k (T/(G_k c) − q_k)/(1 + p_k): the root
    :func:`solve_setting` brackets and refines point by point. On the flank the lines
    lie below the rim's (same G, less compression), so only the rim on counts.
    """

    def __init__(self, x: Mapping[str, Any]) -> None:
        given = x["ball_lift"] is not None
        # from the rim on (the flank's lines lie below the rim's): q_k, the lift at δ = 0
        self.q, beta = lift_points(
            x["ball_lift"] if given else 0.0, x["ball_diameter"], _ride(x), POINTS, True
        )
        self.share = 1.0 if given else 0.5  # 1/(1 + p)
        gain = _gain_at(x, beta)
        # the lines rise with δ only where every push is positive and finite
        self.regular = np.all(np.isfinite(gain) & (gain > 0.0), axis=-1)
        self.inverse_gain = 1.0 / gain

    def setting(self, rate: Any, target: Any, upper: Any) -> Any:
        """δ* for the target peak torque, NaN where none in [0, upper] gives it."""
        compression = (np.asarray(target, float) / np.asarray(rate, float))[..., None]
        delta = np.min(compression * self.inverse_gain - self.q, axis=-1) * self.share
        return np.where((delta >= 0.0) & (delta <= upper), delta, np.nan)
