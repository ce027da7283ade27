from enum import StrEnum


class TraceProgramStudyRequestTraceProgramStudyBaseSurfaceRoughnessType0(StrEnum):
    RZ10 = "Rz<10"
    RZ10_40 = "Rz10-40"
    RZ40_160 = "Rz40-160"

    def __str__(self) -> str:
        return str(self.value)
