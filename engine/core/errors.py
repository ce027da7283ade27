"""The engine's exception tree, documented in one place.

Every error the engine raises on purpose is an :class:`EngineError`, itself a
:class:`ValueError`, so plain Python callers can catch it without importing
this module. The service maps each class to one HTTP status.

``EngineError(ValueError)``
    ``InputOutOfRange``   one named input is outside its allowed range (422).
    ``InfeasibleDesign``  the inputs are each valid but the design cannot work
                          (a clutch that never slips, a motor that never
                          reaches the working speed) (422).
    ``SolverFailed``      a numerical method did not converge (422).
    ``BudgetExceeded``    a computation hit its wall-clock or step budget (422).
"""

from __future__ import annotations

from typing import Any


class EngineError(ValueError):
    """Base of every error the engine raises on purpose."""

    kind = "engine_error"

    def __init__(self, message: str, *, field: str | None = None, **context: Any) -> None:
        super().__init__(message)
        self.message = message
        self.field = field
        self.context = context


class InputOutOfRange(EngineError):
    """A named input is outside the range its model declares."""

    kind = "out_of_range"


class InfeasibleDesign(EngineError):
    """Valid inputs that describe a design which cannot work as intended."""

    kind = "infeasible_design"


class SolverFailed(EngineError):
    """A numerical method failed to converge or to reach its event."""

    kind = "solver_failed"


class BudgetExceeded(EngineError):
    """A computation stopped at its wall-clock or step budget."""

    kind = "budget_exceeded"


class Cancelled(EngineError):
    """The caller withdrew the request (its client disconnected): stopped at a budget check."""

    kind = "cancelled"
