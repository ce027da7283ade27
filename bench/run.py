"""Speed against accuracy, measured: ``make bench`` (or ``python -m bench.run``).

For every model in :data:`engine.MODELS`, every rung that applies to each of
its examples: the median wall time of one :func:`engine.run` (validation,
rung choice and compute, as a caller sees it) and the relative error it
achieves against the most accurate applicable rung, beside the rung's own
error estimate (honest when estimate ≥ achieved). For models with a
vectorised form: a 10⁶-point closed-form sweep and a 200-point sweep of the
most accurate rung. For every output: the time when only that output is
asked for. Then every ``bench/extra_*.py`` adds its rows (``measure() ->
list[dict]``: solver baselines such as scipy's ``solve_ivp``).

Writes ``bench/results.json`` and ``bench/pareto.png`` and prints a table.
Nothing here knows any model's physics; it reads only the spec contract.
"""

from __future__ import annotations

import argparse
import datetime
import functools
import importlib.util
import itertools
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import time
import traceback
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import scipy

import engine
from engine import EngineError, ModelSpec

from .generic import (
    applicable_rungs,
    complete_example,
    extremes,
    reference_rung,
    relative_errors,
)

HERE = Path(__file__).resolve().parent
VECTOR_POINTS = 1_000_000
SIM_SWEEP_POINTS = 200
#: Targets for the vectorised sweeps and the simulations (seconds).
VECTOR_TARGET_S = 1.0
SIM_SWEEP_TARGET_S = 2.0
#: Errors below this are shown on the plot at this floor (double rounding).
ERROR_FLOOR = 1e-16


def median_time(
    call: Callable[[], Any], seconds: float, min_reps: int = 5, max_reps: int = 100_000
) -> tuple[float, int]:
    """Median seconds per call and the number of calls timed.

    Calls are timed in batches large enough (≥ ~1 ms) that the clock's
    resolution does not matter; the median over the batches is robust to the
    odd scheduler hiccup. Stops after ``seconds`` (but times at least
    ``min_reps`` batches).
    """
    start = time.perf_counter()
    call()  # warm-up: imports, caches, compiled code
    first = time.perf_counter() - start
    batch = max(1, min(max_reps, int(1e-3 / max(first, 1e-9))))
    samples: list[float] = []
    begin = time.perf_counter()
    while len(samples) < min_reps or time.perf_counter() - begin < seconds:
        t0 = time.perf_counter()
        for _ in range(batch):
            call()
        samples.append((time.perf_counter() - t0) / batch)
        if len(samples) * batch >= max_reps:
            break
    return statistics.median(samples), len(samples) * batch


def _example_name(spec: ModelSpec, index: int) -> str:
    return "example 0 (reference case)" if index == 0 else f"example {index}"


def measure_rungs(spec: ModelSpec, seconds: float) -> list[dict[str, Any]]:
    """One row per (example, applicable rung): time per run and achieved error."""
    rows: list[dict[str, Any]] = []
    for index, example in enumerate(spec.examples):
        case = _example_name(spec, index)
        try:
            rungs = applicable_rungs(spec, example)
        except EngineError as exc:
            rows.append(_failure(spec, "-", case, f"example refused: {exc}"))
            continue
        ref = reference_rung(spec, example)
        if ref is None:
            continue
        ref_rung, _ = ref
        try:
            reference = engine.run(spec, example, fidelity=ref_rung.name, budget_s=None)
        except EngineError as exc:
            rows.append(_failure(spec, ref_rung.name, case, f"reference run failed: {exc}"))
            continue
        for rung, estimate in rungs:
            try:
                result = engine.run(spec, example, fidelity=rung.name, budget_s=None)
            except EngineError as exc:
                rows.append(_failure(spec, rung.name, case, f"{type(exc).__name__}: {exc}"))
                continue
            compute: list[float] = []

            def call(
                rung: str = rung.name,
                compute: list[float] = compute,
                example: Mapping[str, Any] = example,
            ) -> None:
                compute.append(engine.run(spec, example, fidelity=rung, budget_s=None).elapsed_s)

            time_s, reps = median_time(call, seconds)
            errors = relative_errors(spec, result.results, reference.results)
            is_ref = rung.name == ref_rung.name
            achieved = max(errors.values()) if errors else None
            stated = result.error_estimate if result.error_estimate is not None else estimate
            rows.append(
                {
                    "model": spec.name,
                    "method": rung.name,
                    "case": case,
                    "kind": "rung",
                    "time_s": time_s,
                    "compute_s": statistics.median(compute),
                    "repetitions": reps,
                    "error": None if is_ref else achieved,
                    "error_by_output": {} if is_ref else errors,
                    "outputs_compared": sorted(errors),
                    "reference": ref_rung.name,
                    "estimate": estimate,
                    "result_estimate": result.error_estimate,
                    "honest": None if is_ref or achieved is None else bool(stated >= achieved),
                    "notes": (
                        "reference (most accurate applicable rung)"
                        if is_ref
                        else f"against {ref_rung.name!r} over {len(errors)} float output(s)"
                    ),
                }
            )
    return rows


