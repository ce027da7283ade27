#!/usr/bin/env python
"""Mutation testing of engine/physics and engine/procedures, each module against its tests.

For each module named (default: every module of engine/physics and engine/procedures in
:data:`TESTS`), Cosmic Ray (``pip install -e '.[mutate]'``) lists every mutant of the file:
an operator swapped, a comparison turned, a number changed, a loop or a branch dropped.
Mutants that cannot change behaviour by construction are left out and counted (those inside
type annotations and docstrings, and bitwise or shift operators put in place of arithmetic
on floats, which fail with a TypeError and so say nothing about the tests). A seeded sample
of the rest (``--sample`` per module at most, fewer if the module's share of ``--minutes``,
the time left over the modules left, is too short for its tests; ``--sample 0`` with a long
budget takes them all) is then applied one at a time to a copy of the project and the
module's own tests (:data:`TESTS`, its doctests included) run against it; a mutant is killed
when they fail or time out. Two
copies run side by side (``--jobs``).

A survivor listed in :data:`EQUIVALENT_FILE` (module, operator and the changed lines, with
the reason no output can change) is reported apart as equivalent; the share killed is
printed both over every mutant run and over the killable ones.

Prints, per module and in total, the share killed and each survivor with its diff;
``--json`` writes the same as data. Not part of CI or ``make test``.

    python scripts/mutate.py engine/physics/springs.py procedures/bolt threads \
        --sample 80 --seed 1
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import tomllib
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]

#: Each module's own tests, keyed by its path under engine/: its family's folder (or the
#: files that exercise it) and its validation files; its doctests are always added. Paths
#: that do not exist (moved, renamed) are left out with a warning.
TESTS: dict[str, tuple[str, ...]] = {
    "physics/springs": ("tests/models/springs", "tests/validation/test_springs_textbooks.py"),
    "physics/threads": (
        "tests/models/preload/test_threads.py",
        "tests/models/preload/test_threads_values.py",
        "tests/models/preload/test_preload_formulas.py",
        "tests/validation/test_iso898_loads.py",
    ),
    "physics/fasteners": ("tests/models/fasteners", "tests/validation/test_fasteners_standards.py"),
    "physics/preload": (
        "tests/models/preload",
        "tests/validation/test_preload_vdi2230.py",
        "tests/validation/test_preload_vdi2230_coarse.py",
    ),
    "physics/preload_methods": ("tests/models/preload",),
    "physics/joint": ("tests/models/joint", "tests/validation/test_joint_compliance.py"),
    "physics/clutch": ("tests/models/clutch", "tests/validation/test_clutch_paper.py"),
    "physics/nutrunner": ("tests/models/nutrunner", "tests/validation/test_nutrunner_seed000.py"),
    "physics/motor_spinup": ("tests/models/nutrunner",),
    "physics/rare_impact": ("tests/models/rare_impact", "tests/validation/test_rare_impact_002.py"),
    "physics/blow": ("tests/models/blow", "tests/validation/test_blow_two_mass.py"),
    "procedures/bolt": (
        "tests/models/fasteners",
        "tests/models/preload",
        "tests/models/joint",
        "tests/validation/test_fasteners_standards.py",
    ),
    "procedures/clutch_asbuilt": ("tests/models/clutch", "tests/validation/test_clutch_paper.py"),
    "procedures/striker_cycle": (
        "tests/models/rare_impact",
        "tests/validation/test_rare_impact_002.py",
    ),
}

#: Survivors judged equivalent (no output can change), each with its reason:
#: scripts/mutate_equivalent.toml. They are reported apart and the share killed is given
#: both ways (over every mutant run, and over those that a test could kill).
EQUIVALENT_FILE = ROOT / "scripts" / "mutate_equivalent.toml"

#: The inner loop's selection: no browsers, servers, installs or fuzzing; small
#: hypothesis budgets (tests/conftest.py); the first failure ends the run.
PYTEST_ARGS = (
    "-x -q -p no:cacheprovider --no-header -p no:schemathesis --hypothesis-profile=fast "
    '-m "not slow and not browser and not install and not fuzz"'
)

#: Replacements that make arithmetic on floats a TypeError: killed by any test that runs the
#: line, so they measure nothing.
_TRIVIAL = re.compile(r"core/ReplaceBinaryOperator_\w+_(BitOr|BitAnd|BitXor|LShift|RShift)$")


@dataclass
class Outcome:
    module: str
    mutants: int = 0
    left_out: dict[str, int] = field(default_factory=dict)
    sampled: int = 0
    killed: int = 0
    timeouts: int = 0
    survivors: list[dict[str, Any]] = field(default_factory=list)
    equivalent: list[dict[str, Any]] = field(default_factory=list)
    incompetent: list[dict[str, Any]] = field(default_factory=list)
    baseline_s: float = 0.0
    wall_s: float = 0.0

    @property
    def kill_rate(self) -> float:
        """Killed over every mutant run (an equivalent survivor counts as not killed)."""
        run = self.killed + len(self.survivors) + len(self.equivalent)
        return self.killed / run if run else float("nan")

    @property
    def killable_rate(self) -> float:
        """Killed over the mutants a test could kill (equivalent survivors left out)."""
        run = self.killed + len(self.survivors)
        return self.killed / run if run else float("nan")


def _module_path(key: str) -> Path:
    """engine/<key>.py for a key of :data:`TESTS` (``physics/springs``)."""
    return ROOT / "engine" / f"{key}.py"


def _key(arg: str) -> str:
    """The key of :data:`TESTS` for ``engine/physics/springs.py``, ``physics/springs`` or
    ``springs`` (a bare name must name one module)."""
    rel = arg.removesuffix(".py").removeprefix("./").removeprefix("engine/")
    if rel in TESTS or ((ROOT / "engine" / f"{rel}.py").exists() and "/" in rel):
        return rel
    found = [k for k in TESTS if k.rsplit("/", 1)[-1] == rel]
    if len(found) != 1:
        raise SystemExit(f"{arg}: not one module under engine/ ({found or 'none'})")
    return found[0]


def _normal(diff: str) -> str:
    """A diff's changed lines without their indentation: the part of a survivor that
    :data:`EQUIVALENT_FILE` matches, so that a survivor stays explained when lines move."""
    return "\n".join(
        line[0] + line[1:].strip() for line in diff.splitlines() if line.strip()[1:].strip()
    )


def _equivalents(path: Path = EQUIVALENT_FILE) -> dict[tuple[str, str, str], str]:
    """(module, operator, normalised diff) -> the reason the mutant changes no output."""
    if not path.exists():
        return {}
    with open(path, "rb") as f:
        data = tomllib.load(f)
    out = {}
    for e in data.get("equivalent", []):
        out[(e["module"], e["operator"], _normal(e["diff"]))] = e["reason"]
    return out


def _spans(source: str) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """(start, end) positions (line, column) of annotations and docstrings."""
    tree = ast.parse(source)
    nodes: list[ast.expr | ast.stmt] = []
    for n in ast.walk(tree):
        if isinstance(n, ast.arg) and n.annotation is not None:
            nodes.append(n.annotation)
        elif isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef) and n.returns is not None:
            nodes.append(n.returns)
        elif isinstance(n, ast.AnnAssign):
            nodes.append(n.annotation)
        if (
            isinstance(n, ast.Module | ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef)
            and n.body
            and isinstance(n.body[0], ast.Expr)
            and isinstance(n.body[0].value, ast.Constant)
            and isinstance(n.body[0].value.value, str)
        ):
            nodes.append(n.body[0])
    return [
        ((x.lineno, x.col_offset), (x.end_lineno or x.lineno, x.end_col_offset or 0)) for x in nodes
    ]


def _inside(pos: tuple[int, int], spans: list[tuple[tuple[int, int], tuple[int, int]]]) -> bool:
    return any(a <= pos < b for a, b in spans)


def _copy_tree(dest: Path) -> None:
    """The project's files as they are now (tracked and new, not ignored) into ``dest``."""
    files = subprocess.run(
        ["git", "ls-files", "-co", "--exclude-standard", "-z"],
        cwd=ROOT,
        capture_output=True,
        check=True,
    ).stdout.split(b"\0")
    for raw in files:
        if not raw:
            continue
        rel = Path(os.fsdecode(raw))
        src = ROOT / rel
        if src.is_file():
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / rel)


