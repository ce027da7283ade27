from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="FrictionIso16047Results")


@_attrs_define
class FrictionIso16047Results:
    """
    Attributes:
        test_count (int | None | Unset): Number of tests n in the series [dimensionless]
        thread_diameter (float | None | Unset): Nominal thread diameter d [m]
        thread_pitch (float | None | Unset): Thread pitch P [m]
        pitch_diameter (float | None | Unset): Pitch diameter d2 [m]
        bearing_diameter (float | None | Unset): Mean bearing diameter D_b [m]
        torque_coefficient_mean (float | None | Unset): Mean of the torque coefficient K = T/(F d) over the series
            [dimensionless]
        torque_coefficient_sd (float | None | Unset): Standard deviation (n − 1) of the torque coefficient K = T/(F d)
            over the series [dimensionless]
        torque_coefficient_min (float | None | Unset): Smallest of the torque coefficient K = T/(F d) over the series
            [dimensionless]
        torque_coefficient_max (float | None | Unset): Largest of the torque coefficient K = T/(F d) over the series
            [dimensionless]
        thread_friction_mean (float | None | Unset): Mean of the thread friction μ_th over the series [dimensionless]
        thread_friction_sd (float | None | Unset): Standard deviation (n − 1) of the thread friction μ_th over the
            series [dimensionless]
        thread_friction_min (float | None | Unset): Smallest of the thread friction μ_th over the series [dimensionless]
        thread_friction_max (float | None | Unset): Largest of the thread friction μ_th over the series [dimensionless]
        bearing_friction_mean (float | None | Unset): Mean of the bearing friction μ_b over the series [dimensionless]
        bearing_friction_sd (float | None | Unset): Standard deviation (n − 1) of the bearing friction μ_b over the
            series [dimensionless]
        bearing_friction_min (float | None | Unset): Smallest of the bearing friction μ_b over the series
            [dimensionless]
        bearing_friction_max (float | None | Unset): Largest of the bearing friction μ_b over the series [dimensionless]
        total_friction_mean (float | None | Unset): Mean of the total friction μ_tot over the series [dimensionless]
        total_friction_sd (float | None | Unset): Standard deviation (n − 1) of the total friction μ_tot over the series
            [dimensionless]
        total_friction_min (float | None | Unset): Smallest of the total friction μ_tot over the series [dimensionless]
        total_friction_max (float | None | Unset): Largest of the total friction μ_tot over the series [dimensionless]
    """

    test_count: int | None | Unset = UNSET
    thread_diameter: float | None | Unset = UNSET
    thread_pitch: float | None | Unset = UNSET
    pitch_diameter: float | None | Unset = UNSET
    bearing_diameter: float | None | Unset = UNSET
    torque_coefficient_mean: float | None | Unset = UNSET
    torque_coefficient_sd: float | None | Unset = UNSET
    torque_coefficient_min: float | None | Unset = UNSET
    torque_coefficient_max: float | None | Unset = UNSET
    thread_friction_mean: float | None | Unset = UNSET
    thread_friction_sd: float | None | Unset = UNSET
    thread_friction_min: float | None | Unset = UNSET
    thread_friction_max: float | None | Unset = UNSET
    bearing_friction_mean: float | None | Unset = UNSET
    bearing_friction_sd: float | None | Unset = UNSET
    bearing_friction_min: float | None | Unset = UNSET
    bearing_friction_max: float | None | Unset = UNSET
    total_friction_mean: float | None | Unset = UNSET
    total_friction_sd: float | None | Unset = UNSET
    total_friction_min: float | None | Unset = UNSET
    total_friction_max: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        test_count: int | None | Unset
        if isinstance(self.test_count, Unset):
            test_count = UNSET
        else:
            test_count = self.test_count

        thread_diameter: float | None | Unset
        if isinstance(self.thread_diameter, Unset):
            thread_diameter = UNSET
        else:
            thread_diameter = self.thread_diameter

        thread_pitch: float | None | Unset
        if isinstance(self.thread_pitch, Unset):
            thread_pitch = UNSET
        else:
            thread_pitch = self.thread_pitch

        pitch_diameter: float | None | Unset
        if isinstance(self.pitch_diameter, Unset):
            pitch_diameter = UNSET
        else:
            pitch_diameter = self.pitch_diameter

        bearing_diameter: float | None | Unset
        if isinstance(self.bearing_diameter, Unset):
            bearing_diameter = UNSET
        else:
            bearing_diameter = self.bearing_diameter

        torque_coefficient_mean: float | None | Unset
        if isinstance(self.torque_coefficient_mean, Unset):
            torque_coefficient_mean = UNSET
        else:
            torque_coefficient_mean = self.torque_coefficient_mean

        torque_coefficient_sd: float | None | Unset
        if isinstance(self.torque_coefficient_sd, Unset):
            torque_coefficient_sd = UNSET
        else:
            torque_coefficient_sd = self.torque_coefficient_sd

        torque_coefficient_min: float | None | Unset
        if isinstance(self.torque_coefficient_min, Unset):
            torque_coefficient_min = UNSET
        else:
            torque_coefficient_min = self.torque_coefficient_min

        torque_coefficient_max: float | None | Unset
        if isinstance(self.torque_coefficient_max, Unset):
            torque_coefficient_max = UNSET
        else:
            torque_coefficient_max = self.torque_coefficient_max

        thread_friction_mean: float | None | Unset
        if isinstance(self.thread_friction_mean, Unset):
            thread_friction_mean = UNSET
        else:
            thread_friction_mean = self.thread_friction_mean

        thread_friction_sd: float | None | Unset
        if isinstance(self.thread_friction_sd, Unset):
            thread_friction_sd = UNSET
        else:
            thread_friction_sd = self.thread_friction_sd

        thread_friction_min: float | None | Unset
        if isinstance(self.thread_friction_min, Unset):
            thread_friction_min = UNSET
        else:
            thread_friction_min = self.thread_friction_min

        thread_friction_max: float | None | Unset
        if isinstance(self.thread_friction_max, Unset):
            thread_friction_max = UNSET
        else:
            thread_friction_max = self.thread_friction_max

        bearing_friction_mean: float | None | Unset
        if isinstance(self.bearing_friction_mean, Unset):
            bearing_friction_mean = UNSET
        else:
            bearing_friction_mean = self.bearing_friction_mean

        bearing_friction_sd: float | None | Unset
        if isinstance(self.bearing_friction_sd, Unset):
            bearing_friction_sd = UNSET
        else:
            bearing_friction_sd = self.bearing_friction_sd

        bearing_friction_min: float | None | Unset
        if isinstance(self.bearing_friction_min, Unset):
            bearing_friction_min = UNSET
        else:
            bearing_friction_min = self.bearing_friction_min

        bearing_friction_max: float | None | Unset
        if isinstance(self.bearing_friction_max, Unset):
            bearing_friction_max = UNSET
        else:
            bearing_friction_max = self.bearing_friction_max

        total_friction_mean: float | None | Unset
        if isinstance(self.total_friction_mean, Unset):
            total_friction_mean = UNSET
        else:
            total_friction_mean = self.total_friction_mean

        total_friction_sd: float | None | Unset
        if isinstance(self.total_friction_sd, Unset):
            total_friction_sd = UNSET
        else:
            total_friction_sd = self.total_friction_sd

        total_friction_min: float | None | Unset
        if isinstance(self.total_friction_min, Unset):
            total_friction_min = UNSET
        else:
            total_friction_min = self.total_friction_min

        total_friction_max: float | None | Unset
        if isinstance(self.total_friction_max, Unset):
            total_friction_max = UNSET
        else:
            total_friction_max = self.total_friction_max

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if test_count is not UNSET:
            field_dict["test_count"] = test_count
        if thread_diameter is not UNSET:
            field_dict["thread_diameter"] = thread_diameter
        if thread_pitch is not UNSET:
            field_dict["thread_pitch"] = thread_pitch
        if pitch_diameter is not UNSET:
            field_dict["pitch_diameter"] = pitch_diameter
        if bearing_diameter is not UNSET:
            field_dict["bearing_diameter"] = bearing_diameter
        if torque_coefficient_mean is not UNSET:
            field_dict["torque_coefficient_mean"] = torque_coefficient_mean
        if torque_coefficient_sd is not UNSET:
            field_dict["torque_coefficient_sd"] = torque_coefficient_sd
        if torque_coefficient_min is not UNSET:
            field_dict["torque_coefficient_min"] = torque_coefficient_min
        if torque_coefficient_max is not UNSET:
            field_dict["torque_coefficient_max"] = torque_coefficient_max
        if thread_friction_mean is not UNSET:
            field_dict["thread_friction_mean"] = thread_friction_mean
        if thread_friction_sd is not UNSET:
            field_dict["thread_friction_sd"] = thread_friction_sd
        if thread_friction_min is not UNSET:
            field_dict["thread_friction_min"] = thread_friction_min
        if thread_friction_max is not UNSET:
            field_dict["thread_friction_max"] = thread_friction_max
        if bearing_friction_mean is not UNSET:
            field_dict["bearing_friction_mean"] = bearing_friction_mean
        if bearing_friction_sd is not UNSET:
            field_dict["bearing_friction_sd"] = bearing_friction_sd
        if bearing_friction_min is not UNSET:
            field_dict["bearing_friction_min"] = bearing_friction_min
        if bearing_friction_max is not UNSET:
            field_dict["bearing_friction_max"] = bearing_friction_max
        if total_friction_mean is not UNSET:
            field_dict["total_friction_mean"] = total_friction_mean
        if total_friction_sd is not UNSET:
            field_dict["total_friction_sd"] = total_friction_sd
        if total_friction_min is not UNSET:
            field_dict["total_friction_min"] = total_friction_min
        if total_friction_max is not UNSET:
            field_dict["total_friction_max"] = total_friction_max

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_test_count(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        test_count = _parse_test_count(d.pop("test_count", UNSET))

        def _parse_thread_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_diameter = _parse_thread_diameter(d.pop("thread_diameter", UNSET))

        def _parse_thread_pitch(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_pitch = _parse_thread_pitch(d.pop("thread_pitch", UNSET))

        def _parse_pitch_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        pitch_diameter = _parse_pitch_diameter(d.pop("pitch_diameter", UNSET))

        def _parse_bearing_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_diameter = _parse_bearing_diameter(d.pop("bearing_diameter", UNSET))

        def _parse_torque_coefficient_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_coefficient_mean = _parse_torque_coefficient_mean(d.pop("torque_coefficient_mean", UNSET))

        def _parse_torque_coefficient_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_coefficient_sd = _parse_torque_coefficient_sd(d.pop("torque_coefficient_sd", UNSET))

        def _parse_torque_coefficient_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_coefficient_min = _parse_torque_coefficient_min(d.pop("torque_coefficient_min", UNSET))

        def _parse_torque_coefficient_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_coefficient_max = _parse_torque_coefficient_max(d.pop("torque_coefficient_max", UNSET))

        def _parse_thread_friction_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_friction_mean = _parse_thread_friction_mean(d.pop("thread_friction_mean", UNSET))

        def _parse_thread_friction_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_friction_sd = _parse_thread_friction_sd(d.pop("thread_friction_sd", UNSET))

        def _parse_thread_friction_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_friction_min = _parse_thread_friction_min(d.pop("thread_friction_min", UNSET))

        def _parse_thread_friction_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_friction_max = _parse_thread_friction_max(d.pop("thread_friction_max", UNSET))

        def _parse_bearing_friction_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_friction_mean = _parse_bearing_friction_mean(d.pop("bearing_friction_mean", UNSET))

        def _parse_bearing_friction_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_friction_sd = _parse_bearing_friction_sd(d.pop("bearing_friction_sd", UNSET))

        def _parse_bearing_friction_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_friction_min = _parse_bearing_friction_min(d.pop("bearing_friction_min", UNSET))

        def _parse_bearing_friction_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bearing_friction_max = _parse_bearing_friction_max(d.pop("bearing_friction_max", UNSET))

        def _parse_total_friction_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction_mean = _parse_total_friction_mean(d.pop("total_friction_mean", UNSET))

        def _parse_total_friction_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction_sd = _parse_total_friction_sd(d.pop("total_friction_sd", UNSET))

        def _parse_total_friction_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction_min = _parse_total_friction_min(d.pop("total_friction_min", UNSET))

        def _parse_total_friction_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction_max = _parse_total_friction_max(d.pop("total_friction_max", UNSET))

        friction_iso_16047_results = cls(
            test_count=test_count,
            thread_diameter=thread_diameter,
            thread_pitch=thread_pitch,
            pitch_diameter=pitch_diameter,
            bearing_diameter=bearing_diameter,
            torque_coefficient_mean=torque_coefficient_mean,
            torque_coefficient_sd=torque_coefficient_sd,
            torque_coefficient_min=torque_coefficient_min,
            torque_coefficient_max=torque_coefficient_max,
            thread_friction_mean=thread_friction_mean,
            thread_friction_sd=thread_friction_sd,
            thread_friction_min=thread_friction_min,
            thread_friction_max=thread_friction_max,
            bearing_friction_mean=bearing_friction_mean,
            bearing_friction_sd=bearing_friction_sd,
            bearing_friction_min=bearing_friction_min,
            bearing_friction_max=bearing_friction_max,
            total_friction_mean=total_friction_mean,
            total_friction_sd=total_friction_sd,
            total_friction_min=total_friction_min,
            total_friction_max=total_friction_max,
        )

        friction_iso_16047_results.additional_properties = d
        return friction_iso_16047_results

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
