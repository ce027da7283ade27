"""The study page offers the lognormal law and rank correlations between varied inputs
(issue 34: the API took both, the page neither), in Chromium against a live server."""

from __future__ import annotations

import json
from typing import Any

import httpx
import pytest
from playwright.sync_api import expect

from .test_browser import base_url, browser, page  # noqa: F401  (fixtures)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

MODEL = "preload.tightening"


def _vary(pg: Any, name: str, law: str, **parts: str) -> None:
    row = f'tr[data-name="{name}"]'
    pg.check(f"{row} input[type=checkbox]")
    pg.select_option(f"{row} select[data-part=distribution]", law)
    for part, value in parts.items():
        pg.fill(f"{row} input[data-part={part}]", value)


def test_a_lognormal_law_and_a_correlation_go_to_the_study(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    pg = page
    pg.goto(f"{base_url}/study.html?model={MODEL}")
    pg.wait_for_selector("#study-rows tr")
    box = pg.locator("#study-correlations")
    expect(box).to_be_visible()  # Monte Carlo takes correlations
    expect(pg.locator("#study-add-pair")).to_be_disabled()  # nothing varied yet
    _vary(pg, "thread_friction", "lognormal", mean="0.12", sd="0.015")
    row = 'tr[data-name="thread_friction"]'
    expect(pg.locator(f"{row} input[data-part=mean]")).to_be_visible()
    expect(pg.locator(f"{row} input[data-part=low]")).to_be_hidden()
    _vary(pg, "bearing_friction", "uniform", low="0.1", high="0.16")
    pg.click("#study-add-pair")
    pair = pg.locator("#study-pairs li")
    expect(pair.locator("select[data-part=a]")).to_have_value("thread_friction")
    expect(pair.locator("select[data-part=b]")).to_have_value("bearing_friction")
    pair.locator("input").fill("0.8")
    pg.fill("#study-samples", "500")
    with pg.expect_request(lambda r: r.url.endswith("/study") and r.method == "POST") as sent:
        pg.click("#study-run")
    body = json.loads(sent.value.post_data)
    laws = {v["name"]: v for v in body["variables"]}
    assert laws["thread_friction"] == {
        "name": "thread_friction",
        "distribution": "lognormal",
        "mean": 0.12,
        "sd": 0.015,
    }
    assert body["correlations"] == [
        {"a": "thread_friction", "b": "bearing_friction", "rank_correlation": 0.8}
    ]
    pg.wait_for_selector("#study-result:not([hidden])")
    expect(pg.locator("#study-notes")).to_contain_text("Gaussian copula")
    # the page's study is the API's: the same body gives the same summary
    with httpx.Client(base_url=base_url, timeout=60) as api:
        job = api.post(f"/api/v1/{MODEL.replace('.', '/')}/study", json=body).json()
        while job["state"] in ("queued", "running"):
            job = api.get(job["links"]["self"]).json()
    shown = pg.inner_text("#study-meta")
    assert f"{job['result']['points']:,} designs (monte carlo)" in shown
    # a grid takes no correlations: the box goes, and nothing of it is sent
    pg.select_option("#study-method", "grid")
    expect(box).to_be_hidden()
