"""Model spec for the evaluation of a torque/clamp-force test series (``friction.iso16047``).

The relations live in :mod:`engine.physics.iso16047` and the series statistics in
:mod:`engine.physics.capability`; the thread and bearing geometry come from a designation
through :func:`engine.procedures.bolt.resolve` (or from the numbers given). This module
reads the three measured series, checks that they belong together, and states per
coefficient the mean, standard deviation, minimum and maximum.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..core.errors import InputOutOfRange
from ..core.params import length, quantity, samples
from ..core.spec import (
    Answer,
    Check,
    ModelSpec,
    Output,
    Param,
    Result,
    RunContext,
    Rung,
    fixed_error,
)
from ..core.text import q
from ..physics import capability as cap
from ..physics import iso16047 as iso
from ..physics import threads as th
from ..procedures import bolt as fz

SOURCE = (
    "ISO 16047 (torque/clamp force testing), its relations in the form of VDI 2230-1 R13; "
    "thread and head geometry: ISO 68-1, ISO 261, ISO 273, ISO 4017"
)

#: Largest torque and force a test series may hold, [N*m] and [N].
MAX_TORQUE = 1e5
MAX_FORCE = 1e7

#: The four coefficients: (output stem, what it is).
COEFFICIENTS: tuple[tuple[str, str], ...] = (
    ("torque_coefficient", "torque coefficient K = T/(F d)"),
    ("thread_friction", "thread friction μ_th"),
    ("bearing_friction", "bearing friction μ_b"),
    ("total_friction", "total friction μ_tot"),
)
_STATISTICS: tuple[tuple[str, str], ...] = (
    ("mean", "mean"),
    ("sd", "standard deviation (n − 1)"),
    ("min", "smallest"),
    ("max", "largest"),
)

INPUTS: tuple[Param, ...] = (
    samples(
        "tightening_torques",
        "N*m",
        "Tightening torque T of each test, at the clamp force evaluated (one value per test)",
        minimum=0.0,
        maximum=MAX_TORQUE,
        exclusive_minimum=True,
        required=True,
        symbol="T",
        group="measurements",
    ),
    samples(
        "thread_torques",
        "N*m",
        "Thread torque T_th of each test, in the same order",
        minimum=0.0,
        maximum=MAX_TORQUE,
        required=True,
        symbol="T_th",
        group="measurements",
    ),
    samples(
        "clamp_forces",
        "N",
        "Clamp force F of each test, in the same order",
        minimum=0.0,
        maximum=MAX_FORCE,
        exclusive_minimum=True,
        required=True,
        display_unit="kN",
        symbol="F",
        group="measurements",
    ),
    *(
        p
        for p in fz.THREAD_INPUTS
        if p.name == "thread"  # the grade plays no part in friction
    ),
    length(
        "thread_diameter",
        "Nominal thread diameter d, when no thread designation is given",
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        symbol="d",
        group="bolt",
    ),
    length(
        "thread_pitch",
        "Thread pitch P with thread_diameter; ISO 261 coarse pitch when absent",
        minimum=0.0,
        maximum=0.1,
        exclusive_minimum=True,
        symbol="P",
        group="bolt",
    ),
    length(
        "pitch_diameter",
        "Pitch diameter d2 (ISO 68-1 from d and P, or the designation's, when absent)",
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        symbol="d2",
        group="bolt",
    ),
    length(
        "bearing_outer_diameter",
        "Outside diameter d_o of the bearing contact (a designation's hexagon head d_w,min, "
        "ISO 4017, when absent)",
        minimum=0.0,
        maximum=2.0,
        exclusive_minimum=True,
        symbol="d_o",
        group="bearing",
    ),
    length(
        "hole_diameter",
        "Inside diameter d_i of the bearing contact: the hole of the test washer (a "
        "designation's ISO 273 medium clearance hole when absent)",
        minimum=0.0,
        maximum=2.0,
        exclusive_minimum=True,
        symbol="d_i",
        group="bearing",
    ),
    length(
        "bearing_diameter",
        "Mean bearing diameter D_b = (d_o + d_i)/2 given directly (overrides the two above)",
        minimum=0.0,
        maximum=2.0,
        exclusive_minimum=True,
        symbol="D_b",
        group="bearing",
    ),
)

OUTPUTS: tuple[Output, ...] = (
    Output(
        "test_count",
        "1",
        "Number of tests n in the series",
        kind="int",
        symbol="n",
        step="ISO 16047",
    ),
    Output(
        "thread_diameter",
        "m",
        "Nominal thread diameter d",
        display_unit="mm",
        symbol="d",
        step="ISO 16047",
    ),
    Output("thread_pitch", "m", "Thread pitch P", display_unit="mm", symbol="P", step="ISO 16047"),
    Output(
        "pitch_diameter", "m", "Pitch diameter d2", display_unit="mm", symbol="d_2", step="ISO 68-1"
    ),
    Output(
        "bearing_diameter",
        "m",
        "Mean bearing diameter D_b",
        display_unit="mm",
        symbol="D_b",
        step="ISO 16047",
    ),
    *(
        Output(
            f"{stem}_{stat}",
            "1",
            f"{what.capitalize()} of the {text} over the series",
            symbol=dict(
                torque_coefficient="K_",
                thread_friction="μ_th,",
                bearing_friction="μ_b,",
                total_friction="μ_tot,",
            )[stem]
            + stat,
            step="ISO 16047",
        )
        for stem, text in COEFFICIENTS
        for stat, what in _STATISTICS
    ),
    Output("test_number", "1", "Test number 1…n", series=True),
    *(
        Output(stem, "1", f"{text.capitalize()} of each test", series=True, x="test_number")
        for stem, text in COEFFICIENTS
    ),
)


def _series(x: Mapping[str, Any]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(T, T_th, F) as arrays of one length, or InputOutOfRange naming the odd one."""
    t, t_th, f = (
        np.asarray(x[n], dtype=float)
        for n in ("tightening_torques", "thread_torques", "clamp_forces")
    )
    n = len(t)
    for name, arr in (("thread_torques", t_th), ("clamp_forces", f)):
        if len(arr) != n:
            raise InputOutOfRange(
                f"{name} has {len(arr)} values where tightening_torques has {n}: give one "
                "value per test, in the same order",
                field=name,
            )
    above = np.flatnonzero(t_th > t)
    if above.size:
        i = int(above[0])
        raise InputOutOfRange(
            f"thread_torques[{i}] = {t_th[i]:g} N*m is not allowed: must not exceed the "
            f"tightening torque of the same test ({t[i]:g} N*m); the thread torque is part of it",
            field="thread_torques",
            index=i,
        )
    return t, t_th, f


