"""MkDocs hooks: the manual's generated pages, written from the engine at build time.

Nothing on a model's page is typed by hand: the question it answers, its inputs (SI unit,
display unit, default, allowed and recommended range), outputs, methods ("rungs") with
their stated error, the checks, the assumptions, the equations with their sources (read
from the docstrings of the engine functions the model's procedure calls, as the
calculation report does: :func:`engine.core.equations.equations_of`) and the worked
examples, each one run through :func:`engine.run` while the site is built, so a number on
a page is the number the engine gives. A validation page per model gathers the docstrings
of the validation tests that hold it (``tests/validation/``) and its rows of the accuracy
table (``docs/accuracy.md``, written by ``make bench``). ``CHANGELOG.md`` becomes a page.

The pages are HTML blocks inside Markdown (tables, equations): descriptions hold ``|``,
``*``, ``<`` and ``[001, eq. 2]``, which Markdown would read as syntax. Equations are
LaTeX in ``<div class="latex">``, typeset in the browser by the KaTeX the form already
vendors (``static/vendor/katex``, copied into the site), so nothing is fetched from a CDN.
"""

from __future__ import annotations

import ast
import html
import json
import math
import re
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
KATEX = ROOT / "static" / "vendor" / "katex"

#: Which validation modules hold which model (each module's docstring names its sources).
VALIDATION: dict[str, tuple[str, ...]] = {
    "nutrunner.drive": ("test_nutrunner_seed000.py",),
    "clutch.ball": (
        "test_clutch_paper.py",
        "test_clutch_two_flanks.py",
        "test_springs_textbooks.py",
    ),
    "clutch.spring_design": ("test_springs_textbooks.py",),
    "clutch.ball_setting": (
        "test_clutch_paper.py",
        "test_clutch_two_flanks.py",
        "test_springs_textbooks.py",
    ),
    "impact.rare": ("test_rare_impact_002.py",),
    "impact.rare_design": ("test_rare_impact_002.py",),
    "preload.tightening": (
        "test_preload_vdi2230.py",
        "test_preload_vdi2230_coarse.py",
        "test_iso898_loads.py",
        "test_fasteners_standards.py",
    ),
    "preload.control": ("test_preload_vdi2230.py", "test_fasteners_standards.py"),
    "joint.vdi2230": (
        "test_joint_compliance.py",
        "test_joint_eccentric.py",
        "test_joint_temperature.py",
        "test_preload_vdi2230_coarse.py",
        "test_iso898_loads.py",
        "test_fasteners_standards.py",
        "test_joint_eccentric_published_implementation.py",
    ),
    # the flange's most loaded bolt goes through joint.vdi2230's chain: its validation holds
    "joint.flange": (
        "test_joint_compliance.py",
        "test_joint_eccentric.py",
        "test_joint_eccentric_published_implementation.py",
    ),
    "blow.joint": ("test_blow_two_mass.py",),
    "tool.capability": ("test_capability_published.py",),
    "friction.iso16047": ("test_iso16047_derivation.py",),
    "joint.audit": ("test_audit_restart_torque.py", "test_audit_untightening.py"),
    "preload.ultrasonic": ("test_ultrasonic_acoustoelastic.py",),
    "trace.analysis": ("test_trace_synthetic.py",),
    "trace.program": ("test_trace_synthetic.py",),
    "trace.batch": ("test_trace_synthetic.py",),
    # the R7/R13 functions and the Cm formula it carries a tool through
    "joint.clamp_capability": ("test_clamp_monte_carlo.py", "test_preload_vdi2230.py"),
}

#: Hand-written pages, in the order of the navigation (generated ones are placed among them).
PAGES = (
    ("Home", "index.md"),
    ("API guide", "api.md"),
    ("Form and report", "form.md"),
    ("Deployment", "deployment.md"),
    ("Performance", "performance.md"),
    ("Sources", "sources.md"),
)


