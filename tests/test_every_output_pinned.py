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

Only the tests ``make test-fast`` runs count (:func:`_fast_units`): a test marked ``slow``,
``browser``, ``install`` or ``fuzz``, listed in ``tests/conftest.py``'s SLOW_ITEMS or in a
module the fast set ignores holds nothing here, so the inner loop holds every output too.

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
from engine.core.spec import ModelSpec

ROOT = Path(__file__).resolve().parents[1]

#: Numeric outputs that no value test holds yet, per model. Shrink it; never grow it.
NOT_YET_PINNED: dict[str, set[str]] = {}

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


def _bare(node: ast.AST) -> str:
    """An operand with ``pytest.approx(...)`` taken off, as text to compare."""
    if isinstance(node, ast.Call) and _call_name(node) == "approx" and node.args:
        node = node.args[0]
    return ast.dump(node)


def _compared(operands: list[ast.expr]) -> set[str]:
    """Keys read in one operand while another operand is a value (not the same expression)."""
    keys: set[str] = set()
    for i, op in enumerate(operands):
        others = [o for j, o in enumerate(operands) if j != i]
        if any(_is_value(o) and _bare(o) != _bare(op) for o in others):
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


def _literal_names(node: ast.AST | None, known: dict[str, set[str]]) -> set[str] | None:
    """The strings a literal collection spells out: a tuple, list or set of string literals,
    a dict's literal keys, a module-level name bound to one, or ``sorted``/``tuple``/``list``/
    ``set`` of one. None for anything else (a name computed at run time is not read)."""
    if isinstance(node, ast.Tuple | ast.List | ast.Set):
        items = node.elts
    elif isinstance(node, ast.Dict):
        items = [k for k in node.keys if k is not None]
    elif isinstance(node, ast.Name):
        return known.get(node.id)
    elif isinstance(node, ast.Call) and _call_name(node) in ("sorted", "tuple", "list", "set"):
        return _literal_names(node.args[0], known) if len(node.args) == 1 else None
    elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.args:
        return known.get(node.func.id + "()")  # a module-level function's returned keys
    else:
        return None
    if not all(isinstance(i, ast.Constant) and isinstance(i.value, str) for i in items):
        return None
    return {str(i.value) for i in items if isinstance(i, ast.Constant)}


def _returned_keys(f: ast.FunctionDef) -> set[str] | None:
    """The keys of the dict ``f`` returns, where its text spells each one out."""
    last = f.body[-1] if f.body else None
    if not isinstance(last, ast.Return) or last.value is None:
        return None
    if isinstance(last.value, ast.Dict):
        return _literal_names(last.value, {})
    if not isinstance(last.value, ast.Name):
        return None
    name, keys = last.value.id, None
    for n in ast.walk(f):
        if isinstance(n, ast.AnnAssign | ast.AugAssign) and isinstance(n.value, ast.Dict):
            if isinstance(n.target, ast.Name) and n.target.id == name:  # out: … = {…}; out |= {…}
                keys = (keys or set()) | (_literal_names(n.value, {}) or set())
        elif isinstance(n, ast.Assign) and len(n.targets) == 1:
            t = n.targets[0]
            if isinstance(t, ast.Name) and t.id == name and isinstance(n.value, ast.Dict):
                keys = (keys or set()) | (_literal_names(n.value, {}) or set())
            elif (
                isinstance(t, ast.Subscript)
                and isinstance(t.value, ast.Name)
                and t.value.id == name
                and isinstance(t.slice, ast.Constant)
                and isinstance(t.slice.value, str)
            ):
                keys = (keys or set()) | {t.slice.value}
    return keys


def _module_literals(tree: ast.Module) -> dict[str, set[str]]:
    """Module-level names bound to a literal collection of strings (``NAMES = ("a", "b")``)."""
    known: dict[str, set[str]] = {}
    # a module-level function that returns a dict literal, or a dict it builds from one by
    # literal keys (out = {...}; out["k"] = ...; return out): its call's keys
    returns = {f.name: _returned_keys(f) for f in tree.body if isinstance(f, ast.FunctionDef)}
    returns = {name: keys for name, keys in returns.items() if keys}
    known.update({name + "()": keys for name, keys in returns.items() if keys is not None})
    for stmt in tree.body:
        if isinstance(stmt, ast.Assign | ast.AnnAssign) and stmt.value is not None:
            value = stmt.value
            if isinstance(value, ast.Call) and not value.args and _call_name(value) in returns:
                names = returns[_call_name(value)]
            else:
                names = _literal_names(value, known)
            targets = stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]
            for t in targets:
                if isinstance(t, ast.Name) and names is not None:
                    known[t.id] = names
    return known