def _failure(spec: ModelSpec, method: str, case: str, why: str) -> dict[str, Any]:
    return {
        "model": spec.name,
        "method": method,
        "case": case,
        "kind": "failure",
        "time_s": None,
        "error": None,
        "notes": why,
    }


def _sweep_input(spec: ModelSpec, base: dict[str, Any]) -> tuple[str, float, float] | None:
    """A float input to sweep and a range around the example: ×0.5…×1.5, kept in range.

    The first input (the example's own first) whose whole range the model
    accepts: a quick 5-point sweep must not be refused (an input tied to a
    table, such as a thread size, is skipped).
    """
    given = list(spec.examples[0]) if spec.examples else []
    order = given + [p.name for p in spec.inputs if p.name not in given]
    for name in order:
        param = spec.param(name)
        if param.kind != "float" or not isinstance(base.get(name), float):
            continue
        bounds = extremes(param, base[name])
        assert bounds is not None
        value = base[name]
        lo, hi = (0.5 * value, 1.5 * value) if value > 0 else (value - 1.0, value + 1.0)
        lo, hi = max(lo, bounds[0]), min(hi, bounds[1])
        if lo < hi:
            try:
                engine.sweep(spec, base, name, np.linspace(lo, hi, 5).tolist(), budget_s=10.0)
            except EngineError:
                continue
            return name, lo, hi
    return None


def measure_sweeps(spec: ModelSpec, budget_s: float) -> list[dict[str, Any]]:
    """Vectorised 10⁶-point sweeps; 200-point sweeps of each looped rung and the most accurate."""
    if not spec.examples:
        return []
    try:
        base = complete_example(spec)
    except EngineError:
        return []
    picked = _sweep_input(spec, base)
    if picked is None:
        return []
    vary, lo, hi = picked
    rows: list[dict[str, Any]] = []
    if spec.vectorized is not None:
        values = np.linspace(lo, hi, VECTOR_POINTS)
        vectorized = spec.vectorized
        for rung in spec.vector_rungs:
            ctx = engine.RunContext(
                rung=rung,
                outputs=frozenset(o.name for o in spec.outputs if not o.series),
                tolerance=1e-2,
            )
            direct = _best_of(3, lambda ctx=ctx: vectorized({**base, vary: values}, ctx))  # type: ignore[misc]
            through = _best_of(
                2,
                lambda rung=rung: engine.sweep(spec, base, vary, values, fidelity=rung),  # type: ignore[misc,arg-type]
            )
            rows.append(
                _sweep_row(spec, rung, "vectorized() direct", vary, lo, hi, direct, VECTOR_TARGET_S)
            )
            rows.append(
                _sweep_row(spec, rung, "engine.sweep", vary, lo, hi, through, VECTOR_TARGET_S)
            )
    ref = reference_rung(spec, base)
    looped = [r for r, _ in applicable_rungs(spec, base) if r.name not in spec.vector_rungs]
    if ref is not None and ref[0] not in looped:
        looped.append(ref[0])
    values = np.linspace(lo, hi, SIM_SWEEP_POINTS)
    for sim in looped:
        row = _sweep_row(spec, sim.name, "engine.sweep", vary, lo, hi, None, SIM_SWEEP_TARGET_S)
        start = time.perf_counter()
        try:
            result = engine.sweep(
                spec, base, vary, values.tolist(), fidelity=sim.name, budget_s=budget_s
            )
        except EngineError as exc:
            row["notes"] = f"{type(exc).__name__}: {exc}"
        else:
            elapsed = time.perf_counter() - start
            nulls = sum(v is None for col in result.results.values() for v in col)
            row.update(time_s=elapsed, met=elapsed < SIM_SWEEP_TARGET_S)
            row["notes"] = f"{nulls} null value(s)" if nulls else ""
        rows.append(row)
    return rows


