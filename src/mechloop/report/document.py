"""The course-project report as data, apart from any typesetter: a title page, numbered
sections (each a list of blocks: paragraphs, tables, figures and subsections) and
appendices, all in one language.

:mod:`mechloop.report.pdf` typesets a :class:`Document` with Typst on A4 pages and
:mod:`mechloop.report.docx` writes the same document as an editable Word file; both number
the sections (1, 1.1, …), the figures and the tables (per top-level section: 3.1, 3.2, …)
and the appendices (A, B, … / А, Б, …) themselves, so the content carries no numbers.

Tables and figures are those of the sheets (:mod:`mechloop.views.sheet`): a table is a
caption, a header and rows of text already formatted in the user's units and precision; a
figure is a caption and a function drawing a matplotlib figure already in the document's
language.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from mechloop.views.sheet import FigureItem, Table

__all__ = ["Block", "Document", "FigureItem", "Paragraph", "Section", "Table", "TitlePage"]


@dataclass(frozen=True)
class Paragraph:
    """A paragraph of running text. ``kind``: 'text'; 'warning' (set off, e.g. a chain
    break that makes the cycle figures invalid); 'formula' (a monospaced block whose lines
    are kept as they are, e.g. the structure formula)."""

    text: str
    kind: Literal["text", "warning", "formula"] = "text"


@dataclass(frozen=True)
class Section:
    """A section: its ``title`` (without a number) and its ``blocks`` in order; a block that
    is a Section is a numbered subsection."""

    title: str
    blocks: list[Block] = field(default_factory=list)


Block = Paragraph | Table | FigureItem | Section


@dataclass(frozen=True)
class TitlePage:
    """The title page, every text already in the document's language.

    ``organisation``: the lines at the top (ministry, university, department), empty ones
    left out; ``kind``: the kind of work ("Course project", "Курсовой проект");
    ``course``: the discipline; ``title``: the work's title; ``subject``: what it is about
    (the model's name); ``people``: (label, name) pairs (student, group, supervisor), those
    without a name left out; ``place_year``: the bottom line ("Samara 2026")."""

    organisation: list[str]
    kind: str
    course: str
    title: str
    subject: str
    people: list[tuple[str, str]]
    place_year: str


@dataclass(frozen=True)
class Words:
    """The words a typesetter adds: 'Figure'/'Рис.', 'Table'/'Таблица', 'Appendix'/
    'Приложение', 'Contents'/'Содержание', and the appendices' letters."""

    figure: str
    table: str
    appendix: str
    contents: str
    letters: str


WORDS: dict[str, Words] = {
    "en": Words(figure="Figure", table="Table", appendix="Appendix", contents="Contents",
                letters="ABCDEFGHJKLMNPQRSTUVWXYZ"),
    # GOST 2.105: Cyrillic letters of the appendices without Ё, З, Й, О, Ч, Ь, Ы, Ъ
    "ru": Words(figure="Рисунок", table="Таблица", appendix="Приложение",
                contents="Содержание", letters="АБВГДЕЖИКЛМНПРСТУФХЦШЩЭЮЯ"),
}


@dataclass(frozen=True)
class Document:
    """A report: ``lang`` ('en' or 'ru'), its ``title`` page, numbered ``sections`` and
    lettered ``appendices``; ``name``: the document's name in the file's metadata."""

    lang: str
    name: str
    title: TitlePage
    sections: list[Section]
    appendices: list[Section] = field(default_factory=list)

    @property
    def words(self) -> Words:
        return WORDS[self.lang]


def walk(blocks: list[Block]):
    """Every block of ``blocks`` and of their subsections, depth first, in order."""
    for block in blocks:
        yield block
        if isinstance(block, Section):
            yield from walk(block.blocks)
