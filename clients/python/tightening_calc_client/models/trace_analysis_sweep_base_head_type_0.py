from enum import StrEnum


class TraceAnalysisSweepBaseHeadType0(StrEnum):
    HEX = "hex"
    SOCKET = "socket"

    def __str__(self) -> str:
        return str(self.value)
