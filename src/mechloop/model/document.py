"""A model document as read from a file: YAML or JSON parsed into plain data with the line
of every item, validated into a schema class with every problem collected, and problems
located by line.

This is the lowest layer of loading: :mod:`.load` (vector models) and :mod:`.group_load`
(group files) build on it, and :mod:`.salvage` uses its paths.  It knows no particular
model: the class to validate is a parameter.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Hashable
from pathlib import Path
from typing import Any, TypeVar

import yaml
from pydantic import ValidationError

from mechloop.errors import ModelError, ModelFileError, Problem
from mechloop.model.limits import check_events, read_text
from mechloop.model.signals import MAX_POSITIONS, read_csv_table

T = TypeVar("T")

LineMap = dict[tuple[Any, ...], int]


class _Loader(yaml.SafeLoader):
    """SafeLoader that refuses duplicate keys (a silent overwrite loses data)."""


def _construct_mapping(loader: _Loader, node: yaml.MappingNode, deep: bool = False):
    mapping: dict[Any, Any] = {}
    for key_node, value_node in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if not isinstance(key, Hashable):
            error = yaml.constructor.ConstructorError(
                "while reading a mapping", node.start_mark,
                "found a list or mapping as a key", key_node.start_mark)
            error.hint = "a key is a name or a number: write 'key: value'"  # type: ignore[attr-defined]
            raise error
        if key in mapping:
            raise yaml.constructor.ConstructorError(
                "while reading a mapping", node.start_mark,
                f"found the key {key!r} twice", key_node.start_mark)
        mapping[key] = loader.construct_object(value_node, deep=deep)
    return mapping


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


def _line_map(node: yaml.Node, loader: _Loader, path: tuple = (), out: LineMap | None = None
              ) -> LineMap:
    """Path in the document -> 1-based line where that item starts."""
    out = {} if out is None else out
    out[path] = node.start_mark.line + 1
    if isinstance(node, yaml.MappingNode):
        for key_node, value_node in node.value:
            try:
                key = loader.construct_object(key_node, deep=True)
            except yaml.YAMLError:
                continue
            if isinstance(key, list | dict):
                continue
            out[(*path, key)] = key_node.start_mark.line + 1
            _line_map(value_node, loader, (*path, key), out)
            out[(*path, key)] = key_node.start_mark.line + 1
    elif isinstance(node, yaml.SequenceNode):
        for i, item in enumerate(node.value):
            _line_map(item, loader, (*path, i), out)
    return out


def _locate(path: tuple, lines: LineMap) -> int | None:
    """Line of ``path``, or of its nearest ancestor that is in the file."""
    for cut in range(len(path), -1, -1):
        line = lines.get(tuple(path[:cut]))
        if line is not None:
            return line
    return None


def read_document(path: str | os.PathLike[str]) -> tuple[Any, LineMap]:
    """Parse a YAML/JSON file into plain data and a map of lines; errors name the line."""
    file = str(path)
    try:
        text = read_text(path)
    except FileNotFoundError:
        raise ModelFileError([Problem((), "file not found",
                                      "check the path (mechloop check examples/... )")],
                             file) from None
    except OSError as exc:
        raise ModelFileError([Problem((), f"cannot read the file: {exc.strerror or exc}",
                                      "check the path and its permissions")], file) from None
    return parse_document(text, file)


def parse_document(text: str, file: str | None = None) -> tuple[Any, LineMap]:
    """Parse the YAML/JSON ``text`` of a model (``file``: the name its errors carry) into
    plain data and a map of lines; errors name the line."""
    check_events(text, file)
    try:
        loader = _Loader(text)
        try:
            node = loader.get_single_node()
            data = loader.construct_document(node) if node is not None else None
            lines = _line_map(node, loader) if node is not None else {}
        finally:
            loader.dispose()
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        line = mark.line + 1 if mark is not None else None
        what = getattr(exc, "problem", None) or str(exc)
        context = getattr(exc, "context", None)
        context_mark = getattr(exc, "context_mark", None)
        if context and context_mark is not None and context_mark is not mark:
            context += f" that starts at line {context_mark.line + 1}"
        message = f"YAML syntax error: {what}" + (f" ({context})" if context else "")
        hint = getattr(exc, "hint", None) or ("fix the YAML syntax at that line (indentation, "
                                              "a missing ':' or an unclosed bracket)")
        raise ModelFileError([Problem((), message, hint, line)], file) from None
    if not isinstance(data, dict):
        raise ModelFileError([Problem((), "the file does not hold a model mapping",
                                      "start with keys like 'positions:', 'vectors:' and "
                                      "'contours:' (see examples/crank_slider.yaml)", 1)],
                             file)
    return data, lines


def _data_path(loc: tuple, data: Any) -> tuple:
    """Turn a pydantic error location into a path of the document.

    Union tags and other validator names that pydantic puts in ``loc`` are not keys of the
    document and are dropped; a last element that is not in the document (a missing key)
    is kept.
    """
    path: list[Any] = []
    current = data
    for i, key in enumerate(loc):
        if isinstance(current, dict):
            match = next((k for k in current if k == key or str(k) == str(key)), _MISSING)
            if match is not _MISSING and i < len(loc) - 1 and loc[i + 1] in current \
                    and not isinstance(current[match], dict | list | tuple):
                continue  # a union tag that is also a key (time: {rpm: ...}): not a step
            if match is not _MISSING:
                path.append(match)
                current = current[match]
            elif i == len(loc) - 1 and isinstance(key, str):
                path.append(key)
        elif isinstance(current, list | tuple) and isinstance(key, int):
            path.append(key)
            current = current[key] if 0 <= key < len(current) else None
    return tuple(path)


_MISSING = object()

_HINTS = {
    "missing": "add it",
    "extra_forbidden": "remove it, or check its spelling",
    "int_parsing": "write a whole number",
    "int_from_float": "write a whole number",
    "float_parsing": "write a number",
    "literal_error": "use one of the allowed values",
    "greater_than_equal": "use a larger value",
    "greater_than": "use a larger value",
    "too_short": "add more items",
    "less_than_equal": "use a smaller value",
    "less_than": "use a smaller value",
    "number_range": "write a finite number of a physical size (model units)",
    "ratio_fraction": "write the ratio as teeth over teeth, e.g. -20/50",
    "quantity_length": "write a number and a unit, e.g. '50 mm'",
    "string_too_long": "shorten it: a unit is a short name like 'mm' or 'kN*m'",
    "string_pattern_mismatch": "write the parameter as 'a' or 'r' and a vector number, "
                               "e.g. 'a2'",
}


_BOUNDS = ("greater_than_equal", "greater_than", "less_than_equal", "less_than")


def _describe(error: dict[str, Any]) -> tuple[str, str]:
    kind = error["type"]
    loc = error["loc"]
    name = str(loc[-1]) if loc else "the model"
    message = error["msg"]
    if kind == "missing":
        message = f"'{name}' is required"
    elif kind == "extra_forbidden":
        message = f"unknown key '{name}'"
    hint = _HINTS.get(kind, "")
    value = error.get("input")
    if kind in _BOUNDS and isinstance(value, float) and not math.isfinite(value):
        # pydantic compares a NaN with a bound first and calls it too large or too small
        message = f"{value} is not a finite number"
        hint = "write a finite number"
    if kind == "float_parsing" and loc and loc[-1] == "ratio":
        hint = "write a number or a fraction of tooth counts, e.g. ratio: -20/50"
    if kind == "parameter_role":
        hint = "write e.g. r: 0.05, a: function, a: {argument: 1}, a: {link: a2, delta: 30}"
    elif kind == "argument_form":
        hint = "e.g. 1: {table: {0: 0, 72: 360}} or 1: {law: cycloidal, start: [0, 0], " \
               "end: [36, 90]}"
    elif kind == "table_form":
        hint = "e.g. table: {0: 0, 72: 360} or table: [0, 5, 10, ...]"
    elif kind == "int_parsing" and loc and loc[-1] == "[key]":
        message = "a table position must be a whole number"
        hint = "write positions as 0, 1, 2, ..."
    elif kind == "less_than_equal" and tuple(loc) == ("positions",):
        message = f"{error['input']} positions; a model has at most {MAX_POSITIONS:,}"
        hint = "use fewer positions (a smooth curve needs a few hundred to a few thousand)"
    elif kind == "time_form":
        hint = "e.g. time: {rpm: 3000} or time: {table: {0: 0, 36: 0.03}}"
    return message, hint


def validate_data(cls: type[T], data: dict[str, Any], file: str | None,
                  hint: Callable[[dict[str, Any], str, str], tuple[str, str]] | None = None
                  ) -> tuple[T | None, list[Problem]]:
    """``cls`` validated from the plain data of a file, its CSV tables read first (paths
    relative to the file); or None and every problem, not yet located by line.  ``hint``
    may rewrite the message and fix of a validation error."""
    value, problems, _, _ = _validate_tables(cls, data, file, hint)
    return value, problems


def _validate_tables(cls: type[T], data: dict[str, Any], file: str | None,
                     hint: Callable[[dict[str, Any], str, str], tuple[str, str]] | None = None
                     ) -> tuple[T | None, list[Problem], dict[str, Any], list[Problem]]:
    """:func:`validate_data`, and the data with its CSV tables read and the problems of
    the tables that could not be read (each CSV file is read once)."""
    base = Path(file).resolve().parent if file else Path.cwd()
    data, unread = _import_csv_tables(data, base)  # an unread table stays {csv: ...}
    problems = list(unread)
    try:
        value = cls.model_validate(data)
    except ValidationError as exc:
        for error in exc.errors():
            message, fix = _describe(error)
            if hint is not None:
                message, fix = hint(error, message, fix)
            problems.append(Problem(_data_path(error["loc"], data), message, fix))
        return None, problems, data, unread
    return (None, problems, data, unread) if problems else (value, [], data, unread)


#: Problems listed one by one in an error; the rest are counted.
MAX_PROBLEMS = 50


def located_error(problems: list[Problem], file: str | None, lines: LineMap) -> ModelError:
    """The problems, each with its line in ``file`` (when it has none yet), in the order of
    the file, as one error (the first :data:`MAX_PROBLEMS` of them, and how many more
    there are)."""
    unique = [Problem(p.path, p.message, p.hint, p.line or _locate(p.path, lines))
              for p in _dedupe(problems)]
    unique.sort(key=lambda p: p.line or 0)  # in the order of the file
    shown = unique[:MAX_PROBLEMS]
    if len(unique) > MAX_PROBLEMS:
        shown.append(Problem((), f"{len(unique) - MAX_PROBLEMS:,} more problems not listed",
                             "fix the ones above, then check the file again"))
    return ModelError(shown, file)


def _import_csv_tables(data: dict[str, Any], base: Path
                       ) -> tuple[dict[str, Any], list[Problem]]:
    """Replace every ``{csv: ...}`` table (arguments, time, load values) by the table it
    holds; the files are read relative to ``base``."""
    problems: list[Problem] = []

    def convert(value: Any, path: tuple) -> Any:
        if not (isinstance(value, dict) and "csv" in value):
            return value
        try:
            return read_csv_table(value, base)
        except ValueError as exc:
            message, hint = exc.args if len(exc.args) == 2 else (str(exc), "")
            problems.append(Problem(path, message, hint))
            return value

    data = dict(data)
    if isinstance(data.get("arguments"), dict):
        data["arguments"] = {k: convert(v, ("arguments", k))
                             for k, v in data["arguments"].items()}
    if "time" in data:
        data["time"] = convert(data["time"], ("time",))
    for key in ("forces", "moments"):
        if isinstance(data.get(key), list):
            data[key] = [dict(item, value=convert(item["value"], (key, i, "value")))
                         if isinstance(item, dict) and "value" in item else item
                         for i, item in enumerate(data[key])]
    return data, problems


def _dedupe(problems: list[Problem]) -> list[Problem]:
    seen = set()
    out = []
    for p in problems:
        key = (p.path, p.message)
        if key not in seen:
            seen.add(key)
            out.append(p)
    return out
