from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="TraceBatchResults")


@_attrs_define
class TraceBatchResults:
    """
    Attributes:
        traces (int | None | Unset): Traces read [dimensionless]
        friction_mean (float | None | Unset): Mean of the traces' total friction μ_ges [dimensionless]
        friction_sd (float | None | Unset): Sample standard deviation of μ_ges [dimensionless]
        preload_mean (float | None | Unset): Mean of the traces' preload at their peak torque [N]
        preload_sd (float | None | Unset): Sample standard deviation of the preload [N]
        preload_lowest (float | None | Unset): Lowest preload of the batch [N]
        preload_highest (float | None | Unset): Highest preload of the batch [N]
        outlier_count (int | None | Unset): Traces whose friction lies apart from the others' [dimensionless]
        outlier_traces (None | str | Unset): Those traces, counted from 1 as trace_number, comma-separated (empty: none)
            [dimensionless]
        traces_in_window (int | None | Unset): Traces whose preload bounds lie within F_M,min…F_M,zul [dimensionless]
        capability_index (float | None | Unset): C_p of the preload against F_M,min…F_M,zul [dimensionless]
        critical_capability_index (float | None | Unset): C_pk of the preload against F_M,min…F_M,zul [dimensionless]
        assembly_preload_min (float | None | Unset): The joint's F_M,min (lower end of its window) [N]
        permissible_preload (float | None | Unset): The joint's F_M,zul (upper end of its window) [N]
    """

    traces: int | None | Unset = UNSET
    friction_mean: float | None | Unset = UNSET
    friction_sd: float | None | Unset = UNSET
    preload_mean: float | None | Unset = UNSET
    preload_sd: float | None | Unset = UNSET
    preload_lowest: float | None | Unset = UNSET
    preload_highest: float | None | Unset = UNSET
    outlier_count: int | None | Unset = UNSET
    outlier_traces: None | str | Unset = UNSET
    traces_in_window: int | None | Unset = UNSET
    capability_index: float | None | Unset = UNSET
    critical_capability_index: float | None | Unset = UNSET
    assembly_preload_min: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        traces: int | None | Unset
        if isinstance(self.traces, Unset):
            traces = UNSET
        else:
            traces = self.traces

        friction_mean: float | None | Unset
        if isinstance(self.friction_mean, Unset):
            friction_mean = UNSET
        else:
            friction_mean = self.friction_mean

        friction_sd: float | None | Unset
        if isinstance(self.friction_sd, Unset):
            friction_sd = UNSET
        else:
            friction_sd = self.friction_sd

        preload_mean: float | None | Unset
        if isinstance(self.preload_mean, Unset):
            preload_mean = UNSET
        else:
            preload_mean = self.preload_mean

        preload_sd: float | None | Unset
        if isinstance(self.preload_sd, Unset):
            preload_sd = UNSET
        else:
            preload_sd = self.preload_sd

        preload_lowest: float | None | Unset
        if isinstance(self.preload_lowest, Unset):
            preload_lowest = UNSET
        else:
            preload_lowest = self.preload_lowest

        preload_highest: float | None | Unset
        if isinstance(self.preload_highest, Unset):
            preload_highest = UNSET
        else:
            preload_highest = self.preload_highest

        outlier_count: int | None | Unset
        if isinstance(self.outlier_count, Unset):
            outlier_count = UNSET
        else:
            outlier_count = self.outlier_count

        outlier_traces: None | str | Unset
        if isinstance(self.outlier_traces, Unset):
            outlier_traces = UNSET
        else:
            outlier_traces = self.outlier_traces

        traces_in_window: int | None | Unset
        if isinstance(self.traces_in_window, Unset):
            traces_in_window = UNSET
        else:
            traces_in_window = self.traces_in_window

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

        assembly_preload_min: float | None | Unset
        if isinstance(self.assembly_preload_min, Unset):
            assembly_preload_min = UNSET
        else:
            assembly_preload_min = self.assembly_preload_min

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if traces is not UNSET:
            field_dict["traces"] = traces
        if friction_mean is not UNSET:
            field_dict["friction_mean"] = friction_mean
        if friction_sd is not UNSET:
            field_dict["friction_sd"] = friction_sd
        if preload_mean is not UNSET:
            field_dict["preload_mean"] = preload_mean
        if preload_sd is not UNSET:
            field_dict["preload_sd"] = preload_sd
        if preload_lowest is not UNSET:
            field_dict["preload_lowest"] = preload_lowest
        if preload_highest is not UNSET:
            field_dict["preload_highest"] = preload_highest
        if outlier_count is not UNSET:
            field_dict["outlier_count"] = outlier_count
        if outlier_traces is not UNSET:
            field_dict["outlier_traces"] = outlier_traces
        if traces_in_window is not UNSET:
            field_dict["traces_in_window"] = traces_in_window
        if capability_index is not UNSET:
            field_dict["capability_index"] = capability_index
        if critical_capability_index is not UNSET:
            field_dict["critical_capability_index"] = critical_capability_index
        if assembly_preload_min is not UNSET:
            field_dict["assembly_preload_min"] = assembly_preload_min
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_traces(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        traces = _parse_traces(d.pop("traces", UNSET))

        def _parse_friction_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        friction_mean = _parse_friction_mean(d.pop("friction_mean", UNSET))

        def _parse_friction_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        friction_sd = _parse_friction_sd(d.pop("friction_sd", UNSET))

        def _parse_preload_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_mean = _parse_preload_mean(d.pop("preload_mean", UNSET))

        def _parse_preload_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_sd = _parse_preload_sd(d.pop("preload_sd", UNSET))

        def _parse_preload_lowest(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_lowest = _parse_preload_lowest(d.pop("preload_lowest", UNSET))

        def _parse_preload_highest(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_highest = _parse_preload_highest(d.pop("preload_highest", UNSET))

        def _parse_outlier_count(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        outlier_count = _parse_outlier_count(d.pop("outlier_count", UNSET))

        def _parse_outlier_traces(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        outlier_traces = _parse_outlier_traces(d.pop("outlier_traces", UNSET))

        def _parse_traces_in_window(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        traces_in_window = _parse_traces_in_window(d.pop("traces_in_window", UNSET))

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

        def _parse_assembly_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload_min = _parse_assembly_preload_min(d.pop("assembly_preload_min", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        trace_batch_results = cls(
            traces=traces,
            friction_mean=friction_mean,
            friction_sd=friction_sd,
            preload_mean=preload_mean,
            preload_sd=preload_sd,
            preload_lowest=preload_lowest,
            preload_highest=preload_highest,
            outlier_count=outlier_count,
            outlier_traces=outlier_traces,
            traces_in_window=traces_in_window,
            capability_index=capability_index,
            critical_capability_index=critical_capability_index,
            assembly_preload_min=assembly_preload_min,
            permissible_preload=permissible_preload,
        )

        trace_batch_results.additional_properties = d
        return trace_batch_results

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
