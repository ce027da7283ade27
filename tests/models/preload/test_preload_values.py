"""Values of engine.physics.preload that its other tests left free: the υ table and its refusal."""

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
