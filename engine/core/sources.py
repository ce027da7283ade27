"""The sources the engine cites, machine-readable (``GET /api/v1/sources``).

Every citation in a docstring, a spec or a result's notes names one of these:
``[000, eq. 5]`` is equation 5 of source ``"000"``; ``VDI 2230-1 R7`` is step
R7 of source ``"VDI2230"``. ``docs/sources.md`` holds the same list in prose
(full references, what each source covers, what had to be reconstructed).
The papers' equation numbers are the papers' own.

>>> get_source("001").title
'Parameters of double action ball overturn coupling'
>>> sorted(cited_ids("as [001, eq. 2] and VDI 2230-1:2015 step R7 say"))
['001', 'VDI2230']
"""

from __future__ import annotations

import re
from dataclasses import asdict, dataclass
from typing import Any, Literal

SourceKind = Literal["paper", "standard", "textbook", "web page"]


@dataclass(frozen=True)
class Source:
    """One cited document."""

    id: str
    kind: SourceKind
    title: str
    authors: str
    year: str
    published: str
    #: What the engine takes from it (equations, tables, steps).
    covers: str
    #: Where the copy is illegible or the text inconsistent: what was reconstructed and how.
    reconstruction: str = ""
    #: The title in the original language, where the source is not in English.
    original_title: str = ""

    def reference(self) -> str:
        """One line: authors, title, where published, year."""
        return f"[{self.id}] {self.authors}: {self.title}. {self.published}, {self.year}."

    def describe(self) -> dict[str, Any]:
        """JSON-ready entry for the catalogue."""
        return {**asdict(self), "reference": self.reference()}


_UNKNOWN = "not printed in the available copy"

