from enum import StrEnum


class NutrunnerDriveRequestOutputsType0Item(StrEnum):
    ACCELERATION_TIME = "acceleration_time"
    CONSTANT_POWER_TIME = "constant_power_time"
    COUPLING_ENERGY = "coupling_energy"
    COUPLING_SLIP_TORQUE = "coupling_slip_torque"
    DRIVE_GEAR_ENERGY = "drive_gear_energy"
    DRIVE_INERTIA = "drive_inertia"
    EQUIVALENT_INERTIA = "equivalent_inertia"
    FLYWHEEL_ENERGY = "flywheel_energy"
    FLYWHEEL_SPEED = "flywheel_speed"
    FLYWHEEL_SPEED_CURVE = "flywheel_speed_curve"
    FRICTION_CLUTCH_TORQUE = "friction_clutch_torque"
    GEAR_RATIO = "gear_ratio"
    GEAR_RATIO_TORQUE_CHANGE = "gear_ratio_torque_change"
    IMPACT_TORQUE = "impact_torque"
    KINETIC_ENERGY = "kinetic_energy"
    MAX_SPINDLE_TORQUE = "max_spindle_torque"
    MOTOR_PULLEY_ENERGY = "motor_pulley_energy"
    MOTOR_SPEED_CURVE = "motor_speed_curve"
    SHAFT_SHEAR_STRESS = "shaft_shear_stress"
    SHAFT_STIFFNESS = "shaft_stiffness"
    SHAFT_TORQUE = "shaft_torque"
    SHAFT_TWIST = "shaft_twist"
    SPINDLE_GEARS_ENERGY = "spindle_gears_energy"
    SPINDLE_GEAR_SPEED = "spindle_gear_speed"
    SPINDLE_SHEAR_STRESS = "spindle_shear_stress"
    SPINDLE_STIFFNESS = "spindle_stiffness"
    SPINDLE_TORQUE_RESERVE = "spindle_torque_reserve"
    SPINDLE_TWIST = "spindle_twist"
    TIME = "time"
    TIME_VS_CONSTANT_POWER = "time_vs_constant_power"

    def __str__(self) -> str:
        return str(self.value)
