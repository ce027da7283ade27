from enum import StrEnum


class ClutchSpringDesignStudyRequestClutchSpringDesignStudyBaseSpringKindType0(StrEnum):
    DISC_PACK = "disc_pack"
    HELICAL = "helical"

    def __str__(self) -> str:
        return str(self.value)
