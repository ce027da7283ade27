from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.study_in_method import StudyInMethod
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.correlation_in import CorrelationIn
    from ..models.study_in_base import StudyInBase
    from ..models.variable_in import VariableIn


T = TypeVar("T", bound="StudyIn")


@_attrs_define
class StudyIn:
    """
    Attributes:
        variables (list[VariableIn]):
        base (StudyInBase | Unset): inputs held fixed (defaults fill the rest)
        method (StudyInMethod | Unset):  Default: StudyInMethod.MONTE_CARLO.
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

    variables: list[VariableIn]
    base: StudyInBase | Unset = UNSET
    method: StudyInMethod | Unset = StudyInMethod.MONTE_CARLO
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
        variables = []
        for variables_item_data in self.variables:
            variables_item = variables_item_data.to_dict()
            variables.append(variables_item)

        base: dict[str, Any] | Unset = UNSET
        if not isinstance(self.base, Unset):
            base = self.base.to_dict()

        method: str | Unset = UNSET
        if not isinstance(self.method, Unset):
            method = self.method.value

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

        field_dict.update(
            {
                "variables": variables,
            }
        )
        if base is not UNSET:
            field_dict["base"] = base
        if method is not UNSET:
            field_dict["method"] = method
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
        from ..models.study_in_base import StudyInBase  # noqa: PLC0415
        from ..models.variable_in import VariableIn  # noqa: PLC0415

        d = dict(src_dict)
        variables = []
        _variables = d.pop("variables")
        for variables_item_data in _variables:
            variables_item = VariableIn.from_dict(variables_item_data)

            variables.append(variables_item)

        _base = d.pop("base", UNSET)
        base: StudyInBase | Unset
        if isinstance(_base, Unset):
            base = UNSET
        else:
            base = StudyInBase.from_dict(_base)

        _method = d.pop("method", UNSET)
        method: StudyInMethod | Unset
        if isinstance(_method, Unset):
            method = UNSET
        else:
            method = StudyInMethod(_method)

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

        study_in = cls(
            variables=variables,
            base=base,
            method=method,
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

        return study_in
