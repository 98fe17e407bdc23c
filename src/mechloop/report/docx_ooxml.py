"""Small pieces of WordprocessingML that python-docx has no API for: text made safe for
XML, fields (a table of contents, the page number), a paragraph's border and shading, the
document's settings (update the fields on opening, hyphenation, the language).

Used by :mod:`mechloop.report.docx`; every function works on python-docx objects or their
lxml elements.
"""

from __future__ import annotations

import re
from xml.sax.saxutils import escape

from docx.oxml import OxmlElement
from docx.oxml.ns import qn

#: Characters XML 1.0 cannot hold (C0 controls but tab and line feed, lone surrogates,
#: U+FFFE and U+FFFF) and the C1 controls, which print as nothing.
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\ud800-\udfff\ufffe\uffff]")


def clean(text: str) -> str:
    """``text`` as Word can hold it: line ends as ``\\n`` (``\\r\\n`` and ``\\r`` too), the
    control characters XML cannot carry removed (they print as nothing anyway); tabs and
    line feeds are kept (the writer makes them tab stops and line breaks)."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    return _NOT_XML.sub("", text)


def runs_xml(text: str, rpr: str = "") -> str:
    """The XML of runs holding ``text`` (already :func:`clean`) with run properties
    ``rpr`` (an ``<w:rPr>…</w:rPr>`` string or ''): line feeds as ``<w:br/>``, tabs as
    ``<w:tab/>``, spaces kept."""
    parts = []
    for k, line in enumerate(text.split("\n")):
        if k:
            parts.append("<w:br/>")
        for j, piece in enumerate(line.split("\t")):
            if j:
                parts.append("<w:tab/>")
            if piece:
                parts.append(f'<w:t xml:space="preserve">{escape(piece)}</w:t>')
    return f"<w:r>{rpr}{''.join(parts)}</w:r>"


def _field_char(kind: str, dirty: bool = False):
    element = OxmlElement("w:fldChar")
    element.set(qn("w:fldCharType"), kind)
    if dirty:
        element.set(qn("w:dirty"), "true")
    run = OxmlElement("w:r")
    run.append(element)
    return run


def _instruction(code: str):
    run = OxmlElement("w:r")
    text = OxmlElement("w:instrText")
    text.set(qn("xml:space"), "preserve")
    text.text = f" {code} "
    run.append(text)
    return run


def field_begin(paragraph, code: str) -> None:
    """Append the start of the field ``code`` (e.g. ``PAGE``) to ``paragraph``: its
    beginning, its code and the separator; the runs after it are the field's shown result
    up to :func:`field_end`. Marked dirty, so that Word computes it again."""
    p = paragraph._p
    p.append(_field_char("begin", dirty=True))
    p.append(_instruction(code))
    p.append(_field_char("separate"))


def field_end(paragraph) -> None:
    """Append the end of a field begun by :func:`field_begin` (perhaps paragraphs
    earlier)."""
    paragraph._p.append(_field_char("end"))


def simple_field(paragraph, code: str, shown: str) -> None:
    """Append the whole field ``code`` showing ``shown`` until it is computed."""
    field_begin(paragraph, code)
    paragraph.add_run(shown)
    field_end(paragraph)


def paragraph_border(ppr, *, size_eighths: int = 8, space_pt: int = 4,
                     fill: str | None = None) -> None:
    """Give the paragraph properties ``ppr`` (a ``w:pPr``) a single border of
    ``size_eighths`` eighths of a point on every side, ``space_pt`` points from the text,
    and a background ``fill`` (hex RGB) when given. Neighbouring paragraphs with the same
    border share one box."""
    border = OxmlElement("w:pBdr")
    for side in ("top", "left", "bottom", "right"):
        line = OxmlElement(f"w:{side}")
        line.set(qn("w:val"), "single")
        line.set(qn("w:sz"), str(size_eighths))
        line.set(qn("w:space"), str(space_pt))
        line.set(qn("w:color"), "000000")
        border.append(line)
    _insert_ordered(ppr, border, _PPR_ORDER)
    if fill is not None:
        shading = OxmlElement("w:shd")
        shading.set(qn("w:val"), "clear")
        shading.set(qn("w:color"), "auto")
        shading.set(qn("w:fill"), fill)
        _insert_ordered(ppr, shading, _PPR_ORDER)


def shrink_mark(p) -> None:
    """Make the empty paragraph ``p`` (a ``w:p``, e.g. the one holding a section break)
    one point high, so that it never spills onto a page of its own."""
    ppr = p.get_or_add_pPr()
    for old in ppr.findall(qn("w:spacing")) + ppr.findall(qn("w:rPr")):
        ppr.remove(old)
    spacing = OxmlElement("w:spacing")
    for key, value in (("w:before", "0"), ("w:after", "0"), ("w:line", "20"),
                       ("w:lineRule", "exact")):
        spacing.set(qn(key), value)
    _insert_ordered(ppr, spacing, _PPR_ORDER)
    rpr = OxmlElement("w:rPr")
    for tag in ("w:sz", "w:szCs"):
        size = OxmlElement(tag)
        size.set(qn("w:val"), "2")
        rpr.append(size)
    _insert_ordered(ppr, rpr, _PPR_ORDER)


def set_language(rpr, lang: str) -> None:
    """Set the proofing language of the run properties ``rpr`` (``w:rPr``) to ``lang``
    (a tag as 'ru-RU'), for Latin and Cyrillic text alike."""
    for old in rpr.findall(qn("w:lang")):
        rpr.remove(old)
    element = OxmlElement("w:lang")
    element.set(qn("w:val"), lang)
    element.set(qn("w:eastAsia"), lang)
    element.set(qn("w:bidi"), "ar-SA")
    _insert_ordered(rpr, element, _RPR_ORDER)


def set_fonts(rpr, name: str) -> None:
    """Set every script's font of ``rpr`` to ``name``, removing the theme fonts that
    would otherwise win over it."""
    for old in rpr.findall(qn("w:rFonts")):
        rpr.remove(old)
    element = OxmlElement("w:rFonts")
    for script in ("ascii", "hAnsi", "eastAsia", "cs"):
        element.set(qn(f"w:{script}"), name)
    _insert_ordered(rpr, element, _RPR_ORDER)


def set_settings(settings, *, lang: str) -> None:
    """In the document's settings element: ask Word to update the fields (the table of
    contents, the page numbers) when the file is opened, hyphenate automatically (the
    body is justified) and take ``lang`` as the theme fonts' language."""
    for tag, attributes in (("w:autoHyphenation", {"w:val": "true"}),
                            ("w:updateFields", {"w:val": "true"}),
                            ("w:themeFontLang", {"w:val": lang})):
        for old in settings.findall(qn(tag)):
            settings.remove(old)
        element = OxmlElement(tag)
        for key, value in attributes.items():
            element.set(qn(key), value)
        _insert_ordered(settings, element, _SETTINGS_ORDER)


