"""A thin FastAPI layer over :mod:`engine`: one typed JSON endpoint per model."""

from .main import create_app

__all__ = ["create_app"]
