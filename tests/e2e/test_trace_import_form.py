"""The form's trace upload (static/trace_import.js) in a real browser: a tool's export read
through POST /api/v1/trace/import into the trace fields, then computed.

Uses the browser, server and page fixtures of tests/e2e/test_browser.py (chromium; skipped
where it cannot start, failed under CI).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from tests.e2e import test_browser as browser_test
from tests.e2e.test_browser import _example, _open, _submit

# the fixtures of the browser test, under their names
base_url = browser_test.base_url
browser = browser_test.browser
page = browser_test.page

pytestmark = [pytest.mark.slow, pytest.mark.browser]
DATA = Path(__file__).resolve().parents[1] / "data"


def _lines(page: Any, name: str) -> list[str]:
    text: str = page.input_value(f'[data-field="{name}"] textarea')
    return [t for t in text.splitlines() if t.strip()]


def test_a_csv_export_fills_the_trace_and_computes(page: Any, base_url: str) -> None:
    from playwright.sync_api import expect

    _open(page, base_url, "m=trace.analysis")
    _example(page)  # the M12 joint of the example; its trace is replaced by the file's
    page.select_option("#trace-import-format", "csv")
    page.fill("#trace-import-time_column", "Time")
    page.fill("#trace-import-torque_unit", "Nm")
    page.fill("#trace-import-time_unit", "ms")
    page.check("#trace-import-decimal-comma")
    page.set_input_files("#trace-import-file", str(DATA / "trace_m12.csv"))
    expect(page.locator("#trace-import-status")).to_have_text("read 1 file, 200 samples")
    angle = _lines(page, "angle")
    assert len(angle) == 200 and len(_lines(page, "torque")) == 200
    assert len(_lines(page, "time")) == 200
    # the angle field shows radians, its SI unit: the file's 0.3° a sample
    assert float(angle[1].replace(",", ".")) == pytest.approx(0.3 * math.pi / 180.0, rel=1e-9)
    assert _submit(page) == "ok", page.inner_text("#model")
    rate = page.get_attribute('#results tr[data-output="elastic_rate"] td.num', "data-si")
    assert rate is not None and float(rate) * math.pi / 180.0 == pytest.approx(2.2, rel=0.002)


def test_json_exports_append_as_traces_of_a_batch(page: Any, base_url: str) -> None:
    from playwright.sync_api import expect

    _open(page, base_url, "m=trace.batch")
    for name in ("angle", "torque", "time", "trace_lengths"):
        page.fill(f'[data-field="{name}"] textarea', "")
    page.select_option("#trace-import-format", "rexroth")
    page.set_input_files("#trace-import-file", str(DATA / "trace_m12_rexroth.json"))
    expect(page.locator("#trace-import-status")).to_have_text("read 1 file, 200 samples")
    page.select_option("#trace-import-format", "opc_ua")
    page.set_input_files("#trace-import-file", str(DATA / "trace_m12_opcua.json"))
    expect(page.locator("#trace-import-status")).to_have_text("read 1 file, 200 samples")
    assert len(_lines(page, "angle")) == 400 and _lines(page, "trace_lengths") == ["200", "200"]
    page.select_option("#trace-import-format", "open_protocol")
    page.set_input_files("#trace-import-file", str(DATA / "trace_m12_opcua.json"))
    expect(page.locator("#trace-import-status")).to_contain_text("content.traceType: ")
    assert len(_lines(page, "angle")) == 400  # a refused file leaves the fields as they were
