"""GET /api/v1/fasteners and designation inputs over HTTP (issue 15)."""

from __future__ import annotations


def test_catalogue_route_shape(client):
    r = client.get("/api/v1/fasteners")
    assert r.status_code == 200
    body = r.json()
    assert set(body) == {"threads", "property_classes", "heads", "nuts", "washers", "materials"}
    m10 = next(t for t in body["threads"] if t["designation"] == "M10")
    assert m10["diameter"] == 0.01 and m10["pitch"] == 0.0015 and m10["series"] == "ISO coarse"
    assert {"name", "yield_strength", "tensile_strength", "standard"} <= set(
        body["property_classes"][0]
    )
    assert {"name", "limiting_surface_pressure", "shear_strength"} <= set(body["materials"][0])


def test_a_designation_over_http(client):
    r = client.post("/api/v1/preload/tightening", json={"thread": "M10 ISO 4762 12.9"})
    assert r.status_code == 200, r.text
    assert r.json()["results"]["fastener"] == "M10 ISO 4762 12.9"
    assert r.json()["inputs"]["thread"] == "M10 ISO 4762 12.9"
    r = client.post(
        "/api/v1/preload/control",
        json={"thread": "1/2-13 UNC", "grade": "SAE 5", "required_clamp_force": "15 kN"},
    )
    assert r.status_code == 200, r.text


def test_bad_designations_are_422_naming_the_field(client):
    for body, field in (
        ({"thread": "M13"}, "thread"),
        ({"thread": 12}, "thread"),
        ({"thread": "M" + "1" * 100}, "thread"),
        ({"thread": ""}, "thread"),
        ({"thread": "M12", "grade": "14.9"}, "grade"),
    ):
        r = client.post("/api/v1/preload/tightening", json=body)
        assert r.status_code == 422, (body, r.text)
        assert any(d.get("field") == field for d in r.json()["detail"]), r.text


def test_the_catalogue_describes_the_text_inputs(client):
    models = client.get("/api/v1/models").json()["models"]
    spec = next(m for m in models if m["name"] == "preload.tightening")
    thread = next(p for p in spec["inputs"] if p["name"] == "thread")
    assert thread["kind"] == "text" and "M10 ISO 4762 12.9" in thread["choices"]
    schema = client.get("/openapi.json").json()
    assert "fasteners" in str(schema["paths"].keys())


def test_a_sweep_over_friction_with_a_designation_in_the_base(client):
    r = client.post(
        "/api/v1/preload/tightening/sweep",
        json={
            "base": {"thread": "M8 ISO 4762 12.9", "internal_thread_material": "EN AW-6082 T6"},
            "vary": "thread_friction",
            "start": 0.08,
            "stop": 0.2,
            "num": 5,
            "outputs": ["tightening_torque", "min_engagement_length"],
        },
    )
    assert r.status_code == 200, r.text
    body = r.json()
    torques = body["results"]["tightening_torque"]
    assert all(t is not None for t in torques) and torques == sorted(torques)
    # the engagement the tapped hole needs does not depend on the friction
    lengths = body["results"]["min_engagement_length"]
    assert max(lengths) == min(lengths) and lengths[0] > 0.01
