"""The fastener catalogue held row by row, through the functions that read it.

Each table is written out again here as transcribed from its standard (the validation
tests in tests/validation/test_fasteners_standards.py compare the rows that have a printed
worked source); a test then reads every row back through the public lookups (thread, head,
nut, washer, grade, material, proof stress), so a changed digit, a row read from the wrong
column or a lookup past a row edge fails here. A deliberate change to a row is made in both
places.
"""

import math

import numpy as np
import pytest

from engine.core.errors import InputOutOfRange
from engine.physics import fasteners as fa

INCH = 0.0254  # [m], exact by definition
KSI = 6.894757293168e6  # [Pa], 1000 lbf/in² = 4.4482216152605 N / 0.0254² m² * 1000
MPA = 1e6

# ISO 261 coarse pitch [mm], M1.6…M64
METRIC_COARSE_PITCH_MM = {
    1.6: 0.35,
    2.0: 0.4,
    2.5: 0.45,
    3.0: 0.5,
    3.5: 0.6,
    4.0: 0.7,
    5.0: 0.8,
    6.0: 1.0,
    8.0: 1.25,
    10.0: 1.5,
    12.0: 1.75,
    14.0: 2.0,
    16.0: 2.0,
    18.0: 2.5,
    20.0: 2.5,
    22.0: 2.5,
    24.0: 3.0,
    27.0: 3.0,
    30.0: 3.5,
    33.0: 3.5,
    36.0: 4.0,
    39.0: 4.0,
    42.0: 4.5,
    45.0: 4.5,
    48.0: 5.0,
    52.0: 5.0,
    56.0: 5.5,
    60.0: 5.5,
    64.0: 6.0,
}

# ISO 261/262 fine pitches [mm]
METRIC_FINE_PITCHES_MM = {
    1.6: (0.2,),
    2.0: (0.25,),
    2.5: (0.35,),
    3.0: (0.35,),
    4.0: (0.5,),
    5.0: (0.5,),
    6.0: (0.75,),
    8.0: (1.0,),
    10.0: (1.25, 1.0),
    12.0: (1.5, 1.25),
    14.0: (1.5,),
    16.0: (1.5,),
    18.0: (2.0, 1.5),
    20.0: (2.0, 1.5),
    22.0: (2.0, 1.5),
    24.0: (2.0,),
    27.0: (2.0,),
    30.0: (2.0,),
    33.0: (2.0,),
    36.0: (3.0,),
    39.0: (3.0,),
    42.0: (3.0, 2.0),
    45.0: (3.0, 2.0),
    48.0: (3.0, 2.0),
    52.0: (4.0, 3.0),
    56.0: (4.0, 2.0),
    60.0: (4.0,),
    64.0: (4.0,),
}

# ASME B1.1: major diameter [in], UNC and UNF threads per inch
UNIFIED_SIZES = {
    "1/4": (0.25, 20, 28),
    "5/16": (0.3125, 18, 24),
    "3/8": (0.375, 16, 24),
    "7/16": (0.4375, 14, 20),
    "1/2": (0.5, 13, 20),
    "9/16": (0.5625, 12, 18),
    "5/8": (0.625, 11, 18),
    "3/4": (0.75, 10, 16),
    "7/8": (0.875, 9, 14),
    "1": (1.0, 8, 12),
    "1-1/8": (1.125, 7, 12),
    "1-1/4": (1.25, 7, 12),
    "1-3/8": (1.375, 6, 12),
    "1-1/2": (1.5, 6, 12),
}

# ASME B18.2.1 hex cap screw width across flats [in]
UNIFIED_HEX_FLATS_IN = {
    "1/4": 0.4375,
    "5/16": 0.5,
    "3/8": 0.5625,
    "7/16": 0.625,
    "1/2": 0.75,
    "9/16": 0.8125,
    "5/8": 0.9375,
    "3/4": 1.125,
    "7/8": 1.3125,
    "1": 1.5,
    "1-1/8": 1.6875,
    "1-1/4": 1.875,
    "1-3/8": 2.0625,
    "1-1/2": 2.25,
}

# ASME B18.2.1 hex cap screw head height [in]
UNIFIED_HEX_HEIGHT_IN = {
    "1/4": 0.15625,
    "5/16": 0.203125,
    "3/8": 0.234375,
    "7/16": 0.28125,
    "1/2": 0.3125,
    "9/16": 0.359375,
    "5/8": 0.390625,
    "3/4": 0.46875,
    "7/8": 0.546875,
    "1": 0.609375,
    "1-1/8": 0.6875,
    "1-1/4": 0.78125,
    "1-3/8": 0.84375,
    "1-1/2": 0.9375,
}

# ASME B18.2.8 normal clearance hole [in]
UNIFIED_CLEARANCE_IN = {
    "1/4": 0.281,
    "5/16": 0.344,
    "3/8": 0.406,
    "7/16": 0.469,
    "1/2": 0.531,
    "9/16": 0.594,
    "5/8": 0.656,
    "3/4": 0.781,
    "7/8": 0.938,
    "1": 1.062,
    "1-1/8": 1.188,
    "1-1/4": 1.312,
    "1-3/8": 1.438,
    "1-1/2": 1.562,
}

