from enum import StrEnum


class ImpactRareRequestOutputsType0Item(StrEnum):
    BLOW_TIME = "blow_time"
    CYCLE_TIME = "cycle_time"
    ENGAGEMENT_ACCELERATION = "engagement_acceleration"
    ENGAGEMENT_END = "engagement_end"
    ENGAGEMENT_FREQUENCY = "engagement_frequency"
    ENGAGEMENT_MARGIN = "engagement_margin"
    ENGAGEMENT_START = "engagement_start"
    ENGAGEMENT_TIME = "engagement_time"
    ENGAGEMENT_WINDOW = "engagement_window"
    FLYWHEEL_SPEED = "flywheel_speed"
    FULL_ENGAGEMENT = "full_engagement"
    HALF_COUPLING_LIFT = "half_coupling_lift"
    HALF_COUPLING_RELEASE_SPEED = "half_coupling_release_speed"
    MAX_STRIKER_TRAVEL = "max_striker_travel"
    MIN_RETURN_SPRING_RATE = "min_return_spring_rate"
    RELEASE_RADIUS = "release_radius"
    RELEASE_SPEED = "release_speed"
    RELOCK_MARGIN = "relock_margin"
    RELOCK_TIME = "relock_time"
    RETURN_TIME = "return_time"
    ROLLER_POSITION = "roller_position"
    SHAFT_LIFT = "shaft_lift"
    SPIN_UP_TIME = "spin_up_time"
    SPRING_HEIGHT_LIMIT = "spring_height_limit"
    STAGE = "stage"
    STRIKER_HOME_TIME = "striker_home_time"
    STRIKER_TRAVEL = "striker_travel"
    TIME = "time"

    def __str__(self) -> str:
        return str(self.value)
