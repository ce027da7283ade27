from enum import StrEnum


class ImpactRareDesignStudyRequestImpactRareDesignStudyBaseRollerGeometryType0(StrEnum):
    PAPER = "paper"
    SINGLE_CONE = "single_cone"
    SYMMETRIC_V = "symmetric_v"

    def __str__(self) -> str:
        return str(self.value)
