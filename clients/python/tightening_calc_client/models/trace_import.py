from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.trace_import_format import TraceImportFormat
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.trace_import_content_type_2 import TraceImportContentType2


T = TypeVar("T", bound="TraceImport")


@_attrs_define
class TraceImport:
    """A trace as a tool exported it.

    Attributes:
        format_ (TraceImportFormat): csv: text with a header row; open_protocol: decoded MID 0900 messages (a list);
            opc_ua: StepTraceDataType values (one or a list); rexroth: a result JSON
        content (list[Any] | str | TraceImportContentType2): The CSV text; or the JSON, decoded or as text
        angle_column (str | Unset): CSV: the angle's column Default: 'angle'.
        torque_column (str | Unset): CSV: the torque's column Default: 'torque'.
        time_column (None | str | Unset): CSV: the time's column (absent: no times)
        angle_unit (str | Unset): CSV: unit of the angles Default: 'deg'.
        torque_unit (str | Unset): CSV: unit of the torques Default: 'N*m'.
        time_unit (str | Unset): CSV: unit of the times Default: 's'.
        delimiter (None | str | Unset): CSV: the delimiter (absent: sniffed)
        decimal_comma (bool | Unset): CSV: numbers written 0,5 for 0.5 Default: False.
    """

    format_: TraceImportFormat
    content: list[Any] | str | TraceImportContentType2
    angle_column: str | Unset = "angle"
    torque_column: str | Unset = "torque"
    time_column: None | str | Unset = UNSET
    angle_unit: str | Unset = "deg"
    torque_unit: str | Unset = "N*m"
    time_unit: str | Unset = "s"
    delimiter: None | str | Unset = UNSET
    decimal_comma: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        from ..models.trace_import_content_type_2 import TraceImportContentType2  # noqa: PLC0415

        format_ = self.format_.value

        content: dict[str, Any] | list[Any] | str
        if isinstance(self.content, list):
            content = self.content

        elif isinstance(self.content, TraceImportContentType2):
            content = self.content.to_dict()
        else:
            content = self.content

        angle_column = self.angle_column

        torque_column = self.torque_column

        time_column: None | str | Unset
        if isinstance(self.time_column, Unset):
            time_column = UNSET
        else:
            time_column = self.time_column

        angle_unit = self.angle_unit

        torque_unit = self.torque_unit

        time_unit = self.time_unit

        delimiter: None | str | Unset
        if isinstance(self.delimiter, Unset):
            delimiter = UNSET
        else:
            delimiter = self.delimiter

        decimal_comma = self.decimal_comma

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "format": format_,
                "content": content,
            }
        )
        if angle_column is not UNSET:
            field_dict["angle_column"] = angle_column
        if torque_column is not UNSET:
            field_dict["torque_column"] = torque_column
        if time_column is not UNSET:
            field_dict["time_column"] = time_column
        if angle_unit is not UNSET:
            field_dict["angle_unit"] = angle_unit
        if torque_unit is not UNSET:
            field_dict["torque_unit"] = torque_unit
        if time_unit is not UNSET:
            field_dict["time_unit"] = time_unit
        if delimiter is not UNSET:
            field_dict["delimiter"] = delimiter
        if decimal_comma is not UNSET:
            field_dict["decimal_comma"] = decimal_comma

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.trace_import_content_type_2 import TraceImportContentType2  # noqa: PLC0415

        d = dict(src_dict)
        format_ = TraceImportFormat(d.pop("format"))

        def _parse_content(data: object) -> list[Any] | str | TraceImportContentType2:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                content_type_1 = cast(list[Any], data)

                return content_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                content_type_2 = TraceImportContentType2.from_dict(data)

                return content_type_2
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Any] | str | TraceImportContentType2, data)

        content = _parse_content(d.pop("content"))

        angle_column = d.pop("angle_column", UNSET)

        torque_column = d.pop("torque_column", UNSET)

        def _parse_time_column(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        time_column = _parse_time_column(d.pop("time_column", UNSET))

        angle_unit = d.pop("angle_unit", UNSET)

        torque_unit = d.pop("torque_unit", UNSET)

        time_unit = d.pop("time_unit", UNSET)

        def _parse_delimiter(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        delimiter = _parse_delimiter(d.pop("delimiter", UNSET))

        decimal_comma = d.pop("decimal_comma", UNSET)

        trace_import = cls(
            format_=format_,
            content=content,
            angle_column=angle_column,
            torque_column=torque_column,
            time_column=time_column,
            angle_unit=angle_unit,
            torque_unit=torque_unit,
            time_unit=time_unit,
            delimiter=delimiter,
            decimal_comma=decimal_comma,
        )

        return trace_import
