"""Hypothesis strategies for whole model files: documents drawn from the JSON schemas of
vector models (``mechloop schema``) and of group files, YAML documents of any shape, and
raw text and bytes.

``hypothesis-jsonschema`` would draw documents from the schema, but its release does not
run on current Hypothesis (it calls an internal API that is gone), so :func:`from_schema`
reads the few keywords the model schema uses: ``$ref``, ``type``, ``enum``, ``const``,
``anyOf``/``oneOf``, ``properties``/``required``/``additionalProperties``, ``items``/
``prefixItems``/``minItems``/``maxItems``, ``minimum``/``maximum`` (also exclusive) and
``pattern``.  Numbers are drawn mostly within the schema's bounds, sometimes at absurd or
non-finite values, because those are what a loader must refuse.
"""

from __future__ import annotations

import json
from functools import cache
from typing import Any

from hypothesis import strategies as st

from mechloop.model.groups import group_json_schema
from mechloop.model.schema import model_json_schema

from .mutations import ODD_NUMBERS, dump

SPECIAL = st.sampled_from(ODD_NUMBERS)


def _number(schema: dict[str, Any], *, integer: bool) -> st.SearchStrategy:
    low = schema.get("minimum", schema.get("exclusiveMinimum"))
    high = schema.get("maximum", schema.get("exclusiveMaximum"))
    if integer:
        lo = int(low) if low is not None else -5
        hi = int(high) if high is not None else lo + 100
        plain = st.integers(lo, max(lo, min(hi, lo + 400)))
    else:
        lo = float(low) if low is not None else -1000.0
        hi = float(high) if high is not None else lo + 2000.0
        plain = st.floats(lo, hi, allow_nan=False, allow_infinity=False)
    return st.one_of(plain, plain, plain, SPECIAL)


def _keys() -> st.SearchStrategy:
    """Keys of a mapping whose keys the schema leaves free: mostly small whole numbers and
    the names examples use (vector, body and argument numbers, joint and link names)."""
    return st.one_of(st.integers(0, 8), st.sampled_from(("A", "B", "O", "crank", "S", "x")),
                     st.text(max_size=4))


class _Builder:
    def __init__(self, root: dict[str, Any]):
        self.root = root

    def resolve(self, ref: str) -> dict[str, Any]:
        node: Any = self.root
        for part in ref.lstrip("#/").split("/"):
            node = node[part]
        return node

    def build(self, schema: dict[str, Any] | bool, depth: int = 0) -> st.SearchStrategy:
        if schema is True or schema == {}:
            return _any_value()
        if schema is False:
            return st.nothing()
        if depth > 12:
            return st.none()
        if "$ref" in schema:
            return st.deferred(lambda: self.build(self.resolve(schema["$ref"]), depth + 1))
        if "const" in schema:
            return st.just(schema["const"])
        if "enum" in schema:
            return st.sampled_from(schema["enum"])
        for key in ("anyOf", "oneOf"):
            if key in schema:
                return st.one_of([self.build(s, depth + 1) for s in schema[key]])
        kind = schema.get("type")
        if isinstance(kind, list):
            return st.one_of([self.build({**schema, "type": k}, depth) for k in kind])
        if kind == "null":
            return st.none()
        if kind == "boolean":
            return st.booleans()
        if kind == "integer":
            return _number(schema, integer=True)
        if kind == "number":
            return _number(schema, integer=False)
        if kind == "string":
            if "pattern" in schema:
                return st.from_regex(schema["pattern"], fullmatch=True)
            return st.one_of(st.text(max_size=12), st.sampled_from(
                ("function", "1", "mm", "deg", "5 kg", "0.1 m", "30 deg", "crank")))
        if kind == "array":
            return self._array(schema, depth)
        if kind == "object" or "properties" in schema:
            return self._object(schema, depth)
        return _any_value()

    def _array(self, schema, depth):
        low = schema.get("minItems", 0)
        high = schema.get("maxItems", low + 4)
        if "prefixItems" in schema:
            head = [self.build(s, depth + 1) for s in schema["prefixItems"]]
            tail = schema.get("items", False)
            fixed = st.tuples(*head).map(list)
            if tail is False or len(head) >= high:
                return fixed
            more = st.lists(self.build(tail, depth + 1), max_size=high - len(head))
            return st.tuples(fixed, more).map(lambda p: p[0] + p[1])
        return st.lists(self.build(schema.get("items", {}), depth + 1), min_size=low,
                        max_size=min(high, low + 4))

    def _object(self, schema, depth):
        properties = schema.get("properties", {})
        required = [k for k in schema.get("required", []) if k in properties]
        optional = [k for k in properties if k not in required]
        fixed = st.fixed_dictionaries(
            {k: self.build(properties[k], depth + 1) for k in required},
            optional={k: self.build(properties[k], depth + 1) for k in optional})
        extra = schema.get("additionalProperties", {} if not properties else False)
        if extra is False:
            return fixed
        more = st.dictionaries(_keys(), self.build(extra, depth + 1), max_size=4)
        return st.tuples(fixed, more).map(lambda p: {**p[1], **p[0]})