def _best_of(n: int, call: Callable[[], Any]) -> float:
    """Shortest of ``n`` timings: for one long call, the least disturbed one."""
    best = math.inf
    for _ in range(n):
        t0 = time.perf_counter()
        call()
        best = min(best, time.perf_counter() - t0)
    return best


def _sweep_row(
    spec: ModelSpec,
    rung: str,
    how: str,
    vary: str,
    lo: float,
    hi: float,
    elapsed: float | None,
    target: float,
) -> dict[str, Any]:
    points = VECTOR_POINTS if target == VECTOR_TARGET_S else SIM_SWEEP_POINTS
    return {
        "model": spec.name,
        "method": rung,
        "how": how,
        "vary": vary,
        "range": [lo, hi],
        "points": points,
        "time_s": elapsed,
        "target_s": target,
        "met": None if elapsed is None else elapsed < target,
        "notes": "",
    }


def measure_outputs(spec: ModelSpec, seconds: float) -> list[dict[str, Any]]:
    """Time of the costliest applicable rung at example 0 with all outputs, then each alone.

    The costliest rung (the last applicable one, rungs being declared cheapest
    first) is where computing only what is asked saves the most.
    """
    if not spec.examples:
        return []
    example = spec.examples[0]
    rungs = applicable_rungs(spec, example)
    if not rungs:
        return []
    rung = rungs[-1][0].name
    try:
        engine.run(spec, example, fidelity=rung, budget_s=None)
    except EngineError:
        return []
    all_s, _ = median_time(lambda: engine.run(spec, example, fidelity=rung, budget_s=None), seconds)
    rows = []
    for output in spec.outputs:
        only_s, _ = median_time(
            lambda output=output: engine.run(  # type: ignore[misc]
                spec, example, fidelity=rung, outputs=[output.name], budget_s=None
            ),
            seconds,
        )
        rows.append(
            {
                "model": spec.name,
                "method": rung,
                "output": output.name,
                "time_only_s": only_s,
                "time_all_s": all_s,
                "ratio": only_s / all_s,
            }
        )
    return rows


#: Bench files with a ``measure()`` that are not named ``extra_*.py``.
MORE_EXTRAS: tuple[Path, ...] = (
    HERE / "trace_batch.py",
    HERE / "study_summary.py",
    HERE / "capability_tails.py",  # two 10⁸-point references, a few minutes
    HERE / "cold_start.py",  # spawn to /readyz against a bare app; first simulation after
)


