from enum import StrEnum


class ToolCapabilityRequestStudyType0(StrEnum):
    MACHINE = "machine"
    PROCESS = "process"

    def __str__(self) -> str:
        return str(self.value)
