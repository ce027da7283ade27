from enum import StrEnum


class PreloadTighteningSweepRequestVary(StrEnum):
    BEARING_FRICTION = "bearing_friction"
    BEARING_OUTER_DIAMETER = "bearing_outer_diameter"
    ENGAGEMENT_LENGTH = "engagement_length"
    HOLE_DIAMETER = "hole_diameter"
    INTERNAL_THREAD_SHEAR_STRENGTH = "internal_thread_shear_strength"
    LIMITING_SURFACE_PRESSURE = "limiting_surface_pressure"
    PRELOAD = "preload"
    THREAD_DIAMETER = "thread_diameter"
    THREAD_FRICTION = "thread_friction"
    THREAD_PITCH = "thread_pitch"
    UTILIZATION = "utilization"
    WORKING_BOLT_FORCE = "working_bolt_force"
    YIELD_STRENGTH = "yield_strength"

    def __str__(self) -> str:
        return str(self.value)
