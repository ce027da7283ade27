"""The design-study page in Chromium: a grid study of the striker run from the form, with a
progress bar, a map with the feasible region, a histogram and statistics; a Monte Carlo that
is cancelled; no horizontal scroll on a 390 px phone. Uses the browser and server fixtures of
the form's browser test."""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

import pytest
from playwright.sync_api import expect

import engine

from .test_browser import base_url, browser  # noqa: F401  (fixtures)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

RARE = engine.get_model("impact.rare")


@pytest.fixture(params=[(1400, 900), (390, 844)], ids=["desktop", "phone"])
def study_page(request: Any, browser: Any, base_url: str) -> Iterator[Any]:  # noqa: F811
    width, height = request.param
    context = browser.new_context(viewport={"width": width, "height": height})
    context.set_default_timeout(30_000)
    problems: list[str] = []
    pg = context.new_page()
    pg.on("pageerror", lambda exc: problems.append(str(exc)))
    pg.goto(f"{base_url}/study.html?model=impact.rare")
    pg.wait_for_selector("#study-rows tr")
    yield pg
    context.close()
    assert not problems, problems


def _vary(pg: Any, name: str, **parts: str) -> None:
    pg.check(f'tr[data-name="{name}"] input[type=checkbox]')
    for part, value in parts.items():
        pg.fill(f'tr[data-name="{name}"] input[data-part={part}]', value)


def test_a_grid_study_draws_its_map_and_statistics(study_page: Any) -> None:
    pg = study_page
    pg.select_option("#study-method", "grid")
    _vary(pg, "power_spring_rate", low="25000", high="100000", num="12")
    _vary(pg, "power_spring_preload", low="1 mm", high="6 mm", num="10")
    pg.select_option("#study-feasible", "full_engagement")
    pg.click("#study-run")
    pg.wait_for_selector("#study-result:not([hidden])")
    meta = pg.inner_text("#study-meta")
    assert "120 designs (grid)" in meta
    assert pg.eval_on_selector("#study-progress", "p => p.value") == 1
    assert pg.is_visible("#study-map")
    # the map's feasible fraction equals single runs over the same grid
    ex = dict(RARE.examples[0])
    ok = 0
    for c1 in [25000 + i * 75000 / 11 for i in range(12)]:
        for lam in [0.001 + j * 0.005 / 9 for j in range(10)]:
            point = {**ex, "power_spring_rate": c1, "power_spring_preload": lam}
            ok += bool(engine.run(RARE, point).results["full_engagement"])
    assert f"{100 * ok / 120:.1f} %" in meta
    rows = pg.locator("#study-stats tbody tr").count()
    assert rows >= 5
    assert pg.evaluate("document.documentElement.scrollWidth") <= pg.viewport_size["width"]


def test_a_study_can_be_cancelled_from_the_form(study_page: Any) -> None:
    pg = study_page
    pg.select_option("#study-method", "monte_carlo")
    pg.select_option("#study-fidelity", "simulation")
    pg.fill("#study-samples", "200000")
    _vary(pg, "motor_torque", low="4.5", high="5.5")
    pg.click("#study-run")
    pg.wait_for_selector("#study-cancel:not([disabled])")
    pg.click("#study-cancel")
    # the cancel is answered once the job's cluster is up: starting Dask on a loaded
    # machine took over the default 5 s once (the cancel itself is timed in bench)
    expect(pg.locator("#study-status")).to_have_text(re.compile("^cancelled"), timeout=30_000)
    assert pg.is_hidden("#study-result")
