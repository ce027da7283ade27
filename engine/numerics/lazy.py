"""A module imported on first use, for the heavy imports only some requests need.

scipy's ``stats``, ``special`` and ``integrate`` each cost the service's start-up a
share of its import time (docs/performance.md, cold start), yet only studies,
capability requests and a few rungs call them. A module-level
``stats = LazyModule("scipy.stats")`` reads like the import it replaces
(``stats.truncnorm.ppf(...)``) and imports scipy.stats on the first attribute read;
each attribute read is then stored on the proxy, so later reads cost a plain
attribute look-up.
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = ["LazyModule"]


class LazyModule:
    """The module ``name``, imported on the first read of one of its attributes.

    >>> import sys
    >>> special = LazyModule("scipy.special")
    >>> special
    LazyModule('scipy.special')
    >>> float(special.ndtr(0.0)), "scipy.special" in sys.modules
    (0.5, True)
    >>> special.ndtr is sys.modules["scipy.special"].ndtr
    True

    Dunder names are not forwarded (introspection by doctest, pickle or an IDE does not
    import the module):

    >>> hasattr(LazyModule("no.such.module"), "__wrapped__")
    False
    """

    def __init__(self, name: str) -> None:
        self._name = name

    def __repr__(self) -> str:
        return f"LazyModule({self._name!r})"

    def __getattr__(self, attr: str) -> Any:
        if attr.startswith("__") and attr.endswith("__"):
            raise AttributeError(attr)
        value = getattr(importlib.import_module(self._name), attr)
        setattr(self, attr, value)  # later reads skip __getattr__
        return value
