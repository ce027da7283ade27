from enum import StrEnum


class JointFlangeStudyRequestJointFlangeStudyBaseJointTypeType0(StrEnum):
    TAPPED = "tapped"
    THROUGH = "through"

    def __str__(self) -> str:
        return str(self.value)
