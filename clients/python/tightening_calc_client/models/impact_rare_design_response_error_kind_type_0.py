from enum import StrEnum


class ImpactRareDesignResponseErrorKindType0(StrEnum):
    BOUND = "bound"
    TYPICAL = "typical"

    def __str__(self) -> str:
        return str(self.value)
