"""New models: every bundled model is a template — the course-project tasks (with their
``project:`` cam and gear documents) and the other examples.

A new model opens in the editor unsaved; when it is saved into the folder, the files its
text names (``{csv: ...}`` tables, ``project:`` documents) that lie beside the template
are copied beside it, unless the folder already has them, so the saved model reads as the
template did.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from mechloop.bundled.catalog import examples, examples_dir, find_example
from mechloop.errors import HintedError, MechloopError
from mechloop.model.document import parse_document
from mechloop.output.atomic import atomic_write_bytes
from mechloop.web.safety import WebError, Workspace, file_references


def listing() -> list[dict[str, Any]]:
    """The templates, course tasks first: ``id`` (the example's name), ``group``
    (``course`` or ``example``), ``number`` (the course task), ``title``, ``title_ru``,
    ``file`` (the file name a new model is offered to be saved as)."""
    return [{"id": e.stem, "group": "course" if e.course else "example",
             "number": e.number, "title": e.title, "title_ru": e.title_ru or e.title,
             "file": e.path.name}
            for e in examples() if e.path.suffix == ".yaml"]


def template(name: str) -> Path:
    """The file of the template ``name`` (a bundled model)."""
    try:
        found = find_example(str(name))
    except HintedError as exc:
        raise WebError(exc.message, exc.hint, 404) from None
    if found.path.suffix != ".yaml":
        raise WebError(f"{name!r} is not a model", "pick a model from the list", 404)
    return found.path.resolve()


def copy_companions(text: str, source: Path, target: Path, workspace: Workspace) -> list[str]:
    """Copy the files ``text`` names that lie beside the template ``source`` (inside the
    bundled examples) to the same places beside ``target`` (inside the folder), where the
    folder does not have them yet; the copied files, relative to the folder."""
    try:
        data, _ = parse_document(text, target.name)
    except MechloopError:  # a text that does not parse names no file; validation says why
        return []
    bundled = examples_dir().resolve()
    copied = []
    for _, name in file_references(data):
        if Path(name).is_absolute():
            continue
        origin = (source.parent / name).resolve()
        destination = (target.parent / name).resolve()
        if not origin.is_file() or not origin.is_relative_to(bundled) \
                or not destination.is_relative_to(workspace.root) or destination.exists():
            continue
        destination.parent.mkdir(parents=True, exist_ok=True)
        atomic_write_bytes(destination, origin.read_bytes())
        copied.append(workspace.relative(destination))
    return copied
