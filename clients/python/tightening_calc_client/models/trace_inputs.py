from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="TraceInputs")


@_attrs_define
class TraceInputs:
    """
    Attributes:
        angle (list[float]):
        torque (list[float]):
        time (list[float] | None | Unset):
    """

    angle: list[float]
    torque: list[float]
    time: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        angle = self.angle

        torque = self.torque

        time: list[float] | None | Unset
        if isinstance(self.time, Unset):
            time = UNSET
        elif isinstance(self.time, list):
            time = self.time

        else:
            time = self.time

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "angle": angle,
                "torque": torque,
            }
        )
        if time is not UNSET:
            field_dict["time"] = time

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        angle = cast(list[float], d.pop("angle"))

        torque = cast(list[float], d.pop("torque"))

        def _parse_time(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                time_type_0 = cast(list[float], data)

                return time_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        time = _parse_time(d.pop("time", UNSET))

        trace_inputs = cls(
            angle=angle,
            torque=torque,
            time=time,
        )

        trace_inputs.additional_properties = d
        return trace_inputs

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
