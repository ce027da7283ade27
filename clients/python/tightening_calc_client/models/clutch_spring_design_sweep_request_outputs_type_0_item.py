from enum import StrEnum


class ClutchSpringDesignSweepRequestOutputsType0Item(StrEnum):
    ACTIVE_COILS = "active_coils"
    BINDING_LIMIT = "binding_limit"
    BUCKLING_DEFLECTION = "buckling_deflection"
    CANDIDATES_CHECKED = "candidates_checked"
    CANDIDATES_PASSING = "candidates_passing"
    FREE_LENGTH = "free_length"
    GAP_SUM = "gap_sum"
    MARGIN_BUCKLING = "margin_buckling"
    MARGIN_COIL_GAPS = "margin_coil_gaps"
    MARGIN_INNER_DIAMETER = "margin_inner_diameter"
    MARGIN_OUTER_DIAMETER = "margin_outer_diameter"
    MARGIN_SPRING_INDEX = "margin_spring_index"
    MARGIN_STRESS_AT_SET = "margin_stress_at_set"
    MARGIN_STRESS_AT_STROKE = "margin_stress_at_stroke"
    MASS = "mass"
    MEAN_DIAMETER = "mean_diameter"
    PERMISSIBLE_STRESS = "permissible_stress"
    RATE = "rate"
    SET_DEFLECTION = "set_deflection"
    SET_FORCE = "set_force"
    SET_LENGTH = "set_length"
    SHEAR_STRESS_SET = "shear_stress_set"
    SHEAR_STRESS_STROKE = "shear_stress_stroke"
    SOLID_LENGTH = "solid_length"
    STRESS_UTILISATION_SET = "stress_utilisation_set"
    STRESS_UTILISATION_STROKE = "stress_utilisation_stroke"
    STROKE = "stroke"
    STROKE_FORCE = "stroke_force"
    STROKE_LENGTH = "stroke_length"
    TOTAL_COILS = "total_coils"
    WIRE_DIAMETER = "wire_diameter"

    def __str__(self) -> str:
        return str(self.value)
