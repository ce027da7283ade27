"""ISO 898-1 proof loads and minimum ultimate tensile loads, coarse thread M8–M24.

Source: ISO 898-1:2013, Table 5 (minimum ultimate tensile loads A_s,nom × R_m,min) and Table 7
(proof loads A_s,nom × S_p,nom), coarse thread, as reproduced by Optimas ("ISO Metric Pitch
Thread Proof Loads, according to EN ISO 898-1") and usefastener.com ("Minimum ultimate tensile
loads for metric coarse pitch thread, EN ISO 898-1"). The printed loads use the rounded
tabulated stress area (84.3 mm² for M12) and three significant figures; the engine computes
A_s = π/4 ((d2 + d3)/2)² exactly. Every cell agrees within 0.5 % plus half a unit of the
printed third digit; the only one that needs the second part is M14 12.9, 140 000 N printed
for 115 mm² × 1220 MPa = 140 300 N (we compute 115.4 mm², 140 830 N: +0.59 %).

The proof stresses S_p,nom are ISO 898-1 Table 3's (8.8: 580 MPa up to M16, 600 MPa above;
10.9: 830 MPa; 12.9: 970 MPa); the engine holds R_m,min per class, not S_p.
"""

import pytest

from engine.physics import threads as th

PROOF_STRESS_MPA = {"8.8": (580.0, 600.0), "10.9": (830.0, 830.0), "12.9": (970.0, 970.0)}

# d [mm]: {class: (proof load N, minimum ultimate tensile load N)} as printed
ISO_898_1 = {
    8: {"8.8": (21200, 29200), "10.9": (30400, 38100), "12.9": (35500, 44600)},
    10: {"8.8": (33700, 46400), "10.9": (48100, 60300), "12.9": (56300, 70800)},
    12: {"8.8": (48900, 67400), "10.9": (70000, 87700), "12.9": (81800, 103000)},
    14: {"8.8": (66700, 92000), "10.9": (95500, 120000), "12.9": (112000, 140000)},
    16: {"8.8": (91000, 125000), "10.9": (130000, 163000), "12.9": (152000, 192000)},
    18: {"8.8": (115000, 159000), "10.9": (159000, 200000), "12.9": (186000, 234000)},
    20: {"8.8": (147000, 203000), "10.9": (203000, 255000), "12.9": (238000, 299000)},
    22: {"8.8": (182000, 252000), "10.9": (252000, 315000), "12.9": (294000, 370000)},
    24: {"8.8": (212000, 293000), "10.9": (293000, 367000), "12.9": (342000, 431000)},
}
CELLS = [(d, cls, *loads) for d, row in ISO_898_1.items() for cls, loads in row.items()]


@pytest.mark.parametrize(("d", "cls", "proof", "ultimate"), CELLS)
def test_proof_and_ultimate_loads(d, cls, proof, ultimate):
    # 30400 has 5 digits: half a unit of its third digit is 50 N
    diameter = d * 1e-3
    area = th.stress_area(diameter, th.coarse_pitch(diameter))
    _, tensile = th.property_class_strengths(cls, diameter)
    s_p = PROOF_STRESS_MPA[cls][0 if d <= 16 else 1] * 1e6
    for computed, printed in ((area * s_p, proof), (area * tensile, ultimate)):
        half_digit = 0.5 * 10 ** (len(str(printed)) - 3)
        assert abs(computed - printed) <= 0.005 * printed + half_digit
