"""The form in a real browser (Debian's chromium through Playwright), against a live server.

For every model (the toy specs always; every model in ``engine.MODELS`` once
registered): open the form, submit the worked example, check that the page
shows the values the API returns for the same input, that a plot canvas is
drawn (series, when the model returns any, and a sweep), that a bad value is
marked at its field with the server's message, that changing a unit gives
the same answer, that the link in the address bar reproduces the calculation
and that the JSON/CSV downloads hold the result. A screenshot of each
model's result goes to ``test-output/screenshots/``.

The page may not fetch anything but the local server: every other request
is refused and fails the test (the page must work offline).

Where chromium cannot start, the tests skip saying why; with ``CI`` set they
fail instead, because CI installs chromium (``apt-get install -y chromium``).
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
import os
import re
import socket
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest

import engine
from service import create_app
from tests.toys import STRIKER, TOY

pytestmark = [pytest.mark.slow, pytest.mark.browser]

# E2E_CHROMIUM overrides the browser path (e.g. to check the skip/fail paths)
CHROMIUM = os.environ.get("E2E_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
ROOT = Path(__file__).resolve().parents[2]
SHOTS = ROOT / "test-output" / "screenshots"
TOYS = (TOY, STRIKER)
REAL = tuple(engine.MODELS)
TIMEOUT_MS = 20_000


def _cannot_run(reason: str) -> None:
    """Skip with the reason, or fail when CI (which installs chromium) is running us."""
    if os.environ.get("CI"):
        pytest.fail(f"{reason}; CI is set, and CI must run the browser test", pytrace=False)
    pytest.skip(reason)


# ---------------------------------------------------------------- fixtures


@pytest.fixture(scope="module")
def base_url() -> Iterator[str]:
    """The real app with every registered model plus the toys, served by uvicorn on loopback."""
    import uvicorn

    app = create_app(models=[*REAL, *TOYS])
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
        if not thread.is_alive() or time.monotonic() > deadline:
            pytest.fail("the test server did not start", pytrace=False)
        time.sleep(0.02)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(timeout=10)
    sock.close()


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _cannot_run("the playwright package is not installed (pip install -e '.[dev]')")
    if not os.access(CHROMIUM, os.X_OK):
        _cannot_run(f"{CHROMIUM} is missing: apt-get install -y chromium")
    with sync_playwright() as p:
        try:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        except Exception as exc:  # chromium present but unable to start here
            _cannot_run(f"{CHROMIUM} could not start: {str(exc).splitlines()[0]}")
        yield browser
        browser.close()


@pytest.fixture()
def api(base_url: str) -> Iterator[httpx.Client]:
    with httpx.Client(base_url=base_url + "/api/v1", timeout=60) as client:
        yield client


@pytest.fixture()
def page(browser: Any, base_url: str) -> Iterator[Any]:
    """A fresh page that may reach the test server only, and must log no script error."""
    context = browser.new_context(viewport={"width": 1280, "height": 900}, accept_downloads=True)
    context.set_default_timeout(TIMEOUT_MS)
    outside: list[str] = []
    problems: list[str] = []

    def only_local(route: Any) -> None:
        url = route.request.url
        if url.startswith(base_url) or url.startswith(("blob:", "data:")):
            route.continue_()
        else:
            outside.append(url)
            route.abort()

    context.route("**/*", only_local)
    pg = context.new_page()
    pg.on("pageerror", lambda exc: problems.append(f"page error: {exc}"))
    pg.on(
        "console",
        lambda msg: (
            problems.append(f"console {msg.type}: {msg.text}")
            if msg.type == "error" and "422" not in msg.text  # a refused input logs its 422
            else None
        ),
    )
    yield pg
    context.close()
    assert not outside, f"the page tried to reach outside the server: {outside}"
    assert not problems, problems


# ---------------------------------------------------------------- helpers


def _describe(api: httpx.Client, name: str) -> dict[str, Any]:
    response = api.get(f"/models/{name}")
    assert response.status_code == 200
    return response.json()


def _example(page: Any) -> None:
    """Load example 1 from the form's chooser (a new design starts from the defaults)."""
    if page.locator('#example option[value="0"]').count():
        page.select_option("#example", "0")


def _open(page: Any, base_url: str, fragment: str) -> None:
    page.goto("about:blank")  # a new hash alone would not reload the page
    page.goto(f"{base_url}/#{fragment}")
    page.wait_for_selector("body[data-ready]")


def _submit(page: Any) -> str:
    """Click Compute; return "ok" or "error" once the page has shown the answer."""
    page.evaluate("delete document.body.dataset.result")
    page.click("#compute")
    page.wait_for_selector("body[data-result]")
    return page.evaluate("document.body.dataset.result")


def _shown_results(page: Any) -> dict[str, dict[str, Any]]:
    rows = page.eval_on_selector_all(
        "#results tr",
        """rows => rows.map(r => {
            const td = r.querySelector('td.num');
            const unit = r.querySelector('td.unit').textContent;
            const factor = Number(td.dataset.factor);
            const sig = Number(td.dataset.sig);
            return [r.dataset.output, {si: td.dataset.si, factor, sig, text: td.textContent, unit}];
        })""",
    )
    return dict(rows)


def _same(a: Any, b: Any, rel: float) -> bool:
    if isinstance(a, bool) or isinstance(b, bool) or a is None or b is None:
        return a == b
    if isinstance(a, int | float) and isinstance(b, int | float):
        return math.isclose(a, b, rel_tol=rel, abs_tol=1e-300)
    return a == b


def _parse_si(text: str) -> Any:
    if text == "null":
        return None
    if text in ("true", "false"):
        return text == "true"
    try:
        return float(text)
    except ValueError:
        return text


def _assert_page_matches(page: Any, expected: dict[str, Any], spec: dict[str, Any]) -> None:
    """Every scalar result is shown, its SI value equal to the API's, its text correctly rounded."""
    shown = _shown_results(page)
    scalars = [o["name"] for o in spec["outputs"] if not o["series"]]
    assert set(shown) == {k for k in expected["results"] if k in scalars}
    assert page.inner_text("#rung") == expected["rung"]
    for name, cell in shown.items():
        want = expected["results"][name]
        got = _parse_si(cell["si"])
        assert _same(got, want, 1e-12), (name, got, want)
        if isinstance(want, float) and not isinstance(want, bool):
            # the text is the value in the display unit, rounded to the figures the error
            # estimate supports (at least two), digits grouped by narrow spaces, ± for a scatter
            displayed = _number(cell["text"]) * cell["factor"]
            rel = 0.5 * 10 ** (1 - cell["sig"])
            assert math.isclose(displayed, want, rel_tol=rel, abs_tol=1e-300), (name, cell, want)
    checks = page.locator("#checks li")
    assert checks.count() == len(expected["checks"])
    for i, c in enumerate(expected["checks"]):
        text = checks.nth(i).inner_text()
        failed = "advice" if c["level"] == "advice" else "fail"  # advice warns, it does not fail
        assert ("pass" if c["ok"] else failed) in text and c["detail"] in text
    for w in expected["warnings"]:
        assert w in page.inner_text("#warnings")


