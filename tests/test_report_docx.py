"""The editable DOCX report (issue 15): the synthetic sample document written by
:func:`mechloop.report.docx.write_docx` and read back with python-docx — the headings,
tables, figures and captions of the document in order, the A4 page, the contents and page
number fields, Russian without added English, any text surviving, nothing left on an
error."""

from __future__ import annotations

import dataclasses
import os

import docx
import pytest
from docx.oxml.ns import qn
from helpers.latin import latin_words
from helpers.report_sample import sample_document
from matplotlib.figure import Figure

from mechloop.report.document import (
    FigureItem,
    Paragraph,
    Section,
    Table,
    caption,
    heading,
    numbered,
)
from mechloop.report.document import texts as document_texts
from mechloop.report.docx import write_docx
from mechloop.report.docx_table import column_widths, is_number, numeric_columns, text_em

W = qn("w:t")


@pytest.fixture(scope="module", params=["en", "ru"])
def written(request, tmp_path_factory):
    """(the document, the python-docx document read back from the file, progress calls)."""
    document = sample_document(request.param)
    calls = []
    path = write_docx(document, tmp_path_factory.mktemp("docx") / "report.docx",
                      progress=lambda done, total: calls.append((done, total)))
    return document, docx.Document(str(path)), calls


def _body(doc):
    """The body's paragraphs and tables in order, as python-docx objects."""
    out = []
    for child in doc.element.body.iterchildren():
        if child.tag == qn("w:p"):
            out.append(docx.text.paragraph.Paragraph(child, doc))
        elif child.tag == qn("w:tbl"):
            out.append(docx.table.Table(child, doc))
    return out


def _source_texts(document) -> list[str]:
    """Every text of ``document`` (:func:`mechloop.report.document.texts`)."""
    return document_texts(document)


def _docx_texts(doc):
    """Every text of the DOCX: body paragraphs, table cells, footers."""
    texts = [p.text for p in doc.paragraphs]
    texts += [cell.text for table in doc.tables for row in table.rows for cell in row.cells]
    section = doc.sections[0]
    texts += [p.text for part in (section.footer, section.first_page_footer)
              for p in part.paragraphs]
    return texts


def test_headings_are_the_sections_in_order(written):
    document, doc, _ = written
    found = [p.text for p in doc.paragraphs if p.style.name.startswith("Heading")]
    expected = [heading(document, item) for item in numbered(document)
                if isinstance(item.block, Section)]
    assert found == expected
    levels = [p.style.name for p in doc.paragraphs if p.style.name.startswith("Heading")]
    assert levels == [f"Heading {item.depth}" for item in numbered(document)
                      if isinstance(item.block, Section)]
    assert doc.styles["Heading 1"].paragraph_format.page_break_before
    assert doc.styles["Heading 2"].paragraph_format.keep_with_next
    assert not any(p._p.find(f"{qn('w:pPr')}/{qn('w:numPr')}") is not None
                   for p in doc.paragraphs)  # the numbers are text, not Word lists


def test_tables_with_their_cells_and_captions_above(written):
    document, doc, _ = written
    tables = [item for item in numbered(document) if isinstance(item.block, Table)]
    body = _body(doc)
    found = [k for k, part in enumerate(body) if isinstance(part, docx.table.Table)]
    assert len(found) == len(tables) == len(doc.tables)
    for item, k in zip(tables, found, strict=True):
        table = body[k]
        cells = [tuple(c.text for c in row.cells) for row in table.rows]
        assert cells == [item.block.header, *item.block.rows]
        above = body[k - 1]
        assert above.text == caption(document, item)
        assert above.paragraph_format.keep_with_next
        first = table.rows[0]._tr
        assert first.find(f"{qn('w:trPr')}/{qn('w:tblHeader')}") is not None
        assert table.rows[1]._tr.find(f"{qn('w:trPr')}/{qn('w:tblHeader')}") is None
        assert all(r.text.strip() for c in table.rows[0].cells for r in c.paragraphs[0].runs)
        assert all(r.bold or c.paragraphs[0].style.font.bold
                   for c in table.rows[0].cells for r in c.paragraphs[0].runs)
        assert table.style.name == "Table Grid"
    vectors = doc.tables[0]
    align = {c.text: c.paragraphs[0].alignment for row in vectors.rows[1:] for c in row.cells}
    assert align["−12.25"] == docx.enum.text.WD_ALIGN_PARAGRAPH.RIGHT
    assert align["420.5"] == docx.enum.text.WD_ALIGN_PARAGRAPH.RIGHT
    assert align["function"] is None


