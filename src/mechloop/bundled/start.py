"""``mechloop new``: copy a bundled example to start a model from, with the course
project's documents its ``project:`` section refers to (the cam and gear files, kept at
the same paths relative to the copy, so the copy still reports sheets 3 and 4)."""

from __future__ import annotations

from pathlib import Path, PurePosixPath

import yaml

from mechloop.bundled.catalog import Example, find_example
from mechloop.errors import HintedError


def project_references(model_file: Path) -> list[str]:
    """The relative paths the ``project:`` section of ``model_file`` names (cam first,
    then gears); none when it has no such section."""
    data = yaml.safe_load(model_file.read_text(encoding="utf-8"))
    section = data.get("project") if isinstance(data, dict) else None
    if not isinstance(section, dict):
        return []
    return [str(section[key]) for key in ("cam", "gears") if section.get(key)]


def _documents(example: Example, folder: Path) -> list[tuple[Path, str]]:
    """(where to write, text) of each project document of ``example`` beside a copy in
    ``folder``; a document already there with the same text is not written again, one
    with another text is refused (never overwritten)."""
    out = []
    for reference in project_references(example.path):
        relative = PurePosixPath(reference)
        if relative.is_absolute() or ".." in relative.parts:
            continue  # not a file beside the example: nothing to carry along
        text = (example.path.parent / relative).read_text(encoding="utf-8")
        target = folder / relative
        if target.exists():
            if target.read_text(encoding="utf-8") != text:
                raise HintedError(f"{target} already exists (a project document of "
                                  f"{example.path.name}): mechloop new does not overwrite",
                                  "give another folder, or remove the file first")
            continue
        out.append((target, text))
    return out


def new_model(name: str, target: Path | None = None) -> tuple[Example, Path]:
    """Copy the example ``name`` (see :func:`find_example`) to ``target``: a folder (the
    example's file name inside it; default the current folder) or a file path.  The
    documents of its ``project:`` section are copied too, at the same paths relative to
    the copy (e.g. ``project/01_cam.yaml``); :func:`project_references` names them.

    Returns:
        The example and the path written.

    Raises:
        HintedError: no such example, the target (or a project document with other
        content) exists (never overwritten), or its folder is missing.
    """
    example = find_example(name)
    target = Path.cwd() if target is None else target
    path = target / example.path.name if target.is_dir() else target
    if path.exists():
        raise HintedError(f"{path} already exists: mechloop new does not overwrite",
                          "give another folder or file name, or remove the file first")
    if not path.parent.is_dir():
        raise HintedError(f"the folder {path.parent} does not exist",
                          "create it first, or give an existing folder")
    if path.suffix != example.path.suffix:
        raise HintedError(f"{path} does not end in {example.path.suffix}",
                          f"name the copy *{example.path.suffix}, or give a folder")
    documents = _documents(example, path.parent) if example.path.suffix == ".yaml" else []
    try:
        for document, text in documents:
            document.parent.mkdir(parents=True, exist_ok=True)
            with document.open("x", encoding="utf-8") as handle:
                handle.write(text)
        with path.open("x", encoding="utf-8") as handle:
            handle.write(example.path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise HintedError(f"cannot write {exc.filename or path}: {exc.strerror}",
                          "give a folder you can write to") from None
    return example, path
