"""Engineering models of threaded-joint assembly tools, on SI values.

Pure functions (numpy/scipy), no web code. ``engine/<family>.py`` holds a
family's physics as documented functions citing their source equations;
``engine/models/<family>.py`` the :class:`ModelSpec` declaring each model's
inputs, units, ranges, rungs, checks and notes once; :mod:`engine.sources`
what every citation such as ``[001, eq. 2]`` refers to.
"""

from . import sources
from .errors import BudgetExceeded, EngineError, InfeasibleDesign, InputOutOfRange, SolverFailed
from .models import MODELS, get_model
from .runner import MAX_SWEEP_POINTS, RunResult, SweepResult, run, sweep, sweep_values
from .spec import (
    Check,
    ModelSpec,
    Output,
    Param,
    Plot,
    Result,
    RunContext,
    Rung,
    Window,
    fixed_error,
)

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
    "Plot",
    "Result",
    "RunContext",
    "RunResult",
    "Rung",
    "SolverFailed",
    "SweepResult",
    "Window",
    "fixed_error",
    "get_model",
    "run",
    "sources",
    "sweep",
    "sweep_values",
]
