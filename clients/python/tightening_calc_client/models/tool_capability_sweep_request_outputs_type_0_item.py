from enum import StrEnum


class ToolCapabilitySweepRequestOutputsType0Item(StrEnum):
    CAPABILITY_INDEX = "capability_index"
    CAPABLE = "capable"
    CRITICAL_CAPABILITY_INDEX = "critical_capability_index"
    HARD_MEAN_TORQUE = "hard_mean_torque"
    HARD_TORQUE_SD = "hard_torque_sd"
    INDEX_NAMES = "index_names"
    LOWER_LIMIT = "lower_limit"
    MAX_TORQUE = "max_torque"
    MEAN_OFFSET = "mean_offset"
    MEAN_SHIFT = "mean_shift"
    MEAN_TORQUE = "mean_torque"
    MINIMUM_SAMPLE_COUNT = "minimum_sample_count"
    MIN_TORQUE = "min_torque"
    OUTSIDE_PPM = "outside_ppm"
    REQUIRED_INDEX = "required_index"
    SAMPLE_COUNT = "sample_count"
    SOFT_MEAN_TORQUE = "soft_mean_torque"
    SOFT_TORQUE_SD = "soft_torque_sd"
    TORQUE_SCATTER = "torque_scatter"
    TORQUE_SD = "torque_sd"
    UPPER_LIMIT = "upper_limit"

    def __str__(self) -> str:
        return str(self.value)
