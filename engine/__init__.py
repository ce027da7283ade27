"""Engineering models of threaded-joint assembly tools, on SI values.

Pure functions (numpy/scipy), no web code. Each model module holds the
physics as documented functions citing their source equations, and a
:class:`ModelSpec` declaring its inputs, units, ranges and rungs once.
"""

from .errors import BudgetExceeded, EngineError, InfeasibleDesign, InputOutOfRange, SolverFailed
from .models import MODELS, get_model
from .runner import MAX_SWEEP_POINTS, RunResult, SweepResult, run, sweep, sweep_values
from .spec import Check, ModelSpec, Output, Param, Result, RunContext, Rung, fixed_error

__all__ = [
    "MAX_SWEEP_POINTS",
    "MODELS",
    "BudgetExceeded",
    "Check",
    "EngineError",
    "InfeasibleDesign",
    "InputOutOfRange",
    "ModelSpec",
    "Output",
    "Param",
    "Result",
    "RunContext",
    "RunResult",
    "Rung",
    "SolverFailed",
    "SweepResult",
    "fixed_error",
    "get_model",
    "run",
    "sweep",
    "sweep_values",
]
