"""The answer an engineer reads, in a real browser (issue 31): the answer card at the top of
the result carries the numbers the model's question asks for and the verdict of the
standard's requirements, with rules of thumb as warnings."""

from __future__ import annotations

from typing import Any
from urllib.parse import urlencode

import httpx
import pytest

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    DESKTOP,
    PHONE,
    REAL,
    _open,
    _submit,
    api,
    base_url,
    browser,
    page,
)
from tests.service.test_check_levels import ISSUE_JOINT

pytestmark = [pytest.mark.slow, pytest.mark.browser]

JOINT = "joint.vdi2230"


def _joint_link(values: dict[str, Any]) -> str:
    """The issue's joint as a link: every value SI, written with its unit."""
    units = {"thread_diameter": "m", "plate1_thickness": "m", "plate2_thickness": "m"}
    units |= {"working_load": "N", "working_load_min": "N", "transverse_load": "N"}
    query = {k: f"{v:g} {units[k]}" if k in units else f"{v:g}" for k, v in values.items()}
    return urlencode({"m": JOINT, **query})


@pytest.fixture(autouse=True)
def _joint_registered() -> None:
    if JOINT not in [s.name for s in REAL]:
        pytest.skip(f"{JOINT} is not registered")


@pytest.mark.parametrize("viewport", [DESKTOP, PHONE], ids=["desktop", "phone"])
def test_the_issue_joint_passes_vdi_2230_with_the_rule_of_thumb_as_a_warning(
    page: Any,  # noqa: F811
    api: httpx.Client,  # noqa: F811
    base_url: str,  # noqa: F811
    viewport: dict[str, int],
) -> None:
    page.set_viewport_size(viewport)
    _open(page, base_url, _joint_link(ISSUE_JOINT))
    page.wait_for_selector("body[data-result]")
    assert page.evaluate("document.body.dataset.result") == "ok"
    assert page.inner_text("#verdict") == "✓ passes VDI 2230, 1 warning"
    advice = page.inner_text("#advice")
    assert advice.startswith("seed 004 preload stress: σ0 = F_M,nom/A_0"), advice
    assert "[004, eq. 6] allows 0.4…0.5 σ_T" in advice
    # the card's numbers are the API's, to the figures shown: M_A 73.50 N·m, F_M,min 23.79 kN
    answer = api.post("/joint/vdi2230", json=ISSUE_JOINT).json()["results"]
    card = page.locator("#answer-card")
    torque = card.locator("[data-answer=tightening_torque] .value").inner_text()
    assert torque == f"{answer['tightening_torque']:.2f} N·m" == "73.50 N·m"
    preload = card.locator("[data-answer=assembly_preload_min] .value").inner_text()
    assert preload == f"{answer['assembly_preload_min'] / 1e3:.2f} kN" == "23.79 kN"
    clamp = card.locator("[data-answer=residual_clamp_force_min]").inner_text()
    assert clamp.endswith("≥ FK,erf 0 kN ✓"), clamp
    assert card.locator("[data-answer=slip_safety]").count() == 0  # no F_Q: S_G not given
    # the card is the first thing of the result, in view after Compute
    top = page.eval_on_selector("#answer-card", "e => e.getBoundingClientRect().top")
    assert 0 <= top < viewport["height"] / 2
    assert (
        page.inner_text("#announce") == "Computed (method closed_form): passes VDI 2230, 1 warning."
    )


