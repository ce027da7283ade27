from enum import StrEnum


class JointClampCapabilityRequestOutputsType0Item(StrEnum):
    CATEGORY_MINIMUM_MET = "category_minimum_met"
    CLAMP_FORCE_CPK = "clamp_force_cpk"
    FRICTION_COPULA = "friction_copula"
    HIGH_PPM = "high_ppm"
    HIGH_PPM_ERROR = "high_ppm_error"
    LOW_PPM = "low_ppm"
    LOW_PPM_ERROR = "low_ppm_error"
    MEAN_TORQUE = "mean_torque"
    PERMISSIBLE_PRELOAD = "permissible_preload"
    PRELOAD_MEAN = "preload_mean"
    PRELOAD_MEDIAN = "preload_median"
    PRELOAD_Q00135 = "preload_q00135"
    PRELOAD_Q1E_6 = "preload_q1e-6"
    PRELOAD_Q1_1E_6 = "preload_q1-1e-6"
    PRELOAD_Q99865 = "preload_q99865"
    PRELOAD_SD = "preload_sd"
    QUADRATURE_PANELS = "quadrature_panels"
    REQUIRED_PRELOAD_MIN = "required_preload_min"
    TIGHTENING_FACTOR = "tightening_factor"
    TOOL_CRITICAL_INDEX = "tool_critical_index"
    TORQUE_SD = "torque_sd"
    UTILISATION_MEDIAN = "utilisation_median"
    UTILISATION_Q1_1E_6 = "utilisation_q1-1e-6"
    UTILISATION_Q99865 = "utilisation_q99865"

    def __str__(self) -> str:
        return str(self.value)
