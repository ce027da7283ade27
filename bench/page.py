"""The performance page, docs/performance.md, written from the latest ``make bench``.

``python -m bench.page`` (the last step of ``make bench``) reads ``bench/results.json``
(``bench.run``: rungs, sweeps and every extra row), ``bench/loadtest.json``
(``scripts/loadtest.py``) and, where present, ``bench/shopfloor.json`` (the shared-server
figures, with their own date), and writes one page: a stamp (date, machine, load average
at the start and end of the run, the access log's state, default outputs), one table of
every target with its goal, figure and whether it is met, the figures per model behind
it, and the explanatory notes kept here as static text. A target the run has no figure
for is listed as "not measured in this run". ``--check`` exits 1 when the committed page
differs from what the committed figures give.
"""

# ruff: noqa: E501  (the notes are markdown: table rows cannot wrap)
from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
PAGE = ROOT / "docs" / "performance.md"
NOT_MEASURED = "not measured in this run"

Row = Mapping[str, Any]


@dataclass(frozen=True)
class Target:
    """One target of the performance issues, and which stored rows measure it."""

    label: str
    goal: str
    match: Callable[[Row], bool]


def _source(name: str, case: str = "") -> Callable[[Row], bool]:
    return lambda r: r.get("source") == name and case in str(r.get("case", ""))


def _text(*words: str) -> Callable[[Row], bool]:
    def match(r: Row) -> bool:
        text = f"{r.get('target', '')} {r.get('case', '')}".lower()
        return all(w in text for w in words)

    return match


#: Every target ``make bench`` is meant to print beside its figure, in the page's order.
TARGETS: tuple[Target, ...] = (
    Target(
        "10⁶-point `engine.sweep` of each closed form / its numpy floor",
        "≤ ×3",
        lambda r: _text("sweep", "floor")(r) and r.get("source") != "extra_service.py",
    ),
    Target(
        "10⁶-point Monte Carlo, default outputs, in process / a numpy floor study",
        "≤ ×3",
        _source("study_summary.py", "numpy floor study"),
    ),
    Target(
        "summary and merge, share of the 10⁶-point study",
        "≤ 30 %",
        _source("study_summary.py", "summary and merge"),
    ),
    Target(
        "memory above the idle process / bytes of the raw values kept",
        "≤ ×1.5",
        _source("study_summary.py", ": memory"),
    ),
    Target(
        "study through the HTTP endpoint on a warm cluster / in process",
        "≤ ×1.3",
        _source("study_summary.py", "HTTP study endpoint"),
    ),
    Target(
        "every input on the array path / the model's array cost per point",
        "≤ ×5",
        _source("extra_arrays.py"),
    ),
    Target(
        "blow kernel / a lean kernel of the same equations, per step",
        "≤ ×2",
        _source("extra_blow_lean.py"),
    ),
    Target(
        "10⁴-design simulation study: time beyond its kernels'",
        "≤ 10 %",
        _text("beyond", "kernel"),
    ),
    Target(
        "simulation study, 2 local workers / 1", "≥ ×1.8", _source("extra_study.py", "2 worker")
    ),
    Target(
        "service's share of a closed-form request (request − `engine.run`, access log on) / the same-body FastAPI floor",
        "≤ ×1.3",
        _source("extra_service.py", "request / bare FastAPI"),
    ),
    Target(
        "`engine.run` minus its model's compute / the compute",
        "≤ ×1",
        _source("extra_runner.py", "compute"),
    ),
    Target(
        "default-`auto` request / the same with its rung named",
        "≤ ×1.1",
        _source("extra_runner.py", "auto"),
    ),
    Target(
        "spawn to `/readyz` / a bare uvicorn + FastAPI app's",
        "≤ ×2",
        _source("cold_start.py", "readyz"),
    ),
    Target(
        "first simulation after `/readyz` / the steady simulation request",
        "≤ ×2",
        _source("cold_start.py", "first simulation"),
    ),
    Target(
        "2,000-point closed-form sweep in the engine",
        "≤ 2 ms",
        _source("extra_targets.py", "pts of"),
    ),
    Target(
        "2,000-point closed-form sweep through the app",
        "≤ 20 ms",
        _source("extra_service.py", "sweep via"),
    ),
    Target(
        "simulation request with scalar outputs / (1.5 × kernel + closed-form overhead)",
        "≤ ×1",
        _source("extra_targets.py", "simulation request"),
    ),
    Target(
        "10⁶-point Monte Carlo in process, per point (2 s for 10⁶ points)",
        "≤ 2 µs",
        lambda r: str(r.get("method", "")).startswith("study_mc"),
    ),
    Target(
        "10⁶-point closed-form sweep through `engine.sweep`, every model and vector rung",
        "< 1 s",
        lambda r: r.get("source") == "sweeps" and r.get("points", 0) >= 10**6,
    ),
    Target(
        "200-point sweep of each looped rung and the most accurate",
        "< 2 s",
        lambda r: r.get("source") == "sweeps" and 0 < r.get("points", 0) < 10**6,
    ),
    Target(
        "closed-form p99 latency at 8 keep-alive clients (load test)",
        "< 20 ms",
        _source("loadtest.json", "p99 at"),
    ),
    Target(
        "closed-form p99 beside 8 clients of the heaviest request (load test)",
        "< 50 ms",
        _source("loadtest.json", "beside"),
    ),
    Target(
        "2,000-point closed-form sweep over HTTP (load test)",
        "≤ 20 ms",
        _source("loadtest.json", "2,000-point sweep"),
    ),
)


