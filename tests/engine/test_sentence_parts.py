"""Checks and notes carry their quantities as data (engine/core/text.py).

A sentence's parts, joined, are its plain text; each quantity's SI value, written in its
display unit with its digits, is the text the sentence shows; and over HTTP the same
parts come beside the plain strings, which stay what they were.
"""

from __future__ import annotations

import math

import pytest

import engine
from engine.core.text import DISPLAY, parts, plain, q, split
from engine.models import get_model


def _joined(ps: list) -> str:
    return "".join(p if isinstance(p, str) else p["text"] for p in ps)


def test_a_quantity_reads_as_the_format_it_replaces() -> None:
    # the f-strings the models wrote before, computed by hand here
    assert plain(q(23_790.0, "kN", 4)) == f"{23_790.0 / 1e3:.4g} kN" == "23.79 kN"
    assert plain(q(0.012, "mm", 6)) == f"{0.012 * 1e3:g} mm" == "12 mm"
    assert plain(q(640e6, "MPa", 4)) == "640 MPa"
    assert plain(q(73.51, "N*m", 4)) == "73.51 N·m"
    assert plain(q(math.pi / 4, "deg")) == "45°"
    assert plain(q(201.4, "N*m", fmt=".0f")) == "201 N·m"


def test_parts_carry_the_si_value_and_unit() -> None:
    text, ps = split(f"F_M = {q(23_790.0, 'kN', 4)} … {q(0.0254, 'mm')} long")
    assert text == "F_M = 23.79 kN … 25.4 mm long"
    assert ps[0] == "F_M = " and ps[2] == " … " and ps[4] == " long"
    force, length = ps[1], ps[3]
    assert isinstance(force, dict) and isinstance(length, dict)
    assert (force["value"], force["unit"], force["display_unit"], force["digits"]) == (
        23_790.0,
        "N",
        "kN",
        4,
    )
    assert (length["value"], length["unit"], length["display_unit"]) == (0.0254, "m", "mm")


def test_a_non_finite_value_has_no_value_and_a_stray_mark_is_only_dropped() -> None:
    (quantity,) = parts(q(float("nan"), "kN"))
    assert isinstance(quantity, dict) and quantity["value"] is None
    assert quantity["text"] == "nan kN"
    assert plain("a\ue000b") == "ab"  # not a quantity this module wrote


def test_every_display_unit_converts_back_to_its_si_unit() -> None:
    # 1 display unit in SI, by hand: kN 1000 N, mm 0.001 m, MPa 1e6 Pa, rpm 2π/60 rad/s, ° π/180 rad
    by_hand = {"kN": 1e3, "mm": 1e-3, "MPa": 1e6, "rpm": 2 * math.pi / 60, "deg": math.pi / 180}
    for display, si in by_hand.items():
        assert DISPLAY[display][1] * si == pytest.approx(1.0, rel=1e-15)


def test_joint_checks_and_notes_give_parts_whose_text_is_the_sentence() -> None:
    spec = get_model("joint.vdi2230")
    r = engine.run(spec, spec.examples[0])
    window = next(c for c in r.checks if c.name == "R7_window_fits")
    assert window.detail == _joined(list(window.detail_parts))
    quantities = [p for p in window.detail_parts if isinstance(p, dict)]
    # F_M,min, F_M,max = α_A F_M,min and F_M,zul, in N, as the results give them
    assert [p["unit"] for p in quantities[:3]] == ["N", "N", "N"]
    assert quantities[0]["value"] == pytest.approx(r.results["required_preload_min"], rel=1e-12)
    assert quantities[1]["value"] == pytest.approx(r.results["required_preload_max"], rel=1e-12)
    assert quantities[2]["value"] == pytest.approx(r.results["permissible_preload"], rel=1e-12)
    f_m_min = float(r.results["required_preload_min"])  # type: ignore[arg-type]
    assert quantities[0]["text"] == f"{f_m_min / 1e3:.4g} kN"
    assert len(r.notes_parts) == len(r.notes)
    for note, ps in zip(r.notes, r.notes_parts, strict=True):
        assert _joined(ps) == note and "\ue000" not in note
    assert any(isinstance(p, dict) and p["unit"] == "m" for ps in r.notes_parts for p in ps)


def test_the_api_gives_the_parts_beside_the_plain_sentences(client) -> None:  # type: ignore[no-untyped-def]
    spec = get_model("joint.vdi2230")
    body = client.post("/api/v1/joint/vdi2230", json=spec.examples[0]).json()
    for check in body["checks"]:
        assert _joined(check["detail_parts"]) == check["detail"]
    assert [_joined(ps) for ps in body["notes_parts"]] == body["notes"]
    window = next(c for c in body["checks"] if c["name"] == "R7_window_fits")
    assert window["detail_parts"][1]["unit"] == "N"


def _quantities(notes: list[str], notes_parts: list, start: str) -> list:
    """The quantities of the one note that starts with ``start``, its parts joined checked."""
    (ps,) = [ps for note, ps in zip(notes, notes_parts, strict=True) if note.startswith(start)]
    (note,) = [note for note in notes if note.startswith(start)]
    assert _joined(ps) == note and "\ue000" not in note
    return [p for p in ps if isinstance(p, dict)]


