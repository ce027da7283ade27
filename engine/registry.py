"""Kept so that ``from engine.registry import MODELS, get_model`` still works.

The registry is :mod:`engine.models` (one declaration module per family).
"""

from __future__ import annotations

from .models import MODELS, get_model

__all__ = ["MODELS", "get_model"]
