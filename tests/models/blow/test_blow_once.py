"""blow.joint's rare-impact source works the striker's cycle out once per request.

The release speed, the rollers' radius and the time between blows all come from one
``closed_form_cycle`` of impact.rare's procedure; a request on any rung (with ``auto``
its estimates first) must not run it a second time. The outputs that need no blow are
named in a static list the compute tests against; it must be what ``_tool_values`` gives.
"""

from __future__ import annotations

from collections import Counter
from typing import Any

import pytest

import engine
import engine.models.blow as mb
from engine.core.spec import Scratch
from engine.models.blow import BLOW, RARE_IMPACT_M16


def test_the_static_tool_outputs_are_those_tool_values_gives() -> None:
    values, _ = BLOW.validate(RARE_IMPACT_M16)
    s = mb._setup(values, Scratch())
    assert tuple(mb._tool_values(values, s)) == mb._TOOL_VALUES
    declared = {o.name for o in BLOW.outputs}
    assert set(mb._TOOL_VALUES) <= declared
    assert set(mb._NEED_BLOWS) == declared - set(mb._TOOL_VALUES)


@pytest.mark.parametrize("rung", ["auto", "rigid", "energy", "simulation"])
def test_one_cycle_per_request(monkeypatch: pytest.MonkeyPatch, rung: str) -> None:
    calls: Counter[str] = Counter()
    cycle = mb.closed_form_cycle

    def counted(x: Any, **kw: Any) -> Any:
        calls["cycle"] += 1
        return cycle(x, **kw)

    monkeypatch.setattr(mb, "closed_form_cycle", counted)
    out = engine.run(BLOW, RARE_IMPACT_M16, fidelity=rung)
    assert calls["cycle"] == 1
    # the time between blows is that cycle's motor start to re-lock (not null)
    interval = out.results["blow_interval"]
    assert isinstance(interval, float) and interval > 0.0
