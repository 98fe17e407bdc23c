"""Group files: reading and validating one (every problem at once, located), the
mechanism a file describes, setting dimensions and writing the mechanism back.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import yaml

from mechloop.errors import ModelError, Problem
from mechloop.model.document import located_error, read_document, validate_data
from mechloop.model.groups.build import build_model, dimension_names
from mechloop.model.groups.core import GROUND, _choose
from mechloop.model.groups.spec import GroupMechanism
from mechloop.model.salvage import GROUP_CORE, GROUP_PATCHED, salvage, set_aside
from mechloop.model.schema import Model
from mechloop.output.atomic import atomic_write_text


def model_from_group_data(data: dict[str, Any], *, file: str | None = None,
                          lines: dict[tuple[Any, ...], int] | None = None) -> Model:
    """Validate the plain data of a group-built model file and build its vector model;
    every problem is raised at once, located in the file (see
    :func:`mechloop.model.load.model_from_data`, which calls this for ``groups:``)."""
    return _from_group_data(data, file, lines, build_it=True)


def mechanism_of(path: str | Path) -> GroupMechanism | None:
    """The :class:`GroupMechanism` a model file describes (with its tables read), or None
    for a vector model file.  Problems are raised located, as by
    :func:`mechloop.load_model`."""
    data, lines = read_document(path)
    if "groups" not in data:
        return None
    return _from_group_data(data, str(path), lines, build_it=False)


def _from_group_data(data: dict[str, Any], file: str | None,
                     lines: dict[tuple[Any, ...], int] | None, *, build_it: bool) -> Any:
    lines = lines or {}


    mixed = [k for k in ("vectors", "contours", "bodies", "joints") if k in data]
    if mixed:
        raise located_error([Problem((key,), f"'{key}' belongs to a vector model, and this "
                                     "file describes the mechanism by 'groups'",
                                     f"remove '{key}' (the groups generate it), or remove "
                                     "'groups' and write the vector model")
                             for key in mixed], file, lines)
    mech, problems = validate_data(GroupMechanism, data, file, _group_hint)
    if problems:
        partial, dropped = salvage(data, problems, GroupMechanism, GROUP_CORE,
                                   GROUP_PATCHED)
        if partial is not None:  # what else is wrong, in the parts that validated
            try:
                build_model(partial)
            except ModelError as exc:
                problems += [p for p in exc.problems if p.path and p.path[0] in data
                             and not set_aside(p.path, dropped)]
        raise located_error(problems, file, lines)
    try:
        model = build_model(mech)
    except ModelError as exc:
        raise located_error(list(exc.problems), file, lines) from None
    return model if build_it else mech


def with_dimensions(mech: GroupMechanism, values: dict[str, float]) -> GroupMechanism:
    """``mech`` with dimensions set to ``values`` (model units), keyed as synthesis names
    them (``groups[0].lengths[1]``, ``points.P.angle``, ``ground.C.x``; e.g. a synthesis
    result's ``values()``).  The synthesis task is kept, to refine the result."""
    names = dimension_names(mech)
    unknown = [name for name in values if name not in names]
    if unknown:
        raise ModelError([Problem(("synthesis", "vary", name), f"no dimension named "
                                  f"{name!r}", _choose(name, names)) for name in unknown])
    data = mech.model_dump(mode="json", by_alias=True, exclude_defaults=True)
    for name, value in values.items():
        *keys, last = _document_keys(name)
        node: Any = data
        for key in keys:
            node = node[key]
        node[last] = float(value)
    return GroupMechanism.model_validate(data)


def _document_keys(name: str) -> list[str | int]:
    """The keys of a dimension in the mechanism's document: ``groups[0].lengths[1]`` ->
    ``['groups', 0, 'lengths', 1]``, ``ground.C.x`` -> ``['ground', 'C', 0]``."""
    head, _, rest = name.partition(".")
    if head in (GROUND, "points"):
        key, _, attr = rest.rpartition(".")
        return [head, key, "xy".index(attr) if head == GROUND and attr in ("x", "y")
                else attr]
    keys: list[str | int] = []
    for word, index in re.findall(r"([^.\[\]]+)|\[(\d+)\]", name):
        keys.append(int(index) if index else word)
    return keys


def mechanism_text(mech: GroupMechanism, *, json_form: bool = False) -> str:
    """``mech`` as the text of a group file: YAML, or JSON when ``json_form``."""
    data = mech.model_dump(mode="json", by_alias=True, exclude_defaults=True)
    if json_form:
        return json.dumps(data, indent=2, ensure_ascii=False) + "\n"
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True)


