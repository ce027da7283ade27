from enum import StrEnum


class PreloadControlRequestLoadTypeType0(StrEnum):
    STEADY = "steady"
    VARYING = "varying"

    def __str__(self) -> str:
        return str(self.value)
