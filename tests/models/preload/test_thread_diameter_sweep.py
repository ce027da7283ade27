"""A sweep over the thread diameter gives each point's single run to the last bit.

The sweep evaluates the diameters as one array (the bolt resolved once, every
equation on arrays); the single run evaluates one float. Both call the same
functions, so every output must be equal bit for bit, not merely close: a power
that numpy rounds differently from Python (``d**3`` gave ``yield_rule_torque``
one ulp apart at M5, M8 and M30) is caught here. The joint resolves its bolt the
same way and is held to the same rule.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import engine

#: Every ISO 261 coarse size the catalogue tabulates, M3 … M39 [mm]: more points than
#: one SIMD register holds, so numpy's vector loops (not only their scalar tails) run.
COARSE_SIZES_MM = [3, 3.5, 4, 5, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 27, 30, 33, 36, 39]


def _diameters(example: dict[str, Any]) -> np.ndarray:
    """The swept diameters: the coarse sizes, or -40 … +10 % around a design whose pitch
    is given (below its hole diameter, 17.5 mm for preload.control's example)."""
    if example.get("thread_pitch") is not None:
        d = example["thread_diameter"]
        return np.linspace(0.6 * d, 1.1 * d, 41)
    return np.array(COARSE_SIZES_MM) * 1e-3


@pytest.mark.parametrize("name", ["preload.tightening", "preload.control", "joint.vdi2230"])
def test_a_sweep_over_the_thread_diameter_is_the_single_runs_bit_for_bit(name: str) -> None:
    spec = engine.get_model(name)
    example = dict(spec.examples[0])
    diameters = _diameters(example)
    swept = engine.sweep(spec, example, "thread_diameter", diameters.tolist())
    assert None not in swept.rungs  # every point computed: nothing compared is a null
    floats = 0
    for j, d in enumerate(diameters.tolist()):
        single = engine.run(spec, {**example, "thread_diameter": d}, fidelity=swept.rungs[j])
        for output, column in swept.results.items():
            got, want = column[j], single.results.get(output)  # None: not computed here
            assert type(got) is type(want) and got == want, (output, d, got, want)
            floats += type(want) is float
    assert floats > 10 * len(diameters)  # the float outputs were compared, not skipped
