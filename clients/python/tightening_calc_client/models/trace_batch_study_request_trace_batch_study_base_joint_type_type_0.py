from enum import StrEnum


class TraceBatchStudyRequestTraceBatchStudyBaseJointTypeType0(StrEnum):
    TAPPED = "tapped"
    THROUGH = "through"

    def __str__(self) -> str:
        return str(self.value)
