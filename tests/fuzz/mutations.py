"""Mutations of the bundled example models, as Hypothesis strategies.

A mutated input is the example's parsed document with one to three *document* mutations
(a number replaced by an absurd or non-finite value, a value of the wrong type, a key
dropped or added, a list one item short or long, two vector numbers swapped, a subtree
shared as a YAML alias, a 100 KB string, a table moved to a CSV file with bad rows), written
back as YAML; then, sometimes, one *text* mutation (truncation, flipped bytes, non-UTF-8
bytes, a duplicated or dropped line, deep nesting, a complex key, an alias bomb, a BOM or a
tab).  Each strategy yields the files of one input: ``{"model.yaml": bytes, ...}``.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import yaml
from hypothesis import strategies as st

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.yaml"))

ODD_NUMBERS: tuple[Any, ...] = (
    0, -1, 1, 0.5, -0.5, 1e20, -1e20, math.inf, -math.inf, math.nan, 2**64, -(2**63),
    10**30, 1e9, 1e200, -1e200, 1e-300, 5e-324, 1e308, 360, 720, 1e6, 12, 3,
)
"""Numbers that broke, or could break, a loader or a solver."""

ODD_VALUES: tuple[Any, ...] = (
    "5 kg", "", "abc", "1e400", ".nan", "inf m", "90 deg", "function", "-", [], [1, 2],
    [math.nan], {}, {"vector": 2, "along": "5 kg"}, {"table": {0: math.inf}}, None, True,
    False, "0x10", "1_000", "${x}", "%", "\u00e9\u00e8", "\x00",
)
"""Values of the wrong type or form for most keys."""

KEYS = ("positions", "time", "rpm", "mass", "inertia", "vector", "along", "share", "variant",
        "argument", "table", "link", "delta", "unit", "csv", "value", "angle", "g", "r", "a",
        "name", "center", "at", "joint", "groups", "kind", "lengths", "length", "guide",
        "offset", "through", "column", "derivatives", "law", "start", "end", "unknown_key")
"""Keys to add: ones the model knows (in the wrong place, or twice) and one it does not."""

BAD_CSV_CELLS = ("inf", "-inf", "nan", "1e400", "1e20", "x", "", "2**64", "0", "-1",
                 "18446744073709551616", "1,2", "\"3\"")


def _paths(node: Any, path: tuple = ()) -> list[tuple]:
    """Every path in a document, the root first (mapping keys and list indices)."""
    out = [path]
    if isinstance(node, dict):
        for key, value in node.items():
            out.extend(_paths(value, (*path, key)))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            out.extend(_paths(value, (*path, i)))
    return out


def _get(doc: Any, path: tuple) -> Any:
    for key in path:
        doc = doc[key]
    return doc


def _set(doc: Any, path: tuple, value: Any) -> Any:
    if not path:
        return value
    _get(doc, path[:-1])[path[-1]] = value
    return doc


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _copy(node: Any) -> Any:
    """A deep copy that keeps no sharing (so only the alias mutation makes aliases)."""
    if isinstance(node, dict):
        return {k: _copy(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_copy(v) for v in node]
    return node


@st.composite
def _pick(draw, doc: Any, want=lambda value: True, *, root: bool = False) -> tuple | None:
    paths = [p for p in _paths(doc) if (root or p) and want(_get(doc, p))]
    if not paths:
        return None
    return paths[draw(st.integers(0, len(paths) - 1))]


odd_number = st.one_of(st.sampled_from(ODD_NUMBERS),
                       st.floats(allow_nan=True, allow_infinity=True),
                       st.integers(min_value=-(2**70), max_value=2**70))
odd_value = st.one_of(st.sampled_from(ODD_VALUES), odd_number)


@st.composite
def _number(draw, doc, files):
    path = draw(_pick(doc, _is_number))
    if path is None:
        return doc
    old = _get(doc, path)
    new = draw(st.one_of(odd_number, st.sampled_from((-1.0, 0.5, 2.0, 10.0, 1e-9)).map(
        lambda f: old * f)))
    return _set(doc, path, new)


@st.composite
def _retype(draw, doc, files):
    path = draw(_pick(doc))
    return doc if path is None else _set(doc, path, draw(odd_value))


@st.composite
def _drop(draw, doc, files):
    path = draw(_pick(doc))
    if path is None:
        return doc
    del _get(doc, path[:-1])[path[-1]]
    return doc


@st.composite
def _add_key(draw, doc, files):
    path = draw(_pick(doc, lambda v: isinstance(v, dict), root=True))
    if path is None:
        return doc
    _get(doc, path)[draw(st.sampled_from(KEYS))] = draw(odd_value)
    return doc


@st.composite
def _resize(draw, doc, files):
    """A list one item short (a force table, a vector list) or one item long."""
    path = draw(_pick(doc, lambda v: isinstance(v, list) and v, root=True))
    if path is None:
        return doc
    items = _get(doc, path)
    if draw(st.booleans()):
        items.pop(draw(st.integers(0, len(items) - 1)))
    else:
        items.append(draw(st.one_of(st.just(_copy(items[-1])), odd_value)))
    return doc


@st.composite
def _swap(draw, doc, files):
    """Two whole numbers (vector, body or argument numbers) or two keys of a mapping."""
    ints = [p for p in _paths(doc) if p and isinstance(_get(doc, p), int)
            and not isinstance(_get(doc, p), bool)]
    if len(ints) >= 2 and draw(st.booleans()):
        i, j = draw(st.lists(st.integers(0, len(ints) - 1), min_size=2, max_size=2,
                             unique=True))
        a, b = _get(doc, ints[i]), _get(doc, ints[j])
        _set(doc, ints[i], b)
        _set(doc, ints[j], a)
        return doc
    path = draw(_pick(doc, lambda v: isinstance(v, dict) and len(v) >= 2, root=True))
    if path is None:
        return doc
    mapping = _get(doc, path)
    keys = list(mapping)
    i, j = draw(st.lists(st.integers(0, len(keys) - 1), min_size=2, max_size=2, unique=True))
    keys[i], keys[j] = keys[j], keys[i]
    values = list(mapping.values())
    renamed = dict(zip(keys, values, strict=True))
    mapping.clear()
    mapping.update(renamed)
    return doc


@st.composite
def _alias(draw, doc, files):
    """One subtree reused at another place: written as a YAML anchor and alias."""
    source = draw(_pick(doc, lambda v: isinstance(v, dict | list) and v))
    target = draw(_pick(doc))
    if source is None or target is None or target[:len(source)] == source \
            or source[:len(target)] == target:
        return doc
    return _set(doc, target, _get(doc, source))


@st.composite
def _long_string(draw, doc, files):
    path = draw(_pick(doc, lambda v: not isinstance(v, dict | list)))
    if path is None:
        return doc
    return _set(doc, path, draw(st.sampled_from(("x", "9", "1 ", "mm"))) * 100_000)


@st.composite
def _csv_table(draw, doc, files):
    """A table moved to a CSV file whose rows hold odd values."""
    path = draw(_pick(doc, lambda v: isinstance(v, dict) and isinstance(v.get("table"),
                                                                        dict | list)))
    if path is None:
        return doc
    table = _get(doc, path)["table"]
    rows = list(table.items()) if isinstance(table, dict) else list(enumerate(table))
    lines = ["position,value"] + [f"{k},{v}" for k, v in rows]
    if len(lines) > 1:
        i = draw(st.integers(1, len(lines) - 1))
        cell = draw(st.sampled_from(BAD_CSV_CELLS))
        key = lines[i].split(",", 1)[0]
        lines[i] = draw(st.sampled_from((f"{key},{cell}", f"{cell},{cell}", f"{key}")))
    files["table.csv"] = ("\n".join(lines) + "\n").encode()
    spec = {k: v for k, v in _get(doc, path).items() if k != "table"}
    spec["csv"] = "table.csv"
    return _set(doc, path, spec)


DOCUMENT_MUTATIONS = (_number, _number, _number, _retype, _drop, _add_key, _resize, _swap,
                      _alias, _long_string, _csv_table)


def _nest(depth: int) -> str:
    return "[" * depth + "1" + "]" * depth


BILLION_LAUGHS = "\n".join(
    ["lol0: &l0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    + [f"lol{i}: &l{i} [{', '.join([f'*l{i - 1}'] * 9)}]" for i in range(1, 10)]) + "\n"


@st.composite
def _text_mutation(draw, data: bytes) -> bytes:
    kind = draw(st.sampled_from(("truncate", "flip", "non_utf8", "duplicate_line",
                                 "drop_line", "deep_nesting", "complex_key", "alias_bomb",
                                 "bom", "tab", "nul")))
    n = len(data)
    lines = data.split(b"\n")
    at_line = draw(st.integers(0, max(len(lines) - 1, 0)))
    if kind == "truncate":
        return data[:draw(st.integers(0, n))]
    if kind == "flip" and n:
        out = bytearray(data)
        for _ in range(draw(st.integers(1, 4))):
            i = draw(st.integers(0, n - 1))
            out[i] ^= 1 << draw(st.integers(0, 7))
        return bytes(out)
    if kind == "non_utf8":
        i = draw(st.integers(0, n))
        return data[:i] + draw(st.sampled_from((b"\xff", b"\xc3", b"\xed\xa0\x80",
                                                b"\xe9t\xe9", b"\xfe\xff"))) + data[i:]
    if kind == "duplicate_line":
        return b"\n".join([*lines[:at_line + 1], *lines[at_line:]])
    if kind == "drop_line":
        return b"\n".join(lines[:at_line] + lines[at_line + 1:])
    if kind == "deep_nesting":
        depth = draw(st.sampled_from((50, 1000, 5000)))
        nested = draw(st.sampled_from((_nest(depth), "{a: " * depth + "1" + "}" * depth)))
        return data + f"\nnested: {nested}\n".encode()
    if kind == "complex_key":
        key = draw(st.sampled_from(("? [1, 2]\n: 3", "? {a: 1}\n: 2", "[1, 2]: 3",
                                    "{a: 1}: 2", "? - 1\n  - 2\n: x")))
        return data + b"\n" + key.encode() + b"\n"
    if kind == "alias_bomb":
        return BILLION_LAUGHS.encode() + data
    if kind == "bom":
        return b"\xef\xbb\xbf" + data
    if kind == "tab":
        lines[at_line] = b"\t" + lines[at_line]
        return b"\n".join(lines)
    if kind == "nul":
        i = draw(st.integers(0, n))
        return data[:i] + b"\x00" + data[i:]
    return data


def dump(doc: Any) -> str:
    """The document as YAML (shared subtrees become anchors and aliases)."""
    return yaml.safe_dump(doc, sort_keys=False, allow_unicode=True, width=100)


@st.composite
def mutated(draw, example: Path) -> dict[str, bytes]:
    """The files of one input: ``example`` with document and text mutations."""
    text = example.read_text(encoding="utf-8")
    files: dict[str, bytes] = {}
    steps = draw(st.integers(0, 3))
    if steps:
        doc = _copy(yaml.safe_load(text))
        for _ in range(steps):
            mutation = draw(st.sampled_from(DOCUMENT_MUTATIONS))
            doc = draw(mutation(doc, files))
        data = dump(doc).encode("utf-8", "surrogateescape")
    else:
        data = text.encode()
    if steps == 0 or draw(st.integers(0, 3)) == 0:
        data = draw(_text_mutation(data))
    files["model.yaml"] = data
    return files
