from enum import StrEnum


class VariableInDistribution(StrEnum):
    LOGNORMAL = "lognormal"
    NORMAL = "normal"
    TRIANGULAR = "triangular"
    UNIFORM = "uniform"

    def __str__(self) -> str:
        return str(self.value)
