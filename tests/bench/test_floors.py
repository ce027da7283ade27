"""The numpy floors of ``bench/extra_floors.py`` compute what the engine computes."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from bench import extra_floors, page
from engine.models import get_model


@pytest.mark.parametrize("case", extra_floors.CASES, ids=lambda c: c.model)
def test_floor_equals_engine_at_1000_points(case: extra_floors.Case) -> None:
    sweep, floor = extra_floors.prepare(case, 1000)  # asserts equality to 1e-12 relative
    got, want = floor(), sweep().columns
    assert sorted(got) == sorted(case.outputs)
    for name in case.outputs:
        assert want[name].shape == (1000,)
        assert np.all(np.isfinite(want[name]))
        np.testing.assert_allclose(got[name], want[name], rtol=1e-12, atol=0.0)


def test_tightening_floor_by_hand() -> None:
    """M12 8.8, μ_G = μ_K = 0.12: F_M,zul = 43.11 kN (VDI 2230-1 Table A1), M_A = 83.6 N·m."""
    spec = get_model("preload.tightening")
    floor = extra_floors._tightening_floor(spec, dict(spec.examples[0]))
    got = floor(np.array([0.12]))
    # R7: d2 = 10.863 mm, d0 = 10.358 mm, P = 1.75 mm
    d2, d3, p = 10.863342e-3, 9.852979e-3, 1.75e-3
    d0 = 0.5 * (d2 + d3)
    ratio = 1.5 * d2 / d0 * (p / (math.pi * d2) + 0.12 / math.cos(math.radians(30)))
    preload = 0.9 * 640e6 * math.pi / 4 * d0**2 / math.sqrt(1 + 3 * ratio**2)
    assert got["assembly_preload"][0] == pytest.approx(preload, rel=1e-6)
    assert got["assembly_preload"][0] == pytest.approx(43.11e3, rel=2e-4)
    # R13: k_G = 0.16 P + 0.58 d2 μ_G, k_K = μ_K (16.63 + 13.5)/4 mm
    torque = preload * (0.16 * p + 0.58 * d2 * 0.12 + 0.12 * (16.63e-3 + 13.5e-3) / 4)
    assert got["tightening_torque"][0] == pytest.approx(torque, rel=1e-6)
    assert got["tightening_torque"][0] == pytest.approx(83.64, abs=0.01)


def test_a_wrong_floor_is_refused() -> None:
    """The equality check fails for a floor off by 1e-9: it is not a check that always passes."""
    case = extra_floors.CASES[0]

    def build(spec, base):  # type: ignore[no-untyped-def]
        right = case.build(spec, base)
        return lambda mu: {k: v * (1 + 1e-9) for k, v in right(mu).items()}

    with pytest.raises(AssertionError):
        extra_floors.prepare(dataclasses.replace(case, build=build), 100)


def test_rows_state_the_target() -> None:
    rows = extra_floors.measure(points=200, rounds=1)
    assert [r["model"] for r in rows] == [c.model for c in extra_floors.CASES]
    for row in rows:
        assert row["target"] == "10⁶-point engine.sweep / its numpy floor"
        assert row["target_ratio"] == 3.0
        assert row["met"] == (row["ratio"] <= 3.0)
        assert row["time_s"] > 0 and row["floor_s"] > 0
        # the performance page's first target (the 10⁶-point sweep / its floor) claims it
        stored = {**row, "kind": "extra", "source": "extra_floors.py"}
        assert page.TARGETS[0].match(stored)
        assert "floor" in page.TARGETS[0].label
