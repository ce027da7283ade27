from enum import StrEnum


class JointClampCapabilityStudyRequestJointClampCapabilityStudyBaseCategoryType0(StrEnum):
    A = "A"
    B = "B"
    C = "C"
    NONE = "none"

    def __str__(self) -> str:
        return str(self.value)
