from enum import StrEnum


class ClutchSpringDesignStudyRequestClutchSpringDesignStudyBaseFlankConstructionType0(StrEnum):
    FREE_BALL = "free_ball"
    PRESSURE_DISC = "pressure_disc"

    def __str__(self) -> str:
        return str(self.value)
