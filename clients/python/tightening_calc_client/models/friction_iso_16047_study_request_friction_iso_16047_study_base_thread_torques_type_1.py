from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

T = TypeVar("T", bound="FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1")


@_attrs_define
class FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1:
    """
    Attributes:
        values (list[float]):
        unit (str):
    """

    values: list[float]
    unit: str

    def to_dict(self) -> dict[str, Any]:
        values = self.values

        unit = self.unit

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "values": values,
                "unit": unit,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        values = cast(list[float], d.pop("values"))

        unit = d.pop("unit")

        friction_iso_16047_study_request_friction_iso_16047_study_base_thread_torques_type_1 = cls(
            values=values,
            unit=unit,
        )

        return friction_iso_16047_study_request_friction_iso_16047_study_base_thread_torques_type_1