def _number(value: Any) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    return float(value) if math.isfinite(value) else None


def fmt_time(seconds: float) -> str:
    """``seconds`` with three significant digits in s, ms, µs or ns.

    >>> fmt_time(0.00042), fmt_time(1.5), fmt_time(2.4e-8)
    ('420 µs', '1.5 s', '24 ns')
    """
    for scale, unit in ((1.0, "s"), (1e-3, "ms"), (1e-6, "µs")):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds * 1e9:.3g} ns"


def figure(row: Row, goal: str) -> str:
    """The row's measured figure in its goal's terms: a ratio, a share or a time.

    >>> figure({"ratio": 0.456}, "≤ 30 %"), figure({"ratio": 1.904}, "≤ ×1.3")
    ('46 %', '×1.90')
    >>> figure({"time_s": 0.0021}, "≤ 20 ms"), figure({}, "≤ ×2")
    ('2.1 ms', '-')
    """
    ratio, time_s = _number(row.get("ratio")), _number(row.get("time_s"))
    if "×" in goal and ratio is not None:
        return f"×{ratio:.2f}"
    if "%" in goal and ratio is not None:
        return f"{100 * ratio:.0f} %"
    if time_s is not None:
        return fmt_time(time_s)
    return "-"


def measured_rows(
    results: Mapping[str, Any], loadtest: Mapping[str, Any] | None
) -> list[dict[str, Any]]:
    """Every stored row that states a target: the extras, the sweeps and the load test's."""
    rows = [dict(r) for r in results.get("rows", []) if "met" in r]
    rows += [
        {**r, "source": "sweeps", "case": f"{r.get('how')} {r.get('method')}, {r.get('vary')}"}
        for r in results.get("sweeps", [])
        if r.get("met") is not None
    ]
    if loadtest:
        t = loadtest.get("targets", {})
        if "closed_form_p99_ms" in t:
            clients = loadtest.get("concurrency", "?")
            rows.append(
                {
                    "source": "loadtest.json",
                    "model": loadtest.get("endpoints", {}).get("closed_form", {}).get("model", ""),
                    "case": f"closed-form p99 at {clients} keep-alive clients",
                    "time_s": t["closed_form_p99_ms"] / 1e3,
                    "met": t.get("p99_target_met"),
                }
            )
        if "closed_form_p99_beside_heavy_ms" in t:
            rows.append(
                {
                    "source": "loadtest.json",
                    "model": loadtest.get("endpoints", {}).get("closed_form", {}).get("model", ""),
                    "case": "closed-form p99 beside the heaviest request",
                    "time_s": t["closed_form_p99_beside_heavy_ms"] / 1e3,
                    "met": t.get("lanes_target_met"),
                }
            )
        for model, ms in t.get("sweep_2000_http_ms", {}).items():
            rows.append(
                {
                    "source": "loadtest.json",
                    "model": model,
                    "case": "2,000-point sweep over HTTP",
                    "time_s": ms / 1e3,
                    "met": ms <= 20.0,
                }
            )
    return rows


