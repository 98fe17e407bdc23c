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
``groups`` and ``points`` also in its core (:data:`GROUP_CORE`), with one step more: in
those four sections (:data:`GROUP_PATCHED`) a broken value inside an item — a dimension
that is not a number, a list of the wrong length, a variant out of range — is replaced by
a stand-in that validates (the key's default when it has one, else the dimension 1 or
the pair ``[1, 1]``), so the builder still checks the names and links of the whole file.
A stand-in is a constant dimension, which changes nothing the builder checks about
names; the problems it finds at or under a replaced value are not reported (they would be
about the stand-in).  A broken name, a group kind or a section that is not a list or
mapping has no stand-in: the schema problems are then all that is reported.
"""

from __future__ import annotations

import copy
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from mechloop.errors import Problem
from mechloop.model.document import _data_path
from mechloop.model.schema import Model

#: Sections whose every item the structure depends on.
CORE = frozenset({"positions", "units", "arguments", "vectors", "contours"})
#: The same for a file built from Assur groups.
GROUP_CORE = CORE | {"ground", "input", "groups", "points"}
#: Sections of a group file whose broken values inside an item get a stand-in.
GROUP_PATCHED = frozenset({"ground", "input", "groups", "points"})

#: Most broken values given stand-ins (each costs up to three validations of the file);
#: with more, the schema problems are all that is reported.
MAX_STAND_INS = 20

#: Stand-ins tried for a broken value, in order (None: remove the key, for its default).
_STAND_INS: tuple[Any, ...] = (None, 1.0, [1.0, 1.0])

#: Sections of a group file keyed by names (a key there is a point, not a setting).
_NAMED = frozenset({"ground", "points"})

T = TypeVar("T", bound=BaseModel)


def salvage(data: dict[str, Any], problems: list[Problem], cls: type[T] = Model,
            core: frozenset[str] = CORE, patched: frozenset[str] = frozenset()
            ) -> tuple[T | None, frozenset[tuple]]:
    """``cls`` (a :class:`Model`) validated from ``data`` without what ``problems``
    (schema problems, by document path) concern, and the document paths set aside (a
    top-level section dropped, a value replaced by a stand-in in a section of
    ``patched``); ``(None, ...)`` when nothing sound is left to check."""
    pruned = copy.deepcopy(data)
    dropped: set[tuple] = set()
    stand: list[tuple] = []
    for problem in problems:
        path = problem.path
        if not path:
            return None, frozenset()
        if problem.message.startswith("unknown key") and _delete(pruned, path):
            continue
        if path[0] in patched and len(path) >= 2:
            stand.append(tuple(path))
            continue
        if path[0] in core:
            return None, frozenset()
        pruned.pop(path[0], None)
        dropped.add((path[0],))
    if len(set(stand)) > MAX_STAND_INS:
        return None, frozenset()
    for path in sorted(set(stand), key=len, reverse=True):  # the innermost first
        replaced = _stand_in(pruned, path, cls)
        if replaced is None:
            return None, frozenset()
        dropped.add(replaced)
    try:
        return cls.model_validate(pruned), frozenset(dropped)
    except ValidationError:
        return None, frozenset()


def set_aside(path: tuple, dropped: frozenset[tuple]) -> bool:
    """Whether a problem at ``path`` concerns what :func:`salvage` set aside (it is at or
    under a dropped section or a replaced value)."""
    return any(tuple(path[:len(d)]) == d for d in dropped)


def _stand_in(data: dict[str, Any], path: tuple, cls: type[BaseModel]) -> tuple | None:
    """Replace the value at ``path`` by the first stand-in that leaves no schema problem
    at or under ``path``; the path replaced (``path``, or the list an item is missing
    from), None when no stand-in does."""
    *parents, last = path
    parent: Any = data
    for key in parents:
        try:
            parent = parent[key]
        except (KeyError, IndexError, TypeError):
            return None
    if isinstance(parent, list) and isinstance(last, int) and not 0 <= last < len(parent) \
            and len(parents) >= 2:  # an item missing from a list: replace the list
        return _stand_in(data, tuple(parents), cls)
    if not isinstance(parent, dict | list) or (
            isinstance(parent, list) and not (isinstance(last, int) and 0 <= last < len(parent))):
        return None
    had, old = (last in parent, parent.get(last)) if isinstance(parent, dict) \
        else (True, parent[last])
    for value in _STAND_INS:
        if value is None:
            if not isinstance(parent, dict) or (len(path) == 2 and path[0] in _NAMED):
                continue  # not a key with a default (an item, a named point)
            parent.pop(last, None)
        else:
            parent[last] = copy.deepcopy(value)
        try:
            cls.model_validate(data)
            return path
        except ValidationError as exc:
            if not any(set_aside(_data_path(e["loc"], data), frozenset({path}))
                       for e in exc.errors()):
                return path
        if had:
            parent[last] = old
        elif isinstance(parent, dict):
            parent.pop(last, None)
    return None


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
