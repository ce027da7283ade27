"""Do the error estimates bound the error? ``python -m bench.accuracy [--n 200] [--families ...]``

Each model family measures its own estimates in ``bench/accuracy_<family>.py``, which
exposes ``rows(n: int = 200, seed: int = 0) -> list[dict]``: one dict per (model, rung,
output) with

``model, rung, output``
    what was measured;
``stated``
    the claim, e.g. "1e-6 relative" or "estimate per design";
``kind``
    "bound" or "typical" (as the rung declares it: :attr:`engine.Rung.estimate_kind`);
``n``
    how many designs, drawn uniformly in the declared ranges, were compared;
``exceeded``
    how many of them had ``|result − reference| >`` the stated estimate;
``worst_ratio``
    the largest ``|result − reference| / estimate`` (None where not known);
``reference``
    one line: how the reference was made, and that it is at least 100× tighter;
``skipped`` (optional)
    designs left out because the reference itself failed on them.

This module finds those files, runs each ``rows()``, prints one table and writes
``docs/accuracy.md`` (:data:`HEADER` is its fixed text; the rest is generated and stamped
with the date and the machine's load). It knows no model's physics. A family that fails is
reported, not fatal; the exit status is 1 when a family failed, when a claim labelled a
bound was exceeded, or when a row's kind differs from the kind its rung declares.
"""

from __future__ import annotations

import argparse
import datetime
import importlib
import importlib.util
import math
import os
import platform
import subprocess
import sys
import time
import traceback
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
DOC = ROOT / "docs" / "accuracy.md"
PATTERN = "accuracy_*.py"
KINDS = ("bound", "typical")
REQUIRED = (
    "model",
    "rung",
    "output",
    "stated",
    "kind",
    "n",
    "exceeded",
    "worst_ratio",
    "reference",
)
COLUMNS = (
    "model",
    "rung",
    "output",
    "stated",
    "kind",
    "n",
    "exceeded",
    "share",
    "worst ratio",
    "reference",
)

HEADER = """\
# Accuracy: do the error estimates bound the error?

Every answer of the engine carries an error estimate (`error_estimate`) and says what it
promises (`error_kind`): a **bound**, which no design in the model's declared ranges
exceeds, or a **typical** figure, which some designs exceed; the answer's notes and the
catalogue then give the share measured here. This page holds each claim to a measurement.

**How it is made.** For each model, rung and output, `bench/accuracy_<family>.py` draws
`n` designs uniformly in the declared input ranges (seeded, so the draw repeats), computes
each with the rung, and compares the result with a reference computed at least 100× more
tightly (the reference column says how). A design is *exceeded* when
|result − reference| is larger than the error estimate the rung stated for it. A design on
which the reference itself fails is skipped and counted. `python -m bench.accuracy` runs
every family and writes this page; `make bench` runs it too.

**How to read it.** *stated* is the claim; *kind* is what the rung declares it to be;
*n* the designs compared; *exceeded* how many broke the claim and *share* that count over
*n*; *worst ratio* the largest |error| / estimate over the draw (below 1: the claim held
everywhere; 62×: one design was 62 times further off than claimed). A bound must show
0 exceeded; a row marked **✗** is a bound that was exceeded, a claim the rung may not
make. A typical estimate shows its share here and in every answer that relies on it.
"""


@dataclass
class Row:
    """One measured claim, checked and normalised from a family's dict."""

    family: str
    model: str
    rung: str
    output: str
    stated: str
    kind: str
    n: int
    exceeded: int
    worst_ratio: float | None
    reference: str
    skipped: int = 0
    #: The kind the model's rung declares, where the model is registered (else None).
    declared: str | None = None

    @property
    def share(self) -> float:
        """Share of the compared designs that exceeded the claim (0 with none compared)."""
        return self.exceeded / self.n if self.n else 0.0

    @property
    def broken(self) -> bool:
        """A bound that some design exceeded: a claim the rung may not make."""
        return self.kind == "bound" and self.exceeded > 0

    @property
    def mislabelled(self) -> bool:
        """The measured kind differs from the one the rung declares."""
        return self.declared is not None and self.declared != self.kind


@dataclass
class Measured:
    """Every family's rows, the failures, and how long each family took."""

    rows: list[Row] = field(default_factory=list)
    failures: list[str] = field(default_factory=list)
    seconds: dict[str, float] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return not self.failures and not any(r.broken or r.mislabelled for r in self.rows)


def discover(directory: Path = HERE) -> dict[str, Path]:
    """``{family: path}`` for every ``accuracy_<family>.py`` in ``directory``, sorted."""
    found = sorted(p for p in directory.glob(PATTERN) if p.is_file())
    return {p.stem.removeprefix("accuracy_"): p for p in found}


