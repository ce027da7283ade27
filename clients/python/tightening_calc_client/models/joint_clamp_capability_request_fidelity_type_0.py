from enum import StrEnum


class JointClampCapabilityRequestFidelityType0(StrEnum):
    AUTO = "auto"
    QUADRATURE = "quadrature"

    def __str__(self) -> str:
        return str(self.value)
