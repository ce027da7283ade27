"""Explicit-point studies (issue 34): the designs themselves, as JSON rows or CSV, with
units as in a single run; the same summary, feasibility and points download; limits
checked before any work, refusals naming the design and the input."""

from __future__ import annotations

import asyncio
import csv
import io
import time
from typing import Any

import httpx
import pytest

from service import create_app, studies
from service.config import Settings
from service.studies import StudySettings
from tests.toys import TOY

URL = "/api/v1/toy/disc/study"
BASE = {"speed": 20.0, "mode": "fine"}
# three discs: J = m D² / 8, T = J ω² / 2 at ω = 20 rad/s
DESIGNS = [
    ({"mass": 2.0, "diameter": "400 mm"}, 2.0 * 0.4**2 / 8 * 0.5 * 400),  # 8.0 J
    ({"mass": "500 g", "diameter": 0.2}, 0.5 * 0.2**2 / 8 * 0.5 * 400),  # 0.5 J
    ({"mass": 8.0, "diameter": 0.1}, 8.0 * 0.1**2 / 8 * 0.5 * 400),  # 2.0 J
]


def _post(*bodies: dict[str, Any]) -> list[tuple[int, Any, str]]:
    """Each body posted as a study of toy.disc and, when accepted, polled to its end:
    (status, the finished job or the refusal, the points CSV when kept)."""
    app = create_app(
        models=[TOY],
        settings=Settings(warm_up=False),
        study_settings=StudySettings(inprocess_points=1000),
    )

    async def run() -> list[tuple[int, Any, str]]:
        transport = httpx.ASGITransport(app=app)
        out = []
        async with httpx.AsyncClient(transport=transport, base_url="http://t") as c:
            for body in bodies:
                r = await c.post(URL, json={"fidelity": "exact", "outputs": ["energy"], **body})
                if r.status_code != 202:
                    out.append((r.status_code, r.json(), ""))
                    continue
                link = r.headers["location"]
                deadline = time.monotonic() + 30
                job = r.json()
                while job["state"] in ("queued", "running"):
                    assert time.monotonic() < deadline
                    await asyncio.sleep(0.05)
                    job = (await c.get(link)).json()
                points = ""
                if "points_csv" in job["links"]:
                    points = (await c.get(job["links"]["points_csv"])).text
                out.append((202, job, points))
        return out

    try:
        return asyncio.run(run())
    finally:
        app.state.studies.shutdown()


def test_designs_as_json_rows_and_as_csv_give_the_same_study() -> None:
    rows = [d for d, _ in DESIGNS]
    # a spreadsheet's byte-order mark, a cell with its own unit, a blank line
    table = "\ufeffmass [kg], diameter [mm]\n2,400\n500 g,200\n\n8,100\n"
    (status, job, points), (status_csv, job_csv, _) = _post(
        {"base": BASE, "points": rows, "keep_points": True},
        {"base": BASE, "points_csv": table},
    )
    assert status == status_csv == 202
    assert job["state"] == job_csv["state"] == "done", job
    result = job["result"]
    assert result["method"] == "points" and result["points"] == 3 and result["refused"] == 0
    energies = [e for _, e in DESIGNS]
    assert result["outputs"]["energy"]["mean"] == pytest.approx(sum(energies) / 3, rel=1e-12)
    assert result["outputs"]["energy"]["max"] == pytest.approx(8.0, rel=1e-12)
    assert result["extremes"]["energy"]["min"]["inputs"] == pytest.approx(
        {"mass": 0.5, "diameter": 0.2}, rel=1e-12
    )
    assert result["input_units"] == {"mass": "kg", "diameter": "m"}
    assert "feasible" in result
    assert job_csv["result"]["outputs"] == result["outputs"]
    # the points download: each design in the order given, SI, with its energy
    got = list(csv.DictReader(io.StringIO(points)))
    assert [float(r["energy"]) for r in got] == pytest.approx(energies, rel=1e-12)
    assert [float(r["diameter"]) for r in got] == pytest.approx([0.4, 0.2, 0.1], rel=1e-12)


