from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="JointAuditResults")


@_attrs_define
class JointAuditResults:
    """
    Attributes:
        first_motion_min (float | None | Unset): First motion in the tightening direction, read at once: least [N*m]
        first_motion_max (float | None | Unset): First motion, read at once: most [N*m]
        first_motion_embedded_min (float | None | Unset): First motion after embedding: least [N*m]
        first_motion_embedded_max (float | None | Unset): First motion after embedding: most [N*m]
        breakaway_min (float | None | Unset): Breakaway in the loosening direction, read at once: least [N*m]
        breakaway_max (float | None | Unset): Breakaway (loosening), read at once: most [N*m]
        breakaway_embedded_min (float | None | Unset): Breakaway (loosening) after embedding: least [N*m]
        breakaway_embedded_max (float | None | Unset): Breakaway (loosening) after embedding: most [N*m]
        mark_min (float | None | Unset): Mark torque (back to the mark, turning), read at once: least [N*m]
        mark_max (float | None | Unset): Mark torque, read at once: most [N*m]
        mark_embedded_min (float | None | Unset): Mark torque after embedding: least [N*m]
        mark_embedded_max (float | None | Unset): Mark torque after embedding: most [N*m]
        assembly_preload_min (float | None | Unset): F_M,min the torque band gives (R13) [N]
        assembly_preload_max (float | None | Unset): F_M,max the torque band gives (R13) [N]
        embedding_loss (float | None | Unset): F_Z of the joint model (R4) [N]
        residual_preload_min (float | None | Unset): F_M,min − F_Z after embedding [N]
        residual_preload_max (float | None | Unset): F_M,max − F_Z after embedding [N]
    """

    first_motion_min: float | None | Unset = UNSET
    first_motion_max: float | None | Unset = UNSET
    first_motion_embedded_min: float | None | Unset = UNSET
    first_motion_embedded_max: float | None | Unset = UNSET
    breakaway_min: float | None | Unset = UNSET
    breakaway_max: float | None | Unset = UNSET
    breakaway_embedded_min: float | None | Unset = UNSET
    breakaway_embedded_max: float | None | Unset = UNSET
    mark_min: float | None | Unset = UNSET
    mark_max: float | None | Unset = UNSET
    mark_embedded_min: float | None | Unset = UNSET
    mark_embedded_max: float | None | Unset = UNSET
    assembly_preload_min: float | None | Unset = UNSET
    assembly_preload_max: float | None | Unset = UNSET
    embedding_loss: float | None | Unset = UNSET
    residual_preload_min: float | None | Unset = UNSET
    residual_preload_max: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        first_motion_min: float | None | Unset
        if isinstance(self.first_motion_min, Unset):
            first_motion_min = UNSET
        else:
            first_motion_min = self.first_motion_min

        first_motion_max: float | None | Unset
        if isinstance(self.first_motion_max, Unset):
            first_motion_max = UNSET
        else:
            first_motion_max = self.first_motion_max

        first_motion_embedded_min: float | None | Unset
        if isinstance(self.first_motion_embedded_min, Unset):
            first_motion_embedded_min = UNSET
        else:
            first_motion_embedded_min = self.first_motion_embedded_min

        first_motion_embedded_max: float | None | Unset
        if isinstance(self.first_motion_embedded_max, Unset):
            first_motion_embedded_max = UNSET
        else:
            first_motion_embedded_max = self.first_motion_embedded_max

        breakaway_min: float | None | Unset
        if isinstance(self.breakaway_min, Unset):
            breakaway_min = UNSET
        else:
            breakaway_min = self.breakaway_min

        breakaway_max: float | None | Unset
        if isinstance(self.breakaway_max, Unset):
            breakaway_max = UNSET
        else:
            breakaway_max = self.breakaway_max

        breakaway_embedded_min: float | None | Unset
        if isinstance(self.breakaway_embedded_min, Unset):
            breakaway_embedded_min = UNSET
        else:
            breakaway_embedded_min = self.breakaway_embedded_min

        breakaway_embedded_max: float | None | Unset
        if isinstance(self.breakaway_embedded_max, Unset):
            breakaway_embedded_max = UNSET
        else:
            breakaway_embedded_max = self.breakaway_embedded_max

        mark_min: float | None | Unset
        if isinstance(self.mark_min, Unset):
            mark_min = UNSET
        else:
            mark_min = self.mark_min

        mark_max: float | None | Unset
        if isinstance(self.mark_max, Unset):
            mark_max = UNSET
        else:
            mark_max = self.mark_max

        mark_embedded_min: float | None | Unset
        if isinstance(self.mark_embedded_min, Unset):
            mark_embedded_min = UNSET
        else:
            mark_embedded_min = self.mark_embedded_min

        mark_embedded_max: float | None | Unset
        if isinstance(self.mark_embedded_max, Unset):
            mark_embedded_max = UNSET
        else:
            mark_embedded_max = self.mark_embedded_max

        assembly_preload_min: float | None | Unset
        if isinstance(self.assembly_preload_min, Unset):
            assembly_preload_min = UNSET
        else:
            assembly_preload_min = self.assembly_preload_min

        assembly_preload_max: float | None | Unset
        if isinstance(self.assembly_preload_max, Unset):
            assembly_preload_max = UNSET
        else:
            assembly_preload_max = self.assembly_preload_max

        embedding_loss: float | None | Unset
        if isinstance(self.embedding_loss, Unset):
            embedding_loss = UNSET
        else:
            embedding_loss = self.embedding_loss

        residual_preload_min: float | None | Unset
        if isinstance(self.residual_preload_min, Unset):
            residual_preload_min = UNSET
        else:
            residual_preload_min = self.residual_preload_min

        residual_preload_max: float | None | Unset
        if isinstance(self.residual_preload_max, Unset):
            residual_preload_max = UNSET
        else:
            residual_preload_max = self.residual_preload_max

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if first_motion_min is not UNSET:
            field_dict["first_motion_min"] = first_motion_min
        if first_motion_max is not UNSET:
            field_dict["first_motion_max"] = first_motion_max
        if first_motion_embedded_min is not UNSET:
            field_dict["first_motion_embedded_min"] = first_motion_embedded_min
        if first_motion_embedded_max is not UNSET:
            field_dict["first_motion_embedded_max"] = first_motion_embedded_max
        if breakaway_min is not UNSET:
            field_dict["breakaway_min"] = breakaway_min
        if breakaway_max is not UNSET:
            field_dict["breakaway_max"] = breakaway_max
        if breakaway_embedded_min is not UNSET:
            field_dict["breakaway_embedded_min"] = breakaway_embedded_min
        if breakaway_embedded_max is not UNSET:
            field_dict["breakaway_embedded_max"] = breakaway_embedded_max
        if mark_min is not UNSET:
            field_dict["mark_min"] = mark_min
        if mark_max is not UNSET:
            field_dict["mark_max"] = mark_max
        if mark_embedded_min is not UNSET:
            field_dict["mark_embedded_min"] = mark_embedded_min
        if mark_embedded_max is not UNSET:
            field_dict["mark_embedded_max"] = mark_embedded_max
        if assembly_preload_min is not UNSET:
            field_dict["assembly_preload_min"] = assembly_preload_min
        if assembly_preload_max is not UNSET:
            field_dict["assembly_preload_max"] = assembly_preload_max
        if embedding_loss is not UNSET:
            field_dict["embedding_loss"] = embedding_loss
        if residual_preload_min is not UNSET:
            field_dict["residual_preload_min"] = residual_preload_min
        if residual_preload_max is not UNSET:
            field_dict["residual_preload_max"] = residual_preload_max

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_first_motion_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        first_motion_min = _parse_first_motion_min(d.pop("first_motion_min", UNSET))

        def _parse_first_motion_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        first_motion_max = _parse_first_motion_max(d.pop("first_motion_max", UNSET))

        def _parse_first_motion_embedded_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        first_motion_embedded_min = _parse_first_motion_embedded_min(d.pop("first_motion_embedded_min", UNSET))

        def _parse_first_motion_embedded_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        first_motion_embedded_max = _parse_first_motion_embedded_max(d.pop("first_motion_embedded_max", UNSET))

        def _parse_breakaway_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        breakaway_min = _parse_breakaway_min(d.pop("breakaway_min", UNSET))

        def _parse_breakaway_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        breakaway_max = _parse_breakaway_max(d.pop("breakaway_max", UNSET))

        def _parse_breakaway_embedded_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        breakaway_embedded_min = _parse_breakaway_embedded_min(d.pop("breakaway_embedded_min", UNSET))

        def _parse_breakaway_embedded_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        breakaway_embedded_max = _parse_breakaway_embedded_max(d.pop("breakaway_embedded_max", UNSET))

        def _parse_mark_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mark_min = _parse_mark_min(d.pop("mark_min", UNSET))

        def _parse_mark_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mark_max = _parse_mark_max(d.pop("mark_max", UNSET))

        def _parse_mark_embedded_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mark_embedded_min = _parse_mark_embedded_min(d.pop("mark_embedded_min", UNSET))

        def _parse_mark_embedded_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mark_embedded_max = _parse_mark_embedded_max(d.pop("mark_embedded_max", UNSET))

        def _parse_assembly_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload_min = _parse_assembly_preload_min(d.pop("assembly_preload_min", UNSET))

        def _parse_assembly_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload_max = _parse_assembly_preload_max(d.pop("assembly_preload_max", UNSET))

        def _parse_embedding_loss(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        embedding_loss = _parse_embedding_loss(d.pop("embedding_loss", UNSET))

        def _parse_residual_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        residual_preload_min = _parse_residual_preload_min(d.pop("residual_preload_min", UNSET))

        def _parse_residual_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        residual_preload_max = _parse_residual_preload_max(d.pop("residual_preload_max", UNSET))

        joint_audit_results = cls(
            first_motion_min=first_motion_min,
            first_motion_max=first_motion_max,
            first_motion_embedded_min=first_motion_embedded_min,
            first_motion_embedded_max=first_motion_embedded_max,
            breakaway_min=breakaway_min,
            breakaway_max=breakaway_max,
            breakaway_embedded_min=breakaway_embedded_min,
            breakaway_embedded_max=breakaway_embedded_max,
            mark_min=mark_min,
            mark_max=mark_max,
            mark_embedded_min=mark_embedded_min,
            mark_embedded_max=mark_embedded_max,
            assembly_preload_min=assembly_preload_min,
            assembly_preload_max=assembly_preload_max,
            embedding_loss=embedding_loss,
            residual_preload_min=residual_preload_min,
            residual_preload_max=residual_preload_max,
        )

        joint_audit_results.additional_properties = d
        return joint_audit_results

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
