"""The study page with a model whose array path reports its checks (Result.check_arrays):
the pass fraction of each check and of all of them, and the grid map's feasible region, at
desktop width and on a 390 px phone. The model is a toy whose verdicts are easy to count by
hand; the counts are checked against single runs of the scalar compute, point by point."""

from __future__ import annotations

import socket
import threading
import time
from collections.abc import Iterator, Mapping
from typing import Any

import numpy as np
import pytest

import engine
from engine import Check, InfeasibleDesign, ModelSpec, Output, Param, Result, RunContext, Rung
from service import create_app
from service.studies import StudySettings

from .test_browser import SHOTS, browser  # noqa: F401  (fixture)

pytestmark = [pytest.mark.slow, pytest.mark.browser]

GAP0, A_MAX, REFUSE = 0.95, 0.85, 1.85


def _gate(x: Mapping[str, Any], ctx: RunContext) -> Result:
    a, b = float(x["a"]), float(x["b"])
    if a + b > REFUSE:
        raise InfeasibleDesign("a + b over 1.85 m: the parts collide", field="b")
    gap = a + b - GAP0
    return Result(
        values={"gap": gap, "area": a * b},
        rung=ctx.rung,
        error_estimate=0.0,
        checks=[
            Check("gap_closed", gap >= 0.0, "a + b must reach 0.95 m"),
            Check("a_fits", a <= A_MAX, "a must stay within 0.85 m"),
        ],
    )


def _gate_vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    a, b = np.asarray(x["a"], dtype=float), np.asarray(x["b"], dtype=float)
    dead = a + b > REFUSE
    gap = np.where(dead, np.nan, a + b - GAP0)
    return Result(
        values={"gap": gap, "area": np.where(dead, np.nan, a * b)},
        rung=ctx.rung,
        error_estimate=0.0,
        check_arrays={"gap_closed": a + b - GAP0 >= 0.0, "a_fits": a <= A_MAX},
    )


GATE = ModelSpec(
    name="toy.gate",
    title="Gate (checks on the array path)",
    family="toy",
    summary="Two lengths that must close a gap; its array path reports the checks.",
    source="none",
    inputs=(
        Param("a", "m", "first length", default=0.5, minimum=0.0, maximum=1.0),
        Param("b", "m", "second length", default=0.5, minimum=0.0, maximum=1.0),
    ),
    outputs=(Output("gap", "m", "a + b − 0.95 m"), Output("area", "m^2", "a b")),
    rungs=(Rung("exact", "exact", engine.fixed_error(0.0)),),
    compute=_gate,
    vectorized=_gate_vectorized,
    vector_rungs=("exact",),
    default_fidelity="exact",
    examples=({"a": 0.5, "b": 0.5},),
)

GRID = np.linspace(0.0, 1.0, 11)


def _expected() -> dict[str, Any]:
    """Pass counts from single runs of the scalar compute over the 11 × 11 grid."""
    counts = {"gap_closed": [0, 0], "a_fits": [0, 0]}
    feasible = refused = 0
    for a in GRID:
        for b in GRID:
            try:
                r = engine.run(GATE, {"a": a, "b": b})
            except InfeasibleDesign:
                refused += 1
                continue
            for c in r.checks:
                counts[c.name][0 if c.ok else 1] += 1
            feasible += all(c.ok for c in r.checks)
    return {"counts": counts, "feasible": feasible, "refused": refused}


def test_the_toy_is_counted_by_hand() -> None:
    e = _expected()
    # 3 refused (a + b ≥ 1.9); the gap closes where i + j ≥ 10 (66 of 121, 3 of them
    # refused); a fits for i ≤ 8 (99 pass, 19 fail among the known)
    assert e["refused"] == 3
    assert e["counts"] == {"gap_closed": [63, 55], "a_fits": [99, 19]}
    assert e["feasible"] == 63 - 18  # a too long where the gap closes: i = 9, j ≥ 1; i = 10, j ≤ 8


