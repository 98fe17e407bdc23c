"""The layout of a report's tables and figures on the A4 page of the typeset PDF.

Page: A4 portrait, margins left 30 mm, right 15 mm, top and bottom 20 mm (GOST 7.32), so
the text area is 165 mm × 257 mm; the text is 12 pt.

A table's columns share the text width: each gets at least the width of its longest
unbreakable word (a number never wraps) and the rest in proportion to its longest line;
the font is the largest of 11, 10, 9, 8 and 7 pt at which those least widths fit. A table
too wide even at 7 pt is split into parts of columns, each repeating the first column (the
position or name), the later ones captioned as continued. A figure is scaled to the text
width, or down to the height that leaves room for its caption and a heading above it on
one page.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from mechloop.report.fonts import text_width

MM = 72 / 25.4
#: The text area, pt.
TEXT_WIDTH = (210 - 30 - 15) * MM
TEXT_HEIGHT = (297 - 20 - 20) * MM
#: The text's font size, pt.
TEXT_SIZE = 12.0
#: A table's font sizes, pt, largest first; a table split in parts uses :data:`SPLIT_SIZE`.
TABLE_SIZES = (11.0, 10.0, 9.0, 8.0, 7.0)
SPLIT_SIZE = 8.0
#: A table cell's inset on each side, pt; the width estimates' safety factor.
CELL_INSET = 3.0
SAFETY = 1.04
#: The room kept on a figure's page for its caption's gaps and a heading above it, pt.
FIGURE_ROOM = 60.0

#: What a line may break at: white space and zero-width spaces.
_WORDS = re.compile(r"[\s\u200b]+")
_NUMBER = re.compile(r"[+\-−]?(\d[\d\u00a0\u202f]*([.,]\d*)?|[.,]\d+)"
                     r"([eE][+\-−]?\d+|·10[⁻⁺]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?%?")


def is_number(cell: str) -> bool:
    """Whether a table cell is a number ('12', '−0.25', '1.5e-3', '3,75', '−2,3·10⁴'): it
    is set right-aligned."""
    text = cell.strip()
    return bool(_NUMBER.fullmatch(text)) or text.lstrip("+-−").lower() in ("inf", "∞")


@dataclass(frozen=True)
class TablePart:
    """One part of a table as set: the ``columns`` of the table it shows (indices), their
    ``widths`` as shares of the text width and the font ``size``, pt."""

    columns: list[int]
    widths: list[float]
    size: float


def _column_widths(header, rows, columns, *, bold_header=True):
    """(least, natural) width of each of ``columns``, em: its longest word, its longest
    line (a header cell wraps at its spaces)."""
    least, natural = [], []
    for j in columns:
        cells = [row[j] for row in rows]
        words = [w for cell in cells for w in _WORDS.split(cell)]
        head_words = _WORDS.split(header[j])
        low = max([text_width(w) for w in words]
                  + [text_width(w, bold=bold_header) for w in head_words] + [0.5])
        high = max([text_width(line) for cell in cells for line in cell.splitlines()]
                   + [low])
        least.append(low)
        natural.append(high)
    return least, natural


def _fits(least: list[float], size: float) -> bool:
    return sum(SAFETY * w * size + 2 * CELL_INSET for w in least) <= TEXT_WIDTH


def _part(header, rows, columns, sizes) -> TablePart | None:
    least, natural = _column_widths(header, rows, columns)
    size = next((s for s in sizes if _fits(least, s)), None)
    if size is None:
        return None
    low = [SAFETY * w * size + 2 * CELL_INSET for w in least]
    high = [SAFETY * w * size + 2 * CELL_INSET for w in natural]
    if sum(high) <= TEXT_WIDTH:
        widths = high
    else:
        spare = TEXT_WIDTH - sum(low)
        wish = sum(h - lo for h, lo in zip(high, low, strict=True))
        widths = [lo + spare * (h - lo) / wish for h, lo in zip(high, low, strict=True)]
    total = sum(widths)
    return TablePart(list(columns), [w / total for w in widths], size)


def table_parts(header: tuple[str, ...], rows: list[tuple[str, ...]]) -> list[TablePart]:
    """The parts in which a table is set: one part when its columns fit the text width at
    7 pt or more, else parts of the columns that fit at :data:`SPLIT_SIZE`, each with the
    first column."""
    n = len(header)
    whole = _part(header, rows, range(n), TABLE_SIZES)
    if whole is not None:
        return [whole]
    least, _ = _column_widths(header, rows, range(n))
    groups: list[list[int]] = [[0]]
    for j in range(1, n):
        if len(groups[-1]) > 1 and not _fits([least[k] for k in groups[-1]] + [least[j]],
                                            SPLIT_SIZE):
            groups.append([0])
        groups[-1].append(j)
    parts = [_part(header, rows, group, (SPLIT_SIZE, *TABLE_SIZES[-1:]))
             or TablePart(group, [1 / len(group)] * len(group), TABLE_SIZES[-1])
             for group in groups]
    size = min(p.size for p in parts)
    return [TablePart(p.columns, p.widths, size) for p in parts]


def caption_height(text: str, width: float = TEXT_WIDTH) -> float:
    """The height of a caption of ``text`` set in lines of ``width`` pt, pt."""
    lines = max(1, math.ceil(SAFETY * text_width(text) * TEXT_SIZE / (0.95 * width)))
    return lines * 1.3 * TEXT_SIZE


def figure_size(width_in: float, height_in: float, caption: str) -> tuple[float, float]:
    """The (width, height), pt, of a figure drawn ``width_in`` × ``height_in`` inches: the
    text width, or less so that it, its caption and a heading fit on one page."""
    width = TEXT_WIDTH
    height = width * height_in / width_in
    room = TEXT_HEIGHT - caption_height(caption) - FIGURE_ROOM
    if height > room:
        width, height = width * room / height, room
    return width, height