def _geometry(x: Mapping[str, Any]) -> tuple[float, float, float, float, list[str]]:
    """(d, P, d2, D_b, notes) from the designation or the numbers given."""
    # resolve() asks an inch thread for a grade; friction does not depend on it
    fields, fastener, notes = fz.resolve({**x, "yield_strength": 1.0})
    thread = fastener.thread
    if "bearing_friction_factor" in fields:  # a countersunk head: the preload models' note
        notes = [n for n in notes if not n.startswith("countersunk head")]
        notes.append(
            "countersunk head: μ_b is evaluated as on a flat face at D_b/2 (ISO 16047's "
            f"relation); the friction on the 90° cone is μ_b × sin 45° = μ_b × "
            f"{1.0 / fields['bearing_friction_factor']:.3f}"
        )
    d = float(fields["diameter"])
    pitch = x.get("thread_pitch") or fields.get("pitch") or (thread.pitch if thread else None)
    if pitch is None:
        raise InputOutOfRange(
            f"thread_pitch is required: d = {quantity(d, 'mm')} has no ISO 261 coarse pitch",
            field="thread_pitch",
        )
    d2 = x.get("pitch_diameter")
    if d2 is None:
        d2 = fields.get("pitch_diameter") or (thread.pitch_diameter if thread else None)
    if d2 is None:
        d2 = th.pitch_diameter(d, float(pitch))
        notes.append(f"pitch diameter d2 = d − 0.649519 P = {q(d2, 'mm', fmt='.5g')} (ISO 68-1)")
    if not 0.0 < d2 < d:
        raise InputOutOfRange(
            f"pitch_diameter = {quantity(d2, 'mm')} is not allowed: must lie between 0 and the "
            f"thread diameter {quantity(d, 'mm')}",
            field="pitch_diameter",
        )
    if x.get("bearing_diameter") is not None:
        return d, float(pitch), float(d2), float(x["bearing_diameter"]), notes
    outer = x.get("bearing_outer_diameter") or fields.get("bearing_outer_diameter")
    inner = x.get("hole_diameter") or fields.get("hole_diameter")
    if outer is None or inner is None:
        raise InputOutOfRange(
            "give bearing_diameter, or bearing_outer_diameter and hole_diameter (a thread "
            "designation gives both)",
            field="bearing_diameter",
        )
    if not inner < outer:
        raise InputOutOfRange(
            f"hole_diameter = {quantity(inner, 'mm')} is not allowed: must be below the bearing "
            f"face's outside diameter {quantity(outer, 'mm')}",
            field="hole_diameter",
        )
    d_b = float(iso.mean_bearing_diameter(outer, inner))
    notes.append(
        f"D_b = (d_o + d_i)/2 = ({q(outer, 'mm', fmt='.4g')} + {q(inner, 'mm', fmt='.4g')})/2"
        f" = {q(d_b, 'mm', fmt='.4g')}"
    )
    return d, float(pitch), float(d2), d_b, notes


