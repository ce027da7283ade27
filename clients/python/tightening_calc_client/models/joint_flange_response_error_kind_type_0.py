from enum import StrEnum


class JointFlangeResponseErrorKindType0(StrEnum):
    BOUND = "bound"
    TYPICAL = "typical"

    def __str__(self) -> str:
        return str(self.value)
