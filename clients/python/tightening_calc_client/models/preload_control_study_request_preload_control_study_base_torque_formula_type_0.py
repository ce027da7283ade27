from enum import StrEnum


class PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0(StrEnum):
    APPROX = "approx"
    EXACT = "exact"
    VDI2230 = "vdi2230"

    def __str__(self) -> str:
        return str(self.value)
