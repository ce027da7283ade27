from enum import StrEnum


class ClutchSpringDesignStudyRequestClutchSpringDesignStudyBaseSpringArrangementType0(StrEnum):
    COMMON = "common"
    PER_BALL = "per_ball"

    def __str__(self) -> str:
        return str(self.value)
