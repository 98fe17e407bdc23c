"""The report typeset as a PDF (mechloop.report.pdf): A4 pages with the text inside the
GOST margins, the document's own heading and caption numbers in order, the long appendix
table with its header on every page, wide tables split to fit, no typesetter words in the
Russian text, any text (Typst's special signs too) printed as it is, signs without a font
and Typst failures as user errors that leave no file."""

from __future__ import annotations

import re
import string

import pypdfium2
import pytest
from helpers.latin import latin_words
from helpers.pdf_pages import A4, check_text_area, normal, page_texts
from helpers.report_sample import sample_document
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mechloop.errors import HintedError
from mechloop.report import pdf as pdf_module
from mechloop.report.document import (
    Document,
    FigureItem,
    Paragraph,
    Section,
    Table,
    caption,
    heading,
    numbered,
)
from mechloop.report.pdf import TypesetError, write_pdf
from mechloop.report.pdf_layout import is_number, table_parts


@pytest.fixture(scope="module", params=["en", "ru"])
def sample(request, tmp_path_factory):
    """(document, PDF path, progress calls) of the sample in both languages."""
    document = sample_document(request.param)
    calls = []
    path = write_pdf(document, tmp_path_factory.mktemp("pdf") / f"sample-{request.param}.pdf",
                     progress=lambda done, total: calls.append((done, total)))
    return document, path, calls


def test_every_page_is_a4_portrait_and_progress_is_told_per_figure(sample):
    _, path, calls = sample
    document = pypdfium2.PdfDocument(path)
    assert len(document) >= 5
    for page in document:
        assert page.get_size() == pytest.approx(A4, abs=0.5)
    document.close()
    assert calls == [(1, 2), (2, 2)]


def test_text_stays_inside_the_margins_and_pages_are_numbered(sample):
    check_text_area(sample[1])


def test_headings_and_captions_come_in_document_order_with_their_numbers(sample):
    document, path, _ = sample
    pages = page_texts(path)
    title = normal(pages[0])
    t = document.title
    for text in [*t.organisation, t.kind, t.course, t.title, t.subject, t.place_year,
                 *(f"{label}: {name}" for label, name in t.people)]:
        assert normal(text) in title
    contents = normal(pages[1])
    assert contents.startswith(document.words.contents)
    body = normal(" ".join(pages[2:]))
    at = 0
    for item in numbered(document):
        if isinstance(item.block, Section):
            text = heading(document, item)
            assert normal(text) in contents
        elif isinstance(item.block, FigureItem | Table):
            text = caption(document, item)
        else:
            text = item.block.text
        found = body.find(normal(text), at)
        assert found >= 0, text
        at = found + 1
    assert "Figure 1.1 —" in body or "Рисунок 1.1 —" in body
    assert "φ1, deg" in body  # the figures' texts are text
    assert re.search(r"(Table|Таблица) (A|А)\.1 — ", body)


def test_top_level_sections_start_a_page_and_no_heading_ends_one(tmp_path):
    base = sample_document("en")
    filler = "The reactions are found at every position of the cycle. " * 4
    sections = [Section(f"Section {k}", [
        *(Paragraph(filler) for _ in range(k % 4)),
        *(Section(f"Part {k}.{m}", [*(Paragraph(filler) for _ in range(m + k % 3)),
                                    Table(f"t{k}.{m}", ("a", "b"), [("1", "2")] * (3 + m)),
                                    *(Paragraph(filler[:40 * j]) for j in range(1, m % 4)),
                                    Table(f"u{k}.{m}", ("a", "b"), [("1", "2")] * 3)])
          for m in range(1, 9))]) for k in range(1, 5)]
    document = Document("en", "h", base.title, sections, [Section("More", [Paragraph("x")])])
    pages = page_texts(write_pdf(document, tmp_path / "h.pdf"))[2:]
    headings = [heading(document, item) for item in numbered(document)
                if isinstance(item.block, Section)]
    tops = [heading(document, item) for item in numbered(document) if item.depth == 1
            and isinstance(item.block, Section)]
    starts = [normal(p) for p in pages]
    for text in tops:
        assert sum(p.startswith(text) for p in starts) == 1, text
    for page in pages:
        lines = [line.strip() for line in page.splitlines() if line.strip()]
        # the last line is the page number; a heading or caption keeps to what follows
        assert lines[-2] not in headings and not lines[-2].startswith("Table")


