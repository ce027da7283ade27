from enum import StrEnum


class TraceBatchStudyRequestTraceBatchStudyBaseWasherType0(StrEnum):
    ISO_7089 = "ISO 7089"
    ISO_7092 = "ISO 7092"
    ISO_7093 = "ISO 7093"

    def __str__(self) -> str:
        return str(self.value)
