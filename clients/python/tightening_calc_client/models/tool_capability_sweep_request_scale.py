from enum import StrEnum


class ToolCapabilitySweepRequestScale(StrEnum):
    LINEAR = "linear"
    LOG = "log"

    def __str__(self) -> str:
        return str(self.value)
