"""Every numeric output of every registered model is held by a value test.

A static scan (no test is run) of ``tests/`` and of the doctests in ``engine/``
finds the assertions that compare a model's output with a value:

- ``pin("model", "output", actual, expected, ...)`` (:mod:`tests.pins`): exact;
- an ``assert`` whose comparison (``==``, ``<``, ``<=``, ``>``, ``>=``; so
  ``== pytest.approx(...)`` and ``abs(a - b) < tol`` too) has on one side an
  expression that reads an output by its name as a string literal
  (``r.results["x"]``, ``out["x"]``, ``v.get("x")``, ``chunk.values["x"][3]``)
  and on another side something that is not ``None``, a bool, a string or 0
  (a sign is not a value);
- ``math.isclose``/``np.isclose``/``np.allclose`` inside an ``assert``, and
  ``np.testing.assert_allclose``/``assert_almost_equal``/… anywhere, with such
  an expression as one of the two compared arguments;
- a doctest line that reads an output by name and prints a number.

A name read inside ``len()``, ``isinstance()``, ``type()`` and the like is not a
value. The output is credited to the models the enclosing test function names
(by registry name ``"joint.vdi2230"``, API path ``/joint/vdi2230``, a declaration
imported from ``engine.models`` such as ``VDI2230``, or a module-level alias of
one of those); a function naming none is credited with the models its file names.

What is left is compared with :data:`NOT_YET_PINNED` both ways: a new output no
test holds fails, and so does an output that became held and is still listed
(take it off the list). The list is printed (``pytest -s``).
"""

from __future__ import annotations

import ast
import doctest
import importlib
import pkgutil
import re
from collections.abc import Iterable, Iterator
from pathlib import Path

import engine
import engine.models
from engine.spec import ModelSpec

ROOT = Path(__file__).resolve().parents[1]

#: Numeric outputs that no value test holds yet, per model. Shrink it; never grow it.
NOT_YET_PINNED: dict[str, set[str]] = {
    "blow.joint": {
        "clutch_spring_force_for_target",
        "delivered_preload_max",
        "delivered_preload_min",
        "energy_into_joint",
        "joint_energy_fraction",
        "nut_rotation",
        "saturation_torque",
        "tool_stiffness_used",
    },
    "clutch.ball": {
        "flank_lift",
        "natural_frequency",
        "spring_rate",
        "wahl_factor",
    },
    "clutch.ball_setting": {
        "required_wire_shear_stress",
        "required_wire_spring_index",
        "spring_index",
        "spring_rate",
        "spring_shear_stress",
        "start_torque",
        "suggested_disc_setting",
        "suggested_wire_diameter",
        "suggested_wire_setting",
    },
    "impact.rare": {
        "half_coupling_release_speed",
        "max_striker_travel",
    },
    "joint.vdi2230": {
        "additional_bolt_load",
        "bolt_compliance_engaged",
        "bolt_compliance_free_thread",
        "bolt_compliance_head",
        "bolt_compliance_shank",
        "bolt_elongation",
        "clamp_load_reduction",
        "cone_limit_diameter",
        "cone_tangent",
        "embedding_loss",
        "endurance_limit",
        "fatigue_safety",
        "load_factor",
        "load_factor_k",
        "max_working_load",
        "outer_diameter_used",
        "preload_stress_ratio",
        "residual_clamp_force_min",
        "rigid_joint_angle",
        "separation_load",
        "slip_safety",
        "stress_amplitude",
        "target_angle",
        "thermal_loss",
        "transverse_clamp_force",
        "working_stress",
        "yield_preload",
        "yield_safety",
    },
    "nutrunner.drive": {
        "drive_gear_energy",
        "motor_pulley_energy",
        "shaft_shear_stress",
    },
    "preload.control": {
        "bearing_area",
        "bolt_breaking_force",
        "drive_torque_limit",
        "equivalent_shank_diameter",
        "limiting_surface_pressure",
        "min_engagement_length",
        "preload_factor",
        "scatter_torque_applied",
        "stripping_force",
        "surface_pressure_head",
        "surface_pressure_head_working",
        "surface_pressure_nut",
        "target_force",
        "target_torque",
    },
    "preload.tightening": {
        "bearing_area",
        "bolt_breaking_force",
        "equivalent_stress",
        "minor_diameter",
        "rule_of_thumb_deviation",
        "rule_of_thumb_torque",
        "stripping_force",
        "yield_rule_deviation",
        "yield_rule_torque",
    },
}

