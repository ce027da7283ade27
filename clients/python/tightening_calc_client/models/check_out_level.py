from enum import StrEnum


class CheckOutLevel(StrEnum):
    ADVICE = "advice"
    REQUIREMENT = "requirement"

    def __str__(self) -> str:
        return str(self.value)
