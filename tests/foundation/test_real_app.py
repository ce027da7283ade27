"""The real app with every registered model answers the catalogue and each model's defaults."""

import engine


def test_catalogue_matches_registry(client):
    names = [m["name"] for m in client.get("/api/v1/models").json()["models"]]
    assert names == [s.name for s in engine.MODELS]
    assert client.get("/healthz").json() == {"status": "ok"}
