from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.sweep_response_results import SweepResponseResults
    from ..models.sweep_response_units import SweepResponseUnits


T = TypeVar("T", bound="SweepResponse")


@_attrs_define
class SweepResponse:
    """
    Attributes:
        model (str):
        vary (str):
        unit (str):
        values (list[float]):
        results (SweepResponseResults):
        units (SweepResponseUnits):
        rung (str):
        elapsed_s (float):
        notes (list[str] | Unset):
        warnings (list[str] | Unset):
        rungs (list[None | str] | Unset): the rung that ran at each point (null: refused)
        error_estimates (list[float | None] | Unset): each point's estimated relative error
    """

    model: str
    vary: str
    unit: str
    values: list[float]
    results: SweepResponseResults
    units: SweepResponseUnits
    rung: str
    elapsed_s: float
    notes: list[str] | Unset = UNSET
    warnings: list[str] | Unset = UNSET
    rungs: list[None | str] | Unset = UNSET
    error_estimates: list[float | None] | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        model = self.model

        vary = self.vary

        unit = self.unit

        values = self.values

        results = self.results.to_dict()

        units = self.units.to_dict()

        rung = self.rung

        elapsed_s = self.elapsed_s

        notes: list[str] | Unset = UNSET
        if not isinstance(self.notes, Unset):
            notes = self.notes

        warnings: list[str] | Unset = UNSET
        if not isinstance(self.warnings, Unset):
            warnings = self.warnings

        rungs: list[None | str] | Unset = UNSET
        if not isinstance(self.rungs, Unset):
            rungs = []
            for rungs_item_data in self.rungs:
                rungs_item: None | str
                rungs_item = rungs_item_data
                rungs.append(rungs_item)

        error_estimates: list[float | None] | Unset = UNSET
        if not isinstance(self.error_estimates, Unset):
            error_estimates = []
            for error_estimates_item_data in self.error_estimates:
                error_estimates_item: float | None
                error_estimates_item = error_estimates_item_data
                error_estimates.append(error_estimates_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "model": model,
                "vary": vary,
                "unit": unit,
                "values": values,
                "results": results,
                "units": units,
                "rung": rung,
                "elapsed_s": elapsed_s,
            }
        )
        if notes is not UNSET:
            field_dict["notes"] = notes
        if warnings is not UNSET:
            field_dict["warnings"] = warnings
        if rungs is not UNSET:
            field_dict["rungs"] = rungs
        if error_estimates is not UNSET:
            field_dict["error_estimates"] = error_estimates

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.sweep_response_results import SweepResponseResults  # noqa: PLC0415
        from ..models.sweep_response_units import SweepResponseUnits  # noqa: PLC0415

        d = dict(src_dict)
        model = d.pop("model")

        vary = d.pop("vary")

        unit = d.pop("unit")

        values = cast(list[float], d.pop("values"))

        results = SweepResponseResults.from_dict(d.pop("results"))

        units = SweepResponseUnits.from_dict(d.pop("units"))

        rung = d.pop("rung")

        elapsed_s = d.pop("elapsed_s")

        notes = cast(list[str], d.pop("notes", UNSET))

        warnings = cast(list[str], d.pop("warnings", UNSET))

        _rungs = d.pop("rungs", UNSET)
        rungs: list[None | str] | Unset = UNSET
        if _rungs is not UNSET:
            rungs = []
            for rungs_item_data in _rungs:

                def _parse_rungs_item(data: object) -> None | str:
                    if data is None:
                        return data
                    return cast(None | str, data)

                rungs_item = _parse_rungs_item(rungs_item_data)

                rungs.append(rungs_item)

        _error_estimates = d.pop("error_estimates", UNSET)
        error_estimates: list[float | None] | Unset = UNSET
        if _error_estimates is not UNSET:
            error_estimates = []
            for error_estimates_item_data in _error_estimates:

                def _parse_error_estimates_item(data: object) -> float | None:
                    if data is None:
                        return data
                    return cast(float | None, data)

                error_estimates_item = _parse_error_estimates_item(error_estimates_item_data)

                error_estimates.append(error_estimates_item)

        sweep_response = cls(
            model=model,
            vary=vary,
            unit=unit,
            values=values,
            results=results,
            units=units,
            rung=rung,
            elapsed_s=elapsed_s,
            notes=notes,
            warnings=warnings,
            rungs=rungs,
            error_estimates=error_estimates,
        )

        sweep_response.additional_properties = d
        return sweep_response

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
