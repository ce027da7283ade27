from enum import StrEnum


class NutrunnerDriveStudyRequestNutrunnerDriveStudyBaseMotorCurveType0(StrEnum):
    CONSTANT_POWER = "constant_power"
    INDUCTION = "induction"
    LINEAR = "linear"
    NONE = "none"

    def __str__(self) -> str:
        return str(self.value)