def test_a_bolt_note_and_an_as_built_clutch_note_carry_their_quantities() -> None:
    spec = get_model("preload.tightening")
    r = engine.run(spec, spec.examples[3])  # M10 ISO 4762 12.9
    pitch, area = _quantities(r.notes, r.notes_parts, "thread M10: P = ")
    # ISO 261: M10 coarse pitch 1.5 mm; ISO 898-1: A_s = π/4 ((d2 + d3)/2)², d2 = d − 0.649519 P,
    # d3 = d − 1.226869 P: (9.026 + 8.160)/2 = 8.593 mm, A_s = 57.99 mm²
    assert (pitch["value"], pitch["unit"], pitch["display_unit"]) == (0.0015, "m", "mm")
    d2, d3 = 10.0 - 0.649519 * 1.5, 10.0 - 1.226869 * 1.5
    assert area["value"] == pytest.approx(math.pi / 4 * ((d2 + d3) / 2) ** 2 * 1e-6, rel=1e-5)
    assert (area["unit"], area["display_unit"], area["text"]) == ("m^2", "mm²", "57.99 mm²")

    spec = get_model("clutch.ball")
    x = spec.examples[3]  # as built: EN 10270-1 DH wire, free length, ball lift 2 mm
    r = engine.run(spec, x)
    qs = _quantities(r.notes, r.notes_parts, "torque against lift: ")
    assert [p["unit"] for p in qs] == ["N*m", "N*m", "m", "N", "Pa", "N", "Pa"]
    assert qs[2]["value"] == pytest.approx(x["ball_lift"], rel=1e-12)  # peak at the given lift
    # the spring at the peak: c (Δ + lift), c = G d⁴ / (8 D³ n) with G = 81.5 GPa (DH wire),
    # d = 4 mm, D = 32 mm, n = 8: c = 9948.7 N/m, F = c (30 + 2) mm = 318.36 N
    rate = 81.5e9 * 0.004**4 / (8 * 0.032**3 * 8)
    assert qs[3]["value"] == pytest.approx(rate * (0.030 + 0.002), rel=1e-9)
    assert qs[3]["text"] == "318.4 N" and qs[3]["display_unit"] == "N"
    assert qs[4]["display_unit"] == "MPa" and qs[4]["value"] == pytest.approx(
        r.results["spring_stress_at_peak"], rel=1e-12
    )


def test_a_quantity_carries_its_exact_value_and_the_digits_its_text_shows() -> None:
    # the SI value comes back bit for bit, however awkward
    for value in (0.1 + 0.2, -0.0, 5e-324, 1.7976931348623157e308, -23_790.123456789):
        (quantity,) = parts(q(value, "N"))
        assert isinstance(quantity, dict)
        assert math.copysign(1.0, quantity["value"]) == math.copysign(1.0, value)  # type: ignore[arg-type]
        assert quantity["value"] == value
    (inf,) = parts(q(math.inf, "N", fmt=".0f"))
    assert isinstance(inf, dict) and (inf["value"], inf["digits"], inf["text"]) == (
        None,
        3,
        "inf N",
    )
    # digits: those the text shows, at least 3, at most those asked for (written out by hand)
    cases = [
        (q(0.0012, "mm", 4), "1.2 mm", 3),  # 1.2 shows 2: at least 3
        (q(0.001234, "mm", 6), "1.234 mm", 4),  # 1.234 shows 4 of the 6 asked
        (q(0.0012345678, "mm", 5), "1.2346 mm", 5),  # 5 shown, 5 asked
        (q(12_345.0, "kN", 2), "12 kN", 2),  # fewer than 3 asked: as asked
        (q(2014.0, "N*m", fmt=".1f"), "2014.0 N·m", 5),  # a format: all it shows
        (q(201.4, "N*m", fmt=".0f"), "201 N·m", 3),
        (q(0.0450, "m", fmt=".4f"), "0.0450 m", 3),  # leading zeros are not digits
        (q(-1500.0, "N", fmt=".2e"), "-1.50e+03 N", 3),
    ]
    for sentence, text, digits in cases:
        (quantity,) = parts(sentence)
        assert isinstance(quantity, dict)
        assert (quantity["text"], quantity["digits"]) == (text, digits), sentence


def test_a_run_reads_its_sentences_once_and_as_if_made_at_once() -> None:
    """engine.run leaves the marks in its sentences until they are first read; what is read
    then is what plain() and parts() give of the marked sentences, and the result compares,
    copies and pickles as one made with those values."""
    import dataclasses
    import pickle

    spec = get_model("joint.vdi2230")
    r = engine.run(spec, spec.examples[0])
    assert "notes" not in vars(r) and "checks" not in vars(r)  # nothing read yet
    assert r.warnings == [] and "notes" not in vars(r)  # warnings are made at once
    again = pickle.loads(pickle.dumps(r))  # before the first reading: the marked sentences travel
    assert r.marked_notes and all("\ue000" not in n for n in r.notes)
    assert r.notes == [plain(n) for n in r.marked_notes]
    assert r.notes_parts == [parts(n) for n in r.marked_notes]
    marked_checks = [c for c in r.checks if c.marked]
    assert len(marked_checks) >= 5
    for c in marked_checks:
        assert c.detail == plain(c.marked) and c.detail_parts == parts(c.marked)
    made = dataclasses.replace(r)  # every field given, made at once
    assert made == r and again == r and repr(again) == repr(r)
    assert made.notes_parts == r.notes_parts
    with pytest.raises(AttributeError):
        r.no_such_field  # type: ignore[attr-defined]  # noqa: B018


