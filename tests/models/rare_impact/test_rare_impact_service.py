"""The rare-impact model over HTTP: registered, unit strings, verdicts as 422 not 500."""

import pytest


def test_listed_with_rungs_and_display_units(api):
    m = api.get("/api/v1/models/impact.rare").json()
    assert m["path"] == "/impact/rare"
    assert [r["name"] for r in m["rungs"]] == ["closed_form", "simulation"]
    units = {p["name"]: p["display_unit"] for p in m["inputs"]}
    assert units["cone_angle"] == "deg" and units["power_spring_rate"] == "N/mm"
    assert units["roller_mass"] == "g" and units["motor_no_load_speed"] == "rpm"


def test_unit_strings_give_the_reference_release_speed(api):
    r = api.post(
        "/api/v1/impact/rare",
        json={"cone_angle": "45 deg", "power_spring_rate": "50 N/mm", "roller_mass": "50 g",
              "roller_geometry": "paper", "fidelity": "closed_form"},
    )  # fmt: skip
    assert r.status_code == 200, r.text
    assert r.json()["results"]["release_speed"] == pytest.approx(236.0163, rel=1e-6)


def test_unknown_geometry_is_a_422_naming_the_choices(api):
    r = api.post("/api/v1/impact/rare", json={"roller_geometry": "double_cone"})
    assert r.status_code == 422
    assert "roller_geometry" in r.text and "symmetric_v" in r.text


def test_weak_motor_is_a_422_with_a_sentence(api):
    r = api.post("/api/v1/impact/rare", json={"motor_no_load_speed": "1000 rpm"})
    assert r.status_code == 422
    assert "never reaches the release speed" in r.text


def test_sweep_endpoint_runs_the_closed_form(api):
    r = api.post(
        "/api/v1/impact/rare/sweep",
        json={"base": {}, "vary": "cone_angle", "start": "10 deg", "stop": "80 deg", "num": 50,
              "fidelity": "closed_form", "outputs": ["release_speed", "full_engagement"]},
    )  # fmt: skip
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["rung"] == "closed_form" and len(body["results"]["release_speed"]) == 50
    assert all(v is None or v > 0 for v in body["results"]["release_speed"])


def test_engagement_window_placed_on_the_time_axis(api):
    from engine.models.rare_impact import REFERENCE_DESIGN

    body = api.post(
        "/api/v1/impact/rare", json={**REFERENCE_DESIGN, "fidelity": "simulation", "series": True}
    ).json()
    r = body["results"]
    # the window opens at release (end of stage 1) and lasts φ_eng/ω_M
    assert r["engagement_start"] == r["spin_up_time"]
    assert r["engagement_end"] - r["engagement_start"] == pytest.approx(r["engagement_window"])
    assert body["series"]["time"][0] <= r["engagement_start"] <= r["engagement_end"]


def test_array_sweep_refuses_the_points_the_scalar_model_refuses():
    import engine
    from engine.models.rare_impact import RARE_IMPACT, REFERENCE_DESIGN

    values = [1e-4, 10.0, 300.0]  # no-load speeds: the first two are below ω_M ≈ 236 rad/s
    wanted = ["release_speed", "full_engagement"]
    s = engine.sweep(
        RARE_IMPACT, REFERENCE_DESIGN, "motor_no_load_speed", values, outputs=wanted,
        fidelity="closed_form",
    )  # fmt: skip
    single = engine.run(
        RARE_IMPACT, {**REFERENCE_DESIGN, "motor_no_load_speed": 300.0}, fidelity="closed_form"
    )
    assert s.results["release_speed"][:2] == [None, None]
    assert s.results["full_engagement"][:2] == [None, None]
    assert s.results["release_speed"][2] == pytest.approx(single.results["release_speed"])
    for v in values[:2]:
        with pytest.raises(engine.InfeasibleDesign):
            engine.run(RARE_IMPACT, {**REFERENCE_DESIGN, "motor_no_load_speed": v},
                       fidelity="closed_form")  # fmt: skip