# ISO 273 clearance holes fine, medium, coarse [mm]
CLEARANCE_HOLE_MM = {
    1.6: (1.7, 1.8, 2.0),
    2.0: (2.2, 2.4, 2.6),
    2.5: (2.7, 2.9, 3.1),
    3.0: (3.2, 3.4, 3.6),
    3.5: (3.7, 3.9, 4.2),
    4.0: (4.3, 4.5, 4.8),
    5.0: (5.3, 5.5, 5.8),
    6.0: (6.4, 6.6, 7.0),
    8.0: (8.4, 9.0, 10.0),
    10.0: (10.5, 11.0, 12.0),
    12.0: (13.0, 13.5, 14.5),
    14.0: (15.0, 15.5, 16.5),
    16.0: (17.0, 17.5, 18.5),
    18.0: (19.0, 20.0, 21.0),
    20.0: (21.0, 22.0, 24.0),
    22.0: (23.0, 24.0, 26.0),
    24.0: (25.0, 26.0, 28.0),
    27.0: (28.0, 30.0, 32.0),
    30.0: (31.0, 33.0, 35.0),
    33.0: (34.0, 36.0, 38.0),
    36.0: (37.0, 39.0, 42.0),
    39.0: (40.0, 42.0, 45.0),
    42.0: (43.0, 45.0, 48.0),
    45.0: (46.0, 48.0, 52.0),
    48.0: (50.0, 52.0, 56.0),
    52.0: (54.0, 56.0, 62.0),
    56.0: (58.0, 62.0, 66.0),
    60.0: (62.0, 66.0, 70.0),
    64.0: (66.0, 70.0, 74.0),
}

# ISO 898-1 Table 3 proof stress [MPa], up to and above the size step
ISO898_PROOF_STRESS_MPA = {
    "4.6": (225.0, 225.0),
    "4.8": (310.0, 310.0),
    "5.6": (280.0, 280.0),
    "5.8": (380.0, 380.0),
    "6.8": (440.0, 440.0),
    "8.8": (580.0, 600.0),
    "9.8": (650.0, 650.0),
    "10.9": (830.0, 830.0),
    "12.9": (970.0, 970.0),
}

# ISO 4017/4014: s, k, d_w,min [mm]
HEX_HEAD_MM = {
    1.6: (3.2, 1.1, 2.27),
    2.0: (4.0, 1.4, 3.07),
    2.5: (5.0, 1.7, 4.07),
    3.0: (5.5, 2.0, 4.57),
    3.5: (6.0, 2.4, 5.07),
    4.0: (7.0, 2.8, 5.88),
    5.0: (8.0, 3.5, 6.88),
    6.0: (10.0, 4.0, 8.88),
    8.0: (13.0, 5.3, 11.63),
    10.0: (16.0, 6.4, 14.63),
    12.0: (18.0, 7.5, 16.63),
    14.0: (21.0, 8.8, 19.64),
    16.0: (24.0, 10.0, 22.49),
    18.0: (27.0, 11.5, 25.34),
    20.0: (30.0, 12.5, 28.19),
    22.0: (34.0, 14.0, 31.71),
    24.0: (36.0, 15.0, 33.61),
    27.0: (41.0, 17.0, 38.0),
    30.0: (46.0, 18.7, 42.75),
    33.0: (50.0, 21.0, 46.55),
    36.0: (55.0, 22.5, 51.11),
    39.0: (60.0, 25.0, 55.86),
    42.0: (65.0, 26.0, 59.95),
    45.0: (70.0, 28.0, 64.7),
    48.0: (75.0, 30.0, 69.45),
    52.0: (80.0, 33.0, 74.2),
    56.0: (85.0, 35.0, 78.66),
    60.0: (90.0, 38.0, 83.41),
    64.0: (95.0, 40.0, 88.16),
}

# ISO 4762: key s, k, d_w,min [mm]
SOCKET_HEAD_MM = {
    1.6: (1.5, 1.6, 2.72),
    2.0: (1.5, 2.0, 3.48),
    2.5: (2.0, 2.5, 4.18),
    3.0: (2.5, 3.0, 5.07),
    4.0: (3.0, 4.0, 6.53),
    5.0: (4.0, 5.0, 8.03),
    6.0: (5.0, 6.0, 9.38),
    8.0: (6.0, 8.0, 12.33),
    10.0: (8.0, 10.0, 15.33),
    12.0: (10.0, 12.0, 17.23),
    14.0: (12.0, 14.0, 20.17),
    16.0: (14.0, 16.0, 23.17),
    20.0: (17.0, 20.0, 28.87),
    24.0: (19.0, 24.0, 34.81),
    30.0: (22.0, 30.0, 43.61),
    36.0: (27.0, 36.0, 52.54),
    42.0: (32.0, 42.0, 61.34),
    48.0: (36.0, 48.0, 70.34),
    56.0: (41.0, 56.0, 82.26),
    64.0: (46.0, 64.0, 94.26),
}

# EN 1665: s, k,max, d_w,min [mm]
FLANGE_HEAD_MM = {
    5.0: (8.0, 5.8, 9.8),
    6.0: (10.0, 6.6, 12.2),
    8.0: (13.0, 8.1, 15.8),
    10.0: (16.0, 10.4, 19.6),
    12.0: (18.0, 11.8, 23.8),
    14.0: (21.0, 13.7, 27.6),
    16.0: (24.0, 15.4, 31.9),
    20.0: (30.0, 18.9, 39.9),
}

# ISO 10642: key s, k,max, d_k,min [mm]
COUNTERSUNK_HEAD_MM = {
    3.0: (2.0, 1.86, 5.54),
    4.0: (2.5, 2.48, 7.53),
    5.0: (3.0, 3.1, 9.43),
    6.0: (4.0, 3.72, 11.34),
    8.0: (5.0, 4.96, 15.24),
    10.0: (6.0, 6.2, 19.22),
    12.0: (8.0, 7.44, 23.12),
    16.0: (10.0, 8.8, 29.01),
    20.0: (12.0, 10.16, 36.05),
}

