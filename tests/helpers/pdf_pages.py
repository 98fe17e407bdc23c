"""Pages of a typeset PDF read back with pypdfium2: their texts and the characters outside
the GOST text area (left 30, right 15, top and bottom 20 mm)."""

from __future__ import annotations

import ctypes

import pypdfium2
import pypdfium2.raw as pdfium_c
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
    """Per page the characters (text, left, bottom, right, top) outside the text area
    (pdfium's own calls per character: pypdfium2's ``get_text_range(i, 1)`` and
    ``get_charbox(i)`` take twice as long on a report's ~90,000 characters)."""
    document = pypdfium2.PdfDocument(path)
    box = [ctypes.c_double() for _ in range(4)]  # left, right, bottom, top
    pages = []
    for page in document:
        textpage = page.get_textpage()
        out = []
        for i in range(textpage.count_chars()):
            code = pdfium_c.FPDFText_GetUnicode(textpage, i)
            char = "\ufffe" if code == 2 else chr(code)  # a hyphenated line end's mark,
            # as the page's text has it
            if not char.strip():
                continue
            if not pdfium_c.FPDFText_GetCharBox(textpage, i, *box):
                raise pypdfium2.PdfiumError(f"no box of character {i}")
            left, right, bottom, top = (v.value for v in box)
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
