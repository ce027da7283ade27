from enum import StrEnum


class JointFlangeRequestOutputsType0Item(StrEnum):
    ASSEMBLY_PRELOAD_MAX = "assembly_preload_max"
    ASSEMBLY_PRELOAD_MIN = "assembly_preload_min"
    BOLT_TRANSVERSE_LOAD = "bolt_transverse_load"
    BOLT_WORKING_LOAD = "bolt_working_load"
    BOLT_WORKING_LOAD_MIN = "bolt_working_load_min"
    FATIGUE_SAFETY = "fatigue_safety"
    LOAD_FACTOR = "load_factor"
    MAX_BOLT_FORCE = "max_bolt_force"
    MAX_WORKING_LOAD = "max_working_load"
    PERMISSIBLE_PRELOAD = "permissible_preload"
    REQUIRED_CLAMP_FORCE = "required_clamp_force"
    RESIDUAL_CLAMP_FORCE_MIN = "residual_clamp_force_min"
    SEPARATION_LOAD = "separation_load"
    SLIP_SAFETY = "slip_safety"
    STRESS_AMPLITUDE = "stress_amplitude"
    TIGHTENING_TORQUE = "tightening_torque"
    WORKING_STRESS = "working_stress"
    YIELD_SAFETY = "yield_safety"

    def __str__(self) -> str:
        return str(self.value)
