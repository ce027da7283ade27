from enum import StrEnum


class ClutchBallStudyRequestClutchBallStudyBaseFlankConstructionType0(StrEnum):
    FREE_BALL = "free_ball"
    PRESSURE_DISC = "pressure_disc"

    def __str__(self) -> str:
        return str(self.value)