_COMPARE_OPS = (ast.Eq, ast.Lt, ast.LtE, ast.Gt, ast.GtE)
#: Calls that compare their first two arguments.
_CLOSE = {"isclose", "allclose", "approx"}
_ASSERT_CLOSE = {
    "assert_allclose",
    "assert_almost_equal",
    "assert_array_almost_equal",
    "assert_approx_equal",
    "assert_array_less",
    "assert_array_equal",
    "assert_equal",
}
#: Calls whose argument is not a value (a length, a type, a text).
_NOT_A_VALUE = {"len", "isinstance", "type", "str", "repr", "bool", "sorted", "set", "list", "id"}
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def numeric_outputs() -> dict[str, set[str]]:
    """Each registered model's scalar numeric outputs (float or int, not series)."""
    return {
        s.name: {o.name for o in s.outputs if o.kind in ("float", "int") and not o.series}
        for s in engine.MODELS
    }


def _declarations() -> dict[str, str]:
    """Names under which ``engine.models`` modules export a model (``VDI2230``) → model."""
    names: dict[str, str] = {}
    for info in pkgutil.iter_modules(engine.models.__path__):
        module = importlib.import_module(f"engine.models.{info.name}")
        for attr, value in vars(module).items():
            if isinstance(value, ModelSpec):
                names[attr] = value.name
    return names


DECLARATIONS = _declarations()
_PATHS = {s.name: re.compile(re.escape(s.path) + r"(?![\w])") for s in engine.MODELS}


def _mentions(node: ast.AST, aliases: dict[str, set[str]]) -> set[str]:
    """The models a piece of code names."""
    found: set[str] = set()
    for n in ast.walk(node):
        if isinstance(n, ast.Constant) and isinstance(n.value, str):
            for s in engine.MODELS:
                if s.name in n.value or _PATHS[s.name].search(n.value):
                    found.add(s.name)
        elif isinstance(n, ast.Name | ast.alias):
            ident = n.id if isinstance(n, ast.Name) else (n.asname or n.name)
            if ident in DECLARATIONS:
                found.add(DECLARATIONS[ident])
            found |= aliases.get(ident, set())
    return found


def _value_nodes(node: ast.AST) -> Iterator[ast.AST]:
    """Walk ``node`` but not into calls that turn a value into a non-value (``len(x)``)."""
    yield node
    if isinstance(node, ast.Call):
        f = node.func
        name = f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""
        if name in _NOT_A_VALUE:
            return
    for child in ast.iter_child_nodes(node):
        yield from _value_nodes(child)


def _keys(node: ast.AST) -> set[str]:
    """Output names read by literal from an expression: ``x["name"]``, ``x.get("name")``."""
    keys: set[str] = set()
    for n in _value_nodes(node):
        if (
            isinstance(n, ast.Subscript)
            and isinstance(n.slice, ast.Constant)
            and isinstance(n.slice.value, str)
        ):
            keys.add(n.slice.value)
        elif (
            isinstance(n, ast.Call)
            and isinstance(n.func, ast.Attribute)
            and n.func.attr == "get"
            and n.args
            and isinstance(n.args[0], ast.Constant)
            and isinstance(n.args[0].value, str)
        ):
            keys.add(n.args[0].value)
    return keys


def _is_value(node: ast.AST) -> bool:
    """Whether a compared operand can hold a number (not None, a bool, a text, or a bare 0)."""
    if isinstance(node, ast.Constant):
        return not isinstance(node.value, str | bool | type(None)) and node.value != 0
    return not isinstance(node, ast.JoinedStr)


def _compared(operands: list[ast.expr]) -> set[str]:
    """Keys read in one operand while another operand is a value."""
    keys: set[str] = set()
    for i, op in enumerate(operands):
        if any(_is_value(o) for j, o in enumerate(operands) if j != i):
            keys |= _keys(op)
    return keys


def _call_name(call: ast.Call) -> str:
    f = call.func
    return f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""


