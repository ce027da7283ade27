"""The CSV of stored points leaves the service in small pieces, never a row group whole.

Issue 34's full-scale figures (bench/shopfloor.py): the CSV of a 1,000,000-point joint
study added 814 MB to the service's RSS while it streamed, because each piece was a whole
Parquet row group (65,536 rows: 55 MB of text, and its values as Python floats besides).
Pieces are now ``CSV_ROWS_PER_PIECE`` rows.
"""

from __future__ import annotations

import tracemalloc
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

import service.studies
from service.studies import csv_blocks


def _points(path: Path, rows: int, columns: int, row_group: int) -> np.ndarray:
    """A points file as write_points writes it (float64 columns, null where refused)."""
    values = np.random.default_rng(3).normal(size=(rows, columns)) * 1e3
    values[7, 1] = np.nan  # a refused point
    arrays = [pa.array(values[:, i], mask=~np.isfinite(values[:, i])) for i in range(columns)]
    table = pa.Table.from_arrays(arrays, names=[f"c{i}" for i in range(columns)])
    pq.write_table(table, path, row_group_size=row_group)
    return values


def test_pieces_have_a_bounded_number_of_rows_and_every_row(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """5,000 rows, pieces of 300: 16 of 300 rows and one of 200, the header in the
    first; every value as Python writes it, empty where refused."""
    monkeypatch.setattr(service.studies, "CSV_ROWS_PER_PIECE", 300)
    values = _points(tmp_path / "p.parquet", 5000, 3, 1000)
    pieces = [p.decode() for p in csv_blocks(tmp_path / "p.parquet")]
    counts = [len(p.splitlines()) for p in pieces]
    assert counts == [301] + [300] * 15 + [200]
    lines = "".join(pieces).splitlines()
    assert lines[0] == "c0,c1,c2"
    rows_as_floats = values.tolist()  # Python floats: repr() is how the CSV writes them
    assert lines[1 + 7] == f"{rows_as_floats[7][0]!r},,{rows_as_floats[7][2]!r}"
    assert lines[1 + 4999] == ",".join(repr(v) for v in rows_as_floats[4999])


def test_a_row_group_is_not_held_as_text(tmp_path: Path) -> None:
    """One row group of 20,000 rows × 40 columns (15 MB of CSV): what Python allocates
    while it streams stays under the size of the text, most of it the group's columns
    (6.4 MB: 8 bytes a value), where the group's text whole, encoded, and its values as
    Python floats took 97 MB (measured), six times the text."""
    _points(tmp_path / "p.parquet", 20_000, 40, 65_536)
    tracemalloc.start()
    try:
        size = sum(len(piece) for piece in csv_blocks(tmp_path / "p.parquet"))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert size > 14e6, size
    assert peak < size, (peak, size)
