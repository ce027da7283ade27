from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preload_control_study_request_method import PreloadControlStudyRequestMethod
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.correlation_in import CorrelationIn
    from ..models.preload_control_study_request_points_type_0_item import PreloadControlStudyRequestPointsType0Item
    from ..models.preload_control_study_request_preload_control_study_base import (
        PreloadControlStudyRequestPreloadControlStudyBase,
    )
    from ..models.variable_in import VariableIn


T = TypeVar("T", bound="PreloadControlStudyRequest")


@_attrs_define
class PreloadControlStudyRequest:
    """
    Attributes:
        base (PreloadControlStudyRequestPreloadControlStudyBase | Unset): inputs held fixed (defaults fill the rest)
        variables (list[VariableIn] | Unset): the inputs to vary and how (every method but 'points')
        method (PreloadControlStudyRequestMethod | Unset): how the designs are made; 'points': the designs listed in
            `points` or `points_csv` (set by giving either) Default: PreloadControlStudyRequestMethod.MONTE_CARLO.
        points (list[PreloadControlStudyRequestPointsType0Item] | None | Unset): explicit designs, one object per
            design: the same numeric inputs in each, numbers in SI or strings with a unit as in a single run ('45 mm'); the
            other inputs from `base`
        points_csv (None | str | Unset): explicit designs as CSV text: a header of input names, each with an optional
            unit in brackets ('clamp_length [mm]'), then one design a line; a cell is a number (in the column's unit, SI
            without one) or a number with its own unit
        samples (int | Unset):  Default: 1000.
        seed (int | Unset):  Default: 0.
        fidelity (None | str | Unset):
        tolerance (float | None | Unset):
        outputs (list[str] | None | Unset):
        bins (int | Unset):  Default: 30.
        feasible_when (None | str | Unset):
        correlations (list[CorrelationIn] | Unset): rank correlations between varied inputs (Monte Carlo and LHS only)
        keep_points (bool | Unset): keep the raw points for GET /api/v1/jobs/{id}/points.csv and /points.parquet
            Default: False.
    """

    base: PreloadControlStudyRequestPreloadControlStudyBase | Unset = UNSET
    variables: list[VariableIn] | Unset = UNSET
    method: PreloadControlStudyRequestMethod | Unset = PreloadControlStudyRequestMethod.MONTE_CARLO
    points: list[PreloadControlStudyRequestPointsType0Item] | None | Unset = UNSET
    points_csv: None | str | Unset = UNSET
    samples: int | Unset = 1000
    seed: int | Unset = 0
    fidelity: None | str | Unset = UNSET
    tolerance: float | None | Unset = UNSET
    outputs: list[str] | None | Unset = UNSET
    bins: int | Unset = 30
    feasible_when: None | str | Unset = UNSET
    correlations: list[CorrelationIn] | Unset = UNSET
    keep_points: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        base: dict[str, Any] | Unset = UNSET
        if not isinstance(self.base, Unset):
            base = self.base.to_dict()

        variables: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.variables, Unset):
            variables = []
            for variables_item_data in self.variables:
                variables_item = variables_item_data.to_dict()
                variables.append(variables_item)

        method: str | Unset = UNSET
        if not isinstance(self.method, Unset):
            method = self.method.value

        points: list[dict[str, Any]] | None | Unset
        if isinstance(self.points, Unset):
            points = UNSET
        elif isinstance(self.points, list):
            points = []
            for points_type_0_item_data in self.points:
                points_type_0_item = points_type_0_item_data.to_dict()
                points.append(points_type_0_item)

        else:
            points = self.points

        points_csv: None | str | Unset
        if isinstance(self.points_csv, Unset):
            points_csv = UNSET
        else:
            points_csv = self.points_csv

        samples = self.samples

        seed = self.seed

        fidelity: None | str | Unset
        if isinstance(self.fidelity, Unset):
            fidelity = UNSET
        else:
            fidelity = self.fidelity

        tolerance: float | None | Unset
        if isinstance(self.tolerance, Unset):
            tolerance = UNSET
        else:
            tolerance = self.tolerance

        outputs: list[str] | None | Unset
        if isinstance(self.outputs, Unset):
            outputs = UNSET
        elif isinstance(self.outputs, list):
            outputs = self.outputs

        else:
            outputs = self.outputs

        bins = self.bins

        feasible_when: None | str | Unset
        if isinstance(self.feasible_when, Unset):
            feasible_when = UNSET
        else:
            feasible_when = self.feasible_when

        correlations: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.correlations, Unset):
            correlations = []
            for correlations_item_data in self.correlations:
                correlations_item = correlations_item_data.to_dict()
                correlations.append(correlations_item)

        keep_points = self.keep_points

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if base is not UNSET:
            field_dict["base"] = base
        if variables is not UNSET:
            field_dict["variables"] = variables
        if method is not UNSET:
            field_dict["method"] = method
        if points is not UNSET:
            field_dict["points"] = points
        if points_csv is not UNSET:
            field_dict["points_csv"] = points_csv
        if samples is not UNSET:
            field_dict["samples"] = samples
        if seed is not UNSET:
            field_dict["seed"] = seed
        if fidelity is not UNSET:
            field_dict["fidelity"] = fidelity
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance
        if outputs is not UNSET:
            field_dict["outputs"] = outputs
        if bins is not UNSET:
            field_dict["bins"] = bins
        if feasible_when is not UNSET:
            field_dict["feasible_when"] = feasible_when
        if correlations is not UNSET:
            field_dict["correlations"] = correlations
        if keep_points is not UNSET:
            field_dict["keep_points"] = keep_points

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.correlation_in import CorrelationIn  # noqa: PLC0415
        from ..models.preload_control_study_request_points_type_0_item import PreloadControlStudyRequestPointsType0Item  # noqa: PLC0415
        from ..models.preload_control_study_request_preload_control_study_base import (
            PreloadControlStudyRequestPreloadControlStudyBase,  # noqa: PLC0415
        )
        from ..models.variable_in import VariableIn  # noqa: PLC0415

        d = dict(src_dict)
        _base = d.pop("base", UNSET)
        base: PreloadControlStudyRequestPreloadControlStudyBase | Unset
        if isinstance(_base, Unset):
            base = UNSET
        else:
            base = PreloadControlStudyRequestPreloadControlStudyBase.from_dict(_base)

        _variables = d.pop("variables", UNSET)
        variables: list[VariableIn] | Unset = UNSET
        if _variables is not UNSET:
            variables = []
            for variables_item_data in _variables:
                variables_item = VariableIn.from_dict(variables_item_data)

                variables.append(variables_item)

        _method = d.pop("method", UNSET)
        method: PreloadControlStudyRequestMethod | Unset
        if isinstance(_method, Unset):
            method = UNSET
        else:
            method = PreloadControlStudyRequestMethod(_method)

        def _parse_points(data: object) -> list[PreloadControlStudyRequestPointsType0Item] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                points_type_0 = []
                _points_type_0 = data
                for points_type_0_item_data in _points_type_0:
                    points_type_0_item = PreloadControlStudyRequestPointsType0Item.from_dict(points_type_0_item_data)

                    points_type_0.append(points_type_0_item)

                return points_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[PreloadControlStudyRequestPointsType0Item] | None | Unset, data)

        points = _parse_points(d.pop("points", UNSET))

        def _parse_points_csv(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        points_csv = _parse_points_csv(d.pop("points_csv", UNSET))

        samples = d.pop("samples", UNSET)

        seed = d.pop("seed", UNSET)

        def _parse_fidelity(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        fidelity = _parse_fidelity(d.pop("fidelity", UNSET))

        def _parse_tolerance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))

        def _parse_outputs(data: object) -> list[str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                outputs_type_0 = cast(list[str], data)

                return outputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[str] | None | Unset, data)

        outputs = _parse_outputs(d.pop("outputs", UNSET))

        bins = d.pop("bins", UNSET)

        def _parse_feasible_when(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        feasible_when = _parse_feasible_when(d.pop("feasible_when", UNSET))

        _correlations = d.pop("correlations", UNSET)
        correlations: list[CorrelationIn] | Unset = UNSET
        if _correlations is not UNSET:
            correlations = []
            for correlations_item_data in _correlations:
                correlations_item = CorrelationIn.from_dict(correlations_item_data)

                correlations.append(correlations_item)

        keep_points = d.pop("keep_points", UNSET)

        preload_control_study_request = cls(
            base=base,
            variables=variables,
            method=method,
            points=points,
            points_csv=points_csv,
            samples=samples,
            seed=seed,
            fidelity=fidelity,
            tolerance=tolerance,
            outputs=outputs,
            bins=bins,
            feasible_when=feasible_when,
            correlations=correlations,
            keep_points=keep_points,
        )

        return preload_control_study_request