def _asserted(node: ast.AST) -> set[str]:
    """Keys compared with a value anywhere in ``node`` (a test function or a doctest line)."""
    keys: set[str] = set()
    asserted: list[ast.AST] = [n.test for n in ast.walk(node) if isinstance(n, ast.Assert)]
    for test in asserted:
        for n in ast.walk(test):
            if isinstance(n, ast.Compare) and all(isinstance(o, _COMPARE_OPS) for o in n.ops):
                keys |= _compared([n.left, *n.comparators])
            elif isinstance(n, ast.Call) and _call_name(n) in _CLOSE and len(n.args) >= 2:
                keys |= _compared(list(n.args[:2]))
    for n in ast.walk(node):
        if isinstance(n, ast.Call) and _call_name(n) in _ASSERT_CLOSE and len(n.args) >= 2:
            keys |= _compared(list(n.args[:2]))
    return keys


def _pins(node: ast.AST) -> set[tuple[str, str]]:
    """``pin("model", "output", ...)`` calls."""
    out = set()
    for n in ast.walk(node):
        if isinstance(n, ast.Call) and _call_name(n) == "pin" and len(n.args) >= 4:
            model, output = n.args[:2]
            if isinstance(model, ast.Constant) and isinstance(output, ast.Constant):
                out.add((str(model.value), str(output.value)))
    return out


def _units(tree: ast.Module) -> Iterator[ast.FunctionDef | ast.AsyncFunctionDef]:
    """Test functions and helpers: top-level defs and the methods of top-level classes."""
    for stmt in tree.body:
        if isinstance(stmt, ast.FunctionDef | ast.AsyncFunctionDef):
            yield stmt
        elif isinstance(stmt, ast.ClassDef):
            yield from (s for s in stmt.body if isinstance(s, ast.FunctionDef))


def _aliases(tree: ast.Module) -> dict[str, set[str]]:
    """Module-level names bound to something that names a model (``J = get_model("…")``)."""
    aliases: dict[str, set[str]] = {}
    for stmt in tree.body:
        if isinstance(stmt, ast.Assign | ast.AnnAssign) and stmt.value is not None:
            models = _mentions(stmt.value, aliases)
            targets = stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]
            for t in targets:
                if isinstance(t, ast.Name) and models:
                    aliases[t.id] = models
    return aliases


def _credit(
    keys: Iterable[str], models: set[str], outputs: dict[str, set[str]]
) -> set[tuple[str, str]]:
    return {(m, k) for m in models for k in keys if k in outputs.get(m, set())}


def _quoted(outputs: dict[str, set[str]]) -> re.Pattern[str]:
    """Any output name as a string literal: a file or function without one holds none."""
    names = sorted({n for v in outputs.values() for n in v}, key=len, reverse=True)
    return re.compile("[\"'](?:" + "|".join(map(re.escape, names)) + ")[\"']")


def pinned_in_tests(outputs: dict[str, set[str]]) -> set[tuple[str, str]]:
    """(model, output) pairs a test under ``tests/`` compares with a value."""
    held: set[tuple[str, str]] = set()
    quoted = _quoted(outputs)
    for path in sorted((ROOT / "tests").rglob("*.py")):
        if path.name in ("test_every_output_pinned.py", "pins.py"):
            continue
        text = path.read_text(encoding="utf-8")
        if not quoted.search(text):
            continue
        lines = text.splitlines()
        tree = ast.parse(text)
        aliases = _aliases(tree)
        whole: set[str] | None = None
        for unit in _units(tree):
            source = "\n".join(lines[unit.lineno - 1 : unit.end_lineno])
            if not quoted.search(source):
                continue
            held |= _pins(unit)
            keys = _asserted(unit)
            if keys:
                models = _mentions(unit, aliases)
                if not models:
                    whole = _mentions(tree, aliases) if whole is None else whole
                held |= _credit(keys, models or whole or set(), outputs)
    return held


