from enum import StrEnum


class TraceBatchSweepRequestFidelityType0(StrEnum):
    AUTO = "auto"
    DETECTION = "detection"

    def __str__(self) -> str:
        return str(self.value)
