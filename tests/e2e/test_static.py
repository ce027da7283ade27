"""The page's files are served by the app and need nothing from elsewhere (no CDN).

These run without a browser, so they guard the offline promise even where
chromium is missing; tests/e2e/test_browser.py checks the same in a browser
by refusing every request that leaves the server.
"""

import re
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from service import create_app
from tests.toys import TOY

STATIC = Path(__file__).parents[2] / "static"
PAGE_FILES = [
    "index.html",
    "app.js",
    "trace_import.js",
    "numbers.js",
    "choices.js",
    "style.css",
    "units.json",
]
VENDOR = ["vendor/uplot/uPlot.iife.min.js", "vendor/uplot/uPlot.min.css", "vendor/uplot/LICENSE"]
KATEX = ["vendor/katex/katex.min.js", "vendor/katex/katex.min.css", "vendor/katex/LICENSE"]


@pytest.fixture(scope="module")
def app_client() -> TestClient:
    return TestClient(create_app(models=[TOY]))


@pytest.mark.parametrize("name", PAGE_FILES + VENDOR + KATEX)
def test_served(app_client, name):
    response = app_client.get("/" + name)
    assert response.status_code == 200
    assert response.content == (STATIC / name).read_bytes()


def test_index_is_the_page(app_client):
    assert app_client.get("/").text == (STATIC / "index.html").read_text("utf-8")


@pytest.mark.parametrize("name", [*PAGE_FILES, *VENDOR[:2]])
def test_no_external_address(name):
    text = (STATIC / name).read_text("utf-8")
    # src/href/url()/fetch of an absolute or protocol-relative address would need the network
    refs = re.findall(
        r"""(?:src|href)\s*=\s*["']([^"']+)|url\(\s*["']?([^"')]+)|fetch\(\s*["']([^"']+)""", text
    )
    external = [r for group in refs for r in group if re.match(r"^(?:[a-z]+:)?//", r)]
    assert not external, external


def test_uplot_licence_and_version_are_stated():
    # the page footer and vendor/uplot/README.md name the version the file holds
    head = (STATIC / "vendor/uplot/uPlot.iife.min.js").read_text("utf-8")[:80]
    version = re.search(r"\(v(\d+\.\d+\.\d+)\)", head)
    assert version, head
    assert "MIT" in (STATIC / "vendor/uplot/LICENSE").read_text("utf-8")
    assert f"uPlot {version[1]}" in (STATIC / "index.html").read_text("utf-8")
    assert f"uplot@{version[1]}" in (STATIC / "vendor/uplot/README.md").read_text("utf-8")


def test_katex_fonts_are_all_vendored_and_its_version_stated():
    css = (STATIC / "vendor/katex/katex.min.css").read_text("utf-8")
    fonts = re.findall(r"url\(([^)]+)\)", css)
    assert fonts and all(f.endswith(".woff2") for f in fonts), fonts
    for f in set(fonts):
        assert (STATIC / "vendor/katex" / f).is_file(), f
    head = (STATIC / "vendor/katex/katex.min.js").read_text("utf-8")
    version = re.search(r'version:"(\d+\.\d+\.\d+)"', head)
    assert version, "no version string in katex.min.js"
    assert f"KaTeX {version[1]}" in (STATIC / "index.html").read_text("utf-8")
    assert f"katex@{version[1]}" in (STATIC / "vendor/katex/README.md").read_text("utf-8")
    assert "MIT" in (STATIC / "vendor/katex/LICENSE").read_text("utf-8")


def test_report_url_opens_the_form_s_report_view(app_client):
    response = app_client.get("/report?m=toy.disc&ex=0&proj=A%20B", follow_redirects=False)
    assert response.status_code == 303
    assert response.headers["location"] == "./#m=toy.disc&ex=0&proj=A%20B&view=report"
    bare = app_client.get("/report", follow_redirects=False)
    assert bare.headers["location"] == "./#view=report"
    assert app_client.get("/report?m=toy.disc").text == (STATIC / "index.html").read_text("utf-8")
