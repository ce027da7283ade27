from enum import StrEnum


class ClutchBallSettingStudyRequestClutchBallSettingStudyBaseSpringArrangementType0(StrEnum):
    COMMON = "common"
    PER_BALL = "per_ball"

    def __str__(self) -> str:
        return str(self.value)