def _cell(text: Any) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _met(values: Sequence[Any]) -> str:
    known = [v for v in values if v is not None]
    if not known:
        return "-"
    missed = sum(not v for v in known)
    if not missed:
        return "yes"
    return f"**no** ({missed} of {len(known)} missed)" if len(known) > 1 else "**no**"


def _span(figures: Sequence[str], rows: Sequence[Row]) -> str:
    """The range of the rows' figures, the worst one's model named."""
    shown = [f for f in figures if f != "-"]
    if not shown:
        return "-"
    if len(shown) == 1:
        return shown[0]
    keyed = [
        (_number(r.get("ratio")) or _number(r.get("time_s")) or 0.0, f, r)
        for f, r in zip(figures, rows, strict=True)
        if f != "-"
    ]
    low, high = min(keyed, key=lambda k: k[0]), max(keyed, key=lambda k: k[0])
    return f"{low[1]}–{high[1]} (highest: {high[2].get('model', '?')})"


def targets_table(rows: Sequence[Row]) -> tuple[str, str]:
    """The targets table (one line a target) and the per-row details behind it."""
    summary = ["| target | goal | measured | met? |", "|---|---|---|---|"]
    details = ["| target | model | case | measured | met? | notes |", "|---|---|---|---|---|---|"]
    claimed: set[int] = set()
    for target in TARGETS:
        mine = [r for i, r in enumerate(rows) if i not in claimed and target.match(r)]
        claimed |= {i for i, r in enumerate(rows) if any(r is m for m in mine)}
        if not mine:
            summary.append(f"| {target.label} | {target.goal} | {NOT_MEASURED} | - |")
            continue
        figures = [figure(r, target.goal) for r in mine]
        summary.append(
            f"| {target.label} | {target.goal} | {_cell(_span(figures, mine))} | "
            f"{_met([r.get('met') for r in mine])} |"
        )
        for r, f in zip(mine, figures, strict=True):
            details.append(_detail(target.label, r, f))
    for i, r in enumerate(rows):
        if i in claimed:
            continue
        goal = _own_goal(r)
        label = f"{r.get('target') or r.get('case', '?')} ({r.get('source', '?')})"
        f = figure(r, goal)
        summary.append(f"| {_cell(label)} | {goal} | {_cell(f)} | {_met([r.get('met')])} |")
        details.append(_detail(label, r, f))
    return "\n".join(summary) + "\n", "\n".join(details) + "\n"


def _own_goal(r: Row) -> str:
    if r.get("goal"):
        return str(r["goal"])
    ratio, time_s = _number(r.get("target_ratio")), _number(r.get("target_s"))
    if ratio is not None:
        return f"≤ ×{ratio:g}"
    if time_s is not None:
        return f"≤ {fmt_time(time_s)}"
    return "-"


def _detail(label: str, r: Row, f: str) -> str:
    met = "-" if r.get("met") is None else ("yes" if r["met"] else "**no**")
    return (
        f"| {_cell(label)} | {_cell(r.get('model', ''))} | {_cell(r.get('case', ''))} | "
        f"{_cell(f)} | {met} | {_cell(r.get('notes', ''))} |"
    )


def _load(m: Mapping[str, Any], key: str) -> str:
    value = _number(m.get(key))
    return f"{value:.1f}" if value is not None else "not recorded"


def _access_log(rows: Sequence[Row], loadtest: Mapping[str, Any] | None) -> str:
    """The access log's state as the figures record it (a row's or the load test's ``access_log``)."""
    states = {bool(r["access_log"]) for r in rows if "access_log" in r}
    inproc = ("on" if states == {True} else "off") if len(states) == 1 else ""
    inproc = inproc or ("on in some rows, off in others" if states else "not recorded")
    server = "not recorded"
    if loadtest and "access_log" in loadtest:
        server = "on" if loadtest["access_log"] else "off"
    return f"in-process request rows: {inproc}; load test server: {server}"


def stamp(results: Mapping[str, Any], loadtest: Mapping[str, Any] | None) -> str:
    m = results.get("machine", {})
    commit = str(m.get("git_commit", "?")) + (
        " with uncommitted changes" if m.get("git_dirty") else ""
    )
    lines = [
        f"- **Measured** {m.get('date', 'at an unrecorded date')} by `make bench` at commit "
        f"`{commit}`; load test {loadtest.get('when', '?') if loadtest else NOT_MEASURED}.",
        f"- **Machine**: {m.get('cpu_count', '?')} CPUs, {m.get('processor', '?')}, "
        f"{m.get('platform', '?')}; Python {m.get('python', '?')}, numpy {m.get('numpy', '?')}, "
        f"scipy {m.get('scipy', '?')}.",
        f"- **Load average** (1 min) at the start of the run {_load(m, 'load_start')}, at its end "
        f"{_load(m, 'load_end')}.",
        f"- **Access log**: {_access_log(results.get('rows', []), loadtest)}.",
        "- **Outputs**: each model's default outputs (none named), unless a row says otherwise.",
    ]
    return "\n".join(lines) + "\n"


