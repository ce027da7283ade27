"""blow.joint's rare-impact source and impact.rare answer with one striker.

The blow takes its release speed and its energy from the striker model's own closed
form, so the two models agree on the same design in every roller geometry, for a
single run and on the array path (a sweep). The figures are also held to a hand
calculation of the reference design.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from engine import InfeasibleDesign, get_model, run, sweep
from engine.models.blow import _RI_NAMES, RARE_IMPACT_M16
from engine.models.rare_impact import REFERENCE_DESIGN

BLOW = get_model("blow.joint")
STRIKER = get_model("impact.rare")
GEOMETRIES = ("symmetric_v", "single_cone", "paper")


def _striker_design(geometry: str) -> dict[str, object]:
    """impact.rare's inputs for the striker of the blow's rare-impact example."""
    return {
        **REFERENCE_DESIGN,
        **{n: RARE_IMPACT_M16[n] for n in _RI_NAMES},
        "roller_geometry": geometry,
    }


def _rotating_energy(design: dict[str, object], speed: float, radius: float) -> float:
    """½·I·ω² of flywheel and rollers at release (the paper's geometry: the flywheel alone)."""
    i_m = float(design["flywheel_inertia"])  # type: ignore[arg-type]
    if design["roller_geometry"] != "paper":
        i_m += float(design["roller_count"]) * float(design["roller_mass"]) * radius**2  # type: ignore[arg-type]
    return 0.5 * i_m * speed * speed


@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("rung", ["rigid", "energy"])
def test_blow_and_striker_give_one_release_speed_and_energy(geometry, rung):
    striker = run(STRIKER, _striker_design(geometry), fidelity="closed_form")
    blow = run(BLOW, {**RARE_IMPACT_M16, "roller_geometry": geometry}, fidelity=rung)
    speed = striker.results["release_speed"]
    radius = striker.results["release_radius"]
    assert blow.results["tool_speed"] == pytest.approx(speed, rel=1e-12)
    energy = _rotating_energy(_striker_design(geometry), speed, radius)
    assert blow.results["tool_energy_used"] == pytest.approx(energy, rel=1e-12)
    assert blow.results["tool_inertia_used"] == pytest.approx(2.0 * energy / speed**2, rel=1e-12)


def test_the_reference_striker_by_hand():
    # symmetric V at 45°: κ = ½/tan α = 0.5, r = x0 + κ·h1 = 40 + 2.5 = 42.5 mm.
    # Springs at release: 5e4·(2 + 5) mm + 2e3·(8 + 5) mm = 350 + 26 = 376 N; the weight
    # the travel lifts (m1 + m2 + n·m_p·½)·g = (0.15 + 0.05 + 0.15)·9.80665 = 3.4323 N.
    # Push per ω² and per metre of radius n·m_p·κ = 0.15 kg:
    # ω_M = √(379.4323/(0.15·0.0425)) = √59518.8 = 243.965 rad/s.
    # I = 1e-3 + 6·0.05·0.0425² = 1.541875e-3 kg·m²; E = ½·I·ω_M² = 45.885 J.
    weight = (0.15 + 0.05 + 6 * 0.05 * 0.5) * 9.80665
    speed = math.sqrt((350.0 + 26.0 + weight) / (6 * 0.05 * 0.5 * 0.0425))
    inertia = 1e-3 + 6 * 0.05 * 0.0425**2
    blow = run(BLOW, RARE_IMPACT_M16, fidelity="energy")
    assert blow.results["tool_speed"] == pytest.approx(speed, rel=1e-12)
    assert blow.results["tool_inertia_used"] == pytest.approx(inertia, rel=1e-12)
    assert blow.results["tool_energy_used"] == pytest.approx(45.89, abs=0.005)
    assert blow.results["tool_energy_used"] == pytest.approx(0.5 * inertia * speed**2, rel=1e-12)
    # the blow efficiency scales the energy at the same inertia
    half = run(BLOW, {**RARE_IMPACT_M16, "blow_efficiency": 0.5}, fidelity="energy")
    assert half.results["tool_energy_used"] == pytest.approx(0.25 * inertia * speed**2, rel=1e-12)
    assert half.results["tool_speed"] == pytest.approx(speed / math.sqrt(2.0), rel=1e-12)


@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_a_sweep_of_the_springs_agrees_with_the_striker_point_by_point(geometry):
    rates = np.linspace(3e4, 8e4, 7)
    striker = sweep(
        STRIKER, _striker_design(geometry), "power_spring_rate", rates, fidelity="closed_form"
    )
    blow = sweep(
        BLOW,
        {**RARE_IMPACT_M16, "roller_geometry": geometry},
        "power_spring_rate",
        rates,
        fidelity="energy",
    )
    speed = np.asarray(striker.results["release_speed"], dtype=float)
    radius = np.asarray(striker.results["release_radius"], dtype=float)
    assert np.allclose(blow.results["tool_speed"], speed, rtol=1e-12, atol=0.0)
    energy = [
        _rotating_energy(_striker_design(geometry), w, r)
        for w, r in zip(speed, radius, strict=True)
    ]
    assert np.allclose(blow.results["tool_energy_used"], energy, rtol=1e-12, atol=0.0)
    # the single run of each point gives the same (the array path is no second striker)
    for j in (0, len(rates) - 1):
        alone = run(
            BLOW,
            {**RARE_IMPACT_M16, "roller_geometry": geometry, "power_spring_rate": rates[j]},
            fidelity="energy",
        )
        assert blow.results["tool_speed"][j] == pytest.approx(
            alone.results["tool_speed"], rel=1e-12
        )


def test_a_striker_the_striker_model_refuses_is_refused_by_the_blow():
    # gravity pointing up beats the preloads: impact.rare refuses (released at standstill)
    weak = {"power_spring_preload": 0.0, "auxiliary_spring_preload": 0.0, "gravity": -9.80665}
    with pytest.raises(InfeasibleDesign) as striker:
        run(STRIKER, {**_striker_design("symmetric_v"), **weak}, fidelity="closed_form")
    with pytest.raises(InfeasibleDesign) as blow:
        run(BLOW, {**RARE_IMPACT_M16, **weak}, fidelity="energy")
    assert blow.value.field == striker.value.field == "power_spring_preload"
    # in a sweep the refused point is null and the others are answered
    swept = sweep(BLOW, {**RARE_IMPACT_M16, "gravity": -9.80665, "auxiliary_spring_preload": 0.0},
                  "power_spring_preload", np.array([0.0, 0.002]), fidelity="energy")  # fmt: skip
    assert swept.results["tool_speed"][0] is None
    assert swept.results["tool_speed"][1] is not None


@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_a_sweep_of_gravity_refuses_where_single_runs_refuse(geometry):
    # pointing up, gravity beats the preloads (impact.rare refuses): null in the sweep,
    # refused alone; elsewhere the sweep's speed and energy are the single runs'
    # c1·λ1 = 5e4·0.2 mm = 10 N holds the 0.2 kg (plus the rollers' share) up to g ≈ −29
    base = {
        **RARE_IMPACT_M16,
        "roller_geometry": geometry,
        "power_spring_preload": 0.0002,
        "auxiliary_spring_preload": 0.0,
    }
    values = np.linspace(-100.0, 100.0, 9)
    swept = sweep(BLOW, base, "gravity", values, fidelity="energy")
    refused = 0
    for j, g in enumerate(values):
        try:
            alone = run(BLOW, {**base, "gravity": g}, fidelity="energy")
        except InfeasibleDesign:
            refused += 1
            assert swept.results["tool_speed"][j] is None
            continue
        for name in ("tool_speed", "tool_energy_used", "final_preload"):
            assert swept.results[name][j] == pytest.approx(alone.results[name], rel=1e-12)
    # the paper's stage 1 has no weight: nothing is refused; else g = −100, −75, −50
    assert refused == (0 if geometry == "paper" else 3)
