from enum import StrEnum


class TraceProgramSweepBaseStrategyType0(StrEnum):
    TORQUE_ANGLE = "torque_angle"
    YIELD = "yield"

    def __str__(self) -> str:
        return str(self.value)
