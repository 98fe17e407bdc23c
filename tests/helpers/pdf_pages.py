"""Pages of a typeset PDF read back with pypdfium2: their texts and the characters outside
the GOST text area (left 30, right 15, top and bottom 20 mm)."""

from __future__ import annotations

import pypdfium2
import pytest

MM = 72 / 25.4
A4 = (210 * MM, 297 * MM)
#: The text area, pt from the lower left corner: left 30, right 15, top and bottom 20 mm.
AREA = (30 * MM, 20 * MM, (210 - 15) * MM, (297 - 20) * MM)
TOLERANCE = 1 * MM


def normal(text: str) -> str:
    """``text`` with the marks of hyphenated line ends and the zero-width spaces that
    break long words dropped and white space as single spaces."""
    return " ".join(text.replace("\ufffe", "").replace("\u200b", "").split())


def page_texts(path) -> list[str]:
    document = pypdfium2.PdfDocument(path)
    try:
        return [page.get_textpage().get_text_range() for page in document]
    finally:
        document.close()


def _outside(path):
    """Per page the characters (text, left, bottom, right, top) outside the text area."""
    document = pypdfium2.PdfDocument(path)
    pages = []
    for page in document:
        textpage = page.get_textpage()
        out = []
        for i in range(textpage.count_chars()):
            char = textpage.get_text_range(i, 1)
            if not char.strip():
                continue
            left, bottom, right, top = textpage.get_charbox(i)
            if (left < AREA[0] - TOLERANCE or right > AREA[2] + TOLERANCE
                    or bottom < AREA[1] - TOLERANCE or top > AREA[3] + TOLERANCE):
                out.append((char, left, bottom, right, top))
        pages.append(out)
    document.close()
    return pages


def check_text_area(path):
    """Every character is inside the text area but the page number, which is centred in
    the bottom margin on every page but the title page."""
    pages = _outside(path)
    assert pages[0] == []
    centre = (AREA[0] + AREA[2]) / 2
    for number, out in enumerate(pages[1:], start=2):
        assert "".join(c[0] for c in out) == str(number), number
        left, right = min(c[1] for c in out), max(c[3] for c in out)
        assert (left + right) / 2 == pytest.approx(centre, abs=1.5 * MM)
        assert all(AREA[1] - 15 * MM < c[2] and c[4] < AREA[1] for c in out)
