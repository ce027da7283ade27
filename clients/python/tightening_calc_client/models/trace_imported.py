from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.trace_imported_units import TraceImportedUnits
    from ..models.trace_inputs import TraceInputs


T = TypeVar("T", bound="TraceImported")


@_attrs_define
class TraceImported:
    """
    Attributes:
        format_ (str):
        source (str):
        samples (int):
        inputs (TraceInputs):
        units (TraceImportedUnits):
    """

    format_: str
    source: str
    samples: int
    inputs: TraceInputs
    units: TraceImportedUnits
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        format_ = self.format_

        source = self.source

        samples = self.samples

        inputs = self.inputs.to_dict()

        units = self.units.to_dict()

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "format": format_,
                "source": source,
                "samples": samples,
                "inputs": inputs,
                "units": units,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.trace_imported_units import TraceImportedUnits  # noqa: PLC0415
        from ..models.trace_inputs import TraceInputs  # noqa: PLC0415

        d = dict(src_dict)
        format_ = d.pop("format")

        source = d.pop("source")

        samples = d.pop("samples")

        inputs = TraceInputs.from_dict(d.pop("inputs"))

        units = TraceImportedUnits.from_dict(d.pop("units"))

        trace_imported = cls(
            format_=format_,
            source=source,
            samples=samples,
            inputs=inputs,
            units=units,
        )

        trace_imported.additional_properties = d
        return trace_imported

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