def _number(text: str) -> float:
    """A number as the page shows it: "12\u202f345.6", "±30.00", "1.23e-7"."""
    return float(text.replace("\u202f", "").replace("±", ""))


def _no_horizontal_scroll(page: Any) -> None:
    width, inner = page.evaluate("[document.documentElement.scrollWidth, window.innerWidth]")
    assert width <= inner, f"the page scrolls sideways: {width} px wide in a {inner} px window"


def _canvas_ink(page: Any, selector: str) -> list[int]:
    """Per chart under ``selector``: how many canvas pixels are not blank."""
    return page.eval_on_selector_all(
        selector + " canvas",
        """cs => cs.map(c => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0;
            for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
            return n;
        })""",
    )


def _norm_unit(unit: str) -> str:
    for a, b in (("·", "*"), ("**", "^"), ("²", "^2"), ("³", "^3"), ("µ", "u"), ("μ", "u")):
        unit = unit.replace(a, b)
    return re.sub(r"\s+", "", unit)


def _sweep(page: Any, api: httpx.Client, spec: dict[str, Any]) -> None:
    """Sweep numeric inputs against scalar outputs until one pair gives a curve."""
    numeric = [p["name"] for p in spec["inputs"] if p["kind"] in ("float", "int")]
    outputs = [
        o["name"] for o in spec["outputs"] if not o["series"] and o["kind"] in ("float", "int")
    ]
    if not numeric or not outputs:
        return
    tried = []
    for output in outputs[:3]:
        page.select_option("#sweep-output", output)
        for vary in numeric[:4]:
            tried.append((vary, output))
            page.select_option("#sweep-vary", vary)
            page.fill("#sweep-num", "12")
            page.evaluate("delete document.body.dataset.sweep")
            page.click("#sweep-run")
            page.wait_for_selector("body[data-sweep]")
            sweep = page.evaluate("window.calcState.lastSweep")
            if page.evaluate("document.body.dataset.sweep") != "ok":
                continue
            points = [v for v in sweep["response"]["results"][output] if v is not None]
            if len(points) < 2:
                continue
            again = api.post(spec["path"] + "/sweep", json=sweep["request"])
            assert again.status_code == 200
            assert again.json()["results"] == sweep["response"]["results"]
            ink = _canvas_ink(page, "#sweep-plot")
            assert len(ink) == 1 and ink[0] > 500, ink
            return
    pytest.fail(f"{spec['name']}: no sweep gave a curve of two points or more; tried {tried}")


def _bad_value(spec: dict[str, Any]) -> tuple[dict[str, Any], float | str]:
    """The first bounded numeric input and an SI value outside its range (or a non-number)."""
    for p in spec["inputs"]:
        if p["kind"] not in ("float", "int"):
            continue
        if p["maximum"] is not None:
            return p, p["maximum"] + abs(p["maximum"]) + 1.0
        if p["minimum"] is not None:
            return p, p["minimum"] - abs(p["minimum"]) - 1.0
    first = next(p for p in spec["inputs"] if p["kind"] in ("float", "int"))
    return first, "abc"


def _unit_options(page: Any, name: str) -> list[dict[str, Any]]:
    return page.eval_on_selector_all(
        f"#unit-{name} option",
        """os => os.map(o => ({
            value: o.value, factor: Number(o.dataset.factor), selected: o.selected
        }))""",
    )


# ---------------------------------------------------------------- the walk-through


