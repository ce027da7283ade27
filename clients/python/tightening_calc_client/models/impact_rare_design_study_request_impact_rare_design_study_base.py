from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.impact_rare_design_study_request_impact_rare_design_study_base_roller_geometry_type_0 import (
    ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="ImpactRareDesignStudyRequestImpactRareDesignStudyBase")


@_attrs_define
class ImpactRareDesignStudyRequestImpactRareDesignStudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        flywheel_inertia (float | None | str | Unset): I_M: moment of inertia of the flywheel with half-coupling, shaft
            and striker [002, eq. 1] Default: 0.02.
        motor_torque (float | None | str | Unset): M: motor torque on the flywheel (the stall torque when a no-load
            speed is given) [002, eq. 1] Default: 5.0.
        motor_no_load_speed (float | None | str | Unset): ω_nl: optional; given, the motor torque falls linearly from
            the stall torque to 0 at this speed; absent, the torque is constant
        roller_mass (float | None | str | Unset): m_p: mass of one centrifugal roller [002, eq. 1] Default: 0.05.
        roller_count (int | None | str | Unset): n: number of centrifugal rollers [002, eq. 1] Default: 6.
        roller_radius (float | None | str | Unset): x_0: radius of the rollers' centres at rest [002, eq. 1] Default:
            0.04.
        cone_angle (float | None | str | Unset): α: angle of the conical faces of half-coupling and striker [002, eq.
            1]; the paper's closed form is for 45° Default: 0.7853981633974483.
        half_coupling_mass (float | None | str | Unset): m_1: mass of the half-coupling [002, eq. 1] Default: 0.15.
        stepped_shaft_mass (float | None | str | Unset): m_2: mass of the stepped central shaft [002, eq. 1] Default:
            0.05.
        striker_mass (float | None | str | Unset): m_3: mass of the striker [002, eq. 2] Default: 0.4.
        power_spring_rate (float | None | str | Unset): c_1: rate of the power spring [002, eq. 1] Default: 50000.0.
        auxiliary_spring_rate (float | None | str | Unset): c_2: rate of the auxiliary spring [002, eq. 1] Default:
            2000.0.
        return_spring_rate (float | None | str | Unset): c_3: rate of the return spring [002, eq. 2] Default: 52000.0.
        power_spring_preload (float | None | str | Unset): λ_1: preload deflection of the power spring [002, eq. 1]
            Default: 0.002.
        auxiliary_spring_preload (float | None | str | Unset): λ_2: preload deflection of the auxiliary spring [002, eq.
            1] Default: 0.008.
        return_spring_preload (float | None | str | Unset): λ_3: preload deflection of the return spring [002, eq. 2]
            Default: 0.0021.
        release_travel (float | None | str | Unset): h_1: axial travel of half-coupling and shaft at which the striker
            is released [002, eq. 1] Default: 0.005.
        engagement_height (float | None | str | Unset): h_2: travel of the striker into full engagement with the anvil
            [002, eq. 2] Default: 0.004.
        jaw_height (float | None | str | Unset): h_3: height of the anvil's jaws, the striker's return travel [002, eq.
            3] Default: 0.0035.
        engagement_angle (float | None | str | Unset): φ_eng: the anvil's opening, the angle the flywheel turns while
            the striker must engage [002, after eq. 5] Default: 2.0943951023931953.
        roller_friction (float | None | str | Unset): f: friction coefficient of the rollers on the cones [002, eq. 4]
            Default: 0.1.
        gravity (float | None | str | Unset): g: gravity along the stroke towards the anvil [002, eqs. 2-4]; 9.80665 for
            the paper's vertical tool, 0 for a horizontal one, negative for a tool pointing up Default: 9.80665.
        roller_geometry (ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0 | None | Unset): how
            the rollers sit between the cones (engine/procedures/striker_cycle.py draws them): 'symmetric_v' both faces
            conical, x = x0 + z1/(2 tan α), the paper's 45° release speed; 'single_cone' only the half-coupling's face
            conical, the printed constraint z1 = x1 tan α with consistent forces; 'paper' the printed [002, eq. 1] as it
            stands (its forces do not balance; for reproducing the paper) Default:
            ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0.SYMMETRIC_V.
        change_limit (float | None | str | Unset): L, the largest relative change of any one variable: each stays within
            x0 (1 − L) … x0 (1 + L) and its own input range Default: 0.5.
        min_engagement_margin (float | None | str | Unset): the engagement margin (t_w − t_e)/t_w the design found must
            keep beyond impact.rare's full engagement check: the closed form the search judges by is within about 1 % of the
            simulation, so a design on the edge may land an edge blow Default: 0.02.
        vary_striker_mass (bool | None | Unset): let the search change the striker's mass m3 as well as the six spring
            rates and preloads Default: False.
        search_samples (int | None | str | Unset): random designs judged before the refinement (shells around the
            design, the nearest densest) Default: 4000.
    """

    flywheel_inertia: float | None | str | Unset = 0.02
    motor_torque: float | None | str | Unset = 5.0
    motor_no_load_speed: float | None | str | Unset = UNSET
    roller_mass: float | None | str | Unset = 0.05
    roller_count: int | None | str | Unset = 6
    roller_radius: float | None | str | Unset = 0.04
    cone_angle: float | None | str | Unset = 0.7853981633974483
    half_coupling_mass: float | None | str | Unset = 0.15
    stepped_shaft_mass: float | None | str | Unset = 0.05
    striker_mass: float | None | str | Unset = 0.4
    power_spring_rate: float | None | str | Unset = 50000.0
    auxiliary_spring_rate: float | None | str | Unset = 2000.0
    return_spring_rate: float | None | str | Unset = 52000.0
    power_spring_preload: float | None | str | Unset = 0.002
    auxiliary_spring_preload: float | None | str | Unset = 0.008
    return_spring_preload: float | None | str | Unset = 0.0021
    release_travel: float | None | str | Unset = 0.005
    engagement_height: float | None | str | Unset = 0.004
    jaw_height: float | None | str | Unset = 0.0035
    engagement_angle: float | None | str | Unset = 2.0943951023931953
    roller_friction: float | None | str | Unset = 0.1
    gravity: float | None | str | Unset = 9.80665
    roller_geometry: ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0 | None | Unset = (
        ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0.SYMMETRIC_V
    )
    change_limit: float | None | str | Unset = 0.5
    min_engagement_margin: float | None | str | Unset = 0.02
    vary_striker_mass: bool | None | Unset = False
    search_samples: int | None | str | Unset = 4000

    def to_dict(self) -> dict[str, Any]:
        flywheel_inertia: float | None | str | Unset
        if isinstance(self.flywheel_inertia, Unset):
            flywheel_inertia = UNSET
        else:
            flywheel_inertia = self.flywheel_inertia

        motor_torque: float | None | str | Unset
        if isinstance(self.motor_torque, Unset):
            motor_torque = UNSET
        else:
            motor_torque = self.motor_torque

        motor_no_load_speed: float | None | str | Unset
        if isinstance(self.motor_no_load_speed, Unset):
            motor_no_load_speed = UNSET
        else:
            motor_no_load_speed = self.motor_no_load_speed

        roller_mass: float | None | str | Unset
        if isinstance(self.roller_mass, Unset):
            roller_mass = UNSET
        else:
            roller_mass = self.roller_mass

        roller_count: int | None | str | Unset
        if isinstance(self.roller_count, Unset):
            roller_count = UNSET
        else:
            roller_count = self.roller_count

        roller_radius: float | None | str | Unset
        if isinstance(self.roller_radius, Unset):
            roller_radius = UNSET
        else:
            roller_radius = self.roller_radius

        cone_angle: float | None | str | Unset
        if isinstance(self.cone_angle, Unset):
            cone_angle = UNSET
        else:
            cone_angle = self.cone_angle

        half_coupling_mass: float | None | str | Unset
        if isinstance(self.half_coupling_mass, Unset):
            half_coupling_mass = UNSET
        else:
            half_coupling_mass = self.half_coupling_mass

        stepped_shaft_mass: float | None | str | Unset
        if isinstance(self.stepped_shaft_mass, Unset):
            stepped_shaft_mass = UNSET
        else:
            stepped_shaft_mass = self.stepped_shaft_mass

        striker_mass: float | None | str | Unset
        if isinstance(self.striker_mass, Unset):
            striker_mass = UNSET
        else:
            striker_mass = self.striker_mass

        power_spring_rate: float | None | str | Unset
        if isinstance(self.power_spring_rate, Unset):
            power_spring_rate = UNSET
        else:
            power_spring_rate = self.power_spring_rate

        auxiliary_spring_rate: float | None | str | Unset
        if isinstance(self.auxiliary_spring_rate, Unset):
            auxiliary_spring_rate = UNSET
        else:
            auxiliary_spring_rate = self.auxiliary_spring_rate

        return_spring_rate: float | None | str | Unset
        if isinstance(self.return_spring_rate, Unset):
            return_spring_rate = UNSET
        else:
            return_spring_rate = self.return_spring_rate

        power_spring_preload: float | None | str | Unset
        if isinstance(self.power_spring_preload, Unset):
            power_spring_preload = UNSET
        else:
            power_spring_preload = self.power_spring_preload

        auxiliary_spring_preload: float | None | str | Unset
        if isinstance(self.auxiliary_spring_preload, Unset):
            auxiliary_spring_preload = UNSET
        else:
            auxiliary_spring_preload = self.auxiliary_spring_preload

        return_spring_preload: float | None | str | Unset
        if isinstance(self.return_spring_preload, Unset):
            return_spring_preload = UNSET
        else:
            return_spring_preload = self.return_spring_preload

        release_travel: float | None | str | Unset
        if isinstance(self.release_travel, Unset):
            release_travel = UNSET
        else:
            release_travel = self.release_travel

        engagement_height: float | None | str | Unset
        if isinstance(self.engagement_height, Unset):
            engagement_height = UNSET
        else:
            engagement_height = self.engagement_height

        jaw_height: float | None | str | Unset
        if isinstance(self.jaw_height, Unset):
            jaw_height = UNSET
        else:
            jaw_height = self.jaw_height

        engagement_angle: float | None | str | Unset
        if isinstance(self.engagement_angle, Unset):
            engagement_angle = UNSET
        else:
            engagement_angle = self.engagement_angle

        roller_friction: float | None | str | Unset
        if isinstance(self.roller_friction, Unset):
            roller_friction = UNSET
        else:
            roller_friction = self.roller_friction

        gravity: float | None | str | Unset
        if isinstance(self.gravity, Unset):
            gravity = UNSET
        else:
            gravity = self.gravity

        roller_geometry: None | str | Unset
        if isinstance(self.roller_geometry, Unset):
            roller_geometry = UNSET
        elif isinstance(self.roller_geometry, ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0):
            roller_geometry = self.roller_geometry.value
        else:
            roller_geometry = self.roller_geometry

        change_limit: float | None | str | Unset
        if isinstance(self.change_limit, Unset):
            change_limit = UNSET
        else:
            change_limit = self.change_limit

        min_engagement_margin: float | None | str | Unset
        if isinstance(self.min_engagement_margin, Unset):
            min_engagement_margin = UNSET
        else:
            min_engagement_margin = self.min_engagement_margin

        vary_striker_mass: bool | None | Unset
        if isinstance(self.vary_striker_mass, Unset):
            vary_striker_mass = UNSET
        else:
            vary_striker_mass = self.vary_striker_mass

        search_samples: int | None | str | Unset
        if isinstance(self.search_samples, Unset):
            search_samples = UNSET
        else:
            search_samples = self.search_samples

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if flywheel_inertia is not UNSET:
            field_dict["flywheel_inertia"] = flywheel_inertia
        if motor_torque is not UNSET:
            field_dict["motor_torque"] = motor_torque
        if motor_no_load_speed is not UNSET:
            field_dict["motor_no_load_speed"] = motor_no_load_speed
        if roller_mass is not UNSET:
            field_dict["roller_mass"] = roller_mass
        if roller_count is not UNSET:
            field_dict["roller_count"] = roller_count
        if roller_radius is not UNSET:
            field_dict["roller_radius"] = roller_radius
        if cone_angle is not UNSET:
            field_dict["cone_angle"] = cone_angle
        if half_coupling_mass is not UNSET:
            field_dict["half_coupling_mass"] = half_coupling_mass
        if stepped_shaft_mass is not UNSET:
            field_dict["stepped_shaft_mass"] = stepped_shaft_mass
        if striker_mass is not UNSET:
            field_dict["striker_mass"] = striker_mass
        if power_spring_rate is not UNSET:
            field_dict["power_spring_rate"] = power_spring_rate
        if auxiliary_spring_rate is not UNSET:
            field_dict["auxiliary_spring_rate"] = auxiliary_spring_rate
        if return_spring_rate is not UNSET:
            field_dict["return_spring_rate"] = return_spring_rate
        if power_spring_preload is not UNSET:
            field_dict["power_spring_preload"] = power_spring_preload
        if auxiliary_spring_preload is not UNSET:
            field_dict["auxiliary_spring_preload"] = auxiliary_spring_preload
        if return_spring_preload is not UNSET:
            field_dict["return_spring_preload"] = return_spring_preload
        if release_travel is not UNSET:
            field_dict["release_travel"] = release_travel
        if engagement_height is not UNSET:
            field_dict["engagement_height"] = engagement_height
        if jaw_height is not UNSET:
            field_dict["jaw_height"] = jaw_height
        if engagement_angle is not UNSET:
            field_dict["engagement_angle"] = engagement_angle
        if roller_friction is not UNSET:
            field_dict["roller_friction"] = roller_friction
        if gravity is not UNSET:
            field_dict["gravity"] = gravity
        if roller_geometry is not UNSET:
            field_dict["roller_geometry"] = roller_geometry
        if change_limit is not UNSET:
            field_dict["change_limit"] = change_limit
        if min_engagement_margin is not UNSET:
            field_dict["min_engagement_margin"] = min_engagement_margin
        if vary_striker_mass is not UNSET:
            field_dict["vary_striker_mass"] = vary_striker_mass
        if search_samples is not UNSET:
            field_dict["search_samples"] = search_samples

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_flywheel_inertia(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flywheel_inertia = _parse_flywheel_inertia(d.pop("flywheel_inertia", UNSET))

        def _parse_motor_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_torque = _parse_motor_torque(d.pop("motor_torque", UNSET))

        def _parse_motor_no_load_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_no_load_speed = _parse_motor_no_load_speed(d.pop("motor_no_load_speed", UNSET))

        def _parse_roller_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        roller_mass = _parse_roller_mass(d.pop("roller_mass", UNSET))

        def _parse_roller_count(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        roller_count = _parse_roller_count(d.pop("roller_count", UNSET))

        def _parse_roller_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        roller_radius = _parse_roller_radius(d.pop("roller_radius", UNSET))

        def _parse_cone_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        cone_angle = _parse_cone_angle(d.pop("cone_angle", UNSET))

        def _parse_half_coupling_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        half_coupling_mass = _parse_half_coupling_mass(d.pop("half_coupling_mass", UNSET))

        def _parse_stepped_shaft_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        stepped_shaft_mass = _parse_stepped_shaft_mass(d.pop("stepped_shaft_mass", UNSET))

        def _parse_striker_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        striker_mass = _parse_striker_mass(d.pop("striker_mass", UNSET))

        def _parse_power_spring_rate(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        power_spring_rate = _parse_power_spring_rate(d.pop("power_spring_rate", UNSET))

        def _parse_auxiliary_spring_rate(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        auxiliary_spring_rate = _parse_auxiliary_spring_rate(d.pop("auxiliary_spring_rate", UNSET))

        def _parse_return_spring_rate(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        return_spring_rate = _parse_return_spring_rate(d.pop("return_spring_rate", UNSET))

        def _parse_power_spring_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        power_spring_preload = _parse_power_spring_preload(d.pop("power_spring_preload", UNSET))

        def _parse_auxiliary_spring_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        auxiliary_spring_preload = _parse_auxiliary_spring_preload(d.pop("auxiliary_spring_preload", UNSET))

        def _parse_return_spring_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        return_spring_preload = _parse_return_spring_preload(d.pop("return_spring_preload", UNSET))

        def _parse_release_travel(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        release_travel = _parse_release_travel(d.pop("release_travel", UNSET))

        def _parse_engagement_height(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        engagement_height = _parse_engagement_height(d.pop("engagement_height", UNSET))

        def _parse_jaw_height(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        jaw_height = _parse_jaw_height(d.pop("jaw_height", UNSET))

        def _parse_engagement_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        engagement_angle = _parse_engagement_angle(d.pop("engagement_angle", UNSET))

        def _parse_roller_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        roller_friction = _parse_roller_friction(d.pop("roller_friction", UNSET))

        def _parse_gravity(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        gravity = _parse_gravity(d.pop("gravity", UNSET))

        def _parse_roller_geometry(
            data: object,
        ) -> ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                roller_geometry_type_0 = ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0(data)

                return roller_geometry_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0 | None | Unset, data)

        roller_geometry = _parse_roller_geometry(d.pop("roller_geometry", UNSET))

        def _parse_change_limit(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        change_limit = _parse_change_limit(d.pop("change_limit", UNSET))

        def _parse_min_engagement_margin(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        min_engagement_margin = _parse_min_engagement_margin(d.pop("min_engagement_margin", UNSET))

        def _parse_vary_striker_mass(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        vary_striker_mass = _parse_vary_striker_mass(d.pop("vary_striker_mass", UNSET))

        def _parse_search_samples(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        search_samples = _parse_search_samples(d.pop("search_samples", UNSET))

        impact_rare_design_study_request_impact_rare_design_study_base = cls(
            flywheel_inertia=flywheel_inertia,
            motor_torque=motor_torque,
            motor_no_load_speed=motor_no_load_speed,
            roller_mass=roller_mass,
            roller_count=roller_count,
            roller_radius=roller_radius,
            cone_angle=cone_angle,
            half_coupling_mass=half_coupling_mass,
            stepped_shaft_mass=stepped_shaft_mass,
            striker_mass=striker_mass,
            power_spring_rate=power_spring_rate,
            auxiliary_spring_rate=auxiliary_spring_rate,
            return_spring_rate=return_spring_rate,
            power_spring_preload=power_spring_preload,
            auxiliary_spring_preload=auxiliary_spring_preload,
            return_spring_preload=return_spring_preload,
            release_travel=release_travel,
            engagement_height=engagement_height,
            jaw_height=jaw_height,
            engagement_angle=engagement_angle,
            roller_friction=roller_friction,
            gravity=gravity,
            roller_geometry=roller_geometry,
            change_limit=change_limit,
            min_engagement_margin=min_engagement_margin,
            vary_striker_mass=vary_striker_mass,
            search_samples=search_samples,
        )

        return impact_rare_design_study_request_impact_rare_design_study_base
