"""A report table as a Word table: the grid style, the header row bold and repeated on
every page the table runs onto, rows never split across pages, numbers right-aligned
(:func:`numeric_columns`), the
columns fitted to the text width and the font made smaller (12 pt down to 8 pt) only as far
as the longest unbreakable words need.

The table is written as one piece of XML (python-docx builds cell by cell, which is slow
for the appendix tables of every position: hundreds of rows).
"""

from __future__ import annotations

import re

from docx.oxml import parse_xml
from docx.oxml.ns import nsdecls

from mechloop.report.docx_ooxml import clean, runs_xml

__all__ = ["cleaned", "column_widths", "fits", "is_number", "numeric_columns", "table_element",
           "text_em"]

#: Font sizes tried for a table, points, largest first.
SIZES = (12, 11, 10, 9, 8)
#: Left and right margin inside a cell, twentieths of a point (1.5 mm).
CELL_MARGIN = 85

_ONE = r"[+-]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+-]?\d+|·10[⁻⁺]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?%?"
#: One number, or a range of two ('0 … 360', '0.15...0.25', '10–20').
_NUMBER = re.compile(rf"{_ONE}(?:(?:…|\.\.\.?|–){_ONE})?")
_SPACES = re.compile(r"[\s\u00a0\u2009\u202f]")


def is_number(text: str) -> bool:
    """Whether a cell's ``text`` is one number (with a sign '-', '+' or the Unicode minus
    '−', a decimal point or comma, an exponent, thin spaces between digit groups, a
    trailing '%') or a range of two ('0 … 360')."""
    text = _SPACES.sub("", text.replace("−", "-"))
    return bool(_NUMBER.fullmatch(text))


def numeric_columns(rows: list[tuple[str, ...]], count: int) -> list[bool]:
    """Per column, whether its numbers are right-aligned: when at least half of its
    non-empty cells are numbers (:func:`is_number`); in a column of words a number stays
    left-aligned with them."""
    numbers = [0] * count
    filled = [0] * count
    for row in rows:
        for k, cell in enumerate(row):
            if cell.strip():
                filled[k] += 1
                numbers[k] += is_number(cell)
    return [2 * n >= f > 0 for n, f in zip(numbers, filled, strict=True)]


def text_em(text: str) -> float:
    """An estimate of the width of ``text`` in Times New Roman, in em (font sizes):
    digits and most lower-case letters half an em, capitals 0.72, wide letters 0.9,
    narrow letters, spaces and punctuation 0.28–0.33."""
    width = 0.0
    for char in text:
        if char in " .,:;'!|ilIj":
            width += 0.28
        elif char in "ft()[]-r/":
            width += 0.34
        elif char in "—…%@mwMWЖжШшЩщЮюМмФфы":
            width += 0.9
        elif char.isupper():
            width += 0.72
        else:
            width += 0.56 if char == "−" else 0.5
    return width


def _measure(header: tuple[str, ...], rows: list[tuple[str, ...]]):
    """Per column, the widths (em) of its longest unbreakable word and of its longest
    line (the header in bold)."""
    count = len(header)
    words = [0.0] * count
    lines = [0.0] * count
    for k, name in enumerate(header):
        for line in name.split("\n"):
            words[k] = max(words[k], *(1.1 * text_em(w) for w in line.split() or [""]))
            lines[k] = max(lines[k], 1.1 * text_em(line))
    for row in rows:
        for k, cell in enumerate(row):
            for line in cell.split("\n"):
                lines[k] = max(lines[k], text_em(line))
                words[k] = max(words[k], *(text_em(w) for w in line.split() or [""]))
    return words, lines


#: The room a column needs beside its text: the cell's margins and the grid line, twips.
PADDING = 2 * CELL_MARGIN + 20


def fits(header: tuple[str, ...], rows: list[tuple[str, ...]], width: int) -> bool:
    """Whether a table's longest words fit in ``width`` twips at the smallest size."""
    words, _ = _measure(header, rows)
    return sum(w * SIZES[-1] * 20 + PADDING for w in words) <= width


