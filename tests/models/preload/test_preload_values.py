"""Values of engine.physics.preload that its other tests left free: the υ table and its refusal."""

import numpy as np
import pytest

from engine.core.errors import InputOutOfRange
from engine.physics import preload as pl


def test_preload_factor_ranges_are_the_sources():
    # [004, eq. 2]: υ = 1.25…2.0 under a steady load, 2.5…4.0 under a varying one
    assert pl.preload_factor_range("steady") == (1.25, 2.0)
    assert pl.preload_factor_range("varying") == (2.5, 4.0)
    assert pl.PRELOAD_FACTOR_RANGE == {"steady": (1.25, 2.0), "varying": (2.5, 4.0)}


def test_an_unknown_load_type_is_refused_by_name():
    with pytest.raises(InputOutOfRange) as err:
        pl.preload_factor_range("cyclic")
    assert err.value.field == "load_type"
    assert "'steady' or 'varying'" in str(err.value)


def test_a_histogram_of_one_preload_is_widened_to_half_a_percent():
    # every bolt at 10 kN: the band is widened to 10 kN ± 0.5 % = 9.95…10.05 kN, two bins
    h = pl.preload_histogram(np.full(5, 10e3), bins=2, sample_size=38)
    assert h.bin_centres.tolist() == pytest.approx([9975.0, 10025.0], rel=1e-12)
    assert h.counts.tolist() == [0.0, 38.0]  # 10 kN is the edge: numpy's upper bin
    assert (h.minimum, h.maximum, h.mean, h.std) == (10e3, 10e3, 10e3, 0.0)
    # a band of 1e-12 N at 0 N: widened by the 1e-12 floor
    z = pl.preload_histogram(np.zeros(3), bins=2, sample_size=3)
    assert z.bin_centres.tolist() == pytest.approx([-0.5e-12, 0.5e-12], abs=1e-24)


def test_the_scatter_band_of_one_design_given_as_an_array():
    # a study of one point runs the array lines: the same numbers as the float call
    args = (0.00175, 0.0108633, 0.012, (0.08, 0.16), (0.08, 0.16), 0.01663, 0.0135)
    one = pl.friction_scatter_band(60.0, *args)
    arr = pl.friction_scatter_band(np.array([60.0]), *args)
    for a, b in zip(arr, one, strict=True):
        assert np.shape(a) == (1,) and a[0] == pytest.approx(b, rel=1e-12)
