"""Model spec for the bolted joint after VDI 2230 Part 1 (``joint.vdi2230``).

The physics lives in :mod:`engine.joint` (one function per VDI step), the
bolt data in :mod:`engine.threads`, the tightening relations in
:mod:`engine.preload` and the bolt resolution in the preload declarations;
this module turns a request into a joint, runs the steps R0–R13 in order and
says which step every number comes from.

Surface pressure (VDI R10) and the length of engagement / thread stripping
(VDI R11) belong to the fastener catalogue; they plug in through
:data:`CHECK_HOOKS` without touching this module's compute.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .. import fasteners as fa
from .. import joint as jt
from .. import preload as pl
from ..errors import EngineError, InputOutOfRange
from ..preload_methods import METHODS, get_method
from ..spec import Check, ModelSpec, Output, Param, Result, RunContext, Rung, fixed_error
from . import _fasteners as fz
from .preload import BOLT_INPUTS, Bolt, resolve_bolt

SOURCE = (
    "VDI 2230-1:2015 steps R0–R13 (text paywalled: relations as reproduced in "
    "ECSS-E-HB-32-23A §6–7 and the open implementation misams/BAT); [004] eq. 2–8 for the "
    "review's preload rules; ISO 68-1, 261, 273, 898-1, 4017"
)

#: Bolt-family control methods (the sucker-rod ones do not tighten a bolted joint).
BOLT_METHOD_KEYS: tuple[str, ...] = tuple(m.key for m in METHODS if m.family == "bolt")

#: Steel: Young's modulus [Pa] and thermal expansion [1/K] used as defaults.
STEEL_E = 2.1e11
STEEL_ALPHA = 11.5e-6

MAX_PLATES = 3

# --------------------------------------------------------------------------- inputs

_BOLT_NAMES = (
    "thread",  # a designation ("M12 ISO 4762 10.9", "1/2-13 UNC"), issue 15
    "grade",
    "thread_diameter",
    "thread_pitch",
    "property_class",
    "yield_strength",
    "bearing_outer_diameter",
    "hole_diameter",
    "hole_series",
    "utilization",
)


def _length(name: str, description: str, **kw: Any) -> Param:
    kw.setdefault("maximum", 10.0)
    return Param(name, "m", description, display_unit="mm", **kw)


def _plate_inputs(i: int) -> tuple[Param, ...]:
    first = i == 1
    return (
        _length(
            f"plate{i}_thickness",
            f"Thickness h_{i} of clamped plate {i} (from the head side)"
            + ("" if first else "; absent or 0: no such plate"),
            required=first,
            minimum=0.0,
            exclusive_minimum=first,
            group="plates",
        ),
        Param(
            f"plate{i}_youngs_modulus",
            "Pa",
            f"Young's modulus E_{i} of plate {i}"
            + (" (steel 210 GPa)" if first else "; plate 1's when absent"),
            default=STEEL_E if first else None,
            minimum=1e8,
            maximum=1e12,
            display_unit="GPa",
            group="plates",
        ),
        Param(
            f"plate{i}_expansion",
            "1/K",
            f"Thermal expansion coefficient α_{i} of plate {i}"
            + (
                " (steel 11.5e-6 /K; type e.g. '23e-6 K^-1')"
                if first
                else "; plate 1's when absent"
            ),
            default=STEEL_ALPHA if first else None,
            minimum=0.0,
            maximum=1e-3,
            group="plates",
        ),
    )


JOINT_INPUTS: tuple[Param, ...] = (
    *(p for p in BOLT_INPUTS if p.name in _BOLT_NAMES),
    Param(
        "head",
        "1",
        "Head type: 'hex' (l_SK = 0.5 d) or 'socket' (0.4 d), VDI 2230-1 R3",
        default="hex",
        kind="choice",
        choices=tuple(jt.HEAD_LENGTH_FACTOR),
        group="bolt",
    ),
    Param(
        "joint_type",
        "1",
        "'through': bolt and nut (DSV); 'tapped': screwed into the last part (ESV)",
        default="through",
        kind="choice",
        choices=tuple(jt.NUT_LENGTH_FACTOR),
        group="joint",
    ),
    _length(
        "shank_length",
        "Length of plain shank inside the grip; the rest of the grip is free thread",
        default=0.0,
        minimum=0.0,
        group="bolt",
    ),
    _length(
        "shank_diameter",
        "Plain shank diameter; d when absent",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        group="bolt",
    ),
    _length(
        "reduced_length",
        "Length of a reduced (waisted) shank inside the grip",
        default=0.0,
        minimum=0.0,
        group="bolt",
    ),
    _length(
        "reduced_diameter",
        "Diameter d_T of the reduced shank (needed when reduced_length > 0); the strength "
        "limit F_M,zul is taken at the smallest section (VDI 2230-1 R7)",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1.0,
        group="bolt",
    ),
    Param(
        "youngs_modulus",
        "Pa",
        "Young's modulus of the bolt E_S",
        default=STEEL_E,
        minimum=1e9,
        maximum=1e12,
        display_unit="GPa",
        group="bolt",
    ),
    Param(
        "nut_youngs_modulus",
        "Pa",
        "Young's modulus E_M of the nut or of the part with the tapped thread; E_S when absent",
        minimum=1e8,
        maximum=1e12,
        display_unit="GPa",
        group="bolt",
    ),
    Param(
        "bolt_expansion",
        "1/K",
        "Thermal expansion coefficient α_S of the bolt",
        default=STEEL_ALPHA,
        minimum=0.0,
        maximum=1e-3,
        group="bolt",
    ),
    *_plate_inputs(1),
    *_plate_inputs(2),
    *_plate_inputs(3),
    _length(
        "outer_diameter",
        "Outer diameter D_A of the clamped parts (equivalent); absent: plates wide enough "
        "for the full deformation cone. Must be ≥ the bearing diameter d_W",
        minimum=0.0,
        exclusive_minimum=True,
        group="plates",
    ),
    Param(
        "load_introduction",
        "1",
        "Load-introduction factor n (VDI 2230-1 R3): 1 under the head and nut, "
        "0.5 typical, lower when the load enters near the interface",
        default=0.5,
        minimum=0.0,
        maximum=1.0,
        symbol="n",
        group="loads",
    ),
    Param(
        "working_load",
        "N",
        "Axial working load F_A,max per bolt (0: preload only)",
        default=0.0,
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        symbol="F_A",
        group="loads",
    ),
    Param(
        "working_load_min",
        "N",
        "Lower axial working load F_A,min of an alternating load; static (= F_A,max) when absent",
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        group="loads",
    ),
    Param(
        "transverse_load",
        "N",
        "Transverse load F_Q,max per bolt carried by interface friction",
        default=0.0,
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        symbol="F_Q",
        group="loads",
    ),
    Param(
        "slip_interfaces",
        "1",
        "Number q_F of interfaces that carry the transverse load",
        default=1,
        kind="int",
        minimum=1,
        maximum=20,
        group="loads",
    ),
    Param(
        "interface_friction",
        "1",
        "Smallest interface friction coefficient μ_T,min (VDI 2230-1 Table A6: 0.1…0.2 dry steel)",
        default=0.15,
        minimum=0.0,
        maximum=1.0,
        exclusive_minimum=True,
        group="loads",
    ),
    Param(
        "sealing_clamp_force",
        "N",
        "Clamp force F_KP that must remain for sealing or other reasons (added to the "
        "friction requirement's maximum, VDI 2230-1 R2)",
        default=0.0,
        minimum=0.0,
        maximum=1e8,
        display_unit="kN",
        group="loads",
    ),
    Param(
        "surface_roughness",
        "1",
        "Mean roughness depth class of the bearing faces and interfaces (embedding, VDI R4)",
        default="Rz10-40",
        kind="choice",
        choices=jt.ROUGHNESS_CLASSES,
        group="losses",
    ),
    Param(
        "temperature_change",
        "K",
        "Service temperature minus assembly temperature of the bolt ΔT_S",
        default=0.0,
        minimum=-300.0,
        maximum=1000.0,
        group="losses",
    ),
    Param(
        "plate_temperature_change",
        "K",
        "Temperature change of the plates ΔT_P; ΔT_S when absent",
        minimum=-300.0,
        maximum=1000.0,
        group="losses",
    ),
    Param(
        "bolt_modulus_ratio",
        "1",
        "E of the bolt at service temperature / at room temperature",
        default=1.0,
        minimum=0.1,
        maximum=1.5,
        group="losses",
    ),
    Param(
        "plate_modulus_ratio",
        "1",
        "E of the plates at service temperature / at room temperature",
        default=1.0,
        minimum=0.1,
        maximum=1.5,
        group="losses",
    ),
    Param(
        "thread_friction_min",
        "1",
        "Smallest thread friction μ_G,min (sets F_M,zul and the highest preload)",
        default=0.12,
        minimum=0.0,
        maximum=1.0,
        group="friction",
    ),
    Param(
        "thread_friction_max",
        "1",
        "Largest thread friction μ_G,max (sets the lowest preload at a torque); μ_G,min "
        "when absent",
        minimum=0.0,
        maximum=1.0,
        group="friction",
    ),
    Param(
        "bearing_friction_min",
        "1",
        "Smallest bearing-face friction μ_K,min",
        default=0.12,
        minimum=0.0,
        maximum=1.0,
        group="friction",
    ),
    Param(
        "bearing_friction_max",
        "1",
        "Largest bearing-face friction μ_K,max; μ_K,min when absent",
        minimum=0.0,
        maximum=1.0,
        group="friction",
    ),
    Param(
        "method",
        "1",
        "Tightening method: its scatter gives α_A (GET /api/v1/preload/methods)",
        default="torque_wrench",
        kind="choice",
        choices=BOLT_METHOD_KEYS,
        group="tightening",
    ),
    Param(
        "tightening_factor",
        "1",
        "α_A = F_M,max/F_M,min (VDI 2230-1 R1, Table A8); the method's when absent",
        minimum=1.0,
        maximum=5.0,
        symbol="α_A",
        group="tightening",
    ),
    Param(
        "tightening_torque",
        "N*m",
        "Torque specification M_A (including the prevailing torque): when given, the "
        "assembly preload range comes from it and the friction box",
        minimum=0.0,
        exclusive_minimum=True,
        maximum=1e6,
        group="tightening",
    ),
    Param(
        "torque_tolerance",
        "1",
        "Relative torque tolerance ± of the tool (0.05 for ±5 %)",
        default=0.0,
        minimum=0.0,
        maximum=0.9,
        group="tightening",
    ),
    Param(
        "prevailing_torque",
        "N*m",
        "Prevailing (locking) torque M_ü that produces no preload",
        default=0.0,
        minimum=0.0,
        maximum=1e5,
        group="tightening",
    ),
    Param(
        "prevailing_torque_min",
        "N*m",
        "Smallest prevailing torque M_ü,min (sets the highest preload); prevailing_torque when "
        "absent",
        minimum=0.0,
        maximum=1e5,
        group="tightening",
    ),
    Param(
        "controlled",
        "1",
        "Tightened with a controlled method (false: by feel, [004] warns of over-tightening "
        "below M10)",
        default=True,
        kind="bool",
        group="tightening",
    ),
    Param(
        "bridge_joint",
        "1",
        "High-strength bridge joint: [004] allows σ0 = 0.8…0.9 σ_T",
        default=False,
        kind="bool",
        group="tightening",
    ),
    Param(
        "rolling",
        "1",
        "Thread rolled before or after heat treatment (endurance limit, VDI 2230-1 R9)",
        default="before_heat_treatment",
        kind="choice",
        choices=("before_heat_treatment", "after_heat_treatment"),
        group="fatigue",
    ),
    # bought-part checks (issue 15): surface pressure VDI 2230-1 R10, engagement R11
    *(p for p in fz.CHECK_INPUTS if p.name != "working_bolt_force"),
)

# --------------------------------------------------------------------------- hooks

#: Further checks on the solved joint: each hook takes the inputs and the solved
#: :class:`JointSolution` and returns checks and notes. Surface pressure under head
#: and nut (VDI 2230-1 R10) and the length of engagement / thread stripping (R11)
#: are meant to plug in here from the fastener catalogue.
CheckHook = Callable[[Mapping[str, Any], "JointSolution"], tuple[list[Check], list[str]]]
CHECK_HOOKS: list[CheckHook] = [fz.joint_check_hook]


@dataclass(frozen=True)
class JointSolution:
    """The solved joint a check hook sees (SI)."""

    bolt: Bolt
    grip: float
    bearing_diameter: float
    hole_diameter: float
    assembly_preload_max: float
    max_bolt_force: float
    joint_type: str


# --------------------------------------------------------------------------- helpers


def _plates(x: Mapping[str, Any]) -> tuple[list[float], list[float], list[float]]:
    thick, moduli, alphas = [], [], []
    e1, a1 = float(x["plate1_youngs_modulus"]), float(x["plate1_expansion"])
    for i in range(1, MAX_PLATES + 1):
        h = x.get(f"plate{i}_thickness")
        if h is None or float(h) <= 0.0:
            continue
        e, a = x.get(f"plate{i}_youngs_modulus"), x.get(f"plate{i}_expansion")
        thick.append(float(h))
        moduli.append(e1 if e is None else float(e))
        alphas.append(a1 if a is None else float(a))
    return thick, moduli, alphas


def _friction(x: Mapping[str, Any], name: str) -> tuple[float, float]:
    lo = float(x[f"{name}_min"])
    hi = x.get(f"{name}_max")
    hi = lo if hi is None else float(hi)
    if hi < lo:
        raise InputOutOfRange(
            f"{name}_max = {hi:g} is below {name}_min = {lo:g}: must be ≥ {lo:g}",
            field=f"{name}_max",
        )
    return lo, hi


def _shank_sections(bolt: Bolt, x: Mapping[str, Any], grip: float) -> tuple[list, float]:
    l_shank, l_reduced = float(x["shank_length"]), float(x["reduced_length"])
    if l_shank + l_reduced > grip * (1.0 + 1e-12):
        raise InputOutOfRange(
            f"shank_length + reduced_length = {(l_shank + l_reduced) * 1e3:g} mm exceeds the "
            f"grip l_K = {grip * 1e3:g} mm (sum of the plates): must be ≤ {grip * 1e3:g} mm",
            field="shank_length",
        )
    if l_reduced > 0.0 and x.get("reduced_diameter") is None:
        raise InputOutOfRange(
            "reduced_diameter is required when reduced_length > 0", field="reduced_diameter"
        )
    shank_d = bolt.diameter if x.get("shank_diameter") is None else float(x["shank_diameter"])
    reduced_d = bolt.diameter if x.get("reduced_diameter") is None else float(x["reduced_diameter"])
    for name, value in (("shank_diameter", shank_d), ("reduced_diameter", reduced_d)):
        if value > bolt.diameter * (1 + 1e-12) and x.get(name) is not None:
            raise InputOutOfRange(
                f"{name} = {value * 1e3:g} mm exceeds the thread diameter d = "
                f"{bolt.diameter * 1e3:g} mm: must be ≤ {bolt.diameter * 1e3:g} mm",
                field=name,
            )
    sections = [(l_shank, shank_d), (l_reduced, reduced_d)]
    free = max(grip - l_shank - l_reduced, 0.0)
    return [s for s in sections if s[0] > 0.0], free


def _per_newton(bolt: Bolt, mu_g: float, mu_k: float) -> tuple[float, float]:
    k_thread, k_bearing = pl.tightening_torque_per_preload(
        bolt.pitch,
        bolt.pitch_diameter,
        bolt.diameter,
        mu_g,
        mu_k,
        bolt.bearing_outer_diameter,
        bolt.hole_diameter,
        "vdi2230",
    )
    return float(k_thread), float(k_bearing)


def _kn(force: float) -> str:
    return f"{force / 1e3:.4g} kN"


# --------------------------------------------------------------------------- compute


def _compute(x: Mapping[str, Any], ctx: RunContext) -> Result:
    bolt, notes = resolve_bolt(x)
    checks: list[Check] = []
    warnings: list[str] = []
    joint_type = str(x["joint_type"])
    d, d_w, d_h = bolt.diameter, bolt.bearing_outer_diameter, bolt.hole_diameter

    # R0/R3 geometry -----------------------------------------------------------------
    thick, moduli, alphas = _plates(x)
    grip = sum(thick)
    outer = x.get("outer_diameter")
    if outer is not None and float(outer) < d_w * (1.0 - 1e-12):
        raise InputOutOfRange(
            f"outer_diameter D_A = {float(outer) * 1e3:g} mm is smaller than the bearing "
            f"diameter d_W = {d_w * 1e3:g} mm: must be ≥ {d_w * 1e3:g} mm (D_A = d_W is the "
            "sleeve)",
            field="outer_diameter",
        )
    sections, free_thread = _shank_sections(bolt, x, grip)
    e_s = float(x["youngs_modulus"])
    nut_e = x.get("nut_youngs_modulus")
    bolt_c = jt.bolt_compliance(
        d,
        bolt.minor_diameter,
        e_s,
        sections,
        free_thread,
        str(x["head"]),
        joint_type,
        None if nut_e is None else float(nut_e),
    )
    parts = jt.clamped_compliance(
        thick, moduli, d_w, d_h, None if outer is None else float(outer), joint_type
    )
    delta_s, delta_p = bolt_c.total, parts.total
    n = float(x["load_introduction"])
    phi_k = jt.load_factor(delta_s, delta_p, 1.0)
    phi_n = n * phi_k
    if outer is None:
        notes.append(
            f"D_A not given: plates taken just wide enough for the full cone, D_A = D_A,Gr = "
            f"{parts.outer_diameter * 1e3:.4g} mm (our convention; VDI's cone-angle fit needs a "
            "D_A); a wider plate is stiffer by that fit"
        )
    if parts.tangent <= jt.MIN_CONE_TANGENT:
        warnings.append(
            f"plates very thin against d_W: the cone tangent is held at {jt.MIN_CONE_TANGENT}"
        )

    # R2 required clamp force ------------------------------------------------------------
    f_q = float(x["transverse_load"])
    q_f, mu_t = int(x["slip_interfaces"]), float(x["interface_friction"])
    f_kq = jt.transverse_clamp_force(f_q, q_f, mu_t)
    f_kp = float(x["sealing_clamp_force"])
    f_kerf = max(f_kq, f_kp)

    # R1 tightening factor and friction ----------------------------------------------------
    method = get_method(str(x["method"]))
    mu_g_lo, mu_g_hi = _friction(x, "thread_friction")
    mu_k_lo, mu_k_hi = _friction(x, "bearing_friction")
    f_a = float(x["working_load"])
    f_a_min = f_a if x.get("working_load_min") is None else float(x["working_load_min"])
    if f_a_min > f_a:
        raise InputOutOfRange(
            f"working_load_min = {f_a_min:g} N exceeds working_load = {f_a:g} N: must be ≤ "
            f"{f_a:g} N",
            field="working_load_min",
        )

    # R4 losses ------------------------------------------------------------------------------
    bearing_faces = 2 if joint_type == "through" else 1
    interfaces = len(thick) - 1 if joint_type == "through" else len(thick)
    load_kind = "transverse" if f_q > 0.0 else "axial"
    f_z_len = jt.embedding(str(x["surface_roughness"]), load_kind, bearing_faces, interfaces)
    f_z = jt.embedding_loss(f_z_len, delta_s, delta_p)
    dt_s = float(x["temperature_change"])
    dt_p = (
        dt_s if x.get("plate_temperature_change") is None else float(x["plate_temperature_change"])
    )
    alpha_len = sum(h * a for h, a in zip(thick, alphas, strict=True))

    # R7 permissible preload at the smallest section -----------------------------------------
    d0, where = jt.smallest_section(bolt.stress_diameter, sections)
    a0 = bolt.stress_area if where == "thread" else 0.25 * math.pi * d0 * d0
    nu = float(x["utilization"])
    beta = float(pl.torsion_factor(bolt.pitch, bolt.pitch_diameter, d0, mu_g_lo, "vdi2230"))
    f_mzul = pl.assembly_preload(bolt.yield_strength, a0, beta, nu)
    f_myield = pl.assembly_preload(bolt.yield_strength, a0, beta, 1.0)
    if where == "shank":
        notes.append(
            f"smallest section is the shank, d_0 = {d0 * 1e3:.4g} mm < d_S = "
            f"{bolt.stress_diameter * 1e3:.4g} mm: F_M,zul = {_kn(f_mzul)} at A_0 = "
            f"{a0 * 1e6:.4g} mm² (VDI 2230-1 R7)"
        )

    # assembly preload range: torque specification or design at F_M,zul ------------------
    kt_low, kb_low = _per_newton(bolt, mu_g_lo, mu_k_lo)
    k_low, k_high = kt_low + kb_low, sum(_per_newton(bolt, mu_g_hi, mu_k_hi))
    m_u = float(x["prevailing_torque"])
    m_u_min = m_u if x.get("prevailing_torque_min") is None else float(x["prevailing_torque_min"])
    if m_u_min > m_u:
        raise InputOutOfRange(
            f"prevailing_torque_min = {m_u_min:g} N*m exceeds prevailing_torque = {m_u:g} N*m: "
            f"must be ≤ {m_u:g} N*m",
            field="prevailing_torque_min",
        )
    if x.get("tightening_torque") is not None:
        torque = float(x["tightening_torque"])
        tol = float(x["torque_tolerance"])
        fm_min, fm_max = jt.preload_bounds_from_torque(torque, tol, m_u, k_low, k_high, m_u_min)
        alpha_a = fm_max / fm_min if fm_min > 0.0 else math.inf
        notes.append(
            f"torque {torque:.4g} N·m ± {tol:.0%}, prevailing {m_u:.3g} N·m, μ_G "
            f"{mu_g_lo:g}…{mu_g_hi:g}, μ_K {mu_k_lo:g}…{mu_k_hi:g}: F_M = {_kn(fm_min)} "
            f"(M_A,min at μ_max) … {_kn(fm_max)} (M_A,max at μ_min), VDI 2230-1 R13 inverted"
        )
        design_torque = torque
    else:
        alpha_a = (
            method.tightening_factor
            if x.get("tightening_factor") is None
            else float(x["tightening_factor"])
        )
        fm_max = f_mzul
        fm_min = f_mzul / alpha_a
        design_torque = f_mzul * kt_low + f_mzul * kb_low + m_u
        notes.append(
            f"no torque given: tightened to F_M,zul = {_kn(f_mzul)} with α_A = {alpha_a:.3g} "
            f"({method.key if x.get('tightening_factor') is None else 'as given'}); "
            f"M_A = {design_torque:.4g} N·m at μ_G,min, μ_K,min (VDI 2230-1 R13)"
        )
    if x.get("tightening_torque") is not None and x.get("tightening_factor") is not None:
        notes.append("tightening_factor ignored: the torque specification sets the preload range")

    f_v_min = fm_min - f_z
    th_loss = jt.thermal_preload_loss(
        f_v_min,
        grip,
        float(x["bolt_expansion"]),
        dt_s,
        alpha_len,
        dt_p,
        delta_s,
        delta_p,
        float(x["bolt_modulus_ratio"]),
        float(x["plate_modulus_ratio"]),
    )

    # R5/R6 required window -------------------------------------------------------------------
    alpha_req = alpha_a if math.isfinite(alpha_a) else method.tightening_factor
    req_min = jt.minimum_assembly_preload(f_kerf, f_a, phi_n, f_z, th_loss)
    req_max = alpha_req * req_min
    window_ok = req_max <= f_mzul * (1.0 + 1e-12)
    loss = f_z + max(th_loss, 0.0)
    if 1.0 - phi_n > 0.0:
        fa_limit = max((f_mzul / alpha_req - f_kerf - loss) / (1.0 - phi_n), 0.0)
        fa_sep_any = max((f_mzul - loss) / (1.0 - phi_n), 0.0)
    else:
        fa_limit = fa_sep_any = math.inf
    checks.append(
        Check(
            "R7_window_fits",
            window_ok,
            f"required F_M,max = α_A F_M,min = {alpha_req:.3g} × {_kn(req_min)} = {_kn(req_max)} "
            f"vs F_M,zul = {_kn(f_mzul)}"
            + (
                ""
                if window_ok
                else f": the largest F_A this bolt can carry with α_A = {alpha_req:.3g} is "
                f"{_kn(fa_limit)}; use a more accurate method, a larger or stronger bolt"
            ),
        )
    )
    no_sep_possible = f_a < fa_sep_any
    checks.append(
        Check(
            "separation_avoidable",
            no_sep_possible,
            f"F_A = {_kn(f_a)} vs {_kn(fa_sep_any)}, the load that separates the joint even at "
            f"F_M,zul after embedding and thermal loss ((F_M,zul − F_Z − ΔF_th)/(1 − Φ_n))"
            + ("" if no_sep_possible else ": no admissible preload keeps this joint closed"),
        )
    )

    # residual clamp force and separation at the assembly window's bottom (R12, separation)
    f_kr_min = fm_min - (1.0 - phi_n) * f_a - f_z - max(th_loss, 0.0)
    fa_sep = max(fm_min - f_z - max(th_loss, 0.0), 0.0) / (1.0 - phi_n) if phi_n < 1.0 else math.inf
    clamp_ok = f_kr_min >= f_kerf * (1.0 - 1e-12)
    checks.append(
        Check(
            "residual_clamp_force",
            clamp_ok,
            f"F_KR,min = F_M,min − (1 − Φ_n) F_A − F_Z − ΔF_th = {_kn(f_kr_min)} vs required "
            f"F_K,erf = {_kn(f_kerf)}"
            + ("" if clamp_ok else ": raise the preload floor (torque, method) or lower F_A"),
        )
    )
    if x.get("tightening_torque") is not None:
        top_ok = fm_max <= f_mzul * (1.0 + 1e-12)
        checks.append(
            Check(
                "R7_max_below_permissible",
                top_ok,
                f"F_M,max = {_kn(fm_max)} from the torque vs F_M,zul = {_kn(f_mzul)} "
                f"(ν = {nu:g} at μ_G,min)"
                + ("" if top_ok else ": lower the torque or narrow its tolerance"),
            )
        )

    # R8 working stress ------------------------------------------------------------------------
    add_load = phi_n * f_a
    f_s_max = fm_max + add_load
    stress = jt.service_stress(f_s_max, fm_max, bolt.pitch, bolt.pitch_diameter, d0, mu_g_lo)
    s_f = bolt.yield_strength / stress.equivalent
    checks.append(
        Check(
            "R8_working_stress",
            s_f >= 1.0,
            f"σ_red,B = {stress.equivalent / 1e6:.4g} MPa at F_S,max = {_kn(f_s_max)} vs R_p0.2 "
            f"= {bolt.yield_strength / 1e6:.4g} MPa: S_F = {s_f:.3g} (≥ 1.0)",
        )
    )

    # R9 alternating stress ----------------------------------------------------------------------
    sigma_a = phi_n * (f_a - f_a_min) / (2.0 * bolt.stress_area)
    f_sm = fm_max + phi_n * 0.5 * (f_a + f_a_min)
    sigma_as = jt.endurance_limit(
        d, str(x["rolling"]), f_sm, bolt.stress_area * bolt.yield_strength
    )
    s_d = sigma_as / sigma_a if sigma_a > 0.0 else math.inf
    if sigma_a > 0.0:
        checks.append(
            Check(
                "R9_fatigue",
                s_d >= 1.2,
                f"σ_a = Φ_n (F_A,max − F_A,min)/(2 A_S) = {sigma_a / 1e6:.3g} MPa vs σ_AS = "
                f"{sigma_as / 1e6:.3g} MPa: S_D = {s_d:.3g} (VDI asks ≥ 1.2)",
            )
        )

    # R12 slipping -----------------------------------------------------------------------------
    s_g = f_kr_min * q_f * mu_t / f_q if f_q > 0.0 else math.inf
    if f_q > 0.0:
        need = 1.8 if f_a_min < f_a else 1.2
        checks.append(
            Check(
                "R12_slip",
                s_g >= need,
                f"S_G = F_KR,min q_F μ_T / F_Q = {s_g:.3g} (VDI asks ≥ {need:g} for "
                f"{'alternating' if need > 1.2 else 'static'} load)",
            )
        )

    # [004] rules -------------------------------------------------------------------------------
    nominal = 0.5 * (fm_min + fm_max)
    sigma0 = nominal / a0
    ratio0 = sigma0 / bolt.yield_strength
    accurate = method.scatter <= 0.10 + 1e-12 and x.get("tightening_torque") is None
    if bool(x["bridge_joint"]):
        lo_rule, hi_rule, why = 0.8, 0.9, "bridge joint"
    elif accurate:
        lo_rule, hi_rule, why = 0.5, 0.7, f"{method.key}, ±{method.scatter:.0%}"
    else:
        lo_rule, hi_rule, why = 0.4, 0.5, "method less accurate than ±10 %"
    checks.append(
        Check(
            "seed_004_preload_stress",
            ratio0 <= hi_rule + 1e-12,
            f"σ0 = F_M,nom/A_0 = {sigma0 / 1e6:.4g} MPa = {ratio0:.2f} σ_T; [004, eq. 6] allows "
            f"{lo_rule:g}…{hi_rule:g} σ_T ({why}); VDI 2230 R7 instead limits the equivalent "
            f"stress to ν R_p0.2 (ν = {nu:g}), which allows more",
        )
    )
    if not bool(x["controlled"]) and d < 0.010:
        warnings.append(
            f"d = {d * 1e3:g} mm < 10 mm tightened without control: [004] warns of "
            "over-tightening; lower the admissible load or control the tightening"
        )

    # hooks (R10 surface pressure, R11 engagement) ------------------------------------------------
    solution = JointSolution(bolt, grip, d_w, d_h, fm_max, f_s_max, joint_type)
    for hook in CHECK_HOOKS:
        more_checks, more_notes = hook(x, solution)
        checks.extend(more_checks)
        notes.extend(more_notes)
    if not CHECK_HOOKS:
        notes.append(
            "surface pressure under head and nut (VDI R10) and length of engagement / thread "
            "stripping (VDI R11) are not checked by this model yet"
        )

    # angle and elongation at the nominal preload [004, eq. 7–8] ---------------------------------
    angle = pl.nut_rotation_angle(nominal, delta_s + delta_p, bolt.pitch)
    rigid_angle = pl.nut_rotation_angle(nominal, delta_s, bolt.pitch)

    values: dict[str, Any] = {
        "tightening_factor": alpha_a if math.isfinite(alpha_a) else None,
        "required_clamp_force": f_kerf,
        "transverse_clamp_force": f_kq,
        "bolt_compliance": delta_s,
        "bolt_compliance_head": bolt_c.head,
        "bolt_compliance_shank": bolt_c.shank,
        "bolt_compliance_free_thread": bolt_c.free_thread,
        "bolt_compliance_engaged": bolt_c.engaged_thread + bolt_c.nut,
        "clamped_compliance": delta_p,
        "cone_tangent": parts.tangent,
        "cone_limit_diameter": parts.limit_diameter,
        "outer_diameter_used": parts.outer_diameter,
        "grip": grip,
        "load_factor_k": phi_k,
        "load_factor": phi_n,
        "additional_bolt_load": add_load,
        "clamp_load_reduction": (1.0 - phi_n) * f_a,
        "embedding_settlement": f_z_len,
        "embedding_loss": f_z,
        "thermal_loss": th_loss,
        "required_preload_min": req_min,
        "required_preload_max": req_max,
        "smallest_diameter": d0,
        "smallest_area": a0,
        "permissible_preload": f_mzul,
        "yield_preload": f_myield,
        "assembly_preload_min": fm_min,
        "assembly_preload_max": fm_max,
        "tightening_torque": design_torque,
        "residual_clamp_force_min": f_kr_min,
        "separation_load": fa_sep,
        "max_working_load": fa_limit,
        "max_bolt_force": f_s_max,
        "working_stress": stress.equivalent,
        "yield_safety": s_f,
        "stress_amplitude": sigma_a,
        "endurance_limit": sigma_as,
        "fatigue_safety": s_d if math.isfinite(s_d) else None,
        "slip_safety": s_g if math.isfinite(s_g) else None,
        "preload_stress_ratio": ratio0,
        "bolt_elongation": nominal * delta_s,
        "target_angle": angle,
        "rigid_joint_angle": rigid_angle,
    }
    if not math.isfinite(s_d):
        notes.append("static working load: no alternating stress, fatigue_safety null (R9)")
    if not math.isfinite(s_g):
        notes.append("no transverse load: slip_safety null (R12)")

    series: dict[str, list[float]] = {}
    if ctx.wants(*_DIAGRAM):
        diagram = jt.joint_diagram(fm_min, delta_s, delta_p, f_a, phi_n, f_z)
        series.update({f"diagram_{k}": v for k, v in diagram.items()})
    if ctx.wants(*_WINDOW):
        top = max(2.0 * f_a, min(fa_sep_any, 1e9) if math.isfinite(fa_sep_any) else 2.0 * f_a)
        top = top if top > 0.0 else f_mzul
        loads = [top * i / 40 for i in range(41)]
        req = [jt.minimum_assembly_preload(f_kerf, a, phi_n, f_z, th_loss) for a in loads]
        series.update(
            window_working_load=loads,
            window_required_min=req,
            window_required_max=[alpha_req * r for r in req],
            window_permissible=[f_mzul] * len(loads),
            window_assembly_min=[fm_min] * len(loads),
            window_assembly_max=[fm_max] * len(loads),
        )
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        checks=checks,
        notes=notes,
        warnings=warnings,
        series=series,
    )


_DIAGRAM = tuple(
    f"diagram_{k}"
    for k in (
        "deformation",
        "bolt_line",
        "clamped_line",
        "embedded_clamped_line",
        "preload_level",
        "service_preload_level",
        "working_bolt_force_level",
        "residual_clamp_level",
    )
)
_WINDOW = (
    "window_working_load",
    "window_required_min",
    "window_required_max",
    "window_permissible",
    "window_assembly_min",
    "window_assembly_max",
)


def _f(name: str, desc: str, **kw: Any) -> Output:
    return Output(name, "N", desc, display_unit="kN", **kw)


JOINT_OUTPUTS: tuple[Output, ...] = (
    Output("tightening_factor", "1", "R1: α_A = F_M,max/F_M,min (method, given, or torque box)"),
    _f("required_clamp_force", "R2: F_K,erf = max(F_KQ, F_KP)"),
    _f("transverse_clamp_force", "R2: F_KQ = F_Q/(q_F μ_T,min)"),
    Output("bolt_compliance", "m/N", "R3: δ_S, head + shank + free thread + engaged thread + nut"),
    Output("bolt_compliance_head", "m/N", "R3: δ_SK = l_SK/(E_S A_N), l_SK = 0.5 d / 0.4 d"),
    Output("bolt_compliance_shank", "m/N", "R3: Σ l_i/(E_S A_i) of the plain and reduced shank"),
    Output("bolt_compliance_free_thread", "m/N", "R3: δ_Gew = l_Gew/(E_S A_d3)"),
    Output(
        "bolt_compliance_engaged",
        "m/N",
        "R3: δ_GM = 0.5 d/(E_S A_d3) + l_M/(E_M A_N), l_M = 0.4 d (nut) / 0.33 d (tapped)",
    ),
    Output("clamped_compliance", "m/N", "R3: δ_P, deformation cone and sleeve, plate by plate"),
    Output("cone_tangent", "1", "R3: tan φ of the deformation cone (VDI fit)"),
    Output("cone_limit_diameter", "m", "R3: D_A,Gr = d_W + w l_K tan φ", display_unit="mm"),
    Output("outer_diameter_used", "m", "R3: D_A used", display_unit="mm"),
    Output("grip", "m", "R3: clamp length l_K = Σ h_i", display_unit="mm"),
    Output("load_factor_k", "1", "R3: Φ_K = δ_P/(δ_S + δ_P) (load under head and nut)"),
    Output("load_factor", "1", "R3: Φ_n = n Φ_K"),
    _f("additional_bolt_load", "R3/R8: F_SA = Φ_n F_A,max"),
    _f("clamp_load_reduction", "R3: F_PA = (1 − Φ_n) F_A,max"),
    Output("embedding_settlement", "m", "R4: f_Z from the VDI table", display_unit="mm"),
    _f("embedding_loss", "R4: F_Z = f_Z/(δ_S + δ_P)"),
    _f("thermal_loss", "R4: ΔF_th (positive: preload lost) at F_V,min"),
    _f("required_preload_min", "R5: F_M,min = F_K,erf + (1 − Φ_n) F_A + F_Z + ΔF_th"),
    _f("required_preload_max", "R6: F_M,max = α_A F_M,min"),
    Output("smallest_diameter", "m", "R7: d_0 of the smallest section", display_unit="mm"),
    Output("smallest_area", "m^2", "R7: A_0 = π d_0²/4"),
    _f("permissible_preload", "R7: F_M,zul = ν R_p0.2 A_0/β at the smallest section, μ_G,min"),
    _f("yield_preload", "R7: preload at σ_red = R_p0.2 (ν = 1)"),
    _f("assembly_preload_min", "R1/R13: lowest assembly preload (F_M,zul/α_A or torque box)"),
    _f("assembly_preload_max", "R1/R13: highest assembly preload (F_M,zul or torque box)"),
    Output(
        "tightening_torque",
        "N*m",
        "R13: M_A for F_M,zul at μ_min plus M_ü (or the torque given)",
    ),
    _f("residual_clamp_force_min", "R12: F_KR,min = F_M,min − (1 − Φ_n) F_A − F_Z − ΔF_th"),
    _f("separation_load", "R5/R12: F_A at which the joint opens from the lowest assembly preload"),
    _f("max_working_load", "R5–R7: largest F_A whose required window fits under F_M,zul"),
    _f("max_bolt_force", "R8: F_S,max = F_M,max + Φ_n F_A,max"),
    Output("working_stress", "Pa", "R8: σ_red,B (k_τ = 0.5)", display_unit="MPa"),
    Output("yield_safety", "1", "R8: S_F = R_p0.2/σ_red,B"),
    Output(
        "stress_amplitude", "Pa", "R9: σ_a = Φ_n (F_A,max − F_A,min)/(2 A_S)", display_unit="MPa"
    ),
    Output("endurance_limit", "Pa", "R9: σ_ASV or σ_ASG", display_unit="MPa"),
    Output("fatigue_safety", "1", "R9: S_D = σ_AS/σ_a (null for static load)"),
    Output("slip_safety", "1", "R12: S_G = F_KR,min q_F μ_T/F_Q (null without F_Q)"),
    Output("preload_stress_ratio", "1", "[004, eq. 6]: σ0/σ_T at the nominal preload, on A_0"),
    Output("bolt_elongation", "m", "[004, eq. 7]: F_M,nom δ_S", display_unit="mm"),
    Output(
        "target_angle",
        "rad",
        "[004, eq. 8]: nut angle from snug to F_M,nom with δ_S + δ_P (R3)",
        display_unit="deg",
    ),
    Output(
        "rigid_joint_angle",
        "rad",
        "[004, eq. 9]: the same with rigid plates (what a rigid default gives)",
        display_unit="deg",
    ),
    Output(
        "diagram_deformation",
        "m",
        "Joint diagram (VDI §3.2): deformation axis",
        series=True,
        display_unit="mm",
    ),
    _f(
        "diagram_bolt_line",
        "Joint diagram: bolt line F = f/δ_S",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_clamped_line",
        "Joint diagram: clamped-part line through F_M,min",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_embedded_clamped_line",
        "Joint diagram: clamped-part line after embedding (R4)",
        series=True,
        x="diagram_deformation",
    ),
    _f("diagram_preload_level", "Joint diagram: F_M,min", series=True, x="diagram_deformation"),
    _f(
        "diagram_service_preload_level",
        "Joint diagram: F_V = F_M,min − F_Z",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_working_bolt_force_level",
        "Joint diagram: F_V + Φ_n F_A",
        series=True,
        x="diagram_deformation",
    ),
    _f(
        "diagram_residual_clamp_level",
        "Joint diagram: residual clamp force F_V − (1 − Φ_n) F_A",
        series=True,
        x="diagram_deformation",
    ),
    _f("window_working_load", "Preload window: F_A axis", series=True),
    _f(
        "window_required_min",
        "Preload window: R5 F_M,min(F_A)",
        series=True,
        x="window_working_load",
    ),
    _f(
        "window_required_max",
        "Preload window: R6 α_A F_M,min(F_A)",
        series=True,
        x="window_working_load",
    ),
    _f("window_permissible", "Preload window: R7 F_M,zul", series=True, x="window_working_load"),
    _f(
        "window_assembly_min",
        "Preload window: lowest assembly preload",
        series=True,
        x="window_working_load",
    ),
    _f(
        "window_assembly_max",
        "Preload window: highest assembly preload",
        series=True,
        x="window_working_load",
    ),
)

# --------------------------------------------------------------------------- array path
#
# ``_vectorized`` gives what ``_compute`` gives, point by point, for a request whose numeric
# inputs may be arrays (a sweep, a study's chunk; issue 21/22). The text and choice inputs are
# fixed per request and read once; the bolt is resolved once per distinct bolt (usually
# once); every relation is the same function of engine.joint / engine.preload, called on
# arrays. A point the scalar compute refuses (InputOutOfRange, a division by zero) is NaN in
# every output and unreported in every check. Series (joint diagram, preload window) are
# not part of it: they belong to single runs.

#: Inputs that pick the thread from the tables (resolved per distinct combination).
_TABLE_KEYS = ("thread_diameter", "thread_pitch")

#: Bolt inputs resolve_bolt only copies into the bolt: when varied, left out of the
#: resolution and set per point (see :func:`_bolts`).
_GIVEN_KEYS = ("yield_strength", "bearing_outer_diameter", "hole_diameter")

#: Bolt fields carried as arrays ([m, m², Pa]).
_BOLT_FIELDS = (
    "diameter",
    "pitch",
    "pitch_diameter",
    "minor_diameter",
    "stress_diameter",
    "stress_area",
    "yield_strength",
    "bearing_outer_diameter",
    "hole_diameter",
)


def _size(x: Mapping[str, Any]) -> int:
    sizes = {v.shape[0] for v in x.values() if isinstance(v, np.ndarray) and v.ndim == 1}
    if len(sizes) > 1:
        raise ValueError(f"varied inputs of different lengths {sorted(sizes)}")
    return sizes.pop() if sizes else 1


def _bolts(
    x: Mapping[str, Any], n: int
) -> tuple[list[Bolt | None], np.ndarray, list[str], tuple[str, ...]]:
    """The distinct bolts of the request (None where resolve_bolt refuses), each point's
    index into them, the first point's notes, and the inputs left to :func:`_bolt_columns`.

    Only the inputs that pick a thread from the tables multiply the resolutions. A varied
    yield strength, bearing face or hole (values resolve_bolt only copies into the bolt) is
    left out of the resolution and set per point by :func:`_bolt_columns`, which refuses
    where resolve_bolt would; where leaving them out changes what resolve_bolt does (it
    refuses), they are resolved per distinct value instead. A refusal of every point raises.
    """
    fixed = {k: v for k, v in x.items() if not isinstance(v, np.ndarray)}
    table = [k for k in _TABLE_KEYS if isinstance(x.get(k), np.ndarray)]
    given = tuple(k for k in _GIVEN_KEYS if isinstance(x.get(k), np.ndarray))
    first = {**fixed, **{k: x[k][0].item() for k in (*table, *given)}}
    try:
        notes = resolve_bolt(first)[1]
    except EngineError:
        notes = []
    if given:
        found = _resolve_rows(x, fixed, table, n)
        if found is not None and all(b is not None for b in found[0]):
            bolts = [
                None
                if b is None
                else replace(b, tensile_strength=None)
                if "yield_strength" in given
                else b
                for b in found[0]
            ]
            return bolts, found[1], notes, given
    found = _resolve_rows(x, fixed, [*table, *given], n)
    if found is None:
        resolve_bolt(first)  # raises, says why
        raise AssertionError("unreachable")  # pragma: no cover
    return found[0], found[1], notes, ()


def _resolve_rows(
    x: Mapping[str, Any], fixed: Mapping[str, Any], keys: list[str], n: int
) -> tuple[list[Bolt | None], np.ndarray] | None:
    """resolve_bolt once per distinct combination of ``keys`` (None: every one refused)."""
    if not keys:
        try:
            return [resolve_bolt(fixed)[0]], np.zeros(n, dtype=np.int64)
        except EngineError:
            return None
    rows, index = np.unique(
        np.column_stack([np.asarray(x[k], dtype=float) for k in keys]),
        axis=0,
        return_inverse=True,
    )
    bolts: list[Bolt | None] = []
    for row in rows:
        try:
            bolts.append(resolve_bolt({**fixed, **dict(zip(keys, row.tolist(), strict=True))})[0])
        except EngineError:
            bolts.append(None)
    if all(b is None for b in bolts):
        return None
    return bolts, np.asarray(index, dtype=np.int64).reshape(n)


def _bolt_columns(
    bolts: list[Bolt | None], index: np.ndarray, x: Mapping[str, Any], given: tuple[str, ...]
) -> tuple[dict[str, Any], np.ndarray]:
    """Each bolt field per point (one bolt: numpy scalars, broadcast later), and the points
    refused: a bolt resolve_bolt refused, or (given values) d_h < d or D_f ≤ d_h."""
    if len(bolts) == 1 and bolts[0] is not None:
        columns: dict[str, Any] = {f: np.float64(getattr(bolts[0], f)) for f in _BOLT_FIELDS}
    else:
        columns = {
            f: np.array([np.nan if b is None else getattr(b, f) for b in bolts], dtype=float)[index]
            for f in _BOLT_FIELDS
        }
    for key in given:
        columns[key] = np.asarray(x[key], dtype=float)
    refused = np.zeros(index.size, dtype=bool) | np.isnan(columns["diameter"])
    if given:
        if x.get("hole_diameter") is not None:
            refused |= columns["hole_diameter"] < columns["diameter"]
        refused |= columns["bearing_outer_diameter"] <= columns["hole_diameter"]
    return columns, refused


def _vector_hook_checks(
    x: Mapping[str, Any],
    col: Callable[[str], np.ndarray],
    bolts: list[Bolt | None],
    index: np.ndarray,
    ok: np.ndarray,
    bearing: Any,
    hole: Any,
    fm_max: Any,
    f_s_max: Any,
    probe: Callable[[int], tuple[list[Check], list[str]]],
) -> tuple[dict[str, np.ndarray], list[str]]:
    """The verdicts of ``fz.joint_check_hook`` (VDI 2230-1 R10, R11, ISO 2936) on arrays.

    Which checks a bolt gets is fixed per request and bolt, so the scalar hook runs once
    per distinct bolt (``probe``: at its first computable point) for their names, its notes
    and its refusals; the verdicts are then the same comparisons as
    :func:`engine.models._fasteners.bought_part_checks`, on arrays. A check name this does
    not know raises TypeError (the caller loops instead).
    """
    n = index.size
    out: dict[str, np.ndarray] = {}
    notes: list[str] = []
    limit: Any = None
    if x.get("limiting_surface_pressure") is not None:
        limit = col("limiting_surface_pressure")
    elif x.get("clamped_material") is not None:
        limit = fa.material(str(x["clamped_material"])).limiting_surface_pressure
    tau: Any = None
    if x.get("internal_thread_shear_strength") is not None:
        tau = np.broadcast_to(col("internal_thread_shear_strength"), (n,))
    elif x.get("internal_thread_material") is not None:
        tau = np.full(n, fa.material(str(x["internal_thread_material"])).shear_strength)
    for k, bolt in enumerate(bolts):
        sel = ok & (index == k)
        if bolt is None or not sel.any():
            continue
        checks, said = probe(int(np.flatnonzero(sel)[0]))
        notes += [s for s in said if s not in notes]
        fastener = bolt.fastener or fz.Fastener("", None, None, None)
        outer, inner = bearing, hole
        if x.get("washer") is not None and fastener.thread is not None:
            w = fa.washer(str(x["washer"]), fastener.thread)
            outer, inner = w.outer_diameter, np.maximum(w.inner_diameter, hole)
        for check in checks:
            name = check.name
            if name in ("surface_pressure_assembly", "surface_pressure_working"):
                force = fm_max if name == "surface_pressure_assembly" else f_s_max
                verdict = _surface_pressure(force, outer, inner) <= limit
            elif name == "surface_pressure_nut" and fastener.thread is not None:
                nut = fa.nut(str(x["nut"]), fastener.thread)
                verdict = _surface_pressure(fm_max, nut.bearing_diameter, hole) <= limit
            elif (
                name == "thread_stripping" and tau is not None and bolt.tensile_strength is not None
            ):
                verdict = col("engagement_length") >= _min_engagement(bolt, tau, sel)
            elif name == "drive_torque" and fastener.head is not None:
                key = fa.hex_key_torque(fastener.head.drive_size)
                verdict = col("tightening_torque") <= (np.inf if key is None else key)
            else:
                raise TypeError(f"check hook gives {name!r}, which has no array form here")
            codes = out.setdefault(name, np.full(n, -1, dtype=np.int8))
            codes[sel] = np.asarray(verdict, dtype=np.int8)[sel] if np.ndim(verdict) else verdict
    return out, notes


def _surface_pressure(force: Any, outer: Any, inner: Any) -> Any:
    """:func:`engine.fasteners.surface_pressure` on arrays (the same expressions)."""
    area = np.maximum(0.0, 0.25 * math.pi * (outer**2 - inner**2))
    return np.where(area > 0, force / area, np.inf)


def _min_engagement(bolt: Bolt, tau: np.ndarray, sel: np.ndarray) -> np.ndarray:
    """Least length of engagement (VDI 2230-1 R11) per point, once per distinct τ_BM."""
    assert bolt.tensile_strength is not None
    result = np.full(tau.shape, np.nan)
    values, where = np.unique(tau[sel], return_inverse=True)
    lengths = [
        fa.thread_stripping(
            bolt.diameter,
            bolt.pitch,
            bolt.pitch_diameter,
            bolt.diameter - 1.082532 * bolt.pitch,
            bolt.stress_area,
            bolt.tensile_strength,
            fz.BOLT_SHEAR_RATIO * bolt.tensile_strength,
            t,
            1.0,
        ).min_engagement_length
        for t in values.tolist()
    ]
    result[sel] = np.asarray(lengths, dtype=float)[np.asarray(where).reshape(-1)]
    return result


def _vectorized(x: Mapping[str, Any], ctx: RunContext) -> Result:
    with np.errstate(all="ignore"):
        try:
            return _vector_solution(x, ctx)
        except (LookupError, AttributeError) as exc:
            # the array path is an optimisation, the scalar compute the reference: an input
            # combination it was not written for goes to the loop (points.vector on TypeError)
            raise TypeError(f"joint array path: {type(exc).__name__}: {exc}") from exc


def _vector_solution(x: Mapping[str, Any], ctx: RunContext) -> Result:
    for name in ("head", "joint_type", "surface_roughness", "method", "rolling", "controlled"):
        if isinstance(x.get(name), np.ndarray):
            raise TypeError(f"{name} is fixed per request on the array path")
    n = _size(x)

    def col(name: str) -> Any:
        """A varied input as a float array, a fixed one as a numpy scalar (broadcast later)."""
        value = x[name]
        if isinstance(value, np.ndarray):
            return value.astype(float, copy=False)
        return np.float64(value)

    def col_or(name: str, other: Any) -> Any:
        return other if x.get(name) is None else col(name)

    bolts, bolt_index, notes, given = _bolts(x, n)
    b, refused = _bolt_columns(bolts, bolt_index, x, given)
    warnings: list[str] = []
    joint_type = str(x["joint_type"])
    d, d_w, d_h, pitch = b["diameter"], b["bearing_outer_diameter"], b["hole_diameter"], b["pitch"]
    yield_strength, a_s = b["yield_strength"], b["stress_area"]

    # R0/R3 geometry (every plate present in the request; a 0 thickness adds exactly 0) ----------
    e1, a1 = col("plate1_youngs_modulus"), col("plate1_expansion")
    thick, moduli, alphas = [], [], []
    for i in range(1, MAX_PLATES + 1):
        if x.get(f"plate{i}_thickness") is None:
            continue
        thick.append(np.maximum(col(f"plate{i}_thickness"), 0.0))
        moduli.append(col_or(f"plate{i}_youngs_modulus", e1))
        alphas.append(col_or(f"plate{i}_expansion", a1))
    plates = sum((h > 0.0).astype(np.int64) for h in thick)
    grip = sum(thick)
    outer = None if x.get("outer_diameter") is None else col("outer_diameter")
    if outer is not None:
        refused |= outer < d_w * (1.0 - 1e-12)
    l_shank, l_reduced = col("shank_length"), col("reduced_length")
    refused |= l_shank + l_reduced > grip * (1.0 + 1e-12)
    if x.get("reduced_diameter") is None:
        refused |= l_reduced > 0.0
    shank_d, reduced_d = col_or("shank_diameter", d), col_or("reduced_diameter", d)
    for name, value in (("shank_diameter", shank_d), ("reduced_diameter", reduced_d)):
        if x.get(name) is not None:
            refused |= value > d * (1 + 1e-12)
    sections = [(l_shank, shank_d), (l_reduced, reduced_d)]
    free_thread = np.maximum(grip - l_shank - l_reduced, 0.0)
    e_s = col("youngs_modulus")
    bolt_c = jt.bolt_compliance(
        d,
        b["minor_diameter"],
        e_s,
        sections,
        free_thread,
        str(x["head"]),
        joint_type,
        None if x.get("nut_youngs_modulus") is None else col("nut_youngs_modulus"),
    )
    parts = jt.clamped_compliance(thick, moduli, d_w, d_h, outer, joint_type)
    delta_s, delta_p = bolt_c.total, parts.total
    phi_k = jt.load_factor(delta_s, delta_p, 1.0)
    phi_n = col("load_introduction") * phi_k
    if outer is None:
        notes.append("D_A not given: plates taken just wide enough for the full cone (D_A,Gr)")
    if np.any(~refused & (parts.tangent <= jt.MIN_CONE_TANGENT)):
        warnings.append(
            f"plates very thin against d_W: the cone tangent is held at {jt.MIN_CONE_TANGENT}"
        )

    # R2 required clamp force -----------------------------------------------------------------
    f_q, q_f, mu_t = col("transverse_load"), col("slip_interfaces"), col("interface_friction")
    f_kq = jt.transverse_clamp_force(f_q, q_f, mu_t)
    f_kerf = np.maximum(f_kq, col("sealing_clamp_force"))

    # R1 friction box, loads ------------------------------------------------------------------
    method = get_method(str(x["method"]))
    mu_g_lo, mu_k_lo = col("thread_friction_min"), col("bearing_friction_min")
    mu_g_hi = col_or("thread_friction_max", mu_g_lo)
    mu_k_hi = col_or("bearing_friction_max", mu_k_lo)
    refused |= (mu_g_hi < mu_g_lo) | (mu_k_hi < mu_k_lo)
    f_a = col("working_load")
    f_a_min = col_or("working_load_min", f_a)
    refused |= f_a_min > f_a

    # R4 losses --------------------------------------------------------------------------------
    through = joint_type == "through"
    roughness = str(x["surface_roughness"])
    faces, interfaces = (2, plates - 1) if through else (1, plates)
    f_z_len: Any = np.where(
        f_q > 0.0,
        jt.embedding(roughness, "transverse", faces, interfaces),
        jt.embedding(roughness, "axial", faces, interfaces),
    )
    f_z = jt.embedding_loss(f_z_len, delta_s, delta_p)
    dt_s = col("temperature_change")
    dt_p = col_or("plate_temperature_change", dt_s)
    alpha_len = sum(h * a for h, a in zip(thick, alphas, strict=True))

    # R7 permissible preload at the smallest section -------------------------------------------
    d0, where = jt.smallest_section(b["stress_diameter"], sections)
    a0: Any = np.where(where == "thread", a_s, 0.25 * math.pi * d0 * d0)
    nu = col("utilization")
    beta = pl.torsion_factor(pitch, b["pitch_diameter"], d0, mu_g_lo, "vdi2230")
    f_mzul = pl.assembly_preload(yield_strength, a0, beta, nu)
    f_myield = pl.assembly_preload(yield_strength, a0, beta, 1.0)

    # assembly preload range: torque specification or design at F_M,zul -----------------------
    def per_newton(mu_g: Any, mu_k: Any) -> tuple[np.ndarray, np.ndarray]:
        k_thread, k_bearing = pl.tightening_torque_per_preload(
            pitch, b["pitch_diameter"], d, mu_g, mu_k, d_w, d_h, "vdi2230"
        )
        return np.asarray(k_thread, dtype=float), np.asarray(k_bearing, dtype=float)

    kt_low, kb_low = per_newton(mu_g_lo, mu_k_lo)
    kt_high, kb_high = per_newton(mu_g_hi, mu_k_hi)
    k_low, k_high = kt_low + kb_low, kt_high + kb_high
    m_u = col("prevailing_torque")
    m_u_min = col_or("prevailing_torque_min", m_u)
    refused |= m_u_min > m_u
    torque_given = x.get("tightening_torque") is not None
    alpha_a: Any
    if torque_given:
        torque = col("tightening_torque")
        fm_min, fm_max = jt.preload_bounds_from_torque(
            torque, col("torque_tolerance"), m_u, k_low, k_high, m_u_min
        )
        alpha_a = np.where(fm_min > 0.0, fm_max / fm_min, np.inf)
        design_torque = torque
    else:
        alpha_a = np.broadcast_to(
            float(method.tightening_factor)
            if x.get("tightening_factor") is None
            else col("tightening_factor"),
            (n,),
        )
        fm_max = f_mzul
        fm_min = f_mzul / alpha_a
        design_torque = f_mzul * kt_low + f_mzul * kb_low + m_u
    f_v_min = fm_min - f_z
    th_loss = jt.thermal_preload_loss(
        f_v_min,
        grip,
        col("bolt_expansion"),
        dt_s,
        alpha_len,
        dt_p,
        delta_s,
        delta_p,
        col("bolt_modulus_ratio"),
        col("plate_modulus_ratio"),
    )

    # R5/R6 required window ------------------------------------------------------------------
    alpha_req = np.where(np.isfinite(alpha_a), alpha_a, method.tightening_factor)
    req_min = jt.minimum_assembly_preload(f_kerf, f_a, phi_n, f_z, th_loss)
    req_max = alpha_req * req_min
    loss = f_z + np.maximum(th_loss, 0.0)
    opens = 1.0 - phi_n > 0.0
    fa_limit = np.where(
        opens, np.maximum((f_mzul / alpha_req - f_kerf - loss) / (1.0 - phi_n), 0.0), np.inf
    )
    fa_sep_any = np.where(opens, np.maximum((f_mzul - loss) / (1.0 - phi_n), 0.0), np.inf)
    check_arrays: dict[str, Any] = {
        "R7_window_fits": req_max <= f_mzul * (1.0 + 1e-12),
        "separation_avoidable": f_a < fa_sep_any,
    }
    f_kr_min = fm_min - (1.0 - phi_n) * f_a - f_z - np.maximum(th_loss, 0.0)
    fa_sep = np.where(
        phi_n < 1.0,
        np.maximum(fm_min - f_z - np.maximum(th_loss, 0.0), 0.0) / (1.0 - phi_n),
        np.inf,
    )
    check_arrays["residual_clamp_force"] = f_kr_min >= f_kerf * (1.0 - 1e-12)
    if torque_given:
        check_arrays["R7_max_below_permissible"] = fm_max <= f_mzul * (1.0 + 1e-12)

    # R8 working stress -----------------------------------------------------------------------
    add_load = phi_n * f_a
    f_s_max = fm_max + add_load
    stress = jt.service_stress(f_s_max, fm_max, pitch, b["pitch_diameter"], d0, mu_g_lo)
    # the scalar path divides by σ_red,B (ZeroDivisionError) and squares in Python floats
    # (OverflowError): both refuse the point there
    tau_kept = jt.TORSION_REDUCTION_IN_SERVICE * stress.torsional
    refused |= stress.equivalent == 0.0
    refused |= np.isfinite(stress.axial) & ~np.isfinite(stress.axial**2)
    refused |= np.isfinite(tau_kept) & ~np.isfinite(tau_kept**2)
    s_f = yield_strength / stress.equivalent
    check_arrays["R8_working_stress"] = s_f >= 1.0

    # R9 alternating stress ----------------------------------------------------------------------
    sigma_a = phi_n * (f_a - f_a_min) / (2.0 * a_s)
    f_sm = fm_max + phi_n * 0.5 * (f_a + f_a_min)
    sigma_as = jt.endurance_limit(d, str(x["rolling"]), f_sm, a_s * yield_strength)
    alternating = sigma_a > 0.0
    s_d = np.where(alternating, sigma_as / sigma_a, np.inf)
    check_arrays["R9_fatigue"] = np.where(alternating, s_d >= 1.2, -1).astype(np.int8)

    # R12 slipping ---------------------------------------------------------------------------------
    slipping = f_q > 0.0
    s_g = np.where(slipping, f_kr_min * q_f * mu_t / f_q, np.inf)
    need = np.where(f_a_min < f_a, 1.8, 1.2)
    check_arrays["R12_slip"] = np.where(slipping, s_g >= need, -1).astype(np.int8)

    # [004] rules --------------------------------------------------------------------------------
    nominal = 0.5 * (fm_min + fm_max)
    sigma0 = nominal / a0
    ratio0 = sigma0 / yield_strength
    accurate = method.scatter <= 0.10 + 1e-12 and not torque_given
    if bool(x["bridge_joint"]):
        hi_rule = 0.9
    elif accurate:
        hi_rule = 0.7
    else:
        hi_rule = 0.5
    check_arrays["seed_004_preload_stress"] = ratio0 <= hi_rule + 1e-12
    if not bool(x["controlled"]) and np.any(~refused & (d < 0.010)):
        warnings.append(
            "d < 10 mm tightened without control: [004] warns of over-tightening; lower the "
            "admissible load or control the tightening"
        )

    # hooks (R10 surface pressure, R11 engagement) -------------------------------------------------
    def probe(j: int) -> tuple[list[Check], list[str]]:
        point = {k: (v[j].item() if isinstance(v, np.ndarray) else v) for k, v in x.items()}
        bolt = bolts[int(bolt_index[j])]
        assert bolt is not None

        def at(value: Any) -> float:
            return float(np.broadcast_to(value, (n,))[j])

        if given:
            bolt = replace(
                bolt,
                yield_strength=at(yield_strength),
                bearing_outer_diameter=at(d_w),
                hole_diameter=at(d_h),
            )
        solution = JointSolution(
            bolt, at(grip), at(d_w), at(d_h), at(fm_max), at(f_s_max), joint_type
        )
        return _scalar_hooks(point, solution)

    hook_checks, hook_notes = _vector_hook_checks(
        x, col, bolts, bolt_index, ~refused, d_w, d_h, fm_max, f_s_max, probe
    )
    notes += hook_notes

    angle = pl.nut_rotation_angle(nominal, delta_s + delta_p, pitch)
    rigid_angle = pl.nut_rotation_angle(nominal, delta_s, pitch)
    values: dict[str, Any] = {
        "tightening_factor": alpha_a,
        "required_clamp_force": f_kerf,
        "transverse_clamp_force": f_kq,
        "bolt_compliance": delta_s,
        "bolt_compliance_head": bolt_c.head,
        "bolt_compliance_shank": bolt_c.shank,
        "bolt_compliance_free_thread": bolt_c.free_thread,
        "bolt_compliance_engaged": bolt_c.engaged_thread + bolt_c.nut,
        "clamped_compliance": delta_p,
        "cone_tangent": parts.tangent,
        "cone_limit_diameter": parts.limit_diameter,
        "outer_diameter_used": parts.outer_diameter,
        "grip": grip,
        "load_factor_k": phi_k,
        "load_factor": phi_n,
        "additional_bolt_load": add_load,
        "clamp_load_reduction": (1.0 - phi_n) * f_a,
        "embedding_settlement": f_z_len,
        "embedding_loss": f_z,
        "thermal_loss": th_loss,
        "required_preload_min": req_min,
        "required_preload_max": req_max,
        "smallest_diameter": d0,
        "smallest_area": a0,
        "permissible_preload": f_mzul,
        "yield_preload": f_myield,
        "assembly_preload_min": fm_min,
        "assembly_preload_max": fm_max,
        "tightening_torque": design_torque,
        "residual_clamp_force_min": f_kr_min,
        "separation_load": fa_sep,
        "max_working_load": fa_limit,
        "max_bolt_force": f_s_max,
        "working_stress": stress.equivalent,
        "yield_safety": s_f,
        "stress_amplitude": sigma_a,
        "endurance_limit": sigma_as,
        "fatigue_safety": s_d,
        "slip_safety": s_g,
        "preload_stress_ratio": ratio0,
        "bolt_elongation": nominal * delta_s,
        "target_angle": angle,
        "rigid_joint_angle": rigid_angle,
    }
    if refused.all():
        # nothing to compute: the loop refuses each point with its reason (a 422 naming the
        # field where the sweep's every point is out)
        raise TypeError("every point is refused")
    # what the runner makes of a non-finite value (null) and of a refused point (all null)
    table = np.empty((len(values), n))
    for row, value in zip(table, values.values(), strict=True):
        row[...] = value
    table[~np.isfinite(table)] = np.nan
    any_refused = bool(refused.any())
    if any_refused:
        table[:, refused] = np.nan
    values = dict(zip(values, table, strict=True))
    check_arrays.update(hook_checks)
    reported: dict[str, Any] = {}
    for name, verdict in check_arrays.items():
        codes = np.empty(n, dtype=np.int8)
        codes[...] = verdict
        if any_refused:
            codes[refused] = -1
        if (codes >= 0).any():  # a check no point reports is not in the scalar answers either
            reported[name] = codes
    return Result(
        values=values,
        rung=ctx.rung,
        error_estimate=0.0,
        notes=notes,
        warnings=warnings,
        check_arrays=reported,
    )


def _scalar_hooks(x: Mapping[str, Any], solution: JointSolution) -> tuple[list[Check], list[str]]:
    checks: list[Check] = []
    notes: list[str] = []
    for hook in CHECK_HOOKS:
        if hook not in VECTOR_CHECK_HOOKS:
            raise TypeError(f"check hook {hook!r} has no array form")
        more_checks, more_notes = hook(x, solution)
        checks += more_checks
        notes += more_notes
    return checks, notes


#: The hooks whose checks :func:`_vector_hook_checks` knows on arrays; another hook in
#: :data:`CHECK_HOOKS` sends the request to the per-point loop.
VECTOR_CHECK_HOOKS: tuple[CheckHook, ...] = (fz.joint_check_hook,)


CLOSED_FORM = Rung(
    "closed_form",
    "The VDI 2230-1 calculation steps in closed form (cone/sleeve integrals, no iteration "
    "beyond the D_A fixed point)",
    fixed_error(0.0),
    typical_error="exact for the model; the model's own error (cone fit, friction) dominates",
    typical_time="< 1 ms",
)

VDI2230 = ModelSpec(
    name="joint.vdi2230",
    title="Bolted joint: stiffness, service loads, losses and the preload window (VDI 2230)",
    family="joint",
    summary=(
        "A single bolted joint through VDI 2230 Part 1: bolt and clamped-part compliance "
        "(cone and sleeve, several plates), load factor, working and transverse loads, "
        "embedding and thermal losses, the required preload window against the permissible "
        "preload at the smallest section, the preload range a torque specification gives "
        "over the friction box, working and alternating stress, slipping, and the joint "
        "diagram."
    ),
    source=SOURCE,
    inputs=JOINT_INPUTS,
    outputs=JOINT_OUTPUTS,
    rungs=(CLOSED_FORM,),
    compute=_compute,
    vectorized=_vectorized,
    vector_rungs=("closed_form",),
    assumptions=(
        "VDI 2230-1's text was not available to us: its relations as reproduced in "
        "ECSS-E-HB-32-23A and implemented in misams/BAT (docs/sources.md)",
        "concentric clamping and loading (no bending, Φ_en = Φ_n); the nut's bearing face as "
        "large as the head's",
    ),
    examples=(
        # M12 8.8 through 2 × 20 mm steel, 8 kN alternating 0…8 kN, 2 kN transverse
        {
            "thread_diameter": 0.012,
            "plate1_thickness": 0.020,
            "plate2_thickness": 0.020,
            "working_load": 8e3,
            "working_load_min": 0.0,
            "transverse_load": 2e3,
        },
        # the question users bring: 80 N·m ± 5 %, μ 0.08…0.16, 0.4 N·m prevailing torque
        {
            "thread_diameter": 0.012,
            "plate1_thickness": 0.020,
            "plate2_thickness": 0.020,
            "tightening_torque": 80.0,
            "torque_tolerance": 0.05,
            "prevailing_torque": 0.4,
            "thread_friction_min": 0.08,
            "thread_friction_max": 0.16,
            "bearing_friction_min": 0.08,
            "bearing_friction_max": 0.16,
            "working_load": 10e3,
        },
        # waisted M12 8.8 screwed into aluminium
        {
            "thread_diameter": 0.012,
            "joint_type": "tapped",
            "head": "socket",
            "bearing_outer_diameter": 0.0173,
            "plate1_thickness": 0.060,
            "reduced_length": 0.050,
            "reduced_diameter": 0.0075,
            "nut_youngs_modulus": 7e10,
            "working_load": 5e3,
        },
        # bought parts (issue 15): socket-head M8 12.9 into aluminium, 12 mm of thread
        {
            "thread": "M8 ISO 4762 12.9",
            "joint_type": "tapped",
            "head": "socket",
            "plate1_thickness": 0.012,
            "plate1_youngs_modulus": 7e10,
            "nut_youngs_modulus": 7e10,
            "working_load": 4e3,
            "washer": "ISO 7089",
            "clamped_material": "EN AW-6082 T6",
            "internal_thread_material": "EN AW-6082 T6",
            "engagement_length": 0.012,
        },
    ),
)
