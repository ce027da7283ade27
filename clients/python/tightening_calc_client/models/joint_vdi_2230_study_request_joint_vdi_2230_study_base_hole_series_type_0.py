from enum import StrEnum


class JointVdi2230StudyRequestJointVdi2230StudyBaseHoleSeriesType0(StrEnum):
    COARSE = "coarse"
    FINE = "fine"
    MEDIUM = "medium"

    def __str__(self) -> str:
        return str(self.value)
