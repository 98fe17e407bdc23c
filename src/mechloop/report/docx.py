"""The report as an editable Word file (DOCX) beside the PDF: the same title page,
numbered sections, tables and figures (:mod:`mechloop.report.document`), laid out as a
Russian student's explanatory note (GOST 7.32) that the student edits and binds.

The page and the styles are in :mod:`.docx_styles`, the title and contents pages in
:mod:`.docx_front`, the tables in :mod:`.docx_table`. Headings use Word's Heading 1–3
styles with the numbers of :func:`~mechloop.report.document.numbered` in their text (no
Word list numbering, so the numbers are those of the PDF); a top-level section or an
appendix starts a new page. Figures are PNG pictures of about 200 dots per inch at the
text width. Texts lose the control characters XML cannot hold (:func:`.docx_ooxml.clean`).
"""

from __future__ import annotations

import io
import sys
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import docx
from docx.enum.section import WD_SECTION
from docx.enum.text import WD_ALIGN_PARAGRAPH
from docx.oxml.ns import qn
from docx.shared import Emu, Length, Pt

from mechloop.output.atomic import atomic_file
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
from mechloop.report.docx_front import bookmark, contents_page, page_numbers, title_page
from mechloop.report.docx_ooxml import clean, set_settings, shrink_mark
from mechloop.report.docx_styles import (
    FIGURE_HEIGHT,
    LANDSCAPE_WIDTH,
    LANGUAGES,
    TEXT_WIDTH,
    set_page,
    set_styles,
)
from mechloop.report.docx_table import cleaned, fits, table_element
from mechloop.views.save_once import save_once

__all__ = ["DPI", "write_docx"]

#: Dots per inch of the figures as printed.
DPI = 200

Progress = Callable[[int, int], None]


def write_docx(document: Document, path, *, progress: Progress | None = None) -> Path:
    """Write ``document`` as a Word file at ``path`` and return its path.

    ``progress(done, total)`` is called after each figure is drawn (``total``: the
    number of figures). The file is written atomically: on any error (a figure that
    cannot be drawn, a full disk) nothing is left at ``path`` and a file already there
    stays as it was."""
    doc = build_docx(document, progress=progress)
    target = Path(path)
    with atomic_file(target) as handle:
        doc.save(handle)
    return target


def build_docx(document: Document, *, progress: Progress | None = None):
    """The python-docx document of ``document`` (see :func:`write_docx`)."""
    doc = docx.Document()
    section = doc.sections[0]
    set_page(section)
    set_styles(doc, document.lang)
    for rid, rel in list(doc.part.rels.items()):  # Word 2010's copy of the template's
        if rel.reltype.endswith("/stylesWithEffects"):  # styles: it would not be ours
            doc.part.rels.pop(rid)
    settings = doc.settings.element
    for proof in settings.findall(qn("w:proofState")):  # the template says "checked"
        settings.remove(proof)
    language = LANGUAGES.get(document.lang, "en-US")
    set_settings(settings, lang=language)
    _properties(doc, document, language)

    title_page(doc, document.title, section)
    page_numbers(section)
    items = list(numbered(document))
    marks = {id(item): f"_Toc{k:06d}" for k, item in enumerate(items)
             if isinstance(item.block, Section)}
    entries = [(item.depth, clean(heading(document, item)), marks[id(item)])
               for item in items if isinstance(item.block, Section) and item.depth <= 3]
    contents_page(doc, document.words.contents, entries)

    total = sum(isinstance(item.block, FigureItem) for item in items)
    ids = {"grid": doc.styles["Table Grid"].style_id,
           "cell": doc.styles["Table Text"].style_id,
           "header": doc.styles["Table Header"].style_id}
    done = 0
    after_table = False
    landscape = False
    for k, (item, wide) in enumerate(zip(items, _landscape(items), strict=True)):
        block = item.block
        if wide != landscape:  # a table too wide for A4 portrait: on landscape pages
            set_page(doc.add_section(WD_SECTION.NEW_PAGE), landscape=wide, first=False)
            shrink_mark(doc.element.body.findall(qn("w:p"))[-1])  # the break's paragraph
            landscape = wide
        if isinstance(block, Section):
            _heading(doc, document, item, marks[id(item)], k)
        elif isinstance(block, Paragraph):
            _paragraph(doc, block, space_before=after_table)
        elif isinstance(block, Table):
            _table(doc, document, item, ids, LANDSCAPE_WIDTH if wide else TEXT_WIDTH)
        else:
            _figure(doc, document, item)
            done += 1
            if progress is not None:
                progress(done, total)
        after_table = isinstance(block, Table)
    return doc


