from enum import StrEnum


class PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0(StrEnum):
    STEADY = "steady"
    VARYING = "varying"

    def __str__(self) -> str:
        return str(self.value)