def fmt(value: Any) -> str:
    """A result as the manual prints it: six significant figures, SI.

    >>> fmt(43111.254947598405), fmt(8.426653836460695e-05), fmt(True), fmt(None), fmt(4)
    ('43111.3', '8.42665e-05', 'true', '—', '4')
    """
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:.6g}" if math.isfinite(value) else "—"
    if isinstance(value, str):
        return value
    return json.dumps(value, ensure_ascii=False)


def esc(text: Any) -> str:
    """Text for an HTML cell; ``[`` and ``*`` too, which Markdown could still read."""
    return html.escape(str(text), quote=True).replace("[", "&#91;").replace("*", "&#42;")


def table(head: Iterable[str], rows: Iterable[Iterable[str]]) -> str:
    """An HTML table of already escaped cells (a blank line around it, for Markdown)."""
    out = ["<table>", "<thead><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr></thead>"]
    out.append("<tbody>")
    out += ["<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows]
    out.append("</tbody></table>")
    return "\n" + "\n".join(out) + "\n"


def _range(p: Mapping[str, Any]) -> str:
    if p.get("choices"):
        labels = p.get("choice_labels") or p["choices"]
        return "one of " + ", ".join(
            f"<code>{esc(c)}</code>" + (f" ({esc(lab)})" if lab != c else "")
            for c, lab in zip(p["choices"], labels, strict=True)
        )
    return esc(p.get("range") or "")


def _recommended(p: Mapping[str, Any]) -> str:
    rec = p.get("recommended")
    if not rec:
        return ""
    lo, hi = rec
    return esc(f"{fmt(lo)} … {fmt(hi)}")


def _anchor(text: str) -> str:
    from markdown.extensions.toc import slugify

    return str(slugify(text, "-"))


def source_anchors() -> dict[str, str]:
    """Each source id of docs/sources.md and the anchor of its heading.

    >>> source_anchors()["004"]
    'sources.md#004-selection-of-preload-and-control-of-tightening-review'
    """
    out: dict[str, str] = {}
    for line in (ROOT / "docs" / "sources.md").read_text(encoding="utf-8").splitlines():
        m = re.match(r"### \[([\w.-]+)\]\s*(.*)", line)
        if m and m[1] not in out:
            out[m[1]] = "sources.md#" + _anchor(f"[{m[1]}] {m[2]}")
    return out


def _sources(spec: Any, up: str) -> str:
    """Each source the model cites, its full reference linked to its entry in Sources."""
    from engine.core.sources import SOURCES

    anchors = source_anchors()
    items = []
    for sid in spec.sources:
        ref = esc(f"[{sid}]")
        link = anchors.get(sid)
        text = SOURCES[sid].reference().removeprefix(f"[{sid}] ") if sid in SOURCES else ""
        label = f'<a href="{up}{link}">{ref}</a>' if link else ref
        items.append(f"<li>{label} {esc(text)}</li>")
    return "<ul>\n" + "\n".join(items) + "\n</ul>" if items else ""


def _inputs(spec: Any) -> str:
    rows = []
    for p in (p.describe() for p in spec.inputs):
        default = p["default"]
        default = "required" if p["required"] else "none" if default is None else fmt(default)
        rows.append(
            [
                f"<code>{esc(p['name'])}</code>",
                esc(p.get("symbol") or ""),
                f"<code>{esc(p['unit'])}</code>"
                + (
                    f" (form: {esc(p['display_unit'])})"
                    if p.get("display_unit") not in (None, p["unit"])
                    else ""
                ),
                esc(default),
                _range(p),
                _recommended(p),
                esc(p.get("description") or ""),
            ]
        )
    head = ["input", "symbol", "SI unit", "default", "allowed", "recommended", "meaning"]
    return table(head, rows)


def _outputs(spec: Any) -> str:
    rows = [
        [
            f"<code>{esc(o.name)}</code>",
            f"<code>{esc(o.unit)}</code>",
            "series" + (f" against <code>{esc(o.x)}</code>" if o.x else "")
            if o.series
            else "scalar",
            esc(o.description),
        ]
        for o in spec.outputs
    ]
    return table(["output", "SI unit", "kind", "meaning"], rows)


def _rungs(spec: Any) -> str:
    rows = []
    for r in spec.rungs:
        kind = "heavy (the service's heavy lane)" if r.heavy else "cheap"
        if r.name == spec.default_fidelity:
            kind += ", default"
        rows.append(
            [
                f"<code>{esc(r.name)}</code>",
                esc(kind),
                esc(r.typical_error),
                esc(r.typical_time),
                f"<code>{esc(r.fallback)}</code>" if r.fallback else "",
                esc(r.description),
            ]
        )
    return table(["method", "kind", "stated error", "time", "falls back to", "what it does"], rows)


def _equations(spec: Any) -> str:
    from engine.core.equations import equations_of

    out = []
    for i, e in enumerate(equations_of(spec.compute), 1):
        where = f"<code>{esc(e['module'])}.{esc(e['function'])}</code>"
        source = esc(e["source"]) if e["source"] else "see the function's docstring"
        out.append(f"<p><strong>{i}. {esc(e['summary'])}</strong><br>{where}; {source}</p>")
        out += [f'<div class="latex">{html.escape(tex)}</div>' for tex in e["latex"]]
    return "\n" + "\n".join(out) + "\n"


def run_example(spec: Any, example: Mapping[str, Any]) -> Any:
    """The worked example as the page shows it: :func:`engine.run` on its inputs."""
    import engine

    return engine.run(spec, example, budget_s=60.0)


def _example(spec: Any, i: int, example: Mapping[str, Any]) -> str:
    result = run_example(spec, example)
    given = [
        [f"<code>{esc(k)}</code>", esc(fmt(v)), f"<code>{esc(spec.param(k).unit)}</code>"]
        for k, v in example.items()
    ]
    body = json.dumps(dict(example), ensure_ascii=False).replace("'", "'\\''")  # for the shell
    curl = (
        f"curl -s http://127.0.0.1:8000/api/v1{spec.path} \\\n"
        f"  -H 'content-type: application/json' \\\n  -d '{body}'"
    )
    err = result.error_estimate
    lines = [
        f"### Example {i + 1}",
        "",
        "Inputs given (every other input at its default):",
        table(["input", "value", "SI unit"], given),
        "By REST against `make run`:",
        "",
        "```sh",
        curl,
        "```",
        "",
        f"<p>The engine's answer: method <code>{esc(result.rung)}</code>, error estimate "
        f"{esc(fmt(err) if err is None else f'{err:.2g}')} (relative).</p>",
        table(
            ["output", "value", "SI unit"],
            (
                [
                    f"<code>{esc(k)}</code>",
                    esc(fmt(v)),
                    f"<code>{esc(result.units.get(k, ''))}</code>",
                ]
                for k, v in result.results.items()
            ),
        ),
    ]
    if result.checks:
        lines.append(
            table(
                ["check", "met", "why"],
                (
                    [
                        f"<code>{esc(c.name)}</code>",
                        "yes" if c.ok else "<strong>no</strong>",
                        esc(c.detail),
                    ]
                    for c in result.checks
                ),
            )
        )
    notes = [*result.warnings, *result.notes]
    if notes:
        lines.append("<ul>\n" + "\n".join(f"<li>{esc(n)}</li>" for n in notes) + "\n</ul>\n")
    return "\n".join(lines)


def _checks(spec: Any) -> str:
    """The checks the model reports, with the sentence of its first example that has each."""
    seen: dict[str, str] = {}
    for example in spec.examples:
        for c in run_example(spec, example).checks:
            seen.setdefault(c.name, c.detail)
    if not seen:
        return "<p>This model reports no design checks.</p>\n"
    rows = [[f"<code>{esc(n)}</code>", esc(d)] for n, d in seen.items()]
    return table(["check", "as its worked example states it"], rows)


def model_page(spec: Any) -> str:
    """The Markdown of a model's page."""
    assumptions = "".join(f"<li>{esc(a)}</li>\n" for a in spec.assumptions)
    parts = [
        f"# {spec.title}",
        "",
        f"<p><code>{esc(spec.name)}</code>: <code>POST /api/v1{esc(spec.path)}</code>, "
        f'in the form at <a href="../#m={esc(spec.name)}">/#m={esc(spec.name)}</a>. '
        f'How far to trust it: <a href="../validation/{esc(spec.name)}.md">its validation</a>.</p>',
        "",
        "## The question it answers",
        "",
        f"<p>{esc(spec.summary)}</p>",
        "",
        f"<p>Source: {esc(spec.source)}</p>",
        "",
        _sources(spec, "../"),
        "",
        "## Assumptions",
        "",
        f"<ul>\n{assumptions}</ul>" if assumptions else "<p>None beyond the methods' own.</p>",
        "",
        "## Methods and their stated error",
        "",
        '<p>Each method (rung) states the error it commits; <code>fidelity: "auto"</code> '
        "takes the cheapest one whose estimate meets <code>tolerance</code>. "
        f"Default: <code>{esc(spec.default_fidelity)}</code>.</p>",
        _rungs(spec),
        "## Inputs",
        "",
        "<p>A number is in the SI unit shown; any numeric input may instead be a string with "
        'a unit (<code>"45 mm"</code>). Outside the allowed range the answer is 422 naming '
        "the input; outside the recommended range the result carries a warning.</p>",
        _inputs(spec),
        "## Outputs",
        "",
        _outputs(spec),
        "## Checks",
        "",
        _checks(spec),
        "## Equations",
        "",
        "<p>Every engine function the model's procedure calls, in the order it calls them, "
        "from the functions' own docstrings (the calculation report lists the same).</p>",
        _equations(spec),
        "## Worked examples",
        "",
        "<p>Run through <code>engine.run</code> when this manual was built.</p>",
        "",
        *(_example(spec, i, ex) for i, ex in enumerate(spec.examples)),
    ]
    return "\n".join(parts) + "\n"


def _docstrings(path: Path) -> tuple[str, list[tuple[str, str]]]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    tests = [
        (n.name, (ast.get_docstring(n) or "").split("\n\n")[0])
        for n in tree.body
        if isinstance(n, ast.FunctionDef) and n.name.startswith("test")
    ]
    return ast.get_docstring(tree) or "", tests


def _inline(words: list[str]) -> str:
    """Words joined and escaped, ``code`` as code."""
    return re.sub(r"``(.+?)``", r"<code>\1</code>", esc(" ".join(words)))


def _paragraphs(text: str) -> str:
    """A docstring as HTML paragraphs and bulleted lists (``code`` as code), without the
    project's issue numbers (a reader of the manual cannot look them up).

    >>> number = "issue" + " 18"  # spelled apart: no issue number in this repository's text
    >>> _paragraphs(f"The case of {number} in ``tests``:\\n* one\\n  more\\n* two\\n\\nEnd.")
    '<p>The case in <code>tests</code>:</p>\\n<ul><li>one more</li><li>two</li></ul>\\n<p>End.</p>'
    """
    text = re.sub(r" (?:of |in |from )?\(?issue \d+\)?(?=[\s:;,.])", "", text)

    out = []
    for para in text.split("\n\n"):
        lead: list[str] = []
        items: list[list[str]] = []
        for line in (ln.strip() for ln in para.strip().splitlines()):
            if line.startswith(("* ", "- ")):
                items.append([line[2:]])
            elif items:
                items[-1].append(line)
            elif line:
                lead.append(line)
        if lead:
            out.append(f"<p>{_inline(lead)}</p>")
        if items:
            out.append("<ul>" + "".join(f"<li>{_inline(i)}</li>" for i in items) + "</ul>")
    return "\n".join(out)


def accuracy_rows(name: str, path: Path = ROOT / "docs" / "accuracy.md") -> str | None:
    """The rows of the accuracy table (``make bench``) whose cell names model ``name``, under
    the table's header; "" when it has none, None when there is no table."""
    if not path.is_file():
        return None
    table_lines = [ln for ln in path.read_text(encoding="utf-8").splitlines() if ln[:1] == "|"]
    rows = [
        ln for ln in table_lines[2:] if name in (cell.strip().strip("`") for cell in ln.split("|"))
    ]
    return "\n".join([*table_lines[:2], *rows]) if rows else ""


def validation_page(spec: Any) -> str:
    """The Markdown of a model's validation page."""
    parts = [
        f"# Validation: {spec.title}",
        "",
        f'<p>What holds <a href="../models/{esc(spec.name)}.md"><code>{esc(spec.name)}</code></a> '
        "to published numbers, worked examples and independent implementations: the "
        "validation tests below run in <code>make test</code> (and so in CI), each stating "
        "the printed number it pins and how close. Beside them, "
        f"<code>tests/models/{esc(spec.family)}/</code> holds every function and output to "
        "hand-computed values, and <code>tests/stability/</code> holds every model's methods "
        "to each other over its whole input range.</p>",
        "",
        "## Sources",
        "",
        _sources(spec, "../"),
        "",
        "## Accuracy",
        "",
    ]
    rows = accuracy_rows(spec.name)
    if rows is None:
        parts.append(
            "<p>The accuracy table (stated bound, share of cases exceeding it, worst ratio) "
            "is written by <code>make bench</code> to <code>docs/accuracy.md</code>; this "
            'build found none. See <a href="../accuracy.md">Accuracy</a>.</p>'
        )
    elif rows:
        parts += [
            'From <a href="../accuracy.md">the accuracy table</a> (<code>make bench</code>):',
            "",
            rows,
        ]
    else:
        parts.append(
            f'<p>The <a href="../accuracy.md">accuracy table</a> has no row for '
            f"<code>{esc(spec.name)}</code>.</p>"
        )
    for module in VALIDATION[spec.name]:
        doc, tests = _docstrings(ROOT / "tests" / "validation" / module)
        parts += ["", f"## {module}", "", f"<p><code>tests/validation/{module}</code></p>"]
        parts += [_paragraphs(doc), ""]
        rows_ = [[f"<code>{esc(n)}</code>", _inline(d.split())] for n, d in tests]
        parts.append(table(["test", "what it holds"], rows_))
    return "\n".join(parts) + "\n"


ACCURACY_PLACEHOLDER = """# Accuracy

No accuracy table in this build: `make bench` writes it to `docs/accuracy.md` (for each
model and method, its stated error bound, the share of reference cases that exceed it and
the worst ratio of achieved to stated error), stamped with the date it was measured.
Rebuild the manual after `make bench` to include it.
"""


LOADTEST = ROOT / "bench" / "loadtest.json"
LOADTEST_MARK = "<!-- bench/loadtest.json -->"


def loadtest_section(path: Path = LOADTEST) -> str:
    """The load test's figures as ``make bench`` last wrote them, stamped with their date."""
    if not path.is_file():
        return "No load-test figures in this checkout: `make bench` writes `bench/loadtest.json`.\n"
    data = json.loads(path.read_text(encoding="utf-8"))
    when, cpus = data["when"][:10], data["machine"]["cpus"]
    head = (
        f"`scripts/loadtest.py` as `make bench` last ran it, on {when}: a {cpus}-core machine, "
        f"one server process, {data['concurrency']} keep-alive clients, "
        f"{data['requests_per_endpoint']:,} requests an endpoint.\n"
    )
    labels = {
        "healthz": "<code>/healthz</code>",
        "closed_form": "closed form",
        "simulation": "simulation, single point",
        "closed_form_beside_heavy": "closed form beside 8 clients of the heaviest request",
    }
    rows = [
        [
            labels.get(key, esc(key))
            + (f" (<code>{esc(e['model'])}</code>)" if e.get("model") else ""),
            f"{e['requests_per_s']:,.0f}",
            f"{e['p50_ms']:g}",
            f"{e['p99_ms']:g}",
        ]
        for key, e in data["endpoints"].items()
    ]
    models = [
        [
            f"<code>{esc(name)}</code>",
            f"{m['requests_per_s']:,.0f}",
            f"{m['p99_ms']:g}",
            f"{m['vs_healthz']:.2f}",
            f"{m['ceiling_vs_healthz']:.2f}",
            f"{data['sweeps'][name]['median_ms']:g}" if name in data.get("sweeps", {}) else "",
        ]
        for name, m in data.get("models", {}).items()
    ]
    return (
        head
        + table(["endpoint", "req/s", "p50 ms", "p99 ms"], rows)
        + "\nEvery model's cheapest method on its first example, each run between two `/healthz` "
        "runs; the ceiling is the share of `/healthz` throughput a service adding nothing but "
        "`engine.run` could reach; the sweep is 2,000 points over HTTP (median of 15 calls).\n"
        + table(
            ["model", "req/s", "p99 ms", "/ healthz", "ceiling", "2,000-point sweep ms"], models
        )
    )


def on_page_markdown(markdown: str, page: Any, config: Any, files: Any) -> str:
    if LOADTEST_MARK in markdown:
        markdown = markdown.replace(LOADTEST_MARK, loadtest_section())
    return markdown


def changelog_page() -> str:
    return (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")


# ---- MkDocs events ------------------------------------------------------------------


def on_config(config: Any) -> Any:
    import engine

    docs = Path(config["docs_dir"])
    nav: list[Any] = [{title: page} for title, page in PAGES[:1]]
    nav.append({"Models": [{s.title: f"models/{s.name}.md"} for s in engine.MODELS]})
    validation: list[Any] = [{s.name: f"validation/{s.name}.md"} for s in engine.MODELS]
    validation.append({"Accuracy table": "accuracy.md"})
    if (docs / "mutation.md").is_file():
        validation.append({"Mutation testing": "mutation.md"})
    nav.append({"Validation": validation})
    nav += [{title: page} for title, page in PAGES[1:]]
    nav.append({"Changelog": "changelog.md"})
    listed = {"accuracy.md", "mutation.md", *(page for _, page in PAGES)}
    more = [
        {_title(path): path.relative_to(docs).as_posix()}
        for path in sorted(docs.rglob("*.md"))
        if path.relative_to(docs).as_posix() not in listed
    ]
    if more:  # a page another change adds to docs/ is in the manual without editing this
        nav.append({"More": more})
    config["nav"] = nav
    return config


def _title(path: Path) -> str:
    """A page's first heading, else its file name."""
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("# "):
            return line[2:].strip()
    return path.stem


def on_files(files: Any, config: Any) -> Any:
    from mkdocs.structure.files import File

    import engine

    def add(uri: str, content: str | bytes) -> None:
        if files.get_file_from_path(uri) is None:
            files.append(File.generated(config, uri, content=content))

    for spec in engine.MODELS:
        add(f"models/{spec.name}.md", model_page(spec))
        add(f"validation/{spec.name}.md", validation_page(spec))
    add("accuracy.md", ACCURACY_PLACEHOLDER)
    add("changelog.md", changelog_page())
    pareto = ROOT / "bench" / "pareto.png"
    if pareto.is_file():
        add("bench/pareto.png", pareto.read_bytes())
    for path in sorted(KATEX.rglob("*")):
        if path.is_file() and path.suffix in (".js", ".css", ".woff2"):
            add("vendor/katex/" + path.relative_to(KATEX).as_posix(), path.read_bytes())
    return files


#: Where the service serves the manual (service/main.py): the 404 page, shown at any depth,
#: links its styles and scripts from here, not from the server's root.
SERVED_AT = "/manual"


def on_template_context(context: Any, template_name: str, config: Any) -> Any:
    if template_name == "404.html":
        context["base_url"] = SERVED_AT
    return context
