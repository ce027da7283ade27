"""The real app: every registered model is listed and answers each of its examples."""

import math

import pytest

import engine


def test_catalogue_matches_registry(client):
    listed = client.get("/api/v1/models").json()["models"]
    assert [m["name"] for m in listed] == [s.name for s in engine.MODELS]
    assert len(listed) >= 6  # nutrunner, clutch x2, impact, preload x2
    for m in listed:
        assert m["examples"], f"{m['name']} has no example for the form and the bench"
        assert all(p["unit"] and p["description"] for p in m["inputs"])
    assert client.get("/healthz").json() == {"status": "ok"}


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_every_example_answers_with_finite_values(client, spec):
    for example in spec.examples:
        r = client.post("/api/v1" + spec.path, json=dict(example))
        assert r.status_code == 200, r.text
        body = r.json()
        assert body["model"] == spec.name and body["rung"] in spec.rung_names
        assert body["results"], "no result"
        for name, value in body["results"].items():
            assert value is None or not isinstance(value, float) or math.isfinite(value), name
            assert name in body["units"]