@pytest.mark.parametrize(
    ("body", "field", "says"),
    [
        ({"points": [{"mass": 1.0, "diameter": 0.1}, {"mass": 1.0, "diameter": 12.0}]},
         "points", "design 2 (points[1]), diameter = 12 m is not allowed"),
        ({"points": [{"mass": 1.0, "diameter": 0.1}, {"mass": "5 mm", "diameter": 0.1}]},
         "points", "mass (points[1]) = '5 mm': 'mm' has the wrong dimension"),
        ({"points": [{"mass": 1.0, "diameter": 0.1}, {"mass": 1.0}]},
         "points", "points[1]: diameter is missing"),
        ({"points": [{"mass": 1.0, "diameter": 0.1, "mode": "fine"}]},
         "points", "points[0]: mode is not a numeric input of toy.disc; give it in base"),
        ({"points": [{"mass": 1.0, "diametre": 0.1}]},
         "points", "points[0]: 'diametre' is not an input of toy.disc"),
        ({"points_csv": "mass,diameter\n1,0.1\n1,0.1,3\n"},
         "points_csv", "points_csv line 3: 3 values for the header's 2 inputs"),
        ({"points_csv": "mass,diameter [blorp]\n1,0.1\n"},
         "points_csv", "diameter (points_csv line 2) = '0.1 blorp'"),
        ({"points_csv": "\nmass,diameter [mm]\n\n1,100\n\n1,12000\n"},
         "points_csv", "points_csv line 6, diameter = 12 m is not allowed"),
        ({"points_csv": "mass,dia meter\n1,0.1\n"},
         "points_csv", "points_csv line 1: 'dia meter' is not an input name"),
        ({"points_csv": "mass,diameter\n1,nan\n"},
         "points_csv", "diameter (points_csv line 2) = nan: not a finite number"),
        ({"points_csv": 'mass,diameter\n1,"' + "1" * 140_000 + '"\n'},
         "points_csv", "points_csv: not readable as CSV (field larger than field limit"),
        ({"points": [{"diameter": 0.1}], "points_csv": "diameter\n0.1\n"},
         "points", "give the designs once"),
        ({"points": [{"diameter": 0.1}], "method": "sobol"}, "method", "not 'sobol'"),
        ({"method": "points"}, "points", "method 'points' needs the designs"),
        ({"points": [{"diameter": 0.1}], "variables": [{"name": "mass", "low": 1, "high": 2}]},
         "points", "explicit designs take neither variables nor correlations"),
        ({"points": [{"diameter": 0.1}], "base": {"diameter": 0.2}},
         "points", "diameter is given per design and in base"),
        ({"points": [{"count": 1.5, "diameter": 0.1}]},
         "points", "count = 1.5 is not allowed: must be an integer ≥ 1 and ≤ 100"),
    ],
)  # fmt: skip
def test_a_refusal_names_the_design_and_the_input(
    body: dict[str, Any], field: str, says: str
) -> None:
    ((status, answer, _),) = _post({"base": {"speed": 20.0}, **body})
    assert status == 422, answer
    detail = answer["detail"][0]
    assert detail["field"] == field
    assert says in detail["msg"], detail["msg"]


def test_the_limits_are_checked_before_a_value_is_read(monkeypatch: pytest.MonkeyPatch) -> None:
    """Over the designs or the inputs a study may list, the whole list is refused before
    any cell is read (a cell that cannot be read is not reported)."""
    monkeypatch.setattr(studies, "MAX_POINT_ROWS", 3)
    names = ",".join(f"x{i}" for i in range(65))
    answers = _post(
        {"points_csv": "diameter\n" + "bad\n" * 5},
        {"points_csv": names + "\n" + ",".join(["bad"] * 65) + "\n"},
        {"points": [{f"x{i}": "bad" for i in range(65)}]},
    )
    assert [a[0] for a in answers] == [422] * 3
    msgs = [a[1]["detail"][0]["msg"] for a in answers]
    assert msgs[0] == "points_csv: at most 3 designs"
    assert msgs[1] == "points_csv line 1: at most 64 inputs"
    assert msgs[2] == "points[0]: a design gives 1 to 64 inputs"