def walk_through(page: Any, api: httpx.Client, base_url: str, name: str) -> None:
    spec = _describe(api, name)
    _open(page, base_url, f"m={name}")
    assert page.inner_text("#model-title") == spec["title"]
    assert page.locator(f'nav a[data-model="{name}"]').get_attribute("class") == "active"

    # every field: label, a unit (selector when several make sense), default and range
    for p in spec["inputs"]:
        field = page.locator(f'.field[data-field="{p["name"]}"]')
        assert p["label"] in field.locator("label").inner_text()
        if p["kind"] in ("float", "int"):
            hint = page.inner_text(f"#hint-{p['name']}")
            if p["minimum"] is not None or p["maximum"] is not None:
                assert "allowed: " in hint and any(s in hint for s in "<>≤≥"), hint
            if p["default"] is not None:
                assert "default " in hint, hint
            options = _unit_options(page, p["name"])
            if p["display_unit"] != p["unit"]:
                # the form opens in the model's display unit (add it to static/units.json if not)
                chosen = page.eval_on_selector(
                    f"#unit-{p['name']}", "u => u.value || u.textContent"
                )
                assert _norm_unit(chosen) == _norm_unit(p["display_unit"]) or any(
                    o["selected"] and _norm_unit(o["value"]) == _norm_unit(p["display_unit"])
                    for o in options
                ), f"{name}.{p['name']}: display unit {p['display_unit']!r} not offered"

    # the worked example (defaults fill the rest), chosen as a person would, as the API computes it
    _example(page)
    status = _submit(page)
    assert status == "ok", page.inner_text("#model")
    request = page.evaluate("window.calcState.lastRequest")
    expected = api.post(spec["path"], json=request)
    assert expected.status_code == 200
    expected_json = expected.json()
    _assert_page_matches(page, expected_json, spec)
    # and the unit strings the page sent mean the example's SI values
    example = spec["examples"][0] if spec["examples"] else {}
    direct = api.post(
        spec["path"], json={**example, "fidelity": request["fidelity"]} | _tol(request)
    )
    assert direct.status_code == 200
    for k, v in direct.json()["results"].items():
        assert _same(expected_json["results"][k], v, 1e-6), (k, expected_json["results"][k], v)

    # a series plot for every series the model returned
    if any(expected_json["series"].values()):
        ink = _canvas_ink(page, "#series-plots")
        assert ink and all(n > 500 for n in ink), ink

    # the downloads hold this result
    with page.expect_download() as dl:
        page.click("#download-json")
    saved = json.loads(Path(dl.value.path()).read_text("utf-8"))
    assert saved["request"] == request
    assert saved["response"]["results"] == page.evaluate("window.calcState.lastResponse.results")
    with page.expect_download() as dl:
        page.click("#download-csv")
    rows = list(csv.reader(io.StringIO(Path(dl.value.path()).read_text("utf-8"))))
    csv_results = {r[1]: r[2] for r in rows if r and r[0] == "result"}
    for k, v in expected_json["results"].items():
        if isinstance(v, float):
            assert math.isclose(float(csv_results[k]), v, rel_tol=1e-12), k

    _sweep(page, api, spec)
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(SHOTS / f"{spec['family']}--{name}.png"), full_page=True)

    # the link in the address bar reproduces the calculation in a fresh page
    link = page.url
    other = page.context.new_page()
    other.goto(link)
    other.wait_for_selector("body[data-result]")
    assert other.evaluate("document.body.dataset.result") == "ok"
    _assert_page_matches(other, expected_json, spec)
    other.close()

    # change a unit: the value is converted in the field and the answer stays the same
    for p in spec["inputs"]:
        options = _unit_options(page, p["name"]) if p["kind"] == "float" else []
        value = page.input_value(f"#in-{p['name']}") if options else ""
        if len(options) < 2 or not value:
            continue
        field, unit_sel = f"#in-{p['name']}", f"#unit-{p['name']}"
        old = next(o for o in options if o["selected"])
        new = next(o for o in options if not o["selected"])
        page.select_option(unit_sel, new["value"])
        converted = float(page.input_value(field))
        # a loaded value is shown to two figures more than in its display unit (5 to 7)
        assert math.isclose(converted, float(value) * old["factor"] / new["factor"], rel_tol=1e-5)
        # still the loaded value: sent as its exact SI number, so the answer is identical
        assert _submit(page) == "ok"
        assert page.evaluate("window.calcState.lastRequest")[p["name"]] == request[p["name"]]
        _assert_page_matches(page, expected_json, spec)
        # a typed value is sent as typed with its unit; switching back converts it
        rounded = f"{converted:.6g}"
        typed = next(
            t
            for t in (rounded, repr(float(rounded)), f"{converted:.6e}")
            if t != page.input_value(field)
        )
        page.fill(field, typed)
        assert _submit(page) == "ok"
        sent = page.evaluate("window.calcState.lastRequest")[p["name"]]
        assert sent == (f"{typed} {new['value']}" if new["value"] else float(typed)), sent
        first = page.evaluate("window.calcState.lastResponse")
        page.select_option(unit_sel, old["value"])
        back = float(page.input_value(field))
        # shown to two figures more than typed (here 8 or more), sent as its exact SI value
        assert math.isclose(back, float(typed) * new["factor"] / old["factor"], rel_tol=1e-7)
        assert _submit(page) == "ok"
        sent = page.evaluate("window.calcState.lastRequest")[p["name"]]
        assert sent == float(typed) * new["factor"], sent
        for k, v in page.evaluate("window.calcState.lastResponse.results").items():
            assert _same(v, first["results"][k], 1e-6), (p["name"], k, v, first["results"][k])
        # the link holds the typed value with its unit
        assert f"{p['name']}=" in page.url
        break

    # a bad value: marked at the field before submitting, then with the server's message
    bad, si_value = _bad_value(spec)
    if isinstance(si_value, float):
        unit = page.eval_on_selector(
            f"#unit-{bad['name']}",
            """u => Number(u.selectedOptions ? u.selectedOptions[0].dataset.factor
                                             : u.dataset.factor)""",
        )
        text = f"{si_value / unit:.10g}"
    else:
        text = si_value
    page.fill(f"#in-{bad['name']}", text)
    before = page.inner_text(f"#err-{bad['name']}")
    assert before, f"{name}.{bad['name']} = {text}: no message before submitting"
    assert _submit(page) == "error"
    refused = api.post(spec["path"], json=page.evaluate("window.calcState.lastRequest"))
    assert refused.status_code == 422
    messages = [d["msg"] for d in refused.json()["detail"] if d.get("field") == bad["name"]]
    assert messages, refused.json()
    # the field's message is in the user's unit and words (the form's own range check) or the
    # server's, named by the field's label; the server's own words are kept on the element
    shown = page.inner_text(f"#err-{bad['name']}")
    assert shown.startswith(bad["label"]), shown
    assert shown == before or shown == f"{bad['label']}: {messages[0]}", (shown, before, messages)
    assert page.get_attribute(f"#err-{bad['name']}", "data-server") == messages[0]
    assert page.locator(f'.field[data-field="{bad["name"]}"].invalid').count() == 1

    # a model whose default method returns no series (a closed form) may plot them with a
    # costlier rung (a simulation): plot the first that does, fresh from the example
    if any(o["series"] for o in spec["outputs"]) and not any(expected_json["series"].values()):
        for rung in spec["rungs"]:
            _open(page, base_url, f"m={name}")
            _example(page)
            page.select_option("#fidelity", rung["name"])
            if _submit(page) != "ok":
                continue
            if not any(page.evaluate("window.calcState.lastResponse.series").values()):
                continue
            ink = _canvas_ink(page, "#series-plots")
            assert ink and all(n > 500 for n in ink), (rung["name"], ink)
            shot = SHOTS / f"{spec['family']}--{name}--{rung['name']}.png"
            page.screenshot(path=str(shot), full_page=True)
            break


def _tol(request: dict[str, Any]) -> dict[str, Any]:
    return {"tolerance": request["tolerance"]} if "tolerance" in request else {}


# ---------------------------------------------------------------- the tests


@pytest.mark.parametrize("name", [s.name for s in TOYS])
def test_toy_model_in_the_browser(page, api, base_url, name):
    walk_through(page, api, base_url, name)


@pytest.mark.parametrize(
    "name",
    [s.name for s in REAL]
    or [
        pytest.param(
            None,
            marks=pytest.mark.skip(
                reason="engine.MODELS is empty: no real model registered yet to test in the browser"
            ),
        )
    ],
)
def test_registered_model_in_the_browser(page, api, base_url, name):
    walk_through(page, api, base_url, name)


def test_home_lists_every_family(page, api, base_url):
    _open(page, base_url, "")
    families = [h.strip() for h in page.locator("nav h2").all_text_contents()]
    catalogue = api.get("/models").json()["models"]
    assert families == list(dict.fromkeys(m["family"] for m in catalogue))
    assert page.locator(".card").count() == len(catalogue)
    page.click(f'nav a[data-model="{STRIKER.name}"]')
    page.wait_for_selector("#model-title")
    assert page.inner_text("#model-title") == STRIKER.title


def test_plots_shade_the_window_and_draw_a_histogram(page, base_url):
    _open(page, base_url, f"m={STRIKER.name}")
    _example(page)
    assert _submit(page) == "ok"
    titles = page.locator("#series-plots .u-title").all_inner_texts()
    # travel and flywheel speed against time; preload counts as a histogram over the bin edges
    assert titles == ["travel", "flywheel speed", "preload count (histogram)"]
    # the engagement window is shaded amber, rgba(255, 193, 7, 0.25) on the transparent
    # canvas, over both plots against time and not over the histogram
    amber = page.eval_on_selector_all(
        "#series-plots .chart canvas",
        """cs => cs.map(c => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0;
            for (let i = 0; i < d.length; i += 4)
                if (d[i] === 255 && Math.abs(d[i+1] - 193) < 3 && d[i+2] < 12
                    && Math.abs(d[i+3] - 64) < 3) n++;
            return n;
        })""",
    )
    assert amber[0] > 1000 and amber[1] > 1000 and amber[2] == 0, amber


def test_fidelity_selector_runs_the_named_rung(page, api, base_url):
    _open(page, base_url, f"m={TOY.name}")
    _example(page)
    page.select_option("#fidelity", "rough")
    assert page.is_disabled("#tolerance")
    assert _submit(page) == "ok"
    assert page.inner_text("#rung") == "rough"
    assert page.inner_text("#error-estimate") == "±5 %"
    assert "fidelity=rough" in page.url
    # auto with a 10 % tolerance picks the cheap rung too; 1 % needs the exact one
    page.select_option("#fidelity", "auto")
    page.fill("#tolerance", "10")
    assert _submit(page) == "ok"
    assert page.inner_text("#rung") == "rough"
    page.fill("#tolerance", "1")
    assert _submit(page) == "ok"
    assert page.inner_text("#rung") == "exact"