def run_extras(paths: Sequence[Path]) -> tuple[list[dict[str, Any]], list[str]]:
    """Rows from each ``bench/extra_*.py``'s ``measure()``; failures are reported, not fatal."""
    rows: list[dict[str, Any]] = []
    failures: list[str] = []
    for path in paths:
        try:
            module_spec = importlib.util.spec_from_file_location(f"bench.{path.stem}", path)
            assert module_spec is not None and module_spec.loader is not None
            module = importlib.util.module_from_spec(module_spec)
            # registered before it runs: a dataclass in the module looks itself up there
            sys.modules[module_spec.name] = module
            module_spec.loader.exec_module(module)
            for row in module.measure():
                rows.append({**json_safe(row), "kind": "extra", "source": path.name})
        except Exception:
            failures.append(f"{path.name}: {traceback.format_exc(limit=3)}")
    return rows, failures


def json_safe(value: Any) -> Any:
    """``value`` with numpy scalars as Python numbers and non-finite floats as None."""
    if isinstance(value, dict):
        return {str(k): json_safe(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_safe(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def is_baseline(row: dict[str, Any]) -> bool:
    """A general-purpose solver shown for comparison (scipy's solve_ivp and the like)."""
    method = str(row.get("method", "")).lower()
    return bool(row.get("baseline")) or "solve_ivp" in method or "scipy" in method


def machine() -> dict[str, Any]:
    def git(*args: str) -> str:
        try:
            done = subprocess.run(
                ["git", *args], cwd=HERE, capture_output=True, text=True, check=False
            )
        except OSError:
            return ""
        return done.stdout.strip()

    commit = git("rev-parse", "--short", "HEAD")
    # uncommitted changes to the code (not to the results this run is about to write)
    dirty = bool(git("status", "--porcelain", "--", "engine", "bench/run.py", "bench/generic.py"))
    return {
        "date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "cpu_count": os.cpu_count(),
        "machine": platform.machine(),
        "processor": platform.processor() or platform.machine(),
        "platform": platform.platform(),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "git_commit": commit,
        "git_dirty": dirty,
    }


def plot(rows: Sequence[dict[str, Any]], path: Path) -> None:
    """Time per evaluation (log x) against achieved error (log y), one marker per method."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for row in rows:
        if row.get("kind") not in ("rung", "extra") or not row.get("time_s"):
            continue
        # an extra's row names its model, or only its method (a model's name)
        model = str(row.get("model", row["method"]))
        groups.setdefault((model, str(row["method"])), []).append(row)
    models = sorted({model for model, _ in groups})
    colours = {m: plt.get_cmap("tab10")(i % 10) for i, m in enumerate(models)}
    fig, ax = plt.subplots(figsize=(13, 7), layout="constrained")
    for (model, method), members in sorted(groups.items()):
        time_s = statistics.median(r["time_s"] for r in members)
        errors = [r["error"] for r in members if r.get("error") is not None]
        reference = not errors and all(r.get("reference") == method for r in members)
        if errors:
            error = max(max(errors), ERROR_FLOOR)
        elif reference:
            estimates = [r.get("result_estimate") or r.get("estimate") for r in members]
            known = [e for e in estimates if e]
            if not known:
                continue
            error = max(max(known), ERROR_FLOOR)
        else:
            continue
        baseline = any(is_baseline(r) for r in members)
        marker = "s" if baseline else "o"
        label = f"{model}: {method}" + (" (reference; its estimate)" if reference else "")
        ax.scatter(
            [time_s],
            [error],
            s=70,
            marker=marker,
            facecolors="none" if reference or baseline else colours[model],
            edgecolors=colours[model],
            linewidths=1.5,
            label=label,
        )
        if not baseline:  # baselines' long names are in the legend only
            ax.annotate(
                method[:18], (time_s, error), xytext=(5, 4), textcoords="offset points", fontsize=7
            )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("median time per evaluation [s]")
    ax.set_ylabel("achieved relative error (worst over cases and outputs)")
    ax.set_title(
        "Speed against accuracy (worst case over each method's cases)\n"
        "filled circle: engine rung or method · hollow circle: reference rung, at its own "
        "estimate · square: general solver baseline",
        fontsize=9,
    )
    ax.axhline(ERROR_FLOOR, color="grey", lw=0.5, ls=":")
    ax.grid(True, which="major", alpha=0.3)
    if groups:
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _fmt_time(value: float | None) -> str:
    if value is None:
        return "-"
    for scale, unit in ((1.0, "s"), (1e-3, "ms"), (1e-6, "µs")):
        if value >= scale:
            return f"{value / scale:.3g} {unit}"
    return f"{value * 1e9:.3g} ns"


def _fmt_err(value: Any) -> str:
    return "-" if value is None else f"{value:.2g}"


def table(results: dict[str, Any]) -> str:
    """The results as plain-text tables."""
    lines = ["Rungs: median time per engine.run, achieved error vs the most accurate rung"]
    header = (
        f"{'model':<22} {'method':<18} {'case':<24} {'time':>10} {'compute':>10} "
        f"{'achieved':>9} {'estimate':>9} {'honest':>6}  outputs compared"
    )
    lines.append(header)
    lines.append("-" * len(header))
    for row in results["rows"]:
        honest = {True: "yes", False: "NO", None: "-"}[row.get("honest")]
        lines.append(
            f"{row.get('model', '?'):<22} {row.get('method', '?')!s:<18} "
            f"{row.get('case', ''):<24} "
            f"{_fmt_time(row.get('time_s')):>10} {_fmt_time(row.get('compute_s')):>10} "
            f"{_fmt_err(row.get('error')):>9} {_fmt_err(row.get('estimate')):>9} {honest:>6}  "
            + (", ".join(row.get("outputs_compared", [])) or str(row.get("notes", "")))
        )
    targets = [
        r
        for r in results["rows"]
        if r.get("target_s") is not None or r.get("target_ratio") is not None
    ]
    if targets:  # the speed targets (bench/extra_targets.py, extra_service.py) beside figures
        lines += ["", "Speed targets: measured against target, with the floors"]
        for row in targets:
            met = {True: "met", False: "MISSED"}.get(row.get("met"), "")
            if row.get("share"):  # a share of a time measured alongside, as a percentage
                figure, goal = f"{100 * row['ratio']:.0f} %", f"{100 * row['target_ratio']:g} %"
            elif row.get("target_ratio") is not None:  # a ratio to a floor measured alongside
                figure, goal = f"×{row['ratio']:.2f}", f"×{row['target_ratio']:g}"
            else:
                figure, goal = _fmt_time(row["time_s"]), _fmt_time(row["target_s"])
            lines.append(
                f"{row['model']:<22} {row['case']:<28} {figure:>10} "
                f"target ≤ {goal} {met:<6}  {row.get('notes', '')}"
            )
    if results["sweeps"]:
        lines += ["", "Sweeps"]
        for row in results["sweeps"]:
            met = {True: "met", False: "MISSED", None: ""}[row["met"]]
            lines.append(
                f"{row['model']:<22} {row['method']:<18} {row['how']:<20} {row['points']:>8} pts "
                f"of {row['vary']:<16} {_fmt_time(row['time_s']):>10}  "
                f"target < {_fmt_time(row['target_s'])} {met} {row['notes']}"
            )
    if results["outputs"]:
        lines += ["", "One output asked for vs all outputs (costliest applicable rung, example 0)"]
        for row in results["outputs"]:
            lines.append(
                f"{row['model']:<22} {row['method']:<18} {row['output']:<24} "
                f"{_fmt_time(row['time_only_s']):>10} vs {_fmt_time(row['time_all_s']):>10} "
                f"(×{row['ratio']:.2f})"
            )
    order = [
        f"{name}: {'yes' if info['holds'] else 'NO'} ("
        + ", ".join(f"{r} {_fmt_time(t)}" for r, t in info["median_time_s"].items())
        + ")"
        for name, info in results["rungs_order"].items()
    ]
    lines += ["", "Rungs declared cheapest first, and measured so:", *order]
    if results["failures"]:
        lines += ["", "Extra benchmarks that failed:", *results["failures"]]
    return "\n".join(lines)


def collect(models: Sequence[ModelSpec], seconds: float, extras: Sequence[Path]) -> dict[str, Any]:
    """Every measurement, as the JSON written to ``results.json``."""
    rows: list[dict[str, Any]] = []
    sweeps: list[dict[str, Any]] = []
    outputs: list[dict[str, Any]] = []
    started = time.perf_counter()
    load_start = _load_average()
    failures: list[str] = []
    for spec in models:
        parts: tuple[tuple[str, list[dict[str, Any]], Callable[[], list[dict[str, Any]]]], ...] = (
            ("rungs", rows, functools.partial(measure_rungs, spec, seconds)),
            ("sweeps", sweeps, functools.partial(measure_sweeps, spec, 60.0)),
            ("outputs", outputs, functools.partial(measure_outputs, spec, seconds / 2)),
        )
        for part, into, measure in parts:
            try:
                into.extend(measure())
            except Exception:
                failures.append(f"{spec.name} {part}: {traceback.format_exc(limit=3)}")
    extra_rows, extra_failures = run_extras(extras)
    rows += extra_rows
    failures += extra_failures
    return {
        "machine": {**machine(), "load_start": load_start, "load_end": _load_average()},
        "models": [spec.name for spec in models],
        "rungs_order": {
            spec.name: _cheapest_first(spec, [r for r in rows if r.get("kind") == "rung"])
            for spec in models
        },
        "rows": rows,
        "sweeps": sweeps,
        "outputs": outputs,
        "failures": failures,
        "extras": [p.name for p in extras],
        "elapsed_s": time.perf_counter() - started,
    }


def _load_average() -> float | None:
    """The one-minute load average (None where the platform has none): the page's stamp."""
    return os.getloadavg()[0] if hasattr(os, "getloadavg") else None


def _cheapest_first(spec: ModelSpec, rows: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """Whether the measured times agree with the spec's cheapest-first rung order."""
    times = {}
    for rung in spec.rung_names:
        mine = [r["time_s"] for r in rows if r["model"] == spec.name and r["method"] == rung]
        if mine:
            times[rung] = statistics.median(mine)
    ordered = list(times.values())
    return {
        "median_time_s": times,
        "holds": all(a <= b * 1.2 for a, b in itertools.pairwise(ordered)),
    }


def toy_models() -> list[ModelSpec]:
    """The test-only toy specs, so the pipeline can be exercised on an empty registry."""
    root = str(HERE.parent)
    if root not in sys.path:
        sys.path.insert(0, root)
    from tests.toys import TOY, TOYS

    return [TOY, *TOYS]


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m bench.run", description=__doc__)
    parser.add_argument(
        "--out", type=Path, default=HERE, help="where results.json and pareto.png go"
    )
    parser.add_argument(
        "--seconds", type=float, default=0.25, help="timing budget per measurement (s)"
    )
    parser.add_argument("--toy", action="store_true", help="also measure the test-only toy models")
    parser.add_argument("--no-extras", action="store_true", help="skip bench/extra_*.py")
    parser.add_argument("--no-plot", action="store_true", help="skip pareto.png")
    args = parser.parse_args(argv)
    models = list(engine.MODELS)
    if args.toy or not models:
        if not models:
            print("engine.MODELS is empty: measuring the test-only toy models instead")
        models += toy_models()
    extras = [] if args.no_extras else [*sorted(HERE.glob("extra_*.py")), *MORE_EXTRAS]
    results = collect(models, args.seconds, extras)
    args.out.mkdir(parents=True, exist_ok=True)
    text = json.dumps(json_safe(results), indent=1, allow_nan=False)
    (args.out / "results.json").write_text(text + "\n")
    if not args.no_plot:
        plot(results["rows"], args.out / "pareto.png")
    print(table(results))
    print(f"\n{len(models)} model(s), {results['elapsed_s']:.1f} s; wrote {args.out}/results.json")
    return 1 if results["failures"] else 0


if __name__ == "__main__":
    raise SystemExit(main())
