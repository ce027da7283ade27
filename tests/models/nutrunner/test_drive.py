"""The nut-runner drive model [000]: hand-computed cases, rung agreement, invariants.

The reference design is ``EXAMPLE_LIGHT_TRUCK`` (illustrative: the source gives
no worked numbers): P = 1.1 kW, ω = 1400 rpm, coupling 1.2 kg / 90 mm, pulley
0.8 kg / 80 mm, flywheel 12 kg / 250 mm, drive gear 2.5 kg / 100 mm, six
spindle gears 0.5 kg / 50 mm, shaft 45 × 200 mm, spindles 32 × 300 mm,
G = 80 GPa, M_tr = 10 N·m.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from engine import InfeasibleDesign, InputOutOfRange, RunContext, run, sweep
from engine.models.nutrunner import EXAMPLE_INDUCTION_MOTOR, EXAMPLE_LIGHT_TRUCK, NUTRUNNER_DRIVE
from engine.physics.nutrunner import (
    impact_torque,
    impact_torque_geared,
    kinetic_energy,
    max_spindle_torque,
    part_energies,
    torsional_stiffness,
)

SPEC = NUTRUNNER_DRIVE
BASE = EXAMPLE_LIGHT_TRUCK
W = 1400 * math.pi / 30  # 146.6077 rad/s

# Hand arithmetic for BASE (closed_form):
#   J1 = 1.2·0.09²/8 = 0.001215, J2 = 0.8·0.08²/8 = 0.00064,
#   J3 = 12·0.25²/8 = 0.09375,  J4 = 2.5·0.1²/8 = 0.003125, J5 = 0.5·0.05²/8 = 1.5625e-4
#   belt ratio D2/D3 = 0.32 (squared 0.1024), gear ratio u = D4/D5 = 2 (squared 4)
#   J_eq = 0.001215 + 0.00064 + 0.1024·(0.09375 + 0.003125) + 6·1.5625e-4·0.1024·4
#        = 0.001855 + 0.00992 + 0.000384 = 0.012159 kg·m²
J_EQ = 0.012159
T_HAND = 0.5 * J_EQ * W**2  # = 130.6716 J
#   C7 = π·8e10·0.045⁴/(32·0.2) = 161 031.2 N·m/rad, C8 = π·8e10·0.032⁴/(32·0.3) = 27 451.7
C7 = math.pi * 8e10 * 0.045**4 / 6.4
C8 = math.pi * 8e10 * 0.032**4 / 9.6
#   M = √(2·130.67·C7·C8/(C7 + C8)) = √(261.343·23 453.5) = 2475.76 N·m
#   M(u = 2) = √(261.343 / (4/C7 + 1/C8)) = √(261.343·16 321.8) = 2065.33 N·m


def test_closed_form_by_hand():
    r = run(SPEC, BASE)
    assert r.rung == "closed_form"  # no fidelity given: the paper's model runs
    v = r.results
    assert pytest.approx(130.6716, rel=1e-6) == T_HAND
    assert v["kinetic_energy"] == pytest.approx(T_HAND, rel=1e-12)
    assert v["equivalent_inertia"] == pytest.approx(J_EQ, rel=1e-12)
    assert v["acceleration_time"] == pytest.approx(T_HAND / 1100.0, rel=1e-12)  # 0.118792 s
    assert v["acceleration_time"] == pytest.approx(0.118792, rel=1e-5)
    assert v["shaft_stiffness"] == pytest.approx(161031.17, rel=1e-7)
    assert v["spindle_stiffness"] == pytest.approx(27451.655, rel=1e-7)
    assert v["impact_torque"] == pytest.approx(2475.762, rel=1e-6)
    assert v["shaft_torque"] == v["impact_torque"]
    assert v["max_spindle_torque"] == pytest.approx(2475.762 - 5 * 10.0, rel=1e-6)
    assert v["shaft_twist"] == pytest.approx(2475.762 / C7, rel=1e-6)  # 0.01537 rad
    assert v["spindle_twist"] == pytest.approx(2475.762 / C8, rel=1e-6)  # 0.09019 rad
    # per-part energies: T_k = J_k ω_k²/2
    assert v["coupling_energy"] == pytest.approx(0.5 * 0.001215 * W**2, rel=1e-12)  # 13.06 J
    # J2 ω²/2 = 0.00032·146.6077² = 6.87802 J; J4 (0.32 ω)²/2 = 0.0015625·46.9145² = 3.43901 J
    assert v["motor_pulley_energy"] == pytest.approx(6.87802, rel=1e-6)
    assert v["drive_gear_energy"] == pytest.approx(3.43901, rel=1e-6)
    assert v["flywheel_energy"] == pytest.approx(0.5 * 0.09375 * (0.32 * W) ** 2, rel=1e-12)
    assert v["spindle_gears_energy"] == pytest.approx(6 * 0.5 * 1.5625e-4 * (0.64 * W) ** 2)
    assert v["flywheel_speed"] == pytest.approx(0.32 * W) and v["spindle_gear_speed"] == (
        pytest.approx(0.64 * W)
    )
    parts = ("coupling", "motor_pulley", "flywheel", "drive_gear", "spindle_gears")
    assert sum(v[f"{p}_energy"] for p in parts) == pytest.approx(v["kinetic_energy"], rel=1e-14)
    assert v["gear_ratio"] == 2.0
    # τ = 16 M/(π d³): spindle 16·2475.76/(π·0.032³) = 384.8 MPa
    assert v["spindle_shear_stress"] == pytest.approx(384.79e6, rel=1e-4)
    # the source's shaft carries M too: 16·2475.762/(π·0.045³) = 138.370 MPa
    assert v["shaft_shear_stress"] == pytest.approx(138.370e6, rel=1e-5)
    # coupling 1 without a start torque: K P/ω = 2·1100/146.6077 = 15.00604 N·m
    assert v["coupling_slip_torque"] == pytest.approx(15.00604, rel=1e-6)
    # the estimate is the largest change the gear ratio makes to any output, either way
    # round: the shaft torque, u·M(u)/M = 2·(1 − 0.16578) = 1.66844, i.e. 0.668
    assert r.error_estimate == pytest.approx(2 * (1 + v["gear_ratio_torque_change"]) - 1)
    assert r.error_estimate == pytest.approx(0.668443, rel=1e-5)
    assert any("gear ratio u = D4/D5 = 2" in n for n in r.notes)
    assert all(c.ok for c in r.checks)


def test_gear_ratio_by_hand():
    v = run(SPEC, BASE, fidelity="gear_ratio").results
    # M = √(2T/(u²/C7 + 1/C8)), u = 2: √(261.343·16 321.8) = 2065.33 N·m
    m = math.sqrt(2 * T_HAND / (4 / C7 + 1 / C8))
    assert m == pytest.approx(2065.33, rel=1e-5)
    assert v["impact_torque"] == pytest.approx(m, rel=1e-12)
    assert v["shaft_torque"] == pytest.approx(2 * m, rel=1e-12)
    assert v["shaft_twist"] == pytest.approx(2 * m / C7, rel=1e-12)
    # τ7 = 16 u M/(π d7³) = 16·2·2065.33/(π·0.045³) = 230.86 MPa; τ8 = 16 M/(π d8³) = 321.0 MPa
    assert v["shaft_shear_stress"] == pytest.approx(16 * 2 * m / (math.pi * 0.045**3), rel=1e-12)
    assert v["shaft_shear_stress"] == pytest.approx(230.86e6, rel=1e-4)
    assert v["spindle_shear_stress"] == pytest.approx(321.0e6, rel=1e-3)
    assert v["gear_ratio_torque_change"] == pytest.approx(2065.33 / 2475.762 - 1, rel=1e-5)
    # the energy stored in the twist is the kinetic energy, with u·M on the shaft
    stored = 0.5 * v["shaft_torque"] * v["shaft_twist"] + 0.5 * m * v["spindle_twist"]
    assert stored == pytest.approx(v["kinetic_energy"], rel=1e-12)
    # the spin-up time does not depend on the torque model
    assert v["acceleration_time"] == pytest.approx(T_HAND / 1100.0, rel=1e-12)


def test_paper_energy_balance_closes():
    """[000, eq. 7]: T = M φ7/2 + M φ8/2 with the same M on both."""
    v = run(SPEC, BASE).results
    m = v["impact_torque"]
    assert 0.5 * m * (v["shaft_twist"] + v["spindle_twist"]) == pytest.approx(
        v["kinetic_energy"], rel=1e-12
    )


@pytest.mark.parametrize("d", [0.01, 0.05, 0.3])
def test_rungs_agree_when_gear_ratio_is_one(d):
    x = {**BASE, "drive_gear_diameter": d, "spindle_gear_diameter": d}
    a = run(SPEC, x, fidelity="closed_form")
    b = run(SPEC, x, fidelity="gear_ratio")
    for name in ("impact_torque", "max_spindle_torque", "shaft_twist", "acceleration_time"):
        assert a.results[name] == pytest.approx(b.results[name], rel=1e-14)
    assert a.results["gear_ratio_torque_change"] == pytest.approx(0.0, abs=1e-15)
    # so auto takes the cheapest rung
    assert run(SPEC, x, fidelity="auto").rung == "closed_form"


def test_auto_without_motor_curve_uses_gear_ratio_when_u_matters():
    r = run(SPEC, BASE, fidelity="auto")
    # closed_form estimate = shaft torque change u·M(u)/M − 1 = 66.8 % > 1 %; no motor curve
    assert r.rung == "gear_ratio"
    assert "closed_form 0.67" in r.notes[0]


def test_gear_ratio_moves_torque_down_when_u_above_one_and_up_below():
    up = run(SPEC, {**BASE, "drive_gear_diameter": 0.025}, fidelity="gear_ratio").results
    down = run(SPEC, BASE, fidelity="gear_ratio").results
    assert up["gear_ratio_torque_change"] > 0 > down["gear_ratio_torque_change"]


@pytest.mark.parametrize("k", [0.1, 2.0, 10.0])
def test_time_scales_with_speed_squared_and_torque_with_sqrt_energy(k):
    a = run(SPEC, BASE).results
    b = run(SPEC, {**BASE, "motor_speed": k * W}).results
    assert b["acceleration_time"] / a["acceleration_time"] == pytest.approx(k**2, rel=1e-12)
    assert b["kinetic_energy"] / a["kinetic_energy"] == pytest.approx(k**2, rel=1e-12)
    # M ∝ √T ∝ ω
    assert b["impact_torque"] / a["impact_torque"] == pytest.approx(k, rel=1e-12)
    # scaling every mass by k scales T by k, M by √k
    masses = [n for n in BASE if n.endswith("_mass")]
    c = run(SPEC, {**BASE, **{n: k * BASE[n] for n in masses}}).results
    assert c["impact_torque"] / a["impact_torque"] == pytest.approx(math.sqrt(k), rel=1e-12)


def test_eq5_reduces_when_all_ratios_are_one():
    """[000, eq. 3–5] as reconstructed (docs/sources.md).

    With D2 = D3 and D4 = D5, t = ω²/(16P)·Σ m_k D_k² (z·m5).
    """
    x = {**BASE, "flywheel_diameter": 0.08, "spindle_gear_diameter": 0.1}
    v = run(SPEC, x).results
    ms = 1.2 * 0.09**2 + 0.8 * 0.08**2 + 12 * 0.08**2 + 2.5 * 0.1**2 + 6 * 0.5 * 0.1**2
    assert v["acceleration_time"] == pytest.approx(W**2 / (16 * 1100) * ms, rel=1e-12)


def test_max_spindle_torque_never_exceeds_impact_torque():
    for m_tr in (0.0, 1.0, 100.0, 1e4):
        for z in (1, 2, 6, 32):
            v = run(SPEC, {**BASE, "idle_spindle_friction_torque": m_tr, "spindle_count": z})
            assert v.results["max_spindle_torque"] <= v.results["impact_torque"]
    # one spindle: no idle friction at all
    v = run(SPEC, {**BASE, "spindle_count": 1, "idle_spindle_friction_torque": 500.0}).results
    assert v["max_spindle_torque"] == v["impact_torque"]


def test_friction_that_absorbs_the_blow_warns_and_fails_a_check():
    # M = 2475.76 N·m, 5 idle spindles: M_tr = 600 N·m takes 3000 N·m
    r = run(SPEC, {**BASE, "idle_spindle_friction_torque": 600.0})
    assert r.results["max_spindle_torque"] == pytest.approx(2475.762 - 3000.0, rel=1e-6)
    (check,) = [c for c in r.checks if c.name == "max_spindle_torque_positive"]
    assert not check.ok
    assert "absorbs the whole" in check.detail and "495.2 N*m per spindle" in check.detail
    assert any("no torque reaches the nut" in w for w in r.warnings)


def test_spindle_gear_overlap_check():
    # z = 12 gears of 80 mm on a (100 + 80) mm circle: pitch 180·sin(15°) = 46.6 mm < 80 mm
    r = run(SPEC, {**BASE, "spindle_count": 12, "spindle_gear_diameter": 0.08})
    (check,) = [c for c in r.checks if c.name == "spindle_gears_fit"]
    assert not check.ok and "overlap" in check.detail
    assert "46.59 mm apart on the 180 mm circle" in check.detail
    # the example's six 50 mm gears on a 150 mm circle: 150·sin(30°) = 75 mm > 50 mm
    (fits,) = [c for c in run(SPEC, BASE).checks if c.name == "spindle_gears_fit"]
    assert fits.ok and "75 mm apart" in fits.detail


def test_yield_check_only_when_strength_given():
    names = {c.name for c in run(SPEC, BASE).checks}
    assert "spindle_elastic" not in names
    r = run(SPEC, {**BASE, "shear_yield_strength": 300e6})
    checks = {c.name: c for c in r.checks}
    assert checks["shaft_elastic"].ok  # 138 MPa
    assert not checks["spindle_elastic"].ok and "yields" in checks["spindle_elastic"].detail


def test_constant_power_series_is_square_root_in_time():
    r = run(SPEC, BASE, outputs=["time", "motor_speed_curve", "flywheel_speed_curve"])
    t = np.array(r.series["time"])
    w = np.array(r.series["motor_speed_curve"])
    assert r.results == {}
    assert t[-1] == pytest.approx(T_HAND / 1100.0) and w[-1] == pytest.approx(W)
    np.testing.assert_allclose(w, W * np.sqrt(t / t[-1]), rtol=1e-12)
    np.testing.assert_allclose(r.series["flywheel_speed_curve"], 0.32 * w, rtol=1e-12)
    assert run(SPEC, BASE, outputs=["impact_torque"]).series == {}


def test_public_functions_match_the_model():
    e = part_energies(
        W, 1.2, 0.09, 0.8, 0.08, 12.0, 0.25, 2.5, 0.1, 0.5, 0.05, 6
    )  # same design as BASE
    assert sum(e) == pytest.approx(T_HAND, rel=1e-12)
    assert kinetic_energy(W, 1.2, 0.09, 0.8, 0.08, 12.0, 0.25, 2.5, 0.1, 0.5, 0.05, 6) == (
        pytest.approx(T_HAND, rel=1e-12)
    )
    assert torsional_stiffness(8e10, 0.045, 0.2) == pytest.approx(C7)
    assert impact_torque_geared(T_HAND, C7, C8, 1.0) == pytest.approx(impact_torque(T_HAND, C7, C8))
    assert max_spindle_torque(100.0, 1, 1e9) == 100.0


def test_vectorized_matches_scalar_on_a_log_grid():
    d = np.logspace(-3, 0, 25)
    for rung in ("closed_form", "gear_ratio"):
        s = sweep(SPEC, BASE, "spindle_diameter", d.tolist(), fidelity=rung)
        assert s.rung == rung
        for i in (0, 7, 24):
            p = run(SPEC, {**BASE, "spindle_diameter": float(d[i])}, fidelity=rung).results
            for name in ("impact_torque", "spindle_twist", "max_spindle_torque"):
                assert s.results[name][i] == pytest.approx(p[name], rel=1e-12)


def test_vectorized_sweep_over_spindle_count_is_integer_and_monotone():
    s = sweep(SPEC, BASE, "spindle_count", [1, 2, 4, 8, 16])
    t = s.results["kinetic_energy"]
    assert all(np.diff(t) > 0)


def test_sweep_warns_when_friction_absorbs_blow():
    s = sweep(SPEC, BASE, "idle_spindle_friction_torque", [0.0, 100.0, 1000.0])
    assert s.results["max_spindle_torque"][2] < 0
    assert any("absorbs the whole" in w and "blow" in w for w in s.warnings)


def test_errors_name_the_field():
    with pytest.raises(InputOutOfRange) as e:
        run(SPEC, {**BASE, "spindle_diameter": 0.0})
    assert e.value.field == "spindle_diameter"
    with pytest.raises(InputOutOfRange) as e:
        run(SPEC, {k: v for k, v in BASE.items() if k != "motor_power"})
    assert e.value.field == "motor_power"
    with pytest.raises(InputOutOfRange) as e:
        run(SPEC, BASE, fidelity="motor_curve")
    assert e.value.field == "motor_curve" and "needs a torque–speed curve" in e.value.message


def test_motor_that_never_reaches_speed_is_infeasible():
    x = {**BASE, "motor_curve": "linear", "stall_torque": 30.0, "no_load_speed": 140.0}
    with pytest.raises(InfeasibleDesign, match="can never reach the working speed"):
        run(SPEC, x, fidelity="motor_curve")
    # auto: the constant-power rungs are marked 100 % off, so the motor rung runs and refuses
    with pytest.raises(InfeasibleDesign):
        run(SPEC, x, fidelity="auto")
    # the paper's rung still runs (it knows no motor curve)
    assert run(SPEC, x).rung == "closed_form"


def test_examples_are_complete_and_valid():
    for example in SPEC.examples:
        r = run(SPEC, example, fidelity="auto")
        assert all(v is not None for v in r.results.values())
    assert run(SPEC, EXAMPLE_INDUCTION_MOTOR, fidelity="auto").rung == "motor_curve"


def test_vectorized_large_array_is_finite_and_broadcast():
    """The array form behind sweeps: 10⁵ points over four decades of spindle diameter."""
    x, _ = SPEC.validate(BASE)
    d = np.geomspace(1e-4, 2.0, 100_000)
    names = frozenset(o.name for o in SPEC.outputs if not o.series)
    assert SPEC.vectorized is not None
    r = SPEC.vectorized({**x, "spindle_diameter": d}, RunContext("gear_ratio", names, 0.01))
    assert set(r.values) == names - {
        "drive_inertia",
        "constant_power_time",
        "time_vs_constant_power",
    }
    for name, value in r.values.items():
        arr = np.broadcast_to(np.asarray(value, dtype=float), d.shape)
        assert np.all(np.isfinite(arr)), name
    m = np.asarray(r.values["impact_torque"])
    assert np.all(np.diff(m) > 0)  # a stiffer spindle takes a larger torque
