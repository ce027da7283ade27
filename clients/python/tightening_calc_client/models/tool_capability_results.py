from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="ToolCapabilityResults")


@_attrs_define
class ToolCapabilityResults:
    """
    Attributes:
        mean_torque (float | None | Unset): Mean x̄ of the measured torques [N*m]
        torque_sd (float | None | Unset): Standard deviation s (n − 1) [N*m]
        sample_count (int | None | Unset): Number of values n (null: not given) [dimensionless]
        minimum_sample_count (int | None | Unset): Fewest values the chosen test takes [dimensionless]
        min_torque (float | None | Unset): Smallest measured torque (null without samples) [N*m]
        max_torque (float | None | Unset): Largest measured torque (null without samples) [N*m]
        lower_limit (float | None | Unset): Lower tolerance limit L [N*m]
        upper_limit (float | None | Unset): Upper tolerance limit U [N*m]
        capability_index (float | None | Unset): Cm (machine) or Cp (process): (U − L)/(6s) [dimensionless]
        critical_capability_index (float | None | Unset): Cmk (machine) or Cpk (process): min(U − x̄, x̄ − L)/(3s)
            [dimensionless]
        index_names (None | str | Unset): Which pair the two indices are: 'Cm/Cmk' or 'Cp/Cpk' [dimensionless]
        required_index (float | None | Unset): The index both must reach [dimensionless]
        mean_offset (float | None | Unset): Mean's distance from the middle of the tolerance, as a share of half the
            tolerance [dimensionless]
        outside_ppm (float | None | Unset): Share outside the tolerance if the torques were normal with x̄ and s, in ppm
            [dimensionless]
        torque_scatter (float | None | Unset): The tool's scatter as makers rate it: ±3s over the mean (null at a mean
            of 0) [dimensionless]
        hard_mean_torque (float | None | Unset): Mean of the hard-joint run (null without ISO 5393 runs) [N*m]
        soft_mean_torque (float | None | Unset): Mean of the soft-joint run (null without ISO 5393 runs) [N*m]
        hard_torque_sd (float | None | Unset): s of the hard-joint run (null without ISO 5393 runs) [N*m]
        soft_torque_sd (float | None | Unset): s of the soft-joint run (null without ISO 5393 runs) [N*m]
        mean_shift (float | None | Unset): Mean shift x̄_soft − x̄_hard between the runs (null without ISO 5393 runs)
            [N*m]
        capable (bool | None | Unset): Both indices reach the required index and n is large enough [dimensionless]
    """

    mean_torque: float | None | Unset = UNSET
    torque_sd: float | None | Unset = UNSET
    sample_count: int | None | Unset = UNSET
    minimum_sample_count: int | None | Unset = UNSET
    min_torque: float | None | Unset = UNSET
    max_torque: float | None | Unset = UNSET
    lower_limit: float | None | Unset = UNSET
    upper_limit: float | None | Unset = UNSET
    capability_index: float | None | Unset = UNSET
    critical_capability_index: float | None | Unset = UNSET
    index_names: None | str | Unset = UNSET
    required_index: float | None | Unset = UNSET
    mean_offset: float | None | Unset = UNSET
    outside_ppm: float | None | Unset = UNSET
    torque_scatter: float | None | Unset = UNSET
    hard_mean_torque: float | None | Unset = UNSET
    soft_mean_torque: float | None | Unset = UNSET
    hard_torque_sd: float | None | Unset = UNSET
    soft_torque_sd: float | None | Unset = UNSET
    mean_shift: float | None | Unset = UNSET
    capable: bool | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        mean_torque: float | None | Unset
        if isinstance(self.mean_torque, Unset):
            mean_torque = UNSET
        else:
            mean_torque = self.mean_torque

        torque_sd: float | None | Unset
        if isinstance(self.torque_sd, Unset):
            torque_sd = UNSET
        else:
            torque_sd = self.torque_sd

        sample_count: int | None | Unset
        if isinstance(self.sample_count, Unset):
            sample_count = UNSET
        else:
            sample_count = self.sample_count

        minimum_sample_count: int | None | Unset
        if isinstance(self.minimum_sample_count, Unset):
            minimum_sample_count = UNSET
        else:
            minimum_sample_count = self.minimum_sample_count

        min_torque: float | None | Unset
        if isinstance(self.min_torque, Unset):
            min_torque = UNSET
        else:
            min_torque = self.min_torque

        max_torque: float | None | Unset
        if isinstance(self.max_torque, Unset):
            max_torque = UNSET
        else:
            max_torque = self.max_torque

        lower_limit: float | None | Unset
        if isinstance(self.lower_limit, Unset):
            lower_limit = UNSET
        else:
            lower_limit = self.lower_limit

        upper_limit: float | None | Unset
        if isinstance(self.upper_limit, Unset):
            upper_limit = UNSET
        else:
            upper_limit = self.upper_limit

        capability_index: float | None | Unset
        if isinstance(self.capability_index, Unset):
            capability_index = UNSET
        else:
            capability_index = self.capability_index

        critical_capability_index: float | None | Unset
        if isinstance(self.critical_capability_index, Unset):
            critical_capability_index = UNSET
        else:
            critical_capability_index = self.critical_capability_index

        index_names: None | str | Unset
        if isinstance(self.index_names, Unset):
            index_names = UNSET
        else:
            index_names = self.index_names

        required_index: float | None | Unset
        if isinstance(self.required_index, Unset):
            required_index = UNSET
        else:
            required_index = self.required_index

        mean_offset: float | None | Unset
        if isinstance(self.mean_offset, Unset):
            mean_offset = UNSET
        else:
            mean_offset = self.mean_offset

        outside_ppm: float | None | Unset
        if isinstance(self.outside_ppm, Unset):
            outside_ppm = UNSET
        else:
            outside_ppm = self.outside_ppm

        torque_scatter: float | None | Unset
        if isinstance(self.torque_scatter, Unset):
            torque_scatter = UNSET
        else:
            torque_scatter = self.torque_scatter

        hard_mean_torque: float | None | Unset
        if isinstance(self.hard_mean_torque, Unset):
            hard_mean_torque = UNSET
        else:
            hard_mean_torque = self.hard_mean_torque

        soft_mean_torque: float | None | Unset
        if isinstance(self.soft_mean_torque, Unset):
            soft_mean_torque = UNSET
        else:
            soft_mean_torque = self.soft_mean_torque

        hard_torque_sd: float | None | Unset
        if isinstance(self.hard_torque_sd, Unset):
            hard_torque_sd = UNSET
        else:
            hard_torque_sd = self.hard_torque_sd

        soft_torque_sd: float | None | Unset
        if isinstance(self.soft_torque_sd, Unset):
            soft_torque_sd = UNSET
        else:
            soft_torque_sd = self.soft_torque_sd

        mean_shift: float | None | Unset
        if isinstance(self.mean_shift, Unset):
            mean_shift = UNSET
        else:
            mean_shift = self.mean_shift

        capable: bool | None | Unset
        if isinstance(self.capable, Unset):
            capable = UNSET
        else:
            capable = self.capable

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if mean_torque is not UNSET:
            field_dict["mean_torque"] = mean_torque
        if torque_sd is not UNSET:
            field_dict["torque_sd"] = torque_sd
        if sample_count is not UNSET:
            field_dict["sample_count"] = sample_count
        if minimum_sample_count is not UNSET:
            field_dict["minimum_sample_count"] = minimum_sample_count
        if min_torque is not UNSET:
            field_dict["min_torque"] = min_torque
        if max_torque is not UNSET:
            field_dict["max_torque"] = max_torque
        if lower_limit is not UNSET:
            field_dict["lower_limit"] = lower_limit
        if upper_limit is not UNSET:
            field_dict["upper_limit"] = upper_limit
        if capability_index is not UNSET:
            field_dict["capability_index"] = capability_index
        if critical_capability_index is not UNSET:
            field_dict["critical_capability_index"] = critical_capability_index
        if index_names is not UNSET:
            field_dict["index_names"] = index_names
        if required_index is not UNSET:
            field_dict["required_index"] = required_index
        if mean_offset is not UNSET:
            field_dict["mean_offset"] = mean_offset
        if outside_ppm is not UNSET:
            field_dict["outside_ppm"] = outside_ppm
        if torque_scatter is not UNSET:
            field_dict["torque_scatter"] = torque_scatter
        if hard_mean_torque is not UNSET:
            field_dict["hard_mean_torque"] = hard_mean_torque
        if soft_mean_torque is not UNSET:
            field_dict["soft_mean_torque"] = soft_mean_torque
        if hard_torque_sd is not UNSET:
            field_dict["hard_torque_sd"] = hard_torque_sd
        if soft_torque_sd is not UNSET:
            field_dict["soft_torque_sd"] = soft_torque_sd
        if mean_shift is not UNSET:
            field_dict["mean_shift"] = mean_shift
        if capable is not UNSET:
            field_dict["capable"] = capable

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_mean_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mean_torque = _parse_mean_torque(d.pop("mean_torque", UNSET))

        def _parse_torque_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_sd = _parse_torque_sd(d.pop("torque_sd", UNSET))

        def _parse_sample_count(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        sample_count = _parse_sample_count(d.pop("sample_count", UNSET))

        def _parse_minimum_sample_count(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        minimum_sample_count = _parse_minimum_sample_count(d.pop("minimum_sample_count", UNSET))

        def _parse_min_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        min_torque = _parse_min_torque(d.pop("min_torque", UNSET))

        def _parse_max_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_torque = _parse_max_torque(d.pop("max_torque", UNSET))

        def _parse_lower_limit(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        lower_limit = _parse_lower_limit(d.pop("lower_limit", UNSET))

        def _parse_upper_limit(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        upper_limit = _parse_upper_limit(d.pop("upper_limit", UNSET))

        def _parse_capability_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        capability_index = _parse_capability_index(d.pop("capability_index", UNSET))

        def _parse_critical_capability_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        critical_capability_index = _parse_critical_capability_index(d.pop("critical_capability_index", UNSET))

        def _parse_index_names(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        index_names = _parse_index_names(d.pop("index_names", UNSET))

        def _parse_required_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_index = _parse_required_index(d.pop("required_index", UNSET))

        def _parse_mean_offset(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mean_offset = _parse_mean_offset(d.pop("mean_offset", UNSET))

        def _parse_outside_ppm(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        outside_ppm = _parse_outside_ppm(d.pop("outside_ppm", UNSET))

        def _parse_torque_scatter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_scatter = _parse_torque_scatter(d.pop("torque_scatter", UNSET))

        def _parse_hard_mean_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        hard_mean_torque = _parse_hard_mean_torque(d.pop("hard_mean_torque", UNSET))

        def _parse_soft_mean_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        soft_mean_torque = _parse_soft_mean_torque(d.pop("soft_mean_torque", UNSET))

        def _parse_hard_torque_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        hard_torque_sd = _parse_hard_torque_sd(d.pop("hard_torque_sd", UNSET))

        def _parse_soft_torque_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        soft_torque_sd = _parse_soft_torque_sd(d.pop("soft_torque_sd", UNSET))

        def _parse_mean_shift(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mean_shift = _parse_mean_shift(d.pop("mean_shift", UNSET))

        def _parse_capable(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        capable = _parse_capable(d.pop("capable", UNSET))

        tool_capability_results = cls(
            mean_torque=mean_torque,
            torque_sd=torque_sd,
            sample_count=sample_count,
            minimum_sample_count=minimum_sample_count,
            min_torque=min_torque,
            max_torque=max_torque,
            lower_limit=lower_limit,
            upper_limit=upper_limit,
            capability_index=capability_index,
            critical_capability_index=critical_capability_index,
            index_names=index_names,
            required_index=required_index,
            mean_offset=mean_offset,
            outside_ppm=outside_ppm,
            torque_scatter=torque_scatter,
            hard_mean_torque=hard_mean_torque,
            soft_mean_torque=soft_mean_torque,
            hard_torque_sd=hard_torque_sd,
            soft_torque_sd=soft_torque_sd,
            mean_shift=mean_shift,
            capable=capable,
        )

        tool_capability_results.additional_properties = d
        return tool_capability_results

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
