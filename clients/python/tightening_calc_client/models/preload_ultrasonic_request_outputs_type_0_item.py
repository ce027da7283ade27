from enum import StrEnum


class PreloadUltrasonicRequestOutputsType0Item(StrEnum):
    BOLT_COMPLIANCE = "bolt_compliance"
    BOLT_STRESS = "bolt_stress"
    EFFECTIVE_LENGTH = "effective_length"
    ELONGATION = "elongation"
    PRELOAD = "preload"
    THERMAL_LENGTH_CHANGE = "thermal_length_change"
    TIME_OF_FLIGHT_CHANGE = "time_of_flight_change"
    ULTRASONIC_LENGTH_CHANGE = "ultrasonic_length_change"

    def __str__(self) -> str:
        return str(self.value)
