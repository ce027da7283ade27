"""The design-study page in the unit system chosen: a small grid study of
preload.tightening shows its statistics, its histogram's axis and its units in lbf·ft
when imperial is chosen (on the form's page: the setting is shared) and in N·m when
metric is, the values being the single runs' SI values converted by units.json's factor
and rounded by the shared formatter (4 significant digits, no float noise)."""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from playwright.sync_api import expect

import engine

from .test_browser import base_url, browser  # noqa: F401  (fixtures)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

MODEL = engine.get_model("preload.tightening")
UNITS = json.loads((Path(__file__).parents[2] / "static" / "units.json").read_text())
FRICTIONS = np.linspace(0.10, 0.16, 7)  # the grid the study runs: low, high, 7 points


def _factor(label: str) -> float:
    """The SI factor of a torque unit as units.json gives it (N·m 1, lbf·ft 1.3558…)."""
    return next(f for lab, _api, f in UNITS["N*m"] if lab == label)


def _torques(base: dict[str, Any]) -> np.ndarray:
    """The tightening torque of each grid point in N·m, by single runs of the model on the
    base design the page sent."""
    out = []
    for mu in FRICTIONS:
        point = {**base, "thread_friction": float(mu)}
        out.append(engine.run(MODEL, point).results["tightening_torque"])
    return np.asarray(out, dtype=float)


@pytest.fixture
def page(browser: Any, base_url: str) -> Iterator[Any]:  # noqa: F811
    context = browser.new_context(viewport={"width": 1400, "height": 900})
    context.set_default_timeout(30_000)
    problems: list[str] = []
    pg = context.new_page()
    pg.on("pageerror", lambda exc: problems.append(str(exc)))
    yield pg
    context.close()
    assert not problems, problems


def _run_study(pg: Any) -> dict[str, Any]:
    """Runs the grid study; returns the base design the page sent (values sent as today: SI)."""
    pg.select_option("#study-method", "grid")
    row = 'tr[data-name="thread_friction"]'
    pg.check(f"{row} input[type=checkbox]")
    pg.fill(f"{row} input[data-part=low]", "0.10")
    pg.fill(f"{row} input[data-part=high]", "0.16")
    pg.fill(f"{row} input[data-part=num]", "7")
    with pg.expect_request(lambda r: r.url.endswith("/study") and r.method == "POST") as sent:
        pg.click("#study-run")
    pg.wait_for_selector("#study-result:not([hidden])")
    body = sent.value.post_data_json
    assert body["variables"][0]["low"] == 0.1 and body["variables"][0]["high"] == 0.16
    return dict(body["base"])


def _torque_row(pg: Any) -> list[str]:
    cells = pg.locator('#study-stats tbody tr[data-name="tightening_torque"] td')
    return [t.strip() for t in cells.all_inner_texts()]


def _expect_row(cells: list[str], unit: str, torques: np.ndarray) -> None:
    shown = torques / _factor(unit)
    assert cells[0] == unit
    # mean, sd, 1 %, 50 %, 99 %, min, max: the mean, min and max as single runs give them
    mean, mn, mx = (cells[i] for i in (1, 6, 7))
    assert mean == f"{shown.mean():.4g}", (mean, shown.mean())
    assert mn == f"{shown.min():.4g}", (mn, shown.min())
    assert mx == f"{shown.max():.4g}", (mx, shown.max())
    for text in cells[1:]:
        # sensible digits: at most 4 significant, no float noise ("61.23", not "61.2345678")
        assert re.fullmatch(r"-?\d+(\.\d+)?", text), text
        assert len(text.replace("-", "").replace(".", "").lstrip("0")) <= 4, text


def test_the_study_reads_in_the_unit_system_chosen_on_the_form(page: Any, base_url: str) -> None:  # noqa: F811
    # imperial chosen on the form's page carries to the study page (one stored setting)
    page.goto(f"{base_url}/")
    page.wait_for_selector("body[data-ready='1']")
    page.select_option("#unit-system", "imperial")
    page.goto(f"{base_url}/study.html?model=preload.tightening")
    page.wait_for_selector("#study-rows tr")
    expect(page.locator("#unit-system")).to_have_value("imperial")
    # the inputs read in imperial too (0.012 m = 0.47244 in, to 5 digits), and are sent as
    # the exact SI value they were written from
    expect(page.locator("#in-thread_diameter")).to_have_value("0.47244 in")
    base = _run_study(page)
    assert base["thread_diameter"] == MODEL.examples[0]["thread_diameter"] == 0.012
    torques = _torques(base)
    assert 40 < torques.mean() < 120  # an M12 8.8 at μ 0.10…0.16: tens of N·m
    _expect_row(_torque_row(page), "lbf·ft", torques)
    # a preload reads in an imperial force unit too, never in N
    preload_unit = page.inner_text('#study-stats tbody tr[data-name="assembly_preload"] td.unit')
    assert preload_unit in ("lbf", "kip"), preload_unit
    page.select_option("#study-output", "tightening_torque")
    expect(page.locator("#study-hist")).to_have_attribute(
        "aria-label", "histogram of tightening torque [lbf·ft]"
    )
    # metric: the same study redrawn in N·m, the same values converted back
    page.select_option("#unit-system", "metric")
    _expect_row(_torque_row(page), "N·m", torques)
    expect(page.locator("#study-hist")).to_have_attribute(
        "aria-label", "histogram of tightening torque [N·m]"
    )
    assert page.inner_text('#study-stats tbody tr[data-name="assembly_preload"] td.unit') == "kN"
    expect(page.locator("#in-thread_diameter")).to_have_value("12 mm")
    # and the form reads the study's choice back
    page.goto(f"{base_url}/")
    page.wait_for_selector("body[data-ready='1']")
    expect(page.locator("#unit-system")).to_have_value("metric")
