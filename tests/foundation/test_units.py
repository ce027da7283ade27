import pytest

from service.units import UnitError, to_si


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("45 mm", "m", 0.045),
        ("1450 rpm", "rad/s", 1450 * 2 * 3.141592653589793 / 60),
        ("8e4 MPa", "Pa", 8e10),
        ("45 deg", "rad", 0.7853981633974483),
        ("1.1 kW", "W", 1100.0),
        ("80 N·m", "N*m", 80.0),
        ("80 N*m", "N*m", 80.0),
        ("10 µm", "m", 1e-5),
        ("10 μm", "m", 1e-5),
        ("85 %", "1", 0.85),
        ("0.3", "m", 0.3),
        ("2 kg*m^2", "kg*m^2", 2.0),
        ("45°", "rad", 0.7853981633974483),
    ],
)
def test_reads_practical_units(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "unit"),
    [
        ("45 mm", "kg"),
        ("45 deg", "1"),
        ("__import__('os')", "m"),
        ("10**10**10 m", "m"),
        ("1 m" + " m" * 40, "m"),
        ("nan m", "m"),
        ("1e999 m", "m"),
        ("5 furlongs_per_fortnight", "m"),
        ("", "m"),
    ],
)
def test_refuses_bad_strings_quickly(text, unit):
    with pytest.raises(UnitError):
        to_si(text, unit)
