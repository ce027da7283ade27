"""bench/accuracy.py finds the family files, runs them, and prints and writes the table.

Shown on toy families written here (no real model): the small-angle sine, sin x ≈ x for
x drawn uniformly in (0, 2), against numpy's sine. Its error x − sin x is bounded by
x³/6 (the alternating Taylor series), so that claim holds everywhere; x³/7 does not.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from bench import accuracy
from bench.accuracy import Row

SINE = """
import numpy as np


def rows(n=200, seed=0):
    x = np.random.default_rng(seed).uniform(0.0, 2.0, n)
    error = np.abs(np.sin(x) - x)
    out = []
    for name, estimate, kind in (("x^3/6", x**3 / 6, "bound"), ("x^3/7", x**3 / 7, "typical")):
        ratio = error / estimate
        out.append({
            "model": "toy.sine", "rung": "small_angle", "output": name,
            "stated": "|sin x - x| <= " + name, "kind": kind, "n": n,
            "exceeded": int((ratio > 1.0).sum()), "worst_ratio": float(ratio.max()),
            "reference": "numpy.sin, correct to 1 ulp | far tighter than the claim",
        })
    return out
"""

#: x³/7 claimed as a bound: a claim the rung may not make.
OVERCLAIM = SINE.replace('"typical")', '"bound")')
CRASHES = "def rows(n=200, seed=0):\n    raise RuntimeError('reference diverged')\n"
MALFORMED = (
    "def rows(n=200, seed=0):\n"
    "    return [{'model': 'm', 'rung': 'r', 'output': 'o', 'stated': 's', 'kind': 'usually',\n"
    "             'n': 3, 'exceeded': 0, 'worst_ratio': None, 'reference': 'ref'}]\n"
)


def _families(tmp_path: Path, **files: str) -> Path:
    for family, text in files.items():
        (tmp_path / f"accuracy_{family}.py").write_text(text)
    (tmp_path / "extra_sine.py").write_text(SINE)  # not a family file: not found
    return tmp_path


def _crossover() -> float:
    """Where x − sin x = x³/7 in (0, 2): below it the x³/7 claim fails (bisection)."""
    lo, hi = 0.5, 2.0  # x − sin x − x³/7 > 0 at 0.5, < 0 at 2
    for _ in range(200):
        mid = (lo + hi) / 2
        if mid - math.sin(mid) > mid**3 / 7:
            lo = mid
        else:
            hi = mid
    return lo


def test_discovery_finds_the_family_files_only(tmp_path: Path) -> None:
    d = _families(tmp_path, sine=SINE, crashes=CRASHES)
    assert accuracy.discover(d) == {
        "crashes": d / "accuracy_crashes.py",
        "sine": d / "accuracy_sine.py",
    }
    assert accuracy.discover(tmp_path / "nowhere") == {}


def test_a_toy_family_is_measured_and_tabled(tmp_path: Path) -> None:
    d = _families(tmp_path, sine=SINE)
    measured = accuracy.measure(accuracy.discover(d), n=200, seed=0)
    assert measured.failures == [] and measured.ok
    bound, typical = measured.rows
    # the bound: x − sin x < x³/6 for every x > 0; the ratio tends to 1 only as x → 0
    assert (bound.kind, bound.n, bound.exceeded, bound.share) == ("bound", 200, 0, 0.0)
    assert bound.worst_ratio is not None and 0.99 < bound.worst_ratio < 1.0
    # x³/7 fails below the crossover (1.7529, bisection above), at the same seeded draw
    x_star = _crossover()
    assert x_star == pytest.approx(1.75288, abs=1e-5)
    x = np.random.default_rng(0).uniform(0.0, 2.0, 200)
    count = int((x < x_star).sum())
    assert (typical.kind, typical.exceeded) == ("typical", count) and count == 163
    assert typical.worst_ratio == pytest.approx(
        7 / 6, rel=1e-3
    )  # the x → 0 limit of 7(x − sin x)/x³
    text = accuracy.table(measured.rows)
    head, rule, first, second = text.splitlines()
    assert head.split()[:8] == [
        "model",
        "rung",
        "output",
        "stated",
        "kind",
        "n",
        "exceeded",
        "share",
    ]
    assert len(rule) == len(head) and set(rule) == {"-"}
    assert first.split()[:4] == ["toy.sine", "small_angle", "x^3/6", "|sin"]
    assert "  bound  " in first and first.split("bound")[1].split()[:3] == ["200", "0", "0"]
    # 163 / 200 = 81.5 %, to 2 figures; the worst ratio 7/6 = 1.167 to 3
    assert re.search(r"  typical  +200 +163 +82 % +1\.17  numpy", second), second
    assert second.endswith("numpy.sin, correct to 1 ulp | far tighter than the claim")


def test_a_bound_that_is_exceeded_is_flagged_and_fails_the_run(tmp_path: Path) -> None:
    d = _families(tmp_path, sine=OVERCLAIM)
    out = tmp_path / "accuracy.md"
    assert accuracy.main(["--dir", str(d), "--out", str(out)]) == 1
    text = out.read_text()
    assert text.startswith(accuracy.HEADER)
    assert (
        "| toy.sine | small_angle | x^3/7 | \\|sin x - x\\| <= x^3/7 | bound ✗ | 200 | 163 |"
        in text
    )
    assert "x^3/7: stated as a bound, exceeded in 163 of 200 designs" in text


def test_a_failing_or_malformed_family_is_reported_and_the_rest_kept(tmp_path: Path) -> None:
    d = _families(tmp_path, crashes=CRASHES, malformed=MALFORMED, sine=SINE)
    measured = accuracy.measure(accuracy.discover(d), n=20, seed=1)
    assert [r.output for r in measured.rows] == ["x^3/6", "x^3/7"]
    assert measured.rows[0].n == 20 and not measured.ok
    crash, bad = measured.failures
    assert crash.startswith("accuracy_crashes.py: ") and "reference diverged" in crash
    assert bad == (
        "accuracy_malformed.py, row 1: kind = 'usually' is not allowed: must be 'bound' or "
        "'typical'"
    )


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"exceeded": 4}, "exceeded = 4 is more than n = 3"),
        ({"n": 2.5}, "n = 2.5 is not a count"),
        ({"exceeded": -1}, "exceeded = -1 is negative"),
        ({"reference": None, "stated": None}, None),
    ],
)
def test_rows_are_checked(change: dict[str, object], message: str | None) -> None:
    raw = {
        "model": "toy.sine",
        "rung": "small_angle",
        "output": "o",
        "stated": "s",
        "kind": "bound",
        "n": 3,
        "exceeded": 0,
        "worst_ratio": float("inf"),
        "reference": "ref",
    }
    raw.update(change)
    if message is None:  # texts are printed as given; a non-finite ratio is not known
        row = accuracy.normalise("toy", raw)
        assert (row.reference, row.worst_ratio, accuracy.fmt_ratio(row.worst_ratio)) == (
            "None",
            None,
            "—",
        )
        return
    with pytest.raises(ValueError, match=message):
        accuracy.normalise("toy", raw)
    del raw["reference"]
    with pytest.raises(ValueError, match="a row lacks reference"):
        accuracy.normalise("toy", raw)


def test_share_and_ratio_formats() -> None:
    def row(exceeded: int, n: int = 200, worst: float | None = 1.5) -> Row:
        return Row("f", "m", "r", "o", "s", "typical", n, exceeded, worst, "ref")

    assert [accuracy.fmt_share(row(e)) for e in (0, 1, 28, 200)] == [
        "0 %",
        "0.5 %",
        "14 %",
        "100 %",
    ]
    assert accuracy.fmt_share(row(1, n=5000)) == "< 0.1 %"
    assert [accuracy.fmt_ratio(v) for v in (None, 0.0123, 1.37, 62.4, 3.2e7)] == [
        "—",
        "0.0123",
        "1.37",
        "62×",
        "3.2e+07×",
    ]
    skipped = Row("f", "m", "r", "o", "s", "bound", 197, 0, 0.5, "ref", skipped=3)
    assert accuracy.cells(skipped)[5] == "197 (+3 skipped)"
    mislabelled = Row("f", "m", "r", "o", "s", "typical", 9, 1, 2.0, "ref", declared="bound")
    assert mislabelled.mislabelled and accuracy.cells(mislabelled)[4] == "typical (rung says bound)"
    assert accuracy.declared_kind("no.such.model", "rung") is None


def test_no_family_yet_says_so(tmp_path: Path) -> None:
    out = tmp_path / "accuracy.md"
    assert accuracy.main(["--dir", str(tmp_path), "--out", str(out)]) == 0
    text = out.read_text()
    assert "No family measured yet: there is no `bench/accuracy_*.py`." in text
    assert "Families measured: none." in text and "load average" in text
    assert accuracy.table([]) == "no family measured yet (no bench/accuracy_*.py)"
