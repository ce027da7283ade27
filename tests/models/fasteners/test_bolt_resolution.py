"""One bolt resolution for one design or many (engine.procedures.bolt).

:func:`resolve_bolt` (one design) and :func:`resolve_bolts` (many) run the same step,
``_bolt_numbers``; every model (joint, preload, blow) takes its bolt from them.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.core.errors import InputOutOfRange
from engine.procedures.bolt import resolve_bolt, resolve_bolts

NUMBERS = (
    "diameter",
    "pitch",
    "pitch_diameter",
    "minor_diameter",
    "stress_diameter",
    "stress_area",
    "yield_strength",
    "tensile_strength",
    "bearing_outer_diameter",
    "hole_diameter",
)


def test_a_varied_size_gives_each_point_its_single_design_bolt() -> None:
    d = np.array([0.010, 0.012, 0.016, 0.0125])  # 12.5 mm is no ISO 261 size: refused
    bolts, _ = resolve_bolts({"thread_diameter": d}, 4)
    assert bolts.ok.tolist() == [True, True, True, False]
    for j in range(3):
        alone, _ = resolve_bolt({"thread_diameter": float(d[j])})
        here = bolts.at(j)
        for name in NUMBERS:
            assert getattr(here, name) == pytest.approx(getattr(alone, name), rel=1e-15), name
    with pytest.raises(InputOutOfRange):
        resolve_bolt({"thread_diameter": 0.0125})
    # ISO 261 coarse pitches 1.5, 1.75, 2 mm; ISO 898-1 A_s = 58.0, 84.3, 157 mm²
    assert np.asarray(bolts.pitch)[:3] == pytest.approx([1.5e-3, 1.75e-3, 2e-3], rel=1e-12)
    assert np.asarray(bolts.stress_area)[:3] == pytest.approx([58.0e-6, 84.3e-6, 157e-6], rel=3e-3)
    # 8.8: R_p0.2 640 MPa up to M16, 660 above (ISO 898-1)
    assert np.asarray(bolts.yield_strength)[:3].tolist() == [640e6, 640e6, 640e6]
    distinct, index = bolts.distinct()
    assert [b.diameter for b in distinct] == [0.010, 0.012, 0.016]
    assert index.tolist() == [0, 1, 2, -1]


def test_a_given_hole_below_the_thread_is_refused_at_that_point_only() -> None:
    hole = np.array([0.013, 0.0115, 0.0135])
    bolts, _ = resolve_bolts({"thread_diameter": 0.012, "hole_diameter": hole}, 3)
    assert bolts.ok.tolist() == [True, False, True]
    with pytest.raises(InputOutOfRange, match="hole_diameter"):
        resolve_bolt({"thread_diameter": 0.012, "hole_diameter": 0.0115})
    # one thread size: one distinct bolt, at the first point it takes
    distinct, index = bolts.distinct()
    assert len(distinct) == 1 and distinct[0].hole_diameter == 0.013
    assert index.tolist() == [0, -1, 0]


def test_a_catalogue_part_with_a_varied_size_is_resolved_per_size() -> None:
    x = {"thread_diameter": np.array([0.008, 0.012, 0.008]), "grade": "10.9"}
    with pytest.raises(ValueError, match="point by point"):
        resolve_bolts(x, 3)  # one catalogue part for every point is what the caller takes
    bolts, _ = resolve_bolts(x, 3, per_size=True)
    assert bolts.ok.all()
    # ISO 898-1 10.9: R_p0.2 = 940 MPa, R_m = 1040 MPa (one class for every size here)
    assert np.asarray(bolts.yield_strength).tolist() == [940e6, 940e6, 940e6]
    assert np.asarray(bolts.tensile_strength).tolist() == [1040e6, 1040e6, 1040e6]
    for j, d in enumerate((0.008, 0.012, 0.008)):
        alone, _ = resolve_bolt({"thread_diameter": d, "grade": "10.9"})
        assert bolts.at(j) == alone
    distinct, index = bolts.distinct()
    assert [b.diameter for b in distinct] == [0.008, 0.012]
    assert index.tolist() == [0, 1, 0]