def load(path: Path) -> ModuleType:
    """The family module at ``path`` (imported as part of ``bench`` when it lives here)."""
    if path.resolve().parent == HERE:
        return importlib.import_module(f"bench.{path.stem}")
    spec = importlib.util.spec_from_file_location(path.stem, path)
    if spec is None or spec.loader is None:
        raise ImportError(f"cannot import {path}")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _count(raw: Mapping[str, Any], key: str) -> int:
    value = raw.get(key, 0)
    if isinstance(value, bool) or not isinstance(value, int | float) or value != int(value):
        raise ValueError(f"{key} = {value!r} is not a count")
    if value < 0:
        raise ValueError(f"{key} = {value!r} is negative")
    return int(value)


def normalise(family: str, raw: Mapping[str, Any]) -> Row:
    """A family's dict as a :class:`Row`; ValueError naming the key where it is malformed."""
    missing = [k for k in REQUIRED if k not in raw]
    if missing:
        raise ValueError(f"a row lacks {', '.join(missing)}")
    kind = str(raw["kind"])
    if kind not in KINDS:
        raise ValueError(f"kind = {kind!r} is not allowed: must be 'bound' or 'typical'")
    n, exceeded = _count(raw, "n"), _count(raw, "exceeded")
    if exceeded > n:
        raise ValueError(f"exceeded = {exceeded} is more than n = {n}")
    worst = raw["worst_ratio"]
    worst = None if worst is None else float(worst)
    if worst is not None and not math.isfinite(worst):
        worst = None
    return Row(
        family=family,
        model=str(raw["model"]),
        rung=str(raw["rung"]),
        output=str(raw["output"]),
        stated=str(raw["stated"]),
        kind=kind,
        n=n,
        exceeded=exceeded,
        worst_ratio=worst,
        reference=str(raw["reference"]),
        skipped=_count(raw, "skipped"),
        declared=declared_kind(str(raw["model"]), str(raw["rung"])),
    )


def declared_kind(model: str, rung: str) -> str | None:
    """The ``estimate_kind`` the registered ``model``'s ``rung`` declares, or None if unknown."""
    import engine

    try:
        declared = engine.get_model(model).rung(rung)
    except (KeyError, LookupError, ValueError):
        return None
    return str(getattr(declared, "estimate_kind", "bound"))


def measure(families: Mapping[str, Path], n: int = 200, seed: int = 0) -> Measured:
    """Run each family's ``rows(n, seed)``; a family that raises or returns a malformed row
    is a failure (its well-formed rows are kept)."""
    out = Measured()
    for family, path in families.items():
        start = time.perf_counter()
        print(f"accuracy: {family} ({path.name}) …", file=sys.stderr, flush=True)
        try:
            raws = list(load(path).rows(n=n, seed=seed))
        except Exception:
            out.failures.append(f"{path.name}: {traceback.format_exc(limit=3)}")
            raws = []
        for i, raw in enumerate(raws):
            try:
                out.rows.append(normalise(family, raw))
            except (ValueError, TypeError) as exc:
                out.failures.append(f"{path.name}, row {i + 1}: {exc}")
        out.seconds[family] = time.perf_counter() - start
    return out


def fmt_share(row: Row) -> str:
    """``0 %``, ``< 0.1 %`` or the share to two figures."""
    if row.exceeded == 0:
        return "0 %"
    pct = 100.0 * row.share
    if pct < 0.1:
        return "< 0.1 %"
    return f"{pct:.0f} %" if pct >= 10 else f"{pct:.2g} %"


def fmt_ratio(value: float | None) -> str:
    if value is None:
        return "—"
    return f"{value:.3g}" if value < 10 else f"{value:.0f}×" if value < 1e6 else f"{value:.1e}×"


def cells(row: Row) -> list[str]:
    """A row's cells in :data:`COLUMNS` order, as both tables print them."""
    kind = row.kind + (" ✗" if row.broken else "")
    if row.mislabelled:
        kind += f" (rung says {row.declared})"
    n = f"{row.n}" + (f" (+{row.skipped} skipped)" if row.skipped else "")
    return [
        row.model,
        row.rung,
        row.output,
        row.stated,
        kind,
        n,
        str(row.exceeded),
        fmt_share(row),
        fmt_ratio(row.worst_ratio),
        row.reference,
    ]


