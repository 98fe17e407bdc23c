"""Bounds on a model document, checked before anything in it is expanded or constructed.

A model file is read in three steps, each bounded before the next starts:

1. its size: at most :data:`MAX_DOCUMENT_BYTES` (2 MiB — a model with 100,000 positions
   tabulated inline takes about 1.1 MB; longer tables belong in a CSV file);
2. its text: UTF-8, a bad byte is reported with its line and column;
3. its YAML events (:func:`yaml.parse`, which neither nests nor expands): nesting at most
   :data:`MAX_DEPTH` (64) collections deep, no scalar longer than :data:`MAX_SCALAR_CHARS`
   (10,000 characters), and at most :data:`MAX_NODES` (1,000,000) items once every alias
   is expanded — counted with each anchor's expanded size remembered, so a "billion laughs"
   document of a few hundred bytes is refused after a few dozen events instead of being
   expanded into gigabytes.

Each violation is one located :class:`~mechloop.errors.ModelFileError`.
"""

from __future__ import annotations

from pathlib import Path

import yaml

from mechloop.errors import ModelFileError, Problem

#: Largest model file read, bytes.
MAX_DOCUMENT_BYTES = 2 * 1024 * 1024
#: Deepest nesting of mappings and lists.
MAX_DEPTH = 64
#: Longest single value (a string or a number as written), characters.
MAX_SCALAR_CHARS = 10_000
#: Most items (mappings, lists and values, every alias expanded) in one document.
MAX_NODES = 1_000_000

_Parser = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def read_text(path: str | Path) -> str:
    """The text of a model file, refused when it is larger than :data:`MAX_DOCUMENT_BYTES`
    or not UTF-8 (the error names the line and column of the first bad byte).

    Raises ``FileNotFoundError`` and ``OSError`` as :func:`open` does.
    """
    file = str(path)
    with open(path, "rb") as handle:
        payload = handle.read(MAX_DOCUMENT_BYTES + 1)
    if len(payload) > MAX_DOCUMENT_BYTES:
        raise ModelFileError([Problem(
            (), f"the file is larger than {MAX_DOCUMENT_BYTES // 1024 // 1024} MiB, the "
            "limit for a model file",
            "put long tables in a CSV file ({csv: table.csv}) and keep the model small")],
            file)
    try:
        return payload.decode("utf-8")
    except UnicodeDecodeError as exc:
        before = payload[:exc.start]
        line = before.count(b"\n") + 1
        column = exc.start - (before.rfind(b"\n") + 1) + 1
        raise ModelFileError([Problem(
            (), f"byte 0x{payload[exc.start]:02x} at column {column} is not UTF-8 text",
            "save the file as UTF-8 (or remove the character)", line)], file) from None


def check_events(text: str, file: str | None = None) -> None:
    """Refuse a document that nests too deep, holds a too long value or expands (through
    aliases) to too many items, before it is composed.  A YAML syntax error is left for the
    full parse to report.

    The events come from libyaml when it is installed (fast); where libyaml stops on
    something PyYAML's own parser accepts, the scan is repeated with that parser, so the
    rest of the document is not left unchecked.
    """
    if not _scan(text, _Parser, file) and _Parser is not yaml.SafeLoader:
        _scan(text, yaml.SafeLoader, file)


def _scan(text: str, parser: type, file: str | None) -> bool:
    """Check the events of ``text`` from ``parser``; False when it met a syntax error."""
    depth = 0
    counts: list[tuple[str | None, int]] = []  # open collections: (anchor, items so far)
    sizes: dict[str, int] = {}  # anchor -> expanded size
    total = 0
    try:
        for event in yaml.parse(text, Loader=parser):
            line = event.start_mark.line + 1 if event.start_mark is not None else None
            if isinstance(event, yaml.CollectionStartEvent):
                depth += 1
                if depth > MAX_DEPTH:
                    _refuse(f"the document nests more than {MAX_DEPTH} levels deep",
                            "a model needs only a few levels: remove the extra brackets or "
                            "indentation", line, file)
                counts.append((event.anchor, 1))
                continue
            if isinstance(event, yaml.CollectionEndEvent):
                depth -= 1
                anchor, size = counts.pop()
            elif isinstance(event, yaml.ScalarEvent):
                if len(event.value) > MAX_SCALAR_CHARS:
                    _refuse(f"a value of {len(event.value):,} characters (the limit is "
                            f"{MAX_SCALAR_CHARS:,})", "shorten it: numbers and units are "
                            "short, and long tables belong in a CSV file", line, file)
                anchor, size = event.anchor, 1
            elif isinstance(event, yaml.AliasEvent):
                anchor, size = None, sizes.get(event.anchor, 1)
            else:
                continue
            if anchor is not None:
                sizes[anchor] = size
            if counts:
                counts[-1] = (counts[-1][0], counts[-1][1] + size)
            total += size if isinstance(event, yaml.AliasEvent) else 1
            if total > MAX_NODES:
                _refuse(f"the document expands to more than {MAX_NODES:,} items (aliases "
                        "count each time they are used)", "write the values out instead of "
                        "repeating anchors (&name / *name) inside each other", line, file)
    except yaml.YAMLError:
        return False
    return True


def _refuse(message: str, hint: str, line: int | None, file: str | None) -> None:
    raise ModelFileError([Problem((), message, hint, line)], file)