def _insert_ordered(parent, element, order: list[str]) -> None:
    """Insert ``element`` into ``parent`` where the schema's sequence ``order`` (local
    names) puts it: before the first child that comes after it (Word refuses elements
    out of order)."""
    name = element.tag.split("}")[1]
    later = set(order[order.index(name) + 1:])
    for child in parent:
        if isinstance(child.tag, str) and child.tag.split("}")[-1] in later:
            child.addprevious(element)
            return
    parent.append(element)


# The sequences of the OOXML schema (ECMA-376 part 1, 17.3.1.26 pPr, 17.3.2.28 rPr,
# 17.15.1.78 settings), by local name.
_PPR_ORDER = ["pStyle", "keepNext", "keepLines", "pageBreakBefore", "framePr",
              "widowControl", "numPr", "suppressLineNumbers", "pBdr", "shd", "tabs",
              "suppressAutoHyphens", "kinsoku", "wordWrap", "overflowPunct", "topLinePunct",
              "autoSpaceDE", "autoSpaceDN", "bidi", "adjustRightInd", "snapToGrid",
              "spacing", "ind", "contextualSpacing", "mirrorIndents", "suppressOverlap",
              "jc", "textDirection", "textAlignment", "textboxTightWrap",
              "outlineLvl", "divId", "cnfStyle", "rPr", "sectPr", "pPrChange"]
