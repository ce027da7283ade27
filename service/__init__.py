"""A thin FastAPI layer over :mod:`engine`: one typed JSON endpoint per model.

``create_app`` is imported on first use, so that ``python -m service`` reaches its entry
point (:mod:`service.__main__`, which sets up the start-up) before the engine is imported.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .main import create_app

__all__ = ["create_app"]


def __getattr__(name: str) -> Any:
    if name == "create_app":
        from .main import create_app

        return create_app
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
