"""The page and the styles of the DOCX report, after GOST 7.32 (a Russian explanatory
note): A4 portrait, margins left 30 mm, right 15 mm, top and bottom 20 mm; Times New
Roman 14 pt, 1.5 lines, a 12.5 mm first-line indent and justified text in the body; 12 pt
in tables; headings bold, in Word's own Heading 1–3 styles (the table of contents and the
navigation pane use them).

Styles are set on the document, not on each paragraph, so that a student changes the look
of the whole note in one place.
"""

from __future__ import annotations

from docx.enum.section import WD_ORIENT
from docx.enum.style import WD_STYLE_TYPE
from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_LINE_SPACING, WD_TAB_ALIGNMENT, WD_TAB_LEADER
from docx.oxml.ns import qn
from docx.shared import Emu, Mm, Pt, RGBColor

from mechloop.report.docx_ooxml import paragraph_border, set_fonts, set_language

__all__ = ["BODY_PT", "FIGURE_HEIGHT", "LANDSCAPE_WIDTH", "LANGUAGES", "SERIF", "TABLE_PT",
           "TEXT_WIDTH",
           "set_page", "set_styles"]

SERIF = "Times New Roman"
MONO = "Courier New"
BODY_PT = 14
TABLE_PT = 12
INDENT = Mm(12.5)
PAGE = dict(width=Mm(210), height=Mm(297), left=Mm(30), right=Mm(15), top=Mm(20),
            bottom=Mm(20))
#: A landscape page for a table too wide for the portrait one: its top edge (30 mm)
#: is the one bound with the portrait pages' left edge.
LANDSCAPE = dict(width=Mm(297), height=Mm(210), left=Mm(20), right=Mm(20), top=Mm(30),
                 bottom=Mm(20))
#: The width of the text between the margins.
TEXT_WIDTH = Emu(PAGE["width"] - PAGE["left"] - PAGE["right"])
LANDSCAPE_WIDTH = Emu(LANDSCAPE["width"] - LANDSCAPE["left"] - LANDSCAPE["right"])
#: The largest height of a figure: the text height (257 mm) less room for its
#: caption (two lines) and the spaces around it.
FIGURE_HEIGHT = Mm(210)
#: The proofing language of each document language.
LANGUAGES = {"en": "en-US", "ru": "ru-RU"}


def set_page(section, *, landscape: bool = False, first: bool = True) -> None:
    """A4 portrait with the margins of GOST 7.32 (or ``landscape``, see
    :data:`LANDSCAPE`); the footer 10 mm from the page's edge; with ``first`` the first
    page (the title page) has a footer of its own (no page number)."""
    page = LANDSCAPE if landscape else PAGE
    section.orientation = WD_ORIENT.LANDSCAPE if landscape else WD_ORIENT.PORTRAIT
    section.page_width = page["width"]
    section.page_height = page["height"]
    section.left_margin = page["left"]
    section.right_margin = page["right"]
    section.top_margin = page["top"]
    section.bottom_margin = page["bottom"]
    section.header_distance = Mm(10)
    section.footer_distance = Mm(10)
    section.gutter = 0
    section.different_first_page_header_footer = first


