"""Checks of an output path, made before a (possibly long) run writes to it.

A missing or read-only folder, a folder given as the file, an unknown file type and an
output that is the input model are told as one :class:`OutputError` with the path and the
fix, so that a solve or a synthesis of minutes does not end in a traceback or in a lost
model file.
"""

from __future__ import annotations

import errno
import os
from collections.abc import Iterable
from pathlib import Path

from mechloop.errors import HintedError

#: Errors of the disk or the file system while writing, told as an :class:`OutputError`.
DISK_ERRORS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EROFS, errno.EIO,
                         errno.EACCES, errno.EPERM})

#: Table formats that ``solve``, ``sweep`` and ``synthesize --table`` write.
TABLE_SUFFIXES = (".csv", ".json", ".parquet", ".xlsx")


class OutputError(HintedError):
    """An output file cannot be written where it was asked (no such folder, no permission,
    a folder, the input model, an unknown type, a format's size limit)."""


def destination(path: str | os.PathLike[str]) -> Path:
    """The file that writing to ``path`` replaces: absolute, with every symlink followed
    (also a dangling one, whose target is then created), so a link stays a link and the
    file it points to gets the new content."""
    return Path(os.path.realpath(os.path.abspath(path)))


def _names(suffixes: Iterable[str]) -> str:
    items = list(suffixes)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " or " + items[-1]


def check_output(path: str | os.PathLike[str], *, suffixes: Iterable[str] | None = None,
                 inputs: Iterable[str | os.PathLike[str]] = (), force: bool = False) -> Path:
    """``path`` as a Path when a file can be written there; else an :class:`OutputError`.

    ``suffixes``: the file types allowed (e.g. ``(".csv", ".json")``; default: any);
    ``inputs``: the files the run reads (the model), which the output must not be — also
    through a symlink or a hard link — unless ``force`` (default False).
    """
    target = Path(path)
    allowed = tuple(suffixes) if suffixes is not None else None
    dest = destination(target)
    if dest.is_dir():
        example = target / ("results" + (allowed[0] if allowed else ""))
        raise OutputError(f"{target} is a folder, not a file",
                          f"give a file name inside it, e.g. {example}")
    if allowed is not None and target.suffix.lower() not in allowed:
        raise OutputError(f"{target}: unknown output format '{target.suffix}'",
                          f"use a file name ending in {_names(allowed)}")
    folder = dest.parent
    if not folder.exists():
        raise OutputError(f"cannot write {target}: the folder {folder} does not exist",
                          f"create it first (mkdir -p {folder}) or choose another folder")
    if not folder.is_dir():
        raise OutputError(f"cannot write {target}: {folder} is not a folder",
                          "choose a path inside a folder")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise OutputError(f"cannot write {target}: no permission to write in the folder "
                          f"{folder}", "choose a folder you can write to, or change its "
                          "permissions")
    for i, source in enumerate(inputs):
        if dest.exists() and _same(dest, Path(source)) and not force:
            what = "the input model" if i == 0 else "a table the model reads,"
            raise OutputError(f"{target} is {what} {source}: writing it would overwrite it",
                              "choose another output file, or add --force to replace it")
    return target


def model_inputs(model: str | os.PathLike[str]) -> list[Path]:
    """The files a run reads: the model file, then every ``{csv: FILE}`` table in it
    (relative to the model's folder); just the model when it cannot be read (loading
    reports that)."""
    from mechloop.errors import ModelError
    from mechloop.model.load import read_document

    files = [Path(model)]
    try:
        data, _ = read_document(model)
    except ModelError:
        return files
    base = Path(model).resolve().parent
    stack: list[object] = [data]
    while stack:
        item = stack.pop()
        if isinstance(item, dict):
            if isinstance(item.get("csv"), str):
                files.append(base / item["csv"])
            stack.extend(item.values())
        elif isinstance(item, list):
            stack.extend(item)
    return files


def _same(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def write_error(exc: OSError, target: str | os.PathLike[str]) -> OutputError:
    """The :class:`OutputError` for an ``OSError`` met while writing ``target``."""
    reason = exc.strerror or str(exc)
    if exc.errno in (errno.ENOSPC, errno.EDQUOT):
        fix = "free some disk space or write to another disk"
    elif exc.errno == errno.EFBIG:
        fix = "the file system limits the file size: write to another disk or use Parquet"
    elif exc.errno == errno.EROFS:
        fix = "the file system is read-only: choose a folder on a writable disk"
    elif exc.errno in (errno.EACCES, errno.EPERM):
        fix = "choose a folder you can write to, or change its permissions"
    elif exc.errno == errno.ENOENT:
        fix = "check that the folder exists (mkdir -p) or choose another folder"
    else:
        fix = "check the path and the disk"
    return OutputError(f"cannot write {target}: {reason}", fix)


def check_replaces_schema(path: str | os.PathLike[str]) -> None:
    """An :class:`OutputError` when ``path`` is a file that holds something other than a
    JSON Schema (a model, say): ``mechloop schema -o`` replaces only an empty file or an
    earlier schema without ``--force``."""
    import json

    dest = destination(path)
    if not dest.is_file() or dest.stat().st_size == 0:
        return
    data = None
    if dest.stat().st_size < 64 * 2**20:
        try:
            data = json.loads(dest.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            data = None
    if isinstance(data, dict) and "properties" in data and (
            "$schema" in data or "$defs" in data or data.get("type") == "object"):
        return
    raise OutputError(f"{path} exists and holds no JSON Schema (a model file?): writing the "
                      "schema would replace it",
                      "choose another file name, or add --force to replace the file")