def _landscape(items: list[Numbered]) -> list[bool]:
    """Per block, whether it goes on a landscape page: a table too wide for the portrait
    text width even at the smallest font, and the headings just above it (a heading
    stays with its table)."""
    out = [isinstance(item.block, Table)
           and not fits(*cleaned(item.block.header, item.block.rows), TEXT_WIDTH.twips)
           for item in items]
    for k in range(len(items) - 2, -1, -1):
        if isinstance(items[k].block, Section) and out[k + 1]:
            out[k] = True
    return out


def _properties(doc, document: Document, language: str) -> None:
    """The file's metadata: the title is the document's name; nothing of the template
    ('python-docx' as the author) is left."""
    core = doc.core_properties
    now = datetime.now(UTC).replace(microsecond=0)
    core.title = clean(document.name)
    core.subject = clean(document.title.title)
    core.language = language
    core.author = ""
    core.last_modified_by = ""
    core.comments = ""
    core.keywords = ""
    core.category = ""
    core.created = now
    core.modified = now
    core.revision = 1


def _heading(doc, document: Document, item: Numbered, mark: str, number: int) -> None:
    paragraph = doc.add_paragraph(clean(heading(document, item)),
                                  style=f"Heading {min(item.depth, 9)}")
    if item.appendix and item.depth == 1:  # GOST 2.105: an appendix's heading centred
        paragraph.alignment = WD_ALIGN_PARAGRAPH.CENTER
        paragraph.paragraph_format.first_line_indent = 0
    bookmark(paragraph, mark, number)


def _paragraph(doc, block: Paragraph, *, space_before: bool) -> None:
    """A paragraph of text or a warning (each line of it a paragraph: a line break
    would stretch a justified line), or a formula (one paragraph, its lines kept)."""
    text = clean(block.text)
    if block.kind == "formula":
        paragraphs = [doc.add_paragraph(text, style="Formula")]
    else:
        style = "Warning" if block.kind == "warning" else "Normal"
        paragraphs = [doc.add_paragraph(line, style=style) for line in text.split("\n")]
    if space_before:
        paragraphs[0].paragraph_format.space_before = Pt(12)


def _table(doc, document: Document, item: Numbered, ids: dict[str, str],
           width: Length) -> None:
    """The caption above the table (kept with it), then the table ``width`` wide."""
    table: Table = item.block
    line = doc.add_paragraph(clean(caption(document, item)), style="Caption")
    line.alignment = WD_ALIGN_PARAGRAPH.LEFT
    line.paragraph_format.keep_with_next = True
    line.paragraph_format.space_before = Pt(12)
    line.paragraph_format.space_after = Pt(3)
    element = table_element(table.header, table.rows, width=width.twips, styles=ids)
    line._p.addnext(element)


def _figure(doc, document: Document, item: Numbered) -> None:
    """The figure drawn as a PNG at the text width (a tall one at the height that leaves
    room for its caption), centred, kept with its caption below it."""
    figure = item.block.draw()
    try:
        inches_w, inches_h = figure.get_size_inches()
        width = Emu(int(min(TEXT_WIDTH, FIGURE_HEIGHT * inches_w / inches_h)))
        dpi = DPI * width.inches / inches_w
        picture = io.BytesIO()
        save_once(figure, picture, format="png", dpi=dpi, facecolor="white")
    finally:
        pyplot = sys.modules.get("matplotlib.pyplot")
        if pyplot is not None:
            pyplot.close(figure)
    picture.seek(0)
    holder = doc.add_paragraph(style="Figure")
    shape = holder.add_run().add_picture(picture, width=width)
    text = clean(caption(document, item))
    shape._inline.docPr.set("descr", text)  # the alternative text: what it shows
    doc.add_paragraph(text, style="Caption")
