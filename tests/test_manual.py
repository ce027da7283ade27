"""The manual: it builds (``mkdocs build --strict``: a broken link or anchor fails), every
model has its page and its validation page, the worked examples on the pages show the
numbers ``engine.run`` gives, the pages run under the service's CSP, and the service
serves them at ``/manual/`` (or, not built, a page saying how to build it; never a 500).
"""

from __future__ import annotations

import doctest
import html
import importlib.util
import math
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest
from fastapi.testclient import TestClient

import engine
from service import create_app
from service.config import Settings
from service.middleware import STRICT_CSP
from tests.toys import TOY

ROOT = Path(__file__).resolve().parents[1]


def _hooks() -> ModuleType:
    spec = importlib.util.spec_from_file_location("manual_hooks", ROOT / "scripts/manual/hooks.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


HOOKS = _hooks()


def test_hook_doctests() -> None:
    pytest.importorskip("markdown")  # mkdocs's own dependency; in the dev lock
    assert doctest.testmod(HOOKS).failed == 0


def test_every_model_and_every_validation_module_is_placed() -> None:
    assert set(HOOKS.VALIDATION) == {s.name for s in engine.MODELS}
    placed = {m for modules in HOOKS.VALIDATION.values() for m in modules}
    present = {p.name for p in (ROOT / "tests/validation").glob("test_*.py")}
    assert placed == present, "place each validation module on its models' pages"


def test_numbers_print_as_the_page_prints_them() -> None:
    # six significant figures, SI; nothing non-finite ever printed as a number
    assert HOOKS.fmt(83.63534251785468) == "83.6353"
    assert HOOKS.fmt(1.0e-5) == "1e-05"
    assert HOOKS.fmt(math.nan) == "—"
    assert HOOKS.fmt("M12 8.8") == "M12 8.8"


def test_a_model_s_accuracy_rows_are_its_own(tmp_path: Path) -> None:
    table = tmp_path / "accuracy.md"
    assert HOOKS.accuracy_rows("clutch.ball", table) is None
    table.write_text(
        "# Accuracy\n\nMeasured 2026-01-01.\n\n| model | method | bound |\n|---|---|---|\n"
        "| `clutch.ball` | closed_form | 25 % |\n| `clutch.ball_setting` | closed_form | 1 % |\n",
        encoding="utf-8",
    )
    rows = HOOKS.accuracy_rows("clutch.ball", table)
    assert rows.splitlines() == [
        "| model | method | bound |",
        "|---|---|---|",
        "| `clutch.ball` | closed_form | 25 % |",
    ]
    assert HOOKS.accuracy_rows("impact.rare", table) == ""


def test_load_figures_are_the_last_bench_run_s_with_its_date(tmp_path: Path) -> None:
    assert "make bench" in HOOKS.loadtest_section(tmp_path / "none.json")
    figures = tmp_path / "loadtest.json"
    figures.write_text(
        '{"when": "2026-01-02T03:04:05+00:00", "machine": {"cpus": 2}, "concurrency": 8,'
        ' "requests_per_endpoint": 2000, "endpoints": {"healthz": {"requests_per_s": 9602.8,'
        ' "p50_ms": 0.75, "p99_ms": 0.87}}, "models": {"clutch.ball": {"requests_per_s":'
        ' 2589.9, "p99_ms": 3.48, "vs_healthz": 0.285, "ceiling_vs_healthz": 0.4}},'
        ' "sweeps": {"clutch.ball": {"median_ms": 2.59}}}',
        encoding="utf-8",
    )
    text = HOOKS.loadtest_section(figures)
    assert "on 2026-01-02: a 2-core machine" in text
    assert "<td><code>/healthz</code></td><td>9,603</td><td>0.75</td><td>0.87</td>" in text
    row = "<td><code>clutch.ball</code></td><td>2,590</td><td>3.48</td><td>0.28</td><td>0.40</td>"
    assert row + "<td>2.59</td>" in text


def test_hand_written_pages_exist() -> None:
    for _, page in HOOKS.PAGES:
        assert (ROOT / "docs" / page).is_file(), page


@pytest.fixture(scope="module")
def app() -> TestClient:
    """The real app, without its start-up warm-up (the manual not needed)."""
    return TestClient(create_app(settings=Settings(warm_up=False)))


def _curls(text: str) -> list[list[str]]:
    """The curl commands of a Markdown text's ``sh`` blocks, split as the shell would."""
    found: list[list[str]] = []
    for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S):
        command: list[str] | None = None  # the curl being read, None outside one
        for word in shlex.split(block.replace("\\\n", " "), comments=True):
            if word == "curl":
                command = []
                found.append(command)
            elif word in ("&&", "||", ";", "|"):
                command = None
            if command is not None:
                command.append(word)
    return found


@pytest.mark.parametrize("page", ["README.md", "index.md", "api.md"])
def test_curl_examples_answer_as_documented(app: TestClient, page: str) -> None:
    # every curl in the README and the guides is a real route that takes its body
    path = ROOT / page if page == "README.md" else ROOT / "docs" / page
    curls = _curls(path.read_text(encoding="utf-8"))
    assert len(curls) >= 1
    for words in curls:
        (url,) = [w for w in words if w.startswith("http://127.0.0.1:8000/")]
        body = words[words.index("-d") + 1] if "-d" in words else None
        route = url.removeprefix("http://127.0.0.1:8000")
        answer = (
            app.post(route, content=body, headers={"content-type": "application/json"})
            if body is not None
            else app.get(route)
        )
        assert answer.status_code in (200, 202), (page, route, answer.text[:300])


