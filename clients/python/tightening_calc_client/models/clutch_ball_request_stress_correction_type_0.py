from enum import StrEnum


class ClutchBallRequestStressCorrectionType0(StrEnum):
    BERGSTRASSER = "bergstrasser"
    WAHL = "wahl"

    def __str__(self) -> str:
        return str(self.value)