SOURCES: dict[str, Source] = {
    s.id: s
    for s in (
        Source(
            id="000",
            kind="paper",
            title="Parameters of the drive of a multi-spindle nut-runner",
            original_title="Параметри привода багатошпиндельного гайкокрута (Ukrainian); "
            "English abstract: 'Parameters of multiple-spindle power nut-driver'",
            authors=_UNKNOWN,
            year=_UNKNOWN,
            published="Ukrainian technical journal article (journal " + _UNKNOWN + ")",
            covers="Multi-spindle impact wheel-nut runner: kinematic chain motor 6 -> coupling 1 "
            "-> pulley 2 -> belt -> flywheel 3 -> drive gear 4 -> z spindle gears 5; spin-up "
            "time from the work-energy theorem (eq. 1-5), impact torque from energy "
            "conservation in the twisted shaft 7 and spindle 8 (eq. 6-9), maximum spindle "
            "torque (eq. 10). Model nutrunner.drive.",
            reconstruction="Eq. 3-5 (kinetic energy and acceleration time) and eq. 7-8 (energy "
            "balance) are illegible or garbled in the only copy. Reconstructed from the "
            "theorems the paper names and the kinematic chain it describes: "
            "T = (1/16) sum m_k D_k^2 w_k^2 (z m5 for the spindle gears), t = T/P, "
            "M = sqrt(2 T C7 C8 / (C7 + C8)). The paper puts the same torque on shaft 7 and "
            "spindle 8, ignoring the gear ratio u = D4/D5; the gear_ratio rung adds it "
            "(M = sqrt(2T / (u^2/C7 + 1/C8))) and the result says by how much it differs.",
        ),
        Source(
            id="001",
            kind="paper",
            title="Parameters of double action ball overturn coupling",
            original_title="Параметри кулькової обгінної муфти подвійної дії (Ukrainian)",
            authors="V. O. Malashchenko (Lviv Polytechnic National University), V. F. Semenyuk "
            "(Odesa Polytechnic National University), B. R. Lysiak (Drohobych machine-building "
            "company)",
            year=_UNKNOWN,
            published="Ukrainian technical journal article (journal " + _UNKNOWN + ")",
            covers="Double-action ball overrunning (safety) clutch: forces on one ball with the "
            "load non-uniformity factor K_r = 0.85-0.9 (eq. 1), spring force of a helical "
            "compression spring (eq. 2), axial balance without friction (eq. 3), the torque "
            "limit (after eq. 3), the worked case of its figures 4-5 (D0 = 50 mm, i = 4, "
            "d = 10 mm, D = 45 mm, i_p = 5, alpha = 45 deg). Models clutch.ball and "
            "clutch.ball_setting.",
            reconstruction="The copy is a scan whose Cyrillic came out as Latin look-alikes. The "
            "printed final formula shows K_r dividing, contradicting eq. 1; the engine follows "
            "eq. 1-3 (the printed form is 1/K_r^2, 1.38 at K_r = 0.85, times ours). Eq. 3 sets "
            "one ball's axial force equal to the whole spring force, true only with one spring "
            "per ball (arrangement 'per_ball'); the single spring of the paper's figure 1 "
            "('common', the default) gives T = D0 F / (2 tan alpha). Flank friction "
            "(argued small but present in the paper's second half) enters as "
            "tan(alpha - atan f).",
        ),
        Source(
            id="002",
            kind="paper",
            title="Dynamics of the percussive mechanism of a rare-impact nut wrench with an "
            "axially moving striker",
            original_title="Динамика ударного механизма редкоударного гайковерта с осевым "
            "перемещением бойка (Russian; Ukrainian and English abstracts)",
            authors="N. V. Vodolazskaya (DonNTU, Donetsk), V. M. Iskritsky (DGMA, Kramatorsk)",
            year=_UNKNOWN + " (its reference list goes up to 2005)",
            published="Ukrainian collection of scientific papers (title " + _UNKNOWN + ")",
            covers="One impact in four stages: spin-up with centrifugal rollers on cones "
            "(eq. 1), engagement throw of the striker (eq. 2, closed form eq. 5), return "
            "(eq. 3), re-locking (eq. 4); release speed (after eq. 4), spring choice (eq. 6), "
            "full engagement inside the anvil's opening. Model impact.rare.",
            reconstruction="The release speed is printed for alpha = 45 deg with a single "
            "travel h; the same quasi-static balance of eq. 1 is used for any cone angle (it "
            "reduces to the printed form at 45 deg). Stage 1 carries no weight term although "
            "eq. 2 and 4 show gravity; as in the paper it is weightless and the notes give the "
            "size of the omission. The conditions c3 > c1, lambda1 < lambda3 and "
            "c1 lambda1 = c3 lambda3 cannot hold together; each is reported as printed. The "
            "return condition c3 = m3 g/(h - z3) is a static balance; the exact condition of "
            "eq. 3 is used. With heavy preloads or small cone angles the balance at h1 is "
            "unstable (snap-through at lift-off), which the paper does not discuss. The paper "
            "gives no numbers: the reference design is ours.",
        ),
        Source(
            id="003",
            kind="paper",
            title="Scan of [002] (same article, Ukrainian and Russian abstracts)",
            authors="N. V. Vodolazska, V. M. Iskritsky",
            year=_UNKNOWN,
            published="a second, scanned copy of [002]",
            covers="Used only to read equations that are unclear in the text of [002].",
        ),
        Source(
            id="004",
            kind="paper",
            title="Selection of preload and control of tightening of threaded joints (review)",
            original_title="Вибір попереднього затягування (Ukrainian; section title, the "
            "article's own title is " + _UNKNOWN + ")",
            authors=_UNKNOWN,
            year=_UNKNOWN,
            published="Ukrainian technical journal article, oil and gas equipment context "
            "(sucker rods)",
            covers="Design preload and its limits (eq. 2-6), elongation and nut-angle control "
            "(eq. 7-9), thread, bearing and wrench torque (eq. 10-13), frictionless torque "
            "(eq. 14), approximations (eq. 15-19), control methods and their preload scatter "
            "(fig. 1-9, Thum and Debus: 38 bolts 5/8 in at 80 N m). Models preload.tightening "
            "and preload.control.",
            reconstruction="Eq. 1, 10 and 12 are missing from the text; the standard textbook "
            "relations stand in (thread torque F (d2/2) tan(psi + rho'), bearing-face radius "
            "(Df^3 - dh^3) / (3 (Df^2 - dh^2))) and the docstrings say so. Thread geometry "
            "follows ISO 68-1 / ISO 724 and ISO 898-1 (the review gives none).",
        ),
        Source(
            id="VDI2230",
            kind="standard",
            title="Systematic calculation of highly stressed bolted joints - Joints with one "
            "cylindrical bolt",
            authors="VDI (Verein Deutscher Ingenieure)",
            year="2015",
            published="VDI 2230 Part 1:2015-11, Beuth, Berlin",
            covers="Torsion-corrected equivalent stress and permissible assembly preload "
            "F_M,zul (step R7, utilisation nu = 0.9), tightening torque "
            "M_A = F_M (0.16 P + 0.58 d2 mu_G + D_Km/2 mu_K) (step R13, used with nu = 0.9 in "
            "Table A1), tightening factor alpha_A by tightening method (Table A8). Models "
            "preload.tightening and preload.control.",
            reconstruction="The text is paywalled and was not available; the validation pins "
            "the engine to Table A2 (fine threads, nu = 0.9) as reproduced in Bossard's "
            "technical tables F.049/F.050 and the Mastik catalogue p. 685; the docstrings "
            "name the step.",
        ),
        Source(
            id="ISO68-1",
            kind="standard",
            title="ISO general purpose screw threads - Basic profile - Part 1: Metric screw "
            "threads",
            authors="ISO",
            year="1998",
            published="ISO 68-1:1998",
            covers="Basic profile H = (sqrt 3 / 2) P: pitch diameter d2 = d - 0.6495 P, minor "
            "diameters (engine.physics.threads).",
        ),
        Source(
            id="ISO261",
            kind="standard",
            title="ISO general purpose metric screw threads - General plan",
            authors="ISO",
            year="1998",
            published="ISO 261:1998",
            covers="Coarse and fine pitches per nominal diameter, M3-M39 (engine.physics.threads).",
        ),
        Source(
            id="ISO273",
            kind="standard",
            title="Fasteners - Clearance holes for bolts and screws",
            authors="ISO",
            year="1979",
            published="ISO 273:1979",
            covers="Fine, medium and coarse clearance-hole diameters (bearing-face inner "
            "diameter, engine.physics.threads.clearance_hole).",
        ),
        Source(
            id="ISO724",
            kind="standard",
            title="ISO general-purpose metric screw threads - Basic dimensions",
            authors="ISO",
            year="1993",
            published="ISO 724:1993",
            covers="Basic dimensions d2, d1 derived from ISO 68-1 (engine.physics.threads).",
        ),
        Source(
            id="ISO898-1",
            kind="standard",
            title="Mechanical properties of fasteners made of carbon steel and alloy steel - "
            "Part 1: Bolts, screws and studs with specified property classes",
            authors="ISO",
            year="2013",
            published="ISO 898-1:2013",
            covers="Stress area A_s = (pi/4) ((d2 + d3)/2)^2, yield and tensile strength of "
            "property classes 4.6-12.9 (engine.physics.threads).",
        ),
        Source(
            id="ISO4017",
            kind="standard",
            title="Fasteners - Hexagon head screws - Product grades A and B",
            authors="ISO",
            year="edition not stated in the engine",
            published="ISO 4017",
            covers="Width across flats s and bearing-face diameter d_w of hexagon heads "
            "(engine.physics.threads.hex_bearing_diameter).",
        ),
        Source(
            id="ISO5393",
            kind="standard",
            title="Rotary tools for threaded fasteners - Performance test method",
            authors="ISO",
            year="2017",
            published="ISO 5393:2017 (3rd edition)",
            covers="Test joints of blow.joint: a hard joint reaches the target torque 30 deg "
            "after snug, a soft joint 720 deg (27 and 648 deg from 10 % to 100 % of the "
            "target), read as linear torque rates k_j = T_target / angle.",
        ),
        Source(
            id="ECSS-E-HB-32-23A",
            kind="standard",
            title="Space engineering - Threaded fasteners handbook",
            authors="ESA-ESTEC, Requirements and Standards Division",
            year="2010",
            published="ECSS-E-HB-32-23A, 16 April 2010, Noordwijk (free download from ecss.nl)",
            covers="Open secondary source for the VDI 2230 relations of the joint model "
            "(engine.physics.joint): bolt compliance by sections (sect. 7.5.5, Table 7-1), "
            "clamped-part compliance by the deformation cone and sleeve (sect. 7.6.3, "
            "eq. 7.6.8-7.6.14), embedding table (Table 6-3, after VDI 2230 Table 5.4/1), "
            "thermal preload change (sect. 6.3.5), preload range from a torque specification "
            "with min/max friction and prevailing torque (eq. 6.3.14-6.3.15), worked example "
            "sect. 7.14. Model joint.vdi2230.",
            reconstruction="Read through misams/BAT, which implements it and carries the "
            "worked example's numbers; we did not have the PDF itself.",
        ),
        Source(
            id="BAT",
            kind="textbook",
            title="BAT - Bolt Analysis Tool (open-source ECSS-E-HB-32-23A / VDI 2230 calculator)",
            authors="M. Sams (GitHub misams/BAT)",
            year="2021 (v0.8.4)",
            published="https://github.com/misams/BAT, src/Ecss.py, src/BoltAnalysisBase.py",
            covers="Independent implementation run side by side with engine.physics.joint on "
            "2026-11-23: clamped-part compliance (cone/sleeve), bolt compliance, load factor, "
            "preload range of the ECSS sect. 7.14 worked example "
            "(tests/validation/test_joint_compliance.py). Its cone formula puts the nominal "
            "diameter d where VDI 2230 has the hole d_h, and it spreads one substitute area "
            "over plates of different E; the tests say by how much that differs.",
        ),
        Source(
            id="Wahl",
            kind="textbook",
            title="Mechanical Springs",
            authors="A. M. Wahl",
            year="1963",
            published="2nd ed., McGraw-Hill, New York",
            covers="Stress-correction factor K_w = (4C - 1)/(4C - 4) + 0.615/C and wire shear "
            "stress of helical springs (clutch spring checks, beyond [001]).",
        ),
        Source(
            id="Kloss",
            kind="textbook",
            title="Simplified Kloss formula for the torque-slip curve of an induction motor",
            authors="after M. Kloss, as given in electric-drive textbooks",
            year="textbook relation, no single edition cited",
            published="e.g. any electric machines textbook (T = 2 T_b / (s/s_b + s_b/s))",
            covers="Induction-motor torque-speed curve for the motor_curve rung of "
            "nutrunner.drive (engine.physics.motor_spinup), beyond [000].",
        ),
        Source(
            id="ISO262",
            kind="standard",
            title="ISO general purpose metric screw threads - Selected sizes for screws, bolts and "
            "nuts",
            authors="ISO",
            year="1998",
            published="ISO 262:1998",
            covers="Coarse and fine pitches of the selected sizes M1.6-M64 "
            "(engine.physics.fasteners).",
        ),
        Source(
            id="ISO3506-1",
            kind="standard",
            title="Fasteners - Mechanical properties of corrosion-resistant stainless steel "
            "fasteners - Part 1: Bolts, screws and studs",
            authors="ISO",
            year="2009",
            published="ISO 3506-1:2009",
            covers="Austenitic A2/A4 property classes 50, 70, 80: R_p0.2 210/450/600 MPa, R_m "
            "500/700/800 MPa; 70 and 80 up to M24, 50 up to M39 (engine.physics.fasteners).",
        ),
        Source(
            id="ISO898-2",
            kind="standard",
            title="Mechanical properties of fasteners made of carbon steel and alloy"
            " steel - Part 2: Nuts with specified property classes",
            authors="ISO",
            year="2012",
            published="ISO 898-2:2012",
            covers="Nut property classes (04, 05, 6, 8, 9, 10, 12) and styles paired with bolt "
            "classes (engine.physics.fasteners).",
        ),
        Source(
            id="EN20898-2",
            kind="standard",
            title="Mechanical properties of fasteners - Part 2: Nuts with specified proof "
            "load values - Coarse thread",
            authors="ISO / CEN",
            year="1992",
            published="ISO 898-2:1992 = EN 20898-2:1993 (as reproduced by Bossard, technical "
            "information 'Nuts property classes 04 to 12', and a DIN EN 20898-2 proof-load "
            "extract)",
            covers="Stress under proof load S_p by nut class and size range (04/05 380/500 MPa; "
            "class 8 M12 880 MPa, proof load 74 200 N); class N nuts with bolts up to N.x "
            "(engine.physics.fasteners.nut_proof_stress, nut_pairs_with_bolt).",
        ),
        Source(
            id="EMODULI",
            kind="standard",
            title="Nominal Young's moduli of structural metals",
            authors="CEN (EN 1993-1-1, EN 1999-1-1, EN 1561, EN 1563, EN 10088-1)",
            year="2005",
            published="EN 1993-1-1:2005 §3.2.6 (steel E = 210 GPa); EN 1999-1-1:2007 §3.2.5 "
            "(aluminium alloys E = 70 GPa); the grey- and ductile-iron and stainless standards' "
            "informative values",
            covers="E of the catalogue's metals for a tapped thread's compliance "
            "(engine.physics.fasteners.material_youngs_modulus); typed as the engine's authors "
            "know them, not checked against a printed copy.",
        ),
        Source(
            id="BAT-R11",
            kind="paper",
            title="BAT (Bolt Analysis Tool), thread pull-out analysis after VDI 2230 §5.5.5",
            authors="M. Sams",
            year="2021",
            published="https://github.com/misams/BAT, BAT/src/ThreadPullOut.py",
            covers="VDI 2230-1 R11 as an open implementation states it: R_S, C1, C3 (R_S held "
            "at 0.4), m_ges = R_m A_s P/(C1 C3 τ_BM (P/2 + (d − D2) tan 30°) π d) + 2 P for the "
            "entry chamfers (engine.physics.fasteners.engagement_for_bolt_failure); it sizes at "
            "R_m,min, the engine at 1.2 R_m,min.",
        ),
        Source(
            id="SAEJ429",
            kind="standard",
            title="Mechanical and Material Requirements for Externally Threaded Fasteners",
            authors="SAE International",
            year="2014",
            published="SAE J429",
            covers="Grades 2, 5, 8: proof, yield and tensile strength by size range, 1/4-1-1/2 in "
            "(engine.physics.fasteners).",
        ),
        Source(
            id="ASTMA193",
            kind="standard",
            title="Standard Specification for Alloy-Steel and Stainless Steel Bolting for High "
            "Temperature or High Pressure Service and Other Special Purpose Applications",
            authors="ASTM International",
            year="2020",
            published="ASTM A193/A193M",
            covers="Grade B7: R_m 125 ksi, yield 105 ksi up to 2-1/2 in "
            "(engine.physics.fasteners).",
        ),
        Source(
            id="ASMEB1.1",
            kind="standard",
            title="Unified Inch Screw Threads (UN, UNR, and UNJ Thread Forms)",
            authors="ASME",
            year="2019",
            published="ASME B1.1",
            covers="UNC/UNF series (threads per inch), basic pitch diameter E = D - 0.649519 p, "
            "tensile stress area A_t = 0.7854 (D - 0.9743 p)^2 (engine.physics.fasteners).",
        ),
        Source(
            id="ASMEB18.2.1",
            kind="standard",
            title="Square, Hex, Heavy Hex, and Askew Head Bolts and Hex, Heavy Hex, Hex Flange, "
            "Lobed Head, and Lag Screws (Inch Series)",
            authors="ASME",
            year="2012",
            published="ASME B18.2.1",
            covers="Hex cap screw width across flats F and head height H, 1/4-1-1/2 in;"
            " bearing face taken as 0.95 F (engine.physics.fasteners).",
        ),
        Source(
            id="ASMEB18.2.8",
            kind="standard",
            title="Clearance Holes for Bolts, Screws, and Studs",
            authors="ASME",
            year="1999",
            published="ASME B18.2.8",
            covers="Normal-fit clearance holes for inch bolts (engine.physics.fasteners).",
        ),
        Source(
            id="ISO4014",
            kind="standard",
            title="Hexagon head bolts - Product grades A and B",
            authors="ISO",
            year="2011",
            published="ISO 4014:2011",
            covers="Same head as ISO 4017 (partly threaded): s, k, d_w (engine.physics.fasteners).",
        ),
        Source(
            id="ISO4762",
            kind="standard",
            title="Hexagon socket head cap screws",
            authors="ISO",
            year="2004",
            published="ISO 4762:2004",
            covers="Head diameter, head height k = d, hexagon socket size s, bearing"
            " diameter d_w,min (engine.physics.fasteners).",
        ),
        Source(
            id="EN1665",
            kind="standard",
            title="Hexagon head bolts with flange, heavy series",
            authors="CEN",
            year="1997",
            published="EN 1665:1997",
            covers="Flange bearing diameter d_w,min, width across flats s, head height k, M5-M20 "
            "(engine.physics.fasteners).",
        ),
        Source(
            id="ISO10642",
            kind="standard",
            title="Hexagon socket countersunk head screws",
            authors="ISO",
            year="2004",
            published="ISO 10642:2004",
            covers="90 deg countersunk head: actual head diameter d_k,min, head height,"
            " socket size (engine.physics.fasteners).",
        ),
        Source(
            id="ISO2936",
            kind="standard",
            title="Assembly tools for screws and nuts - Hexagon socket screw keys",
            authors="ISO",
            year="2014",
            published="ISO 2936:2014",
            covers="Minimum test torque of hexagon keys by key size: the drive-torque"
            " limit of socket screws (engine.physics.fasteners).",
        ),
        Source(
            id="ISO4032",
            kind="standard",
            title="Hexagon regular nuts (style 1)",
            authors="ISO",
            year="2012",
            published="ISO 4032:2012",
            covers="Nut height m, width across flats (engine.physics.fasteners).",
        ),
        Source(
            id="ISO4033",
            kind="standard",
            title="Hexagon high nuts (style 2)",
            authors="ISO",
            year="2012",
            published="ISO 4033:2012",
            covers="Nut height m (engine.physics.fasteners).",
        ),
        Source(
            id="ISO4035",
            kind="standard",
            title="Hexagon thin nuts (chamfered)",
            authors="ISO",
            year="2012",
            published="ISO 4035:2012",
            covers="Thin nut height m, classes 04/05 (engine.physics.fasteners).",
        ),
        Source(
            id="ISO7089",
            kind="standard",
            title="Plain washers - Normal series - Product grade A",
            authors="ISO",
            year="2000",
            published="ISO 7089:2000",
            covers="Washer d1, d2, h (engine.physics.fasteners).",
        ),
        Source(
            id="ISO7092",
            kind="standard",
            title="Plain washers - Small series - Product grade A",
            authors="ISO",
            year="2000",
            published="ISO 7092:2000",
            covers="Washer d1, d2, h (engine.physics.fasteners).",
        ),
        Source(
            id="ISO7093",
            kind="standard",
            title="Plain washers - Large series - Part 1: Product grade A",
            authors="ISO",
            year="2000",
            published="ISO 7093-1:2000",
            covers="Washer d1, d2, h (engine.physics.fasteners).",
        ),
        Source(
            id="EN1561",
            kind="standard",
            title="Founding - Grey cast irons",
            authors="CEN",
            year="2011",
            published="EN 1561:2011",
            covers="Informative shear strength of grey cast iron, about 1.1 R_m "
            "(engine.physics.fasteners materials).",
        ),
        Source(
            id="EN1563",
            kind="standard",
            title="Founding - Spheroidal graphite cast irons",
            authors="CEN",
            year="2011",
            published="EN 1563:2011",
            covers="Informative shear strength of nodular iron, about 0.9 R_m "
            "(engine.physics.fasteners materials).",
        ),
        Source(
            id="Alexander",
            kind="paper",
            title="Analysis and design of threaded assemblies",
            authors="E. M. Alexander",
            year="1977",
            published="SAE Technical Paper 770420",
            covers="Thread-stripping model: shear areas of internal and external threads, nut "
            "dilation factor C1, thread-bending factors C2/C3; the basis of VDI 2230-1 R11 "
            "(engine.physics.fasteners.thread_stripping).",
        ),
        Source(
            id="FED-STD-H28",
            kind="standard",
            title="Screw-Thread Standards for Federal Services, Section 2: Unified inch screw "
            "threads",
            authors="US General Services Administration",
            year="1978",
            published="FED-STD-H28/2B",
            covers="Shear areas of internal and external threads per length of engagement"
            " (Appendix B), with tau = 0.6 R_m practice (engine.physics.fasteners).",
        ),
        # --- springs for the clutch as built ---
        Source(
            id="EN13906-1",
            kind="standard",
            title="Cylindrical helical springs made from round wire and bar - Calculation and "
            "design - Part 1: Compression springs",
            authors="CEN/TC 407",
            year="2013",
            published="EN 13906-1:2013",
            covers="Helical compression springs: rate, shear stress and Bergstrasser's stress "
            "correction factor k = (w + 0.5)/(w - 0.75), permissible shear stress 0.5 R_m for "
            "cold-coiled springs, solid length, minimum sum of gaps S_a, buckling by the "
            "seating coefficient nu, natural frequency (engine.physics.springs).",
            reconstruction="Paywalled; the relations are the standard's as reproduced in spring "
            "makers' handbooks, and checked in tests against textbook worked examples.",
        ),
        Source(
            id="EN16983",
            kind="standard",
            title="Disc springs - Quality specifications - Dimensions (calculation of the "
            "former DIN 2092)",
            authors="CEN",
            year="2017",
            published="DIN EN 16983:2017 (replaces DIN 2092 and DIN 2093)",
            covers="Disc springs after Almen and Laszlo: factors K1, K2, K3 (K4 for contact "
            "flats), force F(s), force at flat, stresses at OM, I, II, III, IV, stacks in "
            "series and parallel with the friction factors w_M, w_R (engine.physics.springs).",
            reconstruction="Paywalled; the Almen-Laszlo relations are as printed in DIN 2092 "
            "and disc-spring makers' handbooks; the K-factors are checked against Carvill's "
            "table.",
        ),
        Source(
            id="EN10270",
            kind="standard",
            title="Steel wire for mechanical springs - Part 1: Patented cold drawn unalloyed "
            "spring steel wire; Part 3: Stainless spring steel wire",
            authors="ECISS/TC 106",
            year="2011 (Part 1, +A1:2017); 2011 (Part 3)",
            published="EN 10270-1, EN 10270-3",
            covers="Minimum tensile strength R_m by wire diameter of grades SH and DH "
            "(EN 10270-1) and X10CrNi18-8, 1.4310 (EN 10270-3); preferred wire diameters "
            "(engine.physics.springs).",
            reconstruction="Paywalled. The SH/DH rows for 0.30, 0.32, 0.34 mm were checked "
            "against a public transcription of the table; the other rows and the 1.4310 table "
            "are transcribed and not re-checked (see engine/physics/springs.py).",
        ),
        Source(
            id="Bhandari",
            kind="textbook",
            title="Design of Machine Elements",
            authors="V. B. Bhandari",
            year="3rd ed., 2010",
            published="Tata McGraw-Hill, New Delhi; worked examples as computed in the FOSSEE "
            "Scilab Textbook Companion no. 764",
            covers="Chapter 'Springs': Example 10.1 (a helical spring for 1250 N and 30 mm: "
            "wire 6.625 mm, free length 109.34 mm) and Example 10.3 (Wahl factors for C = 5-8), "
            "pinned in tests/validation/test_springs_textbooks.py.",
        ),
        Source(
            id="Carvill",
            kind="textbook",
            title="Mechanical Engineer's Data Handbook",
            authors="J. Carvill",
            year="1993",
            published="Butterworth-Heinemann, Oxford",
            covers="Belleville washer spring: table of the factors k1, k2, k3 against Do/Di "
            "(1.4-5.0), pinned in tests/validation/test_springs_textbooks.py.",
        ),
        Source(
            id="VDI-VDE2645",
            kind="standard",
            title="Capability test for fastening technology - Part 2: Machine capability test "
            "(MCT); Part 3: Process capability test",
            authors="VDI/VDE",
            year="2014 (Part 2)",
            published="VDI/VDE 2645 Blatt 2 and Blatt 3, Beuth",
            covers="Model tool.capability: the machine (Cm, Cmk) and process (Cp, Cpk) "
            "capability indices of a tightening tool, Cm = (U - L)/(6 s), "
            "Cmk = min(U - mean, mean - L)/(3 s) with the sample standard deviation s; at "
            "least 50 values in one run for a machine test; 25 subgroups of 5 for a process "
            "test; 1.67 as the usual limit of Cmk and Cpk.",
            reconstruction="Paywalled; not read. The formulas, sample sizes and the 1.67 limit "
            "are as public secondary sources print them: blog.gwkgerlach.de (machine and "
            "process capability in screwdriving: 'Cmk >= 1.67', 'at least 50 measurements in "
            "one run', 'at least 25 subgroups of 5 values each', 'Cpk >= 1.67 (Automotive)', "
            "each called a typical limit), Minitab's help page 'What are Cm and Cmk?' (the "
            "same formulas as Cp and Cpk; the data differ), harms-wende.de (machine capability: "
            "at least 50 pieces) and [Danikor]. The limit is therefore an input of the model "
            "(default 1.67), not a rule the engine asserts. ISO 5393's own sample-size rule "
            "could not be read in a public source and is not applied.",
        ),
        Source(
            id="Danikor",
            kind="web page",
            title="Tightening tool accuracy: Cm and Cmk (worked example)",
            authors="Danikor (tightening-tool maker)",
            year="read 2026",
            published="https://www.danikor.com/en/newsinfo/169",
            covers="The worked example reproduced in "
            "tests/validation/test_capability_published.py: target 0.8 N*m +/- 10 % "
            "(0.72...0.88 N*m), 25 readings with mean 0.81 N*m and s = 0.011 N*m, Cm = 2.42. "
            "Its rule of thumb (Cm >= 1.67 and Cmk >= 1.33) is a maker's, not the standard's.",
            reconstruction="The copy read ends after 'Cmk = min[(0.88 - 0.81)/(3 x 0.011), "
            "(0.81 - 0.72)...': the page's Cmk is recomputed from its own numbers "
            "(min(0.07, 0.09)/0.033 = 2.12).",
        ),
        Source(
            id="ISO16047",
            kind="standard",
            title="Fasteners - Torque/clamp force testing",
            authors="ISO/TC 2",
            year="2005 (+A1:2012)",
            published="ISO 16047:2005",
            covers="Model friction.iso16047: from a test series of tightening torque T, thread "
            "torque T_th and clamp force F, the torque coefficient K = T/(F d), the thread "
            "friction mu_th = (T_th/F - P/(2 pi))/(d2/(2 cos 30 deg)), the bearing friction "
            "mu_b = (T - T_th)/(F D_b/2) with D_b = (d_o + d_i)/2, and the total friction "
            "mu_tot = (T/F - P/(2 pi))/(d2/(2 cos 30 deg) + D_b/2), with the series' "
            "statistics.",
            reconstruction="Paywalled; not read, and no public copy printing its formulas was "
            "found. The relations are the thread-torque and bearing-torque relations the "
            "standard evaluates (the same form as VDI 2230-1 R13, whose 0.16 P and 0.58 d2 are "
            "1/(2 pi) = 0.159 and 1/(2 cos 30 deg) = 0.577 rounded), solved for each "
            "coefficient; the engine uses the exact constants. DIN 946, the standard ISO 16047 "
            "replaced, is quoted with the same variables (P, d2, D_Km = (d_w + d_h)/2) by "
            "genfast.com's friction calculator. tests/validation/test_iso16047_derivation.py "
            "checks the evaluation against torques built from chosen coefficients with the "
            "exact helix relation.",
        ),
        Source(
            id="Danikor-ISO5393",
            kind="web page",
            title="6σ, ±3σ: telling tool accuracy apart (ISO 5393)",
            authors="Danikor (tightening-tool maker)",
            year="read 2026",
            published="https://www.danikor.cn/en/newsinfo/293",
            covers="Model tool.capability's ISO 5393 runs: tool accuracy is evaluated with the "
            "6 sigma method of ISO 5393 on readings from hard and soft joints, and makers quote "
            "it as +/-3 sigma over the mean (the model's torque_scatter).",
            reconstruction="ISO 5393 itself was not read. The page's formulas are images; the "
            "pooling of the two runs into one sample (mean, s with n - 1, the mean shift) is "
            "exact arithmetic on the runs' values, not a reading of the standard.",
        ),
        Source(
            id="TorqueAudit",
            kind="web page",
            title="Torque audit methods: first motion, breakaway, mark (residual torque)",
            authors="S&R Torque (srtorque.com, FAQ 9 and 'What is break-away torque'); "
            "Mountz (first movement torque test); Desoutter Delta user manual (loose and "
            "tightening)",
            year="read 2026",
            published="http://www.srtorque.com/faq9.html; "
            "https://www.srtorque.com/resources/what-is-break-away-torque/",
            covers="Model joint.audit: the three audit methods (first motion in the "
            "tightening direction, first motion in the loosening direction, the torque to "
            "turn back to a mark after loosening) and that the static (breakaway) torque "
            "exceeds the dynamic torque of tightening; that auditors read first motion as the "
            "installed torque (a practice, used only in a warning).",
        ),
        Source(
            id="FrictionTables",
            kind="web page",
            title="Static and sliding friction values",
            authors="pickedshares.com; Lust CDA3000 engineering guide, Table 7.21",
            year="read 2026",
            published="https://pickedshares.com/en/static-and-sliding-friction-values/",
            covers="Model joint.audit's default static-friction excess r = 1...1.15: steel on "
            "steel dry static 0.45...0.80 against sliding 0.40...0.70 (ratio about 1.13), "
            "lubricated 0.10 both (ratio 1).",
        ),
        Source(
            id="Bickford",
            kind="textbook",
            title="An Introduction to the Design and Behavior of Bolted Joints",
            authors="J. H. Bickford",
            year="3rd ed.",
            published="Marcel Dekker / CRC Press",
            covers="A published restart torque (the tank-tread end-connector bolts: 5/8-18 "
            "Grade 8 tightened to 150 lb-ft, stretch 0.0015 in relaxing to 0.001 in, restarted "
            "at 100 lb-ft), reproduced in tests/validation/test_audit_restart_torque.py.",
            reconstruction="Read as the chapter abstract published by Taylor & Francis, not "
            "the book.",
        ),
        Source(
            id="BoltScience",
            kind="web page",
            title="Untightening of nuts and bolts",
            authors="Bolt Science Ltd",
            year="read 2026",
            published="https://www.boltscience.com/pages/untightening.htm",
            covers="Model joint.audit: untightened at once, a nut usually needs about 20 % "
            "less torque than it was tightened with (the stretching part of the torque acts "
            "the other way), reproduced in tests/validation/test_audit_untightening.py; after "
            "half a day the release torque can be up to 10 % above the tightening torque "
            "(friction rises), and torque audits are accurate only shortly after tightening.",
        ),
        Source(
            id="ASTME1685",
            kind="standard",
            title="Standard Practice for Measuring the Change in Length of Fasteners Using "
            "the Ultrasonic Pulse-Echo Technique",
            authors="ASTM E28",
            year="2013, 2020",
            published="ASTM E1685",
            covers="Model bolt.ultrasonic: the practice of measuring a bolt's change in length "
            "by pulse-echo time of flight; its scope (bolts of 6.3 mm and more with effective "
            "length-to-diameter ratios of 2:1 or more) as a check.",
            reconstruction="Paywalled; the scope is as the publishers' abstracts print it. "
            "The relations are the instrument makers' ([BoltMike], [Dakota]).",
        ),
        Source(
            id="BoltMike",
            kind="web page",
            title="Guide to Ultrasonic Inspection of Fasteners (BoltMike III), chapter 8: "
            "BoltMike formulas",
            authors="StressTel / GE",
            year="2003",
            published="manualshelf.com copy of the operating manual, page 35",
            covers="Model bolt.ultrasonic: the time of flight is half the sound path "
            "duration; the change in ultrasonic length is the velocity times the change in "
            "time of flight; elongation = stress x effective length / E.",
        ),
        Source(
            id="Dakota",
            kind="web page",
            title="MAX II / MINI-MAX ultrasonic bolt tension monitor, operation manual "
            "(sonic stress factor and temperature factor calibration; quantities of "
            "measurement)",
            authors="Dakota Ultrasonics",
            year="read 2026",
            published="manualshive.com and manualslib.com copies, pages 85-135",
            covers="Model bolt.ultrasonic: the sonic stress factor SSF = (L_M1 - L_M0)/"
            "(L_U1 - L_U0), mechanical over ultrasonic change in length; elongation = change "
            "in time x velocity x stress factor; the temperature factor T_F = (L_T - L_0)/"
            "(L_0 (T - T_0)) x 10^6 combining thermal expansion and the velocity's change; "
            "that stress factor and velocity vary by about 5 % over steel fasteners.",
        ),
        Source(
            id="Saltelli2010",
            kind="paper",
            title="Variance based sensitivity analysis of model output. Design and estimator "
            "for the total sensitivity index",
            authors="A. Saltelli, P. Annoni, I. Azzini, F. Campolongo, M. Ratto, S. Tarantola",
            year="2010",
            published="Computer Physics Communications 181(2), 259-270",
            covers="The sampling design (matrices A, B, AB_i) and the first-order Sobol' "
            "estimator of engine.studies.plan; the total index uses Jansen's estimator (M. J. W. "
            "Jansen, Computer Physics Communications 117, 35-43, 1999). Validated against the "
            "Ishigami function's analytic indices (T. Ishigami, T. Homma, 1990; Saltelli et al., "
            "Global Sensitivity Analysis: The Primer, Wiley 2008, §4.8).",
        ),
        Source(
            id="Desoutter-CVIR",
            kind="web page",
            title="CVIR II user manual, section 9.5: yield point controlled tightening",
            authors="Desoutter (tightening-tool maker)",
            year="2014 (edition 04)",
            published="manual 6159933910, p. 59 (read at manualshive.com, 2026)",
            covers="The yield-point rule of engine.physics.trace.yield_index: the torque rate "
            "is compared with a reference torque rate taken early in the tightening, and the "
            "yield point is where it has fallen to X % of it; default X = 50, reference over "
            "N = 16 samples.",
        ),
        Source(
            id="AtlasCopco-PF",
            kind="web page",
            title="Power Focus 3000 / PowerMACS 4000 manuals: yield control and gradient",
            authors="Atlas Copco (tightening-tool maker)",
            year="read 2026",
            published="Power Focus 3000 manual 9836 3123 01, p. 108; PowerMACS 4000 manual "
            "9836 3521 01, 6.5.3.5 (read at easymanua.ls)",
            covers="Yield control: the torque difference over a step angle is compared with the "
            "largest difference met so far and the yield point is where it falls below a "
            "'yield slope ratio' of it; the gradient is a torque difference over an angle "
            "distance after a sliding-average filter, computed at every sample.",
        ),
        Source(
            id="OPC40450",
            kind="standard",
            title="OPC UA for Joining Systems / Tightening (OPC 40450-1)",
            authors="OPC Foundation and VDMA",
            year="2021 (Tightening 1.00), 2024 (IJT Base 1.00)",
            published="reference.opcfoundation.org, Tightening 10.11-10.12, OPC 40450-1 C.5",
            covers="The StepTraceDataType (StepTraceId, StepResultId, NumberOfTracePoints, "
            "SamplingInterval, StartTimeOffset, StepTraceContent) and TraceContentDataType "
            "(Values, Name, PhysicalQuantity, EngineeringUnits) that "
            "engine.procedures.trace_import reads as JSON; the YIELD tag (C.5): where the "
            "linear growth of torque against angle drops, an approximation any system reports.",
            reconstruction="PhysicalQuantity's coded values (its section 9.1/9.10) were not "
            "read: the importer takes the quantity from Name or EngineeringUnits instead.",
        ),
        Source(
            id="OpenProtocol",
            kind="standard",
            title="Open Protocol: MID 0900 trace curve data, MID 0901 trace plotting parameters",
            authors="Atlas Copco (protocol owner); open parsers node-open-protocol (PR #47) "
            "and open-protocol-codec",
            year="read 2026",
            published="the protocol specification is distributed by its owner; field layout as "
            "the open parsers decode it",
            covers="The decoded fields engine.procedures.trace_import reads: result id, time "
            "stamp, data fields (PID, value, unit), trace type (1 angle, 2 torque, 3 current, "
            "4 gradient, 5 stroke, 6 force), transducer type, unit code, resolution fields "
            "(the sample time interval), number of samples and the samples.",
            reconstruction="The specification itself was not read; the unit codes accepted "
            "(001 N*m, 002 lbf*ft, 003 lbf*in, 008 N*cm, 050 degree, 051 radian, 200 s, "
            "201 min, 202 ms) are as we recall them from it: other codes are refused, and a "
            "user with another code converts first.",
        ),
        Source(
            id="pyscrew",
            kind="web page",
            title="pyscrew: screw-driving data sets and their loader (Rexroth result JSON)",
            authors="N. West and co-workers (open project)",
            year="read 2026",
            published="github.com/nikolaiwest/pyscrew, data on Zenodo",
            covers="The layout of the Bosch Rexroth controller's result JSON that "
            "engine.procedures.trace_import reads: 'tightening steps', each with 'name', "
            "'result' and 'graph' holding 'angle values', 'torque values', 'time values' "
            "(and 'gradient values').",
        ),
        Source(
            id="Kruskal1958",
            kind="paper",
            title="Ordinal measures of association",
            authors="W. H. Kruskal",
            year="1958",
            published="Journal of the American Statistical Association 53(284), 814-861",
            covers="engine.numerics.laws: the rank (Spearman) correlation of a bivariate "
            "normal pair, rho_S = (6/pi) asin(rho/2), which holds for any two margins joined "
            "by a Gaussian copula (ranks do not change under the margins' monotone maps); the "
            "studies and joint.clamp_capability take rank correlations and convert them.",
        ),
        Source(
            id="CSP2862",
            kind="web page",
            title="VDI/VDE 2862 explains: bolting classes A/B/C, minimum requirements",
            authors="A. Lederle (CSP)",
            year="read 2026",
            published="https://www.csp-sw.com/blog/vdi/vde-2862-screw-drive-classes",
            covers="joint.clamp_capability's category check: class A 'Cpk >= 1.67 for torque "
            "and angle of rotation', class B 'Cpk >= 1.33', class C no capability minimum, as "
            "this secondary source summarises VDI/VDE 2862.",
            reconstruction="VDI/VDE 2862 itself (Beuth) was not read; this is one software "
            "maker's summary, the only public one found that states numbers. It sets a minimum "
            "on the tool's torque capability, not on the clamp force or alpha_A; the check is "
            "opt-in (category 'none' by default).",
        ),
        Source(
            id="NFG-898T",
            kind="web page",
            title="Wytrzymałość i temperatura (strength and temperature of bolts)",
            authors="NFG AB (fastener distributor), technical pages",
            year="read 2026",
            published="https://www.nfgab.pl/technologia-i-jakosc/informacje-techniczne/"
            "wytrzymalosci/temperatura",
            covers="ISO 898-1 Annex A (informative) as reprinted: lower yield strength R_eL or "
            "0.2 % proof strength R_p0.2 [N/mm²] at 20/100/200/250/300 °C, 5.6: 300 270 230 "
            "215 195; 8.8: 640 590 540 510 480; 10.9: 940 875 790 745 705; 12.9: 1100 1020 "
            "925 875 825, given as guidance, not requirements "
            "(engine.physics.fasteners.yield_strength_ratio; joint.vdi2230 service_temperature).",
            reconstruction="ISO 898-1 itself was not read; the values are the distributor's "
            "reprint, the only public one found.",
            original_title="Wytrzymałość i temperatura (Polish)",
        ),
        Source(
            id="RICHTER-E",
            kind="web page",
            title="E-Modul & Temperatur (forming handbook, section 1.1.1)",
            authors="4ming (forming handbook), after F. Richter, Die physikalischen Eigenschaften "
            "der Stähle, TU Graz",
            year="read 2026",
            published="https://4ming.de/de/forming-handbuch/e-modul-und-temperatur",
            covers="Young's modulus [GPa] at 20/200/400/600 °C: low-alloy steels 212 199 184 "
            "164; austenitic steels 196 186 179 157; aluminium alloys 70 63 (to 200 °C); "
            "GGG-38 170 168 135 (to 400 °C) (engine.physics.fasteners.youngs_modulus_ratio).",
            reconstruction="Richter's report itself was not read. VDI 2230-1 prints its own "
            "E(T) table, paywalled; tests/validation/test_joint_temperature.py compares these "
            "ratios with [ASME-B31.1-E].",
            original_title="E-Modul & Temperatur (German)",
        ),
        Source(
            id="ASME-B31.1-E",
            kind="web page",
            title="Metals and Alloys - Young's Modulus of Elasticity (after ASME B31.1-1995)",
            authors="The Engineering ToolBox",
            year="read 2026",
            published="https://www.engineeringtoolbox.com/young-modulus-d_773.html",
            covers="E [10^6 psi] at -325…1200 °F after ASME B31.1-1995: grey cast iron 13.4 "
            "13.2 12.9 12.6 12.2 11.7 at 70…600 °F (engine.physics.fasteners."
            "youngs_modulus_ratio), and the carbon-steel and austenitic rows the validation "
            "compares with [RICHTER-E].",
            reconstruction="ASME B31.1 itself was not read.",
        ),
        Source(
            id="STEELPY-VDI",
            kind="web page",
            title="steelpy: VDI 2230 bolt design tool (steelpy/design/codes/bolt/VDI2230.py)",
            authors="S. Vargas-Ortega (open project)",
            year="read 2026",
            published="github.com/svortega/steelpy",
            covers="VDI 2230-1's limit of the eccentric relations on the interface c_T as it "
            "reproduces them: G = h_min + d_W (R0/1, eq. 5.1/38) of a through-bolted joint, "
            "G' = (1.5…2) d_W of a tapped one (engine.physics.joint.interface_limit; "
            "joint.vdi2230's warning where c_T > G).",
            reconstruction="VDI 2230-1's own text was not read; h18340637145/vdi2230 states the "
            "same G and 1.5 d_W (docs/sources.md).",
        ),
    )
}

