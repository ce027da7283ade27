from enum import StrEnum


class BlowJointSweepRequestOutputsType0Item(StrEnum):
    BLOWS_PER_SECOND = "blows_per_second"
    BLOWS_TO_TARGET = "blows_to_target"
    BLOW_INTERVAL = "blow_interval"
    BOLT_VERDICT = "bolt_verdict"
    BREAKING_LOAD = "breaking_load"
    CLUTCH_SPRING_FORCE_FOR_TARGET = "clutch_spring_force_for_target"
    CLUTCH_TORQUE_MAX = "clutch_torque_max"
    CLUTCH_TORQUE_MIN = "clutch_torque_min"
    DELIVERED_PRELOAD_MAX = "delivered_preload_max"
    DELIVERED_PRELOAD_MIN = "delivered_preload_min"
    ENERGY_INTO_JOINT = "energy_into_joint"
    ENERGY_SUPPLIED = "energy_supplied"
    FINAL_PRELOAD = "final_preload"
    FINAL_TORQUE = "final_torque"
    JOINT_ENERGY_FRACTION = "joint_energy_fraction"
    JOINT_RATE_USED = "joint_rate_used"
    NUT_ROTATION = "nut_rotation"
    PEAK_TORQUE = "peak_torque"
    PRELOAD_AFTER_FIRST_BLOW = "preload_after_first_blow"
    PRELOAD_VERDICT = "preload_verdict"
    RIGID_TORQUE = "rigid_torque"
    SATURATION_TORQUE = "saturation_torque"
    TIME_TO_FINAL = "time_to_final"
    TOOL_ENERGY_USED = "tool_energy_used"
    TOOL_INERTIA_USED = "tool_inertia_used"
    TOOL_SPEED = "tool_speed"
    TOOL_STIFFNESS_USED = "tool_stiffness_used"
    TORQUE_AFTER_FIRST_BLOW = "torque_after_first_blow"
    YIELD_PRELOAD = "yield_preload"

    def __str__(self) -> str:
        return str(self.value)