def test_table_caption_is_above_it_and_figure_caption_below_it(sample):
    document, path, _ = sample
    items = {}
    for item in numbered(document):  # the first table and figure, on page 3
        if isinstance(item.block, Table | FigureItem):
            items.setdefault(type(item.block), item)
    pdf = pypdfium2.PdfDocument(path)
    page = pdf[2].get_textpage()

    def top(text):
        searcher = page.search(text)
        start, count = searcher.get_next()
        return max(page.get_charbox(i)[3] for i in range(start, start + count))

    table = items[Table]
    assert top(caption(document, table)[:20]) > top(table.block.header[1])
    figure = items[FigureItem]
    assert top(caption(document, figure)[:20]) < top("φ1, deg")
    pdf.close()


def tall_figure():
    from matplotlib.figure import Figure

    figure = Figure(figsize=(4, 16), layout="constrained")
    axes = figure.subplots(6, 1)
    for k, ax in enumerate(axes):
        ax.plot([0, 1], [0, k])
        ax.set_xlabel(f"top label {k}" if k == 0 else f"label {k}")
    axes[-1].set_xlabel("bottom label")
    return figure


def test_a_tall_figure_is_scaled_down_to_fit_a_page_with_its_caption(tmp_path):
    base = sample_document("en")
    long = "Displacement, velocity and acceleration of the follower over the cycle " * 3
    document = Document("en", "tall", base.title, [Section("S", [
        Paragraph("Text before the figure."), FigureItem(long, tall_figure)])])
    path = write_pdf(document, tmp_path / "tall.pdf")
    check_text_area(path)
    pages = [normal(p) for p in page_texts(path)]
    [page] = [p for p in pages if "bottom label" in p]
    assert "top label 0" in page and f"Figure 1.1 — {normal(long)}" in page


def test_the_appendix_table_spans_pages_with_its_header_on_each(sample):
    document, path, _ = sample
    big = document.appendices[0].blocks[0]
    pages = [normal(p) for p in page_texts(path)]
    header = " ".join(big.header)
    rows = [" ".join(row) for row in big.rows]
    holding = [k for k, p in enumerate(pages) if any(row in p for row in rows)]
    assert len(holding) >= 3
    for k in holding:
        assert pages[k].count(header) == 1, k
    text = " ".join(pages[k] for k in holding)
    at = 0
    for row in rows:
        at = text.index(row, at)


def test_typesetter_words_are_in_the_documents_language(sample):
    """The Russian PDF holds no Latin words but the sample's own names; the English one
    no Cyrillic letters."""
    document, path, _ = sample
    text = " ".join(page_texts(path))
    if document.lang == "en":
        assert not re.search("[А-Яа-яЁё]", text)
        assert "Appendix A" in text and "Contents" in text
        return
    t = document.title
    names = [*t.organisation, t.subject, t.place_year, *(n for _, n in t.people),
             *(cell for block in document.sections[0].blocks if isinstance(block, Table)
               for row in block.rows for cell in row)]
    assert latin_words(text, names) == []
    assert "Приложение А" in text and "Содержание" in text


def test_numeric_cells_are_told_from_words():
    for cell in ["12", "−12.25", "-0.5", "+3", "1.5e-3", "2E+05", "3,75", ".5", " 7 ",
                 "1\u202f234.5", "12%", "inf", "−inf", "−2,3·10⁴", "1,5·10⁻⁵"]:
        assert is_number(cell), cell
    for cell in ["", "—", "r3", "12 mm", "1.2.3", "e5", "-", "argument", "12 / 4", "1e", "1 2",
                 "·10⁴", "2·10"]:
        assert not is_number(cell), cell


def wide_document(rows=70, columns=30, lang="ru"):
    base = sample_document(lang)
    table = Table("Значения во всех положениях механизма",
                  ("положение", *(f"параметр {j}, мм" for j in range(1, columns))),
                  [(str(i), *(f"{(i - 35) * j * 1.37:.3f}".replace("-", "−")
                              for j in range(1, columns))) for i in range(rows)])
    return Document(lang, "wide", base.title, [Section("Таблица", [Paragraph("Текст.")])],
                    [Section("Все значения", [table])])


def test_a_wide_table_is_split_in_parts_that_fit_each_with_the_first_column(tmp_path):
    document = wide_document(rows=40)
    table = document.appendices[0].blocks[0]
    parts = table_parts(table.header, table.rows)
    assert len(parts) > 1
    assert sorted({j for p in parts for j in p.columns}) == list(range(len(table.header)))
    assert all(p.columns[0] == 0 for p in parts)
    assert all(sum(p.widths) == pytest.approx(1) for p in parts)
    path = write_pdf(document, tmp_path / "wide.pdf")
    check_text_area(path)
    body = normal(" ".join(page_texts(path)))
    assert body.count("Продолжение таблицы А.1") == len(parts) - 1
    for row in table.rows[::7]:
        for part in parts:
            assert " ".join(row[j] for j in part.columns) in body


