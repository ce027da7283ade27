from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="TraceProgramResults")


@_attrs_define
class TraceProgramResults:
    """
    Attributes:
        strategy (None | str | Unset): The strategy the settings are for [dimensionless]
        target_preload (float | None | Unset): Preload aimed at: the middle of F_M,min…F_M,zul, or yield [N]
        snug_torque (float | None | Unset): Snug torque: where the angle count starts (with M_ü) [N*m]
        final_angle (float | None | Unset): Angle from snug to stop (torque_angle; null for yield) [rad]
        angle_min (float | None | Unset): Angle window from snug, lower limit [rad]
        angle_max (float | None | Unset): Angle window from snug, upper limit [rad]
        torque_min (float | None | Unset): Torque monitoring window at the stop, lower limit [N*m]
        torque_max (float | None | Unset): Torque monitoring window at the stop, upper limit [N*m]
        rate_min (float | None | Unset): Elastic torque rate expected at the lowest friction [N*m/rad]
        rate_max (float | None | Unset): Elastic torque rate expected at the highest friction [N*m/rad]
        gradient_threshold_min (float | None | Unset): Yield gradient: the share of rate_min [N*m/rad]
        gradient_threshold_max (float | None | Unset): Yield gradient: the share of rate_max [N*m/rad]
        preload_min (float | None | Unset): Lowest preload the program gives over friction and compliance [N]
        preload_max (float | None | Unset): Highest preload the program gives over friction and compliance [N]
        window_fits (bool | None | Unset): The program keeps the preload within F_M,min…F_M,zul [dimensionless]
    """

    strategy: None | str | Unset = UNSET
    target_preload: float | None | Unset = UNSET
    snug_torque: float | None | Unset = UNSET
    final_angle: float | None | Unset = UNSET
    angle_min: float | None | Unset = UNSET
    angle_max: float | None | Unset = UNSET
    torque_min: float | None | Unset = UNSET
    torque_max: float | None | Unset = UNSET
    rate_min: float | None | Unset = UNSET
    rate_max: float | None | Unset = UNSET
    gradient_threshold_min: float | None | Unset = UNSET
    gradient_threshold_max: float | None | Unset = UNSET
    preload_min: float | None | Unset = UNSET
    preload_max: float | None | Unset = UNSET
    window_fits: bool | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        strategy: None | str | Unset
        if isinstance(self.strategy, Unset):
            strategy = UNSET
        else:
            strategy = self.strategy

        target_preload: float | None | Unset
        if isinstance(self.target_preload, Unset):
            target_preload = UNSET
        else:
            target_preload = self.target_preload

        snug_torque: float | None | Unset
        if isinstance(self.snug_torque, Unset):
            snug_torque = UNSET
        else:
            snug_torque = self.snug_torque

        final_angle: float | None | Unset
        if isinstance(self.final_angle, Unset):
            final_angle = UNSET
        else:
            final_angle = self.final_angle

        angle_min: float | None | Unset
        if isinstance(self.angle_min, Unset):
            angle_min = UNSET
        else:
            angle_min = self.angle_min

        angle_max: float | None | Unset
        if isinstance(self.angle_max, Unset):
            angle_max = UNSET
        else:
            angle_max = self.angle_max

        torque_min: float | None | Unset
        if isinstance(self.torque_min, Unset):
            torque_min = UNSET
        else:
            torque_min = self.torque_min

        torque_max: float | None | Unset
        if isinstance(self.torque_max, Unset):
            torque_max = UNSET
        else:
            torque_max = self.torque_max

        rate_min: float | None | Unset
        if isinstance(self.rate_min, Unset):
            rate_min = UNSET
        else:
            rate_min = self.rate_min

        rate_max: float | None | Unset
        if isinstance(self.rate_max, Unset):
            rate_max = UNSET
        else:
            rate_max = self.rate_max

        gradient_threshold_min: float | None | Unset
        if isinstance(self.gradient_threshold_min, Unset):
            gradient_threshold_min = UNSET
        else:
            gradient_threshold_min = self.gradient_threshold_min

        gradient_threshold_max: float | None | Unset
        if isinstance(self.gradient_threshold_max, Unset):
            gradient_threshold_max = UNSET
        else:
            gradient_threshold_max = self.gradient_threshold_max

        preload_min: float | None | Unset
        if isinstance(self.preload_min, Unset):
            preload_min = UNSET
        else:
            preload_min = self.preload_min

        preload_max: float | None | Unset
        if isinstance(self.preload_max, Unset):
            preload_max = UNSET
        else:
            preload_max = self.preload_max

        window_fits: bool | None | Unset
        if isinstance(self.window_fits, Unset):
            window_fits = UNSET
        else:
            window_fits = self.window_fits

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if strategy is not UNSET:
            field_dict["strategy"] = strategy
        if target_preload is not UNSET:
            field_dict["target_preload"] = target_preload
        if snug_torque is not UNSET:
            field_dict["snug_torque"] = snug_torque
        if final_angle is not UNSET:
            field_dict["final_angle"] = final_angle
        if angle_min is not UNSET:
            field_dict["angle_min"] = angle_min
        if angle_max is not UNSET:
            field_dict["angle_max"] = angle_max
        if torque_min is not UNSET:
            field_dict["torque_min"] = torque_min
        if torque_max is not UNSET:
            field_dict["torque_max"] = torque_max
        if rate_min is not UNSET:
            field_dict["rate_min"] = rate_min
        if rate_max is not UNSET:
            field_dict["rate_max"] = rate_max
        if gradient_threshold_min is not UNSET:
            field_dict["gradient_threshold_min"] = gradient_threshold_min
        if gradient_threshold_max is not UNSET:
            field_dict["gradient_threshold_max"] = gradient_threshold_max
        if preload_min is not UNSET:
            field_dict["preload_min"] = preload_min
        if preload_max is not UNSET:
            field_dict["preload_max"] = preload_max
        if window_fits is not UNSET:
            field_dict["window_fits"] = window_fits

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_strategy(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        strategy = _parse_strategy(d.pop("strategy", UNSET))

        def _parse_target_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_preload = _parse_target_preload(d.pop("target_preload", UNSET))

        def _parse_snug_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        snug_torque = _parse_snug_torque(d.pop("snug_torque", UNSET))

        def _parse_final_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        final_angle = _parse_final_angle(d.pop("final_angle", UNSET))

        def _parse_angle_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        angle_min = _parse_angle_min(d.pop("angle_min", UNSET))

        def _parse_angle_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        angle_max = _parse_angle_max(d.pop("angle_max", UNSET))

        def _parse_torque_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_min = _parse_torque_min(d.pop("torque_min", UNSET))

        def _parse_torque_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_max = _parse_torque_max(d.pop("torque_max", UNSET))

        def _parse_rate_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rate_min = _parse_rate_min(d.pop("rate_min", UNSET))

        def _parse_rate_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rate_max = _parse_rate_max(d.pop("rate_max", UNSET))

        def _parse_gradient_threshold_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        gradient_threshold_min = _parse_gradient_threshold_min(d.pop("gradient_threshold_min", UNSET))

        def _parse_gradient_threshold_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        gradient_threshold_max = _parse_gradient_threshold_max(d.pop("gradient_threshold_max", UNSET))

        def _parse_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_min = _parse_preload_min(d.pop("preload_min", UNSET))

        def _parse_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_max = _parse_preload_max(d.pop("preload_max", UNSET))

        def _parse_window_fits(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        window_fits = _parse_window_fits(d.pop("window_fits", UNSET))

        trace_program_results = cls(
            strategy=strategy,
            target_preload=target_preload,
            snug_torque=snug_torque,
            final_angle=final_angle,
            angle_min=angle_min,
            angle_max=angle_max,
            torque_min=torque_min,
            torque_max=torque_max,
            rate_min=rate_min,
            rate_max=rate_max,
            gradient_threshold_min=gradient_threshold_min,
            gradient_threshold_max=gradient_threshold_max,
            preload_min=preload_min,
            preload_max=preload_max,
            window_fits=window_fits,
        )

        trace_program_results.additional_properties = d
        return trace_program_results

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
