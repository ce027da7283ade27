from enum import StrEnum


class JointVdi2230SweepBaseHeadType0(StrEnum):
    HEX = "hex"
    SOCKET = "socket"

    def __str__(self) -> str:
        return str(self.value)
