from enum import StrEnum


class PreloadTighteningSweepBasePreloadConventionType0(StrEnum):
    ELASTIC = "elastic"
    VDI2230 = "vdi2230"

    def __str__(self) -> str:
        return str(self.value)
