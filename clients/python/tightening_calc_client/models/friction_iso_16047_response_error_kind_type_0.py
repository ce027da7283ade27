from enum import StrEnum


class FrictionIso16047ResponseErrorKindType0(StrEnum):
    BOUND = "bound"
    TYPICAL = "typical"

    def __str__(self) -> str:
        return str(self.value)
