from enum import StrEnum


class TraceAnalysisRequestFidelityType0(StrEnum):
    AUTO = "auto"
    DETECTION = "detection"

    def __str__(self) -> str:
        return str(self.value)