_RPR_ORDER = ["rStyle", "rFonts", "b", "bCs", "i", "iCs", "caps", "smallCaps", "strike",
              "dstrike", "outline", "shadow", "emboss", "imprint", "noProof", "snapToGrid",
              "vanish", "webHidden", "color", "spacing", "w", "kern", "position", "sz",
              "szCs", "highlight", "u", "effect", "bdr", "shd", "fitText", "vertAlign",
              "rtl", "cs", "em", "lang", "eastAsianLayout", "specVanish", "oMath"]
_SETTINGS_ORDER = [
    "writeProtection", "view", "zoom", "removePersonalInformation", "removeDateAndTime",
    "doNotDisplayPageBoundaries", "displayBackgroundShape", "printPostScriptOverText",
    "printFractionalCharacterWidth", "printFormsData", "embedTrueTypeFonts",
    "embedSystemFonts", "saveSubsetFonts", "saveFormsData", "mirrorMargins",
    "alignBordersAndEdges", "bordersDoNotSurroundHeader", "bordersDoNotSurroundFooter",
    "gutterAtTop", "hideSpellingErrors", "hideGrammaticalErrors", "activeWritingStyle",
    "proofState", "formsDesign", "attachedTemplate", "linkStyles",
    "stylePaneFormatFilter", "stylePaneSortMethod", "documentType", "mailMerge",
    "revisionView", "trackRevisions", "doNotTrackMoves", "doNotTrackFormatting",
    "documentProtection", "autoFormatOverride", "styleLockTheme", "styleLockQFSet",
    "defaultTabStop", "autoHyphenation", "consecutiveHyphenLimit", "hyphenationZone",
    "doNotHyphenateCaps", "showEnvelope", "summaryLength", "clickAndTypeStyle",
    "defaultTableStyle", "evenAndOddHeaders", "bookFoldRevPrinting", "bookFoldPrinting",
    "bookFoldPrintingSheets", "drawingGridHorizontalSpacing",
    "drawingGridVerticalSpacing", "displayHorizontalDrawingGridEvery",
    "displayVerticalDrawingGridEvery", "doNotUseMarginsForDrawingGridOrigin",
    "drawingGridHorizontalOrigin", "drawingGridVerticalOrigin", "doNotShadeFormData",
    "noPunctuationKerning", "characterSpacingControl", "printTwoOnOne",
    "strictFirstAndLastChars", "noLineBreaksAfter", "noLineBreaksBefore",
    "savePreviewPicture", "doNotValidateAgainstSchema", "saveInvalidXml",
    "ignoreMixedContent", "alwaysShowPlaceholderText", "doNotDemarcateInvalidXml",
    "saveXmlDataOnly", "useXSLTWhenSaving", "saveThroughXslt", "showXMLTags",
    "alwaysMergeEmptyNamespace", "updateFields", "hdrShapeDefaults", "footnotePr",
    "endnotePr", "compat", "docVars", "rsids", "mathPr", "attachedSchema",
    "themeFontLang", "clrSchemeMapping", "doNotIncludeSubdocsInStats",
    "doNotAutoCompressPictures", "forceUpgrade", "captions", "readModeInkLockDown",
    "smartTagType", "schemaLibrary", "shapeDefaults", "doNotEmbedSmartTags",
    "decimalSymbol", "listSeparator"]
