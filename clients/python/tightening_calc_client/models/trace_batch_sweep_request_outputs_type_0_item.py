from enum import StrEnum


class TraceBatchSweepRequestOutputsType0Item(StrEnum):
    ASSEMBLY_PRELOAD_MIN = "assembly_preload_min"
    CAPABILITY_INDEX = "capability_index"
    CRITICAL_CAPABILITY_INDEX = "critical_capability_index"
    FRICTION_MEAN = "friction_mean"
    FRICTION_SD = "friction_sd"
    OUTLIER_COUNT = "outlier_count"
    OUTLIER_TRACES = "outlier_traces"
    PERMISSIBLE_PRELOAD = "permissible_preload"
    PRELOAD_HIGHEST = "preload_highest"
    PRELOAD_LOWEST = "preload_lowest"
    PRELOAD_MEAN = "preload_mean"
    PRELOAD_SD = "preload_sd"
    TRACES = "traces"
    TRACES_IN_WINDOW = "traces_in_window"

    def __str__(self) -> str:
        return str(self.value)
