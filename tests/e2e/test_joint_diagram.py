"""The VDI joint diagram in a real browser (issue 31): one plot drawn as VDI 2230 draws it
from the joint model's series (bolt and clamped-part lines from the preload, F_A inserted
at the working point, F_Z and F_KR marked), in place of the diagram's eight plain curves."""

from __future__ import annotations

import json
from typing import Any

import httpx
import pytest
from playwright.sync_api import expect

from tests.e2e.test_browser import (  # noqa: F401 (fixtures)
    REAL,
    _open,
    api,
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


def test_the_joint_diagram_is_drawn_as_vdi_draws_it(
    page: Any,  # noqa: F811
    api: httpx.Client,  # noqa: F811
    base_url: str,  # noqa: F811
) -> None:
    _open(page, base_url, "")
    page.select_option("#unit-system", "metric")
    _open(page, base_url, f"m={JOINT}&ex=0")
    page.wait_for_selector("body[data-result]")
    request = page.evaluate("window.calcState.lastRequest")
    answer = api.post("/joint/vdi2230", json=request).json()
    series, results = answer["series"], answer["results"]
    figure = page.locator("#series-plots figure.chart", has_text="Joint diagram (VDI 2230)")
    expect(figure).to_have_count(1)
    # one plot for the diagram: no plain curve of a diagram_* series is drawn on its own
    titles = page.locator("#series-plots figure.chart .u-title").all_inner_texts()
    assert not [t for t in titles if t.startswith("Joint diagram:")], titles
    legend = figure.locator(".u-legend").inner_text()
    for line in ("bolt", "clamped parts", "clamped parts after embedding"):
        assert line in legend
    marks = json.loads(figure.get_attribute("data-segments") or "{}")
    # F_A at the working point: from F_KR up to F_S = F_V + Φ_n F_A, at f_SV + Φ_n F_A δ_S
    # (axes in mm and kN here: 1e-3 m and 1e3 N)
    f_kr = results["residual_clamp_force_min"]
    f_a = answer["inputs"]["working_load"]
    f_z = results["embedding_loss"]
    f_m = results["assembly_preload_min"]
    f_s = f_m - f_z + results["load_factor"] * f_a
    x_w, lo, hi = marks["F_A"]
    assert x_w == pytest.approx(series["diagram_working_deformation"][0] / 1e-3, rel=1e-9)
    assert (lo, hi) == (pytest.approx(f_kr / 1e3, rel=1e-9), pytest.approx(f_s / 1e3, rel=1e-9))
    assert hi - lo == pytest.approx(f_a / 1e3, rel=1e-9)  # the full F_A
    assert marks["F_KR"] == [x_w, 0, pytest.approx(f_kr / 1e3, rel=1e-9)]
    # F_Z the drop from F_M,min to F_V at the preload point f_SM = F_M,min δ_S on the bolt line
    x_m, fv, fm = marks["F_Z"]
    assert (fm - fv) == pytest.approx(f_z / 1e3, rel=1e-9)
    assert fm == pytest.approx(f_m / 1e3, rel=1e-9)
    assert x_m == pytest.approx(f_m * results["bolt_compliance"] / 1e-3, rel=1e-9)
    # the separation point is where the model puts it
    assert marks["opening"][0] == pytest.approx(
        series["diagram_opening_deformation"][0] / 1e-3, rel=1e-9
    )
