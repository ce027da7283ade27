from enum import StrEnum


class ImpactRareDesignRequestOutputsType0Item(StrEnum):
    BINDING_CHECKS = "binding_checks"
    CHANGE_AUXILIARY_SPRING_PRELOAD = "change_auxiliary_spring_preload"
    CHANGE_AUXILIARY_SPRING_RATE = "change_auxiliary_spring_rate"
    CHANGE_POWER_SPRING_PRELOAD = "change_power_spring_preload"
    CHANGE_POWER_SPRING_RATE = "change_power_spring_rate"
    CHANGE_RETURN_SPRING_PRELOAD = "change_return_spring_preload"
    CHANGE_RETURN_SPRING_RATE = "change_return_spring_rate"
    CHANGE_STRIKER_MASS = "change_striker_mass"
    CYCLE_TIME = "cycle_time"
    DESIGNS_EVALUATED = "designs_evaluated"
    DESIGNS_PASSING = "designs_passing"
    DESIGN_CHANGE = "design_change"
    ENGAGEMENT_MARGIN = "engagement_margin"
    FOUND = "found"
    NEW_AUXILIARY_SPRING_PRELOAD = "new_auxiliary_spring_preload"
    NEW_AUXILIARY_SPRING_RATE = "new_auxiliary_spring_rate"
    NEW_POWER_SPRING_PRELOAD = "new_power_spring_preload"
    NEW_POWER_SPRING_RATE = "new_power_spring_rate"
    NEW_RETURN_SPRING_PRELOAD = "new_return_spring_preload"
    NEW_RETURN_SPRING_RATE = "new_return_spring_rate"
    NEW_STRIKER_MASS = "new_striker_mass"
    RELOCK_MARGIN = "relock_margin"

    def __str__(self) -> str:
        return str(self.value)
