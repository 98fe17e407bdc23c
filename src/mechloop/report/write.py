"""Write the course-project report: the content (:func:`mechloop.report.content.build_document`)
typeset as a PDF (:mod:`mechloop.report.pdf`, Typst) or an editable Word file
(:mod:`mechloop.report.docx`), as the file's suffix says."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from mechloop.errors import HintedError
from mechloop.model.project import ProjectDocuments
from mechloop.model.report_info import ReportInfo
from mechloop.model.schema import Model

#: The suffixes of a report and the module that typesets each.
SUFFIXES = {".pdf": "pdf", ".docx": "docx"}


def check_suffix(path: str | os.PathLike[str]) -> str:
    """The typesetter ('pdf' or 'docx') of ``path``; a HintedError for another suffix."""
    target = Path(path)
    kind = SUFFIXES.get(target.suffix.lower())
    if kind is None:
        raise HintedError(f"{target}: a report is a .pdf or a .docx file",
                          "use a file name ending in .pdf or .docx")
    return kind


def write_report(model: Model, path: str | os.PathLike[str], *, lang: str = "en",
                 output: str | None = None, position: int | None = None,
                 title: ReportInfo | dict | None = None,
                 project: ProjectDocuments | None = None,
                 progress: Callable[[int, int], None] | None = None,
                 warn: Callable[[str], None] | None = None) -> Path:
    """Write the report of ``model`` to ``path`` (.pdf or .docx), atomically, and return
    the path.

    ``lang``, ``output``, ``position``, ``title``, ``project``, ``warn``: as for
    :func:`mechloop.report.content.build_document`; ``progress(done, total)`` is called
    after each figure drawn.
    """
    from mechloop.report.content import build_document

    check_suffix(path)
    document = build_document(model, lang=lang, output=output, position=position,
                              title=title, project=project, warn=warn)
    return write_document(document, path, progress=progress)


def write_document(document, path: str | os.PathLike[str], *,
                   progress: Callable[[int, int], None] | None = None) -> Path:
    """Typeset ``document`` (:class:`~mechloop.report.document.Document`) into ``path``
    by the typesetter its suffix picks."""
    if check_suffix(path) == "pdf":
        from mechloop.report.pdf import write_pdf

        return write_pdf(document, path, progress=progress)
    from mechloop.report.docx import write_docx

    return write_docx(document, path, progress=progress)
