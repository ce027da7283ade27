from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.variable_in_distribution import VariableInDistribution
from ..models.variable_in_scale import VariableInScale
from ..types import UNSET, Unset

T = TypeVar("T", bound="VariableIn")


@_attrs_define
class VariableIn:
    """One varied input: a grid axis or a distribution; numbers SI or strings with a unit.

    Attributes:
        name (str): the input to vary
        distribution (VariableInDistribution | Unset): for Monte Carlo, LHS and Sobol' (ignored by a grid) Default:
            VariableInDistribution.UNIFORM.
        low (float | None | str | Unset): lower end (grid, uniform, triangular)
        high (float | None | str | Unset): upper end
        mean (float | None | str | Unset): normal, lognormal: mean
        sd (float | None | str | Unset): normal, lognormal: standard deviation (arithmetic)
        mode (float | None | str | Unset): triangular: most likely value
        num (int | Unset): grid: points on this axis Default: 11.
        scale (VariableInScale | Unset): grid: spacing Default: VariableInScale.LINEAR.
    """

    name: str
    distribution: VariableInDistribution | Unset = VariableInDistribution.UNIFORM
    low: float | None | str | Unset = UNSET
    high: float | None | str | Unset = UNSET
    mean: float | None | str | Unset = UNSET
    sd: float | None | str | Unset = UNSET
    mode: float | None | str | Unset = UNSET
    num: int | Unset = 11
    scale: VariableInScale | Unset = VariableInScale.LINEAR

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        distribution: str | Unset = UNSET
        if not isinstance(self.distribution, Unset):
            distribution = self.distribution.value

        low: float | None | str | Unset
        if isinstance(self.low, Unset):
            low = UNSET
        else:
            low = self.low

        high: float | None | str | Unset
        if isinstance(self.high, Unset):
            high = UNSET
        else:
            high = self.high

        mean: float | None | str | Unset
        if isinstance(self.mean, Unset):
            mean = UNSET
        else:
            mean = self.mean

        sd: float | None | str | Unset
        if isinstance(self.sd, Unset):
            sd = UNSET
        else:
            sd = self.sd

        mode: float | None | str | Unset
        if isinstance(self.mode, Unset):
            mode = UNSET
        else:
            mode = self.mode

        num = self.num

        scale: str | Unset = UNSET
        if not isinstance(self.scale, Unset):
            scale = self.scale.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "name": name,
            }
        )
        if distribution is not UNSET:
            field_dict["distribution"] = distribution
        if low is not UNSET:
            field_dict["low"] = low
        if high is not UNSET:
            field_dict["high"] = high
        if mean is not UNSET:
            field_dict["mean"] = mean
        if sd is not UNSET:
            field_dict["sd"] = sd
        if mode is not UNSET:
            field_dict["mode"] = mode
        if num is not UNSET:
            field_dict["num"] = num
        if scale is not UNSET:
            field_dict["scale"] = scale

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        _distribution = d.pop("distribution", UNSET)
        distribution: VariableInDistribution | Unset
        if isinstance(_distribution, Unset):
            distribution = UNSET
        else:
            distribution = VariableInDistribution(_distribution)

        def _parse_low(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        low = _parse_low(d.pop("low", UNSET))

        def _parse_high(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        high = _parse_high(d.pop("high", UNSET))

        def _parse_mean(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        mean = _parse_mean(d.pop("mean", UNSET))

        def _parse_sd(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        sd = _parse_sd(d.pop("sd", UNSET))

        def _parse_mode(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        mode = _parse_mode(d.pop("mode", UNSET))

        num = d.pop("num", UNSET)

        _scale = d.pop("scale", UNSET)
        scale: VariableInScale | Unset
        if isinstance(_scale, Unset):
            scale = UNSET
        else:
            scale = VariableInScale(_scale)

        variable_in = cls(
            name=name,
            distribution=distribution,
            low=low,
            high=high,
            mean=mean,
            sd=sd,
            mode=mode,
            num=num,
            scale=scale,
        )

        return variable_in
