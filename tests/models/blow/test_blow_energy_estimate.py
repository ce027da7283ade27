"""The energy rung's error estimate against the simulation over random designs (issue 29).

The estimate (engine.physics.blow.energy_blow_error) is labelled typical, not a bound: a nut that
sticks again within a blow needs b·T_j to move on, which it does not follow. Here its
measured share exceeded is held to what the label states (3–4 %, at most 6 % allowed
for the sample), and the breakaway's term must lower it against the estimate without it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from engine.physics.blow import BlowProblem, energy_blow, energy_blow_error, simulate_blow


def _sample(seed: int, n: int) -> np.ndarray:
    """(error, estimate, estimate without the breakaway term) of the first blow's joint torque."""
    rng = np.random.default_rng(seed)

    def lu(a: float, b: float) -> float:
        return float(np.exp(rng.uniform(math.log(a), math.log(b))))

    rows: list[tuple[float, float, float]] = []
    while len(rows) < n:
        e, jt, c, js = lu(1.0, 300.0), lu(1e-3, 0.1), lu(2e3, 1e5), lu(1e-5, 3e-3)
        b, rest, k = rng.uniform(1.0, 3.0), rng.uniform(0.14, 1.0), lu(30.0, 3e4)
        t0 = rng.uniform(0.0, 0.8) * math.sqrt(2.0 * e * c) / b  # a nut that turns
        sim = simulate_blow(BlowProblem(jt, js, c, math.sqrt(2.0 * e / jt), k, b, 0.0, rest), t0)
        _, after, rot, _ = energy_blow(e, c, k, t0, b)
        if rot <= 0.0 or sim.rotation <= 0.0:
            continue
        rows.append(
            (
                abs(sim.torque_after / after - 1.0),
                energy_blow_error(jt, js, c, k, rest, b, t0, e),
                energy_blow_error(jt, js, c, k, rest),
            )
        )
    return np.array(rows)


@pytest.mark.slow
def test_the_energy_estimate_is_exceeded_as_rarely_as_its_label_says() -> None:
    r = _sample(3, 400)
    exceeded = float(np.mean(r[:, 0] > r[:, 1]))
    without = float(np.mean(r[:, 0] > r[:, 2]))
    assert exceeded <= 0.06, exceeded  # measured 15 of 400 (3.75 %)
    assert without > exceeded  # measured 34 of 400 without the breakaway's jump
    assert float(np.max(r[:, 0] / r[:, 1])) < 15.0  # measured 10.1
    # the breakaway term only adds (it is 0 at b = 1 or T_0 = 0)
    assert np.all(r[:, 1] >= r[:, 2])