def pinned_in_doctests(outputs: dict[str, set[str]]) -> set[tuple[str, str]]:
    """(model, output) pairs a doctest in ``engine/`` prints as a number or asserts."""
    held: set[tuple[str, str]] = set()
    parser = doctest.DocTestParser()
    quoted = _quoted(outputs)
    for path in sorted((ROOT / "engine").rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if ">>>" not in text or not quoted.search(text):
            continue
        tree = ast.parse(text)
        whole: set[str] | None = None
        for node in ast.walk(tree):
            if not isinstance(
                node, ast.Module | ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef
            ):
                continue
            doc = ast.get_docstring(node)
            if not doc or ">>>" not in doc or not quoted.search(doc):
                continue
            examples = parser.get_examples(doc)
            try:
                models = _mentions(ast.parse("\n".join(e.source for e in examples)), {})
            except SyntaxError:
                continue
            if not models:
                whole = _mentions(tree, {}) if whole is None else whole
                models = whole
            for ex in examples:
                try:
                    line = ast.parse(ex.source)
                except SyntaxError:
                    continue
                keys = _asserted(line)
                if _NUMBER.search(ex.want) and len(line.body) == 1:
                    keys |= _keys(line.body[0])
                if ex.want.strip() == "True" and len(line.body) == 1:
                    keys |= _asserted(ast.Module([ast.Assert(line.body[0].value)], []))  # type: ignore[attr-defined]
                held |= _credit(keys, models, outputs)
    return held


def not_pinned() -> dict[str, set[str]]:
    outputs = numeric_outputs()
    held = pinned_in_tests(outputs) | pinned_in_doctests(outputs)
    left = {m: {o for o in names if (m, o) not in held} for m, names in outputs.items()}
    return {m: names for m, names in left.items() if names}


def test_the_scan_sees_the_assertions_it_should() -> None:
    """The scan's own rules, on snippets: each kind of pin counts, each non-value does not."""
    outputs = {"joint.vdi2230": {"grip", "preload", "load_factor"}}

    def scan(src: str) -> set[str]:
        tree = ast.parse(src)
        unit = tree.body[-1]
        held = _pins(unit) | _credit(_asserted(unit), _mentions(tree, _aliases(tree)), outputs)
        return {o for _, o in held}

    m = 'J = get_model("joint.vdi2230")\n'
    assert scan(m + 'def t():\n    assert r.results["grip"] == pytest.approx(0.03)') == {"grip"}
    assert scan(m + 'def t():\n    assert abs(r["grip"] - 0.03) < 1e-9') == {"grip"}
    assert scan(m + 'def t():\n    assert 0.5 < v.get("load_factor") <= 0.7') == {"load_factor"}
    assert scan(m + 'def t():\n    np.testing.assert_allclose(c.values["grip"][0], 3e-2)') == {
        "grip"
    }
    assert scan(m + 'def t():\n    assert math.isclose(out["preload"], f)') == {"preload"}
    assert scan('def t():\n    pin("joint.vdi2230", "grip", a, 0.03)') == {"grip"}
    # not values: None, text, a sign, a length, a type, a bare truth test, another model
    for body in (
        'assert r["grip"] is not None',
        'assert r["grip"] == None',
        'assert r["grip"] > 0',
        'assert len(r["grip"]) == 3',
        'assert isinstance(r["grip"], float)',
        'assert math.isfinite(r["grip"])',
        'assert r["grip"]',
        'x = r["grip"] == 0.03',
    ):
        assert scan(m + "def t():\n    " + body) == set(), body
    assert scan('def t():\n    assert r["grip"] == 0.03') == set()  # names no model
    assert scan('def t():\n    assert run(VDI2230, x)["grip"] == 0.03') == {"grip"}
    assert scan('def t():\n    assert post("/joint/vdi2230/run")["grip"] == 0.03') == {"grip"}
    assert scan('def t():\n    assert post("/joint/vdi2230x")["grip"] == 0.03') == set()


def test_every_numeric_output_is_held_by_a_value_test() -> None:
    left = not_pinned()
    total = sum(len(v) for v in left.values())
    print(f"\n{total} numeric outputs named in no value assertion:")
    for model in sorted(left):
        print(f"  {model} ({len(left[model])}): {', '.join(sorted(left[model]))}")
    new = {m: sorted(v - NOT_YET_PINNED.get(m, set())) for m, v in left.items()}
    new = {m: v for m, v in new.items() if v}
    done = {m: sorted(v - left.get(m, set())) for m, v in NOT_YET_PINNED.items()}
    done = {m: v for m, v in done.items() if v}
    assert not new, f"outputs no test compares with a value (add a value test): {new}"
    assert not done, f"now held by a test: take them off NOT_YET_PINNED: {done}"
