"""The content of one course-project sheet as data, apart from the page layout: its title,
its figures (each a caption and a function that draws it), its tables (a caption, a header
and rows of text) and its paragraphs, all in one language.

The report (:mod:`mechloop.report.sheets`) makes a :class:`Sheet` a section of its
document, which the PDF and DOCX typesetters lay out (the figures as images, the tables as
tables).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from matplotlib.figure import Figure

from mechloop.views.decimal_mark import localize_ticks, localized


@dataclass(frozen=True)
class Table:
    """A table: ``caption``, ``header`` (column names) and ``rows`` (each one text cell
    per column); ``values`` holds the number behind each row's value cell (SI, for checks)
    or None where the row has no single number."""

    caption: str
    header: tuple[str, ...]
    rows: list[tuple[str, ...]]
    values: list[float | None] = field(default_factory=list)


@dataclass(frozen=True)
class FigureItem:
    """A figure: ``caption`` and ``draw()`` returning the matplotlib figure (already in the
    sheet's language)."""

    caption: str
    draw: Callable[[], Figure]


@dataclass(frozen=True)
class Sheet:
    """Sheet ``number`` of the course project: ``title``, ``figures``, ``tables`` and
    ``paragraphs`` (the checks and conclusions in words), in ``lang``."""

    number: int
    title: str
    lang: str
    figures: list[FigureItem]
    tables: list[Table]
    paragraphs: list[str]


def translate_figure(figure: Figure, words: dict[str, str]) -> Figure:
    """Put ``figure`` in Russian: replace the phrases of ``words`` (longest first) in every
    text and write its numbers, tick labels included, with the decimal comma."""
    from matplotlib.text import Text

    ordered = sorted(words.items(), key=lambda item: -len(item[0]))
    for text in figure.findobj(Text):
        content = text.get_text()
        if not content:
            continue
        for english, other in ordered:
            content = content.replace(english, other)
        text.set_text(localized(content, "ru"))
    return localize_ticks(figure, "ru")


def localized_sheet(sheet: Sheet) -> Sheet:
    """``sheet`` with the numbers of its tables and paragraphs written as its language
    writes them (Russian: decimal comma; the figures do it when drawn)."""
    if sheet.lang != "ru":
        return sheet
    tables = [Table(localized(t.caption, "ru"), t.header,
                    [tuple(localized(cell, "ru") for cell in row) for row in t.rows],
                    t.values) for t in sheet.tables]
    paragraphs = [localized(p, "ru") for p in sheet.paragraphs]
    return Sheet(sheet.number, sheet.title, sheet.lang, sheet.figures, tables, paragraphs)


def number_text(value: float) -> str:
    """A table's number: five significant digits, without an exponent between 10⁻³ and
    10⁹."""
    size = abs(value)
    if size == 0 or not 1e-3 <= size < 1e9:
        return f"{value:.5g}"
    decimals = max(0, 4 - math.floor(math.log10(size)))
    return f"{value:.{decimals}f}".rstrip("0").rstrip(".") if decimals else f"{value:.0f}"