def _flat(body: Mapping[str, Any], prefix: str = "") -> list[str]:
    """``key value`` for each number or string, one level of nesting as ``key.sub``."""
    out: list[str] = []
    for key, value in body.items():
        if isinstance(value, dict) and not prefix:
            out += _flat(value, f"{key}.")
        elif isinstance(value, int | float | str) and not isinstance(value, bool):
            out.append(f"{prefix}{key} {value}")
    return out


def shopfloor_section(shop: Mapping[str, Any] | None) -> str:
    """``bench/shopfloor.json``'s figures, one line a scenario, under their own date."""
    if not shop:
        return ""
    lines = [
        "## Shared-server figures",
        "",
        "From `bench/shopfloor.json` (`python -m bench.shopfloor`, not part of `make bench`), "
        f"taken {_cell(shop.get('taken', 'at an unrecorded date'))}.",
        "",
        "| scenario | figures |",
        "|---|---|",
    ]
    for section, body in shop.items():
        if isinstance(body, dict) and not section.startswith("today"):
            lines.append(f"| {_cell(section)} | {_cell('; '.join(_flat(body)))} |")
    return "\n".join(lines) + "\n\n"


INTRO = """# Performance

How fast the engine and the service answer, as measured by the last `make bench` (the
benchmark suite in `bench/`, then the load test `scripts/loadtest.py`, then the accuracy
table). This page is written by `python -m bench.page` from `bench/results.json` and
`bench/loadtest.json`: do not edit it by hand. `make bench` also rewrites
`bench/pareto.png` (time per evaluation against achieved error, for every model and
method, with scipy `solve_ivp` beside the simulations); it takes about 15 minutes on a
2-core machine. The accuracy half of the same run is the [accuracy table](accuracy.md).

![time per evaluation against achieved error, every model and method](bench/pareto.png)

"""

TARGETS_HEAD = """## Targets

Each target beside its figure from this run: a range over the models a target is measured
for, the model with the highest figure named. Times are medians of several calls; on a
machine shared with other work they are inflated, and the ratios, measured side by side in
one loop, are what compare. The throughput target "≥ 0.8 of `/healthz`" and "≤ 1.3× a bare
endpoint" of earlier runs compared a model with an endpoint that runs nothing; the ratios
to floors measured alongside replace them.

"""

UNDER_LOAD = """## Under load

<!-- bench/loadtest.json -->

`scripts/loadtest.py` starts `python -m service` on a free loopback port (or uses `--url`),
drives `/healthz`, every model's closed form, a simulation and every model's 2,000-point
sweep, then stops the server, printing requests/s, p50/p99 latency and CPU time per
request, each target beside its figure (`--check` exits 1 if one is missed). Its targets
are in the table above; the manual shows its full tables (from `bench/loadtest.json`) here.

"""

DETAILS_HEAD = """### Every figure behind the targets

"""

