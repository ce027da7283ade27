"""Routes that are not a model evaluation (e.g. a catalogue of control methods).

Each family that needs one adds its router here; :func:`service.main.create_app`
includes them all under ``/api/v1``. Keep them as thin as the model routes.
"""

from __future__ import annotations

from fastapi import APIRouter

from .fasteners import router as fasteners_router
from .preload import router as preload_router
from .trace import router as trace_router

EXTRA_ROUTERS: list[APIRouter] = [preload_router, fasteners_router, trace_router]
