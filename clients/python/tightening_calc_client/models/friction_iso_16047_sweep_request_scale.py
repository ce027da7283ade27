from enum import StrEnum


class FrictionIso16047SweepRequestScale(StrEnum):
    LINEAR = "linear"
    LOG = "log"

    def __str__(self) -> str:
        return str(self.value)
