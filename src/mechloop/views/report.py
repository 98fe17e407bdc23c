"""The course-project report (seed 000, sec. 2.1 item 9), kept importable here: the
content is built by :mod:`mechloop.report.content` and typeset by
:mod:`mechloop.report.pdf` (PDF) or :mod:`mechloop.report.docx` (Word);
:func:`write_report` is :func:`mechloop.report.write.write_report`."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from mechloop.model.project import ProjectDocuments
from mechloop.model.report_info import ReportInfo
from mechloop.model.schema import Model
from mechloop.report.content import output_parameter  # noqa: F401 (re-exported)
from mechloop.report.sheets import project_sheets  # noqa: F401 (re-exported)
from mechloop.report.words import TEXT  # noqa: F401 (re-exported)
from mechloop.views.russian import RUSSIAN_WORDS, translate  # noqa: F401 (re-exported)


def write_report(model: Model, path: str | os.PathLike[str], *, lang: str = "en",
                 output: str | None = None, progress: Callable[[int, int], None] | None = None,
                 warn: Callable[[str], None] | None = None,
                 project: ProjectDocuments | None = None, position: int | None = None,
                 title: ReportInfo | dict | None = None) -> Path:
    """Write the course-project report of ``model`` to ``path`` (.pdf or .docx): see
    :func:`mechloop.report.write.write_report`."""
    from mechloop.report.write import write_report as write

    return write(model, path, lang=lang, output=output, position=position, title=title,
                 project=project, progress=progress, warn=warn)