def test_infeasible_design_and_unit_strings(page, base_url):
    _open(page, base_url, f"m={TOY.name}")
    # a unit string typed into the field is passed through and parsed by the server
    page.fill("#in-diameter", "0.3 m")
    page.select_option("#in-mode", "broken")
    assert _submit(page) == "error"
    assert page.inner_text("#err-mode") == "mode: this disc is broken by design"
    page.select_option("#in-mode", "fine")
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastResponse.inputs.diameter") == 0.3
    # a required field left empty is marked before and after submitting
    page.fill("#in-diameter", "")
    assert "required" in page.inner_text("#err-diameter")
    assert _submit(page) == "error"
    assert "required" in page.inner_text("#err-diameter")


def test_result_units_and_a_shared_sweep(page, base_url):
    _open(page, base_url, f"m={STRIKER.name}")
    _example(page)
    assert _submit(page) == "ok"
    # a result shown in another unit is the same SI value converted
    row = page.locator('#results tr[data-output="peak_travel"]')
    assert row.locator("td.num").inner_text() == "10.0000"  # 0.01 m in mm, 6 figures
    row.locator("select.result-unit").select_option(label="m")
    assert row.locator("td.num").inner_text() == "0.0100000"
    # a sweep is part of the link: a fresh page computes and sweeps the same
    page.select_option("#sweep-output", "travel_time")
    page.select_option("#sweep-vary", "mass")
    page.fill("#sweep-num", "7")
    page.click("#sweep-run")
    page.wait_for_selector("body[data-sweep]")
    sweep = page.evaluate("window.calcState.lastSweep")
    assert len(sweep["response"]["values"]) == 7
    assert "sv=mass" in page.url and "so=travel_time" in page.url
    other = page.context.new_page()
    other.goto(page.url)
    other.wait_for_selector("body[data-sweep]")
    again = other.evaluate("window.calcState.lastSweep")
    assert again["request"] == sweep["request"]
    assert again["response"]["results"] == sweep["response"]["results"]
    assert _canvas_ink(other, "#sweep-plot")[0] > 500
    other.close()


def test_disc_spring_clutch_plots_its_falling_torque_against_lift(page, base_url):
    """Issue 17: the disc-spring limiter (clutch.ball, example 4) plots torque, spring force
    and stress against lift, the span over the rim shaded; the torque falls from the start."""
    from engine.models.clutch import BALL_CLUTCH

    index = next(i for i, ex in enumerate(BALL_CLUTCH.examples) if ex.get("spring_type") == "disc")
    _open(page, base_url, f"m=clutch.ball&ex={index}")
    page.wait_for_selector("body[data-result]")
    assert page.evaluate("document.body.dataset.result") == "ok"
    series = page.evaluate("window.calcState.lastResponse.series")
    torque = series["torque_curve"]
    assert len(torque) == len(series["lift"]) == 81
    assert all(b < a for a, b in itertools.pairwise(torque[:41]))  # falls along the flank
    ink = _canvas_ink(page, "#series-plots")
    assert ink and all(n > 500 for n in ink), ink
    amber = page.eval_on_selector_all(
        "#series-plots .chart canvas",
        """cs => cs.map(c => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0;
            for (let i = 0; i < d.length; i += 4)
                if (d[i] === 255 && Math.abs(d[i+1] - 193) < 3 && d[i+2] < 12
                    && Math.abs(d[i+3] - 64) < 3) n++;
            return n;
        })""",
    )
    assert all(n > 1000 for n in amber), amber  # "over the rim" shaded on every chart
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(SHOTS / "clutch--disc-spring-falling-curve.png"), full_page=True)


# ---------------------------------------------- issue 19: phone, state, report, designs

PHONE = {"width": 390, "height": 844}
DESKTOP = {"width": 1400, "height": 900}
DOCS_SHOTS = ROOT / "test-output" / "docs-screenshots"


def _wait_sweep(page: Any) -> str:
    page.wait_for_selector("body[data-sweep]")
    return page.evaluate("document.body.dataset.sweep")


@pytest.mark.parametrize("name", [s.name for s in (*REAL, STRIKER)])
def test_every_model_fits_a_phone_and_a_desktop(page, api, base_url, name):
    """Picked from the menu on a phone the form shows; nothing scrolls the page sideways."""
    spec = _describe(api, name)
    page.set_viewport_size(PHONE)
    _open(page, base_url, "")
    page.click(f'nav a[data-model="{name}"]')
    page.wait_for_selector("#model-title")
    top = page.eval_on_selector("#model-title", "e => e.getBoundingClientRect().top")
    assert 0 <= top < PHONE["height"] / 2, f"{name}: the form starts at {top} px, off the screen"
    _no_horizontal_scroll(page)
    _example(page)
    # the costliest rung returns the series (plots) where the model has any
    for rung in reversed(spec["rungs"]):
        page.select_option("#fidelity", rung["name"])
        if _submit(page) == "ok":
            break
    assert page.evaluate("document.body.dataset.result") == "ok", page.inner_text("#model")
    page.fill("#sweep-num", "5")
    page.click("#sweep-run")
    _wait_sweep(page)
    _no_horizontal_scroll(page)
    right = page.eval_on_selector_all(
        "canvas", "cs => Math.max(0, ...cs.map(c => c.getBoundingClientRect().right))"
    )
    assert right <= PHONE["width"], f"{name}: a plot ends at {right} px"
    # the report view fits too
    page.click("#show-report")
    assert page.is_visible("#report-body")
    _no_horizontal_scroll(page)
    page.click("#close-report")
    assert page.is_visible("#form")
    page.set_viewport_size(DESKTOP)
    page.wait_for_timeout(250)  # the plots follow the window's width
    _no_horizontal_scroll(page)


def test_a_shared_sweep_link_keeps_its_unit(page, base_url):
    """A sweep over 73–220 rad/s reopens as 73–220 rad/s (not rpm), with the same numbers."""
    _open(page, base_url, f"m={STRIKER.name}")
    _example(page)
    assert _submit(page) == "ok"
    page.select_option("#sweep-vary", "speed")
    page.select_option("#sweep-unit", label="rad/s")
    page.fill("#sweep-start", "73")
    page.fill("#sweep-stop", "220")
    page.fill("#sweep-num", "6")
    page.select_option("#sweep-output", "travel_time")
    page.click("#sweep-more summary")
    page.check('#sweep-more input[value="stiffness_ratio"]')
    page.click("#sweep-run")
    assert _wait_sweep(page) == "ok"
    sweep = page.evaluate("window.calcState.lastSweep")
    assert sweep["request"]["start"] == "73 rad/s" and sweep["request"]["stop"] == "220 rad/s"
    assert sweep["request"]["outputs"] == ["travel_time", "stiffness_ratio"]
    assert sweep["response"]["values"][0] == pytest.approx(73.0)
    assert "su=rad%2Fs" in page.url
    # every input is in the link with its unit
    assert "mass=" in page.url and "stroke=" in page.url
    other = page.context.new_page()
    other.goto(page.url)
    assert _wait_sweep(other) == "ok"
    again = other.evaluate("window.calcState.lastSweep")
    assert again["request"] == sweep["request"]
    assert again["response"]["results"] == sweep["response"]["results"]
    # two outputs in two units: twin axes, one canvas
    assert len(_canvas_ink(other, "#sweep-plot")) == 1
    # the sweep is marked stale when an input it kept fixed changes, not the one it varies
    assert other.is_hidden("#sweep-stale")
    other.fill("#in-speed", "1")
    assert other.is_hidden("#sweep-stale")
    other.fill("#in-mass", str(float(other.input_value("#in-mass")) * 2))
    assert other.is_visible("#sweep-stale")
    # and the sweep downloads
    with other.expect_download() as dl:
        other.click("#sweep-csv")
    rows = list(csv.reader(io.StringIO(Path(dl.value.path()).read_text("utf-8"))))
    assert rows[0][0].startswith("speed [rad/s]") and len(rows) == 7
    assert float(rows[1][0]) == pytest.approx(73.0)
    with other.expect_download() as dl:
        other.click("#sweep-json")
    saved = json.loads(Path(dl.value.path()).read_text("utf-8"))
    assert saved["response"]["results"] == sweep["response"]["results"]
    other.close()


