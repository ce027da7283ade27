from enum import StrEnum


class JointClampCapabilityStudyRequestJointClampCapabilityStudyBaseThreadFrictionLawType0(StrEnum):
    FIXED = "fixed"
    LOGNORMAL = "lognormal"
    NORMAL = "normal"
    TRIANGULAR = "triangular"
    TRUNCATED_NORMAL = "truncated_normal"
    UNIFORM = "uniform"

    def __str__(self) -> str:
        return str(self.value)
