from enum import StrEnum


class TraceBatchStudyRequestTraceBatchStudyBaseHeadType0(StrEnum):
    HEX = "hex"
    SOCKET = "socket"

    def __str__(self) -> str:
        return str(self.value)
