from enum import StrEnum


class PreloadUltrasonicStudyRequestMethod(StrEnum):
    GRID = "grid"
    LHS = "lhs"
    MONTE_CARLO = "monte_carlo"
    POINTS = "points"
    SOBOL = "sobol"

    def __str__(self) -> str:
        return str(self.value)
