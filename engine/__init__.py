"""Engineering models of threaded-joint assembly tools, on SI values.

Pure functions (numpy/scipy), no web code, in layers you can see in the folders:

* ``engine/physics/``: one function per equation of a seed or a standard, on floats or
  numpy arrays, each citing its source;
* ``engine/numerics/``: the compiled-ODE kit the simulations share;
* ``engine/procedures/``: one design worked through as named steps (the bolt as bought,
  the clutch as built, the striker cycle);
* ``engine/models/<family>.py``: the :class:`ModelSpec` declaring each model's inputs,
  units, ranges, rungs, checks and notes once, and its adapter to the physics;
* ``engine/core/``: the spec machinery, the runner, sweeps and the sources
  (:mod:`engine.core.sources`: what every citation such as ``[001, eq. 2]`` refers to);
* ``engine/studies/``: design studies (plan, execute on Dask, summarise).
"""

from .core import sources
from .core.errors import (
    BudgetExceeded,
    Cancelled,
    EngineError,
    InfeasibleDesign,
    InputOutOfRange,
    SolverFailed,
)
from .core.runner import MAX_SWEEP_POINTS, RunResult, SweepResult, run, sweep, sweep_values
from .core.spec import (
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
from .models import MODELS, get_model

__all__ = [
    "MAX_SWEEP_POINTS",
    "MODELS",
    "BudgetExceeded",
    "Cancelled",
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
