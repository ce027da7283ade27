"""Every model the product offers, in the order the catalogue lists them.

One declaration module per family (``engine/models/<family>.py``) holds each
model's :class:`~engine.core.spec.ModelSpec`: inputs with units and ranges, outputs,
rungs, compute/check glue and the sentences of its notes. The equations they
call live in ``engine/<family>.py``; the sources they cite in
:mod:`engine.core.sources` (``docs/sources.md``).

Adding a model is adding its spec here: the service's endpoints, the OpenAPI
schema, the form and ``GET /api/v1/models`` all derive from this tuple.
"""

from __future__ import annotations

from ..core.spec import ModelSpec
from .audit import AUDIT as JOINT_AUDIT
from .blow import BLOW
from .capability import CAPABILITY as TOOL_CAPABILITY
from .clamp import CLAMP_CAPABILITY as JOINT_CLAMP_CAPABILITY
from .clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING
from .clutch_spring import SPRING_DESIGN as CLUTCH_SPRING_DESIGN
from .flange import FLANGE as JOINT_FLANGE
from .friction import ISO16047 as FRICTION_ISO16047
from .joint import VDI2230 as JOINT_VDI2230
from .nutrunner import NUTRUNNER_DRIVE
from .preload import CONTROL as PRELOAD_CONTROL
from .preload import TIGHTENING as PRELOAD_TIGHTENING
from .rare_design import RARE_DESIGN
from .rare_impact import RARE_IMPACT
from .trace import ANALYSIS as TRACE_ANALYSIS
from .trace import BATCH as TRACE_BATCH
from .trace import PROGRAM as TRACE_PROGRAM
from .ultrasonic import ULTRASONIC as PRELOAD_ULTRASONIC

MODELS: tuple[ModelSpec, ...] = (
    NUTRUNNER_DRIVE,
    BALL_CLUTCH,
    BALL_CLUTCH_SETTING,
    CLUTCH_SPRING_DESIGN,
    RARE_IMPACT,
    PRELOAD_TIGHTENING,
    PRELOAD_CONTROL,
    PRELOAD_ULTRASONIC,
    JOINT_VDI2230,
    JOINT_AUDIT,
    JOINT_FLANGE,
    BLOW,
    TOOL_CAPABILITY,
    FRICTION_ISO16047,
    TRACE_ANALYSIS,
    TRACE_PROGRAM,
    TRACE_BATCH,
    JOINT_CLAMP_CAPABILITY,
    RARE_DESIGN,
)


def get_model(name: str) -> ModelSpec:
    """The spec called ``name`` (e.g. ``"clutch.ball"``)."""
    for spec in MODELS:
        if spec.name == name:
            return spec
    raise KeyError(name)


__all__ = ["MODELS", "get_model"]
