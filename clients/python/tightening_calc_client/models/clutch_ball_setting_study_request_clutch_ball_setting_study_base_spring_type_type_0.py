from enum import StrEnum


class ClutchBallSettingStudyRequestClutchBallSettingStudyBaseSpringTypeType0(StrEnum):
    DISC = "disc"
    HELICAL = "helical"

    def __str__(self) -> str:
        return str(self.value)
