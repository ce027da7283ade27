from enum import StrEnum


class ImpactRareDesignRequestRollerGeometryType0(StrEnum):
    PAPER = "paper"
    SINGLE_CONE = "single_cone"
    SYMMETRIC_V = "symmetric_v"

    def __str__(self) -> str:
        return str(self.value)
