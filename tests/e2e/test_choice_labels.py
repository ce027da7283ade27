"""Readable choices in a real browser (issue 31): no raw key ("iso5393_hard", "fixed_free")
is shown in a choice list of the form or of the study page; the value sent stays the key."""

from __future__ import annotations

from typing import Any

import pytest

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    REAL,
    _open,
    base_url,
    browser,
    page,
)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

NAMES = {s.name for s in REAL}
RAW_KEY = r"^[a-z][a-z0-9]*(_[a-z0-9]+)+$"  # lowercase words joined by "_"

# (model, input, key, the name shown)
CASES = [
    ("blow.joint", "joint_rate_from", "iso5393_hard", "ISO 5393 hard joint"),
    ("blow.joint", "joint_rate_from", "iso5393_soft", "ISO 5393 soft joint"),
    ("clutch.ball", "spring_seating", "fixed_free", "fixed – free"),
    ("clutch.ball", "spring_arrangement", "per_ball", "one spring per ball"),
]


@pytest.mark.parametrize(("name", "field", "key", "shown"), CASES)
def test_a_raw_key_is_shown_by_its_name_and_sent_as_the_key(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
    name: str,
    field: str,
    key: str,
    shown: str,
) -> None:
    if name not in NAMES:
        pytest.skip(f"{name} is not registered")
    _open(page, base_url, f"m={name}&ex=0")
    option = page.locator(f"#in-{field} option[value='{key}']")
    assert option.inner_text() == shown
    page.goto(f"{base_url}/study.html?model={name}")
    page.wait_for_selector("#study-rows tr")
    assert page.locator(f"#in-{field} option[value='{key}']").inner_text() == shown


@pytest.mark.parametrize("name", sorted(NAMES))
def test_no_choice_list_shows_a_raw_key(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
    name: str,
) -> None:
    _open(page, base_url, f"m={name}")
    shown = page.eval_on_selector_all(
        "#form select option", f"os => os.map(o => o.textContent).filter(t => /{RAW_KEY}/.test(t))"
    )
    assert shown == [], f"{name}: raw keys in its choice lists: {shown}"
