from enum import StrEnum


class ImpactRareSweepRequestOutputsType0Item(StrEnum):
    BLOW_TIME = "blow_time"
    CYCLE_TIME = "cycle_time"
    ENGAGEMENT_ACCELERATION = "engagement_acceleration"
    ENGAGEMENT_END = "engagement_end"
    ENGAGEMENT_FREQUENCY = "engagement_frequency"
    ENGAGEMENT_MARGIN = "engagement_margin"
    ENGAGEMENT_START = "engagement_start"
    ENGAGEMENT_TIME = "engagement_time"
    ENGAGEMENT_WINDOW = "engagement_window"
    FULL_ENGAGEMENT = "full_engagement"
    HALF_COUPLING_RELEASE_SPEED = "half_coupling_release_speed"
    MAX_STRIKER_TRAVEL = "max_striker_travel"
    MIN_RETURN_SPRING_RATE = "min_return_spring_rate"
    RELEASE_RADIUS = "release_radius"
    RELEASE_SPEED = "release_speed"
    RELOCK_MARGIN = "relock_margin"
    RELOCK_TIME = "relock_time"
    RETURN_TIME = "return_time"
    SPIN_UP_TIME = "spin_up_time"
    SPRING_HEIGHT_LIMIT = "spring_height_limit"
    STRIKER_HOME_TIME = "striker_home_time"

    def __str__(self) -> str:
        return str(self.value)
