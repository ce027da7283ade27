from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.clutch_spring_design_request_disc_series_type_0 import ClutchSpringDesignRequestDiscSeriesType0
from ..models.clutch_spring_design_request_fidelity_type_0 import ClutchSpringDesignRequestFidelityType0
from ..models.clutch_spring_design_request_flank_construction_type_0 import (
    ClutchSpringDesignRequestFlankConstructionType0,
)
from ..models.clutch_spring_design_request_objective_type_0 import ClutchSpringDesignRequestObjectiveType0
from ..models.clutch_spring_design_request_outputs_type_0_item import ClutchSpringDesignRequestOutputsType0Item
from ..models.clutch_spring_design_request_spring_arrangement_type_0 import (
    ClutchSpringDesignRequestSpringArrangementType0,
)
from ..models.clutch_spring_design_request_spring_kind_type_0 import ClutchSpringDesignRequestSpringKindType0
from ..models.clutch_spring_design_request_spring_material_type_0 import ClutchSpringDesignRequestSpringMaterialType0
from ..models.clutch_spring_design_request_spring_seating_type_0 import ClutchSpringDesignRequestSpringSeatingType0
from ..types import UNSET, Unset

T = TypeVar("T", bound="ClutchSpringDesignRequest")


@_attrs_define
class ClutchSpringDesignRequest:
    """
    Attributes:
        target_torque (float | str): T, the slipping torque to set [001, eq. 1–3]
        ball_circle_diameter (float | str): D0, diameter of the circle of ball centres [001, eq. 1]
        ball_count (int | str): i, number of balls [001, eq. 1]
        ball_diameter (float | str): d, ball diameter; the groove depth (= Δ in the source) is checked against d/2 [001,
            text after eq. 1]
        groove_angle (float | str): α, flank angle of the grooves; F_a = F_t tan α [001, eq. 1]; the source recommends
            20…70°
        ball_lift (float | str): h, rise of the ball (and the pressure disk) along the flank from seated to the groove's
            rim; the stroke adds the rise over the rim
        max_outer_diameter (float | str): D_e,max, largest outer diameter of the spring (the bore it sits in)
        max_set_length (float | str): L_1, the pocket's length: the spring's length at the setting (its free length is
            chosen so that it sits at this length)
        load_factor (float | None | str | Unset): K_r, load non-uniformity factor between the balls, 0.85…0.9 [001, eq.
            1] Default: 0.85.
        flank_friction (float | None | str | Unset): f, Coulomb friction between ball and flank; the axial push becomes
            F_t tan(α − atan f); 0 is the paper's frictionless case [001, eq. 3] Default: 0.0.
        spring_arrangement (ClutchSpringDesignRequestSpringArrangementType0 | None | Unset): 'common': one spring
            presses all balls through the disk (the paper's fig. 1), T = D0 F/(2 tan(α−ρ)); 'per_ball': each ball has its
            own spring, T = K_r D0 i F/(2 tan(α−ρ)), the paper's published formula [001, eq. 3] Default:
            ClutchSpringDesignRequestSpringArrangementType0.COMMON.
        driving_groove_angle (float | None | str | Unset): α′, flank angle of the driving half-coupling's groove [001,
            fig. 6]; absent: the driving half pushes the ball circumferentially, as eq. 1 assumes. Given, flank_construction
            says how the two flanks push: a free ball rides the flatter flank, F_a/F_t = max(tan(α′ − ρ), tan(α − ρ)); under
            a pressure disc it climbs both, F_a/F_t = tan(α′ − ρ) + tan(α − ρ)
        flank_construction (ClutchSpringDesignRequestFlankConstructionType0 | None | Unset): with driving_groove_angle:
            'free_ball', a free ball between the grooved driving half and the spring-loaded grooved half, riding the flank
            that separates them least, F_a/F_t = max(tan(α′ − ρ), tan(α − ρ)) (never under-reports the slip torque);
            'pressure_disc', axially fixed halves whose flanks both lift the ball and a separate pressure disc, F_a/F_t =
            tan(α′ − ρ) + tan(α − ρ) (virtual work) Default: ClutchSpringDesignRequestFlankConstructionType0.FREE_BALL.
        min_inner_diameter (float | None | str | Unset): D_i,min, smallest inner diameter of the spring (the shaft it
            sits on); 0 for none Default: 0.0.
        spring_kind (ClutchSpringDesignRequestSpringKindType0 | None | Unset): 'helical': a helical compression spring
            (EN 13906-1); 'disc_pack': a stack of DIN 2093 standard disc springs, n nested in parallel in each of i packs in
            series (DIN EN 16983) Default: ClutchSpringDesignRequestSpringKindType0.HELICAL.
        spring_material (ClutchSpringDesignRequestSpringMaterialType0 | None | Unset): spring wire: EN 10270-1 SH or DH,
            or 1.4310 (EN 10270-3); G, E, ρ and τ_zul = 0.5 R_m(d) from the tables Default:
            ClutchSpringDesignRequestSpringMaterialType0.EN10270_1_DH.
        spring_seating (ClutchSpringDesignRequestSpringSeatingType0 | None | Unset): end seating for buckling:
            fixed_fixed (ν = 0.5, parallel ground ends), fixed_hinged (0.7), hinged_hinged (1), fixed_free (2) Default:
            ClutchSpringDesignRequestSpringSeatingType0.FIXED_FIXED.
        dynamic_load (bool | None | Unset): the minimum gap sum S_a × 1.5 (EN 13906-1, dynamic load) Default: False.
        objective (ClutchSpringDesignRequestObjectiveType0 | None | Unset): 'thinnest': the thinnest wire that passes
            every check, with the fewest coils that keep the stress, and of its springs the lightest (a larger force never
            gets a thinner wire); a disc pack: the fewest discs, then the smallest; 'margin': the most coils (packs in
            series) the pocket allows, the most stress margin at full stroke Default:
            ClutchSpringDesignRequestObjectiveType0.THINNEST.
        disc_series (ClutchSpringDesignRequestDiscSeriesType0 | None | Unset): disc pack: the DIN 2093 series to choose
            from: A (stiff, h0/t ≈ 0.4), B (h0/t ≈ 0.75), or any (the rows a public reprint of the standard's table
            confirms) Default: ClutchSpringDesignRequestDiscSeriesType0.ANY.
        disc_yield_strength (float | None | str | Unset): disc pack: R_e, the limit of |σ_OM| at full stroke (DIN EN
            16983, static or moderate fatigue load; about 1400…1600 MPa for C60S and 51CrV4) Default: 1400000000.0.
        fidelity (ClutchSpringDesignRequestFidelityType0 | None | Unset): 'auto' picks the cheapest rung whose error
            estimate meets `tolerance`; or name a rung. Absent: 'auto', or 'auto' when a tolerance is given
        tolerance (float | None | Unset): relative tolerance for 'auto' (0.01)
        outputs (list[ClutchSpringDesignRequestOutputsType0Item] | None | Unset): compute only these outputs and series
            (every scalar output when absent)
        series (bool | Unset): true: compute and send every series too (absent/false: only the series named in
            `outputs`) Default: False.
    """

    target_torque: float | str
    ball_circle_diameter: float | str
    ball_count: int | str
    ball_diameter: float | str
    groove_angle: float | str
    ball_lift: float | str
    max_outer_diameter: float | str
    max_set_length: float | str
    load_factor: float | None | str | Unset = 0.85
    flank_friction: float | None | str | Unset = 0.0
    spring_arrangement: ClutchSpringDesignRequestSpringArrangementType0 | None | Unset = (
        ClutchSpringDesignRequestSpringArrangementType0.COMMON
    )
    driving_groove_angle: float | None | str | Unset = UNSET
    flank_construction: ClutchSpringDesignRequestFlankConstructionType0 | None | Unset = (
        ClutchSpringDesignRequestFlankConstructionType0.FREE_BALL
    )
    min_inner_diameter: float | None | str | Unset = 0.0
    spring_kind: ClutchSpringDesignRequestSpringKindType0 | None | Unset = (
        ClutchSpringDesignRequestSpringKindType0.HELICAL
    )
    spring_material: ClutchSpringDesignRequestSpringMaterialType0 | None | Unset = (
        ClutchSpringDesignRequestSpringMaterialType0.EN10270_1_DH
    )
    spring_seating: ClutchSpringDesignRequestSpringSeatingType0 | None | Unset = (
        ClutchSpringDesignRequestSpringSeatingType0.FIXED_FIXED
    )
    dynamic_load: bool | None | Unset = False
    objective: ClutchSpringDesignRequestObjectiveType0 | None | Unset = ClutchSpringDesignRequestObjectiveType0.THINNEST
    disc_series: ClutchSpringDesignRequestDiscSeriesType0 | None | Unset = ClutchSpringDesignRequestDiscSeriesType0.ANY
    disc_yield_strength: float | None | str | Unset = 1400000000.0
    fidelity: ClutchSpringDesignRequestFidelityType0 | None | Unset = UNSET
    tolerance: float | None | Unset = UNSET
    outputs: list[ClutchSpringDesignRequestOutputsType0Item] | None | Unset = UNSET
    series: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        target_torque: float | str
        target_torque = self.target_torque

        ball_circle_diameter: float | str
        ball_circle_diameter = self.ball_circle_diameter

        ball_count: int | str
        ball_count = self.ball_count

        ball_diameter: float | str
        ball_diameter = self.ball_diameter

        groove_angle: float | str
        groove_angle = self.groove_angle

        ball_lift: float | str
        ball_lift = self.ball_lift

        max_outer_diameter: float | str
        max_outer_diameter = self.max_outer_diameter

        max_set_length: float | str
        max_set_length = self.max_set_length

        load_factor: float | None | str | Unset
        if isinstance(self.load_factor, Unset):
            load_factor = UNSET
        else:
            load_factor = self.load_factor

        flank_friction: float | None | str | Unset
        if isinstance(self.flank_friction, Unset):
            flank_friction = UNSET
        else:
            flank_friction = self.flank_friction

        spring_arrangement: None | str | Unset
        if isinstance(self.spring_arrangement, Unset):
            spring_arrangement = UNSET
        elif isinstance(self.spring_arrangement, ClutchSpringDesignRequestSpringArrangementType0):
            spring_arrangement = self.spring_arrangement.value
        else:
            spring_arrangement = self.spring_arrangement

        driving_groove_angle: float | None | str | Unset
        if isinstance(self.driving_groove_angle, Unset):
            driving_groove_angle = UNSET
        else:
            driving_groove_angle = self.driving_groove_angle

        flank_construction: None | str | Unset
        if isinstance(self.flank_construction, Unset):
            flank_construction = UNSET
        elif isinstance(self.flank_construction, ClutchSpringDesignRequestFlankConstructionType0):
            flank_construction = self.flank_construction.value
        else:
            flank_construction = self.flank_construction

        min_inner_diameter: float | None | str | Unset
        if isinstance(self.min_inner_diameter, Unset):
            min_inner_diameter = UNSET
        else:
            min_inner_diameter = self.min_inner_diameter

        spring_kind: None | str | Unset
        if isinstance(self.spring_kind, Unset):
            spring_kind = UNSET
        elif isinstance(self.spring_kind, ClutchSpringDesignRequestSpringKindType0):
            spring_kind = self.spring_kind.value
        else:
            spring_kind = self.spring_kind

        spring_material: None | str | Unset
        if isinstance(self.spring_material, Unset):
            spring_material = UNSET
        elif isinstance(self.spring_material, ClutchSpringDesignRequestSpringMaterialType0):
            spring_material = self.spring_material.value
        else:
            spring_material = self.spring_material

        spring_seating: None | str | Unset
        if isinstance(self.spring_seating, Unset):
            spring_seating = UNSET
        elif isinstance(self.spring_seating, ClutchSpringDesignRequestSpringSeatingType0):
            spring_seating = self.spring_seating.value
        else:
            spring_seating = self.spring_seating

        dynamic_load: bool | None | Unset
        if isinstance(self.dynamic_load, Unset):
            dynamic_load = UNSET
        else:
            dynamic_load = self.dynamic_load

        objective: None | str | Unset
        if isinstance(self.objective, Unset):
            objective = UNSET
        elif isinstance(self.objective, ClutchSpringDesignRequestObjectiveType0):
            objective = self.objective.value
        else:
            objective = self.objective

        disc_series: None | str | Unset
        if isinstance(self.disc_series, Unset):
            disc_series = UNSET
        elif isinstance(self.disc_series, ClutchSpringDesignRequestDiscSeriesType0):
            disc_series = self.disc_series.value
        else:
            disc_series = self.disc_series

        disc_yield_strength: float | None | str | Unset
        if isinstance(self.disc_yield_strength, Unset):
            disc_yield_strength = UNSET
        else:
            disc_yield_strength = self.disc_yield_strength

        fidelity: None | str | Unset
        if isinstance(self.fidelity, Unset):
            fidelity = UNSET
        elif isinstance(self.fidelity, ClutchSpringDesignRequestFidelityType0):
            fidelity = self.fidelity.value
        else:
            fidelity = self.fidelity

        tolerance: float | None | Unset
        if isinstance(self.tolerance, Unset):
            tolerance = UNSET
        else:
            tolerance = self.tolerance

        outputs: list[str] | None | Unset
        if isinstance(self.outputs, Unset):
            outputs = UNSET
        elif isinstance(self.outputs, list):
            outputs = []
            for outputs_type_0_item_data in self.outputs:
                outputs_type_0_item = outputs_type_0_item_data.value
                outputs.append(outputs_type_0_item)

        else:
            outputs = self.outputs

        series = self.series

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "target_torque": target_torque,
                "ball_circle_diameter": ball_circle_diameter,
                "ball_count": ball_count,
                "ball_diameter": ball_diameter,
                "groove_angle": groove_angle,
                "ball_lift": ball_lift,
                "max_outer_diameter": max_outer_diameter,
                "max_set_length": max_set_length,
            }
        )
        if load_factor is not UNSET:
            field_dict["load_factor"] = load_factor
        if flank_friction is not UNSET:
            field_dict["flank_friction"] = flank_friction
        if spring_arrangement is not UNSET:
            field_dict["spring_arrangement"] = spring_arrangement
        if driving_groove_angle is not UNSET:
            field_dict["driving_groove_angle"] = driving_groove_angle
        if flank_construction is not UNSET:
            field_dict["flank_construction"] = flank_construction
        if min_inner_diameter is not UNSET:
            field_dict["min_inner_diameter"] = min_inner_diameter
        if spring_kind is not UNSET:
            field_dict["spring_kind"] = spring_kind
        if spring_material is not UNSET:
            field_dict["spring_material"] = spring_material
        if spring_seating is not UNSET:
            field_dict["spring_seating"] = spring_seating
        if dynamic_load is not UNSET:
            field_dict["dynamic_load"] = dynamic_load
        if objective is not UNSET:
            field_dict["objective"] = objective
        if disc_series is not UNSET:
            field_dict["disc_series"] = disc_series
        if disc_yield_strength is not UNSET:
            field_dict["disc_yield_strength"] = disc_yield_strength
        if fidelity is not UNSET:
            field_dict["fidelity"] = fidelity
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance
        if outputs is not UNSET:
            field_dict["outputs"] = outputs
        if series is not UNSET:
            field_dict["series"] = series

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_target_torque(data: object) -> float | str:
            return cast(float | str, data)

        target_torque = _parse_target_torque(d.pop("target_torque"))

        def _parse_ball_circle_diameter(data: object) -> float | str:
            return cast(float | str, data)

        ball_circle_diameter = _parse_ball_circle_diameter(d.pop("ball_circle_diameter"))

        def _parse_ball_count(data: object) -> int | str:
            return cast(int | str, data)

        ball_count = _parse_ball_count(d.pop("ball_count"))

        def _parse_ball_diameter(data: object) -> float | str:
            return cast(float | str, data)

        ball_diameter = _parse_ball_diameter(d.pop("ball_diameter"))

        def _parse_groove_angle(data: object) -> float | str:
            return cast(float | str, data)

        groove_angle = _parse_groove_angle(d.pop("groove_angle"))

        def _parse_ball_lift(data: object) -> float | str:
            return cast(float | str, data)

        ball_lift = _parse_ball_lift(d.pop("ball_lift"))

        def _parse_max_outer_diameter(data: object) -> float | str:
            return cast(float | str, data)

        max_outer_diameter = _parse_max_outer_diameter(d.pop("max_outer_diameter"))

        def _parse_max_set_length(data: object) -> float | str:
            return cast(float | str, data)

        max_set_length = _parse_max_set_length(d.pop("max_set_length"))

        def _parse_load_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        load_factor = _parse_load_factor(d.pop("load_factor", UNSET))

        def _parse_flank_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flank_friction = _parse_flank_friction(d.pop("flank_friction", UNSET))

        def _parse_spring_arrangement(data: object) -> ClutchSpringDesignRequestSpringArrangementType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_arrangement_type_0 = ClutchSpringDesignRequestSpringArrangementType0(data)

                return spring_arrangement_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestSpringArrangementType0 | None | Unset, data)

        spring_arrangement = _parse_spring_arrangement(d.pop("spring_arrangement", UNSET))

        def _parse_driving_groove_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        driving_groove_angle = _parse_driving_groove_angle(d.pop("driving_groove_angle", UNSET))

        def _parse_flank_construction(data: object) -> ClutchSpringDesignRequestFlankConstructionType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                flank_construction_type_0 = ClutchSpringDesignRequestFlankConstructionType0(data)

                return flank_construction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestFlankConstructionType0 | None | Unset, data)

        flank_construction = _parse_flank_construction(d.pop("flank_construction", UNSET))

        def _parse_min_inner_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        min_inner_diameter = _parse_min_inner_diameter(d.pop("min_inner_diameter", UNSET))

        def _parse_spring_kind(data: object) -> ClutchSpringDesignRequestSpringKindType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_kind_type_0 = ClutchSpringDesignRequestSpringKindType0(data)

                return spring_kind_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestSpringKindType0 | None | Unset, data)

        spring_kind = _parse_spring_kind(d.pop("spring_kind", UNSET))

        def _parse_spring_material(data: object) -> ClutchSpringDesignRequestSpringMaterialType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_material_type_0 = ClutchSpringDesignRequestSpringMaterialType0(data)

                return spring_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestSpringMaterialType0 | None | Unset, data)

        spring_material = _parse_spring_material(d.pop("spring_material", UNSET))

        def _parse_spring_seating(data: object) -> ClutchSpringDesignRequestSpringSeatingType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_seating_type_0 = ClutchSpringDesignRequestSpringSeatingType0(data)

                return spring_seating_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestSpringSeatingType0 | None | Unset, data)

        spring_seating = _parse_spring_seating(d.pop("spring_seating", UNSET))

        def _parse_dynamic_load(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        dynamic_load = _parse_dynamic_load(d.pop("dynamic_load", UNSET))

        def _parse_objective(data: object) -> ClutchSpringDesignRequestObjectiveType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                objective_type_0 = ClutchSpringDesignRequestObjectiveType0(data)

                return objective_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestObjectiveType0 | None | Unset, data)

        objective = _parse_objective(d.pop("objective", UNSET))

        def _parse_disc_series(data: object) -> ClutchSpringDesignRequestDiscSeriesType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                disc_series_type_0 = ClutchSpringDesignRequestDiscSeriesType0(data)

                return disc_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestDiscSeriesType0 | None | Unset, data)

        disc_series = _parse_disc_series(d.pop("disc_series", UNSET))

        def _parse_disc_yield_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_yield_strength = _parse_disc_yield_strength(d.pop("disc_yield_strength", UNSET))

        def _parse_fidelity(data: object) -> ClutchSpringDesignRequestFidelityType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                fidelity_type_0 = ClutchSpringDesignRequestFidelityType0(data)

                return fidelity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchSpringDesignRequestFidelityType0 | None | Unset, data)

        fidelity = _parse_fidelity(d.pop("fidelity", UNSET))

        def _parse_tolerance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))

        def _parse_outputs(data: object) -> list[ClutchSpringDesignRequestOutputsType0Item] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                outputs_type_0 = []
                _outputs_type_0 = data
                for outputs_type_0_item_data in _outputs_type_0:
                    outputs_type_0_item = ClutchSpringDesignRequestOutputsType0Item(outputs_type_0_item_data)

                    outputs_type_0.append(outputs_type_0_item)

                return outputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[ClutchSpringDesignRequestOutputsType0Item] | None | Unset, data)

        outputs = _parse_outputs(d.pop("outputs", UNSET))

        series = d.pop("series", UNSET)

        clutch_spring_design_request = cls(
            target_torque=target_torque,
            ball_circle_diameter=ball_circle_diameter,
            ball_count=ball_count,
            ball_diameter=ball_diameter,
            groove_angle=groove_angle,
            ball_lift=ball_lift,
            max_outer_diameter=max_outer_diameter,
            max_set_length=max_set_length,
            load_factor=load_factor,
            flank_friction=flank_friction,
            spring_arrangement=spring_arrangement,
            driving_groove_angle=driving_groove_angle,
            flank_construction=flank_construction,
            min_inner_diameter=min_inner_diameter,
            spring_kind=spring_kind,
            spring_material=spring_material,
            spring_seating=spring_seating,
            dynamic_load=dynamic_load,
            objective=objective,
            disc_series=disc_series,
            disc_yield_strength=disc_yield_strength,
            fidelity=fidelity,
            tolerance=tolerance,
            outputs=outputs,
            series=series,
        )

        return clutch_spring_design_request
