from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.clutch_ball_study_request_clutch_ball_study_base_flank_construction_type_0 import (
    ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0,
)
from ..models.clutch_ball_study_request_clutch_ball_study_base_spring_arrangement_type_0 import (
    ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0,
)
from ..models.clutch_ball_study_request_clutch_ball_study_base_spring_material_type_0 import (
    ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0,
)
from ..models.clutch_ball_study_request_clutch_ball_study_base_spring_seating_type_0 import (
    ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0,
)
from ..models.clutch_ball_study_request_clutch_ball_study_base_spring_type_type_0 import (
    ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0,
)
from ..models.clutch_ball_study_request_clutch_ball_study_base_stress_correction_type_0 import (
    ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="ClutchBallStudyRequestClutchBallStudyBase")


@_attrs_define
class ClutchBallStudyRequestClutchBallStudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        ball_circle_diameter (float | str | Unset): D0, diameter of the circle of ball centres [001, eq. 1]
        ball_count (int | str | Unset): i, number of balls [001, eq. 1]
        ball_diameter (float | str | Unset): d, ball diameter; the groove depth (= Δ in the source) is checked against
            d/2 [001, text after eq. 1]
        groove_angle (float | str | Unset): α, flank angle of the grooves; F_a = F_t tan α [001, eq. 1]; the source
            recommends 20…70°
        load_factor (float | None | str | Unset): K_r, load non-uniformity factor between the balls, 0.85…0.9 [001, eq.
            1] Default: 0.85.
        flank_friction (float | None | str | Unset): f, Coulomb friction between ball and flank; the axial push becomes
            F_t tan(α − atan f); 0 is the paper's frictionless case [001, eq. 3] Default: 0.0.
        spring_wire_diameter (float | None | str | Unset): d0, wire diameter of the helical spring [001, eq. 2]
        spring_mean_diameter (float | None | str | Unset): D, mean coil diameter of the helical spring [001, eq. 2]
        spring_active_coils (float | None | str | Unset): i_p, number of active coils of the helical spring [001, eq. 2]
        spring_deflection (float | str | Unset): Δ, spring compression with the balls seated (the nut setting); the
            paper also takes it as the groove depth [001, eq. 2], which ball_lift separates
        shear_modulus (float | None | str | Unset): G, shear modulus of the spring wire; 8·10⁴ MPa for steel [001, eq.
            2] Default: 80000000000.0.
        spring_arrangement (ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0 | None | Unset): 'common':
            one spring presses all balls through the disk (the paper's fig. 1), T = D0 F/(2 tan(α−ρ)); 'per_ball': each ball
            has its own spring, T = K_r D0 i F/(2 tan(α−ρ)), the paper's published formula [001, eq. 3] Default:
            ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0.COMMON.
        torque (float | None | str | Unset): optional: torque at which to give the ball forces (instead of at the limit)
        allowable_shear_stress (float | None | str | Unset): allowable wire shear stress, compared with the stress
            corrected by stress_correction (Wahl or Bergsträsser, EN 13906-1); optional, checked when given
        ball_lift (float | None | str | Unset): h, rise of the ball (and of the pressure disk) along the flank from
            seated to the groove's rim; the ball then rolls over the rim, rising (d/2)(1 − sin α) more. Absent: the paper's
            groove depth, equal to the spring deflection Δ
        driving_groove_angle (float | None | str | Unset): α′, flank angle of the driving half-coupling's groove [001,
            fig. 6]; absent: the driving half pushes the ball circumferentially, as eq. 1 assumes. Given, flank_construction
            says how the two flanks push: a free ball rides the flatter flank, F_a/F_t = max(tan(α′ − ρ), tan(α − ρ)); under
            a pressure disc it climbs both, F_a/F_t = tan(α′ − ρ) + tan(α − ρ)
        flank_construction (ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0 | None | Unset): with
            driving_groove_angle: 'free_ball', a free ball between the grooved driving half and the spring-loaded grooved
            half, riding the flank that separates them least, F_a/F_t = max(tan(α′ − ρ), tan(α − ρ)) (never under-reports
            the slip torque); 'pressure_disc', axially fixed halves whose flanks both lift the ball and a separate pressure
            disc, F_a/F_t = tan(α′ − ρ) + tan(α − ρ) (virtual work) Default:
            ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0.FREE_BALL.
        face_friction (float | None | str | Unset): μ_f, effective friction of the balls riding on the end face once
            disengaged (≈ 0.002 free rolling … 0.1 sliding); gives the residual torque
        spring_type (ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0 | None | Unset): 'helical' (the paper's
            spring, [001, eq. 2]) or 'disc' (a stack of disc springs to DIN EN 16983) Default:
            ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0.HELICAL.
        spring_material (ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0 | None | Unset): helical spring
            wire: 'custom' (give shear_modulus and allowable_shear_stress) or EN 10270-1 SH/DH, 1.4310 (EN 10270-3): G and
            the permissible τ = 0.5 R_m(d) from the tables Default:
            ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0.CUSTOM.
        spring_elastic_modulus (float | None | str | Unset): E of a custom helical spring's wire, used only for its
            buckling (EN 13906-1); absent: E = 2 G (1 + ν) with ν = 0.3, i.e. 2.6 G (208 GPa at G = 80 GPa; EN 13906-1 gives
            206 GPa for spring steel, 185 GPa for 1.4310). Must lie within 2 G … 3 G (Poisson's ratio 0…0.5). A chosen
            spring_material's E overrides it
        stress_correction (ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0 | None | Unset): stress-
            correction factor of the helical spring: Wahl or Bergsträsser (EN 13906-1) Default:
            ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0.WAHL.
        spring_free_length (float | None | str | Unset): L0, free length of the helical spring; given, the solid length
            with its minimum gap S_a and buckling are checked (EN 13906-1)
        spring_seating (ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0 | None | Unset): end seating of the
            helical spring for buckling: fixed_fixed (ν = 0.5, parallel ground ends on nut and disk), fixed_hinged (0.7),
            hinged_hinged (1), fixed_free (2) Default:
            ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0.FIXED_FIXED.
        disc_outer_diameter (float | None | str | Unset): De, outer diameter of the disc springs
        disc_inner_diameter (float | None | str | Unset): Di, inner diameter of the disc springs
        disc_thickness (float | None | str | Unset): t, thickness of one disc
        disc_cone_height (float | None | str | Unset): h0, free cone height of one disc (free height t + h0); h0/t > √2
            gives a falling force
        disc_series (int | None | str | Unset): number of discs (or packs) in series, alternately facing; the stack
            deflection is this times one disc's Default: 1.
        disc_parallel (int | None | str | Unset): number of discs nested in parallel in each pack; the force is this
            times one disc's Default: 1.
        disc_friction (float | None | str | Unset): w_M, friction factor between nested discs (0.02…0.03 lubricated),
            DIN EN 16983; raises the force while the balls climb Default: 0.0.
        disc_elastic_modulus (float | None | str | Unset): E of the disc spring steel Default: 206000000000.0.
        disc_yield_strength (float | None | str | Unset): static limit of σ_OM (the disc's yield strength, 1400…1600 MPa
            for C60S, 51CrV4), DIN EN 16983 Default: 1400000000.0.
    """

    ball_circle_diameter: float | str | Unset = UNSET
    ball_count: int | str | Unset = UNSET
    ball_diameter: float | str | Unset = UNSET
    groove_angle: float | str | Unset = UNSET
    load_factor: float | None | str | Unset = 0.85
    flank_friction: float | None | str | Unset = 0.0
    spring_wire_diameter: float | None | str | Unset = UNSET
    spring_mean_diameter: float | None | str | Unset = UNSET
    spring_active_coils: float | None | str | Unset = UNSET
    spring_deflection: float | str | Unset = UNSET
    shear_modulus: float | None | str | Unset = 80000000000.0
    spring_arrangement: ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0 | None | Unset = (
        ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0.COMMON
    )
    torque: float | None | str | Unset = UNSET
    allowable_shear_stress: float | None | str | Unset = UNSET
    ball_lift: float | None | str | Unset = UNSET
    driving_groove_angle: float | None | str | Unset = UNSET
    flank_construction: ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0 | None | Unset = (
        ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0.FREE_BALL
    )
    face_friction: float | None | str | Unset = UNSET
    spring_type: ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0 | None | Unset = (
        ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0.HELICAL
    )
    spring_material: ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0 | None | Unset = (
        ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0.CUSTOM
    )
    spring_elastic_modulus: float | None | str | Unset = UNSET
    stress_correction: ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0 | None | Unset = (
        ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0.WAHL
    )
    spring_free_length: float | None | str | Unset = UNSET
    spring_seating: ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0 | None | Unset = (
        ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0.FIXED_FIXED
    )
    disc_outer_diameter: float | None | str | Unset = UNSET
    disc_inner_diameter: float | None | str | Unset = UNSET
    disc_thickness: float | None | str | Unset = UNSET
    disc_cone_height: float | None | str | Unset = UNSET
    disc_series: int | None | str | Unset = 1
    disc_parallel: int | None | str | Unset = 1
    disc_friction: float | None | str | Unset = 0.0
    disc_elastic_modulus: float | None | str | Unset = 206000000000.0
    disc_yield_strength: float | None | str | Unset = 1400000000.0

    def to_dict(self) -> dict[str, Any]:
        ball_circle_diameter: float | str | Unset
        if isinstance(self.ball_circle_diameter, Unset):
            ball_circle_diameter = UNSET
        else:
            ball_circle_diameter = self.ball_circle_diameter

        ball_count: int | str | Unset
        if isinstance(self.ball_count, Unset):
            ball_count = UNSET
        else:
            ball_count = self.ball_count

        ball_diameter: float | str | Unset
        if isinstance(self.ball_diameter, Unset):
            ball_diameter = UNSET
        else:
            ball_diameter = self.ball_diameter

        groove_angle: float | str | Unset
        if isinstance(self.groove_angle, Unset):
            groove_angle = UNSET
        else:
            groove_angle = self.groove_angle

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

        spring_wire_diameter: float | None | str | Unset
        if isinstance(self.spring_wire_diameter, Unset):
            spring_wire_diameter = UNSET
        else:
            spring_wire_diameter = self.spring_wire_diameter

        spring_mean_diameter: float | None | str | Unset
        if isinstance(self.spring_mean_diameter, Unset):
            spring_mean_diameter = UNSET
        else:
            spring_mean_diameter = self.spring_mean_diameter

        spring_active_coils: float | None | str | Unset
        if isinstance(self.spring_active_coils, Unset):
            spring_active_coils = UNSET
        else:
            spring_active_coils = self.spring_active_coils

        spring_deflection: float | str | Unset
        if isinstance(self.spring_deflection, Unset):
            spring_deflection = UNSET
        else:
            spring_deflection = self.spring_deflection

        shear_modulus: float | None | str | Unset
        if isinstance(self.shear_modulus, Unset):
            shear_modulus = UNSET
        else:
            shear_modulus = self.shear_modulus

        spring_arrangement: None | str | Unset
        if isinstance(self.spring_arrangement, Unset):
            spring_arrangement = UNSET
        elif isinstance(self.spring_arrangement, ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0):
            spring_arrangement = self.spring_arrangement.value
        else:
            spring_arrangement = self.spring_arrangement

        torque: float | None | str | Unset
        if isinstance(self.torque, Unset):
            torque = UNSET
        else:
            torque = self.torque

        allowable_shear_stress: float | None | str | Unset
        if isinstance(self.allowable_shear_stress, Unset):
            allowable_shear_stress = UNSET
        else:
            allowable_shear_stress = self.allowable_shear_stress

        ball_lift: float | None | str | Unset
        if isinstance(self.ball_lift, Unset):
            ball_lift = UNSET
        else:
            ball_lift = self.ball_lift

        driving_groove_angle: float | None | str | Unset
        if isinstance(self.driving_groove_angle, Unset):
            driving_groove_angle = UNSET
        else:
            driving_groove_angle = self.driving_groove_angle

        flank_construction: None | str | Unset
        if isinstance(self.flank_construction, Unset):
            flank_construction = UNSET
        elif isinstance(self.flank_construction, ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0):
            flank_construction = self.flank_construction.value
        else:
            flank_construction = self.flank_construction

        face_friction: float | None | str | Unset
        if isinstance(self.face_friction, Unset):
            face_friction = UNSET
        else:
            face_friction = self.face_friction

        spring_type: None | str | Unset
        if isinstance(self.spring_type, Unset):
            spring_type = UNSET
        elif isinstance(self.spring_type, ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0):
            spring_type = self.spring_type.value
        else:
            spring_type = self.spring_type

        spring_material: None | str | Unset
        if isinstance(self.spring_material, Unset):
            spring_material = UNSET
        elif isinstance(self.spring_material, ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0):
            spring_material = self.spring_material.value
        else:
            spring_material = self.spring_material

        spring_elastic_modulus: float | None | str | Unset
        if isinstance(self.spring_elastic_modulus, Unset):
            spring_elastic_modulus = UNSET
        else:
            spring_elastic_modulus = self.spring_elastic_modulus

        stress_correction: None | str | Unset
        if isinstance(self.stress_correction, Unset):
            stress_correction = UNSET
        elif isinstance(self.stress_correction, ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0):
            stress_correction = self.stress_correction.value
        else:
            stress_correction = self.stress_correction

        spring_free_length: float | None | str | Unset
        if isinstance(self.spring_free_length, Unset):
            spring_free_length = UNSET
        else:
            spring_free_length = self.spring_free_length

        spring_seating: None | str | Unset
        if isinstance(self.spring_seating, Unset):
            spring_seating = UNSET
        elif isinstance(self.spring_seating, ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0):
            spring_seating = self.spring_seating.value
        else:
            spring_seating = self.spring_seating

        disc_outer_diameter: float | None | str | Unset
        if isinstance(self.disc_outer_diameter, Unset):
            disc_outer_diameter = UNSET
        else:
            disc_outer_diameter = self.disc_outer_diameter

        disc_inner_diameter: float | None | str | Unset
        if isinstance(self.disc_inner_diameter, Unset):
            disc_inner_diameter = UNSET
        else:
            disc_inner_diameter = self.disc_inner_diameter

        disc_thickness: float | None | str | Unset
        if isinstance(self.disc_thickness, Unset):
            disc_thickness = UNSET
        else:
            disc_thickness = self.disc_thickness

        disc_cone_height: float | None | str | Unset
        if isinstance(self.disc_cone_height, Unset):
            disc_cone_height = UNSET
        else:
            disc_cone_height = self.disc_cone_height

        disc_series: int | None | str | Unset
        if isinstance(self.disc_series, Unset):
            disc_series = UNSET
        else:
            disc_series = self.disc_series

        disc_parallel: int | None | str | Unset
        if isinstance(self.disc_parallel, Unset):
            disc_parallel = UNSET
        else:
            disc_parallel = self.disc_parallel

        disc_friction: float | None | str | Unset
        if isinstance(self.disc_friction, Unset):
            disc_friction = UNSET
        else:
            disc_friction = self.disc_friction

        disc_elastic_modulus: float | None | str | Unset
        if isinstance(self.disc_elastic_modulus, Unset):
            disc_elastic_modulus = UNSET
        else:
            disc_elastic_modulus = self.disc_elastic_modulus

        disc_yield_strength: float | None | str | Unset
        if isinstance(self.disc_yield_strength, Unset):
            disc_yield_strength = UNSET
        else:
            disc_yield_strength = self.disc_yield_strength

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if ball_circle_diameter is not UNSET:
            field_dict["ball_circle_diameter"] = ball_circle_diameter
        if ball_count is not UNSET:
            field_dict["ball_count"] = ball_count
        if ball_diameter is not UNSET:
            field_dict["ball_diameter"] = ball_diameter
        if groove_angle is not UNSET:
            field_dict["groove_angle"] = groove_angle
        if load_factor is not UNSET:
            field_dict["load_factor"] = load_factor
        if flank_friction is not UNSET:
            field_dict["flank_friction"] = flank_friction
        if spring_wire_diameter is not UNSET:
            field_dict["spring_wire_diameter"] = spring_wire_diameter
        if spring_mean_diameter is not UNSET:
            field_dict["spring_mean_diameter"] = spring_mean_diameter
        if spring_active_coils is not UNSET:
            field_dict["spring_active_coils"] = spring_active_coils
        if spring_deflection is not UNSET:
            field_dict["spring_deflection"] = spring_deflection
        if shear_modulus is not UNSET:
            field_dict["shear_modulus"] = shear_modulus
        if spring_arrangement is not UNSET:
            field_dict["spring_arrangement"] = spring_arrangement
        if torque is not UNSET:
            field_dict["torque"] = torque
        if allowable_shear_stress is not UNSET:
            field_dict["allowable_shear_stress"] = allowable_shear_stress
        if ball_lift is not UNSET:
            field_dict["ball_lift"] = ball_lift
        if driving_groove_angle is not UNSET:
            field_dict["driving_groove_angle"] = driving_groove_angle
        if flank_construction is not UNSET:
            field_dict["flank_construction"] = flank_construction
        if face_friction is not UNSET:
            field_dict["face_friction"] = face_friction
        if spring_type is not UNSET:
            field_dict["spring_type"] = spring_type
        if spring_material is not UNSET:
            field_dict["spring_material"] = spring_material
        if spring_elastic_modulus is not UNSET:
            field_dict["spring_elastic_modulus"] = spring_elastic_modulus
        if stress_correction is not UNSET:
            field_dict["stress_correction"] = stress_correction
        if spring_free_length is not UNSET:
            field_dict["spring_free_length"] = spring_free_length
        if spring_seating is not UNSET:
            field_dict["spring_seating"] = spring_seating
        if disc_outer_diameter is not UNSET:
            field_dict["disc_outer_diameter"] = disc_outer_diameter
        if disc_inner_diameter is not UNSET:
            field_dict["disc_inner_diameter"] = disc_inner_diameter
        if disc_thickness is not UNSET:
            field_dict["disc_thickness"] = disc_thickness
        if disc_cone_height is not UNSET:
            field_dict["disc_cone_height"] = disc_cone_height
        if disc_series is not UNSET:
            field_dict["disc_series"] = disc_series
        if disc_parallel is not UNSET:
            field_dict["disc_parallel"] = disc_parallel
        if disc_friction is not UNSET:
            field_dict["disc_friction"] = disc_friction
        if disc_elastic_modulus is not UNSET:
            field_dict["disc_elastic_modulus"] = disc_elastic_modulus
        if disc_yield_strength is not UNSET:
            field_dict["disc_yield_strength"] = disc_yield_strength

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_ball_circle_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        ball_circle_diameter = _parse_ball_circle_diameter(d.pop("ball_circle_diameter", UNSET))

        def _parse_ball_count(data: object) -> int | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(int | str | Unset, data)

        ball_count = _parse_ball_count(d.pop("ball_count", UNSET))

        def _parse_ball_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        ball_diameter = _parse_ball_diameter(d.pop("ball_diameter", UNSET))

        def _parse_groove_angle(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        groove_angle = _parse_groove_angle(d.pop("groove_angle", UNSET))

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

        def _parse_spring_wire_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spring_wire_diameter = _parse_spring_wire_diameter(d.pop("spring_wire_diameter", UNSET))

        def _parse_spring_mean_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spring_mean_diameter = _parse_spring_mean_diameter(d.pop("spring_mean_diameter", UNSET))

        def _parse_spring_active_coils(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spring_active_coils = _parse_spring_active_coils(d.pop("spring_active_coils", UNSET))

        def _parse_spring_deflection(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        spring_deflection = _parse_spring_deflection(d.pop("spring_deflection", UNSET))

        def _parse_shear_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shear_modulus = _parse_shear_modulus(d.pop("shear_modulus", UNSET))

        def _parse_spring_arrangement(
            data: object,
        ) -> ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_arrangement_type_0 = ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0(data)

                return spring_arrangement_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0 | None | Unset, data)

        spring_arrangement = _parse_spring_arrangement(d.pop("spring_arrangement", UNSET))

        def _parse_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        torque = _parse_torque(d.pop("torque", UNSET))

        def _parse_allowable_shear_stress(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        allowable_shear_stress = _parse_allowable_shear_stress(d.pop("allowable_shear_stress", UNSET))

        def _parse_ball_lift(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        ball_lift = _parse_ball_lift(d.pop("ball_lift", UNSET))

        def _parse_driving_groove_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        driving_groove_angle = _parse_driving_groove_angle(d.pop("driving_groove_angle", UNSET))

        def _parse_flank_construction(
            data: object,
        ) -> ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                flank_construction_type_0 = ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0(data)

                return flank_construction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0 | None | Unset, data)

        flank_construction = _parse_flank_construction(d.pop("flank_construction", UNSET))

        def _parse_face_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        face_friction = _parse_face_friction(d.pop("face_friction", UNSET))

        def _parse_spring_type(data: object) -> ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_type_type_0 = ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0(data)

                return spring_type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0 | None | Unset, data)

        spring_type = _parse_spring_type(d.pop("spring_type", UNSET))

        def _parse_spring_material(
            data: object,
        ) -> ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_material_type_0 = ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0(data)

                return spring_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchBallStudyRequestClutchBallStudyBaseSpringMaterialType0 | None | Unset, data)

        spring_material = _parse_spring_material(d.pop("spring_material", UNSET))

        def _parse_spring_elastic_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spring_elastic_modulus = _parse_spring_elastic_modulus(d.pop("spring_elastic_modulus", UNSET))

        def _parse_stress_correction(
            data: object,
        ) -> ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                stress_correction_type_0 = ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0(data)

                return stress_correction_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0 | None | Unset, data)

        stress_correction = _parse_stress_correction(d.pop("stress_correction", UNSET))

        def _parse_spring_free_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spring_free_length = _parse_spring_free_length(d.pop("spring_free_length", UNSET))

        def _parse_spring_seating(
            data: object,
        ) -> ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_seating_type_0 = ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0(data)

                return spring_seating_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ClutchBallStudyRequestClutchBallStudyBaseSpringSeatingType0 | None | Unset, data)

        spring_seating = _parse_spring_seating(d.pop("spring_seating", UNSET))

        def _parse_disc_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_outer_diameter = _parse_disc_outer_diameter(d.pop("disc_outer_diameter", UNSET))

        def _parse_disc_inner_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_inner_diameter = _parse_disc_inner_diameter(d.pop("disc_inner_diameter", UNSET))

        def _parse_disc_thickness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_thickness = _parse_disc_thickness(d.pop("disc_thickness", UNSET))

        def _parse_disc_cone_height(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_cone_height = _parse_disc_cone_height(d.pop("disc_cone_height", UNSET))

        def _parse_disc_series(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        disc_series = _parse_disc_series(d.pop("disc_series", UNSET))

        def _parse_disc_parallel(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        disc_parallel = _parse_disc_parallel(d.pop("disc_parallel", UNSET))

        def _parse_disc_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_friction = _parse_disc_friction(d.pop("disc_friction", UNSET))

        def _parse_disc_elastic_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_elastic_modulus = _parse_disc_elastic_modulus(d.pop("disc_elastic_modulus", UNSET))

        def _parse_disc_yield_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        disc_yield_strength = _parse_disc_yield_strength(d.pop("disc_yield_strength", UNSET))

        clutch_ball_study_request_clutch_ball_study_base = cls(
            ball_circle_diameter=ball_circle_diameter,
            ball_count=ball_count,
            ball_diameter=ball_diameter,
            groove_angle=groove_angle,
            load_factor=load_factor,
            flank_friction=flank_friction,
            spring_wire_diameter=spring_wire_diameter,
            spring_mean_diameter=spring_mean_diameter,
            spring_active_coils=spring_active_coils,
            spring_deflection=spring_deflection,
            shear_modulus=shear_modulus,
            spring_arrangement=spring_arrangement,
            torque=torque,
            allowable_shear_stress=allowable_shear_stress,
            ball_lift=ball_lift,
            driving_groove_angle=driving_groove_angle,
            flank_construction=flank_construction,
            face_friction=face_friction,
            spring_type=spring_type,
            spring_material=spring_material,
            spring_elastic_modulus=spring_elastic_modulus,
            stress_correction=stress_correction,
            spring_free_length=spring_free_length,
            spring_seating=spring_seating,
            disc_outer_diameter=disc_outer_diameter,
            disc_inner_diameter=disc_inner_diameter,
            disc_thickness=disc_thickness,
            disc_cone_height=disc_cone_height,
            disc_series=disc_series,
            disc_parallel=disc_parallel,
            disc_friction=disc_friction,
            disc_elastic_modulus=disc_elastic_modulus,
            disc_yield_strength=disc_yield_strength,
        )

        return clutch_ball_study_request_clutch_ball_study_base