def test_stale_results_are_marked_and_units_read_by_people(page, base_url):
    _open(page, base_url, f"m={TOY.name}")
    _example(page)
    assert _submit(page) == "ok"
    assert page.is_hidden("#stale-note")
    first = page.evaluate("window.calcState.lastResponse.results")
    shown = page.input_value("#in-diameter")
    page.fill("#in-diameter", str(float(shown) * 2))
    # marked the moment the input differs, and the result is dimmed
    assert page.is_visible("#stale-note")
    assert "compute again" in page.inner_text("#stale-note")
    assert "stale" in page.get_attribute("#result", "class")
    page.fill("#in-diameter", shown)
    assert page.is_hidden("#stale-note")
    # a unit change is no change of input
    page.select_option("#unit-diameter", "m")
    assert page.is_hidden("#stale-note")
    page.select_option("#unit-diameter", "mm")
    # a decimal comma is read as a point once the comma is the decimal separator
    page.select_option("#decimal-sep", ",")
    page.fill("#in-diameter", shown.replace(".", ",") if "." in shown else shown + ",5")
    assert page.inner_text("#err-diameter") == ""
    assert page.is_visible("#stale-note")
    assert _submit(page) == "ok"
    assert page.is_hidden("#stale-note")
    sent = page.evaluate("window.calcState.lastRequest.diameter")
    assert "," not in sent and sent.endswith(" mm")
    page.select_option("#decimal-sep", ".")
    # imperial: every unit changes at once, the answer does not
    page.fill("#in-diameter", shown)
    assert _submit(page) == "ok"
    page.select_option("#unit-system", "imperial")
    assert page.inner_text("#unit-diameter option:checked") == "in"
    assert page.is_hidden("#stale-note")
    assert _submit(page) == "ok"
    for k, v in page.evaluate("window.calcState.lastResponse.results").items():
        assert _same(v, first[k], 1e-9), k
    # the choice stays for the next form; a link's own units win over it
    _open(page, base_url, f"m={TOY.name}")
    assert page.inner_text("#unit-diameter option:checked") == "in"
    _open(page, base_url, f"m={TOY.name}&ex=0&diameter=150%20mm")
    assert page.inner_text("#unit-diameter option:checked") == "mm"
    assert page.inner_text("#unit-mass option:checked") == "lb"
    page.select_option("#unit-system", "metric")
    assert page.inner_text("#unit-diameter option:checked") == "mm"
    assert page.inner_text("#unit-mass option:checked") == "kg"


def test_histogram_bins_span_full_width_with_limit_lines(page, api, base_url):
    name = "preload.control"
    if name not in [s.name for s in REAL]:
        pytest.skip("preload.control is not registered")
    _open(page, base_url, f"m={name}&ex=0")
    page.wait_for_selector("body[data-result]")
    data = page.evaluate("window.calcState.lastResponse")
    chart = page.evaluate(
        """() => { const c = window.calcState.charts.find(c => c.kind === 'series');
                   return {x: c.chart.data[0], y: c.chart.data[1],
                           min: c.chart.scales.x.min, max: c.chart.scales.x.max}; }"""
    )
    centres = data["series"]["preload_bins"]
    width = (centres[-1] - centres[0]) / (len(centres) - 1) / 1e3
    # the edges half a bin outside the first and last centres: full-width bins
    assert chart["x"][0] == pytest.approx(centres[0] / 1e3 - width / 2)
    assert chart["x"][-1] == pytest.approx(centres[-1] / 1e3 + width / 2)
    assert chart["y"][:-1] == data["series"]["preload_counts"]
    # the axis shows the required and the yield preload the table lists
    assert chart["min"] <= data["results"]["required_preload"] / 1e3
    assert chart["max"] >= data["results"]["yield_preload"] / 1e3
    # method names, not codes; ratios in %; a failed check summarised at the top
    assert "torque_wrench" not in page.inner_text("#results")
    assert "%" in page.inner_text('#results tr[data-output="scatter"]')
    assert page.is_visible("#check-summary")


def test_save_open_and_compare_designs(page, base_url, tmp_path):
    _open(page, base_url, f"m={TOY.name}")
    _example(page)
    page.fill("#report-part", "disc A")
    assert _submit(page) == "ok"
    first = page.evaluate("window.calcState.lastResponse.results")
    with page.expect_download() as dl:
        page.click("#save-design")
    a = tmp_path / "a.design.json"
    dl.value.save_as(a)
    design = json.loads(a.read_text("utf-8"))
    assert design["model"] == TOY.name and design["part"] == "disc A"
    assert design["inputs"]["diameter"].endswith(" mm")  # every input with its unit
    assert set(design["inputs"]) >= {"mass", "diameter", "speed", "mode"}
    page.fill("#in-diameter", "150")
    page.fill("#report-part", "disc B")
    assert _submit(page) == "ok"
    with page.expect_download() as dl:
        page.click("#save-design")
    b = tmp_path / "b.design.json"
    dl.value.save_as(b)

    # opened from another model's page, the file brings back the form and the result
    _open(page, base_url, f"m={STRIKER.name}")
    page.evaluate("delete document.body.dataset.result")
    page.set_input_files("#open-design", str(a))
    page.wait_for_selector("body[data-result]")
    assert page.inner_text("#model-title") == TOY.title
    assert page.input_value("#report-part") == "disc A"
    assert page.evaluate("window.calcState.lastResponse.results") == first

    page.set_input_files("#compare-designs", [str(a), str(b)])
    page.wait_for_selector("body[data-compare]")
    assert page.is_visible("#compare-table")
    heads = page.locator("#compare-table thead th").all_inner_texts()
    assert heads[1:] == ["disc A", "disc B"]
    rows = page.locator("#compare-table tbody tr.differs th").all_inner_texts()
    assert any(r.startswith("diameter") for r in rows) and any(
        r.startswith("inertia") for r in rows
    )
    assert not any(r.startswith("mass") for r in rows)
    assert page.locator("#compare-table td.diff").count() >= 2
    DOCS_SHOTS.mkdir(parents=True, exist_ok=True)
    page.locator("#compare").screenshot(path=str(DOCS_SHOTS / "comparison.png"))