# ISO 2936 minimum test torque [N·m] by key size [mm]
HEX_KEY_TORQUE_NM = {
    1.5: 0.82,
    2.0: 1.9,
    2.5: 3.8,
    3.0: 6.6,
    4.0: 16.0,
    5.0: 30.0,
    6.0: 52.0,
    8.0: 120.0,
    10.0: 220.0,
    12.0: 370.0,
    14.0: 590.0,
    17.0: 980.0,
    19.0: 1360.0,
    22.0: 2110.0,
    24.0: 2750.0,
    27.0: 3910.0,
}

# ISO 4032 / 4033 / 4035 nut height m,max [mm]
NUT_HEIGHT_MM = {
    "ISO 4032": {
        1.6: 1.3,
        2.0: 1.6,
        2.5: 2.0,
        3.0: 2.4,
        4.0: 3.2,
        5.0: 4.7,
        6.0: 5.2,
        8.0: 6.8,
        10.0: 8.4,
        12.0: 10.8,
        14.0: 12.8,
        16.0: 14.8,
        20.0: 18.0,
        24.0: 21.5,
        30.0: 25.6,
        36.0: 31.0,
        42.0: 34.0,
        48.0: 38.0,
        56.0: 45.0,
        64.0: 51.0,
    },
    "ISO 4033": {
        5.0: 5.1,
        6.0: 5.7,
        8.0: 7.5,
        10.0: 9.3,
        12.0: 12.0,
        14.0: 14.1,
        16.0: 16.4,
        20.0: 20.3,
        24.0: 23.9,
        30.0: 28.6,
        36.0: 34.7,
    },
    "ISO 4035": {
        1.6: 1.0,
        2.0: 1.2,
        2.5: 1.6,
        3.0: 1.8,
        4.0: 2.2,
        5.0: 2.7,
        6.0: 3.2,
        8.0: 4.0,
        10.0: 5.0,
        12.0: 6.0,
        14.0: 7.0,
        16.0: 8.0,
        20.0: 10.0,
        24.0: 12.0,
        30.0: 15.0,
        36.0: 18.0,
        42.0: 21.0,
        48.0: 24.0,
        56.0: 28.0,
        64.0: 32.0,
    },
}

# ISO 898-2 classes by nut standard
NUT_CLASSES = {
    "ISO 4032": ("style 1", ("6", "8", "10")),
    "ISO 4033": ("style 2", ("9", "10", "12")),
    "ISO 4035": ("thin", ("04", "05")),
}

# ISO 898-2:1992 stress under proof load [MPa] by thread range
NUT_PROOF_STRESS_MPA = {
    "04": (380.0, 380.0, 380.0, 380.0, 380.0),
    "05": (500.0, 500.0, 500.0, 500.0, 500.0),
    "4": (None, None, None, None, 510.0),
    "5": (520.0, 580.0, 590.0, 610.0, 630.0),
    "6": (600.0, 670.0, 680.0, 700.0, 720.0),
    "8": (800.0, 855.0, 870.0, 880.0, 920.0),
    "9": (900.0, 915.0, 940.0, 950.0, 920.0),
    "10": (1040.0, 1040.0, 1040.0, 1050.0, 1060.0),
    "12": (1140.0, 1140.0, 1140.0, 1170.0, None),
    "12/2": (1150.0, 1150.0, 1160.0, 1190.0, 1200.0),
}

# upper ends of those thread ranges [m]
NUT_PROOF_RANGES_M = (0.004, 0.007, 0.01, 0.016, 0.039)

# ISO 7089 / 7092 / 7093-1 washers: d1 min, d2 max, h [mm]
WASHER_MM = {
    "ISO 7089": {
        1.6: (1.7, 4.0, 0.3),
        2.0: (2.2, 5.0, 0.3),
        2.5: (2.7, 6.0, 0.5),
        3.0: (3.2, 7.0, 0.5),
        4.0: (4.3, 9.0, 0.8),
        5.0: (5.3, 10.0, 1.0),
        6.0: (6.4, 12.0, 1.6),
        8.0: (8.4, 16.0, 1.6),
        10.0: (10.5, 20.0, 2.0),
        12.0: (13.0, 24.0, 2.5),
        14.0: (15.0, 28.0, 2.5),
        16.0: (17.0, 30.0, 3.0),
        20.0: (21.0, 37.0, 3.0),
        24.0: (25.0, 44.0, 4.0),
        30.0: (31.0, 56.0, 4.0),
        36.0: (37.0, 66.0, 5.0),
        42.0: (45.0, 78.0, 8.0),
        48.0: (52.0, 92.0, 8.0),
        56.0: (62.0, 105.0, 10.0),
        64.0: (70.0, 115.0, 10.0),
    },
    "ISO 7092": {
        1.6: (1.7, 3.5, 0.3),
        2.0: (2.2, 4.5, 0.3),
        2.5: (2.7, 5.0, 0.5),
        3.0: (3.2, 6.0, 0.5),
        4.0: (4.3, 8.0, 0.5),
        5.0: (5.3, 9.0, 1.0),
        6.0: (6.4, 11.0, 1.6),
        8.0: (8.4, 15.0, 1.6),
        10.0: (10.5, 18.0, 1.6),
        12.0: (13.0, 20.0, 2.0),
        14.0: (15.0, 24.0, 2.5),
        16.0: (17.0, 28.0, 2.5),
        20.0: (21.0, 34.0, 3.0),
        24.0: (25.0, 39.0, 4.0),
        30.0: (31.0, 50.0, 4.0),
        36.0: (37.0, 60.0, 5.0),
    },
    "ISO 7093": {
        3.0: (3.2, 9.0, 0.8),
        4.0: (4.3, 12.0, 1.0),
        5.0: (5.3, 15.0, 1.2),
        6.0: (6.4, 18.0, 1.6),
        8.0: (8.4, 24.0, 2.0),
        10.0: (10.5, 30.0, 2.5),
        12.0: (13.0, 37.0, 3.0),
        14.0: (15.0, 44.0, 3.0),
        16.0: (17.0, 50.0, 3.0),
        20.0: (22.0, 60.0, 4.0),
        24.0: (26.0, 72.0, 5.0),
        30.0: (33.0, 92.0, 6.0),
        36.0: (39.0, 110.0, 8.0),
    },
}