def save_mechanism(mech: GroupMechanism, path: str | Path) -> Path:
    """Write ``mech`` as a group file (YAML, or JSON for ``.json``) atomically."""
    target = Path(path)
    atomic_write_text(target, mechanism_text(mech, json_form=target.suffix.lower() == ".json"))
    return target


#: What each field a group file may miss holds, for the fix of a "missing" error.
_FIELD_HINTS = {
    "kind": "add kind: L1 (RRR), L2 (RRP), L3 (RPR), L4 (PRP), L5 (RPP) or III (a triad); "
            "for the input crank or slider",
    "links": "add links: [first, second], the names of the group's two links",
    "at": "add at: the placed point(s) the group is pinned to, e.g. at: [A, C]",
    "joint": "add joint: the name of the new pin, e.g. joint: B",
    "lengths": "add lengths: [|at[0] joint|, |joint at[1]|], the two link lengths",
    "length": "add length: the link's length (length units)",
    "guide": "add guide: {through: O, angle: 0}, the line the slider runs along",
    "guides": "add guides: [{through: O, angle: 0}, {through: C, angle: 90}]",
    "through": "add through: a placed point the guide passes through",
    "pivot": "add pivot: the ground point the crank turns about",
    "slot": "add slot: the angle of the yoke's slot from its guide (90 for a Scotch yoke)",
    "point": "add point: a name for the yoke's point on its guide line",
    "distance": "add distance: how far the point is from 'from' (length units)",
    "link": "add link: the name of the link",
    "input": "add input: {kind: crank, pivot: O, joint: A, length: ..., argument: 1}",
    "ground": "add ground: {O: [0, 0], ...}, the fixed points",
    "positions": "add positions: N (the model is calculated at positions 0..N)",
    "mass": "add mass: the link's mass (mass units)",
    "value": "add value: the magnitude (a number, a quantity or a table)",
    "legs": "add legs: three of {link: l, at: A, length: d, joint: B} (or {link: l, guide: "
            "{through: O, angle: 0}, joint: B} for a sliding leg)",
    "sides": "add sides: [|J1 J2|, |J1 J3|], the middle link's joints from the first one",
    "guess": "add guess: {B: [x, y], ...}, where the triad's joints (and moving attachments) "
             "roughly are at position 0",
}


def _group_hint(error: dict[str, Any], message: str, hint: str) -> tuple[str, str]:
    kind = error["type"]
    loc = error["loc"]
    if kind == "missing" and loc and str(loc[-1]) in _FIELD_HINTS:
        return message, _FIELD_HINTS[str(loc[-1])]
    if kind == "group_kind":
        return message, "write kind: L1 (RRR), L2 (RRP), L3 (RPR), L4 (PRP), L5 (RPP) or " \
                        "III (a triad)"
    if kind == "input_kind":
        return message, "write kind: crank (with pivot, joint, length) or kind: slider " \
                        "(with guide, joint)"
    if kind == "place_form":
        return message, "write a point name (center: B), {share: 0.5} or {from: A, " \
                        "distance: 0.1, angle: 0}"
    if kind == "string_pattern_mismatch":
        return message, "write a name without dots or surrounding spaces (a dot separates " \
                        "a link from a point: coupler.B)"
    if "guess" in loc[:-1] and kind in ("missing", "too_short", "too_long", "tuple_type"):
        return "a position is [x, y]", "write the point's approximate [x, y] (length units)"
    legs = (kind == "missing" and len(loc) >= 2 and str(loc[-2]) == "legs"
            and isinstance(loc[-1], int))
    if legs or (kind in ("too_short", "too_long") and loc and str(loc[-1]) == "legs"):
        return "a triad has three legs", "give exactly three legs"
    if kind in ("too_short", "too_long") and loc and str(loc[-1]) in (
            "links", "at", "lengths", "guides", "sides"):
        return message, "give exactly two items, one per link of the group" if str(
            loc[-1]) != "sides" else "give two sides: [|J1 J2|, |J1 J3|]"
    return message, hint
