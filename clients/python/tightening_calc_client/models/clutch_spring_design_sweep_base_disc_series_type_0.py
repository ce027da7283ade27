from enum import StrEnum


class ClutchSpringDesignSweepBaseDiscSeriesType0(StrEnum):
    A = "A"
    ANY = "any"
    B = "B"

    def __str__(self) -> str:
        return str(self.value)
