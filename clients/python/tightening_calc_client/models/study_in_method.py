from enum import StrEnum


class StudyInMethod(StrEnum):
    GRID = "grid"
    LHS = "lhs"
    MONTE_CARLO = "monte_carlo"
    SOBOL = "sobol"

    def __str__(self) -> str:
        return str(self.value)