def _any_value() -> st.SearchStrategy:
    scalars = st.one_of(st.none(), st.booleans(), st.integers(-10, 10), SPECIAL,
                        st.text(max_size=8))
    return st.recursive(scalars, lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(_keys(), inner, max_size=4)),
        max_leaves=12)


@cache
def schema_documents() -> st.SearchStrategy:
    """Documents drawn from the schema of vector models (the one ``mechloop schema``
    prints) and from the schema of group files."""
    groups = group_json_schema()
    groups["required"] = [*groups.get("required", []), "groups"]  # what makes a group file
    built = []
    for schema in (model_json_schema(), groups):
        schema = json.loads(json.dumps(schema))
        built.append(_Builder(schema).build(schema))
    return st.one_of(built)


def schema_files() -> st.SearchStrategy:
    """The files of one input drawn from the schema, as YAML or as JSON."""
    def write(doc_and_json):
        doc, as_json = doc_and_json
        if as_json:
            text = json.dumps(doc, allow_nan=True)
            return {"model.json": text.encode()}
        return {"model.yaml": dump(doc).encode("utf-8", "surrogateescape")}
    return st.tuples(schema_documents(), st.booleans()).map(write)


def yaml_files() -> st.SearchStrategy:
    """YAML documents of any shape with the model's top-level keys."""
    top = st.sampled_from(("positions", "time", "arguments", "vectors", "contours", "bodies",
                           "joints", "forces", "gravity", "groups", "ground", "input",
                           "masses", "points", "units", "synthesis", "machine"))
    return st.dictionaries(top, _any_value(), max_size=6).map(
        lambda doc: {"model.yaml": dump(doc).encode("utf-8", "surrogateescape")})


YAML_BITS = ("positions: ", "vectors:\n", "  1: {r: ", "a: function}", "contours:\n",
             "  - vectors: [1, 2]\n", "&a ", "*a", "? ", ": ", "- ", "[", "]", "{", "}",
             "!!python/object:os.system", "!!binary", "%YAML 1.1\n", "---\n", "...\n",
             ".inf", ".nan", "1e400", "0x1F", "0o17", "~", "'", '"', "#", "\n", "  ", "\t")


def raw_files() -> st.SearchStrategy:
    """Raw text (often YAML-like) and raw bytes as a model file."""
    yamlish = st.lists(st.one_of(st.sampled_from(YAML_BITS), st.text(max_size=6)),
                       max_size=30).map("".join)
    text = st.one_of(yamlish, st.text(max_size=200)).map(
        lambda t: t.encode("utf-8", "surrogatepass"))
    return st.tuples(st.one_of(text, st.binary(max_size=200)),
                     st.sampled_from(("model.yaml", "model.json"))).map(
        lambda p: {p[1]: p[0]})

