"""A model as the editor holds it: YAML (or JSON) text, read into a
:class:`~mechloop.model.schema.Model` by the same loader as a file, every problem kept with
its line, YAML path and fix.

The text belongs to a file (``path``: a model in the served folder, or a bundled example):
the files it names (``{csv: ...}`` tables, ``project:`` documents) are read relative to
that file and only from inside ``root`` (the served folder, or the examples' folder).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mechloop.errors import HintedError, MechloopError, ModelError, Problem, format_path
from mechloop.model.document import LineMap, _locate, located_error, parse_document
from mechloop.model.load import model_from_data
from mechloop.model.schema import Model
from mechloop.web.safety import references_outside


@dataclass(frozen=True)
class Document:
    """A model read from text, with the line of every item of the text."""

    model: Model
    lines: LineMap
    path: Path

    def locate(self, error: ModelError) -> ModelError:
        """``error`` (raised after loading, e.g. by the dynamics) with the lines of the
        text."""
        return ModelError([Problem(p.path, p.message, p.hint, p.line or _locate(p.path,
                                                                               self.lines))
                           for p in error.problems], error.file)


def read_model(text: str, path: Path, root: Path) -> Document:
    """The model the text holds (``path``: the file it belongs to, for its CSV tables).

    Raises :class:`~mechloop.errors.ModelError` with every problem located by line.
    """
    data, lines = parse_document(text, path.name)
    outside = references_outside(data, path.parent, root)
    if outside:
        raise located_error([Problem(where, f"the file {name!r} lies outside the folder "
                                     "the server was started in",
                                     "put the file in that folder and give its path "
                                     "relative to the model") for where, name in outside],
                            path.name, lines)
    return Document(model_from_data(data, file=str(path), lines=lines), lines, path)


def problems(error: MechloopError) -> list[dict[str, Any]]:
    """The problems of an error as JSON-ready items: ``line`` (1-based or None), ``path``
    (``vectors[3].a``), ``message``, ``hint``."""
    if isinstance(error, ModelError):
        return [{"line": p.line, "path": format_path(p.path), "message": p.message,
                 "hint": p.hint} for p in error.problems]
    if isinstance(error, HintedError):
        return [{"line": None, "path": "", "message": error.message, "hint": error.hint}]
    return [{"line": None, "path": "", "message": str(error), "hint": ""}]
