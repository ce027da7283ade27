"""The HTTP contract every model endpoint follows, shown on a toy model."""

import math

import pytest

from tests.toys import TOY


def test_healthz(toy):
    r = toy.get("/healthz")
    assert r.status_code == 200 and r.json() == {"status": "ok"}


def test_catalogue_lists_inputs_units_ranges_rungs(toy):
    (m,) = toy.get("/api/v1/models").json()["models"]
    assert m["path"] == "/toy/disc"
    d = next(p for p in m["inputs"] if p["name"] == "diameter")
    assert d["unit"] == "m" and d["minimum"] == 0.0 and d["exclusive_minimum"] is True
    assert d["display_unit"] == "mm" and d["required"] is True
    assert [r["name"] for r in m["rungs"]] == ["rough", "exact"]
    assert {o["name"]: o["unit"] for o in m["outputs"]}["energy"] == "J"
    assert toy.get("/api/v1/models/toy.disc").json()["name"] == "toy.disc"
    assert toy.get("/api/v1/models/nope").status_code == 404


def test_series_only_when_asked_for(toy):
    # issue 21: the default answer carries scalars, checks and notes, no series
    plain = toy.post("/api/v1/toy/disc", json={"diameter": "200 mm", "fidelity": "exact"}).json()
    assert plain["series"] == {} and "spin" not in plain["units"]
    assert plain["results"]["energy"] == pytest.approx(25.0)
    named = toy.post(
        "/api/v1/toy/disc", json={"diameter": "200 mm", "outputs": ["spin"], "fidelity": "exact"}
    ).json()
    assert named["series"] == {"spin": [0.0, 50.0, 100.0]} and named["results"] == {}
    bad = toy.post("/api/v1/toy/disc", json={"diameter": "200 mm", "series": "maybe"})
    assert bad.status_code == 422


def test_response_shape_and_values(toy):
    r = toy.post(
        "/api/v1/toy/disc", json={"diameter": "200 mm", "fidelity": "exact", "series": True}
    )
    assert r.status_code == 200, r.text
    body = r.json()
    assert set(body) == {
        "model",
        "results",
        "units",
        "rung",
        "error_estimate",
        "error_kind",
        "elapsed_s",
        "checks",
        "notes",
        "notes_parts",
        "warnings",
        "series",
        "inputs",
    }
    assert [p for ps in body["notes_parts"] for p in ps] == body["notes"]  # no quantities
    assert body["model"] == "toy.disc" and body["rung"] == "exact"
    assert body["error_estimate"] == 1e-15 and body["error_kind"] == "bound"
    assert body["results"]["energy"] == pytest.approx(25.0)
    assert body["units"]["energy"] == "J" and body["series"]["spin"] == [0.0, 50.0, 100.0]
    assert body["inputs"]["diameter"] == pytest.approx(0.2)


def test_unit_strings_equal_si_numbers(toy):
    a = toy.post("/api/v1/toy/disc", json={"diameter": 0.2, "speed": 1450 * math.pi / 30})
    b = toy.post("/api/v1/toy/disc", json={"diameter": "0.2 m", "speed": "1450 rpm"})
    assert a.json()["results"]["energy"] == pytest.approx(b.json()["results"]["energy"], rel=1e-12)


def test_outputs_limit_response(toy):
    r = toy.post("/api/v1/toy/disc", json={"diameter": 0.2, "outputs": ["inertia"]}).json()
    assert r["results"] == {"inertia": pytest.approx(0.005)} and r["series"] == {}


@pytest.mark.parametrize(
    ("body", "field", "fragment"),
    [
        ({"diameter": -0.1}, "diameter", "> 0 m"),
        ({"diameter": "45 kg"}, "diameter", "wrong dimension"),
        ({"diameter": 0.1, "angle": "95 deg"}, "angle", "< 1.5708 rad"),
        ({"diameter": 0.1, "count": 2.5}, "count", "integer"),
        ({"diameter": 0.1, "wheels": 3}, "wheels", "Extra inputs"),
        ({"diameter": 0.1, "fidelity": "magic"}, "fidelity", "auto"),
        ({"diameter": 0.1, "tolerance": 2}, "tolerance", "less than 1"),
        ({"diameter": 0.1, "outputs": ["torque"]}, "outputs.0", "energy"),
        ({"diameter": [1]}, "diameter", "number"),
        ({"diameter": True}, "diameter", "number"),
        ({}, "diameter", "required"),
    ],
)
def test_422_names_field_and_range(toy, body, field, fragment):
    r = toy.post("/api/v1/toy/disc", json=body)
    assert r.status_code == 422, r.text
    items = r.json()["detail"]
    match = [i for i in items if i["field"] == field]
    assert match, items
    assert fragment in match[0]["msg"], match[0]["msg"]


