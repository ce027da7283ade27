"""A one-blow series on arrays that works out only the fields asked for equals the loop's."""

from __future__ import annotations

import math

import numpy as np

from engine.physics.blow import BlowProblem, blow_series, energy_blow

FIELDS = (
    "peak",
    "rotation",
    "torque_after",
    "work",
    "final_torque",
    "joint_work",
    "blows",
    "blows_to_target",
    "saturated",
    "yield_blow",
    "elastic_demand",
)


def _designs() -> tuple[BlowProblem, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(35)
    size = 400
    rate = rng.uniform(-200.0, 3000.0, size)  # some flat joints (k_j <= 0)
    p = BlowProblem(
        0.02,
        1e-3,
        rng.uniform(5e3, 3e4, size),
        rng.uniform(10.0, 120.0, size),
        rate,
        rng.uniform(1.0, 1.6, size),
        rng.uniform(0.0, 20.0, size),
    )
    return p, rng.uniform(0.0, 200.0, size), rng.uniform(150.0, 900.0, size)


def test_each_field_alone_is_the_loops() -> None:
    p, t0, ty = _designs()
    loop = blow_series(p, t0, "energy", target_torque=400.0, max_blows=1, yield_torque=ty)
    for name in FIELDS:
        lean = blow_series(
            p, t0, "energy", target_torque=400.0, max_blows=1, yield_torque=ty, need=(name,)
        )
        want, got = getattr(loop, name), getattr(lean, name)
        assert got.dtype == want.dtype, name
        assert np.array_equal(got, want, equal_nan=want.dtype.kind == "f"), name
        assert all(getattr(lean, o) is None for o in FIELDS if o != name)


def test_the_first_blows_torques_by_hand() -> None:
    """E = ½·0.02·100² = 100 J, C = 2e4, k_j = 1000, T_0 = 60 N·m, N = 0, b = 1:
    T = √((100 + 60²/2000)/(½(1/2e4 + 1/1000))) = √(101.8/5.25e-4) = 440.346 N·m; on a
    flat joint (k_j = 0) the nut turns at T_0 = 60 N·m, which is the torque after it."""
    p = BlowProblem(0.02, 1e-3, 2.0e4, 100.0, np.array([1000.0, 0.0]), 1.0)
    s = blow_series(p, 60.0, "energy", max_blows=1, need=("peak", "torque_after"))
    assert math.isclose(s.torque_after[0], math.sqrt(101.8 / 5.25e-4), rel_tol=1e-15)
    assert s.torque_after[1] == 60.0 and s.peak[1] == 60.0
    assert s.rotation is None and s.work is None


def test_energy_blow_without_motion_keeps_the_torques() -> None:
    p, t0, _ = _designs()
    args = (p.energy, p.stiffness, p.rate, t0, p.breakaway, p.drive_torque)
    both, torques = energy_blow(*args), energy_blow(*args, motion=False)
    for want, got in zip(both[:2], torques[:2], strict=True):
        assert np.array_equal(got, want, equal_nan=True)
    assert torques[2:] == (None, None)


def test_a_sweep_asking_the_time_between_blows_stays_on_the_array_path() -> None:
    """The time between blows is a first-blow output; the time to the final torque is the
    whole series'. A sweep asking the former with the first blow's numbers runs on arrays
    (its note says so) and gives the loop's values: asking it once made the one-blow path
    read the series' blow count it leaves out, and every point ran one at a time."""
    import engine

    spec = engine.get_model("blow.joint")
    example = spec.examples[1]
    base = spec.validate(dict(example))[0]
    name = "flywheel_diameter" if base.get("flywheel_diameter") else "struck_inertia"
    values = np.linspace(base[name] * 0.8, base[name] * 1.2, 7)
    asked = ["peak_torque", "blows_per_second", "blow_interval"]
    swept = engine.sweep(spec, example, name, values, fidelity="energy", outputs=asked)
    assert any("evaluated on arrays" in n for n in swept.notes)
    for j in (0, 6):
        one = engine.run(spec, {**example, name: float(values[j])}, fidelity="energy")
        for o in asked:
            assert swept.columns[o][j] == one.results[o]
    interval = np.asarray(swept.columns["blow_interval"], dtype=float)
    assert np.allclose(np.asarray(swept.columns["blows_per_second"], dtype=float) * interval, 1.0)
