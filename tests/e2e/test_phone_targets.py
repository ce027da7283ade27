"""A phone in a real browser (issue 31): at 390 px every control of every model's page,
the result's included, is at least 44 px tall, and Compute is on the first screen (the
sticky action bar), not ten screens down under the form."""

from __future__ import annotations

from typing import Any

import pytest
from playwright.sync_api import expect

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    PHONE,
    REAL,
    _open,
    base_url,
    browser,
    page,
)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

# every visible control a finger taps; the file inputs are hidden behind their labels
SMALL_CONTROLS = """() => {
  const sel = "input:not([type=hidden]), select, textarea, button, summary, a.button, "
    + "label.button, nav a";
  const small = [];
  let total = 0;
  for (const e of document.querySelectorAll(sel)) {
    const r = e.getBoundingClientRect();
    if (r.width === 0 || r.height === 0 || getComputedStyle(e).visibility === "hidden") continue;
    total++;
    const what = `${e.tagName.toLowerCase()}#${e.id}.${e.className}`;
    if (r.height < 44) small.push(`${what} ${r.height} px`);
  }
  return [total, small];
}"""


@pytest.mark.parametrize("name", [s.name for s in REAL])
def test_every_control_is_44_px_and_compute_is_on_the_first_screen(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
    name: str,
) -> None:
    page.set_viewport_size(PHONE)
    # a new design, the page at its top (the first screen)
    _open(page, base_url, f"m={name}")
    page.evaluate("window.scrollTo(0, 0)")
    assert page.evaluate("window.scrollY") == 0
    compute = page.locator("#compute")
    expect(compute).to_be_in_viewport()
    box = compute.bounding_box()
    assert box is not None and box["y"] >= 0 and box["y"] + box["height"] <= PHONE["height"]
    assert box["height"] >= 44
    # nothing covers it: the point at its centre is the button
    hit = page.evaluate(
        "([x, y]) => document.elementFromPoint(x, y)?.id",
        [box["x"] + box["width"] / 2, box["y"] + box["height"] / 2],
    )
    assert hit == "compute"
    # with the first example's result shown, every control is a 44 px tap target
    _open(page, base_url, f"m={name}&ex=0")
    page.wait_for_selector("body[data-result]")
    total, small = page.evaluate(SMALL_CONTROLS)
    assert total > 10  # the form was measured, not an empty page
    assert small == [], f"{name}: {len(small)} of {total} controls under 44 px: {small[:8]}"
