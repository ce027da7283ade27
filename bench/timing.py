"""Timing helpers the benchmark modules share: one call's CPU time, the median wall
time of repeated calls, a time written in microseconds.

Each was written out in two to four modules; one copy here times them all alike.
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable
from typing import Any


def cpu_time(call: Callable[[], Any]) -> float:
    """CPU seconds (``time.process_time``: the machine is shared) of one call of ``call``."""
    start = time.process_time()
    call()
    return time.process_time() - start


def median_wall_time(call: Callable[[], Any], repeats: int, budget_s: float = math.inf) -> float:
    """The median wall time of ``repeats`` calls of ``call``, each timed alone.

    With ``budget_s``, the calls stop once that many seconds have passed in all and at
    least three were timed (a slow call is then timed three times, not ``repeats``):

    >>> calls = []
    >>> median_wall_time(lambda: calls.append(1), 10) >= 0.0, len(calls)
    (True, 10)
    >>> calls.clear()
    >>> _ = median_wall_time(lambda: calls.append(1), 10, budget_s=0.0)
    >>> len(calls)
    3
    """
    times = []
    start = time.perf_counter()
    for _ in range(repeats):
        t0 = time.perf_counter()
        call()
        times.append(time.perf_counter() - t0)
        if time.perf_counter() - start > budget_s and len(times) >= 3:
            break
    return statistics.median(times)


def us(seconds: float) -> str:
    """``seconds`` in whole microseconds, for a row's notes.

    >>> us(36.4e-6)
    '36 µs'
    """
    return f"{seconds * 1e6:.0f} µs"
