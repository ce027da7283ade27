from enum import StrEnum


class ClutchBallRequestOutputsType0Item(StrEnum):
    BALL_AXIAL_FORCE = "ball_axial_force"
    BALL_NORMAL_FORCE = "ball_normal_force"
    BALL_TANGENTIAL_FORCE = "ball_tangential_force"
    BUCKLING_DEFLECTION = "buckling_deflection"
    DISC_FORCE_FLAT = "disc_force_flat"
    FLANK_LIFT = "flank_lift"
    FRICTION_SENSITIVITY = "friction_sensitivity"
    LIFT = "lift"
    LIFT_AT_PEAK = "lift_at_peak"
    NATURAL_FREQUENCY = "natural_frequency"
    PEAK_TORQUE = "peak_torque"
    PERMISSIBLE_STRESS = "permissible_stress"
    RESIDUAL_TORQUE = "residual_torque"
    SELF_LOCKING_MARGIN = "self_locking_margin"
    SOLID_LENGTH = "solid_length"
    SPRING_FORCE = "spring_force"
    SPRING_FORCE_AT_PEAK = "spring_force_at_peak"
    SPRING_FORCE_CURVE = "spring_force_curve"
    SPRING_FORCE_MAX = "spring_force_max"
    SPRING_INDEX = "spring_index"
    SPRING_RATE = "spring_rate"
    SPRING_SHEAR_STRESS = "spring_shear_stress"
    SPRING_STRESS_AT_PEAK = "spring_stress_at_peak"
    SPRING_STRESS_CURVE = "spring_stress_curve"
    SPRING_STRESS_MAX = "spring_stress_max"
    TENSILE_STRENGTH = "tensile_strength"
    TORQUE_AT_RIM = "torque_at_rim"
    TORQUE_CURVE = "torque_curve"
    TORQUE_LIMIT = "torque_limit"
    TOTAL_LIFT = "total_lift"
    WAHL_FACTOR = "wahl_factor"

    def __str__(self) -> str:
        return str(self.value)
