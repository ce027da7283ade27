from enum import StrEnum


class ImpactRareDesignRequestFidelityType0(StrEnum):
    AUTO = "auto"
    CLOSED_FORM = "closed_form"

    def __str__(self) -> str:
        return str(self.value)
