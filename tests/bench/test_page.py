"""The performance page is written from the stored bench figures, and cannot drift from them."""

from __future__ import annotations

import doctest
from pathlib import Path

from bench import page

ROOT = Path(__file__).resolve().parents[2]

#: A small run: two rows of one target (one missed), one row no catalogued target claims,
#: one sweep, and the load test's p99. Every other catalogued target has no figure.
RESULTS = {
    "machine": {
        "date": "2026-01-02T03:04:05+00:00",
        "cpu_count": 2,
        "processor": "x86_64",
        "load_start": 1.25,
        "load_end": 3.5,
        "git_commit": "abc1234",
    },
    "rows": [
        {"kind": "rung", "model": "m", "method": "closed_form", "time_s": 1e-5},
        {
            "kind": "extra",
            "source": "extra_runner.py",
            "model": "a.one",
            "case": "auto / rung named",
            "ratio": 1.05,
            "target_ratio": 1.1,
            "met": True,
            "access_log": True,
        },
        {
            "kind": "extra",
            "source": "extra_runner.py",
            "model": "a.two",
            "case": "auto / rung named",
            "ratio": 1.4,
            "target_ratio": 1.1,
            "met": False,
            "access_log": True,
        },
        {
            "kind": "extra",
            "source": "extra_new.py",
            "model": "b",
            "case": "something new",
            "target": "a new target",
            "time_s": 0.003,
            "target_s": 0.01,
            "met": True,
        },
    ],
    "sweeps": [
        {
            "model": "c",
            "method": "closed_form",
            "how": "engine.sweep",
            "vary": "x",
            "points": 1_000_000,
            "time_s": 0.25,
            "met": True,
        }
    ],
}
LOADTEST = {
    "when": "2026-01-02T03:10:00+00:00",
    "targets": {"closed_form_p99_ms": 1.9, "p99_target_met": True},
}


def test_every_target_row_is_written_and_missing_ones_are_marked() -> None:
    text = page.render(RESULTS, LOADTEST)
    lines = text.splitlines()
    for target in page.TARGETS:
        assert sum(line.startswith(f"| {target.label} | {target.goal} |") for line in lines) == 1
    auto = "| default-`auto` request / the same with its rung named | ≤ ×1.1 |"
    # the range of the two figures, the higher one's model named, one of the two missed
    assert f"{auto} ×1.05–×1.40 (highest: a.two) | **no** (1 of 2 missed) |" in lines
    assert "| a new target (extra_new.py) | ≤ 10 ms | 3 ms | yes |" in lines
    assert any("`engine.sweep`" in ln and "| 250 ms | yes |" in ln for ln in lines)
    assert any("p99 latency at 8" in ln and "| 1.9 ms | yes |" in ln for ln in lines)
    # three catalogued targets have a figure here: auto, the 10⁶-point sweep and the p99
    missing = [ln for ln in lines if f"| {page.NOT_MEASURED} | - |" in ln]
    assert len(missing) == len(page.TARGETS) - 3
    assert "| spawn to `/readyz` / a bare uvicorn + FastAPI app's | ≤ ×2 | not measured" in text
    # the stamp: date, load at start and end, access log, default outputs
    assert "2026-01-02T03:04:05+00:00" in text and "start of the run 1.2, at its end 3.5" in text
    assert "in-process request rows: on; load test server: not recorded" in text
    assert "default outputs" in text and "bench/pareto.png" in text


def test_an_empty_run_still_gives_a_page() -> None:
    text = page.render({})
    assert text.count(page.NOT_MEASURED) >= len(page.TARGETS)
    assert "nan" not in text.lower().replace("nanos", "")


def test_the_committed_page_is_what_the_committed_figures_give() -> None:
    committed = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
    assert committed == page.build(ROOT / "bench"), "run python -m bench.page"


def test_the_generator_s_doctests() -> None:
    # bench/ is outside the doctest paths of pytest's configuration
    assert doctest.testmod(page).failed == 0
