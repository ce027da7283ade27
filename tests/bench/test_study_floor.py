"""The numpy floor study of ``bench.study_summary`` computes the study's own numbers:
the same points drawn, the same F_M and M_A, the same mean, and a summary share that is
a share."""

from __future__ import annotations

import numpy as np
import pytest

from bench import study_summary as s
from engine.studies.execute import run_study


def test_the_floor_draws_and_evaluates_the_studys_points() -> None:
    n = 3_000
    inputs, out = s.floor_values(n)
    study = run_study(s.PRELOAD, s.preload_study(n))
    for name, drawn in zip(("thread_friction", "bearing_friction"), inputs, strict=True):
        assert np.array_equal(study.plan.columns[name], drawn)
    values = study.merged.values
    for name, floor in out.items():
        kept = np.concatenate(list(values.pieces(name)))
        np.testing.assert_allclose(kept, floor, rtol=1e-15, atol=0.0)
    floor_mean = s.floor_summary(inputs, out)["stats"]["assembly_preload"]["mean"]
    assert floor_mean == pytest.approx(study.summary["outputs"]["assembly_preload"]["mean"])
    # M12 8.8 at 90 % of yield with μ_G 0.08…0.16: F_M about 43 kN
    assert 40_000 < floor_mean < 46_000


def test_the_floor_split_gives_a_time_and_a_share() -> None:
    whole, share = s.floor_split(20_000)
    assert whole > 0.0
    assert 0.0 < share < 1.0
