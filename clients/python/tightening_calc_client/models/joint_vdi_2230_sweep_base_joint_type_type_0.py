from enum import StrEnum


class JointVdi2230SweepBaseJointTypeType0(StrEnum):
    TAPPED = "tapped"
    THROUGH = "through"

    def __str__(self) -> str:
        return str(self.value)
