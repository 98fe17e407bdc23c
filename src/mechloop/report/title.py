"""The title page of the report from the model's ``report:`` section
(:class:`mechloop.model.report_info.ReportInfo`) and the command line's options, with the
defaults of the report's language: the kind of work, the course and the title; the
model's name (and description) as the subject; this year."""

from __future__ import annotations

import datetime

from mechloop.model.report_info import ReportInfo
from mechloop.model.schema import Model
from mechloop.report.document import TitlePage


def title_info(model: Model, title: ReportInfo | dict | None = None) -> ReportInfo:
    """The model's ``report:`` section with the fields of ``title`` (a ReportInfo or a
    dict of the command line's options; None values left out) in their place."""
    info = model.report or ReportInfo()
    if title is None:
        return info
    given = title.model_dump(exclude_none=True) if isinstance(title, ReportInfo) \
        else {k: v for k, v in title.items() if v is not None}
    return info.merged(**given)


def title_page(model: Model, info: ReportInfo, w: dict[str, str]) -> TitlePage:
    """The title page: the organisation's lines, kind, course, title, subject, people
    and the place and year."""
    subject = model.name or ""
    if model.description:
        subject = f"{subject}\n{model.description}" if subject else model.description
    people = [(w[key], value) for key in ("student", "group", "supervisor")
              if (value := getattr(info, key))]
    year = info.year or datetime.date.today().year
    place = f"{info.city} {year}" if info.city else str(year)
    return TitlePage(organisation=[line for line in (info.university, info.department)
                                   if line],
                     kind=w["kind"], course=info.course or w["course"],
                     title=info.title or w["title"], subject=subject, people=people,
                     place_year=place)
