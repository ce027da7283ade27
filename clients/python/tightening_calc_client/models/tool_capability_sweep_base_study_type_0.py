from enum import StrEnum


class ToolCapabilitySweepBaseStudyType0(StrEnum):
    MACHINE = "machine"
    PROCESS = "process"

    def __str__(self) -> str:
        return str(self.value)
