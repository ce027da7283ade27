"""Every model the product offers, in the order the catalogue lists them.

Adding a model is adding its spec here: the service's endpoints, the OpenAPI
schema, the form and ``GET /api/v1/models`` all derive from this tuple.
"""

from __future__ import annotations

from .rare_impact import RARE_IMPACT
from .spec import ModelSpec

MODELS: tuple[ModelSpec, ...] = (RARE_IMPACT,)


def get_model(name: str) -> ModelSpec:
    """The spec called ``name`` (e.g. ``"clutch.ball"``)."""
    for spec in MODELS:
        if spec.name == name:
            return spec
    raise KeyError(name)