def _bound_names(node: ast.AST, known: dict[str, set[str]]) -> dict[str, set[str]]:
    """Names a test binds to each of a literal list of strings: its ``parametrize`` arguments
    and the targets of its ``for`` loops over such a list."""
    bound: dict[str, set[str]] = {}
    for d in getattr(node, "decorator_list", []):
        if isinstance(d, ast.Call) and _call_name(d) == "parametrize" and len(d.args) >= 2:
            arg = d.args[0]
            names = _literal_names(d.args[1], known)
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str) and names:
                bound[arg.value] = names
    local = dict(known)  # plus the function's own names bound to a literal collection
    for n in ast.walk(node):
        if isinstance(n, ast.Assign) and len(n.targets) == 1 and isinstance(n.targets[0], ast.Name):
            names = _literal_names(n.value, local)
            if names is not None:
                local[n.targets[0].id] = names
    for n in ast.walk(node):
        if not isinstance(n, ast.For):
            continue
        target = n.target.elts[0] if isinstance(n.target, ast.Tuple) else n.target
        over = n.iter
        if (  # for name, value in WANT.items() / for name in WANT.keys()
            isinstance(over, ast.Call)
            and isinstance(over.func, ast.Attribute)
            and over.func.attr in ("items", "keys")
            and not over.args
        ):
            over = over.func.value
        elif isinstance(n.target, ast.Tuple):
            continue
        names = _literal_names(over, local)
        if names and isinstance(target, ast.Name):
            bound[target.id] = names
    return bound


def _pins(node: ast.AST, known: dict[str, set[str]] | None = None) -> set[tuple[str, str]]:
    """``pin("model", "output", ...)`` calls; the output may be a name bound to each of a
    literal list of output names (a ``parametrize`` argument or a ``for`` loop's target)."""
    bound = _bound_names(node, known or {})
    out = set()
    for n in ast.walk(node):
        if isinstance(n, ast.Call) and _call_name(n) == "pin" and len(n.args) >= 4:
            model, output = n.args[:2]
            if not isinstance(model, ast.Constant):
                continue
            if isinstance(output, ast.Constant):
                out.add((str(model.value), str(output.value)))
            elif isinstance(output, ast.Name) and output.id in bound:
                out |= {(str(model.value), name) for name in bound[output.id]}
    return out


def _units(tree: ast.Module) -> Iterator[ast.FunctionDef | ast.AsyncFunctionDef]:
    """Test functions and helpers: top-level defs and the methods of top-level classes."""
    for stmt in tree.body:
        if isinstance(stmt, ast.FunctionDef | ast.AsyncFunctionDef):
            yield stmt
        elif isinstance(stmt, ast.ClassDef):
            yield from (s for s in stmt.body if isinstance(s, ast.FunctionDef))


#: The marks ``make test-fast`` deselects (the Makefile's FAST), and the module it does not
#: collect: a value held only there is not held by the inner loop.
OUT_OF_FAST_MARKS = ("slow", "browser", "install", "fuzz")
OUT_OF_FAST_FILES = ("tests/service/test_fuzz.py",)


def _out_of_fast(node: ast.AST | None) -> bool:
    """Whether a decorator or a ``pytestmark`` value carries a mark the fast set deselects."""
    if node is None:
        return False
    return any(
        isinstance(n, ast.Attribute)
        and n.attr in OUT_OF_FAST_MARKS
        and isinstance(n.value, ast.Attribute)
        and n.value.attr == "mark"
        for n in ast.walk(node)
    )


