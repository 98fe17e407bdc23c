"""The course project's other documents a mechanism model refers to: the cam of sheet 4
(a ``mechloop cam`` document) and the gear pair or planetary train of sheet 3 (a
``mechloop gear`` document), as the optional model section

.. code-block:: yaml

    project: {cam: cams/roller.yaml, gears: gears/gear_pair.yaml}

with paths relative to the model file.  :func:`project_documents` reads them; a missing or
invalid document is a located error of the model file at ``project.cam`` (or
``project.gears``) that quotes the referenced file's own problems.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import Field

from mechloop.errors import MechloopError, ModelError, Problem
from mechloop.model.signals import _Frozen


class Project(_Frozen):
    """References to the course project's cam and gear documents (paths relative to the
    model file)."""

    cam: str | None = Field(None, description="the cam of sheet 4: a mechloop cam document "
                            "(e.g. cams/roller.yaml), relative to the model file")
    gears: str | None = Field(None, description="the gear pair or planetary train of sheet "
                              "3: a mechloop gear document, relative to the model file")


@dataclass(frozen=True)
class ProjectDocuments:
    """The documents read: ``cam`` (a :class:`mechloop.cams.CamDesign`) and ``gears``
    (a :class:`mechloop.views.gear_sheet.GearTask`), None when not given."""

    cam: Any = None
    gears: Any = None


def _problems(error: MechloopError, reference: str) -> list[tuple[str, str]]:
    """The referenced file's own problems as (message, hint) pairs, each naming that file
    (and its line and key when known)."""
    if isinstance(error, ModelError):
        return [("the referenced file has a problem: "
                 + Problem(p.path, p.message, "", p.line).render(error.file or reference),
                 p.hint) for p in error.problems]
    return [(f"the referenced file has a problem: {reference}: "
             f"{getattr(error, 'message', error)}",
             getattr(error, "hint", "") or "")]


def _read(reference: str, base: Path | None, loader) -> tuple[Any, list[tuple]]:
    path = Path(reference)
    if base is not None and not path.is_absolute():
        path = base / path
    try:
        return loader(path), []
    except MechloopError as exc:
        return None, _problems(exc, reference)


def _load_cam(path):
    from mechloop.cams.document import load_cam

    return load_cam(path)


def _load_gears(path):
    from mechloop.views.gear_sheet import load_gears

    return load_gears(path)


def project_documents(model, model_file: str | os.PathLike[str] | None = None, *,
                      cam: str | os.PathLike[str] | None = None,
                      gears: str | os.PathLike[str] | None = None) -> ProjectDocuments:
    """Read the cam and gear documents of ``model`` (its ``project:`` section, paths
    relative to ``model_file``), or the files ``cam``/``gears`` given instead (relative to
    the working directory: the command line's ``--cam``/``--gears``).

    Raises :class:`~mechloop.errors.ModelError` naming the model file, the line and the
    key ``project.cam``/``project.gears`` with the referenced file's own problems, or
    naming the given file itself.
    """
    loaders = {"cam": _load_cam, "gears": _load_gears}
    section: Project | None = getattr(model, "project", None)
    base = Path(model_file).parent if model_file is not None else None
    found: dict[str, Any] = {}
    problems: list[Problem] = []
    for key, given in (("cam", cam), ("gears", gears)):
        if given is not None:  # a file of the command line: its own errors as they are
            found[key] = loaders[key](given)
            continue
        reference = getattr(section, key, None) if section is not None else None
        if reference is None:
            continue
        found[key], errors = _read(reference, base, loaders[key])
        problems += [Problem(("project", key), message, hint) for message, hint in errors]
    if problems:
        from mechloop.model.document import located_error, read_document

        lines = read_document(model_file)[1] if model_file is not None else {}
        raise located_error(problems, None if model_file is None else str(model_file),
                            lines)
    return ProjectDocuments(**found)
