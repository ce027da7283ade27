from enum import StrEnum


class ToolCapabilitySweepRequestVary(StrEnum):
    HARD_MEAN_TORQUE = "hard_mean_torque"
    HARD_TORQUE_SD = "hard_torque_sd"
    LOWER_LIMIT = "lower_limit"
    MEAN_TORQUE = "mean_torque"
    NOMINAL_TORQUE = "nominal_torque"
    RELATIVE_TOLERANCE = "relative_tolerance"
    REQUIRED_INDEX = "required_index"
    SAMPLE_COUNT = "sample_count"
    SOFT_MEAN_TORQUE = "soft_mean_torque"
    SOFT_TORQUE_SD = "soft_torque_sd"
    TORQUE_SD = "torque_sd"
    UPPER_LIMIT = "upper_limit"

    def __str__(self) -> str:
        return str(self.value)
