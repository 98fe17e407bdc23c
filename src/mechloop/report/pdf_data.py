"""A report document as the JSON data of the Typst template (:file:`template.typ`).

The template reads the data with ``json(...)`` and sets every text as a string, never as
markup, so any character of a model name, caption or cell prints as it is. The data holds
the numbers and captions of :func:`mechloop.report.document.numbered` (Typst numbers
nothing itself), each table split in the parts that fit the page
(:func:`~mechloop.report.pdf_layout.table_parts`) with its cells' alignment, and each
figure's image file and size.
"""

from __future__ import annotations

import re

from mechloop.errors import HintedError
from mechloop.report.document import (
    Document,
    FigureItem,
    Numbered,
    Paragraph,
    Section,
    Table,
    caption,
    heading,
    numbered,
)
from mechloop.report.fonts import missing_glyphs
from mechloop.report.pdf_layout import figure_size, is_number, table_parts

#: The caption of a table's later part when it is split by columns (GOST 2.105).
CONTINUED = {"en": "{word} {number} (continued)", "ru": "Продолжение таблицы {number}"}


class TypesetError(HintedError):
    """The report cannot be typeset (a sign no font has, Typst failing)."""


#: A word longer than this many characters (a path, a long name) gets a line break
#: opportunity (a zero-width space, U+200B, which the PDF's text holds) every
#: :data:`CHUNK` characters, so that it wraps inside the page instead of running off it.
LONG_WORD = 60
CHUNK = 20
_LONG = re.compile(rf"\S{{{LONG_WORD + 1},}}")


def _breakable(word: re.Match) -> str:
    text = word.group()
    return "\u200b".join(text[k:k + CHUNK] for k in range(0, len(text), CHUNK))


def _plain(text: str, *, tabs: int = 0) -> str:
    """``text`` with its line ends as ``\\n``, tabs as spaces (to the next multiple of
    ``tabs`` columns, or one space) and long words breakable."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    text = text.expandtabs(tabs) if tabs else text.replace("\t", " ")
    return _LONG.sub(_breakable, text)


def table_data(document: Document, item: Numbered) -> list[dict]:
    """The parts of the numbered table ``item`` as the template sets them."""
    table: Table = item.block
    header = tuple(_plain(h) for h in table.header)
    rows = [tuple(_plain(c) for c in row) for row in table.rows]
    width = max([len(header), *(len(r) for r in rows)])
    header = header + ("",) * (width - len(header))
    rows = [row + ("",) * (width - len(row)) for row in rows]
    parts = []
    for k, part in enumerate(table_parts(header, rows)):
        title = _plain(caption(document, item)) if k == 0 else CONTINUED[
            document.lang].format(word=document.words.table, number=item.number)
        parts.append({
            "kind": "table", "caption": title, "size": part.size, "widths": part.widths,
            "header": [header[j] for j in part.columns],
            "rows": [[row[j] for j in part.columns] for row in rows],
            "right": [[is_number(row[j]) for j in part.columns] for row in rows],
        })
    return parts


def document_data(document: Document, figure_files: dict[int, tuple[str, float, float]]
                  ) -> dict:
    """The template's data of ``document``; ``figure_files``: per figure block's ``id``
    its image file (relative to the template) and its width and height, inches."""
    blocks: list[dict] = []
    for item in numbered(document):
        block = item.block
        if isinstance(block, Section):
            blocks.append({"kind": "heading", "text": _plain(heading(document, item)),
                           "depth": item.depth})
        elif isinstance(block, Table):
            blocks.extend(table_data(document, item))
        elif isinstance(block, FigureItem):
            file, width_in, height_in = figure_files[id(block)]
            text = _plain(caption(document, item))
            width, height = figure_size(width_in, height_in, text)
            blocks.append({"kind": "figure", "caption": text, "file": file,
                           "width": width, "height": height})
        elif isinstance(block, Paragraph):
            tabs = 4 if block.kind == "formula" else 0
            blocks.append({"kind": block.kind, "text": _plain(block.text, tabs=tabs)})
    title = document.title
    data = {
        "lang": document.lang, "name": document.name, "contents": document.words.contents,
        "title": {"organisation": [_plain(t) for t in title.organisation],
                  "kind": _plain(title.kind), "course": _plain(title.course),
                  "title": _plain(title.title), "subject": _plain(title.subject),
                  "people": [[_plain(a), _plain(b)] for a, b in title.people],
                  "place_year": _plain(title.place_year)},
        "blocks": blocks,
    }
    check_glyphs(data)
    return data


def _texts(data: dict):
    """(text, role, bold) of every text of the template's ``data``."""
    title = data["title"]
    for text in [*title["organisation"], title["course"], title["subject"],
                 title["place_year"], *(label for label, _ in title["people"]),
                 *(name for _, name in title["people"]), data["contents"], data["name"]]:
        yield text, "text", False
    yield title["kind"], "text", False
    yield title["title"], "text", True
    for block in data["blocks"]:
        kind = block["kind"]
        if kind == "heading":
            yield block["text"], "text", True
            yield block["text"], "text", False  # the contents' line
        elif kind == "table":
            yield block["caption"], "text", False
            for text in block["header"]:
                yield text, "text", True
            for row in block["rows"]:
                for text in row:
                    yield text, "text", False
        elif kind == "figure":
            yield block["caption"], "text", False
        elif kind == "formula":
            yield block["text"], "mono", False
        else:
            yield block["text"], "text", kind == "warning"


def check_glyphs(data: dict) -> None:
    """Raise :class:`TypesetError` naming the characters of ``data`` that no font of the
    report has (Typst would print them as empty boxes)."""
    missing: dict[str, str] = {}
    for text, role, bold in _texts(data):
        for char in missing_glyphs(text, role=role, bold=bold):
            missing.setdefault(char, text)
    if missing:
        signs = ", ".join(f"{c!r} (U+{ord(c):04X}) in {t[:60]!r}"
                          for c, t in sorted(missing.items()))
        raise TypesetError(f"the report's fonts have no sign for {signs}",
                           "replace these characters in the model file (names, captions, "
                           "report texts) by ones in the Latin, Cyrillic or Greek alphabets "
                           "or the usual mathematical signs")
