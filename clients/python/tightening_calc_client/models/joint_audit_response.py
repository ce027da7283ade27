from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.joint_audit_response_error_kind_type_0 import JointAuditResponseErrorKindType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.check_out import CheckOut
    from ..models.joint_audit_response_inputs import JointAuditResponseInputs
    from ..models.joint_audit_response_series import JointAuditResponseSeries
    from ..models.joint_audit_response_units import JointAuditResponseUnits
    from ..models.joint_audit_results import JointAuditResults
    from ..models.quantity_out import QuantityOut


T = TypeVar("T", bound="JointAuditResponse")


@_attrs_define
class JointAuditResponse:
    """
    Attributes:
        model (str): model name
        results (JointAuditResults):
        units (JointAuditResponseUnits): SI unit of each result and series
        rung (str): the rung that ran
        error_estimate (float | None): estimated relative error of the results (null: not known)
        elapsed_s (float): compute time, seconds
        error_kind (JointAuditResponseErrorKindType0 | None | Unset): what error_estimate promises: 'bound' (no design
            in the declared ranges exceeds it, measured: docs/accuracy.md) or 'typical' (some do; a note says how often);
            null with no estimate
        checks (list[CheckOut] | Unset):
        notes (list[str] | Unset):
        notes_parts (list[list[QuantityOut | str]] | Unset): each note as texts and quantities (SI values), as notes
        warnings (list[str] | Unset):
        series (JointAuditResponseSeries | Unset): time series for plots, SI values
        inputs (JointAuditResponseInputs | Unset): every input used, defaults filled, SI
    """

    model: str
    results: JointAuditResults
    units: JointAuditResponseUnits
    rung: str
    error_estimate: float | None
    elapsed_s: float
    error_kind: JointAuditResponseErrorKindType0 | None | Unset = UNSET
    checks: list[CheckOut] | Unset = UNSET
    notes: list[str] | Unset = UNSET
    notes_parts: list[list[QuantityOut | str]] | Unset = UNSET
    warnings: list[str] | Unset = UNSET
    series: JointAuditResponseSeries | Unset = UNSET
    inputs: JointAuditResponseInputs | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.quantity_out import QuantityOut  # noqa: PLC0415

        model = self.model

        results = self.results.to_dict()

        units = self.units.to_dict()

        rung = self.rung

        error_estimate: float | None
        error_estimate = self.error_estimate

        elapsed_s = self.elapsed_s

        error_kind: None | str | Unset
        if isinstance(self.error_kind, Unset):
            error_kind = UNSET
        elif isinstance(self.error_kind, JointAuditResponseErrorKindType0):
            error_kind = self.error_kind.value
        else:
            error_kind = self.error_kind

        checks: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.checks, Unset):
            checks = []
            for checks_item_data in self.checks:
                checks_item = checks_item_data.to_dict()
                checks.append(checks_item)

        notes: list[str] | Unset = UNSET
        if not isinstance(self.notes, Unset):
            notes = self.notes

        notes_parts: list[list[dict[str, Any] | str]] | Unset = UNSET
        if not isinstance(self.notes_parts, Unset):
            notes_parts = []
            for notes_parts_item_data in self.notes_parts:
                notes_parts_item = []
                for notes_parts_item_item_data in notes_parts_item_data:
                    notes_parts_item_item: dict[str, Any] | str
                    if isinstance(notes_parts_item_item_data, QuantityOut):
                        notes_parts_item_item = notes_parts_item_item_data.to_dict()
                    else:
                        notes_parts_item_item = notes_parts_item_item_data
                    notes_parts_item.append(notes_parts_item_item)

                notes_parts.append(notes_parts_item)

        warnings: list[str] | Unset = UNSET
        if not isinstance(self.warnings, Unset):
            warnings = self.warnings

        series: dict[str, Any] | Unset = UNSET
        if not isinstance(self.series, Unset):
            series = self.series.to_dict()

        inputs: dict[str, Any] | Unset = UNSET
        if not isinstance(self.inputs, Unset):
            inputs = self.inputs.to_dict()

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "model": model,
                "results": results,
                "units": units,
                "rung": rung,
                "error_estimate": error_estimate,
                "elapsed_s": elapsed_s,
            }
        )
        if error_kind is not UNSET:
            field_dict["error_kind"] = error_kind
        if checks is not UNSET:
            field_dict["checks"] = checks
        if notes is not UNSET:
            field_dict["notes"] = notes
        if notes_parts is not UNSET:
            field_dict["notes_parts"] = notes_parts
        if warnings is not UNSET:
            field_dict["warnings"] = warnings
        if series is not UNSET:
            field_dict["series"] = series
        if inputs is not UNSET:
            field_dict["inputs"] = inputs

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.check_out import CheckOut  # noqa: PLC0415
        from ..models.joint_audit_response_inputs import JointAuditResponseInputs  # noqa: PLC0415
        from ..models.joint_audit_response_series import JointAuditResponseSeries  # noqa: PLC0415
        from ..models.joint_audit_response_units import JointAuditResponseUnits  # noqa: PLC0415
        from ..models.joint_audit_results import JointAuditResults  # noqa: PLC0415
        from ..models.quantity_out import QuantityOut  # noqa: PLC0415

        d = dict(src_dict)
        model = d.pop("model")

        results = JointAuditResults.from_dict(d.pop("results"))

        units = JointAuditResponseUnits.from_dict(d.pop("units"))

        rung = d.pop("rung")

        def _parse_error_estimate(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        error_estimate = _parse_error_estimate(d.pop("error_estimate"))

        elapsed_s = d.pop("elapsed_s")

        def _parse_error_kind(data: object) -> JointAuditResponseErrorKindType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                error_kind_type_0 = JointAuditResponseErrorKindType0(data)

                return error_kind_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointAuditResponseErrorKindType0 | None | Unset, data)

        error_kind = _parse_error_kind(d.pop("error_kind", UNSET))

        _checks = d.pop("checks", UNSET)
        checks: list[CheckOut] | Unset = UNSET
        if _checks is not UNSET:
            checks = []
            for checks_item_data in _checks:
                checks_item = CheckOut.from_dict(checks_item_data)

                checks.append(checks_item)

        notes = cast(list[str], d.pop("notes", UNSET))

        _notes_parts = d.pop("notes_parts", UNSET)
        notes_parts: list[list[QuantityOut | str]] | Unset = UNSET
        if _notes_parts is not UNSET:
            notes_parts = []
            for notes_parts_item_data in _notes_parts:
                notes_parts_item = []
                _notes_parts_item = notes_parts_item_data
                for notes_parts_item_item_data in _notes_parts_item:

                    def _parse_notes_parts_item_item(data: object) -> QuantityOut | str:
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            notes_parts_item_item_type_1 = QuantityOut.from_dict(data)

                            return notes_parts_item_item_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(QuantityOut | str, data)

                    notes_parts_item_item = _parse_notes_parts_item_item(notes_parts_item_item_data)

                    notes_parts_item.append(notes_parts_item_item)

                notes_parts.append(notes_parts_item)

        warnings = cast(list[str], d.pop("warnings", UNSET))

        _series = d.pop("series", UNSET)
        series: JointAuditResponseSeries | Unset
        if isinstance(_series, Unset):
            series = UNSET
        else:
            series = JointAuditResponseSeries.from_dict(_series)

        _inputs = d.pop("inputs", UNSET)
        inputs: JointAuditResponseInputs | Unset
        if isinstance(_inputs, Unset):
            inputs = UNSET
        else:
            inputs = JointAuditResponseInputs.from_dict(_inputs)

        joint_audit_response = cls(
            model=model,
            results=results,
            units=units,
            rung=rung,
            error_estimate=error_estimate,
            elapsed_s=elapsed_s,
            error_kind=error_kind,
            checks=checks,
            notes=notes,
            notes_parts=notes_parts,
            warnings=warnings,
            series=series,
            inputs=inputs,
        )

        joint_audit_response.additional_properties = d
        return joint_audit_response

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
