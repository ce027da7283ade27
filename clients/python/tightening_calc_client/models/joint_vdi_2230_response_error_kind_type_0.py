from enum import StrEnum


class JointVdi2230ResponseErrorKindType0(StrEnum):
    BOUND = "bound"
    TYPICAL = "typical"

    def __str__(self) -> str:
        return str(self.value)
