from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="TraceAnalysisResults")


@_attrs_define
class TraceAnalysisResults:
    """
    Attributes:
        steps_found (int | None | Unset): Steps the trace splits into (torque dropping to about zero) [dimensionless]
        step_analysed (int | None | Unset): The step analysed, counted from 1 [dimensionless]
        snug_angle (float | None | Unset): Snug point: nut angle where the gradient first reaches its share [rad]
        snug_torque (float | None | Unset): Torque at the snug point [N*m]
        zero_preload_angle (float | None | Unset): Nut angle where the elastic line meets M_ü (preload 0) [rad]
        elastic_window_start (float | None | Unset): Nut angle where the elastic window begins [rad]
        elastic_window_end (float | None | Unset): Nut angle where the elastic window ends [rad]
        elastic_rate (float | None | Unset): Elastic torque rate dT/dθ at the nut, robust fit [N*m/rad]
        predicted_rate_min (float | None | Unset): Rate the joint predicts at its lowest friction [N*m/rad]
        predicted_rate_max (float | None | Unset): Rate the joint predicts at its highest friction [N*m/rad]
        yield_detected (bool | None | Unset): A yield point was found (gradient drop) [dimensionless]
        yield_angle (float | None | Unset): Nut angle of the yield point (null: none) [rad]
        yield_torque (float | None | Unset): Torque at the yield point (null: none) [N*m]
        snug_to_yield_angle (float | None | Unset): Yield angle minus the zero-preload angle (null: none) [rad]
        predicted_yield_torque_min (float | None | Unset): Torque at F_M at R_p0.2 (ν = 1), lowest friction [N*m]
        predicted_yield_torque_max (float | None | Unset): Torque at F_M at R_p0.2 (ν = 1), highest friction [N*m]
        predicted_snug_to_yield_min (float | None | Unset): Angle from zero preload to yield, predicted, least [rad]
        predicted_snug_to_yield_max (float | None | Unset): Angle from zero preload to yield, predicted, most [rad]
        final_angle (float | None | Unset): Nut angle at the step's peak torque [rad]
        final_torque (float | None | Unset): Peak torque of the step [N*m]
        torque_per_preload (float | None | Unset): k = (T − M_ü)/F the measured rate implies [m]
        total_friction (float | None | Unset): Total friction μ_ges (μ_G = μ_K) from the measured rate [dimensionless]
        total_friction_min (float | None | Unset): μ_ges at the stiff end of the compliance's uncertainty
            [dimensionless]
        total_friction_max (float | None | Unset): μ_ges at the soft end of the compliance's uncertainty [dimensionless]
        thread_friction_low (float | None | Unset): Lowest μ_G over compliance and friction split [dimensionless]
        thread_friction_high (float | None | Unset): Highest μ_G over compliance and friction split [dimensionless]
        preload (float | None | Unset): Preload at the final torque, F = (T − M_ü)/k [N]
        preload_min (float | None | Unset): Preload's lower bound (soft end of the compliance) [N]
        preload_max (float | None | Unset): Preload's upper bound (stiff end of the compliance) [N]
        yield_preload_min (float | None | Unset): Preload at R_p0.2 (ν = 1) at the highest μ_G the split allows [N]
        assembly_preload_min (float | None | Unset): The joint's F_M,min (lower end of its window) [N]
        permissible_preload (float | None | Unset): The joint's F_M,zul (upper end of its window) [N]
        preload_in_window (bool | None | Unset): Preload bounds within F_M,min…F_M,zul [dimensionless]
    """

    steps_found: int | None | Unset = UNSET
    step_analysed: int | None | Unset = UNSET
    snug_angle: float | None | Unset = UNSET
    snug_torque: float | None | Unset = UNSET
    zero_preload_angle: float | None | Unset = UNSET
    elastic_window_start: float | None | Unset = UNSET
    elastic_window_end: float | None | Unset = UNSET
    elastic_rate: float | None | Unset = UNSET
    predicted_rate_min: float | None | Unset = UNSET
    predicted_rate_max: float | None | Unset = UNSET
    yield_detected: bool | None | Unset = UNSET
    yield_angle: float | None | Unset = UNSET
    yield_torque: float | None | Unset = UNSET
    snug_to_yield_angle: float | None | Unset = UNSET
    predicted_yield_torque_min: float | None | Unset = UNSET
    predicted_yield_torque_max: float | None | Unset = UNSET
    predicted_snug_to_yield_min: float | None | Unset = UNSET
    predicted_snug_to_yield_max: float | None | Unset = UNSET
    final_angle: float | None | Unset = UNSET
    final_torque: float | None | Unset = UNSET
    torque_per_preload: float | None | Unset = UNSET
    total_friction: float | None | Unset = UNSET
    total_friction_min: float | None | Unset = UNSET
    total_friction_max: float | None | Unset = UNSET
    thread_friction_low: float | None | Unset = UNSET
    thread_friction_high: float | None | Unset = UNSET
    preload: float | None | Unset = UNSET
    preload_min: float | None | Unset = UNSET
    preload_max: float | None | Unset = UNSET
    yield_preload_min: float | None | Unset = UNSET
    assembly_preload_min: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    preload_in_window: bool | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        steps_found: int | None | Unset
        if isinstance(self.steps_found, Unset):
            steps_found = UNSET
        else:
            steps_found = self.steps_found

        step_analysed: int | None | Unset
        if isinstance(self.step_analysed, Unset):
            step_analysed = UNSET
        else:
            step_analysed = self.step_analysed

        snug_angle: float | None | Unset
        if isinstance(self.snug_angle, Unset):
            snug_angle = UNSET
        else:
            snug_angle = self.snug_angle

        snug_torque: float | None | Unset
        if isinstance(self.snug_torque, Unset):
            snug_torque = UNSET
        else:
            snug_torque = self.snug_torque

        zero_preload_angle: float | None | Unset
        if isinstance(self.zero_preload_angle, Unset):
            zero_preload_angle = UNSET
        else:
            zero_preload_angle = self.zero_preload_angle

        elastic_window_start: float | None | Unset
        if isinstance(self.elastic_window_start, Unset):
            elastic_window_start = UNSET
        else:
            elastic_window_start = self.elastic_window_start

        elastic_window_end: float | None | Unset
        if isinstance(self.elastic_window_end, Unset):
            elastic_window_end = UNSET
        else:
            elastic_window_end = self.elastic_window_end

        elastic_rate: float | None | Unset
        if isinstance(self.elastic_rate, Unset):
            elastic_rate = UNSET
        else:
            elastic_rate = self.elastic_rate

        predicted_rate_min: float | None | Unset
        if isinstance(self.predicted_rate_min, Unset):
            predicted_rate_min = UNSET
        else:
            predicted_rate_min = self.predicted_rate_min

        predicted_rate_max: float | None | Unset
        if isinstance(self.predicted_rate_max, Unset):
            predicted_rate_max = UNSET
        else:
            predicted_rate_max = self.predicted_rate_max

        yield_detected: bool | None | Unset
        if isinstance(self.yield_detected, Unset):
            yield_detected = UNSET
        else:
            yield_detected = self.yield_detected

        yield_angle: float | None | Unset
        if isinstance(self.yield_angle, Unset):
            yield_angle = UNSET
        else:
            yield_angle = self.yield_angle

        yield_torque: float | None | Unset
        if isinstance(self.yield_torque, Unset):
            yield_torque = UNSET
        else:
            yield_torque = self.yield_torque

        snug_to_yield_angle: float | None | Unset
        if isinstance(self.snug_to_yield_angle, Unset):
            snug_to_yield_angle = UNSET
        else:
            snug_to_yield_angle = self.snug_to_yield_angle

        predicted_yield_torque_min: float | None | Unset
        if isinstance(self.predicted_yield_torque_min, Unset):
            predicted_yield_torque_min = UNSET
        else:
            predicted_yield_torque_min = self.predicted_yield_torque_min

        predicted_yield_torque_max: float | None | Unset
        if isinstance(self.predicted_yield_torque_max, Unset):
            predicted_yield_torque_max = UNSET
        else:
            predicted_yield_torque_max = self.predicted_yield_torque_max

        predicted_snug_to_yield_min: float | None | Unset
        if isinstance(self.predicted_snug_to_yield_min, Unset):
            predicted_snug_to_yield_min = UNSET
        else:
            predicted_snug_to_yield_min = self.predicted_snug_to_yield_min

        predicted_snug_to_yield_max: float | None | Unset
        if isinstance(self.predicted_snug_to_yield_max, Unset):
            predicted_snug_to_yield_max = UNSET
        else:
            predicted_snug_to_yield_max = self.predicted_snug_to_yield_max

        final_angle: float | None | Unset
        if isinstance(self.final_angle, Unset):
            final_angle = UNSET
        else:
            final_angle = self.final_angle

        final_torque: float | None | Unset
        if isinstance(self.final_torque, Unset):
            final_torque = UNSET
        else:
            final_torque = self.final_torque

        torque_per_preload: float | None | Unset
        if isinstance(self.torque_per_preload, Unset):
            torque_per_preload = UNSET
        else:
            torque_per_preload = self.torque_per_preload

        total_friction: float | None | Unset
        if isinstance(self.total_friction, Unset):
            total_friction = UNSET
        else:
            total_friction = self.total_friction

        total_friction_min: float | None | Unset
        if isinstance(self.total_friction_min, Unset):
            total_friction_min = UNSET
        else:
            total_friction_min = self.total_friction_min

        total_friction_max: float | None | Unset
        if isinstance(self.total_friction_max, Unset):
            total_friction_max = UNSET
        else:
            total_friction_max = self.total_friction_max

        thread_friction_low: float | None | Unset
        if isinstance(self.thread_friction_low, Unset):
            thread_friction_low = UNSET
        else:
            thread_friction_low = self.thread_friction_low

        thread_friction_high: float | None | Unset
        if isinstance(self.thread_friction_high, Unset):
            thread_friction_high = UNSET
        else:
            thread_friction_high = self.thread_friction_high

        preload: float | None | Unset
        if isinstance(self.preload, Unset):
            preload = UNSET
        else:
            preload = self.preload

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

        yield_preload_min: float | None | Unset
        if isinstance(self.yield_preload_min, Unset):
            yield_preload_min = UNSET
        else:
            yield_preload_min = self.yield_preload_min

        assembly_preload_min: float | None | Unset
        if isinstance(self.assembly_preload_min, Unset):
            assembly_preload_min = UNSET
        else:
            assembly_preload_min = self.assembly_preload_min

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        preload_in_window: bool | None | Unset
        if isinstance(self.preload_in_window, Unset):
            preload_in_window = UNSET
        else:
            preload_in_window = self.preload_in_window

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if steps_found is not UNSET:
            field_dict["steps_found"] = steps_found
        if step_analysed is not UNSET:
            field_dict["step_analysed"] = step_analysed
        if snug_angle is not UNSET:
            field_dict["snug_angle"] = snug_angle
        if snug_torque is not UNSET:
            field_dict["snug_torque"] = snug_torque
        if zero_preload_angle is not UNSET:
            field_dict["zero_preload_angle"] = zero_preload_angle
        if elastic_window_start is not UNSET:
            field_dict["elastic_window_start"] = elastic_window_start
        if elastic_window_end is not UNSET:
            field_dict["elastic_window_end"] = elastic_window_end
        if elastic_rate is not UNSET:
            field_dict["elastic_rate"] = elastic_rate
        if predicted_rate_min is not UNSET:
            field_dict["predicted_rate_min"] = predicted_rate_min
        if predicted_rate_max is not UNSET:
            field_dict["predicted_rate_max"] = predicted_rate_max
        if yield_detected is not UNSET:
            field_dict["yield_detected"] = yield_detected
        if yield_angle is not UNSET:
            field_dict["yield_angle"] = yield_angle
        if yield_torque is not UNSET:
            field_dict["yield_torque"] = yield_torque
        if snug_to_yield_angle is not UNSET:
            field_dict["snug_to_yield_angle"] = snug_to_yield_angle
        if predicted_yield_torque_min is not UNSET:
            field_dict["predicted_yield_torque_min"] = predicted_yield_torque_min
        if predicted_yield_torque_max is not UNSET:
            field_dict["predicted_yield_torque_max"] = predicted_yield_torque_max
        if predicted_snug_to_yield_min is not UNSET:
            field_dict["predicted_snug_to_yield_min"] = predicted_snug_to_yield_min
        if predicted_snug_to_yield_max is not UNSET:
            field_dict["predicted_snug_to_yield_max"] = predicted_snug_to_yield_max
        if final_angle is not UNSET:
            field_dict["final_angle"] = final_angle
        if final_torque is not UNSET:
            field_dict["final_torque"] = final_torque
        if torque_per_preload is not UNSET:
            field_dict["torque_per_preload"] = torque_per_preload
        if total_friction is not UNSET:
            field_dict["total_friction"] = total_friction
        if total_friction_min is not UNSET:
            field_dict["total_friction_min"] = total_friction_min
        if total_friction_max is not UNSET:
            field_dict["total_friction_max"] = total_friction_max
        if thread_friction_low is not UNSET:
            field_dict["thread_friction_low"] = thread_friction_low
        if thread_friction_high is not UNSET:
            field_dict["thread_friction_high"] = thread_friction_high
        if preload is not UNSET:
            field_dict["preload"] = preload
        if preload_min is not UNSET:
            field_dict["preload_min"] = preload_min
        if preload_max is not UNSET:
            field_dict["preload_max"] = preload_max
        if yield_preload_min is not UNSET:
            field_dict["yield_preload_min"] = yield_preload_min
        if assembly_preload_min is not UNSET:
            field_dict["assembly_preload_min"] = assembly_preload_min
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload
        if preload_in_window is not UNSET:
            field_dict["preload_in_window"] = preload_in_window

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_steps_found(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        steps_found = _parse_steps_found(d.pop("steps_found", UNSET))

        def _parse_step_analysed(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        step_analysed = _parse_step_analysed(d.pop("step_analysed", UNSET))

        def _parse_snug_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        snug_angle = _parse_snug_angle(d.pop("snug_angle", UNSET))

        def _parse_snug_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        snug_torque = _parse_snug_torque(d.pop("snug_torque", UNSET))

        def _parse_zero_preload_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        zero_preload_angle = _parse_zero_preload_angle(d.pop("zero_preload_angle", UNSET))

        def _parse_elastic_window_start(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        elastic_window_start = _parse_elastic_window_start(d.pop("elastic_window_start", UNSET))

        def _parse_elastic_window_end(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        elastic_window_end = _parse_elastic_window_end(d.pop("elastic_window_end", UNSET))

        def _parse_elastic_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        elastic_rate = _parse_elastic_rate(d.pop("elastic_rate", UNSET))

        def _parse_predicted_rate_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        predicted_rate_min = _parse_predicted_rate_min(d.pop("predicted_rate_min", UNSET))

        def _parse_predicted_rate_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        predicted_rate_max = _parse_predicted_rate_max(d.pop("predicted_rate_max", UNSET))

        def _parse_yield_detected(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        yield_detected = _parse_yield_detected(d.pop("yield_detected", UNSET))

        def _parse_yield_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_angle = _parse_yield_angle(d.pop("yield_angle", UNSET))

        def _parse_yield_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_torque = _parse_yield_torque(d.pop("yield_torque", UNSET))

        def _parse_snug_to_yield_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        snug_to_yield_angle = _parse_snug_to_yield_angle(d.pop("snug_to_yield_angle", UNSET))

        def _parse_predicted_yield_torque_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        predicted_yield_torque_min = _parse_predicted_yield_torque_min(d.pop("predicted_yield_torque_min", UNSET))

        def _parse_predicted_yield_torque_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        predicted_yield_torque_max = _parse_predicted_yield_torque_max(d.pop("predicted_yield_torque_max", UNSET))

        def _parse_predicted_snug_to_yield_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        predicted_snug_to_yield_min = _parse_predicted_snug_to_yield_min(d.pop("predicted_snug_to_yield_min", UNSET))

        def _parse_predicted_snug_to_yield_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        predicted_snug_to_yield_max = _parse_predicted_snug_to_yield_max(d.pop("predicted_snug_to_yield_max", UNSET))

        def _parse_final_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        final_angle = _parse_final_angle(d.pop("final_angle", UNSET))

        def _parse_final_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        final_torque = _parse_final_torque(d.pop("final_torque", UNSET))

        def _parse_torque_per_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_per_preload = _parse_torque_per_preload(d.pop("torque_per_preload", UNSET))

        def _parse_total_friction(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction = _parse_total_friction(d.pop("total_friction", UNSET))

        def _parse_total_friction_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction_min = _parse_total_friction_min(d.pop("total_friction_min", UNSET))

        def _parse_total_friction_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_friction_max = _parse_total_friction_max(d.pop("total_friction_max", UNSET))

        def _parse_thread_friction_low(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_friction_low = _parse_thread_friction_low(d.pop("thread_friction_low", UNSET))

        def _parse_thread_friction_high(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thread_friction_high = _parse_thread_friction_high(d.pop("thread_friction_high", UNSET))

        def _parse_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload = _parse_preload(d.pop("preload", UNSET))

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

        def _parse_yield_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_preload_min = _parse_yield_preload_min(d.pop("yield_preload_min", UNSET))

        def _parse_assembly_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload_min = _parse_assembly_preload_min(d.pop("assembly_preload_min", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        def _parse_preload_in_window(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        preload_in_window = _parse_preload_in_window(d.pop("preload_in_window", UNSET))

        trace_analysis_results = cls(
            steps_found=steps_found,
            step_analysed=step_analysed,
            snug_angle=snug_angle,
            snug_torque=snug_torque,
            zero_preload_angle=zero_preload_angle,
            elastic_window_start=elastic_window_start,
            elastic_window_end=elastic_window_end,
            elastic_rate=elastic_rate,
            predicted_rate_min=predicted_rate_min,
            predicted_rate_max=predicted_rate_max,
            yield_detected=yield_detected,
            yield_angle=yield_angle,
            yield_torque=yield_torque,
            snug_to_yield_angle=snug_to_yield_angle,
            predicted_yield_torque_min=predicted_yield_torque_min,
            predicted_yield_torque_max=predicted_yield_torque_max,
            predicted_snug_to_yield_min=predicted_snug_to_yield_min,
            predicted_snug_to_yield_max=predicted_snug_to_yield_max,
            final_angle=final_angle,
            final_torque=final_torque,
            torque_per_preload=torque_per_preload,
            total_friction=total_friction,
            total_friction_min=total_friction_min,
            total_friction_max=total_friction_max,
            thread_friction_low=thread_friction_low,
            thread_friction_high=thread_friction_high,
            preload=preload,
            preload_min=preload_min,
            preload_max=preload_max,
            yield_preload_min=yield_preload_min,
            assembly_preload_min=assembly_preload_min,
            permissible_preload=permissible_preload,
            preload_in_window=preload_in_window,
        )

        trace_analysis_results.additional_properties = d
        return trace_analysis_results

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
