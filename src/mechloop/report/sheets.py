"""The course project's gear sheet (sheet 3) and cam sheet (sheet 4) as sections of the
report: each sheet's tables, paragraphs and figures (:class:`mechloop.views.sheet.Sheet`)
in one section."""

from __future__ import annotations

from mechloop.model.project import ProjectDocuments
from mechloop.report.document import Paragraph, Section
from mechloop.views.sheet import Sheet


def project_sheets(project: ProjectDocuments, lang: str) -> list[Sheet]:
    """The course project's sheet 3 (gears) and sheet 4 (cam) of the documents given."""
    sheets = []
    if project.gears is not None:
        from mechloop.views.gear_sheet import gear_sheet

        sheets.append(gear_sheet(project.gears, lang))
    if project.cam is not None:
        from mechloop.views.cam_sheet import cam_sheet

        sheets.append(cam_sheet(project.cam, lang))
    return sheets


def sheet_section(sheet: Sheet) -> Section:
    """One sheet as a section: its tables, then its paragraphs (the checks and
    conclusions), then its figures."""
    return Section(sheet.title, [*sheet.tables, *(Paragraph(p) for p in sheet.paragraphs),
                                 *sheet.figures])