def _pdf_tools() -> None:
    import shutil

    if not all(shutil.which(t) for t in ("pdfinfo", "pdftoppm", "pdftotext")):
        _cannot_run("pdfinfo/pdftoppm/pdftotext are missing: apt-get install -y poppler-utils")


@pytest.mark.parametrize("name", [s.name for s in (*REAL, STRIKER)])
def test_report_prints_every_equation_on_one_to_eight_a4_pages(page, base_url, tmp_path, name):
    """/report?… opens the report with every equation of the model; printed to PDF it is A4,
    one to eight pages (the joint's VDI 2230 chain with its eccentric, torsion and fitted-bolt
    relations takes about three pages of equations, its plots 12 cm wide and the VDI diagram
    another; seven in all), numbered "page n of N" under a running header, with symbols and the
    standard's step per result, the author, checker and revision, the product's version,
    and a sign-off."""
    import subprocess

    _pdf_tools()
    names = "proj=Line%203&part=Flange&auth=A.%20Author&chk=C.%20Checker&rev=B"
    page.goto(f"{base_url}/report?m={name}&ex=0&{names}")
    page.wait_for_selector("body[data-result]")
    assert page.evaluate("document.body.dataset.result") == "ok"
    assert page.is_visible("#report") and page.is_hidden("#form")
    assert page.inner_text("#report-meta").count("UTC") == 1
    body = page.inner_text("#report-body")
    assert "Inputs" in body and "Results" in body
    # the equations of the rung that ran (its declared steps), else the model's: every one
    listed = page.evaluate(
        "(() => { const s = window.calcState, m = s.model;"
        " const r = (m.rungs || []).find((x) => x.name === s.lastResponse.rung);"
        " return ((r && r.equations) || m.equations).length; })()"
    )
    assert page.locator("#report .eq-row").count() == listed  # every one, no cap
    if listed:
        # equations rendered by KaTeX, not LaTeX source
        assert page.locator("#report .katex").count() >= 3
        assert "\\frac" not in body
    pdf = tmp_path / "report.pdf"
    page.pdf(path=str(pdf), prefer_css_page_size=True, print_background=True)
    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=True)
    pages = int(re.search(r"Pages:\s+(\d+)", info.stdout)[1])
    size = re.search(r"Page size:\s+([\d.]+) x ([\d.]+)", info.stdout)
    assert 1 <= pages <= 8, f"{name}: the report prints on {pages} pages"
    assert abs(float(size[1]) - 595) < 2 and abs(float(size[2]) - 842) < 2, info.stdout
    subprocess.run(["pdftoppm", "-r", "60", "-png", str(pdf), str(tmp_path / "page")], check=True)
    pngs = sorted(tmp_path.glob("page*.png"))
    assert len(pngs) == pages and all(p.stat().st_size > 5000 for p in pngs)
    text = subprocess.run(
        ["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True
    ).stdout
    assert "Line 3" in text and "Flange" in text and "Calculation report" in text
    assert (listed > 0) == ("Equations used" in text)
    # page numbers and the running header on every page; names, version, sign-off
    for n in range(1, pages + 1):
        assert f"page {n} of {pages}" in text, (name, n)
    assert text.count(f"Calculation report · {page.inner_text('#model-title')}") == pages
    flat = " ".join(text.split())  # the PDF's lines joined
    for words in ("A. Author", "C. Checker", "Revision B", "Sign-off", "tightening-calc 0.1.0"):
        assert words in flat, (name, words)
    if name in ("joint.vdi2230", "preload.tightening"):
        assert page.inner_text("#report-fastener") == "M12 8.8"
    # results with their symbols and steps (the joint: VDI 2230-1's R-steps)
    header = page.eval_on_selector_all(
        "#report-body table.results:not(.inputs) thead th", "hs => hs.map(h => h.textContent)"
    )
    assert header == ["result", "symbol", "value", "unit", "step, source"]
    if name == "joint.vdi2230":
        row = page.inner_text('#report-body tr[data-output="residual_clamp_force_min"]')
        assert "FKR,min" in row and "VDI 2230-1 R12" in row, row
    if name == "preload.control":
        DOCS_SHOTS.mkdir(parents=True, exist_ok=True)
        subprocess.run(
            ["pdftoppm", "-r", "90", "-png", "-f", "1", "-l", "1", str(pdf),
             str(DOCS_SHOTS / "report")], check=True,
        )  # fmt: skip


def test_thread_picker_sends_the_designation_or_fills_the_numbers(page, base_url):
    """With GET /api/v1/fasteners (here stubbed), a model that reads designations is sent
    the designation (an inch thread with its grade); a model of numbers gets them filled."""
    names = [s.name for s in REAL]
    if "preload.tightening" not in names or "blow.joint" not in names:
        pytest.skip("preload.tightening or blow.joint is not registered")
    threads = [
        {"designation": "M12", "diameter": 0.012, "pitch": 0.00175, "series": "coarse",
         "bearing_diameter": 0.01663, "hole_diameter": 0.0135, "grade": None},
        {"designation": "M12x1.25", "diameter": 0.012, "pitch": 0.00125, "series": "fine",
         "bearing_diameter": 0.01663, "hole_diameter": 0.0135, "grade": None},
        {"designation": "1/2-13 UNC", "diameter": 0.0127, "pitch": 0.0254 / 13, "series": "UNC",
         "bearing_diameter": 0.0180975, "hole_diameter": 0.0134874, "grade": "SAE 5"},
    ]  # fmt: skip
    catalogue = {
        "threads": threads,
        "property_classes": [{"name": "8.8", "yield_strength": 640e6, "tensile_strength": 800e6}],
        "materials": [],
    }

    page.route("**/api/v1/fasteners", lambda route: route.fulfill(json=catalogue))
    _open(page, base_url, "m=preload.tightening")
    assert "R_p0.2 640 MPa" in page.inner_text("#in-property_class")
    page.select_option("#thread-picker", label="1/2-13 UNC (UNC)")
    assert page.input_value("#in-thread") == "1/2-13 UNC"
    assert page.input_value("#in-grade") == "SAE 5"
    assert page.input_value("#in-thread_diameter") == ""
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastResponse.inputs.grade") == "SAE 5"
    # a metric thread drops the inch grade; a designation typed into the diameter field too
    page.fill("#in-thread_diameter", "m12x1.25")
    page.dispatch_event("#in-thread_diameter", "change")
    assert page.input_value("#in-thread") == "M12x1.25"
    assert page.input_value("#in-grade") == ""
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastResponse.inputs.thread") == "M12x1.25"
    # a model of numbers: diameter, pitch, bearing face and hole
    _open(page, base_url, "m=blow.joint")
    page.select_option("#thread-picker", label="M12x1.25 (fine)")
    assert page.input_value("#in-thread_diameter") == "12"
    assert page.input_value("#in-thread_pitch") == "1.25"
    assert page.input_value("#in-bearing_outer_diameter") == "16.63"
    assert page.input_value("#in-hole_diameter") == "13.5"


def test_inputs_announce_their_unit_and_range(page, base_url):
    _open(page, base_url, f"m={TOY.name}")
    ids = page.get_attribute("#in-diameter", "aria-describedby").split()
    assert ids == ["desc-diameter", "hint-diameter", "err-diameter", "read-diameter"]
    assert "allowed" in page.inner_text(f"#{ids[1]}")
    assert page.get_attribute("#unit-diameter", "aria-label") == "diameter unit"
    # plots have a table as their text alternative
    _open(page, base_url, f"m={STRIKER.name}")
    assert _submit(page) == "ok"
    assert page.locator("#series-plots details.data-table table").count() == 3


# ---------------------------------------------- issue 31: entry that cannot go silently wrong

# (decimal separator, typed, value read or None when refused); "2,000" was read as 2 before
READINGS = [
    (".", "2,000", 2000.0), (".", "1,500.25", 1500.25), (".", "2 000", 2000.0),
    (".", "2\u202f000", 2000.0), (".", "12,345,678", 12345678.0), (".", "2,5", None),
    (".", "2,00", None), (".", "1,5e3", None), (".", "1.5e3", 1500.0), (".", "-.5", -0.5),
    (",", "2,5", 2.5), (",", "2.000", 2000.0), (",", "2 000", 2000.0), (",", "1.234,5", 1234.5),
    (",", "2.5", None), (",", "1,5e-3", 0.0015), (",", "2,000", 2.0), (".", "", None),
    (".", "abc", None), (".", "1..5", None), (",", ",5", 0.5),
]  # fmt: skip


def test_numbers_are_read_by_the_decimal_separator_setting(page: Any, base_url: str) -> None:
    """The page's one number reader (static/numbers.js), run in the browser as a unit test."""
    _open(page, base_url, "")
    got = page.evaluate(
        """async (cases) => {
            const n = await import('./numbers.js');
            return cases.map(([dec, text]) => { const r = n.readNumber(text, dec);
                                               return r.ok ? r.value : null; });
        }""",
        [[d, t] for d, t, _ in READINGS],
    )
    assert got == [v for _, _, v in READINGS]
    quantity = page.evaluate(
        """async () => { const n = await import('./numbers.js');
            return [n.readQuantity('2,000 lbf', '.'), n.readQuantity('1 000 mm', ','),
                    n.readQuantity('2,5 mm', '.').ok, n.readQuantity('M12', '.').text,
                    n.echoNumber(12345.5, ','), n.echoNumber(2000, '.')]; }"""
    )
    assert quantity[0] | {} == {"ok": True, "value": 2000, "canonical": "2000", "grouped": True,
                                "unit": "lbf"}  # fmt: skip
    assert (quantity[1]["canonical"], quantity[1]["unit"]) == ("1000", "mm")
    assert quantity[2:] == [False, True, "12\u202f345,5", "2000"]


def test_imperial_2000_lbf_is_sent_as_2000_lbf_or_refused(page: Any, base_url: str) -> None:
    """Typed "2,000" in lbf is 2,000 lbf with a decimal point, echoed beside the field;
    "2,5" is refused at the field and not sent; with a decimal comma the reverse."""
    name = "joint.vdi2230"
    if name not in [s.name for s in REAL]:
        pytest.skip(f"{name} is not registered")
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ".")
    page.select_option("#unit-system", "imperial")
    _open(page, base_url, f"m={name}&ex=0")
    page.wait_for_selector("body[data-result]")
    assert page.inner_text("#unit-working_load option:checked") == "lbf"
    page.fill("#in-working_load", "2,000")
    assert page.inner_text("#read-working_load") == "= 2000 lbf"
    assert page.inner_text("#err-working_load") == ""
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastRequest.working_load") == "2000 lbf"
    n_per_lbf = 4.4482216152605  # 1 lbf = 0.45359237 kg × 9.80665 m/s²
    sent = page.evaluate("window.calcState.lastResponse.inputs.working_load")
    assert sent == pytest.approx(2000 * n_per_lbf, rel=1e-12)
    assert "working_load=2000+lbf" in page.url  # the link holds the canonical number
    # a decimal comma under a decimal point: refused at the field, nothing sent
    before = page.evaluate("window.calcState.lastResponse.inputs.working_load")
    page.fill("#in-working_load", "2,5")
    message = page.inner_text("#err-working_load")
    assert "“2,5” is not a number with the decimal point" in message, message
    assert page.inner_text("#read-working_load") == ""
    assert _submit(page) == "error"
    assert "cannot be read" in page.inner_text("#error-box")
    assert page.evaluate("window.calcState.lastResponse.inputs.working_load") == before
    # the comma as decimal separator: "2,5" is 2.5 lbf; "2.000" and "2 000" group
    page.select_option("#decimal-sep", ",")
    assert page.inner_text("#err-working_load") == ""
    assert _submit(page) == "ok"
    assert page.evaluate("window.calcState.lastRequest.working_load") == "2.5 lbf"
    for typed in ("2.000", "2 000"):
        page.fill("#in-working_load", typed)
        assert page.inner_text("#read-working_load") == "= 2000 lbf"
        assert _submit(page) == "ok"
        assert page.evaluate("window.calcState.lastRequest.working_load") == "2000 lbf"
    page.fill("#in-working_load", "2.5")
    assert "decimal comma" in page.inner_text("#err-working_load")
    # loaded numbers are shown with the comma; the setting stays for the next page
    _open(page, base_url, f"m={name}&ex=0")
    assert "," in page.input_value("#in-thread_diameter")
    assert page.input_value("#decimal-sep") == ","
    # the sweep's range is read the same way
    page.wait_for_selector("body[data-result]")
    page.select_option("#sweep-vary", "working_load")
    page.fill("#sweep-start", "1.000")
    page.fill("#sweep-stop", "2.000")
    assert page.inner_text("#sweep-read") == "= 1000 … 2000 lbf"
    page.fill("#sweep-num", "3")
    page.click("#sweep-run")
    assert _wait_sweep(page) == "ok"
    sweep = page.evaluate("window.calcState.lastSweep.request")
    assert (sweep["start"], sweep["stop"]) == ("1000 lbf", "2000 lbf")
    page.fill("#sweep-stop", "2.5")
    assert "decimal comma" in page.inner_text("#sweep-read")
    page.evaluate("delete document.body.dataset.sweep")
    page.click("#sweep-run")
    assert _wait_sweep(page) == "error"
    assert "Sweep not run" in page.inner_text("#sweep-error")