def test_the_first_example_names_the_vdi_requirements_that_fail(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    page.set_viewport_size(DESKTOP)
    _open(page, base_url, f"m={JOINT}")
    page.select_option("#example", "0")
    assert _submit(page) == "ok"
    assert page.inner_text("#verdict") == "✗ 3 of 6 VDI 2230 requirements fail, 1 warning"
    failed = page.eval_on_selector_all("#failed li strong", "xs => xs.map(x => x.textContent)")
    assert failed == ["R7 window fits", "residual clamp force", "R12 slip"]
    marks = {
        k: page.inner_text(f"#answer-card [data-answer={k}] .mark").strip()
        for k in ("permissible_preload", "residual_clamp_force_min", "yield_safety", "slip_safety")
    }
    assert marks == {
        "permissible_preload": "✗",
        "residual_clamp_force_min": "✗",
        "yield_safety": "✓",
        "slip_safety": "✗",
    }
    # the full table stays below the card, the advice check marked as advice in it
    assert page.evaluate(
        "document.getElementById('answer-card').compareDocumentPosition("
        "document.getElementById('results')) & Node.DOCUMENT_POSITION_FOLLOWING"
    )
    row = page.inner_text("#checks li[data-level=advice]")
    assert row.startswith("⚠ advice seed_004_preload_stress (advice)"), row


def test_an_input_without_effect_is_disabled_with_its_reason_and_not_sent(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    """The joint's mu_max and torque tolerance act only with a torque specification (declared
    ``used_with`` in the model): without one they are disabled, say why, and are not sent."""
    page.set_viewport_size(DESKTOP)
    _open(page, base_url, f"m={JOINT}")
    page.select_option("#example", "0")
    for name in ("thread_friction_max", "bearing_friction_max", "torque_tolerance"):
        assert page.is_disabled(f"#in-{name}"), name
        reason = page.inner_text(f"#unused-{name}")
        assert reason == "Used only with a tightening torque: without one it changes nothing."
        assert f"unused-{name}" in (page.get_attribute(f"#in-{name}", "aria-describedby") or "")
    assert _submit(page) == "ok"
    assert "torque_tolerance" not in page.evaluate("window.calcState.lastRequest")
    page.fill("#in-tightening_torque", "70")
    assert page.is_enabled("#in-torque_tolerance") and page.is_hidden("#unused-torque_tolerance")
    page.fill("#in-torque_tolerance", "0.1")
    page.fill("#in-thread_friction_max", "0.16")
    assert _submit(page) == "ok"
    sent = page.evaluate("window.calcState.lastRequest")
    assert (sent["torque_tolerance"], sent["thread_friction_max"]) == (0.1, 0.16)


def test_a_disc_pack_s_inputs_are_disabled_for_a_helical_spring_and_the_reverse(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    """clutch.spring_design's disc inputs act only with spring kind "disc pack", its wire
    inputs only with "helical spring" (``used_with="spring_kind=…"``): the other kind's are
    disabled, say why, and are not sent."""
    page.set_viewport_size(DESKTOP)
    _open(page, base_url, "m=clutch.spring_design")
    page.select_option("#example", "0")
    disc, wire = ("disc_series", "disc_yield_strength"), ("spring_material", "spring_seating")
    assert page.input_value("#in-spring_kind") == "helical"
    for name in disc:
        assert page.is_disabled(f"#in-{name}"), name
        reason = page.inner_text(f"#unused-{name}")
        assert reason == "Used only with spring kind “disc pack”: with another it changes nothing."
        assert f"unused-{name}" in (page.get_attribute(f"#in-{name}", "aria-describedby") or "")
    for name in wire:
        assert page.is_enabled(f"#in-{name}") and page.is_hidden(f"#unused-{name}"), name
    assert _submit(page) == "ok"
    sent = page.evaluate("window.calcState.lastRequest")
    assert not set(disc) & set(sent) and set(wire) <= set(sent)
    page.select_option("#in-spring_kind", "disc_pack")
    for name in wire:
        assert page.is_disabled(f"#in-{name}"), name
        reason = page.inner_text(f"#unused-{name}")
        assert (
            reason
            == "Used only with spring kind “helical spring”: with another it changes nothing."
        )
    for name in disc:
        assert page.is_enabled(f"#in-{name}") and page.is_hidden(f"#unused-{name}"), name
    page.select_option("#in-disc_series", "A")
    assert _submit(page) == "ok"
    sent = page.evaluate("window.calcState.lastRequest")
    assert not set(wire) & set(sent) and sent["disc_series"] == "A"
    assert "DIN 2093 A 40" in page.inner_text("#results")