# nominal Young's modulus [GPa]
MATERIAL_YOUNGS_MODULUS_GPA = {
    "S235JR": 210.0,
    "E295": 210.0,
    "C45 (normalised)": 210.0,
    "42CrMo4 (QT)": 210.0,
    "X5CrNi18-10": 200.0,
    "EN-GJL-250": 110.0,
    "EN-GJS-400": 169.0,
    "EN-GJS-500": 169.0,
    "EN AW-6082 T6": 70.0,
    "EN AW-7075 T6": 70.0,
    "EN AC-46000 (die cast)": 70.0,
    "EN AC-42100 T6": 70.0,
    "TiAl6V4": 110.0,
    "MgAl9Zn1 (die cast)": 45.0,
}

# ISO 898-1, ISO 3506-1, SAE J429, ASTM A193: name, standard, R_p, R_m, S_p (MPa or ksi),
# d range (mm or in), material, kind of yield strength
GRADES = [
    ("4.6", "ISO 898-1", 240, 400, 225, (0, 39), "steel", "R_eL"),
    ("4.8", "ISO 898-1", 340, 420, 310, (0, 39), "steel", "R_pf"),
    ("5.6", "ISO 898-1", 300, 500, 280, (0, 39), "steel", "R_eL"),
    ("5.8", "ISO 898-1", 420, 520, 380, (0, 39), "steel", "R_pf"),
    ("6.8", "ISO 898-1", 480, 600, 440, (0, 39), "steel", "R_pf"),
    ("8.8", "ISO 898-1", 640, 800, 580, (0, 16), "steel", "R_p0.2"),
    ("8.8", "ISO 898-1", 660, 830, 600, (16, 39), "steel", "R_p0.2"),
    ("9.8", "ISO 898-1", 720, 900, 650, (0, 16), "steel", "R_p0.2"),
    ("10.9", "ISO 898-1", 940, 1040, 830, (0, 39), "steel", "R_p0.2"),
    ("12.9", "ISO 898-1", 1100, 1220, 970, (0, 39), "steel", "R_p0.2"),
    ("A2-50", "ISO 3506-1", 210, 500, None, (0, 39), "stainless", "R_p0.2"),
    ("A4-50", "ISO 3506-1", 210, 500, None, (0, 39), "stainless", "R_p0.2"),
    ("A2-70", "ISO 3506-1", 450, 700, None, (0, 24), "stainless", "R_p0.2"),
    ("A4-70", "ISO 3506-1", 450, 700, None, (0, 24), "stainless", "R_p0.2"),
    ("A2-80", "ISO 3506-1", 600, 800, None, (0, 24), "stainless", "R_p0.2"),
    ("A4-80", "ISO 3506-1", 600, 800, None, (0, 24), "stainless", "R_p0.2"),
    ("SAE 2", "SAE J429", 57, 74, 55, (0.25, 0.75), "steel", "R_p0.2"),
    ("SAE 2", "SAE J429", 36, 60, 33, (0.75, 1.5), "steel", "R_p0.2"),
    ("SAE 5", "SAE J429", 92, 120, 85, (0.25, 1.0), "steel", "R_p0.2"),
    ("SAE 5", "SAE J429", 81, 105, 74, (1.0, 1.5), "steel", "R_p0.2"),
    ("SAE 8", "SAE J429", 130, 150, 120, (0.25, 1.5), "steel", "R_p0.2"),
    ("B7", "ASTM A193", 105, 125, None, (0, 2.5), "steel", "R_p0.2"),
]

# VDI 2230-1 Table A9 p_G [MPa] (plastics: datasheets), R_m [MPa], tau_B / R_m
MATERIALS = {
    "S235JR": ("steel", 490.0, 360.0, 0.6),
    "E295": ("steel", 710.0, 470.0, 0.6),
    "C45 (normalised)": ("steel", 770.0, 620.0, 0.6),
    "42CrMo4 (QT)": ("steel", 850.0, 900.0, 0.6),
    "X5CrNi18-10": ("steel", 210.0, 500.0, 0.6),
    "EN-GJL-250": ("cast iron", 850.0, 250.0, 1.1),
    "EN-GJS-400": ("cast iron", 600.0, 400.0, 0.9),
    "EN-GJS-500": ("cast iron", 750.0, 500.0, 0.9),
    "EN AW-6082 T6": ("aluminium", 360.0, 310.0, 0.6),
    "EN AW-7075 T6": ("aluminium", 370.0, 540.0, 0.6),
    "EN AC-46000 (die cast)": ("aluminium", 290.0, 240.0, 0.6),
    "EN AC-42100 T6": ("aluminium", 380.0, 290.0, 0.6),
    "TiAl6V4": ("titanium", 1000.0, 890.0, 0.6),
    "MgAl9Zn1 (die cast)": ("magnesium", 220.0, 200.0, 0.6),
    "PA66 (conditioned)": ("plastic", 60.0, 60.0, 0.6),
    "PA66 GF30 (conditioned)": ("plastic", 120.0, 130.0, 0.6),
    "POM": ("plastic", 80.0, 65.0, 0.6),
    "PC": ("plastic", 70.0, 65.0, 0.6),
}


