from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="QuantityOut")


@_attrs_define
class QuantityOut:
    """A number in a check's or a note's sentence, as data: the form writes it in the
    unit system the user chose.

        Attributes:
            value (float | None): SI value (null: not finite)
            unit (str): SI unit, as the model's outputs write units
            display_unit (str): the unit the plain sentence writes it in
            digits (int): significant digits the plain sentence shows
            text (str): the quantity as the plain sentence writes it
            bare (bool | Unset): the text is the number alone (a range's first value) Default: False.
    """

    value: float | None
    unit: str
    display_unit: str
    digits: int
    text: str
    bare: bool | Unset = False
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        value: float | None
        value = self.value

        unit = self.unit

        display_unit = self.display_unit

        digits = self.digits

        text = self.text

        bare = self.bare

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "value": value,
                "unit": unit,
                "display_unit": display_unit,
                "digits": digits,
                "text": text,
            }
        )
        if bare is not UNSET:
            field_dict["bare"] = bare

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_value(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        value = _parse_value(d.pop("value"))

        unit = d.pop("unit")

        display_unit = d.pop("display_unit")

        digits = d.pop("digits")

        text = d.pop("text")

        bare = d.pop("bare", UNSET)

        quantity_out = cls(
            value=value,
            unit=unit,
            display_unit=display_unit,
            digits=digits,
            text=text,
            bare=bare,
        )

        quantity_out.additional_properties = d
        return quantity_out

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