def _iso16047(x: Mapping[str, Any], ctx: RunContext) -> Result:
    t, t_th, f = _series(x)
    d, pitch, d2, d_b, notes = _geometry(x)
    per_test = {
        "torque_coefficient": iso.torque_coefficient(t, f, d),
        "thread_friction": iso.thread_friction_from_test(t_th, f, pitch, d2),
        "bearing_friction": iso.bearing_friction_from_test(t, t_th, f, d_b),
        "total_friction": iso.total_friction_from_test(t, f, pitch, d2, d_b),
    }
    values: dict[str, Any] = {
        "test_count": len(t),
        "thread_diameter": d,
        "thread_pitch": pitch,
        "pitch_diameter": d2,
        "bearing_diameter": d_b,
    }
    for stem, arr in per_test.items():
        values[f"{stem}_mean"] = cap.sample_mean(arr)
        values[f"{stem}_sd"] = cap.sample_standard_deviation(arr)
        values[f"{stem}_min"] = float(np.min(arr))
        values[f"{stem}_max"] = float(np.max(arr))
    negative = [text for stem, text in COEFFICIENTS[1:] if float(np.min(per_test[stem])) <= 0.0]
    checks = [
        Check(
            "positive_friction",
            not negative,
            "every test gives positive friction coefficients"
            if not negative
            else f"the {' and '.join(negative)} come out ≤ 0 in some tests: the thread torque is "
            "below the pitch's share F P/(2π), or equals the tightening torque; check the "
            "measurement channels and their zero",
        )
    ]
    notes.append(
        "μ by ISO 16047's linear relations with 1/(2π) and 1/(2 cos 30°) unrounded; the bearing "
        "friction acts at D_b/2"
    )
    series: dict[str, list[float]] = {}
    if ctx.wants("test_number", *per_test):
        series["test_number"] = [float(i + 1) for i in range(len(t))]
        series.update({stem: [float(v) for v in arr] for stem, arr in per_test.items()})
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        series=series,
    )


CLOSED_FORM = Rung(
    "closed_form",
    "ISO 16047's relations evaluated per test, then the series statistics; exact arithmetic "
    "of the standard's definitions (they linearise the helix: against the exact thread "
    "relation μ_th reads about 1 % high at μ = 0.12)",
    fixed_error(0.0),
    typical_error="exact arithmetic of the standard's definitions",
    typical_time="< 1 ms",
)

ISO16047 = ModelSpec(
    name="friction.iso16047",
    answer=(
        Answer("thread_friction_mean", "μ_th,mean"),
        Answer("bearing_friction_mean", "μ_b,mean"),
        Answer("total_friction_mean", "μ_tot,mean"),
        Answer("torque_coefficient_mean", "K_mean"),
    ),
    title="Friction from a torque/clamp-force test series (ISO 16047)",
    family="friction",
    summary=(
        "From the tightening torque, thread torque and clamp force of each test in a series "
        "and the thread (a designation, or d, P and the bearing diameters): the torque "
        "coefficient K and the thread, bearing and total friction coefficients of each test, "
        "with their mean, standard deviation, minimum and maximum."
    ),
    source=SOURCE,
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_iso16047,
    examples=(
        # five tests of an M10 hexagon-head bolt, evaluated at about 20 kN
        {
            "thread": "M10",
            "tightening_torques": (40.0, 42.5, 39.0, 41.2, 40.3),
            "thread_torques": (17.3, 18.4, 16.9, 17.9, 17.6),
            "clamp_forces": (20e3, 21e3, 19.5e3, 20.5e3, 20e3),
        },
        {
            "thread_diameter": 0.012,
            "tightening_torques": (80.0, 78.0, 83.0),
            "thread_torques": (36.0, 35.5, 37.0),
            "clamp_forces": (35e3, 34e3, 36e3),
            "bearing_diameter": 0.0155,
        },
    ),
)