# ---------------------------------------------------------------- the built site


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    try:
        import mkdocs  # noqa: F401
    except ImportError:
        if os.environ.get("CI"):
            pytest.fail("mkdocs is not installed; CI installs it from requirements-dev.lock")
        pytest.skip("mkdocs is not installed (pip install -e '.[docs]')")
    out = tmp_path_factory.mktemp("site")
    done = subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "-d", str(out)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    return out


def _row(page: str, name: str) -> str | None:
    """The value cell of the first table row naming ``name``."""
    m = re.search(rf"<tr><td><code>{re.escape(name)}</code></td><td>(.*?)</td>", page)
    return m[1] if m else None


@pytest.mark.slow
@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_model_page_shows_the_engine_s_numbers(site: Path, spec: engine.ModelSpec) -> None:
    page = (site / "models" / f"{spec.name}.html").read_text(encoding="utf-8")
    assert f"POST /api/v1{spec.path}" in page
    assert page.count('<div class="latex">') >= 1  # its equations
    example = page.split('id="example-1"', 1)[1]
    result = engine.run(spec, spec.examples[0])
    shown = 0
    for name, value in result.results.items():
        if isinstance(value, float | int) and not isinstance(value, bool):
            assert _row(example, name) == HOOKS.fmt(value), name
            shown += 1
    assert shown >= 3
    for check in result.checks:
        assert f"<code>{html.escape(check.name)}</code>" in example


@pytest.mark.slow
def test_each_page_s_curl_gets_the_page_s_numbers(app: TestClient, site: Path) -> None:
    for spec in engine.MODELS:
        page = (site / "models" / f"{spec.name}.html").read_text(encoding="utf-8")
        example = page.split('id="example-1"', 1)[1]
        found = re.search(r"curl -s http://127\.0\.0\.1:8000(\S+) .*?-d '(.*?)'\n", example, re.S)
        assert found, spec.name
        url, body = found.groups()
        answer = app.post(
            url,
            content=html.unescape(body).replace("'\\''", "'"),
            headers={"content-type": "application/json"},
        )
        assert answer.status_code == 200, (spec.name, answer.text)
        for name, value in answer.json()["results"].items():
            if isinstance(value, float):
                assert _row(example, name) == HOOKS.fmt(value), (spec.name, name)


@pytest.mark.slow
def test_preload_example_stress_area_is_the_iso_898_1_value(site: Path) -> None:
    # M12 coarse, P = 1.75 mm: d2 = 12 − 0.649519·1.75 = 10.863341 mm,
    # d3 = 12 − 1.226869·1.75 = 9.852979 mm, A_s = π/4·((d2 + d3)/2)² = 84.2665 mm²
    # (ISO 898-1 Table 4 prints 84.3 mm²), shown in m² to six figures
    page = (site / "models" / "preload.tightening.html").read_text(encoding="utf-8")
    example = page.split('id="example-1"', 1)[1]
    d2, d3 = 12 - 0.649519 * 1.75, 12 - 1.226869 * 1.75
    assert f"{math.pi / 4 * ((d2 + d3) / 2) ** 2 * 1e-6:.6g}" == "8.42665e-05"
    assert _row(example, "stress_area") == "8.42665e-05"


@pytest.mark.slow
def test_validation_pages_name_their_tests(site: Path) -> None:
    for spec in engine.MODELS:
        page = (site / "validation" / f"{spec.name}.html").read_text(encoding="utf-8")
        for module in HOOKS.VALIDATION[spec.name]:
            assert f"tests/validation/{module}" in page
        assert "accuracy.html" in page


@pytest.mark.slow
def test_pages_need_nothing_the_csp_forbids(site: Path) -> None:
    pages = list(site.rglob("*.html"))
    assert len(pages) > 2 * len(engine.MODELS)
    for path in pages:
        text = path.read_text(encoding="utf-8")
        for tag in re.findall(r"<script\b[^>]*>", text):
            assert "src=" in tag and "//" not in tag, (path, tag)
        assert not re.search(r"<script\b[^>]*>\s*[^<\s]", text), path  # no inline script body
        assert ' style="' not in text, path  # style-src 'self': no inline style attribute
        for href in re.findall(r'<link\b[^>]*href="([^"]+)"', text):
            assert "//" not in href, (path, href)


@pytest.mark.slow
def test_service_serves_the_built_manual(site: Path) -> None:
    client = TestClient(create_app(settings=Settings(manual_dir=str(site), warm_up=False)))
    index = client.get("/manual/")
    assert index.status_code == 200 and "Tightening-tool calculator manual" in index.text
    assert index.headers["content-security-policy"] == STRICT_CSP
    page = client.get("/manual/models/clutch.ball.html")
    assert page.status_code == 200 and "Ball safety clutch" in page.text
    assert client.get("/manual/vendor/katex/katex.min.js").status_code == 200
    bare = client.get("/manual", follow_redirects=False)
    assert bare.status_code == 308 and bare.headers["location"] == "/manual/"
    missing = client.get("/manual/models/no-such-page.html")
    assert missing.status_code == 404 and 'href="/manual/css/base.css"' in missing.text
    assert client.get("/").status_code == 200  # the form is still at /


def test_service_says_how_to_build_a_missing_manual(tmp_path: Path) -> None:
    settings = Settings(manual_dir=str(tmp_path / "none"), warm_up=False)
    # the manual's routes do not depend on the models: the toy model's app serves them
    client = TestClient(create_app([TOY], settings=settings), raise_server_exceptions=False)
    for path in ("/manual/", "/manual/models/clutch.ball.html", "/manual/%2e%2e/%2e%2e/etc"):
        answer = client.get(path)
        assert answer.status_code == 404, path
        assert "make manual" in answer.text and answer.headers["content-type"].startswith(
            "text/html"
        )
        assert answer.headers["content-security-policy"] == STRICT_CSP