def _test_command(python: str, copy: Path, module: Path, tests: list[str]) -> str:
    rel = module.relative_to(ROOT)
    return f"env -C {copy} {python} -m pytest {PYTEST_ARGS} {' '.join(tests)} {rel}"


def _mutants(module: Path, work: Path) -> Iterator[Any]:
    """Every work item Cosmic Ray's init lists for ``module`` (one mutation each)."""
    from cosmic_ray.commands import init
    from cosmic_ray.work_db import WorkDB, use_db

    with use_db(str(work / f"{module.stem}.sqlite"), WorkDB.Mode.create) as db:
        init([module], db, {})
        items = sorted(db.work_items, key=lambda w: (w.mutations[0].start_pos, _name(w)))
    yield from items


def _name(item: Any) -> str:
    return str(item.mutations[0].operator_name)


def _run(
    name: str,
    args: argparse.Namespace,
    copies: list[Path],
    python: str,
    log: Any,
    equivalents: dict[tuple[str, str, str], str],
) -> Outcome:
    from attrs import evolve
    from cosmic_ray.mutating import mutate_and_test
    from cosmic_ray.work_item import TestOutcome, WorkerOutcome

    module = _module_path(name)
    out = Outcome(name)
    tests = [t for t in TESTS.get(name, ()) if (ROOT / t).exists()]
    for t in TESTS.get(name, ()):
        if t not in tests:
            print(f"  warning: {t} does not exist; left out", file=sys.stderr)
    if not tests:
        print(f"  warning: {name} has no tests in the mapping; doctests only", file=sys.stderr)

    # the baseline: the module's own tests pass on each unmutated copy (which warms its
    # caches), then are timed once warm
    def baseline(copy: Path) -> subprocess.CompletedProcess[bytes]:
        command = _test_command(python, copy, module, tests)
        return subprocess.run(command, shell=True, capture_output=True)

    runs: list[subprocess.CompletedProcess[bytes]] = []
    warm = [threading.Thread(target=lambda c=c: runs.append(baseline(c))) for c in copies]
    for w in warm:
        w.start()
    for w in warm:
        w.join()
    for r in runs:
        if r.returncode != 0:
            print(r.stdout.decode()[-3000:])
            raise SystemExit(f"{name}: its tests fail before any mutation")
    t0 = time.perf_counter()
    baseline(copies[0])
    out.baseline_s = time.perf_counter() - t0
    timeout = max(args.min_timeout, args.timeout_factor * out.baseline_s)

    spans = _spans(module.read_text(encoding="utf-8"))
    items = list(_mutants(module, Path(args.work)))
    out.mutants = len(items)
    kept = []
    for item in items:
        spec = item.mutations[0]
        if _inside(tuple(spec.start_pos), spans):
            out.left_out["annotation or docstring"] = (
                out.left_out.get("annotation or docstring", 0) + 1
            )
        elif _TRIVIAL.match(spec.operator_name):
            out.left_out["bitwise/shift on floats"] = (
                out.left_out.get("bitwise/shift on floats", 0) + 1
            )
        else:
            kept.append(item)
    # as many as the module's share of the time budget allows: the time left over the modules
    # left, so what a quick module leaves the next ones use (a survivor runs every test; a
    # killed mutant stops at its first failure, so this errs on the short side)
    share = max(args.deadline - time.perf_counter(), 0.0) / max(args.modules_left, 1)
    n = max(1, int(share * len(copies) / max(out.baseline_s, 1.0)))
    n = min(n, args.sample) if args.sample else n
    rng = random.Random(f"{args.seed}:{name}")
    sample = kept if n >= len(kept) else rng.sample(kept, n)
    sample.sort(key=lambda w: (w.mutations[0].start_pos, _name(w)))
    out.sampled = len(sample)
    print(
        f"{name}: {out.mutants} mutants, {sum(out.left_out.values())} left out "
        f"({', '.join(f'{v} {k}' for k, v in out.left_out.items()) or 'none'}), "
        f"{out.sampled} run (seed {args.seed}); "
        f"tests {out.baseline_s:.1f} s, timeout {timeout:.0f} s",
        flush=True,
    )
    queue = list(sample)
    lock = threading.Lock()

    def worker(copy: Path) -> None:
        target = copy / module.relative_to(ROOT)
        command = _test_command(python, copy, module, tests)
        while True:
            with lock:
                if not queue:
                    return
                item = queue.pop(0)
            spec = item.mutations[0]
            result = mutate_and_test([evolve(spec, module_path=target)], command, timeout)
            line = spec.start_pos[0]
            entry = {
                "line": line,
                "operator": spec.operator_name.removeprefix("core/"),
                "occurrence": spec.occurrence,
                "diff": "\n".join(
                    d
                    for d in (result.diff or "").splitlines()
                    if d[:1] in "+-" and d[:3] not in ("+++", "---")
                ),
            }
            with lock:
                if result.worker_outcome != WorkerOutcome.NORMAL:
                    out.incompetent.append({**entry, "why": (result.output or "")[-300:]})
                    mark = "!"
                elif result.test_outcome == TestOutcome.SURVIVED:
                    why = equivalents.get((name, entry["operator"], _normal(entry["diff"])))
                    if why is None:
                        out.survivors.append(entry)
                        mark = "S"
                    else:
                        out.equivalent.append({**entry, "why": why})
                        mark = "e"
                elif result.test_outcome == TestOutcome.KILLED:
                    out.killed += 1
                    out.timeouts += result.output == "timeout"
                    mark = "."
                else:
                    out.incompetent.append({**entry, "why": (result.output or "")[-300:]})
                    mark = "!"
                print(mark, end="", flush=True)
                log.write(json.dumps({"module": name, "mark": mark, **entry}) + "\n")
                log.flush()  # each mutant as it ends, to follow a long run

    t0 = time.perf_counter()
    threads = [threading.Thread(target=worker, args=(c,)) for c in copies]
    for w in threads:
        w.start()
    for w in threads:
        w.join()
    out.wall_s = time.perf_counter() - t0
    out.survivors.sort(key=lambda e: (e["line"], e["operator"]))
    out.equivalent.sort(key=lambda e: (e["line"], e["operator"]))
    print(f" {out.kill_rate:.1%} killed ({out.killable_rate:.1%} of the killable)", flush=True)
    _survivors(out)
    return out