def test_the_study_page_reads_numbers_by_the_same_setting(page: Any, base_url: str) -> None:
    _open(page, base_url, "")
    page.select_option("#decimal-sep", ",")
    page.goto(f"{base_url}/study.html?model={STRIKER.name}")
    page.wait_for_selector("#study-rows tr")
    assert page.input_value("#decimal-sep") == ","
    row = 'tr[data-name="mass"]'
    page.fill(f"{row} input[data-name]", "2.000")
    assert page.inner_text(f"{row} output.read-as") == "= 2000 kg"
    page.fill(f"{row} input[data-name]", "2.5")
    assert "decimal comma" in page.inner_text(f"{row} output.read-as")
    page.check('tr[data-name="speed"] input[type=checkbox]')
    page.click("#study-run")
    assert "decimal comma" in page.inner_text("#study-error")
    assert page.is_enabled("#study-run")  # nothing was submitted


@pytest.mark.parametrize("name", [s.name for s in (*REAL, TOY)])
def test_a_new_design_starts_from_the_declared_defaults(
    page: Any, api: httpx.Client, base_url: str, name: str
) -> None:
    """The form opens on the model's declared defaults (nothing from an example); Compute
    either answers or names at its field each input still missing; example 1 is one choice
    away and computes."""
    spec = _describe(api, name)
    _open(page, base_url, f"m={name}")
    assert page.input_value("#example") == "defaults"
    for p in spec["inputs"]:
        field = f"#in-{p['name']}"
        if p["kind"] == "bool":
            assert page.is_checked(field) == bool(p["default"]), p["name"]
        elif p["kind"] in ("choice", "text"):
            assert page.input_value(field) == (p["default"] or ""), p["name"]
        elif p["default"] is None:
            assert page.input_value(field) == "", p["name"]  # nothing invented
        else:
            factor = page.eval_on_selector(
                f"#unit-{p['name']}",
                "u => Number(u.selectedOptions ? u.selectedOptions[0].dataset.factor"
                " : u.dataset.factor)",
            )
            shown = float(page.input_value(field)) * factor
            assert shown == pytest.approx(p["default"], rel=1e-6, abs=1e-300), p["name"]
    # Compute answers, or names at its field each input still missing
    if _submit(page) == "error":
        marked = page.eval_on_selector_all(".field.invalid", "fs => fs.map(f => f.dataset.field)")
        box = page.inner_text("#error-box")
        assert marked, box
        labels = {p["name"]: p["label"] for p in spec["inputs"]}
        for field in marked:
            assert labels[field] in box and page.inner_text(f"#err-{field}"), (field, box)
        missing = [p["name"] for p in spec["inputs"] if p["required"] and p["default"] is None]
        assert set(missing) <= set(marked), (missing, marked)
    # the worked example is one choice away
    if spec["examples"]:
        page.select_option("#example", "0")
        assert _submit(page) == "ok", page.inner_text("#error-box")
        if name == "joint.vdi2230":  # example 1's transverse load is the example's, not a default
            assert page.evaluate("window.calcState.lastResponse.inputs.transverse_load") == 2000.0
            page.select_option("#example", "defaults")
            assert page.input_value("#in-transverse_load") == "0"


