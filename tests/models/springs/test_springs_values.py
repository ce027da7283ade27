"""Every tabulated spring value against its standard, and the lookups at their row edges.

The rows are written out again from EN 10270-1 (grades SH/DH, the minimum of each row's
range), EN 10270-3 (1.4310, grade NS) and EN 13906-1, so a wrong digit in the module's copy
fails; the row edges are read on both sides.
"""

import itertools
import math

import numpy as np
import pytest

from engine.core.errors import InputOutOfRange
from engine.physics import springs as sp

# EN 10270-1 SH/DH: (largest wire diameter of the row [mm], minimum R_m [MPa])
EN10270_1 = [
    (0.30, 2660), (0.32, 2640), (0.34, 2610), (0.40, 2560), (0.50, 2480), (0.60, 2410),
    (0.70, 2350), (0.80, 2310), (0.90, 2270), (1.00, 2230), (1.20, 2170), (1.40, 2100),
    (1.60, 2050), (1.80, 2000), (2.00, 1980), (2.50, 1890), (3.00, 1840), (3.50, 1780),
    (4.00, 1740), (4.50, 1690), (5.00, 1670), (6.00, 1590), (7.00, 1540), (8.00, 1480),
    (9.00, 1440), (10.00, 1400), (12.00, 1340), (14.00, 1290), (16.00, 1250),
    (18.00, 1210), (20.00, 1170),
]  # fmt: skip

# EN 10270-3, 1.4310 grade NS (the standard stops at 10 mm)
EN10270_3 = [
    (0.20, 2200), (0.30, 2150), (0.40, 2100), (0.50, 2050), (0.65, 2000), (0.80, 1950),
    (1.00, 1900), (1.25, 1850), (1.50, 1800), (1.75, 1750), (2.00, 1700), (2.50, 1650),
    (3.00, 1600), (3.50, 1550), (4.25, 1500), (5.00, 1450), (6.00, 1400), (7.00, 1350),
    (8.50, 1300), (10.00, 1250),
]  # fmt: skip

TABLES = {"EN10270-1-SH": EN10270_1, "EN10270-1-DH": EN10270_1, "1.4310": EN10270_3}

# EN 10270-1 preferred wire sizes [mm]
PREFERRED = (
    0.30, 0.32, 0.34, 0.36, 0.38, 0.40, 0.43, 0.45, 0.48, 0.50, 0.53, 0.56, 0.60, 0.63,
    0.65, 0.70, 0.75, 0.80, 0.85, 0.90, 0.95, 1.00, 1.05, 1.10, 1.20, 1.25, 1.30, 1.40,
    1.50, 1.60, 1.70, 1.80, 1.90, 2.00, 2.10, 2.25, 2.40, 2.50, 2.60, 2.80, 3.00, 3.20,
    3.40, 3.60, 3.80, 4.00, 4.25, 4.50, 4.75, 5.00, 5.30, 5.60, 6.00, 6.30, 6.50, 7.00,
    7.50, 8.00, 8.50, 9.00, 9.50, 10.00, 10.50, 11.00, 12.00, 12.50, 13.00, 14.00, 15.00,
    16.00, 17.00, 18.00, 19.00, 20.00,
)  # fmt: skip