def _survivors(o: Outcome) -> None:
    """A module's survivors with their diffs (those judged equivalent by one line each)."""
    if o.survivors:
        print(f"survivors in {_module_path(o.module).relative_to(ROOT)}:")
        for s in o.survivors:
            print(f"  line {s['line']}: {s['operator']} #{s['occurrence']}")
            for d in s["diff"].splitlines():
                print(f"      {d}")
    for s in o.equivalent:
        print(f"  equivalent, line {s['line']} {s['operator']}: {s['why']}")
    for s in o.incompetent:
        print(f"  not run (line {s['line']} {s['operator']}): {s['why'][-200:]}")
    sys.stdout.flush()


def _rescored(path: Path, equivalents: dict[tuple[str, str, str], str]) -> list[Outcome]:
    """The outcomes a ``--json`` file holds, survivors matched again against ``equivalents``."""
    outcomes = []
    for d in json.loads(path.read_text()):
        o = Outcome(**{k: v for k, v in d.items() if k in Outcome.__dataclass_fields__})
        survivors, o.survivors = o.survivors, []
        for s in survivors:
            why = equivalents.get((o.module, s["operator"], _normal(s["diff"])))
            (o.survivors if why is None else o.equivalent).append(
                s if why is None else {**s, "why": why}
            )
        outcomes.append(o)
    return outcomes