def test_every_table_is_as_transcribed():
    for name, table in {
        "METRIC_COARSE_PITCH_MM": METRIC_COARSE_PITCH_MM,
        "METRIC_FINE_PITCHES_MM": METRIC_FINE_PITCHES_MM,
        "UNIFIED_SIZES": UNIFIED_SIZES,
        "UNIFIED_HEX_FLATS_IN": UNIFIED_HEX_FLATS_IN,
        "UNIFIED_HEX_HEIGHT_IN": UNIFIED_HEX_HEIGHT_IN,
        "UNIFIED_CLEARANCE_IN": UNIFIED_CLEARANCE_IN,
        "CLEARANCE_HOLE_MM": CLEARANCE_HOLE_MM,
        "ISO898_PROOF_STRESS_MPA": ISO898_PROOF_STRESS_MPA,
        "HEX_HEAD_MM": HEX_HEAD_MM,
        "SOCKET_HEAD_MM": SOCKET_HEAD_MM,
        "FLANGE_HEAD_MM": FLANGE_HEAD_MM,
        "COUNTERSUNK_HEAD_MM": COUNTERSUNK_HEAD_MM,
        "HEX_KEY_TORQUE_NM": HEX_KEY_TORQUE_NM,
        "NUT_HEIGHT_MM": NUT_HEIGHT_MM,
        "NUT_CLASSES": NUT_CLASSES,
        "NUT_PROOF_STRESS_MPA": NUT_PROOF_STRESS_MPA,
        "NUT_PROOF_RANGES_M": NUT_PROOF_RANGES_M,
        "WASHER_MM": WASHER_MM,
        "MATERIAL_YOUNGS_MODULUS_GPA": MATERIAL_YOUNGS_MODULUS_GPA,
    }.items():
        assert getattr(fa, name) == table, name
    assert fa.INCH == INCH and pytest.approx(KSI, rel=1e-12) == fa.KSI and fa.MPA == MPA


@pytest.mark.parametrize("d", sorted(METRIC_COARSE_PITCH_MM))
def test_every_metric_thread_and_its_parts(d):
    coarse = METRIC_COARSE_PITCH_MM[d]
    for p in (coarse, *METRIC_FINE_PITCHES_MM.get(d, ())):
        t = fa.metric_thread(d, p)
        assert t.diameter == pytest.approx(d * 1e-3, rel=1e-12)
        assert t.pitch == pytest.approx(p * 1e-3, rel=1e-12)
        assert t.series == ("ISO coarse" if p == coarse else "ISO fine")
        assert t.designation == (f"M{d:g}" if p == coarse else f"M{d:g}x{p:g}")
        # ISO 68-1 basic profile, H = √3/2 P: d2 = d − 3/4 H, d3 = d − 17/12 H, d1 = d − 5/4 H
        h = math.sqrt(3) / 2 * p
        assert t.pitch_diameter * 1e3 == pytest.approx(d - 0.75 * h, abs=2e-6)
        assert t.minor_diameter * 1e3 == pytest.approx(d - 17 / 12 * h, abs=2e-6)
        assert t.nut_minor_diameter * 1e3 == pytest.approx(d - 1.25 * h, abs=2e-6)
        d0 = d - 0.75 * h / 2 - 17 / 24 * h
        assert t.stress_area * 1e6 == pytest.approx(math.pi / 4 * d0**2, rel=1e-6)
    assert fa.metric_thread(d).pitch == pytest.approx(coarse * 1e-3, rel=1e-12)
    t = fa.metric_thread(d)
    holes = CLEARANCE_HOLE_MM[d]
    for series, hole in zip(("fine", "medium", "coarse"), holes, strict=True):
        assert fa.clearance_hole(t, series) == pytest.approx(hole * 1e-3, rel=1e-12)
    assert fa.clearance_hole(t) == pytest.approx(holes[1] * 1e-3, rel=1e-12)
    for standard, table in (
        ("ISO 4017", HEX_HEAD_MM),
        ("ISO 4014", HEX_HEAD_MM),
        ("ISO 4762", SOCKET_HEAD_MM),
        ("EN 1665", FLANGE_HEAD_MM),
        ("ISO 10642", COUNTERSUNK_HEAD_MM),
    ):
        if d not in table:
            with pytest.raises(InputOutOfRange):
                fa.head(standard, t)
            continue
        s, k, dw = table[d]
        h = fa.head(standard, t)
        assert (h.drive_size, h.head_height, h.bearing_diameter) == pytest.approx(
            (s * 1e-3, k * 1e-3, dw * 1e-3), rel=1e-12
        )
        assert h.cone_angle == (math.pi / 2 if standard == "ISO 10642" else 0.0)
        assert h.drive == ("hex key" if standard in ("ISO 4762", "ISO 10642") else "wrench")
    for standard, heights in NUT_HEIGHT_MM.items():
        if d not in heights:
            with pytest.raises(InputOutOfRange):
                fa.nut(standard, t)
            continue
        n = fa.nut(standard, t)
        s, _, dw = HEX_HEAD_MM[d]
        assert (n.height, n.width_across_flats, n.bearing_diameter) == pytest.approx(
            (heights[d] * 1e-3, s * 1e-3, dw * 1e-3), rel=1e-12
        )
        assert (n.style, n.property_classes) == NUT_CLASSES[standard]
    for standard, rows in WASHER_MM.items():
        if d not in rows:
            with pytest.raises(InputOutOfRange):
                fa.washer(standard, t)
            continue
        w = fa.washer(standard, t)
        d1, d2, hw = rows[d]
        assert (w.inner_diameter, w.outer_diameter, w.thickness) == pytest.approx(
            (d1 * 1e-3, d2 * 1e-3, hw * 1e-3), rel=1e-12
        )


