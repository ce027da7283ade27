"""preload.ultrasonic: both directions by hand, the temperature correction, refusals.

M12 through 2 × 20 mm (all free thread), VDI 2230-1 R3 written out: head 0.5 d and nut
0.4 d at A_N, free thread 40 mm and engaged thread 0.5 d at A_d3, E = 210 GPa.
"""

from __future__ import annotations

import math

import pytest

from engine import InputOutOfRange, run
from engine.models.ultrasonic import M12_40KN, ULTRASONIC
from tests.pins import pin

E = 2.1e11
A_N = math.pi / 4 * 0.012**2
A_D3 = math.pi / 4 * (0.012 - 1.226869 * 1.75e-3) ** 2  # d3 = d − 1.226869 P (ISO 724)
DELTA_S = (0.5 * 0.012 + 0.4 * 0.012) / (E * A_N) + (0.040 + 0.5 * 0.012) / (E * A_D3)
A_S = math.pi / 4 * (0.012 - 0.9382 * 1.75e-3) ** 2  # ISO 898-1 stress area


def test_preload_to_elongation_and_time_of_flight_by_hand() -> None:
    r = run(ULTRASONIC, M12_40KN)
    v = r.results
    pin("preload.ultrasonic", "bolt_compliance", v["bolt_compliance"], DELTA_S, rel=1e-6)
    elong = 40e3 * DELTA_S
    pin("preload.ultrasonic", "elongation", v["elongation"], elong, rel=1e-6)
    pin(
        "preload.ultrasonic",
        "ultrasonic_length_change",
        v["ultrasonic_length_change"],
        elong / 0.3,
        rel=1e-6,
    )
    # round trip: twice the ultrasonic change over the velocity
    pin(
        "preload.ultrasonic",
        "time_of_flight_change",
        v["time_of_flight_change"],
        2 * elong / 0.3 / 5900.0,
        rel=1e-6,
    )
    pin("preload.ultrasonic", "thermal_length_change", v["thermal_length_change"], 0.0)
    pin("preload.ultrasonic", "preload", v["preload"], 40e3)
    pin("preload.ultrasonic", "bolt_stress", v["bolt_stress"], 40e3 / A_S, rel=1e-4)
    pin(
        "preload.ultrasonic",
        "effective_length",
        v["effective_length"],
        E * A_S * DELTA_S,
        rel=1e-4,
    )
    assert {c.name: c.ok for c in r.checks} == {"below_yield": True, "tension": True}


def test_a_reading_back_to_preload_with_the_temperature_taken_off() -> None:
    inputs = dict(ULTRASONIC.examples[1])
    v = run(ULTRASONIC, inputs).results
    # 100 ns round trip at 5900 m/s: 295 µm; the 3 K on 55 mm at 100e-6/K: 16.5 µm
    thermal = 100e-6 * 0.055 * 3.0
    change = 5900.0 * 100e-9 / 2 - thermal
    pin("preload.ultrasonic", "thermal_length_change", v["thermal_length_change"], thermal)
    pin("preload.ultrasonic", "ultrasonic_length_change", v["ultrasonic_length_change"], change)
    pin("preload.ultrasonic", "elongation", v["elongation"], 0.3 * change, rel=1e-12)
    pin("preload.ultrasonic", "preload", v["preload"], 0.3 * change / DELTA_S, rel=1e-6)
    pin("preload.ultrasonic", "time_of_flight_change", v["time_of_flight_change"], 100e-9)


def test_the_two_directions_are_inverses_with_a_temperature_change() -> None:
    base = {**M12_40KN, "temperature_factor": 90e-6, "reading_temperature_change": -4.0}
    base["ultrasonic_length"] = 0.06
    forward = run(ULTRASONIC, base).results
    back_in = {k: v for k, v in base.items() if k != "preload"}
    back = run(ULTRASONIC, {**back_in, "time_of_flight_change": forward["time_of_flight_change"]})
    pin("preload.ultrasonic", "preload", back.results["preload"], 40e3, rel=1e-12)


def test_a_measured_elongation_gives_the_preload_and_the_reading() -> None:
    inputs = {k: v for k, v in M12_40KN.items() if k != "preload"}
    v = run(ULTRASONIC, {**inputs, "elongation": 100e-6}).results
    pin("preload.ultrasonic", "preload", v["preload"], 100e-6 / DELTA_S, rel=1e-6)
    pin(
        "preload.ultrasonic",
        "time_of_flight_change",
        v["time_of_flight_change"],
        2 * 100e-6 / 0.3 / 5900.0,
        rel=1e-12,
    )


def test_refusals_name_the_field() -> None:
    with pytest.raises(InputOutOfRange) as err:
        run(ULTRASONIC, {**M12_40KN, "time_of_flight_change": 1e-7})
    assert err.value.field == "time_of_flight_change"
    bare = {k: v for k, v in M12_40KN.items() if k != "preload"}
    with pytest.raises(InputOutOfRange) as err:
        run(ULTRASONIC, bare)
    assert err.value.field == "preload"
    with pytest.raises(InputOutOfRange) as err:
        run(ULTRASONIC, {**M12_40KN, "temperature_factor": 1e-4, "reading_temperature_change": 2.0})
    assert err.value.field == "ultrasonic_length"


def test_past_yield_and_short_bolts_are_flagged() -> None:
    r = run(ULTRASONIC, {**M12_40KN, "preload": 60e3})  # 712 MPa > 640 MPa
    assert {c.name: c.ok for c in r.checks}["below_yield"] is False
    short = run(ULTRASONIC, {**M12_40KN, "plate1_thickness": 0.004, "plate2_thickness": 0.002})
    assert any("ASTM E1685" in w for w in short.warnings)
