"""Imperial everywhere, in a real browser (issue 31): with imperial chosen, a check's and a
note's quantities read in imperial units, converted from the SI values the API gives beside
each sentence; converted field values are rounded to the precision typed, and both pages
format numbers with one formatter (static/numbers.js)."""

from __future__ import annotations

from typing import Any

import httpx
import pytest

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    REAL,
    _open,
    _submit,
    api,
    base_url,
    browser,
    page,
)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

JOINT = "joint.vdi2230"
LBF = 4.4482216152605  # N, units.json and pint agree (tests/e2e/test_units_table.py)
INCH = 0.0254  # m


@pytest.fixture(autouse=True)
def _joint_registered() -> None:
    if JOINT not in [s.name for s in REAL]:
        pytest.skip(f"{JOINT} is not registered")


def _digits(x: float, sig: int) -> str:
    """The number as the page writes a converted quantity: ``sig`` digits, no trailing zeros."""
    return str(float(f"{x:.{sig}g}")).removesuffix(".0")


def _joint_answer(api: httpx.Client) -> dict[str, Any]:  # noqa: F811
    spec = next(s for s in REAL if s.name == JOINT)
    answer: dict[str, Any] = api.post("/joint/vdi2230", json=spec.examples[0]).json()
    return answer


def test_a_check_and_a_note_read_in_imperial_units(
    page: Any,  # noqa: F811
    api: httpx.Client,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    answer = _joint_answer(api)
    clamp = next(c for c in answer["checks"] if c["name"] == "residual_clamp_force")
    kr, kerf = (p for p in clamp["detail_parts"] if isinstance(p, dict))
    assert clamp["detail"].startswith(
        f"F_KR,min = F_M,min − (1 − Φ_n) F_A − F_Z − ΔF_th = {kr['text']}"
    )
    assert (kr["unit"], kr["display_unit"], kr["digits"]) == ("N", "kN", 4)
    cone = next(ps for ps in answer["notes_parts"] if ps[0].startswith("D_A not given"))
    d_a = cone[1]
    assert (d_a["unit"], d_a["display_unit"]) == ("m", "mm")

    _open(page, base_url, "")
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-system", "metric")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    checks = page.inner_text("#checks")
    assert f"= {kr['text']} vs required F_K,erf = {kerf['text']}" in checks  # "12.28 kN"
    assert f"D_A = D_A,Gr = {d_a['text']} (our" in page.inner_text("#notes")

    page.select_option("#unit-system", "imperial")
    # F_KR,min 12.28 kN = 2761 lbf, F_K,erf 13.33 kN = 2997 lbf; D_A 36.09 mm = 1.421 in,
    # to the digits the metric sentence shows
    kr_lbf = _digits(kr["value"] / LBF, 4)
    kerf_lbf = _digits(kerf["value"] / LBF, 4)
    d_a_in = _digits(d_a["value"] / INCH, d_a["digits"])
    item = page.inner_text("#checks li:has-text('residual_clamp_force')")
    assert f"= {kr_lbf} lbf vs required F_K,erf = {kerf_lbf} lbf" in item, item
    assert " kN" not in item, item
    notes = page.inner_text("#notes")
    assert f"D_A = D_A,Gr = {d_a_in} in (our convention" in notes, notes
    # the failing requirements above the results, in the same units
    failed = page.inner_text("#failed")
    assert f"{kr_lbf} lbf" in failed and "kN" not in failed, failed

    # the printed report too
    page.click("#show-report")
    report = page.inner_text("#report-body")
    assert f"= {kr_lbf} lbf vs required F_K,erf = {kerf_lbf} lbf" in report
    assert f"D_A = D_A,Gr = {d_a_in} in (our convention" in report
    # back to metric: the sentences as the model wrote them
    page.select_option("#unit-system", "metric")
    report = page.inner_text("#report-body")
    assert f"= {kr['text']} vs required F_K,erf = {kerf['text']}" in report


def test_converted_field_values_are_rounded_and_the_answer_stays(
    page: Any,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-system", "metric")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    page.fill("#in-plate1_thickness", "20.5")
    assert _submit(page) == "ok"
    metric = page.evaluate("window.calcState.lastResponse.results")
    page.select_option("#unit-system", "imperial")
    # typed 20.5 mm (3 digits) = 0.80709 in, two digits more than typed, not 0.8070866142
    assert page.input_value("#in-plate1_thickness") == "0.80709"
    # the example's 12 mm, loaded: 0.47244 in, not 0.4724409
    assert page.input_value("#in-thread_diameter") == "0.47244"
    assert page.is_hidden("#stale-note")
    assert _submit(page) == "ok"
    imperial = page.evaluate("window.calcState.lastResponse.results")
    for name, value in metric.items():  # the exact values were sent, not the rounded text
        assert imperial[name] == value, name
    sent = page.evaluate("window.calcState.lastRequest.plate1_thickness")
    assert sent == pytest.approx(0.0205, rel=1e-12)


def test_one_number_formatter_for_both_pages(page: Any, base_url: str) -> None:  # noqa: F811
    _open(page, base_url, "")
    got = page.evaluate(
        """async () => { const n = await import('./numbers.js');
            return [n.formatNumber(12345.6, 4, {dec: '.'}), n.formatNumber(0.5, 3, {dec: '.'}),
                    n.formatNumber(0.5, 3, {trim: true, dec: '.'}),
                    n.formatNumber(2.5, 2, {dec: ','}), n.formatNumber(1.5e-7, 3, {dec: '.'}),
                    n.formatNumber(2.35e6, 3, {trim: true, dec: '.'}), n.formatCount(12350),
                    n.formatCount(4000), n.typedDigits('0.0120'), n.typedDigits('1500')]; }"""
    )
    assert got == [
        "12\u202f350",
        "0.500",
        "0.5",
        "2,5",
        "1.50e-7",
        "2.35e6",
        "12\u202f350",
        "4000",
        3,
        4,
    ]