@pytest.mark.parametrize("size", list(UNIFIED_SIZES))
def test_every_unified_thread_and_its_head(size):
    major, unc, unf = UNIFIED_SIZES[size]
    for tpi, series in ((unc, "UNC"), (unf, "UNF")):
        t = fa.unified_thread(size, tpi)
        assert t.designation == f"{size}-{tpi} {series}" and t.series == series
        assert t.diameter == pytest.approx(major * INCH, rel=1e-12)
        assert t.pitch == pytest.approx(INCH / tpi, rel=1e-12)
        # ASME B1.1 basic profile: d2 = d − 0.649519 P, sharp-V minor d − 1.299038 P,
        # A_s = π/4 (d − 0.9743 P)²
        p = 1 / tpi
        assert t.pitch_diameter / INCH == pytest.approx(major - 0.649519 * p, abs=1e-6)
        assert t.minor_diameter / INCH == pytest.approx(major - 1.299038 * p, abs=1e-6)
        assert t.nut_minor_diameter / INCH == pytest.approx(major - 1.082532 * p, abs=1e-6)
        assert t.stress_area / INCH**2 == pytest.approx(
            math.pi / 4 * (major - 0.9743 / tpi) ** 2, rel=1e-4
        )
        assert fa.clearance_hole(t) == pytest.approx(UNIFIED_CLEARANCE_IN[size] * INCH)
        h = fa.head("ASME B18.2.1", t)
        flats = UNIFIED_HEX_FLATS_IN[size]
        assert (h.bearing_diameter, h.head_height, h.drive_size) == pytest.approx(
            (0.95 * flats * INCH, UNIFIED_HEX_HEIGHT_IN[size] * INCH, flats * INCH), rel=1e-12
        )
        assert fa.head("hex", t) == h
        for standard in NUT_HEIGHT_MM:
            with pytest.raises(InputOutOfRange):
                fa.nut(standard, t)
    assert fa.unified_thread(size).series == "UNC"
    assert fa.unified_thread(size, series="UNF").pitch == pytest.approx(INCH / unf)


def test_every_grade_row_and_its_edges():
    rows = []
    for name, standard, rp, rm, sp, (lo, hi), material, kind in GRADES:
        unit, length = (KSI, INCH) if standard == "SAE J429" or name == "B7" else (MPA, 1e-3)
        rows.append(
            (
                name,
                standard,
                rp * unit,
                rm * unit,
                None if sp is None else sp * unit,
                lo * length,
                hi * length,
                material,
                kind,
            )
        )
    assert [
        (
            g.name,
            g.standard,
            g.yield_strength,
            g.tensile_strength,
            g.proof_stress,
            g.min_diameter,
            g.max_diameter,
            g.material,
            g.yield_kind,
        )
        for g in fa.GRADES
    ] == [
        tuple(pytest.approx(v, rel=1e-12) if isinstance(v, float) else v for v in r) for r in rows
    ]
    for name, _, rp, rm, _, lo, hi, _, _ in rows:
        mid = max(lo, 0.004) if lo == 0 else 0.5 * (lo + hi)
        g = fa.grade_strengths(name, mid)
        assert (g.yield_strength, g.tensile_strength) == pytest.approx((rp, rm), rel=1e-12)
        # the top of its range belongs to the first row that reaches it
        assert fa.grade_strengths(name, hi * (1 + 1e-12)).max_diameter >= hi * (1 - 1e-12)
    for name in ("4.6", "8.8", "A2-70", "SAE 5", "SAE 8", "B7"):
        top = max(r[6] for r in rows if r[0] == name)
        with pytest.raises(InputOutOfRange) as err:
            fa.grade_strengths(name, top * (1 + 1e-6))
        assert err.value.field == "grade"
    with pytest.raises(InputOutOfRange):
        fa.grade_strengths("SAE 5", 0.2 * INCH)  # SAE J429 starts at 1/4 in
    assert fa.grade_strengths("SAE 5", 0.25 * INCH).tensile_strength == pytest.approx(120 * KSI)
    assert fa.grade_strengths("8.8", 0.016).tensile_strength == pytest.approx(800e6)
    assert fa.grade_strengths("8.8", 0.016 * (1 + 1e-6)).tensile_strength == pytest.approx(830e6)
    assert tuple(dict.fromkeys(r[0] for r in rows)) == fa.GRADE_NAMES


