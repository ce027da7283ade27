from enum import StrEnum


class ClutchBallSettingRequestSpringTypeType0(StrEnum):
    DISC = "disc"
    HELICAL = "helical"

    def __str__(self) -> str:
        return str(self.value)
