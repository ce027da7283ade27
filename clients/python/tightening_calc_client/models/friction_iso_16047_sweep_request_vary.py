from enum import StrEnum


class FrictionIso16047SweepRequestVary(StrEnum):
    BEARING_DIAMETER = "bearing_diameter"
    BEARING_OUTER_DIAMETER = "bearing_outer_diameter"
    HOLE_DIAMETER = "hole_diameter"
    PITCH_DIAMETER = "pitch_diameter"
    THREAD_DIAMETER = "thread_diameter"
    THREAD_PITCH = "thread_pitch"

    def __str__(self) -> str:
        return str(self.value)
