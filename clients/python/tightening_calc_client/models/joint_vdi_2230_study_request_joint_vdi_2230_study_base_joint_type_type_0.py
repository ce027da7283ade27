from enum import StrEnum


class JointVdi2230StudyRequestJointVdi2230StudyBaseJointTypeType0(StrEnum):
    TAPPED = "tapped"
    THROUGH = "through"

    def __str__(self) -> str:
        return str(self.value)