@pytest.fixture(scope="module")
def base_url() -> Iterator[str]:
    import uvicorn

    app = create_app(
        models=[*engine.MODELS, GATE], study_settings=StudySettings(inprocess_points=10_000)
    )
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    config = uvicorn.Config(app, log_level="warning", lifespan="off", ws="none")
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not server.started:
        assert thread.is_alive() and time.monotonic() < deadline, "the server did not start"
        time.sleep(0.02)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(timeout=10)
    sock.close()


def _page(request: Any, browser: Any, base_url: str, model: str) -> Iterator[Any]:  # noqa: F811
    width, height = request.param
    context = browser.new_context(viewport={"width": width, "height": height})
    context.set_default_timeout(30_000)
    problems: list[str] = []
    pg = context.new_page()
    pg.on("pageerror", lambda exc: problems.append(str(exc)))
    pg.goto(f"{base_url}/study.html?model={model}")
    pg.wait_for_selector("#study-rows tr")
    pg.shot = f"study--checks-{request.node.callspec.id}"
    yield pg
    context.close()
    assert not problems, problems


VIEWPORTS = {"params": [(1400, 900), (390, 844)], "ids": ["desktop", "phone"]}


@pytest.fixture(**VIEWPORTS)
def gate_page(request: Any, browser: Any, base_url: str) -> Iterator[Any]:  # noqa: F811
    yield from _page(request, browser, base_url, "toy.gate")


@pytest.fixture(**VIEWPORTS)
def clutch_page(request: Any, browser: Any, base_url: str) -> Iterator[Any]:  # noqa: F811
    yield from _page(request, browser, base_url, "clutch.ball")


def _vary(pg: Any, name: str, **parts: str) -> None:
    pg.check(f'tr[data-name="{name}"] input[type=checkbox]')
    for part, value in parts.items():
        pg.fill(f'tr[data-name="{name}"] input[data-part={part}]', value)


def _checks(pg: Any) -> list[str]:
    """The lines of the checks list, whitespace collapsed (the bar breaks innerText's line)."""
    return [" ".join(t.split()) for t in pg.locator("#study-checks li").all_inner_texts()]


def _pct(passed: int, known: int) -> str:
    return f"{100 * passed / known:.1f} %"


def test_a_grid_shows_check_pass_fractions_and_the_feasible_map(gate_page: Any) -> None:
    pg = gate_page
    pg.select_option("#study-method", "grid")
    _vary(pg, "a", low="0", high="1", num="11")
    _vary(pg, "b", low="0", high="1000 mm", num="11")
    pg.check("#study-keep")
    pg.click("#study-run")
    pg.wait_for_selector("#study-result:not([hidden])")
    e = _expected()
    meta = pg.inner_text("#study-meta")
    assert "121 designs (grid), 3 refused" in meta
    assert f"feasible (every reported requirement passes): {_pct(e['feasible'], 118)}" in meta
    items = _checks(pg)
    ok, bad = e["counts"]["gap_closed"]
    assert any(
        f"gap closed: {_pct(ok, ok + bad)} pass ({ok} pass, {bad} fail, 3 not evaluated)" in t
        for t in items
    ), items
    ok, bad = e["counts"]["a_fits"]
    assert any(f"a fits: {_pct(ok, ok + bad)} pass ({ok} pass, {bad} fail" in t for t in items)
    assert any(f"all requirements: {_pct(e['feasible'], 118)}" in t for t in items), items
    assert "not evaluated on the model's array path" not in pg.inner_text("#study-notes")
    # the map: drawn, with the feasible region outlined in red (#b3261e)
    assert pg.is_visible("#study-map")
    red = pg.evaluate(
        """() => {
          const c = document.querySelector('#study-map');
          const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
          let n = 0;
          for (let i = 0; i < d.length; i += 4)
            if (d[i] === 0xb3 && d[i + 1] === 0x26 && d[i + 2] === 0x1e) n++;
          return n;
        }"""
    )
    assert red > 100
    # both downloads are offered
    assert pg.is_visible("#study-csv") and pg.is_visible("#study-parquet")
    assert pg.get_attribute("#study-parquet", "href").endswith("/points.parquet")
    width = pg.viewport_size["width"]
    assert pg.evaluate("document.documentElement.scrollWidth") <= width
    SHOTS.mkdir(parents=True, exist_ok=True)
    pg.screenshot(path=str(SHOTS / f"{pg.shot}-grid.png"), full_page=True)


