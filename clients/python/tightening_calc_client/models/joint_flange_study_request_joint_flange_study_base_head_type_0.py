from enum import StrEnum


class JointFlangeStudyRequestJointFlangeStudyBaseHeadType0(StrEnum):
    HEX = "hex"
    SOCKET = "socket"

    def __str__(self) -> str:
        return str(self.value)
