"""trace.analysis through the API: angles in degrees, and the refusals naming the field."""

from __future__ import annotations

import math

from fastapi.testclient import TestClient

from engine.models.trace import ANALYSIS, M12_JOINT

URL = "/api/v1/trace/analysis"
EXAMPLE = dict(ANALYSIS.examples[0])


def test_angles_in_degrees_give_the_rate_of_radians(client: TestClient) -> None:
    si = client.post(URL, json=EXAMPLE)
    assert si.status_code == 200, si.text
    degrees = [a * 180.0 / math.pi for a in EXAMPLE["angle"]]
    deg = client.post(URL, json={**EXAMPLE, "angle": {"values": degrees, "unit": "deg"}})
    assert deg.status_code == 200, deg.text
    rate_si, rate_deg = si.json()["results"]["elastic_rate"], deg.json()["results"]["elastic_rate"]
    assert math.isclose(rate_si, rate_deg, rel_tol=1e-9)
    assert math.isclose(rate_si * math.pi / 180.0, 2.351, rel_tol=0.002)  # the example's N·m/°


def test_a_trace_that_cannot_be_read_is_a_422_naming_the_field(client: TestClient) -> None:
    angle = list(EXAMPLE["angle"])
    short = client.post(URL, json={**M12_JOINT, "angle": angle[:10], "torque": angle[:10]})
    assert short.status_code == 422 and short.json()["detail"][0]["field"] == "angle"
    uneven = client.post(URL, json={**EXAMPLE, "torque": list(EXAMPLE["torque"])[:-1]})
    assert uneven.status_code == 422 and uneven.json()["detail"][0]["field"] == "torque"
    back = list(angle)
    back[250] -= 0.1
    backwards = client.post(URL, json={**EXAMPLE, "angle": back})
    assert backwards.status_code == 422
    assert backwards.json()["detail"][0]["field"] == "angle"
    assert "runs backwards" in backwards.json()["detail"][0]["msg"]
