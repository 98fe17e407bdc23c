"""``mechloop new``: copy a bundled example to start a model from."""

from __future__ import annotations

from pathlib import Path

from mechloop.bundled.catalog import Example, find_example
from mechloop.errors import HintedError


def new_model(name: str, target: Path | None = None) -> tuple[Example, Path]:
    """Copy the example ``name`` (see :func:`find_example`) to ``target``: a folder (the
    example's file name inside it; default the current folder) or a file path.

    Returns:
        The example and the path written.

    Raises:
        HintedError: no such example, the target exists (never overwritten), or its folder
        is missing.
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
    try:
        with path.open("x", encoding="utf-8") as handle:
            handle.write(example.path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise HintedError(f"cannot write {path}: {exc.strerror}",
                          "give a folder you can write to") from None
    return example, path