def test_figures_with_their_captions_below(written):
    document, doc, calls = written
    figures = [item for item in numbered(document) if isinstance(item.block, FigureItem)]
    assert len(doc.inline_shapes) == len(figures)
    paragraphs = doc.paragraphs
    holders = [k for k, p in enumerate(paragraphs)
               if p._p.findall(f".//{qn('w:drawing')}")]
    assert len(holders) == len(figures)
    for item, k in zip(figures, holders, strict=True):
        assert paragraphs[k + 1].text == caption(document, item)
        assert paragraphs[k + 1].style.name == "Caption"
        assert paragraphs[k].style.paragraph_format.keep_with_next
        assert paragraphs[k].style.name == "Figure"
        assert paragraphs[k]._p.find(f".//{qn('wp:docPr')}").get("descr") == \
            caption(document, item)
    text_width = doc.sections[0].page_width - doc.sections[0].left_margin \
        - doc.sections[0].right_margin
    for shape in doc.inline_shapes:
        image = doc.part.related_parts[shape._inline.graphic.graphicData.pic.blipFill
                                       .blip.embed].image
        assert image.content_type == "image/png"
        assert image.px_width / (shape.width / 914400) == pytest.approx(200, rel=0.01)
        assert shape.width <= text_width + 1000
        assert shape.height <= docx.shared.Mm(210) + 1
    # the wide figure fills the text width; the tall one is as high as allowed
    assert doc.inline_shapes[0].width == pytest.approx(text_width, abs=1000)  # twips
    assert calls == [(k, len(figures)) for k in range(1, len(figures) + 1)]


def test_a4_page_with_the_margins(written):
    _, doc, _ = written
    section = doc.sections[0]
    assert len(doc.sections) == 1
    mm = {name: getattr(section, name).mm for name in
          ("page_width", "page_height", "left_margin", "right_margin", "top_margin",
           "bottom_margin")}
    assert mm == pytest.approx(dict(page_width=210, page_height=297, left_margin=30,
                                    right_margin=15, top_margin=20, bottom_margin=20),
                               abs=0.05)
    normal = doc.styles["Normal"]
    assert normal.font.name == "Times New Roman"
    assert normal.font.size.pt == 14
    assert normal.paragraph_format.line_spacing == 1.5
    assert normal.paragraph_format.first_line_indent.mm == pytest.approx(12.5, abs=0.05)


def test_contents_and_page_number_fields(written):
    document, doc, _ = written
    codes = [t.text.strip() for t in doc.element.body.iter(qn("w:instrText"))]
    assert codes.count('TOC \\o "1-3" \\h \\z \\u') == 1
    settings = doc.settings.element
    update = settings.find(qn("w:updateFields"))
    assert update is not None and update.get(qn("w:val")) == "true"
    assert settings.find(qn("w:proofState")) is None  # Word checks the spelling itself
    parts = [str(part.partname) for part in doc.part.package.iter_parts()]
    assert "/word/styles.xml" in parts
    assert not [p for p in parts if "stylesWithEffects" in p]  # one set of styles: ours
    section = doc.sections[0]
    assert section.different_first_page_header_footer
    footer = [t.text.strip() for t in section.footer._element.iter(qn("w:instrText"))]
    assert footer == ["PAGE"]
    first = section.first_page_footer
    assert not list(first._element.iter(qn("w:instrText")))
    assert [p.text for p in first.paragraphs] == [document.title.place_year]
    # the contents are there before Word updates them: the headings of levels 1-3
    toc = [p for p in doc.paragraphs if p.style.name.startswith("toc ")]
    assert [p.text.rstrip("\t") for p in toc] == [
        heading(document, item) for item in numbered(document)
        if isinstance(item.block, Section) and item.depth <= 3]
    # each with the page number of its heading (a PAGEREF to the heading's bookmark)
    marks = {m.get(qn("w:name")): p.text for p in doc.paragraphs
             for m in p._p.iter(qn("w:bookmarkStart"))}
    for entry in toc:
        refs = [t.text.split()[1] for t in entry._p.iter(qn("w:instrText"))
                if t.text.split()[0] == "PAGEREF"]
        assert [marks[r] for r in refs] == [entry.text.rstrip("\t")]
    titles = [p.text for p in doc.paragraphs if p.style.name == "TOC Heading"]
    assert titles == [document.words.contents]
    assert doc.core_properties.title == document.name
    lang = {"en": "en-US", "ru": "ru-RU"}[document.lang]
    assert doc.core_properties.language == lang
    defaults = doc.styles.element.find(qn("w:docDefaults"))
    assert defaults.find(f".//{qn('w:lang')}").get(qn("w:val")) == lang


def test_title_page(written):
    document, doc, _ = written
    t = document.title
    texts = [p.text for p in doc.paragraphs]
    first = texts.index(document.words.contents)
    expected = [*t.organisation, t.kind, t.course, t.title, t.subject,
                *(f"{label}: {name}" for label, name in t.people)]
    assert texts[:first] == expected


