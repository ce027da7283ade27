"""Every model the product offers, in the order the catalogue lists them.

Adding a model is adding its spec here: the service's endpoints, the OpenAPI
schema, the form and ``GET /api/v1/models`` all derive from this tuple.
"""

from __future__ import annotations

from .clutch import BALL_CLUTCH, BALL_CLUTCH_SETTING
from .joint_models import VDI2230 as JOINT_VDI2230
from .nutrunner import NUTRUNNER_DRIVE
from .preload_models import CONTROL as PRELOAD_CONTROL
from .preload_models import TIGHTENING as PRELOAD_TIGHTENING
from .rare_impact import RARE_IMPACT
from .spec import ModelSpec

MODELS: tuple[ModelSpec, ...] = (
    NUTRUNNER_DRIVE,
    BALL_CLUTCH,
    BALL_CLUTCH_SETTING,
    RARE_IMPACT,
    PRELOAD_TIGHTENING,
    PRELOAD_CONTROL,
    JOINT_VDI2230,
)


def get_model(name: str) -> ModelSpec:
    """The spec called ``name`` (e.g. ``"clutch.ball"``)."""
    for spec in MODELS:
        if spec.name == name:
            return spec
    raise KeyError(name)
