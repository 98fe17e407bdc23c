"""The part of an invalid model file that still validates, so that its structural problems
are reported together with its schema problems (one pass lists everything that can be
known; fixing one mistake does not reveal three more).

A schema problem is set aside without losing what the rest of the file says:

* an unknown key (a misspelling) is dropped: it says nothing the model uses;
* a problem inside a section the kinematic structure does not read (``time``, ``bodies``,
  ``joints``, ``forces``, ``moments``, ``gravity``, ``friction``, ``machine``,
  ``synthesis``, ``name``, ``description``) drops that section;
* a problem in ``positions``, ``units``, ``arguments``, ``vectors`` or ``contours`` leaves
  nothing sound to check: the schema problems are all that is reported.

A file built from Assur groups is salvaged the same way, with ``ground``, ``input``,
``groups`` and ``points`` also in its core (:data:`GROUP_CORE`).
"""

from __future__ import annotations

import copy
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from mechloop.errors import Problem
from mechloop.model.schema import Model

#: Sections whose every item the structure depends on.
CORE = frozenset({"positions", "units", "arguments", "vectors", "contours"})
#: The same for a file built from Assur groups.
GROUP_CORE = CORE | {"ground", "input", "groups", "points"}

T = TypeVar("T", bound=BaseModel)


def salvage(data: dict[str, Any], problems: list[Problem], cls: type[T] = Model,
            core: frozenset[str] = CORE) -> tuple[T | None, frozenset[str]]:
    """``cls`` (a :class:`Model`) validated from ``data`` without what ``problems``
    (schema problems, by document path) concern, and the top-level sections dropped;
    ``(None, ...)`` when nothing sound is left to check."""
    pruned = copy.deepcopy(data)
    dropped: set[str] = set()
    for problem in problems:
        path = problem.path
        if not path:
            return None, frozenset()
        if problem.message.startswith("unknown key") and _delete(pruned, path):
            continue
        if path[0] in core:
            return None, frozenset()
        pruned.pop(path[0], None)
        dropped.add(str(path[0]))
    try:
        return cls.model_validate(pruned), frozenset(dropped)
    except ValidationError:
        return None, frozenset()


def _delete(data: Any, path: tuple) -> bool:
    """Remove the item at ``path``; whether it was there."""
    *parents, last = path
    for key in parents:
        try:
            data = data[key]
        except (KeyError, IndexError, TypeError):
            return False
    if isinstance(data, dict) and last in data:
        del data[last]
        return True
    return False
