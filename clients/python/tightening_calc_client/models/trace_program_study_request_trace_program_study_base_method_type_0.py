from enum import StrEnum


class TraceProgramStudyRequestTraceProgramStudyBaseMethodType0(StrEnum):
    DRILLED_BOLT_ROD = "drilled_bolt_rod"
    ELONGATION_MICROMETER = "elongation_micrometer"
    LIMIT_WRENCH = "limit_wrench"
    MEASURING_WASHER_RING = "measuring_washer_ring"
    NUT_ANGLE = "nut_angle"
    PNEUMATIC_WASHER = "pneumatic_washer"
    SHEAR_OFF_NUT = "shear_off_nut"
    STRAIN_GAUGE = "strain_gauge"
    TORQUE_GRADIENT = "torque_gradient"
    TORQUE_THEN_ANGLE = "torque_then_angle"
    TORQUE_WRENCH = "torque_wrench"
    ULTRASOUND = "ultrasound"

    def __str__(self) -> str:
        return str(self.value)
