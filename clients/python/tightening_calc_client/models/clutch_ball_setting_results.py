from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="ClutchBallSettingResults")


@_attrs_define
class ClutchBallSettingResults:
    """
    Attributes:
        required_spring_force (float | None | Unset): F = 2 T tan(α−ρ)/(D0 s), s = 1 (common) or K_r i (per_ball) [001,
            eq. 1–3] [N]
        required_deflection (float | None | Unset): Δ = 8 F D³ i_p/(G d0⁴) with the given wire: the nut setting [001,
            eq. 2] [m]
        required_wire_diameter (float | None | Unset): d0 = (8 F D³ i_p/(G Δ))^¼ at the given deflection [001, eq. 2]
            [m]
        spring_rate (float | None | Unset): rate of the given wire's spring [N/m]
        spring_index (float | None | Unset): D/d0 of the given wire [dimensionless]
        spring_shear_stress (float | None | Unset): wire stress of the given wire at the required force [Pa]
        required_wire_spring_index (float | None | Unset): D/d0 of the required wire [dimensionless]
        required_wire_shear_stress (float | None | Unset): wire stress of the required wire at the required force [Pa]
        required_peak_setting (float | None | Unset): nut setting (spring deflection with the balls seated) whose PEAK
            torque over the lift is the target, with the given spring; null where none reaches it [m]
        peak_setting_stress_max (float | None | Unset): largest spring stress over the lift at required_peak_setting
            [Pa]
        suggested_wire_diameter (float | None | Unset): smallest preferred wire (EN 10270-1 sizes, index 4…12, same D
            and i_p) that reaches the target peak torque within the permissible stress [m]
        suggested_wire_setting (float | None | Unset): nut setting of the suggested wire for the target peak torque [m]
        suggested_disc_parallel (int | None | Unset): fewest discs in parallel per pack (same discs and series count)
            that reach the target peak torque within σ_OM ≤ yield and without passing flat [dimensionless]
        suggested_disc_setting (float | None | Unset): stack setting with the suggested number of discs in parallel [m]
        rated_drive_torque (float | None | Unset): T_N: drive_torque, or P/ω [N*m]
        start_torque (float | None | Unset): T_a = T_start J_L/(J_A + J_L): what the clutch carries while the motor
            accelerates the load [N*m]
        required_slip_torque (float | None | Unset): max(K T_N, T_a); the target torque when target_torque is not given
            [N*m]
    """

    required_spring_force: float | None | Unset = UNSET
    required_deflection: float | None | Unset = UNSET
    required_wire_diameter: float | None | Unset = UNSET
    spring_rate: float | None | Unset = UNSET
    spring_index: float | None | Unset = UNSET
    spring_shear_stress: float | None | Unset = UNSET
    required_wire_spring_index: float | None | Unset = UNSET
    required_wire_shear_stress: float | None | Unset = UNSET
    required_peak_setting: float | None | Unset = UNSET
    peak_setting_stress_max: float | None | Unset = UNSET
    suggested_wire_diameter: float | None | Unset = UNSET
    suggested_wire_setting: float | None | Unset = UNSET
    suggested_disc_parallel: int | None | Unset = UNSET
    suggested_disc_setting: float | None | Unset = UNSET
    rated_drive_torque: float | None | Unset = UNSET
    start_torque: float | None | Unset = UNSET
    required_slip_torque: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        required_spring_force: float | None | Unset
        if isinstance(self.required_spring_force, Unset):
            required_spring_force = UNSET
        else:
            required_spring_force = self.required_spring_force

        required_deflection: float | None | Unset
        if isinstance(self.required_deflection, Unset):
            required_deflection = UNSET
        else:
            required_deflection = self.required_deflection

        required_wire_diameter: float | None | Unset
        if isinstance(self.required_wire_diameter, Unset):
            required_wire_diameter = UNSET
        else:
            required_wire_diameter = self.required_wire_diameter

        spring_rate: float | None | Unset
        if isinstance(self.spring_rate, Unset):
            spring_rate = UNSET
        else:
            spring_rate = self.spring_rate

        spring_index: float | None | Unset
        if isinstance(self.spring_index, Unset):
            spring_index = UNSET
        else:
            spring_index = self.spring_index

        spring_shear_stress: float | None | Unset
        if isinstance(self.spring_shear_stress, Unset):
            spring_shear_stress = UNSET
        else:
            spring_shear_stress = self.spring_shear_stress

        required_wire_spring_index: float | None | Unset
        if isinstance(self.required_wire_spring_index, Unset):
            required_wire_spring_index = UNSET
        else:
            required_wire_spring_index = self.required_wire_spring_index

        required_wire_shear_stress: float | None | Unset
        if isinstance(self.required_wire_shear_stress, Unset):
            required_wire_shear_stress = UNSET
        else:
            required_wire_shear_stress = self.required_wire_shear_stress

        required_peak_setting: float | None | Unset
        if isinstance(self.required_peak_setting, Unset):
            required_peak_setting = UNSET
        else:
            required_peak_setting = self.required_peak_setting

        peak_setting_stress_max: float | None | Unset
        if isinstance(self.peak_setting_stress_max, Unset):
            peak_setting_stress_max = UNSET
        else:
            peak_setting_stress_max = self.peak_setting_stress_max

        suggested_wire_diameter: float | None | Unset
        if isinstance(self.suggested_wire_diameter, Unset):
            suggested_wire_diameter = UNSET
        else:
            suggested_wire_diameter = self.suggested_wire_diameter

        suggested_wire_setting: float | None | Unset
        if isinstance(self.suggested_wire_setting, Unset):
            suggested_wire_setting = UNSET
        else:
            suggested_wire_setting = self.suggested_wire_setting

        suggested_disc_parallel: int | None | Unset
        if isinstance(self.suggested_disc_parallel, Unset):
            suggested_disc_parallel = UNSET
        else:
            suggested_disc_parallel = self.suggested_disc_parallel

        suggested_disc_setting: float | None | Unset
        if isinstance(self.suggested_disc_setting, Unset):
            suggested_disc_setting = UNSET
        else:
            suggested_disc_setting = self.suggested_disc_setting

        rated_drive_torque: float | None | Unset
        if isinstance(self.rated_drive_torque, Unset):
            rated_drive_torque = UNSET
        else:
            rated_drive_torque = self.rated_drive_torque

        start_torque: float | None | Unset
        if isinstance(self.start_torque, Unset):
            start_torque = UNSET
        else:
            start_torque = self.start_torque

        required_slip_torque: float | None | Unset
        if isinstance(self.required_slip_torque, Unset):
            required_slip_torque = UNSET
        else:
            required_slip_torque = self.required_slip_torque

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if required_spring_force is not UNSET:
            field_dict["required_spring_force"] = required_spring_force
        if required_deflection is not UNSET:
            field_dict["required_deflection"] = required_deflection
        if required_wire_diameter is not UNSET:
            field_dict["required_wire_diameter"] = required_wire_diameter
        if spring_rate is not UNSET:
            field_dict["spring_rate"] = spring_rate
        if spring_index is not UNSET:
            field_dict["spring_index"] = spring_index
        if spring_shear_stress is not UNSET:
            field_dict["spring_shear_stress"] = spring_shear_stress
        if required_wire_spring_index is not UNSET:
            field_dict["required_wire_spring_index"] = required_wire_spring_index
        if required_wire_shear_stress is not UNSET:
            field_dict["required_wire_shear_stress"] = required_wire_shear_stress
        if required_peak_setting is not UNSET:
            field_dict["required_peak_setting"] = required_peak_setting
        if peak_setting_stress_max is not UNSET:
            field_dict["peak_setting_stress_max"] = peak_setting_stress_max
        if suggested_wire_diameter is not UNSET:
            field_dict["suggested_wire_diameter"] = suggested_wire_diameter
        if suggested_wire_setting is not UNSET:
            field_dict["suggested_wire_setting"] = suggested_wire_setting
        if suggested_disc_parallel is not UNSET:
            field_dict["suggested_disc_parallel"] = suggested_disc_parallel
        if suggested_disc_setting is not UNSET:
            field_dict["suggested_disc_setting"] = suggested_disc_setting
        if rated_drive_torque is not UNSET:
            field_dict["rated_drive_torque"] = rated_drive_torque
        if start_torque is not UNSET:
            field_dict["start_torque"] = start_torque
        if required_slip_torque is not UNSET:
            field_dict["required_slip_torque"] = required_slip_torque

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_required_spring_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_spring_force = _parse_required_spring_force(d.pop("required_spring_force", UNSET))

        def _parse_required_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_deflection = _parse_required_deflection(d.pop("required_deflection", UNSET))

        def _parse_required_wire_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_wire_diameter = _parse_required_wire_diameter(d.pop("required_wire_diameter", UNSET))

        def _parse_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_rate = _parse_spring_rate(d.pop("spring_rate", UNSET))

        def _parse_spring_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_index = _parse_spring_index(d.pop("spring_index", UNSET))

        def _parse_spring_shear_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_shear_stress = _parse_spring_shear_stress(d.pop("spring_shear_stress", UNSET))

        def _parse_required_wire_spring_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_wire_spring_index = _parse_required_wire_spring_index(d.pop("required_wire_spring_index", UNSET))

        def _parse_required_wire_shear_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_wire_shear_stress = _parse_required_wire_shear_stress(d.pop("required_wire_shear_stress", UNSET))

        def _parse_required_peak_setting(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_peak_setting = _parse_required_peak_setting(d.pop("required_peak_setting", UNSET))

        def _parse_peak_setting_stress_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        peak_setting_stress_max = _parse_peak_setting_stress_max(d.pop("peak_setting_stress_max", UNSET))

        def _parse_suggested_wire_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        suggested_wire_diameter = _parse_suggested_wire_diameter(d.pop("suggested_wire_diameter", UNSET))

        def _parse_suggested_wire_setting(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        suggested_wire_setting = _parse_suggested_wire_setting(d.pop("suggested_wire_setting", UNSET))

        def _parse_suggested_disc_parallel(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        suggested_disc_parallel = _parse_suggested_disc_parallel(d.pop("suggested_disc_parallel", UNSET))

        def _parse_suggested_disc_setting(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        suggested_disc_setting = _parse_suggested_disc_setting(d.pop("suggested_disc_setting", UNSET))

        def _parse_rated_drive_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rated_drive_torque = _parse_rated_drive_torque(d.pop("rated_drive_torque", UNSET))

        def _parse_start_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        start_torque = _parse_start_torque(d.pop("start_torque", UNSET))

        def _parse_required_slip_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_slip_torque = _parse_required_slip_torque(d.pop("required_slip_torque", UNSET))

        clutch_ball_setting_results = cls(
            required_spring_force=required_spring_force,
            required_deflection=required_deflection,
            required_wire_diameter=required_wire_diameter,
            spring_rate=spring_rate,
            spring_index=spring_index,
            spring_shear_stress=spring_shear_stress,
            required_wire_spring_index=required_wire_spring_index,
            required_wire_shear_stress=required_wire_shear_stress,
            required_peak_setting=required_peak_setting,
            peak_setting_stress_max=peak_setting_stress_max,
            suggested_wire_diameter=suggested_wire_diameter,
            suggested_wire_setting=suggested_wire_setting,
            suggested_disc_parallel=suggested_disc_parallel,
            suggested_disc_setting=suggested_disc_setting,
            rated_drive_torque=rated_drive_torque,
            start_torque=start_torque,
            required_slip_torque=required_slip_torque,
        )

        clutch_ball_setting_results.additional_properties = d
        return clutch_ball_setting_results

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