def _fast_units(tree: ast.Module, where: str) -> Iterator[ast.FunctionDef | ast.AsyncFunctionDef]:
    """:func:`_units` less the tests ``make test-fast`` leaves out: marked (by decorator or the
    module's ``pytestmark``), listed in ``tests/conftest.py``'s SLOW_ITEMS, or in a module it
    ignores. ``where`` is the file's path from the repository root."""
    from tests.conftest import SLOW_ITEMS

    if where in OUT_OF_FAST_FILES or any(
        isinstance(s, ast.Assign)
        and any(isinstance(t, ast.Name) and t.id == "pytestmark" for t in s.targets)
        and _out_of_fast(s.value)
        for s in tree.body
    ):
        return
    for unit in _units(tree):
        if unit.name.startswith("test") and (
            any(_out_of_fast(d) for d in unit.decorator_list)
            or f"{where}::{unit.name}".startswith(SLOW_ITEMS)
        ):
            continue
        yield unit


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
    """(model, output) pairs a test under ``tests/`` compares with a value, counting only
    the tests ``make test-fast`` runs (:func:`_fast_units`): the inner loop holds them all."""
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
        known = _module_literals(tree)
        whole: set[str] | None = None
        for unit in _fast_units(tree, path.relative_to(ROOT).as_posix()):
            source = "\n".join(lines[unit.lineno - 1 : unit.end_lineno])
            if "pin(" in source:
                held |= _pins(unit, known)
            if not quoted.search(source):
                continue
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
        held = _pins(unit, _module_literals(tree))
        held |= _credit(_asserted(unit), _mentions(tree, _aliases(tree)), outputs)
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
    # a pin over a literal list of names: parametrized, or a loop, or a module-level tuple
    names = 'NAMES = ("grip", "preload")\n'
    deco = '@pytest.mark.parametrize("n", NAMES)\n'
    pinned = {"grip", "preload"}
    assert scan(names + deco + 'def t(n):\n    pin("joint.vdi2230", n, a[n], b[n])') == pinned
    assert (
        scan(
            names
            + 'def t():\n    for n in sorted(NAMES):\n        pin("joint.vdi2230", n, a[n], b[n])'
        )
        == pinned
    )
    assert scan(
        'def t():\n    for n in {"grip": 1}:\n        pin("joint.vdi2230", n, a[n], 1)'
    ) == {"grip"}
    made = 'def hand():\n    x = 1\n    return {"grip": x, "preload": 2 * x}\nHAND = hand()\n'
    assert (
        scan(
            made
            + deco.replace("NAMES", "sorted(HAND)")
            + 'def t(n):\n    pin("joint.vdi2230", n, a[n], HAND[n])'
        )
        == pinned
    )
    built = (
        'def hand():\n    out = {"grip": 1}\n    out["preload"] = 2\n    return out\nH = hand()\n'
    )
    assert (
        scan(built + 'def t():\n    for n in H:\n        pin("joint.vdi2230", n, a[n], H[n])')
        == pinned
    )
    loop = 'def t():\n    want = {"grip": 1.0, "preload": 2.0}\n    for n, v in want.items():\n'
    assert scan(loop + '        pin("joint.vdi2230", n, a[n], v)') == pinned
    # a name computed at run time is not read
    assert (
        scan('def t():\n    for n in make():\n        pin("joint.vdi2230", n, a[n], b[n])') == set()
    )
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
        'assert r["grip"] == pytest.approx(r["grip"])',
    ):
        assert scan(m + "def t():\n    " + body) == set(), body
    assert scan('def t():\n    assert r["grip"] == 0.03') == set()  # names no model
    assert scan('def t():\n    assert run(VDI2230, x)["grip"] == 0.03') == {"grip"}
    assert scan('def t():\n    assert post("/joint/vdi2230/run")["grip"] == 0.03') == {"grip"}
    assert scan('def t():\n    assert post("/joint/vdi2230x")["grip"] == 0.03') == set()
    # only what the fast set runs: a test marked slow (or in SLOW_ITEMS) holds nothing there
    fast = 'def test_a():\n    pin("joint.vdi2230", "grip", a, 0.03)\n'
    slow = '@pytest.mark.slow\ndef test_b():\n    pin("joint.vdi2230", "preload", a, 1.0)\n'
    tree = ast.parse(fast + slow)
    assert [u.name for u in _fast_units(tree, "tests/x.py")] == ["test_a"]
    marked = ast.parse("pytestmark = pytest.mark.browser\n" + fast)
    assert list(_fast_units(marked, "tests/x.py")) == []
    listed = "tests/service/test_shopfloor_csv.py"
    tree = ast.parse(fast.replace("test_a", "test_a_row_group_is_not_held_as_text"))
    assert list(_fast_units(tree, listed)) == []


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
