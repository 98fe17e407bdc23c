"""The in-place edit of a model's text (``POST /api/edit``, :mod:`mechloop.web.edit`): the
value asked is what the changed text reads back at its key path, the rest of the data is
unchanged, every other line is the same byte for byte (comments, blank lines, layout), and
a bad path, a bad value or a too large text is a clear 4xx refusal."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from starlette.testclient import TestClient

from mechloop.model.limits import MAX_DOCUMENT_BYTES
from mechloop.web import edit
from mechloop.web.app import create_app
from mechloop.web.edit import edit_text
from mechloop.web.safety import MAX_BODY_BYTES

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SLIDER = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")
#: Block and flow style, comments everywhere, a blank line, an aligned comment column.
COMMENTED = """\
# a header comment
name: Test   # the name
positions: 12

units:
  length: mm     # millimetres
  angle: deg
arguments:
  1:
    table:
      0: 0       # start
      12: 360    # one turn
vectors:
  1: {r: 50, a: {argument: 1}}   # crank
  2:
    r: 200
    a: function
  3: {r: function, a: 180}
contours:
  - vectors: [1, 2, 3]   # the loop
    variant: 1
  - vectors:
      - 1
      - 3
# a closing comment
"""


@pytest.fixture(scope="module")
def client(tmp_path_factory) -> TestClient:
    root = tmp_path_factory.mktemp("work")
    (root / "crank_slider.yaml").write_text(SLIDER, encoding="utf-8")
    return TestClient(create_app(root))


def _get(data, path):
    for key in path:
        data = data[key]
    return data


def _other_lines_kept(before: str, after: str, lines: set[int]) -> None:
    """Every line of ``before`` but those numbered in ``lines`` (0-based) is in ``after``
    unchanged and in order, before the edit and after it."""
    old, new = before.splitlines(keepends=True), after.splitlines(keepends=True)
    first, last = min(lines), max(lines)
    assert new[:first] == old[:first]
    tail = len(old) - last - 1
    assert new[len(new) - tail:] == old[last + 1:] if tail else True


def _line_of(text: str, path) -> set[int]:
    """The 0-based lines of the node at ``path`` (PyYAML's compose)."""
    node = yaml.compose(text)
    for key in path:
        if isinstance(node, yaml.MappingNode):
            node = next(v for k, v in node.value if yaml.safe_load(k.value) == key
                        or k.value == str(key))
        else:
            node = node.value[key]
    end = node.end_mark.line - (node.end_mark.column == 0 and node.end_mark.line > 0)
    return set(range(node.start_mark.line, max(end, node.start_mark.line) + 1))


@pytest.mark.parametrize("value", [
    0.06, 7, -1.5e-7, 1e22, "50 mm", "function", "yes", "no", "null", "1: x", "# not a comment",
    "", "a 'quoted' \"text\"", "шатун", "two\nlines", True, False, None, [1, 2.5, "x"],
    {"argument": 1, "offset": 5}, {"link": "a2", "ratio": "-20/50"}, [], {},
    {"table": {"0": 0, "72": 360}}, [[0, 1], [2, 3]],
])
@pytest.mark.parametrize("path", [["vectors", 1, "r"], ["vectors", 2, "r"],
                                  ["arguments", 1, "table", 12], ["contours", 1, "vectors", 0]])
def test_every_kind_of_value_reads_back_and_nothing_else_changes(value, path):
    changed = edit_text(COMMENTED, path, value=value)
    data, expected = yaml.safe_load(changed), copy.deepcopy(yaml.safe_load(COMMENTED))
    wanted = {0: 0, 72: 360} if value == {"table": {"0": 0, "72": 360}} else value
    wanted = {"table": wanted} if isinstance(wanted, dict) and 0 in wanted else wanted
    _get(expected, path[:-1])[path[-1]] = wanted
    assert data == expected
    _other_lines_kept(COMMENTED, changed, _line_of(COMMENTED, path))


def test_comments_and_layout_are_kept_byte_for_byte():
    changed = edit_text(COMMENTED, ["vectors", 1, "r"], value=55.5)
    assert changed == COMMENTED.replace("{r: 50, a: {argument: 1}}   # crank",
                                        "{r: 55.5, a: {argument: 1}}   # crank")
    changed = edit_text(COMMENTED, ["arguments", 1, "table", 12], value=720)
    assert changed == COMMENTED.replace("12: 360    # one turn", "12: 720    # one turn")
    changed = edit_text(COMMENTED, ["units", "length"], value="cm")
    assert changed == COMMENTED.replace("length: mm     #", "length: cm     #")


def test_a_row_is_added_at_the_indent_of_its_table():
    changed = edit_text(COMMENTED, ["arguments", 1, "table", 6], value=180)
    assert changed == COMMENTED.replace("      12: 360    # one turn\n",
                                        "      12: 360    # one turn\n      6: 180\n")
    changed = edit_text(COMMENTED, ["vectors", 4], value={"r": 10, "a": 90})
    assert changed == COMMENTED.replace("  3: {r: function, a: 180}\n",
                                        "  3: {r: function, a: 180}\n  4: {r: 10, a: 90}\n")
    changed = edit_text(COMMENTED, ["contours", 0, "vectors", 3], value=4)
    assert "  - vectors: [1, 2, 3, 4] # the loop\n" in changed
    changed = edit_text(COMMENTED, ["contours", 1, "vectors", 2], value=2)
    assert changed.endswith("      - 1\n      - 3\n      - 2\n# a closing comment\n")
    changed = edit_text(COMMENTED, ["contours", 2], value={"vectors": [1, 2]})
    assert yaml.safe_load(changed)["contours"][2] == {"vectors": [1, 2]}
    changed = edit_text(COMMENTED, ["vectors", 1, "name"], value="crank")
    assert "  1: {r: 50, a: {argument: 1}, name: crank} # crank\n" in changed
    # a new numbered key is a number where the table's keys are numbers
    assert 6 in yaml.safe_load(edit_text(COMMENTED, ["arguments", 1, "table", "6"],
                                         value=1))["arguments"][1]["table"]


def test_a_row_is_deleted_with_its_lines_and_a_key_renamed_in_place():
    changed = edit_text(COMMENTED, ["vectors", 2], delete=True)
    assert changed == COMMENTED.replace("  2:\n    r: 200\n    a: function\n", "")
    changed = edit_text(COMMENTED, ["vectors", 1, "a"], delete=True)
    assert "  1: {r: 50}                     # crank\n" in changed
    changed = edit_text(COMMENTED, ["contours", 0, "vectors"], delete=True)
    assert "  - variant: 1\n" in changed and yaml.safe_load(changed)["contours"][0] == \
        {"variant": 1}
    changed = edit_text(COMMENTED, ["contours", 1, "vectors", 0], delete=True)
    assert changed.endswith("  - vectors:\n      - 3\n# a closing comment\n")
    changed = edit_text(COMMENTED, ["units"], value={"length": "mm"})
    assert yaml.safe_load(edit_text(changed, ["units", "length"], delete=True))["units"] == {}
    changed = edit_text(COMMENTED, ["arguments", 1, "table", 12], key=24)
    assert changed == COMMENTED.replace("      12: 360    # one turn",
                                        "      24: 360    # one turn")


def test_a_json_model_stays_json():
    text = '{"positions": 4, "vectors": {"1": {"r": 1, "a": 0}}}\n'
    changed = edit_text(text, ["vectors", "1", "name"], value="a: b", file="m.json")
    assert changed == '{"positions": 4, "vectors": {"1": {"r": 1, "a": 0, "name": "a: b"}}}\n'


# ---------------------------------------------------------------- the endpoint
def test_the_endpoint_gives_the_text_and_its_data(client):
    answer = client.post("/api/edit", json={"text": SLIDER, "keys": ["vectors", 1, "r"],
                                            "value": 0.06, "path": "crank_slider.yaml",
                                            "example": "crank_slider"})
    assert answer.status_code == 200
    body = answer.json()
    assert body["text"] == SLIDER.replace("1: {r: 0.05,", "1: {r: 0.06,")
    assert body["data"]["vectors"]["1"]["r"] == 0.06
    data = client.post("/api/data", json={"text": SLIDER}).json()["data"]
    assert data["contours"][0]["vectors"] == [1, 2, 3, 4]
    # the solved diagram follows: tests/test_web_browser.py (the form and the drag)


@pytest.mark.parametrize(("request_", "status", "words"), [
    ({"keys": ["vectors", 9, "r"], "value": 1}, 404, "vectors[9]"),
    ({"keys": ["nothing", "deeper"], "value": 1}, 404, "nothing"),
    ({"keys": ["name", "x"], "value": 1}, 404, "single value"),
    ({"keys": ["contours", 5], "value": 1}, 404, "no item 5 in the list at contours"),
    ({"keys": ["contours", "first"], "value": 1}, 404, "first"),
    ({"keys": "vectors.1.r", "value": 1}, 400, "list of keys"),
    ({"keys": [], "value": 1}, 400, "list of keys"),
    ({"keys": ["vectors", [1]], "value": 1}, 400, "not a name"),
    ({"keys": ["vectors", 9], "delete": True}, 404, "to delete"),
    ({"keys": ["vectors", 1], "key": 2}, 409, "there already"),
    ({"keys": ["vectors", 1], "value": {"r": float("1e400")}}, 400, "JSON"),
    ({"keys": ["k"] * 100, "value": 1}, 413, "100 keys"),
])
def test_a_bad_edit_is_a_clear_refusal(client, request_, status, words):
    if request_.get("value") == {"r": float("1e400")}:  # not JSON: sent as written
        answer = client.post("/api/edit", content=b'{"text": "a: 1", "keys": ["a"], '
                             b'"value": NaN}', headers={"content-type": "application/json"})
    else:
        answer = client.post("/api/edit", json={"text": SLIDER, **request_})
    assert answer.status_code == status, answer.json()
    body = answer.json()
    assert words in body["error"] and body["hint"]


def test_an_alias_a_syntax_error_and_the_size_limits(client, monkeypatch):
    aliased = "base: &b {r: 1, a: 0}\nother: *b\n"
    answer = client.post("/api/edit", json={"text": aliased, "keys": ["other", "r"],
                                            "value": 2})
    assert answer.status_code == 409 and "alias" in answer.json()["error"]
    bad = client.post("/api/edit", json={"text": "a: [1,\nb: 2\n", "keys": ["a"],
                                         "value": 1})
    assert bad.status_code == 422 and bad.json()["problems"][0]["line"] is not None
    twice = client.post("/api/edit", json={"text": "a: 1\nb: 2\na: 3\n", "keys": ["b"],
                                           "value": 1})
    assert twice.status_code == 422 and twice.json()["problems"][0]["line"] == 3
    for text in ("", "- 1\n- 2\n"):
        top = client.post("/api/edit", json={"text": text, "keys": ["a"], "value": 1})
        assert top.status_code == 422 and "model mapping" in top.json()["error"]
    big = client.post("/api/edit", content=b"x" * (MAX_BODY_BYTES + 1),
                      headers={"content-type": "application/json"})
    assert big.status_code == 413
    monkeypatch.setattr(edit, "MAX_DOCUMENT_BYTES", 1000)  # a 2 MB text parses slowly
    near = "a: 1\n" + "#" * 980 + "\n"
    grown = client.post("/api/edit", json={"text": near, "keys": ["a"], "value": "x" * 64})
    assert grown.status_code == 413 and "over 1,000 bytes" in grown.json()["error"]
    over = client.post("/api/edit", json={"text": near + "#" * 30, "keys": ["a"],
                                          "value": 2})
    assert over.status_code == 413 and "the text is over" in over.json()["error"]
    assert MAX_DOCUMENT_BYTES < MAX_BODY_BYTES  # a text at the limit fits in a request


# ---------------------------------------------------------------- the round trip
def _leaves(data, path=()):
    """Every key path of a scalar in ``data``."""
    if isinstance(data, dict):
        for key, value in data.items():
            yield from _leaves(value, (*path, key))
    elif isinstance(data, list):
        for i, value in enumerate(data):
            yield from _leaves(value, (*path, i))
    else:
        yield path


_MODELS = {name: (EXAMPLES / name).read_text(encoding="utf-8") for name in
           ("crank_slider.yaml", "crank_slider_dynamics.yaml", "four_bar_path_synthesis.yaml",
            "six_bar.yaml", "compressor_indicator.yaml")}
_LEAVES = [(name, path) for name, text in _MODELS.items()
           for path in _leaves(yaml.safe_load(text)) if path]
_SCALARS = (st.integers(-10**9, 10**9) | st.floats(allow_nan=False, allow_infinity=False)
            | st.text(max_size=20) | st.booleans() | st.none())
_VALUES = st.recursive(_SCALARS, lambda inner: st.lists(inner, max_size=3)
                       | st.dictionaries(st.from_regex(r"[a-z][a-z0-9_]{0,6}", fullmatch=True),
                                         inner, max_size=3), max_leaves=6)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(leaf=st.sampled_from(_LEAVES), value=_VALUES)
def test_round_trip_edit_parse_read_back(leaf, value):
    name, path = leaf
    text = _MODELS[name]
    changed = edit_text(text, list(path), value=value, file=name)
    expected = copy.deepcopy(yaml.safe_load(text))
    _get(expected, path[:-1])[path[-1]] = value
    assert yaml.safe_load(changed) == expected
    _other_lines_kept(text, changed, _line_of(text, path))


def _collections(data, path=()):
    """Every key path of a mapping or a list in ``data`` (the top level included)."""
    if isinstance(data, dict | list):
        yield path
        items = data.items() if isinstance(data, dict) else enumerate(data)
        for key, value in items:
            yield from _collections(value, (*path, key))


_COLLECTIONS = [(name, path) for name, text in _MODELS.items()
                for path in _collections(yaml.safe_load(text))]
_ENTRIES = [(name, path) for name, text in _MODELS.items()
            for path in _collections(yaml.safe_load(text)) if path] + _LEAVES


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(place=st.sampled_from(_COLLECTIONS), value=_VALUES)
def test_round_trip_a_new_entry_is_added_and_nothing_else_changes(place, value):
    name, path = place
    text = _MODELS[name]
    expected = copy.deepcopy(yaml.safe_load(text))
    target = _get(expected, path)
    key = "zz_new" if isinstance(target, dict) else len(target)
    changed = edit_text(text, [*path, key], value=value, file=name)
    if isinstance(target, dict):
        target[key] = value
    else:
        target.append(value)
    assert yaml.safe_load(changed) == expected
    kept = [line for line in changed.splitlines() if line not in text.splitlines()]
    assert len(kept) <= 1  # one new line, or the one line of a flow collection changed


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(place=st.sampled_from(_ENTRIES))
def test_round_trip_an_entry_is_deleted_and_nothing_else_changes(place):
    name, path = place
    text = _MODELS[name]
    expected = copy.deepcopy(yaml.safe_load(text))
    del _get(expected, path[:-1])[path[-1]]
    changed = edit_text(text, list(path), delete=True, file=name)
    assert yaml.safe_load(changed) == expected
    lines = _line_of(text, path)
    if not isinstance(path[-1], int):  # a mapping's entry starts at its key
        lines |= set(range(_key_line(text, path), max(lines) + 1))
    comments = [line for i, line in enumerate(text.splitlines())
                if line.lstrip().startswith("#") and i not in lines]
    assert [line for line in changed.splitlines() if line.lstrip().startswith("#")] \
        == comments  # every comment line outside the entry kept, in order


def _key_line(text: str, path) -> int:
    node = yaml.compose(text)
    for key in path[:-1]:
        node = next(v for k, v in node.value if yaml.safe_load(k.value) == key
                    or k.value == str(key)) if isinstance(node, yaml.MappingNode) \
            else node.value[key]
    return next(k for k, _ in node.value if yaml.safe_load(k.value) == path[-1]
                or k.value == str(path[-1])).start_mark.line
