"""The front of the DOCX report: the title page (GOST 7.32 layout: the organisation at the
top, the kind of work, the course, the title and the subject in the middle, the people on
the right, the place and year at the bottom, no page number) and the contents page (a Word
TOC field, filled in advance with the headings and a PAGEREF field per heading, so that it
reads right before Word updates it on opening).
"""

from __future__ import annotations

from docx.enum.text import WD_ALIGN_PARAGRAPH
from docx.oxml import OxmlElement
from docx.oxml.ns import qn
from docx.shared import Mm, Pt

from mechloop.report.document import TitlePage
from mechloop.report.docx_ooxml import clean, field_begin, field_end, simple_field

__all__ = ["TOC_CODE", "bookmark", "contents_page", "page_numbers", "title_page"]

#: The table of contents: heading levels 1–3, entries linked to the headings (\h), no tab
#: leader and page numbers in Web view (\z), the headings' outline levels (\u).
TOC_CODE = 'TOC \\o "1-3" \\h \\z \\u'


def title_page(doc, title: TitlePage, section) -> None:
    """Write the title page at the start of ``doc``; ``title.place_year`` goes into the
    first page's footer of ``section``, so it stays at the bottom of the page however long
    the lines above are."""
    for line in title.organisation:
        doc.add_paragraph(clean(line), style="Title Page")
    kind = doc.add_paragraph(style="Title Page")
    kind.paragraph_format.space_before = Mm(55)
    run = kind.add_run(clean(title.kind))
    run.bold = True
    run.font.all_caps = True
    run.font.size = Pt(16)
    course = doc.add_paragraph(clean(title.course), style="Title Page")
    course.paragraph_format.space_before = Pt(6)
    name = doc.add_paragraph(style="Title Page")
    name.paragraph_format.space_before = Pt(24)
    name.paragraph_format.space_after = Pt(12)
    run = name.add_run(clean(title.title))
    run.bold = True
    run.font.size = Pt(20)
    doc.add_paragraph(clean(title.subject), style="Title Page")
    for k, (label, person) in enumerate(title.people):
        line = doc.add_paragraph(f"{clean(label)}: {clean(person)}", style="Title Page")
        line.alignment = WD_ALIGN_PARAGRAPH.LEFT
        line.paragraph_format.left_indent = Mm(90)
        line.paragraph_format.space_before = Mm(40) if k == 0 else Pt(6)
    bottom = section.first_page_footer.paragraphs[0]
    bottom.text = clean(title.place_year)
    bottom.alignment = WD_ALIGN_PARAGRAPH.CENTER


def page_numbers(section) -> None:
    """The page number (a PAGE field) centred in the footer of every page but the
    first."""
    footer = section.footer
    footer.is_linked_to_previous = False
    paragraph = footer.paragraphs[0]
    paragraph.alignment = WD_ALIGN_PARAGRAPH.CENTER
    simple_field(paragraph, "PAGE", "2")


def contents_page(doc, word: str, entries: list[tuple[int, str, str]]) -> None:
    """The contents page: the heading ``word`` ('Contents', 'Содержание') and a TOC field
    whose shown result lists ``entries`` — (level, text, bookmark) of every heading of
    level 1–3 — each with a PAGEREF field to its heading's bookmark."""
    doc.add_paragraph(word, style="TOC Heading")
    if not entries:
        paragraph = doc.add_paragraph(style="toc 1")
        field_begin(paragraph, TOC_CODE)
        field_end(paragraph)
        return
    for k, (level, text, mark) in enumerate(entries):
        paragraph = doc.add_paragraph(style=f"toc {level}")
        if k == 0:
            field_begin(paragraph, TOC_CODE)
        paragraph.add_run(text)
        paragraph.add_run("\t")
        simple_field(paragraph, f"PAGEREF {mark} \\h", "")
        if k == len(entries) - 1:
            field_end(paragraph)


def bookmark(paragraph, name: str, number: int) -> None:
    """Put the bookmark ``name`` (id ``number``) around the whole of ``paragraph``."""
    start = OxmlElement("w:bookmarkStart")
    start.set(qn("w:id"), str(number))
    start.set(qn("w:name"), name)
    end = OxmlElement("w:bookmarkEnd")
    end.set(qn("w:id"), str(number))
    p = paragraph._p
    ppr = p.pPr
    if ppr is not None:
        ppr.addnext(start)
    else:
        p.insert(0, start)
    p.append(end)
