from enum import StrEnum


class JointVdi2230StudyRequestJointVdi2230StudyBaseHeadType0(StrEnum):
    HEX = "hex"
    SOCKET = "socket"

    def __str__(self) -> str:
        return str(self.value)
