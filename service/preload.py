"""``GET /api/v1/preload/methods``: the catalogue of preload-control methods.

The data are the engine's (:mod:`engine.physics.preload_methods`); this route only
serves them.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter

from engine.physics.preload_methods import catalogue

router = APIRouter(prefix="/api/v1/preload", tags=["preload"])


@router.get(
    "/methods",
    operation_id="list_preload_methods",
    summary="Preload-control methods with their scatter and α_A",
)
def methods() -> dict[str, Any]:
    """Every control method of [004] with its scatter, α_A, fit, misfit and source."""
    return {"methods": catalogue()}
