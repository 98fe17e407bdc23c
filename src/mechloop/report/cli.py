"""The ``mechloop report`` command's work: build the document once, typeset it into every
output file asked for, and tell the progress, the warnings and the files written in the
report's language."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from mechloop.model.project import ProjectDocuments
from mechloop.model.schema import Model


def run_report(model: Model, outputs: Sequence[Path], *, lang: str, parameter: str | None,
               position: int | None, title: dict, project: ProjectDocuments | None,
               progress: Callable[[str], object], out, err) -> list[Path]:
    """Write the report of ``model`` to each of ``outputs`` (.pdf or .docx); ``progress``
    makes a Rich progress bar from its label; ``out``/``err`` the consoles."""
    from rich.markup import escape

    from mechloop.report.content import build_document
    from mechloop.report.words import words
    from mechloop.report.write import check_suffix, write_document

    w = words(lang)
    for path in outputs:
        check_suffix(path)

    def warn(text: str) -> None:
        err.print(f"[bold yellow]{w['warning']}:[/] {escape(text)}")

    document = build_document(model, lang=lang, output=parameter, position=position,
                              title=title, project=project, warn=warn)
    written = []
    for path in outputs:
        with progress(w["progress"]) as bar:
            task = bar.add_task(w["progress"], total=None)
            written.append(write_document(
                document, path, progress=lambda done, total, bar=bar, task=task:
                bar.update(task, completed=done, total=total)))
        out.print(escape(w["wrote"].format(path=written[-1])))
    return written
