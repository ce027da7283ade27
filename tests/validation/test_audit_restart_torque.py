"""joint.audit's reading against a published restart torque [Bickford].

Tank-tread end-connector bolts, 5/8-18 UNF Grade 8: tightened with 150 lb·ft to a stretch
of 0.0015 in, the joint relaxed to a stretch of 0.001 in, and "it took only 100 lb-ft to
restart the nut". The preload follows the stretch (F = stretch/compliance), so a third of it
was lost; restarted in the tightening direction with no static excess (r = 1) the reading is
the tightening torque times what is left: 150 · 0.001/0.0015 = 100 lb·ft.
"""

from __future__ import annotations

import pytest

from engine.physics import audit as au

LBFT = 1.3558179483314004  # N·m per lb·ft
INCH = 0.0254


@pytest.mark.parametrize("mu", [0.10, 0.15, 0.20])
def test_restart_torque_of_the_relaxed_tank_tread_bolt(mu: float) -> None:
    pitch = INCH / 18
    d2 = (0.625 - 0.649519 / 18) * INCH  # ASME B1.1 basic pitch diameter
    bearing = 0.25 * (0.9375 + 0.656) * INCH  # D_Km/2 of a 15/16 in hex on a 0.656 in hole
    k_p = float(au.pitch_torque_per_preload(pitch, d2))
    k_mu = 0.58 * d2 * mu + mu * bearing
    torque = 150.0 * LBFT
    preload = torque / (k_p + k_mu)
    lost = preload * (1.0 - 0.001 / 0.0015)  # the stretch fell from 0.0015 to 0.001 in
    restart = au.audit_torque(torque, 0.0, k_p, k_mu, 1.0, lost, au.TIGHTENING)
    # the published 100 lb·ft, whatever the friction (it cancels at r = 1)
    assert float(restart) / LBFT == pytest.approx(100.0, rel=1e-12)
