from enum import StrEnum


class BlowJointStudyRequestBlowJointStudyBaseSourceType0(StrEnum):
    CLUTCH = "clutch"
    ENERGY = "energy"
    NUTRUNNER = "nutrunner"
    RARE_IMPACT = "rare_impact"

    def __str__(self) -> str:
        return str(self.value)
