from enum import StrEnum


class PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0(StrEnum):
    ELASTIC = "elastic"
    VDI2230 = "vdi2230"

    def __str__(self) -> str:
        return str(self.value)
