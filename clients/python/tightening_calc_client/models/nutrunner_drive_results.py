from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="NutrunnerDriveResults")


@_attrs_define
class NutrunnerDriveResults:
    """
    Attributes:
        kinetic_energy (float | None | Unset): Kinetic energy T of parts 1…5 at the working speed [000, eq. 3–4] [J]
        acceleration_time (float | None | Unset): Spin-up time: T/P [000, eq. 5], or ∫J dω/M(ω) (motor_curve) [s]
        shaft_stiffness (float | None | Unset): Torsional stiffness C7 of the flywheel shaft [000, eq. 9] [N*m/rad]
        spindle_stiffness (float | None | Unset): Torsional stiffness C8 of a spindle [000, eq. 9] [N*m/rad]
        impact_torque (float | None | Unset): Peak torque M on the struck spindle [000, eq. 7–8]; with the gear ratio in
            the gear_ratio and motor_curve rungs [N*m]
        max_spindle_torque (float | None | Unset): M_max = M − (z−1)·M_tr [000, eq. 10] [N*m]
        spindle_torque_reserve (float | None | Unset): M_max / M_nut: how many times the torque reaching the nut covers
            what the wheel nut needs ([000]: the spindle torque must tighten and free it) [dimensionless]
        friction_clutch_torque (float | None | Unset): M_tr of each idle spindle's friction clutch, as eq. 10 takes it:
            z_f μ F (D + d)/4 from the clamp of its nut [000] where friction_clutch_clamp_force is given, else
            idle_spindle_friction_torque [N*m]
        shaft_twist (float | None | Unset): Twist of shaft 7 during the blow [000, eq. 6] [rad]
        spindle_twist (float | None | Unset): Twist of spindle 8 during the blow [000, eq. 6] [rad]
        shaft_torque (float | None | Unset): Torque on shaft 7 during the blow: M (source) or u·M (geared) [N*m]
        coupling_energy (float | None | Unset): Kinetic energy of coupling 1 [000, eq. 3] [J]
        motor_pulley_energy (float | None | Unset): Kinetic energy of motor pulley 2 [000, eq. 3] [J]
        flywheel_energy (float | None | Unset): Kinetic energy of flywheel 3 [000, eq. 3] [J]
        drive_gear_energy (float | None | Unset): Kinetic energy of drive gear 4 [000, eq. 3] [J]
        spindle_gears_energy (float | None | Unset): Kinetic energy of all z spindle gears 5 [000, eq. 3] [J]
        equivalent_inertia (float | None | Unset): Inertia of parts 1…5 referred to the motor shaft, 2T/ω² [000, eq.
            3–4] [kg*m^2]
        flywheel_speed (float | None | Unset): Flywheel speed ω3 = ω·D2/D3 [rad/s]
        spindle_gear_speed (float | None | Unset): Spindle gear speed ω5 = ω3·D4/D5 [rad/s]
        gear_ratio (float | None | Unset): u = D4/D5, shaft torque over spindle torque [dimensionless]
        gear_ratio_torque_change (float | None | Unset): Relative change of the impact torque when the gear ratio is
            taken into account: M(u)/M(source) − 1 [dimensionless]
        shaft_shear_stress (float | None | Unset): Peak shear stress in shaft 7, 16·M7/(π d7³) [Pa]
        spindle_shear_stress (float | None | Unset): Peak shear stress in spindle 8, 16·M/(π d8³) [Pa]
        drive_inertia (float | None | Unset): motor_curve: inertia accelerated by the motor at its shaft (rotor, parts
            1…5, divided by the belt and gear efficiencies) [kg*m^2]
        constant_power_time (float | None | Unset): motor_curve: the source's constant-power time T/P [000, eq. 5] [s]
        time_vs_constant_power (float | None | Unset): motor_curve: spin-up time over the constant-power time, minus 1
            [dimensionless]
        coupling_slip_torque (float | None | Unset): slip torque to set on the safety coupling 1: max(K P/ω, T_a), T_a =
            T_b J_L/(J_A + J_L) while a motor with breakdown torque T_b and rotor inertia J_A starts parts 2…5 (J_L) [N*m]
    """

    kinetic_energy: float | None | Unset = UNSET
    acceleration_time: float | None | Unset = UNSET
    shaft_stiffness: float | None | Unset = UNSET
    spindle_stiffness: float | None | Unset = UNSET
    impact_torque: float | None | Unset = UNSET
    max_spindle_torque: float | None | Unset = UNSET
    spindle_torque_reserve: float | None | Unset = UNSET
    friction_clutch_torque: float | None | Unset = UNSET
    shaft_twist: float | None | Unset = UNSET
    spindle_twist: float | None | Unset = UNSET
    shaft_torque: float | None | Unset = UNSET
    coupling_energy: float | None | Unset = UNSET
    motor_pulley_energy: float | None | Unset = UNSET
    flywheel_energy: float | None | Unset = UNSET
    drive_gear_energy: float | None | Unset = UNSET
    spindle_gears_energy: float | None | Unset = UNSET
    equivalent_inertia: float | None | Unset = UNSET
    flywheel_speed: float | None | Unset = UNSET
    spindle_gear_speed: float | None | Unset = UNSET
    gear_ratio: float | None | Unset = UNSET
    gear_ratio_torque_change: float | None | Unset = UNSET
    shaft_shear_stress: float | None | Unset = UNSET
    spindle_shear_stress: float | None | Unset = UNSET
    drive_inertia: float | None | Unset = UNSET
    constant_power_time: float | None | Unset = UNSET
    time_vs_constant_power: float | None | Unset = UNSET
    coupling_slip_torque: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        kinetic_energy: float | None | Unset
        if isinstance(self.kinetic_energy, Unset):
            kinetic_energy = UNSET
        else:
            kinetic_energy = self.kinetic_energy

        acceleration_time: float | None | Unset
        if isinstance(self.acceleration_time, Unset):
            acceleration_time = UNSET
        else:
            acceleration_time = self.acceleration_time

        shaft_stiffness: float | None | Unset
        if isinstance(self.shaft_stiffness, Unset):
            shaft_stiffness = UNSET
        else:
            shaft_stiffness = self.shaft_stiffness

        spindle_stiffness: float | None | Unset
        if isinstance(self.spindle_stiffness, Unset):
            spindle_stiffness = UNSET
        else:
            spindle_stiffness = self.spindle_stiffness

        impact_torque: float | None | Unset
        if isinstance(self.impact_torque, Unset):
            impact_torque = UNSET
        else:
            impact_torque = self.impact_torque

        max_spindle_torque: float | None | Unset
        if isinstance(self.max_spindle_torque, Unset):
            max_spindle_torque = UNSET
        else:
            max_spindle_torque = self.max_spindle_torque

        spindle_torque_reserve: float | None | Unset
        if isinstance(self.spindle_torque_reserve, Unset):
            spindle_torque_reserve = UNSET
        else:
            spindle_torque_reserve = self.spindle_torque_reserve

        friction_clutch_torque: float | None | Unset
        if isinstance(self.friction_clutch_torque, Unset):
            friction_clutch_torque = UNSET
        else:
            friction_clutch_torque = self.friction_clutch_torque

        shaft_twist: float | None | Unset
        if isinstance(self.shaft_twist, Unset):
            shaft_twist = UNSET
        else:
            shaft_twist = self.shaft_twist

        spindle_twist: float | None | Unset
        if isinstance(self.spindle_twist, Unset):
            spindle_twist = UNSET
        else:
            spindle_twist = self.spindle_twist

        shaft_torque: float | None | Unset
        if isinstance(self.shaft_torque, Unset):
            shaft_torque = UNSET
        else:
            shaft_torque = self.shaft_torque

        coupling_energy: float | None | Unset
        if isinstance(self.coupling_energy, Unset):
            coupling_energy = UNSET
        else:
            coupling_energy = self.coupling_energy

        motor_pulley_energy: float | None | Unset
        if isinstance(self.motor_pulley_energy, Unset):
            motor_pulley_energy = UNSET
        else:
            motor_pulley_energy = self.motor_pulley_energy

        flywheel_energy: float | None | Unset
        if isinstance(self.flywheel_energy, Unset):
            flywheel_energy = UNSET
        else:
            flywheel_energy = self.flywheel_energy

        drive_gear_energy: float | None | Unset
        if isinstance(self.drive_gear_energy, Unset):
            drive_gear_energy = UNSET
        else:
            drive_gear_energy = self.drive_gear_energy

        spindle_gears_energy: float | None | Unset
        if isinstance(self.spindle_gears_energy, Unset):
            spindle_gears_energy = UNSET
        else:
            spindle_gears_energy = self.spindle_gears_energy

        equivalent_inertia: float | None | Unset
        if isinstance(self.equivalent_inertia, Unset):
            equivalent_inertia = UNSET
        else:
            equivalent_inertia = self.equivalent_inertia

        flywheel_speed: float | None | Unset
        if isinstance(self.flywheel_speed, Unset):
            flywheel_speed = UNSET
        else:
            flywheel_speed = self.flywheel_speed

        spindle_gear_speed: float | None | Unset
        if isinstance(self.spindle_gear_speed, Unset):
            spindle_gear_speed = UNSET
        else:
            spindle_gear_speed = self.spindle_gear_speed

        gear_ratio: float | None | Unset
        if isinstance(self.gear_ratio, Unset):
            gear_ratio = UNSET
        else:
            gear_ratio = self.gear_ratio

        gear_ratio_torque_change: float | None | Unset
        if isinstance(self.gear_ratio_torque_change, Unset):
            gear_ratio_torque_change = UNSET
        else:
            gear_ratio_torque_change = self.gear_ratio_torque_change

        shaft_shear_stress: float | None | Unset
        if isinstance(self.shaft_shear_stress, Unset):
            shaft_shear_stress = UNSET
        else:
            shaft_shear_stress = self.shaft_shear_stress

        spindle_shear_stress: float | None | Unset
        if isinstance(self.spindle_shear_stress, Unset):
            spindle_shear_stress = UNSET
        else:
            spindle_shear_stress = self.spindle_shear_stress

        drive_inertia: float | None | Unset
        if isinstance(self.drive_inertia, Unset):
            drive_inertia = UNSET
        else:
            drive_inertia = self.drive_inertia

        constant_power_time: float | None | Unset
        if isinstance(self.constant_power_time, Unset):
            constant_power_time = UNSET
        else:
            constant_power_time = self.constant_power_time

        time_vs_constant_power: float | None | Unset
        if isinstance(self.time_vs_constant_power, Unset):
            time_vs_constant_power = UNSET
        else:
            time_vs_constant_power = self.time_vs_constant_power

        coupling_slip_torque: float | None | Unset
        if isinstance(self.coupling_slip_torque, Unset):
            coupling_slip_torque = UNSET
        else:
            coupling_slip_torque = self.coupling_slip_torque

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if kinetic_energy is not UNSET:
            field_dict["kinetic_energy"] = kinetic_energy
        if acceleration_time is not UNSET:
            field_dict["acceleration_time"] = acceleration_time
        if shaft_stiffness is not UNSET:
            field_dict["shaft_stiffness"] = shaft_stiffness
        if spindle_stiffness is not UNSET:
            field_dict["spindle_stiffness"] = spindle_stiffness
        if impact_torque is not UNSET:
            field_dict["impact_torque"] = impact_torque
        if max_spindle_torque is not UNSET:
            field_dict["max_spindle_torque"] = max_spindle_torque
        if spindle_torque_reserve is not UNSET:
            field_dict["spindle_torque_reserve"] = spindle_torque_reserve
        if friction_clutch_torque is not UNSET:
            field_dict["friction_clutch_torque"] = friction_clutch_torque
        if shaft_twist is not UNSET:
            field_dict["shaft_twist"] = shaft_twist
        if spindle_twist is not UNSET:
            field_dict["spindle_twist"] = spindle_twist
        if shaft_torque is not UNSET:
            field_dict["shaft_torque"] = shaft_torque
        if coupling_energy is not UNSET:
            field_dict["coupling_energy"] = coupling_energy
        if motor_pulley_energy is not UNSET:
            field_dict["motor_pulley_energy"] = motor_pulley_energy
        if flywheel_energy is not UNSET:
            field_dict["flywheel_energy"] = flywheel_energy
        if drive_gear_energy is not UNSET:
            field_dict["drive_gear_energy"] = drive_gear_energy
        if spindle_gears_energy is not UNSET:
            field_dict["spindle_gears_energy"] = spindle_gears_energy
        if equivalent_inertia is not UNSET:
            field_dict["equivalent_inertia"] = equivalent_inertia
        if flywheel_speed is not UNSET:
            field_dict["flywheel_speed"] = flywheel_speed
        if spindle_gear_speed is not UNSET:
            field_dict["spindle_gear_speed"] = spindle_gear_speed
        if gear_ratio is not UNSET:
            field_dict["gear_ratio"] = gear_ratio
        if gear_ratio_torque_change is not UNSET:
            field_dict["gear_ratio_torque_change"] = gear_ratio_torque_change
        if shaft_shear_stress is not UNSET:
            field_dict["shaft_shear_stress"] = shaft_shear_stress
        if spindle_shear_stress is not UNSET:
            field_dict["spindle_shear_stress"] = spindle_shear_stress
        if drive_inertia is not UNSET:
            field_dict["drive_inertia"] = drive_inertia
        if constant_power_time is not UNSET:
            field_dict["constant_power_time"] = constant_power_time
        if time_vs_constant_power is not UNSET:
            field_dict["time_vs_constant_power"] = time_vs_constant_power
        if coupling_slip_torque is not UNSET:
            field_dict["coupling_slip_torque"] = coupling_slip_torque

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_kinetic_energy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        kinetic_energy = _parse_kinetic_energy(d.pop("kinetic_energy", UNSET))

        def _parse_acceleration_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        acceleration_time = _parse_acceleration_time(d.pop("acceleration_time", UNSET))

        def _parse_shaft_stiffness(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shaft_stiffness = _parse_shaft_stiffness(d.pop("shaft_stiffness", UNSET))

        def _parse_spindle_stiffness(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spindle_stiffness = _parse_spindle_stiffness(d.pop("spindle_stiffness", UNSET))

        def _parse_impact_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        impact_torque = _parse_impact_torque(d.pop("impact_torque", UNSET))

        def _parse_max_spindle_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_spindle_torque = _parse_max_spindle_torque(d.pop("max_spindle_torque", UNSET))

        def _parse_spindle_torque_reserve(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spindle_torque_reserve = _parse_spindle_torque_reserve(d.pop("spindle_torque_reserve", UNSET))

        def _parse_friction_clutch_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        friction_clutch_torque = _parse_friction_clutch_torque(d.pop("friction_clutch_torque", UNSET))

        def _parse_shaft_twist(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shaft_twist = _parse_shaft_twist(d.pop("shaft_twist", UNSET))

        def _parse_spindle_twist(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spindle_twist = _parse_spindle_twist(d.pop("spindle_twist", UNSET))

        def _parse_shaft_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shaft_torque = _parse_shaft_torque(d.pop("shaft_torque", UNSET))

        def _parse_coupling_energy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        coupling_energy = _parse_coupling_energy(d.pop("coupling_energy", UNSET))

        def _parse_motor_pulley_energy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        motor_pulley_energy = _parse_motor_pulley_energy(d.pop("motor_pulley_energy", UNSET))

        def _parse_flywheel_energy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        flywheel_energy = _parse_flywheel_energy(d.pop("flywheel_energy", UNSET))

        def _parse_drive_gear_energy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        drive_gear_energy = _parse_drive_gear_energy(d.pop("drive_gear_energy", UNSET))

        def _parse_spindle_gears_energy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spindle_gears_energy = _parse_spindle_gears_energy(d.pop("spindle_gears_energy", UNSET))

        def _parse_equivalent_inertia(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        equivalent_inertia = _parse_equivalent_inertia(d.pop("equivalent_inertia", UNSET))

        def _parse_flywheel_speed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        flywheel_speed = _parse_flywheel_speed(d.pop("flywheel_speed", UNSET))

        def _parse_spindle_gear_speed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spindle_gear_speed = _parse_spindle_gear_speed(d.pop("spindle_gear_speed", UNSET))

        def _parse_gear_ratio(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        gear_ratio = _parse_gear_ratio(d.pop("gear_ratio", UNSET))

        def _parse_gear_ratio_torque_change(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        gear_ratio_torque_change = _parse_gear_ratio_torque_change(d.pop("gear_ratio_torque_change", UNSET))

        def _parse_shaft_shear_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shaft_shear_stress = _parse_shaft_shear_stress(d.pop("shaft_shear_stress", UNSET))

        def _parse_spindle_shear_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spindle_shear_stress = _parse_spindle_shear_stress(d.pop("spindle_shear_stress", UNSET))

        def _parse_drive_inertia(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        drive_inertia = _parse_drive_inertia(d.pop("drive_inertia", UNSET))

        def _parse_constant_power_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        constant_power_time = _parse_constant_power_time(d.pop("constant_power_time", UNSET))

        def _parse_time_vs_constant_power(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        time_vs_constant_power = _parse_time_vs_constant_power(d.pop("time_vs_constant_power", UNSET))

        def _parse_coupling_slip_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        coupling_slip_torque = _parse_coupling_slip_torque(d.pop("coupling_slip_torque", UNSET))

        nutrunner_drive_results = cls(
            kinetic_energy=kinetic_energy,
            acceleration_time=acceleration_time,
            shaft_stiffness=shaft_stiffness,
            spindle_stiffness=spindle_stiffness,
            impact_torque=impact_torque,
            max_spindle_torque=max_spindle_torque,
            spindle_torque_reserve=spindle_torque_reserve,
            friction_clutch_torque=friction_clutch_torque,
            shaft_twist=shaft_twist,
            spindle_twist=spindle_twist,
            shaft_torque=shaft_torque,
            coupling_energy=coupling_energy,
            motor_pulley_energy=motor_pulley_energy,
            flywheel_energy=flywheel_energy,
            drive_gear_energy=drive_gear_energy,
            spindle_gears_energy=spindle_gears_energy,
            equivalent_inertia=equivalent_inertia,
            flywheel_speed=flywheel_speed,
            spindle_gear_speed=spindle_gear_speed,
            gear_ratio=gear_ratio,
            gear_ratio_torque_change=gear_ratio_torque_change,
            shaft_shear_stress=shaft_shear_stress,
            spindle_shear_stress=spindle_shear_stress,
            drive_inertia=drive_inertia,
            constant_power_time=constant_power_time,
            time_vs_constant_power=time_vs_constant_power,
            coupling_slip_torque=coupling_slip_torque,
        )

        nutrunner_drive_results.additional_properties = d
        return nutrunner_drive_results

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