@pytest.mark.parametrize("material", sorted(TABLES))
def test_every_row_is_the_standards_and_is_read_on_both_sides_of_its_edge(material):
    rows = TABLES[material]
    assert [(d, rm) for d, rm in sp.MATERIALS[material].strength] == [
        (pytest.approx(d, abs=1e-12), pytest.approx(rm, abs=1e-9)) for d, rm in rows
    ]
    for i, (d, rm) in enumerate(rows):
        # at the row's top diameter (and a round-off above it): this row
        assert sp.tensile_strength(material, d * 1e-3) == rm * 1e6
        assert sp.tensile_strength(material, d * 1e-3 * (1 + 1e-12)) == rm * 1e6
        assert sp.permissible_shear_stress(material, d * 1e-3) == pytest.approx(0.5 * rm * 1e6)
        # just above it: the next row, the lower strength (safe side); beyond the last: refused
        above = d * 1e-3 * (1 + 1e-6)
        if i + 1 < len(rows):
            assert sp.tensile_strength(material, above) == rows[i + 1][1] * 1e6
        else:
            with pytest.raises(InputOutOfRange) as err:
                sp.tensile_strength(material, above)
            assert err.value.field == "spring_wire_diameter"
            assert f"up to {d:g} mm" in str(err.value)
    # the same edges read as one array (the study's path)
    tops = np.array([d for d, _ in rows]) * 1e-3
    assert sp.tensile_strength(material, tops).tolist() == [rm * 1e6 for _, rm in rows]
    nxt = sp.tensile_strength(material, tops * (1 + 1e-6))
    assert nxt[:-1].tolist() == [rm * 1e6 for _, rm in rows[1:]]
    assert math.isnan(nxt[-1])


@pytest.mark.parametrize("material", sorted(TABLES))
def test_a_wire_thinner_than_the_first_row_takes_the_first_row(material):
    first_d, first_rm = TABLES[material][0]
    for d_mm in (0.5 * first_d, 0.9 * first_d, first_d * (1 - 1e-6)):
        assert sp.tensile_strength(material, d_mm * 1e-3) == first_rm * 1e6
    assert sp.tensile_strength(material, np.array([0.1e-3, 0.15e-3])).tolist() == [
        first_rm * 1e6,
        first_rm * 1e6,
    ]


def test_materials_moduli_and_densities():
    # EN 13906-1 reference values: G, E [Pa], ρ [kg/m³]
    expected = {
        "EN10270-1-SH": (81.5e9, 206e9, 7850.0),
        "EN10270-1-DH": (81.5e9, 206e9, 7850.0),
        "1.4310": (70e9, 185e9, 7900.0),
    }
    assert set(sp.MATERIALS) == set(expected)
    for name, (g, e, rho) in expected.items():
        m = sp.MATERIALS[name]
        assert (m.shear_modulus, m.elastic_modulus, m.density) == (g, e, rho)
        assert m.name == name
        lo, hi = m.diameter_range
        assert lo == pytest.approx(TABLES[name][0][0] * 1e-3, rel=1e-12)
        assert hi == pytest.approx(TABLES[name][-1][0] * 1e-3, rel=1e-12)


def test_seating_coefficients_are_en_13906s():
    assert sp.SEATING_COEFFICIENTS == {
        "fixed_free": 2.0,
        "hinged_hinged": 1.0,
        "fixed_hinged": 0.7,
        "fixed_fixed": 0.5,
    }


def test_every_preferred_wire_is_found_and_midpoints_go_to_the_smaller():
    assert tuple(sp.STANDARD_WIRE_DIAMETERS) == pytest.approx(PREFERRED, abs=1e-12)
    for d in PREFERRED:
        near, ok = sp.nearest_standard_wire(d * 1e-3)
        assert ok and near == pytest.approx(d * 1e-3, rel=1e-12)
    for a, b in itertools.pairwise(PREFERRED):
        near, ok = sp.nearest_standard_wire((0.3 * a + 0.7 * b) * 1e-3)
        assert not ok and near == pytest.approx(b * 1e-3, rel=1e-12)
        near, ok = sp.nearest_standard_wire((0.7 * a + 0.3 * b) * 1e-3)
        assert not ok and near == pytest.approx(a * 1e-3, rel=1e-12)
    # within 0.1 µm counts as the size, 0.2 µm off does not
    assert sp.nearest_standard_wire(0.00400005)[1]
    assert not sp.nearest_standard_wire(0.0040002)[1]
    # outside the series: its ends
    assert sp.nearest_standard_wire(0.0001) == (pytest.approx(0.0003), False)
    assert sp.nearest_standard_wire(0.05) == (pytest.approx(0.02), False)
