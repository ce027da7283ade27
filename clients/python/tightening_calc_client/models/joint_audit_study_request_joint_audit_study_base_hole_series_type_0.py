from enum import StrEnum


class JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0(StrEnum):
    COARSE = "coarse"
    FINE = "fine"
    MEDIUM = "medium"

    def __str__(self) -> str:
        return str(self.value)
