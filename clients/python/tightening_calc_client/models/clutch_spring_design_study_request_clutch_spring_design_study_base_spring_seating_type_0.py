from enum import StrEnum


class ClutchSpringDesignStudyRequestClutchSpringDesignStudyBaseSpringSeatingType0(StrEnum):
    FIXED_FIXED = "fixed_fixed"
    FIXED_FREE = "fixed_free"
    FIXED_HINGED = "fixed_hinged"
    HINGED_HINGED = "hinged_hinged"

    def __str__(self) -> str:
        return str(self.value)
