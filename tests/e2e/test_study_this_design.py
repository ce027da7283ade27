""" "Study this design", in a real browser (issue 31): the form's design, with its units,
opens the study page as the study's base, and the study page checks that base with one
run of the model before any point runs, saying at once when the model refuses it."""

from __future__ import annotations

from typing import Any

import pytest
from playwright.sync_api import expect

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    REAL,
    _open,
    base_url,
    browser,
    page,
)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

JOINT = "joint.vdi2230"


@pytest.fixture(autouse=True)
def _joint_registered() -> None:
    if JOINT not in [s.name for s in REAL]:
        pytest.skip(f"{JOINT} is not registered")


def test_study_this_design_carries_the_form_with_units_and_checks_the_base(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-system", "imperial")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    page.fill("#in-working_load", "2,000")  # 2000 lbf, as the form reads it
    page.click("#study-design")
    expect(page).to_have_url(f"{base_url}/study.html?model={JOINT}&from=form")
    expect(page.locator("body[data-base-check]")).to_have_attribute("data-base-check", "ok")
    assert page.input_value("#study-model") == JOINT
    # the form's number in its unit, not the example's value in SI
    assert page.input_value("#in-working_load") == "2000 lbf"
    assert page.inner_text("#study-status") == "Base design checked: the model computes it."
    assert page.inner_text("#study-error") == ""
    # the base's single check went to the model's endpoint with the carried design
    seen: list[Any] = []
    page.on(
        "request", lambda r: seen.append((r.url, r.post_data_json)) if r.method == "POST" else None
    )
    page.check('tr[data-name="working_load"] input[type=checkbox]')
    page.click("#study-run")
    expect(page.locator("#study-result")).to_be_visible(timeout=30_000)
    urls = [u for u, _ in seen]
    assert urls[0].endswith("/api/v1/joint/vdi2230"), urls
    assert urls[1].endswith("/api/v1/joint/vdi2230/study"), urls
    assert seen[0][1]["working_load"] == "2000 lbf"
    assert seen[1][1]["base"]["transverse_load"] == seen[0][1]["transverse_load"]


def test_a_base_the_model_refuses_is_said_at_once_naming_the_field(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-system", "metric")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    page.fill("#in-thread_diameter", "-12")  # refused by the model: a diameter > 0
    page.click("#study-design")
    expect(page.locator("body[data-base-check]")).to_have_attribute("data-base-check", "refused")
    error = page.inner_text("#study-error")
    assert error.startswith("The base design is refused by the model: thread_diameter"), error
    # Run study checks the base again and submits nothing
    seen: list[str] = []
    page.on("request", lambda r: seen.append(r.url) if r.method == "POST" else None)
    page.check('tr[data-name="working_load"] input[type=checkbox]')
    page.evaluate("delete document.body.dataset.baseCheck")
    page.click("#study-run")
    expect(page.locator("body[data-base-check]")).to_have_attribute("data-base-check", "refused")
    expect(page.locator("#study-run")).to_be_enabled()
    assert [u for u in seen if u.endswith("/study")] == []
    assert page.locator("#study-result").is_hidden()
