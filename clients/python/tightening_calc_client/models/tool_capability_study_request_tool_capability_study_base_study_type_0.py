from enum import StrEnum


class ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0(StrEnum):
    MACHINE = "machine"
    PROCESS = "process"

    def __str__(self) -> str:
        return str(self.value)
