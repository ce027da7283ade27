from enum import StrEnum


class ClutchBallStudyRequestClutchBallStudyBaseStressCorrectionType0(StrEnum):
    BERGSTRASSER = "bergstrasser"
    WAHL = "wahl"

    def __str__(self) -> str:
        return str(self.value)
