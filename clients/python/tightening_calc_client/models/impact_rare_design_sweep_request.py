from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.impact_rare_design_sweep_request_fidelity_type_0 import ImpactRareDesignSweepRequestFidelityType0
from ..models.impact_rare_design_sweep_request_outputs_type_0_item import ImpactRareDesignSweepRequestOutputsType0Item
from ..models.impact_rare_design_sweep_request_scale import ImpactRareDesignSweepRequestScale
from ..models.impact_rare_design_sweep_request_vary import ImpactRareDesignSweepRequestVary
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.impact_rare_design_sweep_base import ImpactRareDesignSweepBase


T = TypeVar("T", bound="ImpactRareDesignSweepRequest")


@_attrs_define
class ImpactRareDesignSweepRequest:
    """
    Attributes:
        vary (ImpactRareDesignSweepRequestVary): the input to vary
        start (float | str): first value: SI number or string with a unit
        stop (float | str): last value: SI number or string with a unit
        base (ImpactRareDesignSweepBase | Unset):
        num (int | Unset): number of points Default: 50.
        scale (ImpactRareDesignSweepRequestScale | Unset):  Default: ImpactRareDesignSweepRequestScale.LINEAR.
        outputs (list[ImpactRareDesignSweepRequestOutputsType0Item] | None | Unset):
        fidelity (ImpactRareDesignSweepRequestFidelityType0 | None | Unset): as for a single evaluation (absent: 'auto',
            or 'auto' when a tolerance is given); auto chooses per point
        tolerance (float | None | Unset):
    """

    vary: ImpactRareDesignSweepRequestVary
    start: float | str
    stop: float | str
    base: ImpactRareDesignSweepBase | Unset = UNSET
    num: int | Unset = 50
    scale: ImpactRareDesignSweepRequestScale | Unset = ImpactRareDesignSweepRequestScale.LINEAR
    outputs: list[ImpactRareDesignSweepRequestOutputsType0Item] | None | Unset = UNSET
    fidelity: ImpactRareDesignSweepRequestFidelityType0 | None | Unset = UNSET
    tolerance: float | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        vary = self.vary.value

        start: float | str
        start = self.start

        stop: float | str
        stop = self.stop

        base: dict[str, Any] | Unset = UNSET
        if not isinstance(self.base, Unset):
            base = self.base.to_dict()

        num = self.num

        scale: str | Unset = UNSET
        if not isinstance(self.scale, Unset):
            scale = self.scale.value

        outputs: list[str] | None | Unset
        if isinstance(self.outputs, Unset):
            outputs = UNSET
        elif isinstance(self.outputs, list):
            outputs = []
            for outputs_type_0_item_data in self.outputs:
                outputs_type_0_item = outputs_type_0_item_data.value
                outputs.append(outputs_type_0_item)

        else:
            outputs = self.outputs

        fidelity: None | str | Unset
        if isinstance(self.fidelity, Unset):
            fidelity = UNSET
        elif isinstance(self.fidelity, ImpactRareDesignSweepRequestFidelityType0):
            fidelity = self.fidelity.value
        else:
            fidelity = self.fidelity

        tolerance: float | None | Unset
        if isinstance(self.tolerance, Unset):
            tolerance = UNSET
        else:
            tolerance = self.tolerance

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "vary": vary,
                "start": start,
                "stop": stop,
            }
        )
        if base is not UNSET:
            field_dict["base"] = base
        if num is not UNSET:
            field_dict["num"] = num
        if scale is not UNSET:
            field_dict["scale"] = scale
        if outputs is not UNSET:
            field_dict["outputs"] = outputs
        if fidelity is not UNSET:
            field_dict["fidelity"] = fidelity
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.impact_rare_design_sweep_base import ImpactRareDesignSweepBase  # noqa: PLC0415

        d = dict(src_dict)
        vary = ImpactRareDesignSweepRequestVary(d.pop("vary"))

        def _parse_start(data: object) -> float | str:
            return cast(float | str, data)

        start = _parse_start(d.pop("start"))

        def _parse_stop(data: object) -> float | str:
            return cast(float | str, data)

        stop = _parse_stop(d.pop("stop"))

        _base = d.pop("base", UNSET)
        base: ImpactRareDesignSweepBase | Unset
        if isinstance(_base, Unset):
            base = UNSET
        else:
            base = ImpactRareDesignSweepBase.from_dict(_base)

        num = d.pop("num", UNSET)

        _scale = d.pop("scale", UNSET)
        scale: ImpactRareDesignSweepRequestScale | Unset
        if isinstance(_scale, Unset):
            scale = UNSET
        else:
            scale = ImpactRareDesignSweepRequestScale(_scale)

        def _parse_outputs(data: object) -> list[ImpactRareDesignSweepRequestOutputsType0Item] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                outputs_type_0 = []
                _outputs_type_0 = data
                for outputs_type_0_item_data in _outputs_type_0:
                    outputs_type_0_item = ImpactRareDesignSweepRequestOutputsType0Item(outputs_type_0_item_data)

                    outputs_type_0.append(outputs_type_0_item)

                return outputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[ImpactRareDesignSweepRequestOutputsType0Item] | None | Unset, data)

        outputs = _parse_outputs(d.pop("outputs", UNSET))

        def _parse_fidelity(data: object) -> ImpactRareDesignSweepRequestFidelityType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                fidelity_type_0 = ImpactRareDesignSweepRequestFidelityType0(data)

                return fidelity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ImpactRareDesignSweepRequestFidelityType0 | None | Unset, data)

        fidelity = _parse_fidelity(d.pop("fidelity", UNSET))

        def _parse_tolerance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))

        impact_rare_design_sweep_request = cls(
            vary=vary,
            start=start,
            stop=stop,
            base=base,
            num=num,
            scale=scale,
            outputs=outputs,
            fidelity=fidelity,
            tolerance=tolerance,
        )

        return impact_rare_design_sweep_request