def test_a_result_read_by_two_threads_at_once_gives_both_its_sentences() -> None:
    """Two threads reading a fresh result's notes: one's lookup misses, the other makes
    the fields and lets the marked sentences go, then the first asks for them. That
    moment, set up by hand: the sentence field is answered, not an AttributeError (4
    threads reading fresh results raised it 116 times in 3,000 trials)."""
    spec = get_model("preload.tightening")
    r = engine.run(spec, spec.examples[0])
    notes = r.notes  # the other thread's reading: the fields made, the marks let go
    assert "_marked" not in vars(r)
    for name in ("notes", "checks", "marked_notes"):
        assert type(r).__getattr__(r, name) == vars(r)[name]  # type: ignore[attr-defined]
    assert type(r).__getattr__(r, "notes") is notes  # type: ignore[attr-defined]
    with pytest.raises(AttributeError):
        type(r).__getattr__(r, "no_such_field")  # type: ignore[attr-defined]


def test_parts_and_plain_read_any_sentence_of_quantities_alike() -> None:
    """For sentences of quantities and text in any order (a seeded generator), the parts
    joined are plain()'s text, and no two texts stand side by side. (Stray marks, which no
    model writes, are left out: there the two still differ, e.g. a stray SEP … CLOSE after a
    quantity is dropped with its text by plain() and kept by parts().)"""
    import itertools
    import random

    pieces = ["a", " ", "", q(1.5, "kN"), q(2.0, "mm", bare=True), q(0.1, "%", 4), q(-0.0, "N")]
    pieces.append(q(float("nan"), "MPa", fmt=".1f"))
    rng = random.Random(28)
    for _ in range(3000):
        sentence = "".join(rng.choice(pieces) for _ in range(rng.randint(0, 7)))
        ps = parts(sentence)
        assert _joined(ps) == plain(sentence), sentence
        assert all(
            not (isinstance(a, str) and isinstance(b, str)) for a, b in itertools.pairwise(ps)
        )


@pytest.mark.parametrize("name", ["joint.vdi2230", "preload.tightening", "tool.capability"])
def test_an_answer_reads_each_sentence_once_as_the_fields_read_them(name: str) -> None:
    """answer_sentences() on a fresh result (each marked sentence read once, by split(), the
    result left unread) and on one whose sentences were read already gives what the fields
    and properties give."""
    spec = get_model(name)
    fresh = engine.run(spec, spec.examples[0])
    by_fields = engine.run(spec, spec.examples[0])
    checks, notes, notes_parts = fresh.answer_sentences()
    assert "_marked" in vars(fresh) and "checks" not in vars(fresh)  # left unread
    assert [(c.name, c.ok, c.level) for c, _, _ in checks] == [
        (c.name, c.ok, c.level) for c in by_fields.checks
    ]
    assert [detail for _, detail, _ in checks] == [c.detail for c in by_fields.checks]
    assert [ps for _, _, ps in checks] == [c.detail_parts for c in by_fields.checks]
    assert (notes, notes_parts) == (by_fields.notes, by_fields.notes_parts)
    read = by_fields.answer_sentences()  # read already: from the fields
    assert [c for c, _, _ in read[0]] == by_fields.checks
    assert [(d, ps) for _, d, ps in read[0]] == [(d, ps) for _, d, ps in checks]
    assert read[1:] == (notes, notes_parts)
    if name == "joint.vdi2230":  # marked checks and notes
        assert any("\ue000" in c.detail for c, _, _ in checks) and fresh.marked_notes


def test_an_answer_reads_unmarked_notes_and_a_check_made_readable_before() -> None:
    from engine.core.runner import RunResult
    from engine.core.spec import Check

    marked = "F = " + q(1500.0, "kN")
    checks = [
        Check("a", True, marked),
        Check("b", False, "no number", "advice"),
        Check("c", True, "F = 1.5 kN", "requirement", marked),  # plain, its marks kept
    ]
    r = RunResult._of(checks, ["a note", ""], model="m")
    (a, a_text, a_parts), b, (c, c_text, c_parts) = r.answer_sentences()[0]
    assert (a, a_text, _joined(a_parts)) == (checks[0], "F = 1.5 kN", "F = 1.5 kN")
    assert b == (checks[1], "no number", ["no number"])
    assert (c, c_text, c_parts) == (checks[2], "F = 1.5 kN", a_parts)
    assert r.answer_sentences()[1:] == (["a note", ""], [["a note"], [""]])
    assert r.marked_notes == [] and r.answer_sentences()[0][0][1:] == ("F = 1.5 kN", a_parts)
