"""Settings from the environment, each with an embedded default (nothing to configure)."""

from __future__ import annotations

import os
from dataclasses import dataclass, field


def _origins() -> tuple[str, ...]:
    raw = os.environ.get("CORS_ORIGINS", "")
    return tuple(o.strip() for o in raw.split(",") if o.strip())


@dataclass(frozen=True)
class Settings:
    host: str = field(default_factory=lambda: os.environ.get("HOST", "127.0.0.1"))
    port: int = field(default_factory=lambda: int(os.environ.get("PORT", "8000")))
    cors_origins: tuple[str, ...] = field(default_factory=_origins)
    max_body_bytes: int = field(
        default_factory=lambda: int(os.environ.get("MAX_BODY_BYTES", str(256 * 1024)))
    )
    log_level: str = field(default_factory=lambda: os.environ.get("LOG_LEVEL", "info"))