@pytest.mark.parametrize(
    ("alias", "name"),
    [
        ("Grade 5", "SAE 5"),
        ("gr 8", "SAE 8"),
        ("GR. 5", "SAE 5"),
        ("SAE J429 2", "SAE 2"),
        ("SAE Grade 8", "SAE 8"),
        ("ASTM A193 B7", "B7"),
        ("A193-B7", "B7"),
        ("a2-70", "A2-70"),
        ("10.9", "10.9"),
    ],
)
def test_grade_aliases(alias, name):
    assert fa.normalise_grade(alias) == name


def test_every_material_row():
    assert list(fa.MATERIALS) == list(MATERIALS)
    for name, (kind, p_g, r_m, tau) in MATERIALS.items():
        m = fa.material(name)
        assert m.kind == kind
        assert m.limiting_surface_pressure == pytest.approx(p_g * MPA, rel=1e-12)
        assert m.tensile_strength == pytest.approx(r_m * MPA, rel=1e-12)
        assert m.shear_strength == pytest.approx(tau * r_m * MPA, rel=1e-12)
        e = fa.material_youngs_modulus(name)
        if name in MATERIAL_YOUNGS_MODULUS_GPA:
            assert e == pytest.approx(MATERIAL_YOUNGS_MODULUS_GPA[name] * 1e9, rel=1e-12)
        else:
            assert e is None and kind == "plastic"


@pytest.mark.parametrize("cls", list(NUT_PROOF_STRESS_MPA))
def test_nut_proof_stress_every_range_and_edge(cls):
    row = NUT_PROOF_STRESS_MPA[cls]
    name, style = ("12", "style 2") if cls == "12/2" else (cls, "style 1")
    lows = (0.003, *NUT_PROOF_RANGES_M[:-1])
    for lo, hi, sp in zip(lows, NUT_PROOF_RANGES_M, row, strict=True):
        for d in (hi, hi * (1 + 1e-12), 0.5 * (lo + hi)):
            got = fa.nut_proof_stress(name, d, style)
            if sp is None:
                assert math.isnan(got)
            else:
                assert got == pytest.approx(sp * MPA, rel=1e-12)
    # the same through an array, and outside M3…M39: NaN
    ds = np.array([0.003, *NUT_PROOF_RANGES_M, 0.003 * (1 - 1e-6), 0.039 * (1 + 1e-6)])
    got = fa.nut_proof_stress(name, ds, style)
    expected = [row[0], *row, None, None]
    for g, e in zip(got, expected, strict=True):
        assert math.isnan(g) if e is None else g == pytest.approx(e * MPA, rel=1e-12)
    area = 84.3e-6
    if row[3] is not None:
        assert fa.nut_proof_load(name, 0.012, area, style) == pytest.approx(row[3] * MPA * area)


def test_hex_key_torques_by_key_size():
    for s, torque in HEX_KEY_TORQUE_NM.items():
        assert fa.hex_key_torque(s * 1e-3) == torque
    assert fa.hex_key_torque(0.007) is None


@pytest.mark.parametrize(
    ("nut_class", "rm", "pairs"),
    [
        ("8", 800e6, True),
        ("8", 830e6, True),
        ("8", 900e6, False),
        ("10", 1040e6, True),
        ("10", 1220e6, False),
        ("12", 1220e6, True),
        ("6", 600e6, True),
        ("5", 600e6, False),
        ("04", 400e6, False),
        ("05", 500e6, False),
    ],
)
def test_nut_class_pairs_with_the_bolt_classes_up_to_its_number(nut_class, rm, pairs):
    assert fa.nut_pairs_with_bolt(nut_class, rm) is pairs


def test_countersunk_friction_factor_by_hand():
    # 1/sin(α/2): 90° → √2, 120° → 2/√3, 60° → 2
    assert fa.countersunk_friction_factor() == pytest.approx(math.sqrt(2), rel=1e-12)
    assert fa.countersunk_friction_factor(math.radians(120)) == pytest.approx(2 / math.sqrt(3))
    assert fa.countersunk_friction_factor(math.radians(60)) == pytest.approx(2.0)


def _c2(x):
    return 5.594 - 13.682 * x + 14.107 * x**2 - 6.057 * x**3 + 0.9353 * x**4


def _c3(x):
    return 0.728 + 1.769 * x - 2.896 * x**2 + 1.296 * x**3


@pytest.mark.parametrize(
    ("ratio", "c2", "c3"),
    [
        # Alexander's polynomials by hand, R_S held inside 0.4…2.2
        (1.5, 5.594 - 13.682 * 1.5 + 14.107 * 2.25 - 6.057 * 3.375 + 0.9353 * 5.0625, 0.897),
        (2.0, _c2(2.0), 0.897),
        (3.0, _c2(2.2), 0.897),
        (0.6, 0.897, 0.728 + 1.769 * 0.6 - 2.896 * 0.36 + 1.296 * 0.216),
        (0.1, 0.897, _c3(0.4)),
        (1.0, 0.897, 0.897),
    ],
)
def test_thread_bending_factors_by_hand_for_one_ratio_and_many(ratio, c2, c3):
    assert fa.thread_bending_factors(ratio) == pytest.approx((c2, c3), rel=1e-12)
    arr = fa.thread_bending_factors(np.array([ratio, ratio]))
    assert arr[0] == pytest.approx([c2, c2], rel=1e-12)
    assert arr[1] == pytest.approx([c3, c3], rel=1e-12)


