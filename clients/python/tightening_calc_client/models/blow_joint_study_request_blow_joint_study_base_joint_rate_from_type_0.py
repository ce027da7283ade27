from enum import StrEnum


class BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0(StrEnum):
    ISO5393_HARD = "iso5393_hard"
    ISO5393_SOFT = "iso5393_soft"
    JOINT = "joint"
    NUMBER = "number"

    def __str__(self) -> str:
        return str(self.value)
