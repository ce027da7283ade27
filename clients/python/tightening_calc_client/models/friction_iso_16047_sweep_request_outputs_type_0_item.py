from enum import StrEnum


class FrictionIso16047SweepRequestOutputsType0Item(StrEnum):
    BEARING_DIAMETER = "bearing_diameter"
    BEARING_FRICTION_MAX = "bearing_friction_max"
    BEARING_FRICTION_MEAN = "bearing_friction_mean"
    BEARING_FRICTION_MIN = "bearing_friction_min"
    BEARING_FRICTION_SD = "bearing_friction_sd"
    PITCH_DIAMETER = "pitch_diameter"
    TEST_COUNT = "test_count"
    THREAD_DIAMETER = "thread_diameter"
    THREAD_FRICTION_MAX = "thread_friction_max"
    THREAD_FRICTION_MEAN = "thread_friction_mean"
    THREAD_FRICTION_MIN = "thread_friction_min"
    THREAD_FRICTION_SD = "thread_friction_sd"
    THREAD_PITCH = "thread_pitch"
    TORQUE_COEFFICIENT_MAX = "torque_coefficient_max"
    TORQUE_COEFFICIENT_MEAN = "torque_coefficient_mean"
    TORQUE_COEFFICIENT_MIN = "torque_coefficient_min"
    TORQUE_COEFFICIENT_SD = "torque_coefficient_sd"
    TOTAL_FRICTION_MAX = "total_friction_max"
    TOTAL_FRICTION_MEAN = "total_friction_mean"
    TOTAL_FRICTION_MIN = "total_friction_min"
    TOTAL_FRICTION_SD = "total_friction_sd"

    def __str__(self) -> str:
        return str(self.value)
