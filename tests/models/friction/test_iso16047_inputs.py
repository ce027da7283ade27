"""friction.iso16047: the geometry it takes, the series it returns, what it refuses."""

from __future__ import annotations

import math

import pytest
from fastapi.testclient import TestClient

from engine import InputOutOfRange, get_model, run

MODEL = "friction.iso16047"
THREE = {
    "tightening_torques": [40.0, 41.0, 39.0],
    "thread_torques": [17.0, 18.0, 16.5],
    "clamp_forces": [20e3, 20.5e3, 19.5e3],
}


def test_numbers_instead_of_a_designation() -> None:
    """d = 12 mm with its ISO 261 coarse pitch 1.75 mm; d2 = 12 − 0.649519·1.75 = 10.8634 mm."""
    r = run(get_model(MODEL), {**THREE, "thread_diameter": 0.012, "bearing_diameter": 0.0155})
    assert r.results["thread_pitch"] == pytest.approx(0.00175)
    assert r.results["pitch_diameter"] == pytest.approx(0.012 - 0.649519 * 0.00175, rel=1e-6)
    assert r.results["bearing_diameter"] == 0.0155


def test_a_fine_pitch_off_the_catalogue_takes_iso_68_1() -> None:
    r = run(
        get_model(MODEL),
        {
            **THREE,
            "thread_diameter": 0.0123,
            "thread_pitch": 0.0011,
            "bearing_outer_diameter": 0.018,
            "hole_diameter": 0.013,
        },
    )
    assert r.results["pitch_diameter"] == pytest.approx(0.0123 - 0.649519 * 0.0011, rel=1e-6)
    assert r.results["bearing_diameter"] == pytest.approx(0.0155, rel=1e-12)
    assert any("ISO 68-1" in n for n in r.notes)


def test_per_test_series_for_the_plot() -> None:
    r = run(get_model(MODEL), {**THREE, "thread": "M10"}, series=True)
    assert r.series["test_number"] == [1.0, 2.0, 3.0]
    k = [
        t / (f * 0.010)
        for t, f in zip(THREE["tightening_torques"], THREE["clamp_forces"], strict=True)
    ]
    assert r.series["torque_coefficient"] == pytest.approx(k, rel=1e-12)
    assert len(r.series["thread_friction"]) == 3


def test_a_thread_torque_below_the_pitch_share_fails_its_check() -> None:
    """F P/(2π) = 20 kN · 1.5 mm/(2π) = 4.77 N·m: a thread torque of 4 N·m gives μ_th < 0."""
    inputs = {**THREE, "thread": "M10", "thread_torques": [17.0, 4.0, 16.5]}
    r = run(get_model(MODEL), inputs)
    check = next(c for c in r.checks if c.name == "positive_friction")
    assert not check.ok and "thread friction" in check.detail
    low = r.results["thread_friction_min"]
    assert isinstance(low, float) and low < 0


@pytest.mark.parametrize(
    ("change", "field", "fragment"),
    [
        (
            {"thread_torques": [17.0, 18.0]},
            "thread_torques",
            "has 2 values where tightening_torques has 3",
        ),
        ({"clamp_forces": [20e3, 0.0, 19e3]}, "clamp_forces", "clamp_forces[1] = 0 N"),
        ({"thread_torques": [17.0, 42.0, 16.5]}, "thread_torques", "thread_torques[1] = 42 N*m"),
        ({"thread": None, "thread_diameter": 0.012}, "bearing_diameter", "give bearing_diameter"),
        ({"thread": None}, "thread", "give thread"),
        ({"hole_diameter": 0.02}, "hole_diameter", "below the bearing face"),
        ({"pitch_diameter": 0.011}, "pitch_diameter", "between 0 and the thread diameter"),
        ({"thread": "M10x7"}, "thread", ""),
    ],
)
def test_refusals_name_the_field(change: dict, field: str, fragment: str) -> None:
    inputs = {**THREE, "thread": "M10", **change}
    inputs = {k: v for k, v in inputs.items() if v is not None}
    with pytest.raises(InputOutOfRange) as info:
        run(get_model(MODEL), inputs)
    assert info.value.field == field
    assert fragment in info.value.message


def test_forces_in_kn_through_the_api(client: TestClient) -> None:
    r = client.post(
        "/api/v1/friction/iso16047",
        json={
            "thread": "M10",
            "tightening_torques": THREE["tightening_torques"],
            "thread_torques": THREE["thread_torques"],
            "clamp_forces": {"values": [20, 20.5, 19.5], "unit": "kN"},
        },
    )
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["inputs"]["clamp_forces"] == [20e3, 20.5e3, 19.5e3]
    k = 40.0 / (20e3 * 0.010)
    assert math.isclose(
        body["results"]["torque_coefficient_min"], min(k, 41 / 205, 39 / 195), rel_tol=1e-12
    )


def test_a_countersunk_head_says_how_its_cone_friction_relates() -> None:
    """ISO 10642 M6: d_k,min 11.34 mm, ISO 273 medium hole 6.6 mm: D_b = 8.97 mm; μ_b is the
    flat-face value, and the note gives the cone's as μ_b sin 45° (not the preload models'
    ×1/sin 45° note, which would claim a correction this evaluation does not make)."""
    r = run(
        get_model(MODEL),
        {
            "thread": "M6 ISO 10642 10.9",
            "tightening_torques": [10.0, 11.0],
            "thread_torques": [4.0, 4.5],
            "clamp_forces": [8e3, 8.5e3],
        },
    )
    assert r.results["bearing_diameter"] == pytest.approx((0.01134 + 0.0066) / 2, rel=1e-9)
    assert any("μ_b × 0.707" in n for n in r.notes)
    assert not any("×1/sin 45°" in n for n in r.notes)
