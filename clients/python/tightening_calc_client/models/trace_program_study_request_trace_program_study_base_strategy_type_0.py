from enum import StrEnum


class TraceProgramStudyRequestTraceProgramStudyBaseStrategyType0(StrEnum):
    TORQUE_ANGLE = "torque_angle"
    YIELD = "yield"

    def __str__(self) -> str:
        return str(self.value)
