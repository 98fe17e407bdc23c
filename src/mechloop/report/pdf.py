"""The report typeset as a PDF on A4 pages with Typst.

:func:`write_pdf` draws each figure as a PDF image (:mod:`.figure_image`), writes the
document as JSON data (:mod:`.pdf_data`) beside a copy of the fixed template
(:file:`template.typ`, shipped with the package) in a temporary folder and compiles it with
the ``typst`` package, using only matplotlib's font files (:mod:`.fonts`). The PDF appears
whole or not at all.
"""

from __future__ import annotations

import json
import tempfile
from collections.abc import Callable
from importlib.resources import files
from pathlib import Path

from mechloop.report.document import Document, FigureItem, walk
from mechloop.report.figure_image import figure_pdf
from mechloop.report.fonts import FONT_DIR
from mechloop.report.pdf_data import TypesetError, document_data

__all__ = ["TypesetError", "template_text", "typeset", "write_pdf"]


def template_text() -> str:
    """The Typst template of the report."""
    return files("mechloop.report").joinpath("template.typ").read_text(encoding="utf-8")


def _figures(document: Document) -> list[FigureItem]:
    return [block for block in walk([*document.sections, *document.appendices])
            if isinstance(block, FigureItem)]


def typeset(document: Document, folder: Path, *,
            progress: Callable[[int, int], None] | None = None) -> bytes:
    """The PDF of ``document``, typeset in the empty ``folder`` (its figures' images, the
    data and the template are written there)."""
    figures = _figures(document)
    images: dict[int, tuple[str, float, float]] = {}
    for k, item in enumerate(figures):
        if id(item) not in images:
            content, width, height = figure_pdf(item)
            name = f"figure-{k + 1}.pdf"
            (folder / name).write_bytes(content)
            images[id(item)] = (name, width, height)
        if progress is not None:
            progress(k + 1, len(figures))
    data = document_data(document, images)
    (folder / "data.json").write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")
    main = folder / "main.typ"
    main.write_text(template_text(), encoding="utf-8")
    import typst

    try:
        pdf, warnings = typst.compile_with_warnings(
            main, root=folder, font_paths=[FONT_DIR], ignore_system_fonts=True,
            format="pdf")
    except typst.TypstError as exc:
        raise TypesetError(f"Typst could not typeset the report: {exc.message}",
                           "report this as a bug of mechloop with the model file") from None
    if warnings:
        told = "; ".join(w.message for w in warnings)
        raise TypesetError(f"Typst typeset the report with warnings: {told}",
                           "report this as a bug of mechloop with the model file")
    return pdf


def write_pdf(document: Document, path, *,
              progress: Callable[[int, int], None] | None = None) -> Path:
    """Typeset ``document`` as a PDF at ``path`` (A4, Typst) and return the path.

    ``progress(done, total)`` is called after each figure is drawn. The file is written
    atomically: on any error nothing is left at ``path`` (an older file stays as it was).
    Raises :class:`TypesetError` (a :class:`~mechloop.errors.HintedError`) when a text
    holds a sign that no font of the report has or Typst fails.
    """
    from mechloop.output.atomic import atomic_file

    target = Path(path)
    with tempfile.TemporaryDirectory(prefix="mechloop-report-") as folder:
        pdf = typeset(document, Path(folder), progress=progress)
    with atomic_file(target) as handle:
        handle.write(pdf)
    return target
