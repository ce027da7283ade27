"""The ways of controlling bolt preload the review [004] describes, with their scatter.

One record per method: what it sets (torque, angle, elongation, force or a
circumferential displacement), the preload scatter ±s it gives, the
tightening factor α_A = (1 + s)/(1 − s) that scatter implies (VDI 2230-1:2015
Table A8 defines α_A = F_M,max/F_M,min), where it fits and where it does not,
and where the number comes from.

The review gives numbers for three methods only: torque control ±30 %
(Thum and Debus, fig. 5), nut angle ±20 % and the measuring washer and ring
±10 %. For the others the scatter is the band of VDI 2230-1:2015 Table A8
for the same principle, or, where neither gives one, an assumption that the
record says is one. ``cost_rank`` orders methods by the effort they take
(1 = cheapest); it is our ordering, not the source's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .preload import nut_rotation_angle, scatter_from_tightening_factor, tightening_factor

#: Quantities a method sets; each maps to one target output of ``preload.control``.
CONTROLLED = ("torque", "angle", "elongation", "force", "displacement", "yield")


@dataclass(frozen=True)
class ControlMethod:
    """One preload-control method and what it achieves."""

    key: str
    name: str
    family: str  # "bolt" or "sucker_rod"
    controls: str  # one of CONTROLLED
    scatter: float  # ±s used in calculations (the conservative end of the band)
    scatter_band: tuple[float, float]  # (s_min, s_max) as the source gives it
    scatter_source: str
    fits: str
    does_not_fit: str
    source: str
    cost_rank: int
    assumption: bool = False

    @property
    def tightening_factor(self) -> float:
        """α_A = (1 + s)/(1 − s) at the scatter used in calculations."""
        return tightening_factor(self.scatter)

    def describe(self) -> dict[str, Any]:
        """JSON-ready record for ``GET /api/v1/preload/methods``."""
        return {
            "key": self.key,
            "name": self.name,
            "family": self.family,
            "controls": self.controls,
            "scatter": self.scatter,
            "scatter_band": list(self.scatter_band),
            "tightening_factor": self.tightening_factor,
            "tightening_factor_band": [tightening_factor(s) for s in self.scatter_band],
            "scatter_source": self.scatter_source,
            "scatter_is_assumption": self.assumption,
            "fits": self.fits,
            "does_not_fit": self.does_not_fit,
            "source": self.source,
            "cost_rank": self.cost_rank,
        }


def _band(alpha_lo: float, alpha_hi: float) -> tuple[float, float]:
    return (scatter_from_tightening_factor(alpha_lo), scatter_from_tightening_factor(alpha_hi))


_VDI_A8 = "VDI 2230-1:2015 Table A8"

METHODS: tuple[ControlMethod, ...] = (
    ControlMethod(
        key="torque_wrench",
        name="Torque (dynamometric) wrench",
        family="bolt",
        controls="torque",
        scatter=0.30,
        scatter_band=(0.30, 0.30),
        scatter_source="[004], section 'Контроль сили затягування', fig. 5 (Thum and Debus, "
        '38 bolts 5/8" at 80 N·m): ±30 %',
        fits="Most joints; the simplest indirect method; calibrated wrench, stand-checked.",
        does_not_fit="Joints whose friction is unknown or varies (coating, lubricant, "
        "re-use): the preload follows the friction, not the torque.",
        source="[004], 'Контроль сили затягування', fig. 4, 5; eq. 13–19",
        cost_rank=1,
    ),
    ControlMethod(
        key="limit_wrench",
        name="Limit (click / slip) wrench",
        family="bolt",
        controls="torque",
        scatter=0.30,
        scatter_band=(0.30, 0.30),
        scatter_source="[004]: graduated wrenches, dynamometric and limit alike, rest on "
        "the same torque–preload relation, ±30 %",
        fits="Series assembly where the operator should not read a scale; the wrench "
        "releases or signals at the set torque.",
        does_not_fit="As for the torque wrench: friction scatter passes straight into the preload.",
        source="[004], 'Контроль сили затягування' (граничні ключі)",
        cost_rank=2,
    ),
    ControlMethod(
        key="shear_off_nut",
        name="Shear-off (torque-limiting) nut",
        family="bolt",
        controls="torque",
        scatter=0.30,
        scatter_band=(0.30, 0.30),
        scatter_source="assumption: the neck breaks at a torque, so the scatter of torque "
        "control (±30 %, [004]) applies; the review gives no number",
        fits="Automated assembly without a torque tool; tamper evidence.",
        does_not_fit="Joints needing a defined preload: it is still torque control, plus "
        "the scatter of the neck's breaking torque.",
        source="[004], end of 'Контроль сили затягування'",
        cost_rank=2,
        assumption=True,
    ),
    ControlMethod(
        key="nut_angle",
        name="Nut rotation angle",
        family="bolt",
        controls="angle",
        scatter=0.20,
        scatter_band=(0.20, 0.20),
        scatter_source="[004], nut-angle paragraph: accuracy not better than ±20 %",
        fits="Long bolts; independent of friction; angle measurable to 10…15° with "
        "templates and washers (fig. 3).",
        does_not_fit="Short bolts (the angle is small and its errors large) and joints "
        "whose clamped-part compliance or snug angle φ0 is unknown.",
        source="[004], eq. 8, 9, fig. 3",
        cost_rank=2,
    ),
    ControlMethod(
        key="torque_then_angle",
        name="Torque to snug, then angle",
        family="bolt",
        controls="angle",
        scatter=scatter_from_tightening_factor(1.4),
        scatter_band=_band(1.2, 1.4),
        scatter_source=f"the review says only 'better than torque control'; band from "
        f"{_VDI_A8} (angle-controlled, experimentally determined snug torque and "
        "angle): α_A = 1.2…1.4",
        fits="Joints where the snug point must be reproducible; the preload does not "
        "depend on friction once snug.",
        does_not_fit="Without the experimental torque–angle diagram for the joint; short, "
        "stiff joints.",
        source="[004], paragraph after eq. 19",
        cost_rank=3,
    ),
    ControlMethod(
        key="torque_gradient",
        name="Torque-gradient (yield) control",
        family="bolt",
        controls="yield",
        scatter=scatter_from_tightening_factor(1.4),
        scatter_band=_band(1.2, 1.4),
        scatter_source=f"{_VDI_A8} (yield-controlled tightening): α_A = 1.2…1.4; the "
        "review gives no number",
        fits="Automated assembly with a powered nut-runner that watches dM/dφ.",
        does_not_fit="Bolts of low ductility ([004]: they must be made of highly plastic "
        "material) and bolts that must not be taken to yield (re-use).",
        source="[004], paragraph on gradient control, ref. [2]",
        cost_rank=4,
    ),
    ControlMethod(
        key="measuring_washer_ring",
        name="Measuring washer and ring",
        family="bolt",
        controls="force",
        scatter=0.10,
        scatter_band=(0.10, 0.10),
        scatter_source="[004], fig. 2b paragraph: laboratory and field tests, ±10 %; "
        "allows σ0 = 0.7 σ_T (less accurate methods: 0.4…0.5 σ_T)",
        fits="Critical joints; the ring locks when the washer has yielded by δ at the design load.",
        does_not_fit="Cost-sensitive series joints; each washer is used once.",
        source="[004], fig. 2b",
        cost_rank=4,
    ),
    ControlMethod(
        key="pneumatic_washer",
        name="Pneumatic washer gauge",
        family="bolt",
        controls="force",
        scatter=0.20,
        scatter_band=(0.10, 0.20),
        scatter_source="assumption (±10…20 %): the review cites the method [2] with no "
        "number; it senses the washer's deformation like the measuring washer",
        fits="Joints where a reusable force indication under the nut is wanted.",
        does_not_fit="Without compressed air and a calibrated washer per size.",
        source="[004], fig. 2a, ref. [2]",
        cost_rank=5,
        assumption=True,
    ),
    ControlMethod(
        key="elongation_micrometer",
        name="Bolt elongation by micrometer",
        family="bolt",
        controls="elongation",
        scatter=scatter_from_tightening_factor(1.5),
        scatter_band=_band(1.1, 1.5),
        scatter_source=f"the review: the most accurate method, no number; band from "
        f"{_VDI_A8} (mechanical elongation measurement): α_A = 1.1…1.5",
        fits="Critical joints with both bolt ends reachable: connecting rods, tie rods, "
        "compressor rotors (fig. 1a).",
        does_not_fit="Short bolts (l < 6 d stretch only 20…60 µm: add 1/3 of the nut height "
        "to the length, and the engaged length for studs) and blind holes.",
        source="[004], eq. 7, fig. 1a",
        cost_rank=4,
    ),
    ControlMethod(
        key="drilled_bolt_rod",
        name="Drilled bolt with gauge rod",
        family="bolt",
        controls="elongation",
        scatter=scatter_from_tightening_factor(1.5),
        scatter_band=_band(1.1, 1.5),
        scatter_source=f"no number in the review; band from {_VDI_A8} (mechanical "
        "elongation measurement): α_A = 1.1…1.5",
        fits="Joints checked in service as well as at assembly; rod flush with the bolt "
        "end at full preload (fig. 1b).",
        does_not_fit="Small bolts (the bore weakens them) and bolts made without the bore.",
        source="[004], fig. 1b",
        cost_rank=5,
    ),
    ControlMethod(
        key="strain_gauge",
        name="Strain gauges on the shank",
        family="bolt",
        controls="elongation",
        scatter=0.10,
        scatter_band=(0.05, 0.10),
        scatter_source="assumption (±5…10 %): neither the review nor VDI 2230 Table A8 "
        "gives a number; a calibrated gauge measures the shank strain directly",
        fits="Critical joints and tests; gauges bonded on the plain shank or cast in a "
        "central bore can stay on the part.",
        does_not_fit="Series assembly (cost, wiring); shanks without a plain section.",
        source="[004], paragraph after fig. 1",
        cost_rank=6,
        assumption=True,
    ),
    ControlMethod(
        key="ultrasound",
        name="Ultrasonic elongation measurement",
        family="bolt",
        controls="elongation",
        scatter=scatter_from_tightening_factor(1.2),
        scatter_band=_band(1.05, 1.2),
        scatter_source=f"no number in the review; band from {_VDI_A8} (elongation-"
        "controlled with ultrasound): α_A = 1.05…1.2",
        fits="Critical joints; needs only one bolt end accessible.",
        does_not_fit="Bolts without flat, parallel ends; uncalibrated bolt material.",
        source="[004], paragraph after fig. 2",
        cost_rank=7,
    ),
    ControlMethod(
        key="rod_dynamometric_wrench",
        name="Sucker rod: hand dynamometric wrench",
        family="sucker_rod",
        controls="torque",
        scatter=0.30,
        scatter_band=(0.30, 0.30),
        scatter_source="assumption by analogy with torque control in the review (±30 %); "
        "the sucker-rod section gives no number",
        fits="Sucker-rod couplings: make-up with the 600 mm handle, final tightening with "
        "the 900 mm handle (telescopic, fig. 6).",
        does_not_fit="Rods whose thread friction (dope, wear) is unknown.",
        source="[004], sucker-rod section, fig. 6",
        cost_rank=2,
        assumption=True,
    ),
    ControlMethod(
        key="rod_displacement_marks",
        name="Sucker rod: circumferential displacement marks",
        family="sucker_rod",
        controls="displacement",
        scatter=0.20,
        scatter_band=(0.20, 0.20),
        scatter_source="assumption by analogy with nut-angle control in the review "
        "(±20 %); the mark displacement is a turn angle on the coupling",
        fits="Field make-up: hand-tight, mark, turn until the mark meets the second mark "
        "(fig. 7); a brass or bronze insert keeps the mark through wear (fig. 8).",
        does_not_fit="Worn or re-cut threads (the hand-tight point moves).",
        source="[004], sucker-rod section, fig. 7, 8",
        cost_rank=1,
        assumption=True,
    ),
    ControlMethod(
        key="rod_locking_ring",
        name="Sucker rod: locking ring between coupling and rod shoulder",
        family="sucker_rod",
        controls="force",
        scatter=0.20,
        scatter_band=(0.10, 0.20),
        scatter_source="assumption (±10…20 %): the review gives no number; the ring "
        "senses the closing gap like the measuring ring",
        fits="Make-up without a torque tool: the ring turns freely until the make-up "
        "torque is reached, then it locks (fig. 9).",
        does_not_fit="Couplings without room for the ring at the cone face.",
        source="[004], sucker-rod section, fig. 9",
        cost_rank=3,
        assumption=True,
    ),
)

METHOD_KEYS: tuple[str, ...] = tuple(m.key for m in METHODS)


def get_method(key: str) -> ControlMethod:
    """The method record called ``key``.

    Examples
    --------
    >>> round(get_method("torque_wrench").tightening_factor, 3)
    1.857
    """
    for method in METHODS:
        if method.key == key:
            return method
    raise KeyError(key)


#: Snug point of torque-then-angle: the share of the final torque (and preload) at which the
#: angle count starts; ISO 5393 states its joints' angles from 10 % of the target [ISO5393].
SNUG_FRACTION = 0.10


@dataclass(frozen=True)
class TorqueThenAngle:
    """The two settings of torque-then-angle tightening and the preload at the snug point."""

    snug_preload: Any  # F_snug [N]
    snug_torque: Any  # M_snug [N*m]
    angle: Any  # θ from snug to the final preload [rad]


def torque_then_angle(
    final_preload: Any,
    torque_per_preload: Any,
    total_compliance: Any,
    pitch: Any,
    snug_fraction: Any = SNUG_FRACTION,
) -> TorqueThenAngle:
    r"""Snug torque and final angle of torque-then-angle tightening to a preload.

    .. math::
        F_{snug} = s\,F_M,\qquad M_{snug} = k\,F_{snug},\qquad
        \theta = \frac{(F_M - F_{snug})(\delta_S + \delta_P)}{P}\cdot 360°

    Parameters
    ----------
    final_preload : float or numpy array
        F_M, the preload the angle is to reach, [N]
    torque_per_preload : float or numpy array
        k = M_A/F of the torque formula (thread + bearing), at the friction assumed, [m]
    total_compliance : float or numpy array
        δ_S + δ_P, bolt plus clamped parts, [m/N]
    pitch : float or numpy array
        P, [m]
    snug_fraction : float or numpy array
        s, the share of the final preload (and torque) at the snug point, [-]

    Returns
    -------
    TorqueThenAngle
        F_snug [N], M_snug [N*m], θ [rad]

    Notes
    -----
    [004], paragraph after eq. 19: the first tightening to the "zero" position by a
    graduated tool, then the angle; the review takes both from the joint's experimental
    torque–angle diagram. Without it the snug point is taken at 10 % of the final torque,
    where ISO 5393 starts its joints' angle count [ISO5393]; the angle beyond it is
    [004, eq. 8] for the preload still to come (:func:`engine.physics.preload.nut_rotation_angle`),
    since once snug the preload rises linearly with the turn. The snug torque carries the
    friction scatter; the angle does not. All arguments may be floats or numpy arrays.

    Examples
    --------
    M12 to 40 kN, k = 1.94 mm, δ_S + δ_P = 3.33 + 0.75 µm/kN, P = 1.75 mm:

    >>> import math
    >>> t = torque_then_angle(40e3, 1.94e-3, 4.08e-9, 0.00175)
    >>> round(t.snug_preload), round(t.snug_torque, 2), round(math.degrees(t.angle), 2)
    (4000, 7.76, 30.22)
    """
    snug = snug_fraction * final_preload
    return TorqueThenAngle(
        snug,
        snug * torque_per_preload,
        nut_rotation_angle(final_preload - snug, total_compliance, pitch),
    )


def catalogue() -> list[dict[str, Any]]:
    """Every method as a JSON-ready record, cheapest first within each family."""
    ordered = sorted(METHODS, key=lambda m: (m.family != "bolt", m.cost_rank, m.key))
    return [m.describe() for m in ordered]