# ---------------------------------------------- issue 31: the answer in reach

ANSWER_MODEL = "joint.vdi2230" if "joint.vdi2230" in [s.name for s in REAL] else STRIKER.name
CONTROLS = (
    "#form input:not(.file), #form select, #form button, #model .actions button,"
    " #model .actions select, #model .actions label.button"
)


@pytest.fixture()
def phone(browser: Any, base_url: str) -> Iterator[Any]:
    """A 390 px phone page (twice the pixels, for legible screenshots), local requests only."""
    context = browser.new_context(viewport=PHONE, device_scale_factor=2, has_touch=True)
    context.set_default_timeout(TIMEOUT_MS)
    context.route(
        "**/*",
        lambda route: (
            route.continue_() if route.request.url.startswith(base_url) else route.abort()
        ),
    )
    pg = context.new_page()
    problems: list[str] = []
    pg.on("pageerror", lambda exc: problems.append(str(exc)))
    yield pg
    context.close()
    assert not problems, problems


def _in_view(page: Any, selector: str) -> bool:
    return bool(
        page.eval_on_selector(
            selector,
            "e => { const b = e.getBoundingClientRect();"
            " return b.top >= 0 && b.bottom <= innerHeight && b.height > 0; }",
        )
    )


def _focused(page: Any) -> str:
    return str(page.evaluate("document.activeElement ? document.activeElement.id : ''"))


def test_keyboard_reaches_compute_and_the_answer_on_a_desktop(page: Any, base_url: str) -> None:
    """A skip link leads to Compute (the first Tab, where 108 Tabs were needed); after
    Compute from a field at the top of the form the result is in view and its heading has
    the focus; one live region says what happened (there were 66 alert regions)."""
    page.set_viewport_size(DESKTOP)
    _open(page, base_url, f"m={ANSWER_MODEL}")
    live = "document.querySelectorAll('[role=alert], [role=status], [aria-live]').length"
    assert page.evaluate(live) == 1
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.textContent") == "Skip to Compute"
    page.keyboard.press("Enter")
    assert _focused(page) == "compute" and _in_view(page, "#compute")
    assert "#m=" in page.url  # the skip link leaves the route alone
    DOCS_SHOTS.mkdir(parents=True, exist_ok=True)
    page.evaluate("window.scrollTo(0, 0)")
    page.screenshot(path=str(DOCS_SHOTS / "desktop-form.png"))
    _example(page)
    page.focus("#form input[type=text]")
    page.evaluate("window.scrollTo(0, 0)")
    page.evaluate("delete document.body.dataset.result")
    page.keyboard.press("Enter")
    page.wait_for_selector("body[data-result]")
    assert page.evaluate("document.body.dataset.result") == "ok"
    assert _focused(page) == "result-heading"
    assert page.get_attribute("#result-heading", "tabindex") == "-1"
    assert _in_view(page, "#result-heading")
    assert page.inner_text("#announce").startswith("Computed")
    assert page.evaluate(live) == 1
    page.screenshot(path=str(DOCS_SHOTS / "desktop-results.png"))
    # a refusal is said in the same region, and the focus goes to the field refused
    first = page.eval_on_selector("#form input[inputmode=decimal]", "e => e.id")
    page.fill(f"#{first}", "-1")
    assert _submit(page) == "error"
    assert page.inner_text("#announce").startswith("Not computed")
    marked = ".field.invalid input, .field.invalid select"
    assert _focused(page) == page.eval_on_selector(marked, "e => e.id")


@pytest.mark.parametrize("name", [s.name for s in (*REAL, STRIKER)])
def test_on_a_phone_compute_is_on_the_first_screen_and_every_control_44px(
    phone: Any, base_url: str, name: str
) -> None:
    """Picked from the menu on a 390 px phone: Compute shows at once (a bar at the bottom of
    the window; it was 10 screens down), no control of the form is under 44 px (207 of 212
    were), and after Compute the result is in view with the focus on its heading."""
    _open(phone, base_url, "")
    phone.click(f'nav a[data-model="{name}"]')
    phone.wait_for_selector("#model-title")
    assert _in_view(phone, "#compute"), f"{name}: Compute is off the first screen"
    small = phone.eval_on_selector_all(
        CONTROLS,
        """cs => cs.filter(c => c.offsetParent !== null)
                   .map(c => [c.id || c.name || c.textContent, c.getBoundingClientRect().height])
                   .filter(([, h]) => h < 44)""",
    )
    assert not small, f"{name}: controls under 44 px: {small}"
    if name == ANSWER_MODEL:
        DOCS_SHOTS.mkdir(parents=True, exist_ok=True)
        phone.screenshot(path=str(DOCS_SHOTS / "phone-form.png"))
    _example(phone)
    phone.evaluate("delete document.body.dataset.result")
    phone.click("#compute")  # no scrolling: the bar is on screen
    phone.wait_for_selector("body[data-result]")
    assert phone.evaluate("document.body.dataset.result") == "ok"
    assert _focused(phone) == "result-heading" and _in_view(phone, "#result-heading")
    if name == ANSWER_MODEL:
        phone.screenshot(path=str(DOCS_SHOTS / "phone-results.png"))