def test_russian_docx_adds_no_english(tmp_path):
    russian = sample_document("ru")
    names = ["\n".join(_source_texts(russian))]
    doc = docx.Document(str(write_docx(russian, tmp_path / "ru.docx")))
    assert latin_words("\n".join(_docx_texts(doc)), names) == []
    # the same check finds the English words a writer adds to the English document
    english = docx.Document(str(write_docx(sample_document("en"), tmp_path / "en.docx")))
    found = set(latin_words("\n".join(_docx_texts(english)), names))
    assert {"Contents", "Figure", "Table", "Appendix"} <= found


def test_any_text_survives(tmp_path):
    """XML's special characters stay; control characters XML cannot hold are dropped;
    a line break in a cell or a formula stays a line break."""
    special = 'a < b && c > "d" \'e\''
    noisy = "bell\x07 nul\x00 esc\x1b del\x7f end"
    base = sample_document("en", rows=3, columns=3)
    first = base.sections[0]
    table = Table(special, ("x<y", "&"), [("1 < 2", "\x01−3.5"), ("two\nlines", "")])
    document = dataclasses.replace(
        base, name=special,
        title=dataclasses.replace(base.title, title=noisy),
        sections=[dataclasses.replace(first, title=special,
                                      blocks=[Paragraph(special), Paragraph(noisy, "warning"),
                                              Paragraph("a\r\nb\tc", "formula"), table]),
                  *base.sections[1:]])
    doc = docx.Document(str(write_docx(document, tmp_path / "special.docx")))
    texts = [p.text for p in doc.paragraphs]
    assert f"1 {special}" in texts
    assert special in texts
    assert "bell nul esc del end" in texts
    assert texts.count("bell nul esc del end") == 2  # the title page and the warning
    assert "a\nb\tc" in texts
    assert f"Table 1.1 — {special}" in texts
    assert doc.core_properties.title == special
    cells = [[c.text for c in row.cells] for row in doc.tables[0].rows]
    assert cells == [["x<y", "&"], ["1 < 2", "−3.5"], ["two\nlines", ""]]


def test_an_error_leaves_no_file(tmp_path):
    def broken():
        raise RuntimeError("cannot draw")

    base = sample_document("en", rows=3, columns=3)
    document = dataclasses.replace(base, sections=[
        Section("Broken", [FigureItem("broken", broken)]), *base.sections])
    target = tmp_path / "report.docx"
    with pytest.raises(RuntimeError, match="cannot draw"):
        write_docx(document, target)
    assert os.listdir(tmp_path) == []
    target.write_bytes(b"old report")
    with pytest.raises(RuntimeError, match="cannot draw"):
        write_docx(document, target)
    assert target.read_bytes() == b"old report"
    assert os.listdir(tmp_path) == ["report.docx"]


@pytest.mark.parametrize(("bad", "message"), [
    (Table("bad", ("a", "b"), [("1", "2", "3")]), "row 0 of the table has 3 cells, its header 2"),
    (Table("bad", (), []), "a table needs at least one column")])
def test_a_malformed_table_is_refused(tmp_path, bad, message):
    base = sample_document("en", rows=3, columns=3)
    document = dataclasses.replace(base, sections=[Section("Bad", [bad])])
    with pytest.raises(ValueError, match=message):
        write_docx(document, tmp_path / "bad.docx")
    assert os.listdir(tmp_path) == []


def test_a_short_row_and_an_empty_document(tmp_path):
    base = sample_document("en", rows=3, columns=3)
    short = Table("short", ("a", "b", "c"), [("1",), ()])
    document = dataclasses.replace(base, sections=[Section("Short", [short])], appendices=[])
    doc = docx.Document(str(write_docx(document, tmp_path / "short.docx")))
    assert [[c.text for c in row.cells] for row in doc.tables[0].rows] == [
        ["a", "b", "c"], ["1", "", ""], ["", "", ""]]
    empty = dataclasses.replace(base, sections=[], appendices=[])
    doc = docx.Document(str(write_docx(empty, tmp_path / "empty.docx")))
    codes = [t.text.strip() for t in doc.element.body.iter(qn("w:instrText"))]
    assert codes == ['TOC \\o "1-3" \\h \\z \\u']
    assert not [p for p in doc.paragraphs if p.style.name.startswith("Heading")]


def test_a_tall_figure_fits_the_page_with_its_caption(tmp_path):
    base = sample_document("en", rows=3, columns=3)
    tall = FigureItem("tall", lambda: Figure(figsize=(3, 9)))
    document = dataclasses.replace(base, sections=[Section("Tall", [tall])])
    doc = docx.Document(str(write_docx(document, tmp_path / "tall.docx")))
    shape = doc.inline_shapes[0]
    assert shape.height == pytest.approx(docx.shared.Mm(210), abs=2)
    assert shape.width == pytest.approx(docx.shared.Mm(210) / 3, rel=1e-3)


