from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadTighteningResults")


@_attrs_define
class PreloadTighteningResults:
    """
    Attributes:
        assembly_preload (float | None | Unset): Preload F_M used: the permissible one (below) unless preload was given
            [N]
        permissible_preload (float | None | Unset): Largest preload whose equivalent stress is ν·R_p0.2: F = ν R_p0.2
            A_s / β (VDI 2230 R7; [004, eq. 3]) [N]
        tightening_torque (float | None | Unset): Wrench torque M_A = thread + bearing torque ([004, eq. 13]) by
            torque_formula [N*m]
        thread_torque (float | None | Unset): Thread torque M_p ([004, eq. 10]; VDI: F(0.16P + 0.58 d2 μ_G)) [N*m]
        bearing_torque (float | None | Unset): Bearing-face torque M_T = μ_K F R ([004, eq. 11]) [N*m]
        ideal_torque (float | None | Unset): Frictionless torque M* = F P / (2π) ([004, eq. 14]) [N*m]
        ideal_torque_share (float | None | Unset): M* / M_A; [004] says usually 0.05…0.15 [dimensionless]
        friction_radius (float | None | Unset): Bearing friction radius used: exact R_T ([004, eq. 12]) for 'exact',
            (D_f + d_h)/4 otherwise [m]
        stress_area (float | None | Unset): Stress area A_s = π/4 ((d2 + d3)/2)² (ISO 898-1) [m^2]
        pitch_diameter (float | None | Unset): d2 = d − 0.649519 P (ISO 68-1) [m]
        minor_diameter (float | None | Unset): d3 = d − 1.226869 P (ISO 68-1) [m]
        thread_pitch (float | None | Unset): Pitch P used [m]
        torsion_factor (float | None | Unset): β = σ_red/σ ([004, eq. 5]; VDI 2230 R7) [dimensionless]
        equivalent_stress (float | None | Unset): σ_red = β F / A_s during tightening [Pa]
        yield_strength (float | None | Unset): R_p0.2 used [Pa]
        stress_utilization (float | None | Unset): σ_red / R_p0.2 at the preload used [dimensionless]
        bearing_outer_diameter (float | None | Unset): D_f used [m]
        hole_diameter (float | None | Unset): d_h used [m]
        torque_formula_deviation (float | None | Unset): |M(chosen formula) − M(exact)| / M(exact) for these inputs
            [dimensionless]
        rule_of_thumb_torque (float | None | Unset): 0.2 F0 d ([004, eq. 16]) [N*m]
        rule_of_thumb_deviation (float | None | Unset): (0.2 F0 d − M_A) / M_A [dimensionless]
        yield_rule_torque (float | None | Unset): 0.07 σ_T d³ ([004, eq. 18]; assumes σ0 = 0.6 σ_T, not the preload used
            here) [N*m]
        yield_rule_deviation (float | None | Unset): (0.07 σ_T d³ − M_A) / M_A [dimensionless]
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

    assembly_preload: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    tightening_torque: float | None | Unset = UNSET
    thread_torque: float | None | Unset = UNSET
    bearing_torque: float | None | Unset = UNSET
    ideal_torque: float | None | Unset = UNSET
    ideal_torque_share: float | None | Unset = UNSET
    friction_radius: float | None | Unset = UNSET
    stress_area: float | None | Unset = UNSET
    pitch_diameter: float | None | Unset = UNSET
    minor_diameter: float | None | Unset = UNSET
    thread_pitch: float | None | Unset = UNSET
    torsion_factor: float | None | Unset = UNSET
    equivalent_stress: float | None | Unset = UNSET
    yield_strength: float | None | Unset = UNSET
    stress_utilization: float | None | Unset = UNSET
    bearing_outer_diameter: float | None | Unset = UNSET
    hole_diameter: float | None | Unset = UNSET
    torque_formula_deviation: float | None | Unset = UNSET
    rule_of_thumb_torque: float | None | Unset = UNSET
    rule_of_thumb_deviation: float | None | Unset = UNSET
    yield_rule_torque: float | None | Unset = UNSET
    yield_rule_deviation: float | None | Unset = UNSET
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
        assembly_preload: float | None | Unset
        if isinstance(self.assembly_preload, Unset):
            assembly_preload = UNSET
        else:
            assembly_preload = self.assembly_preload

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        tightening_torque: float | None | Unset
        if isinstance(self.tightening_torque, Unset):
            tightening_torque = UNSET
        else:
            tightening_torque = self.tightening_torque

        thread_torque: float | None | Unset
        if isinstance(self.thread_torque, Unset):
            thread_torque = UNSET
        else:
            thread_torque = self.thread_torque

        bearing_torque: float | None | Unset
        if isinstance(self.bearing_torque, Unset):
            bearing_torque = UNSET
        else:
            bearing_torque = self.bearing_torque

        ideal_torque: float | None | Unset
        if isinstance(self.ideal_torque, Unset):
            ideal_torque = UNSET
        else:
            ideal_torque = self.ideal_torque

        ideal_torque_share: float | None | Unset
        if isinstance(self.ideal_torque_share, Unset):
            ideal_torque_share = UNSET
        else:
            ideal_torque_share = self.ideal_torque_share

        friction_radius: float | None | Unset
        if isinstance(self.friction_radius, Unset):
            friction_radius = UNSET
        else:
            friction_radius = self.friction_radius

        stress_area: float | None | Unset
        if isinstance(self.stress_area, Unset):
            stress_area = UNSET
        else:
            stress_area = self.stress_area

        pitch_diameter: float | None | Unset
        if isinstance(self.pitch_diameter, Unset):
            pitch_diameter = UNSET
        else:
            pitch_diameter = self.pitch_diameter

        minor_diameter: float | None | Unset
        if isinstance(self.minor_diameter, Unset):
            minor_diameter = UNSET
        else:
            minor_diameter = self.minor_diameter

        thread_pitch: float | None | Unset
        if isinstance(self.thread_pitch, Unset):
            thread_pitch = UNSET
        else:
            thread_pitch = self.thread_pitch

        torsion_factor: float | None | Unset
        if isinstance(self.torsion_factor, Unset):
            torsion_factor = UNSET
        else:
            torsion_factor = self.torsion_factor

        equivalent_stress: float | None | Unset
        if isinstance(self.equivalent_stress, Unset):
            equivalent_stress = UNSET
        else:
            equivalent_stress = self.equivalent_stress

        yield_strength: float | None | Unset
        if isinstance(self.yield_strength, Unset):
            yield_strength = UNSET
        else:
            yield_strength = self.yield_strength

        stress_utilization: float | None | Unset
        if isinstance(self.stress_utilization, Unset):
            stress_utilization = UNSET
        else:
            stress_utilization = self.stress_utilization

        bearing_outer_diameter: float | None | Unset
        if isinstance(self.bearing_outer_diameter, Unset):
            bearing_outer_diameter = UNSET
        else:
            bearing_outer_diameter = self.bearing_outer_diameter

        hole_diameter: float | None | Unset
        if isinstance(self.hole_diameter, Unset):
            hole_diameter = UNSET
        else:
            hole_diameter = self.hole_diameter

        torque_formula_deviation: float | None | Unset
        if isinstance(self.torque_formula_deviation, Unset):
            torque_formula_deviation = UNSET
        else:
            torque_formula_deviation = self.torque_formula_deviation

        rule_of_thumb_torque: float | None | Unset
        if isinstance(self.rule_of_thumb_torque, Unset):
            rule_of_thumb_torque = UNSET
        else:
            rule_of_thumb_torque = self.rule_of_thumb_torque

        rule_of_thumb_deviation: float | None | Unset
        if isinstance(self.rule_of_thumb_deviation, Unset):
            rule_of_thumb_deviation = UNSET
        else:
            rule_of_thumb_deviation = self.rule_of_thumb_deviation

        yield_rule_torque: float | None | Unset
        if isinstance(self.yield_rule_torque, Unset):
            yield_rule_torque = UNSET
        else:
            yield_rule_torque = self.yield_rule_torque

        yield_rule_deviation: float | None | Unset
        if isinstance(self.yield_rule_deviation, Unset):
            yield_rule_deviation = UNSET
        else:
            yield_rule_deviation = self.yield_rule_deviation

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
        if assembly_preload is not UNSET:
            field_dict["assembly_preload"] = assembly_preload
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload
        if tightening_torque is not UNSET:
            field_dict["tightening_torque"] = tightening_torque
        if thread_torque is not UNSET:
            field_dict["thread_torque"] = thread_torque
        if bearing_torque is not UNSET:
            field_dict["bearing_torque"] = bearing_torque
        if ideal_torque is not UNSET:
            field_dict["ideal_torque"] = ideal_torque
        if ideal_torque_share is not UNSET:
            field_dict["ideal_torque_share"] = ideal_torque_share
        if friction_radius is not UNSET:
            field_dict["friction_radius"] = friction_radius
        if stress_area is not UNSET:
            field_dict["stress_area"] = stress_area
        if pitch_diameter is not UNSET:
            field_dict["pitch_diameter"] = pitch_diameter
        if minor_diameter is not UNSET:
            field_dict["minor_diameter"] = minor_diameter
        if thread_pitch is not UNSET:
            field_dict["thread_pitch"] = thread_pitch
        if torsion_factor is not UNSET:
            field_dict["torsion_factor"] = torsion_factor
        if equivalent_stress is not UNSET:
            field_dict["equivalent_stress"] = equivalent_stress
        if yield_strength is not UNSET:
            field_dict["yield_strength"] = yield_strength
        if stress_utilization is not UNSET:
            field_dict["stress_utilization"] = stress_utilization
        if bearing_outer_diameter is not UNSET:
            field_dict["bearing_outer_diameter"] = bearing_outer_diameter
        if hole_diameter is not UNSET:
            field_dict["hole_diameter"] = hole_diameter
        if torque_formula_deviation is not UNSET:
            field_dict["torque_formula_deviation"] = torque_formula_deviation
        if rule_of_thumb_torque is not UNSET:
            field_dict["rule_of_thumb_torque"] = rule_of_thumb_torque
        if rule_of_thumb_deviation is not UNSET:
            field_dict["rule_of_thumb_deviation"] = rule_of_thumb_deviation
        if yield_rule_torque is not UNSET:
            field_dict["yield_rule_torque"] = yield_rule_torque
        if yield_rule_deviation is not UNSET:
            field_dict["yield_rule_deviation"] = yield_rule_deviation
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

        def _parse_assembly_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload = _parse_assembly_preload(d.pop("assembly_preload", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        def _parse_tightening_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tightening_torque = _parse_tightening_torque(d.pop("tightening_torque", UNSET))

        def _parse_thread_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_torque = _parse_thread_torque(d.pop("thread_torque", UNSET))

        def _parse_bearing_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_torque = _parse_bearing_torque(d.pop("bearing_torque", UNSET))

        def _parse_ideal_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ideal_torque = _parse_ideal_torque(d.pop("ideal_torque", UNSET))

        def _parse_ideal_torque_share(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ideal_torque_share = _parse_ideal_torque_share(d.pop("ideal_torque_share", UNSET))

        def _parse_friction_radius(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        friction_radius = _parse_friction_radius(d.pop("friction_radius", UNSET))

        def _parse_stress_area(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stress_area = _parse_stress_area(d.pop("stress_area", UNSET))

        def _parse_pitch_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        pitch_diameter = _parse_pitch_diameter(d.pop("pitch_diameter", UNSET))

        def _parse_minor_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        minor_diameter = _parse_minor_diameter(d.pop("minor_diameter", UNSET))

        def _parse_thread_pitch(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_pitch = _parse_thread_pitch(d.pop("thread_pitch", UNSET))

        def _parse_torsion_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torsion_factor = _parse_torsion_factor(d.pop("torsion_factor", UNSET))

        def _parse_equivalent_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        equivalent_stress = _parse_equivalent_stress(d.pop("equivalent_stress", UNSET))

        def _parse_yield_strength(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_strength = _parse_yield_strength(d.pop("yield_strength", UNSET))

        def _parse_stress_utilization(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stress_utilization = _parse_stress_utilization(d.pop("stress_utilization", UNSET))

        def _parse_bearing_outer_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_outer_diameter = _parse_bearing_outer_diameter(d.pop("bearing_outer_diameter", UNSET))

        def _parse_hole_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        hole_diameter = _parse_hole_diameter(d.pop("hole_diameter", UNSET))

        def _parse_torque_formula_deviation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_formula_deviation = _parse_torque_formula_deviation(d.pop("torque_formula_deviation", UNSET))

        def _parse_rule_of_thumb_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rule_of_thumb_torque = _parse_rule_of_thumb_torque(d.pop("rule_of_thumb_torque", UNSET))

        def _parse_rule_of_thumb_deviation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rule_of_thumb_deviation = _parse_rule_of_thumb_deviation(d.pop("rule_of_thumb_deviation", UNSET))

        def _parse_yield_rule_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_rule_torque = _parse_yield_rule_torque(d.pop("yield_rule_torque", UNSET))

        def _parse_yield_rule_deviation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_rule_deviation = _parse_yield_rule_deviation(d.pop("yield_rule_deviation", UNSET))

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

        preload_tightening_results = cls(
            assembly_preload=assembly_preload,
            permissible_preload=permissible_preload,
            tightening_torque=tightening_torque,
            thread_torque=thread_torque,
            bearing_torque=bearing_torque,
            ideal_torque=ideal_torque,
            ideal_torque_share=ideal_torque_share,
            friction_radius=friction_radius,
            stress_area=stress_area,
            pitch_diameter=pitch_diameter,
            minor_diameter=minor_diameter,
            thread_pitch=thread_pitch,
            torsion_factor=torsion_factor,
            equivalent_stress=equivalent_stress,
            yield_strength=yield_strength,
            stress_utilization=stress_utilization,
            bearing_outer_diameter=bearing_outer_diameter,
            hole_diameter=hole_diameter,
            torque_formula_deviation=torque_formula_deviation,
            rule_of_thumb_torque=rule_of_thumb_torque,
            rule_of_thumb_deviation=rule_of_thumb_deviation,
            yield_rule_torque=yield_rule_torque,
            yield_rule_deviation=yield_rule_deviation,
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

        preload_tightening_results.additional_properties = d
        return preload_tightening_results

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
