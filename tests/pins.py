"""One explicit way for a value test to say which model output it holds.

``pin("joint.vdi2230", "grip", r.results["grip"], 0.036, rel=1e-9)`` asserts the
value like ``pytest.approx`` and names the model and the output, so that
:mod:`tests.test_every_output_pinned` counts the output as held without guessing
which model a test file runs. The expected value must be computed independently
(a hand calculation written out in the test, a published number, a limit).
"""

from __future__ import annotations

from typing import Any

import pytest

import engine


def pin(
    model: str,
    output: str,
    actual: Any,
    expected: Any,
    *,
    rel: float | None = None,
    abs: float | None = None,
) -> None:
    """Assert ``actual == pytest.approx(expected, rel=rel, abs=abs)`` for ``model``'s ``output``."""
    names = {o.name for o in engine.get_model(model).outputs}
    assert output in names, f"{model} has no output {output!r}"
    assert actual == pytest.approx(expected, rel=rel, abs=abs), f"{model}: {output}"
