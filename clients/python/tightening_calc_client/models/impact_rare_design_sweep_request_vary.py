from enum import StrEnum


class ImpactRareDesignSweepRequestVary(StrEnum):
    AUXILIARY_SPRING_PRELOAD = "auxiliary_spring_preload"
    AUXILIARY_SPRING_RATE = "auxiliary_spring_rate"
    CHANGE_LIMIT = "change_limit"
    CONE_ANGLE = "cone_angle"
    ENGAGEMENT_ANGLE = "engagement_angle"
    ENGAGEMENT_HEIGHT = "engagement_height"
    FLYWHEEL_INERTIA = "flywheel_inertia"
    GRAVITY = "gravity"
    HALF_COUPLING_MASS = "half_coupling_mass"
    JAW_HEIGHT = "jaw_height"
    MIN_ENGAGEMENT_MARGIN = "min_engagement_margin"
    MOTOR_NO_LOAD_SPEED = "motor_no_load_speed"
    MOTOR_TORQUE = "motor_torque"
    POWER_SPRING_PRELOAD = "power_spring_preload"
    POWER_SPRING_RATE = "power_spring_rate"
    RELEASE_TRAVEL = "release_travel"
    RETURN_SPRING_PRELOAD = "return_spring_preload"
    RETURN_SPRING_RATE = "return_spring_rate"
    ROLLER_COUNT = "roller_count"
    ROLLER_FRICTION = "roller_friction"
    ROLLER_MASS = "roller_mass"
    ROLLER_RADIUS = "roller_radius"
    SEARCH_SAMPLES = "search_samples"
    STEPPED_SHAFT_MASS = "stepped_shaft_mass"
    STRIKER_MASS = "striker_mass"

    def __str__(self) -> str:
        return str(self.value)
