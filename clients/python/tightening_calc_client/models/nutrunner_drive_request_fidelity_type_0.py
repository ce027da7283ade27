from enum import StrEnum


class NutrunnerDriveRequestFidelityType0(StrEnum):
    AUTO = "auto"
    CLOSED_FORM = "closed_form"
    GEAR_RATIO = "gear_ratio"
    MOTOR_CURVE = "motor_curve"

    def __str__(self) -> str:
        return str(self.value)
