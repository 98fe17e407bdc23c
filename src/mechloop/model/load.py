"""Reading and writing model files (YAML or JSON) with located, complete error reports.

Every problem — YAML syntax, a wrong type, an unknown key, a structural mistake — becomes a
:class:`~mechloop.errors.Problem` with the file, the line and the path in the document, and
all of them are raised together as one :class:`~mechloop.errors.ModelError`.
Saving writes a temporary file beside the target and renames it, so a crash never leaves a
half-written model.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import yaml

from mechloop.errors import ModelError, ModelFileError, Problem
from mechloop.model.check import check_model
from mechloop.model.document import (  # noqa: F401 (re-exported: the loading API)
    MAX_PROBLEMS,
    LineMap,
    _data_path,
    _locate,
    _validate_tables,
    located_error,
    read_document,
    validate_data,
)
from mechloop.model.groups.files import model_from_group_data
from mechloop.model.salvage import salvage, set_aside
from mechloop.model.schema import Model, set_model_reader
from mechloop.output.atomic import atomic_write_bytes, atomic_write_text  # noqa: F401 (re-exported)


def model_from_data(data: Any, *, file: str | None = None, lines: LineMap | None = None
                    ) -> Model:
    """Validate plain data into a :class:`Model`, raising all problems at once."""
    lines = lines or {}
    if not isinstance(data, dict):
        raise ModelFileError([Problem((), "a model is a mapping of keys",
                                      "see examples/crank_slider.yaml")], file)
    if "cam" in data and "vectors" not in data:  # a cam design (mechloop.cams), not a model
        raise ModelFileError([Problem(("cam",), "this file is a cam design, not a vector "
                                      "model", "use mechloop cam FILE")], file)
    if "groups" in data:  # a mechanism built from Assur groups: generate its vector model
        return model_from_group_data(data, file=file, lines=lines)
    model, problems, tables, unread = _validate_tables(Model, data, file)
    if problems:  # an unread table validates as is
        partial, dropped = salvage(tables, [p for p in problems if p not in unread])
        if partial is not None:  # what else is wrong, in the parts that validated
            problems += [p for p in check_model(partial)[1]
                         if not (p.path and set_aside(p.path, dropped))]
        raise located_error(problems, file, lines)
    _, problems = check_model(model)
    if problems:
        raise located_error(problems, file, lines)
    return model


set_model_reader(model_from_data)  # Model.from_dict reads through the loader


def load_model(path: str | os.PathLike[str]) -> Model:
    """Read, validate and check a model file (``.yaml``, ``.yml`` or ``.json``); a file
    with ``groups:`` describes the mechanism by Assur groups and gives the vector model
    generated from them (:mod:`mechloop.model.groups`).

    Raises :class:`~mechloop.errors.ModelError` naming the file, line, item and fix of
    every problem.
    """
    data, lines = read_document(path)
    return model_from_data(data, file=str(path), lines=lines)


def locate(error: ModelError, path: str | os.PathLike[str]) -> ModelError:
    """``error`` (raised for a model after it was loaded, e.g. by the dynamics) with the
    file and lines of the model file at ``path``."""
    _, lines = read_document(path)
    return ModelError([Problem(p.path, p.message, p.hint, p.line or _locate(p.path, lines))
                       for p in error.problems], str(path))


def model_to_data(model: Model) -> dict[str, Any]:
    """Plain data of a model, ready for YAML or JSON (defaults left out)."""
    return model.model_dump(mode="json", exclude_defaults=True)


def save_model(model: Model, path: str | os.PathLike[str]) -> None:
    """Write ``model`` to ``path`` (YAML, or JSON for ``.json``) atomically."""
    data = model_to_data(model)
    target = Path(path)
    if target.suffix.lower() == ".json":
        text = json.dumps(data, indent=2, ensure_ascii=False) + "\n"
    else:
        text = yaml.safe_dump(data, sort_keys=False, allow_unicode=True)
    atomic_write_text(target, text)
