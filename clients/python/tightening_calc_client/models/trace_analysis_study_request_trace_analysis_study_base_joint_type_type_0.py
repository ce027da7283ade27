from enum import StrEnum


class TraceAnalysisStudyRequestTraceAnalysisStudyBaseJointTypeType0(StrEnum):
    TAPPED = "tapped"
    THROUGH = "through"

    def __str__(self) -> str:
        return str(self.value)
