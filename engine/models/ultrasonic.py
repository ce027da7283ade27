"""Model spec for ultrasonic elongation ↔ preload (``preload.ultrasonic``).

The bolt and its compliance δ_S are the joint model's (``joint.vdi2230``: its inputs, its
bolt resolution and VDI 2230-1 R3's compliance), taken from a run of that model; the
pulse-echo relations are :mod:`engine.physics.ultrasonic`'s, the elongation–preload one
:mod:`engine.physics.preload`'s.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..core.errors import InputOutOfRange
from ..core.params import positive
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
from ..physics import preload as pl
from ..physics import ultrasonic as us
from ..procedures.bolt import resolve_bolt
from .joint import _BOLT_NAMES, JOINT_INPUTS, VDI2230

SOURCE = (
    "ASTM E1685 practice; the instrument makers' relations [BoltMike] and [Dakota]; the bolt's "
    "compliance δ_S of VDI 2230-1 R3 from joint.vdi2230; F = Δl/δ_S [004, eq. 7]"
)

#: The joint inputs that fix the bolt and its compliance.
_JOINT_NAMES = (
    *(name for name in _BOLT_NAMES if name != "utilization"),
    "head",
    "joint_type",
    "shank_length",
    "shank_diameter",
    "reduced_length",
    "reduced_diameter",
    "youngs_modulus",
    "nut_youngs_modulus",
    "plate1_thickness",
    "plate2_thickness",
    "plate3_thickness",
)

#: ASTM E1685's scope: effective length at least twice the diameter.
MIN_LENGTH_RATIO = 2.0

INPUTS: tuple[Param, ...] = (
    *(p for p in JOINT_INPUTS if p.name in _JOINT_NAMES),
    positive(
        "preload",
        "N",
        "Preload F to convert into elongation and time of flight (or give elongation or "
        "time_of_flight_change to get the preload)",
        maximum=1e8,
        display_unit="kN",
        symbol="F",
        group="ultrasonic",
    ),
    Param(
        "elongation",
        "m",
        "Measured mechanical elongation ΔL (as an instrument displays it, the stress factor "
        "applied), to get the preload and the time of flight",
        minimum=-0.1,
        maximum=0.1,
        display_unit="mm",
        symbol="ΔL",
        group="ultrasonic",
    ),
    Param(
        "time_of_flight_change",
        "s",
        "Measured change in the echo's round-trip time between the zero reading and the "
        "loaded reading (or give preload or elongation)",
        minimum=-1e-3,
        maximum=1e-3,
        display_unit="µs",
        symbol="Δt",
        group="ultrasonic",
    ),
    positive(
        "sound_velocity",
        "m/s",
        "Longitudinal velocity of sound V in the unloaded bolt (calibrate it on the bolt)",
        maximum=20000.0,
        symbol="V",
        group="ultrasonic",
        required=True,
    ),
    Param(
        "stress_factor",
        "1",
        "Stress factor S_F: mechanical over ultrasonic change in length, calibrated per bolt "
        "material [Dakota]",
        required=True,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        symbol="S_F",
        group="ultrasonic",
    ),
    Param(
        "temperature_factor",
        "1/K",
        "Temperature factor τ: relative change of the ultrasonic length per kelvin (thermal "
        "expansion and velocity together; [Dakota]'s T_F × 1e-6)",
        default=0.0,
        minimum=-1e-3,
        maximum=1e-3,
        symbol="τ",
        group="ultrasonic",
    ),
    Param(
        "reading_temperature_change",
        "K",
        "Bolt temperature at the loaded reading minus at the zero reading",
        default=0.0,
        minimum=-200.0,
        maximum=200.0,
        symbol="ΔT",
        group="ultrasonic",
    ),
    positive(
        "ultrasonic_length",
        "m",
        "The bolt's ultrasonic length L_U at the zero reading (for the temperature correction)",
        maximum=10.0,
        display_unit="mm",
        symbol="L_U",
        group="ultrasonic",
    ),
)

OUTPUTS: tuple[Output, ...] = (
    Output(
        "preload", "N", "Preload F = ΔL/δ_S", display_unit="kN", symbol="F_V", step="ASTM E1685"
    ),
    Output(
        "elongation",
        "m",
        "Mechanical elongation ΔL = F δ_S",
        display_unit="mm",
        symbol="ΔL",
        step="ASTM E1685",
    ),
    Output(
        "ultrasonic_length_change",
        "m",
        "Ultrasonic change in length ΔL/S_F, at the zero reading's temperature",
        display_unit="mm",
        symbol="ΔL_U",
        step="ASTM E1685",
    ),
    Output(
        "thermal_length_change",
        "m",
        "Apparent change from the temperature alone, τ L_U ΔT",
        display_unit="mm",
        symbol="ΔL_T",
        step="ASTM E1685",
    ),
    Output(
        "time_of_flight_change",
        "s",
        "Change in round-trip time the instrument reads (stress and temperature)",
        display_unit="µs",
        symbol="Δt",
        step="ASTM E1685",
    ),
    Output(
        "bolt_compliance",
        "m/N",
        "δ_S of the joint model (VDI 2230-1 R3)",
        symbol="δ_S",
        step="VDI 2230-1 R3",
    ),
    Output(
        "effective_length",
        "m",
        "Length of a bar of the stress area with the bolt's compliance, E A_s δ_S",
        display_unit="mm",
        symbol="L_eff",
        step="ASTM E1685",
    ),
    Output(
        "bolt_stress",
        "Pa",
        "Axial stress F/A_s",
        display_unit="MPa",
        symbol="σ_S",
        step="ASTM E1685",
    ),
)


def _compliance(x: Mapping[str, Any], ctx: RunContext) -> float:
    """δ_S of the joint model for the bolt these inputs describe."""
    given = {k: x[k] for k in _JOINT_NAMES if x.get(k) is not None}
    values, _ = VDI2230.validate(given)
    joint_ctx = RunContext(
        rung="closed_form", outputs=frozenset({"bolt_compliance"}), tolerance=ctx.tolerance
    )
    compliance = VDI2230.compute(values, joint_ctx).values["bolt_compliance"]
    assert isinstance(compliance, float)
    return compliance


def _ultrasonic(x: Mapping[str, Any], ctx: RunContext) -> Result:
    given = [n for n in ("preload", "elongation", "time_of_flight_change") if x.get(n) is not None]
    if len(given) != 1:
        raise InputOutOfRange(
            "give one of preload (to get the elongation and time of flight), elongation or "
            "time_of_flight_change (to get the preload)"
            + ("" if not given else f", not {' and '.join(given)}"),
            field=given[-1] if given else "preload",
        )
    bolt, notes = resolve_bolt(x)
    delta_s = _compliance(x, ctx)
    velocity, factor = float(x["sound_velocity"]), float(x["stress_factor"])
    tau, d_t = float(x["temperature_factor"]), float(x["reading_temperature_change"])
    length = x.get("ultrasonic_length")
    if tau * d_t != 0.0 and length is None:
        raise InputOutOfRange(
            "ultrasonic_length is required to correct a temperature change between the readings",
            field="ultrasonic_length",
        )
    thermal = 0.0 if length is None else float(us.thermal_length_change(length, tau, d_t))
    if x.get("preload") is not None:
        force = float(x["preload"])
        elongation = float(pl.elongation(force, delta_s))
        change = float(us.ultrasonic_from_elongation(elongation, factor))
        tof = float(us.time_of_flight_change(change + thermal, velocity))
    elif x.get("elongation") is not None:
        elongation = float(x["elongation"])
        change = float(us.ultrasonic_from_elongation(elongation, factor))
        tof = float(us.time_of_flight_change(change + thermal, velocity))
        force = float(pl.preload_from_elongation(elongation, delta_s))
    else:
        tof = float(x["time_of_flight_change"])
        change = float(us.ultrasonic_length_change(tof, velocity)) - thermal
        elongation = float(us.mechanical_elongation(change, factor))
        force = float(pl.preload_from_elongation(elongation, delta_s))
    e_s = float(x["youngs_modulus"])
    effective = e_s * bolt.stress_area * delta_s
    stress = force / bolt.stress_area
    checks = [
        Check(
            "below_yield",
            stress < bolt.yield_strength,
            f"σ = F/A_s = {q(stress, 'MPa', 4)} "
            + (
                f"< R_p0.2 = {q(bolt.yield_strength, 'MPa', 4)}: elongation and preload are "
                "proportional"
                if stress < bolt.yield_strength
                else f"≥ R_p0.2 = {q(bolt.yield_strength, 'MPa', 4)}: past yield the "
                "elastic relation F = ΔL/δ_S no longer holds"
            ),
        ),
        Check(
            "tension",
            force >= 0.0,
            "the reading shows tension"
            if force >= 0.0
            else "a negative change: the bolt is shorter than at the zero reading (check the "
            "zero reading and the temperature correction)",
        ),
    ]
    warnings: list[str] = []
    ratio = effective / bolt.diameter
    if ratio < MIN_LENGTH_RATIO:
        warnings.append(
            f"effective length {q(effective, 'mm')} is {ratio:.2g} d: ASTM E1685 is meant for "
            f"effective length-to-diameter ratios of {MIN_LENGTH_RATIO:g}:1 or more"
        )
    notes.extend(
        [
            f"δ_S = {delta_s * 1e9:.4g} mm/MN from the joint model (VDI 2230-1 R3: head, shank, "
            "free and engaged thread, nut)",
            "ΔL_U = V Δt/2 (pulse-echo round trip), ΔL = S_F ΔL_U [BoltMike], [Dakota]; "
            "S_F, τ and V are the bolt's calibration, not data of the engine",
        ]
    )
    return Result(
        values={
            "preload": force,
            "elongation": elongation,
            "ultrasonic_length_change": change,
            "thermal_length_change": thermal,
            "time_of_flight_change": tof,
            "bolt_compliance": delta_s,
            "effective_length": effective,
            "bolt_stress": stress,
        },
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        warnings=warnings,
    )


CLOSED_FORM = Rung(
    "closed_form",
    "The makers' linear relations and VDI 2230-1 R3's compliance; the estimate does not "
    "include the calibration's uncertainty (S_F and V vary by about 5 % over steel bolts, "
    "[Dakota]) nor the compliance model's",
    fixed_error(0.0),
    typical_error="exact against the stated relations",
    typical_time="< 1 ms",
)

#: M12 8.8 through 2 × 20 mm, 40 kN; V and S_F are example calibration values, not data.
M12_40KN = {
    "thread_diameter": 0.012,
    "plate1_thickness": 0.020,
    "plate2_thickness": 0.020,
    "preload": 40e3,
    "sound_velocity": 5900.0,
    "stress_factor": 0.3,
}

ULTRASONIC = ModelSpec(
    answer=(
        Answer("preload", "F_V"),
        Answer("elongation", "ΔL"),
        Answer("time_of_flight_change", "Δt"),
        Answer("bolt_stress", "σ_S", check="below_yield"),
    ),
    name="preload.ultrasonic",
    title="Ultrasonic elongation ↔ preload (pulse-echo time of flight)",
    family="preload",
    summary=(
        "From a preload, the bolt's elongation and the change in the echo's time of flight an "
        "ultrasonic instrument should read; or from a measured time-of-flight change, the "
        "elongation and preload. The stress factor, the temperature correction and the bolt's "
        "compliance (VDI 2230-1 R3, as the joint model computes it) enter as ASTM E1685 "
        "practice states them."
    ),
    source=SOURCE,
    inputs=INPUTS,
    outputs=OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_ultrasonic,
    examples=(
        M12_40KN,
        # a reading: 100 ns round trip, bolt 3 K warmer than at the zero reading
        {
            **{k: v for k, v in M12_40KN.items() if k != "preload"},
            "time_of_flight_change": 100e-9,
            "temperature_factor": 100e-6,
            "reading_temperature_change": 3.0,
            "ultrasonic_length": 0.055,
        },
    ),
)
