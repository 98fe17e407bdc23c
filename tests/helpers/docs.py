"""The documentation the tests read: README.md and the reference pages under docs/.

The README is the start (the two commands, a tour); the reference it links to is one page
per topic in ``docs/*.md``. The tests that check the documentation's commands, figures,
Python blocks and links read every one of these files.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: README.md first, then the pages of docs/ by name (paths relative to the repository)
PAGES: list[str] = ["README.md", *sorted(p.relative_to(ROOT).as_posix()
                                         for p in (ROOT / "docs").glob("*.md"))]


def page_text(page: str) -> str:
    """The text of one page, ``page`` relative to the repository (``docs/models.md``)."""
    return (ROOT / page).read_text(encoding="utf-8")


def all_text() -> str:
    """Every page's text, README.md first, separated by a blank line."""
    return "\n\n".join(page_text(p) for p in PAGES)
