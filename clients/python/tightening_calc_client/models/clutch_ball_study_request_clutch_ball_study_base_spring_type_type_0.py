from enum import StrEnum


class ClutchBallStudyRequestClutchBallStudyBaseSpringTypeType0(StrEnum):
    DISC = "disc"
    HELICAL = "helical"

    def __str__(self) -> str:
        return str(self.value)
