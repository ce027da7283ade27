"""Physics docstrings agree with their signatures and with the model declarations.

Every public function of a physics module documents each parameter of its
signature (numpydoc ``Parameters``), each with a ``[unit]``; where a parameter
has the name of an input of the family's models, the two units agree. Units
thus live in the ``Param`` declarations and are checked against the docstrings,
not kept as a second copy that can drift.
"""

from __future__ import annotations

import importlib
import inspect
import re
from collections.abc import Callable, Iterator
from typing import Any

import pytest

import engine

#: Physics module (engine.physics, or the striker cycle in engine.procedures) -> the models
#: whose inputs share its parameter names.
FAMILIES: dict[str, tuple[str, ...]] = {
    "blow": ("blow.joint",),
    "clutch": ("clutch.ball", "clutch.ball_setting"),
    "fasteners": ("preload.tightening", "preload.control"),
    "joint": ("joint.vdi2230",),
    "motor_spinup": ("nutrunner.drive",),
    "nutrunner": ("nutrunner.drive",),
    "preload": ("preload.tightening", "preload.control"),
    "preload_methods": ("preload.tightening", "preload.control"),
    "rare_impact": ("impact.rare",),
    "striker_cycle": ("impact.rare",),
    "springs": ("clutch.ball", "clutch.ball_setting"),
    "threads": ("preload.tightening", "preload.control"),
}

#: Not physics: look-ups by key, documented in prose.
NOT_PHYSICS = {
    "preload_methods.catalogue",
    "preload_methods.get_method",
    # the fastener catalogue's look-ups (keys in, rows out), issue 15
    *(
        f"fasteners.{n}"
        for n in (
            "all_threads",
            "catalogue",
            "clearance_hole",
            "grade_strengths",
            "head",
            "hex_key_torque",
            "material",
            "metric_thread",
            "normalise_grade",
            "nut",
            "parse_designation",
            "unified_thread",
            "washer",
        )
    ),
}
NOT_PHYSICS |= {"springs.SpringMaterial"}  # a data record, documented in prose
#: Physics functions still without a numpydoc Parameters section (their arguments
#: are the paper's symbols, explained in the module docstring). The list may only
#: shrink: a new function must document its parameters, and documenting one of
#: these fails the test until it is taken off the list.
UNDOCUMENTED = {
    "rare_impact.effective_stage1_mass",
    "rare_impact.engagement_window",
    "rare_impact.liftoff_speed",
    "rare_impact.max_striker_travel",
    "rare_impact.min_return_spring_rate",
    "rare_impact.relock_time",
    "rare_impact.return_time",
    "rare_impact.spin_up_time",
    "rare_impact.spring_force_at_release",
    "rare_impact.spring_height_limit",
    "rare_impact.striker_travel",
    "rare_impact.time_to_travel",
}
#: Annotations of numeric parameters, which need a [unit]; others (str, bool, a
#: curve object, a mapping of inputs) are described in words.
NUMERIC = {"float", "int", "Any", "FloatArray"}

_SECTION = re.compile(
    r"^(\s*)Parameters\n\1-{3,}\n(.*?)(?:\n\s*\n\1[A-Z][a-z]+\n\1-{3,}\n|\Z)", re.S | re.M
)
_BRACKET = re.compile(r"\[([^\[\]]+)\]")
#: A bracket that cites a source rather than giving a unit: [000, eq. 5], [004].
_CITATION = re.compile(r"^\d{3}\b|eq\.|fig\.|VDI|ISO")


def _functions() -> Iterator[tuple[str, str, Callable[..., Any]]]:
    for module_name in FAMILIES:
        layer = "procedures" if module_name == "striker_cycle" else "physics"
        module = importlib.import_module(f"engine.{layer}.{module_name}")
        for name, obj in vars(module).items():
            if name.startswith("_") or not inspect.isfunction(obj):
                continue
            if obj.__module__ != module.__name__ or not obj.__doc__:
                continue
            yield module_name, name, obj


FUNCTIONS = sorted(_functions(), key=lambda t: (t[0], t[1]))
CHECKED = [f for f in FUNCTIONS if f"{f[0]}.{f[1]}" not in NOT_PHYSICS | UNDOCUMENTED]


