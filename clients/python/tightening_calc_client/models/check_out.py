from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.check_out_level import CheckOutLevel
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.quantity_out import QuantityOut


T = TypeVar("T", bound="CheckOut")


@_attrs_define
class CheckOut:
    """
    Attributes:
        name (str):
        ok (bool):
        detail (str):
        level (CheckOutLevel | Unset):  Default: CheckOutLevel.REQUIREMENT.
        detail_parts (list[QuantityOut | str] | Unset): detail as texts and quantities (SI values)
    """

    name: str
    ok: bool
    detail: str
    level: CheckOutLevel | Unset = CheckOutLevel.REQUIREMENT
    detail_parts: list[QuantityOut | str] | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.quantity_out import QuantityOut  # noqa: PLC0415

        name = self.name

        ok = self.ok

        detail = self.detail

        level: str | Unset = UNSET
        if not isinstance(self.level, Unset):
            level = self.level.value

        detail_parts: list[dict[str, Any] | str] | Unset = UNSET
        if not isinstance(self.detail_parts, Unset):
            detail_parts = []
            for detail_parts_item_data in self.detail_parts:
                detail_parts_item: dict[str, Any] | str
                if isinstance(detail_parts_item_data, QuantityOut):
                    detail_parts_item = detail_parts_item_data.to_dict()
                else:
                    detail_parts_item = detail_parts_item_data
                detail_parts.append(detail_parts_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "ok": ok,
                "detail": detail,
            }
        )
        if level is not UNSET:
            field_dict["level"] = level
        if detail_parts is not UNSET:
            field_dict["detail_parts"] = detail_parts

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.quantity_out import QuantityOut  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        ok = d.pop("ok")

        detail = d.pop("detail")

        _level = d.pop("level", UNSET)
        level: CheckOutLevel | Unset
        if isinstance(_level, Unset):
            level = UNSET
        else:
            level = CheckOutLevel(_level)

        _detail_parts = d.pop("detail_parts", UNSET)
        detail_parts: list[QuantityOut | str] | Unset = UNSET
        if _detail_parts is not UNSET:
            detail_parts = []
            for detail_parts_item_data in _detail_parts:

                def _parse_detail_parts_item(data: object) -> QuantityOut | str:
                    try:
                        if not isinstance(data, dict):
                            raise TypeError()
                        detail_parts_item_type_1 = QuantityOut.from_dict(data)

                        return detail_parts_item_type_1
                    except (TypeError, ValueError, AttributeError, KeyError):
                        pass
                    return cast(QuantityOut | str, data)

                detail_parts_item = _parse_detail_parts_item(detail_parts_item_data)

                detail_parts.append(detail_parts_item)

        check_out = cls(
            name=name,
            ok=ok,
            detail=detail,
            level=level,
            detail_parts=detail_parts,
        )

        check_out.additional_properties = d
        return check_out

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
