from enum import StrEnum


class JointAuditRequestOutputsType0Item(StrEnum):
    ASSEMBLY_PRELOAD_MAX = "assembly_preload_max"
    ASSEMBLY_PRELOAD_MIN = "assembly_preload_min"
    BREAKAWAY_EMBEDDED_MAX = "breakaway_embedded_max"
    BREAKAWAY_EMBEDDED_MIN = "breakaway_embedded_min"
    BREAKAWAY_MAX = "breakaway_max"
    BREAKAWAY_MIN = "breakaway_min"
    EMBEDDING_LOSS = "embedding_loss"
    FIRST_MOTION_EMBEDDED_MAX = "first_motion_embedded_max"
    FIRST_MOTION_EMBEDDED_MIN = "first_motion_embedded_min"
    FIRST_MOTION_MAX = "first_motion_max"
    FIRST_MOTION_MIN = "first_motion_min"
    MARK_EMBEDDED_MAX = "mark_embedded_max"
    MARK_EMBEDDED_MIN = "mark_embedded_min"
    MARK_MAX = "mark_max"
    MARK_MIN = "mark_min"
    RESIDUAL_PRELOAD_MAX = "residual_preload_max"
    RESIDUAL_PRELOAD_MIN = "residual_preload_min"

    def __str__(self) -> str:
        return str(self.value)
