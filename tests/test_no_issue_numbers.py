"""What a user or a new contributor reads says why in words, not by a tracker's number.

The README, the engine, the service and the form are read by people outside the team,
who cannot look up "issue 21"; the CHANGELOG keeps the history by number.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NUMBERED = re.compile(r"\bissues? ?#?[0-9]+", re.IGNORECASE)


def _files() -> list[Path]:
    files = [ROOT / "README.md"]
    for folder in ("engine", "service", "static"):
        files += [
            p
            for p in (ROOT / folder).rglob("*")
            if p.suffix in {".py", ".js", ".css", ".html", ".md"}
        ]
    return files


def test_the_pattern_finds_what_it_should() -> None:
    assert NUMBERED.search("a fix (issue 21)") and NUMBERED.search("Issues 21/22")
    assert not NUMBERED.search("an issue with 3 bolts") and not NUMBERED.search("tissue 2")


def test_no_issue_number_in_readme_engine_service_or_static() -> None:
    found = [
        f"{p.relative_to(ROOT)}:{n}: {line.strip()}"
        for p in _files()
        for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
        if NUMBERED.search(line)
    ]
    assert found == []
