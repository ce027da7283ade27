"""Sources and layout: every citation resolves inside the repository; physics stays apart.

The layers of ``engine/``, each a folder (see LAYERS): physics in ``engine/physics/``
(no spec machinery), declarations in ``engine/models/<family>.py``, sources in
``engine/core/sources.py`` and ``docs/sources.md``; no import circle in ``engine/``.
"""

from __future__ import annotations

import ast
import functools
import importlib
import re
from pathlib import Path

import pytest

import engine
from engine.core.sources import SOURCES, cited_ids

ROOT = Path(__file__).resolve().parents[2]
#: Files whose text may cite sources (vendored third-party code is not ours).
CITING = [
    p
    for d in ("engine", "service", "static")
    for p in sorted((ROOT / d).rglob("*"))
    if p.suffix in {".py", ".js", ".html"} and "vendor" not in p.parts
]
#: The layers of engine/ and the layers each may import (engine.core.errors is open to all).
#: Physics is pure functions and never the spec machinery; nothing below the models knows
#: a model but the studies, which run them by name (and draw through the numerics' laws);
#: core knows no physics.
LAYERS: dict[str, set[str]] = {
    "core": {"core"},
    "numerics": {"numerics"},
    "physics": {"physics", "numerics"},
    "procedures": {"procedures", "physics", "numerics", "core"},
    "studies": {"studies", "models", "numerics", "core"},
    "models": {"models", "procedures", "physics", "numerics", "core"},
}
LAYERED = [p for layer in LAYERS for p in sorted((ROOT / "engine" / layer).glob("*.py"))]


def test_the_citing_files_are_found():
    names = {p.relative_to(ROOT).as_posix() for p in CITING}
    assert {"engine/physics/nutrunner.py", "engine/models/clutch.py", "static/app.js"} <= names


@pytest.mark.parametrize("path", CITING, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_every_citation_resolves_to_a_source(path):
    text = path.read_text(encoding="utf-8")
    unknown = cited_ids(text) - SOURCES.keys()
    assert not unknown, f"{path.name} cites {sorted(unknown)}, which engine/core/sources.py lacks"
    assert not re.search(r"MODELS\.md|seeds/", text), f"{path.name} cites a file outside the repo"


def test_cited_ids_reads_the_forms_the_code_uses():
    text = "[000, eq. 7–8]; [004]; VDI 2230-1:2015 step R7; ISO 898-1; spring after Wahl"
    assert cited_ids(text) == {"000", "004", "VDI2230", "ISO898-1", "Wahl"}
    assert cited_ids("a list [1, 2] and 2e-3 [m]") == set()


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_every_model_names_its_sources(spec):
    assert spec.sources, f"{spec.name}: its source text cites no known source"
    assert set(spec.sources) <= SOURCES.keys()
    listed = [s["id"] for s in spec.describe()["sources"]]
    assert listed == list(spec.sources)


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_notes_of_every_example_cite_only_known_sources(spec):
    for example in spec.examples:
        result = engine.run(spec, dict(example))
        text = " ".join([*result.notes, *result.warnings, *(c.detail for c in result.checks)])
        assert cited_ids(text) <= SOURCES.keys()
        assert "MODELS.md" not in text and "seeds/" not in text


def test_docs_list_every_source():
    doc = (ROOT / "docs" / "sources.md").read_text(encoding="utf-8")
    headings = set(re.findall(r"^### \[([^\]]+)\]", doc, flags=re.M))
    assert headings == set(SOURCES), "docs/sources.md and engine/core/sources.py list other sources"


def test_the_catalogue_serves_the_sources(client):
    body = client.get("/api/v1/sources").json()
    assert [s["id"] for s in body["sources"]] == list(SOURCES)
    first = body["sources"][0]
    assert first["title"] and first["covers"] and first["reference"].startswith("[000]")
    models = client.get("/api/v1/models").json()["models"]
    nut = next(m for m in models if m["name"] == "nutrunner.drive")
    assert [s["id"] for s in nut["sources"]] == ["000", "Kloss"]


@functools.cache
def _engine_imports(path: Path) -> frozenset[str]:
    """The ``engine`` modules a module imports (relative imports resolved); each file
    parsed once per test process (the layer tests and the circle test read the same files)."""
    package = path.relative_to(ROOT).with_suffix("").parts[:-1]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            base = list(package[: len(package) - node.level + 1]) if node.level else []
            module = ".".join([*base, *(node.module.split(".") if node.module else [])])
            names = [module] if node.module else [f"{module}.{a.name}" for a in node.names]
            found.update(n for n in names if n.startswith("engine"))
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("engine"))
    return frozenset(found)


def test_every_engine_module_is_in_a_layer():
    loose = sorted(p.name for p in (ROOT / "engine").glob("*.py") if p.name != "__init__.py")
    assert loose == []
    assert {
        p.name for p in (ROOT / "engine").iterdir() if p.is_dir() and p.name != "__pycache__"
    } == set(LAYERS)


@pytest.mark.parametrize("path", LAYERED, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_each_layer_imports_only_the_layers_below_it(path):
    layer = path.relative_to(ROOT / "engine").parts[0]
    allowed = {f"engine.{m}" for m in LAYERS[layer]}
    imports = _engine_imports(path) - {"engine.core.errors"}
    bad = sorted(m for m in imports if not any(m == a or m.startswith(a + ".") for a in allowed))
    assert bad == [], f"{path.relative_to(ROOT)} ({layer}) imports {bad}"


def test_no_import_circle_in_engine():
    graph: dict[str, set[str]] = {}
    for path in (ROOT / "engine").rglob("*.py"):
        parts = path.relative_to(ROOT).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        graph[name] = _engine_imports(path)
    modules = set(graph)
    for name in graph:
        graph[name] = {m if m in modules else m.rsplit(".", 1)[0] for m in graph[name]} - {name}
    # the package __init__ files re-export their children: edges into a package are fine
    packages = {"engine", "engine.models"}

    def visit(node: str, stack: list[str]) -> None:
        for nxt in sorted(graph.get(node, ())):
            if nxt in packages:
                continue
            assert nxt not in stack, "import circle: " + " -> ".join([*stack, nxt])
            visit(nxt, [*stack, nxt])

    for start in sorted(modules - packages):
        visit(start, [start])


def _layout_rows() -> list[str]:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme.split("### From a model's name", 1)[1].split("### The tree", 1)[0]
    return [line for line in section.splitlines() if line.startswith("| `")]


@pytest.mark.parametrize("spec", engine.MODELS, ids=lambda s: s.name)
def test_readme_leads_from_each_model_name_to_existing_files(spec):
    rows = [r for r in _layout_rows() if f"`{spec.name}`" in r.split("|")[1]]
    assert rows, f"add a row for {spec.name} to the README's layout table"
    cells = rows[0].split("|")
    paths = re.findall(r"`([\w/.]+(?:\.py|/))`", rows[0])
    assert paths and all((ROOT / p).exists() for p in paths), [
        p for p in paths if not (ROOT / p).exists()
    ]
    assert any(p.startswith("engine/models/") for p in paths)
    assert any(p.startswith("tests/validation/") for p in paths)
    decl = importlib.import_module(spec.compute.__module__).__file__
    assert decl and Path(decl).relative_to(ROOT).as_posix() in cells[3]
    assert set(spec.sources) & set(re.findall(r"\[([\w-]+)\]", cells[4])), spec.sources