#: The explanatory notes: static text, kept from the hand-written page (its tables are
#: dated measurements of earlier runs, kept for the reasons they give).
NOTES = """## Notes

The sections below explain the figures and keep the measurements taken by hand while the
targets were worked on, each with its date; the tables above are the current run's.

### Design studies

`python bench/extra_study.py` (and `bench/extra_joint.py`), on the same 2-core machine,
idle, in November 2026:

| study | time |
|---|---|
| 10⁶-point Monte Carlo of `clutch.ball` (array path, in process) | 1.37 s |
| 10⁶-point Monte Carlo of `joint.vdi2230` (friction, plate thickness, working load scattered) | 2.5 s |
| 10⁶-point Monte Carlo of `preload.control` (μ_G, μ_K, F_K scattered; 33 outputs, 2 checks) | 1.0–1.8 s |
| 10⁵ rare-impact designs, LHS, tolerance 10⁻⁶ (simulation), 1 local Dask worker | 76.0 s |
| the same on 2 local Dask workers | 42.5 s (1.79×) |

Cancelling a running 200,000-design simulation study freed the workers in 0.09 s; progress
is reported after every chunk (256 simulated designs, about 0.2 s).

#### Where a study's time goes

A study summarises each chunk where the chunk runs (on its Dask worker, or in process):
count, mean and standard deviation (combined pairwise, to 1e-12 of numpy's), extremes and
the designs behind them, check and rung counts. As the chunks arrive, each output's values
are counted in 2¹⁴ fine bins placed by the first chunk; the quantiles and the histogram are
then found in one pass over the few bins that hold a quantile's rank or a histogram edge,
and are numpy's to the last bit (where those bins hold over a quarter of the values, as at
a point mass, the merged column is read as before: the same numbers, more time). Spearman's
ρ is computed on the first 200,000 points as before.

`python -m bench.study_summary 1000000`, every output collected, CPU seconds, in process,
on the 2-core machine shared with other work (load 8–15) on 2026-11-26, before → after
(the range of two runs before and three after):

| phase | `joint.vdi2230` (53 outputs) | `preload.tightening` (34 outputs) |
|---|---|---|
| chunks' partial summaries | — → 0.08 s | — → 0.04–0.05 s |
| quantiles and histograms | 0.79–0.86 → 0.10–0.11 s | 0.45–0.55 → 0.12–0.16 s |
| rank correlations | 0.41 → 0.28–0.31 s | 0.17 → 0.16–0.17 s |
| rest of the summary | 0.05–0.19 → ≤ 0.02 s | ≤ 0.07 → < 0.01 s |
| merge (values put in place, fine counts) | 0.48–0.71 → 0.45–0.81 s | 0.21–0.43 → 0.16–0.21 s |
| whole study (`run_study`) | 2.7–3.1 → 2.1–2.6 s | 1.4–1.6 → 0.8–1.2 s |
| share of partials, merge and summary (target ≤ 30 %) | 58–60 % → 42–46 % | 66–70 % → 47–61 % |
| study / numpy floor study (target ≤ ×3) | no floor study | ×5.2–5.3 → ×3.0–4.9 |

The share target is still missed, and the floor ratio was met in one run of three. What
remains is mostly the merge: writing 10⁶ values of
every output into columns allocated for the study costs page faults on fresh memory
(0.08–0.14 s of system time for the joint's 424 MB, more when the kernel compacts memory
for huge pages), and the ranks' sorts of 200,000 points (one per input and per output not
ordered like an earlier one).

### Cold start

`python -m bench.cold_start` (in `make bench`) spawns `python -m service` and a bare
uvicorn + FastAPI app one after the other on free ports, in alternating rounds, and times
each from the spawn to its first 200 from `/readyz`; then it posts each simulation
model's first example (the simulation named) once right after ready and seven times
more. `/readyz` answers 503 "warming" until the warm-up has loaded the compiled kernels
(see [deployment](deployment.md)).

Measured on the shared 2-core machine on 2026-11-26, two runs of four and five rounds
each, the machine's load average 9–12 (other work running: times several-fold an idle
machine's; the ratios are what compare, and the bare app's own time varied 1.5–2.3 s
between runs), before and after `/readyz` waited for the warm-up:

| target | goal | before | after |
|---|---|---|---|
| spawn to `/readyz` / bare app's | ≤ 2× | ×5.6–7.3 (14.9–17.5 s; ready before the warm-up ran) | **missed**: ×7.0–8.2 (11.4–12.7 s; warm-up included) |
| first `impact.rare` simulation after ready / steady | ≤ 2× | ×123–178 (1.4–1.6 s vs 8–17 ms) | ×1.0–1.3 (13–14 ms vs 10–14 ms) |
| first `blow.joint` simulation after ready / steady | ≤ 2× | ×1.1–1.2 | ×1.1–1.4 |

Before and after spawned alternately in one run (load 13–16): the service answered after
15.2 s before and 13.4 s after (medians of four), and was ready after 15.2 s before (not
warmed up) and 14.7 s after (warmed up): the collector's saving pays for the wait.

**Why spawn to ready is missed.** The bare app imports FastAPI and uvicorn; the service
also imports the engine and builds 18 models' request and response schemas, and the
warm-up loads the kernels from numba's cache (0.3–0.5 s idle). `python -m service` imports
and builds with the garbage collector off (about a quarter of that time, measured
alternating). scipy's `optimize`, `stats`, `special` and `integrate` are imported on first
use (`engine.numerics.lazy.LazyModule`): before, `engine.procedures.clutch_asbuilt`
imported scipy.optimize (14 % of `import service.main`) and `engine.numerics.laws`
scipy.stats (9 %); the warm-up imports only scipy.special (`tool.capability`'s example), and
studies import scipy.stats on their first request. pint's unit registry is built from
pint's definition cache (`service/__pycache__/pint`, parsed afresh where it cannot be
read or written): 0.05–0.07 s instead of 0.24–0.47 s. Since then pint is neither imported
nor built before `/readyz` says ready: the warm-up builds the registry just after it (0.3 s
of CPU off the path to ready, pint's import of dask included), so the form's unit strings
still find it built; a request with one that comes sooner waits for it. What remained, from
`python -X importtime` after these changes (three runs, load 3–14): pint and the units
18–31 % (pint imports dask whenever dask is installed, 11–19 %: pint 0.25 offers no
switch, and hiding dask from its import would patch its internals), numba 11–19 %
(imported by the modules that define the kernels, which the warm-up runs anyway; nothing
else imports it), FastAPI 8–12 %, numpy 6–13 %; building the app then takes about a third as long again (pydantic models).
Medians of seven alternating fresh `python -c "import service.main"` runs before and
after these changes: at load 3–5, 3.98 s against 2.21 s (`-X importtime`: 2.60 s against
1.43 s; before the registry cache); at load 12–14, 10.6 s against 6.2 s (7.8 s against
4.4 s), ×0.58 the time, median of the per-run ratios. `bench/cold_start.py`, two rounds with and
then two without these changes: spawn to `/readyz` ×4.9 the bare app (2.17 s) against
×8.0 (2.70 s) at load 4–4.5, ×6.0 (11.9 s) against ×6.9 (8.0 s) at load 13–14; still
above the ≤ 2× target.

### Simulations within a time budget

The rare-impact cycle and the blow simulation are compiled (numba) fixed-step RK4 kernels
with event location. Each takes as many steps as half the time left affords at the
kernel's cost per step, measured on its own runs in the process; `MAX_STEPS` bounds them
only where no deadline is set. A stiff design that needs millions of steps runs when they
fit in `BUDGET_S`; one that does not is declined before it starts, so `auto` (or the rare
impact's declared fallback) answers at once. The blow's simulation takes 0.03–0.3 ms a
blow, about 100 times faster than `solve_ivp` at the same accuracy
(`bench/extra_blow.py`); `bench/extra_rare_impact.py` compares the rare-impact cycle with
the same cycle on DOP853.
"""


