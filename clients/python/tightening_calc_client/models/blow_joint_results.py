from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="BlowJointResults")


@_attrs_define
class BlowJointResults:
    """
    Attributes:
        tool_energy_used (float | None | Unset): kinetic energy per blow (after the blow efficiency) [J]
        tool_inertia_used (float | None | Unset): inertia of the striking tool at the nut [kg*m^2]
        tool_speed (float | None | Unset): tool speed at the blow [rad/s]
        tool_stiffness_used (float | None | Unset): torsional stiffness C of the tool [N*m/rad]
        joint_rate_used (float | None | Unset): torque rate k_j of the joint [N*m/rad]
        rigid_torque (float | None | Unset): √(2EC) + drive torque: the paper's blow into a fixed end [000, eq. 7–8, 10]
            [N*m]
        peak_torque (float | None | Unset): peak spring torque of the first blow [N*m]
        nut_rotation (float | None | Unset): nut rotation in the first blow [rad]
        torque_after_first_blow (float | None | Unset): joint torque after the first blow [N*m]
        preload_after_first_blow (float | None | Unset): preload after the first blow [N]
        blows_to_target (int | None | Unset): blows until the target torque/preload [dimensionless]
        final_torque (float | None | Unset): joint torque after the last blow [N*m]
        final_preload (float | None | Unset): preload after the last blow [N]
        saturation_torque (float | None | Unset): joint torque above which a blow no longer turns the nut (energy
            balance: (N + √(N² + 2EC))/b) [N*m]
        joint_energy_fraction (float | None | Unset): first blow's work into the joint / the tool's kinetic energy E;
            the drive's work N·φ_t during the blow is not in E, so with a drive torque it can exceed 1 [dimensionless]
        energy_supplied (float | None | Unset): energy supplied over all blows [J]
        blow_interval (float | None | Unset): time from one blow to the next: the source's motor spins the flywheel from
            rest back to its blow speed (nut-runner T/P [000, eq. 5]; rare impact: impact.rare's cycle [002]; energy:
            J_t·ω0/N) [s]
        blows_per_second (float | None | Unset): blows per second, 1/blow_interval [1/s]
        time_to_final (float | None | Unset): time from motor start to the last blow: blows × blow_interval [s]
        energy_into_joint (float | None | Unset): work into the joint over all blows [J]
        preload_verdict (None | str | Unset): final preload against [preload_min, preload_max] [dimensionless]
        yield_preload (float | None | Unset): F_M0.2: preload at which the bolt yields, torsion included (VDI 2230-1 R7,
            ν = 1) [N]
        breaking_load (float | None | Unset): F_B = R_m·A_s: the bolt's breaking load [N]
        bolt_verdict (None | str | Unset): what the blows do to the bolt: 'elastic', 'past yield' or 'past breaking'
            [dimensionless]
        clutch_torque_min (float | None | Unset): lowest slipping torque (source clutch) [001, eq. 1–3] [N*m]
        clutch_torque_max (float | None | Unset): highest slipping torque (source clutch) [N*m]
        delivered_preload_min (float | None | Unset): lowest preload the clutch gives [N]
        delivered_preload_max (float | None | Unset): highest preload the clutch gives [N]
        clutch_spring_force_for_target (float | None | Unset): spring force that sets the clutch for the target preload
            at nominal friction [N]
    """

    tool_energy_used: float | None | Unset = UNSET
    tool_inertia_used: float | None | Unset = UNSET
    tool_speed: float | None | Unset = UNSET
    tool_stiffness_used: float | None | Unset = UNSET
    joint_rate_used: float | None | Unset = UNSET
    rigid_torque: float | None | Unset = UNSET
    peak_torque: float | None | Unset = UNSET
    nut_rotation: float | None | Unset = UNSET
    torque_after_first_blow: float | None | Unset = UNSET
    preload_after_first_blow: float | None | Unset = UNSET
    blows_to_target: int | None | Unset = UNSET
    final_torque: float | None | Unset = UNSET
    final_preload: float | None | Unset = UNSET
    saturation_torque: float | None | Unset = UNSET
    joint_energy_fraction: float | None | Unset = UNSET
    energy_supplied: float | None | Unset = UNSET
    blow_interval: float | None | Unset = UNSET
    blows_per_second: float | None | Unset = UNSET
    time_to_final: float | None | Unset = UNSET
    energy_into_joint: float | None | Unset = UNSET
    preload_verdict: None | str | Unset = UNSET
    yield_preload: float | None | Unset = UNSET
    breaking_load: float | None | Unset = UNSET
    bolt_verdict: None | str | Unset = UNSET
    clutch_torque_min: float | None | Unset = UNSET
    clutch_torque_max: float | None | Unset = UNSET
    delivered_preload_min: float | None | Unset = UNSET
    delivered_preload_max: float | None | Unset = UNSET
    clutch_spring_force_for_target: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        tool_energy_used: float | None | Unset
        if isinstance(self.tool_energy_used, Unset):
            tool_energy_used = UNSET
        else:
            tool_energy_used = self.tool_energy_used

        tool_inertia_used: float | None | Unset
        if isinstance(self.tool_inertia_used, Unset):
            tool_inertia_used = UNSET
        else:
            tool_inertia_used = self.tool_inertia_used

        tool_speed: float | None | Unset
        if isinstance(self.tool_speed, Unset):
            tool_speed = UNSET
        else:
            tool_speed = self.tool_speed

        tool_stiffness_used: float | None | Unset
        if isinstance(self.tool_stiffness_used, Unset):
            tool_stiffness_used = UNSET
        else:
            tool_stiffness_used = self.tool_stiffness_used

        joint_rate_used: float | None | Unset
        if isinstance(self.joint_rate_used, Unset):
            joint_rate_used = UNSET
        else:
            joint_rate_used = self.joint_rate_used

        rigid_torque: float | None | Unset
        if isinstance(self.rigid_torque, Unset):
            rigid_torque = UNSET
        else:
            rigid_torque = self.rigid_torque

        peak_torque: float | None | Unset
        if isinstance(self.peak_torque, Unset):
            peak_torque = UNSET
        else:
            peak_torque = self.peak_torque

        nut_rotation: float | None | Unset
        if isinstance(self.nut_rotation, Unset):
            nut_rotation = UNSET
        else:
            nut_rotation = self.nut_rotation

        torque_after_first_blow: float | None | Unset
        if isinstance(self.torque_after_first_blow, Unset):
            torque_after_first_blow = UNSET
        else:
            torque_after_first_blow = self.torque_after_first_blow

        preload_after_first_blow: float | None | Unset
        if isinstance(self.preload_after_first_blow, Unset):
            preload_after_first_blow = UNSET
        else:
            preload_after_first_blow = self.preload_after_first_blow

        blows_to_target: int | None | Unset
        if isinstance(self.blows_to_target, Unset):
            blows_to_target = UNSET
        else:
            blows_to_target = self.blows_to_target

        final_torque: float | None | Unset
        if isinstance(self.final_torque, Unset):
            final_torque = UNSET
        else:
            final_torque = self.final_torque

        final_preload: float | None | Unset
        if isinstance(self.final_preload, Unset):
            final_preload = UNSET
        else:
            final_preload = self.final_preload

        saturation_torque: float | None | Unset
        if isinstance(self.saturation_torque, Unset):
            saturation_torque = UNSET
        else:
            saturation_torque = self.saturation_torque

        joint_energy_fraction: float | None | Unset
        if isinstance(self.joint_energy_fraction, Unset):
            joint_energy_fraction = UNSET
        else:
            joint_energy_fraction = self.joint_energy_fraction

        energy_supplied: float | None | Unset
        if isinstance(self.energy_supplied, Unset):
            energy_supplied = UNSET
        else:
            energy_supplied = self.energy_supplied

        blow_interval: float | None | Unset
        if isinstance(self.blow_interval, Unset):
            blow_interval = UNSET
        else:
            blow_interval = self.blow_interval

        blows_per_second: float | None | Unset
        if isinstance(self.blows_per_second, Unset):
            blows_per_second = UNSET
        else:
            blows_per_second = self.blows_per_second

        time_to_final: float | None | Unset
        if isinstance(self.time_to_final, Unset):
            time_to_final = UNSET
        else:
            time_to_final = self.time_to_final

        energy_into_joint: float | None | Unset
        if isinstance(self.energy_into_joint, Unset):
            energy_into_joint = UNSET
        else:
            energy_into_joint = self.energy_into_joint

        preload_verdict: None | str | Unset
        if isinstance(self.preload_verdict, Unset):
            preload_verdict = UNSET
        else:
            preload_verdict = self.preload_verdict

        yield_preload: float | None | Unset
        if isinstance(self.yield_preload, Unset):
            yield_preload = UNSET
        else:
            yield_preload = self.yield_preload

        breaking_load: float | None | Unset
        if isinstance(self.breaking_load, Unset):
            breaking_load = UNSET
        else:
            breaking_load = self.breaking_load

        bolt_verdict: None | str | Unset
        if isinstance(self.bolt_verdict, Unset):
            bolt_verdict = UNSET
        else:
            bolt_verdict = self.bolt_verdict

        clutch_torque_min: float | None | Unset
        if isinstance(self.clutch_torque_min, Unset):
            clutch_torque_min = UNSET
        else:
            clutch_torque_min = self.clutch_torque_min

        clutch_torque_max: float | None | Unset
        if isinstance(self.clutch_torque_max, Unset):
            clutch_torque_max = UNSET
        else:
            clutch_torque_max = self.clutch_torque_max

        delivered_preload_min: float | None | Unset
        if isinstance(self.delivered_preload_min, Unset):
            delivered_preload_min = UNSET
        else:
            delivered_preload_min = self.delivered_preload_min

        delivered_preload_max: float | None | Unset
        if isinstance(self.delivered_preload_max, Unset):
            delivered_preload_max = UNSET
        else:
            delivered_preload_max = self.delivered_preload_max

        clutch_spring_force_for_target: float | None | Unset
        if isinstance(self.clutch_spring_force_for_target, Unset):
            clutch_spring_force_for_target = UNSET
        else:
            clutch_spring_force_for_target = self.clutch_spring_force_for_target

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if tool_energy_used is not UNSET:
            field_dict["tool_energy_used"] = tool_energy_used
        if tool_inertia_used is not UNSET:
            field_dict["tool_inertia_used"] = tool_inertia_used
        if tool_speed is not UNSET:
            field_dict["tool_speed"] = tool_speed
        if tool_stiffness_used is not UNSET:
            field_dict["tool_stiffness_used"] = tool_stiffness_used
        if joint_rate_used is not UNSET:
            field_dict["joint_rate_used"] = joint_rate_used
        if rigid_torque is not UNSET:
            field_dict["rigid_torque"] = rigid_torque
        if peak_torque is not UNSET:
            field_dict["peak_torque"] = peak_torque
        if nut_rotation is not UNSET:
            field_dict["nut_rotation"] = nut_rotation
        if torque_after_first_blow is not UNSET:
            field_dict["torque_after_first_blow"] = torque_after_first_blow
        if preload_after_first_blow is not UNSET:
            field_dict["preload_after_first_blow"] = preload_after_first_blow
        if blows_to_target is not UNSET:
            field_dict["blows_to_target"] = blows_to_target
        if final_torque is not UNSET:
            field_dict["final_torque"] = final_torque
        if final_preload is not UNSET:
            field_dict["final_preload"] = final_preload
        if saturation_torque is not UNSET:
            field_dict["saturation_torque"] = saturation_torque
        if joint_energy_fraction is not UNSET:
            field_dict["joint_energy_fraction"] = joint_energy_fraction
        if energy_supplied is not UNSET:
            field_dict["energy_supplied"] = energy_supplied
        if blow_interval is not UNSET:
            field_dict["blow_interval"] = blow_interval
        if blows_per_second is not UNSET:
            field_dict["blows_per_second"] = blows_per_second
        if time_to_final is not UNSET:
            field_dict["time_to_final"] = time_to_final
        if energy_into_joint is not UNSET:
            field_dict["energy_into_joint"] = energy_into_joint
        if preload_verdict is not UNSET:
            field_dict["preload_verdict"] = preload_verdict
        if yield_preload is not UNSET:
            field_dict["yield_preload"] = yield_preload
        if breaking_load is not UNSET:
            field_dict["breaking_load"] = breaking_load
        if bolt_verdict is not UNSET:
            field_dict["bolt_verdict"] = bolt_verdict
        if clutch_torque_min is not UNSET:
            field_dict["clutch_torque_min"] = clutch_torque_min
        if clutch_torque_max is not UNSET:
            field_dict["clutch_torque_max"] = clutch_torque_max
        if delivered_preload_min is not UNSET:
            field_dict["delivered_preload_min"] = delivered_preload_min
        if delivered_preload_max is not UNSET:
            field_dict["delivered_preload_max"] = delivered_preload_max
        if clutch_spring_force_for_target is not UNSET:
            field_dict["clutch_spring_force_for_target"] = clutch_spring_force_for_target

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_tool_energy_used(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tool_energy_used = _parse_tool_energy_used(d.pop("tool_energy_used", UNSET))

        def _parse_tool_inertia_used(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tool_inertia_used = _parse_tool_inertia_used(d.pop("tool_inertia_used", UNSET))

        def _parse_tool_speed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tool_speed = _parse_tool_speed(d.pop("tool_speed", UNSET))

        def _parse_tool_stiffness_used(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tool_stiffness_used = _parse_tool_stiffness_used(d.pop("tool_stiffness_used", UNSET))

        def _parse_joint_rate_used(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        joint_rate_used = _parse_joint_rate_used(d.pop("joint_rate_used", UNSET))

        def _parse_rigid_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rigid_torque = _parse_rigid_torque(d.pop("rigid_torque", UNSET))

        def _parse_peak_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        peak_torque = _parse_peak_torque(d.pop("peak_torque", UNSET))

        def _parse_nut_rotation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        nut_rotation = _parse_nut_rotation(d.pop("nut_rotation", UNSET))

        def _parse_torque_after_first_blow(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_after_first_blow = _parse_torque_after_first_blow(d.pop("torque_after_first_blow", UNSET))

        def _parse_preload_after_first_blow(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_after_first_blow = _parse_preload_after_first_blow(d.pop("preload_after_first_blow", UNSET))

        def _parse_blows_to_target(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        blows_to_target = _parse_blows_to_target(d.pop("blows_to_target", UNSET))

        def _parse_final_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        final_torque = _parse_final_torque(d.pop("final_torque", UNSET))

        def _parse_final_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        final_preload = _parse_final_preload(d.pop("final_preload", UNSET))

        def _parse_saturation_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        saturation_torque = _parse_saturation_torque(d.pop("saturation_torque", UNSET))

        def _parse_joint_energy_fraction(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        joint_energy_fraction = _parse_joint_energy_fraction(d.pop("joint_energy_fraction", UNSET))

        def _parse_energy_supplied(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        energy_supplied = _parse_energy_supplied(d.pop("energy_supplied", UNSET))

        def _parse_blow_interval(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        blow_interval = _parse_blow_interval(d.pop("blow_interval", UNSET))

        def _parse_blows_per_second(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        blows_per_second = _parse_blows_per_second(d.pop("blows_per_second", UNSET))

        def _parse_time_to_final(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        time_to_final = _parse_time_to_final(d.pop("time_to_final", UNSET))

        def _parse_energy_into_joint(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        energy_into_joint = _parse_energy_into_joint(d.pop("energy_into_joint", UNSET))

        def _parse_preload_verdict(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        preload_verdict = _parse_preload_verdict(d.pop("preload_verdict", UNSET))

        def _parse_yield_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_preload = _parse_yield_preload(d.pop("yield_preload", UNSET))

        def _parse_breaking_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        breaking_load = _parse_breaking_load(d.pop("breaking_load", UNSET))

        def _parse_bolt_verdict(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        bolt_verdict = _parse_bolt_verdict(d.pop("bolt_verdict", UNSET))

        def _parse_clutch_torque_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clutch_torque_min = _parse_clutch_torque_min(d.pop("clutch_torque_min", UNSET))

        def _parse_clutch_torque_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clutch_torque_max = _parse_clutch_torque_max(d.pop("clutch_torque_max", UNSET))

        def _parse_delivered_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        delivered_preload_min = _parse_delivered_preload_min(d.pop("delivered_preload_min", UNSET))

        def _parse_delivered_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        delivered_preload_max = _parse_delivered_preload_max(d.pop("delivered_preload_max", UNSET))

        def _parse_clutch_spring_force_for_target(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clutch_spring_force_for_target = _parse_clutch_spring_force_for_target(
            d.pop("clutch_spring_force_for_target", UNSET)
        )

        blow_joint_results = cls(
            tool_energy_used=tool_energy_used,
            tool_inertia_used=tool_inertia_used,
            tool_speed=tool_speed,
            tool_stiffness_used=tool_stiffness_used,
            joint_rate_used=joint_rate_used,
            rigid_torque=rigid_torque,
            peak_torque=peak_torque,
            nut_rotation=nut_rotation,
            torque_after_first_blow=torque_after_first_blow,
            preload_after_first_blow=preload_after_first_blow,
            blows_to_target=blows_to_target,
            final_torque=final_torque,
            final_preload=final_preload,
            saturation_torque=saturation_torque,
            joint_energy_fraction=joint_energy_fraction,
            energy_supplied=energy_supplied,
            blow_interval=blow_interval,
            blows_per_second=blows_per_second,
            time_to_final=time_to_final,
            energy_into_joint=energy_into_joint,
            preload_verdict=preload_verdict,
            yield_preload=yield_preload,
            breaking_load=breaking_load,
            bolt_verdict=bolt_verdict,
            clutch_torque_min=clutch_torque_min,
            clutch_torque_max=clutch_torque_max,
            delivered_preload_min=delivered_preload_min,
            delivered_preload_max=delivered_preload_max,
            clutch_spring_force_for_target=clutch_spring_force_for_target,
        )

        blow_joint_results.additional_properties = d
        return blow_joint_results

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
