from enum import StrEnum


class JointVdi2230SweepRequestScale(StrEnum):
    LINEAR = "linear"
    LOG = "log"

    def __str__(self) -> str:
        return str(self.value)