def set_styles(document, lang: str) -> None:
    """Set the document defaults and the styles the writer uses: Normal, Heading 1–9,
    Caption, TOC Heading, toc 1–3, Footer and its own 'Figure' (the picture's
    paragraph), 'Table Text', 'Table Header',
    'Warning', 'Formula' and 'Title Page'."""
    styles = document.styles
    language = LANGUAGES.get(lang, "en-US")
    defaults = styles.element.find(qn("w:docDefaults"))
    rpr = defaults.find(qn("w:rPrDefault")).find(qn("w:rPr"))
    set_fonts(rpr, SERIF)
    set_language(rpr, language)

    normal = styles["Normal"]
    _font(normal, BODY_PT)
    _paragraph(normal, align=WD_ALIGN_PARAGRAPH.JUSTIFY, spacing=1.5, first=INDENT)
    normal.paragraph_format.widow_control = True

    for level in range(1, 10):
        style = styles[f"Heading {level}"]
        _font(style, BODY_PT + (2 if level == 1 else 0), bold=True)
        _paragraph(style, align=WD_ALIGN_PARAGRAPH.LEFT, spacing=1.0, first=INDENT,
                   before=Pt(0 if level == 1 else 12), after=Pt(12 if level == 1 else 6))
        style.paragraph_format.keep_with_next = True
        style.paragraph_format.keep_together = True
        style.paragraph_format.page_break_before = level == 1
        style.font.italic = False

    contents = styles["TOC Heading"]
    _font(contents, BODY_PT + 2, bold=True)
    _paragraph(contents, align=WD_ALIGN_PARAGRAPH.CENTER, spacing=1.0, first=0,
               after=Pt(12))
    contents.paragraph_format.page_break_before = True
    contents.font.all_caps = True  # GOST 7.32: СОДЕРЖАНИЕ
    for level in range(1, 4):
        entry = _style(styles, f"toc {level}", WD_STYLE_TYPE.PARAGRAPH)
        entry.base_style = normal
        _paragraph(entry, align=WD_ALIGN_PARAGRAPH.LEFT, spacing=1.5, first=0,
                   left=Mm(5 * (level - 1)))
        _tabs_right_dots(entry, TEXT_WIDTH)

    caption = styles["Caption"]
    _font(caption, BODY_PT, bold=False)
    _paragraph(caption, align=WD_ALIGN_PARAGRAPH.CENTER, spacing=1.0, first=0,
               before=Pt(6), after=Pt(12))

    picture = _style(styles, "Figure", WD_STYLE_TYPE.PARAGRAPH)
    picture.base_style = normal
    _paragraph(picture, align=WD_ALIGN_PARAGRAPH.CENTER, spacing=1.0, first=0,
               before=Pt(12))
    picture.paragraph_format.keep_with_next = True

    cell = _style(styles, "Table Text", WD_STYLE_TYPE.PARAGRAPH)
    cell.base_style = normal
    _font(cell, TABLE_PT)
    _paragraph(cell, align=WD_ALIGN_PARAGRAPH.LEFT, spacing=1.0, first=0)
    header = _style(styles, "Table Header", WD_STYLE_TYPE.PARAGRAPH)
    header.base_style = cell
    _font(header, TABLE_PT, bold=True)
    _paragraph(header, align=WD_ALIGN_PARAGRAPH.CENTER, spacing=1.0, first=0)
    for style in (cell, header):
        style.paragraph_format.keep_together = True

    warning = _style(styles, "Warning", WD_STYLE_TYPE.PARAGRAPH)
    warning.base_style = normal
    _font(warning, BODY_PT, bold=True)
    _paragraph(warning, align=WD_ALIGN_PARAGRAPH.LEFT, spacing=1.5, first=0,
               before=Pt(6), after=Pt(6), left=Pt(6), right=Pt(6))
    paragraph_border(warning.element.get_or_add_pPr(), size_eighths=12, space_pt=4,
                     fill="F2F2F2")

    formula = _style(styles, "Formula", WD_STYLE_TYPE.PARAGRAPH)
    formula.base_style = normal
    _font(formula, TABLE_PT)
    set_fonts(formula.element.get_or_add_rPr(), MONO)
    formula.font.no_proof = True
    _paragraph(formula, align=WD_ALIGN_PARAGRAPH.LEFT, spacing=1.0, first=0,
               left=INDENT, before=Pt(6), after=Pt(6))
    formula.paragraph_format.keep_together = True

    title = _style(styles, "Title Page", WD_STYLE_TYPE.PARAGRAPH)
    title.base_style = normal
    _font(title, BODY_PT)
    _paragraph(title, align=WD_ALIGN_PARAGRAPH.CENTER, spacing=1.0, first=0)

    footer = styles["Footer"]
    _paragraph(footer, align=WD_ALIGN_PARAGRAPH.CENTER, spacing=1.0, first=0)


def _style(styles, name: str, kind):
    """The style ``name`` of the document, added when the template has none."""
    try:
        return styles[name]
    except KeyError:
        return styles.add_style(name, kind)


def _font(style, size: float, *, bold: bool | None = None) -> None:
    """Times New Roman (for every script, no theme font), black, ``size`` points."""
    set_fonts(style.element.get_or_add_rPr(), SERIF)
    style.font.size = Pt(size)
    style.font.color.rgb = RGBColor(0, 0, 0)
    color = style.element.rPr.find(qn("w:color"))
    for attribute in ("w:themeColor", "w:themeShade", "w:themeTint"):
        color.attrib.pop(qn(attribute), None)
    if bold is not None:
        style.font.bold = bold


def _paragraph(style, *, align, spacing: float, first, before=0, after=0, left=0,
               right=0) -> None:
    fmt = style.paragraph_format
    fmt.alignment = align
    fmt.line_spacing_rule = (WD_LINE_SPACING.SINGLE if spacing == 1.0
                             else WD_LINE_SPACING.ONE_POINT_FIVE)
    fmt.first_line_indent = first
    fmt.left_indent = left
    fmt.right_indent = right
    fmt.space_before = before
    fmt.space_after = after


def _tabs_right_dots(style, position) -> None:
    """A right tab stop with a dotted leader at ``position`` (the page numbers of the
    contents)."""
    style.paragraph_format.tab_stops.add_tab_stop(position, WD_TAB_ALIGNMENT.RIGHT,
                                                  WD_TAB_LEADER.DOTS)
