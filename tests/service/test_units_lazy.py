"""pint is loaded on the first unit string that needs it, never at start-up: a fresh
process builds the app, answers /readyz, the OpenAPI document, the catalogue and requests in
SI numbers without importing pint (nor dask, which pint imports); the first "200 mm" loads
it and reads the same number."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time

import pytest

from .servers import ROOT

SCRIPT = """
import json, sys
from fastapi.testclient import TestClient
from service import create_app
from tests.toys import TOY

seen = {}
with TestClient(create_app(models=[TOY])) as client:
    seen["started"] = "pint" in sys.modules
    pages = [client.get(p).status_code for p in ("/readyz", "/openapi.json", "/api/v1/models")]
    si = client.post("/api/v1/toy/disc", json={"diameter": 0.2})
    seen["unit_free"] = ["pint" in sys.modules, "dask" in sys.modules]
    unit = client.post("/api/v1/toy/disc", json={"diameter": "200 mm"})
    seen["unit_string"] = "pint" in sys.modules
    refused = client.post("/api/v1/toy/disc", json={"diameter": "5 kg"})
print(json.dumps({**seen, "pages": pages, "si": si.json(), "unit": unit.json(),
                  "refused": [refused.status_code, refused.json()["detail"][0]["field"]]}))
"""


def test_pint_is_loaded_by_the_first_unit_string_and_not_before() -> None:
    env = {**os.environ, "WARM_UP": "0", "PYTHONPATH": str(ROOT)}
    out = subprocess.run(
        [sys.executable, "-c", SCRIPT], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert out.returncode == 0, out.stderr[-2000:]
    seen = json.loads(out.stdout.strip().splitlines()[-1])
    assert seen["pages"] == [200, 200, 200]
    assert seen["started"] is False
    assert seen["unit_free"] == [False, False]
    assert seen["unit_string"] is True
    del seen["unit"]["elapsed_s"], seen["si"]["elapsed_s"]
    assert seen["unit"] == seen["si"]  # 200 mm is 0.2 m: the same answer
    assert seen["refused"] == [422, "diameter"]


def test_the_warm_up_builds_the_registry_once_it_says_ready(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The form sends unit strings: the warm-up builds the registry after it says ready, so
    /readyz does not wait for pint and the form's first request does not pay for it."""
    from service import units
    from service.main import WarmUp

    monkeypatch.setattr(units, "_REGISTRY", None)
    seen: list[bool] = []
    warm = WarmUp([], enabled=True)
    warm.start(after=lambda: seen.append(units._REGISTRY is None))
    assert warm.wait(30)
    for _ in range(3000):  # the registry comes after "done"
        if units._REGISTRY is not None:
            break
        time.sleep(0.01)
    assert seen == [True]  # not built before it was ready
    assert units._REGISTRY is not None
    assert units.registry().parse_units("mm") == units.registry().parse_units("millimeter")


def test_the_registry_waits_for_a_quiet_moment_after_ready(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Built at once after ready, pint's import took the processor from the first requests
    (a rare-impact simulation 11-16 ms against its steady 3-6 ms): while a request is open
    the registry waits; once none has been open for REGISTRY_QUIET_S it is built."""
    from service import main, units
    from service.main import WarmUp
    from service.middleware import QUIET

    monkeypatch.setattr(units, "_REGISTRY", None)
    monkeypatch.setattr(main, "REGISTRY_QUIET_S", 0.05)
    QUIET.begin()  # a request open
    try:
        warm = WarmUp([], enabled=True)
        warm.start()
        assert warm.wait(30)
        time.sleep(0.5)
        assert units._REGISTRY is None  # ready, but not quiet: not built
    finally:
        QUIET.end()
    for _ in range(3000):
        if units._REGISTRY is not None:
            break
        time.sleep(0.01)
    assert units._REGISTRY is not None
