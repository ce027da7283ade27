"""The form's unit table (static/units.json) agrees with the API's unit parser.

The page converts a field when its unit selector changes, checks ranges before
submitting and shows results in display units with the factors in this table,
but it sends "value unit" strings that the server parses with pint. A wrong
factor would make the page's range check and results disagree with the
server; these tests compare every factor with pint.
"""

import json
import math
from pathlib import Path

import pytest

from service.units import to_si

TABLE = json.loads((Path(__file__).parents[2] / "static" / "units.json").read_text("utf-8"))
CHOICES = [
    (si, label, api, factor)
    for si, rows in TABLE.items()
    if not si.startswith("_")
    for label, api, factor in rows
]


@pytest.mark.parametrize(("si", "label", "api", "factor"), CHOICES)
def test_factor_matches_the_api_parser(si, label, api, factor):
    # "1 mm" read by the API into metres must equal the table's factor 1e-3
    target = si
    text = f"1 {api}" if api else "1"
    assert math.isclose(to_si(text, target), factor, rel_tol=1e-12), (si, label)


def test_every_si_unit_offers_itself():
    # the fallback when a model's display unit is not in the table is the SI choice
    for si, rows in TABLE.items():
        if si.startswith("_"):
            continue
        assert any(factor == 1 for _, _, factor in rows), si


def test_labels_are_unique_per_unit():
    for si, rows in TABLE.items():
        if not si.startswith("_"):
            assert len({r[0] for r in rows}) == len(rows), si
