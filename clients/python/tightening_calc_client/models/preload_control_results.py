from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadControlResults")


@_attrs_define
class PreloadControlResults:
    """
    Attributes:
        controlled_quantity (None | str | Unset): What the method sets: torque, angle, elongation, force, displacement
            or yield [dimensionless]
        target_torque (float | None | Unset): Torque for the nominal preload F_nom (the middle of the method's band:
            F_M,zul/(1 + scatter), or the preload given) at the given friction μ_G, μ_K, by torque_formula; not VDI 2230-1
            R13's M_A for F_M,zul at μ_G,min, μ_K,min (joint.vdi2230 tightening_torque) [N*m]
        target_angle (float | None | Unset): Nut rotation from snug for the nominal preload ([004, eq. 8/9]) [rad]
        snug_torque (float | None | Unset): torque_then_angle: torque to snug, M_snug = s_snug × target_torque (the
            first step, [004] after eq. 19) [N*m]
        snug_preload (float | None | Unset): torque_then_angle: preload at the snug point, s_snug × F_nom [N]
        angle_after_snug (float | None | Unset): torque_then_angle: the angle to turn beyond snug, θ = (F_nom −
            F_snug)(λ_b + λ_p)/P · 360° ([004, eq. 8]) [rad]
        target_elongation (float | None | Unset): Bolt elongation at the nominal preload, Δl = F0 λ_b ([004, eq. 7]) [m]
        target_displacement (float | None | Unset): Sucker rods: circumferential displacement of the marks on the
            coupling, φ·D_c/2 [m]
        target_force (float | None | Unset): Force the washer/ring is set to (= nominal preload) [N]
        nominal_preload (float | None | Unset): Middle of the method's preload band [N]
        preload_min (float | None | Unset): Lowest preload the method gives, F_nom (1 − s) [N]
        preload_max (float | None | Unset): Highest preload the method gives, F_nom (1 + s) [N]
        scatter (float | None | Unset): The method's preload scatter ±s [dimensionless]
        tightening_factor (float | None | Unset): α_A = (1 + s)/(1 − s) (VDI 2230 Table A8) [dimensionless]
        required_preload (float | None | Unset): υ × required clamp force ([004, eq. 2]) [N]
        preload_factor (float | None | Unset): υ used [dimensionless]
        permissible_preload (float | None | Unset): Preload at ν·R_p0.2 (VDI 2230 R7) [N]
        yield_preload (float | None | Unset): Preload at which σ_red reaches R_p0.2 (ν = 1) [N]
        min_meets_clamp (bool | None | Unset): preload_min ≥ required_preload [dimensionless]
        max_below_yield (bool | None | Unset): preload_max ≤ yield_preload [dimensionless]
        cheaper_methods (None | str | Unset): Cheaper methods of the same family that would also pass both checks
            ('none' if none) [dimensionless]
        passing_methods (None | str | Unset): Every method of the same family that passes both checks, cheapest first
            [dimensionless]
        bolt_compliance (float | None | Unset): λ_b = Σ l_i/(E A_i) incl. m/3 at d3 ([004, eq. 4, 7]) [m/N]
        clamped_compliance (float | None | Unset): λ_p used [m/N]
        equivalent_shank_diameter (float | None | Unset): d_eq of the stretched length ([004, eq. 4]) [m]
        scatter_torque_applied (float | None | Unset): Friction scatter: the tightening torque the histogram and the
            scatter band are computed at (the target torque, or scatter_torque where given) [N*m]
        scatter_preload_min (float | None | Unset): Friction scatter: lowest preload (μ_G and μ_K at their maximum: the
            corner) [N]
        scatter_preload_max (float | None | Unset): Friction scatter: highest preload (μ_G and μ_K at their minimum: the
            corner) [N]
        scatter_preload_mean (float | None | Unset): Friction scatter: mean preload over μ_G, μ_K independent and
            uniform (exact) [N]
        scatter_relative (float | None | Unset): Friction scatter: (max − min)/(max + min), the ± of [004, fig. 5]
            [dimensionless]
        fastener (None | str | Unset): The fastener resolved from the inputs [dimensionless]
        surface_pressure_head (float | None | Unset): Surface pressure under the head (or washer) at the largest
            assembly preload, p = F_M,max / A_p (VDI 2230-1 R10) [Pa]
        surface_pressure_head_working (float | None | Unset): Surface pressure under the head (or washer) at
            working_bolt_force (VDI 2230-1 R10) [Pa]
        surface_pressure_nut (float | None | Unset): Surface pressure under the nut at the largest assembly preload (VDI
            2230-1 R10) [Pa]
        limiting_surface_pressure (float | None | Unset): Limiting surface pressure p_G used (clamped_material or as
            given) [Pa]
        bearing_area (float | None | Unset): Bearing area A_p on the clamped part under the head/washer [m^2]
        min_engagement_length (float | None | Unset): Shortest engagement, entry chamfers (2P) included, for which a
            bolt at its upper strength 1.2 R_m breaks before a thread strips (VDI 2230-1 R11, Alexander) [m]
        stripping_force (float | None | Unset): Force that strips the weaker thread at engagement_length (VDI 2230-1
            R11) [N]
        bolt_breaking_force (float | None | Unset): 1.2 R_m A_s: the upper breaking force the threads must exceed (VDI
            2230-1 R11) [N]
        drive_torque_limit (float | None | Unset): Test torque of the hex key the head takes (ISO 2936): the drive's
            limit [N*m]
        nut_proof_load (float | None | Unset): ISO 898-2 proof load of the nut, S_p A_s: caps F_M,zul (with a nut) [N]
        nut_stripping_force (float | None | Unset): Thread strength of a nut that does not pair with the bolt (thin,
            weaker class): the larger of R11's F_SM = C1 C3 τ_BM A_SGM over m − 2P (τ_BM = 0.6 S_p) and the ISO 898-2 proof
            load the thread is tested to [N]
    """

    controlled_quantity: None | str | Unset = UNSET
    target_torque: float | None | Unset = UNSET
    target_angle: float | None | Unset = UNSET
    snug_torque: float | None | Unset = UNSET
    snug_preload: float | None | Unset = UNSET
    angle_after_snug: float | None | Unset = UNSET
    target_elongation: float | None | Unset = UNSET
    target_displacement: float | None | Unset = UNSET
    target_force: float | None | Unset = UNSET
    nominal_preload: float | None | Unset = UNSET
    preload_min: float | None | Unset = UNSET
    preload_max: float | None | Unset = UNSET
    scatter: float | None | Unset = UNSET
    tightening_factor: float | None | Unset = UNSET
    required_preload: float | None | Unset = UNSET
    preload_factor: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    yield_preload: float | None | Unset = UNSET
    min_meets_clamp: bool | None | Unset = UNSET
    max_below_yield: bool | None | Unset = UNSET
    cheaper_methods: None | str | Unset = UNSET
    passing_methods: None | str | Unset = UNSET
    bolt_compliance: float | None | Unset = UNSET
    clamped_compliance: float | None | Unset = UNSET
    equivalent_shank_diameter: float | None | Unset = UNSET
    scatter_torque_applied: float | None | Unset = UNSET
    scatter_preload_min: float | None | Unset = UNSET
    scatter_preload_max: float | None | Unset = UNSET
    scatter_preload_mean: float | None | Unset = UNSET
    scatter_relative: float | None | Unset = UNSET
    fastener: None | str | Unset = UNSET
    surface_pressure_head: float | None | Unset = UNSET
    surface_pressure_head_working: float | None | Unset = UNSET
    surface_pressure_nut: float | None | Unset = UNSET
    limiting_surface_pressure: float | None | Unset = UNSET
    bearing_area: float | None | Unset = UNSET
    min_engagement_length: float | None | Unset = UNSET
    stripping_force: float | None | Unset = UNSET
    bolt_breaking_force: float | None | Unset = UNSET
    drive_torque_limit: float | None | Unset = UNSET
    nut_proof_load: float | None | Unset = UNSET
    nut_stripping_force: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        controlled_quantity: None | str | Unset
        if isinstance(self.controlled_quantity, Unset):
            controlled_quantity = UNSET
        else:
            controlled_quantity = self.controlled_quantity

        target_torque: float | None | Unset
        if isinstance(self.target_torque, Unset):
            target_torque = UNSET
        else:
            target_torque = self.target_torque

        target_angle: float | None | Unset
        if isinstance(self.target_angle, Unset):
            target_angle = UNSET
        else:
            target_angle = self.target_angle

        snug_torque: float | None | Unset
        if isinstance(self.snug_torque, Unset):
            snug_torque = UNSET
        else:
            snug_torque = self.snug_torque

        snug_preload: float | None | Unset
        if isinstance(self.snug_preload, Unset):
            snug_preload = UNSET
        else:
            snug_preload = self.snug_preload

        angle_after_snug: float | None | Unset
        if isinstance(self.angle_after_snug, Unset):
            angle_after_snug = UNSET
        else:
            angle_after_snug = self.angle_after_snug

        target_elongation: float | None | Unset
        if isinstance(self.target_elongation, Unset):
            target_elongation = UNSET
        else:
            target_elongation = self.target_elongation

        target_displacement: float | None | Unset
        if isinstance(self.target_displacement, Unset):
            target_displacement = UNSET
        else:
            target_displacement = self.target_displacement

        target_force: float | None | Unset
        if isinstance(self.target_force, Unset):
            target_force = UNSET
        else:
            target_force = self.target_force

        nominal_preload: float | None | Unset
        if isinstance(self.nominal_preload, Unset):
            nominal_preload = UNSET
        else:
            nominal_preload = self.nominal_preload

        preload_min: float | None | Unset
        if isinstance(self.preload_min, Unset):
            preload_min = UNSET
        else:
            preload_min = self.preload_min

        preload_max: float | None | Unset
        if isinstance(self.preload_max, Unset):
            preload_max = UNSET
        else:
            preload_max = self.preload_max

        scatter: float | None | Unset
        if isinstance(self.scatter, Unset):
            scatter = UNSET
        else:
            scatter = self.scatter

        tightening_factor: float | None | Unset
        if isinstance(self.tightening_factor, Unset):
            tightening_factor = UNSET
        else:
            tightening_factor = self.tightening_factor

        required_preload: float | None | Unset
        if isinstance(self.required_preload, Unset):
            required_preload = UNSET
        else:
            required_preload = self.required_preload

        preload_factor: float | None | Unset
        if isinstance(self.preload_factor, Unset):
            preload_factor = UNSET
        else:
            preload_factor = self.preload_factor

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        yield_preload: float | None | Unset
        if isinstance(self.yield_preload, Unset):
            yield_preload = UNSET
        else:
            yield_preload = self.yield_preload

        min_meets_clamp: bool | None | Unset
        if isinstance(self.min_meets_clamp, Unset):
            min_meets_clamp = UNSET
        else:
            min_meets_clamp = self.min_meets_clamp

        max_below_yield: bool | None | Unset
        if isinstance(self.max_below_yield, Unset):
            max_below_yield = UNSET
        else:
            max_below_yield = self.max_below_yield

        cheaper_methods: None | str | Unset
        if isinstance(self.cheaper_methods, Unset):
            cheaper_methods = UNSET
        else:
            cheaper_methods = self.cheaper_methods

        passing_methods: None | str | Unset
        if isinstance(self.passing_methods, Unset):
            passing_methods = UNSET
        else:
            passing_methods = self.passing_methods

        bolt_compliance: float | None | Unset
        if isinstance(self.bolt_compliance, Unset):
            bolt_compliance = UNSET
        else:
            bolt_compliance = self.bolt_compliance

        clamped_compliance: float | None | Unset
        if isinstance(self.clamped_compliance, Unset):
            clamped_compliance = UNSET
        else:
            clamped_compliance = self.clamped_compliance

        equivalent_shank_diameter: float | None | Unset
        if isinstance(self.equivalent_shank_diameter, Unset):
            equivalent_shank_diameter = UNSET
        else:
            equivalent_shank_diameter = self.equivalent_shank_diameter

        scatter_torque_applied: float | None | Unset
        if isinstance(self.scatter_torque_applied, Unset):
            scatter_torque_applied = UNSET
        else:
            scatter_torque_applied = self.scatter_torque_applied

        scatter_preload_min: float | None | Unset
        if isinstance(self.scatter_preload_min, Unset):
            scatter_preload_min = UNSET
        else:
            scatter_preload_min = self.scatter_preload_min

        scatter_preload_max: float | None | Unset
        if isinstance(self.scatter_preload_max, Unset):
            scatter_preload_max = UNSET
        else:
            scatter_preload_max = self.scatter_preload_max

        scatter_preload_mean: float | None | Unset
        if isinstance(self.scatter_preload_mean, Unset):
            scatter_preload_mean = UNSET
        else:
            scatter_preload_mean = self.scatter_preload_mean

        scatter_relative: float | None | Unset
        if isinstance(self.scatter_relative, Unset):
            scatter_relative = UNSET
        else:
            scatter_relative = self.scatter_relative

        fastener: None | str | Unset
        if isinstance(self.fastener, Unset):
            fastener = UNSET
        else:
            fastener = self.fastener

        surface_pressure_head: float | None | Unset
        if isinstance(self.surface_pressure_head, Unset):
            surface_pressure_head = UNSET
        else:
            surface_pressure_head = self.surface_pressure_head

        surface_pressure_head_working: float | None | Unset
        if isinstance(self.surface_pressure_head_working, Unset):
            surface_pressure_head_working = UNSET
        else:
            surface_pressure_head_working = self.surface_pressure_head_working

        surface_pressure_nut: float | None | Unset
        if isinstance(self.surface_pressure_nut, Unset):
            surface_pressure_nut = UNSET
        else:
            surface_pressure_nut = self.surface_pressure_nut

        limiting_surface_pressure: float | None | Unset
        if isinstance(self.limiting_surface_pressure, Unset):
            limiting_surface_pressure = UNSET
        else:
            limiting_surface_pressure = self.limiting_surface_pressure

        bearing_area: float | None | Unset
        if isinstance(self.bearing_area, Unset):
            bearing_area = UNSET
        else:
            bearing_area = self.bearing_area

        min_engagement_length: float | None | Unset
        if isinstance(self.min_engagement_length, Unset):
            min_engagement_length = UNSET
        else:
            min_engagement_length = self.min_engagement_length

        stripping_force: float | None | Unset
        if isinstance(self.stripping_force, Unset):
            stripping_force = UNSET
        else:
            stripping_force = self.stripping_force

        bolt_breaking_force: float | None | Unset
        if isinstance(self.bolt_breaking_force, Unset):
            bolt_breaking_force = UNSET
        else:
            bolt_breaking_force = self.bolt_breaking_force

        drive_torque_limit: float | None | Unset
        if isinstance(self.drive_torque_limit, Unset):
            drive_torque_limit = UNSET
        else:
            drive_torque_limit = self.drive_torque_limit

        nut_proof_load: float | None | Unset
        if isinstance(self.nut_proof_load, Unset):
            nut_proof_load = UNSET
        else:
            nut_proof_load = self.nut_proof_load

        nut_stripping_force: float | None | Unset
        if isinstance(self.nut_stripping_force, Unset):
            nut_stripping_force = UNSET
        else:
            nut_stripping_force = self.nut_stripping_force

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if controlled_quantity is not UNSET:
            field_dict["controlled_quantity"] = controlled_quantity
        if target_torque is not UNSET:
            field_dict["target_torque"] = target_torque
        if target_angle is not UNSET:
            field_dict["target_angle"] = target_angle
        if snug_torque is not UNSET:
            field_dict["snug_torque"] = snug_torque
        if snug_preload is not UNSET:
            field_dict["snug_preload"] = snug_preload
        if angle_after_snug is not UNSET:
            field_dict["angle_after_snug"] = angle_after_snug
        if target_elongation is not UNSET:
            field_dict["target_elongation"] = target_elongation
        if target_displacement is not UNSET:
            field_dict["target_displacement"] = target_displacement
        if target_force is not UNSET:
            field_dict["target_force"] = target_force
        if nominal_preload is not UNSET:
            field_dict["nominal_preload"] = nominal_preload
        if preload_min is not UNSET:
            field_dict["preload_min"] = preload_min
        if preload_max is not UNSET:
            field_dict["preload_max"] = preload_max
        if scatter is not UNSET:
            field_dict["scatter"] = scatter
        if tightening_factor is not UNSET:
            field_dict["tightening_factor"] = tightening_factor
        if required_preload is not UNSET:
            field_dict["required_preload"] = required_preload
        if preload_factor is not UNSET:
            field_dict["preload_factor"] = preload_factor
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload
        if yield_preload is not UNSET:
            field_dict["yield_preload"] = yield_preload
        if min_meets_clamp is not UNSET:
            field_dict["min_meets_clamp"] = min_meets_clamp
        if max_below_yield is not UNSET:
            field_dict["max_below_yield"] = max_below_yield
        if cheaper_methods is not UNSET:
            field_dict["cheaper_methods"] = cheaper_methods
        if passing_methods is not UNSET:
            field_dict["passing_methods"] = passing_methods
        if bolt_compliance is not UNSET:
            field_dict["bolt_compliance"] = bolt_compliance
        if clamped_compliance is not UNSET:
            field_dict["clamped_compliance"] = clamped_compliance
        if equivalent_shank_diameter is not UNSET:
            field_dict["equivalent_shank_diameter"] = equivalent_shank_diameter
        if scatter_torque_applied is not UNSET:
            field_dict["scatter_torque_applied"] = scatter_torque_applied
        if scatter_preload_min is not UNSET:
            field_dict["scatter_preload_min"] = scatter_preload_min
        if scatter_preload_max is not UNSET:
            field_dict["scatter_preload_max"] = scatter_preload_max
        if scatter_preload_mean is not UNSET:
            field_dict["scatter_preload_mean"] = scatter_preload_mean
        if scatter_relative is not UNSET:
            field_dict["scatter_relative"] = scatter_relative
        if fastener is not UNSET:
            field_dict["fastener"] = fastener
        if surface_pressure_head is not UNSET:
            field_dict["surface_pressure_head"] = surface_pressure_head
        if surface_pressure_head_working is not UNSET:
            field_dict["surface_pressure_head_working"] = surface_pressure_head_working
        if surface_pressure_nut is not UNSET:
            field_dict["surface_pressure_nut"] = surface_pressure_nut
        if limiting_surface_pressure is not UNSET:
            field_dict["limiting_surface_pressure"] = limiting_surface_pressure
        if bearing_area is not UNSET:
            field_dict["bearing_area"] = bearing_area
        if min_engagement_length is not UNSET:
            field_dict["min_engagement_length"] = min_engagement_length
        if stripping_force is not UNSET:
            field_dict["stripping_force"] = stripping_force
        if bolt_breaking_force is not UNSET:
            field_dict["bolt_breaking_force"] = bolt_breaking_force
        if drive_torque_limit is not UNSET:
            field_dict["drive_torque_limit"] = drive_torque_limit
        if nut_proof_load is not UNSET:
            field_dict["nut_proof_load"] = nut_proof_load
        if nut_stripping_force is not UNSET:
            field_dict["nut_stripping_force"] = nut_stripping_force

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_controlled_quantity(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        controlled_quantity = _parse_controlled_quantity(d.pop("controlled_quantity", UNSET))

        def _parse_target_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_torque = _parse_target_torque(d.pop("target_torque", UNSET))

        def _parse_target_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_angle = _parse_target_angle(d.pop("target_angle", UNSET))

        def _parse_snug_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        snug_torque = _parse_snug_torque(d.pop("snug_torque", UNSET))

        def _parse_snug_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        snug_preload = _parse_snug_preload(d.pop("snug_preload", UNSET))

        def _parse_angle_after_snug(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        angle_after_snug = _parse_angle_after_snug(d.pop("angle_after_snug", UNSET))

        def _parse_target_elongation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_elongation = _parse_target_elongation(d.pop("target_elongation", UNSET))

        def _parse_target_displacement(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_displacement = _parse_target_displacement(d.pop("target_displacement", UNSET))

        def _parse_target_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_force = _parse_target_force(d.pop("target_force", UNSET))

        def _parse_nominal_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        nominal_preload = _parse_nominal_preload(d.pop("nominal_preload", UNSET))

        def _parse_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_min = _parse_preload_min(d.pop("preload_min", UNSET))

        def _parse_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_max = _parse_preload_max(d.pop("preload_max", UNSET))

        def _parse_scatter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        scatter = _parse_scatter(d.pop("scatter", UNSET))

        def _parse_tightening_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tightening_factor = _parse_tightening_factor(d.pop("tightening_factor", UNSET))

        def _parse_required_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_preload = _parse_required_preload(d.pop("required_preload", UNSET))

        def _parse_preload_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_factor = _parse_preload_factor(d.pop("preload_factor", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        def _parse_yield_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_preload = _parse_yield_preload(d.pop("yield_preload", UNSET))

        def _parse_min_meets_clamp(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        min_meets_clamp = _parse_min_meets_clamp(d.pop("min_meets_clamp", UNSET))

        def _parse_max_below_yield(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        max_below_yield = _parse_max_below_yield(d.pop("max_below_yield", UNSET))

        def _parse_cheaper_methods(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        cheaper_methods = _parse_cheaper_methods(d.pop("cheaper_methods", UNSET))

        def _parse_passing_methods(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        passing_methods = _parse_passing_methods(d.pop("passing_methods", UNSET))

        def _parse_bolt_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance = _parse_bolt_compliance(d.pop("bolt_compliance", UNSET))

        def _parse_clamped_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clamped_compliance = _parse_clamped_compliance(d.pop("clamped_compliance", UNSET))

        def _parse_equivalent_shank_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        equivalent_shank_diameter = _parse_equivalent_shank_diameter(d.pop("equivalent_shank_diameter", UNSET))

        def _parse_scatter_torque_applied(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        scatter_torque_applied = _parse_scatter_torque_applied(d.pop("scatter_torque_applied", UNSET))

        def _parse_scatter_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        scatter_preload_min = _parse_scatter_preload_min(d.pop("scatter_preload_min", UNSET))

        def _parse_scatter_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        scatter_preload_max = _parse_scatter_preload_max(d.pop("scatter_preload_max", UNSET))

        def _parse_scatter_preload_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        scatter_preload_mean = _parse_scatter_preload_mean(d.pop("scatter_preload_mean", UNSET))

        def _parse_scatter_relative(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        scatter_relative = _parse_scatter_relative(d.pop("scatter_relative", UNSET))

        def _parse_fastener(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        fastener = _parse_fastener(d.pop("fastener", UNSET))

        def _parse_surface_pressure_head(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        surface_pressure_head = _parse_surface_pressure_head(d.pop("surface_pressure_head", UNSET))

        def _parse_surface_pressure_head_working(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        surface_pressure_head_working = _parse_surface_pressure_head_working(
            d.pop("surface_pressure_head_working", UNSET)
        )

        def _parse_surface_pressure_nut(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        surface_pressure_nut = _parse_surface_pressure_nut(d.pop("surface_pressure_nut", UNSET))

        def _parse_limiting_surface_pressure(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        limiting_surface_pressure = _parse_limiting_surface_pressure(d.pop("limiting_surface_pressure", UNSET))

        def _parse_bearing_area(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_area = _parse_bearing_area(d.pop("bearing_area", UNSET))

        def _parse_min_engagement_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        min_engagement_length = _parse_min_engagement_length(d.pop("min_engagement_length", UNSET))

        def _parse_stripping_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stripping_force = _parse_stripping_force(d.pop("stripping_force", UNSET))

        def _parse_bolt_breaking_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_breaking_force = _parse_bolt_breaking_force(d.pop("bolt_breaking_force", UNSET))

        def _parse_drive_torque_limit(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        drive_torque_limit = _parse_drive_torque_limit(d.pop("drive_torque_limit", UNSET))

        def _parse_nut_proof_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        nut_proof_load = _parse_nut_proof_load(d.pop("nut_proof_load", UNSET))

        def _parse_nut_stripping_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        nut_stripping_force = _parse_nut_stripping_force(d.pop("nut_stripping_force", UNSET))

        preload_control_results = cls(
            controlled_quantity=controlled_quantity,
            target_torque=target_torque,
            target_angle=target_angle,
            snug_torque=snug_torque,
            snug_preload=snug_preload,
            angle_after_snug=angle_after_snug,
            target_elongation=target_elongation,
            target_displacement=target_displacement,
            target_force=target_force,
            nominal_preload=nominal_preload,
            preload_min=preload_min,
            preload_max=preload_max,
            scatter=scatter,
            tightening_factor=tightening_factor,
            required_preload=required_preload,
            preload_factor=preload_factor,
            permissible_preload=permissible_preload,
            yield_preload=yield_preload,
            min_meets_clamp=min_meets_clamp,
            max_below_yield=max_below_yield,
            cheaper_methods=cheaper_methods,
            passing_methods=passing_methods,
            bolt_compliance=bolt_compliance,
            clamped_compliance=clamped_compliance,
            equivalent_shank_diameter=equivalent_shank_diameter,
            scatter_torque_applied=scatter_torque_applied,
            scatter_preload_min=scatter_preload_min,
            scatter_preload_max=scatter_preload_max,
            scatter_preload_mean=scatter_preload_mean,
            scatter_relative=scatter_relative,
            fastener=fastener,
            surface_pressure_head=surface_pressure_head,
            surface_pressure_head_working=surface_pressure_head_working,
            surface_pressure_nut=surface_pressure_nut,
            limiting_surface_pressure=limiting_surface_pressure,
            bearing_area=bearing_area,
            min_engagement_length=min_engagement_length,
            stripping_force=stripping_force,
            bolt_breaking_force=bolt_breaking_force,
            drive_torque_limit=drive_torque_limit,
            nut_proof_load=nut_proof_load,
            nut_stripping_force=nut_stripping_force,
        )

        preload_control_results.additional_properties = d
        return preload_control_results

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
