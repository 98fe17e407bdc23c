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

__all__ = ["Block", "Document", "FigureItem", "Numbered", "Paragraph", "Section", "Table",
           "TitlePage", "Words", "caption", "heading", "numbered", "texts", "walk"]


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


@dataclass(frozen=True)
class Numbered:
    """A block with its number as the typesetters print it.

    ``number``: '2', '2.1', '2.1.3' for a section (or 'А', 'А.1' in an appendix); '3.2'
    for a figure or a table (counted per top-level section or appendix, figures and
    tables apart); '' for a paragraph. ``depth``: 1 for a top-level section or appendix, 2
    for its subsection, …; for other blocks the depth of the section holding them.
    ``appendix``: whether the block is in an appendix."""

    block: Block
    number: str
    depth: int
    appendix: bool


def numbered(document: Document):
    """Every block of ``document`` in order with its number (:class:`Numbered`)."""
    tops = [(str(k), s, False) for k, s in enumerate(document.sections, start=1)]
    tops += [(document.words.letters[k], s, True) for k, s in enumerate(document.appendices)]
    for top, section, appendix in tops:
        yield Numbered(section, top, 1, appendix)
        counts = {"figure": 0, "table": 0}
        yield from _numbered_blocks(section.blocks, top, top, 2, appendix, counts)


def _numbered_blocks(blocks, top: str, prefix: str, depth: int, appendix: bool,
                     counts: dict[str, int]):
    sub = 0
    for block in blocks:
        if isinstance(block, Section):
            sub += 1
            number = f"{prefix}.{sub}"
            yield Numbered(block, number, depth, appendix)
            yield from _numbered_blocks(block.blocks, top, number, depth + 1, appendix,
                                        counts)
        elif isinstance(block, FigureItem | Table):
            kind = "figure" if isinstance(block, FigureItem) else "table"
            counts[kind] += 1
            yield Numbered(block, f"{top}.{counts[kind]}", depth - 1, appendix)
        else:
            yield Numbered(block, "", depth - 1, appendix)


def caption(document: Document, item: Numbered) -> str:
    """The caption line of a numbered figure or table: 'Figure 3.1 — …' /
    'Рисунок 3.1 — …', 'Table 2.1 — …' / 'Таблица 2.1 — …' (GOST 2.105: a table's caption
    above it, a figure's below)."""
    word = (document.words.figure if isinstance(item.block, FigureItem)
            else document.words.table)
    return f"{word} {item.number} — {item.block.caption}"


def heading(document: Document, item: Numbered) -> str:
    """The heading line of a numbered section: '3.1 Title'; an appendix:
    'Appendix A. Title' / 'Приложение А. Title'."""
    if item.appendix and item.depth == 1:
        return f"{document.words.appendix} {item.number}. {item.block.title}"
    return f"{item.number} {item.block.title}"


def texts(document: Document) -> list[str]:
    """Every text of ``document`` in order: its name, the title page, the section titles,
    paragraphs, captions, table headers and cells (for checks of its words)."""
    t = document.title
    out = [document.name, *t.organisation, t.kind, t.course, t.title, t.subject,
           t.place_year, *(text for pair in t.people for text in pair)]
    for section in [*document.sections, *document.appendices]:
        out.append(section.title)
        for block in walk(section.blocks):
            if isinstance(block, Section):
                out.append(block.title)
            elif isinstance(block, Paragraph):
                out.append(block.text)
            elif isinstance(block, FigureItem):
                out.append(block.caption)
            else:
                out += [block.caption, *block.header, *(c for row in block.rows for c in row)]
    return out