#: Patterns that cite a source in text, and the id each resolves to.
_PATTERNS: tuple[tuple[re.Pattern[str], str | None], ...] = (
    (re.compile(r"\[(\d{3})(?=[,\]])"), None),
    (re.compile(r"\bVDI 2230"), "VDI2230"),
    (re.compile(r"\bISO 68-1\b"), "ISO68-1"),
    (re.compile(r"\bISO 261\b"), "ISO261"),
    (re.compile(r"\bISO 273\b"), "ISO273"),
    (re.compile(r"\bISO 724\b"), "ISO724"),
    (re.compile(r"\bISO 898-1\b"), "ISO898-1"),
    (re.compile(r"\bISO 4017\b"), "ISO4017"),
    (re.compile(r"\bISO 262\b"), "ISO262"),
    (re.compile(r"\bISO 3506(?:-1)?\b"), "ISO3506-1"),
    (re.compile(r"\bISO 898-2\b"), "ISO898-2"),
    (re.compile(r"\bEN 20898-2\b"), "EN20898-2"),
    (re.compile(r"\bSAE J429\b"), "SAEJ429"),
    (re.compile(r"\bASTM A193\b"), "ASTMA193"),
    (re.compile(r"\bASME B1\.1\b"), "ASMEB1.1"),
    (re.compile(r"\bASME B18\.2\.1\b"), "ASMEB18.2.1"),
    (re.compile(r"\bASME B18\.2\.8\b"), "ASMEB18.2.8"),
    (re.compile(r"\bISO 4014\b"), "ISO4014"),
    (re.compile(r"\bISO 4762\b"), "ISO4762"),
    (re.compile(r"\bEN 1665\b"), "EN1665"),
    (re.compile(r"\bISO 10642\b"), "ISO10642"),
    (re.compile(r"\bISO 2936\b"), "ISO2936"),
    (re.compile(r"\bISO 4032\b"), "ISO4032"),
    (re.compile(r"\bISO 4033\b"), "ISO4033"),
    (re.compile(r"\bISO 4035\b"), "ISO4035"),
    (re.compile(r"\bISO 7089\b"), "ISO7089"),
    (re.compile(r"\bISO 7092\b"), "ISO7092"),
    (re.compile(r"\bISO 7093\b"), "ISO7093"),
    (re.compile(r"\bEN 1561\b"), "EN1561"),
    (re.compile(r"\bEN 1563\b"), "EN1563"),
    (re.compile(r"\bAlexander\b"), "Alexander"),
    (re.compile(r"\bFED-STD-H28\b"), "FED-STD-H28"),
    (re.compile(r"\bISO 5393\b"), "ISO5393"),
    (re.compile(r"\bWahl\b"), "Wahl"),
    (re.compile(r"\bKloss\b"), "Kloss"),
    (re.compile(r"\bEN 13906-1\b"), "EN13906-1"),
    (re.compile(r"\bEN 16983\b"), "EN16983"),
    (re.compile(r"\bEN 10270-[13]\b"), "EN10270"),
    (re.compile(r"\bBhandari\b"), "Bhandari"),
    (re.compile(r"\bCarvill\b"), "Carvill"),
    (re.compile(r"\bECSS-E-HB-32-23A\b"), "ECSS-E-HB-32-23A"),
    (re.compile(r"\bmisams/BAT\b"), "BAT"),
    (re.compile(r"\bVDI/VDE 2645\b"), "VDI-VDE2645"),
    (re.compile(r"\bDanikor\b"), "Danikor"),
    (re.compile(r"\bKruskal1958\b"), "Kruskal1958"),
    (re.compile(r"\bCSP2862\b"), "CSP2862"),
    (re.compile(r"\bISO 16047\b"), "ISO16047"),
    (re.compile(r"\bDanikor-ISO5393\b"), "Danikor-ISO5393"),
    (re.compile(r"\bTorqueAudit\b"), "TorqueAudit"),
    (re.compile(r"\bFrictionTables\b"), "FrictionTables"),
    (re.compile(r"\bBickford\b"), "Bickford"),
    (re.compile(r"\bBoltScience\b"), "BoltScience"),
    (re.compile(r"\bASTM E1685\b"), "ASTME1685"),
    (re.compile(r"\bBoltMike\b"), "BoltMike"),
    (re.compile(r"\bDakota\b"), "Dakota"),
    (re.compile(r"\bDesoutter-CVIR\b"), "Desoutter-CVIR"),
    (re.compile(r"\bAtlasCopco-PF\b"), "AtlasCopco-PF"),
    (re.compile(r"\bOPC 40450\b"), "OPC40450"),
    (re.compile(r"\bOpen Protocol\b"), "OpenProtocol"),
    (re.compile(r"\bpyscrew\b"), "pyscrew"),
    (re.compile(r"\[NFG-898T\]"), "NFG-898T"),
    (re.compile(r"\[RICHTER-E\]"), "RICHTER-E"),
    (re.compile(r"\[ASME-B31\.1-E\]"), "ASME-B31.1-E"),
    (re.compile(r"\[STEELPY-VDI\]"), "STEELPY-VDI"),
)


def cited_ids(text: str) -> set[str]:
    """The source ids a text cites: ``[002, eq. 5]`` gives ``"002"``, ``VDI 2230`` ``"VDI2230"``."""
    found: set[str] = set()
    for pattern, fixed in _PATTERNS:
        for match in pattern.finditer(text):
            found.add(fixed if fixed is not None else match.group(1))
    return found


def get_source(source_id: str) -> Source:
    """The source called ``source_id``; KeyError if there is none."""
    return SOURCES[source_id]


def catalogue() -> list[dict[str, Any]]:
    """Every source, JSON-ready, in citation order."""
    return [s.describe() for s in SOURCES.values()]