def test_a_table_of_nine_columns_gets_a_smaller_font_and_fits(tmp_path):
    base = sample_document("en", rows=3)
    header = ("position", *(f"value {j}, kN·m" for j in range(1, 9)))
    rows = [(str(i), *(f"−{1000 * i + 12.3456 * j:.3f}" for j in range(1, 9)))
            for i in range(40)]
    [part] = table_parts(header, rows)
    [small] = table_parts(header, [tuple(c[:4] for c in row) for row in rows])
    assert part.size < small.size == 11
    document = Document("en", "nine", base.title, [Section("S", [Table("t", header, rows)])])
    path = write_pdf(document, tmp_path / "nine.pdf")
    check_text_area(path)
    body = normal(" ".join(page_texts(path)))
    assert all(" ".join(row) in body for row in rows)


#: Printable text of the alphabets and signs the fonts have, Typst's markup signs
#: included.
ALPHABET = (string.ascii_letters + string.digits + string.punctuation + " "
            + "АБВГДЕЁЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯабвгдеёжзийклмнопрстуфхцчшщъыьэюя"
            + "αβγδεζηθλμνξπρστφχψωΔΦΩ−·²³≤≥…°→⌀±×≈№—–«»")


@settings(max_examples=12, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=st.text(alphabet=ALPHABET, min_size=1, max_size=120).filter(str.strip))
def test_any_text_is_printed_as_it_is(text, tmp_path):
    base = sample_document("en")
    document = Document("en", text, base.title, [Section(text, [
        Paragraph(text), Table(text, ("a", "b"), [(text, "1")]), Paragraph(text, "warning"),
        Paragraph(text, "formula")])])
    path = write_pdf(document, tmp_path / "any.pdf")
    body = normal(" ".join(page_texts(path)[2:]))
    want = normal(text)
    for piece in (f"1 {want}", f"Table 1.1 — {want}"):
        assert piece in body
    # the heading, the paragraph, the caption, the cell, the warning and the formula
    assert body.count(want) >= 6


def test_long_words_and_lines_wrap_inside_the_page(tmp_path):
    base = sample_document("en")
    word = "very_long_model_name_" * 9 + "/" + "x" * 70
    formula = "F = " + " + ".join(f"m{i}·a{i}" for i in range(60))
    blocks = [Paragraph(f"In {word} the\ttab."), Paragraph(word, "formula"),
              Paragraph(formula, "formula"), Table(word, ("name", "value"), [(word, "1.5")])]
    path = write_pdf(Document("en", "long", base.title, [Section(word, blocks)]),
                     tmp_path / "long.pdf")
    check_text_area(path)
    body = normal(" ".join(page_texts(path)[2:]))
    solid = body.replace(" ", "")  # a line may break inside a long word
    assert solid.count(word) == 5
    assert f"In{word}thetab." in solid and normal(formula) in body


def test_a_sign_without_a_font_is_a_user_error_and_leaves_no_file(tmp_path):
    base = sample_document("en")
    document = Document("en", "x", base.title, [Section("S", [Paragraph("Gear 漢 ok")])])
    target = tmp_path / "r.pdf"
    with pytest.raises(TypesetError, match=r"U\+6F22") as raised:
        write_pdf(document, target)
    assert isinstance(raised.value, HintedError) and raised.value.hint
    assert list(tmp_path.iterdir()) == []


def test_a_typst_failure_is_a_user_error_and_keeps_the_old_file(tmp_path, monkeypatch):
    target = tmp_path / "r.pdf"
    target.write_bytes(b"old")
    monkeypatch.setattr(pdf_module, "template_text", lambda: '#let x = json("none.json")')
    with pytest.raises(TypesetError, match="Typst could not typeset"):
        write_pdf(wide_document(rows=3, columns=3), target)
    assert target.read_bytes() == b"old"
    assert list(tmp_path.iterdir()) == [target]


def test_a_failing_figure_leaves_no_file(tmp_path):
    def fail():
        raise RuntimeError("no figure")

    base = sample_document("en")
    document = Document("en", "x", base.title, [Section("S", [FigureItem("f", fail)])])
    with pytest.raises(RuntimeError):
        write_pdf(document, tmp_path / "r.pdf")
    assert list(tmp_path.iterdir()) == []