@pytest.mark.parametrize(("text", "number"), [
    ("12", True), ("−12.25", True), ("-0.5", True), ("+3", True), ("1,5", True),
    ("1.5e-3", True), ("2.0E+06", True), ("1 234.5", True), ("12%", True), (".5", True),
    ("", False), ("r3", False), ("1-2", False), ("—", False), ("12 mm", False),
    ("argument", False), ("1.2.3", False), ("0 … 360", True), ("342.54 … 371.54", True),
    ("−5...5", True), ("10–20", True), ("0 … r3", False), ("… 5", False),
    ("−2,3·10⁴", True), ("1,5·10⁻⁵", True), ("·10⁴", False)])
def test_numbers_are_recognised(text, number):
    assert is_number(text) is number


def test_numbers_are_right_aligned_in_columns_of_numbers():
    rows = [("1", "crank", "0.05", "x"), ("2", "rod", "0 … 360", "1, 4"),
            ("3", "12", "", "text"), ("", "guide", "−3", "more text")]
    assert numeric_columns(rows, 4) == [True, False, True, False]
    assert numeric_columns([], 2) == [False, False]


def test_columns_fit_the_width_and_hold_their_longest_words():
    width = 9354
    narrow = column_widths(("a", "b"), [("1", "2")], width)
    assert narrow[0] == 12 and sum(narrow[1]) == width
    head = tuple(f"column {k}" for k in range(12))
    rows = [tuple(f"{k * 1234.5678:.4f}" for k in range(12))] * 3
    size, widths = column_widths(head, rows, width)
    assert size < 12 and sum(widths) == width
    for k, w in enumerate(widths):  # every cell's number on one line at that size
        assert w >= text_em(rows[0][k]) * size * 20
    words = ("description",)
    long = [("a long text " * 20,)]
    size, widths = column_widths(words, long, width)
    assert size == 12 and widths == [width]  # a long text wraps, the font stays


def test_a_table_too_wide_for_portrait_goes_on_landscape_pages(tmp_path):
    """Twelve columns of nine-character numbers do not fit 165 mm even at 8 pt: the
    table gets landscape pages of its own (bound by their top edge), numbered on."""
    base = sample_document("en", rows=3, columns=3)
    numbers = tuple(f"{(k + 1) * 123.456:.3f}".replace("-", "−") for k in range(12))
    wide = Table("Wide", tuple(f"quantity {k}, unit" for k in range(12)), [numbers] * 4)
    narrow = Table("Narrow", ("a", "b"), [("1", "2")])
    document = dataclasses.replace(base, sections=[
        Section("Tables", [narrow, wide, wide, Paragraph("after")]),
        Section("Wide first", [Section("Its subsection", [wide])]), *base.sections])
    doc = docx.Document(str(write_docx(document, tmp_path / "wide.docx")))
    sections = doc.sections
    assert [round(s.page_width.mm) for s in sections] == [210, 297, 210, 297, 210]
    assert sections[1].orientation == docx.enum.section.WD_ORIENT.LANDSCAPE
    assert sections[1].top_margin.mm == pytest.approx(30, abs=0.05)
    assert [s.different_first_page_header_footer for s in sections] == [True] + [False] * 4
    assert [s.footer.is_linked_to_previous for s in sections] == [False] + [True] * 4
    body = _body(doc)
    breaks = [k for k, part in enumerate(body) if isinstance(part, docx.text.paragraph.Paragraph)
              and part._p.find(f"{qn('w:pPr')}/{qn('w:sectPr')}") is not None]
    tables = [k for k, part in enumerate(body) if isinstance(part, docx.table.Table)]
    assert breaks[0] < tables[1] < tables[2] < breaks[1] < tables[3]  # both wide ones
    assert tables[0] < breaks[0]
    for k in breaks:  # the empty paragraphs holding the breaks: 1 pt, never a page
        assert body[k].text == ""
        assert body[k].paragraph_format.line_spacing == docx.shared.Pt(1)
    # the headings above a wide table go with it onto the landscape page
    headings = [k for k, part in enumerate(body)
                if isinstance(part, docx.text.paragraph.Paragraph)
                and part.style.name.startswith("Heading")]
    assert breaks[2] < headings[1] < headings[2] < tables[3] < breaks[3] < headings[3]
    assert [body[k].text for k in headings[1:3]] == ["2 Wide first", "2.1 Its subsection"]
    size, widths = column_widths(wide.header, wide.rows, 14570)  # 257 mm
    assert size >= 9
    grid = [int(c.get(qn("w:w"))) for c in body[tables[1]]._tbl.iter(qn("w:gridCol"))]
    assert grid == widths
