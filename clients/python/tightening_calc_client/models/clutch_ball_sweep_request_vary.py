from enum import StrEnum


class ClutchBallSweepRequestVary(StrEnum):
    ALLOWABLE_SHEAR_STRESS = "allowable_shear_stress"
    BALL_CIRCLE_DIAMETER = "ball_circle_diameter"
    BALL_COUNT = "ball_count"
    BALL_DIAMETER = "ball_diameter"
    BALL_LIFT = "ball_lift"
    DISC_CONE_HEIGHT = "disc_cone_height"
    DISC_ELASTIC_MODULUS = "disc_elastic_modulus"
    DISC_FRICTION = "disc_friction"
    DISC_INNER_DIAMETER = "disc_inner_diameter"
    DISC_OUTER_DIAMETER = "disc_outer_diameter"
    DISC_PARALLEL = "disc_parallel"
    DISC_SERIES = "disc_series"
    DISC_THICKNESS = "disc_thickness"
    DISC_YIELD_STRENGTH = "disc_yield_strength"
    DRIVING_GROOVE_ANGLE = "driving_groove_angle"
    FACE_FRICTION = "face_friction"
    FLANK_FRICTION = "flank_friction"
    GROOVE_ANGLE = "groove_angle"
    LOAD_FACTOR = "load_factor"
    SHEAR_MODULUS = "shear_modulus"
    SPRING_ACTIVE_COILS = "spring_active_coils"
    SPRING_DEFLECTION = "spring_deflection"
    SPRING_ELASTIC_MODULUS = "spring_elastic_modulus"
    SPRING_FREE_LENGTH = "spring_free_length"
    SPRING_MEAN_DIAMETER = "spring_mean_diameter"
    SPRING_WIRE_DIAMETER = "spring_wire_diameter"
    TORQUE = "torque"

    def __str__(self) -> str:
        return str(self.value)
