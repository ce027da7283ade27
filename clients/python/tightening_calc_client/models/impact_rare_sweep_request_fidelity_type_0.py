from enum import StrEnum


class ImpactRareSweepRequestFidelityType0(StrEnum):
    AUTO = "auto"
    CLOSED_FORM = "closed_form"
    SIMULATION = "simulation"

    def __str__(self) -> str:
        return str(self.value)
