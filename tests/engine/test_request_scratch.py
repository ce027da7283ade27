"""One request computes its heavy steps once, and nothing of it reaches the next request.

The runner gives each request (one ``engine.run``, one array evaluation of a sweep or a
study chunk) a :class:`~engine.core.spec.Scratch`: the rung estimates leave their work
there (impact.rare's cycle, the preload models' bolt and torque coefficients) and the
compute of the same request reads it. It is not a module-level cache: a caller that
refills the same numpy buffer between two requests gets each design's own answer.
"""

from __future__ import annotations

from collections import Counter
from typing import Any

import numpy as np
import pytest

import engine
import engine.models.preload as mp
import engine.models.rare_impact as mr
from engine.core.spec import Scratch
from engine.models.preload import TIGHTENING
from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN
from engine.studies.plan import evaluate_chunk


def _count_cycles(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    calls: Counter[str] = Counter()
    cycle = mr.closed_form_cycle

    def counted(x: Any, **kw: Any) -> Any:
        calls["cycle"] += 1
        return cycle(x, **kw)

    monkeypatch.setattr(mr, "closed_form_cycle", counted)
    return calls


def test_scratch_keeps_a_value_per_key_for_its_own_life() -> None:
    s, other = Scratch(), Scratch()
    assert s.once("a", lambda: 1.5) == 1.5
    assert s.once("a", lambda: 2.5) == 1.5  # kept
    assert s.once("b", lambda: 2.5) == 2.5  # another key
    assert other.once("a", lambda: 3.5) == 3.5  # another request sees nothing of s


def test_rare_impact_runs_its_cycle_once_per_request(monkeypatch: pytest.MonkeyPatch) -> None:
    calls = _count_cycles(monkeypatch)
    first = engine.run(RARE_IMPACT, REFERENCE_DESIGN)  # auto: the estimate, then the run
    assert first.rung == "closed_form" and calls["cycle"] == 1
    again = engine.run(RARE_IMPACT, REFERENCE_DESIGN)
    assert calls["cycle"] == 2  # the next request computes its own
    assert again.results == first.results
    calls.clear()
    engine.sweep(RARE_IMPACT, REFERENCE_DESIGN, "motor_torque", [4.0, 5.0, 6.0], tolerance=0.05)
    assert calls["cycle"] == 1  # the chunk's estimates and its array path share one cycle


def test_a_refilled_buffer_gives_each_design_its_own_cycle() -> None:
    """Two chunks in a row through one numpy buffer: each point as its own single run."""
    outputs = ["release_speed", "spin_up_time"]
    buffer = np.array([30000.0, 50000.0])
    got = []
    for rates in ([30000.0, 50000.0], [70000.0, 90000.0]):
        buffer[:] = rates
        chunk = evaluate_chunk(
            RARE_IMPACT, REFERENCE_DESIGN, {"power_spring_rate": buffer}, outputs, tolerance=0.05
        )
        got.append(chunk.values["release_speed"].copy())
        for j, rate in enumerate(rates):
            alone = engine.run(RARE_IMPACT, {**REFERENCE_DESIGN, "power_spring_rate": rate})
            assert chunk.values["release_speed"][j] == pytest.approx(
                alone.results["release_speed"], rel=1e-12
            )
    # a stiffer power spring releases later, at a higher speed: the second chunk is not
    # the first one's answer handed back
    assert np.all(got[1] > got[0])


def test_preload_resolves_each_request_s_own_bolt(monkeypatch: pytest.MonkeyPatch) -> None:
    """M12 then M16 in a row: each request its own bolt, resolved once for estimate and run."""
    resolved: list[float] = []
    resolve = mp._resolve_design

    def counted(x: Any) -> Any:
        design = resolve(x)
        resolved.append(design.bolt.diameter)
        return design

    monkeypatch.setattr(mp, "_resolve_design", counted)
    m12 = engine.run(TIGHTENING, {"thread_diameter": 0.012})
    m16 = engine.run(TIGHTENING, {"thread_diameter": 0.016})
    assert resolved == [0.012, 0.016]
    # ISO 898-1 / ISO 261: A_s of M12 84.3 mm², of M16 157 mm²
    assert m12.results["stress_area"] == pytest.approx(84.3e-6, rel=2e-3)
    assert m16.results["stress_area"] == pytest.approx(157e-6, rel=3e-3)  # the table rounds 156.7
