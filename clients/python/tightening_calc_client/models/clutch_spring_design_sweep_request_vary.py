from enum import StrEnum


class ClutchSpringDesignSweepRequestVary(StrEnum):
    BALL_CIRCLE_DIAMETER = "ball_circle_diameter"
    BALL_COUNT = "ball_count"
    BALL_DIAMETER = "ball_diameter"
    BALL_LIFT = "ball_lift"
    DISC_YIELD_STRENGTH = "disc_yield_strength"
    DRIVING_GROOVE_ANGLE = "driving_groove_angle"
    FLANK_FRICTION = "flank_friction"
    GROOVE_ANGLE = "groove_angle"
    LOAD_FACTOR = "load_factor"
    MAX_OUTER_DIAMETER = "max_outer_diameter"
    MAX_SET_LENGTH = "max_set_length"
    MIN_INNER_DIAMETER = "min_inner_diameter"
    TARGET_TORQUE = "target_torque"

    def __str__(self) -> str:
        return str(self.value)