def test_engagement_for_bolt_failure_adds_two_pitches_to_every_length():
    # M12 8.8 into S235JR: thread_stripping at 1.2 R_m on the full threads (m − 2 P),
    # then 2 P of entry chamfers on each minimum length
    args = (0.012, 0.00175, 0.0108633, 0.0101056, 84.27e-6)
    for length in (0.012, 0.002):
        s = fa.engagement_for_bolt_failure(*args, 800e6, 480e6, 216e6, length)
        plain = fa.thread_stripping(*args, 1.2 * 800e6, 480e6, 216e6, max(length - 0.0035, 0.0))
        assert s.bolt_breaking_force == pytest.approx(1.2 * 800e6 * 84.27e-6, rel=1e-12)
        assert s.min_engagement_length == pytest.approx(plain.min_engagement_length + 0.0035)
        assert s.min_engagement_internal == pytest.approx(plain.min_engagement_internal + 0.0035)
        assert s.min_engagement_external == pytest.approx(plain.min_engagement_external + 0.0035)
        assert s.internal_strip_force == pytest.approx(plain.internal_strip_force, abs=1e-9)
        assert s.external_strip_force == pytest.approx(plain.external_strip_force, abs=1e-9)
    many = fa.engagement_for_bolt_failure(*args, 800e6, 480e6, 216e6, np.array([0.012, 0.002]))
    assert many.internal_strip_force[1] == 0.0
    # the minimum lengths do not depend on the length as built
    assert many.min_engagement_external == pytest.approx(s.min_engagement_external)


def test_refusals_state_the_range_and_the_size_asked():
    with pytest.raises(InputOutOfRange) as err:
        fa.grade_strengths("A2-70", 0.030)
    assert "A2-70 (ISO 3506-1) is defined for d = 0…24 mm, not 30 mm" in str(err.value)
    with pytest.raises(InputOutOfRange) as err:
        fa.grade_strengths("SAE 5", 0.2 * INCH)
    assert "SAE 5 (SAE J429) is defined for d = 6.35…38.1 mm, not 5.08 mm" in str(err.value)
    with pytest.raises(InputOutOfRange) as err:
        fa.metric_thread(11)
    assert "M11 is not an ISO 261 size in the catalogue (M1.6…M64: M1.6, M2, M2.5, M3" in str(
        err.value
    )
    with pytest.raises(InputOutOfRange) as err:
        fa.metric_thread(12, 1.0)
    assert "pitch 1 mm is not an ISO 261/262 pitch of M12 (allowed: 1.75, 1.5, 1.25 mm)" in str(
        err.value
    )
    with pytest.raises(InputOutOfRange) as err:
        fa.head("EN 1665", fa.metric_thread(24))
    assert "EN 1665 has no M24 in the catalogue (sizes M5, M6, M8, M10, M12, M14, M16, M20)" in str(
        err.value
    )


def test_a_grade_range_tolerates_round_off_at_both_ends():
    # 1/4 in computed as 0.00635 × (1 − 1e-12) is still SAE J429's smallest size
    low = fa.grade_strengths("SAE 5", 0.25 * INCH * (1 - 1e-12))
    assert low.tensile_strength == pytest.approx(120 * KSI, rel=1e-12)
    high = fa.grade_strengths("SAE 8", 1.5 * INCH * (1 + 1e-12))
    assert high.tensile_strength == pytest.approx(150 * KSI, rel=1e-12)
    with pytest.raises(InputOutOfRange):
        fa.grade_strengths("SAE 5", 0.25 * INCH * (1 - 1e-6))


def test_catalogue_records_are_frozen():
    # parts are shared by every request and design of a study: none may be changed in place
    import dataclasses

    t = fa.metric_thread(12)
    records = [
        t,
        fa.grade_strengths("8.8", 0.012),
        fa.head("ISO 4017", t),
        fa.nut("ISO 4032", t),
        fa.washer("ISO 7089", t),
        fa.material("S235JR"),
        fa.parse_designation("M12"),
    ]
    for r in records:
        field = dataclasses.fields(r)[0].name
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(r, field, None)


def test_thread_stripping_forces_carry_c1_and_the_bending_factors():
    # M12 (d2 10.8633, D1 10.1056 mm), a strong nut thread (τ_BM 600 MPa) on a 480 MPa
    # bolt thread: R_S > 1, so C2 is Alexander's polynomial and C3 = 0.897; C1 = 0.9 given
    args = (0.012, 0.00175, 0.0108633, 0.0101056, 84.27e-6, 800e6, 480e6, 600e6, 0.010)
    s = fa.thread_stripping(*args, c1=0.9)
    a_n = fa.internal_thread_shear_area(0.012, 0.00175, 0.0108633, 1.0)
    a_s = fa.external_thread_shear_area(0.00175, 0.0108633, 0.0101056, 1.0)
    r_s = 600e6 * a_n / (480e6 * a_s)
    assert r_s > 1.0 and s.strength_ratio == pytest.approx(r_s, rel=1e-12)
    c2 = _c2(min(r_s, 2.2))
    assert (s.c1, s.c2, s.c3) == pytest.approx((0.9, c2, 0.897), rel=1e-12)
    assert s.external_strip_force == pytest.approx(0.9 * c2 * 480e6 * a_s * 0.010, rel=1e-12)
    assert s.internal_strip_force == pytest.approx(0.9 * 0.897 * 600e6 * a_n * 0.010, rel=1e-12)
    f_b = 800e6 * 84.27e-6
    assert s.min_engagement_external == pytest.approx(f_b / (0.9 * c2 * 480e6 * a_s), rel=1e-12)
    assert s.min_engagement_internal == pytest.approx(f_b / (0.9 * 0.897 * 600e6 * a_n), rel=1e-12)
