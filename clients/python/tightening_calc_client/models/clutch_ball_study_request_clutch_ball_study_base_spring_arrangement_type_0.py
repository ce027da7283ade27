from enum import StrEnum


class ClutchBallStudyRequestClutchBallStudyBaseSpringArrangementType0(StrEnum):
    COMMON = "common"
    PER_BALL = "per_ball"

    def __str__(self) -> str:
        return str(self.value)