def test_the_undocumented_list_only_shrinks():
    lacking = {f"{m}.{n}" for m, n, f in FUNCTIONS if not documented(f.__doc__)}
    assert lacking - NOT_PHYSICS == UNDOCUMENTED


def documented(doc: str) -> dict[str, str | None]:
    """Parameter name -> its unit (the last ``[...]`` of its description), from numpydoc."""
    match = _SECTION.search(inspect.cleandoc(doc))
    if not match:
        return {}
    indent = match.group(1)
    out: dict[str, str | None] = {}
    current: list[str] = []
    text: list[str] = []

    def close() -> None:
        units = [u.strip() for u in _BRACKET.findall(" ".join(text))]
        units = [u for u in units if not _CITATION.search(u)]
        if len(current) > 1 and len(units) == len(current):  # "mass, diameter: ... [kg], [m]"
            out.update(zip(current, units, strict=True))
            return
        for n in current:
            out[n] = units[-1] if units else None

    for line in match.group(2).splitlines():
        if line.startswith(indent) and line.strip() and not line[len(indent) :].startswith(" "):
            close()
            names = line.split(":", 1)[0].strip()
            current = [n.strip().lstrip("*") for n in names.split(",")]
            text = []
        elif line.strip():
            text.append(line.strip())
    close()
    return out


def normal(unit: str) -> str:
    """Spelling-independent form of a unit: ``N·m`` = ``N*m``, ``[-]`` = ``1``, ``m²`` = ``m^2``."""
    u = unit.replace("·", "*").replace("²", "^2").replace("³", "^3").replace(" ", "")
    return "1" if u in {"-", "1", "dimensionless"} else u


def test_the_parser_reads_a_numpydoc_section():
    doc = """Title.

    Parameters
    ----------
    mass, other : float
        Mass of the disc, [kg]
    angle : float, optional
        Flank angle, [rad]

    Returns
    -------
    x : float
        Something, [m]
    """
    assert documented(doc) == {"mass": "kg", "other": "kg", "angle": "rad"}
    pair = documented("Parameters\n----------\nm, d : float\n    Disc [000, eq. 3], [kg], [m]\n")
    assert pair == {"m": "kg", "d": "m"}
    assert normal("N·m") == normal("N*m") and normal("-") == "1"


def test_functions_are_found():
    names = {f"{m}.{n}" for m, n, _ in FUNCTIONS}
    assert {"nutrunner.impact_torque", "clutch.spring_rate", "preload.lead_angle"} <= names


@pytest.mark.parametrize(
    ("module", "name", "func"), CHECKED, ids=lambda v: getattr(v, "__qualname__", str(v))
)
def test_docstring_names_every_parameter_with_a_unit(module, name, func):
    params = inspect.signature(func).parameters
    docs = documented(func.__doc__)
    assert docs, f"engine/{module}.py: {name} has no Parameters section"
    variadic = any(p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD) for p in params.values())
    named = [n for n, p in params.items() if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    missing = [n for n in named if n not in docs]
    assert not missing, f"engine/{module}.py: {name} does not document {missing}"
    if not variadic:
        extra = [n for n in docs if n not in params]
        assert not extra, f"engine/{module}.py: {name} documents {extra}, not in its signature"
    numeric = {
        n
        for n, p in params.items()
        if str(p.annotation).replace(" | None", "") in NUMERIC
        and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
    }
    no_unit = [n for n, u in docs.items() if u is None and n in numeric]
    assert not no_unit, f"engine/{module}.py: {name} gives no [unit] for {no_unit}"


@pytest.mark.parametrize(
    ("module", "name", "func"), CHECKED, ids=lambda v: getattr(v, "__qualname__", str(v))
)
def test_docstring_units_match_the_model_inputs_of_the_same_name(module, name, func):
    params: dict[str, str] = {}
    for model in FAMILIES[module]:
        for p in engine.get_model(model).inputs:
            if p.is_numeric:
                params.setdefault(p.name, p.unit)
    for arg, unit in documented(func.__doc__).items():
        if arg in params and unit is not None:
            assert normal(unit) == normal(params[arg]), (
                f"engine/{module}.py: {name}({arg}) says [{unit}], the model input says "
                f"[{params[arg]}]"
            )