def test_a_monte_carlo_shows_the_pass_fractions_without_a_map(gate_page: Any) -> None:
    pg = gate_page
    pg.select_option("#study-method", "monte_carlo")
    pg.fill("#study-samples", "4000")
    _vary(pg, "a", low="0.5", high="1")
    pg.click("#study-run")
    pg.wait_for_selector("#study-result:not([hidden])")
    assert pg.is_hidden("#study-map-fig")
    # b = 0.5 m: the gap closes for a ≥ 0.45 m, so always; a fits below 0.85 m: ~70 %
    items = _checks(pg)
    assert any(t == "✓ gap closed: 100.0 % pass (4000 pass, 0 fail)" for t in items), items
    (fits,) = [t for t in items if "a fits" in t]
    share = float(fits.split(": ")[1].split(" %")[0])
    assert 67.0 < share < 73.0, fits
    assert pg.evaluate("document.documentElement.scrollWidth") <= pg.viewport_size["width"]
    pg.screenshot(path=str(SHOTS / f"{pg.shot}-mc.png"), full_page=True)


def test_the_ball_clutch_grid_shows_the_checks_its_array_path_reports(clutch_page: Any) -> None:
    """clutch.ball's array path reports its four checks: the page's pass shares are the
    single runs' verdicts over the same 8 × 8 grid of spring deflection and wire diameter."""
    pg = clutch_page
    clutch = engine.get_model("clutch.ball")
    ex = dict(clutch.examples[0])
    deflections, wires = np.linspace(0.001, 0.012, 8), np.linspace(0.0015, 0.008, 8)
    counts: dict[str, list[int]] = {}
    feasible = 0
    for s in deflections:
        for d in wires:
            r = engine.run(clutch, {**ex, "spring_deflection": s, "spring_wire_diameter": d})
            for c in r.checks:
                counts.setdefault(c.name, [0, 0])[0 if c.ok else 1] += 1
            # feasible: every requirement passes (the spring index, groove angle and
            # self-locking margin are advice: rules of thumb that warn)
            feasible += all(c.ok for c in r.checks if c.level == "requirement")
    assert set(counts) == {"spring_index", "groove_depth", "groove_angle", "self_locking"}
    assert 0 < feasible < 64  # the map has a feasible region and an infeasible one
    pg.select_option("#study-method", "grid")
    _vary(pg, "spring_deflection", low="0.001", high="0.012", num="8")
    _vary(pg, "spring_wire_diameter", low="0.0015", high="0.008", num="8")
    pg.click("#study-run")
    pg.wait_for_selector("#study-result:not([hidden])")
    meta = pg.inner_text("#study-meta")
    assert "64 designs (grid), 0 refused" in meta and "closed_form ×64" in meta
    items = _checks(pg)
    for name, (ok, bad) in counts.items():
        advice = " (advice, not counted)" if clutch.check_level(name) == "advice" else ""
        line = f"{name.replace('_', ' ')}{advice}: {_pct(ok, 64)} pass ({ok} pass, {bad} fail)"
        assert any(line in t for t in items), (line, items)
    assert any(
        f"all requirements: {_pct(feasible, 64)} pass ({feasible} of 64 designs)" in t
        for t in items
    )
    assert "not evaluated on the model's array path" not in pg.inner_text("#study-notes")
    assert pg.is_visible("#study-map")
    assert pg.evaluate("document.documentElement.scrollWidth") <= pg.viewport_size["width"]
    pg.screenshot(path=str(SHOTS / f"{pg.shot}-clutch.png"), full_page=True)
