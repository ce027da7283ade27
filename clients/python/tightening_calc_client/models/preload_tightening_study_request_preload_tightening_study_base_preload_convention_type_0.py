from enum import StrEnum


class PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0(StrEnum):
    ELASTIC = "elastic"
    VDI2230 = "vdi2230"

    def __str__(self) -> str:
        return str(self.value)
