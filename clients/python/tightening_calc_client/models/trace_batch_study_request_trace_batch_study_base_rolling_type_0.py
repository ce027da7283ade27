from enum import StrEnum


class TraceBatchStudyRequestTraceBatchStudyBaseRollingType0(StrEnum):
    AFTER_HEAT_TREATMENT = "after_heat_treatment"
    BEFORE_HEAT_TREATMENT = "before_heat_treatment"

    def __str__(self) -> str:
        return str(self.value)
