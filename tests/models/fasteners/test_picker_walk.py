"""Every entry of the form's thread picker computes in every model that offers the picker.

The picker (static/app.js, ``threadPicker``) is shown for a fieldset holding
``thread_diameter`` and ``thread_pitch``, with the threads of GET /api/v1/fasteners.
What it sends, written out here as the form does it: to a model with a ``thread``
input, the designation (and the grade the catalogue pairs with an inch thread), with
the numbers the designation sets cleared; to a model of numbers, the thread's
diameter and pitch and its default head's bearing face and clearance hole. The rest
of the request is the model's first example (what the form opens with).
"""

from __future__ import annotations

import math
from typing import Any

import pytest

from engine import run
from engine.core.spec import ModelSpec
from engine.models import MODELS
from engine.physics.fasteners import catalogue, metric_thread

#: Inputs the picker sets or clears.
PICKED = ("thread_diameter", "thread_pitch", "bearing_outer_diameter", "hole_diameter")

THREADS: list[dict[str, Any]] = catalogue()["threads"]


def _offers_picker(spec: ModelSpec) -> bool:
    groups = {p.name: p.group for p in spec.inputs}
    return (
        "thread_diameter" in groups
        and "thread_pitch" in groups
        and groups["thread_diameter"] == groups["thread_pitch"]
    )


PICKER_MODELS = [m for m in MODELS if _offers_picker(m)]


def form_request(spec: ModelSpec, entry: dict[str, Any]) -> dict[str, Any]:
    """The request the form sends after ``entry`` is picked on the first example."""
    x = {k: v for k, v in spec.examples[0].items() if k not in PICKED}
    names = {p.name for p in spec.inputs}
    if "thread" in names:
        x["thread"] = entry["designation"]
        if entry["grade"] is not None and "grade" in names:  # as app.js: only to a grade input
            x["grade"] = entry["grade"]
        return x
    x.update(
        thread_diameter=entry["diameter"],
        thread_pitch=entry["pitch"],
        bearing_outer_diameter=entry["bearing_diameter"],
        hole_diameter=entry["hole_diameter"],
    )
    return x


def test_the_picker_is_offered_by_the_models_that_take_a_thread() -> None:
    assert {m.name for m in PICKER_MODELS} >= {
        "joint.vdi2230",
        "preload.tightening",
        "preload.control",
        "blow.joint",
    }
    assert len(THREADS) == 95  # ISO M1.6…M64 coarse and fine, UNC/UNF 1/4…1-1/2


@pytest.mark.parametrize("spec", PICKER_MODELS, ids=lambda m: m.name)
def test_every_picker_entry_computes_a_finite_answer(spec: ModelSpec) -> None:
    refused: list[str] = []
    for entry in THREADS:
        x = form_request(spec, entry)
        try:
            r = run(spec, x)
        except ValueError as exc:  # EngineError is a ValueError
            refused.append(f"{entry['designation']}: {exc}")
            continue
        # a blow that yields a small bolt before the example's target reaches no target
        yields = r.results.get("bolt_verdict") not in (None, "elastic")
        nulls = [
            k for k, v in r.results.items() if v is None and not (yields and k == "blows_to_target")
        ]
        assert not nulls, (entry["designation"], nulls)
        for k, v in r.results.items():
            if isinstance(v, float):
                assert math.isfinite(v), (entry["designation"], k, v)
        if "thread" in x:
            assert r.inputs["thread"] == entry["designation"]
    assert refused == []


def test_an_inch_entry_carries_its_grade_and_the_default_parts() -> None:
    """1/2-13 UNC: SAE J429 grade 5, the ASME B18.2.1 hex cap screw's bearing face
    0.95 F = 0.95 × 3/4 in = 0.7125 in, the B18.2.8 normal hole 0.531 in."""
    entry = next(t for t in THREADS if t["designation"] == "1/2-13 UNC")
    assert entry["grade"] == "SAE 5"
    assert entry["bearing_diameter"] == pytest.approx(0.7125 * 0.0254, rel=1e-12)
    assert entry["hole_diameter"] == pytest.approx(0.531 * 0.0254, rel=1e-12)
    tightening = next(m for m in PICKER_MODELS if m.name == "preload.tightening")
    r = run(tightening, form_request(tightening, entry)).results
    # SAE J429 grade 5, 1/4…1 in: 92 ksi yield
    assert r["yield_strength"] == pytest.approx(92 * 6.894757293168e6, rel=1e-12)
    assert r["bearing_outer_diameter"] == pytest.approx(entry["bearing_diameter"], rel=1e-12)


def test_a_metric_entry_sends_what_the_designation_resolves_to() -> None:
    """For a model of numbers the picker sends what the designation gives a model of
    designations: M20's ISO 4017 d_w,min 28.19 mm and ISO 273 medium hole 22 mm."""
    entry = next(t for t in THREADS if t["designation"] == "M20")
    assert entry["grade"] is None
    assert entry["bearing_diameter"] == pytest.approx(28.19e-3, rel=1e-12)
    assert entry["hole_diameter"] == pytest.approx(22e-3, rel=1e-12)
    assert entry["pitch"] == metric_thread(20).pitch == pytest.approx(2.5e-3)


def test_beyond_m39_the_m39_strengths_are_taken_and_said() -> None:
    """ISO 898-1 stops at M39: 8.8 at M48 takes its M39 minimums (660/830 MPa, d > 16 mm),
    with a note; the torque is the VDI 2230 formula's on those numbers."""
    tightening = next(m for m in PICKER_MODELS if m.name == "preload.tightening")
    r = run(tightening, {"thread": "M48", "property_class": "8.8"})
    assert r.results["yield_strength"] == 660e6
    assert any("only up to M39" in n and "assumption" in n for n in r.notes)
    at_39 = run(tightening, {"thread": "M39", "property_class": "8.8"})
    assert at_39.results["yield_strength"] == 660e6
    assert not any("only up to M39" in n for n in at_39.notes)
    # M48: P = 5 mm, d2 = 48 − 0.649519·5 = 44.752405 mm, A_s = 1473 mm² (ISO 898-1 form)
    d2 = 48e-3 - 0.649519 * 5e-3
    d3 = 48e-3 - 1.226869 * 5e-3
    a_s = math.pi / 4 * ((d2 + d3) / 2) ** 2
    assert r.results["stress_area"] == pytest.approx(a_s, rel=1e-12)
    # ν = 0.9, β = sqrt(1 + 3 (3/2 · d2/d0 · (P/(π d2) + μ_G/cos 30°))²), d0 = (d2 + d3)/2
    d0 = (d2 + d3) / 2
    mu = 0.12 / math.cos(math.radians(30))
    beta = math.sqrt(1 + 3 * (1.5 * d2 / d0 * (5e-3 / (math.pi * d2) + mu)) ** 2)
    f_m = 0.9 * 660e6 * a_s / beta
    assert r.results["permissible_preload"] == pytest.approx(f_m, rel=1e-9)
