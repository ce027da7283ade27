"""A temperature change is a difference: 3 degC of warming is 3 K, never 276.15 K.

An offset unit (degC, degF) given for a change is refused with a 422 that names the field
and the units to use; kelvin and the pint difference units delta_degC / delta_degF convert
without an offset. An absolute temperature still converts with its offset.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from engine import Param, get_model
from service import create_app
from service.studies import StudySettings
from service.units import UnitError, is_temperature_change, quantity, to_si

JOINT = get_model("joint.vdi2230")
EXAMPLE = dict(JOINT.examples[0])


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    app = create_app(models=[JOINT], study_settings=StudySettings(inprocess_points=1000))
    with TestClient(app) as c:
        yield c


@pytest.mark.parametrize(
    ("text", "kelvin"),
    [
        ("3 K", 3.0),
        ("3 kelvin", 3.0),
        ("3 delta_degC", 3.0),
        ("-20 delta_degC", -20.0),
        ("9 delta_degF", 5.0),  # 9 °F of change = 9 × 5/9 K
        ("1 delta_degF", 5.0 / 9.0),
        ("500 mK", 0.5),
    ],
)
def test_a_change_reads_kelvin_and_difference_units_without_an_offset(
    text: str, kelvin: float
) -> None:
    assert to_si(text, "K", difference=True) == pytest.approx(kelvin, rel=1e-12)


@pytest.mark.parametrize("text", ["3 degC", "1 degF", "3 °C", "1 °F", "3 celsius", "5 degreeC"])
def test_an_offset_unit_is_refused_for_a_change(text: str) -> None:
    with pytest.raises(UnitError, match="delta_degC or delta_degF"):
        to_si(text, "K", difference=True)


@pytest.mark.parametrize(
    ("text", "kelvin"),
    [
        ("20 degC", 293.15),
        ("20 °C", 293.15),
        ("68 degF", 293.15),  # (68 − 32) × 5/9 + 273.15
        ("-40 degF", 233.15),  # −40 °F = −40 °C
        ("300 K", 300.0),
    ],
)
def test_an_absolute_temperature_keeps_its_offset(text: str, kelvin: float) -> None:
    assert to_si(text, "K") == pytest.approx(kelvin, rel=1e-12)


def test_the_joint_declares_its_temperature_changes() -> None:
    changes = {p.name for p in JOINT.inputs if is_temperature_change(p)}
    assert changes == {"temperature_change", "plate_temperature_change"}
    absolute = Param("service_temperature", "K", "Temperature of the joint in service")
    assert not is_temperature_change(absolute)
    assert quantity(absolute, "20 degC", "low", "variables") == pytest.approx(293.15)


@pytest.mark.parametrize("unit", ["degC", "degF"])
def test_a_design_refuses_an_offset_unit_for_a_change_naming_the_field(
    client: TestClient, unit: str
) -> None:
    r = client.post(JOINT_URL, json={**EXAMPLE, "temperature_change": f"3 {unit}"})
    assert r.status_code == 422, r.text
    (item,) = r.json()["detail"]
    assert item["field"] == "temperature_change"
    assert "temperature_change" in item["msg"]
    assert "K, delta_degC or delta_degF" in item["msg"]
    assert f"e.g. '3 delta_{unit}'" in item["msg"]


def test_a_design_reads_a_change_in_delta_units_as_kelvin(client: TestClient) -> None:
    # the bolt warms, the plates do not: ΔT_S ≠ ΔT_P costs preload
    design = {**EXAMPLE, "plate_temperature_change": 0.0}
    kelvin = client.post(JOINT_URL, json={**design, "temperature_change": 50.0})
    celsius = client.post(JOINT_URL, json={**design, "temperature_change": "50 delta_degC"})
    fahrenheit = client.post(JOINT_URL, json={**design, "temperature_change": "90 delta_degF"})
    assert kelvin.status_code == celsius.status_code == fahrenheit.status_code == 200
    loss = kelvin.json()["results"]["thermal_loss"]
    assert abs(loss) > 100.0  # newtons: the comparison below means something
    assert celsius.json()["inputs"]["temperature_change"] == pytest.approx(50.0, rel=1e-12)
    assert fahrenheit.json()["inputs"]["temperature_change"] == pytest.approx(50.0, rel=1e-12)
    assert celsius.json()["results"]["thermal_loss"] == pytest.approx(loss, rel=1e-12)
    assert fahrenheit.json()["results"]["thermal_loss"] == pytest.approx(loss, rel=1e-12)


def test_a_sweep_end_and_a_study_law_refuse_an_offset_unit_for_a_change(client: TestClient) -> None:
    sweep = client.post(
        JOINT_URL + "/sweep",
        json={"base": EXAMPLE, "vary": "temperature_change", "start": 0, "stop": "3 degC"},
    )
    assert sweep.status_code == 422, sweep.text
    (item,) = sweep.json()["detail"]
    assert item["field"] == "stop" and "delta_degC" in item["msg"]
    study = client.post(
        JOINT_URL + "/study",
        json={
            "base": EXAMPLE,
            "variables": [{"name": "temperature_change", "low": "1 degF", "high": 50}],
        },
    )
    assert study.status_code == 422, study.text
    (item,) = study.json()["detail"]
    assert item["field"] == "variables" and "delta_degF" in item["msg"]
    base = client.post(
        JOINT_URL + "/study",
        json={
            "base": {**EXAMPLE, "plate_temperature_change": "3 degC"},
            "variables": [{"name": "working_load", "low": 1000, "high": 8000}],
        },
    )
    assert base.status_code == 422, base.text
    (item,) = base.json()["detail"]
    assert item["field"] == "plate_temperature_change" and "delta_degC" in item["msg"]


def test_the_schema_says_which_units_a_change_takes(client: TestClient) -> None:
    schema = client.get("/openapi.json").json()["components"]["schemas"]
    texts = [
        alt.get("description", "")
        for model in schema.values()
        for name, prop in model.get("properties", {}).items()
        if name == "temperature_change"
        for alt in prop.get("anyOf", [])
    ]
    assert any("delta_degC" in t for t in texts)


JOINT_URL = "/api/v1" + JOINT.path
