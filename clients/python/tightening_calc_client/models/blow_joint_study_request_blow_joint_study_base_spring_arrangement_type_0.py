from enum import StrEnum


class BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0(StrEnum):
    COMMON = "common"
    PER_BALL = "per_ball"

    def __str__(self) -> str:
        return str(self.value)