def table(rows: Sequence[Row]) -> str:
    """The rows as a plain-text table, columns padded (the reference last, unpadded)."""
    if not rows:
        return "no family measured yet (no bench/accuracy_*.py)"
    body = [cells(r) for r in rows]
    widths = [max(len(c), *(len(b[i]) for b in body)) for i, c in enumerate(COLUMNS[:-1])]
    right = {"n", "exceeded", "share", "worst ratio"}

    def line(values: Sequence[str]) -> str:
        padded = [
            v.rjust(w) if name in right else v.ljust(w)
            for v, w, name in zip(values, widths, COLUMNS, strict=False)
        ]
        return "  ".join([*padded, values[-1]]).rstrip()

    head = line(COLUMNS)
    return "\n".join([head, "-" * len(head), *(line(b) for b in body)])


def _md(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def markdown_table(rows: Sequence[Row]) -> str:
    if not rows:
        return "No family measured yet: there is no `bench/accuracy_*.py`."
    lines = [
        "| " + " | ".join(COLUMNS) + " |",
        # no alignment markers: they become inline styles, which the manual's CSP forbids
        "|" + "|".join("---" for _ in COLUMNS) + "|",
    ]
    lines += ["| " + " | ".join(_md(c) for c in cells(r)) + " |" for r in rows]
    return "\n".join(lines)


def stamp(n: int, seed: int, seconds: float) -> str:
    """The date, the machine and its load, the commit, and the draw."""
    now = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    try:
        load1, load5, _ = os.getloadavg()
        load = f"load average {load1:.2f} (1 min), {load5:.2f} (5 min)"
    except OSError:
        load = "load average not available"
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=False,
        ).stdout.strip()
    except OSError:
        commit = ""
    return (
        f"Generated {now} on {platform.machine()} ({os.cpu_count()} CPUs, {load}), "
        f"Python {platform.python_version()}"
        + (f", commit {commit}" if commit else "")
        + f"; n = {n} designs per row asked, seed {seed}; {seconds:.0f} s."
    )


def document(measured: Measured, n: int, seed: int, families: Iterable[str]) -> str:
    """docs/accuracy.md: :data:`HEADER`, the stamp, the table, and what did not hold."""
    total = sum(measured.seconds.values())
    names = ", ".join(families) or "none"
    parts = [
        HEADER,
        "<!-- Generated by `python -m bench.accuracy`: edit HEADER in bench/accuracy.py. -->",
        "",
        stamp(n, seed, total),
        f"Families measured: {names}.",
        "",
        "## Measured",
        "",
        markdown_table(measured.rows),
    ]
    broken = [r for r in measured.rows if r.broken]
    mislabelled = [r for r in measured.rows if r.mislabelled]
    if broken or mislabelled or measured.failures:
        parts += ["", "## What did not hold", ""]
        parts += [
            f"- {r.model} / {r.rung} / {r.output}: stated as a bound, exceeded in "
            f"{r.exceeded} of {r.n} designs (worst {fmt_ratio(r.worst_ratio)})."
            for r in broken
        ]
        parts += [
            f"- {r.model} / {r.rung}: measured as {r.kind}, the rung declares {r.declared}."
            for r in mislabelled
        ]
        parts += [f"- {_md(f.strip().splitlines()[0])}" for f in measured.failures]
    return "\n".join(parts) + "\n"


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m bench.accuracy", description=__doc__.split("\n\n")[0]
    )
    parser.add_argument("--n", type=int, default=200, help="designs per row (default 200)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the draw (default 0)")
    parser.add_argument(
        "--families", nargs="*", default=None, help="only these families (default: every file)"
    )
    parser.add_argument(
        "--out",
        type=Path,
        default=None,
        help="where the page goes (default docs/accuracy.md when every family runs; "
        "with --families, nothing is written unless --out is given)",
    )
    parser.add_argument("--dir", type=Path, default=HERE, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.n < 1:
        parser.error("--n must be at least 1")
    every = discover(args.dir)
    if args.families is None:
        chosen = every
    else:
        unknown = sorted(set(args.families) - every.keys())
        if unknown:
            parser.error(
                f"no bench/accuracy_<family>.py for {', '.join(unknown)}; found "
                + (", ".join(every) or "none")
            )
        chosen = {f: every[f] for f in args.families}
    measured = measure(chosen, n=args.n, seed=args.seed)
    print("Error estimates against references (bench/accuracy_*.py)")
    print(table(measured.rows))
    for failure in measured.failures:
        print(f"\nFAILED {failure.rstrip()}")
    out = args.out if args.out is not None else (DOC if args.families is None else None)
    if out is not None:
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(document(measured, args.n, args.seed, chosen), encoding="utf-8")
        print(f"\n{len(measured.rows)} row(s) from {len(chosen)} family file(s); wrote {out}")
    return 0 if measured.ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
