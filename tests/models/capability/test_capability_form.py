"""The samples field in a real browser: pasted values under either decimal separator, a CSV
file, the unit chosen for the whole list, and a refusal that names the value."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import expect

from tests.e2e.test_browser import _open, _submit, base_url, browser, page  # noqa: F401

pytestmark = [pytest.mark.slow, pytest.mark.browser]

#: 1 lbf·ft in N·m
LBF_FT = 0.45359237 * 9.80665 * 0.3048


def _fresh(page: Any, base_url: str) -> None:  # noqa: F811
    _open(page, base_url, "m=tool.capability")
    page.select_option("#example", "defaults")
    page.fill("#in-nominal_torque", "10")


def test_pasted_values_with_a_decimal_comma(page: Any, base_url: str) -> None:  # noqa: F811
    _fresh(page, base_url)
    page.select_option("#decimal-sep", ",")
    page.fill("#in-torque_samples", "9,9; 10\n10,1")
    assert page.inner_text("#read-torque_samples") == "3 values read"
    assert _submit(page) == "ok"
    sent = page.evaluate("window.calcState.lastRequest")["torque_samples"]
    assert sent == {"values": [9.9, 10, 10.1], "unit": "N*m"}
    results = page.evaluate("window.calcState.lastResponse.results")
    assert math.isclose(results["mean_torque"], 10.0, rel_tol=1e-12)
    # with a decimal point, commas separate values too
    page.select_option("#decimal-sep", ".")
    page.fill("#in-torque_samples", "9.9, 10, 10.1")
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastRequest")["torque_samples"]["values"] == [
        9.9,
        10,
        10.1,
    ]


def test_a_value_in_lbf_ft_and_a_refused_value(page: Any, base_url: str) -> None:  # noqa: F811
    _fresh(page, base_url)
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-torque_samples", "lbf*ft")
    page.fill("#in-torque_samples", "7\n7.5\n7.25")
    page.fill("#in-nominal_torque", "7.25 lbf*ft")
    assert _submit(page) == "ok"
    results = page.evaluate("window.calcState.lastResponse.results")
    assert math.isclose(results["mean_torque"], 7.25 * LBF_FT, rel_tol=1e-9)
    page.fill("#in-torque_samples", "7\n-1\n7.25")
    message = page.inner_text("#err-torque_samples")
    assert "value 2" in message and "not allowed" in message, message
    page.fill("#in-torque_samples", "7\nabc")
    assert "value 2, “abc”" in page.inner_text("#err-torque_samples")
    assert _submit(page) == "error"


def test_a_csv_file_fills_the_field(page: Any, base_url: str, tmp_path: Path) -> None:  # noqa: F811
    _fresh(page, base_url)
    page.select_option("#decimal-sep", ".")
    csv = tmp_path / "run.csv"
    csv.write_text("torque,angle\n10.2,31\n9.8,30\n10.0,29\n", encoding="utf-8")
    page.set_input_files("#file-torque_samples", str(csv))
    # the file is read asynchronously: wait for the field (no string evaluation, which the
    # page's CSP refuses)
    expect(page.locator("#in-torque_samples")).to_have_value("10.2\n9.8\n10.0")
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastResponse.results")["sample_count"] == 3


def test_the_link_carries_the_list_and_its_unit(page: Any, base_url: str) -> None:  # noqa: F811
    _fresh(page, base_url)
    page.select_option("#decimal-sep", ",")
    page.select_option("#unit-torque_samples", "lbf*ft")
    page.fill("#in-torque_samples", "7\n7,5\n7,25")
    assert _submit(page) == "ok"
    first = page.evaluate("window.calcState.lastResponse.results")
    assert "torque_samples=7+7.5+7.25+lbf*ft" in page.url.replace("%20", "+"), page.url
    url = page.url
    page.goto("about:blank")
    page.goto(url)
    page.wait_for_selector("body[data-ready]")
    assert page.input_value("#in-torque_samples") == "7\n7,5\n7,25"
    assert page.eval_on_selector("#unit-torque_samples", "s => s.value") == "lbf*ft"
    assert _submit(page) == "ok"
    again = page.evaluate("window.calcState.lastResponse.results")
    assert again["mean_torque"] == first["mean_torque"]
