from enum import StrEnum


class ClutchSpringDesignStudyRequestClutchSpringDesignStudyBaseObjectiveType0(StrEnum):
    MARGIN = "margin"
    THINNEST = "thinnest"

    def __str__(self) -> str:
        return str(self.value)
