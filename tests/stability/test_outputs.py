"""``outputs`` limits the answer to what is asked, and the value asked for alone is the same.

For every model, rung and output at the first example: asking for one output
returns that output only (scalar or series), present exactly when the full run
has it, with the same value (a model that computes an output only as a side
effect of another would return nothing, or something else). Whether asking
for less is also faster is a benchmark figure (``make bench``, "one output
asked for"), not an assertion: machines are noisy.
"""

from __future__ import annotations

import math

import pytest

from bench.generic import applicable_rungs
from engine import ModelSpec

from .common import FIXED, MODELS_UNDER_TEST, ids, run_checked


@pytest.mark.parametrize("spec", MODELS_UNDER_TEST, ids=ids)
def test_one_output_returns_only_that_output(spec: ModelSpec) -> None:
    case = {**spec.examples[0], **FIXED.get(spec.name, {})}
    for rung, estimate in applicable_rungs(spec, case):
        full = run_checked(spec, case, fidelity=rung.name, series=True)
        assert full is not None, f"{spec.name}: the first example must run on {rung.name}"
        for output in spec.outputs:
            alone = run_checked(spec, case, fidelity=rung.name, outputs=[output.name])
            assert alone is not None
            returned = set(alone.results) | set(alone.series)
            assert returned <= {output.name}, f"{spec.name} asked for {output.name}: {returned}"
            assert set(alone.units) == returned
            if output.series:
                assert (output.name in alone.series) == (output.name in full.series)
                continue
            # an output asked for by name always comes back: null (with a note) where this
            # rung does not compute it, as absent or null in a full run
            assert output.name in alone.results, f"{spec.name}: {output.name} asked, not returned"
            assert (alone.results[output.name] is None) == (
                full.results.get(output.name) is None
            ), f"{spec.name}/{rung.name}: {output.name} alone vs in a full run"
            a, b = alone.results.get(output.name), full.results.get(output.name)
            if isinstance(a, float) and isinstance(b, float):
                assert math.isclose(a, b, rel_tol=max(1e-9, estimate), abs_tol=1e-300), (
                    f"{spec.name}/{rung.name}: {output.name} alone {a!r}, in a full run {b!r}"
                )
            else:
                assert a == b
