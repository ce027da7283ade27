"""``GET /api/v1/fasteners``: the fastener catalogue the form's pickers read.

The data are the engine's (:func:`engine.physics.fasteners.catalogue`, SI units); this
route only serves them.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from fastapi import APIRouter

from engine.physics.fasteners import catalogue

router = APIRouter(prefix="/api/v1", tags=["fasteners"])


@lru_cache(maxsize=1)
def _catalogue() -> dict[str, Any]:
    return catalogue()


@router.get(
    "/fasteners",
    operation_id="list_fasteners",
    summary="Threads, grades, heads, nuts, washers and materials (SI)",
)
def fasteners() -> dict[str, Any]:
    """Every catalogue entry a thread designation, grade or material input accepts."""
    return _catalogue()
