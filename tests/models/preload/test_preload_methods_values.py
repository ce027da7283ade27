"""Every preload-control method record against its source, and the catalogue built from them.

The scatter ±s is the review's [004] where it gives one, else VDI 2230-1:2015 Table A8's
band of α_A for the same principle, turned into s by hand here: s = (α_A − 1)/(α_A + 1)
(the inverse of α_A = (1 + s)/(1 − s)); the records marked assumption say so.
"""

import pytest

from engine.physics import preload_methods as pm


def s_of(alpha: float) -> float:
    return (alpha - 1.0) / (alpha + 1.0)


# key: (family, controls, s used, (s_min, s_max), cost rank, assumption)
RECORDS = {
    "torque_wrench": ("bolt", "torque", 0.30, (0.30, 0.30), 1, False),
    "limit_wrench": ("bolt", "torque", 0.30, (0.30, 0.30), 2, False),
    "shear_off_nut": ("bolt", "torque", 0.30, (0.30, 0.30), 2, True),
    "nut_angle": ("bolt", "angle", 0.20, (0.20, 0.20), 2, False),
    "torque_then_angle": ("bolt", "angle", s_of(1.4), (s_of(1.2), s_of(1.4)), 3, False),
    "torque_gradient": ("bolt", "yield", s_of(1.4), (s_of(1.2), s_of(1.4)), 4, False),
    "measuring_washer_ring": ("bolt", "force", 0.10, (0.10, 0.10), 4, False),
    "pneumatic_washer": ("bolt", "force", 0.20, (0.10, 0.20), 5, True),
    "elongation_micrometer": ("bolt", "elongation", s_of(1.5), (s_of(1.1), s_of(1.5)), 4, False),
    "drilled_bolt_rod": ("bolt", "elongation", s_of(1.5), (s_of(1.1), s_of(1.5)), 5, False),
    "strain_gauge": ("bolt", "elongation", 0.10, (0.05, 0.10), 6, True),
    "ultrasound": ("bolt", "elongation", s_of(1.2), (s_of(1.05), s_of(1.2)), 7, False),
    "rod_dynamometric_wrench": ("sucker_rod", "torque", 0.30, (0.30, 0.30), 2, True),
    "rod_displacement_marks": ("sucker_rod", "displacement", 0.20, (0.20, 0.20), 1, True),
    "rod_locking_ring": ("sucker_rod", "force", 0.20, (0.10, 0.20), 3, True),
}


def test_the_methods_are_these_in_this_order():
    assert tuple(RECORDS) == pm.METHOD_KEYS
    assert pm.CONTROLLED == ("torque", "angle", "elongation", "force", "displacement", "yield")


@pytest.mark.parametrize("key", list(RECORDS))
def test_every_record(key):
    family, controls, s, band, rank, assumption = RECORDS[key]
    m = pm.get_method(key)
    assert (m.key, m.family, m.controls, m.cost_rank, m.assumption) == (
        key,
        family,
        controls,
        rank,
        assumption,
    )
    assert m.controls in pm.CONTROLLED
    assert m.scatter == pytest.approx(s, rel=1e-12)
    assert m.scatter_band == pytest.approx(band, rel=1e-12)
    alpha = (1 + s) / (1 - s)
    assert m.tightening_factor == pytest.approx(alpha, rel=1e-12)
    d = m.describe()
    assert d["key"] == key and d["family"] == family and d["controls"] == controls
    assert d["scatter"] == pytest.approx(s, rel=1e-12)
    assert d["scatter_band"] == pytest.approx(list(band), rel=1e-12)
    assert d["tightening_factor"] == pytest.approx(alpha, rel=1e-12)
    assert d["tightening_factor_band"] == pytest.approx(
        [(1 + b) / (1 - b) for b in band], rel=1e-12
    )
    assert d["scatter_is_assumption"] is assumption and d["cost_rank"] == rank
    for text in ("name", "scatter_source", "fits", "does_not_fit", "source"):
        assert d[text] == getattr(m, text) and d[text]
    # the record says where its number comes from, and an assumption says it is one
    assert ("assumption" in m.scatter_source) == assumption


def test_an_unknown_method_is_a_key_error():
    with pytest.raises(KeyError):
        pm.get_method("telepathy")


def test_catalogue_lists_bolts_first_then_rods_cheapest_first():
    keys = [r["key"] for r in pm.catalogue()]
    expected = sorted(RECORDS, key=lambda k: (RECORDS[k][0] != "bolt", RECORDS[k][4], k))
    assert keys == expected
    assert keys[0] == "torque_wrench" and keys[-1] == "rod_locking_ring"