def test_nan_and_inf_in_json_refused(toy):
    for raw in ('{"diameter": NaN}', '{"diameter": Infinity}', '{"diameter": 1e308}'):
        r = toy.post("/api/v1/toy/disc", content=raw, headers={"content-type": "application/json"})
        assert r.status_code == 422, raw
        assert r.json()["detail"][0]["field"] == "diameter"


def test_infeasible_design_is_422_plain_message(toy):
    r = toy.post("/api/v1/toy/disc", json={"diameter": 0.1, "mode": "broken"})
    assert r.status_code == 422
    (item,) = r.json()["detail"]
    assert item["type"] == "infeasible_design" and "broken" in item["msg"]


def test_non_finite_output_is_null_never_nan(toy):
    r = toy.post("/api/v1/toy/disc", json={"diameter": 0.1, "blowup": True})
    assert r.status_code == 200
    assert r.json()["results"]["ratio"] is None
    assert "NaN" not in r.text and "Infinity" not in r.text


def test_sweep(toy):
    r = toy.post(
        "/api/v1/toy/disc/sweep",
        json={
            "base": {"diameter": 0.2},
            "vary": "speed",
            "start": "0 rpm",
            "stop": 100.0,
            "num": 3,
            "outputs": ["energy"],
            "fidelity": "exact",
        },
    )
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["values"] == pytest.approx([0.0, 50.0, 100.0])
    assert body["results"]["energy"] == pytest.approx([0.0, 6.25, 25.0])
    assert body["unit"] == "rad/s" and body["units"] == {"energy": "J"}


def test_sweep_without_base_uses_defaults(toy):
    r = toy.post(
        "/api/v1/toy/disc/sweep",
        json={"vary": "diameter", "start": 0.1, "stop": 0.2, "num": 2, "fidelity": "exact"},
    )
    assert r.status_code == 200, r.text
    assert r.json()["results"]["energy"] == pytest.approx(
        [0.5 * 0.01 / 8 * 1e4, 0.5 * 0.04 / 8 * 1e4]
    )


def test_sweep_bounds(toy):
    r = toy.post(
        "/api/v1/toy/disc/sweep",
        json={"base": {"diameter": 0.2}, "vary": "speed", "start": 0, "stop": 1, "num": 5000},
    )
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "num"
    r = toy.post(
        "/api/v1/toy/disc/sweep",
        json={"base": {"diameter": 0.2}, "vary": "speed", "start": 0, "stop": 1e9, "num": 3},
    )
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "speed"


def test_body_limit_413(toy):
    r = toy.post(
        "/api/v1/toy/disc",
        content=b"{" + b" " * 300_000 + b"}",
        headers={"content-type": "application/json"},
    )
    assert r.status_code == 413 and r.json()["detail"][0]["type"] == "body_too_large"


def test_openapi_and_static(toy):
    spec = toy.get("/openapi.json").json()
    assert "/api/v1/toy/disc" in spec["paths"] and "/api/v1/toy/disc/sweep" in spec["paths"]
    props = spec["components"]["schemas"]["ToyDiscRequest"]["properties"]
    assert props["diameter"]["x-unit"] == "m"
    assert props["diameter"]["anyOf"][0]["exclusiveMinimum"] == 0.0
    assert toy.get("/docs").status_code == 200
    page = toy.get("/")
    assert page.status_code == 200 and "<html" in page.text


def test_warm_up_runs_every_rung_of_the_first_example_and_swallows_refusals():
    from service.main import warm_up

    calls = []

    def compute(x, ctx):
        calls.append(ctx.rung)
        raise RuntimeError("a warm-up failure must not escape")

    import dataclasses

    broken = dataclasses.replace(TOY, compute=compute)
    warm_up([broken])
    assert calls == ["rough", "exact"]
