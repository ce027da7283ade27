from enum import StrEnum


class ClutchSpringDesignRequestObjectiveType0(StrEnum):
    MARGIN = "margin"
    THINNEST = "thinnest"

    def __str__(self) -> str:
        return str(self.value)
