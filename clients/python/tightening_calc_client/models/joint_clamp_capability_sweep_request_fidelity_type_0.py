from enum import StrEnum


class JointClampCapabilitySweepRequestFidelityType0(StrEnum):
    AUTO = "auto"
    QUADRATURE = "quadrature"

    def __str__(self) -> str:
        return str(self.value)
