from enum import StrEnum


class TraceProgramRequestOutputsType0Item(StrEnum):
    ANGLE_MAX = "angle_max"
    ANGLE_MIN = "angle_min"
    FINAL_ANGLE = "final_angle"
    GRADIENT_THRESHOLD_MAX = "gradient_threshold_max"
    GRADIENT_THRESHOLD_MIN = "gradient_threshold_min"
    PRELOAD_MAX = "preload_max"
    PRELOAD_MIN = "preload_min"
    RATE_MAX = "rate_max"
    RATE_MIN = "rate_min"
    SNUG_TORQUE = "snug_torque"
    STRATEGY = "strategy"
    TARGET_PRELOAD = "target_preload"
    TORQUE_MAX = "torque_max"
    TORQUE_MIN = "torque_min"
    WINDOW_FITS = "window_fits"

    def __str__(self) -> str:
        return str(self.value)
