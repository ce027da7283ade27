"""parts() reads the quantities q() wrote in one loop without joining helpers, and hands any
sentence with a mark outside such a quantity to the piece-by-piece reader
(engine.core.text._parts_marked): the two give the same parts for every sentence."""

from __future__ import annotations

import re

import pytest

import engine
from engine.core.text import CLOSE, OPEN, SEP, _parts_marked, parts, plain, q, split
from engine.models import MODELS


def _sentences() -> list[str]:
    out: list[str] = []
    for spec in MODELS:
        result = engine.run(spec, spec.examples[0])
        out += [c.marked or c.detail for c in result.checks]
        out += result.marked_notes or result.notes
    return out


def test_every_first_examples_sentence_reads_as_the_piece_by_piece_reader() -> None:
    sentences = [s for s in _sentences() if OPEN in s]
    assert len(sentences) > 20
    for s in sentences:
        assert parts(s) == _parts_marked(s), s


GOOD = q(23_790.0, "kN")


@pytest.mark.parametrize(
    "sentence",
    [
        "a" + OPEN + "b" + SEP + "c",
        GOOD + CLOSE,
        SEP + GOOD,
        OPEN + GOOD,
        GOOD[:-1],
        OPEN + "t" + SEP + "zz" + SEP + "kN" + SEP + "3" + SEP + CLOSE,  # not hex
        OPEN + "t" + SEP + "00" * 8 + SEP + "kN" + SEP + "x:1" + SEP + CLOSE,  # bad digits
        OPEN + "t" + SEP + "00" * 8 + SEP + "furlong" + SEP + "3" + SEP + CLOSE,
        OPEN + "t" + SEP + "00 " * 8 + SEP + "kN" + SEP + "3" + SEP + CLOSE,  # spaced hex
        OPEN,
        q(float("nan"), "mm") + " then " + q(float("inf"), "mm", 5),
    ],
)
def test_a_sentence_with_stray_marks_reads_as_before(sentence: str) -> None:
    assert parts(sentence) == _parts_marked(sentence)


def test_a_quantity_written_with_four_digits_carries_them_by_hand() -> None:
    # 0.001234 m in mm with 4 digits: "1.234 mm", 4 digits shown
    (quantity,) = parts(q(0.001234, "mm", 4))
    assert isinstance(quantity, dict)
    assert (quantity["text"], quantity["digits"], quantity["value"]) == ("1.234 mm", 4, 0.001234)
    # 0.0012 m with 4 digits writes "1.2 mm": the parts carry at least 3
    (short,) = parts(q(0.0012, "mm", 4))
    assert isinstance(short, dict) and short["digits"] == 3
    assert plain("x " + q(float("nan"), "kN")) == "x nan kN"
    nan = parts("x " + q(float("nan"), "kN"))[1]
    assert isinstance(nan, dict) and (nan["value"], nan["digits"]) == (None, 3)


@pytest.mark.parametrize(
    "sentence",
    [
        "a" + SEP + "x" + OPEN + "y" + CLOSE + " b",  # the data's pattern runs over a mark
        SEP + "x" + OPEN + GOOD,
        GOOD + SEP + OPEN + CLOSE,
        OPEN + "t" + SEP + "u" + SEP + "v" + CLOSE,  # three fields: dropped as before
        GOOD + " and " + q(0.0254, "mm", 4),
    ],
)
def test_plain_reads_a_sentence_with_stray_marks_as_before(sentence: str) -> None:
    # the reading before: the data dropped up to a closing mark with no opening mark
    # between, the opening marks dropped, parts() where a mark was left over
    before = re.sub(f"{SEP}[^{OPEN}{CLOSE}]*{CLOSE}", "", sentence).replace(OPEN, "")
    if SEP in before or CLOSE in before:
        before = "".join(p if isinstance(p, str) else p["text"] for p in parts(sentence))
    assert plain(sentence) == before


@pytest.mark.parametrize(
    "sentence",
    [
        "a" + SEP + "x" + OPEN + "y" + CLOSE + " b",
        GOOD + SEP + OPEN + CLOSE,
        GOOD + " x" + SEP + "y" + CLOSE + " z",  # separator … closing mark after a quantity
        CLOSE + GOOD,
        GOOD + " and " + q(0.0254, "mm", 4) + " then " + q(2.0, "kN", bare=True),
        "no quantity",
        "",
    ],
)
def test_split_reads_a_sentence_as_plain_and_parts_apart(sentence: str) -> None:
    # one reading where no mark stands outside a quantity; plain()'s where one does
    assert split(sentence) == (plain(sentence), parts(sentence))


def test_a_digits_field_is_read_once_and_a_bad_one_refused_each_time(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from engine.core import text

    monkeypatch.setattr(text, "_LIMITS", {})  # room whatever other tests have read
    _LIMITS, _digits = text._LIMITS, text._digits
    assert _digits("4:5", "1.234 mm") == _digits("4:5", "1.234 mm") == 4
    assert _LIMITS["4:5"] == (4, 5) and _digits(":6", "2014.0 N·m") == 5
    assert _digits("6:9", "12345.6 N") == 6 and _digits("2", "12 mm") == 2
    for bad in ("x:1", "", "4:"):
        with pytest.raises(ValueError):
            _digits(bad, "1.0 mm")
        assert bad not in _LIMITS
