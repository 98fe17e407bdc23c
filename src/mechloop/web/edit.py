"""One change of a model's YAML text, made in place: the forms and the drag of the web page
change a value, add or remove a row, or rename a key by its key path, and every other byte
of the text — the user's comments, blank lines, layout, quoting — stays as it was.

The text is composed with PyYAML (the same loader and limits as a model file,
:func:`mechloop.model.document.parse_document`); the node at the path gives the span of
text (its start and end marks) that the change replaces, and only that span changes:

* **set** (``value``): the node's text becomes the value written as YAML on one line
  (a mapping or list in flow style, ``{law: linear, start: [0, 0]}``); a key that is not
  there yet is added — in a block mapping as a new line under the last entry, at its
  indent; in a flow mapping or list before its closing bracket;
* **delete**: the entry (its whole lines in block style, the item and its comma in flow
  style); the only entry of a collection leaves ``{}`` or ``[]``;
* **rename** (``key``): the key's text only.

The value comes from JSON: keys of a mapping written with digits only (``"36"``) become
whole numbers (YAML's ``36:``, as argument tables and vectors are keyed); a path element
matches a key equal to it or to its digits' number.  The changed text is read back and
the value at the path compared with the value asked: an edit that would read back
differently is refused rather than written.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from typing import Any

import yaml

from mechloop.errors import ModelError, format_path
from mechloop.model.document import _Loader, parse_document
from mechloop.model.limits import MAX_DEPTH, MAX_DOCUMENT_BYTES, check_events
from mechloop.web.safety import WebError

#: Longest key path of one edit.
MAX_PATH = MAX_DEPTH
_DIGITS = re.compile(r"^-?[0-9]+$")

Key = str | int


def plain(value: Any) -> Any:
    """``value`` from JSON with the keys of every mapping that are digits as numbers."""
    if isinstance(value, dict):
        return {(int(k) if isinstance(k, str) and _DIGITS.match(k) else k): plain(v)
                for k, v in value.items()}
    if isinstance(value, list):
        return [plain(v) for v in value]
    return value


def _check_value(value: Any, depth: int = 0) -> None:
    if depth > MAX_DEPTH:
        raise WebError("the value nests too deep", f"at most {MAX_DEPTH} levels", 413)
    if isinstance(value, float) and not math.isfinite(value):
        raise WebError("the value is not a finite number", "give a finite number")
    if isinstance(value, dict):
        for k, v in value.items():
            if not isinstance(k, str | int) or isinstance(k, bool):
                raise WebError(f"the key {k!r} is not a name or a number", "use a name")
            _check_value(v, depth + 1)
    elif isinstance(value, list):
        for v in value:
            _check_value(v, depth + 1)
    elif not (value is None or isinstance(value, bool | int | float | str)):
        raise WebError(f"{type(value).__name__} is not a value of a model",
                       "give a number, a string, true/false, null, a list or a mapping")


def render(value: Any, *, as_json: bool = False) -> str:
    """``value`` as YAML text on one line (JSON, which is YAML too, for a JSON model or a
    string with a line break)."""
    if as_json:
        return json.dumps(value, ensure_ascii=False)
    text = yaml.safe_dump(value, default_flow_style=True, width=10**9, allow_unicode=True,
                          sort_keys=False)
    text = text.removesuffix("\n").removesuffix("\n...").removesuffix("\n")
    if "\n" in text:  # a string with line breaks: YAML folds it; JSON escapes them
        return json.dumps(value, ensure_ascii=False)
    return text


@dataclass(frozen=True)
class _Step:
    """One level of the path: the collection, the index of the entry in it (None: not
    there yet) and its key node (mappings)."""

    parent: yaml.Node
    index: int | None
    key_node: yaml.Node | None


def _key_of(node: yaml.Node, loader: _Loader) -> Any:
    try:
        return loader.construct_object(node, deep=True)
    except yaml.YAMLError:
        return None


def _same_key(key: Any, wanted: Key) -> bool:
    if isinstance(key, bool):
        return False
    if key == wanted:
        return True
    return (isinstance(wanted, str) and isinstance(key, int) and bool(_DIGITS.match(wanted))
            and key == int(wanted))


def _end(node: yaml.Node) -> int:
    """The index just after the node's own text: a block collection ends with its last
    entry (not at the next token, past comments); a block scalar without its line breaks."""
    if isinstance(node, yaml.MappingNode | yaml.SequenceNode) and not node.flow_style:
        if node.value:
            last = node.value[-1]
            return _end(last[1] if isinstance(node, yaml.MappingNode) else last)
    return node.end_mark.index


def splice(text: str, start: int, end: int, new: str) -> str:
    """``text`` with ``text[start:end]`` replaced by ``new``; a comment after it on the same
    line keeps its column where the spaces before it allow (aligned comments stay
    aligned)."""
    out = text[:start] + new + text[end:]
    if "\n" in text[start:end] or "\n" in new:
        return out
    gap = re.match(r"([}\]]*)( +)#", text[end:])  # after the brackets that close it
    if gap is None:
        return out
    spaces = max(1, len(gap[2]) - (len(new) - (end - start)))
    at = start + len(new) + len(gap[1])
    return out[:at] + " " * spaces + out[at + len(gap[2]):]


def _trimmed_end(text: str, node: yaml.Node) -> int:
    end = _end(node)
    while end > node.start_mark.index and text[end - 1] in " \t\r\n":
        end -= 1
    return end


class _Edit:
    """A text and its composed tree, with the spans of its nodes."""

    def __init__(self, text: str, file: str):
        self.text = text
        self.file = file
        check_events(text, file)  # the limits, before anything is composed
        self.loader = _Loader(text)
        try:
            self.root = self.loader.get_single_node()
        except yaml.YAMLError:
            parse_document(text, file)  # raises the syntax error located at its line
            raise
        finally:
            self.loader.dispose()
        if not isinstance(self.root, yaml.MappingNode):
            parse_document(text, file)  # raises: the text holds no model mapping
        self.as_json = file.lower().endswith(".json") or text.lstrip().startswith("{")

    def walk(self, path: list[Key]) -> tuple[yaml.Node, _Step | None]:
        """The node at ``path`` (None when only its last key is missing) and the last
        step to it."""
        node, step = self.root, None
        for depth, wanted in enumerate(path):
            where = format_path(tuple(path[:depth])) or "the top level"
            if node is None:
                raise WebError(f"no key {format_path(tuple(path[:depth]))!r} in the model",
                               "add the entries above it first", 404)
            if isinstance(node, yaml.MappingNode):
                index = next((i for i, (k, _) in enumerate(node.value)
                              if _same_key(_key_of(k, self.loader), wanted)), None)
                if index is not None and node.value[index][1].start_mark.index \
                        < node.value[index][0].end_mark.index:
                    raise WebError(f"{format_path(tuple(path[:depth + 1]))} is an alias of "
                                   "another entry", "edit the anchored entry in the text", 409)
                step = _Step(node, index, None if index is None else node.value[index][0])
                node = None if index is None else node.value[index][1]
            elif isinstance(node, yaml.SequenceNode):
                if isinstance(wanted, bool) or not isinstance(wanted, int) \
                        or not 0 <= wanted <= len(node.value):
                    raise WebError(f"no item {wanted!r} in the list at {where}",
                                   f"give an index 0..{len(node.value)} (the last adds one)",
                                   404)
                index = wanted if wanted < len(node.value) else None
                step = _Step(node, index, None)
                node = None if index is None else node.value[index]
            else:
                raise WebError(f"{where} holds a single value, not entries",
                               f"set {where} itself", 404)
        return node, step

    # -- the changes -------------------------------------------------------------------
    def replace(self, node: yaml.Node, value: Any) -> str:
        start, end = node.start_mark.index, _trimmed_end(self.text, node)
        written = render(value, as_json=self.as_json)
        if start == end and isinstance(node, yaml.ScalarNode) and node.value == "":
            written = (" " if start and self.text[start - 1] == ":" else "") + written
        return splice(self.text, start, end, written)

    def add(self, step: _Step, key: Key, value: Any) -> str:
        parent, text = step.parent, self.text
        mapping = isinstance(parent, yaml.MappingNode)
        if mapping:
            keys = [_key_of(k, self.loader) for k, _ in parent.value]
            if isinstance(key, str) and _DIGITS.match(key) and all(
                    isinstance(k, int) and not isinstance(k, bool) for k in keys):
                key = int(key)
            entry = f"{render(key, as_json=self.as_json)}: {render(value, as_json=self.as_json)}"
        else:
            entry = render(value, as_json=self.as_json)
        if parent.flow_style or not parent.value:
            close = parent.end_mark.index - 1
            at = close
            while at > parent.start_mark.index + 1 and text[at - 1] in " \t\r\n":
                at -= 1
            joint = ", " if parent.value else ""
            return splice(text, at, at, joint + entry)
        last = parent.value[-1]
        end = _trimmed_end(text, last[1] if mapping else last)
        line_end = text.find("\n", end)
        line_end = len(text) if line_end < 0 else line_end
        if text[line_end - 1:line_end] == "\r":
            line_end -= 1
        column = parent.start_mark.column
        if not mapping:
            entry = "- " + entry
        return text[:line_end] + "\n" + " " * column + entry + text[line_end:]

    def delete(self, node: yaml.Node, step: _Step) -> str:
        parent, text = step.parent, self.text
        mapping = isinstance(parent, yaml.MappingNode)
        if len(parent.value) == 1:
            return self.replace(parent, {} if mapping else [])
        first = step.key_node if mapping else node
        start, end = first.start_mark.index, _trimmed_end(text, node)
        if parent.flow_style:
            after = re.match(r"\s*,[ \t]*", text[end:])
            if after and step.index < len(parent.value) - 1:
                return splice(text, start, end + after.end(), "")
            before = re.search(r",\s*$", text[:start])
            return splice(text, before.start() if before else start, end, "")
        line_start = text.rfind("\n", 0, start) + 1
        head = text[line_start:start]
        if not mapping:
            head = head.rstrip()
            if not head.endswith("-") or head[:-1].strip():
                raise WebError("the item does not start its own line",
                               "delete it in the text", 409)
        elif head.strip():  # the first key of a list item ("- key: ..."): keep the dash
            following = parent.value[step.index + 1][0].start_mark.index
            return text[:start] + text[following:]
        line_end = text.find("\n", end)
        line_end = len(text) if line_end < 0 else line_end + 1
        return text[:line_start] + text[line_end:]

    def rename(self, step: _Step, key: Key) -> str:
        node = step.key_node
        start, end = node.start_mark.index, node.end_mark.index
        return splice(self.text, start, end, render(key, as_json=self.as_json))


def _read_back(text: str, file: str, path: list[Key], original: str) -> tuple[bool, Any]:
    """(whether ``path`` is in the changed ``text``, the value there); an ``original`` text
    that does not read (a key twice) raises its own located error."""
    try:
        data, _ = parse_document(text, file)
    except ModelError:
        parse_document(original, file)
        return False, None
    for key in path:
        if isinstance(data, dict):
            found = [k for k in data if _same_key(k, key)]
            if not found:
                return False, None
            data = data[found[0]]
        elif isinstance(data, list) and isinstance(key, int) and 0 <= key < len(data):
            data = data[key]
        else:
            return False, None
    return True, data


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b
    if isinstance(a, int | float) and isinstance(b, int | float):
        return a == b
    if isinstance(a, dict) and isinstance(b, dict):
        return len(a) == len(b) and all(
            any(_same_key(k, j) and _same(v, b[j]) for j in b) for k, v in a.items())
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    return type(a) is type(b) and a == b


def _check_path(path: Any) -> list[Key]:
    if not isinstance(path, list) or not path:
        raise WebError("'keys' is not a list of keys",
                       "give the key path as a list, e.g. [\"vectors\", 1, \"r\"]")
    if len(path) > MAX_PATH:
        raise WebError(f"the key path has {len(path)} keys", f"at most {MAX_PATH}", 413)
    for key in path:
        if isinstance(key, bool) or not isinstance(key, str | int):
            raise WebError(f"the key {key!r} of the path is not a name or a number",
                           "give names and numbers only")
    return list(path)


def edit_text(text: str, path: Any, *, value: Any = None, delete: bool = False,
              key: Any = None, file: str = "model.yaml") -> str:
    """``text`` with the one change asked (see the module docstring): set ``value`` at
    ``path`` (the default), ``delete`` the entry, or rename its key to ``key``.

    Raises :class:`~mechloop.web.safety.WebError` (404: no such key; 409: an entry the
    change cannot make in place; 413: too large) or the located
    :class:`~mechloop.errors.ModelError` of a text that is not YAML.
    """
    if len(text.encode("utf-8")) > MAX_DOCUMENT_BYTES:
        raise WebError(f"the text is over {MAX_DOCUMENT_BYTES:,} bytes",
                       "keep long tables in a CSV file", 413)
    path = _check_path(path)
    value = plain(value)
    _check_value(value)
    document = _Edit(text, file)
    node, step = document.walk(path)
    where = format_path(tuple(path))
    if key is not None:
        if node is None or not isinstance(step.parent, yaml.MappingNode):
            raise WebError(f"no key {where!r} to rename", "rename an existing key", 404)
        if isinstance(key, bool) or not isinstance(key, str | int) or key == "":
            raise WebError(f"the new key {key!r} is not a name or a number", "give a name")
        if isinstance(key, str) and _DIGITS.match(key):
            key = int(key)
        if any(_same_key(_key_of(k, document.loader), key) for k, _ in step.parent.value
               if k is not step.key_node):
            raise WebError(f"the key {key!r} is there already", "pick another key", 409)
        changed, path = document.rename(step, key), [*path[:-1], key]
        found, _ = _read_back(changed, file, path, text)
        if not found:
            raise WebError(f"renaming {where} would not read back", "rename it in the text",
                           409)
    elif delete:
        if node is None:
            raise WebError(f"no key {where!r} to delete", "delete an existing entry", 404)
        changed = document.delete(node, step)
        found, _ = _read_back(changed, file, path[:-1], text)
        if not found:
            raise WebError(f"deleting {where} would not read back", "delete it in the text",
                           409)
    else:
        changed = document.replace(node, value) if node is not None \
            else document.add(step, path[-1], value)
        found, back = _read_back(changed, file, path, text)
        if not found or not _same(back, value):
            raise WebError(f"the value at {where} would read back as {back!r}, not "
                           f"{value!r}", "change it in the text", 409)
    if len(changed.encode("utf-8")) > MAX_DOCUMENT_BYTES:
        raise WebError(f"the edited text would be over {MAX_DOCUMENT_BYTES:,} bytes",
                       "keep long tables in a CSV file", 413)
    return changed


def json_data(text: str, file: str = "model.yaml") -> Any:
    """The plain data of ``text`` as the forms read it: JSON-ready (keys as strings,
    dates and other YAML types as their text)."""
    data, _ = parse_document(text, file)
    return _jsonable(data)


def _jsonable(value: Any) -> Any:
    if isinstance(value, dict):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_jsonable(v) for v in value]
    if value is None or isinstance(value, bool | int | str):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else str(value)
    return str(value)
