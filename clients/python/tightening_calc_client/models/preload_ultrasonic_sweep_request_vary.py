from enum import StrEnum


class PreloadUltrasonicSweepRequestVary(StrEnum):
    BEARING_OUTER_DIAMETER = "bearing_outer_diameter"
    ELONGATION = "elongation"
    HOLE_DIAMETER = "hole_diameter"
    NUT_YOUNGS_MODULUS = "nut_youngs_modulus"
    PLATE1_THICKNESS = "plate1_thickness"
    PLATE2_THICKNESS = "plate2_thickness"
    PLATE3_THICKNESS = "plate3_thickness"
    PRELOAD = "preload"
    READING_TEMPERATURE_CHANGE = "reading_temperature_change"
    REDUCED_DIAMETER = "reduced_diameter"
    REDUCED_LENGTH = "reduced_length"
    SHANK_DIAMETER = "shank_diameter"
    SHANK_LENGTH = "shank_length"
    SOUND_VELOCITY = "sound_velocity"
    STRESS_FACTOR = "stress_factor"
    TEMPERATURE_FACTOR = "temperature_factor"
    THREAD_DIAMETER = "thread_diameter"
    THREAD_PITCH = "thread_pitch"
    TIME_OF_FLIGHT_CHANGE = "time_of_flight_change"
    ULTRASONIC_LENGTH = "ultrasonic_length"
    YIELD_STRENGTH = "yield_strength"
    YOUNGS_MODULUS = "youngs_modulus"

    def __str__(self) -> str:
        return str(self.value)