def _report(outcomes: list[Outcome], wall_s: float) -> None:
    print(
        "\nmodule                     mutants  left out  run  killed  survived  equivalent"
        "  killed/run  killed/killable   time"
    )
    for o in outcomes:
        print(
            f"{o.module:26} {o.mutants:7} {sum(o.left_out.values()):9} {o.sampled:4} "
            f"{o.killed:7} {len(o.survivors):9} {len(o.equivalent):11} {o.kill_rate:11.1%} "
            f"{o.killable_rate:16.1%} {o.wall_s / 60:5.1f} min"
        )
    killed = sum(o.killed for o in outcomes)
    survived = sum(len(o.survivors) for o in outcomes)
    equivalent = sum(len(o.equivalent) for o in outcomes)
    run = killed + survived + equivalent
    print(
        f"{'all':26} {sum(o.mutants for o in outcomes):7} "
        f"{sum(sum(o.left_out.values()) for o in outcomes):9} {run:4} {killed:7} {survived:9} "
        f"{equivalent:11} {killed / max(run, 1):11.1%} "
        f"{killed / max(killed + survived, 1):16.1%} {wall_s / 60:5.1f} min"
    )
    if survived:
        print(
            "\nsurvivors not explained (a test should kill them, or scripts/mutate_equivalent.toml"
        )
        print("should say why no output changes):")
        for o in outcomes:
            for s in o.survivors:
                first = next(iter(s["diff"].splitlines()), "")
                print(f"  {o.module}:{s['line']} {s['operator']}  {first.strip()}")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("modules", nargs="*", help="engine/<name>.py files or names (default: all)")
    p.add_argument("--sample", type=int, default=100, help="at most this many per module (0: all)")
    p.add_argument(
        "--minutes",
        type=float,
        default=50.0,
        help="time budget: each module takes the time left over the modules left",
    )
    p.add_argument("--seed", default="0", help="seed of the sample")
    p.add_argument("--jobs", type=int, default=2, help="copies of the project run side by side")
    p.add_argument("--timeout-factor", type=float, default=4.0)
    p.add_argument("--min-timeout", type=float, default=60.0)
    p.add_argument("--json", help="write the outcome here")
    p.add_argument("--log", help="write each mutant's outcome here as it ends (JSON lines)")
    p.add_argument("--python", default=sys.executable)
    p.add_argument(
        "--rescore",
        metavar="JSON",
        help="no run: print the report of a --json outcome with today's list of equivalents",
    )
    args = p.parse_args(argv)
    if args.rescore:
        _report(_rescored(Path(args.rescore), _equivalents()), float("nan"))
        return 0
    names = [_key(m) for m in args.modules] or list(TESTS)
    equivalents = _equivalents()
    args.modules_left = len(names)
    with tempfile.TemporaryDirectory(prefix="mutate-") as tmp:
        args.work = tmp
        # compiled bytecode of the unmutated copies, kept apart from the project's: Cosmic Ray
        # runs each mutant with PYTHONDONTWRITEBYTECODE=1 and a mutated (or restored) file has
        # a newer time stamp than its cached bytecode, so only the unchanged files load from it
        os.environ["PYTHONPYCACHEPREFIX"] = str(Path(tmp) / "pycache")
        os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
        copies = []
        for i in range(max(1, args.jobs)):
            copy = Path(tmp) / f"copy{i}"
            _copy_tree(copy)
            copies.append(copy)
        t0 = time.perf_counter()
        with open(args.log or Path(tmp) / "log.jsonl", "w") as log:
            args.deadline = t0 + args.minutes * 60
            outcomes = []
            for n in names:
                outcomes.append(_run(n, args, copies, args.python, log, equivalents))
                args.modules_left -= 1
        wall_s = time.perf_counter() - t0
    _report(outcomes, wall_s)
    if args.json:
        Path(args.json).write_text(
            json.dumps(
                [
                    {**o.__dict__, "kill_rate": o.kill_rate, "killable_rate": o.killable_rate}
                    for o in outcomes
                ],
                indent=1,
            )
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