def render(
    results: Mapping[str, Any],
    loadtest: Mapping[str, Any] | None = None,
    shopfloor: Mapping[str, Any] | None = None,
) -> str:
    """The whole page from the stored figures."""
    rows = measured_rows(results, loadtest)
    summary, details = targets_table(rows)
    failures = results.get("failures") or []
    failed = ""
    if failures:
        names = sorted({str(f).split(":", 1)[0] for f in failures})
        failed = (
            "Benchmarks that failed in this run: " + ", ".join(f"`{n}`" for n in names) + ".\n\n"
        )
    return (
        INTRO
        + stamp(results, loadtest)
        + "\n"
        + TARGETS_HEAD
        + summary
        + "\n"
        + failed
        + DETAILS_HEAD
        + details
        + "\n"
        + UNDER_LOAD
        + shopfloor_section(shopfloor)
        + NOTES
    )


def _read(path: Path) -> dict[str, Any] | None:
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else None


def build(bench: Path = HERE) -> str:
    results = _read(bench / "results.json") or {}
    return render(results, _read(bench / "loadtest.json"), _read(bench / "shopfloor.json"))


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m bench.page", description=__doc__)
    parser.add_argument("--out", type=Path, default=PAGE, help="the page to write")
    parser.add_argument("--check", action="store_true", help="exit 1 if the page is stale")
    args = parser.parse_args(argv)
    text = build()
    if args.check:
        current = args.out.read_text(encoding="utf-8") if args.out.is_file() else ""
        if current != text:
            print(f"{args.out} is stale: run python -m bench.page", file=sys.stderr)
            return 1
        return 0
    args.out.write_text(text, encoding="utf-8")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
