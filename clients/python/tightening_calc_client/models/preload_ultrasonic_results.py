from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadUltrasonicResults")


@_attrs_define
class PreloadUltrasonicResults:
    """
    Attributes:
        preload (float | None | Unset): Preload F = ΔL/δ_S [N]
        elongation (float | None | Unset): Mechanical elongation ΔL = F δ_S [m]
        ultrasonic_length_change (float | None | Unset): Ultrasonic change in length ΔL/S_F, at the zero reading's
            temperature [m]
        thermal_length_change (float | None | Unset): Apparent change from the temperature alone, τ L_U ΔT [m]
        time_of_flight_change (float | None | Unset): Change in round-trip time the instrument reads (stress and
            temperature) [s]
        bolt_compliance (float | None | Unset): δ_S of the joint model (VDI 2230-1 R3) [m/N]
        effective_length (float | None | Unset): Length of a bar of the stress area with the bolt's compliance, E A_s
            δ_S [m]
        bolt_stress (float | None | Unset): Axial stress F/A_s [Pa]
    """

    preload: float | None | Unset = UNSET
    elongation: float | None | Unset = UNSET
    ultrasonic_length_change: float | None | Unset = UNSET
    thermal_length_change: float | None | Unset = UNSET
    time_of_flight_change: float | None | Unset = UNSET
    bolt_compliance: float | None | Unset = UNSET
    effective_length: float | None | Unset = UNSET
    bolt_stress: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        preload: float | None | Unset
        if isinstance(self.preload, Unset):
            preload = UNSET
        else:
            preload = self.preload

        elongation: float | None | Unset
        if isinstance(self.elongation, Unset):
            elongation = UNSET
        else:
            elongation = self.elongation

        ultrasonic_length_change: float | None | Unset
        if isinstance(self.ultrasonic_length_change, Unset):
            ultrasonic_length_change = UNSET
        else:
            ultrasonic_length_change = self.ultrasonic_length_change

        thermal_length_change: float | None | Unset
        if isinstance(self.thermal_length_change, Unset):
            thermal_length_change = UNSET
        else:
            thermal_length_change = self.thermal_length_change

        time_of_flight_change: float | None | Unset
        if isinstance(self.time_of_flight_change, Unset):
            time_of_flight_change = UNSET
        else:
            time_of_flight_change = self.time_of_flight_change

        bolt_compliance: float | None | Unset
        if isinstance(self.bolt_compliance, Unset):
            bolt_compliance = UNSET
        else:
            bolt_compliance = self.bolt_compliance

        effective_length: float | None | Unset
        if isinstance(self.effective_length, Unset):
            effective_length = UNSET
        else:
            effective_length = self.effective_length

        bolt_stress: float | None | Unset
        if isinstance(self.bolt_stress, Unset):
            bolt_stress = UNSET
        else:
            bolt_stress = self.bolt_stress

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if preload is not UNSET:
            field_dict["preload"] = preload
        if elongation is not UNSET:
            field_dict["elongation"] = elongation
        if ultrasonic_length_change is not UNSET:
            field_dict["ultrasonic_length_change"] = ultrasonic_length_change
        if thermal_length_change is not UNSET:
            field_dict["thermal_length_change"] = thermal_length_change
        if time_of_flight_change is not UNSET:
            field_dict["time_of_flight_change"] = time_of_flight_change
        if bolt_compliance is not UNSET:
            field_dict["bolt_compliance"] = bolt_compliance
        if effective_length is not UNSET:
            field_dict["effective_length"] = effective_length
        if bolt_stress is not UNSET:
            field_dict["bolt_stress"] = bolt_stress

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload = _parse_preload(d.pop("preload", UNSET))

        def _parse_elongation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        elongation = _parse_elongation(d.pop("elongation", UNSET))

        def _parse_ultrasonic_length_change(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ultrasonic_length_change = _parse_ultrasonic_length_change(d.pop("ultrasonic_length_change", UNSET))

        def _parse_thermal_length_change(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thermal_length_change = _parse_thermal_length_change(d.pop("thermal_length_change", UNSET))

        def _parse_time_of_flight_change(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        time_of_flight_change = _parse_time_of_flight_change(d.pop("time_of_flight_change", UNSET))

        def _parse_bolt_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance = _parse_bolt_compliance(d.pop("bolt_compliance", UNSET))

        def _parse_effective_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        effective_length = _parse_effective_length(d.pop("effective_length", UNSET))

        def _parse_bolt_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_stress = _parse_bolt_stress(d.pop("bolt_stress", UNSET))

        preload_ultrasonic_results = cls(
            preload=preload,
            elongation=elongation,
            ultrasonic_length_change=ultrasonic_length_change,
            thermal_length_change=thermal_length_change,
            time_of_flight_change=time_of_flight_change,
            bolt_compliance=bolt_compliance,
            effective_length=effective_length,
            bolt_stress=bolt_stress,
        )

        preload_ultrasonic_results.additional_properties = d
        return preload_ultrasonic_results

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
