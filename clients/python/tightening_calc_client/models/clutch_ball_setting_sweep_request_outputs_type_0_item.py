from enum import StrEnum


class ClutchBallSettingSweepRequestOutputsType0Item(StrEnum):
    PEAK_SETTING_STRESS_MAX = "peak_setting_stress_max"
    RATED_DRIVE_TORQUE = "rated_drive_torque"
    REQUIRED_DEFLECTION = "required_deflection"
    REQUIRED_PEAK_SETTING = "required_peak_setting"
    REQUIRED_SLIP_TORQUE = "required_slip_torque"
    REQUIRED_SPRING_FORCE = "required_spring_force"
    REQUIRED_WIRE_DIAMETER = "required_wire_diameter"
    REQUIRED_WIRE_SHEAR_STRESS = "required_wire_shear_stress"
    REQUIRED_WIRE_SPRING_INDEX = "required_wire_spring_index"
    SPRING_INDEX = "spring_index"
    SPRING_RATE = "spring_rate"
    SPRING_SHEAR_STRESS = "spring_shear_stress"
    START_TORQUE = "start_torque"
    SUGGESTED_DISC_PARALLEL = "suggested_disc_parallel"
    SUGGESTED_DISC_SETTING = "suggested_disc_setting"
    SUGGESTED_WIRE_DIAMETER = "suggested_wire_diameter"
    SUGGESTED_WIRE_SETTING = "suggested_wire_setting"

    def __str__(self) -> str:
        return str(self.value)
