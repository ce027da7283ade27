from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.nutrunner_drive_study_request_nutrunner_drive_study_base_motor_curve_type_0 import (
    NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="NutrunnerDriveStudyRequestNutrunnerDriveStudyBase")


@_attrs_define
class NutrunnerDriveStudyRequestNutrunnerDriveStudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        motor_power (float | str | Unset): Motor power P, delivered at constant power during spin-up [000, eq. 2, 5]
        motor_speed (float | str | Unset): Motor shaft speed ω at the end of spin-up (the working speed at impact) [000,
            eq. 3–5]
        coupling_mass (float | str | Unset): Mass of the safety coupling 1, a solid uniform disc [000, eq. 3–4]
        coupling_diameter (float | str | Unset): Outer diameter of the safety coupling 1, a solid uniform disc [000, eq.
            3–4]
        motor_pulley_mass (float | str | Unset): Mass of the motor pulley 2, a solid uniform disc [000, eq. 3–4]
        motor_pulley_diameter (float | str | Unset): Diameter of the motor pulley 2, also taken as the belt's pitch
            diameter [000, eq. 3–5]
        flywheel_mass (float | str | Unset): Mass of the flywheel 3 (the driven pulley), a solid uniform disc [000, eq.
            3–4]
        flywheel_diameter (float | str | Unset): Diameter of the flywheel 3 (the driven pulley), also taken as the
            belt's pitch diameter [000, eq. 3–5]
        drive_gear_mass (float | str | Unset): Mass of the drive gear 4, a solid uniform disc [000, eq. 3–4]
        drive_gear_diameter (float | str | Unset): Pitch diameter of the drive gear 4, also taken as its disc diameter
            [000, eq. 3–5]
        spindle_gear_mass (float | str | Unset): Mass of one spindle gear 5, a solid uniform disc [000, eq. 3–4]
        spindle_gear_diameter (float | str | Unset): Pitch diameter of one spindle gear 5, also taken as its disc
            diameter [000, eq. 3–5]
        spindle_count (int | str | Unset): Number of spindles z (one per wheel nut) [000, eq. 4, 10]
        shaft_diameter (float | str | Unset): Diameter of the flywheel shaft 7 [000, eq. 9]
        shaft_length (float | str | Unset): Twisted length of the flywheel shaft 7 [000, eq. 9]
        spindle_diameter (float | str | Unset): Diameter of a spindle 8 [000, eq. 9]
        spindle_length (float | str | Unset): Twisted length of a spindle 8 [000, eq. 9]
        shear_modulus (float | None | str | Unset): Shear modulus G of shaft and spindle; 8·10¹⁰ Pa (steel) in the
            source [000, eq. 9] Default: 80000000000.0.
        idle_spindle_friction_torque (float | None | str | Unset): Friction-clutch torque M_tr of each idle spindle,
            taken off the blow [000, eq. 10] Default: 0.0.
        friction_clutch_clamp_force (float | None | str | Unset): F, force nut 12 clamps each diaphragm friction clutch
            with [000]; given, M_tr = z_f μ F (D + d)/4 replaces idle_spindle_friction_torque (uniform wear)
        friction_clutch_friction (float | None | str | Unset): μ of the friction clutch faces (about 0.1 oiled …
            0.15–0.2 dry steel)
        friction_clutch_outer_diameter (float | None | str | Unset): D, outer diameter of the friction face
        friction_clutch_inner_diameter (float | None | str | Unset): d, inner diameter of the friction face (0 for a
            full disc), below D
        friction_clutch_faces (int | None | str | Unset): z_f, friction faces the clamp force passes through Default: 1.
        wheel_nut_torque (float | None | str | Unset): Torque the wheel nut needs: its tightening torque, or the larger
            torque that breaks it loose; set for each make of vehicle [000]; 600 N*m (a truck's M20×1.5 wheel nut) when
            absent Default: 600.0.
        shear_yield_strength (float | None | str | Unset): Optional shear yield strength of shaft and spindle steel;
            when given, a check says whether the blow keeps them elastic (the source's model needs that)
        motor_curve (None | NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0 | Unset): Torque–speed
            curve for the motor_curve rung: 'none'; 'linear' (stall_torque, no_load_speed); 'induction' (Kloss formula from
            rated_torque, rated_speed, breakdown_torque, synchronous_speed); 'constant_power' (motor_power above the torque
            limit stall_torque). Not in the source. Default:
            NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0.NONE.
        stall_torque (float | None | str | Unset): Linear curve: torque at standstill; constant_power curve: the torque
            limit
        no_load_speed (float | None | str | Unset): Linear curve: speed at which the torque falls to zero
        rated_torque (float | None | str | Unset): Induction curve: rated torque (default motor_power / rated_speed)
        rated_speed (float | None | str | Unset): Induction curve: rated speed (default motor_speed)
        breakdown_torque (float | None | str | Unset): Induction curve: breakdown (pull-out) torque, above the rated
            torque
        synchronous_speed (float | None | str | Unset): Induction curve: synchronous speed (1500 rpm for a 4-pole 50 Hz
            motor)
        rotor_inertia (float | None | str | Unset): Motor rotor inertia, added to the spin-up (not to the blow: coupling
            1 slips) Default: 0.0.
        belt_efficiency (float | None | str | Unset): V-belt efficiency while accelerating (1 = the source's lossless
            drive) Default: 1.0.
        gear_efficiency (float | None | str | Unset): Gear mesh 4–5 efficiency while accelerating (1 = the source's
            lossless drive) Default: 1.0.
        coupling_service_factor (float | None | str | Unset): service factor K on the motor's rated torque P/ω for the
            slip torque of the safety coupling 1; 1.5 (smooth) … 3 (shocks), as torque-limiter makers advise Default: 2.0.
    """

    motor_power: float | str | Unset = UNSET
    motor_speed: float | str | Unset = UNSET
    coupling_mass: float | str | Unset = UNSET
    coupling_diameter: float | str | Unset = UNSET
    motor_pulley_mass: float | str | Unset = UNSET
    motor_pulley_diameter: float | str | Unset = UNSET
    flywheel_mass: float | str | Unset = UNSET
    flywheel_diameter: float | str | Unset = UNSET
    drive_gear_mass: float | str | Unset = UNSET
    drive_gear_diameter: float | str | Unset = UNSET
    spindle_gear_mass: float | str | Unset = UNSET
    spindle_gear_diameter: float | str | Unset = UNSET
    spindle_count: int | str | Unset = UNSET
    shaft_diameter: float | str | Unset = UNSET
    shaft_length: float | str | Unset = UNSET
    spindle_diameter: float | str | Unset = UNSET
    spindle_length: float | str | Unset = UNSET
    shear_modulus: float | None | str | Unset = 80000000000.0
    idle_spindle_friction_torque: float | None | str | Unset = 0.0
    friction_clutch_clamp_force: float | None | str | Unset = UNSET
    friction_clutch_friction: float | None | str | Unset = UNSET
    friction_clutch_outer_diameter: float | None | str | Unset = UNSET
    friction_clutch_inner_diameter: float | None | str | Unset = UNSET
    friction_clutch_faces: int | None | str | Unset = 1
    wheel_nut_torque: float | None | str | Unset = 600.0
    shear_yield_strength: float | None | str | Unset = UNSET
    motor_curve: None | NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0 | Unset = (
        NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0.NONE
    )
    stall_torque: float | None | str | Unset = UNSET
    no_load_speed: float | None | str | Unset = UNSET
    rated_torque: float | None | str | Unset = UNSET
    rated_speed: float | None | str | Unset = UNSET
    breakdown_torque: float | None | str | Unset = UNSET
    synchronous_speed: float | None | str | Unset = UNSET
    rotor_inertia: float | None | str | Unset = 0.0
    belt_efficiency: float | None | str | Unset = 1.0
    gear_efficiency: float | None | str | Unset = 1.0
    coupling_service_factor: float | None | str | Unset = 2.0

    def to_dict(self) -> dict[str, Any]:
        motor_power: float | str | Unset
        if isinstance(self.motor_power, Unset):
            motor_power = UNSET
        else:
            motor_power = self.motor_power

        motor_speed: float | str | Unset
        if isinstance(self.motor_speed, Unset):
            motor_speed = UNSET
        else:
            motor_speed = self.motor_speed

        coupling_mass: float | str | Unset
        if isinstance(self.coupling_mass, Unset):
            coupling_mass = UNSET
        else:
            coupling_mass = self.coupling_mass

        coupling_diameter: float | str | Unset
        if isinstance(self.coupling_diameter, Unset):
            coupling_diameter = UNSET
        else:
            coupling_diameter = self.coupling_diameter

        motor_pulley_mass: float | str | Unset
        if isinstance(self.motor_pulley_mass, Unset):
            motor_pulley_mass = UNSET
        else:
            motor_pulley_mass = self.motor_pulley_mass

        motor_pulley_diameter: float | str | Unset
        if isinstance(self.motor_pulley_diameter, Unset):
            motor_pulley_diameter = UNSET
        else:
            motor_pulley_diameter = self.motor_pulley_diameter

        flywheel_mass: float | str | Unset
        if isinstance(self.flywheel_mass, Unset):
            flywheel_mass = UNSET
        else:
            flywheel_mass = self.flywheel_mass

        flywheel_diameter: float | str | Unset
        if isinstance(self.flywheel_diameter, Unset):
            flywheel_diameter = UNSET
        else:
            flywheel_diameter = self.flywheel_diameter

        drive_gear_mass: float | str | Unset
        if isinstance(self.drive_gear_mass, Unset):
            drive_gear_mass = UNSET
        else:
            drive_gear_mass = self.drive_gear_mass

        drive_gear_diameter: float | str | Unset
        if isinstance(self.drive_gear_diameter, Unset):
            drive_gear_diameter = UNSET
        else:
            drive_gear_diameter = self.drive_gear_diameter

        spindle_gear_mass: float | str | Unset
        if isinstance(self.spindle_gear_mass, Unset):
            spindle_gear_mass = UNSET
        else:
            spindle_gear_mass = self.spindle_gear_mass

        spindle_gear_diameter: float | str | Unset
        if isinstance(self.spindle_gear_diameter, Unset):
            spindle_gear_diameter = UNSET
        else:
            spindle_gear_diameter = self.spindle_gear_diameter

        spindle_count: int | str | Unset
        if isinstance(self.spindle_count, Unset):
            spindle_count = UNSET
        else:
            spindle_count = self.spindle_count

        shaft_diameter: float | str | Unset
        if isinstance(self.shaft_diameter, Unset):
            shaft_diameter = UNSET
        else:
            shaft_diameter = self.shaft_diameter

        shaft_length: float | str | Unset
        if isinstance(self.shaft_length, Unset):
            shaft_length = UNSET
        else:
            shaft_length = self.shaft_length

        spindle_diameter: float | str | Unset
        if isinstance(self.spindle_diameter, Unset):
            spindle_diameter = UNSET
        else:
            spindle_diameter = self.spindle_diameter

        spindle_length: float | str | Unset
        if isinstance(self.spindle_length, Unset):
            spindle_length = UNSET
        else:
            spindle_length = self.spindle_length

        shear_modulus: float | None | str | Unset
        if isinstance(self.shear_modulus, Unset):
            shear_modulus = UNSET
        else:
            shear_modulus = self.shear_modulus

        idle_spindle_friction_torque: float | None | str | Unset
        if isinstance(self.idle_spindle_friction_torque, Unset):
            idle_spindle_friction_torque = UNSET
        else:
            idle_spindle_friction_torque = self.idle_spindle_friction_torque

        friction_clutch_clamp_force: float | None | str | Unset
        if isinstance(self.friction_clutch_clamp_force, Unset):
            friction_clutch_clamp_force = UNSET
        else:
            friction_clutch_clamp_force = self.friction_clutch_clamp_force

        friction_clutch_friction: float | None | str | Unset
        if isinstance(self.friction_clutch_friction, Unset):
            friction_clutch_friction = UNSET
        else:
            friction_clutch_friction = self.friction_clutch_friction

        friction_clutch_outer_diameter: float | None | str | Unset
        if isinstance(self.friction_clutch_outer_diameter, Unset):
            friction_clutch_outer_diameter = UNSET
        else:
            friction_clutch_outer_diameter = self.friction_clutch_outer_diameter

        friction_clutch_inner_diameter: float | None | str | Unset
        if isinstance(self.friction_clutch_inner_diameter, Unset):
            friction_clutch_inner_diameter = UNSET
        else:
            friction_clutch_inner_diameter = self.friction_clutch_inner_diameter

        friction_clutch_faces: int | None | str | Unset
        if isinstance(self.friction_clutch_faces, Unset):
            friction_clutch_faces = UNSET
        else:
            friction_clutch_faces = self.friction_clutch_faces

        wheel_nut_torque: float | None | str | Unset
        if isinstance(self.wheel_nut_torque, Unset):
            wheel_nut_torque = UNSET
        else:
            wheel_nut_torque = self.wheel_nut_torque

        shear_yield_strength: float | None | str | Unset
        if isinstance(self.shear_yield_strength, Unset):
            shear_yield_strength = UNSET
        else:
            shear_yield_strength = self.shear_yield_strength

        motor_curve: None | str | Unset
        if isinstance(self.motor_curve, Unset):
            motor_curve = UNSET
        elif isinstance(self.motor_curve, NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0):
            motor_curve = self.motor_curve.value
        else:
            motor_curve = self.motor_curve

        stall_torque: float | None | str | Unset
        if isinstance(self.stall_torque, Unset):
            stall_torque = UNSET
        else:
            stall_torque = self.stall_torque

        no_load_speed: float | None | str | Unset
        if isinstance(self.no_load_speed, Unset):
            no_load_speed = UNSET
        else:
            no_load_speed = self.no_load_speed

        rated_torque: float | None | str | Unset
        if isinstance(self.rated_torque, Unset):
            rated_torque = UNSET
        else:
            rated_torque = self.rated_torque

        rated_speed: float | None | str | Unset
        if isinstance(self.rated_speed, Unset):
            rated_speed = UNSET
        else:
            rated_speed = self.rated_speed

        breakdown_torque: float | None | str | Unset
        if isinstance(self.breakdown_torque, Unset):
            breakdown_torque = UNSET
        else:
            breakdown_torque = self.breakdown_torque

        synchronous_speed: float | None | str | Unset
        if isinstance(self.synchronous_speed, Unset):
            synchronous_speed = UNSET
        else:
            synchronous_speed = self.synchronous_speed

        rotor_inertia: float | None | str | Unset
        if isinstance(self.rotor_inertia, Unset):
            rotor_inertia = UNSET
        else:
            rotor_inertia = self.rotor_inertia

        belt_efficiency: float | None | str | Unset
        if isinstance(self.belt_efficiency, Unset):
            belt_efficiency = UNSET
        else:
            belt_efficiency = self.belt_efficiency

        gear_efficiency: float | None | str | Unset
        if isinstance(self.gear_efficiency, Unset):
            gear_efficiency = UNSET
        else:
            gear_efficiency = self.gear_efficiency

        coupling_service_factor: float | None | str | Unset
        if isinstance(self.coupling_service_factor, Unset):
            coupling_service_factor = UNSET
        else:
            coupling_service_factor = self.coupling_service_factor

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if motor_power is not UNSET:
            field_dict["motor_power"] = motor_power
        if motor_speed is not UNSET:
            field_dict["motor_speed"] = motor_speed
        if coupling_mass is not UNSET:
            field_dict["coupling_mass"] = coupling_mass
        if coupling_diameter is not UNSET:
            field_dict["coupling_diameter"] = coupling_diameter
        if motor_pulley_mass is not UNSET:
            field_dict["motor_pulley_mass"] = motor_pulley_mass
        if motor_pulley_diameter is not UNSET:
            field_dict["motor_pulley_diameter"] = motor_pulley_diameter
        if flywheel_mass is not UNSET:
            field_dict["flywheel_mass"] = flywheel_mass
        if flywheel_diameter is not UNSET:
            field_dict["flywheel_diameter"] = flywheel_diameter
        if drive_gear_mass is not UNSET:
            field_dict["drive_gear_mass"] = drive_gear_mass
        if drive_gear_diameter is not UNSET:
            field_dict["drive_gear_diameter"] = drive_gear_diameter
        if spindle_gear_mass is not UNSET:
            field_dict["spindle_gear_mass"] = spindle_gear_mass
        if spindle_gear_diameter is not UNSET:
            field_dict["spindle_gear_diameter"] = spindle_gear_diameter
        if spindle_count is not UNSET:
            field_dict["spindle_count"] = spindle_count
        if shaft_diameter is not UNSET:
            field_dict["shaft_diameter"] = shaft_diameter
        if shaft_length is not UNSET:
            field_dict["shaft_length"] = shaft_length
        if spindle_diameter is not UNSET:
            field_dict["spindle_diameter"] = spindle_diameter
        if spindle_length is not UNSET:
            field_dict["spindle_length"] = spindle_length
        if shear_modulus is not UNSET:
            field_dict["shear_modulus"] = shear_modulus
        if idle_spindle_friction_torque is not UNSET:
            field_dict["idle_spindle_friction_torque"] = idle_spindle_friction_torque
        if friction_clutch_clamp_force is not UNSET:
            field_dict["friction_clutch_clamp_force"] = friction_clutch_clamp_force
        if friction_clutch_friction is not UNSET:
            field_dict["friction_clutch_friction"] = friction_clutch_friction
        if friction_clutch_outer_diameter is not UNSET:
            field_dict["friction_clutch_outer_diameter"] = friction_clutch_outer_diameter
        if friction_clutch_inner_diameter is not UNSET:
            field_dict["friction_clutch_inner_diameter"] = friction_clutch_inner_diameter
        if friction_clutch_faces is not UNSET:
            field_dict["friction_clutch_faces"] = friction_clutch_faces
        if wheel_nut_torque is not UNSET:
            field_dict["wheel_nut_torque"] = wheel_nut_torque
        if shear_yield_strength is not UNSET:
            field_dict["shear_yield_strength"] = shear_yield_strength
        if motor_curve is not UNSET:
            field_dict["motor_curve"] = motor_curve
        if stall_torque is not UNSET:
            field_dict["stall_torque"] = stall_torque
        if no_load_speed is not UNSET:
            field_dict["no_load_speed"] = no_load_speed
        if rated_torque is not UNSET:
            field_dict["rated_torque"] = rated_torque
        if rated_speed is not UNSET:
            field_dict["rated_speed"] = rated_speed
        if breakdown_torque is not UNSET:
            field_dict["breakdown_torque"] = breakdown_torque
        if synchronous_speed is not UNSET:
            field_dict["synchronous_speed"] = synchronous_speed
        if rotor_inertia is not UNSET:
            field_dict["rotor_inertia"] = rotor_inertia
        if belt_efficiency is not UNSET:
            field_dict["belt_efficiency"] = belt_efficiency
        if gear_efficiency is not UNSET:
            field_dict["gear_efficiency"] = gear_efficiency
        if coupling_service_factor is not UNSET:
            field_dict["coupling_service_factor"] = coupling_service_factor

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_motor_power(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        motor_power = _parse_motor_power(d.pop("motor_power", UNSET))

        def _parse_motor_speed(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        motor_speed = _parse_motor_speed(d.pop("motor_speed", UNSET))

        def _parse_coupling_mass(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        coupling_mass = _parse_coupling_mass(d.pop("coupling_mass", UNSET))

        def _parse_coupling_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        coupling_diameter = _parse_coupling_diameter(d.pop("coupling_diameter", UNSET))

        def _parse_motor_pulley_mass(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        motor_pulley_mass = _parse_motor_pulley_mass(d.pop("motor_pulley_mass", UNSET))

        def _parse_motor_pulley_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        motor_pulley_diameter = _parse_motor_pulley_diameter(d.pop("motor_pulley_diameter", UNSET))

        def _parse_flywheel_mass(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        flywheel_mass = _parse_flywheel_mass(d.pop("flywheel_mass", UNSET))

        def _parse_flywheel_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        flywheel_diameter = _parse_flywheel_diameter(d.pop("flywheel_diameter", UNSET))

        def _parse_drive_gear_mass(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        drive_gear_mass = _parse_drive_gear_mass(d.pop("drive_gear_mass", UNSET))

        def _parse_drive_gear_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        drive_gear_diameter = _parse_drive_gear_diameter(d.pop("drive_gear_diameter", UNSET))

        def _parse_spindle_gear_mass(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        spindle_gear_mass = _parse_spindle_gear_mass(d.pop("spindle_gear_mass", UNSET))

        def _parse_spindle_gear_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        spindle_gear_diameter = _parse_spindle_gear_diameter(d.pop("spindle_gear_diameter", UNSET))

        def _parse_spindle_count(data: object) -> int | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(int | str | Unset, data)

        spindle_count = _parse_spindle_count(d.pop("spindle_count", UNSET))

        def _parse_shaft_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        shaft_diameter = _parse_shaft_diameter(d.pop("shaft_diameter", UNSET))

        def _parse_shaft_length(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        shaft_length = _parse_shaft_length(d.pop("shaft_length", UNSET))

        def _parse_spindle_diameter(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        spindle_diameter = _parse_spindle_diameter(d.pop("spindle_diameter", UNSET))

        def _parse_spindle_length(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        spindle_length = _parse_spindle_length(d.pop("spindle_length", UNSET))

        def _parse_shear_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shear_modulus = _parse_shear_modulus(d.pop("shear_modulus", UNSET))

        def _parse_idle_spindle_friction_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        idle_spindle_friction_torque = _parse_idle_spindle_friction_torque(d.pop("idle_spindle_friction_torque", UNSET))

        def _parse_friction_clutch_clamp_force(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_clutch_clamp_force = _parse_friction_clutch_clamp_force(d.pop("friction_clutch_clamp_force", UNSET))

        def _parse_friction_clutch_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_clutch_friction = _parse_friction_clutch_friction(d.pop("friction_clutch_friction", UNSET))

        def _parse_friction_clutch_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_clutch_outer_diameter = _parse_friction_clutch_outer_diameter(
            d.pop("friction_clutch_outer_diameter", UNSET)
        )

        def _parse_friction_clutch_inner_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_clutch_inner_diameter = _parse_friction_clutch_inner_diameter(
            d.pop("friction_clutch_inner_diameter", UNSET)
        )

        def _parse_friction_clutch_faces(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        friction_clutch_faces = _parse_friction_clutch_faces(d.pop("friction_clutch_faces", UNSET))

        def _parse_wheel_nut_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        wheel_nut_torque = _parse_wheel_nut_torque(d.pop("wheel_nut_torque", UNSET))

        def _parse_shear_yield_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shear_yield_strength = _parse_shear_yield_strength(d.pop("shear_yield_strength", UNSET))

        def _parse_motor_curve(
            data: object,
        ) -> None | NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                motor_curve_type_0 = NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0(data)

                return motor_curve_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0 | Unset, data)

        motor_curve = _parse_motor_curve(d.pop("motor_curve", UNSET))

        def _parse_stall_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        stall_torque = _parse_stall_torque(d.pop("stall_torque", UNSET))

        def _parse_no_load_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        no_load_speed = _parse_no_load_speed(d.pop("no_load_speed", UNSET))

        def _parse_rated_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        rated_torque = _parse_rated_torque(d.pop("rated_torque", UNSET))

        def _parse_rated_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        rated_speed = _parse_rated_speed(d.pop("rated_speed", UNSET))

        def _parse_breakdown_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        breakdown_torque = _parse_breakdown_torque(d.pop("breakdown_torque", UNSET))

        def _parse_synchronous_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        synchronous_speed = _parse_synchronous_speed(d.pop("synchronous_speed", UNSET))

        def _parse_rotor_inertia(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        rotor_inertia = _parse_rotor_inertia(d.pop("rotor_inertia", UNSET))

        def _parse_belt_efficiency(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        belt_efficiency = _parse_belt_efficiency(d.pop("belt_efficiency", UNSET))

        def _parse_gear_efficiency(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        gear_efficiency = _parse_gear_efficiency(d.pop("gear_efficiency", UNSET))

        def _parse_coupling_service_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        coupling_service_factor = _parse_coupling_service_factor(d.pop("coupling_service_factor", UNSET))

        nutrunner_drive_study_request_nutrunner_drive_study_base = cls(
            motor_power=motor_power,
            motor_speed=motor_speed,
            coupling_mass=coupling_mass,
            coupling_diameter=coupling_diameter,
            motor_pulley_mass=motor_pulley_mass,
            motor_pulley_diameter=motor_pulley_diameter,
            flywheel_mass=flywheel_mass,
            flywheel_diameter=flywheel_diameter,
            drive_gear_mass=drive_gear_mass,
            drive_gear_diameter=drive_gear_diameter,
            spindle_gear_mass=spindle_gear_mass,
            spindle_gear_diameter=spindle_gear_diameter,
            spindle_count=spindle_count,
            shaft_diameter=shaft_diameter,
            shaft_length=shaft_length,
            spindle_diameter=spindle_diameter,
            spindle_length=spindle_length,
            shear_modulus=shear_modulus,
            idle_spindle_friction_torque=idle_spindle_friction_torque,
            friction_clutch_clamp_force=friction_clutch_clamp_force,
            friction_clutch_friction=friction_clutch_friction,
            friction_clutch_outer_diameter=friction_clutch_outer_diameter,
            friction_clutch_inner_diameter=friction_clutch_inner_diameter,
            friction_clutch_faces=friction_clutch_faces,
            wheel_nut_torque=wheel_nut_torque,
            shear_yield_strength=shear_yield_strength,
            motor_curve=motor_curve,
            stall_torque=stall_torque,
            no_load_speed=no_load_speed,
            rated_torque=rated_torque,
            rated_speed=rated_speed,
            breakdown_torque=breakdown_torque,
            synchronous_speed=synchronous_speed,
            rotor_inertia=rotor_inertia,
            belt_efficiency=belt_efficiency,
            gear_efficiency=gear_efficiency,
            coupling_service_factor=coupling_service_factor,
        )

        return nutrunner_drive_study_request_nutrunner_drive_study_base
