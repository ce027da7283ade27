from enum import StrEnum


class ImpactRareDesignSweepRequestFidelityType0(StrEnum):
    AUTO = "auto"
    CLOSED_FORM = "closed_form"

    def __str__(self) -> str:
        return str(self.value)
