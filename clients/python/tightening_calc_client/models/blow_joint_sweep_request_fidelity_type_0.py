from enum import StrEnum


class BlowJointSweepRequestFidelityType0(StrEnum):
    AUTO = "auto"
    ENERGY = "energy"
    RIGID = "rigid"
    SIMULATION = "simulation"

    def __str__(self) -> str:
        return str(self.value)