def column_widths(header: tuple[str, ...], rows: list[tuple[str, ...]],
                  width: int) -> tuple[int, list[int]]:
    """The font size (points) and the column widths (twentieths of a point, summing to
    ``width``) of a table: the largest size of :data:`SIZES` at which every column holds
    its longest word; the columns then get their whole lines where the width allows,
    the rest shared in proportion to what each still lacks. (A table whose words do not
    fit even at the smallest size gets widths in proportion to them: the words break.)"""
    words, lines = _measure(header, rows)
    for size in SIZES:
        least = [w * size * 20 + PADDING for w in words]
        if sum(least) <= width:
            break
    else:
        scale = width / sum(least)
        return size, _whole([w * scale for w in least], width)
    full = [max(a, line * size * 20 + PADDING) for a, line in zip(least, lines, strict=True)]
    if sum(full) <= width:
        spare = width - sum(full)
        total = sum(full)
        return size, _whole([f + spare * f / total for f in full], width)
    lack = [f - a for f, a in zip(full, least, strict=True)]
    share = (width - sum(least)) / sum(lack)
    return size, _whole([a + share * d for a, d in zip(least, lack, strict=True)], width)


def _whole(widths: list[float], total: int) -> list[int]:
    """``widths`` rounded to integers summing to ``total``."""
    whole = [int(w) for w in widths]
    whole[-1] += total - sum(whole)
    return whole


def cleaned(header: tuple[str, ...], rows: list[tuple[str, ...]]):
    """The header and the rows with their texts :func:`clean`; ValueError for a row with
    more cells than the header (a shorter one is filled with empty cells) and for a table
    without columns."""
    if not header:
        raise ValueError("a table needs at least one column; its header is empty")
    header = tuple(clean(h) for h in header)
    rows = [tuple(clean(c) for c in row) for row in rows]
    for k, row in enumerate(rows):
        if len(row) > len(header):
            raise ValueError(f"row {k} of the table has {len(row)} cells, its header "
                             f"{len(header)}: {row!r}")
    return header, rows


def table_element(header: tuple[str, ...], rows: list[tuple[str, ...]], *, width: int,
                  styles: dict[str, str]):
    """The ``w:tbl`` element of a table with ``header`` and ``rows`` (cell texts),
    ``width`` twentieths of a point wide; ``styles``: the style ids of 'grid' (the table
    style), 'cell' and 'header' (paragraph styles)."""
    header, rows = cleaned(header, rows)
    size, widths = column_widths(header, rows, width)
    rpr = "" if size == 12 else \
        f'<w:rPr><w:sz w:val="{2 * size}"/><w:szCs w:val="{2 * size}"/></w:rPr>'
    grid = "".join(f'<w:gridCol w:w="{w}"/>' for w in widths)
    parts = [f'<w:tbl {nsdecls("w")}><w:tblPr><w:tblStyle w:val="{styles["grid"]}"/>'
             f'<w:tblW w:w="{width}" w:type="dxa"/><w:tblLayout w:type="fixed"/>'
             f'<w:tblCellMar><w:left w:w="{CELL_MARGIN}" w:type="dxa"/>'
             f'<w:right w:w="{CELL_MARGIN}" w:type="dxa"/></w:tblCellMar>'
             '<w:tblLook w:val="04A0" w:firstRow="1" w:lastRow="0" w:firstColumn="0" '
             'w:lastColumn="0" w:noHBand="1" w:noVBand="1"/></w:tblPr>'
             f"<w:tblGrid>{grid}</w:tblGrid>"]
    parts.append(_row(header, widths, styles["header"], rpr, None))
    right = numeric_columns(rows, len(header))
    for row in rows:
        cells = tuple(row) + ("",) * (len(header) - len(row))
        parts.append(_row(cells, widths, styles["cell"], rpr, right))
    parts.append("</w:tbl>")
    return parse_xml("".join(parts))


def _row(cells: tuple[str, ...], widths: list[int], style: str, rpr: str,
         right: list[bool] | None) -> str:
    """A row's XML; ``right``: per column, whether its numbers are right-aligned; None
    for the header row (repeated on every page, centred by its style)."""
    trpr = "<w:trPr><w:cantSplit/><w:tblHeader/></w:trPr>" if right is None else \
        "<w:trPr><w:cantSplit/></w:trPr>"
    out = [f"<w:tr>{trpr}"]
    for k, (text, width) in enumerate(zip(cells, widths, strict=True)):
        align = '<w:jc w:val="right"/>' if right and right[k] and is_number(text) else ""
        out.append(f'<w:tc><w:tcPr><w:tcW w:w="{width}" w:type="dxa"/></w:tcPr>'
                   f'<w:p><w:pPr><w:pStyle w:val="{style}"/>{align}</w:pPr>'
                   f"{runs_xml(text, rpr) if text else ''}</w:p></w:tc>")
    out.append("</w:tr>")
    return "".join(out)
