"""Entry that cannot go silently wrong, in a real browser (issue 31): under a decimal point
"2,000" is two thousand; under a decimal comma "1,500" is one and a half and the value read
is echoed beside the field; an ambiguous group is refused at the field, naming it."""

from __future__ import annotations

from typing import Any

import pytest

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    REAL,
    _open,
    _submit,
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


def test_point_separator_reads_2000_as_two_thousand_and_refuses_1_50(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-system", "imperial")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    page.fill("#in-working_load", "2,000")
    assert page.inner_text("#read-working_load") == "= 2000 lbf"
    assert _submit(page) == "ok"
    sent = page.evaluate("window.calcState.lastResponse.inputs.working_load")
    assert sent == pytest.approx(2000 * 4.4482216152605, rel=1e-12)  # 1 lbf = 4.448… N
    # "1,50" is neither 1.5 (the comma is not the decimal mark) nor a group of three
    label = "working load"  # the field named in its refusal
    page.fill("#in-working_load", "1,50")
    message = page.inner_text("#err-working_load")
    assert message.startswith(label + ": "), message
    assert "“1,50” is not a number with the decimal point" in message
    assert page.inner_text("#read-working_load") == ""
    assert _submit(page) == "error"


def test_comma_separator_reads_1500_as_one_and_a_half_and_says_so(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ",")
    page.select_option("#unit-system", "metric")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    unit = page.inner_text("#unit-working_load option:checked")
    assert unit == "kN"
    page.fill("#in-working_load", "1,500")
    # typed as the digits 1500, read as 1.5: the reading is echoed beside the field
    assert page.inner_text("#read-working_load") == "= 1,5 kN"
    assert page.inner_text("#err-working_load") == ""
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastResponse.inputs.working_load") == 1500.0  # N
    # a plain decimal that cannot be mistaken for a group is not echoed
    page.fill("#in-working_load", "1,5")
    assert page.inner_text("#read-working_load") == ""
    page.fill("#in-working_load", "12,5")
    assert page.inner_text("#read-working_load") == ""
    # a group of thousands under the comma is the point: echoed as read
    page.fill("#in-working_load", "1.500")
    assert page.inner_text("#read-working_load") == "= 1500 kN"
